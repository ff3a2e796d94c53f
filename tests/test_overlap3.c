/* Tests of the 3D overlap and point-containment queries and of the 3D dispatchers: exact cases
 * per pair (separated, touching, overlapping, nested, coincident, degenerate), and random pairs
 * of every type checked against a double-precision reference (tests/reference3.h) away from the
 * boundary, under both argument orders, a common rigid motion, and huge and tiny scales. */
#include "collide/query3.h"
#include "reference3.h"
#include "test.h"

#include <string.h>

/* ---- shape constructors from doubles (the cast to cdReal is the test's input) ------------- */

static cd3Vec V(double x, double y, double z)
{
	return cd3MakeVec((cdReal)x, (cdReal)y, (cdReal)z);
}

static cd3Shape Sph(double x, double y, double z, double r)
{
	return cd3MakeSphereShape((cd3Sphere){V(x, y, z), (cdReal)r});
}

static cd3Shape Cap(double x1, double y1, double z1, double x2, double y2, double z2, double r)
{
	return cd3MakeCapsuleShape((cd3Capsule){V(x1, y1, z1), V(x2, y2, z2), (cdReal)r});
}

static cd3Shape Abb(double x1, double y1, double z1, double x2, double y2, double z2)
{
	return cd3MakeAabbShape((cd3Aabb){V(x1, y1, z1), V(x2, y2, z2)});
}

static cd3Quat RotZ(double degrees)
{
	return cd3MakeQuatAxisAngle(V(0, 0, 1), (cdReal)(degrees * 3.14159265358979323846 / 180.0));
}

static cd3Quat RotY(double degrees)
{
	return cd3MakeQuatAxisAngle(V(0, 1, 0), (cdReal)(degrees * 3.14159265358979323846 / 180.0));
}

static cd3Shape Bx(double x, double y, double z, double hx, double hy, double hz, cd3Quat q)
{
	return cd3MakeBoxShape((cd3Box){V(x, y, z), V(hx, hy, hz), q});
}

static cd3Shape Tri(double ax, double ay, double az, double bx, double by, double bz, double cx, double cy,
					double cz)
{
	return cd3MakeTriangleShape((cd3Triangle){V(ax, ay, az), V(bx, by, bz), V(cx, cy, cz)});
}

static cd3Shape Pln(double nx, double ny, double nz, double offset)
{
	double n = sqrt(nx * nx + ny * ny + nz * nz);
	return cd3MakePlaneShape((cd3Plane){V(nx / n, ny / n, nz / n), (cdReal)offset});
}

static cd3Shape Seg(double x1, double y1, double z1, double x2, double y2, double z2)
{
	return cd3MakeSegmentShape((cd3Segment){V(x1, y1, z1), V(x2, y2, z2)});
}

/* Both argument orders through the dispatcher. */
static void Expect(cd3Shape a, cd3Shape b, bool expected, int line)
{
	bool ab = cd3Overlap(&a, &b);
	bool ba = cd3Overlap(&b, &a);
	TEST_CHECKF(ab == expected && ba == expected, "line %d: %s-%s: expected %d, got %d (swapped %d)", line,
				cd3GetShapeTypeName(a.type), cd3GetShapeTypeName(b.type), (int)expected, (int)ab, (int)ba);
}

#define EXPECT(a, b, expected) Expect(a, b, expected, __LINE__)

static const double S2 = 1.41421356237309504880; /* sqrt(2) */
static const double S3 = 1.73205080756887729353; /* sqrt(3) */
static const double K = 0.70710678118654752440;	 /* 1 / sqrt(2) */

static void TestSourceTexts(void)
{
	cd3Aabb box = {V(-1, -1, -1), V(1, 1, 1)};
	TEST_CHECK(cd3PointInAabb(V(0, 0, 0), box));
	TEST_CHECK(cd3PointInAabb(V(1, 1, 1), box));
	TEST_CHECK(cd3PointInAabb(V(-1, 0, 1), box));
	TEST_CHECK(!cd3PointInAabb(V(1.001, 0, 0), box));
	TEST_CHECK(!cd3PointInAabb(V(0, 0, -1.001), box));
	cd3Aabb point = {V(2, 2, 2), V(2, 2, 2)};
	TEST_CHECK(cd3PointInAabb(V(2, 2, 2), point));
	TEST_CHECK(!cd3PointInAabb(V(2, 2, 2.001), point));

	TEST_CHECK(cd3OverlapAabbAabb(box, box));
	TEST_CHECK(cd3OverlapAabbAabb(box, (cd3Aabb){V(1, 1, 1), V(2, 2, 2)}));
	TEST_CHECK(!cd3OverlapAabbAabb(box, (cd3Aabb){V(1.01, 1, 1), V(2, 2, 2)}));
	TEST_CHECK(cd3OverlapAabbAabb(box, (cd3Aabb){V(-0.5, -0.5, -0.5), V(0.5, 0.5, 0.5)}));
	TEST_CHECK(cd3OverlapAabbAabb(box, point) == false);
	TEST_CHECK(cd3OverlapAabbAabb(point, point));
	TEST_CHECK(cd3OverlapAabbAabb((cd3Aabb){V(-5, -0.1, -0.1), V(5, 0.1, 0.1)},
								  (cd3Aabb){V(-0.1, -5, -0.1), V(0.1, 5, 0.1)}));

	cd3Sphere s = {V(1, 0, 0), 2};
	TEST_CHECK(cd3PointInSphere(V(3, 0, 0), s));
	TEST_CHECK(cd3PointInSphere(V(1, 0, 0), s));
	TEST_CHECK(!cd3PointInSphere(V(3.001, 0, 0), s));
	TEST_CHECK(cd3PointInSphere(V(1, 0, 0), (cd3Sphere){V(1, 0, 0), 0}));
	TEST_CHECK(!cd3PointInSphere(V(1, 0, 0.001), (cd3Sphere){V(1, 0, 0), 0}));

	TEST_CHECK(cd3OverlapSphereSphere((cd3Sphere){V(0, 0, 0), 1}, (cd3Sphere){V(3, 0, 0), 2}));
	TEST_CHECK(!cd3OverlapSphereSphere((cd3Sphere){V(0, 0, 0), 1}, (cd3Sphere){V(3.01, 0, 0), 2}));
	TEST_CHECK(cd3OverlapSphereAabb((cd3Sphere){V(2, 0, 0), 1}, box));
	TEST_CHECK(!cd3OverlapSphereAabb((cd3Sphere){V(2.01, 0, 0), 1}, box));
	/* Exact touching in binary: 3-4-5 triangle of squared distances. */
	TEST_CHECK(cd3OverlapSphereAabb((cd3Sphere){V(4, 5, 0), 5}, box) == true);
	TEST_CHECK(cd3OverlapSphereAabb((cd3Sphere){V(4, 5, 0), CD_R(4.99)}, box) == false);
	TEST_CHECK(cd3OverlapSphereSphere((cd3Sphere){V(0, 0, 0), 2}, (cd3Sphere){V(3, 4, 0), 3}));
	TEST_CHECK(!cd3OverlapSphereSphere((cd3Sphere){V(0, 0, 0), 2}, (cd3Sphere){V(3, 4, 0), CD_R(2.99)}));
}

