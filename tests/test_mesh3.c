/* Triangle meshes: builder errors, stats and validation, and every BVH query against a brute-force
 * loop over the triangles with the primitive routines (ray casts, any hit, closest point, overlap,
 * bounds queries) on random soups, a terrain and a sphere mesh, with and without a mesh transform. */
#include "collide/mesh3.h"

#include <float.h>
#include "random_meshes3.h"
#include "random_shapes3.h"
#include "test.h"

static cd3Mesh* Build(const TestMesh* m)
{
	cd3Mesh* mesh = NULL;
	cdResult result = cd3CreateMesh(m->vertices, m->vertexCount, m->indices, m->triangleCount, &mesh);
	TEST_CHECKF(result == CD_OK && mesh != NULL, "result %s", cdGetResultString(result));
	if (mesh != NULL)
	{
		TEST_CHECK(cd3ValidateMesh(mesh) == CD_OK);
	}
	return mesh;
}

static void TestBadInput(void)
{
	cd3Vec v[4] = {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {1, 0, 1}};
	int good[6] = {0, 2, 1, 1, 2, 3};
	cd3Mesh* mesh = (cd3Mesh*)&mesh; /* must be reset to NULL on failure */
	TEST_CHECK(cd3CreateMesh(NULL, 4, good, 2, &mesh) == CD_ERROR_INVALID_ARGUMENT && mesh == NULL);
	TEST_CHECK(cd3CreateMesh(v, 4, NULL, 2, &mesh) == CD_ERROR_INVALID_ARGUMENT);
	TEST_CHECK(cd3CreateMesh(v, 4, good, 2, NULL) == CD_ERROR_INVALID_ARGUMENT);
	TEST_CHECK(cd3CreateMesh(v, 0, good, 2, &mesh) == CD_ERROR_INVALID_ARGUMENT);
	TEST_CHECK(cd3CreateMesh(v, 4, good, 0, &mesh) == CD_ERROR_INVALID_ARGUMENT);
	TEST_CHECK(cd3CreateMesh(v, 4, good, -3, &mesh) == CD_ERROR_INVALID_ARGUMENT);
	TEST_CHECK(cd3CreateMesh(v, CD3_MAX_MESH_VERTICES + 1, good, 2, &mesh) == CD_ERROR_TOO_MANY_POINTS);
	TEST_CHECK(cd3CreateMesh(v, 4, good, CD3_MAX_MESH_TRIANGLES + 1, &mesh) == CD_ERROR_TOO_MANY_POINTS);
	int outOfRange[6] = {0, 2, 1, 1, 2, 4};
	TEST_CHECK(cd3CreateMesh(v, 4, outOfRange, 2, &mesh) == CD_ERROR_INVALID_ARGUMENT && mesh == NULL);
	int negative[6] = {0, 2, 1, -1, 2, 3};
	TEST_CHECK(cd3CreateMesh(v, 4, negative, 2, &mesh) == CD_ERROR_INVALID_ARGUMENT);
	cd3Vec bad[4] = {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {1, 0, 1}};
	bad[3].y = (cdReal)NAN;
	TEST_CHECK(cd3CreateMesh(bad, 4, good, 2, &mesh) == CD_ERROR_NOT_FINITE && mesh == NULL);
	bad[3].y = (cdReal)INFINITY;
	TEST_CHECK(cd3CreateMesh(bad, 4, good, 2, &mesh) == CD_ERROR_NOT_FINITE);
	/* Finite but beyond the limit (the fuzzer's case: a vertex near FLT_MAX, whose padded float
	 * bound was infinite); just inside the limit builds and validates. */
	bad[3].y = CD3_MESH_MAX_COORDINATE * CD_R(2.0);
	TEST_CHECK(cd3CreateMesh(bad, 4, good, 2, &mesh) == CD_ERROR_OUT_OF_RANGE && mesh == NULL);
	bad[3].y = -(cdReal)FLT_MAX;
	TEST_CHECK(cd3CreateMesh(bad, 4, good, 2, &mesh) == CD_ERROR_OUT_OF_RANGE);
	bad[3].y = CD3_MESH_MAX_COORDINATE;
	TEST_CHECK(cd3CreateMesh(bad, 4, good, 2, &mesh) == CD_OK && mesh != NULL);
	TEST_CHECK(cd3ValidateMesh(mesh) == CD_OK);
	cd3DestroyMesh(mesh);
	/* Every triangle degenerate: coincident corners, collinear corners. */
	cd3Vec line[3] = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
	int flat[6] = {0, 1, 2, 0, 0, 1};
	TEST_CHECK(cd3CreateMesh(line, 3, flat, 2, &mesh) == CD_ERROR_DEGENERATE && mesh == NULL);
	TEST_CHECK(cd3ValidateMesh(NULL) == CD_ERROR_INVALID_ARGUMENT);
	cd3MeshStats none = cd3Mesh_GetStats(NULL);
	TEST_CHECK(none.triangleCount == 0 && none.bytes == 0);
}

