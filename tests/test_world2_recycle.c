/* Contact recycling (cd2WorldDef.contactRecycleDistance): the same scenes with recycling off (0),
 * at the default and at a larger distance meet the same quality criteria (a pyramid stands, a
 * bouncing ball keeps its height, events come once), recycling really changes the results (it
 * runs), and bullets are never recycled. */
#include "test.h"

#include <collide/collide.h>

#include <string.h>

#include "world2_test_scenes.h"

#define DT (CD_R(1.0) / CD_R(60.0))

static const cdReal k_distances[3] = {CD_R(0.0), CD_R(0.02), CD_R(0.05)};

/* A pyramid of 20 stands for 10 s without sleeping with every recycle distance; the top box ends
 * within 1 cm of where it ends without recycling, but not at the same bits. */
static void TestPyramid(void)
{
	cd2Vec ends[3];
	for (int d = 0; d < 3; ++d)
	{
		cd2WorldDef wd = cd2DefaultWorldDef();
		wd.enableSleep = false;
		wd.contactRecycleDistance = k_distances[d];
		cd2WorldId world = cd2CreateWorld(&wd);
		cd2BodyId top = MakePyramid(world, 20);
		cd2Vec start = cd2Body_GetPosition(top), settled = start;
		for (int i = 0; i < 600; ++i)
		{
			cd2World_Step(world, DT, 4);
			if (i == 59)
			{
				settled = cd2Body_GetPosition(top);
			}
		}
		ends[d] = cd2Body_GetPosition(top);
		TEST_CHECKF(cd2Length(cd2Sub(ends[d], settled)) < CD_R(0.02), "distance %g: top moved %g after 1 s",
					(double)k_distances[d], (double)cd2Length(cd2Sub(ends[d], settled)));
		TEST_CHECKF(cd2Length(cd2Sub(ends[d], start)) < CD_R(0.05), "distance %g: top moved %g",
					(double)k_distances[d], (double)cd2Length(cd2Sub(ends[d], start)));
		cd2Counters c = cd2World_GetCounters(world);
		TEST_CHECKF(c.touchingContactCount >= 590, "distance %g: touching %d", (double)k_distances[d],
					c.touchingContactCount);
		cd2DestroyWorld(world);
	}
	for (int d = 1; d < 3; ++d)
	{
		TEST_CHECKF(cd2Length(cd2Sub(ends[d], ends[0])) < CD_R(0.01), "distance %g: %g from no recycling",
					(double)k_distances[d], (double)cd2Length(cd2Sub(ends[d], ends[0])));
		TEST_CHECKF(ends[d].x != ends[0].x || ends[d].y != ends[0].y, "distance %g: the same bits as without",
					(double)k_distances[d]);
	}
}

static int s_preSolveCalls = 0;

static bool CountPreSolve(cd2ShapeId shapeIdA, cd2ShapeId shapeIdB, const cd2Manifold* manifold,
						  void* context)
{
	(void)shapeIdA;
	(void)shapeIdB;
	(void)context;
	TEST_CHECK(manifold->pointCount > 0);
	++s_preSolveCalls;
	return true;
}

/* A bouncy ball falls 4.5 m onto the ground and comes back near its height; a box lands and rests:
 * one begin event each, a pre-solve call every step the box touches, and an end event when the box
 * is thrown up again. The same with every recycle distance. */
