/* The shared radix sort of src/base (internal module, linked from the static library): sorted
 * output, a permutation of the input, both buffers, the insertion-sort size, and sorting from a
 * lowest bit keeping the order of keys equal there. */
#include "test.h"

#include "../src/base/radix_sort.h"

#include <stdlib.h>
#include <string.h>

#define MAX_KEYS 5000

static uint64_t g_keys[MAX_KEYS], g_scratch[MAX_KEYS], g_copy[MAX_KEYS];

static int CompareKeys(const void* a, const void* b)
{
	uint64_t x = *(const uint64_t*)a, y = *(const uint64_t*)b;
	return (x > y) - (x < y);
}

/* Sorts count random keys masked to `mask` and compares with qsort. */
static void CheckAgainstQsort(TestRng* rng, int count, uint64_t mask)
{
	for (int i = 0; i < count; ++i)
	{
		g_keys[i] = TestRngNext(rng) & mask;
		g_copy[i] = g_keys[i];
	}
	uint64_t* sorted = cdRadixSortKeys(g_keys, g_scratch, count);
	TEST_CHECK(sorted == g_keys || sorted == g_scratch);
	qsort(g_copy, (size_t)count, sizeof(uint64_t), CompareKeys);
	TEST_CHECKF(count == 0 || memcmp(sorted, g_copy, (size_t)count * sizeof(uint64_t)) == 0,
				"count %d mask %llx", count, (unsigned long long)mask);
}

static void TestSortsLikeQsort(void)
{
	TestRng rng = TestRngMake(11);
	const int counts[] = {0, 1, 2, 47, 48, 49, 1000, MAX_KEYS};
	const uint64_t masks[] = {0, 1, 0xFF, 0xFFFFF, 0xFFFFFFFFull, ~0ull, 0xFF00000000ull};
	for (size_t c = 0; c < sizeof(counts) / sizeof(counts[0]); ++c)
	{
		for (size_t m = 0; m < sizeof(masks) / sizeof(masks[0]); ++m)
		{
			CheckAgainstQsort(&rng, counts[c], masks[m]);
		}
	}
}

/* Keys (high = value, low 32 bits = original index) sorted from bit 32: the values ascend and
 * equal values keep the ascending index order they came in. */
static void TestFromBitIsStable(void)
{
	TestRng rng = TestRngMake(12);
	const int count = 3000;
	for (int i = 0; i < count; ++i)
	{
		uint64_t value = (uint64_t)TestRngInt(&rng, 40);
		g_keys[i] = (value << 32) | (uint64_t)i;
	}
	uint64_t* sorted = cdRadixSortKeysFrom(g_keys, g_scratch, count, 32);
	int ordered = 1;
	for (int i = 1; i < count; ++i)
	{
		uint64_t a = sorted[i - 1], b = sorted[i];
		if ((a >> 32) > (b >> 32) || ((a >> 32) == (b >> 32) && (a & 0xFFFFFFFFu) >= (b & 0xFFFFFFFFu)))
		{
			ordered = 0;
		}
	}
	TEST_CHECK(ordered);
	/* Every index appears once. */
	memset(g_copy, 0, sizeof(g_copy));
	for (int i = 0; i < count; ++i)
	{
		g_copy[sorted[i] & 0xFFFFFFFFu] += 1;
	}
	int once = 1;
	for (int i = 0; i < count; ++i)
	{
		once = once && g_copy[i] == 1;
	}
	TEST_CHECK(once);
}

int main(void)
{
	TEST_RUN(TestSortsLikeQsort);
	TEST_RUN(TestFromBitIsStable);
	return TEST_SUMMARY();
}
