/* Tests of the 2D contact manifolds (manifold2.h): exact cases for every pair family, then
 * properties over thousands of random pairs of every type (rounded polygons included):
 * - each point lies midway between the surfaces: point -+ separation/2 * normal is on A's and on
 *   B's surface (within TOL of the shape, and leaving the shape when moved on along the normal);
 * - the normal is a unit vector from A to B;
 * - the smallest separation is the distance (cd2Distance) for separated pairs and minus the
 *   penetration depth (an independent double-precision search over directions) for overlapping
 *   ones; no points beyond the speculative distance, points for every pair within it;
 * - symmetry of the dispatcher, invariance under a rigid motion, feature ids stable under tiny
 *   motions;
 * - a box, a circle and a capsule sliding along a chain of collinear segments only ever get the
 *   straight-up normal (and plain two-sided segments do show the ghost normals the chain avoids).
 * Pairs within BAND of a decision boundary (touching, the speculative distance) are skipped for
 * the checks that depend on that decision. */
#include "collide/manifold2.h"
#include "../src/query/sat2_separation.h" /* internal: the separating-axis scan */
#include "random_shapes2.h"
#include "test.h"

#include <math.h>
#include <string.h>

#if CD_DOUBLE
#define TOL 1e-6
#else
#define TOL 2e-4
#endif

/* The reference-edge choice may favour A's edge by up to the flip tolerance (0.1 linear slop). */
#define FLIP_SLACK (0.1 * 0.005 + TOL)
#define BAND 1e-3
#define SPECULATIVE 0.1

static cd2Vec V(double x, double y)
{
	return cd2MakeVec((cdReal)x, (cdReal)y);
}

static cd2Polygon BoxPolygon(double cx, double cy, double hx, double hy, double angle)
{
	cd2Box box = {V(cx, cy), V(hx, hy), cd2MakeRot((cdReal)angle)};
	cd2Polygon polygon;
	cdResult result = cd2MakeBoxPolygon(box, &polygon);
	TEST_CHECK(result == CD_OK);
	return polygon;
}

static double MinSeparation(const cd2Manifold* m)
{
	double s = INFINITY;
	for (int i = 0; i < m->pointCount; ++i)
	{
		s = fmin(s, (double)m->points[i].separation);
	}
	return s;
}

static void PrintManifold(const cd2Manifold* m)
{
	fprintf(stderr, "  manifold: normal (%.9g %.9g) count %d\n", (double)m->normal.x, (double)m->normal.y,
			m->pointCount);
	for (int i = 0; i < m->pointCount; ++i)
	{
		fprintf(stderr, "    point (%.9g %.9g) separation %.9g id 0x%x\n", (double)m->points[i].point.x,
				(double)m->points[i].point.y, (double)m->points[i].separation, (unsigned)m->points[i].id);
	}
}

/* ---- exact cases ------------------------------------------------------------------------------ */

static void CheckPoint(const cd2Manifold* m, int i, double x, double y, double separation)
{
	TEST_CHECKF(i < m->pointCount, "point %d missing", i);
	if (i >= m->pointCount)
	{
		return;
	}
	TEST_CHECKF(fabs((double)m->points[i].point.x - x) <= TOL &&
					fabs((double)m->points[i].point.y - y) <= TOL &&
					fabs((double)m->points[i].separation - separation) <= TOL,
				"point %d: (%.9g %.9g) separation %.9g, expected (%g %g) %g", i, (double)m->points[i].point.x,
				(double)m->points[i].point.y, (double)m->points[i].separation, x, y, separation);
}

static void CheckNormal(const cd2Manifold* m, double x, double y)
{
	TEST_CHECKF(fabs((double)m->normal.x - x) <= TOL && fabs((double)m->normal.y - y) <= TOL,
				"normal (%.9g %.9g), expected (%g %g)", (double)m->normal.x, (double)m->normal.y, x, y);
}

/* Points sorted by x for the exact checks (the order of the two points is not part of the API). */
static cd2Manifold SortedByX(cd2Manifold m)
{
	if (m.pointCount == 2 && m.points[1].point.x < m.points[0].point.x)
	{
		cd2ManifoldPoint t = m.points[0];
		m.points[0] = m.points[1];
		m.points[1] = t;
	}
	return m;
}

static void TestBoxes(void)
{
	cd2Polygon ground = BoxPolygon(0, -1, 3, 1, 0); /* top face y = 0 */

	/* resting, penetrating by 0.01: two points at the bottom corners, midway at y = -0.005 */
	cd2Polygon box = BoxPolygon(0, 0.49, 0.5, 0.5, 0);
	cd2Manifold m = SortedByX(cd2CollidePolygonPolygon(&ground, &box, CD_R(0.0)));
	TEST_CHECK(m.pointCount == 2);
	CheckNormal(&m, 0, 1);
	CheckPoint(&m, 0, -0.5, -0.005, -0.01);
	CheckPoint(&m, 1, 0.5, -0.005, -0.01);
	TEST_CHECK(m.points[0].id != m.points[1].id);

	/* the same pair the other way round: normal down, same points */
	cd2Manifold r = SortedByX(cd2CollidePolygonPolygon(&box, &ground, CD_R(0.0)));
	TEST_CHECK(r.pointCount == 2);
	CheckNormal(&r, 0, -1);
	CheckPoint(&r, 0, -0.5, -0.005, -0.01);
	CheckPoint(&r, 1, 0.5, -0.005, -0.01);

	/* touching exactly, then apart by 0.01: reported only within the speculative distance */
	box = BoxPolygon(0, 0.5, 0.5, 0.5, 0);
	m = cd2CollidePolygonPolygon(&ground, &box, CD_R(0.0));
	TEST_CHECK(m.pointCount == 2);
	CheckPoint(&m, 0, m.points[0].point.x > 0 ? 0.5 : -0.5, 0, 0);
	box = BoxPolygon(0, 0.51, 0.5, 0.5, 0);
	m = cd2CollidePolygonPolygon(&ground, &box, CD_R(0.0));
	TEST_CHECK(m.pointCount == 0);
	m = SortedByX(cd2CollidePolygonPolygon(&ground, &box, CD_R(0.02)));
	TEST_CHECK(m.pointCount == 2);
	CheckNormal(&m, 0, 1);
	CheckPoint(&m, 0, -0.5, 0.005, 0.01);
	CheckPoint(&m, 1, 0.5, 0.005, 0.01);
	m = cd2CollidePolygonPolygon(&ground, &box, CD_R(0.005));
	TEST_CHECK(m.pointCount == 0);

	/* deep: sunk by 0.3 */
	box = BoxPolygon(0, 0.2, 0.5, 0.5, 0);
	m = SortedByX(cd2CollidePolygonPolygon(&ground, &box, CD_R(0.0)));
	TEST_CHECK(m.pointCount == 2);
	CheckNormal(&m, 0, 1);
	CheckPoint(&m, 0, -0.5, -0.15, -0.3);

	/* overhanging the ground's right end: clipped at x = 3 */
	box = BoxPolygon(3.2, 0.49, 0.5, 0.5, 0);
	m = SortedByX(cd2CollidePolygonPolygon(&ground, &box, CD_R(0.0)));
	TEST_CHECK(m.pointCount == 2);
	CheckNormal(&m, 0, 1);
	CheckPoint(&m, 0, 2.7, -0.005, -0.01);
	CheckPoint(&m, 1, 3.0, -0.005, -0.01);

	/* a box turned 45 degrees, corner down 0.02 into the ground: one point */
	double h = 0.5 * sqrt(2.0);
	box = BoxPolygon(0.25, h - 0.02, 0.5, 0.5, 0.25 * 3.14159265358979);
	m = cd2CollidePolygonPolygon(&ground, &box, CD_R(0.0));
	TEST_CHECK(m.pointCount == 1);
	CheckNormal(&m, 0, 1);
	CheckPoint(&m, 0, 0.25, -0.01, -0.02);

	/* corner to corner, apart along the diagonal: one point, normal along the gap */
	cd2Polygon a = BoxPolygon(0, 0, 0.5, 0.5, 0), b = BoxPolygon(1.03, 1.04, 0.5, 0.5, 0);
	m = cd2CollidePolygonPolygon(&a, &b, CD_R(0.1));
	TEST_CHECK(m.pointCount == 1);
	CheckNormal(&m, 0.6, 0.8);
	CheckPoint(&m, 0, 0.515, 0.52, 0.05);

	/* the dispatcher takes AABBs and boxes as polygons */
	cd2Aabb aabb = {V(-3, -2), V(3, 0)};
	cd2Box obox = {V(0, 0.49), V(0.5, 0.5), CD2_ROT_IDENTITY};
	cd2Shape sa = cd2MakeAabbShape(aabb), sb = cd2MakeBoxShape(obox);
	m = SortedByX(cd2Collide(&sa, &sb, CD_R(0.0)));
	TEST_CHECK(m.pointCount == 2);
	CheckNormal(&m, 0, 1);
	CheckPoint(&m, 0, -0.5, -0.005, -0.01);
}

static void TestRoundedPolygons(void)
{
	/* A rounded box (core [-1,1]x[-1,0], radius 0.1) under a rounded box (radius 0.05), cores apart
	 * by 0.1: the surfaces overlap by 0.05. */
	cd2Box core = {V(0, -0.5), V(1, 0.5), CD2_ROT_IDENTITY};
	cd2Polygon ground, box;
	TEST_CHECK(cd2MakeRoundedBoxPolygon(core, CD_R(0.1), &ground) == CD_OK);
	cd2Box top = {V(0, 0.6), V(0.5, 0.5), CD2_ROT_IDENTITY};
	TEST_CHECK(cd2MakeRoundedBoxPolygon(top, CD_R(0.05), &box) == CD_OK);
	cd2Manifold m = SortedByX(cd2CollidePolygonPolygon(&ground, &box, CD_R(0.0)));
	TEST_CHECK(m.pointCount == 2);
	CheckNormal(&m, 0, 1);
	CheckPoint(&m, 0, -0.5, 0.075, -0.05);
	CheckPoint(&m, 1, 0.5, 0.075, -0.05);

	/* a circle against the rounded corner (1,0): center at distance 1 along (0.6, 0.8), surfaces
	 * apart by 0.05 */
	cd2Circle circle = {V(1.6, 0.8), CD_R(0.85)};
	m = cd2CollideCirclePolygon(circle, &ground, CD_R(0.1));
	TEST_CHECK(m.pointCount == 1);
	CheckNormal(&m, -0.6, -0.8); /* from the circle to the polygon */
	CheckPoint(&m, 0, 1.0 + 0.6 * 0.125, 0.8 * 0.125, 0.05);
	TEST_CHECK(cd2CollideCirclePolygon(circle, &ground, CD_R(0.0)).pointCount == 0);
	circle.radius = CD_R(0.8);
	TEST_CHECK(cd2CollideCirclePolygon(circle, &ground, CD_R(0.05)).pointCount == 0);
	TEST_CHECK(cd2CollideCirclePolygon(circle, &ground, CD_R(0.11)).pointCount == 1);
}

