/* collide: 3D manifolds in A's frame (manifold3.h, "local-frame forms"). Shape B is moved into
 * A's frame on the stack (a hull composes its transform, its vertices stay where they are) and
 * the world-space pair function runs on the result, so both forms give the same answer by
 * construction; A is never transformed and the manifold stays in A's frame. */
#include "collide/manifold3.h"

static inline cd3Sphere SphereIn(cd3Transform xf, cd3Sphere s)
{
	s.center = cd3TransformPoint(xf, s.center);
	return s;
}

static inline cd3Capsule CapsuleIn(cd3Transform xf, cd3Capsule c)
{
	c.p1 = cd3TransformPoint(xf, c.p1);
	c.p2 = cd3TransformPoint(xf, c.p2);
	return c;
}

static inline cd3Box BoxIn(cd3Transform xf, cd3Box b)
{
	b.center = cd3TransformPoint(xf, b.center);
	b.rotation = cd3MulQuat(xf.q, b.rotation);
	return b;
}

static inline cd3HullShape HullIn(cd3Transform xf, cd3HullShape h)
{
	h.transform = cd3MulTransforms(xf, h.transform);
	return h;
}

static inline cd3Triangle TriangleIn(cd3Transform xf, cd3Triangle t)
{
	t.a = cd3TransformPoint(xf, t.a);
	t.b = cd3TransformPoint(xf, t.b);
	t.c = cd3TransformPoint(xf, t.c);
	return t;
}

cd3Manifold cd3CollideSphereSphereLocal(cd3Sphere a, cd3Sphere b, cd3Transform xfB,
										cdReal speculativeDistance)
{
	return cd3CollideSphereSphere(a, SphereIn(xfB, b), speculativeDistance);
}

cd3Manifold cd3CollideSphereCapsuleLocal(cd3Sphere a, cd3Capsule b, cd3Transform xfB,
										 cdReal speculativeDistance)
{
	return cd3CollideSphereCapsule(a, CapsuleIn(xfB, b), speculativeDistance);
}

cd3Manifold cd3CollideSphereBoxLocal(cd3Sphere a, cd3Box b, cd3Transform xfB, cdReal speculativeDistance)
{
	return cd3CollideSphereBox(a, BoxIn(xfB, b), speculativeDistance);
}

cd3Manifold cd3CollideSphereHullLocal(cd3Sphere a, cd3HullShape b, cd3Transform xfB,
									  cdReal speculativeDistance)
{
	return cd3CollideSphereHull(a, HullIn(xfB, b), speculativeDistance);
}

cd3Manifold cd3CollideSphereTriangleLocal(cd3Sphere a, cd3Triangle b, cd3Transform xfB,
										  cdReal speculativeDistance)
{
	return cd3CollideSphereTriangle(a, TriangleIn(xfB, b), speculativeDistance);
}

cd3Manifold cd3CollideCapsuleCapsuleLocal(cd3Capsule a, cd3Capsule b, cd3Transform xfB,
										  cdReal speculativeDistance)
{
	return cd3CollideCapsuleCapsule(a, CapsuleIn(xfB, b), speculativeDistance);
}

cd3Manifold cd3CollideCapsuleBoxLocal(cd3Capsule a, cd3Box b, cd3Transform xfB, cdReal speculativeDistance)
{
	return cd3CollideCapsuleBox(a, BoxIn(xfB, b), speculativeDistance);
}

cd3Manifold cd3CollideCapsuleHullLocal(cd3Capsule a, cd3HullShape b, cd3Transform xfB,
									   cdReal speculativeDistance)
{
	return cd3CollideCapsuleHull(a, HullIn(xfB, b), speculativeDistance);
}

cd3Manifold cd3CollideCapsuleTriangleLocal(cd3Capsule a, cd3Triangle b, cd3Transform xfB,
										   cdReal speculativeDistance)
{
	return cd3CollideCapsuleTriangle(a, TriangleIn(xfB, b), speculativeDistance);
}

/* cd3CollideBoxBoxLocal: in manifold3.c, next to the box-box manifold. */

cd3Manifold cd3CollideBoxHullLocal(cd3Box a, cd3HullShape b, cd3Transform xfB, cdReal speculativeDistance)
{
	return cd3CollideBoxHull(a, HullIn(xfB, b), speculativeDistance);
}

cd3Manifold cd3CollideBoxTriangleLocal(cd3Box a, cd3Triangle b, cd3Transform xfB, cdReal speculativeDistance)
{
	return cd3CollideBoxTriangle(a, TriangleIn(xfB, b), speculativeDistance);
}

cd3Manifold cd3CollideHullHullLocal(cd3HullShape a, cd3HullShape b, cd3Transform xfB,
									cdReal speculativeDistance)
{
	return cd3CollideHullHull(a, HullIn(xfB, b), speculativeDistance);
}

/* The pair in canonical order (triangle first): the hull-triangle manifold with the opposite
 * normal, as cd3Collide reports a swapped pair (same points, separations and ids). */
cd3Manifold cd3CollideTriangleHull(cd3Triangle a, cd3HullShape b, cdReal speculativeDistance)
{
	cd3Manifold m = cd3CollideHullTriangle(b, a, speculativeDistance);
	m.normal = cd3Neg(m.normal);
	return m;
}

cd3Manifold cd3CollideTriangleHullLocal(cd3Triangle a, cd3HullShape b, cd3Transform xfB,
										cdReal speculativeDistance)
{
	return cd3CollideTriangleHull(a, HullIn(xfB, b), speculativeDistance);
}

cd3Manifold cd3CollideTriangleTriangleLocal(cd3Triangle a, cd3Triangle b, cd3Transform xfB,
											cdReal speculativeDistance)
{
	return cd3CollideTriangleTriangle(a, TriangleIn(xfB, b), speculativeDistance);
}

cd3Manifold cd3CollideLocal(const cd3Shape* a, const cd3Shape* b, cd3Transform xfB,
							cdReal speculativeDistance)
{
	CD_ASSERT(a != NULL && b != NULL);
	cd3Shape s = *b;
	switch (b->type)
	{
		case CD3_SHAPE_SPHERE:
			s.sphere = SphereIn(xfB, b->sphere);
			break;
		case CD3_SHAPE_CAPSULE:
			s.capsule = CapsuleIn(xfB, b->capsule);
			break;
		case CD3_SHAPE_AABB:
		{
			/* A rotated AABB is a box (cd3Collide reads an AABB as a box with identity rotation). */
			cd3Box box;
			box.center = cd3AabbCenter(b->aabb);
			box.halfExtents = cd3AabbHalfExtents(b->aabb);
			box.rotation = CD3_QUAT_IDENTITY;
			s.type = CD3_SHAPE_BOX;
			s.box = BoxIn(xfB, box);
			break;
		}
		case CD3_SHAPE_BOX:
			s.box = BoxIn(xfB, b->box);
			break;
		case CD3_SHAPE_TRIANGLE:
			s.triangle = TriangleIn(xfB, b->triangle);
			break;
		case CD3_SHAPE_HULL:
			s.hull = HullIn(xfB, b->hull);
			break;
		default:
			/* Planes and segments have no manifold: cd3Collide returns an empty one. */
			break;
	}
	return cd3Collide(a, &s, speculativeDistance);
}
