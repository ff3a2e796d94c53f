/* collide: generic 2D dispatchers on tagged shapes: overlap (either order), point containment and
 * closest point, expanded from the shape and pair tables (pairs2.h). cd2Raycast and cd2Distance
 * live with their algorithms. */
#include "collide/query2.h"

#include "pairs2.h"

/* A segment has no inside: the point must lie on it within round-off, that is within
 * 8 * CD_REAL_EPSILON of the largest coordinate involved (as the overlap tests). */
static bool PointOnSegment2(cd2Vec p, cd2Segment g)
{
	cd2Vec closest = cd2ClosestPointOnSegment(g, p);
	cdReal scale = cdMax(cdMax(cdAbs(p.x), cdAbs(p.y)),
						 cdMax(cdMax(cdAbs(g.p1.x), cdAbs(g.p1.y)), cdMax(cdAbs(g.p2.x), cdAbs(g.p2.y))));
	cdReal tolerance = CD_R(8.0) * CD_REAL_EPSILON * scale;
	return cd2VecDistanceSquared(closest, p) <= tolerance * tolerance;
}

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
	switch (CD2_PAIR_KEY(a->type, b->type))
	{
#define CD2_OVERLAP_CASE(A, B, Overlap, Distance, Collide)                                                   \
	case CD2_PAIR_KEY(CD2_TYPE_##A, CD2_TYPE_##B):                                                           \
		return Overlap(CD2_SHAPE_ARG(A, a), CD2_SHAPE_ARG(B, b));
		CD2_PAIR_TABLE(CD2_OVERLAP_CASE)
#undef CD2_OVERLAP_CASE
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
#define CD2_POINT_IN_CASE(Name, PointIn, ClosestPointOn, Raycast, ...)                                       \
	case CD2_TYPE_##Name:                                                                                    \
		return PointIn(p, CD2_SHAPE_ARG(Name, shape));
		CD2_SHAPE_TABLE(CD2_POINT_IN_CASE)
#undef CD2_POINT_IN_CASE
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
#define CD2_CLOSEST_CASE(Name, PointIn, ClosestPointOn, Raycast, ...)                                        \
	case CD2_TYPE_##Name:                                                                                    \
		return ClosestPointOn(CD2_SHAPE_ARG(Name, shape), p);
		CD2_SHAPE_TABLE(CD2_CLOSEST_CASE)
#undef CD2_CLOSEST_CASE
		default:
			break;
	}
	CD_ASSERT(false && "unknown shape type");
	return p;
}
