/* The local-frame manifolds of manifold3.h against the world-space ones: the same answer, bit for
 * bit, when B's frame is placed in A's frame by the same transform; within round-off when both
 * bodies move; and more precise far from the origin, where world coordinates lose digits. */
#include "collide/manifold3.h"
#include "random_shapes3.h"
#include "test.h"

#include <math.h>
#include <stdio.h>

/* b placed by xf the way the local forms place it (manifold3.h): points transformed, rotations and
 * hull transforms multiplied, an AABB read as a box. */
static cd3Shape Place(const cd3Shape* b, cd3Transform xf)
{
	cd3Shape s = *b;
	switch (b->type)
	{
		case CD3_SHAPE_SPHERE:
			s.sphere.center = cd3TransformPoint(xf, b->sphere.center);
			break;
		case CD3_SHAPE_CAPSULE:
			s.capsule.p1 = cd3TransformPoint(xf, b->capsule.p1);
			s.capsule.p2 = cd3TransformPoint(xf, b->capsule.p2);
			break;
		case CD3_SHAPE_AABB:
			s.type = CD3_SHAPE_BOX;
			s.box.center = cd3TransformPoint(xf, cd3AabbCenter(b->aabb));
			s.box.halfExtents = cd3AabbHalfExtents(b->aabb);
			s.box.rotation = cd3MulQuat(xf.q, CD3_QUAT_IDENTITY);
			break;
		case CD3_SHAPE_BOX:
			s.box.center = cd3TransformPoint(xf, b->box.center);
			s.box.rotation = cd3MulQuat(xf.q, b->box.rotation);
			break;
		case CD3_SHAPE_TRIANGLE:
			s.triangle.a = cd3TransformPoint(xf, b->triangle.a);
			s.triangle.b = cd3TransformPoint(xf, b->triangle.b);
			s.triangle.c = cd3TransformPoint(xf, b->triangle.c);
			break;
		case CD3_SHAPE_HULL:
			s.hull.transform = cd3MulTransforms(xf, b->hull.transform);
			break;
		default:
			break; /* planes and segments: no manifold either way */
	}
	return s;
}

static cd3Transform RandomTransform(TestRng* rng, double extent)
{
	cd3Transform xf;
	xf.p = RandomVec(rng, extent);
	xf.q = RandomQuat(rng);
	return xf;
}

static bool SameBits(cd3Manifold m, cd3Manifold n)
{
	if (m.pointCount != n.pointCount || !cd3VecEqual(m.normal, n.normal))
	{
		return false;
	}
	for (int i = 0; i < m.pointCount; ++i)
	{
		if (!cd3VecEqual(m.points[i].point, n.points[i].point) ||
			m.points[i].separation != n.points[i].separation || m.points[i].id != n.points[i].id)
		{
			return false;
		}
	}
	return true;
}

/* The typed pair function of (a, b) in both forms, when a and b are in canonical order and have one
 * (AABBs go through cd3Collide only). */
static bool TypedPair(const cd3Shape* a, const cd3Shape* b, cd3Transform xf, cdReal d, cd3Manifold* local,
					  cd3Manifold* world)
{
	cd3Shape w = Place(b, xf);
	cd3ShapeType ta = a->type, tb = b->type;
#define PAIR(TA, TB, F, fa, fb)                                                                              \
	if (ta == TA && tb == TB)                                                                                \
	{                                                                                                        \
		*local = F##Local(a->fa, b->fb, xf, d);                                                              \
		*world = F(a->fa, w.fb, d);                                                                          \
		return true;                                                                                         \
	}
	PAIR(CD3_SHAPE_SPHERE, CD3_SHAPE_SPHERE, cd3CollideSphereSphere, sphere, sphere)
	PAIR(CD3_SHAPE_SPHERE, CD3_SHAPE_CAPSULE, cd3CollideSphereCapsule, sphere, capsule)
	PAIR(CD3_SHAPE_SPHERE, CD3_SHAPE_BOX, cd3CollideSphereBox, sphere, box)
	PAIR(CD3_SHAPE_SPHERE, CD3_SHAPE_HULL, cd3CollideSphereHull, sphere, hull)
	PAIR(CD3_SHAPE_SPHERE, CD3_SHAPE_TRIANGLE, cd3CollideSphereTriangle, sphere, triangle)
	PAIR(CD3_SHAPE_CAPSULE, CD3_SHAPE_CAPSULE, cd3CollideCapsuleCapsule, capsule, capsule)
	PAIR(CD3_SHAPE_CAPSULE, CD3_SHAPE_BOX, cd3CollideCapsuleBox, capsule, box)
	PAIR(CD3_SHAPE_CAPSULE, CD3_SHAPE_HULL, cd3CollideCapsuleHull, capsule, hull)
	PAIR(CD3_SHAPE_CAPSULE, CD3_SHAPE_TRIANGLE, cd3CollideCapsuleTriangle, capsule, triangle)
	PAIR(CD3_SHAPE_BOX, CD3_SHAPE_BOX, cd3CollideBoxBox, box, box)
	PAIR(CD3_SHAPE_BOX, CD3_SHAPE_HULL, cd3CollideBoxHull, box, hull)
	PAIR(CD3_SHAPE_BOX, CD3_SHAPE_TRIANGLE, cd3CollideBoxTriangle, box, triangle)
	PAIR(CD3_SHAPE_HULL, CD3_SHAPE_HULL, cd3CollideHullHull, hull, hull)
	PAIR(CD3_SHAPE_TRIANGLE, CD3_SHAPE_HULL, cd3CollideTriangleHull, triangle, hull)
	PAIR(CD3_SHAPE_TRIANGLE, CD3_SHAPE_TRIANGLE, cd3CollideTriangleTriangle, triangle, triangle)
#undef PAIR
	return false;
}