static void TestCircles(void)
{
	cd2Polygon ground = BoxPolygon(0, -1, 3, 1, 0);
	cd2Circle a = {V(0, 0.9), CD_R(1.0)};
	cd2Manifold m = cd2CollideCirclePolygon(a, &ground, CD_R(0.0));
	TEST_CHECK(m.pointCount == 1);
	CheckNormal(&m, 0, -1);
	CheckPoint(&m, 0, 0, -0.05, -0.1);

	/* center inside the polygon, nearest the top face */
	a.center = V(1, -0.2);
	a.radius = CD_R(0.1);
	m = cd2CollideCirclePolygon(a, &ground, CD_R(0.0));
	TEST_CHECK(m.pointCount == 1);
	CheckNormal(&m, 0, -1);
	CheckPoint(&m, 0, 1, -0.15, -0.3);

	/* against the corner (3, 0) */
	a.center = V(3.6, 0.8);
	a.radius = CD_R(1.1);
	m = cd2CollideCirclePolygon(a, &ground, CD_R(0.0));
	TEST_CHECK(m.pointCount == 1);
	CheckNormal(&m, -0.6, -0.8);
	CheckPoint(&m, 0, 3.0 - 0.03, -0.04, -0.1);

	/* circles: touching, apart, coincident */
	cd2Circle b = {V(3, 4), CD_R(2.0)}, c = {V(0, 0), CD_R(3.0)};
	m = cd2CollideCircleCircle(c, b, CD_R(0.0));
	TEST_CHECK(m.pointCount == 1);
	CheckNormal(&m, 0.6, 0.8);
	CheckPoint(&m, 0, 1.8, 2.4, 0);
	c.radius = CD_R(2.9);
	TEST_CHECK(cd2CollideCircleCircle(c, b, CD_R(0.0)).pointCount == 0);
	m = cd2CollideCircleCircle(c, b, CD_R(0.2));
	TEST_CHECK(m.pointCount == 1 && fabs((double)m.points[0].separation - 0.1) <= TOL);
	m = cd2CollideCircleCircle(b, b, CD_R(0.0));
	TEST_CHECK(m.pointCount == 1 && fabs((double)m.points[0].separation + 4.0) <= TOL);
	TEST_CHECK(fabs((double)cd2Length(m.normal) - 1.0) <= TOL);

	/* circle and capsule side, circle and segment end */
	cd2Capsule capsule = {V(-2, 0), V(2, 0), CD_R(0.5)};
	cd2Circle d = {V(1, 1.2), CD_R(0.8)};
	m = cd2CollideCircleCapsule(d, capsule, CD_R(0.0));
	TEST_CHECK(m.pointCount == 1);
	CheckNormal(&m, 0, -1);
	CheckPoint(&m, 0, 1, 0.45, -0.1);
	cd2Segment segment = {V(-2, 0), V(2, 0)};
	cd2Circle e = {V(2.3, 0.4), CD_R(0.6)};
	m = cd2CollideCircleSegment(e, segment, CD_R(0.0));
	TEST_CHECK(m.pointCount == 1);
	CheckNormal(&m, -0.6, -0.8);
	CheckPoint(&m, 0, 2.0 - 0.6 * 0.05, -0.8 * 0.05, -0.1);
	/* on the segment's line beyond its end: the normal runs along it */
	e.center = V(2.5, 0);
	m = cd2CollideCircleSegment(e, segment, CD_R(0.0));
	TEST_CHECK(m.pointCount == 1);
	CheckNormal(&m, -1, 0);
}

static void TestCapsulesAndSegments(void)
{
	cd2Polygon ground = BoxPolygon(0, -1, 3, 1, 0);
	cd2Capsule capsule = {V(-1, 0.4), V(1, 0.4), CD_R(0.5)};
	cd2Manifold m = SortedByX(cd2CollideCapsulePolygon(capsule, &ground, CD_R(0.0)));
	TEST_CHECK(m.pointCount == 2);
	CheckNormal(&m, 0, -1);
	CheckPoint(&m, 0, -1, -0.05, -0.1);
	CheckPoint(&m, 1, 1, -0.05, -0.1);

	/* capsules parallel, overlapping by 0.1 over x in [0, 1] */
	cd2Capsule a = {V(-2, 0), V(1, 0), CD_R(0.5)}, b = {V(0, 0.9), V(3, 0.9), CD_R(0.5)};
	m = SortedByX(cd2CollideCapsuleCapsule(a, b, CD_R(0.0)));
	TEST_CHECK(m.pointCount == 2);
	CheckNormal(&m, 0, 1);
	CheckPoint(&m, 0, 0, 0.45, -0.1);
	CheckPoint(&m, 1, 1, 0.45, -0.1);

	/* collinear capsules end to end, 0.2 apart at the cores: overlapping by 0.8 along the axis */
	cd2Capsule c = {V(1.2, 0), V(4, 0), CD_R(0.5)};
	m = cd2CollideCapsuleCapsule(a, c, CD_R(0.0));
	TEST_CHECK(m.pointCount == 1);
	CheckNormal(&m, 1, 0);
	CheckPoint(&m, 0, 1.1, 0, -0.8);

	/* zero-length capsule is a circle, apart by 0.4 */
	cd2Capsule dot = {V(0, 1.3), V(0, 1.3), CD_R(0.4)};
	m = cd2CollideCapsuleCapsule(a, dot, CD_R(0.5));
	TEST_CHECK(m.pointCount == 1);
	CheckNormal(&m, 0, 1);
	CheckPoint(&m, 0, 0, 0.7, 0.4);
	TEST_CHECK(cd2CollideCapsuleCapsule(a, dot, CD_R(0.3)).pointCount == 0);

	/* segments: crossing (distance 0), apart, collinear within the speculative distance */
	cd2Segment s1 = {V(-1, 0), V(1, 0)}, s2 = {V(0, -1), V(0, 1)}, s3 = {V(0, 0.5), V(2, 0.5)},
			   s4 = {V(1.05, 0), V(3, 0)};
	m = cd2CollideSegmentSegment(s1, s2, CD_R(0.0));
	TEST_CHECK(m.pointCount >= 1 && MinSeparation(&m) <= 0.0);
	TEST_CHECK(cd2CollideSegmentSegment(s1, s3, CD_R(0.0)).pointCount == 0);
	m = SortedByX(cd2CollideSegmentSegment(s1, s3, CD_R(0.6)));
	TEST_CHECK(m.pointCount == 2);
	CheckNormal(&m, 0, 1);
	CheckPoint(&m, 0, 0, 0.25, 0.5);
	CheckPoint(&m, 1, 1, 0.25, 0.5);
	TEST_CHECK(cd2CollideSegmentSegment(s1, s4, CD_R(0.0)).pointCount == 0);
	m = cd2CollideSegmentSegment(s1, s4, CD_R(0.1));
	TEST_CHECK(m.pointCount == 1);
	CheckNormal(&m, 1, 0);
	CheckPoint(&m, 0, 1.025, 0, 0.05);

	/* a segment across the top of the ground polygon */
	cd2Segment across = {V(-1, 0.01), V(1, -0.01)};
	m = cd2CollidePolygonSegment(&ground, across, CD_R(0.0));
	TEST_CHECK(m.pointCount == 1);
	CheckNormal(&m, 0, 1);
	CheckPoint(&m, 0, 1, -0.005, -0.01);
}

/* A triangle's vertex near the long edge of a thin triangle whose other edges wrap around it: A's
 * max-separation edge is not at its closest vertex (A's separations are all negative), so the
 * closest features must be searched beyond it. */
static void TestWrappedVertex(void)
{
	cd2Vec pa[3] = {V(-0.228804588, -0.136747122), V(0.0212139077, 0.233639941),
					V(-0.138902396, 0.286263257)};
	cd2Vec pb[3] = {V(0.0100767612, -0.370180339), V(0.273660183, 1.59275758), V(0.0614802837, 1.22982275)};
	cd2Polygon a, b;
	TEST_CHECK(cd2MakePolygon(pa, 3, &a) == CD_OK && cd2MakePolygon(pb, 3, &b) == CD_OK);
	cd2Shape sa = cd2MakePolygonShape(&a), sb = cd2MakePolygonShape(&b);
	cd2ClosestPoints closest = cd2Distance(&sa, &sb);
	TEST_CHECK(closest.distance > CD_R(0.005) && closest.distance < CD_R(0.01));
	cd2Manifold m = cd2CollidePolygonPolygon(&a, &b, CD_R(0.02));
	TEST_CHECK(m.pointCount >= 1);
	TEST_CHECK_NEAR(MinSeparation(&m), (double)closest.distance, TOL);
	cd2Vec gap = cd2Normalize(cd2Sub(closest.pointB, closest.pointA));
	CheckNormal(&m, (double)gap.x, (double)gap.y);
}

/* ---- fuzzer findings (fuzz_manifold2, the values of its inputs) -------------------------------- */

static double DistanceToShape(const cd2Shape* s, cd2Vec p);

/* Each point lies midway: point -+ separation/2 * normal within `tolerance` of A / B (0 inside a
 * solid); the smallest separation is `separation` within `tolerance`. */
