/* Tests of the 3D shapes: type names, tagged-shape makers, validators (with reasons), bounds. */
#include "collide/geometry3.h"
#include "collide/query3.h"
#include "reference3.h"
#include "test.h"

#include <string.h>

static const cdReal nan_ = (cdReal)NAN;
static const cdReal inf_ = (cdReal)INFINITY;

static void TestTypeNamesAndMakers(void)
{
	const char* names[] = {"sphere", "capsule", "aabb", "box", "triangle", "plane", "segment", "hull"};
	for (int i = 0; i < (int)CD3_SHAPE_TYPE_COUNT; ++i)
	{
		TEST_CHECKF(strcmp(cd3GetShapeTypeName((cd3ShapeType)i), names[i]) == 0, "type %d", i);
	}
	TEST_CHECK(strcmp(cd3GetShapeTypeName(CD3_SHAPE_TYPE_COUNT), "unknown") == 0);
	TEST_CHECK(strcmp(cd3GetShapeTypeName((cd3ShapeType)99), "unknown") == 0);

	cd3Sphere sphere = {{1, 2, 3}, 4};
	cd3Shape s = cd3MakeSphereShape(sphere);
	TEST_CHECK(s.type == CD3_SHAPE_SPHERE && s.sphere.radius == 4 && s.sphere.center.z == 3);
	cd3Capsule capsule = {{1, 2, 3}, {4, 5, 6}, 7};
	s = cd3MakeCapsuleShape(capsule);
	TEST_CHECK(s.type == CD3_SHAPE_CAPSULE && s.capsule.p2.y == 5 && s.capsule.radius == 7);
	cd3Aabb aabb = {{-1, -2, -3}, {1, 2, 3}};
	s = cd3MakeAabbShape(aabb);
	TEST_CHECK(s.type == CD3_SHAPE_AABB && s.aabb.min.y == -2 && s.aabb.max.z == 3);
	cd3Box box = {{1, 1, 1}, {2, 3, 4}, CD3_QUAT_IDENTITY};
	s = cd3MakeBoxShape(box);
	TEST_CHECK(s.type == CD3_SHAPE_BOX && s.box.halfExtents.z == 4 && s.box.rotation.w == 1);
	cd3Triangle triangle = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
	s = cd3MakeTriangleShape(triangle);
	TEST_CHECK(s.type == CD3_SHAPE_TRIANGLE && s.triangle.b.x == 1 && s.triangle.c.y == 1);
	cd3Plane plane = {{0, 1, 0}, 2};
	s = cd3MakePlaneShape(plane);
	TEST_CHECK(s.type == CD3_SHAPE_PLANE && s.plane.normal.y == 1 && s.plane.offset == 2);
	cd3Segment segment = {{0, 0, 0}, {0, 0, 5}};
	s = cd3MakeSegmentShape(segment);
	TEST_CHECK(s.type == CD3_SHAPE_SEGMENT && s.segment.p2.z == 5);
}

