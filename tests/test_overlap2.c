/* Tests of the 2D point containment and overlap tests: exact cases for every function, then
 * property tests over random pairs of every type pair (symmetry through cd2Overlap, agreement with
 * the double-precision reference distance of reference2.h, invariance under rigid transforms), at
 * ordinary, huge and tiny scales. */
#include "collide/query2.h"
#include "reference2.h"
#include "test.h"

static cd2Vec V(double x, double y)
{
	return cd2MakeVec((cdReal)x, (cdReal)y);
}

static cd2Circle Circle(double x, double y, double r)
{
	cd2Circle c = {V(x, y), (cdReal)r};
	return c;
}

static cd2Capsule Capsule(double x1, double y1, double x2, double y2, double r)
{
	cd2Capsule c = {V(x1, y1), V(x2, y2), (cdReal)r};
	return c;
}

static cd2Aabb Aabb(double x1, double y1, double x2, double y2)
{
	cd2Aabb b = {V(x1, y1), V(x2, y2)};
	return b;
}

static cd2Box Box(double x, double y, double hx, double hy, double angle)
{
	cd2Box b = {V(x, y), V(hx, hy), cd2MakeRot((cdReal)angle)};
	return b;
}

/* Rotation by exactly a quarter turn (no round-off in cos/sin). */
static cd2Box QuarterBox(double x, double y, double hx, double hy)
{
	cd2Box b = {V(x, y), V(hx, hy), {(cdReal)0, (cdReal)1}};
	return b;
}

static cd2Segment Segment(double x1, double y1, double x2, double y2)
{
	cd2Segment g = {V(x1, y1), V(x2, y2)};
	return g;
}

/* Axis-aligned square polygon [x, x + size] x [y, y + size]. */
static cd2Polygon Square(double x, double y, double size)
{
	cd2Vec points[4] = {V(x, y), V(x + size, y), V(x + size, y + size), V(x, y + size)};
	cd2Polygon polygon;
	cdResult result = cd2MakePolygon(points, 4, &polygon);
	TEST_CHECK(result == CD_OK);
	return polygon;
}

/* Triangle (0,0), (2,0), (0,2) shifted by (x, y). */
static cd2Polygon Triangle(double x, double y)
{
	cd2Vec points[3] = {V(x, y), V(x + 2, y), V(x, y + 2)};
	cd2Polygon polygon;
	cdResult result = cd2MakePolygon(points, 3, &polygon);
	TEST_CHECK(result == CD_OK);
	return polygon;
}

static void TestPointIn(void)
{
	cd2Aabb b = Aabb(-1, -2, 3, 4);
	TEST_CHECK(cd2PointInAabb(V(0, 0), b));
	TEST_CHECK(cd2PointInAabb(V(3, 4), b));
	TEST_CHECK(cd2PointInAabb(V(-1, 0), b));
	TEST_CHECK(!cd2PointInAabb(V(3.001, 0), b));
	TEST_CHECK(!cd2PointInAabb(V(0, -2.001), b));
	TEST_CHECK(cd2PointInAabb(V(1, 1), Aabb(1, 1, 1, 1)));
	TEST_CHECK(!cd2PointInAabb(V(1, 1.001), Aabb(1, 1, 1, 1)));

	TEST_CHECK(cd2PointInCircle(V(3, 4), Circle(0, 0, 5)));
	TEST_CHECK(!cd2PointInCircle(V(3, 4.001), Circle(0, 0, 5)));
	TEST_CHECK(cd2PointInCircle(V(1, 1), Circle(1, 1, 0)));
	TEST_CHECK(!cd2PointInCircle(V(1, 1.001), Circle(1, 1, 0)));

	cd2Capsule capsule = Capsule(0, 0, 4, 0, 1);
	TEST_CHECK(cd2PointInCapsule(V(2, 1), capsule));
	TEST_CHECK(cd2PointInCapsule(V(5, 0), capsule));
	TEST_CHECK(cd2PointInCapsule(V(-0.6, 0.8), capsule));
	TEST_CHECK(!cd2PointInCapsule(V(2, 1.001), capsule));
	TEST_CHECK(!cd2PointInCapsule(V(-0.61, 0.8), capsule));
	TEST_CHECK(cd2PointInCapsule(V(7, 7), Capsule(7, 7, 7, 7, 0)));
	TEST_CHECK(cd2PointInCapsule(V(7.5, 7), Capsule(7, 7, 7, 7, 0.5)));

	cd2Box box = Box(1, 1, 2, 1, CD_PI / 6);
	TEST_CHECK(cd2PointInBox(V(1, 1), box));
	cd2Rot q = cd2MakeRot(CD_PI / 6);
	cd2Vec corner = cd2Add(V(1, 1), cd2RotateVector(q, V(2, 1)));
	TEST_CHECK(cd2PointInBox(corner, box));
	TEST_CHECK(!cd2PointInBox(cd2Add(V(1, 1), cd2RotateVector(q, V(2.001, 1))), box));
	TEST_CHECK(cd2PointInBox(cd2Add(V(1, 1), cd2RotateVector(q, V(-1.5, -1))), box));
	TEST_CHECK(!cd2PointInBox(cd2Add(V(1, 1), cd2RotateVector(q, V(-1.5, -1.001))), box));
	TEST_CHECK(cd2PointInBox(V(2, 3), Box(2, 3, 0, 0, 1.0)));
	TEST_CHECK(!cd2PointInBox(V(2, 3.001), Box(2, 3, 0, 0, 1.0)));

	cd2Polygon triangle = Triangle(0, 0);
	TEST_CHECK(cd2PointInPolygon(V(0.5, 0.5), &triangle));
	TEST_CHECK(cd2PointInPolygon(V(0, 0), &triangle));
	TEST_CHECK(cd2PointInPolygon(V(1, 1), &triangle));
	TEST_CHECK(cd2PointInPolygon(V(0, 2), &triangle));
	TEST_CHECK(!cd2PointInPolygon(V(1.001, 1.001), &triangle));
	TEST_CHECK(!cd2PointInPolygon(V(-0.001, 1), &triangle));
	TEST_CHECK(!cd2PointInPolygon(V(3, -1), &triangle));
}

static void TestAabbAabb(void)
{
	cd2Aabb a = Aabb(0, 0, 2, 2);
	TEST_CHECK(!cd2OverlapAabbAabb(a, Aabb(3, 0, 4, 2)));	/* separated in x */
	TEST_CHECK(!cd2OverlapAabbAabb(a, Aabb(0, 2.5, 2, 3))); /* separated in y */
	TEST_CHECK(!cd2OverlapAabbAabb(a, Aabb(2.5, 2.5, 3, 3)));
	TEST_CHECK(cd2OverlapAabbAabb(a, Aabb(2, 0, 4, 2)));	 /* touching edge */
	TEST_CHECK(cd2OverlapAabbAabb(a, Aabb(2, 2, 4, 4)));	 /* touching corner */
	TEST_CHECK(cd2OverlapAabbAabb(a, Aabb(1, 1, 3, 3)));	 /* overlapping */
	TEST_CHECK(cd2OverlapAabbAabb(a, Aabb(0.5, 0.5, 1, 1))); /* nested */
	TEST_CHECK(cd2OverlapAabbAabb(Aabb(0.5, 0.5, 1, 1), a));
	TEST_CHECK(cd2OverlapAabbAabb(a, a));				 /* coincident */
	TEST_CHECK(cd2OverlapAabbAabb(a, Aabb(1, 1, 1, 1))); /* zero size inside */
	TEST_CHECK(cd2OverlapAabbAabb(a, Aabb(2, 1, 2, 1))); /* zero size on the edge */
	TEST_CHECK(!cd2OverlapAabbAabb(a, Aabb(2.001, 1, 2.001, 1)));
	TEST_CHECK(cd2OverlapAabbAabb(Aabb(1, 1, 1, 1), Aabb(1, 1, 1, 1)));
	TEST_CHECK(cd2OverlapAabbAabb(a, Aabb(-1, 1, 3, 1.5))); /* crossing, no corner inside */
}

