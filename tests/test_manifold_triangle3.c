/* Tests of cd3CollideTriangleTriangle: exact face, coplanar, crossing and edge-edge cases,
 * degenerate triangles, and random pairs against cd3Distance / cd3OverlapTriangleTriangle
 * (overlap <=> a point with non-positive separation, the separation of apart pairs is their
 * distance), points on both triangles, symmetry (A, B vs B, A) and invariance under a rigid
 * transform. */
#include "collide/manifold3.h"

#include "manifold_separation3.h"
#include "test.h"

#include <stdbool.h>

#define V3(x, y, z) cd3MakeVec((cdReal)(x), (cdReal)(y), (cdReal)(z))

/* Round-off allowance: coordinates are up to ~4. */
#define TOL (CD_DOUBLE ? 1e-9 : 5e-5)
/* Reference distances this close to a decision boundary are skipped. */
#define BAND 2e-3

static cd3Triangle Tri(cd3Vec a, cd3Vec b, cd3Vec c)
{
	cd3Triangle t = {a, b, c};
	return t;
}

static double DistanceToTriangle(cd3Triangle t, cd3Vec p)
{
	cd3Shape shape = cd3MakeTriangleShape(t);
	return (double)cd3VecDistance(cd3ClosestPointOnShape(&shape, p), p);
}

static bool IsFiniteManifold(const cd3Manifold* m)
{
	bool ok = cd3IsValidVec(m->normal) && m->pointCount >= 0 && m->pointCount <= 4;
	for (int i = 0; ok && i < m->pointCount; ++i)
	{
		ok = cd3IsValidVec(m->points[i].point) && isfinite((double)m->points[i].separation);
	}
	if (ok && m->pointCount > 0)
	{
		ok = fabs((double)cd3Length(m->normal) - 1.0) <= 1e-4;
	}
	return ok;
}

/* Each point lies midway: point - s/2 n on A and point + s/2 n on B. */
static bool PointsOnBoth(const cd3Manifold* m, cd3Triangle a, cd3Triangle b, double tolerance, double* worst)
{
	*worst = 0.0;
	for (int i = 0; i < m->pointCount; ++i)
	{
		cdReal h = CD_R(0.5) * m->points[i].separation;
		cd3Vec onA = cd3MulSub(m->points[i].point, h, m->normal);
		cd3Vec onB = cd3MulAdd(m->points[i].point, h, m->normal);
		*worst = fmax(*worst, fmax(DistanceToTriangle(a, onA), DistanceToTriangle(b, onB)));
	}
	return *worst <= tolerance;
}

static void CheckNormal(const cd3Manifold* m, double x, double y, double z)
{
	TEST_CHECKF(m->pointCount > 0 && fabs((double)m->normal.x - x) <= TOL &&
					fabs((double)m->normal.y - y) <= TOL && fabs((double)m->normal.z - z) <= TOL,
				"normal (%.9g %.9g %.9g), expected (%g %g %g), %d points", (double)m->normal.x,
				(double)m->normal.y, (double)m->normal.z, x, y, z, m->pointCount);
}

/* ---- exact cases ------------------------------------------------------------------------------ */

