/* collide (internal): the support vertex of a point set, the inner loop of EPA and of the
 * incident-face search on large hulls. A hull of 32 vertices is scanned some twenty times per
 * contact, and a scalar arg-max over it mispredicts a branch on almost every new maximum, so the
 * float build on SSE2 scans four vertices at a time without branches (transposing them from the
 * vertex array as it goes: no copy, any count). Both paths compute each dot product in the order
 * of cd3Dot and return the first vertex of the largest dot product, so they give the same index
 * bit for bit. Not installed. */
#ifndef COLLIDE_SAT3_SUPPORT_H
#define COLLIDE_SAT3_SUPPORT_H

#include "collide/geometry3.h"

#if !CD_DOUBLE && defined(__SSE2__)
#include <emmintrin.h>
#define CD3_SUPPORT_SSE 1
#else
#define CD3_SUPPORT_SSE 0
#endif

#if CD3_SUPPORT_SSE
/* Four consecutive vertices (12 floats from f) as coordinate vectors. */
static inline void cd3SupportLoad4(const float* f, __m128* x, __m128* y, __m128* z)
{
	/* a0 = x0 y0 z0 x1, a1 = y1 z1 x2 y2, a2 = z2 x3 y3 z3 */
	__m128 a0 = _mm_loadu_ps(f), a1 = _mm_loadu_ps(f + 4), a2 = _mm_loadu_ps(f + 8);
	__m128 x23 = _mm_shuffle_ps(a1, a2, _MM_SHUFFLE(1, 1, 2, 2));
	*x = _mm_shuffle_ps(a0, x23, _MM_SHUFFLE(2, 0, 3, 0));
	__m128 y01 = _mm_shuffle_ps(a0, a1, _MM_SHUFFLE(0, 0, 1, 1));
	__m128 y23 = _mm_shuffle_ps(a1, a2, _MM_SHUFFLE(2, 2, 3, 3));
	*y = _mm_shuffle_ps(y01, y23, _MM_SHUFFLE(2, 0, 2, 0));
	__m128 z01 = _mm_shuffle_ps(a0, a1, _MM_SHUFFLE(1, 1, 2, 2));
	*z = _mm_shuffle_ps(z01, a2, _MM_SHUFFLE(3, 0, 2, 0));
}

/* The dot products of four consecutive vertices (12 floats from f) with the direction. */
static inline __m128 cd3SupportDots4(const float* f, __m128 dx, __m128 dy, __m128 dz)
{
	__m128 x, y, z;
	cd3SupportLoad4(f, &x, &y, &z);
	return _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, x), _mm_mul_ps(dy, y)), _mm_mul_ps(dz, z));
}
#endif

/* Scalar tail: continues the first-maximum scan from index `start`. */
static inline int cd3SupportIndexScalar(const cd3Vec* vertices, int start, int count, cd3Vec direction,
										int best, cdReal highest)
{
	for (int i = start; i < count; ++i)
	{
		cdReal d = cd3Dot(direction, vertices[i]);
		bool higher = d > highest;
		best = higher ? i : best;
		highest = higher ? d : highest;
	}
	return best;
}

#if CD3_SUPPORT_SSE
/* Keeps, lane by lane, the first of the larger values and its index. */
static inline void cd3SupportKeepHigher(__m128 d, __m128i index, __m128* best, __m128i* bestIndex)
{
	__m128 higher = _mm_cmpgt_ps(d, *best);
	*best = _mm_or_ps(_mm_and_ps(higher, d), _mm_andnot_ps(higher, *best));
	__m128i mask = _mm_castps_si128(higher);
	*bestIndex = _mm_or_si128(_mm_and_si128(mask, index), _mm_andnot_si128(mask, *bestIndex));
}

/* Lane k saw the indices k mod 4 and kept its first maximum; across lanes the first maximum is
 * the smallest index among the lanes holding the largest value (usually one lane: no branch to
 * mispredict). */
static inline int cd3SupportFirstMaximum(__m128 best, __m128i bestIndex, float* highest)
{
	__m128 top = _mm_max_ps(best, _mm_shuffle_ps(best, best, _MM_SHUFFLE(1, 0, 3, 2)));
	top = _mm_max_ps(top, _mm_shuffle_ps(top, top, _MM_SHUFFLE(2, 3, 0, 1)));
	int lanes = _mm_movemask_ps(_mm_cmpeq_ps(best, top));
	int32_t indices[4];
	_mm_storeu_si128((__m128i*)(void*)indices, bestIndex);
	static const int8_t FIRST_LANE[16] = {0, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0};
	int winner = indices[FIRST_LANE[lanes]];
	if (lanes & (lanes - 1))
	{
		for (int k = 0; k < 4; ++k)
		{
			if (((lanes >> k) & 1) && indices[k] < winner)
			{
				winner = indices[k];
			}
		}
	}
	*highest = _mm_cvtss_f32(top);
	return winner;
}
#endif

