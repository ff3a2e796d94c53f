/* Meshes for the mesh tests and the mesh benchmark: a terrain grid, a latitude-longitude sphere
 * (with the zero-area triangles at its poles), a soup of random triangles and flat floors, regular
 * and randomly tessellated. Each fills caller-sized arrays (the *Counts functions give the sizes).
 * Header-only; depends on test.h's TestRng. */
#ifndef COLLIDE_TEST_RANDOM_MESHES3_H
#define COLLIDE_TEST_RANDOM_MESHES3_H

#include "collide/mesh3.h"
#include "test.h"

#include <math.h>
#include <stdlib.h>

typedef struct TestMesh
{
	cd3Vec* vertices;
	int* indices;
	int vertexCount;
	int triangleCount;
} TestMesh;

static inline TestMesh TestMeshAllocate(int vertexCount, int triangleCount)
{
	TestMesh m;
	m.vertices = (cd3Vec*)malloc((size_t)vertexCount * sizeof(cd3Vec));
	m.indices = (int*)malloc((size_t)triangleCount * 3 * sizeof(int));
	m.vertexCount = vertexCount;
	m.triangleCount = triangleCount;
	return m;
}

static inline void TestMeshFree(TestMesh* m)
{
	free(m->vertices);
	free(m->indices);
	m->vertices = NULL;
	m->indices = NULL;
}

/* Two triangles per cell of an n by n grid of `cell`-sized squares centred on the origin in the
 * x-z plane, counter-clockwise seen from +y; heights from `height` (NULL: flat at y = 0). The
 * diagonal of each cell is random when rng is not NULL. */
static inline TestMesh TestMeshGrid(int n, double cell, double (*height)(double x, double z), TestRng* rng)
{
	TestMesh m = TestMeshAllocate((n + 1) * (n + 1), 2 * n * n);
	double half = 0.5 * n * cell;
	for (int j = 0; j <= n; ++j)
	{
		for (int i = 0; i <= n; ++i)
		{
			double x = -half + i * cell, z = -half + j * cell;
			m.vertices[j * (n + 1) + i] =
				cd3MakeVec((cdReal)x, (cdReal)(height ? height(x, z) : 0.0), (cdReal)z);
		}
	}
	int t = 0;
	for (int j = 0; j < n; ++j)
	{
		for (int i = 0; i < n; ++i)
		{
			int v00 = j * (n + 1) + i, v10 = v00 + 1, v01 = v00 + n + 1, v11 = v01 + 1;
			bool flip = rng != NULL && TestRngInt(rng, 2) == 0;
			int* x = m.indices + 3 * t;
			if (!flip)
			{
				x[0] = v00, x[1] = v01, x[2] = v10;
				x[3] = v10, x[4] = v01, x[5] = v11;
			}
			else
			{
				x[0] = v00, x[1] = v11, x[2] = v10;
				x[3] = v00, x[4] = v01, x[5] = v11;
			}
			t += 2;
		}
	}
	return m;
}

static inline double TestTerrainHeight(double x, double z)
{
	return 0.6 * sin(0.37 * x) * cos(0.29 * z) + 0.25 * sin(1.3 * x + 0.7 * z);
}

/* A flat floor at y = 0 of side n * cell, randomly tessellated: a grid whose inner vertices are
 * jittered in x and z (by up to 0.3 cell), with random diagonals, and `splits` random triangles
 * each split into three at a random inner point. Every vertex lies exactly at y = 0. */
