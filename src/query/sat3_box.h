/* collide (internal): box pieces of the separating axis test that the box-box manifold needs
 * without building polytopes. Not installed. */
#ifndef COLLIDE_SAT3_BOX_H
#define COLLIDE_SAT3_BOX_H

#include "sat3.h"

#include "base/real_bits.h"

#include <string.h>

/* Edge pairs whose cross product is shorter than this fraction of |eA| |eB| are parallel (as in
 * sat3.c). */
#define CD3_BOX_PARALLEL_SINE CD_R(1.0e-5)

/* The endpoints (origin, then the twin's origin) of half-edge `edge` of a box with these half
 * extents, in the box's frame, numbered as by cd3InitBoxPolytope. */
void cd3BoxEdgeLocal(cd3Vec halfExtents, int edge, cd3Vec* p1, cd3Vec* p2);

/* The box edge parallel to axis `axis` that supports the box along `direction` (box frame). */
static inline int cd3SupportingBoxEdge(int axis, cd3Vec direction)
{
	/* CD3_BOX_EDGE_FROM[v][axis]: the half-edge from vertex v (its `axis` bit clear) to v with that bit
	 * set; -1 where the bit is already set. */
	static const int CD3_BOX_EDGE_FROM[8][3] = {{9, 17, 1},	 {-1, 5, 10},  {18, -1, 13}, {-1, -1, 6},
												{21, 2, -1}, {-1, 22, -1}, {14, -1, -1}, {-1, -1, -1}};

	int vertex = 0;
	for (int k = 0; k < 3; ++k)
	{
		if (k != axis && cd3GetComponent(direction, k) > CD_R(0.0))
		{
			vertex |= 1 << k;
		}
	}
	return CD3_BOX_EDGE_FROM[vertex][axis];
}

/* True when x, y and z are all +0: one integer test instead of a compare-and-branch on each (the
 * box-box path asks this of every pose, and -0, which fails it, takes the general path, whose
 * answer is the same up to the sign of a zero). */
static inline bool cd3AreZeroBits(cdReal x, cdReal y, cdReal z)
{
	return (cdGetRealBits(x) | cdGetRealBits(y) | cdGetRealBits(z)) == 0;
}

/* The identity rotation, tested as cd3AreZeroBits on x, y, z and w == 1 (on the bits: 1 has no
 * other representation, and integer tests combine without the flags of a float comparison). */
static inline bool cd3IsIdentityQuatBits(cd3Quat q)
{
	return ((cdGetRealBits(q.x) | cdGetRealBits(q.y) | cdGetRealBits(q.z)) |
			(cdGetRealBits(q.w) ^ cdGetRealBits(CD_R(1.0)))) == 0;
}

/* |a| as a max, which compiles to one instruction: the signs of the box SAT's matrix entries and
 * centre offsets are random, so cdAbs's comparison branch mispredicts half the time. */
static inline cdReal cd3AbsNoBranch(cdReal a)
{
	return cdMax(a, -a);
}

/* The best edge axis so far of the box SAT. */
typedef struct cd3BoxEdgeBest
{
	cdReal separation;
	cd3Vec axis;
	int i, j;
} cd3BoxEdgeBest;

/* Below this sine of the angle between the edges, B's radius on their axis is projected
 * explicitly (see cd3BoxEdgeAxis). */
#define CD3_BOX_EXPLICIT_RADIUS_SINE CD_R(0.015625)

/* Always inlined where the compiler allows forcing it: nine calls in a row, each a few multiplies
 * on the common path, which a call would turn into spills of the SAT's matrix entries. */
#if defined(__GNUC__) || defined(__clang__)
#define CD3_BOX_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define CD3_BOX_ALWAYS_INLINE inline
#endif

/* Edge axis A_i x B_j in A's frame: (0, -r[2][j], r[1][j]) for i = 0 and its cyclic shifts (ri1j
 * and ri2j: the matrix entries of B's axis j on A's axes i+1 and i+2), so the projections are sums
 * of the matrix entries: radiusA and radiusB are the boxes' and centre the centres' projections,
 * all times the axis length. True when the best edge separation so far exceeds exitSeparation
 * (the boxes are then apart by more than the caller cares about).
 *
 * radiusB takes B's axes k != j on the axis from the identity B_k . (A_i x B_j) = +-A_i . B_l: an
 * entry whose round-off, epsilon, is divided by the axis length, the sine of the edges' angle.
 * For nearly parallel edges that is far from the projection (a needle AABB 1e9 long and a box
 * whose axis was 1.5e-5 rad off it, in float: 7.8e6 of separation on an axis along which they
 * overlap), so below a sine of 1/64 the radius is projected on the axis itself, B's axes being
 * the columns of m: round-off a few epsilon of the radius, whatever the sine. Rare: a random
 * pair of boxes has such an edge pair 0.2% of the time. */
