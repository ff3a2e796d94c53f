/* collide: islands and sleep. The awake dynamic bodies are kept in persistent sets (see
 * cd2AwakeSets in world2_internal.h): bodies that touch (non-sensor contacts) or are jointed share
 * a set; sets merge when such a link appears and are split, lazily, only when one may hold a group
 * that can sleep. A group whose bodies have all been slower than their sleep threshold for
 * CD2_TIME_TO_SLEEP seconds goes to sleep as one island: its bodies leave the solver's arrays and
 * their contacts are no longer updated until something wakes the island (a new touch, a force with
 * wake, a teleport, a joint). So the step's sleep check reads the awake bodies' rest flags and
 * splits only the sets it must, instead of grouping every touch and joint of the world. The
 * bookkeeping is indices only, nothing 2D-specific beyond the body and contact
 * records. */
#include "world2_internal.h"

#include <stdint.h>
#include <stdlib.h>

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
		cd2AwakeSets_SyncBody(world, b);
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
	cd2AwakeSets_SyncBody(world, bodyIndex);
}

/* ---- awake sets ------------------------------------------------------------------------------ */

/* The bodies linked to a body for sleeping: through its touching non-sensor contacts and its
 * joints other than filter joints, one after another (cd2NextLinked). */
typedef struct cd2LinkWalk
{
	int contactKey, jointKey;
} cd2LinkWalk;

static cd2LinkWalk cd2BeginLinkWalk(const cd2Body* body)
{
	cd2LinkWalk walk = {body->headContactKey, body->headJointKey};
	return walk;
}

/* The next linked body, CD2_NULL_INDEX when there is none. */
static int cd2NextLinked(const cd2World* world, cd2LinkWalk* walk)
{
	while (walk->contactKey != CD2_NULL_INDEX)
	{
		const cd2Contact* contact = world->contacts.data + cd2EdgeContact(walk->contactKey);
		int side = cd2EdgeSide(walk->contactKey);
		walk->contactKey = contact->nextKey[side];
		if (contact->inUse &&
			(contact->flags & (CD2_CONTACT_TOUCHING | CD2_CONTACT_SENSOR)) == CD2_CONTACT_TOUCHING)
		{
			return side == 0 ? contact->bodyB : contact->bodyA;
		}
	}
	while (walk->jointKey != CD2_NULL_INDEX)
	{
		const cd2Joint* joint = world->joints.data + cd2EdgeContact(walk->jointKey);
		int side = cd2EdgeSide(walk->jointKey);
		walk->jointKey = joint->nextKey[side];
		if (joint->inUse && joint->type != CD2_FILTER_JOINT)
		{
			return side == 0 ? joint->bodyB : joint->bodyA;
		}
	}
	return CD2_NULL_INDEX;
}

/* The set of a body, CD2_NULL_INDEX when it is in none. */
static int cd2SetOf(const cd2AwakeSets* sets, int bodyIndex)
{
	return bodyIndex < sets->links.count ? sets->links.data[bodyIndex].set : CD2_NULL_INDEX;
}

/* A link per body (new ones in no set); false when memory runs out. */
static bool cd2ReserveAwakeLinks(cd2World* world)
{
	cd2AwakeSets* sets = &world->awakeSets;
	int n = world->bodies.count;
	if (sets->links.count >= n)
	{
		return true;
	}
	if (!cdArrayReserveFor(sets->links, n))
	{
		return false;
	}
	for (int i = sets->links.count; i < n; ++i)
	{
		cd2AwakeLink* link = sets->links.data + i;
		link->set = CD2_NULL_INDEX;
		link->prev = CD2_NULL_INDEX;
		link->next = CD2_NULL_INDEX;
	}
	sets->links.count = n;
	return true;
}

/* An empty clean set; CD2_NULL_INDEX when memory runs out. The free list always has room for
 * every set, so freeing one never fails. */
