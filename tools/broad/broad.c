/* collide tool: `collide broad` runs the broadphase benchmark scene (scenes/broad_scene.h, the
 * same boxes and moves as bench/broad) on the chosen structures through the public broad.h and
 * prints, per structure: build time, time per frame (median and mean), the pair count, time per
 * box query and per ray cast, the structure's memory per proxy, its height and SAH cost. Every
 * structure must report the same pair count in every frame, the reference sweep's count in the
 * last frame, the same query and ray hits, and pass its validator; else exit status 1.
 *
 * A frame, as in the bench: the scene moves its boxes (untimed), then (timed) MoveProxy for each
 * moved box and UpdatePairs, whose reported pairs replace, in a contact list, the pairs with a
 * moved side (scenes/broad_scene.h: BroadPairList); the result is the complete pair set, counted
 * on the tight boxes. Untimed warm-up frames come first: fat boxes reach their steady state only
 * after a dozen frames or so. */
#define _POSIX_C_SOURCE 200809L

#include "broad.h"

#include "broad_scene.h"

#include <collide/broad.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#define BROAD_EXIT_MISMATCH 1
#define BROAD_EXIT_ERROR 2
#define BROAD_MAX_N 10000000
#define BROAD_MAX_FRAMES 100000

const char* const toolBroadUsage =
	"usage: collide broad [--dim 2|3] [--n N] [--structure tree|sap|grid|octree|all]\n"
	"                     [--scene moving|mix] [--frames K] [--warmup W]\n";

typedef struct BroadOptions
{
	int dim;
	int n;
	BroadSceneKind kind;
	int frames;
	int warmup;
	bool use[CD_BROADPHASE_TYPE_COUNT];
} BroadOptions;

static const char* structureName(cdBroadPhaseType type, int dim)
{
	static const char* const names[CD_BROADPHASE_TYPE_COUNT] = {"tree", "sap", "grid", "octree"};
	if (type == CD_BROADPHASE_SPATIAL_TREE && dim == 2)
	{
		return "quadtree";
	}
	return names[type];
}

static double nowSeconds(void)
{
	struct timespec now;
	clock_gettime(CLOCK_MONOTONIC, &now);
	return (double)now.tv_sec + 1e-9 * (double)now.tv_nsec;
}

/* ---- progress line on stderr ------------------------------------------------------------------
 * On a terminal: one line rewritten in place, a few times per second. Otherwise (a log file):
 * a plain line per second, and only once the run has taken more than a second, so that short
 * runs print nothing. Never on stdout, which holds the table. */

typedef struct Progress
{
	bool terminal;
	double start;
	double last;
	bool shown;
} Progress;

static void progressShow(Progress* progress, const char* text)
{
	double now = nowSeconds();
	if (progress->terminal ? now - progress->last < 0.25
						   : (now - progress->start < 1.0 || now - progress->last < 1.0))
	{
		return;
	}
	progress->last = now;
	if (progress->terminal)
	{
		fprintf(stderr, "\r%-72.72s", text);
	}
	else
	{
		fprintf(stderr, "%s\n", text);
	}
	fflush(stderr);
	progress->shown = true;
}

static void progressClear(Progress* progress)
{
	if (progress->terminal && progress->shown)
	{
		fprintf(stderr, "\r%72s\r", "");
		fflush(stderr);
	}
	progress->shown = false;
}

/* ---- one structure, 2D or 3D ------------------------------------------------------------------ */

typedef struct Broad
{
	int dim;
	cd2BroadPhase* bp2;
	cd3BroadPhase* bp3;
	int* proxies; /* per scene box */
} Broad;

static cd2Aabb toAabb2(const BroadBox* box)
{
	cd2Aabb aabb = {{(cdReal)box->min[0], (cdReal)box->min[1]}, {(cdReal)box->max[0], (cdReal)box->max[1]}};
	return aabb;
}

static cd3Aabb toAabb3(const BroadBox* box)
{
	cd3Aabb aabb = {{(cdReal)box->min[0], (cdReal)box->min[1], (cdReal)box->min[2]},
					{(cdReal)box->max[0], (cdReal)box->max[1], (cdReal)box->max[2]}};
	return aabb;
}