static void TestPointContainment(void)
{
	cd3Capsule c = {V(0, 0, 0), V(0, 4, 0), 1};
	TEST_CHECK(cd3PointInCapsule(V(1, 2, 0), c));
	TEST_CHECK(cd3PointInCapsule(V(0, 5, 0), c));
	TEST_CHECK(cd3PointInCapsule(V(0, 2, 0), c));
	TEST_CHECK(!cd3PointInCapsule(V(1.01, 2, 0), c));
	TEST_CHECK(!cd3PointInCapsule(V(0, -1.01, 0), c));
	TEST_CHECK(cd3PointInCapsule(V(0, 3, 0), (cd3Capsule){V(0, 0, 0), V(0, 4, 0), 0}));
	TEST_CHECK(!cd3PointInCapsule(V(0.01, 3, 0), (cd3Capsule){V(0, 0, 0), V(0, 4, 0), 0}));
	TEST_CHECK(cd3PointInCapsule(V(0, 0, 0), (cd3Capsule){V(0, 0, 0), V(0, 0, 0), 0}));

	cd3Box b = {V(1, 0, 0), V(1, 2, 3), RotZ(45)};
	TEST_CHECK(cd3PointInBox(V(1, 0, 0), b));
	TEST_CHECK(cd3PointInBox(V(1 + K, K, 0), b)); /* on the +x face */
	TEST_CHECK(cd3PointInBox(V(1 + K, K, 3), b)); /* on an edge */
	TEST_CHECK(!cd3PointInBox(V(1 + K + 0.01, K + 0.01, 0), b));
	TEST_CHECK(!cd3PointInBox(V(1, 0, 3.01), b));
	TEST_CHECK(cd3PointInBox(V(2, 2, 2), (cd3Box){V(2, 2, 2), V(0, 0, 0), RotY(30)}));
	TEST_CHECK(!cd3PointInBox(V(2, 2, 2.01), (cd3Box){V(2, 2, 2), V(0, 0, 0), RotY(30)}));

	cd3Plane p = {V(0, 1, 0), 2};
	TEST_CHECK(cd3PointInPlane(V(5, 2, 5), p));
	TEST_CHECK(cd3PointInPlane(V(5, -100, 5), p));
	TEST_CHECK(!cd3PointInPlane(V(5, 2.01, 5), p));

	/* Through the dispatcher, including the non-solid shapes. */
	cd3Shape t = Tri(0, 0, 0, 4, 0, 0, 0, 4, 0);
	TEST_CHECK(cd3PointInShape(&t, V(1, 1, 0)));
	TEST_CHECK(cd3PointInShape(&t, V(2, 2, 0)));
	TEST_CHECK(cd3PointInShape(&t, V(0, 0, 0)));
	TEST_CHECK(!cd3PointInShape(&t, V(1, 1, 0.001)));
	TEST_CHECK(!cd3PointInShape(&t, V(2.01, 2.01, 0)));
	cd3Shape line = Tri(0, 0, 0, 2, 0, 0, 4, 0, 0);
	TEST_CHECK(cd3PointInShape(&line, V(3, 0, 0)));
	TEST_CHECK(!cd3PointInShape(&line, V(3, 0.01, 0)));
	cd3Shape g = Seg(0, 0, 0, 4, 4, 4);
	TEST_CHECK(cd3PointInShape(&g, V(1, 1, 1)));
	TEST_CHECK(cd3PointInShape(&g, V(4, 4, 4)));
	TEST_CHECK(!cd3PointInShape(&g, V(1, 1, 1.01)));
	TEST_CHECK(!cd3PointInShape(&g, V(4.01, 4.01, 4.01)));
	cd3Shape dot = Seg(1, 2, 3, 1, 2, 3);
	TEST_CHECK(cd3PointInShape(&dot, V(1, 2, 3)));
	TEST_CHECK(!cd3PointInShape(&dot, V(1, 2, 3.001)));
	cd3Shape sphere = Sph(0, 0, 0, 1);
	TEST_CHECK(cd3PointInShape(&sphere, V(0, 1, 0)) && !cd3PointInShape(&sphere, V(0, 1.01, 0)));
	cd3Shape capsule = Cap(0, 0, 0, 0, 4, 0, 1);
	TEST_CHECK(cd3PointInShape(&capsule, V(0, 5, 0)) && !cd3PointInShape(&capsule, V(0, 5.01, 0)));
	cd3Shape aabb = Abb(0, 0, 0, 1, 1, 1);
	TEST_CHECK(cd3PointInShape(&aabb, V(1, 1, 1)) && !cd3PointInShape(&aabb, V(1, 1, 1.01)));
	cd3Shape box = Bx(0, 0, 0, 1, 1, 1, RotZ(45));
	TEST_CHECK(cd3PointInShape(&box, V(S2, 0, 0)) && !cd3PointInShape(&box, V(S2 + 0.01, 0, 0)));
	cd3Shape plane = Pln(0, 0, 1, 1);
	TEST_CHECK(cd3PointInShape(&plane, V(9, 9, 1)) && !cd3PointInShape(&plane, V(9, 9, 1.01)));
}

static void TestSpherePairs(void)
{
	EXPECT(Sph(0, 0, 0, 1), Sph(3, 0, 0, 2), true);
	EXPECT(Sph(0, 0, 0, 1), Sph(3.01, 0, 0, 2), false);
	EXPECT(Sph(0, 0, 0, 1), Sph(2.5, 0, 0, 2), true);
	EXPECT(Sph(0, 0, 0, 5), Sph(1, 0, 0, 1), true);
	EXPECT(Sph(1, 2, 3, 1), Sph(1, 2, 3, 1), true);
	EXPECT(Sph(1, 2, 3, 0), Sph(1, 2, 3, 0), true);
	EXPECT(Sph(0, 0, 0, 0), Sph(1, 0, 0, 1), true);
	EXPECT(Sph(0, 0, 0, 0), Sph(1.01, 0, 0, 1), false);

	cd3Shape capsule = Cap(0, 0, 0, 0, 4, 0, 1);
	EXPECT(Sph(3, 2, 0, 2), capsule, true);
	EXPECT(Sph(3.01, 2, 0, 2), capsule, false);
	EXPECT(Sph(0, 6, 0, 1), capsule, true);
	EXPECT(Sph(0, 6.01, 0, 1), capsule, false);
	EXPECT(Sph(0, 2, 0, 0.5), capsule, true);
	EXPECT(Sph(0, 2, 0, 50), capsule, true);
	EXPECT(Sph(2, 0, 0, 1), Cap(0, 0, 0, 0, 0, 0, 1), true);
	EXPECT(Sph(2.01, 0, 0, 1), Cap(0, 0, 0, 0, 0, 0, 1), false);
	EXPECT(Sph(0, 2, 0, 0), Cap(0, 0, 0, 0, 4, 0, 0), true);
	EXPECT(Sph(0.01, 2, 0, 0), Cap(0, 0, 0, 0, 4, 0, 0), false);

	cd3Shape aabb = Abb(-1, -1, -1, 1, 1, 1);
	EXPECT(Sph(2, 0, 0, 1), aabb, true);
	EXPECT(Sph(2.01, 0, 0, 1), aabb, false);
	EXPECT(Sph(2, 2, 2, 1.8), aabb, true);
	EXPECT(Sph(2, 2, 2, 1.7), aabb, false);
	EXPECT(Sph(0, 0, 0, 0.5), aabb, true);
	EXPECT(Sph(0, 0, 0, 10), aabb, true);
	EXPECT(Sph(1, 1, 2, 1), Abb(1, 1, 1, 1, 1, 1), true);
	EXPECT(Sph(1, 1, 2.01, 1), Abb(1, 1, 1, 1, 1, 1), false);

	cd3Shape box = Bx(0, 0, 0, 1, 2, 3, RotZ(45));
	EXPECT(Sph(2 * K, 2 * K, 0, 1), box, true); /* touching the +x face */
	EXPECT(Sph(2 * K + 0.01, 2 * K + 0.01, 0, 1), box, false);
	EXPECT(Sph(0, 0, 4, 1), box, true); /* touching the +z face */
	EXPECT(Sph(0, 0, 4.01, 1), box, false);
	EXPECT(Sph(0, 0, 0, 0.5), box, true);
	EXPECT(Sph(0.3, 0.2, 0.1, 0), box, true);
	EXPECT(Sph(0, 0, 0, 1), Bx(1, 0, 0, 0, 0, 0, RotY(10)), true);
	EXPECT(Sph(-0.01, 0, 0, 1), Bx(1, 0, 0, 0, 0, 0, RotY(10)), false);

	cd3Shape t = Tri(0, 0, 0, 4, 0, 0, 0, 4, 0);
	EXPECT(Sph(1, 1, 2, 2), t, true);
	EXPECT(Sph(1, 1, 2.01, 2), t, false);
	EXPECT(Sph(1, 1, -2, 2), t, true);
	EXPECT(Sph(1, 1, 0, 0), t, true);
	EXPECT(Sph(-1, 0, 0, 1), t, true);
	EXPECT(Sph(-1.01, 0, 0, 1), t, false);
	EXPECT(Sph(3, 3, 0, S2 + 0.001), t, true);
	EXPECT(Sph(3, 3, 0, S2 - 0.001), t, false);
	EXPECT(Sph(3, 1, 0, 1), Tri(0, 0, 0, 2, 0, 0, 4, 0, 0), true);
	EXPECT(Sph(3, 1.01, 0, 1), Tri(0, 0, 0, 2, 0, 0, 4, 0, 0), false);
	EXPECT(Sph(1, 1, 1, 0), Tri(1, 1, 1, 1, 1, 1, 1, 1, 1), true);

	cd3Shape plane = Pln(0, 1, 0, 2);
	EXPECT(Sph(0, 3, 0, 1), plane, true);
	EXPECT(Sph(0, 3.01, 0, 1), plane, false);
	EXPECT(Sph(0, -10, 0, 0), plane, true);
	EXPECT(Sph(0, 2, 0, 0), plane, true);
	EXPECT(Sph(0, 2.01, 0, 0), plane, false);

	cd3Shape g = Seg(0, 0, 0, 4, 0, 0);
	EXPECT(Sph(2, 1, 0, 1), g, true);
	EXPECT(Sph(2, 1.01, 0, 1), g, false);
	EXPECT(Sph(5, 0, 0, 1), g, true);
	EXPECT(Sph(5.01, 0, 0, 1), g, false);
	EXPECT(Sph(2, 0, 0, 0), g, true);
	EXPECT(Sph(4, 0, 0, 1), Seg(5, 0, 0, 5, 0, 0), true);
	EXPECT(Sph(4, 0, 0, 0.99), Seg(5, 0, 0, 5, 0, 0), false);
}

