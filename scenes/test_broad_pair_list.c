/* The bench's contact list (broadPairList*) against brute force: it is the instrument every
 * broadphase frame time is measured with, so its counts must be exact in both of its modes.
 *
 * A tiny fat-box "structure" stands in for a broadphase: each box keeps a fat box (its tight box
 * grown by a margin) and gets a new one when its tight box leaves it; the structure then reports
 * every pair with such a box whose fat boxes overlap, in random order and either way round, as
 * the contract of broadPairListEndFrame asks. After each frame the list's count must equal the
 * number of pairs whose tight boxes overlap. */
#include "broad_scene.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

enum
{
	BOX_COUNT = 300,
	FRAME_COUNT = 60
};

static uint64_t rngState = 0x9e3779b97f4a7c15u;

static float uniformFloat(float lo, float hi)
{
	rngState = rngState * 6364136223846793005u + 1442695040888963407u;
	return lo + (hi - lo) * (float)(rngState >> 40) / (float)(1u << 24);
}

static BroadBox makeBox(float x, float y, float half)
{
	BroadBox box = {{x - half, y - half, 0.0f}, {x + half, y + half, 1.0f}};
	return box;
}

static BroadBox grow(BroadBox box, float margin)
{
	for (int axis = 0; axis < 2; ++axis)
	{
		box.min[axis] -= margin;
		box.max[axis] += margin;
	}
	return box;
}

/* The oracle's own box test, written apart from broadBoxesOverlap: the list under test uses that one. */
static bool overlap(const BroadBox* a, const BroadBox* b)
{
	for (int axis = 0; axis < 3; ++axis)
	{
		if (a->min[axis] > b->max[axis] || b->min[axis] > a->max[axis])
		{
			return false;
		}
	}
	return true;
}

static bool contains(const BroadBox* outer, const BroadBox* inner)
{
	for (int axis = 0; axis < 3; ++axis)
	{
		if (inner->min[axis] < outer->min[axis] || inner->max[axis] > outer->max[axis])
		{
			return false;
		}
	}
	return true;
}

static size_t bruteForceCount(const BroadBox* boxes)
{
	size_t count = 0;
	for (int i = 0; i < BOX_COUNT; ++i)
	{
		for (int j = i + 1; j < BOX_COUNT; ++j)
		{
			count += overlap(&boxes[i], &boxes[j]) ? 1u : 0u;
		}
	}
	return count;
}

static int failures = 0;

static void check(bool condition, const char* what, int frame)
{
	if (!condition)
	{
		fprintf(stderr, "FAILED (frame %d): %s\n", frame, what);
		++failures;
	}
}

/* Reports the pairs with a box whose fat box changed, shuffled, each either way round. */
static void reportPairs(BroadPairList* list, const BroadBox* fat, const bool* fatChanged)
{
	static int pairs[BOX_COUNT * BOX_COUNT][2];
	int count = 0;
	for (int i = 0; i < BOX_COUNT; ++i)
	{
		for (int j = i + 1; j < BOX_COUNT; ++j)
		{
			if ((fatChanged[i] || fatChanged[j]) && overlap(&fat[i], &fat[j]))
			{
				bool swap = uniformFloat(0.0f, 1.0f) < 0.5f;
				pairs[count][0] = swap ? j : i;
				pairs[count][1] = swap ? i : j;
				++count;
			}
		}
	}
	for (int k = count - 1; k > 0; --k)
	{
		int other = (int)uniformFloat(0.0f, (float)k + 0.999f);
		int a = pairs[k][0], b = pairs[k][1];
		pairs[k][0] = pairs[other][0];
		pairs[k][1] = pairs[other][1];
		pairs[other][0] = a;
		pairs[other][1] = b;
	}
	for (int k = 0; k < count; ++k)
	{
		broadPairListAdd(list, pairs[k][0], pairs[k][1]);
	}
}

int main(void)
{
	static BroadBox tight[BOX_COUNT], fat[BOX_COUNT];
	static bool fatChanged[BOX_COUNT], tightChanged[BOX_COUNT];
	const float world = 20.0f, margin = 0.3f;
	BroadPairList list;
	if (!broadPairListInit(&list, BOX_COUNT))
	{
		fprintf(stderr, "out of memory\n");
		return 1;
	}
	/* Boxes 0 and 1 coincide, so the pair of box 0 (whose overlap bit is stored as ~0 = -1) is in
	 * the list from the start. */
	for (int i = 0; i < BOX_COUNT; ++i)
	{
		tight[i] =
			i < 2 ? makeBox(5.0f, 5.0f, 0.5f)
				  : makeBox(uniformFloat(0.0f, world), uniformFloat(0.0f, world), uniformFloat(0.2f, 0.8f));
		fat[i] = grow(tight[i], margin);
		fatChanged[i] = true;
		broadPairListMarkMoved(&list, i);
	}
	for (int frame = 0; frame < FRAME_COUNT; ++frame)
	{
		if (frame > 0)
		{
			/* Most boxes stay; some drift, a few jump (a quarter of the frames move them all). */
			bool allMove = frame % 4 == 3;
			for (int i = 0; i < BOX_COUNT; ++i)
			{
				fatChanged[i] = tightChanged[i] = false;
				float r = uniformFloat(0.0f, 1.0f);
				if (!allMove && r > 0.2f)
				{
					continue;
				}
				float dx = r < 0.02f ? uniformFloat(-world, world) : uniformFloat(-0.2f, 0.2f);
				float dy = r < 0.02f ? uniformFloat(-world, world) : uniformFloat(-0.2f, 0.2f);
				for (int axis = 0; axis < 2; ++axis)
				{
					float d = axis == 0 ? dx : dy;
					tight[i].min[axis] += d;
					tight[i].max[axis] += d;
				}
				tightChanged[i] = true;
				if (!contains(&fat[i], &tight[i]))
				{
					fat[i] = grow(tight[i], margin);
					fatChanged[i] = true;
					broadPairListMarkMoved(&list, i);
				}
			}
			/* Both modes of EndFrame: with the changed boxes marked (only their pairs are compared
			 * again), and without marks (every kept pair is). */
			if (frame % 2 == 0)
			{
				for (int i = 0; i < BOX_COUNT; ++i)
				{
					if (tightChanged[i])
					{
						broadPairListMarkChanged(&list, i);
					}
				}
			}
		}
		reportPairs(&list, fat, fatChanged);
		size_t expected = bruteForceCount(tight);
		size_t counted = broadPairListEndFrame(&list, tight);
		check(counted == expected, "the list counts the pairs whose tight boxes overlap", frame);
		check(expected > 0, "the scene has overlapping pairs to count", frame);
	}
	/* A pair that names no box of the scene makes the count unusable, not wrong. */
	broadPairListAdd(&list, 3, BOX_COUNT);
	check(broadPairListEndFrame(&list, tight) == SIZE_MAX, "an index outside the scene fails the list",
		  FRAME_COUNT);
	broadPairListFree(&list);
	if (!broadPairListInit(&list, BOX_COUNT))
	{
		return 1;
	}
	broadPairListAdd(&list, -1, 0);
	check(broadPairListEndFrame(&list, tight) == SIZE_MAX, "a negative index fails the list", FRAME_COUNT);
	broadPairListFree(&list);
	if (failures == 0)
	{
		printf("pair list: %d frames of %d boxes agree with brute force\n", FRAME_COUNT, BOX_COUNT);
	}
	return failures == 0 ? 0 : 1;
}