static void CheckFinding(const char* what, const cd2Shape* a, const cd2Shape* b, const cd2Manifold* m,
						 double separation, double tolerance)
{
	TEST_CHECKF(m->pointCount >= 1, "%s: no points", what);
	TEST_CHECKF(fabs((double)cd2Length(m->normal) - 1.0) <= TOL, "%s: normal of length %.9g", what,
				(double)cd2Length(m->normal));
	for (int i = 0; i < m->pointCount; ++i)
	{
		const cd2ManifoldPoint* p = &m->points[i];
		double offA = DistanceToShape(a, cd2MulAdd(p->point, CD_R(-0.5) * p->separation, m->normal));
		double offB = DistanceToShape(b, cd2MulAdd(p->point, CD_R(0.5) * p->separation, m->normal));
		TEST_CHECKF(offA <= tolerance && offB <= tolerance,
					"%s: point %d (%.9g %.9g) separation %.9g is %.3g off A, %.3g off B", what, i,
					(double)p->point.x, (double)p->point.y, (double)p->separation, offA, offB);
	}
	if (m->pointCount >= 1)
	{
		TEST_CHECKF(fabs(MinSeparation(m) - separation) <= tolerance,
					"%s: smallest separation %.9g, expected %.9g", what, MinSeparation(m), separation);
	}
	if (m->pointCount < 1 || fabs(MinSeparation(m) - separation) > tolerance)
	{
		PrintManifold(m);
	}
}

static cd2Vec Turned(double x, double y, double angle, cd2Vec origin)
{
	double c = cos(angle), s = sin(angle);
	return cd2Add(origin, V(c * x - s * y, s * x + c * y));
}

/* Perpendicular capsules (and segments) whose axes share an end point: the cores touch there, so
 * the shapes overlap by the sum of the radii (fuzz finding manifold2-capsules-shared-end: the far
 * end of the upright capsule was kept, at a positive separation, and the pair got no contact).
 * Turned through every angle and moved off the origin, the shared end staying exact. */
static void TestSharedEnds(void)
{
	cd2Capsule a = {V(-0.875, 0), V(0, 0), CD_R(0.0)}, b = {V(0, 0), V(0, 0.625), CD_R(0.5)};
	cd2Shape sa = cd2MakeCapsuleShape(a), sb = cd2MakeCapsuleShape(b);
	cd2Manifold m = cd2Collide(&sa, &sb, CD_R(0.0));
	CheckFinding("shared end", &sa, &sb, &m, -0.5, TOL);
	/* Both faces separate by 0 (a tie): B's upright core lies beyond the side line of A's face,
	 * so B's face holds the contact: A's end pushed into B's side by 0.5, midway at x = -0.25. */
	TEST_CHECK(m.pointCount == 1);
	CheckNormal(&m, 1, 0);
	CheckPoint(&m, 0, -0.25, 0, -0.5);
	m = cd2Collide(&sb, &sa, CD_R(0.0));
	CheckFinding("shared end (b, a)", &sb, &sa, &m, -0.5, TOL);

	/* manifold2-capsules-shared-end-symmetry, at scale 1 and at the fuzzer's 1e9: collide(b, a)
	 * had no points, collide(a, b) two (the cores touch: 1.625 deep). */
	for (int k = 0; k < 2; ++k)
	{
		double scale = k == 0 ? 1.0 : 1e9;
		cd2Capsule c = {V(-scale, -scale), V(-scale, scale), (cdReal)(0.625 * scale)};
		cd2Capsule d = {V(-0.5 * scale, -scale), V(-scale, -scale), (cdReal)scale};
		cd2Shape sc = cd2MakeCapsuleShape(c), sd = cd2MakeCapsuleShape(d);
		m = cd2Collide(&sc, &sd, CD_R(0.0));
		CheckFinding("shared end symmetry (a, b)", &sc, &sd, &m, -1.625 * scale, TOL * scale);
		m = cd2Collide(&sd, &sc, CD_R(0.0));
		CheckFinding("shared end symmetry (b, a)", &sd, &sc, &m, -1.625 * scale, TOL * scale);
	}

	int cases = 0;
	for (int step = 0; step < 720; ++step)
	{
		double angle = step * (3.14159265358979 / 360.0);
		cd2Vec origin = V(step % 3 == 0 ? 0.0 : 0.3125, step % 2 == 0 ? 0.0 : -0.6875);
		cd2Vec shared = origin;
		cd2Vec farA = Turned(-0.875, 0, angle, origin), farB = Turned(0, 0.625, angle, origin);
		cd2Capsule ca = {farA, shared, CD_R(0.25)}, cb = {shared, farB, CD_R(0.5)};
		cd2Segment ga = {farA, shared}, gb = {shared, farB};
		cd2Shape capA = cd2MakeCapsuleShape(ca), capB = cd2MakeCapsuleShape(cb);
		cd2Shape segA = cd2MakeSegmentShape(ga), segB = cd2MakeSegmentShape(gb);
		char what[96];
		snprintf(what, sizeof what, "capsules at %.4f rad", angle);
		m = cd2CollideCapsuleCapsule(ca, cb, CD_R(0.0));
		CheckFinding(what, &capA, &capB, &m, -0.75, TOL);
		m = cd2CollideCapsuleCapsule(cb, ca, CD_R(0.0));
		CheckFinding(what, &capB, &capA, &m, -0.75, TOL);
		snprintf(what, sizeof what, "capsule and segment at %.4f rad", angle);
		m = cd2CollideCapsuleSegment(cb, ga, CD_R(0.0));
		CheckFinding(what, &capB, &segA, &m, -0.5, TOL);
		m = cd2CollideCapsuleSegment(ca, gb, CD_R(0.0));
		CheckFinding(what, &capA, &segB, &m, -0.25, TOL);
		/* Touching segments: turned, their separation is a rounding error either side of 0, so
		 * they are asked with a speculative distance of TOL (unturned, with none). */
		cdReal touching = step == 0 ? CD_R(0.0) : (cdReal)TOL;
		snprintf(what, sizeof what, "segments at %.4f rad", angle);
		m = cd2CollideSegmentSegment(ga, gb, touching);
		CheckFinding(what, &segA, &segB, &m, 0.0, TOL);
		m = cd2CollideSegmentSegment(gb, ga, touching);
		CheckFinding(what, &segB, &segA, &m, 0.0, TOL);
		++cases;
	}
	TEST_CHECK(cases == 720);
}

/* manifold2-box-capsule-overlap-positive: the capsule's axis points straight away from the box
 * face it faces, so its core edge (offset sideways by the radius) fell beyond the face's side lines
 * and the far end was kept, at separation +5.35 though the box sits inside the capsule. The core's
 * near end is outside the face x . axis = 1.25 by d, so the shapes overlap by radius - d along the
 * face normal. */
static void TestBoxAlongCapsule(void)
{
	double h = 0.5 * sqrt(2.0);
	cd2Box box = {V(1.875, -0.5), V(1.25, 1.75), {(cdReal)-h, (cdReal)-h}};
	cd2Capsule capsule = {V(-1.5, -1.5), V(-12.375, -12.375), CD_R(11.875)};
	cd2Shape sa = cd2MakeBoxShape(box), sb = cd2MakeCapsuleShape(capsule);
	double axisX = -h, axisY = -h; /* the box's x axis: the face normal towards the capsule */
	double d = axisX * (-1.5 - 1.875) + axisY * (-1.5 + 0.5) - 1.25;
	double depth = 11.875 - d;
	cd2Manifold m = cd2Collide(&sa, &sb, CD_R(12.375));
	CheckFinding("box along a capsule", &sa, &sb, &m, -depth, TOL);
	TEST_CHECK(m.pointCount == 1);
	CheckNormal(&m, axisX, axisY);
	/* midway between the face point (core end moved back by d) and the capsule's surface point */
	double along = 0.5 * (11.875 + d);
	CheckPoint(&m, 0, -1.5 + along * -axisX, -1.5 + along * -axisY, -depth);
	cd2Manifold r = cd2Collide(&sb, &sa, CD_R(12.375));
	CheckFinding("capsule along a box", &sb, &sa, &r, -depth, TOL);
	CheckNormal(&r, -axisX, -axisY);
}

/* manifold2-far-speculative-box-box and -aabb-box: shapes 1e9 apart with a speculative distance of
 * 1e9. In float a box of size 9 at y = 1e9 has its corners rounded to 64: its faces are degenerate,
 * a closest point was taken as inside one, and that face's tilted normal gave the contact a
 * separation of 0.89e9 (0.71e9) along it with the point 4.5e8 off the box. The one point along the
 * gap is the contact: separation the distance, surfaces within round-off of the scale. */
static void TestFarSpeculative(void)
{
	cd2Box a = {V(0.875, -1), V(9.125, 9.125), {CD_R(0.707106829), CD_R(0.707106829)}};
	cd2Box b = {V(3.25, 1e9), V(9.125, 9.125), {CD_R(-0.44721359), CD_R(0.89442718)}};
	cd2Shape sa = cd2MakeBoxShape(a), sb = cd2MakeBoxShape(b);
	/* the lowest corner of b (offsets 9.125 (c + s) below its centre) over the highest of a */
	double gap = 1e9 - 9.125 * (0.89442718 + 0.44721359) - (-1.0 + 9.125 * sqrt(2.0));
	cd2Manifold m = cd2Collide(&sa, &sb, CD_R(1e9));
	CheckFinding("far boxes", &sa, &sb, &m, gap, 1e-6 * 1e9);
	CheckNormal(&m, 0, 1);
	m = cd2Collide(&sb, &sa, CD_R(1e9));
	CheckFinding("far boxes (b, a)", &sb, &sa, &m, gap, 1e-6 * 1e9);
	CheckNormal(&m, 0, -1);

	cd2Aabb aabb = {V(-1.25000001e-08, -3.74999987e-09), V(1.125e-08, 9.99999994e-09)};
	cd2Box tiny = {
		V(-1e9, 9.99999972e-10), V(6.50000018e-08, 4.99999997e-09), {CD_R(-0.707106769), CD_R(-0.707106769)}};
	sa = cd2MakeAabbShape(aabb);
	sb = cd2MakeBoxShape(tiny);
	m = cd2Collide(&sa, &sb, CD_R(1e9));
	CheckFinding("far AABB and box", &sa, &sb, &m, 1e9, 1e-6 * 1e9);
	CheckNormal(&m, -1, 0);
	m = cd2Collide(&sb, &sa, CD_R(1e9));
	CheckFinding("far box and AABB", &sb, &sa, &m, 1e9, 1e-6 * 1e9);
	CheckNormal(&m, 1, 0);
}

/* manifold2-huge-capsules-surface: a small capsule inside a capsule of radius 1e9 whose axis
 * crosses it; the point was 2.9e8 off the small one. In float the axes' crossing is known to about
 * 64 only, so the depth is the big radius within round-off of the scale. */
