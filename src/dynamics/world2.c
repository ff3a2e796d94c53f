/* collide: 2D worlds: creation, the step's pipeline, settings, events and callbacks. */
#include "world2_internal.h"
#include "../broad/broad_internal.h"
#include "../base/thread_pool.h"

#include <stdio.h>
#include <time.h>

static cd2World* s_worlds[CD2_MAX_WORLDS];
static uint16_t s_worldGenerations[CD2_MAX_WORLDS];

void cd2Refuse(const char* reason, const char* file, int line)
{
	if (cdInternalAssert(reason, file, line))
	{
#if !defined(NDEBUG) || defined(CD_ENABLE_ASSERT)
		abort();
#endif
	}
}

uint32_t cd2NextGeneration(cd2World* world)
{
	world->generationCounter += 1;
	if (world->generationCounter == 0)
	{
		world->generationCounter = 1;
	}
	return world->generationCounter;
}

cd2World* cd2GetWorldQuiet(cd2WorldId id)
{
	if (id.index1 == 0 || id.index1 > CD2_MAX_WORLDS)
	{
		return NULL;
	}
	cd2World* world = s_worlds[id.index1 - 1];
	if (world == NULL || world->generation != id.generation)
	{
		return NULL;
	}
	return world;
}

cd2World* cd2GetWorld(cd2WorldId id)
{
	cd2World* world = cd2GetWorldQuiet(id);
	if (world == NULL)
	{
		CD2_REFUSE("stale or null world id");
	}
	return world;
}

cd2World* cd2GetWorldFromIndex(uint16_t world0)
{
	return world0 < CD2_MAX_WORLDS ? s_worlds[world0] : NULL;
}

cd2WorldDef cd2DefaultWorldDef(void)
{
	cd2WorldDef def;
	memset(&def, 0, sizeof(def));
	def.gravity = cd2MakeVec(CD_R(0.0), CD_R(-10.0));
	def.restitutionThreshold = CD_R(1.0);
	def.hitEventThreshold = CD_R(1.0);
	def.contactHertz = CD_R(30.0);
	def.contactDampingRatio = CD_R(10.0);
	def.contactPushMaxVelocity = CD_R(3.0);
	def.jointHertz = CD_R(60.0);
	def.jointDampingRatio = CD_R(2.0);
	def.maximumLinearSpeed = CD_R(400.0);
	def.lengthUnitsPerMeter = CD_R(0.0);
	def.contactRecycleDistance = CD_R(0.02);
	def.enableSleep = true;
	def.enableContinuous = true;
	def.workerCount = 1;
	return def;
}

static bool cd2IsNonNegative(cdReal a)
{
	return cdIsValidReal(a) && a >= CD_R(0.0);
}