static void TestCircleCircle(void)
{
	cd2Circle a = Circle(0, 0, 1);
	TEST_CHECK(!cd2OverlapCircleCircle(a, Circle(3, 0, 1)));
	TEST_CHECK(cd2OverlapCircleCircle(a, Circle(2, 0, 1))); /* touching */
	TEST_CHECK(cd2OverlapCircleCircle(a, Circle(3, 4, 4))); /* touching on a 3-4-5 diagonal */
	TEST_CHECK(!cd2OverlapCircleCircle(a, Circle(3, 4, 3.999)));
	TEST_CHECK(cd2OverlapCircleCircle(a, Circle(1, 1, 1)));		/* overlapping */
	TEST_CHECK(cd2OverlapCircleCircle(a, Circle(0.1, 0, 0.2))); /* nested */
	TEST_CHECK(cd2OverlapCircleCircle(a, a));
	TEST_CHECK(cd2OverlapCircleCircle(Circle(1, 1, 0), Circle(1, 1, 0)));
	TEST_CHECK(!cd2OverlapCircleCircle(Circle(1, 1, 0), Circle(1, 1.001, 0)));
	TEST_CHECK(cd2OverlapCircleCircle(Circle(1, 0, 0), a)); /* point on the circle */
}

static void TestPolygonPolygon(void)
{
	cd2Polygon a = Square(0, 0, 2);
	cd2Polygon separated = Square(3, 0, 1);
	cd2Polygon touchingEdge = Square(2, 0.5, 1);
	cd2Polygon touchingCorner = Square(2, 2, 1);
	cd2Polygon overlapping = Square(1, 1, 2);
	cd2Polygon nested = Square(0.5, 0.5, 1);
	TEST_CHECK(!cd2OverlapPolygonPolygon(&a, &separated));
	TEST_CHECK(cd2OverlapPolygonPolygon(&a, &touchingEdge));
	TEST_CHECK(cd2OverlapPolygonPolygon(&a, &touchingCorner));
	TEST_CHECK(cd2OverlapPolygonPolygon(&a, &overlapping));
	TEST_CHECK(cd2OverlapPolygonPolygon(&a, &nested));
	TEST_CHECK(cd2OverlapPolygonPolygon(&nested, &a));
	TEST_CHECK(cd2OverlapPolygonPolygon(&a, &a));

	/* Triangle hypotenuse x + y = 2 against a square whose corner (1, 1) is on it, then moved off
	 * along the diagonal: only the triangle's hypotenuse normal separates them. */
	cd2Polygon triangle = Triangle(0, 0);
	cd2Polygon onHypotenuse = Square(1, 1, 1);
	cd2Polygon offHypotenuse = Square(1.01, 1.01, 1);
	TEST_CHECK(cd2OverlapPolygonPolygon(&triangle, &onHypotenuse));
	TEST_CHECK(!cd2OverlapPolygonPolygon(&triangle, &offHypotenuse));
	TEST_CHECK(!cd2OverlapPolygonPolygon(&offHypotenuse, &triangle));
}

static void TestCirclePairs(void)
{
	/* capsule along x from 0 to 4, radius 1 */
	cd2Capsule capsule = Capsule(0, 0, 4, 0, 1);
	TEST_CHECK(!cd2OverlapCircleCapsule(Circle(2, 3, 1), capsule));
	TEST_CHECK(cd2OverlapCircleCapsule(Circle(2, 2, 1), capsule)); /* touching the side */
	TEST_CHECK(cd2OverlapCircleCapsule(Circle(7, 0, 2), capsule)); /* touching the cap */
	TEST_CHECK(!cd2OverlapCircleCapsule(Circle(7.01, 0, 2), capsule));
	TEST_CHECK(cd2OverlapCircleCapsule(Circle(2, 0.5, 0.1), capsule)); /* nested */
	TEST_CHECK(cd2OverlapCircleCapsule(Circle(2, 0, 10), capsule));	   /* capsule nested in circle */
	TEST_CHECK(cd2OverlapCircleCapsule(Circle(1, 1, 0), Capsule(1, 1, 1, 1, 0))); /* degenerate */
	TEST_CHECK(cd2OverlapCircleCapsule(Circle(4, 3, 4), Capsule(0, 0, 0, 0, 1))); /* 3-4-5 */
	TEST_CHECK(cd2OverlapCircleCapsule(Circle(0, 0, 1), capsule));				  /* coincident end disks */
	TEST_CHECK(!cd2OverlapCircleCapsule(Circle(4, 3, 3.99), Capsule(0, 0, 0, 0, 1)));

	cd2Aabb b = Aabb(0, 0, 2, 2);
	TEST_CHECK(!cd2OverlapCircleAabb(Circle(4, 1, 1), b));
	TEST_CHECK(cd2OverlapCircleAabb(Circle(3, 1, 1), b));	  /* touching a face */
	TEST_CHECK(cd2OverlapCircleAabb(Circle(5, 6, 5), b));	  /* touching the corner (2, 2) */
	TEST_CHECK(!cd2OverlapCircleAabb(Circle(5, 6, 4.99), b)); /* the face test alone would say yes */
	TEST_CHECK(cd2OverlapCircleAabb(Circle(1, 1, 0.1), b));	  /* nested */
	TEST_CHECK(cd2OverlapCircleAabb(Circle(1, 1, 10), b));	  /* box nested in circle */
	TEST_CHECK(cd2OverlapCircleAabb(Circle(2, 1, 0), b));	  /* point on the edge */
	TEST_CHECK(cd2OverlapCircleAabb(Circle(3, 3, 0), Aabb(3, 3, 3, 3)));
	TEST_CHECK(!cd2OverlapCircleAabb(Circle(3, 3.5, 0.49), Aabb(3, 3, 3, 3)));

	cd2Box box = QuarterBox(0, 0, 2, 1); /* quarter turn: extends 1 in x, 2 in y */
	TEST_CHECK(cd2OverlapCircleBox(Circle(2, 0, 1), box));
	TEST_CHECK(!cd2OverlapCircleBox(Circle(2.01, 0, 1), box));
	TEST_CHECK(cd2OverlapCircleBox(Circle(0, 3, 1), box));
	TEST_CHECK(cd2OverlapCircleBox(Circle(0, 0, 0.1), box));
	cd2Box diamond = Box(0, 0, 1, 1, CD_PI / 4); /* corner at (sqrt 2, 0) */
	TEST_CHECK(cd2OverlapCircleBox(Circle(sqrt(2.0) + 1, 0, 1), diamond));
	TEST_CHECK(!cd2OverlapCircleBox(Circle(sqrt(2.0) + 1.01, 0, 1), diamond));
	TEST_CHECK(!cd2OverlapCircleBox(Circle(1.5, 1.5, 0.7), diamond)); /* distance 1.5 sqrt2 - 1 */
	TEST_CHECK(cd2OverlapCircleBox(Circle(1.5, 1.5, 1.13), diamond));
	TEST_CHECK(cd2OverlapCircleBox(Circle(5, 5, 0), Box(5, 5, 0, 0, 0.3)));

	cd2Polygon triangle = Triangle(0, 0);
	TEST_CHECK(!cd2OverlapCirclePolygon(Circle(2, 2, 1.4), &triangle)); /* distance sqrt 2 */
	TEST_CHECK(cd2OverlapCirclePolygon(Circle(2, 2, 1.42), &triangle));
	TEST_CHECK(cd2OverlapCirclePolygon(Circle(-1, 1, 1), &triangle)); /* touching edge x = 0 */
	TEST_CHECK(!cd2OverlapCirclePolygon(Circle(-1.01, 1, 1), &triangle));
	TEST_CHECK(cd2OverlapCirclePolygon(Circle(0.5, 0.5, 0.1), &triangle));
	TEST_CHECK(cd2OverlapCirclePolygon(Circle(0.5, 0.5, 10), &triangle));
	TEST_CHECK(cd2OverlapCirclePolygon(Circle(0, 0, 0), &triangle));
	TEST_CHECK(cd2OverlapCirclePolygon(Circle(-3, -4, 5), &triangle)); /* touching vertex (0, 0) */
	TEST_CHECK(!cd2OverlapCirclePolygon(Circle(-3, -4, 4.99), &triangle));

	cd2Segment segment = Segment(0, 0, 4, 0);
	TEST_CHECK(cd2OverlapCircleSegment(Circle(2, 1, 1), segment));
	TEST_CHECK(!cd2OverlapCircleSegment(Circle(2, 1.01, 1), segment));
	TEST_CHECK(cd2OverlapCircleSegment(Circle(7, 4, 5), segment)); /* touching the end */
	TEST_CHECK(!cd2OverlapCircleSegment(Circle(7, 4, 4.99), segment));
	TEST_CHECK(cd2OverlapCircleSegment(Circle(2, 0, 10), segment)); /* nested */
	TEST_CHECK(cd2OverlapCircleSegment(Circle(2, 0, 0), segment));
	TEST_CHECK(cd2OverlapCircleSegment(Circle(1, 1, 0), Segment(1, 1, 1, 1)));
	TEST_CHECK(!cd2OverlapCircleSegment(Circle(1, 1.5, 0.49), Segment(1, 1, 1, 1)));
}

