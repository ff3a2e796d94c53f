/* The 2D world's determinism: a falling pile (a pyramid of boxes dropped from a height, with
 * circles and capsules raining on it) is stepped for 3 s and every body's state (position,
 * rotation, velocities) is hashed bit for bit. The hash must be the same on every run, for every
 * worker count, and equal to the one committed below for the build (float or double on x86-64 and
 * aarch64, where the SSE2, AVX2 (-DCOLLIDE_AVX2=ON, eight lanes) and NEON solvers and the scalar
 * fallback of four or eight lanes, -DCOLLIDE_NO_SIMD, all give the same bits: the lane width does
 * not change a lane's arithmetic; scripts/test-aarch64.sh runs it under qemu; other machines check
 * the first two only). A change of the solver that changes results on purpose updates the
 * committed hashes, with the reason in its commit. */
#include "test.h"

#include <collide/collide.h>

#include "../src/dynamics/world2_internal.h" /* cd2SetAlwaysParallel */

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#if defined(__unix__) || defined(__APPLE__)
#include <pthread.h>
#define HAVE_PTHREADS 1
#else
#define HAVE_PTHREADS 0
#endif

/* A user task system for the tests: every task is cut into pieces of minRange items, run either
 * inline in reverse order at finishTask (workerIndex cycling), or on two threads of its own
 * started by enqueueTask and joined by finishTask (the pieces dealt out alternately). */
typedef struct TestTaskSystem
{
	bool threaded;
	bool atEnqueue; /* run every piece inside enqueueTask and return NULL (the task already ran) */
	int workerCount;
	int enqueued;  /* tasks handed to the system */
	int badRanges; /* pieces shorter than minRange (not last) or tasks with no items */
	cdTaskCallback* task;
	void* taskContext;
	int itemCount, minRange;
} TestTaskSystem;

typedef struct TestThreadJob
{
	TestTaskSystem* system;
	int first; /* piece index to start from; every second piece after it */
} TestThreadJob;

static void RunPieces(TestTaskSystem* system, int first, int stride)
{
	int piece = system->minRange > 0 ? system->minRange : 1;
	int pieceCount = (system->itemCount + piece - 1) / piece;
	for (int k = first; k < pieceCount; k += stride)
	{
		int start = k * piece;
		int end = start + piece < system->itemCount ? start + piece : system->itemCount;
		system->task(start, end, (uint32_t)(k % system->workerCount), system->taskContext);
	}
}

#if HAVE_PTHREADS
static TestThreadJob s_jobs[2];
static pthread_t s_threads[2];

static void* TestThreadMain(void* arg)
{
	TestThreadJob* job = (TestThreadJob*)arg;
	RunPieces(job->system, job->first, 2);
	return NULL;
}
#endif

static void* TestEnqueue(cdTaskCallback* task, int itemCount, int minRange, void* taskContext,
						 void* userContext)
{
	TestTaskSystem* system = (TestTaskSystem*)userContext;
	system->enqueued++;
	if (itemCount <= 0 || minRange < 1)
	{
		system->badRanges++;
	}
	system->task = task;
	system->taskContext = taskContext;
	system->itemCount = itemCount;
	system->minRange = minRange;
	if (system->atEnqueue)
	{
		RunPieces(system, 0, 1);
		return NULL;
	}
#if HAVE_PTHREADS
	if (system->threaded)
	{
		for (int i = 0; i < 2; ++i)
		{
			s_jobs[i].system = system;
			s_jobs[i].first = i;
			if (pthread_create(s_threads + i, NULL, TestThreadMain, s_jobs + i) != 0)
			{
				/* Could not start a thread: run its share here. */
				RunPieces(system, i, 2);
				s_threads[i] = pthread_self();
			}
		}
	}
#endif
	return system;
}

static void TestFinish(void* userTask, void* userContext)
{
	TestTaskSystem* system = (TestTaskSystem*)userContext;
	TEST_CHECK(userTask == system);
#if HAVE_PTHREADS
	if (system->threaded)
	{
		for (int i = 0; i < 2; ++i)
		{
			if (!pthread_equal(s_threads[i], pthread_self()))
			{
				pthread_join(s_threads[i], NULL);
			}
		}
		return;
	}
#endif
	int piece = system->minRange > 0 ? system->minRange : 1;
	int pieceCount = (system->itemCount + piece - 1) / piece;
	for (int k = pieceCount - 1; k >= 0; --k)
	{
		RunPieces(system, k, pieceCount + 1);
	}
}