cd2WorldId cd2CreateWorld(const cd2WorldDef* def)
{
	if (def == NULL || !cd2IsValidVec(def->gravity) || !cd2IsNonNegative(def->restitutionThreshold) ||
		!cd2IsNonNegative(def->hitEventThreshold) || !cd2IsNonNegative(def->contactHertz) ||
		!cd2IsNonNegative(def->contactDampingRatio) || !cd2IsNonNegative(def->contactPushMaxVelocity) ||
		!cd2IsNonNegative(def->jointHertz) || !cd2IsNonNegative(def->jointDampingRatio) ||
		!(cdIsValidReal(def->maximumLinearSpeed) && def->maximumLinearSpeed > CD_R(0.0)) ||
		!cd2IsNonNegative(def->lengthUnitsPerMeter) || !cd2IsNonNegative(def->contactRecycleDistance) ||
		def->workerCount < 0 || (def->enqueueTask == NULL) != (def->finishTask == NULL))
	{
		CD2_REFUSE("cd2CreateWorld: bad world definition (NaN, negative or missing value)");
		return CD2_NULL_WORLD_ID;
	}
	int slot = -1;
	for (int i = 0; i < CD2_MAX_WORLDS; ++i)
	{
		if (s_worlds[i] == NULL)
		{
			slot = i;
			break;
		}
	}
	if (slot < 0)
	{
		CD2_REFUSE("cd2CreateWorld: too many worlds");
		return CD2_NULL_WORLD_ID;
	}
	cd2World* world = (cd2World*)cdAlloc(sizeof(cd2World));
	if (world == NULL)
	{
		return CD2_NULL_WORLD_ID;
	}
	memset(world, 0, sizeof(*world));
	world->awakeSets.valid = true;
	cd2BroadPhaseDef bpDef = cd2DefaultBroadPhaseDef();
	bpDef.type = CD_BROADPHASE_TREE;
	/* The world computes the fat boxes itself (so that a snapshot can restore them exactly). */
	bpDef.margin = CD_R(0.0);
	bpDef.displacementMultiplier = CD_R(0.0);
	if (cd2BroadPhase_Create(&bpDef, &world->broadPhase) != CD_OK)
	{
		cdFree(world);
		return CD2_NULL_WORLD_ID;
	}
	cd2BroadPhase_SetEnlargeMoves(world->broadPhase, true);
	if (cd2BroadPhase_Create(&bpDef, &world->staticBroadPhase) != CD_OK)
	{
		cd2BroadPhase_Destroy(world->broadPhase);
		cdFree(world);
		return CD2_NULL_WORLD_ID;
	}
	if (def->lengthUnitsPerMeter > CD_R(0.0))
	{
		cdSetLengthUnitsPerMeter(def->lengthUnitsPerMeter);
	}
	world->index = (uint16_t)slot;
	s_worldGenerations[slot] = (uint16_t)(s_worldGenerations[slot] + 1u);
	if (s_worldGenerations[slot] == 0)
	{
		s_worldGenerations[slot] = 1;
	}
	world->generation = s_worldGenerations[slot];
	world->gravity = def->gravity;
	world->restitutionThreshold = def->restitutionThreshold;
	world->hitEventThreshold = def->hitEventThreshold;
	world->contactHertz = def->contactHertz;
	world->contactDampingRatio = def->contactDampingRatio;
	world->contactPushMaxVelocity = def->contactPushMaxVelocity;
	world->jointHertz = def->jointHertz;
	world->jointDampingRatio = def->jointDampingRatio;
	world->maximumLinearSpeed = def->maximumLinearSpeed;
	world->contactRecycleDistance = def->contactRecycleDistance;
	world->enableSleep = def->enableSleep;
	world->enableContinuous = def->enableContinuous;
	world->userData = def->userData;
	world->workerCount = def->workerCount > 1 ? def->workerCount : 1;
	if (def->enqueueTask != NULL)
	{
		world->enqueueTask = def->enqueueTask;
		world->finishTask = def->finishTask;
		world->userTaskContext = def->userTaskContext;
	}
	else if (world->workerCount > 1)
	{
		/* No task system given: the built-in pool. Without threads (no pool) the step runs on the
		 * calling thread, with the same results. */
		world->threadPool = cdThreadPool_Create(world->workerCount);
		if (world->threadPool != NULL)
		{
			world->enqueueTask = cdThreadPool_Enqueue;
			world->finishTask = cdThreadPool_Finish;
			world->userTaskContext = world->threadPool;
		}
	}
	s_worlds[slot] = world;
	cd2WorldId id = {(uint16_t)(slot + 1), world->generation};
	return id;
}

void cd2DestroyWorld(cd2WorldId worldId)
{
	cd2World* world = cd2GetWorld(worldId);
	if (world == NULL || world->locked)
	{
		return;
	}
	cd2BroadPhase_Destroy(world->broadPhase);
	cd2BroadPhase_Destroy(world->staticBroadPhase);
	cdArrayFree(world->bodies);
	cdArrayFree(world->shapes);
	cdArrayFree(world->chains);
	cdArrayFree(world->contacts);
	cdArrayFree(world->joints);
	cdArrayFree(world->islands);
	cd2AwakeSets_Destroy(world);
	cd2ColorCache_Destroy(&world->contactColorCache);
	cd2ColorCache_Destroy(&world->jointColorCache);
	cdIdPool_Destroy(&world->bodyPool);
	cdIdPool_Destroy(&world->shapePool);
	cdIdPool_Destroy(&world->chainPool);
	cdIdPool_Destroy(&world->contactPool);
	cdIdPool_Destroy(&world->jointPool);
	cdIdPool_Destroy(&world->islandPool);
	cdPairSet_Destroy(&world->pairs);
	cdArrayFree(world->beginEvents);
	cdArrayFree(world->endEvents);
	cdArrayFree(world->hitEvents);
	cdArrayFree(world->sensorBeginEvents);
	cdArrayFree(world->sensorEndEvents);
	cdArrayFree(world->moveEvents);
	cdArrayFree(world->jointEvents);
	cdArena_Destroy(&world->arena);
	cdThreadPool_Destroy(world->threadPool);
	s_worlds[world->index] = NULL;
	cdFree(world);
}

bool cd2World_IsValid(cd2WorldId worldId)
{
	return cd2GetWorldQuiet(worldId) != NULL;
}

void cd2SetAlwaysParallel(cd2WorldId worldId, bool alwaysParallel)
{
	cd2World* world = cd2GetWorld(worldId);
	if (world != NULL)
	{
		world->alwaysParallel = alwaysParallel;
	}
}

