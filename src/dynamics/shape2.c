/* collide: shapes on 2D bodies (circle, capsule, polygon, segment, chain segments): creation,
 * bounds and the broadphase proxy, filters, properties. Geometry is kept in the body frame. */
#include "world2_internal.h"

cd2WorldShape* cd2GetShape(cd2World* world, cd2ShapeId id)
{
	if (world == NULL || id.index1 <= 0 || id.index1 > world->shapes.count)
	{
		return NULL;
	}
	cd2WorldShape* shape = world->shapes.data + (id.index1 - 1);
	if (!shape->inUse || shape->generation != id.generation)
	{
		return NULL;
	}
	return shape;
}

cd2ShapeId cd2MakeShapeId(const cd2World* world, int index)
{
	cd2ShapeId id = {index + 1, world->index, world->shapes.data[index].generation};
	return id;
}

static cd2WorldShape* cd2LookupShape(cd2ShapeId id, cd2World** outWorld, bool mutating)
{
	cd2World* world = cd2GetWorldFromIndex(id.world0);
	cd2WorldShape* shape = cd2GetShape(world, id);
	if (shape == NULL)
	{
		CD2_REFUSE("stale or null shape id");
		return NULL;
	}
	if (mutating && world->locked)
	{
		CD2_REFUSE("the world is locked during the step");
		return NULL;
	}
	*outWorld = world;
	return shape;
}

cd2Filter cd2DefaultFilter(void)
{
	cd2Filter filter = {1u, UINT64_MAX, 0};
	return filter;
}

cd2ShapeDef cd2DefaultShapeDef(void)
{
	cd2ShapeDef def;
	memset(&def, 0, sizeof(def));
	def.density = CD_R(1.0);
	def.friction = CD_R(0.6);
	def.filter = cd2DefaultFilter();
	def.enableSensorEvents = true;
	def.enableContactEvents = true;
	return def;
}

bool cd2ShouldShapesCollide(cd2Filter a, cd2Filter b)
{
	if (a.groupIndex == b.groupIndex && a.groupIndex != 0)
	{
		return a.groupIndex > 0;
	}
	return (a.maskBits & b.categoryBits) != 0 && (a.categoryBits & b.maskBits) != 0;
}

static cd2Polygon cd2TransformPolygon(const cd2Polygon* p, cd2Transform xf)
{
	cd2Polygon out = *p;
	for (int i = 0; i < p->count; ++i)
	{
		out.vertices[i] = cd2TransformPoint(xf, p->vertices[i]);
		out.normals[i] = cd2RotateVector(xf.q, p->normals[i]);
	}
	out.centroid = cd2TransformPoint(xf, p->centroid);
	return out;
}

cd2Shape cd2MakeTaggedShape(const cd2WorldShape* shape, cd2Transform xf)
{
	/* Only the member of the shape's type is written: this runs twice per contact per step, and
	 * clearing the whole union (a polygon's size) cost more than the transform. */
	cd2Shape out;
	out.type = CD2_SHAPE_CIRCLE;
	switch (shape->type)
	{
		case CD2_WORLD_SHAPE_CIRCLE:
			out.type = CD2_SHAPE_CIRCLE;
			out.circle.center = cd2TransformPoint(xf, shape->geometry.circle.center);
			out.circle.radius = shape->geometry.circle.radius;
			break;
		case CD2_WORLD_SHAPE_CAPSULE:
			out.type = CD2_SHAPE_CAPSULE;
			out.capsule.p1 = cd2TransformPoint(xf, shape->geometry.capsule.p1);
			out.capsule.p2 = cd2TransformPoint(xf, shape->geometry.capsule.p2);
			out.capsule.radius = shape->geometry.capsule.radius;
			break;
		case CD2_WORLD_SHAPE_POLYGON:
			out.type = CD2_SHAPE_POLYGON;
			out.polygon = cd2TransformPolygon(&shape->geometry.polygon, xf);
			break;
		case CD2_WORLD_SHAPE_SEGMENT:
			out.type = CD2_SHAPE_SEGMENT;
			out.segment.p1 = cd2TransformPoint(xf, shape->geometry.segment.p1);
			out.segment.p2 = cd2TransformPoint(xf, shape->geometry.segment.p2);
			break;
		case CD2_WORLD_SHAPE_CHAIN_SEGMENT:
			out.type = CD2_SHAPE_SEGMENT;
			out.segment.p1 = cd2TransformPoint(xf, shape->geometry.chainSegment.p1);
			out.segment.p2 = cd2TransformPoint(xf, shape->geometry.chainSegment.p2);
			break;
	}
	return out;
}