#define DT (CD_R(1.0) / CD_R(60.0))
#define STEPS 180

static void HashBytes(uint64_t* h, const void* data, size_t size)
{
	const unsigned char* p = (const unsigned char*)data;
	for (size_t i = 0; i < size; ++i)
	{
		*h = (*h ^ p[i]) * UINT64_C(1099511628211);
	}
}

static void HashReal(uint64_t* h, cdReal value)
{
	/* -0 and +0 are the same state. */
	if (value == CD_R(0.0))
	{
		value = CD_R(0.0);
	}
	HashBytes(h, &value, sizeof(value));
}

/* A world of `workerCount` workers: the built-in pool, or the test's task system when given. */
/* The worlds of these tests are small: a step would run every stage on the stepping thread (too
 * little work to hand out). The tests hand it out anyway, to run the task paths, except where
 * they check that decision. */
static bool s_alwaysParallel = true;

static cd2WorldId CreateWorld(int workerCount, TestTaskSystem* system)
{
	cd2WorldDef wd = cd2DefaultWorldDef();
	wd.workerCount = workerCount;
	if (system != NULL)
	{
		system->workerCount = workerCount;
		wd.enqueueTask = TestEnqueue;
		wd.finishTask = TestFinish;
		wd.userTaskContext = system;
	}
	cd2WorldId world = cd2CreateWorld(&wd);
	cd2SetAlwaysParallel(world, s_alwaysParallel);
	return world;
}

/* The bits of the bodies' poses and velocities. */
static uint64_t HashBodies(const cd2BodyId* bodies, int count)
{
	uint64_t h = UINT64_C(14695981039346656037);
	for (int i = 0; i < count; ++i)
	{
		cd2Vec p = cd2Body_GetPosition(bodies[i]);
		cd2Rot q = cd2Body_GetRotation(bodies[i]);
		cd2Vec v = cd2Body_GetLinearVelocity(bodies[i]);
		HashReal(&h, p.x);
		HashReal(&h, p.y);
		HashReal(&h, q.c);
		HashReal(&h, q.s);
		HashReal(&h, v.x);
		HashReal(&h, v.y);
		HashReal(&h, cd2Body_GetAngularVelocity(bodies[i]));
	}
	return h;
}

static uint64_t RunPile(int workerCount, TestTaskSystem* system, int* bodyCountOut)
{
	cd2WorldId world = CreateWorld(workerCount, system);
	cd2BodyDef bd = cd2DefaultBodyDef();
	cd2BodyId ground = cd2CreateBody(world, &bd);
	cd2ShapeDef sd = cd2DefaultShapeDef();
	cd2Segment floor = {{CD_R(-40.0), CD_R(0.0)}, {CD_R(40.0), CD_R(0.0)}};
	cd2CreateSegmentShape(ground, &sd, &floor);

	enum
	{
		MAX_BODIES = 256
	};
	cd2BodyId bodies[MAX_BODIES];
	int count = 0;
	cd2Polygon box;
	cd2MakeBoxPolygon((cd2Box){{CD_R(0.0), CD_R(0.0)}, {CD_R(0.5), CD_R(0.5)}, {CD_R(1.0), CD_R(0.0)}}, &box);
	int base = 12;
	for (int row = 0; row < base; ++row)
	{
		for (int i = 0; i < base - row; ++i)
		{
			bd = cd2DefaultBodyDef();
			bd.type = CD_DYNAMIC_BODY;
			/* Gaps of a tenth between the boxes: they fall and settle. */
			bd.position = cd2MakeVec(CD_R(1.1) * ((cdReal)i - CD_R(0.5) * (cdReal)(base - row - 1)),
									 CD_R(2.0) + CD_R(1.1) * (cdReal)row);
			bodies[count] = cd2CreateBody(world, &bd);
			cd2CreatePolygonShape(bodies[count], &sd, &box);
			++count;
		}
	}
	for (int i = 0; i < 24; ++i)
	{
		bd = cd2DefaultBodyDef();
		bd.type = CD_DYNAMIC_BODY;
		bd.position =
			cd2MakeVec(CD_R(-6.0) + CD_R(0.53) * (cdReal)i, CD_R(18.0) + CD_R(0.7) * (cdReal)(i % 5));
		bd.angularVelocity = CD_R(0.3) * (cdReal)(i % 7) - CD_R(1.0);
		bodies[count] = cd2CreateBody(world, &bd);
		if (i % 2 == 0)
		{
			cd2Circle circle = {{CD_R(0.0), CD_R(0.0)}, CD_R(0.25)};
			cd2CreateCircleShape(bodies[count], &sd, &circle);
		}
		else
		{
			cd2Capsule capsule = {{CD_R(-0.3), CD_R(0.0)}, {CD_R(0.3), CD_R(0.0)}, CD_R(0.15)};
			cd2CreateCapsuleShape(bodies[count], &sd, &capsule);
		}
		++count;
	}
	for (int step = 0; step < STEPS; ++step)
	{
		cd2World_Step(world, DT, 4);
	}
	uint64_t h = HashBodies(bodies, count);
	cd2DestroyWorld(world);
	*bodyCountOut = count;
	return h;
}

