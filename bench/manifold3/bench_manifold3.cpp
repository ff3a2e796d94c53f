// collide_bench_manifold3: ns per call of 3D convex pair queries (distance, overlap, depth,
// manifold) on box-box, hull(32)-hull(32), box-triangle, hull(8)-hull(8) and box-box-as-hulls pairs, with the
// peers that do the same job, on the same pairs in the same run: Bullet (btGjkEpaSolver2 for
// distance/overlap/depth, btBoxBoxDetector = ODE's box-box SAT and clipping, btGjkPairDetector +
// btGjkEpaPenetrationDepthSolver for the hull manifold), libccd (ccdGJKIntersect, ccdMPRIntersect,
// ccdGJKPenetration, ccdMPRPenetration) and FCL (fcl::distance, fcl::collide with its libccd-based GJK
// solver; its box-box contact is ODE's), each when pkg-config finds it.
//
// Pairs: unit-size shapes near contact, as a physics step sees them. Each set has kPairs
// overlapping pairs (depth 0.005 to 0.05) and kPairs separated pairs (gap 0.005 to 0.05):
// distance runs on the separated ones, depth and manifold on the overlapping ones, overlap on
// all. Half the box pairs rest face on face (a stack), half are at random; hulls have 32 vertices
// on random ellipsoids; half the boxes on triangles (terrain pieces about the box's size) rest a
// face on the triangle, half are at random; hull(8) have 8 vertices on a jittered sphere (18 edges);
// "box-box as hulls" are the box-box pairs given to every library as hulls (collide: cd3MakeBoxHull).
// Bullet's box-triangle manifold is its GJK-EPA pair detector on a btTriangleShape, as for hulls.
// collide has no depth-only query: its depth row is the manifold
// call (the depth is the manifold's smallest separation), so depth and manifold rows time the same call.
//
// Answers are checked against an exact reference computed here in double: the separating axis
// test over every face normal and every edge pair (a superset of the critical axes, so its
// largest separation is the exact signed separation for overlapping pairs and its sign decides
// overlap exactly). Printed per peer: overlap counts (reference: the SAT sign), and the max and
// mean relative depth error against the reference depth; distances against collide's.
//
// Timing: each figure is the median of 9 runs of about 20 ms of thread CPU time (so that other
// processes on a shared machine stall no one's clock), all queries' runs interleaved.
// The "manifold, local frame" rows time the local-frame form on the same pairs as a solver calls
// it: shapes in body frames, the relative transform computed from the body transforms in each call.
// Usage: collide_bench_manifold3 [--quick]
#include <BulletCollision/CollisionDispatch/btBoxBoxDetector.h>
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/CollisionShapes/btTriangleShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpa2.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>
#ifdef COLLIDE_BENCH_HAVE_CCD
#include <ccd/ccd.h>
#endif
#ifdef COLLIDE_BENCH_HAVE_FCL
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/convex.h>
#include <fcl/geometry/shape/triangle_p.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>
#endif