static void TestValidators(void)
{
	cd3Aabb aabb = {{-1, -1, -1}, {1, 1, 1}};
	TEST_CHECK(cd3IsValidAabb(aabb));
	cd3Aabb point = {{2, 2, 2}, {2, 2, 2}};
	TEST_CHECK(cd3IsValidAabb(point));
	cd3Aabb inverted = {{1, -1, -1}, {0, 1, 1}};
	TEST_CHECK(!cd3IsValidAabb(inverted));
	aabb.max.y = nan_;
	TEST_CHECK(!cd3IsValidAabb(aabb));
	aabb.max.y = inf_;
	TEST_CHECK(!cd3IsValidAabb(aabb));

	cd3Sphere sphere = {{0, 0, 0}, 1};
	TEST_CHECK(cd3IsValidSphere(sphere));
	sphere.radius = 0;
	TEST_CHECK(cd3IsValidSphere(sphere));
	sphere.radius = CD_R(-0.001);
	TEST_CHECK(!cd3IsValidSphere(sphere));
	sphere.radius = inf_;
	TEST_CHECK(!cd3IsValidSphere(sphere));
	sphere.radius = 1;
	sphere.center.x = nan_;
	TEST_CHECK(!cd3IsValidSphere(sphere));

	cd3Capsule capsule = {{0, 0, 0}, {0, 0, 0}, 0};
	TEST_CHECK(cd3IsValidCapsule(capsule));
	capsule.radius = -1;
	TEST_CHECK(!cd3IsValidCapsule(capsule));
	capsule.radius = 1;
	capsule.p2.z = -inf_;
	TEST_CHECK(!cd3IsValidCapsule(capsule));
	capsule.p2.z = 0;
	capsule.radius = nan_;
	TEST_CHECK(!cd3IsValidCapsule(capsule));

	cd3Segment segment = {{0, 0, 0}, {0, 0, 0}};
	TEST_CHECK(cd3IsValidSegment(segment));
	segment.p1.y = nan_;
	TEST_CHECK(!cd3IsValidSegment(segment));

	cd3Triangle triangle = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
	TEST_CHECK(cd3IsValidTriangle(triangle));
	cd3Triangle tiny = {{CD_R(1e-9), 0, 0}, {CD_R(2e-9), 0, 0}, {CD_R(1e-9), CD_R(1e-9), 0}};
	TEST_CHECK(cd3IsValidTriangle(tiny));
	cd3Triangle huge = {{CD_R(1e9), 0, 0}, {CD_R(-1e9), 0, 0}, {0, CD_R(1e9), CD_R(1e9)}};
	TEST_CHECK(cd3IsValidTriangle(huge));
	cd3Triangle collinear = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
	TEST_CHECK(!cd3IsValidTriangle(collinear));
	cd3Triangle coincident = {{1, 1, 1}, {1, 1, 1}, {2, 2, 2}};
	TEST_CHECK(!cd3IsValidTriangle(coincident));
	cd3Triangle allSame = {{1, 1, 1}, {1, 1, 1}, {1, 1, 1}};
	TEST_CHECK(!cd3IsValidTriangle(allSame));
	triangle.c.z = inf_;
	TEST_CHECK(!cd3IsValidTriangle(triangle));

	cd3Plane plane = {{0, 0, 1}, -3};
	TEST_CHECK(cd3IsValidPlane(plane));
	plane.normal = cd3MakeVec(0, 0, CD_R(1.1));
	TEST_CHECK(!cd3IsValidPlane(plane));
	plane.normal = CD3_VEC_ZERO;
	TEST_CHECK(!cd3IsValidPlane(plane));
	plane.normal = cd3MakeVec(0, 0, 1);
	plane.offset = nan_;
	TEST_CHECK(!cd3IsValidPlane(plane));
	cd3Plane diagonal = {cd3Normalize(cd3MakeVec(1, 2, 3)), 1};
	TEST_CHECK(cd3IsValidPlane(diagonal));

	cd3Box box = {{0, 0, 0}, {1, 0, 2}, CD3_QUAT_IDENTITY};
	TEST_CHECK(cd3IsValidBox(box));
	box.rotation = cd3MakeQuatAxisAngle(cd3MakeVec(1, 1, 0), CD_R(0.7));
	TEST_CHECK(cd3IsValidBox(box));
	box.rotation = cd3MakeQuat(0, 0, 0, 2);
	TEST_CHECK(!cd3IsValidBox(box));
	box.rotation = cd3MakeQuat(0, 0, 0, 0);
	TEST_CHECK(!cd3IsValidBox(box));
	box.rotation = cd3MakeQuat(nan_, 0, 0, 1);
	TEST_CHECK(!cd3IsValidBox(box));
	box.rotation = CD3_QUAT_IDENTITY;
	box.halfExtents.x = -1;
	TEST_CHECK(!cd3IsValidBox(box));

	cd3Ray ray = {{0, 0, 0}, {0, 0, 0}};
	TEST_CHECK(cd3IsValidRay(ray));
	ray.translation.x = inf_;
	TEST_CHECK(!cd3IsValidRay(ray));
}

