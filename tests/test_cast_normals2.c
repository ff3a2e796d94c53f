/* The normal of a 2D shape cast hit is the contact normal of the touching features: at the
 * reported fraction, the line through the hit point with the reported normal separates the two
 * shapes (to within 2e-4 for unit-size shapes), in the float and the double build, over random
 * pairs of polygons (rounded or not), boxes, circles and capsules. */
#include "collide/cast.h"
#include "random_shapes2.h"
#include "test.h"

#include <math.h>
#include <string.h>

#define LINE_TOLERANCE 2e-4

/* max over the shape of dot(x, n), in double from the shape's own data. */
static double Support(const cd2Shape* s, const double n[2])
{
	switch (s->type)
	{
		case CD2_SHAPE_CIRCLE:
			return s->circle.center.x * n[0] + s->circle.center.y * n[1] + s->circle.radius;
		case CD2_SHAPE_CAPSULE:
		{
			double a = s->capsule.p1.x * n[0] + s->capsule.p1.y * n[1];
			double b = s->capsule.p2.x * n[0] + s->capsule.p2.y * n[1];
			return (a > b ? a : b) + s->capsule.radius;
		}
		case CD2_SHAPE_AABB:
			return (n[0] >= 0.0 ? s->aabb.max.x : s->aabb.min.x) * n[0] +
				   (n[1] >= 0.0 ? s->aabb.max.y : s->aabb.min.y) * n[1];
		case CD2_SHAPE_BOX:
		{
			double c = s->box.rotation.c, sn = s->box.rotation.s;
			double ux = c * n[0] + sn * n[1], uy = -sn * n[0] + c * n[1];
			return s->box.center.x * n[0] + s->box.center.y * n[1] + fabs(ux) * s->box.halfExtents.x +
				   fabs(uy) * s->box.halfExtents.y;
		}
		case CD2_SHAPE_POLYGON:
		{
			double best = -INFINITY;
			for (int i = 0; i < s->polygon.count; ++i)
			{
				double d = s->polygon.vertices[i].x * n[0] + s->polygon.vertices[i].y * n[1];
				best = d > best ? d : best;
			}
			return best + s->polygon.radius;
		}
		default:
			return NAN;
	}
}

static cd2Shape Translated(const cd2Shape* s, cd2Vec d)
{
	cd2Transform t = {d, CD2_ROT_IDENTITY};
	return TransformShape(s, t);
}

typedef struct Family
{
	const char* name;
	cd2ShapeType a, b;
} Family;

static void TestRandomCastNormals(void)
{
	static const Family families[] = {
		{"polygon-polygon", CD2_SHAPE_POLYGON, CD2_SHAPE_POLYGON},
		{"box-box", CD2_SHAPE_BOX, CD2_SHAPE_BOX},
		{"box-polygon", CD2_SHAPE_BOX, CD2_SHAPE_POLYGON},
		{"circle-polygon", CD2_SHAPE_CIRCLE, CD2_SHAPE_POLYGON},
		{"polygon-circle", CD2_SHAPE_POLYGON, CD2_SHAPE_CIRCLE},
		{"capsule-polygon", CD2_SHAPE_CAPSULE, CD2_SHAPE_POLYGON},
		{"polygon-capsule", CD2_SHAPE_POLYGON, CD2_SHAPE_CAPSULE},
		{"capsule-capsule", CD2_SHAPE_CAPSULE, CD2_SHAPE_CAPSULE},
		{"circle-circle", CD2_SHAPE_CIRCLE, CD2_SHAPE_CIRCLE},
		{"aabb-box", CD2_SHAPE_AABB, CD2_SHAPE_BOX},
	};
	TestRng rng = TestRngMake(0xca57a0222ull);
	for (size_t f = 0; f < sizeof(families) / sizeof(families[0]); ++f)
	{
		int hits = 0, failures = 0;
		double worst = 0.0;
		for (int i = 0; i < 3000; ++i)
		{
			cd2Shape a = RandomShape(&rng, families[f].a), b = RandomShape(&rng, families[f].b);
			double angle = TestRngRange(&rng, 0.0, 6.283185307179586),
				   distance = TestRngRange(&rng, 3.5, 4.5);
			cd2Vec start = cd2MakeVec((cdReal)(distance * cos(angle)), (cdReal)(distance * sin(angle)));
			cd2Vec centerA = cd2AabbCenter(cd2ComputeShapeAabb(&a));
			cd2Vec centerB = cd2AabbCenter(cd2ComputeShapeAabb(&b));
			a = Translated(&a, cd2Add(cd2Sub(centerB, centerA), start));
			cd2Vec translation = cd2Add(cd2Scale(CD_R(-2.0), start), RandomVec(&rng, 1.0));
			cd2CastOutput out = cd2ShapeCast(&a, &b, translation);
			if (!out.hit || out.fraction <= CD_R(0.0))
			{
				continue;
			}
			++hits;
			cd2Shape moved = Translated(&a, cd2Scale(out.fraction, translation));
			double n[2] = {out.normal.x, out.normal.y}, m[2] = {-n[0], -n[1]};
			double level = out.point.x * n[0] + out.point.y * n[1];
			double errorB = Support(&b, n) - level;
			double errorA = level + Support(&moved, m);
			double error = errorA > errorB ? errorA : errorB;
			worst = error > worst ? error : worst;
			double length = cd2Length(out.normal);
			if (!(error <= LINE_TOLERANCE) || !(fabs(length - 1.0) < 1e-5))
			{
				if (++failures <= 3)
				{
					TEST_CHECKF(false,
								"%s pair %d: fraction %.9g normal (%.9g %.9g) cuts A by %.3g, B by %.3g",
								families[f].name, i, (double)out.fraction, (double)out.normal.x,
								(double)out.normal.y, errorA, errorB);
					PrintShape("A", &a);
					PrintShape("B", &b);
					fprintf(stderr, "  translation (%.9g %.9g)\n", (double)translation.x,
							(double)translation.y);
				}
			}
		}
		printf("  %-16s %4d hits, %d lines cut deeper than %.0e, worst %.3g\n", families[f].name, hits,
			   failures, LINE_TOLERANCE, worst);
		TEST_CHECKF(hits > 1000, "%s: only %d hits", families[f].name, hits);
		TEST_CHECKF(failures == 0, "%s: %d failures", families[f].name, failures);
	}
}

int main(void)
{
	TEST_RUN(TestRandomCastNormals);
	return TEST_SUMMARY();
}