static void TestFaces(void)
{
	cd3Triangle a = Tri(V3(0, 0, 0), V3(4, 0, 0), V3(0, 4, 0));
	double worst;
	for (int side = 0; side < 2; ++side)
	{
		double h = side == 0 ? 0.05 : -0.05;
		cd3Triangle b = Tri(V3(1, 1, h), V3(2, 1, h), V3(1, 2, h));
		cd3Manifold m = cd3CollideTriangleTriangle(a, b, CD_R(0.1));
		TEST_CHECK(m.pointCount == 3);
		CheckNormal(&m, 0, 0, side == 0 ? 1 : -1);
		for (int i = 0; i < m.pointCount; ++i)
		{
			TEST_CHECK_NEAR(m.points[i].separation, 0.05, TOL);
			TEST_CHECK_NEAR(m.points[i].point.z, 0.5 * h, TOL);
		}
		TEST_CHECK(PointsOnBoth(&m, a, b, TOL, &worst));
		/* Ids differ between points and stay the same when B moves a little. */
		cd3Triangle moved = Tri(V3(1.01, 1, h), V3(2.01, 1, h), V3(1.01, 2, h));
		cd3Manifold m2 = cd3CollideTriangleTriangle(a, moved, CD_R(0.1));
		TEST_CHECK(m2.pointCount == 3 && m.points[0].id != m.points[1].id &&
				   m.points[1].id != m.points[2].id && m.points[0].id != m.points[2].id);
		for (int i = 0; i < 3 && m2.pointCount == 3; ++i)
		{
			TEST_CHECK(m2.points[i].id == m.points[i].id);
		}
		/* Beyond the speculative distance: nothing. */
		TEST_CHECK(cd3CollideTriangleTriangle(a, b, CD_R(0.04)).pointCount == 0);
	}

	/* B hangs over A's edge: clipped at A's side plane x + y = 4... here at x = 0. */
	cd3Triangle over = Tri(V3(-1, 1, 0.02), V3(1, 1, 0.02), V3(-1, 2, 0.02));
	cd3Manifold m = cd3CollideTriangleTriangle(a, over, CD_R(0.05));
	CheckNormal(&m, 0, 0, 1);
	TEST_CHECK(m.pointCount == 3);
	for (int i = 0; i < m.pointCount; ++i)
	{
		TEST_CHECK(m.points[i].point.x >= -CD_R(1e-6));
		TEST_CHECK_NEAR(m.points[i].separation, 0.02, TOL);
	}
	TEST_CHECK(PointsOnBoth(&m, a, over, TOL, &worst));

	/* B's vertex just beside A's edge and just above its plane, closer than the direct path's
	 * threshold: nothing of B lies over A's face, the contact is the closest pair. */
	cd3Triangle beside = Tri(V3(-3e-4, 1, 2e-4), V3(-1, 1, 1), V3(-1, 2, 1));
	m = cd3CollideTriangleTriangle(a, beside, CD_R(0.01));
	TEST_CHECK(m.pointCount == 1 && IsFiniteManifold(&m));
	TEST_CHECK(m.pointCount == 1 && fabs((double)m.points[0].separation - sqrt(13e-8)) <= 1e-6 + TOL);
	TEST_CHECK(PointsOnBoth(&m, a, beside, 2e-4, &worst));

	/* Tilted above A: only the low vertex is within reach. */
	cd3Triangle tilted = Tri(V3(1, 1, 0.01), V3(2, 1, 1), V3(1, 2, 1));
	m = cd3CollideTriangleTriangle(a, tilted, CD_R(0.05));
	TEST_CHECK(m.pointCount == 1);
	CheckNormal(&m, 0, 0, 1);
	TEST_CHECK_NEAR(m.points[0].separation, 0.01, TOL);
	TEST_CHECK(PointsOnBoth(&m, a, tilted, TOL, &worst));
}

static void TestCoplanar(void)
{
	cd3Triangle a = Tri(V3(0, 0, 0), V3(4, 0, 0), V3(0, 4, 0));
	cd3Triangle inside = Tri(V3(1, 1, 0), V3(2, 1, 0), V3(1, 2, 0));
	cd3Manifold m = cd3CollideTriangleTriangle(a, inside, CD_R(0.0));
	TEST_CHECK(m.pointCount == 3);
	TEST_CHECK(fabs((double)m.normal.z) >= 1.0 - TOL);
	double worst;
	for (int i = 0; i < m.pointCount; ++i)
	{
		TEST_CHECK_NEAR(m.points[i].separation, 0.0, TOL);
	}
	TEST_CHECK(PointsOnBoth(&m, a, inside, TOL, &worst));

	/* A hexagonal overlap reduced to 4 points. */
	cd3Triangle across = Tri(V3(3, 3, 0), V3(-1, 1.5, 0), V3(1.5, -1, 0));
	m = cd3CollideTriangleTriangle(a, across, CD_R(0.0));
	TEST_CHECK(m.pointCount == 4);
	for (int i = 0; i < m.pointCount; ++i)
	{
		TEST_CHECK_NEAR(m.points[i].separation, 0.0, TOL);
	}
	TEST_CHECK(PointsOnBoth(&m, a, across, TOL, &worst));

	/* Coplanar and apart within the plane: one point at the gap. */
	cd3Triangle beside = Tri(V3(2.1, 2.1, 0), V3(4, 2.1, 0), V3(2.1, 4, 0));
	m = cd3CollideTriangleTriangle(a, beside, CD_R(0.5));
	TEST_CHECK(m.pointCount == 1);
	CheckNormal(&m, sqrt(0.5), sqrt(0.5), 0);
	TEST_CHECK_NEAR(m.points[0].separation, 0.2 * sqrt(0.5), TOL);
	TEST_CHECK(cd3CollideTriangleTriangle(a, beside, CD_R(0.1)).pointCount == 0);
}

