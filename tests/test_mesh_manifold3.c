/* Manifolds of convex shapes against triangle meshes: shapes sliding over flat floors made of many
 * triangles (regular and randomly tessellated, moved by random transforms) get only the floor's
 * normal and the right depth at every position, convex ridges keep their edge normals, concave
 * valleys give face normals, a lone triangle gives exactly cd3Collide's manifold, and ids stay put
 * under small motions. */
#include "collide/mesh3.h"
#include "random_meshes3.h"
#include "random_shapes3.h"
#include "test.h"

#define CAPACITY 256

static cd3Mesh* Build(const TestMesh* m)
{
	cd3Mesh* mesh = NULL;
	cdResult result = cd3CreateMesh(m->vertices, m->vertexCount, m->indices, m->triangleCount, &mesh);
	TEST_CHECKF(result == CD_OK, "%s", cdGetResultString(result));
	return mesh;
}

/* Shapes resting with their lowest point at height -depth on the plane y = 0 of the frame xf,
 * centred at (x, z) and turned by `yaw` about the vertical. */
static cd3Shape RestingShape(int kind, cdReal x, cdReal z, cdReal yaw, cdReal depth, cd3Transform xf,
							 const cd3Hull* hull)
{
	cd3Quat turn = cd3MakeQuatAxisAngle(cd3MakeVec(CD_R(0.0), CD_R(1.0), CD_R(0.0)), yaw);
	cd3Shape s;
	memset(&s, 0, sizeof(s));
	switch (kind)
	{
		case 0:
			s = cd3MakeSphereShape((cd3Sphere){{x, CD_R(0.45) - depth, z}, CD_R(0.45)});
			break;
		case 1:
		{
			cd3Vec half = cd3RotateVector(turn, cd3MakeVec(CD_R(0.7), CD_R(0.0), CD_R(0.0)));
			cd3Vec c = {x, CD_R(0.3) - depth, z};
			s = cd3MakeCapsuleShape((cd3Capsule){cd3Sub(c, half), cd3Add(c, half), CD_R(0.3)});
			break;
		}
		case 2:
			s = cd3MakeBoxShape(
				(cd3Box){{x, CD_R(0.35) - depth, z}, {CD_R(0.8), CD_R(0.35), CD_R(0.55)}, turn});
			break;
		default:
			s = cd3MakeHullShape(hull, (cd3Transform){{x, CD_R(0.4) - depth, z}, turn});
			break;
	}
	return TransformShape(&s, xf);
}

static const char* KIND_NAMES[4] = {"sphere", "capsule", "box", "hull"};

/* Walks each shape along lines across the floor (grid lines, diagonals through vertices, random
 * lines) and checks every manifold: floor normal, every point at the depth, some contact always. */
