/* Tests of the mass properties in 2D and 3D: closed forms, a box hull equal to the box, a
 * zero-length capsule equal to a ball, capsules against slice-by-slice integration, random hulls
 * and rounded polygons against stratified Monte-Carlo integration in double, invariance of the
 * inertia's trace under rotation, and the parallel-axis theorem on composed bodies. */
#include "collide/geometry2.h"
#include "collide/geometry3.h"
#include "random_shapes3.h"
#include "test.h"

#define PI 3.14159265358979323846

typedef struct DMass3
{
	double mass, center[3], inertia[3][3];
} DMass3;

static DMass3 FromMass3(cd3MassData m)
{
	DMass3 d;
	d.mass = (double)m.mass;
	d.center[0] = (double)m.center.x;
	d.center[1] = (double)m.center.y;
	d.center[2] = (double)m.center.z;
	cd3Vec columns[3] = {m.inertia.cx, m.inertia.cy, m.inertia.cz};
	for (int j = 0; j < 3; ++j)
	{
		d.inertia[0][j] = (double)columns[j].x;
		d.inertia[1][j] = (double)columns[j].y;
		d.inertia[2][j] = (double)columns[j].z;
	}
	return d;
}

/* Largest difference between two mass data, relative to the mass, the size and the inertia. */
static double MassError3(const DMass3* a, const DMass3* b, double size)
{
	double scale = fabs(b->mass) > 0.0 ? fabs(b->mass) : 1.0;
	double error = fabs(a->mass - b->mass) / scale;
	double inertiaScale = fabs(b->inertia[0][0]) + fabs(b->inertia[1][1]) + fabs(b->inertia[2][2]);
	inertiaScale = inertiaScale > 0.0 ? inertiaScale : 1.0;
	for (int i = 0; i < 3; ++i)
	{
		double c = fabs(a->center[i] - b->center[i]) / size;
		error = c > error ? c : error;
		for (int j = 0; j < 3; ++j)
		{
			double e = fabs(a->inertia[i][j] - b->inertia[i][j]) / inertiaScale;
			error = e > error ? e : error;
		}
	}
	return error;
}

static void CheckSymmetric(const DMass3* m)
{
	double scale = fabs(m->inertia[0][0]) + fabs(m->inertia[1][1]) + fabs(m->inertia[2][2]) + 1e-300;
	for (int i = 0; i < 3; ++i)
	{
		for (int j = 0; j < 3; ++j)
		{
			TEST_CHECKF(fabs(m->inertia[i][j] - m->inertia[j][i]) <= 1e-6 * scale, "inertia not symmetric");
		}
	}
}

