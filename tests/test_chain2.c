/* Tests of 2D chains: builder errors and welding, ghost vertices, shapes sliding over tessellated
 * straight terrain (no ghost normals, right depths), convex corners, one-sidedness, loops, and
 * the hierarchy's box query, ray cast and manifolds against brute force over the segments. */
#include "collide/chain2.h"
#include "../src/query/chain_manifold2.h" /* internal: the dedicated segment-polygon manifold */

#include "test.h"

#include <math.h>
#include <stdbool.h>
#include <string.h>

#define V(x, y) cd2MakeVec((cdReal)(x), (cdReal)(y))

/* Round-off allowance of the geometric checks: coordinates are up to ~50, so float's eps * 50
 * is ~6e-6; the bound leaves room for a few operations. */
#define TOL (CD_DOUBLE ? 1e-9 : 2e-4)

static cd2Chain* MakeChain(const cd2Vec* points, int count, bool loop)
{
	cd2Chain* chain = NULL;
	cdResult result = cd2CreateChain(points, count, loop, &chain);
	TEST_CHECKF(result == CD_OK && chain != NULL, "cd2CreateChain: %s", cdGetResultString(result));
	if (chain != NULL)
	{
		TEST_CHECK(cd2ValidateChain(chain) == CD_OK);
	}
	return chain;
}

static cd2Transform MakeTransform(double x, double y, double angle)
{
	cd2Transform t = {V(x, y), cd2MakeRot((cdReal)angle)};
	return t;
}

/* ---- builder ---------------------------------------------------------------------------------- */

static void TestBadInput(void)
{
	cd2Chain* chain = (cd2Chain*)(uintptr_t)1; /* must stay untouched on failure */
	cd2Chain* const untouched = chain;
	cd2Vec line[4] = {V(3, 0), V(2, 0), V(1, 0), V(0, 0)};
	TEST_CHECK(cd2CreateChain(NULL, 4, false, &chain) == CD_ERROR_INVALID_ARGUMENT);
	TEST_CHECK(cd2CreateChain(line, 4, false, NULL) == CD_ERROR_INVALID_ARGUMENT);
	TEST_CHECK(cd2CreateChain(line, -1, false, &chain) == CD_ERROR_INVALID_ARGUMENT);
	TEST_CHECK(cd2CreateChain(line, 0, false, &chain) == CD_ERROR_DEGENERATE);
	TEST_CHECK(cd2CreateChain(line, 1, false, &chain) == CD_ERROR_DEGENERATE);
	TEST_CHECK(cd2CreateChain(line, 2, true, &chain) == CD_ERROR_DEGENERATE);
	TEST_CHECK(cd2CreateChain(line, CD2_MAX_CHAIN_POINTS + 1, false, &chain) == CD_ERROR_TOO_MANY_POINTS);

	cd2Vec bad[3] = {V(0, 0), V(1, 0), V(2, 0)};
	bad[1].x = (cdReal)NAN;
	TEST_CHECK(cd2CreateChain(bad, 3, false, &chain) == CD_ERROR_NOT_FINITE);
	bad[1].x = (cdReal)INFINITY;
	TEST_CHECK(cd2CreateChain(bad, 3, false, &chain) == CD_ERROR_NOT_FINITE);
	bad[1] = V(1, 0);
	bad[2].y = -(cdReal)INFINITY;
	TEST_CHECK(cd2CreateChain(bad, 3, true, &chain) == CD_ERROR_NOT_FINITE);

	/* Duplicates weld away; too few distinct points left is degenerate. */
	cd2Vec same[3] = {V(1, 1), V(1, 1), V(1, 1)};
	TEST_CHECK(cd2CreateChain(same, 3, false, &chain) == CD_ERROR_DEGENERATE);
	cd2Vec closedPair[3] = {V(0, 0), V(1, 0), V(0, 0)}; /* a loop of two distinct points */
	TEST_CHECK(cd2CreateChain(closedPair, 3, true, &chain) == CD_ERROR_DEGENERATE);
	TEST_CHECK(chain == untouched);

	/* Welding consecutive duplicates (and the closing repeat of a loop). */
	cd2Vec dup[7] = {V(3, 0), V(3, 0), V(2, 0), V(2, 0.0001), V(1, 0), V(0, 0), V(0, 0)};
	cd2Chain* welded = MakeChain(dup, 7, false);
	if (welded != NULL)
	{
		TEST_CHECK(cd2Chain_GetPointCount(welded) == 4 && cd2Chain_GetSegmentCount(welded) == 3);
		TEST_CHECK(!cd2Chain_IsLoop(welded));
		const cd2Vec* p = cd2Chain_GetPoints(welded);
		TEST_CHECK(p[0].x == CD_R(3.0) && p[1].x == CD_R(2.0) && p[1].y == CD_R(0.0) && p[3].x == CD_R(0.0));
		cd2Aabb bounds = cd2Chain_GetBounds(welded);
		TEST_CHECK(bounds.min.x == CD_R(0.0) && bounds.max.x == CD_R(3.0) && bounds.min.y == CD_R(0.0) &&
				   bounds.max.y == CD_R(0.0));
		cd2DestroyChain(welded);
	}
	cd2Vec square[5] = {V(0, 0), V(1, 0), V(1, 1), V(0, 1), V(0, 0)};
	cd2Chain* loop = MakeChain(square, 5, true);
	if (loop != NULL)
	{
		TEST_CHECK(cd2Chain_GetPointCount(loop) == 4 && cd2Chain_GetSegmentCount(loop) == 4);
		TEST_CHECK(cd2Chain_IsLoop(loop));
		cd2DestroyChain(loop);
	}
	cd2DestroyChain(NULL);
	TEST_CHECK(cd2ValidateChain(NULL) == CD_ERROR_INVALID_ARGUMENT);
}

static bool VecIs(cd2Vec v, double x, double y)
{
	return fabs((double)v.x - x) <= 1e-12 && fabs((double)v.y - y) <= 1e-12;
}

static void TestGhosts(void)
{
	cd2Vec points[4] = {V(3, 0), V(2, 0), V(1, 1), V(0, 1)};
	cd2Chain* open = MakeChain(points, 4, false);
	cd2Chain* loop = MakeChain(points, 4, true);
	if (open == NULL || loop == NULL)
	{
		return;
	}
	cd2ChainSegment s = cd2Chain_GetSegment(open, 0);
	TEST_CHECK(VecIs(s.ghost1, 4, 0) && VecIs(s.p1, 3, 0) && VecIs(s.p2, 2, 0) && VecIs(s.ghost2, 1, 1));
	s = cd2Chain_GetSegment(open, 2);
	TEST_CHECK(VecIs(s.ghost1, 2, 0) && VecIs(s.p1, 1, 1) && VecIs(s.p2, 0, 1) && VecIs(s.ghost2, -1, 1));
	TEST_CHECK(cd2Chain_GetSegmentCount(loop) == 4);
	s = cd2Chain_GetSegment(loop, 0);
	TEST_CHECK(VecIs(s.ghost1, 0, 1) && VecIs(s.p1, 3, 0) && VecIs(s.p2, 2, 0) && VecIs(s.ghost2, 1, 1));
	s = cd2Chain_GetSegment(loop, 3);
	TEST_CHECK(VecIs(s.ghost1, 1, 1) && VecIs(s.p1, 0, 1) && VecIs(s.p2, 3, 0) && VecIs(s.ghost2, 2, 0));
	cd2DestroyChain(open);
	cd2DestroyChain(loop);
}

/* ---- sliding over straight terrain ------------------------------------------------------------ */

/* A straight line through `origin` along unit direction (cos a, sin a), tessellated from s = +L
 * to s = -L (right to left along the direction, so the free side is the left normal of the
 * direction, i.e. (-sin a, cos a)). Returns the number of points. */
static int Tessellate(cd2Vec* points, int capacity, double angle, double ox, double oy, double length,
					  bool randomLengths, TestRng* rng)
{
	double c = cos(angle), s = sin(angle);
	int n = 0;
	double t = length;
	while (n < capacity)
	{
		points[n++] = V(ox + c * t, oy + s * t);
		if (t <= -length)
		{
			break;
		}
		double step = randomLengths ? TestRngRange(rng, 0.05, 0.6) : 0.25;
		t = t - step < -length ? -length : t - step;
	}
	return n;
}

typedef struct Slider
{
	cd2Shape shape;
	double bottomLow, bottomHigh; /* extent of the contact face along the line (box, capsule) */
} Slider;

/* Shapes resting on the line at position t along it, sunk by `sink`, in the line's frame mapped
 * to world by (angle, origin). */
static Slider MakeSlider(int kind, double t, double sink, double angle, double ox, double oy)
{
	double c = cos(angle), s = sin(angle);
	double nx = -s, ny = c;
	Slider slider;
	memset(&slider, 0, sizeof(slider));
	if (kind == 0)
	{
		double h = 0.5 - sink;
		cd2Box box = {V(ox + c * t + nx * h, oy + s * t + ny * h), V(0.5, 0.5), cd2MakeRot((cdReal)angle)};
		slider.shape = cd2MakeBoxShape(box);
		slider.bottomLow = t - 0.5;
		slider.bottomHigh = t + 0.5;
	}
	else if (kind == 1)
	{
		double h = 0.3 - sink;
		cd2Circle circle = {V(ox + c * t + nx * h, oy + s * t + ny * h), CD_R(0.3)};
		slider.shape = cd2MakeCircleShape(circle);
		slider.bottomLow = slider.bottomHigh = t;
	}
	else
	{
		double h = 0.2 - sink;
		cd2Capsule capsule = {V(ox + c * (t - 0.7) + nx * h, oy + s * (t - 0.7) + ny * h),
							  V(ox + c * (t + 0.7) + nx * h, oy + s * (t + 0.7) + ny * h), CD_R(0.2)};
		slider.shape = cd2MakeCapsuleShape(capsule);
		slider.bottomLow = t - 0.7;
		slider.bottomHigh = t + 0.7;
	}
	return slider;
}