/* The index of the first vertex with the largest dot product with `direction` (count >= 1). */
static inline int cd3SupportIndex(const cd3Vec* vertices, int count, cd3Vec direction)
{
#if CD3_SUPPORT_SSE
	_Static_assert(sizeof(cd3Vec) == 3 * sizeof(float), "cd3Vec must be three packed floats");
	if (count >= 8)
	{
		const float* f = &vertices[0].x;
		__m128 dx = _mm_set1_ps(direction.x), dy = _mm_set1_ps(direction.y), dz = _mm_set1_ps(direction.z);
		__m128i index = _mm_set_epi32(3, 2, 1, 0);
		__m128i four = _mm_set1_epi32(4);
		__m128 best = cd3SupportDots4(f, dx, dy, dz);
		__m128i bestIndex = index;
		int groups = count / 4;
		for (int g = 1; g < groups; ++g)
		{
			f += 12;
			index = _mm_add_epi32(index, four);
			cd3SupportKeepHigher(cd3SupportDots4(f, dx, dy, dz), index, &best, &bestIndex);
		}
		float highest;
		int winner = cd3SupportFirstMaximum(best, bestIndex, &highest);
		return cd3SupportIndexScalar(vertices, groups * 4, count, direction, winner, highest);
	}
#endif
	return cd3SupportIndexScalar(vertices, 1, count, direction, 0, cd3Dot(direction, vertices[0]));
}

/* The index of the first plane whose normal has the largest dot product with `direction`
 * (count >= 1): the face most aligned with a direction. */
static inline int cd3PlaneSupportIndex(const cd3Plane* planes, int count, cd3Vec direction, cdReal* dot)
{
	int start = 1;
	int best = 0;
	cdReal highest = cd3Dot(planes[0].normal, direction);
#if CD3_SUPPORT_SSE
	_Static_assert(sizeof(cd3Plane) == 4 * sizeof(float), "cd3Plane must be four packed floats");
	if (count >= 8)
	{
		const float* f = &planes[0].normal.x;
		__m128 dx = _mm_set1_ps(direction.x), dy = _mm_set1_ps(direction.y), dz = _mm_set1_ps(direction.z);
		__m128i index = _mm_set_epi32(3, 2, 1, 0);
		__m128i four = _mm_set1_epi32(4);
		__m128 bestValue = _mm_set1_ps(-CD_REAL_MAX);
		__m128i bestIndex = index;
		int groups = count / 4;
		for (int g = 0; g < groups; ++g, f += 16)
		{
			__m128 r0 = _mm_loadu_ps(f), r1 = _mm_loadu_ps(f + 4), r2 = _mm_loadu_ps(f + 8),
				   r3 = _mm_loadu_ps(f + 12);
			_MM_TRANSPOSE4_PS(r0, r1, r2, r3);
			__m128 d = _mm_add_ps(_mm_add_ps(_mm_mul_ps(r0, dx), _mm_mul_ps(r1, dy)), _mm_mul_ps(r2, dz));
			if (g == 0)
			{
				bestValue = d;
			}
			else
			{
				cd3SupportKeepHigher(d, index, &bestValue, &bestIndex);
			}
			index = _mm_add_epi32(index, four);
		}
		float top;
		best = cd3SupportFirstMaximum(bestValue, bestIndex, &top);
		highest = top;
		start = groups * 4;
	}
#endif
	for (int i = start; i < count; ++i)
	{
		cdReal d = cd3Dot(planes[i].normal, direction);
		bool higher = d > highest;
		best = higher ? i : best;
		highest = higher ? d : highest;
	}
	*dot = highest;
	return best;
}

/* Points stored as coordinate arrays (structure of arrays), padded to a multiple of 4 with
 * copies of point 0 (a copy never beats the first point under the first-maximum rule). Small
 * polytopes get this form on the stack when they are scanned many times: a scan then needs no
 * shuffles, and B's points are moved into A's frame once instead of each direction and answer. */
#define CD3_SOA_MAX_POINTS 64

typedef struct cd3SoaPoints
{
	int count, padded;
	cdReal x[CD3_SOA_MAX_POINTS], y[CD3_SOA_MAX_POINTS], z[CD3_SOA_MAX_POINTS];
} cd3SoaPoints;