static int cd2NewAwakeSet(cd2World* world)
{
	cd2AwakeSets* sets = &world->awakeSets;
	int id;
	if (sets->freeSets.count > 0)
	{
		id = sets->freeSets.data[--sets->freeSets.count];
	}
	else
	{
		if (!cdArrayReserveFor(sets->sets, sets->sets.count + 1) ||
			!cdArrayReserveFor(sets->freeSets, sets->sets.count + 1))
		{
			return CD2_NULL_INDEX;
		}
		id = sets->sets.count++;
	}
	cd2AwakeSet* set = sets->sets.data + id;
	set->headBody = CD2_NULL_INDEX;
	set->bodyCount = 0;
	set->restlessStamp = 0;
	set->queuedStamp = 0;
	set->dirty = false;
	return id;
}

static void cd2FreeAwakeSet(cd2AwakeSets* sets, int id)
{
	sets->sets.data[id].bodyCount = 0;
	sets->sets.data[id].headBody = CD2_NULL_INDEX;
	sets->freeSets.data[sets->freeSets.count++] = id;
}

static void cd2InsertAwake(cd2AwakeSets* sets, int id, int bodyIndex)
{
	cd2AwakeSet* set = sets->sets.data + id;
	cd2AwakeLink* link = sets->links.data + bodyIndex;
	link->set = id;
	link->prev = CD2_NULL_INDEX;
	link->next = set->headBody;
	if (set->headBody != CD2_NULL_INDEX)
	{
		sets->links.data[set->headBody].prev = bodyIndex;
	}
	set->headBody = bodyIndex;
	set->bodyCount += 1;
}

/* Takes the body out of its set; what stays may have come apart (dirty). */
static void cd2RemoveAwake(cd2AwakeSets* sets, int bodyIndex)
{
	cd2AwakeLink* link = sets->links.data + bodyIndex;
	cd2AwakeSet* set = sets->sets.data + link->set;
	if (link->prev != CD2_NULL_INDEX)
	{
		sets->links.data[link->prev].next = link->next;
	}
	else
	{
		set->headBody = link->next;
	}
	if (link->next != CD2_NULL_INDEX)
	{
		sets->links.data[link->next].prev = link->prev;
	}
	set->bodyCount -= 1;
	if (set->bodyCount == 0)
	{
		cd2FreeAwakeSet(sets, link->set);
	}
	else
	{
		set->dirty = true;
	}
	link->set = CD2_NULL_INDEX;
	link->prev = CD2_NULL_INDEX;
	link->next = CD2_NULL_INDEX;
}

/* Moves the smaller set's bodies into the larger one. */
static void cd2MergeAwakeSets(cd2AwakeSets* sets, int a, int b)
{
	if (sets->sets.data[a].bodyCount < sets->sets.data[b].bodyCount)
	{
		int t = a;
		a = b;
		b = t;
	}
	cd2AwakeSet* big = sets->sets.data + a;
	cd2AwakeSet* small = sets->sets.data + b;
	int last = CD2_NULL_INDEX;
	for (int i = small->headBody; i != CD2_NULL_INDEX; i = sets->links.data[i].next)
	{
		sets->links.data[i].set = a;
		last = i;
	}
	if (last != CD2_NULL_INDEX)
	{
		sets->links.data[last].next = big->headBody;
		if (big->headBody != CD2_NULL_INDEX)
		{
			sets->links.data[big->headBody].prev = last;
		}
		big->headBody = small->headBody;
	}
	big->bodyCount += small->bodyCount;
	big->dirty = big->dirty || small->dirty;
	cd2FreeAwakeSet(sets, b);
}

void cd2AwakeSets_Invalidate(cd2World* world)
{
	world->awakeSets.valid = false;
}

void cd2AwakeSets_Destroy(cd2World* world)
{
	cdArrayFree(world->awakeSets.sets);
	cdArrayFree(world->awakeSets.freeSets);
	cdArrayFree(world->awakeSets.links);
	world->awakeSets.valid = false;
}

void cd2AwakeSets_Link(cd2World* world, int bodyA, int bodyB)
{
	cd2AwakeSets* sets = &world->awakeSets;
	if (!sets->valid)
	{
		return;
	}
	int a = cd2SetOf(sets, bodyA), b = cd2SetOf(sets, bodyB);
	if (a != CD2_NULL_INDEX && b != CD2_NULL_INDEX && a != b)
	{
		cd2MergeAwakeSets(sets, a, b);
	}
}