static void TestSlidingOnStraightTerrain(void)
{
	enum
	{
		CAPACITY = 64
	};
	static cd2Vec points[1024];
	TestRng rng = TestRngMake(0xC4A1);
	int contacts = 0;
	for (int variant = 0; variant < 6; ++variant)
	{
		/* Flat or tilted terrain, uniform or random tessellation, identity or moved chain frame. */
		double angle = (variant % 3 == 0) ? 0.0 : (variant % 3 == 1 ? 0.3 : -2.2);
		bool randomLengths = variant >= 3;
		double ox = 1.5 * variant, oy = -2.0 + variant;
		/* Half of the variants put the line in the chain's frame and move the frame instead. */
		bool moveFrame = (variant % 2) == 1;
		cd2Transform frame = moveFrame ? MakeTransform(ox, oy, angle) : MakeTransform(0, 0, 0);
		int n = moveFrame ? Tessellate(points, 1024, 0.0, 0.0, 0.0, 12.0, randomLengths, &rng)
						  : Tessellate(points, 1024, angle, ox, oy, 12.0, randomLengths, &rng);
		cd2Chain* chain = MakeChain(points, n, false);
		if (chain == NULL)
		{
			return;
		}
		double nx = -sin(angle), ny = cos(angle), dx = cos(angle), dy = sin(angle);
		for (int step = 0; step < 400; ++step)
		{
			double t = -9.0 + step * 0.04517;
			double sink = 0.002 + 0.01 * (step % 4);
			for (int kind = 0; kind < 3; ++kind)
			{
				Slider slider = MakeSlider(kind, t, sink, angle, ox, oy);
				cd2Manifold manifolds[CAPACITY];
				int segments[CAPACITY];
				int count =
					cd2CollideChain(chain, frame, &slider.shape, CD_R(0.02), manifolds, CAPACITY, segments);
				TEST_CHECKF(count >= 1 && count < CAPACITY, "variant %d t %.4f kind %d: %d manifolds",
							variant, t, kind, count);
				double low = 1e30, high = -1e30;
				for (int k = 0; k < count; ++k)
				{
					const cd2Manifold* m = &manifolds[k];
					TEST_CHECKF(
						m->pointCount > 0 && fabs((double)m->normal.x - nx) <= 1e-4 &&
							fabs((double)m->normal.y - ny) <= 1e-4,
						"variant %d t %.4f kind %d segment %d: normal (%.9g %.9g), terrain (%.6f %.6f)",
						variant, t, kind, segments[k], (double)m->normal.x, (double)m->normal.y, nx, ny);
					TEST_CHECK(k == 0 || segments[k] > segments[k - 1]);
					for (int p = 0; p < m->pointCount; ++p)
					{
						double separation = (double)m->points[p].separation;
						TEST_CHECKF(fabs(separation + sink) <= TOL,
									"variant %d t %.4f kind %d: separation %.9g, sunk %.4g", variant, t, kind,
									separation, sink);
						/* The point lies midway: sink/2 below the line's surface. */
						double px = (double)m->points[p].point.x - ox, py = (double)m->points[p].point.y - oy;
						double height = px * nx + py * ny;
						TEST_CHECKF(fabs(height + 0.5 * sink) <= TOL,
									"variant %d t %.4f kind %d: height %.9g", variant, t, kind, height);
						double along = px * dx + py * dy;
						low = fmin(low, along);
						high = fmax(high, along);
					}
					contacts += m->pointCount;
				}
				/* The contact patch spans the whole bottom face: both ends of a box and a capsule. */
				TEST_CHECKF(fabs(low - slider.bottomLow) <= TOL && fabs(high - slider.bottomHigh) <= TOL,
							"variant %d t %.4f kind %d: contact span [%.6f %.6f], face [%.6f %.6f]", variant,
							t, kind, low, high, slider.bottomLow, slider.bottomHigh);
			}
		}
		cd2DestroyChain(chain);
	}
	printf("straight terrain: %d contact points\n", contacts);
	TEST_CHECK(contacts > 10000);
}

/* Tilted boxes and polygons resting on a corner: the normal is still the terrain's, and the
 * deepest point is the lowest corner's depth. */
static void TestTiltedShapesOnTerrain(void)
{
	static cd2Vec points[1024];
	TestRng rng = TestRngMake(0x71E);
	double angle = 0.4, c = cos(angle), s = sin(angle), nx = -s, ny = c;
	int n = Tessellate(points, 1024, angle, 0.5, -1.0, 10.0, true, &rng);
	cd2Chain* chain = MakeChain(points, n, false);
	if (chain == NULL)
	{
		return;
	}
	int checked = 0;
	for (int step = 0; step < 300; ++step)
	{
		double t = -7.0 + step * 0.0467;
		double tilt = TestRngRange(&rng, -0.6, 0.6);
		double sink = TestRngRange(&rng, 0.001, 0.03);
		double hx = TestRngRange(&rng, 0.2, 0.8), hy = TestRngRange(&rng, 0.2, 0.8);
		/* Height of the centre above the line when the lowest corner touches it. */
		double h = hx * fabs(sin(tilt)) + hy * cos(tilt) - sink;
		cd2Box box = {V(0.5 + c * t + nx * h, -1.0 + s * t + ny * h), V(hx, hy),
					  cd2MakeRot((cdReal)(angle + tilt))};
		cd2Shape shape = cd2MakeBoxShape(box);
		cd2Manifold manifolds[16];
		int count = cd2CollideChain(chain, MakeTransform(0, 0, 0), &shape, CD_R(0.0), manifolds, 16, NULL);
		double deepest = 1e30;
		for (int k = 0; k < count; ++k)
		{
			TEST_CHECKF(fabs((double)manifolds[k].normal.x - nx) <= 1e-4 &&
							fabs((double)manifolds[k].normal.y - ny) <= 1e-4,
						"t %.4f tilt %.3f: normal (%.9g %.9g)", t, tilt, (double)manifolds[k].normal.x,
						(double)manifolds[k].normal.y);
			for (int p = 0; p < manifolds[k].pointCount; ++p)
			{
				deepest = fmin(deepest, (double)manifolds[k].points[p].separation);
			}
		}
		TEST_CHECKF(count >= 1 && fabs(deepest + sink) <= TOL,
					"t %.4f tilt %.3f: %d manifolds, deepest %.9g, sunk %.6g", t, tilt, count, deepest, sink);
		++checked;
	}
	TEST_CHECK(checked == 300);
	cd2DestroyChain(chain);
}

/* AABBs, segments and zero-size boxes go through the same paths (polygon, zero-radius capsule). */
static void TestOtherShapes(void)
{
	cd2Vec points[9];
	for (int i = 0; i < 9; ++i)
	{
		points[i] = V(4.0 - i, 0);
	}
	cd2Chain* chain = MakeChain(points, 9, false);
	if (chain == NULL)
	{
		return;
	}
	cd2Transform identity = MakeTransform(0, 0, 0);
	cd2Manifold manifolds[8];
	for (int step = 0; step < 50; ++step)
	{
		double x = -2.0 + step * 0.0813;
		cd2Aabb aabb = {V(x - 0.4, -0.01), V(x + 0.4, 0.5)};
		cd2Segment segment = {V(x - 0.3, 0.01), V(x + 0.3, 0.01)};
		cd2Box flat = {V(x, 0.015), V(0.5, 0), cd2MakeRot(0)}; /* zero height: a segment */
		cd2Box dot = {V(x, 0.015), V(0, 0), cd2MakeRot(0)};	   /* zero size: a point */
		cd2Shape shapes[4] = {cd2MakeAabbShape(aabb), cd2MakeSegmentShape(segment), cd2MakeBoxShape(flat),
							  cd2MakeBoxShape(dot)};
		const double expected[4] = {-0.01, 0.01, 0.015, 0.015};
		const double span[4][2] = {{x - 0.4, x + 0.4}, {x - 0.3, x + 0.3}, {x - 0.5, x + 0.5}, {x, x}};
		for (int k = 0; k < 4; ++k)
		{
			int count = cd2CollideChain(chain, identity, &shapes[k], CD_R(0.02), manifolds, 8, NULL);
			double low = 1e30, high = -1e30;
			bool ok = count >= 1;
			for (int m = 0; m < count; ++m)
			{
				ok = ok && manifolds[m].normal.x == CD_R(0.0) && manifolds[m].normal.y == CD_R(1.0);
				for (int p = 0; p < manifolds[m].pointCount; ++p)
				{
					ok = ok && fabs((double)manifolds[m].points[p].separation - expected[k]) <= TOL;
					low = fmin(low, (double)manifolds[m].points[p].point.x);
					high = fmax(high, (double)manifolds[m].points[p].point.x);
				}
			}
			ok = ok && fabs(low - span[k][0]) <= TOL && fabs(high - span[k][1]) <= TOL;
			TEST_CHECKF(ok, "x %.4f shape %d: %d manifolds, span [%.6f %.6f]", x, k, count, low, high);
		}
	}
	cd2DestroyChain(chain);
}

/* The same terrain made of independent two-sided segments does catch: the test above can fail. */
static void TestTwoSidedSegmentsCatch(void)
{
	static cd2Vec points[256];
	TestRng rng = TestRngMake(0x5E6);
	int n = Tessellate(points, 256, 0.0, 0.0, 0.0, 5.0, true, &rng);
	int ghosts = 0;
	for (int step = 0; step < 200; ++step)
	{
		Slider slider = MakeSlider(0, -3.0 + step * 0.0301, 0.02, 0.0, 0.0, 0.0);
		cd2Polygon box;
		TEST_CHECK(cd2MakeBoxPolygon(slider.shape.box, &box) == CD_OK);
		for (int i = 0; i + 1 < n; ++i)
		{
			cd2Segment segment = {points[i], points[i + 1]};
			cd2Manifold m = cd2CollidePolygonSegment(&box, segment, CD_R(0.02));
			ghosts += m.pointCount > 0 && fabs((double)m.normal.y) < 0.99;
		}
	}
	TEST_CHECK(ghosts > 10);
}

/* ---- corners, back side, loops ---------------------------------------------------------------- */

static void TestHill(void)
{
	/* Right to left: up to a peak at (0, 5), down again. A convex corner. */
	cd2Vec points[3] = {V(10, 0), V(0, 5), V(-10, 0)};
	cd2Chain* chain = MakeChain(points, 3, false);
	if (chain == NULL)
	{
		return;
	}
	cd2Manifold manifolds[8];
	int segments[8];
	/* Circles around the peak in every direction between the two faces' normals. */
	double n0 = atan2(10.0, 5.0), n1 = atan2(10.0, -5.0); /* normals of the right and left faces */
	for (int i = 0; i <= 20; ++i)
	{
		double a = n0 + (n1 - n0) * (0.02 + 0.96 * i / 20.0);
		double sink = 0.01;
		double r = 0.5;
		cd2Circle ball = {V(cos(a) * (r - sink), 5.0 + sin(a) * (r - sink)), (cdReal)r};
		cd2Shape shape = cd2MakeCircleShape(ball);
		int count = cd2CollideChain(chain, MakeTransform(0, 0, 0), &shape, CD_R(0.0), manifolds, 8, segments);
		/* Both faces allow the normal: the vertex is reported once, by the lower segment. */
		TEST_CHECKF(count == 1 && segments[0] == 0, "angle %.4f: %d manifolds", a, count);
		for (int k = 0; k < count; ++k)
		{
			TEST_CHECKF(manifolds[k].pointCount == 1 && fabs((double)manifolds[k].normal.x - cos(a)) <= TOL &&
							fabs((double)manifolds[k].normal.y - sin(a)) <= TOL &&
							fabs((double)manifolds[k].points[0].separation + sink) <= TOL,
						"angle %.4f segment %d: normal (%.6f %.6f) separation %.6f", a, segments[k],
						(double)manifolds[k].normal.x, (double)manifolds[k].normal.y,
						(double)manifolds[k].points[0].separation);
		}
	}
	/* A box balanced on the peak: the corner contact, normal straight up. */
	cd2Box box = {V(0.1, 5.49), V(0.5, 0.5), cd2MakeRot(0)};
	cd2Shape shape = cd2MakeBoxShape(box);
	int count = cd2CollideChain(chain, MakeTransform(0, 0, 0), &shape, CD_R(0.0), manifolds, 8, segments);
	int pointTotal = 0;
	for (int k = 0; k < count; ++k)
	{
		TEST_CHECK(fabs((double)manifolds[k].normal.x) <= TOL &&
				   fabs((double)manifolds[k].normal.y - 1) <= TOL);
		for (int p = 0; p < manifolds[k].pointCount; ++p)
		{
			TEST_CHECK_NEAR(manifolds[k].points[p].point.x, 0.0, TOL);
			TEST_CHECK_NEAR(manifolds[k].points[p].separation, -0.01, TOL);
			++pointTotal;
		}
	}
	TEST_CHECK(pointTotal == 1);
	cd2DestroyChain(chain);
}

