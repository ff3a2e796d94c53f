/* Tests of the 2D closest-point queries: exact cases for every shape and for segment pairs, then
 * random shapes and points checked by dense sampling of the shape in double (the returned point
 * lies on the shape and is no farther than the nearest sample), at ordinary, huge and tiny scales. */
#include "collide/query2.h"
#include "reference2.h"
#include "test.h"

static cd2Vec V(double x, double y)
{
	return cd2MakeVec((cdReal)x, (cdReal)y);
}

static cd2Segment Segment(double x1, double y1, double x2, double y2)
{
	cd2Segment g = {V(x1, y1), V(x2, y2)};
	return g;
}

#define CHECK_VEC(v, ex, ey, tolerance)                                                                      \
	do                                                                                                       \
	{                                                                                                        \
		cd2Vec checked_ = (v);                                                                               \
		TEST_CHECK_NEAR(checked_.x, (ex), (tolerance));                                                      \
		TEST_CHECK_NEAR(checked_.y, (ey), (tolerance));                                                      \
	} while (0)

static void TestCircleCapsuleSegment(void)
{
	cd2Circle circle = {V(1, 1), 2};
	CHECK_VEC(cd2ClosestPointOnCircle(circle, V(1, 1)), 1, 1, 0);		 /* center */
	CHECK_VEC(cd2ClosestPointOnCircle(circle, V(2, 1.5)), 2, 1.5, 0);	 /* inside: itself */
	CHECK_VEC(cd2ClosestPointOnCircle(circle, V(1, 3)), 1, 3, 0);		 /* on the boundary */
	CHECK_VEC(cd2ClosestPointOnCircle(circle, V(4, 5)), 2.2, 2.6, 1e-6); /* 3-4-5 direction */
	cd2Circle point = {V(-1, 2), 0};
	CHECK_VEC(cd2ClosestPointOnCircle(point, V(5, 5)), -1, 2, 0);
	CHECK_VEC(cd2ClosestPointOnCircle(point, V(-1, 2)), -1, 2, 0);

	cd2Capsule capsule = {V(0, 0), V(4, 0), 1};
	CHECK_VEC(cd2ClosestPointOnCapsule(capsule, V(2, 0.5)), 2, 0.5, 0);
	CHECK_VEC(cd2ClosestPointOnCapsule(capsule, V(2, 3)), 2, 1, 1e-6);
	CHECK_VEC(cd2ClosestPointOnCapsule(capsule, V(2, -3)), 2, -1, 1e-6);
	CHECK_VEC(cd2ClosestPointOnCapsule(capsule, V(7, 4)), 4.6, 0.8, 1e-6);
	CHECK_VEC(cd2ClosestPointOnCapsule(capsule, V(-3, 0)), -1, 0, 1e-6);
	cd2Capsule ball = {V(1, 1), V(1, 1), 1};
	CHECK_VEC(cd2ClosestPointOnCapsule(ball, V(4, 5)), 1.6, 1.8, 1e-6);
	cd2Capsule stick = {V(0, 0), V(0, 2), 0};
	CHECK_VEC(cd2ClosestPointOnCapsule(stick, V(3, 1)), 0, 1, 1e-6);

	cd2Segment g = Segment(0, 0, 4, 0);
	CHECK_VEC(cd2ClosestPointOnSegment(g, V(1, 3)), 1, 0, 1e-6);
	CHECK_VEC(cd2ClosestPointOnSegment(g, V(-2, 3)), 0, 0, 0);
	CHECK_VEC(cd2ClosestPointOnSegment(g, V(9, -3)), 4, 0, 0);
	CHECK_VEC(cd2ClosestPointOnSegment(g, V(3, 0)), 3, 0, 1e-6);
	CHECK_VEC(cd2ClosestPointOnSegment(Segment(2, 2, 2, 2), V(9, -3)), 2, 2, 0);
	CHECK_VEC(cd2ClosestPointOnSegment(Segment(0, 0, 2, 2), V(2, 0)), 1, 1, 1e-6);
}

