/* Tests of the 2D shapes: type names, tagged-shape constructors, validators (with their reasons)
 * and bounding boxes (exact cases, and random shapes whose box must be the tight box of the shape's
 * extreme points computed in double). */
#include "collide/geometry2.h"
#include "reference2.h"
#include "test.h"

#include <string.h>

static cd2Vec V(double x, double y)
{
	return cd2MakeVec((cdReal)x, (cdReal)y);
}

static void TestNamesAndMakers(void)
{
	TEST_CHECK(strcmp(cd2GetShapeTypeName(CD2_SHAPE_CIRCLE), "circle") == 0);
	TEST_CHECK(strcmp(cd2GetShapeTypeName(CD2_SHAPE_CAPSULE), "capsule") == 0);
	TEST_CHECK(strcmp(cd2GetShapeTypeName(CD2_SHAPE_AABB), "aabb") == 0);
	TEST_CHECK(strcmp(cd2GetShapeTypeName(CD2_SHAPE_BOX), "box") == 0);
	TEST_CHECK(strcmp(cd2GetShapeTypeName(CD2_SHAPE_POLYGON), "polygon") == 0);
	TEST_CHECK(strcmp(cd2GetShapeTypeName(CD2_SHAPE_SEGMENT), "segment") == 0);
	TEST_CHECK(strcmp(cd2GetShapeTypeName(CD2_SHAPE_TYPE_COUNT), "unknown") == 0);
	TEST_CHECK(strcmp(cd2GetShapeTypeName((cd2ShapeType)-1), "unknown") == 0);

	cd2Circle circle = {V(1, 2), 3};
	cd2Shape s = cd2MakeCircleShape(circle);
	TEST_CHECK(s.type == CD2_SHAPE_CIRCLE && s.circle.center.x == 1 && s.circle.radius == 3);
	cd2Capsule capsule = {V(1, 2), V(3, 4), 5};
	s = cd2MakeCapsuleShape(capsule);
	TEST_CHECK(s.type == CD2_SHAPE_CAPSULE && s.capsule.p2.y == 4 && s.capsule.radius == 5);
	cd2Aabb aabb = {V(-1, -2), V(1, 2)};
	s = cd2MakeAabbShape(aabb);
	TEST_CHECK(s.type == CD2_SHAPE_AABB && s.aabb.min.y == -2 && s.aabb.max.x == 1);
	cd2Box box = {V(1, 1), V(2, 3), CD2_ROT_IDENTITY};
	s = cd2MakeBoxShape(box);
	TEST_CHECK(s.type == CD2_SHAPE_BOX && s.box.halfExtents.y == 3);
	cd2Polygon polygon;
	TEST_CHECK(cd2MakeBoxPolygon(box, &polygon) == CD_OK);
	s = cd2MakePolygonShape(&polygon);
	TEST_CHECK(s.type == CD2_SHAPE_POLYGON && memcmp(&s.polygon, &polygon, sizeof polygon) == 0);
	cd2Segment segment = {V(0, 1), V(2, 3)};
	s = cd2MakeSegmentShape(segment);
	TEST_CHECK(s.type == CD2_SHAPE_SEGMENT && s.segment.p2.x == 2);
}

