/* Tests of cd3ShapeCast and cd3TimeOfImpact: exact cases (analytic fractions and times, the
 * half-space, rays as point casts, contact at the start), a thin fast bullet, a long thin box
 * turning fast past a small box, a box hull that must behave as the box, and property tests on
 * random pairs against the double-precision distance bracket of reference3.h sampled in time. */
#include "collide/cast.h"
#include "needle_cases3.h"
#include "reference3.h"
#include "test.h"

#include <string.h>

#define SLOP 0.005

/* The local shape placed by the sweep at t (AABBs become boxes when turned). */
static cd3Shape PlacedAt(const cd3Shape* local, const cd3Sweep* sweep, double t)
{
	cd3Transform xf = cd3GetSweepTransform(sweep, (cdReal)t);
	if (local->type == CD3_SHAPE_AABB)
	{
		cd3Box box = {cd3TransformPoint(xf, cd3AabbCenter(local->aabb)), cd3AabbHalfExtents(local->aabb),
					  xf.q};
		return cd3MakeBoxShape(box);
	}
	return TransformShape(local, xf);
}

/* Reference distance at time t: the upper end of the bracket, a distance realized by two points of
 * the shapes, so a value below a threshold proves penetration (checks on it never fail wrongly). */
static double RefDistanceAt(const cd3Shape* a, const cd3Sweep* sa, const cd3Shape* b, const cd3Sweep* sb,
							double t)
{
	cd3Shape pa = PlacedAt(a, sa, t), pb = PlacedAt(b, sb, t);
	RShape ra = RFromShape(&pa), rb = RFromShape(&pb);
	return RComputeDistance(&ra, &rb).upper;
}

static double RefMinimumBefore(const cd3Shape* a, const cd3Sweep* sa, const cd3Shape* b, const cd3Sweep* sb,
							   double end, int samples)
{
	double smallest = INFINITY;
	for (int i = 0; i < samples; ++i)
	{
		smallest = fmin(smallest, RefDistanceAt(a, sa, b, sb, end * i / samples));
	}
	return smallest;
}

static cd3Sweep StillSweep(void)
{
	cd3Sweep s;
	memset(&s, 0, sizeof(s));
	s.rotation0 = s.rotation1 = CD3_QUAT_IDENTITY;
	return s;
}

static cd3Sweep LinearSweep(cd3Vec from, cd3Vec to)
{
	cd3Sweep s = StillSweep();
	s.center0 = from;
	s.center1 = to;
	return s;
}

static cd3Shape Sphere(cdReal x, cdReal y, cdReal z, cdReal r)
{
	cd3Sphere s = {{x, y, z}, r};
	return cd3MakeSphereShape(s);
}

static cd3Shape UnitBox(void)
{
	cd3Box b = {CD3_VEC_ZERO, {CD_R(1.0), CD_R(1.0), CD_R(1.0)}, CD3_QUAT_IDENTITY};
	return cd3MakeBoxShape(b);
}

static void TestCastSphereAtBoxAndPlane(void)
{
	cd3Shape sphere = Sphere(CD_R(-5.0), CD_R(0.0), CD_R(0.0), CD_R(0.5));
	cd3Shape box = UnitBox();
	cd3CastOutput out = cd3ShapeCast(&sphere, &box, cd3MakeVec(CD_R(10.0), CD_R(0.0), CD_R(0.0)));
	TEST_CHECK(out.hit && !out.hitIterationCap);
	TEST_CHECK_NEAR(out.fraction, 0.35, 1e-5);
	TEST_CHECK(out.fraction <= CD_R(0.35));
	TEST_CHECK_NEAR(out.normal.x, -1.0, 1e-5);
	TEST_CHECK_NEAR(out.point.x, -1.0, 1e-5);
	TEST_CHECK(!cd3ShapeCast(&sphere, &box, cd3MakeVec(CD_R(0.0), CD_R(10.0), CD_R(0.0))).hit);

	cd3Plane ground = {{CD_R(0.0), CD_R(1.0), CD_R(0.0)}, CD_R(0.0)};
	cd3Shape plane = cd3MakePlaneShape(ground);
	cd3Shape high = Sphere(CD_R(3.0), CD_R(5.0), CD_R(1.0), CD_R(0.5));
	cd3CastOutput fall = cd3ShapeCast(&high, &plane, cd3MakeVec(CD_R(1.0), CD_R(-10.0), CD_R(0.0)));
	TEST_CHECK(fall.hit);
	TEST_CHECK_NEAR(fall.fraction, 0.45, 1e-5);
	TEST_CHECK_NEAR(fall.normal.y, 1.0, 1e-5);
	TEST_CHECK_NEAR(fall.point.y, 0.0, 1e-5);
	/* The half-space moving up to the sphere: its normal seen from B is -y. */
	cd3CastOutput rise = cd3ShapeCast(&plane, &high, cd3MakeVec(CD_R(0.0), CD_R(10.0), CD_R(0.0)));
	TEST_CHECK(rise.hit);
	TEST_CHECK_NEAR(rise.fraction, 0.45, 1e-5);
	TEST_CHECK_NEAR(rise.normal.y, -1.0, 1e-5);

	/* Touching and overlapping at the start: fraction 0, normal -normalize(translation). */
	cd3Shape touching = Sphere(CD_R(-1.5), CD_R(0.0), CD_R(0.0), CD_R(0.5));
	cd3Shape inside = Sphere(CD_R(0.2), CD_R(0.0), CD_R(0.0), CD_R(0.5));
	cd3Vec translation = cd3MakeVec(CD_R(0.0), CD_R(3.0), CD_R(4.0));
	for (int k = 0; k < 2; ++k)
	{
		cd3CastOutput start = cd3ShapeCast(k ? &inside : &touching, &box, translation);
		TEST_CHECK(start.hit && start.fraction == CD_R(0.0) && start.iterations >= 1 &&
				   start.iterations < CD_CAST_MAX_ITERATIONS);
		TEST_CHECK_NEAR(start.normal.y, -0.6, 1e-6);
		TEST_CHECK_NEAR(start.normal.z, -0.8, 1e-6);
	}
}

