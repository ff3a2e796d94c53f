/* Internal: 2D shapes as GJK sees them. Every shape is the convex hull of at most
 * CD2_MAX_POLYGON_VERTICES "core" points grown by a radius (a circle is a point, a capsule a
 * segment, a box its four corners, a rounded polygon its vertices and rounding radius). */
#ifndef COLLIDE_SUPPORT2_H
#define COLLIDE_SUPPORT2_H

#include "collide/geometry2.h"

#define CD2_CORE_MAX_POINTS CD2_MAX_POLYGON_VERTICES

typedef struct cd2Core
{
	cd2Vec points[CD2_CORE_MAX_POINTS];
	int count;
	cdReal radius;
} cd2Core;

/* Fills *core; returns false for an unknown type or an empty polygon. */
static inline bool cd2MakeCore(const cd2Shape* shape, cd2Core* core)
{
	core->radius = CD_R(0.0);
	core->count = 0;
	switch (shape->type)
	{
		case CD2_SHAPE_CIRCLE:
			core->points[0] = shape->circle.center;
			core->count = 1;
			core->radius = shape->circle.radius;
			return true;
		case CD2_SHAPE_CAPSULE:
			core->points[0] = shape->capsule.p1;
			core->points[1] = shape->capsule.p2;
			core->count = 2;
			core->radius = shape->capsule.radius;
			return true;
		case CD2_SHAPE_AABB:
		{
			cd2Vec lo = shape->aabb.min, hi = shape->aabb.max;
			core->points[0] = lo;
			core->points[1] = cd2MakeVec(hi.x, lo.y);
			core->points[2] = hi;
			core->points[3] = cd2MakeVec(lo.x, hi.y);
			core->count = 4;
			return true;
		}
		case CD2_SHAPE_BOX:
		{
			const cd2Box* box = &shape->box;
			cd2Vec axisX = cd2RotateVector(box->rotation, cd2MakeVec(box->halfExtents.x, CD_R(0.0)));
			cd2Vec axisY = cd2RotateVector(box->rotation, cd2MakeVec(CD_R(0.0), box->halfExtents.y));
			core->points[0] = cd2Sub(cd2Sub(box->center, axisX), axisY);
			core->points[1] = cd2Sub(cd2Add(box->center, axisX), axisY);
			core->points[2] = cd2Add(cd2Add(box->center, axisX), axisY);
			core->points[3] = cd2Add(cd2Sub(box->center, axisX), axisY);
			core->count = 4;
			return true;
		}
		case CD2_SHAPE_POLYGON:
		{
			int count = cdMinInt(shape->polygon.count, CD2_CORE_MAX_POINTS);
			for (int i = 0; i < count; ++i)
			{
				core->points[i] = shape->polygon.vertices[i];
			}
			core->count = count;
			core->radius = shape->polygon.radius;
			return count > 0;
		}
		case CD2_SHAPE_SEGMENT:
			core->points[0] = shape->segment.p1;
			core->points[1] = shape->segment.p2;
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

#endif
