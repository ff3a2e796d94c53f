/* collide: 2D contacts: broadphase pairs become contacts, each step updates their manifolds
 * (warm-started by feature id) and emits the begin/end and sensor events. */
#include "world2_internal.h"

#include "../base/radix_sort.h"
#include "../broad/broad_internal.h"
#include "../query/pairs2.h"

#include <limits.h>

/* ---- the narrowphase in local frames ------------------------------------------------------------
 * The one place that computes a pair's manifold: both shapes stay in their body frames (no copy of
 * the stored geometry) and only B's transform in A's frame is passed, so the result is in A's frame
 * and the solver can hold anchors relative to the bodies. The typed local-frame pair functions
 * (manifold2.h) do the work; a pair stored out of their canonical order runs with the roles swapped
 * and the normal flipped, the smaller shape moved into the other's frame. */
static inline cd2Manifold cd2FlipNormal(cd2Manifold m)
{
	m.normal = cd2Neg(m.normal);
	return m;
}

static inline cd2Circle cd2CircleIn(cd2Transform xf, cd2Circle c)
{
	c.center = cd2TransformPoint(xf, c.center);
	return c;
}

static inline cd2Capsule cd2CapsuleIn(cd2Transform xf, cd2Capsule c)
{
	c.p1 = cd2TransformPoint(xf, c.p1);
	c.p2 = cd2TransformPoint(xf, c.p2);
	return c;
}

static inline cd2Transform cd2InverseTransform(cd2Transform xf)
{
	cd2Transform inv;
	inv.q.c = xf.q.c;
	inv.q.s = -xf.q.s;
	inv.p = cd2Neg(cd2InvRotateVector(xf.q, xf.p));
	return inv;
}

/* The world's shapes in the pair table (src/query/pairs2.h): the table's circle, capsule, polygon
 * and segment are world shape types (an AABB or a box is made a polygon when it joins a body, so
 * their rows are skipped: CD2_WORLD_PROBE_ marks them), each with the world type and the way its
 * functions take it from a const cd2WorldShape* s. */
#define CD2_WORLD_TYPE_Circle CD2_WORLD_SHAPE_CIRCLE
#define CD2_WORLD_TYPE_Capsule CD2_WORLD_SHAPE_CAPSULE
#define CD2_WORLD_TYPE_Polygon CD2_WORLD_SHAPE_POLYGON
#define CD2_WORLD_TYPE_Segment CD2_WORLD_SHAPE_SEGMENT
#define CD2_WORLD_ARG_Circle(s) ((s)->geometry.circle)
#define CD2_WORLD_ARG_Capsule(s) ((s)->geometry.capsule)
#define CD2_WORLD_ARG_Polygon(s) (&(s)->geometry.polygon)
#define CD2_WORLD_ARG_Segment(s) ((s)->geometry.segment)
#define CD2_WORLD_PROBE_Aabb ~, 1
#define CD2_WORLD_PROBE_Box ~, 1
/* IN_WORLD(Name, MACRO) expands to MACRO when Name is a world shape type, to nothing otherwise. */
#define CD2_IN_WORLD(name, macro)                                                                            \
	CD_PAIR_CAT(CD_PAIR_SELECT_, CD_PAIR_SECOND_I(CD_PAIR_CAT(CD2_WORLD_PROBE_, name), 0, ~))(macro)
#define CD2_WORLD_PAIR_KEY(typeA, typeB)                                                                     \
	((int)(typeA) * ((int)CD2_WORLD_SHAPE_CHAIN_SEGMENT + 1) + (int)(typeB))

/* A pair stored out of the table's order (B before A in it): B moves into A's frame and the
 * table's function runs with the roles swapped, the normal flipped. A circle or a capsule is cheap
 * to move; a polygon is not, so for a polygon B the other shape moves into the polygon's frame
 * (the local form with the inverse transform) and the manifold comes back into A's. */
