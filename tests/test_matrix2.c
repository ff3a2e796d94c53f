/* The whole 2D overlap matrix (every ordered pair of the 6 shape types) against GJK: cd2Overlap
 * agrees with cd2Distance(a, b).distance == 0 away from the boundary, is symmetric, and is
 * invariant under a common rigid transform (translation only with an AABB).
 *
 * "Away from the boundary": a separated pair counts when its distance exceeds BAND; an
 * overlapping pair counts when it stays overlapping after B moves by BAND along each of 8
 * directions (the axes and the diagonals), which means a penetration of at least about
 * BAND * cos(22.5 degrees) whatever its direction. Half of the pairs are pushed close to touching
 * (separated or penetrating by 2 to 20 BANDs) so that the boundary is probed, not only the bulk. */
#include "random_shapes2.h"
#include "test.h"

#include "../src/query/pairs2.h"
#include "../src/query/support2.h"

#define BAND 1e-3

static cd2Shape Translated(const cd2Shape* shape, cd2Vec offset)
{
	cd2Transform t = {offset, CD2_ROT_IDENTITY};
	return TransformShape(shape, t);
}

/* 8 unit directions: +-axes and the normalized diagonals. */
static cd2Vec Direction(int i)
{
	cdReal c = CD_R(0.70710678118654752);
	static const int signs[8][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {1, -1}, {-1, 1}, {-1, -1}};
	cdReal scale = i < 4 ? CD_R(1.0) : c;
	return cd2MakeVec(scale * (cdReal)signs[i][0], scale * (cdReal)signs[i][1]);
}

static bool DeeplyOverlapping(const cd2Shape* a, const cd2Shape* b)
{
	for (int i = 0; i < 8; ++i)
	{
		cd2Shape moved = Translated(b, cd2Scale((cdReal)BAND, Direction(i)));
		if (cd2Distance(a, &moved).distance > CD_R(0.0))
		{
			return false;
		}
	}
	return true;
}

/* Moves b along the closest-point direction so that the pair is separated by `gap` (negative:
 * penetrating by about -gap). Pairs already overlapping are left alone. */
static cd2Shape PushTowards(const cd2Shape* a, const cd2Shape* b, double gap)
{
	cd2ClosestPoints r = cd2Distance(a, b);
	if (r.distance <= CD_R(0.0))
	{
		return *b;
	}
	cd2Vec n = cd2Normalize(cd2Sub(r.pointB, r.pointA));
	return Translated(b, cd2Scale((cdReal)(gap - (double)r.distance), n));
}

typedef struct MatrixCounts
{
	int separated, overlapping, skipped;
} MatrixCounts;

static void CheckPair(TestRng* rng, const cd2Shape* a, const cd2Shape* b, MatrixCounts* counts)
{
	bool ab = cd2Overlap(a, b);
	bool ba = cd2Overlap(b, a);
	TEST_CHECKF(ab == ba, "%s/%s: overlap(a,b) = %d, overlap(b,a) = %d", TypeName(a->type), TypeName(b->type),
				(int)ab, (int)ba);
	if (ab != ba)
	{
		PrintShape("a", a);
		PrintShape("b", b);
	}

	double distance = (double)cd2Distance(a, b).distance;
	bool expected;
	if (distance > BAND)
	{
		expected = false;
		++counts->separated;
	}
	else if (distance == 0.0 && DeeplyOverlapping(a, b))
	{
		expected = true;
		++counts->overlapping;
	}
	else
	{
		++counts->skipped;
		return;
	}
	TEST_CHECKF(ab == expected, "%s/%s: overlap %d, GJK distance %.9g", TypeName(a->type), TypeName(b->type),
				(int)ab, distance);
	if (ab != expected)
	{
		PrintShape("a", a);
		PrintShape("b", b);
	}

	cd2Transform t;
	t.p = RandomVec(rng, 5.0);
	t.q = (a->type == CD2_SHAPE_AABB || b->type == CD2_SHAPE_AABB) ? CD2_ROT_IDENTITY : RandomRot(rng);
	cd2Shape ta = TransformShape(a, t), tb = TransformShape(b, t);
	bool moved = cd2Overlap(&ta, &tb);
	TEST_CHECKF(moved == expected, "%s/%s: overlap %d after a rigid transform, %d before (distance %.9g)",
				TypeName(a->type), TypeName(b->type), (int)moved, (int)ab, distance);
	if (moved != expected)
	{
		PrintShape("a", a);
		PrintShape("b", b);
	}
}

