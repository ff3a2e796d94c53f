/* Tests of the convex polygon builders cd2MakePolygon and cd2MakeBoxPolygon: exact cases, errors
 * (leaving the output untouched), random clouds checked against the rules every polygon keeps
 * (convex, counter-clockwise, unit outward normals, area centroid, vertices taken from the input,
 * every input point inside within the weld tolerance), and huge and small coordinates. */
#include "collide/query2.h"
#include "test.h"

#include <string.h>

static cd2Vec V(double x, double y)
{
	return cd2MakeVec((cdReal)x, (cdReal)y);
}

/* A polygon filled with a byte pattern, to check that failing builders leave it untouched. */
static cd2Polygon Sentinel(void)
{
	cd2Polygon polygon;
	memset(&polygon, 0x5A, sizeof polygon);
	return polygon;
}

static bool IsSentinel(const cd2Polygon* polygon)
{
	cd2Polygon sentinel = Sentinel();
	return memcmp(polygon, &sentinel, sizeof sentinel) == 0;
}

static double MaxAbsCoordinate(const cd2Vec* points, int count)
{
	double m = 0.0;
	for (int i = 0; i < count; ++i)
	{
		m = fmax(m, fmax(fabs((double)points[i].x), fabs((double)points[i].y)));
	}
	return m;
}

/* Checks every rule of a built polygon independently of the validator, in double. `points` are the
 * builder's input; `tolerance` is the allowed distance of an input point outside the polygon. */
static void CheckPolygon(const cd2Polygon* polygon, const cd2Vec* points, int count, double tolerance,
						 const char* label)
{
	int n = polygon->count;
	TEST_CHECKF(n >= 3 && n <= CD2_MAX_POLYGON_VERTICES, "%s: count %d", label, n);
	if (n < 3 || n > CD2_MAX_POLYGON_VERTICES)
	{
		return;
	}
	TEST_CHECKF(cd2IsValidPolygon(polygon), "%s: validator rejects the result", label);
	double scale = fmax(1.0, MaxAbsCoordinate(polygon->vertices, n));
	/* shoelace relative to the vertex mean, so that far-away polygons keep their precision */
	double mx = 0.0, my = 0.0;
	for (int i = 0; i < n; ++i)
	{
		mx += (double)polygon->vertices[i].x / n;
		my += (double)polygon->vertices[i].y / n;
	}
	double twiceArea = 0.0, cx = 0.0, cy = 0.0;
	for (int i = 0; i < n; ++i)
	{
		cd2Vec a = polygon->vertices[i], b = polygon->vertices[(i + 1) % n],
			   c = polygon->vertices[(i + 2) % n];
		/* every vertex is one of the input points */
		bool found = false;
		for (int j = 0; j < count; ++j)
		{
			found = found || cd2VecEqual(a, points[j]);
		}
		TEST_CHECKF(found, "%s: vertex %d (%g, %g) is not an input point", label, i, (double)a.x,
					(double)a.y);
		/* strictly convex, counter-clockwise turn at every vertex */
		double ex = (double)b.x - (double)a.x, ey = (double)b.y - (double)a.y;
		double fx = (double)c.x - (double)b.x, fy = (double)c.y - (double)b.y;
		TEST_CHECKF(ex * fy - ey * fx > 0.0, "%s: no left turn at vertex %d", label, (i + 1) % n);
		/* unit outward normal perpendicular to its edge */
		double length = hypot(ex, ey);
		double nx = (double)polygon->normals[i].x, ny = (double)polygon->normals[i].y;
		TEST_CHECKF(fabs(hypot(nx, ny) - 1.0) < 1e-5, "%s: normal %d not unit", label, i);
		TEST_CHECKF(fabs(nx - ey / length) < 1e-5 && fabs(ny + ex / length) < 1e-5,
					"%s: normal %d (%g, %g) wrong", label, i, nx, ny);
		/* area centroid by the shoelace formula */
		double ax = (double)a.x - mx, ay = (double)a.y - my, bx = (double)b.x - mx, by = (double)b.y - my;
		double cross = ax * by - bx * ay;
		twiceArea += cross;
		cx += (ax + bx) * cross;
		cy += (ay + by) * cross;
		/* every input point lies inside, or outside by at most the tolerance */
		for (int j = 0; j < count; ++j)
		{
			double outside =
				nx * ((double)points[j].x - (double)a.x) + ny * ((double)points[j].y - (double)a.y);
			TEST_CHECKF(outside <= tolerance + 1e-6 * scale, "%s: input %d is %g outside edge %d", label, j,
						outside, i);
		}
	}
	TEST_CHECKF(twiceArea > 0.0, "%s: area %g", label, 0.5 * twiceArea);
	if (twiceArea > 0.0)
	{
		cx = mx + cx / (3.0 * twiceArea);
		cy = my + cy / (3.0 * twiceArea);
		double centroidTolerance = 1e-5 * scale;
		TEST_CHECKF(fabs(cx - (double)polygon->centroid.x) <= centroidTolerance &&
						fabs(cy - (double)polygon->centroid.y) <= centroidTolerance,
					"%s: centroid (%g, %g), expected (%g, %g)", label, (double)polygon->centroid.x,
					(double)polygon->centroid.y, cx, cy);
	}
}