cd2Aabb cd2ComputeWorldShapeAabb(const cd2WorldShape* shape, cd2Transform xf)
{
	if (shape->type == CD2_WORLD_SHAPE_POLYGON)
	{
		/* The vertices only (the same bits as the transformed polygon's box, without moving the
		 * normals and the centroid): this runs for every awake shape every step. */
		const cd2Polygon* p = &shape->geometry.polygon;
		cd2Vec v = cd2TransformPoint(xf, p->vertices[0]);
		cd2Aabb aabb = {v, v};
		for (int i = 1; i < p->count; ++i)
		{
			v = cd2TransformPoint(xf, p->vertices[i]);
			aabb.min = cd2Min(aabb.min, v);
			aabb.max = cd2Max(aabb.max, v);
		}
		return cd2AabbInflate(aabb, p->radius);
	}
	/* The round shapes and segments also skip the tagged copy and the dispatch; each case gives the
	 * bits of cd2ComputeShapeAabb on the transformed shape. */
	cd2Vec p1;
	cd2Vec p2;
	cdReal radius = CD_R(0.0);
	switch (shape->type)
	{
		case CD2_WORLD_SHAPE_CIRCLE:
		{
			cd2Vec c = cd2TransformPoint(xf, shape->geometry.circle.center);
			cd2Vec r = {shape->geometry.circle.radius, shape->geometry.circle.radius};
			cd2Aabb aabb = {cd2Sub(c, r), cd2Add(c, r)};
			return aabb;
		}
		case CD2_WORLD_SHAPE_CAPSULE:
			p1 = shape->geometry.capsule.p1;
			p2 = shape->geometry.capsule.p2;
			radius = shape->geometry.capsule.radius;
			break;
		case CD2_WORLD_SHAPE_SEGMENT:
			p1 = shape->geometry.segment.p1;
			p2 = shape->geometry.segment.p2;
			break;
		case CD2_WORLD_SHAPE_CHAIN_SEGMENT:
			p1 = shape->geometry.chainSegment.p1;
			p2 = shape->geometry.chainSegment.p2;
			break;
		default:
		{
			cd2Shape tagged = cd2MakeTaggedShape(shape, xf);
			return cd2ComputeShapeAabb(&tagged);
		}
	}
	p1 = cd2TransformPoint(xf, p1);
	p2 = cd2TransformPoint(xf, p2);
	cd2Aabb aabb = {cd2Min(p1, p2), cd2Max(p1, p2)};
	if (shape->type == CD2_WORLD_SHAPE_CAPSULE)
	{
		cd2Vec r = {radius, radius};
		aabb.min = cd2Sub(aabb.min, r);
		aabb.max = cd2Add(aabb.max, r);
	}
	return aabb;
}

/* The fat-box margin of a moving shape: a fraction of its size, at most CD2_AABB_MARGIN. The
 * margin spares the broadphase a move while the shape jiggles in place, but every pair of fat
 * boxes that overlap is a contact the narrowphase updates each step; a margin as large as a small
 * shape itself keeps two to three times the contacts of the shapes that really are close. */
static cdReal cd2ShapeAabbMargin(const cd2WorldShape* shape)
{
	cdReal extent = CD_R(0.0);
	switch (shape->type)
	{
		case CD2_WORLD_SHAPE_CIRCLE:
			extent = shape->geometry.circle.radius;
			break;
		case CD2_WORLD_SHAPE_CAPSULE:
			extent = CD_R(0.5) * cd2Length(cd2Sub(shape->geometry.capsule.p2, shape->geometry.capsule.p1)) +
					 shape->geometry.capsule.radius;
			break;
		case CD2_WORLD_SHAPE_POLYGON:
		{
			const cd2Polygon* polygon = &shape->geometry.polygon;
			cdReal far2 = CD_R(0.0);
			for (int i = 0; i < polygon->count; ++i)
			{
				cd2Vec d = cd2Sub(polygon->vertices[i], polygon->centroid);
				far2 = cdMax(far2, cd2Dot(d, d));
			}
			extent = cdSqrt(far2) + polygon->radius;
			break;
		}
		case CD2_WORLD_SHAPE_SEGMENT:
			extent = CD_R(0.5) * cd2Length(cd2Sub(shape->geometry.segment.p2, shape->geometry.segment.p1));
			break;
		case CD2_WORLD_SHAPE_CHAIN_SEGMENT:
			extent = CD_R(0.5) *
					 cd2Length(cd2Sub(shape->geometry.chainSegment.p2, shape->geometry.chainSegment.p1));
			break;
	}
	return cdMin(CD2_AABB_MARGIN, CD2_AABB_MARGIN_FRACTION * extent);
}

