/* Random shapes for the property tests of the 3D queries: every shape type, with degenerate
 * sizes (exactly zero) one time in eight, a common rigid transform, and a printer for failing
 * cases. Header-only, shared by the test programs. */
#ifndef COLLIDE_TEST_RANDOM_SHAPES3_H
#define COLLIDE_TEST_RANDOM_SHAPES3_H

#include "collide/query3.h"
#include "test.h"

#include <string.h>

static inline cdReal RandomReal(TestRng* rng, double lower, double upper)
{
	return (cdReal)TestRngRange(rng, lower, upper);
}

static inline cd3Vec RandomVec(TestRng* rng, double extent)
{
	return cd3MakeVec(RandomReal(rng, -extent, extent), RandomReal(rng, -extent, extent),
					  RandomReal(rng, -extent, extent));
}

static inline cd3Quat RandomQuat(TestRng* rng)
{
	double x, y, z, w, n;
	do
	{
		x = TestRngRange(rng, -1.0, 1.0);
		y = TestRngRange(rng, -1.0, 1.0);
		z = TestRngRange(rng, -1.0, 1.0);
		w = TestRngRange(rng, -1.0, 1.0);
		n = sqrt(x * x + y * y + z * z + w * w);
	} while (n < 0.1 || n > 1.0);
	return cd3MakeQuat((cdReal)(x / n), (cdReal)(y / n), (cdReal)(z / n), (cdReal)(w / n));
}

static inline cd3Vec RandomUnit(TestRng* rng)
{
	cd3Quat q = RandomQuat(rng);
	return cd3RotateVector(q, cd3MakeVec(CD_R(0.0), CD_R(0.0), CD_R(1.0)));
}

/* Hulls for random hull shapes: a fixed pool built once from its own seed (boxes, cylinders,
 * cones and random clouds of 4 to 64 points), so that every program sees the same hulls. The
 * pool and the scaled copies stay allocated until exit (reachable, so no leak is reported). */
#define RANDOM_HULL_POOL 32

static inline const cd3Hull* RandomHull(TestRng* rng)
{
	static cd3Hull* pool[RANDOM_HULL_POOL];
	static bool built = false;
	if (!built)
	{
		TestRng own = {0x5eed4a11u};
		for (int i = 0; i < RANDOM_HULL_POOL; ++i)
		{
			cdResult result = CD_ERROR_DEGENERATE;
			while (result != CD_OK)
			{
				double a = TestRngRange(&own, 0.15, 1.2), b = TestRngRange(&own, 0.15, 1.2);
				double c = TestRngRange(&own, 0.15, 1.2);
				int segments = 3 + TestRngInt(&own, 22);
				switch (i % 4)
				{
					case 0:
						result = cd3MakeBoxHull(cd3MakeVec((cdReal)a, (cdReal)b, (cdReal)c), &pool[i]);
						break;
					case 1:
						result = cd3MakeCylinderHull((cdReal)a, (cdReal)b, segments, &pool[i]);
						break;
					case 2:
						result = cd3MakeConeHull((cdReal)a, (cdReal)b, segments, &pool[i]);
						break;
					default:
					{
						cd3Vec points[64];
						int count = 4 + TestRngInt(&own, 61);
						bool onSphere = TestRngInt(&own, 2) == 0;
						for (int k = 0; k < count; ++k)
						{
							cd3Vec p = cd3MakeVec((cdReal)TestRngRange(&own, -1.0, 1.0),
												  (cdReal)TestRngRange(&own, -1.0, 1.0),
												  (cdReal)TestRngRange(&own, -1.0, 1.0));
							p = onSphere ? cd3Normalize(p) : p;
							points[k] = cd3MulComponents(cd3MakeVec((cdReal)a, (cdReal)b, (cdReal)c), p);
						}
						result = cd3ComputeHull(points, count, &pool[i]);
						break;
					}
				}
			}
		}
		built = true;
	}
	return pool[TestRngInt(rng, RANDOM_HULL_POOL)];
}

