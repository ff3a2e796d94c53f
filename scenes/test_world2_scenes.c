/* The 2D world scenes' quality criteria (world2_quality.h) on made-up snapshots: each criterion
 * passes on a state that meets it and fails on one that breaks it, since every engine column of
 * bench/world2 is judged by them. With the world in the tree, the small scenes of world2_scenes.h
 * run their full step counts in collide and must meet their criteria, and their snapshots must hold
 * every body the world counts. */
#include "test.h"
#include "world2_quality.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#if defined(W2_HAVE_WORLD)
#include "world2_scenes.h"
#endif

static World2Body makeBody(uint64_t key, double x, double y, int type)
{
	World2Body b;
	memset(&b, 0, sizeof(b));
	b.key = key;
	b.x = x;
	b.y = y;
	b.type = type;
	b.mass = type == WORLD2_DYNAMIC ? 1.0 : 0.0;
	return b;
}

/* A pyramid of base 4 of unit boxes, keys 1..10, and a static ground (key 100). */
static void buildPyramid(World2Snapshot* s)
{
	uint64_t key = 1;
	World2Body ground = makeBody(100, 0.0, -1.0, WORLD2_STATIC);
	TEST_CHECK(world2SnapshotAdd(s, &ground));
	for (int i = 0; i < 4; ++i)
	{
		for (int j = i; j < 4; ++j)
		{
			World2Body b =
				makeBody(key++, (i + 1) * 0.5 + (j - i) * 1.0 - 2.0, 2.0 * i * 0.5 + 0.5, WORLD2_DYNAMIC);
			TEST_CHECK(world2SnapshotAdd(s, &b));
		}
	}
}

static void TestSceneList(void)
{
	TEST_CHECK(world2SceneFind("pyramid_40") == WORLD2_PYRAMID_40);
	TEST_CHECK(world2SceneFind("tumbler") == WORLD2_TUMBLER);
	TEST_CHECK(world2SceneFind("nope") == WORLD2_SCENE_COUNT);
	TEST_CHECK(world2SceneFind(NULL) == WORLD2_SCENE_COUNT);
	TEST_CHECK(world2SceneInfo(WORLD2_SCENE_COUNT) == NULL);
	/* Box2D v3's benchmark/main.c step counts. */
	TEST_CHECK(world2SceneInfo(WORLD2_LARGE_PYRAMID)->stepCount == 500);
	TEST_CHECK(world2SceneInfo(WORLD2_MANY_PYRAMIDS)->stepCount == 200);
	TEST_CHECK(world2SceneInfo(WORLD2_RAIN)->stepCount == 1000);
	TEST_CHECK(world2SceneInfo(WORLD2_SMASH)->stepCount == 300);
	TEST_CHECK(world2SceneInfo(WORLD2_TUMBLER)->stepCount == 750);
	for (int i = 0; i < WORLD2_SCENE_COUNT; ++i)
	{
		TEST_CHECK(world2SceneInfo((World2SceneId)i)->subStepCount == 4);
	}
}

static void TestPyramidCriterion(void)
{
	World2Snapshot start = {0}, end = {0};
	buildPyramid(&start);
	buildPyramid(&end);
	/* The apex is the last box (key 10, at y = 3.5); the others moving a lot does not matter. */
	end.bodies[1].x += 0.5;
	end.bodies[10].y -= 0.01;
	World2Quality q = world2CheckQuality(WORLD2_PYRAMID_20, &start, &end, 10.0);
	TEST_CHECK(q.computed && q.pass);
	TEST_CHECK_NEAR(q.value, 0.01, 1e-12);
	end.bodies[10].y -= 0.02;
	q = world2CheckQuality(WORLD2_PYRAMID_20, &start, &end, 10.0);
	TEST_CHECKF(q.computed && !q.pass, "%s", q.text);
	TEST_CHECK_NEAR(q.value, 0.03, 1e-12);
	/* A non-finite body fails whatever it is. */
	end.bodies[10].y = 3.5;
	end.bodies[3].vx = NAN;
	q = world2CheckQuality(WORLD2_PYRAMID_20, &start, &end, 10.0);
	TEST_CHECK(q.computed && !q.pass);
	/* A vanished box fails. */
	end.bodies[3].vx = 0.0;
	end.count -= 1;
	q = world2CheckQuality(WORLD2_PYRAMID_20, &start, &end, 10.0);
	TEST_CHECK(q.computed && !q.pass);
	world2SnapshotFree(&start);
	world2SnapshotFree(&end);
}

