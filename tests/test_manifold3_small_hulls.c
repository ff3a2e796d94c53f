/* Hull-hull contacts of small hulls, whose separating-axis test takes the paths of its size: the
 * Gauss-map test as sign masks (A with at most 32 edges and 16 faces), as dot products per edge
 * pair (more), B carried into A's frame once (at most 64 vertices and faces) or per edge, and the
 * brute separating-axis test itself (at most 1,024 edge pairs). Over random overlapping pairs of
 * hulls of 4 to 48 points, in both argument orders, the depth of the manifold must be the exact
 * depth (a brute separating-axis test in double over every face normal and every edge pair's
 * cross product) and the contact must not be empty. */
#include "collide/collide.h"
#include "../src/query/sat3.h" /* internal: the pruned separating-axis test against the full one */
#include "manifold_separation3.h"
#include "test.h"

#include <math.h>

static cd3Vec RandomUnit(TestRng* rng)
{
	for (;;)
	{
		double x = TestRngRange(rng, -1.0, 1.0), y = TestRngRange(rng, -1.0, 1.0),
			   z = TestRngRange(rng, -1.0, 1.0);
		double length = sqrt(x * x + y * y + z * z);
		if (length > 0.1 && length <= 1.0)
		{
			return cd3MakeVec((cdReal)(x / length), (cdReal)(y / length), (cdReal)(z / length));
		}
	}
}

static cd3Quat RandomRotation(TestRng* rng)
{
	for (;;)
	{
		double x = TestRngRange(rng, -1.0, 1.0), y = TestRngRange(rng, -1.0, 1.0);
		double z = TestRngRange(rng, -1.0, 1.0), w = TestRngRange(rng, -1.0, 1.0);
		double length = sqrt(x * x + y * y + z * z + w * w);
		if (length > 0.1 && length <= 1.0)
		{
			return cd3MakeQuat((cdReal)(x / length), (cdReal)(y / length), (cdReal)(z / length),
							   (cdReal)(w / length));
		}
	}
}

/* A hull of `count` points on a jittered, stretched sphere of size about 1. */
static cd3Hull* RandomHull(TestRng* rng, int count)
{
	cd3Hull* hull = NULL;
	while (hull == NULL)
	{
		cd3Vec points[64];
		double sx = TestRngRange(rng, 0.4, 1.0), sy = TestRngRange(rng, 0.4, 1.0),
			   sz = TestRngRange(rng, 0.4, 1.0);
		for (int i = 0; i < count; ++i)
		{
			cd3Vec u = RandomUnit(rng);
			double r = TestRngRange(rng, 0.85, 1.15);
			points[i] = cd3MakeVec((cdReal)(r * sx * u.x), (cdReal)(r * sy * u.y), (cdReal)(r * sz * u.z));
		}
		cd3ComputeHull(points, count, &hull);
	}
	return hull;
}

typedef struct Placed
{
	double v[64][3];
	int count;
	const cd3Hull* hull;
	cd3Quat rotation;
} Placed;

static void Place(const cd3HullShape* s, Placed* p)
{
	p->hull = s->hull;
	p->rotation = s->transform.q;
	p->count = s->hull->vertexCount;
	for (int i = 0; i < p->count; ++i)
	{
		cd3Vec w = cd3TransformPoint(s->transform, s->hull->vertices[i]);
		p->v[i][0] = (double)w.x;
		p->v[i][1] = (double)w.y;
		p->v[i][2] = (double)w.z;
	}
}

static void Extent(const Placed* p, const double* axis, double* lo, double* hi)
{
	*lo = INFINITY;
	*hi = -INFINITY;
	for (int i = 0; i < p->count; ++i)
	{
		double d = p->v[i][0] * axis[0] + p->v[i][1] * axis[1] + p->v[i][2] * axis[2];
		*lo = fmin(*lo, d);
		*hi = fmax(*hi, d);
	}
}

/* Separation of the two along the axis (unit or not: normalized here); -INFINITY for a null axis. */
static double AxisGap(const Placed* a, const Placed* b, double x, double y, double z)
{
	double length = sqrt(x * x + y * y + z * z);
	if (!(length > 1e-9))
	{
		return -INFINITY;
	}
	double axis[3] = {x / length, y / length, z / length};
	double loA, hiA, loB, hiB;
	Extent(a, axis, &loA, &hiA);
	Extent(b, axis, &loB, &hiB);
	return fmax(loB - hiA, loA - hiB);
}

/* The exact signed separation of two convex polytopes: the largest gap over the face normals and the cross
 * products of every pair of edges. */