static void TestAabbBoxPolygon(void)
{
	cd2Aabb b = {V(0, 0), V(2, 1)};
	CHECK_VEC(cd2ClosestPointOnAabb(b, V(1, 0.5)), 1, 0.5, 0);
	CHECK_VEC(cd2ClosestPointOnAabb(b, V(3, 3)), 2, 1, 0);
	CHECK_VEC(cd2ClosestPointOnAabb(b, V(1, -3)), 1, 0, 0);
	CHECK_VEC(cd2ClosestPointOnAabb(b, V(-1, 0.25)), 0, 0.25, 0);
	cd2Aabb dot = {V(1, 1), V(1, 1)};
	CHECK_VEC(cd2ClosestPointOnAabb(dot, V(5, -5)), 1, 1, 0);

	cd2Box box = {V(1, 1), V(2, 1), cd2MakeRot(CD_PI / 2)}; /* extends 1 in x, 2 in y */
	CHECK_VEC(cd2ClosestPointOnBox(box, V(1.5, 2)), 1.5, 2, 0);
	CHECK_VEC(cd2ClosestPointOnBox(box, V(5, 1.5)), 2, 1.5, 1e-6);
	CHECK_VEC(cd2ClosestPointOnBox(box, V(5, 9)), 2, 3, 1e-6);
	CHECK_VEC(cd2ClosestPointOnBox(box, V(1, -5)), 1, -1, 1e-6);
	cd2Box diamond = {V(0, 0), V(1, 1), cd2MakeRot(CD_PI / 4)};
	CHECK_VEC(cd2ClosestPointOnBox(diamond, V(3, 0)), sqrt(2.0), 0, 1e-6);
	CHECK_VEC(cd2ClosestPointOnBox(diamond, V(2, 2)), sqrt(0.5), sqrt(0.5), 1e-6);
	cd2Box flat = {V(0, 0), V(1, 0), CD2_ROT_IDENTITY};
	CHECK_VEC(cd2ClosestPointOnBox(flat, V(0.5, 2)), 0.5, 0, 0);
	CHECK_VEC(cd2ClosestPointOnBox(flat, V(0.5, 0)), 0.5, 0, 0);

	cd2Vec points[3] = {V(0, 0), V(2, 0), V(0, 2)};
	cd2Polygon triangle;
	TEST_CHECK(cd2MakePolygon(points, 3, &triangle) == CD_OK);
	CHECK_VEC(cd2ClosestPointOnPolygon(&triangle, V(0.5, 0.5)), 0.5, 0.5, 0);
	CHECK_VEC(cd2ClosestPointOnPolygon(&triangle, V(1, 1)), 1, 1, 0); /* on the hypotenuse */
	CHECK_VEC(cd2ClosestPointOnPolygon(&triangle, V(2, 2)), 1, 1, 1e-6);
	CHECK_VEC(cd2ClosestPointOnPolygon(&triangle, V(-1, -1)), 0, 0, 0);
	CHECK_VEC(cd2ClosestPointOnPolygon(&triangle, V(4, -1)), 2, 0, 0);
	CHECK_VEC(cd2ClosestPointOnPolygon(&triangle, V(-3, 1.5)), 0, 1.5, 1e-6);
	CHECK_VEC(cd2ClosestPointOnPolygon(&triangle, V(1, -0.5)), 1, 0, 1e-6);
}

static void CheckPair(cd2Segment a, cd2Segment b, double ax, double ay, double bx, double by, double distance)
{
	cd2ClosestPoints c = cd2ClosestPointsSegmentSegment(a, b);
	CHECK_VEC(c.pointA, ax, ay, 1e-6);
	CHECK_VEC(c.pointB, bx, by, 1e-6);
	TEST_CHECK_NEAR(c.distance, distance, 1e-6);
}