static void TestBackSide(void)
{
	cd2Vec points[41];
	for (int i = 0; i <= 40; ++i)
	{
		points[i] = V(10.0 - 0.5 * i, 0);
	}
	cd2Chain* chain = MakeChain(points, 41, false);
	if (chain == NULL)
	{
		return;
	}
	cd2Manifold manifolds[8];
	for (int step = 0; step < 100; ++step)
	{
		double x = -8.0 + step * 0.161;
		for (int kind = 0; kind < 3; ++kind)
		{
			/* Mirror the sliders below the floor: their centres are behind every segment. */
			Slider slider = MakeSlider(kind, x, 0.05, CD_PI, 0, 0);
			int count =
				cd2CollideChain(chain, MakeTransform(0, 0, 0), &slider.shape, CD_R(0.02), manifolds, 8, NULL);
			TEST_CHECKF(count == 0, "x %.3f kind %d: %d manifolds from behind", x, kind, count);
			/* The same slider above the floor touches it. */
			Slider above = MakeSlider(kind, -x, 0.05, 0, 0, 0);
			TEST_CHECK(cd2CollideChain(chain, MakeTransform(0, 0, 0), &above.shape, CD_R(0.02), manifolds, 8,
									   NULL) > 0);
		}
	}
	cd2DestroyChain(chain);
}

static void TestLoops(void)
{
	/* Counter-clockwise square around a solid island of side 4 centred at the origin. */
	cd2Vec island[4] = {V(-2, -2), V(2, -2), V(2, 2), V(-2, 2)};
	cd2Vec room[4] = {V(-2, -2), V(-2, 2), V(2, 2), V(2, -2)}; /* clockwise: a room */
	cd2Chain* a = MakeChain(island, 4, true);
	cd2Chain* b = MakeChain(room, 4, true);
	if (a == NULL || b == NULL)
	{
		return;
	}
	cd2Transform frame = MakeTransform(3, -1, 0.7);
	cd2Manifold manifolds[8];
	int segments[8];
	const double outward[4][2] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
	for (int side = 0; side < 4; ++side)
	{
		for (int i = 0; i < 9; ++i)
		{
			double along = -1.6 + 0.4 * i;
			double ox = outward[side][0], oy = outward[side][1];
			/* local centre 0.25 outside (island) or inside (room) the wall, radius 0.3 */
			for (int which = 0; which < 2; ++which)
			{
				double h = which == 0 ? 2.25 : 1.75;
				cd2Vec local = V(ox * h - oy * along, oy * h + ox * along);
				cd2Circle ball = {cd2TransformPoint(frame, local), CD_R(0.3)};
				cd2Shape shape = cd2MakeCircleShape(ball);
				int count =
					cd2CollideChain(which == 0 ? a : b, frame, &shape, CD_R(0.0), manifolds, 8, segments);
				double sign = which == 0 ? 1.0 : -1.0;
				cd2Vec expected = cd2RotateVector(frame.q, V(sign * ox, sign * oy));
				TEST_CHECKF(count == 1 && fabs((double)manifolds[0].normal.x - (double)expected.x) <= TOL &&
								fabs((double)manifolds[0].normal.y - (double)expected.y) <= TOL &&
								fabs((double)manifolds[0].points[0].separation + 0.05) <= TOL,
							"side %d along %.2f %s: %d manifolds", side, along,
							which == 0 ? "island" : "room", count);
				/* From the other side of the wall (inside the island, outside the room): nothing. */
				double h2 = which == 0 ? 1.75 : 2.25;
				cd2Vec local2 = V(ox * h2 - oy * along, oy * h2 + ox * along);
				ball.center = cd2TransformPoint(frame, local2);
				shape = cd2MakeCircleShape(ball);
				TEST_CHECK(cd2CollideChain(which == 0 ? a : b, frame, &shape, CD_R(0.0), manifolds, 8,
										   segments) == 0);
			}
		}
	}
	/* The island's corners are convex: a ball off a corner gets the diagonal normal. */
	cd2Circle ball = {cd2TransformPoint(frame, V(2.2, 2.2)), CD_R(0.3)};
	cd2Shape shape = cd2MakeCircleShape(ball);
	int count = cd2CollideChain(a, frame, &shape, CD_R(0.0), manifolds, 8, segments);
	cd2Vec diagonal = cd2RotateVector(frame.q, V(sqrt(0.5), sqrt(0.5)));
	TEST_CHECK(count == 1 && segments[0] == 1);
	for (int k = 0; k < count; ++k)
	{
		TEST_CHECK(fabs((double)manifolds[k].normal.x - (double)diagonal.x) <= TOL &&
				   fabs((double)manifolds[k].normal.y - (double)diagonal.y) <= TOL);
	}
	/* The loop's closing corner (between the last segment and segment 0): segment 0 keeps it. */
	ball.center = cd2TransformPoint(frame, V(-2.2, -2.2));
	shape = cd2MakeCircleShape(ball);
	count = cd2CollideChain(a, frame, &shape, CD_R(0.0), manifolds, 8, segments);
	TEST_CHECK(count == 1 && segments[0] == 0);
	/* The room's corners are concave: a ball in a corner gets both walls. */
	ball.center = cd2TransformPoint(frame, V(1.8, 1.8));
	shape = cd2MakeCircleShape(ball);
	TEST_CHECK(cd2CollideChain(b, frame, &shape, CD_R(0.0), manifolds, 8, segments) == 2);
	/* Capacity: only the first manifold is written. */
	TEST_CHECK(cd2CollideChain(b, frame, &shape, CD_R(0.0), manifolds, 1, segments) == 1);
	TEST_CHECK(cd2CollideChain(b, frame, &shape, CD_R(0.0), manifolds, 0, segments) == 0);
	cd2DestroyChain(a);
	cd2DestroyChain(b);
}

/* ---- the hierarchy against brute force -------------------------------------------------------- */

/* A random walk from right to left: bumpy terrain with overhangs now and then. */
static int RandomTerrain(cd2Vec* points, int count, TestRng* rng)
{
	double x = 0.5 * count, y = 0.0;
	for (int i = 0; i < count; ++i)
	{
		points[i] = V(x, y);
		double angle = TestRngRange(rng, -1.2, 1.2) + (TestRngInt(rng, 20) == 0 ? 1.5 : 0.0);
		double length = TestRngRange(rng, 0.1, 1.0);
		x -= cos(angle) * length;
		y += sin(angle) * length;
	}
	return count;
}

typedef struct Collected
{
	int indices[4096];
	int count;
	int stopAfter;
} Collected;

static bool Collect(int segmentIndex, void* context)
{
	Collected* c = (Collected*)context;
	if (c->count < 4096)
	{
		c->indices[c->count] = segmentIndex;
	}
	++c->count;
	return c->count != c->stopAfter;
}

static void TestQueryAabb(void)
{
	static cd2Vec points[10001];
	TestRng rng = TestRngMake(0xAABB);
	int n = RandomTerrain(points, 10001, &rng);
	cd2Chain* chain = MakeChain(points, n, false);
	if (chain == NULL)
	{
		return;
	}
	int segmentCount = cd2Chain_GetSegmentCount(chain);
	TEST_CHECK(segmentCount == 10000);
	cd2Aabb all = cd2Chain_GetBounds(chain);
	static Collected collected;
	for (int trial = 0; trial < 200; ++trial)
	{
		cd2Vec c = V(TestRngRange(&rng, (double)all.min.x, (double)all.max.x),
					 TestRngRange(&rng, (double)all.min.y, (double)all.max.y));
		cd2Vec h = V(TestRngRange(&rng, 0, 3), TestRngRange(&rng, 0, 3));
		cd2Aabb box = {cd2Sub(c, h), cd2Add(c, h)};
		collected.count = 0;
		collected.stopAfter = -1;
		cd2Chain_QueryAabb(chain, MakeTransform(0, 0, 0), box, Collect, &collected);
		int expected = 0;
		bool same = true;
		for (int i = 0; i < segmentCount; ++i)
		{
			cd2ChainSegment s = cd2Chain_GetSegment(chain, i);
			cd2Aabb sb = {cd2Min(s.p1, s.p2), cd2Max(s.p1, s.p2)};
			if (cd2OverlapAabbAabb(sb, box))
			{
				same = same && expected < collected.count && collected.indices[expected] == i;
				++expected;
			}
		}
		TEST_CHECKF(same && expected == collected.count, "trial %d: %d segments, brute force %d", trial,
					collected.count, expected);
		if (expected >= 2)
		{
			collected.count = 0;
			collected.stopAfter = 2;
			cd2Chain_QueryAabb(chain, MakeTransform(0, 0, 0), box, Collect, &collected);
			TEST_CHECK(collected.count == 2);
		}
	}
	/* Under a rotation the query may report more, never fewer. */
	cd2Transform frame = MakeTransform(5, -3, 1.1);
	for (int trial = 0; trial < 100; ++trial)
	{
		cd2Vec c = cd2TransformPoint(frame, V(TestRngRange(&rng, (double)all.min.x, (double)all.max.x),
											  TestRngRange(&rng, (double)all.min.y, (double)all.max.y)));
		cd2Vec h = V(TestRngRange(&rng, 0, 3), TestRngRange(&rng, 0, 3));
		cd2Aabb box = {cd2Sub(c, h), cd2Add(c, h)};
		collected.count = 0;
		collected.stopAfter = -1;
		cd2Chain_QueryAabb(chain, frame, box, Collect, &collected);
		int found = 0, missing = 0;
		for (int i = 0; i < segmentCount; ++i)
		{
			cd2ChainSegment s = cd2Chain_GetSegment(chain, i);
			cd2Segment world = {cd2TransformPoint(frame, s.p1), cd2TransformPoint(frame, s.p2)};
			/* shrunk a little so that round-off of the transform cannot decide */
			if (cd2OverlapAabbSegment(cd2AabbInflate(box, CD_R(-0.01)), world))
			{
				bool listed = false;
				for (int k = 0; k < collected.count && k < 4096; ++k)
				{
					listed = listed || collected.indices[k] == i;
				}
				found += listed;
				missing += !listed;
			}
		}
		TEST_CHECKF(missing == 0,
					"rotated trial %d: %d segments touching the box were not reported (%d were)", trial,
					missing, found);
	}
	cd2DestroyChain(chain);
}

