/* Tests of the 3D convex hull builder (cd3ComputeHull) and validator: exact solids, coplanar
 * merging, welding, degenerate and bad input, scales, and thousands of random clouds whose hulls
 * must validate, contain every input point and reach as far as the cloud in every direction. */
#include "collide/geometry3.h"
#include "collide/query3.h"
#include "random_shapes3.h"
#include "test.h"

#include <string.h>

/* Every face plane has every point below it within the hull's tolerance. */
static double WorstContainment(const cd3Hull* hull, const cd3Vec* points, int count)
{
	double worst = -INFINITY;
	for (int f = 0; f < hull->faceCount; ++f)
	{
		cd3Plane plane = hull->planes[f];
		for (int i = 0; i < count; ++i)
		{
			double h = (double)plane.normal.x * (double)points[i].x +
					   (double)plane.normal.y * (double)points[i].y +
					   (double)plane.normal.z * (double)points[i].z - (double)plane.offset;
			worst = h > worst ? h : worst;
		}
	}
	return worst;
}

/* Largest gap, over random directions, between the cloud's reach and the hull's reach. */
static double WorstSupportGap(TestRng* rng, const cd3Hull* hull, const cd3Vec* points, int count)
{
	double worst = 0.0;
	for (int k = 0; k < 64; ++k)
	{
		cd3Vec d = RandomUnit(rng);
		double cloud = -INFINITY, reach = -INFINITY;
		for (int i = 0; i < count; ++i)
		{
			double s = (double)d.x * (double)points[i].x + (double)d.y * (double)points[i].y +
					   (double)d.z * (double)points[i].z;
			cloud = s > cloud ? s : cloud;
		}
		for (int i = 0; i < hull->vertexCount; ++i)
		{
			cd3Vec v = hull->vertices[i];
			double s = (double)d.x * (double)v.x + (double)d.y * (double)v.y + (double)d.z * (double)v.z;
			reach = s > reach ? s : reach;
		}
		double gap = fabs(cloud - reach);
		worst = gap > worst ? gap : worst;
	}
	return worst;
}

/* Every hull vertex is one of the input points, bit for bit. */
static bool VerticesAreInputPoints(const cd3Hull* hull, const cd3Vec* points, int count)
{
	for (int v = 0; v < hull->vertexCount; ++v)
	{
		bool found = false;
		for (int i = 0; i < count && !found; ++i)
		{
			found = cd3VecEqual(hull->vertices[v], points[i]);
		}
		if (!found)
		{
			return false;
		}
	}
	return true;
}

/* Builds the hull of the cloud and runs the generic checks; returns it (or NULL) for more. */
static cd3Hull* CheckCloud(TestRng* rng, const char* label, const cd3Vec* points, int count)
{
	cd3Hull* hull = NULL;
	cdResult result = cd3ComputeHull(points, count, &hull);
	TEST_CHECKF(result == CD_OK && hull != NULL, "%s (%d points): %s", label, count,
				cdGetResultString(result));
	if (hull == NULL)
	{
		return NULL;
	}
	cdResult valid = cd3ValidateHull(hull);
	TEST_CHECKF(valid == CD_OK, "%s (%d points): the hull does not validate: %s", label, count,
				cdGetResultString(valid));
	double tolerance = (double)cd3Hull_GetTolerance(hull);
	double containment = WorstContainment(hull, points, count);
	TEST_CHECKF(containment <= tolerance, "%s (%d points): a point lies %.3g above a face (tolerance %.3g)",
				label, count, containment, tolerance);
	double gap = WorstSupportGap(rng, hull, points, count);
	TEST_CHECKF(gap <= tolerance, "%s (%d points): the hull falls %.3g short of the cloud (tolerance %.3g)",
				label, count, gap, tolerance);
	TEST_CHECKF(VerticesAreInputPoints(hull, points, count), "%s: a hull vertex is not an input point",
				label);
	TEST_CHECKF(hull->vertexCount - hull->edgeCount / 2 + hull->faceCount == 2, "%s: V - E + F = %d", label,
				hull->vertexCount - hull->edgeCount / 2 + hull->faceCount);
	return hull;
}

static cd3Vec V3(double x, double y, double z)
{
	return cd3MakeVec((cdReal)x, (cdReal)y, (cdReal)z);
}