static CD3_BOX_ALWAYS_INLINE bool cd3BoxEdgeAxis(cd3BoxEdgeBest* e, int i, int j, cdReal ri1j, cdReal ri2j,
												 cdReal radiusA, cdReal radiusB, cdReal centre,
												 cdReal faceBest, cdReal exitSeparation, const cd3Mat33* m,
												 cd3Vec hb)
{
	cdReal length2 = ri1j * ri1j + ri2j * ri2j;
	if (!(length2 > CD3_BOX_PARALLEL_SINE * CD3_BOX_PARALLEL_SINE))
	{
		return false;
	}
	if (length2 < CD3_BOX_EXPLICIT_RADIUS_SINE * CD3_BOX_EXPLICIT_RADIUS_SINE)
	{
		cdReal components[3] = {CD_R(0.0), CD_R(0.0), CD_R(0.0)};
		components[(i + 1) % 3] = -ri2j;
		components[(i + 2) % 3] = ri1j;
		cd3Vec axis = cd3MakeVec(components[0], components[1], components[2]);
		radiusB = hb.x * cdAbs(cd3Dot(m->cx, axis)) + hb.y * cdAbs(cd3Dot(m->cy, axis)) +
				  hb.z * cdAbs(cd3Dot(m->cz, axis));
	}
	cdReal gap = cd3AbsNoBranch(centre) - radiusA - radiusB; /* separation * sqrt(length2) */
	/* An edge axis matters only when it beats every axis so far: decided on squares, so that
	 * only the winners pay a square root. */
	cdReal threshold = cdMax(e->separation, faceBest);
	cdReal bar = threshold * threshold * length2;
	bool ahead = threshold >= CD_R(0.0), behind = !ahead;
	bool beats =
		(ahead & (gap > CD_R(0.0)) & (gap * gap > bar)) | (behind & ((gap >= CD_R(0.0)) | (gap * gap < bar)));
	if (!beats)
	{
		return false;
	}
	cdReal separation = gap / cdSqrt(length2);
	if (separation > e->separation)
	{
		e->separation = separation;
		cdReal components[3] = {CD_R(0.0), CD_R(0.0), CD_R(0.0)};
		components[(i + 1) % 3] = -ri2j;
		components[(i + 2) % 3] = ri1j;
		cd3Vec axis = cd3Normalize(cd3MakeVec(components[0], components[1], components[2]));
		e->axis = centre < CD_R(0.0) ? cd3Neg(axis) : axis;
		e->i = i;
		e->j = j;
	}
	return e->separation > exitSeparation;
}

#if !CD_DOUBLE && defined(__SSE2__)
#include <emmintrin.h>
#define CD3_BOX_FACES_SSE 1
#else
#define CD3_BOX_FACES_SSE 0
#endif

/* B's frame in A's and the six face separations of two boxes, four lanes at a time (lane 3
 * unused), in the SSE2 float build (elsewhere only declared: the SAT computes them itself). Every
 * lane is the scalar code's operations in its order (cd3MakeMatFromQuat, the face separations of
 * cd3SatBoxesInPlace, |x| as cdMax(x, -x)), so every value is the same bits. */
typedef struct cd3BoxFaces cd3BoxFaces;

#if CD3_BOX_FACES_SSE
struct cd3BoxFaces
{
	float column[3][4]; /* column[j][i]: B's axis j on A's axis i (the rotation's columns) */
	float row[3][4];	/* row[i][j]: the same entries by rows (lane 3 unused) */
	float faceA[4];		/* separation along A's axis i */
	float offsetB[4];	/* the centre offset on B's axis j */
	float faceB[4];		/* separation along B's axis j */
};

/* cdMax(x, -x) in each lane (maxps returns its second operand unless the first is greater). */
static inline __m128 cd3BoxAbs4(__m128 x)
{
	return _mm_max_ps(x, _mm_xor_ps(x, _mm_set1_ps(-0.0f)));
}