static void TestSameBitsEveryRunAndWorkerCount(void)
{
	int count = 0;
	uint64_t reference = RunPile(1, NULL, &count);
	TEST_CHECK(count == 78 + 24);
	for (int run = 0; run < 2; ++run)
	{
		int workers[3] = {1, 2, 4};
		for (int k = 0; k < 3; ++k)
		{
			int n = 0;
			uint64_t h = RunPile(workers[k], NULL, &n);
			TEST_CHECKF(h == reference, "run %d, %d workers: hash %016llx, single thread %016llx", run,
						workers[k], (unsigned long long)h, (unsigned long long)reference);
			/* The user's task system, inline (pieces in reverse order) and on its own threads. */
			for (int threaded = 0; threaded < 2; ++threaded)
			{
				TestTaskSystem system;
				memset(&system, 0, sizeof(system));
				system.threaded = threaded != 0;
				h = RunPile(workers[k], &system, &n);
				TEST_CHECKF(h == reference,
							"run %d, %d workers, user tasks (%s): hash %016llx, single thread %016llx", run,
							workers[k], threaded ? "threads" : "inline", (unsigned long long)h,
							(unsigned long long)reference);
				/* One worker: the step runs alone; more: every step hands its solver stages to the
				 * system (one task for the further workers, and any others). */
				TEST_CHECKF(workers[k] == 1 ? system.enqueued == 0 : system.enqueued >= STEPS,
							"%d workers: %d tasks enqueued", workers[k], system.enqueued);
				TEST_CHECK(system.badRanges == 0);
			}
		}
	}
#if defined(__x86_64__) || defined(_M_X64) || defined(__aarch64__)
#if CD_DOUBLE
	const uint64_t committed = UINT64_C(0xec588d5966c10a7c);
#else
	const uint64_t committed = UINT64_C(0x4a4b4009e6dc9299);
#endif
	TEST_CHECKF(reference == committed, "hash %016llx, committed %016llx", (unsigned long long)reference,
				(unsigned long long)committed);
#endif
}

/* A hanging grid of bodies joined by revolute joints (Box2D's joint_grid, smaller) with a
 * kinematic bar swinging a second grid, and boxes dropped through: the joints are solved colour by
 * colour on every worker, and a colour's joints share no awake body (the kinematic bar included),
 * so the bits are the same for any worker count. The ThreadSanitizer job runs this test. */
