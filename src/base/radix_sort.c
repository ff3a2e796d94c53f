/* collide: LSD radix sort of 64-bit keys (see radix_sort.h). */
#include "base/radix_sort.h"

#include <string.h>

enum
{
	CD_RADIX_BITS = 11,
	CD_RADIX_BUCKETS = 1 << CD_RADIX_BITS,
	CD_INSERTION_SORT_LIMIT = 48
};

uint64_t* cdRadixSortKeys(uint64_t* keys, uint64_t* scratch, int count)
{
	return cdRadixSortKeysFrom(keys, scratch, count, 0);
}

uint64_t* cdRadixSortKeysFrom(uint64_t* keys, uint64_t* scratch, int count, int lowestBit)
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
