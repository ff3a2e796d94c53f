/* collide: 2D queries on primitive shapes: overlap tests, point containment, closest points,
 * ray casts, and the generic dispatchers on tagged shapes. Queries allocate nothing.
 * The semantics are those of query3.h (closed shapes, rays starting inside hit at fraction 0
 * with normal -normalize(translation), closest point on a solid is the point itself when it is
 * inside), spelled out in docs/API.md. */
#ifndef COLLIDE_QUERY2_H
#define COLLIDE_QUERY2_H

#include "collide/geometry2.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct cd2RayHit
{
	cdReal fraction; /* t in [0, 1] */
	cd2Vec point;	 /* origin + fraction * translation */
	cd2Vec normal;	 /* outward unit normal of the surface at point */
} cd2RayHit;

/* Closest points between two shapes; distance 0 and pointA == pointB when they overlap. */
typedef struct cd2ClosestPoints
{
	cd2Vec pointA;
	cd2Vec pointB;
	cdReal distance;
} cd2ClosestPoints;

/* ---- the source texts' tests ------------------------------------------------------------- */
CD_API bool cd2PointInAabb(cd2Vec p, cd2Aabb b);
CD_API bool cd2OverlapAabbAabb(cd2Aabb a, cd2Aabb b);
CD_API bool cd2OverlapCircleCircle(cd2Circle a, cd2Circle b);
/* Separating axis test over the edge normals of both polygons. */
CD_API bool cd2OverlapPolygonPolygon(const cd2Polygon* a, const cd2Polygon* b);

/* ---- point containment (solid shapes) ---------------------------------------------------- */
CD_API bool cd2PointInCircle(cd2Vec p, cd2Circle c);
CD_API bool cd2PointInCapsule(cd2Vec p, cd2Capsule c);
CD_API bool cd2PointInBox(cd2Vec p, cd2Box b);
CD_API bool cd2PointInPolygon(cd2Vec p, const cd2Polygon* polygon);

/* ---- overlap, canonical order: Circle, Capsule, Aabb, Box, Polygon, Segment --------------- */
CD_API bool cd2OverlapCircleCapsule(cd2Circle a, cd2Capsule b);
CD_API bool cd2OverlapCircleAabb(cd2Circle a, cd2Aabb b);
CD_API bool cd2OverlapCircleBox(cd2Circle a, cd2Box b);
CD_API bool cd2OverlapCirclePolygon(cd2Circle a, const cd2Polygon* b);
CD_API bool cd2OverlapCircleSegment(cd2Circle a, cd2Segment b);

CD_API bool cd2OverlapCapsuleCapsule(cd2Capsule a, cd2Capsule b);
CD_API bool cd2OverlapCapsuleAabb(cd2Capsule a, cd2Aabb b);
CD_API bool cd2OverlapCapsuleBox(cd2Capsule a, cd2Box b);
CD_API bool cd2OverlapCapsulePolygon(cd2Capsule a, const cd2Polygon* b);
CD_API bool cd2OverlapCapsuleSegment(cd2Capsule a, cd2Segment b);

CD_API bool cd2OverlapAabbBox(cd2Aabb a, cd2Box b);
CD_API bool cd2OverlapAabbPolygon(cd2Aabb a, const cd2Polygon* b);
CD_API bool cd2OverlapAabbSegment(cd2Aabb a, cd2Segment b);

CD_API bool cd2OverlapBoxBox(cd2Box a, cd2Box b);
CD_API bool cd2OverlapBoxPolygon(cd2Box a, const cd2Polygon* b);
CD_API bool cd2OverlapBoxSegment(cd2Box a, cd2Segment b);

CD_API bool cd2OverlapPolygonSegment(const cd2Polygon* a, cd2Segment b);

CD_API bool cd2OverlapSegmentSegment(cd2Segment a, cd2Segment b);