static void TestSquare(void)
{
	/* The same square given in several orders, clockwise included. */
	cd2Vec orders[3][4] = {{V(0, 0), V(1, 0), V(1, 1), V(0, 1)},
						   {V(0, 1), V(1, 1), V(1, 0), V(0, 0)},
						   {V(1, 1), V(0, 0), V(0, 1), V(1, 0)}};
	for (int k = 0; k < 3; ++k)
	{
		cd2Polygon polygon = Sentinel();
		TEST_CHECK(cd2MakePolygon(orders[k], 4, &polygon) == CD_OK);
		TEST_CHECK(polygon.count == 4);
		CheckPolygon(&polygon, orders[k], 4, 0.0, "square");
		TEST_CHECK(polygon.centroid.x == (cdReal)0.5 && polygon.centroid.y == (cdReal)0.5);
		/* the normals of a unit square are the axes */
		int axisNormals = 0;
		for (int i = 0; i < polygon.count; ++i)
		{
			cd2Vec nrm = polygon.normals[i];
			axisNormals +=
				(fabs((double)nrm.x) == 1.0 && nrm.y == 0) || (fabs((double)nrm.y) == 1.0 && nrm.x == 0);
		}
		TEST_CHECK(axisNormals == 4);
	}

	cd2Vec triangle[3] = {V(0, 0), V(0, 3), V(3, 0)}; /* clockwise input */
	cd2Polygon polygon;
	TEST_CHECK(cd2MakePolygon(triangle, 3, &polygon) == CD_OK);
	TEST_CHECK(polygon.count == 3);
	CheckPolygon(&polygon, triangle, 3, 0.0, "triangle");
	TEST_CHECK_NEAR(polygon.centroid.x, 1.0, 1e-6);
	TEST_CHECK_NEAR(polygon.centroid.y, 1.0, 1e-6);
}

static void TestWeldAndCollinear(void)
{
	double weld = (double)CD2_POLYGON_WELD_TOLERANCE;
	TEST_CHECK(weld > 0.0);
	TEST_CHECK((double)cd2GetPolygonWeldTolerance((cdReal)0) == weld);
	TEST_CHECK((double)cd2GetPolygonWeldTolerance((cdReal)1e30f) >= 63.0 * (double)CD_REAL_EPSILON * 1e30);

	/* exact and near duplicates (well within the weld tolerance) */
	cd2Vec duplicates[8] = {
		V(0, 0),		 V(2, 0), V(2, 2), V(0, 2), V(0, 0), V(2 + 0.2 * weld, 0), V(2, 2 - 0.3 * weld),
		V(0.1 * weld, 2)};
	cd2Polygon polygon;
	TEST_CHECK(cd2MakePolygon(duplicates, 8, &polygon) == CD_OK);
	TEST_CHECK(polygon.count == 4);
	CheckPolygon(&polygon, duplicates, 8, weld, "duplicates");

	/* mid-edge points and a point barely outside an edge are dropped */
	cd2Vec collinear[7] = {V(0, 0), V(1, 0), V(2, 0), V(2, 1), V(2, 2), V(0, 2), V(-0.3 * weld, 1)};
	TEST_CHECK(cd2MakePolygon(collinear, 7, &polygon) == CD_OK);
	TEST_CHECK(polygon.count == 4);
	CheckPolygon(&polygon, collinear, 7, weld, "collinear");

	/* a point clearly outside an edge is kept */
	cd2Vec pentagon[5] = {V(0, 0), V(2, 0), V(2, 2), V(0, 2), V(-10 * weld, 1)};
	TEST_CHECK(cd2MakePolygon(pentagon, 5, &polygon) == CD_OK);
	TEST_CHECK(polygon.count == 5);
	CheckPolygon(&polygon, pentagon, 5, 0.0, "pentagon");

	/* interior points are ignored; the 8-point octagon is kept whole */
	cd2Vec octagon[8];
	for (int i = 0; i < 8; ++i)
	{
		double angle = i * 3.14159265358979323846 / 4;
		octagon[i] = V(cos(angle), sin(angle));
	}
	TEST_CHECK(cd2MakePolygon(octagon, 8, &polygon) == CD_OK);
	TEST_CHECK(polygon.count == 8);
	CheckPolygon(&polygon, octagon, 8, 0.0, "octagon");
	cd2Vec withInterior[8] = {V(0, 0), V(4, 0), V(0, 4), V(1, 1), V(0.5, 0.5), V(1, 2), V(2, 1), V(0.1, 0.2)};
	TEST_CHECK(cd2MakePolygon(withInterior, 8, &polygon) == CD_OK);
	TEST_CHECK(polygon.count == 3);
	CheckPolygon(&polygon, withInterior, 8, 0.0, "interior points");
}