static void TestCapsulePairs(void)
{
	cd2Capsule a = Capsule(0, 0, 4, 0, 1);
	TEST_CHECK(!cd2OverlapCapsuleCapsule(a, Capsule(0, 3, 4, 3, 0.9))); /* parallel */
	TEST_CHECK(cd2OverlapCapsuleCapsule(a, Capsule(0, 3, 4, 3, 2)));	/* parallel, touching */
	TEST_CHECK(cd2OverlapCapsuleCapsule(a, Capsule(2, -3, 2, 3, 0.1))); /* crossing */
	TEST_CHECK(cd2OverlapCapsuleCapsule(a, Capsule(7, 0, 9, 0, 2)));	/* collinear, touching */
	TEST_CHECK(!cd2OverlapCapsuleCapsule(a, Capsule(7.01, 0, 9, 0, 2)));
	TEST_CHECK(cd2OverlapCapsuleCapsule(a, Capsule(1, 0, 2, 0, 0.1))); /* nested */
	TEST_CHECK(cd2OverlapCapsuleCapsule(a, a));
	TEST_CHECK(cd2OverlapCapsuleCapsule(Capsule(1, 1, 1, 1, 0), Capsule(1, 1, 1, 1, 0)));
	TEST_CHECK(cd2OverlapCapsuleCapsule(Capsule(0, 0, 0, 0, 1), Capsule(3, 4, 3, 4, 4)));
	TEST_CHECK(!cd2OverlapCapsuleCapsule(Capsule(0, 0, 0, 0, 1), Capsule(3, 4, 3, 4, 3.99)));

	cd2Aabb b = Aabb(0, 0, 2, 2);
	TEST_CHECK(!cd2OverlapCapsuleAabb(Capsule(3, -1, 3, 3, 0.9), b));
	TEST_CHECK(cd2OverlapCapsuleAabb(Capsule(3, -1, 3, 3, 1), b)); /* touching a face */
	TEST_CHECK(cd2OverlapCapsuleAabb(Capsule(-1, 1, 3, 1, 0), b)); /* crossing segment */
	TEST_CHECK(cd2OverlapCapsuleAabb(Capsule(5, 6, 9, 6, 5), b));  /* touching the corner */
	TEST_CHECK(!cd2OverlapCapsuleAabb(Capsule(5, 6, 9, 6, 4.99), b));
	TEST_CHECK(cd2OverlapCapsuleAabb(Capsule(0.5, 0.5, 1, 1, 0.1), b)); /* nested */
	TEST_CHECK(cd2OverlapCapsuleAabb(Capsule(1, 1, 1, 1, 0), Aabb(1, 1, 1, 1)));
	TEST_CHECK(!cd2OverlapCapsuleAabb(Capsule(1, 4, 4, 1, 0.7), b)); /* line x + y = 5: distance sqrt 2/2 */
	TEST_CHECK(cd2OverlapCapsuleAabb(Capsule(1, 4, 4, 1, 0.71), b));

	cd2Box box = QuarterBox(0, 0, 2, 1);
	TEST_CHECK(cd2OverlapCapsuleBox(Capsule(2, -5, 2, 5, 1), box));
	TEST_CHECK(!cd2OverlapCapsuleBox(Capsule(2.01, -5, 2.01, 5, 1), box));
	TEST_CHECK(cd2OverlapCapsuleBox(Capsule(0, 0, 0, 0, 0), box));
	cd2Box diamond = Box(0, 0, 1, 1, CD_PI / 4);
	TEST_CHECK(!cd2OverlapCapsuleBox(Capsule(1.5, 1.5, 3, 3, 0.7), diamond));
	TEST_CHECK(cd2OverlapCapsuleBox(Capsule(1.5, 1.5, 3, 3, 1.13), diamond));
	TEST_CHECK(cd2OverlapCapsuleBox(Capsule(-5, 0, 5, 0, 0), diamond));
	TEST_CHECK(cd2OverlapCapsuleBox(Capsule(3, 3, 3, 3, 1), Box(3, 4, 0, 0, 0.5)));

	cd2Polygon triangle = Triangle(0, 0);
	TEST_CHECK(!cd2OverlapCapsulePolygon(Capsule(2, 2, 3, 3, 1.4), &triangle));
	TEST_CHECK(cd2OverlapCapsulePolygon(Capsule(2, 2, 3, 3, 1.42), &triangle));
	TEST_CHECK(cd2OverlapCapsulePolygon(Capsule(3, -1, -1, 3, 0), &triangle));	/* along the hypotenuse */
	TEST_CHECK(!cd2OverlapCapsulePolygon(Capsule(3, 0, 0, 3, 0.7), &triangle)); /* parallel, sqrt 2/2 away */
	TEST_CHECK(cd2OverlapCapsulePolygon(Capsule(3, 0, 0, 3, 0.71), &triangle));
	TEST_CHECK(cd2OverlapCapsulePolygon(Capsule(-1, -1, 3, 3, 0), &triangle)); /* crossing */
	TEST_CHECK(cd2OverlapCapsulePolygon(Capsule(0.2, 0.2, 0.3, 0.3, 0.01), &triangle));
	TEST_CHECK(cd2OverlapCapsulePolygon(Capsule(-1, -1, -1, 5, 1), &triangle));
	TEST_CHECK(!cd2OverlapCapsulePolygon(Capsule(-1.01, -1, -1.01, 5, 1), &triangle));

	cd2Segment segment = Segment(0, 0, 4, 0);
	TEST_CHECK(cd2OverlapCapsuleSegment(Capsule(2, 2, 5, 2, 2), segment));
	TEST_CHECK(!cd2OverlapCapsuleSegment(Capsule(2, 2, 5, 2, 1.99), segment));
	TEST_CHECK(cd2OverlapCapsuleSegment(Capsule(2, -1, 2, 1, 0), segment));
	TEST_CHECK(cd2OverlapCapsuleSegment(Capsule(0, 0, 4, 0, 0), segment));
	TEST_CHECK(cd2OverlapCapsuleSegment(Capsule(7, 4, 7, 4, 5), segment));
	TEST_CHECK(!cd2OverlapCapsuleSegment(Capsule(7, 4, 7, 4, 4.99), segment));
	TEST_CHECK(cd2OverlapCapsuleSegment(Capsule(1, 0, 1, 0, 0), Segment(1, 0, 1, 0)));
}

