/* The normal of a 3D shape cast hit is the contact normal of the touching features: at the
 * reported fraction, the plane through the hit point with the reported normal separates the two
 * shapes (to within 2e-4 for unit-size shapes), in the float and the double build. Random pairs
 * of every family (box, hull, sphere, capsule, AABB) and the exact case of a box cast whose
 * closest-point normal erred by 3.8e-3 rad in float. */
#include "collide/cast.h"
#include "random_shapes3.h"
#include "test.h"

#include <math.h>
#include <string.h>

#define PLANE_TOLERANCE 2e-4

/* max over the shape of dot(x, n), in double from the shape's own data. */
static double Support(const cd3Shape* s, const double n[3])
{
	switch (s->type)
	{
		case CD3_SHAPE_SPHERE:
		{
			cd3Vec c = s->sphere.center;
			return c.x * n[0] + c.y * n[1] + c.z * n[2] + s->sphere.radius;
		}
		case CD3_SHAPE_CAPSULE:
		{
			cd3Vec p = s->capsule.p1, q = s->capsule.p2;
			double a = p.x * n[0] + p.y * n[1] + p.z * n[2], b = q.x * n[0] + q.y * n[1] + q.z * n[2];
			return (a > b ? a : b) + s->capsule.radius;
		}
		case CD3_SHAPE_AABB:
		{
			const cdReal* lo = &s->aabb.min.x;
			const cdReal* hi = &s->aabb.max.x;
			double sum = 0.0;
			for (int k = 0; k < 3; ++k)
			{
				sum += n[k] >= 0.0 ? hi[k] * n[k] : lo[k] * n[k];
			}
			return sum;
		}
		case CD3_SHAPE_BOX:
		{
			cd3Vec c = s->box.center;
			double sum = c.x * n[0] + c.y * n[1] + c.z * n[2];
			const cdReal* h = &s->box.halfExtents.x;
			for (int k = 0; k < 3; ++k)
			{
				cd3Vec unit = cd3MakeVec(k == 0 ? CD_R(1.0) : CD_R(0.0), k == 1 ? CD_R(1.0) : CD_R(0.0),
										 k == 2 ? CD_R(1.0) : CD_R(0.0));
				cd3Vec axis = cd3RotateVector(s->box.rotation, unit);
				sum += fabs(axis.x * n[0] + axis.y * n[1] + axis.z * n[2]) * h[k];
			}
			return sum;
		}
		case CD3_SHAPE_HULL:
		{
			double best = -INFINITY;
			for (int i = 0; i < s->hull.hull->vertexCount; ++i)
			{
				cd3Vec v = cd3TransformPoint(s->hull.transform, s->hull.hull->vertices[i]);
				double d = v.x * n[0] + v.y * n[1] + v.z * n[2];
				best = d > best ? d : best;
			}
			return best;
		}
		default:
			return NAN;
	}
}

static cd3Shape Translated(const cd3Shape* s, cd3Vec d)
{
	cd3Transform t = {d, CD3_QUAT_IDENTITY};
	return TransformShape(s, t);
}

/* Gap errors of the plane through the hit with the hit normal: how far B reaches above it and A
 * below it (both <= 0 when the plane separates them). */
static void PlaneErrors(const cd3Shape* a, const cd3Shape* b, cd3Vec translation, cd3CastOutput out,
						double* errorA, double* errorB)
{
	cd3Shape moved = Translated(a, cd3Scale(out.fraction, translation));
	double n[3] = {out.normal.x, out.normal.y, out.normal.z};
	double m[3] = {-n[0], -n[1], -n[2]};
	double level = out.point.x * n[0] + out.point.y * n[1] + out.point.z * n[2];
	*errorB = Support(b, n) - level;		 /* B lies below the plane */
	*errorA = level - (-Support(&moved, m)); /* A lies above it */
}