static void TestCastPointAgreesWithRaycast(void)
{
	TestRng rng = TestRngMake(0xCA53u);
	const cd3ShapeType types[4] = {CD3_SHAPE_SPHERE, CD3_SHAPE_CAPSULE, CD3_SHAPE_AABB, CD3_SHAPE_BOX};
	int hits = 0, misses = 0;
	for (int i = 0; i < 3000; ++i)
	{
		cd3Shape b = RandomShape(&rng, types[TestRngInt(&rng, 4)], 1.0);
		cd3Vec origin = RandomVec(&rng, -6.0, 6.0);
		cd3Vec aim = RandomVec(&rng, -2.0, 2.0);
		cd3Ray ray = {origin, cd3Scale((cdReal)TestRngRange(&rng, 0.5, 2.0), cd3Sub(aim, origin))};
		cd3Shape point = Sphere(origin.x, origin.y, origin.z, CD_R(0.0));
		cd3Segment path = {origin, cd3Add(origin, ray.translation)};
		cd3Shape pathShape = cd3MakeSegmentShape(path);
		RShape rb = RFromShape(&b), rpath = RFromShape(&pathShape), rpoint = RFromShape(&point);
		double pathDistance = RComputeDistance(&rpath, &rb).upper;
		double startDistance = RComputeDistance(&rpoint, &rb).upper;
		cd3RayHit rayHit;
		bool rayHits = cd3Raycast(&b, ray, &rayHit);
		cd3CastOutput out = cd3ShapeCast(&point, &b, ray.translation);
		if (startDistance < 1e-3 || (pathDistance < 1e-3 && !rayHits))
		{
			continue;
		}
		double length = (double)cd3Length(ray.translation);
		double approach = -(double)cd3Dot(rayHit.normal, ray.translation);
		if (rayHits && approach > 0.05 * length)
		{
			++hits;
			TEST_CHECKF(out.hit && fabs((double)out.fraction - (double)rayHit.fraction) <=
									   1e-4 * length / approach + 1e-5,
						"case %d %s: cast %d %.9g ray %.9g", i, cd3GetShapeTypeName(b.type), out.hit,
						(double)out.fraction, (double)rayHit.fraction);
			TEST_CHECKF(cd3Dot(out.normal, ray.translation) < CD_R(0.0), "case %d normal", i);
		}
		else if (!rayHits)
		{
			++misses;
			TEST_CHECKF(!out.hit, "case %d: the ray misses by %.3g, the cast hits at %.9g", i, pathDistance,
						(double)out.fraction);
		}
	}
	TEST_CHECKF(hits > 250 && misses > 300, "%d hits, %d misses", hits, misses);
}