cd2Aabb cd2ComputeShapeBounds(const cd2World* world, const cd2WorldShape* shape)
{
	const cd2Body* body = world->bodies.data + shape->body;
	cd2Aabb aabb = cd2ComputeWorldShapeAabb(shape, body->transform);
	aabb = cd2AabbInflate(aabb, CD_SPECULATIVE_DISTANCE);
	if (body->isBullet && body->type != CD_STATIC_BODY && world->stepTimeStep > CD_R(0.0))
	{
		/* A bullet reaches where it will be next step, so its contacts with moving bodies exist
		 * before it gets there (continuous collision stops it in front of them). Other bodies do
		 * not: the reach made every moving body's fat box overlap neighbours it could not touch, and
		 * their contacts rely on the speculative margin and, against static shapes, on continuous
		 * collision. */
		cd2Vec d = cd2Scale(world->stepTimeStep, body->linearVelocity);
		cd2Aabb ahead = {cd2Add(aabb.min, d), cd2Add(aabb.max, d)};
		aabb = cd2AabbUnion(aabb, ahead);
	}
	return aabb;
}

bool cd2ShapeProxyNeedsSync(const cd2WorldShape* shape)
{
	return shape->proxyId == CD_NULL_PROXY || !cd2AabbContains(shape->fatAabb, shape->aabb);
}

void cd2DestroyShapeProxy(cd2World* world, cd2WorldShape* shape)
{
	if (shape->proxyId == CD_NULL_PROXY)
	{
		return;
	}
	if ((cd2BroadPhase_GetUserData(world->broadPhase, shape->proxyId) & CD2_PROXY_STATIC) != 0u)
	{
		world->staticProxyCount -= 1;
	}
	cd2BroadPhase_DestroyProxy(world->broadPhase, shape->proxyId);
	shape->proxyId = CD_NULL_PROXY;
	if (shape->staticProxyId != CD_NULL_PROXY)
	{
		cd2BroadPhase_DestroyProxy(world->staticBroadPhase, shape->staticProxyId);
		shape->staticProxyId = CD_NULL_PROXY;
	}
}

/* The static shape's proxy in the static broadphase, with its fat box of the main one (made anew:
 * a static shape rarely moves). */
static void cd2SyncStaticProxy(cd2World* world, int shapeIndex)
{
	cd2WorldShape* shape = world->shapes.data + shapeIndex;
	if (shape->staticProxyId != CD_NULL_PROXY)
	{
		cd2BroadPhase_DestroyProxy(world->staticBroadPhase, shape->staticProxyId);
	}
	shape->staticProxyId = cd2BroadPhase_CreateProxy(world->staticBroadPhase, shape->fatAabb,
													 cd2ProxyUserData(shapeIndex, true));
	if (shape->staticProxyId == CD_NULL_PROXY)
	{
		world->outOfMemory = true;
	}
}

cd2Aabb cd2ComputeShapeFatBox(const cd2World* world, const cd2WorldShape* shape)
{
	const cd2Body* body = world->bodies.data + shape->body;
	cdReal margin = body->type == CD_STATIC_BODY ? CD_R(0.0) : cd2ShapeAabbMargin(shape);
	return cd2AabbInflate(shape->aabb, margin);
}

void cd2SyncShapeProxyTo(cd2World* world, int shapeIndex, cd2Aabb fat)
{
	cd2WorldShape* shape = world->shapes.data + shapeIndex;
	if (cd2BroadPhase_MoveProxy(world->broadPhase, shape->proxyId, fat, CD2_VEC_ZERO))
	{
		shape->fatAabb = fat;
	}
	else if (!cd2AabbContains(shape->fatAabb, shape->aabb))
	{
		world->outOfMemory = true;
	}
	else
	{
		/* A same-size fat box is not a move for the broadphase; keep its box and ours equal. */
		shape->fatAabb = cd2BroadPhase_GetFatAabb(world->broadPhase, shape->proxyId);
	}
	if (shape->staticProxyId != CD_NULL_PROXY)
	{
		cd2SyncStaticProxy(world, shapeIndex);
	}
}