static void TestSphereAndBox(void)
{
	cd3Sphere s = {cd3MakeVec(CD_R(1.0), CD_R(2.0), CD_R(3.0)), CD_R(0.5)};
	DMass3 m = FromMass3(cd3ComputeSphereMass(s, CD_R(2.0)));
	double mass = 2.0 * 4.0 / 3.0 * PI * 0.125;
	TEST_CHECK_NEAR(m.mass, mass, 1e-6 * mass);
	TEST_CHECK_NEAR(m.inertia[1][1], 0.4 * mass * 0.25, 1e-6 * mass);
	TEST_CHECK(m.inertia[0][1] == 0.0 && m.center[2] == 3.0);

	cd3Box box = {cd3MakeVec(CD_R(-1.0), CD_R(0.0), CD_R(4.0)), cd3MakeVec(CD_R(1.0), CD_R(2.0), CD_R(3.0)),
				  CD3_QUAT_IDENTITY};
	m = FromMass3(cd3ComputeBoxMass(box, CD_R(0.5)));
	TEST_CHECK_NEAR(m.mass, 0.5 * 48.0, 1e-5);
	TEST_CHECK_NEAR(m.inertia[0][0], 24.0 * (4.0 + 9.0) / 3.0, 1e-4);
	TEST_CHECK_NEAR(m.inertia[1][1], 24.0 * (1.0 + 9.0) / 3.0, 1e-4);
	TEST_CHECK_NEAR(m.inertia[2][2], 24.0 * (1.0 + 4.0) / 3.0, 1e-4);
	cd3Aabb aabb = {cd3MakeVec(CD_R(-2.0), CD_R(-2.0), CD_R(1.0)),
					cd3MakeVec(CD_R(0.0), CD_R(2.0), CD_R(7.0))};
	DMass3 a = FromMass3(cd3ComputeAabbMass(aabb, CD_R(0.5)));
	TEST_CHECK(MassError3(&a, &m, 1.0) <= 1e-6);

	/* Turned 90 degrees about z, the x and y moments swap. */
	box.rotation = cd3MakeQuatAxisAngle(cd3MakeVec(CD_R(0.0), CD_R(0.0), CD_R(1.0)), CD_R(0.5) * CD_PI);
	DMass3 r = FromMass3(cd3ComputeBoxMass(box, CD_R(0.5)));
	TEST_CHECK_NEAR(r.inertia[0][0], m.inertia[1][1], 1e-4);
	TEST_CHECK_NEAR(r.inertia[1][1], m.inertia[0][0], 1e-4);
	TEST_CHECK_NEAR(r.inertia[0][1], 0.0, 1e-4);

	/* Non-solid shapes weigh nothing. */
	cd3Shape tri =
		cd3MakeTriangleShape((cd3Triangle){cd3MakeVec(0, 0, 0), cd3MakeVec(3, 0, 0), cd3MakeVec(0, 3, 0)});
	cd3MassData none = cd3ComputeShapeMass(&tri, CD_R(1.0));
	TEST_CHECK(none.mass == CD_R(0.0) && none.center.x == CD_R(1.0) && none.inertia.cx.x == CD_R(0.0));
	cd3Shape plane = cd3MakePlaneShape((cd3Plane){cd3MakeVec(0, 1, 0), CD_R(0.0)});
	TEST_CHECK(cd3ComputeShapeMass(&plane, CD_R(1.0)).mass == CD_R(0.0));
}

/* Capsule about its centre, by slices across the axis: a disc of radius rho(t) has axial moment
 * m rho^2 / 2 and moment m (rho^2 / 4 + t^2) about a perpendicular axis through the centre. */
static void CapsuleBySlices(double length, double radius, double* mass, double* axial, double* across)
{
	const int steps = 20000;
	double half = 0.5 * length + radius;
	double h = 2.0 * half / steps;
	*mass = *axial = *across = 0.0;
	for (int i = 0; i <= steps; ++i)
	{
		double t = -half + i * h;
		double beyond = fabs(t) - 0.5 * length;
		double rho2 = beyond <= 0.0 ? radius * radius : radius * radius - beyond * beyond;
		rho2 = rho2 > 0.0 ? rho2 : 0.0;
		double w = (i == 0 || i == steps) ? 1.0 : (i % 2 ? 4.0 : 2.0); /* Simpson */
		double dm = w * PI * rho2 * h / 3.0;
		*mass += dm;
		*axial += dm * rho2 / 2.0;
		*across += dm * (rho2 / 4.0 + t * t);
	}
}