static void SlideOverFloor(const TestMesh* floor, double halfSize, TestRng* rng, const char* name)
{
	cd3Mesh* mesh = Build(floor);
	if (mesh == NULL)
	{
		return;
	}
	cd3Hull* hull = NULL;
	TEST_CHECK(cd3MakeBoxHull(cd3MakeVec(CD_R(0.5), CD_R(0.4), CD_R(0.3)), &hull) == CD_OK);
	cd3MeshManifold* manifolds = (cd3MeshManifold*)malloc(CAPACITY * sizeof(cd3MeshManifold));
	cdReal depth = CD_R(0.02);
	int positions = 0, bad = 0;
	/* Paths 0-2 on the floor as given, 3-4 on the floor moved by a random transform. */
	for (int path = 0; path < 5; ++path)
	{
		cd3Transform xf =
			path < 3 ? CD3_TRANSFORM_IDENTITY : (cd3Transform){RandomVec(rng, 3.0), RandomQuat(rng)};
		cd3Vec down = cd3RotateVector(xf.q, cd3MakeVec(CD_R(0.0), -CD_R(1.0), CD_R(0.0)));
		double reach = halfSize - 1.2;
		double z0, z1;
		switch (path % 3)
		{
			case 0: /* along a grid line */
				z0 = z1 = 0.0;
				break;
			case 1: /* a diagonal through the grid's vertices */
				z0 = -reach, z1 = reach;
				break;
			default:
				z0 = TestRngRange(rng, -reach, reach), z1 = TestRngRange(rng, -reach, reach);
				break;
		}
		cdReal yaw = path % 3 == 1 ? CD_R(0.0) : RandomReal(rng, 0.0, 3.0);
		for (int step = 0; step <= 32; ++step)
		{
			double u = (double)step / 32.0;
			cdReal x = (cdReal)(-reach + 2.0 * reach * u), z = (cdReal)(z0 + (z1 - z0) * u);
			for (int kind = 0; kind < 4; ++kind)
			{
				cd3Shape shape = RestingShape(kind, x, z, yaw, depth, xf, hull);
				int count = cd3CollideMesh(&shape, mesh, xf, CD_R(0.01), manifolds, CAPACITY);
				++positions;
				int points = 0;
				cdReal deepest = CD_REAL_MAX;
				bool ok = count > 0 && count < CAPACITY;
				for (int i = 0; i < count; ++i)
				{
					cd3Manifold* m = &manifolds[i].manifold;
					ok = ok && cd3VecDistance(m->normal, down) <= CD_R(1e-3);
					for (int p = 0; p < m->pointCount; ++p)
					{
						ok = ok && cdAbs(m->points[p].separation + depth) <= CD_R(1e-3);
						deepest = cdMin(deepest, m->points[p].separation);
						++points;
					}
				}
				ok = ok && points > 0 && cdAbs(deepest + depth) <= CD_R(1e-3);
				if (!ok && ++bad <= 10)
				{
					TEST_CHECKF(ok, "%s, path %d step %d, %s at (%g, %g): %d manifolds, deepest %g", name,
								path, step, KIND_NAMES[kind], (double)x, (double)z, count, (double)deepest);
					for (int i = 0; i < count && i < 6; ++i)
					{
						cd3Manifold* m = &manifolds[i].manifold;
						fprintf(stderr, "  tri %d normal (%g %g %g) points %d sep0 %g\n",
								manifolds[i].triangleIndex, (double)m->normal.x, (double)m->normal.y,
								(double)m->normal.z, m->pointCount, (double)m->points[0].separation);
					}
				}
			}
		}
	}
	TEST_CHECKF(bad == 0, "%s: %d of %d positions wrong", name, bad, positions);
	free(manifolds);
	cd3DestroyHull(hull);
	cd3DestroyMesh(mesh);
}

static void TestRegularFloor(void)
{
	TestRng rng = TestRngMake(0xf1a7u);
	TestMesh floor = TestMeshGrid(10, 1.0, NULL, NULL);
	SlideOverFloor(&floor, 5.0, &rng, "regular floor");
	TestMeshFree(&floor);
}

static void TestRandomFloor(void)
{
	TestRng rng = TestRngMake(0x7a2d0f1u);
	for (int round = 0; round < 1; ++round)
	{
		TestMesh floor = TestMeshRandomFloor(10, 1.0, 150, &rng);
		SlideOverFloor(&floor, 5.0, &rng, "random floor");
		TestMeshFree(&floor);
	}
}

/* A roof: two slopes of `slope` radians meeting at the ridge x = 0 (convex seen from above,
 * concave from below when flip makes it a valley), 4 triangles per slope along z. */
static TestMesh Roof(double slope, bool valley)
{
	TestMesh m = TestMeshAllocate(3 * 5, 16);
	double drop = 2.0 * tan(slope) * (valley ? -1.0 : 1.0);
	for (int i = 0; i <= 4; ++i)
	{
		cdReal z = (cdReal)(-2.0 + i);
		m.vertices[3 * i] = cd3MakeVec(-CD_R(2.0), (cdReal)-drop, z);
		m.vertices[3 * i + 1] = cd3MakeVec(CD_R(0.0), CD_R(0.0), z);
		m.vertices[3 * i + 2] = cd3MakeVec(CD_R(2.0), (cdReal)-drop, z);
	}
	int t = 0;
	for (int i = 0; i < 4; ++i)
	{
		for (int side = 0; side < 2; ++side)
		{
			int a = 3 * i + side, b = a + 1, c = a + 3, d = a + 4;
			int* x = m.indices + 3 * t;
			/* counter-clockwise from above */
			x[0] = a, x[1] = c, x[2] = b;
			x[3] = b, x[4] = c, x[5] = d;
			t += 2;
		}
	}
	return m;
}

