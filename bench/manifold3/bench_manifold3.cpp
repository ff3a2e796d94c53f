// collide_bench_manifold3: ns per call of the 3D contact manifolds, with Bullet (btBoxBoxDetector:
// ODE's box-box SAT and clipping; btGjkPairDetector + btGjkEpaPenetrationDepthSolver) and libccd
// (ccdMPRPenetration, ccdGJKPenetration) on the same pairs in the same run.
//
// Pairs are near contact: unit-size shapes overlapping by 0 to 0.05 (the resting contacts a
// physics step sees). box-box: collide's full manifold (up to 4 points) against Bullet's box-box
// detector (up to 4 points). hull(32)-hull(32): hulls of 32 vertices on random ellipsoids;
// collide's exact depth (GJK/EPA on the vertices for hulls this large) plus manifold against Bullet's GJK/EPA
// (one point, margins 0) and libccd's MPR and GJK/EPA (depth, direction and one point; libccd's support
// functions loop over the 32 vertices like collide's). collide takes world-space shapes; Bullet and libccd
// take local shapes and transforms. Each figure is the median of 9 runs of about 20 ms, the libraries' runs
// interleaved so that all see the same machine load.
// Usage: collide_bench_manifold3 [--quick]
#include <BulletCollision/CollisionDispatch/btBoxBoxDetector.h>
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>
#ifdef COLLIDE_BENCH_HAVE_CCD
#include <ccd/ccd.h>
#endif

#include "collide/collide.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <memory>
#include <random>
#include <vector>

