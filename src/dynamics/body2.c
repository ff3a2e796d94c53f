/* collide: 2D bodies: creation, destruction, state, forces, mass from shapes. */
#include "world2_internal.h"

cd2Body* cd2GetBody(cd2World* world, cd2BodyId id)
{
	if (world == NULL || id.index1 <= 0 || id.index1 > world->bodies.count)
	{
		return NULL;
	}
	cd2Body* body = world->bodies.data + (id.index1 - 1);
	if (!body->inUse || body->generation != id.generation)
	{
		return NULL;
	}
	return body;
}

cd2BodyId cd2MakeBodyId(const cd2World* world, int index)
{
	cd2BodyId id = {index + 1, world->index, world->bodies.data[index].generation};
	return id;
}

/* The body of an id, or NULL with a refusal (stale id, or a locked world when mutating). */
static cd2Body* cd2LookupBody(cd2BodyId id, cd2World** outWorld, bool mutating)
{
	cd2World* world = cd2GetWorldFromIndex(id.world0);
	cd2Body* body = cd2GetBody(world, id);
	if (body == NULL)
	{
		CD2_REFUSE("stale or null body id");
		return NULL;
	}
	if (mutating && world->locked)
	{
		CD2_REFUSE("the world is locked during the step");
		return NULL;
	}
	*outWorld = world;
	return body;
}

cd2BodyDef cd2DefaultBodyDef(void)
{
	cd2BodyDef def;
	memset(&def, 0, sizeof(def));
	def.type = CD_STATIC_BODY;
	def.rotation = CD2_ROT_IDENTITY;
	def.gravityScale = CD_R(1.0);
	def.sleepThreshold = CD_R(0.05) * cdGetLengthUnitsPerMeter();
	def.enableSleep = true;
	def.isAwake = true;
	def.isEnabled = true;
	return def;
}

static bool cd2IsNonNegative(cdReal a)
{
	return cdIsValidReal(a) && a >= CD_R(0.0);
}

cd2BodyId cd2CreateBody(cd2WorldId worldId, const cd2BodyDef* def)
{
	cd2World* world = cd2GetWorld(worldId);
	if (world == NULL)
	{
		return CD2_NULL_BODY_ID;
	}
	if (world->locked)
	{
		CD2_REFUSE("cd2CreateBody: the world is locked during the step");
		return CD2_NULL_BODY_ID;
	}
	if (def == NULL ||
		(def->type != CD_STATIC_BODY && def->type != CD_KINEMATIC_BODY && def->type != CD_DYNAMIC_BODY) ||
		!cd2IsValidVec(def->position) || !cd2IsValidRot(def->rotation) ||
		!cd2IsValidVec(def->linearVelocity) || !cdIsValidReal(def->angularVelocity) ||
		!cd2IsNonNegative(def->linearDamping) || !cd2IsNonNegative(def->angularDamping) ||
		!cdIsValidReal(def->gravityScale) || !cd2IsNonNegative(def->sleepThreshold))
	{
		CD2_REFUSE(
			"cd2CreateBody: bad body definition (NaN/Inf, non-unit rotation, negative damping, bad type)");
		return CD2_NULL_BODY_ID;
	}
	int index = cdIdPool_Alloc(&world->bodyPool);
	if (index < 0 || !cdArrayReserveFor(world->bodies, index + 1))
	{
		if (index >= 0)
		{
			cdIdPool_Free(&world->bodyPool, index);
		}
		return CD2_NULL_BODY_ID;
	}
	if (index >= world->bodies.count)
	{
		world->bodies.count = index + 1;
	}
	cd2Body* body = world->bodies.data + index;
	memset(body, 0, sizeof(*body));
	body->generation = cd2NextGeneration(world);
	body->inUse = true;
	body->type = def->type;
	body->transform.p = def->position;
	body->transform.q = def->rotation;
	body->center = def->position;
	body->center0 = def->position;
	body->rotation0 = def->rotation;
	body->linearVelocity = def->type == CD_STATIC_BODY ? CD2_VEC_ZERO : def->linearVelocity;
	body->angularVelocity = def->type == CD_STATIC_BODY ? CD_R(0.0) : def->angularVelocity;
	body->linearDamping = def->linearDamping;
	body->angularDamping = def->angularDamping;
	body->gravityScale = def->gravityScale;
	body->sleepThreshold = def->sleepThreshold;
	body->enableSleep = def->enableSleep;
	body->awake = def->type != CD_STATIC_BODY;
	body->fixedRotation = def->fixedRotation;
	body->isBullet = def->isBullet;
	body->enabled = def->isEnabled;
	body->headShape = CD2_NULL_INDEX;
	body->headContactKey = CD2_NULL_INDEX;
	body->headJointKey = CD2_NULL_INDEX;
	body->islandId = CD2_NULL_INDEX;
	body->islandNext = CD2_NULL_INDEX;
	body->solverIndex = CD2_NULL_INDEX;
	body->userData = def->userData;
	cd2UpdateBodyMass(world, index);
	if (body->type != CD_STATIC_BODY && !def->isAwake && def->enableSleep)
	{
		/* Created asleep: its own island. */
		cd2SleepBodyGroup(world, index);
	}
	cd2AwakeSets_SyncBody(world, index);
	return cd2MakeBodyId(world, index);
}