static void TestBounceAndEvents(void)
{
	for (int d = 0; d < 3; ++d)
	{
		cd2WorldDef wd = cd2DefaultWorldDef();
		wd.enableSleep = false;
		wd.contactRecycleDistance = k_distances[d];
		cd2WorldId world = cd2CreateWorld(&wd);
		MakeGround(world);
		cd2BodyDef bd = cd2DefaultBodyDef();
		bd.type = CD_DYNAMIC_BODY;
		bd.position = cd2MakeVec(CD_R(-10.0), CD_R(5.0));
		cd2BodyId ball = cd2CreateBody(world, &bd);
		cd2ShapeDef sd = cd2DefaultShapeDef();
		sd.restitution = CD_R(1.0);
		sd.friction = CD_R(0.0);
		sd.enableContactEvents = false;
		cd2Circle circle = {{CD_R(0.0), CD_R(0.0)}, CD_R(0.5)};
		cd2CreateCircleShape(ball, &sd, &circle);
		bd.position = cd2MakeVec(CD_R(10.0), CD_R(0.51));
		cd2BodyId box = cd2CreateBody(world, &bd);
		sd = cd2DefaultShapeDef();
		sd.enableContactEvents = true;
		sd.enablePreSolveEvents = true;
		cd2Polygon poly;
		cd2MakeBoxPolygon((cd2Box){{CD_R(0.0), CD_R(0.0)}, {CD_R(0.5), CD_R(0.5)}, {CD_R(1.0), CD_R(0.0)}},
						  &poly);
		cd2ShapeId boxShape = cd2CreatePolygonShape(box, &sd, &poly);
		s_preSolveCalls = 0;
		cd2World_SetPreSolveCallback(world, CountPreSolve, NULL);
		int begins = 0, ends = 0, touchingSteps = 0;
		cdReal apex = CD_R(0.0);
		bool bounced = false;
		for (int i = 0; i < 240; ++i)
		{
			cd2World_Step(world, DT, 4);
			cd2ContactEvents ce = cd2World_GetContactEvents(world);
			for (int k = 0; k < ce.beginCount; ++k)
			{
				begins += cd2ShapeIdEqual(ce.beginEvents[k].shapeIdB, boxShape) ||
						  cd2ShapeIdEqual(ce.beginEvents[k].shapeIdA, boxShape);
			}
			for (int k = 0; k < ce.endCount; ++k)
			{
				ends += cd2ShapeIdEqual(ce.endEvents[k].shapeIdB, boxShape) ||
						cd2ShapeIdEqual(ce.endEvents[k].shapeIdA, boxShape);
			}
			touchingSteps += cd2Body_GetPosition(box).y < CD_R(0.6);
			cdReal vy = cd2Body_GetLinearVelocity(ball).y, y = cd2Body_GetPosition(ball).y;
			bounced = bounced || vy > CD_R(1.0);
			if (bounced && y > apex)
			{
				apex = y;
			}
		}
		TEST_CHECKF(apex > CD_R(4.75), "distance %g: bounced back to %g of 5", (double)k_distances[d],
					(double)apex);
		TEST_CHECKF(begins == 1 && ends == 0, "distance %g: %d begin, %d end events", (double)k_distances[d],
					begins, ends);
		/* The box starts within the speculative margin: a pre-solve call every step. */
		TEST_CHECKF(s_preSolveCalls == 240 && touchingSteps == 240,
					"distance %g: %d pre-solve calls, %d steps resting", (double)k_distances[d],
					s_preSolveCalls, touchingSteps);
		cd2Body_SetLinearVelocity(box, cd2MakeVec(CD_R(0.0), CD_R(10.0)));
		for (int i = 0; i < 30; ++i)
		{
			cd2World_Step(world, DT, 4);
			cd2ContactEvents ce = cd2World_GetContactEvents(world);
			for (int k = 0; k < ce.endCount; ++k)
			{
				ends += cd2ShapeIdEqual(ce.endEvents[k].shapeIdB, boxShape) ||
						cd2ShapeIdEqual(ce.endEvents[k].shapeIdA, boxShape);
			}
		}
		TEST_CHECKF(ends == 1, "distance %g: %d end events after the throw", (double)k_distances[d], ends);
		cd2DestroyWorld(world);
	}
}

/* Bullets bouncing in a closed room of static walls: their contacts always run the narrowphase, so
 * the run is bit for bit the same with recycling off and on, and no bullet leaves the room. */