static void TestValidators(void)
{
	const cdReal nan = (cdReal)NAN, inf = (cdReal)INFINITY;

	TEST_CHECK(cd2IsValidAabb((cd2Aabb){V(0, 0), V(1, 1)}));
	TEST_CHECK(cd2IsValidAabb((cd2Aabb){V(1, 1), V(1, 1)}));
	TEST_CHECK(!cd2IsValidAabb((cd2Aabb){V(1, 0), V(0, 1)}));
	TEST_CHECK(!cd2IsValidAabb((cd2Aabb){V(0, 0), {1, nan}}));
	TEST_CHECK(!cd2IsValidAabb((cd2Aabb){{-inf, 0}, V(1, 1)}));

	TEST_CHECK(cd2IsValidCircle((cd2Circle){V(0, 0), 0}));
	TEST_CHECK(cd2IsValidCircle((cd2Circle){V(0, 0), 2}));
	TEST_CHECK(!cd2IsValidCircle((cd2Circle){V(0, 0), -1}));
	TEST_CHECK(!cd2IsValidCircle((cd2Circle){V(0, 0), inf}));
	TEST_CHECK(!cd2IsValidCircle((cd2Circle){{nan, 0}, 1}));

	TEST_CHECK(cd2IsValidCapsule((cd2Capsule){V(0, 0), V(0, 0), 0}));
	TEST_CHECK(!cd2IsValidCapsule((cd2Capsule){V(0, 0), V(1, 0), -0.5}));
	TEST_CHECK(!cd2IsValidCapsule((cd2Capsule){V(0, 0), {1, inf}, 1}));

	TEST_CHECK(cd2IsValidSegment((cd2Segment){V(0, 0), V(0, 0)}));
	TEST_CHECK(!cd2IsValidSegment((cd2Segment){V(0, 0), {nan, 0}}));

	TEST_CHECK(cd2IsValidBox((cd2Box){V(0, 0), V(0, 0), CD2_ROT_IDENTITY}));
	TEST_CHECK(cd2IsValidBox((cd2Box){V(0, 0), V(1, 2), cd2MakeRot(1.0f)}));
	TEST_CHECK(!cd2IsValidBox((cd2Box){V(0, 0), V(-1, 2), CD2_ROT_IDENTITY}));
	TEST_CHECK(!cd2IsValidBox((cd2Box){V(0, 0), V(1, 2), {1, 1}}));
	TEST_CHECK(!cd2IsValidBox((cd2Box){V(0, 0), V(1, 2), {0, 0}}));
	TEST_CHECK(!cd2IsValidBox((cd2Box){V(0, 0), V(1, 2), {nan, 0}}));

	TEST_CHECK(cd2IsValidRay((cd2Ray){V(0, 0), V(0, 0)}));
	TEST_CHECK(!cd2IsValidRay((cd2Ray){V(0, 0), {inf, 0}}));

	/* reasons through cd2ValidateShape */
	cd2Shape s = cd2MakeCircleShape((cd2Circle){V(0, 0), -1});
	TEST_CHECK(cd2ValidateShape(&s) == CD_ERROR_NEGATIVE_SIZE && !cd2IsValidShape(&s));
	s = cd2MakeCircleShape((cd2Circle){V(0, 0), nan});
	TEST_CHECK(cd2ValidateShape(&s) == CD_ERROR_NOT_FINITE);
	s = cd2MakeCapsuleShape((cd2Capsule){V(0, 0), V(1, 1), -1});
	TEST_CHECK(cd2ValidateShape(&s) == CD_ERROR_NEGATIVE_SIZE);
	s = cd2MakeAabbShape((cd2Aabb){V(2, 0), V(1, 1)});
	TEST_CHECK(cd2ValidateShape(&s) == CD_ERROR_NEGATIVE_SIZE);
	s = cd2MakeBoxShape((cd2Box){V(0, 0), V(1, 1), {(cdReal)0.5, 0}});
	TEST_CHECK(cd2ValidateShape(&s) == CD_ERROR_NOT_NORMALIZED);
	s = cd2MakeBoxShape((cd2Box){V(0, 0), V(1, -1), CD2_ROT_IDENTITY});
	TEST_CHECK(cd2ValidateShape(&s) == CD_ERROR_NEGATIVE_SIZE);
	s = cd2MakeSegmentShape((cd2Segment){V(0, 0), {0, inf}});
	TEST_CHECK(cd2ValidateShape(&s) == CD_ERROR_NOT_FINITE);
	s = cd2MakeSegmentShape((cd2Segment){V(0, 0), V(1, 1)});
	TEST_CHECK(cd2ValidateShape(&s) == CD_OK && cd2IsValidShape(&s));
	s.type = CD2_SHAPE_TYPE_COUNT;
	TEST_CHECK(cd2ValidateShape(&s) == CD_ERROR_INVALID_ARGUMENT);
	TEST_CHECK(cd2ValidateShape(NULL) == CD_ERROR_INVALID_ARGUMENT);
	TEST_CHECK(!cd2IsValidShape(NULL));
}