static void TestToiExactAndBullet(void)
{
	cd3Shape sphere = Sphere(CD_R(0.0), CD_R(0.0), CD_R(0.0), CD_R(0.5));
	cd3Shape box = UnitBox();
	cd3Sweep sa = LinearSweep(cd3MakeVec(CD_R(-5.0), CD_R(0.0), CD_R(0.0)),
							  cd3MakeVec(CD_R(5.0), CD_R(0.0), CD_R(0.0)));
	cd3Sweep sb = StillSweep();
	cdReal target = CD_R(0.01), tolerance = CD_R(0.0025);
	cdToiOutput out = cd3TimeOfImpact(&sphere, &sa, &box, &sb, target, tolerance);
	TEST_CHECK(out.state == CD_TOI_HIT);
	TEST_CHECKF(out.t >= CD_R(0.34875) - CD_R(1e-6) && out.t <= CD_R(0.349) + CD_R(1e-6), "t = %.9g",
				(double)out.t);
	cd3Sweep inside = LinearSweep(cd3MakeVec(CD_R(-1.2), CD_R(0.0), CD_R(0.0)), CD3_VEC_ZERO);
	TEST_CHECK(cd3TimeOfImpact(&sphere, &inside, &box, &sb, target, tolerance).state == CD_TOI_OVERLAPPED);
	cd3Sweep away = LinearSweep(cd3MakeVec(CD_R(-5.0), CD_R(0.0), CD_R(0.0)),
								cd3MakeVec(CD_R(-9.0), CD_R(0.0), CD_R(0.0)));
	cdToiOutput separated = cd3TimeOfImpact(&sphere, &away, &box, &sb, target, tolerance);
	TEST_CHECK(separated.state == CD_TOI_SEPARATED && separated.t == CD_R(1.0));

	/* A 0.01 bullet through a 0.05 wall at 100 m per step. */
	cd3Shape bullet = Sphere(CD_R(0.0), CD_R(0.0), CD_R(0.0), CD_R(0.01));
	cd3Box wallBox = {CD3_VEC_ZERO, {CD_R(0.025), CD_R(2.0), CD_R(2.0)}, CD3_QUAT_IDENTITY};
	cd3Shape wall = cd3MakeBoxShape(wallBox);
	cd3Sweep fast = LinearSweep(cd3MakeVec(CD_R(-50.0), CD_R(0.3), CD_R(-0.2)),
								cd3MakeVec(CD_R(50.0), CD_R(0.3), CD_R(-0.2)));
	cdToiOutput hit = cd3TimeOfImpact(&bullet, &fast, &wall, &sb, (cdReal)SLOP, (cdReal)(0.25 * SLOP));
	TEST_CHECK(hit.state == CD_TOI_HIT);
	double distance = RefDistanceAt(&bullet, &fast, &wall, &sb, (double)hit.t);
	TEST_CHECKF(distance >= SLOP - 1e-4 && distance <= 1.25 * SLOP + 1e-4, "distance %.9g", distance);

	/* A half-space moving (not turning) up to a resting sphere; a turning one fails. */
	cd3Plane ground = {{CD_R(0.0), CD_R(1.0), CD_R(0.0)}, CD_R(0.0)};
	cd3Shape plane = cd3MakePlaneShape(ground);
	cd3Shape high = Sphere(CD_R(0.0), CD_R(5.0), CD_R(0.0), CD_R(0.5));
	cd3Sweep lift = LinearSweep(CD3_VEC_ZERO, cd3MakeVec(CD_R(0.0), CD_R(10.0), CD_R(0.0)));
	cdToiOutput lifted = cd3TimeOfImpact(&plane, &lift, &high, &sb, target, tolerance);
	TEST_CHECK(lifted.state == CD_TOI_HIT);
	TEST_CHECKF(lifted.t >= CD_R(0.44875) - CD_R(1e-6) && lifted.t <= CD_R(0.449) + CD_R(1e-6), "t = %.9g",
				(double)lifted.t);
	lift.rotation1 = cd3MakeQuatAxisAngle(cd3MakeVec(CD_R(1.0), CD_R(0.0), CD_R(0.0)), CD_R(0.1));
	TEST_CHECK(cd3TimeOfImpact(&plane, &lift, &high, &sb, target, tolerance).state == CD_TOI_FAILED);
}