static void TestAabbPairs(void)
{
	cd2Aabb a = Aabb(0, 0, 2, 2);
	TEST_CHECK(cd2OverlapAabbBox(a, QuarterBox(3, 1, 2, 1))); /* touching the face x = 2 */
	TEST_CHECK(!cd2OverlapAabbBox(a, QuarterBox(3.01, 1, 2, 1)));
	cd2Box diamond = Box(3, 3, 1, 1, CD_PI / 4); /* corners at distance sqrt 2 from (3, 3) */
	TEST_CHECK(!cd2OverlapAabbBox(a, diamond));	 /* gap along the diagonal: 2 sqrt 2 - 1 - sqrt 2 */
	TEST_CHECK(cd2OverlapAabbBox(a, Box(3, 1, 1, 1, CD_PI / 4)));			  /* corner 3 - sqrt2 inside */
	TEST_CHECK(cd2OverlapAabbBox(a, Box(2 + sqrt(2.0), 1, 1, 1, CD_PI / 4))); /* corner touching */
	TEST_CHECK(!cd2OverlapAabbBox(a, Box(2.01 + sqrt(2.0), 1, 1, 1, CD_PI / 4)));
	TEST_CHECK(cd2OverlapAabbBox(a, Box(1, 1, 0.1, 0.2, 0.3))); /* nested */
	TEST_CHECK(cd2OverlapAabbBox(a, Box(1, 1, 5, 5, 0.3)));		/* AABB nested in box */
	TEST_CHECK(cd2OverlapAabbBox(a, Box(1, 1, 1, 1, 0)));		/* coincident */
	TEST_CHECK(cd2OverlapAabbBox(Aabb(1, 1, 1, 1), Box(1, 1, 0, 0, 0.7)));
	TEST_CHECK(!cd2OverlapAabbBox(Aabb(1, 1, 1, 1), Box(1, 1.01, 0, 0, 0.7)));
	TEST_CHECK(cd2OverlapAabbBox(Aabb(0, 0, 2, 0), Box(1, 1, 1, 0, CD_PI / 2))); /* two segments */

	cd2Polygon triangle = Triangle(0, 0);
	TEST_CHECK(cd2OverlapAabbPolygon(Aabb(1, 1, 2, 2), &triangle));
	TEST_CHECK(!cd2OverlapAabbPolygon(Aabb(1.01, 1.01, 2, 2), &triangle));
	TEST_CHECK(cd2OverlapAabbPolygon(Aabb(-1, -1, 0, 0), &triangle));
	TEST_CHECK(cd2OverlapAabbPolygon(Aabb(-1, -1, 3, 3), &triangle));
	cd2Polygon unitSquare = Square(0, 0, 1);
	TEST_CHECK(cd2OverlapAabbPolygon(Aabb(0, 0, 1, 1), &unitSquare)); /* coincident */
	TEST_CHECK(cd2OverlapAabbPolygon(Aabb(1, 0, 2, 1), &unitSquare)); /* sharing an edge */
	TEST_CHECK(!cd2OverlapAabbPolygon(Aabb(1.01, 0, 2, 1), &unitSquare));
	TEST_CHECK(cd2OverlapAabbPolygon(Aabb(0.2, 0.2, 0.2, 0.2), &triangle));
	TEST_CHECK(!cd2OverlapAabbPolygon(Aabb(1.2, 1.2, 1.2, 1.2), &triangle));

	TEST_CHECK(cd2OverlapAabbSegment(a, Segment(-1, 1, 3, 1))); /* crossing, no end inside */
	TEST_CHECK(cd2OverlapAabbSegment(a, Segment(1, 3, 3, 1)));	/* touching the corner (2, 2) */
	TEST_CHECK(!cd2OverlapAabbSegment(a, Segment(1.01, 3.01, 3.01, 1.01)));
	TEST_CHECK(!cd2OverlapAabbSegment(a, Segment(1, 3.5, 3.5, 1)));
	TEST_CHECK(cd2OverlapAabbSegment(a, Segment(0.5, 0.5, 1, 1)));
	TEST_CHECK(cd2OverlapAabbSegment(a, Segment(2, -5, 2, 5))); /* along the face */
	TEST_CHECK(cd2OverlapAabbSegment(a, Segment(1, 1, 1, 1)));
	TEST_CHECK(!cd2OverlapAabbSegment(a, Segment(3, 1, 3, 1)));
	TEST_CHECK(cd2OverlapAabbSegment(Aabb(1, 1, 1, 1), Segment(0, 0, 2, 2)));
	TEST_CHECK(!cd2OverlapAabbSegment(Aabb(1, 1.01, 1, 1.01), Segment(0, 0, 2, 2)));
}

static void TestBoxPairs(void)
{
	cd2Box a = Box(0, 0, 1, 1, 0);
	TEST_CHECK(cd2OverlapBoxBox(a, QuarterBox(2, 0, 1, 1)));
	TEST_CHECK(!cd2OverlapBoxBox(a, QuarterBox(2.01, 0, 1, 1)));
	TEST_CHECK(cd2OverlapBoxBox(a, Box(1 + sqrt(2.0), 0, 1, 1, CD_PI / 4))); /* corner on face */
	TEST_CHECK(!cd2OverlapBoxBox(a, Box(1.01 + sqrt(2.0), 0, 1, 1, CD_PI / 4)));
	/* Corners pointing at each other: separated only along the diagonal axis of the second box. */
	cd2Box rotated = Box(2.5, 2.5, 1, 1, CD_PI / 4);
	TEST_CHECK(!cd2OverlapBoxBox(a, rotated)); /* gap 2.5 sqrt2 - sqrt2 - 1 along the diagonal */
	TEST_CHECK(cd2OverlapBoxBox(a, Box(1.5, 1.5, 1, 1, CD_PI / 4)));
	TEST_CHECK(cd2OverlapBoxBox(a, Box(0.1, 0.2, 0.1, 0.1, 1.0))); /* nested */
	TEST_CHECK(cd2OverlapBoxBox(a, a));
	TEST_CHECK(cd2OverlapBoxBox(Box(3, 3, 0, 0, 0.5), Box(3, 3, 0, 0, 1.5)));
	TEST_CHECK(!cd2OverlapBoxBox(Box(3, 3, 0, 0, 0.5), Box(3, 3.01, 0, 0, 1.5)));
	TEST_CHECK(cd2OverlapBoxBox(Box(0, 0, 1, 0, 0), Box(0, 0, 1, 0, CD_PI / 2))); /* crossing sticks */
	TEST_CHECK(!cd2OverlapBoxBox(Box(0, 0, 1, 0, 0), Box(2.01, 0, 1, 0, 0)));	  /* collinear sticks */
	TEST_CHECK(cd2OverlapBoxBox(Box(0, 0, 1, 0, 0), Box(2, 0, 1, 0, 0)));

	cd2Polygon triangle = Triangle(0, 0);
	/* Boxes along the diagonal, their local x axis facing the hypotenuse x + y = 2. */
	TEST_CHECK(cd2OverlapBoxPolygon(Box(2, 2, sqrt(2.0), 0.5, CD_PI / 4), &triangle));
	TEST_CHECK(!cd2OverlapBoxPolygon(Box(2, 2, 1.4, 0.5, CD_PI / 4), &triangle));
	TEST_CHECK(cd2OverlapBoxPolygon(Box(1.5, 1.5, sqrt(0.5), 1, CD_PI / 4), &triangle));
	TEST_CHECK(!cd2OverlapBoxPolygon(Box(1.51, 1.51, sqrt(0.5), 1, CD_PI / 4), &triangle));
	TEST_CHECK(cd2OverlapBoxPolygon(Box(0.3, 0.3, 0.1, 0.1, 0.2), &triangle));
	TEST_CHECK(cd2OverlapBoxPolygon(Box(0.3, 0.3, 9, 9, 0.2), &triangle));
	TEST_CHECK(cd2OverlapBoxPolygon(Box(0, 0, 0, 0, 0.2), &triangle));
	cd2Polygon square = Square(-1, -1, 2);
	TEST_CHECK(cd2OverlapBoxPolygon(Box(0, 0, 1, 1, 0), &square));	   /* coincident */
	TEST_CHECK(cd2OverlapBoxPolygon(QuarterBox(0, 3, 2, 1), &square)); /* touching the top edge */
	TEST_CHECK(!cd2OverlapBoxPolygon(QuarterBox(0, 3.01, 2, 1), &square));

	TEST_CHECK(cd2OverlapBoxSegment(a, Segment(-3, 0, 3, 0)));
	TEST_CHECK(cd2OverlapBoxSegment(a, Segment(1, 1, 3, 3)));
	TEST_CHECK(!cd2OverlapBoxSegment(a, Segment(1.01, 1.01, 3, 3)));
	cd2Box diamond = Box(0, 0, 1, 1, CD_PI / 4);
	TEST_CHECK(!cd2OverlapBoxSegment(diamond, Segment(1, 1, 3, -1.01)));
	TEST_CHECK(cd2OverlapBoxSegment(diamond, Segment(sqrt(0.5), sqrt(0.5), 3, 3)));
	TEST_CHECK(cd2OverlapBoxSegment(diamond, Segment(0.1, 0.1, 0.2, 0.2)));
	TEST_CHECK(cd2OverlapBoxSegment(diamond, Segment(0, 0, 0, 0)));
	TEST_CHECK(!cd2OverlapBoxSegment(Box(0, 0, 0, 0, 0.3), Segment(0, 0.01, 0, 0.01)));
}

