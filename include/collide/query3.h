/* collide: 3D queries on primitive shapes: overlap tests, point containment, closest points,
 * ray casts, and the generic dispatchers on tagged shapes. Queries allocate nothing.
 *
 * Semantics (pinned down by tests/; this is the one statement of these rules, for the 2D
 * queries of query2.h too, and docs/API.md links here):
 * - Shapes are closed: touching counts as overlapping. Overlap is true exactly when the
 *   distance between the shapes is zero, up to the tolerance below.
 * - Tolerance: the source texts' tests (cd3PointInAabb, cd3OverlapAabbAabb, cd3PointInSphere,
 *   cd3OverlapSphereSphere, cd3OverlapSphereAabb; cd2PointInAabb, cd2OverlapAabbAabb,
 *   cd2OverlapCircleCircle and the 2D circle/AABB tests) compare squared distances exactly (<=,
 *   no square root). Every other test accepts a gap of up to 16 CD_REAL_EPSILON (3D) or
 *   8 CD_REAL_EPSILON (2D) times the largest coordinate involved, measured relative to one of
 *   the two shapes (about 2e-6 relative in float, 4e-15 in double), so that touching within
 *   round-off counts. Half-space tests measure the offset from the world origin.
 * - Degenerate shapes: zero radii, zero-size boxes and AABBs, zero-length capsules and segments
 *   are valid and behave as the point, segment or disk they are. Zero-area triangles are
 *   rejected by the validators but never crash a query or yield NaN (they act as their longest
 *   edge).
 * - Closest point (cd?ClosestPointOn<Shape>) on a solid shape is the query point itself when it
 *   lies inside; on the non-solid triangle and segment it is the nearest surface point.
 * - Closest points between two shapes (cd?ClosestPoints*, cd?Distance): pointA on A, pointB on
 *   B, distance = |pointB - pointA|; when the shapes meet, distance is 0 and pointA == pointB
 *   is a common point.
 * - Ray casts: a ray is {origin, translation}, the points origin + t * translation for t in
 *   [0, 1]. A hit reports the first point where the ray enters the shape: its fraction t, the
 *   point and the outward unit surface normal there; *hit is untouched on a miss. A ray whose
 *   origin lies inside a solid shape (or on its boundary) hits at fraction 0 with point =
 *   origin and normal = -normalize(translation) (the zero vector for a zero translation), in
 *   2D and 3D alike. The 3D triangle and the 2D segment are two-sided: the normal faces the
 *   ray's origin; a ray lying in a triangle's plane misses, and zero-length rays never hit
 *   triangles or segments.
 * - Pair functions take the shapes in canonical order (3D: Sphere, Capsule, Aabb, Box,
 *   Triangle, Plane, Segment, Hull; 2D: Circle, Capsule, Aabb, Box, Polygon, Segment); same-type
 *   pairs give bit-identical answers in either order, and the generic dispatchers (cd?Overlap,
 *   cd?Distance) accept either order. */
#ifndef COLLIDE_QUERY3_H
#define COLLIDE_QUERY3_H

#include "collide/geometry3.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct cd3RayHit
{
	cdReal fraction; /* t in [0, 1] */
	cd3Vec point;	 /* origin + fraction * translation */
	cd3Vec normal;	 /* outward unit normal of the surface at point */
} cd3RayHit;

/* Closest points between two shapes. When the shapes overlap, distance is 0 and pointA ==
 * pointB is a point inside both. */
typedef struct cd3ClosestPoints
{
	cd3Vec pointA;
	cd3Vec pointB;
	cdReal distance;
} cd3ClosestPoints;

/* ---- the source texts' tests ------------------------------------------------------------- */
CD_API bool cd3PointInAabb(cd3Vec p, cd3Aabb b);
CD_API bool cd3OverlapAabbAabb(cd3Aabb a, cd3Aabb b);
CD_API bool cd3PointInSphere(cd3Vec p, cd3Sphere s);
CD_API bool cd3OverlapSphereSphere(cd3Sphere a, cd3Sphere b);
CD_API bool cd3OverlapSphereAabb(cd3Sphere s, cd3Aabb b);

