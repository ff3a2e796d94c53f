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
 * Circle, Capsule, Polygon, Segment; cd2Collide takes tagged shapes in either order. */
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
 * between the two reference edges, A's is preferred (by up to 0.1 linear slop). */
CD_API cd2Manifold cd2Collide(const cd2Shape* a, const cd2Shape* b, cdReal speculativeDistance);

#ifdef __cplusplus
}
#endif

#endif
