/* Tests of the 3D closest-point queries: closest point on each shape, segment-segment and
 * triangle-segment closest pairs. Exact cases per Voronoi region, degenerate inputs, and random
 * cases checked against an independent double-precision projection (tests/reference3.h) and
 * against dense sampling of the shapes. */
#include "collide/query3.h"
#include "reference3.h"
#include "test.h"

/* Relative accuracy expected from a closest-point routine in cdReal. */
#define REL_TOLERANCE (CD_DOUBLE ? 1e-11 : 2e-5)

static bool VecNear(cd3Vec a, cd3Vec b, double tolerance)
{
	return RDist(RFromVec(a), RFromVec(b)) <= tolerance;
}

static bool IsFiniteVec(cd3Vec v)
{
	return cd3IsValidVec(v);
}

#define CHECK_VEC(actual, ex, ey, ez, tolerance)                                                             \
	do                                                                                                       \
	{                                                                                                        \
		cd3Vec actual_ = (actual);                                                                           \
		TEST_CHECKF(VecNear(actual_, cd3MakeVec(ex, ey, ez), tolerance),                                     \
					"%s = (%.9g %.9g %.9g), expected (%g %g %g)", #actual, (double)actual_.x,                \
					(double)actual_.y, (double)actual_.z, (double)(ex), (double)(ey), (double)(ez));         \
	} while (0)

static void TestSphereCapsuleSegment(void)
{
	cd3Sphere sphere = {{1, 0, 0}, 2};
	CHECK_VEC(cd3ClosestPointOnSphere(sphere, cd3MakeVec(5, 0, 0)), 3, 0, 0, 1e-6);
	CHECK_VEC(cd3ClosestPointOnSphere(sphere, cd3MakeVec(1, -4, 0)), 1, -2, 0, 1e-6);
	cd3Vec inside = {CD_R(1.5), CD_R(0.3), CD_R(-0.2)};
	TEST_CHECK(cd3VecEqual(cd3ClosestPointOnSphere(sphere, inside), inside));
	TEST_CHECK(cd3VecEqual(cd3ClosestPointOnSphere(sphere, sphere.center), sphere.center));
	/* On the surface counts as inside. */
	TEST_CHECK(cd3VecEqual(cd3ClosestPointOnSphere(sphere, cd3MakeVec(3, 0, 0)), cd3MakeVec(3, 0, 0)));
	cd3Sphere point = {{1, 2, 3}, 0};
	TEST_CHECK(cd3VecEqual(cd3ClosestPointOnSphere(point, cd3MakeVec(7, -8, 9)), point.center));
	TEST_CHECK(cd3VecEqual(cd3ClosestPointOnSphere(point, point.center), point.center));

	cd3Segment segment = {{0, 0, 0}, {4, 0, 0}};
	CHECK_VEC(cd3ClosestPointOnSegment(segment, cd3MakeVec(2, 3, 0)), 2, 0, 0, 1e-6);
	CHECK_VEC(cd3ClosestPointOnSegment(segment, cd3MakeVec(-2, 3, 1)), 0, 0, 0, 0);
	CHECK_VEC(cd3ClosestPointOnSegment(segment, cd3MakeVec(9, -3, 1)), 4, 0, 0, 0);
	CHECK_VEC(cd3ClosestPointOnSegment(segment, cd3MakeVec(1, 0, 0)), 1, 0, 0, 1e-6);
	cd3Segment dot = {{1, 1, 1}, {1, 1, 1}};
	CHECK_VEC(cd3ClosestPointOnSegment(dot, cd3MakeVec(5, 0, 0)), 1, 1, 1, 0);
	CHECK_VEC(cd3ClosestPointOnSegment(dot, cd3MakeVec(1, 1, 1)), 1, 1, 1, 0);

	cd3Capsule capsule = {{0, 0, 0}, {0, 4, 0}, 1};
	CHECK_VEC(cd3ClosestPointOnCapsule(capsule, cd3MakeVec(3, 2, 0)), 1, 2, 0, 1e-6);
	CHECK_VEC(cd3ClosestPointOnCapsule(capsule, cd3MakeVec(0, 7, 0)), 0, 5, 0, 1e-6);
	CHECK_VEC(cd3ClosestPointOnCapsule(capsule, cd3MakeVec(0, -3, 0)), 0, -1, 0, 1e-6);
	inside = cd3MakeVec(CD_R(0.5), CD_R(3.5), CD_R(0.2));
	TEST_CHECK(cd3VecEqual(cd3ClosestPointOnCapsule(capsule, inside), inside));
	cd3Capsule ball = {{2, 0, 0}, {2, 0, 0}, 1};
	CHECK_VEC(cd3ClosestPointOnCapsule(ball, cd3MakeVec(2, 0, 5)), 2, 0, 1, 1e-6);
	cd3Capsule line = {{0, 0, 0}, {0, 4, 0}, 0};
	CHECK_VEC(cd3ClosestPointOnCapsule(line, cd3MakeVec(3, 2, 0)), 0, 2, 0, 1e-6);
}