static void TestToiTurningLongBox(void)
{
	cd3Box stickBox = {CD3_VEC_ZERO, {CD_R(5.0), CD_R(0.05), CD_R(0.05)}, CD3_QUAT_IDENTITY};
	cd3Shape stick = cd3MakeBoxShape(stickBox);
	cd3Box smallBox = {{CD_R(3.0), CD_R(2.0), CD_R(0.1)},
					   {CD_R(0.2), CD_R(0.2), CD_R(0.2)},
					   cd3MakeQuatAxisAngle(cd3MakeVec(CD_R(1.0), CD_R(1.0), CD_R(0.0)), CD_R(0.4))};
	cd3Shape small = cd3MakeBoxShape(smallBox);
	const double angles[3] = {1.5, 2.5, 3.1};
	for (int k = 0; k < 3; ++k)
	{
		cd3Sweep sa = StillSweep(), sb = StillSweep();
		cd3Vec axis = cd3MakeVec(CD_R(0.05), CD_R(0.0), CD_R(1.0));
		sa.rotation0 = cd3MakeQuatAxisAngle(axis, CD_R(-1.0));
		sa.rotation1 = cd3MakeQuatAxisAngle(axis, (cdReal)(angles[k] - 1.0));
		cdToiOutput out = cd3TimeOfImpact(&stick, &sa, &small, &sb, (cdReal)SLOP, (cdReal)(0.25 * SLOP));
		TEST_CHECKF(out.state == CD_TOI_HIT, "angle %g: state %d after %d iterations", angles[k],
					(int)out.state, out.iterations);
		double distance = RefDistanceAt(&stick, &sa, &small, &sb, (double)out.t);
		TEST_CHECKF(distance >= SLOP - 1e-4 && distance <= 1.25 * SLOP + 1e-4, "angle %g: distance %.9g",
					angles[k], distance);
		double before = RefMinimumBefore(&stick, &sa, &small, &sb, (double)out.t, 4000);
		TEST_CHECKF(before >= SLOP - 1e-4, "angle %g: %.9g before t", angles[k], before);
		cdToiOutput swapped = cd3TimeOfImpact(&small, &sb, &stick, &sa, (cdReal)SLOP, (cdReal)(0.25 * SLOP));
		TEST_CHECK(swapped.state == CD_TOI_HIT);
		TEST_CHECK_NEAR(swapped.t, out.t, 1e-4);
	}
}

static cd3Sweep RandomSweep(TestRng* rng, bool rotate)
{
	cd3Sweep s = StillSweep();
	s.localCenter = RandomVec(rng, -0.5, 0.5);
	s.center0 = RandomVec(rng, -1.2, 1.2);
	s.center1 = RandomVec(rng, -1.2, 1.2);
	if (rotate)
	{
		s.rotation0 = RandomQuat(rng);
		s.rotation1 = RandomQuat(rng);
	}
	return s;
}

static void TestToiRandomPairs(void)
{
	TestRng rng = TestRngMake(0x7013u);
	const cd3ShapeType types[6] = {CD3_SHAPE_SPHERE, CD3_SHAPE_CAPSULE,	 CD3_SHAPE_AABB,
								   CD3_SHAPE_BOX,	 CD3_SHAPE_TRIANGLE, CD3_SHAPE_SEGMENT};
	int counts[4] = {0, 0, 0, 0};
	for (int i = 0; i < 800; ++i)
	{
		cd3Shape a = RandomShape(&rng, types[TestRngInt(&rng, 6)], 0.5);
		cd3Shape b = RandomShape(&rng, types[TestRngInt(&rng, 6)], 0.5);
		cd3Sweep sa = RandomSweep(&rng, true), sb = RandomSweep(&rng, TestRngInt(&rng, 2) == 0);
		cdToiOutput out = cd3TimeOfImpact(&a, &sa, &b, &sb, (cdReal)SLOP, (cdReal)(0.25 * SLOP));
		counts[out.state]++;
		TEST_CHECKF(out.t >= CD_R(0.0) && out.t <= CD_R(1.0), "case %d", i);
		double start = RefDistanceAt(&a, &sa, &b, &sb, 0.0);
		if (start < 1.25 * SLOP + 1e-4)
		{
			TEST_CHECKF(start < 1e-4 || out.state == CD_TOI_HIT || start > 1.25 * SLOP - 1e-4,
						"case %d: start %.9g state %d", i, start, (int)out.state);
			TEST_CHECKF(start > 1e-4 || out.state == CD_TOI_OVERLAPPED || out.state == CD_TOI_HIT, "case %d",
						i);
			continue;
		}
		double end = out.state == CD_TOI_SEPARATED ? 1.0 : (double)out.t;
		double before = RefMinimumBefore(&a, &sa, &b, &sb, end, 48);
		TEST_CHECKF(before >= SLOP - 1e-4, "case %d: distance %.9g before t = %.9g (state %d)", i, before,
					end, (int)out.state);
		if (out.state == CD_TOI_HIT)
		{
			double distance = RefDistanceAt(&a, &sa, &b, &sb, (double)out.t);
			cd3Shape pa = PlacedAt(&a, &sa, (double)out.t), pb = PlacedAt(&b, &sb, (double)out.t);
			RShape ra = RFromShape(&pa), rb = RFromShape(&pb);
			RDistance bracket = RComputeDistance(&ra, &rb);
			/* The bracket may be wide where alternating projections converge slowly (near-parallel
			 * faces): fail only when it excludes the band. */
			TEST_CHECKF(bracket.upper >= SLOP - 1e-4 && bracket.lower <= 1.25 * SLOP + 1e-4,
						"case %d: distance %.9g (bracket %.9g %.9g, cd3Distance %.9g) %s %s", i, distance,
						bracket.lower, bracket.upper, (double)cd3Distance(&pa, &pb).distance,
						cd3GetShapeTypeName(a.type), cd3GetShapeTypeName(b.type));
		}
		cdToiOutput swapped = cd3TimeOfImpact(&b, &sb, &a, &sa, (cdReal)SLOP, (cdReal)(0.25 * SLOP));
		if (!(swapped.state == out.state && fabs((double)swapped.t - (double)out.t) <= 1e-4))
		{
			double distance = RefDistanceAt(&a, &sa, &b, &sb, (double)swapped.t);
			TEST_CHECKF(swapped.state == CD_TOI_FAILED || out.state == CD_TOI_FAILED ||
							(distance <= 1.25 * SLOP + 1e-4 && swapped.state == CD_TOI_HIT),
						"case %d: swapped state %d t %.9g vs %d t %.9g", i, (int)swapped.state,
						(double)swapped.t, (int)out.state, (double)out.t);
		}
	}
	printf("random 3D TOI: %d hit, %d separated, %d overlapped, %d failed\n", counts[0], counts[1], counts[2],
		   counts[3]);
	TEST_CHECK(counts[CD_TOI_HIT] > 100 && counts[CD_TOI_SEPARATED] > 100);
	TEST_CHECK(counts[CD_TOI_FAILED] <= 16);
}

