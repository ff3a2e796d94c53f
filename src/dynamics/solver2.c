/* collide: the 2D step's solve: the dense arrays of awake bodies and touching contacts, the
 * sub-stepped soft step (integrate velocities, warm start, solve with bias, integrate positions,
 * relax without bias; restitution last), then finalize (transforms, bounds, continuous collision,
 * hit and move events, sleep). The contacts are sorted by graph colour; the coloured ones are solved
 * CD_W at a time (contact_solver_wide2.c), the overflow colour and the joints one by one.
 *
 * Scheduling: everything from listing the awake bodies and the touching contacts to finalizing the
 * bodies is two fixed lists of stages, each an index range (chunks of bodies or contacts, bodies,
 * joints, constraints, wide blocks of one colour, or a single item for the serial parts) cut into
 * blocks. The first list is the setup's (cd2SolveSetup): the dense lists of bodies and constraints,
 * then the colourings of the contacts and of the joints next to the filling of the solver bodies;
 * the stepping thread then lays out the wide blocks and sets the second list from what the first
 * found: preparing the joints and contacts, the sub-steps, finalize. Every thread of the step (the
 * stepping thread and one task per further worker, enqueued once per list) walks the same list: it takes
 * blocks of the current stage with an atomic counter until none is left, adds the number it finished to the
 * stage's count, then waits until every block of the stage is finished before going on to the next
 * (cdSyncCount: a short spin, then asleep, so that a thread descheduled in the middle of a block can take
 * over the waiting thread's processor). Consecutive stages of one block each (the last small colours, the
 * overflow colour) are one block of one stage, run by one thread in list order: one wait instead of one per
 * stage. A small solve (CD2_PARALLEL_MIN_SOLVE) runs the list on the stepping thread alone. A thread only
 * ever waits for blocks that a running thread has taken, never for another thread to arrive, so the step
 * finishes whatever the task system does with the tasks (run them late, inline or one after another). Each
 * block writes only its own items (a colour's blocks share no movable body), so the results are the same bits
 * for any worker count.
 *
 * The last stage, finalize, does per body all that reads only the body itself and static geometry:
 * transform, sleep time, continuous collision of a fast non-bullet, the shapes' tight boxes, the
 * move event (written at the body's solver index). What reads other bodies' final poses or writes
 * a shared structure follows on the stepping thread, over the bodies finalize flagged, in body
 * order as before: kinematic wakes, bullets, then the broadphase moves (after every sweep: the
 * sweeps query the broadphase as it was before the step's moves). */
#include "world2_internal.h"

#include "../base/graph_color.h"
#include "../broad/broad_internal.h"
#include "../base/thread_pool.h"

#if !defined(__STDC_NO_ATOMICS__)
#include <stdatomic.h>
#define CD2_STAGE_ATOMICS 1
typedef atomic_int cd2StageCounter;
#else
/* No C11 atomics: the step runs on the stepping thread only. */
#define CD2_STAGE_ATOMICS 0
typedef int cd2StageCounter;
#endif

cd2Softness cd2MakeSoft(cdReal hertz, cdReal zeta, cdReal h)
{
	cd2Softness soft = {CD_R(0.0), CD_R(1.0), CD_R(0.0)};
	if (hertz == CD_R(0.0))
	{
		return soft;
	}
	cdReal omega = CD_R(2.0) * CD_PI * hertz;
	cdReal a1 = CD_R(2.0) * zeta + h * omega;
	cdReal a2 = h * omega * a1;
	cdReal a3 = CD_R(1.0) / (CD_R(1.0) + a2);
	soft.biasRate = omega / a1;
	soft.massScale = a2 * a3;
	soft.impulseScale = a3;
	return soft;
}

cd2Rot cd2IntegrateRotation(cd2Rot q, cdReal deltaAngle)
{
	cd2Rot q2 = {q.c - deltaAngle * q.s, q.s + deltaAngle * q.c};
	cdReal mag = cdSqrt(q2.s * q2.s + q2.c * q2.c);
	cdReal invMag = mag > CD_R(0.0) ? CD_R(1.0) / mag : CD_R(0.0);
	cd2Rot out = {q2.c * invMag, q2.s * invMag};
	return out;
}

static void cd2IntegrateVelocities(cd2StepContext* context, int start, int end)
{
	cdReal maxLinear = context->maxLinearVelocity;
	cdReal maxAngular = CD2_MAX_ROTATION * context->inv_h;
	for (int i = start; i < end; ++i)
	{
		const cd2SolverBodyParams* p = context->params + i;
		cd2SolverBody* s = context->bodies + i;
		if (!p->dynamic)
		{
			continue;
		}
		cd2Vec v = s->linearVelocity;
		cdReal w = s->angularVelocity;
		/* Damping as an implicit factor: stable for any damping and step. */
		v = cd2MulAdd(p->deltaV, p->linearDamping, v);
		w = p->deltaW + w / p->angularDamping;
		if (cd2Dot(v, v) > maxLinear * maxLinear)
		{
			v = cd2Scale(maxLinear / cd2Length(v), v);
		}
		if (w * w > maxAngular * maxAngular)
		{
			w = w > CD_R(0.0) ? maxAngular : -maxAngular;
		}
		s->linearVelocity = v;
		s->angularVelocity = w;
	}
}

static void cd2IntegratePositions(cd2StepContext* context, int start, int end)
{
	cdReal h = context->h;
	cdReal maxLinear = context->maxLinearVelocity;
	cdReal maxAngular = CD2_MAX_ROTATION * context->inv_h;
	for (int i = start; i < end; ++i)
	{
		cd2SolverBody* s = context->bodies + i;
		/* The speed caps hold after the constraints too: conflicting joints (a loop of rigid joints
		 * that cannot all hold) must not run away. */
		if (cd2Dot(s->linearVelocity, s->linearVelocity) > maxLinear * maxLinear)
		{
			s->linearVelocity = cd2Scale(maxLinear / cd2Length(s->linearVelocity), s->linearVelocity);
		}
		if (s->angularVelocity * s->angularVelocity > maxAngular * maxAngular)
		{
			s->angularVelocity = s->angularVelocity > CD_R(0.0) ? maxAngular : -maxAngular;
		}
		s->deltaRotation = cd2IntegrateRotation(s->deltaRotation, h * s->angularVelocity);
		s->deltaPosition = cd2MulAdd(s->deltaPosition, h, s->linearVelocity);
	}
}

/* The solver bodies [start, end) from their world bodies. */
static void cd2SetupBodies(cd2World* world, cd2StepContext* context, int start, int end)
{
	cdReal h = context->h;
	for (int k = start; k < end; ++k)
	{
		cd2Body* body = world->bodies.data + context->bodyIndices[k];
		context->accelerations[k] =
			body->invMass > CD_R(0.0)
				? cd2MulAdd(cd2Scale(body->invMass, body->force), body->gravityScale, world->gravity)
				: CD2_VEC_ZERO;
		body->center0 = body->center;
		body->rotation0 = body->transform.q;
		body->isFast = false;
		cd2SolverBody* s = context->bodies + k;
		s->linearVelocity = body->linearVelocity;
		s->angularVelocity = body->angularVelocity;
		s->deltaPosition = CD2_VEC_ZERO;
		s->deltaRotation = CD2_ROT_IDENTITY;
		s->invMass = body->invMass;
		s->invInertia = body->invInertia;
		cd2SolverBodyParams* p = context->params + k;
		p->dynamic = body->type == CD_DYNAMIC_BODY;
		p->deltaV = cd2Scale(h * body->invMass,
							 cd2MulAdd(body->force, body->mass * body->gravityScale, world->gravity));
		p->deltaW = h * body->invInertia * body->torque;
		p->linearDamping = CD_R(1.0) / (CD_R(1.0) + h * body->linearDamping);
		p->angularDamping = CD_R(1.0) + h * body->angularDamping;
	}
}