/* Fills *f for box A unrotated at the origin with half extents ha and box B with half extents
 * hb, rotated by q and centred at t (A's frame). True when a face axis puts them apart by more
 * than `limit` (no separation is then a NaN): the answer cd3SatBoxesInPlace gives with faceExit
 * = limit is then apart beyond the limit. With onlyIfNear, *f is left unwritten when true is
 * returned (a caller that then stops saves the stores). */
static inline bool cd3ComputeBoxFaces(cd3BoxFaces* f, cd3Vec ha, cd3Vec hb, cd3Quat rotation, cd3Vec t,
									  float limit, bool onlyIfNear)
{
	/* Lanes x, y, z, w; the comments name the lanes low to high. */
	__m128 q = _mm_setr_ps(rotation.x, rotation.y, rotation.z, rotation.w);
	__m128 q2 = _mm_add_ps(q, q); /* x2 y2 z2 w2 */
	/* The diagonal: 1 - (yy + zz), 1 - (xx + zz), 1 - (xx + yy). */
	__m128 first = _mm_mul_ps(_mm_shuffle_ps(q, q, _MM_SHUFFLE(3, 0, 0, 1)),
							  _mm_shuffle_ps(q2, q2, _MM_SHUFFLE(3, 0, 0, 1))); /* yy xx xx */
	__m128 second = _mm_mul_ps(_mm_shuffle_ps(q, q, _MM_SHUFFLE(3, 1, 2, 2)),
							   _mm_shuffle_ps(q2, q2, _MM_SHUFFLE(3, 1, 2, 2))); /* zz zz yy */
	__m128 diagonal = _mm_sub_ps(_mm_set1_ps(1.0f), _mm_add_ps(first, second));
	/* Off the diagonal: xy, xz, yz plus or minus wz, wy, wx. */
	__m128 products = _mm_mul_ps(_mm_shuffle_ps(q, q, _MM_SHUFFLE(3, 1, 0, 0)),
								 _mm_shuffle_ps(q2, q2, _MM_SHUFFLE(3, 2, 2, 1))); /* xy xz yz */
	__m128 w = _mm_mul_ps(_mm_shuffle_ps(q, q, _MM_SHUFFLE(3, 3, 3, 3)),
						  _mm_shuffle_ps(q2, q2, _MM_SHUFFLE(3, 0, 1, 2))); /* wz wy wx */
	__m128 plus = _mm_add_ps(products, w);									/* m.cx.y m.cz.x m.cy.z */
	__m128 minus = _mm_sub_ps(products, w);									/* m.cy.x m.cx.z m.cz.y */
	/* The columns (A's axes in the lanes) ... */
	__m128 c0 = _mm_shuffle_ps(_mm_shuffle_ps(diagonal, plus, _MM_SHUFFLE(0, 0, 0, 0)), minus,
							   _MM_SHUFFLE(1, 1, 2, 0)); /* d0 p0 m1 */
	__m128 c1 = _mm_shuffle_ps(_mm_shuffle_ps(minus, diagonal, _MM_SHUFFLE(1, 1, 0, 0)), plus,
							   _MM_SHUFFLE(2, 2, 2, 0)); /* m0 d1 p2 */
	__m128 c2 = _mm_shuffle_ps(_mm_shuffle_ps(plus, minus, _MM_SHUFFLE(2, 2, 1, 1)), diagonal,
							   _MM_SHUFFLE(2, 2, 2, 0)); /* p1 m2 d2 */
	/* ... and the rows (B's axes in the lanes). */
	__m128 r0 = _mm_shuffle_ps(_mm_shuffle_ps(diagonal, minus, _MM_SHUFFLE(0, 0, 0, 0)), plus,
							   _MM_SHUFFLE(1, 1, 2, 0)); /* d0 m0 p1 */
	__m128 r1 = _mm_shuffle_ps(_mm_shuffle_ps(plus, diagonal, _MM_SHUFFLE(1, 1, 0, 0)), minus,
							   _MM_SHUFFLE(2, 2, 2, 0)); /* p0 d1 m2 */
	__m128 r2 = _mm_shuffle_ps(_mm_shuffle_ps(minus, plus, _MM_SHUFFLE(2, 2, 1, 1)), diagonal,
							   _MM_SHUFFLE(2, 2, 2, 0)); /* m1 p2 d2 */
	__m128 va = _mm_setr_ps(ha.x, ha.y, ha.z, 0.0f);
	__m128 vb = _mm_setr_ps(hb.x, hb.y, hb.z, 0.0f);
	__m128 vt = _mm_setr_ps(t.x, t.y, t.z, 0.0f);
	/* A's faces: |t_i| - ha_i - (hb0 |r_i0| + hb1 |r_i1| + hb2 |r_i2|). */
	__m128 radiusB = _mm_add_ps(_mm_add_ps(_mm_mul_ps(_mm_shuffle_ps(vb, vb, 0x00), cd3BoxAbs4(c0)),
										   _mm_mul_ps(_mm_shuffle_ps(vb, vb, 0x55), cd3BoxAbs4(c1))),
								_mm_mul_ps(_mm_shuffle_ps(vb, vb, 0xaa), cd3BoxAbs4(c2)));
	__m128 faceA = _mm_sub_ps(_mm_sub_ps(cd3BoxAbs4(vt), va), radiusB);
	/* B's faces: the offset on B's axis j (cd3Dot(t, column j)), A's radius on it. */
	__m128 offsetB = _mm_add_ps(_mm_add_ps(_mm_mul_ps(_mm_shuffle_ps(vt, vt, 0x00), r0),
										   _mm_mul_ps(_mm_shuffle_ps(vt, vt, 0x55), r1)),
								_mm_mul_ps(_mm_shuffle_ps(vt, vt, 0xaa), r2));
	__m128 radiusA = _mm_add_ps(_mm_add_ps(_mm_mul_ps(_mm_shuffle_ps(va, va, 0x00), cd3BoxAbs4(r0)),
										   _mm_mul_ps(_mm_shuffle_ps(va, va, 0x55), cd3BoxAbs4(r1))),
								_mm_mul_ps(_mm_shuffle_ps(va, va, 0xaa), cd3BoxAbs4(r2)));
	__m128 faceB = _mm_sub_ps(_mm_sub_ps(cd3BoxAbs4(offsetB), vb), radiusA);
	__m128 bound = _mm_set1_ps(limit);
	int beyond = _mm_movemask_ps(_mm_or_ps(_mm_cmpgt_ps(faceA, bound), _mm_cmpgt_ps(faceB, bound)));
	int unordered = _mm_movemask_ps(_mm_cmpunord_ps(faceA, faceB));
	bool apart = (beyond & 7) != 0 && (unordered & 7) == 0;
	if (apart && onlyIfNear)
	{
		return true;
	}
	_mm_storeu_ps(f->column[0], c0);
	_mm_storeu_ps(f->column[1], c1);
	_mm_storeu_ps(f->column[2], c2);
	_mm_storeu_ps(f->row[0], r0);
	_mm_storeu_ps(f->row[1], r1);
	_mm_storeu_ps(f->row[2], r2);
	_mm_storeu_ps(f->faceA, faceA);
	_mm_storeu_ps(f->offsetB, offsetB);
	_mm_storeu_ps(f->faceB, faceB);
	return apart;
}

