/* Tests of cd2Distance (GJK): exact cases, and thousands of random pairs of every type
 * combination against an independent brute-force reference in double precision (feature
 * enumeration), plus symmetry, rigid-transform invariance and witness-point checks. */
#include "collide/query2.h"
#include "random_shapes2.h"
#include "test.h"

#include "../src/query/support2.h"

#include <math.h>
#include <string.h>

/* ---- double-precision reference ------------------------------------------------------------ */
typedef struct DVec
{
	double x, y;
} DVec;

static DVec DMake(double x, double y)
{
	DVec v = {x, y};
	return v;
}
static DVec DFrom(cd2Vec v)
{
	return DMake((double)v.x, (double)v.y);
}
static DVec DAdd(DVec a, DVec b)
{
	return DMake(a.x + b.x, a.y + b.y);
}
static DVec DSub(DVec a, DVec b)
{
	return DMake(a.x - b.x, a.y - b.y);
}
static DVec DScale(double s, DVec a)
{
	return DMake(s * a.x, s * a.y);
}
static double DDot(DVec a, DVec b)
{
	return a.x * b.x + a.y * b.y;
}
static double DCross(DVec a, DVec b)
{
	return a.x * b.y - a.y * b.x;
}
static double DLength(DVec a)
{
	return sqrt(DDot(a, a));
}

static double PointSegmentDistance(DVec p, DVec a, DVec b)
{
	DVec e = DSub(b, a);
	double ee = DDot(e, e);
	double t = ee > 0.0 ? DDot(DSub(p, a), e) / ee : 0.0;
	t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
	return DLength(DSub(p, DAdd(a, DScale(t, e))));
}

static double SegmentSegmentDistance(DVec p1, DVec q1, DVec p2, DVec q2)
{
	double o1 = DCross(DSub(q1, p1), DSub(p2, p1)), o2 = DCross(DSub(q1, p1), DSub(q2, p1));
	double o3 = DCross(DSub(q2, p2), DSub(p1, p2)), o4 = DCross(DSub(q2, p2), DSub(q1, p2));
	if (((o1 < 0.0 && o2 > 0.0) || (o1 > 0.0 && o2 < 0.0)) &&
		((o3 < 0.0 && o4 > 0.0) || (o3 > 0.0 && o4 < 0.0)))
	{
		return 0.0; /* proper crossing */
	}
	double best = PointSegmentDistance(p1, p2, q2);
	double d = PointSegmentDistance(q1, p2, q2);
	best = d < best ? d : best;
	d = PointSegmentDistance(p2, p1, q1);
	best = d < best ? d : best;
	d = PointSegmentDistance(q2, p1, q1);
	return d < best ? d : best;
}

/* A shape as its core vertices (a closed loop for solids) grown by a radius. */
typedef struct RefShape
{
	DVec vertices[CD2_MAX_POLYGON_VERTICES];
	int count;
	bool solid; /* count >= 3, counter-clockwise */
	double radius;
} RefShape;

static RefShape MakeRef(const cd2Shape* shape)
{
	RefShape r;
	memset(&r, 0, sizeof(r));
	switch (shape->type)
	{
		case CD2_SHAPE_CIRCLE:
			r.vertices[0] = DFrom(shape->circle.center);
			r.count = 1;
			r.radius = (double)shape->circle.radius;
			break;
		case CD2_SHAPE_CAPSULE:
			r.vertices[0] = DFrom(shape->capsule.p1);
			r.vertices[1] = DFrom(shape->capsule.p2);
			r.count = 2;
			r.radius = (double)shape->capsule.radius;
			break;
		case CD2_SHAPE_SEGMENT:
			r.vertices[0] = DFrom(shape->segment.p1);
			r.vertices[1] = DFrom(shape->segment.p2);
			r.count = 2;
			break;
		case CD2_SHAPE_AABB:
		{
			DVec lo = DFrom(shape->aabb.min), hi = DFrom(shape->aabb.max);
			r.vertices[0] = lo;
			r.vertices[1] = DMake(hi.x, lo.y);
			r.vertices[2] = hi;
			r.vertices[3] = DMake(lo.x, hi.y);
			r.count = 4;
			r.solid = true;
			break;
		}
		case CD2_SHAPE_BOX:
		{
			DVec c = DFrom(shape->box.center), h = DFrom(shape->box.halfExtents);
			double cs = (double)shape->box.rotation.c, sn = (double)shape->box.rotation.s;
			DVec ax = DMake(cs * h.x, sn * h.x), ay = DMake(-sn * h.y, cs * h.y);
			r.vertices[0] = DSub(DSub(c, ax), ay);
			r.vertices[1] = DSub(DAdd(c, ax), ay);
			r.vertices[2] = DAdd(DAdd(c, ax), ay);
			r.vertices[3] = DAdd(DSub(c, ax), ay);
			r.count = 4;
			r.solid = true;
			break;
		}
		case CD2_SHAPE_POLYGON:
			for (int i = 0; i < shape->polygon.count; ++i)
			{
				r.vertices[i] = DFrom(shape->polygon.vertices[i]);
			}
			r.count = shape->polygon.count;
			r.radius = (double)shape->polygon.radius;
			r.solid = true;
			break;
		default:
			break;
	}
	return r;
}

/* Twice the signed area of the core loop (0 for points and segments). */
static double RefArea(const RefShape* r)
{
	double area = 0.0;
	for (int i = 0; r->solid && i < r->count; ++i)
	{
		area += DCross(r->vertices[i], r->vertices[(i + 1) % r->count]);
	}
	return area;
}

/* Inside a solid of non-zero area; a flat box or polygon is just its loop of edges. */
static bool RefPointInSolid(const RefShape* r, DVec p)
{
	if (!r->solid || RefArea(r) <= 0.0)
	{
		return false;
	}
	for (int i = 0; i < r->count; ++i)
	{
		DVec a = r->vertices[i], b = r->vertices[(i + 1) % r->count];
		if (DCross(DSub(b, a), DSub(p, a)) < -1e-12 * DLength(DSub(b, a)) * DLength(DSub(p, a)))
		{
			return false;
		}
	}
	return true;
}

static int EdgeCount(const RefShape* r)
{
	return r->solid ? r->count : r->count - 1;
}

static double RefPointCoreDistance(const RefShape* r, DVec p)
{
	if (RefPointInSolid(r, p))
	{
		return 0.0;
	}
	double best = DLength(DSub(p, r->vertices[0]));
	for (int i = 0; i < EdgeCount(r); ++i)
	{
		double d = PointSegmentDistance(p, r->vertices[i], r->vertices[(i + 1) % r->count]);
		best = d < best ? d : best;
	}
	return best;
}

static double RefPointShapeDistance(const RefShape* r, DVec p)
{
	double d = RefPointCoreDistance(r, p) - r->radius;
	return d > 0.0 ? d : 0.0;
}