/* Reference one-sided ray cast on one segment in double, by solving the 2x2 system. Returns the
 * fraction or -1; *ambiguous is set when round-off could flip the answer (the crossing near an
 * end of the segment or of the ray, the origin near the line, or the ray nearly parallel). */
static double ReferenceRaycast(cd2Vec p1, cd2Vec p2, cd2Ray ray, bool* ambiguous)
{
	double ex = (double)p2.x - (double)p1.x, ey = (double)p2.y - (double)p1.y;
	double dx = (double)ray.translation.x, dy = (double)ray.translation.y;
	double length = sqrt(ex * ex + ey * ey), speed = sqrt(dx * dx + dy * dy);
	double nx = ey / length, ny = -ex / length; /* right normal: the free side */
	double dn = dx * nx + dy * ny;
	double rx = (double)ray.origin.x - (double)p1.x, ry = (double)ray.origin.y - (double)p1.y;
	double height = rx * nx + ry * ny;
	*ambiguous = false;
	if (dn == 0.0)
	{
		return -1.0;
	}
	double t = height / -dn;
	double hx = rx + t * dx, hy = ry + t * dy;
	double u = (hx * ex + hy * ey) / (length * length);
	bool crossingInRange = t >= -1e-4 && t <= 1.0 + 1e-4 && u >= -1e-3 && u <= 1.0 + 1e-3;
	if (crossingInRange && (fabs(u) < 1e-3 || fabs(u - 1.0) < 1e-3 || fabs(t) < 1e-4 ||
							fabs(t - 1.0) < 1e-4 || fabs(dn) < 1e-3 * speed))
	{
		*ambiguous = true;
	}
	if (dn > 0.0 || height < 0.0 || t > 1.0 || u < 0.0 || u > 1.0)
	{
		return -1.0;
	}
	return t;
}

static void TestRaycast(void)
{
	static cd2Vec points[1001];
	TestRng rng = TestRngMake(0x8A7);
	int hits = 0, compared = 0;
	for (int variant = 0; variant < 4; ++variant)
	{
		bool loop = variant == 3;
		int n;
		if (loop)
		{
			/* A wobbly counter-clockwise ring. */
			n = 600;
			for (int i = 0; i < n; ++i)
			{
				double a = 2.0 * CD_PI * i / n;
				double r = 20.0 + 2.0 * sin(7.0 * a) + TestRngRange(&rng, -0.3, 0.3);
				points[i] = V(r * cos(a), r * sin(a));
			}
		}
		else
		{
			n = RandomTerrain(points, variant == 0 ? 1001 : 300, &rng);
		}
		cd2Chain* chain = MakeChain(points, n, loop);
		if (chain == NULL)
		{
			return;
		}
		int segmentCount = cd2Chain_GetSegmentCount(chain);
		cd2Transform frame = variant == 0 ? MakeTransform(0, 0, 0) : MakeTransform(-4, 7, 0.4 * variant);
		cd2Aabb all = cd2Chain_GetBounds(chain);
		for (int trial = 0; trial < 400; ++trial)
		{
			cd2Vec localOrigin = V(TestRngRange(&rng, (double)all.min.x, (double)all.max.x),
								   TestRngRange(&rng, (double)all.min.y, (double)all.max.y));
			double angle = TestRngRange(&rng, 0, 2 * CD_PI), length = TestRngRange(&rng, 0.5, 30.0);
			cd2Ray local = {localOrigin, V(length * cos(angle), length * sin(angle))};
			cd2Ray ray = {cd2TransformPoint(frame, local.origin),
						  cd2RotateVector(frame.q, local.translation)};
			/* The reference works on the local ray and segments, in double. */
			double best = 2.0;
			int bestIndex = -1;
			bool nearBoundary = false;
			for (int i = 0; i < segmentCount; ++i)
			{
				cd2ChainSegment s = cd2Chain_GetSegment(chain, i);
				bool ambiguous;
				double t = ReferenceRaycast(s.p1, s.p2, local, &ambiguous);
				nearBoundary = nearBoundary || ambiguous;
				if (t >= 0.0 && t < best)
				{
					if (best - t < 1e-4)
					{
						nearBoundary = true;
					}
					best = t;
					bestIndex = i;
				}
				else if (t >= 0.0 && t - best < 1e-4)
				{
					nearBoundary = true;
				}
			}
			if (best > 1.0 - 1e-4 && best < 1.0 + 1e-4)
			{
				nearBoundary = true;
			}
			if (nearBoundary)
			{
				continue;
			}
			cd2RayHit hit = {CD_R(-1.0), V(99, 99), V(99, 99)};
			int index = -7;
			bool found = cd2RaycastChain(chain, frame, ray, &hit, &index);
			++compared;
			TEST_CHECKF(found == (bestIndex >= 0), "variant %d trial %d: hit %d, reference segment %d",
						variant, trial, (int)found, bestIndex);
			if (!found)
			{
				TEST_CHECK(hit.fraction == CD_R(-1.0) && index == -7);
				continue;
			}
			++hits;
			if (bestIndex < 0)
			{
				continue;
			}
			cd2ChainSegment s = cd2Chain_GetSegment(chain, bestIndex);
			cd2Vec front = cd2RotateVector(frame.q, cd2Normalize(cd2RightPerp(cd2Sub(s.p2, s.p1))));
			double scale = 30.0 * (CD_DOUBLE ? 1e-10 : 1e-5);
			TEST_CHECKF(index == bestIndex && fabs((double)hit.fraction - best) * length <= scale + TOL &&
							fabs((double)hit.normal.x - (double)front.x) <= TOL &&
							fabs((double)hit.normal.y - (double)front.y) <= TOL,
						"variant %d trial %d: segment %d fraction %.9g, reference %d %.9g", variant, trial,
						index, (double)hit.fraction, bestIndex, best);
			cd2Vec expected = cd2MulAdd(ray.origin, hit.fraction, ray.translation);
			TEST_CHECK(cd2VecDistance(expected, hit.point) <= (cdReal)(TOL * 10));
		}
		cd2DestroyChain(chain);
	}
	printf("ray casts: %d compared, %d hits\n", compared, hits);
	TEST_CHECK(compared > 1000 && hits > 200);

	/* Exact cases on a floor: from above hits, from below passes, along the floor misses. */
	cd2Vec floor[3] = {V(2, 0), V(0, 0), V(-2, 0)};
	cd2Chain* chain = MakeChain(floor, 3, false);
	if (chain == NULL)
	{
		return;
	}
	cd2RayHit hit;
	int index = -1;
	cd2Ray down = {V(0.5, 1), V(0, -2)};
	TEST_CHECK(cd2RaycastChain(chain, MakeTransform(0, 0, 0), down, &hit, &index));
	TEST_CHECK(index == 0 && hit.fraction == CD_R(0.5) && hit.normal.x == CD_R(0.0) &&
			   hit.normal.y == CD_R(1.0));
	cd2Ray up = {V(0.5, -1), V(0, 2)};
	TEST_CHECK(!cd2RaycastChain(chain, MakeTransform(0, 0, 0), up, &hit, NULL));
	cd2Ray along = {V(3, 0), V(-6, 0)};
	TEST_CHECK(!cd2RaycastChain(chain, MakeTransform(0, 0, 0), along, &hit, NULL));
	cd2Ray onVertex = {V(0, 1), V(0, -1)}; /* the shared vertex: the lower segment index */
	TEST_CHECK(cd2RaycastChain(chain, MakeTransform(0, 0, 0), onVertex, &hit, &index));
	TEST_CHECK(index == 0 && hit.fraction == CD_R(1.0));
	cd2Ray fromSurface = {V(-1, 0), V(0.5, -1)}; /* starts on the floor, moving into it */
	TEST_CHECK(cd2RaycastChain(chain, MakeTransform(0, 0, 0), fromSurface, &hit, &index));
	TEST_CHECK(index == 1 && hit.fraction == CD_R(0.0) && hit.point.x == CD_R(-1.0));
	/* A one-segment chain: its root is the segment's own box. */
	cd2Vec single[2] = {V(1, 0), V(-1, 0)};
	cd2Chain* one = MakeChain(single, 2, false);
	if (one != NULL)
	{
		TEST_CHECK(cd2Chain_GetSegmentCount(one) == 1);
		TEST_CHECK(cd2RaycastChain(one, MakeTransform(0, 0, 0), down, &hit, &index) && index == 0);
		cd2Ray miss = {V(1.5, 1), V(0, -2)};
		TEST_CHECK(!cd2RaycastChain(one, MakeTransform(0, 0, 0), miss, &hit, NULL));
		cd2Circle ball = {V(0.2, 0.25), CD_R(0.3)};
		cd2Shape shape = cd2MakeCircleShape(ball);
		cd2Manifold m;
		TEST_CHECK(cd2CollideChain(one, MakeTransform(0, 0, 0), &shape, CD_R(0.0), &m, 1, &index) == 1 &&
				   index == 0);
		ball.center = V(3, 0.25);
		shape = cd2MakeCircleShape(ball);
		TEST_CHECK(cd2CollideChain(one, MakeTransform(0, 0, 0), &shape, CD_R(0.0), &m, 1, NULL) == 0);
		cd2DestroyChain(one);
	}
	/* A direction component too small to invert: no NaN, the hit below is found. */
	cd2Ray denormal = {V(0.5, 1), V(CD_DOUBLE ? 1e-310 : 1e-40, -2)};
	TEST_CHECK(cd2RaycastChain(chain, MakeTransform(0, 0, 0), denormal, &hit, &index));
	TEST_CHECK(index == 0 && fabs((double)hit.fraction - 0.5) <= TOL && cd2IsValidVec(hit.point));
	cd2Ray zero = {V(0, 1), V(0, 0)};
	TEST_CHECK(!cd2RaycastChain(chain, MakeTransform(0, 0, 0), zero, &hit, NULL));
	cd2DestroyChain(chain);
}

/* A ray along a segment's line, far short of it, under a rotation a hair off 90 degrees: the
 * crossing test's two cross products are both round-off there (fuzz_chain2 found a hit at the
 * ray's origin, 1.4e9 from the segment). Any hit must lie on its segment. */
