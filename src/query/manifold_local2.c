/* collide: 2D manifolds in A's frame (manifold2.h, "local-frame forms"). Shape B is moved into
 * A's frame on the stack and the world-space pair function runs on the result, so both forms give
 * the same answer by construction. One exception, for cost: a circle, capsule or chain segment
 * against a polygon moves the small shape into the polygon's frame instead (a few points rather
 * than up to 8 vertices and normals) and maps the manifold back, equal within round-off.
 * cd2CollideCirclePolygonLocal, cd2CollidePolygonCircleLocal and cd2CollidePolygonPolygonLocal,
 * the calls of a 2D step's commonest contacts, are in manifold2.c, next to the cores they run on. */
#include "collide/manifold2.h"

static inline cd2Circle CircleIn(cd2Transform xf, cd2Circle c)
{
	c.center = cd2TransformPoint(xf, c.center);
	return c;
}

static inline cd2Capsule CapsuleIn(cd2Transform xf, cd2Capsule c)
{
	c.p1 = cd2TransformPoint(xf, c.p1);
	c.p2 = cd2TransformPoint(xf, c.p2);
	return c;
}

static inline cd2Segment SegmentIn(cd2Transform xf, cd2Segment s)
{
	s.p1 = cd2TransformPoint(xf, s.p1);
	s.p2 = cd2TransformPoint(xf, s.p2);
	return s;
}

static inline void PolygonIn(cd2Polygon* out, cd2Transform xf, const cd2Polygon* p)
{
	int n = p->count;
	CD_ASSERT(0 <= n && n <= CD2_MAX_POLYGON_VERTICES);
	for (int i = 0; i < n; ++i)
	{
		out->vertices[i] = cd2TransformPoint(xf, p->vertices[i]);
		out->normals[i] = cd2RotateVector(xf.q, p->normals[i]);
	}
	out->centroid = cd2TransformPoint(xf, p->centroid);
	out->count = n;
	out->radius = p->radius;
}

/* The inverse of xf: the frame of A in B's frame. */
static inline cd2Transform Inverse(cd2Transform xf)
{
	cd2Transform inv;
	inv.q.c = xf.q.c;
	inv.q.s = -xf.q.s;
	inv.p = cd2Neg(cd2InvRotateVector(xf.q, xf.p));
	return inv;
}

static inline cd2ChainSegment ChainSegmentIn(cd2Transform xf, const cd2ChainSegment* c)
{
	cd2ChainSegment s;
	s.ghost1 = cd2TransformPoint(xf, c->ghost1);
	s.p1 = cd2TransformPoint(xf, c->p1);
	s.p2 = cd2TransformPoint(xf, c->p2);
	s.ghost2 = cd2TransformPoint(xf, c->ghost2);
	return s;
}

cd2Manifold cd2CollideCircleCircleLocal(cd2Circle a, cd2Circle b, cd2Transform xfB,
										cdReal speculativeDistance)
{
	return cd2CollideCircleCircle(a, CircleIn(xfB, b), speculativeDistance);
}

cd2Manifold cd2CollideCircleCapsuleLocal(cd2Circle a, cd2Capsule b, cd2Transform xfB,
										 cdReal speculativeDistance)
{
	return cd2CollideCircleCapsule(a, CapsuleIn(xfB, b), speculativeDistance);
}

cd2Manifold cd2CollideCircleSegmentLocal(cd2Circle a, cd2Segment b, cd2Transform xfB,
										 cdReal speculativeDistance)
{
	return cd2CollideCircleSegment(a, SegmentIn(xfB, b), speculativeDistance);
}

cd2Manifold cd2CollideCapsuleCapsuleLocal(cd2Capsule a, cd2Capsule b, cd2Transform xfB,
										  cdReal speculativeDistance)
{
	return cd2CollideCapsuleCapsule(a, CapsuleIn(xfB, b), speculativeDistance);
}

cd2Manifold cd2CollideCapsulePolygonLocal(cd2Capsule a, const cd2Polygon* b, cd2Transform xfB,
										  cdReal speculativeDistance)
{
	CD_ASSERT(b != NULL);
	return cd2TransformManifold(xfB,
								cd2CollideCapsulePolygon(CapsuleIn(Inverse(xfB), a), b, speculativeDistance));
}

cd2Manifold cd2CollideCapsuleSegmentLocal(cd2Capsule a, cd2Segment b, cd2Transform xfB,
										  cdReal speculativeDistance)
{
	return cd2CollideCapsuleSegment(a, SegmentIn(xfB, b), speculativeDistance);
}

cd2Manifold cd2CollidePolygonSegmentLocal(const cd2Polygon* a, cd2Segment b, cd2Transform xfB,
										  cdReal speculativeDistance)
{
	CD_ASSERT(a != NULL);
	return cd2CollidePolygonSegment(a, SegmentIn(xfB, b), speculativeDistance);
}

cd2Manifold cd2CollideSegmentSegmentLocal(cd2Segment a, cd2Segment b, cd2Transform xfB,
										  cdReal speculativeDistance)
{
	return cd2CollideSegmentSegment(a, SegmentIn(xfB, b), speculativeDistance);
}

