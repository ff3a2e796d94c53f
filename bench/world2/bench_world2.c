/* collide_bench_world2: the 2D world scenes on collide and the peers in the same run.
 *
 *   collide_bench_world2 [--scene NAME[,NAME...]] [--engine NAME[,NAME...]] [--runs R]
 *                        [--steps N] [--workers 1|2|12] [--budget S] [--smoke] [--list] [--profile]
 *
 * For every scene, engine and worker count (1 and 2 where the engine has threads) the scene is
 * built R times (default 3) and stepped its step count at 60 Hz with its sub-step count; the
 * first step is not timed (as in Box2D v3's benchmark app). ms/step is the median of the runs.
 * Memory is the heap growth (glibc mallinfo2) from before the world to after building the scene,
 * per body, and from there to after the last step, per contact (contacts the engine reports at the
 * end). --budget S: no further run of a (scene, engine, workers) starts after S seconds on it (the
 * figure then says how many runs it is the median of). The quality criterion (scenes/world2_quality.h) is
 * judged on the first run's snapshots.
 * --smoke: pyramid_20, 30 steps, 1 run, 1 worker; exits 1 unless every built column ran and
 * computed its quality criterion. Exit 2 on bad arguments.
 * --profile: after each scene, the engines' own per-stage times (cd2World_GetProfile,
 * b2World_GetProfile) side by side, ms per step on the stepping thread, the mean over the timed
 * steps of every run; stages that mean the same share a row. Profiling makes collide read the
 * clock at every stage (Box2D v3 always does), so its ms/step may rise slightly. */
#define _POSIX_C_SOURCE 200809L
#include "bench_world2.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#ifndef BENCH_COMPILER
#define BENCH_COMPILER "unknown"
#endif
#ifndef BENCH_BUILD_TYPE
#define BENCH_BUILD_TYPE "unknown"
#endif
#ifndef BENCH_LIBRARY_FLAGS
#define BENCH_LIBRARY_FLAGS ""
#endif

typedef struct EngineSlot
{
	const char* name;
	const World2Engine* engine; /* NULL: not built */
	const char* why;
} EngineSlot;

static EngineSlot engines[] = {
#if W2_HAVE_COLLIDE
	{"collide", &world2EngineCollide, NULL},
#else
	{"collide", NULL, W2_COLLIDE_WHY},
#endif
#if W2_HAVE_BOX2D3
	{"box2d-v3", &world2EngineBox2d3, NULL},
#else
	{"box2d-v3", NULL, W2_BOX2D3_WHY},
#endif
#if W2_HAVE_BOX2D24
	{"box2d-2.4", &world2EngineBox2d24, NULL},
#else
	{"box2d-2.4", NULL, W2_BOX2D24_WHY},
#endif
#if W2_HAVE_CHIPMUNK
	{"chipmunk", &world2EngineChipmunk, NULL},
#else
	{"chipmunk", NULL, W2_CHIPMUNK_WHY},
#endif
};
enum
{
	ENGINE_COUNT = (int)(sizeof(engines) / sizeof(engines[0])),
	MAX_RUNS = 31
};