static uint64_t RunJointGrid(int workerCount, TestTaskSystem* system)
{
	cd2WorldId world = CreateWorld(workerCount, system);
	cd2BodyDef bd = cd2DefaultBodyDef();
	cd2BodyId ground = cd2CreateBody(world, &bd);
	bd.type = CD_KINEMATIC_BODY;
	bd.position = cd2MakeVec(CD_R(20.0), CD_R(0.0));
	bd.angularVelocity = CD_R(0.5);
	cd2BodyId bar = cd2CreateBody(world, &bd);
	cd2ShapeDef sd = cd2DefaultShapeDef();
	sd.filter.groupIndex = -1; /* the grids' links do not collide with each other */
	cd2Circle link = {{CD_R(0.0), CD_R(0.0)}, CD_R(0.4)};
	enum
	{
		N = 10,
		GRIDS = 2,
		DROPS = 12
	};
	cd2BodyId bodies[GRIDS * N * N + DROPS];
	int count = 0;
	for (int g = 0; g < GRIDS; ++g)
	{
		cd2Vec origin = cd2MakeVec(CD_R(20.0) * (cdReal)g, CD_R(0.0));
		cd2BodyId anchor = g == 0 ? ground : bar;
		for (int k = 0; k < N; ++k)
		{
			for (int i = 0; i < N; ++i)
			{
				bd = cd2DefaultBodyDef();
				bd.type = CD_DYNAMIC_BODY;
				bd.position = cd2MakeVec(origin.x + (cdReal)k, origin.y - (cdReal)i);
				cd2BodyId body = cd2CreateBody(world, &bd);
				cd2CreateCircleShape(body, &sd, &link);
				cd2RevoluteJointDef jd = cd2DefaultRevoluteJointDef();
				if (i > 0)
				{
					jd.bodyIdA = bodies[count - 1];
					jd.bodyIdB = body;
					jd.localAnchorA = cd2MakeVec(CD_R(0.0), CD_R(-0.5));
					jd.localAnchorB = cd2MakeVec(CD_R(0.0), CD_R(0.5));
					cd2CreateRevoluteJoint(world, &jd);
				}
				else if (k == 0 || k == N - 1)
				{
					jd.bodyIdA = anchor;
					jd.bodyIdB = body;
					jd.localAnchorA = cd2MakeVec((cdReal)k, CD_R(0.5));
					jd.localAnchorB = cd2MakeVec(CD_R(0.0), CD_R(0.5));
					cd2CreateRevoluteJoint(world, &jd);
				}
				if (k > 0)
				{
					jd = cd2DefaultRevoluteJointDef();
					jd.bodyIdA = bodies[count - N];
					jd.bodyIdB = body;
					jd.localAnchorA = cd2MakeVec(CD_R(0.5), CD_R(0.0));
					jd.localAnchorB = cd2MakeVec(CD_R(-0.5), CD_R(0.0));
					cd2CreateRevoluteJoint(world, &jd);
				}
				bodies[count++] = body;
			}
		}
	}
	cd2ShapeDef dropDef = cd2DefaultShapeDef();
	cd2Polygon box;
	cd2MakeBoxPolygon((cd2Box){{CD_R(0.0), CD_R(0.0)}, {CD_R(0.3), CD_R(0.3)}, {CD_R(1.0), CD_R(0.0)}}, &box);
	for (int i = 0; i < DROPS; ++i)
	{
		bd = cd2DefaultBodyDef();
		bd.type = CD_DYNAMIC_BODY;
		bd.position = cd2MakeVec(CD_R(0.8) * (cdReal)i, CD_R(3.0) + CD_R(0.5) * (cdReal)(i % 3));
		bodies[count] = cd2CreateBody(world, &bd);
		cd2CreatePolygonShape(bodies[count], &dropDef, &box);
		++count;
	}
	for (int step = 0; step < STEPS; ++step)
	{
		cd2World_Step(world, DT, 4);
	}
	uint64_t h = HashBodies(bodies, count);
	cd2DestroyWorld(world);
	return h;
}

static void TestJointGridSameBitsEveryWorkerCount(void)
{
	uint64_t reference = RunJointGrid(1, NULL);
	int workers[2] = {2, 4};
	for (int k = 0; k < 2; ++k)
	{
		uint64_t h = RunJointGrid(workers[k], NULL);
		TEST_CHECKF(h == reference, "%d workers: hash %016llx, single thread %016llx", workers[k],
					(unsigned long long)h, (unsigned long long)reference);
		TestTaskSystem system;
		memset(&system, 0, sizeof(system));
		system.threaded = true;
		h = RunJointGrid(workers[k], &system);
		TEST_CHECKF(h == reference, "%d workers, user threads: hash %016llx, single thread %016llx",
					workers[k], (unsigned long long)h, (unsigned long long)reference);
		TEST_CHECK(system.badRanges == 0);
	}
}

