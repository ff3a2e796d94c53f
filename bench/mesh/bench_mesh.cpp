// collide_bench_mesh: triangle meshes. ns per closest-hit and any-hit ray cast on a terrain of
// about 100k triangles and on a latitude-longitude sphere of about 100k triangles, BVH build
// time, bytes per triangle, and ns per box (and sphere) manifold against the terrain; with
// Bullet's btBvhTriangleMeshShape (quantized BVH, btTriangleRaycastCallback) on the same meshes
// and the same rays in the same run. Hit counts of both are printed and compared, and so are the
// fractions of rays both hit.
//
// Bullet has no any-hit ray query on a triangle mesh (its callback can stop reporting, not the
// walk), so its any-hit column is n/a; its mesh manifolds need a collision world and dispatcher,
// so the manifold rows have no peer.
//
// Timing: thread CPU time (other processes on a shared machine stall no one's clock); each
// figure is the median of 5 runs over all the rays (or boxes).
// Usage: collide_bench_mesh [--quick]
#include <BulletCollision/CollisionShapes/btBvhTriangleMeshShape.h>
#include <BulletCollision/CollisionShapes/btOptimizedBvh.h>
#include <BulletCollision/CollisionShapes/btTriangleIndexVertexArray.h>
#include <BulletCollision/NarrowPhaseCollision/btRaycastCallback.h>

extern "C" {
#include "collide/mesh3.h"
}

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <functional>
#include <random>
#include <vector>

namespace
{
const double kPi = 3.14159265358979323846;

struct Mesh
{
	std::vector<cd3Vec> vertices;
	std::vector<int> indices;
	int TriangleCount() const
	{
		return (int)indices.size() / 3;
	}
};

double TerrainHeight(double x, double z)
{
	return 0.6 * std::sin(0.37 * x) * std::cos(0.29 * z) + 0.25 * std::sin(1.3 * x + 0.7 * z);
}

cd3Vec Vec(double x, double y, double z)
{
	return cd3MakeVec((cdReal)x, (cdReal)y, (cdReal)z);
}

// n by n cells of size 1 centred on the origin, two triangles each.
Mesh Terrain(int n)
{
	Mesh m;
	double half = 0.5 * n;
	for (int j = 0; j <= n; ++j)
	{
		for (int i = 0; i <= n; ++i)
		{
			double x = -half + i, z = -half + j;
			m.vertices.push_back(Vec(x, TerrainHeight(x, z), z));
		}
	}
	for (int j = 0; j < n; ++j)
	{
		for (int i = 0; i < n; ++i)
		{
			int v00 = j * (n + 1) + i, v10 = v00 + 1, v01 = v00 + n + 1, v11 = v01 + 1;
			int t[6] = {v00, v01, v10, v10, v01, v11};
			m.indices.insert(m.indices.end(), t, t + 6);
		}
	}
	return m;
}

// A unit sphere of rings by segments quads; the pole quads' zero-area halves are left out so that
// both libraries see the same triangles.
Mesh Sphere(int rings, int segments)
{
	Mesh m;
	for (int r = 0; r <= rings; ++r)
	{
		double theta = kPi * r / rings;
		for (int s = 0; s < segments; ++s)
		{
			double phi = 2.0 * kPi * s / segments;
			m.vertices.push_back(
				Vec(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)));
		}
	}
	for (int r = 0; r < rings; ++r)
	{
		for (int s = 0; s < segments; ++s)
		{
			int v00 = r * segments + s, v01 = r * segments + (s + 1) % segments;
			int v10 = v00 + segments, v11 = v01 + segments;
			if (r > 0)
			{
				int t[3] = {v00, v01, v10};
				m.indices.insert(m.indices.end(), t, t + 3);
			}
			if (r < rings - 1)
			{
				int t[3] = {v01, v11, v10};
				m.indices.insert(m.indices.end(), t, t + 3);
			}
		}
	}
	return m;
}