static void TestRayAlongSegmentLine(void)
{
	cd2Vec a = V(-1e9, -1e9), b = V(1e9, 1e9), c = V(1e9, -1e9);
	cd2Vec points[6] = {a, b, a, b, c, a};
	cd2Chain* chain = MakeChain(points, 6, false);
	if (chain == NULL)
	{
		return;
	}
	cd2Transform frame = {V(1e9, -1e9), {(cdReal)7.64355548e-08, CD_R(-1.0)}};
	cd2Ray ray = {V(-1e9, 1e9), V(1e9, -1e9)};
	cd2RayHit hit = {CD_R(-1.0), V(0, 0), V(0, 0)};
	int index = -1;
	if (cd2RaycastChain(chain, frame, ray, &hit, &index))
	{
		cd2ChainSegment s = cd2Chain_GetSegment(chain, index);
		cd2Segment world = {cd2TransformPoint(frame, s.p1), cd2TransformPoint(frame, s.p2)};
		cd2Vec onSegment = cd2ClosestPointOnSegment(world, hit.point);
		double off = hypot((double)(onSegment.x - hit.point.x), (double)(onSegment.y - hit.point.y));
		TEST_CHECKF(off <= 1e-3 * 1e9, "hit segment %d at fraction %g, %g off it", index,
					(double)hit.fraction, off);
	}
	cd2DestroyChain(chain);
}

/* cd2CollideChain against every segment's own manifold. */
static void TestCollideAgainstBruteForce(void)
{
	static cd2Vec points[1001];
	TestRng rng = TestRngMake(0xC011);
	int n = RandomTerrain(points, 1001, &rng);
	cd2Chain* chain = MakeChain(points, n, false);
	if (chain == NULL)
	{
		return;
	}
	int segmentCount = cd2Chain_GetSegmentCount(chain);
	cd2Aabb all = cd2Chain_GetBounds(chain);
	int touching = 0, sharedRemoved = 0;
	for (int trial = 0; trial < 500; ++trial)
	{
		/* Near the terrain: start on a random vertex and move a little. */
		cd2Vec base = points[TestRngInt(&rng, n)];
		cd2Vec center =
			V((double)base.x + TestRngRange(&rng, -1, 1), (double)base.y + TestRngRange(&rng, -1, 1));
		cd2Shape shape;
		int kind = trial % 4;
		if (kind == 0)
		{
			cd2Circle c = {center, (cdReal)TestRngRange(&rng, 0, 1)};
			shape = cd2MakeCircleShape(c);
		}
		else if (kind == 1)
		{
			cd2Capsule c = {center, V((double)center.x + TestRngRange(&rng, -1, 1), (double)center.y + 0.3),
							(cdReal)TestRngRange(&rng, 0, 0.5)};
			shape = cd2MakeCapsuleShape(c);
		}
		else if (kind == 2)
		{
			cd2Box b = {center, V(TestRngRange(&rng, 0, 1), TestRngRange(&rng, 0.1, 1)),
						cd2MakeRot((cdReal)TestRngRange(&rng, -3, 3))};
			shape = cd2MakeBoxShape(b);
		}
		else
		{
			cd2Vec cloud[6];
			for (int i = 0; i < 6; ++i)
			{
				cloud[i] = V((double)center.x + TestRngRange(&rng, -0.8, 0.8),
							 (double)center.y + TestRngRange(&rng, -0.8, 0.8));
			}
			cd2Polygon polygon;
			if (cd2MakePolygon(cloud, 6, &polygon) != CD_OK)
			{
				continue;
			}
			shape = cd2MakePolygonShape(&polygon);
		}
		cd2Manifold manifolds[32];
		int segments[32];
		int count =
			cd2CollideChain(chain, MakeTransform(0, 0, 0), &shape, CD_R(0.05), manifolds, 32, segments);
		int expected = 0;
		bool same = true;
		cd2Manifold previous = {{CD_R(0.0), CD_R(0.0)}, {{{CD_R(0.0), CD_R(0.0)}, CD_R(0.0), 0u}}, 0};
		int previousIndex = -2;
		cd2Polygon boxPolygon;
		if (kind == 2)
		{
			TEST_CHECK(cd2MakeBoxPolygon(shape.box, &boxPolygon) == CD_OK);
		}
		for (int i = 0; i < segmentCount; ++i)
		{
			cd2ChainSegment s = cd2Chain_GetSegment(chain, i);
			cd2Manifold m;
			if (kind == 0)
			{
				m = cd2CollideChainSegmentCircle(&s, shape.circle, CD_R(0.05));
			}
			else if (kind == 1)
			{
				m = cd2CollideChainSegmentCapsule(&s, shape.capsule, CD_R(0.05));
			}
			else
			{
				m = cd2CollideChainSegmentPolygon(&s, kind == 2 ? &boxPolygon : &shape.polygon, CD_R(0.05));
			}
			/* A vertex contact the previous segment already reports is kept there only. */
			if (m.pointCount > 0 && previousIndex == i - 1 &&
				(double)cd2Dot(m.normal, previous.normal) >= 1.0 - 1e-4)
			{
				int kept = 0;
				for (int p = 0; p < m.pointCount; ++p)
				{
					bool shared = false;
					for (int q = 0; q < previous.pointCount; ++q)
					{
						shared =
							shared || (double)cd2VecDistance(m.points[p].point, previous.points[q].point) <=
										  0.01 * (double)CD_LINEAR_SLOP + 1e-4;
					}
					if (!shared)
					{
						m.points[kept++] = m.points[p];
					}
				}
				m.pointCount = kept;
				sharedRemoved += kept == 0;
			}
			if (m.pointCount == 0)
			{
				continue;
			}
			previous = m;
			previousIndex = i;
			bool match = expected < count && segments[expected] == i &&
						 manifolds[expected].pointCount == m.pointCount &&
						 cd2VecDistance(manifolds[expected].normal, m.normal) <= (cdReal)TOL;
			for (int p = 0; match && p < m.pointCount; ++p)
			{
				match =
					manifolds[expected].points[p].id == m.points[p].id &&
					cd2VecDistance(manifolds[expected].points[p].point, m.points[p].point) <= (cdReal)TOL &&
					fabs((double)manifolds[expected].points[p].separation - (double)m.points[p].separation) <=
						TOL;
			}
			TEST_CHECKF(match, "trial %d kind %d: segment %d differs from its own manifold", trial, kind, i);
			same = same && match;
			++expected;
		}
		TEST_CHECKF(same && count == expected, "trial %d kind %d: %d manifolds, brute force %d", trial, kind,
					count, expected);
		touching += count > 0;

		/* Moving the chain and the shape together moves the manifolds with them. */
		cd2Transform frame =
			MakeTransform(TestRngRange(&rng, -5, 5), TestRngRange(&rng, -5, 5), TestRngRange(&rng, -3, 3));
		cd2Shape moved = shape;
		if (kind == 0)
		{
			moved.circle.center = cd2TransformPoint(frame, shape.circle.center);
		}
		else if (kind == 1)
		{
			moved.capsule.p1 = cd2TransformPoint(frame, shape.capsule.p1);
			moved.capsule.p2 = cd2TransformPoint(frame, shape.capsule.p2);
		}
		else if (kind == 2)
		{
			moved.box.center = cd2TransformPoint(frame, shape.box.center);
			moved.box.rotation = cd2MulRot(frame.q, shape.box.rotation);
		}
		else
		{
			for (int i = 0; i < shape.polygon.count; ++i)
			{
				moved.polygon.vertices[i] = cd2TransformPoint(frame, shape.polygon.vertices[i]);
				moved.polygon.normals[i] = cd2RotateVector(frame.q, shape.polygon.normals[i]);
			}
			moved.polygon.centroid = cd2TransformPoint(frame, shape.polygon.centroid);
		}
		cd2Manifold movedManifolds[32];
		int movedSegments[32];
		const double invariance = CD_DOUBLE ? 1e-7 : 1e-2;
		int movedCount = cd2CollideChain(chain, frame, &moved, CD_R(0.05), movedManifolds, 32, movedSegments);
		/* Round-off may tip a grazing or corner case: compare only when the counts agree. The
		 * terrain reaches |x| ~ 1500, where float rounds coordinates by ~1e-4, and a short capsule
		 * core turns that into a normal error several times larger. */
		if (movedCount == count)
		{
			for (int k = 0; k < count; ++k)
			{
				cd2Vec normal = cd2RotateVector(frame.q, manifolds[k].normal);
				/* A vertex both neighbours touch may go to the other one at its fan's edge. */
				bool ok = abs(movedSegments[k] - segments[k]) <= 1 &&
						  movedManifolds[k].pointCount == manifolds[k].pointCount &&
						  cd2VecDistance(normal, movedManifolds[k].normal) <= (cdReal)invariance;
				for (int p = 0; ok && p < manifolds[k].pointCount; ++p)
				{
					cd2Vec q = cd2TransformPoint(frame, manifolds[k].points[p].point);
					ok = cd2VecDistance(q, movedManifolds[k].points[p].point) <= (cdReal)invariance &&
						 fabs((double)manifolds[k].points[p].separation -
							  (double)movedManifolds[k].points[p].separation) <= invariance;
				}
				TEST_CHECKF(
					ok,
					"trial %d kind %d: moved manifold %d (segment %d/%d) differs: points %d/%d normal (%.6f "
					"%.6f)/(%.6f %.6f) sep %.6f/%.6f",
					trial, kind, k, segments[k], movedSegments[k], manifolds[k].pointCount,
					movedManifolds[k].pointCount, (double)normal.x, (double)normal.y,
					(double)movedManifolds[k].normal.x, (double)movedManifolds[k].normal.y,
					(double)manifolds[k].points[0].separation,
					(double)movedManifolds[k].points[0].separation);
			}
		}
	}
	printf("collide: %d of 500 shapes touch the terrain, %d shared vertex contacts kept once\n", touching,
		   sharedRemoved);
	TEST_CHECK(touching > 150);
	(void)all;
	cd2DestroyChain(chain);
}

/* ---- the dedicated segment-polygon manifold ---------------------------------------------------- */

/* A random one-sided segment with ghosts that turn by a random angle at each end (convex,
 * concave, straight on exactly, or within a hair of straight) and a random polygon near it: a box
 * (now and then square to the segment, so that faces are parallel), a hull of 3 to 8 points, a
 * third of them rounded; placed anywhere from behind the segment to above it and beyond its ends. */