/* The hull scaled by k about its origin: a new hull, kept until exit. */
static inline const cd3Hull* ScaledHull(const cd3Hull* hull, cdReal k)
{
	static cd3Hull** kept = NULL;
	static int keptCount = 0, keptCapacity = 0;
	cd3Vec* points = (cd3Vec*)malloc((size_t)hull->vertexCount * sizeof(cd3Vec));
	for (int i = 0; i < hull->vertexCount; ++i)
	{
		points[i] = cd3Scale(k, hull->vertices[i]);
	}
	cd3Hull* scaled = NULL;
	cdResult result = cd3ComputeHull(points, hull->vertexCount, &scaled);
	free(points);
	if (result != CD_OK)
	{
		fprintf(stderr, "ScaledHull: scaling by %g failed: %s\n", (double)k, cdGetResultString(result));
		return hull;
	}
	if (keptCount == keptCapacity)
	{
		keptCapacity = keptCapacity ? 2 * keptCapacity : 256;
		kept = (cd3Hull**)realloc(kept, (size_t)keptCapacity * sizeof(cd3Hull*));
	}
	kept[keptCount++] = scaled;
	return scaled;
}

/* A size in [0, upper), exactly zero one time in eight (degenerate shapes must work too). */
static inline cdReal RandomSize(TestRng* rng, double upper)
{
	return TestRngInt(rng, 8) == 0 ? CD_R(0.0) : RandomReal(rng, 0.0, upper);
}

static inline cd3Shape RandomShape(TestRng* rng, cd3ShapeType type)
{
	cd3Shape s;
	memset(&s, 0, sizeof(s));
	s.type = type;
	cd3Vec center = RandomVec(rng, 2.0);
	switch (type)
	{
		case CD3_SHAPE_SPHERE:
			s.sphere.center = center;
			s.sphere.radius = RandomSize(rng, 1.2);
			break;
		case CD3_SHAPE_CAPSULE:
		{
			cd3Vec half = cd3Scale(RandomSize(rng, 1.2), RandomUnit(rng));
			s.capsule.p1 = cd3Sub(center, half);
			s.capsule.p2 = cd3Add(center, half);
			s.capsule.radius = RandomSize(rng, 0.8);
			break;
		}
		case CD3_SHAPE_AABB:
		{
			cd3Vec half = cd3MakeVec(RandomSize(rng, 1.2), RandomSize(rng, 1.2), RandomSize(rng, 1.2));
			s.aabb.min = cd3Sub(center, half);
			s.aabb.max = cd3Add(center, half);
			break;
		}
		case CD3_SHAPE_BOX:
			s.box.center = center;
			s.box.halfExtents = cd3MakeVec(RandomSize(rng, 1.2), RandomSize(rng, 1.2), RandomSize(rng, 1.2));
			s.box.rotation = RandomQuat(rng);
			break;
		case CD3_SHAPE_TRIANGLE:
			s.triangle.a = cd3Add(center, RandomVec(rng, 1.5));
			s.triangle.b = cd3Add(center, RandomVec(rng, 1.5));
			s.triangle.c = TestRngInt(rng, 10) == 0
							   ? cd3Lerp(s.triangle.a, s.triangle.b, RandomReal(rng, -0.5, 1.5))
							   : cd3Add(center, RandomVec(rng, 1.5));
			break;
		case CD3_SHAPE_PLANE:
			s.plane.normal = RandomUnit(rng);
			s.plane.offset = cd3Dot(s.plane.normal, center) + RandomReal(rng, -1.0, 1.0);
			break;
		case CD3_SHAPE_SEGMENT:
		{
			cd3Vec half = cd3Scale(RandomSize(rng, 1.5), RandomUnit(rng));
			s.segment.p1 = cd3Sub(center, half);
			s.segment.p2 = cd3Add(center, half);
			break;
		}
		case CD3_SHAPE_HULL:
			s.hull.hull = RandomHull(rng);
			s.hull.transform.p = center;
			s.hull.transform.q = RandomQuat(rng);
			break;
		default:
			break;
	}
	return s;
}