static void TestCapsuleInHugeCapsule(void)
{
	cd2Capsule a = {V(-0.174999997, -1.1875), V(-1.03750002, 0.125), CD_R(0.137500003)};
	cd2Capsule b = {V(0, 9.99999972e-10), V(-1e9, -1e9), CD_R(1e9)};
	cd2Shape sa = cd2MakeCapsuleShape(a), sb = cd2MakeCapsuleShape(b);
	cd2Manifold m = cd2Collide(&sa, &sb, CD_R(1e9));
	CheckFinding("capsule in a huge capsule", &sa, &sb, &m, -1e9, 1e-6 * 1e9);
	m = cd2Collide(&sb, &sa, CD_R(1e9));
	CheckFinding("huge capsule around a capsule", &sb, &sa, &m, -1e9, 1e-6 * 1e9);

	/* A capsule of radius 5e8 standing upright across a long segment (its lower end 0.54 under
	 * it): its core edge offset sideways by the radius reached past the segment's end, the
	 * deepest vertex's point was clipped there, and the pair got no contact. Deep by the radius
	 * (plus 0.54, below round-off at this scale). */
	cd2Capsule upright = {V(7.875, 5e8), V(-9.25, -7.625), CD_R(5e8)};
	cd2Capsule across = {V(5e8, -11.625), V(-1e9, 2), CD_R(0.0)};
	sa = cd2MakeCapsuleShape(upright);
	sb = cd2MakeCapsuleShape(across);
	m = cd2Collide(&sa, &sb, CD_R(0.0));
	CheckFinding("upright capsule across a segment", &sa, &sb, &m, -5e8, 1e-6 * 1e9);
	m = cd2Collide(&sb, &sa, CD_R(0.0));
	CheckFinding("segment across an upright capsule", &sb, &sa, &m, -5e8, 1e-6 * 1e9);
}

static double ReferenceSeparation(const cd2Shape* a, const cd2Shape* b);

/* A thin triangle deep inside a rounded quad (radius 12.5): the quad's incident edge lies beyond
 * the side lines of the triangle's reference edge, and the one end kept must be the deeper one
 * (the other end gave -13.4 for a depth of 20.5, its point 0.68 off the triangle). Found by
 * fuzz_manifold2 while the end nearer to the reference edge was kept. */
static void TestTriangleInRoundedQuad(void)
{
	cd2Vec pa[3] = {V(-12, -12.5), V(-1, -1), V(-0.25, 0.375)};
	cd2Vec pb[4] = {V(-12.5, -12.5), V(0.375, -12.5), V(-0.25, 1.125), V(-11.875, -0.75)};
	cd2Polygon a, b;
	TEST_CHECK(cd2MakePolygon(pa, 3, &a) == CD_OK && cd2MakeRoundedPolygon(pb, 4, CD_R(12.5), &b) == CD_OK);
	cd2Shape sa = cd2MakePolygonShape(&a), sb = cd2MakePolygonShape(&b);
	double depth = -ReferenceSeparation(&sa, &sb);
	TEST_CHECK(depth > 20.0);
	cd2Manifold m = cd2Collide(&sa, &sb, CD_R(0.0));
	CheckFinding("triangle in a rounded quad", &sa, &sb, &m, -depth, 20.0 * TOL);
	m = cd2Collide(&sb, &sa, CD_R(0.0));
	CheckFinding("rounded quad around a triangle", &sb, &sa, &m, -depth, 20.0 * TOL);
}

/* A circle of radius 1e9 whose edge reaches a box of size 3.5 at x = -1e9: in float the box's
 * corners round to x = -1e9 exactly, a vertical segment whatever the box's rotation (87.7 degrees
 * here), and the face region was judged along that edge while the face point moves along the
 * box's tilted normal: the point was 4e7 off the box. The box and the circle touch within
 * round-off of the scale: one point of separation 0 within 1e-6 of it. */
static void TestCircleReachingFarBox(void)
{
	cd2Circle circle = {V(0, -12.375), CD_R(1e9)};
	cd2Box box = {V(-1e9, -12.5), V(1.75, 2.5), {CD_R(0.0399680361), CD_R(-0.99920094)}};
	cd2Shape sa = cd2MakeCircleShape(circle), sb = cd2MakeBoxShape(box);
	cd2Manifold m = cd2Collide(&sa, &sb, CD_R(12.5));
	CheckFinding("circle reaching a far box", &sa, &sb, &m, 0.0, 1e-6 * 1e9);
	m = cd2Collide(&sb, &sa, CD_R(12.5));
	CheckFinding("far box in a circle's reach", &sb, &sa, &m, 0.0, 1e-6 * 1e9);
}

/* A segment standing nearly square to another and ending 1e-4 short of its end (within the 0.1
 * slop in which cores count as touching): clipped to the short segment's side line, the long one's
 * contact ran out to its far end, at separation 1 instead of the gap 1e-4. Found by fuzz_manifold2
 * in the double build at 1e30 (a segment of length 1e30 rising 1.3e-5 over its length). */
static void TestSegmentShortOfEnd(void)
{
	cd2Segment a = {V(0, 0), V(0, 0.01)}, b = {V(0, -1e-4), V(1, 0)};
	cd2Shape sa = cd2MakeSegmentShape(a), sb = cd2MakeSegmentShape(b);
	/* the gap: from a's lower end (the origin) to its closest point on b, in double */
	double bx = (double)b.p2.x - (double)b.p1.x, by = (double)b.p2.y - (double)b.p1.y;
	double t = fmax(0.0, fmin(1.0, -((double)b.p1.x * bx + (double)b.p1.y * by) / (bx * bx + by * by)));
	double gap = hypot((double)b.p1.x + t * bx, (double)b.p1.y + t * by);
	TEST_CHECK(gap > 0.9e-4 && gap < 1.1e-4);
	cd2Manifold m = cd2Collide(&sa, &sb, CD_R(2.0));
	CheckFinding("segment short of another's end", &sa, &sb, &m, gap, TOL);
	m = cd2Collide(&sb, &sa, CD_R(2.0));
	CheckFinding("segment short of another's end (b, a)", &sb, &sa, &m, gap, TOL);
	/* The same with a box's face as the short edge: a long segment rising 1e-3 per unit, ending
	 * 1e-4 under the box's lower left corner. Clipped to the box's left face, its contact was 0.1
	 * from the box at x = -0.6 (and 999.5 at the face's top); the gap is 1e-4. */
	cd2Aabb box = {V(-0.5, -0.5), V(0.5, 0.5)};
	cd2Segment under = {V(-0.5, -0.5001), V(-1000, 0.5)};
	sa = cd2MakeAabbShape(box);
	sb = cd2MakeSegmentShape(under);
	bx = (double)under.p2.x - (double)under.p1.x;
	by = (double)under.p2.y - (double)under.p1.y;
	double cx = -0.5 - (double)under.p1.x, cy = -0.5 - (double)under.p1.y;
	t = fmax(0.0, fmin(1.0, (cx * bx + cy * by) / (bx * bx + by * by)));
	gap = hypot(cx - t * bx, cy - t * by);
	TEST_CHECK(gap > 0.9e-4 && gap < 1.1e-4);
	m = cd2Collide(&sa, &sb, CD_R(0.2));
	CheckFinding("segment under a box's corner", &sa, &sb, &m, gap, TOL);
	m = cd2Collide(&sb, &sa, CD_R(0.2));
	CheckFinding("segment under a box's corner (b, a)", &sb, &sa, &m, gap, TOL);
#if CD_DOUBLE
	/* fuzz_manifold2, double build: the same with a box of 7e-19 by 2e-30 and a segment 7.3e12 long,
	 * 7.125e-5 under it, whose contact was 7.3e12 from the box */
	cd2Box speck = {V(0, 0), V(3.60549004e-19, 1e-30), {CD_R(-1.0), CD_R(0.0)}};
	cd2Segment beneath = {V(-7.31282984e+12, 3.60549004e-19), V(-1e-30, -7.125e-05)};
	sa = cd2MakeBoxShape(speck);
	sb = cd2MakeSegmentShape(beneath);
	m = cd2Collide(&sa, &sb, CD_R(7.31282984e+12));
	CheckFinding("segment 7.3e12 long under a speck", &sa, &sb, &m, 7.125e-5, 1e-9);
	m = cd2Collide(&sb, &sa, CD_R(7.31282984e+12));
	CheckFinding("segment 7.3e12 long under a speck (b, a)", &sb, &sa, &m, 7.125e-5, 1e-9);

	cd2Segment c = {V(1.625e-06, 1.625e-06), V(1.625e-06, 2.125e-06)};
	cd2Segment d = {V(1.625e-06, -1.1375e-05), V(1e30, 1.625e-06)};
	sa = cd2MakeSegmentShape(c);
	sb = cd2MakeSegmentShape(d);
	/* the gap runs from c's lower end straight down to d's start (d rises 1.3e-5 over 1e30) */
	m = cd2Collide(&sa, &sb, CD_R(1e30));
	CheckFinding("segment of length 1e30 short of a segment", &sa, &sb, &m, 1.3e-5, 1e-9);
	m = cd2Collide(&sb, &sa, CD_R(1e30));
	CheckFinding("segment of length 1e30 short of a segment (b, a)", &sb, &sa, &m, 1.3e-5, 1e-9);
#endif
}

/* Findings of fuzz_manifold2 (regression inputs). A flat AABB (a segment from the origin
 * along +x) and a rounded triangle whose core corner (-0.000625, 0) lies on the segment's line
 * 6.25e-4 short of its end: the cores are apart by less than the 0.1 slop of the separating-axis
 * path, the triangle's corner lies beyond the segment face's side line, and the point kept there
 * projected 6.25e-4 off the segment. The gap point: separation 6.25e-4 - radius. */
