/* collide: islands and sleep. Each step groups the awake dynamic bodies that touch (non-sensor
 * contacts) or are jointed, with a union-find over body indices; a group whose bodies have all
 * been slower than their sleep threshold for CD2_TIME_TO_SLEEP seconds goes to sleep as one
 * island: its bodies leave the solver's arrays and their contacts are no longer updated until
 * something wakes the island (a new touch, a force with wake, a teleport, a joint). The
 * bookkeeping is indices only, nothing 2D-specific beyond the body and contact records. */
#include "world2_internal.h"

#include <stdlib.h>

static int cd2FindRoot(int* parent, int i)
{
	while (parent[i] != i)
	{
		parent[i] = parent[parent[i]];
		i = parent[i];
	}
	return i;
}

static void cd2Union(int* parent, int a, int b)
{
	int ra = cd2FindRoot(parent, a), rb = cd2FindRoot(parent, b);
	if (ra == rb)
	{
		return;
	}
	/* The smaller index becomes the root: the result does not depend on the order of unions. */
	if (ra < rb)
	{
		parent[rb] = ra;
	}
	else
	{
		parent[ra] = rb;
	}
}

static bool cd2IsSleepCandidate(const cd2Body* body)
{
	return body->inUse && body->enabled && body->awake && body->type == CD_DYNAMIC_BODY;
}

void cd2WakeIsland(cd2World* world, int islandId)
{
	if (islandId < 0 || islandId >= world->islands.count || !world->islands.data[islandId].inUse)
	{
		return;
	}
	cd2Island* island = world->islands.data + islandId;
	int b = island->headBody;
	while (b != CD2_NULL_INDEX)
	{
		cd2Body* body = world->bodies.data + b;
		int next = body->islandNext;
		body->awake = true;
		body->sleepTime = CD_R(0.0);
		body->islandId = CD2_NULL_INDEX;
		body->islandNext = CD2_NULL_INDEX;
		b = next;
	}
	island->inUse = false;
	island->headBody = CD2_NULL_INDEX;
	island->bodyCount = 0;
	cdIdPool_Free(&world->islandPool, islandId);
}

/* A new sleeping island; CD2_NULL_INDEX when memory runs out (the bodies then stay awake). */
static int cd2NewIsland(cd2World* world)
{
	int id = cdIdPool_Alloc(&world->islandPool);
	if (id < 0 || !cdArrayReserveFor(world->islands, id + 1))
	{
		if (id >= 0)
		{
			cdIdPool_Free(&world->islandPool, id);
		}
		return CD2_NULL_INDEX;
	}
	if (id >= world->islands.count)
	{
		world->islands.count = id + 1;
	}
	cd2Island* island = world->islands.data + id;
	island->inUse = true;
	island->headBody = CD2_NULL_INDEX;
	island->bodyCount = 0;
	return id;
}

static void cd2PutToSleep(cd2World* world, int islandId, int bodyIndex)
{
	cd2Body* body = world->bodies.data + bodyIndex;
	cd2Island* island = world->islands.data + islandId;
	body->awake = false;
	body->linearVelocity = CD2_VEC_ZERO;
	body->angularVelocity = CD_R(0.0);
	body->islandId = islandId;
	body->islandNext = island->headBody;
	island->headBody = bodyIndex;
	island->bodyCount += 1;
}

/* Builds the groups of the awake dynamic bodies into parent (size bodies.count). */
/* The groups of sleep candidates that touch or are jointed (union-find in parent). candidate[i]
 * receives whether body i is one: the contact and joint passes read it there (a byte each, in
 * cache) instead of two bodies' records at random per contact. */
static void cd2BuildGroups(cd2World* world, int* parent, uint8_t* candidate)
{
	for (int i = 0; i < world->bodies.count; ++i)
	{
		parent[i] = i;
		candidate[i] = cd2IsSleepCandidate(world->bodies.data + i) ? 1u : 0u;
	}
	for (int i = 0; i < world->contacts.count; ++i)
	{
		const cd2Contact* contact = world->contacts.data + i;
		if (!contact->inUse || (contact->flags & CD2_CONTACT_TOUCHING) == 0 ||
			(contact->flags & CD2_CONTACT_SENSOR) != 0)
		{
			continue;
		}
		if (candidate[contact->bodyA] != 0u && candidate[contact->bodyB] != 0u)
		{
			cd2Union(parent, contact->bodyA, contact->bodyB);
		}
	}
	for (int i = 0; i < world->joints.count; ++i)
	{
		const cd2Joint* joint = world->joints.data + i;
		if (!joint->inUse || joint->type == CD2_FILTER_JOINT)
		{
			continue;
		}
		if (candidate[joint->bodyA] != 0u && candidate[joint->bodyB] != 0u)
		{
			cd2Union(parent, joint->bodyA, joint->bodyB);
		}
	}
}