static void TestErrors(void)
{
	cd2Vec square[4] = {V(0, 0), V(1, 0), V(1, 1), V(0, 1)};
	cd2Polygon polygon = Sentinel();

	TEST_CHECK(cd2MakePolygon(NULL, 4, &polygon) == CD_ERROR_INVALID_ARGUMENT);
	TEST_CHECK(cd2MakePolygon(square, 4, NULL) == CD_ERROR_INVALID_ARGUMENT);
	TEST_CHECK(cd2MakePolygon(square, -1, &polygon) == CD_ERROR_INVALID_ARGUMENT);
	TEST_CHECK(cd2MakePolygon(square, 0, &polygon) == CD_ERROR_DEGENERATE);
	TEST_CHECK(cd2MakePolygon(square, 1, &polygon) == CD_ERROR_DEGENERATE);
	TEST_CHECK(cd2MakePolygon(square, 2, &polygon) == CD_ERROR_DEGENERATE);

	cd2Vec line[5] = {V(0, 0), V(1, 1), V(2, 2), V(-3, -3), V(0.5, 0.5)};
	TEST_CHECK(cd2MakePolygon(line, 5, &polygon) == CD_ERROR_DEGENERATE);
	cd2Vec nearlyLine[3] = {V(0, 0), V(4, 0), V(2, 0.1 * (double)CD2_POLYGON_WELD_TOLERANCE)};
	TEST_CHECK(cd2MakePolygon(nearlyLine, 3, &polygon) == CD_ERROR_DEGENERATE);
	cd2Vec samePoint[4] = {V(1, 1), V(1, 1), V(1, 1), V(1, 1)};
	TEST_CHECK(cd2MakePolygon(samePoint, 4, &polygon) == CD_ERROR_DEGENERATE);
	cd2Vec twoPoints[4] = {V(1, 1), V(3, 1), V(1, 1), V(3, 1)};
	TEST_CHECK(cd2MakePolygon(twoPoints, 4, &polygon) == CD_ERROR_DEGENERATE);
	/* smaller than the weld tolerance */
	double tiny = 0.2 * (double)CD2_POLYGON_WELD_TOLERANCE;
	cd2Vec tinyTriangle[3] = {V(0, 0), V(tiny, 0), V(0, tiny)};
	TEST_CHECK(cd2MakePolygon(tinyTriangle, 3, &polygon) == CD_ERROR_DEGENERATE);

	cd2Vec bad[4] = {V(0, 0), V(1, 0), V(1, 1), V(0, 1)};
	bad[2].x = (cdReal)NAN;
	TEST_CHECK(cd2MakePolygon(bad, 4, &polygon) == CD_ERROR_NOT_FINITE);
	bad[2].x = (cdReal)INFINITY;
	TEST_CHECK(cd2MakePolygon(bad, 4, &polygon) == CD_ERROR_NOT_FINITE);
	bad[2].x = (cdReal)1;
	bad[0].y = -(cdReal)INFINITY;
	TEST_CHECK(cd2MakePolygon(bad, 4, &polygon) == CD_ERROR_NOT_FINITE);
	bad[0].y = (cdReal)NAN;
	TEST_CHECK(cd2MakePolygon(bad, 1, &polygon) == CD_ERROR_NOT_FINITE);

	cd2Vec many[CD2_MAX_POLYGON_VERTICES + 1];
	for (int i = 0; i < CD2_MAX_POLYGON_VERTICES + 1; ++i)
	{
		double angle = i * 2.0 * 3.14159265358979323846 / (CD2_MAX_POLYGON_VERTICES + 1);
		many[i] = V(cos(angle), sin(angle));
	}
	TEST_CHECK(cd2MakePolygon(many, CD2_MAX_POLYGON_VERTICES + 1, &polygon) == CD_ERROR_TOO_MANY_POINTS);
	TEST_CHECK(IsSentinel(&polygon));

	/* box polygon errors */
	cd2Box box = {V(0, 0), V(1, 0), CD2_ROT_IDENTITY};
	TEST_CHECK(cd2MakeBoxPolygon(box, &polygon) == CD_ERROR_DEGENERATE);
	box.halfExtents = V(0, 0);
	TEST_CHECK(cd2MakeBoxPolygon(box, &polygon) == CD_ERROR_DEGENERATE);
	box.halfExtents = V(1, -1);
	TEST_CHECK(cd2MakeBoxPolygon(box, &polygon) == CD_ERROR_NEGATIVE_SIZE);
	box.halfExtents = V(1, 1);
	box.center.x = (cdReal)NAN;
	TEST_CHECK(cd2MakeBoxPolygon(box, &polygon) == CD_ERROR_NOT_FINITE);
	box.center.x = 0;
	box.rotation.c = (cdReal)2;
	TEST_CHECK(cd2MakeBoxPolygon(box, &polygon) == CD_ERROR_NOT_NORMALIZED);
	box.rotation = CD2_ROT_IDENTITY;
	TEST_CHECK(cd2MakeBoxPolygon(box, NULL) == CD_ERROR_INVALID_ARGUMENT);
	TEST_CHECK(IsSentinel(&polygon));
}

