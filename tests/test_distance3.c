/* Tests of cd3Distance (GJK): exact cases, and thousands of random pairs of every type
 * combination against an independent brute-force reference in double precision (feature
 * enumeration), plus symmetry, rigid-transform invariance and witness-point checks. */
#include "needle_cases3.h"
#include "test_distance3_reference.h"

static double g_maxError = 0.0;

static void CheckPair(TestRng* rng, const cd3Shape* a, const cd3Shape* b)
{
	g_printedCase = false;
	double expected = RefDistance(a, b);
	cd3ClosestPoints r = cd3Distance(a, b);
	bool ok = CheckResult(a, b, r);
	double error = fabs((double)r.distance - expected);
	g_maxError = error > g_maxError ? error : g_maxError;
	bool near = error <= TOLERANCE;
	TEST_CHECKF(near, "distance %.9g, reference %.9g", (double)r.distance, expected);
	ReportCase(ok && near, a, b);
	g_printedCase = !(ok && near);

	/* Symmetry: the same distance, and the witnesses swapped. The witnesses are unique when
	 * one shape is a ball (strictly convex); otherwise both pairs need only be valid. */
	cd3ClosestPoints s = cd3Distance(b, a);
	bool okSwapped = CheckResult(b, a, s);
	bool symmetric = fabs((double)(s.distance - r.distance)) <= TOLERANCE;
	TEST_CHECKF(symmetric, "d(a,b) = %.9g, d(b,a) = %.9g", (double)r.distance, (double)s.distance);
	if (a->type == CD3_SHAPE_SPHERE || b->type == CD3_SHAPE_SPHERE)
	{
		double moved =
			DLength(DSub(DFrom(r.pointA), DFrom(s.pointB))) + DLength(DSub(DFrom(r.pointB), DFrom(s.pointA)));
		bool swapped = r.distance == CD_R(0.0) || moved <= 100.0 * TOLERANCE;
		TEST_CHECKF(swapped, "witnesses not swapped: moved by %.3g", moved);
		symmetric = symmetric && swapped;
	}
	ReportCase(okSwapped && symmetric, a, b);
	g_printedCase = g_printedCase || !(okSwapped && symmetric);

	/* Invariance under a common rigid transform (translation only with an AABB). */
	cd3Transform t;
	t.p = RandomVec(rng, 3.0);
	t.q = (a->type == CD3_SHAPE_AABB || b->type == CD3_SHAPE_AABB) ? CD3_QUAT_IDENTITY : RandomQuat(rng);
	cd3Shape ta = TransformShape(a, t), tb = TransformShape(b, t);
	cd3ClosestPoints u = cd3Distance(&ta, &tb);
	bool invariant = fabs((double)(u.distance - r.distance)) <= 2.0 * TOLERANCE;
	TEST_CHECKF(invariant, "transformed distance %.9g, original %.9g", (double)u.distance,
				(double)r.distance);
	ReportCase(invariant, a, b);
}

static void TestRandomPairs(void)
{
	TestRng rng = TestRngMake(0x6a6b3d01u);
	const int pairsPerCombination = 700;
	for (int ta = 0; ta < CD3_SHAPE_TYPE_COUNT; ++ta)
	{
		for (int tb = ta; tb < CD3_SHAPE_TYPE_COUNT; ++tb)
		{
			/* The brute-force reference on hulls (up to 64 vertices) costs most: fewer pairs. */
			bool hull = ta == CD3_SHAPE_HULL || tb == CD3_SHAPE_HULL;
			for (int i = 0; i < (hull ? pairsPerCombination / 7 : pairsPerCombination); ++i)
			{
				cd3Shape a = RandomShape(&rng, (cd3ShapeType)ta);
				cd3Shape b = RandomShape(&rng, (cd3ShapeType)tb);
				CheckPair(&rng, &a, &b);
			}
		}
	}
	printf("largest distance error against the reference: %.3g\n", g_maxError);
}

/* ---- exact cases ------------------------------------------------------------------------------- */
static void TestSpheres(void)
{
	cd3Shape a = Sphere(CD_R(0.0), CD_R(0.0), CD_R(0.0), CD_R(1.0));
	cd3Shape b = Sphere(CD_R(4.0), CD_R(0.0), CD_R(0.0), CD_R(2.0));
	cd3ClosestPoints r = cd3Distance(&a, &b);
	TEST_CHECK_NEAR(r.distance, 1.0, TOLERANCE);
	NEAR_VEC(r.pointA, V(1.0, 0.0, 0.0));
	NEAR_VEC(r.pointB, V(2.0, 0.0, 0.0));

	/* Touching: distance 0, one point. */
	b.sphere.center.x = CD_R(3.0);
	r = cd3Distance(&a, &b);
	TEST_CHECK(r.distance == CD_R(0.0) && cd3VecEqual(r.pointA, r.pointB));
	NEAR_VEC(r.pointA, V(1.0, 0.0, 0.0));

	/* Overlapping: the point lies inside both. */
	b.sphere.center.x = CD_R(2.0);
	r = cd3Distance(&a, &b);
	TEST_CHECK(r.distance == CD_R(0.0) && cd3VecEqual(r.pointA, r.pointB));
	TEST_CHECK(cd3Length(r.pointA) <= CD_R(1.0) + TOLERANCE &&
			   cd3VecDistance(r.pointA, b.sphere.center) <= CD_R(2.0));

	/* Coincident zero-radius spheres (points). */
	cd3Shape p = Sphere(CD_R(1.0), CD_R(2.0), CD_R(3.0), CD_R(0.0));
	r = cd3Distance(&p, &p);
	TEST_CHECK(r.distance == CD_R(0.0) && cd3VecEqual(r.pointA, p.sphere.center));
}

