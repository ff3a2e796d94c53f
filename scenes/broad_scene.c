/* The broadphase benchmark scene (see broad_scene.h). The random stream and the order of its
 * draws define the scene: changing either changes every published figure's scene. */
#include "broad_scene.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum
{
	MOTION_STILL,
	MOTION_MOVING,
	MOTION_TELEPORTING
};

/* splitmix64: tiny, fast and the same on every platform. */
static uint64_t nextRandom(uint64_t* state)
{
	uint64_t z = (*state += 0x9e3779b97f4a7c15ULL);
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
	return z ^ (z >> 31);
}

static float uniform(uint64_t* state, float lo, float hi)
{
	return lo + (hi - lo) * (float)((double)(nextRandom(state) >> 11) * (1.0 / 9007199254740992.0));
}

static float minFloat(float a, float b)
{
	return a < b ? a : b;
}

static float maxFloat(float a, float b)
{
	return a > b ? a : b;
}

static void setBox(BroadBox* box, const float* center, const float* half, int dim)
{
	for (int axis = 0; axis < 3; ++axis)
	{
		box->min[axis] = center[axis] - half[axis];
		box->max[axis] = center[axis] + half[axis];
	}
	if (dim == 2)
	{
		box->min[2] = 0.0f;
		box->max[2] = 1.0f;
	}
}

uint64_t broadSceneSeed(int dim, int n)
{
	return (uint64_t)0xC011DE + (uint64_t)n * (uint64_t)31 + (uint64_t)dim;
}

const char* broadSceneKindName(BroadSceneKind kind)
{
	return kind == BROAD_SCENE_MIX ? "mix" : "moving";
}

void broadSceneFree(BroadScene* scene)
{
	free(scene->boxes);
	free(scene->velocity);
	free(scene->displacement);
	free(scene->moved);
	free(scene->queries);
	free(scene->rays);
	free(scene->center);
	free(scene->half);
	free(scene->motion);
	memset(scene, 0, sizeof *scene);
}

static void initQueries(BroadScene* scene)
{
	for (int q = 0; q < scene->queryCount; ++q)
	{
		float center[3] = {0.0f, 0.0f, 0.5f}, half[3] = {0.0f, 0.0f, 0.5f};
		BroadRay* ray = &scene->rays[q];
		float length = minFloat(scene->worldSize, 20.0f);
		float direction[3] = {0.0f, 0.0f, 0.0f}, norm = 0.0f;
		for (int axis = 0; axis < scene->dim; ++axis)
		{
			center[axis] = uniform(&scene->rngState, 0.0f, scene->worldSize);
			half[axis] = uniform(&scene->rngState, 1.0f, 3.0f);
			ray->origin[axis] = uniform(&scene->rngState, 0.0f, scene->worldSize);
			direction[axis] = uniform(&scene->rngState, -1.0f, 1.0f);
			norm += direction[axis] * direction[axis];
		}
		norm = sqrtf(maxFloat(norm, 1e-12f));
		if (scene->dim == 2)
		{
			ray->origin[2] = 0.5f;
		}
		for (int axis = 0; axis < 3; ++axis)
		{
			ray->translation[axis] = direction[axis] * length / norm;
		}
		setBox(&scene->queries[q], center, half, 3);
	}
}