static void RandomSegmentPolygon(TestRng* rng, cd2ChainSegment* s, cd2Polygon* polygon)
{
	double angle = TestRngRange(rng, -3.2, 3.2);
	double length = TestRngRange(rng, 0.2, 3.0);
	double x = TestRngRange(rng, -5, 5), y = TestRngRange(rng, -5, 5);
	s->p1 = V(x, y);
	s->p2 = V(x + length * cos(angle), y + length * sin(angle));
	for (int end = 0; end < 2; ++end)
	{
		double turn;
		switch (TestRngInt(rng, 5))
		{
			case 0:
				turn = 0.0;
				break;
			case 1:
				turn = TestRngRange(rng, -1e-3, 1e-3);
				break;
			case 2:
				turn = TestRngRange(rng, 0.02, 1.4); /* convex */
				break;
			case 3:
				turn = -TestRngRange(rng, 0.02, 1.4); /* concave */
				break;
			default:
				turn = TestRngRange(rng, -0.3, 0.3);
				break;
		}
		double ghostLength = TestRngRange(rng, 0.2, 3.0);
		if (end == 0)
		{
			double a = angle - turn; /* the previous segment's direction, turning left by `turn` */
			s->ghost1 = turn == 0.0 ? cd2Sub(s->p1, cd2Sub(s->p2, s->p1))
									: V((double)s->p1.x - ghostLength * cos(a),
										(double)s->p1.y - ghostLength * sin(a));
		}
		else
		{
			double a = angle + turn;
			s->ghost2 = turn == 0.0 ? cd2Add(s->p2, cd2Sub(s->p2, s->p1))
									: V((double)s->p2.x + ghostLength * cos(a),
										(double)s->p2.y + ghostLength * sin(a));
		}
	}
	double size = TestRngRange(rng, 0.05, 1.0);
	double along = TestRngRange(rng, -0.4, 1.4);
	double height = TestRngRange(rng, -0.8, 1.6) * size;
	double nx = sin(angle), ny = -cos(angle); /* the front normal, right of p1 -> p2 */
	cd2Vec center =
		V(x + along * length * cos(angle) + height * nx, y + along * length * sin(angle) + height * ny);
	cdReal radius = TestRngInt(rng, 3) == 0 ? (cdReal)TestRngRange(rng, 0.0, 0.3) : CD_R(0.0);
	cdResult result;
	if (TestRngInt(rng, 2) == 0)
	{
		double rotation = TestRngInt(rng, 4) == 0 ? angle + 0.5 * 3.14159265358979 * TestRngInt(rng, 4)
												  : TestRngRange(rng, -3.2, 3.2);
		cd2Box box = {center, V(size, TestRngRange(rng, 0.05, 1.0)), cd2MakeRot((cdReal)rotation)};
		result = cd2MakeRoundedBoxPolygon(box, radius, polygon);
	}
	else
	{
		cd2Vec cloud[8];
		int count = 3 + TestRngInt(rng, 6);
		for (int i = 0; i < count; ++i)
		{
			cloud[i] = V((double)center.x + TestRngRange(rng, -size, size),
						 (double)center.y + TestRngRange(rng, -size, size));
		}
		result = cd2MakeRoundedPolygon(cloud, count, radius, polygon);
	}
	if (result != CD_OK)
	{
		cd2Box box = {center, V(size, size), cd2MakeRot(CD_R(0.3))};
		TEST_CHECK(cd2MakeBoxPolygon(box, polygon) == CD_OK);
	}
}

/* Distance from p to the polygon's core (negative inside: minus the depth below the nearest face). */
static double CoreDistance(const cd2Polygon* polygon, cd2Vec p)
{
	double deepest = -1e300;
	for (int i = 0; i < polygon->count; ++i)
	{
		deepest = fmax(deepest, (double)cd2Dot(polygon->normals[i], cd2Sub(p, polygon->vertices[i])));
	}
	if (deepest <= 0.0)
	{
		return deepest;
	}
	double best = 1e300;
	for (int i = 0; i < polygon->count; ++i)
	{
		cd2Segment edge = {polygon->vertices[i], polygon->vertices[i + 1 < polygon->count ? i + 1 : 0]};
		best = fmin(best, (double)cd2VecDistance(p, cd2ClosestPointOnSegment(edge, p)));
	}
	return best;
}

static bool SameAsGeneric(int trial, const char* kind, const cd2Manifold* direct, const cd2Manifold* generic,
						  double tolerance);

/* cd2CollideChainSegmentPolygonDirect (what cd2CollideChain runs for polygons) against the generic
 * core-core path cd2CollideChainSegmentPolygon of manifold2.c on random segments, ghosts and
 * polygons at all distances: the same points, separations, normal and feature ids; every point
 * midway between the two surfaces. Then against the two-sided segment's manifold (cd2Collide)
 * where its normal is one the chain allows, clear of the fan's edges and of ties between the two
 * shapes' faces: the same normal and deepest separation. */
static void TestDirectSegmentPolygon(void)
{
	TestRng rng = TestRngMake(0x5E6D);
	const double tolerance = CD_DOUBLE ? 1e-9 : 2e-4;
	const cdReal speculative[3] = {CD_R(0.0), CD_R(0.02), CD_R(0.25)};
	int contacts = 0, exact = 0, cases = 6000, twoSidedCompared = 0, faceReference = 0, gapContacts = 0;
	for (int trial = 0; trial < cases; ++trial)
	{
		cd2ChainSegment s;
		cd2Polygon polygon;
		RandomSegmentPolygon(&rng, &s, &polygon);
		cdReal distance = speculative[TestRngInt(&rng, 3)];
		cd2Manifold direct = cd2CollideChainSegmentPolygonDirect(&s, &polygon, distance);
		cd2Manifold generic = cd2CollideChainSegmentPolygon(&s, &polygon, distance);
		exact += SameAsGeneric(trial, "polygon", &direct, &generic, tolerance);
		if (direct.pointCount == 0)
		{
			continue;
		}
		++contacts;
		gapContacts += (direct.points[0].id >> 16) >= 4u;
		faceReference += (direct.points[0].id & CD2_FEATURE_FLIP) == 0u && (direct.points[0].id >> 16) < 4u;

		/* Midway between the surfaces: on the segment below, on the polygon's surface above; the
		 * normal unit and facing the front. */
		cd2Segment core = {s.p1, s.p2};
		cd2Vec front = cd2RightPerp(cd2Normalize(cd2Sub(s.p2, s.p1)));
		TEST_CHECKF(fabs((double)cd2Length(direct.normal) - 1.0) <= tolerance &&
						(double)cd2Dot(direct.normal, front) >= 0.0,
					"trial %d: normal (%.7g %.7g)", trial, (double)direct.normal.x, (double)direct.normal.y);
		for (int i = 0; i < direct.pointCount; ++i)
		{
			const cd2ManifoldPoint* p = &direct.points[i];
			cd2Vec onA = cd2MulSub(p->point, CD_R(0.5) * p->separation, direct.normal);
			cd2Vec onB = cd2MulAdd(p->point, CD_R(0.5) * p->separation, direct.normal);
			double offA = (double)cd2VecDistance(onA, cd2ClosestPointOnSegment(core, onA));
			double offB = CoreDistance(&polygon, onB) - (double)polygon.radius;
			TEST_CHECKF(offA <= 10.0 * tolerance && fabs(offB) <= 10.0 * tolerance &&
							p->separation <= distance,
						"trial %d point %d: %.3g off the segment, %.3g off the polygon, separation %.7g",
						trial, i, offA, offB, (double)p->separation);
		}
	}

	/* The two-sided segment (cd2Collide: the normal points from the segment to the polygon) where
	 * the chain allows its normal and the shapes' best faces are not near a tie. */
	TestRng rng2 = TestRngMake(0x5E6E);
	for (int trial = 0; trial < cases; ++trial)
	{
		cd2ChainSegment s;
		cd2Polygon polygon;
		RandomSegmentPolygon(&rng2, &s, &polygon);
		cdReal distance = speculative[TestRngInt(&rng2, 3)];
		cd2Segment segment = {s.p1, s.p2};
		cd2Shape a = cd2MakeSegmentShape(segment), b = cd2MakePolygonShape(&polygon);
		cd2Manifold twoSided = cd2Collide(&a, &b, distance);
		if (twoSided.pointCount == 0)
		{
			continue;
		}
		cd2Vec direction = cd2Normalize(cd2Sub(s.p2, s.p1));
		cd2Vec front = cd2RightPerp(direction);
		cd2Vec m = twoSided.normal;
		double side = (double)cd2Cross(front, m);
		bool allowed;
		if (fabs(side) < 1e-6 && (double)cd2Dot(m, front) > 0.0)
		{
			allowed = true; /* the segment's own normal */
		}
		else if (side > 1e-3)
		{
			cd2Vec next = cd2Normalize(cd2Sub(s.ghost2, s.p2));
			allowed = (double)cd2Cross(direction, next) > 1e-3 &&
					  (double)cd2Cross(m, cd2RightPerp(next)) > 1e-3; /* inside the convex fan */
		}
		else if (side < -1e-3)
		{
			cd2Vec previous = cd2Normalize(cd2Sub(s.p1, s.ghost1));
			allowed = (double)cd2Cross(previous, direction) > 1e-3 &&
					  (double)cd2Cross(cd2RightPerp(previous), m) > 1e-3;
		}
		else
		{
			allowed = false;
		}
		/* The separating axis values of the segment's front face and of the polygon's best face:
		 * the two orders prefer their own first shape's face on a near tie. */
		double faceA = 1e300, faceB = -1e300;
		for (int j = 0; j < polygon.count; ++j)
		{
			faceA = fmin(faceA, (double)cd2Dot(front, cd2Sub(polygon.vertices[j], s.p1)));
			double e = fmin((double)cd2Dot(polygon.normals[j], cd2Sub(s.p1, polygon.vertices[j])),
							(double)cd2Dot(polygon.normals[j], cd2Sub(s.p2, polygon.vertices[j])));
			faceB = fmax(faceB, e);
		}
		bool behind = (double)cd2Dot(front, cd2Sub(polygon.centroid, s.p1)) < 1e-3;
		if (!allowed || behind || fabs(faceA - faceB) < 0.01 || fmax(faceA, faceB) > 0.0)
		{
			continue; /* separated cores take the closest-feature path, where the tie rules differ too */
		}
		cd2Manifold direct = cd2CollideChainSegmentPolygonDirect(&s, &polygon, distance);
		double deepestDirect = 1e300, deepestTwoSided = 1e300;
		for (int i = 0; i < direct.pointCount; ++i)
		{
			deepestDirect = fmin(deepestDirect, (double)direct.points[i].separation);
		}
		for (int i = 0; i < twoSided.pointCount; ++i)
		{
			deepestTwoSided = fmin(deepestTwoSided, (double)twoSided.points[i].separation);
		}
		TEST_CHECKF(
			direct.pointCount == twoSided.pointCount &&
				(double)cd2VecDistance(direct.normal, m) <= tolerance &&
				fabs(deepestDirect - deepestTwoSided) <= tolerance * fmax(1.0, fabs(deepestTwoSided)),
			"trial %d: direct %d points (%.7g %.7g) deepest %.7g, two-sided %d points (%.7g %.7g) deepest "
			"%.7g",
			trial, direct.pointCount, (double)direct.normal.x, (double)direct.normal.y, deepestDirect,
			twoSided.pointCount, (double)m.x, (double)m.y, deepestTwoSided);
		++twoSidedCompared;
	}
	printf("direct segment-polygon: %d of %d cases in contact (%d on the segment's face, %d along a gap), %d "
		   "bit for bit as the generic path; %d compared with the two-sided segment\n",
		   contacts, cases, faceReference, gapContacts, exact, twoSidedCompared);
	TEST_CHECK(contacts > cases / 4 && faceReference > contacts / 4 && gapContacts > 20 &&
			   twoSidedCompared > cases / 10);
}

