/* Test helpers for the 2D query tests: random valid shapes and an independent double-precision
 * reference distance between any two shapes. Header-only, test code only.
 *
 * The reference sees every shape as a convex point set (1 point for a circle, 2 for a capsule or
 * segment, the corners of an AABB or box, the vertices of a polygon) inflated by a radius (a
 * rounded polygon's rounding radius). Two such
 * cores are at distance 0 when a vertex of one lies inside the other (solid, 3+ points) or two edges
 * meet; otherwise their distance is the smallest edge-to-edge distance, computed with the
 * parametric clamping of Ericson 5.1.9 in double, unlike the library's orientation-based code. */
#ifndef COLLIDE_TEST_REFERENCE2_H
#define COLLIDE_TEST_REFERENCE2_H

#include "collide/query2.h"
#include "test.h"

#include <math.h>
#include <stdbool.h>

typedef struct RefVec
{
	double x, y;
} RefVec;

typedef struct RefShape
{
	RefVec points[CD2_MAX_POLYGON_VERTICES];
	int count;
	double radius;
} RefShape;

static inline RefVec RefMake(double x, double y)
{
	RefVec v = {x, y};
	return v;
}

static inline RefVec RefFromVec(cd2Vec v)
{
	return RefMake((double)v.x, (double)v.y);
}

static inline RefVec RefSub(RefVec a, RefVec b)
{
	return RefMake(a.x - b.x, a.y - b.y);
}

static inline double RefDot(RefVec a, RefVec b)
{
	return a.x * b.x + a.y * b.y;
}

static inline double RefCross(RefVec a, RefVec b)
{
	return a.x * b.y - a.y * b.x;
}

static inline double RefDistance2(RefVec a, RefVec b)
{
	return hypot(a.x - b.x, a.y - b.y);
}

static inline double RefClamp01(double t)
{
	return t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
}

static inline double RefPointSegmentDistance(RefVec p, RefVec a, RefVec b)
{
	RefVec d = RefSub(b, a);
	double dd = RefDot(d, d);
	double t = dd > 0.0 ? RefClamp01(RefDot(RefSub(p, a), d) / dd) : 0.0;
	return RefDistance2(p, RefMake(a.x + t * d.x, a.y + t * d.y));
}

/* Ericson, Real-Time Collision Detection, 5.1.9, in double. */
static inline double RefSegmentSegmentDistance(RefVec p1, RefVec q1, RefVec p2, RefVec q2)
{
	RefVec d1 = RefSub(q1, p1), d2 = RefSub(q2, p2), r = RefSub(p1, p2);
	double a = RefDot(d1, d1), e = RefDot(d2, d2), f = RefDot(d2, r);
	double s, t;
	if (a <= 0.0 && e <= 0.0)
	{
		return RefDistance2(p1, p2);
	}
	if (a <= 0.0)
	{
		s = 0.0;
		t = RefClamp01(f / e);
	}
	else
	{
		double c = RefDot(d1, r);
		if (e <= 0.0)
		{
			t = 0.0;
			s = RefClamp01(-c / a);
		}
		else
		{
			double b = RefDot(d1, d2);
			double denom = a * e - b * b;
			s = denom > 0.0 ? RefClamp01((b * f - c * e) / denom) : 0.0;
			t = (b * s + f) / e;
			if (t < 0.0)
			{
				t = 0.0;
				s = RefClamp01(-c / a);
			}
			else if (t > 1.0)
			{
				t = 1.0;
				s = RefClamp01((b - c) / a);
			}
		}
	}
	RefVec c1 = RefMake(p1.x + s * d1.x, p1.y + s * d1.y);
	RefVec c2 = RefMake(p2.x + t * d2.x, p2.y + t * d2.y);
	/* Parallel overlapping segments: the clamped parameters above may pick a non-closest pair, so
	 * also try the endpoints (they realise the minimum whenever the segments do not cross). */
	double best = RefDistance2(c1, c2);
	best = fmin(best, RefPointSegmentDistance(p1, p2, q2));
	best = fmin(best, RefPointSegmentDistance(q1, p2, q2));
	best = fmin(best, RefPointSegmentDistance(p2, p1, q1));
	best = fmin(best, RefPointSegmentDistance(q2, p1, q1));
	return best;
}

/* Inside (or on) a counter-clockwise convex polygon of 3+ points. */
static inline bool RefPointInConvex(RefVec p, const RefShape* s)
{
	/* A zero-area set (a zero-size box or AABB) has no interior: its edges carry its distance. */
	double twiceArea = 0.0;
	for (int i = 0; i < s->count; ++i)
	{
		twiceArea += RefCross(s->points[i], s->points[(i + 1) % s->count]);
	}
	if (s->count < 3 || !(twiceArea > 0.0))
	{
		return false;
	}
	for (int i = 0; i < s->count; ++i)
	{
		RefVec a = s->points[i], b = s->points[(i + 1) % s->count];
		if (RefCross(RefSub(b, a), RefSub(p, a)) < 0.0)
		{
			return false;
		}
	}
	return true;
}

