/* Tests of the base layer: result strings, version, allocator and assert hooks, units. */
#include "collide/base.h"
#include "test.h"

#include <math.h>
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

/* cdAtan2 against the double atan2 on angles all around the circle and radii from 1e-30 to 1e30
 * (every octant and both folds), within the documented 3e-7 rad; exact quadrant angles and the
 * signed zeros as atan2 gives them. */
static void TestAtan2(void)
{
	TestRng rng = TestRngMake(7);
	double worst = 0.0;
	for (int i = 0; i < 200000; ++i)
	{
		double angle = TestRngRange(&rng, -3.14159265358979, 3.14159265358979);
		double radius = pow(10.0, TestRngRange(&rng, -30.0, 30.0));
		cdReal y = (cdReal)(radius * sin(angle)), x = (cdReal)(radius * cos(angle));
		double error = fabs((double)cdAtan2(y, x) - atan2((double)y, (double)x));
		error = error > 3.14159 ? fabs(error - 6.283185307179586) : error; /* +-pi */
		worst = error > worst ? error : worst;
	}
	TEST_CHECKF(worst < 3e-7, "cdAtan2 off by %g rad", worst);
	TEST_CHECK(cdAtan2(CD_R(0.0), CD_R(1.0)) == CD_R(0.0) && !signbit(cdAtan2(CD_R(0.0), CD_R(1.0))));
	TEST_CHECK(signbit(cdAtan2(-CD_R(0.0), CD_R(1.0))));
	TEST_CHECK_NEAR(cdAtan2(CD_R(1.0), CD_R(0.0)), 1.5707963267948966, 2e-7);
	TEST_CHECK_NEAR(cdAtan2(CD_R(0.0), -CD_R(1.0)), 3.141592653589793, 3e-7);
	TEST_CHECK_NEAR(cdAtan2(-CD_R(0.0), -CD_R(1.0)), -3.141592653589793, 3e-7);
	TEST_CHECK_NEAR(cdAtan2(-CD_R(1.0), -CD_R(1.0)), -2.356194490192345, 3e-7);
	TEST_CHECK(cdAtan2(CD_R(0.0), CD_R(0.0)) == CD_R(0.0));
	TEST_CHECK(isnan(cdAtan2(NAN, CD_R(1.0))) && isnan(cdAtan2(CD_R(1.0), NAN)));
	TEST_CHECK_NEAR(cdAtan2(INFINITY, INFINITY), 0.7853981633974483, 1e-7);
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
	TEST_RUN(TestAtan2);
	return TEST_SUMMARY();
}