/* Polygons as the library builds them: cd2MakeRoundedPolygon on the random convex points and radius. */
static cd2Shape BuiltShape(TestRng* rng, cd2ShapeType type)
{
	cd2Shape shape = RandomShape(rng, type);
	if (type == CD2_SHAPE_POLYGON)
	{
		cd2Polygon built;
		cdResult result =
			cd2MakeRoundedPolygon(shape.polygon.vertices, shape.polygon.count, shape.polygon.radius, &built);
		TEST_CHECKF(result == CD_OK, "cd2MakeRoundedPolygon failed: %d", (int)result);
		if (result == CD_OK)
		{
			shape.polygon = built;
		}
	}
	return shape;
}

static void TestOverlapMatrix(void)
{
	TestRng rng = TestRngMake(0x6a6b3d05u);
	const int pairsPerCombination = 500;
	for (int ta = 0; ta < CD2_SHAPE_TYPE_COUNT; ++ta)
	{
		for (int tb = 0; tb < CD2_SHAPE_TYPE_COUNT; ++tb)
		{
			MatrixCounts counts = {0, 0, 0};
			for (int i = 0; i < pairsPerCombination; ++i)
			{
				cd2Shape a = BuiltShape(&rng, (cd2ShapeType)ta);
				cd2Shape b = BuiltShape(&rng, (cd2ShapeType)tb);
				int mode = TestRngInt(&rng, 4);
				if (mode == 1)
				{
					b = PushTowards(&a, &b, TestRngRange(&rng, 2.0, 20.0) * BAND);
				}
				else if (mode == 2)
				{
					b = PushTowards(&a, &b, -TestRngRange(&rng, 2.0, 20.0) * BAND);
				}
				CheckPair(&rng, &a, &b, &counts);
			}
			/* Both outcomes must be exercised, or the pair's check proves little. */
			TEST_CHECKF(counts.overlapping > 20 && counts.separated > 20,
						"%s/%s: only %d separated and %d overlapping cases (%d skipped)",
						TypeName((cd2ShapeType)ta), TypeName((cd2ShapeType)tb), counts.separated,
						counts.overlapping, counts.skipped);
		}
	}
}

/* The shape and pair tables (src/query/pairs2.h) that drive the dispatchers: one row per shape
 * type and one row per unordered pair of types, each in canonical order, every pair exactly once;
 * and each pair's typed overlap function answers as cd2Overlap in both orders. */
static int g_pairRows[CD2_SHAPE_TYPE_COUNT][CD2_SHAPE_TYPE_COUNT];
static int g_shapeRows[CD2_SHAPE_TYPE_COUNT];

