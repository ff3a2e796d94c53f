/* The constraint colourings of src/base (internal module, linked from the static library), in
 * index order and mixed: no two constraints of a colour share a movable body, immovable
 * constraints and pairs keep to their colour ranges, the order runs colour by colour in index
 * order, a constraint goes to the overflow colour only when every colour of its range is taken,
 * and, mixed, on a regular structure (a pyramid's contacts listed box by box) every colour holds a
 * mix of kinds of contact. The same with the caller's scratch memory. */
#include "test.h"

#include "../src/base/graph_color.h"

#include <stdlib.h>
#include <string.h>

#define MAX_CONSTRAINTS 6000
#define MAX_BODIES 3000

static int g_bodyA[MAX_CONSTRAINTS], g_bodyB[MAX_CONSTRAINTS];
static int g_colors[MAX_CONSTRAINTS], g_order[MAX_CONSTRAINTS];
/* Per colour and body: the constraint of that colour on the body, or -1. */
static int g_owner[CD_GRAPH_COLOR_COUNT][MAX_BODIES];

static bool IsPairColor(int color)
{
	return color >= 0 && color < CD_GRAPH_COLOR_COUNT - CD_GRAPH_IMMOVABLE_COLORS;
}

static bool IsImmovableColor(int color)
{
	return color >= 1 && color < CD_GRAPH_COLOR_COUNT;
}

/* Colours count constraints on bodyCount bodies and checks every rule of graph_color.h. */
static void CheckColoring(int count, int bodyCount, bool mixed)
{
	cdArena arena;
	memset(&arena, 0, sizeof(arena));
	bool ok = mixed ? cdColorConstraintsMixed(g_bodyA, g_bodyB, count, bodyCount, g_colors, g_order, &arena)
					: cdColorConstraints(g_bodyA, g_bodyB, count, bodyCount, g_colors, g_order, &arena);
	TEST_CHECK(ok);
	cdArena_Destroy(&arena);
	if (!ok)
	{
		return;
	}
	/* With the caller's scratch (left dirty by anything before): the same colours and order. */
	static int scratchColors[MAX_CONSTRAINTS], scratchOrder[MAX_CONSTRAINTS];
	static uint32_t used[MAX_BODIES];
	int start[CD_GRAPH_COLOR_COUNT + 2];
	memset(used, 0xa5, sizeof(used));
	memset(start, 0x5a, sizeof(start));
	memset(scratchColors, 0x77, sizeof(scratchColors));
	memset(scratchOrder, 0x77, sizeof(scratchOrder));
	cdColorConstraintsScratch(g_bodyA, g_bodyB, count, bodyCount, scratchColors, scratchOrder, mixed, used,
							  start);
	TEST_CHECK(count == 0 || memcmp(scratchColors, g_colors, (size_t)count * sizeof(int)) == 0);
	TEST_CHECK(count == 0 || memcmp(scratchOrder, g_order, (size_t)count * sizeof(int)) == 0);
	memset(g_owner, 0xff, sizeof(g_owner));
	for (int i = 0; i < count; ++i)
	{
		int color = g_colors[i];
		bool immovable = g_bodyA[i] < 0 || g_bodyB[i] < 0;
		TEST_CHECKF(color == CD_GRAPH_COLOR_COUNT ||
						(immovable ? IsImmovableColor(color) : IsPairColor(color)),
					"constraint %d (%d, %d): colour %d", i, g_bodyA[i], g_bodyB[i], color);
		if (color < 0 || color >= CD_GRAPH_COLOR_COUNT)
		{
			continue;
		}
		const int bodies[2] = {g_bodyA[i], g_bodyB[i]};
		for (int k = 0; k < 2; ++k)
		{
			if (bodies[k] < 0)
			{
				continue;
			}
			int* owner = &g_owner[color][bodies[k]];
			TEST_CHECKF(*owner < 0, "colour %d: constraints %d and %d share body %d", color, *owner, i,
						bodies[k]);
			*owner = i;
		}
	}
	/* The overflow only when every colour of the constraint's range has one of its bodies. */
	for (int i = 0; i < count; ++i)
	{
		if (g_colors[i] != CD_GRAPH_COLOR_COUNT)
		{
			continue;
		}
		bool immovable = g_bodyA[i] < 0 || g_bodyB[i] < 0;
		for (int color = 0; color < CD_GRAPH_COLOR_COUNT; ++color)
		{
			if (!(immovable ? IsImmovableColor(color) : IsPairColor(color)))
			{
				continue;
			}
			bool taken = (g_bodyA[i] >= 0 && g_owner[color][g_bodyA[i]] >= 0) ||
						 (g_bodyB[i] >= 0 && g_owner[color][g_bodyB[i]] >= 0);
			TEST_CHECKF(taken, "constraint %d in the overflow while colour %d is free", i, color);
		}
	}
	/* The order: a permutation, colour by colour, index order within a colour. */
	static unsigned char seen[MAX_CONSTRAINTS];
	memset(seen, 0, sizeof(seen));
	for (int k = 0; k < count; ++k)
	{
		int i = g_order[k];
		TEST_CHECKF(i >= 0 && i < count && seen[i] == 0, "order[%d] = %d", k, i);
		if (i < 0 || i >= count)
		{
			return;
		}
		seen[i] = 1;
		if (k > 0)
		{
			int previous = g_order[k - 1];
			TEST_CHECKF(g_colors[previous] < g_colors[i] ||
							(g_colors[previous] == g_colors[i] && previous < i),
						"order[%d] = %d (colour %d) after %d (colour %d)", k, i, g_colors[i], previous,
						g_colors[previous]);
		}
	}
}