static void TestBoxesAndAabbs(void)
{
	cd3Shape a = Aabb(V(0.0, 0.0, 0.0), V(1.0, 1.0, 1.0));
	cd3Shape b = Aabb(V(3.0, 0.5, 0.5), V(4.0, 2.0, 2.0));
	TEST_CHECK_NEAR(cd3Distance(&a, &b).distance, 2.0, TOLERANCE);

	/* Corner to corner: sqrt(3). */
	b = Aabb(V(2.0, 2.0, 2.0), V(3.0, 3.0, 3.0));
	cd3ClosestPoints r = cd3Distance(&a, &b);
	TEST_CHECK_NEAR(r.distance, sqrt(3.0), TOLERANCE);
	NEAR_VEC(r.pointA, V(1.0, 1.0, 1.0));
	NEAR_VEC(r.pointB, V(2.0, 2.0, 2.0));

	/* Face contact counts as touching. */
	b = Aabb(V(1.0, 0.0, 0.0), V(2.0, 1.0, 1.0));
	TEST_CHECK(cd3Distance(&a, &b).distance == CD_R(0.0));

	/* Nested. */
	b = Aabb(V(0.25, 0.25, 0.25), V(0.5, 0.5, 0.5));
	r = cd3Distance(&a, &b);
	TEST_CHECK(r.distance == CD_R(0.0) && cd3VecEqual(r.pointA, r.pointB));

	/* A box turned 45 degrees about z: its corner reaches x = 5 - sqrt(2). */
	cd3Quat q = cd3MakeQuatAxisAngle(V(0.0, 0.0, 1.0), CD_R(0.25) * CD_PI);
	cd3Shape box = Box(V(5.0, 0.5, 0.5), V(1.0, 1.0, 0.5), q);
	r = cd3Distance(&a, &box);
	TEST_CHECK_NEAR(r.distance, 4.0 - sqrt(2.0), 4.0 * TOLERANCE);
	TEST_CHECK_NEAR(r.pointB.x, 5.0 - sqrt(2.0), 4.0 * TOLERANCE);
	TEST_CHECK_NEAR(r.pointB.y, 0.5, 4.0 * TOLERANCE);

	/* Zero-size box (a point) touching a corner. */
	cd3Shape point = Box(V(1.0, 1.0, 1.0), V(0.0, 0.0, 0.0), CD3_QUAT_IDENTITY);
	TEST_CHECK(cd3Distance(&a, &point).distance == CD_R(0.0));
	point.box.center = V(1.0, 1.0, 3.0);
	TEST_CHECK_NEAR(cd3Distance(&point, &a).distance, 2.0, TOLERANCE);
}

static void TestCapsulesSegmentsTriangles(void)
{
	/* Parallel capsules: distance 3 - 0.5 - 0.25. */
	cd3Shape a = Capsule(V(0.0, 0.0, 0.0), V(4.0, 0.0, 0.0), CD_R(0.5));
	cd3Shape b = Capsule(V(1.0, 3.0, 0.0), V(2.0, 3.0, 0.0), CD_R(0.25));
	cd3ClosestPoints r = cd3Distance(&a, &b);
	TEST_CHECK_NEAR(r.distance, 2.25, TOLERANCE);
	TEST_CHECK_NEAR(r.pointA.y, 0.5, TOLERANCE);
	TEST_CHECK_NEAR(r.pointB.y, 2.75, TOLERANCE);

	/* Zero-length capsule is a sphere. */
	b = Capsule(V(2.0, 0.0, 2.0), V(2.0, 0.0, 2.0), CD_R(1.0));
	TEST_CHECK_NEAR(cd3Distance(&a, &b).distance, 0.5, TOLERANCE);

	/* Crossing segments (skew lines at distance 1, then touching). */
	cd3Shape s1 = Segment(V(-1.0, 0.0, 0.0), V(1.0, 0.0, 0.0));
	cd3Shape s2 = Segment(V(0.0, -1.0, 1.0), V(0.0, 1.0, 1.0));
	r = cd3Distance(&s1, &s2);
	TEST_CHECK_NEAR(r.distance, 1.0, TOLERANCE);
	NEAR_VEC(r.pointA, V(0.0, 0.0, 0.0));
	NEAR_VEC(r.pointB, V(0.0, 0.0, 1.0));
	s2 = Segment(V(0.0, -1.0, 0.0), V(0.0, 1.0, 0.0));
	r = cd3Distance(&s1, &s2);
	TEST_CHECK(r.distance == CD_R(0.0) && cd3VecEqual(r.pointA, r.pointB));
	NEAR_VEC(r.pointA, V(0.0, 0.0, 0.0));

	/* Segment piercing a triangle, and one hovering above it. */
	cd3Shape t = Triangle(V(-1.0, -1.0, 0.0), V(2.0, -1.0, 0.0), V(-1.0, 2.0, 0.0));
	cd3Shape g = Segment(V(0.0, 0.0, -1.0), V(0.0, 0.0, 1.0));
	r = cd3Distance(&t, &g);
	TEST_CHECK(r.distance == CD_R(0.0));
	NEAR_VEC(r.pointA, V(0.0, 0.0, 0.0));
	g = Segment(V(0.0, 0.0, 0.5), V(3.0, 3.0, 0.5));
	TEST_CHECK_NEAR(cd3Distance(&t, &g).distance, 0.5, TOLERANCE);

	/* Degenerate (collinear) triangle behaves as its segment. */
	cd3Shape flat = Triangle(V(0.0, 0.0, 0.0), V(1.0, 0.0, 0.0), V(2.0, 0.0, 0.0));
	cd3Shape p = Sphere(CD_R(1.5), CD_R(2.0), CD_R(0.0), CD_R(0.5));
	r = cd3Distance(&flat, &p);
	TEST_CHECK_NEAR(r.distance, 1.5, TOLERANCE);
	NEAR_VEC(r.pointA, V(1.5, 0.0, 0.0));
	cd3Shape dot = Triangle(V(1.0, 1.0, 1.0), V(1.0, 1.0, 1.0), V(1.0, 1.0, 1.0));
	TEST_CHECK_NEAR(cd3Distance(&dot, &p).distance, sqrt(0.25 + 1.0 + 1.0) - 0.5, TOLERANCE);
}