static void TestSegmentSegment(void)
{
	cd2Segment a = Segment(0, 0, 4, 0);
	CheckPair(a, Segment(1, -1, 3, 1), 2, 0, 2, 0, 0);		  /* crossing */
	CheckPair(a, Segment(2, 0, 2, 5), 2, 0, 2, 0, 0);		  /* T junction */
	CheckPair(a, Segment(1, 2, 3, 5), 1, 0, 1, 2, 2);		  /* end of b nearest */
	CheckPair(a, Segment(6, 1, 6, 9), 4, 0, 6, 1, sqrt(5.0)); /* end to end */
	CheckPair(a, Segment(7, -3, 7, 3), 4, 0, 7, 0, 3);		  /* end of a to interior of b */
	CheckPair(a, Segment(2, 2, 2, 2), 2, 0, 2, 2, 2);		  /* b is a point */
	CheckPair(Segment(1, 1, 1, 1), Segment(4, 5, 4, 5), 1, 1, 4, 5, 5);
	CheckPair(Segment(1, 1, 1, 1), Segment(0, 0, 2, 2), 1, 1, 1, 1, 0);
	CheckPair(a, Segment(5, 0, 8, 0), 4, 0, 5, 0, 1); /* collinear, apart */
	CheckPair(a, Segment(-3, 0, -1, 0), 0, 0, -1, 0, 1);

	/* parallel and overlapping segments: any closest pair will do, at the right distance */
	cd2ClosestPoints c = cd2ClosestPointsSegmentSegment(a, Segment(1, 2, 6, 2));
	TEST_CHECK_NEAR(c.distance, 2, 1e-6);
	TEST_CHECK_NEAR(c.pointA.y, 0, 1e-6);
	TEST_CHECK_NEAR(c.pointB.y, 2, 1e-6);
	TEST_CHECK(c.pointA.x >= 1 && c.pointA.x <= 4 && fabs((double)c.pointA.x - (double)c.pointB.x) < 1e-6);
	c = cd2ClosestPointsSegmentSegment(a, Segment(1, 0, 3, 0)); /* collinear, nested */
	TEST_CHECK_NEAR(c.distance, 0, 1e-6);
	TEST_CHECK(c.pointA.x >= 1 && c.pointA.x <= 3);
	/* nearly parallel: no division by a vanishing determinant */
	c = cd2ClosestPointsSegmentSegment(a, Segment(0, 1, 4, (cdReal)1.000001));
	TEST_CHECK_NEAR(c.distance, 1, 1e-5);
}

/* ---- property tests ---------------------------------------------------------------------------- */

/* Densely sampled distance from p to the shape's outline (its core for circles and capsules, less
 * the radius) in double, and the largest error the sampling step can make. */
static double SampledDistance(const cd2Shape* s, cd2Vec p, double* samplingError)
{
	RefShape r = RefFromShape(s);
	RefVec q = RefFromVec(p);
	const int samplesPerEdge = 400;
	double best = INFINITY;
	*samplingError = 0.0;
	int edges = r.count == 1 ? 1 : (r.count == 2 ? 1 : r.count);
	for (int i = 0; i < edges; ++i)
	{
		RefVec a = r.points[i], b = r.points[(i + 1) % r.count];
		*samplingError = fmax(*samplingError, RefDistance2(a, b) / samplesPerEdge);
		for (int k = 0; k <= samplesPerEdge; ++k)
		{
			double t = (double)k / samplesPerEdge;
			RefVec sample = RefMake(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y));
			best = fmin(best, RefDistance2(q, sample));
		}
	}
	return best - r.radius;
}

static void CheckClosestPoints(const char* label, double center, double extent, int perType, uint64_t seed)
{
	TestRng rng = TestRngMake(seed);
	for (int type = 0; type < CD2_SHAPE_TYPE_COUNT; ++type)
	{
		int inside = 0, outside = 0;
		for (int n = 0; n < perType; ++n)
		{
			cd2Vec origin = V(center, center);
			cd2Shape s = RandomShape(&rng, (cd2ShapeType)type, origin, extent);
			cd2Vec p = RandomVec(&rng, origin, 1.5 * extent);
			cd2Vec q = cd2ClosestPointOnShape(&s, p);
			const char* name = cd2GetShapeTypeName(s.type);
			TEST_CHECKF(cd2IsValidVec(q), "%s %s: not finite", label, name);
			double magnitude = fmax(RefShapeScale(&s), fmax(fabs((double)p.x), fabs((double)p.y)));
			double tolerance = 64.0 * (double)CD_REAL_EPSILON * magnitude + 1e-9 * extent;
			/* q lies on the shape */
			TEST_CHECKF(RefPointShapeDistance(&s, q) <= tolerance,
						"%s %s case %d: closest point %.9g off the shape", label, name, n,
						RefPointShapeDistance(&s, q));
			double reference = RefPointShapeDistance(&s, p);
			double found = RefDistance2(RefFromVec(p), RefFromVec(q));
			if (reference == 0.0 && s.type != CD2_SHAPE_SEGMENT)
			{
				/* inside a solid: the point itself (a boundary point within round-off at the edge) */
				TEST_CHECKF(found <= tolerance, "%s %s case %d: inside point moved by %.9g", label, name, n,
							found);
				++inside;
				continue;
			}
			++outside;
			double samplingError;
			double sampled = SampledDistance(&s, p, &samplingError);
			TEST_CHECKF(found <= sampled + tolerance && found >= sampled - samplingError - tolerance,
						"%s %s case %d: distance %.9g, sampled %.9g (+- %.3g)", label, name, n, found,
						sampled, samplingError);
		}
		TEST_CHECKF(outside > perType / 4, "%s: only %d outside cases", label, outside);
		TEST_CHECKF(inside >= perType / 50 || type == CD2_SHAPE_SEGMENT, "%s %s: only %d inside cases", label,
					cd2GetShapeTypeName((cd2ShapeType)type), inside);
	}
}

