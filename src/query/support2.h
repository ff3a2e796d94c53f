/* Internal: 2D shapes as GJK sees them. Every shape is the convex hull of at most
 * CD2_MAX_POLYGON_VERTICES "core" points grown by a radius (a circle is a point, a capsule a
 * segment, a box its four corners, a rounded polygon its vertices and rounding radius). */
#ifndef COLLIDE_SUPPORT2_H
#define COLLIDE_SUPPORT2_H

#include "collide/geometry2.h"

#define CD2_CORE_MAX_POINTS CD2_MAX_POLYGON_VERTICES

typedef struct cd2Core
{
	const cd2Vec* points; /* a polygon's own vertices, or storage */
	cd2Vec storage[4];
	int count;
	cdReal radius;
} cd2Core;

/* Fills *core (pointing into the shape for a polygon: the shape must outlive it); returns false
 * for an unknown type or an empty polygon. */
static inline bool cd2MakeCore(const cd2Shape* shape, cd2Core* core)
{
	core->radius = CD_R(0.0);
	core->count = 0;
	core->points = core->storage;
	cd2Vec* storage = core->storage;
	switch (shape->type)
	{
		case CD2_SHAPE_CIRCLE:
			storage[0] = shape->circle.center;
			core->count = 1;
			core->radius = shape->circle.radius;
			return true;
		case CD2_SHAPE_CAPSULE:
			storage[0] = shape->capsule.p1;
			storage[1] = shape->capsule.p2;
			core->count = 2;
			core->radius = shape->capsule.radius;
			return true;
		case CD2_SHAPE_AABB:
		{
			cd2Vec lo = shape->aabb.min, hi = shape->aabb.max;
			storage[0] = lo;
			storage[1] = cd2MakeVec(hi.x, lo.y);
			storage[2] = hi;
			storage[3] = cd2MakeVec(lo.x, hi.y);
			core->count = 4;
			return true;
		}
		case CD2_SHAPE_BOX:
		{
			const cd2Box* box = &shape->box;
			cd2Vec axisX = cd2RotateVector(box->rotation, cd2MakeVec(box->halfExtents.x, CD_R(0.0)));
			cd2Vec axisY = cd2RotateVector(box->rotation, cd2MakeVec(CD_R(0.0), box->halfExtents.y));
			storage[0] = cd2Sub(cd2Sub(box->center, axisX), axisY);
			storage[1] = cd2Sub(cd2Add(box->center, axisX), axisY);
			storage[2] = cd2Add(cd2Add(box->center, axisX), axisY);
			storage[3] = cd2Add(cd2Sub(box->center, axisX), axisY);
			core->count = 4;
			return true;
		}
		case CD2_SHAPE_POLYGON:
		{
			int count = cdMinInt(shape->polygon.count, CD2_CORE_MAX_POINTS);
			core->points = shape->polygon.vertices;
			core->count = count;
			core->radius = shape->polygon.radius;
			return count > 0;
		}
		case CD2_SHAPE_SEGMENT:
			storage[0] = shape->segment.p1;
			storage[1] = shape->segment.p2;
			core->count = 2;
			return true;
		default:
			return false;
	}
}

/* Index of the core point farthest along `direction` (the first one on ties). */
static inline int cd2CoreSupport(const cd2Core* core, cd2Vec direction)
{
	int best = 0;
	cdReal bestValue = cd2Dot(core->points[0], direction);
	for (int i = 1; i < core->count; ++i)
	{
		cdReal value = cd2Dot(core->points[i], direction);
		if (value > bestValue)
		{
			best = i;
			bestValue = value;
		}
	}
	return best;
}

/* Support by hill climbing from `start` along the counter-clockwise ring of core points: on a
 * convex ring the projections rise to one maximum (plateaus only at an edge perpendicular to the
 * direction, which is the top or the bottom), so a vertex neither of whose neighbours projects
 * farther is the support. Faster than the scan for larger rings when the start is close, as in
 * GJK where the previous support is. Small rings are scanned. */
static inline int cd2CoreSupportFrom(const cd2Core* core, cd2Vec direction, int start)
{
	int count = core->count;
	if (count < 6)
	{
		return cd2CoreSupport(core, direction);
	}
	int best = start;
	cdReal bestValue = cd2Dot(core->points[best], direction);
	for (int step = 0; step < count; ++step)
	{
		int next = best + 1 < count ? best + 1 : 0;
		int previous = best > 0 ? best - 1 : count - 1;
		cdReal nextValue = cd2Dot(core->points[next], direction);
		cdReal previousValue = cd2Dot(core->points[previous], direction);
		if (nextValue > bestValue && nextValue >= previousValue)
		{
			best = next;
			bestValue = nextValue;
		}
		else if (previousValue > bestValue)
		{
			best = previous;
			bestValue = previousValue;
		}
		else
		{
			break;
		}
	}
	return best;
}

/* Squared distance from p to the polygon edge a-b and the edge's closest point, computed from the
 * edge end nearer to p: the round-off then grows with p's offset from that end, not with the
 * coordinates, so that it compares with tolerances relative to those offsets (point containment
 * near a vertex, beyond a sharp tip). */
static inline cdReal cd2EdgeDistanceSquared(cd2Vec a, cd2Vec b, cd2Vec p, cd2Vec* closest)
{
	cd2Vec fromA = cd2Sub(p, a), fromB = cd2Sub(p, b);
	bool nearA = cdMax(cdAbs(fromA.x), cdAbs(fromA.y)) <= cdMax(cdAbs(fromB.x), cdAbs(fromB.y));
	cd2Vec end = nearA ? a : b;
	cd2Vec offset = nearA ? fromA : fromB;
	cd2Vec edge = nearA ? cd2Sub(b, a) : cd2Sub(a, b);
	cdReal lengthSquared = cd2Dot(edge, edge);
	cdReal along = cd2Dot(offset, edge);
	cd2Vec foot = CD2_VEC_ZERO; /* relative to end */
	/* The clamps come first so that a zero-length (or underflowing) edge never divides by 0. */
	if (along >= lengthSquared && lengthSquared > CD_R(0.0))
	{
		foot = edge;
	}
	else if (along > CD_R(0.0) && lengthSquared > CD_R(0.0))
	{
		foot = cd2Scale(along / lengthSquared, edge);
	}
	*closest = cd2Add(end, foot);
	return cd2LengthSquared(cd2Sub(offset, foot));
}

#endif
