/* collide: 2D chain builder and validator.
 *
 * The bounding hierarchy is a complete 4-ary tree over the segments in chain order, stored level
 * by level (no child pointers: the children of box i at level k + 1 are boxes 4i to 4i + 3 at
 * level k). A polyline's consecutive segments are neighbours in space, so boxes over runs of them
 * stay tight for terrain; the layout costs 4/3 of a box per segment and builds in O(n) without
 * sorting. */
#include "chain2_internal.h"

#include <string.h>

static cd2Aabb SegmentBounds(cd2Vec a, cd2Vec b)
{
	cd2Aabb box = {cd2Min(a, b), cd2Max(a, b)};
	return box;
}

static void BuildHierarchy(cd2Chain* chain)
{
	int size = chain->segmentCount;
	int offset = 0;
	for (int i = 0; i < size; ++i)
	{
		chain->bounds[i] = SegmentBounds(chain->points[i], cd2ChainPoint(chain, i + 1));
	}
	chain->levelCount = 0;
	for (;;)
	{
		chain->levelOffset[chain->levelCount] = offset;
		chain->levelSize[chain->levelCount] = size;
		++chain->levelCount;
		if (size == 1)
		{
			break;
		}
		int parentOffset = offset + size;
		int parentSize = (size + CHAIN_BRANCH - 1) / CHAIN_BRANCH;
		for (int i = 0; i < parentSize; ++i)
		{
			int first = CHAIN_BRANCH * i;
			int last = first + CHAIN_BRANCH < size ? first + CHAIN_BRANCH : size;
			cd2Aabb box = chain->bounds[offset + first];
			for (int k = first + 1; k < last; ++k)
			{
				box = cd2AabbUnion(box, chain->bounds[offset + k]);
			}
			chain->bounds[parentOffset + i] = box;
		}
		offset = parentOffset;
		size = parentSize;
	}
}

/* Boxes in a hierarchy over n leaves: n + ceil(n/4) + ... + 1 < 4n/3 + levels. */
static int HierarchySize(int leaves)
{
	int total = 0;
	for (int size = leaves;; size = (size + CHAIN_BRANCH - 1) / CHAIN_BRANCH)
	{
		total += size;
		if (size == 1)
		{
			return total;
		}
	}
}

cdResult cd2CreateChain(const cd2Vec* points, int count, bool isLoop, cd2Chain** chain)
{
	if (points == NULL || chain == NULL || count < 0)
	{
		return CD_ERROR_INVALID_ARGUMENT;
	}
	if (count > CD2_MAX_CHAIN_POINTS)
	{
		return CD_ERROR_TOO_MANY_POINTS;
	}
	cdReal maxAbs = CD_R(0.0);
	for (int i = 0; i < count; ++i)
	{
		if (!cd2IsValidVec(points[i]))
		{
			return CD_ERROR_NOT_FINITE;
		}
		maxAbs = cdMax(maxAbs, cdMax(cdAbs(points[i].x), cdAbs(points[i].y)));
	}
	double tolerance = (double)cd2GetPolygonWeldTolerance(maxAbs);
	double toleranceSquared = tolerance * tolerance;

	/* Count the points that survive welding first, so that one allocation holds everything. */
	int kept = 0;
	int last = -1;
	for (int i = 0; i < count; ++i)
	{
		if (last >= 0)
		{
			double dx = (double)points[i].x - (double)points[last].x;
			double dy = (double)points[i].y - (double)points[last].y;
			if (dx * dx + dy * dy <= toleranceSquared)
			{
				continue;
			}
		}
		last = i;
		++kept;
	}
	bool closingWeld = false;
	if (isLoop && kept >= 2)
	{
		double dx = (double)points[last].x - (double)points[0].x;
		double dy = (double)points[last].y - (double)points[0].y;
		closingWeld = dx * dx + dy * dy <= toleranceSquared;
		kept -= closingWeld ? 1 : 0;
	}
	if (kept < (isLoop ? 3 : 2))
	{
		return CD_ERROR_DEGENERATE;
	}

	int segmentCount = isLoop ? kept : kept - 1;
	int boxCount = HierarchySize(segmentCount);
	size_t headerSize = (sizeof(cd2Chain) + 31u) & ~(size_t)31u;
	size_t pointsSize = (sizeof(cd2Vec) * (size_t)kept + 31u) & ~(size_t)31u;
	size_t total = headerSize + pointsSize + sizeof(cd2Aabb) * (size_t)boxCount;
	unsigned char* memory = (unsigned char*)cdAlloc(total);
	if (memory == NULL)
	{
		return CD_ERROR_OUT_OF_MEMORY;
	}
	cd2Chain* out = (cd2Chain*)memory;
	memset(out, 0, sizeof(*out));
	out->points = (cd2Vec*)(memory + headerSize);
	out->bounds = (cd2Aabb*)(memory + headerSize + pointsSize);
	out->isLoop = isLoop;
	out->segmentCount = segmentCount;

	int n = 0;
	last = -1;
	for (int i = 0; i < count && n < kept; ++i)
	{
		if (last >= 0)
		{
			double dx = (double)points[i].x - (double)points[last].x;
			double dy = (double)points[i].y - (double)points[last].y;
			if (dx * dx + dy * dy <= toleranceSquared)
			{
				continue;
			}
		}
		last = i;
		out->points[n++] = points[i];
	}
	out->pointCount = n;
	BuildHierarchy(out);
	*chain = out;
	return CD_OK;
}