void cd2World_Step(cd2WorldId worldId, cdReal timeStep, int subStepCount)
{
	cd2World* world = cd2GetWorld(worldId);
	if (world == NULL)
	{
		return;
	}
	if (world->locked)
	{
		CD2_REFUSE("cd2World_Step: the world is locked (called from a callback)");
		return;
	}
	if (!cdIsValidReal(timeStep) || timeStep < CD_R(0.0) || subStepCount < 1 ||
		subStepCount > CD2_MAX_SUB_STEPS)
	{
		CD2_REFUSE("cd2World_Step: the time step must be finite and >= 0, the sub-step count 1 to "
				   "CD2_MAX_SUB_STEPS");
		return;
	}
	world->locked = true;
	/* Drop the last step's events; keep end events that destructions between the steps added. */
	int keepEnd = world->endEvents.count - world->stepEndEventCount;
	if (keepEnd > 0 && world->stepEndEventCount > 0)
	{
		memmove(world->endEvents.data, world->endEvents.data + world->stepEndEventCount,
				(size_t)keepEnd * sizeof(cd2ContactEndTouchEvent));
	}
	world->endEvents.count = keepEnd;
	int keepSensorEnd = world->sensorEndEvents.count - world->stepSensorEndEventCount;
	if (keepSensorEnd > 0 && world->stepSensorEndEventCount > 0)
	{
		memmove(world->sensorEndEvents.data, world->sensorEndEvents.data + world->stepSensorEndEventCount,
				(size_t)keepSensorEnd * sizeof(cd2SensorEndTouchEvent));
	}
	world->sensorEndEvents.count = keepSensorEnd;
	world->beginEvents.count = 0;
	world->hitEvents.count = 0;
	world->sensorBeginEvents.count = 0;
	world->moveEvents.count = 0;
	world->jointEvents.count = 0;

	/* New pairs become contacts, then every awake contact gets its manifold. */
	world->stepTimeStep = timeStep;
#ifdef CD2_VALIDATE_AWAKE_SETS
	cd2AwakeSets_Validate(world);
#endif
	double stepStart = 0.0;
	if (world->profiling)
	{
		memset(&world->profile, 0, sizeof(world->profile));
		stepStart = cd2ProfileNow();
		world->profileMark = stepStart;
	}
	cd2UpdateBroadPhasePairs(world);
	CD2_PROFILE_MARK(world, pairs);
	cd2UpdateContacts(world, timeStep);
	CD2_PROFILE_MARK(world, collide);
	if (timeStep > CD_R(0.0))
	{
		double solveStart = world->profileMark;
		cd2Solve(world, timeStep, subStepCount);
		if (world->profiling)
		{
			world->profile.solve = (float)(1000.0 * (cd2ProfileNow() - solveStart));
			world->profileMark = cd2ProfileNow();
		}
	}
#ifdef CD2_VALIDATE_AWAKE_SETS
	cd2AwakeSets_Validate(world);
#endif
	cd2UpdateSensors(world);
	CD2_PROFILE_MARK(world, sensors);
	if (world->profiling)
	{
		world->profile.step = (float)(1000.0 * (cd2ProfileNow() - stepStart));
	}
	cdArena_Reset(&world->arena);
	world->stepSolveEntries = NULL;
	world->stepTimeStep = CD_R(0.0);
	world->stepEndEventCount = world->endEvents.count;
	world->stepSensorEndEventCount = world->sensorEndEvents.count;
	world->locked = false;
}

void cd2World_SetGravity(cd2WorldId worldId, cd2Vec gravity)
{
	cd2World* world = cd2GetWorld(worldId);
	if (world == NULL)
	{
		return;
	}
	if (!cd2IsValidVec(gravity) || world->locked)
	{
		CD2_REFUSE("cd2World_SetGravity: NaN/Inf gravity or locked world");
		return;
	}
	world->gravity = gravity;
}

cd2Vec cd2World_GetGravity(cd2WorldId worldId)
{
	cd2World* world = cd2GetWorld(worldId);
	return world != NULL ? world->gravity : CD2_VEC_ZERO;
}

void cd2World_EnableSleeping(cd2WorldId worldId, bool flag)
{
	cd2World* world = cd2GetWorld(worldId);
	if (world == NULL || world->locked)
	{
		return;
	}
	world->enableSleep = flag;
	if (!flag)
	{
		for (int i = 0; i < world->islands.count; ++i)
		{
			if (world->islands.data[i].inUse)
			{
				cd2WakeIsland(world, i);
			}
		}
	}
}

void cd2World_EnableContinuous(cd2WorldId worldId, bool flag)
{
	cd2World* world = cd2GetWorld(worldId);
	if (world != NULL && !world->locked)
	{
		world->enableContinuous = flag;
	}
}

void* cd2World_GetUserData(cd2WorldId worldId)
{
	cd2World* world = cd2GetWorld(worldId);
	return world != NULL ? world->userData : NULL;
}

