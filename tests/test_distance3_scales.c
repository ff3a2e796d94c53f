/* Tests of cd3Distance (GJK) at extreme and mixed scales, on thin boxes and long segments, and on
 * hulls at large scale, against the brute-force double reference of test_distance3_reference.h
 * (split from test_distance3.c to keep each program within the sanitizer build's time budget). */
#include "test_distance3_reference.h"

static void TestExtremeScales(void)
{
	TestRng rng = TestRngMake(0x6a6b3d06u);
#if CD_DOUBLE
	const double exponents = 30.0;
#else
	const double exponents = 9.0;
#endif
	for (int i = 0; i < 4000; ++i)
	{
		cd3Shape a = RandomShape(&rng, (cd3ShapeType)TestRngInt(&rng, CD3_SHAPE_TYPE_COUNT));
		cd3Shape b = RandomShape(&rng, (cd3ShapeType)TestRngInt(&rng, CD3_SHAPE_TYPE_COUNT));
		double k = pow(10.0, TestRngRange(&rng, -exponents, exponents));
		cd3Shape sa = ScaleShape(&a, (cdReal)k), sb = ScaleShape(&b, (cdReal)k);
		double expected = RefDistance(&sa, &sb) / k;
		double unit = RefDistance(&a, &b);
		cd3ClosestPoints r = cd3Distance(&sa, &sb);
		bool ok = isfinite((double)r.distance) && CheckFinitePoints(r) &&
				  fabs((double)r.distance / k - expected) <= 1e-3 * (1.0 + expected) &&
				  fabs(expected - unit) <= 1e-3 * (1.0 + unit);
		TEST_CHECKF(ok, "scale %g: distance / scale = %.9g, reference %.9g (unscaled %.9g)", k,
					(double)r.distance / k, expected, unit);
		if (!ok)
		{
			PrintShape("a", &sa);
			PrintShape("b", &sb);
		}

		double k2 = pow(10.0, TestRngRange(&rng, -exponents, exponents));
		cd3Shape mixed = ScaleShape(&b, (cdReal)k2);
		r = cd3Distance(&sa, &mixed);
		cd3ClosestPoints s = cd3Distance(&mixed, &sa);
		ok = isfinite((double)r.distance) && r.distance >= CD_R(0.0) && CheckFinitePoints(r) &&
			 isfinite((double)s.distance) && CheckFinitePoints(s);
		TEST_CHECKF(ok, "scales %g and %g: distance %g", k, k2, (double)r.distance);
		if (!ok)
		{
			PrintShape("a", &sa);
			PrintShape("b", &mixed);
		}

		/* Small shapes far out: finite, and no farther apart than their centres' round-off allows. */
		cd3Transform far = {
			cd3Scale((cdReal)pow(10.0, TestRngRange(&rng, 0.0, exponents)), RandomVec(&rng, 1.0)),
			CD3_QUAT_IDENTITY};
		cd3Shape fa = TransformShape(&sa, far), fb = TransformShape(&mixed, far);
		r = cd3Distance(&fa, &fb);
		ok = isfinite((double)r.distance) && r.distance >= CD_R(0.0) && CheckFinitePoints(r);
		TEST_CHECKF(ok, "scales %g and %g, offset %g: distance %g", k, k2, (double)far.p.x,
					(double)r.distance);
	}
}

/* GJK once dropped a support point whose gain was below the resolution of the squared distances
 * (a far vertex, or a face-normal direction on which a thin box's four far corners tie): the
 * simplex came back unchanged and the search stalled far from the answer. Exact cases from the
 * fuzzer (fuzz_query3), then random thin boxes against points just off their thin side and long
 * segments at the 1e9 scale, all against the brute-force double reference. */
