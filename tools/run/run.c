/* collide run: steps a physics scene file (docs/SCENES.md) and writes what it saw.
 *
 *   collide run SCENE.json [--steps N] [--dt S] [--substeps K] [--svg OUT.svg] [--png DIR]
 *                          [--every K] [--size W[xH]] [--draw LIST] [--csv OUT.csv] [--quiet]
 *
 * Frames are drawn with the world's debug-draw callbacks (frame.c). A progress bar goes to stderr
 * when stderr is a terminal; the summary goes to stdout. Exit 0 on success, 2 on any error. */
#define _POSIX_C_SOURCE 200809L /* isatty, fileno, clock_gettime */

#include "run.h"

#include "frame.h"
#include "world_scene.h"

#ifdef COLLIDE_TOOL_WORLD2_SCENES
#include "world2_scenes.h"
#endif

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#define RUN_EXIT_ERROR 2
#define RUN_MAX_STEPS 100000000

static const char* const s_runUsage =
	"usage: collide run SCENE.json [--steps N] [--dt SECONDS] [--substeps K] [--svg OUT.svg]\n"
	"                  [--png DIR] [--every K] [--size W[xH]] [--draw LIST] [--csv OUT.csv] [--quiet]\n"
	"       collide run --scene NAME [--steps N] [same output options]\n";

static void printRunHelp(void)
{
	fputs(s_runUsage, stdout);
	fputs("\n"
		  "Builds the world of SCENE.json (its \"world\" section, docs/SCENES.md), steps it and prints a\n"
		  "summary: steps, milliseconds per step, bodies, contacts, sleeping bodies.\n"
		  "\n"
		  "  --steps N       steps to run (default 60)\n"
		  "  --dt SECONDS    time step (default: the file's \"timeStep\", else 1/60)\n"
		  "  --substeps K    sub-steps per step, 1 to 64 (default: the file's \"subSteps\", else 4)\n"
		  "  --svg OUT.svg   draw the final state; with --every K also OUT-NNNNNN.svg every K steps\n"
		  "  --png DIR       draw PNG frames DIR/frame-NNNNNN.png (step 0, every K steps, the last)\n"
		  "  --every K       frame interval in steps for --png (default 1) and --svg (default: none)\n"
		  "  --size W[xH]    picture size in pixels (default 800 wide, height from the view)\n"
		  "  --draw LIST     what to draw, comma-separated: shapes,joints,contacts,aabbs\n"
		  "                  (default shapes,joints)\n"
		  "  --csv OUT.csv   body states: step,time,body,name,x,y,angle,vx,vy,w,awake per body and step\n"
		  "                  (step 0 is the initial state)\n"
		  "  --quiet         no progress bar and no summary\n"
		  "  --scene NAME    instead of a file, a built-in scene of scenes/world2_scenes with its own\n"
		  "                  per-step code, 60 Hz and sub-steps (default steps: the scene's count)\n",
		  stdout);
#ifdef COLLIDE_TOOL_WORLD2_SCENES
	fputs("                  NAME:", stdout);
	for (int i = 0; i < (int)WORLD2_SCENE_COUNT; ++i)
	{
		printf(" %s", world2SceneInfo((World2SceneId)i)->name);
	}
	fputs("\n", stdout);
#else
	fputs("                  (not in this build: the scene library was not built)\n", stdout);
#endif
	if (!toolHasPng())
	{
		fputs("\nThis build has no PNG support (built without cairo: install libcairo2-dev and rebuild).\n",
			  stdout);
	}
}

static int runUsageError(const char* reason)
{
	fprintf(stderr, "collide run: %s\n%s", reason, s_runUsage);
	return RUN_EXIT_ERROR;
}

static bool parseCount(const char* text, long min, long max, long* out)
{
	if (text == NULL || text[0] == 0)
	{
		return false;
	}
	char* end;
	errno = 0;
	long value = strtol(text, &end, 10);
	if (errno != 0 || *end != 0 || value < min || value > max)
	{
		return false;
	}
	*out = value;
	return true;
}

