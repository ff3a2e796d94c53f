/* libFuzzer target for triangle meshes: arbitrary vertex and index arrays (raw float bit patterns
 * with NaN and infinities, lattices that make coincident vertices, zero-area and coplanar
 * triangles, scales from tiny to huge, indices out of range). The builder must return exactly the
 * documented error (non-finite input first, then coordinates beyond the limit, then indices,
 * then all-degenerate), and a mesh it
 * returns must validate; then ray casts, any-hit casts and closest points equal a brute-force loop
 * over the triangles, overlap equals the OR over the triangles, and manifolds stay finite. */
#include "collide/mesh3.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The documented range of the queries: magnitudes up to MAX and down to MIN, or exactly zero
 * (below MIN squared distances underflow: a point 1e-43 off a triangle reads as touching it). */
#if CD_DOUBLE
#define MESH_FUZZ_MAX 1e30
#define MESH_FUZZ_MIN 1e-30
#else
#define MESH_FUZZ_MAX 1e9
#define MESH_FUZZ_MIN 1e-9
#endif

static void Fail(const char* what, int detail)
{
	fprintf(stderr, "fuzz_mesh3: %s (%d)\n", what, detail);
	abort();
}

typedef struct Reader
{
	const uint8_t* data;
	size_t size, at;
} Reader;

static uint8_t Byte(Reader* r)
{
	return r->at < r->size ? r->data[r->at++] : 0;
}

static cdReal Coordinate(Reader* r, uint8_t mode, double scale, double offset)
{
	if (mode & 1)
	{
		uint32_t bits = 0;
		for (int i = 0; i < 4; ++i)
		{
			bits |= (uint32_t)Byte(r) << (8 * i);
		}
		float f;
		memcpy(&f, &bits, sizeof f);
		double v = (double)f;
		if ((mode & 2) && isfinite(v))
		{
			v = v > MESH_FUZZ_MAX ? MESH_FUZZ_MAX : (v < -MESH_FUZZ_MAX ? -MESH_FUZZ_MAX : v);
			v = fabs(v) < MESH_FUZZ_MIN ? 0.0 : v;
		}
		return (cdReal)v;
	}
	/* A lattice of 16 values per axis: shared positions, flat and collinear triangles. */
	uint8_t b = Byte(r);
	return (cdReal)(offset + scale * ((double)(b & 15) - 7.5) * 0.25);
}

static bool InRangeReal(cdReal x)
{
	double a = fabs((double)x);
	return a <= MESH_FUZZ_MAX && (a >= MESH_FUZZ_MIN || a == 0.0);
}

