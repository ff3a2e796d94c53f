/* The pyramid of base 40 (820 boxes) stands for 10 s on its own (no sleeping): its own program,
 * because it is the slowest of the world's tests (about 0.7 s optimized, longer under the
 * sanitizers). */
#include "../test.h"

#include <collide/collide.h>

#define DT (CD_R(1.0) / CD_R(60.0))

static cd2BodyId MakeGround(cd2WorldId world)
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

static cd2BodyId MakeBox(cd2WorldId world, cd2Vec position, cdReal halfWidth, cdReal halfHeight,
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

/* The peers' pyramid: unit boxes, rows offset by half a box. Returns the top box. */
static cd2BodyId MakePyramid(cd2WorldId world, int base)
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

static void TestPyramid40Stands(void)
{
	cd2WorldDef wd = cd2DefaultWorldDef();
	wd.enableSleep = false; /* the stack must hold by itself, not by sleeping */
	cd2WorldId world = cd2CreateWorld(&wd);
	cd2BodyId top = MakePyramid(world, 40);
	cd2Vec start = cd2Body_GetPosition(top);
	cd2Vec settled = start;
	for (int i = 0; i < 600; ++i)
	{
		cd2World_Step(world, DT, 4);
		if (i == 59)
		{
			settled = cd2Body_GetPosition(top);
		}
	}
	cd2Vec end = cd2Body_GetPosition(top);
	/* The soft contacts compress the 40 rows by about 12 centimetres within the first second; after
	 * that the top box must stay put. */
	TEST_CHECKF(cd2Length(cd2Sub(end, settled)) < CD_R(0.02), "top moved %g from 1 s to 10 s",
				(double)cd2Length(cd2Sub(end, settled)));
	TEST_CHECKF(cd2Length(cd2Sub(end, start)) < CD_R(0.15), "top moved %g from its start",
				(double)cd2Length(cd2Sub(end, start)));
	cd2Counters c = cd2World_GetCounters(world);
	TEST_CHECK(c.bodyCount == 821);
	TEST_CHECKF(c.touchingContactCount >= 2370, "touching %d", c.touchingContactCount);
	cd2DestroyWorld(world);
}

int main(void)
{
	TEST_RUN(TestPyramid40Stands);
	return TEST_SUMMARY();
}
