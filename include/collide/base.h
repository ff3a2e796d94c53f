/* collide: base layer. The real type, result codes, version, assert and allocator hooks, and the
 * tolerances every other layer shares. Depends on libc only. */
#ifndef COLLIDE_BASE_H
#define COLLIDE_BASE_H

#include <float.h>
#include <math.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include "collide/config.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Export macro: CD_API marks the public functions of the shared library. */
#if defined(_WIN32) && defined(COLLIDE_SHARED)
#if defined(COLLIDE_BUILDING)
#define CD_API __declspec(dllexport)
#else
#define CD_API __declspec(dllimport)
#endif
#elif defined(COLLIDE_BUILDING) && defined(__GNUC__)
#define CD_API __attribute__((visibility("default")))
#else
#define CD_API
#endif

/* ------------------------------------------------------------------------------------------ */
/* The real type. float by default; the CMake option COLLIDE_DOUBLE makes it double everywhere. */
#if CD_DOUBLE
typedef double cdReal;
#define CD_REAL_MAX DBL_MAX
#define CD_REAL_EPSILON DBL_EPSILON
#define CD_R(x) (x)
#else
typedef float cdReal;
#define CD_REAL_MAX FLT_MAX
#define CD_REAL_EPSILON FLT_EPSILON
#define CD_R(x) (x##f)
#endif

#define CD_PI CD_R(3.14159265358979323846)

/* Result codes of builders, validators and loaders. Enum constants are CD_UPPER_SNAKE
 * (see CONTRIBUTING.md). Zero is success so that `if (result) { error }` reads naturally. */
typedef enum cdResult
{
	CD_OK = 0,
	CD_ERROR_INVALID_ARGUMENT, /* null pointer, negative count, bad flag */
	CD_ERROR_NOT_FINITE,	   /* NaN or infinity in the input */
	CD_ERROR_NEGATIVE_SIZE,	   /* negative radius, half extent or other size */
	CD_ERROR_DEGENERATE,	   /* too few distinct points, collinear or coplanar set, zero area */
	CD_ERROR_TOO_MANY_POINTS,  /* more points than the documented limit */
	CD_ERROR_NOT_NORMALIZED,   /* a quaternion, rotation or plane normal that is not unit length */
	CD_ERROR_OUT_OF_MEMORY,
	CD_ERROR_PARSE,		   /* malformed input file */
	CD_ERROR_OUT_OF_RANGE, /* a finite coordinate beyond a builder's documented limit */
	CD_RESULT_COUNT
} cdResult;

/* A short English description of a result code ("ok", "NaN or infinite input", ...). */
CD_API const char* cdGetResultString(cdResult result);

/* ------------------------------------------------------------------------------------------ */
/* Version of the library that was linked (the header's is CD_VERSION_MAJOR/MINOR/PATCH). */
typedef struct cdVersion
{
	int major, minor, patch;
} cdVersion;

CD_API cdVersion cdGetVersion(void);

/* 1 when the compiled library uses double, 0 for float: lets a program check that it was
 * compiled with the same config.h as the library it links against. */
CD_API int cdGetRealIsDouble(void);

/* ------------------------------------------------------------------------------------------ */
/* Assertions. CD_ASSERT checks arguments and invariants in debug builds (and whenever
 * CD_ENABLE_ASSERT is defined). The handler receives the failed condition and its location; it
 * returns true to break into the debugger/abort and false to continue. */
typedef bool cdAssertFcn(const char* condition, const char* fileName, int lineNumber);

/* Replace the assert handler; NULL restores the default (print to stderr and abort). */
CD_API void cdSetAssertFcn(cdAssertFcn* assertFcn);

/* Calls the current handler; used by CD_ASSERT, returns its answer. */
CD_API bool cdInternalAssert(const char* condition, const char* fileName, int lineNumber);