static void TestCapsulePairs(void)
{
	cd3Shape c = Cap(0, 0, 0, 0, 4, 0, 1);
	EXPECT(c, Cap(2, 0, 0, 2, 4, 0, 1), true);
	EXPECT(c, Cap(2.01, 0, 0, 2.01, 4, 0, 1), false);
	EXPECT(c, Cap(0, 6, 0, 0, 9, 0, 1), true); /* end to end */
	EXPECT(c, Cap(0, 6.01, 0, 0, 9, 0, 1), false);
	EXPECT(c, Cap(-1, 2, 1, 1, 2, 1, 0), true);
	EXPECT(Cap(0, 0, 0, 0, 4, 0, 0), Cap(-1, 2, 1, 1, 2, 1, 0), false);
	EXPECT(Cap(0, 0, 0, 0, 4, 0, 0.5), Cap(-1, 2, 1, 1, 2, 1, 0.5), true);
	EXPECT(Cap(0, 0, 0, 0, 4, 0, 0), Cap(-1, 2, 0, 1, 2, 0, 0), true);
	EXPECT(Cap(0, 0, 0, 0, 0, 0, 1), Cap(2, 0, 0, 2, 0, 0, 1), true);
	EXPECT(Cap(0, 0, 0, 0, 0, 0, 1), Cap(2.01, 0, 0, 2.01, 0, 0, 1), false);
	EXPECT(c, c, true);
	EXPECT(c, Cap(0, 1, 0, 0, 2, 0, 0.1), true);

	cd3Shape aabb = Abb(-1, -1, -1, 1, 1, 1);
	EXPECT(Cap(2, -5, 0, 2, 5, 0, 1), aabb, true);
	EXPECT(Cap(2.01, -5, 0, 2.01, 5, 0, 1), aabb, false);
	EXPECT(Cap(-5, 0, 0, 5, 0, 0, 0), aabb, true);
	EXPECT(Cap(2, 2, -5, 2, 2, 5, 1.42), aabb, true);
	EXPECT(Cap(2, 2, -5, 2, 2, 5, 1.41), aabb, false);
	EXPECT(Cap(0, 0, 0, 0.1, 0, 0, 0.1), aabb, true);
	EXPECT(Cap(3, 3, 0, 5, 5, 0, 0), aabb, false);
	EXPECT(Cap(-1, 1, 0, 1, 1, 0, 1), Abb(0, 0, 0, 0, 0, 0), true);
	EXPECT(Cap(-1, 1, 0, 1, 1, 0, 0.99), Abb(0, 0, 0, 0, 0, 0), false);
	EXPECT(Cap(1, 1, 1, 1, 1, 1, 0), aabb, true);

	cd3Shape box = Bx(0, 0, 0, 1, 1, 1, RotZ(45));
	EXPECT(Cap(S2 + 1, 0, -5, S2 + 1, 0, 5, 1), box, true);
	EXPECT(Cap(S2 + 1.01, 0, -5, S2 + 1.01, 0, 5, 1), box, false);
	EXPECT(Cap(S2 + 1, -5, 0, S2 + 1, 5, 0, 1), box, true);
	EXPECT(Cap(S2, -5, 0, S2, 5, 0, 0), box, true);
	EXPECT(Cap(S2 + 0.01, -5, 0, S2 + 0.01, 5, 0, 0), box, false);
	EXPECT(Cap(0, 0, 0, 0, 0, 0, 0), box, true);
	EXPECT(Cap(0, 0, 1, 0, 0, 1, 0), Bx(0, 0, 0, 0, 0, 0, RotZ(10)), false);
	EXPECT(Cap(0, 0, 1, 0, 0, 1, 1), Bx(0, 0, 0, 0, 0, 0, RotZ(10)), true);

	cd3Shape t = Tri(0, 0, 0, 4, 0, 0, 0, 4, 0);
	EXPECT(Cap(1, 1, 1, 1, 1, 5, 1), t, true);
	EXPECT(Cap(1, 1, 1.01, 1, 1, 5, 1), t, false);
	EXPECT(Cap(1, 1, -1, 1, 1, 1, 0), t, true);
	EXPECT(Cap(1, 1, 2, 2, 1, 2, 2), t, true);
	EXPECT(Cap(1, 1, 2, 2, 1, 2, 1.99), t, false);
	EXPECT(Cap(4, 4, -1, 4, 4, 1, S2 * 2 + 0.001), t, true);
	EXPECT(Cap(4, 4, -1, 4, 4, 1, S2 * 2 - 0.001), t, false);
	EXPECT(Cap(3, -1, 0, 3, 1, 0, 0), Tri(0, 0, 0, 2, 0, 0, 4, 0, 0), true);

	cd3Shape plane = Pln(0, 1, 0, 0);
	EXPECT(Cap(0, 2, 0, 0, 5, 0, 2), plane, true);
	EXPECT(Cap(0, 2, 0, 0, 5, 0, 1.99), plane, false);
	EXPECT(Cap(0, -1, 0, 0, 5, 0, 0), plane, true);
	EXPECT(Cap(0, 0, 0, 0, 0, 0, 0), plane, true);

	EXPECT(c, Seg(1, -1, 0, 1, 5, 0), true);
	EXPECT(c, Seg(1.01, -1, 0, 1.01, 5, 0), false);
	EXPECT(c, Seg(-3, 2, 0, 3, 2, 0), true);
	EXPECT(c, Seg(0, 2, 0, 0, 2, 0), true);
	EXPECT(Cap(0, 0, 0, 0, 0, 0, 1), Seg(1, 0, 0, 1, 0, 0), true);
}

static void TestAabbPairs(void)
{
	cd3Shape a = Abb(-1, -1, -1, 1, 1, 1);
	EXPECT(a, Abb(1, 1, 1, 2, 2, 2), true);
	EXPECT(a, Abb(1.01, 1, 1, 2, 2, 2), false);
	EXPECT(a, Abb(0, 0, 0, 0, 0, 0), true);
	EXPECT(a, a, true);

	cd3Shape box = Bx(1 + S2, 0, 0, 1, 1, 1, RotZ(45)); /* its vertex edge on the +x face */
	EXPECT(a, box, true);
	EXPECT(a, Bx(1 + S2 + 0.01, 0, 0, 1, 1, 1, RotZ(45)), false);
	EXPECT(a, Bx(1 + S2 - 0.01, 0, 0, 1, 1, 1, RotZ(45)), true);
	EXPECT(a, Bx(0, 0, 0, 0.1, 0.2, 0.3, RotY(30)), true);
	EXPECT(a, Bx(0, 0, 0, 5, 5, 5, RotY(30)), true);
	EXPECT(a, Bx(1, 1, 1, 0, 0, 0, RotY(30)), true);
	EXPECT(a, Bx(1, 1, 1.01, 0, 0, 0, RotY(30)), false);
	/* Edge against edge: a 45-degree box whose edge crosses the cube's edge (1, 1, z). */
	EXPECT(a, Bx(1 + K, 1 + K, 0, 1, 1, 5, RotZ(45)), true);
	EXPECT(a, Bx(1 + K + 0.01, 1 + K + 0.01, 0, 1, 1, 5, RotZ(45)), false);

	EXPECT(a, Tri(3, 0, 0, 0, 3, 0, 0, 0, 3), true); /* touches the corner (1, 1, 1) */
	EXPECT(a, Tri(3.01, 0, 0, 0, 3.01, 0, 0, 0, 3.01), false);
	EXPECT(a, Tri(2, 0, 0, 0, 2, 0, 0, 0, 2), true);
	EXPECT(a, Tri(1, -5, -5, 1, 5, 0, 1, -5, 5), true);
	EXPECT(a, Tri(1.01, -5, -5, 1.01, 5, 0, 1.01, -5, 5), false);
	EXPECT(a, Tri(2, 0, 0, 0, 2, 0, 3, 3, 0), true); /* its edge meets the cube's edge (1, 1, z) */
	EXPECT(a, Tri(2.01, 0.01, 0, 0.01, 2.01, 0, 3.01, 3.01, 0), false);
	EXPECT(a, Tri(-0.5, -0.5, 0, 0.5, -0.5, 0, 0, 0.5, 0), true);
	EXPECT(a, Tri(-5, -5, 0, 5, -5, 0, 0, 5, 0), true);
	EXPECT(a, Tri(2, 0, 0, 0, 2, 0, 1, 1, 0), true); /* degenerate, touching */
	EXPECT(a, Tri(2.01, 0.01, 0, 0.01, 2.01, 0, 1.01, 1.01, 0), false);
	EXPECT(Abb(0, 0, 0, 0, 0, 0), Tri(-1, -1, 0, 1, -1, 0, 0, 1, 0), true);
	EXPECT(Abb(0, 0, 0.01, 0, 0, 0.01), Tri(-1, -1, 0, 1, -1, 0, 0, 1, 0), false);

	EXPECT(a, Pln(1, 1, 1, -S3), true);
	EXPECT(a, Pln(1, 1, 1, -S3 - 0.01), false);
	EXPECT(a, Pln(0, 1, 0, -1), true);
	EXPECT(a, Pln(0, 1, 0, -1.01), false);
	EXPECT(a, Pln(0, -1, 0, 5), true);
	EXPECT(Abb(2, 2, 2, 2, 2, 2), Pln(0, 0, 1, 2), true);

	EXPECT(a, Seg(2, -1, 0, -1, 2, 0), true);
	EXPECT(a, Seg(1, 1, -5, 1, 1, 5), true);
	EXPECT(a, Seg(1.01, 1, -5, 1.01, 1, 5), false);
	EXPECT(a, Seg(0, 0, 0, 0.5, 0.5, 0.5), true);
	EXPECT(a, Seg(1, 0.5, 0.5, 1, 0.5, 0.5), true);
	EXPECT(a, Seg(3, 0, 0, 0, 3, 0), false); /* x + y = 3 misses the corner edge x + y = 2 */
	EXPECT(a, Seg(2, 0, 0, 0, 2, 0), true);
	EXPECT(a, Seg(2.01, 0.01, 0, 0.01, 2.01, 0), false);
}