static void TestIssueBoxCase(void)
{
	cd3Shape a, b;
	memset(&a, 0, sizeof(a));
	memset(&b, 0, sizeof(b));
	a.type = b.type = CD3_SHAPE_BOX;
	a.box = (cd3Box){{CD_R(-0.854673147), CD_R(1.6047523), CD_R(-1.93558645)},
					 {CD_R(0.924514592), CD_R(0.903244615), CD_R(0.924298823)},
					 {CD_R(0.745737255), CD_R(0.473845601), CD_R(-0.189695388), CD_R(0.428207874)}};
	b.box = (cd3Box){{CD_R(0.0877410248), CD_R(-0.104361132), CD_R(-0.0526990294)},
					 {CD_R(0.866688669), CD_R(0.297198892), CD_R(0.351139188)},
					 {CD_R(0.103836589), CD_R(0.937838018), CD_R(-0.324411869), CD_R(-0.0665942803)}};
	cd3Vec translation = cd3MakeVec(CD_R(1.77421464), CD_R(-1.98794139), CD_R(4.46842241));
	cd3CastOutput out = cd3ShapeCast(&a, &b, translation);
	TEST_CHECK(out.hit);
	/* The exact contact normal (a face of one box or an edge pair), within float round-off. */
	TEST_CHECK_NEAR(out.normal.x, 0.092185, 2e-5);
	TEST_CHECK_NEAR(out.normal.y, 0.572562, 2e-5);
	TEST_CHECK_NEAR(out.normal.z, -0.814662, 2e-5);
	double errorA, errorB;
	PlaneErrors(&a, &b, translation, out, &errorA, &errorB);
	TEST_CHECKF(errorA <= PLANE_TOLERANCE && errorB <= PLANE_TOLERANCE, "A %.3g B %.3g", errorA, errorB);
}

typedef struct Family
{
	const char* name;
	cd3ShapeType a, b;
} Family;

static void TestRandomCastNormals(void)
{
	static const Family families[] = {
		{"box-box", CD3_SHAPE_BOX, CD3_SHAPE_BOX},
		{"hull-hull", CD3_SHAPE_HULL, CD3_SHAPE_HULL},
		{"hull-box", CD3_SHAPE_HULL, CD3_SHAPE_BOX},
		{"box-hull", CD3_SHAPE_BOX, CD3_SHAPE_HULL},
		{"sphere-box", CD3_SHAPE_SPHERE, CD3_SHAPE_BOX},
		{"box-sphere", CD3_SHAPE_BOX, CD3_SHAPE_SPHERE},
		{"sphere-hull", CD3_SHAPE_SPHERE, CD3_SHAPE_HULL},
		{"capsule-box", CD3_SHAPE_CAPSULE, CD3_SHAPE_BOX},
		{"box-capsule", CD3_SHAPE_BOX, CD3_SHAPE_CAPSULE},
		{"capsule-hull", CD3_SHAPE_CAPSULE, CD3_SHAPE_HULL},
		{"capsule-capsule", CD3_SHAPE_CAPSULE, CD3_SHAPE_CAPSULE},
		{"aabb-box", CD3_SHAPE_AABB, CD3_SHAPE_BOX},
		{"sphere-sphere", CD3_SHAPE_SPHERE, CD3_SHAPE_SPHERE},
	};
	TestRng rng = TestRngMake(0xca57a0123ull);
	for (size_t f = 0; f < sizeof(families) / sizeof(families[0]); ++f)
	{
		int hits = 0, failures = 0;
		double worst = 0.0;
		for (int i = 0; i < 3000; ++i)
		{
			cd3Shape a = RandomShape(&rng, families[f].a), b = RandomShape(&rng, families[f].b);
			/* A starts about 4 away and moves through B's middle, off by a random amount. */
			cd3Vec start = cd3Scale(RandomReal(&rng, 3.5, 4.5), RandomUnit(&rng));
			cd3Vec centerA = cd3AabbCenter(cd3ComputeShapeAabb(&a));
			cd3Vec centerB = cd3AabbCenter(cd3ComputeShapeAabb(&b));
			a = Translated(&a, cd3Add(cd3Sub(centerB, centerA), start));
			cd3Vec translation = cd3Add(cd3Scale(CD_R(-2.0), start), RandomVec(&rng, 1.0));
			cd3CastOutput out = cd3ShapeCast(&a, &b, translation);
			if (!out.hit || out.fraction <= CD_R(0.0))
			{
				continue;
			}
			++hits;
			double errorA, errorB;
			PlaneErrors(&a, &b, translation, out, &errorA, &errorB);
			double error = errorA > errorB ? errorA : errorB;
			worst = error > worst ? error : worst;
			double length = cd3Length(out.normal);
			if (!(error <= PLANE_TOLERANCE) || !(fabs(length - 1.0) < 1e-5))
			{
				if (++failures <= 3)
				{
					TEST_CHECKF(false,
								"%s pair %d: fraction %.9g normal (%.9g %.9g %.9g) cuts A by %.3g, B by %.3g",
								families[f].name, i, (double)out.fraction, (double)out.normal.x,
								(double)out.normal.y, (double)out.normal.z, errorA, errorB);
					PrintShape("A", &a);
					PrintShape("B", &b);
					fprintf(stderr, "  translation (%.9g %.9g %.9g)\n", (double)translation.x,
							(double)translation.y, (double)translation.z);
				}
			}
		}
		printf("  %-16s %4d hits, %d planes cut deeper than %.0e, worst %.3g\n", families[f].name, hits,
			   failures, PLANE_TOLERANCE, worst);
		TEST_CHECKF(hits > 1000, "%s: only %d hits", families[f].name, hits);
		TEST_CHECKF(failures == 0, "%s: %d failures", families[f].name, failures);
	}
}