static void TestCornerShortOfFlatBox(void)
{
	cd2Aabb flat = {V(0, 0), V(0.0116250003, 0)};
	cd2Vec points[3] = {V(-0.0125000002, -0.0125000002), V(-0.000624999986, 0),
						V(-0.0125000002, -0.00462500006)};
	cd2Polygon triangle;
	TEST_CHECK(cd2MakeRoundedPolygon(points, 3, CD_R(0.00937500037), &triangle) == CD_OK);
	cd2Shape sa = cd2MakeAabbShape(flat), sb = cd2MakePolygonShape(&triangle);
	double expected = -(double)points[1].x - (double)triangle.radius;
	cd2Manifold m = cd2Collide(&sa, &sb, CD_R(0.0));
	CheckFinding("rounded corner short of a flat box", &sa, &sb, &m, expected, TOL * 0.01);
	m = cd2Collide(&sb, &sa, CD_R(0.0));
	CheckFinding("flat box beyond a rounded corner", &sb, &sa, &m, expected, TOL * 0.01);
	/* A box of size 2e-9 (a point, turned) 0.3375 under an AABB's lower right corner: its closest
	 * point counted as inside one of its faces by rounding, and that face's tilted normal measured
	 * 0.377 for a gap of 0.3375. */
	cd2Aabb block = {V(-1.14999998, -0.8125), V(0, 0.275000006)};
	cd2Box speck = {V(0, -1.14999998), V(1e-9, 1e-9), {CD_R(0.44721359), CD_R(-0.89442718)}};
	sa = cd2MakeAabbShape(block);
	sb = cd2MakeBoxShape(speck);
	expected = (double)block.min.y - (double)speck.center.y - 1.5e-9;
	m = cd2Collide(&sa, &sb, CD_R(0.774999976));
	CheckFinding("speck under a block's corner", &sa, &sb, &m, expected, TOL);
	m = cd2Collide(&sb, &sa, CD_R(0.774999976));
	CheckFinding("block's corner over a speck", &sb, &sa, &m, expected, TOL);

	/* A flat AABB (a segment) and a triangle rounded by 6.25e-4 whose core corner is 7.29e-4 from
	 * the segment's end, beyond its side line: apart by 1.04e-4, yet a point 6.25e-4 off the
	 * segment came out at separation -2.5e-4 (found in the double build). */
	cd2Vec corner[3] = {V(-0.0115, -0.012125), V(0, -0.000375), V(0, 0.006375)};
	TEST_CHECK(cd2MakeRoundedPolygon(corner, 3, CD_R(0.000625), &triangle) == CD_OK);
	cd2Aabb sliver = {V(-0.0125, -0.0125), V(-0.012125, -0.0125)};
	sa = cd2MakeAabbShape(sliver);
	sb = cd2MakePolygonShape(&triangle);
	expected = hypot((double)corner[0].x - (double)sliver.max.x, (double)corner[0].y - (double)sliver.max.y) -
			   (double)triangle.radius;
	TEST_CHECK(expected > 1e-4);
	TEST_CHECK(cd2Collide(&sa, &sb, CD_R(0.0)).pointCount == 0);
	TEST_CHECK(cd2Collide(&sb, &sa, CD_R(0.0)).pointCount == 0);
	m = cd2Collide(&sa, &sb, CD_R(2e-4));
	CheckFinding("rounded corner beyond a sliver's end", &sa, &sb, &m, expected, TOL * 0.01);
	m = cd2Collide(&sb, &sa, CD_R(2e-4));
	CheckFinding("sliver's end before a rounded corner", &sb, &sa, &m, expected, TOL * 0.01);
	/* Capsules of radius 1.2e-6 whose cores pass within 6e-16 of each other (one is 5e8 long): the
	 * point along that gap had a normal of length 1.00005 (the distance the closest points report
	 * is not the length of their difference at that size). */
	cd2Capsule shortCapsule = {V(0, 0), V(4.49999987e-07, 0), CD_R(1.24999997e-06)};
	cd2Capsule longCapsule = {V(0, -1.15e-06), V(-2.87500001e-07, 5e8), CD_R(1.23749999e-06)};
	sa = cd2MakeCapsuleShape(shortCapsule);
	sb = cd2MakeCapsuleShape(longCapsule);
	for (int order = 0; order < 2; ++order)
	{
		m = order == 0 ? cd2Collide(&sa, &sb, CD_R(0.0)) : cd2Collide(&sb, &sa, CD_R(0.0));
		TEST_CHECK(m.pointCount >= 1);
		TEST_CHECK_NEAR(cd2Length(m.normal), 1.0, 1e-6);
		TEST_CHECK(m.pointCount >= 1 && MinSeparation(&m) < -2e-6);
	}
#if CD_DOUBLE
	/* Double build: a triangle rounded by 1e30 whose edge's line passes 177 (round-off at this
	 * scale) from a segment's end, the segment square to that edge: the segment's end was clipped
	 * within rounding of the side line, its point ran to the far end at +4e29, and the pair (deep
	 * by the radius) got no contact. */
	cd2Vec huge[3] = {V(-105, 1e30), V(0, 0), V(1e30, 1e30)};
	cd2Polygon rounded;
	TEST_CHECK(cd2MakeRoundedPolygon(huge, 3, CD_R(1e30), &rounded) == CD_OK);
	cd2Segment upright = {V(1e30, -1e30), V(-125, -125)};
	sa = cd2MakePolygonShape(&rounded);
	sb = cd2MakeSegmentShape(upright);
	m = cd2Collide(&sa, &sb, CD_R(0.0));
	CheckFinding("segment square to a huge rounded triangle", &sa, &sb, &m, -1e30, 1e-9 * 1e30);
	m = cd2Collide(&sb, &sa, CD_R(0.0));
	CheckFinding("huge rounded triangle square to a segment", &sb, &sa, &m, -1e30, 1e-9 * 1e30);
#endif
}

/* ---- random properties ------------------------------------------------------------------------ */

static cd2Shape PointShape(cd2Vec p)
{
	cd2Circle c = {p, CD_R(0.0)};
	return cd2MakeCircleShape(c);
}

static double DistanceToShape(const cd2Shape* s, cd2Vec p)
{
	cd2Shape point = PointShape(p);
	return (double)cd2Distance(s, &point).distance;
}

/* Whether the shape has an inside (zero-area shapes are segments or points). */
static bool HasArea(const cd2Shape* s)
{
	switch (s->type)
	{
		case CD2_SHAPE_CIRCLE:
			return s->circle.radius > CD_R(0.0);
		case CD2_SHAPE_CAPSULE:
			return s->capsule.radius > CD_R(0.0);
		case CD2_SHAPE_AABB:
			return s->aabb.max.x > s->aabb.min.x && s->aabb.max.y > s->aabb.min.y;
		case CD2_SHAPE_BOX:
			return s->box.halfExtents.x > CD_R(0.0) && s->box.halfExtents.y > CD_R(0.0);
		case CD2_SHAPE_POLYGON:
			return true;
		default:
			return false;
	}
}

/* p is on the surface of s: within TOL of it, and out of it once moved by 20 TOL along `outward`
 * (for shapes with an inside; a zero-area shape is all surface). */
static bool OnSurface(const cd2Shape* s, cd2Vec p, cd2Vec outward, double scale)
{
	double tolerance = TOL * scale;
	if (DistanceToShape(s, p) > tolerance)
	{
		return false;
	}
	if (!HasArea(s))
	{
		return true;
	}
	return DistanceToShape(s, cd2MulAdd(p, (cdReal)(20.0 * tolerance), outward)) > 0.0;
}

/* Support of a shape in direction u, in double: core vertices plus the radius. */
static double Support(const cd2Shape* s, double ux, double uy)
{
	cd2Vec pts[CD2_MAX_POLYGON_VERTICES];
	int count = 0;
	double radius = 0.0;
	switch (s->type)
	{
		case CD2_SHAPE_CIRCLE:
			pts[count++] = s->circle.center;
			radius = (double)s->circle.radius;
			break;
		case CD2_SHAPE_CAPSULE:
			pts[count++] = s->capsule.p1;
			pts[count++] = s->capsule.p2;
			radius = (double)s->capsule.radius;
			break;
		case CD2_SHAPE_AABB:
			pts[count++] = s->aabb.min;
			pts[count++] = s->aabb.max;
			pts[count++] = V((double)s->aabb.min.x, (double)s->aabb.max.y);
			pts[count++] = V((double)s->aabb.max.x, (double)s->aabb.min.y);
			break;
		case CD2_SHAPE_BOX:
		{
			double c = (double)s->box.rotation.c, sn = (double)s->box.rotation.s;
			double hx = (double)s->box.halfExtents.x, hy = (double)s->box.halfExtents.y;
			double best = -INFINITY;
			for (int i = 0; i < 4; ++i)
			{
				double lx = (i & 1) ? hx : -hx, ly = (i & 2) ? hy : -hy;
				double x = (double)s->box.center.x + c * lx - sn * ly;
				double y = (double)s->box.center.y + sn * lx + c * ly;
				best = fmax(best, x * ux + y * uy);
			}
			return best;
		}
		case CD2_SHAPE_POLYGON:
			for (int i = 0; i < s->polygon.count; ++i)
			{
				pts[count++] = s->polygon.vertices[i];
			}
			radius = (double)s->polygon.radius;
			break;
		default:
			pts[count++] = s->segment.p1;
			pts[count++] = s->segment.p2;
			break;
	}
	double best = -INFINITY;
	for (int i = 0; i < count; ++i)
	{
		best = fmax(best, (double)pts[i].x * ux + (double)pts[i].y * uy);
	}
	return best + radius;
}

/* Separation of b from a along the unit direction (angle): negative when they overlap along it. */
static double SeparationAlong(const cd2Shape* a, const cd2Shape* b, double angle)
{
	double ux = cos(angle), uy = sin(angle);
	return -Support(b, -ux, -uy) - Support(a, ux, uy);
}

/* The largest separation over all directions (minus the penetration depth when overlapping):
 * a dense scan, then golden-section refinement around the best few samples. */
static double ReferenceSeparation(const cd2Shape* a, const cd2Shape* b)
{
	const int samples = 720;
	const double step = 2.0 * 3.14159265358979323846 / samples;
	double values[720];
	for (int i = 0; i < samples; ++i)
	{
		values[i] = SeparationAlong(a, b, i * step);
	}
	double best = -INFINITY;
	for (int i = 0; i < samples; ++i)
	{
		double previous = values[(i + samples - 1) % samples], next = values[(i + 1) % samples];
		if (values[i] < previous || values[i] < next)
		{
			continue; /* not a local maximum */
		}
		double lo = (i - 1) * step, hi = (i + 1) * step;
		for (int k = 0; k < 60; ++k)
		{
			double m1 = lo + (hi - lo) * 0.381966, m2 = hi - (hi - lo) * 0.381966;
			if (SeparationAlong(a, b, m1) < SeparationAlong(a, b, m2))
			{
				lo = m1;
			}
			else
			{
				hi = m2;
			}
		}
		best = fmax(best, fmax(values[i], SeparationAlong(a, b, 0.5 * (lo + hi))));
	}
	return best;
}