void cd2AwakeSets_Unlink(cd2World* world, int bodyA, int bodyB)
{
	cd2AwakeSets* sets = &world->awakeSets;
	if (!sets->valid)
	{
		return;
	}
	int a = cd2SetOf(sets, bodyA);
	if (a != CD2_NULL_INDEX && a == cd2SetOf(sets, bodyB))
	{
		sets->sets.data[a].dirty = true;
	}
}

void cd2AwakeSets_SyncBody(cd2World* world, int bodyIndex)
{
	cd2AwakeSets* sets = &world->awakeSets;
	if (!sets->valid)
	{
		return;
	}
	const cd2Body* body = world->bodies.data + bodyIndex;
	bool candidate = cd2IsSleepCandidate(body);
	int current = cd2SetOf(sets, bodyIndex);
	if (candidate == (current != CD2_NULL_INDEX))
	{
		return;
	}
	if (!candidate)
	{
		cd2RemoveAwake(sets, bodyIndex);
		return;
	}
	int id = cd2ReserveAwakeLinks(world) ? cd2NewAwakeSet(world) : CD2_NULL_INDEX;
	if (id == CD2_NULL_INDEX)
	{
		sets->valid = false; /* rebuilt by the next sleep check */
		return;
	}
	cd2InsertAwake(sets, id, bodyIndex);
	cd2LinkWalk walk = cd2BeginLinkWalk(body);
	for (int other = cd2NextLinked(world, &walk); other != CD2_NULL_INDEX;
		 other = cd2NextLinked(world, &walk))
	{
		cd2AwakeSets_Link(world, bodyIndex, other);
	}
}

/* Gathers the bodies reachable from those already in sets->sets[id] (listed in queue[0, count))
 * through links to awake dynamic bodies in no set, into the set and the queue; returns the
 * queue's new length. restless receives whether one of them has not rested. */
static int cd2FloodAwakeSet(cd2World* world, int id, int* queue, int count, bool* restless)
{
	cd2AwakeSets* sets = &world->awakeSets;
	for (int head = 0; head < count; ++head)
	{
		const cd2Body* body = world->bodies.data + queue[head];
		*restless = *restless || body->sleepTime < CD2_TIME_TO_SLEEP;
		cd2LinkWalk walk = cd2BeginLinkWalk(body);
		for (int other = cd2NextLinked(world, &walk); other != CD2_NULL_INDEX;
			 other = cd2NextLinked(world, &walk))
		{
			if (sets->links.data[other].set == CD2_NULL_INDEX &&
				cd2IsSleepCandidate(world->bodies.data + other))
			{
				cd2InsertAwake(sets, id, other);
				queue[count++] = other;
			}
		}
	}
	return count;
}

/* Builds the sets anew: each one connected group (clean). False when memory runs out. */
static bool cd2RebuildAwakeSets(cd2World* world)
{
	cd2AwakeSets* sets = &world->awakeSets;
	sets->sets.count = 0;
	sets->freeSets.count = 0;
	sets->links.count = 0;
	int n = world->bodies.count;
	if (!cd2ReserveAwakeLinks(world))
	{
		return false;
	}
	int* queue = n > 0 ? (int*)cdArena_AllocUncleared(&world->arena, (size_t)n * sizeof(int)) : NULL;
	if (n > 0 && queue == NULL)
	{
		return false;
	}
	for (int i = 0; i < n; ++i)
	{
		if (sets->links.data[i].set != CD2_NULL_INDEX || !cd2IsSleepCandidate(world->bodies.data + i))
		{
			continue;
		}
		int id = cd2NewAwakeSet(world);
		if (id == CD2_NULL_INDEX)
		{
			return false;
		}
		cd2InsertAwake(sets, id, i);
		queue[0] = i;
		bool restless = false;
		(void)cd2FloodAwakeSet(world, id, queue, 1, &restless);
	}
	sets->valid = true;
	return true;
}

