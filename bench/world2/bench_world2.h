/* One engine column of collide_bench_world2: builds a scene of scenes/world2_quality.h, steps it
 * and takes engine-neutral snapshots for the quality criteria. Each adapter is compiled alone with
 * its engine's headers (Box2D v3 and Box2D 2.4 share header and library names). */
#ifndef COLLIDE_BENCH_WORLD2_H
#define COLLIDE_BENCH_WORLD2_H

#include "world2_quality.h"

#include <stdbool.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct World2Engine
{
	const char* name;
	const char* settings; /* solver settings, printed under the table */
	int maxWorkers;		  /* 1: the engine has no threads */
	bool (*supports)(World2SceneId scene);
	/* NULL on failure. */
	void* (*create)(World2SceneId scene, int workerCount);
	/* stepIndex counts from 0; the adapter runs the scene's own per-step code (rain, spinner). */
	void (*step)(void* world, World2SceneId scene, int stepIndex, float timeStep, int subStepCount);
	bool (*snapshot)(void* world, World2Snapshot* out);
	void (*counts)(void* world, int* bodyCount, int* contactCount);
	void (*destroy)(void* world);
	/* Optional: the scene's own criterion when it needs more than snapshots (events); NULL or a
	 * result with computed == false falls back to world2CheckQuality. */
	World2Quality (*quality)(void* world, World2SceneId scene, const World2Snapshot* start,
							 const World2Snapshot* end, double time);
} World2Engine;

/* Defined by the adapters that are built (W2_HAVE_<ENGINE>). */
extern const World2Engine world2EngineCollide;
extern const World2Engine world2EngineBox2d3;
extern const World2Engine world2EngineBox2d24;
extern const World2Engine world2EngineChipmunk;

#ifdef __cplusplus
}
#endif

#endif
