/* The lanes of the wide contact solver (src/dynamics/wide2.h): every helper, in whichever version
 * this build compiles (AVX2, SSE2, NEON, WebAssembly SIMD128 or the scalar lanes, CD_W wide), gives
 * in each lane the bits of the one scalar operation it stands for, written out here in plain C:
 * on random values and on the ones where instruction sets differ (signed zeros for min and max,
 * NaN, infinities, subnormals). This is what lets the solver give the same bits at every width and
 * on every machine; the golden hash of test_world2_determinism checks the whole solver. */
#include "test.h"

#include <collide/collide.h>

#include "../src/dynamics/wide2.h"

#include <float.h>
#include <string.h>

#define VALUE_COUNT 4096

static const char* WideName(void)
{
#if CD_WIDE_AVX2
	return "AVX2";
#elif CD_WIDE_NEON
	return "NEON";
#elif CD_WIDE_SSE
	return "SSE2";
#elif defined(CD_WIDE_WASM)
	return "WebAssembly SIMD128";
#else
	return "scalar";
#endif
}

static bool SameBits(cdReal a, cdReal b)
{
	if (a != a && b != b)
	{
		return true; /* any NaN: NaN payloads are not part of the contract */
	}
	return memcmp(&a, &b, sizeof(a)) == 0;
}

/* A value drawn from the special ones or from a wide random range. */
static cdReal DrawValue(TestRng* rng)
{
	static const double special[] = {0.0,	 -0.0, 1.0,	  -1.0, 0.5,   2.0,		 1e-40,		-1e-40,
									 1e-300, 3e38, -3e38, 1e30, -1e30, INFINITY, -INFINITY, NAN};
	int kind = TestRngInt(rng, 4);
	if (kind == 0)
	{
		return (cdReal)special[TestRngInt(rng, (int)(sizeof(special) / sizeof(special[0])))];
	}
	if (kind == 1)
	{
		return (cdReal)TestRngRange(rng, -2.0, 2.0);
	}
	static const double scales[] = {1e-30, 1e-20, 1e-10, 1e-3, 1.0, 1e3, 1e10, 1e20, 1e30};
	double magnitude =
		TestRngRange(rng, 1.0, 10.0) * scales[TestRngInt(rng, (int)(sizeof(scales) / sizeof(scales[0])))];
	return (cdReal)(TestRngInt(rng, 2) == 0 ? magnitude : -magnitude);
}

static cdReal g_a[VALUE_COUNT], g_b[VALUE_COUNT], g_c[VALUE_COUNT];

static void FillValues(uint64_t seed)
{
	TestRng rng = TestRngMake(seed);
	for (int i = 0; i < VALUE_COUNT; ++i)
	{
		g_a[i] = DrawValue(&rng);
		/* Often equal or of opposite sign, so that ties and signed zeros meet. */
		int relation = TestRngInt(&rng, 6);
		g_b[i] = relation == 0 ? g_a[i] : (relation == 1 ? -g_a[i] : DrawValue(&rng));
		g_c[i] = DrawValue(&rng);
	}
}

/* A mask as CD_R(1.0) / CD_R(0.0) lanes, read through cdWSelect (the versions store masks
 * differently). */
static cdW MaskToReal(cdW mask)
{
	return cdWSelect(mask, cdWSplat(CD_R(1.0)), cdWZero());
}

typedef enum Op
{
	OP_ADD,
	OP_SUB,
	OP_MUL,
	OP_DIV,
	OP_NEG,
	OP_MAX,
	OP_MIN,
	OP_CLAMP,
	OP_SELECT,
	OP_GREATER,
	OP_LESS,
	OP_EQUAL,
	OP_NOT_EQUAL,
	OP_OR,
	OP_AND,
	OP_AND_NOT,
	OP_COUNT
} Op;

static const char* const g_opNames[OP_COUNT] = {"add",		"sub",	 "mul",	   "div",	  "neg",  "max",
												"min",		"clamp", "select", "greater", "less", "equal",
												"notEqual", "or",	 "and",	   "andNot"};

static cdW WideOp(Op op, cdW a, cdW b, cdW c)
{
	switch (op)
	{
		case OP_ADD:
			return cdWAdd(a, b);
		case OP_SUB:
			return cdWSub(a, b);
		case OP_MUL:
			return cdWMul(a, b);
		case OP_DIV:
			return cdWDiv(a, b);
		case OP_NEG:
			return cdWNeg(a);
		case OP_MAX:
			return cdWMax(a, b);
		case OP_MIN:
			return cdWMin(a, b);
		case OP_CLAMP:
			return cdWClamp(a, b, c);
		case OP_SELECT:
			return cdWSelect(cdWGreater(c, cdWZero()), a, b);
		case OP_GREATER:
			return MaskToReal(cdWGreater(a, b));
		case OP_LESS:
			return MaskToReal(cdWLess(a, b));
		case OP_EQUAL:
			return MaskToReal(cdWEqual(a, b));
		case OP_NOT_EQUAL:
			return MaskToReal(cdWNotEqual(a, b));
		case OP_OR:
			return MaskToReal(cdWOr(cdWGreater(a, b), cdWLess(c, cdWZero())));
		case OP_AND:
			return MaskToReal(cdWAnd(cdWGreater(a, b), cdWLess(c, cdWZero())));
		case OP_AND_NOT:
			return MaskToReal(cdWAndNot(cdWGreater(a, b), cdWLess(c, cdWZero())));
		default:
			return cdWZero();
	}
}

static cdReal Truth(bool value)
{
	return value ? CD_R(1.0) : CD_R(0.0);
}