/* A box hull and the box it was built from give the same casts and times of impact. */
static void TestHullActsAsBox(void)
{
	cd3Hull* hull = NULL;
	cd3Vec half = {CD_R(0.8), CD_R(0.3), CD_R(0.5)};
	TEST_CHECK(cd3MakeBoxHull(half, &hull) == CD_OK);
	if (hull == NULL)
	{
		return;
	}
	TestRng rng = TestRngMake(0x4011u);
	for (int i = 0; i < 300; ++i)
	{
		cd3Shape other = RandomShape(&rng, TestRngInt(&rng, 2) ? CD3_SHAPE_CAPSULE : CD3_SHAPE_BOX, 0.5);
		cd3Box box = {CD3_VEC_ZERO, half, CD3_QUAT_IDENTITY};
		cd3Shape boxShape = cd3MakeBoxShape(box);
		cd3Shape hullShape = cd3MakeHullShape(hull, CD3_TRANSFORM_IDENTITY);
		cd3Sweep sa = RandomSweep(&rng, true), sb = RandomSweep(&rng, true);
		cdToiOutput viaBox =
			cd3TimeOfImpact(&boxShape, &sa, &other, &sb, (cdReal)SLOP, (cdReal)(0.25 * SLOP));
		cdToiOutput viaHull =
			cd3TimeOfImpact(&hullShape, &sa, &other, &sb, (cdReal)SLOP, (cdReal)(0.25 * SLOP));
		TEST_CHECKF(viaBox.state == viaHull.state || viaBox.state == CD_TOI_FAILED ||
						viaHull.state == CD_TOI_FAILED,
					"case %d: box %d hull %d", i, (int)viaBox.state, (int)viaHull.state);
		if (viaBox.state == viaHull.state)
		{
			TEST_CHECKF(fabs((double)viaBox.t - (double)viaHull.t) <= 2e-3, "case %d: box %.9g hull %.9g", i,
						(double)viaBox.t, (double)viaHull.t);
		}
		cd3Shape placedBox = PlacedAt(&boxShape, &sa, 0.0);
		cd3Shape placedHull = hullShape;
		placedHull.hull.transform = cd3GetSweepTransform(&sa, CD_R(0.0));
		cd3Vec translation = RandomVec(&rng, -4.0, 4.0);
		cd3CastOutput castBox = cd3ShapeCast(&placedBox, &other, translation);
		cd3CastOutput castHull = cd3ShapeCast(&placedHull, &other, translation);
		TEST_CHECKF(castBox.hit == castHull.hit ||
						fabs((double)castBox.fraction - (double)castHull.fraction) < 1e-3,
					"case %d: cast box %d hull %d", i, castBox.hit, castHull.hit);
		if (castBox.hit && castHull.hit)
		{
			TEST_CHECKF(fabs((double)castBox.fraction - (double)castHull.fraction) <= 1e-3, "case %d", i);
		}
	}
	cd3DestroyHull(hull);
}