double CpuSeconds()
{
	timespec t;
	clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
	return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

// Median over `runs` runs of fn() (which does `count` operations), in ns per operation.
double TimeNs(int runs, int count, const std::function<void()>& fn)
{
	std::vector<double> t;
	for (int r = 0; r < runs; ++r)
	{
		double start = CpuSeconds();
		fn();
		t.push_back((CpuSeconds() - start) * 1e9 / count);
	}
	std::sort(t.begin(), t.end());
	return t[t.size() / 2];
}

struct BulletMesh
{
	std::vector<btScalar> vertices;
	std::vector<int> indices;
	btTriangleIndexVertexArray* array = nullptr;
	btBvhTriangleMeshShape* shape = nullptr;

	explicit BulletMesh(const Mesh& m) : indices(m.indices)
	{
		for (const cd3Vec& v : m.vertices)
		{
			vertices.push_back((btScalar)v.x);
			vertices.push_back((btScalar)v.y);
			vertices.push_back((btScalar)v.z);
		}
		array = new btTriangleIndexVertexArray(m.TriangleCount(), indices.data(), 3 * sizeof(int),
											   (int)m.vertices.size(), vertices.data(), 3 * sizeof(btScalar));
	}
	void Build()
	{
		delete shape;
		shape = new btBvhTriangleMeshShape(array, true, true);
	}
	size_t TreeBytes() const
	{
		btOptimizedBvh* bvh = shape->getOptimizedBvh();
		return (size_t)bvh->getQuantizedNodeArray().size() * sizeof(btQuantizedBvhNode) +
			   (size_t)bvh->getSubtreeInfoArray().size() * sizeof(btBvhSubtreeInfo);
	}
	~BulletMesh()
	{
		delete shape;
		delete array;
	}
};

struct ClosestCallback : public btTriangleRaycastCallback
{
	int triangle = -1;
	ClosestCallback(const btVector3& from, const btVector3& to) : btTriangleRaycastCallback(from, to, 0)
	{
	}
	btScalar reportHit(const btVector3&, btScalar fraction, int, int triangleIndex) override
	{
		triangle = triangleIndex;
		return fraction; // later triangles must be nearer
	}
};

struct RayResult
{
	bool hit;
	double fraction;
};

void RayRows(const char* name, const Mesh& m, const std::vector<cd3Ray>& rays, int runs)
{
	cd3Mesh* mesh = nullptr;
	double buildNs = TimeNs(runs, 1, [&] {
		cd3DestroyMesh(mesh);
		mesh = nullptr;
		cd3CreateMesh(m.vertices.data(), (int)m.vertices.size(), m.indices.data(), m.TriangleCount(), &mesh);
	});
	BulletMesh bullet(m);
	double bulletBuildNs = TimeNs(runs, 1, [&] { bullet.Build(); });
	cd3MeshStats stats = cd3Mesh_GetStats(mesh);
	int n = (int)rays.size();
	std::vector<RayResult> ours(n), theirs(n), any(n);
	cd3Transform id = CD3_TRANSFORM_IDENTITY;
	double closestNs = TimeNs(runs, n, [&] {
		for (int i = 0; i < n; ++i)
		{
			cd3MeshRayHit hit;
			ours[i].hit = cd3RaycastMesh(mesh, id, rays[i], &hit);
			ours[i].fraction = ours[i].hit ? (double)hit.hit.fraction : 2.0;
		}
	});
	double anyNs = TimeNs(runs, n, [&] {
		for (int i = 0; i < n; ++i)
		{
			any[i].hit = cd3RaycastMeshAny(mesh, id, rays[i]);
		}
	});
	double bulletNs = TimeNs(runs, n, [&] {
		for (int i = 0; i < n; ++i)
		{
			btVector3 from((btScalar)rays[i].origin.x, (btScalar)rays[i].origin.y,
						   (btScalar)rays[i].origin.z);
			btVector3 to = from + btVector3((btScalar)rays[i].translation.x, (btScalar)rays[i].translation.y,
											(btScalar)rays[i].translation.z);
			ClosestCallback cb(from, to);
			bullet.shape->performRaycast(&cb, from, to);
			theirs[i].hit = cb.triangle >= 0;
			theirs[i].fraction = cb.triangle >= 0 ? (double)cb.m_hitFraction : 2.0;
		}
	});
	int hits = 0, anyHits = 0, bulletHits = 0, disagree = 0;
	double maxFractionGap = 0.0;
	for (int i = 0; i < n; ++i)
	{
		hits += ours[i].hit;
		anyHits += any[i].hit;
		bulletHits += theirs[i].hit;
		disagree += ours[i].hit != theirs[i].hit;
		if (ours[i].hit && theirs[i].hit)
		{
			maxFractionGap = std::max(maxFractionGap, std::fabs(ours[i].fraction - theirs[i].fraction));
		}
	}
	std::printf(
		"%-8s %7d tris  build: collide %7.2f ms, Bullet %7.2f ms   bytes/tri: collide %.1f, Bullet tree %.1f"
		" (+%.1f for the mesh arrays it references)\n",
		name, stats.triangleCount, buildNs * 1e-6, bulletBuildNs * 1e-6,
		(double)stats.bytes / stats.triangleCount, (double)bullet.TreeBytes() / m.TriangleCount(),
		(double)(m.vertices.size() * 3 * sizeof(btScalar) + m.indices.size() * sizeof(int)) /
			m.TriangleCount());
	std::printf("%-8s tree: %d nodes, depth %d, SAH cost %.1f\n", name, stats.nodeCount, stats.depth,
				stats.sahCost);
	std::printf("%-8s ray closest: collide %7.1f ns, Bullet %7.1f ns (%.2fx)   any hit: collide %7.1f ns, "
				"Bullet n/a\n",
				name, closestNs, bulletNs, bulletNs / closestNs, anyNs);
	std::printf("%-8s hits of %d rays: collide %d (any-hit %d), Bullet %d; %d rays disagree%s; max fraction "
				"gap %.2g\n",
				name, n, hits, anyHits, bulletHits, disagree,
				hits == bulletHits && anyHits == hits && disagree == 0 ? " (identical)" : " (CHECK)",
				maxFractionGap);
	cd3DestroyMesh(mesh);
}

void ManifoldRows(const Mesh& terrain, double half, int count, int runs, std::mt19937& rng)
{
	cd3Mesh* mesh = nullptr;
	cd3CreateMesh(terrain.vertices.data(), (int)terrain.vertices.size(), terrain.indices.data(),
				  terrain.TriangleCount(), &mesh);
	std::uniform_real_distribution<double> xz(-half, half), yaw(0.0, 3.0);
	std::vector<cd3Shape> boxes, spheres;
	for (int i = 0; i < count; ++i)
	{
		double x = xz(rng), z = xz(rng);
		double h = TerrainHeight(x, z);
		cd3Box box = {Vec(x, h + 0.3 - 0.02, z), Vec(0.5, 0.3, 0.4),
					  cd3MakeQuatAxisAngle(Vec(0.0, 1.0, 0.0), (cdReal)yaw(rng))};
		boxes.push_back(cd3MakeBoxShape(box));
		cd3Sphere sphere = {Vec(x, h + 0.5 - 0.02, z), (cdReal)0.5};
		spheres.push_back(cd3MakeSphereShape(sphere));
	}
	std::vector<cd3MeshManifold> out(64);
	cd3Transform id = CD3_TRANSFORM_IDENTITY;
	long manifolds = 0;
	double boxNs = TimeNs(runs, count, [&] {
		manifolds = 0;
		for (const cd3Shape& s : boxes)
		{
			manifolds += cd3CollideMesh(&s, mesh, id, (cdReal)0.02, out.data(), (int)out.size());
		}
	});
	long sphereManifolds = 0;
	double sphereNs = TimeNs(runs, count, [&] {
		sphereManifolds = 0;
		for (const cd3Shape& s : spheres)
		{
			sphereManifolds += cd3CollideMesh(&s, mesh, id, (cdReal)0.02, out.data(), (int)out.size());
		}
	});
	std::printf(
		"terrain  manifold: box %7.1f ns (%.1f triangles in contact), sphere %7.1f ns (%.1f); Bullet n/a\n",
		boxNs, (double)manifolds / count, sphereNs, (double)sphereManifolds / count);
	cd3DestroyMesh(mesh);
}
} // namespace

