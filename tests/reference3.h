/* Double-precision reference geometry for the 3D query tests: random shapes, point projection,
 * support functions, uniform samples, and a rigorous distance bracket between two shapes.
 *
 * Written independently of src/query: the triangle projection goes through the plane and the
 * barycentric signs (not Voronoi regions), and the distance between shapes comes from
 * alternating projections (von Neumann) for an upper bound and the support functions along the
 * final direction for a lower bound, so [lower, upper] always brackets the true distance. */
#ifndef COLLIDE_TEST_REFERENCE3_H
#define COLLIDE_TEST_REFERENCE3_H

#include "collide/query3.h"
#include "test.h"

#include <math.h>

typedef struct RVec
{
	double x, y, z;
} RVec;

static inline RVec RMake(double x, double y, double z)
{
	RVec v = {x, y, z};
	return v;
}
static inline RVec RAdd(RVec a, RVec b)
{
	return RMake(a.x + b.x, a.y + b.y, a.z + b.z);
}
static inline RVec RSub(RVec a, RVec b)
{
	return RMake(a.x - b.x, a.y - b.y, a.z - b.z);
}
static inline RVec RScale(double s, RVec a)
{
	return RMake(s * a.x, s * a.y, s * a.z);
}
static inline double RDot(RVec a, RVec b)
{
	return a.x * b.x + a.y * b.y + a.z * b.z;
}
static inline RVec RCross(RVec a, RVec b)
{
	return RMake(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline double RLength(RVec a)
{
	return sqrt(RDot(a, a));
}
static inline double RDist(RVec a, RVec b)
{
	return RLength(RSub(a, b));
}
static inline double RClamp(double a, double lo, double hi)
{
	return a < lo ? lo : (a > hi ? hi : a);
}
static inline double RMaxAbs(RVec v)
{
	return fmax(fabs(v.x), fmax(fabs(v.y), fabs(v.z)));
}
static inline RVec RFromVec(cd3Vec v)
{
	return RMake((double)v.x, (double)v.y, (double)v.z);
}
static inline cd3Vec RToVec(RVec v)
{
	return cd3MakeVec((cdReal)v.x, (cdReal)v.y, (cdReal)v.z);
}

/* A shape in double; boxes carry their rotation as three orthonormal axes. */
typedef struct RShape
{
	cd3ShapeType type;
	RVec p[3];	   /* sphere: p[0] center; capsule/segment: p[0], p[1]; triangle: p[0..2];
					  aabb: min, max; box: center, halfExtents; plane: normal */
	RVec axis[3];  /* box axes */
	double radius; /* sphere/capsule radius; plane offset */
} RShape;

static inline RShape RFromShape(const cd3Shape* s)
{
	RShape r;
	r.type = s->type;
	r.p[0] = r.p[1] = r.p[2] = RMake(0, 0, 0);
	r.radius = 0.0;
	r.axis[0] = RMake(1, 0, 0);
	r.axis[1] = RMake(0, 1, 0);
	r.axis[2] = RMake(0, 0, 1);
	switch (s->type)
	{
		case CD3_SHAPE_SPHERE:
			r.p[0] = RFromVec(s->sphere.center);
			r.radius = (double)s->sphere.radius;
			break;
		case CD3_SHAPE_CAPSULE:
			r.p[0] = RFromVec(s->capsule.p1);
			r.p[1] = RFromVec(s->capsule.p2);
			r.radius = (double)s->capsule.radius;
			break;
		case CD3_SHAPE_AABB:
			r.p[0] = RFromVec(s->aabb.min);
			r.p[1] = RFromVec(s->aabb.max);
			break;
		case CD3_SHAPE_BOX:
		{
			r.p[0] = RFromVec(s->box.center);
			r.p[1] = RFromVec(s->box.halfExtents);
			double x = (double)s->box.rotation.x, y = (double)s->box.rotation.y,
				   z = (double)s->box.rotation.z, w = (double)s->box.rotation.w;
			double n = sqrt(x * x + y * y + z * z + w * w);
			x /= n;
			y /= n;
			z /= n;
			w /= n;
			r.axis[0] = RMake(1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y));
			r.axis[1] = RMake(2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x));
			r.axis[2] = RMake(2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y));
			break;
		}
		case CD3_SHAPE_TRIANGLE:
			r.p[0] = RFromVec(s->triangle.a);
			r.p[1] = RFromVec(s->triangle.b);
			r.p[2] = RFromVec(s->triangle.c);
			break;
		case CD3_SHAPE_PLANE:
			r.p[0] = RFromVec(s->plane.normal);
			r.radius = (double)s->plane.offset;
			break;
		case CD3_SHAPE_SEGMENT:
			r.p[0] = RFromVec(s->segment.p1);
			r.p[1] = RFromVec(s->segment.p2);
			break;
		default:
			break;
	}
	return r;
}