static void TestCube(void)
{
	TestRng rng = TestRngMake(0x4e11001u);
	cd3Vec corners[8];
	for (int i = 0; i < 8; ++i)
	{
		corners[i] = V3((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0);
	}
	cd3Hull* hull = CheckCloud(&rng, "cube", corners, 8);
	if (hull == NULL)
	{
		return;
	}
	TEST_CHECK(hull->vertexCount == 8 && hull->faceCount == 6 && hull->edgeCount == 24);
	TEST_CHECK_NEAR(hull->volume, 8.0, 1e-5);
	TEST_CHECK_NEAR(cd3Length(hull->centroid), 0.0, 1e-6);
	TEST_CHECK(cd3VecEqual(hull->bounds.min, V3(-1, -1, -1)) && cd3VecEqual(hull->bounds.max, V3(1, 1, 1)));
	int axes[6] = {0, 0, 0, 0, 0, 0};
	for (int f = 0; f < 6; ++f)
	{
		cd3Vec n = hull->planes[f].normal;
		int count = 0;
		for (int e = hull->faceEdges[f], k = 0; k == 0 || e != hull->faceEdges[f];
			 e = hull->edges[e].next, ++k)
		{
			++count;
		}
		TEST_CHECKF(count == 4, "face %d has %d vertices", f, count);
		TEST_CHECK_NEAR(hull->planes[f].offset, 1.0, 1e-6);
		for (int a = 0; a < 3; ++a)
		{
			double c = (double)cd3GetComponent(n, a);
			if (fabs(c - 1.0) < 1e-6)
			{
				++axes[2 * a];
			}
			if (fabs(c + 1.0) < 1e-6)
			{
				++axes[2 * a + 1];
			}
		}
	}
	for (int i = 0; i < 6; ++i)
	{
		TEST_CHECKF(axes[i] == 1, "axis direction %d used by %d faces", i, axes[i]);
	}
	cd3DestroyHull(hull);
}

/* Random tetrahedra: 4 vertices, 4 faces, the volume |det| / 6 and the vertex mean as centroid. */
static void TestTetrahedra(void)
{
	TestRng rng = TestRngMake(0x4e11002u);
	for (int i = 0; i < 500; ++i)
	{
		cd3Vec p[4];
		for (int k = 0; k < 4; ++k)
		{
			p[k] = RandomVec(&rng, 2.0);
		}
		double e[3][3];
		for (int k = 0; k < 3; ++k)
		{
			e[k][0] = (double)p[k + 1].x - (double)p[0].x;
			e[k][1] = (double)p[k + 1].y - (double)p[0].y;
			e[k][2] = (double)p[k + 1].z - (double)p[0].z;
		}
		double det = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
					 e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
					 e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
		if (fabs(det) < 0.05)
		{
			continue; /* nearly flat: merging may rightly treat it as degenerate */
		}
		cd3Hull* hull = CheckCloud(&rng, "tetrahedron", p, 4);
		if (hull == NULL)
		{
			continue;
		}
		TEST_CHECK(hull->vertexCount == 4 && hull->faceCount == 4 && hull->edgeCount == 12);
		TEST_CHECK_NEAR(hull->volume, fabs(det) / 6.0, 1e-5 * (1.0 + fabs(det)));
		cd3Vec mean = cd3Scale(CD_R(0.25), cd3Add(cd3Add(p[0], p[1]), cd3Add(p[2], p[3])));
		TEST_CHECK_NEAR(cd3VecDistance(mean, hull->centroid), 0.0, 1e-5);
		cd3DestroyHull(hull);
	}
}

static void TestRandomClouds(void)
{
	TestRng rng = TestRngMake(0x4e11003u);
	cd3Vec points[300];
	for (int i = 0; i < 600; ++i)
	{
		int count = 4 + TestRngInt(&rng, 150);
		int kind = TestRngInt(&rng, 3);
		cd3Vec scale =
			V3(TestRngRange(&rng, 0.1, 2.0), TestRngRange(&rng, 0.1, 2.0), TestRngRange(&rng, 0.1, 2.0));
		for (int k = 0; k < count; ++k)
		{
			cd3Vec p = kind == 0 ? RandomVec(&rng, 1.0) : RandomUnit(&rng);
			if (kind == 2)
			{
				/* On a grid: many exactly coplanar and collinear points. */
				p = V3((double)TestRngInt(&rng, 4), (double)TestRngInt(&rng, 4), (double)TestRngInt(&rng, 4));
			}
			points[k] = cd3MulComponents(scale, p);
		}
		cd3Hull* hull = NULL;
		cdResult result = cd3ComputeHull(points, count, &hull);
		if (result == CD_ERROR_DEGENERATE)
		{
			/* Only small grid clouds can be flat; the others are solid with certainty. */
			TEST_CHECKF(kind == 2 && count < 40, "random cloud kind %d of %d points called degenerate", kind,
						count);
			continue;
		}
		cd3DestroyHull(hull);
		hull = CheckCloud(&rng, kind == 0 ? "ball cloud" : (kind == 1 ? "sphere cloud" : "grid cloud"),
						  points, count);
		cd3DestroyHull(hull);
	}
}

/* Thousands of points on a sphere: every point is a vertex (none is coplanar with its
 * neighbours at this density), the faces are triangles. */
static void TestSphereCloud(void)
{
	TestRng rng = TestRngMake(0x4e11004u);
	static cd3Vec points[4096];
	const int counts[2] = {500, 2000};
	for (int c = 0; c < 2; ++c)
	{
		int count = counts[c];
		for (int i = 0; i < count; ++i)
		{
			points[i] = cd3Scale(CD_R(3.0), RandomUnit(&rng));
		}
		cd3Hull* hull = CheckCloud(&rng, "sphere", points, count);
		if (hull != NULL)
		{
			TEST_CHECKF(hull->vertexCount >= count * 99 / 100, "%d of %d points are vertices",
						hull->vertexCount, count);
			double exact = 4.0 / 3.0 * CD_PI * 27.0;
			TEST_CHECKF(hull->volume < exact && hull->volume > 0.97 * exact, "volume %g of %g",
						(double)hull->volume, exact);
		}
		cd3DestroyHull(hull);
	}
}

/* A box given by many points on each face (a grid, rotated) has 6 faces and 8 vertices. */
static void TestCoplanarMerging(void)
{
	TestRng rng = TestRngMake(0x4e11005u);
	static cd3Vec points[6 * 49];
	for (int trial = 0; trial < 50; ++trial)
	{
		cd3Quat q = trial == 0 ? CD3_QUAT_IDENTITY : RandomQuat(&rng);
		cd3Vec half =
			V3(TestRngRange(&rng, 0.2, 2.0), TestRngRange(&rng, 0.2, 2.0), TestRngRange(&rng, 0.2, 2.0));
		cd3Vec center = RandomVec(&rng, 3.0);
		int count = 0;
		for (int face = 0; face < 6; ++face)
		{
			int axis = face / 2;
			double sign = (face & 1) ? -1.0 : 1.0;
			for (int i = 0; i < 7; ++i)
			{
				for (int j = 0; j < 7; ++j)
				{
					double u = -1.0 + i / 3.0, v = -1.0 + j / 3.0;
					double c[3];
					c[axis] = sign;
					c[(axis + 1) % 3] = u;
					c[(axis + 2) % 3] = v;
					cd3Vec local = V3(c[0] * (double)half.x, c[1] * (double)half.y, c[2] * (double)half.z);
					points[count++] = cd3Add(center, cd3RotateVector(q, local));
				}
			}
		}
		cd3Hull* hull = CheckCloud(&rng, "box grid", points, count);
		if (hull != NULL)
		{
			TEST_CHECKF(hull->faceCount == 6 && hull->vertexCount == 8 && hull->edgeCount == 24,
						"box grid: %d faces, %d vertices, %d half-edges", hull->faceCount, hull->vertexCount,
						hull->edgeCount);
			double volume = 8.0 * (double)half.x * (double)half.y * (double)half.z;
			TEST_CHECK_NEAR(hull->volume, volume, 1e-4 * volume);
			TEST_CHECK_NEAR(cd3VecDistance(hull->centroid, center), 0.0, 1e-5);
		}
		cd3DestroyHull(hull);
	}

	/* Prisms and pyramids: flat caps are one face each. */
	for (int segments = 3; segments <= 64; segments += 5)
	{
		cd3Hull* cylinder = NULL;
		TEST_CHECK(cd3MakeCylinderHull(CD_R(0.5), CD_R(2.0), segments, &cylinder) == CD_OK);
		if (cylinder != NULL)
		{
			TEST_CHECK(cd3ValidateHull(cylinder) == CD_OK);
			TEST_CHECKF(cylinder->faceCount == segments + 2 && cylinder->vertexCount == 2 * segments,
						"cylinder of %d: %d faces, %d vertices", segments, cylinder->faceCount,
						cylinder->vertexCount);
			double area = 0.5 * segments * 4.0 * sin(2.0 * CD_PI / segments);
			TEST_CHECK_NEAR(cylinder->volume, area, 1e-5 * area);
			TEST_CHECK_NEAR(cd3Length(cylinder->centroid), 0.0, 1e-5);
		}
		cd3DestroyHull(cylinder);
		cd3Hull* cone = NULL;
		TEST_CHECK(cd3MakeConeHull(CD_R(1.5), CD_R(1.0), segments, &cone) == CD_OK);
		if (cone != NULL)
		{
			TEST_CHECK(cd3ValidateHull(cone) == CD_OK);
			TEST_CHECKF(cone->faceCount == segments + 1 && cone->vertexCount == segments + 1,
						"cone of %d: %d faces, %d vertices", segments, cone->faceCount, cone->vertexCount);
			double area = 0.5 * segments * sin(2.0 * CD_PI / segments);
			TEST_CHECK_NEAR(cone->volume, area * 3.0 / 3.0, 1e-5);
			/* The centroid of a cone is a quarter of the way up from the base. */
			TEST_CHECK_NEAR(cone->centroid.y, -1.5 + 0.75, 1e-5);
		}
		cd3DestroyHull(cone);
	}
}

/* Near-duplicate points (a few epsilons of the extent apart) are welded: a cube whose corners
 * are each given eight times with jitter still has 8 vertices and 6 faces. */
static void TestWelding(void)
{
	TestRng rng = TestRngMake(0x4e11006u);
	cd3Vec points[64];
	double jitter = 2.0 * (double)CD_REAL_EPSILON;
	for (int trial = 0; trial < 100; ++trial)
	{
		for (int i = 0; i < 64; ++i)
		{
			int c = i % 8;
			cd3Vec corner = V3((c & 1) ? 1.0 : -1.0, (c & 2) ? 1.0 : -1.0, (c & 4) ? 1.0 : -1.0);
			points[i] = i < 8 ? corner : cd3Add(corner, cd3Scale((cdReal)jitter, RandomVec(&rng, 1.0)));
		}
		cd3Hull* hull = CheckCloud(&rng, "jittered cube", points, 64);
		if (hull != NULL)
		{
			TEST_CHECKF(hull->vertexCount == 8 && hull->faceCount == 6,
						"jittered cube: %d vertices, %d faces", hull->vertexCount, hull->faceCount);
		}
		cd3DestroyHull(hull);
	}
	/* Exact duplicates of every point of a random cloud change nothing. */
	for (int trial = 0; trial < 100; ++trial)
	{
		for (int i = 0; i < 32; ++i)
		{
			points[i] = RandomVec(&rng, 1.0);
			points[i + 32] = points[i];
		}
		cd3Hull* once = NULL;
		cd3Hull* twice = NULL;
		TEST_CHECK(cd3ComputeHull(points, 32, &once) == CD_OK);
		TEST_CHECK(cd3ComputeHull(points, 64, &twice) == CD_OK);
		if (once != NULL && twice != NULL)
		{
			TEST_CHECK(once->vertexCount == twice->vertexCount && once->faceCount == twice->faceCount);
			TEST_CHECK_NEAR(once->volume, twice->volume, 1e-6);
		}
		cd3DestroyHull(once);
		cd3DestroyHull(twice);
	}
}

static void ExpectResult(const char* label, const cd3Vec* points, int count, cdResult expected)
{
	cd3Hull* hull = (cd3Hull*)(uintptr_t)1;
	cdResult result = cd3ComputeHull(points, count, &hull);
	TEST_CHECKF(result == expected && hull == NULL, "%s: %s, expected %s", label, cdGetResultString(result),
				cdGetResultString(expected));
	if (result == CD_OK)
	{
		cd3DestroyHull(hull);
	}
}

static void TestDegenerateAndBadInput(void)
{
	TestRng rng = TestRngMake(0x4e11007u);
	static cd3Vec points[CD3_MAX_HULL_POINTS + 1];
	for (int trial = 0; trial < 200; ++trial)
	{
		int count = 4 + TestRngInt(&rng, 60);
		cd3Quat q = RandomQuat(&rng);
		cd3Vec center = RandomVec(&rng, 5.0);
		cd3Vec axis = RandomUnit(&rng);
		cd3Vec point = RandomVec(&rng, 5.0);
		for (int i = 0; i < count; ++i)
		{
			cd3Vec flat = V3(TestRngRange(&rng, -2.0, 2.0), TestRngRange(&rng, -2.0, 2.0), 0.0);
			points[i] = cd3Add(center, cd3RotateVector(q, flat));
		}
		ExpectResult("flat", points, count, CD_ERROR_DEGENERATE);
		for (int i = 0; i < count; ++i)
		{
			points[i] = cd3MulAdd(center, RandomReal(&rng, -3.0, 3.0), axis);
		}
		ExpectResult("collinear (needle)", points, count, CD_ERROR_DEGENERATE);
		for (int i = 0; i < count; ++i)
		{
			points[i] = point;
		}
		ExpectResult("coincident", points, count, CD_ERROR_DEGENERATE);
		for (int i = 0; i < 3; ++i)
		{
			points[i] = RandomVec(&rng, 2.0);
		}
		ExpectResult("three points", points, 3, CD_ERROR_DEGENERATE);
	}
	/* Axis-aligned flat sets, and a square with its centre. */
	cd3Vec square[5] = {V3(0, 0, 0), V3(1, 0, 0), V3(1, 1, 0), V3(0, 1, 0), V3(0.5, 0.5, 0)};
	ExpectResult("square", square, 5, CD_ERROR_DEGENERATE);
	ExpectResult("no points", square, 0, CD_ERROR_DEGENERATE);
	ExpectResult("NULL points", NULL, 5, CD_ERROR_INVALID_ARGUMENT);
	ExpectResult("negative count", square, -1, CD_ERROR_INVALID_ARGUMENT);
	TEST_CHECK(cd3ComputeHull(square, 5, NULL) == CD_ERROR_INVALID_ARGUMENT);

	cd3Vec bad[5] = {V3(0, 0, 0), V3(1, 0, 0), V3(0, 1, 0), V3(0, 0, 1), V3(1, 1, 1)};
	bad[3].y = (cdReal)NAN;
	ExpectResult("NaN", bad, 5, CD_ERROR_NOT_FINITE);
	bad[3].y = (cdReal)INFINITY;
	ExpectResult("infinity", bad, 5, CD_ERROR_NOT_FINITE);

	for (int i = 0; i <= CD3_MAX_HULL_POINTS; ++i)
	{
		points[i] = RandomVec(&rng, 1.0);
	}
	ExpectResult("too many points", points, CD3_MAX_HULL_POINTS + 1, CD_ERROR_TOO_MANY_POINTS);

	/* Builders check their sizes. */
	cd3Hull* hull = NULL;
	TEST_CHECK(cd3MakeBoxHull(V3(1, 0, 1), &hull) == CD_ERROR_DEGENERATE && hull == NULL);
	TEST_CHECK(cd3MakeBoxHull(V3(1, -1, 1), &hull) == CD_ERROR_NEGATIVE_SIZE && hull == NULL);
	TEST_CHECK(cd3MakeBoxHull(V3(1, NAN, 1), &hull) == CD_ERROR_NOT_FINITE && hull == NULL);
	TEST_CHECK(cd3MakeCylinderHull(CD_R(1.0), CD_R(1.0), 2, &hull) == CD_ERROR_INVALID_ARGUMENT &&
			   hull == NULL);
	TEST_CHECK(cd3MakeCylinderHull(CD_R(0.0), CD_R(1.0), 8, &hull) == CD_ERROR_DEGENERATE && hull == NULL);
	TEST_CHECK(cd3MakeConeHull(CD_R(1.0), CD_R(-1.0), 8, &hull) == CD_ERROR_NEGATIVE_SIZE && hull == NULL);
	TEST_CHECK(cd3MakeBoxHull(V3(1, 2, 3), &hull) == CD_OK && hull != NULL);
	if (hull != NULL)
	{
		TEST_CHECK(hull->faceCount == 6 && hull->vertexCount == 8);
		TEST_CHECK_NEAR(hull->volume, 48.0, 1e-4);
	}
	cd3DestroyHull(hull);
	cd3DestroyHull(NULL);

	/* Far beyond the documented range: a box whose volume overflows cdReal (fuzz_hull3 found the
	 * float case) is refused, never handed out with an infinite volume. */
	cdReal huge = (cdReal)(cdGetRealIsDouble() ? 1e150 : 1e37);
	hull = NULL;
	cdResult result = cd3MakeBoxHull(V3(huge, huge, huge), &hull);
	TEST_CHECKF(result == CD_ERROR_DEGENERATE && hull == NULL, "box of half extent %g: result %d",
				(double)huge, (int)result);
	cd3DestroyHull(hull);
}

/* Huge, tiny and far-away clouds: the same checks, tolerances relative to the cloud. */
static void TestScalesAndOffsets(void)
{
	TestRng rng = TestRngMake(0x4e11008u);
	cd3Vec points[200];
	const double scales[4] = {1e6, 1e-3, 1.0, 1.0};
	const double offsets[4] = {0.0, 0.0, 1e5, -1e3};
	for (int s = 0; s < 4; ++s)
	{
		for (int trial = 0; trial < 100; ++trial)
		{
			int count = 8 + TestRngInt(&rng, 150);
			cd3Vec offset = cd3Scale((cdReal)offsets[s], cd3Normalize(V3(1.0, -0.6, 0.3)));
			for (int i = 0; i < count; ++i)
			{
				cd3Vec p = trial % 2 ? RandomUnit(&rng) : RandomVec(&rng, 1.0);
				points[i] = cd3Add(offset, cd3Scale((cdReal)scales[s], p));
			}
			char label[64];
			snprintf(label, sizeof(label), "scale %g offset %g", scales[s], offsets[s]);
			cd3Hull* hull = CheckCloud(&rng, label, points, count);
			if (hull != NULL)
			{
				double unit = scales[s] * scales[s] * scales[s];
				TEST_CHECKF(hull->volume > CD_R(0.0) && (double)hull->volume < 8.0 * unit * 1.001,
							"%s: volume %g", label, (double)hull->volume);
			}
			cd3DestroyHull(hull);
		}
	}
}

/* The hard cases for merging: points on the faces of a box jittered off their planes by a few
 * epsilons (right around the merge tolerance), thin slabs and needles that are still solid. The
 * builder must succeed and the hull validate and contain every point. */
static void TestNearlyCoplanar(void)
{
	TestRng rng = TestRngMake(0x4e1100au);
	static cd3Vec points[400];
	int refused = 0;
	for (int trial = 0; trial < 150; ++trial)
	{
		int count = 20 + TestRngInt(&rng, 300);
		cd3Quat q = RandomQuat(&rng);
		double jitter = pow(10.0, TestRngRange(&rng, 0.0, 3.0)) * (double)CD_REAL_EPSILON;
		for (int i = 0; i < count; ++i)
		{
			double c[3] = {TestRngRange(&rng, -1.0, 1.0), TestRngRange(&rng, -1.0, 1.0),
						   TestRngRange(&rng, -1.0, 1.0)};
			int axis = TestRngInt(&rng, 3);
			c[axis] = (TestRngInt(&rng, 2) ? 1.0 : -1.0) * (1.0 + TestRngRange(&rng, -jitter, jitter));
			points[i] = cd3RotateVector(q, V3(c[0], c[1], c[2]));
		}
		char label[64];
		snprintf(label, sizeof(label), "box faces jittered by %.3g", jitter);
		cd3Hull* hull = NULL;
		cdResult result = cd3ComputeHull(points, count, &hull);
		cd3DestroyHull(hull);
		if (result == CD_ERROR_DEGENERATE)
		{
			/* Documented: points coplanar to within the build tolerance may be refused (never
			 * turned into a broken hull); it must stay rare. */
			++refused;
		}
		else
		{
			hull = CheckCloud(&rng, label, points, count);
			cd3DestroyHull(hull);
		}

		/* A slab 1e-3 thick, and a needle 1e-3 wide. */
		double thin = 1e-3;
		for (int i = 0; i < count; ++i)
		{
			cd3Vec p = V3(TestRngRange(&rng, -1.0, 1.0), TestRngRange(&rng, -1.0, 1.0),
						  TestRngRange(&rng, -thin, thin));
			if (trial % 2)
			{
				p.y = (cdReal)(TestRngRange(&rng, -thin, thin));
			}
			points[i] = cd3RotateVector(q, p);
		}
		hull = CheckCloud(&rng, trial % 2 ? "needle" : "slab", points, count);
		cd3DestroyHull(hull);
	}
	TEST_CHECKF(refused <= 2, "%d of 150 jittered boxes refused as degenerate", refused);
}

/* ---- hulls as shapes -------------------------------------------------------------------------- */

/* Largest signed height of p over the world face planes, in double (> 0 outside). */
static double HullHeight(const cd3Shape* s, cd3Vec p, int* face)
{
	const cd3Hull* hull = s->hull.hull;
	cd3Vec local = cd3InvTransformPoint(s->hull.transform, p);
	double worst = -INFINITY;
	for (int f = 0; f < hull->faceCount; ++f)
	{
		cd3Plane plane = hull->planes[f];
		double h = (double)plane.normal.x * (double)local.x + (double)plane.normal.y * (double)local.y +
				   (double)plane.normal.z * (double)local.z - (double)plane.offset;
		if (h > worst)
		{
			worst = h;
			if (face != NULL)
			{
				*face = f;
			}
		}
	}
	return worst;
}

static void TestHullShapeBasics(void)
{
	cd3Hull* box = NULL;
	TEST_CHECK(cd3MakeBoxHull(V3(1, 1, 1), &box) == CD_OK);
	if (box == NULL)
	{
		return;
	}
	TEST_CHECK(strcmp(cd3GetShapeTypeName(CD3_SHAPE_HULL), "hull") == 0);
	cd3Transform t = {V3(0, 2, 0), cd3MakeQuatAxisAngle(V3(0, 1, 0), CD_R(0.25) * CD_PI)};
	cd3Shape shape = cd3MakeHullShape(box, t);
	TEST_CHECK(cd3ValidateShape(&shape) == CD_OK && cd3IsValidHullShape(shape.hull));
	cd3Aabb aabb = cd3ComputeShapeAabb(&shape);
	TEST_CHECK_NEAR(aabb.max.x, sqrt(2.0), 1e-5);
	TEST_CHECK_NEAR(aabb.min.y, 1.0, 1e-6);
	TEST_CHECK_NEAR(aabb.max.y, 3.0, 1e-6);

	/* Resting on the ground y <= 1 (touching), then lifted off it. */
	cd3Shape ground = cd3MakePlaneShape((cd3Plane){V3(0, 1, 0), CD_R(1.0)});
	TEST_CHECK(cd3Overlap(&shape, &ground) && cd3Overlap(&ground, &shape));
	ground.plane.offset = CD_R(0.99);
	TEST_CHECK(!cd3Overlap(&shape, &ground) && !cd3Overlap(&ground, &shape));
	TEST_CHECK_NEAR(cd3Distance(&shape, &ground).distance, 0.01, 1e-5);

	/* Against a sphere beside a face, and a box hull beside an edge. */
	cd3Shape ball = cd3MakeSphereShape((cd3Sphere){V3(0, 2, 3), CD_R(0.5)});
	TEST_CHECK_NEAR(cd3Distance(&shape, &ball).distance, 3.0 - sqrt(2.0) - 0.5, 1e-5);
	cd3Shape other = cd3MakeHullShape(box, (cd3Transform){V3(4, 2, 0), CD3_QUAT_IDENTITY});
	TEST_CHECK_NEAR(cd3Distance(&shape, &other).distance, 3.0 - sqrt(2.0), 1e-5);
	TEST_CHECK(!cd3Overlap(&shape, &other));
	other.hull.transform.p.x = CD_R(1.0) + (cdReal)sqrt(2.0);
	TEST_CHECK(cd3Overlap(&shape, &other) && cd3Overlap(&other, &shape));

	/* Containment, closest point, ray. */
	TEST_CHECK(cd3PointInShape(&shape, V3(0, 2, 0)) && cd3PointInShape(&shape, V3(1.4, 2, 0)));
	TEST_CHECK(!cd3PointInShape(&shape, V3(1.42, 2, 0)));
	cd3Vec q = cd3ClosestPointOnShape(&shape, V3(5, 2.5, 0));
	TEST_CHECK_NEAR(q.x, sqrt(2.0), 1e-5);
	TEST_CHECK_NEAR(q.y, 2.5, 1e-5);
	TEST_CHECK(cd3VecEqual(cd3ClosestPointOnShape(&shape, V3(0.1, 2.2, 0.3)), V3(0.1, 2.2, 0.3)));
	cd3RayHit hit = {CD_R(-1.0), CD3_VEC_ZERO, CD3_VEC_ZERO};
	cd3Ray ray = {V3(0, 5, 0), V3(0, -10, 0)};
	TEST_CHECK(cd3Raycast(&shape, ray, &hit));
	TEST_CHECK_NEAR(hit.fraction, 0.2, 1e-6);
	TEST_CHECK_NEAR(hit.normal.y, 1.0, 1e-6);
	ray.origin = V3(0, 2, 0);
	TEST_CHECK(cd3Raycast(&shape, ray, &hit) && hit.fraction == CD_R(0.0) && hit.normal.y == CD_R(1.0));
	ray.origin = V3(3, 5, 0);
	hit.fraction = CD_R(-1.0);
	TEST_CHECK(!cd3Raycast(&shape, ray, &hit) && hit.fraction == CD_R(-1.0));

	/* Validation of the shape. */
	cd3Shape bad = shape;
	bad.hull.hull = NULL;
	TEST_CHECK(cd3ValidateShape(&bad) == CD_ERROR_INVALID_ARGUMENT);
	bad = shape;
	bad.hull.transform.q.w = CD_R(2.0);
	TEST_CHECK(cd3ValidateShape(&bad) == CD_ERROR_NOT_NORMALIZED);
	bad = shape;
	bad.hull.transform.p.z = (cdReal)NAN;
	TEST_CHECK(cd3ValidateShape(&bad) == CD_ERROR_NOT_FINITE);
	cd3DestroyHull(box);
}

/* Random hull shapes: bounds are tight, containment and closest points agree with the face
 * planes in double, ray hits lie on the surface and misses pass no point inside. */
static void TestHullShapeProperties(void)
{
	TestRng rng = TestRngMake(0x4e1100bu);
	int hits = 0, misses = 0, inside = 0, outside = 0;
	for (int i = 0; i < 3000; ++i)
	{
		cd3Shape s = RandomShape(&rng, CD3_SHAPE_HULL);
		const cd3Hull* hull = s.hull.hull;
		if (i < 64)
		{
			TEST_CHECK(cd3ValidateShape(&s) == CD_OK);
		}
		cd3Aabb aabb = cd3ComputeShapeAabb(&s);
		cd3Vec lo = aabb.max, hi = aabb.min;
		for (int v = 0; v < hull->vertexCount; ++v)
		{
			cd3Vec w = cd3TransformPoint(s.hull.transform, hull->vertices[v]);
			lo = cd3Min(lo, w);
			hi = cd3Max(hi, w);
		}
		TEST_CHECKF(cd3VecDistance(lo, aabb.min) <= 1e-5 && cd3VecDistance(hi, aabb.max) <= 1e-5,
					"bounds not tight");

		cd3Vec p = cd3Add(s.hull.transform.p, RandomVec(&rng, 1.0));
		double height = HullHeight(&s, p, NULL);
		if (fabs(height) > 1e-4)
		{
			bool in = cd3PointInShape(&s, p);
			TEST_CHECKF(in == (height < 0.0), "point in hull %d, height %.9g", (int)in, height);
			inside += height < 0.0;
			outside += height > 0.0;
			cd3Vec q = cd3ClosestPointOnShape(&s, p);
			if (height < 0.0)
			{
				TEST_CHECK(cd3VecEqual(p, q));
			}
			else
			{
				/* On the surface, no farther than the nearest plane allows, and closer than any
				 * vertex. */
				double onSurface = HullHeight(&s, q, NULL);
				double d = (double)cd3VecDistance(p, q);
				double nearestVertex = INFINITY;
				for (int v = 0; v < hull->vertexCount; ++v)
				{
					double dv =
						(double)cd3VecDistance(p, cd3TransformPoint(s.hull.transform, hull->vertices[v]));
					nearestVertex = dv < nearestVertex ? dv : nearestVertex;
				}
				TEST_CHECKF(fabs(onSurface) <= 1e-5 && d >= height - 1e-5 && d <= nearestVertex + 1e-5,
							"closest point: height %.3g, distance %.9g, plane bound %.9g, vertex bound %.9g",
							onSurface, d, height, nearestVertex);
			}
		}

		cd3Vec start = cd3Add(s.hull.transform.p, RandomVec(&rng, 2.5));
		cd3Ray ray = {start,
					  cd3Add(cd3Scale(CD_R(2.0), cd3Sub(s.hull.transform.p, start)), RandomVec(&rng, 2.0))};
		cd3RayHit hit = {CD_R(-1.0), CD3_VEC_ZERO, CD3_VEC_ZERO};
		if (cd3Raycast(&s, ray, &hit))
		{
			++hits;
			int face = -1;
			double h = HullHeight(&s, hit.point, &face);
			bool ok = hit.fraction >= CD_R(0.0) && hit.fraction <= CD_R(1.0) &&
					  (hit.fraction == CD_R(0.0) ? h <= 1e-5 : fabs(h) <= 1e-5) &&
					  fabs((double)cd3Length(hit.normal) - 1.0) <= 1e-5;
			TEST_CHECKF(ok, "ray hit: fraction %.9g, height %.3g", (double)hit.fraction, h);
			if (hit.fraction > CD_R(0.0))
			{
				/* Just before the hit the ray is outside, and the normal faces the ray. */
				cd3Vec before = cd3MulAdd(ray.origin, hit.fraction - CD_R(1e-3), ray.translation);
				TEST_CHECK(HullHeight(&s, before, NULL) > 0.0 &&
						   cd3Dot(hit.normal, ray.translation) < CD_R(0.0));
			}
			else
			{
				TEST_CHECK(HullHeight(&s, ray.origin, NULL) <= 1e-5);
			}
		}
		else
		{
			++misses;
			for (int k = 0; k <= 64; ++k)
			{
				cd3Vec x = cd3MulAdd(ray.origin, (cdReal)k / CD_R(64.0), ray.translation);
				double h = HullHeight(&s, x, NULL);
				TEST_CHECKF(h > -1e-4, "missed ray passes %.3g inside", -h);
				if (h <= -1e-4)
				{
					break;
				}
			}
		}
	}
	TEST_CHECKF(hits > 300 && misses > 300 && inside > 300 && outside > 300,
				"%d hits, %d misses, %d in, %d out", hits, misses, inside, outside);
}

/* Found by fuzz_query3 (fuzz/crashes/query3-hull-sliver-weld): a sliver 7e-10 thick at the 1e-4
 * scale whose two nearly parallel back faces were both within the merge tolerance of the corner
 * (-1.25e-4, -1.25e-4, -1.25e-4); merging them dropped that corner although it is no point of
 * their common edge. The corner must stay a vertex. */
static void TestSliverCorner(void)
{
	TestRng rng = TestRngMake(0x4e1100cu);
	cdReal s = (cdReal)-0.000125000006;
	cd3Vec points[7] = {V3(0, 0, 0),
						V3(0, 0, -0.000123749996),
						cd3MakeVec(s, s, (cdReal)-0.000119999997),
						V3(-9.99999972e-10, 0, -9.99999972e-10),
						cd3MakeVec(s, s, s),
						cd3MakeVec(s, s, s),
						cd3MakeVec(s, s, s)};
	cd3Hull* hull = CheckCloud(&rng, "sliver corner", points, 7);
	if (hull != NULL)
	{
		TEST_CHECKF(hull->vertexCount == 5, "%d vertices", hull->vertexCount);
	}
	cd3DestroyHull(hull);
}

/* ---- the validator rejects broken hulls ---------------------------------------------------------- */
typedef struct MutableHull
{
	cd3Hull hull;
	cd3Vec vertices[8];
	cd3HullHalfEdge edges[24];
	int32_t faceEdges[6];
	cd3Plane planes[6];
} MutableHull;

static void CopyHull(MutableHull* m, const cd3Hull* source)
{
	m->hull = *source;
	memcpy(m->vertices, source->vertices, 8 * sizeof(cd3Vec));
	memcpy(m->edges, source->edges, 24 * sizeof(cd3HullHalfEdge));
	memcpy(m->faceEdges, source->faceEdges, 6 * sizeof(int32_t));
	memcpy(m->planes, source->planes, 6 * sizeof(cd3Plane));
	m->hull.vertices = m->vertices;
	/* Assembled by hand: no columns nor query data (they would be the source's). */
	m->hull.vertexColumns = NULL;
	m->hull.queryData = NULL;
	m->hull.edges = m->edges;
	m->hull.faceEdges = m->faceEdges;
	m->hull.planes = m->planes;
}

#if CD_DOUBLE
static void ExpectRefusedOrValid(const cd3Vec* points, int count)
{
	cd3Hull* hull = NULL;
	cdResult result = cd3ComputeHull(points, count, &hull);
	TEST_CHECKF(result == CD_ERROR_DEGENERATE || (result == CD_OK && cd3ValidateHull(hull) == CD_OK),
				"%d points: result %d, validation %d", count, (int)result,
				hull != NULL ? (int)cd3ValidateHull(hull) : -1);
	cd3DestroyHull(hull);
}
#endif

/* fuzz_hull3 (double build): a lattice far from the origin with near-duplicates; a thin face
 * passed its neighbours while a far vertex stood 3 percent beyond the tolerance above it. Refused
 * or valid, never broken. */
static void TestFarLatticeFinding(void)
{
#if CD_DOUBLE
	static const double p[][3] = {{999935.00000000023, 999925.00000000023, 999925},
								  {1000015, 999925, 1000065.0000000007},
								  {999995, 999985, 1000005},
								  {1000005.0000000009, 1000075.0000000017, 1000045},
								  {999925.00000000023, 999925, 999925},
								  {999925, 1000015, 1000045},
								  {999965.00000000093, 1000075.0000000007, 999925},
								  {1000045, 1000045, 1000045},
								  {999965.00000000093, 1000075.0000000007, 999925},
								  {1000075.0000000017, 1000045, 1000035},
								  {1000075, 1000005, 999995},
								  {1000055, 999945, 1000045.0000000012},
								  {999945, 1000055, 999945},
								  {999945, 1000055, 1000035},
								  {1000035, 1000035, 999925},
								  {999925, 999925, 999925},
								  {999925, 999925, 999925},
								  {999945, 1000045, 999925},
								  {1000055.0000000007, 999925.00000000128, 999935.00000000023},
								  {999925, 999925.00000000128, 999925},
								  {999925.00000000151, 999995.00000000047, 999955},
								  {999925, 1000075.0000000017, 1000075.0000000017},
								  {1000075.0000000017, 1000075.0000000017, 1000075.0000000017},
								  {1000075.0000000017, 1000075.0000000017, 1000075.0000000007},
								  {999925, 1000045, 1000045},
								  {1000045, 999965.00000000093, 1000075.0000000007},
								  {999925, 1000075.0000000017, 1000035},
								  {1000035, 1000075, 999925.00000000128},
								  {999925, 999935.00000000023, 999985.00000000116},
								  {999925.0000000007, 999925, 999935.00000000023},
								  {999935.00000000023, 999925.00000000023, 999925},
								  {1000075.0000000017, 999925, 999925}};
	int count = (int)(sizeof(p) / sizeof(p[0]));
	cd3Vec points[64];
	for (int i = 0; i < count; ++i)
	{
		points[i] = cd3MakeVec(p[i][0], p[i][1], p[i][2]);
	}
	ExpectRefusedOrValid(points, count);
	/* The same with 86 points: slivers 1e-10 high and 120 long, a vertex twice the tolerance
	 * above one of them, in a hull too large for the small-hull global check. */
	static const double q[][3] = {{999935.00000000023, 999925.00000000023, 999925},
								  {999935.00000000047, 999925, 1000035.0000000007},
								  {999995, 999985, 1000005},
								  {1000005.0000000009, 1000075.0000000017, 1000045},
								  {999925.00000000023, 999925, 1000065},
								  {1000045, 1000045, 1000045},
								  {999965.00000000093, 1000075.0000000007, 1000005},
								  {1000045, 1000075.0000000017, 1000075.0000000017},
								  {1000075.0000000017, 1000075.0000000017, 1000065.0000000009},
								  {1000075.0000000017, 1000075.0000000017, 1000075.0000000017},
								  {999925.00000000151, 999995.00000000047, 999955},
								  {1000045, 999925, 999995},
								  {999925, 1000055.0000000007, 999925.00000000128},
								  {999935.00000000023, 999925, 999925.00000000128},
								  {999925, 999925.00000000151, 999985.00000000047},
								  {999955, 999925, 1000075.0000000017},
								  {1000075.0000000017, 1000075.0000000017, 1000075.0000000017},
								  {1000075.0000000017, 1000075.0000000017, 1000075.0000000017},
								  {1000075.0000000017, 1000075.0000000017, 1000045},
								  {1000045, 999995, 999965.00000000093},
								  {1000075.0000000007, 999925, 999925},
								  {999995, 999925, 1000075.0000000017},
								  {1000075.0000000017, 999925.00000000128, 999925},
								  {999935.00000000023, 999945.00000000128, 999925.0000000007},
								  {999925, 1000005, 1000065},
								  {1000045, 1000035.0000000007, 999925.00000000047},
								  {1000005.0000000009, 1000045, 1000075.0000000017},
								  {999995.00000000175, 1000075.0000000017, 1000025},
								  {1000005, 1000065.0000000017, 1000065.0000000017},
								  {1000065.0000000017, 1000065.0000000017, 1000065.0000000017},
								  {1000065.0000000017, 1000065.0000000017, 1000065.0000000017},
								  {1000065.0000000017, 1000065.0000000017, 1000065.0000000017},
								  {1000065.0000000017, 1000065.0000000017, 1000065.0000000017},
								  {1000065.0000000017, 1000065.0000000017, 1000065.0000000017},
								  {1000065.0000000017, 1000065.0000000017, 1000065.0000000017},
								  {1000065.0000000017, 1000065.0000000017, 1000065.0000000017},
								  {1000065.0000000017, 1000065.0000000017, 1000065.0000000017},
								  {999925, 1000035, 999925},
								  {1000045.0000000005, 999945, 1000045},
								  {999975, 999945, 999925},
								  {1000025, 999925, 999935},
								  {999935, 999935, 999935},
								  {999985, 1000045, 1000005.0000000009},
								  {1000005, 999995, 1000065.0000000017},
								  {1000065.0000000017, 1000065.0000000017, 1000065.0000000017},
								  {1000065.0000000017, 1000065.0000000017, 1000065.0000000017},
								  {1000065.0000000017, 1000065.0000000017, 1000065.0000000017},
								  {1000065.0000000017, 1000065.0000000017, 1000065.0000000017},
								  {1000065.0000000017, 1000065.0000000017, 1000065.0000000017},
								  {1000065.0000000017, 1000065.0000000017, 1000065.0000000017},
								  {1000065.0000000017, 1000065.0000000017, 1000065.0000000017},
								  {1000065.0000000017, 1000065.0000000017, 1000065.0000000017},
								  {1000065.0000000017, 1000065.0000000017, 1000065.0000000017},
								  {1000065.0000000017, 1000065.0000000017, 1000065.0000000017},
								  {1000065.0000000017, 1000065.0000000017, 1000065.0000000017},
								  {1000065.0000000017, 1000065.0000000017, 1000065.0000000017},
								  {1000065.0000000017, 1000065.0000000017, 1000065.0000000017},
								  {1000065.0000000017, 1000065.0000000017, 1000065.0000000017},
								  {1000065.0000000017, 1000065.0000000017, 1000065.0000000017},
								  {1000065.0000000017, 1000065.0000000017, 999955.00000000151},
								  {999955.00000000151, 999965, 1000045},
								  {1000045, 999935.00000000047, 1000005.0000000009},
								  {1000075.0000000017, 1000045, 999995.00000000175},
								  {1000075.0000000017, 999965, 1000005},
								  {999965, 999925, 999925},
								  {999925, 1000045, 999925},
								  {999925, 1000005, 1000035},
								  {999935, 999945, 1000015},
								  {999935, 1000035, 999925},
								  {1000035, 999925, 1000045.0000000005},
								  {999945, 1000045, 999975},
								  {999945, 999925, 1000025},
								  {999925, 999935, 999935},
								  {999935, 999935, 999985},
								  {1000045, 1000005.0000000009, 999925},
								  {999995, 999925, 999925.00000000128},
								  {999935.00000000023, 1000065.0000000002, 999925.00000000128},
								  {999925, 999925, 1000055.0000000017},
								  {1000075.0000000017, 1000075.0000000017, 1000075.0000000017},
								  {999925, 999935.00000000023, 999925.00000000128},
								  {999975, 999965, 999925.00000000047},
								  {999925, 999965, 999945},
								  {1000075, 1000045.0000000005, 999945},
								  {1000045, 1000065, 999945},
								  {999925.00000000047, 1000025, 999925},
								  {1000075.0000000017, 999925, 999925}};
	count = (int)(sizeof(q) / sizeof(q[0]));
	static cd3Vec more[128];
	for (int i = 0; i < count; ++i)
	{
		more[i] = cd3MakeVec(q[i][0], q[i][1], q[i][2]);
	}
	ExpectRefusedOrValid(more, count);
#endif
}

static void TestValidator(void)
{
	cd3Hull* box = NULL;
	TEST_CHECK(cd3MakeBoxHull(V3(1, 1, 1), &box) == CD_OK);
	if (box == NULL)
	{
		return;
	}
	TEST_CHECK(cd3ValidateHull(NULL) == CD_ERROR_INVALID_ARGUMENT);
	MutableHull m;
	CopyHull(&m, box);
	TEST_CHECK(cd3ValidateHull(&m.hull) == CD_OK);

	m.vertices[3].x = (cdReal)NAN;
	TEST_CHECK(cd3ValidateHull(&m.hull) == CD_ERROR_NOT_FINITE);
	CopyHull(&m, box);
	m.planes[2].normal = cd3Scale(CD_R(1.1), m.planes[2].normal);
	TEST_CHECK(cd3ValidateHull(&m.hull) == CD_ERROR_NOT_NORMALIZED);
	CopyHull(&m, box);
	m.planes[2].normal = cd3Neg(m.planes[2].normal);
	m.planes[2].offset = -m.planes[2].offset;
	TEST_CHECK(cd3ValidateHull(&m.hull) == CD_ERROR_DEGENERATE); /* inward */
	CopyHull(&m, box);
	m.vertices[5] = cd3Scale(CD_R(1.01), m.vertices[5]); /* pokes out of its three faces */
	TEST_CHECK(cd3ValidateHull(&m.hull) == CD_ERROR_DEGENERATE);
	CopyHull(&m, box);
	m.planes[4].offset += CD_R(0.01); /* off its vertices: not planar */
	TEST_CHECK(cd3ValidateHull(&m.hull) == CD_ERROR_DEGENERATE);
	CopyHull(&m, box);
	m.edges[0].twin = m.edges[1].twin == 0 ? 2 : 1;
	TEST_CHECK(cd3ValidateHull(&m.hull) == CD_ERROR_INVALID_ARGUMENT);
	CopyHull(&m, box);
	m.edges[7].origin = 99;
	TEST_CHECK(cd3ValidateHull(&m.hull) == CD_ERROR_INVALID_ARGUMENT);
	CopyHull(&m, box);
	m.hull.faceCount = 5; /* open surface */
	TEST_CHECK(cd3ValidateHull(&m.hull) == CD_ERROR_INVALID_ARGUMENT);
	/* The support columns: the builder's match its vertices (padding: vertex 0), and columns
	 * that say otherwise (a vertex moved in `vertices` only) are refused. */
	TEST_CHECK(box->vertexColumns != NULL);
	cdReal columns[3 * CD3_HULL_COLUMN_STRIDE(8)];
	for (int i = 0; i < 3 * CD3_HULL_COLUMN_STRIDE(8); ++i)
	{
		columns[i] = box->vertexColumns[i];
	}
	CopyHull(&m, box);
	m.hull.vertexColumns = columns;
	TEST_CHECK(cd3ValidateHull(&m.hull) == CD_OK);
	m.vertices[6] = cd3Scale(CD_R(0.5), m.vertices[6]);
	TEST_CHECK(cd3ValidateHull(&m.hull) == CD_ERROR_INVALID_ARGUMENT);
	cd3DestroyHull(box);
	/* Padding repeats vertex 0: a hull of 5 vertices has 3 padding entries per column. */
	static const cd3Vec pyramid[5] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0.5f, 0.5f, 1}};
	cd3Hull* hull = NULL;
	TEST_CHECK(cd3ComputeHull(pyramid, 5, &hull) == CD_OK);
	if (hull != NULL)
	{
		int stride = CD3_HULL_COLUMN_STRIDE(hull->vertexCount);
		TEST_CHECK(hull->vertexCount == 5 && stride == 8);
		for (int i = 0; i < stride; ++i)
		{
			cd3Vec v = hull->vertices[i < hull->vertexCount ? i : 0];
			TEST_CHECKF(hull->vertexColumns[i] == v.x && hull->vertexColumns[stride + i] == v.y &&
							hull->vertexColumns[2 * stride + i] == v.z,
						"column entry %d", i);
		}
	}
	cd3DestroyHull(hull);
}