static double RefCoreDistance(const RefShape* a, const RefShape* b)
{
	double best = INFINITY;
	for (int i = 0; i < a->count; ++i)
	{
		double d = RefPointCoreDistance(b, a->vertices[i]);
		best = d < best ? d : best;
	}
	for (int i = 0; i < b->count; ++i)
	{
		double d = RefPointCoreDistance(a, b->vertices[i]);
		best = d < best ? d : best;
	}
	for (int i = 0; i < EdgeCount(a); ++i)
	{
		for (int j = 0; j < EdgeCount(b); ++j)
		{
			double d = SegmentSegmentDistance(a->vertices[i], a->vertices[(i + 1) % a->count], b->vertices[j],
											  b->vertices[(j + 1) % b->count]);
			best = d < best ? d : best;
		}
	}
	return best;
}

static double RefDistance(const cd2Shape* sa, const cd2Shape* sb)
{
	RefShape a = MakeRef(sa), b = MakeRef(sb);
	double d = RefCoreDistance(&a, &b) - a.radius - b.radius;
	return d > 0.0 ? d : 0.0;
}

/* Absolute tolerance for shapes of size ~1-5 near the origin: float round-off in the shapes
 * themselves (rotations, transforms) and in GJK's termination. */
#if CD_DOUBLE
#define TOLERANCE 1e-9
#else
#define TOLERANCE 2e-5
#endif

static bool g_printedCase = false;

static void ReportCase(bool ok, const cd2Shape* a, const cd2Shape* b)
{
	if (!ok && !g_printedCase && g_testFailures <= TEST_MAX_PRINTED_FAILURES)
	{
		PrintShape("a", a);
		PrintShape("b", b);
		g_printedCase = true;
	}
}

static bool CheckResult(const cd2Shape* a, const cd2Shape* b, cd2ClosestPoints r)
{
	RefShape ra = MakeRef(a), rb = MakeRef(b);
	DVec pa = DFrom(r.pointA), pb = DFrom(r.pointB);
	double distance = (double)r.distance;
	bool finite = isfinite(distance) && isfinite(pa.x) && isfinite(pa.y) && isfinite(pb.x) && isfinite(pb.y);
	TEST_CHECKF(finite, "non-finite result %g", distance);
	if (!finite)
	{
		return false;
	}
	double onA = RefPointShapeDistance(&ra, pa), onB = RefPointShapeDistance(&rb, pb);
	double gap = DLength(DSub(pb, pa));
	bool ok = distance >= 0.0 && onA <= TOLERANCE && onB <= TOLERANCE && fabs(gap - distance) <= TOLERANCE;
	TEST_CHECKF(ok,
				"witness off: distance %.9g, pointA off A by %.3g, pointB off B by %.3g, |pB - pA| = %.9g",
				distance, onA, onB, gap);
	bool same = distance > 0.0 || cd2VecEqual(r.pointA, r.pointB);
	TEST_CHECKF(same, "overlap reported with different points, |pB - pA| = %.3g", gap);

	/* Apart, pointB is the point of b closest to pointA (unique on a convex set): a cross-check
	 * with the library's own closest-point routines. The tolerance is wider than for the
	 * distance: near a tie between features (a point almost over an edge's end) the distance is
	 * flat while the witness slides, so GJK's stopping point moves it more than the distance. */
	bool closest = true;
	if (distance > 10.0 * TOLERANCE)
	{
		double moved = DLength(DSub(DFrom(cd2ClosestPointOnShape(b, r.pointA)), pb));
		closest = moved <= 100.0 * TOLERANCE;
		TEST_CHECKF(closest, "pointB is %.3g from the point of b closest to pointA", moved);
	}
	return ok && same && closest;
}

static bool CheckFinitePoints(cd2ClosestPoints r)
{
	return cd2IsValidVec(r.pointA) && cd2IsValidVec(r.pointB);
}

static double g_maxError = 0.0;

static void CheckPair(TestRng* rng, const cd2Shape* a, const cd2Shape* b)
{
	g_printedCase = false;
	double expected = RefDistance(a, b);
	cd2ClosestPoints r = cd2Distance(a, b);
	bool ok = CheckResult(a, b, r);
	double error = fabs((double)r.distance - expected);
	g_maxError = error > g_maxError ? error : g_maxError;
	bool near = error <= TOLERANCE;
	TEST_CHECKF(near, "distance %.9g, reference %.9g", (double)r.distance, expected);
	ReportCase(ok && near, a, b);

	/* Symmetry: the same distance, and the witnesses swapped (unique when one shape is a disk,
	 * otherwise both pairs need only be valid). */
	cd2ClosestPoints s = cd2Distance(b, a);
	bool okSwapped = CheckResult(b, a, s);
	bool symmetric = fabs((double)(s.distance - r.distance)) <= TOLERANCE;
	TEST_CHECKF(symmetric, "d(a,b) = %.9g, d(b,a) = %.9g", (double)r.distance, (double)s.distance);
	if (a->type == CD2_SHAPE_CIRCLE || b->type == CD2_SHAPE_CIRCLE)
	{
		double moved =
			DLength(DSub(DFrom(r.pointA), DFrom(s.pointB))) + DLength(DSub(DFrom(r.pointB), DFrom(s.pointA)));
		bool swapped = r.distance == CD_R(0.0) || moved <= 100.0 * TOLERANCE;
		TEST_CHECKF(swapped, "witnesses not swapped: moved by %.3g", moved);
		symmetric = symmetric && swapped;
	}
	ReportCase(okSwapped && symmetric, a, b);

	/* Invariance under a common rigid transform (translation only with an AABB). */
	cd2Transform t;
	t.p = RandomVec(rng, 3.0);
	t.q = (a->type == CD2_SHAPE_AABB || b->type == CD2_SHAPE_AABB) ? CD2_ROT_IDENTITY : RandomRot(rng);
	cd2Shape ta = TransformShape(a, t), tb = TransformShape(b, t);
	cd2ClosestPoints u = cd2Distance(&ta, &tb);
	bool invariant = fabs((double)(u.distance - r.distance)) <= 2.0 * TOLERANCE;
	TEST_CHECKF(invariant, "transformed distance %.9g, original %.9g", (double)u.distance,
				(double)r.distance);
	ReportCase(invariant, a, b);
}

static void TestRandomPairs(void)
{
	TestRng rng = TestRngMake(0x6a6b3d02u);
	const int pairsPerCombination = 1000;
	for (int ta = 0; ta < CD2_SHAPE_TYPE_COUNT; ++ta)
	{
		for (int tb = ta; tb < CD2_SHAPE_TYPE_COUNT; ++tb)
		{
			for (int i = 0; i < pairsPerCombination; ++i)
			{
				cd2Shape a = RandomShape(&rng, (cd2ShapeType)ta);
				cd2Shape b = RandomShape(&rng, (cd2ShapeType)tb);
				CheckPair(&rng, &a, &b);
			}
		}
	}
	printf("largest distance error against the reference: %.3g\n", g_maxError);
}

