/* collide: generic 2D dispatchers on tagged shapes: overlap (either order), point containment and
 * closest point. cd2Raycast and cd2Distance live with their algorithms. */
#include "collide/query2.h"

bool cd2Overlap(const cd2Shape* a, const cd2Shape* b)
{
	CD_ASSERT(a != NULL && b != NULL);
	/* Overlap is symmetric: swap into the canonical (enum) order the pair functions are named in. */
	if (a->type > b->type)
	{
		const cd2Shape* swap = a;
		a = b;
		b = swap;
	}
	switch (a->type)
	{
		case CD2_SHAPE_CIRCLE:
			switch (b->type)
			{
				case CD2_SHAPE_CIRCLE:
					return cd2OverlapCircleCircle(a->circle, b->circle);
				case CD2_SHAPE_CAPSULE:
					return cd2OverlapCircleCapsule(a->circle, b->capsule);
				case CD2_SHAPE_AABB:
					return cd2OverlapCircleAabb(a->circle, b->aabb);
				case CD2_SHAPE_BOX:
					return cd2OverlapCircleBox(a->circle, b->box);
				case CD2_SHAPE_POLYGON:
					return cd2OverlapCirclePolygon(a->circle, &b->polygon);
				case CD2_SHAPE_SEGMENT:
					return cd2OverlapCircleSegment(a->circle, b->segment);
				default:
					break;
			}
			break;
		case CD2_SHAPE_CAPSULE:
			switch (b->type)
			{
				case CD2_SHAPE_CAPSULE:
					return cd2OverlapCapsuleCapsule(a->capsule, b->capsule);
				case CD2_SHAPE_AABB:
					return cd2OverlapCapsuleAabb(a->capsule, b->aabb);
				case CD2_SHAPE_BOX:
					return cd2OverlapCapsuleBox(a->capsule, b->box);
				case CD2_SHAPE_POLYGON:
					return cd2OverlapCapsulePolygon(a->capsule, &b->polygon);
				case CD2_SHAPE_SEGMENT:
					return cd2OverlapCapsuleSegment(a->capsule, b->segment);
				default:
					break;
			}
			break;
		case CD2_SHAPE_AABB:
			switch (b->type)
			{
				case CD2_SHAPE_AABB:
					return cd2OverlapAabbAabb(a->aabb, b->aabb);
				case CD2_SHAPE_BOX:
					return cd2OverlapAabbBox(a->aabb, b->box);
				case CD2_SHAPE_POLYGON:
					return cd2OverlapAabbPolygon(a->aabb, &b->polygon);
				case CD2_SHAPE_SEGMENT:
					return cd2OverlapAabbSegment(a->aabb, b->segment);
				default:
					break;
			}
			break;
		case CD2_SHAPE_BOX:
			switch (b->type)
			{
				case CD2_SHAPE_BOX:
					return cd2OverlapBoxBox(a->box, b->box);
				case CD2_SHAPE_POLYGON:
					return cd2OverlapBoxPolygon(a->box, &b->polygon);
				case CD2_SHAPE_SEGMENT:
					return cd2OverlapBoxSegment(a->box, b->segment);
				default:
					break;
			}
			break;
		case CD2_SHAPE_POLYGON:
			switch (b->type)
			{
				case CD2_SHAPE_POLYGON:
					return cd2OverlapPolygonPolygon(&a->polygon, &b->polygon);
				case CD2_SHAPE_SEGMENT:
					return cd2OverlapPolygonSegment(&a->polygon, b->segment);
				default:
					break;
			}
			break;
		case CD2_SHAPE_SEGMENT:
			if (b->type == CD2_SHAPE_SEGMENT)
			{
				return cd2OverlapSegmentSegment(a->segment, b->segment);
			}
			break;
		default:
			break;
	}
	CD_ASSERT(false && "unknown shape type");
	return false;
}

bool cd2PointInShape(const cd2Shape* shape, cd2Vec p)
{
	CD_ASSERT(shape != NULL);
	switch (shape->type)
	{
		case CD2_SHAPE_CIRCLE:
			return cd2PointInCircle(p, shape->circle);
		case CD2_SHAPE_CAPSULE:
			return cd2PointInCapsule(p, shape->capsule);
		case CD2_SHAPE_AABB:
			return cd2PointInAabb(p, shape->aabb);
		case CD2_SHAPE_BOX:
			return cd2PointInBox(p, shape->box);
		case CD2_SHAPE_POLYGON:
			return cd2PointInPolygon(p, &shape->polygon);
		case CD2_SHAPE_SEGMENT:
		{
			/* A segment has no inside: the point must lie on it within round-off, that is within
			 * 8 * CD_REAL_EPSILON of the largest coordinate involved (as the overlap tests). */
			cd2Segment g = shape->segment;
			cd2Vec closest = cd2ClosestPointOnSegment(g, p);
			cdReal scale = cdMax(cdMax(cdAbs(p.x), cdAbs(p.y)), cdMax(cdMax(cdAbs(g.p1.x), cdAbs(g.p1.y)),
																	  cdMax(cdAbs(g.p2.x), cdAbs(g.p2.y))));
			cdReal tolerance = CD_R(8.0) * CD_REAL_EPSILON * scale;
			return cd2VecDistanceSquared(closest, p) <= tolerance * tolerance;
		}
		default:
			break;
	}
	CD_ASSERT(false && "unknown shape type");
	return false;
}

cd2Vec cd2ClosestPointOnShape(const cd2Shape* shape, cd2Vec p)
{
	CD_ASSERT(shape != NULL);
	switch (shape->type)
	{
		case CD2_SHAPE_CIRCLE:
			return cd2ClosestPointOnCircle(shape->circle, p);
		case CD2_SHAPE_CAPSULE:
			return cd2ClosestPointOnCapsule(shape->capsule, p);
		case CD2_SHAPE_AABB:
			return cd2ClosestPointOnAabb(shape->aabb, p);
		case CD2_SHAPE_BOX:
			return cd2ClosestPointOnBox(shape->box, p);
		case CD2_SHAPE_POLYGON:
			return cd2ClosestPointOnPolygon(&shape->polygon, p);
		case CD2_SHAPE_SEGMENT:
			return cd2ClosestPointOnSegment(shape->segment, p);
		default:
			break;
	}
	CD_ASSERT(false && "unknown shape type");
	return p;
}
