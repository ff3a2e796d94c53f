/* Internal: 2D shapes as GJK sees them. Every shape is the convex hull of at most
 * CD2_MAX_POLYGON_VERTICES "core" points grown by a radius (a circle is a point, a capsule a
 * segment, a box its four corners, a rounded polygon its vertices and rounding radius). */
#ifndef COLLIDE_SUPPORT2_H
#define COLLIDE_SUPPORT2_H

#include "collide/geometry2.h"
#include "collide/query2.h"
#include "pairs2.h"
#include "sat2_separation.h"

#define CD2_CORE_MAX_POINTS CD2_MAX_POLYGON_VERTICES

typedef struct cd2Core
{
	const cd2Vec* points; /* a polygon's own vertices, or storage */
	cd2Vec storage[4];
	int count;
	cdReal radius;
} cd2Core;

/* The shape table's support columns (pairs2.h: MakeCore and Radius, one row per shape). Each
 * MakeCore(shape, core) fills the core's points and count from the tagged shape (read through the
 * pointer, as the hand-written switch did: a by-value member made GCC copy it first); the radius
 * comes from the Radius column. */
#define CD2_CIRCLE_RADIUS(s) ((s)->circle.radius)
#define CD2_CAPSULE_RADIUS(s) ((s)->capsule.radius)
#define CD2_POLYGON_RADIUS(s) ((s)->polygon.radius)

static inline bool cd2MakeCircleCore(const cd2Shape* shape, cd2Core* core)
{
	core->storage[0] = shape->circle.center;
	core->count = 1;
	return true;
}

static inline bool cd2MakeCapsuleCore(const cd2Shape* shape, cd2Core* core)
{
	core->storage[0] = shape->capsule.p1;
	core->storage[1] = shape->capsule.p2;
	core->count = 2;
	return true;
}

static inline bool cd2MakeAabbCore(const cd2Shape* shape, cd2Core* core)
{
	cd2Vec lo = shape->aabb.min, hi = shape->aabb.max;
	core->storage[0] = lo;
	core->storage[1] = cd2MakeVec(hi.x, lo.y);
	core->storage[2] = hi;
	core->storage[3] = cd2MakeVec(lo.x, hi.y);
	core->count = 4;
	return true;
}

static inline bool cd2MakeBoxCore(const cd2Shape* shape, cd2Core* core)
{
	const cd2Box* box = &shape->box;
	cd2Vec axisX = cd2RotateVector(box->rotation, cd2MakeVec(box->halfExtents.x, CD_R(0.0)));
	cd2Vec axisY = cd2RotateVector(box->rotation, cd2MakeVec(CD_R(0.0), box->halfExtents.y));
	core->storage[0] = cd2Sub(cd2Sub(box->center, axisX), axisY);
	core->storage[1] = cd2Sub(cd2Add(box->center, axisX), axisY);
	core->storage[2] = cd2Add(cd2Add(box->center, axisX), axisY);
	core->storage[3] = cd2Add(cd2Sub(box->center, axisX), axisY);
	core->count = 4;
	return true;
}

/* Points into the polygon: the shape must outlive the core. */
static inline bool cd2MakePolygonCore(const cd2Shape* shape, cd2Core* core)
{
	int count = cdMinInt(shape->polygon.count, CD2_CORE_MAX_POINTS);
	core->points = shape->polygon.vertices;
	core->count = count;
	return count > 0;
}

static inline bool cd2MakeSegmentCore(const cd2Shape* shape, cd2Core* core)
{
	core->storage[0] = shape->segment.p1;
	core->storage[1] = shape->segment.p2;
	core->count = 2;
	return true;
}

/* Fills *core from the shape table (pointing into the shape for a polygon: the shape must outlive
 * it); returns false for an unknown type or an empty polygon. */
static inline bool cd2MakeCore(const cd2Shape* shape, cd2Core* core)
{
	core->radius = CD_R(0.0);
	core->count = 0;
	core->points = core->storage;
	switch (shape->type)
	{
#define CD2_CORE_RADIUS(Radius) core->radius = Radius(shape);
#define CD2_CORE_CASE(Name, PointIn, ClosestPointOn, Raycast, TypeName, Validate, ComputeAabb, ComputeMass,  \
					  MakeCore, Radius)                                                                      \
	case CD2_TYPE_##Name:                                                                                    \
	{                                                                                                        \
		bool made = MakeCore(shape, core);                                                                   \
		CD_SHAPE_HAS(Radius, CD2_CORE_RADIUS)(Radius) return made;                                           \
	}
		CD2_SHAPE_TABLE(CD2_CORE_CASE)
#undef CD2_CORE_CASE
#undef CD2_CORE_RADIUS
		default:
			return false;
	}
}

