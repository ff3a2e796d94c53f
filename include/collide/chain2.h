/* collide: 2D chains: polylines of one-sided segments for terrain and level geometry.
 *
 * A chain is a polyline p0, p1, ..., p(n-1) (open) or a closed loop (the last point joins the
 * first). Segment i runs from point i to point i + 1. Like every cd2ChainSegment, each segment is
 * one-sided: its free side is to the RIGHT of its direction (the side of cd2RightPerp(p(i+1) -
 * p(i))), as for a polygon's counter-clockwise boundary seen from outside. So:
 *   - a floor runs from right to left (its free side is up);
 *   - a loop around a solid island runs counter-clockwise, a loop around a room (a cave) runs
 *     clockwise.
 * Shapes behind a segment get no contact from it, and a shape sliding along the chain never
 * catches on an inner vertex (no ghost collisions): each segment knows its neighbours' far
 * vertices (the ghosts) and limits its contact normal to the directions the chain allows there.
 * The open ends of a chain have ghosts that extend the end segments straight on, so nothing
 * pokes out past an open end.
 *
 * The chain keeps a static bounding-volume hierarchy over its segments (a 4-ary tree over runs
 * of consecutive segments: a polyline's neighbours are close in space), so queries on chains of
 * many thousands of segments visit O(log n + k) nodes for the k segments they touch.
 *
 * Chains are built once (they allocate through the allocator hooks) and are read-only after
 * that: queries allocate nothing and are safe from many threads. The chain lives in its own
 * local frame; queries take the chain's transform and shapes and rays in world space. */
#ifndef COLLIDE_CHAIN2_H
#define COLLIDE_CHAIN2_H

#include "collide/manifold2.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Most points a chain holds (after welding). */
#define CD2_MAX_CHAIN_POINTS (1 << 24)

typedef struct cd2Chain cd2Chain; /* opaque */

/* Builds a chain from `count` points (copied). Consecutive points closer than the polygon weld
 * tolerance (cd2GetPolygonWeldTolerance of the largest |coordinate|) are welded into the first
 * of them; in a loop a last point that repeats the first is welded too. Fails, leaving *chain
 * untouched, with:
 *   CD_ERROR_INVALID_ARGUMENT  points or chain is NULL, or count < 0
 *   CD_ERROR_NOT_FINITE        a coordinate is NaN or infinite
 *   CD_ERROR_TOO_MANY_POINTS   count > CD2_MAX_CHAIN_POINTS
 *   CD_ERROR_DEGENERATE        fewer than 2 distinct points (3 for a loop) after welding
 *   CD_ERROR_OUT_OF_MEMORY     the allocator hook returned NULL */
CD_API cdResult cd2CreateChain(const cd2Vec* points, int count, bool isLoop, cd2Chain** chain);

/* Frees a chain (NULL is allowed). */
CD_API void cd2DestroyChain(cd2Chain* chain);

/* Checks a chain's invariants: finite points, enough points, no zero-length segment, and a
 * bounding hierarchy that encloses every segment. CD_OK for every chain cd2CreateChain made. */
CD_API cdResult cd2ValidateChain(const cd2Chain* chain);

CD_API int cd2Chain_GetSegmentCount(const cd2Chain* chain);
CD_API int cd2Chain_GetPointCount(const cd2Chain* chain);
CD_API const cd2Vec* cd2Chain_GetPoints(const cd2Chain* chain); /* local frame, after welding */
CD_API bool cd2Chain_IsLoop(const cd2Chain* chain);
CD_API cd2Aabb cd2Chain_GetBounds(const cd2Chain* chain); /* local frame */

/* Segment `index` (0 <= index < segment count) in the chain's local frame, with its ghosts: the
 * neighbours' far vertices, or at an open end the end segment extended by its own length. */
CD_API cd2ChainSegment cd2Chain_GetSegment(const cd2Chain* chain, int index);

/* Ray cast against the chain's segments, one-sided: a segment is hit only from its free side
 * (the ray moving against its normal, the origin on the free side or on the segment); rays
 * coming from behind pass through. Reports the first hit (the smallest fraction; on a tie at a
 * shared vertex the lower segment index) with the segment's unit front normal, in world space,
 * and its segment index (segmentIndex may be NULL). *hit and *segmentIndex are left untouched on
 * a miss. The chain is not solid: there is no "origin inside" case. */
CD_API bool cd2RaycastChain(const cd2Chain* chain, cd2Transform chainTransform, cd2Ray ray, cd2RayHit* hit,
							int* segmentIndex);

/* Called with each segment whose bounds overlap the query box; return false to stop the query. */
typedef bool cd2ChainQueryFcn(int segmentIndex, void* context);

/* Calls fcn for every segment whose (closed) bounding box overlaps `bounds` (world space; under
 * a rotated transform the query uses the local box that encloses it, so it may report a few
 * more segments). Segments come in increasing index order. */
CD_API void cd2Chain_QueryAabb(const cd2Chain* chain, cd2Transform chainTransform, cd2Aabb bounds,
							   cd2ChainQueryFcn* fcn, void* context);

/* Contact manifolds between the chain (shape A) and a tagged shape B in world space: one
 * manifold per segment in contact (or within speculativeDistance), each the manifold of
 * cd2CollideChainSegment{Circle,Capsule,Polygon} of that segment in world space, so the normal
 * points from the terrain to the shape. Boxes and AABBs collide as polygons, segments as
 * zero-radius capsules. Manifolds come in increasing segment index order; segmentIndices[k]
 * (may be NULL) receives the segment of manifolds[k]. A point's feature id is that of the
 * segment's manifold: (segment index, id) stays the same while the same features touch. A convex
 * vertex contact that both of its segments report is kept once, in the lower segment's manifold
 * (in a loop, segment 0's over the last segment's). Returns
 * the number of manifolds written, at most capacity (segments beyond capacity are dropped). */
CD_API int cd2CollideChain(const cd2Chain* chain, cd2Transform chainTransform, const cd2Shape* shape,
						   cdReal speculativeDistance, cd2Manifold* manifolds, int capacity,
						   int* segmentIndices);

/* Former names (before the naming rule of CONTRIBUTING.md), kept as aliases for one release so
 * that code written against them still builds; tests/check_names.py accepts exactly these. */
#define cd2GetChainSegmentCount cd2Chain_GetSegmentCount
#define cd2GetChainPointCount cd2Chain_GetPointCount
#define cd2GetChainPoints cd2Chain_GetPoints
#define cd2IsChainLoop cd2Chain_IsLoop
#define cd2GetChainBounds cd2Chain_GetBounds
#define cd2GetChainSegment cd2Chain_GetSegment

#ifdef __cplusplus
}
#endif

#endif
