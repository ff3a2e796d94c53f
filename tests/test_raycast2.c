/* Tests of the 2D ray casts: exact cases per shape, property tests against an independent
 * double-precision reference (a convex function that is <= 0 exactly on each solid shape, searched
 * along the ray; Cramer's rule for segments), support functions for the normals, rigid-transform
 * and scale invariance, and agreement with the 3D casts on the same configuration in z = 0. */
#include "collide/query2.h"
#include "collide/query3.h"
#include "test.h"

#if CD_DOUBLE
#define TOL 1e-9
#define BAND 1e-6
#else
#define TOL 2e-4
#define BAND 1e-2
#endif

/* ---- double-precision vectors ---------------------------------------------------------------- */
typedef struct DVec
{
	double x, y;
} DVec;

static DVec DMake(double x, double y)
{
	DVec v = {x, y};
	return v;
}

static DVec D(cd2Vec v)
{
	return DMake((double)v.x, (double)v.y);
}

static cd2Vec V(DVec v)
{
	return cd2MakeVec((cdReal)v.x, (cdReal)v.y);
}

static DVec DAdd(DVec a, DVec b)
{
	return DMake(a.x + b.x, a.y + b.y);
}

static DVec DSub(DVec a, DVec b)
{
	return DMake(a.x - b.x, a.y - b.y);
}

static DVec DScale(double s, DVec a)
{
	return DMake(s * a.x, s * a.y);
}

static double DDot(DVec a, DVec b)
{
	return a.x * b.x + a.y * b.y;
}

static double DCross(DVec a, DVec b)
{
	return a.x * b.y - a.y * b.x;
}

static double DLength(DVec a)
{
	return sqrt(DDot(a, a));
}

static DVec DNormalize(DVec a)
{
	double length = DLength(a);
	return length > 0.0 ? DScale(1.0 / length, a) : DMake(0.0, 0.0);
}

/* Rotation by the angle of (c, s), renormalized in double. */
static DVec DRotate(cd2Rot q, DVec v)
{
	double n = sqrt((double)q.c * q.c + (double)q.s * q.s), c = q.c / n, s = q.s / n;
	return DMake(c * v.x - s * v.y, s * v.x + c * v.y);
}

static DVec DInvRotate(cd2Rot q, DVec v)
{
	cd2Rot inverse = {q.c, -q.s};
	return DRotate(inverse, v);
}

/* ---- reference geometry in double ----------------------------------------------------------------- */

static double RefDistanceToSegment(DVec p, DVec a, DVec b)
{
	DVec ab = DSub(b, a);
	double lengthSquared = DDot(ab, ab);
	double s = lengthSquared > 0.0 ? DDot(DSub(p, a), ab) / lengthSquared : 0.0;
	s = s < 0.0 ? 0.0 : (s > 1.0 ? 1.0 : s);
	return DLength(DSub(p, DAdd(a, DScale(s, ab))));
}

/* Convex, <= 0 exactly on the solid shape. Polygon edges come from the vertices alone (the stored
 * normals are what the library reads, so the reference does not trust them). */
static double RefValue(const cd2Shape* s, DVec p)
{
	switch (s->type)
	{
		case CD2_SHAPE_CIRCLE:
			return DLength(DSub(p, D(s->circle.center))) - (double)s->circle.radius;
		case CD2_SHAPE_CAPSULE:
			return RefDistanceToSegment(p, D(s->capsule.p1), D(s->capsule.p2)) - (double)s->capsule.radius;
		case CD2_SHAPE_AABB:
		{
			DVec lo = D(s->aabb.min), hi = D(s->aabb.max);
			return fmax(fmax(lo.x - p.x, p.x - hi.x), fmax(lo.y - p.y, p.y - hi.y));
		}
		case CD2_SHAPE_BOX:
		{
			DVec local = DInvRotate(s->box.rotation, DSub(p, D(s->box.center)));
			return fmax(fabs(local.x) - (double)s->box.halfExtents.x,
						fabs(local.y) - (double)s->box.halfExtents.y);
		}
		case CD2_SHAPE_POLYGON:
		{
			double value = -INFINITY;
			int count = s->polygon.count;
			for (int i = 0; i < count; ++i)
			{
				DVec a = D(s->polygon.vertices[i]), b = D(s->polygon.vertices[(i + 1) % count]);
				DVec edge = DNormalize(DSub(b, a));
				value = fmax(value, DCross(DSub(p, a), edge)); /* outward normal (edge.y, -edge.x) */
			}
			double radius = (double)s->polygon.radius;
			if (radius > 0.0 && value > 0.0)
			{
				/* Outside the core: the rounded polygon's value is the true distance minus radius. */
				double distance = INFINITY;
				for (int i = 0; i < count; ++i)
				{
					distance = fmin(distance, RefDistanceToSegment(p, D(s->polygon.vertices[i]),
																   D(s->polygon.vertices[(i + 1) % count])));
				}
				value = distance;
			}
			return value - radius;
		}
		default:
			return 0.0;
	}
}

static double RefSupport(const cd2Shape* s, DVec n)
{
	switch (s->type)
	{
		case CD2_SHAPE_CIRCLE:
			return DDot(n, D(s->circle.center)) + (double)s->circle.radius * DLength(n);
		case CD2_SHAPE_CAPSULE:
			return fmax(DDot(n, D(s->capsule.p1)), DDot(n, D(s->capsule.p2))) +
				   (double)s->capsule.radius * DLength(n);
		case CD2_SHAPE_AABB:
		{
			DVec lo = D(s->aabb.min), hi = D(s->aabb.max);
			return fmax(n.x * lo.x, n.x * hi.x) + fmax(n.y * lo.y, n.y * hi.y);
		}
		case CD2_SHAPE_BOX:
		{
			DVec local = DInvRotate(s->box.rotation, n);
			return DDot(n, D(s->box.center)) + fabs(local.x) * (double)s->box.halfExtents.x +
				   fabs(local.y) * (double)s->box.halfExtents.y;
		}
		case CD2_SHAPE_POLYGON:
		{
			double value = -INFINITY;
			for (int i = 0; i < s->polygon.count; ++i)
			{
				value = fmax(value, DDot(n, D(s->polygon.vertices[i])));
			}
			return value + (double)s->polygon.radius * DLength(n);
		}
		default:
			return 0.0;
	}
}

typedef struct RefCast
{
	bool hit;
	double fraction;
	bool clear;
} RefCast;

static RefCast RefRaycastSolid(const cd2Shape* s, DVec o, DVec d, double band)
{
	RefCast ref = {false, 0.0, true};
	double lo = 0.0, hi = 1.0;
	for (int i = 0; i < 70; ++i)
	{
		double m1 = lo + (hi - lo) / 3.0, m2 = hi - (hi - lo) / 3.0;
		if (RefValue(s, DAdd(o, DScale(m1, d))) <= RefValue(s, DAdd(o, DScale(m2, d))))
		{
			hi = m2;
		}
		else
		{
			lo = m1;
		}
	}
	double tMin = 0.5 * (lo + hi);
	double valueMin = RefValue(s, DAdd(o, DScale(tMin, d)));
	double valueStart = RefValue(s, o);
	double valueEnd = RefValue(s, DAdd(o, d));
	ref.clear = fabs(valueMin) > band && fabs(valueStart) > band && fabs(valueEnd) > band;
	if (valueStart <= 0.0)
	{
		ref.hit = true;
		return ref;
	}
	if (valueMin > 0.0)
	{
		return ref;
	}
	ref.hit = true;
	lo = 0.0;
	hi = tMin;
	for (int i = 0; i < 80; ++i)
	{
		double mid = 0.5 * (lo + hi);
		if (RefValue(s, DAdd(o, DScale(mid, d))) > 0.0)
		{
			lo = mid;
		}
		else
		{
			hi = mid;
		}
	}
	ref.fraction = hi;
	return ref;
}

/* ---- random shapes and rays -------------------------------------------------------------------- */

static cdReal R(TestRng* rng, double lower, double upper)
{
	return (cdReal)TestRngRange(rng, lower, upper);
}

static cd2Vec RandomVec(TestRng* rng, double extent)
{
	return cd2MakeVec(R(rng, -extent, extent), R(rng, -extent, extent));
}

static cd2Rot RandomRot(TestRng* rng)
{
	double angle = TestRngRange(rng, -3.14159265358979, 3.14159265358979);
	cd2Rot q = {(cdReal)cos(angle), (cdReal)sin(angle)};
	return q;
}

/* A convex polygon filled by hand under the rules of geometry2.h: vertices on an ellipse at sorted
 * angles (counter-clockwise, strictly convex), outward unit normals from the edges. */
static cd2Polygon MakePolygonByHand(const DVec* points, int count)
{
	cd2Polygon polygon;
	polygon.count = count;
	polygon.radius = (cdReal)0;
	DVec centroid = DMake(0.0, 0.0);
	for (int i = 0; i < count; ++i)
	{
		polygon.vertices[i] = V(points[i]);
		centroid = DAdd(centroid, DScale(1.0 / count, points[i]));
	}
	for (int i = 0; i < count; ++i)
	{
		DVec edge = DSub(D(polygon.vertices[(i + 1) % count]), D(polygon.vertices[i]));
		polygon.normals[i] = V(DNormalize(DMake(edge.y, -edge.x)));
	}
	polygon.centroid = V(centroid);
	return polygon;
}