static void TestRidgeAndValley(void)
{
	cd3MeshManifold manifolds[CAPACITY];
	cdReal slope = CD_R(0.5); /* about 29 degrees */
	cd3Vec leftFace = {-(cdReal)sin(0.5), (cdReal)cos(0.5), CD_R(0.0)};
	cd3Vec rightFace = {(cdReal)sin(0.5), (cdReal)cos(0.5), CD_R(0.0)};
	{
		TestMesh roof = Roof((double)slope, false);
		cd3Mesh* mesh = Build(&roof);
		if (mesh != NULL)
		{
			/* A sphere on the ridge: the ridge's own normal, straight down, at the depth. */
			for (int i = 0; i <= 10; ++i)
			{
				cdReal z = CD_R(-1.5) + CD_R(0.3) * (cdReal)i;
				cd3Shape s = cd3MakeSphereShape((cd3Sphere){{CD_R(0.0), CD_R(0.48), z}, CD_R(0.5)});
				int count = cd3CollideMesh(&s, mesh, CD3_TRANSFORM_IDENTITY, CD_R(0.0), manifolds, CAPACITY);
				bool ok = count > 0;
				for (int k = 0; k < count; ++k)
				{
					cd3Manifold* m = &manifolds[k].manifold;
					ok = ok &&
						 cd3VecDistance(m->normal, cd3MakeVec(CD_R(0.0), -CD_R(1.0), CD_R(0.0))) <=
							 CD_R(1e-3) &&
						 cdAbs(m->points[0].separation + CD_R(0.02)) <= CD_R(1e-3);
				}
				TEST_CHECKF(ok, "ridge sphere at z %g: %d manifolds", (double)z, count);
				for (int k = 0; !ok && k < count; ++k)
				{
					cd3Manifold* m = &manifolds[k].manifold;
					fprintf(stderr, "  tri %d normal (%g %g %g) points %d sep0 %g p0 (%g %g %g)\n",
							manifolds[k].triangleIndex, (double)m->normal.x, (double)m->normal.y,
							(double)m->normal.z, m->pointCount, (double)m->points[0].separation,
							(double)m->points[0].point.x, (double)m->points[0].point.y,
							(double)m->points[0].point.z);
				}
			}
			/* A box lying on the ridge: its bottom face's normal, points along the ridge. */
			cd3Shape box = cd3MakeBoxShape((cd3Box){
				{CD_R(0.0), CD_R(0.29), CD_R(0.1)}, {CD_R(0.5), CD_R(0.3), CD_R(0.5)}, CD3_QUAT_IDENTITY});
			int count = cd3CollideMesh(&box, mesh, CD3_TRANSFORM_IDENTITY, CD_R(0.0), manifolds, CAPACITY);
			bool ok = count > 0;
			for (int k = 0; k < count; ++k)
			{
				cd3Manifold* m = &manifolds[k].manifold;
				ok = ok &&
					 cd3VecDistance(m->normal, cd3MakeVec(CD_R(0.0), -CD_R(1.0), CD_R(0.0))) <= CD_R(1e-3);
				for (int p = 0; p < m->pointCount; ++p)
				{
					ok = ok && cdAbs(m->points[p].point.x) <= CD_R(1e-3);
				}
			}
			TEST_CHECKF(ok, "ridge box: %d manifolds", count);
			for (int k = 0; !ok && k < count; ++k)
			{
				cd3Manifold* m = &manifolds[k].manifold;
				for (int p = 0; p < m->pointCount; ++p)
				{
					fprintf(stderr, "  tri %d normal (%g %g %g) sep %g point (%g %g %g)\n",
							manifolds[k].triangleIndex, (double)m->normal.x, (double)m->normal.y,
							(double)m->normal.z, (double)m->points[p].separation,
							(double)m->points[p].point.x, (double)m->points[p].point.y,
							(double)m->points[p].point.z);
				}
			}
			/* A sphere resting on one slope, away from the ridge: that face's normal. */
			cd3Vec c = cd3MulAdd(cd3MakeVec(CD_R(1.0), -(cdReal)tan(0.5), CD_R(0.0)), CD_R(0.49), rightFace);
			cd3Shape s = cd3MakeSphereShape((cd3Sphere){c, CD_R(0.5)});
			count = cd3CollideMesh(&s, mesh, CD3_TRANSFORM_IDENTITY, CD_R(0.0), manifolds, CAPACITY);
			ok = count > 0;
			for (int k = 0; k < count; ++k)
			{
				ok = ok && cd3VecDistance(manifolds[k].manifold.normal, cd3Neg(rightFace)) <= CD_R(1e-3) &&
					 cdAbs(manifolds[k].manifold.points[0].separation + CD_R(0.01)) <= CD_R(1e-3);
			}
			TEST_CHECKF(ok, "slope sphere: %d manifolds", count);
			cd3DestroyMesh(mesh);
		}
		TestMeshFree(&roof);
	}
	{
		/* A valley: a sphere touching both slopes gets the two face normals only, whichever
		 * triangles it meets, and slides along the valley without edge normals. */
		TestMesh valley = Roof((double)slope, true);
		cd3Mesh* mesh = Build(&valley);
		if (mesh != NULL)
		{
			cdReal r = CD_R(0.5);
			/* Touching both faces at depth 0.02: the centre on the axis at height (r - d) / cos. */
			cdReal h = (r - CD_R(0.02)) / (cdReal)cos(0.5);
			for (int i = 0; i <= 10; ++i)
			{
				cdReal z = CD_R(-1.5) + CD_R(0.3) * (cdReal)i;
				cd3Shape s = cd3MakeSphereShape((cd3Sphere){{CD_R(0.0), h, z}, r});
				int count = cd3CollideMesh(&s, mesh, CD3_TRANSFORM_IDENTITY, CD_R(0.0), manifolds, CAPACITY);
				bool ok = count >= 2, left = false, right = false;
				/* The valley's faces: the roof's mirrored. */
				cd3Vec leftUp = {-leftFace.x, leftFace.y, CD_R(0.0)};
				cd3Vec rightUp = {-rightFace.x, rightFace.y, CD_R(0.0)};
				for (int k = 0; k < count; ++k)
				{
					cd3Vec n = cd3Neg(manifolds[k].manifold.normal);
					bool isLeft = cd3VecDistance(n, leftUp) <= CD_R(1e-3);
					bool isRight = cd3VecDistance(n, rightUp) <= CD_R(1e-3);
					left = left || isLeft;
					right = right || isRight;
					ok = ok && (isLeft || isRight) &&
						 cdAbs(manifolds[k].manifold.points[0].separation + CD_R(0.02)) <= CD_R(1e-3);
				}
				TEST_CHECKF(ok && left && right, "valley sphere at z %g: %d manifolds", (double)z, count);
			}
			cd3DestroyMesh(mesh);
		}
		TestMeshFree(&valley);
	}
}