static void TestBoxPolygon(void)
{
	TestRng rng = TestRngMake(0xB0C5);
	for (int n = 0; n < 500; ++n)
	{
		double angle = TestRngRange(&rng, -4.0, 4.0);
		cd2Box box = {V(TestRngRange(&rng, -10, 10), TestRngRange(&rng, -10, 10)),
					  V(TestRngRange(&rng, 0.01, 3), TestRngRange(&rng, 0.01, 3)), cd2MakeRot((cdReal)angle)};
		cd2Polygon polygon;
		TEST_CHECK(cd2MakeBoxPolygon(box, &polygon) == CD_OK);
		TEST_CHECK(polygon.count == 4);
		CheckPolygon(&polygon, polygon.vertices, polygon.count, 0.0, "box");
		TEST_CHECK_NEAR(polygon.centroid.x, box.center.x, 1e-5);
		TEST_CHECK_NEAR(polygon.centroid.y, box.center.y, 1e-5);
		/* every vertex is a corner of the box: local coordinates (+-hx, +-hy) */
		for (int i = 0; i < 4; ++i)
		{
			cd2Vec local = cd2InvRotateVector(box.rotation, cd2Sub(polygon.vertices[i], box.center));
			TEST_CHECK_NEAR(fabs((double)local.x), box.halfExtents.x, 1e-5);
			TEST_CHECK_NEAR(fabs((double)local.y), box.halfExtents.y, 1e-5);
		}
		/* the first normal is the box's -y axis */
		cd2Vec down = cd2RotateVector(box.rotation, V(0, -1));
		TEST_CHECK_NEAR(polygon.normals[0].x, down.x, 1e-5);
		TEST_CHECK_NEAR(polygon.normals[0].y, down.y, 1e-5);
	}
	/* a box far smaller than the weld tolerance is still a valid polygon */
	cd2Box small = {V(1, 1), V(1e-5, 2e-5), cd2MakeRot((cdReal)0.3)};
	cd2Polygon polygon;
	TEST_CHECK(cd2MakeBoxPolygon(small, &polygon) == CD_OK);
	TEST_CHECK(cd2IsValidPolygon(&polygon));

	/* boxes shrinking towards the round-off of a huge center: a valid polygon or DEGENERATE with the
	 * output untouched, never a broken polygon */
	int built = 0, rejected = 0;
	for (double size = 1e6; size > 1e-3; size *= 0.5)
	{
		cd2Box far = {V(1e9, -1e9), V(size, 0.5 * size), cd2MakeRot((cdReal)0.7)};
		cd2Polygon farPolygon = Sentinel();
		cdResult result = cd2MakeBoxPolygon(far, &farPolygon);
		TEST_CHECKF(result == CD_OK || result == CD_ERROR_DEGENERATE, "size %g: %s", size,
					cdGetResultString(result));
		if (result == CD_OK)
		{
			++built;
			TEST_CHECKF(cd2IsValidPolygon(&farPolygon) && farPolygon.count == 4, "size %g", size);
		}
		else
		{
			++rejected;
			TEST_CHECK(IsSentinel(&farPolygon));
		}
	}
	TEST_CHECK(built > 10);
#if !CD_DOUBLE
	TEST_CHECK(rejected > 0); /* float cannot hold a millimetre box at 1e9 */
#endif
}

/* Random clouds: on success every rule holds; on failure the cloud really is degenerate, that is
 * every point lies within two weld tolerances of the line through its two farthest points. */
