/* collide_bench: prints a table of nanoseconds per query for every primitive query of collide.
 *
 * Method, per row: generate a batch of random valid inputs (4096, with the second shape placed
 * so that about half the answers are true, which keeps branches realistic), run the function
 * over the batch once to warm up and to size the repetition count, then time 7 runs of
 * `reps` passes over the batch with CLOCK_MONOTONIC. The table shows the median and the fastest
 * run in ns per call, and the fraction of calls that answered true.
 *
 * Usage: collide_bench [--quick] [--filter SUBSTRING] [--runs N] [--csv] */
#define _POSIX_C_SOURCE 200809L

#include "bench.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#ifndef BENCH_COMPILER
#define BENCH_COMPILER "unknown compiler"
#endif
#ifndef BENCH_BUILD_TYPE
#define BENCH_BUILD_TYPE "unknown"
#endif
#ifndef BENCH_LIBRARY_FLAGS
#define BENCH_LIBRARY_FLAGS ""
#endif

#define BENCH_MAX_RUNS 15
#define BENCH_MAX_IMPLS 8
#define BENCH_SEED 0x5EEDC011DEull

typedef struct BenchOptions
{
	bool quick;
	bool csv;
	const char* filter;
	int runs;
	int batchCount;
	double secondsPerRun;
} BenchOptions;

typedef struct BenchResult
{
	double medianNs;
	double minNs;
	double trueFraction;
} BenchResult;

/* Every answer of every run ends up here, so no call can be optimized away. */
static volatile int64_t g_sink;

static double NowSeconds(void)
{
	struct timespec now;
	clock_gettime(CLOCK_MONOTONIC, &now);
	return (double)now.tv_sec + 1e-9 * (double)now.tv_nsec;
}

static bool HasSpread(const BenchCase* benchCase)
{
	return benchCase->input != BENCH_POINT_CLOUD2 && benchCase->input != BENCH_BOX2;
}

static double TrueFractionAt(BenchBatch* batch, const BenchCase* benchCase, int count, double spread)
{
	BenchGenerate(batch, benchCase, count, spread, BENCH_SEED ^ 0xCA11B8A7Eull);
	int64_t trueCount = benchCase->run(batch, 1);
	g_sink += trueCount;
	return (double)trueCount / (double)batch->count;
}

/* The spread at which about half the answers are true, found by bisection on a log scale; the
 * fraction falls as the spread grows. Pairs that are (almost) always or never true, such as two
 * half-spaces or two segments in 3D, end at one end of the range. */
static double CalibrateSpread(BenchBatch* batch, const BenchCase* benchCase, const BenchOptions* options)
{
	double lower = 0.01, upper = 100.0;
	int count = cdMinInt(options->batchCount, 1024);
	if (!HasSpread(benchCase) || TrueFractionAt(batch, benchCase, count, lower) <= 0.5)
	{
		return lower;
	}
	if (TrueFractionAt(batch, benchCase, count, upper) >= 0.5)
	{
		return upper;
	}
	int steps = options->quick ? 4 : 12;
	for (int step = 0; step < steps; ++step)
	{
		double middle = sqrt(lower * upper);
		if (TrueFractionAt(batch, benchCase, count, middle) > 0.5)
		{
			lower = middle;
		}
		else
		{
			upper = middle;
		}
	}
	return sqrt(lower * upper);
}

static int CompareDoubles(const void* a, const void* b)
{
	double x = *(const double*)a, y = *(const double*)b;
	return (x > y) - (x < y);
}

static BenchResult Measure(BenchBatch* batch, const BenchCase* benchCase, const BenchOptions* options)
{
	double spread = CalibrateSpread(batch, benchCase, options);
	BenchGenerate(batch, benchCase, options->batchCount, spread, BENCH_SEED);

	double start = NowSeconds();
	int64_t trueCount = benchCase->run(batch, 1);
	double passSeconds = NowSeconds() - start;
	g_sink += trueCount;

	int reps = 1;
	if (!options->quick)
	{
		double wanted = options->secondsPerRun / (passSeconds > 1e-7 ? passSeconds : 1e-7);
		reps = wanted < 1.0 ? 1 : (wanted > 1e6 ? 1000000 : (int)wanted);
	}

	double nsPerCall[BENCH_MAX_RUNS];
	for (int run = 0; run < options->runs; ++run)
	{
		start = NowSeconds();
		g_sink += benchCase->run(batch, reps);
		double seconds = NowSeconds() - start;
		nsPerCall[run] = 1e9 * seconds / ((double)reps * (double)batch->count);
	}
	qsort(nsPerCall, (size_t)options->runs, sizeof(double), CompareDoubles);

	BenchResult result;
	result.medianNs = options->runs % 2 == 1
						  ? nsPerCall[options->runs / 2]
						  : 0.5 * (nsPerCall[options->runs / 2 - 1] + nsPerCall[options->runs / 2]);
	result.minNs = nsPerCall[0];
	result.trueFraction = (double)trueCount / (double)batch->count;
	return result;
}