static void TestBulletsNeverRecycled(void)
{
	cd2Vec final[2][8];
	for (int d = 0; d < 2; ++d)
	{
		cd2WorldDef wd = cd2DefaultWorldDef();
		wd.gravity = cd2MakeVec(CD_R(0.0), CD_R(-10.0));
		wd.contactRecycleDistance = d == 0 ? CD_R(0.0) : CD_R(0.05);
		cd2WorldId world = cd2CreateWorld(&wd);
		cd2BodyDef bd = cd2DefaultBodyDef();
		cd2BodyId room = cd2CreateBody(world, &bd);
		cd2ShapeDef sd = cd2DefaultShapeDef();
		sd.restitution = CD_R(0.5);
		const cdReal walls[4][4] = {{0, -5, 5, 0.1f}, {0, 5, 5, 0.1f}, {-5, 0, 0.1f, 5}, {5, 0, 0.1f, 5}};
		for (int w = 0; w < 4; ++w)
		{
			cd2Polygon wall;
			cd2MakeBoxPolygon(
				(cd2Box){{walls[w][0], walls[w][1]}, {walls[w][2], walls[w][3]}, {CD_R(1.0), CD_R(0.0)}},
				&wall);
			cd2CreatePolygonShape(room, &sd, &wall);
		}
		cd2BodyId bullets[8];
		for (int b = 0; b < 8; ++b)
		{
			bd = cd2DefaultBodyDef();
			bd.type = CD_DYNAMIC_BODY;
			bd.isBullet = true;
			bd.position = cd2MakeVec(CD_R(-4.0) + (cdReal)b, (cdReal)(b % 3) - CD_R(1.0));
			bd.linearVelocity =
				cd2MakeVec(CD_R(150.0) - CD_R(40.0) * (cdReal)b, CD_R(90.0) - CD_R(25.0) * (cdReal)b);
			bullets[b] = cd2CreateBody(world, &bd);
			sd = cd2DefaultShapeDef();
			sd.restitution = CD_R(0.5);
			cd2Circle circle = {{CD_R(0.0), CD_R(0.0)}, CD_R(0.1)};
			cd2CreateCircleShape(bullets[b], &sd, &circle);
		}
		for (int i = 0; i < 600; ++i)
		{
			cd2World_Step(world, DT, 4);
		}
		for (int b = 0; b < 8; ++b)
		{
			final[d][b] = cd2Body_GetPosition(bullets[b]);
			TEST_CHECKF(cdAbs(final[d][b].x) < CD_R(5.0) && cdAbs(final[d][b].y) < CD_R(5.0),
						"bullet %d left the room: (%g, %g)", b, (double) final[d][b].x,
						(double) final[d][b].y);
		}
		cd2DestroyWorld(world);
	}
	TEST_CHECK(memcmp(final[0], final[1], sizeof(final[0])) == 0);
}

/* A negative or NaN distance is refused. */
static bool s_refused = false;

static bool NoteRefusal(const char* condition, const char* fileName, int lineNumber)
{
	(void)condition;
	(void)fileName;
	(void)lineNumber;
	s_refused = true;
	return false;
}

static void TestBadDistance(void)
{
	cdSetAssertFcn(NoteRefusal);
	cd2WorldDef wd = cd2DefaultWorldDef();
	wd.contactRecycleDistance = -CD_R(1.0);
	s_refused = false;
	TEST_CHECK(cd2World_IsValid(cd2CreateWorld(&wd)) == false);
	TEST_CHECK(s_refused);
	cdSetAssertFcn(NULL);
}

int main(void)
{
	(void)CheckPyramidStands; /* shared header; the pyramid here runs with several distances */
	TEST_RUN(TestPyramid);
	TEST_RUN(TestBounceAndEvents);
	TEST_RUN(TestBulletsNeverRecycled);
	TEST_RUN(TestBadDistance);
	return TEST_SUMMARY();
}