static void TestJointGridCriterion(void)
{
	World2Snapshot start = {0}, end = {0};
	uint64_t key = 1;
	for (int k = 0; k < 3; ++k)
	{
		for (int i = 0; i < 3; ++i)
		{
			World2Body b = makeBody(key++, k, -i, (i == 0 && k == 1) ? WORLD2_STATIC : WORLD2_DYNAMIC);
			TEST_CHECK(world2SnapshotAdd(&start, &b));
			TEST_CHECK(world2SnapshotAdd(&end, &b));
		}
	}
	World2Quality q = world2CheckQuality(WORLD2_JOINT_GRID, &start, &end, 1.0);
	TEST_CHECK(q.computed && q.pass);
	TEST_CHECK_NEAR(q.value, 0.0, 1e-12);
	/* Turning one disc a quarter turn moves its four anchors: the gap to its neighbours is
	 * |(0.5, 0) - (0, 0.5)| = 0.707 m, more than half a link. */
	end.bodies[4].angle = 0.5 * 3.14159265358979323846;
	q = world2CheckQuality(WORLD2_JOINT_GRID, &start, &end, 1.0);
	TEST_CHECK(q.computed && !q.pass);
	TEST_CHECK_NEAR(q.value, sqrt(0.5), 1e-9);
	end.bodies[4].angle = 0.25 * 3.14159265358979323846; /* 0.38 m: stretched, not torn */
	q = world2CheckQuality(WORLD2_JOINT_GRID, &start, &end, 1.0);
	TEST_CHECK(q.computed && q.pass);
	TEST_CHECK_NEAR(q.value, sqrt(2.0 - sqrt(2.0)) * 0.5, 1e-9);
	world2SnapshotFree(&start);
	world2SnapshotFree(&end);
}

static void TestTumblerSpinnerSmash(void)
{
	World2Snapshot s = {0};
	World2Body drum = makeBody(1, 0.0, 10.0, WORLD2_DYNAMIC);
	drum.mass = 1000.0;
	drum.angle = 0.25 * 3.14159265358979323846;
	World2Body box = makeBody(2, 6.0, 16.0, WORLD2_DYNAMIC); /* (6, 6) from the centre: 8.49 m along x' */
	TEST_CHECK(world2SnapshotAdd(&s, &drum));
	TEST_CHECK(world2SnapshotAdd(&s, &box));
	World2Quality q = world2CheckQuality(WORLD2_TUMBLER, &s, &s, 1.0);
	TEST_CHECK(q.computed && q.pass);
	TEST_CHECK_NEAR(q.value, 6.0 * sqrt(2.0), 1e-9);
	s.bodies[1].y = 17.0; /* (6, 7): 9.19 along x', 0.71 along y': still in */
	TEST_CHECK(world2CheckQuality(WORLD2_TUMBLER, &s, &s, 1.0).pass);
	s.bodies[1].x = 7.0; /* (7, 7): 9.90 m out along x' */
	TEST_CHECK(!world2CheckQuality(WORLD2_TUMBLER, &s, &s, 1.0).pass);

	world2SnapshotClear(&s);
	World2Body inside = makeBody(1, 39.0, 32.0, WORLD2_DYNAMIC);
	TEST_CHECK(world2SnapshotAdd(&s, &inside));
	TEST_CHECK(world2CheckQuality(WORLD2_SPINNER, &s, &s, 1.0).pass);
	s.bodies[0].x = 41.0;
	TEST_CHECK(!world2CheckQuality(WORLD2_SPINNER, &s, &s, 1.0).pass);

	World2Snapshot start = {0}, end = {0};
	World2Body a = makeBody(1, 0, 0, WORLD2_DYNAMIC), b = makeBody(2, 1, 0, WORLD2_DYNAMIC);
	a.mass = 2.0;
	a.vx = 10.0;
	TEST_CHECK(world2SnapshotAdd(&start, &a) && world2SnapshotAdd(&start, &b));
	a.vx = 6.0;
	b.vx = 8.0; /* 2 * 6 + 1 * 8 = 20: kept */
	TEST_CHECK(world2SnapshotAdd(&end, &a) && world2SnapshotAdd(&end, &b));
	TEST_CHECK(world2CheckQuality(WORLD2_SMASH, &start, &end, 1.0).pass);
	end.bodies[1].vx = 8.5; /* 2.5% more */
	q = world2CheckQuality(WORLD2_SMASH, &start, &end, 1.0);
	TEST_CHECK(!q.pass);
	TEST_CHECK_NEAR(q.value, 0.025, 1e-12);
	world2SnapshotFree(&s);
	world2SnapshotFree(&start);
	world2SnapshotFree(&end);
}

