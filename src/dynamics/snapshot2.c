/* collide: snapshots of a 2D world. The state is plain data (records that hold indices, never
 * pointers other than user data), so it is written array by array: the settings, the bodies,
 * shapes, chains, contacts (with their warm-start impulses), joints (with theirs), sleeping
 * islands and the id pools' free lists. The broadphase is not written: it is rebuilt from the
 * shapes' fat boxes, which is all that its answers depend on (pairs are sorted by shape index
 * before they become contacts, so proxy ids never reach the simulation). */
#include "world2_internal.h"
#include "../broad/broad_internal.h"

#define CD2_STATE_MAGIC 0x53324443u /* "CD2S" */
#define CD2_STATE_VERSION 4u

typedef struct cd2StateHeader
{
	uint32_t magic, version, realSize;
	uint32_t recordSizes[6];
	uint64_t totalSize, checksum;
} cd2StateHeader;

/* A checksum of everything after the header: a buffer damaged in storage or transit (a flipped
 * bit, a cut) is refused whole instead of restoring records whose links (shape lists, contact
 * and joint edges, islands) would point anywhere; those links are not checked one by one. */
static uint64_t cd2Checksum(const unsigned char* data, size_t size)
{
	uint64_t h = 0x9e3779b97f4a7c15u ^ (uint64_t)size;
	size_t i = 0;
	for (; i + 8 <= size; i += 8)
	{
		uint64_t word;
		memcpy(&word, data + i, sizeof word);
		h = (h ^ word) * 0xff51afd7ed558ccdu;
		h ^= h >> 29;
	}
	for (; i < size; ++i)
	{
		h = (h ^ data[i]) * 0x100000001b3u;
	}
	return h ^ (h >> 32);
}

typedef struct cd2StateSettings
{
	cd2Vec gravity;
	cdReal restitutionThreshold, hitEventThreshold, contactHertz, contactDampingRatio, contactPushMaxVelocity,
		jointHertz, jointDampingRatio, maximumLinearSpeed, contactRecycleDistance;
	uint32_t enableSleep, enableContinuous;
} cd2StateSettings;

typedef struct cd2Writer
{
	unsigned char* out; /* NULL: only count */
	size_t size;
} cd2Writer;

static void cd2Write(cd2Writer* w, const void* data, size_t size)
{
	if (w->out != NULL && size > 0)
	{
		memcpy(w->out + w->size, data, size);
	}
	w->size += size;
}

static void cd2WriteArray(cd2Writer* w, const void* data, int count, size_t elementSize)
{
	int32_t n = count;
	cd2Write(w, &n, sizeof(n));
	cd2Write(w, data, (size_t)count * elementSize);
}

static void cd2WritePool(cd2Writer* w, const cdIdPool* pool)
{
	int32_t next = pool->nextIndex;
	cd2Write(w, &next, sizeof(next));
	cd2WriteArray(w, pool->freeIds, pool->freeCount, sizeof(int));
}