static bool IsSolid(const cd2Shape* s)
{
	return s->type != CD2_SHAPE_SEGMENT;
}

typedef struct Counts
{
	int separated, penetrating, empty, skipped;
} Counts;

static void ReportPair(const cd2Shape* a, const cd2Shape* b, const cd2Manifold* m)
{
	PrintShape("a", a);
	PrintShape("b", b);
	PrintManifold(m);
}

static void CheckManifold(const cd2Shape* a, const cd2Shape* b, cdReal speculative, Counts* counts)
{
	cd2Manifold m = cd2Collide(a, b, speculative);
	bool ok = m.pointCount >= 0 && m.pointCount <= 2;
	TEST_CHECKF(ok, "%s/%s: point count %d", TypeName(a->type), TypeName(b->type), m.pointCount);
	if (!ok)
	{
		return;
	}
	double distance = (double)cd2Distance(a, b).distance;
	double spec = (double)speculative;

	/* Separated beyond the speculative distance: nothing; within it: something. */
	if (distance > spec + BAND)
	{
		TEST_CHECKF(m.pointCount == 0, "%s/%s: distance %.6g > speculative %.3g but %d points",
					TypeName(a->type), TypeName(b->type), distance, spec, m.pointCount);
		++counts->empty;
		return;
	}
	if (distance > spec - BAND)
	{
		++counts->skipped;
		return;
	}
	ok = m.pointCount >= 1;
	TEST_CHECKF(ok, "%s/%s: distance %.6g within the speculative distance but no point", TypeName(a->type),
				TypeName(b->type), distance);
	if (!ok)
	{
		ReportPair(a, b, &m);
		return;
	}
	bool allOk = true;
	ok = fabs((double)cd2Length(m.normal) - 1.0) <= TOL;
	TEST_CHECKF(ok, "normal not unit");
	allOk = allOk && ok;
	for (int i = 0; i < m.pointCount; ++i)
	{
		const cd2ManifoldPoint* p = &m.points[i];
		ok = (double)p->separation <= spec + TOL;
		TEST_CHECKF(ok, "%s/%s: separation %.6g beyond speculative", TypeName(a->type), TypeName(b->type),
					(double)p->separation);
		allOk = allOk && ok;
		cd2Vec onA = cd2MulSub(p->point, CD_R(0.5) * p->separation, m.normal);
		cd2Vec onB = cd2MulAdd(p->point, CD_R(0.5) * p->separation, m.normal);
		ok = OnSurface(a, onA, m.normal, 1.0) && OnSurface(b, onB, cd2Neg(m.normal), 1.0);
		TEST_CHECKF(ok, "%s/%s: point %d not on both surfaces (off A by %.3g, off B by %.3g)",
					TypeName(a->type), TypeName(b->type), i, DistanceToShape(a, onA),
					DistanceToShape(b, onB));
		allOk = allOk && ok;
	}

	/* Normal from A to B: B lies farther along it than A. */
	double along = SeparationAlong(a, b, atan2((double)m.normal.y, (double)m.normal.x));
	double minSeparation = MinSeparation(&m);
	if (distance > BAND)
	{
		++counts->separated;
		ok = fabs(minSeparation - distance) <= FLIP_SLACK && minSeparation > 0.0 && !cd2Overlap(a, b);
		TEST_CHECKF(ok, "%s/%s: smallest separation %.9g, distance %.9g", TypeName(a->type),
					TypeName(b->type), minSeparation, distance);
		allOk = allOk && ok;
		ok = along >= distance - FLIP_SLACK;
		TEST_CHECKF(ok, "%s/%s: along the normal the gap is %.6g, distance %.6g", TypeName(a->type),
					TypeName(b->type), along, distance);
		allOk = allOk && ok;
	}
	else if (distance == 0.0 && IsSolid(a) && IsSolid(b))
	{
		double reference = ReferenceSeparation(a, b);
		if (reference < -BAND)
		{
			++counts->penetrating;
			/* Never deeper than the penetration depth, and the chosen axis is (nearly) the best. */
			ok = minSeparation >= reference - FLIP_SLACK && along >= reference - FLIP_SLACK &&
				 minSeparation < 0.0 && cd2Overlap(a, b);
			TEST_CHECKF(ok, "%s/%s: smallest separation %.9g, along normal %.9g, reference %.9g",
						TypeName(a->type), TypeName(b->type), minSeparation, along, reference);
			allOk = allOk && ok;
		}
		else
		{
			++counts->skipped;
		}
	}
	else
	{
		++counts->skipped;
	}
	if (!allOk)
	{
		ReportPair(a, b, &m);
	}
}

/* Moves b so that it is apart from a by `gap` along their closest direction (if separated). */
static cd2Shape Pushed(const cd2Shape* a, const cd2Shape* b, double gap)
{
	cd2ClosestPoints r = cd2Distance(a, b);
	if (r.distance <= CD_R(0.0))
	{
		return *b;
	}
	cd2Vec n = cd2Normalize(cd2Sub(r.pointB, r.pointA));
	cd2Transform t = {cd2Scale((cdReal)(gap - (double)r.distance), n), CD2_ROT_IDENTITY};
	return TransformShape(b, t);
}

static void TestRandomPairs(void)
{
	TestRng rng = TestRngMake(0x3A7F01);
	Counts counts = {0, 0, 0, 0};
	for (int ta = 0; ta < CD2_SHAPE_TYPE_COUNT; ++ta)
	{
		for (int tb = 0; tb < CD2_SHAPE_TYPE_COUNT; ++tb)
		{
			for (int n = 0; n < 90; ++n)
			{
				cd2Shape a = RandomShape(&rng, (cd2ShapeType)ta);
				cd2Shape b = RandomShape(&rng, (cd2ShapeType)tb);
				if (n % 3 == 0)
				{
					b = Pushed(&a, &b, TestRngRange(&rng, 0.0, 1.5 * SPECULATIVE));
				}
				CheckManifold(&a, &b, (cdReal)SPECULATIVE, &counts);
			}
		}
	}
	printf("random pairs: %d separated, %d penetrating, %d empty, %d skipped\n", counts.separated,
		   counts.penetrating, counts.empty, counts.skipped);
	TEST_CHECK(counts.separated > 400 && counts.penetrating > 400 && counts.empty > 1000);
}

/* B moved by the depth along the normal just touches A (the exact separation of ReferenceSeparation
 * within 2e-4) for random overlapping pairs of polygons (rounded or not), boxes, circles and
 * capsules, both orders. The depth is the reference edge's separation, which the flip tolerance
 * (0.1 slop) may choose over a slightly shallower edge of the other shape: it is then deeper than
 * the smallest depth by at most that tolerance (checked too), and exact along the reported normal,
 * which is what the solver pushes along (docs/API.md, "2D contact manifolds"). */
static void TestDepthAlongNormal(void)
{
	static const cd2ShapeType types[4] = {CD2_SHAPE_POLYGON, CD2_SHAPE_BOX, CD2_SHAPE_CIRCLE,
										  CD2_SHAPE_CAPSULE};
	TestRng rng = TestRngMake(0xde9a7402ull);
	int checked = 0, failures = 0;
	double worst = 0.0, deepest = 0.0;
	for (int ta = 0; ta < 4; ++ta)
	{
		for (int tb = 0; tb < 4; ++tb)
		{
			for (int n = 0; n < 500; ++n)
			{
				cd2Shape a = RandomShape(&rng, types[ta]), b = RandomShape(&rng, types[tb]);
				cd2Manifold m = cd2Collide(&a, &b, CD_R(0.0));
				if (m.pointCount == 0)
				{
					continue;
				}
				double separation = MinSeparation(&m);
				cd2Transform t = {cd2Scale((cdReal)-separation, m.normal), CD2_ROT_IDENTITY};
				cd2Shape moved = TransformShape(&b, t);
				double after = ReferenceSeparation(&a, &moved);
				double exact = ReferenceSeparation(&a, &b);
				++checked;
				worst = fmax(worst, fabs(after));
				deepest = fmax(deepest, exact - separation);
				bool ok =
					fabs(after) <= 2e-4 && separation <= exact + TOL && separation >= exact - FLIP_SLACK;
				if (!ok && ++failures <= 3)
				{
					TEST_CHECKF(false, "%s-%s #%d: separation %.9g (exact %.9g); moved by it, %.3g apart",
								TypeName(a.type), TypeName(b.type), n, separation, exact, after);
					ReportPair(&a, &b, &m);
				}
			}
		}
	}
	printf("depth along the normal: %d pairs, %d off, worst %.3g after the move, deepest %.3g beyond the "
		   "exact depth\n",
		   checked, failures, worst, deepest);
	TEST_CHECK(checked > 1500);
	TEST_CHECK(failures == 0);
}

static bool SameIds(const cd2Manifold* m1, const cd2Manifold* m2)
{
	if (m1->pointCount != m2->pointCount)
	{
		return false;
	}
	for (int i = 0; i < m1->pointCount; ++i)
	{
		bool found = false;
		for (int j = 0; j < m2->pointCount; ++j)
		{
			found = found || m1->points[i].id == m2->points[j].id;
		}
		if (!found)
		{
			return false;
		}
	}
	return true;
}

/* Separations away from the speculative cut, so that both manifolds keep the same points. */
static bool ClearOfCut(const cd2Manifold* m, double spec)
{
	for (int i = 0; i < m->pointCount; ++i)
	{
		if (fabs((double)m->points[i].separation - spec) < BAND)
		{
			return false;
		}
	}
	return true;
}