static void cd2FinalizeBodies(cd2World* world, const cd2StepContext* context, int start, int end)
{
	bool sleepAllowed = world->enableSleep;
	cdReal timeStep = context->dt;
	for (int k = start; k < end; ++k)
	{
		cd2Body* body = world->bodies.data + context->bodyIndices[k];
		const cd2SolverBody* s = context->bodies + k;
		body->linearVelocity = s->linearVelocity;
		body->angularVelocity = s->angularVelocity;
		/* The relax pass and restitution come after the last position update: cap once more. */
		if (cd2Dot(body->linearVelocity, body->linearVelocity) >
			context->maxLinearVelocity * context->maxLinearVelocity)
		{
			body->linearVelocity =
				cd2Scale(context->maxLinearVelocity / cd2Length(body->linearVelocity), body->linearVelocity);
		}
		body->center = cd2Add(body->center, s->deltaPosition);
		body->transform.q = cd2NormalizeRot(cd2MulRot(s->deltaRotation, body->transform.q));
		body->transform.p = cd2Sub(body->center, cd2RotateVector(body->transform.q, body->localCenter));
		body->force = CD2_VEC_ZERO;
		body->torque = CD_R(0.0);
		cdReal speed = cd2Length(body->linearVelocity);
		cdReal sleepVelocity = cdMax(body->maxExtent * cdAbs(body->angularVelocity), speed);
		if (!sleepAllowed || !body->enableSleep || sleepVelocity > body->sleepThreshold)
		{
			body->sleepTime = CD_R(0.0);
		}
		else
		{
			body->sleepTime += timeStep;
		}
		if (world->enableContinuous && body->type == CD_DYNAMIC_BODY)
		{
			/* Fast: it may have moved through something thinner than half its inner extent. */
			cdReal travel = speed * timeStep + cdAbs(body->angularVelocity) * timeStep * body->maxExtent;
			body->isFast = body->isBullet || CD_R(0.5) * body->minExtent < travel;
		}
		unsigned flags = 0u;
		if (body->type == CD_KINEMATIC_BODY)
		{
			flags |= CD2_FINAL_KINEMATIC;
		}
		if (body->sleepTime >= CD2_TIME_TO_SLEEP)
		{
			flags |= CD2_FINAL_RESTED;
		}
		if (body->isFast && body->isBullet)
		{
			/* A bullet sweeps against the others' final poses: after this stage, on one thread. */
			context->finalFlags[k] = (uint8_t)(flags | CD2_FINAL_BULLET);
			continue;
		}
		if (body->isFast)
		{
			/* A fast non-bullet sweeps against static shapes only: it reads the broadphase (not
			 * moved until after this stage), the static bodies and itself, and writes only itself,
			 * so it runs here, with the same result as after every other body. */
			cd2SolveContinuous(world, context->bodyIndices[k]);
		}
		/* The shapes' boxes from the final transform; the broadphase hears of those that left their
		 * fat box after this stage, in body order (its tree is not thread-safe). */
		for (int si = body->headShape; si != CD2_NULL_INDEX; si = world->shapes.data[si].nextShape)
		{
			cd2WorldShape* shape = world->shapes.data + si;
			shape->aabb = cd2ComputeShapeBounds(world, shape);
			if (cd2ShapeProxyNeedsSync(shape))
			{
				if ((flags & CD2_FINAL_SYNC_PROXY) != 0u)
				{
					flags |= CD2_FINAL_SYNC_SEVERAL;
				}
				else
				{
					flags |= CD2_FINAL_SYNC_PROXY;
					cd2FinalSync* sync = context->finalSync + k;
					sync->shape = si;
					sync->proxy = shape->proxyId;
					sync->fat = cd2ComputeShapeFatBox(world, shape);
				}
			}
		}
		context->finalFlags[k] = (uint8_t)flags;
		if (context->moveEvents != NULL)
		{
			cd2BodyMoveEvent* event = context->moveEvents + k;
			event->transform = body->transform;
			event->bodyId = cd2MakeBodyId(world, context->bodyIndices[k]);
			event->userData = body->userData;
			event->fellAsleep = false;
		}
	}
}

typedef enum cd2StageKind
{
	CD2_STAGE_COUNT_BODIES,			/* chunks of world bodies (the setup's, before the list) */
	CD2_STAGE_LIST_BODIES,			/* chunks of world bodies, then of contacts and of joints (counted) */
	CD2_STAGE_LIST_CONTACTS,		/* chunks of contacts, then of joints */
	CD2_STAGE_COLOR_AND_SETUP,		/* the two colourings, then blocks of bodies */
	CD2_STAGE_PREPARE_JOINTS,		/* joints, in index order */
	CD2_STAGE_PREPARE_CONTACTS,		/* constraints */
	CD2_STAGE_PACK_WIDE,			/* wide blocks */
	CD2_STAGE_INTEGRATE_VELOCITIES, /* bodies */
	CD2_STAGE_WARM_START_JOINTS,	/* joints of one colour */
	CD2_STAGE_WARM_START_WIDE,		/* wide blocks of one colour */
	CD2_STAGE_WARM_START_OVERFLOW,	/* single */
	CD2_STAGE_SOLVE_JOINTS,			/* joints of one colour */
	CD2_STAGE_SOLVE_WIDE,			/* wide blocks of one colour */
	CD2_STAGE_SOLVE_OVERFLOW,		/* single */
	CD2_STAGE_INTEGRATE_POSITIONS,	/* bodies */
	CD2_STAGE_STORE_WIDE,			/* wide blocks */
	CD2_STAGE_RESTITUTION_WIDE,		/* wide blocks of one colour */
	CD2_STAGE_RESTITUTION,			/* single */
	CD2_STAGE_STORE_IMPULSES,		/* constraints */
	CD2_STAGE_STORE_JOINTS,			/* joints */
	CD2_STAGE_FINALIZE_BODIES		/* bodies */
} cd2StageKind;

typedef struct cd2Stage
{
	/* A cache line per stage (the list is placed on a line boundary): the threads' writes to one
	 * stage's counters do not evict the next stage's fields from the other threads' caches. */
	_Alignas(64) cd2StageCounter claimed; /* blocks taken */
#if CD2_STAGE_ATOMICS
	cdSyncCount done; /* blocks finished (each thread adds its count once it has no more) */
#endif
	cd2StageKind kind;
	bool useBias;
	int first; /* the first item (a colour's first wide block) */
	int itemCount, blockSize, blockCount;
	/* A stage of one block that starts a run of such stages: the run's length (the whole run is
	 * one block of this stage, done by one thread in list order, one wait instead of one per
	 * stage: the small colours at the end of the colouring, the overflow colour, a few joints);
	 * 1 otherwise. */
	int runLength;
} cd2Stage;

/* The setup of the step before the stages proper: the dense lists of awake bodies, of the
 * touching contacts and of the joints to solve, counted and then written chunk by chunk (chunks of a
 * fixed size, so that the lists do not depend on how the chunks are split among threads; the
 * contacts and joints are counted in the stage that lists the bodies), then the colourings of the
 * contacts and of the joints, each on one thread, next to the filling of the solver bodies. The
 * scratch is allocated before, for the largest counts (the arena is not for several threads). */
#define CD2_SETUP_CHUNK 1024

typedef struct cd2SolveSetup
{
	int* solverOf;	   /* per world body: its solver index, or CD2_NULL_INDEX */
	int* colorBodyOf;  /* the same for dynamic bodies only (kinematic ones take no colour) */
	uint8_t* bodyKind; /* per world body: 0 not solved, 1 kinematic, 2 dynamic */
	int* bodyChunkCounts;
	int bodyChunkCount;
	const cd2ContactSolveEntry* entries; /* NULL: read from the contacts */
	int* contactChunkCounts;
	int* contactChunkHits;
	uint8_t* contactChunkNew; /* the chunk's constraints differ from the cached colouring's */
	int contactChunkCount;
	int* jointChunkCounts;
	int* jointChunkThresholds; /* of which with a force or torque threshold */
	/* Per joint, from the count: its bodies when solved, else CD2_NULL_INDEX twice (the list then
	 * reads this small array, not the joint records again). */
	int* jointBodies;
	/* On one thread: the joints are not counted first but listed in one pass over their records
	 * (the list stage is one block then). */
	bool jointsInOnePass;
	int jointChunkCount;
	cd2ConstraintPair* pairs; /* the constraints in contact index order */
	int* bodyA;				  /* the colouring's bodies of each pair */
	int* bodyB;
	/* The last steps' colourings (NULL: none, out of memory), whose colours and order are taken
	 * when the constraints are the same; otherwise they keep the new ones. */
	cd2ColorCache* contactCache;
	cd2ColorCache* jointCache;
	/* The contacts' colouring, in the cache or else in the step's scratch (NULL when out of
	 * memory: then not coloured). */
	int* colors;
	int* order;
	cd2ConstraintPair* sorted;
	uint32_t* used;
	int colorStart[CD_GRAPH_COLOR_COUNT + 2];
	/* The joints' (NULL when out of memory: every joint in the overflow colour). */
	int* jointBodyA;
	int* jointBodyB;
	int* jointColors;
	int* jointOrder;
	int* jointSorted;
	uint32_t* jointUsed;
	int jointColorScratch[CD_GRAPH_COLOR_COUNT + 2];
	/* The bodies per block of the solver bodies' filling, next to the colourings. */
	int setupBlockSize;
	/* The joints' colouring is the first item (when there are more joints than contacts). */
	bool jointsFirst;
} cd2SolveSetup;

typedef struct cd2StageList
{
	cd2World* world;
	cd2StepContext* step;
	cd2SolveSetup* setup;
	/* The setup's stages, walked first; then the rest, set by the stepping thread from what the
	 * setup found (two walks, each with its own tasks: a thread never waits for another to arrive). */
	cd2Stage* preStages;
	int preStageCount;
	cd2Stage* stages;
	int stageCount, stageCapacity;
	int workerCount;
	/* Set by the prepare and pack stages when a constraint has restitution; the restitution stages,
	 * after them, are passed over by every worker while it is 0. */
	cd2StageCounter* bouncing;
} cd2StageList;

void cd2ColorCache_Destroy(cd2ColorCache* cache)
{
	cdFree(cache->bodyA);
	cdFree(cache->bodyB);
	cdFree(cache->colors);
	cdFree(cache->order);
	memset(cache, 0, sizeof(*cache));
}

/* Room for capacity constraints (a larger cache forgets its colouring); false when out of memory
 * (then the cache is empty and unused). */