void cd2DestroyChain(cd2Chain* chain)
{
	cdFree(chain);
}

cdResult cd2ValidateChain(const cd2Chain* chain)
{
	if (chain == NULL || chain->points == NULL || chain->bounds == NULL)
	{
		return CD_ERROR_INVALID_ARGUMENT;
	}
	if (chain->pointCount > CD2_MAX_CHAIN_POINTS)
	{
		return CD_ERROR_TOO_MANY_POINTS;
	}
	if (chain->pointCount < (chain->isLoop ? 3 : 2) ||
		chain->segmentCount != (chain->isLoop ? chain->pointCount : chain->pointCount - 1))
	{
		return CD_ERROR_DEGENERATE;
	}
	for (int i = 0; i < chain->pointCount; ++i)
	{
		if (!cd2IsValidVec(chain->points[i]))
		{
			return CD_ERROR_NOT_FINITE;
		}
	}
	for (int i = 0; i < chain->segmentCount; ++i)
	{
		cd2Vec a = chain->points[i], b = cd2ChainPoint(chain, i + 1);
		if (a.x == b.x && a.y == b.y)
		{
			return CD_ERROR_DEGENERATE;
		}
	}
	if (chain->levelCount < 1 || chain->levelCount > CHAIN_MAX_LEVELS ||
		chain->levelSize[0] != chain->segmentCount || chain->levelSize[chain->levelCount - 1] != 1)
	{
		return CD_ERROR_INVALID_ARGUMENT;
	}
	for (int i = 0; i < chain->segmentCount; ++i)
	{
		cd2Aabb box = chain->bounds[i];
		cd2Aabb tight = SegmentBounds(chain->points[i], cd2ChainPoint(chain, i + 1));
		if (!cd2AabbContains(box, tight))
		{
			return CD_ERROR_INVALID_ARGUMENT;
		}
	}
	for (int level = 1; level < chain->levelCount; ++level)
	{
		int below = chain->levelOffset[level - 1], size = chain->levelSize[level - 1];
		if (chain->levelSize[level] != (size + CHAIN_BRANCH - 1) / CHAIN_BRANCH)
		{
			return CD_ERROR_INVALID_ARGUMENT;
		}
		for (int i = 0; i < size; ++i)
		{
			if (!cd2AabbContains(chain->bounds[chain->levelOffset[level] + i / CHAIN_BRANCH],
								 chain->bounds[below + i]))
			{
				return CD_ERROR_INVALID_ARGUMENT;
			}
		}
	}
	return CD_OK;
}

int cd2Chain_GetSegmentCount(const cd2Chain* chain)
{
	CD_ASSERT(chain != NULL);
	return chain->segmentCount;
}

int cd2Chain_GetPointCount(const cd2Chain* chain)
{
	CD_ASSERT(chain != NULL);
	return chain->pointCount;
}

const cd2Vec* cd2Chain_GetPoints(const cd2Chain* chain)
{
	CD_ASSERT(chain != NULL);
	return chain->points;
}

bool cd2Chain_IsLoop(const cd2Chain* chain)
{
	CD_ASSERT(chain != NULL);
	return chain->isLoop;
}

cd2Aabb cd2Chain_GetBounds(const cd2Chain* chain)
{
	CD_ASSERT(chain != NULL);
	return chain->bounds[chain->levelOffset[chain->levelCount - 1]];
}

cd2ChainSegment cd2Chain_GetSegment(const cd2Chain* chain, int index)
{
	CD_ASSERT(chain != NULL && index >= 0 && index < chain->segmentCount);
	int n = chain->pointCount;
	cd2ChainSegment s;
	s.p1 = chain->points[index];
	s.p2 = cd2ChainPoint(chain, index + 1);
	if (chain->isLoop)
	{
		s.ghost1 = chain->points[(index + n - 1) % n];
		s.ghost2 = chain->points[(index + 2) % n];
	}
	else
	{
		/* Open ends continue straight on: a flat junction, so nothing catches there. */
		cd2Vec edge = cd2Sub(s.p2, s.p1);
		s.ghost1 = index > 0 ? chain->points[index - 1] : cd2Sub(s.p1, edge);
		s.ghost2 = index + 2 < n ? chain->points[index + 2] : cd2Add(s.p2, edge);
	}
	return s;
}