static void cd2WriteState(const cd2World* world, cd2Writer* w)
{
	cd2StateHeader header;
	memset(&header, 0, sizeof(header));
	header.magic = CD2_STATE_MAGIC;
	header.version = CD2_STATE_VERSION;
	header.realSize = (uint32_t)sizeof(cdReal);
	header.recordSizes[0] = (uint32_t)sizeof(cd2Body);
	header.recordSizes[1] = (uint32_t)sizeof(cd2WorldShape);
	header.recordSizes[2] = (uint32_t)sizeof(cd2ChainRec);
	header.recordSizes[3] = (uint32_t)sizeof(cd2Contact);
	header.recordSizes[4] = (uint32_t)sizeof(cd2Joint);
	header.recordSizes[5] = (uint32_t)sizeof(cd2Island);
	size_t headerAt = w->size;
	cd2Write(w, &header, sizeof(header));
	cd2StateSettings settings;
	memset(&settings, 0, sizeof(settings));
	settings.gravity = world->gravity;
	settings.restitutionThreshold = world->restitutionThreshold;
	settings.hitEventThreshold = world->hitEventThreshold;
	settings.contactHertz = world->contactHertz;
	settings.contactDampingRatio = world->contactDampingRatio;
	settings.contactPushMaxVelocity = world->contactPushMaxVelocity;
	settings.jointHertz = world->jointHertz;
	settings.jointDampingRatio = world->jointDampingRatio;
	settings.maximumLinearSpeed = world->maximumLinearSpeed;
	settings.contactRecycleDistance = world->contactRecycleDistance;
	settings.enableSleep = world->enableSleep;
	settings.enableContinuous = world->enableContinuous;
	cd2Write(w, &settings, sizeof(settings));
	cd2WriteArray(w, world->bodies.data, world->bodies.count, sizeof(cd2Body));
	cd2WriteArray(w, world->shapes.data, world->shapes.count, sizeof(cd2WorldShape));
	cd2WriteArray(w, world->chains.data, world->chains.count, sizeof(cd2ChainRec));
	cd2WriteArray(w, world->contacts.data, world->contacts.count, sizeof(cd2Contact));
	cd2WriteArray(w, world->joints.data, world->joints.count, sizeof(cd2Joint));
	cd2WriteArray(w, world->islands.data, world->islands.count, sizeof(cd2Island));
	cd2WritePool(w, &world->bodyPool);
	cd2WritePool(w, &world->shapePool);
	cd2WritePool(w, &world->chainPool);
	cd2WritePool(w, &world->contactPool);
	cd2WritePool(w, &world->jointPool);
	cd2WritePool(w, &world->islandPool);
	if (w->out != NULL)
	{
		header.totalSize = (uint64_t)(w->size - headerAt);
		header.checksum =
			cd2Checksum(w->out + headerAt + sizeof(header), w->size - headerAt - sizeof(header));
		memcpy(w->out + headerAt, &header, sizeof(header));
	}
}

size_t cd2World_GetStateSize(cd2WorldId worldId)
{
	cd2World* world = cd2GetWorld(worldId);
	if (world == NULL)
	{
		return 0;
	}
	cd2Writer w = {NULL, 0};
	cd2WriteState(world, &w);
	return w.size;
}

cdResult cd2World_SaveState(cd2WorldId worldId, void* buffer, size_t capacity)
{
	cd2World* world = cd2GetWorld(worldId);
	if (world == NULL || buffer == NULL || world->locked)
	{
		return CD_ERROR_INVALID_ARGUMENT;
	}
	cd2Writer counter = {NULL, 0};
	cd2WriteState(world, &counter);
	if (capacity < counter.size)
	{
		return CD_ERROR_INVALID_ARGUMENT;
	}
	cd2Writer w = {(unsigned char*)buffer, 0};
	cd2WriteState(world, &w);
	return CD_OK;
}

/* ---- restore ------------------------------------------------------------------------------------ */
typedef struct cd2Reader
{
	const unsigned char* in;
	size_t size, at;
	bool failed;
} cd2Reader;

static void cd2Read(cd2Reader* r, void* out, size_t size)
{
	if (r->failed || size > r->size - r->at)
	{
		r->failed = true;
		return;
	}
	if (size > 0)
	{
		memcpy(out, r->in + r->at, size);
	}
	r->at += size;
}

/* Reads an array into freshly allocated memory (*data, NULL when empty) with its count. */
static void cd2ReadArray(cd2Reader* r, void** data, int* count, int* capacity, size_t elementSize)
{
	int32_t n = 0;
	cd2Read(r, &n, sizeof(n));
	*data = NULL;
	*count = 0;
	*capacity = 0;
	if (r->failed || n < 0 || (size_t)n > (r->size - r->at) / (elementSize > 0 ? elementSize : 1))
	{
		r->failed = true;
		return;
	}
	if (n == 0)
	{
		return;
	}
	if (!cdArrayReserve(data, capacity, n, elementSize))
	{
		r->failed = true;
		return;
	}
	cd2Read(r, *data, (size_t)n * elementSize);
	*count = n;
}

