/* Tests of the 3D ray casts: exact cases per shape, and property tests against an independent
 * double-precision reference (a convex function that is <= 0 exactly on each solid shape, searched
 * along the ray), support functions for the normals, rigid-transform invariance and scale
 * invariance at huge and tiny coordinates. */
#include "collide/query3.h"
#include "test.h"

#include <float.h>

#if CD_DOUBLE
/* Relative tolerances for round-off, and the band around the surface where the reference and the
 * library may disagree about hit or miss. */
#define TOL 1e-9
#define BAND 1e-6
#else
#define TOL 2e-4
#define BAND 1e-2
#endif

/* ---- double-precision vectors, independent of the library's math ---------------------------- */
typedef struct DVec
{
	double x, y, z;
} DVec;

static DVec DMake(double x, double y, double z)
{
	DVec v = {x, y, z};
	return v;
}

static DVec D(cd3Vec v)
{
	return DMake((double)v.x, (double)v.y, (double)v.z);
}

static cd3Vec V(DVec v)
{
	return cd3MakeVec((cdReal)v.x, (cdReal)v.y, (cdReal)v.z);
}

static DVec DAdd(DVec a, DVec b)
{
	return DMake(a.x + b.x, a.y + b.y, a.z + b.z);
}

static DVec DSub(DVec a, DVec b)
{
	return DMake(a.x - b.x, a.y - b.y, a.z - b.z);
}

static DVec DScale(double s, DVec a)
{
	return DMake(s * a.x, s * a.y, s * a.z);
}

static double DDot(DVec a, DVec b)
{
	return a.x * b.x + a.y * b.y + a.z * b.z;
}