static void TestSymmetryAndInvariance(void)
{
	TestRng rng = TestRngMake(0x3A7F02);
	int symmetric = 0, invariant = 0, stable = 0;
	for (int ta = 0; ta < CD2_SHAPE_TYPE_COUNT; ++ta)
	{
		for (int tb = 0; tb < CD2_SHAPE_TYPE_COUNT; ++tb)
		{
			for (int n = 0; n < 50; ++n)
			{
				cd2Shape a = RandomShape(&rng, (cd2ShapeType)ta);
				cd2Shape b = RandomShape(&rng, (cd2ShapeType)tb);
				if (n % 2 == 0)
				{
					b = Pushed(&a, &b, TestRngRange(&rng, 0.0, SPECULATIVE));
				}
				cdReal spec = (cdReal)SPECULATIVE;
				cd2Manifold ab = cd2Collide(&a, &b, spec);
				if (!ClearOfCut(&ab, SPECULATIVE))
				{
					continue;
				}

				/* Symmetry: exact for different types (the same pair function runs); shapes of the
				 * same type may pick the other reference edge on a near tie. */
				cd2Manifold ba = cd2Collide(&b, &a, spec);
				bool ok;
				if (ta != tb && !((ta == CD2_SHAPE_AABB || ta == CD2_SHAPE_BOX || ta == CD2_SHAPE_POLYGON) &&
								  (tb == CD2_SHAPE_AABB || tb == CD2_SHAPE_BOX || tb == CD2_SHAPE_POLYGON)))
				{
					ok = ba.pointCount == ab.pointCount && cd2VecEqual(ba.normal, cd2Neg(ab.normal));
					for (int i = 0; ok && i < ab.pointCount; ++i)
					{
						ok = cd2VecEqual(ab.points[i].point, ba.points[i].point) &&
							 ab.points[i].separation == ba.points[i].separation &&
							 ab.points[i].id == ba.points[i].id;
					}
				}
				else
				{
					ok = (ab.pointCount == 0) == (ba.pointCount == 0) &&
						 (ab.pointCount == 0 || fabs(MinSeparation(&ab) - MinSeparation(&ba)) <= FLIP_SLACK);
				}
				TEST_CHECKF(ok, "%s/%s: cd2Collide(b, a) is not the flipped cd2Collide(a, b)",
							TypeName(a.type), TypeName(b.type));
				if (!ok)
				{
					ReportPair(&a, &b, &ab);
					PrintManifold(&ba);
				}
				++symmetric;

				/* Rigid motion (translation only with an AABB). */
				bool hasAabb = ta == CD2_SHAPE_AABB || tb == CD2_SHAPE_AABB;
				cd2Transform x = {RandomVec(&rng, 20.0), hasAabb ? CD2_ROT_IDENTITY : RandomRot(&rng)};
				cd2Shape xa = TransformShape(&a, x), xb = TransformShape(&b, x);
				cd2Manifold moved = cd2Collide(&xa, &xb, spec);
				ok = moved.pointCount == ab.pointCount;
				if (ok && ab.pointCount > 0)
				{
					cd2Vec turned = cd2RotateVector(x.q, ab.normal);
					ok = fabs(MinSeparation(&moved) - MinSeparation(&ab)) <= 20 * TOL + FLIP_SLACK &&
						 (cd2VecDistance(turned, moved.normal) <= 1e-2 ||
						  fabs(MinSeparation(&moved) - MinSeparation(&ab)) <= FLIP_SLACK);
				}
				TEST_CHECKF(ok, "%s/%s: a rigid motion changed the manifold", TypeName(a.type),
							TypeName(b.type));
				if (!ok)
				{
					ReportPair(&a, &b, &ab);
					PrintManifold(&moved);
				}
				++invariant;

				/* Tiny motion: the same features, so the same ids (when the normal stays put). */
				cd2Transform nudge = {cd2Scale(CD_R(1e-4), cd2Normalize(RandomVec(&rng, 1.0))),
									  CD2_ROT_IDENTITY};
				cd2Shape nb = TransformShape(&b, nudge);
				cd2Manifold nudged = cd2Collide(&a, &nb, spec);
				if (ClearOfCut(&nudged, SPECULATIVE) && nudged.pointCount == ab.pointCount &&
					ab.pointCount > 0 && cd2VecDistance(nudged.normal, ab.normal) <= 1e-6 &&
					fabs(MinSeparation(&ab)) > BAND)
				{
					ok = SameIds(&ab, &nudged);
					TEST_CHECKF(ok, "%s/%s: ids changed under a tiny motion", TypeName(a.type),
								TypeName(b.type));
					if (!ok)
					{
						ReportPair(&a, &b, &ab);
						PrintManifold(&nudged);
					}
					++stable;
				}
			}
		}
	}
	printf("symmetry %d, invariance %d, id stability %d pairs\n", symmetric, invariant, stable);
	TEST_CHECK(symmetric > 1000 && invariant > 1000 && stable > 300);
}

/* ---- chains ----------------------------------------------------------------------------------- */

/* A flat floor at y = 0 from x = 10 to x = -10 (right to left: the free side is up), in unit
 * segments; segment i runs from x = 10 - i to x = 9 - i. */
static cd2ChainSegment FloorSegment(int i)
{
	cd2ChainSegment s = {V(11 - i, 0), V(10 - i, 0), V(9 - i, 0), V(8 - i, 0)};
	return s;
}

static void TestChainNoGhosts(void)
{
	int contacts = 0, ghostsWithoutChain = 0;
	for (int step = 0; step < 700; ++step)
	{
		double x = -4.0 + step * 0.0117;
		double sink = 0.005 + 0.01 * (step % 3);
		cd2Polygon box = BoxPolygon(x, 0.5 - sink, 0.5, 0.5, 0);
		cd2Circle circle = {V(x, 0.3 - sink), CD_R(0.3)};
		cd2Capsule capsule = {V(x - 0.7, 0.2 - sink), V(x + 0.7, 0.2 - sink), CD_R(0.2)};
		int boxPoints = 0;
		for (int i = 0; i < 20; ++i)
		{
			cd2ChainSegment s = FloorSegment(i);
			cd2Manifold ms[3] = {cd2CollideChainSegmentPolygon(&s, &box, CD_R(0.02)),
								 cd2CollideChainSegmentCircle(&s, circle, CD_R(0.02)),
								 cd2CollideChainSegmentCapsule(&s, capsule, CD_R(0.02))};
			for (int k = 0; k < 3; ++k)
			{
				bool ok = ms[k].pointCount == 0 ||
						  (ms[k].normal.x == CD_R(0.0) && fabs((double)ms[k].normal.y - 1.0) <= 1e-6);
				TEST_CHECKF(ok, "x %.4f segment %d shape %d: normal (%.9g %.9g)", x, i, k,
							(double)ms[k].normal.x, (double)ms[k].normal.y);
				for (int p = 0; p < ms[k].pointCount; ++p)
				{
					TEST_CHECKF(fabs((double)ms[k].points[p].separation + sink) <= TOL,
								"x %.4f segment %d shape %d: separation %.9g, sunk %.3g", x, i, k,
								(double)ms[k].points[p].separation, sink);
				}
				contacts += ms[k].pointCount;
			}
			boxPoints += ms[0].pointCount;

			cd2Segment plain = {s.p1, s.p2};
			cd2Manifold two = cd2CollidePolygonSegment(&box, plain, CD_R(0.02));
			if (two.pointCount > 0 && fabs((double)two.normal.y) < 0.99)
			{
				++ghostsWithoutChain;
			}
		}
		TEST_CHECKF(boxPoints >= 2, "x %.4f: the box gets %d points from the floor", x, boxPoints);
	}
	printf("chain: %d contacts, plain segments give %d ghost normals\n", contacts, ghostsWithoutChain);
	TEST_CHECK(contacts > 2000 && ghostsWithoutChain > 10);

	/* One-sided: a box below the floor gets nothing; a convex corner allows tilted normals. */
	cd2ChainSegment s = FloorSegment(5);
	cd2Polygon below = BoxPolygon(5.5, -0.49, 0.5, 0.5, 0);
	TEST_CHECK(cd2CollideChainSegmentPolygon(&s, &below, CD_R(0.0)).pointCount == 0);
	cd2ChainSegment corner = {V(6, 0), V(5, 0), V(4, 0), V(4, -1)}; /* drops at x = 4 */
	cd2Circle ball = {V(3.7, 0.4), CD_R(0.55)};
	cd2Manifold m = cd2CollideChainSegmentCircle(&corner, ball, CD_R(0.0));
	TEST_CHECK(m.pointCount == 1);
	CheckNormal(&m, -0.6, 0.8);
	CheckPoint(&m, 0, 4 + 0.6 * 0.025, -0.8 * 0.025, -0.05);
	/* past the next segment's normal at a 45-degree drop: that segment's business */
	cd2ChainSegment slope = {V(6, 0), V(5, 0), V(4, 0), V(3, -1)};
	ball.center = V(3.5, 0.1);
	ball.radius = CD_R(0.6);
	TEST_CHECK(cd2CollideChainSegmentCircle(&slope, ball, CD_R(0.0)).pointCount == 0);
	cd2Segment twoSided = {slope.p1, slope.p2};
	TEST_CHECK(cd2CollideCircleSegment(ball, twoSided, CD_R(0.0)).pointCount == 1);
}

/* The separating-axis scan (SSE2 four edges at a time in the float build, a plain loop elsewhere),
 * and its form with a limit, against the early-exit scan the manifolds used before: the same edge
 * and the same value bit for bit, for every pair of counts 1..8, with coordinates drawn from a few values in
 * half the rounds so that edges tie (the first one wins) and separations come out as zeros of either sign. */