static void TestAabbBoxPlane(void)
{
	cd3Aabb aabb = {{-1, -2, -3}, {1, 2, 3}};
	CHECK_VEC(cd3ClosestPointOnAabb(aabb, cd3MakeVec(5, 0, 0)), 1, 0, 0, 0);
	CHECK_VEC(cd3ClosestPointOnAabb(aabb, cd3MakeVec(5, -5, 5)), 1, -2, 3, 0);
	cd3Vec inside = {CD_R(0.5), CD_R(-1.5), CD_R(2.9)};
	TEST_CHECK(cd3VecEqual(cd3ClosestPointOnAabb(aabb, inside), inside));
	cd3Aabb point = {{1, 1, 1}, {1, 1, 1}};
	CHECK_VEC(cd3ClosestPointOnAabb(point, cd3MakeVec(-4, 5, 0)), 1, 1, 1, 0);

	/* 45 degrees about z: the box's +x face normal is (1, 1, 0) / sqrt(2). */
	cd3Box box = {{1, 0, 0}, {1, 2, 3}, cd3MakeQuatAxisAngle(cd3MakeVec(0, 0, 1), CD_PI * CD_R(0.25))};
	cdReal k = CD_R(0.70710678118654752);
	CHECK_VEC(cd3ClosestPointOnBox(box, cd3MakeVec(1 + 5 * k, 5 * k, 0)), 1 + k, k, 0, 1e-5);
	CHECK_VEC(cd3ClosestPointOnBox(box, cd3MakeVec(1, 0, 10)), 1, 0, 3, 1e-5);
	inside = cd3MakeVec(CD_R(1.3), CD_R(0.4), CD_R(-2.5));
	TEST_CHECK(cd3VecEqual(cd3ClosestPointOnBox(box, inside), inside));
	cd3Box flat = {{0, 0, 0}, {1, 0, 1}, CD3_QUAT_IDENTITY};
	CHECK_VEC(cd3ClosestPointOnBox(flat, cd3MakeVec(CD_R(0.5), 4, -3)), 0.5, 0, -1, 1e-6);
	cd3Box pointBox = {{3, 2, 1}, {0, 0, 0}, cd3MakeQuatAxisAngle(cd3MakeVec(1, 2, 3), 1)};
	CHECK_VEC(cd3ClosestPointOnBox(pointBox, cd3MakeVec(9, 9, 9)), 3, 2, 1, 1e-6);

	cd3Plane plane = {{0, 1, 0}, 2};
	CHECK_VEC(cd3ClosestPointOnPlane(plane, cd3MakeVec(3, 7, -1)), 3, 2, -1, 0);
	inside = cd3MakeVec(3, -7, -1);
	TEST_CHECK(cd3VecEqual(cd3ClosestPointOnPlane(plane, inside), inside));
	TEST_CHECK(cd3VecEqual(cd3ClosestPointOnPlane(plane, cd3MakeVec(0, 2, 0)), cd3MakeVec(0, 2, 0)));
	cd3Plane tilted = {cd3Normalize(cd3MakeVec(1, 1, 0)), 0};
	CHECK_VEC(cd3ClosestPointOnPlane(tilted, cd3MakeVec(2, 0, 5)), 1, -1, 5, 1e-6);
}

static void TestTriangleRegions(void)
{
	cd3Triangle t = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
	CHECK_VEC(cd3ClosestPointOnTriangle(t, cd3MakeVec(-1, -1, 2)), 0, 0, 0, 0);	  /* vertex a */
	CHECK_VEC(cd3ClosestPointOnTriangle(t, cd3MakeVec(6, -1, 1)), 4, 0, 0, 0);	  /* vertex b */
	CHECK_VEC(cd3ClosestPointOnTriangle(t, cd3MakeVec(-1, 7, -1)), 0, 4, 0, 0);	  /* vertex c */
	CHECK_VEC(cd3ClosestPointOnTriangle(t, cd3MakeVec(2, -3, 1)), 2, 0, 0, 1e-6); /* edge ab */
	CHECK_VEC(cd3ClosestPointOnTriangle(t, cd3MakeVec(-3, 1, 1)), 0, 1, 0, 1e-6); /* edge ca */
	CHECK_VEC(cd3ClosestPointOnTriangle(t, cd3MakeVec(3, 3, -2)), 2, 2, 0, 1e-6); /* edge bc */
	CHECK_VEC(cd3ClosestPointOnTriangle(t, cd3MakeVec(1, 1, 5)), 1, 1, 0, 1e-6);  /* face, above */
	CHECK_VEC(cd3ClosestPointOnTriangle(t, cd3MakeVec(1, 2, -5)), 1, 2, 0, 1e-6); /* face, below */
	CHECK_VEC(cd3ClosestPointOnTriangle(t, cd3MakeVec(1, 2, 0)), 1, 2, 0, 1e-6);  /* in the face */
	CHECK_VEC(cd3ClosestPointOnTriangle(t, cd3MakeVec(4, 0, 0)), 4, 0, 0, 0);	  /* on a vertex */

	/* Degenerate triangles are the segment or point they collapsed to. */
	cd3Triangle collinear = {{0, 0, 0}, {2, 0, 0}, {4, 0, 0}};
	CHECK_VEC(cd3ClosestPointOnTriangle(collinear, cd3MakeVec(3, 5, 0)), 3, 0, 0, 1e-6);
	CHECK_VEC(cd3ClosestPointOnTriangle(collinear, cd3MakeVec(7, 1, 1)), 4, 0, 0, 1e-6);
	CHECK_VEC(cd3ClosestPointOnTriangle(collinear, cd3MakeVec(-1, 1, 1)), 0, 0, 0, 1e-6);
	cd3Triangle repeated = {{0, 0, 0}, {0, 0, 0}, {4, 0, 0}};
	CHECK_VEC(cd3ClosestPointOnTriangle(repeated, cd3MakeVec(1, 1, 0)), 1, 0, 0, 1e-6);
	cd3Triangle repeated2 = {{4, 0, 0}, {0, 0, 0}, {4, 0, 0}};
	CHECK_VEC(cd3ClosestPointOnTriangle(repeated2, cd3MakeVec(1, -1, 0)), 1, 0, 0, 1e-6);
	cd3Triangle point = {{1, 2, 3}, {1, 2, 3}, {1, 2, 3}};
	CHECK_VEC(cd3ClosestPointOnTriangle(point, cd3MakeVec(0, 0, 0)), 1, 2, 3, 0);
	CHECK_VEC(cd3ClosestPointOnTriangle(point, cd3MakeVec(1, 2, 3)), 1, 2, 3, 0);
}