/* A mesh of one triangle has only boundary edges, all active: exactly cd3Collide's answer. */
static void TestLoneTriangle(void)
{
	TestRng rng = TestRngMake(0x10e7u);
	cd3MeshManifold manifolds[4];
	int contacts = 0;
	for (int i = 0; i < 500; ++i)
	{
		cd3Shape tri = RandomShape(&rng, CD3_SHAPE_TRIANGLE);
		if (!cd3IsValidTriangle(tri.triangle))
		{
			continue;
		}
		cd3Vec v[3] = {tri.triangle.a, tri.triangle.b, tri.triangle.c};
		int idx[3] = {0, 1, 2};
		cd3Mesh* mesh = NULL;
		if (cd3CreateMesh(v, 3, idx, 1, &mesh) != CD_OK)
		{
			TEST_CHECK(false);
			continue;
		}
		static const cd3ShapeType types[5] = {CD3_SHAPE_SPHERE, CD3_SHAPE_CAPSULE, CD3_SHAPE_AABB,
											  CD3_SHAPE_BOX, CD3_SHAPE_HULL};
		cd3Shape shape = RandomShape(&rng, types[TestRngInt(&rng, 5)]);
		cd3Manifold expected = cd3Collide(&shape, &tri, CD_R(0.05));
		int count = cd3CollideMesh(&shape, mesh, CD3_TRANSFORM_IDENTITY, CD_R(0.05), manifolds, 4);
		bool same = count == (expected.pointCount > 0 ? 1 : 0);
		if (same && count == 1)
		{
			cd3Manifold* m = &manifolds[0].manifold;
			same = manifolds[0].triangleIndex == 0 && m->pointCount == expected.pointCount &&
				   cd3VecEqual(m->normal, expected.normal);
			for (int p = 0; same && p < m->pointCount; ++p)
			{
				same = cd3VecEqual(m->points[p].point, expected.points[p].point) &&
					   m->points[p].separation == expected.points[p].separation &&
					   m->points[p].id == expected.points[p].id;
			}
			++contacts;
		}
		TEST_CHECKF(same, "case %d (%s): mesh %d manifolds, cd3Collide %d points", i,
					cd3GetShapeTypeName(shape.type), count, expected.pointCount);
		cd3DestroyMesh(mesh);
	}
	TEST_CHECKF(contacts > 20, "%d contacts", contacts);
}