static void TestSeparationScan(void)
{
	TestRng rng = {0x5e9a7u};
	static const double levels[4] = {-0.5, 0.0, 0.25, 1.0};
	for (int round = 0; round < 6400; ++round)
	{
		int count = 1 + round % 8, otherCount = 1 + (round / 8) % 8;
		bool coarse = round % 2 == 0;
		cd2Vec normals[8], vertices[8], others[8];
		for (int i = 0; i < 8; ++i)
		{
			normals[i] = coarse ? V(levels[TestRngInt(&rng, 4)], levels[TestRngInt(&rng, 4)])
								: V(TestRngRange(&rng, -1, 1), TestRngRange(&rng, -1, 1));
			vertices[i] = coarse ? V(levels[TestRngInt(&rng, 4)], -levels[TestRngInt(&rng, 4)])
								 : V(TestRngRange(&rng, -2, 2), TestRngRange(&rng, -2, 2));
			others[i] = coarse ? V(-levels[TestRngInt(&rng, 4)], levels[TestRngInt(&rng, 4)])
							   : V(TestRngRange(&rng, -2, 2), TestRngRange(&rng, -2, 2));
		}
		cdReal expected = -CD_REAL_MAX;
		int expectedEdge = 0;
		for (int i = 0; i < count; ++i)
		{
			cdReal lowest = CD_REAL_MAX;
			for (int j = 0; j < otherCount && lowest > expected; ++j)
			{
				lowest = cdMin(lowest, cd2Dot(normals[i], cd2Sub(others[j], vertices[i])));
			}
			if (lowest > expected)
			{
				expected = lowest;
				expectedEdge = i;
			}
		}
		int edge = -1, plainEdge = -1;
		cdReal got = cd2MaxSeparation(normals, vertices, count, others, otherCount, &edge);
		cdReal plain = cd2MaxSeparationScalar(normals, vertices, count, others, otherCount, &plainEdge);
		TEST_CHECKF(edge == expectedEdge && memcmp(&got, &expected, sizeof got) == 0,
					"round %d (%d edges, %d points): edge %d separation %.9g, expected edge %d %.9g", round,
					count, otherCount, edge, (double)got, expectedEdge, (double)expected);
		TEST_CHECKF(
			plainEdge == expectedEdge && memcmp(&plain, &expected, sizeof plain) == 0,
			"round %d (%d edges, %d points): plain scan edge %d separation %.9g, expected edge %d %.9g",
			round, count, otherCount, plainEdge, (double)plain, expectedEdge, (double)expected);
		/* The form with a limit: beyond it exactly when the separation exceeds the limit, else the
		 * same edge and value; limits just below, at and just above the separation (and zero, at
		 * which the coarse rounds' zeros of either sign sit). */
		cdReal limits[4] = {expected, expected - CD_R(0.125), expected + CD_R(0.125), CD_R(0.0)};
		for (int k = 0; k < 4; ++k)
		{
			int withinEdge = -1;
			cdReal separation = CD_R(7.0);
			bool within = cd2MaxSeparationWithin(normals, vertices, count, others, otherCount, limits[k],
												 &withinEdge, &separation);
			bool expectWithin = !(expected > limits[k]);
			TEST_CHECKF(within == expectWithin &&
							(!within || (withinEdge == expectedEdge &&
										 memcmp(&separation, &expected, sizeof separation) == 0)),
						"round %d (%d edges, %d points), limit %.9g: within %d edge %d separation %.9g, "
						"expected within %d edge %d %.9g",
						round, count, otherCount, (double)limits[k], within, withinEdge, (double)separation,
						expectWithin, expectedEdge, (double)expected);
		}
	}
}

/* Contacts whose coordinates' round-off exceeds the shapes' sizes (fuzz_manifold2 rows
 * manifold2-double-far-flat-aabb-triangle and manifold2-segment-through-rotated-box). A flat AABB
 * at the range's end above a small triangle: every triangle edge ties for the closest, and the one
 * taken must not be a face looking away (separation -M). A segment 7e8 long crossing a box of size
 * 24 whose direction rounds to the box's axis in float: its clip kept points 3.5e8 along it with
 * separation 7.07e8; the contact's separation must be that of cd2Distance within the round-off. */
static void TestRoundOffBeyondShapeSize(void)
{
	cdReal far = CD_DOUBLE ? CD_R(1e30) : CD_R(1e9);
	cd2Vec points[3] = {{CD_R(-0.125), CD_R(-0.125)}, {CD_R(0.03), CD_R(-0.125)}, {CD_R(0.03), CD_R(0.03)}};
	cd2Shape triangle;
	triangle.type = CD2_SHAPE_POLYGON;
	TEST_CHECK(cd2MakePolygon(points, 3, &triangle.polygon) == CD_OK);
	cd2Shape aabb;
	aabb.type = CD2_SHAPE_AABB;
	aabb.aabb.min = cd2MakeVec(CD_R(0.0775), far);
	aabb.aabb.max = cd2MakeVec(far, far);
	cd2Manifold m = cd2Collide(&triangle, &aabb, far);
	TEST_CHECK(m.pointCount > 0);
	for (int i = 0; i < m.pointCount; ++i)
	{
		TEST_CHECKF(m.points[i].separation >= CD_R(0.5) * far && m.normal.y > CD_R(0.0),
					"flat AABB at %g: separation %g, normal (%g %g)", (double)far,
					(double)m.points[i].separation, (double)m.normal.x, (double)m.normal.y);
	}

	cd2Shape segment, box;
	segment.type = CD2_SHAPE_CAPSULE;
	segment.capsule = (cd2Capsule){{CD_R(7.875), CD_R(-9.5)}, {CD_R(5e8), CD_R(5e8)}, CD_R(0.0)};
	box.type = CD2_SHAPE_BOX;
	box.box.center = cd2MakeVec(CD_R(0.0), CD_R(-11.625));
	box.box.halfExtents = cd2MakeVec(CD_R(12.125), CD_R(1.75));
	box.box.rotation = cd2NormalizeRot((cd2Rot){CD_R(-0.707106829), CD_R(-0.707106829)});
	cd2ClosestPoints d = cd2Distance(&segment, &box);
	m = cd2Collide(&segment, &box, CD_R(1e9));
	/* The contract's tolerance: 8 epsilon of the largest coordinate (5e8), 64 taken. */
	cdReal band = CD_R(64.0) * CD_REAL_EPSILON * CD_R(1e9);
	TEST_CHECK(m.pointCount > 0);
	for (int i = 0; i < m.pointCount; ++i)
	{
		TEST_CHECKF(cdAbs(m.points[i].separation - d.distance) <= band,
					"long segment: separation %g, distance %g (band %g)", (double)m.points[i].separation,
					(double)d.distance, (double)band);
	}
}

/* The incident edge of a tie within round-off (fuzz_manifold2 finding, float build): a segment
 * (0, 13750)-(0, -115000) reaching 5,000 into a sliver 1.4e9 long whose two long edges' normals
 * both round to x = 1. The first of the tie lay wholly below the segment's extent and gave one point
 * at y = -2.67e8 (2.67e8 off the segment); the incident edge is the one that reaches over it. Every
 * point lies on both shapes within the contract's tolerance at 1e9. */
static void TestIncidentEdgeTie(void)
{
	cd2Vec points[5] = {{CD_R(-431602080.0), CD_R(1e9)},
						{CD_R(-45000.0), CD_R(-430751712.0)},
						{CD_R(-7500.0), CD_R(-267181264.0)},
						{CD_R(5000.0), CD_R(-88750.0)},
						{CD_R(-13750.0), CD_R(-13750.0)}};
	cd2Shape sliver, segment;
	sliver.type = CD2_SHAPE_POLYGON;
	TEST_CHECK(cd2MakePolygon(points, 5, &sliver.polygon) == CD_OK);
	segment.type = CD2_SHAPE_SEGMENT;
	segment.segment.p1 = cd2MakeVec((cdReal)9.99999972e-10, CD_R(13750.0));
	segment.segment.p2 = cd2MakeVec((cdReal)9.99999972e-10, CD_R(-115000.0));
	cd2Manifold m = cd2Collide(&sliver, &segment, CD_R(25000.0));
	TEST_CHECK(m.pointCount > 0);
	double band = 256.0 * (double)CD_REAL_EPSILON * 1e9;
	for (int i = 0; i < m.pointCount; ++i)
	{
		cd2Vec p = m.points[i].point;
		cd2Vec onB = cd2MulAdd(p, CD_R(0.5) * m.points[i].separation, m.normal);
		double offSegment = (double)cd2Length(cd2Sub(onB, cd2ClosestPointOnSegment(segment.segment, onB)));
		TEST_CHECKF(offSegment <= band, "point %d (%.9g %.9g): %.9g off the segment (band %.9g)", i,
					(double)p.x, (double)p.y, offSegment, band);
		TEST_CHECKF(m.points[i].separation < CD_R(0.0), "point %d: separation %.9g for shapes that overlap",
					i, (double)m.points[i].separation);
	}

	/* The same sliver rounded by 1e9 around a box near its sharp end: the radius moves the tied
	 * edges' surface ends along the box's face, so the tie is decided on the core ends (the first
	 * edge's point had been 2.67e8 off the box). */
	cd2Vec rounded[6] = {{CD_R(-431602080.0), (cdReal)9.17479852e-08},
						 {CD_R(-45000.0), CD_R(-536870432.0)},
						 {CD_R(-7500.0), CD_R(-267181264.0)},
						 {CD_R(5000.0), CD_R(-88750.0)},
						 {CD_R(-13750.0), CD_R(-13750.0)},
						 {CD_R(-116250.0), CD_R(0.0)}};
	TEST_CHECK(cd2MakeRoundedPolygon(rounded, 6, CD_R(1e9), &sliver.polygon) == CD_OK);
	cd2Shape box;
	box.type = CD2_SHAPE_BOX;
	box.box.center = cd2MakeVec(CD_R(-10000.0), (cdReal)9.99999972e-10);
	box.box.halfExtents = cd2MakeVec(CD_R(118750.0), CD_R(10000.0));
	box.box.rotation.c = (cdReal)1.49999996e-05;
	box.box.rotation.s = CD_R(1.0);
	m = cd2Collide(&sliver, &box, CD_R(1e9));
	TEST_CHECK(m.pointCount > 0);
	for (int i = 0; i < m.pointCount; ++i)
	{
		cd2Vec onB = cd2MulAdd(m.points[i].point, CD_R(0.5) * m.points[i].separation, m.normal);
		double offBox = (double)cd2Length(cd2Sub(onB, cd2ClosestPointOnShape(&box, onB)));
		TEST_CHECKF(offBox <= band, "rounded sliver: point %d %.9g off the box (band %.9g)", i, offBox, band);
	}
}

int main(void)
{
	TEST_RUN(TestRoundOffBeyondShapeSize);
	TEST_RUN(TestIncidentEdgeTie);
	TEST_RUN(TestBoxes);
	TEST_RUN(TestDepthAlongNormal);
	TEST_RUN(TestRoundedPolygons);
	TEST_RUN(TestCircles);
	TEST_RUN(TestCapsulesAndSegments);
	TEST_RUN(TestWrappedVertex);
	TEST_RUN(TestSharedEnds);
	TEST_RUN(TestBoxAlongCapsule);
	TEST_RUN(TestFarSpeculative);
	TEST_RUN(TestCapsuleInHugeCapsule);
	TEST_RUN(TestTriangleInRoundedQuad);
	TEST_RUN(TestCircleReachingFarBox);
	TEST_RUN(TestSegmentShortOfEnd);
	TEST_RUN(TestCornerShortOfFlatBox);
	TEST_RUN(TestRandomPairs);
	TEST_RUN(TestSymmetryAndInvariance);
	TEST_RUN(TestChainNoGhosts);
	TEST_RUN(TestSeparationScan);
	return TEST_SUMMARY();
}
