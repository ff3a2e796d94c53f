/* collide: the small SIMD helpers of the wide contact solver. A cdW holds CD_W reals, one per
 * contact lane. The float build uses AVX2 (eight floats) when the compiler targets it (-mavx2, the
 * COLLIDE_AVX2 option), SSE2 (four floats) otherwise on x86-64, NEON (four floats) on aarch64 and
 * WebAssembly SIMD128 (four floats) under -msimd128; elsewhere (the double build, other machines,
 * or COLLIDE_NO_SIMD) a plain array of CD_W reals with the same operations done lane by lane. The
 * width is 8 in a float build that targets AVX2 (with or without COLLIDE_NO_SIMD, so that the
 * scalar lanes can be checked against AVX2's) or when COLLIDE_WIDE8 is defined, and 4 otherwise.
 * Every helper is one IEEE operation per lane or a select (no fused multiply-add, and min and max
 * are a comparison and a select, never an instruction with its own rules for NaN or zero signs),
 * and the build uses -ffp-contract=off, so all versions of one width produce the same bits for the
 * same lanes. A lane's arithmetic does not depend on its neighbours either, so the solver gives
 * the same bits at every width (contact_solver_wide2.c). */
#ifndef COLLIDE_WIDE2_H
#define COLLIDE_WIDE2_H

#include "collide/math2.h"

#include <string.h>

#if defined(COLLIDE_WIDE8) || (!CD_DOUBLE && defined(__AVX2__))
#define CD_W 8
#else
#define CD_W 4
#endif

#define CD_WIDE_AVX2 0
#define CD_WIDE_NEON 0

#if !CD_DOUBLE && CD_W == 8 && defined(__AVX2__) && !defined(COLLIDE_NO_SIMD)
#include <immintrin.h>
#define CD_WIDE_SSE 0
#undef CD_WIDE_AVX2
#define CD_WIDE_AVX2 1
typedef __m256 cdW;

static inline cdW cdWZero(void)
{
	return _mm256_setzero_ps();
}
static inline cdW cdWSplat(cdReal a)
{
	return _mm256_set1_ps(a);
}
static inline cdW cdWAdd(cdW a, cdW b)
{
	return _mm256_add_ps(a, b);
}
static inline cdW cdWSub(cdW a, cdW b)
{
	return _mm256_sub_ps(a, b);
}
static inline cdW cdWMul(cdW a, cdW b)
{
	return _mm256_mul_ps(a, b);
}
static inline cdW cdWDiv(cdW a, cdW b)
{
	return _mm256_div_ps(a, b);
}
static inline cdW cdWNeg(cdW a)
{
	return _mm256_xor_ps(a, _mm256_set1_ps(-0.0f));
}
/* a > b ? a : b and a < b ? a : b, lane by lane (cdMax, cdMin): maxps and minps return their
 * second operand unless the first is strictly greater (smaller), like SSE2's. */
static inline cdW cdWMax(cdW a, cdW b)
{
	return _mm256_max_ps(a, b);
}
static inline cdW cdWMin(cdW a, cdW b)
{
	return _mm256_min_ps(a, b);
}
/* mask ? a : b, mask lanes all ones or all zeros. */
static inline cdW cdWSelect(cdW mask, cdW a, cdW b)
{
	return _mm256_blendv_ps(b, a, mask);
}
/* The ordered, non-signalling comparisons of SSE2's cmpgt, cmplt and cmpeq, and cmpneq's
 * unordered one (true when either lane is NaN). */