/* ---- exact cases ------------------------------------------------------------------------------- */
static cd2Shape Circle(cdReal x, cdReal y, cdReal radius)
{
	cd2Shape s;
	memset(&s, 0, sizeof(s));
	s.type = CD2_SHAPE_CIRCLE;
	s.circle.center = cd2MakeVec(x, y);
	s.circle.radius = radius;
	return s;
}

static cd2Shape Aabb(cd2Vec lo, cd2Vec hi)
{
	cd2Shape s;
	memset(&s, 0, sizeof(s));
	s.type = CD2_SHAPE_AABB;
	s.aabb.min = lo;
	s.aabb.max = hi;
	return s;
}

static cd2Shape Capsule(cd2Vec p1, cd2Vec p2, cdReal radius)
{
	cd2Shape s;
	memset(&s, 0, sizeof(s));
	s.type = CD2_SHAPE_CAPSULE;
	s.capsule.p1 = p1;
	s.capsule.p2 = p2;
	s.capsule.radius = radius;
	return s;
}

static cd2Shape Segment(cd2Vec p1, cd2Vec p2)
{
	cd2Shape s;
	memset(&s, 0, sizeof(s));
	s.type = CD2_SHAPE_SEGMENT;
	s.segment.p1 = p1;
	s.segment.p2 = p2;
	return s;
}

static cd2Shape Box(cd2Vec center, cd2Vec half, cd2Rot rotation)
{
	cd2Shape s;
	memset(&s, 0, sizeof(s));
	s.type = CD2_SHAPE_BOX;
	s.box.center = center;
	s.box.halfExtents = half;
	s.box.rotation = rotation;
	return s;
}

/* The unit square [0,1]^2 as a hand-built polygon. */
static cd2Shape UnitSquarePolygon(void)
{
	cd2Shape s;
	memset(&s, 0, sizeof(s));
	s.type = CD2_SHAPE_POLYGON;
	s.polygon.vertices[0] = cd2MakeVec(CD_R(0.0), CD_R(0.0));
	s.polygon.vertices[1] = cd2MakeVec(CD_R(1.0), CD_R(0.0));
	s.polygon.vertices[2] = cd2MakeVec(CD_R(1.0), CD_R(1.0));
	s.polygon.vertices[3] = cd2MakeVec(CD_R(0.0), CD_R(1.0));
	s.polygon.normals[0] = cd2MakeVec(CD_R(0.0), CD_R(-1.0));
	s.polygon.normals[1] = cd2MakeVec(CD_R(1.0), CD_R(0.0));
	s.polygon.normals[2] = cd2MakeVec(CD_R(0.0), CD_R(1.0));
	s.polygon.normals[3] = cd2MakeVec(CD_R(-1.0), CD_R(0.0));
	s.polygon.centroid = cd2MakeVec(CD_R(0.5), CD_R(0.5));
	s.polygon.count = 4;
	return s;
}

#define V(x, y) cd2MakeVec(CD_R(x), CD_R(y))
#define NEAR_VEC(a, b)                                                                                       \
	do                                                                                                       \
	{                                                                                                        \
		TEST_CHECK_NEAR((a).x, (b).x, TOLERANCE);                                                            \
		TEST_CHECK_NEAR((a).y, (b).y, TOLERANCE);                                                            \
	} while (0)

static void TestCircles(void)
{
	cd2Shape a = Circle(CD_R(0.0), CD_R(0.0), CD_R(1.0));
	cd2Shape b = Circle(CD_R(0.0), CD_R(5.0), CD_R(2.0));
	cd2ClosestPoints r = cd2Distance(&a, &b);
	TEST_CHECK_NEAR(r.distance, 2.0, TOLERANCE);
	NEAR_VEC(r.pointA, V(0.0, 1.0));
	NEAR_VEC(r.pointB, V(0.0, 3.0));
	b.circle.center.y = CD_R(3.0);
	r = cd2Distance(&a, &b);
	TEST_CHECK(r.distance == CD_R(0.0) && cd2VecEqual(r.pointA, r.pointB));
	NEAR_VEC(r.pointA, V(0.0, 1.0));
	b.circle.center.y = CD_R(0.5);
	r = cd2Distance(&a, &b);
	TEST_CHECK(r.distance == CD_R(0.0) && cd2VecEqual(r.pointA, r.pointB) &&
			   cd2Length(r.pointA) <= CD_R(1.0));
	cd2Shape p = Circle(CD_R(3.0), CD_R(-1.0), CD_R(0.0));
	r = cd2Distance(&p, &p);
	TEST_CHECK(r.distance == CD_R(0.0) && cd2VecEqual(r.pointA, p.circle.center));
}

static void TestPolygonsAndBoxes(void)
{
	cd2Shape square = UnitSquarePolygon();
	cd2Shape aabb = Aabb(V(3.0, 3.0), V(4.0, 5.0));
	cd2ClosestPoints r = cd2Distance(&square, &aabb);
	TEST_CHECK_NEAR(r.distance, sqrt(8.0), TOLERANCE);
	NEAR_VEC(r.pointA, V(1.0, 1.0));
	NEAR_VEC(r.pointB, V(3.0, 3.0));

	/* Edge contact, nesting, a zero-size box on a corner. */
	aabb = Aabb(V(1.0, 0.25), V(2.0, 0.75));
	TEST_CHECK(cd2Distance(&square, &aabb).distance == CD_R(0.0));
	aabb = Aabb(V(0.25, 0.25), V(0.75, 0.75));
	r = cd2Distance(&aabb, &square);
	TEST_CHECK(r.distance == CD_R(0.0) && cd2VecEqual(r.pointA, r.pointB));
	cd2Shape point = Box(V(1.0, 1.0), V(0.0, 0.0), CD2_ROT_IDENTITY);
	TEST_CHECK(cd2Distance(&point, &square).distance == CD_R(0.0));

	/* A box turned 45 degrees: its corner reaches x = 4 - sqrt(2). */
	cd2Shape box = Box(V(4.0, 0.5), V(1.0, 1.0), cd2MakeRot(CD_R(0.25) * CD_PI));
	r = cd2Distance(&square, &box);
	TEST_CHECK_NEAR(r.distance, 3.0 - sqrt(2.0), 4.0 * TOLERANCE);
	NEAR_VEC(r.pointA, V(1.0, 0.5));
	TEST_CHECK_NEAR(r.pointB.x, 4.0 - sqrt(2.0), 4.0 * TOLERANCE);
}