static void TestPlanes(void)
{
	cd3Shape ground = Plane(V(0.0, 1.0, 0.0), CD_R(1.0));
	cd3Shape s = Sphere(CD_R(3.0), CD_R(4.0), CD_R(0.0), CD_R(1.0));
	cd3ClosestPoints r = cd3Distance(&ground, &s);
	TEST_CHECK_NEAR(r.distance, 2.0, TOLERANCE);
	NEAR_VEC(r.pointA, V(3.0, 1.0, 0.0));
	NEAR_VEC(r.pointB, V(3.0, 3.0, 0.0));
	r = cd3Distance(&s, &ground);
	NEAR_VEC(r.pointA, V(3.0, 3.0, 0.0));
	NEAR_VEC(r.pointB, V(3.0, 1.0, 0.0));

	/* Resting and sunk shapes: distance 0 at a point inside both. */
	s.sphere.center.y = CD_R(2.0);
	TEST_CHECK(cd3Distance(&ground, &s).distance == CD_R(0.0));
	cd3Shape box = Aabb(V(-1.0, -5.0, -1.0), V(1.0, 0.0, 1.0));
	r = cd3Distance(&box, &ground);
	TEST_CHECK(r.distance == CD_R(0.0) && cd3VecEqual(r.pointA, r.pointB) && r.pointA.y <= CD_R(1.0));

	/* Opposite half-spaces: apart, then overlapping; non-opposite ones always meet. */
	cd3Shape sky = Plane(V(0.0, -1.0, 0.0), CD_R(-4.0)); /* y >= 4 */
	r = cd3Distance(&ground, &sky);
	TEST_CHECK_NEAR(r.distance, 3.0, TOLERANCE);
	TEST_CHECK_NEAR(r.pointA.y, 1.0, TOLERANCE);
	TEST_CHECK_NEAR(r.pointB.y, 4.0, TOLERANCE);
	sky.plane.offset = CD_R(0.0); /* y >= 0 */
	r = cd3Distance(&ground, &sky);
	TEST_CHECK(r.distance == CD_R(0.0) && r.pointA.y >= CD_R(0.0) && r.pointA.y <= CD_R(1.0));
	cd3Shape wall = Plane(V(1.0, 0.0, 0.0), CD_R(-7.0));
	r = cd3Distance(&ground, &wall);
	TEST_CHECK(r.distance == CD_R(0.0) && cd3VecEqual(r.pointA, r.pointB));
	TEST_CHECK_NEAR(r.pointA.x, -7.0, TOLERANCE);
	TEST_CHECK_NEAR(r.pointA.y, 1.0, TOLERANCE);
	cd3Shape same = Plane(V(0.0, 1.0, 0.0), CD_R(-3.0));
	r = cd3Distance(&ground, &same);
	TEST_CHECK(r.distance == CD_R(0.0) && r.pointA.y <= CD_R(-3.0));
}

/* The common point of two meeting half-spaces lies in both. For nearly parallel normals (the
 * fuzzer's cosine 1 - 1.5e-8, below float resolution) the solve for the line where the
 * boundaries meet put it 1.2e-4 outside both. Exact case, then random pairs from nearly parallel
 * to nearly opposite normals (sine from 1e-9 to 1 either way) and offsets of every size. */
static bool InHalfSpace(cd3Plane p, cd3Vec x, double tolerance)
{
	return DDot(DFrom(p.normal), DFrom(x)) - (double)p.offset <= tolerance;
}

static void TestHalfSpaceWitnesses(void)
{
	cd3Plane a = {V(-1.0, 0.0, 0.0), CD_R(-0.000121249999)};
	cd3Plane b = {cd3Normalize(V(-1.0, -0.000125000006, -0.000125000006)), CD_R(-0.000125000006)};
	TestRng rng = TestRngMake(0x6a6b3d08u);
	for (int i = 0; i <= 4000; ++i)
	{
		if (i > 0)
		{
			cd3Vec n = RandomUnit(&rng);
			cd3Vec side = cd3Normalize(cd3Cross(n, RandomUnit(&rng)));
			double sine = pow(10.0, TestRngRange(&rng, -9.0, 0.0));
			double cosine = sqrt(1.0 - sine * sine) * (TestRngInt(&rng, 2) == 0 ? -1.0 : 1.0);
			double scale = pow(10.0, TestRngRange(&rng, -6.0, 6.0));
			a.normal = n;
			b.normal = cd3Normalize(cd3Add(cd3Scale((cdReal)cosine, n), cd3Scale((cdReal)sine, side)));
			a.offset = (cdReal)(scale * TestRngRange(&rng, -1.0, 1.0));
			b.offset = (cdReal)(scale * TestRngRange(&rng, -1.0, 1.0));
		}
		cd3Shape sa = cd3MakePlaneShape(a), sb = cd3MakePlaneShape(b);
		cd3ClosestPoints r = cd3Distance(&sa, &sb);
		if (r.distance > CD_R(0.0))
		{
			continue; /* apart: opposite normals, checked in TestPlanes and test_overlap3 */
		}
		double magnitude =
			fmax(fmax(fabs((double)a.offset), fabs((double)b.offset)), DLength(DFrom(r.pointA)));
		double tolerance = 64.0 * (double)CD_REAL_EPSILON * magnitude;
		TEST_CHECKF(
			CheckFinitePoints(r) && cd3VecEqual(r.pointA, r.pointB) && InHalfSpace(a, r.pointA, tolerance) &&
				InHalfSpace(b, r.pointA, tolerance),
			"case %d: normals (%.9g %.9g %.9g) and (%.9g %.9g %.9g), offsets %.9g and %.9g: the common "
			"point is %.3g and %.3g outside (tolerance %.3g)",
			i, (double)a.normal.x, (double)a.normal.y, (double)a.normal.z, (double)b.normal.x,
			(double)b.normal.y, (double)b.normal.z, (double)a.offset, (double)b.offset,
			DDot(DFrom(a.normal), DFrom(r.pointA)) - (double)a.offset,
			DDot(DFrom(b.normal), DFrom(r.pointA)) - (double)b.offset, tolerance);
	}
}

/* Far from the origin and very small or very large: finite answers, right to round-off. */
static void TestScales(void)
{
	const cdReal scales[] = {CD_R(1e-9), CD_R(1e-4), CD_R(1.0), CD_R(1e4), CD_R(1e9)};
	for (int i = 0; i < 5; ++i)
	{
		cdReal k = scales[i];
		cd3Quat q = cd3MakeQuatAxisAngle(V(1.0, 2.0, 3.0), CD_R(0.7));
		cd3Shape box = Box(cd3Scale(k, V(1.0, 2.0, 3.0)), cd3Scale(k, V(1.0, 0.5, 0.25)), q);
		cd3Shape cap = Capsule(cd3Scale(k, V(5.0, 2.0, 3.0)), cd3Scale(k, V(5.0, 4.0, 3.0)), CD_R(0.5) * k);
		cd3ClosestPoints r = cd3Distance(&box, &cap);
		double expected = RefDistance(&box, &cap);
		TEST_CHECKF(isfinite((double)r.distance) && fabs((double)r.distance - expected) <= 1e-4 * expected,
					"scale %g: distance %.9g, reference %.9g", (double)k, (double)r.distance, expected);
		cd3Shape t = Triangle(cd3Scale(k, V(0.0, 0.0, 0.0)), cd3Scale(k, V(1.0, 0.0, 0.0)),
							  cd3Scale(k, V(0.0, 1.0, 0.0)));
		cd3Shape s = Sphere(CD_R(0.25) * k, CD_R(0.25) * k, CD_R(2.0) * k, k);
		r = cd3Distance(&t, &s);
		TEST_CHECK_NEAR((double)r.distance / (double)k, 1.0, 1e-4);
	}
}