void cd2DestroyBody(cd2BodyId bodyId)
{
	cd2World* world = NULL;
	cd2Body* body = cd2LookupBody(bodyId, &world, true);
	if (body == NULL)
	{
		return;
	}
	int index = bodyId.index1 - 1;
	if (body->islandId != CD2_NULL_INDEX)
	{
		cd2WakeIsland(world, body->islandId);
	}
	while (body->headJointKey != CD2_NULL_INDEX)
	{
		cd2DestroyJointInternal(world, cd2EdgeContact(body->headJointKey), true);
	}
	while (world->chains.count > 0)
	{
		bool found = false;
		for (int i = 0; i < world->chains.count; ++i)
		{
			cd2ChainRec* chain = world->chains.data + i;
			if (chain->inUse && chain->body == index)
			{
				chain->inUse = false;
				cdIdPool_Free(&world->chainPool, i);
				found = true;
			}
		}
		if (!found)
		{
			break;
		}
	}
	while (body->headShape != CD2_NULL_INDEX)
	{
		cd2DestroyShapeInternal(world, body->headShape, true);
	}
	body->inUse = false;
	body->generation = 0;
	cd2AwakeSets_SyncBody(world, index);
	cdIdPool_Free(&world->bodyPool, index);
}

bool cd2Body_IsValid(cd2BodyId bodyId)
{
	return cd2GetBody(cd2GetWorldFromIndex(bodyId.world0), bodyId) != NULL;
}

void cd2WakeBody(cd2World* world, int bodyIndex)
{
	cd2Body* body = world->bodies.data + bodyIndex;
	if (body->type == CD_STATIC_BODY)
	{
		return;
	}
	if (body->islandId != CD2_NULL_INDEX)
	{
		cd2WakeIsland(world, body->islandId);
	}
	body->awake = true;
	body->sleepTime = CD_R(0.0);
	cd2AwakeSets_SyncBody(world, bodyIndex);
}

/* The extents continuous collision needs: the smallest inner and the largest outer radius of the
 * body's shapes about the centre of mass. */