/* The chains criterion: a link that falls from rest at its pivot's height to hanging straight
 * down lost all of its potential drop if it ends at rest, none if it ends at the speed of the
 * fall. */
static void TestChainsCriterion(void)
{
	World2Snapshot start = {0}, end = {0};
	World2Body pivot = {1, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, WORLD2_STATIC};
	World2Body link = {2, 0.5, 0.0, 0.0, 0.0, 0.0, 0.0, 0.2, WORLD2_DYNAMIC};
	TEST_CHECK(world2SnapshotAdd(&start, &pivot) && world2SnapshotAdd(&start, &link));
	World2Body hanging = {2, 0.0, -0.5, -1.5707963, 0.0, 0.0, 0.0, 0.2, WORLD2_DYNAMIC};
	TEST_CHECK(world2SnapshotAdd(&end, &pivot) && world2SnapshotAdd(&end, &hanging));
	World2Quality q = world2CheckQuality(WORLD2_CHAINS, &start, &end, 10.0);
	TEST_CHECK(q.computed && !q.pass);
	TEST_CHECK_NEAR(q.value, 1.0, 1e-12);
	world2SnapshotClear(&end);
	hanging.vx = sqrt(10.0); /* v^2 / 2 = g h */
	TEST_CHECK(world2SnapshotAdd(&end, &pivot) && world2SnapshotAdd(&end, &hanging));
	q = world2CheckQuality(WORLD2_CHAINS, &start, &end, 10.0);
	TEST_CHECK(q.computed && q.pass);
	TEST_CHECK_NEAR(q.value, 0.0, 1e-12);
	world2SnapshotFree(&start);
	world2SnapshotFree(&end);
}

static void TestRampCriterion(void)
{
	/* The steep block slides g (sin 40 - 0.5 cos 40) t^2 / 2 along the ramp in t = 2 s. */
	const double pi = 3.14159265358979323846, t = 2.0;
	double a = 10.0 * (sin(WORLD2_RAMP_STEEP_DEGREES * pi / 180.0) -
					   WORLD2_RAMP_FRICTION * cos(WORLD2_RAMP_STEEP_DEGREES * pi / 180.0));
	double d = 0.5 * a * t * t;
	World2Snapshot start = {0}, end = {0};
	World2Body gentle = makeBody(1, -15.0, 0.7, WORLD2_DYNAMIC),
			   steep = makeBody(2, 19.0, 4.0, WORLD2_DYNAMIC);
	TEST_CHECK(world2SnapshotAdd(&start, &gentle) && world2SnapshotAdd(&start, &steep));
	steep.x -= d * cos(40.0 * pi / 180.0);
	steep.y -= d * sin(40.0 * pi / 180.0) * 1.01; /* 1% off along one axis: within 2% */
	TEST_CHECK(world2SnapshotAdd(&end, &gentle) && world2SnapshotAdd(&end, &steep));
	World2Quality q = world2CheckQuality(WORLD2_RAMP, &start, &end, t);
	TEST_CHECKF(q.computed && q.pass, "%s", q.text);
	end.bodies[0].x += 0.02; /* the gentle block slipped 2 cm */
	TEST_CHECK(!world2CheckQuality(WORLD2_RAMP, &start, &end, t).pass);
	end.bodies[0].x -= 0.02;
	end.bodies[1].x = start.bodies[1].x - 0.9 * d * cos(40.0 * pi / 180.0);
	end.bodies[1].y = start.bodies[1].y - 0.9 * d * sin(40.0 * pi / 180.0);
	q = world2CheckQuality(WORLD2_RAMP, &start, &end, t);
	TEST_CHECK(!q.pass);
	TEST_CHECK_NEAR(q.value, 0.1, 1e-9);
	world2SnapshotFree(&start);
	world2SnapshotFree(&end);
}