static void TestPolygonSegmentAndSegments(void)
{
	cd2Polygon triangle = Triangle(0, 0);
	TEST_CHECK(cd2OverlapPolygonSegment(&triangle, Segment(2, 0, 5, 0)));	/* touching vertex */
	TEST_CHECK(cd2OverlapPolygonSegment(&triangle, Segment(3, -1, -1, 3))); /* along the hypotenuse */
	TEST_CHECK(!cd2OverlapPolygonSegment(&triangle, Segment(3.01, -1, -1, 3.01)));
	TEST_CHECK(cd2OverlapPolygonSegment(&triangle, Segment(-1, 0.5, 3, 0.5)));
	TEST_CHECK(cd2OverlapPolygonSegment(&triangle, Segment(0.2, 0.2, 0.4, 0.3)));
	TEST_CHECK(cd2OverlapPolygonSegment(&triangle, Segment(0.2, 0.2, 0.2, 0.2)));
	TEST_CHECK(cd2OverlapPolygonSegment(&triangle, Segment(0, 0, 2, 0)));  /* coincident with an edge */
	TEST_CHECK(cd2OverlapPolygonSegment(&triangle, Segment(-1, 0, 3, 0))); /* containing an edge */
	TEST_CHECK(!cd2OverlapPolygonSegment(&triangle, Segment(-1, -0.01, 3, -0.01)));
	TEST_CHECK(!cd2OverlapPolygonSegment(&triangle, Segment(2, 2, 2, 2)));

	cd2Segment a = Segment(0, 0, 4, 0);
	TEST_CHECK(cd2OverlapSegmentSegment(a, Segment(2, -1, 2, 1))); /* crossing */
	TEST_CHECK(cd2OverlapSegmentSegment(a, Segment(2, 0, 2, 1)));  /* T junction */
	TEST_CHECK(!cd2OverlapSegmentSegment(a, Segment(2, 0.01, 2, 1)));
	TEST_CHECK(cd2OverlapSegmentSegment(a, Segment(4, 0, 6, 0))); /* collinear, end to end */
	TEST_CHECK(!cd2OverlapSegmentSegment(a, Segment(4.01, 0, 6, 0)));
	TEST_CHECK(cd2OverlapSegmentSegment(a, Segment(1, 0, 2, 0)));  /* collinear, nested */
	TEST_CHECK(!cd2OverlapSegmentSegment(a, Segment(0, 1, 4, 1))); /* parallel */
	TEST_CHECK(cd2OverlapSegmentSegment(a, a));
	TEST_CHECK(cd2OverlapSegmentSegment(a, Segment(3, 0, 3, 0)));  /* point on it */
	TEST_CHECK(!cd2OverlapSegmentSegment(a, Segment(5, 0, 5, 0))); /* point beyond the end */
	TEST_CHECK(cd2OverlapSegmentSegment(Segment(1, 2, 1, 2), Segment(1, 2, 1, 2)));
	TEST_CHECK(!cd2OverlapSegmentSegment(Segment(1, 2, 1, 2), Segment(1, 2.01, 1, 2.01)));
	TEST_CHECK(!cd2OverlapSegmentSegment(a, Segment(5, 1, 6, -1))); /* lines cross beyond the end */
}

/* ---- property tests ---------------------------------------------------------------------------- */

static const char* TypeName(const cd2Shape* s)
{
	return cd2GetShapeTypeName(s->type);
}

/* The pair function named in canonical order, called directly (not through cd2Overlap). */
static bool DirectOverlap(const cd2Shape* a, const cd2Shape* b)
{
	if (a->type > b->type)
	{
		const cd2Shape* swap = a;
		a = b;
		b = swap;
	}
	int key = (int)a->type * 8 + (int)b->type;
	switch (key)
	{
		case CD2_SHAPE_CIRCLE * 8 + CD2_SHAPE_CIRCLE:
			return cd2OverlapCircleCircle(a->circle, b->circle);
		case CD2_SHAPE_CIRCLE * 8 + CD2_SHAPE_CAPSULE:
			return cd2OverlapCircleCapsule(a->circle, b->capsule);
		case CD2_SHAPE_CIRCLE * 8 + CD2_SHAPE_AABB:
			return cd2OverlapCircleAabb(a->circle, b->aabb);
		case CD2_SHAPE_CIRCLE * 8 + CD2_SHAPE_BOX:
			return cd2OverlapCircleBox(a->circle, b->box);
		case CD2_SHAPE_CIRCLE * 8 + CD2_SHAPE_POLYGON:
			return cd2OverlapCirclePolygon(a->circle, &b->polygon);
		case CD2_SHAPE_CIRCLE * 8 + CD2_SHAPE_SEGMENT:
			return cd2OverlapCircleSegment(a->circle, b->segment);
		case CD2_SHAPE_CAPSULE * 8 + CD2_SHAPE_CAPSULE:
			return cd2OverlapCapsuleCapsule(a->capsule, b->capsule);
		case CD2_SHAPE_CAPSULE * 8 + CD2_SHAPE_AABB:
			return cd2OverlapCapsuleAabb(a->capsule, b->aabb);
		case CD2_SHAPE_CAPSULE * 8 + CD2_SHAPE_BOX:
			return cd2OverlapCapsuleBox(a->capsule, b->box);
		case CD2_SHAPE_CAPSULE * 8 + CD2_SHAPE_POLYGON:
			return cd2OverlapCapsulePolygon(a->capsule, &b->polygon);
		case CD2_SHAPE_CAPSULE * 8 + CD2_SHAPE_SEGMENT:
			return cd2OverlapCapsuleSegment(a->capsule, b->segment);
		case CD2_SHAPE_AABB * 8 + CD2_SHAPE_AABB:
			return cd2OverlapAabbAabb(a->aabb, b->aabb);
		case CD2_SHAPE_AABB * 8 + CD2_SHAPE_BOX:
			return cd2OverlapAabbBox(a->aabb, b->box);
		case CD2_SHAPE_AABB * 8 + CD2_SHAPE_POLYGON:
			return cd2OverlapAabbPolygon(a->aabb, &b->polygon);
		case CD2_SHAPE_AABB * 8 + CD2_SHAPE_SEGMENT:
			return cd2OverlapAabbSegment(a->aabb, b->segment);
		case CD2_SHAPE_BOX * 8 + CD2_SHAPE_BOX:
			return cd2OverlapBoxBox(a->box, b->box);
		case CD2_SHAPE_BOX * 8 + CD2_SHAPE_POLYGON:
			return cd2OverlapBoxPolygon(a->box, &b->polygon);
		case CD2_SHAPE_BOX * 8 + CD2_SHAPE_SEGMENT:
			return cd2OverlapBoxSegment(a->box, b->segment);
		case CD2_SHAPE_POLYGON * 8 + CD2_SHAPE_POLYGON:
			return cd2OverlapPolygonPolygon(&a->polygon, &b->polygon);
		case CD2_SHAPE_POLYGON * 8 + CD2_SHAPE_SEGMENT:
			return cd2OverlapPolygonSegment(&a->polygon, b->segment);
		case CD2_SHAPE_SEGMENT * 8 + CD2_SHAPE_SEGMENT:
			return cd2OverlapSegmentSegment(a->segment, b->segment);
		default:
			TEST_CHECKF(false, "unexpected pair %d %d", (int)a->type, (int)b->type);
			return false;
	}
}

