/* collide: queries on a 2D world: shapes in a box, shapes overlapping a shape, ray casts (closest
 * or all, with a callback) and shape casts, all through the broadphase tree and with a category
 * filter. Queries read the world only; they may run from any thread while no step runs. */
#include "world2_internal.h"

cd2QueryFilter cd2DefaultQueryFilter(void)
{
	cd2QueryFilter filter = {1u, UINT64_MAX};
	return filter;
}

static bool cd2QueryAccepts(const cd2WorldShape* shape, cd2QueryFilter filter)
{
	return (shape->filter.categoryBits & filter.maskBits) != 0 &&
		   (shape->filter.maskBits & filter.categoryBits) != 0;
}

typedef struct cd2OverlapContext
{
	cd2World* world;
	cd2QueryFilter filter;
	cd2Aabb aabb;
	const cd2Shape* shape; /* NULL: box query */
	cd2OverlapResultFcn* fcn;
	void* userContext;
} cd2OverlapContext;

static bool cd2OverlapCallback(int proxyId, uint64_t userData, void* context)
{
	(void)proxyId;
	cd2OverlapContext* c = (cd2OverlapContext*)context;
	int index = cd2ProxyShape(userData);
	const cd2WorldShape* shape = c->world->shapes.data + index;
	if (!cd2QueryAccepts(shape, c->filter))
	{
		return true;
	}
	cd2Transform xf = c->world->bodies.data[shape->body].transform;
	if (c->shape == NULL)
	{
		if (!cd2OverlapAabbAabb(cd2ComputeWorldShapeAabb(shape, xf), c->aabb))
		{
			return true;
		}
	}
	else
	{
		cd2Shape tagged = cd2MakeTaggedShape(shape, xf);
		if (!cd2Overlap(c->shape, &tagged))
		{
			return true;
		}
	}
	return c->fcn(cd2MakeShapeId(c->world, index), c->userContext);
}

static cd2World* cd2QueryWorld(cd2WorldId worldId)
{
	cd2World* world = cd2GetWorld(worldId);
	if (world != NULL && world->locked)
	{
		CD2_REFUSE("world queries are not allowed during the step");
		return NULL;
	}
	return world;
}

void cd2World_OverlapAabb(cd2WorldId worldId, cd2Aabb aabb, cd2QueryFilter filter, cd2OverlapResultFcn* fcn,
						  void* context)
{
	cd2World* world = cd2QueryWorld(worldId);
	if (world == NULL || fcn == NULL || !cd2IsValidAabb(aabb))
	{
		return;
	}
	cd2OverlapContext c = {world, filter, aabb, NULL, fcn, context};
	cd2BroadPhase_Query(world->broadPhase, aabb, cd2OverlapCallback, &c);
}

void cd2World_OverlapShape(cd2WorldId worldId, const cd2Shape* shape, cd2QueryFilter filter,
						   cd2OverlapResultFcn* fcn, void* context)
{
	cd2World* world = cd2QueryWorld(worldId);
	if (world == NULL || fcn == NULL || shape == NULL || !cd2IsValidShape(shape))
	{
		return;
	}
	cd2Aabb aabb = cd2ComputeShapeAabb(shape);
	cd2OverlapContext c = {world, filter, aabb, shape, fcn, context};
	cd2BroadPhase_Query(world->broadPhase, aabb, cd2OverlapCallback, &c);
}

typedef struct cd2RayContext
{
	cd2World* world;
	cd2QueryFilter filter;
	cd2CastResultFcn* fcn;
	void* userContext;
} cd2RayContext;

static cdReal cd2RayCallback(cd2Ray ray, cdReal maxFraction, int proxyId, uint64_t userData, void* context)
{
	(void)proxyId;
	cd2RayContext* c = (cd2RayContext*)context;
	int index = cd2ProxyShape(userData);
	const cd2WorldShape* shape = c->world->shapes.data + index;
	if (shape->isSensor || !cd2QueryAccepts(shape, c->filter))
	{
		return -CD_R(1.0);
	}
	cd2Transform xf = c->world->bodies.data[shape->body].transform;
	cd2Shape tagged = cd2MakeTaggedShape(shape, xf);
	cd2Ray clipped = {ray.origin, cd2Scale(maxFraction, ray.translation)};
	cd2RayHit hit;
	if (!cd2Raycast(&tagged, clipped, &hit))
	{
		return -CD_R(1.0);
	}
	if (shape->type == CD2_WORLD_SHAPE_CHAIN_SEGMENT)
	{
		/* One-sided: only from the free side. */
		cd2Vec front = cd2RightPerp(cd2Sub(tagged.segment.p2, tagged.segment.p1));
		if (cd2Dot(front, ray.translation) >= CD_R(0.0))
		{
			return -CD_R(1.0);
		}
		hit.normal = cd2Normalize(front);
	}
	cdReal fraction = hit.fraction * maxFraction;
	cdReal answer = c->fcn(cd2MakeShapeId(c->world, index), hit.point, hit.normal, fraction, c->userContext);
	return answer > maxFraction ? maxFraction : answer;
}