void cd2SyncShapeProxy(cd2World* world, int shapeIndex, bool forceMove)
{
	cd2WorldShape* shape = world->shapes.data + shapeIndex;
	cd2Aabb aabb = shape->aabb;
	if (shape->proxyId == CD_NULL_PROXY)
	{
		shape->fatAabb = cd2ComputeShapeFatBox(world, shape);
		bool isStatic = world->bodies.data[shape->body].type == CD_STATIC_BODY;
		shape->proxyId = cd2BroadPhase_CreateProxy(world->broadPhase, shape->fatAabb,
												   cd2ProxyUserData(shapeIndex, isStatic));
		if (shape->proxyId == CD_NULL_PROXY)
		{
			world->outOfMemory = true;
		}
		else if (isStatic)
		{
			world->staticProxyCount += 1;
			cd2SyncStaticProxy(world, shapeIndex);
		}
		return;
	}
	if (forceMove || !cd2AabbContains(shape->fatAabb, aabb))
	{
		cd2SyncShapeProxyTo(world, shapeIndex, cd2ComputeShapeFatBox(world, shape));
	}
}

void cd2UpdateShapeBounds(cd2World* world, int shapeIndex, bool forceMove)
{
	cd2WorldShape* shape = world->shapes.data + shapeIndex;
	shape->aabb = cd2ComputeShapeBounds(world, shape);
	if (world->bodies.data[shape->body].enabled)
	{
		cd2SyncShapeProxy(world, shapeIndex, forceMove);
	}
}

static bool cd2IsValidShapeDef(const cd2ShapeDef* def)
{
	return def != NULL && cdIsValidReal(def->density) && def->density >= CD_R(0.0) &&
		   cdIsValidReal(def->friction) && def->friction >= CD_R(0.0) && cdIsValidReal(def->restitution) &&
		   def->restitution >= CD_R(0.0) && cdIsValidReal(def->rollingResistance) &&
		   def->rollingResistance >= CD_R(0.0) && cdIsValidReal(def->tangentSpeed);
}

/* Allocates a shape on the body with the def's properties; the geometry is filled by the caller. */
static int cd2AddShape(cd2World* world, int bodyIndex, const cd2ShapeDef* def, cd2WorldShapeType type)
{
	int index = cdIdPool_Alloc(&world->shapePool);
	if (index < 0 || !cdArrayReserveFor(world->shapes, index + 1))
	{
		if (index >= 0)
		{
			cdIdPool_Free(&world->shapePool, index);
		}
		return CD2_NULL_INDEX;
	}
	if (index >= world->shapes.count)
	{
		world->shapes.count = index + 1;
	}
	cd2WorldShape* shape = world->shapes.data + index;
	memset(shape, 0, sizeof(*shape));
	cd2Body* body = world->bodies.data + bodyIndex;
	shape->generation = cd2NextGeneration(world);
	shape->inUse = true;
	shape->type = type;
	shape->body = bodyIndex;
	shape->nextShape = body->headShape;
	body->headShape = index;
	body->shapeCount += 1;
	shape->chain = CD2_NULL_INDEX;
	shape->nextChainShape = CD2_NULL_INDEX;
	shape->density = def->density;
	shape->friction = def->friction;
	shape->restitution = def->restitution;
	shape->rollingResistance = def->rollingResistance;
	shape->tangentSpeed = def->tangentSpeed;
	shape->filter = def->filter;
	shape->isSensor = def->isSensor;
	shape->enableSensorEvents = def->enableSensorEvents;
	shape->enableContactEvents = def->enableContactEvents;
	shape->enableHitEvents = def->enableHitEvents;
	shape->enablePreSolveEvents = def->enablePreSolveEvents;
	shape->userData = def->userData;
	shape->proxyId = CD_NULL_PROXY;
	shape->staticProxyId = CD_NULL_PROXY;
	return index;
}

/* Common end of every shape creation: bounds, proxy, mass. A sleeping body stays asleep (a body
 * made with isAwake false keeps sleeping once its shapes are on; an awake body touching the new
 * shape wakes it). */
static cd2ShapeId cd2FinishShape(cd2World* world, int index, bool updateMass)
{
	cd2WorldShape* shape = world->shapes.data + index;
	if (updateMass)
	{
		cd2UpdateBodyMass(world, shape->body);
	}
	cd2UpdateShapeBounds(world, index, false);
	return cd2MakeShapeId(world, index);
}

static cd2Body* cd2ShapeCreationBody(cd2BodyId bodyId, const cd2ShapeDef* def, cd2World** world)
{
	*world = cd2GetWorldFromIndex(bodyId.world0);
	cd2Body* body = cd2GetBody(*world, bodyId);
	if (body == NULL)
	{
		CD2_REFUSE("stale or null body id");
		return NULL;
	}
	if ((*world)->locked)
	{
		CD2_REFUSE("the world is locked during the step");
		return NULL;
	}
	if (!cd2IsValidShapeDef(def))
	{
		CD2_REFUSE("bad shape definition (NaN/Inf or negative density, friction, restitution)");
		return NULL;
	}
	return body;
}