/* ---- point containment (solid shapes) ---------------------------------------------------- */
CD_API bool cd3PointInCapsule(cd3Vec p, cd3Capsule c);
CD_API bool cd3PointInBox(cd3Vec p, cd3Box b);
CD_API bool cd3PointInPlane(cd3Vec p, cd3Plane plane);
/* Below every face plane, within cd3Hull_GetTolerance (the hull's planes are rounded). */
CD_API bool cd3PointInHull(cd3Vec p, cd3HullShape hull);

/* ---- overlap, canonical order: Sphere, Capsule, Aabb, Box, Triangle, Plane, Segment -------- */
CD_API bool cd3OverlapSphereCapsule(cd3Sphere s, cd3Capsule c);
CD_API bool cd3OverlapSphereBox(cd3Sphere s, cd3Box b);
CD_API bool cd3OverlapSphereTriangle(cd3Sphere s, cd3Triangle t);
CD_API bool cd3OverlapSpherePlane(cd3Sphere s, cd3Plane p);
CD_API bool cd3OverlapSphereSegment(cd3Sphere s, cd3Segment g);

CD_API bool cd3OverlapCapsuleCapsule(cd3Capsule a, cd3Capsule b);
CD_API bool cd3OverlapCapsuleAabb(cd3Capsule c, cd3Aabb b);
CD_API bool cd3OverlapCapsuleBox(cd3Capsule c, cd3Box b);
CD_API bool cd3OverlapCapsuleTriangle(cd3Capsule c, cd3Triangle t);
CD_API bool cd3OverlapCapsulePlane(cd3Capsule c, cd3Plane p);
CD_API bool cd3OverlapCapsuleSegment(cd3Capsule c, cd3Segment g);

CD_API bool cd3OverlapAabbBox(cd3Aabb a, cd3Box b);
CD_API bool cd3OverlapAabbTriangle(cd3Aabb a, cd3Triangle t);
CD_API bool cd3OverlapAabbPlane(cd3Aabb a, cd3Plane p);
CD_API bool cd3OverlapAabbSegment(cd3Aabb a, cd3Segment g);

CD_API bool cd3OverlapBoxBox(cd3Box a, cd3Box b);
CD_API bool cd3OverlapBoxTriangle(cd3Box b, cd3Triangle t);
CD_API bool cd3OverlapBoxPlane(cd3Box b, cd3Plane p);
CD_API bool cd3OverlapBoxSegment(cd3Box b, cd3Segment g);

CD_API bool cd3OverlapTriangleTriangle(cd3Triangle a, cd3Triangle b);
CD_API bool cd3OverlapTrianglePlane(cd3Triangle t, cd3Plane p);
CD_API bool cd3OverlapTriangleSegment(cd3Triangle t, cd3Segment g);

/* Two half-spaces overlap unless their normals are opposite (the sine of their angle at most
 * 16 CD_REAL_EPSILON) and their solid sides are apart by more than the tolerance above. */
CD_API bool cd3OverlapPlanePlane(cd3Plane a, cd3Plane b);
CD_API bool cd3OverlapPlaneSegment(cd3Plane p, cd3Segment g);

CD_API bool cd3OverlapSegmentSegment(cd3Segment a, cd3Segment b);

/* ---- closest point on a shape to a point (the point itself when inside a solid) ---------- */
CD_API cd3Vec cd3ClosestPointOnSphere(cd3Sphere s, cd3Vec p);
CD_API cd3Vec cd3ClosestPointOnCapsule(cd3Capsule c, cd3Vec p);
CD_API cd3Vec cd3ClosestPointOnAabb(cd3Aabb b, cd3Vec p);
CD_API cd3Vec cd3ClosestPointOnBox(cd3Box b, cd3Vec p);
CD_API cd3Vec cd3ClosestPointOnTriangle(cd3Triangle t, cd3Vec p);
CD_API cd3Vec cd3ClosestPointOnPlane(cd3Plane plane, cd3Vec p);
CD_API cd3Vec cd3ClosestPointOnSegment(cd3Segment g, cd3Vec p);
CD_API cd3Vec cd3ClosestPointOnHull(cd3HullShape hull, cd3Vec p); /* GJK point against the hull */