static void TestSegmentSegmentExact(void)
{
	/* Crossing: distance 0 at the crossing. */
	cd3Segment a = {{-1, 0, 0}, {1, 0, 0}};
	cd3Segment b = {{0, -1, 0}, {0, 1, 0}};
	cd3ClosestPoints r = cd3ClosestPointsSegmentSegment(a, b);
	CHECK_VEC(r.pointA, 0, 0, 0, 1e-6);
	TEST_CHECK(r.distance == 0 && cd3VecEqual(r.pointA, r.pointB));
	/* Crossing at an inexact point: still distance 0 and one common point. */
	cd3Segment c = {{CD_R(-0.3), CD_R(0.1), CD_R(0.7)}, {CD_R(1.9), CD_R(-1.3), CD_R(-0.2)}};
	cd3Vec crossing = cd3Lerp(c.p1, c.p2, CD_R(0.37));
	cd3Segment d = {cd3MulSub(crossing, CD_R(0.6), cd3MakeVec(CD_R(0.3), CD_R(1.1), CD_R(-0.4))),
					cd3MulAdd(crossing, CD_R(0.9), cd3MakeVec(CD_R(0.3), CD_R(1.1), CD_R(-0.4)))};
	r = cd3ClosestPointsSegmentSegment(c, d);
	TEST_CHECK(r.distance == 0 && cd3VecEqual(r.pointA, r.pointB));
	CHECK_VEC(r.pointA, crossing.x, crossing.y, crossing.z, 1e-5);
	/* Skew, interior closest points. */
	b = (cd3Segment){{CD_R(0.5), -1, 2}, {CD_R(0.5), 1, 2}};
	r = cd3ClosestPointsSegmentSegment(a, b);
	CHECK_VEC(r.pointA, 0.5, 0, 0, 1e-6);
	CHECK_VEC(r.pointB, 0.5, 0, 2, 1e-6);
	TEST_CHECK_NEAR(r.distance, 2, 1e-6);
	/* Skew, clamped at endpoints. */
	b = (cd3Segment){{3, 1, 1}, {3, 5, 1}};
	r = cd3ClosestPointsSegmentSegment(a, b);
	CHECK_VEC(r.pointA, 1, 0, 0, 1e-6);
	CHECK_VEC(r.pointB, 3, 1, 1, 1e-6);
	/* Parallel and overlapping in projection: the gap, and both points on their segments. */
	b = (cd3Segment){{0, 3, 0}, {5, 3, 0}};
	r = cd3ClosestPointsSegmentSegment(a, b);
	TEST_CHECK_NEAR(r.distance, 3, 1e-6);
	TEST_CHECK(r.pointA.x >= 0 && r.pointA.x <= 1 && r.pointB.x >= 0 && r.pointB.x <= 1);
	TEST_CHECK_NEAR(r.pointA.x, r.pointB.x, 1e-6);
	/* Anti-parallel. */
	b = (cd3Segment){{5, 3, 0}, {0, 3, 0}};
	r = cd3ClosestPointsSegmentSegment(a, b);
	TEST_CHECK_NEAR(r.distance, 3, 1e-6);
	/* Collinear and disjoint: end to end. */
	b = (cd3Segment){{3, 0, 0}, {5, 0, 0}};
	r = cd3ClosestPointsSegmentSegment(a, b);
	CHECK_VEC(r.pointA, 1, 0, 0, 0);
	CHECK_VEC(r.pointB, 3, 0, 0, 0);
	TEST_CHECK_NEAR(r.distance, 2, 1e-6);
	b = (cd3Segment){{-5, 0, 0}, {-3, 0, 0}};
	r = cd3ClosestPointsSegmentSegment(a, b);
	CHECK_VEC(r.pointA, -1, 0, 0, 0);
	CHECK_VEC(r.pointB, -3, 0, 0, 0);
	/* Collinear and overlapping: distance 0. */
	b = (cd3Segment){{CD_R(0.5), 0, 0}, {4, 0, 0}};
	r = cd3ClosestPointsSegmentSegment(a, b);
	TEST_CHECK_NEAR(r.distance, 0, 1e-6);
	/* Coincident. */
	r = cd3ClosestPointsSegmentSegment(a, a);
	TEST_CHECK_NEAR(r.distance, 0, 1e-6);
	/* Degenerate: a point against a segment, and two points. */
	cd3Segment point = {{CD_R(0.25), 2, 0}, {CD_R(0.25), 2, 0}};
	r = cd3ClosestPointsSegmentSegment(point, a);
	CHECK_VEC(r.pointB, 0.25, 0, 0, 1e-6);
	TEST_CHECK_NEAR(r.distance, 2, 1e-6);
	r = cd3ClosestPointsSegmentSegment(a, point);
	CHECK_VEC(r.pointA, 0.25, 0, 0, 1e-6);
	cd3Segment other = {{1, 2, 2}, {1, 2, 2}};
	r = cd3ClosestPointsSegmentSegment(point, other);
	TEST_CHECK_NEAR(r.distance, sqrt(0.75 * 0.75 + 4.0), 1e-6);
	r = cd3ClosestPointsSegmentSegment(point, point);
	TEST_CHECK(r.distance == 0 && cd3VecEqual(r.pointA, point.p1));
}