#if !defined(NDEBUG) || defined(CD_ENABLE_ASSERT)
#define CD_ASSERT(condition)                                                                                 \
	do                                                                                                       \
	{                                                                                                        \
		if (!(condition) && cdInternalAssert(#condition, __FILE__, (int)__LINE__))                           \
		{                                                                                                    \
			abort();                                                                                         \
		}                                                                                                    \
	} while (0)
#else
#define CD_ASSERT(condition) ((void)0)
#endif

/* ------------------------------------------------------------------------------------------ */
/* Allocator hooks. Queries never allocate; growing structures (hulls, meshes, trees, worlds)
 * allocate through these. The allocation function must return memory aligned to at least
 * `alignment` (a power of two, at most 64) or NULL. */
typedef void* cdAllocFcn(size_t size, size_t alignment);
typedef void cdFreeFcn(void* memory);

/* Replace the allocator; passing NULL for both restores the default (aligned malloc). */
CD_API void cdSetAllocator(cdAllocFcn* allocFcn, cdFreeFcn* freeFcn);

/* Allocate through the current hooks, 32-byte aligned. Returns NULL for size 0 or failure. */
CD_API void* cdAlloc(size_t size);
CD_API void cdFree(void* memory);

/* ------------------------------------------------------------------------------------------ */
/* How an iterative query ended. Every iterative algorithm has a cap; when it is reached the query
 * returns the best answer found so far and says so here. */
typedef struct cdDistanceStatus
{
	int iterations;		  /* GJK iterations used (0 when no iteration was needed, e.g. half-spaces) */
	bool hitIterationCap; /* true when GJK stopped at its cap before converging */
} cdDistanceStatus;

/* ------------------------------------------------------------------------------------------ */
/* Length units and tolerances. Everything is in metres by default. A game that works in pixels
 * calls cdSetLengthUnitsPerMeter(e.g. 32) once before creating anything, and every length
 * tolerance below scales with it. */
CD_API void cdSetLengthUnitsPerMeter(cdReal lengthUnits);
CD_API cdReal cdGetLengthUnitsPerMeter(void);

/* Linear slop: contacts closer than this are considered resting (0.005 m). */
#define CD_LINEAR_SLOP (CD_R(0.005) * cdGetLengthUnitsPerMeter())

/* Speculative distance: contact points this far apart are still reported (4 slops). */
#define CD_SPECULATIVE_DISTANCE (CD_R(4.0) * CD_LINEAR_SLOP)

/* ------------------------------------------------------------------------------------------ */
/* Scalar helpers on cdReal. */

static inline bool cdIsValidReal(cdReal a)
{
	return isfinite(a) != 0;
}

static inline cdReal cdSqrt(cdReal a)
{
#if CD_DOUBLE
	return sqrt(a);
#else
	return sqrtf(a);
#endif
}

/* atan2(y, x) in (-pi, pi]. The float build computes it itself (an odd polynomial on |t| <= tan(pi/8)
 * after folding the octants; within 3e-7 of the true angle, as atan2f) so that the 2D world's
 * joint angles are the same bits on every platform, wasm included, and cost a few multiplies
 * instead of a libm call. The double build calls atan2. */
static inline cdReal cdAtan2(cdReal y, cdReal x)
{
#if CD_DOUBLE
	return atan2(y, x);
#else
	float ax = fabsf(x), ay = fabsf(y);
	float big = ax > ay ? ax : ay, small = ax > ay ? ay : ax;
	if (!(big > 0.0f))
	{
		return big == 0.0f ? (signbit(x) ? (signbit(y) ? -3.14159265f : 3.14159265f) : y) : x + y;
	}
	/* t = tan(angle - base), |t| <= tan(pi/8). */
	float base = 0.0f, t;
	if (small >= 0.414213562f * big)
	{
		base = 0.785398163f;
		t = small == big ? 0.0f : (small - big) / (small + big); /* equal: also both infinite */
	}
	else
	{
		t = small / big;
	}
	float u = t * t;
	float r = base + t * (0.999999982f +
						  u * (-0.333327969f + u * (0.199744048f + u * (-0.138514789f + u * 0.0798496421f))));
	if (ay > ax)
	{
		r = 1.57079633f - r;
	}
	if (x < 0.0f)
	{
		r = 3.14159265f - r;
	}
	return signbit(y) ? -r : r;
#endif
}

static inline cdReal cdAbs(cdReal a)
{
	return a < CD_R(0.0) ? -a : a;
}

static inline cdReal cdMin(cdReal a, cdReal b)
{
	return a < b ? a : b;
}

static inline cdReal cdMax(cdReal a, cdReal b)
{
	return a > b ? a : b;
}

static inline cdReal cdClamp(cdReal a, cdReal lower, cdReal upper)
{
	return a < lower ? lower : (a > upper ? upper : a);
}

static inline cdReal cdSign(cdReal a)
{
	return a < CD_R(0.0) ? CD_R(-1.0) : CD_R(1.0);
}

static inline int cdMinInt(int a, int b)
{
	return a < b ? a : b;
}

static inline int cdMaxInt(int a, int b)
{
	return a > b ? a : b;
}

/* Former names (before the naming rule of CONTRIBUTING.md), kept as aliases for one release so
 * that code written against them still builds; tests/check_names.py accepts exactly these. */
#define cdResultString cdGetResultString

#ifdef __cplusplus
}
#endif

#endif