static void TestCapsulesAndSegments(void)
{
	cd2Shape a = Capsule(V(0.0, 0.0), V(4.0, 0.0), CD_R(0.5));
	cd2Shape b = Capsule(V(1.0, 3.0), V(2.0, 3.0), CD_R(0.25));
	TEST_CHECK_NEAR(cd2Distance(&a, &b).distance, 2.25, TOLERANCE);
	b = Capsule(V(6.0, 0.0), V(6.0, 0.0), CD_R(1.0)); /* zero length */
	cd2ClosestPoints r = cd2Distance(&a, &b);
	TEST_CHECK_NEAR(r.distance, 0.5, TOLERANCE);
	NEAR_VEC(r.pointA, V(4.5, 0.0));
	NEAR_VEC(r.pointB, V(5.0, 0.0));

	cd2Shape s1 = Segment(V(-1.0, 0.0), V(1.0, 0.0));
	cd2Shape s2 = Segment(V(0.0, -1.0), V(0.0, 1.0));
	r = cd2Distance(&s1, &s2);
	TEST_CHECK(r.distance == CD_R(0.0) && cd2VecEqual(r.pointA, r.pointB));
	NEAR_VEC(r.pointA, V(0.0, 0.0));
	s2 = Segment(V(2.0, 0.0), V(5.0, 0.0)); /* collinear, apart */
	TEST_CHECK_NEAR(cd2Distance(&s1, &s2).distance, 1.0, TOLERANCE);
	s2 = Segment(V(0.5, 0.0), V(5.0, 0.0)); /* collinear, overlapping */
	TEST_CHECK(cd2Distance(&s1, &s2).distance == CD_R(0.0));
	cd2Shape dot = Segment(V(0.5, 2.0), V(0.5, 2.0));
	r = cd2Distance(&dot, &s1);
	TEST_CHECK_NEAR(r.distance, 2.0, TOLERANCE);
	NEAR_VEC(r.pointB, V(0.5, 0.0));
}

static void TestScales(void)
{
	const cdReal scales[] = {CD_R(1e-9), CD_R(1e-4), CD_R(1.0), CD_R(1e4), CD_R(1e9)};
	for (int i = 0; i < 5; ++i)
	{
		cdReal k = scales[i];
		cd2Shape box = Box(cd2Scale(k, V(1.0, 2.0)), cd2Scale(k, V(1.0, 0.5)), cd2MakeRot(CD_R(0.7)));
		cd2Shape cap = Capsule(cd2Scale(k, V(5.0, 2.0)), cd2Scale(k, V(5.0, 4.0)), CD_R(0.5) * k);
		cd2ClosestPoints r = cd2Distance(&box, &cap);
		double expected = RefDistance(&box, &cap);
		TEST_CHECKF(isfinite((double)r.distance) && fabs((double)r.distance - expected) <= 1e-4 * expected,
					"scale %g: distance %.9g, reference %.9g", (double)k, (double)r.distance, expected);
	}
}

/* Every pair scaled as a whole to the ends of the documented range (1e-9..1e9 in float,
 * 1e-30..1e30 in double): finite answers that scale with the shapes; and pairs whose two shapes
 * differ in size by up to 18 (float) or 60 (double) orders of magnitude: finite answers. */
static void TestExtremeScales(void)
{
	TestRng rng = TestRngMake(0x6a6b3d06u);
#if CD_DOUBLE
	const double exponents = 30.0;
#else
	const double exponents = 9.0;
#endif
	for (int i = 0; i < 4000; ++i)
	{
		cd2Shape a = RandomShape(&rng, (cd2ShapeType)TestRngInt(&rng, CD2_SHAPE_TYPE_COUNT));
		cd2Shape b = RandomShape(&rng, (cd2ShapeType)TestRngInt(&rng, CD2_SHAPE_TYPE_COUNT));
		double k = pow(10.0, TestRngRange(&rng, -exponents, exponents));
		cd2Shape sa = ScaleShape(&a, (cdReal)k), sb = ScaleShape(&b, (cdReal)k);
		double expected = RefDistance(&sa, &sb) / k;
		double unit = RefDistance(&a, &b);
		cd2ClosestPoints r = cd2Distance(&sa, &sb);
		bool ok = isfinite((double)r.distance) && CheckFinitePoints(r) &&
				  fabs((double)r.distance / k - expected) <= 1e-3 * (1.0 + expected) &&
				  fabs(expected - unit) <= 1e-3 * (1.0 + unit);
		TEST_CHECKF(ok, "scale %g: distance / scale = %.9g, reference %.9g (unscaled %.9g)", k,
					(double)r.distance / k, expected, unit);
		if (!ok)
		{
			PrintShape("a", &sa);
			PrintShape("b", &sb);
		}

		double k2 = pow(10.0, TestRngRange(&rng, -exponents, exponents));
		cd2Shape mixed = ScaleShape(&b, (cdReal)k2);
		r = cd2Distance(&sa, &mixed);
		cd2ClosestPoints s = cd2Distance(&mixed, &sa);
		ok = isfinite((double)r.distance) && r.distance >= CD_R(0.0) && CheckFinitePoints(r) &&
			 isfinite((double)s.distance) && CheckFinitePoints(s);
		TEST_CHECKF(ok, "scales %g and %g: distance %g", k, k2, (double)r.distance);
		if (!ok)
		{
			PrintShape("a", &sa);
			PrintShape("b", &mixed);
		}

		/* Small shapes far out: finite, and no farther apart than their centres' round-off allows. */
		cd2Transform far = {
			cd2Scale((cdReal)pow(10.0, TestRngRange(&rng, 0.0, exponents)), RandomVec(&rng, 1.0)),
			CD2_ROT_IDENTITY};
		cd2Shape fa = TransformShape(&sa, far), fb = TransformShape(&mixed, far);
		r = cd2Distance(&fa, &fb);
		ok = isfinite((double)r.distance) && r.distance >= CD_R(0.0) && CheckFinitePoints(r);
		TEST_CHECKF(ok, "scales %g and %g, offset %g: distance %g", k, k2, (double)far.p.x,
					(double)r.distance);
	}
}

/* ---- ill-conditioned pairs against the reference, tolerance relative to the pair's scale ------- */

/* The largest coordinate or size of a shape (its extent from the origin). */
static double ShapeScale(const cd2Shape* shape)
{
	RefShape r = MakeRef(shape);
	double scale = r.radius;
	for (int i = 0; i < r.count; ++i)
	{
		scale = fmax(scale, fmax(fabs(r.vertices[i].x), fabs(r.vertices[i].y)));
	}
	return scale;
}

/* GJK's distance and witnesses carry round-off of a few epsilons of the largest coordinate
 * (support values, the stopping gap, the weights): 128 epsilons of the scale leaves room for that
 * and still catches the failures these cases pin down (errors of 1e-4 to 1e-1 of the scale). */
#define SCALED_TOLERANCE(scale) (128.0 * (double)CD_REAL_EPSILON * (scale))