static cd2Shape Translated(const cd2Shape* s, cd2Vec t)
{
	cd2Shape r = *s;
	switch (s->type)
	{
		case CD2_SHAPE_CIRCLE:
			r.circle.center = cd2Add(s->circle.center, t);
			break;
		case CD2_SHAPE_CAPSULE:
			r.capsule.p1 = cd2Add(s->capsule.p1, t);
			r.capsule.p2 = cd2Add(s->capsule.p2, t);
			break;
		case CD2_SHAPE_AABB:
			r.aabb.min = cd2Add(s->aabb.min, t);
			r.aabb.max = cd2Add(s->aabb.max, t);
			break;
		case CD2_SHAPE_BOX:
			r.box.center = cd2Add(s->box.center, t);
			break;
		case CD2_SHAPE_POLYGON:
			for (int i = 0; i < s->polygon.count; ++i)
			{
				r.polygon.vertices[i] = cd2Add(s->polygon.vertices[i], t);
			}
			r.polygon.centroid = cd2Add(s->polygon.centroid, t);
			break;
		default:
			r.segment.p1 = cd2Add(s->segment.p1, t);
			r.segment.p2 = cd2Add(s->segment.p2, t);
			break;
	}
	return r;
}

/* The shape moved by a rigid transform; an AABB becomes the equivalent box. */
static cd2Shape Transformed(const cd2Shape* s, cd2Transform x)
{
	cd2Shape r = *s;
	switch (s->type)
	{
		case CD2_SHAPE_CIRCLE:
			r.circle.center = cd2TransformPoint(x, s->circle.center);
			break;
		case CD2_SHAPE_CAPSULE:
			r.capsule.p1 = cd2TransformPoint(x, s->capsule.p1);
			r.capsule.p2 = cd2TransformPoint(x, s->capsule.p2);
			break;
		case CD2_SHAPE_AABB:
		{
			cd2Box box = {cd2TransformPoint(x, cd2AabbCenter(s->aabb)), cd2AabbHalfExtents(s->aabb), x.q};
			r = cd2MakeBoxShape(box);
			break;
		}
		case CD2_SHAPE_BOX:
			r.box.center = cd2TransformPoint(x, s->box.center);
			r.box.rotation = cd2MulRot(x.q, s->box.rotation);
			break;
		case CD2_SHAPE_POLYGON:
		{
			cd2Vec points[CD2_MAX_POLYGON_VERTICES];
			for (int i = 0; i < s->polygon.count; ++i)
			{
				points[i] = cd2TransformPoint(x, s->polygon.vertices[i]);
			}
			cdResult result = cd2MakeRoundedPolygon(points, s->polygon.count, s->polygon.radius, &r.polygon);
			TEST_CHECKF(result == CD_OK, "transformed polygon rejected: %s", cdGetResultString(result));
			break;
		}
		default:
			r.segment.p1 = cd2TransformPoint(x, s->segment.p1);
			r.segment.p2 = cd2TransformPoint(x, s->segment.p2);
			break;
	}
	return r;
}

/* Reference classification: +1 clearly separated, -1 clearly overlapping (still overlapping after
 * moving b by `band` in eight directions), 0 too close to the boundary to call. */
static int ReferenceClass(const cd2Shape* a, const cd2Shape* b, double band)
{
	double distance = RefShapeDistance(a, b);
	if (distance > band)
	{
		return 1;
	}
	if (distance > 0.0)
	{
		return 0;
	}
	for (int k = 0; k < 8; ++k)
	{
		double angle = k * (3.14159265358979323846 / 4);
		cd2Shape moved = Translated(b, V(band * cos(angle), band * sin(angle)));
		if (RefShapeDistance(a, &moved) > 0.0)
		{
			return 0;
		}
	}
	return -1;
}

typedef struct Scale
{
	const char* name;
	double center;
	double extent;
	int pairsPerType;
} Scale;

static void CheckRandomPairs(Scale scale, uint64_t seed)
{
	TestRng rng = TestRngMake(seed);
	int decided = 0, overlapping = 0;
	for (int ta = 0; ta < CD2_SHAPE_TYPE_COUNT; ++ta)
	{
		for (int tb = 0; tb < CD2_SHAPE_TYPE_COUNT; ++tb)
		{
			for (int n = 0; n < scale.pairsPerType; ++n)
			{
				cd2Vec center = V(scale.center, -scale.center);
				cd2Shape a = RandomShape(&rng, (cd2ShapeType)ta, center, scale.extent);
				cd2Shape b = RandomShape(&rng, (cd2ShapeType)tb, center, scale.extent);
				bool ab = cd2Overlap(&a, &b);
				bool ba = cd2Overlap(&b, &a);
				TEST_CHECKF(ab == ba, "%s %s: symmetry, case %d", TypeName(&a), TypeName(&b), n);
				TEST_CHECKF(ab == DirectOverlap(&a, &b), "%s %s: dispatcher", TypeName(&a), TypeName(&b));

				double magnitude = fmax(RefShapeScale(&a), RefShapeScale(&b));
				double band = 1e-3 * scale.extent + 64.0 * (double)CD_REAL_EPSILON * magnitude;
				int expected = ReferenceClass(&a, &b, band);
				if (expected != 0)
				{
					++decided;
					overlapping += expected < 0;
					TEST_CHECKF(ab == (expected < 0),
								"%s scale: %s %s case %d: overlap %d, reference distance %.9g", scale.name,
								TypeName(&a), TypeName(&b), n, (int)ab, RefShapeDistance(&a, &b));
				}
			}
		}
	}
	/* The random scenes must exercise both answers, or this test proves nothing. */
	TEST_CHECKF(overlapping > decided / 10 && overlapping < decided - decided / 10, "%s: %d of %d overlap",
				scale.name, overlapping, decided);
}

static void TestReferenceOrdinary(void)
{
	Scale scale = {"ordinary", 0.0, 3.0, 150};
	CheckRandomPairs(scale, 0x2D0E1);
}

static void TestReferenceFar(void)
{
	/* 1e4 from the origin with shapes of size 10 (float keeps about 1e-3 there). */
	Scale scale = {"far", 1e4, 10.0, 40};
	CheckRandomPairs(scale, 0x2D0E2);
}

static void TestReferenceHuge(void)
{
#if CD_DOUBLE
	Scale scale = {"huge", 1e30, 1e27, 25};
#else
	Scale scale = {"huge", 1e9, 1e6, 25};
#endif
	CheckRandomPairs(scale, 0x2D0E3);
}

static void TestReferenceTiny(void)
{
#if CD_DOUBLE
	Scale scale = {"tiny", 0.0, 1e-30, 25};
#else
	Scale scale = {"tiny", 0.0, 1e-9, 25};
#endif
	CheckRandomPairs(scale, 0x2D0E4);
}

static void TestRigidInvariance(void)
{
	TestRng rng = TestRngMake(0x2D0E5);
	int compared = 0;
	for (int ta = 0; ta < CD2_SHAPE_TYPE_COUNT; ++ta)
	{
		for (int tb = 0; tb < CD2_SHAPE_TYPE_COUNT; ++tb)
		{
			for (int n = 0; n < 60; ++n)
			{
				cd2Shape a = RandomShape(&rng, (cd2ShapeType)ta, CD2_VEC_ZERO, 3.0);
				cd2Shape b = RandomShape(&rng, (cd2ShapeType)tb, CD2_VEC_ZERO, 3.0);
				if (ReferenceClass(&a, &b, 1e-2) == 0)
				{
					continue;
				}
				bool before = cd2Overlap(&a, &b);

				/* AABBs move by translation only ... */
				cd2Vec shift = RandomVec(&rng, CD2_VEC_ZERO, 50.0);
				cd2Shape ta2 = Translated(&a, shift), tb2 = Translated(&b, shift);
				TEST_CHECKF(cd2Overlap(&ta2, &tb2) == before, "%s %s: translation changed the answer",
							TypeName(&a), TypeName(&b));

				/* ... and become the equivalent box under a rotation. */
				cd2Transform x = {RandomVec(&rng, CD2_VEC_ZERO, 50.0),
								  cd2MakeRot(RandomReal(&rng, -CD_PI, CD_PI))};
				cd2Shape ra = Transformed(&a, x), rb = Transformed(&b, x);
				TEST_CHECKF(cd2Overlap(&ra, &rb) == before, "%s %s: rigid transform changed the answer",
							TypeName(&a), TypeName(&b));
				++compared;
			}
		}
	}
	TEST_CHECK(compared > 1000);
}