bool broadSceneInit(BroadScene* scene, int dim, int n, BroadSceneKind kind, uint64_t seed)
{
	memset(scene, 0, sizeof *scene);
	if ((dim != 2 && dim != 3) || n < 1)
	{
		return false;
	}
	size_t count = (size_t)n;
	scene->dim = dim;
	scene->n = n;
	scene->kind = kind;
	scene->timeStep = 1.0f / 60.0f;
	scene->rngState = seed;
	/* Mean edge 1 m; about 1/8 (3D) or 1/4 (2D) box per unit volume gives about one overlap per
	 * box. */
	scene->worldSize = dim == 3 ? 2.0f * cbrtf((float)n) : 2.0f * sqrtf((float)n);
	scene->worldSize = maxFloat(scene->worldSize, 8.0f);
	scene->queryCount = n < 50 ? 50 : (n > 1000 ? 1000 : n);
	scene->boxes = calloc(count, sizeof(BroadBox));
	scene->velocity = calloc(count * 3, sizeof(float));
	scene->displacement = calloc(count * 3, sizeof(float));
	scene->moved = calloc(count, sizeof(int));
	scene->queries = calloc((size_t)scene->queryCount, sizeof(BroadBox));
	scene->rays = calloc((size_t)scene->queryCount, sizeof(BroadRay));
	scene->center = calloc(count * 3, sizeof(float));
	scene->half = calloc(count * 3, sizeof(float));
	scene->motion = calloc(count, sizeof(uint8_t));
	if (!scene->boxes || !scene->velocity || !scene->displacement || !scene->moved || !scene->queries ||
		!scene->rays || !scene->center || !scene->half || !scene->motion)
	{
		broadSceneFree(scene);
		return false;
	}
	for (size_t i = 0; i < count; ++i)
	{
		for (size_t axis = 0; axis < (size_t)dim; ++axis)
		{
			scene->half[i * 3 + axis] = uniform(&scene->rngState, 0.25f, 0.75f);
			scene->center[i * 3 + axis] = uniform(&scene->rngState, 0.75f, scene->worldSize - 0.75f);
			scene->velocity[i * 3 + axis] = uniform(&scene->rngState, -1.0f, 1.0f);
		}
		scene->motion[i] = MOTION_MOVING;
		if (kind == BROAD_SCENE_MIX)
		{
			float r = uniform(&scene->rngState, 0.0f, 1.0f);
			scene->motion[i] = r < 0.90f ? MOTION_STILL : (r < 0.99f ? MOTION_MOVING : MOTION_TELEPORTING);
		}
		setBox(&scene->boxes[i], &scene->center[i * 3], &scene->half[i * 3], dim);
	}
	initQueries(scene);
	return true;
}

void broadSceneStep(BroadScene* scene)
{
	scene->movedCount = 0;
	for (size_t i = 0; i < (size_t)scene->n; ++i)
	{
		float* c = &scene->center[i * 3];
		const float* h = &scene->half[i * 3];
		float* v = &scene->velocity[i * 3];
		float* d = &scene->displacement[i * 3];
		if (scene->motion[i] == MOTION_STILL)
		{
			continue;
		}
		if (scene->motion[i] == MOTION_MOVING)
		{
			for (int axis = 0; axis < scene->dim; ++axis)
			{
				float next = c[axis] + v[axis] * scene->timeStep;
				if (next - h[axis] < 0.0f || next + h[axis] > scene->worldSize)
				{
					v[axis] = -v[axis]; /* bounce off the walls */
					next = c[axis] + v[axis] * scene->timeStep;
				}
				c[axis] = next;
				d[axis] = v[axis] * scene->timeStep;
			}
		}
		else
		{
			for (int axis = 0; axis < scene->dim; ++axis)
			{
				c[axis] = uniform(&scene->rngState, 0.75f, scene->worldSize - 0.75f);
				d[axis] = 0.0f;
			}
		}
		setBox(&scene->boxes[i], c, h, scene->dim);
		scene->moved[scene->movedCount++] = (int)i;
	}
}

BroadBox broadSceneWorldBounds(const BroadScene* scene)
{
	BroadBox world;
	for (int axis = 0; axis < 3; ++axis)
	{
		world.min[axis] = 0.0f;
		world.max[axis] = axis < scene->dim ? scene->worldSize : 1.0f;
	}
	return world;
}