static double g_maxScaledError = 0.0;

/* cd2Distance(a, b) and (b, a) against the reference: distance, witnesses on their shapes, the
 * gap between them, one common point at distance 0. Returns the first result. */
static cd2ClosestPoints CheckScaledPair(const cd2Shape* a, const cd2Shape* b, const char* what)
{
	double scale = fmax(ShapeScale(a), ShapeScale(b));
	double tolerance = SCALED_TOLERANCE(scale);
	double expected = RefDistance(a, b);
	RefShape ra = MakeRef(a), rb = MakeRef(b);
	cd2ClosestPoints first = {CD2_VEC_ZERO, CD2_VEC_ZERO, CD_R(0.0)};
	for (int order = 0; order < 2; ++order)
	{
		const cd2Shape* x = order == 0 ? a : b;
		const cd2Shape* y = order == 0 ? b : a;
		cd2ClosestPoints r = cd2Distance(x, y);
		first = order == 0 ? r : first;
		const RefShape* rx = order == 0 ? &ra : &rb;
		const RefShape* ry = order == 0 ? &rb : &ra;
		double offX = RefPointShapeDistance(rx, DFrom(r.pointA));
		double offY = RefPointShapeDistance(ry, DFrom(r.pointB));
		double gap = DLength(DSub(DFrom(r.pointB), DFrom(r.pointA)));
		double error = fabs((double)r.distance - expected);
		double worst = fmax(fmax(error, fabs(gap - (double)r.distance)), fmax(offX, offY));
		g_maxScaledError = fmax(g_maxScaledError, worst / scale);
		bool ok = isfinite((double)r.distance) && CheckFinitePoints(r) && worst <= tolerance &&
				  (r.distance > CD_R(0.0) || cd2VecEqual(r.pointA, r.pointB));
		TEST_CHECKF(
			ok,
			"%s, order %d: distance %.9g, reference %.9g, witnesses off their shapes by %.3g and %.3g, "
			"|pB - pA| = %.9g (tolerance %.3g)",
			what, order, (double)r.distance, expected, offX, offY, gap, tolerance);
		if (!ok)
		{
			PrintShape("a", a);
			PrintShape("b", b);
		}
	}
	return first;
}

/* The fuzzers' findings, with the values they printed (float values, exact in double too). */
static void TestGjkFuzzFindings(void)
{
	/* Segments sharing the end point (0, -125000), one of them 1e9 long: touching. GJK stalled
	 * between two nearly equidistant edges of the sliver Minkowski difference at 116250. */
	cd2Vec shared = V(0.0, -125000.0);
	cd2Shape a = Segment(V(-1e9, 0.0), shared);
	cd2Shape b = Segment(V(0.0, -8750.0), shared);
	cd2ClosestPoints r = CheckScaledPair(&a, &b, "segments sharing an end point");
	TEST_CHECKF(r.distance == CD_R(0.0) && cd2Length(cd2Sub(r.pointA, shared)) <= SCALED_TOLERANCE(1e9),
				"distance %.9g, common point (%.9g %.9g)", (double)r.distance, (double)r.pointA.x,
				(double)r.pointA.y);

	/* A point inside a box of half extents 1 and 2.6e-5: distance 0, and the common point is the
	 * point itself (the only point of the circle of radius 0); the sliver triangle's weights put it
	 * 2.2e-4 away. */
	cd2Vec point = cd2MakeVec(CD_R(-0.000125), CD_R(-0.000125));
	cd2Shape thin = Box(cd2MakeVec(CD_R(-8.375e-5), CD_R(-7.125e-5)), cd2MakeVec(CD_R(1.0), CD_R(2.625e-5)),
						cd2NormalizeRot((cd2Rot){CD_R(-0.00012375), CD_R(-0.000125)}));
	cd2Shape dot = Circle(point.x, point.y, CD_R(0.0));
	TEST_CHECK(cd2PointInBox(point, thin.box));
	r = CheckScaledPair(&thin, &dot, "point in a thin box");
	TEST_CHECKF(r.distance == CD_R(0.0) && cd2Length(cd2Sub(r.pointB, point)) <= SCALED_TOLERANCE(1.0),
				"distance %.9g, common point %.3g from the point", (double)r.distance,
				(double)cd2Length(cd2Sub(r.pointB, point)));

	/* A box 2.1e-4 thin and 1.9e7 long at 45 degrees through a flat AABB (a vertical segment of
	 * length 7.5e-6 inside the box's slab): overlapping; the double build put the common point
	 * 17.9 away from the AABB. */
	cdReal diagonal = -CD_R(0.70710678118654752);
	cd2Shape slab = Box(cd2MakeVec(CD_R(1e-30), CD_R(5e-6)), cd2MakeVec(CD_R(1.0625e-4), CD_R(9568256.0)),
						(cd2Rot){diagonal, diagonal});
	cd2Shape flat = Aabb(cd2MakeVec(CD_R(-1e-5), CD_R(-1.225e-4)), cd2MakeVec(CD_R(-1e-5), CD_R(-1.15e-4)));
	r = CheckScaledPair(&slab, &flat, "flat AABB in a long thin box");
	TEST_CHECK(r.distance == CD_R(0.0));

	/* The point (-12.5, -12.5) on the axis of a box 4.8e15 long and 25 wide at 45 degrees (found
	 * by the double fuzzer; in float the box is only 4.8e15 long where the documented range ends,
	 * an ordinary case): the common point is the point itself. */
	cd2Shape needle = Box(CD2_VEC_ZERO, cd2MakeVec((cdReal)0x1.100ap+51, CD_R(12.5)),
						  (cd2Rot){(cdReal)-0x1.6a09e667f3bccp-1, (cdReal)-0x1.6a09e667f3bccp-1});
	cd2Shape onAxis = Circle(CD_R(-12.5), CD_R(-12.5), CD_R(0.0));
	r = CheckScaledPair(&needle, &onAxis, "point on the axis of a needle box");
	TEST_CHECKF(r.distance == CD_R(0.0) &&
					cd2Length(cd2Sub(r.pointB, onAxis.circle.center)) <= SCALED_TOLERANCE(0x1.100ap+51),
				"distance %.9g, common point %.3g from the point", (double)r.distance,
				(double)cd2Length(cd2Sub(r.pointB, onAxis.circle.center)));
}

/* Thin boxes (aspect ratios up to 1e6 in float, 1e12 in double) against random shapes and points
 * inside them; long segments that share an end point or nearly do (lengths up to 1e9 / 1e30);
 * random pairs scaled up to 1e9 / 1e30. */