static inline RVec RProjectSegment(RVec a, RVec b, RVec p)
{
	RVec d = RSub(b, a);
	double dd = RDot(d, d);
	if (dd == 0.0)
	{
		return a;
	}
	return RAdd(a, RScale(RClamp(RDot(RSub(p, a), d) / dd, 0.0, 1.0), d));
}

static inline RVec RProjectBall(RVec c, double radius, RVec p)
{
	RVec d = RSub(p, c);
	double length = RLength(d);
	if (length <= radius)
	{
		return p;
	}
	return RAdd(c, RScale(radius / length, d));
}

/* Through the plane: project, accept when all three edge tests agree with the normal's side,
 * otherwise the nearest edge point. */
static inline RVec RProjectTriangle(RVec a, RVec b, RVec c, RVec p)
{
	RVec n = RCross(RSub(b, a), RSub(c, a));
	double nn = RDot(n, n);
	double scale = fmax(RMaxAbs(RSub(b, a)), RMaxAbs(RSub(c, a)));
	if (nn > 1e-24 * scale * scale * scale * scale)
	{
		RVec q = RSub(p, RScale(RDot(RSub(p, a), n) / nn, n));
		if (RDot(n, RCross(RSub(b, a), RSub(q, a))) >= 0 && RDot(n, RCross(RSub(c, b), RSub(q, b))) >= 0 &&
			RDot(n, RCross(RSub(a, c), RSub(q, c))) >= 0)
		{
			return q;
		}
	}
	RVec best = RProjectSegment(a, b, p);
	RVec e2 = RProjectSegment(b, c, p);
	RVec e3 = RProjectSegment(c, a, p);
	if (RDist(e2, p) < RDist(best, p))
	{
		best = e2;
	}
	if (RDist(e3, p) < RDist(best, p))
	{
		best = e3;
	}
	return best;
}

static inline RVec RProject(const RShape* s, RVec p)
{
	switch (s->type)
	{
		case CD3_SHAPE_SPHERE:
			return RProjectBall(s->p[0], s->radius, p);
		case CD3_SHAPE_CAPSULE:
			return RProjectBall(RProjectSegment(s->p[0], s->p[1], p), s->radius, p);
		case CD3_SHAPE_AABB:
			return RMake(RClamp(p.x, s->p[0].x, s->p[1].x), RClamp(p.y, s->p[0].y, s->p[1].y),
						 RClamp(p.z, s->p[0].z, s->p[1].z));
		case CD3_SHAPE_BOX:
		{
			RVec d = RSub(p, s->p[0]);
			double h[3] = {s->p[1].x, s->p[1].y, s->p[1].z};
			RVec q = s->p[0];
			for (int i = 0; i < 3; ++i)
			{
				q = RAdd(q, RScale(RClamp(RDot(d, s->axis[i]), -h[i], h[i]), s->axis[i]));
			}
			return q;
		}
		case CD3_SHAPE_TRIANGLE:
			return RProjectTriangle(s->p[0], s->p[1], s->p[2], p);
		case CD3_SHAPE_PLANE:
		{
			double height = RDot(s->p[0], p) - s->radius;
			if (height <= 0)
			{
				return p;
			}
			return RSub(p, RScale(height / RDot(s->p[0], s->p[0]), s->p[0]));
		}
		case CD3_SHAPE_SEGMENT:
			return RProjectSegment(s->p[0], s->p[1], p);
		default:
			return p;
	}
}