#if defined(W2_HAVE_WORLD)
static void runCollideScene(World2SceneId id)
{
	const World2SceneInfo* info = world2SceneInfo(id);
	World2Scene scene;
	TEST_CHECK(world2SceneCreate(&scene, id, 1));
	World2Snapshot start = {0}, end = {0};
	for (int i = 0; i < info->stepCount; ++i)
	{
		if (i == info->settleStepCount)
		{
			TEST_CHECK(world2SceneSnapshot(&scene, &start));
		}
		world2SceneStep(&scene, i);
	}
	TEST_CHECK(world2SceneSnapshot(&scene, &end));
	cd2Counters counters = cd2World_GetCounters(scene.world);
	TEST_CHECKF(end.count == counters.bodyCount, "%s: snapshot %d bodies, world %d", info->name, end.count,
				counters.bodyCount);
	World2Quality q =
		world2SceneQuality(&scene, &start, &end, (double)(info->stepCount - info->settleStepCount) / 60.0);
	TEST_CHECKF(q.computed && q.pass, "%s: %s", info->name, q.text);
	printf("%s: %s\n", info->name, q.text);
	world2SnapshotFree(&start);
	world2SnapshotFree(&end);
	world2SceneDestroy(&scene);
}

static void TestCollidePyramid20(void)
{
	runCollideScene(WORLD2_PYRAMID_20);
}

static void TestCollideCardHouse(void)
{
	runCollideScene(WORLD2_CARD_HOUSE);
}

static void TestCollideRamp(void)
{
	runCollideScene(WORLD2_RAMP);
}

static void TestCollideBullets(void)
{
	runCollideScene(WORLD2_BULLETS);
}

static void TestCollideSideScroller(void)
{
	runCollideScene(WORLD2_SIDE_SCROLLER);
}

static void TestCollideSlingshot(void)
{
	runCollideScene(WORLD2_SLINGSHOT);
}

static void TestCollideChains(void)
{
	runCollideScene(WORLD2_CHAINS);
}

static void TestBadSceneId(void)
{
	World2Scene scene;
	TEST_CHECK(!world2SceneCreate(&scene, WORLD2_SCENE_COUNT, 1));
}
#endif

int main(void)
{
	TEST_RUN(TestSceneList);
	TEST_RUN(TestPyramidCriterion);
	TEST_RUN(TestJointGridCriterion);
	TEST_RUN(TestTumblerSpinnerSmash);
	TEST_RUN(TestRampCriterion);
	TEST_RUN(TestChainsCriterion);
#if defined(W2_HAVE_WORLD)
	TEST_RUN(TestCollidePyramid20);
	TEST_RUN(TestCollideCardHouse);
	TEST_RUN(TestCollideRamp);
	TEST_RUN(TestCollideBullets);
	TEST_RUN(TestCollideSideScroller);
	TEST_RUN(TestCollideSlingshot);
	TEST_RUN(TestCollideChains);
	TEST_RUN(TestBadSceneId);
#endif
	return TEST_SUMMARY();
}