static bool cd2ColorCache_Reserve(cd2ColorCache* cache, int capacity)
{
	if (capacity <= cache->capacity)
	{
		return true;
	}
	int grown = cdMaxInt(cdMaxInt(capacity, cache->capacity + cache->capacity / 2), 64);
	cd2ColorCache_Destroy(cache);
	size_t size = (size_t)grown * sizeof(int);
	cache->bodyA = (int*)cdAlloc(size);
	cache->bodyB = (int*)cdAlloc(size);
	cache->colors = (int*)cdAlloc(size);
	cache->order = (int*)cdAlloc(size);
	if (cache->bodyA == NULL || cache->bodyB == NULL || cache->colors == NULL || cache->order == NULL)
	{
		cd2ColorCache_Destroy(cache);
		return false;
	}
	cache->capacity = grown;
	return true;
}

static int cd2ChunkEnd(int chunk, int count)
{
	return count - chunk * CD2_SETUP_CHUNK > CD2_SETUP_CHUNK ? (chunk + 1) * CD2_SETUP_CHUNK : count;
}

/* Where chunk startChunk's items start in a dense list: the counts of the chunks before it. */
static int cd2ChunkOffset(const int* chunkCounts, int startChunk)
{
	int offset = 0;
	for (int c = 0; c < startChunk; ++c)
	{
		offset += chunkCounts[c];
	}
	return offset;
}

/* Chunks [startChunk, endChunk) of the world bodies: which are solved (awake, enabled, not static),
 * counted per chunk; the others lose their solver index. */
static void cd2CountBodies(cd2World* world, cd2SolveSetup* setup, int startChunk, int endChunk)
{
	int count = world->bodies.count;
	for (int c = startChunk; c < endChunk; ++c)
	{
		int solved = 0;
		for (int i = c * CD2_SETUP_CHUNK, end = cd2ChunkEnd(c, count); i < end; ++i)
		{
			cd2Body* body = world->bodies.data + i;
			uint8_t kind = 0;
			if (!body->inUse || !body->enabled || !body->awake || body->type == CD_STATIC_BODY)
			{
				if (body->solverIndex != CD2_NULL_INDEX) /* (most are already: no write) */
				{
					body->solverIndex = CD2_NULL_INDEX;
				}
			}
			else
			{
				kind = body->type == CD_DYNAMIC_BODY ? 2 : 1;
				++solved;
			}
			setup->bodyKind[i] = kind;
		}
		setup->bodyChunkCounts[c] = solved;
	}
}

/* The solved bodies of chunks [startChunk, endChunk) get their dense indices, in body order after
 * those of the chunks before (the same whatever the split). */
static void cd2ListBodies(cd2World* world, cd2StepContext* context, cd2SolveSetup* setup, int startChunk,
						  int endChunk)
{
	int k = cd2ChunkOffset(setup->bodyChunkCounts, startChunk);
	int end = cd2ChunkEnd(endChunk - 1, world->bodies.count);
	for (int i = startChunk * CD2_SETUP_CHUNK; i < end; ++i)
	{
		uint8_t kind = setup->bodyKind[i];
		if (kind == 0)
		{
			setup->solverOf[i] = CD2_NULL_INDEX;
			setup->colorBodyOf[i] = CD2_NULL_INDEX;
			continue;
		}
		setup->solverOf[i] = k;
		setup->colorBodyOf[i] = kind == 2 ? k : CD2_NULL_INDEX;
		world->bodies.data[i].solverIndex = k;
		context->bodyIndices[k] = i;
		++k;
	}
	if (endChunk == setup->bodyChunkCount)
	{
		context->bodyCount = k;
	}
}

/* The contact's solve entry (from the contact update, else from the contact) and whether it is a
 * constraint this step: touching, with an awake body. */
static bool cd2ContactSolved(const cd2World* world, const cd2SolveSetup* setup, int i,
							 cd2ContactSolveEntry* out)
{
	if (setup->entries != NULL)
	{
		*out = setup->entries[i];
	}
	else
	{
		cd2SetContactSolveEntry(out, world->contacts.data + i);
	}
	/* (The kinds, not the solver indices: the contacts are counted while the bodies are listed.) */
	return out->bodyA != CD2_NULL_INDEX &&
		   (setup->bodyKind[out->bodyA] != 0 || setup->bodyKind[out->bodyB] != 0);
}

static void cd2CountContacts(cd2World* world, cd2SolveSetup* setup, int startChunk, int endChunk)
{
	int count = world->contacts.count;
	for (int c = startChunk; c < endChunk; ++c)
	{
		int solved = 0, hits = 0;
		for (int i = c * CD2_SETUP_CHUNK, end = cd2ChunkEnd(c, count); i < end; ++i)
		{
			cd2ContactSolveEntry entry;
			if (cd2ContactSolved(world, setup, i, &entry))
			{
				++solved;
				hits += (entry.flags & CD2_CONTACT_HIT_EVENTS) != 0 ? 1 : 0;
			}
		}
		setup->contactChunkCounts[c] = solved;
		setup->contactChunkHits[c] = hits;
	}
}

/* The constraints of chunks [startChunk, endChunk): their pairs in contact index order. */
static void cd2ListContacts(cd2World* world, cd2StepContext* context, cd2SolveSetup* setup, int startChunk,
							int endChunk)
{
	int k = cd2ChunkOffset(setup->contactChunkCounts, startChunk);
	const cd2ColorCache* cache = setup->contactCache;
	int cached = cache != NULL ? cache->count : 0;
	for (int c = startChunk; c < endChunk; ++c)
	{
		bool fresh = false;
		for (int i = c * CD2_SETUP_CHUNK, end = cd2ChunkEnd(c, world->contacts.count); i < end; ++i)
		{
			cd2ContactSolveEntry entry;
			if (!cd2ContactSolved(world, setup, i, &entry))
			{
				continue;
			}
			int a = setup->colorBodyOf[entry.bodyA], b = setup->colorBodyOf[entry.bodyB];
			setup->pairs[k].contact = i;
			setup->pairs[k].indexA = setup->solverOf[entry.bodyA];
			setup->pairs[k].indexB = setup->solverOf[entry.bodyB];
			setup->bodyA[k] = a;
			setup->bodyB[k] = b;
			fresh = fresh || k >= cached || cache->bodyA[k] != a || cache->bodyB[k] != b;
			++k;
		}
		setup->contactChunkNew[c] = (uint8_t)fresh;
	}
	if (endChunk == setup->contactChunkCount)
	{
		context->constraintCount = k;
	}
}

/* Colour order of the contacts (see graph_color.h); the pairs stay in index order when there is no
 * scratch. */
static void cd2ColorContacts(cd2StepContext* context, cd2SolveSetup* setup)
{
	context->indexOrder = setup->pairs;
	context->pairs = setup->pairs;
	int n = context->constraintCount;
	if (n < 2 || setup->colors == NULL || setup->order == NULL || setup->sorted == NULL ||
		setup->used == NULL)
	{
		return;
	}
	cd2ColorCache* cache = setup->contactCache;
	bool same = cache != NULL && cache->count == n;
	for (int c = 0; c < setup->contactChunkCount && same; ++c)
	{
		same = setup->contactChunkNew[c] == 0;
	}
	if (!same)
	{
		cdColorConstraintsScratch(setup->bodyA, setup->bodyB, n, context->bodyCount, setup->colors,
								  setup->order, true, setup->used, setup->colorStart);
		if (cache != NULL)
		{
			memcpy(cache->bodyA, setup->bodyA, (size_t)n * sizeof(int));
			memcpy(cache->bodyB, setup->bodyB, (size_t)n * sizeof(int));
			cache->count = n;
		}
	}
	for (int i = 0; i < n; ++i)
	{
		setup->sorted[i] = setup->pairs[setup->order[i]];
		setup->bodyA[i] = setup->colors[setup->order[i]];
	}
	context->pairs = setup->sorted;
	context->colorOfConstraint = setup->bodyA;
}

/* Sorts context->joints by graph colour (graph_color.h), as the contacts: the joints of one
 * colour share no awake body, so a colour's joints run on any number of threads with the same
 * bits, and the results do not depend on the worker count. Kinematic bodies count as movable here
 * (a joint's solve writes both of its awake bodies); static and sleeping ones do not. Out of
 * scratch memory: every joint in the overflow colour, in index order, on one thread. Also the
 * slots of the sorted joints in joint index order (context->jointIndexOrder: the listed joints
 * were in index order, so it is the inverse of the colour order). */