static void TestBoxPairs(void)
{
	cd3Shape a = Bx(0, 0, 0, 1, 1, 1, RotZ(45));
	/* Edge against edge, perpendicular: a's edge (sqrt2, 0, z), b's edge (sqrt2, y, 0). */
	EXPECT(a, Bx(2 * S2, 0, 0, 1, 1, 1, RotY(45)), true);
	EXPECT(a, Bx(2 * S2 + 0.01, 0, 0, 1, 1, 1, RotY(45)), false);
	EXPECT(a, Bx(2 * S2 - 0.01, 0, 0, 1, 1, 1, RotY(45)), true);
	/* Face to face with a common rotation. */
	cd3Quat q = cd3NormalizeQuat(cd3MakeQuat(CD_R(0.3), CD_R(-0.5), CD_R(0.2), CD_R(0.7)));
	cd3Vec axisX = cd3RotateVector(q, V(1, 0, 0));
	cd3Vec axisY = cd3RotateVector(q, V(0, 1, 0));
	cd3Shape rotated = cd3MakeBoxShape((cd3Box){V(1, 2, 3), V(1, 2, 0.5), q});
	EXPECT(rotated, cd3MakeBoxShape((cd3Box){cd3MulAdd(V(1, 2, 3), 2, axisX), V(1, 2, 0.5), q}), true);
	EXPECT(rotated, cd3MakeBoxShape((cd3Box){cd3MulAdd(V(1, 2, 3), CD_R(2.01), axisX), V(1, 2, 0.5), q}),
		   false);
	/* Parallel edges touching: displaced along the face diagonal. */
	cd3Vec diagonal = cd3Add(cd3Scale(2, axisX), cd3Scale(4, axisY));
	EXPECT(rotated, cd3MakeBoxShape((cd3Box){cd3Add(V(1, 2, 3), diagonal), V(1, 2, 0.5), q}), true);
	EXPECT(rotated,
		   cd3MakeBoxShape((cd3Box){cd3Add(V(1, 2, 3), cd3Scale(CD_R(1.005), diagonal)), V(1, 2, 0.5), q}),
		   false);
	EXPECT(a, a, true);
	EXPECT(a, Bx(0, 0, 0, 0.1, 0.1, 0.1, RotY(17)), true);
	EXPECT(Bx(1, 1, 1, 0, 0, 0, RotY(17)), Bx(1, 1, 1, 0, 0, 0, RotZ(3)), true);
	EXPECT(Bx(1, 1, 1, 0, 0, 0, RotY(17)), Bx(1, 1, 1.01, 0, 0, 0, RotZ(3)), false);

	EXPECT(a, Tri(S2, -5, -5, S2, 5, 0, S2, -5, 5), true);
	EXPECT(a, Tri(S2 + 0.01, -5, -5, S2 + 0.01, 5, 0, S2 + 0.01, -5, 5), false);
	EXPECT(a, Tri(-0.1, 0, 0, 0.1, 0, 0, 0, 0.1, 0), true);
	EXPECT(a, Tri(S2, 0, 2, S2, 0, 3, S2, 0, 4), false); /* degenerate, above the box */
	EXPECT(a, Tri(S2, 0, 0, S2, 0, 3, S2, 0, 4), true);	 /* degenerate, touching the edge */

	EXPECT(a, Pln(1, 0, 0, -S2), true);
	EXPECT(a, Pln(1, 0, 0, -S2 - 0.01), false);
	EXPECT(a, Pln(0, 0, -1, -1), true);
	EXPECT(a, Pln(0, 0, -1, -1.01), false);

	EXPECT(a, Seg(S2, 0, -5, S2, 0, 5), true);
	EXPECT(a, Seg(S2 + 0.01, 0, -5, S2 + 0.01, 0, 5), false);
	EXPECT(a, Seg(S2, -1, 0, S2, 1, 0), true);
	EXPECT(a, Seg(0, 0, 0, 0, 0, 0), true);
	EXPECT(a, Seg(-5, -5, 1.01, 5, 5, 1.01), false);
}

static void TestTrianglePlaneSegmentPairs(void)
{
	cd3Shape t = Tri(0, 0, 0, 4, 0, 0, 0, 4, 0);
	EXPECT(t, Tri(1, 1, -1, 2, 1, 1, 1, 2, 1), true);
	EXPECT(t, Tri(1, 1, 0.01, 2, 1, 2.01, 1, 2, 2.01), false);
	EXPECT(t, Tri(1, 1, 0, 2, 1, 2, 1, 2, 2), true);
	EXPECT(t, Tri(1, 1, 0, 5, 1, 0, 1, 5, 0), true);  /* coplanar, overlapping */
	EXPECT(t, Tri(3, 3, 0, 5, 3, 0, 3, 5, 0), false); /* coplanar, apart */
	EXPECT(t, Tri(2, 2, 0, 4, 4, 0, 2, 4, 0), true);  /* coplanar, touching at a vertex */
	EXPECT(t, Tri(2.01, 2.01, 0, 4, 4, 0, 2.01, 4, 0), false);
	EXPECT(t, Tri(0.5, 0.5, 0, 1, 0.5, 0, 0.5, 1, 0), true);   /* coplanar, nested */
	EXPECT(t, Tri(4, 0, 0, 8, 0, 0, 4, -4, 0), true);		   /* coplanar, sharing a vertex */
	EXPECT(t, Tri(0, -0.01, 0, 4, -0.01, 0, 2, -4, 0), false); /* coplanar, parallel edges apart */
	EXPECT(t, Tri(0, 0, 0, 4, 0, 0, 2, -4, 0), true);		   /* coplanar, sharing an edge */
	EXPECT(t, t, true);
	EXPECT(t, Tri(2, -1, 0, 2, 1, 0, 2, 0, -3), true);
	EXPECT(t, Tri(2, -1, -0.01, 2, 1, -0.01, 2, 0, -3), false);
	EXPECT(t, Tri(0, 0, 0.01, 4, 0, 0.01, 0, 4, 0.01), false);
	EXPECT(t, Tri(1, 1, -1, 1, 1, 0, 1, 1, 1), true);
	EXPECT(t, Tri(5, 5, -1, 5, 5, 0, 5, 5, 1), false);
	EXPECT(Tri(1, 1, 1, 1, 1, 1, 1, 1, 1), Tri(1, 1, 1, 1, 1, 1, 1, 1, 1), true);
	EXPECT(Tri(1, 1, 1, 1, 1, 1, 1, 1, 1), Tri(0, 0, 0, 2, 0, 0, 4, 0, 0), false);
	EXPECT(Tri(1, -1, 0, 1, 1, 0, 1, 0, 0), Tri(0, 0, 0, 2, 0, 0, 4, 0, 0), true);

	EXPECT(t, Pln(0, 0, 1, 0), true);
	EXPECT(t, Pln(0, 0, 1, -0.01), false);
	EXPECT(t, Pln(0, 0, -1, 0), true);
	EXPECT(t, Pln(1, 1, 0, -0.01), false);
	EXPECT(t, Pln(1, 1, 0, 0), true);

	EXPECT(t, Seg(1, 1, -1, 1, 1, 1), true);
	EXPECT(t, Seg(1, 1, 0.01, 1, 1, 1), false);
	EXPECT(t, Seg(1, 1, 0, 1, 1, 1), true);
	EXPECT(t, Seg(-1, 1, 0, 5, 1, 0), true);
	EXPECT(t, Seg(5, 5, 0, 6, 6, 0), false);
	EXPECT(t, Seg(2, 2, -1, 2, 2, 1), true);
	EXPECT(t, Seg(2.01, 2.01, -1, 2.01, 2.01, 1), false);
	EXPECT(t, Seg(1, 1, 0, 1, 1, 0), true);
	EXPECT(Tri(0, 0, 0, 2, 0, 0, 4, 0, 0), Seg(3, -1, 0, 3, 1, 0), true);
	EXPECT(Tri(0, 0, 0, 2, 0, 0, 4, 0, 0), Seg(3, -1, 0.01, 3, 1, 0.01), false);

	cd3Shape p = Pln(0, 1, 0, 1);
	EXPECT(p, Pln(0, -1, 0, -1), true);
	EXPECT(p, Pln(0, -1, 0, -1.01), false);
	EXPECT(p, Pln(0, -1, 0, 5), true);
	EXPECT(p, Pln(0, -1, 0.001, -5), true); /* not opposite: they meet far away */
	EXPECT(p, Pln(1, 0, 0, -100), true);
	EXPECT(p, p, true);

	EXPECT(Pln(0, 1, 0, 0), Seg(0, 1, 0, 0, 2, 0), false);
	EXPECT(Pln(0, 1, 0, 0), Seg(0, 0, 0, 0, 5, 0), true);
	EXPECT(Pln(0, 1, 0, 0), Seg(3, 0, 0, 3, 0, 0), true);

	cd3Shape g = Seg(-1, 0, 0, 1, 0, 0);
	EXPECT(g, Seg(0, -1, 0, 0, 1, 0), true);
	EXPECT(g, Seg(0, -1, 0.01, 0, 1, 0.01), false);
	EXPECT(g, Seg(0.5, 0, 0, 3, 0, 0), true);
	EXPECT(g, Seg(1, 0, 0, 3, 0, 0), true);
	EXPECT(g, Seg(1.01, 0, 0, 3, 0, 0), false);
	EXPECT(g, Seg(0, 1, 0, 2, 1, 0), false);
	EXPECT(g, Seg(0.3, 0, 0, 0.3, 0, 0), true);
	EXPECT(g, Seg(0.3, 0.01, 0, 0.3, 0.01, 0), false);
	EXPECT(Seg(2, 2, 2, 2, 2, 2), Seg(2, 2, 2, 2, 2, 2), true);
}