void cd2World_Raycast(cd2WorldId worldId, cd2Vec origin, cd2Vec translation, cd2QueryFilter filter,
					  cd2CastResultFcn* fcn, void* context)
{
	cd2World* world = cd2QueryWorld(worldId);
	if (world == NULL || fcn == NULL || !cd2IsValidVec(origin) || !cd2IsValidVec(translation))
	{
		return;
	}
	cd2RayContext c = {world, filter, fcn, context};
	cd2Ray ray = {origin, translation};
	cd2BroadPhase_RayCast(world->broadPhase, ray, cd2RayCallback, &c);
}

static cdReal cd2ClosestCallback(cd2ShapeId shapeId, cd2Vec point, cd2Vec normal, cdReal fraction,
								 void* context)
{
	cd2RayResult* result = (cd2RayResult*)context;
	result->shapeId = shapeId;
	result->point = point;
	result->normal = normal;
	result->fraction = fraction;
	result->hit = true;
	return fraction;
}

cd2RayResult cd2World_RaycastClosest(cd2WorldId worldId, cd2Vec origin, cd2Vec translation,
									 cd2QueryFilter filter)
{
	cd2RayResult result;
	memset(&result, 0, sizeof(result));
	result.fraction = CD_R(1.0);
	cd2World_Raycast(worldId, origin, translation, filter, cd2ClosestCallback, &result);
	return result;
}

typedef struct cd2ShapeCastContext
{
	cd2World* world;
	cd2QueryFilter filter;
	const cd2Shape* shape;
	cd2Vec translation;
	cdReal maxFraction;
	bool stop;
	cd2CastResultFcn* fcn;
	void* userContext;
} cd2ShapeCastContext;

static bool cd2ShapeCastCallback(int proxyId, uint64_t userData, void* context)
{
	(void)proxyId;
	cd2ShapeCastContext* c = (cd2ShapeCastContext*)context;
	int index = cd2ProxyShape(userData);
	const cd2WorldShape* shape = c->world->shapes.data + index;
	if (shape->isSensor || !cd2QueryAccepts(shape, c->filter))
	{
		return true;
	}
	cd2Shape tagged = cd2MakeTaggedShape(shape, c->world->bodies.data[shape->body].transform);
	cd2CastOutput out = cd2ShapeCast(c->shape, &tagged, cd2Scale(c->maxFraction, c->translation));
	if (!out.hit)
	{
		return true;
	}
	cdReal fraction = out.fraction * c->maxFraction;
	cdReal answer = c->fcn(cd2MakeShapeId(c->world, index), out.point, out.normal, fraction, c->userContext);
	if (answer == CD_R(0.0))
	{
		c->stop = true;
		return false;
	}
	if (answer > CD_R(0.0) && answer < c->maxFraction)
	{
		c->maxFraction = answer;
	}
	return true;
}

void cd2World_ShapeCast(cd2WorldId worldId, const cd2Shape* shape, cd2Vec translation, cd2QueryFilter filter,
						cd2CastResultFcn* fcn, void* context)
{
	cd2World* world = cd2QueryWorld(worldId);
	if (world == NULL || fcn == NULL || shape == NULL || !cd2IsValidShape(shape) ||
		!cd2IsValidVec(translation))
	{
		return;
	}
	cd2Aabb start = cd2ComputeShapeAabb(shape);
	cd2Aabb end = {cd2Add(start.min, translation), cd2Add(start.max, translation)};
	cd2ShapeCastContext c = {world, filter, shape, translation, CD_R(1.0), false, fcn, context};
	cd2BroadPhase_Query(world->broadPhase, cd2AabbUnion(start, end), cd2ShapeCastCallback, &c);
}