cd2ShapeId cd2CreateCircleShape(cd2BodyId bodyId, const cd2ShapeDef* def, const cd2Circle* circle)
{
	cd2World* world;
	if (cd2ShapeCreationBody(bodyId, def, &world) == NULL)
	{
		return CD2_NULL_SHAPE_ID;
	}
	if (circle == NULL || !cd2IsValidCircle(*circle))
	{
		CD2_REFUSE("cd2CreateCircleShape: invalid circle");
		return CD2_NULL_SHAPE_ID;
	}
	int index = cd2AddShape(world, bodyId.index1 - 1, def, CD2_WORLD_SHAPE_CIRCLE);
	if (index < 0)
	{
		return CD2_NULL_SHAPE_ID;
	}
	world->shapes.data[index].geometry.circle = *circle;
	return cd2FinishShape(world, index, true);
}

cd2ShapeId cd2CreateCapsuleShape(cd2BodyId bodyId, const cd2ShapeDef* def, const cd2Capsule* capsule)
{
	cd2World* world;
	if (cd2ShapeCreationBody(bodyId, def, &world) == NULL)
	{
		return CD2_NULL_SHAPE_ID;
	}
	if (capsule == NULL || !cd2IsValidCapsule(*capsule))
	{
		CD2_REFUSE("cd2CreateCapsuleShape: invalid capsule");
		return CD2_NULL_SHAPE_ID;
	}
	int index = cd2AddShape(world, bodyId.index1 - 1, def, CD2_WORLD_SHAPE_CAPSULE);
	if (index < 0)
	{
		return CD2_NULL_SHAPE_ID;
	}
	world->shapes.data[index].geometry.capsule = *capsule;
	return cd2FinishShape(world, index, true);
}

cd2ShapeId cd2CreatePolygonShape(cd2BodyId bodyId, const cd2ShapeDef* def, const cd2Polygon* polygon)
{
	cd2World* world;
	if (cd2ShapeCreationBody(bodyId, def, &world) == NULL)
	{
		return CD2_NULL_SHAPE_ID;
	}
	if (polygon == NULL || !cd2IsValidPolygon(polygon))
	{
		CD2_REFUSE("cd2CreatePolygonShape: invalid polygon (build it with cd2MakePolygon)");
		return CD2_NULL_SHAPE_ID;
	}
	int index = cd2AddShape(world, bodyId.index1 - 1, def, CD2_WORLD_SHAPE_POLYGON);
	if (index < 0)
	{
		return CD2_NULL_SHAPE_ID;
	}
	world->shapes.data[index].geometry.polygon = *polygon;
	return cd2FinishShape(world, index, true);
}

cd2ShapeId cd2CreateSegmentShape(cd2BodyId bodyId, const cd2ShapeDef* def, const cd2Segment* segment)
{
	cd2World* world;
	if (cd2ShapeCreationBody(bodyId, def, &world) == NULL)
	{
		return CD2_NULL_SHAPE_ID;
	}
	if (segment == NULL || !cd2IsValidSegment(*segment))
	{
		CD2_REFUSE("cd2CreateSegmentShape: invalid segment");
		return CD2_NULL_SHAPE_ID;
	}
	int index = cd2AddShape(world, bodyId.index1 - 1, def, CD2_WORLD_SHAPE_SEGMENT);
	if (index < 0)
	{
		return CD2_NULL_SHAPE_ID;
	}
	world->shapes.data[index].geometry.segment = *segment;
	return cd2FinishShape(world, index, true);
}

void cd2DestroyShapeInternal(cd2World* world, int shapeIndex, bool wakeBodies)
{
	cd2WorldShape* shape = world->shapes.data + shapeIndex;
	cd2Body* body = world->bodies.data + shape->body;
	/* Contacts of this shape. */
	int key = body->headContactKey;
	while (key != CD2_NULL_INDEX)
	{
		cd2Contact* contact = world->contacts.data + cd2EdgeContact(key);
		int next = contact->nextKey[cd2EdgeSide(key)];
		if (contact->shapeA == shapeIndex || contact->shapeB == shapeIndex)
		{
			cd2DestroyContact(world, cd2EdgeContact(key), wakeBodies);
		}
		key = next;
	}
	if (shape->proxyId != CD_NULL_PROXY)
	{
		cd2DestroyShapeProxy(world, shape);
	}
	/* Unlink from the body. */
	int* link = &body->headShape;
	while (*link != CD2_NULL_INDEX && *link != shapeIndex)
	{
		link = &world->shapes.data[*link].nextShape;
	}
	if (*link == shapeIndex)
	{
		*link = shape->nextShape;
		body->shapeCount -= 1;
	}
	shape->inUse = false;
	shape->generation = 0;
	cdIdPool_Free(&world->shapePool, shapeIndex);
}