static void TestCapsule(void)
{
	TestRng rng = TestRngMake(0x3a55001u);
	for (int i = 0; i < 100; ++i)
	{
		double length = i == 0 ? 0.0 : TestRngRange(&rng, 0.0, 3.0), radius = TestRngRange(&rng, 0.1, 1.5);
		cd3Vec axis = RandomUnit(&rng);
		cd3Vec center = RandomVec(&rng, 5.0);
		cd3Capsule c = {cd3MulSub(center, (cdReal)(0.5 * length), axis),
						cd3MulAdd(center, (cdReal)(0.5 * length), axis), (cdReal)radius};
		DMass3 m = FromMass3(cd3ComputeCapsuleMass(c, CD_R(1.0)));
		double mass, axial, across;
		CapsuleBySlices(length, radius, &mass, &axial, &across);
		CheckSymmetric(&m);
		TEST_CHECKF(fabs(m.mass - mass) <= 1e-5 * mass, "capsule L %g r %g: mass %.9g, slices %.9g", length,
					radius, m.mass, mass);
		/* The tensor's moment about the axis and about a perpendicular. */
		double a[3] = {(double)axis.x, (double)axis.y, (double)axis.z};
		cd3Vec p = cd3Perpendicular(axis);
		double q[3] = {(double)p.x, (double)p.y, (double)p.z};
		double aia = 0.0, qiq = 0.0;
		for (int r = 0; r < 3; ++r)
		{
			for (int s = 0; s < 3; ++s)
			{
				aia += a[r] * m.inertia[r][s] * a[s];
				qiq += q[r] * m.inertia[r][s] * q[s];
			}
		}
		TEST_CHECKF(fabs(aia - axial) <= 1e-5 * axial && fabs(qiq - across) <= 1e-5 * across,
					"capsule L %g r %g: axial %.9g vs %.9g, across %.9g vs %.9g", length, radius, aia, axial,
					qiq, across);
		TEST_CHECK_NEAR(cd3VecDistance(cd3ComputeCapsuleMass(c, CD_R(1.0)).center, center), 0.0, 1e-5);
	}
	/* Zero length: exactly a ball. */
	cd3Vec at = cd3MakeVec(CD_R(1.0), CD_R(-2.0), CD_R(0.5));
	cd3Capsule point = {at, at, CD_R(0.75)};
	cd3Sphere ball = {at, CD_R(0.75)};
	DMass3 cm = FromMass3(cd3ComputeCapsuleMass(point, CD_R(3.0)));
	DMass3 sm = FromMass3(cd3ComputeSphereMass(ball, CD_R(3.0)));
	TEST_CHECK(MassError3(&cm, &sm, 1.0) <= 1e-6);
}

/* Stratified Monte-Carlo integration of a hull shape in double (a jittered grid over its box). */
static DMass3 HullByMonteCarlo(TestRng* rng, const cd3Shape* s, int cells)
{
	const cd3Hull* hull = s->hull.hull;
	cd3Aabb box = hull->bounds;
	double lo[3] = {(double)box.min.x, (double)box.min.y, (double)box.min.z};
	double step[3] = {((double)box.max.x - lo[0]) / cells, ((double)box.max.y - lo[1]) / cells,
					  ((double)box.max.z - lo[2]) / cells};
	double cellVolume = step[0] * step[1] * step[2];
	double mass = 0.0, first[3] = {0, 0, 0}, second[3][3] = {{0}};
	for (int i = 0; i < cells; ++i)
	{
		for (int j = 0; j < cells; ++j)
		{
			for (int k = 0; k < cells; ++k)
			{
				double x[3] = {lo[0] + (i + TestRngRange(rng, 0.0, 1.0)) * step[0],
							   lo[1] + (j + TestRngRange(rng, 0.0, 1.0)) * step[1],
							   lo[2] + (k + TestRngRange(rng, 0.0, 1.0)) * step[2]};
				bool inside = true;
				for (int f = 0; f < hull->faceCount && inside; ++f)
				{
					cd3Plane p = hull->planes[f];
					inside =
						(double)p.normal.x * x[0] + (double)p.normal.y * x[1] + (double)p.normal.z * x[2] <=
						(double)p.offset;
				}
				if (!inside)
				{
					continue;
				}
				mass += cellVolume;
				for (int r = 0; r < 3; ++r)
				{
					first[r] += cellVolume * x[r];
					for (int c = 0; c < 3; ++c)
					{
						second[r][c] += cellVolume * x[r] * x[c];
					}
				}
			}
		}
	}
	/* Local frame: centre and inertia, then rotated like the shape. */
	DMass3 local;
	local.mass = mass;
	for (int r = 0; r < 3; ++r)
	{
		local.center[r] = first[r] / mass;
	}
	double cov[3][3];
	for (int r = 0; r < 3; ++r)
	{
		for (int c = 0; c < 3; ++c)
		{
			cov[r][c] = second[r][c] - mass * local.center[r] * local.center[c];
		}
	}
	double trace = cov[0][0] + cov[1][1] + cov[2][2];
	cd3Mat33 rm = cd3MakeMatFromQuat(s->hull.transform.q);
	double rot[3][3] = {{(double)rm.cx.x, (double)rm.cy.x, (double)rm.cz.x},
						{(double)rm.cx.y, (double)rm.cy.y, (double)rm.cz.y},
						{(double)rm.cx.z, (double)rm.cy.z, (double)rm.cz.z}};
	DMass3 world;
	world.mass = mass;
	for (int r = 0; r < 3; ++r)
	{
		world.center[r] = (double)cd3GetComponent(s->hull.transform.p, r);
		for (int c = 0; c < 3; ++c)
		{
			world.center[r] += rot[r][c] * local.center[c];
			double sum = 0.0;
			for (int a = 0; a < 3; ++a)
			{
				for (int b = 0; b < 3; ++b)
				{
					sum += rot[r][a] * ((a == b ? trace : 0.0) - cov[a][b]) * rot[c][b];
				}
			}
			world.inertia[r][c] = sum;
		}
	}
	return world;
}