static void TestValidateShapeReasons(void)
{
	TEST_CHECK(cd3ValidateShape(NULL) == CD_ERROR_INVALID_ARGUMENT);
	TEST_CHECK(!cd3IsValidShape(NULL));
	cd3Shape s = cd3MakeSphereShape((cd3Sphere){{0, 0, 0}, 1});
	TEST_CHECK(cd3ValidateShape(&s) == CD_OK && cd3IsValidShape(&s));
	s.sphere.radius = -1;
	TEST_CHECK(cd3ValidateShape(&s) == CD_ERROR_NEGATIVE_SIZE);
	s.sphere.center.x = nan_;
	TEST_CHECK(cd3ValidateShape(&s) == CD_ERROR_NOT_FINITE);

	s = cd3MakeCapsuleShape((cd3Capsule){{0, 0, 0}, {1, 0, 0}, -2});
	TEST_CHECK(cd3ValidateShape(&s) == CD_ERROR_NEGATIVE_SIZE);

	s = cd3MakeAabbShape((cd3Aabb){{0, 0, 0}, {1, -1, 1}});
	TEST_CHECK(cd3ValidateShape(&s) == CD_ERROR_NEGATIVE_SIZE);
	s.aabb.min.z = inf_;
	TEST_CHECK(cd3ValidateShape(&s) == CD_ERROR_NOT_FINITE);

	s = cd3MakeBoxShape((cd3Box){{0, 0, 0}, {1, 1, 1}, {0, 0, CD_R(0.5), 1}});
	TEST_CHECK(cd3ValidateShape(&s) == CD_ERROR_NOT_NORMALIZED);
	s.box.halfExtents.z = -1;
	TEST_CHECK(cd3ValidateShape(&s) == CD_ERROR_NEGATIVE_SIZE);

	s = cd3MakeTriangleShape((cd3Triangle){{0, 0, 0}, {1, 0, 0}, {2, 0, 0}});
	TEST_CHECK(cd3ValidateShape(&s) == CD_ERROR_DEGENERATE);
	s.triangle.b.y = nan_;
	TEST_CHECK(cd3ValidateShape(&s) == CD_ERROR_NOT_FINITE);

	s = cd3MakePlaneShape((cd3Plane){{0, 2, 0}, 0});
	TEST_CHECK(cd3ValidateShape(&s) == CD_ERROR_NOT_NORMALIZED);
	s.plane.offset = inf_;
	TEST_CHECK(cd3ValidateShape(&s) == CD_ERROR_NOT_FINITE);

	s = cd3MakeSegmentShape((cd3Segment){{0, 0, 0}, {0, 0, inf_}});
	TEST_CHECK(cd3ValidateShape(&s) == CD_ERROR_NOT_FINITE);

	s.type = CD3_SHAPE_TYPE_COUNT;
	TEST_CHECK(cd3ValidateShape(&s) == CD_ERROR_INVALID_ARGUMENT);
	s.type = (cd3ShapeType)-1;
	TEST_CHECK(cd3ValidateShape(&s) == CD_ERROR_INVALID_ARGUMENT);

	/* Every random shape that is not degenerate is valid; degenerate triangles are rejected. */
	TestRng rng = TestRngMake(0x5EED3001u);
	for (int i = 0; i < 2000; ++i)
	{
		cd3ShapeType type = (cd3ShapeType)TestRngInt(&rng, (int)CD3_SHAPE_HULL); /* hulls: test_hull3 */
		cd3Shape shape = RandomShape(&rng, type, 1.0);
		cdResult result = cd3ValidateShape(&shape);
		if (type == CD3_SHAPE_TRIANGLE)
		{
			cd3Triangle t = shape.triangle;
			cd3Vec n = cd3Cross(cd3Sub(t.b, t.a), cd3Sub(t.c, t.a));
			cdReal sine = cd3Length(n) / (cd3VecDistance(t.a, t.b) * cd3VecDistance(t.a, t.c));
			bool coincident = cd3VecEqual(t.a, t.b) || cd3VecEqual(t.b, t.c) || cd3VecEqual(t.c, t.a);
			if (coincident)
			{
				TEST_CHECKF(result == CD_ERROR_DEGENERATE, "coincident vertices: result %d", (int)result);
			}
			else if (sine > CD_R(1e-3))
			{
				TEST_CHECKF(result == CD_OK, "sine %g: result %d", (double)sine, (int)result);
			}
		}
		else
		{
			TEST_CHECKF(result == CD_OK, "%s result %d", cd3GetShapeTypeName(type), (int)result);
		}
	}
}