/* Splits a dirty set into its connected groups (clean sets), appended to parts; returns how many,
 * or -1 when memory ran out (the sets are then invalid). restlessParts[k] receives whether part k
 * holds a body that has not rested. */
static int cd2SplitAwakeSet(cd2World* world, int id, int* parts, bool* restlessParts)
{
	cd2AwakeSets* sets = &world->awakeSets;
	int count = sets->sets.data[id].bodyCount;
	int* members = (int*)cdArena_AllocUncleared(&world->arena, 2 * (size_t)count * sizeof(int));
	if (members == NULL)
	{
		sets->valid = false;
		return -1;
	}
	int* queue = members + count;
	int n = 0;
	for (int b = sets->sets.data[id].headBody; b != CD2_NULL_INDEX; b = sets->links.data[b].next)
	{
		members[n++] = b;
	}
	for (int i = 0; i < n; ++i)
	{
		cd2AwakeLink* link = sets->links.data + members[i];
		link->set = CD2_NULL_INDEX;
		link->prev = CD2_NULL_INDEX;
		link->next = CD2_NULL_INDEX;
	}
	cd2FreeAwakeSet(sets, id);
	int partCount = 0;
	for (int i = 0; i < n; ++i)
	{
		if (sets->links.data[members[i]].set != CD2_NULL_INDEX)
		{
			continue;
		}
		int part = cd2NewAwakeSet(world);
		if (part == CD2_NULL_INDEX)
		{
			sets->valid = false;
			return -1;
		}
		cd2InsertAwake(sets, part, members[i]);
		queue[0] = members[i];
		bool restless = false;
		(void)cd2FloodAwakeSet(world, part, queue, 1, &restless);
		parts[partCount] = part;
		restlessParts[partCount] = restless;
		partCount += 1;
	}
	return partCount;
}

/* Whether a rested dynamic body has no linked awake dynamic body that has not rested: without one,
 * no group holding it can sleep, and its set is not looked at. */
static bool cd2RestsAmongRested(const cd2World* world, const cd2Body* body)
{
	cd2LinkWalk walk = cd2BeginLinkWalk(body);
	for (int other = cd2NextLinked(world, &walk); other != CD2_NULL_INDEX;
		 other = cd2NextLinked(world, &walk))
	{
		const cd2Body* neighbour = world->bodies.data + other;
		if (cd2IsSleepCandidate(neighbour) && neighbour->sleepTime < CD2_TIME_TO_SLEEP)
		{
			return false;
		}
	}
	return true;
}

static int cd2CompareIndicesDescending(const void* a, const void* b)
{
	int x = *(const int*)a, y = *(const int*)b;
	return (x < y) - (x > y);
}

typedef struct cd2SleepingGroup
{
	int set;
	int maxBody;
} cd2SleepingGroup;

static int cd2CompareGroupsDescending(const void* a, const void* b)
{
	int x = ((const cd2SleepingGroup*)a)->maxBody, y = ((const cd2SleepingGroup*)b)->maxBody;
	return (x < y) - (x > y);
}