static bool broadCreate(Broad* broad, cdBroadPhaseType type, const BroadScene* scene)
{
	memset(broad, 0, sizeof *broad);
	broad->dim = scene->dim;
	broad->proxies = malloc((size_t)scene->n * sizeof(int));
	if (!broad->proxies)
	{
		return false;
	}
	BroadBox world = broadSceneWorldBounds(scene);
	if (scene->dim == 3)
	{
		cd3BroadPhaseDef def = cd3DefaultBroadPhaseDef();
		def.type = type;
		def.bounds = toAabb3(&world);
		def.capacity = scene->n;
		return cd3CreateBroadPhase(&def, &broad->bp3) == CD_OK;
	}
	cd2BroadPhaseDef def = cd2DefaultBroadPhaseDef();
	def.type = type;
	def.bounds = toAabb2(&world);
	def.capacity = scene->n;
	return cd2CreateBroadPhase(&def, &broad->bp2) == CD_OK;
}

static void broadDestroy(Broad* broad)
{
	if (broad->bp3)
	{
		cd3DestroyBroadPhase(broad->bp3);
	}
	if (broad->bp2)
	{
		cd2DestroyBroadPhase(broad->bp2);
	}
	free(broad->proxies);
	memset(broad, 0, sizeof *broad);
}

static bool broadCreateProxy(Broad* broad, const BroadScene* scene, int index)
{
	const BroadBox* box = &scene->boxes[index];
	broad->proxies[index] = broad->dim == 3
								? cd3BroadPhase_CreateProxy(broad->bp3, toAabb3(box), (uint64_t)index)
								: cd2BroadPhase_CreateProxy(broad->bp2, toAabb2(box), (uint64_t)index);
	return broad->proxies[index] != CD_NULL_PROXY;
}

static void addPair(int proxyA, int proxyB, uint64_t userDataA, uint64_t userDataB, void* context)
{
	(void)proxyA;
	(void)proxyB;
	broadPairListAdd(context, (int)userDataA, (int)userDataB);
}

/* Tells the structure the moved boxes and returns the complete pair count (SIZE_MAX when the
 * pair list ran out of memory). */
static size_t broadFrame(Broad* broad, const BroadScene* scene, BroadPairList* pairs)
{
	for (int k = 0; k < scene->movedCount; ++k)
	{
		int index = scene->moved[k];
		const float* d = &scene->displacement[(size_t)index * 3];
		bool changed;
		if (broad->dim == 3)
		{
			cd3Vec displacement = {(cdReal)d[0], (cdReal)d[1], (cdReal)d[2]};
			changed = cd3BroadPhase_MoveProxy(broad->bp3, broad->proxies[index],
											  toAabb3(&scene->boxes[index]), displacement);
		}
		else
		{
			cd2Vec displacement = {(cdReal)d[0], (cdReal)d[1]};
			changed = cd2BroadPhase_MoveProxy(broad->bp2, broad->proxies[index],
											  toAabb2(&scene->boxes[index]), displacement);
		}
		if (changed)
		{
			broadPairListMarkMoved(pairs, index);
		}
	}
	if (broad->dim == 3)
	{
		cd3BroadPhase_UpdatePairs(broad->bp3, addPair, pairs);
	}
	else
	{
		cd2BroadPhase_UpdatePairs(broad->bp2, addPair, pairs);
	}
	return broadPairListEndFrame(pairs, scene->boxes);
}

/* Counts the boxes whose tight box overlaps the query box / meets the ray among those the
 * structure reports (on its fat boxes). */
typedef struct HitCounter
{
	const BroadScene* scene;
	const BroadBox* box;
	const BroadRay* ray;
	size_t hits;
} HitCounter;

static bool countQueryHit(int proxyId, uint64_t userData, void* context)
{
	(void)proxyId;
	HitCounter* counter = context;
	counter->hits += broadBoxesOverlap(&counter->scene->boxes[userData], counter->box) ? 1u : 0u;
	return true;
}

static cdReal countRayHit(cdReal maxFraction, uint64_t userData, HitCounter* counter)
{
	counter->hits += broadRayHitsBox(counter->ray, &counter->scene->boxes[userData]) ? 1u : 0u;
	return maxFraction; /* every box the ray meets, no clipping (as the bench) */
}