static void TestHulls(void)
{
	TestRng rng = TestRngMake(0x3a55002u);
	/* A box hull weighs what the box does, turned or not. */
	for (int i = 0; i < 50; ++i)
	{
		cd3Vec half =
			cd3MakeVec(RandomReal(&rng, 0.1, 2.0), RandomReal(&rng, 0.1, 2.0), RandomReal(&rng, 0.1, 2.0));
		cd3Hull* hull = NULL;
		TEST_CHECK(cd3MakeBoxHull(half, &hull) == CD_OK);
		if (hull == NULL)
		{
			continue;
		}
		cd3Transform t = {RandomVec(&rng, 10.0), RandomQuat(&rng)};
		cd3Box box = {t.p, half, t.q};
		cd3Shape shape = cd3MakeHullShape(hull, t);
		DMass3 h = FromMass3(cd3ComputeShapeMass(&shape, CD_R(1.5)));
		DMass3 b = FromMass3(cd3ComputeBoxMass(box, CD_R(1.5)));
		CheckSymmetric(&h);
		TEST_CHECKF(MassError3(&h, &b, 1.0) <= 1e-5, "box hull differs from the box by %.3g",
					MassError3(&h, &b, 1.0));
		cd3DestroyHull(hull);
	}

	/* Random hulls against Monte-Carlo integration; the trace is the same in every pose. */
	for (int i = 0; i < 12; ++i)
	{
		cd3Shape s = RandomShape(&rng, CD3_SHAPE_HULL);
		DMass3 exact = FromMass3(cd3ComputeHullMass(s.hull, CD_R(1.0)));
		DMass3 sampled = HullByMonteCarlo(&rng, &s, 48);
		double size = (double)cd3Length(cd3Sub(s.hull.hull->bounds.max, s.hull.hull->bounds.min));
		double error = MassError3(&exact, &sampled, size);
		TEST_CHECKF(error <= 5e-3, "hull %d: mass data off Monte-Carlo by %.3g (mass %.6g vs %.6g)", i, error,
					exact.mass, sampled.mass);
		TEST_CHECK_NEAR(exact.mass, (double)s.hull.hull->volume, 1e-5 * exact.mass);

		cd3Transform other = {RandomVec(&rng, 100.0), RandomQuat(&rng)};
		cd3Shape moved = s;
		moved.hull.transform = other;
		DMass3 m = FromMass3(cd3ComputeHullMass(moved.hull, CD_R(1.0)));
		double trace = exact.inertia[0][0] + exact.inertia[1][1] + exact.inertia[2][2];
		double movedTrace = m.inertia[0][0] + m.inertia[1][1] + m.inertia[2][2];
		TEST_CHECK_NEAR(movedTrace, trace, 1e-5 * trace);
		TEST_CHECK_NEAR(m.mass, exact.mass, 1e-6 * exact.mass);
		cd3Vec localCenter = cd3InvTransformPoint(
			s.hull.transform,
			cd3MakeVec((cdReal)exact.center[0], (cdReal)exact.center[1], (cdReal)exact.center[2]));
		cd3Vec expected = cd3TransformPoint(other, localCenter);
		TEST_CHECK_NEAR(cd3VecDistance(expected, cd3MakeVec((cdReal)m.center[0], (cdReal)m.center[1],
															(cdReal)m.center[2])),
						0.0, 1e-4);
	}

	/* Parallel axis: two boxes side by side, each moved to the common centre, make the long box. */
	cd3Hull* halfBox = NULL;
	cd3Hull* longBox = NULL;
	TEST_CHECK(cd3MakeBoxHull(cd3MakeVec(CD_R(1.0), CD_R(0.5), CD_R(0.25)), &halfBox) == CD_OK);
	TEST_CHECK(cd3MakeBoxHull(cd3MakeVec(CD_R(2.0), CD_R(0.5), CD_R(0.25)), &longBox) == CD_OK);
	if (halfBox != NULL && longBox != NULL)
	{
		cd3Quat q = cd3MakeQuatAxisAngle(cd3MakeVec(CD_R(1.0), CD_R(2.0), CD_R(-1.0)), CD_R(0.8));
		cd3Vec at = cd3MakeVec(CD_R(3.0), CD_R(-1.0), CD_R(2.0));
		cd3Vec offset = cd3RotateVector(q, cd3MakeVec(CD_R(1.0), CD_R(0.0), CD_R(0.0)));
		DMass3 left =
			FromMass3(cd3ComputeHullMass((cd3HullShape){halfBox, {cd3Sub(at, offset), q}}, CD_R(2.0)));
		DMass3 right =
			FromMass3(cd3ComputeHullMass((cd3HullShape){halfBox, {cd3Add(at, offset), q}}, CD_R(2.0)));
		DMass3 whole = FromMass3(cd3ComputeHullMass((cd3HullShape){longBox, {at, q}}, CD_R(2.0)));
		DMass3 sum;
		sum.mass = left.mass + right.mass;
		double d[3] = {(double)offset.x, (double)offset.y, (double)offset.z};
		for (int r = 0; r < 3; ++r)
		{
			sum.center[r] = 0.5 * (left.center[r] + right.center[r]);
			for (int c = 0; c < 3; ++c)
			{
				/* Each half is |d| away: I + m (|d|^2 1 - d d^T). */
				double shift = (r == c ? d[0] * d[0] + d[1] * d[1] + d[2] * d[2] : 0.0) - d[r] * d[c];
				sum.inertia[r][c] = left.inertia[r][c] + right.inertia[r][c] + sum.mass * shift;
			}
		}
		TEST_CHECKF(MassError3(&sum, &whole, 1.0) <= 1e-5, "parallel axis: off by %.3g",
					MassError3(&sum, &whole, 1.0));
	}
	cd3DestroyHull(halfBox);
	cd3DestroyHull(longBox);
}