#define CD2_SWAPPED_Circle(Collide, b, a) cd2FlipNormal(Collide(cd2CircleIn(xfAB, b), a, sd))
#define CD2_SWAPPED_Capsule(Collide, b, a) cd2FlipNormal(Collide(cd2CapsuleIn(xfAB, b), a, sd))
#define CD2_SWAPPED_Polygon(Collide, b, a)                                                                   \
	cd2FlipNormal(cd2TransformManifold(xfAB, Collide##Local(b, a, cd2InverseTransform(xfAB), sd)))

/* A pair in the table's order runs its local-frame form; the same pair stored the other way round
 * runs CD2_SWAPPED_<A>. */
#define CD2_CONTACT_FORWARD(NameA, NameB, Collide)                                                           \
	case CD2_WORLD_PAIR_KEY(CD2_WORLD_TYPE_##NameA, CD2_WORLD_TYPE_##NameB):                                 \
		return Collide##Local(CD2_WORLD_ARG_##NameA(shapeA), CD2_WORLD_ARG_##NameB(shapeB), xfAB, sd);
#define CD2_CONTACT_SWAPPED(NameA, NameB, Collide)                                                           \
	case CD2_WORLD_PAIR_KEY(CD2_WORLD_TYPE_##NameB, CD2_WORLD_TYPE_##NameA):                                 \
		return CD2_SWAPPED_##NameA(Collide, CD2_WORLD_ARG_##NameA(shapeB), CD2_WORLD_ARG_##NameB(shapeA));
/* A same-shape pair has one case: CD2_IS_SAME(A, B) is 1 for those, 0 otherwise. */
#define CD2_SAME_PROBE_Circle_Circle ~, 1
#define CD2_SAME_PROBE_Capsule_Capsule ~, 1
#define CD2_SAME_PROBE_Polygon_Polygon ~, 1
#define CD2_SAME_PROBE_Segment_Segment ~, 1
#define CD2_IS_SAME(a, b)                                                                                    \
	CD_PAIR_SECOND_I(CD_PAIR_CAT(CD2_SAME_PROBE_, CD_PAIR_CAT(a, CD_PAIR_CAT(_, b))), 0, ~)
#define CD2_CONTACT_BOTH(NameA, NameB, Collide)                                                              \
	CD2_CONTACT_FORWARD(NameA, NameB, Collide)                                                               \
	CD_PAIR_CAT(CD_PAIR_SELECT_, CD2_IS_SAME(NameA, NameB))(CD2_CONTACT_SWAPPED)(NameA, NameB, Collide)
#define CD2_CONTACT_TYPED(NameA, NameB, Collide)                                                             \
	CD_PAIR_TYPED(Collide, CD2_CONTACT_BOTH)(NameA, NameB, Collide)
#define CD2_CONTACT_ROW(NameA, NameB, Overlap, Distance, Collide)                                            \
	CD2_IN_WORLD(NameA, CD2_IN_WORLD(NameB, CD2_CONTACT_TYPED))(NameA, NameB, Collide)

cd2Manifold cd2ContactCollide(const cd2WorldShape* shapeA, const cd2WorldShape* shapeB, cd2Transform xfAB,
							  cdReal speculativeDistance)
{
	cdReal sd = speculativeDistance;
	if (shapeA->type == CD2_WORLD_SHAPE_CHAIN_SEGMENT)
	{
		/* A chain segment is no shape type of the table: it is always A (one-sided, with ghosts). */
		const cd2ChainSegment* seg = &shapeA->geometry.chainSegment;
		switch (shapeB->type)
		{
			case CD2_WORLD_SHAPE_CIRCLE:
				return cd2CollideChainSegmentCircleLocal(seg, shapeB->geometry.circle, xfAB, sd);
			case CD2_WORLD_SHAPE_CAPSULE:
				return cd2CollideChainSegmentCapsuleLocal(seg, shapeB->geometry.capsule, xfAB, sd);
			case CD2_WORLD_SHAPE_POLYGON:
				return cd2CollideChainSegmentPolygonLocal(seg, &shapeB->geometry.polygon, xfAB, sd);
			case CD2_WORLD_SHAPE_SEGMENT:
			{
				cd2Capsule capsule = {shapeB->geometry.segment.p1, shapeB->geometry.segment.p2, CD_R(0.0)};
				return cd2CollideChainSegmentCapsuleLocal(seg, capsule, xfAB, sd);
			}
			default:
				break;
		}
	}
	else if (shapeA->type == CD2_WORLD_SHAPE_POLYGON && shapeB->type == CD2_WORLD_SHAPE_CIRCLE)
	{
		/* Stored polygon first: the polygon-first form places only the centre and maps nothing back.
		 * Every contact is the table's swapped circle-polygon call's (the circle placed by xfAB, the
		 * normal flipped) bit for bit, without the flip or the world-space form's edge search; an
		 * empty manifold's zero normal is +0 where the flip made it -0. */
		return cd2CollidePolygonCircleLocal(&shapeA->geometry.polygon, shapeB->geometry.circle, xfAB, sd);
	}
	else
	{
		switch (CD2_WORLD_PAIR_KEY(shapeA->type, shapeB->type))
		{
			CD2_PAIR_TABLE(CD2_CONTACT_ROW)
			default:
				break;
		}
	}
	/* Two chain segments never make a contact. */
	cd2Manifold none;
	memset(&none, 0, sizeof(none));
	return none;
}

/* The key that matches a point with last step's for warm starting: a name of the point that
 * does not change while the same features touch, whichever way the manifold describes them.
 * - A clipped polygon point's id says whether it is an incident vertex (code 0/1) or was clipped
 *   at a side of the reference edge (2/3); with aligned boxes that flips from step to step while
 *   the point stays where it is. The incident edge runs against the reference edge, so its vertex
 *   1 is the one clipped at side 2 and vertex 0 the one clipped at side 3: one slot for {1, 2},
 *   one for {0, 3}.
 * - Between two near-parallel faces the reference face switches between A's and B's (the flip
 *   bit) as the bodies rock by a fraction of the slop. Name the point by (edge of A, edge of B)
 *   instead of (reference, incident); the reference edge runs the other way round when it is B's,
 *   so the slots swap too. */
static uint32_t cd2WarmStartKey(uint32_t id)
{
	uint32_t code = (id >> 16) & 0xffu;
	if (code > 3u || (id >> 25) != 0u)
	{
		return id;
	}
	bool flip = (id & CD2_FEATURE_FLIP) != 0u;
	uint32_t reference = id & 0xffu, incident = (id >> 8) & 0xffu;
	uint32_t slot = (code == 1u || code == 2u) ? 1u : 0u;
	uint32_t edgeA = flip ? incident : reference, edgeB = flip ? reference : incident;
	if (flip)
	{
		slot = 1u - slot;
	}
	return edgeA | edgeB << 8 | slot << 16;
}

/* Whether two shapes whose boxes overlap get a contact, apart from the user's filter callback:
 * reads the world only, so the pair search calls it on the workers. */
static bool cd2ShouldCreateContact(const cd2World* world, int indexA, int indexB)
{
	const cd2WorldShape* a = world->shapes.data + indexA;
	const cd2WorldShape* b = world->shapes.data + indexB;
	if (a->body == b->body || (a->isSensor && b->isSensor))
	{
		return false;
	}
	if (a->type == CD2_WORLD_SHAPE_CHAIN_SEGMENT && b->type == CD2_WORLD_SHAPE_CHAIN_SEGMENT)
	{
		return false;
	}
	if (!cd2ShouldShapesCollide(a->filter, b->filter))
	{
		return false;
	}
	const cd2Body* bodyA = world->bodies.data + a->body;
	const cd2Body* bodyB = world->bodies.data + b->body;
	if (a->isSensor || b->isSensor)
	{
		const cd2WorldShape* sensor = a->isSensor ? a : b;
		const cd2WorldShape* visitor = a->isSensor ? b : a;
		return sensor->enableSensorEvents && visitor->enableSensorEvents &&
			   (bodyA->type != CD_STATIC_BODY || bodyB->type != CD_STATIC_BODY);
	}
	return cd2ShouldBodiesCollide(world, a->body, b->body);
}

static void cd2LinkContactEdge(cd2World* world, int contactIndex, int side, int bodyIndex)
{
	cd2Contact* contact = world->contacts.data + contactIndex;
	cd2Body* body = world->bodies.data + bodyIndex;
	int key = (contactIndex << 1) | side;
	contact->prevKey[side] = CD2_NULL_INDEX;
	contact->nextKey[side] = body->headContactKey;
	if (body->headContactKey != CD2_NULL_INDEX)
	{
		cd2Contact* head = world->contacts.data + cd2EdgeContact(body->headContactKey);
		head->prevKey[cd2EdgeSide(body->headContactKey)] = key;
	}
	body->headContactKey = key;
}

static void cd2UnlinkContactEdge(cd2World* world, int contactIndex, int side, int bodyIndex)
{
	cd2Contact* contact = world->contacts.data + contactIndex;
	int prev = contact->prevKey[side], next = contact->nextKey[side];
	if (prev != CD2_NULL_INDEX)
	{
		world->contacts.data[cd2EdgeContact(prev)].nextKey[cd2EdgeSide(prev)] = next;
	}
	else
	{
		world->bodies.data[bodyIndex].headContactKey = next;
	}
	if (next != CD2_NULL_INDEX)
	{
		world->contacts.data[cd2EdgeContact(next)].prevKey[cd2EdgeSide(next)] = prev;
	}
}

static void cd2CreateContact(cd2World* world, int indexA, int indexB)
{
	/* A chain segment is always shape A (its manifolds point from the terrain). */
	if (world->shapes.data[indexB].type == CD2_WORLD_SHAPE_CHAIN_SEGMENT)
	{
		int t = indexA;
		indexA = indexB;
		indexB = t;
	}
	int index = cdIdPool_Alloc(&world->contactPool);
	if (index < 0 || !cdArrayReserveFor(world->contacts, index + 1) ||
		!cdPairSet_Add(&world->pairs, cdPairKey(indexA, indexB)))
	{
		if (index >= 0)
		{
			cdIdPool_Free(&world->contactPool, index);
		}
		world->outOfMemory = true;
		return;
	}
	if (index >= world->contacts.count)
	{
		world->contacts.count = index + 1;
	}
	const cd2WorldShape* a = world->shapes.data + indexA;
	const cd2WorldShape* b = world->shapes.data + indexB;
	cd2Contact* contact = world->contacts.data + index;
	memset(contact, 0, sizeof(*contact));
	contact->inUse = true;
	contact->shapeA = indexA;
	contact->shapeB = indexB;
	contact->bodyA = a->body;
	contact->bodyB = b->body;
	contact->flags = (a->isSensor || b->isSensor) ? CD2_CONTACT_SENSOR : 0u;
	world->sensorContactCount += (a->isSensor || b->isSensor) ? 1 : 0;
	/* Mixing rules: geometric mean friction, larger restitution, larger rolling resistance. */
	contact->friction = cdSqrt(a->friction * b->friction);
	contact->restitution = cdMax(a->restitution, b->restitution);
	contact->rollingResistance = cdMax(a->rollingResistance, b->rollingResistance);
	contact->tangentSpeed = a->tangentSpeed + b->tangentSpeed;
	cd2LinkContactEdge(world, index, 0, a->body);
	cd2LinkContactEdge(world, index, 1, b->body);
}

/* ---- pairs -------------------------------------------------------------------------------------
 * The broadphase's pair search runs on the workers (cd2FindPairsTask over ranges of its items: the
 * moved proxies' queries, or the tree nodes of a sweep when many moved), filtered there; each worker
 * keeps the keys of the pairs that would make a new contact in its own buffer.
 * This thread then sorts them all by shape key and creates the contacts in that order: the order
 * of the contacts depends only on the set of pairs, never on the split or the thread timing. */

/* One worker's new pairs (padded to a cache line: workers write their own counts). */
typedef struct cd2PairBuffer
{
	uint64_t* keys;
	int count, capacity;
	char padding[64 - sizeof(uint64_t*) - 2 * sizeof(int)];
} cd2PairBuffer;

typedef struct cd2PairSearch
{
	const cd2World* world;
	cd2PairBuffer* buffers; /* one per worker */
	uint8_t* failed;		/* per item: 1 when its range overflowed its worker's buffer */
} cd2PairSearch;

/* The pairs a worker's search reports wait in a small batch: each one's slot of the pair set
 * starts loading when it arrives (most reported pairs already have their contact, and the set is too
 * large for the nearest caches), and the batch is checked in arrival order when full, so the lookups'
 * misses overlap instead of each stalling the search. */
#define CD2_PAIR_BATCH 16

typedef struct cd2PairSink
{
	const cd2World* world;
	cd2PairBuffer* buffer;
	bool overflow;
	int pendingCount;
	uint64_t pending[CD2_PAIR_BATCH];
} cd2PairSink;

/* The batch's pairs that make a new contact into the worker's buffer, in arrival order. */
static void cd2FlushPairs(cd2PairSink* sink)
{
	const cd2World* world = sink->world;
	cd2PairBuffer* buffer = sink->buffer;
	for (int i = 0; i < sink->pendingCount; ++i)
	{
		uint64_t key = sink->pending[i];
		int indexA = (int)(uint32_t)key, indexB = (int)(uint32_t)(key >> 32);
		/* Most overlaps of moved boxes already have their contact. */
		if (cdPairSet_Contains(&world->pairs, key) || !world->shapes.data[indexA].inUse ||
			!world->shapes.data[indexB].inUse || !cd2ShouldCreateContact(world, indexA, indexB))
		{
			continue;
		}
		if (buffer->count == buffer->capacity)
		{
			sink->overflow = true;
			break;
		}
		buffer->keys[buffer->count++] = key;
	}
	sink->pendingCount = 0;
}

static void cd2CollectPair(int proxyA, int proxyB, uint64_t userDataA, uint64_t userDataB, void* context)
{
	(void)proxyA;
	(void)proxyB;
	cd2PairSink* sink = (cd2PairSink*)context;
	uint64_t key = cdPairKey(cd2ProxyShape(userDataA), cd2ProxyShape(userDataB));
	const uint64_t* slot = cdPairSet_HomeSlot(&sink->world->pairs, key);
	if (slot != NULL)
	{
		CD2_PREFETCH(slot);
	}
	sink->pending[sink->pendingCount++] = key;
	if (sink->pendingCount == CD2_PAIR_BATCH)
	{
		cd2FlushPairs(sink);
	}
}

/* The pairs of items [start, end) of the broadphase's search into this worker's buffer. A range whose pairs
 * do not fit leaves nothing there and is marked for the serial retry. */
static void cd2FindPairsTask(int startIndex, int endIndex, uint32_t workerIndex, void* taskContext)
{
	cd2PairSearch* search = (cd2PairSearch*)taskContext;
	cd2PairSink sink;
	sink.world = search->world;
	sink.buffer = search->buffers + workerIndex;
	sink.overflow = false;
	sink.pendingCount = 0;
	int rangeStart = sink.buffer->count;
	cd2BroadPhase_QueryMovedPairs(search->world->broadPhase, startIndex, endIndex, cd2CollectPair, &sink);
	cd2FlushPairs(&sink);
	if (sink.overflow)
	{
		sink.buffer->count = rangeStart;
		memset(search->failed + startIndex, 1, (size_t)(endIndex - startIndex));
	}
}

/* Jobs of the broadphase's deferred rebuild (the part of its tree that moves grew). */
static void cd2RebuildTreeTask(int startIndex, int endIndex, uint32_t workerIndex, void* taskContext)
{
	(void)workerIndex;
	cd2BroadPhase_RebuildJobs((cd2BroadPhase*)taskContext, startIndex, endIndex);
}

void cd2UpdateBroadPhasePairs(cd2World* world)
{
	/* First the tree where last step's moves grew it, rebuilt in subtrees on the workers. */
	int jobCount = cd2BroadPhase_BeginRebuild(world->broadPhase);
	if (jobCount > 0)
	{
		/* (The jobs' sizes are unknown here: a small world rebuilds on this thread.) */
		int minParallel = world->shapes.count >= CD2_PARALLEL_MIN_SHAPES ? 2 : jobCount + 1;
		cd2RunTask(world, cd2RebuildTreeTask, jobCount, 1, minParallel, world->broadPhase);
	}
	cd2BroadPhase_EndRebuild(world->broadPhase);
	CD2_PROFILE_MARK(world, rebuildTree);
	int itemCount = cd2BroadPhase_BeginMovedPairs(world->broadPhase);
	if (itemCount == 0)
	{
		cd2BroadPhase_EndMovedPairs(world->broadPhase, true);
		return;
	}
	/* Step scratch (the arena keeps its block between steps: no allocation in a steady state).
	 * Room for two new pairs per item (a moved proxy's query or a tree node of the sweep) in each
	 * worker's buffer; more goes to the retry. */
	int workerCount = cdMaxInt(world->workerCount, 1);
	int capacity = 2 * itemCount + 256;
	cd2PairSearch search;
	search.world = world;
	search.buffers =
		(cd2PairBuffer*)cdArena_Alloc(&world->arena, (size_t)workerCount * sizeof(cd2PairBuffer));
	search.failed = (uint8_t*)cdArena_Alloc(&world->arena, (size_t)itemCount);
	bool ok = search.buffers != NULL && search.failed != NULL;
	for (int w = 0; ok && w < workerCount; ++w)
	{
		search.buffers[w].keys =
			(uint64_t*)cdArena_AllocUncleared(&world->arena, (size_t)capacity * sizeof(uint64_t));
		search.buffers[w].capacity = capacity;
		ok = search.buffers[w].keys != NULL;
	}
	if (!ok)
	{
		/* Out of memory: no new contacts this step; the moves are kept so the pairs come back. */
		world->outOfMemory = true;
		cd2BroadPhase_EndMovedPairs(world->broadPhase, false);
		return;
	}
	cd2RunTask(world, cd2FindPairsTask, itemCount, 64, CD2_PARALLEL_MIN_PAIR_ITEMS, &search);
	/* The ranges that overflowed, again on this thread, with room doubled until they fit. */
	bool anyFailed = memchr(search.failed, 1, (size_t)itemCount) != NULL;
	cd2PairBuffer retry = {NULL, 0, 0, {0}};
	for (int retryCapacity = 2 * capacity; anyFailed; retryCapacity *= 2)
	{
		retry.keys =
			(uint64_t*)cdArena_AllocUncleared(&world->arena, (size_t)retryCapacity * sizeof(uint64_t));
		retry.count = 0;
		retry.capacity = retryCapacity;
		if (retry.keys == NULL || retryCapacity > (INT_MAX >> 2))
		{
			world->outOfMemory = true;
			cd2BroadPhase_EndMovedPairs(world->broadPhase, false);
			return;
		}
		cd2PairSink sink;
		sink.world = world;
		sink.buffer = &retry;
		sink.overflow = false;
		sink.pendingCount = 0;
		for (int i = 0; i < itemCount && !sink.overflow; ++i)
		{
			if (search.failed[i] != 0)
			{
				cd2BroadPhase_QueryMovedPairs(world->broadPhase, i, i + 1, cd2CollectPair, &sink);
				cd2FlushPairs(&sink);
			}
		}
		anyFailed = sink.overflow;
	}
	cd2BroadPhase_EndMovedPairs(world->broadPhase, true);

	int total = retry.count;
	for (int w = 0; w < workerCount; ++w)
	{
		total += search.buffers[w].count;
	}
	if (total == 0)
	{
		return;
	}
	uint64_t* keys = (uint64_t*)cdArena_AllocUncleared(&world->arena, (size_t)total * sizeof(uint64_t));
	uint64_t* scratch = (uint64_t*)cdArena_AllocUncleared(&world->arena, (size_t)total * sizeof(uint64_t));
	if (keys == NULL || scratch == NULL)
	{
		/* (The moves are gone: these pairs come back when one of their boxes moves again.) */
		world->outOfMemory = true;
		return;
	}
	int at = 0;
	for (int w = 0; w < workerCount; ++w)
	{
		if (search.buffers[w].count > 0)
		{
			memcpy(keys + at, search.buffers[w].keys, (size_t)search.buffers[w].count * sizeof(uint64_t));
			at += search.buffers[w].count;
		}
	}
	if (retry.count > 0)
	{
		memcpy(keys + at, retry.keys, (size_t)retry.count * sizeof(uint64_t));
	}
	/* Contacts are created in shape order, not proxy order: proxy ids depend on the broadphase's
	 * history, shape indices are part of the saved state. Each key once (a pair is found once, but
	 * stay safe); pairs with a contact were dropped by the workers, the ones created here are new. */
	const uint64_t* sorted = cdRadixSortKeys(keys, scratch, total);
	for (int i = 0; i < total; ++i)
	{
		uint64_t key = sorted[i];
		if (i > 0 && sorted[i - 1] == key)
		{
			continue;
		}
		int indexA = (int)(uint32_t)key, indexB = (int)(uint32_t)(key >> 32);
		/* The user's filter on this thread, in shape order. */
		if (world->customFilterFcn != NULL &&
			!world->customFilterFcn(cd2MakeShapeId(world, indexA), cd2MakeShapeId(world, indexB),
									world->customFilterContext))
		{
			continue;
		}
		cd2CreateContact(world, indexA, indexB);
	}
}

static void cd2EmitEndEvent(cd2World* world, const cd2Contact* contact)
{
	const cd2WorldShape* a = world->shapes.data + contact->shapeA;
	const cd2WorldShape* b = world->shapes.data + contact->shapeB;
	if ((contact->flags & CD2_CONTACT_SENSOR) != 0)
	{
		cd2SensorEndTouchEvent e;
		e.sensorShapeId = cd2MakeShapeId(world, a->isSensor ? contact->shapeA : contact->shapeB);
		e.visitorShapeId = cd2MakeShapeId(world, a->isSensor ? contact->shapeB : contact->shapeA);
		if (!cdArrayPush(world->sensorEndEvents, e))
		{
			world->outOfMemory = true;
		}
	}
	else if (a->enableContactEvents || b->enableContactEvents)
	{
		cd2ContactEndTouchEvent e;
		e.shapeIdA = cd2MakeShapeId(world, contact->shapeA);
		e.shapeIdB = cd2MakeShapeId(world, contact->shapeB);
		if (!cdArrayPush(world->endEvents, e))
		{
			world->outOfMemory = true;
		}
	}
}

void cd2DestroyContact(cd2World* world, int contactIndex, bool wakeBodies)
{
	cd2Contact* contact = world->contacts.data + contactIndex;
	if ((contact->flags & CD2_CONTACT_TOUCHING) != 0)
	{
		cd2EmitEndEvent(world, contact);
		if (wakeBodies && (contact->flags & CD2_CONTACT_SENSOR) == 0)
		{
			cd2WakeBody(world, contact->bodyA);
			cd2WakeBody(world, contact->bodyB);
		}
	}
	cdPairSet_Remove(&world->pairs, cdPairKey(contact->shapeA, contact->shapeB));
	world->sensorContactCount -= (contact->flags & CD2_CONTACT_SENSOR) != 0 ? 1 : 0;
	cd2UnlinkContactEdge(world, contactIndex, 0, contact->bodyA);
	cd2UnlinkContactEdge(world, contactIndex, 1, contact->bodyB);
	contact->inUse = false;
	cdIdPool_Free(&world->contactPool, contactIndex);
	/* After the wakes: a woken body joins its set through the contact while it is there. */
	if ((contact->flags & (CD2_CONTACT_TOUCHING | CD2_CONTACT_SENSOR)) == CD2_CONTACT_TOUCHING)
	{
		cd2AwakeSets_Unlink(world, contact->bodyA, contact->bodyB);
	}
}

static cd2Manifold cd2WorldManifold(const cd2Contact* contact)
{
	cd2Manifold m;
	memset(&m, 0, sizeof(m));
	m.normal = contact->normal;
	m.pointCount = contact->pointCount;
	for (int i = 0; i < contact->pointCount; ++i)
	{
		m.points[i].point = contact->cache[i].point;
		m.points[i].separation = contact->points[i].separation;
		m.points[i].id = contact->cache[i].id;
	}
	return m;
}

/* The sensor test: do the shapes overlap (touching counts)? */
static bool cd2SensorOverlaps(cd2World* world, const cd2Contact* contact)
{
	const cd2WorldShape* a = world->shapes.data + contact->shapeA;
	const cd2WorldShape* b = world->shapes.data + contact->shapeB;
	cd2Shape ta = cd2MakeTaggedShape(a, world->bodies.data[a->body].transform);
	cd2Shape tb = cd2MakeTaggedShape(b, world->bodies.data[b->body].transform);
	return cd2Overlap(&ta, &tb);
}

void cd2UpdateSensors(cd2World* world)
{
	/* Most worlds have no sensor: do not read every contact for none. */
	if (world->sensorContactCount == 0)
	{
		return;
	}
	for (int i = 0; i < world->contacts.count; ++i)
	{
		cd2Contact* contact = world->contacts.data + i;
		if (!contact->inUse || (contact->flags & CD2_CONTACT_SENSOR) == 0)
		{
			continue;
		}
		const cd2Body* bodyA = world->bodies.data + contact->bodyA;
		const cd2Body* bodyB = world->bodies.data + contact->bodyB;
		if (!bodyA->awake && !bodyB->awake)
		{
			continue;
		}
		const cd2WorldShape* shapeA = world->shapes.data + contact->shapeA;
		bool wasTouching = (contact->flags & CD2_CONTACT_TOUCHING) != 0;
		bool touching = cd2SensorOverlaps(world, contact);
		if (touching && !wasTouching)
		{
			cd2SensorBeginTouchEvent e;
			e.sensorShapeId = cd2MakeShapeId(world, shapeA->isSensor ? contact->shapeA : contact->shapeB);
			e.visitorShapeId = cd2MakeShapeId(world, shapeA->isSensor ? contact->shapeB : contact->shapeA);
			if (!cdArrayPush(world->sensorBeginEvents, e))
			{
				world->outOfMemory = true;
			}
			contact->flags |= CD2_CONTACT_TOUCHING;
		}
		else if (!touching && wasTouching)
		{
			cd2EmitEndEvent(world, contact);
			contact->flags &= ~(uint32_t)CD2_CONTACT_TOUCHING;
		}
	}
}

/* ---- contact recycling ---------------------------------------------------------------------------
 * The idea of keeping a manifold while the bodies barely move comes from persistent contact
 * manifolds (PhysX, Bullet) in the single-distance form Box2D v3 uses ("contact recycling"). When
 * the narrowphase runs, each point is stored on both bodies (in A's and in B's body frame, where the
 * two coincide) with its separation, and the normal in A's frame, along with the pose of B's frame
 * in A's. In later steps, while every point of B has moved by less than the recycle distance in
 * A's frame since then (or every point of A in B's frame: translation of the other body's origin
 * plus the chord of the relative rotation times the body's reach), the stored points are carried by
 * the bodies and only their separations follow the motion along the normal, as the solver does
 * between sub-steps; the narrowphase is skipped. Points that were not in the manifold can have
 * come at most that distance closer, so a pair with no points is kept only while the motion is
 * smaller than the gap that its last speculative distance guaranteed, less what this step can
 * close. Fast bodies and bullets always run the narrowphase. */

/* Cosine of the largest relative rotation a recycled manifold may carry (about 11 degrees). */
#define CD2_RECYCLE_COS_ANGLE CD_R(0.98)

static bool cd2RecycleManifold(cd2Contact* contact, const cd2Body* bodyA, const cd2Body* bodyB,
							   cd2Transform xfAB, cdReal tolerance)
{
	cd2Transform c = contact->cachedPose;
	cdReal cosine = c.q.c * xfAB.q.c + c.q.s * xfAB.q.s;
	if (!(cosine > CD2_RECYCLE_COS_ANGLE))
	{
		return false;
	}
	cdReal chord = cdSqrt(cdMax(CD_R(2.0) - CD_R(2.0) * cosine, CD_R(0.0)));
	/* How far the points of B moved in A's frame (the origin's move plus the rotation at B's reach
	 * from its origin); failing that, how far those of A moved in B's frame (a small body on a large
	 * one passes one of the two). */
	cdReal reachB = bodyB->maxExtent + cd2Length(bodyB->localCenter);
	if (!(cd2Length(cd2Sub(xfAB.p, c.p)) + chord * reachB < tolerance))
	{
		cdReal reachA = bodyA->maxExtent + cd2Length(bodyA->localCenter);
		cd2Vec moveA = cd2Sub(cd2InvRotateVector(xfAB.q, xfAB.p), cd2InvRotateVector(c.q, c.p));
		if (!(cd2Length(moveA) + chord * reachA < tolerance))
		{
			return false;
		}
	}
	cd2Transform xfA = bodyA->transform, xfB = bodyB->transform;
	cd2Vec n = cd2RotateVector(xfA.q, contact->localNormal);
	cd2Vec dc = cd2Sub(bodyB->center, bodyA->center);
	contact->normal = n;
	for (int k = 0; k < contact->pointCount; ++k)
	{
		cd2ContactPoint* cp = contact->points + k;
		cd2ContactPointCache* cc = contact->cache + k;
		/* The stored point as carried by A and by B, from the centres (no large coordinates). */
		cd2Vec rA = cd2RotateVector(xfA.q, cd2Sub(cc->localPointA, bodyA->localCenter));
		cd2Vec rB = cd2RotateVector(xfB.q, cd2Sub(cc->localPointB, bodyB->localCenter));
		cd2Vec d = cd2Add(dc, cd2Sub(rB, rA));
		cp->separation = cc->baseSeparation + cd2Dot(d, n);
		cp->anchorA = cd2MulAdd(rA, CD_R(0.5), d);
		cp->anchorB = cd2MulSub(rB, CD_R(0.5), d);
		cc->point = cd2Add(bodyA->center, cp->anchorA);
	}
	return true;
}

/* The narrowphase for one contact, stored with the data recycling needs. */
static void cd2ComputeManifold(cd2Contact* contact, const cd2WorldShape* shapeA, const cd2WorldShape* shapeB,
							   const cd2Body* bodyA, const cd2Body* bodyB, cd2Transform xfAB,
							   cdReal speculative, cdReal timeStep)
{
	cd2Manifold m = cd2ContactCollide(shapeA, shapeB, xfAB, speculative);
	cd2Transform xfA = bodyA->transform;
	/* The narrowphase ran with the margin of the fastest closing the two bodies allow; a point
	 * beyond the fixed margin stays only while its own approach speed along the normal can close
	 * its gap in this step. Points of bodies sliding past or moving apart are no constraints then.
	 * What no point reports is apart by at least the smallest separation dropped (and the margin
	 * the narrowphase ran with): what an empty manifold's recycling relies on. */
	cdReal guaranteed = speculative;
	if (m.pointCount > 0)
	{
		cd2Vec n = cd2RotateVector(xfA.q, m.normal);
		int kept = 0;
		for (int k = 0; k < m.pointCount; ++k)
		{
			cd2ManifoldPoint mp = m.points[k];
			if (mp.separation > CD_SPECULATIVE_DISTANCE)
			{
				cd2Vec p = cd2TransformPoint(xfA, mp.point);
				cd2Vec vA = cd2Add(bodyA->linearVelocity,
								   cd2CrossSV(bodyA->angularVelocity, cd2Sub(p, bodyA->center)));
				cd2Vec vB = cd2Add(bodyB->linearVelocity,
								   cd2CrossSV(bodyB->angularVelocity, cd2Sub(p, bodyB->center)));
				cdReal approach = -cd2Dot(cd2Sub(vB, vA), n);
				if (mp.separation > CD_SPECULATIVE_DISTANCE + timeStep * cdMax(approach, CD_R(0.0)))
				{
					guaranteed = cdMin(guaranteed, mp.separation);
					continue;
				}
			}
			m.points[kept++] = mp;
		}
		m.pointCount = kept;
	}
	cd2ContactPoint old[2];
	uint32_t oldId[2] = {contact->cache[0].id, contact->cache[1].id};
	int oldCount = contact->pointCount;
	memcpy(old, contact->points, sizeof(old));
	contact->pointCount = m.pointCount;
	contact->normal = cd2RotateVector(xfA.q, m.normal);
	contact->localNormal = m.normal;
	contact->cachedPose = xfAB;
	contact->cachedSpeculative = guaranteed;
	contact->flags |= CD2_CONTACT_CACHE_VALID;
	for (int k = 0; k < m.pointCount; ++k)
	{
		cd2ContactPoint* cp = contact->points + k;
		cd2ContactPointCache* cc = contact->cache + k;
		memset(cp, 0, sizeof(*cp));
		memset(cc, 0, sizeof(*cc));
		cc->point = cd2TransformPoint(xfA, m.points[k].point);
		cp->anchorA = cd2Sub(cc->point, bodyA->center);
		cp->anchorB = cd2Sub(cc->point, bodyB->center);
		cp->separation = m.points[k].separation;
		cc->id = m.points[k].id;
		cc->localPointA = m.points[k].point;
		cc->localPointB = cd2InvTransformPoint(xfAB, m.points[k].point);
		cc->baseSeparation = m.points[k].separation;
		/* Warm starting: the same features keep their impulses. */
		for (int j = 0; j < oldCount; ++j)
		{
			if (cd2WarmStartKey(oldId[j]) == cd2WarmStartKey(cc->id))
			{
				cp->normalImpulse = old[j].normalImpulse;
				cp->tangentImpulse = old[j].tangentImpulse;
				break;
			}
		}
	}
	if (m.pointCount == 0)
	{
		contact->rollingImpulse = CD_R(0.0);
	}
}

typedef struct cd2ContactUpdateContext
{
	cd2World* world;
	cdReal timeStep;
	cdReal recycleDistance; /* in length units, 0: off */
	/* Per contact: 1 when the merge on the calling thread has something to do for it (it ended,
	 * began or stopped touching, or the pre-solve callback wants it), else 0. Written by the
	 * contact's own task, so the merge reads a byte per contact instead of every record. */
	uint8_t* changed;
	cd2ContactSolveEntry* entries; /* per contact, for the solver (NULL: none) */
} cd2ContactUpdateContext;

void cd2SetContactSolveEntry(cd2ContactSolveEntry* entry, const cd2Contact* contact)
{
	bool solved = contact->inUse && contact->pointCount > 0 &&
				  (contact->flags & (CD2_CONTACT_SENSOR | CD2_CONTACT_DISABLED | CD2_CONTACT_TOUCHING)) ==
					  CD2_CONTACT_TOUCHING;
	entry->bodyA = solved ? contact->bodyA : CD2_NULL_INDEX;
	entry->bodyB = solved ? contact->bodyB : CD2_NULL_INDEX;
	entry->flags = contact->inUse ? contact->flags : 0u;
}

/* One contact of the parallel pass: it writes only itself (its manifold, the SIM flags and its byte
 * of changed), reading the bodies and shapes as they were at the start of the step, so any split
 * gives the same bits. */
static void cd2UpdateContact(const cd2ContactUpdateContext* ctx, int i)
{
	cd2World* world = ctx->world;
	uint8_t* changed = ctx->changed;
	cd2Contact* contact = world->contacts.data + i;
	if (!contact->inUse)
	{
		return;
	}
	const cd2Body* bodyA = world->bodies.data + contact->bodyA;
	const cd2Body* bodyB = world->bodies.data + contact->bodyB;
	if (!bodyA->awake && !bodyB->awake)
	{
		return; /* sleeping (or static against sleeping): keep as is */
	}
	const cd2WorldShape* shapeA = world->shapes.data + contact->shapeA;
	const cd2WorldShape* shapeB = world->shapes.data + contact->shapeB;
	if (!cd2OverlapAabbAabb(shapeA->fatAabb, shapeB->fatAabb))
	{
		contact->flags |= CD2_CONTACT_SIM_DISJOINT;
		if (changed != NULL)
		{
			changed[i] = 1;
		}
		return;
	}
	contact->flags &= ~(uint32_t)(CD2_CONTACT_DISABLED | CD2_CONTACT_HIT_EVENTS);
	/* The shapes' current hit-event flags, for the solver's hit report this step. */
	if (shapeA->enableHitEvents || shapeB->enableHitEvents)
	{
		contact->flags |= CD2_CONTACT_HIT_EVENTS;
	}
	if ((contact->flags & CD2_CONTACT_SENSOR) != 0)
	{
		return; /* sensors are updated after the solve (cd2UpdateSensors) */
	}
	cd2Transform xfAB = cd2InvMulTransforms(bodyA->transform, bodyB->transform);
	/* Speculative margin: the fixed one plus how far the bodies can close in this step, so a
	 * fast body is caught at the surface rather than found inside it a step later. */
	cdReal closing = cd2Length(cd2Sub(bodyB->linearVelocity, bodyA->linearVelocity)) +
					 cdAbs(bodyA->angularVelocity) * bodyA->maxExtent +
					 cdAbs(bodyB->angularVelocity) * bodyB->maxExtent;
	cdReal speculative = CD_SPECULATIVE_DISTANCE + ctx->timeStep * closing;
	bool recycled = false;
	if (ctx->recycleDistance > CD_R(0.0) && (contact->flags & CD2_CONTACT_CACHE_VALID) != 0 &&
		!bodyA->isFast && !bodyB->isFast && !bodyA->isBullet && !bodyB->isBullet)
	{
		cdReal tolerance = ctx->recycleDistance;
		if (contact->pointCount == 0)
		{
			tolerance = cdMin(tolerance, contact->cachedSpeculative - ctx->timeStep * closing);
		}
		recycled = cd2RecycleManifold(contact, bodyA, bodyB, xfAB, tolerance);
	}
	if (!recycled)
	{
		cd2ComputeManifold(contact, shapeA, shapeB, bodyA, bodyB, xfAB, speculative, ctx->timeStep);
	}
	/* The merge's work: a change of touching, or a pre-solve call. */
	bool touching = contact->pointCount > 0;
	bool wasTouching = (contact->flags & CD2_CONTACT_TOUCHING) != 0;
	if (touching != wasTouching || (touching && world->preSolveFcn != NULL &&
									(shapeA->enablePreSolveEvents || shapeB->enablePreSolveEvents)))
	{
		contact->flags |= CD2_CONTACT_SIM_UPDATED;
		if (changed != NULL)
		{
			changed[i] = 1;
		}
	}
}

/* How many contacts ahead of the one updated the update starts loading their inputs. */
#define CD2_UPDATE_PREFETCH_AHEAD 8
/* Bodies within this many indices of the current contact's count as near (see below). */
#define CD2_UPDATE_PREFETCH_NEAR 64

static void cd2UpdateContactsTask(int startIndex, int endIndex, uint32_t workerIndex, void* taskContext)
{
	(void)workerIndex;
	const cd2ContactUpdateContext* ctx = (const cd2ContactUpdateContext*)taskContext;
	if (ctx->changed != NULL)
	{
		memset(ctx->changed + startIndex, 0, (size_t)(endIndex - startIndex));
	}
	const cd2World* world = ctx->world;
	for (int i = startIndex; i < endIndex; ++i)
	{
		/* The bodies and shapes of a contact a few ahead start loading now: they lie far apart in
		 * memory, and this loop's time is mostly waiting for them.
		 * (Written out here: in a helper function GCC judged the prefetches free of effects and
		 * dropped the call.) */
		const cd2Contact* ahead = i + CD2_UPDATE_PREFETCH_AHEAD < endIndex
									  ? world->contacts.data + i + CD2_UPDATE_PREFETCH_AHEAD
									  : NULL;
		/* Only when that contact's body lies far from this one's in memory: contacts made in body
		 * order (a stack, a pyramid) are read in body order, which the hardware prefetcher follows
		 * by itself, and the extra loads there only cost. */
		if (ahead != NULL && ahead->inUse &&
			(uint32_t)(ahead->bodyB - world->contacts.data[i].bodyB + CD2_UPDATE_PREFETCH_NEAR) >
				2u * CD2_UPDATE_PREFETCH_NEAR)
		{
			const cd2Body* bodyA = world->bodies.data + ahead->bodyA;
			const cd2Body* bodyB = world->bodies.data + ahead->bodyB;
			const cd2WorldShape* shapeA = world->shapes.data + ahead->shapeA;
			const cd2WorldShape* shapeB = world->shapes.data + ahead->shapeB;
			CD2_PREFETCH(&bodyA->transform);
			CD2_PREFETCH(&bodyA->linearVelocity);
			CD2_PREFETCH(&bodyA->maxExtent);
			CD2_PREFETCH(&bodyB->transform);
			CD2_PREFETCH(&bodyB->linearVelocity);
			CD2_PREFETCH(&bodyB->maxExtent);
			CD2_PREFETCH(&shapeA->type);
			CD2_PREFETCH(&shapeA->geometry.polygon.normals[0]);
			CD2_PREFETCH(&shapeA->geometry.polygon.count);
			CD2_PREFETCH(&shapeA->enableHitEvents);
			CD2_PREFETCH(&shapeA->fatAabb.max);
			CD2_PREFETCH(&shapeB->type);
			CD2_PREFETCH(&shapeB->geometry.polygon.normals[0]);
			CD2_PREFETCH(&shapeB->geometry.polygon.count);
			CD2_PREFETCH(&shapeB->enableHitEvents);
			CD2_PREFETCH(&shapeB->fatAabb.max);
		}
		cd2UpdateContact(ctx, i);
		/* What the solver sees, unless the merge changes the contact (it rewrites its entry then). */
		if (ctx->entries != NULL)
		{
			cd2SetContactSolveEntry(ctx->entries + i, ctx->world->contacts.data + i);
		}
	}
}

/* The index of the first nonzero byte of changed at or after i (count when none; every index when
 * there is no changed array). */
static int cd2NextChanged(const uint8_t* changed, int i, int count)
{
	if (changed == NULL)
	{
		return i;
	}
	while (i < count && (i & 7) != 0)
	{
		if (changed[i] != 0)
		{
			return i;
		}
		++i;
	}
	while (i + 8 <= count)
	{
		uint64_t word;
		memcpy(&word, changed + i, sizeof(word));
		if (word != 0)
		{
			break;
		}
		i += 8;
	}
	while (i < count && changed[i] == 0)
	{
		++i;
	}
	return i;
}

/* The serial part of one contact's update: destruction, the pre-solve callback, events, waking. */
static void cd2MergeContact(cd2World* world, int i)
{
	cd2Contact* contact = world->contacts.data + i;
	if (!contact->inUse || (contact->flags & (CD2_CONTACT_SIM_DISJOINT | CD2_CONTACT_SIM_UPDATED)) == 0)
	{
		return;
	}
	if ((contact->flags & CD2_CONTACT_SIM_DISJOINT) != 0)
	{
		contact->flags &= ~(uint32_t)CD2_CONTACT_SIM_DISJOINT;
		cd2DestroyContact(world, i, false);
		return;
	}
	contact->flags &= ~(uint32_t)CD2_CONTACT_SIM_UPDATED;
	const cd2WorldShape* shapeA = world->shapes.data + contact->shapeA;
	const cd2WorldShape* shapeB = world->shapes.data + contact->shapeB;
	bool wasTouching = (contact->flags & CD2_CONTACT_TOUCHING) != 0;
	bool touching = contact->pointCount > 0;
	if (touching && world->preSolveFcn != NULL &&
		(shapeA->enablePreSolveEvents || shapeB->enablePreSolveEvents))
	{
		cd2Manifold wm = cd2WorldManifold(contact);
		if (!world->preSolveFcn(cd2MakeShapeId(world, contact->shapeA),
								cd2MakeShapeId(world, contact->shapeB), &wm, world->preSolveContext))
		{
			contact->flags |= CD2_CONTACT_DISABLED;
		}
	}
	if (touching && !wasTouching && (shapeA->enableContactEvents || shapeB->enableContactEvents))
	{
		cd2ContactBeginTouchEvent e;
		e.shapeIdA = cd2MakeShapeId(world, contact->shapeA);
		e.shapeIdB = cd2MakeShapeId(world, contact->shapeB);
		e.manifold = cd2WorldManifold(contact);
		if (!cdArrayPush(world->beginEvents, e))
		{
			world->outOfMemory = true;
		}
	}
	if (touching)
	{
		contact->flags |= CD2_CONTACT_TOUCHING;
	}
	else
	{
		contact->flags &= ~(uint32_t)CD2_CONTACT_TOUCHING;
	}
	if (wasTouching && !touching)
	{
		cd2EmitEndEvent(world, contact);
		if ((contact->flags & CD2_CONTACT_SENSOR) == 0)
		{
			cd2AwakeSets_Unlink(world, contact->bodyA, contact->bodyB);
		}
	}
	if (touching && !wasTouching)
	{
		/* A new touch joins islands: wake the sleeping side. */
		if (!world->bodies.data[contact->bodyA].awake)
		{
			cd2WakeBody(world, contact->bodyA);
		}
		if (!world->bodies.data[contact->bodyB].awake)
		{
			cd2WakeBody(world, contact->bodyB);
		}
		if ((contact->flags & CD2_CONTACT_SENSOR) == 0)
		{
			cd2AwakeSets_Link(world, contact->bodyA, contact->bodyB);
		}
	}
}

/* The merge's look-ahead (see cd2UpdateContacts): hints only, never read as data. Macros, not
 * functions: GCC 12 took a function made of prefetches for one without effects and dropped its
 * calls. */
#define CD2_MERGE_AHEAD_FAR 8
#define CD2_MERGE_AHEAD_NEAR 4
/* The record's fields the merge reads first (flags, shapes, bodies, edge keys). */
#define cd2PrefetchMergeRecord(world, index)                                                                 \
	do                                                                                                       \
	{                                                                                                        \
		const cd2Contact* prefetched_ = (world)->contacts.data + (index);                                    \
		CD2_PREFETCH(&prefetched_->flags);                                                                   \
		CD2_PREFETCH(&prefetched_->nextKey[1]);                                                              \
	} while (0)
/* What destroying a contact that left its pair touches: the pair set's slot of its key and the
 * edge-list neighbours' keys. */
#define cd2PrefetchMergeTargets(world, index)                                                                \
	do                                                                                                       \
	{                                                                                                        \
		const cd2Contact* target_ = (world)->contacts.data + (index);                                        \
		if (target_->inUse && (target_->flags & CD2_CONTACT_SIM_DISJOINT) != 0)                              \
		{                                                                                                    \
			const uint64_t* slot_ =                                                                          \
				cdPairSet_HomeSlot(&(world)->pairs, cdPairKey(target_->shapeA, target_->shapeB));            \
			if (slot_ != NULL)                                                                               \
			{                                                                                                \
				CD2_PREFETCH(slot_);                                                                         \
			}                                                                                                \
			for (int side_ = 0; side_ < 2; ++side_)                                                          \
			{                                                                                                \
				if (target_->prevKey[side_] != CD2_NULL_INDEX)                                               \
				{                                                                                            \
					CD2_PREFETCH(                                                                            \
						&(world)->contacts.data[cd2EdgeContact(target_->prevKey[side_])].nextKey[0]);        \
				}                                                                                            \
				if (target_->nextKey[side_] != CD2_NULL_INDEX)                                               \
				{                                                                                            \
					CD2_PREFETCH(                                                                            \
						&(world)->contacts.data[cd2EdgeContact(target_->nextKey[side_])].prevKey[0]);        \
				}                                                                                            \
			}                                                                                                \
		}                                                                                                    \
	} while (0)

void cd2UpdateContacts(cd2World* world, cdReal timeStep)
{
	/* Manifolds on the workers, then the state changes (destruction, pre-solve callbacks, events,
	 * waking) on this thread in contact index order. */
	cd2ContactUpdateContext ctx;
	ctx.world = world;
	ctx.timeStep = timeStep;
	ctx.recycleDistance = world->contactRecycleDistance * cdGetLengthUnitsPerMeter();
	world->stepSolveEntries = NULL;
	int count = world->contacts.count;
	if (count == 0)
	{
		return;
	}
	/* Out of scratch memory (NULL): the merge reads every contact. */
	ctx.changed = (uint8_t*)cdArena_AllocUncleared(&world->arena, (size_t)count);
	ctx.entries = (cd2ContactSolveEntry*)cdArena_AllocUncleared(&world->arena,
																(size_t)count * sizeof(cd2ContactSolveEntry));
	cd2RunTask(world, cd2UpdateContactsTask, count, 64, CD2_PARALLEL_MIN_CONTACTS, &ctx);

	/* (Contacts destroyed below only free their slot: count and the indices stay valid.)
	 * Two cursors run ahead over the changed contacts, loading what the merge will read: the
	 * records CD2_MERGE_AHEAD_FAR ahead, then, CD2_MERGE_AHEAD_NEAR ahead, what destroying one
	 * touches (its pair set slot, the neighbours in its bodies' edge lists). */
	int far = 0, near = 0;
	if (ctx.changed != NULL)
	{
		far = cd2NextChanged(ctx.changed, 0, count);
		near = far;
		for (int k = 0; k < CD2_MERGE_AHEAD_FAR && far < count; ++k)
		{
			cd2PrefetchMergeRecord(world, far);
			far = cd2NextChanged(ctx.changed, far + 1, count);
		}
		for (int k = 0; k < CD2_MERGE_AHEAD_NEAR && near < count; ++k)
		{
			cd2PrefetchMergeTargets(world, near);
			near = cd2NextChanged(ctx.changed, near + 1, count);
		}
	}
	for (int i = cd2NextChanged(ctx.changed, 0, count); i < count;
		 i = cd2NextChanged(ctx.changed, i + 1, count))
	{
		if (far < count)
		{
			cd2PrefetchMergeRecord(world, far);
			far = cd2NextChanged(ctx.changed, far + 1, count);
		}
		if (near < count)
		{
			cd2PrefetchMergeTargets(world, near);
			near = cd2NextChanged(ctx.changed, near + 1, count);
		}
		cd2MergeContact(world, i);
		if (ctx.entries != NULL)
		{
			cd2SetContactSolveEntry(ctx.entries + i, world->contacts.data + i);
		}
	}
	world->stepSolveEntries = ctx.entries;
}