/* rotation * v + translation of each point (count <= CD3_SOA_MAX_POINTS), as cd3MulMV and cd3Add
 * compute it. */
static inline void cd3MakeSoaPoints(cd3SoaPoints* s, const cd3Vec* points, int count, cd3Mat33 rotation,
									cd3Vec translation)
{
	CD_ASSERT(count >= 1 && count <= CD3_SOA_MAX_POINTS);
	s->count = count;
	s->padded = (count + 3) & ~3;
	int start = 0;
#if CD3_SUPPORT_SSE
	/* Four at a time, in cd3MulMV's order of operations (the same bits). */
	__m128 m00 = _mm_set1_ps(rotation.cx.x), m10 = _mm_set1_ps(rotation.cx.y),
		   m20 = _mm_set1_ps(rotation.cx.z);
	__m128 m01 = _mm_set1_ps(rotation.cy.x), m11 = _mm_set1_ps(rotation.cy.y),
		   m21 = _mm_set1_ps(rotation.cy.z);
	__m128 m02 = _mm_set1_ps(rotation.cz.x), m12 = _mm_set1_ps(rotation.cz.y),
		   m22 = _mm_set1_ps(rotation.cz.z);
	__m128 tx = _mm_set1_ps(translation.x), ty = _mm_set1_ps(translation.y), tz = _mm_set1_ps(translation.z);
	for (; start + 4 <= count; start += 4)
	{
		__m128 x, y, z;
		cd3SupportLoad4(&points[start].x, &x, &y, &z);
		_mm_storeu_ps(s->x + start, _mm_add_ps(_mm_add_ps(_mm_add_ps(_mm_mul_ps(x, m00), _mm_mul_ps(y, m01)),
														  _mm_mul_ps(z, m02)),
											   tx));
		_mm_storeu_ps(s->y + start, _mm_add_ps(_mm_add_ps(_mm_add_ps(_mm_mul_ps(x, m10), _mm_mul_ps(y, m11)),
														  _mm_mul_ps(z, m12)),
											   ty));
		_mm_storeu_ps(s->z + start, _mm_add_ps(_mm_add_ps(_mm_add_ps(_mm_mul_ps(x, m20), _mm_mul_ps(y, m21)),
														  _mm_mul_ps(z, m22)),
											   tz));
	}
#endif
	for (int i = start; i < s->padded; ++i)
	{
		cd3Vec p = cd3Add(cd3MulMV(rotation, points[i < count ? i : 0]), translation);
		s->x[i] = p.x;
		s->y[i] = p.y;
		s->z[i] = p.z;
	}
}

/* The points as they are. */
static inline void cd3CopySoaPoints(cd3SoaPoints* s, const cd3Vec* points, int count)
{
	CD_ASSERT(count >= 1 && count <= CD3_SOA_MAX_POINTS);
	s->count = count;
	s->padded = (count + 3) & ~3;
	int start = 0;
#if CD3_SUPPORT_SSE
	for (; start + 4 <= count; start += 4)
	{
		__m128 x, y, z;
		cd3SupportLoad4(&points[start].x, &x, &y, &z);
		_mm_storeu_ps(s->x + start, x);
		_mm_storeu_ps(s->y + start, y);
		_mm_storeu_ps(s->z + start, z);
	}
#endif
	for (int i = start; i < s->padded; ++i)
	{
		cd3Vec p = points[i < count ? i : 0];
		s->x[i] = p.x;
		s->y[i] = p.y;
		s->z[i] = p.z;
	}
}

static inline cd3Vec cd3SoaPoint(const cd3SoaPoints* s, int i)
{
	return cd3MakeVec(s->x[i], s->y[i], s->z[i]);
}

/* Lowest set bit of a nonzero mask. */
static inline int cd3LowestBit(uint64_t bits)
{
#if defined(__GNUC__)
	return __builtin_ctzll(bits);
#else
	int i = 0;
	while (!(bits & 1u))
	{
		bits >>= 1;
		++i;
	}
	return i;
#endif
}

#if CD3_SUPPORT_SSE
/* Up to this many points, cd3ColumnsSupportIndex finds the largest dot product first and its
 * first index after: one bit per point. */
#define CD3_COLUMNS_TWO_PASS_MAX 64

/* The support of at most CD3_COLUMNS_TWO_PASS_MAX column points (padded a multiple of 4) in two
 * passes: the dot products and their maximum (two running maxima, so that the chain of dependent
 * operations is half the groups long), then a bit per point equal to the maximum, whose lowest
 * set bit is the first maximum. The one-pass scan carried the value and the index of every lane
 * through a compare and a select per group, a chain of six cycles per group that the GJK loop
 * waits on (its next step needs the support point); two passes shorten that chain for about the
 * same instruction count.
 * Same products, same sums, same first-maximum rule: the same index bit for bit (an all-NaN
 * direction, which no bit matches, gives 0). */
