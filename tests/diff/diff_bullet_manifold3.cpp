// Differential test of the 3D manifolds' depth against Bullet (libbullet-dev): btBoxBoxDetector
// (ODE's box-box SAT) on random box pairs, btGjkPairDetector with btGjkEpaPenetrationDepthSolver on
// random hull pairs (32 random points each, in a box or on an ellipsoid, built by cd3ComputeHull and handed
// to Bullet as btConvexHullShape). Bullet's collision margins are set to 0, so both libraries see the same
// shapes.
//
// Also computed, in double: the exact signed separation by the separating axis test over every
// face normal and every edge-pair cross product (the reference). collide must match it within
// 1e-4 relative on every pair away from its face/edge ties; Bullet is compared with the same
// tolerance and its disagreements are counted and reported: ODE's box-box prefers face axes over
// edge axes by a fudge factor of 1.05 (so pairs whose face and edge depths are within 6% are ties
// for it), and Bullet's EPA stops at its own tolerance. The overlap answers must agree away from
// the boundary (|reference| > 1e-3).
#include <BulletCollision/CollisionDispatch/btBoxBoxDetector.h>
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>

#include "collide/collide.h"
#include "test.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace
{
struct V3
{
	double x, y, z;
};
double Dot(V3 a, V3 b)
{
	return a.x * b.x + a.y * b.y + a.z * b.z;
}
V3 Cross(V3 a, V3 b)
{
	return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double Length(V3 a)
{
	return std::sqrt(Dot(a, a));
}
V3 FromVec(cd3Vec v)
{
	return {(double)v.x, (double)v.y, (double)v.z};
}

// A polytope in world space, in double: vertices, edge directions, face normals.
struct Poly
{
	std::vector<V3> vertices, edges, normals;
};

Poly FromHull(const cd3Hull* h, cd3Transform t)
{
	Poly p;
	for (int i = 0; i < h->vertexCount; ++i)
	{
		p.vertices.push_back(FromVec(cd3TransformPoint(t, h->vertices[i])));
	}
	for (int i = 0; i < h->edgeCount; ++i)
	{
		if (h->edges[i].twin > i)
		{
			cd3Vec d =
				cd3Sub(h->vertices[h->edges[h->edges[i].twin].origin], h->vertices[h->edges[i].origin]);
			p.edges.push_back(FromVec(cd3RotateVector(t.q, d)));
		}
	}
	for (int i = 0; i < h->faceCount; ++i)
	{
		p.normals.push_back(FromVec(cd3RotateVector(t.q, h->planes[i].normal)));
	}
	return p;
}

double AxisSeparation(const Poly& a, const Poly& b, V3 axis)
{
	double len = Length(axis);
	double loA = INFINITY, hiA = -INFINITY, loB = INFINITY, hiB = -INFINITY;
	for (V3 v : a.vertices)
	{
		double d = Dot(v, axis) / len;
		loA = std::min(loA, d);
		hiA = std::max(hiA, d);
	}
	for (V3 v : b.vertices)
	{
		double d = Dot(v, axis) / len;
		loB = std::min(loB, d);
		hiB = std::max(hiB, d);
	}
	return std::max(loB - hiA, loA - hiB);
}

// Largest separation over face normals (face) and over edge crosses (edge).
void BruteSat(const Poly& a, const Poly& b, double* face, double* edge)
{
	*face = -INFINITY;
	*edge = -INFINITY;
	for (V3 n : a.normals)
	{
		*face = std::max(*face, AxisSeparation(a, b, n));
	}
	for (V3 n : b.normals)
	{
		*face = std::max(*face, AxisSeparation(a, b, n));
	}
	for (V3 u : a.edges)
	{
		for (V3 w : b.edges)
		{
			V3 c = Cross(u, w);
			if (Length(c) > 1e-6 * Length(u) * Length(w))
			{
				*edge = std::max(*edge, AxisSeparation(a, b, c));
			}
		}
	}
}

struct MinResult : btDiscreteCollisionDetectorInterface::Result
{
	double distance = INFINITY;
	int count = 0;
	void setShapeIdentifiersA(int, int) override
	{
	}
	void setShapeIdentifiersB(int, int) override
	{
	}
	void addContactPoint(const btVector3&, const btVector3&, btScalar depth) override
	{
		distance = std::min(distance, (double)depth);
		++count;
	}
};

btTransform ToBullet(cd3Transform t)
{
	return btTransform(btQuaternion((btScalar)t.q.x, (btScalar)t.q.y, (btScalar)t.q.z, (btScalar)t.q.w),
					   btVector3((btScalar)t.p.x, (btScalar)t.p.y, (btScalar)t.p.z));
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

cd3Quat RandomRotation(TestRng* rng)
{
	for (;;)
	{
		double x = TestRngRange(rng, -1, 1), y = TestRngRange(rng, -1, 1), z = TestRngRange(rng, -1, 1),
			   w = TestRngRange(rng, -1, 1);
		double n = std::sqrt(x * x + y * y + z * z + w * w);
		if (n > 0.1 && n <= 1.0)
		{
			return cd3MakeQuat((cdReal)(x / n), (cdReal)(y / n), (cdReal)(z / n), (cdReal)(w / n));
		}
	}
}

cd3Transform RandomTransform(TestRng* rng, double reach)
{
	cd3Transform t;
	t.p = cd3MakeVec((cdReal)TestRngRange(rng, -reach, reach), (cdReal)TestRngRange(rng, -reach, reach),
					 (cdReal)TestRngRange(rng, -reach, reach));
	t.q = RandomRotation(rng);
	return t;
}

const double kTolerance = 1e-4;

bool Near(double a, double b)
{
	return std::fabs(a - b) <= kTolerance * std::max(std::fabs(b), 1e-2);
}

struct Tally
{
	int compared = 0, skippedTies = 0, bulletDisagrees = 0, bulletOverlapDisagrees = 0;
};

void Compare(const char* what, int index, double reference, double face, double edge, double size,
			 double collideSep, bool bulletReported, double bulletSep, double bulletTieBand, Tally* tally)
{
	if (std::fabs(reference) < 1e-3)
	{
		return;
	}
	// collide's own tie band: a face is kept over an edge pair (and A's face over B's) by up to
	// 1e-4 of the pair's size, the sum of the diagonals of their bounds.
	if (std::fabs(face - edge) < 1.5e-4 * size)
	{
		++tally->skippedTies;
		return;
	}
	++tally->compared;
	if (reference <= 0.0)
	{
		TEST_CHECKF(Near(collideSep, reference), "%s #%d: collide %.9g, exact %.9g", what, index, collideSep,
					reference);
	}
	bool bulletOverlap = bulletReported && bulletSep <= 0.0;
	if (bulletOverlap != (reference <= 0.0))
	{
		++tally->bulletOverlapDisagrees;
	}
	bool tie = std::fabs(face - edge) <= bulletTieBand * std::max(std::fabs(face), std::fabs(edge));
	if (reference <= 0.0 && bulletReported && !tie)
	{
		if (!Near(bulletSep, collideSep))
		{
			++tally->bulletDisagrees;
			if (tally->bulletDisagrees <= 5)
			{
				std::printf("  %s #%d: Bullet %.9g, collide %.9g, exact %.9g\n", what, index, bulletSep,
							collideSep, reference);
			}
		}
	}
}

void TestBoxes()
{
	TestRng rng = {0xb0b0b0b0u};
	Tally tally, localTally;
	cd3Hull* unit = nullptr;
	for (int n = 0; n < 3000; ++n)
	{
		cd3Box a, b;
		a.halfExtents = cd3MakeVec((cdReal)TestRngRange(&rng, 0.2, 1.2), (cdReal)TestRngRange(&rng, 0.2, 1.2),
								   (cdReal)TestRngRange(&rng, 0.2, 1.2));
		b.halfExtents = cd3MakeVec((cdReal)TestRngRange(&rng, 0.2, 1.2), (cdReal)TestRngRange(&rng, 0.2, 1.2),
								   (cdReal)TestRngRange(&rng, 0.2, 1.2));
		cd3Transform ta = RandomTransform(&rng, 1.0), tb = RandomTransform(&rng, 1.0);
		a.center = ta.p;
		a.rotation = ta.q;
		b.center = tb.p;
		b.rotation = tb.q;
		cd3Hull *ha = nullptr, *hb = nullptr;
		if (cd3MakeBoxHull(a.halfExtents, &ha) != CD_OK || cd3MakeBoxHull(b.halfExtents, &hb) != CD_OK)
		{
			TEST_CHECK(false);
			continue;
		}
		double face, edge;
		BruteSat(FromHull(ha, ta), FromHull(hb, tb), &face, &edge);
		double reference = std::max(face, edge);
		cd3DestroyHull(ha);
		cd3DestroyHull(hb);

		cd3Manifold m = cd3CollideBoxBox(a, b, CD_R(0.0));
		double collideSep = m.pointCount > 0 ? MinSeparation(m) : INFINITY;
		// The local-frame form: both boxes in their own frames, B's frame in A's.
		cd3Box la = {CD3_VEC_ZERO, a.halfExtents, CD3_QUAT_IDENTITY},
			   lb = {CD3_VEC_ZERO, b.halfExtents, CD3_QUAT_IDENTITY};
		cd3Manifold ml = cd3CollideBoxBoxLocal(la, lb, cd3InvMulTransforms(ta, tb), CD_R(0.0));
		double localSep = ml.pointCount > 0 ? MinSeparation(ml) : INFINITY;

		btBoxShape boxA(
			btVector3((btScalar)a.halfExtents.x, (btScalar)a.halfExtents.y, (btScalar)a.halfExtents.z));
		btBoxShape boxB(
			btVector3((btScalar)b.halfExtents.x, (btScalar)b.halfExtents.y, (btScalar)b.halfExtents.z));
		btBoxBoxDetector detector(&boxA, &boxB);
		btDiscreteCollisionDetectorInterface::ClosestPointInput input;
		input.m_transformA = ToBullet(ta);
		input.m_transformB = ToBullet(tb);
		MinResult result;
		detector.getClosestPoints(input, result, nullptr);
		double size = 2.0 * (double)(cd3Length(a.halfExtents) + cd3Length(b.halfExtents));
		Compare("box-box", n, reference, face, edge, size, collideSep, result.count > 0, result.distance,
				0.06, &tally);
		Compare("box-box local", n, reference, face, edge, size, localSep, result.count > 0, result.distance,
				0.06, &localTally);
		if (std::fabs(reference) > 1e-3)
		{
			TEST_CHECKF((m.pointCount > 0) == (reference <= 0.0), "box-box #%d: %d points, exact %.9g", n,
						m.pointCount, reference);
			TEST_CHECKF((ml.pointCount > 0) == (reference <= 0.0), "box-box local #%d: %d points, exact %.9g",
						n, ml.pointCount, reference);
		}
	}
	(void)unit;
	std::printf(
		"box-box: %d compared, %d face/edge ties skipped, Bullet (btBoxBoxDetector) depth off by more "
		"than 1e-4 relative on %d (away from its 5%% face bias), overlap answer differs on %d\n",
		tally.compared, tally.skippedTies, tally.bulletDisagrees, tally.bulletOverlapDisagrees);
	TEST_CHECK(tally.compared > 2000);
	std::printf("box-box, local form (cd3CollideBoxBoxLocal): %d compared against the exact depth\n",
				localTally.compared);
	TEST_CHECK(localTally.compared > 2000);
}

// 32 points in a box (about 20 hull vertices: the SAT path) or on an ellipsoid (32 vertices: the
// GJK/EPA path of large hulls).
cd3Hull* RandomHull(TestRng* rng, int count, bool onEllipsoid)
{
	std::vector<cd3Vec> points((size_t)count);
	double sx = TestRngRange(rng, 0.3, 1.2), sy = TestRngRange(rng, 0.3, 1.2),
		   sz = TestRngRange(rng, 0.3, 1.2);
	for (int i = 0; i < count; ++i)
	{
		double x = TestRngRange(rng, -1, 1), y = TestRngRange(rng, -1, 1), z = TestRngRange(rng, -1, 1);
		double length = std::sqrt(x * x + y * y + z * z);
		if (onEllipsoid && length > 1e-3)
		{
			x /= length;
			y /= length;
			z /= length;
		}
		points[(size_t)i] = cd3MakeVec((cdReal)(sx * x), (cdReal)(sy * y), (cdReal)(sz * z));
	}
	cd3Hull* hull = nullptr;
	if (cd3ComputeHull(points.data(), count, &hull) != CD_OK)
	{
		return nullptr;
	}
	return hull;
}

btConvexHullShape MakeBulletHull(const cd3Hull* h)
{
	btConvexHullShape shape;
	for (int i = 0; i < h->vertexCount; ++i)
	{
		shape.addPoint(
			btVector3((btScalar)h->vertices[i].x, (btScalar)h->vertices[i].y, (btScalar)h->vertices[i].z),
			false);
	}
	shape.recalcLocalAabb();
	shape.setMargin(0);
	return shape;
}

void TestHulls()
{
	TestRng rng = {0x4011u};
	Tally tally, localTally;
	for (int n = 0; n < 3000; ++n)
	{
		bool onEllipsoid = n % 2 == 1;
		cd3Hull* ha = RandomHull(&rng, 32, onEllipsoid);
		cd3Hull* hb = RandomHull(&rng, 32, onEllipsoid);
		if (ha == nullptr || hb == nullptr)
		{
			TEST_CHECK(false);
			cd3DestroyHull(ha);
			cd3DestroyHull(hb);
			continue;
		}
		cd3Transform ta = RandomTransform(&rng, 0.8), tb = RandomTransform(&rng, 0.8);
		double face, edge;
		BruteSat(FromHull(ha, ta), FromHull(hb, tb), &face, &edge);
		double reference = std::max(face, edge);
		cd3HullShape a = {ha, ta}, b = {hb, tb};
		cd3Manifold m = cd3CollideHullHull(a, b, CD_R(0.0));
		double collideSep = m.pointCount > 0 ? MinSeparation(m) : INFINITY;
		// The local-frame form: both hulls in their own frames, B's frame in A's.
		cd3HullShape la = {ha, CD3_TRANSFORM_IDENTITY}, lb = {hb, CD3_TRANSFORM_IDENTITY};
		cd3Manifold ml = cd3CollideHullHullLocal(la, lb, cd3InvMulTransforms(ta, tb), CD_R(0.0));
		double localSep = ml.pointCount > 0 ? MinSeparation(ml) : INFINITY;

		btConvexHullShape bulletA = MakeBulletHull(ha), bulletB = MakeBulletHull(hb);
		btVoronoiSimplexSolver simplex;
		btGjkEpaPenetrationDepthSolver epa;
		btGjkPairDetector detector(&bulletA, &bulletB, &simplex, &epa);
		btDiscreteCollisionDetectorInterface::ClosestPointInput input;
		input.m_transformA = ToBullet(ta);
		input.m_transformB = ToBullet(tb);
		MinResult result;
		detector.getClosestPoints(input, result, nullptr);
		double size = (double)(cd3Length(cd3Sub(ha->bounds.max, ha->bounds.min)) +
							   cd3Length(cd3Sub(hb->bounds.max, hb->bounds.min)));
		Compare("hull-hull", n, reference, face, edge, size, collideSep, result.count > 0, result.distance,
				0.0, &tally);
		Compare("hull-hull local", n, reference, face, edge, size, localSep, result.count > 0,
				result.distance, 0.0, &localTally);
		if (std::fabs(reference) > 1e-3)
		{
			TEST_CHECKF((m.pointCount > 0) == (reference <= 0.0), "hull-hull #%d: %d points, exact %.9g", n,
						m.pointCount, reference);
			TEST_CHECKF((ml.pointCount > 0) == (reference <= 0.0),
						"hull-hull local #%d: %d points, exact %.9g", n, ml.pointCount, reference);
		}
		cd3DestroyHull(ha);
		cd3DestroyHull(hb);
	}
	std::printf(
		"hull-hull: %d compared, %d face/edge ties skipped, Bullet (GJK/EPA) depth off by more than 1e-4 "
		"relative on %d, overlap answer differs on %d\n",
		tally.compared, tally.skippedTies, tally.bulletDisagrees, tally.bulletOverlapDisagrees);
	TEST_CHECK(tally.compared > 1500);
	std::printf("hull-hull, local form (cd3CollideHullHullLocal): %d compared against the exact depth\n",
				localTally.compared);
	TEST_CHECK(localTally.compared > 1500);
	// Bullet is a peer, not the reference: it must agree on the large majority.
	TEST_CHECK(tally.bulletDisagrees * 20 < tally.compared);
	TEST_CHECK(tally.bulletOverlapDisagrees * 100 < tally.compared);
}
} // namespace

int main()
{
	TEST_RUN(TestBoxes);
	TEST_RUN(TestHulls);
	return TEST_SUMMARY();
}