static void cd2ReadPool(cd2Reader* r, cdIdPool* pool)
{
	int32_t next = 0;
	cd2Read(r, &next, sizeof(next));
	memset(pool, 0, sizeof(*pool));
	pool->nextIndex = next;
	cd2ReadArray(r, (void**)&pool->freeIds, &pool->freeCount, &pool->freeCapacity, sizeof(int));
	if (next < 0)
	{
		r->failed = true;
	}
}

typedef struct cd2LoadedState
{
	cd2StateSettings settings;
	CD_ARRAY(cd2Body) bodies;
	CD_ARRAY(cd2WorldShape) shapes;
	CD_ARRAY(cd2ChainRec) chains;
	CD_ARRAY(cd2Contact) contacts;
	CD_ARRAY(cd2Joint) joints;
	CD_ARRAY(cd2Island) islands;
	cdIdPool pools[6];
} cd2LoadedState;

static void cd2FreeLoaded(cd2LoadedState* s)
{
	cdArrayFree(s->bodies);
	cdArrayFree(s->shapes);
	cdArrayFree(s->chains);
	cdArrayFree(s->contacts);
	cdArrayFree(s->joints);
	cdArrayFree(s->islands);
	for (int i = 0; i < 6; ++i)
	{
		cdIdPool_Destroy(&s->pools[i]);
	}
}