static void TestTriangleSegmentExact(void)
{
	cd3Triangle t = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
	/* Piercing the face. */
	cd3Segment g = {{1, 1, -2}, {1, 1, 2}};
	cd3ClosestPoints r = cd3ClosestPointsTriangleSegment(t, g);
	TEST_CHECK(r.distance == 0 && cd3VecEqual(r.pointA, r.pointB));
	CHECK_VEC(r.pointA, 1, 1, 0, 1e-6);
	CHECK_VEC(r.pointB, 1, 1, 0, 1e-6);
	/* Slanted piercing. */
	g = (cd3Segment){{CD_R(0.1), CD_R(0.3), -2}, {CD_R(2.3), CD_R(1.7), CD_R(2.9)}};
	r = cd3ClosestPointsTriangleSegment(t, g);
	TEST_CHECK(r.distance == 0 && cd3VecEqual(r.pointA, r.pointB));
	TEST_CHECK_NEAR(r.pointA.z, 0, 1e-6);
	g = (cd3Segment){{0, 0, -2}, {2, 2, 2}};
	r = cd3ClosestPointsTriangleSegment(t, g);
	TEST_CHECK_NEAR(r.distance, 0, 1e-6);
	CHECK_VEC(r.pointB, 1, 1, 0, 1e-6);
	/* Above the face, parallel to it. */
	g = (cd3Segment){{1, 1, 3}, {2, 1, 3}};
	r = cd3ClosestPointsTriangleSegment(t, g);
	TEST_CHECK_NEAR(r.distance, 3, 1e-6);
	TEST_CHECK_NEAR(r.pointA.z, 0, 1e-6);
	/* Endpoint closest to the face. */
	g = (cd3Segment){{1, 1, 1}, {1, 1, 9}};
	r = cd3ClosestPointsTriangleSegment(t, g);
	CHECK_VEC(r.pointA, 1, 1, 0, 1e-6);
	CHECK_VEC(r.pointB, 1, 1, 1, 1e-6);
	/* Crossing below edge bc, outside the triangle: edge-edge. */
	g = (cd3Segment){{4, 4, -1}, {4, 4, 1}};
	r = cd3ClosestPointsTriangleSegment(t, g);
	CHECK_VEC(r.pointA, 2, 2, 0, 1e-6);
	CHECK_VEC(r.pointB, 4, 4, 0, 1e-6);
	TEST_CHECK_NEAR(r.distance, sqrt(8.0), 1e-6);
	/* In the plane, crossing the triangle: distance 0. */
	g = (cd3Segment){{-1, 1, 0}, {5, 1, 0}};
	r = cd3ClosestPointsTriangleSegment(t, g);
	TEST_CHECK_NEAR(r.distance, 0, 1e-6);
	/* In the plane, inside the triangle. */
	g = (cd3Segment){{CD_R(0.5), CD_R(0.5), 0}, {1, CD_R(0.5), 0}};
	r = cd3ClosestPointsTriangleSegment(t, g);
	TEST_CHECK_NEAR(r.distance, 0, 1e-6);
	/* Zero-length segment: the point query. */
	g = (cd3Segment){{1, 1, 5}, {1, 1, 5}};
	r = cd3ClosestPointsTriangleSegment(t, g);
	CHECK_VEC(r.pointA, 1, 1, 0, 1e-6);
	TEST_CHECK_NEAR(r.distance, 5, 1e-6);
	/* Degenerate triangles: a segment, a point. */
	cd3Triangle line = {{0, 0, 0}, {2, 0, 0}, {4, 0, 0}};
	g = (cd3Segment){{1, -1, 1}, {1, 1, 1}};
	r = cd3ClosestPointsTriangleSegment(line, g);
	CHECK_VEC(r.pointA, 1, 0, 0, 1e-6);
	TEST_CHECK_NEAR(r.distance, 1, 1e-6);
	cd3Triangle point = {{1, 1, 1}, {1, 1, 1}, {1, 1, 1}};
	r = cd3ClosestPointsTriangleSegment(point, g);
	CHECK_VEC(r.pointA, 1, 1, 1, 0);
	CHECK_VEC(r.pointB, 1, 1, 1, 1e-6);
	TEST_CHECK_NEAR(r.distance, 0, 1e-6);
}

/* Nearly parallel segments that cross: the distance must stay near zero (the textbook a*e - b*b
 * form loses half the digits here). */
static void TestNearlyParallelSegments(void)
{
	TestRng rng = TestRngMake(0x5EED3101u);
	const double angles[] = {1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6};
	for (int i = 0; i < 600; ++i)
	{
		double angle = angles[i % 6];
		cd3Vec direction = RandomUnit(&rng);
		cd3Vec perpendicular = cd3Perpendicular(direction);
		cd3Vec crossing = RandomVec(&rng, -2, 2);
		cdReal c = (cdReal)cos(angle), s = (cdReal)sin(angle);
		cd3Vec other = cd3Add(cd3Scale(c, direction), cd3Scale(s, perpendicular));
		double length = TestRngRange(&rng, 1, 4);
		cdReal before = (cdReal)TestRngRange(&rng, 0.2, 0.8);
		cd3Segment a = {cd3MulSub(crossing, before * (cdReal)length, direction),
						cd3MulAdd(crossing, (1 - before) * (cdReal)length, direction)};
		cd3Segment b = {cd3MulSub(crossing, (1 - before) * (cdReal)length, other),
						cd3MulAdd(crossing, before * (cdReal)length, other)};
		cd3ClosestPoints r = cd3ClosestPointsSegmentSegment(a, b);
		RShape ra = RFromShape(&(cd3Shape){.type = CD3_SHAPE_SEGMENT, .segment = a});
		RShape rb = RFromShape(&(cd3Shape){.type = CD3_SHAPE_SEGMENT, .segment = b});
		/* The inputs are rounded, so the true distance of the rounded segments is not exactly 0:
		 * bound it by the reference. */
		RDistance reference = RComputeDistance(&ra, &rb);
		double tolerance = REL_TOLERANCE * 4.0;
		TEST_CHECKF((double)r.distance <= reference.upper + tolerance,
					"angle %g: distance %.9g, reference [%g, %g]", angle, (double)r.distance, reference.lower,
					reference.upper);
		TEST_CHECKF(RDist(RProject(&ra, RFromVec(r.pointA)), RFromVec(r.pointA)) <= tolerance,
					"pointA off a");
		TEST_CHECKF(RDist(RProject(&rb, RFromVec(r.pointB)), RFromVec(r.pointB)) <= tolerance,
					"pointB off b");
	}
}

/* Thin but valid triangles (smallest angle down to 1e-6): the closest point of points on and
 * near them stays accurate, although their computed normal is poor in float. */
static void TestThinTriangles(void)
{
	TestRng rng = TestRngMake(0x5EED3105u);
	const double thickness[] = {1e-2, 1e-3, 1e-4, 1e-5, 1e-6};
	int tested = 0;
	for (int i = 0; i < 2000; ++i)
	{
		cd3Vec a = RandomVec(&rng, -2, 2), b = cd3Add(a, RandomVec(&rng, -2, 2));
		cd3Vec side = cd3Perpendicular(cd3Normalize(cd3Sub(b, a)));
		cdReal along = (cdReal)TestRngRange(&rng, -0.2, 1.2);
		cdReal across = (cdReal)(thickness[i % 5] * TestRngRange(&rng, 0.5, 1.0)) * cd3Length(cd3Sub(b, a));
		cd3Triangle t = {a, b, cd3MulAdd(cd3Lerp(a, b, along), across, side)};
		if (!cd3IsValidTriangle(t))
		{
			continue;
		}
		++tested;
		cd3Shape shape = cd3MakeTriangleShape(t);
		RShape r = RFromShape(&shape);
		RVec onTriangle = RSample(&r, &rng, RMake(0, 0, 0), 0.0);
		RVec rp = RAdd(onTriangle, RScale(TestRngRange(&rng, -0.1, 0.1), RFromVec(RandomUnit(&rng))));
		cd3Vec p = RToVec(rp);
		rp = RFromVec(p);
		RVec rq = RFromVec(cd3ClosestPointOnTriangle(t, p));
		RVec reference = RProject(&r, rp);
		double tolerance = REL_TOLERANCE * RShapeScale(&r);
		TEST_CHECKF(RDist(rq, reference) <= tolerance &&
						fabs(RDist(rp, rq) - RDist(rp, reference)) <= tolerance,
					"thickness %g: error %g", thickness[i % 5], RDist(rq, reference));
	}
	TEST_CHECKF(tested > 1000, "only %d valid thin triangles", tested);
}