static DVec DCross(DVec a, DVec b)
{
	return DMake(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

static double DLength(DVec a)
{
	return sqrt(DDot(a, a));
}

static DVec DNormalize(DVec a)
{
	double length = DLength(a);
	return length > 0.0 ? DScale(1.0 / length, a) : DMake(0.0, 0.0, 0.0);
}

/* Rotation by the quaternion q (renormalized in double), as a 3x3 matrix product. */
static DVec DRotate(cd3Quat q, DVec v)
{
	double n = sqrt((double)q.x * q.x + (double)q.y * q.y + (double)q.z * q.z + (double)q.w * q.w);
	double x = q.x / n, y = q.y / n, z = q.z / n, w = q.w / n;
	return DMake((1 - 2 * (y * y + z * z)) * v.x + 2 * (x * y - w * z) * v.y + 2 * (x * z + w * y) * v.z,
				 2 * (x * y + w * z) * v.x + (1 - 2 * (x * x + z * z)) * v.y + 2 * (y * z - w * x) * v.z,
				 2 * (x * z - w * y) * v.x + 2 * (y * z + w * x) * v.y + (1 - 2 * (x * x + y * y)) * v.z);
}

static DVec DInvRotate(cd3Quat q, DVec v)
{
	return DRotate(cd3MakeQuat(-q.x, -q.y, -q.z, q.w), v);
}

/* ---- reference geometry in double -------------------------------------------------------------- */

static double RefDistanceToSegment(DVec p, DVec a, DVec b)
{
	DVec ab = DSub(b, a);
	double lengthSquared = DDot(ab, ab);
	double s = lengthSquared > 0.0 ? DDot(DSub(p, a), ab) / lengthSquared : 0.0;
	s = s < 0.0 ? 0.0 : (s > 1.0 ? 1.0 : s);
	return DLength(DSub(p, DAdd(a, DScale(s, ab))));
}

/* A convex function whose zero sublevel set is the solid shape: the signed distance for spheres and
 * capsules, the largest signed face-plane distance for boxes and planes. */
static double RefValue(const cd3Shape* s, DVec p)
{
	switch (s->type)
	{
		case CD3_SHAPE_SPHERE:
			return DLength(DSub(p, D(s->sphere.center))) - (double)s->sphere.radius;
		case CD3_SHAPE_CAPSULE:
			return RefDistanceToSegment(p, D(s->capsule.p1), D(s->capsule.p2)) - (double)s->capsule.radius;
		case CD3_SHAPE_AABB:
		{
			DVec lo = D(s->aabb.min), hi = D(s->aabb.max);
			double v = fmax(lo.x - p.x, p.x - hi.x);
			v = fmax(v, fmax(lo.y - p.y, p.y - hi.y));
			return fmax(v, fmax(lo.z - p.z, p.z - hi.z));
		}
		case CD3_SHAPE_BOX:
		{
			DVec local = DInvRotate(s->box.rotation, DSub(p, D(s->box.center)));
			DVec h = D(s->box.halfExtents);
			return fmax(fabs(local.x) - h.x, fmax(fabs(local.y) - h.y, fabs(local.z) - h.z));
		}
		case CD3_SHAPE_PLANE:
			return DDot(D(s->plane.normal), p) - (double)s->plane.offset;
		default:
			return 0.0;
	}
}

/* max over the shape of dot(n, x): a unit n is an outward normal at a boundary point x exactly
 * when the support value equals dot(n, x). Planes are checked separately. */
static double RefSupport(const cd3Shape* s, DVec n)
{
	switch (s->type)
	{
		case CD3_SHAPE_SPHERE:
			return DDot(n, D(s->sphere.center)) + (double)s->sphere.radius * DLength(n);
		case CD3_SHAPE_CAPSULE:
			return fmax(DDot(n, D(s->capsule.p1)), DDot(n, D(s->capsule.p2))) +
				   (double)s->capsule.radius * DLength(n);
		case CD3_SHAPE_AABB:
		{
			DVec lo = D(s->aabb.min), hi = D(s->aabb.max);
			return fmax(n.x * lo.x, n.x * hi.x) + fmax(n.y * lo.y, n.y * hi.y) + fmax(n.z * lo.z, n.z * hi.z);
		}
		case CD3_SHAPE_BOX:
		{
			DVec local = DInvRotate(s->box.rotation, n);
			DVec h = D(s->box.halfExtents);
			return DDot(n, D(s->box.center)) + fabs(local.x) * h.x + fabs(local.y) * h.y +
				   fabs(local.z) * h.z;
		}
		default:
			return 0.0;
	}
}

typedef struct RefCast
{
	bool hit;
	double fraction;
	bool clear; /* far enough from every tangency that hit/miss and the fraction are well defined */
} RefCast;

/* Minimizes the convex RefValue along the ray by ternary search, then bisects for the entry. */
static RefCast RefRaycastSolid(const cd3Shape* s, DVec o, DVec d, double band)
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

static cd3Vec RandomVec(TestRng* rng, double extent)
{
	return cd3MakeVec(R(rng, -extent, extent), R(rng, -extent, extent), R(rng, -extent, extent));
}

static cd3Quat RandomQuat(TestRng* rng)
{
	double x, y, z, w, n;
	do
	{
		x = TestRngRange(rng, -1, 1);
		y = TestRngRange(rng, -1, 1);
		z = TestRngRange(rng, -1, 1);
		w = TestRngRange(rng, -1, 1);
		n = sqrt(x * x + y * y + z * z + w * w);
	} while (n < 0.1 || n > 1.0);
	return cd3MakeQuat((cdReal)(x / n), (cdReal)(y / n), (cdReal)(z / n), (cdReal)(w / n));
}

static cd3Vec RandomUnit(TestRng* rng)
{
	for (;;)
	{
		DVec v = D(RandomVec(rng, 1.0));
		double length = DLength(v);
		if (length > 0.1 && length < 1.0)
		{
			return V(DScale(1.0 / length, v));
		}
	}
}

/* A solid shape within a few units of the origin; every tenth one degenerate (zero size). */
static cd3Shape RandomSolid(TestRng* rng, cd3ShapeType type)
{
	bool degenerate = TestRngInt(rng, 10) == 0;
	cd3Shape s;
	s.type = type;
	switch (type)
	{
		case CD3_SHAPE_SPHERE:
			s.sphere.center = RandomVec(rng, 3.0);
			s.sphere.radius = degenerate ? CD_R(0.0) : R(rng, 0.1, 3.0);
			break;
		case CD3_SHAPE_CAPSULE:
			s.capsule.p1 = RandomVec(rng, 3.0);
			s.capsule.p2 = degenerate ? s.capsule.p1 : cd3Add(s.capsule.p1, RandomVec(rng, 2.0));
			s.capsule.radius = TestRngInt(rng, 10) == 0 ? CD_R(0.0) : R(rng, 0.1, 2.0);
			break;
		case CD3_SHAPE_AABB:
		{
			cd3Vec center = RandomVec(rng, 3.0);
			cd3Vec half =
				degenerate ? CD3_VEC_ZERO : cd3MakeVec(R(rng, 0.1, 2), R(rng, 0.1, 2), R(rng, 0.1, 2));
			s.aabb.min = cd3Sub(center, half);
			s.aabb.max = cd3Add(center, half);
			break;
		}
		case CD3_SHAPE_BOX:
			s.box.center = RandomVec(rng, 3.0);
			s.box.halfExtents =
				degenerate ? CD3_VEC_ZERO : cd3MakeVec(R(rng, 0.1, 2), R(rng, 0.1, 2), R(rng, 0.1, 2));
			s.box.rotation = RandomQuat(rng);
			break;
		case CD3_SHAPE_PLANE:
			s.plane.normal = RandomUnit(rng);
			s.plane.offset = R(rng, -3.0, 3.0);
			break;
		default:
			break;
	}
	return s;
}

/* A ray from a random origin towards a point near the origin, reaching 0.3 to 2 times as far. */
static cd3Ray RandomRay(TestRng* rng)
{
	cd3Ray ray;
	ray.origin = RandomVec(rng, 10.0);
	cd3Vec target = RandomVec(rng, 4.0);
	ray.translation = cd3Scale(R(rng, 0.3, 2.0), cd3Sub(target, ray.origin));
	if (TestRngInt(rng, 50) == 0)
	{
		ray.translation = CD3_VEC_ZERO;
	}
	return ray;
}

static bool IsFiniteHit(cd3RayHit hit)
{
	return isfinite(hit.fraction) && cd3IsValidVec(hit.point) && cd3IsValidVec(hit.normal);
}

static cd3RayHit UntouchedHit(void)
{
	cd3RayHit hit;
	hit.fraction = CD_R(42.0);
	hit.point = cd3MakeVec(CD_R(1.0), CD_R(2.0), CD_R(3.0));
	hit.normal = cd3MakeVec(CD_R(4.0), CD_R(5.0), CD_R(6.0));
	return hit;
}

static bool IsUntouched(cd3RayHit hit)
{
	cd3RayHit u = UntouchedHit();
	return hit.fraction == u.fraction && cd3VecEqual(hit.point, u.point) && cd3VecEqual(hit.normal, u.normal);
}

/* The contract for one cast of a solid shape, checked against the reference; `scale` is the size
 * of the scene (tolerances are relative to it). */
static void CheckSolidCast(const cd3Shape* s, cd3Ray ray, double scale, int index)
{
	cd3RayHit hit = UntouchedHit();
	bool got = cd3Raycast(s, ray, &hit);
	DVec o = D(ray.origin), d = D(ray.translation);
	double tol = TOL * scale;
	RefCast ref = RefRaycastSolid(s, o, d, BAND * scale);
	double valueStart = RefValue(s, o);
	const char* name = cd3GetShapeTypeName(s->type);

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
		/* A miss must really miss: sample the ray against the shape. */
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
		/* Clearly inside: fraction 0, point = origin, normal = -normalize(translation). */
		TEST_CHECKF(hit.fraction == CD_R(0.0) && cd3VecEqual(hit.point, ray.origin),
					"%s case %d: inside origin gave fraction %g", name, index, (double)hit.fraction);
		DVec expectedNormal = DScale(-1.0, DNormalize(d));
		TEST_CHECKF(DLength(DSub(normal, expectedNormal)) <= 1e-5, "%s case %d: inside normal (%g %g %g)",
					name, index, normal.x, normal.y, normal.z);
		return;
	}
	if (valueStart <= BAND * scale)
	{
		return; /* starts on the surface within round-off: either answer is right */
	}

	/* Clearly outside: the hit is an entry point on the surface with an outward normal. */
	TEST_CHECKF(fabs(DLength(normal) - 1.0) <= 1e-5, "%s case %d: normal length %.9g", name, index,
				DLength(normal));
	TEST_CHECKF(fabs(RefValue(s, point)) <= tol, "%s case %d: point %g off the surface", name, index,
				RefValue(s, point));
	if (s->type == CD3_SHAPE_PLANE)
	{
		TEST_CHECKF(DLength(DSub(normal, D(s->plane.normal))) <= 1e-6,
					"%s case %d: normal is not the plane's", name, index);
	}
	else
	{
		double support = RefSupport(s, normal);
		TEST_CHECKF(fabs(support - DDot(normal, point)) <= tol,
					"%s case %d: normal not outward: support %.9g, at point %.9g", name, index, support,
					DDot(normal, point));
	}
	TEST_CHECKF(DDot(normal, DNormalize(d)) <= 1e-5, "%s case %d: the ray leaves through the normal's face",
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

static cd3Ray Ray(cdReal ox, cdReal oy, cdReal oz, cdReal dx, cdReal dy, cdReal dz)
{
	cd3Ray ray = {cd3MakeVec(ox, oy, oz), cd3MakeVec(dx, dy, dz)};
	return ray;
}

#define CHECK_VEC(v, ex, ey, ez, tol)                                                                        \
	do                                                                                                       \
	{                                                                                                        \
		TEST_CHECK_NEAR((v).x, ex, tol);                                                                     \
		TEST_CHECK_NEAR((v).y, ey, tol);                                                                     \
		TEST_CHECK_NEAR((v).z, ez, tol);                                                                     \
	} while (0)

#define EXACT 1e-6

static void TestSphereExact(void)
{
	cd3Sphere s = {cd3MakeVec(CD_R(1.0), CD_R(2.0), CD_R(3.0)), CD_R(1.0)};
	cd3RayHit hit;

	/* Hits along each axis direction, from both sides: entry at distance 2 of a ray of length 4. */
	for (int axis = 0; axis < 3; ++axis)
	{
		for (int sign = -1; sign <= 1; sign += 2)
		{
			cdReal o[3] = {CD_R(1.0), CD_R(2.0), CD_R(3.0)};
			cdReal d[3] = {CD_R(0.0), CD_R(0.0), CD_R(0.0)};
			o[axis] += (cdReal)(3 * sign);
			d[axis] = (cdReal)(-4 * sign);
			hit = UntouchedHit();
			TEST_CHECK(cd3RaycastSphere(s, Ray(o[0], o[1], o[2], d[0], d[1], d[2]), &hit));
			TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
			cdReal n[3] = {CD_R(0.0), CD_R(0.0), CD_R(0.0)};
			n[axis] = (cdReal)sign;
			CHECK_VEC(hit.normal, n[0], n[1], n[2], EXACT);
			CHECK_VEC(hit.point, 1.0 + n[0], 2.0 + n[1], 3.0 + n[2], EXACT);
		}
	}

	/* Miss beside, pointing away, and ending just before the sphere. */
	hit = UntouchedHit();
	TEST_CHECK(!cd3RaycastSphere(s, Ray(-2, 4, 3, 6, 0, 0), &hit));
	TEST_CHECK(!cd3RaycastSphere(s, Ray(-2, 2, 3, -6, 0, 0), &hit));
	TEST_CHECK(!cd3RaycastSphere(s, Ray(-2, 2, 3, CD_R(1.99), 0, 0), &hit));
	TEST_CHECK(IsUntouched(hit));
	/* Ending exactly on the surface (x = 0) hits at fraction 1. */
	TEST_CHECK(cd3RaycastSphere(s, Ray(-2, 2, 3, 2, 0, 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 1.0, EXACT);

	/* Tangent: the line touches at (1, 3, 3) (closed shapes count touching). */
	hit = UntouchedHit();
	TEST_CHECK(cd3RaycastSphere(s, Ray(-3, 3, 3, 8, 0, 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, 1e-3);
	CHECK_VEC(hit.normal, 0.0, 1.0, 0.0, 1e-3);

	/* Inside and on the surface: fraction 0, point = origin, normal = -normalize(translation). */
	hit = UntouchedHit();
	TEST_CHECK(cd3RaycastSphere(s, Ray(CD_R(1.5), 2, 3, 0, 0, 5), &hit));
	TEST_CHECK(hit.fraction == CD_R(0.0));
	CHECK_VEC(hit.point, 1.5, 2.0, 3.0, 0.0);
	CHECK_VEC(hit.normal, 0.0, 0.0, -1.0, EXACT);
	TEST_CHECK(cd3RaycastSphere(s, Ray(2, 2, 3, 3, 0, 0), &hit)); /* on the surface, moving out */
	TEST_CHECK(hit.fraction == CD_R(0.0));
	CHECK_VEC(hit.normal, -1.0, 0.0, 0.0, EXACT);

	/* Zero-length rays hit only from inside, with a zero normal. */
	TEST_CHECK(cd3RaycastSphere(s, Ray(1, 2, CD_R(3.5), 0, 0, 0), &hit));
	TEST_CHECK(hit.fraction == CD_R(0.0));
	CHECK_VEC(hit.normal, 0.0, 0.0, 0.0, 0.0);
	hit = UntouchedHit();
	TEST_CHECK(!cd3RaycastSphere(s, Ray(5, 2, 3, 0, 0, 0), &hit));
	TEST_CHECK(IsUntouched(hit));

	/* Zero radius: a point, hit only by rays through it; the normal faces back along the ray. */
	cd3Sphere point = {cd3MakeVec(CD_R(1.0), CD_R(0.0), CD_R(0.0)), CD_R(0.0)};
	TEST_CHECK(cd3RaycastSphere(point, Ray(-1, 0, 0, 4, 0, 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.normal, -1.0, 0.0, 0.0, EXACT);
	TEST_CHECK(!cd3RaycastSphere(point, Ray(-1, CD_R(0.001), 0, 4, 0, 0), &hit));
	/* Diagonal through a zero-radius sphere: round-off must not turn the normal around. */
	cd3Sphere diagonal = {cd3MakeVec(CD_R(1.0), CD_R(1.0), CD_R(1.0)), CD_R(0.0)};
	TEST_CHECK(cd3RaycastSphere(diagonal, Ray(0, 0, 0, 2, 2, 2), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.normal, -0.57735027, -0.57735027, -0.57735027, EXACT);
	/* Rays from the origin through zero-radius spheres (and zero-length, zero-radius capsules) in
	 * many directions: when they hit, the normal faces back along the ray. */
	int hits = 0;
	for (int a = -3; a <= 3; ++a)
	{
		for (int b = -3; b <= 3; ++b)
		{
			for (int c = -3; c <= 3; ++c)
			{
				for (int k = 1; k <= 7 && (a != 0 || b != 0 || c != 0); ++k)
				{
					cd3Vec center =
						cd3Scale(CD_R(0.1) * (cdReal)k, cd3MakeVec((cdReal)a, (cdReal)b, (cdReal)c));
					cd3Sphere dot = {center, CD_R(0.0)};
					cd3Capsule pill = {center, center, CD_R(0.0)};
					cd3Ray ray = {CD3_VEC_ZERO, cd3Scale(CD_R(3.0), center)};
					if (cd3RaycastSphere(dot, ray, &hit))
					{
						++hits;
						TEST_CHECKF(cd3Dot(hit.normal, ray.translation) < CD_R(0.0) &&
										fabs((double)cd3Length(hit.normal) - 1.0) <= 1e-5,
									"(%d %d %d) * %d: normal (%g %g %g)", a, b, c, k, (double)hit.normal.x,
									(double)hit.normal.y, (double)hit.normal.z);
					}
					if (cd3RaycastCapsule(pill, ray, &hit))
					{
						TEST_CHECKF(cd3Dot(hit.normal, ray.translation) < CD_R(0.0),
									"capsule (%d %d %d) * %d", a, b, c, k);
					}
				}
			}
		}
	}
	TEST_CHECKF(hits > 500, "only %d of the rays through a point hit it", hits);
}

static void TestCapsuleExact(void)
{
	/* Axis from (0,0,0) to (4,0,0), radius 1. */
	cd3Capsule c = {CD3_VEC_ZERO, cd3MakeVec(CD_R(4.0), CD_R(0.0), CD_R(0.0)), CD_R(1.0)};
	cd3RayHit hit;

	/* Side hits from +y, -y, +z, -z over the middle. */
	TEST_CHECK(cd3RaycastCapsule(c, Ray(2, 5, 0, 0, -8, 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.point, 2.0, 1.0, 0.0, EXACT);
	CHECK_VEC(hit.normal, 0.0, 1.0, 0.0, EXACT);
	TEST_CHECK(cd3RaycastCapsule(c, Ray(3, -5, 0, 0, 8, 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.normal, 0.0, -1.0, 0.0, EXACT);
	TEST_CHECK(cd3RaycastCapsule(c, Ray(1, 0, 3, 0, 0, -4), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.normal, 0.0, 0.0, 1.0, EXACT);
	TEST_CHECK(cd3RaycastCapsule(c, Ray(1, 0, -3, 0, 0, 4), &hit));
	CHECK_VEC(hit.normal, 0.0, 0.0, -1.0, EXACT);

	/* Along the axis (parallel to the side): enters the end caps. */
	TEST_CHECK(cd3RaycastCapsule(c, Ray(-5, 0, 0, 8, 0, 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.point, -1.0, 0.0, 0.0, EXACT);
	CHECK_VEC(hit.normal, -1.0, 0.0, 0.0, EXACT);
	TEST_CHECK(cd3RaycastCapsule(c, Ray(9, 0, 0, -8, 0, 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.normal, 1.0, 0.0, 0.0, EXACT);
	/* Parallel to the axis, off the axis by 0.6: enters the cap sphere at x = -0.8. */
	TEST_CHECK(cd3RaycastCapsule(c, Ray(-5, CD_R(0.6), 0, 10, 0, 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.42, EXACT);
	CHECK_VEC(hit.normal, -0.8, 0.6, 0.0, EXACT);
	/* Parallel to the axis and outside the radius: miss. */
	hit = UntouchedHit();
	TEST_CHECK(!cd3RaycastCapsule(c, Ray(-5, CD_R(1.01), 0, 10, 0, 0), &hit));
	TEST_CHECK(IsUntouched(hit));
	/* Tangent to the side. */
	TEST_CHECK(cd3RaycastCapsule(c, Ray(-5, 1, 0, 10, 0, 0), &hit));
	CHECK_VEC(hit.normal, 0.0, 1.0, 0.0, 1e-3);
	/* Diagonal onto the cap beyond the end: from (6, 3, 0) towards (4, 0, 0)... enters the p2 ball. */
	TEST_CHECK(cd3RaycastCapsule(c, Ray(4, 0, 5, 0, 0, -5), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.8, EXACT);
	CHECK_VEC(hit.normal, 0.0, 0.0, 1.0, EXACT);
	TEST_CHECK(cd3RaycastCapsule(c, Ray(8, 3, 0, -4, -3, 0), &hit));
	/* |(8,3)-(4,0)| = 5: the entry is 4 along the unit direction (-0.8, -0.6) of length 5. */
	TEST_CHECK_NEAR(hit.fraction, 0.8, EXACT);
	CHECK_VEC(hit.normal, 0.8, 0.6, 0.0, EXACT);
	/* Ends just before. */
	TEST_CHECK(!cd3RaycastCapsule(c, Ray(2, 5, 0, 0, CD_R(-3.99), 0), &hit));
	/* Nearly parallel to the axis: into the cap ball at x = -sqrt(1 - 0.999^2), and onto the side
	 * at a grazing angle. */
	TEST_CHECK(cd3RaycastCapsule(c, Ray(-5, CD_R(0.999), 0, 10, CD_R(1e-7), 0), &hit));
	TEST_CHECK(IsFiniteHit(hit));
	TEST_CHECK_NEAR(hit.fraction, (5.0 - sqrt(1.0 - 0.999 * 0.999)) / 10.0, 1e-3);
	TEST_CHECK(cd3RaycastCapsule(c, Ray(1, CD_R(1.001), 0, 2, CD_R(-0.002), 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, 1e-3);
	CHECK_VEC(hit.normal, 0.0, 1.0, 0.0, 1e-5);

	/* Inside, on the surface, zero-length. */
	TEST_CHECK(cd3RaycastCapsule(c, Ray(2, CD_R(0.5), 0, 0, 3, 0), &hit));
	TEST_CHECK(hit.fraction == CD_R(0.0));
	CHECK_VEC(hit.normal, 0.0, -1.0, 0.0, EXACT);
	TEST_CHECK(cd3RaycastCapsule(c, Ray(2, 1, 0, 0, -3, 0), &hit));
	TEST_CHECK(hit.fraction == CD_R(0.0));
	CHECK_VEC(hit.point, 2.0, 1.0, 0.0, 0.0);
	CHECK_VEC(hit.normal, 0.0, 1.0, 0.0, EXACT);
	TEST_CHECK(cd3RaycastCapsule(c, Ray(-1, 0, 0, 0, 0, 0), &hit));
	CHECK_VEC(hit.normal, 0.0, 0.0, 0.0, 0.0);
	TEST_CHECK(!cd3RaycastCapsule(c, Ray(-2, 0, 0, 0, 0, 0), &hit));

	/* Zero length: a sphere. */
	cd3Capsule ball = {cd3MakeVec(CD_R(1.0), CD_R(1.0), CD_R(1.0)),
					   cd3MakeVec(CD_R(1.0), CD_R(1.0), CD_R(1.0)), CD_R(2.0)};
	TEST_CHECK(cd3RaycastCapsule(ball, Ray(1, 1, 5, 0, 0, -4), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.normal, 0.0, 0.0, 1.0, EXACT);
	/* Zero radius: the segment itself; a ray crossing it hits with the normal facing back. */
	cd3Capsule line = {cd3MakeVec(CD_R(0.0), CD_R(-1.0), CD_R(0.0)),
					   cd3MakeVec(CD_R(0.0), CD_R(1.0), CD_R(0.0)), CD_R(0.0)};
	TEST_CHECK(cd3RaycastCapsule(line, Ray(-2, CD_R(0.5), 0, 4, 0, 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.normal, -1.0, 0.0, 0.0, EXACT);
	TEST_CHECK(IsFiniteHit(hit));
}

/* A ray from a point on a capsule's side (rounded to cdReal from the exact surface point) towards
 * the axis ends deep inside: a hit at or near fraction 0 at every scale up to 1e9, although the
 * inside test may round the origin to either side (the 1e9 case missed; fuzz_query2). */
static void TestCapsuleRayFromSurfaceInward(void)
{
#define SURFACE_VEC(x, y) cd3MakeVec((cdReal)(x), (cdReal)(y), CD_R(0.0))
	cd3Capsule big = {SURFACE_VEC(-1e9, -1e9), SURFACE_VEC(1e9, 5e8), CD_R(1e9)};
	cd3RayHit hit;
	TEST_CHECK(cd3RaycastCapsule(big, Ray(CD_R(-1e9), CD_R(2.5e8), 0, CD_R(1e9), 0, 0), &hit));
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
		cd3Capsule c = {SURFACE_VEC(ax, ay), SURFACE_VEC(bx, by), (cdReal)radius};
		cd3Ray ray = {SURFACE_VEC(px, py), SURFACE_VEC(footX - px, footY - py)};
		if (!cd3RaycastCapsule(c, ray, &hit) || hit.fraction > CD_R(1e-3))
		{
			++misses;
		}
	}
	TEST_CHECKF(misses == 0, "%d of 20000 rays from the side inward missed or entered late", misses);
#undef SURFACE_VEC
}

static void TestAabbExact(void)
{
	cd3Aabb b = {cd3MakeVec(CD_R(-1.0), CD_R(-2.0), CD_R(-3.0)), cd3MakeVec(CD_R(1.0), CD_R(2.0), CD_R(3.0))};
	cd3RayHit hit;
	/* Each face, straight on: the ray starts 2 outside the face and has length 4. */
	for (int axis = 0; axis < 3; ++axis)
	{
		for (int sign = -1; sign <= 1; sign += 2)
		{
			cdReal o[3] = {CD_R(0.5), CD_R(0.5), CD_R(0.5)};
			cdReal d[3] = {CD_R(0.0), CD_R(0.0), CD_R(0.0)};
			cdReal face = (cdReal)((axis + 1) * sign);
			o[axis] = face + (cdReal)(2 * sign);
			d[axis] = (cdReal)(-4 * sign);
			hit = UntouchedHit();
			TEST_CHECK(cd3RaycastAabb(b, Ray(o[0], o[1], o[2], d[0], d[1], d[2]), &hit));
			TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
			cdReal n[3] = {CD_R(0.0), CD_R(0.0), CD_R(0.0)};
			n[axis] = (cdReal)sign;
			CHECK_VEC(hit.normal, n[0], n[1], n[2], 0.0);
			cdReal p[3] = {CD_R(0.5), CD_R(0.5), CD_R(0.5)};
			p[axis] = face;
			CHECK_VEC(hit.point, p[0], p[1], p[2], EXACT);
		}
	}
	/* Oblique entry through the x = 1 face at (1, 1, 0). */
	TEST_CHECK(cd3RaycastAabb(b, Ray(3, 2, 0, -4, -2, 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.normal, 1.0, 0.0, 0.0, 0.0);
	/* Parallel to a face: outside the slab misses, inside the slab hits, along the face hits. */
	TEST_CHECK(!cd3RaycastAabb(b, Ray(-5, CD_R(2.5), 0, 10, 0, 0), &hit));
	TEST_CHECK(cd3RaycastAabb(b, Ray(-5, CD_R(1.5), 0, 10, 0, 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.4, EXACT);
	CHECK_VEC(hit.normal, -1.0, 0.0, 0.0, 0.0);
	TEST_CHECK(cd3RaycastAabb(b, Ray(-5, 2, 3, 10, 0, 0), &hit)); /* along an edge: touching */
	TEST_CHECK_NEAR(hit.fraction, 0.4, EXACT);
	/* Misses: beside, away, just short. */
	hit = UntouchedHit();
	TEST_CHECK(!cd3RaycastAabb(b, Ray(5, 5, 5, 1, 1, 1), &hit));
	TEST_CHECK(!cd3RaycastAabb(b, Ray(3, 0, 0, 4, 0, 0), &hit));
	TEST_CHECK(!cd3RaycastAabb(b, Ray(3, 0, 0, CD_R(-1.99), 0, 0), &hit));
	TEST_CHECK(!cd3RaycastAabb(b, Ray(3, 0, 0, 0, 0, 0), &hit));
	TEST_CHECK(IsUntouched(hit));
	/* Touching a corner. */
	TEST_CHECK(cd3RaycastAabb(b, Ray(2, 3, 4, -2, -2, -2), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.point, 1.0, 2.0, 3.0, EXACT);
	/* Inside, on the surface, zero-length inside. */
	TEST_CHECK(cd3RaycastAabb(b, Ray(0, 0, 0, 0, 5, 0), &hit));
	TEST_CHECK(hit.fraction == CD_R(0.0));
	CHECK_VEC(hit.normal, 0.0, -1.0, 0.0, 0.0);
	TEST_CHECK(cd3RaycastAabb(b, Ray(1, 0, 0, -5, 0, 0), &hit));
	TEST_CHECK(hit.fraction == CD_R(0.0));
	CHECK_VEC(hit.point, 1.0, 0.0, 0.0, 0.0);
	CHECK_VEC(hit.normal, 1.0, 0.0, 0.0, 0.0);
	TEST_CHECK(cd3RaycastAabb(b, Ray(0, 0, 0, 0, 0, 0), &hit));
	CHECK_VEC(hit.normal, 0.0, 0.0, 0.0, 0.0);
	/* Zero-size box: a point. */
	cd3Aabb point = {cd3MakeVec(CD_R(1.0), CD_R(1.0), CD_R(1.0)),
					 cd3MakeVec(CD_R(1.0), CD_R(1.0), CD_R(1.0))};
	TEST_CHECK(cd3RaycastAabb(point, Ray(-1, 1, 1, 4, 0, 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.normal, -1.0, 0.0, 0.0, 0.0);
	TEST_CHECK(!cd3RaycastAabb(point, Ray(-1, CD_R(1.001), 1, 4, 0, 0), &hit));
	/* A denormal direction component must not produce NaN. */
	cd3Ray tinyComponent = Ray(-5, 0, 0, 10, CD_R(1e-40), 0);
	hit = UntouchedHit();
	TEST_CHECK(cd3RaycastAabb(b, tinyComponent, &hit));
	TEST_CHECK(IsFiniteHit(hit));
	TEST_CHECK_NEAR(hit.fraction, 0.4, EXACT);
}

static cd3Quat QuatAxisAngle(double x, double y, double z, double radians)
{
	double n = sqrt(x * x + y * y + z * z), s = sin(0.5 * radians) / n;
	return cd3MakeQuat((cdReal)(s * x), (cdReal)(s * y), (cdReal)(s * z), (cdReal)cos(0.5 * radians));
}

static void TestBoxExact(void)
{
	/* Half extents (1, 2, 3), rotated 90 degrees about z: local x maps to world y, local y to -x. */
	cd3Box b = {cd3MakeVec(CD_R(10.0), CD_R(0.0), CD_R(0.0)), cd3MakeVec(CD_R(1.0), CD_R(2.0), CD_R(3.0)),
				QuatAxisAngle(0, 0, 1, CD_PI / 2)};
	cd3RayHit hit;
	/* World extents: x in [8, 12], y in [-1, 1], z in [-3, 3]. */
	TEST_CHECK(cd3RaycastBox(b, Ray(4, 0, 0, 8, 0, 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.normal, -1.0, 0.0, 0.0, EXACT);
	CHECK_VEC(hit.point, 8.0, 0.0, 0.0, 1e-5);
	TEST_CHECK(cd3RaycastBox(b, Ray(16, 0, 0, -8, 0, 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.normal, 1.0, 0.0, 0.0, EXACT);
	TEST_CHECK(cd3RaycastBox(b, Ray(10, 3, 0, 0, -4, 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.normal, 0.0, 1.0, 0.0, EXACT);
	TEST_CHECK(cd3RaycastBox(b, Ray(10, -3, 0, 0, 4, 0), &hit));
	CHECK_VEC(hit.normal, 0.0, -1.0, 0.0, EXACT);
	TEST_CHECK(cd3RaycastBox(b, Ray(10, 0, 5, 0, 0, -4), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.normal, 0.0, 0.0, 1.0, EXACT);
	TEST_CHECK(cd3RaycastBox(b, Ray(10, 0, -5, 0, 0, 4), &hit));
	CHECK_VEC(hit.normal, 0.0, 0.0, -1.0, EXACT);
	/* Parallel to a face, outside and inside the slab; short; inside; zero-length. */
	TEST_CHECK(!cd3RaycastBox(b, Ray(4, CD_R(1.5), 0, 16, 0, 0), &hit));
	TEST_CHECK(cd3RaycastBox(b, Ray(4, CD_R(0.5), 0, 16, 0, 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.25, EXACT);
	hit = UntouchedHit();
	TEST_CHECK(!cd3RaycastBox(b, Ray(4, 0, 0, CD_R(3.99), 0, 0), &hit));
	TEST_CHECK(IsUntouched(hit));
	TEST_CHECK(cd3RaycastBox(b, Ray(10, 0, 0, 0, 0, 2), &hit));
	TEST_CHECK(hit.fraction == CD_R(0.0));
	CHECK_VEC(hit.normal, 0.0, 0.0, -1.0, EXACT);
	TEST_CHECK(cd3RaycastBox(b, Ray(11, 0, 0, 0, 0, 0), &hit));
	CHECK_VEC(hit.normal, 0.0, 0.0, 0.0, 0.0);
	TEST_CHECK(!cd3RaycastBox(b, Ray(13, 0, 0, 0, 0, 0), &hit));
	/* A rotation a little off unit length (within the validator's tolerance) still gives unit normals. */
	cd3Box loose = b;
	double grow = CD_DOUBLE ? 1.0 + 2e-10 : 1.0 + 2e-5;
	loose.rotation = cd3MakeQuat((cdReal)(grow * b.rotation.x), (cdReal)(grow * b.rotation.y),
								 (cdReal)(grow * b.rotation.z), (cdReal)(grow * b.rotation.w));
	TEST_CHECK(cd3IsValidQuat(loose.rotation));
	TEST_CHECK(cd3RaycastBox(loose, Ray(10, 3, 0, 0, -4, 0), &hit));
	TEST_CHECK_NEAR(cd3Length(hit.normal), 1.0, 1e-6);
	/* Zero-size box: a point at its center. */
	cd3Box point = {cd3MakeVec(CD_R(1.0), CD_R(0.0), CD_R(0.0)), CD3_VEC_ZERO, CD3_QUAT_IDENTITY};
	TEST_CHECK(cd3RaycastBox(point, Ray(-1, 0, 0, 4, 0, 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.normal, -1.0, 0.0, 0.0, 0.0);
}

static void TestTriangleExact(void)
{
	/* In the z = 0 plane, counter-clockwise from +z: face normal +z. */
	cd3Triangle t = {cd3MakeVec(CD_R(0.0), CD_R(0.0), CD_R(0.0)), cd3MakeVec(CD_R(4.0), CD_R(0.0), CD_R(0.0)),
					 cd3MakeVec(CD_R(0.0), CD_R(4.0), CD_R(0.0))};
	cd3RayHit hit;
	/* Front and back: the normal faces the ray origin. */
	TEST_CHECK(cd3RaycastTriangle(t, Ray(1, 1, 2, 0, 0, -4), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.point, 1.0, 1.0, 0.0, EXACT);
	CHECK_VEC(hit.normal, 0.0, 0.0, 1.0, EXACT);
	TEST_CHECK(cd3RaycastTriangle(t, Ray(1, 1, -2, 0, 0, 4), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.normal, 0.0, 0.0, -1.0, EXACT);
	/* Oblique. */
	TEST_CHECK(cd3RaycastTriangle(t, Ray(0, 0, 3, 3, 3, -6), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.point, 1.5, 1.5, 0.0, EXACT);
	/* On an edge and a vertex (closed). */
	TEST_CHECK(cd3RaycastTriangle(t, Ray(2, 2, 1, 0, 0, -2), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	TEST_CHECK(cd3RaycastTriangle(t, Ray(4, 0, 1, 0, 0, -2), &hit));
	/* Misses: outside each edge, short, away, parallel above, in the plane, zero-length. */
	hit = UntouchedHit();
	TEST_CHECK(!cd3RaycastTriangle(t, Ray(CD_R(2.1), CD_R(2.1), 1, 0, 0, -2), &hit));
	TEST_CHECK(!cd3RaycastTriangle(t, Ray(-CD_R(0.1), 1, 1, 0, 0, -2), &hit));
	TEST_CHECK(!cd3RaycastTriangle(t, Ray(1, -CD_R(0.1), 1, 0, 0, -2), &hit));
	TEST_CHECK(!cd3RaycastTriangle(t, Ray(1, 1, 1, 0, 0, CD_R(-0.99)), &hit));
	TEST_CHECK(!cd3RaycastTriangle(t, Ray(1, 1, 1, 0, 0, 2), &hit));
	TEST_CHECK(!cd3RaycastTriangle(t, Ray(-5, 1, 1, 10, 0, 0), &hit));
	TEST_CHECK(!cd3RaycastTriangle(t, Ray(-5, 1, 0, 10, 0, 0), &hit));
	TEST_CHECK(!cd3RaycastTriangle(t, Ray(1, 1, 0, 0, 0, 0), &hit));
	TEST_CHECK(IsUntouched(hit));
	/* Starting on the triangle: fraction 0, normal against the translation. */
	TEST_CHECK(cd3RaycastTriangle(t, Ray(1, 1, 0, 0, 0, 3), &hit));
	TEST_CHECK(hit.fraction == CD_R(0.0));
	CHECK_VEC(hit.normal, 0.0, 0.0, -1.0, EXACT);
	/* Ending exactly on it. */
	TEST_CHECK(cd3RaycastTriangle(t, Ray(1, 1, 2, 0, 0, -2), &hit));
	TEST_CHECK_NEAR(hit.fraction, 1.0, EXACT);
	/* Degenerate (collinear, coincident): no hit and no NaN. */
	cd3Triangle line = {cd3MakeVec(CD_R(0.0), CD_R(0.0), CD_R(0.0)),
						cd3MakeVec(CD_R(1.0), CD_R(0.0), CD_R(0.0)),
						cd3MakeVec(CD_R(2.0), CD_R(0.0), CD_R(0.0))};
	cd3Triangle dot = {CD3_VEC_ZERO, CD3_VEC_ZERO, CD3_VEC_ZERO};
	hit = UntouchedHit();
	TEST_CHECK(!cd3RaycastTriangle(line, Ray(1, 0, 1, 0, 0, -2), &hit));
	TEST_CHECK(!cd3RaycastTriangle(line, Ray(-1, 0, 0, 4, 0, 0), &hit));
	TEST_CHECK(!cd3RaycastTriangle(dot, Ray(0, 0, 1, 0, 0, -2), &hit));
	TEST_CHECK(IsUntouched(hit));
}

static void TestPlaneExact(void)
{
	/* y <= 2. */
	cd3Plane p = {cd3MakeVec(CD_R(0.0), CD_R(1.0), CD_R(0.0)), CD_R(2.0)};
	cd3RayHit hit;
	TEST_CHECK(cd3RaycastPlane(p, Ray(1, 6, 1, 0, -8, 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.point, 1.0, 2.0, 1.0, EXACT);
	CHECK_VEC(hit.normal, 0.0, 1.0, 0.0, 0.0);
	TEST_CHECK(cd3RaycastPlane(p, Ray(0, 4, 0, 4, -4, 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	hit = UntouchedHit();
	TEST_CHECK(!cd3RaycastPlane(p, Ray(1, 6, 1, 0, 8, 0), &hit));		   /* away */
	TEST_CHECK(!cd3RaycastPlane(p, Ray(1, 6, 1, 5, 0, 0), &hit));		   /* parallel above */
	TEST_CHECK(!cd3RaycastPlane(p, Ray(1, 6, 1, 0, CD_R(-3.9), 0), &hit)); /* short */
	TEST_CHECK(!cd3RaycastPlane(p, Ray(1, 6, 1, 0, 0, 0), &hit));		   /* zero-length outside */
	TEST_CHECK(IsUntouched(hit));
	TEST_CHECK(cd3RaycastPlane(p, Ray(1, 0, 1, 5, 0, 0), &hit)); /* inside, parallel */
	TEST_CHECK(hit.fraction == CD_R(0.0));
	CHECK_VEC(hit.normal, -1.0, 0.0, 0.0, 0.0);
	TEST_CHECK(cd3RaycastPlane(p, Ray(1, 2, 1, 0, 3, 0), &hit)); /* on the surface, moving out */
	TEST_CHECK(hit.fraction == CD_R(0.0));
	CHECK_VEC(hit.normal, 0.0, -1.0, 0.0, 0.0);
	TEST_CHECK(cd3RaycastPlane(p, Ray(1, 0, 1, 0, 0, 0), &hit));
	CHECK_VEC(hit.normal, 0.0, 0.0, 0.0, 0.0);
}

static cd3Shape SegmentShape(cd3Vec p1, cd3Vec p2)
{
	cd3Shape s;
	s.type = CD3_SHAPE_SEGMENT;
	s.segment.p1 = p1;
	s.segment.p2 = p2;
	return s;
}

static void TestSegmentExact(void)
{
	cd3Shape s = SegmentShape(cd3MakeVec(CD_R(0.0), CD_R(-1.0), CD_R(0.0)),
							  cd3MakeVec(CD_R(0.0), CD_R(3.0), CD_R(0.0)));
	cd3RayHit hit;
	/* Crossing: normal perpendicular to the segment, facing the origin. */
	TEST_CHECK(cd3Raycast(&s, Ray(-2, 1, 0, 4, 0, 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.point, 0.0, 1.0, 0.0, EXACT);
	CHECK_VEC(hit.normal, -1.0, 0.0, 0.0, EXACT);
	/* Oblique crossing from above-left: normal is still perpendicular to the segment. */
	TEST_CHECK(cd3Raycast(&s, Ray(-2, 3, 0, 4, -2, 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.normal, -1.0, 0.0, 0.0, EXACT);
	TEST_CHECK(cd3Raycast(&s, Ray(0, 1, 2, 0, 0, -4), &hit));
	CHECK_VEC(hit.normal, 0.0, 0.0, 1.0, EXACT);
	/* Through an end point. */
	TEST_CHECK(cd3Raycast(&s, Ray(-2, 3, 0, 4, 0, 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	/* Misses: passing beside (out of plane, beyond the end), short, zero-length on the segment. */
	hit = UntouchedHit();
	TEST_CHECK(!cd3Raycast(&s, Ray(-2, 1, CD_R(0.001), 4, 0, 0), &hit));
	TEST_CHECK(!cd3Raycast(&s, Ray(-2, CD_R(3.001), 0, 4, 0, 0), &hit));
	TEST_CHECK(!cd3Raycast(&s, Ray(-2, 1, 0, CD_R(1.99), 0, 0), &hit));
	TEST_CHECK(!cd3Raycast(&s, Ray(0, 1, 0, 0, 0, 0), &hit));
	TEST_CHECK(IsUntouched(hit));
	/* Along the segment: first shared point, normal -normalize(translation). */
	TEST_CHECK(cd3Raycast(&s, Ray(0, -5, 0, 0, 8, 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.point, 0.0, -1.0, 0.0, EXACT);
	CHECK_VEC(hit.normal, 0.0, -1.0, 0.0, EXACT);
	TEST_CHECK(cd3Raycast(&s, Ray(0, 7, 0, 0, -8, 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.normal, 0.0, 1.0, 0.0, EXACT);
	/* Starting on it and leaving sideways: fraction 0, normal against the translation. */
	TEST_CHECK(cd3Raycast(&s, Ray(0, 1, 0, 3, 0, 0), &hit));
	TEST_CHECK(hit.fraction == CD_R(0.0));
	CHECK_VEC(hit.normal, -1.0, 0.0, 0.0, EXACT);
	/* Parallel but apart. */
	TEST_CHECK(!cd3Raycast(&s, Ray(CD_R(0.01), -5, 0, 0, 10, 0), &hit));
	/* Zero-length segment: a point. */
	cd3Shape point = SegmentShape(cd3MakeVec(CD_R(1.0), CD_R(1.0), CD_R(1.0)),
								  cd3MakeVec(CD_R(1.0), CD_R(1.0), CD_R(1.0)));
	TEST_CHECK(cd3Raycast(&point, Ray(1, 1, -1, 0, 0, 4), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	CHECK_VEC(hit.normal, 0.0, 0.0, -1.0, EXACT);
	TEST_CHECK(!cd3Raycast(&point, Ray(1, CD_R(1.001), -1, 0, 0, 4), &hit));
}

static void TestDispatcher(void)
{
	/* The dispatcher gives the same answers as the functions it dispatches to. */
	TestRng rng = TestRngMake(7);
	cd3ShapeType types[] = {CD3_SHAPE_SPHERE, CD3_SHAPE_CAPSULE, CD3_SHAPE_AABB, CD3_SHAPE_BOX,
							CD3_SHAPE_PLANE};
	for (int i = 0; i < 500; ++i)
	{
		cd3Shape s = RandomSolid(&rng, types[i % 5]);
		cd3Ray ray = RandomRay(&rng);
		cd3RayHit a = UntouchedHit(), b = UntouchedHit();
		bool hitA = cd3Raycast(&s, ray, &a), hitB = false;
		switch (s.type)
		{
			case CD3_SHAPE_SPHERE:
				hitB = cd3RaycastSphere(s.sphere, ray, &b);
				break;
			case CD3_SHAPE_CAPSULE:
				hitB = cd3RaycastCapsule(s.capsule, ray, &b);
				break;
			case CD3_SHAPE_AABB:
				hitB = cd3RaycastAabb(s.aabb, ray, &b);
				break;
			case CD3_SHAPE_BOX:
				hitB = cd3RaycastBox(s.box, ray, &b);
				break;
			default:
				hitB = cd3RaycastPlane(s.plane, ray, &b);
				break;
		}
		TEST_CHECKF(hitA == hitB && a.fraction == b.fraction && cd3VecEqual(a.normal, b.normal),
					"case %d (%s)", i, cd3GetShapeTypeName(s.type));
	}
	cd3Triangle t = {CD3_VEC_ZERO, cd3MakeVec(CD_R(1.0), CD_R(0.0), CD_R(0.0)),
					 cd3MakeVec(CD_R(0.0), CD_R(1.0), CD_R(0.0))};
	cd3Shape ts;
	ts.type = CD3_SHAPE_TRIANGLE;
	ts.triangle = t;
	cd3RayHit hit;
	TEST_CHECK(cd3Raycast(&ts, Ray(CD_R(0.25), CD_R(0.25), 1, 0, 0, -2), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, EXACT);
	cd3Shape bad;
	bad.type = CD3_SHAPE_TYPE_COUNT;
	bad.sphere.center = CD3_VEC_ZERO;
	bad.sphere.radius = CD_R(1.0);
	hit = UntouchedHit();
	TEST_CHECK(!cd3Raycast(&bad, Ray(0, 0, 0, 1, 0, 0), &hit));
	TEST_CHECK(IsUntouched(hit));
}

/* ---- property tests ----------------------------------------------------------------------------- */

static void TestSolidsAgainstReference(void)
{
	TestRng rng = TestRngMake(0x5eed3001);
	cd3ShapeType types[] = {CD3_SHAPE_SPHERE, CD3_SHAPE_CAPSULE, CD3_SHAPE_AABB, CD3_SHAPE_BOX,
							CD3_SHAPE_PLANE};
	for (int i = 0; i < 10000; ++i)
	{
		cd3Shape s = RandomSolid(&rng, types[i % 5]);
		cd3Ray ray = RandomRay(&rng);
		CheckSolidCast(&s, ray, 10.0, i);
	}
}

/* Rays aimed at random points just inside or outside the surface (via the support point), so that
 * grazing and near-tangent rays are common. */
static void TestSolidsNearTangent(void)
{
	TestRng rng = TestRngMake(0x5eed3002);
	cd3ShapeType types[] = {CD3_SHAPE_SPHERE, CD3_SHAPE_CAPSULE, CD3_SHAPE_AABB, CD3_SHAPE_BOX};
	for (int i = 0; i < 4000; ++i)
	{
		cd3Shape s = RandomSolid(&rng, types[i % 4]);
		cd3Ray ray = RandomRay(&rng);
		/* Pick a direction perpendicular-ish to the line of sight and aim at the silhouette. */
		DVec o = D(ray.origin);
		DVec n = D(RandomUnit(&rng));
		DVec toward = DNormalize(DSub(D(RandomVec(&rng, 0.1)), o));
		n = DNormalize(DSub(n, DScale(DDot(n, toward), toward)));
		if (DLength(n) == 0.0)
		{
			continue;
		}
		/* The support point along n, found by the shape's support function numerically. */
		double support = RefSupport(&s, n);
		double offset = TestRngRange(&rng, -0.05, 0.05);
		DVec target = DAdd(DScale(support + offset - DDot(n, o), n), o);
		target = DAdd(target, DScale(DDot(DSub(D(RandomVec(&rng, 3.0)), target), toward), toward));
		ray.translation = V(DScale(TestRngRange(&rng, 1.0, 3.0), DSub(target, o)));
		CheckSolidCast(&s, ray, 10.0, i);
	}
}

static cd3Shape TransformShape(const cd3Shape* s, cd3Transform xf)
{
	cd3Shape t = *s;
	switch (s->type)
	{
		case CD3_SHAPE_SPHERE:
			t.sphere.center = cd3TransformPoint(xf, s->sphere.center);
			break;
		case CD3_SHAPE_CAPSULE:
			t.capsule.p1 = cd3TransformPoint(xf, s->capsule.p1);
			t.capsule.p2 = cd3TransformPoint(xf, s->capsule.p2);
			break;
		case CD3_SHAPE_AABB: /* translation only */
			t.aabb.min = cd3Add(s->aabb.min, xf.p);
			t.aabb.max = cd3Add(s->aabb.max, xf.p);
			break;
		case CD3_SHAPE_BOX:
			t.box.center = cd3TransformPoint(xf, s->box.center);
			t.box.rotation = cd3NormalizeQuat(cd3MulQuat(xf.q, s->box.rotation));
			break;
		case CD3_SHAPE_TRIANGLE:
			t.triangle.a = cd3TransformPoint(xf, s->triangle.a);
			t.triangle.b = cd3TransformPoint(xf, s->triangle.b);
			t.triangle.c = cd3TransformPoint(xf, s->triangle.c);
			break;
		case CD3_SHAPE_PLANE:
			t.plane.normal = cd3RotateVector(xf.q, s->plane.normal);
			t.plane.offset = s->plane.offset + cd3Dot(t.plane.normal, xf.p);
			break;
		case CD3_SHAPE_SEGMENT:
			t.segment.p1 = cd3TransformPoint(xf, s->segment.p1);
			t.segment.p2 = cd3TransformPoint(xf, s->segment.p2);
			break;
		default:
			break;
	}
	return t;
}

static cd3Shape RandomTriangleShape(TestRng* rng)
{
	cd3Shape s;
	s.type = CD3_SHAPE_TRIANGLE;
	s.triangle.a = RandomVec(rng, 4.0);
	s.triangle.b = RandomVec(rng, 4.0);
	s.triangle.c = RandomVec(rng, 4.0);
	return s;
}

static void TestRigidTransformInvariance(void)
{
	TestRng rng = TestRngMake(0x5eed3003);
	cd3ShapeType types[] = {CD3_SHAPE_SPHERE, CD3_SHAPE_CAPSULE, CD3_SHAPE_AABB,
							CD3_SHAPE_BOX,	  CD3_SHAPE_PLANE,	 CD3_SHAPE_TRIANGLE};
	for (int i = 0; i < 6000; ++i)
	{
		cd3ShapeType type = types[i % 6];
		cd3Shape s = type == CD3_SHAPE_TRIANGLE ? RandomTriangleShape(&rng) : RandomSolid(&rng, type);
		cd3Ray ray = RandomRay(&rng);
		cd3Transform xf = {RandomVec(&rng, 20.0),
						   type == CD3_SHAPE_AABB ? CD3_QUAT_IDENTITY : RandomQuat(&rng)};
		cd3Shape moved = TransformShape(&s, xf);
		cd3Ray movedRay = {cd3TransformPoint(xf, ray.origin), cd3RotateVector(xf.q, ray.translation)};

		/* Compare only where the answer is robust: the reference must be clear in both frames. */
		bool clear;
		if (type == CD3_SHAPE_TRIANGLE)
		{
			/* Clear when the ray is not nearly in the plane and does not pass near an edge or end
			 * near the plane. */
			DVec a = D(s.triangle.a), b = D(s.triangle.b), c = D(s.triangle.c);
			DVec n = DNormalize(DCross(DSub(b, a), DSub(c, a)));
			DVec o = D(ray.origin), d = D(ray.translation);
			double h0 = DDot(n, DSub(o, a)), h1 = DDot(n, DSub(DAdd(o, d), a));
			clear = fabs(h0) > BAND * 10 && fabs(h1) > BAND * 10;
			if (clear && h0 * h1 < 0.0)
			{
				DVec p = DAdd(o, DScale(h0 / (h0 - h1), d));
				DVec corners[3] = {a, b, c};
				for (int e = 0; e < 3; ++e)
				{
					clear = clear && RefDistanceToSegment(p, corners[e], corners[(e + 1) % 3]) > BAND * 10;
				}
			}
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
		cd3RayHit hit = UntouchedHit(), movedHit = UntouchedHit();
		bool got = cd3Raycast(&s, ray, &hit);
		bool movedGot = cd3Raycast(&moved, movedRay, &movedHit);
		TEST_CHECKF(got == movedGot, "%s case %d: %d vs %d after a rigid transform",
					cd3GetShapeTypeName(type), i, got, movedGot);
		if (got && movedGot)
		{
			double length = DLength(D(ray.translation));
			TEST_CHECKF(fabs((double)hit.fraction - (double)movedHit.fraction) * length <= 10 * TOL * 10,
						"%s case %d: fraction %.9g vs %.9g", cd3GetShapeTypeName(type), i,
						(double)hit.fraction, (double)movedHit.fraction);
			DVec rotated = DRotate(xf.q, D(hit.normal));
			TEST_CHECKF(DLength(DSub(rotated, D(movedHit.normal))) <= 10 * TOL, "%s case %d: normal",
						cd3GetShapeTypeName(type), i);
		}
	}
}

/* Triangles against a Cramer's-rule reference in double. */
static void TestTrianglesAgainstReference(void)
{
	TestRng rng = TestRngMake(0x5eed3004);
	int hits = 0;
	for (int i = 0; i < 10000; ++i)
	{
		cd3Shape s = RandomTriangleShape(&rng);
		cd3Ray ray = RandomRay(&rng);
		DVec a = D(s.triangle.a), b = D(s.triangle.b), c = D(s.triangle.c);
		if (i % 2 == 0)
		{
			/* Aim at a point of the triangle's plane near the triangle, so that half the rays hit. */
			double aimU = TestRngRange(&rng, -0.2, 1.0), aimV = TestRngRange(&rng, -0.2, 1.0 - aimU);
			DVec aim = DAdd(a, DAdd(DScale(aimU, DSub(b, a)), DScale(aimV, DSub(c, a))));
			ray.translation = V(DScale(TestRngRange(&rng, 0.5, 2.0), DSub(aim, D(ray.origin))));
		}
		DVec o = D(ray.origin), d = D(ray.translation);
		DVec e1 = DSub(b, a), e2 = DSub(c, a), r = DSub(o, a);
		DVec faceNormal = DCross(e1, e2);
		/* o + t d = a + u e1 + v e2  <=>  -t d + u e1 + v e2 = r. */
		double det = DDot(DScale(-1.0, d), faceNormal);
		double area = DLength(faceNormal);
		cd3RayHit hit = UntouchedHit();
		bool got = cd3Raycast(&s, ray, &hit);
		if (!got)
		{
			TEST_CHECKF(IsUntouched(hit), "case %d: miss changed *hit", i);
		}
		if (fabs(det) <= 1e-3 * area * DLength(d) || area < 1e-2)
		{
			continue; /* nearly in the plane, or a sliver */
		}
		double t = DDot(r, faceNormal) / det;
		double u = DDot(DScale(-1.0, d), DCross(r, e2)) / det;
		double v = DDot(DScale(-1.0, d), DCross(e1, r)) / det;
		double margin = BAND;
		bool clear = fabs(t) > margin && fabs(t - 1) > margin && fabs(u) > margin && fabs(v) > margin &&
					 fabs(1 - u - v) > margin;
		bool expected = t >= 0 && t <= 1 && u >= 0 && v >= 0 && u + v <= 1;
		if (clear)
		{
			TEST_CHECKF(got == expected, "case %d: got %d, expected %d (t %g u %g v %g)", i, got, expected, t,
						u, v);
		}
		if (!got)
		{
			continue;
		}
		++hits;
		DVec n = DScale(1.0 / area, faceNormal);
		DVec normal = D(hit.normal), point = D(hit.point);
		TEST_CHECKF(IsFiniteHit(hit) && hit.fraction >= CD_R(0.0) && hit.fraction <= CD_R(1.0), "case %d", i);
		TEST_CHECKF(fabs(fabs(DDot(normal, n)) - 1.0) <= 1e-5, "case %d: normal is not the face normal", i);
		TEST_CHECKF(DDot(normal, d) < 0.0, "case %d: normal does not face the origin", i);
		TEST_CHECKF(fabs(DDot(n, DSub(point, a))) <= TOL * 10, "case %d: point off the plane by %g", i,
					DDot(n, DSub(point, a)));
		if (clear)
		{
			TEST_CHECKF(fabs((double)hit.fraction - t) * DLength(d) <= TOL * 100,
						"case %d: fraction %.9g vs %.9g", i, (double)hit.fraction, t);
		}
	}
	TEST_CHECKF(hits > 1000, "only %d hits: the random rays do not exercise the hit path", hits);
}

/* Distance in double from p to the triangle: the nearest of the three edges and, when p projects
 * inside, the face (barycentric signs), independent of the library. */
static double RefDistanceToTriangle(DVec p, DVec a, DVec b, DVec c)
{
	double best = RefDistanceToSegment(p, a, b);
	best = fmin(best, RefDistanceToSegment(p, b, c));
	best = fmin(best, RefDistanceToSegment(p, c, a));
	DVec n = DCross(DSub(b, a), DSub(c, a));
	double nn = DDot(n, n);
	if (nn > 0.0)
	{
		double u = DDot(n, DCross(DSub(b, p), DSub(c, p))), v = DDot(n, DCross(DSub(c, p), DSub(a, p))),
			   w = DDot(n, DCross(DSub(a, p), DSub(b, p)));
		if (u >= 0.0 && v >= 0.0 && w >= 0.0)
		{
			best = fmin(best, fabs(DDot(n, DSub(p, a))) / sqrt(nn));
		}
	}
	return best;
}

/* A triangle hit's point lies on the triangle: within `tolerance` of it. */
static bool HitOnTriangle(cd3Triangle t, cd3RayHit hit, double tolerance)
{
	return RefDistanceToTriangle(D(hit.point), D(t.a), D(t.b), D(t.c)) <= tolerance;
}

/* The fuzzer's triangle rays (fuzz_query3): the inside test and the plane fraction were computed
 * apart, so a ray could "pass inside" and still get a point far from the triangle. */
static void TestTriangleRobustness(void)
{
	/* From vertex c, nearly parallel to the plane (which it crosses only at c): fraction 0 at c.
	 * The float computation gave fraction 0.0909, a point 2e-4 off a triangle of size 1.25e-3. */
	cdReal k = CD_R(0.00124999997);
	cd3Triangle grazed = {cd3MakeVec(0, 0, CD_R(-1e-9)), cd3MakeVec(CD_R(-1e-9), -k, -k),
						  cd3MakeVec(-k, -k, -k)};
	cd3RayHit hit = UntouchedHit();
	bool got = cd3RaycastTriangle(grazed, Ray(-k, -k, -k, -k, -k, -k), &hit);
	TEST_CHECKF(got && hit.fraction <= CD_R(1e-6) && DLength(DSub(D(hit.point), D(grazed.c))) <= 1e-9,
				"grazing ray from vertex c: hit %d, fraction %.9g, point %.9g from c", (int)got,
				(double)hit.fraction, DLength(DSub(D(hit.point), D(grazed.c))));

	/* From 1e9 away, starting in the plane y = 0 of a triangle of size 10 at the origin and
	 * leaving it: a miss (it reported a hit 1e9 away). Then rays from 1e9 away that do cross it. */
	cd3Triangle small = {cd3MakeVec(CD_R(-7.625), 0, 0), cd3MakeVec(CD_R(2.25), 0, CD_R(1e-9)),
						 cd3MakeVec(0, 0, 0)};
	hit = UntouchedHit();
	TEST_CHECK(!cd3RaycastTriangle(
		small, Ray(CD_R(1e9), 0, CD_R(-12.5), CD_R(-12.5), CD_R(-12.5), CD_R(-12.5)), &hit));
	TEST_CHECK(IsUntouched(hit));
	cd3Triangle wide = {cd3MakeVec(-10, 0, -10), cd3MakeVec(10, 0, -10), cd3MakeVec(0, 0, 10)};
	TEST_CHECK(cd3RaycastTriangle(wide, Ray(1, CD_R(1e9), 1, 0, CD_R(-2e9), 0), &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.5, 1e-6);
	TEST_CHECKF(HitOnTriangle(wide, hit, 16.0 * (double)CD_REAL_EPSILON * 1e9), "point (%g %g %g)",
				(double)hit.point.x, (double)hit.point.y, (double)hit.point.z);
	TEST_CHECK(!cd3RaycastTriangle(wide, Ray(1, CD_R(1e9), 2000, 0, CD_R(-2e9), 0), &hit));

	/* Lying in the plane (through a and c, along the line of the origin, a and c), from c: a miss
	 * (docs/API.md), or at most a hit at c. It reported the ray's end, 21.65 away. */
	cd3Triangle flat = {cd3MakeVec(-1, -1, -1), cd3MakeVec(0, CD_R(-10.25), CD_R(-12.5)),
						cd3MakeVec(CD_R(-12.5), CD_R(-12.5), CD_R(-12.5))};
	hit = UntouchedHit();
	got = cd3RaycastTriangle(
		flat, Ray(CD_R(-12.5), CD_R(-12.5), CD_R(-12.5), CD_R(-12.5), CD_R(-12.5), CD_R(-12.5)), &hit);
	TEST_CHECKF(!got || (hit.fraction <= CD_R(1e-6) && HitOnTriangle(flat, hit, 1e-5)),
				"in-plane ray: fraction %.9g, point %.3g off", (double)hit.fraction,
				RefDistanceToTriangle(D(hit.point), D(flat.a), D(flat.b), D(flat.c)));

	/* Along the axis of a needle, 0.5 beside it, passing its far tip (double build, fuzz_query3):
	 * near the axis every point is close to the lines of both long edges, and a hit 16 lengths
	 * past the tip passed the edge-line test. */
	cd3Triangle needle = {cd3MakeVec(CD_R(0.5), CD_R(0.25), 0), cd3MakeVec(0, 7, CD_R(6.375)),
						  cd3MakeVec(CD_R(1.68523752e22), CD_R(0.5), CD_R(0.25))};
	cd3Ray alongNeedle = Ray(0, 0, 0, CD_R(5e29), 0, 0);
	if (CD_DOUBLE)
	{
		hit = UntouchedHit();
		got = cd3RaycastTriangle(needle, alongNeedle, &hit);
		double off = RefDistanceToTriangle(D(hit.point), D(needle.a), D(needle.b), D(needle.c));
		TEST_CHECKF(!got || off <= 64.0 * (double)CD_REAL_EPSILON * 5e29,
					"along a needle: the hit is %.3g off", off);
	}

	/* Random: triangles of size 1e-3..10 near the origin; rays from up to the end of the range
	 * aimed at them, and rays from a point of the triangle at a grazing angle (1e-7..1e-2 rad off
	 * the plane). Every hit lies on the triangle within a few epsilon of the coordinates, and the
	 * rays aimed well inside hit. */
	TestRng rng = TestRngMake(0x5eed3009);
	double range = CD_DOUBLE ? 1e30 : 1e9;
	int hits = 0;
	for (int i = 0; i < 4000; ++i)
	{
		double size = pow(10.0, TestRngRange(&rng, -3.0, 1.0));
		cd3Triangle t = {RandomVec(&rng, size), RandomVec(&rng, size), RandomVec(&rng, size)};
		DVec a = D(t.a), b = D(t.b), c = D(t.c);
		DVec n = DCross(DSub(b, a), DSub(c, a));
		if (DLength(n) < 1e-2 * DDot(DSub(b, a), DSub(b, a)) ||
			DLength(n) < 1e-2 * DDot(DSub(c, a), DSub(c, a)))
		{
			continue; /* slivers: their own tests */
		}
		double u = TestRngRange(&rng, 0.0, 1.0), v = TestRngRange(&rng, 0.0, 1.0 - u);
		DVec on = DAdd(a, DAdd(DScale(u, DSub(b, a)), DScale(v, DSub(c, a))));
		bool inner = u > 0.05 && v > 0.05 && u + v < 0.95;
		cd3Ray ray;
		double magnitude;
		if (i % 2 == 0)
		{
			double distance = range * pow(10.0, TestRngRange(&rng, -6.0, 0.0));
			DVec from = DAdd(on, DScale(distance, D(RandomUnit(&rng))));
			ray.origin = V(from);
			ray.translation = V(DScale(TestRngRange(&rng, 1.0, 2.0), DSub(on, D(ray.origin))));
			magnitude = distance * 2.0;
			/* Only where double precision (the library's and this check's) resolves the triangle
			 * from that far. */
			inner = inner && 1e4 * DBL_EPSILON * distance < size;
		}
		else
		{
			DVec unitNormal = DScale(1.0 / DLength(n), n);
			DVec along = DNormalize(DCross(unitNormal, D(RandomUnit(&rng))));
			double tilt = pow(10.0, TestRngRange(&rng, -7.0, -2.0)) * (TestRngInt(&rng, 2) == 0 ? -1.0 : 1.0);
			ray.origin = V(on);
			ray.translation = V(DScale(size, DAdd(along, DScale(tilt, unitNormal))));
			magnitude = 4.0 * size;
			inner = false;
		}
		if (inner)
		{
			/* The rounded ray need not aim at `on` any more: where does it cross the plane? */
			DVec o = D(ray.origin), d = D(ray.translation);
			double speed = DDot(n, d);
			double fraction = speed != 0.0 ? DDot(n, DSub(a, o)) / speed : -1.0;
			DVec x = DAdd(o, DScale(fraction, d));
			double nn = DDot(n, n);
			double wa = DDot(n, DCross(DSub(b, x), DSub(c, x))) / nn,
				   wb = DDot(n, DCross(DSub(c, x), DSub(a, x))) / nn;
			inner = fraction > 0.01 && fraction < 0.99 && wa > 0.01 && wb > 0.01 && 1.0 - wa - wb > 0.01;
		}
		hit = UntouchedHit();
		got = cd3RaycastTriangle(t, ray, &hit);
		double tolerance = 64.0 * (double)CD_REAL_EPSILON * magnitude;
		hits += got ? 1 : 0;
		TEST_CHECKF(!got || HitOnTriangle(t, hit, tolerance),
					"case %d: the hit point is %.3g off the triangle (tolerance %.3g)", i,
					RefDistanceToTriangle(D(hit.point), a, b, c), tolerance);
		TEST_CHECKF(!inner || got, "case %d: a ray aimed inside the triangle from %.3g away misses", i,
					DLength(DSub(D(ray.origin), on)));
	}
	TEST_CHECKF(hits > 1000, "only %d hits", hits);
}

/* A zero-radius capsule at the 1e9 scale (fuzz_query3): the side entry's perpendicular parts are
 * all round-off there, and a ray starting 1e-9 from its end reported a hit 2.4e8 from it. Every
 * hit must lie on the capsule within the segment cast's tolerance (64 epsilon of the
 * coordinates); then random thin capsules far out, with rays from near their ends. */
static void TestThinCapsulesFarOut(void)
{
	cd3Capsule c = {cd3MakeVec(CD_R(-5e8), CD_R(-1e9), CD_R(-1e9)),
					cd3MakeVec(CD_R(-9.99999972e-10), CD_R(-1e9), 0), CD_R(0.0)};
	TestRng rng = TestRngMake(0x5eed300a);
	for (int i = 0; i <= 4000; ++i)
	{
		cd3Ray ray = Ray(0, CD_R(-1e9), 0, CD_R(-1e9), 0, CD_R(-1e9));
		double scale = CD_DOUBLE ? 1e30 : 1e9;
		if (i > 0)
		{
			c.p1 = RandomVec(&rng, scale);
			c.p2 = RandomVec(&rng, scale);
			c.radius = TestRngInt(&rng, 2) == 0
						   ? CD_R(0.0)
						   : (cdReal)(scale * pow(10.0, TestRngRange(&rng, -12.0, -6.0)));
			DVec end = D(TestRngInt(&rng, 2) == 0 ? c.p1 : c.p2);
			ray.origin =
				V(DAdd(end, DScale(scale * 1e-6 * TestRngRange(&rng, 0.0, 1.0), D(RandomUnit(&rng)))));
			ray.translation = V(DScale(scale, D(RandomUnit(&rng))));
		}
		cd3RayHit hit = UntouchedHit();
		if (!cd3RaycastCapsule(c, ray, &hit))
		{
			continue;
		}
		double magnitude =
			fmax(fmax(DLength(D(c.p1)), DLength(D(c.p2))),
				 fmax(DLength(D(ray.origin)), DLength(DAdd(D(ray.origin), D(ray.translation)))));
		double off = fabs(RefDistanceToSegment(D(hit.point), D(c.p1), D(c.p2)) - (double)c.radius);
		/* From inside (within double round-off: the fuzzer's origin is 1e-9 from the end), only
		 * fraction 0 at the origin; otherwise a point of the surface. */
		bool inside = RefDistanceToSegment(D(ray.origin), D(c.p1), D(c.p2)) <= (double)c.radius;
		TEST_CHECKF((inside && hit.fraction == CD_R(0.0)) ||
						off <= 128.0 * (double)CD_REAL_EPSILON * magnitude,
					"case %d: fraction %.9g, the hit point is %.3g off the capsule's surface (radius %g)", i,
					(double)hit.fraction, off, (double)c.radius);
	}
}

/* Segments: rays aimed at a random point of the segment hit there; rays aimed beside it miss. */
static void TestSegmentsAimed(void)
{
	TestRng rng = TestRngMake(0x5eed3005);
	for (int i = 0; i < 5000; ++i)
	{
		cd3Shape s = SegmentShape(RandomVec(&rng, 4.0), RandomVec(&rng, 4.0));
		cd3Vec origin = RandomVec(&rng, 10.0);
		double along = TestRngRange(&rng, 0.0, 1.0);
		DVec p1 = D(s.segment.p1), p2 = D(s.segment.p2);
		DVec target = DAdd(p1, DScale(along, DSub(p2, p1)));
		double reach = TestRngRange(&rng, 1.2, 3.0);
		cd3Ray ray = {origin, V(DScale(reach, DSub(target, D(origin))))};
		cd3RayHit hit = UntouchedHit();
		bool got = cd3Raycast(&s, ray, &hit);
		TEST_CHECKF(got, "case %d: a ray through the segment missed", i);
		if (got)
		{
			TEST_CHECKF(fabs((double)hit.fraction - 1.0 / reach) <= 1e-4, "case %d: fraction %g, expected %g",
						i, (double)hit.fraction, 1.0 / reach);
			DVec n = D(hit.normal), axis = DNormalize(DSub(p2, p1));
			TEST_CHECKF(fabs(DLength(n) - 1.0) <= 1e-5 && fabs(DDot(n, axis)) <= 1e-3 &&
							DDot(n, D(ray.translation)) <= 0.0,
						"case %d: normal (%g %g %g)", i, n.x, n.y, n.z);
		}
		/* Shift the aim sideways by 1e-3 (perpendicular to both the segment and the ray): miss. */
		DVec side = DNormalize(DCross(DSub(p2, p1), D(ray.translation)));
		if (DLength(side) > 0.0)
		{
			cd3Ray beside = {V(DAdd(D(origin), DScale(1e-3, side))), ray.translation};
			TEST_CHECKF(!cd3Raycast(&s, beside, &hit), "case %d: a ray passing 1e-3 beside hit", i);
		}
	}
}

/* Power-of-two scalings are exact, so a scaled scene must give the same fraction (the algorithms
 * are homogeneous); at huge and tiny scales nothing may become NaN. Huge offsets with unit-size
 * shapes lose all precision in float but must still give finite, in-range answers. */
static void TestScales(void)
{
	TestRng rng = TestRngMake(0x5eed3006);
	cd3ShapeType types[] = {CD3_SHAPE_SPHERE, CD3_SHAPE_CAPSULE,  CD3_SHAPE_AABB,	CD3_SHAPE_BOX,
							CD3_SHAPE_PLANE,  CD3_SHAPE_TRIANGLE, CD3_SHAPE_SEGMENT};
#if CD_DOUBLE
	const double scales[] = {0x1p-100, 0x1p-30, 0x1p20, 0x1p30, 0x1p100};
	const double offsets[] = {1e6, 1e9, 1e30};
#else
	const double scales[] = {0x1p-30, 0x1p-20, 0x1p20, 0x1p30};
	const double offsets[] = {1e6, 1e8, 1e9};
#endif
	int scaleCount = (int)(sizeof(scales) / sizeof(scales[0]));
	int offsetCount = (int)(sizeof(offsets) / sizeof(offsets[0]));
	for (int i = 0; i < 3500; ++i)
	{
		cd3ShapeType type = types[i % 7];
		cd3Shape s;
		if (type == CD3_SHAPE_TRIANGLE)
		{
			s = RandomTriangleShape(&rng);
		}
		else if (type == CD3_SHAPE_SEGMENT)
		{
			s = SegmentShape(RandomVec(&rng, 4.0), RandomVec(&rng, 4.0));
		}
		else
		{
			s = RandomSolid(&rng, type);
		}
		cd3Ray ray = RandomRay(&rng);
		cd3RayHit base = UntouchedHit();
		bool baseGot = cd3Raycast(&s, ray, &base);

		double k = scales[i % scaleCount];
		cd3Shape scaled = s;
		cdReal kr = (cdReal)k;
		switch (type)
		{
			case CD3_SHAPE_SPHERE:
				scaled.sphere.center = cd3Scale(kr, s.sphere.center);
				scaled.sphere.radius = kr * s.sphere.radius;
				break;
			case CD3_SHAPE_CAPSULE:
				scaled.capsule.p1 = cd3Scale(kr, s.capsule.p1);
				scaled.capsule.p2 = cd3Scale(kr, s.capsule.p2);
				scaled.capsule.radius = kr * s.capsule.radius;
				break;
			case CD3_SHAPE_AABB:
				scaled.aabb.min = cd3Scale(kr, s.aabb.min);
				scaled.aabb.max = cd3Scale(kr, s.aabb.max);
				break;
			case CD3_SHAPE_BOX:
				scaled.box.center = cd3Scale(kr, s.box.center);
				scaled.box.halfExtents = cd3Scale(kr, s.box.halfExtents);
				break;
			case CD3_SHAPE_PLANE:
				scaled.plane.offset = kr * s.plane.offset;
				break;
			case CD3_SHAPE_TRIANGLE:
				scaled.triangle.a = cd3Scale(kr, s.triangle.a);
				scaled.triangle.b = cd3Scale(kr, s.triangle.b);
				scaled.triangle.c = cd3Scale(kr, s.triangle.c);
				break;
			default:
				scaled.segment.p1 = cd3Scale(kr, s.segment.p1);
				scaled.segment.p2 = cd3Scale(kr, s.segment.p2);
				break;
		}
		cd3Ray scaledRay = {cd3Scale(kr, ray.origin), cd3Scale(kr, ray.translation)};
		cd3RayHit hit = UntouchedHit();
		bool got = cd3Raycast(&scaled, scaledRay, &hit);
		TEST_CHECKF(got == baseGot, "%s case %d scale %g: %d vs %d", cd3GetShapeTypeName(type), i, k, got,
					baseGot);
		if (got && baseGot)
		{
			TEST_CHECKF(IsFiniteHit(hit), "%s case %d scale %g: not finite", cd3GetShapeTypeName(type), i, k);
			TEST_CHECKF(fabs((double)hit.fraction - (double)base.fraction) <= 1e-5 &&
							DLength(DSub(D(hit.normal), D(base.normal))) <= 1e-5,
						"%s case %d scale %g: fraction %.9g vs %.9g", cd3GetShapeTypeName(type), i, k,
						(double)hit.fraction, (double)base.fraction);
		}

		/* Far from the origin: finite, in range, unit (or zero) normal. */
		double offset = offsets[i % offsetCount];
		cd3Vec shift = V(DScale(offset, D(RandomUnit(&rng))));
		cd3Transform xf = {shift, CD3_QUAT_IDENTITY};
		cd3Shape far = TransformShape(&s, xf);
		cd3Ray farRay = {cd3Add(ray.origin, shift), ray.translation};
		if (TestRngInt(&rng, 2) == 0)
		{
			far = TransformShape(&scaled, xf);
			farRay.origin = cd3Add(scaledRay.origin, shift);
			farRay.translation = scaledRay.translation;
		}
		hit = UntouchedHit();
		if (cd3Raycast(&far, farRay, &hit))
		{
			double n = DLength(D(hit.normal));
			TEST_CHECKF(IsFiniteHit(hit) && hit.fraction >= CD_R(0.0) && hit.fraction <= CD_R(1.0) &&
							(fabs(n - 1.0) <= 1e-5 || n == 0.0),
						"%s case %d offset %g: fraction %g normal length %g", cd3GetShapeTypeName(type), i,
						offset, (double)hit.fraction, n);
		}
	}
}

int main(void)
{
	TEST_RUN(TestSphereExact);
	TEST_RUN(TestCapsuleExact);
	TEST_RUN(TestCapsuleRayFromSurfaceInward);
	TEST_RUN(TestAabbExact);
	TEST_RUN(TestBoxExact);
	TEST_RUN(TestTriangleExact);
	TEST_RUN(TestTriangleRobustness);
	TEST_RUN(TestThinCapsulesFarOut);
	TEST_RUN(TestPlaneExact);
	TEST_RUN(TestSegmentExact);
	TEST_RUN(TestDispatcher);
	TEST_RUN(TestSolidsAgainstReference);
	TEST_RUN(TestSolidsNearTangent);
	TEST_RUN(TestRigidTransformInvariance);
	TEST_RUN(TestTrianglesAgainstReference);
	TEST_RUN(TestSegmentsAimed);
	TEST_RUN(TestScales);
	return TEST_SUMMARY();
}