/* Checks a dedicated manifold against the generic one: same count, normal, points, separations and
 * ids (within round-off); returns whether they agree bit for bit. */
static bool SameAsGeneric(int trial, const char* kind, const cd2Manifold* direct, const cd2Manifold* generic,
						  double tolerance)
{
	bool same = direct->pointCount == generic->pointCount &&
				(double)cd2VecDistance(direct->normal, generic->normal) <= tolerance;
	for (int i = 0; same && i < direct->pointCount; ++i)
	{
		const cd2ManifoldPoint* d = &direct->points[i];
		const cd2ManifoldPoint* g = &generic->points[i];
		same = d->id == g->id && (double)cd2VecDistance(d->point, g->point) <= tolerance &&
			   fabs((double)d->separation - (double)g->separation) <=
				   tolerance * fmax(1.0, fabs((double)g->separation));
	}
	TEST_CHECKF(
		same,
		"%s trial %d: direct %d points normal (%.7g %.7g) id %x sep %.7g, generic %d points normal (%.7g "
		"%.7g) id %x sep %.7g",
		kind, trial, direct->pointCount, (double)direct->normal.x, (double)direct->normal.y,
		direct->points[0].id, (double)direct->points[0].separation, generic->pointCount,
		(double)generic->normal.x, (double)generic->normal.y, generic->points[0].id,
		(double)generic->points[0].separation);
	bool identical = same && cd2VecEqual(direct->normal, generic->normal);
	for (int i = 0; identical && i < direct->pointCount; ++i)
	{
		identical = cd2VecEqual(direct->points[i].point, generic->points[i].point) &&
					direct->points[i].separation == generic->points[i].separation;
	}
	return identical;
}

/* The dedicated capsule and circle manifolds against the generic ones, on the same random
 * segments and ghosts: capsules of every direction (now and then parallel to the segment, along
 * its line, or of zero length) and circles (some of zero radius), placed as the polygons are.
 * Every point lies midway between the surfaces. */
static void TestDirectSegmentCapsuleCircle(void)
{
	TestRng rng = TestRngMake(0xCA95);
	const double tolerance = CD_DOUBLE ? 1e-9 : 2e-4;
	const cdReal speculative[3] = {CD_R(0.0), CD_R(0.02), CD_R(0.25)};
	const int cases = 6000;
	int capsuleContacts = 0, circleContacts = 0, capsuleExact = 0, circleExact = 0;
	for (int trial = 0; trial < cases; ++trial)
	{
		cd2ChainSegment s;
		cd2Polygon polygon;
		RandomSegmentPolygon(&rng, &s, &polygon);
		cdReal distance = speculative[TestRngInt(&rng, 3)];
		cd2Vec center = polygon.centroid;
		cd2Segment core = {s.p1, s.p2};
		double segmentAngle = atan2((double)(s.p2.y - s.p1.y), (double)(s.p2.x - s.p1.x));

		double half = TestRngRange(&rng, 0.05, 1.0);
		int shape = TestRngInt(&rng, 5);
		double angle = shape == 0	? segmentAngle
					   : shape == 1 ? segmentAngle + 3.14159265358979
									: TestRngRange(&rng, -3.2, 3.2);
		cd2Capsule capsule = {V((double)center.x - half * cos(angle), (double)center.y - half * sin(angle)),
							  V((double)center.x + half * cos(angle), (double)center.y + half * sin(angle)),
							  TestRngInt(&rng, 4) == 0 ? CD_R(0.0) : (cdReal)TestRngRange(&rng, 0.0, 0.4)};
		if (shape == 2)
		{
			capsule.p2 = capsule.p1; /* zero length: a circle */
		}
		else if (shape == 3)
		{
			/* Along the segment's line (collinear cores), within a hair of it, past either end. */
			double t = TestRngRange(&rng, -1.0, 2.0),
				   offset = TestRngInt(&rng, 2) == 0 ? 0.0 : TestRngRange(&rng, -1e-3, 1e-3);
			cd2Vec d = cd2Sub(s.p2, s.p1);
			cd2Vec normal = cd2RightPerp(cd2Normalize(d));
			capsule.p1 = V((double)s.p1.x + t * (double)d.x + offset * (double)normal.x,
						   (double)s.p1.y + t * (double)d.y + offset * (double)normal.y);
			capsule.p2 = V((double)capsule.p1.x + half * cos(segmentAngle),
						   (double)capsule.p1.y + half * sin(segmentAngle));
		}
		cd2Manifold direct = cd2CollideChainSegmentCapsuleDirect(&s, capsule, distance);
		cd2Manifold generic = cd2CollideChainSegmentCapsule(&s, capsule, distance);
		capsuleExact += SameAsGeneric(trial, "capsule", &direct, &generic, tolerance);
		cd2Segment capsuleCore = {capsule.p1, capsule.p2};
		for (int i = 0; i < direct.pointCount; ++i)
		{
			const cd2ManifoldPoint* p = &direct.points[i];
			cd2Vec onA = cd2MulSub(p->point, CD_R(0.5) * p->separation, direct.normal);
			cd2Vec onB = cd2MulAdd(p->point, CD_R(0.5) * p->separation, direct.normal);
			double offA = (double)cd2VecDistance(onA, cd2ClosestPointOnSegment(core, onA));
			double offB = (double)cd2VecDistance(onB, cd2ClosestPointOnSegment(capsuleCore, onB)) -
						  (double)capsule.radius;
			TEST_CHECKF(offA <= 10.0 * tolerance && fabs(offB) <= 10.0 * tolerance &&
							p->separation <= distance,
						"capsule trial %d point %d: %.3g off the segment, %.3g off the capsule", trial, i,
						offA, offB);
		}
		capsuleContacts += direct.pointCount > 0;

		cd2Circle circle = {center,
							TestRngInt(&rng, 4) == 0 ? CD_R(0.0) : (cdReal)TestRngRange(&rng, 0.0, 0.8)};
		direct = cd2CollideChainSegmentCircleDirect(&s, circle, distance);
		generic = cd2CollideChainSegmentCircle(&s, circle, distance);
		circleExact += SameAsGeneric(trial, "circle", &direct, &generic, tolerance);
		for (int i = 0; i < direct.pointCount; ++i)
		{
			const cd2ManifoldPoint* p = &direct.points[i];
			cd2Vec onA = cd2MulSub(p->point, CD_R(0.5) * p->separation, direct.normal);
			cd2Vec onB = cd2MulAdd(p->point, CD_R(0.5) * p->separation, direct.normal);
			double offA = (double)cd2VecDistance(onA, cd2ClosestPointOnSegment(core, onA));
			double offB = (double)cd2VecDistance(onB, circle.center) - (double)circle.radius;
			TEST_CHECKF(
				offA <= 10.0 * tolerance && fabs(offB) <= 10.0 * tolerance && p->separation <= distance,
				"circle trial %d point %d: %.3g off the segment, %.3g off the circle", trial, i, offA, offB);
		}
		circleContacts += direct.pointCount > 0;
	}
	printf("direct segment-capsule: %d of %d in contact, %d bit for bit; segment-circle: %d in contact, %d "
		   "bit for "
		   "bit\n",
		   capsuleContacts, cases, capsuleExact, circleContacts, circleExact);
	TEST_CHECK(capsuleContacts > cases / 8 && circleContacts > cases / 8);
}

/* fuzz_chain2 (fuzz/corpus/fuzz_chain2/regression-capsule-end-on-segment-end-1e9): a loop reaching
 * x = -1e9 and a zero-radius capsule whose end lies 5.8e-4 from the end of the long segment 7.
 * The capsule's core separates more than the segment's face, and its closest points to the
 * segment come out 5.8e-4 apart one way round the segment and 5.8e-10 the other (a crossing found
 * by rounding); the generic path takes the nearer and so the face contact. The dedicated routine
 * tried only one way round and reported a gap contact along -x: now both, as the generic path. */
static void TestDirectCapsuleEndOnSegmentEnd(void)
{
	const double xy[26] = {587500,	0,		 0,		  0,		0,		 1137500, 0,	   0,		-1100000,
						   -175000, 437500,	 -525000, -950000,	1050000, -1e9,	  1212500, 0,		200000,
						   -962500, -400000, -862500, -1112500, 50000,	 -237500, 1087500, -1237500};
	cd2Vec points[13];
	for (int i = 0; i < 13; ++i)
	{
		points[i] = V(xy[2 * i], xy[2 * i + 1]);
	}
	cd2Chain* chain = MakeChain(points, 13, true);
	if (chain == NULL)
	{
		return;
	}
	cd2Capsule capsule = {V(-0.000580846914, 200000), V(-962500, -1112500), CD_R(0.0)};
	for (int i = 0; i < cd2Chain_GetSegmentCount(chain); ++i)
	{
		cd2ChainSegment s = cd2Chain_GetSegment(chain, i);
		cd2Manifold direct = cd2CollideChainSegmentCapsuleDirect(&s, capsule, CD_R(637500.0));
		cd2Manifold generic = cd2CollideChainSegmentCapsule(&s, capsule, CD_R(637500.0));
		TEST_CHECKF(direct.pointCount == generic.pointCount &&
						(double)cd2VecDistance(direct.normal, generic.normal) <= 1e-6 &&
						(direct.pointCount == 0 || direct.points[0].id == generic.points[0].id),
					"segment %d: direct %d points normal (%.9g %.9g), generic %d points normal (%.9g %.9g)",
					i, direct.pointCount, (double)direct.normal.x, (double)direct.normal.y,
					generic.pointCount, (double)generic.normal.x, (double)generic.normal.y);
	}
	cd2DestroyChain(chain);
}

/* fuzz_chain2 (fuzz/corpus/fuzz_chain2/regression-capsule-end-on-core-line): a capsule standing
 * upright below the end p2 = (0, 0) of a floor segment, its core on the line x = 0 through p2.
 * The closest points are p2 and the capsule's top end (a gap contact along -y); the dedicated
 * routine searched only the capsule edges facing each segment end, and p2, on the core's line,
 * faces neither: it took p1 instead, whose tilted normal then fell back to the face contact. */