/* A point of the core's hull near its middle (halfway between its first point and the one
 * half-way round): GJK's cold start looks for supports along the line between two of them. */
static inline cd2Vec cd2CoreCenter(const cd2Core* core)
{
	return cd2Lerp(core->points[0], core->points[core->count / 2], CD_R(0.5));
}

/* Largest |coordinate| without a branch per coordinate (max(x, -x) is a max instruction; a
 * branchy absolute value mispredicts in GJK's hot loops, whose signs are as good as random). */
static inline cdReal cd2MaxAbs(cd2Vec v)
{
	return cdMax(cdMax(v.x, -v.x), cdMax(v.y, -v.y));
}

/* Index of the core point farthest along `direction` (the first one on ties). */
static inline int cd2CoreSupport(const cd2Core* core, cd2Vec direction)
{
	int best = 0;
	cdReal bestValue = cd2Dot(core->points[0], direction);
	for (int i = 1; i < core->count; ++i)
	{
		cdReal value = cd2Dot(core->points[i], direction);
		if (value > bestValue)
		{
			best = i;
			bestValue = value;
		}
	}
	return best;
}

/* cd2CoreSupport with the larger value kept by a select instead of a branch per point: which
 * point wins is as random as the direction, so a compare-and-branch per point (or a hill climb,
 * whose step count is as random) mispredicts in GJK's loop. The same index as cd2CoreSupport, the
 * first one on ties. */
static inline int cd2CoreSupportSelect(const cd2Core* core, cd2Vec direction)
{
	int best = 0;
	cdReal bestValue = cd2Dot(core->points[0], direction);
	for (int i = 1; i < core->count; ++i)
	{
		cdReal value = cd2Dot(core->points[i], direction);
		bool higher = value > bestValue;
		best = higher ? i : best;
		bestValue = higher ? value : bestValue;
	}
	return best;
}

/* cd2CoreSupportSelect without a loop: in the float build on SSE2 (or WebAssembly SIMD128) the
 * dot products of four points at a time in the lanes of a vector, the maximum by shuffles and the
 * first lane that equals it by a bit mask, so that no branch depends on the count or on which
 * point wins (the loop's exit and its selects mispredicted about two branches per GJK support
 * on collide_bench_scenes' polygon pairs of 3 to 8 vertices). Lanes past the count repeat point
 * 0, which never beats point 0 under the first-maximum rule. Each dot product is cd2Dot's (x
 * products summed), so the index is cd2CoreSupportSelect's bit for bit, NaN directions included
 * (point 0). Elsewhere the scalar scan. */
