/* cd3CollideBoxTriangle's separating axis test takes shortcuts for the box (its extent in closed
 * form, its twelve edges as three directions, the triangle carried into the box's frame once),
 * so it is checked against two references on random boxes and triangles, resting face on face and
 * at random: cd3CollideTriangleHull on the same box built as a hull (the general polytope path)
 * must find the same contact, and the deepest separation of an overlapping pair must be the exact
 * signed separation of a double-precision SAT over every face normal and edge pair. */
#include "collide/manifold3.h"
#include "random_shapes3.h"
#include "manifold_separation3.h"
#include "test.h"

#include <math.h>

/* Coordinates are up to about 3. */
#define TOL (CD_DOUBLE ? 1e-9 : 1e-4)

typedef struct D3
{
	double x, y, z;
} D3;

static D3 ToD3(cd3Vec v)
{
	D3 d = {(double)v.x, (double)v.y, (double)v.z};
	return d;
}

static D3 Sub3(D3 a, D3 b)
{
	D3 d = {a.x - b.x, a.y - b.y, a.z - b.z};
	return d;
}

static double Dot3(D3 a, D3 b)
{
	return a.x * b.x + a.y * b.y + a.z * b.z;
}

static D3 Cross3(D3 a, D3 b)
{
	D3 d = {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
	return d;
}

static double Separation(const D3* a, int na, const D3* b, int nb, D3 axis)
{
	double loA = INFINITY, hiA = -INFINITY, loB = INFINITY, hiB = -INFINITY;
	for (int i = 0; i < na; ++i)
	{
		double d = Dot3(axis, a[i]);
		loA = fmin(loA, d);
		hiA = fmax(hiA, d);
	}
	for (int i = 0; i < nb; ++i)
	{
		double d = Dot3(axis, b[i]);
		loB = fmin(loB, d);
		hiB = fmax(hiB, d);
	}
	return fmax(loB - hiA, loA - hiB);
}

/* The exact signed separation of a (non-degenerate) box and triangle: the largest over the box's
 * three face normals, the triangle's normal and the nine edge crosses. */
static double ReferenceSeparation(cd3Box box, cd3Triangle t)
{
	D3 corners[8], tri[3] = {ToD3(t.a), ToD3(t.b), ToD3(t.c)}, axes[3];
	for (int k = 0; k < 3; ++k)
	{
		cd3Vec unit = cd3MakeVec(k == 0 ? CD_R(1.0) : CD_R(0.0), k == 1 ? CD_R(1.0) : CD_R(0.0),
								 k == 2 ? CD_R(1.0) : CD_R(0.0));
		axes[k] = ToD3(cd3RotateVector(box.rotation, unit));
	}
	D3 c = ToD3(box.center), h = ToD3(box.halfExtents);
	for (int i = 0; i < 8; ++i)
	{
		double sx = (i & 1) ? h.x : -h.x, sy = (i & 2) ? h.y : -h.y, sz = (i & 4) ? h.z : -h.z;
		corners[i].x = c.x + sx * axes[0].x + sy * axes[1].x + sz * axes[2].x;
		corners[i].y = c.y + sx * axes[0].y + sy * axes[1].y + sz * axes[2].y;
		corners[i].z = c.z + sx * axes[0].z + sy * axes[1].z + sz * axes[2].z;
	}
	double best = -INFINITY;
	for (int k = 0; k < 3; ++k)
	{
		best = fmax(best, Separation(corners, 8, tri, 3, axes[k]));
	}
	D3 edges[3] = {Sub3(tri[1], tri[0]), Sub3(tri[2], tri[1]), Sub3(tri[0], tri[2])};
	D3 normal = Cross3(edges[0], Sub3(tri[2], tri[0]));
	best = fmax(best, Separation(corners, 8, tri, 3, normal) / sqrt(Dot3(normal, normal)));
	for (int k = 0; k < 3; ++k)
	{
		for (int e = 0; e < 3; ++e)
		{
			D3 n = Cross3(axes[k], edges[e]);
			double length = sqrt(Dot3(n, n));
			if (length > 1e-9 * sqrt(Dot3(edges[e], edges[e])))
			{
				D3 u = {n.x / length, n.y / length, n.z / length};
				best = fmax(best, Separation(corners, 8, tri, 3, u));
			}
		}
	}
	return best;
}

/* A random box near the origin, and a triangle about its size placed by a random signed gap
 * along a direction: `resting` lays the triangle parallel to one of the box's faces. */
static void RandomPair(TestRng* rng, bool resting, cd3Box* box, cd3Triangle* t)
{
	box->center = RandomVec(rng, 0.2);
	box->halfExtents =
		cd3MakeVec(RandomReal(rng, 0.1, 1.0), RandomReal(rng, 0.1, 1.0), RandomReal(rng, 0.1, 1.0));
	box->rotation = RandomQuat(rng);
	int axis = (int)TestRngRange(rng, 0.0, 2.999);
	cd3Vec unit = cd3MakeVec(axis == 0 ? CD_R(1.0) : CD_R(0.0), axis == 1 ? CD_R(1.0) : CD_R(0.0),
							 axis == 2 ? CD_R(1.0) : CD_R(0.0));
	cd3Vec up = resting ? cd3RotateVector(box->rotation, unit) : RandomUnit(rng);
	cd3Vec side = cd3Normalize(cd3Cross(up, RandomUnit(rng)));
	cd3Vec other = cd3Cross(up, side);
	/* The triangle's plane at the box's extent along `up`, give or take a random gap. */
	cdReal reach = CD_R(0.0);
	for (int k = 0; k < 3; ++k)
	{
		cd3Vec e = cd3MakeVec(k == 0 ? CD_R(1.0) : CD_R(0.0), k == 1 ? CD_R(1.0) : CD_R(0.0),
							  k == 2 ? CD_R(1.0) : CD_R(0.0));
		reach += cd3GetComponent(box->halfExtents, k) * cdAbs(cd3Dot(up, cd3RotateVector(box->rotation, e)));
	}
	cd3Vec base = cd3Add(box->center, cd3Scale(reach + RandomReal(rng, -0.3, 0.3), up));
	cd3Vec corners[3];
	for (int k = 0; k < 3; ++k)
	{
		double angle = 2.0943951023931957 * k + TestRngRange(rng, -0.4, 0.4);
		double radius = TestRngRange(rng, 0.3, 2.0);
		corners[k] = cd3Add(base, cd3Add(cd3Scale((cdReal)(radius * cos(angle)), side),
										 cd3Scale((cdReal)(radius * sin(angle)), other)));
	}
	t->a = corners[0];
	t->b = corners[1];
	t->c = corners[2];
}

static void TestAgainstHullPathAndReference(void)
{
	TestRng rng = TestRngMake(0xB07A);
	int contacts = 0, deep = 0;
	for (int i = 0; i < 4000; ++i)
	{
		cd3Box box;
		cd3Triangle t;
		RandomPair(&rng, i % 2 == 0, &box, &t);
		cdReal speculative = (i % 3 == 0) ? CD_R(0.1) : CD_R(0.0);
		cd3Manifold m = cd3CollideBoxTriangle(box, t, speculative);
		cd3Hull* hull = NULL;
		if (cd3MakeBoxHull(box.halfExtents, &hull) != CD_OK)
		{
			TEST_CHECK(false);
			continue;
		}
		cd3HullShape hullShape = {hull, {box.center, box.rotation}};
		cd3Manifold h = cd3CollideTriangleHull(t, hullShape, speculative);
		cd3DestroyHull(hull);
		double reference = ReferenceSeparation(box, t);
		/* The contact exists on both paths alike, away from the speculative distance. */
		if (fabs(reference - (double)speculative) > 1e-3)
		{
			TEST_CHECKF((m.pointCount > 0) == (h.pointCount > 0) &&
							(m.pointCount > 0) == (reference <= (double)speculative),
						"pair %d: box path %d points, hull path %d, reference separation %g", i, m.pointCount,
						h.pointCount, reference);
		}
		if (m.pointCount > 0 && h.pointCount > 0)
		{
			++contacts;
			TEST_CHECKF(fabs(MinSeparation(&m) - MinSeparation(&h)) <= TOL,
						"pair %d: deepest separation %.9g (box path) against %.9g (hull path)", i,
						MinSeparation(&m), MinSeparation(&h));
		}
		if (m.pointCount > 0 && reference < 0.0)
		{
			++deep;
			/* The depth is the depth along the normal: the triangle moved by it along the normal just
			 * touches the box. The reference feature's tie bias (1e-4 of the size, face and edge) can
			 * take a normal along which that depth exceeds the smallest one by up to that much. */
			cd3Vec shift = cd3Scale((cdReal)-MinSeparation(&m), m.normal);
			cd3Triangle moved = {cd3Add(t.a, shift), cd3Add(t.b, shift), cd3Add(t.c, shift)};
			double after = ReferenceSeparation(box, moved);
			cd3Aabb bounds = cd3ComputeTriangleAabb(t);
			double size =
				2.0 * (double)cd3Length(box.halfExtents) + (double)cd3Length(cd3Sub(bounds.max, bounds.min));
			TEST_CHECKF(fabs(after) <= TOL,
						"pair %d: deepest separation %.9g; moved by it along the normal, %.3g apart", i,
						MinSeparation(&m), after);
			TEST_CHECKF(MinSeparation(&m) <= reference + TOL &&
							MinSeparation(&m) >= reference - 2e-4 * size - TOL,
						"pair %d: deepest separation %.9g, exact %.9g", i, MinSeparation(&m), reference);
		}
	}
	printf("box-triangle: %d pairs in contact on both paths, %d overlapping against the exact SAT\n",
		   contacts, deep);
	TEST_CHECK(contacts > 1000 && deep > 500);
}

int main(void)
{
	TEST_RUN(TestAgainstHullPathAndReference);
	return TEST_SUMMARY();
}
