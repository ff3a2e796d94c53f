/* The whole 3D overlap matrix (every ordered pair of the 7 shape types) against GJK: cd3Overlap
 * agrees with cd3Distance(a, b).distance == 0 away from the boundary, is symmetric, and is
 * invariant under a common rigid transform (translation only with an AABB).
 *
 * "Away from the boundary": a separated pair counts when its distance exceeds BAND; an
 * overlapping pair counts when it stays overlapping after B moves by BAND along each of 14
 * directions (the axes and the cube diagonals), which means a penetration of at least about
 * BAND / sqrt(3) whatever its direction. Half of the pairs are pushed close to touching
 * (separated or penetrating by 2 to 20 BANDs) so that the boundary is probed, not only the bulk. */
#include "random_shapes3.h"
#include "test.h"

#include "../src/query/pairs3.h"
#include "../src/query/support3.h"

#define BAND 1e-3

static cd3Shape Translated(const cd3Shape* shape, cd3Vec offset)
{
	cd3Transform t = {offset, CD3_QUAT_IDENTITY};
	return TransformShape(shape, t);
}

/* 14 unit directions: +-axes and the normalized cube diagonals. */
static cd3Vec Direction(int i)
{
	if (i < 6)
	{
		cdReal s = (i & 1) ? CD_R(-1.0) : CD_R(1.0);
		return i < 2 ? cd3MakeVec(s, CD_R(0.0), CD_R(0.0))
					 : (i < 4 ? cd3MakeVec(CD_R(0.0), s, CD_R(0.0)) : cd3MakeVec(CD_R(0.0), CD_R(0.0), s));
	}
	int k = i - 6;
	cdReal c = CD_R(0.57735026918962576);
	return cd3MakeVec((k & 1) ? -c : c, (k & 2) ? -c : c, (k & 4) ? -c : c);
}

static bool DeeplyOverlapping(const cd3Shape* a, const cd3Shape* b)
{
	for (int i = 0; i < 14; ++i)
	{
		cd3Shape moved = Translated(b, cd3Scale((cdReal)BAND, Direction(i)));
		if (cd3Distance(a, &moved).distance > CD_R(0.0))
		{
			return false;
		}
	}
	return true;
}

/* Moves b along the closest-point direction so that the pair is separated by `gap` (negative:
 * penetrating by about -gap). Pairs already overlapping are left alone. */
static cd3Shape PushTowards(const cd3Shape* a, const cd3Shape* b, double gap)
{
	cd3ClosestPoints r = cd3Distance(a, b);
	if (r.distance <= CD_R(0.0))
	{
		return *b;
	}
	cd3Vec n = cd3Normalize(cd3Sub(r.pointB, r.pointA));
	return Translated(b, cd3Scale((cdReal)(gap - (double)r.distance), n));
}

typedef struct MatrixCounts
{
	int separated, overlapping, skipped;
} MatrixCounts;

static void CheckPair(TestRng* rng, const cd3Shape* a, const cd3Shape* b, MatrixCounts* counts)
{
	bool ab = cd3Overlap(a, b);
	bool ba = cd3Overlap(b, a);
	TEST_CHECKF(ab == ba, "%s/%s: overlap(a,b) = %d, overlap(b,a) = %d", TypeName(a->type), TypeName(b->type),
				(int)ab, (int)ba);
	if (ab != ba)
	{
		PrintShape("a", a);
		PrintShape("b", b);
	}

	double distance = (double)cd3Distance(a, b).distance;
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

	cd3Transform t;
	t.p = RandomVec(rng, 5.0);
	t.q = (a->type == CD3_SHAPE_AABB || b->type == CD3_SHAPE_AABB) ? CD3_QUAT_IDENTITY : RandomQuat(rng);
	cd3Shape ta = TransformShape(a, t), tb = TransformShape(b, t);
	bool moved = cd3Overlap(&ta, &tb);
	TEST_CHECKF(moved == expected, "%s/%s: overlap %d after a rigid transform, %d before (distance %.9g)",
				TypeName(a->type), TypeName(b->type), (int)moved, (int)ab, distance);
	if (moved != expected)
	{
		PrintShape("a", a);
		PrintShape("b", b);
	}
}