/* Whether a group can sleep at all this step, from the rested bodies alone (bodyIndices[k] for the
 * k with rested[k] != 0): a group sleeps when all its bodies have rested, so a rested dynamic
 * body that touches or is jointed to an awake dynamic body that has not rested cannot be in one.
 * When every rested body has such a neighbour (and no kinematic body rested), the union-find over
 * the world would put nothing to sleep and is passed over; the answer is exact. */
bool cd2SleepPossible(const cd2World* world, const int* bodyIndices, const uint8_t* rested,
					  uint8_t restedMask, int count)
{
	for (int k = 0; k < count; ++k)
	{
		if ((rested[k] & restedMask) == 0u)
		{
			continue;
		}
		const cd2Body* body = world->bodies.data + bodyIndices[k];
		if (body->sleepTime < CD2_TIME_TO_SLEEP)
		{
			continue; /* woken since (a moving kinematic body touches it): its group stays awake */
		}
		if (!cd2IsSleepCandidate(body))
		{
			return true; /* a kinematic body sleeps alone */
		}
		bool blocked = false;
		for (int key = body->headContactKey; key != CD2_NULL_INDEX && !blocked;)
		{
			const cd2Contact* contact = world->contacts.data + cd2EdgeContact(key);
			if (contact->inUse && (contact->flags & CD2_CONTACT_TOUCHING) != 0 &&
				(contact->flags & CD2_CONTACT_SENSOR) == 0)
			{
				const cd2Body* other =
					world->bodies.data + (cd2EdgeSide(key) == 0 ? contact->bodyB : contact->bodyA);
				blocked = cd2IsSleepCandidate(other) && other->sleepTime < CD2_TIME_TO_SLEEP;
			}
			key = contact->nextKey[cd2EdgeSide(key)];
		}
		for (int key = body->headJointKey; key != CD2_NULL_INDEX && !blocked;)
		{
			const cd2Joint* joint = world->joints.data + cd2EdgeContact(key);
			if (joint->inUse && joint->type != CD2_FILTER_JOINT)
			{
				const cd2Body* other =
					world->bodies.data + (cd2EdgeSide(key) == 0 ? joint->bodyB : joint->bodyA);
				blocked = cd2IsSleepCandidate(other) && other->sleepTime < CD2_TIME_TO_SLEEP;
			}
			key = joint->nextKey[cd2EdgeSide(key)];
		}
		if (!blocked)
		{
			return true;
		}
	}
	return false;
}

int cd2UpdateSleep(cd2World* world)
{
	int n = world->bodies.count;
	int slept = 0;
	if (n == 0)
	{
		return 0;
	}
	int* parent = (int*)cdArena_AllocUncleared(&world->arena, (size_t)n * sizeof(int));
	cdReal* minSleep = (cdReal*)cdArena_AllocUncleared(&world->arena, (size_t)n * sizeof(cdReal));
	int* islandOfRoot = (int*)cdArena_AllocUncleared(&world->arena, (size_t)n * sizeof(int));
	uint8_t* candidate = (uint8_t*)cdArena_AllocUncleared(&world->arena, (size_t)n);
	if (parent == NULL || minSleep == NULL || islandOfRoot == NULL || candidate == NULL)
	{
		world->outOfMemory = true;
		return 0;
	}
	cd2BuildGroups(world, parent, candidate);
	for (int i = 0; i < n; ++i)
	{
		minSleep[i] = CD_REAL_MAX;
		islandOfRoot[i] = CD2_NULL_INDEX;
	}
	for (int i = 0; i < n; ++i)
	{
		const cd2Body* body = world->bodies.data + i;
		if (cd2IsSleepCandidate(body))
		{
			int root = cd2FindRoot(parent, i);
			minSleep[root] = cdMin(minSleep[root], body->sleepTime);
		}
	}
	/* Kinematic bodies sleep alone once they stop. */
	for (int i = 0; i < n; ++i)
	{
		const cd2Body* body = world->bodies.data + i;
		if (body->inUse && body->enabled && body->awake && body->type == CD_KINEMATIC_BODY &&
			body->sleepTime >= CD2_TIME_TO_SLEEP)
		{
			int island = cd2NewIsland(world);
			if (island != CD2_NULL_INDEX)
			{
				cd2PutToSleep(world, island, i);
				slept += 1;
			}
		}
	}
	/* Bodies in decreasing index order, so each island's list runs in increasing order. */
	for (int i = n - 1; i >= 0; --i)
	{
		const cd2Body* body = world->bodies.data + i;
		if (!cd2IsSleepCandidate(body))
		{
			continue;
		}
		int root = cd2FindRoot(parent, i);
		if (minSleep[root] < CD2_TIME_TO_SLEEP)
		{
			continue;
		}
		if (islandOfRoot[root] == CD2_NULL_INDEX)
		{
			islandOfRoot[root] = cd2NewIsland(world);
			if (islandOfRoot[root] == CD2_NULL_INDEX)
			{
				minSleep[root] = CD_R(0.0);
				continue;
			}
		}
		cd2PutToSleep(world, islandOfRoot[root], i);
		slept += 1;
	}
	return slept;
}