int main(int argc, char** argv)
{
	bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
	int runs = quick ? 1 : 5;
	int rayCount = quick ? 200 : 20000;
	std::mt19937 rng(12345);
	std::printf("collide_bench_mesh (cdReal %s; median of %d runs, thread CPU time)\n",
				cdGetRealIsDouble() ? "double" : "float", runs);

	// Terrain: 224 x 224 cells, 100352 triangles. Rays from 2..10 above it, slanting down; their
	// lengths make some stop short.
	Mesh terrain = Terrain(quick ? 32 : 224);
	double half = quick ? 14.0 : 100.0;
	std::uniform_real_distribution<double> xz(-half, half), up(2.0, 10.0), slant(-20.0, 20.0),
		length(0.1, 1.0);
	std::vector<cd3Ray> terrainRays;
	for (int i = 0; i < rayCount; ++i)
	{
		cd3Vec o = Vec(xz(rng), up(rng), xz(rng));
		double k = length(rng);
		terrainRays.push_back(cd3Ray{o, Vec(k * slant(rng), -15.0 * k, k * slant(rng))});
	}
	RayRows("terrain", terrain, terrainRays, runs);

	// Sphere: 160 rings by 320 segments, 101760 triangles. Rays from a radius-3 shell towards
	// points within 1.2 of the centre (some pass beside it).
	Mesh sphere = Sphere(quick ? 16 : 160, quick ? 32 : 320);
	std::normal_distribution<double> gauss;
	std::uniform_real_distribution<double> inner(-1.2, 1.2);
	std::vector<cd3Ray> sphereRays;
	for (int i = 0; i < rayCount; ++i)
	{
		double x = gauss(rng), y = gauss(rng), z = gauss(rng);
		double l = std::sqrt(x * x + y * y + z * z);
		cd3Vec o = Vec(3.0 * x / l, 3.0 * y / l, 3.0 * z / l);
		cd3Vec target = Vec(inner(rng), inner(rng), inner(rng));
		sphereRays.push_back(cd3Ray{o, cd3Sub(target, o)});
	}
	RayRows("sphere", sphere, sphereRays, runs);

	ManifoldRows(terrain, half, quick ? 100 : 5000, runs, rng);
	return 0;
}