static inline cd3Shape TransformShape(const cd3Shape* shape, cd3Transform t)
{
	cd3Shape s = *shape;
	switch (shape->type)
	{
		case CD3_SHAPE_SPHERE:
			s.sphere.center = cd3TransformPoint(t, shape->sphere.center);
			break;
		case CD3_SHAPE_CAPSULE:
			s.capsule.p1 = cd3TransformPoint(t, shape->capsule.p1);
			s.capsule.p2 = cd3TransformPoint(t, shape->capsule.p2);
			break;
		case CD3_SHAPE_AABB: /* translation only */
			s.aabb.min = cd3Add(shape->aabb.min, t.p);
			s.aabb.max = cd3Add(shape->aabb.max, t.p);
			break;
		case CD3_SHAPE_BOX:
			s.box.center = cd3TransformPoint(t, shape->box.center);
			s.box.rotation = cd3NormalizeQuat(cd3MulQuat(t.q, shape->box.rotation));
			break;
		case CD3_SHAPE_TRIANGLE:
			s.triangle.a = cd3TransformPoint(t, shape->triangle.a);
			s.triangle.b = cd3TransformPoint(t, shape->triangle.b);
			s.triangle.c = cd3TransformPoint(t, shape->triangle.c);
			break;
		case CD3_SHAPE_PLANE:
			s.plane.normal = cd3RotateVector(t.q, shape->plane.normal);
			s.plane.offset = shape->plane.offset + cd3Dot(s.plane.normal, t.p);
			break;
		case CD3_SHAPE_SEGMENT:
			s.segment.p1 = cd3TransformPoint(t, shape->segment.p1);
			s.segment.p2 = cd3TransformPoint(t, shape->segment.p2);
			break;
		case CD3_SHAPE_HULL:
			s.hull.transform = cd3MulTransforms(t, shape->hull.transform);
			s.hull.transform.q = cd3NormalizeQuat(s.hull.transform.q);
			break;
		default:
			break;
	}
	return s;
}

/* The shape scaled by k about the origin (positions and sizes alike). */
static inline cd3Shape ScaleShape(const cd3Shape* shape, cdReal k)
{
	cd3Shape s = *shape;
	switch (shape->type)
	{
		case CD3_SHAPE_SPHERE:
			s.sphere.center = cd3Scale(k, shape->sphere.center);
			s.sphere.radius = k * shape->sphere.radius;
			break;
		case CD3_SHAPE_CAPSULE:
			s.capsule.p1 = cd3Scale(k, shape->capsule.p1);
			s.capsule.p2 = cd3Scale(k, shape->capsule.p2);
			s.capsule.radius = k * shape->capsule.radius;
			break;
		case CD3_SHAPE_AABB:
			s.aabb.min = cd3Scale(k, shape->aabb.min);
			s.aabb.max = cd3Scale(k, shape->aabb.max);
			break;
		case CD3_SHAPE_BOX:
			s.box.center = cd3Scale(k, shape->box.center);
			s.box.halfExtents = cd3Scale(k, shape->box.halfExtents);
			break;
		case CD3_SHAPE_TRIANGLE:
			s.triangle.a = cd3Scale(k, shape->triangle.a);
			s.triangle.b = cd3Scale(k, shape->triangle.b);
			s.triangle.c = cd3Scale(k, shape->triangle.c);
			break;
		case CD3_SHAPE_PLANE:
			s.plane.offset = k * shape->plane.offset;
			break;
		case CD3_SHAPE_SEGMENT:
			s.segment.p1 = cd3Scale(k, shape->segment.p1);
			s.segment.p2 = cd3Scale(k, shape->segment.p2);
			break;
		case CD3_SHAPE_HULL:
			s.hull.hull = ScaledHull(shape->hull.hull, k);
			s.hull.transform.p = cd3Scale(k, shape->hull.transform.p);
			break;
		default:
			break;
	}
	return s;
}