static inline cdW cdWGreater(cdW a, cdW b)
{
	return _mm256_cmp_ps(a, b, _CMP_GT_OQ);
}
static inline cdW cdWLess(cdW a, cdW b)
{
	return _mm256_cmp_ps(a, b, _CMP_LT_OQ);
}
static inline cdW cdWEqual(cdW a, cdW b)
{
	return _mm256_cmp_ps(a, b, _CMP_EQ_OQ);
}
static inline cdW cdWNotEqual(cdW a, cdW b)
{
	return _mm256_cmp_ps(a, b, _CMP_NEQ_UQ);
}
static inline cdW cdWOr(cdW a, cdW b)
{
	return _mm256_or_ps(a, b);
}
static inline cdW cdWAnd(cdW a, cdW b)
{
	return _mm256_and_ps(a, b);
}
static inline cdW cdWAndNot(cdW a, cdW b)
{
	return _mm256_andnot_ps(a, b);
}
static inline void cdWStore(cdReal* out, cdW a)
{
	_mm256_storeu_ps(out, a);
}
static inline cdW cdWLoad(const cdReal* in)
{
	return _mm256_loadu_ps(in);
}
static inline bool cdWAny(cdW mask)
{
	return _mm256_movemask_ps(mask) != 0;
}
#elif !CD_DOUBLE && CD_W == 4 && defined(__SSE2__) && !defined(COLLIDE_NO_SIMD)
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
#elif !CD_DOUBLE && CD_W == 4 && defined(__wasm_simd128__) && !defined(COLLIDE_NO_SIMD)
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
#elif !CD_DOUBLE && CD_W == 4 && defined(__ARM_NEON) && defined(__aarch64__) && !defined(COLLIDE_NO_SIMD)
/* NEON on aarch64 (part of the baseline there): the same four-float operations. Masks are kept as
 * float vectors holding all-ones or all-zero lanes. vmaxq_f32 and vminq_f32 are not used: they
 * return NaN for a NaN operand and +0 for max(-0, +0), where cdMax(a, b) is a > b ? a : b; a
 * comparison and a bit select give exactly that. vdivq_f32 is the IEEE division (aarch64 only). */
#include <arm_neon.h>
#define CD_WIDE_SSE 0
#undef CD_WIDE_NEON
#define CD_WIDE_NEON 1
typedef float32x4_t cdW;

static inline cdW cdWZero(void)
{
	return vdupq_n_f32(0.0f);
}
static inline cdW cdWSplat(cdReal a)
{
	return vdupq_n_f32(a);
}
static inline cdW cdWAdd(cdW a, cdW b)
{
	return vaddq_f32(a, b);
}
static inline cdW cdWSub(cdW a, cdW b)
{
	return vsubq_f32(a, b);
}
static inline cdW cdWMul(cdW a, cdW b)
{
	return vmulq_f32(a, b);
}
static inline cdW cdWDiv(cdW a, cdW b)
{
	return vdivq_f32(a, b);
}
static inline cdW cdWNeg(cdW a)
{
	return vnegq_f32(a);
}
static inline cdW cdWMax(cdW a, cdW b)
{
	return vbslq_f32(vcgtq_f32(a, b), a, b);
}
static inline cdW cdWMin(cdW a, cdW b)
{
	return vbslq_f32(vcltq_f32(a, b), a, b);
}
/* mask ? a : b, mask lanes all ones or all zeros. */
static inline cdW cdWSelect(cdW mask, cdW a, cdW b)
{
	return vbslq_f32(vreinterpretq_u32_f32(mask), a, b);
}
static inline cdW cdWGreater(cdW a, cdW b)
{
	return vreinterpretq_f32_u32(vcgtq_f32(a, b));
}
static inline cdW cdWLess(cdW a, cdW b)
{
	return vreinterpretq_f32_u32(vcltq_f32(a, b));
}
static inline cdW cdWEqual(cdW a, cdW b)
{
	return vreinterpretq_f32_u32(vceqq_f32(a, b));
}
/* Not equal, true when either lane is NaN (SSE2's cmpneq). */
static inline cdW cdWNotEqual(cdW a, cdW b)
{
	return vreinterpretq_f32_u32(vmvnq_u32(vceqq_f32(a, b)));
}
static inline cdW cdWOr(cdW a, cdW b)
{
	return vreinterpretq_f32_u32(vorrq_u32(vreinterpretq_u32_f32(a), vreinterpretq_u32_f32(b)));
}
static inline cdW cdWAnd(cdW a, cdW b)
{
	return vreinterpretq_f32_u32(vandq_u32(vreinterpretq_u32_f32(a), vreinterpretq_u32_f32(b)));
}
/* (not a) and b: vbicq_u32(x, y) is x and not y. */
static inline cdW cdWAndNot(cdW a, cdW b)
{
	return vreinterpretq_f32_u32(vbicq_u32(vreinterpretq_u32_f32(b), vreinterpretq_u32_f32(a)));
}
static inline void cdWStore(cdReal* out, cdW a)
{
	vst1q_f32(out, a);
}
static inline cdW cdWLoad(const cdReal* in)
{
	return vld1q_f32(in);
}
static inline bool cdWAny(cdW mask)
{
	return vmaxvq_u32(vreinterpretq_u32_f32(mask)) != 0;
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
	bool any = false;
	for (int i = 0; i < CD_W; ++i)
	{
		any = any || mask.v[i] != CD_R(0.0);
	}
	return any;
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
