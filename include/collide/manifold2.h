/* collide: 2D contact manifolds between circles, capsules, polygons (rounded or not, boxes and
 * AABBs through the dispatcher), segments and one-sided chain segments.
 *
 * Every function takes its shapes in world space (like the rest of the query API) and a
 * speculative distance (>= 0): contact points whose surfaces are still apart by up to that
 * distance are reported with a positive separation; points farther apart are dropped. The
 * manifold's normal is a unit vector pointing from shape A (the first argument) to shape B. Each
 * point lies midway between the two surfaces: point - separation/2 * normal is on A's surface and
 * point + separation/2 * normal on B's. A pair with pointCount 0 has no contact (its normal is
 * zero). Segments are zero-radius capsules: two segments (no area) only touch where they cross
 * or come within the speculative distance. Functions name their shapes in the canonical order
 * Circle, Capsule, Polygon, Segment (cd2CollidePolygonCircle, the polygon-first form of
 * cd2CollideCirclePolygon, is the one addition out of that order); cd2Collide takes tagged shapes
 * in either order.
 *
 * Reference edge bias (the one statement of this rule; docs/API.md links here): between two
 * polygon-like cores (polygons, boxes, AABBs, capsules and segments as their axes) the reference
 * edge is A's unless B's separates by more than 0.1 CD_LINEAR_SLOP (5e-4 m at the default length
 * unit). The separations are measured along the reference edge's normal, so they are the exact
 * depths along the reported normal: B moved by minus the smallest separation along the normal just
 * touches A. The bias can take an edge whose depth exceeds the smallest depth by up to 0.1 slop;
 * it is kept on purpose: the reference edge, the normal and the feature ids then stay the same from
 * step to step when two edges are nearly tied (a box resting on another at a tiny tilt), which is
 * what warm starting needs, and a solver pushing along the reported normal by the reported depth
 * ends the overlap exactly, the extra push well inside the slop it leaves anyway. */
#ifndef COLLIDE_MANIFOLD2_H
#define COLLIDE_MANIFOLD2_H

#include "collide/query2.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct cd2ManifoldPoint
{
	cd2Vec point;	   /* world, midway between the surfaces */
	cdReal separation; /* negative when penetrating */
	uint32_t id;	   /* feature id: the same while the same features touch (for warm starting) */
} cd2ManifoldPoint;

typedef struct cd2Manifold
{
	cd2Vec normal; /* from A to B, unit (zero when pointCount is 0) */
	cd2ManifoldPoint points[2];
	int pointCount;
} cd2Manifold;

/* A one-sided segment p1 -> p2 of a chain (terrain), with its neighbours' far vertices ghost1 (the
 * vertex before p1) and ghost2 (the one after p2). Like a polygon's boundary the chain runs
 * counter-clockwise around the solid: the free side is to the right of p1 -> p2 (the side of
 * cd2RightPerp(p2 - p1)), so a floor runs from right to left. Shapes whose centre lies behind the
 * segment get no contact, and the normal is limited to the directions the chain allows at that
 * point (the segment's own normal, or between the two segments' normals at a convex vertex), so a
 * shape sliding across a junction never catches on an inner vertex (no ghost collisions). */
typedef struct cd2ChainSegment
{
	cd2Vec ghost1, p1, p2, ghost2;
} cd2ChainSegment;

/* Feature ids of polygon contacts pack (reference edge) | (incident edge << 8) | (which point:
 * 0/1 = incident edge's first/second vertex, 2/3 = clipped at the reference edge's first/second
 * side) << 16 | (1 << 24 when the reference edge belongs to B). Contacts at a single vertex or
 * with a circle use the vertex or edge index. */
#define CD2_FEATURE_FLIP (1u << 24)

CD_API cd2Manifold cd2CollideCircleCircle(cd2Circle a, cd2Circle b, cdReal speculativeDistance);
CD_API cd2Manifold cd2CollideCircleCapsule(cd2Circle a, cd2Capsule b, cdReal speculativeDistance);
CD_API cd2Manifold cd2CollideCirclePolygon(cd2Circle a, const cd2Polygon* b, cdReal speculativeDistance);
CD_API cd2Manifold cd2CollideCircleSegment(cd2Circle a, cd2Segment b, cdReal speculativeDistance);
/* The one pair also offered out of canonical order, for a solver that keeps the polygon as A: the
 * same points, separations and feature ids as cd2CollideCirclePolygon(b, a, ...), bit for bit,
 * with the opposite normal (from the polygon to the circle). */