static void cd2ComputeExtents(cd2World* world, cd2Body* body)
{
	cdReal minExtent = CD_REAL_MAX, maxExtent = CD_R(0.0);
	for (int s = body->headShape; s != CD2_NULL_INDEX; s = world->shapes.data[s].nextShape)
	{
		const cd2WorldShape* shape = world->shapes.data + s;
		cd2Aabb box = cd2ComputeWorldShapeAabb(shape, CD2_TRANSFORM_IDENTITY);
		cd2Vec a = cd2Sub(box.min, body->localCenter), b = cd2Sub(box.max, body->localCenter);
		cd2Vec far = cd2Max(cd2Abs(a), cd2Abs(b));
		maxExtent = cdMax(maxExtent, cd2Length(far));
		cdReal inner = CD_R(0.0);
		switch (shape->type)
		{
			case CD2_WORLD_SHAPE_CIRCLE:
				inner = shape->geometry.circle.radius;
				break;
			case CD2_WORLD_SHAPE_CAPSULE:
				inner = shape->geometry.capsule.radius;
				break;
			case CD2_WORLD_SHAPE_POLYGON:
			{
				const cd2Polygon* p = &shape->geometry.polygon;
				cdReal d = CD_REAL_MAX;
				for (int i = 0; i < p->count; ++i)
				{
					d = cdMin(d, cd2Dot(p->normals[i], cd2Sub(p->vertices[i], p->centroid)));
				}
				inner = cdMax(d, CD_R(0.0)) + p->radius;
				break;
			}
			default:
				inner = CD_R(0.0);
				break;
		}
		minExtent = cdMin(minExtent, inner);
	}
	body->minExtent = minExtent == CD_REAL_MAX ? CD_R(0.0) : minExtent;
	body->maxExtent = maxExtent;
}

void cd2UpdateBodyMass(cd2World* world, int bodyIndex)
{
	cd2Body* body = world->bodies.data + bodyIndex;
	cd2Vec oldCenter = body->center;
	if (!body->customMass)
	{
		body->mass = CD_R(0.0);
		body->inertia = CD_R(0.0);
		body->localCenter = CD2_VEC_ZERO;
	}
	if (body->type != CD_DYNAMIC_BODY)
	{
		body->mass = CD_R(0.0);
		body->inertia = CD_R(0.0);
		body->invMass = CD_R(0.0);
		body->invInertia = CD_R(0.0);
		body->localCenter = CD2_VEC_ZERO;
		body->center = body->transform.p;
		cd2ComputeExtents(world, body);
		return;
	}
	if (!body->customMass)
	{
		cdReal mass = CD_R(0.0), inertiaOrigin = CD_R(0.0);
		cd2Vec moment = CD2_VEC_ZERO;
		for (int s = body->headShape; s != CD2_NULL_INDEX; s = world->shapes.data[s].nextShape)
		{
			const cd2WorldShape* shape = world->shapes.data + s;
			if (shape->density == CD_R(0.0) || shape->type == CD2_WORLD_SHAPE_SEGMENT ||
				shape->type == CD2_WORLD_SHAPE_CHAIN_SEGMENT)
			{
				continue;
			}
			cd2Shape tagged = cd2MakeTaggedShape(shape, CD2_TRANSFORM_IDENTITY);
			cd2MassData md = cd2ComputeShapeMass(&tagged, shape->density);
			mass += md.mass;
			moment = cd2MulAdd(moment, md.mass, md.center);
			inertiaOrigin += md.rotationalInertia + md.mass * cd2Dot(md.center, md.center);
		}
		if (mass > CD_R(0.0))
		{
			cd2Vec localCenter = cd2Scale(CD_R(1.0) / mass, moment);
			body->mass = mass;
			body->localCenter = localCenter;
			body->inertia = inertiaOrigin - mass * cd2Dot(localCenter, localCenter);
		}
		else
		{
			/* Documented default: a dynamic body without mass weighs 1 kg at its origin and does
			 * not rotate from contacts. */
			body->mass = CD_R(1.0);
			body->inertia = CD_R(0.0);
		}
	}
	body->invMass = body->mass > CD_R(0.0) ? CD_R(1.0) / body->mass : CD_R(0.0);
	body->invInertia =
		(body->inertia > CD_R(0.0) && !body->fixedRotation) ? CD_R(1.0) / body->inertia : CD_R(0.0);
	body->center = cd2TransformPoint(body->transform, body->localCenter);
	body->center0 = body->center;
	/* Keep the velocity of the origin: the centre moved. */
	body->linearVelocity =
		cd2Add(body->linearVelocity, cd2CrossSV(body->angularVelocity, cd2Sub(body->center, oldCenter)));
	cd2ComputeExtents(world, body);
}