/* The (triangle, id) keys of a box resting on the random floor stay the same under motions far
 * smaller than the triangles. */
static void TestStableIds(void)
{
	TestRng rng = TestRngMake(0x1d5u);
	TestMesh floor = TestMeshRandomFloor(8, 1.0, 60, &rng);
	cd3Mesh* mesh = Build(&floor);
	if (mesh == NULL)
	{
		TestMeshFree(&floor);
		return;
	}
	static cd3MeshManifold a[CAPACITY], b[CAPACITY];
	int stable = 0, trials = 0;
	for (int i = 0; i < 100; ++i)
	{
		cdReal x = RandomReal(&rng, -2.5, 2.5), z = RandomReal(&rng, -2.5, 2.5),
			   yaw = RandomReal(&rng, 0.0, 3.0);
		int kind = TestRngInt(&rng, 3);
		cd3Shape s0 = RestingShape(kind, x, z, yaw, CD_R(0.02), CD3_TRANSFORM_IDENTITY, NULL);
		cd3Shape s1 = RestingShape(kind, x + CD_R(1e-4), z - CD_R(1e-4), yaw, CD_R(0.0201),
								   CD3_TRANSFORM_IDENTITY, NULL);
		int na = cd3CollideMesh(&s0, mesh, CD3_TRANSFORM_IDENTITY, CD_R(0.01), a, CAPACITY);
		int nb = cd3CollideMesh(&s1, mesh, CD3_TRANSFORM_IDENTITY, CD_R(0.01), b, CAPACITY);
		++trials;
		/* Same triangles in the same order (the same BVH walk), same ids. */
		bool same = na == nb;
		for (int k = 0; same && k < na; ++k)
		{
			same = a[k].triangleIndex == b[k].triangleIndex &&
				   a[k].manifold.pointCount == b[k].manifold.pointCount;
			for (int p = 0; same && p < a[k].manifold.pointCount; ++p)
			{
				same = a[k].manifold.points[p].id == b[k].manifold.points[p].id;
			}
		}
		stable += same ? 1 : 0;
	}
	/* A motion can cross a clip boundary by chance (a corner passing a vertex): nearly all stay. */
	TEST_CHECKF(stable >= trials * 95 / 100, "%d of %d stable", stable, trials);
	cd3DestroyMesh(mesh);
	TestMeshFree(&floor);
}