void cd2DestroyShape(cd2ShapeId shapeId, bool updateBodyMass)
{
	cd2World* world = NULL;
	cd2WorldShape* shape = cd2LookupShape(shapeId, &world, true);
	if (shape == NULL)
	{
		return;
	}
	if (shape->chain != CD2_NULL_INDEX)
	{
		CD2_REFUSE("cd2DestroyShape: chain segments go with their chain (cd2DestroyChainShape)");
		return;
	}
	int body = shape->body;
	cd2DestroyShapeInternal(world, shapeId.index1 - 1, true);
	if (updateBodyMass)
	{
		cd2UpdateBodyMass(world, body);
	}
	cd2WakeBody(world, body);
}

bool cd2Shape_IsValid(cd2ShapeId shapeId)
{
	return cd2GetShape(cd2GetWorldFromIndex(shapeId.world0), shapeId) != NULL;
}

/* ---- chains ----------------------------------------------------------------------------------- */
cd2ChainDef cd2DefaultChainDef(void)
{
	cd2ChainDef def;
	memset(&def, 0, sizeof(def));
	def.friction = CD_R(0.6);
	def.filter = cd2DefaultFilter();
	return def;
}

static cd2ChainRec* cd2LookupChain(cd2ChainId id, cd2World** outWorld, bool mutating)
{
	cd2World* world = cd2GetWorldFromIndex(id.world0);
	if (world == NULL || id.index1 <= 0 || id.index1 > world->chains.count ||
		!world->chains.data[id.index1 - 1].inUse ||
		world->chains.data[id.index1 - 1].generation != id.generation)
	{
		CD2_REFUSE("stale or null chain id");
		return NULL;
	}
	if (mutating && world->locked)
	{
		CD2_REFUSE("the world is locked during the step");
		return NULL;
	}
	*outWorld = world;
	return world->chains.data + (id.index1 - 1);
}

cd2ChainId cd2CreateChainShape(cd2BodyId bodyId, const cd2ChainDef* def)
{
	cd2World* world = cd2GetWorldFromIndex(bodyId.world0);
	cd2Body* body = cd2GetBody(world, bodyId);
	if (body == NULL || world->locked)
	{
		CD2_REFUSE("cd2CreateChainShape: stale body id or locked world");
		return CD2_NULL_CHAIN_ID;
	}
	if (def == NULL || !cdIsValidReal(def->friction) || def->friction < CD_R(0.0) ||
		!cdIsValidReal(def->restitution) || def->restitution < CD_R(0.0))
	{
		CD2_REFUSE("cd2CreateChainShape: bad chain definition");
		return CD2_NULL_CHAIN_ID;
	}
	cd2Chain* built = NULL;
	if (cd2CreateChain(def->points, def->count, def->isLoop, &built) != CD_OK)
	{
		CD2_REFUSE("cd2CreateChainShape: bad chain points (see cd2CreateChain)");
		return CD2_NULL_CHAIN_ID;
	}
	int chainIndex = cdIdPool_Alloc(&world->chainPool);
	if (chainIndex < 0 || !cdArrayReserveFor(world->chains, chainIndex + 1))
	{
		if (chainIndex >= 0)
		{
			cdIdPool_Free(&world->chainPool, chainIndex);
		}
		cd2DestroyChain(built);
		return CD2_NULL_CHAIN_ID;
	}
	if (chainIndex >= world->chains.count)
	{
		world->chains.count = chainIndex + 1;
	}
	cd2ChainRec* chain = world->chains.data + chainIndex;
	memset(chain, 0, sizeof(*chain));
	chain->generation = cd2NextGeneration(world);
	chain->inUse = true;
	chain->body = bodyId.index1 - 1;
	chain->headShape = CD2_NULL_INDEX;
	chain->userData = def->userData;
	cd2ShapeDef sd = cd2DefaultShapeDef();
	sd.density = CD_R(0.0);
	sd.friction = def->friction;
	sd.restitution = def->restitution;
	sd.filter = def->filter;
	sd.enableSensorEvents = def->enableSensorEvents;
	sd.userData = def->userData;
	int count = cd2GetChainSegmentCount(built);
	for (int i = count - 1; i >= 0; --i)
	{
		int index = cd2AddShape(world, chain->body, &sd, CD2_WORLD_SHAPE_CHAIN_SEGMENT);
		if (index < 0)
		{
			break;
		}
		chain = world->chains.data + chainIndex;
		cd2WorldShape* shape = world->shapes.data + index;
		shape->geometry.chainSegment = cd2GetChainSegment(built, i);
		shape->chain = chainIndex;
		shape->nextChainShape = chain->headShape;
		chain->headShape = index;
		chain->segmentCount += 1;
		cd2FinishShape(world, index, false);
	}
	cd2DestroyChain(built);
	cd2ChainId id = {chainIndex + 1, world->index, world->chains.data[chainIndex].generation};
	return id;
}