/* ---- getters and setters ------------------------------------------------------------------- */
#define CD2_BODY_GET(ret, fallback, expr) /* ret: documentation only */                                      \
	cd2World* world = NULL;                                                                                  \
	cd2Body* body = cd2LookupBody(bodyId, &world, false);                                                    \
	(void)world;                                                                                             \
	if (body == NULL)                                                                                        \
	{                                                                                                        \
		return fallback;                                                                                     \
	}                                                                                                        \
	return (expr)

cd2BodyType cd2Body_GetType(cd2BodyId bodyId)
{
	CD2_BODY_GET(cd2BodyType, CD_STATIC_BODY, body->type);
}

cd2Vec cd2Body_GetPosition(cd2BodyId bodyId)
{
	CD2_BODY_GET(cd2Vec, CD2_VEC_ZERO, body->transform.p);
}

cd2Rot cd2Body_GetRotation(cd2BodyId bodyId)
{
	CD2_BODY_GET(cd2Rot, CD2_ROT_IDENTITY, body->transform.q);
}

cd2Transform cd2Body_GetTransform(cd2BodyId bodyId)
{
	CD2_BODY_GET(cd2Transform, CD2_TRANSFORM_IDENTITY, body->transform);
}

cd2Vec cd2Body_GetLocalPoint(cd2BodyId bodyId, cd2Vec worldPoint)
{
	CD2_BODY_GET(cd2Vec, CD2_VEC_ZERO, cd2InvTransformPoint(body->transform, worldPoint));
}

cd2Vec cd2Body_GetWorldPoint(cd2BodyId bodyId, cd2Vec localPoint)
{
	CD2_BODY_GET(cd2Vec, CD2_VEC_ZERO, cd2TransformPoint(body->transform, localPoint));
}

cd2Vec cd2Body_GetLocalVector(cd2BodyId bodyId, cd2Vec worldVector)
{
	CD2_BODY_GET(cd2Vec, CD2_VEC_ZERO, cd2InvRotateVector(body->transform.q, worldVector));
}

cd2Vec cd2Body_GetWorldVector(cd2BodyId bodyId, cd2Vec localVector)
{
	CD2_BODY_GET(cd2Vec, CD2_VEC_ZERO, cd2RotateVector(body->transform.q, localVector));
}

cd2Vec cd2Body_GetWorldCenterOfMass(cd2BodyId bodyId)
{
	CD2_BODY_GET(cd2Vec, CD2_VEC_ZERO, body->center);
}

cd2Vec cd2Body_GetLocalCenterOfMass(cd2BodyId bodyId)
{
	CD2_BODY_GET(cd2Vec, CD2_VEC_ZERO, body->localCenter);
}

cd2Vec cd2Body_GetLinearVelocity(cd2BodyId bodyId)
{
	CD2_BODY_GET(cd2Vec, CD2_VEC_ZERO, body->linearVelocity);
}

cdReal cd2Body_GetAngularVelocity(cd2BodyId bodyId)
{
	CD2_BODY_GET(cdReal, CD_R(0.0), body->angularVelocity);
}

cdReal cd2Body_GetMass(cd2BodyId bodyId)
{
	CD2_BODY_GET(cdReal, CD_R(0.0), body->mass);
}

cdReal cd2Body_GetRotationalInertia(cd2BodyId bodyId)
{
	CD2_BODY_GET(cdReal, CD_R(0.0), body->inertia);
}

cdReal cd2Body_GetLinearDamping(cd2BodyId bodyId)
{
	CD2_BODY_GET(cdReal, CD_R(0.0), body->linearDamping);
}

cdReal cd2Body_GetAngularDamping(cd2BodyId bodyId)
{
	CD2_BODY_GET(cdReal, CD_R(0.0), body->angularDamping);
}

cdReal cd2Body_GetGravityScale(cd2BodyId bodyId)
{
	CD2_BODY_GET(cdReal, CD_R(0.0), body->gravityScale);
}

bool cd2Body_IsFixedRotation(cd2BodyId bodyId)
{
	CD2_BODY_GET(bool, false, body->fixedRotation);
}