/* Translation only, target 0: the time of impact is the shape cast's fraction (both within their
 * tolerances over the approach speed). */
static void TestToiTranslationEqualsCast(void)
{
	TestRng rng = TestRngMake(0x70C3u);
	const cd3ShapeType types[7] = {CD3_SHAPE_SPHERE,   CD3_SHAPE_CAPSULE, CD3_SHAPE_AABB, CD3_SHAPE_BOX,
								   CD3_SHAPE_TRIANGLE, CD3_SHAPE_SEGMENT, CD3_SHAPE_PLANE};
	int compared = 0;
	for (int i = 0; i < 3000; ++i)
	{
		cd3Shape a = RandomShape(&rng, types[TestRngInt(&rng, 6)], 0.7);
		cd3Shape b = RandomShape(&rng, types[TestRngInt(&rng, 7)], 0.7);
		cd3Vec translation = RandomVec(&rng, -4.0, 4.0);
		cd3Sweep sa = LinearSweep(CD3_VEC_ZERO, translation), sb = StillSweep();
		cdToiOutput toi = cd3TimeOfImpact(&a, &sa, &b, &sb, CD_R(0.0), CD_R(1e-5));
		cd3CastOutput cast = cd3ShapeCast(&a, &b, translation);
		if (toi.state == CD_TOI_OVERLAPPED)
		{
			TEST_CHECKF(cast.hit && cast.fraction == CD_R(0.0), "case %d", i);
			continue;
		}
		if (!cast.hit || toi.state != CD_TOI_HIT)
		{
			TEST_CHECKF(cast.hit == (toi.state == CD_TOI_HIT) ||
							RefDistanceAt(&a, &sa, &b, &sb, 1.0) < 1e-4 ||
							RefMinimumBefore(&a, &sa, &b, &sb, 1.0, 64) < 1e-4,
						"case %d: cast %d toi %d", i, cast.hit, (int)toi.state);
			continue;
		}
		double approach = -(double)cd3Dot(cast.normal, translation);
		if (cast.fraction == CD_R(0.0) || approach < 0.1 * (double)cd3Length(translation))
		{
			continue;
		}
		++compared;
		double toiTolerance = fmax(1e-5, 64.0 * CD_REAL_EPSILON * 8.0);
		TEST_CHECKF(fabs((double)toi.t - (double)cast.fraction) <= (toiTolerance + 1e-5) / approach + 1e-6,
					"case %d %s %s: toi %.9g cast %.9g", i, cd3GetShapeTypeName(a.type),
					cd3GetShapeTypeName(b.type), (double)toi.t, (double)cast.fraction);
	}
	TEST_CHECKF(compared > 200, "%d compared", compared);
}

/* fuzz_cast (float): a grazing cast of two hulls at scale 12. The ray cast's direction v / |v|,
 * a sum of cancelling terms 1e-4 from the origin, erred by 1%: a support already in the simplex
 * looked like no progress, and the advancement's equally round-off normal called the hulls
 * receding, so the cast missed though they overlap deeply at fraction 0.5625. */
/* The distance after A moved by s * translation (this build's GJK: the hulls are 1e-4 to 1 apart
 * where it is asked, far above its round-off). */
static double HullGapAt(const cd3Shape* a, cd3Vec translation, const cd3Shape* b, double s)
{
	cd3Shape moved = *a;
	moved.hull.transform.p = cd3MulAdd(a->hull.transform.p, (cdReal)s, translation);
	return (double)cd3Distance(&moved, b).distance;
}

/* fuzz_cast (float): a grazing cast of two hulls at scale 12. The ray cast's direction v / |v|,
 * a sum of cancelling terms 1e-4 from the origin, erred by about 1%: a support already in the
 * simplex looked like no progress, and the advancement's equally round-off normal called the
 * hulls receding, so the cast missed though they overlap deeply at fraction 0.5625. */