bool broadRayHitsBox(const BroadRay* ray, const BroadBox* box)
{
	float tmin = 0.0f, tmax = 1.0f;
	for (int axis = 0; axis < 3; ++axis)
	{
		float o = ray->origin[axis], d = ray->translation[axis];
		if (d == 0.0f)
		{
			if (o < box->min[axis] || o > box->max[axis])
			{
				return false;
			}
			continue;
		}
		float t1 = (box->min[axis] - o) / d, t2 = (box->max[axis] - o) / d;
		tmin = maxFloat(tmin, minFloat(t1, t2));
		tmax = minFloat(tmax, maxFloat(t1, t2));
		if (tmin > tmax)
		{
			return false;
		}
	}
	return true;
}

typedef struct SweepEntry
{
	float minX;
	int index;
} SweepEntry;

static int compareSweepEntries(const void* a, const void* b)
{
	const SweepEntry* x = a;
	const SweepEntry* y = b;
	if (x->minX != y->minX)
	{
		return x->minX < y->minX ? -1 : 1;
	}
	return (x->index > y->index) - (x->index < y->index);
}

size_t broadSceneCountPairs(const BroadScene* scene)
{
	SweepEntry* order = malloc((size_t)scene->n * sizeof *order);
	if (!order)
	{
		return SIZE_MAX;
	}
	for (int i = 0; i < scene->n; ++i)
	{
		order[i].minX = scene->boxes[i].min[0];
		order[i].index = i;
	}
	qsort(order, (size_t)scene->n, sizeof *order, compareSweepEntries);
	size_t count = 0;
	for (int i = 0; i < scene->n; ++i)
	{
		const BroadBox* a = &scene->boxes[order[i].index];
		for (int j = i + 1; j < scene->n && order[j].minX <= a->max[0]; ++j)
		{
			count += broadBoxesOverlap(a, &scene->boxes[order[j].index]) ? 1u : 0u;
		}
	}
	free(order);
	return count;
}

/* ---- pair list ---------------------------------------------------------------------------- */

enum
{
	BROAD_PAIR_MOVED = 1,
	BROAD_PAIR_CHANGED = 2
};

bool broadPairListInit(BroadPairList* list, int boxCount)
{
	memset(list, 0, sizeof *list);
	list->boxCount = boxCount < 0 ? 0 : boxCount;
	list->flags = calloc((size_t)list->boxCount + 1, 1);
	list->flaggedList = malloc(((size_t)list->boxCount + 1) * sizeof(int));
	if (!list->flags || !list->flaggedList)
	{
		broadPairListFree(list);
		return false;
	}
	return true;
}

void broadPairListFree(BroadPairList* list)
{
	free(list->pairs);
	free(list->fresh);
	free(list->flags);
	free(list->flaggedList);
	memset(list, 0, sizeof *list);
}

static void markBox(BroadPairList* list, int index, uint8_t flag)
{
	if (index < 0 || index >= list->boxCount)
	{
		list->failed = true;
		return;
	}
	if (list->flags[index] == 0)
	{
		list->flaggedList[list->flaggedCount++] = index;
	}
	list->flags[index] |= flag;
}

void broadPairListMarkMoved(BroadPairList* list, int index)
{
	markBox(list, index, BROAD_PAIR_MOVED);
}

void broadPairListMarkChanged(BroadPairList* list, int index)
{
	list->tracksChanges = true;
	markBox(list, index, BROAD_PAIR_CHANGED);
}

static bool reservePairs(BroadPair** pairs, size_t* capacity, size_t needed)
{
	if (needed <= *capacity)
	{
		return true;
	}
	size_t grown = *capacity < 64 ? 64 : *capacity * 2;
	grown = grown < needed ? needed : grown;
	BroadPair* bigger = realloc(*pairs, grown * sizeof(BroadPair));
	if (!bigger)
	{
		return false;
	}
	*pairs = bigger;
	*capacity = grown;
	return true;
}

void broadPairListAdd(BroadPairList* list, int a, int b)
{
	if (a < 0 || b < 0 || a >= list->boxCount || b >= list->boxCount)
	{
		list->failed = true; /* not a box of the scene: the counts can no longer be right */
		return;
	}
	if (!reservePairs(&list->fresh, &list->freshCapacity, list->freshCount + 1))
	{
		list->failed = true;
		return;
	}
	list->fresh[list->freshCount].a = a;
	list->fresh[list->freshCount].bOrOverlap = b;
	++list->freshCount;
}