/* Needles: one edge shorter than the round-off of the others (the fuzzer's triangle has edges
 * 1.4e-9 and 1.08e8, with a right angle at a, and the validator accepts it). With p at vertex c,
 * p - a and p - b round to the same vector, and the point c itself fell into the region of the
 * short edge: (0, 0, 1e-9) came back, 1.08e8 away. Every vertex order, points on the triangle
 * and off its plane, then random needles against the double reference. */
static void TestNeedleTriangles(void)
{
	cd3Vec a = cd3MakeVec(CD_R(0.0), CD_R(0.0), CD_R(1e-9)), b = cd3MakeVec(CD_R(1e-9), CD_R(0.0), CD_R(0.0));
	cd3Vec c = cd3MakeVec(CD_R(6.25e7), CD_R(6.25e7), CD_R(6.25e7));
	/* The face normal is ab x ac, along (1, -2, 1); points off the plane project back. */
	cd3Vec up = cd3Scale(CD_R(1000.0), cd3Normalize(cd3MakeVec(CD_R(1.0), CD_R(-2.0), CD_R(1.0))));
	cd3Vec midAc = cd3Lerp(a, c, CD_R(0.5)), midBc = cd3Lerp(b, c, CD_R(0.5));
	cd3Vec queries[6][2] = {
		{c, c},
		{midAc, midAc},
		{midBc, midBc},
		{cd3Add(c, up), c},
		{cd3Sub(midAc, up), midAc},
		{cd3Add(c, cd3MakeVec(CD_R(1e7), CD_R(1e7), CD_R(1e7))), c},
	};
	cd3Vec corners[3] = {a, b, c};
	static const int orders[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
	double tolerance = REL_TOLERANCE * 6.25e7;
	for (int o = 0; o < 6; ++o)
	{
		cd3Triangle t = {corners[orders[o][0]], corners[orders[o][1]], corners[orders[o][2]]};
		for (int q = 0; q < 6; ++q)
		{
			cd3Vec closest = cd3ClosestPointOnTriangle(t, queries[q][0]);
			double error = RDist(RFromVec(closest), RFromVec(queries[q][1]));
			TEST_CHECKF(error <= tolerance, "order %d, query %d: closest (%.9g %.9g %.9g), %.3g off", o, q,
						(double)closest.x, (double)closest.y, (double)closest.z, error);
		}
	}

#if CD_DOUBLE
	/* A needle whose short edge bc is 2e8 long and whose tip a is 2.5e17 away (double build,
	 * fuzz_query3; beyond the float build's documented range, so checked in double only): the
	 * point 1e7 above the face near bc came back as vertex b, 1.1e8 away. */
	cd3Triangle spike = {cd3MakeVec(CD_R(-1e7), CD_R(2.48148436e17), CD_R(-1e7)),
						 cd3MakeVec(CD_R(-1.2e8), CD_R(1e7), 0), cd3MakeVec(CD_R(2e7), CD_R(-1.2375e8), 0)};
	cd3Vec above = cd3MakeVec(CD_R(-1e7), CD_R(-1e7), CD_R(1e7));
	double spikeDistance = RDist(RFromVec(cd3ClosestPointOnTriangle(spike, above)), RFromVec(above));
	TEST_CHECKF(fabs(spikeDistance - 1e7) <= 1e-3 * 1e7, "needle with a far tip: %.9g away, 1e7 expected",
				spikeDistance);
#endif

	TestRng rng = TestRngMake(0x5EED3106u);
	for (int i = 0; i < 3000; ++i)
	{
		/* A long edge of length up to 1e8, a short one 1e-17..1e-9 of it, at a random angle. */
		double length = pow(10.0, TestRngRange(&rng, 0.0, CD_DOUBLE ? 20.0 : 8.0));
		double shortLength = length * pow(10.0, TestRngRange(&rng, -17.0, -9.0));
		cd3Vec p0 = RandomVec(&rng, -1, 1);
		cd3Vec p1 = cd3MulAdd(p0, (cdReal)shortLength, RandomUnit(&rng));
		cd3Vec p2 = cd3MulAdd(p0, (cdReal)length, RandomUnit(&rng));
		cd3Vec points[3] = {p0, p1, p2};
		const int* order = orders[TestRngInt(&rng, 6)];
		cd3Triangle t = {points[order[0]], points[order[1]], points[order[2]]};
		/* Expectations from the construction (the double reference is no more accurate than the
		 * double build on needles): vertex c itself (distance 0), or a point of a long edge moved
		 * off it along the face normal (computed in double from the vertices) by `height`. */
		RVec ra = RFromVec(p0), rb = RFromVec(p1), rc = RFromVec(p2);
		RVec normal = RCross(RSub(rb, ra), RSub(rc, ra));
		double normalLength = RLength(normal);
		normal = normalLength > 0.0 ? RScale(1.0 / normalLength, normal) : RMake(0, 0, 0);
		RVec start = TestRngInt(&rng, 2) == 0 ? ra : rb;
		RVec onEdge = RAdd(start, RScale(TestRngRange(&rng, 0.0, 1.0), RSub(rc, start)));
		double height = TestRngInt(&rng, 2) == 0 ? 0.0 : length * TestRngRange(&rng, -0.1, 0.1);
		bool atVertex = TestRngInt(&rng, 4) == 0;
		RVec rp = atVertex ? rc : RAdd(onEdge, RScale(height, normal));
		double built = atVertex || normalLength == 0.0 ? 0.0 : fabs(height);
		RVec rq = RFromVec(cd3ClosestPointOnTriangle(t, RToVec(rp)));
		double distance = RDist(RFromVec(RToVec(rp)), rq);
		TEST_CHECKF(
			fabs(distance - built) <= REL_TOLERANCE * fmax(length, RMaxAbs(rp)),
			"needle of length %g and %g: %.9g from the point, built %.9g away; triangle (%.17g %.17g %.17g) "
			"(%.17g %.17g %.17g) (%.17g %.17g %.17g), point (%.17g %.17g %.17g)",
			length, shortLength, distance, built, (double)t.a.x, (double)t.a.y, (double)t.a.z, (double)t.b.x,
			(double)t.b.y, (double)t.b.z, (double)t.c.x, (double)t.c.y, (double)t.c.z, rp.x, rp.y, rp.z);
	}
}

/* cd3PointInHull on a wedge (fuzz_query3): two faces of this hull meet at about 1e-4 rad along
 * its long edge from (5e8, 5e8, -1.25e6) to (5e8, 5e8, 5e8). The point 1.25e6 beyond that edge
 * along x and y (1.77e6 from the hull) is only 198 above one face and below the other, within
 * the planes' tolerance (2.3e3 at these coordinates): it counted as inside. */
static void TestPointInHullWedge(void)
{
	static const float cloud[] = {500000000, 500000000, -1250000,  -1250000,  -1250000,	 -1250000,
								  -1250000,	 -1250000,	0,		   0,		  0,		 0,
								  0,		 0,			0,		   -1150000,  -1250000,	 -1250000,
								  500000000, 500000000, 500000000, 500000000, 500000000, -662500};
	cd3Vec points[8];
	for (int i = 0; i < 8; ++i)
	{
		points[i] = cd3MakeVec((cdReal)cloud[3 * i], (cdReal)cloud[3 * i + 1], (cdReal)cloud[3 * i + 2]);
	}
	cd3Hull* hull = NULL;
	TEST_CHECK(cd3ComputeHull(points, 8, &hull) == CD_OK && hull != NULL);
	if (hull == NULL)
	{
		return;
	}
	cd3HullShape shape = {hull,
						  {cd3MakeVec(CD_R(5e8), CD_R(-1250000.0), CD_R(-1250000.0)),
						   cd3NormalizeQuat(cd3MakeQuat(CD_R(-0.5), CD_R(-0.5), CD_R(-0.5), CD_R(-0.5)))}};
	/* (5e8, 5e8, 5e8) in the hull's frame is (5.0125e8, 5.0125e8, 0). */
	cd3Vec p = cd3MakeVec(CD_R(5e8), CD_R(5e8), CD_R(5e8));
	TEST_CHECK(!cd3PointInHull(p, shape));
	double away = RDist(RFromVec(cd3ClosestPointOnHull(shape, p)), RFromVec(p));
	TEST_CHECKF(fabs(away - 1.25e6 * sqrt(2.0)) <= 1e-3 * 1.25e6, "closest point %.9g away", away);
	/* Points of the hull still count: its vertices and the middle of that edge. */
	for (int i = 0; i < hull->vertexCount; ++i)
	{
		TEST_CHECK(cd3PointInHull(cd3TransformPoint(shape.transform, hull->vertices[i]), shape));
	}
	cd3Vec middle = cd3MakeVec(CD_R(5e8), CD_R(5e8), CD_R(2.49375e8));
	TEST_CHECK(cd3PointInHull(cd3TransformPoint(shape.transform, middle), shape));
	cd3DestroyHull(hull);

	/* A 5e-6 rad wedge: (4.25e6, -1e9, -1e9) in its frame is 22 above one face (below the
	 * float round-off of that height) and 4.25e6 beyond the hull's largest x, -6.625. */
	static const float wedge[] = {-1e+09f, -7356.64795f, -6.625f, -6.625f, -6.875f, -6.625f,
								  -6.625f, -6.625f,		 -6.625f, -6.625f, -1e+09f, -1e+09f,
								  -1e+09f, -1e+09f,		 -1e+09f, -1e+09f, -1e+09f, -1e+09f};
	for (int i = 0; i < 6; ++i)
	{
		points[i] = cd3MakeVec((cdReal)wedge[3 * i], (cdReal)wedge[3 * i + 1], (cdReal)wedge[3 * i + 2]);
	}
	hull = NULL;
	TEST_CHECK(cd3ComputeHull(points, 6, &hull) == CD_OK && hull != NULL);
	if (hull != NULL)
	{
		cd3HullShape thin = {hull, {CD3_VEC_ZERO, CD3_QUAT_IDENTITY}};
		cd3Vec beyond = cd3MakeVec(CD_R(4250220.5), CD_R(-1e9), CD_R(-1e9));
		TEST_CHECK(!cd3PointInHull(beyond, thin));
		TEST_CHECK(cd3PointInHull(cd3MakeVec(CD_R(-6.625), CD_R(-1e9), CD_R(-1e9)), thin));
		cd3DestroyHull(hull);
	}
}

/* A sheet a few dozen float epsilons thick (fuzz_hull3): its centroid lies 1.5e-8 below its two
 * large faces, within their plane tolerance, so the distance decides; GJK across the sheet reports
 * about 4e-8 for that interior point, which the decision band must absorb. */
static void TestPointInHullSheet(void)
{
	static const float sheet[6][3] = {{0.0f, 0.0f, 0.0f},
									  {1.74499774e-39f, 0.0f, 1.47654819e-41f},
									  {0.000717163086f, 0.000710401335f, 0.000710401335f},
									  {0.0114889704f, 0.0114889704f, 0.0114889704f},
									  {0.0114889704f, 0.0114890514f, 0.0114889704f},
									  {0.0115101896f, 0.0114889704f, 0.0114889704f}};
	cd3Vec points[6];
	for (int i = 0; i < 6; ++i)
	{
		points[i] = cd3MakeVec((cdReal)sheet[i][0], (cdReal)sheet[i][1], (cdReal)sheet[i][2]);
	}
	cd3Hull* hull = NULL;
	cdResult result = cd3ComputeHull(points, 6, &hull);
	/* The double build may weld the sheet flat; the float build keeps it. */
	TEST_CHECK(result == CD_OK || (CD_DOUBLE && result == CD_ERROR_DEGENERATE));
	if (hull != NULL)
	{
		cd3HullShape shape = {hull, CD3_TRANSFORM_IDENTITY};
		TEST_CHECK(cd3PointInHull(hull->centroid, shape));
		for (int i = 0; i < hull->vertexCount; ++i)
		{
			TEST_CHECK(cd3PointInHull(hull->vertices[i], shape));
		}
		/* Outside by far more than the band: off the sheet along its normal. */
		cd3Vec off = cd3Add(hull->centroid, cd3Scale(CD_R(1e-4), hull->planes[0].normal));
		TEST_CHECK(!cd3PointInHull(off, shape));
		cd3DestroyHull(hull);
	}
}

/* A segment piercing a sliver (two vertices 0.125 apart, the third 20 away) well inside
 * (barycentrics 0.51, 0.14, 0.35 at the crossing, in double): the crossing point, from a float
 * normal of the sliver, landed 3e-5 off its plane, beyond the touching tolerance (fuzz_query3). */
static void TestSegmentPiercingSliver(void)
{
	cd3Segment g = {cd3MakeVec(CD_R(-2.0), CD_R(-6.875), CD_R(0.0)),
					cd3MakeVec(CD_R(-11.75), CD_R(-4.375), CD_R(-12.125))};
	cd3Triangle t = {cd3MakeVec(CD_R(0.0), CD_R(0.5), CD_R(2.0)),
					 cd3MakeVec(CD_R(-12.375), CD_R(-12.5), CD_R(-12.5)),
					 cd3MakeVec(CD_R(-12.5), CD_R(-12.5), CD_R(-12.5))};
	cd3ClosestPoints r = cd3ClosestPointsTriangleSegment(t, g);
	TEST_CHECKF(r.distance == CD_R(0.0) && cd3VecEqual(r.pointA, r.pointB), "distance %.9g",
				(double)r.distance);
	TEST_CHECK(cd3OverlapTriangleSegment(t, g));
}

/* Closest point on each shape to random points, at several scales: finite, on the shape,
 * at the reference's distance, the point itself when inside, and no sampled point is closer. */
static void TestRandomClosestPoint(void)
{
	TestRng rng = TestRngMake(0x5EED3102u);
	const double scales[] = {1.0, 1e-6, 1e6, CD_DOUBLE ? 1e30 : 1e9, CD_DOUBLE ? 1e-30 : 1e-9};
	int insideCount = 0;
	for (int i = 0; i < 7000; ++i)
	{
		double scale = scales[i % 5];
		cd3ShapeType type = (cd3ShapeType)(i % (int)CD3_SHAPE_TYPE_COUNT);
		cd3Shape shape = RandomShape(&rng, type, scale);
		RShape r = RFromShape(&shape);
		cd3Vec p = cd3Scale((cdReal)scale, RandomVec(&rng, -4, 4));
		RVec rp = RFromVec(p);
		cd3Vec q = cd3ClosestPointOnShape(&shape, p);
		TEST_CHECKF(IsFiniteVec(q), "%s: non-finite", cd3GetShapeTypeName(type));
		RVec rq = RFromVec(q);
		double tolerance = REL_TOLERANCE * fmax(RShapeScale(&r), RMaxAbs(rp));
		RVec reference = RProject(&r, rp);
		double distance = RDist(rp, rq);
		double referenceDistance = RDist(rp, reference);
		/* On the shape. */
		TEST_CHECKF(RDist(RProject(&r, rq), rq) <= tolerance, "%s scale %g: result %g off the shape",
					cd3GetShapeTypeName(type), scale, RDist(RProject(&r, rq), rq));
		/* As close as the exact projection (which is unique for a convex set). */
		TEST_CHECKF(fabs(distance - referenceDistance) <= tolerance && RDist(rq, reference) <= 10 * tolerance,
					"%s scale %g: distance %.9g, reference %.9g", cd3GetShapeTypeName(type), scale, distance,
					referenceDistance);
		/* Inside a solid: the point itself. */
		bool solid = type != CD3_SHAPE_TRIANGLE && type != CD3_SHAPE_SEGMENT;
		if (solid && referenceDistance == 0.0)
		{
			++insideCount;
			TEST_CHECKF(cd3VecEqual(p, q), "%s: inside point moved", cd3GetShapeTypeName(type));
		}
		/* No sampled point of the shape is closer. */
		for (int k = 0; k < 40; ++k)
		{
			RVec sample = RSample(&r, &rng, reference, 2.0 * scale);
			TEST_CHECKF(RDist(rp, sample) >= distance - tolerance, "%s: sample closer by %g",
						cd3GetShapeTypeName(type), distance - RDist(rp, sample));
		}
	}
	TEST_CHECKF(insideCount > 200, "only %d inside cases", insideCount);
}

/* Random segment pairs and triangle-segment pairs: both points on their shapes, the distance
 * field consistent, within the reference bracket, and no sampled pair closer. */
static void TestRandomPairs(void)
{
	TestRng rng = TestRngMake(0x5EED3103u);
	const double scales[] = {1.0, 1e-6, 1e6, CD_DOUBLE ? 1e30 : 1e9, CD_DOUBLE ? 1e-30 : 1e-9};
	int zeroCount = 0;
	for (int i = 0; i < 3000; ++i)
	{
		double scale = scales[i % 5];
		bool triangle = (i / 5) % 2 == 0;
		cd3Shape a = RandomShape(&rng, triangle ? CD3_SHAPE_TRIANGLE : CD3_SHAPE_SEGMENT, scale);
		cd3Shape b = RandomShape(&rng, CD3_SHAPE_SEGMENT, scale);
		RShape ra = RFromShape(&a);
		if (TestRngInt(&rng, 3) == 0)
		{
			/* Through a point of A: (nearly, after rounding) intersecting. */
			cd3Vec through = RToVec(RSample(&ra, &rng, RMake(0, 0, 0), 0.0));
			cd3Vec direction = cd3Sub(b.segment.p2, b.segment.p1);
			cdReal before = (cdReal)TestRngRange(&rng, 0, 1);
			b.segment.p1 = cd3MulSub(through, before, direction);
			b.segment.p2 = cd3MulAdd(through, 1 - before, direction);
		}
		cd3ClosestPoints result = triangle ? cd3ClosestPointsTriangleSegment(a.triangle, b.segment)
										   : cd3ClosestPointsSegmentSegment(a.segment, b.segment);
		RShape rb = RFromShape(&b);
		double tolerance = REL_TOLERANCE * fmax(RShapeScale(&ra), RShapeScale(&rb));
		RVec pa = RFromVec(result.pointA), pb = RFromVec(result.pointB);
		TEST_CHECKF(IsFiniteVec(result.pointA) && IsFiniteVec(result.pointB) &&
						cdIsValidReal(result.distance),
					"non-finite");
		TEST_CHECKF(RDist(RProject(&ra, pa), pa) <= tolerance, "%s: pointA off A by %g",
					triangle ? "triangle" : "segment", RDist(RProject(&ra, pa), pa));
		TEST_CHECKF(RDist(RProject(&rb, pb), pb) <= tolerance, "pointB off B by %g",
					RDist(RProject(&rb, pb), pb));
		TEST_CHECK_NEAR(result.distance, RDist(pa, pb), tolerance);
		RDistance reference = RComputeDistance(&ra, &rb);
		TEST_CHECKF((double)result.distance >= reference.lower - tolerance &&
						(double)result.distance <= reference.upper + tolerance,
					"%s scale %g: distance %.9g, reference [%.9g, %.9g]", triangle ? "triangle" : "segment",
					scale, (double)result.distance, reference.lower, reference.upper);
		if (reference.upper <= tolerance)
		{
			++zeroCount;
		}
		/* Meeting within a few epsilon of their size: one common point at distance 0. */
		if (reference.upper <= 2.0 * CD_REAL_EPSILON * fmax(RShapeScale(&ra), RShapeScale(&rb)))
		{
			TEST_CHECKF(result.distance == 0 && cd3VecEqual(result.pointA, result.pointB),
						"%s meeting: distance %g", triangle ? "triangle" : "segment",
						(double)result.distance);
		}
		for (int k = 0; k < 40; ++k)
		{
			RVec sa = RSample(&ra, &rng, RMake(0, 0, 0), 0.0);
			RVec sb = RSample(&rb, &rng, RMake(0, 0, 0), 0.0);
			TEST_CHECKF(RDist(sa, sb) >= (double)result.distance - tolerance, "sampled pair closer by %g",
						(double)result.distance - RDist(sa, sb));
		}
	}
	TEST_CHECKF(zeroCount > 50, "only %d intersecting pairs", zeroCount);
}

/* Far from the origin: a unit-sized problem offset by 1e6 (float) or 1e12 (double) stays finite
 * and accurate to the input's own resolution. */
static void TestFarFromOrigin(void)
{
	TestRng rng = TestRngMake(0x5EED3104u);
	double offset = CD_DOUBLE ? 1e12 : 1e6;
	cd3Vec shift = cd3MakeVec((cdReal)offset, (cdReal)-offset, (cdReal)(0.5 * offset));
	for (int i = 0; i < 1400; ++i)
	{
		cd3ShapeType type = (cd3ShapeType)(i % (int)CD3_SHAPE_TYPE_COUNT);
		cd3Shape local = RandomShape(&rng, type, 1.0);
		cd3Shape shape = TransformShape(&local, (cd3Transform){shift, CD3_QUAT_IDENTITY});
		cd3Vec p = cd3Add(shift, RandomVec(&rng, -4, 4));
		cd3Vec q = cd3ClosestPointOnShape(&shape, p);
		RShape r = RFromShape(&shape);
		RVec rq = RFromVec(q);
		double tolerance = 8.0 * CD_REAL_EPSILON * offset;
		TEST_CHECKF(IsFiniteVec(q), "non-finite");
		TEST_CHECKF(RDist(RProject(&r, rq), rq) <= tolerance, "%s: off the shape by %g",
					cd3GetShapeTypeName(type), RDist(RProject(&r, rq), rq));
		TEST_CHECKF(fabs(RDist(rq, RFromVec(p)) - RDist(RProject(&r, RFromVec(p)), RFromVec(p))) <= tolerance,
					"%s: distance off", cd3GetShapeTypeName(type));
	}
}

/* A sliver triangle 2L long and 2W wide at one end (W / L = 1e-9): points on its long edge ac
 * are their own closest points. Ericson's ab.bp taken as ab.ap - ab.ab cancelled to round-off
 * (2 W^2 against L^2) and a point near b came back as vertex b, W away (fuzz_manifold3, double
 * build: L = 1e30, W = 1e21, corpus regression-manifold3-double-sphere-sliver-triangle). */
static void TestSliverTriangleLongEdge(void)
{
	double lengths[2] = {1e9, CD_DOUBLE ? 1e30 : 1e20};
	for (int k = 0; k < 2; ++k)
	{
		double L = lengths[k], W = 1e-9 * L;
		cd3Triangle t = {
			{(cdReal)L, CD_R(0.0), (cdReal)(-2.0 * W)}, CD3_VEC_ZERO, {(cdReal)-L, CD_R(0.0), CD_R(0.0)}};
		for (int i = 1; i < 8; ++i)
		{
			double f = i / 8.0; /* along ac from a */
			cd3Vec p = cd3Lerp(t.a, t.c, (cdReal)f);
			double moved = (double)cd3VecDistance(cd3ClosestPointOnTriangle(t, p), p);
			TEST_CHECKF(moved <= 64.0 * (double)CD_REAL_EPSILON * L, "L %g, point %g along ac: moved by %.3g",
						L, f, moved);
		}
	}
}

int main(void)
{
	TEST_RUN(TestSphereCapsuleSegment);
	TEST_RUN(TestAabbBoxPlane);
	TEST_RUN(TestTriangleRegions);
	TEST_RUN(TestSegmentSegmentExact);
	TEST_RUN(TestTriangleSegmentExact);
	TEST_RUN(TestNearlyParallelSegments);
	TEST_RUN(TestThinTriangles);
	TEST_RUN(TestNeedleTriangles);
	TEST_RUN(TestPointInHullWedge);
	TEST_RUN(TestPointInHullSheet);
	TEST_RUN(TestSegmentPiercingSliver);
	TEST_RUN(TestRandomClosestPoint);
	TEST_RUN(TestRandomPairs);
	TEST_RUN(TestFarFromOrigin);
	TEST_RUN(TestSliverTriangleLongEdge);
	return TEST_SUMMARY();
}