static void TestCastGrazingHulls(void)
{
	const cd3Vec pointsA[10] = {
		{CD_R(0.375), CD_R(-12.0), CD_R(1.0)},	   {CD_R(-2.75), CD_R(2.625), CD_R(-0.375)},
		{CD_R(0.875), CD_R(-12.125), CD_R(-12.5)}, {CD_R(0.25), CD_R(-0.375), CD_R(-0.5)},
		{CD_R(0.375), CD_R(-0.375), CD_R(-0.5)},   {CD_R(0.0), CD_R(0.0), CD_R(0.0)},
		{CD_R(0.0), CD_R(0.0), CD_R(0.0)},		   {CD_R(0.0), CD_R(-8.875), CD_R(-0.25)},
		{CD_R(0.375), CD_R(4.75), CD_R(1.375)},	   {CD_R(-2.25), CD_R(0.0), CD_R(0.625)}};
	const cd3Vec pointsB[4] = {{CD_R(6.5), CD_R(0.375), CD_R(1.375)},
							   {CD_R(-2.25), CD_R(0.0), CD_R(0.75)},
							   {CD_R(0.5), CD_R(0.0), CD_R(0.125)},
							   {CD_R(-12.5), CD_R(-12.5), CD_R(-12.5)}};
	cd3Hull *hullA = NULL, *hullB = NULL;
	TEST_CHECK(cd3ComputeHull(pointsA, 10, &hullA) == CD_OK);
	TEST_CHECK(cd3ComputeHull(pointsB, 4, &hullB) == CD_OK);
	if (hullA == NULL || hullB == NULL)
	{
		return;
	}
	cd3Transform placeA = {
		{CD_R(-0.375), CD_R(1.75), CD_R(-1.5)},
		{(cdReal)-0.182574183, (cdReal)-0.426006407, (cdReal)-0.243432239, (cdReal)-0.852012813}};
	cd3Transform placeB = {{CD_R(2.375), CD_R(0.0), CD_R(0.0)}, CD3_QUAT_IDENTITY};
	cd3Shape a = cd3MakeHullShape(hullA, placeA), b = cd3MakeHullShape(hullB, placeB);
	cd3Vec translation = {CD_R(-12.5), CD_R(-12.5), CD_R(-12.5)};
	cd3CastOutput out = cd3ShapeCast(&a, &b, translation);
	TEST_CHECKF(HullGapAt(&a, translation, &b, 0.5625) == 0.0, "overlap at 0.5625: %.9g",
				HullGapAt(&a, translation, &b, 0.5625));
	TEST_CHECKF(out.hit && out.fraction <= CD_R(0.5625), "hit %d at %.9g", out.hit, (double)out.fraction);
	double gap = HullGapAt(&a, translation, &b, (double)out.fraction);
	TEST_CHECKF(gap <= (double)CD_CAST_TOLERANCE + 1e-4, "%.9g apart at the hit %.9g", gap,
				(double)out.fraction);
	for (int i = 0; i < 64; ++i)
	{
		double s = (double)out.fraction * i / 64;
		TEST_CHECKF(HullGapAt(&a, translation, &b, s) > 0.0, "contact at %.9g before the hit %.9g", s,
					(double)out.fraction);
	}
	cd3DestroyHull(hullA);
	cd3DestroyHull(hullB);
}

#if CD_DOUBLE
/* fuzz_cast (double): a sphere coming from 1.9e28 towards a box, target 8.6e19. The bounding
 * spheres' quadratic took its discriminant as half^2 - speed^2 c, two products of 1e113 that
 * agree to far below round-off, called it negative and the pair separated for the whole step,
 * though at t = 1 the shapes are 24.6 apart. */
static void TestToiHugeTarget(void)
{
	cd3Shape sphere = Sphere(-12.5, -12.5, -12.25, 1.75);
	cd3Box box = {
		{-0.75, 1.5, 1.5}, {0.375, 0.75, 0.5}, {-0.13009761, -0.0400300338, -0.980735828, -0.140105118}};
	cd3Shape boxShape = cd3MakeBoxShape(box);
	cd3Sweep sa = {{1.0, -1.625, 1.25},
				   {1.85976343e+28, -0.875, -16059611.0},
				   {-1.875, -12.5, -12.5},
				   {0.288675135, 0.948504014, 0.123717915, -0.0412393049},
				   {-0.59805036, 0.512614595, 0.341743063, -0.512614595}};
	cd3Sweep sb = {{0.375, -0.5, 0.0},
				   {-0.375, -0.375, -0.25},
				   {1.25, 1.25, 2.125},
				   {1.4282734e-17, 8.56964043e-18, -0.707106781, -0.707106781},
				   {-0.5, -0.5, -0.5, -0.5}};
	double target = 8.55512933e+19;
	cd3Shape endA = PlacedAt(&sphere, &sa, 1.0), endB = PlacedAt(&boxShape, &sb, 1.0);
	TEST_CHECK((double)cd3Distance(&endA, &endB).distance < target);
	cdToiOutput out = cd3TimeOfImpact(&sphere, &sa, &boxShape, &sb, target, 0.75);
	TEST_CHECKF(out.state == CD_TOI_HIT && out.t < 1.0, "state %d t %.17g", (int)out.state, out.t);
	cd3Shape atA = PlacedAt(&sphere, &sa, out.t), atB = PlacedAt(&boxShape, &sb, out.t);
	double distance = (double)cd3Distance(&atA, &atB).distance;
	/* The time of impact's documented round-off: 64 epsilons of the sweep's largest coordinate. */
	TEST_CHECKF(fabs(distance - target) <= 64.0 * CD_REAL_EPSILON * 1.86e28, "distance %.17g at t %.17g",
				distance, out.t);
}
#endif

