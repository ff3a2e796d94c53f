/* collide: broadphase pieces shared by 2D and 3D: type names, array growth. The key sort is the
 * shared radix sort of src/base/radix_sort.c. */
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