static void TestExactBounds(void)
{
	cd3Aabb b = cd3ComputeSphereAabb((cd3Sphere){{1, 2, 3}, 2});
	TEST_CHECK(cd3VecEqual(b.min, cd3MakeVec(-1, 0, 1)) && cd3VecEqual(b.max, cd3MakeVec(3, 4, 5)));
	b = cd3ComputeSphereAabb((cd3Sphere){{1, 2, 3}, 0});
	TEST_CHECK(cd3VecEqual(b.min, cd3MakeVec(1, 2, 3)) && cd3VecEqual(b.max, cd3MakeVec(1, 2, 3)));

	b = cd3ComputeCapsuleAabb((cd3Capsule){{1, 0, 0}, {-1, 2, 0}, 1});
	TEST_CHECK(cd3VecEqual(b.min, cd3MakeVec(-2, -1, -1)) && cd3VecEqual(b.max, cd3MakeVec(2, 3, 1)));

	b = cd3ComputeBoxAabb((cd3Box){{1, 1, 1}, {1, 2, 3}, CD3_QUAT_IDENTITY});
	TEST_CHECK(cd3VecEqual(b.min, cd3MakeVec(0, -1, -2)) && cd3VecEqual(b.max, cd3MakeVec(2, 3, 4)));
	/* 90 degrees about z swaps the x and y extents. */
	b = cd3ComputeBoxAabb(
		(cd3Box){{0, 0, 0}, {1, 2, 3}, cd3MakeQuatAxisAngle(cd3MakeVec(0, 0, 1), CD_PI * CD_R(0.5))});
	TEST_CHECK_NEAR(b.max.x, 2, 1e-5);
	TEST_CHECK_NEAR(b.max.y, 1, 1e-5);
	TEST_CHECK_NEAR(b.max.z, 3, 1e-5);
	TEST_CHECK_NEAR(b.min.x, -2, 1e-5);
	/* 45 degrees about z: the x extent is (1 + 2) / sqrt(2). */
	b = cd3ComputeBoxAabb(
		(cd3Box){{0, 0, 0}, {1, 2, 3}, cd3MakeQuatAxisAngle(cd3MakeVec(0, 0, 1), CD_PI * CD_R(0.25))});
	TEST_CHECK_NEAR(b.max.x, 3.0 / sqrt(2.0), 1e-5);
	TEST_CHECK_NEAR(b.max.y, 3.0 / sqrt(2.0), 1e-5);
	/* A quaternion at the edge of the validator's tolerance must not shrink the bounds. */
	cdReal stretch = CD_DOUBLE ? CD_R(1.0) : CD_R(1.00004);
	b = cd3ComputeBoxAabb((cd3Box){{0, 0, 0}, {1, 1, 1}, {0, 0, 0, stretch}});
	TEST_CHECK_NEAR(b.max.x, 1, 1e-6);

	b = cd3ComputeTriangleAabb((cd3Triangle){{0, 5, 0}, {1, -1, 2}, {-3, 0, 1}});
	TEST_CHECK(cd3VecEqual(b.min, cd3MakeVec(-3, -1, 0)) && cd3VecEqual(b.max, cd3MakeVec(1, 5, 2)));
	b = cd3ComputeSegmentAabb((cd3Segment){{0, 5, 0}, {1, -1, 2}});
	TEST_CHECK(cd3VecEqual(b.min, cd3MakeVec(0, -1, 0)) && cd3VecEqual(b.max, cd3MakeVec(1, 5, 2)));

	/* Half-spaces: bounded only along an axis-aligned normal. */
	b = cd3ComputePlaneAabb((cd3Plane){{0, 1, 0}, 2});
	TEST_CHECK(b.max.y == 2 && b.min.y == -CD_REAL_MAX && b.max.x == CD_REAL_MAX && b.min.z == -CD_REAL_MAX);
	b = cd3ComputePlaneAabb((cd3Plane){{0, -1, 0}, 2});
	TEST_CHECK(b.min.y == -2 && b.max.y == CD_REAL_MAX);
	b = cd3ComputePlaneAabb((cd3Plane){{-1, 0, 0}, -3});
	TEST_CHECK(b.min.x == 3 && b.max.x == CD_REAL_MAX && b.min.y == -CD_REAL_MAX);
	b = cd3ComputePlaneAabb((cd3Plane){{0, 0, 1}, -1});
	TEST_CHECK(b.max.z == -1 && b.min.z == -CD_REAL_MAX);
	b = cd3ComputePlaneAabb((cd3Plane){cd3Normalize(cd3MakeVec(1, 1, 0)), 0});
	TEST_CHECK(b.min.x == -CD_REAL_MAX && b.max.x == CD_REAL_MAX && b.min.y == -CD_REAL_MAX &&
			   b.max.y == CD_REAL_MAX && b.max.z == CD_REAL_MAX);

	cd3Shape s = cd3MakeSegmentShape((cd3Segment){{0, 5, 0}, {1, -1, 2}});
	b = cd3ComputeShapeAabb(&s);
	TEST_CHECK(cd3VecEqual(b.min, cd3MakeVec(0, -1, 0)));
	s = cd3MakeAabbShape((cd3Aabb){{0, 1, 2}, {3, 4, 5}});
	b = cd3ComputeShapeAabb(&s);
	TEST_CHECK(cd3VecEqual(b.min, cd3MakeVec(0, 1, 2)) && cd3VecEqual(b.max, cd3MakeVec(3, 4, 5)));
}