/* One lane per j of cd3BoxEdgeAxis's inputs for the three edge axes A_i x B_j of one i: ri1 and
 * ri2 the rows i+1 and i+2 of the rotation, a the absolute rows, radiusB from absolute row i.
 * threshold2 is the threshold's square and ahead whether the threshold is >= 0 (the same in
 * every lane, so a branch on it is the selection cd3BoxEdgeAxis makes). */
static inline __m128 cd3BoxEdgeCandidates4(__m128 ri1, __m128 ri2, __m128 ai1, __m128 ai2, __m128 ai,
										   __m128 hai1, __m128 hai2, __m128 ti1, __m128 ti2, __m128 hb1,
										   __m128 hb2, __m128 threshold2, bool ahead)
{
	/* cd3BoxEdgeAxis: ri1j * ri1j + ri2j * ri2j; radiusA ha(i+1) a(i+2)j + ha(i+2) a(i+1)j;
	 * radiusB hb(j+1) ai(j+2) + hb(j+2) ai(j+1); centre t(i+2) ri1j - t(i+1) ri2j. */
	__m128 length2 = _mm_add_ps(_mm_mul_ps(ri1, ri1), _mm_mul_ps(ri2, ri2));
	__m128 radiusA = _mm_add_ps(_mm_mul_ps(hai1, ai2), _mm_mul_ps(hai2, ai1));
	__m128 radiusB = _mm_add_ps(_mm_mul_ps(hb1, _mm_shuffle_ps(ai, ai, _MM_SHUFFLE(3, 1, 0, 2))),
								_mm_mul_ps(hb2, _mm_shuffle_ps(ai, ai, _MM_SHUFFLE(3, 0, 2, 1))));
	__m128 centre = _mm_sub_ps(_mm_mul_ps(ti2, ri1), _mm_mul_ps(ti1, ri2));
	__m128 gap = _mm_sub_ps(_mm_sub_ps(cd3BoxAbs4(centre), radiusA), radiusB);
	__m128 bar = _mm_mul_ps(threshold2, length2);
	__m128 gap2 = _mm_mul_ps(gap, gap);
	__m128 zero = _mm_setzero_ps();
	__m128 beats = ahead ? _mm_and_ps(_mm_cmpgt_ps(gap, zero), _mm_cmpgt_ps(gap2, bar))
						 : _mm_or_ps(_mm_cmpge_ps(gap, zero), _mm_cmplt_ps(gap2, bar));
	__m128 explicitRadius =
		_mm_cmplt_ps(length2, _mm_set1_ps(CD3_BOX_EXPLICIT_RADIUS_SINE * CD3_BOX_EXPLICIT_RADIUS_SINE));
	__m128 notParallel = _mm_cmpgt_ps(length2, _mm_set1_ps(CD3_BOX_PARALLEL_SINE * CD3_BOX_PARALLEL_SINE));
	return _mm_and_ps(notParallel, _mm_or_ps(beats, explicitRadius));
}