/* A task system that runs each task to the end inside enqueueTask, before the stepping thread goes
 * on: the step's further workers' task then does the whole solve on its own, and the step must
 * neither wait for it forever nor change a bit. */
static void TestTasksRunInsideEnqueue(void)
{
	int count = 0;
	uint64_t reference = RunPile(1, NULL, &count);
	int workers[2] = {2, 4};
	for (int k = 0; k < 2; ++k)
	{
		TestTaskSystem system;
		memset(&system, 0, sizeof(system));
		system.atEnqueue = true;
		int n = 0;
		uint64_t h = RunPile(workers[k], &system, &n);
		TEST_CHECKF(h == reference, "%d workers, tasks run at enqueue: hash %016llx, single thread %016llx",
					workers[k], (unsigned long long)h, (unsigned long long)reference);
		TEST_CHECKF(system.enqueued >= STEPS, "%d workers: %d tasks enqueued", workers[k], system.enqueued);
		TEST_CHECK(system.badRanges == 0);
	}
}

/* By default a small world's step hands nothing to the workers (a second worker would only add
 * the cost of handing work out), and a large one hands its solve out every step; the bits are the
 * same either way. */
static void TestSmallWorldStaysOnOneThread(void)
{
	int count = 0;
	uint64_t reference = RunPile(1, NULL, &count);
	s_alwaysParallel = false;
	TestTaskSystem system;
	memset(&system, 0, sizeof(system));
	int n = 0;
	uint64_t h = RunPile(2, &system, &n);
	TEST_CHECKF(h == reference, "hash %016llx, single thread %016llx", (unsigned long long)h,
				(unsigned long long)reference);
	TEST_CHECKF(system.enqueued == 0, "%d tasks enqueued for a pile of %d bodies", system.enqueued, n);
	h = RunPile(2, NULL, &n);
	TEST_CHECKF(h == reference, "built-in pool: hash %016llx, single thread %016llx", (unsigned long long)h,
				(unsigned long long)reference);

	/* 1,600 boxes resting in a block on the ground: about 3,000 contacts, solved on the workers. */
	memset(&system, 0, sizeof(system));
	cd2WorldId world = CreateWorld(2, &system);
	cd2BodyDef bd = cd2DefaultBodyDef();
	cd2BodyId ground = cd2CreateBody(world, &bd);
	cd2ShapeDef sd = cd2DefaultShapeDef();
	cd2Segment floor = {{CD_R(-40.0), CD_R(0.0)}, {CD_R(40.0), CD_R(0.0)}};
	cd2CreateSegmentShape(ground, &sd, &floor);
	cd2Polygon box;
	cd2MakeBoxPolygon((cd2Box){{CD_R(0.0), CD_R(0.0)}, {CD_R(0.5), CD_R(0.5)}, {CD_R(1.0), CD_R(0.0)}}, &box);
	for (int row = 0; row < 40; ++row)
	{
		for (int i = 0; i < 40; ++i)
		{
			bd = cd2DefaultBodyDef();
			bd.type = CD_DYNAMIC_BODY;
			bd.position = cd2MakeVec((cdReal)i - CD_R(20.0), CD_R(0.5) + (cdReal)row);
			cd2CreatePolygonShape(cd2CreateBody(world, &bd), &sd, &box);
		}
	}
	for (int step = 0; step < 10; ++step)
	{
		cd2World_Step(world, DT, 4);
	}
	cd2Counters counters = cd2World_GetCounters(world);
	TEST_CHECKF(counters.contactCount > 2500, "%d contacts", counters.contactCount);
	TEST_CHECKF(system.enqueued >= 10, "%d tasks enqueued in 10 steps of %d contacts", system.enqueued,
				counters.contactCount);
	TEST_CHECK(system.badRanges == 0);
	cd2DestroyWorld(world);
	s_alwaysParallel = true;
}

/* Four discs in two touching pairs (A-B, C-D) and six discs in three jointed pairs, without
 * gravity; bodies[0..10). */
