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
	"                  [--png DIR] [--every K] [--size W[xH]] [--draw LIST] [--csv OUT.csv] [--quiet]\n";

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
		  "  --quiet         no progress bar and no summary\n",
		  stdout);
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

static bool writeCsvRows(FILE* csv, const ToolWorld* world, long step, double time)
{
	for (int i = 0; i < world->bodyCount; ++i)
	{
		cd2BodyId body = world->bodies[i].id;
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

static int runScene(const RunOptions* o)
{
	ToolWorld world;
	ToolError error;
	if (!toolLoadWorld(o->path, &world, &error))
	{
		if (error.line > 0)
		{
			fprintf(stderr, "%s:%d: %s\n", o->path, error.line, error.message);
		}
		else
		{
			fprintf(stderr, "%s: %s\n", o->path, error.message);
		}
		return RUN_EXIT_ERROR;
	}
	double dt = o->hasDt ? o->dt : world.timeStep;
	int subSteps = o->subSteps > 0 ? (int)o->subSteps : world.subSteps;
	if (world.oneWayCount > 0)
	{
		cd2World_SetPreSolveCallback(world.world, oneWayPreSolve, NULL);
	}
	int status = 0;
	FILE* csv = NULL;
	if (o->csvPath != NULL)
	{
		csv = fopen(o->csvPath, "w");
		if (csv == NULL)
		{
			fprintf(stderr, "%s: cannot write: %s\n", o->csvPath, strerror(errno));
			toolFreeWorld(&world);
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
	ToolView view = toolMakeView(world.world, world.hasView ? world.viewMin : NULL,
								 world.hasView ? world.viewMax : NULL, o->width, o->height);
	bool progress = !o->quiet && isatty(fileno(stderr));
	if (status == 0 && csv != NULL && !writeCsvRows(csv, &world, 0, 0.0))
	{
		status = RUN_EXIT_ERROR;
	}
	if (status == 0 && !writeFrames(o, &world, &view, 0, o->steps == 0))
	{
		status = RUN_EXIT_ERROR;
	}
	double stepSeconds = 0.0;
	long contactBegins = 0, sensorBegins = 0;
	long step = 0;
	long progressEvery = o->steps / 100 > 0 ? o->steps / 100 : 1;
	for (step = 1; status == 0 && step <= o->steps; ++step)
	{
		double t0 = nowSeconds();
		cd2World_Step(world.world, (cdReal)dt, subSteps);
		stepSeconds += nowSeconds() - t0;
		cd2ContactEvents contactEvents = cd2World_GetContactEvents(world.world);
		cd2SensorEvents sensorEvents = cd2World_GetSensorEvents(world.world);
		contactBegins += contactEvents.beginCount;
		sensorBegins += sensorEvents.beginCount;
		if (csv != NULL && !writeCsvRows(csv, &world, step, (double)step * dt))
		{
			status = RUN_EXIT_ERROR;
		}
		if (status == 0 && !writeFrames(o, &world, &view, step, step == o->steps))
		{
			status = RUN_EXIT_ERROR;
		}
		if (progress && (step % progressEvery == 0 || step == o->steps))
		{
			progressBar(step, o->steps, step == o->steps);
		}
	}
	if (csv != NULL)
	{
		if (fclose(csv) != 0 && status == 0)
		{
			fprintf(stderr, "%s: cannot write: %s\n", o->csvPath, strerror(errno));
			status = RUN_EXIT_ERROR;
		}
		else if (status != 0 && errno != 0)
		{
			/* reported where it happened */
		}
	}
	if (status == 0 && !o->quiet)
	{
		cd2Counters counters = cd2World_GetCounters(world.world);
		int sleeping = 0, dynamicCount = 0;
		for (int i = 0; i < world.bodyCount; ++i)
		{
			if (cd2Body_GetType(world.bodies[i].id) == CD_DYNAMIC_BODY)
			{
				++dynamicCount;
				sleeping += cd2Body_IsAwake(world.bodies[i].id) ? 0 : 1;
			}
		}
		printf("scene: %s\n", o->path);
		printf("steps: %ld of %.6g s, %d sub-steps (%.6g s simulated)\n", o->steps, dt, subSteps,
			   (double)o->steps * dt);
		printf("ms/step: %.4f\n", o->steps > 0 ? 1000.0 * stepSeconds / (double)o->steps : 0.0);
		printf("bodies: %d (%d dynamic, %d sleeping), shapes: %d, joints: %d\n", counters.bodyCount,
			   dynamicCount, sleeping, counters.shapeCount, counters.jointCount);
		printf("contacts: %d (%d touching)\n", counters.contactCount, counters.touchingContactCount);
		printf("events: %ld contacts began, %ld sensor entries\n", contactBegins, sensorBegins);
		if (o->csvPath != NULL)
		{
			printf("csv: %s (%ld rows)\n", o->csvPath, (long)world.bodyCount * (o->steps + 1));
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
	toolFreeWorld(&world);
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
		static const char* const withValue[] = {"--steps", "--dt",	 "--substeps", "--svg", "--png",
												"--every", "--size", "--draw",	   "--csv", NULL};
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
	if (o.path == NULL)
	{
		return runUsageError("run needs a scene file");
	}
	return runScene(&o);
}
