/* collide: broadphase pieces shared by 2D and 3D: type names, array growth, key sorting. */
#if defined(__linux__) && !defined(_DEFAULT_SOURCE)
#define _DEFAULT_SOURCE /* madvise */
#endif
#include "broad/broad_internal.h"

#if defined(__linux__)
#include <sys/mman.h>
#endif

#ifdef CD_BROAD_COUNT_OPS
unsigned long long cdBroadOpCounts[CD_BROAD_OP_COUNT];
#endif

const char* cdGetBroadPhaseTypeName(cdBroadPhaseType type)
{
	switch (type)
	{
		case CD_BROADPHASE_TREE:
			return "tree";
		case CD_BROADPHASE_SAP:
			return "sap";
		case CD_BROADPHASE_GRID:
			return "grid";
		case CD_BROADPHASE_SPATIAL_TREE:
			return "quadtree/octree";
		case CD_BROADPHASE_TYPE_COUNT:
			break;
	}
	return "unknown";
}

void cdBroadAdviseLarge(void* memory, size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
	const uintptr_t huge = (uintptr_t)2 << 20;
	if (memory == NULL || bytes < 2 * huge)
	{
		return;
	}
	uintptr_t begin = ((uintptr_t)memory + huge - 1) & ~(huge - 1);
	uintptr_t end = ((uintptr_t)memory + bytes) & ~(huge - 1);
	if (end > begin)
	{
		/* Advice only: memory from a user allocator that cannot take it just stays as it is. */
		(void)madvise((void*)begin, (size_t)(end - begin), MADV_HUGEPAGE);
	}
#else
	(void)memory;
	(void)bytes;
#endif
}

bool cdBroadReserve(void** array, int* capacity, int needed, size_t elementSize)
{
	if (needed <= *capacity)
	{
		return true;
	}
	int grown = *capacity + *capacity / 2;
	int newCapacity = needed > grown ? needed : grown;
	if (newCapacity < 16)
	{
		newCapacity = 16;
	}
	void* memory = cdAlloc((size_t)newCapacity * elementSize);
	if (memory == NULL)
	{
		return false;
	}
	cdBroadAdviseLarge(memory, (size_t)newCapacity * elementSize);
	if (*array != NULL)
	{
		memcpy(memory, *array, (size_t)*capacity * elementSize);
		cdFree(*array);
	}
	*array = memory;
	*capacity = newCapacity;
	return true;
}

int cdBroadBitsFor(int count)
{
	int bits = 1;
	while (bits < 31 && (1 << bits) < count)
	{
		++bits;
	}
	return bits;
}

enum
{
	CD_RADIX_BITS = 11,
	CD_RADIX_BUCKETS = 1 << CD_RADIX_BITS,
	CD_INSERTION_SORT_LIMIT = 48
};

uint64_t* cdBroadSortKeys(uint64_t* keys, uint64_t* scratch, int count)
{
	return cdBroadSortKeysFrom(keys, scratch, count, 0);
}

uint64_t* cdBroadSortKeysFrom(uint64_t* keys, uint64_t* scratch, int count, int lowestBit)
{
	if (count < CD_INSERTION_SORT_LIMIT)
	{
		for (int i = 1; i < count; ++i)
		{
			uint64_t key = keys[i];
			int j = i - 1;
			while (j >= 0 && keys[j] > key)
			{
				keys[j + 1] = keys[j];
				--j;
			}
			keys[j + 1] = key;
		}
		return keys;
	}

	uint64_t used = 0;
	for (int i = 0; i < count; ++i)
	{
		used |= keys[i];
	}
	int bits = 0;
	while (bits < 64 && (used >> bits) != 0)
	{
		++bits;
	}

	uint32_t histogram[CD_RADIX_BUCKETS];
	uint64_t* from = keys;
	uint64_t* to = scratch;
	for (int shift = lowestBit; shift < bits; shift += CD_RADIX_BITS)
	{
		memset(histogram, 0, sizeof(histogram));
		for (int i = 0; i < count; ++i)
		{
			++histogram[(from[i] >> shift) & (CD_RADIX_BUCKETS - 1)];
		}
		/* A digit all keys share would only copy the array. */
		if (histogram[(from[0] >> shift) & (CD_RADIX_BUCKETS - 1)] == (uint32_t)count)
		{
			continue;
		}
		uint32_t offset = 0;
		for (int b = 0; b < CD_RADIX_BUCKETS; ++b)
		{
			uint32_t n = histogram[b];
			histogram[b] = offset;
			offset += n;
		}
		for (int i = 0; i < count; ++i)
		{
			uint64_t key = from[i];
			to[histogram[(key >> shift) & (CD_RADIX_BUCKETS - 1)]++] = key;
		}
		uint64_t* swap = from;
		from = to;
		to = swap;
	}
	return from;
}