static void TestSameAsWorldForm(void)
{
	TestRng rng = TestRngMake(0x10ca4u);
	int typed = 0;
	for (int ta = 0; ta < CD3_SHAPE_TYPE_COUNT; ++ta)
	{
		for (int tb = 0; tb < CD3_SHAPE_TYPE_COUNT; ++tb)
		{
			for (int i = 0; i < 100; ++i)
			{
				cd3Shape a = RandomShape(&rng, (cd3ShapeType)ta);
				cd3Shape b = RandomShape(&rng, (cd3ShapeType)tb);
				cd3Transform xf = RandomTransform(&rng, 2.0);
				cdReal d = TestRngInt(&rng, 2) == 0 ? CD_R(0.0) : RandomReal(&rng, 0.0, 0.5);
				cd3Shape w = Place(&b, xf);
				cd3Manifold local = cd3CollideLocal(&a, &b, xf, d);
				cd3Manifold world = cd3Collide(&a, &w, d);
				TEST_CHECKF(SameBits(local, world), "%s-%s case %d: %d vs %d points", TypeName(a.type),
							TypeName(b.type), i, local.pointCount, world.pointCount);
				cd3Manifold tl, tw;
				if (TypedPair(&a, &b, xf, d, &tl, &tw))
				{
					++typed;
					TEST_CHECKF(SameBits(tl, tw), "typed %s-%s case %d", TypeName(a.type), TypeName(b.type),
								i);
				}
			}
		}
	}
	TEST_CHECK(typed == 15 * 100);
}

/* Both bodies moved: the world form on the two placed shapes against the local form mapped to the
 * world. Equal within 1e-6 relative to the coordinates, with the same points and feature ids
 * except at the rare near ties where one of two features wins by round-off (at most 2% of the
 * pairs: 3D has many more of them, e.g. the four-point reduction of a clipped polygon). */
static void TestMovedBodies(void)
{
	TestRng rng = TestRngMake(0x10ca5u);
	int cases = 0, ties = 0;
	double worst = 0.0;
	double tolerance = 1e-6;
	for (int ta = 0; ta < CD3_SHAPE_TYPE_COUNT; ++ta)
	{
		for (int tb = 0; tb < CD3_SHAPE_TYPE_COUNT; ++tb)
		{
			for (int i = 0; i < 100; ++i)
			{
				cd3Shape a = RandomShape(&rng, (cd3ShapeType)ta);
				cd3Shape b = RandomShape(&rng, (cd3ShapeType)tb);
				cd3Transform xfA = RandomTransform(&rng, 10.0);
				cd3Transform xfRel = RandomTransform(&rng, 2.0);
				cd3Transform xfB = cd3MulTransforms(xfA, xfRel);
				cdReal d = RandomReal(&rng, 0.0, 0.3);
				cd3Shape wa = Place(&a, xfA), wb = Place(&b, xfB);
				cd3Manifold world = cd3Collide(&wa, &wb, d);
				cd3Manifold local = cd3TransformManifold(xfA, cd3CollideLocal(&a, &b, xfRel, d));
				++cases;
				bool same = world.pointCount == local.pointCount;
				for (int k = 0; same && k < world.pointCount; ++k)
				{
					same = world.points[k].id == local.points[k].id;
				}
				if (!same)
				{
					++ties;
					continue;
				}
				double scale = 14.0 + 10.0 * sqrt(3.0);
				for (int k = 0; k < world.pointCount; ++k)
				{
					cd3Vec dp = cd3Sub(world.points[k].point, local.points[k].point);
					double e = fmax(fabs((double)dp.x), fmax(fabs((double)dp.y), fabs((double)dp.z)));
					e = fmax(e,
							 fabs((double)world.points[k].separation - (double)local.points[k].separation));
					worst = fmax(worst, e / scale);
				}
			}
		}
	}
	printf("moved bodies: %d pairs, %d near ties, worst relative difference %.3g (tolerance %.3g)\n", cases,
		   ties, worst, tolerance);
	TEST_CHECKF(ties * 50 <= cases, "%d of %d pairs differ in points or ids", ties, cases);
	TEST_CHECKF(worst <= tolerance, "worst %g", worst);
}

