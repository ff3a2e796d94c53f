/* The collide column: the scenes of scenes/world2_scenes.c in a collide world with its defaults
 * (b2-like soft step), workerCount workers. */
#include "bench_world2.h"

#include "world2_scenes.h"

#include <stdlib.h>

static bool collideSupports(World2SceneId scene)
{
	return scene < WORLD2_SCENE_COUNT;
}

static void* collideCreate(World2SceneId id, int workerCount)
{
	World2Scene* scene = (World2Scene*)malloc(sizeof(World2Scene));
	if (scene == NULL)
	{
		return NULL;
	}
	if (!world2SceneCreate(scene, id, workerCount))
	{
		free(scene);
		return NULL;
	}
	return scene;
}

static void collideStep(void* world, World2SceneId id, int stepIndex, float timeStep, int subStepCount)
{
	(void)id;
	(void)timeStep;
	(void)subStepCount; /* the scene's own (world2_quality.h), the same figures */
	world2SceneStep((World2Scene*)world, stepIndex);
}

static bool collideSnapshot(void* world, World2Snapshot* out)
{
	return world2SceneSnapshot((const World2Scene*)world, out);
}

static void collideCounts(void* world, int* bodyCount, int* contactCount)
{
	cd2Counters c = cd2World_GetCounters(((World2Scene*)world)->world);
	*bodyCount = c.bodyCount;
	*contactCount = c.contactCount;
}

static void collideDestroy(void* world)
{
	world2SceneDestroy((World2Scene*)world);
	free(world);
}

static World2Quality collideQuality(void* world, World2SceneId id, const World2Snapshot* start,
									const World2Snapshot* end, double time)
{
	(void)id;
	return world2SceneQuality((const World2Scene*)world, start, end, time);
}

static void collideEnableProfile(void* world)
{
	cd2World_EnableProfiling(((World2Scene*)world)->world, true);
}

static void collideProfile(void* world, double* rows)
{
	cd2Profile p = cd2World_GetProfile(((World2Scene*)world)->world);
	rows[W2P_STEP] = p.step;
	rows[W2P_PAIRS] = p.pairs;
	rows[W2P_REBUILD_TREE] = p.rebuildTree;
	rows[W2P_COLLIDE] = p.collide;
	rows[W2P_SOLVE] = p.solve;
	rows[W2P_SOLVER_SETUP] = p.solverSetup;
	rows[W2P_PREPARE] = p.prepareConstraints;
	rows[W2P_INTEGRATE_VELOCITIES] = p.integrateVelocities;
	rows[W2P_WARM_START] = p.warmStart;
	rows[W2P_SOLVE_IMPULSES] = p.solveImpulses;
	rows[W2P_INTEGRATE_POSITIONS] = p.integratePositions;
	rows[W2P_RELAX] = p.relaxImpulses;
	rows[W2P_RESTITUTION] = p.applyRestitution;
	rows[W2P_STORE] = p.storeImpulses;
	rows[W2P_FINALIZE] = p.finalize;
	rows[W2P_REFIT] = p.refit;
	rows[W2P_EVENTS] = (double)p.hitEvents + p.jointEvents;
	rows[W2P_SLEEP] = p.sleepIslands;
	rows[W2P_SENSORS] = p.sensors;
}

const World2Engine world2EngineCollide = {
	"collide",
	"collide's 2D world (defaults of cd2DefaultWorldDef), 4 sub-steps, scenes/world2_scenes.c; workerCount "
	"is "
	"passed to cd2CreateWorld (2 workers: its built-in pool)",
	2,
	collideSupports,
	collideCreate,
	collideStep,
	collideSnapshot,
	collideCounts,
	collideDestroy,
	collideQuality,
	collideEnableProfile,
	collideProfile,
};