static void cd2ColorJoints(cd2StepContext* context, cd2SolveSetup* setup)
{
	int n = context->jointCount;
	int* start = context->jointColorStart;
	int* indexOrder = context->jointIndexOrder;
	for (int c = 0; c < CD_GRAPH_COLOR_COUNT + 2; ++c)
	{
		start[c] = 0;
	}
	start[CD_GRAPH_COLOR_COUNT + 1] = n;
	if (n < 2 || setup->jointBodyA == NULL || setup->jointBodyB == NULL || setup->jointColors == NULL ||
		setup->jointOrder == NULL || setup->jointSorted == NULL || setup->jointUsed == NULL)
	{
		for (int k = 0; k < n && indexOrder != NULL; ++k)
		{
			indexOrder[k] = k;
		}
		return;
	}
	int* colors = setup->jointColors;
	int* order = setup->jointOrder;
	int* sorted = setup->jointSorted;
	cd2ColorCache* cache = setup->jointCache;
	if (cache == NULL || cache->count != n ||
		memcmp(cache->bodyA, setup->jointBodyA, (size_t)n * sizeof(int)) != 0 ||
		memcmp(cache->bodyB, setup->jointBodyB, (size_t)n * sizeof(int)) != 0)
	{
		cdColorConstraintsScratch(setup->jointBodyA, setup->jointBodyB, n, context->bodyCount, colors, order,
								  false, setup->jointUsed, setup->jointColorScratch);
		if (cache != NULL)
		{
			memcpy(cache->bodyA, setup->jointBodyA, (size_t)n * sizeof(int));
			memcpy(cache->bodyB, setup->jointBodyB, (size_t)n * sizeof(int));
			cache->count = n;
		}
	}
	start[CD_GRAPH_COLOR_COUNT + 1] = 0;
	for (int i = 0; i < n; ++i)
	{
		sorted[i] = context->joints[order[i]];
		start[colors[i] + 1] += 1;
	}
	for (int i = 0; i < n && indexOrder != NULL; ++i)
	{
		indexOrder[order[i]] = i;
	}
	for (int c = 1; c < CD_GRAPH_COLOR_COUNT + 2; ++c)
	{
		start[c] += start[c - 1];
	}
	memcpy(context->joints, sorted, (size_t)n * sizeof(int));
}

/* The joint events of the step: the solved joints whose reaction exceeded a threshold, in the
 * solver's (deterministic) joint order. On the calling thread, after the stages stored the
 * reactions; only when some solved joint has a threshold. */
static void cd2ReportJointEvents(cd2World* world, const cd2StepContext* context)
{
	for (int i = 0; i < context->jointCount; ++i)
	{
		int index = context->joints[i];
		const cd2Joint* joint = world->joints.data + index;
		cdReal force = cd2Length(joint->constraintForce), torque = cdAbs(joint->constraintTorque);
		bool overForce = joint->forceThreshold > CD_R(0.0) && force > joint->forceThreshold;
		bool overTorque = joint->torqueThreshold > CD_R(0.0) && torque > joint->torqueThreshold;
		if (!overForce && !overTorque)
		{
			continue;
		}
		if (!cdArrayReserveFor(world->jointEvents, world->jointEvents.count + 1))
		{
			world->outOfMemory = true;
			return;
		}
		cd2JointEvent* event = world->jointEvents.data + world->jointEvents.count++;
		cd2JointId id = {index + 1, world->index, joint->generation};
		event->jointId = id;
		event->userData = joint->userData;
		event->force = joint->constraintForce;
		event->torque = joint->constraintTorque;
	}
}

/* Whether joint i is solved: an awake body, none disabled (a body not solved is static, asleep or
 * disabled; a disabled one drops the joint). By the bodies' kinds: counted while they are listed. */
static bool cd2JointSolved(const cd2World* world, const cd2SolveSetup* setup, const cd2Joint* joint)
{
	if (!joint->inUse || joint->type == CD2_FILTER_JOINT)
	{
		return false;
	}
	bool solvedA = setup->bodyKind[joint->bodyA] != 0, solvedB = setup->bodyKind[joint->bodyB] != 0;
	return (solvedA || solvedB) && (solvedA || world->bodies.data[joint->bodyA].enabled) &&
		   (solvedB || world->bodies.data[joint->bodyB].enabled);
}

static void cd2CountJoints(cd2World* world, cd2SolveSetup* setup, int startChunk, int endChunk)
{
	int count = world->joints.count;
	for (int c = startChunk; c < endChunk; ++c)
	{
		int solved = 0, thresholds = 0;
		for (int i = c * CD2_SETUP_CHUNK, end = cd2ChunkEnd(c, count); i < end; ++i)
		{
			const cd2Joint* joint = world->joints.data + i;
			if (i + 16 < end)
			{
				CD2_PREFETCH(joint + 16);
			}
			bool isSolved = cd2JointSolved(world, setup, joint);
			setup->jointBodies[2 * i] = isSolved ? joint->bodyA : CD2_NULL_INDEX;
			setup->jointBodies[2 * i + 1] = isSolved ? joint->bodyB : CD2_NULL_INDEX;
			if (isSolved)
			{
				++solved;
				thresholds += joint->forceThreshold > CD_R(0.0) || joint->torqueThreshold > CD_R(0.0) ? 1 : 0;
			}
		}
		setup->jointChunkCounts[c] = solved;
		setup->jointChunkThresholds[c] = thresholds;
	}
}

/* The joints to solve of chunks [startChunk, endChunk), in index order after those of the chunks
 * before (coloured later, see cd2ColorJoints). */
static void cd2ListJoints(cd2World* world, cd2StepContext* context, cd2SolveSetup* setup, int startChunk,
						  int endChunk)
{
	int k = cd2ChunkOffset(setup->jointChunkCounts, startChunk);
	const int* solverOf = setup->solverOf;
	int count = world->joints.count;
	bool onePass = setup->jointsInOnePass;
	CD_ASSERT(!onePass || (startChunk == 0 && endChunk == setup->jointChunkCount));
	int thresholds = 0;
	for (int i = startChunk * CD2_SETUP_CHUNK, end = cd2ChunkEnd(endChunk - 1, count);
		 i < end && context->joints != NULL; ++i)
	{
		int bodyA, bodyB;
		if (onePass)
		{
			const cd2Joint* joint = world->joints.data + i;
			if (i + 16 < end)
			{
				CD2_PREFETCH(joint + 16);
			}
			if (!cd2JointSolved(world, setup, joint))
			{
				continue;
			}
			bodyA = joint->bodyA;
			bodyB = joint->bodyB;
			thresholds += joint->forceThreshold > CD_R(0.0) || joint->torqueThreshold > CD_R(0.0) ? 1 : 0;
		}
		else
		{
			bodyA = setup->jointBodies[2 * i];
			bodyB = setup->jointBodies[2 * i + 1];
			if (bodyA == CD2_NULL_INDEX)
			{
				continue;
			}
		}
		if (setup->jointBodyA != NULL && setup->jointBodyB != NULL)
		{
			setup->jointBodyA[k] = solverOf[bodyA];
			setup->jointBodyB[k] = solverOf[bodyB];
		}
		context->joints[k++] = i;
	}
	if (endChunk == setup->jointChunkCount)
	{
		for (int c = 0; c < setup->jointChunkCount && !onePass; ++c)
		{
			thresholds += setup->jointChunkThresholds[c];
		}
		context->jointCount = k;
		context->thresholdJointCount = thresholds;
	}
}

/* Items [start, end) of the colour-and-setup stage: item 0 and item 1 are the contacts' and the
 * joints' colourings (the larger first), each whole on one thread; item 2 + b fills block b of the
 * solver bodies. */
static void cd2ColorAndSetup(cd2World* world, cd2StepContext* context, cd2SolveSetup* setup, int start,
							 int end)
{
	for (int item = start; item < end; ++item)
	{
		int job = item < 2 && setup->jointsFirst ? 1 - item : item;
		if (job == 0)
		{
			cd2ColorContacts(context, setup);
		}
		else if (job == 1)
		{
			cd2ColorJoints(context, setup);
		}
		else
		{
			int first = (job - 2) * setup->setupBlockSize;
			int last = cdMinInt(first + setup->setupBlockSize, context->bodyCount);
			if (first < last)
			{
				cd2SetupBodies(world, context, first, last);
			}
		}
	}
}

/* Appends a stage of itemCount items in blocks of at least minBlock (a few blocks per worker). */
static void cd2AddStage(cd2StageList* list, cd2StageKind kind, int itemCount, int minBlock, int first,
						bool useBias)
{
	if (itemCount <= 0 || list->stageCount >= list->stageCapacity)
	{
		return;
	}
	cd2Stage* stage = list->stages + list->stageCount++;
	int blockSize = itemCount;
	if (list->workerCount > 1)
	{
		int even = (itemCount + 4 * list->workerCount - 1) / (4 * list->workerCount);
		blockSize = even > minBlock ? even : minBlock;
	}
#if CD2_STAGE_ATOMICS
	atomic_init(&stage->claimed, 0);
	cdSyncCount_Init(&stage->done, 0);
#else
	stage->claimed = 0;
#endif
	stage->kind = kind;
	stage->useBias = useBias;
	stage->first = first;
	stage->itemCount = itemCount;
	stage->blockSize = blockSize;
	stage->blockCount = (itemCount + blockSize - 1) / blockSize;
	stage->runLength = 1;
}

/* Joins each run of consecutive one-block stages into one (see runLength). */
static void cd2JoinSmallStages(cd2StageList* list)
{
	for (int s = 0; s < list->stageCount;)
	{
		int end = s + 1;
		if (list->stages[s].blockCount == 1)
		{
			while (end < list->stageCount && list->stages[end].blockCount == 1)
			{
				++end;
			}
		}
		list->stages[s].runLength = end - s;
		s = end;
	}
}

static void cd2AddWideStages(cd2StageList* list, cd2StageKind kind, bool useBias)
{
	const cd2StepContext* context = list->step;
	for (int c = 0; c < context->colorCount; ++c)
	{
		int first = context->colorBlockStart[c];
		cd2AddStage(list, kind, context->colorBlockStart[c + 1] - first, 4, first, useBias);
	}
}