static double BruteSeparation(const Placed* a, const Placed* b)
{
	double best = -INFINITY;
	const Placed* both[2] = {a, b};
	for (int s = 0; s < 2; ++s)
	{
		const Placed* p = both[s];
		for (int f = 0; f < p->hull->faceCount; ++f)
		{
			cd3Vec n = cd3RotateVector(p->rotation, p->hull->planes[f].normal);
			best = fmax(best, AxisGap(a, b, (double)n.x, (double)n.y, (double)n.z));
		}
	}
	for (int i = 0; i < a->hull->edgeCount; ++i)
	{
		const cd3HullHalfEdge* ea = &a->hull->edges[i];
		const double* a0 = a->v[ea->origin];
		const double* a1 = a->v[a->hull->edges[ea->twin].origin];
		double da[3] = {a1[0] - a0[0], a1[1] - a0[1], a1[2] - a0[2]};
		for (int j = 0; j < b->hull->edgeCount; ++j)
		{
			const cd3HullHalfEdge* eb = &b->hull->edges[j];
			const double* b0 = b->v[eb->origin];
			const double* b1 = b->v[b->hull->edges[eb->twin].origin];
			double db[3] = {b1[0] - b0[0], b1[1] - b0[1], b1[2] - b0[2]};
			best = fmax(best, AxisGap(a, b, da[1] * db[2] - da[2] * db[1], da[2] * db[0] - da[0] * db[2],
									  da[0] * db[1] - da[1] * db[0]));
		}
	}
	return best;
}

/* Overlapping pairs of hulls of the given point counts (their edge pairs at most 1,024: the
 * separating-axis path): the depth is exact in both orders. Returns the pairs checked. */
static int CheckPairs(TestRng* rng, int countA, int countB, int pairs)
{
	int checked = 0;
	for (int k = 0; k < pairs; ++k)
	{
		cd3Hull* ha = RandomHull(rng, countA);
		cd3Hull* hb = RandomHull(rng, countB);
		if ((ha->edgeCount / 2) * (hb->edgeCount / 2) > 1024)
		{
			cd3DestroyHull(ha);
			cd3DestroyHull(hb);
			continue;
		}
		cd3HullShape a = {ha, {cd3Scale(CD_R(0.2), RandomUnit(rng)), RandomRotation(rng)}};
		cd3HullShape b = {
			hb, {cd3Scale((cdReal)TestRngRange(rng, 0.3, 1.2), RandomUnit(rng)), RandomRotation(rng)}};
		Placed pa, pb;
		Place(&a, &pa);
		Place(&b, &pb);
		double exact = BruteSeparation(&pa, &pb);
		if (exact < -0.005)
		{
			/* The size scale of the tolerances: the smaller hull's diagonal (the bias between a
			 * face of A and one of B, 1e-4 of it, and round-off). */
			double size = 2.5;
			cd3Manifold ab = cd3CollideHullHull(a, b, CD_R(0.0));
			cd3Manifold ba = cd3CollideHullHull(b, a, CD_R(0.0));
			TEST_CHECKF(ab.pointCount > 0 && ba.pointCount > 0,
						"hull(%d)-hull(%d) pair %d: no contact (%d, %d)", countA, countB, k, ab.pointCount,
						ba.pointCount);
			double tolerance = 3e-4 * size;
			TEST_CHECKF(fabs(MinSeparation(&ab) - exact) <= tolerance,
						"hull(%d)-hull(%d) pair %d: depth %g, exact %g", countA, countB, k,
						MinSeparation(&ab), exact);
			TEST_CHECKF(fabs(MinSeparation(&ba) - exact) <= tolerance,
						"hull(%d)-hull(%d) pair %d, B first: depth %g, exact %g", countA, countB, k,
						MinSeparation(&ba), exact);
			++checked;
		}
		cd3DestroyHull(ha);
		cd3DestroyHull(hb);
	}
	return checked;
}

/* Both on the mask path: a tetrahedron (6 edges, 4 faces), hull(8) (18 edges, 12 faces) and
 * hull(10) (up to 24 edges, 16 faces). */
static void TestMaskedGaussTest(void)
{
	TestRng rng = TestRngMake(0x5a7e11u);
	int checked = CheckPairs(&rng, 4, 8, 300) + CheckPairs(&rng, 8, 8, 400) + CheckPairs(&rng, 10, 6, 300);
	TEST_CHECKF(checked > 400, "%d overlapping pairs", checked);
}

/* A beyond the mask path's bounds (more than 16 faces or 32 edges): hull(12) to hull(16) against
 * small ones, in both orders (B first puts the large one in B). */