/* The edge axes that cd3BoxEdgeAxis may take, bit 3 i + j for A_i x B_j: the others are parallel,
 * or do not beat faceBest (then they beat no larger threshold either: the test on squares is
 * monotone in the threshold, rounding included), and cd3BoxEdgeAxis would return false on them
 * without a change, whatever the best edge so far. The same operations on the same values as
 * cd3BoxEdgeAxis in each lane, so the same decisions. */
static inline unsigned cd3BoxEdgeCandidates(const cd3BoxFaces* f, cd3Vec ha, cd3Vec hb, cd3Vec t,
											cdReal faceBest)
{
	__m128 r0 = _mm_loadu_ps(f->row[0]), r1 = _mm_loadu_ps(f->row[1]), r2 = _mm_loadu_ps(f->row[2]);
	__m128 a0 = cd3BoxAbs4(r0), a1 = cd3BoxAbs4(r1), a2 = cd3BoxAbs4(r2);
	__m128 ha0 = _mm_set1_ps(ha.x), ha1 = _mm_set1_ps(ha.y), ha2 = _mm_set1_ps(ha.z);
	__m128 t0 = _mm_set1_ps(t.x), t1 = _mm_set1_ps(t.y), t2 = _mm_set1_ps(t.z);
	__m128 hb1 = _mm_setr_ps(hb.y, hb.z, hb.x, 0.0f), hb2 = _mm_setr_ps(hb.z, hb.x, hb.y, 0.0f);
	/* cd3BoxEdgeAxis's threshold is faceBest for the first axis (the best edge is -CD_REAL_MAX). */
	__m128 threshold2 = _mm_set1_ps(faceBest * faceBest);
	bool ahead = faceBest >= CD_R(0.0);
	unsigned m0 = (unsigned)_mm_movemask_ps(
		cd3BoxEdgeCandidates4(r1, r2, a1, a2, a0, ha1, ha2, t1, t2, hb1, hb2, threshold2, ahead));
	unsigned m1 = (unsigned)_mm_movemask_ps(
		cd3BoxEdgeCandidates4(r2, r0, a2, a0, a1, ha2, ha0, t2, t0, hb1, hb2, threshold2, ahead));
	unsigned m2 = (unsigned)_mm_movemask_ps(
		cd3BoxEdgeCandidates4(r0, r1, a0, a1, a2, ha0, ha1, t0, t1, hb1, hb2, threshold2, ahead));
	return (m0 & 7u) | (m1 & 7u) << 3 | (m2 & 7u) << 6;
}
#endif

/* cd3SatBoxes writing into *result, inline: the box-box manifold reads the result at once, and
 * a result returned through memory stalls on store forwarding. The matrix entries are named
 * scalars, not arrays: arrays filled a float at a time and read back two at a time by the
 * vectorizer stalled on store forwarding too. With the best face separation above faceExit the
 * edge axes are skipped (edgeSeparation -CD_REAL_MAX, no edges), and the edge axes stop at the first
 * one beyond faceExit (edgeSeparation is then that axis's, above faceExit, not the largest): pass
 * CD_REAL_MAX for every axis. */