int cd2UpdateSleep(cd2World* world, const int* bodyIndices, const uint8_t* flags, int count)
{
	cd2AwakeSets* sets = &world->awakeSets;
	if (count == 0)
	{
		return 0;
	}
	if (!sets->valid && !cd2RebuildAwakeSets(world))
	{
		world->outOfMemory = true;
		return 0;
	}
	if (sets->stamp == INT32_MAX)
	{
		for (int i = 0; i < sets->sets.count; ++i)
		{
			sets->sets.data[i].restlessStamp = 0;
			sets->sets.data[i].queuedStamp = 0;
		}
		sets->stamp = 0;
	}
	int stamp = ++sets->stamp;
	/* The sets to look at: those of the rested bodies whose linked bodies have all rested. Every
	 * set holding a body that has not rested is marked restless. */
	int* queued = (int*)cdArena_AllocUncleared(&world->arena, (size_t)count * sizeof(int));
	cd2SleepingGroup* groups =
		(cd2SleepingGroup*)cdArena_AllocUncleared(&world->arena, (size_t)count * sizeof(cd2SleepingGroup));
	int* parts = (int*)cdArena_AllocUncleared(&world->arena, (size_t)count * sizeof(int));
	bool* restlessParts = (bool*)cdArena_AllocUncleared(&world->arena, (size_t)count * sizeof(bool));
	if (queued == NULL || groups == NULL || parts == NULL || restlessParts == NULL)
	{
		world->outOfMemory = true;
		return 0;
	}
	int queuedCount = 0;
	bool kinematicRested = false;
	for (int k = 0; k < count; ++k)
	{
		unsigned f = flags[k];
		if ((f & CD2_FINAL_KINEMATIC) != 0u)
		{
			kinematicRested = kinematicRested || (f & CD2_FINAL_RESTED) != 0u;
			continue;
		}
		int id = cd2SetOf(sets, bodyIndices[k]);
		if (id == CD2_NULL_INDEX)
		{
			continue;
		}
		cd2AwakeSet* set = sets->sets.data + id;
		/* (A body that rested in finalize may have been woken since: a moving kinematic body.) */
		const cd2Body* body = world->bodies.data + bodyIndices[k];
		if ((f & CD2_FINAL_RESTED) == 0u || body->sleepTime < CD2_TIME_TO_SLEEP)
		{
			set->restlessStamp = stamp;
			continue;
		}
		if (set->queuedStamp != stamp && cd2RestsAmongRested(world, body))
		{
			set->queuedStamp = stamp;
			queued[queuedCount++] = id;
		}
	}
	int slept = 0;
	/* Kinematic bodies sleep alone once they stop (their islands first, in body order). */
	for (int k = 0; k < count && kinematicRested; ++k)
	{
		int index = bodyIndices[k];
		const cd2Body* body = world->bodies.data + index;
		if ((flags[k] & CD2_FINAL_KINEMATIC) != 0u && body->sleepTime >= CD2_TIME_TO_SLEEP)
		{
			int island = cd2NewIsland(world);
			if (island != CD2_NULL_INDEX)
			{
				cd2PutToSleep(world, island, index);
				slept += 1;
			}
		}
	}
	/* The groups that sleep: a clean set whose bodies all rested; the groups of a dirty set (split)
	 * that hold no restless body. */
	int groupCount = 0;
	for (int q = 0; q < queuedCount; ++q)
	{
		int id = queued[q];
		const cd2AwakeSet* set = sets->sets.data + id;
		bool restless = set->restlessStamp == stamp;
		if (!set->dirty)
		{
			if (!restless)
			{
				groups[groupCount++].set = id;
			}
			continue;
		}
		int partCount = cd2SplitAwakeSet(world, id, parts, restlessParts);
		if (partCount < 0)
		{
			world->outOfMemory = true;
			return slept;
		}
		for (int p = 0; p < partCount; ++p)
		{
			if (!restlessParts[p])
			{
				groups[groupCount++].set = parts[p];
			}
		}
	}
	/* Islands in decreasing order of their largest body index, each listing its bodies in
	 * increasing order: the order does not depend on the sets' history. */
	for (int g = 0; g < groupCount; ++g)
	{
		int maxBody = CD2_NULL_INDEX;
		for (int b = sets->sets.data[groups[g].set].headBody; b != CD2_NULL_INDEX;
			 b = sets->links.data[b].next)
		{
			maxBody = b > maxBody ? b : maxBody;
		}
		groups[g].maxBody = maxBody;
	}
	qsort(groups, (size_t)groupCount, sizeof(cd2SleepingGroup), cd2CompareGroupsDescending);
	for (int g = 0; g < groupCount; ++g)
	{
		int id = groups[g].set;
		int n = 0;
		for (int b = sets->sets.data[id].headBody; b != CD2_NULL_INDEX; b = sets->links.data[b].next)
		{
			parts[n++] = b;
		}
		int island = cd2NewIsland(world);
		if (island == CD2_NULL_INDEX)
		{
			continue; /* stays awake */
		}
		qsort(parts, (size_t)n, sizeof(int), cd2CompareIndicesDescending);
		for (int i = 0; i < n; ++i)
		{
			cd2PutToSleep(world, island, parts[i]);
		}
		slept += n;
	}
	return slept;
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
	/* The group is the start body's connected part of the touch and joint graph (the links of
	 * cd2NextLinked), found by a walk from it: its cost is the group's, not the world's, so that
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
		cd2LinkWalk walk = cd2BeginLinkWalk(body);
		for (int other = cd2NextLinked(world, &walk); other != CD2_NULL_INDEX;
			 other = cd2NextLinked(world, &walk))
		{
			cd2Body* neighbour = world->bodies.data + other;
			if (!cd2IsSleepCandidate(neighbour) || neighbour->islandId == island)
			{
				continue;
			}
			neighbour->islandId = island;
			group[count++] = other;
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

#ifdef CD2_VALIDATE_AWAKE_SETS
#include <stdio.h>

static void cd2AwakeSetsFail(const char* what, int index)
{
	fprintf(stderr, "awake sets: %s (%d)\n", what, index);
	abort();
}

void cd2AwakeSets_Validate(cd2World* world)
{
	cd2AwakeSets* sets = &world->awakeSets;
	if (!sets->valid)
	{
		return;
	}
	int n = world->bodies.count;
	for (int i = 0; i < n; ++i)
	{
		bool candidate = cd2IsSleepCandidate(world->bodies.data + i);
		int id = cd2SetOf(sets, i);
		if (candidate != (id != CD2_NULL_INDEX))
		{
			cd2AwakeSetsFail(candidate ? "an awake dynamic body in no set"
									   : "a set holds a body that is not awake and dynamic",
							 i);
		}
		if (!candidate)
		{
			continue;
		}
		cd2LinkWalk walk = cd2BeginLinkWalk(world->bodies.data + i);
		for (int other = cd2NextLinked(world, &walk); other != CD2_NULL_INDEX;
			 other = cd2NextLinked(world, &walk))
		{
			if (cd2IsSleepCandidate(world->bodies.data + other) && cd2SetOf(sets, other) != id)
			{
				cd2AwakeSetsFail("linked awake bodies in different sets", i);
			}
		}
	}
	int* seen = (int*)cdAlloc((size_t)(n > 0 ? n : 1) * sizeof(int));
	int* queue = (int*)cdAlloc((size_t)(n > 0 ? n : 1) * sizeof(int));
	if (seen == NULL || queue == NULL)
	{
		cdFree(seen);
		cdFree(queue);
		return;
	}
	for (int i = 0; i < n; ++i)
	{
		seen[i] = CD2_NULL_INDEX;
	}
	for (int id = 0; id < sets->sets.count; ++id)
	{
		const cd2AwakeSet* set = sets->sets.data + id;
		if (set->bodyCount == 0)
		{
			continue;
		}
		int count = 0;
		for (int b = set->headBody; b != CD2_NULL_INDEX; b = sets->links.data[b].next)
		{
			if (sets->links.data[b].set != id)
			{
				cd2AwakeSetsFail("a member names another set", b);
			}
			count += 1;
		}
		if (count != set->bodyCount)
		{
			cd2AwakeSetsFail("a set's count is off", id);
		}
		if (set->dirty)
		{
			continue;
		}
		/* A clean set is one connected group. */
		int reached = 1;
		queue[0] = set->headBody;
		seen[set->headBody] = id;
		for (int head = 0; head < reached; ++head)
		{
			cd2LinkWalk walk = cd2BeginLinkWalk(world->bodies.data + queue[head]);
			for (int other = cd2NextLinked(world, &walk); other != CD2_NULL_INDEX;
				 other = cd2NextLinked(world, &walk))
			{
				if (cd2IsSleepCandidate(world->bodies.data + other) && seen[other] != id)
				{
					seen[other] = id;
					queue[reached++] = other;
				}
			}
		}
		if (reached != set->bodyCount)
		{
			cd2AwakeSetsFail("a clean set is not one group", id);
		}
	}
	cdFree(seen);
	cdFree(queue);
}
#endif