/* A segment far longer than the box it is cast at (a needle Minkowski difference): the segment
 * lies 5 above a face of a box of size 2-20, over the face's inner part, and moves 10 towards it,
 * so it hits at fraction 0.5. GJK's faces on the needle took their normals from the vertices'
 * differences, whose round-off (epsilon times the length) tilted them beyond the gap over the
 * needle's length: the cast missed (double build, fuzz_cast, corpus
 * regression-cast-double-segment-box-box-miss). */
#if CD_DOUBLE
#define CAST_NEEDLE_LENGTH 1.0e9
#else
#define CAST_NEEDLE_LENGTH 1.0e4
#endif

static void TestCastNeedleSegmentAtBox(void)
{
	TestRng rng = TestRngMake(0xca57e16u);
	/* The cast's round-off: 64 epsilons of the coordinates (CAST_ROUND_OFF) and GJK's on the
	 * needle, over the 10 travelled. */
	double tolerance = 128.0 * (double)CD_REAL_EPSILON * CAST_NEEDLE_LENGTH / 10.0;
	double worst = 0.0;
	for (int trial = 0; trial < 500; ++trial)
	{
		NeedleCase needle = MakeNeedleOverBox(&rng, CAST_NEEDLE_LENGTH, 5.0);
		cd3Shape a = cd3MakeSegmentShape(needle.segment), b = cd3MakeBoxShape(needle.box);
		cd3CastOutput out = cd3ShapeCast(&a, &b, cd3Scale(CD_R(-10.0), needle.normal));
		double error = out.hit ? fabs((double)out.fraction - 0.5) : 1.0;
		worst = fmax(worst, error);
		TEST_CHECKF(out.hit && error <= tolerance, "hit %d at fraction %.9g, expected 0.5 (tolerance %.3g)",
					(int)out.hit, (double)out.fraction, tolerance);
	}
	printf("  needle segment casts: worst fraction error %.3g (length %.0e, tolerance %.3g)\n", worst,
		   CAST_NEEDLE_LENGTH, tolerance);
#if CD_DOUBLE
	/* The fuzzer's case, to the bit: a box flat to a segment 6.4e8 long, cast at a box of size 25
	 * that it overlaps deeply at fraction 0.5. */
	cd3Box needle = {
		{-11.875, -1.125, 5.125}, {318767104, 0, 0}, {0, 0, -0.90502370174983282, -0.42536113982242141}};
	cd3Box target = {{-12.5, -12.5, -12.5}, {12.5, 12.5, 12.5}, {-0.5, -0.5, -0.5, -0.5}};
	cd3Shape needleShape = cd3MakeBoxShape(needle), targetShape = cd3MakeBoxShape(target);
	cd3CastOutput fuzzed = cd3ShapeCast(&needleShape, &targetShape, cd3MakeVec(-12.5, -12.5, -12.5));
	TEST_CHECKF(fuzzed.hit && fuzzed.fraction <= 0.5, "hit %d at fraction %.17g", (int)fuzzed.hit,
				(double)fuzzed.fraction);
#endif
}

int main(void)
{
	TEST_RUN(TestCastSphereAtBoxAndPlane);
	TEST_RUN(TestCastPointAgreesWithRaycast);
	TEST_RUN(TestToiExactAndBullet);
	TEST_RUN(TestToiTurningLongBox);
	TEST_RUN(TestToiRandomPairs);
	TEST_RUN(TestHullActsAsBox);
	TEST_RUN(TestToiTranslationEqualsCast);
	TEST_RUN(TestCastGrazingHulls);
	TEST_RUN(TestCastNeedleSegmentAtBox);
#if CD_DOUBLE
	TEST_RUN(TestToiHugeTarget);
#endif
	return TEST_SUMMARY();
}