static inline int cd2CoreSupportLanes(const cd2Core* core, cd2Vec direction)
{
#if CD2_SEPARATION_SSE || CD2_SEPARATION_WASM
	int count = core->count;
	CD_ASSERT(count >= 1 && count <= CD2_CORE_MAX_POINTS);
	const cd2Vec* p = core->points;
	int i1 = count > 1 ? 1 : 0, i2 = count > 2 ? 2 : 0, i3 = count > 3 ? 3 : 0;
#if !defined(__GNUC__) && !defined(__clang__)
	static const int8_t FIRST_LANE[16] = {0, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0};
#endif
#if CD2_SEPARATION_SSE
	__m128 dx = _mm_set1_ps(direction.x), dy = _mm_set1_ps(direction.y);
	__m128 x, y;
	cd2SeparationLoad4(p, 0, i1, i2, i3, &x, &y);
	__m128 low = _mm_add_ps(_mm_mul_ps(x, dx), _mm_mul_ps(y, dy));
	__m128 high = low;
	if (count > 4)
	{
		int i5 = count > 5 ? 5 : 0, i6 = count > 6 ? 6 : 0, i7 = count > 7 ? 7 : 0;
		cd2SeparationLoad4(p, 4, i5, i6, i7, &x, &y);
		high = _mm_add_ps(_mm_mul_ps(x, dx), _mm_mul_ps(y, dy));
	}
	__m128 top = _mm_max_ps(low, high);
	top = _mm_max_ps(top, _mm_shuffle_ps(top, top, _MM_SHUFFLE(1, 0, 3, 2)));
	top = _mm_max_ps(top, _mm_shuffle_ps(top, top, _MM_SHUFFLE(2, 3, 0, 1)));
	int lanes = _mm_movemask_ps(_mm_cmpeq_ps(low, top)) | _mm_movemask_ps(_mm_cmpeq_ps(high, top)) << 4;
#else
	v128_t dx = wasm_f32x4_splat(direction.x), dy = wasm_f32x4_splat(direction.y);
	v128_t x, y;
	cd2SeparationLoad4Wasm(p, 0, i1, i2, i3, &x, &y);
	v128_t low = wasm_f32x4_add(wasm_f32x4_mul(x, dx), wasm_f32x4_mul(y, dy));
	v128_t high = low;
	if (count > 4)
	{
		int i5 = count > 5 ? 5 : 0, i6 = count > 6 ? 6 : 0, i7 = count > 7 ? 7 : 0;
		cd2SeparationLoad4Wasm(p, 4, i5, i6, i7, &x, &y);
		high = wasm_f32x4_add(wasm_f32x4_mul(x, dx), wasm_f32x4_mul(y, dy));
	}
	v128_t top = wasm_f32x4_pmax(high, low);
	top = wasm_f32x4_pmax(wasm_i32x4_shuffle(top, top, 2, 3, 0, 1), top);
	top = wasm_f32x4_pmax(wasm_i32x4_shuffle(top, top, 1, 0, 3, 2), top);
	int lanes = (int)(wasm_i32x4_bitmask(wasm_f32x4_eq(low, top)) |
					  wasm_i32x4_bitmask(wasm_f32x4_eq(high, top)) << 4);
#endif
	/* The lowest set bit; none (a NaN maximum matches no lane) gives bit 8, and so point 0 as the
	 * scan. Without a branch on which half holds it. */
#if defined(__GNUC__) || defined(__clang__)
	return __builtin_ctz((unsigned)lanes | 0x100u) & 7;
#else
	return (lanes & 15) != 0 ? FIRST_LANE[lanes & 15] : (lanes != 0 ? 4 + FIRST_LANE[lanes >> 4] : 0);
#endif
#else
	return cd2CoreSupportSelect(core, direction);
#endif
}

/* max over the core's points of dot(p, direction): the largest lane of cd2CoreSupportLanes's dot
 * products (each cd2Dot's, so the value of its support point bit for bit, up to the sign of a
 * zero), without going back from the index to the point, which made a chain of dependent steps
 * (the index, the load, the dot product) at every step of a time of impact. Elsewhere the scan. */
static inline cdReal cd2CoreSupportValueLanes(const cd2Core* core, cd2Vec direction)
{
#if CD2_SEPARATION_SSE
	int count = core->count;
	CD_ASSERT(count >= 1 && count <= CD2_CORE_MAX_POINTS);
	const cd2Vec* p = core->points;
	int i1 = count > 1 ? 1 : 0, i2 = count > 2 ? 2 : 0, i3 = count > 3 ? 3 : 0;
	int i4 = count > 4 ? 4 : 0, i5 = count > 5 ? 5 : 0, i6 = count > 6 ? 6 : 0, i7 = count > 7 ? 7 : 0;
	__m128 dx = _mm_set1_ps(direction.x), dy = _mm_set1_ps(direction.y);
	__m128 x, y;
	cd2SeparationLoad4(p, 0, i1, i2, i3, &x, &y);
	__m128 low = _mm_add_ps(_mm_mul_ps(x, dx), _mm_mul_ps(y, dy));
	cd2SeparationLoad4(p, i4, i5, i6, i7, &x, &y);
	__m128 high = _mm_add_ps(_mm_mul_ps(x, dx), _mm_mul_ps(y, dy));
	__m128 top = _mm_max_ps(low, high);
	top = _mm_max_ps(top, _mm_shuffle_ps(top, top, _MM_SHUFFLE(1, 0, 3, 2)));
	top = _mm_max_ps(top, _mm_shuffle_ps(top, top, _MM_SHUFFLE(2, 3, 0, 1)));
	return _mm_cvtss_f32(top);
#else
	return cd2Dot(core->points[cd2CoreSupportLanes(core, direction)], direction);
#endif
}