static void TestIllConditionedPairs(void)
{
	TestRng rng = TestRngMake(0x6a6b3d07u);
#if CD_DOUBLE
	const double thinnest = 12.0, largest = 30.0;
#else
	const double thinnest = 6.0, largest = 9.0;
#endif
	for (int i = 0; i < 3000; ++i)
	{
		/* A thin box and a random shape or a point inside the box. */
		cdReal length = RandomReal(&rng, 0.5, 3.0);
		cdReal width = (cdReal)pow(10.0, -TestRngRange(&rng, 1.0, thinnest));
		cd2Vec half = TestRngInt(&rng, 2) == 0 ? cd2MakeVec(length, width) : cd2MakeVec(width, length);
		cd2Shape box = Box(RandomVec(&rng, 1.0), half, RandomRot(&rng));
		cd2Shape other;
		if (TestRngInt(&rng, 2) == 0)
		{
			other = RandomShape(&rng, (cd2ShapeType)TestRngInt(&rng, CD2_SHAPE_TYPE_COUNT));
		}
		else
		{
			cd2Vec local =
				cd2MakeVec(RandomReal(&rng, -1.0, 1.0) * half.x, RandomReal(&rng, -1.0, 1.0) * half.y);
			cd2Vec inside = cd2Add(box.box.center, cd2RotateVector(box.box.rotation, local));
			other = Circle(inside.x, inside.y, CD_R(0.0));
		}
		cd2ClosestPoints r = CheckScaledPair(&box, &other, "thin box");
		if (other.type == CD2_SHAPE_CIRCLE && other.circle.radius == CD_R(0.0) &&
			RefDistance(&box, &other) == 0.0)
		{
			double off = (double)cd2Length(cd2Sub(r.pointB, other.circle.center));
			TEST_CHECKF(off <= SCALED_TOLERANCE(ShapeScale(&box)),
						"common point %.3g from the point inside the thin box", off);
		}

		/* Two long segments from one end point, or with their end points a small gap apart. */
		double k = pow(10.0, TestRngRange(&rng, 0.0, largest));
		cd2Vec end = cd2Scale((cdReal)(1e-3 * k), RandomVec(&rng, 1.0));
		cd2Vec endB = end;
		if (TestRngInt(&rng, 2) == 0)
		{
			endB = cd2Add(
				end, cd2Scale((cdReal)(k * pow(10.0, -TestRngRange(&rng, 1.0, 5.0))), RandomVec(&rng, 1.0)));
		}
		cd2Vec farA = cd2Add(end, cd2Scale((cdReal)(k * TestRngRange(&rng, 0.1, 1.0)),
										   cd2RotateVector(RandomRot(&rng), V(1.0, 0.0))));
		cd2Vec farB = cd2Add(endB, cd2Scale((cdReal)(k * pow(10.0, -TestRngRange(&rng, 0.0, 5.0))),
											cd2RotateVector(RandomRot(&rng), V(1.0, 0.0))));
		cd2Shape sa = Segment(TestRngInt(&rng, 2) == 0 ? farA : end, TestRngInt(&rng, 2) == 0 ? end : farA);
		if (cd2VecEqual(sa.segment.p1, sa.segment.p2))
		{
			sa.segment.p1 = farA;
		}
		cd2Shape sb = Segment(farB, endB);
		CheckScaledPair(&sa, &sb, "long segments");

		/* A random pair scaled as a whole. */
		cd2Shape pa = RandomShape(&rng, (cd2ShapeType)TestRngInt(&rng, CD2_SHAPE_TYPE_COUNT));
		cd2Shape pb = RandomShape(&rng, (cd2ShapeType)TestRngInt(&rng, CD2_SHAPE_TYPE_COUNT));
		cd2Shape ka = ScaleShape(&pa, (cdReal)k), kb = ScaleShape(&pb, (cdReal)k);
		CheckScaledPair(&ka, &kb, "scaled pair");
	}
	printf("largest error relative to the scale in ill-conditioned pairs: %.3g epsilon\n",
		   g_maxScaledError / (double)CD_REAL_EPSILON);
}

/* cd2DistanceWithStatus reports GJK's work and gives the same answer as cd2Distance. */
static void TestDistanceStatus(void)
{
	cd2Box box = {{0, 0}, {1, 2}, cd2MakeRot(CD_R(0.4))};
	cd2Circle circle = {{5, 1}, 0.5f};
	cd2Shape a = cd2MakeBoxShape(box), b = cd2MakeCircleShape(circle);
	cdDistanceStatus status = {-1, true};
	cd2ClosestPoints withStatus = cd2DistanceWithStatus(&a, &b, &status);
	cd2ClosestPoints plain = cd2Distance(&a, &b);
	TEST_CHECK(withStatus.distance == plain.distance && withStatus.distance > CD_R(1.0));
	TEST_CHECKF(status.iterations >= 1 && status.iterations <= 64 && !status.hitIterationCap,
				"iterations %d, cap %d", status.iterations, (int)status.hitIterationCap);
	TEST_CHECK(cd2DistanceWithStatus(&a, &b, NULL).distance == plain.distance);
}

/* ---- simplex cache --------------------------------------------------------------------------- */
#if CD_DOUBLE
#define CACHE_AGREEMENT 1e-9
#else
#define CACHE_AGREEMENT 2e-4
#endif

static void FillRandomBytes(TestRng* rng, void* memory, size_t size)
{
	unsigned char* bytes = (unsigned char*)memory;
	for (size_t i = 0; i < size; ++i)
	{
		bytes[i] = (unsigned char)(TestRngNext(rng) >> 24);
	}
}

/* The same answer whatever the cache holds: nothing, random bytes, random but in-range indices,
 * another pair's simplex, this pair's own simplex. */
static void TestCacheAgrees(void)
{
	TestRng rng = TestRngMake(0x5ca4e001u);
	cd2SimplexCache other;
	memset(&other, 0, sizeof(other));
	int pairs = 0;
	for (int ta = 0; ta < CD2_SHAPE_TYPE_COUNT; ++ta)
	{
		for (int tb = 0; tb < CD2_SHAPE_TYPE_COUNT; ++tb)
		{
			for (int i = 0; i < 80; ++i, ++pairs)
			{
				cd2Shape a = RandomShape(&rng, (cd2ShapeType)ta);
				cd2Shape b = RandomShape(&rng, (cd2ShapeType)tb);
				cd2ClosestPoints plain = cd2Distance(&a, &b);
				cd2SimplexCache caches[5];
				memset(&caches[0], 0, sizeof(caches[0]));
				FillRandomBytes(&rng, &caches[1], sizeof(caches[1]));
				caches[2].count = 1 + TestRngInt(&rng, 3);
				caches[2].metric = RandomReal(&rng, -1.0, 4.0);
				for (int k = 0; k < 3; ++k)
				{
					caches[2].indexA[k] = TestRngInt(&rng, 9) - 1;
					caches[2].indexB[k] = TestRngInt(&rng, 9) - 1;
				}
				caches[3] = other;
				memset(&caches[4], 0, sizeof(caches[4]));
				cd2DistanceCached(&a, &b, &caches[4], NULL);
				for (int c = 0; c < 5; ++c)
				{
					cdDistanceStatus status;
					cd2ClosestPoints cached = cd2DistanceCached(&a, &b, &caches[c], &status);
					double error = fabs((double)cached.distance - (double)plain.distance);
					double gap = (double)cd2Length(cd2Sub(cached.pointB, cached.pointA));
					TEST_CHECKF(error <= CACHE_AGREEMENT &&
									fabs(gap - (double)cached.distance) <= CACHE_AGREEMENT &&
									!status.hitIterationCap && caches[c].count >= 1 && caches[c].count <= 3,
								"%s-%s cache %d: cached %.9g, plain %.9g, points %.9g apart, count %d",
								TypeName((cd2ShapeType)ta), TypeName((cd2ShapeType)tb), c,
								(double)cached.distance, (double)plain.distance, gap, caches[c].count);
				}
				other = caches[4];
			}
		}
	}
	printf("%d pairs, 5 caches each\n", pairs);
}