static bool parseSeconds(const char* text, double* out)
{
	if (text == NULL || text[0] == 0)
	{
		return false;
	}
	char* end;
	errno = 0;
	double value = strtod(text, &end);
	if (errno != 0 || *end != 0 || !(value > 0.0 && value <= 1.0))
	{
		return false;
	}
	*out = value;
	return true;
}

static bool parseDrawList(const char* text, ToolDrawFlags* flags)
{
	ToolDrawFlags f = {false, false, false, false};
	const char* p = text;
	if (p == NULL || *p == 0)
	{
		return false;
	}
	while (*p != 0)
	{
		const char* comma = strchr(p, ',');
		size_t n = comma != NULL ? (size_t)(comma - p) : strlen(p);
		if (n == 6 && strncmp(p, "shapes", n) == 0)
		{
			f.shapes = true;
		}
		else if (n == 6 && strncmp(p, "joints", n) == 0)
		{
			f.joints = true;
		}
		else if (n == 8 && strncmp(p, "contacts", n) == 0)
		{
			f.contacts = true;
		}
		else if (n == 5 && strncmp(p, "aabbs", n) == 0)
		{
			f.aabbs = true;
		}
		else
		{
			return false;
		}
		if (comma == NULL)
		{
			break;
		}
		p = comma + 1;
		if (*p == 0)
		{
			return false;
		}
	}
	*flags = f;
	return true;
}

/* One-way platforms: a contact with a "oneWay" shape counts only while the other shape is above
 * it (the normal from the platform points up) and not sunk into it. */
static bool oneWayPreSolve(cd2ShapeId shapeIdA, cd2ShapeId shapeIdB, const cd2Manifold* manifold,
						   void* context)
{
	(void)context;
	double sign;
	if (cd2Shape_GetUserData(shapeIdA) == &toolOneWayTag)
	{
		sign = 1.0;
	}
	else if (cd2Shape_GetUserData(shapeIdB) == &toolOneWayTag)
	{
		sign = -1.0;
	}
	else
	{
		return true;
	}
	if (sign * (double)manifold->normal.y < 0.7)
	{
		return false;
	}
	for (int i = 0; i < manifold->pointCount; ++i)
	{
		if ((double)manifold->points[i].separation < -0.1)
		{
			return false;
		}
	}
	return true;
}