static void TestCrossing(void)
{
	double worst;
	/* B stands in the plane y = 1 and dips 0.1 below A's plane: pushed up along A's normal. */
	cd3Triangle a = Tri(V3(0, 0, 0), V3(4, 0, 0), V3(0, 4, 0));
	cd3Triangle b = Tri(V3(1, 1, -0.1), V3(2, 1, -0.1), V3(1.5, 1, 2));
	cd3Manifold m = cd3CollideTriangleTriangle(a, b, CD_R(0.0));
	CheckNormal(&m, 0, 0, 1);
	TEST_CHECK(m.pointCount == 2);
	for (int i = 0; i < m.pointCount; ++i)
	{
		TEST_CHECK_NEAR(m.points[i].separation, -0.1, TOL);
	}
	TEST_CHECK(PointsOnBoth(&m, a, b, TOL, &worst));

	/* Ids stay while B moves a little (same features), and the two points' ids differ. */
	cd3Triangle nudged = Tri(V3(1.02, 1.01, -0.09), V3(2.02, 1.01, -0.09), V3(1.52, 1.01, 2));
	cd3Manifold m2 = cd3CollideTriangleTriangle(a, nudged, CD_R(0.0));
	TEST_CHECK(m.pointCount == 2 && m2.pointCount == 2 && m.points[0].id != m.points[1].id);
	for (int i = 0; i < 2 && m.pointCount == 2 && m2.pointCount == 2; ++i)
	{
		TEST_CHECK(m2.points[i].id == m.points[i].id);
	}

	/* The same from below: B's tip pokes 0.1 above A, pushed down. */
	cd3Triangle below = Tri(V3(1, 1, 0.1), V3(2, 1, 0.1), V3(1.5, 1, -2));
	m = cd3CollideTriangleTriangle(a, below, CD_R(0.0));
	CheckNormal(&m, 0, 0, -1);
	TEST_CHECK(m.pointCount == 2 && fabs(MinSeparation(&m) + 0.1) <= TOL);

	/* Edge against edge: A hangs down from an edge along x, B stands up on an edge along y,
	 * overlapping by 0.05 in z. */
	cd3Triangle hanging = Tri(V3(-1, 0, 0), V3(1, 0, 0), V3(0, 0, -2));
	cd3Triangle standing = Tri(V3(0, -1, -0.05), V3(0, 1, -0.05), V3(0, 0, 2));
	m = cd3CollideTriangleTriangle(hanging, standing, CD_R(0.0));
	TEST_CHECK(m.pointCount == 1);
	CheckNormal(&m, 0, 0, 1);
	if (m.pointCount == 1)
	{
		TEST_CHECK_NEAR(m.points[0].separation, -0.05, TOL);
		TEST_CHECK(cd3VecDistance(m.points[0].point, V3(0, 0, -0.025)) <= (cdReal)TOL);
		TEST_CHECK((m.points[0].id & CD3_FEATURE_EDGES) != 0u);
	}
	/* Apart by 0.05 instead: the distance, same normal. */
	cd3Triangle apart = Tri(V3(0, -1, 0.05), V3(0, 1, 0.05), V3(0, 0, 2));
	m = cd3CollideTriangleTriangle(hanging, apart, CD_R(0.1));
	TEST_CHECK(m.pointCount == 1);
	CheckNormal(&m, 0, 0, 1);
	TEST_CHECK(m.pointCount == 1 && fabs((double)m.points[0].separation - 0.05) <= TOL);
	TEST_CHECK(PointsOnBoth(&m, hanging, apart, TOL, &worst));
}