static bool InsideWithTolerance(cd3Aabb b, RVec p, double tolerance)
{
	return (double)b.min.x - tolerance <= p.x && p.x <= (double)b.max.x + tolerance &&
		   (double)b.min.y - tolerance <= p.y && p.y <= (double)b.max.y + tolerance &&
		   (double)b.min.z - tolerance <= p.z && p.z <= (double)b.max.z + tolerance;
}

/* Random points of every shape, and closest points of far points, lie in the shape's bounds;
 * and the bounds are tight: each face of the box is reached by a support point. */
static void TestRandomBounds(void)
{
	TestRng rng = TestRngMake(0x5EED3002u);
	const double scales[] = {1.0, 1e-6, 1e6, CD_DOUBLE ? 1e30 : 1e9, CD_DOUBLE ? 1e-30 : 1e-9};
	for (int i = 0; i < 3000; ++i)
	{
		double scale = scales[i % 5];
		cd3ShapeType type = (cd3ShapeType)TestRngInt(&rng, (int)CD3_SHAPE_HULL); /* hulls: test_hull3 */
		cd3Shape shape = RandomShape(&rng, type, scale);
		cd3Aabb b = cd3ComputeShapeAabb(&shape);
		TEST_CHECK(cd3IsValidAabb(b));
		RShape r = RFromShape(&shape);
		double tolerance = 8.0 * CD_REAL_EPSILON * RShapeScale(&r);
		if (type == CD3_SHAPE_PLANE)
		{
			for (int k = 0; k < 20; ++k)
			{
				RVec p = RSample(&r, &rng, RMake(0, 0, 0), 5.0 * scale);
				TEST_CHECKF(InsideWithTolerance(b, p, tolerance), "plane sample outside its bounds");
			}
			continue;
		}
		for (int k = 0; k < 20; ++k)
		{
			RVec p = RSample(&r, &rng, RMake(0, 0, 0), 0.0);
			TEST_CHECKF(InsideWithTolerance(b, p, tolerance),
						"%s sample (%g %g %g) outside [%g %g %g]-[%g %g %g]", cd3GetShapeTypeName(type), p.x,
						p.y, p.z, (double)b.min.x, (double)b.min.y, (double)b.min.z, (double)b.max.x,
						(double)b.max.y, (double)b.max.z);
			cd3Vec far = cd3Scale((cdReal)scale, RandomVec(&rng, -10, 10));
			cd3Vec closest = cd3ClosestPointOnShape(&shape, far);
			TEST_CHECKF(InsideWithTolerance(b, RFromVec(closest), tolerance), "%s closest point outside",
						cd3GetShapeTypeName(type));
		}
		/* Tight: the support point along each axis direction reaches the face. */
		RVec directions[6] = {RMake(1, 0, 0),  RMake(-1, 0, 0), RMake(0, 1, 0),
							  RMake(0, -1, 0), RMake(0, 0, 1),	RMake(0, 0, -1)};
		double faces[6] = {(double)b.max.x,	 -(double)b.min.x, (double)b.max.y,
						   -(double)b.min.y, (double)b.max.z,  -(double)b.min.z};
		for (int k = 0; k < 6; ++k)
		{
			double reach = RDot(RSupport(&r, directions[k]), directions[k]);
			TEST_CHECKF(fabs(reach - faces[k]) <= tolerance, "%s face %d: support %g bound %g",
						cd3GetShapeTypeName(type), k, reach, faces[k]);
		}
	}
}