static void TestThinBoxesAndLongSegments(void)
{
	/* The box is 2.4e-4 thick and 2 wide; the point is 9.88e-5 off its thin side (GJK said 3.4e-4,
	 * the distance to the far side). */
	cd3Quat tilted = cd3NormalizeQuat(
		cd3MakeQuat(CD_R(-1.0), CD_R(-0.0001175), CD_R(-0.000115000003), CD_R(-0.000125000006)));
	cd3Shape thin = Box(V(-0.000103749997, -0.0001175, -1.0), V(0.000121249999, 1.0, 1.0), tilted);
	cd3Shape point = Sphere(CD_R(-0.00011375), CD_R(7.37500013e-05), CD_R(0.0), CD_R(0.0));
	double expected = RefDistance(&thin, &point);
	TEST_CHECKF(expected > 9.8e-5 && expected < 9.95e-5, "reference %.9g", expected);
	CheckAgainstReference(&thin, &point, 64.0 * (double)CD_REAL_EPSILON, "fuzzer's thin box and point");

	/* Two segments, one reaching 1e9 away: the closest points are the near end of the long one
	 * and a point of the short one, 147765 apart (GJK said 248470). The documented accuracy is
	 * 16 epsilon of the coordinates. */
	cd3Shape longSegment = Segment(V(-107500.0, 1e9, 1e9), V(-112500.0, -125000.0, 22500.0));
	cd3Shape shortSegment = Segment(V(22500.0, 22500.0, -125000.0), V(-125000.0, -125000.0, -125000.0));
	expected = RefDistance(&longSegment, &shortSegment);
	TEST_CHECKF(expected > 147000.0 && expected < 148500.0, "reference %.9g", expected);
	CheckAgainstReference(&longSegment, &shortSegment, 16.0 * (double)CD_REAL_EPSILON * 1e9,
						  "fuzzer's long segments");

	TestRng rng = TestRngMake(0x6a6b3d07u);
	for (int i = 0; i < 2000; ++i)
	{
		/* A box 1e-4..1e-3 thick and about 1 wide, turned at random, and a point or small sphere
		 * up to 1e-3 beyond one of its thin sides, anywhere across it. */
		double thickness = pow(10.0, TestRngRange(&rng, -4.0, -3.0));
		/* Turned at random, or (half the time) by a quarter or half turn tilted by up to 1e-3:
		 * the search direction is then close to the axes, where corners tie. */
		cd3Quat q = RandomQuat(&rng);
		if (TestRngInt(&rng, 2) == 0)
		{
			static const cdReal turns[6][4] = {{1, 0, 0, 0},
											   {0, 1, 0, 0},
											   {0, 0, 1, 0},
											   {0, 0, 0, 1},
											   {CD_R(0.70710678), 0, 0, CD_R(0.70710678)},
											   {0, CD_R(0.70710678), 0, CD_R(0.70710678)}};
			const cdReal* turn = turns[TestRngInt(&rng, 6)];
			q = cd3NormalizeQuat(cd3MakeQuat(
				turn[0] + RandomReal(&rng, -1e-3, 1e-3), turn[1] + RandomReal(&rng, -1e-3, 1e-3),
				turn[2] + RandomReal(&rng, -1e-3, 1e-3), turn[3] + RandomReal(&rng, -1e-3, 1e-3)));
		}
		cd3Vec half = cd3MakeVec((cdReal)thickness, RandomReal(&rng, 0.5, 1.5), RandomReal(&rng, 0.5, 1.5));
		cd3Shape box = Box(RandomVec(&rng, 1.0), half, q);
		double side = TestRngInt(&rng, 2) == 0 ? -1.0 : 1.0;
		/* Across the side, and half the time level with one of its edges (where the search
		 * approached from the far side and stalled). */
		double across = TestRngInt(&rng, 2) == 0 ? TestRngRange(&rng, -1.0, 1.0)
												 : (TestRngInt(&rng, 2) == 0 ? -1.0 : 1.0);
		cd3Vec local = cd3MakeVec((cdReal)(side * (thickness + TestRngRange(&rng, 0.0, 1e-3))),
								  (cdReal)(across * (double)half.y),
								  (cdReal)(TestRngRange(&rng, -1.2, 1.2) * (double)half.z));
		cd3Vec p = cd3Add(box.box.center, cd3RotateVector(q, local));
		cdReal radius = TestRngInt(&rng, 2) == 0 ? CD_R(0.0) : (cdReal)TestRngRange(&rng, 0.0, 1e-4);
		cd3Shape ball = Sphere(p.x, p.y, p.z, radius);
		CheckAgainstReference(&box, &ball, 64.0 * (double)CD_REAL_EPSILON * 4.0, "thin box and ball");

		/* A segment from near the origin to about 1e9 away (on the axes or diagonals, as the
		 * fuzzer's lattice puts it), against one nearby, all on a lattice of step 2500. The
		 * documented accuracy: 16 epsilon of the largest coordinate. */
		cdReal lattice[9];
		for (int k = 0; k < 9; ++k)
		{
			lattice[k] = (cdReal)(2500 * (TestRngInt(&rng, 101) - 50));
		}
		cdReal far[3];
		for (int k = 0; k < 3; ++k)
		{
			int choice = TestRngInt(&rng, 3);
			far[k] = choice == 0 ? CD_R(0.0) : (choice == 1 ? CD_R(1e9) : CD_R(-1e9));
		}
		far[0] = far[0] == CD_R(0.0) && far[1] == CD_R(0.0) && far[2] == CD_R(0.0) ? CD_R(1e9) : far[0];
		cd3Shape reaching = Segment(cd3MakeVec(far[0] + lattice[0], far[1] + lattice[1], far[2]),
									cd3MakeVec(lattice[2], lattice[3], lattice[4]));
		cd3Shape nearby = Segment(cd3MakeVec(lattice[5], lattice[6], lattice[7]),
								  cd3MakeVec(lattice[8], lattice[0], lattice[3]));
		CheckAgainstReference(&reaching, &nearby, 16.0 * (double)CD_REAL_EPSILON * 1.0002e9, "long segments");
	}
}