/* Far from the origin: box (or sphere, hull) B resting a known gap above box A, both bodies
 * translated to coordinates around 1e4..1e5. The local form sees the shapes' own coordinates and
 * the exact relative translation; the world form loses the digits of the coordinates. */
static void TestFarFromOrigin(void)
{
	TestRng rng = TestRngMake(0x10ca6u);
	double worstLocal = 0.0, worstWorld = 0.0;
	cd3Hull* cube = NULL;
	TEST_CHECK(cd3MakeBoxHull(cd3MakeVec(CD_R(0.5), CD_R(0.5), CD_R(0.5)), &cube) == CD_OK);
	for (int i = 0; i < 300; ++i)
	{
		double far = TestRngRange(&rng, 1.0e4, 1.0e5);
		cd3Transform xfA = {cd3MakeVec((cdReal)far, (cdReal)(-0.6 * far), (cdReal)(0.3 * far)),
							CD3_QUAT_IDENTITY};
		cdReal gap = RandomReal(&rng, 0.001, 0.05);
		cdReal h = RandomReal(&rng, 0.2, 1.0);
		int kind = TestRngInt(&rng, 3);
		cdReal hb = kind == 2 ? CD_R(0.5) : RandomReal(&rng, 0.2, 1.0);
		cd3Transform xfB = {
			cd3Add(xfA.p, cd3MakeVec(RandomReal(&rng, -0.1, 0.1), h + gap + hb, RandomReal(&rng, -0.1, 0.1))),
			CD3_QUAT_IDENTITY};
		cd3Transform xfRel = cd3InvMulTransforms(xfA, xfB);
		cdReal trueGap = (xfB.p.y - xfA.p.y) - h - hb;
		cd3Shape a =
			cd3MakeBoxShape((cd3Box){CD3_VEC_ZERO, cd3MakeVec(CD_R(2.0), h, CD_R(2.0)), CD3_QUAT_IDENTITY});
		cd3Shape b;
		if (kind == 0)
		{
			b = cd3MakeBoxShape(
				(cd3Box){CD3_VEC_ZERO, cd3MakeVec(CD_R(0.5), hb, CD_R(0.5)), CD3_QUAT_IDENTITY});
		}
		else if (kind == 1)
		{
			b = cd3MakeSphereShape((cd3Sphere){CD3_VEC_ZERO, hb});
		}
		else
		{
			b = cd3MakeHullShape(cube, CD3_TRANSFORM_IDENTITY);
		}
		cd3Manifold local = cd3CollideLocal(&a, &b, xfRel, CD_R(0.1));
		cd3Shape wa = Place(&a, xfA), wb = Place(&b, xfB);
		cd3Manifold world = cd3Collide(&wa, &wb, CD_R(0.1));
		TEST_CHECKF(local.pointCount == (kind == 1 ? 1 : 4), "case %d kind %d: %d points", i, kind,
					local.pointCount);
		for (int k = 0; k < local.pointCount; ++k)
		{
			worstLocal = fmax(worstLocal, fabs((double)local.points[k].separation - (double)trueGap));
		}
		for (int k = 0; k < world.pointCount; ++k)
		{
			worstWorld = fmax(worstWorld, fabs((double)world.points[k].separation - (double)trueGap));
		}
	}
	cd3DestroyHull(cube);
	printf("far from the origin: worst gap error local %.3g, world %.3g\n", worstLocal, worstWorld);
	TEST_CHECKF(worstLocal <= 16.0 * (double)CD_REAL_EPSILON * 3.0, "local error %g", worstLocal);
	TEST_CHECK(worstLocal <= worstWorld || worstWorld <= 16.0 * (double)CD_REAL_EPSILON * 3.0);
}

int main(void)
{
	TEST_RUN(TestSameAsWorldForm);
	TEST_RUN(TestMovedBodies);
	TEST_RUN(TestFarFromOrigin);
	return TEST_SUMMARY();
}