static void CheckRandomClouds(uint64_t seed, double offset, double minExtent, double maxExtent, int clouds,
							  const char* label)
{
	TestRng rng = TestRngMake(seed);
	int built = 0;
	for (int n = 0; n < clouds; ++n)
	{
		int count = 3 + TestRngInt(&rng, CD2_MAX_POLYGON_VERTICES - 2);
		double extent = exp(TestRngRange(&rng, log(minExtent), log(maxExtent)));
		double squash =
			TestRngInt(&rng, 4) == 0 ? TestRngRange(&rng, 0.0, 1e-2) : 1.0; /* nearly flat clouds */
		double angle = TestRngRange(&rng, -3.2, 3.2);
		cd2Vec points[CD2_MAX_POLYGON_VERTICES];
		for (int i = 0; i < count; ++i)
		{
			double u = TestRngRange(&rng, -extent, extent), v = squash * TestRngRange(&rng, -extent, extent);
			if (TestRngInt(&rng, 6) == 0 && i > 0)
			{
				points[i] = points[TestRngInt(&rng, i)]; /* exact duplicates */
				continue;
			}
			points[i] =
				V(offset + cos(angle) * u - sin(angle) * v, -offset + sin(angle) * u + cos(angle) * v);
		}
		double tolerance = (double)cd2GetPolygonWeldTolerance((cdReal)MaxAbsCoordinate(points, count));
		cd2Polygon polygon = Sentinel();
		cdResult result = cd2MakePolygon(points, count, &polygon);
		if (result == CD_OK)
		{
			++built;
			CheckPolygon(&polygon, points, count, tolerance, label);
			continue;
		}
		TEST_CHECKF(result == CD_ERROR_DEGENERATE, "%s: cloud %d: %s", label, n, cdGetResultString(result));
		TEST_CHECKF(IsSentinel(&polygon), "%s: failed build wrote its output", label);
		int far1 = 0, far2 = 0;
		double farthest = -1.0;
		for (int i = 0; i < count; ++i)
		{
			for (int j = i + 1; j < count; ++j)
			{
				double d = hypot((double)points[i].x - (double)points[j].x,
								 (double)points[i].y - (double)points[j].y);
				if (d > farthest)
				{
					farthest = d, far1 = i, far2 = j;
				}
			}
		}
		double dx = (double)points[far2].x - (double)points[far1].x,
			   dy = (double)points[far2].y - (double)points[far1].y;
		for (int i = 0; i < count && farthest > 0.0; ++i)
		{
			double height = fabs(dx * ((double)points[i].y - (double)points[far1].y) -
								 dy * ((double)points[i].x - (double)points[far1].x)) /
							farthest;
			TEST_CHECKF(height <= 2.0 * tolerance, "%s: cloud %d rejected though point %d is %g off its line",
						label, n, i, height);
		}
	}
	TEST_CHECKF(built > clouds / 2, "%s: only %d of %d clouds built", label, built, clouds);
}

static void TestRandomClouds(void)
{
	CheckRandomClouds(0xC10D1, 0.0, 0.05, 50.0, 3000, "ordinary");
	CheckRandomClouds(0xC10D2, 1e6, 50.0, 1e4, 1000, "huge 1e6");
#if CD_DOUBLE
	CheckRandomClouds(0xC10D3, 8.5e29, 1e28, 1e29, 500, "huge 1e30");
#else
	CheckRandomClouds(0xC10D3, 8.5e8, 1e7, 1e8, 500, "huge 1e9");
#endif
}

/* Coordinates beyond the documented range are refused (fuzz finding polygon2-huge-coords-contains,
 * now in fuzz/corpus/fuzz_polygon2: points up to 7e9 in float built a polygon that left an input
 * point 1.3e5 outside); the limit itself is accepted. */
static void TestOutOfRange(void)
{
	cd2Polygon polygon, before;
	memset(&polygon, 0x5a, sizeof(polygon));
	before = polygon;
	double big = 7.0 * (double)CD2_POLYGON_MAX_COORDINATE;
	cd2Vec far[3] = {V(0, 5e4), V(-big, 5e4), V(-125000, 10000)};
	TEST_CHECK(cd2MakePolygon(far, 3, &polygon) == CD_ERROR_OUT_OF_RANGE);
	TEST_CHECK(memcmp(&polygon, &before, sizeof(polygon)) == 0);
	TEST_CHECK(cd2MakeRoundedPolygon(far, 3, CD_R(1.0), &polygon) == CD_ERROR_OUT_OF_RANGE);
	double edge = (double)CD2_POLYGON_MAX_COORDINATE;
	cd2Vec limit[3] = {V(edge, edge), V(-edge, edge), V(0, -edge)};
	TEST_CHECK(cd2MakePolygon(limit, 3, &polygon) == CD_OK);
}