cdResult cd2World_RestoreState(cd2WorldId worldId, const void* buffer, size_t size)
{
	cd2World* world = cd2GetWorld(worldId);
	if (world == NULL || buffer == NULL || world->locked)
	{
		return CD_ERROR_INVALID_ARGUMENT;
	}
	cd2Reader r = {(const unsigned char*)buffer, size, 0, false};
	cd2StateHeader header;
	cd2Read(&r, &header, sizeof(header));
	if (r.failed || header.magic != CD2_STATE_MAGIC || header.version != CD2_STATE_VERSION ||
		header.realSize != sizeof(cdReal) || header.recordSizes[0] != sizeof(cd2Body) ||
		header.recordSizes[1] != sizeof(cd2WorldShape) || header.recordSizes[2] != sizeof(cd2ChainRec) ||
		header.recordSizes[3] != sizeof(cd2Contact) || header.recordSizes[4] != sizeof(cd2Joint) ||
		header.recordSizes[5] != sizeof(cd2Island) || header.totalSize > size ||
		header.totalSize < sizeof(header) ||
		cd2Checksum((const unsigned char*)buffer + sizeof(header),
					(size_t)header.totalSize - sizeof(header)) != header.checksum)
	{
		return CD_ERROR_PARSE;
	}
	cd2LoadedState s;
	memset(&s, 0, sizeof(s));
	cd2Read(&r, &s.settings, sizeof(s.settings));
	cd2ReadArray(&r, (void**)&s.bodies.data, &s.bodies.count, &s.bodies.capacity, sizeof(cd2Body));
	cd2ReadArray(&r, (void**)&s.shapes.data, &s.shapes.count, &s.shapes.capacity, sizeof(cd2WorldShape));
	cd2ReadArray(&r, (void**)&s.chains.data, &s.chains.count, &s.chains.capacity, sizeof(cd2ChainRec));
	cd2ReadArray(&r, (void**)&s.contacts.data, &s.contacts.count, &s.contacts.capacity, sizeof(cd2Contact));
	cd2ReadArray(&r, (void**)&s.joints.data, &s.joints.count, &s.joints.capacity, sizeof(cd2Joint));
	cd2ReadArray(&r, (void**)&s.islands.data, &s.islands.count, &s.islands.capacity, sizeof(cd2Island));
	for (int i = 0; i < 6; ++i)
	{
		cd2ReadPool(&r, &s.pools[i]);
	}
	/* Structural checks so that a corrupt buffer cannot make indices point outside the arrays. */
	bool ok = !r.failed && s.pools[0].nextIndex == s.bodies.count && s.pools[1].nextIndex == s.shapes.count &&
			  s.pools[2].nextIndex == s.chains.count && s.pools[3].nextIndex == s.contacts.count &&
			  s.pools[4].nextIndex == s.joints.count && s.pools[5].nextIndex == s.islands.count;
	for (int i = 0; ok && i < s.shapes.count; ++i)
	{
		const cd2WorldShape* shape = s.shapes.data + i;
		ok = !shape->inUse || (shape->body >= 0 && shape->body < s.bodies.count);
	}
	for (int i = 0; ok && i < s.contacts.count; ++i)
	{
		const cd2Contact* c = s.contacts.data + i;
		ok = !c->inUse ||
			 (c->shapeA >= 0 && c->shapeA < s.shapes.count && c->shapeB >= 0 && c->shapeB < s.shapes.count &&
			  c->bodyA >= 0 && c->bodyA < s.bodies.count && c->bodyB >= 0 && c->bodyB < s.bodies.count);
	}
	for (int i = 0; ok && i < s.joints.count; ++i)
	{
		const cd2Joint* j = s.joints.data + i;
		ok = !j->inUse ||
			 (j->bodyA >= 0 && j->bodyA < s.bodies.count && j->bodyB >= 0 && j->bodyB < s.bodies.count);
	}
	if (!ok)
	{
		cd2FreeLoaded(&s);
		return r.failed ? CD_ERROR_PARSE : CD_ERROR_PARSE;
	}
	/* A fresh broadphase with the saved fat boxes. */
	cd2BroadPhaseDef bpDef = cd2DefaultBroadPhaseDef();
	bpDef.type = CD_BROADPHASE_TREE;
	bpDef.margin = CD_R(0.0);
	bpDef.displacementMultiplier = CD_R(0.0);
	cd2BroadPhase* bp = NULL;
	if (cd2BroadPhase_Create(&bpDef, &bp) != CD_OK)
	{
		cd2FreeLoaded(&s);
		return CD_ERROR_OUT_OF_MEMORY;
	}
	cd2BroadPhase_SetEnlargeMoves(bp, true);
	cd2BroadPhase* staticBp = NULL;
	if (cd2BroadPhase_Create(&bpDef, &staticBp) != CD_OK)
	{
		cd2BroadPhase_Destroy(bp);
		cd2FreeLoaded(&s);
		return CD_ERROR_OUT_OF_MEMORY;
	}
	cdPairSet pairs;
	memset(&pairs, 0, sizeof(pairs));
	bool memoryOk = true;
	int staticProxyCount = 0;
	for (int i = 0; i < s.shapes.count && memoryOk; ++i)
	{
		cd2WorldShape* shape = s.shapes.data + i;
		shape->staticProxyId = CD_NULL_PROXY;
		if (!shape->inUse || shape->proxyId == CD_NULL_PROXY)
		{
			continue;
		}
		bool isStatic = s.bodies.data[shape->body].type == CD_STATIC_BODY;
		shape->proxyId = cd2BroadPhase_CreateProxy(bp, shape->fatAabb, cd2ProxyUserData(i, isStatic));
		memoryOk = shape->proxyId != CD_NULL_PROXY;
		if (isStatic && memoryOk)
		{
			staticProxyCount += 1;
			shape->staticProxyId =
				cd2BroadPhase_CreateProxy(staticBp, shape->fatAabb, cd2ProxyUserData(i, true));
			memoryOk = shape->staticProxyId != CD_NULL_PROXY;
		}
	}
	for (int i = 0; i < s.contacts.count && memoryOk; ++i)
	{
		const cd2Contact* c = s.contacts.data + i;
		if (c->inUse)
		{
			memoryOk = cdPairSet_Add(&pairs, cdPairKey(c->shapeA, c->shapeB));
		}
	}
	if (!memoryOk)
	{
		cd2BroadPhase_Destroy(bp);
		cd2BroadPhase_Destroy(staticBp);
		cdPairSet_Destroy(&pairs);
		cd2FreeLoaded(&s);
		return CD_ERROR_OUT_OF_MEMORY;
	}
	/* Commit. */
	cd2BroadPhase_Destroy(world->broadPhase);
	world->broadPhase = bp;
	cd2BroadPhase_Destroy(world->staticBroadPhase);
	world->staticBroadPhase = staticBp;
	world->staticProxyCount = staticProxyCount;
	cdPairSet_Destroy(&world->pairs);
	world->pairs = pairs;
	cdArrayFree(world->bodies);
	cdArrayFree(world->shapes);
	cdArrayFree(world->chains);
	cdArrayFree(world->contacts);
	cdArrayFree(world->joints);
	cdArrayFree(world->islands);
	world->bodies.data = s.bodies.data;
	world->bodies.count = s.bodies.count;
	world->bodies.capacity = s.bodies.capacity;
	world->shapes.data = s.shapes.data;
	world->shapes.count = s.shapes.count;
	world->shapes.capacity = s.shapes.capacity;
	world->chains.data = s.chains.data;
	world->chains.count = s.chains.count;
	world->chains.capacity = s.chains.capacity;
	world->contacts.data = s.contacts.data;
	world->contacts.count = s.contacts.count;
	world->contacts.capacity = s.contacts.capacity;
	world->sensorContactCount = 0;
	for (int i = 0; i < world->contacts.count; ++i)
	{
		const cd2Contact* contact = world->contacts.data + i;
		world->sensorContactCount += contact->inUse && (contact->flags & CD2_CONTACT_SENSOR) != 0 ? 1 : 0;
	}
	world->joints.data = s.joints.data;
	world->joints.count = s.joints.count;
	world->joints.capacity = s.joints.capacity;
	world->islands.data = s.islands.data;
	world->islands.count = s.islands.count;
	world->islands.capacity = s.islands.capacity;
	cdIdPool* pools[6] = {&world->bodyPool,	   &world->shapePool, &world->chainPool,
						  &world->contactPool, &world->jointPool, &world->islandPool};
	for (int i = 0; i < 6; ++i)
	{
		cdIdPool_Destroy(pools[i]);
		*pools[i] = s.pools[i];
	}
	world->gravity = s.settings.gravity;
	world->restitutionThreshold = s.settings.restitutionThreshold;
	world->hitEventThreshold = s.settings.hitEventThreshold;
	world->contactHertz = s.settings.contactHertz;
	world->contactDampingRatio = s.settings.contactDampingRatio;
	world->contactPushMaxVelocity = s.settings.contactPushMaxVelocity;
	world->jointHertz = s.settings.jointHertz;
	world->jointDampingRatio = s.settings.jointDampingRatio;
	world->maximumLinearSpeed = s.settings.maximumLinearSpeed;
	/* NaN or negative from a corrupt buffer: off. */
	world->contactRecycleDistance =
		s.settings.contactRecycleDistance >= CD_R(0.0) ? s.settings.contactRecycleDistance : CD_R(0.0);
	world->enableSleep = s.settings.enableSleep != 0;
	world->enableContinuous = s.settings.enableContinuous != 0;
	world->beginEvents.count = 0;
	world->endEvents.count = 0;
	world->hitEvents.count = 0;
	world->sensorBeginEvents.count = 0;
	world->sensorEndEvents.count = 0;
	world->moveEvents.count = 0;
	world->jointEvents.count = 0;
	world->stepEndEventCount = 0;
	world->stepSensorEndEventCount = 0;
	/* The awake sets are derived: the next sleep check builds them from the restored links. */
	cd2AwakeSets_Invalidate(world);
	return CD_OK;
}