cd2Manifold cd2CollideChainSegmentCircleLocal(const cd2ChainSegment* a, cd2Circle b, cd2Transform xfB,
											  cdReal speculativeDistance)
{
	CD_ASSERT(a != NULL);
	return cd2CollideChainSegmentCircle(a, CircleIn(xfB, b), speculativeDistance);
}

cd2Manifold cd2CollideChainSegmentCapsuleLocal(const cd2ChainSegment* a, cd2Capsule b, cd2Transform xfB,
											   cdReal speculativeDistance)
{
	CD_ASSERT(a != NULL);
	return cd2CollideChainSegmentCapsule(a, CapsuleIn(xfB, b), speculativeDistance);
}

cd2Manifold cd2CollideChainSegmentPolygonLocal(const cd2ChainSegment* a, const cd2Polygon* b,
											   cd2Transform xfB, cdReal speculativeDistance)
{
	CD_ASSERT(a != NULL && b != NULL);
	cd2ChainSegment c = ChainSegmentIn(Inverse(xfB), a);
	return cd2TransformManifold(xfB, cd2CollideChainSegmentPolygon(&c, b, speculativeDistance));
}

/* Out of line: inlined into cd2CollideLocal, its vectorized placements made GCC spill xfB on
 * entry and read it back 16 bytes at a time (a store-forwarding stall) before the type tests that
 * send the commonest pairs elsewhere. */
#if defined(__GNUC__) || defined(__clang__)
#define LOCAL_NOINLINE __attribute__((noinline))
#else
#define LOCAL_NOINLINE
#endif

static LOCAL_NOINLINE cd2Manifold CollidePlaced(const cd2Shape* a, const cd2Shape* b, cd2Transform xfB,
												cdReal speculativeDistance);

cd2Manifold cd2CollideLocal(const cd2Shape* a, const cd2Shape* b, cd2Transform xfB,
							cdReal speculativeDistance)
{
	CD_ASSERT(a != NULL && b != NULL);
	/* A 2D step's commonest contacts straight to their local-frame functions (the same answer as
	 * the general path, bit for bit, without building a placed shape). */
	if (b->type == CD2_SHAPE_POLYGON && a->type == CD2_SHAPE_POLYGON)
	{
		return cd2CollidePolygonPolygonLocal(&a->polygon, &b->polygon, xfB, speculativeDistance);
	}
	if (b->type == CD2_SHAPE_POLYGON && a->type == CD2_SHAPE_CIRCLE)
	{
		return cd2CollideCirclePolygonLocal(a->circle, &b->polygon, xfB, speculativeDistance);
	}
	if (a->type == CD2_SHAPE_POLYGON && b->type == CD2_SHAPE_CIRCLE)
	{
		/* The same contact bit for bit as cd2Collide on the placed circle (the circle-polygon core,
		 * normal flipped); an empty manifold's zero normal is +0 where the flip made it -0. */
		return cd2CollidePolygonCircleLocal(&a->polygon, b->circle, xfB, speculativeDistance);
	}
	return CollidePlaced(a, b, xfB, speculativeDistance);
}

static cd2Manifold CollidePlaced(const cd2Shape* a, const cd2Shape* b, cd2Transform xfB,
								 cdReal speculativeDistance)
{
	cd2Shape s;
	if (b->type == CD2_SHAPE_POLYGON &&
		(a->type == CD2_SHAPE_CIRCLE || a->type == CD2_SHAPE_CAPSULE || a->type == CD2_SHAPE_SEGMENT))
	{
		/* The small shape A into the polygon's frame (see the top of the file). */
		cd2Transform inv = Inverse(xfB);
		s.type = a->type;
		if (a->type == CD2_SHAPE_CIRCLE)
		{
			s.circle = CircleIn(inv, a->circle);
		}
		else if (a->type == CD2_SHAPE_CAPSULE)
		{
			s.capsule = CapsuleIn(inv, a->capsule);
		}
		else
		{
			s.segment = SegmentIn(inv, a->segment);
		}
		return cd2TransformManifold(xfB, cd2Collide(&s, b, speculativeDistance));
	}
	s.type = b->type;
	switch (b->type)
	{
		case CD2_SHAPE_CIRCLE:
			s.circle = CircleIn(xfB, b->circle);
			break;
		case CD2_SHAPE_CAPSULE:
			s.capsule = CapsuleIn(xfB, b->capsule);
			break;
		case CD2_SHAPE_AABB:
			/* A rotated AABB is a box: the same rectangle core, so the same feature ids. */
			s.type = CD2_SHAPE_BOX;
			s.box.center = cd2TransformPoint(xfB, cd2AabbCenter(b->aabb));
			s.box.halfExtents = cd2AabbHalfExtents(b->aabb);
			s.box.rotation = xfB.q;
			break;
		case CD2_SHAPE_BOX:
			s.box.center = cd2TransformPoint(xfB, b->box.center);
			s.box.halfExtents = b->box.halfExtents;
			s.box.rotation = cd2MulRot(xfB.q, b->box.rotation);
			break;
		case CD2_SHAPE_POLYGON:
			PolygonIn(&s.polygon, xfB, &b->polygon);
			break;
		default:
			s.segment = SegmentIn(xfB, b->segment);
			break;
	}
	return cd2Collide(a, &s, speculativeDistance);
}