static void TestPairTables(void)
{
#define COUNT_SHAPE(Name, PointIn, ClosestPointOn, Raycast, ...) ++g_shapeRows[CD2_TYPE_##Name];
	CD2_SHAPE_TABLE(COUNT_SHAPE)
#undef COUNT_SHAPE
#define COUNT_PAIR(A, B, Overlap, Distance, Collide) ++g_pairRows[CD2_TYPE_##A][CD2_TYPE_##B];
	CD2_PAIR_TABLE(COUNT_PAIR)
#undef COUNT_PAIR
	for (int i = 0; i < CD2_SHAPE_TYPE_COUNT; ++i)
	{
		TEST_CHECKF(g_shapeRows[i] == 1, "%s: %d shape rows", TypeName((cd2ShapeType)i), g_shapeRows[i]);
		for (int j = 0; j < CD2_SHAPE_TYPE_COUNT; ++j)
		{
			int expected = i <= j ? 1 : 0;
			TEST_CHECKF(g_pairRows[i][j] == expected, "%s-%s: %d pair rows, expected %d",
						TypeName((cd2ShapeType)i), TypeName((cd2ShapeType)j), g_pairRows[i][j], expected);
		}
	}

	TestRng rng = TestRngMake(0x7ab1e2u);
	int checked = 0;
	for (int n = 0; n < 200; ++n)
	{
#define CHECK_OVERLAP(A, B, Overlap, Distance, Collide)                                                      \
	{                                                                                                        \
		cd2Shape a = RandomShape(&rng, CD2_TYPE_##A), b = RandomShape(&rng, CD2_TYPE_##B);                   \
		bool typed = Overlap(CD2_SHAPE_ARG(A, &a), CD2_SHAPE_ARG(B, &b));                                    \
		TEST_CHECKF(typed == cd2Overlap(&a, &b) && typed == cd2Overlap(&b, &a), "%s #%d", #Overlap, n);      \
		++checked;                                                                                           \
	}
		CD2_PAIR_TABLE(CHECK_OVERLAP)
#undef CHECK_OVERLAP
	}
	TEST_CHECK(checked == 200 * 21);
}

static void CheckCore(TestRng* rng, const cd2Shape* shape, cdReal radius, const char* name)
{
	cd2Core core;
	TEST_CHECKF(cd2MakeCore(shape, &core), "%s: no core", name);
	if (core.count < 1)
	{
		return;
	}
	TEST_CHECKF(core.radius == radius, "%s: core radius %g, row radius %g", name, (double)core.radius,
				(double)radius);
	cd2Aabb bounds = cd2ComputeShapeAabb(shape);
	cdReal tolerance = CD_R(1e-4);
	for (int i = 0; i < core.count; ++i)
	{
		cd2Vec p = core.points[i];
		TEST_CHECKF(p.x - core.radius >= bounds.min.x - tolerance &&
						p.x + core.radius <= bounds.max.x + tolerance &&
						p.y - core.radius >= bounds.min.y - tolerance &&
						p.y + core.radius <= bounds.max.y + tolerance,
					"%s: core point %d outside the bounds", name, i);
	}
	for (int k = 0; k < 8; ++k)
	{
		cd2Rot r = RandomRot(rng);
		cd2Vec u = cd2MakeVec(r.c, r.s);
		cd2Vec support = core.points[cd2CoreSupport(&core, u)];
		cd2Vec on = cd2MulAdd(support, CD_R(0.999) * core.radius, u);
		cd2Vec beyond = cd2MulAdd(support, core.radius + CD_R(0.01), u);
		cdReal off = cd2Length(cd2Sub(cd2ClosestPointOnShape(shape, on), on));
		TEST_CHECKF(off <= tolerance, "%s: support point %g outside the shape", name, (double)off);
		TEST_CHECKF(!cd2PointInShape(shape, beyond), "%s: the shape reaches past its support point", name);
	}
}

/* The support columns of the shape table (MakeCore, Radius), which GJK, the casts and cd2Distance
 * see every shape through: for random shapes of every row the core is made, its radius is the
 * row's Radius (0 for a sharp shape), its points grown by the radius lie in the shape's bounds,
 * and along random directions the support point (the farthest core point pushed out by the
 * radius) lies in the shape (within 1e-4) while a point 0.01 farther along does not. */
static void TestShapeCores(void)
{
	TestRng rng = TestRngMake(0xc0e5u);
	int checked = 0;
	for (int n = 0; n < 300; ++n)
	{
#define CHECK_CORE(Name, PointIn, ClosestPointOn, Raycast, TypeName, Validate, ComputeAabb, ComputeMass,     \
				   MakeCore, Radius)                                                                         \
	{                                                                                                        \
		cd2Shape shape = RandomShape(&rng, CD2_TYPE_##Name);                                                 \
		cdReal radius = CD_R(0.0);                                                                           \
		CD_SHAPE_HAS(Radius, CORE_RADIUS)(Radius) CheckCore(&rng, &shape, radius, #Name);                    \
		++checked;                                                                                           \
	}
#define CORE_RADIUS(Radius) radius = Radius(&shape);
		CD2_SHAPE_TABLE(CHECK_CORE)
#undef CORE_RADIUS
#undef CHECK_CORE
	}
	TEST_CHECK(checked == 300 * CD2_SHAPE_TYPE_COUNT);
}

int main(void)
{
	TEST_RUN(TestPairTables);
	TEST_RUN(TestShapeCores);
	TEST_RUN(TestOverlapMatrix);
	return TEST_SUMMARY();
}