static void TestHugeAndSmall(void)
{
	/* a square of side 100 at 1e6: welding scales with the coordinates, the square survives */
	cd2Vec far[4] = {V(1e6, 1e6), V(1e6 + 100, 1e6), V(1e6 + 100, 1e6 + 100), V(1e6, 1e6 + 100)};
	cd2Polygon polygon;
	TEST_CHECK(cd2MakePolygon(far, 4, &polygon) == CD_OK);
	TEST_CHECK(polygon.count == 4);
	CheckPolygon(&polygon, far, 4, 0.0, "far square");
	TEST_CHECK_NEAR(polygon.centroid.x, 1e6 + 50, 0.1);

	/* at 1e6 the tolerance follows the coordinates: a point half a tolerance outside an edge is
	 * dropped, one four tolerances outside is kept */
	double farTolerance = (double)cd2GetPolygonWeldTolerance((cdReal)(1e6 + 100));
	cd2Vec farCollinear[5] = {V(1e6, 1e6), V(1e6 + 100, 1e6), V(1e6 + 100, 1e6 + 100), V(1e6, 1e6 + 100),
							  V(1e6 + 50, 1e6 - 0.5 * farTolerance)};
	TEST_CHECK(cd2MakePolygon(farCollinear, 5, &polygon) == CD_OK);
	TEST_CHECK(polygon.count == 4);
	farCollinear[4].y = (cdReal)(1e6 - 4.0 * farTolerance);
	TEST_CHECK(cd2MakePolygon(farCollinear, 5, &polygon) == CD_OK);
	TEST_CHECK(polygon.count == 5);

	/* small shapes: with kilometre units (1e-3 length units per metre) the tolerances shrink a
	 * thousandfold, and a square of side 1e-3 builds */
	cd2Vec small[4] = {V(0, 0), V(1e-3, 0), V(1e-3, 1e-3), V(0, 1e-3)};
	TEST_CHECK(cd2MakePolygon(small, 4, &polygon) == CD_ERROR_DEGENERATE);
	cdSetLengthUnitsPerMeter((cdReal)1e-3);
	cd2Polygon smallPolygon = Sentinel();
	TEST_CHECK(cd2MakePolygon(small, 4, &smallPolygon) == CD_OK);
	TEST_CHECK(smallPolygon.count == 4);
	CheckPolygon(&smallPolygon, small, 4, 0.0, "small square");
	TEST_CHECK_NEAR(smallPolygon.centroid.x, 5e-4, 1e-9);
	cdSetLengthUnitsPerMeter((cdReal)1);
}

/* Euclidean distance from p to the polygon (0 inside), in double. */
static double DistanceToPolygon(const cd2Polygon* polygon, cd2Vec p)
{
	bool inside = true;
	double nearest = INFINITY;
	for (int i = 0; i < polygon->count; ++i)
	{
		cd2Vec a = polygon->vertices[i], b = polygon->vertices[(i + 1) % polygon->count];
		double abx = (double)b.x - (double)a.x, aby = (double)b.y - (double)a.y;
		double apx = (double)p.x - (double)a.x, apy = (double)p.y - (double)a.y;
		inside = inside && abx * apy - aby * apx >= 0.0;
		double t = fmin(fmax((apx * abx + apy * aby) / (abx * abx + aby * aby), 0.0), 1.0);
		nearest = fmin(nearest, hypot(apx - t * abx, apy - t * aby));
	}
	return inside ? 0.0 : nearest;
}

/* Dropping nearly collinear vertices in a sharp corner (fuzz_polygon2 finding, float build): a
 * sliver 1e9 long and 1.25e5 wide whose drops each kept every input point within the tolerance
 * of the new edge's line, yet left (-125000, -81250) 39,469 from the polygon, past the sharp corner
 * at (-117500, -120000) (the tolerance at 1e9 is 7,629). Every input point must lie within one
 * weld and one drop of the polygon, measured as a distance, not along one edge's normal. */
static void TestSharpCornerDrop(void)
{
	cd2Vec points[8] = {
		V(3.20185665e-31, -665531328), V(3.76527642e-37, -1e9), V(-117500, -120000), V(-125000, -125000),
		V(-125000, -125000),		   V(-125000, -125000),		V(-125000, -81250),	 V(-110000, -27238384)};
	cd2Polygon polygon;
	TEST_CHECK(cd2MakePolygon(points, 8, &polygon) == CD_OK);
	double maxAbs = MaxAbsCoordinate(points, 8);
	double tolerance =
		2.0 * (double)cd2GetPolygonWeldTolerance((cdReal)maxAbs) + 16.0 * (double)CD_REAL_EPSILON * maxAbs;
	for (int i = 0; i < 8; ++i)
	{
		double d = DistanceToPolygon(&polygon, points[i]);
		TEST_CHECKF(d <= tolerance, "input %d (%.9g, %.9g) is %.9g from the polygon (tolerance %.9g)", i,
					(double)points[i].x, (double)points[i].y, d, tolerance);
	}
}