/* A core's points held in vector lanes for the whole of a GJK call (float build on SSE2): x and y
 * of points 0-3 and 4-7, lanes past the count repeating point 0, so that each support is the dot
 * products and the first maximum of cd2CoreSupportLanes without reloading and reshuffling the
 * points (GJK takes three or four supports per shape and call). cd2CoreLanesSupport gives
 * cd2CoreSupportLanes's index bit for bit. Elsewhere a pointer to the core and its support. */
#if CD2_SEPARATION_SSE
typedef struct cd2CoreLanes
{
	__m128 x0, y0, x1, y1;
} cd2CoreLanes;

static inline void cd2MakeCoreLanes(const cd2Core* core, cd2CoreLanes* lanes)
{
	int count = core->count;
	CD_ASSERT(count >= 1 && count <= CD2_CORE_MAX_POINTS);
	const cd2Vec* p = core->points;
	int i1 = count > 1 ? 1 : 0, i2 = count > 2 ? 2 : 0, i3 = count > 3 ? 3 : 0;
	int i4 = count > 4 ? 4 : 0, i5 = count > 5 ? 5 : 0, i6 = count > 6 ? 6 : 0, i7 = count > 7 ? 7 : 0;
	cd2SeparationLoad4(p, 0, i1, i2, i3, &lanes->x0, &lanes->y0);
	cd2SeparationLoad4(p, i4, i5, i6, i7, &lanes->x1, &lanes->y1);
}

/* The lanes of a body-frame core placed by xf (each lane as cd2TransformPoint: the rotated point
 * plus the translation, in that order), and the placed points themselves, stored whole vectors at
 * a time (placed: room for CD2_CORE_MAX_POINTS points) so that reading one back is forwarded from
 * the store. */
static inline void cd2MakePlacedCoreLanes(const cd2Core* local, cd2Transform xf, cd2Vec* placed,
										  cd2CoreLanes* lanes)
{
	cd2CoreLanes l;
	cd2MakeCoreLanes(local, &l);
	__m128 c = _mm_set1_ps(xf.q.c), s = _mm_set1_ps(xf.q.s);
	__m128 px = _mm_set1_ps(xf.p.x), py = _mm_set1_ps(xf.p.y);
	lanes->x0 = _mm_add_ps(_mm_sub_ps(_mm_mul_ps(c, l.x0), _mm_mul_ps(s, l.y0)), px);
	lanes->y0 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(s, l.x0), _mm_mul_ps(c, l.y0)), py);
	lanes->x1 = _mm_add_ps(_mm_sub_ps(_mm_mul_ps(c, l.x1), _mm_mul_ps(s, l.y1)), px);
	lanes->y1 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(s, l.x1), _mm_mul_ps(c, l.y1)), py);
	float* out = (float*)(void*)placed;
	_mm_storeu_ps(out, _mm_unpacklo_ps(lanes->x0, lanes->y0));
	_mm_storeu_ps(out + 4, _mm_unpackhi_ps(lanes->x0, lanes->y0));
	_mm_storeu_ps(out + 8, _mm_unpacklo_ps(lanes->x1, lanes->y1));
	_mm_storeu_ps(out + 12, _mm_unpackhi_ps(lanes->x1, lanes->y1));
}

static inline int cd2CoreLanesSupport(const cd2CoreLanes* lanes, cd2Vec direction)
{
	__m128 dx = _mm_set1_ps(direction.x), dy = _mm_set1_ps(direction.y);
	__m128 low = _mm_add_ps(_mm_mul_ps(lanes->x0, dx), _mm_mul_ps(lanes->y0, dy));
	__m128 high = _mm_add_ps(_mm_mul_ps(lanes->x1, dx), _mm_mul_ps(lanes->y1, dy));
	__m128 top = _mm_max_ps(low, high);
	top = _mm_max_ps(top, _mm_shuffle_ps(top, top, _MM_SHUFFLE(1, 0, 3, 2)));
	top = _mm_max_ps(top, _mm_shuffle_ps(top, top, _MM_SHUFFLE(2, 3, 0, 1)));
	int lanesEqual = _mm_movemask_ps(_mm_cmpeq_ps(low, top)) | _mm_movemask_ps(_mm_cmpeq_ps(high, top)) << 4;
#if defined(__GNUC__) || defined(__clang__)
	return __builtin_ctz((unsigned)lanesEqual | 0x100u) & 7;
#else
	static const int8_t FIRST_LANE[16] = {0, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0};
	return (lanesEqual & 15) != 0 ? FIRST_LANE[lanesEqual & 15]
								  : (lanesEqual != 0 ? 4 + FIRST_LANE[lanesEqual >> 4] : 0);
#endif
}
#else
typedef struct cd2CoreLanes
{
	const cd2Core* core;
} cd2CoreLanes;

