/* Tests of the base layer: result strings, version, allocator and assert hooks, units. */
#include "collide/base.h"
#include "test.h"

#include <string.h>

static void TestResultStrings(void)
{
	for (int code = 0; code <= (int)CD_RESULT_COUNT; ++code)
	{
		const char* text = cdGetResultString((cdResult)code);
		TEST_CHECK(text != NULL && strlen(text) > 0);
	}
	TEST_CHECK(strcmp(cdGetResultString(CD_OK), "ok") == 0);
	TEST_CHECK(strcmp(cdGetResultString((cdResult)1000), "unknown result code") == 0);
}

static void TestVersionAndReal(void)
{
	cdVersion version = cdGetVersion();
	TEST_CHECK(version.major == CD_VERSION_MAJOR && version.minor == CD_VERSION_MINOR &&
			   version.patch == CD_VERSION_PATCH);
	TEST_CHECK(cdGetRealIsDouble() == CD_DOUBLE);
	TEST_CHECK(sizeof(cdReal) == (CD_DOUBLE ? sizeof(double) : sizeof(float)));
}

static int g_allocCount = 0;
static int g_freeCount = 0;

static void* CountingAlloc(size_t size, size_t alignment)
{
	++g_allocCount;
	(void)alignment;
	return aligned_alloc(64, (size + 63) & ~(size_t)63);
}

static void CountingFree(void* memory)
{
	++g_freeCount;
	free(memory);
}

static void TestAllocator(void)
{
	void* block = cdAlloc(100);
	TEST_CHECK(block != NULL && ((uintptr_t)block % 32) == 0);
	memset(block, 0xAB, 100);
	cdFree(block);
	TEST_CHECK(cdAlloc(0) == NULL);
	cdFree(NULL);

	cdSetAllocator(CountingAlloc, CountingFree);
	block = cdAlloc(10);
	TEST_CHECK(block != NULL);
	cdFree(block);
	TEST_CHECK(g_allocCount == 1 && g_freeCount == 1);
	cdSetAllocator(NULL, NULL);
	block = cdAlloc(10);
	cdFree(block);
	TEST_CHECK(g_allocCount == 1 && g_freeCount == 1);
}

static int g_assertCount = 0;

static bool CountingAssert(const char* condition, const char* fileName, int lineNumber)
{
	(void)condition;
	(void)fileName;
	(void)lineNumber;
	++g_assertCount;
	return false;
}

static void TestAssertHookAndUnits(void)
{
	cdSetAssertFcn(CountingAssert);
	TEST_CHECK(cdGetLengthUnitsPerMeter() == CD_R(1.0));
	TEST_CHECK(CD_LINEAR_SLOP == CD_R(0.005));
	cdSetLengthUnitsPerMeter(CD_R(32.0));
	TEST_CHECK(cdGetLengthUnitsPerMeter() == CD_R(32.0));
	TEST_CHECK(CD_LINEAR_SLOP == CD_R(0.005) * CD_R(32.0));
	/* Bad units are refused (and reported through the assert hook in debug builds). */
	cdSetLengthUnitsPerMeter(CD_R(-1.0));
	cdSetLengthUnitsPerMeter((cdReal)NAN);
	TEST_CHECK(cdGetLengthUnitsPerMeter() == CD_R(32.0));
#ifndef NDEBUG
	TEST_CHECK(g_assertCount == 2);
#endif
	cdSetLengthUnitsPerMeter(CD_R(1.0));
	cdSetAssertFcn(NULL);
}

int main(void)
{
	TEST_RUN(TestResultStrings);
	TEST_RUN(TestVersionAndReal);
	TEST_RUN(TestAllocator);
	TEST_RUN(TestAssertHookAndUnits);
	return TEST_SUMMARY();
}