/* A point of s maximizing dot(direction, x); not for planes. */
static inline RVec RSupport(const RShape* s, RVec direction)
{
	double length = RLength(direction);
	RVec unit = length > 0 ? RScale(1.0 / length, direction) : RMake(0, 0, 0);
	switch (s->type)
	{
		case CD3_SHAPE_SPHERE:
			return RAdd(s->p[0], RScale(s->radius, unit));
		case CD3_SHAPE_CAPSULE:
		{
			RVec base = RDot(s->p[0], direction) >= RDot(s->p[1], direction) ? s->p[0] : s->p[1];
			return RAdd(base, RScale(s->radius, unit));
		}
		case CD3_SHAPE_AABB:
			return RMake(direction.x >= 0 ? s->p[1].x : s->p[0].x, direction.y >= 0 ? s->p[1].y : s->p[0].y,
						 direction.z >= 0 ? s->p[1].z : s->p[0].z);
		case CD3_SHAPE_BOX:
		{
			double h[3] = {s->p[1].x, s->p[1].y, s->p[1].z};
			RVec q = s->p[0];
			for (int i = 0; i < 3; ++i)
			{
				q = RAdd(q, RScale(RDot(direction, s->axis[i]) >= 0 ? h[i] : -h[i], s->axis[i]));
			}
			return q;
		}
		case CD3_SHAPE_TRIANGLE:
		case CD3_SHAPE_SEGMENT:
		{
			int count = s->type == CD3_SHAPE_TRIANGLE ? 3 : 2;
			RVec best = s->p[0];
			for (int i = 1; i < count; ++i)
			{
				if (RDot(s->p[i], direction) > RDot(best, direction))
				{
					best = s->p[i];
				}
			}
			return best;
		}
		default:
			return RMake(0, 0, 0);
	}
}

/* A point of the shape (some interior point for solids); planes: the point nearest the origin. */
static inline RVec RReferencePoint(const RShape* s)
{
	switch (s->type)
	{
		case CD3_SHAPE_AABB:
			return RScale(0.5, RAdd(s->p[0], s->p[1]));
		case CD3_SHAPE_TRIANGLE:
			return RScale(1.0 / 3.0, RAdd(s->p[0], RAdd(s->p[1], s->p[2])));
		case CD3_SHAPE_PLANE:
			return RScale(s->radius / RDot(s->p[0], s->p[0]), s->p[0]);
		case CD3_SHAPE_CAPSULE:
		case CD3_SHAPE_SEGMENT:
			return RScale(0.5, RAdd(s->p[0], s->p[1]));
		default:
			return s->p[0];
	}
}

/* Largest coordinate magnitude of the shape's defining data (for relative tolerances). */
static inline double RShapeScale(const RShape* s)
{
	double scale = fabs(s->radius);
	if (s->type == CD3_SHAPE_PLANE)
	{
		return scale; /* p[0] is the unit normal, not a coordinate */
	}
	for (int i = 0; i < 3; ++i)
	{
		scale = fmax(scale, RMaxAbs(s->p[i]));
	}
	return scale;
}

/* Uniform-ish random point of the shape (solids: interior; triangle/segment: on it). Planes:
 * a random point of the half-space within `reach` of `near`. */