/* Rounded polygons: the builders' radius checks, and every 2D query on a rounded unit square
 * [0,1]^2 with radius 0.5 (the stadium-cornered square reaching from -0.5 to 1.5). */
static void TestRounded(void)
{
	cd2Vec points[4] = {V(0, 0), V(1, 0), V(1, 1), V(0, 1)};
	cd2Polygon sentinel = Sentinel(), polygon = Sentinel();
	TEST_CHECK(cd2MakeRoundedPolygon(points, 4, (cdReal)-0.1, &polygon) == CD_ERROR_NEGATIVE_SIZE);
	TEST_CHECK(cd2MakeRoundedPolygon(points, 4, (cdReal)NAN, &polygon) == CD_ERROR_NOT_FINITE);
	TEST_CHECK(cd2MakeRoundedPolygon(points, 4, (cdReal)INFINITY, &polygon) == CD_ERROR_NOT_FINITE);
	TEST_CHECK(cd2MakeRoundedPolygon(points, 2, (cdReal)0.5, &polygon) == CD_ERROR_DEGENERATE);
	TEST_CHECK(cd2MakeRoundedPolygon(points, 4, (cdReal)0.5, NULL) == CD_ERROR_INVALID_ARGUMENT);
	TEST_CHECK(memcmp(&polygon, &sentinel, sizeof polygon) == 0);
	cd2Box box = {V(0.5, 0.5), V(0.5, 0.5), CD2_ROT_IDENTITY};
	TEST_CHECK(cd2MakeRoundedBoxPolygon(box, (cdReal)-1, &polygon) == CD_ERROR_NEGATIVE_SIZE);
	TEST_CHECK(memcmp(&polygon, &sentinel, sizeof polygon) == 0);

	cd2Polygon sharp;
	TEST_CHECK(cd2MakePolygon(points, 4, &sharp) == CD_OK && sharp.radius == (cdReal)0);
	TEST_CHECK(cd2MakeRoundedBoxPolygon(box, (cdReal)0.5, &polygon) == CD_OK);
	TEST_CHECK(polygon.radius == (cdReal)0.5 && polygon.count == 4 && cd2IsValidPolygon(&polygon));
	TEST_CHECK(cd2MakeRoundedPolygon(points, 4, (cdReal)0.5, &polygon) == CD_OK);
	TEST_CHECK(polygon.radius == (cdReal)0.5 && cd2IsValidPolygon(&polygon));
	cd2Polygon bad = polygon;
	bad.radius = (cdReal)-0.5;
	TEST_CHECK(!cd2IsValidPolygon(&bad));
	bad.radius = (cdReal)NAN;
	TEST_CHECK(!cd2IsValidPolygon(&bad));

	cd2Aabb bounds = cd2ComputePolygonAabb(&polygon);
	TEST_CHECK(bounds.min.x == (cdReal)-0.5 && bounds.min.y == (cdReal)-0.5 && bounds.max.x == (cdReal)1.5 &&
			   bounds.max.y == (cdReal)1.5);

	/* Inside the rounded edge band, outside the rounded corner, on the corner arc. */
	TEST_CHECK(cd2PointInPolygon(V(-0.4, 0.5), &polygon));
	TEST_CHECK(cd2PointInPolygon(V(1.5, 0.5), &polygon));
	TEST_CHECK(!cd2PointInPolygon(V(-0.45, -0.45), &polygon));
	TEST_CHECK(cd2PointInPolygon(V(-0.3, -0.4), &polygon)); /* at distance 0.5 from the corner */
	TEST_CHECK(!cd2PointInPolygon(V(-0.31, -0.41), &polygon));

	cd2Vec q = cd2ClosestPointOnPolygon(&polygon, V(3, 0.5));
	TEST_CHECK_NEAR(q.x, 1.5, 1e-6);
	TEST_CHECK_NEAR(q.y, 0.5, 1e-6);
	q = cd2ClosestPointOnPolygon(&polygon, V(-3, -4)); /* from the corner (0,0): direction (-0.6,-0.8) */
	TEST_CHECK_NEAR(q.x, -0.3, 1e-6);
	TEST_CHECK_NEAR(q.y, -0.4, 1e-6);
	q = cd2ClosestPointOnPolygon(&polygon, V(-0.2, 0.5));
	TEST_CHECK(q.x == (cdReal)-0.2 && q.y == (cdReal)0.5);

	cd2Circle touching = {V(3, 0.5), (cdReal)1.5};
	cd2Circle apart = {V(3, 0.5), (cdReal)1.49};
	TEST_CHECK(cd2OverlapCirclePolygon(touching, &polygon));
	TEST_CHECK(!cd2OverlapCirclePolygon(apart, &polygon));
	cd2Polygon other;
	cd2Vec far[4] = {V(2.0, 0), V(3, 0), V(3, 1), V(2.0, 1)};
	TEST_CHECK(cd2MakeRoundedPolygon(far, 4, (cdReal)0.49, &other) == CD_OK);
	TEST_CHECK(!cd2OverlapPolygonPolygon(&polygon, &other));
	TEST_CHECK(cd2MakeRoundedPolygon(far, 4, (cdReal)0.51, &other) == CD_OK);
	TEST_CHECK(cd2OverlapPolygonPolygon(&polygon, &other));
	/* Corner to corner: the cores' corners (1,1) and (2,2) are sqrt(2) apart. */
	cd2Vec diagonal[4] = {V(2, 2), V(3, 2), V(3, 3), V(2, 3)};
	TEST_CHECK(cd2MakeRoundedPolygon(diagonal, 4, (cdReal)0.9, &other) == CD_OK);
	TEST_CHECK(!cd2OverlapPolygonPolygon(&polygon, &other)); /* 1.4 < 1.41421 */
	TEST_CHECK(cd2MakeRoundedPolygon(diagonal, 4, (cdReal)0.92, &other) == CD_OK);
	TEST_CHECK(cd2OverlapPolygonPolygon(&polygon, &other));
	cd2Segment segment = {V(-0.6, -1), V(-0.6, 2)};
	TEST_CHECK(!cd2OverlapPolygonSegment(&polygon, segment));
	segment.p1.x = segment.p2.x = (cdReal)-0.49;
	TEST_CHECK(cd2OverlapPolygonSegment(&polygon, segment));

	cd2Ray ray = {V(-2, 0.5), V(4, 0)};
	cd2RayHit hit;
	TEST_CHECK(cd2RaycastPolygon(&polygon, ray, &hit));
	TEST_CHECK_NEAR(hit.fraction, 1.5 / 4.0, 1e-6);
	TEST_CHECK_NEAR(hit.normal.x, -1.0, 1e-6);
	cd2Ray diagonalRay = {V(-2, -2), V(2, 2)}; /* meets the corner arc at (-0.5,-0.5)/sqrt(2) */
	TEST_CHECK(cd2RaycastPolygon(&polygon, diagonalRay, &hit));
	TEST_CHECK_NEAR(hit.point.x, -0.5 / sqrt(2.0), 1e-5);
	TEST_CHECK_NEAR(hit.normal.x, -1.0 / sqrt(2.0), 1e-5);
	TEST_CHECK_NEAR(hit.normal.y, -1.0 / sqrt(2.0), 1e-5);
	cd2Ray inside = {V(-0.3, 0.5), V(0, 1)};
	TEST_CHECK(cd2RaycastPolygon(&polygon, inside, &hit) && hit.fraction == (cdReal)0);
	cd2Ray miss = {V(-0.45, -2), V(-0.1, 1.5)};
	TEST_CHECK(!cd2RaycastPolygon(&polygon, miss, &hit));

	cd2Shape a = cd2MakePolygonShape(&polygon);
	cd2Circle point = {V(4, 5), (cdReal)0};
	cd2Shape b = cd2MakeCircleShape(point);
	cd2ClosestPoints closest = cd2Distance(&a, &b); /* corner (1,1) to (4,5): 5, minus 0.5 */
	TEST_CHECK_NEAR(closest.distance, 4.5, 1e-5);
	TEST_CHECK_NEAR(closest.pointA.x, 1.3, 1e-5);
	TEST_CHECK_NEAR(closest.pointA.y, 1.4, 1e-5);
}

int main(void)
{
	TEST_RUN(TestSquare);
	TEST_RUN(TestWeldAndCollinear);
	TEST_RUN(TestErrors);
	TEST_RUN(TestBoxPolygon);
	TEST_RUN(TestRandomClouds);
	TEST_RUN(TestHugeAndSmall);
	TEST_RUN(TestOutOfRange);
	TEST_RUN(TestSharpCornerDrop);
	TEST_RUN(TestRounded);
	return TEST_SUMMARY();
}