static void TestExact(void)
{
	/* A unit square at y = 0 and a degenerate triangle in between (input index 1). */
	cd3Vec v[5] = {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {1, 0, 1}, {2, 0, 2}};
	int indices[9] = {0, 2, 1, 0, 3, 4, 1, 2, 3};
	cd3Mesh* mesh = NULL;
	TEST_CHECK(cd3CreateMesh(v, 5, indices, 3, &mesh) == CD_OK);
	if (mesh == NULL)
	{
		return;
	}
	TEST_CHECK(cd3ValidateMesh(mesh) == CD_OK);
	cd3MeshStats stats = cd3Mesh_GetStats(mesh);
	TEST_CHECK(stats.triangleCount == 2 && stats.droppedTriangleCount == 1 && stats.vertexCount == 5);
	/* Two triangles: one 8-wide root over one or two leaves. */
	TEST_CHECK(stats.nodeCount == 1 && stats.leafCount >= 1 && stats.leafCount <= 2 && stats.depth == 2 &&
			   stats.bytes > 0);
	/* The square's outline: 4 boundary edges, active on both sides; its diagonal is flat. */
	TEST_CHECK(stats.activeEdgeCount == 8);
	TEST_CHECK(stats.bounds.min.x <= CD_R(0.0) && stats.bounds.max.x >= CD_R(1.0) &&
			   stats.bounds.max.z >= CD_R(1.0));
	TEST_CHECK(cd3Mesh_GetTriangleCount(mesh) == 2);
	cd3Triangle t;
	TEST_CHECK(cd3Mesh_GetTriangle(mesh, 2, &t) && cd3VecEqual(t.a, v[1]) && cd3VecEqual(t.c, v[3]));
	TEST_CHECK(!cd3Mesh_GetTriangle(mesh, 1, &t) && !cd3Mesh_GetTriangle(mesh, 3, &t) &&
			   !cd3Mesh_GetTriangle(mesh, -1, &t));

	cd3Transform id = CD3_TRANSFORM_IDENTITY;
	cd3Ray down = {{CD_R(0.75), CD_R(2.0), CD_R(0.5)}, {CD_R(0.0), -CD_R(4.0), CD_R(0.0)}};
	cd3MeshRayHit hit;
	TEST_CHECK(cd3RaycastMesh(mesh, id, down, &hit));
	TEST_CHECK_NEAR(hit.hit.fraction, 0.5, 1e-6);
	TEST_CHECK(hit.triangleIndex == 2);
	TEST_CHECK_NEAR(hit.hit.normal.y, 1.0, 1e-6);
	TEST_CHECK(cd3RaycastMeshAny(mesh, id, down));
	cd3Ray up = {{CD_R(0.25), -CD_R(1.0), CD_R(0.5)}, {CD_R(0.0), CD_R(2.0), CD_R(0.0)}};
	TEST_CHECK(cd3RaycastMesh(mesh, id, up, &hit) && hit.triangleIndex == 0);
	TEST_CHECK_NEAR(hit.hit.normal.y, -1.0, 1e-6); /* two-sided: faces the origin */
	cd3Ray shortRay = {{CD_R(0.5), CD_R(2.0), CD_R(0.5)}, {CD_R(0.0), -CD_R(1.5), CD_R(0.0)}};
	hit.triangleIndex = 77;
	TEST_CHECK(!cd3RaycastMesh(mesh, id, shortRay, &hit) && hit.triangleIndex == 77);
	TEST_CHECK(!cd3RaycastMeshAny(mesh, id, shortRay));
	cd3Ray beside = {{CD_R(1.5), CD_R(2.0), CD_R(0.5)}, {CD_R(0.0), -CD_R(4.0), CD_R(0.0)}};
	TEST_CHECK(!cd3RaycastMesh(mesh, id, beside, &hit));
	/* A ray lying in the plane of the square (zero y component) meets no triangle face. */
	cd3Ray grazing = {{-CD_R(1.0), CD_R(0.5), CD_R(0.5)}, {CD_R(3.0), CD_R(0.0), CD_R(0.0)}};
	TEST_CHECK(!cd3RaycastMesh(mesh, id, grazing, &hit));

	cd3MeshClosestPoint cp;
	TEST_CHECK(
		cd3ClosestPointOnMesh(mesh, id, cd3MakeVec(CD_R(0.2), CD_R(3.0), CD_R(0.3)), CD_REAL_MAX, &cp));
	TEST_CHECK_NEAR(cp.distance, 3.0, 1e-6);
	TEST_CHECK(cp.triangleIndex == 0 && cp.point.y == CD_R(0.0));
	TEST_CHECK(
		cd3ClosestPointOnMesh(mesh, id, cd3MakeVec(CD_R(2.0), CD_R(0.0), CD_R(1.0)), CD_REAL_MAX, &cp));
	TEST_CHECK_NEAR(cp.distance, 1.0, 1e-6);
	TEST_CHECK(cp.triangleIndex == 2);
	TEST_CHECK(!cd3ClosestPointOnMesh(mesh, id, cd3MakeVec(CD_R(2.0), CD_R(0.0), CD_R(1.0)), CD_R(0.5), &cp));
	/* On the shared diagonal: both triangles at distance 0, the lower input index wins. */
	TEST_CHECK(
		cd3ClosestPointOnMesh(mesh, id, cd3MakeVec(CD_R(0.5), CD_R(0.0), CD_R(0.5)), CD_REAL_MAX, &cp));
	TEST_CHECK(cp.distance == CD_R(0.0) && cp.triangleIndex == 0);

	/* Overlap: touching counts. */
	cd3Shape sphere = cd3MakeSphereShape((cd3Sphere){{CD_R(0.5), CD_R(1.0), CD_R(0.5)}, CD_R(1.0)});
	TEST_CHECK(cd3OverlapMesh(&sphere, mesh, id));
	sphere.sphere.center.y = CD_R(1.01);
	TEST_CHECK(!cd3OverlapMesh(&sphere, mesh, id));
	cd3Shape plane = cd3MakePlaneShape((cd3Plane){{CD_R(0.0), CD_R(1.0), CD_R(0.0)}, -CD_R(0.5)});
	TEST_CHECK(!cd3OverlapMesh(&plane, mesh, id));
	plane.plane.offset = CD_R(0.0);
	TEST_CHECK(cd3OverlapMesh(&plane, mesh, id));
	cd3DestroyMesh(mesh);
}