static void BuildPairs(cd2WorldId world, cd2BodyId* bodies, cd2JointId* joints)
{
	cd2ShapeDef sd = cd2DefaultShapeDef();
	for (int i = 0; i < 10; ++i)
	{
		cd2BodyDef bd = cd2DefaultBodyDef();
		bd.type = CD_DYNAMIC_BODY;
		/* A and B overlap by a tenth, as C and D; the jointed discs are far apart. */
		bd.position = i < 4 ? cd2MakeVec(CD_R(3.0) * (cdReal)(i / 2) + CD_R(0.9) * (cdReal)(i % 2), CD_R(0.0))
							: cd2MakeVec(CD_R(1.5) * (cdReal)i, CD_R(20.0));
		bd.angularVelocity = CD_R(0.1) * (cdReal)i;
		bodies[i] = cd2CreateBody(world, &bd);
		cd2Circle circle = {{CD_R(0.0), CD_R(0.0)}, i < 4 ? CD_R(0.5) : CD_R(0.2)};
		cd2CreateCircleShape(bodies[i], &sd, &circle);
	}
	for (int k = 0; k < 3; ++k)
	{
		cd2RevoluteJointDef jd = cd2DefaultRevoluteJointDef();
		jd.bodyIdA = bodies[4 + 2 * k];
		jd.bodyIdB = bodies[5 + 2 * k];
		jd.localAnchorA = cd2MakeVec(CD_R(0.75), CD_R(0.0));
		jd.localAnchorB = cd2MakeVec(CD_R(-0.75), CD_R(0.0));
		joints[k] = cd2CreateRevoluteJoint(world, &jd);
	}
}

/* The solver keeps a step's colourings and takes them again while the next step's constraints are
 * the same. A step with as many constraints as the last one but not the same (a touch ends and
 * another begins; two joints are destroyed and two made, on shared bodies) is coloured anew: it
 * gives the same bits as a world restored from the state before that step, which has kept no
 * colouring. (Taking the old colours would put constraints on one body in one colour.) */
static void TestColoringKeptOnlyWhileTheSame(void)
{
	int workers[3] = {1, 2, 4};
	for (int w = 0; w < 3; ++w)
	{
		cd2WorldId world = CreateWorld(workers[w], NULL);
		cd2World_SetGravity(world, CD2_VEC_ZERO);
		cd2BodyId bodies[10];
		cd2JointId joints[3];
		BuildPairs(world, bodies, joints);
		for (int step = 0; step < 3; ++step)
		{
			cd2World_Step(world, DT, 4);
		}
		TEST_CHECK(cd2World_GetCounters(world).touchingContactCount == 2);
		/* C moves next to B, D away: the touches become A-B and B-C. The joints become a chain
		 * of the first four jointed discs: 4-5, 5-6, 6-7. */
		cd2Body_SetTransform(bodies[2], cd2MakeVec(CD_R(1.8), CD_R(0.0)), cd2MakeRot(CD_R(0.0)));
		cd2Body_SetTransform(bodies[3], cd2MakeVec(CD_R(30.0), CD_R(0.0)), cd2MakeRot(CD_R(0.0)));
		/* A and C close in on B: both touches push. */
		cd2Body_SetLinearVelocity(bodies[0], cd2MakeVec(CD_R(2.0), CD_R(0.0)));
		cd2Body_SetLinearVelocity(bodies[1], CD2_VEC_ZERO);
		cd2Body_SetLinearVelocity(bodies[2], cd2MakeVec(CD_R(-2.0), CD_R(0.0)));
		cd2DestroyJoint(joints[1]);
		cd2DestroyJoint(joints[2]);
		for (int k = 2; k >= 1; --k)
		{
			cd2RevoluteJointDef jd = cd2DefaultRevoluteJointDef();
			jd.bodyIdA = bodies[4 + k];
			jd.bodyIdB = bodies[5 + k];
			jd.localAnchorA = cd2MakeVec(CD_R(0.75), CD_R(0.0));
			jd.localAnchorB = cd2MakeVec(CD_R(-0.75), CD_R(0.0));
			joints[k] = cd2CreateRevoluteJoint(world, &jd);
		}
		size_t size = cd2World_GetStateSize(world);
		void* state = malloc(size);
		TEST_CHECK(state != NULL && cd2World_SaveState(world, state, size) == CD_OK);
		for (int step = 0; step < 5; ++step)
		{
			cd2World_Step(world, DT, 4);
		}
		TEST_CHECK(cd2World_GetCounters(world).touchingContactCount == 2);
		uint64_t kept = HashBodies(bodies, 10);

		cd2WorldId fresh = CreateWorld(workers[w], NULL);
		cd2BodyId freshBodies[10];
		cd2JointId freshJoints[3];
		BuildPairs(fresh, freshBodies, freshJoints);
		TEST_CHECK(state != NULL && cd2World_RestoreState(fresh, state, size) == CD_OK);
		for (int step = 0; step < 5; ++step)
		{
			cd2World_Step(fresh, DT, 4);
		}
		uint64_t anew = HashBodies(freshBodies, 10);
		TEST_CHECKF(kept == anew, "%d workers: hash %016llx after the change, %016llx restored", workers[w],
					(unsigned long long)kept, (unsigned long long)anew);
		free(state);
		cd2DestroyWorld(fresh);
		cd2DestroyWorld(world);
	}
}

