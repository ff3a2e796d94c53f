/* collide (internal): the separating-axis scan of the 2D manifolds, the largest separation of one
 * convex core from another over the first core's edge normals.
 *
 * For each edge i of A the separation is min over B's vertices j of dot(n_i, b_j - v_i); the
 * answer is the first edge of the largest separation. A scalar scan that stops an edge as soon as
 * its running minimum falls to the best so far executes fewest instructions, but its exit branch
 * is data-dependent and mispredicts several times per polygon pair, which costs more than the
 * work it saves.
 * So every edge is scanned to the end without branches: the float build on SSE2 holds four of
 * A's edges in the lanes of a vector (edge normals and vertices transposed once) and walks B's
 * vertices, and so does the float build for WebAssembly SIMD128; elsewhere (double, other
 * targets) a plain loop with selects. All compute each dot product in cd2Dot's order and take
 * the minimum as cdMin does, so they return the same edge and the same value bit for bit, which
 * are also those of the early-exit scan (an edge it stops early could not have won: its full
 * minimum is below its partial one). Not installed. */
#ifndef COLLIDE_SAT2_SEPARATION_H
#define COLLIDE_SAT2_SEPARATION_H

#include "collide/math2.h"

#if !CD_DOUBLE && defined(__SSE2__)
#include <emmintrin.h>
#define CD2_SEPARATION_SSE 1
#else
#define CD2_SEPARATION_SSE 0
#endif

/* The same four-lane scan with WebAssembly SIMD128 (clang -msimd128). */
#if !CD_DOUBLE && !CD2_SEPARATION_SSE && defined(__wasm_simd128__)
#include <wasm_simd128.h>
#define CD2_SEPARATION_WASM 1
#else
#define CD2_SEPARATION_WASM 0
#endif

/* The plain scan, for any count, and the reference the tests compare the others with. */
static inline cdReal cd2MaxSeparationScalar(const cd2Vec* normals, const cd2Vec* vertices, int count,
											const cd2Vec* others, int otherCount, int* edge)
{
	cdReal best = -CD_REAL_MAX;
	int bestEdge = 0;
	for (int i = 0; i < count; ++i)
	{
		cd2Vec n = normals[i];
		cd2Vec v = vertices[i];
		cdReal lowest = CD_REAL_MAX;
		for (int j = 0; j < otherCount; ++j)
		{
			lowest = cdMin(lowest, cd2Dot(n, cd2Sub(others[j], v)));
		}
		bool higher = lowest > best;
		bestEdge = higher ? i : bestEdge;
		best = higher ? lowest : best;
	}
	*edge = bestEdge;
	return best;
}

#if CD2_SEPARATION_SSE
/* Four of the vectors p[i0], p[i1], p[i2], p[i3] as an x and a y vector. Loaded 8 bytes at a
 * time, straight from the arrays: gathering them into a stack buffer first and reading it back
 * 16 bytes at a time would wait on store forwarding. */
static inline void cd2SeparationLoad4(const cd2Vec* p, int i0, int i1, int i2, int i3, __m128* x, __m128* y)
{
	__m128 lo = _mm_loadh_pi(_mm_loadl_pi(_mm_setzero_ps(), (const __m64*)(const void*)&p[i0]),
							 (const __m64*)(const void*)&p[i1]);
	__m128 hi = _mm_loadh_pi(_mm_loadl_pi(_mm_setzero_ps(), (const __m64*)(const void*)&p[i2]),
							 (const __m64*)(const void*)&p[i3]);
	*x = _mm_shuffle_ps(lo, hi, _MM_SHUFFLE(2, 0, 2, 0));
	*y = _mm_shuffle_ps(lo, hi, _MM_SHUFFLE(3, 1, 3, 1));
}

/* The separations of B from the four edges of A in lanes (normal nx, ny, vertex vx, vy). */
static inline __m128 cd2SeparationLanes(__m128 nx, __m128 ny, __m128 vx, __m128 vy, const cd2Vec* others,
										int otherCount)
{
	__m128 lowest = _mm_set1_ps(CD_REAL_MAX);
	for (int j = 0; j < otherCount; ++j)
	{
		__m128 dx = _mm_sub_ps(_mm_set1_ps(others[j].x), vx);
		__m128 dy = _mm_sub_ps(_mm_set1_ps(others[j].y), vy);
		/* _mm_min_ps(a, b) is a < b ? a : b, cdMin's rule (the same zero when both are zeros). */
		lowest = _mm_min_ps(lowest, _mm_add_ps(_mm_mul_ps(nx, dx), _mm_mul_ps(ny, dy)));
	}
	return lowest;
}

/* The separations of B from A's edges 0-3 (low) and 4-7 (high; low again for up to four edges),
 * and their maximum in every lane of *top. Lanes past the count repeat edge 0: a copy never beats
 * the first edge under the first-maximum rule. */