static inline TestMesh TestMeshRandomFloor(int n, double cell, int splits, TestRng* rng)
{
	TestMesh grid = TestMeshGrid(n, cell, NULL, rng);
	TestMesh m = TestMeshAllocate(grid.vertexCount + splits, grid.triangleCount + 2 * splits);
	for (int v = 0; v < grid.vertexCount; ++v)
	{
		m.vertices[v] = grid.vertices[v];
		int i = v % (n + 1), j = v / (n + 1);
		if (i > 0 && i < n && j > 0 && j < n)
		{
			m.vertices[v].x += (cdReal)TestRngRange(rng, -0.3 * cell, 0.3 * cell);
			m.vertices[v].z += (cdReal)TestRngRange(rng, -0.3 * cell, 0.3 * cell);
		}
	}
	for (int k = 0; k < 3 * grid.triangleCount; ++k)
	{
		m.indices[k] = grid.indices[k];
	}
	int triangles = grid.triangleCount;
	for (int s = 0; s < splits; ++s)
	{
		int t = TestRngInt(rng, triangles);
		int a = m.indices[3 * t], b = m.indices[3 * t + 1], c = m.indices[3 * t + 2];
		double u = TestRngRange(rng, 0.1, 0.8), w = TestRngRange(rng, 0.1, 0.9 - u);
		cd3Vec p = cd3Add(m.vertices[a], cd3Add(cd3Scale((cdReal)u, cd3Sub(m.vertices[b], m.vertices[a])),
												cd3Scale((cdReal)w, cd3Sub(m.vertices[c], m.vertices[a]))));
		p.y = CD_R(0.0);
		int v = grid.vertexCount + s;
		m.vertices[v] = p;
		m.indices[3 * t + 2] = v; /* a b p */
		int* x = m.indices + 3 * triangles;
		x[0] = b, x[1] = c, x[2] = v;
		x[3] = c, x[4] = a, x[5] = v;
		triangles += 2;
	}
	TestMeshFree(&grid);
	return m;
}

/* A latitude-longitude sphere: `rings` bands of `segments` quads, each two triangles facing out;
 * the quads at the poles have two coincident corners, so one of their triangles has zero area. */
static inline TestMesh TestMeshSphere(cd3Vec center, double radius, int rings, int segments)
{
	TestMesh m = TestMeshAllocate((rings + 1) * (segments + 1), 2 * rings * segments);
	for (int r = 0; r <= rings; ++r)
	{
		double theta = 3.14159265358979323846 * r / rings;
		for (int s = 0; s <= segments; ++s)
		{
			double phi = 2.0 * 3.14159265358979323846 * (s % segments) / segments;
			double y = r == 0 ? 1.0 : (r == rings ? -1.0 : cos(theta));
			double ring = r == 0 || r == rings ? 0.0 : sin(theta);
			m.vertices[r * (segments + 1) + s] =
				cd3MakeVec((cdReal)(center.x + radius * ring * cos(phi)), (cdReal)(center.y + radius * y),
						   (cdReal)(center.z + radius * ring * sin(phi)));
		}
	}
	int t = 0;
	for (int r = 0; r < rings; ++r)
	{
		for (int s = 0; s < segments; ++s)
		{
			int v00 = r * (segments + 1) + s, v01 = v00 + 1, v10 = v00 + segments + 1, v11 = v10 + 1;
			int* x = m.indices + 3 * t;
			x[0] = v00, x[1] = v01, x[2] = v10;
			x[3] = v01, x[4] = v11, x[5] = v10;
			t += 2;
		}
	}
	return m;
}

/* `count` random triangles with corners within `extent` of random centres within `spread`. */
static inline TestMesh TestMeshSoup(int count, double spread, double extent, TestRng* rng)
{
	TestMesh m = TestMeshAllocate(3 * count, count);
	for (int t = 0; t < count; ++t)
	{
		cd3Vec c =
			cd3MakeVec((cdReal)TestRngRange(rng, -spread, spread), (cdReal)TestRngRange(rng, -spread, spread),
					   (cdReal)TestRngRange(rng, -spread, spread));
		for (int k = 0; k < 3; ++k)
		{
			m.vertices[3 * t + k] = cd3Add(c, cd3MakeVec((cdReal)TestRngRange(rng, -extent, extent),
														 (cdReal)TestRngRange(rng, -extent, extent),
														 (cdReal)TestRngRange(rng, -extent, extent)));
			m.indices[3 * t + k] = 3 * t + k;
		}
	}
	return m;
}

#endif