bool cd2Body_IsBullet(cd2BodyId bodyId)
{
	CD2_BODY_GET(bool, false, body->isBullet);
}

bool cd2Body_IsAwake(cd2BodyId bodyId)
{
	CD2_BODY_GET(bool, false, body->awake);
}

bool cd2Body_IsEnabled(cd2BodyId bodyId)
{
	CD2_BODY_GET(bool, false, body->enabled);
}

void* cd2Body_GetUserData(cd2BodyId bodyId)
{
	CD2_BODY_GET(void*, NULL, body->userData);
}

int cd2Body_GetShapeCount(cd2BodyId bodyId)
{
	CD2_BODY_GET(int, 0, body->shapeCount);
}

cd2WorldId cd2Body_GetWorld(cd2BodyId bodyId)
{
	cd2World* world = NULL;
	cd2Body* body = cd2LookupBody(bodyId, &world, false);
	if (body == NULL)
	{
		return CD2_NULL_WORLD_ID;
	}
	cd2WorldId id = {(uint16_t)(world->index + 1), world->generation};
	return id;
}

cd2MassData cd2Body_GetMassData(cd2BodyId bodyId)
{
	cd2MassData md = {CD_R(0.0), CD2_VEC_ZERO, CD_R(0.0)};
	cd2World* world = NULL;
	cd2Body* body = cd2LookupBody(bodyId, &world, false);
	if (body != NULL)
	{
		md.mass = body->mass;
		md.center = body->localCenter;
		md.rotationalInertia = body->inertia;
	}
	return md;
}

int cd2Body_GetShapes(cd2BodyId bodyId, cd2ShapeId* shapeArray, int capacity)
{
	cd2World* world = NULL;
	cd2Body* body = cd2LookupBody(bodyId, &world, false);
	if (body == NULL || shapeArray == NULL)
	{
		return 0;
	}
	int n = 0;
	for (int s = body->headShape; s != CD2_NULL_INDEX && n < capacity; s = world->shapes.data[s].nextShape)
	{
		shapeArray[n++] = cd2MakeShapeId(world, s);
	}
	return n;
}

/* Moves every shape's broadphase box after a teleport. */
static void cd2RefreshBodyShapes(cd2World* world, cd2Body* body)
{
	for (int s = body->headShape; s != CD2_NULL_INDEX; s = world->shapes.data[s].nextShape)
	{
		cd2UpdateShapeBounds(world, s, true);
	}
}

void cd2Body_SetTransform(cd2BodyId bodyId, cd2Vec position, cd2Rot rotation)
{
	cd2World* world = NULL;
	cd2Body* body = cd2LookupBody(bodyId, &world, true);
	if (body == NULL)
	{
		return;
	}
	if (!cd2IsValidVec(position) || !cd2IsValidRot(rotation))
	{
		CD2_REFUSE("cd2Body_SetTransform: NaN/Inf position or non-unit rotation");
		return;
	}
	body->transform.p = position;
	body->transform.q = rotation;
	body->center = cd2TransformPoint(body->transform, body->localCenter);
	body->center0 = body->center;
	body->rotation0 = rotation;
	cd2RefreshBodyShapes(world, body);
	cd2WakeBody(world, bodyId.index1 - 1);
}

void cd2Body_SetLinearVelocity(cd2BodyId bodyId, cd2Vec velocity)
{
	cd2World* world = NULL;
	cd2Body* body = cd2LookupBody(bodyId, &world, true);
	if (body == NULL)
	{
		return;
	}
	if (!cd2IsValidVec(velocity))
	{
		CD2_REFUSE("cd2Body_SetLinearVelocity: NaN/Inf velocity");
		return;
	}
	if (body->type == CD_STATIC_BODY)
	{
		return;
	}
	if (cd2Dot(velocity, velocity) > CD_R(0.0))
	{
		cd2WakeBody(world, bodyId.index1 - 1);
	}
	body->linearVelocity = velocity;
}