void cd2DestroyChainShape(cd2ChainId chainId)
{
	cd2World* world = NULL;
	cd2ChainRec* chain = cd2LookupChain(chainId, &world, true);
	if (chain == NULL)
	{
		return;
	}
	int s = chain->headShape;
	while (s != CD2_NULL_INDEX)
	{
		int next = world->shapes.data[s].nextChainShape;
		cd2DestroyShapeInternal(world, s, true);
		s = next;
	}
	chain->inUse = false;
	chain->generation = 0;
	cdIdPool_Free(&world->chainPool, chainId.index1 - 1);
}

bool cd2ChainShape_IsValid(cd2ChainId chainId)
{
	cd2World* world = cd2GetWorldFromIndex(chainId.world0);
	return world != NULL && chainId.index1 > 0 && chainId.index1 <= world->chains.count &&
		   world->chains.data[chainId.index1 - 1].inUse &&
		   world->chains.data[chainId.index1 - 1].generation == chainId.generation;
}

int cd2ChainShape_GetSegmentCount(cd2ChainId chainId)
{
	cd2World* world = NULL;
	cd2ChainRec* chain = cd2LookupChain(chainId, &world, false);
	return chain != NULL ? chain->segmentCount : 0;
}

/* ---- properties -------------------------------------------------------------------------------- */
cd2WorldShapeType cd2Shape_GetType(cd2ShapeId shapeId)
{
	cd2World* world = NULL;
	cd2WorldShape* shape = cd2LookupShape(shapeId, &world, false);
	return shape != NULL ? shape->type : CD2_WORLD_SHAPE_CIRCLE;
}

cd2BodyId cd2Shape_GetBody(cd2ShapeId shapeId)
{
	cd2World* world = NULL;
	cd2WorldShape* shape = cd2LookupShape(shapeId, &world, false);
	return shape != NULL ? cd2MakeBodyId(world, shape->body) : CD2_NULL_BODY_ID;
}

cd2Shape cd2Shape_GetWorldShape(cd2ShapeId shapeId)
{
	cd2World* world = NULL;
	cd2WorldShape* shape = cd2LookupShape(shapeId, &world, false);
	if (shape == NULL)
	{
		cd2Shape empty;
		memset(&empty, 0, sizeof(empty));
		return empty;
	}
	return cd2MakeTaggedShape(shape, world->bodies.data[shape->body].transform);
}

cd2Aabb cd2Shape_GetAabb(cd2ShapeId shapeId)
{
	cd2World* world = NULL;
	cd2WorldShape* shape = cd2LookupShape(shapeId, &world, false);
	if (shape == NULL)
	{
		cd2Aabb empty = {CD2_VEC_ZERO, CD2_VEC_ZERO};
		return empty;
	}
	return cd2ComputeWorldShapeAabb(shape, world->bodies.data[shape->body].transform);
}

bool cd2Shape_IsSensor(cd2ShapeId shapeId)
{
	cd2World* world = NULL;
	cd2WorldShape* shape = cd2LookupShape(shapeId, &world, false);
	return shape != NULL && shape->isSensor;
}

cdReal cd2Shape_GetDensity(cd2ShapeId shapeId)
{
	cd2World* world = NULL;
	cd2WorldShape* shape = cd2LookupShape(shapeId, &world, false);
	return shape != NULL ? shape->density : CD_R(0.0);
}

void cd2Shape_SetDensity(cd2ShapeId shapeId, cdReal density, bool updateBodyMass)
{
	cd2World* world = NULL;
	cd2WorldShape* shape = cd2LookupShape(shapeId, &world, true);
	if (shape == NULL)
	{
		return;
	}
	if (!cdIsValidReal(density) || density < CD_R(0.0))
	{
		CD2_REFUSE("cd2Shape_SetDensity: density must be finite and >= 0");
		return;
	}
	shape->density = density;
	if (updateBodyMass)
	{
		cd2UpdateBodyMass(world, shape->body);
	}
}