/* ---- against brute force ----------------------------------------------------------------------- */

static bool BruteRay(const TestMesh* m, cd3Transform xf, cd3Ray ray, cd3MeshRayHit* out)
{
	bool found = false;
	for (int t = 0; t < m->triangleCount; ++t)
	{
		cd3Triangle tri = {m->vertices[m->indices[3 * t]], m->vertices[m->indices[3 * t + 1]],
						   m->vertices[m->indices[3 * t + 2]]};
		if (!cd3IsValidTriangle(tri))
		{
			continue;
		}
		cd3Triangle w = {cd3TransformPoint(xf, tri.a), cd3TransformPoint(xf, tri.b),
						 cd3TransformPoint(xf, tri.c)};
		cd3RayHit hit;
		if (cd3RaycastTriangle(w, ray, &hit) && (!found || hit.fraction < out->hit.fraction))
		{
			found = true;
			out->hit = hit;
			out->triangleIndex = t;
		}
	}
	return found;
}

static cdReal BruteClosest(const TestMesh* m, cd3Vec p, int* index)
{
	cdReal best = CD_REAL_MAX;
	for (int t = 0; t < m->triangleCount; ++t)
	{
		cd3Triangle tri = {m->vertices[m->indices[3 * t]], m->vertices[m->indices[3 * t + 1]],
						   m->vertices[m->indices[3 * t + 2]]};
		if (!cd3IsValidTriangle(tri))
		{
			continue;
		}
		cdReal d2 = cd3VecDistanceSquared(cd3ClosestPointOnTriangle(tri, p), p);
		if (d2 < best)
		{
			best = d2;
			*index = t;
		}
	}
	return cdSqrt(best);
}