/* ---- the machine ---------------------------------------------------------------------------- */

static void ReadCpu(char* model, size_t modelSize, int* logicalCpus)
{
	snprintf(model, modelSize, "unknown CPU");
	*logicalCpus = 0;
	FILE* file = fopen("/proc/cpuinfo", "r");
	if (file == NULL)
	{
		return;
	}
	char line[512];
	bool haveModel = false;
	while (fgets(line, sizeof(line), file) != NULL)
	{
		if (strncmp(line, "processor", 9) == 0)
		{
			++*logicalCpus;
		}
		else if (!haveModel && strncmp(line, "model name", 10) == 0)
		{
			const char* value = strchr(line, ':');
			if (value != NULL)
			{
				value += value[1] == ' ' ? 2 : 1;
				snprintf(model, modelSize, "%s", value);
				model[strcspn(model, "\n")] = '\0';
				haveModel = true;
			}
		}
	}
	fclose(file);
}

static void PrintHeader(const BenchOptions* options)
{
	char cpu[256];
	int logicalCpus;
	ReadCpu(cpu, sizeof(cpu), &logicalCpus);
	cdVersion version = cdGetVersion();
	const char* prefix = options->csv ? "# " : "";
	printf("%scollide_bench: collide %d.%d.%d, cdReal = %s\n", prefix, version.major, version.minor,
		   version.patch, cdGetRealIsDouble() ? "double" : "float");
	printf("%scompiler: %s; build type %s; library flags: %s\n", prefix, BENCH_COMPILER, BENCH_BUILD_TYPE,
		   BENCH_LIBRARY_FLAGS);
	printf("%sCPU: %s (%d logical CPUs)\n", prefix, cpu, logicalCpus);
	printf("%smethod: batches of %d random inputs, %d timed runs per row%s; ns/op is the median run,\n",
		   prefix, options->batchCount, options->runs, options->quick ? " of one pass" : "");
	printf("%smin the fastest; 'true' is the fraction of overlaps, hits, points inside, zero distances or\n",
		   prefix);
	printf("%sbuilder successes.\n", prefix);
	if (options->quick)
	{
		printf("%s--quick: smoke test only, the figures below are not measurements.\n", prefix);
	}
}

/* ---- the table ------------------------------------------------------------------------------ */

typedef struct BenchTable
{
	const BenchCase* cases[512];
	int caseCount;
	const char* peers[BENCH_MAX_IMPLS];
	int peerCount;
} BenchTable;

static bool Matches(const BenchCase* benchCase, const char* filter)
{
	return filter == NULL || strstr(benchCase->name, filter) != NULL ||
		   strstr(benchCase->group, filter) != NULL;
}

static void AddCases(BenchTable* table, const BenchCase* cases, int count, const char* filter)
{
	for (int i = 0; i < count; ++i)
	{
		const BenchCase* benchCase = cases + i;
		if (!Matches(benchCase, filter) ||
			table->caseCount == (int)(sizeof(table->cases) / sizeof(table->cases[0])))
		{
			continue;
		}
		table->cases[table->caseCount++] = benchCase;
		if (strcmp(benchCase->impl, BENCH_IMPL_COLLIDE) == 0)
		{
			continue;
		}
		bool known = false;
		for (int p = 0; p < table->peerCount; ++p)
		{
			known = known || strcmp(table->peers[p], benchCase->impl) == 0;
		}
		if (!known && table->peerCount < BENCH_MAX_IMPLS)
		{
			table->peers[table->peerCount++] = benchCase->impl;
		}
	}
}

static void PrintColumnTitles(const BenchTable* table)
{
	printf("  %-40s %9s %9s %6s", "function", "ns/op", "min", "true");
	for (int p = 0; p < table->peerCount; ++p)
	{
		printf(" %12s", table->peers[p]);
	}
	printf("\n");
}