void cd2World_SetUserData(cd2WorldId worldId, void* userData)
{
	cd2World* world = cd2GetWorld(worldId);
	if (world != NULL)
	{
		world->userData = userData;
	}
}

double cd2ProfileNow(void)
{
	struct timespec t;
	if (timespec_get(&t, TIME_UTC) == 0)
	{
		return 0.0;
	}
	return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

void cd2World_EnableProfiling(cd2WorldId worldId, bool flag)
{
	cd2World* world = cd2GetWorld(worldId);
	if (world == NULL)
	{
		return;
	}
	world->profiling = flag;
	memset(&world->profile, 0, sizeof(world->profile));
}

cd2Profile cd2World_GetProfile(cd2WorldId worldId)
{
	cd2Profile profile;
	memset(&profile, 0, sizeof(profile));
	cd2World* world = cd2GetWorld(worldId);
	if (world != NULL && world->profiling)
	{
		profile = world->profile;
	}
	return profile;
}

cd2Counters cd2World_GetCounters(cd2WorldId worldId)
{
	cd2Counters c;
	memset(&c, 0, sizeof(c));
	cd2World* world = cd2GetWorld(worldId);
	if (world == NULL)
	{
		return c;
	}
	c.bodyCount = cdIdPool_GetCount(&world->bodyPool);
	c.shapeCount = cdIdPool_GetCount(&world->shapePool);
	c.contactCount = cdIdPool_GetCount(&world->contactPool);
	c.jointCount = cdIdPool_GetCount(&world->jointPool);
	c.islandCount = cdIdPool_GetCount(&world->islandPool);
	for (int i = 0; i < world->contacts.count; ++i)
	{
		const cd2Contact* contact = world->contacts.data + i;
		if (contact->inUse && (contact->flags & CD2_CONTACT_TOUCHING) != 0 &&
			(contact->flags & CD2_CONTACT_SENSOR) == 0)
		{
			c.touchingContactCount += 1;
		}
	}
	for (int i = 0; i < world->bodies.count; ++i)
	{
		const cd2Body* body = world->bodies.data + i;
		if (body->inUse && body->awake && body->type != CD_STATIC_BODY)
		{
			c.awakeBodyCount += 1;
		}
	}
	return c;
}

cd2ContactEvents cd2World_GetContactEvents(cd2WorldId worldId)
{
	cd2ContactEvents events;
	memset(&events, 0, sizeof(events));
	cd2World* world = cd2GetWorld(worldId);
	if (world == NULL)
	{
		return events;
	}
	events.beginEvents = world->beginEvents.data;
	events.beginCount = world->beginEvents.count;
	events.endEvents = world->endEvents.data;
	events.endCount = world->endEvents.count;
	events.hitEvents = world->hitEvents.data;
	events.hitCount = world->hitEvents.count;
	return events;
}

cd2SensorEvents cd2World_GetSensorEvents(cd2WorldId worldId)
{
	cd2SensorEvents events;
	memset(&events, 0, sizeof(events));
	cd2World* world = cd2GetWorld(worldId);
	if (world == NULL)
	{
		return events;
	}
	events.beginEvents = world->sensorBeginEvents.data;
	events.beginCount = world->sensorBeginEvents.count;
	events.endEvents = world->sensorEndEvents.data;
	events.endCount = world->sensorEndEvents.count;
	return events;
}

cd2BodyEvents cd2World_GetBodyEvents(cd2WorldId worldId)
{
	cd2BodyEvents events;
	memset(&events, 0, sizeof(events));
	cd2World* world = cd2GetWorld(worldId);
	if (world == NULL)
	{
		return events;
	}
	events.moveEvents = world->moveEvents.data;
	events.moveCount = world->moveEvents.count;
	return events;
}

cd2JointEvents cd2World_GetJointEvents(cd2WorldId worldId)
{
	cd2JointEvents events;
	memset(&events, 0, sizeof(events));
	cd2World* world = cd2GetWorld(worldId);
	if (world == NULL)
	{
		return events;
	}
	events.jointEvents = world->jointEvents.data;
	events.count = world->jointEvents.count;
	return events;
}

void cd2World_SetPreSolveCallback(cd2WorldId worldId, cd2PreSolveFcn* fcn, void* context)
{
	cd2World* world = cd2GetWorld(worldId);
	if (world == NULL || world->locked)
	{
		return;
	}
	world->preSolveFcn = fcn;
	world->preSolveContext = context;
}

void cd2World_SetCustomFilterCallback(cd2WorldId worldId, cd2CustomFilterFcn* fcn, void* context)
{
	cd2World* world = cd2GetWorld(worldId);
	if (world == NULL || world->locked)
	{
		return;
	}
	world->customFilterFcn = fcn;
	world->customFilterContext = context;
}