static void cd2SetBouncing(const cd2StageList* list)
{
#if CD2_STAGE_ATOMICS
	atomic_store_explicit(list->bouncing, 1, memory_order_relaxed);
#else
	*list->bouncing = 1;
#endif
}

static bool cd2StageSkipped(const cd2StageList* list, const cd2Stage* stage)
{
	if (stage->kind != CD2_STAGE_RESTITUTION_WIDE && stage->kind != CD2_STAGE_RESTITUTION)
	{
		return false;
	}
#if CD2_STAGE_ATOMICS
	return atomic_load_explicit(list->bouncing, memory_order_relaxed) == 0;
#else
	return *list->bouncing == 0;
#endif
}

static void cd2ExecuteStage(const cd2StageList* list, const cd2Stage* stage, int start, int end)
{
	cd2World* world = list->world;
	cd2StepContext* context = list->step;
	switch (stage->kind)
	{
		case CD2_STAGE_COUNT_BODIES:
			cd2CountBodies(world, list->setup, start, end);
			break;
		case CD2_STAGE_LIST_BODIES:
		{
			/* Items: the body chunks, then the contact chunks and the joint chunks to count. */
			const cd2SolveSetup* setup = list->setup;
			int bodies = setup->bodyChunkCount, contacts = bodies + setup->contactChunkCount;
			if (start < bodies)
			{
				cd2ListBodies(world, context, list->setup, start, cdMinInt(end, bodies));
			}
			if (start < contacts && end > bodies)
			{
				cd2CountContacts(world, list->setup, cdMaxInt(start, bodies) - bodies,
								 cdMinInt(end, contacts) - bodies);
			}
			if (end > contacts)
			{
				cd2CountJoints(world, list->setup, cdMaxInt(start, contacts) - contacts, end - contacts);
			}
			break;
		}
		case CD2_STAGE_LIST_CONTACTS:
		{
			/* Items: the contact chunks, then the joint chunks. */
			int contacts = list->setup->contactChunkCount;
			if (start < contacts)
			{
				cd2ListContacts(world, context, list->setup, start, cdMinInt(end, contacts));
			}
			if (end > contacts)
			{
				cd2ListJoints(world, context, list->setup, cdMaxInt(start, contacts) - contacts,
							  end - contacts);
			}
			break;
		}
		case CD2_STAGE_COLOR_AND_SETUP:
			cd2ColorAndSetup(world, context, list->setup, start, end);
			break;
		case CD2_STAGE_PREPARE_JOINTS:
			cd2PrepareJointRange(world, context, start, end);
			break;
		case CD2_STAGE_PREPARE_CONTACTS:
			if (cd2PrepareContacts(world, context, stage->first + start, stage->first + end))
			{
				cd2SetBouncing(list);
			}
			break;
		case CD2_STAGE_PACK_WIDE:
			if (cd2PackContactsWide(world, context, start, end))
			{
				cd2SetBouncing(list);
			}
			break;
		case CD2_STAGE_INTEGRATE_VELOCITIES:
			cd2IntegrateVelocities(context, start, end);
			break;
		case CD2_STAGE_WARM_START_JOINTS:
			cd2WarmStartJoints(world, context, stage->first + start, stage->first + end);
			break;
		case CD2_STAGE_WARM_START_WIDE:
			cd2WarmStartContactsWide(context, stage->first + start, stage->first + end);
			break;
		case CD2_STAGE_WARM_START_OVERFLOW:
			cd2WarmStartContacts(context);
			break;
		case CD2_STAGE_SOLVE_JOINTS:
			cd2SolveJoints(world, context, stage->first + start, stage->first + end, stage->useBias);
			break;
		case CD2_STAGE_SOLVE_WIDE:
			cd2SolveContactsWide(context, stage->first + start, stage->first + end, stage->useBias);
			break;
		case CD2_STAGE_SOLVE_OVERFLOW:
			cd2SolveContacts(context, stage->useBias);
			break;
		case CD2_STAGE_INTEGRATE_POSITIONS:
			cd2IntegratePositions(context, start, end);
			break;
		case CD2_STAGE_STORE_WIDE:
			cd2StoreContactsWide(world, context, start, end);
			break;
		case CD2_STAGE_RESTITUTION_WIDE:
			cd2ApplyRestitutionWide(context, stage->first + start, stage->first + end);
			break;
		case CD2_STAGE_RESTITUTION:
			cd2ApplyRestitution(context);
			break;
		case CD2_STAGE_STORE_IMPULSES:
			cd2StoreImpulses(world, context, stage->first + start, stage->first + end);
			break;
		case CD2_STAGE_STORE_JOINTS:
			cd2StoreJointReactions(world, context, start, end);
			break;
		case CD2_STAGE_FINALIZE_BODIES:
			cd2FinalizeBodies(world, context, start, end);
			break;
	}
}

/* The profile field a stage's time goes to (the setup's stages go to solverSetup as a whole). */
static float* cd2StageProfileField(cd2World* world, const cd2Stage* stage)
{
	cd2Profile* p = &world->profile;
	switch (stage->kind)
	{
		case CD2_STAGE_PREPARE_JOINTS:
		case CD2_STAGE_PREPARE_CONTACTS:
		case CD2_STAGE_PACK_WIDE:
			return &p->prepareConstraints;
		case CD2_STAGE_INTEGRATE_VELOCITIES:
			return &p->integrateVelocities;
		case CD2_STAGE_WARM_START_JOINTS:
		case CD2_STAGE_WARM_START_WIDE:
		case CD2_STAGE_WARM_START_OVERFLOW:
			return &p->warmStart;
		case CD2_STAGE_SOLVE_JOINTS:
		case CD2_STAGE_SOLVE_WIDE:
		case CD2_STAGE_SOLVE_OVERFLOW:
			return stage->useBias ? &p->solveImpulses : &p->relaxImpulses;
		case CD2_STAGE_INTEGRATE_POSITIONS:
			return &p->integratePositions;
		case CD2_STAGE_RESTITUTION_WIDE:
		case CD2_STAGE_RESTITUTION:
			return &p->applyRestitution;
		case CD2_STAGE_STORE_WIDE:
		case CD2_STAGE_STORE_IMPULSES:
		case CD2_STAGE_STORE_JOINTS:
			return &p->storeImpulses;
		case CD2_STAGE_FINALIZE_BODIES:
			return &p->finalize;
		default:
			return &p->solverSetup;
	}
}

/* Adds the time since the last mark to the stage's profile field (the stepping thread, profiling on). */
static void cd2ProfileStage(cd2World* world, const cd2Stage* stage)
{
	if (world != NULL)
	{
		double now = cd2ProfileNow();
		*cd2StageProfileField(world, stage) += (float)(1000.0 * (now - world->profileMark));
		world->profileMark = now;
	}
}

/* The stages of a run (runLength), each whole, in order. Every thread reads the same restitution
 * flag: it was set before the stages that set it were seen finished. */
static void cd2ExecuteRun(const cd2StageList* list, const cd2Stage* first, cd2World* profileWorld)
{
	for (int k = 0; k < first->runLength; ++k)
	{
		const cd2Stage* stage = first + k;
		if (!cd2StageSkipped(list, stage))
		{
			cd2ExecuteStage(list, stage, 0, stage->itemCount);
		}
		cd2ProfileStage(profileWorld, stage);
	}
}

/* Walks every stage in order, taking blocks while there are some, then waiting for the blocks that
 * other threads took (release on finishing a block, acquire on seeing them all finished: the next
 * stage reads what this one wrote). A run of one-block stages is one block. */
static void cd2RunStages(const cd2StageList* list, cd2Stage* stages, int stageCount, cd2World* profileWorld)
{
	for (int s = 0; s < stageCount; s += stages[s].runLength)
	{
		cd2Stage* stage = stages + s;
		if (stage->runLength > 1)
		{
#if CD2_STAGE_ATOMICS
			if (atomic_fetch_add_explicit(&stage->claimed, 1, memory_order_relaxed) == 0)
			{
				cd2ExecuteRun(list, stage, profileWorld);
				cdSyncCount_Add(&stage->done, 1);
			}
			else
			{
				cdSyncCount_AwaitAtLeast(&stage->done, 1);
				cd2ProfileStage(profileWorld, stage);
			}
#else
			cd2ExecuteRun(list, stage, profileWorld);
#endif
			continue;
		}
		/* Every worker reads the same flag here: it was set before the stages that set it were
		 * seen finished. */
		if (cd2StageSkipped(list, stage))
		{
			continue;
		}
#if CD2_STAGE_ATOMICS
		int finished = 0;
		for (;;)
		{
			int block = atomic_fetch_add_explicit(&stage->claimed, 1, memory_order_relaxed);
			if (block >= stage->blockCount)
			{
				break;
			}
			int start = block * stage->blockSize;
			int end =
				start + stage->blockSize < stage->itemCount ? start + stage->blockSize : stage->itemCount;
			cd2ExecuteStage(list, stage, start, end);
			++finished;
		}
		/* One addition per thread and stage (a thread that took nothing need not write). */
		if (finished > 0)
		{
			cdSyncCount_Add(&stage->done, finished);
		}
		if (finished != stage->blockCount) /* else all of it on this thread: nothing to wait for */
		{
			cdSyncCount_AwaitAtLeast(&stage->done, stage->blockCount);
		}
#else
		cd2ExecuteStage(list, stage, 0, stage->itemCount);
#endif
		cd2ProfileStage(profileWorld, stage);
	}
}

