/* libFuzzer target for the physics scene loader of `collide run` (tools/collide/world_load.c):
 * the "world" section read, validated and built through the world API, then stepped. The loader
 * reads from a path only, so each input is written to a scratch file first. Seeds: the example
 * worlds and the malformed ones (examples/worlds, examples/worlds/bad) and fuzz/corpus/.
 *
 * Checked, with aborts on violation: no crash or sanitizer report (leaks included); a failed load
 * leaves no world and no body list behind (a new world can still be created afterwards: none
 * leaked) and gives a NUL-terminated message with a line >= 0;
 * a loaded world holds what the format allows (counts within the limits, every body id valid, a
 * time step in (0, 1], 1 to 64 sub-steps); three steps keep every body's position, angle and
 * velocities finite. */
#include "fuzz_scratch.h"
#include "world_scene.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static void Fail(const char* what, int body)
{
	fprintf(stderr, "fuzz_world_scene: %s (body %d)\n", what, body);
	fflush(stderr);
	abort();
}

static bool Finite2(cd2Vec v)
{
	return isfinite((double)v.x) && isfinite((double)v.y);
}

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	const char* path = WriteScratchFile("fuzz_world_scene", data, size);
	ToolWorld world;
	ToolError error;
	memset(&error, 0x5a, sizeof error);
	if (!toolLoadWorld(path, &world, &error))
	{
		if (world.world.index1 != 0 || world.bodies != NULL || world.bodyCount != 0)
		{
			Fail("a failed load left a world behind", -1);
		}
		if (error.line < 0 || memchr(error.message, 0, sizeof error.message) == NULL || error.message[0] == 0)
		{
			Fail("a failed load without a message or with a negative line", -1);
		}
		/* A failed load destroys what it built: a world can still be created. */
		cd2WorldDef def = cd2DefaultWorldDef();
		cd2WorldId probe = cd2CreateWorld(&def);
		if (!cd2World_IsValid(probe))
		{
			Fail("no world left to create: a failed load leaked its world", -1);
		}
		cd2DestroyWorld(probe);
		return 0;
	}
	if (!cd2World_IsValid(world.world) || world.bodyCount < 0 || world.bodyCount > TOOL_MAX_WORLD_BODIES ||
		world.jointCount < 0 || world.jointCount > TOOL_MAX_WORLD_JOINTS || !(world.timeStep > 0.0) ||
		world.timeStep > 1.0 || world.subSteps < 1 || world.subSteps > TOOL_MAX_SUB_STEPS)
	{
		Fail("a loaded world outside the format's limits", -1);
	}
	cd2Counters counters = cd2World_GetCounters(world.world);
	if (counters.bodyCount != world.bodyCount || counters.jointCount != world.jointCount ||
		counters.shapeCount != world.shapeCount)
	{
		Fail("the world's counters differ from what the loader built", -1);
	}
	for (int i = 0; i < world.bodyCount; ++i)
	{
		if (!cd2Body_IsValid(world.bodies[i].id))
		{
			Fail("a loaded body id is not valid", i);
		}
	}
	for (int step = 0; step < 3; ++step)
	{
		cd2World_Step(world.world, (cdReal)world.timeStep, world.subSteps);
	}
	for (int i = 0; i < world.bodyCount; ++i)
	{
		cd2BodyId body = world.bodies[i].id;
		if (!Finite2(cd2Body_GetPosition(body)) || !Finite2(cd2Body_GetLinearVelocity(body)) ||
			!isfinite((double)cd2Body_GetAngularVelocity(body)) ||
			!isfinite((double)cd2RotGetAngle(cd2Body_GetRotation(body))))
		{
			Fail("a body is not finite after three steps", i);
		}
	}
	toolFreeWorld(&world);
	if (world.world.index1 != 0 || world.bodies != NULL)
	{
		Fail("toolFreeWorld left a world behind", -1);
	}
	return 0;
}
