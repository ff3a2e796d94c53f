/* collide: the dedicated manifolds of a one-sided chain segment against a polygon, a capsule or a
 * circle (internal, not installed). */
#ifndef COLLIDE_CHAIN_MANIFOLD2_H
#define COLLIDE_CHAIN_MANIFOLD2_H

#include "collide/manifold2.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The manifold of cd2CollideChainSegmentPolygon (the same decisions: manifold2.c's generic
 * core-core path on the segment's two-sided core, then the chain's check of the normal), computed
 * by a routine written for this one pair: no core set-up, the segment's separations from one pass
 * over the polygon's vertices, clipping specialised to each reference side, and the closest points
 * of a polygon standing clear above the segment found from its vertices' heights instead of a
 * segment-segment search over every edge. cd2CollideChain uses it for polygons, boxes and AABBs. */
cd2Manifold cd2CollideChainSegmentPolygonDirect(const cd2ChainSegment* a, const cd2Polygon* b,
												cdReal speculativeDistance);

/* The same for cd2CollideChainSegmentCapsule (the capsule's segment is a two-sided core of two
 * vertices; a zero-length one is a point) and cd2CollideChainSegmentCircle. */
cd2Manifold cd2CollideChainSegmentCapsuleDirect(const cd2ChainSegment* a, cd2Capsule b,
												cdReal speculativeDistance);
cd2Manifold cd2CollideChainSegmentCircleDirect(const cd2ChainSegment* a, cd2Circle b,
											   cdReal speculativeDistance);

#ifdef __cplusplus
}
#endif

#endif