static void TestEdgeCases(void)
{
	TestMesh floor = TestMeshGrid(4, 1.0, NULL, NULL);
	cd3Mesh* mesh = Build(&floor);
	if (mesh != NULL)
	{
		cd3MeshManifold manifolds[CAPACITY];
		cd3Shape box = cd3MakeBoxShape((cd3Box){
			{CD_R(0.0), CD_R(0.49), CD_R(0.0)}, {CD_R(1.5), CD_R(0.5), CD_R(1.5)}, CD3_QUAT_IDENTITY});
		int all = cd3CollideMesh(&box, mesh, CD3_TRANSFORM_IDENTITY, CD_R(0.0), manifolds, CAPACITY);
		TEST_CHECK(all > 4);
		TEST_CHECK(cd3CollideMesh(&box, mesh, CD3_TRANSFORM_IDENTITY, CD_R(0.0), manifolds, 3) == 3);
		TEST_CHECK(cd3CollideMesh(&box, mesh, CD3_TRANSFORM_IDENTITY, CD_R(0.0), manifolds, 0) == 0);
		/* Far above: nothing, even within a speculative distance smaller than the gap. */
		box.box.center.y = CD_R(0.7);
		TEST_CHECK(cd3CollideMesh(&box, mesh, CD3_TRANSFORM_IDENTITY, CD_R(0.1), manifolds, CAPACITY) == 0);
		/* Speculative: a gap of 0.05 within 0.1 reports positive separations. */
		box.box.center.y = CD_R(0.55);
		int n = cd3CollideMesh(&box, mesh, CD3_TRANSFORM_IDENTITY, CD_R(0.1), manifolds, CAPACITY);
		bool ok = n > 0;
		for (int k = 0; k < n; ++k)
		{
			for (int p = 0; p < manifolds[k].manifold.pointCount; ++p)
			{
				ok = ok && cdAbs(manifolds[k].manifold.points[p].separation - CD_R(0.05)) <= CD_R(1e-4);
			}
		}
		TEST_CHECK(ok);
		/* Shapes without a manifold against triangles. */
		cd3Shape plane = cd3MakePlaneShape((cd3Plane){{CD_R(0.0), CD_R(1.0), CD_R(0.0)}, CD_R(0.0)});
		cd3Shape segment = cd3MakeSegmentShape(
			(cd3Segment){{CD_R(0.0), -CD_R(1.0), CD_R(0.0)}, {CD_R(0.0), CD_R(1.0), CD_R(0.0)}});
		cd3Shape triangle = cd3MakeTriangleShape((cd3Triangle){{0, 0, 0}, {1, 1, 0}, {0, 1, 1}});
		TEST_CHECK(cd3CollideMesh(&plane, mesh, CD3_TRANSFORM_IDENTITY, CD_R(0.0), manifolds, CAPACITY) == 0);
		TEST_CHECK(cd3CollideMesh(&segment, mesh, CD3_TRANSFORM_IDENTITY, CD_R(0.0), manifolds, CAPACITY) ==
				   0);
		TEST_CHECK(cd3CollideMesh(&triangle, mesh, CD3_TRANSFORM_IDENTITY, CD_R(0.0), manifolds, CAPACITY) ==
				   0);
		/* Degenerate shapes: a zero-radius sphere and a zero-size box on the floor. */
		cd3Shape point = cd3MakeSphereShape((cd3Sphere){{CD_R(0.3), CD_R(0.0), CD_R(0.2)}, CD_R(0.0)});
		n = cd3CollideMesh(&point, mesh, CD3_TRANSFORM_IDENTITY, CD_R(0.0), manifolds, CAPACITY);
		TEST_CHECK(n >= 1 && manifolds[0].manifold.points[0].separation == CD_R(0.0));
		cd3Shape flat =
			cd3MakeBoxShape((cd3Box){{CD_R(0.3), CD_R(0.0), CD_R(0.2)}, {0, 0, 0}, CD3_QUAT_IDENTITY});
		n = cd3CollideMesh(&flat, mesh, CD3_TRANSFORM_IDENTITY, CD_R(0.0), manifolds, CAPACITY);
		ok = n >= 1;
		for (int k = 0; k < n; ++k)
		{
			ok = ok && cd3IsValidVec(manifolds[k].manifold.normal) &&
				 cdIsValidReal(manifolds[k].manifold.points[0].separation);
		}
		TEST_CHECK(ok);
		cd3DestroyMesh(mesh);
	}
	TestMeshFree(&floor);
}

int main(void)
{
	TEST_RUN(TestRegularFloor);
	TEST_RUN(TestRandomFloor);
	TEST_RUN(TestRidgeAndValley);
	TEST_RUN(TestLoneTriangle);
	TEST_RUN(TestStableIds);
	TEST_RUN(TestEdgeCases);
	return TEST_SUMMARY();
}