/* ---- closest point on a shape to a point (the point itself when inside a solid) ---------- */
CD_API cd2Vec cd2ClosestPointOnCircle(cd2Circle c, cd2Vec p);
CD_API cd2Vec cd2ClosestPointOnCapsule(cd2Capsule c, cd2Vec p);
CD_API cd2Vec cd2ClosestPointOnAabb(cd2Aabb b, cd2Vec p);
CD_API cd2Vec cd2ClosestPointOnBox(cd2Box b, cd2Vec p);
CD_API cd2Vec cd2ClosestPointOnPolygon(const cd2Polygon* polygon, cd2Vec p);
CD_API cd2Vec cd2ClosestPointOnSegment(cd2Segment g, cd2Vec p);

/* Closest points between two segments. */
CD_API cd2ClosestPoints cd2ClosestPointsSegmentSegment(cd2Segment a, cd2Segment b);

/* ---- ray casts: true and *hit filled on a hit; *hit untouched on a miss -------------------- */
CD_API bool cd2RaycastCircle(cd2Circle c, cd2Ray ray, cd2RayHit* hit);
CD_API bool cd2RaycastCapsule(cd2Capsule c, cd2Ray ray, cd2RayHit* hit);
CD_API bool cd2RaycastAabb(cd2Aabb b, cd2Ray ray, cd2RayHit* hit);
CD_API bool cd2RaycastBox(cd2Box b, cd2Ray ray, cd2RayHit* hit);
CD_API bool cd2RaycastPolygon(const cd2Polygon* polygon, cd2Ray ray, cd2RayHit* hit);
/* Two-sided: the normal faces the ray's origin. */
CD_API bool cd2RaycastSegment(cd2Segment g, cd2Ray ray, cd2RayHit* hit);

/* ---- generic dispatchers on tagged shapes (either order) ---------------------------------- */
CD_API bool cd2Overlap(const cd2Shape* a, const cd2Shape* b);
/* Point containment; for the non-solid segment: distance below the tolerance. */
CD_API bool cd2PointInShape(const cd2Shape* shape, cd2Vec p);
CD_API cd2Vec cd2ClosestPointOnShape(const cd2Shape* shape, cd2Vec p);
CD_API bool cd2Raycast(const cd2Shape* shape, cd2Ray ray, cd2RayHit* hit);

/* Distance and closest points between any two shapes (GJK on the support functions).
 * pointA lies on a, pointB on b. */
CD_API cd2ClosestPoints cd2Distance(const cd2Shape* a, const cd2Shape* b);

/* cd2Distance, also telling how GJK went (status may be NULL). */
CD_API cd2ClosestPoints cd2DistanceWithStatus(const cd2Shape* a, const cd2Shape* b, cdDistanceStatus* status);

/* A GJK warm start across frames (Catto, "Computing Distance", GDC 2010): the last simplex as
 * indices into the shapes' core points (a polygon's vertices, a box's corners in the order
 * bottom-left, bottom-right, top-right, top-left, a capsule's or segment's ends, a circle's
 * centre) plus its size (length or area) to tell when the shapes changed too much for it to
 * help. Zero it before the first call (count 0: no warm start). Any content is safe: a cache
 * whose indices are out of range, repeated, or whose size changed by more than a factor of 2 is
 * ignored. */
typedef struct cd2SimplexCache
{
	cdReal metric;
	int count;
	int indexA[3];
	int indexB[3];
} cd2SimplexCache;

/* cd2DistanceWithStatus warm-started from *cache, which it then updates (cache may be NULL). The
 * answer is the same as without the cache up to round-off; the iterations are fewer when the
 * shapes moved little since the cache was written. */
CD_API cd2ClosestPoints cd2DistanceCached(const cd2Shape* a, const cd2Shape* b, cd2SimplexCache* cache,
										  cdDistanceStatus* status);

/* cd2Distance of a and of b placed by xfB (B's frame in A's frame, cd2InvMulTransforms(xfA, xfB)
 * of the two body transforms), without copying b: only the points of b's core (a polygon's
 * vertices, a box's corners, a capsule's ends...) are moved, by cd2TransformPoint. The closest
 * points are in A's frame. For a polygon b the answer is cd2Distance's on b's vertices moved the
 * same way, bit for bit; for other shapes it agrees up to round-off. */
CD_API cd2ClosestPoints cd2DistanceLocal(const cd2Shape* a, const cd2Shape* b, cd2Transform xfB);

#ifdef __cplusplus
}
#endif

#endif