/* Every pair scaled as a whole to the ends of the documented range (1e-9..1e9 in float,
 * 1e-30..1e30 in double): finite answers that scale with the shapes; and pairs whose two shapes
 * differ in size by up to 18 (float) or 60 (double) orders of magnitude: finite answers. */
/* The hull support scan runs four vertices at a time with a scalar tail (sat3_support.h): hulls
 * of every vertex count from 4 to 20 (every tail length) against random boxes and hulls, and a
 * cube hull, whose corners tie four by four along the axes, against the same cube as a box. */
static void TestHullVertexCounts(void)
{
	TestRng rng = TestRngMake(20261121);
	for (int count = 4; count <= 20; ++count)
	{
		cd3Vec points[20];
		for (int i = 0; i < count; ++i)
		{
			cd3Vec d = RandomUnit(&rng);
			points[i] = cd3MakeVec(d.x * RandomReal(&rng, 0.4, 0.7), d.y * RandomReal(&rng, 0.4, 0.7),
								   d.z * RandomReal(&rng, 0.4, 0.7));
		}
		cd3Hull* hull = NULL;
		if (cd3ComputeHull(points, count, &hull) != CD_OK || hull == NULL)
		{
			TEST_CHECKF(false, "hull of %d random points", count);
			continue;
		}
		for (int k = 0; k < 40; ++k)
		{
			cd3Transform place = {RandomVec(&rng, 0.5), RandomQuat(&rng)};
			cd3Shape shape = cd3MakeHullShape(hull, place);
			cd3Shape other;
			if (k % 2 == 0)
			{
				cd3Box box = {cd3Add(RandomUnit(&rng), RandomVec(&rng, 0.5)),
							  cd3MakeVec(RandomReal(&rng, 0.1, 0.5), RandomReal(&rng, 0.1, 0.5),
										 RandomReal(&rng, 0.1, 0.5)),
							  RandomQuat(&rng)};
				other = cd3MakeBoxShape(box);
			}
			else
			{
				cd3Transform near = {cd3Scale(CD_R(1.5), RandomUnit(&rng)), RandomQuat(&rng)};
				other = cd3MakeHullShape(RandomHull(&rng), near);
			}
			if (RefDistance(&shape, &other) < 1e-3)
			{
				continue;
			}
			CheckAgainstReference(&shape, &other, 64.0 * (double)CD_REAL_EPSILON * 4.0, "hull of n vertices");
		}
		cd3DestroyHull(hull);
	}

	cd3Vec corners[8];
	for (int i = 0; i < 8; ++i)
	{
		corners[i] = cd3MakeVec((i & 1) ? CD_R(0.5) : CD_R(-0.5), (i & 2) ? CD_R(0.5) : CD_R(-0.5),
								(i & 4) ? CD_R(0.5) : CD_R(-0.5));
	}
	cd3Hull* cube = NULL;
	TEST_CHECK(cd3ComputeHull(corners, 8, &cube) == CD_OK && cube != NULL);
	if (cube == NULL)
	{
		return;
	}
	for (int k = 0; k < 200; ++k)
	{
		cd3Transform t = {RandomVec(&rng, 1.0), RandomQuat(&rng)};
		cd3Shape cubeHull = cd3MakeHullShape(cube, t);
		cd3Box box = {t.p, cd3MakeVec(CD_R(0.5), CD_R(0.5), CD_R(0.5)), t.q};
		cd3Shape cubeBox = cd3MakeBoxShape(box);
		/* Axis-aligned in the cube's frame: the support ties among a face's four corners. */
		static const cd3Vec axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
		cd3Vec local = cd3Scale(k % 2 == 0 ? CD_R(1.0) : CD_R(-1.0), axes[k % 3]);
		cd3Vec offset = cd3Add(cd3Scale(RandomReal(&rng, 0.6, 1.5), local), RandomVec(&rng, 0.3));
		cd3Sphere sphere = {cd3Add(t.p, cd3RotateVector(t.q, offset)), RandomReal(&rng, 0.0, 0.05)};
		cd3Shape ball = cd3MakeSphereShape(sphere);
		cd3ClosestPoints fromHull = cd3Distance(&cubeHull, &ball), fromBox = cd3Distance(&cubeBox, &ball);
		double tolerance = 64.0 * (double)CD_REAL_EPSILON * 4.0;
		TEST_CHECKF(fabs((double)fromHull.distance - (double)fromBox.distance) <= tolerance &&
						cd3Length(cd3Sub(fromHull.pointA, fromBox.pointA)) <=
							CD_R(64.0) * CD_REAL_EPSILON * CD_R(4.0),
					"cube hull %.9g vs box %.9g", (double)fromHull.distance, (double)fromBox.distance);
		if (RefDistance(&cubeHull, &ball) >= 1e-3)
		{
			CheckAgainstReference(&cubeHull, &ball, tolerance, "cube hull and ball");
		}
	}
	cd3DestroyHull(cube);
}

static void TestDistanceStatus(void)
{
	cd3Box box = {{0, 0, 0}, {1, 1, 1}, cd3MakeQuatAxisAngle(cd3MakeVec(1, 2, 3), CD_R(0.7))};
	cd3Sphere sphere = {{4, 0.5f, -0.25f}, 0.5f};
	cd3Shape a = cd3MakeBoxShape(box), b = cd3MakeSphereShape(sphere);
	cdDistanceStatus status = {-1, true};
	cd3ClosestPoints withStatus = cd3DistanceWithStatus(&a, &b, &status);
	cd3ClosestPoints plain = cd3Distance(&a, &b);
	TEST_CHECK(withStatus.distance == plain.distance && withStatus.distance > CD_R(1.0));
	TEST_CHECKF(status.iterations >= 1 && status.iterations <= 64 && !status.hitIterationCap,
				"iterations %d, cap %d", status.iterations, (int)status.hitIterationCap);

	/* Half-spaces need no iteration. */
	cd3Plane ground = {{0, 1, 0}, 0};
	cd3Shape plane = cd3MakePlaneShape(ground);
	status.iterations = -1;
	status.hitIterationCap = true;
	cd3ClosestPoints toPlane = cd3DistanceWithStatus(&plane, &b, &status);
	TEST_CHECK_NEAR(toPlane.distance, 0.0, 1e-6);
	TEST_CHECK(status.iterations == 0 && !status.hitIterationCap);

	/* A NULL status is allowed. */
	TEST_CHECK(cd3DistanceWithStatus(&a, &b, NULL).distance == plain.distance);
}