static cd2Polygon RandomPolygon(TestRng* rng)
{
	int count = 3 + TestRngInt(rng, CD2_MAX_POLYGON_VERTICES - 2);
	double angles[CD2_MAX_POLYGON_VERTICES];
	/* Sorted angles at least a little apart, so that no edge is tiny. */
	double step = 6.283185307179586 / count;
	double start = TestRngRange(rng, 0.0, 6.283185307179586);
	for (int i = 0; i < count; ++i)
	{
		angles[i] = start + step * (i + TestRngRange(rng, 0.0, 0.7));
	}
	DVec center = D(RandomVec(rng, 3.0));
	double rx = TestRngRange(rng, 0.3, 3.0), ry = TestRngRange(rng, 0.3, 3.0);
	DVec points[CD2_MAX_POLYGON_VERTICES];
	for (int i = 0; i < count; ++i)
	{
		points[i] = DAdd(center, DMake(rx * cos(angles[i]), ry * sin(angles[i])));
	}
	cd2Polygon polygon = MakePolygonByHand(points, count);
	/* Rounded one time in three. */
	polygon.radius = TestRngInt(rng, 3) == 0 ? R(rng, 0.0, 1.0) : CD_R(0.0);
	return polygon;
}

static cd2Shape RandomSolid(TestRng* rng, cd2ShapeType type)
{
	bool degenerate = TestRngInt(rng, 10) == 0;
	cd2Shape s;
	s.type = type;
	switch (type)
	{
		case CD2_SHAPE_CIRCLE:
			s.circle.center = RandomVec(rng, 3.0);
			s.circle.radius = degenerate ? CD_R(0.0) : R(rng, 0.1, 3.0);
			break;
		case CD2_SHAPE_CAPSULE:
			s.capsule.p1 = RandomVec(rng, 3.0);
			s.capsule.p2 = degenerate ? s.capsule.p1 : cd2Add(s.capsule.p1, RandomVec(rng, 2.0));
			s.capsule.radius = TestRngInt(rng, 10) == 0 ? CD_R(0.0) : R(rng, 0.1, 2.0);
			break;
		case CD2_SHAPE_AABB:
		{
			cd2Vec center = RandomVec(rng, 3.0);
			cd2Vec half = degenerate ? CD2_VEC_ZERO : cd2MakeVec(R(rng, 0.1, 2), R(rng, 0.1, 2));
			s.aabb.min = cd2Sub(center, half);
			s.aabb.max = cd2Add(center, half);
			break;
		}
		case CD2_SHAPE_BOX:
			s.box.center = RandomVec(rng, 3.0);
			s.box.halfExtents = degenerate ? CD2_VEC_ZERO : cd2MakeVec(R(rng, 0.1, 2), R(rng, 0.1, 2));
			s.box.rotation = RandomRot(rng);
			break;
		case CD2_SHAPE_POLYGON:
			s.polygon = RandomPolygon(rng);
			break;
		case CD2_SHAPE_SEGMENT:
			s.segment.p1 = RandomVec(rng, 4.0);
			s.segment.p2 = RandomVec(rng, 4.0);
			break;
		default:
			break;
	}
	return s;
}

static cd2Ray RandomRay(TestRng* rng)
{
	cd2Ray ray;
	ray.origin = RandomVec(rng, 10.0);
	cd2Vec target = RandomVec(rng, 4.0);
	ray.translation = cd2Scale(R(rng, 0.3, 2.0), cd2Sub(target, ray.origin));
	if (TestRngInt(rng, 50) == 0)
	{
		ray.translation = CD2_VEC_ZERO;
	}
	return ray;
}

static bool IsFiniteHit(cd2RayHit hit)
{
	return isfinite(hit.fraction) && cd2IsValidVec(hit.point) && cd2IsValidVec(hit.normal);
}

static cd2RayHit UntouchedHit(void)
{
	cd2RayHit hit;
	hit.fraction = CD_R(42.0);
	hit.point = cd2MakeVec(CD_R(1.0), CD_R(2.0));
	hit.normal = cd2MakeVec(CD_R(4.0), CD_R(5.0));
	return hit;
}

static bool IsUntouched(cd2RayHit hit)
{
	cd2RayHit u = UntouchedHit();
	return hit.fraction == u.fraction && cd2VecEqual(hit.point, u.point) && cd2VecEqual(hit.normal, u.normal);
}

static void CheckSolidCast(const cd2Shape* s, cd2Ray ray, double scale, int index)
{
	cd2RayHit hit = UntouchedHit();
	bool got = cd2Raycast(s, ray, &hit);
	DVec o = D(ray.origin), d = D(ray.translation);
	double tol = TOL * scale;
	RefCast ref = RefRaycastSolid(s, o, d, BAND * scale);
	double valueStart = RefValue(s, o);
	const char* name = cd2GetShapeTypeName(s->type);

	if (!got)
	{
		TEST_CHECKF(IsUntouched(hit), "%s case %d: miss changed *hit", name, index);
	}
	if (ref.clear)
	{
		TEST_CHECKF(got == ref.hit, "%s case %d: got %d, reference %d (fraction %.9g)", name, index, got,
					ref.hit, ref.fraction);
	}
	if (!ref.hit && ref.clear)
	{
		for (int i = 0; i <= 64; ++i)
		{
			double t = i / 64.0;
			TEST_CHECKF(RefValue(s, DAdd(o, DScale(t, d))) > 0.0, "%s case %d: reference miss enters at %g",
						name, index, t);
		}
	}
	if (!got)
	{
		return;
	}

	TEST_CHECKF(IsFiniteHit(hit), "%s case %d: not finite", name, index);
	TEST_CHECKF(hit.fraction >= CD_R(0.0) && hit.fraction <= CD_R(1.0), "%s case %d: fraction %g", name,
				index, (double)hit.fraction);
	DVec point = D(hit.point), normal = D(hit.normal);
	DVec expectedPoint = DAdd(o, DScale((double)hit.fraction, d));
	TEST_CHECKF(DLength(DSub(point, expectedPoint)) <= tol, "%s case %d: point off the ray by %g", name,
				index, DLength(DSub(point, expectedPoint)));

	if (valueStart < -BAND * scale)
	{
		TEST_CHECKF(hit.fraction == CD_R(0.0) && cd2VecEqual(hit.point, ray.origin),
					"%s case %d: inside origin gave fraction %g", name, index, (double)hit.fraction);
		DVec expectedNormal = DScale(-1.0, DNormalize(d));
		TEST_CHECKF(DLength(DSub(normal, expectedNormal)) <= 1e-5, "%s case %d: inside normal (%g %g)", name,
					index, normal.x, normal.y);
		return;
	}
	if (valueStart <= BAND * scale)
	{
		return;
	}

	TEST_CHECKF(fabs(DLength(normal) - 1.0) <= 1e-5, "%s case %d: normal length %.9g", name, index,
				DLength(normal));
	TEST_CHECKF(fabs(RefValue(s, point)) <= tol, "%s case %d: point %g off the surface", name, index,
				RefValue(s, point));
	double support = RefSupport(s, normal);
	TEST_CHECKF(fabs(support - DDot(normal, point)) <= tol,
				"%s case %d: normal not outward: support %.9g, at point %.9g", name, index, support,
				DDot(normal, point));
	TEST_CHECKF(DDot(normal, DNormalize(d)) <= 1e-5, "%s case %d: the ray leaves through the normal's side",
				name, index);
	TEST_CHECKF(RefValue(s, DAdd(point, DScale(1e-2 * scale, normal))) > 0.0,
				"%s case %d: a step along the normal stays inside", name, index);
	if (ref.clear && ref.hit)
	{
		double error = fabs((double)hit.fraction - ref.fraction) * DLength(d);
		TEST_CHECKF(error <= 10.0 * tol, "%s case %d: fraction %.9g, reference %.9g", name, index,
					(double)hit.fraction, ref.fraction);
	}
}

/* ---- exact cases --------------------------------------------------------------------------------- */

static cd2Ray Ray(cdReal ox, cdReal oy, cdReal dx, cdReal dy)
{
	cd2Ray ray = {cd2MakeVec(ox, oy), cd2MakeVec(dx, dy)};
	return ray;
}

#define CHECK_VEC(v, ex, ey, tol)                                                                            \
	do                                                                                                       \
	{                                                                                                        \
		TEST_CHECK_NEAR((v).x, ex, tol);                                                                     \
		TEST_CHECK_NEAR((v).y, ey, tol);                                                                     \
	} while (0)

#define EXACT 1e-6