static void TestOverlapMatrix(void)
{
	TestRng rng = TestRngMake(0x6a6b3d03u);
	const int pairsPerCombination = 400;
	for (int ta = 0; ta < CD3_SHAPE_TYPE_COUNT; ++ta)
	{
		for (int tb = 0; tb < CD3_SHAPE_TYPE_COUNT; ++tb)
		{
			MatrixCounts counts = {0, 0, 0};
			for (int i = 0; i < pairsPerCombination; ++i)
			{
				cd3Shape a = RandomShape(&rng, (cd3ShapeType)ta);
				cd3Shape b = RandomShape(&rng, (cd3ShapeType)tb);
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
			/* Both outcomes must be exercised, or the pair's check proves little. Two random
			 * half-spaces always meet, and two segments never overlap robustly in 3D. */
			bool bothPlanes = ta == CD3_SHAPE_PLANE && tb == CD3_SHAPE_PLANE;
			bool bothSegments = ta == CD3_SHAPE_SEGMENT && tb == CD3_SHAPE_SEGMENT;
			TEST_CHECKF((counts.overlapping > 20 || bothSegments) && (counts.separated > 20 || bothPlanes),
						"%s/%s: only %d separated and %d overlapping cases (%d skipped)",
						TypeName((cd3ShapeType)ta), TypeName((cd3ShapeType)tb), counts.separated,
						counts.overlapping, counts.skipped);
		}
	}
}

/* Half-spaces are separated only with opposite normals: exactly opposite pairs, apart or not. */
static void TestOppositePlanes(void)
{
	TestRng rng = TestRngMake(0x6a6b3d04u);
	int separated = 0;
	for (int i = 0; i < 500; ++i)
	{
		cd3Shape a = RandomShape(&rng, CD3_SHAPE_PLANE);
		cd3Shape b = a;
		b.plane.normal = cd3Neg(a.plane.normal);
		b.plane.offset = RandomReal(&rng, -3.0, 3.0);
		double gap = -((double)a.plane.offset + (double)b.plane.offset);
		if (fabs(gap) <= BAND)
		{
			continue;
		}
		separated += gap > 0.0;
		bool expected = gap < 0.0;
		TEST_CHECKF(cd3Overlap(&a, &b) == expected && cd3Overlap(&b, &a) == expected, "gap %.9g", gap);
		TEST_CHECKF((cd3Distance(&a, &b).distance == CD_R(0.0)) == expected, "gap %.9g, distance %.9g", gap,
					(double)cd3Distance(&a, &b).distance);
		cd3Transform t = {RandomVec(&rng, 5.0), RandomQuat(&rng)};
		cd3Shape ta = TransformShape(&a, t), tb = TransformShape(&b, t);
		/* The transformed normals stay opposite up to round-off: the overlap tolerance covers it. */
		TEST_CHECKF(cd3Overlap(&ta, &tb) == expected, "gap %.9g after a rigid transform", gap);
	}
	TEST_CHECK(separated > 100);
}

/* The shape and pair tables (src/query/pairs3.h) that drive the dispatchers: one row per shape
 * type and one row per unordered pair of types, each in canonical order, every pair exactly once;
 * and each pair's typed overlap function answers as cd3Overlap in both orders. */
static int g_pairRows[CD3_SHAPE_TYPE_COUNT][CD3_SHAPE_TYPE_COUNT];
static int g_shapeRows[CD3_SHAPE_TYPE_COUNT];

static void TestPairTables(void)
{
#define COUNT_SHAPE(Name, PointIn, ClosestPointOn, Raycast, ...) ++g_shapeRows[CD3_TYPE_##Name];
	CD3_SHAPE_TABLE(COUNT_SHAPE)
#undef COUNT_SHAPE
#define COUNT_PAIR(A, B, Overlap, Distance, Collide) ++g_pairRows[CD3_TYPE_##A][CD3_TYPE_##B];
	CD3_PAIR_TABLE(COUNT_PAIR)
	CD3_HULL_PAIR_TABLE(COUNT_PAIR)
#undef COUNT_PAIR
	for (int i = 0; i < CD3_SHAPE_TYPE_COUNT; ++i)
	{
		TEST_CHECKF(g_shapeRows[i] == 1, "%s: %d shape rows", TypeName((cd3ShapeType)i), g_shapeRows[i]);
		for (int j = 0; j < CD3_SHAPE_TYPE_COUNT; ++j)
		{
			int expected = i <= j ? 1 : 0;
			TEST_CHECKF(g_pairRows[i][j] == expected, "%s-%s: %d pair rows, expected %d",
						TypeName((cd3ShapeType)i), TypeName((cd3ShapeType)j), g_pairRows[i][j], expected);
		}
	}

	TestRng rng = TestRngMake(0x7ab1e3u);
	int checked = 0;
	for (int n = 0; n < 200; ++n)
	{
#define CHECK_OVERLAP(A, B, Overlap, Distance, Collide)                                                      \
	{                                                                                                        \
		cd3Shape a = RandomShape(&rng, CD3_TYPE_##A), b = RandomShape(&rng, CD3_TYPE_##B);                   \
		bool typed = Overlap(CD3_SHAPE_ARG(A, &a), CD3_SHAPE_ARG(B, &b));                                    \
		TEST_CHECKF(typed == cd3Overlap(&a, &b) && typed == cd3Overlap(&b, &a), "%s #%d", #Overlap, n);      \
		++checked;                                                                                           \
	}
		CD3_PAIR_TABLE(CHECK_OVERLAP)
#undef CHECK_OVERLAP
	}
	TEST_CHECK(checked == 200 * 28);
}

static void CheckCore(TestRng* rng, const cd3Shape* shape, bool hasCore, cdReal radius, const char* name)
{
	cd3Core core;
	bool made = cd3MakeCore(shape, &core);
	TEST_CHECKF(made == hasCore, "%s: core made %d, row has one %d", name, (int)made, (int)hasCore);
	if (!made || core.count < 1)
	{
		return;
	}
	TEST_CHECKF(core.radius == radius, "%s: core radius %g, row radius %g", name, (double)core.radius,
				(double)radius);
	cd3Aabb bounds = cd3ComputeShapeAabb(shape);
	cdReal tolerance = CD_R(1e-4);
	for (int i = 0; i < core.count; ++i)
	{
		cd3Vec p = cd3CorePoint(&core, i);
		TEST_CHECKF(p.x - core.radius >= bounds.min.x - tolerance &&
						p.x + core.radius <= bounds.max.x + tolerance &&
						p.y - core.radius >= bounds.min.y - tolerance &&
						p.y + core.radius <= bounds.max.y + tolerance &&
						p.z - core.radius >= bounds.min.z - tolerance &&
						p.z + core.radius <= bounds.max.z + tolerance,
					"%s: core point %d outside the bounds", name, i);
	}
	for (int k = 0; k < 8; ++k)
	{
		cd3Vec u = RandomUnit(rng);
		cd3Vec support = cd3CorePoint(&core, cd3CoreSupport(&core, u));
		cd3Vec on = cd3MulAdd(support, CD_R(0.999) * core.radius, u);
		cd3Vec beyond = cd3MulAdd(support, core.radius + CD_R(0.01), u);
		cdReal off = cd3Length(cd3Sub(cd3ClosestPointOnShape(shape, on), on));
		TEST_CHECKF(off <= tolerance, "%s: support point %g outside the shape", name, (double)off);
		TEST_CHECKF(!cd3PointInShape(shape, beyond), "%s: the shape reaches past its support point", name);
	}
}

/* The support columns of the shape table (MakeCore, Radius), which GJK, the casts and
 * cd3Distance see every shape through: for random shapes of every row the core is made (none for
 * the half-space, whose MakeCore is NONE), its radius is the row's Radius (0 for a sharp shape),
 * its points grown by the radius lie in the shape's bounds, and along random directions the
 * support point (the farthest core point pushed out by the radius) lies in the shape (within
 * 1e-4) while a point 0.01 farther along does not. */
static void TestShapeCores(void)
{
	TestRng rng = TestRngMake(0xc0e5u);
	int checked = 0;
	for (int n = 0; n < 300; ++n)
	{
#define CHECK_CORE(Name, PointIn, ClosestPointOn, Raycast, TypeName, Validate, ComputeAabb, ComputeMass,     \
				   MakeCore, Radius)                                                                         \
	{                                                                                                        \
		cd3Shape shape = RandomShape(&rng, CD3_TYPE_##Name);                                                 \
		cdReal radius = CD_R(0.0);                                                                           \
		CD_SHAPE_HAS(Radius, CORE_RADIUS)                                                                    \
		(Radius) CheckCore(&rng, &shape, CD_PAIR_IS_UNTYPED(MakeCore) == 0, radius, #Name);                  \
		++checked;                                                                                           \
	}
#define CORE_RADIUS(Radius) radius = Radius(&shape);
		CD3_SHAPE_TABLE(CHECK_CORE)
#undef CORE_RADIUS
#undef CHECK_CORE
	}
	TEST_CHECK(checked == 300 * CD3_SHAPE_TYPE_COUNT);
}

int main(void)
{
	TEST_RUN(TestPairTables);
	TEST_RUN(TestShapeCores);
	TEST_RUN(TestOverlapMatrix);
	TEST_RUN(TestOppositePlanes);
	return TEST_SUMMARY();
}