static double nowSeconds(void)
{
	struct timespec t;
	clock_gettime(CLOCK_MONOTONIC, &t);
	return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* Bytes in use on the heap; -1 when not measurable. */
static double heapBytes(void)
{
#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 33))
	struct mallinfo2 m = mallinfo2();
	return (double)m.uordblks + (double)m.hblkhd;
#else
	return -1.0;
#endif
}

static int compareDoubles(const void* a, const void* b)
{
	double x = *(const double*)a, y = *(const double*)b;
	return x < y ? -1 : (x > y ? 1 : 0);
}

typedef struct Result
{
	bool ran;
	const char* error;
	double msPerStep[2];	/* 1 and 2 workers; < 0: not run */
	double minMsPerStep[2]; /* the fastest run: other processes only ever add time */
	int runCount[2];
	int bodies, contacts;
	double bytesPerBody, bytesPerContact; /* < 0: not measurable */
	World2Quality quality;
	double profile[2][W2P_ROW_COUNT]; /* --profile: sums over the timed steps */
	int profileSteps[2];
} Result;

typedef struct Options
{
	bool scenes[WORLD2_SCENE_COUNT];
	bool engines[ENGINE_COUNT];
	int runs;
	int steps; /* 0: the scene's own */
	bool workers[2];
	bool smoke;
	bool profile;
	double budget; /* seconds per (scene, engine, workers) after which no more runs start; 0: none */
} Options;

/* One run; fills ms/step and, when measure, bodies, contacts, memory and quality. */
static bool runOnce(const World2Engine* e, World2SceneId id, int workers, int steps, bool measure,
					bool profile, double* msPerStep, Result* r)
{
	const World2SceneInfo* info = world2SceneInfo(id);
	const float timeStep = 1.0f / 60.0f;
	double m0 = heapBytes();
	void* world = e->create(id, workers);
	if (world == NULL)
	{
		r->error = "the scene could not be built";
		return false;
	}
	double m1 = heapBytes();
	World2Snapshot start = {0}, end = {0};
	int bodies0 = 0, contacts0 = 0;
	int settle = info->settleStepCount < steps / 2 ? info->settleStepCount : steps / 2;
	if (measure)
	{
		e->counts(world, &bodies0, &contacts0);
	}
	profile = profile && e->enableProfile != NULL && e->profile != NULL;
	if (profile)
	{
		e->enableProfile(world);
	}
	double excluded = 0.0; /* time of the settled snapshot and of reading the profile */
	double t0 = 0.0;
	for (int i = 0; i < steps; ++i)
	{
		if (measure && i == settle)
		{
			double s0 = nowSeconds();
			if (!e->snapshot(world, &start))
			{
				r->error = "snapshot failed";
			}
			excluded += i > 0 ? nowSeconds() - s0 : 0.0;
		}
		e->step(world, id, i, timeStep, info->subStepCount);
		if (i == 0)
		{
			t0 = nowSeconds(); /* the first step is not timed */
		}
		else if (profile)
		{
			double p0 = nowSeconds();
			double rows[W2P_ROW_COUNT] = {0.0};
			e->profile(world, rows);
			double inSolve = 0.0;
			for (int k = W2P_SOLVER_SETUP; k <= W2P_SLEEP; ++k)
			{
				inSolve += rows[k];
			}
			rows[W2P_SOLVE_OTHER] = rows[W2P_SOLVE] - inSolve;
			for (int k = 0; k < W2P_ROW_COUNT; ++k)
			{
				r->profile[workers - 1][k] += rows[k];
			}
			r->profileSteps[workers - 1] += 1;
			excluded += nowSeconds() - p0;
		}
	}
	double t1 = nowSeconds();
	*msPerStep = steps > 1 ? 1000.0 * (t1 - t0 - excluded) / (double)(steps - 1) : 0.0;
	if (measure)
	{
		double m2 = heapBytes();
		e->counts(world, &r->bodies, &r->contacts);
		if (!e->snapshot(world, &end))
		{
			r->error = "snapshot failed";
		}
		/* Per body only when the scene made most of its bodies when built (rain makes them while
		 * it steps). */
		r->bytesPerBody =
			(m0 >= 0.0 && bodies0 > 0 && 2 * bodies0 >= r->bodies) ? (m1 - m0) / (double)bodies0 : -1.0;
		r->bytesPerContact = (m0 >= 0.0 && r->contacts > 0) ? (m2 - m1) / (double)r->contacts : -1.0;
		r->quality.computed = false;
		if (e->quality != NULL)
		{
			r->quality = e->quality(world, id, &start, &end, (double)(steps - settle) * (double)timeStep);
		}
		if (!r->quality.computed)
		{
			r->quality = world2CheckQuality(id, &start, &end, (double)(steps - settle) * (double)timeStep);
		}
	}
	world2SnapshotFree(&start);
	world2SnapshotFree(&end);
	e->destroy(world);
	return true;
}

/* Every engine that builds the scene, with runs interleaved (run 1 of every engine and worker
 * count, then run 2...) so that a busy spell of a shared machine falls on all columns alike. */
static void runScene(World2SceneId id, const Options* o, Result* results)
{
	const World2SceneInfo* info = world2SceneInfo(id);
	int steps = o->steps > 0 ? o->steps : info->stepCount;
	bool active[ENGINE_COUNT];
	static double times[ENGINE_COUNT][2][MAX_RUNS];
	double spent[ENGINE_COUNT][2];
	for (int e = 0; e < ENGINE_COUNT; ++e)
	{
		Result* r = &results[e];
		memset(r, 0, sizeof(*r));
		r->msPerStep[0] = r->msPerStep[1] = r->minMsPerStep[0] = r->minMsPerStep[1] = -1.0;
		r->bytesPerBody = r->bytesPerContact = -1.0;
		active[e] = o->engines[e] && engines[e].engine != NULL && engines[e].engine->supports(id);
		spent[e][0] = spent[e][1] = 0.0;
	}
	for (int run = 0; run < o->runs; ++run)
	{
		for (int w = 1; w <= 2; ++w)
		{
			for (int e = 0; e < ENGINE_COUNT; ++e)
			{
				Result* r = &results[e];
				if (!o->workers[w - 1] || !active[e] || w > engines[e].engine->maxWorkers ||
					(run > 0 && o->budget > 0.0 && spent[e][w - 1] > o->budget))
				{
					continue;
				}
				bool measure = !r->ran;
				double begin = nowSeconds();
				double ms = 0.0;
				if (!runOnce(engines[e].engine, id, w, steps, measure, o->profile, &ms, r))
				{
					active[e] = false;
					continue;
				}
				spent[e][w - 1] += nowSeconds() - begin;
				r->ran = true;
				times[e][w - 1][r->runCount[w - 1]++] = ms;
			}
		}
	}
	for (int e = 0; e < ENGINE_COUNT; ++e)
	{
		for (int w = 0; w < 2; ++w)
		{
			int n = results[e].runCount[w];
			if (n > 0)
			{
				double* t = times[e][w];
				qsort(t, (size_t)n, sizeof(double), compareDoubles);
				results[e].msPerStep[w] = (n % 2 == 1) ? t[n / 2] : 0.5 * (t[n / 2 - 1] + t[n / 2]);
				results[e].minMsPerStep[w] = t[0];
			}
		}
	}
}

static void printFigure(double v, const char* format, int width)
{
	if (v < 0.0)
	{
		printf(" %*s |", width, "-");
	}
	else
	{
		char text[32];
		snprintf(text, sizeof(text), format, v);
		printf(" %*s |", width, text);
	}
}

/* --profile: one table per scene, a column per engine and worker count that has a profile. */
static void printProfile(const char* sceneName, const Result* results)
{
	static const char* rowNames[W2P_ROW_COUNT] = {"step",
												  "pairs (new pairs, new contacts)",
												  "tree rebuild",
												  "collide (manifolds, touch changes)",
												  "solve",
												  "  solver setup",
												  "  prepare constraints",
												  "  integrate velocities",
												  "  warm start",
												  "  solve impulses",
												  "  integrate positions",
												  "  relax impulses",
												  "  restitution",
												  "  store impulses",
												  "  finalize bodies (v3 transforms)",
												  "  refit, bullets",
												  "  events (hit, joint)",
												  "  sleep (v3: and split islands)",
												  "  solve other",
												  "sensors"};
	int columns[2 * ENGINE_COUNT][2];
	int columnCount = 0;
	for (int w = 0; w < 2; ++w)
	{
		for (int e = 0; e < ENGINE_COUNT; ++e)
		{
			if (results[e].ran && results[e].profileSteps[w] > 0)
			{
				columns[columnCount][0] = e;
				columns[columnCount][1] = w;
				++columnCount;
			}
		}
	}
	if (columnCount == 0)
	{
		return;
	}
	printf(
		"\nprofile, %s: ms/step on the stepping thread (mean over the timed steps of every run)\n\n| stage |",
		sceneName);
	for (int c = 0; c < columnCount; ++c)
	{
		printf(" %s %dw |", engines[columns[c][0]].name, columns[c][1] + 1);
	}
	printf("\n|---|");
	for (int c = 0; c < columnCount; ++c)
	{
		printf("---:|");
	}
	printf("\n");
	for (int k = 0; k < W2P_ROW_COUNT; ++k)
	{
		printf("| %s |", rowNames[k]);
		for (int c = 0; c < columnCount; ++c)
		{
			const Result* r = &results[columns[c][0]];
			int w = columns[c][1];
			printf(" %.3f |", r->profile[w][k] / (double)r->profileSteps[w]);
		}
		printf("\n");
	}
	printf("\n");
	fflush(stdout);
}

static bool parseList(const char* arg, bool* flags, int count, const char* (*nameOf)(int))
{
	char buffer[512];
	snprintf(buffer, sizeof(buffer), "%s", arg);
	for (char* token = strtok(buffer, ","); token != NULL; token = strtok(NULL, ","))
	{
		bool found = false;
		for (int i = 0; i < count; ++i)
		{
			if (strcmp(nameOf(i), token) == 0)
			{
				flags[i] = true;
				found = true;
			}
		}
		if (!found)
		{
			fprintf(stderr, "collide_bench_world2: unknown name '%s'\n", token);
			return false;
		}
	}
	return true;
}

static const char* sceneNameOf(int i)
{
	return world2SceneInfo((World2SceneId)i)->name;
}

static const char* engineNameOf(int i)
{
	return engines[i].name;
}

static void usage(void)
{
	fprintf(stderr,
			"usage: collide_bench_world2 [--scene NAME[,NAME...]] [--engine NAME[,NAME...]] [--runs R]\n"
			"                            [--steps N] [--workers 1|2|12] [--budget S] [--smoke] [--list]\n"
			"                            [--profile]\n");
}

int main(int argc, char** argv)
{
	Options o;
	memset(&o, 0, sizeof(o));
	o.runs = 3;
	o.workers[0] = o.workers[1] = true;
	bool anyScene = false, anyEngine = false;
	for (int i = 1; i < argc; ++i)
	{
		const char* a = argv[i];
		const char* v = i + 1 < argc ? argv[i + 1] : NULL;
		if (strcmp(a, "--list") == 0)
		{
			for (int s = 0; s < WORLD2_SCENE_COUNT; ++s)
			{
				const World2SceneInfo* info = world2SceneInfo((World2SceneId)s);
				printf("%-14s %5d steps, %d sub-steps%s\n", info->name, info->stepCount, info->subStepCount,
					   info->box2dScene ? " (Box2D v3 benchmark scene)" : "");
			}
			return 0;
		}
		else if (strcmp(a, "--smoke") == 0)
		{
			o.smoke = true;
		}
		else if (strcmp(a, "--profile") == 0)
		{
			o.profile = true;
		}
		else if (strcmp(a, "--scene") == 0 && v != NULL)
		{
			if (!parseList(v, o.scenes, WORLD2_SCENE_COUNT, sceneNameOf))
			{
				return 2;
			}
			anyScene = true;
			++i;
		}
		else if (strcmp(a, "--engine") == 0 && v != NULL)
		{
			if (!parseList(v, o.engines, ENGINE_COUNT, engineNameOf))
			{
				return 2;
			}
			anyEngine = true;
			++i;
		}
		else if (strcmp(a, "--runs") == 0 && v != NULL)
		{
			o.runs = atoi(v);
			if (o.runs < 1 || o.runs > MAX_RUNS)
			{
				fprintf(stderr, "collide_bench_world2: --runs takes 1-%d\n", MAX_RUNS);
				return 2;
			}
			++i;
		}
		else if (strcmp(a, "--steps") == 0 && v != NULL)
		{
			o.steps = atoi(v);
			if (o.steps < 2 || o.steps > 1000000)
			{
				fprintf(stderr, "collide_bench_world2: --steps takes 2-1000000\n");
				return 2;
			}
			++i;
		}
		else if (strcmp(a, "--budget") == 0 && v != NULL)
		{
			o.budget = atof(v);
			if (!(o.budget >= 0.0 && o.budget < 1e6))
			{
				fprintf(stderr, "collide_bench_world2: --budget takes seconds >= 0\n");
				return 2;
			}
			++i;
		}
		else if (strcmp(a, "--workers") == 0 && v != NULL)
		{
			o.workers[0] = strchr(v, '1') != NULL;
			o.workers[1] = strchr(v, '2') != NULL;
			if (!o.workers[0] && !o.workers[1])
			{
				fprintf(stderr, "collide_bench_world2: --workers takes 1, 2 or 12\n");
				return 2;
			}
			++i;
		}
		else
		{
			usage();
			return 2;
		}
	}
	if (o.smoke)
	{
		if (!anyScene)
		{
			o.scenes[WORLD2_PYRAMID_20] = anyScene = true;
		}
		o.runs = 1;
		o.steps = o.steps > 0 ? o.steps : 30;
		o.workers[1] = false;
	}
	for (int s = 0; s < WORLD2_SCENE_COUNT && !anyScene; ++s)
	{
		o.scenes[s] = true;
	}
	for (int e = 0; e < ENGINE_COUNT && !anyEngine; ++e)
	{
		o.engines[e] = true;
	}

	printf("collide_bench_world2: %s, build %s, library flags '%s'\n", BENCH_COMPILER, BENCH_BUILD_TYPE,
		   BENCH_LIBRARY_FLAGS);
	printf("%d run(s) per figure: median (and fastest run), interleaved across engines and worker counts; 60 "
		   "Hz; "
		   "ms/step excludes the first step; memory: heap growth per body (building) and per contact "
		   "(stepping); "
		   "x v3: median / Box2D v3's median\n",
		   o.runs);
	for (int e = 0; e < ENGINE_COUNT; ++e)
	{
		if (!o.engines[e])
		{
			continue;
		}
		if (engines[e].engine == NULL)
		{
			printf("  %-10s MISSING: %s\n", engines[e].name, engines[e].why);
		}
		else
		{
			printf("  %-10s %s\n", engines[e].name, engines[e].engine->settings);
		}
	}
	printf("\n| scene | engine | bodies | contacts | ms/step 1w | ms/step 2w | 2w speed-up | B/body | "
		   "B/contact | "
		   "x v3 1w | x v3 2w | quality |\n");
	printf("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n");
	fflush(stdout);

	int failures = 0;
	static Result results[WORLD2_SCENE_COUNT][ENGINE_COUNT];
	for (int s = 0; s < WORLD2_SCENE_COUNT; ++s)
	{
		if (!o.scenes[s])
		{
			continue;
		}
		World2SceneId id = (World2SceneId)s;
		const World2SceneInfo* info = world2SceneInfo(id);
		Result* v3 = NULL;
		runScene(id, &o, results[s]);
		for (int e = 0; e < ENGINE_COUNT; ++e)
		{
			if (strcmp(engines[e].name, "box2d-v3") == 0 && results[s][e].ran)
			{
				v3 = &results[s][e];
			}
		}
		for (int e = 0; e < ENGINE_COUNT; ++e)
		{
			if (!o.engines[e])
			{
				continue;
			}
			Result* r = &results[s][e];
			if (engines[e].engine == NULL || !engines[e].engine->supports(id))
			{
				if (engines[e].engine == NULL &&
					(s == WORLD2_PYRAMID_20 || info->box2dScene || strcmp(engines[e].name, "collide") == 0))
				{
					printf("| %s | %s | | | | | | | | | | missing: %s |\n", info->name, engines[e].name,
						   engines[e].why);
				}
				continue;
			}
			if (!r->ran)
			{
				printf("| %s | %s | | | | | | | | | | failed: %s |\n", info->name, engines[e].name,
					   r->error != NULL ? r->error : "?");
				++failures;
				continue;
			}
			printf("| %s | %s |", info->name, engines[e].name);
			printf(" %d | %d |", r->bodies, r->contacts);
			for (int w = 0; w < 2; ++w)
			{
				char cell[64];
				if (r->msPerStep[w] < 0.0)
				{
					snprintf(cell, sizeof(cell), "-");
				}
				else if (r->runCount[w] < o.runs)
				{
					snprintf(cell, sizeof(cell), "%.3f (min %.3f, %d run%s)", r->msPerStep[w],
							 r->minMsPerStep[w], r->runCount[w], r->runCount[w] == 1 ? "" : "s");
				}
				else
				{
					snprintf(cell, sizeof(cell), "%.3f (min %.3f)", r->msPerStep[w], r->minMsPerStep[w]);
				}
				printf(" %s |", cell);
			}
			printFigure((r->msPerStep[0] > 0.0 && r->msPerStep[1] > 0.0) ? r->msPerStep[0] / r->msPerStep[1]
																		 : -1.0,
						"%.2fx", 1);
			printFigure(r->bytesPerBody, "%.0f", 1);
			printFigure(r->bytesPerContact, "%.0f", 1);
			double ratio1 = -1.0, ratio2 = -1.0;
			if (v3 != NULL && v3 != r)
			{
				ratio1 = (v3->msPerStep[0] > 0.0 && r->msPerStep[0] >= 0.0)
							 ? r->msPerStep[0] / v3->msPerStep[0]
							 : -1.0;
				ratio2 = (v3->msPerStep[1] > 0.0 && r->msPerStep[1] >= 0.0)
							 ? r->msPerStep[1] / v3->msPerStep[1]
							 : -1.0;
			}
			printFigure(ratio1, "%.2f", 1);
			printFigure(ratio2, "%.2f", 1);
			if (r->quality.computed)
			{
				printf(" %s: %s |\n", r->quality.pass ? "PASS" : "FAIL", r->quality.text);
			}
			else
			{
				printf(" not computed |\n");
				if (o.smoke)
				{
					++failures;
				}
			}
			fflush(stdout);
		}
		if (o.profile)
		{
			printProfile(info->name, results[s]);
		}
	}
	/* Box2D 2.4 target: collide at most 0.5x Box2D 2.4 on pyramid_40. */
	if (o.scenes[WORLD2_PYRAMID_40])
	{
		for (int e = 0; e < ENGINE_COUNT; ++e)
		{
			const Result* b24 = &results[WORLD2_PYRAMID_40][e];
			if (strcmp(engines[e].name, "box2d-2.4") != 0 || !b24->ran || b24->msPerStep[0] <= 0.0)
			{
				continue;
			}
			for (int f = 0; f < ENGINE_COUNT; ++f)
			{
				const Result* r = &results[WORLD2_PYRAMID_40][f];
				if (f != e && r->ran && r->msPerStep[0] > 0.0)
				{
					printf("pyramid_40, 1 worker: %s at %.2fx Box2D 2.4\n", engines[f].name,
						   r->msPerStep[0] / b24->msPerStep[0]);
				}
			}
		}
	}
	if (failures > 0)
	{
		printf("%d column(s) failed\n", failures);
		return 1;
	}
	return 0;
}