/* ---- random pairs against the reference ---------------------------------------------------- */

typedef enum Verdict
{
	VERDICT_APART,
	VERDICT_OVERLAP,
	VERDICT_UNDECIDED
} Verdict;

static cd3Shape Translated(const cd3Shape* s, RVec offset)
{
	cd3Transform t = {RToVec(offset), CD3_QUAT_IDENTITY};
	return TransformShape(s, t);
}

/* The shape's defining numbers, for failure messages. */
static const char* ShapeText(const cd3Shape* s, char* buffer, size_t size)
{
	/* The union's numbers in order; the box is its largest member. */
	cdReal v[sizeof(cd3Box) / sizeof(cdReal)];
	memcpy(v, &s->box, sizeof(cd3Box));
	int count = s->type == CD3_SHAPE_SPHERE		? 4
				: s->type == CD3_SHAPE_CAPSULE	? 7
				: s->type == CD3_SHAPE_AABB		? 6
				: s->type == CD3_SHAPE_BOX		? 10
				: s->type == CD3_SHAPE_TRIANGLE ? 9
				: s->type == CD3_SHAPE_PLANE	? 4
												: 6;
	int used = snprintf(buffer, size, "%s(", cd3GetShapeTypeName(s->type));
	for (int i = 0; i < count && used > 0 && (size_t)used < size; ++i)
	{
		used += snprintf(buffer + used, size - (size_t)used, i == 0 ? "%.9g" : ", %.9g", (double)v[i]);
	}
	if (used > 0 && (size_t)used < size)
	{
		snprintf(buffer + used, size - (size_t)used, ")");
	}
	return buffer;
}

/* Apart when the reference distance exceeds `band`; overlapping when the shapes still meet
 * after moving b by `band` along each of the six axis directions (their convex Minkowski
 * difference then holds a ball of radius band / sqrt 3 around the origin); else undecided. */
static Verdict ReferenceVerdict(const cd3Shape* a, const cd3Shape* b, double band)
{
	RShape ra = RFromShape(a), rb = RFromShape(b);
	RDistance d = RComputeDistance(&ra, &rb);
	/* Zero up to the double reference's own resolution at the shapes' coordinates. */
	RShape ra0 = RFromShape(a), rb0 = RFromShape(b);
	double zero = fmax(1e-7 * band, 1e-14 * fmax(RShapeScale(&ra0), RShapeScale(&rb0)));
	if (d.lower > band)
	{
		return VERDICT_APART;
	}
	if (d.upper > zero)
	{
		return VERDICT_UNDECIDED;
	}
	RVec moves[6] = {RMake(band, 0, 0),	 RMake(-band, 0, 0), RMake(0, band, 0),
					 RMake(0, -band, 0), RMake(0, 0, band),	 RMake(0, 0, -band)};
	for (int i = 0; i < 6; ++i)
	{
		cd3Shape moved = Translated(b, moves[i]);
		RShape rm = RFromShape(&moved);
		if (RComputeDistance(&ra, &rm).upper > zero)
		{
			return VERDICT_UNDECIDED;
		}
	}
	return VERDICT_OVERLAP;
}

static cd3Transform RandomRigid(TestRng* rng, bool translationOnly, double scale)
{
	cd3Transform t;
	t.p = cd3Scale((cdReal)scale, RandomVec(rng, -5, 5));
	t.q = translationOnly ? CD3_QUAT_IDENTITY : RandomQuat(rng);
	return t;
}

/* Every pair of types, both orders, against the reference; then the same pair under a common
 * rigid motion. Counts make sure both verdicts were exercised for every pair that can have them. */
/* Shapes of size `scale` around `offset`, judged `band` away from the boundary. */
static void RunRandomPairs(double scale, double offset, double band, int casesPerPair, uint64_t seed)
{
	RVec shift = RMake(offset, -0.5 * offset, 0.25 * offset);
	TestRng rng = TestRngMake(seed);
	for (int ta = 0; ta < (int)CD3_SHAPE_HULL; ++ta) /* hulls: test_matrix3, test_hull3 */
	{
		for (int tb = ta; tb < (int)CD3_SHAPE_HULL; ++tb)
		{
			int apart = 0, overlapping = 0;
			for (int i = 0; i < casesPerPair; ++i)
			{
				cd3Shape a = RandomShape(&rng, (cd3ShapeType)ta, scale);
				cd3Shape b = RandomShape(&rng, (cd3ShapeType)tb, scale);
				if (TestRngInt(&rng, 2) == 0 && b.type != CD3_SHAPE_PLANE)
				{
					/* Move b's reference point onto a point of a: many more overlapping and
					 * near-touching pairs. */
					RShape ra = RFromShape(&a), rb = RFromShape(&b);
					RVec target = RSample(&ra, &rng, RMake(0, 0, 0), 2.0 * scale);
					b = Translated(&b, RSub(target, RReferencePoint(&rb)));
				}
				if (offset != 0.0)
				{
					a = Translated(&a, shift);
					b = Translated(&b, shift);
				}
				bool ab = cd3Overlap(&a, &b);
				bool ba = cd3Overlap(&b, &a);
				TEST_CHECKF(ab == ba, "%s-%s scale %g: order matters (%d vs %d)", cd3GetShapeTypeName(a.type),
							cd3GetShapeTypeName(b.type), scale, (int)ab, (int)ba);
				Verdict verdict = ReferenceVerdict(&a, &b, band);
				if (verdict == VERDICT_UNDECIDED)
				{
					continue;
				}
				bool expected = verdict == VERDICT_OVERLAP;
				apart += expected ? 0 : 1;
				overlapping += expected ? 1 : 0;
				char textA[256], textB[256];
				TEST_CHECKF(ab == expected, "%s and %s: got %d, reference %d",
							ShapeText(&a, textA, sizeof textA), ShapeText(&b, textB, sizeof textB), (int)ab,
							(int)expected);

				bool translationOnly = a.type == CD3_SHAPE_AABB || b.type == CD3_SHAPE_AABB;
				cd3Transform motion = RandomRigid(&rng, translationOnly, scale);
				cd3Shape ma = TransformShape(&a, motion), mb = TransformShape(&b, motion);
				bool moved = cd3Overlap(&mb, &ma);
				TEST_CHECKF(moved == expected, "moved %s and %s: got %d, reference %d",
							ShapeText(&ma, textA, sizeof textA), ShapeText(&mb, textB, sizeof textB),
							(int)moved, (int)expected);
			}
			/* Segment pairs (and segment or degenerate shapes against thin ones) rarely overlap
			 * robustly; everything else must see both verdicts. */
			bool thin = ta == CD3_SHAPE_SEGMENT || tb == CD3_SHAPE_SEGMENT ||
						(ta == CD3_SHAPE_TRIANGLE && tb == CD3_SHAPE_TRIANGLE);
			if (ta == CD3_SHAPE_PLANE && tb == CD3_SHAPE_PLANE)
			{
				continue; /* random half-spaces always meet; the exact cases cover the rest */
			}
			TEST_CHECKF(apart >= casesPerPair / 20, "%s-%s scale %g: only %d apart cases",
						cd3GetShapeTypeName((cd3ShapeType)ta), cd3GetShapeTypeName((cd3ShapeType)tb), scale,
						apart);
			if (!thin || ta == CD3_SHAPE_SPHERE || ta == CD3_SHAPE_CAPSULE || ta == CD3_SHAPE_AABB ||
				ta == CD3_SHAPE_BOX)
			{
				TEST_CHECKF(overlapping >= casesPerPair / 20, "%s-%s scale %g: only %d overlapping cases",
							cd3GetShapeTypeName((cd3ShapeType)ta), cd3GetShapeTypeName((cd3ShapeType)tb),
							scale, overlapping);
			}
		}
	}
}

static void TestRandomPairsUnitScale(void)
{
	RunRandomPairs(1.0, 0.0, 1e-3, 400, 0x5EED3201u);
}

static void TestRandomPairsHugeAndTiny(void)
{
	double huge = CD_DOUBLE ? 1e30 : 1e9, tiny = CD_DOUBLE ? 1e-30 : 1e-9;
	RunRandomPairs(huge, 0.0, 1e-3 * huge, 100, 0x5EED3202u);
	RunRandomPairs(1e6, 0.0, 1e-3 * 1e6, 100, 0x5EED3203u);
	RunRandomPairs(1e-6, 0.0, 1e-3 * 1e-6, 100, 0x5EED3204u);
	RunRandomPairs(tiny, 0.0, 1e-3 * tiny, 100, 0x5EED3205u);
}

/* Unit-sized shapes far from the origin: the band must cover the input's own resolution there
 * and the tests' tolerance, a few epsilon of the coordinates (1e3 in float: 1e-4 and 2e-3). */
static void TestRandomPairsFarFromOrigin(void)
{
	double offset = CD_DOUBLE ? 1e9 : 1e3;
	double band = CD_DOUBLE ? 1e-4 : 1e-2;
	RunRandomPairs(1.0, offset, band, 150, 0x5EED3208u);
}

