/* collide: hash set of 64-bit pair keys, open addressing with linear probing and backward-shift
 * deletion (no tombstones, so lookups stay short after many removals). */
#include "container.h"

void cdPairSet_Destroy(cdPairSet* set)
{
	cdFree(set->keys);
	memset(set, 0, sizeof(*set));
}

void cdPairSet_Clear(cdPairSet* set)
{
	if (set->capacity > 0)
	{
		memset(set->keys, 0, (size_t)set->capacity * sizeof(uint64_t));
	}
	set->count = 0;
}

static bool cdPairSet_Grow(cdPairSet* set)
{
	int capacity = set->capacity == 0 ? 32 : 2 * set->capacity;
	uint64_t* keys = (uint64_t*)cdAlloc((size_t)capacity * sizeof(uint64_t));
	if (keys == NULL)
	{
		return false;
	}
	memset(keys, 0, (size_t)capacity * sizeof(uint64_t));
	uint32_t mask = (uint32_t)capacity - 1u;
	for (int i = 0; i < set->capacity; ++i)
	{
		uint64_t stored = set->keys[i];
		if (stored == 0)
		{
			continue;
		}
		uint32_t slot = cdPairHash(stored - 1) & mask;
		while (keys[slot] != 0)
		{
			slot = (slot + 1) & mask;
		}
		keys[slot] = stored;
	}
	cdFree(set->keys);
	set->keys = keys;
	set->capacity = capacity;
	return true;
}

bool cdPairSet_Add(cdPairSet* set, uint64_t key)
{
	if (2 * (set->count + 1) > set->capacity && !cdPairSet_Grow(set))
	{
		return false;
	}
	uint32_t mask = (uint32_t)set->capacity - 1u;
	uint32_t slot = cdPairHash(key) & mask;
	while (set->keys[slot] != 0)
	{
		if (set->keys[slot] == key + 1)
		{
			return true;
		}
		slot = (slot + 1) & mask;
	}
	set->keys[slot] = key + 1;
	set->count += 1;
	return true;
}

static int cdPairSet_Slot(const cdPairSet* set, uint64_t key)
{
	if (set->capacity == 0)
	{
		return -1;
	}
	uint32_t mask = (uint32_t)set->capacity - 1u;
	uint32_t slot = cdPairHash(key) & mask;
	while (set->keys[slot] != 0)
	{
		if (set->keys[slot] == key + 1)
		{
			return (int)slot;
		}
		slot = (slot + 1) & mask;
	}
	return -1;
}

bool cdPairSet_Contains(const cdPairSet* set, uint64_t key)
{
	return cdPairSet_Slot(set, key) >= 0;
}

bool cdPairSet_Remove(cdPairSet* set, uint64_t key)
{
	int found = cdPairSet_Slot(set, key);
	if (found < 0)
	{
		return false;
	}
	uint32_t mask = (uint32_t)set->capacity - 1u;
	uint32_t hole = (uint32_t)found;
	uint32_t next = (hole + 1) & mask;
	while (set->keys[next] != 0)
	{
		uint32_t home = cdPairHash(set->keys[next] - 1) & mask;
		/* Move the entry back into the hole when its home is not in (hole, next]. */
		bool between = hole <= next ? (hole < home && home <= next) : (hole < home || home <= next);
		if (!between)
		{
			set->keys[hole] = set->keys[next];
			hole = next;
		}
		next = (next + 1) & mask;
	}
	set->keys[hole] = 0;
	set->count -= 1;
	return true;
}