/* The one scalar operation each helper stands for. */
static cdReal ScalarOp(Op op, cdReal a, cdReal b, cdReal c)
{
	switch (op)
	{
		case OP_ADD:
			return a + b;
		case OP_SUB:
			return a - b;
		case OP_MUL:
			return a * b;
		case OP_DIV:
			return a / b;
		case OP_NEG:
			return -a;
		case OP_MAX:
			return a > b ? a : b;
		case OP_MIN:
			return a < b ? a : b;
		case OP_CLAMP:
			return a < b ? b : (a > c ? c : a);
		case OP_SELECT:
			return c > CD_R(0.0) ? a : b;
		case OP_GREATER:
			return Truth(a > b);
		case OP_LESS:
			return Truth(a < b);
		case OP_EQUAL:
			return Truth(a == b);
		case OP_NOT_EQUAL:
			return Truth(a != b);
		case OP_OR:
			return Truth(a > b || c < CD_R(0.0));
		case OP_AND:
			return Truth(a > b && c < CD_R(0.0));
		case OP_AND_NOT:
			return Truth(!(a > b) && c < CD_R(0.0));
		default:
			return CD_R(0.0);
	}
}

static void TestEveryHelperMatchesTheScalarOperation(void)
{
	printf("wide lanes: %s, %d lanes\n", WideName(), CD_W);
	FillValues(0x3a11de5u);
	for (int op = 0; op < OP_COUNT; ++op)
	{
		int mismatches = 0;
		for (int start = 0; start + CD_W <= VALUE_COUNT; start += CD_W)
		{
			cdW a = cdWLoad(g_a + start), b = cdWLoad(g_b + start), c = cdWLoad(g_c + start);
			cdReal out[CD_W];
			cdWStore(out, WideOp((Op)op, a, b, c));
			for (int lane = 0; lane < CD_W; ++lane)
			{
				int i = start + lane;
				cdReal expected = ScalarOp((Op)op, g_a[i], g_b[i], g_c[i]);
				if (!SameBits(out[lane], expected))
				{
					if (++mismatches <= 5)
					{
						TEST_CHECKF(
							false,
							"%s lane %d: a %.9g b %.9g c %.9g: wide %.9g (sign %d), scalar %.9g (sign %d)",
							g_opNames[op], lane, (double)g_a[i], (double)g_b[i], (double)g_c[i],
							(double)out[lane], signbit(out[lane]) != 0, (double)expected,
							signbit(expected) != 0);
					}
				}
			}
		}
		TEST_CHECKF(mismatches == 0, "%s: %d lanes differ", g_opNames[op], mismatches);
	}
}

/* The signed zeros by name: cdMax(-0, +0) is +0 and cdMax(+0, -0) is -0 (the second operand on
 * a tie), and the same for cdMin; instructions with their own rules (NEON's fmax) would give +0. */
static void TestMinMaxKeepTheSecondOperandOnTies(void)
{
	cdW negZero = cdWSplat(-CD_R(0.0)), posZero = cdWZero();
	cdReal out[CD_W];
	cdWStore(out, cdWMax(negZero, posZero));
	TEST_CHECK(out[0] == CD_R(0.0) && !signbit(out[0]));
	cdWStore(out, cdWMax(posZero, negZero));
	TEST_CHECK(out[CD_W - 1] == CD_R(0.0) && signbit(out[CD_W - 1]));
	cdWStore(out, cdWMin(posZero, negZero));
	TEST_CHECK(signbit(out[0]));
	cdWStore(out, cdWMin(negZero, posZero));
	TEST_CHECK(!signbit(out[CD_W - 1]));
	/* A NaN first operand gives the second (the comparison is false), not NaN. */
	cdWStore(out, cdWMax(cdWSplat((cdReal)NAN), cdWSplat(CD_R(2.0))));
	TEST_CHECK(out[0] == CD_R(2.0));
	cdWStore(out, cdWMin(cdWSplat((cdReal)NAN), cdWSplat(CD_R(2.0))));
	TEST_CHECK(out[CD_W - 1] == CD_R(2.0));
}

/* Lanes are addressed in order: load, store, get, set and any agree on which lane is which. */
static void TestLanesAreInOrder(void)
{
	cdReal in[CD_W], out[CD_W];
	for (int i = 0; i < CD_W; ++i)
	{
		in[i] = (cdReal)(i + 1);
	}
	cdW w = cdWLoad(in);
	cdWStore(out, w);
	for (int i = 0; i < CD_W; ++i)
	{
		TEST_CHECK(out[i] == (cdReal)(i + 1));
		TEST_CHECK(cdWGetLane(&w, i) == (cdReal)(i + 1));
	}
	TEST_CHECK(!cdWAny(cdWGreater(cdWZero(), cdWZero())));
	for (int lane = 0; lane < CD_W; ++lane)
	{
		cdW v = cdWZero();
		cdWSetLane(&v, lane, CD_R(5.0));
		cdWStore(out, v);
		for (int i = 0; i < CD_W; ++i)
		{
			TEST_CHECK(out[i] == (i == lane ? CD_R(5.0) : CD_R(0.0)));
		}
		/* Only this lane's mask is true, and cdWAny sees it. */
		TEST_CHECKF(cdWAny(cdWGreater(v, cdWZero())), "lane %d", lane);
		TEST_CHECKF(!cdWAny(cdWLess(v, cdWZero())), "lane %d", lane);
	}
}

int main(void)
{
	TEST_RUN(TestEveryHelperMatchesTheScalarOperation);
	TEST_RUN(TestMinMaxKeepTheSecondOperandOnTies);
	TEST_RUN(TestLanesAreInOrder);
	return TEST_SUMMARY();
}
