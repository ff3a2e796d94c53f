/* collide: the small SIMD helpers of the wide contact solver. A cdW holds CD_W reals, one per
 * contact lane. SSE2 (four floats) in the float build on x86-64; elsewhere (the double build, other
 * machines, or COLLIDE_NO_SIMD) a plain array of four reals with the same operations done lane by
 * lane. Every helper is one IEEE operation per lane or a select, and the build uses
 * -ffp-contract=off, so both versions produce the same bits for the same lanes. */
#ifndef COLLIDE_WIDE2_H
#define COLLIDE_WIDE2_H

#include "collide/math2.h"

#include <string.h>

#define CD_W 4

#if !CD_DOUBLE && defined(__SSE2__) && !defined(COLLIDE_NO_SIMD)
#include <emmintrin.h>
#define CD_WIDE_SSE 1
typedef __m128 cdW;

static inline cdW cdWZero(void)
{
	return _mm_setzero_ps();
}
static inline cdW cdWSplat(cdReal a)
{
	return _mm_set1_ps(a);
}
static inline cdW cdWAdd(cdW a, cdW b)
{
	return _mm_add_ps(a, b);
}
static inline cdW cdWSub(cdW a, cdW b)
{
	return _mm_sub_ps(a, b);
}
static inline cdW cdWMul(cdW a, cdW b)
{
	return _mm_mul_ps(a, b);
}
static inline cdW cdWDiv(cdW a, cdW b)
{
	return _mm_div_ps(a, b);
}
static inline cdW cdWNeg(cdW a)
{
	return _mm_xor_ps(a, _mm_set1_ps(-0.0f));
}
/* a > b ? a : b, lane by lane (cdMax). */
static inline cdW cdWMax(cdW a, cdW b)
{
	return _mm_max_ps(a, b);
}
/* a < b ? a : b, lane by lane (cdMin). */
static inline cdW cdWMin(cdW a, cdW b)
{
	return _mm_min_ps(a, b);
}
/* mask ? a : b, mask lanes all ones or all zeros. */
static inline cdW cdWSelect(cdW mask, cdW a, cdW b)
{
	return _mm_or_ps(_mm_and_ps(mask, a), _mm_andnot_ps(mask, b));
}
static inline cdW cdWGreater(cdW a, cdW b)
{
	return _mm_cmpgt_ps(a, b);
}
static inline cdW cdWLess(cdW a, cdW b)
{
	return _mm_cmplt_ps(a, b);
}
static inline cdW cdWEqual(cdW a, cdW b)
{
	return _mm_cmpeq_ps(a, b);
}
static inline cdW cdWNotEqual(cdW a, cdW b)
{
	return _mm_cmpneq_ps(a, b);
}
/* Lane by lane a or b, a and b, and (not a) and b, of masks. */
static inline cdW cdWOr(cdW a, cdW b)
{
	return _mm_or_ps(a, b);
}
static inline cdW cdWAnd(cdW a, cdW b)
{
	return _mm_and_ps(a, b);
}
static inline cdW cdWAndNot(cdW a, cdW b)
{
	return _mm_andnot_ps(a, b);
}
static inline void cdWStore(cdReal* out, cdW a)
{
	_mm_storeu_ps(out, a);
}
static inline cdW cdWLoad(const cdReal* in)
{
	return _mm_loadu_ps(in);
}
/* Whether any lane of a mask is true. */
static inline bool cdWAny(cdW mask)
{
	return _mm_movemask_ps(mask) != 0;
}
#elif !CD_DOUBLE && defined(__wasm_simd128__) && !defined(COLLIDE_NO_SIMD)
/* WebAssembly SIMD128 (clang -msimd128): the same four-float operations. pmin/pmax are the
 * "pseudo" min/max, b < a ? b : a and a < b ? b : a, so cdWMin(a, b) = pmin(b, a) is a < b ? a : b
 * and cdWMax(a, b) = pmax(b, a) is b < a ? a : b, i.e. a > b ? a : b: cdMin's and cdMax's rules. */
#include <wasm_simd128.h>
#define CD_WIDE_SSE 0
#define CD_WIDE_WASM 1
typedef v128_t cdW;

static inline cdW cdWZero(void)
{
	return wasm_f32x4_splat(0.0f);
}
static inline cdW cdWSplat(cdReal a)
{
	return wasm_f32x4_splat(a);
}
static inline cdW cdWAdd(cdW a, cdW b)
{
	return wasm_f32x4_add(a, b);
}
static inline cdW cdWSub(cdW a, cdW b)
{
	return wasm_f32x4_sub(a, b);
}
static inline cdW cdWMul(cdW a, cdW b)
{
	return wasm_f32x4_mul(a, b);
}
static inline cdW cdWDiv(cdW a, cdW b)
{
	return wasm_f32x4_div(a, b);
}
static inline cdW cdWNeg(cdW a)
{
	return wasm_f32x4_neg(a);
}
static inline cdW cdWMax(cdW a, cdW b)
{
	return wasm_f32x4_pmax(b, a);
}
static inline cdW cdWMin(cdW a, cdW b)
{
	return wasm_f32x4_pmin(b, a);
}
/* mask ? a : b, mask lanes all ones or all zeros. */
static inline cdW cdWSelect(cdW mask, cdW a, cdW b)
{
	return wasm_v128_bitselect(a, b, mask);
}
static inline cdW cdWGreater(cdW a, cdW b)
{
	return wasm_f32x4_gt(a, b);
}
static inline cdW cdWLess(cdW a, cdW b)
{
	return wasm_f32x4_lt(a, b);
}
static inline cdW cdWEqual(cdW a, cdW b)
{
	return wasm_f32x4_eq(a, b);
}
static inline cdW cdWNotEqual(cdW a, cdW b)
{
	return wasm_f32x4_ne(a, b);
}
static inline cdW cdWOr(cdW a, cdW b)
{
	return wasm_v128_or(a, b);
}
static inline cdW cdWAnd(cdW a, cdW b)
{
	return wasm_v128_and(a, b);
}
static inline cdW cdWAndNot(cdW a, cdW b)
{
	return wasm_v128_andnot(b, a);
}
static inline void cdWStore(cdReal* out, cdW a)
{
	wasm_v128_store(out, a);
}
static inline cdW cdWLoad(const cdReal* in)
{
	return wasm_v128_load(in);
}
static inline bool cdWAny(cdW mask)
{
	return wasm_v128_any_true(mask);
}
#else
#define CD_WIDE_SSE 0
typedef struct cdW
{
	cdReal v[CD_W];
} cdW;

