/* Small 2D worlds shared by the world's tests (test_world2.c, slow/test_world2_pyramid40.c):
 * a ground box, dynamic boxes, the pyramid, and the check that a pyramid stands on its own.
 * Header-only: each test is one program. Include after test.h and <collide/collide.h>. */
#ifndef COLLIDE_TESTS_WORLD2_TEST_SCENES_H
#define COLLIDE_TESTS_WORLD2_TEST_SCENES_H

/* A static box 200 wide and 2 high whose top is at y = 0. */
static inline cd2BodyId MakeGround(cd2WorldId world)
{
	cd2BodyDef bd = cd2DefaultBodyDef();
	bd.position = cd2MakeVec(CD_R(0.0), CD_R(-1.0));
	cd2BodyId ground = cd2CreateBody(world, &bd);
	cd2ShapeDef sd = cd2DefaultShapeDef();
	cd2Polygon box;
	cd2MakeBoxPolygon((cd2Box){{CD_R(0.0), CD_R(0.0)}, {CD_R(100.0), CD_R(1.0)}, {CD_R(1.0), CD_R(0.0)}},
					  &box);
	cd2CreatePolygonShape(ground, &sd, &box);
	return ground;
}

static inline cd2BodyId MakeBox(cd2WorldId world, cd2Vec position, cdReal halfWidth, cdReal halfHeight,
								cdReal density, cdReal friction)
{
	cd2BodyDef bd = cd2DefaultBodyDef();
	bd.type = CD_DYNAMIC_BODY;
	bd.position = position;
	cd2BodyId body = cd2CreateBody(world, &bd);
	cd2ShapeDef sd = cd2DefaultShapeDef();
	sd.density = density;
	sd.friction = friction;
	cd2Polygon box;
	cd2MakeBoxPolygon((cd2Box){{CD_R(0.0), CD_R(0.0)}, {halfWidth, halfHeight}, {CD_R(1.0), CD_R(0.0)}},
					  &box);
	cd2CreatePolygonShape(body, &sd, &box);
	return body;
}

/* The peers' pyramid on the ground: unit boxes, rows offset by half a box. Returns the top box. */
static inline cd2BodyId MakePyramid(cd2WorldId world, int base)
{
	MakeGround(world);
	cd2BodyId top = CD2_NULL_BODY_ID;
	for (int i = 0; i < base; ++i)
	{
		for (int j = i; j < base; ++j)
		{
			cdReal x = (cdReal)(i + 1) * CD_R(0.5) + (cdReal)(j - i) - CD_R(0.5) * (cdReal)base;
			cdReal y = CD_R(0.5) + (cdReal)i;
			top = MakeBox(world, cd2MakeVec(x, y), CD_R(0.5), CD_R(0.5), CD_R(1.0), CD_R(0.6));
		}
	}
	return top;
}

/* The pyramid of `base` stands for 10 s (600 steps of 1/60 s, 4 sub-steps) without sleeping: the
 * top box moves less than 0.02 after the first second and less than `maxSettle` in all (the soft
 * contacts compress the rows within the first second), the world holds the boxes and the ground,
 * and at least `minTouching` contacts touch. Returns how far the top box got sideways from where
 * it was after the first second (the largest |dx| over the 9 s that follow). */
static inline cdReal CheckPyramidStands(int base, cdReal maxSettle, int minTouching)
{
	cd2WorldDef wd = cd2DefaultWorldDef();
	wd.enableSleep = false; /* the stack must hold by itself, not by sleeping */
	cd2WorldId world = cd2CreateWorld(&wd);
	cd2BodyId top = MakePyramid(world, base);
	cd2Vec start = cd2Body_GetPosition(top);
	cd2Vec settled = start;
	cdReal sway = CD_R(0.0);
	for (int i = 0; i < 600; ++i)
	{
		cd2World_Step(world, CD_R(1.0) / CD_R(60.0), 4);
		if (i == 59)
		{
			settled = cd2Body_GetPosition(top);
		}
		else if (i > 59)
		{
			sway = cdMax(sway, cdAbs(cd2Body_GetPosition(top).x - settled.x));
		}
	}
	cd2Vec end = cd2Body_GetPosition(top);
	TEST_CHECKF(cd2Length(cd2Sub(end, settled)) < CD_R(0.02), "top moved %g from 1 s to 10 s",
				(double)cd2Length(cd2Sub(end, settled)));
	TEST_CHECKF(cd2Length(cd2Sub(end, start)) < maxSettle, "top moved %g from its start",
				(double)cd2Length(cd2Sub(end, start)));
	cd2Counters c = cd2World_GetCounters(world);
	TEST_CHECKF(c.bodyCount == base * (base + 1) / 2 + 1, "bodies %d", c.bodyCount);
	TEST_CHECKF(c.touchingContactCount >= minTouching, "touching %d", c.touchingContactCount);
	cd2DestroyWorld(world);
	return sway;
}

#endif
