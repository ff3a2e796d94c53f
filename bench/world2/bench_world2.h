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

/* --profile: the engines' own per-stage times of a step (ms), lined up by meaning; a row an engine
 * does not time separately stays 0 (its time is in another row; see bench_world2.c). */
typedef enum World2ProfileRow
{
	W2P_STEP,
	W2P_PAIRS,
	W2P_REBUILD_TREE,
	W2P_COLLIDE,
	W2P_SOLVE,
	W2P_SOLVER_SETUP,
	W2P_PREPARE,
	W2P_INTEGRATE_VELOCITIES,
	W2P_WARM_START,
	W2P_SOLVE_IMPULSES,
	W2P_INTEGRATE_POSITIONS,
	W2P_RELAX,
	W2P_RESTITUTION,
	W2P_STORE,
	W2P_FINALIZE,
	W2P_REFIT,
	W2P_EVENTS,
	W2P_SLEEP,
	W2P_SOLVE_OTHER, /* solve minus its rows above (set by the bench) */
	W2P_SENSORS,
	W2P_ROW_COUNT
} World2ProfileRow;

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
	/* Optional (--profile): turn the engine's profile on (before the first step), and read the last
	 * step's into rows[W2P_ROW_COUNT] (ms). */
	void (*enableProfile)(void* world);
	void (*profile)(void* world, double* rows);
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
