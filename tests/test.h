/* collide's test runner: a few macros, header-only.
 *
 * Why our own and not cmocka: every test program must build unchanged in the float, double
 * and sanitizer builds without an extra package, and the property tests need to print the
 * seed and the failing values of the random case they drew (TEST_CHECKF), which cmocka's
 * assert macros cannot. A failed check does not stop the test, so one run shows every failure.
 *
 * Usage:
 *   static void TestSomething(void) { TEST_CHECK(1 + 1 == 2); }
 *   int main(void) { TEST_RUN(TestSomething); return TEST_SUMMARY(); }
 */
#ifndef COLLIDE_TEST_H
#define COLLIDE_TEST_H

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

static int g_testChecks = 0;
static int g_testFailures = 0;
static int g_testCasesPassed = 0;
static int g_testCasesFailed = 0;
static const char* g_testCurrent = "";

/* Stop printing after this many failures per program, so a systematic bug stays readable. */
#define TEST_MAX_PRINTED_FAILURES 50

#define TEST_CHECKF(condition, ...)                                                                          \
	do                                                                                                       \
	{                                                                                                        \
		++g_testChecks;                                                                                      \
		if (!(condition))                                                                                    \
		{                                                                                                    \
			if (++g_testFailures <= TEST_MAX_PRINTED_FAILURES)                                               \
			{                                                                                                \
				fprintf(stderr, "%s:%d: %s: check failed: %s: ", __FILE__, __LINE__, g_testCurrent,          \
						#condition);                                                                         \
				fprintf(stderr, __VA_ARGS__);                                                                \
				fprintf(stderr, "\n");                                                                       \
			}                                                                                                \
		}                                                                                                    \
	} while (0)

#define TEST_CHECK(condition) TEST_CHECKF(condition, "%s", "")

/* |a - b| <= tolerance, both finite. */
#define TEST_CHECK_NEAR(a, b, tolerance)                                                                     \
	do                                                                                                       \
	{                                                                                                        \
		double testA_ = (double)(a), testB_ = (double)(b), testTol_ = (double)(tolerance);                   \
		TEST_CHECKF(isfinite(testA_) && isfinite(testB_) && fabs(testA_ - testB_) <= testTol_,               \
					"%s = %.9g, %s = %.9g, tolerance %.3g", #a, testA_, #b, testB_, testTol_);               \
	} while (0)

#define TEST_RUN(function)                                                                                   \
	do                                                                                                       \
	{                                                                                                        \
		int failuresBefore_ = g_testFailures;                                                                \
		g_testCurrent = #function;                                                                           \
		function();                                                                                          \
		if (g_testFailures == failuresBefore_)                                                               \
		{                                                                                                    \
			++g_testCasesPassed;                                                                             \
		}                                                                                                    \
		else                                                                                                 \
		{                                                                                                    \
			++g_testCasesFailed;                                                                             \
			fprintf(stderr, "FAILED %s (%d failed checks)\n", #function, g_testFailures - failuresBefore_);  \
		}                                                                                                    \
	} while (0)

/* Prints "<checks> checks; N passed, N failed" (test cases) and returns the exit code. */
static inline int TEST_SUMMARY(void)
{
	printf("%d checks\n%d passed, %d failed\n", g_testChecks, g_testCasesPassed, g_testCasesFailed);
	return g_testCasesFailed == 0 && g_testCasesPassed > 0 ? 0 : 1;
}

/* ---- deterministic random numbers (splitmix64), the same on every platform -------------------- */
typedef struct TestRng
{
	uint64_t state;
} TestRng;

/* Seed from CD_TEST_SEED in the environment when set, else from `fallback`; printed so that a
 * failing property test can be replayed. */
static inline TestRng TestRngMake(uint64_t fallback)
{
	TestRng rng;
	const char* text = getenv("CD_TEST_SEED");
	rng.state = text != NULL ? (uint64_t)strtoull(text, NULL, 0) : fallback;
	return rng;
}

static inline uint64_t TestRngNext(TestRng* rng)
{
	uint64_t z = (rng->state += 0x9E3779B97F4A7C15ull);
	z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
	z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
	return z ^ (z >> 31);
}

/* Uniform double in [lower, upper). */
static inline double TestRngRange(TestRng* rng, double lower, double upper)
{
	double unit = (double)(TestRngNext(rng) >> 11) * (1.0 / 9007199254740992.0);
	return lower + (upper - lower) * unit;
}

/* Uniform int in [0, count). */
static inline int TestRngInt(TestRng* rng, int count)
{
	return (int)(TestRngNext(rng) % (uint64_t)count);
}

/* ---- an allocator that runs out, for out-of-memory tests ---------------------------------------- */
/* Install with cdSetAllocator(TestBudgetAlloc, TestBudgetFree) after TestBudgetReset(n): the
 * first n allocations succeed, every later one fails (counted in `failed`); `live` counts the
 * blocks not yet freed, so a leak shows as live != 0 once everything is destroyed. */
typedef struct TestBudget
{
	long left;
	int failed;
	int live;
} TestBudget;
static TestBudget g_testBudget;

static inline void TestBudgetReset(long allocations)
{
	g_testBudget.left = allocations;
	g_testBudget.failed = 0;
	g_testBudget.live = 0;
}

static inline void* TestBudgetAlloc(size_t size, size_t alignment)
{
	(void)alignment; /* collide asks for 32 at most */
	if (g_testBudget.left <= 0)
	{
		++g_testBudget.failed;
		return NULL;
	}
	--g_testBudget.left;
	++g_testBudget.live;
	return aligned_alloc(32, (size + 31u) & ~(size_t)31u);
}

static inline void TestBudgetFree(void* memory)
{
	if (memory != NULL)
	{
		--g_testBudget.live;
	}
	free(memory);
}

#endif