static void TestCircleExact(void)
{
	cd2Circle c = {cd2MakeVec(CD_R(1.0), CD_R(2.0)), CD_R(1.0)};
	cd2RayHit hit;
	TEST_CHECK(cd2RaycastCircle(c, Ray(-2, 2, 4, 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.point, 0.0, 2.0, EXACT);
	CHECK_VEC(hit.normal, -1.0, 0.0, EXACT);
	TEST_CHECK(cd2RaycastCircle(c, Ray(4, 2, -4, 0), &hit));
	CHECK_VEC(hit.normal, 1.0, 0.0, EXACT);
	TEST_CHECK(cd2RaycastCircle(c, Ray(1, 5, 0, -4), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.normal, 0.0, 1.0, EXACT);
	TEST_CHECK(cd2RaycastCircle(c, Ray(1, -1, 0, 4), &hit));
	CHECK_VEC(hit.normal, 0.0, -1.0, EXACT);
	/* Oblique: from (5, 5) towards the center (1, 2), distance 5, entry after 4 of 10. */
	TEST_CHECK(cd2RaycastCircle(c, Ray(5, 5, -8, -6), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.4, EXACT);
	CHECK_VEC(hit.normal, 0.8, 0.6, EXACT);
	hit = UntouchedHit();
	TEST_CHECK(!cd2RaycastCircle(c, Ray(-2, 4, 6, 0), &hit));
	TEST_CHECK(!cd2RaycastCircle(c, Ray(-2, 2, -6, 0), &hit));
	TEST_CHECK(!cd2RaycastCircle(c, Ray(-2, 2, CD_R(1.99), 0), &hit));
	TEST_CHECK(!cd2RaycastCircle(c, Ray(-2, 2, 0, 0), &hit));
	TEST_CHECK(IsUntouched(hit));
	TEST_CHECK(cd2RaycastCircle(c, Ray(-3, 3, 8, 0), &hit)); /* tangent at (1, 3) */
	CHECK_VEC(hit.normal, 0.0, 1.0, 1e-3);
	TEST_CHECK(cd2RaycastCircle(c, Ray(1, CD_R(2.5), 3, 0), &hit));
	TEST_CHECK(hit.fraction == CD_R(0.0));
	CHECK_VEC(hit.point, 1.0, 2.5, 0.0);
	CHECK_VEC(hit.normal, -1.0, 0.0, EXACT);
	TEST_CHECK(cd2RaycastCircle(c, Ray(2, 2, 3, 0), &hit)); /* on the surface */
	TEST_CHECK(hit.fraction == CD_R(0.0));
	TEST_CHECK(cd2RaycastCircle(c, Ray(1, 2, 0, 0), &hit));
	CHECK_VEC(hit.normal, 0.0, 0.0, 0.0);
	cd2Circle point = {cd2MakeVec(CD_R(1.0), CD_R(0.0)), CD_R(0.0)};
	TEST_CHECK(cd2RaycastCircle(point, Ray(-1, 0, 4, 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.normal, -1.0, 0.0, EXACT);
	TEST_CHECK(!cd2RaycastCircle(point, Ray(-1, CD_R(0.001), 4, 0), &hit));
	/* Diagonal through a zero-radius circle: round-off must not turn the normal around. */
	cd2Circle diagonal = {cd2MakeVec(CD_R(1.0), CD_R(1.0)), CD_R(0.0)};
	TEST_CHECK(cd2RaycastCircle(diagonal, Ray(0, 0, 2, 2), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.normal, -0.70710678, -0.70710678, EXACT);
	/* Rays from the origin through zero-radius circles in many directions: when they hit, the
	 * normal faces back along the ray. */
	int hits = 0;
	for (int a = -5; a <= 5; ++a)
	{
		for (int b = -5; b <= 5; ++b)
		{
			for (int k = 1; k <= 9; ++k)
			{
				cd2Circle dot = {cd2Scale(CD_R(0.1) * (cdReal)k, cd2MakeVec((cdReal)a, (cdReal)b)),
								 CD_R(0.0)};
				cd2Ray ray = {CD2_VEC_ZERO, cd2Scale(CD_R(3.0), dot.center)};
				if ((a != 0 || b != 0) && cd2RaycastCircle(dot, ray, &hit))
				{
					++hits;
					TEST_CHECKF(cd2Dot(hit.normal, ray.translation) < CD_R(0.0) &&
									fabs((double)cd2Length(hit.normal) - 1.0) <= 1e-5,
								"(%d %d) * %d: normal (%g %g)", a, b, k, (double)hit.normal.x,
								(double)hit.normal.y);
				}
			}
		}
	}
	TEST_CHECKF(hits > 100, "only %d of the rays through a point hit it", hits);
}

static void TestCapsuleExact(void)
{
	cd2Capsule c = {CD2_VEC_ZERO, cd2MakeVec(CD_R(4.0), CD_R(0.0)), CD_R(1.0)};
	cd2RayHit hit;
	TEST_CHECK(cd2RaycastCapsule(c, Ray(2, 5, 0, -8), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.point, 2.0, 1.0, EXACT);
	CHECK_VEC(hit.normal, 0.0, 1.0, EXACT);
	TEST_CHECK(cd2RaycastCapsule(c, Ray(3, -5, 0, 8), &hit));
	CHECK_VEC(hit.normal, 0.0, -1.0, EXACT);
	TEST_CHECK(cd2RaycastCapsule(c, Ray(-5, 0, 8, 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.normal, -1.0, 0.0, EXACT);
	TEST_CHECK(cd2RaycastCapsule(c, Ray(9, 0, -8, 0), &hit));
	CHECK_VEC(hit.normal, 1.0, 0.0, EXACT);
	TEST_CHECK(cd2RaycastCapsule(c, Ray(-5, CD_R(0.6), 10, 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.42, EXACT);
	CHECK_VEC(hit.normal, -0.8, 0.6, EXACT);
	TEST_CHECK(cd2RaycastCapsule(c, Ray(8, 3, -4, -3), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.8, EXACT);
	CHECK_VEC(hit.normal, 0.8, 0.6, EXACT);
	hit = UntouchedHit();
	TEST_CHECK(!cd2RaycastCapsule(c, Ray(-5, CD_R(1.01), 10, 0), &hit));
	TEST_CHECK(!cd2RaycastCapsule(c, Ray(2, 5, 0, CD_R(-3.99)), &hit));
	/* Nearly parallel to the axis: into the cap at x = -sqrt(1 - 0.999^2), onto the side grazing. */
	TEST_CHECK(cd2RaycastCapsule(c, Ray(-5, CD_R(0.999), 10, CD_R(1e-7)), &hit));
	TEST_CHECK(IsFiniteHit(hit));
	TEST_CHECK_NEAR(hit.fraction, (5.0 - sqrt(1.0 - 0.999 * 0.999)) / 10.0, 1e-3);
	TEST_CHECK(cd2RaycastCapsule(c, Ray(1, CD_R(1.001), 2, CD_R(-0.002)), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, 1e-3);
	CHECK_VEC(hit.normal, 0.0, 1.0, 1e-5);
	hit = UntouchedHit();
	TEST_CHECK(!cd2RaycastCapsule(c, Ray(-2, 0, 0, 0), &hit));
	TEST_CHECK(IsUntouched(hit));
	TEST_CHECK(cd2RaycastCapsule(c, Ray(-5, 1, 10, 0), &hit)); /* along the flat side: touching */
	CHECK_VEC(hit.normal, 0.0, 1.0, 1e-3);
	TEST_CHECK(cd2RaycastCapsule(c, Ray(2, CD_R(0.5), 0, 3), &hit));
	TEST_CHECK(hit.fraction == CD_R(0.0));
	CHECK_VEC(hit.normal, 0.0, -1.0, EXACT);
	TEST_CHECK(cd2RaycastCapsule(c, Ray(2, 1, 0, -3), &hit));
	TEST_CHECK(hit.fraction == CD_R(0.0));
	TEST_CHECK(cd2RaycastCapsule(c, Ray(-1, 0, 0, 0), &hit));
	CHECK_VEC(hit.normal, 0.0, 0.0, 0.0);
	cd2Capsule disk = {cd2MakeVec(CD_R(1.0), CD_R(1.0)), cd2MakeVec(CD_R(1.0), CD_R(1.0)), CD_R(2.0)};
	TEST_CHECK(cd2RaycastCapsule(disk, Ray(1, 5, 0, -4), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.normal, 0.0, 1.0, EXACT);
	cd2Capsule line = {cd2MakeVec(CD_R(0.0), CD_R(-1.0)), cd2MakeVec(CD_R(0.0), CD_R(1.0)), CD_R(0.0)};
	TEST_CHECK(cd2RaycastCapsule(line, Ray(-2, CD_R(0.5), 4, 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.normal, -1.0, 0.0, EXACT);
}

/* A ray from a point on a capsule's side (rounded to cdReal from the exact surface point) towards
 * the axis ends deep inside: a hit at or near fraction 0 at every scale up to 1e9, although the
 * inside test may round the origin to either side (the 1e9 case missed; fuzz_query2). */
static void TestCapsuleRayFromSurfaceInward(void)
{
#define SURFACE_VEC(x, y) cd2MakeVec((cdReal)(x), (cdReal)(y))
	cd2Capsule big = {SURFACE_VEC(-1e9, -1e9), SURFACE_VEC(1e9, 5e8), CD_R(1e9)};
	cd2RayHit hit;
	TEST_CHECK(cd2RaycastCapsule(big, Ray(CD_R(-1e9), CD_R(2.5e8), CD_R(1e9), 0), &hit));
	TEST_CHECK(hit.fraction <= CD_R(1e-6));
	TestRng rng = TestRngMake(0x5eed0cab);
	int misses = 0;
	for (int i = 0; i < 20000; ++i)
	{
		double scale = pow(10.0, TestRngRange(&rng, 0.0, 9.0));
		double ax = TestRngRange(&rng, -scale, scale), ay = TestRngRange(&rng, -scale, scale);
		double bx = TestRngRange(&rng, -scale, scale), by = TestRngRange(&rng, -scale, scale);
		double radius = TestRngRange(&rng, 0.05, 1.05) * scale;
		double length = sqrt((bx - ax) * (bx - ax) + (by - ay) * (by - ay));
		double ux = (bx - ax) / length, uy = (by - ay) / length;
		double t = TestRngRange(&rng, 0.0, 1.0);
		double side = TestRngRange(&rng, -1.0, 1.0) < 0.0 ? -1.0 : 1.0;
		double footX = ax + t * (bx - ax), footY = ay + t * (by - ay);
		double px = footX - side * uy * radius, py = footY + side * ux * radius;
		cd2Capsule c = {SURFACE_VEC(ax, ay), SURFACE_VEC(bx, by), (cdReal)radius};
		cd2Ray ray = {SURFACE_VEC(px, py), SURFACE_VEC(footX - px, footY - py)};
		if (!cd2RaycastCapsule(c, ray, &hit) || hit.fraction > CD_R(1e-3))
		{
			++misses;
		}
	}
	TEST_CHECKF(misses == 0, "%d of 20000 rays from the side inward missed or entered late", misses);
#undef SURFACE_VEC
}

static void TestAabbExact(void)
{
	cd2Aabb b = {cd2MakeVec(CD_R(-1.0), CD_R(-2.0)), cd2MakeVec(CD_R(1.0), CD_R(2.0))};
	cd2RayHit hit;
	TEST_CHECK(cd2RaycastAabb(b, Ray(-3, CD_R(0.5), 4, 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.point, -1.0, 0.5, EXACT);
	CHECK_VEC(hit.normal, -1.0, 0.0, 0.0);
	TEST_CHECK(cd2RaycastAabb(b, Ray(3, CD_R(0.5), -4, 0), &hit));
	CHECK_VEC(hit.normal, 1.0, 0.0, 0.0);
	TEST_CHECK(cd2RaycastAabb(b, Ray(CD_R(0.5), 4, 0, -4), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.normal, 0.0, 1.0, 0.0);
	TEST_CHECK(cd2RaycastAabb(b, Ray(CD_R(0.5), -4, 0, 4), &hit));
	CHECK_VEC(hit.normal, 0.0, -1.0, 0.0);
	TEST_CHECK(cd2RaycastAabb(b, Ray(3, 2, -4, -2), &hit)); /* oblique through x = 1 at (1, 1) */
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.normal, 1.0, 0.0, 0.0);
	TEST_CHECK(!cd2RaycastAabb(b, Ray(-5, CD_R(2.5), 10, 0), &hit)); /* parallel, outside */
	TEST_CHECK(cd2RaycastAabb(b, Ray(-5, 2, 10, 0), &hit));			 /* along the top side */
	TEST_CHECK_NEAR(hit.fraction, 0.4, EXACT);
	TEST_CHECK(cd2RaycastAabb(b, Ray(2, 3, -2, -2), &hit)); /* corner */
	CHECK_VEC(hit.point, 1.0, 2.0, EXACT);
	hit = UntouchedHit();
	TEST_CHECK(!cd2RaycastAabb(b, Ray(3, 0, 4, 0), &hit));
	TEST_CHECK(!cd2RaycastAabb(b, Ray(3, 0, CD_R(-1.99), 0), &hit));
	TEST_CHECK(!cd2RaycastAabb(b, Ray(3, 0, 0, 0), &hit));
	TEST_CHECK(IsUntouched(hit));
	TEST_CHECK(cd2RaycastAabb(b, Ray(0, 0, 0, 5), &hit));
	TEST_CHECK(hit.fraction == CD_R(0.0));
	CHECK_VEC(hit.normal, 0.0, -1.0, 0.0);
	TEST_CHECK(cd2RaycastAabb(b, Ray(1, 0, -5, 0), &hit));
	TEST_CHECK(hit.fraction == CD_R(0.0));
	CHECK_VEC(hit.normal, 1.0, 0.0, 0.0);
	TEST_CHECK(cd2RaycastAabb(b, Ray(0, 0, 0, 0), &hit));
	CHECK_VEC(hit.normal, 0.0, 0.0, 0.0);
	cd2Aabb point = {cd2MakeVec(CD_R(1.0), CD_R(1.0)), cd2MakeVec(CD_R(1.0), CD_R(1.0))};
	TEST_CHECK(cd2RaycastAabb(point, Ray(-1, 1, 4, 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	TEST_CHECK(!cd2RaycastAabb(point, Ray(-1, CD_R(1.001), 4, 0), &hit));
	hit = UntouchedHit();
	TEST_CHECK(cd2RaycastAabb(b, Ray(-5, 0, 10, CD_R(1e-40)), &hit));
	TEST_CHECK(IsFiniteHit(hit));
}

static void TestBoxExact(void)
{
	/* Half extents (1, 2) rotated by 90 degrees: world x in [8, 12], y in [-1, 1]. */
	cd2Box b = {cd2MakeVec(CD_R(10.0), CD_R(0.0)), cd2MakeVec(CD_R(1.0), CD_R(2.0)), cd2MakeRot(CD_PI / 2)};
	cd2RayHit hit;
	TEST_CHECK(cd2RaycastBox(b, Ray(4, 0, 8, 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.normal, -1.0, 0.0, EXACT);
	TEST_CHECK(cd2RaycastBox(b, Ray(16, 0, -8, 0), &hit));
	CHECK_VEC(hit.normal, 1.0, 0.0, EXACT);
	TEST_CHECK(cd2RaycastBox(b, Ray(10, 3, 0, -4), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.normal, 0.0, 1.0, EXACT);
	TEST_CHECK(cd2RaycastBox(b, Ray(10, -3, 0, 4), &hit));
	CHECK_VEC(hit.normal, 0.0, -1.0, EXACT);
	TEST_CHECK(!cd2RaycastBox(b, Ray(4, CD_R(1.5), 16, 0), &hit));
	hit = UntouchedHit();
	TEST_CHECK(!cd2RaycastBox(b, Ray(4, 0, CD_R(3.99), 0), &hit));
	TEST_CHECK(IsUntouched(hit));
	TEST_CHECK(cd2RaycastBox(b, Ray(10, 0, 0, 2), &hit));
	TEST_CHECK(hit.fraction == CD_R(0.0));
	CHECK_VEC(hit.normal, 0.0, -1.0, EXACT);
	TEST_CHECK(cd2RaycastBox(b, Ray(11, 0, 0, 0), &hit));
	TEST_CHECK(!cd2RaycastBox(b, Ray(13, 0, 0, 0), &hit));
	/* A rotation a little off unit length (within the validator's tolerance) still gives unit normals. */
	cd2Box loose = b;
	double grow = CD_DOUBLE ? 1.0 + 2e-10 : 1.0 + 2e-5;
	loose.rotation.c = (cdReal)(grow * b.rotation.c);
	loose.rotation.s = (cdReal)(grow * b.rotation.s);
	TEST_CHECK(cd2IsValidRot(loose.rotation));
	TEST_CHECK(cd2RaycastBox(loose, Ray(10, 3, 0, -4), &hit));
	TEST_CHECK_NEAR(cd2Length(hit.normal), 1.0, 1e-6);
	cd2Box point = {cd2MakeVec(CD_R(1.0), CD_R(0.0)), CD2_VEC_ZERO, CD2_ROT_IDENTITY};
	TEST_CHECK(cd2RaycastBox(point, Ray(-1, 0, 4, 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.normal, -1.0, 0.0, 0.0);
}

static void TestPolygonExact(void)
{
	/* The triangle (0,0), (4,0), (0,4). */
	DVec points[3] = {DMake(0, 0), DMake(4, 0), DMake(0, 4)};
	cd2Polygon p = MakePolygonByHand(points, 3);
	cd2RayHit hit;
	TEST_CHECK(cd2RaycastPolygon(&p, Ray(1, -2, 0, 4), &hit)); /* bottom side */
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.point, 1.0, 0.0, EXACT);
	CHECK_VEC(hit.normal, 0.0, -1.0, EXACT);
	TEST_CHECK(cd2RaycastPolygon(&p, Ray(-2, 1, 4, 0), &hit)); /* left side */
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.normal, -1.0, 0.0, EXACT);
	TEST_CHECK(cd2RaycastPolygon(&p, Ray(4, 4, -4, -4), &hit)); /* hypotenuse at (2, 2) */
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.normal, 0.70710678, 0.70710678, EXACT);
	TEST_CHECK(cd2RaycastPolygon(&p, Ray(-5, 0, 10, 0), &hit)); /* along the bottom side: touching */
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	TEST_CHECK(cd2RaycastPolygon(&p, Ray(6, -2, -2, 2), &hit)); /* through the vertex (4, 0) */
	TEST_CHECK_NEAR(hit.fraction, 1.0, EXACT);
	hit = UntouchedHit();
	TEST_CHECK(!cd2RaycastPolygon(&p, Ray(-5, CD_R(-0.5), 10, 0), &hit)); /* parallel below */
	TEST_CHECK(!cd2RaycastPolygon(&p, Ray(3, 3, 4, 4), &hit));			  /* away */
	TEST_CHECK(!cd2RaycastPolygon(&p, Ray(1, -2, 0, CD_R(1.99)), &hit));  /* short */
	TEST_CHECK(!cd2RaycastPolygon(&p, Ray(5, 5, 0, 0), &hit));
	TEST_CHECK(IsUntouched(hit));
	TEST_CHECK(cd2RaycastPolygon(&p, Ray(1, 1, 5, 0), &hit)); /* inside */
	TEST_CHECK(hit.fraction == CD_R(0.0));
	CHECK_VEC(hit.normal, -1.0, 0.0, EXACT);
	TEST_CHECK(cd2RaycastPolygon(&p, Ray(1, 0, 0, -3), &hit)); /* on the boundary */
	TEST_CHECK(hit.fraction == CD_R(0.0));
	CHECK_VEC(hit.normal, 0.0, 1.0, EXACT);
	TEST_CHECK(cd2RaycastPolygon(&p, Ray(1, 1, 0, 0), &hit));
	CHECK_VEC(hit.normal, 0.0, 0.0, 0.0);

	/* An origin on an edge 0.00125 from its end (found by fuzz_query2): on the boundary, so a hit at
	 * fraction 0, although the edge's closest point rounds off it by more than round-off of that
	 * offset when computed from the far end. */
	cd2Vec corners[3] = {cd2MakeVec(CD_R(-0.125), CD_R(-0.035)), cd2MakeVec(CD_R(-0.04625), CD_R(-0.125)),
						 cd2MakeVec(CD_R(0.11625), CD_R(-0.125))};
	cd2Polygon near;
	TEST_CHECK(cd2MakePolygon(corners, 3, &near) == CD_OK);
	TEST_CHECK(cd2RaycastPolygon(&near, Ray(CD_R(0.115), CD_R(-0.125), CD_R(-0.125), CD_R(0.035)), &hit));
	TEST_CHECK(hit.fraction == CD_R(0.0));
	TEST_CHECK(cd2PointInPolygon(cd2MakeVec(CD_R(0.115), CD_R(-0.125)), &near));

	/* An origin 6e-6 from the core of a polygon rounded by 1 with edges 1e9 long (found by
	 * fuzz_query2): inside, a hit at fraction 0; the core distance recomputed from the core point's
	 * coordinates (1e9 along the edge) came out about 30. */
	cd2Vec rounded[5] = {cd2MakeVec(CD_R(-1e9), CD_R(0.0)), cd2MakeVec(CD_R(-8e8), CD_R(-5.875e8)),
						 cd2MakeVec(CD_R(-5e7), CD_R(-1e9)), cd2MakeVec(CD_R(0.0), CD_R(-9.125e8)),
						 cd2MakeVec(CD_R(2.625e8), CD_R(-7.68813788e-06))};
	cd2Polygon roundedPolygon;
	TEST_CHECK(cd2MakeRoundedPolygon(rounded, 5, CD_R(1.0), &roundedPolygon) == CD_OK);
	TEST_CHECK(cd2PointInPolygon(CD2_VEC_ZERO, &roundedPolygon));
	TEST_CHECK(
		cd2RaycastPolygon(&roundedPolygon, Ray(CD_R(0.0), CD_R(0.0), CD_R(0.0), CD_R(-8.625e8)), &hit));
	TEST_CHECK(hit.fraction == CD_R(0.0));
}

/* Slivers (tip angles down to 1e-5, up to 1e9 / 1e30 long): a ray from beyond the sharp tip, on
 * an edge's extension or behind the tip, starts outside however close it stays to both edge lines:
 * moving away it misses, moving through the tip it enters there. The fuzzer's sliver first. */
static void TestSliverPolygon(void)
{
	cd2Vec points[3] = {cd2MakeVec(CD_R(32500.0), CD_R(-125000.0)), cd2MakeVec(CD_R(1e9), CD_R(-125000.0)),
						cd2MakeVec(CD_R(1e9), CD_R(-43750.0))};
	cd2Polygon sliver;
	TEST_CHECK(cd2MakePolygon(points, 3, &sliver) == CD_OK);
	cd2RayHit hit = UntouchedHit();
	TEST_CHECK(
		!cd2RaycastPolygon(&sliver, Ray(CD_R(-125000.0), CD_R(-125000.0), CD_R(-1000.0), CD_R(0.0)), &hit));
	TEST_CHECK(IsUntouched(hit));
	TEST_CHECK(
		cd2RaycastPolygon(&sliver, Ray(CD_R(-125000.0), CD_R(-125000.0), CD_R(315000.0), CD_R(0.0)), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);

	TestRng rng = TestRngMake(0x511BE6);
#if CD_DOUBLE
	const double largest = 30.0;
#else
	const double largest = 9.0;
#endif
	int checked = 0;
	for (int n = 0; n < 3000; ++n)
	{
		double k = pow(10.0, TestRngRange(&rng, -largest, largest));
		double angle = pow(10.0, TestRngRange(&rng, -5.0, -1.0));
		double heading = TestRngRange(&rng, -3.2, 3.2);
		DVec u = DMake(cos(heading - 0.5 * angle), sin(heading - 0.5 * angle));
		DVec w = DMake(cos(heading + 0.5 * angle), sin(heading + 0.5 * angle));
		DVec tip = DMake(k * TestRngRange(&rng, -1.0, 1.0), k * TestRngRange(&rng, -1.0, 1.0));
		cd2Vec corners[3] = {V(tip), V(DAdd(tip, DScale(k * TestRngRange(&rng, 0.5, 2.0), u))),
							 V(DAdd(tip, DScale(k * TestRngRange(&rng, 0.5, 2.0), w)))};
		cd2Polygon polygon;
		if (cd2MakePolygon(corners, 3, &polygon) != CD_OK)
		{
			continue;
		}
		tip = D(corners[0]);
		DVec back = TestRngInt(&rng, 2) == 0 ? u : DMake(cos(heading), sin(heading));
		double d = k * pow(10.0, TestRngRange(&rng, -6.0, 0.0));
		cd2Vec origin = V(DSub(tip, DScale(d, back)));
		DVec offset = DSub(D(origin), tip);
		double distance = sqrt(DDot(offset, offset));
		if (distance <= 64.0 * (double)CD_REAL_EPSILON * fmax(fabs(tip.x), fabs(tip.y)))
		{
			continue; /* the origin rounded onto the tip */
		}
		++checked;
		hit = UntouchedHit();
		bool away =
			cd2RaycastPolygon(&polygon, Ray(origin.x, origin.y, (cdReal)offset.x, (cdReal)offset.y), &hit);
		TEST_CHECKF(!away && IsUntouched(hit),
					"case %d: angle %.3g, ray from %.3g beyond the tip moving away hits at %.9g", n, angle,
					distance, (double)hit.fraction);
		bool through = cd2RaycastPolygon(
			&polygon, Ray(origin.x, origin.y, (cdReal)(-2.0 * offset.x), (cdReal)(-2.0 * offset.y)), &hit);
		TEST_CHECKF(through && fabs((double)hit.fraction - 0.5) <= 1e-3,
					"case %d: angle %.3g, ray from %.3g beyond the tip through it: hit %d at %.9g", n, angle,
					distance, (int)through, (double)hit.fraction);
	}
	TEST_CHECKF(checked > 1000, "only %d cases", checked);
}

/* A rounded polygon whose rim (radius 1) is thinner than the round-off of its edges (1e9 long, in
 * float about 119): a ray that starts 0.4 outside the rim near a vertex and ends deep inside the
 * core was missed by every edge's capsule (fuzz_query2 finding). It must hit, at the rim or on the
 * core within that round-off. */
static void TestRimThinnerThanRoundOff(void)
{
	cd2Vec points[5] = {cd2MakeVec(CD_R(-1e9), CD_R(6750000.0)), cd2MakeVec(CD_R(7125000.0), CD_R(-1e9)),
						cd2MakeVec(CD_R(1e9), CD_R(-1e9)), cd2MakeVec(CD_R(0.0), CD_R(0.0)),
						cd2MakeVec(CD_R(-12500000.0), CD_R(7125000.0))};
	cd2Polygon polygon;
	TEST_CHECK(cd2MakeRoundedPolygon(points, 5, (cdReal)0.999999881, &polygon) == CD_OK);
	cd2RayHit hit = UntouchedHit();
	cd2Ray ray = Ray((cdReal)0.999999881, (cdReal)0.999999881, (cdReal)0.999999881, CD_R(-12500000.0));
	TEST_CHECK(cd2RaycastPolygon(&polygon, ray, &hit));
	/* The entry is within a few hundred units (the round-off at 1e9) of the vertex at the origin:
	 * a fraction of at most 1e-4 of the ray's 1.25e7. */
	TEST_CHECKF(hit.fraction >= CD_R(0.0) && hit.fraction <= CD_R(1e-4), "fraction %.9g",
				(double)hit.fraction);
	TEST_CHECK_NEAR((double)cd2Length(hit.normal), 1.0, 1e-5);
}

static void TestSegmentExact(void)
{
	cd2Segment g = {cd2MakeVec(CD_R(0.0), CD_R(-1.0)), cd2MakeVec(CD_R(0.0), CD_R(3.0))};
	cd2RayHit hit;
	TEST_CHECK(cd2RaycastSegment(g, Ray(-2, 1, 4, 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.point, 0.0, 1.0, EXACT);
	CHECK_VEC(hit.normal, -1.0, 0.0, EXACT);
	TEST_CHECK(cd2RaycastSegment(g, Ray(2, 1, -4, 0), &hit)); /* two-sided */
	CHECK_VEC(hit.normal, 1.0, 0.0, EXACT);
	TEST_CHECK(cd2RaycastSegment(g, Ray(-2, 3, 4, -2), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.normal, -1.0, 0.0, EXACT);
	TEST_CHECK(cd2RaycastSegment(g, Ray(-2, 3, 4, 0), &hit)); /* end point */
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	hit = UntouchedHit();
	TEST_CHECK(!cd2RaycastSegment(g, Ray(-2, CD_R(3.01), 4, 0), &hit));
	TEST_CHECK(!cd2RaycastSegment(g, Ray(-2, 1, CD_R(1.99), 0), &hit));
	TEST_CHECK(!cd2RaycastSegment(g, Ray(-2, 1, -4, 0), &hit));
	TEST_CHECK(!cd2RaycastSegment(g, Ray(0, 1, 0, 0), &hit));			/* zero-length, on it */
	TEST_CHECK(!cd2RaycastSegment(g, Ray(CD_R(0.5), -5, 0, 10), &hit)); /* parallel, apart */
	TEST_CHECK(IsUntouched(hit));
	TEST_CHECK(cd2RaycastSegment(g, Ray(0, -5, 0, 8), &hit)); /* along it */
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.normal, 0.0, -1.0, EXACT);
	TEST_CHECK(cd2RaycastSegment(g, Ray(0, 1, 0, 8), &hit)); /* along it, starting on it */
	TEST_CHECK(hit.fraction == CD_R(0.0));
	TEST_CHECK(cd2RaycastSegment(g, Ray(0, 1, 3, 0), &hit)); /* starting on it, leaving sideways */
	TEST_CHECK(hit.fraction == CD_R(0.0));
	CHECK_VEC(hit.normal, -1.0, 0.0, EXACT);
	cd2Segment point = {cd2MakeVec(CD_R(1.0), CD_R(1.0)), cd2MakeVec(CD_R(1.0), CD_R(1.0))};
	TEST_CHECK(cd2RaycastSegment(point, Ray(-1, 1, 4, 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.normal, -1.0, 0.0, EXACT);
	TEST_CHECK(!cd2RaycastSegment(point, Ray(-1, CD_R(1.001), 4, 0), &hit));
}

static void TestDispatcher(void)
{
	TestRng rng = TestRngMake(11);
	for (int i = 0; i < 600; ++i)
	{
		cd2Shape s = RandomSolid(&rng, (cd2ShapeType)(i % 6));
		cd2Ray ray = RandomRay(&rng);
		cd2RayHit a = UntouchedHit(), b = UntouchedHit();
		bool hitA = cd2Raycast(&s, ray, &a), hitB = false;
		switch (s.type)
		{
			case CD2_SHAPE_CIRCLE:
				hitB = cd2RaycastCircle(s.circle, ray, &b);
				break;
			case CD2_SHAPE_CAPSULE:
				hitB = cd2RaycastCapsule(s.capsule, ray, &b);
				break;
			case CD2_SHAPE_AABB:
				hitB = cd2RaycastAabb(s.aabb, ray, &b);
				break;
			case CD2_SHAPE_BOX:
				hitB = cd2RaycastBox(s.box, ray, &b);
				break;
			case CD2_SHAPE_POLYGON:
				hitB = cd2RaycastPolygon(&s.polygon, ray, &b);
				break;
			default:
				hitB = cd2RaycastSegment(s.segment, ray, &b);
				break;
		}
		TEST_CHECKF(hitA == hitB && a.fraction == b.fraction && cd2VecEqual(a.normal, b.normal),
					"case %d (%s)", i, cd2GetShapeTypeName(s.type));
	}
	cd2Shape bad;
	bad.type = CD2_SHAPE_TYPE_COUNT;
	bad.circle.center = CD2_VEC_ZERO;
	bad.circle.radius = CD_R(1.0);
	cd2RayHit hit = UntouchedHit();
	TEST_CHECK(!cd2Raycast(&bad, Ray(0, 0, 1, 0), &hit));
	TEST_CHECK(IsUntouched(hit));
}

/* ---- property tests ----------------------------------------------------------------------------- */

static void TestSolidsAgainstReference(void)
{
	TestRng rng = TestRngMake(0x5eed2001);
	for (int i = 0; i < 10000; ++i)
	{
		cd2Shape s = RandomSolid(&rng, (cd2ShapeType)(i % 5));
		CheckSolidCast(&s, RandomRay(&rng), 10.0, i);
	}
}

/* Rays aimed close to the silhouette (the support line along a random direction). */
static void TestSolidsNearTangent(void)
{
	TestRng rng = TestRngMake(0x5eed2002);
	for (int i = 0; i < 5000; ++i)
	{
		cd2Shape s = RandomSolid(&rng, (cd2ShapeType)(i % 5));
		cd2Ray ray = RandomRay(&rng);
		DVec o = D(ray.origin);
		DVec toward = DNormalize(DSub(D(RandomVec(&rng, 0.1)), o));
		DVec n = DMake(-toward.y, toward.x);
		if (TestRngInt(&rng, 2) == 0)
		{
			n = DScale(-1.0, n);
		}
		double height = RefSupport(&s, n) + TestRngRange(&rng, -0.05, 0.05) - DDot(n, o);
		DVec target =
			DAdd(o, DAdd(DScale(height, n), DScale(DDot(DSub(D(RandomVec(&rng, 3.0)), o), toward), toward)));
		ray.translation = V(DScale(TestRngRange(&rng, 1.0, 3.0), DSub(target, o)));
		CheckSolidCast(&s, ray, 10.0, i);
	}
}

/* Distance between the segments a1-a2 and b1-b2 in double (0 when they cross). */
static double RefSegmentSegmentDistance(DVec a1, DVec a2, DVec b1, DVec b2)
{
	double o1 = DCross(DSub(a2, a1), DSub(b1, a1)), o2 = DCross(DSub(a2, a1), DSub(b2, a1));
	double o3 = DCross(DSub(b2, b1), DSub(a1, b1)), o4 = DCross(DSub(b2, b1), DSub(a2, b1));
	if (((o1 < 0.0 && o2 > 0.0) || (o1 > 0.0 && o2 < 0.0)) &&
		((o3 < 0.0 && o4 > 0.0) || (o3 > 0.0 && o4 < 0.0)))
	{
		return 0.0;
	}
	return fmin(fmin(RefDistanceToSegment(a1, b1, b2), RefDistanceToSegment(a2, b1, b2)),
				fmin(RefDistanceToSegment(b1, a1, a2), RefDistanceToSegment(b2, a1, a2)));
}

/* Rays along a segment's line (nearly: the rounding of the points, and offsets of up to 1e-6 of
 * its length), from beyond one end: moving away they miss, and any hit lies on the segment; on
 * exactly collinear lattice cases the fraction is the one at which the ray reaches the end. The
 * crossing of two lines that round-off cannot tell apart decided these before. The fuzzer's case first: the
 * segment's end (-0.010375, -0.010375) lies on the ray's line y = x, behind the origin. */
static void TestGrazingSegments(void)
{
	cd2Segment g = {cd2MakeVec(CD_R(0.0), CD_R(1e-9)), cd2MakeVec(CD_R(-0.010375), CD_R(-0.010375))};
	cd2RayHit hit = UntouchedHit();
	TEST_CHECK(!cd2RaycastSegment(g, Ray(CD_R(-0.0125), CD_R(-0.0125), CD_R(-0.0125), CD_R(-0.0125)), &hit));
	TEST_CHECK(IsUntouched(hit));
	TEST_CHECK(cd2RaycastSegment(g, Ray(CD_R(-0.0125), CD_R(-0.0125), CD_R(0.0125), CD_R(0.0125)), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.17, 1e-4);
	TEST_CHECK(RefDistanceToSegment(D(hit.point), D(g.p1), D(g.p2)) <= 1e-9);

	TestRng rng = TestRngMake(0x6A2E5);
#if CD_DOUBLE
	const double largest = 30.0;
#else
	const double largest = 9.0;
#endif
	int misses = 0, hits = 0;
	for (int n = 0; n < 20000; ++n)
	{
		double k = pow(10.0, TestRngRange(&rng, -largest, largest));
		DVec p1 = DMake(k * TestRngRange(&rng, -1.0, 1.0), k * TestRngRange(&rng, -1.0, 1.0));
		double heading = TestRngRange(&rng, -3.2, 3.2);
		DVec u = DMake(cos(heading), sin(heading)), normal = DMake(-sin(heading), cos(heading));
		double length = k * TestRngRange(&rng, 0.01, 2.0);
		cd2Segment segment = {V(p1), V(DAdd(p1, DScale(length, u)))};
		DVec a = D(segment.p1), b = D(segment.p2);
		double beyond = length * pow(10.0, TestRngRange(&rng, -6.0, 0.0));
		double offset = n % 2 == 0 ? 0.0 : length * TestRngRange(&rng, -1e-6, 1e-6);
		DVec origin = DAdd(DAdd(b, DScale(beyond, u)), DScale(offset, normal));
		double reach =
			n % 4 < 2 ? TestRngRange(&rng, 0.1, 2.0) * length : -TestRngRange(&rng, 0.1, 2.0) * length;
		cd2Ray ray = {V(origin), V(DScale(-reach, u))};
		DVec o = D(ray.origin), d = D(ray.translation);
		double scale =
			fmax(fmax(fabs(o.x), fabs(o.y)), fmax(fmax(fabs(a.x), fabs(a.y)), fmax(fabs(b.x), fabs(b.y))));
		scale = fmax(scale, fmax(fabs(o.x + d.x), fabs(o.y + d.y)));
		double tolerance = 64.0 * (double)CD_REAL_EPSILON * scale;
		double distance = RefSegmentSegmentDistance(o, DAdd(o, d), a, b);
		hit = UntouchedHit();
		bool got = cd2RaycastSegment(segment, ray, &hit);
		if (!got)
		{
			++misses;
			TEST_CHECKF(IsUntouched(hit), "case %d: miss changed *hit", n);
			/* A miss must not cross clearly: both ends of the segment farther than the tolerance from
			 * the ray's line, on opposite sides, the crossing within the ray. */
			double side1 = DCross(d, DSub(a, o)) / sqrt(DDot(d, d)),
				   side2 = DCross(d, DSub(b, o)) / sqrt(DDot(d, d));
			bool clearCrossing = false;
			if (fabs(side1) > tolerance && fabs(side2) > tolerance && (side1 > 0.0) != (side2 > 0.0))
			{
				DVec crossing = DAdd(a, DScale(side1 / (side1 - side2), DSub(b, a)));
				double t = DDot(DSub(crossing, o), d) / DDot(d, d);
				clearCrossing = t > 1e-3 && t < 1.0 - 1e-3;
			}
			TEST_CHECKF(!clearCrossing, "case %d: the ray crosses the segment but misses", n);
			continue;
		}
		++hits;
		double off = RefDistanceToSegment(D(hit.point), a, b);
		TEST_CHECKF(
			off <= tolerance && distance <= tolerance,
			"case %d: hit %.3g off the segment (ray %.3g from it, tolerance %.3g, reach %.3g, beyond %.3g)",
			n, off, distance, tolerance, reach, beyond);
		/* Moving away, only a ray starting on the segment (within round-off) hits. */
		TEST_CHECKF(reach > 0.0 || distance <= tolerance,
					"case %d: a ray moving away from the segment hits at %.9g", n, (double)hit.fraction);
	}
	TEST_CHECKF(hits > 2000 && misses > 9000, "%d hits, %d misses", hits, misses);

	/* Exactly collinear (lattice points along the axes and diagonals, scaled by powers of two): a ray
	 * from beyond the end at distance c along the line with reach r enters at fraction c / r. */
	for (int n = 0; n < 4000; ++n)
	{
		static const int directions[4][2] = {{1, 0}, {0, 1}, {1, 1}, {1, -1}};
		const int* u = directions[n % 4];
		double unit = ldexp(1.0, TestRngInt(&rng, 40) - 20);
		double x = unit * (TestRngInt(&rng, 2001) - 1000), y = unit * (TestRngInt(&rng, 2001) - 1000);
		double length = unit * (1 + TestRngInt(&rng, 100)), beyond = unit * (1 + TestRngInt(&rng, 100));
		double reach = unit * (1 + TestRngInt(&rng, 300));
		cd2Segment segment = {cd2MakeVec((cdReal)x, (cdReal)y),
							  cd2MakeVec((cdReal)(x + length * u[0]), (cdReal)(y + length * u[1]))};
		cd2Vec origin =
			cd2MakeVec((cdReal)(x + (length + beyond) * u[0]), (cdReal)(y + (length + beyond) * u[1]));
		cd2Ray toward = {origin, cd2MakeVec((cdReal)(-reach * u[0]), (cdReal)(-reach * u[1]))};
		cd2Ray away = {origin, cd2MakeVec((cdReal)(reach * u[0]), (cdReal)(reach * u[1]))};
		hit = UntouchedHit();
		TEST_CHECKF(!cd2RaycastSegment(segment, away, &hit) && IsUntouched(hit),
					"lattice case %d: moving away hits", n);
		bool got = cd2RaycastSegment(segment, toward, &hit);
		TEST_CHECKF(got == (beyond <= reach), "lattice case %d: hit %d, beyond %g, reach %g", n, (int)got,
					beyond, reach);
		if (got)
		{
			TEST_CHECKF(fabs((double)hit.fraction - beyond / reach) <= 4.0 * (double)CD_REAL_EPSILON,
						"lattice case %d: fraction %.9g, expected %.9g", n, (double)hit.fraction,
						beyond / reach);
		}
	}
}

/* Segments against Cramer's rule in double. */
static void TestSegmentsAgainstReference(void)
{
	TestRng rng = TestRngMake(0x5eed2003);
	int hits = 0;
	for (int i = 0; i < 10000; ++i)
	{
		cd2Shape s = RandomSolid(&rng, CD2_SHAPE_SEGMENT);
		cd2Ray ray = RandomRay(&rng);
		DVec o = D(ray.origin), d = D(ray.translation), p1 = D(s.segment.p1), p2 = D(s.segment.p2);
		DVec e = DSub(p2, p1), r = DSub(p1, o);
		/* o + t d = p1 + u e  <=>  t d - u e = r. */
		double det = DCross(d, DScale(-1.0, e));
		cd2RayHit hit = UntouchedHit();
		bool got = cd2Raycast(&s, ray, &hit);
		if (!got)
		{
			TEST_CHECKF(IsUntouched(hit), "case %d: miss changed *hit", i);
		}
		double lengths = DLength(d) * DLength(e);
		if (fabs(det) <= 1e-3 * lengths || lengths < 1e-2)
		{
			continue;
		}
		double t = DCross(r, DScale(-1.0, e)) / det;
		double u = DCross(d, r) / det;
		bool clear = fabs(t) > BAND && fabs(t - 1) > BAND && fabs(u) > BAND && fabs(u - 1) > BAND;
		bool expected = t >= 0 && t <= 1 && u >= 0 && u <= 1;
		if (clear)
		{
			TEST_CHECKF(got == expected, "case %d: got %d, expected %d (t %g, u %g)", i, got, expected, t, u);
		}
		if (!got)
		{
			continue;
		}
		++hits;
		DVec normal = D(hit.normal), axis = DNormalize(e);
		TEST_CHECKF(IsFiniteHit(hit) && hit.fraction >= CD_R(0.0) && hit.fraction <= CD_R(1.0), "case %d", i);
		TEST_CHECKF(fabs(DLength(normal) - 1.0) <= 1e-5 && fabs(DDot(normal, axis)) <= 1e-5 &&
						DDot(normal, d) < 0.0,
					"case %d: normal (%g %g)", i, normal.x, normal.y);
		TEST_CHECKF(RefDistanceToSegment(D(hit.point), p1, p2) <= TOL * 10, "case %d: point off the segment",
					i);
		if (clear)
		{
			TEST_CHECKF(fabs((double)hit.fraction - t) * DLength(d) <= TOL * 100,
						"case %d: fraction %.9g vs %.9g", i, (double)hit.fraction, t);
		}
	}
	TEST_CHECKF(hits > 500, "only %d hits", hits);
}

static cd2Shape TransformShape(const cd2Shape* s, cd2Transform xf)
{
	cd2Shape t = *s;
	switch (s->type)
	{
		case CD2_SHAPE_CIRCLE:
			t.circle.center = cd2TransformPoint(xf, s->circle.center);
			break;
		case CD2_SHAPE_CAPSULE:
			t.capsule.p1 = cd2TransformPoint(xf, s->capsule.p1);
			t.capsule.p2 = cd2TransformPoint(xf, s->capsule.p2);
			break;
		case CD2_SHAPE_AABB:
			t.aabb.min = cd2Add(s->aabb.min, xf.p);
			t.aabb.max = cd2Add(s->aabb.max, xf.p);
			break;
		case CD2_SHAPE_BOX:
			t.box.center = cd2TransformPoint(xf, s->box.center);
			t.box.rotation = cd2NormalizeRot(cd2MulRot(xf.q, s->box.rotation));
			break;
		case CD2_SHAPE_POLYGON:
			for (int i = 0; i < s->polygon.count; ++i)
			{
				t.polygon.vertices[i] = cd2TransformPoint(xf, s->polygon.vertices[i]);
				t.polygon.normals[i] = cd2RotateVector(xf.q, s->polygon.normals[i]);
			}
			t.polygon.centroid = cd2TransformPoint(xf, s->polygon.centroid);
			break;
		case CD2_SHAPE_SEGMENT:
			t.segment.p1 = cd2TransformPoint(xf, s->segment.p1);
			t.segment.p2 = cd2TransformPoint(xf, s->segment.p2);
			break;
		default:
			break;
	}
	return t;
}

static void TestRigidTransformInvariance(void)
{
	TestRng rng = TestRngMake(0x5eed2004);
	for (int i = 0; i < 6000; ++i)
	{
		cd2ShapeType type = (cd2ShapeType)(i % 6);
		cd2Shape s = RandomSolid(&rng, type);
		cd2Ray ray = RandomRay(&rng);
		cd2Transform xf = {RandomVec(&rng, 20.0),
						   type == CD2_SHAPE_AABB ? CD2_ROT_IDENTITY : RandomRot(&rng)};
		cd2Shape moved = TransformShape(&s, xf);
		cd2Ray movedRay = {cd2TransformPoint(xf, ray.origin), cd2RotateVector(xf.q, ray.translation)};
		bool clear;
		if (type == CD2_SHAPE_SEGMENT)
		{
			/* Clear when both end points are off the segment's line, the ray is not along it, and
			 * the segment's end points are off the ray's line. */
			DVec o = D(ray.origin), d = D(ray.translation), p1 = D(s.segment.p1), p2 = D(s.segment.p2);
			DVec axis = DNormalize(DSub(p2, p1)), unit = DNormalize(d);
			double band = BAND * 10;
			clear = fabs(DCross(axis, DSub(o, p1))) > band &&
					fabs(DCross(axis, DSub(DAdd(o, d), p1))) > band &&
					fabs(DCross(unit, DSub(p1, o))) > band && fabs(DCross(unit, DSub(p2, o))) > band &&
					DLength(d) > band;
		}
		else
		{
			RefCast ref = RefRaycastSolid(&s, D(ray.origin), D(ray.translation), BAND * 10);
			RefCast movedRef =
				RefRaycastSolid(&moved, D(movedRay.origin), D(movedRay.translation), BAND * 10);
			clear = ref.clear && movedRef.clear;
		}
		if (!clear)
		{
			continue;
		}
		cd2RayHit hit = UntouchedHit(), movedHit = UntouchedHit();
		bool got = cd2Raycast(&s, ray, &hit);
		bool movedGot = cd2Raycast(&moved, movedRay, &movedHit);
		TEST_CHECKF(got == movedGot, "%s case %d: %d vs %d after a rigid transform",
					cd2GetShapeTypeName(type), i, got, movedGot);
		if (got && movedGot)
		{
			double length = DLength(D(ray.translation));
			TEST_CHECKF(fabs((double)hit.fraction - (double)movedHit.fraction) * length <= 10 * TOL * 10,
						"%s case %d: fraction %.9g vs %.9g", cd2GetShapeTypeName(type), i,
						(double)hit.fraction, (double)movedHit.fraction);
			DVec rotated = DRotate(xf.q, D(hit.normal));
			TEST_CHECKF(DLength(DSub(rotated, D(movedHit.normal))) <= 10 * TOL, "%s case %d: normal",
						cd2GetShapeTypeName(type), i);
		}
	}
}

/* The same configuration embedded in the z = 0 plane gives the same answers in 3D. */
static cd3Vec To3(cd2Vec v)
{
	return cd3MakeVec(v.x, v.y, CD_R(0.0));
}

static void TestAgreesWith3D(void)
{
	TestRng rng = TestRngMake(0x5eed2005);
	cd2ShapeType types[] = {CD2_SHAPE_CIRCLE, CD2_SHAPE_CAPSULE, CD2_SHAPE_AABB, CD2_SHAPE_BOX,
							CD2_SHAPE_SEGMENT};
	int compared = 0;
	for (int i = 0; i < 5000; ++i)
	{
		cd2Shape s = RandomSolid(&rng, types[i % 5]);
		cd2Ray ray = RandomRay(&rng);
		cd3Shape s3;
		switch (s.type)
		{
			case CD2_SHAPE_CIRCLE:
				s3.type = CD3_SHAPE_SPHERE;
				s3.sphere.center = To3(s.circle.center);
				s3.sphere.radius = s.circle.radius;
				break;
			case CD2_SHAPE_CAPSULE:
				s3.type = CD3_SHAPE_CAPSULE;
				s3.capsule.p1 = To3(s.capsule.p1);
				s3.capsule.p2 = To3(s.capsule.p2);
				s3.capsule.radius = s.capsule.radius;
				break;
			case CD2_SHAPE_AABB:
				s3.type = CD3_SHAPE_AABB;
				s3.aabb.min = cd3MakeVec(s.aabb.min.x, s.aabb.min.y, CD_R(-1.0));
				s3.aabb.max = cd3MakeVec(s.aabb.max.x, s.aabb.max.y, CD_R(1.0));
				break;
			case CD2_SHAPE_BOX:
			{
				/* cos(a) = 1 - 2 sin^2(a / 2) and sin(a) = 2 sin(a / 2) cos(a / 2): the half-angle
				 * quaternion about z. */
				double angle = atan2((double)s.box.rotation.s, (double)s.box.rotation.c);
				s3.type = CD3_SHAPE_BOX;
				s3.box.center = To3(s.box.center);
				s3.box.halfExtents = cd3MakeVec(s.box.halfExtents.x, s.box.halfExtents.y, CD_R(1.0));
				s3.box.rotation =
					cd3MakeQuat(CD_R(0.0), CD_R(0.0), (cdReal)sin(0.5 * angle), (cdReal)cos(0.5 * angle));
				break;
			}
			default:
				s3.type = CD3_SHAPE_SEGMENT;
				s3.segment.p1 = To3(s.segment.p1);
				s3.segment.p2 = To3(s.segment.p2);
				break;
		}
		cd3Ray ray3 = {To3(ray.origin), To3(ray.translation)};
		cd2RayHit hit = UntouchedHit();
		cd3RayHit hit3;
		bool got = cd2Raycast(&s, ray, &hit);
		bool got3 = cd3Raycast(&s3, ray3, &hit3);
		if (s.type != CD2_SHAPE_SEGMENT)
		{
			RefCast ref = RefRaycastSolid(&s, D(ray.origin), D(ray.translation), BAND * 10);
			if (!ref.clear)
			{
				continue;
			}
		}
		else if (!got)
		{
			continue; /* a 2D miss may still pass within the 3D tolerance of the segment */
		}
		++compared;
		TEST_CHECKF(got == got3, "%s case %d: 2D %d, 3D %d", cd2GetShapeTypeName(s.type), i, got, got3);
		if (got && got3)
		{
			double length = DLength(D(ray.translation));
			TEST_CHECKF(fabs((double)hit.fraction - (double)hit3.fraction) * length <= TOL * 10 &&
							fabs((double)hit.normal.x - (double)hit3.normal.x) <= 10 * TOL &&
							fabs((double)hit.normal.y - (double)hit3.normal.y) <= 10 * TOL &&
							fabs((double)hit3.normal.z) <= 10 * TOL,
						"%s case %d: 2D (%.9g; %g %g), 3D (%.9g; %g %g %g)", cd2GetShapeTypeName(s.type), i,
						(double)hit.fraction, (double)hit.normal.x, (double)hit.normal.y,
						(double)hit3.fraction, (double)hit3.normal.x, (double)hit3.normal.y,
						(double)hit3.normal.z);
		}
	}
	TEST_CHECKF(compared > 3000, "only %d cases compared", compared);
}

/* A box polygon from the polygon builder gives the same answers as the box. */
static void TestBoxPolygonAgreesWithBox(void)
{
	TestRng rng = TestRngMake(0x5eed2006);
	for (int i = 0; i < 2000; ++i)
	{
		cd2Box box = RandomSolid(&rng, CD2_SHAPE_BOX).box;
		box.halfExtents = cd2MakeVec(R(&rng, 0.1, 2.0), R(&rng, 0.1, 2.0));
		cd2Shape polygon;
		polygon.type = CD2_SHAPE_POLYGON;
		cdResult result = cd2MakeBoxPolygon(box, &polygon.polygon);
		TEST_CHECKF(result == CD_OK, "case %d: cd2MakeBoxPolygon failed: %s", i, cdGetResultString(result));
		if (result != CD_OK)
		{
			continue;
		}
		cd2Shape boxShape;
		boxShape.type = CD2_SHAPE_BOX;
		boxShape.box = box;
		cd2Ray ray = RandomRay(&rng);
		RefCast ref = RefRaycastSolid(&boxShape, D(ray.origin), D(ray.translation), BAND * 10);
		if (!ref.clear)
		{
			continue;
		}
		cd2RayHit a = UntouchedHit(), b = UntouchedHit();
		bool gotA = cd2Raycast(&boxShape, ray, &a), gotB = cd2Raycast(&polygon, ray, &b);
		TEST_CHECKF(gotA == gotB, "case %d: box %d, polygon %d", i, gotA, gotB);
		if (gotA && gotB)
		{
			TEST_CHECKF(fabs((double)a.fraction - (double)b.fraction) * DLength(D(ray.translation)) <=
								TOL * 10 &&
							DLength(DSub(D(a.normal), D(b.normal))) <= 10 * TOL,
						"case %d: box %.9g, polygon %.9g", i, (double)a.fraction, (double)b.fraction);
		}
	}
}

static void TestScales(void)
{
	TestRng rng = TestRngMake(0x5eed2007);
#if CD_DOUBLE
	const double scales[] = {0x1p-100, 0x1p-30, 0x1p20, 0x1p30, 0x1p100};
	const double offsets[] = {1e6, 1e9, 1e30};
#else
	const double scales[] = {0x1p-30, 0x1p-20, 0x1p20, 0x1p30};
	const double offsets[] = {1e6, 1e8, 1e9};
#endif
	int scaleCount = (int)(sizeof(scales) / sizeof(scales[0]));
	int offsetCount = (int)(sizeof(offsets) / sizeof(offsets[0]));
	for (int i = 0; i < 3000; ++i)
	{
		cd2ShapeType type = (cd2ShapeType)(i % 6);
		cd2Shape s = RandomSolid(&rng, type);
		cd2Ray ray = RandomRay(&rng);
		cd2RayHit base = UntouchedHit();
		bool baseGot = cd2Raycast(&s, ray, &base);

		cdReal k = (cdReal)scales[i % scaleCount];
		cd2Shape scaled = s;
		switch (type)
		{
			case CD2_SHAPE_CIRCLE:
				scaled.circle.center = cd2Scale(k, s.circle.center);
				scaled.circle.radius = k * s.circle.radius;
				break;
			case CD2_SHAPE_CAPSULE:
				scaled.capsule.p1 = cd2Scale(k, s.capsule.p1);
				scaled.capsule.p2 = cd2Scale(k, s.capsule.p2);
				scaled.capsule.radius = k * s.capsule.radius;
				break;
			case CD2_SHAPE_AABB:
				scaled.aabb.min = cd2Scale(k, s.aabb.min);
				scaled.aabb.max = cd2Scale(k, s.aabb.max);
				break;
			case CD2_SHAPE_BOX:
				scaled.box.center = cd2Scale(k, s.box.center);
				scaled.box.halfExtents = cd2Scale(k, s.box.halfExtents);
				break;
			case CD2_SHAPE_POLYGON:
				for (int v = 0; v < s.polygon.count; ++v)
				{
					scaled.polygon.vertices[v] = cd2Scale(k, s.polygon.vertices[v]);
				}
				scaled.polygon.centroid = cd2Scale(k, s.polygon.centroid);
				scaled.polygon.radius = k * s.polygon.radius;
				break;
			default:
				scaled.segment.p1 = cd2Scale(k, s.segment.p1);
				scaled.segment.p2 = cd2Scale(k, s.segment.p2);
				break;
		}
		cd2Ray scaledRay = {cd2Scale(k, ray.origin), cd2Scale(k, ray.translation)};
		cd2RayHit hit = UntouchedHit();
		bool got = cd2Raycast(&scaled, scaledRay, &hit);
		TEST_CHECKF(got == baseGot, "%s case %d scale %g: %d vs %d", cd2GetShapeTypeName(type), i, (double)k,
					got, baseGot);
		if (got && baseGot)
		{
			TEST_CHECKF(IsFiniteHit(hit) && fabs((double)hit.fraction - (double)base.fraction) <= 1e-5 &&
							DLength(DSub(D(hit.normal), D(base.normal))) <= 1e-5,
						"%s case %d scale %g: fraction %.9g vs %.9g", cd2GetShapeTypeName(type), i, (double)k,
						(double)hit.fraction, (double)base.fraction);
		}

		double offset = offsets[i % offsetCount];
		double angle = TestRngRange(&rng, 0.0, 6.283185307179586);
		cd2Transform xf = {cd2MakeVec((cdReal)(offset * cos(angle)), (cdReal)(offset * sin(angle))),
						   CD2_ROT_IDENTITY};
		bool useScaled = TestRngInt(&rng, 2) == 0;
		cd2Shape far = TransformShape(useScaled ? &scaled : &s, xf);
		cd2Ray farRay = useScaled ? scaledRay : ray;
		farRay.origin = cd2Add(farRay.origin, xf.p);
		hit = UntouchedHit();
		if (cd2Raycast(&far, farRay, &hit))
		{
			double n = DLength(D(hit.normal));
			TEST_CHECKF(IsFiniteHit(hit) && hit.fraction >= CD_R(0.0) && hit.fraction <= CD_R(1.0) &&
							(fabs(n - 1.0) <= 1e-5 || n == 0.0),
						"%s case %d offset %g: fraction %g normal length %g", cd2GetShapeTypeName(type), i,
						offset, (double)hit.fraction, n);
		}
	}
}

int main(void)
{
	TEST_RUN(TestCircleExact);
	TEST_RUN(TestCapsuleExact);
	TEST_RUN(TestCapsuleRayFromSurfaceInward);
	TEST_RUN(TestAabbExact);
	TEST_RUN(TestBoxExact);
	TEST_RUN(TestPolygonExact);
	TEST_RUN(TestSegmentExact);
	TEST_RUN(TestSliverPolygon);
	TEST_RUN(TestRimThinnerThanRoundOff);
	TEST_RUN(TestDispatcher);
	TEST_RUN(TestSolidsAgainstReference);
	TEST_RUN(TestSolidsNearTangent);
	TEST_RUN(TestSegmentsAgainstReference);
	TEST_RUN(TestGrazingSegments);
	TEST_RUN(TestRigidTransformInvariance);
	TEST_RUN(TestAgreesWith3D);
	TEST_RUN(TestBoxPolygonAgreesWithBox);
	TEST_RUN(TestScales);
	return TEST_SUMMARY();
}