static void TestLargerA(void)
{
	TestRng rng = TestRngMake(0x5a7e12u);
	int checked = CheckPairs(&rng, 12, 8, 300) + CheckPairs(&rng, 16, 5, 300) + CheckPairs(&rng, 14, 12, 200);
	TEST_CHECKF(checked > 300, "%d overlapping pairs", checked);
}

/* B of more than 64 faces (not carried into A's frame once): hull(40) to hull(48) against a
 * tetrahedron, within 1,024 edge pairs. */
static void TestUncarriedB(void)
{
	TestRng rng = TestRngMake(0x5a7e13u);
	int checked = CheckPairs(&rng, 4, 40, 150) + CheckPairs(&rng, 4, 48, 150);
	TEST_CHECKF(checked > 80, "%d overlapping pairs", checked);
}

static bool SameManifold(const cd3Manifold* x, const cd3Manifold* y)
{
	bool same = x->pointCount == y->pointCount && cd3VecEqual(x->normal, y->normal);
	for (int i = 0; same && i < x->pointCount; ++i)
	{
		same = cd3VecEqual(x->points[i].point, y->points[i].point) &&
			   x->points[i].separation == y->points[i].separation && x->points[i].id == y->points[i].id;
	}
	return same;
}

/* Hulls of at most 16 faces and 32 edges carry precomputed query data, larger ones none; a hull
 * without it (assembled by hand) gets the very same contacts, overlapping or apart, in both orders;
 * and the validator refuses data that is not the hull's own. */
static void TestQueryDataAgrees(void)
{
	TestRng rng = TestRngMake(0x5a7e14u);
	int compared = 0, refused = 0;
	for (int k = 0; k < 600; ++k)
	{
		int countA = 4 + (int)TestRngRange(&rng, 0.0, 9.0), countB = 4 + (int)TestRngRange(&rng, 0.0, 9.0);
		cd3Hull* ha = RandomHull(&rng, countA);
		cd3Hull* hb = RandomHull(&rng, countB);
		for (const cd3Hull* h = ha; h != NULL; h = h == ha ? hb : NULL)
		{
			bool small = h->faceCount <= 16 && h->edgeCount / 2 <= 32;
			TEST_CHECKF((h->queryData != NULL) == small, "%d faces, %d edges: query data %s", h->faceCount,
						h->edgeCount / 2, h->queryData != NULL ? "present" : "absent");
		}
		cd3Hull plainA = *ha, plainB = *hb;
		plainA.queryData = NULL;
		plainB.queryData = NULL;
		TEST_CHECK(cd3ValidateHull(&plainA) == CD_OK && cd3ValidateHull(ha) == CD_OK);
		cd3HullShape a = {ha, {cd3Scale(CD_R(0.2), RandomUnit(&rng)), RandomRotation(&rng)}};
		cd3HullShape b = {
			hb, {cd3Scale((cdReal)TestRngRange(&rng, 0.3, 2.0), RandomUnit(&rng)), RandomRotation(&rng)}};
		cd3HullShape pa = {&plainA, a.transform}, pb = {&plainB, b.transform};
		cd3Manifold withData = cd3CollideHullHull(a, b, CD_R(0.1));
		cd3Manifold without = cd3CollideHullHull(pa, pb, CD_R(0.1));
		cd3Manifold mixed = cd3CollideHullHull(a, pb, CD_R(0.1));
		cd3Manifold reversed = cd3CollideHullHull(b, a, CD_R(0.1));
		cd3Manifold reversedPlain = cd3CollideHullHull(pb, pa, CD_R(0.1));
		TEST_CHECKF(SameManifold(&withData, &without) && SameManifold(&withData, &mixed) &&
						SameManifold(&reversed, &reversedPlain),
					"pair %d (hull(%d)-hull(%d)): %d points with the data, %d without", k, countA, countB,
					withData.pointCount, without.pointCount);
		compared += withData.pointCount > 0;
		/* Another hull's data of the same sizes is not this hull's. */
		if (ha->queryData != NULL && hb->queryData != NULL && ha->edgeCount == hb->edgeCount &&
			ha->faceCount == hb->faceCount)
		{
			cd3Hull swapped = *ha;
			swapped.queryData = hb->queryData;
			TEST_CHECK(cd3ValidateHull(&swapped) == CD_ERROR_INVALID_ARGUMENT);
			++refused;
		}
		cd3DestroyHull(ha);
		cd3DestroyHull(hb);
	}
	TEST_CHECKF(compared > 200 && refused > 20, "%d pairs in contact, %d swaps refused", compared, refused);
}

