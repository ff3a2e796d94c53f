/* collide: dimension-free containers for the worlds (2D now, 3D later): a growable array, an
 * id pool with generations, a hash set of 64-bit pair keys, a bit set and a bump arena. Internal:
 * not part of the public API. Every allocation goes through cdAlloc/cdFree. Deterministic: the
 * order in which ids are handed out depends only on the order of the calls. */
#ifndef COLLIDE_CONTAINER_H
#define COLLIDE_CONTAINER_H

#include "collide/base.h"

#include <string.h>

/* ---- growable array (array.c) ------------------------------------------------------------------
 * Makes room for at least `needed` elements of `elementSize` bytes in *data (capacity in
 * *capacity), keeping the contents and zeroing the new tail. Returns false when memory runs out
 * (the array is then unchanged). */
bool cdArrayReserve(void** data, int* capacity, int needed, size_t elementSize);

/* A typed growable array: struct { T* data; int count, capacity; }. */
#define CD_ARRAY(T)                                                                                          \
	struct                                                                                                   \
	{                                                                                                        \
		T* data;                                                                                             \
		int count;                                                                                           \
		int capacity;                                                                                        \
	}

#define cdArrayReserveFor(array, needed)                                                                     \
	cdArrayReserve((void**)&(array).data, &(array).capacity, (needed), sizeof(*(array).data))

/* Appends; evaluates to false when memory ran out. */
#define cdArrayPush(array, value)                                                                            \
	(cdArrayReserveFor(array, (array).count + 1) ? ((array).data[(array).count++] = (value), true) : false)

#define cdArrayFree(array)                                                                                   \
	do                                                                                                       \
	{                                                                                                        \
		cdFree((array).data);                                                                                \
		(array).data = NULL;                                                                                 \
		(array).count = 0;                                                                                   \
		(array).capacity = 0;                                                                                \
	} while (0)

/* ---- id pool (id_pool.c) -----------------------------------------------------------------------
 * Hands out slot indices, reusing freed ones last-in first-out. Generations live with the
 * objects (each object records the generation it was created with). */
typedef struct cdIdPool
{
	int* freeIds;
	int freeCount;
	int freeCapacity;
	int nextIndex; /* slots [0, nextIndex) have been handed out at least once */
} cdIdPool;

void cdIdPool_Destroy(cdIdPool* pool);
/* Returns a slot index, or -1 when memory runs out. */
int cdIdPool_Alloc(cdIdPool* pool);
void cdIdPool_Free(cdIdPool* pool, int id);
static inline int cdIdPool_GetCount(const cdIdPool* pool)
{
	return pool->nextIndex - pool->freeCount;
}

/* ---- pair set (pair_set.c) -------------------------------------------------------------------
 * Open-addressing hash set of 64-bit keys (two 32-bit ids). Keys only: a lookup, made for every
 * overlap the broadphase reports, touches one array. */
typedef struct cdPairSet
{
	uint64_t* keys; /* 0 = empty slot; stored keys are key + 1 */
	int capacity;	/* power of two */
	int count;
} cdPairSet;

static inline uint64_t cdPairKey(int a, int b)
{
	uint32_t lo = (uint32_t)(a < b ? a : b), hi = (uint32_t)(a < b ? b : a);
	return ((uint64_t)hi << 32) | lo;
}

/* The set's hash of a key. */
static inline uint32_t cdPairHash(uint64_t key)
{
	key ^= key >> 33;
	key *= 0xff51afd7ed558ccdull;
	key ^= key >> 33;
	return (uint32_t)key;
}

/* Where a lookup of key starts reading (NULL for an empty set): a caller that looks up many keys
 * can start loading their slots ahead (a prefetch) so the misses overlap. */
static inline const uint64_t* cdPairSet_HomeSlot(const cdPairSet* set, uint64_t key)
{
	return set->capacity > 0 ? set->keys + (cdPairHash(key) & ((uint32_t)set->capacity - 1u)) : NULL;
}

void cdPairSet_Destroy(cdPairSet* set);
void cdPairSet_Clear(cdPairSet* set);
/* Returns false when memory runs out. Adding an existing key changes nothing. */
bool cdPairSet_Add(cdPairSet* set, uint64_t key);
bool cdPairSet_Contains(const cdPairSet* set, uint64_t key);
bool cdPairSet_Remove(cdPairSet* set, uint64_t key);

/* ---- bit set ------------------------------------------------------------------------------------ */
typedef struct cdBitSet
{
	uint64_t* words;
	int wordCount;
} cdBitSet;

/* Grows to hold bitCount bits and clears every bit; false when memory runs out. */
static inline bool cdBitSet_ResizeAndClear(cdBitSet* set, int bitCount)
{
	int words = (bitCount + 63) / 64;
	int capacity = set->wordCount;
	if (!cdArrayReserve((void**)&set->words, &capacity, words, sizeof(uint64_t)))
	{
		return false;
	}
	set->wordCount = capacity;
	if (set->wordCount > 0)
	{
		memset(set->words, 0, (size_t)set->wordCount * sizeof(uint64_t));
	}
	return true;
}

static inline void cdBitSet_Set(cdBitSet* set, int bit)
{
	set->words[bit >> 6] |= (uint64_t)1 << (bit & 63);
}

static inline bool cdBitSet_Get(const cdBitSet* set, int bit)
{
	return ((bit >> 6) < set->wordCount) && ((set->words[bit >> 6] >> (bit & 63)) & 1u) != 0;
}

static inline void cdBitSet_Destroy(cdBitSet* set)
{
	cdFree(set->words);
	set->words = NULL;
	set->wordCount = 0;
}

/* ---- arena (arena.c) ---------------------------------------------------------------------------
 * A bump allocator for the scratch memory of one step: blocks are 32-byte aligned and live until
 * cdArena_Reset. It keeps its largest block between steps, so a steady state allocates nothing. */
typedef struct cdArena
{
	char* base;
	size_t capacity;
	size_t used;
	size_t peak;
	void** overflow; /* blocks that did not fit, freed on reset */
	int overflowCount;
	int overflowCapacity;
} cdArena;

/* Zeroed memory, or NULL when memory runs out (or size is 0). */
void* cdArena_Alloc(cdArena* arena, size_t size);
/* The same without zeroing the block: for large arrays the caller writes before reading. */
void* cdArena_AllocUncleared(cdArena* arena, size_t size);
/* Frees everything handed out; grows the main block to the peak use of the last round. */
void cdArena_Reset(cdArena* arena);
void cdArena_Destroy(cdArena* arena);

#endif