namespace
{
const int kPairs = 256;

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

// Moves B along the manifold normal until the pair overlaps by `depth` (a few refinements).
template <typename Collide, typename Move> void PlaceAtDepth(Collide collide, Move move, double depth)
{
	for (int k = 0; k < 4; ++k)
	{
		cd3Manifold m = collide(CD_R(100.0));
		if (m.pointCount == 0)
		{
			return;
		}
		move(cd3Scale((cdReal)(-depth - MinSeparation(m)), m.normal));
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

double Median(std::vector<double> v)
{
	std::sort(v.begin(), v.end());
	return v[v.size() / 2];
}

// Runs each body over all pairs repeatedly for about `seconds`, interleaved, `runs` times; returns
// the median ns per call of each.
std::vector<double> Measure(const std::vector<std::function<int()>>& bodies, int pairs, int runs,
							double seconds)
{
	std::vector<std::vector<double>> samples(bodies.size());
	volatile int sink = 0;
	for (int r = 0; r < runs; ++r)
	{
		for (size_t b = 0; b < bodies.size(); ++b)
		{
			auto start = std::chrono::steady_clock::now();
			long calls = 0;
			double elapsed = 0.0;
			do
			{
				sink = sink + bodies[b]();
				calls += pairs;
				elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
			} while (elapsed < seconds);
			samples[b].push_back(elapsed * 1e9 / (double)calls);
		}
	}
	std::vector<double> out;
	for (auto& s : samples)
	{
		out.push_back(Median(s));
	}
	return out;
}

#ifdef COLLIDE_BENCH_HAVE_CCD
struct CcdHull
{
	const cd3Hull* hull;
	cd3Transform transform;
};

void CcdSupport(const void* object, const ccd_vec3_t* dir, ccd_vec3_t* out)
{
	const CcdHull* h = (const CcdHull*)object;
	cd3Vec d = cd3InvRotateVector(h->transform.q,
								  cd3MakeVec((cdReal)dir->v[0], (cdReal)dir->v[1], (cdReal)dir->v[2]));
	int best = 0;
	cdReal bestDot = cd3Dot(d, h->hull->vertices[0]);
	for (int i = 1; i < h->hull->vertexCount; ++i)
	{
		cdReal x = cd3Dot(d, h->hull->vertices[i]);
		if (x > bestDot)
		{
			bestDot = x;
			best = i;
		}
	}
	cd3Vec p = cd3TransformPoint(h->transform, h->hull->vertices[best]);
	ccdVec3Set(out, p.x, p.y, p.z);
}

void CcdCenter(const void* object, ccd_vec3_t* out)
{
	const CcdHull* h = (const CcdHull*)object;
	cd3Vec p = cd3TransformPoint(h->transform, h->hull->centroid);
	ccdVec3Set(out, p.x, p.y, p.z);
}
#endif
} // namespace

int main(int argc, char** argv)
{
	bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
	int runs = quick ? 3 : 9;
	double seconds = quick ? 0.005 : 0.02;
	std::mt19937_64 rng(20261121);
	std::uniform_real_distribution<double> u(0.0, 1.0);

	// ---- box-box ----
	std::vector<cd3Box> boxA(kPairs), boxB(kPairs);
	std::vector<std::unique_ptr<btBoxShape>> bulletBoxA, bulletBoxB;
	std::vector<btTransform> xa(kPairs), xb(kPairs);
	for (int i = 0; i < kPairs; ++i)
	{
		cd3Box a, b;
		a.halfExtents = cd3MakeVec((cdReal)(0.3 + 0.4 * u(rng)), (cdReal)(0.3 + 0.4 * u(rng)),
								   (cdReal)(0.3 + 0.4 * u(rng)));
		b.halfExtents = cd3MakeVec((cdReal)(0.3 + 0.4 * u(rng)), (cdReal)(0.3 + 0.4 * u(rng)),
								   (cdReal)(0.3 + 0.4 * u(rng)));
		a.center = cd3MakeVec(0, 0, 0);
		a.rotation = RandomRotation(rng);
		// Half the pairs resting face on face (the common case in a stack), half at random.
		b.rotation = i % 2 == 0 ? a.rotation : RandomRotation(rng);
		b.center = cd3Scale(CD_R(1.5),
							i % 2 == 0 ? cd3RotateVector(a.rotation, cd3MakeVec(0, 1, 0)) : RandomUnit(rng));
		PlaceAtDepth([&](cdReal s) { return cd3CollideBoxBox(a, b, s); },
					 [&](cd3Vec d) { b.center = cd3Add(b.center, d); }, 0.05 * u(rng));
		boxA[(size_t)i] = a;
		boxB[(size_t)i] = b;
		bulletBoxA.emplace_back(new btBoxShape(
			btVector3((btScalar)a.halfExtents.x, (btScalar)a.halfExtents.y, (btScalar)a.halfExtents.z)));
		bulletBoxB.emplace_back(new btBoxShape(
			btVector3((btScalar)b.halfExtents.x, (btScalar)b.halfExtents.y, (btScalar)b.halfExtents.z)));
		xa[(size_t)i] = ToBullet({a.center, a.rotation});
		xb[(size_t)i] = ToBullet({b.center, b.rotation});
	}
	auto collideBoxes = [&]() {
		int points = 0;
		for (int i = 0; i < kPairs; ++i)
		{
			points += cd3CollideBoxBox(boxA[(size_t)i], boxB[(size_t)i], CD_R(0.0)).pointCount;
		}
		return points;
	};
	auto bulletBoxes = [&]() {
		int points = 0;
		for (int i = 0; i < kPairs; ++i)
		{
			btBoxBoxDetector detector(bulletBoxA[(size_t)i].get(), bulletBoxB[(size_t)i].get());
			btDiscreteCollisionDetectorInterface::ClosestPointInput input;
			input.m_transformA = xa[(size_t)i];
			input.m_transformB = xb[(size_t)i];
			CountResult result;
			detector.getClosestPoints(input, result, nullptr);
			points += result.count;
		}
		return points;
	};
	std::printf("box-box: collide %d points, Bullet %d points over %d pairs\n", collideBoxes(), bulletBoxes(),
				kPairs);
	std::vector<double> boxTimes = Measure({collideBoxes, bulletBoxes}, kPairs, runs, seconds);

	// ---- hull(32)-hull(32) ----
	const int kHulls = 32;
	std::vector<cd3Hull*> hulls;
	std::vector<std::unique_ptr<btConvexHullShape>> bulletHulls;
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
		bulletHulls.push_back(std::move(shape));
	}
	std::vector<cd3HullShape> hullA(kPairs), hullB(kPairs);
	std::vector<int> indexA(kPairs), indexB(kPairs);
	for (int i = 0; i < kPairs; ++i)
	{
		indexA[(size_t)i] = (int)(rng() % kHulls);
		indexB[(size_t)i] = (int)(rng() % kHulls);
		cd3HullShape a = {hulls[(size_t)indexA[(size_t)i]], {cd3MakeVec(0, 0, 0), RandomRotation(rng)}};
		cd3HullShape b = {hulls[(size_t)indexB[(size_t)i]],
						  {cd3Scale(CD_R(1.2), RandomUnit(rng)), RandomRotation(rng)}};
		PlaceAtDepth([&](cdReal s) { return cd3CollideHullHull(a, b, s); },
					 [&](cd3Vec d) { b.transform.p = cd3Add(b.transform.p, d); }, 0.05 * u(rng));
		hullA[(size_t)i] = a;
		hullB[(size_t)i] = b;
	}
	auto collideHulls = [&]() {
		int points = 0;
		for (int i = 0; i < kPairs; ++i)
		{
			points += cd3CollideHullHull(hullA[(size_t)i], hullB[(size_t)i], CD_R(0.0)).pointCount;
		}
		return points;
	};
	btVoronoiSimplexSolver simplex;
	btGjkEpaPenetrationDepthSolver epa;
	auto bulletHullsGjk = [&]() {
		int points = 0;
		for (int i = 0; i < kPairs; ++i)
		{
			btGjkPairDetector detector(bulletHulls[(size_t)indexA[(size_t)i]].get(),
									   bulletHulls[(size_t)indexB[(size_t)i]].get(), &simplex, &epa);
			btDiscreteCollisionDetectorInterface::ClosestPointInput input;
			input.m_transformA = ToBullet(hullA[(size_t)i].transform);
			input.m_transformB = ToBullet(hullB[(size_t)i].transform);
			CountResult result;
			detector.getClosestPoints(input, result, nullptr);
			points += result.count;
		}
		return points;
	};
	std::vector<std::function<int()>> hullBodies = {collideHulls, bulletHullsGjk};
	std::vector<const char*> hullNames = {"collide cd3CollideHullHull (depth + manifold)", "Bullet GJK/EPA"};
#ifdef COLLIDE_BENCH_HAVE_CCD
	std::vector<CcdHull> ccdA(kPairs), ccdB(kPairs);
	for (int i = 0; i < kPairs; ++i)
	{
		ccdA[(size_t)i] = {hullA[(size_t)i].hull, hullA[(size_t)i].transform};
		ccdB[(size_t)i] = {hullB[(size_t)i].hull, hullB[(size_t)i].transform};
	}
	ccd_t ccd;
	CCD_INIT(&ccd);
	ccd.support1 = CcdSupport;
	ccd.support2 = CcdSupport;
	ccd.center1 = CcdCenter;
	ccd.center2 = CcdCenter;
	ccd.max_iterations = 100;
	auto ccdMpr = [&]() {
		int hits = 0;
		for (int i = 0; i < kPairs; ++i)
		{
			ccd_real_t depth;
			ccd_vec3_t dir, pos;
			hits += ccdMPRPenetration(&ccdA[(size_t)i], &ccdB[(size_t)i], &ccd, &depth, &dir, &pos) == 0;
		}
		return hits;
	};
	auto ccdGjkEpa = [&]() {
		int hits = 0;
		for (int i = 0; i < kPairs; ++i)
		{
			ccd_real_t depth;
			ccd_vec3_t dir, pos;
			hits += ccdGJKPenetration(&ccdA[(size_t)i], &ccdB[(size_t)i], &ccd, &depth, &dir, &pos) == 0;
		}
		return hits;
	};
	hullBodies.push_back(ccdMpr);
	hullBodies.push_back(ccdGjkEpa);
	hullNames.push_back("libccd MPR");
	hullNames.push_back("libccd GJK/EPA");
#endif
	std::vector<double> hullTimes = Measure(hullBodies, kPairs, runs, seconds);

	std::printf("\n| pair (%d near-contact pairs) | query | ns per call |\n|---|---|---|\n", kPairs);
	std::printf("| box-box | collide cd3CollideBoxBox (manifold) | %.0f |\n", boxTimes[0]);
	std::printf("| box-box | Bullet btBoxBoxDetector (manifold) | %.0f |\n", boxTimes[1]);
	for (size_t i = 0; i < hullTimes.size(); ++i)
	{
		std::printf("| hull(32)-hull(32) | %s | %.0f |\n", hullNames[i], hullTimes[i]);
	}
	std::printf("\nratios: box-box collide/Bullet %.2f (target <= 1); hull-hull collide/Bullet GJK-EPA %.2f "
				"(target <= 0.5)",
				boxTimes[0] / boxTimes[1], hullTimes[0] / hullTimes[1]);
#ifdef COLLIDE_BENCH_HAVE_CCD
	std::printf("; collide/libccd MPR %.2f (target <= 1)", hullTimes[0] / hullTimes[2]);
#endif
	std::printf("\n");
	for (cd3Hull* h : hulls)
	{
		cd3DestroyHull(h);
	}
	return 0;
}