static inline RVec RSample(const RShape* s, TestRng* rng, RVec near, double reach)
{
	switch (s->type)
	{
		case CD3_SHAPE_SPHERE:
		case CD3_SHAPE_CAPSULE:
		{
			RVec center = s->type == CD3_SHAPE_SPHERE
							  ? s->p[0]
							  : RAdd(s->p[0], RScale(TestRngRange(rng, 0, 1), RSub(s->p[1], s->p[0])));
			RVec d;
			do
			{
				d = RMake(TestRngRange(rng, -1, 1), TestRngRange(rng, -1, 1), TestRngRange(rng, -1, 1));
			} while (RDot(d, d) > 1.0);
			/* Half of the samples on the boundary, where the closest points live. */
			if (TestRngInt(rng, 2) == 0 && RLength(d) > 0)
			{
				d = RScale(1.0 / RLength(d), d);
			}
			return RAdd(center, RScale(s->radius, d));
		}
		case CD3_SHAPE_AABB:
			return RMake(TestRngRange(rng, s->p[0].x, s->p[1].x), TestRngRange(rng, s->p[0].y, s->p[1].y),
						 TestRngRange(rng, s->p[0].z, s->p[1].z));
		case CD3_SHAPE_BOX:
		{
			double h[3] = {s->p[1].x, s->p[1].y, s->p[1].z};
			RVec q = s->p[0];
			int face = TestRngInt(rng, 4); /* 3 of 4 samples on a face */
			for (int i = 0; i < 3; ++i)
			{
				double c = TestRngRange(rng, -h[i], h[i]);
				if (face == i)
				{
					c = TestRngInt(rng, 2) ? h[i] : -h[i];
				}
				q = RAdd(q, RScale(c, s->axis[i]));
			}
			return q;
		}
		case CD3_SHAPE_TRIANGLE:
		{
			double u = TestRngRange(rng, 0, 1), v = TestRngRange(rng, 0, 1);
			if (u + v > 1)
			{
				u = 1 - u;
				v = 1 - v;
			}
			return RAdd(s->p[0], RAdd(RScale(u, RSub(s->p[1], s->p[0])), RScale(v, RSub(s->p[2], s->p[0]))));
		}
		case CD3_SHAPE_SEGMENT:
			return RAdd(s->p[0], RScale(TestRngRange(rng, 0, 1), RSub(s->p[1], s->p[0])));
		case CD3_SHAPE_PLANE:
		{
			RVec q = RAdd(near, RMake(TestRngRange(rng, -reach, reach), TestRngRange(rng, -reach, reach),
									  TestRngRange(rng, -reach, reach)));
			return RProject(s, q);
		}
		default:
			return near;
	}
}

/* Bracket of the distance between two shapes: lower <= distance <= upper. */
typedef struct RDistance
{
	double lower, upper;
	RVec pointA, pointB; /* the pair that realizes upper */
} RDistance;

/* Distance from a bounded shape to a half-space, exactly. */
static inline RDistance RDistanceToPlane(const RShape* other, const RShape* plane)
{
	RVec n = plane->p[0];
	RVec deepest = RSupport(other, RScale(-1.0, n));
	double gap = (RDot(n, deepest) - plane->radius) / RLength(n);
	RDistance d;
	d.lower = d.upper = fmax(gap, 0.0);
	d.pointA = deepest;
	d.pointB = RProject(plane, deepest);
	return d;
}