/* One further worker's share of the setup's stages, then of the others: the same walks. */
static void cd2PreStageTask(int start, int end, uint32_t workerIndex, void* taskContext)
{
	(void)start;
	(void)end;
	(void)workerIndex;
	const cd2StageList* list = (const cd2StageList*)taskContext;
	cd2RunStages(list, list->preStages, list->preStageCount, NULL);
}

static void cd2StageTask(int start, int end, uint32_t workerIndex, void* taskContext)
{
	(void)start;
	(void)end;
	(void)workerIndex;
	const cd2StageList* list = (const cd2StageList*)taskContext;
	cd2RunStages(list, list->stages, list->stageCount, NULL);
}

/* One task per further worker (the stepping thread walks the stages too); NULL when there are
 * none or the task system ran them already. */
static void* cd2StartHelpers(cd2World* world, cdTaskCallback* task, cd2StageList* list)
{
#if CD2_STAGE_ATOMICS
	if (world->threadPool != NULL)
	{
		return cdThreadPool_EnqueueEach(task, world->workerCount - 1, list, world->threadPool);
	}
	return world->enqueueTask(task, world->workerCount - 1, 1, list, world->userTaskContext);
#else
	(void)world;
	(void)task;
	(void)list;
	return NULL;
#endif
}

/* Hit events: touching contacts whose approach speed exceeded the threshold and that pushed. */
static void cd2ReportHits(cd2World* world, cd2StepContext* context)
{
	/* In contact index order: the contacts are read front to back. */
	for (int i = 0; i < context->constraintCount; ++i)
	{
		const cd2Contact* contact = world->contacts.data + context->indexOrder[i].contact;
		if ((contact->flags & CD2_CONTACT_HIT_EVENTS) == 0)
		{
			continue;
		}
		cd2ContactHitEvent event;
		memset(&event, 0, sizeof(event));
		event.approachSpeed = world->hitEventThreshold;
		bool hit = false;
		for (int k = 0; k < contact->pointCount; ++k)
		{
			cdReal approach = -contact->cache[k].relativeVelocity;
			if (approach > event.approachSpeed && contact->points[k].maxNormalImpulse > CD_R(0.0))
			{
				event.approachSpeed = approach;
				event.point = contact->cache[k].point;
				hit = true;
			}
		}
		if (hit)
		{
			event.normal = contact->normal;
			event.shapeIdA = cd2MakeShapeId(world, contact->shapeA);
			event.shapeIdB = cd2MakeShapeId(world, contact->shapeB);
			if (!cdArrayPush(world->hitEvents, event))
			{
				world->outOfMemory = true;
			}
		}
	}
}

void cd2RunTask(cd2World* world, cdTaskCallback* task, int itemCount, int minRange, int minParallel,
				void* taskContext)
{
	if (itemCount <= 0)
	{
		return;
	}
	/* Too little work to be worth a second thread (handing a task out and waiting for it costs
	 * microseconds): on this thread. */
	if (world->workerCount <= 1 || world->enqueueTask == NULL || itemCount <= minRange ||
		(itemCount < minParallel && !world->alwaysParallel))
	{
		task(0, itemCount, 0, taskContext);
		return;
	}
	/* NULL: the task system ran the task already (on this thread). */
	void* userTask = world->enqueueTask(task, itemCount, minRange, taskContext, world->userTaskContext);
	if (userTask != NULL)
	{
		world->finishTask(userTask, world->userTaskContext);
	}
}

/* One stage per non-empty joint colour; the overflow colour's joints in one block. */
static void cd2AddJointStages(cd2StageList* list, cd2StageKind kind, bool useBias)
{
	const int* start = list->step->jointColorStart;
	for (int c = 0; c <= CD_GRAPH_COLOR_COUNT; ++c)
	{
		int count = start[c + 1] - start[c];
		int minBlock = c == CD_GRAPH_COLOR_COUNT ? count : 16;
		cd2AddStage(list, kind, count, minBlock, start[c], useBias);
	}
}