cdReal cd2Shape_GetFriction(cd2ShapeId shapeId)
{
	cd2World* world = NULL;
	cd2WorldShape* shape = cd2LookupShape(shapeId, &world, false);
	return shape != NULL ? shape->friction : CD_R(0.0);
}

void cd2Shape_SetFriction(cd2ShapeId shapeId, cdReal friction)
{
	cd2World* world = NULL;
	cd2WorldShape* shape = cd2LookupShape(shapeId, &world, true);
	if (shape == NULL)
	{
		return;
	}
	if (!cdIsValidReal(friction) || friction < CD_R(0.0))
	{
		CD2_REFUSE("cd2Shape_SetFriction: friction must be finite and >= 0");
		return;
	}
	shape->friction = friction;
}

cdReal cd2Shape_GetRestitution(cd2ShapeId shapeId)
{
	cd2World* world = NULL;
	cd2WorldShape* shape = cd2LookupShape(shapeId, &world, false);
	return shape != NULL ? shape->restitution : CD_R(0.0);
}

void cd2Shape_SetRestitution(cd2ShapeId shapeId, cdReal restitution)
{
	cd2World* world = NULL;
	cd2WorldShape* shape = cd2LookupShape(shapeId, &world, true);
	if (shape == NULL)
	{
		return;
	}
	if (!cdIsValidReal(restitution) || restitution < CD_R(0.0))
	{
		CD2_REFUSE("cd2Shape_SetRestitution: restitution must be finite and >= 0");
		return;
	}
	shape->restitution = restitution;
}

cd2Filter cd2Shape_GetFilter(cd2ShapeId shapeId)
{
	cd2World* world = NULL;
	cd2WorldShape* shape = cd2LookupShape(shapeId, &world, false);
	return shape != NULL ? shape->filter : cd2DefaultFilter();
}

void cd2Shape_SetFilter(cd2ShapeId shapeId, cd2Filter filter)
{
	cd2World* world = NULL;
	cd2WorldShape* shape = cd2LookupShape(shapeId, &world, true);
	if (shape == NULL)
	{
		return;
	}
	shape->filter = filter;
	int index = shapeId.index1 - 1;
	cd2Body* body = world->bodies.data + shape->body;
	int key = body->headContactKey;
	while (key != CD2_NULL_INDEX)
	{
		cd2Contact* contact = world->contacts.data + cd2EdgeContact(key);
		int next = contact->nextKey[cd2EdgeSide(key)];
		if (contact->shapeA == index || contact->shapeB == index)
		{
			cd2DestroyContact(world, cd2EdgeContact(key), true);
		}
		key = next;
	}
	/* A new proxy counts as moved: the broadphase reports its pairs again at the next step. */
	if (shape->proxyId != CD_NULL_PROXY)
	{
		cd2DestroyShapeProxy(world, shape);
		cd2UpdateShapeBounds(world, index, false);
	}
	cd2WakeBody(world, shape->body);
}

void* cd2Shape_GetUserData(cd2ShapeId shapeId)
{
	cd2World* world = NULL;
	cd2WorldShape* shape = cd2LookupShape(shapeId, &world, false);
	return shape != NULL ? shape->userData : NULL;
}

void cd2Shape_SetUserData(cd2ShapeId shapeId, void* userData)
{
	cd2World* world = NULL;
	cd2WorldShape* shape = cd2LookupShape(shapeId, &world, false);
	if (shape != NULL)
	{
		shape->userData = userData;
	}
}

#define CD2_SHAPE_FLAG(field)                                                                                \
	cd2World* world = NULL;                                                                                  \
	cd2WorldShape* shape = cd2LookupShape(shapeId, &world, true);                                            \
	if (shape != NULL)                                                                                       \
	{                                                                                                        \
		shape->field = flag;                                                                                 \
	}

void cd2Shape_EnableSensorEvents(cd2ShapeId shapeId, bool flag)
{
	CD2_SHAPE_FLAG(enableSensorEvents)
}

void cd2Shape_EnableContactEvents(cd2ShapeId shapeId, bool flag)
{
	CD2_SHAPE_FLAG(enableContactEvents)
}

void cd2Shape_EnableHitEvents(cd2ShapeId shapeId, bool flag)
{
	CD2_SHAPE_FLAG(enableHitEvents)
}

void cd2Shape_EnablePreSolveEvents(cd2ShapeId shapeId, bool flag)
{
	CD2_SHAPE_FLAG(enablePreSolveEvents)
}