/* The pruned separating-axis test (the contact path of small polytopes) skips the edges that cannot
 * separate more than the best face less a slack, nor more than zero: over random pairs of hulls (and
 * of a box and a hull), overlapping and apart, its separation and face axes are the full test's bit
 * for bit, and so is its edge pair whenever the full test's separates more than that floor; below
 * it the pruned test's edge pair separates no more than the full test's. */
static void TestPrunedSatAgrees(void)
{
	TestRng rng = TestRngMake(0x5a7e15u);
	int prunedCount = 0, edgesAbove = 0, edgesBest = 0;
	for (int k = 0; k < 1500; ++k)
	{
		int countA = 4 + (int)TestRngRange(&rng, 0.0, 9.0), countB = 4 + (int)TestRngRange(&rng, 0.0, 9.0);
		cd3Hull* ha = RandomHull(&rng, countA);
		cd3Hull* hb = RandomHull(&rng, countB);
		cd3HullShape a = {ha, {cd3Scale(CD_R(0.2), RandomUnit(&rng)), RandomRotation(&rng)}};
		cd3HullShape b = {
			hb, {cd3Scale((cdReal)TestRngRange(&rng, 0.3, 2.5), RandomUnit(&rng)), RandomRotation(&rng)}};
		cd3Polytope pa, pb;
		if (k % 5 == 4)
		{
			cd3Box box = {a.transform.p, cd3MakeVec(CD_R(0.6), CD_R(0.3), CD_R(0.45)), a.transform.q};
			cd3InitBoxPolytope(&pa, box);
		}
		else
		{
			cd3InitHullPolytope(&pa, a);
		}
		cd3InitHullPolytope(&pb, b);
		cdReal slack = CD_R(1.0e-4) * (cdReal)TestRngRange(&rng, 0.0, 4.0);
		cd3SatResult full = cd3SatPolytopes(&pa, &pb);
		bool pruned = false;
		cd3SatResult cut = cd3SatPolytopesPruned(&pa, &pb, CD_REAL_MAX, slack, &pruned);
		prunedCount += pruned;
		TEST_CHECKF(cd3SatSeparation(&cut) == cd3SatSeparation(&full), "pair %d: separation %g, full test %g",
					k, (double)cd3SatSeparation(&cut), (double)cd3SatSeparation(&full));
		TEST_CHECKF(
			cut.faceA == full.faceA && cut.faceB == full.faceB &&
				cut.faceSeparationA == full.faceSeparationA && cut.faceSeparationB == full.faceSeparationB,
			"pair %d: face axes %d %d, full test %d %d", k, cut.faceA, cut.faceB, full.faceA, full.faceB);
		cdReal floor = cdMin(cdMax(full.faceSeparationA, full.faceSeparationB) - slack, CD_R(0.0));
		if (full.edgeA >= 0 && full.edgeSeparation >= floor)
		{
			TEST_CHECKF(cut.edgeA == full.edgeA && cut.edgeB == full.edgeB &&
							cut.edgeSeparation == full.edgeSeparation &&
							cd3VecEqual(cut.edgeNormal, full.edgeNormal),
						"pair %d: edge pair %d-%d at %g, full test %d-%d at %g", k, cut.edgeA, cut.edgeB,
						(double)cut.edgeSeparation, full.edgeA, full.edgeB, (double)full.edgeSeparation);
			++edgesAbove;
			edgesBest += full.edgeSeparation > cdMax(full.faceSeparationA, full.faceSeparationB);
		}
		else
		{
			TEST_CHECKF(cut.edgeSeparation <= full.edgeSeparation, "pair %d: edge pair at %g, full test %g",
						k, (double)cut.edgeSeparation, (double)full.edgeSeparation);
		}
		TEST_CHECK(pruned || (cut.edgeA == full.edgeA && cut.edgeSeparation == full.edgeSeparation));
		cd3DestroyHull(ha);
		cd3DestroyHull(hb);
	}
	TEST_CHECKF(prunedCount > 1200 && edgesAbove > 900 && edgesBest > 500,
				"%d pairs pruned, %d edge pairs above the floor, %d of them the best axis", prunedCount,
				edgesAbove, edgesBest);
}

int main(void)
{
	TEST_RUN(TestPrunedSatAgrees);
	TEST_RUN(TestQueryDataAgrees);
	TEST_RUN(TestMaskedGaussTest);
	TEST_RUN(TestLargerA);
	TEST_RUN(TestUncarriedB);
	return TEST_SUMMARY();
}
