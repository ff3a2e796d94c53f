// collide_bench_scenes: ns per query, called the way a physics step calls it, on the shared peer
// scenes (scenes.h: 1,024 pairs per set, even pairs overlapping, odd pairs apart by 0.01-0.5;
// a 250 x 200 height field of 100,000 triangles and random downward rays), with Box2D 2.4,
// Bullet's btBoxBoxDetector and ODE's trimesh on the same inputs in the same run.
//
// How every query is called (the same for collide and the peers):
// - each shape is stored in its own body frame with its body transform, as a solver keeps it;
// - inside the timed loop, B is placed in A's frame from the two body transforms (collide:
//   cd2InvMulTransforms / cd3InvMulTransforms, then the ...Local function), which is what
//   b2CollidePolygons, b2Distance and btBoxBoxDetector do inside their calls;
// - 2D distance: B's polygon is moved into A's frame in the loop (vertices and normals) and
//   cd2Distance is called, or cd2DistanceLocal gets B's local polygon and the transform; Box2D's
//   b2Distance gets the two local proxies and the transforms, from a cold simplex cache;
// - circle-polygon manifolds: collide's circle-first call (the circle as A: its centre taken into
//   the polygon's frame and the contact mapped back into the circle's) and its polygon-first call
//   (the polygon as A as in b2CollidePolygonAndCircle: only the centre is placed, the contact
//   reported in the polygon's frame), from the two body transforms as Box2D's call takes them
//   (cd2CollidePolygonCircleBodies) and from the relative transform composed in the loop
//   (cd2CollidePolygonCircleLocal);
// - time of impact: both take local shapes and two sweeps (A at rest, B translating and rotating
//   from separated to overlapping); target separation one linear slop, tolerance a quarter slop;
// - mesh rays: the closest hit of each ray (segment of length 30) on the height field.
// - 2D manifolds, "world output" rows: collide's manifold holds the normal, the points and their
//   separations (in A's frame), b2Manifold only local anchors; a step needs world normals, points
//   and separations, which Box2D 2.4's solver gets from b2WorldManifold and collide's world from
//   one rotation and one transform per point. These rows time the manifold call and that step to
//   world output on the pairs that touch, on both sides; the other manifold rows time the call
//   alone. Contact margins match Box2D's polygon skin (b2_polygonRadius per polygon).
//
// Timing: thread CPU time; each figure is the median of the runs, collide's and the peers' runs
// alternating so that all see the same machine load. Compare ratios, not nanoseconds, across
// machines. Usage: collide_bench_scenes [--quick] [--filter TEXT]
#include "scenes.h"

#include "collide/collide.h"

#ifdef COLLIDE_BENCH_HAVE_BOX2D
#include <box2d/b2_distance.h>
#include <box2d/b2_time_of_impact.h>
#include <box2d/box2d.h>
#endif
#ifdef COLLIDE_BENCH_HAVE_BULLET
#include <BulletCollision/CollisionDispatch/btBoxBoxDetector.h>
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#endif
#ifdef COLLIDE_BENCH_HAVE_ODE
#include <ode/ode.h>
#endif

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <functional>
#include <string>
#include <vector>