static void TestDirectCapsuleEndOnCoreLine(void)
{
	cd2ChainSegment s = {V(-875000, 0), V(-437500, 0), V(0, 0), V(0, -1100000)};
	cd2Capsule capsule = {V(0, -862500), V(0, -1237500), CD_R(400000.0)};
	cd2Manifold direct = cd2CollideChainSegmentCapsuleDirect(&s, capsule, CD_R(725000.0));
	cd2Manifold generic = cd2CollideChainSegmentCapsule(&s, capsule, CD_R(725000.0));
	TEST_CHECKF(direct.pointCount == 1 && generic.pointCount == 1 &&
					direct.points[0].id == generic.points[0].id &&
					(double)cd2VecDistance(direct.normal, generic.normal) <= 1e-6,
				"direct %d points id %x normal (%.9g %.9g), generic %d points id %x normal (%.9g %.9g)",
				direct.pointCount, direct.points[0].id, (double)direct.normal.x, (double)direct.normal.y,
				generic.pointCount, generic.points[0].id, (double)generic.normal.x, (double)generic.normal.y);
	/* The contact is the gap between the segment's end and the capsule's top end. */
	TEST_CHECK_NEAR((double)direct.normal.y, -1.0, 1e-6);
	TEST_CHECK_NEAR((double)direct.points[0].separation, 862500.0 - 400000.0, 1e-3);
}

/* fuzz_chain2 (fuzz/corpus/fuzz_chain2/regression-capsule-ends-tie-1e9): a capsule of radius 1e9
 * whose short core lies 6.7e8 above a segment 1.5e9 long. Its two ends are equally far from the
 * segment up to the rounding at that scale (64), and the generic path's search over the core's
 * edges picks the second end; the dedicated routine took the lowest end by height (the first):
 * now it runs the same search, candidate for candidate, and picks the same end. */
static void TestDirectCapsuleEndsTie(void)
{
	cd2ChainSegment s = {V(-26841788, -58.75), V(116848000, -1e9), V(-1e9, -28.75), V(-71.25, 67.5)};
	cd2Capsule capsule = {V(35, 13.75), V(-22.5, 2.5), CD_R(1e9)};
	cd2Manifold direct = cd2CollideChainSegmentCapsuleDirect(&s, capsule, CD_R(97.5));
	cd2Manifold generic = cd2CollideChainSegmentCapsule(&s, capsule, CD_R(97.5));
	TEST_CHECKF(direct.pointCount == generic.pointCount && direct.pointCount == 1 &&
					direct.points[0].id == generic.points[0].id &&
					direct.points[0].separation == generic.points[0].separation,
				"direct %d points id %x separation %.9g, generic %d points id %x separation %.9g",
				direct.pointCount, direct.points[0].id, (double)direct.points[0].separation,
				generic.pointCount, generic.points[0].id, (double)generic.points[0].separation);
}

/* fuzz_chain2 (fuzz/corpus/fuzz_chain2/regression-capsule-face-side-1e9): a segment ending 0.125
 * below the upright core of a capsule of radius 1e9. The closest points are the segment's end and
 * a point inside the core, so the capsule's face is tried; the generic path takes the side of the
 * two-sided core that faces the gap (here square to both sides: the first), the dedicated routine
 * took the side that separated most and reported that face's contact (normal +x) where the
 * generic path reports the segment's face. */
static void TestDirectCapsuleFaceSide(void)
{
	cd2ChainSegment s = {V(0, 0), V(0, -1e9), V(1e9, -0.125001937), V(-1e9, -1e9)};
	cd2Capsule capsule = {V(1e9, -1e9), V(1e9, 1e9), CD_R(1e9)};
	cd2Manifold direct = cd2CollideChainSegmentCapsuleDirect(&s, capsule, CD_R(0.0));
	cd2Manifold generic = cd2CollideChainSegmentCapsule(&s, capsule, CD_R(0.0));
	/* In double the segment's end (rounded from the fuzzer's floats) ends just clear of the capsule:
	 * no contact either way. */
	TEST_CHECKF(direct.pointCount == generic.pointCount && (CD_DOUBLE || direct.pointCount > 0) &&
					direct.points[0].id == generic.points[0].id &&
					(double)cd2VecDistance(direct.normal, generic.normal) <= 1e-6,
				"direct %d points id %x normal (%.9g %.9g), generic %d points id %x normal (%.9g %.9g)",
				direct.pointCount, direct.points[0].id, (double)direct.normal.x, (double)direct.normal.y,
				generic.pointCount, generic.points[0].id, (double)generic.normal.x, (double)generic.normal.y);
}

/* fuzz_chain2 (fuzz/corpus/fuzz_chain2/regression-polygon-face-facing-away-1e9): a rounded sliver
 * polygon reaching from 1e9 to a vertex near a short chain segment. At those coordinates the
 * closest points of the cores tie between the polygon's edges, and the one found has its closest
 * point inside a face whose normal points away from the segment. The generic path refuses such a
 * face and takes the gap contact; the dedicated routine clipped against that face, which the chain
 * then turned into a two-point contact on the segment's face where the generic path reports none. */
static void TestDirectPolygonFaceFacingAway(void)
{
	cd2ChainSegment s = {V(0.0081249997, 0.0081249997), V(-0.00162500003, -0.00124999997),
						 V(-0.00325000007, -0.00412499998), V(0.00800000038, 0.0118749999)};
	cd2Vec points[3] = {V(-1e9, -1e9), V(-9.99999972e-10, 0.00862499978), V(-1e9, -32934408.0)};
	cd2Polygon polygon;
	TEST_CHECK(cd2MakeRoundedPolygon(points, 3, CD_R(0.0125000002), &polygon) == CD_OK);
	cd2Manifold direct = cd2CollideChainSegmentPolygonDirect(&s, &polygon, CD_R(0.0));
	cd2Manifold generic = cd2CollideChainSegmentPolygon(&s, &polygon, CD_R(0.0));
	bool same = direct.pointCount == generic.pointCount && cd2VecEqual(direct.normal, generic.normal);
	for (int i = 0; same && i < direct.pointCount; ++i)
	{
		same = direct.points[i].id == generic.points[i].id &&
			   cd2VecEqual(direct.points[i].point, generic.points[i].point) &&
			   direct.points[i].separation == generic.points[i].separation;
	}
	TEST_CHECKF(same, "direct %d points normal (%.9g %.9g), generic %d points normal (%.9g %.9g)",
				direct.pointCount, (double)direct.normal.x, (double)direct.normal.y, generic.pointCount,
				(double)generic.normal.x, (double)generic.normal.y);
}

/* Extreme scales: nothing NaN, normals unit, hits on the chain's side. */
static void TestScales(void)
{
	static cd2Vec points[200];
	TestRng rng = TestRngMake(0x5CA1E);
	const double scales[] = {1e-9, 1e-5, 1.0, 1e5, 1e9};
	int finite = 0;
	for (int si = 0; si < 5; ++si)
	{
		double k = scales[si];
		int n = RandomTerrain(points, 200, &rng);
		for (int i = 0; i < n; ++i)
		{
			points[i] = V(k * (double)points[i].x, k * (double)points[i].y);
		}
		/* The weld tolerance is half a linear slop: at other scales the length unit follows. */
		cdSetLengthUnitsPerMeter((cdReal)k);
		cd2Chain* chain = MakeChain(points, n, si % 2 == 1);
		if (chain == NULL)
		{
			cdSetLengthUnitsPerMeter(CD_R(1.0));
			continue;
		}
		cd2Transform frame = MakeTransform(k * 3.0, -k * 2.0, 0.3 * si);
		cd2Aabb all = cd2Chain_GetBounds(chain);
		for (int trial = 0; trial < 200; ++trial)
		{
			cd2Vec c = cd2TransformPoint(frame, V(TestRngRange(&rng, (double)all.min.x, (double)all.max.x),
												  TestRngRange(&rng, (double)all.min.y, (double)all.max.y)));
			cd2Shape shape;
			if (trial % 3 == 0)
			{
				cd2Circle circle = {c, (cdReal)(k * TestRngRange(&rng, 0, 2))};
				shape = cd2MakeCircleShape(circle);
			}
			else if (trial % 3 == 1)
			{
				cd2Capsule capsule = {c, V((double)c.x + k, (double)c.y),
									  (cdReal)(k * TestRngRange(&rng, 0, 1))};
				shape = cd2MakeCapsuleShape(capsule);
			}
			else
			{
				cd2Box box = {c, V(k * TestRngRange(&rng, 0, 2), k * TestRngRange(&rng, 0, 2)),
							  cd2MakeRot((cdReal)TestRngRange(&rng, -3, 3))};
				shape = cd2MakeBoxShape(box);
			}
			cd2Manifold manifolds[64];
			int count = cd2CollideChain(chain, frame, &shape, (cdReal)(0.1 * k), manifolds, 64, NULL);
			bool ok = true;
			for (int m = 0; m < count; ++m)
			{
				ok = ok && cd2IsValidVec(manifolds[m].normal) &&
					 fabs((double)cd2Length(manifolds[m].normal) - 1.0) <= 1e-3;
				for (int p = 0; p < manifolds[m].pointCount; ++p)
				{
					ok = ok && cd2IsValidVec(manifolds[m].points[p].point) &&
						 isfinite((double)manifolds[m].points[p].separation);
				}
			}
			cd2Ray ray = {c, V(k * TestRngRange(&rng, -20, 20), k * TestRngRange(&rng, -20, 20))};
			cd2RayHit hit;
			if (cd2RaycastChain(chain, frame, ray, &hit, NULL))
			{
				ok = ok && cd2IsValidVec(hit.point) && cd2IsValidVec(hit.normal) &&
					 hit.fraction >= CD_R(0.0) && hit.fraction <= CD_R(1.0) &&
					 fabs((double)cd2Length(hit.normal) - 1.0) <= 1e-3 &&
					 cd2Dot(hit.normal, ray.translation) <= CD_R(0.0);
			}
			TEST_CHECKF(ok, "scale %g trial %d: not finite or not unit", k, trial);
			finite += ok;
		}
		TEST_CHECK(cd2Chain_GetPointCount(chain) == n);
		cd2DestroyChain(chain);
		cdSetLengthUnitsPerMeter(CD_R(1.0));
	}
	TEST_CHECK(finite == 1000);
}

int main(void)
{
	TEST_RUN(TestBadInput);
	TEST_RUN(TestGhosts);
	TEST_RUN(TestSlidingOnStraightTerrain);
	TEST_RUN(TestTiltedShapesOnTerrain);
	TEST_RUN(TestOtherShapes);
	TEST_RUN(TestTwoSidedSegmentsCatch);
	TEST_RUN(TestHill);
	TEST_RUN(TestBackSide);
	TEST_RUN(TestLoops);
	TEST_RUN(TestQueryAabb);
	TEST_RUN(TestRaycast);
	TEST_RUN(TestRayAlongSegmentLine);
	TEST_RUN(TestCollideAgainstBruteForce);
	TEST_RUN(TestDirectSegmentPolygon);
	TEST_RUN(TestDirectSegmentCapsuleCircle);
	TEST_RUN(TestDirectCapsuleEndOnSegmentEnd);
	TEST_RUN(TestDirectCapsuleEndOnCoreLine);
	TEST_RUN(TestDirectCapsuleEndsTie);
	TEST_RUN(TestDirectCapsuleFaceSide);
	TEST_RUN(TestDirectPolygonFaceFacingAway);
	TEST_RUN(TestScales);
	return TEST_SUMMARY();
}