static cdReal countRayHit3(cd3Ray ray, cdReal maxFraction, int proxyId, uint64_t userData, void* context)
{
	(void)ray;
	(void)proxyId;
	return countRayHit(maxFraction, userData, context);
}

static cdReal countRayHit2(cd2Ray ray, cdReal maxFraction, int proxyId, uint64_t userData, void* context)
{
	(void)ray;
	(void)proxyId;
	return countRayHit(maxFraction, userData, context);
}

static size_t broadQuery(const Broad* broad, const BroadScene* scene, const BroadBox* box)
{
	HitCounter counter = {scene, box, NULL, 0};
	if (broad->dim == 3)
	{
		cd3BroadPhase_Query(broad->bp3, toAabb3(box), countQueryHit, &counter);
	}
	else
	{
		cd2BroadPhase_Query(broad->bp2, toAabb2(box), countQueryHit, &counter);
	}
	return counter.hits;
}

static size_t broadRayCast(const Broad* broad, const BroadScene* scene, const BroadRay* ray)
{
	HitCounter counter = {scene, NULL, ray, 0};
	if (broad->dim == 3)
	{
		cd3Ray r = {{(cdReal)ray->origin[0], (cdReal)ray->origin[1], (cdReal)ray->origin[2]},
					{(cdReal)ray->translation[0], (cdReal)ray->translation[1], (cdReal)ray->translation[2]}};
		cd3BroadPhase_Raycast(broad->bp3, r, countRayHit3, &counter);
	}
	else
	{
		cd2Ray r = {{(cdReal)ray->origin[0], (cdReal)ray->origin[1]},
					{(cdReal)ray->translation[0], (cdReal)ray->translation[1]}};
		cd2BroadPhase_Raycast(broad->bp2, r, countRayHit2, &counter);
	}
	return counter.hits;
}

/* ---- running and reporting ------------------------------------------------------------------- */

typedef struct StructureResult
{
	double buildMs, medianMs, meanMs, queryUs, rayUs;
	size_t queryHits, rayHits;
	size_t* counts; /* pairs per frame: frame 0 (the initial pairs), warm-up, timed */
	cdBroadPhaseStats stats;
	bool valid;
} StructureResult;

static int compareDoubles(const void* a, const void* b)
{
	double x = *(const double*)a, y = *(const double*)b;
	return (x > y) - (x < y);
}

/* Runs the scene on one structure. Returns false when memory runs out. */
static bool runStructure(const BroadOptions* options, cdBroadPhaseType type, BroadScene* scene,
						 Progress* progress, StructureResult* result)
{
	const char* name = structureName(type, options->dim);
	int totalFrames = options->warmup + options->frames;
	double* frameSeconds = malloc((size_t)options->frames * sizeof(double));
	result->counts = malloc(((size_t)totalFrames + 1) * sizeof(size_t));
	BroadPairList pairs;
	Broad broad;
	memset(&pairs, 0, sizeof pairs);
	memset(&broad, 0, sizeof broad);
	bool ok = frameSeconds && result->counts && broadPairListInit(&pairs, scene->n);
	ok = ok && broadCreate(&broad, type, scene);
	char text[128];

	double buildStart = nowSeconds();
	for (int i = 0; ok && i < scene->n; ++i)
	{
		ok = broadCreateProxy(&broad, scene, i);
		if ((i & 4095) == 0)
		{
			snprintf(text, sizeof text, "[%s] building: %d of %d proxies", name, i, scene->n);
			progressShow(progress, text);
		}
	}
	result->buildMs = 1e3 * (nowSeconds() - buildStart);
	if (ok)
	{
		result->counts[0] = broadFrame(&broad, scene, &pairs);
	}
	double timedSeconds = 0.0;
	for (int frame = 1; ok && frame <= totalFrames; ++frame)
	{
		broadSceneStep(scene);
		double start = nowSeconds();
		result->counts[frame] = broadFrame(&broad, scene, &pairs);
		double seconds = nowSeconds() - start;
		if (frame > options->warmup)
		{
			frameSeconds[frame - options->warmup - 1] = seconds;
			timedSeconds += seconds;
		}
		ok = result->counts[frame] != SIZE_MAX;
		snprintf(text, sizeof text, "[%s] frame %d/%d (%d warm-up), %.3g ms", name, frame, totalFrames,
				 options->warmup, 1e3 * seconds);
		progressShow(progress, text);
	}
	if (ok)
	{
		qsort(frameSeconds, (size_t)options->frames, sizeof(double), compareDoubles);
		size_t mid = (size_t)options->frames / 2;
		double median =
			options->frames % 2 ? frameSeconds[mid] : 0.5 * (frameSeconds[mid - 1] + frameSeconds[mid]);
		result->medianMs = 1e3 * median;
		result->meanMs = 1e3 * timedSeconds / options->frames;

		snprintf(text, sizeof text, "[%s] %d box queries and ray casts", name, scene->queryCount);
		progressShow(progress, text);
		double start = nowSeconds();
		for (int q = 0; q < scene->queryCount; ++q)
		{
			result->queryHits += broadQuery(&broad, scene, &scene->queries[q]);
		}
		double middle = nowSeconds();
		for (int q = 0; q < scene->queryCount; ++q)
		{
			result->rayHits += broadRayCast(&broad, scene, &scene->rays[q]);
		}
		double end = nowSeconds();
		result->queryUs = 1e6 * (middle - start) / scene->queryCount;
		result->rayUs = 1e6 * (end - middle) / scene->queryCount;

		snprintf(text, sizeof text, "[%s] validating", name);
		progressShow(progress, text);
		result->stats =
			broad.dim == 3 ? cd3BroadPhase_GetStats(broad.bp3) : cd2BroadPhase_GetStats(broad.bp2);
		result->valid =
			broad.dim == 3 ? cd3BroadPhase_Validate(broad.bp3) : cd2BroadPhase_Validate(broad.bp2);
	}
	broadDestroy(&broad);
	broadPairListFree(&pairs);
	free(frameSeconds);
	progressClear(progress);
	return ok;
}