/* fuzz_query3 (double build): a point inside a box 2.3e-3 x 2.5e-3 x 6.5e5 was 6.1e-5 away by GJK
 * (the closest point on the box is the point itself). The values are the fuzzer's, to the bit in
 * double (rounded to float in the float build, where the case passes as well). */
static void TestPointInsideLongBox(void)
{
	cd3Box box = {
		{(cdReal)-0.00061249999999999998, (cdReal)-0.00061249999999999998, (cdReal)-0.00061249999999999998},
		{(cdReal)0.00115, (cdReal)0.001225, (cdReal)326941.53125},
		{(cdReal)0.51320932208477166, (cdReal)0.51320932208477166, (cdReal)0.0, (cdReal)0.68791887853916189}};
	cd3Vec p = {(cdReal)-0.00125, (cdReal)-0.00125, (cdReal)-0.00125};
	cd3Shape boxShape = cd3MakeBoxShape(box);
	cd3Shape point = cd3MakeSphereShape((cd3Sphere){p, CD_R(0.0)});
	TEST_CHECK(cd3PointInBox(p, box));
	double tolerance = 64.0 * (double)CD_REAL_EPSILON * 326941.53125;
	double forward = (double)cd3Distance(&boxShape, &point).distance;
	double backward = (double)cd3Distance(&point, &boxShape).distance;
	TEST_CHECKF(forward <= tolerance && backward <= tolerance, "distances %.9g, %.9g (tolerance %.3g)",
				forward, backward, tolerance);
}

/* fuzz_query3 (fuzz/corpus/fuzz_query3/regression-gjk-lean-needle-triangle): a point 1.75e-4 from
 * a box 1.6e-3 x 1 x 2.5e-3. GJK's lean solver took the face weights of a needle triangle (0.0025
 * by 1) from products of dot products whose round-off exceeded them, stepped away, and the next
 * support, a duplicate, stopped it at the previous segment's 5.95e-4. Checked against the closest
 * point on the box and the brute-force reference, in both orders. */
static void TestPointNearThinBox(void)
{
	cd3Box box = {{CD_R(0.000125000006), CD_R(-0.000274999999), CD_R(-0.00124999997)},
				  {CD_R(0.00079999998), CD_R(0.5), CD_R(0.00123749999)},
				  {CD_R(-0.5), CD_R(-0.5), CD_R(-0.5), CD_R(-0.5)}};
	cd3Vec p = {CD_R(-0.000449999992), CD_R(0.000699999975), CD_R(0.00121250004)};
	cd3Shape boxShape = cd3MakeBoxShape(box);
	cd3Shape point = cd3MakeSphereShape((cd3Sphere){p, CD_R(0.0)});
	double closest = (double)cd3Length(cd3Sub(cd3ClosestPointOnBox(box, p), p));
	double expected = RefDistance(&boxShape, &point);
	double forward = (double)cd3Distance(&boxShape, &point).distance;
	double backward = (double)cd3Distance(&point, &boxShape).distance;
	TEST_CHECKF(fabs(closest - expected) <= 1e-6, "closest point %.9g away, reference %.9g", closest,
				expected);
	TEST_CHECKF(fabs(forward - expected) <= 1e-6 && fabs(backward - expected) <= 1e-6,
				"distances %.9g, %.9g, reference %.9g", forward, backward, expected);
}

/* ---- needles: a Minkowski difference far longer than wide -------------------------------------
 * A long segment against a small box makes a difference whose faces are slivers: GJK's vertices
 * lie half the length from the closest point, which is within the sliver's width of them. Their
 * face weights must come from the short edges (the round-off of the vertices, epsilon times the
 * length), not from the origin's triangles with two long sides (epsilon times the length squared
 * over the width: 1.05 at length 1e9 and width 2-20 in double, 0.08 at 1e4 in float). */
#if CD_DOUBLE
#define NEEDLE_LENGTH 1.0e9
#else
#define NEEDLE_LENGTH 1.0e4
#endif
#define NEEDLE_TOLERANCE (16.0 * (double)CD_REAL_EPSILON * NEEDLE_LENGTH)

/* A segment NEEDLE_LENGTH long in the plane `gap` above a face of a box of size 2-20, passing
 * over a point of the face's inner part in a random direction of that plane: the exact distance
 * is the gap. */
static void TestNeedleDifferences(void)
{
	TestRng rng = TestRngMake(0x7ee41e16u);
	double worst = 0.0;
	for (int trial = 0; trial < 2000; ++trial)
	{
		double gap = TestRngInt(&rng, 2) ? 0.0 : TestRngRange(&rng, 0.5, 3.0);
		NeedleCase needle = MakeNeedleOverBox(&rng, NEEDLE_LENGTH, gap);
		cd3Shape a = cd3MakeSegmentShape(needle.segment), b = cd3MakeBoxShape(needle.box);
		double forward = (double)cd3Distance(&a, &b).distance,
			   backward = (double)cd3Distance(&b, &a).distance;
		double error = fmax(fabs(forward - gap), fabs(backward - gap));
		worst = fmax(worst, error);
		TEST_CHECKF(error <= NEEDLE_TOLERANCE, "gap %.9g: distances %.9g and %.9g (tolerance %.3g)", gap,
					forward, backward, NEEDLE_TOLERANCE);
		if (gap == 0.0)
		{
			TEST_CHECKF(cd3Overlap(&a, &b),
						"a segment on a face of the box does not overlap it (distance %.9g)", forward);
		}
		else
		{
			TEST_CHECKF(!cd3Overlap(&a, &b), "a segment %.9g above a face overlaps the box", gap);
		}
	}
	printf("  needle segment-box pairs: worst distance error %.3g (length %.0e, tolerance %.3g)\n", worst,
		   NEEDLE_LENGTH, NEEDLE_TOLERANCE);
}

/* A prism NEEDLE_LENGTH / 10 long over a square of side 2-20, as a hull, and points on its long
 * faces: each is on the hull (distance 0, its own closest point). */
