/* collide: greedy constraint colouring, see graph_color.h. */
#include "graph_color.h"

#include <string.h>

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

/* Constraints are coloured in blocks of CD_GRAPH_SCRAMBLE_SIZE consecutive indices, each block in
 * a pseudo-random order (see cdColorConstraints). */
#define CD_GRAPH_SCRAMBLE_BITS 8
#define CD_GRAPH_SCRAMBLE_SIZE (1 << CD_GRAPH_SCRAMBLE_BITS)

/* A bijection of [0, CD_GRAPH_SCRAMBLE_SIZE) chosen by seed: odd multiplications and xor-shifts,
 * each invertible modulo a power of two. */
static inline uint32_t cdScramble(uint32_t x, uint32_t seed)
{
	const uint32_t mask = (uint32_t)CD_GRAPH_SCRAMBLE_SIZE - 1u;
	const int shift = CD_GRAPH_SCRAMBLE_BITS / 2 + 1;
	x = (x * 0x9E3779B1u + seed) & mask;
	x ^= x >> shift;
	x = (x * 0x85EBCA6Bu) & mask;
	x ^= x >> shift;
	return x;
}

/* Per body, one bit per colour it already has (used, bodyCount words): a constraint's free colours
 * are the bits clear in both of its bodies' masks. */
static void cdColor(const int* bodyA, const int* bodyB, int count, int bodyCount, int* colors, int* order,
					uint32_t* used, int* start, bool mixed)
{
	if (count == 0)
	{
		return;
	}
	if (bodyCount > 0)
	{
		memset(used, 0, (size_t)bodyCount * sizeof(uint32_t));
	}
	/* Movable pairs: colours 0 .. CD_GRAPH_COLOR_COUNT - 1 - CD_GRAPH_IMMOVABLE_COLORS; constraints
	 * with an immovable body: colours 1 .. CD_GRAPH_COLOR_COUNT - 1. */
	const uint32_t pairColors = ((uint32_t)1 << (CD_GRAPH_COLOR_COUNT - CD_GRAPH_IMMOVABLE_COLORS)) - 1u;
	const uint32_t immovableColors = (((uint32_t)1 << CD_GRAPH_COLOR_COUNT) - 1u) & ~(uint32_t)1;
	/* The colouring is greedy, so its visiting order decides which constraints share a colour. In
	 * index order, on a regular structure (a pyramid of boxes, whose contacts are stored in a
	 * regular pattern) every colour would hold one kind of contact, such as every box's contact
	 * with the box below on its left: each pass of the solver would then correct all the left
	 * supports before all the right ones, and that bias, the same in every sub-step, sways a tall
	 * pyramid sideways. Mixed: visited block by block, each block in a pseudo-random order (the
	 * same every step), every colour holds a mix of kinds, and the blocks keep the accesses local.
	 * A chain of joints listed link by link keeps the index order: its colours alternate along the
	 * chain, one pass over every other joint, then the others. */
	for (int first = 0; first < count; first += CD_GRAPH_SCRAMBLE_SIZE)
	{
		uint32_t seed = (uint32_t)(first / CD_GRAPH_SCRAMBLE_SIZE) * 0x9E3779B9u;
		for (int k = 0; k < CD_GRAPH_SCRAMBLE_SIZE; ++k)
		{
			int i = first + (mixed ? (int)cdScramble((uint32_t)k, seed) : k);
			if (i >= count)
			{
				continue;
			}
			int a = bodyA[i], b = bodyB[i];
			int color = CD_GRAPH_COLOR_COUNT;
			/* A pair of movable bodies takes the first free colour below the reserved ones; a
			 * constraint with an immovable body the last free colour, searching down to colour 1,
			 * so that it is solved after the pairs around it and has the last word in each pass. */
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
}

static bool cdColorInArena(const int* bodyA, const int* bodyB, int count, int bodyCount, int* colors,
						   int* order, cdArena* arena, bool mixed)
{
	for (int i = 0; i < count; ++i)
	{
		order[i] = i;
	}
	if (count == 0)
	{
		return true;
	}
	uint32_t* used =
		(uint32_t*)cdArena_AllocUncleared(arena, (size_t)(bodyCount > 0 ? bodyCount : 1) * sizeof(uint32_t));
	int* start = (int*)cdArena_AllocUncleared(arena, (size_t)(CD_GRAPH_COLOR_COUNT + 2) * sizeof(int));
	if (used == NULL || start == NULL)
	{
		return false;
	}
	cdColor(bodyA, bodyB, count, bodyCount, colors, order, used, start, mixed);
	return true;
}

bool cdColorConstraints(const int* bodyA, const int* bodyB, int count, int bodyCount, int* colors, int* order,
						cdArena* arena)
{
	return cdColorInArena(bodyA, bodyB, count, bodyCount, colors, order, arena, false);
}

bool cdColorConstraintsMixed(const int* bodyA, const int* bodyB, int count, int bodyCount, int* colors,
							 int* order, cdArena* arena)
{
	return cdColorInArena(bodyA, bodyB, count, bodyCount, colors, order, arena, true);
}

void cdColorConstraintsScratch(const int* bodyA, const int* bodyB, int count, int bodyCount, int* colors,
							   int* order, bool mixed, uint32_t* used, int* start)
{
	cdColor(bodyA, bodyB, count, bodyCount, colors, order, used, start, mixed);
}