/* GJK's hull supports read the vertex columns; a hull without them (assembled by hand) is read
 * from its vertices. Both must give the very same answers: the same first-maximum vertex. */
static void TestColumnsAgreeWithVertices(void)
{
	TestRng rng = TestRngMake(0xc01u);
	int compared = 0;
	for (int i = 0; i < 2000; ++i)
	{
		cd3Shape a = RandomShape(&rng, CD3_SHAPE_HULL);
		cd3Shape b = RandomShape(&rng, i % 3 == 0 ? CD3_SHAPE_BOX : CD3_SHAPE_HULL);
		cd3Hull plainA = *a.hull.hull;
		plainA.vertexColumns = NULL;
		cd3Shape plain = a;
		plain.hull.hull = &plainA;
		TEST_CHECK(a.hull.hull->vertexColumns != NULL);
		cd3ClosestPoints withColumns = cd3Distance(&a, &b);
		cd3ClosestPoints withVertices = cd3Distance(&plain, &b);
		TEST_CHECKF(withColumns.distance == withVertices.distance &&
						cd3VecEqual(withColumns.pointA, withVertices.pointA) &&
						cd3VecEqual(withColumns.pointB, withVertices.pointB),
					"pair %d: distance %.9g with the columns, %.9g without", i, (double)withColumns.distance,
					(double)withVertices.distance);
		++compared;
	}
	TEST_CHECK(compared == 2000);
}

