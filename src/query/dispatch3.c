/* collide: generic 3D dispatchers on tagged shapes: overlap (either order), point containment
 * and closest point, expanded from the shape and pair tables (pairs3.h). */
#include "collide/query3.h"

#include "distance3.h"
#include "pairs3.h"

#include <string.h>

/* Relative tolerance of cd3PointInShape for the non-solid triangle and segment, the same as the
 * overlap tests use (see overlap3.c). */
#define CD_POINT_IN_SHAPE_TOLERANCE (CD_R(16.0) * CD_REAL_EPSILON)

static cdReal MaxAbsComponent(cd3Vec v)
{
	return cdMax(cdAbs(v.x), cdMax(cdAbs(v.y), cdAbs(v.z)));
}

/* Pairs in canonical order (a->type <= b->type), without a hull: CD3_PAIR_TABLE. */
static bool OverlapOrdered(const cd3Shape* a, const cd3Shape* b)
{
	switch (CD3_PAIR_KEY(a->type, b->type))
	{
#define CD3_OVERLAP_CASE(A, B, Overlap, Distance, Collide)                                                   \
	case CD3_PAIR_KEY(CD3_TYPE_##A, CD3_TYPE_##B):                                                           \
		return Overlap(CD3_SHAPE_ARG(A, a), CD3_SHAPE_ARG(B, b));
		CD3_PAIR_TABLE(CD3_OVERLAP_CASE)
#undef CD3_OVERLAP_CASE
		default:
			break;
	}
	CD_ASSERT(false && "invalid shape type");
	return false;
}

/* Pairs with a hull (CD3_HULL_PAIR_TABLE), in canonical order (the hull second; two hulls by their
 * bytes, so that either argument order runs the very same computation): the boolean GJK of
 * distance3.c. */
static bool OverlapWithHull(const cd3Shape* a, const cd3Shape* b)
{
	return cd3OverlapGjk(a, b);
}

bool cd3Overlap(const cd3Shape* a, const cd3Shape* b)
{
	CD_ASSERT(a != NULL && b != NULL);
	if ((unsigned)a->type >= (unsigned)CD3_SHAPE_TYPE_COUNT ||
		(unsigned)b->type >= (unsigned)CD3_SHAPE_TYPE_COUNT)
	{
		CD_ASSERT(false && "invalid shape type");
		return false;
	}
	if (a->type == CD3_SHAPE_HULL || b->type == CD3_SHAPE_HULL)
	{
		bool inOrder = a->type != b->type ? a->type < b->type : memcmp(a, b, sizeof(cd3Shape)) <= 0;
		return inOrder ? OverlapWithHull(a, b) : OverlapWithHull(b, a);
	}
	return a->type <= b->type ? OverlapOrdered(a, b) : OverlapOrdered(b, a);
}

/* The triangle and the segment have no inside: the point must lie on them within round-off, relative
 * to the shape's extent around p (as the overlap tests). */
static bool PointOnTriangle3(cd3Vec p, cd3Triangle t)
{
	cd3Triangle local = {cd3Sub(t.a, p), cd3Sub(t.b, p), cd3Sub(t.c, p)};
	cd3Vec closest = cd3ClosestPointOnTriangle(local, CD3_VEC_ZERO);
	cdReal magnitude =
		cdMax(MaxAbsComponent(local.a), cdMax(MaxAbsComponent(local.b), MaxAbsComponent(local.c)));
	cdReal tolerance = CD_POINT_IN_SHAPE_TOLERANCE * magnitude;
	return cd3LengthSquared(closest) <= tolerance * tolerance;
}

static bool PointOnSegment3(cd3Vec p, cd3Segment g)
{
	cd3Segment local = {cd3Sub(g.p1, p), cd3Sub(g.p2, p)};
	cd3Vec closest = cd3ClosestPointOnSegment(local, CD3_VEC_ZERO);
	cdReal magnitude = cdMax(MaxAbsComponent(local.p1), MaxAbsComponent(local.p2));
	cdReal tolerance = CD_POINT_IN_SHAPE_TOLERANCE * magnitude;
	return cd3LengthSquared(closest) <= tolerance * tolerance;
}

bool cd3PointInShape(const cd3Shape* shape, cd3Vec p)
{
	CD_ASSERT(shape != NULL);
	switch (shape->type)
	{
#define CD3_POINT_IN_CASE(Name, PointIn, ClosestPointOn, Raycast, ...)                                       \
	case CD3_TYPE_##Name:                                                                                    \
		return PointIn(p, CD3_SHAPE_ARG(Name, shape));
		CD3_SHAPE_TABLE(CD3_POINT_IN_CASE)
#undef CD3_POINT_IN_CASE
		default:
			break;
	}
	CD_ASSERT(false && "invalid shape type");
	return false;
}

cd3Vec cd3ClosestPointOnShape(const cd3Shape* shape, cd3Vec p)
{
	CD_ASSERT(shape != NULL);
	switch (shape->type)
	{
#define CD3_CLOSEST_CASE(Name, PointIn, ClosestPointOn, Raycast, ...)                                        \
	case CD3_TYPE_##Name:                                                                                    \
		return ClosestPointOn(CD3_SHAPE_ARG(Name, shape), p);
		CD3_SHAPE_TABLE(CD3_CLOSEST_CASE)
#undef CD3_CLOSEST_CASE
		default:
			break;
	}
	CD_ASSERT(false && "invalid shape type");
	return p;
}