static void TestDegenerate(void)
{
	cd3Triangle a = Tri(V3(0, 0, 0), V3(4, 0, 0), V3(0, 4, 0));
	cd3Vec p = V3(1, 1, 0.03);
	cd3Triangle point = Tri(p, p, p);
	cd3Manifold m = cd3CollideTriangleTriangle(a, point, CD_R(0.05));
	TEST_CHECK(IsFiniteManifold(&m) && m.pointCount == 1);
	CheckNormal(&m, 0, 0, 1);
	TEST_CHECK(m.pointCount == 1 && fabs((double)m.points[0].separation - 0.03) <= TOL);
	m = cd3CollideTriangleTriangle(point, a, CD_R(0.05));
	CheckNormal(&m, 0, 0, -1);

	cd3Triangle segment = Tri(V3(1, 1, -0.02), V3(2, 2, -0.02), V3(1.5, 1.5, -0.02));
	m = cd3CollideTriangleTriangle(a, segment, CD_R(0.05));
	TEST_CHECK(IsFiniteManifold(&m) && m.pointCount >= 1);
	CheckNormal(&m, 0, 0, -1);
	TEST_CHECK(fabs(MinSeparation(&m) - 0.02) <= TOL);

	/* A segment piercing A: touching, finite. */
	cd3Triangle piercing = Tri(V3(1, 1, -1), V3(1, 1, 1), V3(1, 1, 0.5));
	m = cd3CollideTriangleTriangle(a, piercing, CD_R(0.0));
	TEST_CHECK(IsFiniteManifold(&m) && m.pointCount >= 1 && MinSeparation(&m) <= 0.0);

	/* Two points, two collinear segments: no NaN. */
	cd3Triangle other = Tri(V3(1, 1, 0.03), V3(1, 1, 0.03), V3(1, 1, 0.03));
	m = cd3CollideTriangleTriangle(point, other, CD_R(0.0));
	TEST_CHECK(IsFiniteManifold(&m) && m.pointCount == 1 && m.points[0].separation <= CD_R(0.0));
	cd3Triangle s1 = Tri(V3(0, 0, 0), V3(1, 0, 0), V3(2, 0, 0));
	cd3Triangle s2 = Tri(V3(1.5, 0, 0), V3(3, 0, 0), V3(2, 0, 0));
	m = cd3CollideTriangleTriangle(s1, s2, CD_R(0.0));
	TEST_CHECK(IsFiniteManifold(&m) && m.pointCount == 1);
	cd3Triangle s3 = Tri(V3(0, 0.5, 0), V3(1, 0.5, 0), V3(2, 0.5, 0));
	m = cd3CollideTriangleTriangle(s1, s3, CD_R(1.0));
	TEST_CHECK(IsFiniteManifold(&m) && m.pointCount == 1);
	CheckNormal(&m, 0, 1, 0);
	TEST_CHECK(m.pointCount == 1 && fabs((double)m.points[0].separation - 0.5) <= TOL);
}

/* ---- an independent separating axis test, in double ------------------------------------------ */

typedef struct DVec
{
	double x, y, z;
} DVec;

static DVec D(cd3Vec v)
{
	DVec d = {(double)v.x, (double)v.y, (double)v.z};
	return d;
}

static DVec DSub(DVec a, DVec b)
{
	DVec d = {a.x - b.x, a.y - b.y, a.z - b.z};
	return d;
}