static cd3Triangle InputTriangle(const TestMesh* m, int t)
{
	cd3Triangle tri = {m->vertices[m->indices[3 * t]], m->vertices[m->indices[3 * t + 1]],
					   m->vertices[m->indices[3 * t + 2]]};
	return tri;
}

static cd3Transform RandomTransform(TestRng* rng)
{
	cd3Transform xf;
	xf.p = RandomVec(rng, 5.0);
	xf.q = RandomQuat(rng);
	return xf;
}

/* cd3RaycastMesh and cd3RaycastMeshAny against the loop over all triangles; returns whether the
 * loop hits. */
static bool CheckRay(const TestMesh* m, const cd3Mesh* mesh, cd3Transform xf, cd3Ray ray, const char* name,
					 int i)
{
	cd3MeshRayHit expected = {{0, {0, 0, 0}, {0, 0, 0}}, -1}, got = expected;
	bool brute = BruteRay(m, xf, ray, &expected);
	bool bvh = cd3RaycastMesh(mesh, xf, ray, &got);
	bool any = cd3RaycastMeshAny(mesh, xf, ray);
	/* The same triangle routine on the same world triangles: the same answer, bit for bit; the
	 * index may differ only at an exact tie, which both must then report at that fraction. */
	bool same = brute == bvh && any == brute;
	if (same && brute)
	{
		same = got.hit.fraction == expected.hit.fraction;
		if (same && got.triangleIndex != expected.triangleIndex)
		{
			cd3Triangle alt = InputTriangle(m, got.triangleIndex);
			cd3Triangle w = {cd3TransformPoint(xf, alt.a), cd3TransformPoint(xf, alt.b),
							 cd3TransformPoint(xf, alt.c)};
			cd3RayHit check;
			same = got.triangleIndex < expected.triangleIndex && cd3RaycastTriangle(w, ray, &check) &&
				   check.fraction == expected.hit.fraction;
		}
	}
	TEST_CHECKF(same, "%s ray %d: brute %d (t %.9g, tri %d), bvh %d (t %.9g, tri %d), any %d", name, i, brute,
				brute ? (double)expected.hit.fraction : -1.0, brute ? expected.triangleIndex : -1, bvh,
				bvh ? (double)got.hit.fraction : -1.0, bvh ? got.triangleIndex : -1, any);
	return brute;
}

