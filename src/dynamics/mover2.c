/* collide: the kinematic character mover of the 2D world: contact planes around a capsule, a
 * capsule cast along a path, and the two small solvers that turn planes into a sliding motion. */
#include "world2_internal.h"

static bool cd2MoverAccepts(const cd2WorldShape* shape, cd2QueryFilter filter)
{
	return !shape->isSensor && (shape->filter.categoryBits & filter.maskBits) != 0 &&
		   (shape->filter.maskBits & filter.categoryBits) != 0;
}

typedef struct cd2MoverContext
{
	cd2World* world;
	cd2Capsule mover;
	cd2QueryFilter filter;
	cd2PlaneResultFcn* fcn;
	void* userContext;
	cd2Vec translation;
	cdReal fraction;
} cd2MoverContext;

static bool cd2CollideMoverCallback(int proxyId, uint64_t userData, void* context)
{
	(void)proxyId;
	cd2MoverContext* c = (cd2MoverContext*)context;
	int index = cd2ProxyShape(userData);
	const cd2WorldShape* shape = c->world->shapes.data + index;
	if (!cd2MoverAccepts(shape, c->filter))
	{
		return true;
	}
	cd2Transform xf = c->world->bodies.data[shape->body].transform;
	cd2Manifold m;
	if (shape->type == CD2_WORLD_SHAPE_CHAIN_SEGMENT)
	{
		const cd2ChainSegment* local = &shape->geometry.chainSegment;
		cd2ChainSegment segment = {cd2TransformPoint(xf, local->ghost1), cd2TransformPoint(xf, local->p1),
								   cd2TransformPoint(xf, local->p2), cd2TransformPoint(xf, local->ghost2)};
		m = cd2CollideChainSegmentCapsule(&segment, c->mover, CD_SPECULATIVE_DISTANCE);
	}
	else
	{
		cd2Shape a = cd2MakeTaggedShape(shape, xf);
		cd2Shape b = cd2MakeCapsuleShape(c->mover);
		m = cd2Collide(&a, &b, CD_SPECULATIVE_DISTANCE);
	}
	if (m.pointCount == 0)
	{
		return true;
	}
	cd2PlaneResult plane;
	plane.shapeId = cd2MakeShapeId(c->world, index);
	plane.normal = m.normal;
	int deepest = (m.pointCount == 2 && m.points[1].separation < m.points[0].separation) ? 1 : 0;
	plane.separation = m.points[deepest].separation;
	plane.point = m.points[deepest].point;
	return c->fcn(&plane, c->userContext);
}

void cd2World_CollideMover(cd2WorldId worldId, const cd2Capsule* mover, cd2QueryFilter filter,
						   cd2PlaneResultFcn* fcn, void* context)
{
	cd2World* world = cd2GetWorld(worldId);
	if (world == NULL || mover == NULL || fcn == NULL)
	{
		return;
	}
	if (world->locked || !cd2IsValidCapsule(*mover))
	{
		CD2_REFUSE("cd2World_CollideMover: invalid capsule or locked world");
		return;
	}
	cd2MoverContext c = {world, *mover, filter, fcn, context, CD2_VEC_ZERO, CD_R(1.0)};
	cd2Aabb box = cd2AabbInflate(cd2ComputeCapsuleAabb(*mover), CD_SPECULATIVE_DISTANCE);
	cd2BroadPhase_Query(world->broadPhase, box, cd2CollideMoverCallback, &c);
}

static bool cd2CastMoverCallback(int proxyId, uint64_t userData, void* context)
{
	(void)proxyId;
	cd2MoverContext* c = (cd2MoverContext*)context;
	int index = cd2ProxyShape(userData);
	const cd2WorldShape* shape = c->world->shapes.data + index;
	if (!cd2MoverAccepts(shape, c->filter))
	{
		return true;
	}
	cd2Transform xf = c->world->bodies.data[shape->body].transform;
	cd2Shape other = cd2MakeTaggedShape(shape, xf);
	cd2Shape moving = cd2MakeCapsuleShape(c->mover);
	if (shape->type == CD2_WORLD_SHAPE_CHAIN_SEGMENT)
	{
		/* One-sided: a mover behind the segment or moving away from its front passes. */
		cd2Vec front = cd2RightPerp(cd2Sub(other.segment.p2, other.segment.p1));
		cd2Vec center = cd2Lerp(c->mover.p1, c->mover.p2, CD_R(0.5));
		if (cd2Dot(front, cd2Sub(center, other.segment.p1)) < CD_R(0.0) ||
			cd2Dot(front, c->translation) >= CD_R(0.0))
		{
			return true;
		}
	}
	cd2CastOutput out = cd2ShapeCast(&moving, &other, c->translation);
	/* Shapes it already touches are the planes' business, not the cast's. */
	if (out.hit && out.fraction > CD_R(0.0) && out.fraction < c->fraction)
	{
		c->fraction = out.fraction;
	}
	return true;
}

cdReal cd2World_CastMover(cd2WorldId worldId, const cd2Capsule* mover, cd2Vec translation,
						  cd2QueryFilter filter)
{
	cd2World* world = cd2GetWorld(worldId);
	if (world == NULL || mover == NULL)
	{
		return CD_R(0.0);
	}
	if (world->locked || !cd2IsValidCapsule(*mover) || !cd2IsValidVec(translation))
	{
		CD2_REFUSE("cd2World_CastMover: invalid capsule or translation, or locked world");
		return CD_R(0.0);
	}
	cd2MoverContext c = {world, *mover, filter, NULL, NULL, translation, CD_R(1.0)};
	cd2Aabb start = cd2ComputeCapsuleAabb(*mover);
	cd2Aabb end = {cd2Add(start.min, translation), cd2Add(start.max, translation)};
	cd2BroadPhase_Query(world->broadPhase, cd2AabbUnion(start, end), cd2CastMoverCallback, &c);
	return c.fraction;
}

cd2Vec cd2SolvePlanes(cd2Vec targetDelta, const cd2PlaneResult* planes, int count)
{
	cd2Vec delta = targetDelta;
	if (planes == NULL || count <= 0)
	{
		return delta;
	}
	/* Gauss-Seidel over the planes: push out of each violated one along its normal. Corners (a
	 * floor and a wall) converge in a few sweeps; the cap keeps it bounded. */
	for (int iteration = 0; iteration < 20; ++iteration)
	{
		cdReal worst = CD_R(0.0);
		for (int i = 0; i < count; ++i)
		{
			cdReal s = planes[i].separation + cd2Dot(planes[i].normal, delta);
			if (s < CD_R(0.0))
			{
				delta = cd2MulSub(delta, s, planes[i].normal);
				worst = cdMin(worst, s);
			}
		}
		if (worst > -CD_R(0.01) * CD_LINEAR_SLOP)
		{
			break;
		}
	}
	return delta;
}

cd2Vec cd2ClipVector(cd2Vec vector, const cd2PlaneResult* planes, int count)
{
	cd2Vec v = vector;
	for (int i = 0; planes != NULL && i < count; ++i)
	{
		if (planes[i].separation > CD_LINEAR_SLOP)
		{
			continue;
		}
		cdReal d = cd2Dot(v, planes[i].normal);
		if (d < CD_R(0.0))
		{
			v = cd2MulSub(v, d, planes[i].normal);
		}
	}
	return v;
}
