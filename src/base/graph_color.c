/* collide: greedy constraint colouring, see graph_color.h. */
#include "graph_color.h"

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
	int words = (bodyCount + 63) / 64;
	uint64_t* used = (uint64_t*)cdArena_Alloc(arena, (size_t)CD_GRAPH_COLOR_COUNT *
														 (size_t)(words > 0 ? words : 1) * sizeof(uint64_t));
	int* start = (int*)cdArena_Alloc(arena, (size_t)(CD_GRAPH_COLOR_COUNT + 2) * sizeof(int));
	if (used == NULL || start == NULL)
	{
		return false;
	}
	for (int i = 0; i < count; ++i)
	{
		int a = bodyA[i], b = bodyB[i];
		int color = CD_GRAPH_COLOR_COUNT;
		/* A pair of movable bodies takes the first free colour below the reserved ones; a
		 * constraint with an immovable body the last free colour, searching down to colour 1, so
		 * that it is solved after the pairs around it and has the last word in each pass. */
		bool immovable = a < 0 || b < 0;
		int first = immovable ? CD_GRAPH_COLOR_COUNT - 1 : 0;
		int last = immovable ? 1 : CD_GRAPH_COLOR_COUNT - 1 - CD_GRAPH_IMMOVABLE_COLORS;
		int stepColor = immovable ? -1 : 1;
		for (int c = first; immovable ? c >= last : c <= last; c += stepColor)
		{
			uint64_t* set = used + (size_t)c * (size_t)words;
			bool busyA = a >= 0 && ((set[a >> 6] >> (a & 63)) & 1u) != 0;
			bool busyB = b >= 0 && ((set[b >> 6] >> (b & 63)) & 1u) != 0;
			if (!busyA && !busyB)
			{
				if (a >= 0)
				{
					set[a >> 6] |= (uint64_t)1 << (a & 63);
				}
				if (b >= 0)
				{
					set[b >> 6] |= (uint64_t)1 << (b & 63);
				}
				color = c;
				break;
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