/* Support point of a shape in direction n, in double. */
static RefVec RefSupport(const cd2Shape* s, RefVec n)
{
	RefShape r = RefFromShape(s);
	int best = 0;
	for (int i = 1; i < r.count; ++i)
	{
		if (RefDot(r.points[i], n) > RefDot(r.points[best], n))
		{
			best = i;
		}
	}
	return RefMake(r.points[best].x + r.radius * n.x, r.points[best].y + r.radius * n.y);
}

/* Touching within round-off counts: b is moved so that its support point in -n meets a's support
 * point in n (so n separates them and they meet at one point, up to the rounding of the move to
 * cdReal). Every such pair must overlap; moved apart along n by `gap` it must not. */
static void CheckTouching(const char* label, double center, double extent, int perPair, uint64_t seed)
{
	TestRng rng = TestRngMake(seed);
	for (int ta = 0; ta < CD2_SHAPE_TYPE_COUNT; ++ta)
	{
		for (int tb = 0; tb < CD2_SHAPE_TYPE_COUNT; ++tb)
		{
			for (int n = 0; n < perPair; ++n)
			{
				cd2Vec origin = V(center, center);
				cd2Shape a = RandomShape(&rng, (cd2ShapeType)ta, origin, extent);
				cd2Shape b = RandomShape(&rng, (cd2ShapeType)tb, origin, extent);
				double angle = TestRngRange(&rng, -3.2, 3.2);
				RefVec normal = RefMake(cos(angle), sin(angle));
				RefVec contactA = RefSupport(&a, normal);
				RefVec contactB = RefSupport(&b, RefMake(-normal.x, -normal.y));
				cd2Shape touching = Translated(&b, V(contactA.x - contactB.x, contactA.y - contactB.y));
				/* The exact tests (circle-circle, circle-AABB, AABB-AABB) rightly see the gap the rounding
				 * of the move leaves; their touching cases are exact cases above. */
				bool exactPair = (ta == CD2_SHAPE_CIRCLE || ta == CD2_SHAPE_AABB) &&
								 (tb == CD2_SHAPE_CIRCLE || tb == CD2_SHAPE_AABB);
				TEST_CHECKF(exactPair || cd2Overlap(&a, &touching),
							"%s: %s %s case %d: touching pair not overlapping", label, TypeName(&a),
							TypeName(&b), n);
				double magnitude = fmax(RefShapeScale(&a), RefShapeScale(&touching));
				double gap = 1e-4 * extent + 64.0 * (double)CD_REAL_EPSILON * magnitude;
				cd2Shape apart = Translated(&touching, V(gap * normal.x, gap * normal.y));
				TEST_CHECKF(!cd2Overlap(&a, &apart), "%s: %s %s case %d: pair %.3g apart overlapping", label,
							TypeName(&a), TypeName(&b), n, gap);
			}
		}
	}
}

static void TestTouching(void)
{
	CheckTouching("ordinary", 0.0, 3.0, 200, 0x70C1);
	CheckTouching("far", 1e4, 10.0, 50, 0x70C2);
#if CD_DOUBLE
	CheckTouching("huge", 1e30, 1e27, 50, 0x70C3);
	CheckTouching("tiny", 0.0, 1e-30, 50, 0x70C4);
#else
	CheckTouching("huge", 1e9, 1e6, 50, 0x70C3);
	CheckTouching("tiny", 0.0, 1e-9, 50, 0x70C4);
#endif
}

/* Inside a solid by more than `band`: the reference puts p moved by band in 8 directions inside. */
static bool ClearlyInside(const cd2Shape* s, cd2Vec p, double band)
{
	for (int k = 0; k < 8; ++k)
	{
		double angle = k * (3.14159265358979323846 / 4);
		if (RefPointShapeDistance(s, cd2Add(p, V(band * cos(angle), band * sin(angle)))) > 0.0)
		{
			return false;
		}
	}
	return true;
}

/* Point containment through cd2PointInShape against the reference, for every type. */
static void CheckPointInShape(const char* label, double center, double extent, int perType, uint64_t seed)
{
	TestRng rng = TestRngMake(seed);
	cd2Vec origin = V(center, -center);
	for (int type = 0; type < CD2_SHAPE_TYPE_COUNT; ++type)
	{
		int inside = 0;
		for (int n = 0; n < perType; ++n)
		{
			cd2Shape s = RandomShape(&rng, (cd2ShapeType)type, origin, extent);
			cd2Vec p = RandomVec(&rng, origin, 1.5 * extent);
			bool onSegment = type == CD2_SHAPE_SEGMENT && n % 2 == 0;
			if (onSegment)
			{
				/* an end, or a point computed (with round-off) on the segment */
				p = n % 4 == 0 ? s.segment.p1
							   : cd2Lerp(s.segment.p1, s.segment.p2, RandomReal(&rng, 0.0, 1.0));
			}
			double magnitude = fmax(RefShapeScale(&s), fmax(fabs((double)p.x), fabs((double)p.y)));
			double band = 1e-3 * extent + 64.0 * (double)CD_REAL_EPSILON * magnitude;
			double distance = RefPointShapeDistance(&s, p);
			bool result = cd2PointInShape(&s, p);
			if (distance > band)
			{
				TEST_CHECKF(!result, "%s %s: point at distance %.9g reported inside", label, TypeName(&s),
							distance);
			}
			else if (onSegment || (type != CD2_SHAPE_SEGMENT && ClearlyInside(&s, p, band)))
			{
				TEST_CHECKF(result, "%s %s: point inside reported outside (case %d)", label, TypeName(&s), n);
				inside += result;
			}
		}
		TEST_CHECKF(inside > perType / 40, "%s %s: only %d points inside", label,
					cd2GetShapeTypeName((cd2ShapeType)type), inside);
	}
}

/* Point containment through cd2PointInShape against the reference, for every type and scale. */
static void TestPointInShapeReference(void)
{
	CheckPointInShape("ordinary", 0.0, 2.0, 800, 0x2D0E6);
	CheckPointInShape("far", 1e4, 10.0, 200, 0x2D0E7);
#if CD_DOUBLE
	CheckPointInShape("huge", 1e30, 1e27, 200, 0x2D0E8);
	CheckPointInShape("tiny", 0.0, 1e-30, 200, 0x2D0E9);
#else
	CheckPointInShape("huge", 1e9, 1e6, 200, 0x2D0E8);
	CheckPointInShape("tiny", 0.0, 1e-9, 200, 0x2D0E9);
#endif
}

/* The typed pair function on two shapes of the same type, in the order given. */
static bool SameTypeOverlap(const cd2Shape* a, const cd2Shape* b)
{
	switch (a->type)
	{
		case CD2_SHAPE_CIRCLE:
			return cd2OverlapCircleCircle(a->circle, b->circle);
		case CD2_SHAPE_CAPSULE:
			return cd2OverlapCapsuleCapsule(a->capsule, b->capsule);
		case CD2_SHAPE_AABB:
			return cd2OverlapAabbAabb(a->aabb, b->aabb);
		case CD2_SHAPE_BOX:
			return cd2OverlapBoxBox(a->box, b->box);
		case CD2_SHAPE_POLYGON:
			return cd2OverlapPolygonPolygon(&a->polygon, &b->polygon);
		default:
			return cd2OverlapSegmentSegment(a->segment, b->segment);
	}
}

/* Same-type pairs answer the same in either order (docs/API.md), also where round-off decides:
 * pairs made touching (support points meeting), then nudged by a few ulps of their coordinates,
 * at every scale; the fuzzer's polygon pair first. */