static int cd2CompareIndicesDescending(const void* a, const void* b)
{
	int x = *(const int*)a, y = *(const int*)b;
	return (x < y) - (x > y);
}

/* Returns an empty island to the pool (memory for its group ran out). */
static void cd2FreeIsland(cd2World* world, int islandId)
{
	world->islands.data[islandId].inUse = false;
	cdIdPool_Free(&world->islandPool, islandId);
}

void cd2SleepBodyGroup(cd2World* world, int bodyIndex)
{
	cd2Body* start = world->bodies.data + bodyIndex;
	if (start->type == CD_STATIC_BODY || !start->awake)
	{
		return;
	}
	if (start->type == CD_KINEMATIC_BODY)
	{
		int island = cd2NewIsland(world);
		if (island != CD2_NULL_INDEX)
		{
			cd2PutToSleep(world, island, bodyIndex);
		}
		return;
	}
	/* The group is the start body's connected part of the touch and joint graph (the edges of
	 * cd2BuildGroups), found by a walk from it: its cost is the group's, not the world's, so that
	 * creating many bodies asleep stays linear. A visited body is marked by the new island's id
	 * (awake candidates have none). */
	if (!cd2IsSleepCandidate(start))
	{
		return; /* disabled: it neither sleeps nor wakes */
	}
	int island = cd2NewIsland(world);
	if (island == CD2_NULL_INDEX)
	{
		return;
	}
	/* Room for every body; left uncleared, so its cost is the group's too. */
	int count = 0;
	int* group = (int*)cdAlloc((size_t)world->bodies.count * sizeof(int));
	if (group == NULL)
	{
		cd2FreeIsland(world, island);
		return;
	}
	group[count++] = bodyIndex;
	start->islandId = island;
	for (int next = 0; next < count; ++next)
	{
		const cd2Body* body = world->bodies.data + group[next];
		for (int pass = 0; pass < 2; ++pass)
		{
			int key = pass == 0 ? body->headContactKey : body->headJointKey;
			while (key != CD2_NULL_INDEX)
			{
				int other = CD2_NULL_INDEX, side = cd2EdgeSide(key);
				if (pass == 0)
				{
					const cd2Contact* contact = world->contacts.data + cd2EdgeContact(key);
					if (contact->inUse && (contact->flags & CD2_CONTACT_TOUCHING) != 0 &&
						(contact->flags & CD2_CONTACT_SENSOR) == 0)
					{
						other = side == 0 ? contact->bodyB : contact->bodyA;
					}
					key = contact->nextKey[side];
				}
				else
				{
					const cd2Joint* joint = world->joints.data + cd2EdgeContact(key);
					if (joint->inUse && joint->type != CD2_FILTER_JOINT)
					{
						other = side == 0 ? joint->bodyB : joint->bodyA;
					}
					key = joint->nextKey[side];
				}
				cd2Body* neighbour = other == CD2_NULL_INDEX ? NULL : world->bodies.data + other;
				if (neighbour == NULL || !cd2IsSleepCandidate(neighbour) || neighbour->islandId == island)
				{
					continue;
				}
				neighbour->islandId = island;
				group[count++] = other;
			}
		}
	}
	/* In decreasing index order, so that the island's list runs in increasing order, as the
	 * step's own sleeping does. */
	qsort(group, (size_t)count, sizeof(int), cd2CompareIndicesDescending);
	for (int i = 0; i < count; ++i)
	{
		cd2PutToSleep(world, island, group[i]);
	}
	cdFree(group);
}

void cd2RemoveBodyFromIsland(cd2World* world, int bodyIndex)
{
	cd2Body* body = world->bodies.data + bodyIndex;
	if (body->islandId == CD2_NULL_INDEX)
	{
		return;
	}
	cd2WakeIsland(world, body->islandId);
}