static inline RDistance RComputeDistance(const RShape* a, const RShape* b)
{
	RDistance d;
	if (a->type == CD3_SHAPE_PLANE && b->type == CD3_SHAPE_PLANE)
	{
		/* Opposite normals and apart: the gap; otherwise they meet. */
		RVec na = a->p[0], nb = b->p[0];
		double sine = RLength(RCross(na, nb));
		double gap = -(a->radius + b->radius);
		d.lower = d.upper = (RDot(na, nb) < 0 && sine < 1e-12 && gap > 0) ? gap : 0.0;
		d.pointA = d.pointB = RMake(0, 0, 0);
		return d;
	}
	if (b->type == CD3_SHAPE_PLANE)
	{
		return RDistanceToPlane(a, b);
	}
	if (a->type == CD3_SHAPE_PLANE)
	{
		RDistance flipped = RDistanceToPlane(b, a);
		d = flipped;
		d.pointA = flipped.pointB;
		d.pointB = flipped.pointA;
		return d;
	}
	double scale = fmax(RShapeScale(a), RShapeScale(b));
	RVec x = RReferencePoint(b);
	d.lower = 0.0;
	d.upper = INFINITY;
	d.pointA = d.pointB = x;
	for (int iteration = 0; iteration < 400; ++iteration)
	{
		RVec pa = RProject(a, x);
		RVec pb = RProject(b, pa);
		double gap = RDist(pa, pb);
		if (gap < d.upper)
		{
			d.upper = gap;
			d.pointA = pa;
			d.pointB = pb;
		}
		if (gap == 0.0)
		{
			break;
		}
		RVec w = RSub(pa, pb); /* from B toward A */
		double lowestA = RDot(w, RSupport(a, RScale(-1.0, w)));
		double highestB = RDot(w, RSupport(b, w));
		d.lower = fmax(d.lower, (lowestA - highestB) / RLength(w));
		if (d.upper - d.lower <= 1e-11 * fmax(scale, 1e-300) || d.upper <= 1e-14 * scale)
		{
			break;
		}
		x = pb;
	}
	return d;
}

/* ---- random shapes ------------------------------------------------------------------------- */

static inline cd3Vec RandomVec(TestRng* rng, double lo, double hi)
{
	return cd3MakeVec((cdReal)TestRngRange(rng, lo, hi), (cdReal)TestRngRange(rng, lo, hi),
					  (cdReal)TestRngRange(rng, lo, hi));
}

static inline cd3Quat RandomQuat(TestRng* rng)
{
	for (;;)
	{
		double x = TestRngRange(rng, -1, 1), y = TestRngRange(rng, -1, 1), z = TestRngRange(rng, -1, 1),
			   w = TestRngRange(rng, -1, 1);
		double n = sqrt(x * x + y * y + z * z + w * w);
		if (n > 0.1 && n <= 1.0)
		{
			return cd3MakeQuat((cdReal)(x / n), (cdReal)(y / n), (cdReal)(z / n), (cdReal)(w / n));
		}
	}
}

static inline cd3Vec RandomUnit(TestRng* rng)
{
	for (;;)
	{
		double x = TestRngRange(rng, -1, 1), y = TestRngRange(rng, -1, 1), z = TestRngRange(rng, -1, 1);
		double n = sqrt(x * x + y * y + z * z);
		if (n > 0.1 && n <= 1.0)
		{
			return cd3MakeVec((cdReal)(x / n), (cdReal)(y / n), (cdReal)(z / n));
		}
	}
}

/* A random shape of the given type around the origin (coordinates within about +-3, sizes up to
 * about 1.5), scaled by `scale`. One in ten is degenerate (zero radius or size, zero length). */