static void TestPolygonValidator(void)
{
	cd2Vec points[4] = {V(0, 0), V(2, 0), V(2, 1), V(0, 1)};
	cd2Polygon good;
	TEST_CHECK(cd2MakePolygon(points, 4, &good) == CD_OK);
	TEST_CHECK(cd2IsValidPolygon(&good));
	cd2Shape s = cd2MakePolygonShape(&good);
	TEST_CHECK(cd2ValidateShape(&s) == CD_OK);
	TEST_CHECK(!cd2IsValidPolygon(NULL));

	cd2Polygon p = good;
	p.count = 2;
	TEST_CHECK(!cd2IsValidPolygon(&p));
	p.count = CD2_MAX_POLYGON_VERTICES + 1;
	TEST_CHECK(!cd2IsValidPolygon(&p));
	s = cd2MakePolygonShape(&p);
	TEST_CHECK(cd2ValidateShape(&s) == CD_ERROR_TOO_MANY_POINTS);

	p = good;
	p.vertices[1].x = (cdReal)NAN;
	s = cd2MakePolygonShape(&p);
	TEST_CHECK(cd2ValidateShape(&s) == CD_ERROR_NOT_FINITE);

	p = good;
	p.normals[0] = cd2Scale((cdReal)1.1, p.normals[0]);
	s = cd2MakePolygonShape(&p);
	TEST_CHECK(cd2ValidateShape(&s) == CD_ERROR_NOT_NORMALIZED);

	/* normals swapped: unit but not perpendicular to their edges */
	p = good;
	cd2Vec swap = p.normals[0];
	p.normals[0] = p.normals[1];
	p.normals[1] = swap;
	s = cd2MakePolygonShape(&p);
	TEST_CHECK(cd2ValidateShape(&s) == CD_ERROR_DEGENERATE);

	/* clockwise order (vertices reversed, normals recomputed outward for that order) */
	p = good;
	for (int i = 0; i < 4; ++i)
	{
		p.vertices[i] = good.vertices[3 - i];
	}
	for (int i = 0; i < 4; ++i)
	{
		cd2Vec e = cd2Sub(p.vertices[(i + 1) % 4], p.vertices[i]);
		p.normals[i] = cd2Normalize(cd2RightPerp(e));
	}
	TEST_CHECK(!cd2IsValidPolygon(&p));

	/* non-convex: an arrow head, normals consistent with its edges */
	cd2Vec arrow[4] = {V(0, 0), V(2, 1), V(0, 2), V(1, 1)};
	p.count = 4;
	for (int i = 0; i < 4; ++i)
	{
		p.vertices[i] = arrow[i];
		p.normals[i] = cd2Normalize(cd2RightPerp(cd2Sub(arrow[(i + 1) % 4], arrow[i])));
	}
	p.centroid = V(0.8, 1);
	TEST_CHECK(!cd2IsValidPolygon(&p));

	/* repeated vertex: zero-length edge */
	p = good;
	p.vertices[1] = p.vertices[0];
	TEST_CHECK(!cd2IsValidPolygon(&p));

	/* centroid outside */
	p = good;
	p.centroid = V(5, 5);
	TEST_CHECK(!cd2IsValidPolygon(&p));

	/* A dent 100 deep near the origin next to a vertex at 1e9: within 64 epsilons of the largest
	 * coordinate (7600 in float), but a dent all the same (cd2PointInPolygon, whose tolerance is
	 * relative to the offsets it compares, finds vertices 0 and 2 outside the edges around it). */
	cd2Vec dent[4] = {V(0, 0), V(1e9, 0), V(0, 2000), V(100, 1000)};
	p.count = 4;
	for (int i = 0; i < 4; ++i)
	{
		p.vertices[i] = dent[i];
		p.normals[i] = cd2Normalize(cd2RightPerp(cd2Sub(dent[(i + 1) % 4], dent[i])));
	}
	p.centroid = V(3e8, 600);
	TEST_CHECK(!cd2IsValidPolygon(&p));
	/* Without the dent it is a valid triangle, its vertices inside it. */
	p.count = 3;
	p.normals[2] = cd2Normalize(cd2RightPerp(cd2Sub(dent[0], dent[2])));
	TEST_CHECK(cd2IsValidPolygon(&p));
	for (int i = 0; i < 3; ++i)
	{
		TEST_CHECK(cd2PointInPolygon(p.vertices[i], &p));
	}
}

static void CheckAabb(cd2Aabb b, double minX, double minY, double maxX, double maxY, double tolerance)
{
	TEST_CHECK_NEAR(b.min.x, minX, tolerance);
	TEST_CHECK_NEAR(b.min.y, minY, tolerance);
	TEST_CHECK_NEAR(b.max.x, maxX, tolerance);
	TEST_CHECK_NEAR(b.max.y, maxY, tolerance);
}

