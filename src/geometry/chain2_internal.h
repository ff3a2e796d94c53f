/* collide: the layout of a 2D chain, shared by its builder (chain2.c) and its queries
 * (query/chain_query2.c). Not installed. */
#ifndef COLLIDE_CHAIN2_INTERNAL_H
#define COLLIDE_CHAIN2_INTERNAL_H

#include "collide/chain2.h"

/* Levels of the bounding hierarchy: level 0 holds one box per segment, level k + 1 one box per
 * CHAIN_BRANCH consecutive boxes of level k, up to a single root. 2^24 points need 13 levels. Four
 * children of 16 bytes (float) share one cache line: a query reads half as many lines from the
 * cold lower levels as a binary tree would. */
#define CHAIN_BRANCH 4
#define CHAIN_MAX_LEVELS 32

struct cd2Chain
{
	cd2Vec* points;
	int pointCount;
	int segmentCount;
	bool isLoop;
	int levelCount;
	int levelOffset[CHAIN_MAX_LEVELS]; /* index of the level's first box in bounds */
	int levelSize[CHAIN_MAX_LEVELS];
	cd2Aabb* bounds;
};

static inline cd2Vec cd2ChainPoint(const cd2Chain* chain, int index)
{
	return chain->points[index == chain->pointCount ? 0 : index];
}

#endif