static void TestPointsOnNeedleHull(void)
{
	TestRng rng = TestRngMake(0x7ee41e17u);
	double length = 0.1 * NEEDLE_LENGTH, worst = 0.0;
	for (int trial = 0; trial < 200; ++trial)
	{
		double side = TestRngRange(&rng, 2.0, 20.0);
		cd3Vec points[8];
		for (int i = 0; i < 8; ++i)
		{
			points[i] = cd3MakeVec((cdReal)((i & 1) ? side : 0.0), (cdReal)((i & 2) ? side : 0.0),
								   (cdReal)((i & 4) ? length : 0.0));
		}
		cd3Hull* hull = NULL;
		TEST_CHECK(cd3ComputeHull(points, 8, &hull) == CD_OK);
		if (hull == NULL)
		{
			return;
		}
		cd3Transform transform = {RandomVec(&rng, 10.0), RandomQuat(&rng)};
		cd3Shape shape = cd3MakeHullShape(hull, transform);
		for (int k = 0; k < 10; ++k)
		{
			/* A point of the face x = 0 or y = 0 (local), away from the ends. */
			double across = TestRngRange(&rng, 0.0, side), along = TestRngRange(&rng, 0.05, 0.95) * length;
			bool faceX = TestRngInt(&rng, 2) == 0;
			cd3Vec local =
				cd3MakeVec((cdReal)(faceX ? 0.0 : across), (cdReal)(faceX ? across : 0.0), (cdReal)along);
			cd3Vec p = cd3TransformPoint(transform, local);
			cd3Shape point = cd3MakeSphereShape((cd3Sphere){p, CD_R(0.0)});
			double distance = (double)cd3Distance(&shape, &point).distance;
			double moved = (double)cd3VecDistance(cd3ClosestPointOnShape(&shape, p), p);
			worst = fmax(worst, fmax(distance, moved));
			TEST_CHECKF(
				distance <= NEEDLE_TOLERANCE && moved <= NEEDLE_TOLERANCE,
				"a point on a needle hull's face is %.9g away, its closest point %.9g (tolerance %.3g)",
				distance, moved, NEEDLE_TOLERANCE);
		}
		cd3DestroyHull(hull);
	}
	printf("  points on needle hulls: worst distance %.3g (length %.0e, tolerance %.3g)\n", worst,
		   0.1 * NEEDLE_LENGTH, NEEDLE_TOLERANCE);
}

#if CD_DOUBLE
/* fuzz_query3, double build (corpus regression-query3-double-needle-hull-witness,
 * regression-query3-double-segment-box-triangle-overlap-distance): the fuzzer's values, to the
 * bit. A point of a needle hull's surface (7e9 long, 12.5 wide) was 7.7 away from it by GJK, and
 * a box flat to a segment 2e9 long crossing a triangle of size 13 was 1.26 away from it. */
static void TestNeedleFuzzCases(void)
{
	cd3Vec pointsA[12] = {{-11.625, 0, 0},
						  {0, 0, 0},
						  {0, -1, -1},
						  {1, 1, 1},
						  {-5, -1, 0},
						  {-11.25, -12.5, -12.5},
						  {-12.5, -12.5, -12.5},
						  {-12.5, -12.5, -1},
						  {-1.75, 1, 1},
						  {1, 1, 1},
						  {-1, -1, -6951902720.0},
						  {1.5120095175902293e-09, -12.5, -6973005312.0}};
	cd3Vec pointsB[4] = {{-2.625, 0.5, 1}, {-12, -1, -1}, {1, 1, 1}, {1, -4.625, 1}};
	cd3Hull *hullA = NULL, *hullB = NULL;
	TEST_CHECK(cd3ComputeHull(pointsA, 12, &hullA) == CD_OK);
	TEST_CHECK(cd3ComputeHull(pointsB, 4, &hullB) == CD_OK);
	if (hullA != NULL && hullB != NULL)
	{
		cd3Transform placeA = {
			{1.60174560546875, -12.5, -12.5},
			{-0.49362970296310121, -0.6170371287038765, -0.61086675741683771, 0.049362970296310121}};
		cd3Transform placeB = {
			{-1.0000000000000001e-30, -6960029184.0, -6950198784.0},
			{-0.54807436572704549, 0.070719272997038118, -0.58932727497531767, -0.58932727497531767}};
		cd3Shape a = cd3MakeHullShape(hullA, placeA), b = cd3MakeHullShape(hullB, placeB);
		cd3ClosestPoints r = cd3Distance(&a, &b);
		/* 1e-10 of the scale, as the fuzzer's band. */
		double tolerance = 1e-10 * 1.2e10;
		double offA = (double)cd3VecDistance(cd3ClosestPointOnShape(&a, r.pointA), r.pointA);
		double offB = (double)cd3VecDistance(cd3ClosestPointOnShape(&b, r.pointB), r.pointB);
		TEST_CHECKF(offA <= tolerance && offB <= tolerance, "witnesses off their hulls by %.3g and %.3g",
					offA, offB);
		cd3Shape point = cd3MakeSphereShape((cd3Sphere){r.pointA, 0.0});
		double onA = (double)cd3Distance(&a, &point).distance;
		TEST_CHECKF(onA <= tolerance, "pointA is %.9g from hull A by cd3Distance", onA);
	}
	cd3DestroyHull(hullA);
	cd3DestroyHull(hullB);

	/* The same needle with its far end 2.8e8 long (corpus
	 * regression-query3-double-needle-hull-sliver-face): the witness on it, a point of its surface,
	 * was 3.4 from it by GJK, on a face whose three vertices lie nearly in line along the needle
	 * (its normal from products that cancelled, and the point from weights that erred along it). */
	cd3Vec pointsD[12] = {{-11.625, 0, 0},
						  {0, 0, 0},
						  {0, -1, -1},
						  {1, 1, 1},
						  {-12.5, -12.5, -12.5},
						  {-5, -1, 0},
						  {-11.25, -12.5, -12.25},
						  {-12.5, -12.5, -12.5},
						  {1, 1, 1},
						  {-6.25, 1, 1},
						  {-1, -1, -7253892608.0},
						  {1.5120095175902293e-09, -12.5, -6973005312.0}};
	cd3Vec pointsE[4] = {{-2.625, 0.5, 1}, {-12, -1, 10}, {-1, 1, 1}, {1, 1, -4.625}};
	cd3Hull *hullD = NULL, *hullE = NULL;
	TEST_CHECK(cd3ComputeHull(pointsD, 12, &hullD) == CD_OK);
	TEST_CHECK(cd3ComputeHull(pointsE, 4, &hullE) == CD_OK);
	if (hullD != NULL && hullE != NULL)
	{
		cd3Transform placeD = {
			{1.60174560546875, -12.5, -12.5},
			{-0.49362970296310121, -0.6170371287038765, -0.61086675741683771, 0.049362970296310121}};
		cd3Transform placeE = {{-1.0000000000000001e-30, -6960029184.0, -6950198784.0},
							   {-0.67839851982059918, 0.087535292880077317, 0, -0.72946077400064435}};
		cd3Shape d = cd3MakeHullShape(hullD, placeD), e = cd3MakeHullShape(hullE, placeE);
		cd3ClosestPoints r = cd3Distance(&d, &e);
		cd3Shape point = cd3MakeSphereShape((cd3Sphere){r.pointA, 0.0});
		double onD = (double)cd3Distance(&d, &point).distance;
		double moved = (double)cd3VecDistance(cd3ClosestPointOnShape(&d, r.pointA), r.pointA);
		double tolerance = 1e-10 * 1.26e10;
		TEST_CHECKF(onD <= tolerance && moved <= tolerance,
					"pointA %.9g from the hull, its closest point %.9g away", onD, moved);
	}
	cd3DestroyHull(hullD);
	cd3DestroyHull(hullE);

	/* A hull 7e9 across whose face through a point runs between a vertex next to the point and
	 * two far ones (corpus regression-query3-double-huge-hull-point-stall): the point of its
	 * surface GJK returned for a point 6.16 away was itself 1.29 away from the hull by GJK, whose
	 * new far vertex brought a gain below round-off and was dropped again at each step. */
	cd3Vec pointsC[12] = {{-3.625, 0, 0},
						  {0, 0, 0},
						  {0, 0, 0},
						  {0, -1, -6974103552.0},
						  {-6.5, -6949306368.0, -6973005312.0},
						  {-4724858368.0, 3.25, -6960029184.0},
						  {-6950198784.0, -11.625, 1.5},
						  {-12.5, -12.5, -12.375},
						  {-2.625, 0.5, 1},
						  {-12, -1, -1},
						  {1, 1, 1},
						  {1, -4.625, 1}};
	cd3Hull* hullC = NULL;
	TEST_CHECK(cd3ComputeHull(pointsC, 12, &hullC) == CD_OK);
	if (hullC != NULL)
	{
		cd3Transform place = {
			{1.60174560546875, -12.5, -12.5},
			{-0.49362970296310121, -0.6170371287038765, -0.61086675741683771, 0.049362970296310121}};
		cd3Shape hull = cd3MakeHullShape(hullC, place);
		cd3Shape point = cd3MakeSphereShape((cd3Sphere){{-12.5, -12.5, -12.5}, 0.0});
		cd3ClosestPoints r = cd3Distance(&hull, &point);
		cd3Shape onHull = cd3MakeSphereShape((cd3Sphere){r.pointA, 0.0});
		double again = cd3Distance(&hull, &onHull).distance;
		double moved = (double)cd3VecDistance(cd3ClosestPointOnShape(&hull, r.pointA), r.pointA);
		double tolerance = 64.0 * (double)CD_REAL_EPSILON * 7e9;
		TEST_CHECKF(fabs(r.distance - 6.1606693809636) <= 1e-6, "distance %.17g", r.distance);
		TEST_CHECKF(
			again <= tolerance && moved <= tolerance,
			"the closest point is %.9g from the hull, its own closest point %.9g away (tolerance %.3g)",
			again, moved, tolerance);
		cd3DestroyHull(hullC);
	}

	cd3Box box = {{-0.5, -11.625, 0},
				  {0, 989911296, 0},
				  {0, 0.8295613557843402, -0.51847584736521268, 0.20739033894608505}};
	cd3Triangle triangle = {{0, 0.5, 1}, {0.5, -12, 3.25}, {0.5, -12.5, -12.5}};
	cd3Shape boxShape = cd3MakeBoxShape(box), triangleShape = cd3MakeTriangleShape(triangle);
	double expected = RefDistance(&boxShape, &triangleShape);
	double forward = cd3Distance(&boxShape, &triangleShape).distance;
	double backward = cd3Distance(&triangleShape, &boxShape).distance;
	TEST_CHECKF(cd3Overlap(&boxShape, &triangleShape), "no overlap (reference distance %.9g)", expected);
	TEST_CHECKF(fabs(forward - expected) <= 1e-6 && fabs(backward - expected) <= 1e-6,
				"distances %.9g and %.9g, reference %.9g", forward, backward, expected);
}
#endif