namespace
{
double ThreadSeconds()
{
	timespec ts;
	clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

long g_sink = 0;

// ns per item of f(i) over i in [0, n), reps times.
double TimeOnce(const std::function<int(int)>& f, int n, int reps)
{
	double start = ThreadSeconds();
	for (int r = 0; r < reps; ++r)
	{
		for (int i = 0; i < n; ++i)
		{
			g_sink += f(i);
		}
	}
	return (ThreadSeconds() - start) * 1e9 / ((double)reps * (double)n);
}

int Calibrate(const std::function<int(int)>& f, int n, double seconds)
{
	int reps = 1;
	while (reps < (1 << 20) && TimeOnce(f, n, reps) * 1e-9 * (double)reps * (double)n < seconds)
	{
		reps *= 2;
	}
	return reps;
}

double Median(std::vector<double> v)
{
	std::sort(v.begin(), v.end());
	return v[v.size() / 2];
}

struct Column
{
	const char* peer; // nullptr: collide
	std::function<int(int)> f;
};

struct Options
{
	int runs = 9;
	double seconds = 0.03;
	const char* filter = nullptr;
};

// Times collide and each peer in alternation; prints one line per peer.
void Row(const Options& o, const char* name, int n, const std::function<int(int)>& mine,
		 const std::vector<Column>& peers)
{
	if (o.filter != nullptr && std::strstr(name, o.filter) == nullptr)
	{
		return;
	}
	std::vector<int> reps;
	reps.push_back(Calibrate(mine, n, o.seconds));
	for (const Column& c : peers)
	{
		reps.push_back(Calibrate(c.f, n, o.seconds));
	}
	std::vector<std::vector<double>> samples(peers.size() + 1);
	for (int run = 0; run < o.runs; ++run)
	{
		samples[0].push_back(TimeOnce(mine, n, reps[0]));
		for (size_t p = 0; p < peers.size(); ++p)
		{
			samples[p + 1].push_back(TimeOnce(peers[p].f, n, reps[p + 1]));
		}
	}
	double m = Median(samples[0]);
	if (peers.empty())
	{
		std::printf("%-40s %9.1f %-26s %9s %7s\n", name, m, "(no peer built)", "", "");
	}
	for (size_t p = 0; p < peers.size(); ++p)
	{
		double t = Median(samples[p + 1]);
		std::printf("%-40s %9.1f %-26s %9.1f %7.2f\n", name, m, peers[p].peer, t, m / t);
	}
	std::fflush(stdout);
}

// ---- 2D ----------------------------------------------------------------------------------------
struct Body2
{
	cd2Polygon local; // in the body frame
	cd2Transform xf;
};

cd2Polygon MakeLocalPolygon(const sc_poly2& p)
{
	cd2Vec points[SC_POLY2_MAX];
	for (int i = 0; i < p.n; ++i)
	{
		points[i] = cd2MakeVec((cdReal)p.p[i][0], (cdReal)p.p[i][1]);
	}
	cd2Polygon out;
	if (cd2MakePolygon(points, p.n, &out) != CD_OK)
	{
		std::fprintf(stderr, "cd2MakePolygon failed\n");
		std::exit(1);
	}
	return out;
}

cd2Transform MakeTransform2(const double c[2], double angle)
{
	cd2Transform xf;
	xf.p = cd2MakeVec((cdReal)c[0], (cdReal)c[1]);
	xf.q = cd2MakeRot((cdReal)angle);
	return xf;
}

// B's polygon in A's frame, as a caller without a local-frame function must build it.
cd2Polygon PlaceInFrame(const cd2Polygon& p, cd2Transform xf)
{
	cd2Polygon out;
	out.count = p.count;
	out.radius = p.radius;
	for (int i = 0; i < p.count; ++i)
	{
		out.vertices[i] = cd2TransformPoint(xf, p.vertices[i]);
		out.normals[i] = cd2RotateVector(xf.q, p.normals[i]);
	}
	out.centroid = cd2TransformPoint(xf, p.centroid);
	return out;
}

#ifdef COLLIDE_BENCH_HAVE_BOX2D
b2PolygonShape ToBox2D(const sc_poly2& p)
{
	b2Vec2 points[b2_maxPolygonVertices];
	for (int i = 0; i < p.n; ++i)
	{
		points[i].Set((float)p.p[i][0], (float)p.p[i][1]);
	}
	b2PolygonShape shape;
	shape.Set(points, p.n);
	return shape;
}
b2Transform ToBox2D(const double c[2], double angle)
{
	b2Transform x;
	x.Set(b2Vec2((float)c[0], (float)c[1]), (float)angle);
	return x;
}

// Box2D's world output of a manifold (world normal, points and separations), as its solver
// builds it for a touching contact; returns pointCount (one separation is tested so that the
// result is used).
int Box2DWorldOutput(const b2Manifold& m, const b2Transform& xfA, float radiusA, const b2Transform& xfB,
					 float radiusB)
{
	if (m.pointCount == 0)
	{
		return 0;
	}
	b2WorldManifold w;
	w.Initialize(&m, xfA, radiusA, xfB, radiusB);
	return m.pointCount + (w.separations[0] > 1.0e30f ? 1 : 0);
}
#endif

// collide's world output of a manifold in A's frame (cd2CollideLocal and the ...Local functions):
// the normal rotated and the points moved by A's body transform, as the 2D world does for a
// touching contact; returns pointCount (the results are tested so that they are computed).
int WorldOutput(const cd2Manifold& m, cd2Transform xfA)
{
	if (m.pointCount == 0)
	{
		return 0;
	}
	cd2Vec normal = cd2RotateVector(xfA.q, m.normal);
	cdReal check = normal.x + normal.y;
	for (int k = 0; k < m.pointCount; ++k)
	{
		cd2Vec point = cd2TransformPoint(xfA, m.points[k].point);
		check += point.x + point.y + m.points[k].separation;
	}
	return m.pointCount + (check > (cdReal)1.0e30 ? 1 : 0);
}

struct Set2
{
	std::vector<Body2> a, b;
	std::vector<cd2Circle> circle; // local (centred), kind 2
	std::vector<cd2Transform> xfCircle;
#ifdef COLLIDE_BENCH_HAVE_BOX2D
	std::vector<b2PolygonShape> pa, pb;
	std::vector<b2CircleShape> pc;
	std::vector<b2Transform> xa, xb, xc;
#endif
};

Set2 MakeSet2(int kind, uint64_t seed)
{
	sc_pair2* pairs = sc_gen_pairs2(kind, SC_NPAIRS, seed);
	Set2 s;
	for (int i = 0; i < SC_NPAIRS; ++i)
	{
		const sc_pair2& p = pairs[i];
		s.a.push_back(Body2{MakeLocalPolygon(p.a), MakeTransform2(p.a.c, p.a.angle)});
#ifdef COLLIDE_BENCH_HAVE_BOX2D
		s.pa.push_back(ToBox2D(p.a));
		s.xa.push_back(ToBox2D(p.a.c, p.a.angle));
#endif
		if (kind == 2)
		{
			cd2Circle c;
			c.center = cd2MakeVec((cdReal)0, (cdReal)0);
			c.radius = (cdReal)p.cb.r;
			s.circle.push_back(c);
			s.xfCircle.push_back(MakeTransform2(p.cb.c, 0.0));
#ifdef COLLIDE_BENCH_HAVE_BOX2D
			b2CircleShape bc;
			bc.m_p.SetZero();
			bc.m_radius = (float)p.cb.r;
			s.pc.push_back(bc);
			s.xc.push_back(ToBox2D(p.cb.c, 0.0));
#endif
		}
		else
		{
			s.b.push_back(Body2{MakeLocalPolygon(p.b), MakeTransform2(p.b.c, p.b.angle)});
#ifdef COLLIDE_BENCH_HAVE_BOX2D
			s.pb.push_back(ToBox2D(p.b));
			s.xb.push_back(ToBox2D(p.b.c, p.b.angle));
#endif
		}
	}
	std::free(pairs);
	return s;
}

struct Toi2
{
	std::vector<cd2Shape> a, b;
	std::vector<cd2Sweep> sa, sb;
#ifdef COLLIDE_BENCH_HAVE_BOX2D
	std::vector<b2PolygonShape> pa, pb;
	std::vector<b2Sweep> wa, wb;
#endif
};

Toi2 MakeToi2()
{
	sc_toi2* t = sc_gen_toi2(SC_NPAIRS, SC_SEED_TOI2);
	Toi2 s;
	for (int i = 0; i < SC_NPAIRS; ++i)
	{
		cd2Polygon la = MakeLocalPolygon(t[i].a), lb = MakeLocalPolygon(t[i].b);
		s.a.push_back(cd2MakePolygonShape(&la));
		s.b.push_back(cd2MakePolygonShape(&lb));
		cd2Sweep a, b;
		a.localCenter = cd2MakeVec((cdReal)0, (cdReal)0);
		a.center0 = a.center1 = cd2MakeVec((cdReal)t[i].a.c[0], (cdReal)t[i].a.c[1]);
		a.angle0 = a.angle1 = (cdReal)t[i].a.angle;
		b.localCenter = a.localCenter;
		b.center0 = cd2MakeVec((cdReal)t[i].b_c0[0], (cdReal)t[i].b_c0[1]);
		b.center1 = cd2MakeVec((cdReal)t[i].b_c1[0], (cdReal)t[i].b_c1[1]);
		b.angle0 = (cdReal)t[i].b_a0;
		b.angle1 = (cdReal)t[i].b_a1;
		s.sa.push_back(a);
		s.sb.push_back(b);
#ifdef COLLIDE_BENCH_HAVE_BOX2D
		s.pa.push_back(ToBox2D(t[i].a));
		s.pb.push_back(ToBox2D(t[i].b));
		b2Sweep wa, wb;
		wa.localCenter.SetZero();
		wa.c0.Set((float)t[i].a.c[0], (float)t[i].a.c[1]);
		wa.c = wa.c0;
		wa.a0 = wa.a = (float)t[i].a.angle;
		wa.alpha0 = 0.0f;
		wb.localCenter.SetZero();
		wb.c0.Set((float)t[i].b_c0[0], (float)t[i].b_c0[1]);
		wb.c.Set((float)t[i].b_c1[0], (float)t[i].b_c1[1]);
		wb.a0 = (float)t[i].b_a0;
		wb.a = (float)t[i].b_a1;
		wb.alpha0 = 0.0f;
		s.wa.push_back(wa);
		s.wb.push_back(wb);
#endif
	}
	std::free(t);
	return s;
}

// ---- 3D boxes ----------------------------------------------------------------------------------
struct Box3Set
{
	std::vector<cd3Box> a, b; // local: centred, unrotated
	std::vector<cd3Transform> xa, xb;
#ifdef COLLIDE_BENCH_HAVE_BULLET
	std::vector<btBoxShape*> ba, bb;
	std::vector<btTransform> ta, tb;
#endif
};

Box3Set MakeBox3()
{
	sc_pair3* pairs = sc_gen_pairs3(SC_BOX, 0, SC_NPAIRS, SC_SEED_BOX3);
	Box3Set s;
	for (int i = 0; i < SC_NPAIRS; ++i)
	{
		const sc_box3* boxes[2] = {&pairs[i].a.u.box, &pairs[i].b.u.box};
		for (int k = 0; k < 2; ++k)
		{
			const sc_box3& x = *boxes[k];
			cd3Box box;
			box.center = cd3MakeVec((cdReal)0, (cdReal)0, (cdReal)0);
			box.halfExtents = cd3MakeVec((cdReal)x.h[0], (cdReal)x.h[1], (cdReal)x.h[2]);
			box.rotation = cd3MakeQuat((cdReal)0, (cdReal)0, (cdReal)0, (cdReal)1);
			cd3Transform xf;
			xf.p = cd3MakeVec((cdReal)x.c[0], (cdReal)x.c[1], (cdReal)x.c[2]);
			xf.q = cd3MakeQuat((cdReal)x.q[0], (cdReal)x.q[1], (cdReal)x.q[2], (cdReal)x.q[3]);
			(k == 0 ? s.a : s.b).push_back(box);
			(k == 0 ? s.xa : s.xb).push_back(xf);
#ifdef COLLIDE_BENCH_HAVE_BULLET
			(k == 0 ? s.ba : s.bb)
				.push_back(new btBoxShape(btVector3((btScalar)x.h[0], (btScalar)x.h[1], (btScalar)x.h[2])));
			btTransform t;
			t.setOrigin(btVector3((btScalar)x.c[0], (btScalar)x.c[1], (btScalar)x.c[2]));
			t.setRotation(
				btQuaternion((btScalar)x.q[0], (btScalar)x.q[1], (btScalar)x.q[2], (btScalar)x.q[3]));
			(k == 0 ? s.ta : s.tb).push_back(t);
#endif
		}
	}
	std::free(pairs);
	return s;
}

#ifdef COLLIDE_BENCH_HAVE_BULLET
struct CountResult : btDiscreteCollisionDetectorInterface::Result
{
	int count = 0;
	void setShapeIdentifiersA(int, int) override
	{
	}
	void setShapeIdentifiersB(int, int) override
	{
	}
	void addContactPoint(const btVector3&, const btVector3&, btScalar) override
	{
		++count;
	}
};
#endif
} // namespace

int main(int argc, char** argv)
{
	Options o;
	for (int i = 1; i < argc; ++i)
	{
		if (std::strcmp(argv[i], "--quick") == 0)
		{
			o.runs = 1;
			o.seconds = 0.0;
		}
		else if (std::strcmp(argv[i], "--filter") == 0 && i + 1 < argc)
		{
			o.filter = argv[++i];
		}
		else
		{
			std::fprintf(stderr, "usage: collide_bench_scenes [--quick] [--filter TEXT]\n");
			return 2;
		}
	}
	bool quick = o.runs == 1;
	std::printf("collide_bench_scenes (cdReal = %s): ns per query, median of %d runs, %d pairs per set;\n"
				"shapes in body frames, B placed in A's frame inside the timed loop\n",
				sizeof(cdReal) == sizeof(double) ? "double" : "float", o.runs, SC_NPAIRS);
	std::printf("%-40s %9s %-26s %9s %7s\n", "query", "collide", "peer", "peer ns", "ratio");

	// Box2D 2.4 reports polygon contacts up to 2 * b2_polygonRadius apart; collide's sharp polygons
	// get the same margin as a speculative distance.
	const cdReal speculative = (cdReal)(4.0 * 0.005);
	const cdReal slop = (cdReal)0.005;

	for (int kind = 0; kind < 2; ++kind)
	{
		Set2 s = MakeSet2(kind, kind == 0 ? SC_SEED_BOX2 : SC_SEED_POLY2);
		auto mine = [&s, speculative](int i) {
			cd2Transform xf = cd2InvMulTransforms(s.a[(size_t)i].xf, s.b[(size_t)i].xf);
			return cd2CollidePolygonPolygonLocal(&s.a[(size_t)i].local, &s.b[(size_t)i].local, xf,
												 speculative)
				.pointCount;
		};
		std::vector<Column> peers;
#ifdef COLLIDE_BENCH_HAVE_BOX2D
		peers.push_back(Column{"box2d-2.4 b2CollidePolygons", [&s](int i) {
								   b2Manifold m;
								   b2CollidePolygons(&m, &s.pa[(size_t)i], s.xa[(size_t)i], &s.pb[(size_t)i],
													 s.xb[(size_t)i]);
								   return m.pointCount;
							   }});
#endif
		Row(o, kind == 0 ? "2D manifold box-box" : "2D manifold polygon-polygon", SC_NPAIRS, mine, peers);

		auto mineWorld = [&s, speculative](int i) {
			cd2Transform xf = cd2InvMulTransforms(s.a[(size_t)i].xf, s.b[(size_t)i].xf);
			return WorldOutput(
				cd2CollidePolygonPolygonLocal(&s.a[(size_t)i].local, &s.b[(size_t)i].local, xf, speculative),
				s.a[(size_t)i].xf);
		};
		std::vector<Column> worldPeers;
#ifdef COLLIDE_BENCH_HAVE_BOX2D
		worldPeers.push_back(Column{"box2d-2.4 +b2WorldManifold", [&s](int i) {
										b2Manifold m;
										b2CollidePolygons(&m, &s.pa[(size_t)i], s.xa[(size_t)i],
														  &s.pb[(size_t)i], s.xb[(size_t)i]);
										return Box2DWorldOutput(m, s.xa[(size_t)i], s.pa[(size_t)i].m_radius,
																s.xb[(size_t)i], s.pb[(size_t)i].m_radius);
									}});
#endif
		Row(o, kind == 0 ? "2D manifold box-box, world output" : "2D manifold polygon, world output",
			SC_NPAIRS, mineWorld, worldPeers);

		// The 2D world's call: the tagged-shape dispatcher in the local frame.
		std::vector<cd2Shape> ta, tb;
		for (int i = 0; i < SC_NPAIRS; ++i)
		{
			ta.push_back(cd2MakePolygonShape(&s.a[(size_t)i].local));
			tb.push_back(cd2MakePolygonShape(&s.b[(size_t)i].local));
		}
		auto dispatch = [&](int i) {
			cd2Transform xf = cd2InvMulTransforms(s.a[(size_t)i].xf, s.b[(size_t)i].xf);
			return cd2CollideLocal(&ta[(size_t)i], &tb[(size_t)i], xf, speculative).pointCount;
		};
		Row(o, kind == 0 ? "2D manifold box-box, cd2CollideLocal" : "2D manifold polygon, cd2CollideLocal",
			SC_NPAIRS, dispatch, peers);

		if (kind == 1)
		{
			auto distance = [&](int i) {
				cd2Transform xf = cd2InvMulTransforms(s.a[(size_t)i].xf, s.b[(size_t)i].xf);
				cd2Shape b;
				b.type = CD2_SHAPE_POLYGON;
				b.polygon = PlaceInFrame(s.b[(size_t)i].local, xf);
				return (int)(cd2Distance(&ta[(size_t)i], &b).distance > (cdReal)0.1);
			};
			std::vector<Column> distancePeers;
#ifdef COLLIDE_BENCH_HAVE_BOX2D
			distancePeers.push_back(Column{"box2d-2.4 b2Distance", [&s](int i) {
											   b2DistanceInput input;
											   input.proxyA.Set(&s.pa[(size_t)i], 0);
											   input.proxyB.Set(&s.pb[(size_t)i], 0);
											   input.transformA = s.xa[(size_t)i];
											   input.transformB = s.xb[(size_t)i];
											   input.useRadii = false;
											   b2SimplexCache cache;
											   cache.count = 0;
											   b2DistanceOutput output;
											   b2Distance(&output, &cache, &input);
											   return (int)(output.distance > 0.1f);
										   }});
#endif
			Row(o, "2D distance polygon-polygon", SC_NPAIRS, distance, distancePeers);
			// The local-frame entry: only B's vertices are moved, inside the call.
			auto distanceLocal = [&](int i) {
				cd2Transform xf = cd2InvMulTransforms(s.a[(size_t)i].xf, s.b[(size_t)i].xf);
				return (int)(cd2DistanceLocal(&ta[(size_t)i], &tb[(size_t)i], xf).distance > (cdReal)0.1);
			};
			Row(o, "2D distance polygon, cd2DistanceLocal", SC_NPAIRS, distanceLocal, distancePeers);
		}
	}
	{
		Set2 s = MakeSet2(2, SC_SEED_CIRCLE2);
		// Box2D 2.4 reports circle-polygon contacts up to b2_polygonRadius apart (the polygon's
		// skin); collide's sharp polygon gets the same margin as a speculative distance.
		const cdReal skin = (cdReal)(2.0 * 0.005);
		auto mine = [&s, skin](int i) {
			cd2Transform xf = cd2InvMulTransforms(s.xfCircle[(size_t)i], s.a[(size_t)i].xf);
			return cd2CollideCirclePolygonLocal(s.circle[(size_t)i], &s.a[(size_t)i].local, xf, skin)
				.pointCount;
		};
		std::vector<Column> peers;
#ifdef COLLIDE_BENCH_HAVE_BOX2D
		peers.push_back(Column{"box2d-2.4 b2CollidePolygonAndCircle", [&s](int i) {
								   b2Manifold m;
								   b2CollidePolygonAndCircle(&m, &s.pa[(size_t)i], s.xa[(size_t)i],
															 &s.pc[(size_t)i], s.xc[(size_t)i]);
								   return m.pointCount;
							   }});
#endif
		Row(o, "2D manifold circle-polygon", SC_NPAIRS, mine, peers);

		auto mineWorld = [&s, skin](int i) {
			cd2Transform xf = cd2InvMulTransforms(s.xfCircle[(size_t)i], s.a[(size_t)i].xf);
			return WorldOutput(
				cd2CollideCirclePolygonLocal(s.circle[(size_t)i], &s.a[(size_t)i].local, xf, skin),
				s.xfCircle[(size_t)i]);
		};
		std::vector<Column> worldPeers;
#ifdef COLLIDE_BENCH_HAVE_BOX2D
		worldPeers.push_back(Column{"box2d-2.4 +b2WorldManifold", [&s](int i) {
										b2Manifold m;
										b2CollidePolygonAndCircle(&m, &s.pa[(size_t)i], s.xa[(size_t)i],
																  &s.pc[(size_t)i], s.xc[(size_t)i]);
										return Box2DWorldOutput(m, s.xa[(size_t)i], s.pa[(size_t)i].m_radius,
																s.xc[(size_t)i], s.pc[(size_t)i].m_radius);
									}});
#endif
		Row(o, "2D manifold circle-polygon, world output", SC_NPAIRS, mineWorld, worldPeers);

		// The polygon as A, as Box2D 2.4's call takes it: only the circle's centre is placed in the
		// polygon's frame, and the manifold is reported there. cd2CollidePolygonCircleBodies takes
		// the two body transforms, as b2CollidePolygonAndCircle does; the Local form takes the
		// relative transform, composed in the loop (what collide's 2D world passes, having composed
		// it for the contact anyway).
		auto polygonFirst = [&s, skin](int i) {
			return cd2CollidePolygonCircleBodies(&s.a[(size_t)i].local, s.a[(size_t)i].xf,
												 s.circle[(size_t)i], s.xfCircle[(size_t)i], skin)
				.pointCount;
		};
		Row(o, "2D manifold polygon-circle", SC_NPAIRS, polygonFirst, peers);
		auto polygonFirstLocal = [&s, skin](int i) {
			cd2Transform xf = cd2InvMulTransforms(s.a[(size_t)i].xf, s.xfCircle[(size_t)i]);
			return cd2CollidePolygonCircleLocal(&s.a[(size_t)i].local, s.circle[(size_t)i], xf, skin)
				.pointCount;
		};
		Row(o, "2D manifold polygon-circle, Local form", SC_NPAIRS, polygonFirstLocal, peers);
		auto polygonFirstWorld = [&s, skin](int i) {
			return WorldOutput(cd2CollidePolygonCircleBodies(&s.a[(size_t)i].local, s.a[(size_t)i].xf,
															 s.circle[(size_t)i], s.xfCircle[(size_t)i],
															 skin),
							   s.a[(size_t)i].xf);
		};
		Row(o, "2D manifold polygon-circle, world output", SC_NPAIRS, polygonFirstWorld, worldPeers);
	}
	{
		Toi2 s = MakeToi2();
		auto mine = [&s, slop](int i) {
			return (int)cd2TimeOfImpact(&s.a[(size_t)i], &s.sa[(size_t)i], &s.b[(size_t)i], &s.sb[(size_t)i],
										slop, (cdReal)0.25 * slop)
				.state;
		};
		std::vector<Column> peers;
#ifdef COLLIDE_BENCH_HAVE_BOX2D
		peers.push_back(Column{"box2d-2.4 b2TimeOfImpact", [&s](int i) {
								   b2TOIInput input;
								   input.proxyA.Set(&s.pa[(size_t)i], 0);
								   input.proxyB.Set(&s.pb[(size_t)i], 0);
								   input.sweepA = s.wa[(size_t)i];
								   input.sweepB = s.wb[(size_t)i];
								   input.tMax = 1.0f;
								   b2TOIOutput output;
								   b2TimeOfImpact(&output, &input);
								   return (int)output.state;
							   }});
#endif
		Row(o, "2D time of impact polygon-polygon", SC_NPAIRS, mine, peers);
	}
	{
		Box3Set s = MakeBox3();
		auto mine = [&s](int i) {
			cd3Transform xf = cd3InvMulTransforms(s.xa[(size_t)i], s.xb[(size_t)i]);
			return cd3CollideBoxBoxLocal(s.a[(size_t)i], s.b[(size_t)i], xf, (cdReal)0).pointCount;
		};
		std::vector<Column> peers;
#ifdef COLLIDE_BENCH_HAVE_BULLET
		peers.push_back(Column{"bullet btBoxBoxDetector", [&s](int i) {
								   btBoxBoxDetector detector(s.ba[(size_t)i], s.bb[(size_t)i]);
								   btDiscreteCollisionDetectorInterface::ClosestPointInput input;
								   input.m_transformA = s.ta[(size_t)i];
								   input.m_transformB = s.tb[(size_t)i];
								   CountResult result;
								   detector.getClosestPoints(input, result, nullptr);
								   return result.count;
							   }});
#endif
		Row(o, "3D box-box depth + manifold", SC_NPAIRS, mine, peers);
#ifdef COLLIDE_BENCH_HAVE_BULLET
		for (size_t i = 0; i < s.ba.size(); ++i)
		{
			delete s.ba[i];
			delete s.bb[i];
		}
#endif
	}
	if (o.filter == nullptr || std::strstr("3D closest-hit ray, height field 100k", o.filter) != nullptr)
	{
		sc_mesh m = sc_gen_heightfield(SC_MESH_NX, SC_MESH_NY, SC_SEED_MESH);
		int rayCount = quick ? 2000 : 200000;
		sc_ray* rays = sc_gen_rays(rayCount, SC_MESH_NX, SC_MESH_NY, SC_SEED_RAYS);
		std::vector<cd3Vec> vertices;
		for (int i = 0; i < m.nv; ++i)
		{
			vertices.push_back(
				cd3MakeVec((cdReal)m.v[3 * i], (cdReal)m.v[3 * i + 1], (cdReal)m.v[3 * i + 2]));
		}
		cd3Mesh* mesh = nullptr;
		if (cd3CreateMesh(vertices.data(), m.nv, m.idx, m.nt, &mesh) != CD_OK)
		{
			std::fprintf(stderr, "cd3CreateMesh failed\n");
			return 1;
		}
		std::vector<cd3Ray> cdRays((size_t)rayCount);
		for (int i = 0; i < rayCount; ++i)
		{
			const sc_ray& r = rays[i];
			cdRays[(size_t)i].origin = cd3MakeVec((cdReal)r.o[0], (cdReal)r.o[1], (cdReal)r.o[2]);
			cdRays[(size_t)i].translation =
				cd3MakeVec((cdReal)(r.d[0] * r.len), (cdReal)(r.d[1] * r.len), (cdReal)(r.d[2] * r.len));
		}
		cd3Transform identity;
		identity.p = cd3MakeVec((cdReal)0, (cdReal)0, (cdReal)0);
		identity.q = cd3MakeQuat((cdReal)0, (cdReal)0, (cdReal)0, (cdReal)1);
		auto mine = [&](int i) {
			cd3MeshRayHit hit;
			return (int)cd3RaycastMesh(mesh, identity, cdRays[(size_t)i], &hit);
		};
		int hitsMine = 0;
		for (int i = 0; i < rayCount; ++i)
		{
			hitsMine += mine(i);
		}
		std::vector<Column> peers;
#ifdef COLLIDE_BENCH_HAVE_ODE
		dInitODE2(0);
		std::vector<dTriIndex> odeIndices(m.idx, m.idx + 3 * m.nt);
		dTriMeshDataID data = dGeomTriMeshDataCreate();
		dGeomTriMeshDataBuildSingle(data, m.v, 3 * (int)sizeof(float), m.nv, odeIndices.data(), 3 * m.nt,
									3 * (int)sizeof(dTriIndex));
		dGeomID odeMesh = dCreateTriMesh(nullptr, data, nullptr, nullptr, nullptr);
		dGeomID odeRay = dCreateRay(nullptr, 30.0);
		dGeomRaySetClosestHit(odeRay, 1);
		auto ode = [&](int i) {
			const sc_ray& r = rays[i];
			dGeomRaySet(odeRay, r.o[0], r.o[1], r.o[2], r.d[0], r.d[1], r.d[2]);
			dGeomRaySetLength(odeRay, r.len);
			dContactGeom contact;
			return dCollide(odeRay, odeMesh, 1, &contact, (int)sizeof(dContactGeom));
		};
		int hitsOde = 0;
		for (int i = 0; i < rayCount; ++i)
		{
			hitsOde += ode(i);
		}
		std::printf("mesh rays: %d rays, %d triangles; hits collide %d, ode %d\n", rayCount, m.nt, hitsMine,
					hitsOde);
		peers.push_back(Column{"ode dCollide(ray, trimesh)", ode});
#else
		std::printf("mesh rays: %d rays, %d triangles; hits collide %d; ODE not built (libode-dev)\n",
					rayCount, m.nt, hitsMine);
#endif
		Row(o, "3D closest-hit ray, height field 100k", rayCount, mine, peers);
#ifdef COLLIDE_BENCH_HAVE_ODE
		dGeomDestroy(odeRay);
		dGeomDestroy(odeMesh);
		dGeomTriMeshDataDestroy(data);
		dCloseODE();
#endif
		cd3DestroyMesh(mesh);
		std::free(rays);
		sc_free_mesh(&m);
	}
	if (g_sink == 42)
	{
		std::printf("\n");
	}
	return 0;
}