static inline cd3Shape RandomShape(TestRng* rng, cd3ShapeType type, double scale)
{
	bool degenerate = TestRngInt(rng, 10) == 0;
	cd3Shape s;
	s.type = type;
	cdReal k = (cdReal)scale;
	switch (type)
	{
		case CD3_SHAPE_SPHERE:
			s.sphere.center = cd3Scale(k, RandomVec(rng, -2, 2));
			s.sphere.radius = degenerate ? CD_R(0.0) : k * (cdReal)TestRngRange(rng, 0.05, 1.5);
			break;
		case CD3_SHAPE_CAPSULE:
			s.capsule.p1 = cd3Scale(k, RandomVec(rng, -2, 2));
			s.capsule.p2 =
				degenerate ? s.capsule.p1 : cd3Add(s.capsule.p1, cd3Scale(k, RandomVec(rng, -1.5, 1.5)));
			s.capsule.radius =
				(degenerate && TestRngInt(rng, 2)) ? CD_R(0.0) : k * (cdReal)TestRngRange(rng, 0.05, 1.0);
			break;
		case CD3_SHAPE_AABB:
		{
			cd3Vec c = cd3Scale(k, RandomVec(rng, -2, 2));
			cd3Vec h = cd3Scale(k, RandomVec(rng, 0.05, 1.5));
			if (degenerate)
			{
				h.x = CD_R(0.0);
				if (TestRngInt(rng, 2))
				{
					h = CD3_VEC_ZERO;
				}
			}
			s.aabb.min = cd3Sub(c, h);
			s.aabb.max = cd3Add(c, h);
			break;
		}
		case CD3_SHAPE_BOX:
			s.box.center = cd3Scale(k, RandomVec(rng, -2, 2));
			s.box.halfExtents = cd3Scale(k, RandomVec(rng, 0.05, 1.5));
			if (degenerate)
			{
				s.box.halfExtents.y = CD_R(0.0);
				if (TestRngInt(rng, 2))
				{
					s.box.halfExtents = CD3_VEC_ZERO;
				}
			}
			s.box.rotation = RandomQuat(rng);
			break;
		case CD3_SHAPE_TRIANGLE:
			s.triangle.a = cd3Scale(k, RandomVec(rng, -2.5, 2.5));
			s.triangle.b = cd3Add(s.triangle.a, cd3Scale(k, RandomVec(rng, -2, 2)));
			s.triangle.c = cd3Add(s.triangle.a, cd3Scale(k, RandomVec(rng, -2, 2)));
			if (degenerate)
			{
				/* Collinear, or all three at one point. */
				s.triangle.c =
					TestRngInt(rng, 2) ? cd3Lerp(s.triangle.a, s.triangle.b, CD_R(0.5)) : s.triangle.a;
				if (TestRngInt(rng, 3) == 0)
				{
					s.triangle.b = s.triangle.c = s.triangle.a;
				}
			}
			break;
		case CD3_SHAPE_PLANE:
			s.plane.normal = RandomUnit(rng);
			s.plane.offset = k * (cdReal)TestRngRange(rng, -2, 2);
			break;
		case CD3_SHAPE_SEGMENT:
		default:
			s.type = CD3_SHAPE_SEGMENT;
			s.segment.p1 = cd3Scale(k, RandomVec(rng, -2.5, 2.5));
			s.segment.p2 =
				degenerate ? s.segment.p1 : cd3Add(s.segment.p1, cd3Scale(k, RandomVec(rng, -3, 3)));
			break;
	}
	return s;
}

/* The shape moved by x -> q x + p (AABBs: translation only). */
static inline cd3Shape TransformShape(const cd3Shape* s, cd3Transform t)
{
	cd3Shape r = *s;
	switch (s->type)
	{
		case CD3_SHAPE_SPHERE:
			r.sphere.center = cd3TransformPoint(t, s->sphere.center);
			break;
		case CD3_SHAPE_CAPSULE:
			r.capsule.p1 = cd3TransformPoint(t, s->capsule.p1);
			r.capsule.p2 = cd3TransformPoint(t, s->capsule.p2);
			break;
		case CD3_SHAPE_AABB:
			r.aabb.min = cd3Add(s->aabb.min, t.p);
			r.aabb.max = cd3Add(s->aabb.max, t.p);
			break;
		case CD3_SHAPE_BOX:
			r.box.center = cd3TransformPoint(t, s->box.center);
			r.box.rotation = cd3NormalizeQuat(cd3MulQuat(t.q, s->box.rotation));
			break;
		case CD3_SHAPE_TRIANGLE:
			r.triangle.a = cd3TransformPoint(t, s->triangle.a);
			r.triangle.b = cd3TransformPoint(t, s->triangle.b);
			r.triangle.c = cd3TransformPoint(t, s->triangle.c);
			break;
		case CD3_SHAPE_PLANE:
			r.plane.normal = cd3RotateVector(t.q, s->plane.normal);
			r.plane.offset = s->plane.offset + cd3Dot(r.plane.normal, t.p);
			break;
		case CD3_SHAPE_SEGMENT:
			r.segment.p1 = cd3TransformPoint(t, s->segment.p1);
			r.segment.p2 = cd3TransformPoint(t, s->segment.p2);
			break;
		default:
			break;
	}
	return r;
}

#endif