static void TestSameTypeSymmetry(void)
{
	cd2Vec pa[3] = {V(-1e9, -1e9), V(-787.5, 825), V(-1e9, -1237.5)};
	cd2Vec pb[3] = {V(-1250, -1250), V(-475, -1250), V(-287.5, 0)};
	cd2Polygon a, b;
	TEST_CHECK(cd2MakePolygon(pa, 3, &a) == CD_OK && cd2MakePolygon(pb, 3, &b) == CD_OK);
	TEST_CHECK(cd2OverlapPolygonPolygon(&a, &b) == cd2OverlapPolygonPolygon(&b, &a));

	TestRng rng = TestRngMake(0x5E1F);
	const double scales[][2] = {
		{0.0, 3.0},
		{1e4, 10.0},
#if CD_DOUBLE
		{1e30, 1e27},
		{1e30, 1e3},
		{0.0, 1e-30}
#else
		{1e9, 1e6},
		{1e9, 1e3},
		{0.0, 1e-9}
#endif
	};
	int overlapping = 0, apart = 0;
	for (int type = 0; type < CD2_SHAPE_TYPE_COUNT; ++type)
	{
		for (int n = 0; n < 2000; ++n)
		{
			const double* scale = scales[n % 5];
			cd2Vec origin = V(scale[0], -scale[0]);
			cd2Shape sa = RandomShape(&rng, (cd2ShapeType)type, origin, scale[1]);
			cd2Shape sb = RandomShape(&rng, (cd2ShapeType)type, origin, scale[1]);
			double angle = TestRngRange(&rng, -3.2, 3.2);
			RefVec normal = RefMake(cos(angle), sin(angle));
			RefVec contactA = RefSupport(&sa, normal);
			RefVec contactB = RefSupport(&sb, RefMake(-normal.x, -normal.y));
			double magnitude = fmax(RefShapeScale(&sa), RefShapeScale(&sb));
			double nudge = TestRngRange(&rng, -64.0, 64.0) * (double)CD_REAL_EPSILON * magnitude;
			cd2Shape touching = Translated(&sb, V(contactA.x - contactB.x + nudge * normal.x,
												  contactA.y - contactB.y + nudge * normal.y));
			bool ab = SameTypeOverlap(&sa, &touching), ba = SameTypeOverlap(&touching, &sa);
			TEST_CHECKF(ab == ba && cd2Overlap(&sa, &touching) == ab && cd2Overlap(&touching, &sa) == ab,
						"%s pair %d (scale %g): overlap(a, b) = %d, overlap(b, a) = %d", TypeName(&sa), n,
						scale[1], (int)ab, (int)ba);
			overlapping += ab;
			apart += !ab;
		}
	}
	/* The nudges fall on both sides of touching. */
	TEST_CHECKF(overlapping > 1000 && apart > 1000, "%d pairs overlapping, %d apart", overlapping, apart);
}

/* Slivers: triangles with a sharp tip (angles down to 1e-5), up to 1e9 (float) / 1e30 (double)
 * long and far from the origin. Containment's tolerance is relative to the offsets compared: a
 * point beyond the tip, on an edge's extension or behind the tip, is outside once its distance
 * exceeds a few hundred epsilons of its offset from the tip; points inside near the tip and the
 * vertices are inside. */
static void TestSliverPolygons(void)
{
	/* The fuzzer's sliver (tip angle 8.1e-5): the point lies on the extension of the bottom edge,
	 * 157500 beyond the tip (32500, -125000). */
	cd2Vec points[3] = {V(32500, -125000), V(1e9, -125000), V(1e9, -43750)};
	cd2Polygon sliver;
	TEST_CHECK(cd2MakePolygon(points, 3, &sliver) == CD_OK);
	TEST_CHECK(!cd2PointInPolygon(V(-125000, -125000), &sliver));
	TEST_CHECK(!cd2PointInPolygon(V(32499, -125000), &sliver));
	TEST_CHECK(cd2PointInPolygon(V(32500, -125000), &sliver));
	/* At x = 5e8 the sliver spans y from -125000 to -84376.3 (round-off there: 8 eps of 5e8 = 477 in
	 * float). */
	TEST_CHECK(cd2PointInPolygon(V(5e8, -100000), &sliver));
	TEST_CHECK(cd2PointInPolygon(V(5e8, -125000), &sliver));
	TEST_CHECK(!cd2PointInPolygon(V(5e8, -82000), &sliver));
	TEST_CHECK(!cd2PointInPolygon(V(5e8, -127000), &sliver));

	TestRng rng = TestRngMake(0x511BE5);
#if CD_DOUBLE
	const double largest = 30.0;
#else
	const double largest = 9.0;
#endif
	int built = 0, outsideChecked = 0, insideChecked = 0;
	for (int n = 0; n < 3000; ++n)
	{
		double k = pow(10.0, TestRngRange(&rng, -largest, largest));
		double angle = pow(10.0, TestRngRange(&rng, -5.0, -1.0));
		double heading = TestRngRange(&rng, -3.2, 3.2);
		double ux = cos(heading - 0.5 * angle), uy = sin(heading - 0.5 * angle);
		double wx = cos(heading + 0.5 * angle), wy = sin(heading + 0.5 * angle);
		double bx = cos(heading), by = sin(heading);
		double tipX = k * TestRngRange(&rng, -1.0, 1.0), tipY = k * TestRngRange(&rng, -1.0, 1.0);
		double l1 = k * TestRngRange(&rng, 0.5, 2.0), l2 = k * TestRngRange(&rng, 0.5, 2.0);
		cd2Vec corners[3] = {V(tipX, tipY), V(tipX + l1 * ux, tipY + l1 * uy),
							 V(tipX + l2 * wx, tipY + l2 * wy)};
		cd2Polygon polygon;
		if (cd2MakePolygon(corners, 3, &polygon) != CD_OK)
		{
			continue;
		}
		++built;
		cd2Shape shape = cd2MakePolygonShape(&polygon);
		for (int i = 0; i < polygon.count; ++i)
		{
			TEST_CHECKF(cd2PointInPolygon(polygon.vertices[i], &polygon), "case %d: vertex %d outside", n, i);
		}
		RefVec tip = RefFromVec(corners[0]);
		/* Beyond the tip: on the extension of an edge, or behind it along the bisector. */
		double d = k * pow(10.0, TestRngRange(&rng, -6.0, 0.0));
		cd2Vec beyond[2] = {V(tipX - d * ux, tipY - d * uy), V(tipX - d * bx, tipY - d * by)};
		for (int i = 0; i < 2; ++i)
		{
			double distance = RefPointShapeDistance(&shape, beyond[i]);
			double offset = sqrt(RefDistance2(RefFromVec(beyond[i]), tip));
			if (distance > 256.0 * (double)CD_REAL_EPSILON * offset)
			{
				++outsideChecked;
				TEST_CHECKF(!cd2PointInPolygon(beyond[i], &polygon),
							"case %d: point %.3g beyond the tip (angle %.3g), %.3g from the polygon, inside",
							n, offset, angle, distance);
			}
		}
		/* Inside near the tip, along the bisector: its distance to the edge lines is d sin(angle / 2). */
		cd2Vec in = V(tipX + d * bx, tipY + d * by);
		RefVec p = RefFromVec(in);
		double margin = INFINITY;
		for (int i = 0; i < 3; ++i)
		{
			RefVec a = RefFromVec(polygon.vertices[i]), b = RefFromVec(polygon.vertices[(i + 1) % 3]);
			RefVec e = RefSub(b, a);
			margin = fmin(margin, RefCross(e, RefSub(p, a)) / sqrt(RefDot(e, e)));
		}
		if (margin > 256.0 * (double)CD_REAL_EPSILON * sqrt(RefDistance2(p, tip)))
		{
			++insideChecked;
			TEST_CHECKF(cd2PointInPolygon(in, &polygon),
						"case %d: point %.3g inside from every edge line, outside", n, margin);
		}
	}
	TEST_CHECKF(built > 1000 && outsideChecked > 1000 && insideChecked > 500,
				"built %d slivers, checked %d points outside, %d inside", built, outsideChecked,
				insideChecked);
}

int main(void)
{
	TEST_RUN(TestPointIn);
	TEST_RUN(TestAabbAabb);
	TEST_RUN(TestCircleCircle);
	TEST_RUN(TestPolygonPolygon);
	TEST_RUN(TestCirclePairs);
	TEST_RUN(TestCapsulePairs);
	TEST_RUN(TestAabbPairs);
	TEST_RUN(TestBoxPairs);
	TEST_RUN(TestPolygonSegmentAndSegments);
	TEST_RUN(TestReferenceOrdinary);
	TEST_RUN(TestReferenceFar);
	TEST_RUN(TestReferenceHuge);
	TEST_RUN(TestReferenceTiny);
	TEST_RUN(TestRigidInvariance);
	TEST_RUN(TestTouching);
	TEST_RUN(TestPointInShapeReference);
	TEST_RUN(TestSameTypeSymmetry);
	TEST_RUN(TestSliverPolygons);
	return TEST_SUMMARY();
}