void cd2Body_SetAngularVelocity(cd2BodyId bodyId, cdReal angularVelocity)
{
	cd2World* world = NULL;
	cd2Body* body = cd2LookupBody(bodyId, &world, true);
	if (body == NULL)
	{
		return;
	}
	if (!cdIsValidReal(angularVelocity))
	{
		CD2_REFUSE("cd2Body_SetAngularVelocity: NaN/Inf");
		return;
	}
	if (body->type == CD_STATIC_BODY || body->fixedRotation)
	{
		return;
	}
	if (angularVelocity != CD_R(0.0))
	{
		cd2WakeBody(world, bodyId.index1 - 1);
	}
	body->angularVelocity = angularVelocity;
}

/* Shared by the force and impulse functions: the body when it should take the push. */
static cd2Body* cd2BodyForPush(cd2BodyId bodyId, cd2World** world, bool wake, bool valid)
{
	cd2Body* body = cd2LookupBody(bodyId, world, true);
	if (body == NULL)
	{
		return NULL;
	}
	if (!valid)
	{
		CD2_REFUSE("NaN/Inf force, torque, impulse or point");
		return NULL;
	}
	if (body->type != CD_DYNAMIC_BODY)
	{
		return NULL;
	}
	if (!body->awake)
	{
		if (!wake)
		{
			return NULL;
		}
		cd2WakeBody(*world, bodyId.index1 - 1);
	}
	return body;
}

void cd2Body_ApplyForce(cd2BodyId bodyId, cd2Vec force, cd2Vec worldPoint, bool wake)
{
	cd2World* world = NULL;
	cd2Body* body = cd2BodyForPush(bodyId, &world, wake, cd2IsValidVec(force) && cd2IsValidVec(worldPoint));
	if (body != NULL)
	{
		body->force = cd2Add(body->force, force);
		body->torque += cd2Cross(cd2Sub(worldPoint, body->center), force);
	}
}

void cd2Body_ApplyForceToCenter(cd2BodyId bodyId, cd2Vec force, bool wake)
{
	cd2World* world = NULL;
	cd2Body* body = cd2BodyForPush(bodyId, &world, wake, cd2IsValidVec(force));
	if (body != NULL)
	{
		body->force = cd2Add(body->force, force);
	}
}

void cd2Body_ApplyTorque(cd2BodyId bodyId, cdReal torque, bool wake)
{
	cd2World* world = NULL;
	cd2Body* body = cd2BodyForPush(bodyId, &world, wake, cdIsValidReal(torque));
	if (body != NULL)
	{
		body->torque += torque;
	}
}

void cd2Body_ApplyLinearImpulse(cd2BodyId bodyId, cd2Vec impulse, cd2Vec worldPoint, bool wake)
{
	cd2World* world = NULL;
	cd2Body* body = cd2BodyForPush(bodyId, &world, wake, cd2IsValidVec(impulse) && cd2IsValidVec(worldPoint));
	if (body != NULL)
	{
		body->linearVelocity = cd2MulAdd(body->linearVelocity, body->invMass, impulse);
		body->angularVelocity += body->invInertia * cd2Cross(cd2Sub(worldPoint, body->center), impulse);
	}
}

void cd2Body_ApplyLinearImpulseToCenter(cd2BodyId bodyId, cd2Vec impulse, bool wake)
{
	cd2World* world = NULL;
	cd2Body* body = cd2BodyForPush(bodyId, &world, wake, cd2IsValidVec(impulse));
	if (body != NULL)
	{
		body->linearVelocity = cd2MulAdd(body->linearVelocity, body->invMass, impulse);
	}
}

void cd2Body_ApplyAngularImpulse(cd2BodyId bodyId, cdReal impulse, bool wake)
{
	cd2World* world = NULL;
	cd2Body* body = cd2BodyForPush(bodyId, &world, wake, cdIsValidReal(impulse));
	if (body != NULL)
	{
		body->angularVelocity += body->invInertia * impulse;
	}
}