CD_API cd2Manifold cd2CollidePolygonCircle(const cd2Polygon* a, cd2Circle b, cdReal speculativeDistance);
CD_API cd2Manifold cd2CollideCapsuleCapsule(cd2Capsule a, cd2Capsule b, cdReal speculativeDistance);
CD_API cd2Manifold cd2CollideCapsulePolygon(cd2Capsule a, const cd2Polygon* b, cdReal speculativeDistance);
CD_API cd2Manifold cd2CollideCapsuleSegment(cd2Capsule a, cd2Segment b, cdReal speculativeDistance);
CD_API cd2Manifold cd2CollidePolygonPolygon(const cd2Polygon* a, const cd2Polygon* b,
											cdReal speculativeDistance);
CD_API cd2Manifold cd2CollidePolygonSegment(const cd2Polygon* a, cd2Segment b, cdReal speculativeDistance);
CD_API cd2Manifold cd2CollideSegmentSegment(cd2Segment a, cd2Segment b, cdReal speculativeDistance);

/* The chain segment is shape A: the normal points from the terrain to the shape. */
CD_API cd2Manifold cd2CollideChainSegmentCircle(const cd2ChainSegment* a, cd2Circle b,
												cdReal speculativeDistance);
CD_API cd2Manifold cd2CollideChainSegmentCapsule(const cd2ChainSegment* a, cd2Capsule b,
												 cdReal speculativeDistance);
CD_API cd2Manifold cd2CollideChainSegmentPolygon(const cd2ChainSegment* a, const cd2Polygon* b,
												 cdReal speculativeDistance);

/* Any two tagged shapes, in either order (AABBs and boxes collide as polygons). Shapes of
 * different kinds run the pair function in canonical order and flip the normal when a and b were
 * swapped, so cd2Collide(b, a) reports the same points, separations and ids with the opposite
 * normal. Two polygon-like shapes (polygon, box, AABB) run in the given order: on a near tie
 * between the two reference edges, A's is preferred (the reference edge bias above). */
CD_API cd2Manifold cd2Collide(const cd2Shape* a, const cd2Shape* b, cdReal speculativeDistance);

/* ---- local-frame forms ---------------------------------------------------------------------
 * What a solver calls: shape A in its own (body) frame, shape B in its own frame, and xfB, the
 * transform of B's frame in A's frame (cd2InvMulTransforms(xfA, xfB) of the two body transforms).
 * The manifold comes back in A's frame: cd2TransformManifold(xfA, m) gives the world manifold.
 * Each function is named after its world-space form with the suffix Local and gives the same
 * points (in A's frame), normal, separations and feature ids as the world-space form called on a
 * and on b transformed by xfB (points by cd2TransformPoint, rotations by cd2MulRot): bit for bit,
 * since B is placed in A's frame on the stack and A is used as given. The one exception is a
 * circle, capsule, segment or chain segment against a polygon: the small shape is placed in the
 * polygon's frame instead (cheaper than moving up to 8 vertices and normals) and the manifold
 * mapped back, equal within round-off (1e-6 relative to the coordinates) with the same ids.
 * Contacts far from the origin keep their precision, since the shapes' coordinates stay those of
 * their body frames. An AABB given as B is read as a box in its own frame (rotated by xfB). */
CD_API cd2Manifold cd2CollideCircleCircleLocal(cd2Circle a, cd2Circle b, cd2Transform xfB,
											   cdReal speculativeDistance);
CD_API cd2Manifold cd2CollideCircleCapsuleLocal(cd2Circle a, cd2Capsule b, cd2Transform xfB,
												cdReal speculativeDistance);
CD_API cd2Manifold cd2CollideCirclePolygonLocal(cd2Circle a, const cd2Polygon* b, cd2Transform xfB,
												cdReal speculativeDistance);
CD_API cd2Manifold cd2CollideCircleSegmentLocal(cd2Circle a, cd2Segment b, cd2Transform xfB,
												cdReal speculativeDistance);
