/* Speculative contact points in the 2D world: a point beyond the fixed margin (CD_SPECULATIVE_DISTANCE)
 * is kept only while its approach speed along the normal can close the gap in the step. A box
 * sliding fast just above the ground gets no point (no constraint, no touch) and keeps its height
 * and speed; a box approaching as fast is still caught at the surface in one step (no sinking); and
 * a box sliding fast while it slowly descends lands without sinking either. */
#include "test.h"

#include <collide/collide.h>

#include "world2_test_scenes.h"

#define DT (CD_R(1.0) / CD_R(60.0))

/* A world without gravity: the bodies move only as set. */
static cd2WorldId MakeWorld(void)
{
	cd2WorldDef wd = cd2DefaultWorldDef();
	wd.gravity = cd2MakeVec(CD_R(0.0), CD_R(0.0));
	wd.enableSleep = false;
	return cd2CreateWorld(&wd);
}

/* A half-unit box whose bottom is `gap` above the ground (top at y = 0), moving at velocity v. */
static cd2BodyId MakeMovingBox(cd2WorldId world, cdReal gap, cd2Vec v)
{
	cd2BodyDef bd = cd2DefaultBodyDef();
	bd.type = CD_DYNAMIC_BODY;
	bd.position = cd2MakeVec(CD_R(0.0), CD_R(0.5) + gap);
	bd.linearVelocity = v;
	cd2BodyId box = cd2CreateBody(world, &bd);
	cd2ShapeDef sd = cd2DefaultShapeDef();
	sd.friction = CD_R(0.0);
	cd2Polygon polygon;
	cd2MakeBoxPolygon((cd2Box){{CD_R(0.0), CD_R(0.0)}, {CD_R(0.5), CD_R(0.5)}, {CD_R(1.0), CD_R(0.0)}},
					  &polygon);
	cd2CreatePolygonShape(box, &sd, &polygon);
	return box;
}

/* 6 m/s sideways, 5 cm above the ground: its box overlaps the ground's (a contact), its point would
 * be within the closing-speed margin (0.02 + 6 / 60 m) but it does not approach: no point. */
static void TestSlidingPastMakesNoPoint(void)
{
	cd2WorldId world = MakeWorld();
	MakeGround(world);
	cd2BodyId box = MakeMovingBox(world, CD_R(0.05), cd2MakeVec(CD_R(6.0), CD_R(0.0)));
	for (int i = 0; i < 30; ++i)
	{
		cd2World_Step(world, DT, 4);
		cd2Counters c = cd2World_GetCounters(world);
		TEST_CHECKF(c.contactCount == 1, "step %d: %d contacts", i, c.contactCount);
		TEST_CHECKF(c.touchingContactCount == 0, "step %d: %d touching", i, c.touchingContactCount);
	}
	cd2Vec p = cd2Body_GetPosition(box);
	cd2Vec v = cd2Body_GetLinearVelocity(box);
	TEST_CHECK_NEAR(p.y, CD_R(0.55), CD_R(1e-5));
	TEST_CHECK_NEAR(v.x, CD_R(6.0), CD_R(1e-4));
	TEST_CHECK_NEAR(v.y, CD_R(0.0), CD_R(1e-6));
	TEST_CHECK_NEAR(p.x, CD_R(6.0) * CD_R(30.0) * DT, CD_R(1e-3));
	cd2DestroyWorld(world);
}

/* 6 m/s straight down, 8 cm above the ground (not fast enough for continuous collision: 0.1 m a
 * step, under half the box): the point is kept, the box stops at the surface within the first step
 * instead of sinking 2 cm into it. */
static void TestApproachingIsCaught(void)
{
	cd2WorldId world = MakeWorld();
	MakeGround(world);
	cd2BodyId box = MakeMovingBox(world, CD_R(0.08), cd2MakeVec(CD_R(0.0), CD_R(-6.0)));
	cd2World_Step(world, DT, 4);
	cd2Counters c = cd2World_GetCounters(world);
	TEST_CHECKF(c.touchingContactCount == 1, "%d touching", c.touchingContactCount);
	cdReal bottom = cd2Body_GetPosition(box).y - CD_R(0.5);
	TEST_CHECKF(bottom > -CD_LINEAR_SLOP && bottom < CD_R(0.01), "bottom at %g after one step",
				(double)bottom);
	for (int i = 0; i < 30; ++i)
	{
		cd2World_Step(world, DT, 4);
		bottom = cd2Body_GetPosition(box).y - CD_R(0.5);
		TEST_CHECKF(bottom > -CD_LINEAR_SLOP, "step %d: bottom at %g", i, (double)bottom);
	}
	TEST_CHECKF(cdAbs(cd2Body_GetLinearVelocity(box).y) < CD_R(0.01), "still moving at %g",
				(double)cd2Body_GetLinearVelocity(box).y);
	cd2DestroyWorld(world);
}

/* 6 m/s sideways and 0.3 m/s down from 10 cm: the point is dropped while the gap is larger than a
 * step's descent (plus the margin) and comes back before the gap closes: the box lands and slides on
 * without sinking. */
static void TestSlidingDescentLands(void)
{
	cd2WorldId world = MakeWorld();
	MakeGround(world);
	cd2BodyId box = MakeMovingBox(world, CD_R(0.1), cd2MakeVec(CD_R(6.0), CD_R(-0.3)));
	bool touched = false;
	int untouchedSteps = 0;
	for (int i = 0; i < 60; ++i)
	{
		cd2World_Step(world, DT, 4);
		cdReal bottom = cd2Body_GetPosition(box).y - CD_R(0.5);
		TEST_CHECKF(bottom > -CD_LINEAR_SLOP, "step %d: bottom at %g", i, (double)bottom);
		bool touching = cd2World_GetCounters(world).touchingContactCount > 0;
		touched = touched || touching;
		untouchedSteps += touching ? 0 : 1;
	}
	TEST_CHECK(touched);
	/* Without the filter the 0.12 m margin would have touched from the first step. */
	TEST_CHECKF(untouchedSteps >= 5, "%d steps without a point", untouchedSteps);
	cdReal bottom = cd2Body_GetPosition(box).y - CD_R(0.5);
	TEST_CHECKF(bottom < CD_R(0.01), "bottom at %g: not landed", (double)bottom);
	cd2DestroyWorld(world);
}

int main(void)
{
	TEST_RUN(TestSlidingPastMakesNoPoint);
	TEST_RUN(TestApproachingIsCaught);
	TEST_RUN(TestSlidingDescentLands);
	return TEST_SUMMARY();
}