/* Closest points between two segments, and between a triangle and a segment. */
CD_API cd3ClosestPoints cd3ClosestPointsSegmentSegment(cd3Segment a, cd3Segment b);
CD_API cd3ClosestPoints cd3ClosestPointsTriangleSegment(cd3Triangle t, cd3Segment g);

/* ---- ray casts: true and *hit filled on a hit; *hit untouched on a miss -------------------- */
CD_API bool cd3RaycastSphere(cd3Sphere s, cd3Ray ray, cd3RayHit* hit);
CD_API bool cd3RaycastCapsule(cd3Capsule c, cd3Ray ray, cd3RayHit* hit);
CD_API bool cd3RaycastAabb(cd3Aabb b, cd3Ray ray, cd3RayHit* hit);
CD_API bool cd3RaycastBox(cd3Box b, cd3Ray ray, cd3RayHit* hit);
CD_API bool cd3RaycastTriangle(cd3Triangle t, cd3Ray ray, cd3RayHit* hit);
CD_API bool cd3RaycastPlane(cd3Plane plane, cd3Ray ray, cd3RayHit* hit);
/* Cyrus-Beck clipping against the face planes, in the hull's frame. */
CD_API bool cd3RaycastHull(cd3HullShape hull, cd3Ray ray, cd3RayHit* hit);

/* ---- generic dispatchers on tagged shapes (either order) ---------------------------------- */
/* Pairs with a hull are decided by GJK (distance within a few epsilons of the shapes' size
 * counts as touching); hull against half-space by the hull's deepest vertex. */
CD_API bool cd3Overlap(const cd3Shape* a, const cd3Shape* b);

/* Point containment; for the non-solid triangle and segment: distance below the tolerance. */
CD_API bool cd3PointInShape(const cd3Shape* shape, cd3Vec p);
CD_API cd3Vec cd3ClosestPointOnShape(const cd3Shape* shape, cd3Vec p);

/* A segment is hit when the ray passes within 64 CD_REAL_EPSILON times the largest coordinate
 * of it; the normal points from the segment towards the ray. */
CD_API bool cd3Raycast(const cd3Shape* shape, cd3Ray ray, cd3RayHit* hit);

/* Distance and closest points between any two shapes (GJK on the support functions; a
 * half-space is handled exactly). pointA lies on a, pointB on b. */
CD_API cd3ClosestPoints cd3Distance(const cd3Shape* a, const cd3Shape* b);

/* cd3Distance, also telling how GJK went (status may be NULL). GJK (cd3Distance, cd2Distance and
 * their cached forms) stops after 64 iterations at the latest and returns the best answer found;
 * status->hitIterationCap then says so. */
CD_API cd3ClosestPoints cd3DistanceWithStatus(const cd3Shape* a, const cd3Shape* b, cdDistanceStatus* status);

/* A GJK warm start across frames (Catto, "Computing Distance", GDC 2010): the last simplex as
 * indices into the shapes' core points (a hull's vertices, a box's or AABB's corners with bit 0,
 * 1, 2 of the index choosing +x, +y, +z, a triangle's vertices, a capsule's or segment's ends, a
 * sphere's centre) plus its size (length, area or volume) to tell when the shapes changed too
 * much for it to help. Zero it before the first call (count 0: no warm start). Any content is
 * safe: a cache whose indices are out of range, repeated, or whose size changed by more than a
 * factor of 2 is ignored. Half-spaces do not use it. */
typedef struct cd3SimplexCache
{
	cdReal metric;
	int count;
	int indexA[4];
	int indexB[4];
} cd3SimplexCache;

/* cd3DistanceWithStatus warm-started from *cache, which it then updates (cache may be NULL). The
 * answer is the same as without the cache up to round-off; the iterations are fewer when the
 * shapes moved little since the cache was written. */
CD_API cd3ClosestPoints cd3DistanceCached(const cd3Shape* a, const cd3Shape* b, cd3SimplexCache* cache,
										  cdDistanceStatus* status);

#ifdef __cplusplus
}
#endif

#endif