/* ---- allocation failures ------------------------------------------------------------------------- */
static void TestOutOfMemory(void)
{
	TestRng rng = TestRngMake(0x4e11009u);
	cd3Vec points[100];
	for (int i = 0; i < 100; ++i)
	{
		points[i] = RandomUnit(&rng);
	}
	bool succeeded = false;
	for (int budget = 0; budget < 200 && !succeeded; ++budget)
	{
		TestBudgetReset(budget);
		cdSetAllocator(TestBudgetAlloc, TestBudgetFree);
		cd3Hull* hull = NULL;
		cdResult result = cd3ComputeHull(points, 100, &hull);
		succeeded = result == CD_OK;
		TEST_CHECKF(result == CD_OK || (result == CD_ERROR_OUT_OF_MEMORY && hull == NULL), "budget %d: %s",
					budget, cdGetResultString(result));
		cd3DestroyHull(hull);
		TEST_CHECKF(g_testBudget.live == 0, "budget %d: %d allocations leaked", budget, g_testBudget.live);
		cdSetAllocator(NULL, NULL);
	}
	TEST_CHECK(succeeded);
}

int main(void)
{
	TEST_RUN(TestCube);
	TEST_RUN(TestTetrahedra);
	TEST_RUN(TestRandomClouds);
	TEST_RUN(TestSphereCloud);
	TEST_RUN(TestCoplanarMerging);
	TEST_RUN(TestWelding);
	TEST_RUN(TestNearlyCoplanar);
	TEST_RUN(TestSliverCorner);
	TEST_RUN(TestFarLatticeFinding);
	TEST_RUN(TestDegenerateAndBadInput);
	TEST_RUN(TestScalesAndOffsets);
	TEST_RUN(TestValidator);
	TEST_RUN(TestHullShapeBasics);
	TEST_RUN(TestHullShapeProperties);
	TEST_RUN(TestColumnsAgreeWithVertices);
	TEST_RUN(TestOutOfMemory);
	return TEST_SUMMARY();
}