static inline void cd2SeparationLanes8(const cd2Vec* normals, const cd2Vec* vertices, int count,
									   const cd2Vec* others, int otherCount, __m128* low, __m128* high,
									   __m128* top)
{
	int i1 = count > 1 ? 1 : 0, i2 = count > 2 ? 2 : 0, i3 = count > 3 ? 3 : 0;
	__m128 nx, ny, vx, vy;
	cd2SeparationLoad4(normals, 0, i1, i2, i3, &nx, &ny);
	cd2SeparationLoad4(vertices, 0, i1, i2, i3, &vx, &vy);
	*low = cd2SeparationLanes(nx, ny, vx, vy, others, otherCount);
	*high = *low;
	if (count > 4)
	{
		int i5 = count > 5 ? 5 : 0, i6 = count > 6 ? 6 : 0, i7 = count > 7 ? 7 : 0;
		cd2SeparationLoad4(normals, 4, i5, i6, i7, &nx, &ny);
		cd2SeparationLoad4(vertices, 4, i5, i6, i7, &vx, &vy);
		*high = cd2SeparationLanes(nx, ny, vx, vy, others, otherCount);
	}
	__m128 t = _mm_max_ps(*low, *high);
	t = _mm_max_ps(t, _mm_shuffle_ps(t, t, _MM_SHUFFLE(1, 0, 3, 2)));
	*top = _mm_max_ps(t, _mm_shuffle_ps(t, t, _MM_SHUFFLE(2, 3, 0, 1)));
}

/* The first edge whose lane equals the maximum top (-0 and +0 compare equal, as under the scalar
 * rule), and that lane's value. */
static inline int cd2SeparationFirstLane(__m128 low, __m128 high, __m128 top, cdReal* value)
{
	int lanes = _mm_movemask_ps(_mm_cmpeq_ps(low, top)) | _mm_movemask_ps(_mm_cmpeq_ps(high, top)) << 4;
	static const int8_t FIRST_LANE[16] = {0, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0};
	int first = (lanes & 15) != 0 ? FIRST_LANE[lanes & 15] : 4 + FIRST_LANE[lanes >> 4];
	float values[8];
	_mm_storeu_ps(values, low);
	_mm_storeu_ps(values + 4, high);
	*value = values[first];
	return first;
}
#endif

#if CD2_SEPARATION_WASM
/* p[i0..i3] as an x and a y vector (the SSE version's loads). */
static inline void cd2SeparationLoad4Wasm(const cd2Vec* p, int i0, int i1, int i2, int i3, v128_t* x,
										  v128_t* y)
{
	v128_t lo = wasm_v128_load64_lane(&p[i1], wasm_v128_load64_zero(&p[i0]), 1);
	v128_t hi = wasm_v128_load64_lane(&p[i3], wasm_v128_load64_zero(&p[i2]), 1);
	*x = wasm_i32x4_shuffle(lo, hi, 0, 2, 4, 6);
	*y = wasm_i32x4_shuffle(lo, hi, 1, 3, 5, 7);
}

static inline v128_t cd2SeparationLanesWasm(v128_t nx, v128_t ny, v128_t vx, v128_t vy, const cd2Vec* others,
											int otherCount)
{
	v128_t lowest = wasm_f32x4_splat(CD_REAL_MAX);
	for (int j = 0; j < otherCount; ++j)
	{
		v128_t dx = wasm_f32x4_sub(wasm_f32x4_splat(others[j].x), vx);
		v128_t dy = wasm_f32x4_sub(wasm_f32x4_splat(others[j].y), vy);
		/* pmin(d, lowest) is lowest < d ? lowest : d, cdMin(lowest, d)'s rule. */
		v128_t d = wasm_f32x4_add(wasm_f32x4_mul(nx, dx), wasm_f32x4_mul(ny, dy));
		lowest = wasm_f32x4_pmin(d, lowest);
	}
	return lowest;
}
#endif

/* The largest separation of the points `others` from the convex core of `count` edges (count
 * <= CD2_MAX_POLYGON_VERTICES, normals[i] the outward normal of the edge from vertices[i]), and
 * in *edge the first edge that has it. */