void cd2Body_SetMassData(cd2BodyId bodyId, cd2MassData massData)
{
	cd2World* world = NULL;
	cd2Body* body = cd2LookupBody(bodyId, &world, true);
	if (body == NULL)
	{
		return;
	}
	if (!cd2IsNonNegative(massData.mass) || !cd2IsNonNegative(massData.rotationalInertia) ||
		!cd2IsValidVec(massData.center))
	{
		CD2_REFUSE("cd2Body_SetMassData: mass and inertia must be finite and >= 0");
		return;
	}
	body->customMass = true;
	body->mass = massData.mass;
	body->inertia = massData.rotationalInertia;
	body->localCenter = massData.center;
	cd2UpdateBodyMass(world, bodyId.index1 - 1);
}

void cd2Body_ApplyMassFromShapes(cd2BodyId bodyId)
{
	cd2World* world = NULL;
	cd2Body* body = cd2LookupBody(bodyId, &world, true);
	if (body != NULL)
	{
		body->customMass = false;
		cd2UpdateBodyMass(world, bodyId.index1 - 1);
	}
}

#define CD2_BODY_SET_NONNEG(field, name)                                                                     \
	cd2World* world = NULL;                                                                                  \
	cd2Body* body = cd2LookupBody(bodyId, &world, true);                                                     \
	if (body == NULL)                                                                                        \
	{                                                                                                        \
		return;                                                                                              \
	}                                                                                                        \
	if (!cd2IsNonNegative(value))                                                                            \
	{                                                                                                        \
		CD2_REFUSE(name ": the value must be finite and >= 0");                                              \
		return;                                                                                              \
	}                                                                                                        \
	body->field = value

void cd2Body_SetLinearDamping(cd2BodyId bodyId, cdReal value)
{
	CD2_BODY_SET_NONNEG(linearDamping, "cd2Body_SetLinearDamping");
}

void cd2Body_SetAngularDamping(cd2BodyId bodyId, cdReal value)
{
	CD2_BODY_SET_NONNEG(angularDamping, "cd2Body_SetAngularDamping");
}

void cd2Body_SetGravityScale(cd2BodyId bodyId, cdReal gravityScale)
{
	cd2World* world = NULL;
	cd2Body* body = cd2LookupBody(bodyId, &world, true);
	if (body == NULL)
	{
		return;
	}
	if (!cdIsValidReal(gravityScale))
	{
		CD2_REFUSE("cd2Body_SetGravityScale: NaN/Inf");
		return;
	}
	body->gravityScale = gravityScale;
}

void cd2Body_SetFixedRotation(cd2BodyId bodyId, bool flag)
{
	cd2World* world = NULL;
	cd2Body* body = cd2LookupBody(bodyId, &world, true);
	if (body == NULL)
	{
		return;
	}
	body->fixedRotation = flag;
	if (flag)
	{
		body->angularVelocity = CD_R(0.0);
	}
	cd2UpdateBodyMass(world, bodyId.index1 - 1);
}

void cd2Body_SetBullet(cd2BodyId bodyId, bool flag)
{
	cd2World* world = NULL;
	cd2Body* body = cd2LookupBody(bodyId, &world, true);
	if (body != NULL)
	{
		body->isBullet = flag;
	}
}

void cd2Body_SetAwake(cd2BodyId bodyId, bool awake)
{
	cd2World* world = NULL;
	cd2Body* body = cd2LookupBody(bodyId, &world, true);
	if (body == NULL || body->type == CD_STATIC_BODY)
	{
		return;
	}
	if (awake)
	{
		cd2WakeBody(world, bodyId.index1 - 1);
	}
	else if (body->awake)
	{
		cd2SleepBodyGroup(world, bodyId.index1 - 1);
	}
}

void cd2Body_EnableSleep(cd2BodyId bodyId, bool enableSleep)
{
	cd2World* world = NULL;
	cd2Body* body = cd2LookupBody(bodyId, &world, true);
	if (body == NULL)
	{
		return;
	}
	body->enableSleep = enableSleep;
	if (!enableSleep)
	{
		cd2WakeBody(world, bodyId.index1 - 1);
	}
}