static inline const char* TypeName(cd3ShapeType type)
{
	static const char* names[] = {"sphere", "capsule", "aabb", "box", "triangle", "plane", "segment", "hull"};
	return (int)type >= 0 && type < CD3_SHAPE_TYPE_COUNT ? names[type] : "?";
}

static inline void PrintShape(const char* label, const cd3Shape* s)
{
	fprintf(stderr, "  %s %s: ", label, TypeName(s->type));
	switch (s->type)
	{
		case CD3_SHAPE_SPHERE:
			fprintf(stderr, "center (%.9g %.9g %.9g) radius %.9g\n", (double)s->sphere.center.x,
					(double)s->sphere.center.y, (double)s->sphere.center.z, (double)s->sphere.radius);
			break;
		case CD3_SHAPE_CAPSULE:
			fprintf(stderr, "p1 (%.9g %.9g %.9g) p2 (%.9g %.9g %.9g) radius %.9g\n", (double)s->capsule.p1.x,
					(double)s->capsule.p1.y, (double)s->capsule.p1.z, (double)s->capsule.p2.x,
					(double)s->capsule.p2.y, (double)s->capsule.p2.z, (double)s->capsule.radius);
			break;
		case CD3_SHAPE_AABB:
			fprintf(stderr, "min (%.9g %.9g %.9g) max (%.9g %.9g %.9g)\n", (double)s->aabb.min.x,
					(double)s->aabb.min.y, (double)s->aabb.min.z, (double)s->aabb.max.x,
					(double)s->aabb.max.y, (double)s->aabb.max.z);
			break;
		case CD3_SHAPE_BOX:
			fprintf(stderr, "center (%.9g %.9g %.9g) half (%.9g %.9g %.9g) q (%.9g %.9g %.9g %.9g)\n",
					(double)s->box.center.x, (double)s->box.center.y, (double)s->box.center.z,
					(double)s->box.halfExtents.x, (double)s->box.halfExtents.y, (double)s->box.halfExtents.z,
					(double)s->box.rotation.x, (double)s->box.rotation.y, (double)s->box.rotation.z,
					(double)s->box.rotation.w);
			break;
		case CD3_SHAPE_TRIANGLE:
			fprintf(stderr, "a (%.9g %.9g %.9g) b (%.9g %.9g %.9g) c (%.9g %.9g %.9g)\n",
					(double)s->triangle.a.x, (double)s->triangle.a.y, (double)s->triangle.a.z,
					(double)s->triangle.b.x, (double)s->triangle.b.y, (double)s->triangle.b.z,
					(double)s->triangle.c.x, (double)s->triangle.c.y, (double)s->triangle.c.z);
			break;
		case CD3_SHAPE_PLANE:
			fprintf(stderr, "normal (%.9g %.9g %.9g) offset %.9g\n", (double)s->plane.normal.x,
					(double)s->plane.normal.y, (double)s->plane.normal.z, (double)s->plane.offset);
			break;
		case CD3_SHAPE_SEGMENT:
			fprintf(stderr, "p1 (%.9g %.9g %.9g) p2 (%.9g %.9g %.9g)\n", (double)s->segment.p1.x,
					(double)s->segment.p1.y, (double)s->segment.p1.z, (double)s->segment.p2.x,
					(double)s->segment.p2.y, (double)s->segment.p2.z);
			break;
		case CD3_SHAPE_HULL:
		{
			cd3Transform t = s->hull.transform;
			fprintf(stderr, "p (%.9g %.9g %.9g) q (%.9g %.9g %.9g %.9g), %d local vertices:\n", (double)t.p.x,
					(double)t.p.y, (double)t.p.z, (double)t.q.x, (double)t.q.y, (double)t.q.z, (double)t.q.w,
					s->hull.hull->vertexCount);
			for (int i = 0; i < s->hull.hull->vertexCount; ++i)
			{
				cd3Vec v = s->hull.hull->vertices[i];
				fprintf(stderr, "    (%.9g %.9g %.9g)\n", (double)v.x, (double)v.y, (double)v.z);
			}
			break;
		}
		default:
			break;
	}
}

#endif
