/* Shared pieces of the query fuzzers: a byte reader that decodes numbers (a small lattice scaled
 * by a per-input power of ten, raw float bit patterns, and special values: NaN, infinities, the
 * ends of the documented range), the clamp into the documented range, and the failure report.
 *
 * The documented range (docs/API.md): magnitudes up to 1e9 and down to 1e-9 (or exactly zero) in
 * float, 1e30 / 1e-30 in double. Raw values go to the validators unchanged; the queries get the
 * clamped copies. */
#ifndef COLLIDE_FUZZ_COMMON_H
#define COLLIDE_FUZZ_COMMON_H

#include "collide/collide.h"

#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#if CD_DOUBLE
#define FUZZ_MAX_MAGNITUDE 1e30
#define FUZZ_MIN_MAGNITUDE 1e-30
#else
#define FUZZ_MAX_MAGNITUDE 1e9
#define FUZZ_MIN_MAGNITUDE 1e-9
#endif

/* Tolerances of the checks, relative to the largest magnitude involved in a check. FUZZ_TOL is
 * for quantities computed twice (distance in both orders, |pointB - pointA| against the
 * distance, a witness point against the closest point on its shape); FUZZ_BAND keeps the
 * overlap-versus-distance comparison away from the boundary, where round-off decides either way.
 * Both are far above the library's own tolerances (8-64 epsilon): a violation is a real error,
 * not round-off. */
#if CD_DOUBLE
#define FUZZ_TOL 1e-10
#define FUZZ_BAND 1e-9
#else
#define FUZZ_TOL 1e-4
#define FUZZ_BAND 1e-3
#endif

/* A length whose square is below the smallest normal cdReal: |v| computed from squares reads 0. */
#if CD_DOUBLE
#define FUZZ_UNDERFLOW_GAP 1.5e-154
#else
#define FUZZ_UNDERFLOW_GAP 1.1e-19
#endif

/* A ray normal must be unit length within this (or exactly zero). */
#define FUZZ_UNIT_TOL (64.0 * (double)CD_REAL_EPSILON)

typedef struct FuzzReader
{
	const uint8_t* data;
	size_t size, at;
	double latticeScale; /* lattice values are multiples of 0.125 times this power of ten */
} FuzzReader;

static inline uint8_t FuzzByte(FuzzReader* r)
{
	return r->at < r->size ? r->data[r->at++] : 0;
}

/* The first byte chooses the lattice scale 10^k, k in [-8, 9]. */
static inline FuzzReader FuzzBegin(const uint8_t* data, size_t size)
{
	FuzzReader r = {data, size, 0, 1.0};
	int exponent = (int)(FuzzByte(&r) % 18) - 8;
	double scale = 1.0;
	for (int i = 0; i < (exponent < 0 ? -exponent : exponent); ++i)
	{
		scale = exponent < 0 ? scale / 10.0 : scale * 10.0;
	}
	r.latticeScale = scale;
	return r;
}

/* One raw number: often a lattice value (so that shapes touch, coincide and nest), sometimes a
 * raw float bit pattern or a special value. May be NaN, infinite or out of range. */
static inline cdReal FuzzRawReal(FuzzReader* r)
{
	uint8_t b = FuzzByte(r);
	if (b < 200)
	{
		return (cdReal)((double)((int)b - 100) * 0.125 * r->latticeScale);
	}
	if (b < 232)
	{
		uint32_t bits = 0;
		for (int i = 0; i < 4; ++i)
		{
			bits = (bits << 8) | FuzzByte(r);
		}
		float value;
		memcpy(&value, &bits, sizeof value);
		return (cdReal)value;
	}
	switch (b)
	{
		case 232:
			return (cdReal)NAN;
		case 233:
			return (cdReal)INFINITY;
		case 234:
			return (cdReal)-INFINITY;
		case 235:
			return (cdReal)FUZZ_MAX_MAGNITUDE;
		case 236:
			return (cdReal)-FUZZ_MAX_MAGNITUDE;
		case 237:
			return (cdReal)FUZZ_MIN_MAGNITUDE;
		case 238:
			return (cdReal)-FUZZ_MIN_MAGNITUDE;
		case 239:
			return CD_REAL_MAX;
		case 240:
			return (cdReal)1e-40f; /* a float subnormal */
		case 241:
			return CD_R(-0.0);
		case 242:
			return CD_R(1.0);
		case 243:
			return CD_R(-1.0);
		case 244:
			return CD_R(0.5);
		case 245:
			return (cdReal)(1.0 + (double)CD_REAL_EPSILON);
		case 246:
			return (cdReal)(1.0 - (double)CD_REAL_EPSILON);
		case 247:
			return (cdReal)(0.5 * FUZZ_MAX_MAGNITUDE);
		default:
			return CD_R(0.0);
	}
}

/* Into the documented range: NaN becomes 0, larger magnitudes the largest, smaller non-zero
 * magnitudes the smallest (keeping the sign). */
static inline cdReal FuzzClampReal(cdReal x)
{
	if (isnan(x))
	{
		return CD_R(0.0);
	}
	double a = fabs((double)x);
	if (a > FUZZ_MAX_MAGNITUDE)
	{
		return (cdReal)(x < CD_R(0.0) ? -FUZZ_MAX_MAGNITUDE : FUZZ_MAX_MAGNITUDE);
	}
	if (a > 0.0 && a < FUZZ_MIN_MAGNITUDE)
	{
		return (cdReal)(x < CD_R(0.0) ? -FUZZ_MIN_MAGNITUDE : FUZZ_MIN_MAGNITUDE);
	}
	return x;
}

static inline cdReal FuzzClampSize(cdReal x)
{
	return cdAbs(FuzzClampReal(x));
}

static inline bool FuzzFinite(cdReal x)
{
	return isfinite(x) != 0;
}

static inline double FuzzMaxAbs(double a, cdReal b)
{
	double c = fabs((double)b);
	return c > a ? c : a;
}

/* Prints the case and aborts, so that libFuzzer saves the input. */
static inline void FuzzFail(const char* format, ...)
{
	va_list args;
	va_start(args, format);
	fprintf(stderr, "fuzz check failed: ");
	vfprintf(stderr, format, args);
	fprintf(stderr, "\n");
	va_end(args);
	fflush(stderr);
	abort();
}

/* true when the environment variable FUZZ_SKIP names this check (a comma-separated list). For
 * exploring past a known, reported failure by hand; the CTest runs never set it. */
static inline bool FuzzSkipped(const char* check)
{
	const char* list = getenv("FUZZ_SKIP");
	size_t length = strlen(check);
	for (const char* at = list; at != NULL && *at != 0;)
	{
		const char* end = strchr(at, ',');
		size_t n = end != NULL ? (size_t)(end - at) : strlen(at);
		if (n == length && strncmp(at, check, n) == 0)
		{
			return true;
		}
		at = end != NULL ? end + 1 : NULL;
	}
	return false;
}

/* Prints `count` reals with every digit needed to reproduce them (9 for a float, 17 for a
 * double). */
static inline void FuzzPrintReals(const char* label, const char* typeName, const cdReal* values, int count)
{
	fprintf(stderr, "  %s %s:", label, typeName);
	for (int i = 0; i < count; ++i)
	{
		fprintf(stderr, " %.*g", CD_DOUBLE ? 17 : 9, (double)values[i]);
	}
	fprintf(stderr, "\n");
}

#endif