void cd2Body_SetUserData(cd2BodyId bodyId, void* userData)
{
	cd2World* world = NULL;
	cd2Body* body = cd2LookupBody(bodyId, &world, false);
	if (body != NULL)
	{
		body->userData = userData;
	}
}

/* Removes the body's contacts and broadphase proxies (disable) or puts the proxies back. */
static void cd2SetBodyInSimulation(cd2World* world, int index, bool enabled)
{
	cd2Body* body = world->bodies.data + index;
	while (body->headContactKey != CD2_NULL_INDEX)
	{
		cd2DestroyContact(world, cd2EdgeContact(body->headContactKey), true);
	}
	for (int s = body->headShape; s != CD2_NULL_INDEX; s = world->shapes.data[s].nextShape)
	{
		cd2WorldShape* shape = world->shapes.data + s;
		if (!enabled && shape->proxyId != CD_NULL_PROXY)
		{
			cd2DestroyShapeProxy(world, shape);
		}
		if (enabled)
		{
			cd2UpdateShapeBounds(world, s, true);
		}
	}
}

void cd2Body_Disable(cd2BodyId bodyId)
{
	cd2World* world = NULL;
	cd2Body* body = cd2LookupBody(bodyId, &world, true);
	if (body == NULL || !body->enabled)
	{
		return;
	}
	int index = bodyId.index1 - 1;
	if (body->islandId != CD2_NULL_INDEX)
	{
		cd2WakeIsland(world, body->islandId);
	}
	body->enabled = false;
	cd2SetBodyInSimulation(world, index, false);
	cd2AwakeSets_SyncBody(world, index);
}

void cd2Body_Enable(cd2BodyId bodyId)
{
	cd2World* world = NULL;
	cd2Body* body = cd2LookupBody(bodyId, &world, true);
	if (body == NULL || body->enabled)
	{
		return;
	}
	body->enabled = true;
	cd2SetBodyInSimulation(world, bodyId.index1 - 1, true);
	cd2WakeBody(world, bodyId.index1 - 1);
}

void cd2Body_SetType(cd2BodyId bodyId, cd2BodyType type)
{
	cd2World* world = NULL;
	cd2Body* body = cd2LookupBody(bodyId, &world, true);
	if (body == NULL || body->type == type)
	{
		return;
	}
	if (type != CD_STATIC_BODY && type != CD_KINEMATIC_BODY && type != CD_DYNAMIC_BODY)
	{
		CD2_REFUSE("cd2Body_SetType: unknown body type");
		return;
	}
	int index = bodyId.index1 - 1;
	if (body->islandId != CD2_NULL_INDEX)
	{
		cd2WakeIsland(world, body->islandId);
	}
	body->type = type;
	if (type == CD_STATIC_BODY)
	{
		body->linearVelocity = CD2_VEC_ZERO;
		body->angularVelocity = CD_R(0.0);
		body->awake = false;
	}
	else
	{
		body->awake = true;
		body->sleepTime = CD_R(0.0);
	}
	cd2UpdateBodyMass(world, index);
	/* Pairs depend on the types: rebuild them. */
	if (body->enabled)
	{
		cd2SetBodyInSimulation(world, index, false);
		cd2SetBodyInSimulation(world, index, true);
	}
	cd2AwakeSets_SyncBody(world, index);
}

bool cd2ShouldBodiesCollide(const cd2World* world, int bodyA, int bodyB)
{
	const cd2Body* a = world->bodies.data + bodyA;
	const cd2Body* b = world->bodies.data + bodyB;
	if (a->type != CD_DYNAMIC_BODY && b->type != CD_DYNAMIC_BODY)
	{
		return false;
	}
	/* Walk the shorter joint list. */
	int key = a->headJointKey;
	int other = bodyB;
	while (key != CD2_NULL_INDEX)
	{
		const cd2Joint* joint = world->joints.data + (key >> 1);
		int side = key & 1;
		int otherBody = side == 0 ? joint->bodyB : joint->bodyA;
		if (otherBody == other && !joint->collideConnected)
		{
			return false;
		}
		key = joint->nextKey[side];
	}
	return true;
}