/* ---- 2D ------------------------------------------------------------------------------------------ */

static double SegmentDistance2(double px, double py, double ax, double ay, double bx, double by)
{
	double ex = bx - ax, ey = by - ay, ee = ex * ex + ey * ey;
	double t = ee > 0.0 ? ((px - ax) * ex + (py - ay) * ey) / ee : 0.0;
	t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
	double dx = px - ax - t * ex, dy = py - ay - t * ey;
	return sqrt(dx * dx + dy * dy);
}

/* Point in the rounded polygon: inside the core, or within radius of an edge. */
static bool InRoundedPolygon(const cd2Polygon* p, double x, double y)
{
	bool core = p->count >= 3;
	double best = INFINITY;
	for (int i = 0; i < p->count; ++i)
	{
		int j = (i + 1) % p->count;
		double ax = (double)p->vertices[i].x, ay = (double)p->vertices[i].y;
		double bx = (double)p->vertices[j].x, by = (double)p->vertices[j].y;
		core = core && (bx - ax) * (y - ay) - (by - ay) * (x - ax) >= 0.0;
		double d = SegmentDistance2(x, y, ax, ay, bx, by);
		best = d < best ? d : best;
	}
	return core || best <= (double)p->radius;
}

static void TestMass2(void)
{
	cd2Circle circle = {cd2MakeVec(CD_R(1.0), CD_R(2.0)), CD_R(0.5)};
	cd2MassData m = cd2ComputeCircleMass(circle, CD_R(2.0));
	TEST_CHECK_NEAR(m.mass, 2.0 * PI * 0.25, 1e-6);
	TEST_CHECK_NEAR(m.rotationalInertia, 0.5 * 2.0 * PI * 0.25 * 0.25, 1e-6);

	cd2Box box = {cd2MakeVec(CD_R(1.0), CD_R(-1.0)), cd2MakeVec(CD_R(2.0), CD_R(0.5)), cd2MakeRot(CD_R(0.3))};
	m = cd2ComputeBoxMass(box, CD_R(3.0));
	TEST_CHECK_NEAR(m.mass, 3.0 * 4.0, 1e-5);
	TEST_CHECK_NEAR(m.rotationalInertia, 12.0 * (16.0 + 1.0) / 12.0, 1e-5);
	cd2Polygon polygon;
	TEST_CHECK(cd2MakeBoxPolygon(box, &polygon) == CD_OK);
	cd2MassData p = cd2ComputePolygonMass(&polygon, CD_R(3.0));
	TEST_CHECK_NEAR(p.mass, m.mass, 1e-5);
	TEST_CHECK_NEAR(p.rotationalInertia, m.rotationalInertia, 1e-4);
	TEST_CHECK_NEAR(p.center.x, 1.0, 1e-5);
	TEST_CHECK_NEAR(p.center.y, -1.0, 1e-5);
	cd2Aabb aabb = {cd2MakeVec(CD_R(-1.0), CD_R(-1.5)), cd2MakeVec(CD_R(3.0), CD_R(-0.5))};
	cd2MassData a = cd2ComputeAabbMass(aabb, CD_R(3.0));
	TEST_CHECK_NEAR(a.mass, m.mass, 1e-5);
	TEST_CHECK_NEAR(a.rotationalInertia, m.rotationalInertia, 1e-4);

	/* Capsule: zero length is the circle; otherwise slices across the axis. */
	cd2Capsule dot = {circle.center, circle.center, circle.radius};
	cd2MassData c = cd2ComputeCapsuleMass(dot, CD_R(2.0));
	TEST_CHECK_NEAR(c.mass, cd2ComputeCircleMass(circle, CD_R(2.0)).mass, 1e-6);
	TEST_CHECK_NEAR(c.rotationalInertia, cd2ComputeCircleMass(circle, CD_R(2.0)).rotationalInertia, 1e-6);
	TestRng rng = TestRngMake(0x3a55003u);
	for (int i = 0; i < 50; ++i)
	{
		double length = TestRngRange(&rng, 0.0, 3.0), r = TestRngRange(&rng, 0.1, 1.0);
		double angle = TestRngRange(&rng, 0.0, 6.0);
		cd2Vec u = cd2MakeVec((cdReal)cos(angle), (cdReal)sin(angle));
		cd2Vec center = cd2MakeVec((cdReal)TestRngRange(&rng, -5, 5), (cdReal)TestRngRange(&rng, -5, 5));
		cd2Capsule capsule = {cd2MulSub(center, (cdReal)(0.5 * length), u),
							  cd2MulAdd(center, (cdReal)(0.5 * length), u), (cdReal)r};
		const int steps = 20000;
		double half = 0.5 * length + r, h = 2.0 * half / steps, mass = 0.0, inertia = 0.0;
		for (int k = 0; k <= steps; ++k)
		{
			double t = -half + k * h, beyond = fabs(t) - 0.5 * length;
			double w2 = beyond <= 0.0 ? r * r : r * r - beyond * beyond;
			double width = w2 > 0.0 ? sqrt(w2) : 0.0; /* half width of the slice */
			double weight = (k == 0 || k == steps) ? 1.0 : (k % 2 ? 4.0 : 2.0);
			double dm = weight * 2.0 * width * h / 3.0;
			mass += dm;
			inertia += dm * (width * width / 3.0 + t * t);
		}
		cd2MassData cm = cd2ComputeCapsuleMass(capsule, CD_R(1.0));
		TEST_CHECKF(fabs((double)cm.mass - mass) <= 1e-4 * mass &&
						fabs((double)cm.rotationalInertia - inertia) <= 1e-4 * inertia,
					"capsule L %g r %g: mass %.9g vs %.9g, inertia %.9g vs %.9g", length, r, (double)cm.mass,
					mass, (double)cm.rotationalInertia, inertia);
	}

	/* Rounded polygons against stratified Monte-Carlo; a rounded box's area in closed form. */
	cd2Vec corners[4] = {cd2MakeVec(-1, -0.5f), cd2MakeVec(1, -0.5f), cd2MakeVec(1, 0.5f),
						 cd2MakeVec(-1, 0.5f)};
	cd2Polygon rounded;
	TEST_CHECK(cd2MakeRoundedPolygon(corners, 4, CD_R(0.25), &rounded) == CD_OK);
	cd2MassData rm = cd2ComputePolygonMass(&rounded, CD_R(1.0));
	TEST_CHECK_NEAR(rm.mass, 2.0 + 0.25 * 6.0 + PI * 0.0625, 1e-5);
	for (int i = 0; i < 20; ++i)
	{
		cd2Vec points[8];
		int count = 3 + TestRngInt(&rng, 6);
		for (int k = 0; k < count; ++k)
		{
			points[k] =
				cd2MakeVec((cdReal)TestRngRange(&rng, -1.0, 1.0), (cdReal)TestRngRange(&rng, -1.0, 1.0));
		}
		double radius = i % 2 ? 0.0 : TestRngRange(&rng, 0.05, 0.5);
		cd2Polygon poly;
		if (cd2MakeRoundedPolygon(points, count, (cdReal)radius, &poly) != CD_OK)
		{
			continue;
		}
		/* A jittered grid over the polygon's own bounds. */
		double loX = INFINITY, loY = INFINITY, hiX = -INFINITY, hiY = -INFINITY;
		for (int k = 0; k < poly.count; ++k)
		{
			loX = fmin(loX, (double)poly.vertices[k].x - radius);
			loY = fmin(loY, (double)poly.vertices[k].y - radius);
			hiX = fmax(hiX, (double)poly.vertices[k].x + radius);
			hiY = fmax(hiY, (double)poly.vertices[k].y + radius);
		}
		const int cells = 300;
		double stepX = (hiX - loX) / cells, stepY = (hiY - loY) / cells, cell = stepX * stepY;
		double area = 0.0, mx = 0.0, my = 0.0, polar = 0.0;
		for (int x = 0; x < cells; ++x)
		{
			for (int y = 0; y < cells; ++y)
			{
				double px = loX + (x + TestRngRange(&rng, 0.0, 1.0)) * stepX;
				double py = loY + (y + TestRngRange(&rng, 0.0, 1.0)) * stepY;
				if (InRoundedPolygon(&poly, px, py))
				{
					area += cell;
					mx += cell * px;
					my += cell * py;
					polar += cell * (px * px + py * py);
				}
			}
		}
		double cx = mx / area, cy = my / area;
		double inertia = polar - area * (cx * cx + cy * cy);
		cd2MassData pm = cd2ComputePolygonMass(&poly, CD_R(1.0));
		bool ok = fabs((double)pm.mass - area) <= 3e-3 * area && fabs((double)pm.center.x - cx) <= 3e-3 &&
				  fabs((double)pm.center.y - cy) <= 3e-3 &&
				  fabs((double)pm.rotationalInertia - inertia) <= 5e-3 * inertia;
		TEST_CHECKF(ok,
					"polygon %d (radius %g): mass %.6g vs %.6g, centre (%.4g %.4g) vs (%.4g %.4g), inertia "
					"%.6g vs %.6g",
					i, radius, (double)pm.mass, area, (double)pm.center.x, (double)pm.center.y, cx, cy,
					(double)pm.rotationalInertia, inertia);
	}

	/* The dispatcher, and a segment weighs nothing. */
	cd2Shape shape = cd2MakeCircleShape(circle);
	TEST_CHECK(cd2ComputeShapeMass(&shape, CD_R(2.0)).mass == cd2ComputeCircleMass(circle, CD_R(2.0)).mass);
	cd2Segment segment = {cd2MakeVec(0, 0), cd2MakeVec(2, 0)};
	shape = cd2MakeSegmentShape(segment);
	TEST_CHECK(cd2ComputeShapeMass(&shape, CD_R(1.0)).mass == CD_R(0.0));
}

int main(void)
{
	TEST_RUN(TestSphereAndBox);
	TEST_RUN(TestCapsule);
	TEST_RUN(TestHulls);
	TEST_RUN(TestMass2);
	return TEST_SUMMARY();
}