/* ---- simplex cache --------------------------------------------------------------------------- */
#if CD_DOUBLE
#define CACHE_AGREEMENT 1e-9
#else
#define CACHE_AGREEMENT 2e-4
#endif

static void FillRandomBytes(TestRng* rng, void* memory, size_t size)
{
	unsigned char* bytes = (unsigned char*)memory;
	for (size_t i = 0; i < size; ++i)
	{
		bytes[i] = (unsigned char)(TestRngNext(rng) >> 24);
	}
}

/* The same answer whatever the cache holds: nothing, random bytes, random but in-range indices,
 * another pair's simplex, this pair's own simplex. */
static void TestCacheAgrees(void)
{
	TestRng rng = TestRngMake(0x5ca4e003u);
	cd3SimplexCache other;
	memset(&other, 0, sizeof(other));
	int pairs = 0;
	for (int ta = 0; ta < CD3_SHAPE_TYPE_COUNT; ++ta)
	{
		for (int tb = 0; tb < CD3_SHAPE_TYPE_COUNT; ++tb)
		{
			bool plane = ta == CD3_SHAPE_PLANE || tb == CD3_SHAPE_PLANE;
			for (int i = 0; i < 25; ++i, ++pairs)
			{
				cd3Shape a = RandomShape(&rng, (cd3ShapeType)ta);
				cd3Shape b = RandomShape(&rng, (cd3ShapeType)tb);
				cd3ClosestPoints plain = cd3Distance(&a, &b);
				cd3SimplexCache caches[5];
				memset(&caches[0], 0, sizeof(caches[0]));
				FillRandomBytes(&rng, &caches[1], sizeof(caches[1]));
				caches[2].count = 1 + TestRngInt(&rng, 4);
				caches[2].metric = RandomReal(&rng, -1.0, 8.0);
				for (int k = 0; k < 4; ++k)
				{
					caches[2].indexA[k] = TestRngInt(&rng, 66) - 1;
					caches[2].indexB[k] = TestRngInt(&rng, 66) - 1;
				}
				caches[3] = other;
				memset(&caches[4], 0, sizeof(caches[4]));
				cd3DistanceCached(&a, &b, &caches[4], NULL);
				for (int c = 0; c < 5; ++c)
				{
					cdDistanceStatus status;
					cd3ClosestPoints cached = cd3DistanceCached(&a, &b, &caches[c], &status);
					double error = fabs((double)cached.distance - (double)plain.distance);
					double gap = (double)cd3Length(cd3Sub(cached.pointB, cached.pointA));
					bool countValid = plane || (caches[c].count >= 1 && caches[c].count <= 4);
					TEST_CHECKF(error <= CACHE_AGREEMENT &&
									fabs(gap - (double)cached.distance) <= CACHE_AGREEMENT &&
									!status.hitIterationCap && countValid,
								"%s-%s cache %d: cached %.9g, plain %.9g, points %.9g apart, count %d",
								TypeName((cd3ShapeType)ta), TypeName((cd3ShapeType)tb), c,
								(double)cached.distance, (double)plain.distance, gap, caches[c].count);
				}
				if (!plane)
				{
					other = caches[4];
				}
			}
		}
	}
	printf("%d pairs, 5 caches each\n", pairs);
}