/* Largest width of a bounded shape (0 for a half-space). */
static double RExtent(const RShape* s)
{
	if (s->type == CD3_SHAPE_PLANE)
	{
		return 0.0;
	}
	double extent = 0.0;
	RVec axes[3] = {RMake(1, 0, 0), RMake(0, 1, 0), RMake(0, 0, 1)};
	for (int i = 0; i < 3; ++i)
	{
		extent = fmax(extent, RDot(axes[i], RSub(RSupport(s, axes[i]), RSupport(s, RScale(-1.0, axes[i])))));
	}
	return extent;
}

/* Pairs moved into contact along their reference closest direction must overlap (touching counts),
 * and moved to a small gap must not. The exact source-text tests (sphere-sphere, sphere-AABB,
 * AABB-AABB) are left out: after rounding the moved shape, touching there is a coin toss. */
static void TestTouchingPairs(void)
{
	TestRng rng = TestRngMake(0x5EED3209u);
	const double gap = CD_DOUBLE ? 1e-9 : 1e-3;
	const double touchingSlack = 4.0 * CD_REAL_EPSILON;
	for (int ta = 0; ta < (int)CD3_SHAPE_HULL; ++ta) /* hulls: test_matrix3, test_hull3 */
	{
		for (int tb = ta; tb < (int)CD3_SHAPE_HULL; ++tb)
		{
			bool exact = (ta == CD3_SHAPE_SPHERE && (tb == CD3_SHAPE_SPHERE || tb == CD3_SHAPE_AABB)) ||
						 (ta == CD3_SHAPE_AABB && tb == CD3_SHAPE_AABB) ||
						 (ta == CD3_SHAPE_PLANE && tb == CD3_SHAPE_PLANE);
			if (exact)
			{
				continue;
			}
			int touching = 0, apart = 0;
			for (int i = 0; i < 150; ++i)
			{
				cd3Shape a = RandomShape(&rng, (cd3ShapeType)ta, 1.0);
				cd3Shape b = RandomShape(&rng, (cd3ShapeType)tb, 1.0);
				RShape ra = RFromShape(&a), rb = RFromShape(&b);
				RDistance d = RComputeDistance(&ra, &rb);
				if (!(d.lower > 0.05) || d.upper - d.lower > 1e-9)
				{
					continue;
				}
				RVec move = RSub(d.pointA, d.pointB);
				cd3Shape touch = Translated(&b, move);
				RShape rt = RFromShape(&touch);
				char textA[256], textB[256];
				/* Rounding the moved shape leaves a gap of an ulp or so; the queries absorb that
				 * relative to the shapes' size, so a pair of points must meet exactly. */
				double slack = touchingSlack * fmax(RExtent(&ra), RExtent(&rb));
				if (RComputeDistance(&ra, &rt).upper <= slack)
				{
					++touching;
					TEST_CHECKF(cd3Overlap(&a, &touch) && cd3Overlap(&touch, &a), "touching %s and %s",
								ShapeText(&a, textA, sizeof textA), ShapeText(&touch, textB, sizeof textB));
				}
				cd3Shape near = Translated(&b, RScale(1.0 - gap / d.upper, move));
				RShape rn = RFromShape(&near);
				if (RComputeDistance(&ra, &rn).lower > 0.5 * gap)
				{
					++apart;
					TEST_CHECKF(!cd3Overlap(&a, &near) && !cd3Overlap(&near, &a), "%g apart: %s and %s", gap,
								ShapeText(&a, textA, sizeof textA), ShapeText(&near, textB, sizeof textB));
				}
			}
			TEST_CHECKF(touching >= 5 && apart >= 20, "%s-%s: %d touching, %d apart cases",
						cd3GetShapeTypeName((cd3ShapeType)ta), cd3GetShapeTypeName((cd3ShapeType)tb),
						touching, apart);
		}
	}
}

/* Point containment of random points against the reference projection, with the same band. */
static void TestRandomPointInShape(void)
{
	TestRng rng = TestRngMake(0x5EED3206u);
	int inside = 0, outside = 0;
	for (int i = 0; i < 7000; ++i)
	{
		cd3ShapeType type = (cd3ShapeType)(i % (int)CD3_SHAPE_HULL);
		cd3Shape shape = RandomShape(&rng, type, 1.0);
		RShape r = RFromShape(&shape);
		RVec rp;
		if ((type == CD3_SHAPE_TRIANGLE || type == CD3_SHAPE_SEGMENT) && TestRngInt(&rng, 2) == 0)
		{
			rp = RSample(&r, &rng, RMake(0, 0, 0), 0.0);
		}
		else
		{
			rp = RFromVec(RandomVec(&rng, -3, 3));
		}
		cd3Vec p = RToVec(rp);
		rp = RFromVec(p);
		bool result = cd3PointInShape(&shape, p);
		double distance = RDist(RProject(&r, rp), rp);
		if (distance > 1e-3)
		{
			++outside;
			TEST_CHECKF(!result, "%s: point %g away reported inside", cd3GetShapeTypeName(type), distance);
			continue;
		}
		bool solid = type != CD3_SHAPE_TRIANGLE && type != CD3_SHAPE_SEGMENT;
		if (!solid)
		{
			/* On the surface up to the input's rounding: the tolerance must accept it. */
			if (distance <= 1e-9)
			{
				++inside;
				TEST_CHECKF(result, "%s: point on the shape (%g away) reported outside",
							cd3GetShapeTypeName(type), distance);
			}
			continue;
		}
		bool deep = distance == 0.0;
		for (int k = 0; k < 3 && deep; ++k)
		{
			for (int sign = -1; sign <= 1 && deep; sign += 2)
			{
				RVec q = rp;
				double step = 1e-3 * sign;
				q.x += k == 0 ? step : 0;
				q.y += k == 1 ? step : 0;
				q.z += k == 2 ? step : 0;
				deep = RDist(RProject(&r, q), q) == 0.0;
			}
		}
		if (deep)
		{
			++inside;
			TEST_CHECKF(result, "%s: deep point reported outside", cd3GetShapeTypeName(type));
		}
	}
	TEST_CHECKF(inside > 500 && outside > 1000, "inside %d, outside %d", inside, outside);
}

/* The closest point on a solid shape to a far point is contained (on the boundary), through the
 * dispatcher; the tolerance of the rotated and projected tests must accept it. */
static void TestClosestPointIsContained(void)
{
	TestRng rng = TestRngMake(0x5EED3207u);
	for (int i = 0; i < 3000; ++i)
	{
		cd3ShapeType type = (cd3ShapeType)(i % (int)CD3_SHAPE_HULL);
		if (type == CD3_SHAPE_SPHERE)
		{
			continue; /* point-in-sphere is exact by contract; its boundary points round either way */
		}
		cd3Shape shape = RandomShape(&rng, type, 1.0);
		cd3Vec p = RandomVec(&rng, -6, 6);
		cd3Vec q = cd3ClosestPointOnShape(&shape, p);
		if (type == CD3_SHAPE_PLANE)
		{
			/* The projection cancels p's normal component, so q carries an error of epsilon
			 * times |p|, not times |q| or the offset that the containment test scales with. */
			double height = RDot(RFromVec(shape.plane.normal), RFromVec(q)) - (double)shape.plane.offset;
			double magnitude = fmax(RMaxAbs(RFromVec(p)), fabs((double)shape.plane.offset));
			TEST_CHECKF(height <= 8.0 * CD_REAL_EPSILON * magnitude, "plane: closest point %g outside",
						height);
			continue;
		}
		TEST_CHECKF(cd3PointInShape(&shape, q), "%s: closest point (%g %g %g) not contained",
					cd3GetShapeTypeName(type), (double)q.x, (double)q.y, (double)q.z);
		/* And a sphere of radius 0 there overlaps the shape. */
		cd3Shape point = cd3MakeSphereShape((cd3Sphere){q, CD_R(0.0)});
		TEST_CHECKF(cd3Overlap(&point, &shape), "%s: point sphere at the closest point misses",
					cd3GetShapeTypeName(type));
	}
}

/* No NaN and no crash on degenerate and extreme inputs: every pair of degenerate shapes. */
static void TestDegenerateNeverCrash(void)
{
	cd3Shape shapes[] = {
		Sph(0, 0, 0, 0),
		Cap(0, 0, 0, 0, 0, 0, 0),
		Abb(0, 0, 0, 0, 0, 0),
		Bx(0, 0, 0, 0, 0, 0, CD3_QUAT_IDENTITY),
		Tri(0, 0, 0, 0, 0, 0, 0, 0, 0),
		Pln(0, 1, 0, 0),
		Seg(0, 0, 0, 0, 0, 0),
		Tri(0, 0, 0, 1, 1, 1, 2, 2, 2),
		Tri(0, 0, 0, 0, 0, 0, 1, 0, 0),
	};
	int count = (int)(sizeof(shapes) / sizeof(shapes[0]));
	for (int i = 0; i < count; ++i)
	{
		for (int j = 0; j < count; ++j)
		{
			/* All contain the origin, so all overlap. */
			TEST_CHECKF(cd3Overlap(&shapes[i], &shapes[j]), "%d-%d", i, j);
			cd3Shape far = Translated(&shapes[j], RMake(5, 7, 3));
			/* Far apart, except that a half-space reaches everything below it. */
			bool expected = far.type == CD3_SHAPE_PLANE;
			TEST_CHECKF(cd3Overlap(&shapes[i], &far) == expected, "%d-%d far", i, j);
		}
		cd3Vec q = cd3ClosestPointOnShape(&shapes[i], V(1, 2, 3));
		TEST_CHECK(cd3IsValidVec(q));
	}
}