/* Rays from a box around the mesh towards random points of it; every 8th ray is short. */
static void CheckRays(const TestMesh* m, cd3Aabb bounds, int count, TestRng* rng, const char* name)
{
	cd3Mesh* mesh = Build(m);
	if (mesh == NULL)
	{
		return;
	}
	cd3Vec center = cd3AabbCenter(bounds);
	cdReal size = cd3Length(cd3Sub(bounds.max, bounds.min));
	int hits = 0;
	for (int i = 0; i < count; ++i)
	{
		cd3Transform xf = i % 2 == 0 ? CD3_TRANSFORM_IDENTITY : RandomTransform(rng);
		cd3Vec from = cd3Add(center, RandomVec(rng, (double)size));
		cd3Vec to = cd3Add(center, RandomVec(rng, 0.5 * (double)size));
		cd3Vec d = cd3Sub(to, from);
		if (i % 8 == 0)
		{
			d = cd3Scale(RandomReal(rng, 0.0, 1.0), d);
		}
		if (i % 10 == 4)
		{
			/* Axis-parallel (on the identity placement): zero components, one of them negative zero. */
			int axis = (i / 10) % 3;
			cdReal along = cd3GetComponent(d, axis);
			d = cd3MakeVec(axis == 0 ? along : -CD_R(0.0), axis == 1 ? along : CD_R(0.0),
						   axis == 2 ? along : -CD_R(0.0));
		}
		cd3Ray ray = {cd3TransformPoint(xf, from), cd3RotateVector(xf.q, d)};
		hits += CheckRay(m, mesh, xf, ray, name, i) ? 1 : 0;
	}
	/* The rays must exercise both outcomes. */
	TEST_CHECKF(hits > 0 && hits < count, "%s: %d hits of %d", name, hits, count);
	cd3DestroyMesh(mesh);
}

static void CheckClosest(const TestMesh* m, cd3Aabb bounds, int count, TestRng* rng, const char* name)
{
	cd3Mesh* mesh = Build(m);
	if (mesh == NULL)
	{
		return;
	}
	cd3Vec center = cd3AabbCenter(bounds);
	cdReal size = cd3Length(cd3Sub(bounds.max, bounds.min));
	for (int i = 0; i < count; ++i)
	{
		cd3Vec p = cd3Add(center, RandomVec(rng, 0.8 * (double)size));
		int bruteIndex = -1;
		cdReal brute = BruteClosest(m, p, &bruteIndex);
		cd3MeshClosestPoint cp;
		bool found = cd3ClosestPointOnMesh(mesh, CD3_TRANSFORM_IDENTITY, p, CD_REAL_MAX, &cp);
		TEST_CHECKF(found && cdAbs(cp.distance - brute) <= CD_R(1e-5) * (CD_R(1.0) + brute),
					"%s point %d: brute %.9g (tri %d), bvh %.9g (tri %d)", name, i, (double)brute, bruteIndex,
					found ? (double)cp.distance : -1.0, found ? cp.triangleIndex : -1);
		if (!found)
		{
			continue;
		}
		/* The point lies on the triangle it names. */
		cd3Triangle tri = InputTriangle(m, cp.triangleIndex);
		cdReal off = cd3VecDistance(cd3ClosestPointOnTriangle(tri, cp.point), cp.point);
		TEST_CHECKF(off <= CD_R(1e-5) * (CD_R(1.0) + size), "%s point %d: %.3g off its triangle", name, i,
					(double)off);
		/* Under a mesh transform: the same distance, the point moved with the mesh. */
		cd3Transform xf = RandomTransform(rng);
		cd3MeshClosestPoint moved;
		bool foundMoved = cd3ClosestPointOnMesh(mesh, xf, cd3TransformPoint(xf, p), CD_REAL_MAX, &moved);
		TEST_CHECKF(foundMoved && cdAbs(moved.distance - cp.distance) <= CD_R(1e-4) * (CD_R(1.0) + size) &&
						cd3VecDistance(moved.point, cd3TransformPoint(xf, cp.point)) <=
							CD_R(1e-3) * (CD_R(1.0) + size),
					"%s point %d: moved distance %.9g vs %.9g", name, i,
					foundMoved ? (double)moved.distance : -1.0, (double)cp.distance);
		/* A limit just below the distance finds nothing; just above finds it. */
		if (brute > CD_R(1e-3))
		{
			cd3MeshClosestPoint limited;
			TEST_CHECK(!cd3ClosestPointOnMesh(mesh, CD3_TRANSFORM_IDENTITY, p, CD_R(0.99) * brute, &limited));
			TEST_CHECK(cd3ClosestPointOnMesh(mesh, CD3_TRANSFORM_IDENTITY, p, CD_R(1.01) * brute, &limited));
		}
	}
	cd3DestroyMesh(mesh);
}