static void TestClosestPointOrdinary(void)
{
	CheckClosestPoints("ordinary", 0.0, 2.0, 400, 0xC105E1);
}

static void TestClosestPointHugeTiny(void)
{
#if CD_DOUBLE
	CheckClosestPoints("huge", 1e30, 1e27, 100, 0xC105E2);
	CheckClosestPoints("tiny", 0.0, 1e-30, 100, 0xC105E3);
#else
	CheckClosestPoints("huge", 1e9, 1e6, 100, 0xC105E2);
	CheckClosestPoints("tiny", 0.0, 1e-9, 100, 0xC105E3);
#endif
	CheckClosestPoints("far", 1e4, 10.0, 100, 0xC105E4);
}

/* Slivers (tip angles down to 1e-5, up to 1e9 / 1e30 long): a point beyond the sharp tip, on an
 * edge's extension or behind the tip, has the tip as its closest point, however close it stays to
 * both edge lines; the fuzzer's sliver first. */
static void TestSliverPolygons(void)
{
	cd2Vec points[3] = {V(32500, -125000), V(1e9, -125000), V(1e9, -43750)};
	cd2Polygon sliver;
	TEST_CHECK(cd2MakePolygon(points, 3, &sliver) == CD_OK);
	CHECK_VEC(cd2ClosestPointOnPolygon(&sliver, V(-125000, -125000)), 32500, -125000, 0);

	TestRng rng = TestRngMake(0xC105E5);
#if CD_DOUBLE
	const double largest = 30.0;
#else
	const double largest = 9.0;
#endif
	int checked = 0;
	for (int n = 0; n < 3000; ++n)
	{
		double k = pow(10.0, TestRngRange(&rng, -largest, largest));
		double angle = pow(10.0, TestRngRange(&rng, -5.0, -1.0));
		double heading = TestRngRange(&rng, -3.2, 3.2);
		double ux = cos(heading - 0.5 * angle), uy = sin(heading - 0.5 * angle);
		double wx = cos(heading + 0.5 * angle), wy = sin(heading + 0.5 * angle);
		double tipX = k * TestRngRange(&rng, -1.0, 1.0), tipY = k * TestRngRange(&rng, -1.0, 1.0);
		double l1 = k * TestRngRange(&rng, 0.5, 2.0), l2 = k * TestRngRange(&rng, 0.5, 2.0);
		cd2Vec corners[3] = {V(tipX, tipY), V(tipX + l1 * ux, tipY + l1 * uy),
							 V(tipX + l2 * wx, tipY + l2 * wy)};
		cd2Polygon polygon;
		if (cd2MakePolygon(corners, 3, &polygon) != CD_OK)
		{
			continue;
		}
		double d = k * pow(10.0, TestRngRange(&rng, -6.0, 0.0));
		double bx = TestRngInt(&rng, 2) == 0 ? ux : cos(heading),
			   by = TestRngInt(&rng, 2) == 0 ? uy : sin(heading);
		cd2Vec p = V(tipX - d * bx, tipY - d * by);
		RefVec tip = RefFromVec(corners[0]);
		double offset = sqrt(RefDistance2(RefFromVec(p), tip));
		double tolerance = 64.0 * (double)CD_REAL_EPSILON * fmax(offset, fmax(fabs(tip.x), fabs(tip.y)));
		if (offset <= 2.0 * tolerance)
		{
			continue; /* p rounded onto the tip */
		}
		++checked;
		double moved = sqrt(RefDistance2(RefFromVec(cd2ClosestPointOnPolygon(&polygon, p)), tip));
		TEST_CHECKF(moved <= tolerance,
					"case %d: angle %.3g, point %.3g beyond the tip: closest point %.3g from the tip", n,
					angle, offset, moved);
	}
	TEST_CHECKF(checked > 1000, "only %d cases", checked);
}

