/* One simulation, two machines: the native side. Builds the falling pyramid (the large_pyramid
 * layout of scenes/world2_scenes.c, base 20 unit boxes on a 200 m ground box, lifted by 1 m so
 * it falls, lands and settles; sleeping off), steps it at 60 Hz with 4 sub-steps and prints, per
 * step, a 32-bit FNV-1a hash of every body's state (x, y, cos, sin, vx, vy, angular velocity as
 * float bits, bodies in creation order). test/world2.lockstep.test.mjs builds the same scene
 * through the JavaScript API on the wasm build and compares the hashes step by step.
 * Usage: world2_lockstep [steps] [base] [drop]. */
#include <collide/collide.h>
#include <collide/world2.h>

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_BODIES 2000

static uint32_t fnv(uint32_t h, const void* data, size_t size)
{
	const unsigned char* p = (const unsigned char*)data;
	for (size_t i = 0; i < size; ++i)
	{
		h ^= p[i];
		h *= 16777619u;
	}
	return h;
}

int main(int argc, char** argv)
{
	int steps = argc > 1 ? atoi(argv[1]) : 300;
	int base = argc > 2 ? atoi(argv[2]) : 20;
	float drop = argc > 3 ? (float)atof(argv[3]) : 1.0f;
	if (cdGetRealIsDouble())
	{
		fprintf(stderr, "world2_lockstep: needs the float build\n");
		return 2;
	}
	if (steps < 0 || base < 1 || base > 60)
	{
		fprintf(stderr, "usage: world2_lockstep [steps] [base 1..60] [drop]\n");
		return 2;
	}
	cd2WorldDef wd = cd2DefaultWorldDef();
	wd.enableSleep = false;
	cd2WorldId world = cd2CreateWorld(&wd);
	static cd2BodyId bodies[MAX_BODIES];
	int count = 0;

	cd2BodyDef gd = cd2DefaultBodyDef();
	gd.position = (cd2Vec){0.0f, -1.0f};
	cd2BodyId ground = cd2CreateBody(world, &gd);
	bodies[count++] = ground;
	cd2ShapeDef sd = cd2DefaultShapeDef();
	cd2Polygon groundBox;
	memset(&groundBox, 0, sizeof groundBox);
	cd2MakeBoxPolygon((cd2Box){{0.0f, 0.0f}, {100.0f, 1.0f}, cd2MakeRot(0.0f)}, &groundBox);
	cd2CreatePolygonShape(ground, &sd, &groundBox);

	cd2BodyDef bd = cd2DefaultBodyDef();
	bd.type = CD_DYNAMIC_BODY;
	sd.density = 1.0f;
	const float a = 0.5f;
	cd2Polygon box;
	memset(&box, 0, sizeof box);
	cd2MakeBoxPolygon((cd2Box){{0.0f, 0.0f}, {a, a}, cd2MakeRot(0.0f)}, &box);
	for (int i = 0; i < base; ++i)
	{
		float y = (2.0f * (float)i + 1.0f) * a + drop;
		for (int j = i; j < base; ++j)
		{
			float x = ((float)i + 1.0f) * a + 2.0f * (float)(j - i) * a - a * (float)base;
			bd.position = (cd2Vec){x, y};
			cd2BodyId b = cd2CreateBody(world, &bd);
			cd2CreatePolygonShape(b, &sd, &box);
			bodies[count++] = b;
		}
	}
	for (int step = 0; step < steps; ++step)
	{
		cd2World_Step(world, 1.0f / 60.0f, 4);
		uint32_t h = 2166136261u;
		for (int k = 0; k < count; ++k)
		{
			cd2Transform xf = cd2Body_GetTransform(bodies[k]);
			cd2Vec v = cd2Body_GetLinearVelocity(bodies[k]);
			float s[7] = {xf.p.x, xf.p.y, xf.q.c, xf.q.s, v.x, v.y, cd2Body_GetAngularVelocity(bodies[k])};
			h = fnv(h, s, sizeof s);
		}
		printf("%08x\n", (unsigned)h);
	}
	cd2Transform top = cd2Body_GetTransform(bodies[count - 1]);
	fprintf(stderr, "top box at (%.6f, %.6f)\n", (double)top.p.x, (double)top.p.y);
	cd2DestroyWorld(world);
	return 0;
}
