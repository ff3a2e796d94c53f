/* Tests of cd3Distance (GJK): exact cases, and thousands of random pairs of every type
 * combination against an independent brute-force reference in double precision (feature
 * enumeration), plus symmetry, rigid-transform invariance and witness-point checks. */
#include "collide/query3.h"
#include "random_shapes3.h"
#include "test.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

/* ---- double-precision reference ------------------------------------------------------------ */
typedef struct DVec
{
	double x, y, z;
} DVec;

static DVec DMake(double x, double y, double z)
{
	DVec v = {x, y, z};
	return v;
}
static DVec DFrom(cd3Vec v)
{
	return DMake((double)v.x, (double)v.y, (double)v.z);
}
static DVec DAdd(DVec a, DVec b)
{
	return DMake(a.x + b.x, a.y + b.y, a.z + b.z);
}
static DVec DSub(DVec a, DVec b)
{
	return DMake(a.x - b.x, a.y - b.y, a.z - b.z);
}
static DVec DScale(double s, DVec a)
{
	return DMake(s * a.x, s * a.y, s * a.z);
}
static double DDot(DVec a, DVec b)
{
	return a.x * b.x + a.y * b.y + a.z * b.z;
}
static DVec DCross(DVec a, DVec b)
{
	return DMake(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static double DLength(DVec a)
{
	return sqrt(DDot(a, a));
}

/* q v q* for a (nearly) unit quaternion, in double. */
static DVec DRotate(cd3Quat q, DVec v)
{
	DVec u = DMake((double)q.x, (double)q.y, (double)q.z);
	DVec t = DScale(2.0, DCross(u, v));
	return DAdd(DAdd(v, DScale((double)q.w, t)), DCross(u, t));
}

static double PointSegmentDistance(DVec p, DVec a, DVec b)
{
	DVec e = DSub(b, a);
	double ee = DDot(e, e);
	double t = ee > 0.0 ? DDot(DSub(p, a), e) / ee : 0.0;
	t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
	return DLength(DSub(p, DAdd(a, DScale(t, e))));
}

static double PointTriangleDistance(DVec p, DVec a, DVec b, DVec c)
{
	double best = PointSegmentDistance(p, a, b);
	double other = PointSegmentDistance(p, b, c);
	best = other < best ? other : best;
	other = PointSegmentDistance(p, c, a);
	best = other < best ? other : best;
	DVec n = DCross(DSub(b, a), DSub(c, a));
	double nn = DDot(n, n);
	if (nn > 0.0)
	{
		DVec ap = DSub(p, a);
		double s = DDot(n, ap) / nn;
		DVec q = DSub(p, DScale(s, n));
		if (DDot(n, DCross(DSub(b, a), DSub(q, a))) >= 0.0 &&
			DDot(n, DCross(DSub(c, b), DSub(q, b))) >= 0.0 && DDot(n, DCross(DSub(a, c), DSub(q, c))) >= 0.0)
		{
			double planar = fabs(DDot(n, ap)) / sqrt(nn);
			best = planar < best ? planar : best;
		}
	}
	return best;
}

static double SegmentSegmentDistance(DVec p1, DVec q1, DVec p2, DVec q2)
{
	double best = PointSegmentDistance(p1, p2, q2);
	double d = PointSegmentDistance(q1, p2, q2);
	best = d < best ? d : best;
	d = PointSegmentDistance(p2, p1, q1);
	best = d < best ? d : best;
	d = PointSegmentDistance(q2, p1, q1);
	best = d < best ? d : best;
	/* Interior critical point of |p1 + s d1 - p2 - t d2|^2. */
	DVec d1 = DSub(q1, p1), d2 = DSub(q2, p2), r = DSub(p1, p2);
	double a = DDot(d1, d1), e = DDot(d2, d2), b = DDot(d1, d2), c = DDot(d1, r), f = DDot(d2, r);
	double det = a * e - b * b;
	if (det > 1e-12 * a * e)
	{
		double s = (b * f - c * e) / det;
		double t = (a * f - b * c) / det;
		if (s > 0.0 && s < 1.0 && t > 0.0 && t < 1.0)
		{
			d = DLength(DSub(DAdd(p1, DScale(s, d1)), DAdd(p2, DScale(t, d2))));
			best = d < best ? d : best;
		}
	}
	return best;
}

/* Segment p-q crosses the plane of triangle a-b-c strictly, inside the triangle. */
static bool SegmentPiercesTriangle(DVec p, DVec q, DVec a, DVec b, DVec c)
{
	DVec n = DCross(DSub(b, a), DSub(c, a));
	double sp = DDot(n, DSub(p, a)), sq = DDot(n, DSub(q, a));
	if (!((sp < 0.0 && sq > 0.0) || (sp > 0.0 && sq < 0.0)))
	{
		return false;
	}
	DVec x = DAdd(p, DScale(sp / (sp - sq), DSub(q, p)));
	return DDot(n, DCross(DSub(b, a), DSub(x, a))) >= 0.0 && DDot(n, DCross(DSub(c, b), DSub(x, b))) >= 0.0 &&
		   DDot(n, DCross(DSub(a, c), DSub(x, c))) >= 0.0;
}

/* A finite shape as vertices, edges and triangles (its core) grown by a radius; solid boxes also
 * keep their frame, and solid hulls their face planes, for point containment. */
#define REF_MAX_VERTICES 64
#define REF_MAX_EDGES (3 * REF_MAX_VERTICES)
#define REF_MAX_TRIANGLES (2 * REF_MAX_VERTICES)

typedef struct RefShape
{
	int vertexCount, edgeCount, triangleCount;
	double radius;
	bool solidBox;
	DVec center, axes[3], halfExtents;
	bool isPlane;
	DVec normal;
	double offset;
	bool solidHull;
	int planeCount;
	/* Arrays last: only the fields above are cleared (the arrays are read up to their counts). */
	DVec vertices[REF_MAX_VERTICES];
	int edges[REF_MAX_EDGES][2];
	int triangles[REF_MAX_TRIANGLES][3];
	DVec planeNormals[REF_MAX_TRIANGLES];
	double planeOffsets[REF_MAX_TRIANGLES];
} RefShape;

static const int g_boxEdges[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
									  {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
/* Two triangles per face of the cube whose vertex i has bits (x, y, z) = (i & 1, i & 2, i & 4). */
static const int g_boxTriangles[12][3] = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
										  {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};

static RefShape MakeRef(const cd3Shape* shape)
{
	RefShape r;
	memset(&r, 0, offsetof(RefShape, vertices));
	switch (shape->type)
	{
		case CD3_SHAPE_SPHERE:
			r.vertices[0] = DFrom(shape->sphere.center);
			r.vertexCount = 1;
			r.radius = (double)shape->sphere.radius;
			break;
		case CD3_SHAPE_CAPSULE:
			r.vertices[0] = DFrom(shape->capsule.p1);
			r.vertices[1] = DFrom(shape->capsule.p2);
			r.vertexCount = 2;
			r.edges[0][0] = 0;
			r.edges[0][1] = 1;
			r.edgeCount = 1;
			r.radius = (double)shape->capsule.radius;
			break;
		case CD3_SHAPE_SEGMENT:
			r.vertices[0] = DFrom(shape->segment.p1);
			r.vertices[1] = DFrom(shape->segment.p2);
			r.vertexCount = 2;
			r.edges[0][0] = 0;
			r.edges[0][1] = 1;
			r.edgeCount = 1;
			break;
		case CD3_SHAPE_TRIANGLE:
			r.vertices[0] = DFrom(shape->triangle.a);
			r.vertices[1] = DFrom(shape->triangle.b);
			r.vertices[2] = DFrom(shape->triangle.c);
			r.vertexCount = 3;
			for (int i = 0; i < 3; ++i)
			{
				r.edges[i][0] = i;
				r.edges[i][1] = (i + 1) % 3;
				r.triangles[0][i] = i;
			}
			r.edgeCount = 3;
			r.triangleCount = 1;
			break;
		case CD3_SHAPE_AABB:
		case CD3_SHAPE_BOX:
		{
			r.solidBox = true;
			if (shape->type == CD3_SHAPE_AABB)
			{
				DVec lo = DFrom(shape->aabb.min), hi = DFrom(shape->aabb.max);
				r.center = DScale(0.5, DAdd(lo, hi));
				r.halfExtents = DScale(0.5, DSub(hi, lo));
				r.axes[0] = DMake(1.0, 0.0, 0.0);
				r.axes[1] = DMake(0.0, 1.0, 0.0);
				r.axes[2] = DMake(0.0, 0.0, 1.0);
			}
			else
			{
				r.center = DFrom(shape->box.center);
				r.halfExtents = DFrom(shape->box.halfExtents);
				r.axes[0] = DRotate(shape->box.rotation, DMake(1.0, 0.0, 0.0));
				r.axes[1] = DRotate(shape->box.rotation, DMake(0.0, 1.0, 0.0));
				r.axes[2] = DRotate(shape->box.rotation, DMake(0.0, 0.0, 1.0));
			}
			for (int i = 0; i < 8; ++i)
			{
				DVec p = r.center;
				p = DAdd(p, DScale((i & 1) ? r.halfExtents.x : -r.halfExtents.x, r.axes[0]));
				p = DAdd(p, DScale((i & 2) ? r.halfExtents.y : -r.halfExtents.y, r.axes[1]));
				p = DAdd(p, DScale((i & 4) ? r.halfExtents.z : -r.halfExtents.z, r.axes[2]));
				r.vertices[i] = p;
			}
			r.vertexCount = 8;
			memcpy(r.edges, g_boxEdges, sizeof(g_boxEdges));
			memcpy(r.triangles, g_boxTriangles, sizeof(g_boxTriangles));
			r.edgeCount = 12;
			r.triangleCount = 12;
			break;
		}
		case CD3_SHAPE_PLANE:
			r.isPlane = true;
			r.normal = DFrom(shape->plane.normal);
			r.offset = (double)shape->plane.offset;
			break;
		case CD3_SHAPE_HULL:
		{
			/* World vertices in double; every edge once; each face as a fan of triangles, and its
			 * plane through its first vertex. */
			const cd3Hull* hull = shape->hull.hull;
			cd3Transform t = shape->hull.transform;
			if (hull->vertexCount > REF_MAX_VERTICES)
			{
				fprintf(stderr, "reference: hull of %d vertices is too large\n", hull->vertexCount);
				break;
			}
			r.solidHull = true;
			r.vertexCount = hull->vertexCount;
			for (int i = 0; i < hull->vertexCount; ++i)
			{
				r.vertices[i] = DAdd(DRotate(t.q, DFrom(hull->vertices[i])), DFrom(t.p));
			}
			for (int e = 0; e < hull->edgeCount; ++e)
			{
				if (e < hull->edges[e].twin)
				{
					r.edges[r.edgeCount][0] = hull->edges[e].origin;
					r.edges[r.edgeCount][1] = hull->edges[hull->edges[e].next].origin;
					++r.edgeCount;
				}
			}
			for (int f = 0; f < hull->faceCount; ++f)
			{
				int e0 = hull->faceEdges[f];
				int first = hull->edges[e0].origin;
				for (int e = hull->edges[e0].next; hull->edges[e].next != e0; e = hull->edges[e].next)
				{
					r.triangles[r.triangleCount][0] = first;
					r.triangles[r.triangleCount][1] = hull->edges[e].origin;
					r.triangles[r.triangleCount][2] = hull->edges[hull->edges[e].next].origin;
					++r.triangleCount;
				}
				DVec n = DRotate(t.q, DFrom(hull->planes[f].normal));
				n = DScale(1.0 / DLength(n), n);
				r.planeNormals[r.planeCount] = n;
				r.planeOffsets[r.planeCount] = DDot(n, r.vertices[first]);
				++r.planeCount;
			}
			break;
		}
		default:
			break;
	}
	return r;
}

static bool RefPointInBox(const RefShape* r, DVec p)
{
	if (r->solidHull)
	{
		/* Below every face plane; a relative slack for round-off, as for boxes. */
		for (int i = 0; i < r->planeCount; ++i)
		{
			double h = DDot(r->planeNormals[i], p);
			if (h - r->planeOffsets[i] > 1e-12 * (fabs(h) + fabs(r->planeOffsets[i])))
			{
				return false;
			}
		}
		return true;
	}
	if (!r->solidBox)
	{
		return false;
	}
	DVec d = DSub(p, r->center);
	double h[3] = {r->halfExtents.x, r->halfExtents.y, r->halfExtents.z};
	for (int i = 0; i < 3; ++i)
	{
		/* A relative slack, so that the test works at every scale. */
		double projection = fabs(DDot(d, r->axes[i]));
		if (projection > h[i] + 1e-12 * (h[i] + projection))
		{
			return false;
		}
	}
	return true;
}

/* Distance from a point to the core of a finite shape (0 inside a solid box). */
static double RefPointCoreDistance(const RefShape* r, DVec p)
{
	if (RefPointInBox(r, p))
	{
		return 0.0;
	}
	double best = INFINITY;
	for (int i = 0; i < r->vertexCount; ++i)
	{
		double d = DLength(DSub(p, r->vertices[i]));
		best = d < best ? d : best;
	}
	for (int i = 0; i < r->edgeCount; ++i)
	{
		double d = PointSegmentDistance(p, r->vertices[r->edges[i][0]], r->vertices[r->edges[i][1]]);
		best = d < best ? d : best;
	}
	for (int i = 0; i < r->triangleCount; ++i)
	{
		const int* t = r->triangles[i];
		double d = PointTriangleDistance(p, r->vertices[t[0]], r->vertices[t[1]], r->vertices[t[2]]);
		best = d < best ? d : best;
	}
	return best;
}

/* Distance from a point to the shape (0 inside a solid). */
static double RefPointShapeDistance(const RefShape* r, DVec p)
{
	if (r->isPlane)
	{
		double s = DDot(r->normal, p) - r->offset;
		return s > 0.0 ? s : 0.0;
	}
	double d = RefPointCoreDistance(r, p) - r->radius;
	return d > 0.0 ? d : 0.0;
}

static bool AnyEdgePierces(const RefShape* edges, const RefShape* triangles)
{
	for (int i = 0; i < edges->edgeCount; ++i)
	{
		for (int j = 0; j < triangles->triangleCount; ++j)
		{
			const int* t = triangles->triangles[j];
			if (SegmentPiercesTriangle(edges->vertices[edges->edges[i][0]],
									   edges->vertices[edges->edges[i][1]], triangles->vertices[t[0]],
									   triangles->vertices[t[1]], triangles->vertices[t[2]]))
			{
				return true;
			}
		}
	}
	return false;
}

/* Distance between the cores of two finite shapes by feature enumeration; intersection is
 * detected separately (a vertex inside a solid box, or an edge piercing a triangle). */
static double RefCoreDistance(const RefShape* a, const RefShape* b)
{
	for (int i = 0; i < b->vertexCount; ++i)
	{
		if (RefPointInBox(a, b->vertices[i]))
		{
			return 0.0;
		}
	}
	for (int i = 0; i < a->vertexCount; ++i)
	{
		if (RefPointInBox(b, a->vertices[i]))
		{
			return 0.0;
		}
	}
	if (AnyEdgePierces(a, b) || AnyEdgePierces(b, a))
	{
		return 0.0;
	}
	double best = INFINITY;
	for (int i = 0; i < a->vertexCount; ++i)
	{
		double d = RefPointCoreDistance(b, a->vertices[i]);
		best = d < best ? d : best;
	}
	for (int i = 0; i < b->vertexCount; ++i)
	{
		double d = RefPointCoreDistance(a, b->vertices[i]);
		best = d < best ? d : best;
	}
	for (int i = 0; i < a->edgeCount; ++i)
	{
		for (int j = 0; j < b->edgeCount; ++j)
		{
			double d = SegmentSegmentDistance(a->vertices[a->edges[i][0]], a->vertices[a->edges[i][1]],
											  b->vertices[b->edges[j][0]], b->vertices[b->edges[j][1]]);
			best = d < best ? d : best;
		}
	}
	return best;
}

static double RefPlaneDepth(const RefShape* plane, const RefShape* shape)
{
	double lowest = INFINITY;
	for (int i = 0; i < shape->vertexCount; ++i)
	{
		double s = DDot(plane->normal, shape->vertices[i]);
		lowest = s < lowest ? s : lowest;
	}
	return lowest - shape->radius - plane->offset;
}

static double RefDistance(const cd3Shape* sa, const cd3Shape* sb)
{
	RefShape a = MakeRef(sa), b = MakeRef(sb);
	double d;
	if (a.isPlane && b.isPlane)
	{
		bool opposite = a.normal.x == -b.normal.x && a.normal.y == -b.normal.y && a.normal.z == -b.normal.z;
		d = opposite ? -(a.offset + b.offset) : 0.0;
	}
	else if (a.isPlane)
	{
		d = RefPlaneDepth(&a, &b);
	}
	else if (b.isPlane)
	{
		d = RefPlaneDepth(&b, &a);
	}
	else
	{
		d = RefCoreDistance(&a, &b) - a.radius - b.radius;
	}
	return d > 0.0 ? d : 0.0;
}

/* Absolute tolerance for shapes of size ~1-5 near the origin: float round-off in the shapes
 * themselves (box rotations, transforms) and in GJK's termination. */
#if CD_DOUBLE
#define TOLERANCE 1e-9
#else
#define TOLERANCE 2e-5
#endif

static bool g_printedCase = false;

static void ReportCase(bool ok, const cd3Shape* a, const cd3Shape* b)
{
	if (!ok && !g_printedCase && g_testFailures <= TEST_MAX_PRINTED_FAILURES)
	{
		PrintShape("a", a);
		PrintShape("b", b);
	}
}

/* The result is finite, its witnesses lie on their shapes, |pointA - pointB| == distance, and
 * an overlap reports the same point twice. */
static bool CheckResult(const cd3Shape* a, const cd3Shape* b, cd3ClosestPoints r)
{
	RefShape ra = MakeRef(a), rb = MakeRef(b);
	DVec pa = DFrom(r.pointA), pb = DFrom(r.pointB);
	double distance = (double)r.distance;
	bool finite = isfinite(distance) && isfinite(pa.x) && isfinite(pa.y) && isfinite(pa.z) &&
				  isfinite(pb.x) && isfinite(pb.y) && isfinite(pb.z);
	TEST_CHECKF(finite, "non-finite result %g", distance);
	if (!finite)
	{
		return false;
	}
	double onA = RefPointShapeDistance(&ra, pa), onB = RefPointShapeDistance(&rb, pb);
	double gap = DLength(DSub(pb, pa));
	/* Witnesses of half-spaces can lie far out (where two planes meet): relative round-off. */
	double magnitude = DLength(pa) > DLength(pb) ? DLength(pa) : DLength(pb);
	double tolerance = TOLERANCE * (magnitude > 1.0 ? magnitude : 1.0);
	bool ok = distance >= 0.0 && onA <= tolerance && onB <= tolerance && fabs(gap - distance) <= tolerance;
	TEST_CHECKF(ok,
				"witness off: distance %.9g, pointA off A by %.3g, pointB off B by %.3g, |pB - pA| = %.9g",
				distance, onA, onB, gap);
	bool same = distance > 0.0 || cd3VecEqual(r.pointA, r.pointB);
	TEST_CHECKF(same, "overlap reported with different points, |pB - pA| = %.3g", gap);

	/* Apart, pointB is the point of b closest to pointA (unique on a convex set): a cross-check
	 * with the library's own closest-point routines. The tolerance is wider than for the
	 * distance: near a tie between features (a point almost over an edge's end) the distance is
	 * flat while the witness slides, so GJK's stopping point moves it more than the distance. */
	bool closest = true;
	if (distance > 10.0 * TOLERANCE)
	{
		double moved = DLength(DSub(DFrom(cd3ClosestPointOnShape(b, r.pointA)), pb));
		closest = moved <= 100.0 * TOLERANCE;
		TEST_CHECKF(closest, "pointB is %.3g from the point of b closest to pointA", moved);
	}
	return ok && same && closest;
}

static bool CheckFinitePoints(cd3ClosestPoints r)
{
	return cd3IsValidVec(r.pointA) && cd3IsValidVec(r.pointB);
}

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
static cd3Shape Sphere(cdReal x, cdReal y, cdReal z, cdReal radius)
{
	cd3Shape s;
	memset(&s, 0, sizeof(s));
	s.type = CD3_SHAPE_SPHERE;
	s.sphere.center = cd3MakeVec(x, y, z);
	s.sphere.radius = radius;
	return s;
}

static cd3Shape Aabb(cd3Vec lo, cd3Vec hi)
{
	cd3Shape s;
	memset(&s, 0, sizeof(s));
	s.type = CD3_SHAPE_AABB;
	s.aabb.min = lo;
	s.aabb.max = hi;
	return s;
}

static cd3Shape Capsule(cd3Vec p1, cd3Vec p2, cdReal radius)
{
	cd3Shape s;
	memset(&s, 0, sizeof(s));
	s.type = CD3_SHAPE_CAPSULE;
	s.capsule.p1 = p1;
	s.capsule.p2 = p2;
	s.capsule.radius = radius;
	return s;
}

static cd3Shape Segment(cd3Vec p1, cd3Vec p2)
{
	cd3Shape s;
	memset(&s, 0, sizeof(s));
	s.type = CD3_SHAPE_SEGMENT;
	s.segment.p1 = p1;
	s.segment.p2 = p2;
	return s;
}

static cd3Shape Triangle(cd3Vec a, cd3Vec b, cd3Vec c)
{
	cd3Shape s;
	memset(&s, 0, sizeof(s));
	s.type = CD3_SHAPE_TRIANGLE;
	s.triangle.a = a;
	s.triangle.b = b;
	s.triangle.c = c;
	return s;
}

static cd3Shape Plane(cd3Vec normal, cdReal offset)
{
	cd3Shape s;
	memset(&s, 0, sizeof(s));
	s.type = CD3_SHAPE_PLANE;
	s.plane.normal = normal;
	s.plane.offset = offset;
	return s;
}

static cd3Shape Box(cd3Vec center, cd3Vec half, cd3Quat rotation)
{
	cd3Shape s;
	memset(&s, 0, sizeof(s));
	s.type = CD3_SHAPE_BOX;
	s.box.center = center;
	s.box.halfExtents = half;
	s.box.rotation = rotation;
	return s;
}

#define V(x, y, z) cd3MakeVec(CD_R(x), CD_R(y), CD_R(z))
#define NEAR_VEC(a, b)                                                                                       \
	do                                                                                                       \
	{                                                                                                        \
		TEST_CHECK_NEAR((a).x, (b).x, TOLERANCE);                                                            \
		TEST_CHECK_NEAR((a).y, (b).y, TOLERANCE);                                                            \
		TEST_CHECK_NEAR((a).z, (b).z, TOLERANCE);                                                            \
	} while (0)

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
static void CheckAgainstReference(const cd3Shape* a, const cd3Shape* b, double tolerance, const char* what)
{
	double expected = RefDistance(a, b);
	cd3ClosestPoints r = cd3Distance(a, b);
	cd3ClosestPoints s = cd3Distance(b, a);
	bool ok =
		fabs((double)r.distance - expected) <= tolerance && fabs((double)s.distance - expected) <= tolerance;
	TEST_CHECKF(ok, "%s: distance %.9g and %.9g (swapped), reference %.9g, tolerance %.3g", what,
				(double)r.distance, (double)s.distance, expected, tolerance);
	if (!ok)
	{
		PrintShape("a", a);
		PrintShape("b", b);
	}
}

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

int main(void)
{
	TEST_RUN(TestSpheres);
	TEST_RUN(TestBoxesAndAabbs);
	TEST_RUN(TestCapsulesSegmentsTriangles);
	TEST_RUN(TestPlanes);
	TEST_RUN(TestHalfSpaceWitnesses);
	TEST_RUN(TestScales);
	TEST_RUN(TestRandomPairs);
	TEST_RUN(TestExtremeScales);
	TEST_RUN(TestThinBoxesAndLongSegments);
	TEST_RUN(TestHullsAtLargeScale);
	TEST_RUN(TestHullVertexCounts);
	TEST_RUN(TestDistanceStatus);
	TEST_RUN(TestPointInsideLongBox);
	TEST_RUN(TestCacheAgrees);
	TEST_RUN(TestCacheSavesIterations);
	return TEST_SUMMARY();
}