static void TestRandomConstraints(void)
{
	TestRng rng = TestRngMake(7);
	/* Around and across the sizes of the visiting blocks (a few hundred). */
	const int counts[] = {0, 1, 2, 3, 255, 256, 257, 511, 1000, 4097, MAX_CONSTRAINTS};
	const int bodyCounts[] = {1, 2, 40, 700, MAX_BODIES};
	for (size_t c = 0; c < sizeof(counts) / sizeof(counts[0]); ++c)
	{
		for (size_t b = 0; b < sizeof(bodyCounts) / sizeof(bodyCounts[0]); ++b)
		{
			int count = counts[c], bodyCount = bodyCounts[b];
			for (int i = 0; i < count; ++i)
			{
				/* One constraint in eight has an immovable body (-1); with one body, every one. */
				int a = TestRngInt(&rng, bodyCount);
				int other = TestRngInt(&rng, bodyCount);
				bool immovable = bodyCount == 1 || TestRngInt(&rng, 8) == 0 || other == a;
				g_bodyA[i] = a;
				g_bodyB[i] = immovable ? -1 : other;
				if (TestRngInt(&rng, 2) == 0)
				{
					int t = g_bodyA[i];
					g_bodyA[i] = g_bodyB[i];
					g_bodyB[i] = t;
				}
			}
			CheckColoring(count, bodyCount, false);
			CheckColoring(count, bodyCount, true);
		}
	}
}

/* Kinds of contact in a pyramid: with the ground, with the right neighbour, and with the box above
 * on the left and on the right. */
enum
{
	KIND_GROUND,
	KIND_SIDE,
	KIND_UP_LEFT,
	KIND_UP_RIGHT,
	KIND_COUNT
};

/* A pyramid of base 60 (1830 boxes, 5370 contacts) listed box by box, row by row, each box with
 * its contacts in the same order: the regular layout a world's contact list has for a pyramid.
 * Coloured mixed, every colour with many constraints holds both kinds of support, neither above
 * three quarters: in index order the colours hold one kind each (every box's support on its left
 * solved before every support on its right, a bias the same in every pass that sways the
 * pyramid). */
static void TestPyramidColorsMixKinds(void)
{
	const int base = 60;
	static int index[60][60];
	static int kind[MAX_CONSTRAINTS];
	int bodyCount = 0, count = 0;
	for (int row = 0; row < base; ++row)
	{
		for (int j = row; j < base; ++j)
		{
			index[row][j] = bodyCount++;
		}
	}
	for (int row = 0; row < base; ++row)
	{
		for (int j = row; j < base; ++j)
		{
			int box = index[row][j];
			if (row == 0)
			{
				g_bodyA[count] = -1;
				g_bodyB[count] = box;
				kind[count++] = KIND_GROUND;
			}
			if (j + 1 < base)
			{
				g_bodyA[count] = box;
				g_bodyB[count] = index[row][j + 1];
				kind[count++] = KIND_SIDE;
			}
			/* The boxes of the next row stand on boxes j - 1 and j of this one. */
			if (row + 1 < base && j >= row + 1)
			{
				g_bodyA[count] = box;
				g_bodyB[count] = index[row + 1][j];
				kind[count++] = KIND_UP_LEFT;
			}
			if (row + 1 < base && j + 1 < base)
			{
				g_bodyA[count] = box;
				g_bodyB[count] = index[row + 1][j + 1];
				kind[count++] = KIND_UP_RIGHT;
			}
		}
	}
	TEST_CHECKF(count <= MAX_CONSTRAINTS && bodyCount <= MAX_BODIES, "%d constraints, %d bodies", count,
				bodyCount);
	CheckColoring(count, bodyCount, true);
	int perColor[CD_GRAPH_COLOR_COUNT + 1][KIND_COUNT];
	memset(perColor, 0, sizeof(perColor));
	for (int i = 0; i < count; ++i)
	{
		perColor[g_colors[i]][kind[i]] += 1;
	}
	int checked = 0;
	for (int color = 0; color < CD_GRAPH_COLOR_COUNT; ++color)
	{
		int left = perColor[color][KIND_UP_LEFT], right = perColor[color][KIND_UP_RIGHT];
		if (left + right < 200)
		{
			continue;
		}
		++checked;
		TEST_CHECKF(4 * left <= 3 * (left + right) && 4 * right <= 3 * (left + right),
					"colour %d: %d supports on the left, %d on the right", color, left, right);
	}
	TEST_CHECKF(checked >= 3, "%d colours with 200 supports or more", checked);
	TEST_CHECKF(
		perColor[CD_GRAPH_COLOR_COUNT][KIND_UP_LEFT] + perColor[CD_GRAPH_COLOR_COUNT][KIND_UP_RIGHT] == 0,
		"supports in the overflow colour");
}

int main(void)
{
	TEST_RUN(TestRandomConstraints);
	TEST_RUN(TestPyramidColorsMixKinds);
	return TEST_SUMMARY();
}
