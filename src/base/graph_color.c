/* collide: greedy constraint colouring, see graph_color.h. */
#include "graph_color.h"

/* The colour masks below hold one bit per colour. */
typedef char cdGraphColorsFit[CD_GRAPH_COLOR_COUNT <= 31 ? 1 : -1];

/* Lowest and highest set bit of a nonzero mask. */
static inline int cdLowestBit32(uint32_t bits)
{
#if defined(__GNUC__) || defined(__clang__)
	return __builtin_ctz(bits);
#else
	int i = 0;
	while ((bits & 1u) == 0u)
	{
		bits >>= 1;
		++i;
	}
	return i;
#endif
}

static inline int cdHighestBit32(uint32_t bits)
{
#if defined(__GNUC__) || defined(__clang__)
	return 31 - __builtin_clz(bits);
#else
	int i = 31;
	while ((bits & 0x80000000u) == 0u)
	{
		bits <<= 1;
		--i;
	}
	return i;
#endif
}

bool cdColorConstraints(const int* bodyA, const int* bodyB, int count, int bodyCount, int* colors, int* order,
						cdArena* arena)
{
	for (int i = 0; i < count; ++i)
	{
		order[i] = i;
	}
	if (count == 0)
	{
		return true;
	}
	/* Per body, one bit per colour it already has: a constraint's free colours are the bits clear in
	 * both of its bodies' masks. */
	uint32_t* used =
		(uint32_t*)cdArena_Alloc(arena, (size_t)(bodyCount > 0 ? bodyCount : 1) * sizeof(uint32_t));
	int* start = (int*)cdArena_Alloc(arena, (size_t)(CD_GRAPH_COLOR_COUNT + 2) * sizeof(int));
	if (used == NULL || start == NULL)
	{
		return false;
	}
	/* Movable pairs: colours 0 .. CD_GRAPH_COLOR_COUNT - 1 - CD_GRAPH_IMMOVABLE_COLORS; constraints
	 * with an immovable body: colours 1 .. CD_GRAPH_COLOR_COUNT - 1. */
	const uint32_t pairColors = ((uint32_t)1 << (CD_GRAPH_COLOR_COUNT - CD_GRAPH_IMMOVABLE_COLORS)) - 1u;
	const uint32_t immovableColors = (((uint32_t)1 << CD_GRAPH_COLOR_COUNT) - 1u) & ~(uint32_t)1;
	for (int i = 0; i < count; ++i)
	{
		int a = bodyA[i], b = bodyB[i];
		int color = CD_GRAPH_COLOR_COUNT;
		/* A pair of movable bodies takes the first free colour below the reserved ones; a
		 * constraint with an immovable body the last free colour, searching down to colour 1, so
		 * that it is solved after the pairs around it and has the last word in each pass. */
		bool immovable = a < 0 || b < 0;
		uint32_t busy = (a >= 0 ? used[a] : 0u) | (b >= 0 ? used[b] : 0u);
		uint32_t free = ~busy & (immovable ? immovableColors : pairColors);
		if (free != 0u)
		{
			color = immovable ? cdHighestBit32(free) : cdLowestBit32(free);
			uint32_t bit = (uint32_t)1 << color;
			if (a >= 0)
			{
				used[a] |= bit;
			}
			if (b >= 0)
			{
				used[b] |= bit;
			}
		}
		colors[i] = color;
	}
	/* Counting sort by colour, stable. */
	for (int c = 0; c < CD_GRAPH_COLOR_COUNT + 2; ++c)
	{
		start[c] = 0;
	}
	for (int i = 0; i < count; ++i)
	{
		start[colors[i] + 1] += 1;
	}
	for (int c = 1; c < CD_GRAPH_COLOR_COUNT + 2; ++c)
	{
		start[c] += start[c - 1];
	}
	for (int i = 0; i < count; ++i)
	{
		order[start[colors[i]]++] = i;
	}
	return true;
}
