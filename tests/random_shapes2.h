/* Random shapes for the property tests of the 2D queries: every shape type, with degenerate
 * sizes (exactly zero) one time in eight, rounded polygons one time in three, a common rigid transform, and a
 * printer for failing cases. Header-only, shared by the test programs. */
#ifndef COLLIDE_TEST_RANDOM_SHAPES2_H
#define COLLIDE_TEST_RANDOM_SHAPES2_H

#include "collide/query2.h"
#include "test.h"

#include <string.h>

static inline cdReal RandomReal(TestRng* rng, double lower, double upper)
{
	return (cdReal)TestRngRange(rng, lower, upper);
}

static inline cd2Vec RandomVec(TestRng* rng, double extent)
{
	return cd2MakeVec(RandomReal(rng, -extent, extent), RandomReal(rng, -extent, extent));
}

static inline cd2Rot RandomRot(TestRng* rng)
{
	return cd2MakeRot(RandomReal(rng, -3.2, 3.2));
}

static inline cdReal RandomSize(TestRng* rng, double upper)
{
	return TestRngInt(rng, 8) == 0 ? CD_R(0.0) : RandomReal(rng, 0.0, upper);
}

/* A convex counter-clockwise polygon: sorted angles on an ellipse, then turned (built by hand so
 * that these tests depend on cd2Distance only). */
static inline cd2Polygon RandomPolygon(TestRng* rng, cd2Vec center)
{
	cd2Polygon polygon;
	memset(&polygon, 0, sizeof(polygon));
	int count = 3 + TestRngInt(rng, CD2_MAX_POLYGON_VERTICES - 2);
	double angles[CD2_MAX_POLYGON_VERTICES];
	for (int i = 0; i < count; ++i)
	{
		/* One random angle per sector keeps the vertices apart. */
		angles[i] = (i + TestRngRange(rng, 0.1, 0.9)) * 2.0 * 3.14159265358979 / count;
	}
	double rx = TestRngRange(rng, 0.2, 1.5), ry = TestRngRange(rng, 0.2, 1.5);
	cd2Rot q = RandomRot(rng);
	cd2Vec sum = CD2_VEC_ZERO;
	for (int i = 0; i < count; ++i)
	{
		cd2Vec local = cd2MakeVec((cdReal)(rx * cos(angles[i])), (cdReal)(ry * sin(angles[i])));
		polygon.vertices[i] = cd2Add(center, cd2RotateVector(q, local));
		sum = cd2Add(sum, polygon.vertices[i]);
	}
	for (int i = 0; i < count; ++i)
	{
		cd2Vec edge = cd2Sub(polygon.vertices[(i + 1) % count], polygon.vertices[i]);
		polygon.normals[i] = cd2Normalize(cd2RightPerp(edge));
	}
	polygon.centroid = cd2Scale(CD_R(1.0) / (cdReal)count, sum);
	polygon.count = count;
	polygon.radius = TestRngInt(rng, 3) == 0 ? RandomReal(rng, 0.0, 0.5) : CD_R(0.0);
	return polygon;
}

static inline cd2Shape RandomShape(TestRng* rng, cd2ShapeType type)
{
	cd2Shape s;
	memset(&s, 0, sizeof(s));
	s.type = type;
	cd2Vec center = RandomVec(rng, 2.0);
	switch (type)
	{
		case CD2_SHAPE_CIRCLE:
			s.circle.center = center;
			s.circle.radius = RandomSize(rng, 1.2);
			break;
		case CD2_SHAPE_CAPSULE:
		{
			cd2Vec half = cd2RotateVector(RandomRot(rng), cd2MakeVec(RandomSize(rng, 1.2), CD_R(0.0)));
			s.capsule.p1 = cd2Sub(center, half);
			s.capsule.p2 = cd2Add(center, half);
			s.capsule.radius = RandomSize(rng, 0.8);
			break;
		}
		case CD2_SHAPE_AABB:
		{
			cd2Vec half = cd2MakeVec(RandomSize(rng, 1.2), RandomSize(rng, 1.2));
			s.aabb.min = cd2Sub(center, half);
			s.aabb.max = cd2Add(center, half);
			break;
		}
		case CD2_SHAPE_BOX:
			s.box.center = center;
			s.box.halfExtents = cd2MakeVec(RandomSize(rng, 1.2), RandomSize(rng, 1.2));
			s.box.rotation = RandomRot(rng);
			break;
		case CD2_SHAPE_POLYGON:
			s.polygon = RandomPolygon(rng, center);
			break;
		case CD2_SHAPE_SEGMENT:
		{
			cd2Vec half = cd2RotateVector(RandomRot(rng), cd2MakeVec(RandomSize(rng, 1.5), CD_R(0.0)));
			s.segment.p1 = cd2Sub(center, half);
			s.segment.p2 = cd2Add(center, half);
			break;
		}
		default:
			break;
	}
	return s;
}