static int s_refusals = 0;

static bool CountRefusal(const char* condition, const char* fileName, int lineNumber)
{
	(void)condition;
	(void)fileName;
	(void)lineNumber;
	++s_refusals;
	return false; /* no abort: the call returns a null id */
}

/* enqueueTask without finishTask (or the reverse) cannot work: refused. */
static void TestHalfATaskSystemIsRefused(void)
{
	cdSetAssertFcn(CountRefusal);
	cd2WorldDef wd = cd2DefaultWorldDef();
	wd.workerCount = 2;
	wd.enqueueTask = TestEnqueue;
	cd2WorldId world = cd2CreateWorld(&wd);
	TEST_CHECK(!cd2World_IsValid(world));
	wd.enqueueTask = NULL;
	wd.finishTask = TestFinish;
	world = cd2CreateWorld(&wd);
	TEST_CHECK(!cd2World_IsValid(world));
	TEST_CHECK(s_refusals == 2);
	cdSetAssertFcn(NULL);
	wd.finishTask = NULL;
	world = cd2CreateWorld(&wd);
	TEST_CHECK(cd2World_IsValid(world));
	cd2DestroyWorld(world);
}

/* Worlds with the built-in pool are created and destroyed many times (threads started and joined,
 * nothing left behind: the sanitizer builds check the leaks), stepping once or not at all. */
static void TestPoolCreateDestroy(void)
{
	for (int i = 0; i < 20; ++i)
	{
		cd2WorldDef wd = cd2DefaultWorldDef();
		wd.workerCount = 1 + i % 4;
		cd2WorldId world = cd2CreateWorld(&wd);
		TEST_CHECK(cd2World_IsValid(world));
		if (i % 2 == 0)
		{
			cd2BodyDef bd = cd2DefaultBodyDef();
			bd.type = CD_DYNAMIC_BODY;
			cd2BodyId body = cd2CreateBody(world, &bd);
			cd2ShapeDef sd = cd2DefaultShapeDef();
			cd2Circle circle = {{CD_R(0.0), CD_R(0.0)}, CD_R(0.5)};
			cd2CreateCircleShape(body, &sd, &circle);
			cd2World_Step(world, DT, 4);
			TEST_CHECK(cd2Body_GetPosition(body).y < CD_R(0.0));
		}
		cd2DestroyWorld(world);
	}
}

int main(void)
{
	TEST_RUN(TestSameBitsEveryRunAndWorkerCount);
	TEST_RUN(TestJointGridSameBitsEveryWorkerCount);
	TEST_RUN(TestTasksRunInsideEnqueue);
	TEST_RUN(TestSmallWorldStaysOnOneThread);
	TEST_RUN(TestColoringKeptOnlyWhileTheSame);
	TEST_RUN(TestHalfATaskSystemIsRefused);
	TEST_RUN(TestPoolCreateDestroy);
	return TEST_SUMMARY();
}