static inline void cd3SatBoxesInPlace(const cd3Box* boxA, const cd3Box* boxB, cd3SatResult* result,
									  cd3Mat33* rotation, cd3Vec* translation, cdReal faceExit,
									  const cd3BoxFaces* faces)
{
	cd3Quat qa = boxA->rotation;
	/* A box in its body's frame usually has the identity rotation: conj(qa) q and the rotated
	 * offset are then q and the offset themselves (up to the sign of a zero), without the products. */
	bool identityA = cd3IsIdentityQuatBits(qa);
	cd3Quat q = boxB->rotation; /* B's axes in A's frame */
	cd3Vec t = cd3Sub(boxB->center, boxA->center);
	if (!identityA)
	{
		q = cd3InvMulQuat(qa, q);
		t = cd3InvRotateVector(qa, t);
	}
	cdReal ha0 = boxA->halfExtents.x, ha1 = boxA->halfExtents.y, ha2 = boxA->halfExtents.z;
	cdReal hb0 = boxB->halfExtents.x, hb1 = boxB->halfExtents.y, hb2 = boxB->halfExtents.z;
#if CD3_BOX_FACES_SSE
	/* The matrix and the face separations four lanes at a time (the same bits), or as the caller
	 * computed them already for these boxes (cd3CollideBoxBoxLocal). */
	cd3BoxFaces computed;
	if (faces == NULL)
	{
		(void)cd3ComputeBoxFaces(&computed, boxA->halfExtents, boxB->halfExtents, q, t, faceExit, false);
		faces = &computed;
	}
	cd3Mat33 m;
	m.cx = cd3MakeVec(faces->column[0][0], faces->column[0][1], faces->column[0][2]);
	m.cy = cd3MakeVec(faces->column[1][0], faces->column[1][1], faces->column[1][2]);
	m.cz = cd3MakeVec(faces->column[2][0], faces->column[2][1], faces->column[2][2]);
#else
	(void)faces;
	cd3Mat33 m = cd3MakeMatFromQuat(q);
#endif
	*rotation = m;
	*translation = t;
	/* rij = A's axis i . B's axis j, aij = |rij| */
	cdReal r00 = m.cx.x, r10 = m.cx.y, r20 = m.cx.z;
	cdReal r01 = m.cy.x, r11 = m.cy.y, r21 = m.cy.z;
	cdReal r02 = m.cz.x, r12 = m.cz.y, r22 = m.cz.z;
#if CD3_BOX_FACES_SSE
	/* |rij| where an edge axis the screening kept needs it (the face separations came in lanes). */
#define CD3_BOX_ABS(ij) cd3AbsNoBranch(r##ij)
#else
	cdReal a00 = cd3AbsNoBranch(r00), a10 = cd3AbsNoBranch(r10), a20 = cd3AbsNoBranch(r20);
	cdReal a01 = cd3AbsNoBranch(r01), a11 = cd3AbsNoBranch(r11), a21 = cd3AbsNoBranch(r21);
	cdReal a02 = cd3AbsNoBranch(r02), a12 = cd3AbsNoBranch(r12), a22 = cd3AbsNoBranch(r22);
#define CD3_BOX_ABS(ij) a##ij
#endif
	cdReal t0 = t.x, t1 = t.y, t2 = t.z;

	cd3SatResult r;
	/* A's faces: B's radius on A's axis i. */
	/* Named scalars and selects, not arrays indexed by the best axis: the indexed load waited on
	 * the stores of the array (store forwarding) just before the exit test. */
#if CD3_BOX_FACES_SSE
	cdReal fa0 = faces->faceA[0], fa1 = faces->faceA[1], fa2 = faces->faceA[2];
#else
	cdReal fa0 = cd3AbsNoBranch(t0) - ha0 - (hb0 * a00 + hb1 * a01 + hb2 * a02);
	cdReal fa1 = cd3AbsNoBranch(t1) - ha1 - (hb0 * a10 + hb1 * a11 + hb2 * a12);
	cdReal fa2 = cd3AbsNoBranch(t2) - ha2 - (hb0 * a20 + hb1 * a21 + hb2 * a22);
#endif
	int bestA = fa1 > fa0 ? 1 : 0;
	cdReal sepA = fa1 > fa0 ? fa1 : fa0;
	bestA = fa2 > sepA ? 2 : bestA;
	sepA = fa2 > sepA ? fa2 : sepA;
	cdReal tBestA = bestA == 0 ? t0 : (bestA == 1 ? t1 : t2);
	r.faceSeparationA = sepA;
	r.faceA = 2 * bestA + (tBestA > CD_R(0.0) ? 1 : 0);
	if (r.faceSeparationA > faceExit)
	{
		/* Apart beyond the caller's limit along one of A's face normals: B's faces and the edges
		 * are skipped (faceSeparationB and edgeSeparation -CD_REAL_MAX). */
		r.faceSeparationB = -CD_REAL_MAX;
		r.faceB = 0;
		r.edgeSeparation = -CD_REAL_MAX;
		r.edgeA = -1;
		r.edgeB = -1;
		r.edgeNormal = cd3MakeVec(CD_R(0.0), CD_R(0.0), CD_R(0.0));
		*result = r;
		return;
	}
	/* B's faces: the centre offset on B's axis j, A's radius on it. */
#if CD3_BOX_FACES_SSE
	cdReal tb0 = faces->offsetB[0], tb1 = faces->offsetB[1], tb2 = faces->offsetB[2];
	cdReal fb0 = faces->faceB[0], fb1 = faces->faceB[1], fb2 = faces->faceB[2];
#else
	cdReal tb0 = cd3Dot(t, m.cx), tb1 = cd3Dot(t, m.cy), tb2 = cd3Dot(t, m.cz);
	cdReal fb0 = cd3AbsNoBranch(tb0) - hb0 - (ha0 * a00 + ha1 * a10 + ha2 * a20);
	cdReal fb1 = cd3AbsNoBranch(tb1) - hb1 - (ha0 * a01 + ha1 * a11 + ha2 * a21);
	cdReal fb2 = cd3AbsNoBranch(tb2) - hb2 - (ha0 * a02 + ha1 * a12 + ha2 * a22);
#endif
	int bestB = fb1 > fb0 ? 1 : 0;
	cdReal sepB = fb1 > fb0 ? fb1 : fb0;
	bestB = fb2 > sepB ? 2 : bestB;
	sepB = fb2 > sepB ? fb2 : sepB;
	cdReal tBestB = bestB == 0 ? tb0 : (bestB == 1 ? tb1 : tb2);
	r.faceSeparationB = sepB;
	/* B's face toward A: A lies on B's negative side when tB > 0. */
	r.faceB = 2 * bestB + (tBestB > CD_R(0.0) ? 0 : 1);

	cdReal faceBest = cdMax(r.faceSeparationA, r.faceSeparationB);
	if (faceBest > faceExit)
	{
		/* Apart by more than the caller's limit along a face normal: the edge axes can only make
		 * the separation larger, so they are skipped (half of a broadphase's pairs end here). */
		r.edgeSeparation = -CD_REAL_MAX;
		r.edgeA = -1;
		r.edgeB = -1;
		r.edgeNormal = cd3MakeVec(CD_R(0.0), CD_R(0.0), CD_R(0.0));
		*result = r;
		return;
	}
	cd3BoxEdgeBest e;
	e.separation = -CD_REAL_MAX;
	e.axis = cd3MakeVec(CD_R(0.0), CD_R(0.0), CD_R(0.0));
	e.i = e.j = 0;
	/* The edge axes in turn, stopping at the first one that puts the boxes
	 * beyond faceExit (the answer is then empty whatever the other axes give). */
	cd3Vec hb = boxB->halfExtents;
#if CD3_BOX_FACES_SSE
	unsigned candidates = cd3BoxEdgeCandidates(faces, boxA->halfExtents, hb, t, faceBest);
#define CD3_BOX_EDGE_CANDIDATE(k) ((candidates >> (k)) & 1u)
#else
#define CD3_BOX_EDGE_CANDIDATE(k) 1u
#endif
	bool apart = (CD3_BOX_EDGE_CANDIDATE(0) &&
				  cd3BoxEdgeAxis(&e, 0, 0, r10, r20, ha1 * CD3_BOX_ABS(20) + ha2 * CD3_BOX_ABS(10),
								 hb1 * CD3_BOX_ABS(02) + hb2 * CD3_BOX_ABS(01), t2 * r10 - t1 * r20, faceBest,
								 faceExit, &m, hb)) ||
				 (CD3_BOX_EDGE_CANDIDATE(1) &&
				  cd3BoxEdgeAxis(&e, 0, 1, r11, r21, ha1 * CD3_BOX_ABS(21) + ha2 * CD3_BOX_ABS(11),
								 hb2 * CD3_BOX_ABS(00) + hb0 * CD3_BOX_ABS(02), t2 * r11 - t1 * r21, faceBest,
								 faceExit, &m, hb)) ||
				 (CD3_BOX_EDGE_CANDIDATE(2) &&
				  cd3BoxEdgeAxis(&e, 0, 2, r12, r22, ha1 * CD3_BOX_ABS(22) + ha2 * CD3_BOX_ABS(12),
								 hb0 * CD3_BOX_ABS(01) + hb1 * CD3_BOX_ABS(00), t2 * r12 - t1 * r22, faceBest,
								 faceExit, &m, hb)) ||
				 (CD3_BOX_EDGE_CANDIDATE(3) &&
				  cd3BoxEdgeAxis(&e, 1, 0, r20, r00, ha2 * CD3_BOX_ABS(00) + ha0 * CD3_BOX_ABS(20),
								 hb1 * CD3_BOX_ABS(12) + hb2 * CD3_BOX_ABS(11), t0 * r20 - t2 * r00, faceBest,
								 faceExit, &m, hb)) ||
				 (CD3_BOX_EDGE_CANDIDATE(4) &&
				  cd3BoxEdgeAxis(&e, 1, 1, r21, r01, ha2 * CD3_BOX_ABS(01) + ha0 * CD3_BOX_ABS(21),
								 hb2 * CD3_BOX_ABS(10) + hb0 * CD3_BOX_ABS(12), t0 * r21 - t2 * r01, faceBest,
								 faceExit, &m, hb)) ||
				 (CD3_BOX_EDGE_CANDIDATE(5) &&
				  cd3BoxEdgeAxis(&e, 1, 2, r22, r02, ha2 * CD3_BOX_ABS(02) + ha0 * CD3_BOX_ABS(22),
								 hb0 * CD3_BOX_ABS(11) + hb1 * CD3_BOX_ABS(10), t0 * r22 - t2 * r02, faceBest,
								 faceExit, &m, hb)) ||
				 (CD3_BOX_EDGE_CANDIDATE(6) &&
				  cd3BoxEdgeAxis(&e, 2, 0, r00, r10, ha0 * CD3_BOX_ABS(10) + ha1 * CD3_BOX_ABS(00),
								 hb1 * CD3_BOX_ABS(22) + hb2 * CD3_BOX_ABS(21), t1 * r00 - t0 * r10, faceBest,
								 faceExit, &m, hb)) ||
				 (CD3_BOX_EDGE_CANDIDATE(7) &&
				  cd3BoxEdgeAxis(&e, 2, 1, r01, r11, ha0 * CD3_BOX_ABS(11) + ha1 * CD3_BOX_ABS(01),
								 hb2 * CD3_BOX_ABS(20) + hb0 * CD3_BOX_ABS(22), t1 * r01 - t0 * r11, faceBest,
								 faceExit, &m, hb)) ||
				 (CD3_BOX_EDGE_CANDIDATE(8) &&
				  cd3BoxEdgeAxis(&e, 2, 2, r02, r12, ha0 * CD3_BOX_ABS(12) + ha1 * CD3_BOX_ABS(02),
								 hb0 * CD3_BOX_ABS(21) + hb1 * CD3_BOX_ABS(20), t1 * r02 - t0 * r12, faceBest,
								 faceExit, &m, hb));
#undef CD3_BOX_EDGE_CANDIDATE
#undef CD3_BOX_ABS
	(void)apart;
	r.edgeSeparation = e.separation;
	r.edgeA = -1;
	r.edgeB = -1;
	if (e.separation > -CD_REAL_MAX)
	{
		r.edgeA = cd3SupportingBoxEdge(e.i, e.axis);
		cd3Vec inB = {-cd3Dot(e.axis, m.cx), -cd3Dot(e.axis, m.cy), -cd3Dot(e.axis, m.cz)};
		r.edgeB = cd3SupportingBoxEdge(e.j, inB);
	}
	r.edgeNormal = identityA ? e.axis : cd3RotateVector(qa, e.axis);
	*result = r;
}

#endif