static void CheckSegmentPairs(const char* label, double extent, int count, uint64_t seed)
{
	TestRng rng = TestRngMake(seed);
	for (int n = 0; n < count; ++n)
	{
		cd2Segment a = RandomShape(&rng, CD2_SHAPE_SEGMENT, CD2_VEC_ZERO, extent).segment;
		cd2Segment b = RandomShape(&rng, CD2_SHAPE_SEGMENT, CD2_VEC_ZERO, extent).segment;
		int kind = TestRngInt(&rng, 4);
		if (kind == 0)
		{
			/* parallel: b is a shifted along a random offset */
			cd2Vec shift = RandomVec(&rng, CD2_VEC_ZERO, extent);
			b.p1 = cd2Add(a.p1, shift);
			b.p2 = cd2Add(a.p2, shift);
		}
		else if (kind == 1)
		{
			/* collinear: b lies on a's line */
			cd2Vec d = cd2Sub(a.p2, a.p1);
			b.p1 = cd2MulAdd(a.p1, RandomReal(&rng, -2.0, 2.0), d);
			b.p2 = cd2MulAdd(a.p1, RandomReal(&rng, -2.0, 2.0), d);
		}
		cd2ClosestPoints c = cd2ClosestPointsSegmentSegment(a, b);
		double tolerance = 64.0 * (double)CD_REAL_EPSILON * 3.0 * extent;
		RefVec a1 = RefFromVec(a.p1), a2 = RefFromVec(a.p2), b1 = RefFromVec(b.p1), b2 = RefFromVec(b.p2);
		RefVec pa = RefFromVec(c.pointA), pb = RefFromVec(c.pointB);
		TEST_CHECKF(isfinite((double)c.distance), "%s case %d: distance not finite", label, n);
		TEST_CHECKF(RefPointSegmentDistance(pa, a1, a2) <= tolerance,
					"%s case %d (kind %d): pointA off a by %.9g, distance %.9g", label, n, kind,
					RefPointSegmentDistance(pa, a1, a2), (double)c.distance);
		TEST_CHECKF(RefPointSegmentDistance(pb, b1, b2) <= tolerance,
					"%s case %d (kind %d): pointB off b by %.9g, distance %.9g", label, n, kind,
					RefPointSegmentDistance(pb, b1, b2), (double)c.distance);
		TEST_CHECKF(fabs(RefDistance2(pa, pb) - (double)c.distance) <= tolerance,
					"%s case %d: distance %.9g vs %.9g", label, n, (double)c.distance, RefDistance2(pa, pb));
		/* dense sampling of a against the exact distance to b, and the other way round */
		const int samples = 400;
		double sampled = INFINITY;
		for (int k = 0; k <= samples; ++k)
		{
			double t = (double)k / samples;
			sampled = fmin(sampled, RefPointSegmentDistance(
										RefMake(a1.x + t * (a2.x - a1.x), a1.y + t * (a2.y - a1.y)), b1, b2));
			sampled = fmin(sampled, RefPointSegmentDistance(
										RefMake(b1.x + t * (b2.x - b1.x), b1.y + t * (b2.y - b1.y)), a1, a2));
		}
		double samplingError = fmax(RefDistance2(a1, a2), RefDistance2(b1, b2)) / samples;
		TEST_CHECKF((double)c.distance <= sampled + tolerance &&
						(double)c.distance >= sampled - samplingError - tolerance,
					"%s case %d (kind %d): distance %.9g, sampled %.9g", label, n, kind, (double)c.distance,
					sampled);
	}
}

static void TestSegmentPairsSampled(void)
{
	CheckSegmentPairs("ordinary", 3.0, 2000, 0x5E65E1);
#if CD_DOUBLE
	CheckSegmentPairs("huge", 1e30, 300, 0x5E65E2);
	CheckSegmentPairs("tiny", 1e-30, 300, 0x5E65E3);
#else
	CheckSegmentPairs("huge", 1e9, 300, 0x5E65E2);
	CheckSegmentPairs("tiny", 1e-9, 300, 0x5E65E3);
#endif
}

int main(void)
{
	TEST_RUN(TestCircleCapsuleSegment);
	TEST_RUN(TestAabbBoxPolygon);
	TEST_RUN(TestSegmentSegment);
	TEST_RUN(TestClosestPointOrdinary);
	TEST_RUN(TestClosestPointHugeTiny);
	TEST_RUN(TestSegmentPairsSampled);
	TEST_RUN(TestSliverPolygons);
	return TEST_SUMMARY();
}