static DVec DCross(DVec a, DVec b)
{
	DVec d = {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
	return d;
}

static double DDot(DVec a, DVec b)
{
	return a.x * b.x + a.y * b.y + a.z * b.z;
}

/* Separation along an axis; two-sided: B read on the side it lies (the larger of the two gaps). */
static double DAxisSeparation(const DVec* a, const DVec* b, DVec axis, bool twoSided)
{
	double length = sqrt(DDot(axis, axis));
	double aLow = INFINITY, aHigh = -INFINITY, bLow = INFINITY, bHigh = -INFINITY;
	for (int i = 0; i < 3; ++i)
	{
		aLow = fmin(aLow, DDot(a[i], axis) / length);
		aHigh = fmax(aHigh, DDot(a[i], axis) / length);
		bLow = fmin(bLow, DDot(b[i], axis) / length);
		bHigh = fmax(bHigh, DDot(b[i], axis) / length);
	}
	return twoSided ? fmax(bLow - aHigh, aLow - bHigh) : bLow - aHigh;
}

/* The largest separation over both face normals and the nine edge-edge axes (the faces of the
 * Minkowski difference of two triangles that are not parallel). */
static double ReferenceSat(cd3Triangle ta, cd3Triangle tb)
{
	DVec a[3] = {D(ta.a), D(ta.b), D(ta.c)}, b[3] = {D(tb.a), D(tb.b), D(tb.c)};
	DVec axes[11];
	int count = 0;
	axes[count++] = DCross(DSub(a[1], a[0]), DSub(a[2], a[0]));
	axes[count++] = DCross(DSub(b[1], b[0]), DSub(b[2], b[0]));
	for (int i = 0; i < 3; ++i)
	{
		for (int j = 0; j < 3; ++j)
		{
			axes[count++] = DCross(DSub(a[(i + 1) % 3], a[i]), DSub(b[(j + 1) % 3], b[j]));
		}
	}
	double best = -INFINITY;
	for (int k = 0; k < count; ++k)
	{
		if (DDot(axes[k], axes[k]) > 1e-12)
		{
			best = fmax(best, DAxisSeparation(a, b, axes[k], true));
		}
	}
	return best;
}

/* ---- random pairs ----------------------------------------------------------------------------- */

static cd3Vec RandomPoint(TestRng* rng, double extent)
{
	return V3(TestRngRange(rng, -extent, extent), TestRngRange(rng, -extent, extent),
			  TestRngRange(rng, -extent, extent));
}

static cd3Triangle RandomTriangle(TestRng* rng, int kind)
{
	cd3Vec center = RandomPoint(rng, 0.8);
	cd3Vec a = cd3Add(center, RandomPoint(rng, 1.0));
	cd3Vec b = cd3Add(center, RandomPoint(rng, 1.0));
	cd3Vec c = cd3Add(center, RandomPoint(rng, 1.0));
	if (kind == 1)
	{
		c = cd3Lerp(a, b, (cdReal)TestRngRange(rng, -0.5, 1.5)); /* collinear */
	}
	else if (kind == 2)
	{
		b = a; /* a segment with a repeated vertex */
	}
	return Tri(a, b, c);
}

static cd3Triangle TransformTriangle(cd3Transform t, cd3Triangle x)
{
	return Tri(cd3TransformPoint(t, x.a), cd3TransformPoint(t, x.b), cd3TransformPoint(t, x.c));
}

static void TestRandomPairs(void)
{
	TestRng rng = TestRngMake(0x7217);
	const cdReal speculative = CD_R(0.1);
	int overlapping = 0, near = 0, apart = 0, symmetric = 0, invariant = 0, deepChecked = 0;
	for (int trial = 0; trial < 4000; ++trial)
	{
		int kindA = trial % 10 == 7 ? 1 : (trial % 10 == 8 ? 2 : 0);
		int kindB = trial % 10 == 9 ? 1 : 0;
		cd3Triangle a = RandomTriangle(&rng, kindA);
		cd3Triangle b = RandomTriangle(&rng, kindB);
		cd3Shape sa = cd3MakeTriangleShape(a), sb = cd3MakeTriangleShape(b);
		double d = (double)cd3Distance(&sa, &sb).distance;
		bool overlap = cd3OverlapTriangleTriangle(a, b);
		cd3Manifold m = cd3CollideTriangleTriangle(a, b, speculative);
		TEST_CHECKF(IsFiniteManifold(&m), "trial %d: not finite", trial);
		double minSeparation = MinSeparation(&m);

		if (d > (double)speculative + BAND)
		{
			TEST_CHECKF(m.pointCount == 0, "trial %d: distance %.6g, %d points", trial, d, m.pointCount);
			continue;
		}
		if (d < BAND && d > 0.0)
		{
			continue; /* at the boundary between touching and apart */
		}
		if (d > (double)speculative - BAND)
		{
			continue;
		}
		TEST_CHECKF(m.pointCount > 0, "trial %d: distance %.6g, no points", trial, d);
		if (m.pointCount == 0)
		{
			continue;
		}
		if (d == 0.0)
		{
			TEST_CHECKF(overlap, "trial %d: distance 0 but cd3OverlapTriangleTriangle false", trial);
			TEST_CHECKF(minSeparation <= 0.0, "trial %d: overlapping, min separation %.6g", trial,
						minSeparation);
			/* The depth is the least overlap over the axes (within the choice bias, 1e-4 of the
			 * size ~3.5), never deeper: no point is below what the best axis allows. */
			if (kindA == 0 && kindB == 0)
			{
				double best = ReferenceSat(a, b);
				DVec pa[3] = {D(a.a), D(a.b), D(a.c)}, pb[3] = {D(b.a), D(b.b), D(b.c)};
				double alongNormal = DAxisSeparation(pa, pb, D(m.normal), false);
				TEST_CHECKF(alongNormal >= best - 4e-4 - 10 * TOL && minSeparation >= best - 4e-4 - 10 * TOL,
							"trial %d: overlap along the normal %.9g, min separation %.9g, best axis %.9g",
							trial, alongNormal, minSeparation, best);
				++deepChecked;
			}
			++overlapping;
		}
		else
		{
			TEST_CHECKF(!overlap, "trial %d: distance %.6g but overlap", trial, d);
			/* Apart: the smallest separation is the distance. */
			TEST_CHECKF(fabs(minSeparation - d) <= 1e-4, "trial %d: min separation %.9g, distance %.9g",
						trial, minSeparation, d);
			++apart;
		}
		++near;
		double worst;
		TEST_CHECKF(PointsOnBoth(&m, a, b, 2e-3, &worst), "trial %d: a point is %.3g off its triangle", trial,
					worst);
		for (int i = 0; i < m.pointCount; ++i)
		{
			TEST_CHECK(m.points[i].separation <= speculative);
		}

		/* Symmetry: B against A reports the same contact with the opposite normal (apart pairs
		 * have one answer; crossing pairs may pick another axis within the bias). */
		cd3Manifold r = cd3CollideTriangleTriangle(b, a, speculative);
		if (d > 0.0)
		{
			TEST_CHECKF(r.pointCount > 0 && fabs(MinSeparation(&r) - minSeparation) <= 1e-4 &&
							cd3VecDistance(r.normal, cd3Neg(m.normal)) <= CD_R(1e-3),
						"trial %d: reversed pair: %d points, separation %.9g vs %.9g", trial, r.pointCount,
						MinSeparation(&r), minSeparation);
			++symmetric;
		}
		else
		{
			TEST_CHECKF(r.pointCount > 0 && MinSeparation(&r) <= 0.0, "trial %d: reversed pair not touching",
						trial);
		}

		/* Invariance under a common rigid transform. */
		cd3Vec axis = cd3Normalize(RandomPoint(&rng, 1.0));
		if (cd3LengthSquared(axis) == CD_R(0.0))
		{
			continue;
		}
		cd3Transform t = {RandomPoint(&rng, 3.0),
						  cd3MakeQuatAxisAngle(axis, (cdReal)TestRngRange(&rng, -3, 3))};
		cd3Manifold moved =
			cd3CollideTriangleTriangle(TransformTriangle(t, a), TransformTriangle(t, b), speculative);
		bool ok = moved.pointCount > 0 && fabs(MinSeparation(&moved) - minSeparation) <= 1e-3;
		if (ok && d > 0.0)
		{
			ok = cd3VecDistance(moved.normal, cd3RotateVector(t.q, m.normal)) <= CD_R(1e-3);
		}
		TEST_CHECKF(ok, "trial %d: moved pair: %d points, separation %.9g vs %.9g", trial, moved.pointCount,
					MinSeparation(&moved), minSeparation);
		invariant += ok;
	}
	printf(
		"triangle pairs: %d near (%d overlapping, %d depth-checked, %d apart), %d symmetric, %d invariant\n",
		near, overlapping, deepChecked, apart, symmetric, invariant);
	TEST_CHECK(overlapping > 300 && deepChecked > 200 && apart > 100 && invariant > 400);
}

/* Parallel and coplanar random pairs: the face contact's points span the overlap. */
static void TestRandomParallel(void)
{
	TestRng rng = TestRngMake(0x9A2A);
	int faces = 0;
	for (int trial = 0; trial < 1000; ++trial)
	{
		double gap = trial % 3 == 0 ? 0.0 : TestRngRange(&rng, -0.05, 0.05);
		cd3Triangle a = Tri(V3(TestRngRange(&rng, -1, 0), TestRngRange(&rng, -1, 0), 0),
							V3(TestRngRange(&rng, 0.5, 1.5), TestRngRange(&rng, -1, 0), 0),
							V3(TestRngRange(&rng, -1, 1), TestRngRange(&rng, 0.5, 1.5), 0));
		cd3Triangle b = Tri(V3(TestRngRange(&rng, -1, 1), TestRngRange(&rng, -1, 1), gap),
							V3(TestRngRange(&rng, -1, 1), TestRngRange(&rng, -1, 1), gap),
							V3(TestRngRange(&rng, -1, 1), TestRngRange(&rng, -1, 1), gap));
		cd3Vec axis = cd3Normalize(RandomPoint(&rng, 1.0));
		if (cd3LengthSquared(axis) == CD_R(0.0))
		{
			continue;
		}
		cd3Transform t = {RandomPoint(&rng, 2.0),
						  cd3MakeQuatAxisAngle(axis, (cdReal)TestRngRange(&rng, -3, 3))};
		cd3Triangle ta = TransformTriangle(t, a), tb = TransformTriangle(t, b);
		cd3Shape sa = cd3MakeTriangleShape(ta), sb = cd3MakeTriangleShape(tb);
		double d = (double)cd3Distance(&sa, &sb).distance;
		cd3Manifold m = cd3CollideTriangleTriangle(ta, tb, CD_R(0.1));
		TEST_CHECK(IsFiniteManifold(&m));
		/* Only pairs that clearly overlap in the plane: B's footprint meets A's well inside. */
		if (fabs(d - fabs(gap)) > 1e-4 || m.pointCount == 0)
		{
			continue;
		}
		cd3Vec up = cd3RotateVector(t.q, V3(0, 0, 1));
		if (fabs((double)cd3Dot(m.normal, up)) < 1.0 - 1e-4)
		{
			continue; /* the footprints are apart: an edge contact */
		}
		++faces;
		double worst;
		TEST_CHECKF(PointsOnBoth(&m, ta, tb, 1e-3, &worst), "trial %d: a point is %.3g off", trial, worst);
		for (int i = 0; i < m.pointCount; ++i)
		{
			TEST_CHECKF(fabs(fabs((double)m.points[i].separation) - fabs(gap)) <= 1e-4,
						"trial %d: separation %.9g, gap %.9g", trial, (double)m.points[i].separation, gap);
		}
		TEST_CHECK(gap == 0.0 || cd3Dot(m.normal, up) * (cdReal)gap > CD_R(0.0));
	}
	printf("parallel pairs with a face contact: %d\n", faces);
	TEST_CHECK(faces > 200);
}

/* Every scale of the documented range: finite results, unit normals, and (well inside the
 * touching/apart decision) contacts exactly when the triangles touch. */
static void TestScales(void)
{
	TestRng rng = TestRngMake(0x5CA1E3);
	const double scales[] = {1e-9, 1e-4, 1.0, 1e4, 1e9};
	int agreed = 0;
	for (int si = 0; si < 5; ++si)
	{
		double k = scales[si];
		for (int trial = 0; trial < 400; ++trial)
		{
			cd3Triangle a = RandomTriangle(&rng, trial % 7 == 3 ? 1 : 0);
			cd3Triangle b = RandomTriangle(&rng, trial % 7 == 5 ? 2 : 0);
			a = Tri(cd3Scale((cdReal)k, a.a), cd3Scale((cdReal)k, a.b), cd3Scale((cdReal)k, a.c));
			b = Tri(cd3Scale((cdReal)k, b.a), cd3Scale((cdReal)k, b.b), cd3Scale((cdReal)k, b.c));
			cd3Manifold m = cd3CollideTriangleTriangle(a, b, (cdReal)(0.1 * k));
			TEST_CHECKF(IsFiniteManifold(&m), "scale %g trial %d: not finite", k, trial);
			cd3Shape sa = cd3MakeTriangleShape(a), sb = cd3MakeTriangleShape(b);
			double d = (double)cd3Distance(&sa, &sb).distance / k;
			if (d == 0.0)
			{
				TEST_CHECKF(m.pointCount > 0 && MinSeparation(&m) <= 0.0,
							"scale %g trial %d: touching, %d points", k, trial, m.pointCount);
				++agreed;
			}
			else if (d > 0.02 && d < 0.08)
			{
				TEST_CHECKF(m.pointCount > 0 && fabs(MinSeparation(&m) / k - d) <= 1e-3,
							"scale %g trial %d: distance %.6g, %d points, separation %.6g", k, trial, d,
							m.pointCount, MinSeparation(&m) / k);
				++agreed;
			}
			else if (d > 0.12)
			{
				TEST_CHECK(m.pointCount == 0);
				++agreed;
			}
		}
	}
	TEST_CHECK(agreed > 1000);
}

/* Needles and slivers (one side 1e-4 of the others, or a vertex 1e-5 off the opposite edge)
 * against ordinary triangles (and now and then against each other):
 * finite results, and contacts exactly when touching (away from the boundary). */
static void TestNeedles(void)
{
	TestRng rng = TestRngMake(0x9EED);
	int touching = 0, apart = 0;
	for (int trial = 0; trial < 2000; ++trial)
	{
		cd3Triangle t[2];
		t[1] = RandomTriangle(&rng, 0);
		for (int k = 0; k < (trial % 8 == 7 ? 2 : 1); ++k)
		{
			cd3Vec centroid = cd3Scale(CD_R(1.0) / CD_R(3.0), cd3Add(cd3Add(t[1].a, t[1].b), t[1].c));
			cd3Vec p = cd3Add(centroid, RandomPoint(&rng, 1.0)), q = cd3Sub(centroid, RandomPoint(&rng, 1.0));
			double thin = trial % 2 == 0 ? 1e-4 : 1e-5;
			cd3Vec offset = cd3Scale((cdReal)thin, RandomPoint(&rng, 1.0));
			t[k] = trial % 4 < 2 ? Tri(p, q, cd3Add(q, offset))							/* needle */
								 : Tri(p, q, cd3Add(cd3Lerp(p, q, CD_R(0.5)), offset)); /* sliver */
		}
		cd3Manifold m = cd3CollideTriangleTriangle(t[0], t[1], CD_R(0.05));
		TEST_CHECKF(IsFiniteManifold(&m), "trial %d: not finite", trial);
		cd3Shape sa = cd3MakeTriangleShape(t[0]), sb = cd3MakeTriangleShape(t[1]);
		double d = (double)cd3Distance(&sa, &sb).distance;
		if (d == 0.0)
		{
			TEST_CHECKF(m.pointCount > 0 && MinSeparation(&m) <= 0.0, "trial %d: touching, %d points", trial,
						m.pointCount);
			++touching;
		}
		else if (d > 0.05 + BAND)
		{
			TEST_CHECKF(m.pointCount == 0, "trial %d: apart by %.6g, %d points", trial, d, m.pointCount);
			++apart;
		}
		else if (d > BAND && d < 0.05 - BAND)
		{
			TEST_CHECKF(m.pointCount > 0 && fabs(MinSeparation(&m) - d) <= 1e-4,
						"trial %d: distance %.6g, separation %.6g", trial, d, MinSeparation(&m));
		}
	}
	printf("needles: %d touching, %d apart\n", touching, apart);
	TEST_CHECK(touching > 200 && apart > 200);
}

int main(void)
{
	TEST_RUN(TestFaces);
	TEST_RUN(TestCoplanar);
	TEST_RUN(TestCrossing);
	TEST_RUN(TestDegenerate);
	TEST_RUN(TestRandomPairs);
	TEST_RUN(TestRandomParallel);
	TEST_RUN(TestScales);
	TEST_RUN(TestNeedles);
	return TEST_SUMMARY();
}