static void printRow(const char* name, const StructureResult* result, size_t lastPairs)
{
	char height[16] = "-", sah[32] = "-";
	if (result->stats.height > 0)
	{
		snprintf(height, sizeof height, "%d", result->stats.height);
	}
	if (result->stats.sahCost > 0.0)
	{
		snprintf(sah, sizeof sah, "%.1f", result->stats.sahCost);
	}
	double bytesPerProxy = result->stats.proxyCount > 0
							   ? (double)result->stats.memoryBytes / (double)result->stats.proxyCount
							   : 0.0;
	printf("%-10s %10.2f %10.3f %10.3f %10zu %9.2f %9.2f %12.0f %7s %9s %6s\n", name, result->buildMs,
		   result->medianMs, result->meanMs, lastPairs, result->queryUs, result->rayUs, bytesPerProxy, height,
		   sah, result->valid ? "yes" : "NO");
	fflush(stdout);
}

/* Compares one structure with the first one run; prints what differs. */
static bool sameAsFirst(const char* name, const StructureResult* result, const char* firstName,
						const StructureResult* first, int totalFrames)
{
	bool same = true;
	for (int frame = 0; frame <= totalFrames; ++frame)
	{
		if (result->counts[frame] != first->counts[frame])
		{
			printf("mismatch: frame %d: %s reports %zu pairs, %s %zu\n", frame, name, result->counts[frame],
				   firstName, first->counts[frame]);
			same = false;
			break;
		}
	}
	if (result->queryHits != first->queryHits || result->rayHits != first->rayHits)
	{
		printf("mismatch: %s counts %zu query hits and %zu ray hits, %s %zu and %zu\n", name,
			   result->queryHits, result->rayHits, firstName, first->queryHits, first->rayHits);
		same = false;
	}
	return same;
}