/* The supported range: a box or hull longer than CD3_MAX_ASPECT_RATIO times its thinnest is
 * refused with CD_ERROR_OUT_OF_RANGE (only sizes beyond the float range reach it in float). */
static void TestAspectRatioRange(void)
{
	cdReal limit = (cdReal)CD3_MAX_ASPECT_RATIO;
	cd3Quat q = cd3MakeQuat(CD_R(0.0), CD_R(0.6), CD_R(0.0), CD_R(0.8));
	cd3Box box = {{CD_R(3.0), CD_R(-2.0), CD_R(1.0)}, {CD_R(1.0), CD_R(1.0), CD_R(1.0)}, q};
	cd3Shape shape = cd3MakeBoxShape(box);
	TEST_CHECK(cd3ValidateShape(&shape) == CD_OK);
	/* Zero extents stay valid whatever the others: a rectangle, a segment, a point. */
	box.halfExtents = cd3MakeVec(CD_R(1e9), CD_R(0.0), CD_R(0.0));
	shape = cd3MakeBoxShape(box);
	TEST_CHECK(cd3ValidateShape(&shape) == CD_OK && cd3IsValidBox(box));
	box.halfExtents = CD3_VEC_ZERO;
	TEST_CHECK(cd3IsValidBox(box));
#if CD_DOUBLE
	TEST_CHECK(limit == CD_R(1e6));
	box.halfExtents = cd3MakeVec(CD_R(1.0), CD_R(0.5) * limit, CD_R(2.0));
	TEST_CHECK(cd3IsValidBox(box));
	box.halfExtents = cd3MakeVec(CD_R(1.0), CD_R(2.0) * limit, CD_R(2.0));
	shape = cd3MakeBoxShape(box);
	TEST_CHECK(!cd3IsValidBox(box));
	TEST_CHECK(cd3ValidateShape(&shape) == CD_ERROR_OUT_OF_RANGE);
	TEST_CHECK(!cd3IsValidShape(&shape));
	/* A sheet: one extent thin against the other two. */
	box.halfExtents = cd3MakeVec(CD_R(1e3), CD_R(1e3), CD_R(1e3) / (CD_R(2.0) * limit));
	TEST_CHECK(!cd3IsValidBox(box));
	/* A hull: the box of half extents (length, width, width) as points, aspect length / width. */
	for (int k = 0; k < 2; ++k)
	{
		cdReal width = CD_R(1e4);
		cdReal length = (k == 0 ? CD_R(4.0) : CD_R(0.25)) * (cdReal)CD3_MAX_HULL_ASPECT_RATIO * width;
		cd3Vec points[8];
		for (int i = 0; i < 8; ++i)
		{
			points[i] =
				cd3MakeVec((i & 1) ? length : -length, (i & 2) ? width : -width, (i & 4) ? width : -width);
		}
		cd3Hull* hull = NULL;
		cdResult result = cd3ComputeHull(points, 8, &hull);
		TEST_CHECKF(k == 0 ? result == CD_ERROR_OUT_OF_RANGE && hull == NULL
						   : result == CD_OK && hull != NULL && cd3ValidateHull(hull) == CD_OK,
					"needle of aspect %g: %s", (double)(length / width), cdGetResultString(result));
		cd3DestroyHull(hull);
	}
#else
	TEST_CHECK(limit >= CD_R(1e18)); /* the ratio of the float range's ends */
	box.halfExtents = cd3MakeVec(CD_R(1e-9), CD_R(1e9), CD_R(1.0));
	TEST_CHECK(cd3IsValidBox(box));
#endif
}

int main(void)
{
	TEST_RUN(TestTypeNamesAndMakers);
	TEST_RUN(TestValidators);
	TEST_RUN(TestValidateShapeReasons);
	TEST_RUN(TestExactBounds);
	TEST_RUN(TestRandomBounds);
	TEST_RUN(TestAspectRatioRange);
	return TEST_SUMMARY();
}