static inline cd2Shape TransformShape(const cd2Shape* shape, cd2Transform t)
{
	cd2Shape s = *shape;
	switch (shape->type)
	{
		case CD2_SHAPE_CIRCLE:
			s.circle.center = cd2TransformPoint(t, shape->circle.center);
			break;
		case CD2_SHAPE_CAPSULE:
			s.capsule.p1 = cd2TransformPoint(t, shape->capsule.p1);
			s.capsule.p2 = cd2TransformPoint(t, shape->capsule.p2);
			break;
		case CD2_SHAPE_AABB: /* translation only */
			s.aabb.min = cd2Add(shape->aabb.min, t.p);
			s.aabb.max = cd2Add(shape->aabb.max, t.p);
			break;
		case CD2_SHAPE_BOX:
			s.box.center = cd2TransformPoint(t, shape->box.center);
			s.box.rotation = cd2NormalizeRot(cd2MulRot(t.q, shape->box.rotation));
			break;
		case CD2_SHAPE_POLYGON:
			for (int i = 0; i < shape->polygon.count; ++i)
			{
				s.polygon.vertices[i] = cd2TransformPoint(t, shape->polygon.vertices[i]);
				s.polygon.normals[i] = cd2RotateVector(t.q, shape->polygon.normals[i]);
			}
			s.polygon.centroid = cd2TransformPoint(t, shape->polygon.centroid);
			break;
		case CD2_SHAPE_SEGMENT:
			s.segment.p1 = cd2TransformPoint(t, shape->segment.p1);
			s.segment.p2 = cd2TransformPoint(t, shape->segment.p2);
			break;
		default:
			break;
	}
	return s;
}

/* The shape scaled by k about the origin (positions and sizes alike). */
static inline cd2Shape ScaleShape(const cd2Shape* shape, cdReal k)
{
	cd2Shape s = *shape;
	switch (shape->type)
	{
		case CD2_SHAPE_CIRCLE:
			s.circle.center = cd2Scale(k, shape->circle.center);
			s.circle.radius = k * shape->circle.radius;
			break;
		case CD2_SHAPE_CAPSULE:
			s.capsule.p1 = cd2Scale(k, shape->capsule.p1);
			s.capsule.p2 = cd2Scale(k, shape->capsule.p2);
			s.capsule.radius = k * shape->capsule.radius;
			break;
		case CD2_SHAPE_AABB:
			s.aabb.min = cd2Scale(k, shape->aabb.min);
			s.aabb.max = cd2Scale(k, shape->aabb.max);
			break;
		case CD2_SHAPE_BOX:
			s.box.center = cd2Scale(k, shape->box.center);
			s.box.halfExtents = cd2Scale(k, shape->box.halfExtents);
			break;
		case CD2_SHAPE_POLYGON:
			for (int i = 0; i < shape->polygon.count; ++i)
			{
				s.polygon.vertices[i] = cd2Scale(k, shape->polygon.vertices[i]);
			}
			s.polygon.centroid = cd2Scale(k, shape->polygon.centroid);
			s.polygon.radius = k * shape->polygon.radius;
			break;
		case CD2_SHAPE_SEGMENT:
			s.segment.p1 = cd2Scale(k, shape->segment.p1);
			s.segment.p2 = cd2Scale(k, shape->segment.p2);
			break;
		default:
			break;
	}
	return s;
}

static inline const char* TypeName(cd2ShapeType type)
{
	static const char* names[] = {"circle", "capsule", "aabb", "box", "polygon", "segment"};
	return (int)type >= 0 && type < CD2_SHAPE_TYPE_COUNT ? names[type] : "?";
}

static inline void PrintShape(const char* label, const cd2Shape* s)
{
	fprintf(stderr, "  %s %s:", label, TypeName(s->type));
	switch (s->type)
	{
		case CD2_SHAPE_CIRCLE:
			fprintf(stderr, " center (%.9g %.9g) radius %.9g", (double)s->circle.center.x,
					(double)s->circle.center.y, (double)s->circle.radius);
			break;
		case CD2_SHAPE_CAPSULE:
			fprintf(stderr, " p1 (%.9g %.9g) p2 (%.9g %.9g) radius %.9g", (double)s->capsule.p1.x,
					(double)s->capsule.p1.y, (double)s->capsule.p2.x, (double)s->capsule.p2.y,
					(double)s->capsule.radius);
			break;
		case CD2_SHAPE_AABB:
			fprintf(stderr, " min (%.9g %.9g) max (%.9g %.9g)", (double)s->aabb.min.x, (double)s->aabb.min.y,
					(double)s->aabb.max.x, (double)s->aabb.max.y);
			break;
		case CD2_SHAPE_BOX:
			fprintf(stderr, " center (%.9g %.9g) half (%.9g %.9g) rot (%.9g %.9g)", (double)s->box.center.x,
					(double)s->box.center.y, (double)s->box.halfExtents.x, (double)s->box.halfExtents.y,
					(double)s->box.rotation.c, (double)s->box.rotation.s);
			break;
		case CD2_SHAPE_POLYGON:
			for (int i = 0; i < s->polygon.count; ++i)
			{
				fprintf(stderr, " (%.9g %.9g)", (double)s->polygon.vertices[i].x,
						(double)s->polygon.vertices[i].y);
			}
			fprintf(stderr, " radius %.9g", (double)s->polygon.radius);
			break;
		case CD2_SHAPE_SEGMENT:
			fprintf(stderr, " p1 (%.9g %.9g) p2 (%.9g %.9g)", (double)s->segment.p1.x,
					(double)s->segment.p1.y, (double)s->segment.p2.x, (double)s->segment.p2.y);
			break;
		default:
			break;
	}
	fprintf(stderr, "\n");
}

#endif