void cd2Solve(cd2World* world, cdReal timeStep, int subStepCount)
{
	cd2StepContext context;
	memset(&context, 0, sizeof(context));
	context.dt = timeStep;
	context.inv_dt = CD_R(1.0) / timeStep;
	context.subStepCount = subStepCount;
	context.h = timeStep / (cdReal)subStepCount;
	context.inv_h = (cdReal)subStepCount * context.inv_dt;
	/* Stiffer than an eighth of the sub-step rate would ring. */
	cdReal contactHertz = cdMin(world->contactHertz, CD_R(0.125) * context.inv_h);
	context.contactSoftness = cd2MakeSoft(contactHertz, world->contactDampingRatio, context.h);
	context.staticSoftness = cd2MakeSoft(CD_R(2.0) * contactHertz, world->contactDampingRatio, context.h);
	/* Joints: the world's joint stiffness, capped at a quarter of the sub-step rate. */
	cdReal jointHertz = cdMin(world->jointHertz, CD_R(0.25) * context.inv_h);
	context.jointSoftness = cd2MakeSoft(jointHertz, world->jointDampingRatio, context.h);
	context.restitutionThreshold = world->restitutionThreshold;
	context.maxLinearVelocity = world->maximumLinearSpeed * cdGetLengthUnitsPerMeter();
	context.contactPushMaxVelocity = world->contactPushMaxVelocity * cdGetLengthUnitsPerMeter();
	context.enableWarmStarting = true;

	/* The awake bodies, dense. */
	int bodyCapacity = world->bodies.count;
	int contactCapacity = world->contacts.count;
	int jointCapacity = world->joints.count;
	/* One more: the zero body the wide contact solver points immovable bodies at. */
	context.bodies = (cd2SolverBody*)cdArena_AllocUncleared(&world->arena, (size_t)(bodyCapacity + 1) *
																			   sizeof(cd2SolverBody));
	context.bodyIndices = (int*)cdArena_AllocUncleared(&world->arena, (size_t)bodyCapacity * sizeof(int));
	context.params = (cd2SolverBodyParams*)cdArena_AllocUncleared(
		&world->arena, (size_t)bodyCapacity * sizeof(cd2SolverBodyParams));
	context.accelerations =
		(cd2Vec*)cdArena_AllocUncleared(&world->arena, (size_t)(bodyCapacity + 1) * sizeof(cd2Vec));
	/* The setup's lists and scratch (see cd2SolveSetup). Per world body its solver index, and the
	 * same for dynamic bodies only: small arrays, so that the contact loops do not visit the
	 * bodies. */
	cd2SolveSetup setup;
	memset(&setup, 0, sizeof(setup));
	setup.bodyChunkCount = (bodyCapacity + CD2_SETUP_CHUNK - 1) / CD2_SETUP_CHUNK;
	setup.contactChunkCount = (contactCapacity + CD2_SETUP_CHUNK - 1) / CD2_SETUP_CHUNK;
	setup.solverOf = (int*)cdArena_AllocUncleared(&world->arena, (size_t)bodyCapacity * sizeof(int));
	setup.colorBodyOf = (int*)cdArena_AllocUncleared(&world->arena, (size_t)bodyCapacity * sizeof(int));
	setup.bodyKind = (uint8_t*)cdArena_AllocUncleared(&world->arena, (size_t)bodyCapacity);
	setup.bodyChunkCounts =
		(int*)cdArena_AllocUncleared(&world->arena, (size_t)setup.bodyChunkCount * sizeof(int));
	setup.contactChunkCounts =
		(int*)cdArena_AllocUncleared(&world->arena, (size_t)setup.contactChunkCount * sizeof(int));
	setup.contactChunkHits =
		(int*)cdArena_AllocUncleared(&world->arena, (size_t)setup.contactChunkCount * sizeof(int));
	setup.contactChunkNew = (uint8_t*)cdArena_AllocUncleared(&world->arena, (size_t)setup.contactChunkCount);
	setup.jointChunkCount = (jointCapacity + CD2_SETUP_CHUNK - 1) / CD2_SETUP_CHUNK;
	setup.jointChunkCounts =
		(int*)cdArena_AllocUncleared(&world->arena, (size_t)setup.jointChunkCount * sizeof(int));
	setup.jointChunkThresholds =
		(int*)cdArena_AllocUncleared(&world->arena, (size_t)setup.jointChunkCount * sizeof(int));
	setup.jointBodies = (int*)cdArena_AllocUncleared(&world->arena, (size_t)jointCapacity * 2 * sizeof(int));
	/* From the entries the contact update left (a small array read in order), else from the
	 * contacts themselves. */
	setup.entries = world->stepSolveEntries;
	setup.pairs = (cd2ConstraintPair*)cdArena_AllocUncleared(&world->arena, (size_t)contactCapacity *
																				sizeof(cd2ConstraintPair));
	setup.bodyA = (int*)cdArena_AllocUncleared(&world->arena, (size_t)contactCapacity * sizeof(int));
	setup.bodyB = (int*)cdArena_AllocUncleared(&world->arena, (size_t)contactCapacity * sizeof(int));
	context.joints = (int*)cdArena_Alloc(&world->arena, (size_t)jointCapacity * sizeof(int));
	context.jointIndexOrder =
		(int*)cdArena_AllocUncleared(&world->arena, (size_t)jointCapacity * sizeof(int));
	if ((bodyCapacity > 0 &&
		 (context.bodies == NULL || context.bodyIndices == NULL || context.params == NULL ||
		  context.accelerations == NULL || setup.solverOf == NULL || setup.colorBodyOf == NULL ||
		  setup.bodyKind == NULL || setup.bodyChunkCounts == NULL)) ||
		(contactCapacity > 0 && (setup.contactChunkCounts == NULL || setup.contactChunkHits == NULL ||
								 setup.contactChunkNew == NULL || setup.pairs == NULL ||
								 setup.bodyA == NULL || setup.bodyB == NULL)) ||
		(jointCapacity > 0 &&
		 (context.joints == NULL || context.jointIndexOrder == NULL || setup.jointChunkCounts == NULL ||
		  setup.jointChunkThresholds == NULL || setup.jointBodies == NULL)))
	{
		world->outOfMemory = true;
		return;
	}
	/* The colourings' scratch; without it they leave the index order. */
	if (contactCapacity > 1)
	{
		if (cd2ColorCache_Reserve(&world->contactColorCache, contactCapacity))
		{
			setup.contactCache = &world->contactColorCache;
			setup.colors = setup.contactCache->colors;
			setup.order = setup.contactCache->order;
		}
		else
		{
			setup.colors = (int*)cdArena_AllocUncleared(&world->arena, (size_t)contactCapacity * sizeof(int));
			setup.order = (int*)cdArena_AllocUncleared(&world->arena, (size_t)contactCapacity * sizeof(int));
		}
		setup.sorted = (cd2ConstraintPair*)cdArena_AllocUncleared(
			&world->arena, (size_t)contactCapacity * sizeof(cd2ConstraintPair));
		setup.used =
			(uint32_t*)cdArena_AllocUncleared(&world->arena, (size_t)(bodyCapacity + 1) * sizeof(uint32_t));
	}
	if (jointCapacity > 1)
	{
		setup.jointBodyA = (int*)cdArena_AllocUncleared(&world->arena, (size_t)jointCapacity * sizeof(int));
		setup.jointBodyB = (int*)cdArena_AllocUncleared(&world->arena, (size_t)jointCapacity * sizeof(int));
		if (cd2ColorCache_Reserve(&world->jointColorCache, jointCapacity))
		{
			setup.jointCache = &world->jointColorCache;
			setup.jointColors = setup.jointCache->colors;
			setup.jointOrder = setup.jointCache->order;
		}
		else
		{
			setup.jointColors =
				(int*)cdArena_AllocUncleared(&world->arena, (size_t)jointCapacity * sizeof(int));
			setup.jointOrder =
				(int*)cdArena_AllocUncleared(&world->arena, (size_t)jointCapacity * sizeof(int));
		}
		setup.jointSorted = (int*)cdArena_AllocUncleared(&world->arena, (size_t)jointCapacity * sizeof(int));
		setup.jointUsed =
			(uint32_t*)cdArena_AllocUncleared(&world->arena, (size_t)(bodyCapacity + 1) * sizeof(uint32_t));
	}
	setup.jointsFirst = jointCapacity > contactCapacity;

	/* The stages, from the setup's to finalizing the bodies (see the top of the file). Whether the
	 * workers help is first judged on the world's counts (at least the solve's), then on the solve's
	 * once the setup has counted it: a small solve runs on this thread only, its stages taking a
	 * few microseconds each, about what handing them out and waiting at each stage's end would
	 * cost. */
	cd2StageList list;
	memset(&list, 0, sizeof(list));
	list.world = world;
	list.step = &context;
	list.setup = &setup;
	bool canParallel = world->workerCount > 1 && world->enqueueTask != NULL && CD2_STAGE_ATOMICS;
	int worldWork = contactCapacity + 2 * jointCapacity + bodyCapacity / 4;
	bool helpersStart = canParallel && (worldWork >= CD2_PARALLEL_MIN_SOLVE || world->alwaysParallel);
	list.workerCount = helpersStart ? world->workerCount : 1;
	cd2Stage preStages[5];
	list.preStages = preStages;
	list.stages = preStages;
	list.stageCapacity = 5;
	cd2AddStage(&list, CD2_STAGE_COUNT_BODIES, setup.bodyChunkCount, 1, 0, false);
	/* The contacts and the joints are counted while the bodies are listed (by the bodies' kinds, set
	 * by the count), and listed together; on one thread the joints are listed in one pass. */
	setup.jointsInOnePass = list.workerCount == 1;
	cd2AddStage(&list, CD2_STAGE_LIST_BODIES,
				setup.bodyChunkCount + setup.contactChunkCount +
					(setup.jointsInOnePass ? 0 : setup.jointChunkCount),
				1, 0, false);
	cd2AddStage(&list, CD2_STAGE_LIST_CONTACTS, setup.contactChunkCount + setup.jointChunkCount, 1, 0, false);
	{
		/* Blocks of solver bodies as the setup stage's were (the count is not known yet: blocks past
		 * it do nothing). */
		int even = (bodyCapacity + 4 * list.workerCount - 1) / (4 * list.workerCount);
		setup.setupBlockSize = cdMaxInt(list.workerCount > 1 ? cdMaxInt(even, 64) : bodyCapacity, 1);
		int setupBlocks = (bodyCapacity + setup.setupBlockSize - 1) / setup.setupBlockSize;
		cd2AddStage(&list, CD2_STAGE_COLOR_AND_SETUP, 2 + setupBlocks, 1, 0, false);
		/* (One item per block, whatever the worker count.) */
		cd2Stage* stage = list.stages + list.stageCount - 1;
		stage->blockSize = 1;
		stage->blockCount = stage->itemCount;
	}
	list.preStageCount = list.stageCount;
	list.stages = NULL;
	list.stageCount = 0;
	list.stageCapacity = 0;

	void* helpers = helpersStart ? cd2StartHelpers(world, cd2PreStageTask, &list) : NULL;
	cd2RunStages(&list, list.preStages, list.preStageCount, NULL);
	if (helpers != NULL)
	{
		world->finishTask(helpers, world->userTaskContext);
	}
	{
		/* The zero body, after the awake ones. */
		cd2SolverBody* zero = context.bodies + context.bodyCount;
		memset(zero, 0, sizeof(*zero));
		zero->deltaRotation = CD2_ROT_IDENTITY;
	}
	int hitCandidates = 0;
	for (int c = 0; c < setup.contactChunkCount; ++c)
	{
		hitCandidates += setup.contactChunkHits[c];
	}
	context.storeApproach = hitCandidates > 0;
	bool ok = true;
	if (!cd2PrepareContactsWide(world, &context))
	{
		/* Out of scratch memory: every constraint one by one. */
		context.wideCount = 0;
		context.overflowStart = 0;
	}
	/* One-by-one constraints for the overflow colour only (constraint i at i - overflowStart). */
	int overflowConstraints = context.constraintCount - context.overflowStart;
	context.constraints = (cd2ContactConstraint*)cdArena_AllocUncleared(
		&world->arena, (size_t)overflowConstraints * sizeof(cd2ContactConstraint));
	if (overflowConstraints > 0 && context.constraints == NULL)
	{
		ok = false;
	}
	if (ok && !cd2PrepareJoints(world, &context))
	{
		ok = false;
	}

	int solveWork = context.constraintCount + 2 * context.jointCount + context.bodyCount / 4;
	bool parallel = helpersStart && (solveWork >= CD2_PARALLEL_MIN_SOLVE || world->alwaysParallel);
	list.workerCount = parallel ? world->workerCount : 1;
	cd2StageCounter bouncing;
#if CD2_STAGE_ATOMICS
	atomic_init(&bouncing, 0);
#else
	bouncing = 0;
#endif
	list.bouncing = &bouncing;
	int jointColors = 0;
	for (int c = 0; c <= CD_GRAPH_COLOR_COUNT; ++c)
	{
		jointColors += context.jointColorStart[c + 1] > context.jointColorStart[c] ? 1 : 0;
	}
	/* Restitution adds one stage per contact colour after the sub-steps. */
	list.stageCapacity =
		10 + context.colorCount + subStepCount * (8 + 3 * (context.colorCount + jointColors));
	/* (One more, to start the stages on a cache line.) */
	char* stageMemory =
		ok ? (char*)cdArena_AllocUncleared(&world->arena, (size_t)(list.stageCapacity + 1) * sizeof(cd2Stage))
		   : NULL;
	context.finalFlags =
		ok ? (uint8_t*)cdArena_AllocUncleared(&world->arena, (size_t)bodyCapacity + 1) : NULL;
	context.finalSync = ok ? (cd2FinalSync*)cdArena_AllocUncleared(&world->arena, (size_t)(bodyCapacity + 1) *
																					  sizeof(cd2FinalSync))
						   : NULL;
	/* (The serial pass's list of the bodies it moves in the broadphase.) */
	int* finalMoves =
		ok ? (int*)cdArena_AllocUncleared(&world->arena, (size_t)(bodyCapacity + 1) * sizeof(int)) : NULL;
	if (stageMemory == NULL || context.finalFlags == NULL || context.finalSync == NULL || finalMoves == NULL)
	{
		world->outOfMemory = true;
		return;
	}
	list.stages = (cd2Stage*)(stageMemory + (64u - (uintptr_t)stageMemory % 64u) % 64u);
	int overflowCount = context.constraintCount > context.overflowStart ? 1 : 0;
	/* The coloured constraints are prepared by the pack stage, block by block (in cache when packed);
	 * this stage prepares the overflow colour's. */
	cd2AddStage(&list, CD2_STAGE_PREPARE_JOINTS, context.jointCount, 32, 0, false);
	cd2AddStage(&list, CD2_STAGE_PREPARE_CONTACTS, context.constraintCount - context.overflowStart, 32,
				context.overflowStart, false);
	cd2AddStage(&list, CD2_STAGE_PACK_WIDE, context.wideCount, 8, 0, false);
	for (int step = 0; step < subStepCount; ++step)
	{
		cd2AddStage(&list, CD2_STAGE_INTEGRATE_VELOCITIES, context.bodyCount, 64, 0, false);
		cd2AddJointStages(&list, CD2_STAGE_WARM_START_JOINTS, false);
		cd2AddWideStages(&list, CD2_STAGE_WARM_START_WIDE, false);
		cd2AddStage(&list, CD2_STAGE_WARM_START_OVERFLOW, overflowCount, 1, 0, false);
		cd2AddJointStages(&list, CD2_STAGE_SOLVE_JOINTS, true);
		cd2AddWideStages(&list, CD2_STAGE_SOLVE_WIDE, true);
		cd2AddStage(&list, CD2_STAGE_SOLVE_OVERFLOW, overflowCount, 1, 0, true);
		cd2AddStage(&list, CD2_STAGE_INTEGRATE_POSITIONS, context.bodyCount, 64, 0, false);
		cd2AddJointStages(&list, CD2_STAGE_SOLVE_JOINTS, false);
		cd2AddWideStages(&list, CD2_STAGE_SOLVE_WIDE, false);
		cd2AddStage(&list, CD2_STAGE_SOLVE_OVERFLOW, overflowCount, 1, 0, false);
	}
	/* Restitution colour by colour, then the overflow colour's (the order of the one-by-one pass),
	 * passed over when no constraint has restitution; then the impulses back into the contacts. */
	cd2AddWideStages(&list, CD2_STAGE_RESTITUTION_WIDE, false);
	cd2AddStage(&list, CD2_STAGE_RESTITUTION, overflowCount, 1, 0, false);
	cd2AddStage(&list, CD2_STAGE_STORE_WIDE, context.wideCount, 8, 0, false);
	cd2AddStage(&list, CD2_STAGE_STORE_IMPULSES, context.constraintCount - context.overflowStart, 32,
				context.overflowStart, false);
	cd2AddStage(&list, CD2_STAGE_STORE_JOINTS, context.jointCount, 64, 0, false);
	cd2AddStage(&list, CD2_STAGE_FINALIZE_BODIES, context.bodyCount, 64, 0, false);

	cd2JoinSmallStages(&list);

	/* The move events are written by index; the step cleared the array. */
	context.moveEvents = NULL;
	if (world->moveEvents.count == 0 && cdArrayReserveFor(world->moveEvents, context.bodyCount))
	{
		context.moveEvents = world->moveEvents.data;
	}
	else if (context.bodyCount > 0)
	{
		world->outOfMemory = true;
	}

	CD2_PROFILE_MARK(world, solverSetup);
	helpers = parallel ? cd2StartHelpers(world, cd2StageTask, &list) : NULL;
	cd2RunStages(&list, list.stages, list.stageCount, world->profiling ? world : NULL);
	if (helpers != NULL)
	{
		world->finishTask(helpers, world->userTaskContext);
	}

	CD2_PROFILE_MARK(world, finalize);
	if (context.thresholdJointCount > 0)
	{
		cd2ReportJointEvents(world, &context);
		CD2_PROFILE_MARK(world, jointEvents);
	}
	/* The rest of finalize, on this thread: what reads other bodies' final poses or writes shared
	 * structures, for the bodies the finalize stage flagged, in body order. */
	bool sleepAllowed = world->enableSleep;
	bool rested = false;
	for (int k = 0; k < context.bodyCount; ++k)
	{
		unsigned flags = context.finalFlags[k];
		rested = rested || (flags & CD2_FINAL_RESTED) != 0u;
		if ((flags & CD2_FINAL_KINEMATIC) == 0u)
		{
			continue;
		}
		/* A moving kinematic body keeps what touches it awake. (Its sleep time is read here, not
		 * in finalize: a wake above may have reset it.) */
		const cd2Body* body = world->bodies.data + context.bodyIndices[k];
		if (body->sleepTime > CD_R(0.0))
		{
			continue;
		}
		for (int key = body->headContactKey; key != CD2_NULL_INDEX;)
		{
			const cd2Contact* contact = world->contacts.data + cd2EdgeContact(key);
			int other = cd2EdgeSide(key) == 0 ? contact->bodyB : contact->bodyA;
			if ((contact->flags & CD2_CONTACT_TOUCHING) != 0 && (contact->flags & CD2_CONTACT_SENSOR) == 0)
			{
				world->bodies.data[other].sleepTime = CD_R(0.0);
			}
			key = contact->nextKey[cd2EdgeSide(key)];
		}
	}
	/* Bullets: continuous collision against static shapes and the others' final poses (the
	 * non-bullets' sweeps are done), then their boxes and move events. */
	for (int k = 0; k < context.bodyCount; ++k)
	{
		if ((context.finalFlags[k] & CD2_FINAL_BULLET) == 0u)
		{
			continue;
		}
		int index = context.bodyIndices[k];
		cd2SolveContinuous(world, index);
		const cd2Body* body = world->bodies.data + index;
		if (context.moveEvents != NULL)
		{
			cd2BodyMoveEvent* event = context.moveEvents + k;
			event->transform = body->transform;
			event->bodyId = cd2MakeBodyId(world, index);
			event->userData = body->userData;
			event->fellAsleep = false;
		}
	}
	/* The broadphase, after every sweep (they query it as it was before the step's moves), in body
	 * order. A body with one shape to move (most) takes the fat box the finalize stage computed; the
	 * records of the moves a few bodies ahead are loaded meanwhile, level by level (the shape, the
	 * proxy's table entries, its parent in the tree, the grandparent): scattered records that the
	 * moves would otherwise wait for one after the other. */
	int finalMoveCount = 0;
	for (int k = 0; k < context.bodyCount; ++k)
	{
		if ((context.finalFlags[k] & (CD2_FINAL_SYNC_PROXY | CD2_FINAL_BULLET)) != 0u)
		{
			finalMoves[finalMoveCount++] = k;
		}
	}
	enum
	{
		CD2_FINAL_AHEAD = 8,
		CD2_FINAL_STAGES = 4
	};
	for (int j = 0; j < finalMoveCount; ++j)
	{
		for (int stage = 0; stage < CD2_FINAL_STAGES; ++stage)
		{
			int at = j + (CD2_FINAL_STAGES - stage) * CD2_FINAL_AHEAD;
			if (at < finalMoveCount &&
				(context.finalFlags[finalMoves[at]] &
				 (CD2_FINAL_SYNC_PROXY | CD2_FINAL_BULLET | CD2_FINAL_SYNC_SEVERAL)) == CD2_FINAL_SYNC_PROXY)
			{
				const cd2FinalSync* next = context.finalSync + finalMoves[at];
				if (stage == 0)
				{
					CD2_PREFETCH(&world->shapes.data[next->shape].fatAabb);
				}
				cd2BroadPhase_PrefetchMove(world->broadPhase, next->proxy, stage);
			}
		}
		int k = finalMoves[j];
		unsigned flags = context.finalFlags[k];
		if ((flags & (CD2_FINAL_BULLET | CD2_FINAL_SYNC_SEVERAL)) == 0u &&
			world->shapes.data[context.finalSync[k].shape].proxyId != CD_NULL_PROXY)
		{
			cd2SyncShapeProxyTo(world, context.finalSync[k].shape, context.finalSync[k].fat);
			continue;
		}
		const cd2Body* body = world->bodies.data + context.bodyIndices[k];
		for (int s = body->headShape; s != CD2_NULL_INDEX; s = world->shapes.data[s].nextShape)
		{
			if ((flags & CD2_FINAL_BULLET) != 0u)
			{
				cd2UpdateShapeBounds(world, s, false);
			}
			else if (cd2ShapeProxyNeedsSync(world->shapes.data + s))
			{
				cd2SyncShapeProxy(world, s, false);
			}
		}
	}
	CD2_PROFILE_MARK(world, refit);
	if (hitCandidates > 0)
	{
		cd2ReportHits(world, &context);
	}
	/* Only a body that has rested for CD2_TIME_TO_SLEEP can fall asleep (an island sleeps when its
	 * least rested body has); without one there is nothing to check. */
	CD2_PROFILE_MARK(world, hitEvents);
	if (sleepAllowed && rested &&
		cd2UpdateSleep(world, context.bodyIndices, context.finalFlags, context.bodyCount) > 0)
	{
		for (int k = 0; k < context.bodyCount && context.moveEvents != NULL; ++k)
		{
			context.moveEvents[k].fellAsleep = !world->bodies.data[context.bodyIndices[k]].awake;
		}
	}
	if (context.moveEvents != NULL)
	{
		world->moveEvents.count = context.bodyCount;
	}
	CD2_PROFILE_MARK(world, sleepIslands);
}
