/* collide: generic 3D dispatchers on tagged shapes: overlap (either order), point containment
 * and closest point. */
#include "collide/query3.h"

#include "distance3.h"

#include <string.h>

/* Relative tolerance of cd3PointInShape for the non-solid triangle and segment, the same as the
 * overlap tests use (see overlap3.c). */
#define CD_POINT_IN_SHAPE_TOLERANCE (CD_R(16.0) * CD_REAL_EPSILON)

static cdReal MaxAbsComponent(cd3Vec v)
{
	return cdMax(cdAbs(v.x), cdMax(cdAbs(v.y), cdAbs(v.z)));
}

/* Pairs in canonical order: a->type <= b->type. */
static bool OverlapOrdered(const cd3Shape* a, const cd3Shape* b)
{
	switch (a->type)
	{
		case CD3_SHAPE_SPHERE:
			switch (b->type)
			{
				case CD3_SHAPE_SPHERE:
					return cd3OverlapSphereSphere(a->sphere, b->sphere);
				case CD3_SHAPE_CAPSULE:
					return cd3OverlapSphereCapsule(a->sphere, b->capsule);
				case CD3_SHAPE_AABB:
					return cd3OverlapSphereAabb(a->sphere, b->aabb);
				case CD3_SHAPE_BOX:
					return cd3OverlapSphereBox(a->sphere, b->box);
				case CD3_SHAPE_TRIANGLE:
					return cd3OverlapSphereTriangle(a->sphere, b->triangle);
				case CD3_SHAPE_PLANE:
					return cd3OverlapSpherePlane(a->sphere, b->plane);
				case CD3_SHAPE_SEGMENT:
					return cd3OverlapSphereSegment(a->sphere, b->segment);
				default:
					break;
			}
			break;
		case CD3_SHAPE_CAPSULE:
			switch (b->type)
			{
				case CD3_SHAPE_CAPSULE:
					return cd3OverlapCapsuleCapsule(a->capsule, b->capsule);
				case CD3_SHAPE_AABB:
					return cd3OverlapCapsuleAabb(a->capsule, b->aabb);
				case CD3_SHAPE_BOX:
					return cd3OverlapCapsuleBox(a->capsule, b->box);
				case CD3_SHAPE_TRIANGLE:
					return cd3OverlapCapsuleTriangle(a->capsule, b->triangle);
				case CD3_SHAPE_PLANE:
					return cd3OverlapCapsulePlane(a->capsule, b->plane);
				case CD3_SHAPE_SEGMENT:
					return cd3OverlapCapsuleSegment(a->capsule, b->segment);
				default:
					break;
			}
			break;
		case CD3_SHAPE_AABB:
			switch (b->type)
			{
				case CD3_SHAPE_AABB:
					return cd3OverlapAabbAabb(a->aabb, b->aabb);
				case CD3_SHAPE_BOX:
					return cd3OverlapAabbBox(a->aabb, b->box);
				case CD3_SHAPE_TRIANGLE:
					return cd3OverlapAabbTriangle(a->aabb, b->triangle);
				case CD3_SHAPE_PLANE:
					return cd3OverlapAabbPlane(a->aabb, b->plane);
				case CD3_SHAPE_SEGMENT:
					return cd3OverlapAabbSegment(a->aabb, b->segment);
				default:
					break;
			}
			break;
		case CD3_SHAPE_BOX:
			switch (b->type)
			{
				case CD3_SHAPE_BOX:
					return cd3OverlapBoxBox(a->box, b->box);
				case CD3_SHAPE_TRIANGLE:
					return cd3OverlapBoxTriangle(a->box, b->triangle);
				case CD3_SHAPE_PLANE:
					return cd3OverlapBoxPlane(a->box, b->plane);
				case CD3_SHAPE_SEGMENT:
					return cd3OverlapBoxSegment(a->box, b->segment);
				default:
					break;
			}
			break;
		case CD3_SHAPE_TRIANGLE:
			switch (b->type)
			{
				case CD3_SHAPE_TRIANGLE:
					return cd3OverlapTriangleTriangle(a->triangle, b->triangle);
				case CD3_SHAPE_PLANE:
					return cd3OverlapTrianglePlane(a->triangle, b->plane);
				case CD3_SHAPE_SEGMENT:
					return cd3OverlapTriangleSegment(a->triangle, b->segment);
				default:
					break;
			}
			break;
		case CD3_SHAPE_PLANE:
			switch (b->type)
			{
				case CD3_SHAPE_PLANE:
					return cd3OverlapPlanePlane(a->plane, b->plane);
				case CD3_SHAPE_SEGMENT:
					return cd3OverlapPlaneSegment(a->plane, b->segment);
				default:
					break;
			}
			break;
		case CD3_SHAPE_SEGMENT:
			if (b->type == CD3_SHAPE_SEGMENT)
			{
				return cd3OverlapSegmentSegment(a->segment, b->segment);
			}
			break;
		default:
			break;
	}
	CD_ASSERT(false && "invalid shape type");
	return false;
}