/* The polygon as A: only the circle's centre is placed (cd2TransformPoint(xfB, b.center)) and the
 * manifold is built in the polygon's frame, nothing mapped back; bit for bit
 * cd2CollidePolygonCircle(a, placed circle). With the relative transform at hand, the cheapest
 * way to collide a circle with a polygon: cd2CollideCirclePolygonLocal(b, a, inverse of xfB) gives
 * the same contact within round-off with the opposite normal, but takes the centre back into the
 * polygon's frame and maps the manifold back into the circle's. */
CD_API cd2Manifold cd2CollidePolygonCircleLocal(const cd2Polygon* a, cd2Circle b, cd2Transform xfB,
												cdReal speculativeDistance);
/* The same contact from the two body transforms, as a narrowphase holding two bodies has them
 * (and as Box2D's b2CollidePolygonAndCircle takes them): the polygon in its body frame placed by
 * xfA, the circle in its body frame placed by xfB. Only the circle's centre is moved into the
 * polygon's frame, by cd2InvTransformPoint(xfA, cd2TransformPoint(xfB, b.center)), and the
 * manifold comes back in the polygon's frame; bit for bit cd2CollidePolygonCircle(a, circle
 * placed there). No relative transform is composed (a circle needs no rotation): for a circle
 * centred on its body the manifold has the values of cd2CollidePolygonCircleLocal(a, b,
 * cd2InvMulTransforms(xfA, xfB)), for less work than composing that transform and calling it. */
CD_API cd2Manifold cd2CollidePolygonCircleBodies(const cd2Polygon* a, cd2Transform xfA, cd2Circle b,
												 cd2Transform xfB, cdReal speculativeDistance);
CD_API cd2Manifold cd2CollideCapsuleCapsuleLocal(cd2Capsule a, cd2Capsule b, cd2Transform xfB,
												 cdReal speculativeDistance);
CD_API cd2Manifold cd2CollideCapsulePolygonLocal(cd2Capsule a, const cd2Polygon* b, cd2Transform xfB,
												 cdReal speculativeDistance);
CD_API cd2Manifold cd2CollideCapsuleSegmentLocal(cd2Capsule a, cd2Segment b, cd2Transform xfB,
												 cdReal speculativeDistance);
CD_API cd2Manifold cd2CollidePolygonPolygonLocal(const cd2Polygon* a, const cd2Polygon* b, cd2Transform xfB,
												 cdReal speculativeDistance);
CD_API cd2Manifold cd2CollidePolygonSegmentLocal(const cd2Polygon* a, cd2Segment b, cd2Transform xfB,
												 cdReal speculativeDistance);
CD_API cd2Manifold cd2CollideSegmentSegmentLocal(cd2Segment a, cd2Segment b, cd2Transform xfB,
												 cdReal speculativeDistance);
CD_API cd2Manifold cd2CollideChainSegmentCircleLocal(const cd2ChainSegment* a, cd2Circle b, cd2Transform xfB,
													 cdReal speculativeDistance);
CD_API cd2Manifold cd2CollideChainSegmentCapsuleLocal(const cd2ChainSegment* a, cd2Capsule b,
													  cd2Transform xfB, cdReal speculativeDistance);
CD_API cd2Manifold cd2CollideChainSegmentPolygonLocal(const cd2ChainSegment* a, const cd2Polygon* b,
													  cd2Transform xfB, cdReal speculativeDistance);
/* cd2Collide in A's frame: either order, as cd2Collide. */
CD_API cd2Manifold cd2CollideLocal(const cd2Shape* a, const cd2Shape* b, cd2Transform xfB,
								   cdReal speculativeDistance);

/* The manifold m (in the frame of transform xf) in the outer frame: points transformed, normal
 * rotated; separations and ids unchanged. */
static inline cd2Manifold cd2TransformManifold(cd2Transform xf, cd2Manifold m)
{
	m.normal = cd2RotateVector(xf.q, m.normal);
	for (int i = 0; i < m.pointCount; ++i)
	{
		m.points[i].point = cd2TransformPoint(xf, m.points[i].point);
	}
	return m;
}

#ifdef __cplusplus
}
#endif

#endif