static inline int cd3ColumnsSupportTwoPass(const float* xs, const float* ys, const float* zs, int padded,
										   __m128 dx, __m128 dy, __m128 dz)
{
	__m128 dots[CD3_COLUMNS_TWO_PASS_MAX / 4];
	int groups = padded >> 2;
	for (int g = 0; g < groups; ++g)
	{
		int i = 4 * g;
		dots[g] =
			_mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, _mm_loadu_ps(xs + i)), _mm_mul_ps(dy, _mm_loadu_ps(ys + i))),
					   _mm_mul_ps(dz, _mm_loadu_ps(zs + i)));
	}
	/* max(new, old) returns old when either is NaN: a NaN product never becomes the maximum. */
	__m128 highEven = dots[0], highOdd = dots[groups > 1 ? 1 : 0];
	for (int g = 2; g + 1 < groups; g += 2)
	{
		highEven = _mm_max_ps(dots[g], highEven);
		highOdd = _mm_max_ps(dots[g + 1], highOdd);
	}
	if (groups > 2 && (groups & 1))
	{
		highEven = _mm_max_ps(dots[groups - 1], highEven);
	}
	__m128 top = _mm_max_ps(highEven, highOdd);
	top = _mm_max_ps(top, _mm_shuffle_ps(top, top, _MM_SHUFFLE(1, 0, 3, 2)));
	top = _mm_max_ps(top, _mm_shuffle_ps(top, top, _MM_SHUFFLE(2, 3, 0, 1)));
	uint64_t bits = 0;
	for (int g = 0; g < groups; ++g)
	{
		bits |= (uint64_t)(unsigned)_mm_movemask_ps(_mm_cmpeq_ps(dots[g], top)) << (4 * g);
	}
	return bits != 0 ? cd3LowestBit(bits) : 0;
}
#endif

/* cd3SupportIndex over points stored as three coordinate arrays of `padded` entries (a multiple
 * of 4, padded with copies of point 0): the same index, bit for bit (the same products and sums,
 * the same first-maximum rule; a padding copy never beats point 0's smaller index). A hull's
 * vertexColumns have this form. */
static inline int cd3ColumnsSupportIndex(const cdReal* xs, const cdReal* ys, const cdReal* zs, int count,
										 int padded, cd3Vec direction)
{
#if CD3_SUPPORT_SSE
	(void)count;
	__m128 dx = _mm_set1_ps(direction.x), dy = _mm_set1_ps(direction.y), dz = _mm_set1_ps(direction.z);
	if (padded <= CD3_COLUMNS_TWO_PASS_MAX)
	{
		return cd3ColumnsSupportTwoPass(xs, ys, zs, padded, dx, dy, dz);
	}
	__m128i index = _mm_set_epi32(3, 2, 1, 0);
	__m128i four = _mm_set1_epi32(4);
	__m128 best = _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, _mm_loadu_ps(xs)), _mm_mul_ps(dy, _mm_loadu_ps(ys))),
							 _mm_mul_ps(dz, _mm_loadu_ps(zs)));
	__m128i bestIndex = index;
	for (int i = 4; i < padded; i += 4)
	{
		index = _mm_add_epi32(index, four);
		__m128 d =
			_mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, _mm_loadu_ps(xs + i)), _mm_mul_ps(dy, _mm_loadu_ps(ys + i))),
					   _mm_mul_ps(dz, _mm_loadu_ps(zs + i)));
		cd3SupportKeepHigher(d, index, &best, &bestIndex);
	}
	float highest;
	return cd3SupportFirstMaximum(best, bestIndex, &highest);
#else
	(void)padded;
	int best = 0;
	cdReal highest = direction.x * xs[0] + direction.y * ys[0] + direction.z * zs[0];
	for (int i = 1; i < count; ++i)
	{
		cdReal d = direction.x * xs[i] + direction.y * ys[i] + direction.z * zs[i];
		bool higher = d > highest;
		best = higher ? i : best;
		highest = higher ? d : highest;
	}
	return best;
#endif
}

/* cd3SupportIndex over the arrays. */
static inline int cd3SoaSupportIndex(const cd3SoaPoints* s, cd3Vec direction)
{
	return cd3ColumnsSupportIndex(s->x, s->y, s->z, s->count, s->padded, direction);
}

#endif