/* Pairs with a hull, in canonical order (the hull second; two hulls by their bytes, so that
 * either argument order runs the very same computation): the boolean GJK of distance3.c. */
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

bool cd3PointInShape(const cd3Shape* shape, cd3Vec p)
{
	CD_ASSERT(shape != NULL);
	switch (shape->type)
	{
		case CD3_SHAPE_SPHERE:
			return cd3PointInSphere(p, shape->sphere);
		case CD3_SHAPE_CAPSULE:
			return cd3PointInCapsule(p, shape->capsule);
		case CD3_SHAPE_AABB:
			return cd3PointInAabb(p, shape->aabb);
		case CD3_SHAPE_BOX:
			return cd3PointInBox(p, shape->box);
		case CD3_SHAPE_PLANE:
			return cd3PointInPlane(p, shape->plane);
		case CD3_SHAPE_HULL:
			return cd3PointInHull(p, shape->hull);
		case CD3_SHAPE_TRIANGLE:
		{
			/* Relative to p, so the tolerance follows the triangle's extent around p. */
			cd3Triangle t = shape->triangle;
			cd3Triangle local = {cd3Sub(t.a, p), cd3Sub(t.b, p), cd3Sub(t.c, p)};
			cd3Vec closest = cd3ClosestPointOnTriangle(local, CD3_VEC_ZERO);
			cdReal magnitude =
				cdMax(MaxAbsComponent(local.a), cdMax(MaxAbsComponent(local.b), MaxAbsComponent(local.c)));
			cdReal tolerance = CD_POINT_IN_SHAPE_TOLERANCE * magnitude;
			return cd3LengthSquared(closest) <= tolerance * tolerance;
		}
		case CD3_SHAPE_SEGMENT:
		{
			cd3Segment local = {cd3Sub(shape->segment.p1, p), cd3Sub(shape->segment.p2, p)};
			cd3Vec closest = cd3ClosestPointOnSegment(local, CD3_VEC_ZERO);
			cdReal magnitude = cdMax(MaxAbsComponent(local.p1), MaxAbsComponent(local.p2));
			cdReal tolerance = CD_POINT_IN_SHAPE_TOLERANCE * magnitude;
			return cd3LengthSquared(closest) <= tolerance * tolerance;
		}
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
		case CD3_SHAPE_SPHERE:
			return cd3ClosestPointOnSphere(shape->sphere, p);
		case CD3_SHAPE_CAPSULE:
			return cd3ClosestPointOnCapsule(shape->capsule, p);
		case CD3_SHAPE_AABB:
			return cd3ClosestPointOnAabb(shape->aabb, p);
		case CD3_SHAPE_BOX:
			return cd3ClosestPointOnBox(shape->box, p);
		case CD3_SHAPE_TRIANGLE:
			return cd3ClosestPointOnTriangle(shape->triangle, p);
		case CD3_SHAPE_PLANE:
			return cd3ClosestPointOnPlane(shape->plane, p);
		case CD3_SHAPE_SEGMENT:
			return cd3ClosestPointOnSegment(shape->segment, p);
		case CD3_SHAPE_HULL:
			return cd3ClosestPointOnHull(shape->hull, p);
		default:
			break;
	}
	CD_ASSERT(false && "invalid shape type");
	return p;
}