#include "collide/collide.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace
{
const int kPairs = 256; // overlapping pairs; as many separated ones

btTransform ToBullet(cd3Transform t)
{
	return btTransform(btQuaternion((btScalar)t.q.x, (btScalar)t.q.y, (btScalar)t.q.z, (btScalar)t.q.w),
					   btVector3((btScalar)t.p.x, (btScalar)t.p.y, (btScalar)t.p.z));
}

cd3Quat RandomRotation(std::mt19937_64& rng)
{
	std::normal_distribution<double> g(0.0, 1.0);
	double x = g(rng), y = g(rng), z = g(rng), w = g(rng);
	double n = std::sqrt(x * x + y * y + z * z + w * w);
	return cd3MakeQuat((cdReal)(x / n), (cdReal)(y / n), (cdReal)(z / n), (cdReal)(w / n));
}

cd3Vec RandomUnit(std::mt19937_64& rng)
{
	std::normal_distribution<double> g(0.0, 1.0);
	return cd3Normalize(cd3MakeVec((cdReal)g(rng), (cdReal)g(rng), (cdReal)g(rng)));
}

double MinSeparation(const cd3Manifold& m)
{
	double s = INFINITY;
	for (int i = 0; i < m.pointCount; ++i)
	{
		s = std::min(s, (double)m.points[i].separation);
	}
	return s;
}

// Moves B along the manifold normal until the pair's signed separation is `separation` (a few
// refinements).
template <typename Collide, typename Move>
void PlaceAtSeparation(Collide collide, Move move, double separation)
{
	for (int k = 0; k < 6; ++k)
	{
		cd3Manifold m = collide(CD_R(100.0));
		if (m.pointCount == 0)
		{
			return;
		}
		move(cd3Scale((cdReal)(separation - MinSeparation(m)), m.normal));
	}
}

// ---- exact reference: SAT in double over every face normal and edge pair ----

struct D3
{
	double x, y, z;
};
D3 Sub(D3 a, D3 b)
{
	return {a.x - b.x, a.y - b.y, a.z - b.z};
}
double Dot(D3 a, D3 b)
{
	return a.x * b.x + a.y * b.y + a.z * b.z;
}
D3 Cross(D3 a, D3 b)
{
	return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
D3 Rotate(cd3Quat q, D3 v)
{
	D3 u = {(double)q.x, (double)q.y, (double)q.z};
	double w = (double)q.w;
	D3 t = Cross(u, v);
	t = {2 * t.x, 2 * t.y, 2 * t.z};
	D3 c = Cross(u, t);
	return {v.x + w * t.x + c.x, v.y + w * t.y + c.y, v.z + w * t.z + c.z};
}

struct RefPolytope
{
	std::vector<D3> vertices, normals, edges; // world
};

RefPolytope RefBox(cd3Box b)
{
	RefPolytope p;
	D3 c = {(double)b.center.x, (double)b.center.y, (double)b.center.z};
	D3 h = {(double)b.halfExtents.x, (double)b.halfExtents.y, (double)b.halfExtents.z};
	for (int i = 0; i < 8; ++i)
	{
		D3 local = {(i & 1) ? h.x : -h.x, (i & 2) ? h.y : -h.y, (i & 4) ? h.z : -h.z};
		D3 r = Rotate(b.rotation, local);
		p.vertices.push_back({c.x + r.x, c.y + r.y, c.z + r.z});
	}
	D3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
	for (D3 a : axes)
	{
		p.normals.push_back(Rotate(b.rotation, a));
		p.edges.push_back(Rotate(b.rotation, a));
	}
	return p;
}

RefPolytope RefHull(cd3HullShape s)
{
	RefPolytope p;
	const cd3Hull* h = s.hull;
	D3 c = {(double)s.transform.p.x, (double)s.transform.p.y, (double)s.transform.p.z};
	for (int i = 0; i < h->vertexCount; ++i)
	{
		D3 r = Rotate(s.transform.q,
					  {(double)h->vertices[i].x, (double)h->vertices[i].y, (double)h->vertices[i].z});
		p.vertices.push_back({c.x + r.x, c.y + r.y, c.z + r.z});
	}
	for (int f = 0; f < h->faceCount; ++f)
	{
		cd3Vec n = h->planes[f].normal;
		p.normals.push_back(Rotate(s.transform.q, {(double)n.x, (double)n.y, (double)n.z}));
	}
	for (int e = 0; e < h->edgeCount; ++e)
	{
		if (h->edges[e].twin > e)
		{
			p.edges.push_back(Sub(p.vertices[(size_t)h->edges[h->edges[e].twin].origin],
								  p.vertices[(size_t)h->edges[e].origin]));
		}
	}
	return p;
}

RefPolytope RefTriangle(cd3Triangle t)
{
	RefPolytope p;
	for (cd3Vec v : {t.a, t.b, t.c})
	{
		p.vertices.push_back({(double)v.x, (double)v.y, (double)v.z});
	}
	p.normals.push_back(Cross(Sub(p.vertices[1], p.vertices[0]), Sub(p.vertices[2], p.vertices[0])));
	double l = std::sqrt(Dot(p.normals[0], p.normals[0]));
	p.normals[0] = {p.normals[0].x / l, p.normals[0].y / l, p.normals[0].z / l};
	for (int e = 0; e < 3; ++e)
	{
		p.edges.push_back(Sub(p.vertices[(size_t)(e + 1) % 3], p.vertices[(size_t)e]));
	}
	return p;
}

double AxisSeparation(const RefPolytope& a, const RefPolytope& b, D3 n)
{
	double loA = INFINITY, hiA = -INFINITY, loB = INFINITY, hiB = -INFINITY;
	for (D3 v : a.vertices)
	{
		double d = Dot(n, v);
		loA = std::min(loA, d);
		hiA = std::max(hiA, d);
	}
	for (D3 v : b.vertices)
	{
		double d = Dot(n, v);
		loB = std::min(loB, d);
		hiB = std::max(hiB, d);
	}
	return std::max(loB - hiA, loA - hiB);
}

// The exact signed separation (minus the depth when overlapping; a lower bound of the distance
// when apart, whose sign is exact).
double ReferenceSeparation(const RefPolytope& a, const RefPolytope& b)
{
	double best = -INFINITY;
	for (D3 n : a.normals)
	{
		best = std::max(best, AxisSeparation(a, b, n));
	}
	for (D3 n : b.normals)
	{
		best = std::max(best, AxisSeparation(a, b, n));
	}
	for (D3 ea : a.edges)
	{
		for (D3 eb : b.edges)
		{
			D3 n = Cross(ea, eb);
			double l = std::sqrt(Dot(n, n));
			if (l > 1e-9 * std::sqrt(Dot(ea, ea) * Dot(eb, eb)))
			{
				best = std::max(best, AxisSeparation(a, b, {n.x / l, n.y / l, n.z / l}));
			}
		}
	}
	return best;
}

// ---- timing ----

double ThreadSeconds()
{
	timespec t;
	clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
	return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

double Median(std::vector<double> v)
{
	std::sort(v.begin(), v.end());
	return v[v.size() / 2];
}

// A timed query: its body runs over `calls` pairs and returns a checksum.
struct Query
{
	std::function<int()> body;
	int calls;
	double ns;
};

void MeasureAll(std::vector<Query*>& queries, int runs, double seconds)
{
	std::vector<std::vector<double>> samples(queries.size());
	volatile int sink = 0;
	for (int r = 0; r < runs; ++r)
	{
		for (size_t q = 0; q < queries.size(); ++q)
		{
			double start = ThreadSeconds(), elapsed = 0.0;
			long calls = 0;
			do
			{
				sink = sink + queries[q]->body();
				calls += queries[q]->calls;
				elapsed = ThreadSeconds() - start;
			} while (elapsed < seconds);
			samples[q].push_back(elapsed * 1e9 / (double)calls);
		}
	}
	for (size_t q = 0; q < queries.size(); ++q)
	{
		queries[q]->ns = Median(samples[q]);
	}
}

struct CountResult : btDiscreteCollisionDetectorInterface::Result
{
	int count = 0;
	double depth = 0.0;
	void setShapeIdentifiersA(int, int) override
	{
	}
	void setShapeIdentifiersB(int, int) override
	{
	}
	void addContactPoint(const btVector3&, const btVector3&, btScalar d) override
	{
		++count;
		depth = std::min(depth, (double)d);
	}
};

#ifdef COLLIDE_BENCH_HAVE_CCD
// A libccd object: a box or a hull with its transform; the support function loops over the
// vertices (hull) or picks the corner by signs (box), in the shape's frame, like collide's.
struct CcdObject
{
	const cd3Hull* hull; // NULL: a box, or a triangle when isTriangle
	cd3Vec halfExtents;
	cd3Transform transform;
	bool isTriangle;
	cd3Vec corners[3]; // the triangle's, in its frame
};

void CcdSupport(const void* object, const ccd_vec3_t* dir, ccd_vec3_t* out)
{
	const CcdObject* o = (const CcdObject*)object;
	cd3Vec d = cd3InvRotateVector(o->transform.q,
								  cd3MakeVec((cdReal)dir->v[0], (cdReal)dir->v[1], (cdReal)dir->v[2]));
	cd3Vec local;
	if (o->isTriangle)
	{
		int best = 0;
		for (int i = 1; i < 3; ++i)
		{
			best = cd3Dot(d, o->corners[i]) > cd3Dot(d, o->corners[best]) ? i : best;
		}
		local = o->corners[best];
	}
	else if (o->hull == nullptr)
	{
		cd3Vec h = o->halfExtents;
		local = cd3MakeVec(d.x >= 0 ? h.x : -h.x, d.y >= 0 ? h.y : -h.y, d.z >= 0 ? h.z : -h.z);
	}
	else
	{
		int best = 0;
		cdReal bestDot = cd3Dot(d, o->hull->vertices[0]);
		for (int i = 1; i < o->hull->vertexCount; ++i)
		{
			cdReal x = cd3Dot(d, o->hull->vertices[i]);
			if (x > bestDot)
			{
				bestDot = x;
				best = i;
			}
		}
		local = o->hull->vertices[best];
	}
	cd3Vec p = cd3TransformPoint(o->transform, local);
	ccdVec3Set(out, p.x, p.y, p.z);
}

void CcdCenter(const void* object, ccd_vec3_t* out)
{
	const CcdObject* o = (const CcdObject*)object;
	cd3Vec c = o->isTriangle
				   ? cd3TransformPoint(o->transform,
									   cd3Scale(CD_R(1.0) / CD_R(3.0),
												cd3Add(o->corners[0], cd3Add(o->corners[1], o->corners[2]))))
			   : o->hull == nullptr ? o->transform.p
									: cd3TransformPoint(o->transform, o->hull->centroid);
	ccdVec3Set(out, c.x, c.y, c.z);
}
#endif

#ifdef COLLIDE_BENCH_HAVE_FCL
fcl::Transform3d ToFcl(cd3Transform t)
{
	fcl::Transform3d x = fcl::Transform3d::Identity();
	x.linear() =
		Eigen::Quaterniond((double)t.q.w, (double)t.q.x, (double)t.q.y, (double)t.q.z).toRotationMatrix();
	x.translation() = Eigen::Vector3d((double)t.p.x, (double)t.p.y, (double)t.p.z);
	return x;
}

std::shared_ptr<fcl::CollisionGeometryd> FclHull(const cd3Hull* h)
{
	auto vertices = std::make_shared<std::vector<Eigen::Vector3d>>();
	for (int i = 0; i < h->vertexCount; ++i)
	{
		vertices->emplace_back((double)h->vertices[i].x, (double)h->vertices[i].y, (double)h->vertices[i].z);
	}
	auto faces = std::make_shared<std::vector<int>>();
	for (int f = 0; f < h->faceCount; ++f)
	{
		std::vector<int> loop;
		int e = h->faceEdges[f];
		do
		{
			loop.push_back(h->edges[e].origin);
			e = h->edges[e].next;
		} while (e != h->faceEdges[f]);
		faces->push_back((int)loop.size());
		faces->insert(faces->end(), loop.begin(), loop.end());
	}
	return std::make_shared<fcl::Convexd>(vertices, h->faceCount, faces);
}
#endif

// One pair kind (box-box, hull-hull or box-triangle): the shapes in every library's form.
struct PairSet
{
	std::string name;
	std::string collideManifold;   // the function the manifold row times
	bool boxBoxPeer = false;	   // Bullet's manifold: btBoxBoxDetector, else its GJK-EPA pair detector
	bool fclPairs = true;		   // false: FCL has no such pair (its box-triangle answers no contact)
	std::vector<cd3Shape> a, b;	   // 2 kPairs: even overlapping, odd separated
	std::vector<double> reference; // exact signed separation (SAT), as above
	std::vector<const btConvexShape*> btA, btB;
	std::vector<btTransform> xa, xb;
#ifdef COLLIDE_BENCH_HAVE_CCD
	std::vector<CcdObject> ccdA, ccdB;
#endif
#ifdef COLLIDE_BENCH_HAVE_FCL
	std::vector<std::shared_ptr<fcl::CollisionGeometryd>> fclA, fclB;
	std::vector<fcl::Transform3d> fxa, fxb;
#endif
};

cd3Manifold CollideShapes(const cd3Shape& a, const cd3Shape& b, cdReal speculative)
{
	if (a.type == CD3_SHAPE_BOX && b.type == CD3_SHAPE_TRIANGLE)
	{
		return cd3CollideBoxTriangle(a.box, b.triangle, speculative);
	}
	if (a.type == CD3_SHAPE_BOX)
	{
		return cd3CollideBoxBox(a.box, b.box, speculative);
	}
	return cd3CollideHullHull(a.hull, b.hull, speculative);
}

// A shape split into its body frame and the body's transform, the way a solver stores it.
struct BodyShape
{
	cd3Shape local;
	cd3Transform transform;
};

BodyShape InBodyFrame(const cd3Shape& shape)
{
	BodyShape body{shape, CD3_TRANSFORM_IDENTITY};
	if (shape.type == CD3_SHAPE_BOX)
	{
		body.transform = {shape.box.center, shape.box.rotation};
		body.local.box.center = cd3MakeVec(0, 0, 0);
		body.local.box.rotation = CD3_QUAT_IDENTITY;
	}
	else if (shape.type == CD3_SHAPE_HULL)
	{
		body.transform = shape.hull.transform;
		body.local.hull.transform = CD3_TRANSFORM_IDENTITY;
	}
	return body; // triangles: terrain, its body at the origin
}

// The local-frame form as a solver calls it: the relative transform from the two body transforms,
// then the pair function in A's frame.
cd3Manifold CollideBodies(const BodyShape& a, const BodyShape& b, cdReal speculative)
{
	cd3Transform xf = cd3InvMulTransforms(a.transform, b.transform);
	if (a.local.type == CD3_SHAPE_BOX && b.local.type == CD3_SHAPE_TRIANGLE)
	{
		return cd3CollideBoxTriangleLocal(a.local.box, b.local.triangle, xf, speculative);
	}
	if (a.local.type == CD3_SHAPE_BOX)
	{
		return cd3CollideBoxBoxLocal(a.local.box, b.local.box, xf, speculative);
	}
	return cd3CollideHullHullLocal(a.local.hull, b.local.hull, xf, speculative);
}

struct Stats
{
	double maxError = 0.0, sumError = 0.0;
	int count = 0, failed = 0;
	void Add(double value, double reference)
	{
		double e = std::fabs(value - reference) / std::fabs(reference);
		maxError = std::max(maxError, e);
		sumError += e;
		++count;
	}
	std::string Text() const
	{
		char s[96];
		std::snprintf(s, sizeof s, "max %.1e mean %.1e (%d pairs%s)", maxError,
					  count ? sumError / count : 0.0, count,
					  failed ? (", " + std::to_string(failed) + " no answer").c_str() : "");
		return s;
	}
};
} // namespace

int main(int argc, char** argv)
{
	bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
	int runs = quick ? 3 : 9;
	double seconds = quick ? 0.005 : 0.02;
	std::mt19937_64 rng(20261121);
	std::uniform_real_distribution<double> u(0.0, 1.0);
	const int n = 2 * kPairs;
	auto signedGap = [&](int i) { return (i % 2 == 0 ? -1.0 : 1.0) * (0.005 + 0.045 * u(rng)); };

	// ---- box-box ----
	PairSet boxes;
	boxes.name = "box-box";
	boxes.collideManifold = "cd3CollideBoxBox";
	boxes.boxBoxPeer = true;
	std::vector<std::unique_ptr<btBoxShape>> btBoxes;
	for (int i = 0; i < n; ++i)
	{
		cd3Box a, b;
		a.halfExtents = cd3MakeVec((cdReal)(0.3 + 0.4 * u(rng)), (cdReal)(0.3 + 0.4 * u(rng)),
								   (cdReal)(0.3 + 0.4 * u(rng)));
		b.halfExtents = cd3MakeVec((cdReal)(0.3 + 0.4 * u(rng)), (cdReal)(0.3 + 0.4 * u(rng)),
								   (cdReal)(0.3 + 0.4 * u(rng)));
		a.center = cd3MakeVec(0, 0, 0);
		a.rotation = RandomRotation(rng);
		// Half the pairs resting face on face (the common case in a stack), half at random.
		bool stacked = (i / 2) % 2 == 0;
		b.rotation = stacked ? a.rotation : RandomRotation(rng);
		b.center =
			cd3Scale(CD_R(1.5), stacked ? cd3RotateVector(a.rotation, cd3MakeVec(0, 1, 0)) : RandomUnit(rng));
		PlaceAtSeparation([&](cdReal s) { return cd3CollideBoxBox(a, b, s); },
						  [&](cd3Vec d) { b.center = cd3Add(b.center, d); }, signedGap(i));
		boxes.a.push_back(cd3MakeBoxShape(a));
		boxes.b.push_back(cd3MakeBoxShape(b));
		boxes.reference.push_back(ReferenceSeparation(RefBox(a), RefBox(b)));
		for (cd3Box box : {a, b})
		{
			btBoxes.emplace_back(new btBoxShape(btVector3(
				(btScalar)box.halfExtents.x, (btScalar)box.halfExtents.y, (btScalar)box.halfExtents.z)));
			btBoxes.back()->setMargin(0);
		}
		boxes.btA.push_back(btBoxes[btBoxes.size() - 2].get());
		boxes.btB.push_back(btBoxes.back().get());
		boxes.xa.push_back(ToBullet({a.center, a.rotation}));
		boxes.xb.push_back(ToBullet({b.center, b.rotation}));
#ifdef COLLIDE_BENCH_HAVE_CCD
		boxes.ccdA.push_back({nullptr, a.halfExtents, {a.center, a.rotation}, false, {}});
		boxes.ccdB.push_back({nullptr, b.halfExtents, {b.center, b.rotation}, false, {}});
#endif
#ifdef COLLIDE_BENCH_HAVE_FCL
		boxes.fclA.push_back(
			std::make_shared<fcl::Boxd>(2.0 * a.halfExtents.x, 2.0 * a.halfExtents.y, 2.0 * a.halfExtents.z));
		boxes.fclB.push_back(
			std::make_shared<fcl::Boxd>(2.0 * b.halfExtents.x, 2.0 * b.halfExtents.y, 2.0 * b.halfExtents.z));
		boxes.fxa.push_back(ToFcl({a.center, a.rotation}));
		boxes.fxb.push_back(ToFcl({b.center, b.rotation}));
#endif
	}

	// ---- hull(32)-hull(32) ----
	const int kHulls = 32;
	std::vector<cd3Hull*> hulls;
	std::vector<std::unique_ptr<btConvexHullShape>> btHulls;
#ifdef COLLIDE_BENCH_HAVE_FCL
	std::vector<std::shared_ptr<fcl::CollisionGeometryd>> fclHulls;
#endif
	for (int h = 0; h < kHulls; ++h)
	{
		cd3Hull* hull = nullptr;
		while (hull == nullptr || hull->vertexCount != 32)
		{
			cd3DestroyHull(hull);
			hull = nullptr;
			cd3Vec points[32];
			double sx = 0.4 + 0.3 * u(rng), sy = 0.4 + 0.3 * u(rng), sz = 0.4 + 0.3 * u(rng);
			for (auto& p : points)
			{
				cd3Vec d = RandomUnit(rng);
				p = cd3MakeVec((cdReal)(sx * d.x), (cdReal)(sy * d.y), (cdReal)(sz * d.z));
			}
			cd3ComputeHull(points, 32, &hull);
		}
		hulls.push_back(hull);
		auto shape = std::make_unique<btConvexHullShape>();
		for (int i = 0; i < hull->vertexCount; ++i)
		{
			shape->addPoint(btVector3((btScalar)hull->vertices[i].x, (btScalar)hull->vertices[i].y,
									  (btScalar)hull->vertices[i].z),
							false);
		}
		shape->recalcLocalAabb();
		shape->setMargin(0);
		btHulls.push_back(std::move(shape));
#ifdef COLLIDE_BENCH_HAVE_FCL
		fclHulls.push_back(FclHull(hull));
#endif
	}
	PairSet hullPairs;
	hullPairs.name = "hull(32)-hull(32)";
	hullPairs.collideManifold = "cd3CollideHullHull";
	for (int i = 0; i < n; ++i)
	{
		int ia = (int)(rng() % kHulls), ib = (int)(rng() % kHulls);
		cd3HullShape a = {hulls[(size_t)ia], {cd3MakeVec(0, 0, 0), RandomRotation(rng)}};
		cd3HullShape b = {hulls[(size_t)ib], {cd3Scale(CD_R(1.2), RandomUnit(rng)), RandomRotation(rng)}};
		PlaceAtSeparation([&](cdReal s) { return cd3CollideHullHull(a, b, s); },
						  [&](cd3Vec d) { b.transform.p = cd3Add(b.transform.p, d); }, signedGap(i));
		hullPairs.a.push_back(cd3MakeHullShape(a.hull, a.transform));
		hullPairs.b.push_back(cd3MakeHullShape(b.hull, b.transform));
		hullPairs.reference.push_back(ReferenceSeparation(RefHull(a), RefHull(b)));
		hullPairs.btA.push_back(btHulls[(size_t)ia].get());
		hullPairs.btB.push_back(btHulls[(size_t)ib].get());
		hullPairs.xa.push_back(ToBullet(a.transform));
		hullPairs.xb.push_back(ToBullet(b.transform));
#ifdef COLLIDE_BENCH_HAVE_CCD
		hullPairs.ccdA.push_back({a.hull, cd3MakeVec(0, 0, 0), a.transform, false, {}});
		hullPairs.ccdB.push_back({b.hull, cd3MakeVec(0, 0, 0), b.transform, false, {}});
#endif
#ifdef COLLIDE_BENCH_HAVE_FCL
		hullPairs.fclA.push_back(fclHulls[(size_t)ia]);
		hullPairs.fclB.push_back(fclHulls[(size_t)ib]);
		hullPairs.fxa.push_back(ToFcl(a.transform));
		hullPairs.fxb.push_back(ToFcl(b.transform));
#endif
	}

	// ---- box-triangle: a box on a piece of terrain ----
	PairSet boxTriangles;
	boxTriangles.name = "box-triangle";
	boxTriangles.collideManifold = "cd3CollideBoxTriangle";
	boxTriangles.fclPairs = false;
	std::vector<std::unique_ptr<btTriangleShape>> btTriangles;
	for (int i = 0; i < n; ++i)
	{
		cd3Box a;
		a.halfExtents = cd3MakeVec((cdReal)(0.3 + 0.4 * u(rng)), (cdReal)(0.3 + 0.4 * u(rng)),
								   (cdReal)(0.3 + 0.4 * u(rng)));
		a.center = cd3MakeVec(0, 0, 0);
		a.rotation = RandomRotation(rng);
		// A triangle of about the box's size under it: its plane through a point 1.5 below the box
		// centre, facing up (along the box's y axis when resting, at random otherwise).
		bool resting = (i / 2) % 2 == 0;
		cd3Vec up = resting ? cd3RotateVector(a.rotation, cd3MakeVec(0, 1, 0)) : RandomUnit(rng);
		cd3Vec side = cd3Normalize(cd3Cross(up, RandomUnit(rng)));
		cd3Vec other = cd3Cross(up, side);
		cd3Vec base = cd3Scale(CD_R(-1.5), up);
		cd3Triangle b;
		cd3Vec corners[3];
		for (int k = 0; k < 3; ++k)
		{
			double angle = 2.0943951023931957 * k + 0.4 * (u(rng) - 0.5);
			double radius = 0.8 + 0.8 * u(rng);
			corners[k] = cd3Add(base, cd3Add(cd3Scale((cdReal)(radius * std::cos(angle)), side),
											 cd3Scale((cdReal)(radius * std::sin(angle)), other)));
		}
		b = {corners[0], corners[1], corners[2]};
		PlaceAtSeparation([&](cdReal sp) { return cd3CollideBoxTriangle(a, b, sp); },
						  [&](cd3Vec d) {
							  b.a = cd3Add(b.a, d);
							  b.b = cd3Add(b.b, d);
							  b.c = cd3Add(b.c, d);
						  },
						  signedGap(i));
		boxTriangles.a.push_back(cd3MakeBoxShape(a));
		boxTriangles.b.push_back(cd3MakeTriangleShape(b));
		boxTriangles.reference.push_back(ReferenceSeparation(RefBox(a), RefTriangle(b)));
		btBoxes.emplace_back(new btBoxShape(
			btVector3((btScalar)a.halfExtents.x, (btScalar)a.halfExtents.y, (btScalar)a.halfExtents.z)));
		btBoxes.back()->setMargin(0);
		auto toBt = [](cd3Vec v) { return btVector3((btScalar)v.x, (btScalar)v.y, (btScalar)v.z); };
		btTriangles.emplace_back(new btTriangleShape(toBt(b.a), toBt(b.b), toBt(b.c)));
		btTriangles.back()->setMargin(0);
		boxTriangles.btA.push_back(btBoxes.back().get());
		boxTriangles.btB.push_back(btTriangles.back().get());
		boxTriangles.xa.push_back(ToBullet({a.center, a.rotation}));
		boxTriangles.xb.push_back(ToBullet(CD3_TRANSFORM_IDENTITY));
#ifdef COLLIDE_BENCH_HAVE_CCD
		boxTriangles.ccdA.push_back({nullptr, a.halfExtents, {a.center, a.rotation}, false, {}});
		boxTriangles.ccdB.push_back(
			{nullptr, cd3MakeVec(0, 0, 0), CD3_TRANSFORM_IDENTITY, true, {b.a, b.b, b.c}});
#endif
#ifdef COLLIDE_BENCH_HAVE_FCL
		boxTriangles.fclA.push_back(
			std::make_shared<fcl::Boxd>(2.0 * a.halfExtents.x, 2.0 * a.halfExtents.y, 2.0 * a.halfExtents.z));
		auto toFcl = [](cd3Vec v) { return Eigen::Vector3d((double)v.x, (double)v.y, (double)v.z); };
		boxTriangles.fclB.push_back(std::make_shared<fcl::TrianglePd>(toFcl(b.a), toFcl(b.b), toFcl(b.c)));
		boxTriangles.fxa.push_back(ToFcl({a.center, a.rotation}));
		boxTriangles.fxb.push_back(ToFcl(CD3_TRANSFORM_IDENTITY));
#endif
	}

	// ---- small hulls: hull(8)-hull(8) and boxes given as hulls ----
	// A hull pair set from hulls placed by transforms: every library gets the same hull (Bullet a
	// btConvexHullShape of its vertices, libccd and FCL the hull itself).
	std::vector<cd3Hull*> smallHulls;
	std::vector<std::unique_ptr<btConvexHullShape>> btSmallHulls;
	auto addHullPair = [&](PairSet& set, const cd3Hull* ha, cd3Transform ta, const cd3Hull* hb,
						   cd3Transform tb) {
		cd3HullShape a = {ha, ta}, b = {hb, tb};
		set.a.push_back(cd3MakeHullShape(a.hull, a.transform));
		set.b.push_back(cd3MakeHullShape(b.hull, b.transform));
		set.reference.push_back(ReferenceSeparation(RefHull(a), RefHull(b)));
		for (const cd3Hull* h : {ha, hb})
		{
			auto shape = std::make_unique<btConvexHullShape>();
			for (int i = 0; i < h->vertexCount; ++i)
			{
				shape->addPoint(btVector3((btScalar)h->vertices[i].x, (btScalar)h->vertices[i].y,
										  (btScalar)h->vertices[i].z),
								false);
			}
			shape->recalcLocalAabb();
			shape->setMargin(0);
			btSmallHulls.push_back(std::move(shape));
		}
		set.btA.push_back(btSmallHulls[btSmallHulls.size() - 2].get());
		set.btB.push_back(btSmallHulls.back().get());
		set.xa.push_back(ToBullet(a.transform));
		set.xb.push_back(ToBullet(b.transform));
#ifdef COLLIDE_BENCH_HAVE_CCD
		set.ccdA.push_back({a.hull, cd3MakeVec(0, 0, 0), a.transform, false, {}});
		set.ccdB.push_back({b.hull, cd3MakeVec(0, 0, 0), b.transform, false, {}});
#endif
#ifdef COLLIDE_BENCH_HAVE_FCL
		set.fclA.push_back(FclHull(ha));
		set.fclB.push_back(FclHull(hb));
		set.fxa.push_back(ToFcl(a.transform));
		set.fxb.push_back(ToFcl(b.transform));
#endif
	};
	// hull(8): 8 points on a jittered Fibonacci sphere (z and azimuth jittered, radius 0.85 to 1.15
	// times a scale of 0.5 to 1 per hull), as in the peers' shared scenes; 12 triangles, 18 edges.
	for (int h = 0; h < kHulls; ++h)
	{
		cd3Hull* hull = nullptr;
		while (hull == nullptr || hull->vertexCount != 8)
		{
			cd3DestroyHull(hull);
			hull = nullptr;
			cd3Vec points[8];
			double scale = 0.5 + 0.5 * u(rng);
			for (int k = 0; k < 8; ++k)
			{
				double z = std::clamp(1.0 - (2.0 * k + 1.0) / 8.0 + 0.2 * (u(rng) - 0.5), -0.999, 0.999);
				double azimuth = k * 2.399963229728653 + 0.3 * (u(rng) - 0.5);
				double radius = scale * (0.85 + 0.3 * u(rng)), ring = std::sqrt(1.0 - z * z);
				points[k] = cd3MakeVec((cdReal)(radius * ring * std::cos(azimuth)),
									   (cdReal)(radius * ring * std::sin(azimuth)), (cdReal)(radius * z));
			}
			cd3ComputeHull(points, 8, &hull);
		}
		smallHulls.push_back(hull);
	}
	PairSet hull8Pairs;
	hull8Pairs.name = "hull(8)-hull(8)";
	hull8Pairs.collideManifold = "cd3CollideHullHull";
	for (int i = 0; i < n; ++i)
	{
		cd3HullShape a = {smallHulls[rng() % (size_t)kHulls], {cd3MakeVec(0, 0, 0), RandomRotation(rng)}};
		cd3HullShape b = {smallHulls[rng() % (size_t)kHulls],
						  {cd3Scale(CD_R(1.2), RandomUnit(rng)), RandomRotation(rng)}};
		PlaceAtSeparation([&](cdReal s) { return cd3CollideHullHull(a, b, s); },
						  [&](cd3Vec d) { b.transform.p = cd3Add(b.transform.p, d); }, signedGap(i));
		addHullPair(hull8Pairs, a.hull, a.transform, b.hull, b.transform);
	}
	// The box-box pairs above with each box given as a hull (cd3MakeBoxHull): against the box-box
	// rows, what a box costs when a user hands it in as a hull.
	PairSet boxHullPairs;
	boxHullPairs.name = "box-box as hulls";
	boxHullPairs.collideManifold = "cd3CollideHullHull";
	for (int i = 0; i < n; ++i)
	{
		const cd3Box& a = boxes.a[(size_t)i].box;
		const cd3Box& b = boxes.b[(size_t)i].box;
		cd3Hull *ha = nullptr, *hb = nullptr;
		cd3MakeBoxHull(a.halfExtents, &ha);
		cd3MakeBoxHull(b.halfExtents, &hb);
		smallHulls.push_back(ha);
		smallHulls.push_back(hb);
		addHullPair(boxHullPairs, ha, {a.center, a.rotation}, hb, {b.center, b.rotation});
	}

#ifdef COLLIDE_BENCH_HAVE_CCD
	ccd_t ccd;
	CCD_INIT(&ccd);
	ccd.support1 = CcdSupport;
	ccd.support2 = CcdSupport;
	ccd.center1 = CcdCenter;
	ccd.center2 = CcdCenter;
	ccd.max_iterations = 100;
#endif
	btVoronoiSimplexSolver simplex;
	btGjkEpaPenetrationDepthSolver epaSolver;

	// Columns of the table; a row's cell is empty when the peer has no such query.
	enum Column
	{
		COLLIDE,
		BULLET,
		CCD_GJK,
		CCD_MPR,
		FCL,
		COLUMNS
	};
	const char* columnNames[COLUMNS] = {"collide", "Bullet", "libccd GJK", "libccd MPR", "FCL"};
	struct Row
	{
		std::string pair, query;
		Query cells[COLUMNS];
		bool present[COLUMNS] = {false, false, false, false, false};
		std::string notes[COLUMNS];
	};
	std::vector<Row> rows;

	for (PairSet* set : {&boxes, &hullPairs, &boxTriangles, &hull8Pairs, &boxHullPairs})
	{
		PairSet& s = *set;
		// Checks first (untimed): overlap counts, distances and depths against the reference.
		int refOverlaps = 0;
		for (int i = 0; i < n; ++i)
		{
			refOverlaps += s.reference[(size_t)i] <= 0.0;
		}

		Row distance;
		distance.pair = s.name;
		distance.query = "distance";
		Row overlap;
		overlap.pair = s.name;
		overlap.query = "overlap";
		Row depth;
		depth.pair = s.name;
		depth.query = "depth";
		Row manifold;
		manifold.pair = s.name;
		manifold.query = "manifold";
		Row manifoldLocal;
		manifoldLocal.pair = s.name;
		manifoldLocal.query = "manifold, local frame";
		auto set_ = [&s](Row& row, int column, std::function<int()> body, int calls, std::string note) {
			if (column == FCL && !s.fclPairs)
			{
				return;
			}
			row.cells[column] = {body, calls, 0.0};
			row.present[column] = true;
			row.notes[column] = note;
		};

		// ---- distance (separated pairs) ----
		{
			std::vector<double> collideDistance((size_t)n, 0.0);
			for (int i = 1; i < n; i += 2)
			{
				collideDistance[(size_t)i] = cd3Distance(&s.a[(size_t)i], &s.b[(size_t)i]).distance;
			}
			set_(
				distance, COLLIDE,
				[&s]() {
					int k = 0;
					for (int i = 1; i < n; i += 2)
					{
						k += cd3Distance(&s.a[(size_t)i], &s.b[(size_t)i]).distance > 0;
					}
					return k;
				},
				kPairs, "cd3Distance");
			Stats bt;
			for (int i = 1; i < n; i += 2)
			{
				btGjkEpaSolver2::sResults r;
				if (btGjkEpaSolver2::Distance(s.btA[(size_t)i], s.xa[(size_t)i], s.btB[(size_t)i],
											  s.xb[(size_t)i], btVector3(1, 0, 0), r))
				{
					bt.Add(r.distance, collideDistance[(size_t)i]);
				}
				else
				{
					++bt.failed;
				}
			}
			set_(
				distance, BULLET,
				[&s]() {
					int k = 0;
					for (int i = 1; i < n; i += 2)
					{
						btGjkEpaSolver2::sResults r;
						k += btGjkEpaSolver2::Distance(s.btA[(size_t)i], s.xa[(size_t)i], s.btB[(size_t)i],
													   s.xb[(size_t)i], btVector3(1, 0, 0), r);
					}
					return k;
				},
				kPairs, "btGjkEpaSolver2::Distance; vs collide " + bt.Text());
#ifdef COLLIDE_BENCH_HAVE_FCL
			Stats fs;
			for (int i = 1; i < n; i += 2)
			{
				fcl::DistanceRequestd request;
				fcl::DistanceResultd result;
				fcl::distance(s.fclA[(size_t)i].get(), s.fxa[(size_t)i], s.fclB[(size_t)i].get(),
							  s.fxb[(size_t)i], request, result);
				fs.Add(result.min_distance, collideDistance[(size_t)i]);
			}
			set_(
				distance, FCL,
				[&s]() {
					int k = 0;
					for (int i = 1; i < n; i += 2)
					{
						fcl::DistanceRequestd request;
						fcl::DistanceResultd result;
						fcl::distance(s.fclA[(size_t)i].get(), s.fxa[(size_t)i], s.fclB[(size_t)i].get(),
									  s.fxb[(size_t)i], request, result);
						k += result.min_distance > 0;
					}
					return k;
				},
				kPairs, "fcl::distance; vs collide " + fs.Text());
#endif
		}

		// ---- overlap (all pairs) ----
		{
			auto countText = [&](int count) {
				return "overlapping " + std::to_string(count) + " of " + std::to_string(n) + " (reference " +
					   std::to_string(refOverlaps) + ")";
			};
			auto collideOverlap = [&s]() {
				int k = 0;
				for (int i = 0; i < n; ++i)
				{
					k += cd3Overlap(&s.a[(size_t)i], &s.b[(size_t)i]);
				}
				return k;
			};
			set_(overlap, COLLIDE, collideOverlap, n, "cd3Overlap; " + countText(collideOverlap()));
			auto bulletOverlap = [&s]() {
				int k = 0;
				for (int i = 0; i < n; ++i)
				{
					btGjkEpaSolver2::sResults r;
					k += !btGjkEpaSolver2::Distance(s.btA[(size_t)i], s.xa[(size_t)i], s.btB[(size_t)i],
													s.xb[(size_t)i], btVector3(1, 0, 0), r);
				}
				return k;
			};
			set_(overlap, BULLET, bulletOverlap, n,
				 "btGjkEpaSolver2::Distance false; " + countText(bulletOverlap()));
#ifdef COLLIDE_BENCH_HAVE_CCD
			auto gjk = [&s, &ccd]() {
				int k = 0;
				for (int i = 0; i < n; ++i)
				{
					k += ccdGJKIntersect(&s.ccdA[(size_t)i], &s.ccdB[(size_t)i], &ccd) != 0;
				}
				return k;
			};
			auto mpr = [&s, &ccd]() {
				int k = 0;
				for (int i = 0; i < n; ++i)
				{
					k += ccdMPRIntersect(&s.ccdA[(size_t)i], &s.ccdB[(size_t)i], &ccd) != 0;
				}
				return k;
			};
			set_(overlap, CCD_GJK, gjk, n, "ccdGJKIntersect; " + countText(gjk()));
			set_(overlap, CCD_MPR, mpr, n, "ccdMPRIntersect; " + countText(mpr()));
#endif
#ifdef COLLIDE_BENCH_HAVE_FCL
			auto fclOverlap = [&s]() {
				int k = 0;
				for (int i = 0; i < n; ++i)
				{
					fcl::CollisionRequestd request;
					fcl::CollisionResultd result;
					fcl::collide(s.fclA[(size_t)i].get(), s.fxa[(size_t)i], s.fclB[(size_t)i].get(),
								 s.fxb[(size_t)i], request, result);
					k += result.isCollision();
				}
				return k;
			};
			set_(overlap, FCL, fclOverlap, n, "fcl::collide, no contact; " + countText(fclOverlap()));
#endif
		}

		// ---- depth and manifold (overlapping pairs) ----
		{
			Stats cs;
			for (int i = 0; i < n; i += 2)
			{
				cd3Manifold m = CollideShapes(s.a[(size_t)i], s.b[(size_t)i], CD_R(0.0));
				if (m.pointCount > 0)
				{
					cs.Add(-MinSeparation(m), -s.reference[(size_t)i]);
				}
				else
				{
					++cs.failed;
				}
			}
			auto collideManifold = [&s]() {
				int k = 0;
				for (int i = 0; i < n; i += 2)
				{
					k += CollideShapes(s.a[(size_t)i], s.b[(size_t)i], CD_R(0.0)).pointCount;
				}
				return k;
			};
			set_(depth, COLLIDE, collideManifold, kPairs, "the manifold call; depth error " + cs.Text());
			set_(manifold, COLLIDE, collideManifold, kPairs,
				 s.collideManifold + "; depth error " + cs.Text());

			// The same pairs in body frames: the local-frame form, as a solver calls it.
			Stats ls;
			std::vector<BodyShape> bodyA, bodyB;
			for (int i = 0; i < n; ++i)
			{
				bodyA.push_back(InBodyFrame(s.a[(size_t)i]));
				bodyB.push_back(InBodyFrame(s.b[(size_t)i]));
			}
			for (int i = 0; i < n; i += 2)
			{
				cd3Manifold m = CollideBodies(bodyA[(size_t)i], bodyB[(size_t)i], CD_R(0.0));
				if (m.pointCount > 0)
				{
					ls.Add(-MinSeparation(m), -s.reference[(size_t)i]);
				}
				else
				{
					++ls.failed;
				}
			}
			set_(
				manifoldLocal, COLLIDE,
				[bodyA, bodyB]() {
					int k = 0;
					for (int i = 0; i < n; i += 2)
					{
						k += CollideBodies(bodyA[(size_t)i], bodyB[(size_t)i], CD_R(0.0)).pointCount;
					}
					return k;
				},
				kPairs, s.collideManifold + "Local, shapes in body frames; depth error " + ls.Text());

			Stats bt;
			for (int i = 0; i < n; i += 2)
			{
				btGjkEpaSolver2::sResults r;
				if (btGjkEpaSolver2::Penetration(s.btA[(size_t)i], s.xa[(size_t)i], s.btB[(size_t)i],
												 s.xb[(size_t)i], btVector3(1, 0, 0), r, false))
				{
					bt.Add(-r.distance, -s.reference[(size_t)i]);
				}
				else
				{
					++bt.failed;
				}
			}
			set_(
				depth, BULLET,
				[&s]() {
					int k = 0;
					for (int i = 0; i < n; i += 2)
					{
						btGjkEpaSolver2::sResults r;
						k += btGjkEpaSolver2::Penetration(s.btA[(size_t)i], s.xa[(size_t)i], s.btB[(size_t)i],
														  s.xb[(size_t)i], btVector3(1, 0, 0), r, false);
					}
					return k;
				},
				kPairs, "btGjkEpaSolver2::Penetration; depth error " + bt.Text());

			Stats bm;
			std::function<int(int, double*)> bulletManifold;
			if (s.boxBoxPeer)
			{
				bulletManifold = [&s](int i, double* d) {
					btBoxBoxDetector detector((btBoxShape*)s.btA[(size_t)i], (btBoxShape*)s.btB[(size_t)i]);
					btDiscreteCollisionDetectorInterface::ClosestPointInput input;
					input.m_transformA = s.xa[(size_t)i];
					input.m_transformB = s.xb[(size_t)i];
					CountResult result;
					detector.getClosestPoints(input, result, nullptr);
					*d = -result.depth;
					return result.count;
				};
			}
			else
			{
				bulletManifold = [&s, &simplex, &epaSolver](int i, double* d) {
					btGjkPairDetector detector((const btConvexShape*)s.btA[(size_t)i],
											   (const btConvexShape*)s.btB[(size_t)i], &simplex, &epaSolver);
					btDiscreteCollisionDetectorInterface::ClosestPointInput input;
					input.m_transformA = s.xa[(size_t)i];
					input.m_transformB = s.xb[(size_t)i];
					CountResult result;
					detector.getClosestPoints(input, result, nullptr);
					*d = -result.depth;
					return result.count;
				};
			}
			for (int i = 0; i < n; i += 2)
			{
				double d = 0.0;
				if (bulletManifold(i, &d) > 0)
				{
					bm.Add(d, -s.reference[(size_t)i]);
				}
				else
				{
					++bm.failed;
				}
			}
			set_(
				manifold, BULLET,
				[bulletManifold]() {
					int k = 0;
					double d;
					for (int i = 0; i < n; i += 2)
					{
						k += bulletManifold(i, &d);
					}
					return k;
				},
				kPairs,
				std::string(s.boxBoxPeer ? "btBoxBoxDetector"
										 : "btGjkPairDetector + btGjkEpaPenetrationDepthSolver") +
					"; depth error " + bm.Text());
#ifdef COLLIDE_BENCH_HAVE_CCD
			for (int column : {CCD_GJK, CCD_MPR})
			{
				auto penetration = [&s, &ccd, column](int i, double* d) {
					ccd_real_t depthValue;
					ccd_vec3_t dir, pos;
					int r = column == CCD_GJK ? ccdGJKPenetration(&s.ccdA[(size_t)i], &s.ccdB[(size_t)i],
																  &ccd, &depthValue, &dir, &pos)
											  : ccdMPRPenetration(&s.ccdA[(size_t)i], &s.ccdB[(size_t)i],
																  &ccd, &depthValue, &dir, &pos);
					*d = depthValue;
					return r == 0;
				};
				Stats st;
				for (int i = 0; i < n; i += 2)
				{
					double d = 0.0;
					if (penetration(i, &d))
					{
						st.Add(d, -s.reference[(size_t)i]);
					}
					else
					{
						++st.failed;
					}
				}
				set_(
					depth, column,
					[penetration]() {
						int k = 0;
						double d;
						for (int i = 0; i < n; i += 2)
						{
							k += penetration(i, &d);
						}
						return k;
					},
					kPairs,
					std::string(column == CCD_GJK ? "ccdGJKPenetration" : "ccdMPRPenetration") +
						"; depth error " + st.Text());
			}
#endif
#ifdef COLLIDE_BENCH_HAVE_FCL
			for (int contacts : {1, 4})
			{
				auto fclCollide = [&s, contacts](int i, double* d) {
					fcl::CollisionRequestd request((size_t)contacts, true);
					fcl::CollisionResultd result;
					fcl::collide(s.fclA[(size_t)i].get(), s.fxa[(size_t)i], s.fclB[(size_t)i].get(),
								 s.fxb[(size_t)i], request, result);
					*d = 0.0;
					for (size_t c = 0; c < result.numContacts(); ++c)
					{
						*d = std::max(*d, result.getContact(c).penetration_depth);
					}
					return (int)result.numContacts();
				};
				Stats st;
				for (int i = 0; i < n; i += 2)
				{
					double d = 0.0;
					if (fclCollide(i, &d) > 0)
					{
						st.Add(d, -s.reference[(size_t)i]);
					}
					else
					{
						++st.failed;
					}
				}
				set_(
					contacts == 1 ? depth : manifold, FCL,
					[fclCollide]() {
						int k = 0;
						double d;
						for (int i = 0; i < n; i += 2)
						{
							k += fclCollide(i, &d);
						}
						return k;
					},
					kPairs,
					std::string(contacts == 1 ? "fcl::collide, 1 contact"
											  : "fcl::collide, up to 4 contacts") +
						"; depth error " + st.Text());
			}
#endif
		}
		rows.push_back(distance);
		rows.push_back(overlap);
		rows.push_back(depth);
		rows.push_back(manifold);
		rows.push_back(manifoldLocal);
	}

	std::vector<Query*> queries;
	for (Row& row : rows)
	{
		for (int c = 0; c < COLUMNS; ++c)
		{
			if (row.present[c])
			{
				queries.push_back(&row.cells[c]);
			}
		}
	}
	MeasureAll(queries, runs, seconds);

	std::printf(
		"ns per call, median of %d runs (thread CPU time), %d overlapping + %d separated near-contact pairs "
		"per kind; ratio = collide / peer\n\n",
		runs, kPairs, kPairs);
	std::printf("| pair | query |");
	for (const char* name : columnNames)
	{
		std::printf(" %s |", name);
	}
	std::printf("\n|---|---|");
	for (int c = 0; c < COLUMNS; ++c)
	{
		std::printf("---|");
	}
	std::printf("\n");
	for (const Row& row : rows)
	{
		std::printf("| %s | %s |", row.pair.c_str(), row.query.c_str());
		for (int c = 0; c < COLUMNS; ++c)
		{
			if (!row.present[c])
			{
				std::printf(" - |");
			}
			else if (c == COLLIDE || !row.present[COLLIDE])
			{
				std::printf(" %.0f |", row.cells[c].ns);
			}
			else
			{
				std::printf(" %.0f (%.2f) |", row.cells[c].ns, row.cells[COLLIDE].ns / row.cells[c].ns);
			}
		}
		std::printf("\n");
	}
	std::printf(
		"\nWhat each cell ran, and its answers against the exact SAT reference (relative depth error; "
		"distances against collide's):\n");
	for (const Row& row : rows)
	{
		for (int c = 0; c < COLUMNS; ++c)
		{
			if (row.present[c])
			{
				std::printf("- %s %s, %s: %s\n", row.pair.c_str(), row.query.c_str(), columnNames[c],
							row.notes[c].c_str());
			}
		}
	}
	/* Each pair set adds five rows, in this order: distance, overlap, depth, manifold, local manifold;
	 * the sets: box-box, hull-hull, box-triangle, hull(8)-hull(8), box-box as hulls. */
	const auto rowOf = [&rows](int set, int query) -> const Row& { return rows[(size_t)(5 * set + query)]; };
	enum
	{
		DEPTH_ROW = 2,
		MANIFOLD_ROW = 3
	};
	const Row& boxManifold = rowOf(0, MANIFOLD_ROW);
	const Row& hullDepth = rowOf(1, DEPTH_ROW);
	const Row& hullManifold = rowOf(1, MANIFOLD_ROW);
	const Row& boxTriangleManifold = rowOf(2, MANIFOLD_ROW);
	std::printf(
		"\ntargets: box-box manifold collide / btBoxBoxDetector %.2f (<= 1); hull-hull manifold collide / "
		"Bullet GJK-EPA %.2f (<= 0.5)",
		boxManifold.cells[COLLIDE].ns / boxManifold.cells[BULLET].ns,
		hullManifold.cells[COLLIDE].ns / hullManifold.cells[BULLET].ns);
	if (hullDepth.present[CCD_MPR])
	{
		std::printf("; collide / ccdMPRPenetration %.2f (<= 1)",
					hullManifold.cells[COLLIDE].ns / hullDepth.cells[CCD_MPR].ns);
	}
	std::printf("; box-triangle manifold collide / Bullet GJK-EPA %.2f\n",
				boxTriangleManifold.cells[COLLIDE].ns / boxTriangleManifold.cells[BULLET].ns);
	const Row& hull8Depth = rowOf(3, DEPTH_ROW);
	const Row& hull8Manifold = rowOf(3, MANIFOLD_ROW);
	const Row& boxHullManifold = rowOf(4, MANIFOLD_ROW);
	std::printf("small hulls: hull(8)-hull(8) manifold collide / Bullet btGjkEpaSolver2 depth %.2f, / Bullet "
				"GJK-EPA pair detector manifold %.2f (<= 0.5)",
				hull8Manifold.cells[COLLIDE].ns / hull8Depth.cells[BULLET].ns,
				hull8Manifold.cells[COLLIDE].ns / hull8Manifold.cells[BULLET].ns);
	if (hull8Depth.present[CCD_MPR])
	{
		std::printf("; collide / ccdMPRPenetration %.2f (<= 1)",
					hull8Manifold.cells[COLLIDE].ns / hull8Depth.cells[CCD_MPR].ns);
	}
	std::printf("; box-box manifold as hulls / as cd3Box %.2f (<= 2)\n",
				boxHullManifold.cells[COLLIDE].ns / boxManifold.cells[COLLIDE].ns);
	for (cd3Hull* h : smallHulls)
	{
		cd3DestroyHull(h);
	}
	for (cd3Hull* h : hulls)
	{
		cd3DestroyHull(h);
	}
	return 0;
}
