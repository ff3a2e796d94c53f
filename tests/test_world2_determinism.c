/* The 2D world's determinism: a falling pile (a pyramid of boxes dropped from a height, with
 * circles and capsules raining on it) is stepped for 3 s and every body's state (position,
 * rotation, velocities) is hashed bit for bit. The hash must be the same on every run, for every
 * worker count, and equal to the one committed below for the build (float or double on x86-64,
 * where the SSE2 solver and its scalar fallback, -DCOLLIDE_NO_SIMD, give the same bits; other
 * machines check the first two only). A change of the solver that changes results on purpose
 * updates the committed hashes, with the reason in its commit. */
#include "test.h"

#include <collide/collide.h>

#include <stdint.h>
#include <string.h>

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

static uint64_t RunPile(int workerCount, int* bodyCountOut)
{
	cd2WorldDef wd = cd2DefaultWorldDef();
	wd.workerCount = workerCount;
	cd2WorldId world = cd2CreateWorld(&wd);
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
		bd.position = cd2MakeVec(CD_R(-6.0) + CD_R(0.53) * (cdReal)i, CD_R(18.0) + CD_R(0.7) * (cdReal)(i % 5));
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
	cd2DestroyWorld(world);
	*bodyCountOut = count;
	return h;
}

static void TestSameBitsEveryRunAndWorkerCount(void)
{
	int count = 0;
	uint64_t reference = RunPile(1, &count);
	TEST_CHECK(count == 78 + 24);
	for (int run = 0; run < 2; ++run)
	{
		int workers[3] = {1, 2, 4};
		for (int k = 0; k < 3; ++k)
		{
			int n = 0;
			uint64_t h = RunPile(workers[k], &n);
			TEST_CHECKF(h == reference, "run %d, %d workers: hash %016llx, single thread %016llx", run, workers[k],
						(unsigned long long)h, (unsigned long long)reference);
		}
	}
#if defined(__x86_64__) || defined(_M_X64)
#if CD_DOUBLE
	const uint64_t committed = UINT64_C(0xacfad48bae22ebc5);
#else
	const uint64_t committed = UINT64_C(0x0ebca92f03c7161f);
#endif
	TEST_CHECKF(reference == committed, "hash %016llx, committed %016llx", (unsigned long long)reference,
				(unsigned long long)committed);
#endif
}

int main(void)
{
	TEST_RUN(TestSameBitsEveryRunAndWorkerCount);
	return TEST_SUMMARY();
}