static void TestBoundsExact(void)
{
	CheckAabb(cd2ComputeCircleAabb((cd2Circle){V(1, 2), 3}), -2, -1, 4, 5, 0);
	CheckAabb(cd2ComputeCircleAabb((cd2Circle){V(1, 2), 0}), 1, 2, 1, 2, 0);
	CheckAabb(cd2ComputeCapsuleAabb((cd2Capsule){V(3, -1), V(1, 2), 1}), 0, -2, 4, 3, 0);
	CheckAabb(cd2ComputeBoxAabb((cd2Box){V(1, 1), V(2, 1), CD2_ROT_IDENTITY}), -1, 0, 3, 2, 0);
	CheckAabb(cd2ComputeBoxAabb((cd2Box){V(0, 0), V(1, 1), cd2MakeRot(CD_PI / 4)}), -sqrt(2.0), -sqrt(2.0),
			  sqrt(2.0), sqrt(2.0), 1e-6);
	CheckAabb(cd2ComputeBoxAabb((cd2Box){V(0, 0), V(2, 1), cd2MakeRot(CD_PI / 2)}), -1, -2, 1, 2, 1e-6);
	CheckAabb(cd2ComputeSegmentAabb((cd2Segment){V(3, -1), V(1, 2)}), 1, -1, 3, 2, 0);
	cd2Vec points[3] = {V(0, 0), V(4, 1), V(1, 3)};
	cd2Polygon polygon;
	TEST_CHECK(cd2MakePolygon(points, 3, &polygon) == CD_OK);
	CheckAabb(cd2ComputePolygonAabb(&polygon), 0, 0, 4, 3, 0);
	cd2Shape s = cd2MakePolygonShape(&polygon);
	CheckAabb(cd2ComputeShapeAabb(&s), 0, 0, 4, 3, 0);
	cd2Aabb aabb = {V(-1, -1), V(2, 2)};
	s = cd2MakeAabbShape(aabb);
	CheckAabb(cd2ComputeShapeAabb(&s), -1, -1, 2, 2, 0);
}

/* The box of a random shape is the tight box of its extreme points, computed in double. */
static void TestBoundsRandom(void)
{
	TestRng rng = TestRngMake(0xB0B0);
	for (int type = 0; type < CD2_SHAPE_TYPE_COUNT; ++type)
	{
		for (int n = 0; n < 500; ++n)
		{
			cd2Shape s = RandomShape(&rng, (cd2ShapeType)type, V(3, -2), 4.0);
			cd2Aabb b = cd2ComputeShapeAabb(&s);
			RefShape r = RefFromShape(&s);
			double minX = INFINITY, minY = INFINITY, maxX = -INFINITY, maxY = -INFINITY;
			for (int i = 0; i < r.count; ++i)
			{
				minX = fmin(minX, r.points[i].x - r.radius);
				minY = fmin(minY, r.points[i].y - r.radius);
				maxX = fmax(maxX, r.points[i].x + r.radius);
				maxY = fmax(maxY, r.points[i].y + r.radius);
			}
			double tolerance = 1e-5;
			TEST_CHECKF(
				fabs((double)b.min.x - minX) <= tolerance && fabs((double)b.min.y - minY) <= tolerance &&
					fabs((double)b.max.x - maxX) <= tolerance && fabs((double)b.max.y - maxY) <= tolerance,
				"%s: box (%g %g, %g %g), expected (%g %g, %g %g)", cd2GetShapeTypeName(s.type),
				(double)b.min.x, (double)b.min.y, (double)b.max.x, (double)b.max.y, minX, minY, maxX, maxY);
			TEST_CHECK(cd2IsValidShape(&s));
			TEST_CHECK(cd2IsValidAabb(b));
		}
	}
}

static void TestAabbHelpers(void)
{
	cd2Aabb a = {V(0, 0), V(2, 1)}, b = {V(1, -1), V(3, 0.5)};
	CheckAabb(cd2AabbUnion(a, b), 0, -1, 3, 1, 0);
	TEST_CHECK(cd2AabbContains(cd2AabbUnion(a, b), a) && !cd2AabbContains(a, b));
	TEST_CHECK_NEAR(cd2AabbPerimeter(a), 6, 0);
	CheckAabb(cd2AabbInflate(a, 1), -1, -1, 3, 2, 0);
	TEST_CHECK_NEAR(cd2AabbCenter(a).x, 1, 0);
	TEST_CHECK_NEAR(cd2AabbHalfExtents(a).y, 0.5, 0);
}

int main(void)
{
	TEST_RUN(TestNamesAndMakers);
	TEST_RUN(TestValidators);
	TEST_RUN(TestPolygonValidator);
	TEST_RUN(TestBoundsExact);
	TEST_RUN(TestBoundsRandom);
	TEST_RUN(TestAabbHelpers);
	return TEST_SUMMARY();
}