static bool InRange(cd3Vec v)
{
	return InRangeReal(v.x) && InRangeReal(v.y) && InRangeReal(v.z);
}

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	Reader r = {data, size, 0};
	uint8_t mode = Byte(&r);
	double scale = pow(10.0, (double)((int)Byte(&r) % 19 - 9));
	double offset = (Byte(&r) & 1) ? scale * pow(10.0, (double)(Byte(&r) % 6)) : 0.0;
	int vertexCount = 1 + Byte(&r) % 48;
	int triangleCount = 1 + Byte(&r) % 48;
	cd3Vec vertices[48];
	int indices[3 * 48];
	bool finite = true, inRange = true, belowLimit = true;
	for (int i = 0; i < vertexCount; ++i)
	{
		vertices[i].x = Coordinate(&r, mode, scale, offset);
		vertices[i].y = Coordinate(&r, mode, scale, offset);
		vertices[i].z = Coordinate(&r, mode, scale, offset);
		finite = finite && cd3IsValidVec(vertices[i]);
		inRange = inRange && InRange(vertices[i]);
		belowLimit = belowLimit && fabs((double)vertices[i].x) <= (double)CD3_MESH_MAX_COORDINATE &&
					 fabs((double)vertices[i].y) <= (double)CD3_MESH_MAX_COORDINATE &&
					 fabs((double)vertices[i].z) <= (double)CD3_MESH_MAX_COORDINATE;
	}
	bool indicesOk = true;
	for (int i = 0; i < 3 * triangleCount; ++i)
	{
		/* Mostly in range; (mode & 4) lets -1 and vertexCount through now and then. */
		int b = Byte(&r);
		indices[i] = (mode & 4) ? b % (vertexCount + 2) - 1 : b % vertexCount;
		indicesOk = indicesOk && indices[i] >= 0 && indices[i] < vertexCount;
	}
	int valid = 0;
	for (int t = 0; indicesOk && t < triangleCount; ++t)
	{
		cd3Triangle tri = {vertices[indices[3 * t]], vertices[indices[3 * t + 1]],
						   vertices[indices[3 * t + 2]]};
		valid += cd3IsValidTriangle(tri) ? 1 : 0;
	}
	cdResult expected = !finite		  ? CD_ERROR_NOT_FINITE
						: !belowLimit ? CD_ERROR_OUT_OF_RANGE
						: !indicesOk  ? CD_ERROR_INVALID_ARGUMENT
						: valid == 0  ? CD_ERROR_DEGENERATE
									  : CD_OK;
	cd3Mesh* mesh = NULL;
	cdResult result = cd3CreateMesh(vertices, vertexCount, indices, triangleCount, &mesh);
	if (result != expected)
	{
		Fail("unexpected result", (int)result);
	}
	if (result != CD_OK)
	{
		if (mesh != NULL)
		{
			Fail("mesh returned on failure", (int)result);
		}
		return 0;
	}
	if (cd3ValidateMesh(mesh) != CD_OK)
	{
		Fail("built mesh does not validate", (int)cd3ValidateMesh(mesh));
	}
	cd3MeshStats stats = cd3Mesh_GetStats(mesh);
	if (stats.triangleCount != valid || stats.droppedTriangleCount != triangleCount - valid)
	{
		Fail("stats", stats.triangleCount);
	}
	if (!inRange)
	{
		cd3DestroyMesh(mesh);
		return 0;
	}

	/* Rays between lattice points around the mesh: the BVH answers what the loop answers. */
	for (int q = 0; q < 3; ++q)
	{
		cd3Vec from = vertices[Byte(&r) % vertexCount], to = vertices[Byte(&r) % vertexCount];
		cd3Vec nudge = {(cdReal)(scale * ((int)(Byte(&r) % 9) - 4)),
						(cdReal)(scale * ((int)(Byte(&r) % 9) - 4)),
						(cdReal)(scale * ((int)(Byte(&r) % 9) - 4))};
		from = cd3Add(from, nudge);
		cd3Ray ray = {from, cd3Scale(CD_R(1.5), cd3Sub(to, from))};
		bool brute = false;
		cdReal bruteFraction = CD_R(2.0);
		for (int t = 0; t < triangleCount; ++t)
		{
			cd3Triangle tri = {vertices[indices[3 * t]], vertices[indices[3 * t + 1]],
							   vertices[indices[3 * t + 2]]};
			cd3RayHit hit;
			if (cd3IsValidTriangle(tri) && cd3RaycastTriangle(tri, ray, &hit) && hit.fraction < bruteFraction)
			{
				brute = true;
				bruteFraction = hit.fraction;
			}
		}
		cd3MeshRayHit hit;
		bool got = cd3RaycastMesh(mesh, CD3_TRANSFORM_IDENTITY, ray, &hit);
		bool any = cd3RaycastMeshAny(mesh, CD3_TRANSFORM_IDENTITY, ray);
		if (got != brute || any != brute || (got && hit.hit.fraction != bruteFraction))
		{
			if (getenv("FUZZ_MESH_DEBUG"))
			{
				fprintf(
					stderr,
					"got %d any %d brute %d, fractions %.9g %.9g\nray (%.9g %.9g %.9g) + (%.9g %.9g %.9g)\n",
					got, any, brute, got ? (double)hit.hit.fraction : -1.0, (double)bruteFraction,
					(double)ray.origin.x, (double)ray.origin.y, (double)ray.origin.z,
					(double)ray.translation.x, (double)ray.translation.y, (double)ray.translation.z);
				for (int t = 0; t < triangleCount; ++t)
				{
					cd3Triangle tri = {vertices[indices[3 * t]], vertices[indices[3 * t + 1]],
									   vertices[indices[3 * t + 2]]};
					cd3RayHit h;
					if (cd3IsValidTriangle(tri) && cd3RaycastTriangle(tri, ray, &h))
					{
						fprintf(stderr,
								"tri %d hit %.9g: (%.9g %.9g %.9g) (%.9g %.9g %.9g) (%.9g %.9g %.9g)\n", t,
								(double)h.fraction, (double)tri.a.x, (double)tri.a.y, (double)tri.a.z,
								(double)tri.b.x, (double)tri.b.y, (double)tri.b.z, (double)tri.c.x,
								(double)tri.c.y, (double)tri.c.z);
					}
				}
			}
			Fail("ray cast differs from the loop", q);
		}
		if (got && (!(cd3Length(hit.hit.normal) > CD_R(0.99)) || !cd3IsValidVec(hit.hit.point)))
		{
			Fail("ray hit not finite", q);
		}

		cd3Vec p = cd3Lerp(from, to, CD_R(0.3));
		cdReal bestSquared = CD_REAL_MAX;
		for (int t = 0; t < triangleCount; ++t)
		{
			cd3Triangle tri = {vertices[indices[3 * t]], vertices[indices[3 * t + 1]],
							   vertices[indices[3 * t + 2]]};
			if (cd3IsValidTriangle(tri))
			{
				bestSquared = cdMin(bestSquared, cd3VecDistanceSquared(cd3ClosestPointOnTriangle(tri, p), p));
			}
		}
		cd3MeshClosestPoint cp;
		if (!cd3ClosestPointOnMesh(mesh, CD3_TRANSFORM_IDENTITY, p, CD_REAL_MAX, &cp))
		{
			Fail("no closest point", q);
		}
		cdReal d2 = cd3VecDistanceSquared(cp.point, p);
		if (!(d2 == bestSquared))
		{
			Fail("closest point differs from the loop", q);
		}

		cd3Shape sphere = cd3MakeSphereShape((cd3Sphere){p, (cdReal)(scale * (Byte(&r) % 8))});
		bool overlap = false;
		for (int t = 0; t < triangleCount && !overlap; ++t)
		{
			cd3Triangle tri = {vertices[indices[3 * t]], vertices[indices[3 * t + 1]],
							   vertices[indices[3 * t + 2]]};
			cd3Shape triangle = cd3MakeTriangleShape(tri);
			overlap = cd3IsValidTriangle(tri) && cd3Overlap(&sphere, &triangle);
		}
		if (cd3OverlapMesh(&sphere, mesh, CD3_TRANSFORM_IDENTITY) != overlap)
		{
			if (getenv("FUZZ_MESH_DEBUG"))
			{
				fprintf(stderr, "sphere (%.9g %.9g %.9g) r %.9g brute %d\n", (double)p.x, (double)p.y,
						(double)p.z, (double)sphere.sphere.radius, overlap);
				for (int t = 0; t < triangleCount; ++t)
				{
					cd3Triangle tri = {vertices[indices[3 * t]], vertices[indices[3 * t + 1]],
									   vertices[indices[3 * t + 2]]};
					cd3Shape triangle = cd3MakeTriangleShape(tri);
					if (cd3IsValidTriangle(tri) && cd3Overlap(&sphere, &triangle))
					{
						fprintf(stderr, "tri %d: (%.9g %.9g %.9g) (%.9g %.9g %.9g) (%.9g %.9g %.9g)\n", t,
								(double)tri.a.x, (double)tri.a.y, (double)tri.a.z, (double)tri.b.x,
								(double)tri.b.y, (double)tri.b.z, (double)tri.c.x, (double)tri.c.y,
								(double)tri.c.z);
					}
				}
			}
			Fail("overlap differs from the loop", q);
		}

		cd3MeshManifold manifolds[16];
		cd3Box box = {p, {(cdReal)scale, (cdReal)(0.5 * scale), (cdReal)(2.0 * scale)}, CD3_QUAT_IDENTITY};
		cd3Capsule capsule = {p, cd3Add(p, nudge), (cdReal)(0.5 * scale)};
		cd3Shape shapes[3] = {sphere, cd3MakeBoxShape(box), cd3MakeCapsuleShape(capsule)};
		for (int s = 0; s < 3; ++s)
		{
			int n = cd3CollideMesh(&shapes[s], mesh, CD3_TRANSFORM_IDENTITY, (cdReal)(0.1 * scale), manifolds,
								   16);
			if (n < 0 || n > 16)
			{
				Fail("manifold count", n);
			}
			for (int k = 0; k < n; ++k)
			{
				const cd3Manifold* m = &manifolds[k].manifold;
				if (m->pointCount < 1 || m->pointCount > 4 || !cd3IsValidVec(m->normal) ||
					cdAbs(cd3Length(m->normal) - CD_R(1.0)) > CD_R(1e-3) || manifolds[k].triangleIndex < 0 ||
					manifolds[k].triangleIndex >= triangleCount)
				{
					Fail("bad manifold", k);
				}
				for (int i = 0; i < m->pointCount; ++i)
				{
					if (!cd3IsValidVec(m->points[i].point) || !cdIsValidReal(m->points[i].separation))
					{
						Fail("manifold point not finite", i);
					}
				}
			}
		}
	}
	cd3DestroyMesh(mesh);
	return 0;
}