/* Two half-spaces with nearly opposite normals: cd3OverlapPlanePlane and cd3Distance decide
 * together (the overlap test called normals with sine 5.1e-7 crossing while the distance called
 * them opposite and 1.2e7 apart). Exact case from the fuzzer, then sines from 0.1 to 1000
 * epsilon, across both former thresholds (4 and 16 epsilon): overlap holds exactly when the
 * distance is 0, in both orders, and a positive distance is the gap between the offsets. */
static void TestNearlyOppositeHalfSpaces(void)
{
	cd3Shape a = cd3MakePlaneShape((cd3Plane){V(8.51063831e-17, 0, -1), (cdReal)-12125000.0});
	cd3Shape b = Pln(-3.6363636e-07, -3.6363636e-07, 1, 0);
	TestRng rng = TestRngMake(0x5EED3209u);
	for (int i = 0; i <= 4000; ++i)
	{
		if (i > 0)
		{
			/* n_b = -n_a tilted by `sine` towards a random perpendicular direction. */
			double sine = (double)CD_REAL_EPSILON * pow(10.0, TestRngRange(&rng, -1.0, 3.0));
			RVec n = RFromVec(RandomUnit(&rng)), side = RCross(n, RFromVec(RandomUnit(&rng)));
			side = RScale(1.0 / RLength(side), side);
			RVec m = RAdd(RScale(-sqrt(1.0 - sine * sine), n), RScale(sine, side));
			double scale = pow(10.0, TestRngRange(&rng, -6.0, 6.0));
			a = Pln(n.x, n.y, n.z, scale * TestRngRange(&rng, -1.0, 1.0));
			b = Pln(m.x, m.y, m.z, scale * TestRngRange(&rng, -1.0, 1.0));
		}
		bool ab = cd3Overlap(&a, &b), ba = cd3Overlap(&b, &a);
		cd3ClosestPoints dab = cd3Distance(&a, &b), dba = cd3Distance(&b, &a);
		double gap = -((double)a.plane.offset + (double)b.plane.offset);
		bool consistent = ab == ba && ab == (dab.distance == CD_R(0.0)) && ba == (dba.distance == CD_R(0.0));
		bool gapRight = dab.distance == CD_R(0.0) || fabs((double)dab.distance - gap) <= 1e-5 * fabs(gap);
		TEST_CHECKF(
			consistent && gapRight,
			"case %d: normals (%.9g %.9g %.9g) and (%.9g %.9g %.9g), offsets %.9g and %.9g: overlap %d/%d, "
			"distance %.9g/%.9g (gap %.9g)",
			i, (double)a.plane.normal.x, (double)a.plane.normal.y, (double)a.plane.normal.z,
			(double)b.plane.normal.x, (double)b.plane.normal.y, (double)b.plane.normal.z,
			(double)a.plane.offset, (double)b.plane.offset, (int)ab, (int)ba, (double)dab.distance,
			(double)dba.distance, gap);
	}
}

/* Capsule-triangle and triangle-segment reject separated pairs early (bounding boxes, then the
 * triangle's plane) before the closest points: exact touching cases right at both rejection
 * bounds, then pairs placed at the radius times (1 +- 1e-3 .. 0.3) from a random point of the
 * triangle, along its normal (the plane test) and away from an edge or corner (the box test),
 * slivers included, at several scales, against the double reference away from the boundary. */
static void TestTriangleSegmentRejection(void)
{
	/* A face-parallel axis exactly at the radius above the face, and at the radius beside a
	 * corner along x (the boxes' gap equals the radius): touching. */
	cd3Shape t = Tri(0, 0, 0, 4, 0, 0, 0, 4, 0);
	Expect(t, Cap(1, 1, 2, 2, 1, 2, 2), true, __LINE__);
	Expect(t, Cap(1, 1, -2, 2, 1, -2, 2), true, __LINE__);
	Expect(t, Cap(1, 1, 2, 2, 1, 2, 1.999), false, __LINE__);
	Expect(t, Cap(6, 0, 0, 6, 1, 0, 2), true, __LINE__);
	Expect(t, Cap(6, 0, 0, 6, 1, 0, 1.999), false, __LINE__);
	Expect(t, Seg(4, 0, 0, 5, 0, 0), true, __LINE__);
	Expect(t, Seg(1, 1, 0, 2, 1, 0), true, __LINE__);
	Expect(t, Seg(1, 1, 0.001, 2, 1, 0.001), false, __LINE__);
	Expect(t, Seg(1, 1, 1, 1, 1, -1), true, __LINE__);
	double huge = CD_DOUBLE ? 1e30 : 1e9;
	cd3Shape big = Tri(0, 0, 0, 4 * huge, 0, 0, 0, 4 * huge, 0);
	Expect(big, Cap(6 * huge, 0, 0, 6 * huge, huge, 0, 2 * huge), true, __LINE__);
	Expect(big, Cap(huge, huge, 2 * huge, 2 * huge, huge, 2 * huge, 2 * huge), true, __LINE__);

	TestRng rng = TestRngMake(0x5EED3210u);
	const double scales[] = {1.0, 1e-6, 1e6, CD_DOUBLE ? 1e-30 : 1e-9, CD_DOUBLE ? 1e30 : 1e9};
	int decided[2] = {0, 0};
	for (int i = 0; i < 3000; ++i)
	{
		double scale = scales[i % 5];
		RVec a = RMake(TestRngRange(&rng, -1, 1), TestRngRange(&rng, -1, 1), TestRngRange(&rng, -1, 1));
		RVec b =
			RAdd(a, RMake(TestRngRange(&rng, -1, 1), TestRngRange(&rng, -1, 1), TestRngRange(&rng, -1, 1)));
		RVec c =
			RAdd(a, RMake(TestRngRange(&rng, -1, 1), TestRngRange(&rng, -1, 1), TestRngRange(&rng, -1, 1)));
		if (i % 4 == 0)
		{
			/* A sliver: c close to the line ab. */
			double along = TestRngRange(&rng, -0.5, 1.5), off = pow(10.0, TestRngRange(&rng, -6.0, -2.0));
			c = RAdd(RAdd(a, RScale(along, RSub(b, a))), RScale(off, RSub(c, a)));
		}
		RVec n = RCross(RSub(b, a), RSub(c, a));
		double nLength = RLength(n);
		if (!(nLength > 0.0))
		{
			continue;
		}
		n = RScale(1.0 / nLength, n);
		double radius = i % 3 == 0 ? 0.0 : TestRngRange(&rng, 0.0, 0.5);
		double u = TestRngRange(&rng, 0, 1), v = TestRngRange(&rng, 0, 1);
		RVec anchor = RAdd(a, RAdd(RScale(u, RSub(b, a)), RScale(v * (1.0 - u), RSub(c, a))));
		RVec direction = n;
		if (i % 2 == 1)
		{
			/* Away from a corner or edge: outside the triangle's box along some axis. */
			anchor = i % 4 == 1 ? b : RAdd(a, RScale(0.5, RSub(c, a)));
			direction = RFromVec(RandomUnit(&rng));
		}
		double factor = 1.0 + (TestRngInt(&rng, 2) ? 1.0 : -1.0) * pow(10.0, TestRngRange(&rng, -3.0, -0.5));
		double distance = radius > 0.0 ? factor * radius : pow(10.0, TestRngRange(&rng, -3.0, -0.5));
		RVec near = RAdd(anchor, RScale(distance * (TestRngInt(&rng, 2) ? 1.0 : -1.0), direction));
		RVec along = RCross(direction, RFromVec(RandomUnit(&rng)));
		double length = TestRngRange(&rng, 0.0, 1.0);
		RVec p1 = RAdd(near, RScale(length, along)),
			 p2 = RSub(near, RScale(length * TestRngRange(&rng, 0, 1), along));
		RVec shift = RScale(TestRngRange(&rng, -2.0, 2.0), RMake(1, 1, 1));
		a = RScale(scale, RAdd(a, shift));
		b = RScale(scale, RAdd(b, shift));
		c = RScale(scale, RAdd(c, shift));
		p1 = RScale(scale, RAdd(p1, shift));
		p2 = RScale(scale, RAdd(p2, shift));
		cd3Shape tri = Tri(a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z);
		cd3Shape other = radius > 0.0 ? Cap(p1.x, p1.y, p1.z, p2.x, p2.y, p2.z, radius * scale)
									  : Seg(p1.x, p1.y, p1.z, p2.x, p2.y, p2.z);
		Verdict verdict = ReferenceVerdict(&tri, &other, 1e-4 * scale);
		if (verdict == VERDICT_UNDECIDED)
		{
			continue;
		}
		bool expected = verdict == VERDICT_OVERLAP;
		++decided[expected];
		bool direct = radius > 0.0 ? cd3OverlapCapsuleTriangle(other.capsule, tri.triangle)
								   : cd3OverlapTriangleSegment(tri.triangle, other.segment);
		char textA[256], textB[256];
		TEST_CHECKF(direct == expected && cd3Overlap(&other, &tri) == expected,
					"%s and %s: got %d, reference %d", ShapeText(&tri, textA, sizeof textA),
					ShapeText(&other, textB, sizeof textB), (int)direct, (int)expected);
	}
	TEST_CHECKF(decided[0] >= 500 && decided[1] >= 500, "%d apart, %d overlapping cases", decided[0],
				decided[1]);
}

