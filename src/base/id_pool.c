/* collide: id pool: slot indices handed out and reused last-in first-out. */
#include "container.h"

void cdIdPool_Destroy(cdIdPool* pool)
{
	cdFree(pool->freeIds);
	memset(pool, 0, sizeof(*pool));
}

int cdIdPool_Alloc(cdIdPool* pool)
{
	if (pool->freeCount > 0)
	{
		return pool->freeIds[--pool->freeCount];
	}
	if (pool->nextIndex == INT32_MAX)
	{
		return -1;
	}
	return pool->nextIndex++;
}

void cdIdPool_Free(cdIdPool* pool, int id)
{
	CD_ASSERT(0 <= id && id < pool->nextIndex);
	if (!cdArrayReserve((void**)&pool->freeIds, &pool->freeCapacity, pool->freeCount + 1, sizeof(int)))
	{
		return; /* the slot leaks rather than being handed out twice */
	}
	pool->freeIds[pool->freeCount++] = id;
}