#define CD_W_LANES(expr)                                                                                     \
	cdW r;                                                                                                   \
	for (int i = 0; i < CD_W; ++i)                                                                           \
	{                                                                                                        \
		r.v[i] = (expr);                                                                                     \
	}                                                                                                        \
	return r

static inline cdW cdWZero(void)
{
	CD_W_LANES(CD_R(0.0));
}
static inline cdW cdWSplat(cdReal a)
{
	CD_W_LANES(a);
}
static inline cdW cdWAdd(cdW a, cdW b)
{
	CD_W_LANES(a.v[i] + b.v[i]);
}
static inline cdW cdWSub(cdW a, cdW b)
{
	CD_W_LANES(a.v[i] - b.v[i]);
}
static inline cdW cdWMul(cdW a, cdW b)
{
	CD_W_LANES(a.v[i] * b.v[i]);
}
static inline cdW cdWDiv(cdW a, cdW b)
{
	CD_W_LANES(a.v[i] / b.v[i]);
}
static inline cdW cdWNeg(cdW a)
{
	CD_W_LANES(-a.v[i]);
}
static inline cdW cdWMax(cdW a, cdW b)
{
	CD_W_LANES(cdMax(a.v[i], b.v[i]));
}
static inline cdW cdWMin(cdW a, cdW b)
{
	CD_W_LANES(cdMin(a.v[i], b.v[i]));
}
/* Masks are CD_R(1.0) (true) or CD_R(0.0) (false) lanes in the scalar version. */
static inline cdW cdWSelect(cdW mask, cdW a, cdW b)
{
	CD_W_LANES(mask.v[i] != CD_R(0.0) ? a.v[i] : b.v[i]);
}
static inline cdW cdWGreater(cdW a, cdW b)
{
	CD_W_LANES(a.v[i] > b.v[i] ? CD_R(1.0) : CD_R(0.0));
}
static inline cdW cdWLess(cdW a, cdW b)
{
	CD_W_LANES(a.v[i] < b.v[i] ? CD_R(1.0) : CD_R(0.0));
}
static inline cdW cdWEqual(cdW a, cdW b)
{
	CD_W_LANES(a.v[i] == b.v[i] ? CD_R(1.0) : CD_R(0.0));
}
static inline cdW cdWNotEqual(cdW a, cdW b)
{
	CD_W_LANES(a.v[i] != b.v[i] ? CD_R(1.0) : CD_R(0.0));
}
static inline cdW cdWOr(cdW a, cdW b)
{
	CD_W_LANES(a.v[i] != CD_R(0.0) || b.v[i] != CD_R(0.0) ? CD_R(1.0) : CD_R(0.0));
}
static inline cdW cdWAnd(cdW a, cdW b)
{
	CD_W_LANES(a.v[i] != CD_R(0.0) && b.v[i] != CD_R(0.0) ? CD_R(1.0) : CD_R(0.0));
}
static inline cdW cdWAndNot(cdW a, cdW b)
{
	CD_W_LANES(a.v[i] == CD_R(0.0) && b.v[i] != CD_R(0.0) ? CD_R(1.0) : CD_R(0.0));
}
static inline void cdWStore(cdReal* out, cdW a)
{
	for (int i = 0; i < CD_W; ++i)
	{
		out[i] = a.v[i];
	}
}
static inline cdW cdWLoad(const cdReal* in)
{
	CD_W_LANES(in[i]);
}
static inline bool cdWAny(cdW mask)
{
	return mask.v[0] != CD_R(0.0) || mask.v[1] != CD_R(0.0) || mask.v[2] != CD_R(0.0) ||
		   mask.v[3] != CD_R(0.0);
}
#undef CD_W_LANES
#endif

static inline void cdWSetLane(cdW* w, int lane, cdReal value)
{
	memcpy((char*)w + (size_t)lane * sizeof(cdReal), &value, sizeof(value));
}

static inline cdReal cdWGetLane(const cdW* w, int lane)
{
	cdReal value;
	memcpy(&value, (const char*)w + (size_t)lane * sizeof(cdReal), sizeof(value));
	return value;
}

/* a < lower ? lower : (a > upper ? upper : a), lane by lane (cdClamp). */
static inline cdW cdWClamp(cdW a, cdW lower, cdW upper)
{
	return cdWSelect(cdWLess(a, lower), lower, cdWSelect(cdWGreater(a, upper), upper, a));
}

#endif