/* Measures one row: collide's case and every peer case of the same name, then prints it. */
static void RunRow(const BenchTable* table, int first, bool* done, BenchBatch* batch,
				   const BenchOptions* options)
{
	const char* name = table->cases[first]->name;
	bool haveCollide = false;
	BenchResult collide = {0.0, 0.0, 0.0};
	double peerNs[BENCH_MAX_IMPLS];
	for (int p = 0; p < BENCH_MAX_IMPLS; ++p)
	{
		peerNs[p] = -1.0;
	}
	for (int i = first; i < table->caseCount; ++i)
	{
		const BenchCase* benchCase = table->cases[i];
		if (done[i] || strcmp(benchCase->name, name) != 0)
		{
			continue;
		}
		done[i] = true;
		BenchResult result = Measure(batch, benchCase, options);
		if (options->csv)
		{
			printf("%s,%s,%s,%.3f,%.3f,%.4f\n", benchCase->group, name, benchCase->impl, result.medianNs,
				   result.minNs, result.trueFraction);
		}
		if (strcmp(benchCase->impl, BENCH_IMPL_COLLIDE) == 0)
		{
			haveCollide = true;
			collide = result;
			continue;
		}
		for (int p = 0; p < table->peerCount; ++p)
		{
			if (strcmp(table->peers[p], benchCase->impl) == 0)
			{
				peerNs[p] = result.medianNs;
			}
		}
	}
	if (options->csv)
	{
		return;
	}
	if (haveCollide)
	{
		printf("  %-40s %9.1f %9.1f %6.2f", name, collide.medianNs, collide.minNs, collide.trueFraction);
	}
	else
	{
		printf("  %-40s %9s %9s %6s", name, "-", "-", "-");
	}
	for (int p = 0; p < table->peerCount; ++p)
	{
		if (peerNs[p] >= 0.0)
		{
			printf(" %12.1f", peerNs[p]);
		}
		else
		{
			printf(" %12s", "-");
		}
	}
	printf("\n");
	fflush(stdout);
}

static void Usage(FILE* stream)
{
	fprintf(stream, "usage: collide_bench [--quick] [--filter SUBSTRING] [--runs N] [--csv]\n"
					"  --quick             one short pass per function: a smoke test, not a measurement\n"
					"  --filter SUBSTRING  only the rows whose function or section contains SUBSTRING\n"
					"  --runs N            timed runs per row, 1..15 (default 7); the median is reported\n"
					"  --csv               print group,function,impl,median_ns,min_ns,true_fraction\n");
}

static bool ParseOptions(int argc, char** argv, BenchOptions* options)
{
	options->quick = false;
	options->csv = false;
	options->filter = NULL;
	options->runs = 7;
	options->batchCount = BENCH_BATCH_MAX;
	options->secondsPerRun = 0.04;
	for (int i = 1; i < argc; ++i)
	{
		if (strcmp(argv[i], "--quick") == 0)
		{
			options->quick = true;
		}
		else if (strcmp(argv[i], "--csv") == 0)
		{
			options->csv = true;
		}
		else if (strcmp(argv[i], "--filter") == 0 && i + 1 < argc)
		{
			options->filter = argv[++i];
		}
		else if (strcmp(argv[i], "--runs") == 0 && i + 1 < argc)
		{
			options->runs = atoi(argv[++i]);
			if (options->runs < 1 || options->runs > BENCH_MAX_RUNS)
			{
				fprintf(stderr, "collide_bench: --runs takes 1..%d\n", BENCH_MAX_RUNS);
				return false;
			}
		}
		else if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0)
		{
			Usage(stdout);
			exit(0);
		}
		else
		{
			fprintf(stderr, "collide_bench: unknown argument '%s'\n", argv[i]);
			Usage(stderr);
			return false;
		}
	}
	if (options->quick)
	{
		options->batchCount = 128;
		options->runs = cdMinInt(options->runs, 3);
	}
	return true;
}

int main(int argc, char** argv)
{
	BenchOptions options;
	if (!ParseOptions(argc, argv, &options))
	{
		return 2;
	}
	if (cdGetRealIsDouble() != CD_DOUBLE)
	{
		fprintf(stderr, "collide_bench: compiled with CD_DOUBLE=%d but the library has cdReal = %s\n",
				CD_DOUBLE, cdGetRealIsDouble() ? "double" : "float");
		return 1;
	}

	static BenchTable table;
	AddCases(&table, g_bench3Cases, g_bench3CaseCount, options.filter);
	AddCases(&table, g_bench2Cases, g_bench2CaseCount, options.filter);
	if (table.caseCount == 0)
	{
		fprintf(stderr, "collide_bench: no function matches '%s'\n", options.filter);
		return 1;
	}

	PrintHeader(&options);
	if (options.csv)
	{
		printf("group,function,impl,median_ns,min_ns,true_fraction\n");
	}

	BenchBatch* batch = BenchCreateBatch();
	static bool done[sizeof(table.cases) / sizeof(table.cases[0])];
	const char* group = NULL;
	double start = NowSeconds();
	for (int i = 0; i < table.caseCount; ++i)
	{
		if (done[i])
		{
			continue;
		}
		if (!options.csv && (group == NULL || strcmp(group, table.cases[i]->group) != 0))
		{
			group = table.cases[i]->group;
			printf("\n%s\n", group);
			PrintColumnTitles(&table);
		}
		RunRow(&table, i, done, batch, &options);
	}
	BenchDestroyBatch(batch);
	printf("%s%d functions in %.1f s\n", options.csv ? "# " : "\n", table.caseCount, NowSeconds() - start);
	return 0;
}