static inline RefShape RefFromShape(const cd2Shape* shape)
{
	RefShape r = {{{0.0, 0.0}}, 0, 0.0};
	switch (shape->type)
	{
		case CD2_SHAPE_CIRCLE:
			r.count = 1;
			r.points[0] = RefFromVec(shape->circle.center);
			r.radius = (double)shape->circle.radius;
			break;
		case CD2_SHAPE_CAPSULE:
			r.count = 2;
			r.points[0] = RefFromVec(shape->capsule.p1);
			r.points[1] = RefFromVec(shape->capsule.p2);
			r.radius = (double)shape->capsule.radius;
			break;
		case CD2_SHAPE_AABB:
		{
			cd2Aabb b = shape->aabb;
			r.count = 4;
			r.points[0] = RefMake((double)b.min.x, (double)b.min.y);
			r.points[1] = RefMake((double)b.max.x, (double)b.min.y);
			r.points[2] = RefMake((double)b.max.x, (double)b.max.y);
			r.points[3] = RefMake((double)b.min.x, (double)b.max.y);
			break;
		}
		case CD2_SHAPE_BOX:
		{
			cd2Box b = shape->box;
			double length = hypot((double)b.rotation.c, (double)b.rotation.s);
			double c = (double)b.rotation.c / length, s = (double)b.rotation.s / length;
			double hx = (double)b.halfExtents.x, hy = (double)b.halfExtents.y;
			static const double signs[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
			r.count = 4;
			for (int i = 0; i < 4; ++i)
			{
				double lx = signs[i][0] * hx, ly = signs[i][1] * hy;
				r.points[i] =
					RefMake((double)b.center.x + c * lx - s * ly, (double)b.center.y + s * lx + c * ly);
			}
			break;
		}
		case CD2_SHAPE_POLYGON:
			r.count = shape->polygon.count;
			for (int i = 0; i < r.count; ++i)
			{
				r.points[i] = RefFromVec(shape->polygon.vertices[i]);
			}
			r.radius = (double)shape->polygon.radius;
			break;
		case CD2_SHAPE_SEGMENT:
			r.count = 2;
			r.points[0] = RefFromVec(shape->segment.p1);
			r.points[1] = RefFromVec(shape->segment.p2);
			break;
		default:
			break;
	}
	return r;
}

/* Distance between the cores (radius ignored). */
static inline double RefCoreDistance(const RefShape* a, const RefShape* b)
{
	for (int i = 0; i < b->count; ++i)
	{
		if (RefPointInConvex(b->points[i], a))
		{
			return 0.0;
		}
	}
	for (int i = 0; i < a->count; ++i)
	{
		if (RefPointInConvex(a->points[i], b))
		{
			return 0.0;
		}
	}
	double best = INFINITY;
	for (int i = 0; i < a->count; ++i)
	{
		RefVec a1 = a->points[i], a2 = a->points[(i + 1) % a->count];
		for (int j = 0; j < b->count; ++j)
		{
			RefVec b1 = b->points[j], b2 = b->points[(j + 1) % b->count];
			best = fmin(best, RefSegmentSegmentDistance(a1, a2, b1, b2));
		}
	}
	return best;
}

/* Distance between two shapes, 0 when they overlap. */
static inline double RefShapeDistance(const cd2Shape* a, const cd2Shape* b)
{
	RefShape ra = RefFromShape(a), rb = RefFromShape(b);
	return fmax(0.0, RefCoreDistance(&ra, &rb) - ra.radius - rb.radius);
}

/* Largest |coordinate| or size of a shape (to scale tolerances). */
static inline double RefShapeScale(const cd2Shape* s)
{
	RefShape r = RefFromShape(s);
	double scale = r.radius;
	for (int i = 0; i < r.count; ++i)
	{
		scale = fmax(scale, fmax(fabs(r.points[i].x), fabs(r.points[i].y)));
	}
	return scale;
}

/* Distance from p to the shape (0 inside a solid). */
static inline double RefPointShapeDistance(const cd2Shape* shape, cd2Vec p)
{
	cd2Circle point = {p, (cdReal)0};
	cd2Shape pointShape = cd2MakeCircleShape(point);
	return RefShapeDistance(shape, &pointShape);
}

/* ---- random shapes ---------------------------------------------------------------------------- */

static inline cdReal RandomReal(TestRng* rng, double lower, double upper)
{
	return (cdReal)TestRngRange(rng, lower, upper);
}

/* A size in [0, extent], exactly zero one time in eight (degenerate shapes are valid). */
static inline cdReal RandomSize(TestRng* rng, double extent)
{
	return TestRngInt(rng, 8) == 0 ? (cdReal)0 : RandomReal(rng, 0.0, extent);
}

static inline cd2Vec RandomVec(TestRng* rng, cd2Vec center, double extent)
{
	return cd2MakeVec(center.x + RandomReal(rng, -extent, extent),
					  center.y + RandomReal(rng, -extent, extent));
}

/* Random points around the origin in [-1, 1]^2 that the builder accepts. */
static inline cd2Polygon RandomUnitPolygon(TestRng* rng)
{
	cd2Polygon polygon;
	for (;;)
	{
		cd2Vec points[CD2_MAX_POLYGON_VERTICES];
		int count = 3 + TestRngInt(rng, CD2_MAX_POLYGON_VERTICES - 2);
		for (int i = 0; i < count; ++i)
		{
			points[i] = RandomVec(rng, CD2_VEC_ZERO, 1.0);
		}
		if (cd2MakePolygon(points, count, &polygon) == CD_OK)
		{
			return polygon;
		}
	}
}

/* A random polygon of 3 to 8 random points around center. Where the builder's weld tolerance is
 * too coarse for `extent` (tiny shapes), a unit polygon is scaled instead (that keeps it valid). */
static inline cd2Polygon RandomPolygon(TestRng* rng, cd2Vec center, double extent)
{
	cd2Polygon polygon;
	for (int attempt = 0; attempt < 50; ++attempt)
	{
		cd2Vec points[CD2_MAX_POLYGON_VERTICES];
		int count = 3 + TestRngInt(rng, CD2_MAX_POLYGON_VERTICES - 2);
		for (int i = 0; i < count; ++i)
		{
			points[i] = RandomVec(rng, center, extent);
		}
		if (cd2MakePolygon(points, count, &polygon) == CD_OK)
		{
			return polygon;
		}
	}
	polygon = RandomUnitPolygon(rng);
	for (int i = 0; i < polygon.count; ++i)
	{
		polygon.vertices[i] = cd2MulAdd(center, (cdReal)extent, polygon.vertices[i]);
	}
	polygon.centroid = cd2MulAdd(center, (cdReal)extent, polygon.centroid);
	return polygon;
}

/* A random valid shape of the given type near center, of size about `extent`. */
static inline cd2Shape RandomShape(TestRng* rng, cd2ShapeType type, cd2Vec center, double extent)
{
	switch (type)
	{
		case CD2_SHAPE_CIRCLE:
		{
			cd2Circle c = {RandomVec(rng, center, extent), RandomSize(rng, extent)};
			return cd2MakeCircleShape(c);
		}
		case CD2_SHAPE_CAPSULE:
		{
			cd2Vec p1 = RandomVec(rng, center, extent);
			cd2Vec p2 = TestRngInt(rng, 8) == 0 ? p1 : RandomVec(rng, center, extent);
			cd2Capsule c = {p1, p2, RandomSize(rng, 0.5 * extent)};
			return cd2MakeCapsuleShape(c);
		}
		case CD2_SHAPE_AABB:
		{
			cd2Vec c = RandomVec(rng, center, extent);
			cd2Vec h = {RandomSize(rng, extent), RandomSize(rng, extent)};
			cd2Aabb b = {cd2Sub(c, h), cd2Add(c, h)};
			return cd2MakeAabbShape(b);
		}
		case CD2_SHAPE_BOX:
		{
			cd2Box b = {RandomVec(rng, center, extent),
						{RandomSize(rng, extent), RandomSize(rng, extent)},
						cd2MakeRot(RandomReal(rng, -CD_PI, CD_PI))};
			return cd2MakeBoxShape(b);
		}
		case CD2_SHAPE_POLYGON:
		{
			/* Rounded one time in three. */
			cd2Polygon p = RandomPolygon(rng, RandomVec(rng, center, extent), extent);
			p.radius = TestRngInt(rng, 3) == 0 ? RandomReal(rng, 0.0, 0.5 * extent) : (cdReal)0;
			return cd2MakePolygonShape(&p);
		}
		case CD2_SHAPE_SEGMENT:
		default:
		{
			cd2Vec p1 = RandomVec(rng, center, extent);
			cd2Vec p2 = TestRngInt(rng, 8) == 0 ? p1 : RandomVec(rng, center, extent);
			cd2Segment g = {p1, p2};
			return cd2MakeSegmentShape(g);
		}
	}
}

#endif