static int runBroad(const BroadOptions* options)
{
	int totalFrames = options->warmup + options->frames;
	printf("collide broad: %dD, N = %d, scene %s, %d timed frames after %d warm-up (cdReal = %s)\n",
		   options->dim, options->n, broadSceneKindName(options->kind), options->frames, options->warmup,
		   cdGetRealIsDouble() ? "double" : "float");
	printf("frame: move the proxies of the moved boxes + complete set of overlapping pairs (median and\n"
		   "mean ms); pairs: in the last frame; query/ray: us per call, mean over %d random boxes/rays;\n"
		   "bytes/proxy: the structure's own memory (stats) per proxy; height and SAH cost where "
		   "meaningful.\n\n",
		   options->n < 50 ? 50 : (options->n > 1000 ? 1000 : options->n));
	printf("%-10s %10s %10s %10s %10s %9s %9s %12s %7s %9s %6s\n", "structure", "build ms", "median ms",
		   "mean ms", "pairs", "query us", "ray us", "bytes/proxy", "height", "SAH cost", "valid");
	fflush(stdout);

	Progress progress = {isatty(fileno(stderr)) != 0, nowSeconds(), 0.0, false};
	StructureResult results[CD_BROADPHASE_TYPE_COUNT];
	memset(results, 0, sizeof results);
	int first = -1;
	bool consistent = true, allValid = true;
	size_t reference = 0;
	int status = 0;
	char names[128] = "";
	for (int t = 0; t < CD_BROADPHASE_TYPE_COUNT && status == 0; ++t)
	{
		if (!options->use[t])
		{
			continue;
		}
		cdBroadPhaseType type = (cdBroadPhaseType)t;
		const char* name = structureName(type, options->dim);
		BroadScene scene;
		if (!broadSceneInit(&scene, options->dim, options->n, options->kind,
							broadSceneSeed(options->dim, options->n)) ||
			!runStructure(options, type, &scene, &progress, &results[t]))
		{
			fprintf(stderr, "collide: out of memory (%s, N = %d)\n", name, options->n);
			status = BROAD_EXIT_ERROR;
		}
		else
		{
			if (first < 0)
			{
				first = t;
				/* Every structure runs the same deterministic scene: the last frame's boxes are the
				 * same for all. */
				reference = broadSceneCountPairs(&scene);
			}
			printRow(name, &results[t], results[t].counts[totalFrames]);
			if (t != first)
			{
				consistent =
					sameAsFirst(name, &results[t], structureName((cdBroadPhaseType)first, options->dim),
								&results[first], totalFrames) &&
					consistent;
			}
			allValid = allValid && results[t].valid;
			snprintf(names + strlen(names), sizeof names - strlen(names), "%s%s", names[0] ? ", " : "", name);
		}
		broadSceneFree(&scene);
	}
	if (status == 0)
	{
		size_t last = results[first].counts[totalFrames];
		if (reference != last)
		{
			printf("mismatch: the last frame has %zu overlapping pairs (reference sweep), %s reports %zu\n",
				   reference, structureName((cdBroadPhaseType)first, options->dim), last);
			consistent = false;
		}
		if (consistent && allValid)
		{
			printf("\ncheck: OK: %s: the same pair count in all %d frames (%zu in the last, as the reference "
				   "sweep), the same query hits (%zu) and ray hits (%zu), structures valid\n",
				   names, totalFrames + 1, last, results[first].queryHits, results[first].rayHits);
		}
		else
		{
			printf("\ncheck: FAILED: %s\n",
				   consistent ? "a structure failed its validator" : "counts disagree");
			status = BROAD_EXIT_MISMATCH;
		}
	}
	for (int t = 0; t < CD_BROADPHASE_TYPE_COUNT; ++t)
	{
		free(results[t].counts);
	}
	return status;
}

/* ---- arguments -------------------------------------------------------------------------------- */

static int broadUsageError(const char* reason)
{
	fprintf(stderr, "collide: %s\n%s", reason, toolBroadUsage);
	return BROAD_EXIT_ERROR;
}

/* Whole numbers in [min, max]; "1e5" is accepted. */
static bool parseCount(const char* text, int min, int max, int* out)
{
	char* end = NULL;
	double value = strtod(text, &end);
	if (end == text || *end != 0 || !(value >= (double)min && value <= (double)max) || value != floor(value))
	{
		return false;
	}
	*out = (int)value;
	return true;
}