static int pairSecond(BroadPair pair)
{
	return pair.bOrOverlap < 0 ? ~pair.bOrOverlap : pair.bOrOverlap;
}

static bool pairOverlapping(BroadPair pair)
{
	return pair.bOrOverlap < 0;
}

/* The pair with its overlap bit set to the comparison of its two tight boxes. */
static BroadPair comparePair(BroadPair pair, const BroadBox* boxes)
{
	int b = pairSecond(pair);
	pair.bOrOverlap = broadBoxesOverlap(&boxes[pair.a], &boxes[b]) ? ~b : b;
	return pair;
}

/* Whether a kept pair's boxes are compared again: flags are the pair's two boxes' flags. */
static bool pairNeedsCompare(const BroadPairList* list, int flags)
{
	return !(flags & BROAD_PAIR_MOVED) && ((flags & BROAD_PAIR_CHANGED) || !list->tracksChanges);
}

/* Starts loading the two boxes of a pair (a hint: nothing elsewhere). The pairs' boxes lie at
 * random in the scene's array, which outgrows the cache at 1M boxes: loading them this many pairs
 * ahead lets the misses overlap instead of being waited for one by one. */
enum
{
	PAIR_BOX_AHEAD = 16
};
static void prefetchPairBoxes(const BroadBox* boxes, BroadPair pair)
{
#if defined(__GNUC__) || defined(__clang__)
	__builtin_prefetch(&boxes[pair.a]);
	__builtin_prefetch(&boxes[pairSecond(pair)]);
#else
	(void)boxes;
	(void)pair;
#endif
}

size_t broadPairListEndFrame(BroadPairList* list, const BroadBox* boxes)
{
	size_t count = 0, kept = 0;
	for (size_t k = 0; k < list->pairCount; ++k)
	{
		if (k + PAIR_BOX_AHEAD < list->pairCount)
		{
			BroadPair ahead = list->pairs[k + PAIR_BOX_AHEAD];
			if (pairNeedsCompare(list, list->flags[ahead.a] | list->flags[pairSecond(ahead)]))
			{
				prefetchPairBoxes(boxes, ahead);
			}
		}
		BroadPair pair = list->pairs[k];
		int flags = list->flags[pair.a] | list->flags[pairSecond(pair)];
		if (flags & BROAD_PAIR_MOVED)
		{
			continue;
		}
		if (pairNeedsCompare(list, flags))
		{
			pair = comparePair(pair, boxes);
		}
		count += pairOverlapping(pair) ? 1u : 0u;
		list->pairs[kept++] = pair;
	}
	list->pairCount = kept;
	if (!reservePairs(&list->pairs, &list->pairCapacity, kept + list->freshCount))
	{
		list->failed = true;
	}
	else
	{
		for (size_t k = 0; k < list->freshCount; ++k)
		{
			if (k + PAIR_BOX_AHEAD < list->freshCount)
			{
				prefetchPairBoxes(boxes, list->fresh[k + PAIR_BOX_AHEAD]);
			}
			BroadPair pair = comparePair(list->fresh[k], boxes);
			count += pairOverlapping(pair) ? 1u : 0u;
			list->pairs[list->pairCount++] = pair;
		}
	}
	list->freshCount = 0;
	for (int k = 0; k < list->flaggedCount; ++k)
	{
		list->flags[list->flaggedList[k]] = 0;
	}
	list->flaggedCount = 0;
	list->tracksChanges = false;
	return list->failed ? SIZE_MAX : count;
}

size_t broadPairListBytes(const BroadPairList* list)
{
	return (list->pairCapacity + list->freshCapacity) * sizeof(BroadPair) + (size_t)list->boxCount + 1 +
		   ((size_t)list->boxCount + 1) * sizeof(int);
}