typedef struct Collected
{
	int count;
	char* seen;
} Collected;

static bool Collect(int index, void* context)
{
	Collected* c = (Collected*)context;
	c->seen[index] += 1;
	c->count += 1;
	return true;
}

static bool StopAtOnce(int index, void* context)
{
	(void)index;
	*(int*)context += 1;
	return false;
}

static void CheckQueriesAndOverlap(const TestMesh* m, cd3Aabb bounds, int count, TestRng* rng,
								   const char* name)
{
	cd3Mesh* mesh = Build(m);
	if (mesh == NULL)
	{
		return;
	}
	char* seen = (char*)calloc((size_t)m->triangleCount, 1);
	cd3Vec center = cd3AabbCenter(bounds);
	cdReal size = cd3Length(cd3Sub(bounds.max, bounds.min));
	int overlaps = 0;
	for (int i = 0; i < count; ++i)
	{
		/* Bounds query: every triangle whose box overlaps is reported exactly once. */
		cd3Vec c = cd3Add(center, RandomVec(rng, 0.6 * (double)size));
		cd3Vec h = cd3Abs(RandomVec(rng, 0.1 * (double)size));
		cd3Aabb box = {cd3Sub(c, h), cd3Add(c, h)};
		Collected collected = {0, seen};
		memset(seen, 0, (size_t)m->triangleCount);
		TEST_CHECK(cd3Mesh_QueryAabb(mesh, box, Collect, &collected));
		bool ok = true;
		for (int t = 0; t < m->triangleCount; ++t)
		{
			cd3Triangle tri = InputTriangle(m, t);
			bool valid = cd3IsValidTriangle(tri);
			bool must = valid && cd3OverlapAabbAabb(cd3ComputeTriangleAabb(tri), box);
			ok = ok && seen[t] <= 1 && (!must || seen[t] == 1) && (valid || seen[t] == 0);
		}
		TEST_CHECKF(ok, "%s query %d", name, i);
		if (collected.count > 0)
		{
			int calls = 0;
			TEST_CHECK(!cd3Mesh_QueryAabb(mesh, box, StopAtOnce, &calls) && calls == 1);
		}

		/* Overlap equals the OR of cd3Overlap over the triangles, with the mesh moved too. */
		cd3Transform xf = i % 3 == 0 ? CD3_TRANSFORM_IDENTITY : RandomTransform(rng);
		cd3Shape local = RandomShape(rng, (cd3ShapeType)TestRngInt(rng, CD3_SHAPE_TYPE_COUNT));
		local = ScaleShape(&local, CD_R(0.1) * size);
		local = TransformShape(&local, (cd3Transform){c, CD3_QUAT_IDENTITY});
		if (local.type == CD3_SHAPE_AABB)
		{
			xf.q = CD3_QUAT_IDENTITY; /* an AABB stays one only under translation: compare like for like */
		}
		cd3Shape shape = TransformShape(&local, xf);
		bool brute = false;
		for (int t = 0; t < m->triangleCount && !brute; ++t)
		{
			cd3Triangle tri = InputTriangle(m, t);
			if (!cd3IsValidTriangle(tri))
			{
				continue;
			}
			cd3Shape w = cd3MakeTriangleShape((cd3Triangle){
				cd3TransformPoint(xf, tri.a), cd3TransformPoint(xf, tri.b), cd3TransformPoint(xf, tri.c)});
			brute = cd3Overlap(&shape, &w);
		}
		bool got = cd3OverlapMesh(&shape, mesh, xf);
		overlaps += got ? 1 : 0;
		TEST_CHECKF(got == brute, "%s overlap %d (%s): brute %d, mesh %d", name, i,
					cd3GetShapeTypeName(shape.type), brute, got);
	}
	TEST_CHECKF(overlaps > count / 20 && overlaps < count, "%s: %d overlaps of %d", name, overlaps, count);
	free(seen);
	cd3DestroyMesh(mesh);
}