static inline void cd2MakeCoreLanes(const cd2Core* core, cd2CoreLanes* lanes)
{
	lanes->core = core;
}

static inline int cd2CoreLanesSupport(const cd2CoreLanes* lanes, cd2Vec direction)
{
	return cd2CoreSupportLanes(lanes->core, direction);
}
#endif

/* Support by hill climbing from `start` along the counter-clockwise ring of core points: on a
 * convex ring the projections rise to one maximum (plateaus only at an edge perpendicular to the
 * direction, which is the top or the bottom), so a vertex neither of whose neighbours projects
 * farther is the support. Faster than the scan for larger rings when the start is close, as in
 * GJK where the previous support is (the 2D shape cast of polygons with 3-8 vertices uses it).
 * Segments and points are scanned. */
static inline int cd2CoreSupportFrom(const cd2Core* core, cd2Vec direction, int start)
{
	int count = core->count;
	if (count < 3)
	{
		return cd2CoreSupport(core, direction);
	}
	int best = start;
	cdReal bestValue = cd2Dot(core->points[best], direction);
	for (int step = 0; step < count; ++step)
	{
		int next = best + 1 < count ? best + 1 : 0;
		int previous = best > 0 ? best - 1 : count - 1;
		cdReal nextValue = cd2Dot(core->points[next], direction);
		cdReal previousValue = cd2Dot(core->points[previous], direction);
		if (nextValue > bestValue && nextValue >= previousValue)
		{
			best = next;
			bestValue = nextValue;
		}
		else if (previousValue > bestValue)
		{
			best = previous;
			bestValue = previousValue;
		}
		else
		{
			break;
		}
	}
	return best;
}

/* Squared distance from p to the polygon edge a-b and the edge's closest point, computed from the
 * edge end nearer to p: the round-off then grows with p's offset from that end (*offsetScale, its
 * largest |coordinate|), not with the coordinates, so that it compares with tolerances relative to
 * those offsets (point containment near a vertex, beyond a sharp tip). */
static inline cdReal cd2EdgeDistanceSquared(cd2Vec a, cd2Vec b, cd2Vec p, cd2Vec* closest,
											cdReal* offsetScale)
{
	cd2Vec fromA = cd2Sub(p, a), fromB = cd2Sub(p, b);
	cdReal scaleA = cdMax(cdAbs(fromA.x), cdAbs(fromA.y)), scaleB = cdMax(cdAbs(fromB.x), cdAbs(fromB.y));
	bool nearA = scaleA <= scaleB;
	cd2Vec end = nearA ? a : b;
	cd2Vec offset = nearA ? fromA : fromB;
	cd2Vec edge = nearA ? cd2Sub(b, a) : cd2Sub(a, b);
	cdReal lengthSquared = cd2Dot(edge, edge);
	cdReal along = cd2Dot(offset, edge);
	cd2Vec foot = CD2_VEC_ZERO; /* relative to end */
	/* The clamps come first so that a zero-length (or underflowing) edge never divides by 0. */
	if (along >= lengthSquared && lengthSquared > CD_R(0.0))
	{
		foot = edge;
	}
	else if (along > CD_R(0.0) && lengthSquared > CD_R(0.0))
	{
		foot = cd2Scale(along / lengthSquared, edge);
	}
	*closest = cd2Add(end, foot);
	*offsetScale = nearA ? scaleA : scaleB;
	return cd2LengthSquared(cd2Sub(offset, foot));
}