/* A segment nearly parallel to a flat box (or AABB) edge, tilted by `angle` towards both other
 * axes so that it crosses both face planes, and skew to the edge by `gap`: only the cross-product
 * axis separates them. Its round-off is that of each term's factors, not the largest coordinate
 * over the sine of the angle (which called a gap of 5.3e-9 at size 1 touching in double: fuzz
 * query3-double-needle-box-hull-overlap-distance). The exact distance is the gap. */
static void TestSegmentNearlyParallelToBoxEdge(void)
{
	cdReal a = CD_DOUBLE ? CD_R(5e-10) : CD_R(5e-4);
	cdReal gap = CD_DOUBLE ? CD_R(1e-10) : CD_R(1e-4);
	for (int k = 0; k < 2; ++k)
	{
		cdReal offset = k == 0 ? (cdReal)sqrt(2.0) * gap : CD_R(0.0);
		cd3Box box = {CD3_VEC_ZERO, {CD_R(1.0), CD_R(0.0), CD_R(0.0)}, CD3_QUAT_IDENTITY};
		cd3Aabb aabb = {{CD_R(-1.0), CD_R(0.0), CD_R(0.0)}, {CD_R(1.0), CD_R(0.0), CD_R(0.0)}};
		cd3Segment segment = {{CD_R(-0.5), -a, offset - a}, {CD_R(0.5), a, offset + a}};
		bool boxOverlap = cd3OverlapBoxSegment(box, segment);
		bool aabbOverlap = cd3OverlapAabbSegment(aabb, segment);
		cd3Shape shapeA = cd3MakeBoxShape(box), shapeB = cd3MakeSegmentShape(segment);
		cd3ClosestPoints d = cd3Distance(&shapeA, &shapeB);
		cdReal expected = k == 0 ? gap : CD_R(0.0);
		TEST_CHECKF(boxOverlap == (k == 1), "box, gap %g: overlap %d, distance %g", (double)expected,
					(int)boxOverlap, (double)d.distance);
		TEST_CHECKF(aabbOverlap == (k == 1), "aabb, gap %g: overlap %d", (double)expected, (int)aabbOverlap);
		TEST_CHECK_NEAR(d.distance, expected, CD_R(0.01) * gap);
	}
}

/* Two boxes flat to segments 2 long, crossing at an angle of theta (1e-7 in double, 1e-3 in
 * float), one over the other by a gap along the cross product of their directions (a mix of the
 * first one's y and z axes, so that no face axis separates them): apart by exactly the gap. The
 * box SAT's cross axis of the two edges has length sin(theta), so its absolute tolerance (16
 * epsilon of the sizes) was a band of that over the sine, 7e-8 in double: boxes 1e-8 apart
 * overlapped (fuzz_query3, double build, gaps 1.8e-9 and 5.3e-9 at an angle of 1.2e-7). Within
 * the band the SAT leaves the answer to GJK. */
static void TestNearlyParallelSegmentBoxes(void)
{
	double theta = CD_DOUBLE ? 1e-7 : 1e-3, phi = 0.7;
	cdReal gap = CD_DOUBLE ? CD_R(1e-8) : CD_R(2e-4);
	/* B turned by theta about k = (0, -sin phi, cos phi): its direction leaves x towards
	 * (0, cos phi, sin phi), and x cross it is along k. */
	cd3Vec k = {CD_R(0.0), (cdReal)-sin(phi), (cdReal)cos(phi)};
	cdReal half = (cdReal)sin(0.5 * theta);
	cd3Quat turn = {CD_R(0.0), half * k.y, half * k.z, (cdReal)cos(0.5 * theta)};
	for (int i = 0; i < 2; ++i)
	{
		cdReal offset = i == 0 ? gap : CD_R(0.0);
		cd3Box a = {CD3_VEC_ZERO, {CD_R(1.0), CD_R(0.0), CD_R(0.0)}, CD3_QUAT_IDENTITY};
		cd3Box b = {cd3Scale(offset, k), {CD_R(1.0), CD_R(0.0), CD_R(0.0)}, turn};
		cd3Aabb aabb = {{CD_R(-1.0), CD_R(0.0), CD_R(0.0)}, {CD_R(1.0), CD_R(0.0), CD_R(0.0)}};
		cd3Shape shapeA = cd3MakeBoxShape(a), shapeB = cd3MakeBoxShape(b);
		double distance = (double)cd3Distance(&shapeA, &shapeB).distance;
		bool expected = i == 1;
		TEST_CHECKF(cd3OverlapBoxBox(a, b) == expected && cd3OverlapBoxBox(b, a) == expected,
					"boxes %.3g apart: overlap %d (distance %.3g)", (double)offset,
					(int)cd3OverlapBoxBox(a, b), distance);
		TEST_CHECKF(cd3OverlapAabbBox(aabb, b) == expected, "AABB and box %.3g apart: overlap %d",
					(double)offset, (int)cd3OverlapAabbBox(aabb, b));
		TEST_CHECK_NEAR(distance, (double)offset, 0.01 * (double)gap);
	}
#if CD_DOUBLE
	/* The fuzzer's pair, to the bit (corpus regression-query3-double-nearly-parallel-segment-boxes-1). */
	cd3Box box = {
		{-1.2500000000000002e-07, -1.1500000000000002e-07, -1.1750000000000003e-07},
		{0.99999999999999978, 0, 0},
		{0.99999999999997691, -1.237499999999972e-07, -1.2499999999999716e-07, -1.2499999999999716e-07}};
	cd3Aabb flat = {{-1.2500000000000002e-07, -1.2500000000000002e-07, -1.2500000000000002e-07},
					{0.99999999999999978, -1.2500000000000002e-07, -1.2500000000000002e-07}};
	TEST_CHECK(!cd3OverlapAabbBox(flat, box));
#endif
}

/* fuzz_query3 (corpus regression-triangle-corner-on-hull-vertex): a triangle whose corner is a
 * vertex of a hull it overlaps deeply (its other corners inside and outside). The cores'
 * difference has a point at the origin, GJK's triangle passed within round-off of it, the support
 * along -v repeated a vertex, and the boolean GJK said apart. */
static void TestTriangleCornerOnHullVertex(void)
{
	cd3Vec points[5] = {{CD_R(0.5), CD_R(6.0), CD_R(0.5)},
						{CD_R(0.0), CD_R(-1.0), CD_R(-1.0)},
						{CD_R(1.0), CD_R(1.0), CD_R(1.0)},
						{CD_R(-1.0), CD_R(-1.0), CD_R(1.0)},
						{CD_R(-1.0), CD_R(1.0), CD_R(1.0)}};
	cd3Hull* hull = NULL;
	TEST_CHECK(cd3ComputeHull(points, 5, &hull) == CD_OK);
	if (hull == NULL)
	{
		return;
	}
	cd3Transform place = {CD3_VEC_ZERO,
						  {CD_R(0.0), CD_R(-0.408248276), CD_R(0.408248276), CD_R(0.816496551)}};
	cd3Shape a = cd3MakeHullShape(hull, place);
	cd3Triangle triangle = {
		{CD_R(-1.0), CD_R(1.0), CD_R(1.0)}, {CD_R(1.0), CD_R(0.0), CD_R(0.0)}, CD3_VEC_ZERO};
	cd3Shape b = cd3MakeTriangleShape(triangle);
	/* The reference: the triangle's centroid lies inside the hull. */
	TEST_CHECK(cd3PointInShape(&a, cd3MakeVec(CD_R(0.0), CD_R(1.0) / CD_R(3.0), CD_R(1.0) / CD_R(3.0))));
	TEST_CHECK(cd3Overlap(&a, &b) && cd3Overlap(&b, &a));
	TEST_CHECK(cd3Distance(&a, &b).distance == CD_R(0.0) && cd3Distance(&b, &a).distance == CD_R(0.0));
	cd3DestroyHull(hull);
}

int main(void)
{
	TEST_RUN(TestSourceTexts);
	TEST_RUN(TestPointContainment);
	TEST_RUN(TestSpherePairs);
	TEST_RUN(TestCapsulePairs);
	TEST_RUN(TestAabbPairs);
	TEST_RUN(TestBoxPairs);
	TEST_RUN(TestTrianglePlaneSegmentPairs);
	TEST_RUN(TestRandomPairsUnitScale);
	TEST_RUN(TestRandomPairsHugeAndTiny);
	TEST_RUN(TestRandomPairsFarFromOrigin);
	TEST_RUN(TestTouchingPairs);
	TEST_RUN(TestRandomPointInShape);
	TEST_RUN(TestClosestPointIsContained);
	TEST_RUN(TestDegenerateNeverCrash);
	TEST_RUN(TestNearlyOppositeHalfSpaces);
	TEST_RUN(TestTriangleSegmentRejection);
	TEST_RUN(TestSegmentNearlyParallelToBoxEdge);
	TEST_RUN(TestNearlyParallelSegmentBoxes);
	TEST_RUN(TestTriangleCornerOnHullVertex);
	return TEST_SUMMARY();
}