static cd3Aabb MeshBounds(const TestMesh* m)
{
	cd3Aabb b = {m->vertices[0], m->vertices[0]};
	for (int v = 1; v < m->vertexCount; ++v)
	{
		b.min = cd3Min(b.min, m->vertices[v]);
		b.max = cd3Max(b.max, m->vertices[v]);
	}
	return b;
}

static void RunAll(TestMesh* m, TestRng* rng, const char* name, int rays, int points, int shapes)
{
	cd3Aabb bounds = MeshBounds(m);
	CheckRays(m, bounds, rays, rng, name);
	CheckClosest(m, bounds, points, rng, name);
	CheckQueriesAndOverlap(m, bounds, shapes, rng, name);
	TestMeshFree(m);
}

static void TestSoup(void)
{
	TestRng rng = TestRngMake(0x3e5a01u);
	for (int round = 0; round < 2; ++round)
	{
		TestMesh m = TestMeshSoup(80 + 160 * round, 4.0, 0.8, &rng);
		RunAll(&m, &rng, "soup", 400, 150, 100);
	}
	/* One triangle; many copies of one triangle (coincident centroids). */
	TestMesh one = TestMeshSoup(1, 1.0, 1.0, &rng);
	RunAll(&one, &rng, "single", 300, 100, 100);
	TestMesh same = TestMeshSoup(40, 0.0, 1.0, &rng);
	for (int t = 1; t < same.triangleCount; ++t)
	{
		for (int k = 0; k < 3; ++k)
		{
			same.vertices[3 * t + k] = same.vertices[k];
		}
	}
	RunAll(&same, &rng, "copies", 200, 50, 50);
}

static void TestTerrain(void)
{
	TestRng rng = TestRngMake(0x7e44a1u);
	TestMesh m = TestMeshGrid(12, 1.0, TestTerrainHeight, &rng);
	RunAll(&m, &rng, "terrain", 500, 200, 150);
}

static void TestSphereMesh(void)
{
	TestRng rng = TestRngMake(0x5f3e4eu);
	const int rings = 10, segments = 12;
	TestMesh m = TestMeshSphere(cd3MakeVec(CD_R(1.0), CD_R(2.0), CD_R(3.0)), 2.0, rings, segments);
	cd3Mesh* mesh = Build(&m);
	if (mesh != NULL)
	{
		cd3MeshStats stats = cd3Mesh_GetStats(mesh);
		/* The pole fans: one zero-area triangle per quad of the first and last band. */
		TEST_CHECK(stats.droppedTriangleCount == 2 * segments &&
				   stats.triangleCount == 2 * rings * segments - 2 * segments);
		/* A closed surface: welded at the seam and the poles, no edge is a boundary; every edge is
		 * convex from outside and concave from inside (one active side), except the diagonals of
		 * the bands' quads, which are planar (inactive from both sides). */
		TEST_CHECK(stats.activeEdgeCount == 3 * stats.triangleCount - 2 * (rings - 2) * segments);
		cd3DestroyMesh(mesh);
	}
	RunAll(&m, &rng, "sphere", 500, 200, 150);
}

/* Rays through the mesh's vertices and edges, where cd3RaycastTriangle decides within its
 * tolerance and the walk's quick triangle test must not reject what it accepts: from near and
 * from far (up to 10^4 mesh sizes), ending beyond the point or exactly on it. */