/* Closest point on a polygon's core (the vertices' hull, radius ignored), with the squared
 * distance to it (0 inside) and the round-off scale of that distance (the largest |coordinate| of
 * p's offset from the nearest edge's nearer end; 0 inside). The side of each edge line is measured
 * from the edge's end nearer to p, so that its round-off is relative to p's offset from it. A
 * point within round-off (8 epsilons of that offset) of an edge line is inside only if it is that
 * close to the boundary too: beyond a sharp vertex a point stays within round-off of both edge
 * lines however far it is (a point 157500 beyond a sliver's tip counted as inside). */
static inline cd2Vec cd2ClosestPointOnCore(const cd2Polygon* polygon, cd2Vec p, cdReal* distanceSquared,
										   cdReal* offsetScale)
{
	int count = polygon->count;
	bool inside = true, nearEdgeLine = false;
	cdReal nearTolerance = CD_REAL_MAX;
	for (int i = 0; i < count; ++i)
	{
		cd2Vec offset = cd2Sub(p, polygon->vertices[i]);
		cd2Vec offsetFromEnd = cd2Sub(p, polygon->vertices[i + 1 < count ? i + 1 : 0]);
		cdReal scale = cdMax(cdAbs(offset.x), cdAbs(offset.y));
		cdReal scaleFromEnd = cdMax(cdAbs(offsetFromEnd.x), cdAbs(offsetFromEnd.y));
		if (scaleFromEnd < scale)
		{
			offset = offsetFromEnd;
			scale = scaleFromEnd;
		}
		cdReal separation = cd2Dot(polygon->normals[i], offset);
		cdReal tolerance = CD_R(8.0) * CD_REAL_EPSILON * scale;
		inside = inside && separation <= CD_R(0.0);
		if (cdAbs(separation) <= tolerance)
		{
			nearEdgeLine = true;
			nearTolerance = cdMin(nearTolerance, tolerance);
		}
	}
	*distanceSquared = CD_R(0.0);
	*offsetScale = CD_R(0.0);
	if (inside && !nearEdgeLine)
	{
		return p;
	}
	/* Outside a convex polygon the closest point lies on its boundary. */
	cd2Vec best = polygon->vertices[0];
	cdReal bestDistanceSquared = CD_REAL_MAX, bestScale = CD_R(0.0);
	for (int i = 0; i < count; ++i)
	{
		cd2Vec candidate;
		cdReal scale;
		cdReal candidateSquared = cd2EdgeDistanceSquared(
			polygon->vertices[i], polygon->vertices[i + 1 < count ? i + 1 : 0], p, &candidate, &scale);
		if (candidateSquared < bestDistanceSquared)
		{
			best = candidate;
			bestDistanceSquared = candidateSquared;
			bestScale = scale;
		}
	}
	/* An inside point is no farther from the boundary than from any edge line. */
	cdReal limit = CD_R(2.0) * nearTolerance;
	if (inside && bestDistanceSquared <= limit * limit)
	{
		return p;
	}
	*distanceSquared = bestDistanceSquared;
	*offsetScale = bestScale;
	return best;
}

/* GJK's simplex, shared by the distance (distance2.c) and the shape cast (cast.inc). */
typedef struct cd2GjkVertex
{
	cd2Vec a, b, w; /* support points on A and B, w = a - b */
	int indexA, indexB;
} cd2GjkVertex;

typedef struct cd2GjkSimplex
{
	cd2GjkVertex v[3];
	cdReal lambda[3];
	int count;
} cd2GjkSimplex;

/* Reduces the simplex to the vertices that support its point closest to the origin and sets
 * their weights (lambda, summing to 1); true when the origin is enclosed (the shapes touch). */
bool cd2SolveGjkSimplex(cd2GjkSimplex* simplex);

/* The direction from the simplex (closest point v) towards the origin, of any length, built from
 * the simplex's edges where -v, a sum of large cancelling terms, would point off (distance2.c). */
cd2Vec cd2GjkSearchDirection(const cd2GjkSimplex* simplex, cd2Vec v);

/* GJK distance of two cores (distance2.c), radii included, warm-started from *cache and
 * updating it (cache and status may be NULL). */
cd2ClosestPoints cd2DistanceCores(const cd2Core* coreA, const cd2Core* coreB, cd2SimplexCache* cache,
								  cdDistanceStatus* status);

#endif