/* Round shapes: the hit normal is the true surface normal, the direction from the closest point
 * of the box to the sphere's centre at the hit (in double), to 1e-4 rad in float: the cast stops
 * when the cores are within the radius plus the tolerance, where the ray cast's point of the
 * difference is not yet the closest one (its direction was off by up to 4e-3 rad). */
static void TestSphereBoxSurfaceNormal(void)
{
	TestRng rng = TestRngMake(0x5b4e0a1ull);
	int hits = 0, failures = 0;
	double worst = 0.0;
	for (int i = 0; i < 3000; ++i)
	{
		cd3Shape a = RandomShape(&rng, CD3_SHAPE_SPHERE), b = RandomShape(&rng, CD3_SHAPE_BOX);
		a.sphere.radius = (cdReal)TestRngRange(&rng, 0.1, 1.0);
		cd3Vec start = cd3Scale(RandomReal(&rng, 3.5, 4.5), RandomUnit(&rng));
		a = Translated(&a, cd3Add(cd3Sub(b.box.center, a.sphere.center), start));
		cd3Vec translation = cd3Add(cd3Scale(CD_R(-2.0), start), RandomVec(&rng, 1.0));
		cd3CastOutput out = cd3ShapeCast(&a, &b, translation);
		if (!out.hit || out.fraction <= CD_R(0.0))
		{
			continue;
		}
		++hits;
		cd3Vec center = cd3MulAdd(a.sphere.center, out.fraction, translation);
		cd3Vec closest = cd3ClosestPointOnBox(b.box, center);
		double d[3] = {(double)center.x - (double)closest.x, (double)center.y - (double)closest.y,
					   (double)center.z - (double)closest.z};
		double length = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
		/* The angle from the cross product (acos of a dot product near 1 turns the normal's
		 * float round-off of its length, 6e-8, into 3.5e-4 rad). */
		double n[3] = {(double)out.normal.x, (double)out.normal.y, (double)out.normal.z};
		double c[3] = {n[1] * d[2] - n[2] * d[1], n[2] * d[0] - n[0] * d[2], n[0] * d[1] - n[1] * d[0]};
		double nLength = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
		double angle = asin(fmin(1.0, sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) / (length * nLength)));
		angle = n[0] * d[0] + n[1] * d[1] + n[2] * d[2] < 0.0 ? 3.14159265358979 - angle : angle;
		worst = fmax(worst, angle);
		if (!(angle <= 1e-4) && ++failures <= 3)
		{
			TEST_CHECKF(false, "pair %d: normal %.3g rad off the surface normal", i, angle);
		}
	}
	printf("  sphere-box surface normal: %d hits, worst %.3g rad\n", hits, worst);
	TEST_CHECK(hits > 1000);
	TEST_CHECK(failures == 0);
}

int main(void)
{
	TEST_RUN(TestIssueBoxCase);
	TEST_RUN(TestRandomCastNormals);
	TEST_RUN(TestSphereBoxSurfaceNormal);
	return TEST_SUMMARY();
}
