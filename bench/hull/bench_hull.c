/* Hull benchmark: ns per cd3ComputeHull on random points on a sphere (32, 256, 4096 points: the
 * hard case, every point a vertex) and in a ball (most points inside), and ns per GJK distance
 * between two 32-vertex hulls in random poses (half of the pairs overlapping). Prints a table;
 * `--quick` runs every row once (smoke test, no timing claims). */
#define _POSIX_C_SOURCE 199309L
#include "collide/collide.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static uint64_t g_state = 0x8a5cd789635d2dffull;

static double Uniform(double lower, double upper)
{
	g_state += 0x9E3779B97F4A7C15ull;
	uint64_t z = g_state;
	z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
	z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
	z ^= z >> 31;
	return lower + (upper - lower) * (double)(z >> 11) * (1.0 / 9007199254740992.0);
}

static cd3Vec RandomPoint(bool onSphere)
{
	double x, y, z, n;
	do
	{
		x = Uniform(-1.0, 1.0);
		y = Uniform(-1.0, 1.0);
		z = Uniform(-1.0, 1.0);
		n = sqrt(x * x + y * y + z * z);
	} while (n > 1.0 || n < 1e-3);
	double s = onSphere ? 1.0 / n : 1.0;
	return cd3MakeVec((cdReal)(x * s), (cdReal)(y * s), (cdReal)(z * s));
}

static cd3Quat RandomQuat(void)
{
	cd3Vec axis = RandomPoint(true);
	return cd3MakeQuatAxisAngle(axis, (cdReal)Uniform(0.0, 6.283185307179586));
}

static double Now(void)
{
	struct timespec t;
	clock_gettime(CLOCK_MONOTONIC, &t);
	return (double)t.tv_sec * 1e9 + (double)t.tv_nsec;
}

static volatile double g_sink;

static void BenchBuild(int count, bool onSphere, bool quick)
{
	const int clouds = 16;
	cd3Vec* points = (cd3Vec*)malloc((size_t)(clouds * count) * sizeof(cd3Vec));
	for (int i = 0; i < clouds * count; ++i)
	{
		points[i] = RandomPoint(onSphere);
	}
	int repeats = quick ? 1 : (count >= 4096 ? 4 : (count >= 256 ? 40 : 400));
	int vertices = 0, faces = 0, builds = 0;
	double start = Now();
	for (int r = 0; r < repeats; ++r)
	{
		for (int c = 0; c < clouds; ++c)
		{
			cd3Hull* hull = NULL;
			if (cd3ComputeHull(points + c * count, count, &hull) != CD_OK)
			{
				fprintf(stderr, "bench_hull: build failed\n");
				exit(1);
			}
			vertices += hull->vertexCount;
			faces += hull->faceCount;
			++builds;
			cd3DestroyHull(hull);
		}
	}
	double ns = (Now() - start) / builds;
	printf("| cd3ComputeHull, %4d points %-9s | %12.0f | %8.1f | %8.1f |\n", count,
		   onSphere ? "on sphere" : "in ball", ns, (double)vertices / builds, (double)faces / builds);
	free(points);
}

static void BenchDistance(bool quick)
{
	enum
	{
		HULLS = 16,
		PAIRS = 4096
	};
	cd3Hull* hulls[HULLS];
	for (int h = 0; h < HULLS; ++h)
	{
		cd3Vec points[32];
		for (int i = 0; i < 32; ++i)
		{
			points[i] = RandomPoint(true);
		}
		if (cd3ComputeHull(points, 32, &hulls[h]) != CD_OK)
		{
			fprintf(stderr, "bench_hull: build failed\n");
			exit(1);
		}
	}
	static cd3Shape a[PAIRS], b[PAIRS];
	for (int i = 0; i < PAIRS; ++i)
	{
		cd3Transform ta = {cd3MakeVec(CD_R(0.0), CD_R(0.0), CD_R(0.0)), RandomQuat()};
		cd3Vec offset = cd3Scale((cdReal)Uniform(1.0, 3.0), RandomPoint(true));
		cd3Transform tb = {offset, RandomQuat()};
		a[i] = cd3MakeHullShape(hulls[i % HULLS], ta);
		b[i] = cd3MakeHullShape(hulls[(i * 7 + 3) % HULLS], tb);
	}
	int repeats = quick ? 1 : 100;
	int overlapping = 0;
	double sum = 0.0;
	double start = Now();
	for (int r = 0; r < repeats; ++r)
	{
		for (int i = 0; i < PAIRS; ++i)
		{
			cd3ClosestPoints c = cd3Distance(&a[i], &b[i]);
			sum += (double)c.distance;
			overlapping += c.distance == CD_R(0.0);
		}
	}
	double ns = (Now() - start) / ((double)repeats * PAIRS);
	g_sink = sum;
	printf("| cd3Distance, hull(32)-hull(32)          | %12.1f | %8s | %8s |   (%.0f%% overlapping)\n", ns,
		   "", "", 100.0 * overlapping / ((double)repeats * PAIRS));
	for (int h = 0; h < HULLS; ++h)
	{
		cd3DestroyHull(hulls[h]);
	}
}

int main(int argc, char** argv)
{
	bool quick = argc > 1 && strcmp(argv[1], "--quick") == 0;
	printf("collide hull benchmark (%s, cdReal = %s)\n\n",
		   quick ? "quick: one pass, no timing claims" : "timed", cdGetRealIsDouble() ? "double" : "float");
	printf("| operation                               |   ns per op  | vertices |   faces  |\n");
	printf("|-----------------------------------------|--------------|----------|----------|\n");
	const int counts[3] = {32, 256, 4096};
	for (int i = 0; i < 3; ++i)
	{
		BenchBuild(counts[i], true, quick);
		BenchBuild(counts[i], false, quick);
	}
	BenchDistance(quick);
	return 0;
}