static void CheckRaysThroughEdges(const TestMesh* m, cd3Aabb bounds, int count, TestRng* rng,
								  const char* name)
{
	cd3Mesh* mesh = Build(m);
	if (mesh == NULL)
	{
		return;
	}
	cdReal size = cd3Length(cd3Sub(bounds.max, bounds.min));
	int hits = 0;
	for (int i = 0; i < count; ++i)
	{
		int t = (int)((double)RandomReal(rng, 0.0, 1.0) * (double)m->triangleCount) % m->triangleCount;
		cd3Triangle tri = InputTriangle(m, t);
		cd3Vec target;
		if (i % 3 == 0)
		{
			target = i % 2 == 0 ? tri.a : tri.c; /* a vertex */
		}
		else
		{
			cdReal s = i % 3 == 1 ? CD_R(0.5) : RandomReal(rng, 0.0, 1.0); /* on an edge */
			target = cd3Add(tri.a, cd3Scale(s, cd3Sub(i % 2 == 0 ? tri.b : tri.c, tri.a)));
		}
		cdReal distances[3] = {CD_R(0.01), CD_R(1.0), CD_R(1.0e4)};
		cd3Vec from = cd3Add(target, RandomVec(rng, (double)(distances[i % 3] * size)));
		cd3Vec d = cd3Sub(target, from);
		if (i % 4 != 3)
		{
			d = cd3Scale(CD_R(1.5), d);
		}
		cd3Transform xf = i % 5 < 3 ? CD3_TRANSFORM_IDENTITY : RandomTransform(rng);
		cd3Ray ray = {cd3TransformPoint(xf, from), cd3RotateVector(xf.q, d)};
		hits += CheckRay(m, mesh, xf, ray, name, i) ? 1 : 0;
	}
	/* Aimed at the mesh: most rays hit it (some pass a silhouette edge or end just short). */
	TEST_CHECKF(hits > count / 2, "%s: %d hits of %d", name, hits, count);
	cd3DestroyMesh(mesh);
}

static void TestRaysThroughEdges(void)
{
	TestRng rng = TestRngMake(0xed9e5u);
	TestMesh terrain = TestMeshGrid(12, 1.0, TestTerrainHeight, &rng);
	CheckRaysThroughEdges(&terrain, MeshBounds(&terrain), 3000, &rng, "terrain edges");
	TestMesh sphere = TestMeshSphere(cd3MakeVec(CD_R(1.0), CD_R(2.0), CD_R(3.0)), 2.0, 10, 12);
	CheckRaysThroughEdges(&sphere, MeshBounds(&sphere), 3000, &rng, "sphere edges");
	TestMeshFree(&terrain);
	TestMeshFree(&sphere);
}

static void TestStats(void)
{
	TestRng rng = TestRngMake(0x57a75u);
	TestMesh m = TestMeshGrid(64, 1.0, TestTerrainHeight, &rng);
	cd3Mesh* mesh = Build(&m);
	if (mesh != NULL)
	{
		cd3MeshStats s = cd3Mesh_GetStats(mesh);
		TEST_CHECK(s.triangleCount == 2 * 64 * 64 && s.droppedTriangleCount == 0);
		/* 8-wide nodes with two to eight children each (nodes and leaves). */
		TEST_CHECKF(7 * s.nodeCount >= s.leafCount - 1 && s.nodeCount <= s.leafCount - 1 &&
						s.leafCount >= s.triangleCount / 8,
					"%d nodes, %d leaves", s.nodeCount, s.leafCount);
		/* A SAH tree of 8192 triangles is shallow and cheap: far below the linear list (cost n). */
		TEST_CHECKF(s.depth <= 30 && s.sahCost < 0.01 * s.triangleCount, "depth %d, cost %.1f", s.depth,
					s.sahCost);
		/* The triangles themselves plus the tree, the index maps and the flags. */
		TEST_CHECKF(s.bytes < (size_t)s.triangleCount * (sizeof(cd3Triangle) + 48), "%zu bytes", s.bytes);
		cd3DestroyMesh(mesh);
	}
	TestMeshFree(&m);
}

int main(void)
{
	TEST_RUN(TestBadInput);
	TEST_RUN(TestExact);
	TEST_RUN(TestSoup);
	TEST_RUN(TestTerrain);
	TEST_RUN(TestSphereMesh);
	TEST_RUN(TestRaysThroughEdges);
	TEST_RUN(TestStats);
	return TEST_SUMMARY();
}