/* A pair moving a little each frame: the cache of the last frame saves iterations. */
static void TestCacheSavesIterations(void)
{
	TestRng rng = TestRngMake(0x5ca4e002u);
	long long coldIterations = 0, warmIterations = 0;
	int queries = 0;
	const cd2ShapeType types[3] = {CD2_SHAPE_POLYGON, CD2_SHAPE_BOX, CD2_SHAPE_CAPSULE};
	for (int sequence = 0; sequence < 150; ++sequence)
	{
		cd2Shape a = RandomShape(&rng, types[TestRngInt(&rng, 3)]);
		cd2Shape b0 = RandomShape(&rng, types[TestRngInt(&rng, 3)]);
		cd2Vec velocity = RandomVec(&rng, 0.02);
		cdReal spin = RandomReal(&rng, -0.02, 0.02);
		cd2SimplexCache cache;
		memset(&cache, 0, sizeof(cache));
		for (int frame = 0; frame < 20; ++frame, ++queries)
		{
			cd2Transform motion = {cd2Scale((cdReal)frame, velocity), cd2MakeRot(spin * (cdReal)frame)};
			cd2Shape b = TransformShape(&b0, motion);
			cdDistanceStatus cold, warm;
			cd2ClosestPoints plain = cd2DistanceWithStatus(&a, &b, &cold);
			cd2ClosestPoints cached = cd2DistanceCached(&a, &b, &cache, &warm);
			coldIterations += cold.iterations;
			warmIterations += warm.iterations;
			TEST_CHECKF(fabs((double)cached.distance - (double)plain.distance) <= CACHE_AGREEMENT,
						"sequence %d frame %d: cached %.9g, plain %.9g", sequence, frame,
						(double)cached.distance, (double)plain.distance);
		}
	}
	double cold = (double)coldIterations / queries, warm = (double)warmIterations / queries;
	printf("mean iterations: %.2f without the cache, %.2f with it\n", cold, warm);
	TEST_CHECKF(warm < 0.75 * cold, "mean iterations %.2f with the cache, %.2f without", warm, cold);
}

/* cd2Distance on two circles takes the closed form named by the pair table (src/query/pairs2.h)
 * instead of GJK; it must give GJK's answer bit for bit (cd2DistanceWithStatus runs GJK), in both
 * orders: random pairs, coincident and nearly coincident centres, zero radii, signed zeros and
 * large and small scales. */
static void TestClosedFormMatchesGjk(void)
{
	TestRng rng = TestRngMake(0xc105edu);
	int checked = 0;
	for (int i = 0; i < 6000; ++i)
	{
		cd2Shape a = RandomShape(&rng, CD2_SHAPE_CIRCLE), b = RandomShape(&rng, CD2_SHAPE_CIRCLE);
		switch (i % 6)
		{
			case 1:
				b.circle.center = a.circle.center;
				break;
			case 2:
				b.circle.center = cd2Add(a.circle.center, cd2MakeVec(RandomReal(&rng, -1e-6, 1e-6),
																	 RandomReal(&rng, -1e-6, 1e-6)));
				break;
			case 3:
				a.circle.center = cd2MakeVec(-0.0f, 0.0f);
				b.circle.center = cd2MakeVec(0.0f, -0.0f);
				a.circle.radius = CD_R(0.0);
				b.circle.radius = CD_R(0.0);
				break;
			case 4:
				a.circle.center = cd2Scale(CD_R(1e6), a.circle.center);
				b.circle.center = cd2Scale(CD_R(1e6), b.circle.center);
				break;
			case 5:
				a.circle.center = cd2Scale(CD_R(1e-6), a.circle.center);
				b.circle.center = cd2Scale(CD_R(1e-6), b.circle.center);
				a.circle.radius *= CD_R(1e-6);
				b.circle.radius *= CD_R(1e-6);
				break;
			default:
				break;
		}
		for (int order = 0; order < 2; ++order)
		{
			const cd2Shape* first = order == 0 ? &a : &b;
			const cd2Shape* second = order == 0 ? &b : &a;
			cdDistanceStatus status;
			cd2ClosestPoints closed = cd2Distance(first, second);
			cd2ClosestPoints gjk = cd2DistanceWithStatus(first, second, &status);
			TEST_CHECKF(memcmp(&closed, &gjk, sizeof(closed)) == 0,
						"pair %d, order %d: distance %.9g, GJK %.9g", i, order, (double)closed.distance,
						(double)gjk.distance);
			++checked;
		}
	}
	TEST_CHECK(checked == 12000);
}

/* b in its own frame placed by xf, as a shape of the same type (an AABB turns into a box). */
static cd2Shape PlaceShape(const cd2Shape* b, cd2Transform xf)
{
	cd2Shape placed = *b;
	switch (b->type)
	{
		case CD2_SHAPE_CIRCLE:
			placed.circle.center = cd2TransformPoint(xf, b->circle.center);
			break;
		case CD2_SHAPE_CAPSULE:
			placed.capsule.p1 = cd2TransformPoint(xf, b->capsule.p1);
			placed.capsule.p2 = cd2TransformPoint(xf, b->capsule.p2);
			break;
		case CD2_SHAPE_SEGMENT:
			placed.segment.p1 = cd2TransformPoint(xf, b->segment.p1);
			placed.segment.p2 = cd2TransformPoint(xf, b->segment.p2);
			break;
		case CD2_SHAPE_AABB:
		{
			cd2Box box;
			box.center = cd2Scale(CD_R(0.5), cd2Add(b->aabb.min, b->aabb.max));
			box.halfExtents = cd2Scale(CD_R(0.5), cd2Sub(b->aabb.max, b->aabb.min));
			box.rotation = cd2MakeRot(CD_R(0.0));
			placed.type = CD2_SHAPE_BOX;
			placed.box = box;
			placed.box.center = cd2TransformPoint(xf, box.center);
			placed.box.rotation = xf.q;
			break;
		}
		case CD2_SHAPE_BOX:
			placed.box.center = cd2TransformPoint(xf, placed.box.center);
			placed.box.rotation = cd2MulRot(xf.q, placed.box.rotation);
			break;
		case CD2_SHAPE_POLYGON:
			for (int i = 0; i < b->polygon.count; ++i)
			{
				placed.polygon.vertices[i] = cd2TransformPoint(xf, b->polygon.vertices[i]);
				placed.polygon.normals[i] = cd2RotateVector(xf.q, b->polygon.normals[i]);
			}
			placed.polygon.centroid = cd2TransformPoint(xf, b->polygon.centroid);
			break;
		default:
			break;
	}
	return placed;
}