/* Hulls at the 1e9 scale (fuzz_query3): a tetrahedron of support points, thin for its size, gave
 * barycentric weights that did enclose the origin but rebuilt a point 1e-3 of the size away from
 * it, so a segment touching a hull got a "common" point 1e6 off the hull; and a point on a long
 * edge of a hull came out 329000 away when such weights were refused instead of refined. */
static cd3Hull* HullOf(const float* coordinates, int count)
{
	cd3Vec points[16];
	for (int i = 0; i < count; ++i)
	{
		points[i] = cd3MakeVec((cdReal)coordinates[3 * i], (cdReal)coordinates[3 * i + 1],
							   (cdReal)coordinates[3 * i + 2]);
	}
	cd3Hull* hull = NULL;
	TEST_CHECK(cd3ComputeHull(points, count, &hull) == CD_OK && hull != NULL);
	return hull;
}

static void TestHullsAtLargeScale(void)
{
	static const float cloud[] = {-11625000, -11625000, -11625000, -11625000, -11625000, -11625000, -11625000,
								  -12500000, -12500000, -12500000, -1625000,  0,		 1000000,	500000,
								  2250000,	 0,			0,		   2500000,	  1000000,	 500000,	750000,
								  500000,	 -3000000,	250000,	   250000,	  6000000,	 0,			1e+09,
								  -12500000, -12500000, -12500000, -12500000, -12500000};
	cd3Hull* hull = HullOf(cloud, 11);
	if (hull != NULL)
	{
		cd3Shape shape;
		memset(&shape, 0, sizeof shape);
		shape.type = CD3_SHAPE_HULL;
		shape.hull.hull = hull;
		shape.hull.transform.p = V(-11625000.0, -11625000.0, -11625000.0);
		shape.hull.transform.q =
			cd3NormalizeQuat(cd3MakeQuat(CD_R(-0.5), CD_R(-0.5), CD_R(-0.5), CD_R(-0.5)));
		cd3Shape segment = Segment(V(-1e9, -1e9, -1e9), V(-11625000.0, -11875000.0, -11625000.0));
		CheckAgainstReference(&segment, &shape, 16.0 * (double)CD_REAL_EPSILON * 2e9,
							  "segment and hull at 1e9");
		cd3ClosestPoints r = cd3Distance(&segment, &shape);
		g_printedCase = false;
		CheckResult(&segment, &shape, r);
		cd3DestroyHull(hull);
	}

	/* (-1.25e7, -1.25e7, -1.25e7) lies on the segment between the input points (-1e9, -1e9, -1e9)
	 * and (5e5, 5e5, 5e5): distance 0, within the documented tolerance. */
	static const float sliver[] = {
		-1e+09, -1e+09,	   -1e+09,	  500000,	 2250000,	0,		   0,		  500000,	 1000000,
		500000, 500000,	   500000,	  -3000000,	 250000,	-3375000,  250000,	  6000000,	 0,
		0,		-12500000, -12500000, -12500000, -12500000, -12500000, -12500000, -12500000, -12500000};
	hull = HullOf(sliver, 9);
	if (hull != NULL)
	{
		cd3Shape shape;
		memset(&shape, 0, sizeof shape);
		shape.type = CD3_SHAPE_HULL;
		shape.hull.hull = hull;
		shape.hull.transform.q = CD3_QUAT_IDENTITY;
		cd3Shape point = Sphere(CD_R(-12500000.0), CD_R(-12500000.0), CD_R(-12500000.0), CD_R(0.0));
		cd3ClosestPoints r = cd3Distance(&shape, &point);
		TEST_CHECKF((double)r.distance <= 16.0 * (double)CD_REAL_EPSILON * 1e9,
					"point on a hull edge: distance %.9g", (double)r.distance);
		cd3DestroyHull(hull);
	}

	/* A needle-shaped hull (one vertex 1e9 out, the others within 1.25e6): the point
	 * (-1.25e6, -1.25e6, -1.25e6) lies 187000 inside it (its faces, in double), but the
	 * tetrahedron of support points, measured from the far vertex, passed for flat, and GJK
	 * reported the distance to one face. */
	static const float needle[] = {
		-1187500, 812500,	-9.99999972e-10f, -1250000, -1250000, -1250000, -512500,  -1250000, -1250000,
		-937500,  600000,	675000,			  -525000,	0,		  0,		-1e+09,	  0,		0,
		0,		  -1250000, -1250000,		  -1250000, -1250000, -1250000, -1250000, -1250000, -1250000};
	hull = HullOf(needle, 9);
	if (hull != NULL)
	{
		cd3Shape shape;
		memset(&shape, 0, sizeof shape);
		shape.type = CD3_SHAPE_HULL;
		shape.hull.hull = hull;
		shape.hull.transform.p = V(-937500.0, 0.0, -1175000.0);
		shape.hull.transform.q = cd3NormalizeQuat(
			cd3MakeQuat(CD_R(-0.501248419), CD_R(-0.501248419), CD_R(-0.496235907), CD_R(-0.501248419)));
		cd3Shape point = Sphere(CD_R(-1250000.0), CD_R(-1250000.0), CD_R(-1250000.0), CD_R(0.0));
		cd3ClosestPoints r = cd3Distance(&shape, &point);
		TEST_CHECKF(r.distance == CD_R(0.0) && RefDistance(&shape, &point) == 0.0,
					"point inside a needle hull: distance %.9g, reference %.9g", (double)r.distance,
					RefDistance(&shape, &point));
		cd3DestroyHull(hull);
	}
}

/* cd3DistanceWithStatus reports GJK's work and gives the same answer as cd3Distance. */
int main(void)
{
	TEST_RUN(TestExtremeScales);
	TEST_RUN(TestThinBoxesAndLongSegments);
	TEST_RUN(TestHullsAtLargeScale);
	return TEST_SUMMARY();
}