static bool parseStructures(const char* text, bool* use)
{
	memset(use, 0, CD_BROADPHASE_TYPE_COUNT * sizeof(bool));
	const char* start = text;
	for (;;)
	{
		size_t length = strcspn(start, ",");
		if (length == 3 && strncmp(start, "all", 3) == 0)
		{
			for (int t = 0; t < CD_BROADPHASE_TYPE_COUNT; ++t)
			{
				use[t] = true;
			}
		}
		else if (length == 4 && strncmp(start, "tree", 4) == 0)
		{
			use[CD_BROADPHASE_TREE] = true;
		}
		else if (length == 3 && strncmp(start, "sap", 3) == 0)
		{
			use[CD_BROADPHASE_SAP] = true;
		}
		else if (length == 4 && strncmp(start, "grid", 4) == 0)
		{
			use[CD_BROADPHASE_GRID] = true;
		}
		else if ((length == 6 && strncmp(start, "octree", 6) == 0) ||
				 (length == 8 && strncmp(start, "quadtree", 8) == 0))
		{
			use[CD_BROADPHASE_SPATIAL_TREE] = true;
		}
		else
		{
			return false;
		}
		if (start[length] == 0)
		{
			return true;
		}
		start += length + 1;
	}
}

static void printBroadHelp(void)
{
	fputs(toolBroadUsage, stdout);
	fputs("\n"
		  "Runs the broadphase benchmark scene (the one bench/broad measures against Bullet, FCL and\n"
		  "Box2D; docs/BROADPHASE.md) on collide's structures and prints one row per structure.\n"
		  "\n"
		  "  --dim 2|3         dimension (default 3)\n"
		  "  --n N             number of boxes, 1 to 10000000 (default 10000; 1e5 is accepted)\n"
		  "  --structure S     tree, sap, grid, octree (quadtree in 2D), all, or a comma-separated\n"
		  "                    list (default all)\n"
		  "  --scene moving    every box moves every frame (default)\n"
		  "  --scene mix       90% of the boxes still, 9% moving, 1% teleporting every frame\n"
		  "  --frames K        timed frames (default 10)\n"
		  "  --warmup W        untimed frames before them (default 10)\n"
		  "\n"
		  "A progress line goes to stderr on a terminal, or when a run takes more than a second.\n"
		  "Exit status: 0 when every structure reports the same pairs (and the reference sweep's\n"
		  "count), query and ray hits, and passes its validator; 1 when not; 2 on a usage error.\n",
		  stdout);
}

int toolBroadMain(int argc, char** argv)
{
	BroadOptions options = {3, 10000, BROAD_SCENE_MOVING, 10, 10, {true, true, true, true}};
	for (int i = 1; i < argc; ++i)
	{
		const char* arg = argv[i];
		if (strcmp(arg, "--help") == 0 || strcmp(arg, "-h") == 0)
		{
			printBroadHelp();
			return 0;
		}
		const char* const valued[] = {"--dim", "--n", "--structure", "--scene", "--frames", "--warmup"};
		int option = -1;
		for (int k = 0; k < (int)(sizeof valued / sizeof valued[0]); ++k)
		{
			option = strcmp(arg, valued[k]) == 0 ? k : option;
		}
		char reason[160];
		if (option < 0)
		{
			snprintf(reason, sizeof reason, "%s '%.64s'",
					 arg[0] == '-' ? "unknown option" : "unexpected argument", arg);
			return broadUsageError(reason);
		}
		if (i + 1 >= argc)
		{
			snprintf(reason, sizeof reason, "%s needs a value", arg);
			return broadUsageError(reason);
		}
		const char* value = argv[++i];
		bool ok = true;
		switch (option)
		{
			case 0:
				ok = parseCount(value, 2, 3, &options.dim);
				break;
			case 1:
				ok = parseCount(value, 1, BROAD_MAX_N, &options.n);
				break;
			case 2:
				ok = parseStructures(value, options.use);
				break;
			case 3:
				ok = strcmp(value, "moving") == 0 || strcmp(value, "mix") == 0;
				options.kind = strcmp(value, "mix") == 0 ? BROAD_SCENE_MIX : BROAD_SCENE_MOVING;
				break;
			case 4:
				ok = parseCount(value, 1, BROAD_MAX_FRAMES, &options.frames);
				break;
			default:
				ok = parseCount(value, 0, BROAD_MAX_FRAMES, &options.warmup);
				break;
		}
		if (!ok)
		{
			snprintf(reason, sizeof reason, "bad value for %s: '%.64s'", arg, value);
			return broadUsageError(reason);
		}
	}
	return runBroad(&options);
}