static double nowSeconds(void)
{
	struct timespec t;
	clock_gettime(CLOCK_MONOTONIC, &t);
	return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static void progressBar(long step, long steps, bool done)
{
	int width = 40;
	int filled = steps > 0 ? (int)((double)width * (double)step / (double)steps) : width;
	char bar[64];
	for (int i = 0; i < width; ++i)
	{
		bar[i] = i < filled ? '#' : '.';
	}
	bar[width] = 0;
	fprintf(stderr, "\r[%s] %ld/%ld steps%s", bar, step, steps, done ? "\n" : "");
	fflush(stderr);
}

static bool writeCsvRows(FILE* csv, const ToolWorld* world, long step, double time, long* rows)
{
	for (int i = 0; i < world->bodyCount; ++i)
	{
		cd2BodyId body = world->bodies[i].id;
		if (!cd2Body_IsValid(body))
		{
			continue; /* destroyed by a built-in scene's own code */
		}
		*rows += 1;
		cd2Vec p = cd2Body_GetPosition(body);
		cd2Vec v = cd2Body_GetLinearVelocity(body);
		double angle = (double)cd2RotGetAngle(cd2Body_GetRotation(body));
		fprintf(csv, "%ld,%.9g,%d,%s,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%d\n", step, time, i,
				world->bodies[i].name, (double)p.x, (double)p.y, angle, (double)v.x, (double)v.y,
				(double)cd2Body_GetAngularVelocity(body), cd2Body_IsAwake(body) ? 1 : 0);
	}
	return !ferror(csv);
}

typedef struct RunOptions
{
	const char* path;
	long steps;
	double dt;
	bool hasDt;
	long subSteps;
	const char* svgPath;
	const char* pngDir;
	const char* csvPath;
	long every;
	bool hasEvery;
	int width, height;
	ToolDrawFlags draw;
	bool quiet;
	const char* sceneName;
	bool hasSteps;
} RunOptions;

/* "out.svg" -> "out-000120.svg" */
static void seriesName(const char* svgPath, long step, char* out, size_t size)
{
	size_t n = strlen(svgPath);
	if (n >= 4 && strcmp(svgPath + n - 4, ".svg") == 0)
	{
		n -= 4;
	}
	snprintf(out, size, "%.*s-%06ld.svg", (int)n, svgPath, step);
}

static bool writeFrames(const RunOptions* o, const ToolWorld* world, const ToolView* view, long step,
						bool last)
{
	char path[4096];
	if (o->pngDir != NULL && (last || step % o->every == 0))
	{
		char reason[256];
		snprintf(path, sizeof path, "%s/frame-%06ld.png", o->pngDir, step);
		if (!toolWriteFramePng(path, world->world, view, o->draw, reason, sizeof reason))
		{
			fprintf(stderr, "%s: %s\n", path, reason);
			return false;
		}
	}
	if (o->svgPath != NULL && o->hasEvery && step % o->every == 0)
	{
		seriesName(o->svgPath, step, path, sizeof path);
		if (!toolWriteFrameSvg(path, world->world, view, o->draw, o->path))
		{
			fprintf(stderr, "%s: cannot write: %s\n", path, strerror(errno));
			return false;
		}
	}
	if (o->svgPath != NULL && last)
	{
		if (!toolWriteFrameSvg(o->svgPath, world->world, view, o->draw, o->path))
		{
			fprintf(stderr, "%s: cannot write: %s\n", o->svgPath, strerror(errno));
			return false;
		}
	}
	return true;
}

/* The world being run: from a file, or a built-in scene (its bodies change as it runs). */
typedef struct RunWorld
{
	ToolWorld file; /* for a built-in scene: world, timeStep, subSteps and a copy of its body list */
#ifdef COLLIDE_TOOL_WORLD2_SCENES
	World2Scene scene;
#endif
	bool builtIn;
	long steps;
} RunWorld;

#ifdef COLLIDE_TOOL_WORLD2_SCENES
/* Copies the scene's body list (rain spawns ragdolls as it runs). */
static bool syncSceneBodies(RunWorld* run)
{
	if (run->scene.bodyCount > run->file.bodyCount || run->file.bodies == NULL)
	{
		size_t count = (size_t)(run->scene.bodyCount > 0 ? run->scene.bodyCount : 1);
		ToolWorldBody* bigger = realloc(run->file.bodies, count * sizeof(ToolWorldBody));
		if (bigger == NULL)
		{
			return false;
		}
		run->file.bodies = bigger;
	}
	for (int i = 0; i < run->scene.bodyCount; ++i)
	{
		run->file.bodies[i].id = run->scene.bodies[i];
		run->file.bodies[i].name[0] = 0;
	}
	run->file.bodyCount = run->scene.bodyCount;
	return true;
}
#endif

/* Loads the file or builds the built-in scene; prints the error and returns false on failure. */
static bool openWorld(const RunOptions* o, RunWorld* run)
{
	memset(run, 0, sizeof *run);
	run->steps = o->steps;
	if (o->sceneName != NULL)
	{
#ifdef COLLIDE_TOOL_WORLD2_SCENES
		World2SceneId id = world2SceneFind(o->sceneName);
		if (id == WORLD2_SCENE_COUNT)
		{
			fprintf(stderr,
					"collide run: no built-in scene is named '%.64s' (collide run --help lists them)\n",
					o->sceneName);
			return false;
		}
		if (!world2SceneCreate(&run->scene, id, 1))
		{
			fprintf(stderr, "collide run: %s: the scene could not be built (out of memory?)\n", o->sceneName);
			return false;
		}
		run->builtIn = true;
		run->file.world = run->scene.world;
		run->file.timeStep = 1.0 / 60.0;
		run->file.subSteps = world2SceneInfo(id)->subStepCount;
		if (!o->hasSteps)
		{
			run->steps = world2SceneInfo(id)->stepCount;
		}
		if (!syncSceneBodies(run))
		{
			world2SceneDestroy(&run->scene);
			free(run->file.bodies);
			fprintf(stderr, "collide run: out of memory\n");
			return false;
		}
		return true;
#else
		fprintf(stderr, "collide run: --scene: this build has no built-in scenes (scenes/world2_scenes)\n");
		return false;
#endif
	}
	ToolError error;
	if (!toolLoadWorld(o->path, &run->file, &error))
	{
		if (error.line > 0)
		{
			fprintf(stderr, "%s:%d: %s\n", o->path, error.line, error.message);
		}
		else
		{
			fprintf(stderr, "%s: %s\n", o->path, error.message);
		}
		return false;
	}
	if (run->file.oneWayCount > 0)
	{
		cd2World_SetPreSolveCallback(run->file.world, oneWayPreSolve, NULL);
	}
	return true;
}

/* One step: the built-in scene's own code and step, or cd2World_Step. */
static bool stepWorld(RunWorld* run, long stepIndex, double dt, int subSteps)
{
#ifdef COLLIDE_TOOL_WORLD2_SCENES
	if (run->builtIn)
	{
		world2SceneStep(&run->scene, (int)stepIndex);
		return syncSceneBodies(run);
	}
#endif
	(void)stepIndex;
	cd2World_Step(run->file.world, (cdReal)dt, subSteps);
	return true;
}

static void closeWorld(RunWorld* run)
{
#ifdef COLLIDE_TOOL_WORLD2_SCENES
	if (run->builtIn)
	{
		world2SceneDestroy(&run->scene);
		free(run->file.bodies);
		memset(run, 0, sizeof *run);
		return;
	}
#endif
	toolFreeWorld(&run->file);
}

static int runScene(const RunOptions* o)
{
	RunWorld run;
	if (!openWorld(o, &run))
	{
		return RUN_EXIT_ERROR;
	}
	ToolWorld* world = &run.file;
	const char* title = o->sceneName != NULL ? o->sceneName : o->path;
	long steps = run.steps;
	double dt = o->hasDt ? o->dt : world->timeStep;
	int subSteps = o->subSteps > 0 ? (int)o->subSteps : world->subSteps;
	int status = 0;
	FILE* csv = NULL;
	long csvRows = 0;
	if (o->csvPath != NULL)
	{
		csv = fopen(o->csvPath, "w");
		if (csv == NULL)
		{
			fprintf(stderr, "%s: cannot write: %s\n", o->csvPath, strerror(errno));
			closeWorld(&run);
			return RUN_EXIT_ERROR;
		}
		fputs("step,time,body,name,x,y,angle,vx,vy,w,awake\n", csv);
	}
	if (o->pngDir != NULL)
	{
		struct stat info;
		if (stat(o->pngDir, &info) != 0 && mkdir(o->pngDir, 0777) != 0)
		{
			fprintf(stderr, "%s: cannot create the folder: %s\n", o->pngDir, strerror(errno));
			status = RUN_EXIT_ERROR;
		}
	}
	cd2BodyId* bodyIds = malloc((size_t)(world->bodyCount > 0 ? world->bodyCount : 1) * sizeof(cd2BodyId));
	if (bodyIds == NULL)
	{
		fprintf(stderr, "collide run: out of memory\n");
		if (csv != NULL)
		{
			fclose(csv);
		}
		closeWorld(&run);
		return RUN_EXIT_ERROR;
	}
	for (int i = 0; i < world->bodyCount; ++i)
	{
		bodyIds[i] = world->bodies[i].id;
	}
	ToolView view = toolMakeView(bodyIds, world->bodyCount, world->hasView ? world->viewMin : NULL,
								 world->hasView ? world->viewMax : NULL, o->width, o->height);
	free(bodyIds);
	RunOptions frameOptions = *o;
	frameOptions.path = title;
	bool progress = !o->quiet && isatty(fileno(stderr));
	if (status == 0 && csv != NULL && !writeCsvRows(csv, world, 0, 0.0, &csvRows))
	{
		status = RUN_EXIT_ERROR;
	}
	if (status == 0 && !writeFrames(&frameOptions, world, &view, 0, steps == 0))
	{
		status = RUN_EXIT_ERROR;
	}
	double stepSeconds = 0.0;
	long contactBegins = 0, sensorBegins = 0, jointsBroken = 0;
	long progressEvery = steps / 100 > 0 ? steps / 100 : 1;
	for (long step = 1; status == 0 && step <= steps; ++step)
	{
		double t0 = nowSeconds();
		if (!stepWorld(&run, step - 1, dt, subSteps))
		{
			fprintf(stderr, "collide run: out of memory\n");
			status = RUN_EXIT_ERROR;
			break;
		}
		stepSeconds += nowSeconds() - t0;
		cd2ContactEvents contactEvents = cd2World_GetContactEvents(world->world);
		cd2SensorEvents sensorEvents = cd2World_GetSensorEvents(world->world);
		contactBegins += contactEvents.beginCount;
		sensorBegins += sensorEvents.beginCount;
		/* Breakable joints (forceThreshold, torqueThreshold): destroyed on their events. */
		cd2JointEvents jointEvents = cd2World_GetJointEvents(world->world);
		for (int e = 0; e < jointEvents.count; ++e)
		{
			cd2DestroyJoint(jointEvents.jointEvents[e].jointId);
		}
		jointsBroken += jointEvents.count;
		if (csv != NULL && !writeCsvRows(csv, world, step, (double)step * dt, &csvRows))
		{
			status = RUN_EXIT_ERROR;
		}
		if (status == 0 && !writeFrames(&frameOptions, world, &view, step, step == steps))
		{
			status = RUN_EXIT_ERROR;
		}
		if (progress && (step % progressEvery == 0 || step == steps))
		{
			progressBar(step, steps, step == steps);
		}
	}
	if (csv != NULL && fclose(csv) != 0 && status == 0)
	{
		fprintf(stderr, "%s: cannot write: %s\n", o->csvPath, strerror(errno));
		status = RUN_EXIT_ERROR;
	}
	if (status == 0 && !o->quiet)
	{
		cd2Counters counters = cd2World_GetCounters(world->world);
		int sleeping = 0, dynamicCount = 0;
		for (int i = 0; i < world->bodyCount; ++i)
		{
			cd2BodyId body = world->bodies[i].id;
			if (cd2Body_IsValid(body) && cd2Body_GetType(body) == CD_DYNAMIC_BODY)
			{
				++dynamicCount;
				sleeping += cd2Body_IsAwake(body) ? 0 : 1;
			}
		}
		printf("scene: %s\n", title);
		printf("steps: %ld of %.6g s, %d sub-steps (%.6g s simulated)\n", steps, dt, subSteps,
			   (double)steps * dt);
		printf("ms/step: %.4f\n", steps > 0 ? 1000.0 * stepSeconds / (double)steps : 0.0);
		printf("bodies: %d (%d dynamic, %d sleeping), shapes: %d, joints: %d\n", counters.bodyCount,
			   dynamicCount, sleeping, counters.shapeCount, counters.jointCount);
		printf("contacts: %d (%d touching)\n", counters.contactCount, counters.touchingContactCount);
		printf("events: %ld contacts began, %ld sensor entries, %ld joints broke\n", contactBegins,
			   sensorBegins, jointsBroken);
		if (o->csvPath != NULL)
		{
			printf("csv: %s (%ld rows)\n", o->csvPath, csvRows);
		}
		if (o->svgPath != NULL)
		{
			printf("svg: %s\n", o->svgPath);
		}
		if (o->pngDir != NULL)
		{
			printf("png: %s/frame-*.png (%dx%d)\n", o->pngDir, view.width, view.height);
		}
		if (fflush(stdout) != 0)
		{
			fprintf(stderr, "collide: cannot write the summary: %s\n", strerror(errno));
			status = RUN_EXIT_ERROR;
		}
	}
	closeWorld(&run);
	return status;
}

int toolRunMain(int argc, char** argv)
{
	RunOptions o;
	memset(&o, 0, sizeof o);
	o.steps = 60;
	o.every = 1;
	o.width = 800;
	o.height = 0;
	o.draw = (ToolDrawFlags){true, true, false, false};
	bool optionsEnded = false;
	for (int i = 1; i < argc; ++i)
	{
		const char* arg = argv[i];
		const char* value = i + 1 < argc ? argv[i + 1] : NULL;
		char reason[160];
		if (!optionsEnded && (strcmp(arg, "--help") == 0 || strcmp(arg, "-h") == 0))
		{
			printRunHelp();
			return 0;
		}
		if (!optionsEnded && strcmp(arg, "--") == 0)
		{
			optionsEnded = true;
			continue;
		}
		if (optionsEnded || arg[0] != '-' || arg[1] == 0)
		{
			if (o.path != NULL)
			{
				snprintf(reason, sizeof reason, "unexpected argument '%.64s'", arg);
				return runUsageError(reason);
			}
			o.path = arg;
			continue;
		}
		if (strcmp(arg, "--quiet") == 0)
		{
			o.quiet = true;
			continue;
		}
		static const char* const withValue[] = {"--steps", "--dt",	  "--substeps", "--svg",
												"--png",   "--every", "--size",		"--draw",
												"--csv",   "--scene", NULL};
		bool known = false;
		for (int k = 0; withValue[k] != NULL; ++k)
		{
			known = known || strcmp(arg, withValue[k]) == 0;
		}
		if (!known)
		{
			snprintf(reason, sizeof reason, "unknown option '%.64s'", arg);
			return runUsageError(reason);
		}
		if (value == NULL || value[0] == 0)
		{
			snprintf(reason, sizeof reason, "%s needs a value", arg);
			return runUsageError(reason);
		}
		++i;
		long number;
		if (strcmp(arg, "--steps") == 0)
		{
			if (!parseCount(value, 0, RUN_MAX_STEPS, &o.steps))
			{
				return runUsageError("--steps must be a whole number from 0 to 100000000");
			}
			o.hasSteps = true;
		}
		else if (strcmp(arg, "--dt") == 0)
		{
			if (!parseSeconds(value, &o.dt))
			{
				return runUsageError("--dt must be a number of seconds in (0, 1]");
			}
			o.hasDt = true;
		}
		else if (strcmp(arg, "--substeps") == 0)
		{
			if (!parseCount(value, 1, TOOL_MAX_SUB_STEPS, &o.subSteps))
			{
				return runUsageError("--substeps must be a whole number from 1 to 64");
			}
		}
		else if (strcmp(arg, "--every") == 0)
		{
			if (!parseCount(value, 1, RUN_MAX_STEPS, &o.every))
			{
				return runUsageError("--every must be a whole number from 1 to 100000000");
			}
			o.hasEvery = true;
		}
		else if (strcmp(arg, "--size") == 0)
		{
			char text[64];
			snprintf(text, sizeof text, "%s", value);
			char* x = strchr(text, 'x');
			if (x != NULL)
			{
				*x = 0;
			}
			if (!parseCount(text, 16, 4096, &number))
			{
				return runUsageError("--size must be W or WxH, each from 16 to 4096 pixels");
			}
			o.width = (int)number;
			if (x != NULL)
			{
				if (!parseCount(x + 1, 16, 4096, &number))
				{
					return runUsageError("--size must be W or WxH, each from 16 to 4096 pixels");
				}
				o.height = (int)number;
			}
		}
		else if (strcmp(arg, "--draw") == 0)
		{
			if (!parseDrawList(value, &o.draw))
			{
				return runUsageError(
					"--draw takes a comma-separated list of shapes, joints, contacts, aabbs");
			}
		}
		else if (strcmp(arg, "--scene") == 0)
		{
			o.sceneName = value;
		}
		else if (strcmp(arg, "--svg") == 0)
		{
			o.svgPath = value;
		}
		else if (strcmp(arg, "--png") == 0)
		{
			if (!toolHasPng())
			{
				fprintf(stderr,
						"collide run: --png: this collide was built without cairo, so it cannot write "
						"PNG files (install libcairo2-dev and rebuild; --svg works without it)\n");
				return RUN_EXIT_ERROR;
			}
			o.pngDir = value;
		}
		else
		{
			o.csvPath = value;
		}
	}
	if (o.sceneName != NULL && o.path != NULL)
	{
		return runUsageError("give a scene file or --scene NAME, not both");
	}
	if (o.sceneName != NULL && (o.hasDt || o.subSteps > 0))
	{
		return runUsageError(
			"a built-in scene (--scene) runs at its own 60 Hz and sub-steps: no --dt or --substeps");
	}
	if (o.path == NULL && o.sceneName == NULL)
	{
		return runUsageError("run needs a scene file (or --scene NAME)");
	}
	return runScene(&o);
}