/* A pair moving a little each frame: the cache of the last frame saves iterations. */
static void TestCacheSavesIterations(void)
{
	TestRng rng = TestRngMake(0x5ca4e004u);
	long long coldIterations = 0, warmIterations = 0;
	int queries = 0;
	const cd3ShapeType types[3] = {CD3_SHAPE_HULL, CD3_SHAPE_BOX, CD3_SHAPE_CAPSULE};
	for (int sequence = 0; sequence < 80; ++sequence)
	{
		cd3Shape a = RandomShape(&rng, types[TestRngInt(&rng, 3)]);
		cd3Shape b0 = RandomShape(&rng, types[TestRngInt(&rng, 3)]);
		cd3Vec velocity = RandomVec(&rng, 0.02);
		cd3Vec axis = RandomUnit(&rng);
		cdReal spin = RandomReal(&rng, -0.02, 0.02);
		cd3SimplexCache cache;
		memset(&cache, 0, sizeof(cache));
		for (int frame = 0; frame < 20; ++frame, ++queries)
		{
			cdReal half = CD_R(0.5) * spin * (cdReal)frame;
			cdReal sine = (cdReal)sin((double)half), cosine = (cdReal)cos((double)half);
			cd3Transform motion = {
				cd3Scale((cdReal)frame, velocity),
				cd3NormalizeQuat(cd3MakeQuat(sine * axis.x, sine * axis.y, sine * axis.z, cosine))};
			cd3Shape b = TransformShape(&b0, motion);
			cdDistanceStatus cold, warm;
			cd3ClosestPoints plain = cd3DistanceWithStatus(&a, &b, &cold);
			cd3ClosestPoints cached = cd3DistanceCached(&a, &b, &cache, &warm);
			coldIterations += cold.iterations;
			warmIterations += warm.iterations;
			TEST_CHECKF(fabs((double)cached.distance - (double)plain.distance) <= CACHE_AGREEMENT,
						"sequence %d frame %d: cached %.9g, plain %.9g", sequence, frame,
						(double)cached.distance, (double)plain.distance);
		}
	}
	double cold = (double)coldIterations / queries, warm = (double)warmIterations / queries;
	printf("mean iterations: %.2f without the cache, %.2f with it\n", cold, warm);
	TEST_CHECKF(warm < 0.75 * cold, "mean iterations %.2f with the cache, %.2f without", warm, cold);
}

/* cd3Distance on two spheres takes the closed form named by the pair table (src/query/pairs3.h)
 * instead of GJK; it must give GJK's answer bit for bit (cd3DistanceWithStatus runs GJK), in both
 * orders: random pairs, coincident and nearly coincident centres, zero radii, signed zeros and
 * large and small scales. */
static void TestClosedFormMatchesGjk(void)
{
	TestRng rng = TestRngMake(0xc105edu);
	int checked = 0;
	for (int i = 0; i < 6000; ++i)
	{
		cd3Shape a = RandomShape(&rng, CD3_SHAPE_SPHERE), b = RandomShape(&rng, CD3_SHAPE_SPHERE);
		switch (i % 6)
		{
			case 1:
				b.sphere.center = a.sphere.center;
				break;
			case 2:
				b.sphere.center = cd3Add(a.sphere.center, cd3MakeVec(RandomReal(&rng, -1e-6, 1e-6),
																	 RandomReal(&rng, -1e-6, 1e-6),
																	 RandomReal(&rng, -1e-6, 1e-6)));
				break;
			case 3:
				a.sphere.center = cd3MakeVec(-0.0f, 0.0f, -0.0f);
				b.sphere.center = cd3MakeVec(0.0f, -0.0f, 0.0f);
				a.sphere.radius = CD_R(0.0);
				b.sphere.radius = CD_R(0.0);
				break;
			case 4:
				a.sphere.center = cd3Scale(CD_R(1e6), a.sphere.center);
				b.sphere.center = cd3Scale(CD_R(1e6), b.sphere.center);
				break;
			case 5:
				a.sphere.center = cd3Scale(CD_R(1e-6), a.sphere.center);
				b.sphere.center = cd3Scale(CD_R(1e-6), b.sphere.center);
				a.sphere.radius *= CD_R(1e-6);
				b.sphere.radius *= CD_R(1e-6);
				break;
			default:
				break;
		}
		for (int order = 0; order < 2; ++order)
		{
			const cd3Shape* first = order == 0 ? &a : &b;
			const cd3Shape* second = order == 0 ? &b : &a;
			cdDistanceStatus status;
			cd3ClosestPoints closed = cd3Distance(first, second);
			cd3ClosestPoints gjk = cd3DistanceWithStatus(first, second, &status);
			TEST_CHECKF(memcmp(&closed, &gjk, sizeof(closed)) == 0,
						"pair %d, order %d: distance %.9g, GJK %.9g", i, order, (double)closed.distance,
						(double)gjk.distance);
			++checked;
		}
	}
	TEST_CHECK(checked == 12000);
}

int main(void)
{
	TEST_RUN(TestSpheres);
	TEST_RUN(TestBoxesAndAabbs);
	TEST_RUN(TestCapsulesSegmentsTriangles);
	TEST_RUN(TestPlanes);
	TEST_RUN(TestHalfSpaceWitnesses);
	TEST_RUN(TestScales);
	TEST_RUN(TestRandomPairs);
	TEST_RUN(TestHullVertexCounts);
	TEST_RUN(TestDistanceStatus);
	TEST_RUN(TestPointInsideLongBox);
	TEST_RUN(TestPointNearThinBox);
	TEST_RUN(TestNeedleDifferences);
	TEST_RUN(TestPointsOnNeedleHull);
#if CD_DOUBLE
	TEST_RUN(TestNeedleFuzzCases);
#endif
	TEST_RUN(TestCacheAgrees);
	TEST_RUN(TestCacheSavesIterations);
	TEST_RUN(TestClosedFormMatchesGjk);
	return TEST_SUMMARY();
}