static inline cdReal cd2MaxSeparation(const cd2Vec* normals, const cd2Vec* vertices, int count,
									  const cd2Vec* others, int otherCount, int* edge)
{
#if CD2_SEPARATION_SSE
	_Static_assert(sizeof(cd2Vec) == 2 * sizeof(float), "cd2Vec must be two packed floats");
	_Static_assert(CD2_MAX_POLYGON_VERTICES <= 8, "two groups of four edges");
	CD_ASSERT(count >= 1 && count <= CD2_MAX_POLYGON_VERTICES && otherCount >= 1);
	__m128 low, high, top;
	cd2SeparationLanes8(normals, vertices, count, others, otherCount, &low, &high, &top);
	cdReal best;
	int first = cd2SeparationFirstLane(low, high, top, &best);
	/* The scalar scan starts from -CD_REAL_MAX and keeps edge 0 when nothing exceeds it. */
	if (!(best > -CD_REAL_MAX))
	{
		*edge = 0;
		return -CD_REAL_MAX;
	}
	*edge = first;
	return best;
#elif CD2_SEPARATION_WASM
	_Static_assert(sizeof(cd2Vec) == 2 * sizeof(float), "cd2Vec must be two packed floats");
	_Static_assert(CD2_MAX_POLYGON_VERTICES <= 8, "two groups of four edges");
	CD_ASSERT(count >= 1 && count <= CD2_MAX_POLYGON_VERTICES && otherCount >= 1);
	int i1 = count > 1 ? 1 : 0, i2 = count > 2 ? 2 : 0, i3 = count > 3 ? 3 : 0;
	v128_t nx, ny, vx, vy;
	cd2SeparationLoad4Wasm(normals, 0, i1, i2, i3, &nx, &ny);
	cd2SeparationLoad4Wasm(vertices, 0, i1, i2, i3, &vx, &vy);
	v128_t low = cd2SeparationLanesWasm(nx, ny, vx, vy, others, otherCount);
	v128_t high = low;
	if (count > 4)
	{
		int i5 = count > 5 ? 5 : 0, i6 = count > 6 ? 6 : 0, i7 = count > 7 ? 7 : 0;
		cd2SeparationLoad4Wasm(normals, 4, i5, i6, i7, &nx, &ny);
		cd2SeparationLoad4Wasm(vertices, 4, i5, i6, i7, &vx, &vy);
		high = cd2SeparationLanesWasm(nx, ny, vx, vy, others, otherCount);
	}
	/* pmax(b, a) is a > b ? a : b, as _mm_max_ps(a, b). */
	v128_t top = wasm_f32x4_pmax(high, low);
	top = wasm_f32x4_pmax(wasm_i32x4_shuffle(top, top, 2, 3, 0, 1), top);
	top = wasm_f32x4_pmax(wasm_i32x4_shuffle(top, top, 1, 0, 3, 2), top);
	int lanes = (int)(wasm_i32x4_bitmask(wasm_f32x4_eq(low, top)) |
					  wasm_i32x4_bitmask(wasm_f32x4_eq(high, top)) << 4);
	static const int8_t FIRST_LANE_WASM[16] = {0, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0};
	int first = (lanes & 15) != 0 ? FIRST_LANE_WASM[lanes & 15] : 4 + FIRST_LANE_WASM[lanes >> 4];
	float values[8];
	wasm_v128_store(values, low);
	wasm_v128_store(values + 4, high);
	cdReal best = values[first];
	if (!(best > -CD_REAL_MAX))
	{
		*edge = 0;
		return -CD_REAL_MAX;
	}
	*edge = first;
	return best;
#else
	return cd2MaxSeparationScalar(normals, vertices, count, others, otherCount, edge);
#endif
}

/* cd2MaxSeparation for a caller that stops when the separation exceeds `limit`: false when it
 * does (then *edge and *separation are not set), else true with the same edge and separation as
 * cd2MaxSeparation. The SSE form tests the maximum as soon as the lanes are reduced, before the
 * lookup of its first lane: that exit is the branch a broadphase's mix of pairs (about half of them
 * apart) mispredicts, and it no longer waits on the lookup (on finite input the maximum and the
 * value of its first lane are the same number, so the test is the same). */
static inline bool cd2MaxSeparationWithin(const cd2Vec* normals, const cd2Vec* vertices, int count,
										  const cd2Vec* others, int otherCount, cdReal limit, int* edge,
										  cdReal* separation)
{
#if CD2_SEPARATION_SSE
	CD_ASSERT(count >= 1 && count <= CD2_MAX_POLYGON_VERTICES && otherCount >= 1);
	__m128 low, high, top;
	cd2SeparationLanes8(normals, vertices, count, others, otherCount, &low, &high, &top);
	if (_mm_cvtss_f32(top) > limit)
	{
		return false;
	}
	cdReal best;
	int first = cd2SeparationFirstLane(low, high, top, &best);
	if (!(best > -CD_REAL_MAX))
	{
		first = 0;
		best = -CD_REAL_MAX;
	}
	/* Non-finite lanes can make the first lane's value differ from the maximum: the test as
	 * cd2MaxSeparation's caller makes it. */
	if (best > limit)
	{
		return false;
	}
	*edge = first;
	*separation = best;
	return true;
#else
	cdReal best = cd2MaxSeparation(normals, vertices, count, others, otherCount, edge);
	*separation = best;
	return !(best > limit);
#endif
}

#endif