/* GJK's supports by vector lanes (support2.h) pick the point of the plain scan, the first of the
 * largest dot product, for every count from 1 to 8: on ties (points and directions on a coarse
 * grid, repeated points, a zero direction) and on NaN directions (point 0). */
static void TestSupportLanesMatchScan(void)
{
	TestRng rng = TestRngMake(0x5a9907u);
	const cdReal levels[4] = {CD_R(-1.0), CD_R(0.0), CD_R(0.5), CD_R(1.0)};
	for (int round = 0; round < 20000; ++round)
	{
		int count = 1 + round % CD2_CORE_MAX_POINTS;
		bool coarse = (round / CD2_CORE_MAX_POINTS) % 2 == 0;
		cd2Vec points[CD2_CORE_MAX_POINTS];
		for (int i = 0; i < CD2_CORE_MAX_POINTS; ++i)
		{
			cdReal x = (cdReal)TestRngRange(&rng, -3.0, 3.0), y = (cdReal)TestRngRange(&rng, -3.0, 3.0);
			points[i] = coarse ? cd2MakeVec(levels[TestRngInt(&rng, 4)], levels[TestRngInt(&rng, 4)])
							   : cd2MakeVec(x, y);
		}
		cdReal dx = (cdReal)TestRngRange(&rng, -1.0, 1.0), dy = (cdReal)TestRngRange(&rng, -1.0, 1.0);
		cd2Vec direction = coarse ? cd2MakeVec(levels[TestRngInt(&rng, 4)], levels[TestRngInt(&rng, 4)])
								  : cd2MakeVec(dx, dy);
		if (round % 97 == 0)
		{
			direction.x = (cdReal)NAN;
		}
		cd2Core core;
		core.points = points;
		core.count = count;
		core.radius = CD_R(0.0);
		int scan = cd2CoreSupport(&core, direction);
		int lanes = cd2CoreSupportLanes(&core, direction);
		TEST_CHECKF(lanes == scan, "round %d (%d points, direction %g %g): lanes %d, scan %d", round, count,
					(double)direction.x, (double)direction.y, lanes, scan);
	}
}

/* cd2DistanceLocal against cd2Distance on b placed by hand: bit for bit for a polygon (the same
 * vertices), up to round-off for the shapes whose core points are built after the move. */
static void TestDistanceLocal(void)
{
	TestRng rng = TestRngMake(0x10ca1d15u);
	int exact = 0, checked = 0;
	for (int ta = 0; ta < CD2_SHAPE_TYPE_COUNT; ++ta)
	{
		for (int tb = 0; tb < CD2_SHAPE_TYPE_COUNT; ++tb)
		{
			for (int i = 0; i < 300; ++i)
			{
				cd2Shape a = RandomShape(&rng, (cd2ShapeType)ta);
				cd2Shape b = RandomShape(&rng, (cd2ShapeType)tb);
				cd2Transform xf;
				xf.p = RandomVec(&rng, 4.0);
				xf.q = RandomRot(&rng);
				cd2Shape placed = PlaceShape(&b, xf);
				cd2ClosestPoints local = cd2DistanceLocal(&a, &b, xf);
				cd2ClosestPoints world = cd2Distance(&a, &placed);
				TEST_CHECKF(cdIsValidReal(local.distance) && local.distance >= CD_R(0.0),
							"types %d-%d pair %d: distance %g", ta, tb, i, (double)local.distance);
				if (tb == CD2_SHAPE_POLYGON)
				{
					TEST_CHECKF(memcmp(&local, &world, sizeof(local)) == 0,
								"polygon b, types %d-%d pair %d: local %.9g, placed %.9g", ta, tb, i,
								(double)local.distance, (double)world.distance);
					++exact;
				}
				else
				{
					/* Shapes of size up to ~10 placed up to 4 away: round-off of a few ulps of 20. */
					double tolerance = 2e-4 * (sizeof(cdReal) == 4 ? 1.0 : 1e-8);
					TEST_CHECK_NEAR(local.distance, world.distance, tolerance);
					double gapA = (double)cd2Length(cd2Sub(local.pointA, world.pointA));
					double gapB = (double)cd2Length(cd2Sub(local.pointB, world.pointB));
					/* Closest points are unique unless edges are parallel: then only the distance
					 * and each point's distance from the other shape must agree. */
					cd2Shape at = cd2MakeCircleShape((cd2Circle){local.pointB, CD_R(0.0)});
					cd2Shape bt = cd2MakeCircleShape((cd2Circle){local.pointA, CD_R(0.0)});
					double dA = (double)cd2Distance(&a, &at).distance;
					double dB = (double)cd2Distance(&placed, &bt).distance;
					TEST_CHECKF((gapA <= 1e-3 && gapB <= 1e-3) ||
									(fabs(dA - (double)world.distance) <= 1e-3 &&
									 fabs(dB - (double)world.distance) <= 1e-3),
								"types %d-%d pair %d: points off by %g, %g", ta, tb, i, gapA, gapB);
				}
				++checked;
			}
		}
	}
	TEST_CHECK(exact == 300 * CD2_SHAPE_TYPE_COUNT);
	TEST_CHECK(checked == 300 * CD2_SHAPE_TYPE_COUNT * CD2_SHAPE_TYPE_COUNT);
}

int main(void)
{
	TEST_RUN(TestCircles);
	TEST_RUN(TestPolygonsAndBoxes);
	TEST_RUN(TestDistanceStatus);
	TEST_RUN(TestCapsulesAndSegments);
	TEST_RUN(TestScales);
	TEST_RUN(TestRandomPairs);
	TEST_RUN(TestExtremeScales);
	TEST_RUN(TestGjkFuzzFindings);
	TEST_RUN(TestIllConditionedPairs);
	TEST_RUN(TestCacheAgrees);
	TEST_RUN(TestCacheSavesIterations);
	TEST_RUN(TestClosedFormMatchesGjk);
	TEST_RUN(TestDistanceLocal);
	TEST_RUN(TestSupportLanesMatchScan);
	return TEST_SUMMARY();
}
