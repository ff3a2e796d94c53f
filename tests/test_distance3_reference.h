/* The double-precision brute-force reference of cd3Distance's tests (test_distance3.c,
 * test_distance3_scales.c: two programs, so that each stays within the sanitizer build's time
 * budget) and the shape constructors of their exact cases. */
#ifndef COLLIDE_TEST_DISTANCE3_REFERENCE_H
#define COLLIDE_TEST_DISTANCE3_REFERENCE_H

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

static inline DVec DMake(double x, double y, double z)
{
	DVec v = {x, y, z};
	return v;
}
static inline DVec DFrom(cd3Vec v)
{
	return DMake((double)v.x, (double)v.y, (double)v.z);
}
static inline DVec DAdd(DVec a, DVec b)
{
	return DMake(a.x + b.x, a.y + b.y, a.z + b.z);
}
static inline DVec DSub(DVec a, DVec b)
{
	return DMake(a.x - b.x, a.y - b.y, a.z - b.z);
}
static inline DVec DScale(double s, DVec a)
{
	return DMake(s * a.x, s * a.y, s * a.z);
}
static inline double DDot(DVec a, DVec b)
{
	return a.x * b.x + a.y * b.y + a.z * b.z;
}
static inline DVec DCross(DVec a, DVec b)
{
	return DMake(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline double DLength(DVec a)
{
	return sqrt(DDot(a, a));
}

/* q v q* for a (nearly) unit quaternion, in double. */
static inline DVec DRotate(cd3Quat q, DVec v)
{
	DVec u = DMake((double)q.x, (double)q.y, (double)q.z);
	DVec t = DScale(2.0, DCross(u, v));
	return DAdd(DAdd(v, DScale((double)q.w, t)), DCross(u, t));
}

static inline double PointSegmentDistance(DVec p, DVec a, DVec b)
{
	DVec e = DSub(b, a);
	double ee = DDot(e, e);
	double t = ee > 0.0 ? DDot(DSub(p, a), e) / ee : 0.0;
	t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
	return DLength(DSub(p, DAdd(a, DScale(t, e))));
}

/* Distance from p to the interior of triangle a-b-c (closed), INFINITY when p does not project
 * into it or when its plane is no closer than `bound`. The reference takes the edges and vertices
 * of a shape from its own lists (every triangle edge is a shape edge, or a diagonal inside a face
 * that its two triangles cover), so the triangle needs only its face. */
static inline double PointTriangleInteriorDistance(DVec p, DVec a, DVec b, DVec c, double bound)
{
	DVec n = DCross(DSub(b, a), DSub(c, a));
	double nn = DDot(n, n);
	if (!(nn > 0.0))
	{
		return INFINITY;
	}
	DVec ap = DSub(p, a);
	double planar = fabs(DDot(n, ap)) / sqrt(nn);
	if (!(planar < bound))
	{
		return INFINITY;
	}
	double s = DDot(n, ap) / nn;
	DVec q = DSub(p, DScale(s, n));
	if (DDot(n, DCross(DSub(b, a), DSub(q, a))) >= 0.0 && DDot(n, DCross(DSub(c, b), DSub(q, b))) >= 0.0 &&
		DDot(n, DCross(DSub(a, c), DSub(q, c))) >= 0.0)
	{
		return planar;
	}
	return INFINITY;
}

/* Distance between segments p1-q1 and p2-q2 at an interior critical point of both (INFINITY when
 * there is none): the minimum over endpoints is the reference's point-to-core distances. */
static inline double SegmentSegmentInteriorDistance(DVec p1, DVec q1, DVec p2, DVec q2)
{
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
			return DLength(DSub(DAdd(p1, DScale(s, d1)), DAdd(p2, DScale(t, d2))));
		}
	}
	return INFINITY;
}

/* Segment p-q crosses the plane of triangle a-b-c strictly, inside the triangle. */
static inline bool SegmentPiercesTriangle(DVec p, DVec q, DVec a, DVec b, DVec c)
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

/* Fills *out in place: a RefShape is kilobytes, and copies of it cost the sanitizer build much of
 * this test's time. */
static inline void MakeRef(const cd3Shape* shape, RefShape* out)
{
	RefShape* r = out;
	memset(r, 0, offsetof(RefShape, vertices));
	switch (shape->type)
	{
		case CD3_SHAPE_SPHERE:
			r->vertices[0] = DFrom(shape->sphere.center);
			r->vertexCount = 1;
			r->radius = (double)shape->sphere.radius;
			break;
		case CD3_SHAPE_CAPSULE:
			r->vertices[0] = DFrom(shape->capsule.p1);
			r->vertices[1] = DFrom(shape->capsule.p2);
			r->vertexCount = 2;
			r->edges[0][0] = 0;
			r->edges[0][1] = 1;
			r->edgeCount = 1;
			r->radius = (double)shape->capsule.radius;
			break;
		case CD3_SHAPE_SEGMENT:
			r->vertices[0] = DFrom(shape->segment.p1);
			r->vertices[1] = DFrom(shape->segment.p2);
			r->vertexCount = 2;
			r->edges[0][0] = 0;
			r->edges[0][1] = 1;
			r->edgeCount = 1;
			break;
		case CD3_SHAPE_TRIANGLE:
			r->vertices[0] = DFrom(shape->triangle.a);
			r->vertices[1] = DFrom(shape->triangle.b);
			r->vertices[2] = DFrom(shape->triangle.c);
			r->vertexCount = 3;
			for (int i = 0; i < 3; ++i)
			{
				r->edges[i][0] = i;
				r->edges[i][1] = (i + 1) % 3;
				r->triangles[0][i] = i;
			}
			r->edgeCount = 3;
			r->triangleCount = 1;
			break;
		case CD3_SHAPE_AABB:
		case CD3_SHAPE_BOX:
		{
			r->solidBox = true;
			if (shape->type == CD3_SHAPE_AABB)
			{
				DVec lo = DFrom(shape->aabb.min), hi = DFrom(shape->aabb.max);
				r->center = DScale(0.5, DAdd(lo, hi));
				r->halfExtents = DScale(0.5, DSub(hi, lo));
				r->axes[0] = DMake(1.0, 0.0, 0.0);
				r->axes[1] = DMake(0.0, 1.0, 0.0);
				r->axes[2] = DMake(0.0, 0.0, 1.0);
			}
			else
			{
				r->center = DFrom(shape->box.center);
				r->halfExtents = DFrom(shape->box.halfExtents);
				r->axes[0] = DRotate(shape->box.rotation, DMake(1.0, 0.0, 0.0));
				r->axes[1] = DRotate(shape->box.rotation, DMake(0.0, 1.0, 0.0));
				r->axes[2] = DRotate(shape->box.rotation, DMake(0.0, 0.0, 1.0));
			}
			for (int i = 0; i < 8; ++i)
			{
				DVec p = r->center;
				p = DAdd(p, DScale((i & 1) ? r->halfExtents.x : -r->halfExtents.x, r->axes[0]));
				p = DAdd(p, DScale((i & 2) ? r->halfExtents.y : -r->halfExtents.y, r->axes[1]));
				p = DAdd(p, DScale((i & 4) ? r->halfExtents.z : -r->halfExtents.z, r->axes[2]));
				r->vertices[i] = p;
			}
			r->vertexCount = 8;
			memcpy(r->edges, g_boxEdges, sizeof(g_boxEdges));
			memcpy(r->triangles, g_boxTriangles, sizeof(g_boxTriangles));
			r->edgeCount = 12;
			r->triangleCount = 12;
			break;
		}
		case CD3_SHAPE_PLANE:
			r->isPlane = true;
			r->normal = DFrom(shape->plane.normal);
			r->offset = (double)shape->plane.offset;
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
			r->solidHull = true;
			r->vertexCount = hull->vertexCount;
			for (int i = 0; i < hull->vertexCount; ++i)
			{
				r->vertices[i] = DAdd(DRotate(t.q, DFrom(hull->vertices[i])), DFrom(t.p));
			}
			for (int e = 0; e < hull->edgeCount; ++e)
			{
				if (e < hull->edges[e].twin)
				{
					r->edges[r->edgeCount][0] = hull->edges[e].origin;
					r->edges[r->edgeCount][1] = hull->edges[hull->edges[e].next].origin;
					++r->edgeCount;
				}
			}
			for (int f = 0; f < hull->faceCount; ++f)
			{
				int e0 = hull->faceEdges[f];
				int first = hull->edges[e0].origin;
				for (int e = hull->edges[e0].next; hull->edges[e].next != e0; e = hull->edges[e].next)
				{
					r->triangles[r->triangleCount][0] = first;
					r->triangles[r->triangleCount][1] = hull->edges[e].origin;
					r->triangles[r->triangleCount][2] = hull->edges[hull->edges[e].next].origin;
					++r->triangleCount;
				}
				DVec n = DRotate(t.q, DFrom(hull->planes[f].normal));
				n = DScale(1.0 / DLength(n), n);
				r->planeNormals[r->planeCount] = n;
				r->planeOffsets[r->planeCount] = DDot(n, r->vertices[first]);
				++r->planeCount;
			}
			break;
		}
		default:
			break;
	}
}

static inline bool RefPointInBox(const RefShape* r, DVec p)
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

/* Distance from a point to the core of a finite shape (0 inside a solid box), or `bound` when the
 * core is no closer than that (a caller's best so far: faces farther than it are skipped). */
static inline double RefPointCoreDistance(const RefShape* r, DVec p, double bound)
{
	if (RefPointInBox(r, p))
	{
		return 0.0;
	}
	double best = bound;
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
		double d =
			PointTriangleInteriorDistance(p, r->vertices[t[0]], r->vertices[t[1]], r->vertices[t[2]], best);
		best = d < best ? d : best;
	}
	return best;
}

/* Distance from a point to the shape (0 inside a solid). */
static inline double RefPointShapeDistance(const RefShape* r, DVec p)
{
	if (r->isPlane)
	{
		double s = DDot(r->normal, p) - r->offset;
		return s > 0.0 ? s : 0.0;
	}
	double d = RefPointCoreDistance(r, p, INFINITY) - r->radius;
	return d > 0.0 ? d : 0.0;
}

static inline bool AnyEdgePierces(const RefShape* edges, const RefShape* triangles)
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
static inline double RefCoreDistance(const RefShape* a, const RefShape* b)
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
		double d = RefPointCoreDistance(b, a->vertices[i], best);
		best = d < best ? d : best;
	}
	for (int i = 0; i < b->vertexCount; ++i)
	{
		double d = RefPointCoreDistance(a, b->vertices[i], best);
		best = d < best ? d : best;
	}
	for (int i = 0; i < a->edgeCount; ++i)
	{
		for (int j = 0; j < b->edgeCount; ++j)
		{
			double d =
				SegmentSegmentInteriorDistance(a->vertices[a->edges[i][0]], a->vertices[a->edges[i][1]],
											   b->vertices[b->edges[j][0]], b->vertices[b->edges[j][1]]);
			best = d < best ? d : best;
		}
	}
	return best;
}

static inline double RefPlaneDepth(const RefShape* plane, const RefShape* shape)
{
	double lowest = INFINITY;
	for (int i = 0; i < shape->vertexCount; ++i)
	{
		double s = DDot(plane->normal, shape->vertices[i]);
		lowest = s < lowest ? s : lowest;
	}
	return lowest - shape->radius - plane->offset;
}

static inline double RefDistance(const cd3Shape* sa, const cd3Shape* sb)
{
	RefShape a, b;
	MakeRef(sa, &a);
	MakeRef(sb, &b);
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

static inline void ReportCase(bool ok, const cd3Shape* a, const cd3Shape* b)
{
	if (!ok && !g_printedCase && g_testFailures <= TEST_MAX_PRINTED_FAILURES)
	{
		PrintShape("a", a);
		PrintShape("b", b);
	}
}

/* The result is finite, its witnesses lie on their shapes, |pointA - pointB| == distance, and
 * an overlap reports the same point twice. */
static inline bool CheckResult(const cd3Shape* a, const cd3Shape* b, cd3ClosestPoints r)
{
	RefShape ra, rb;
	MakeRef(a, &ra);
	MakeRef(b, &rb);
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

static inline bool CheckFinitePoints(cd3ClosestPoints r)
{
	return cd3IsValidVec(r.pointA) && cd3IsValidVec(r.pointB);
}

/* cd3Distance in both orders within `tolerance` of the reference. */
static inline void CheckAgainstReference(const cd3Shape* a, const cd3Shape* b, double tolerance,
										 const char* what)
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

/* ---- exact-case shapes ------------------------------------------------------------------------------- */
static inline cd3Shape Sphere(cdReal x, cdReal y, cdReal z, cdReal radius)
{
	cd3Shape s;
	memset(&s, 0, sizeof(s));
	s.type = CD3_SHAPE_SPHERE;
	s.sphere.center = cd3MakeVec(x, y, z);
	s.sphere.radius = radius;
	return s;
}

static inline cd3Shape Aabb(cd3Vec lo, cd3Vec hi)
{
	cd3Shape s;
	memset(&s, 0, sizeof(s));
	s.type = CD3_SHAPE_AABB;
	s.aabb.min = lo;
	s.aabb.max = hi;
	return s;
}

static inline cd3Shape Capsule(cd3Vec p1, cd3Vec p2, cdReal radius)
{
	cd3Shape s;
	memset(&s, 0, sizeof(s));
	s.type = CD3_SHAPE_CAPSULE;
	s.capsule.p1 = p1;
	s.capsule.p2 = p2;
	s.capsule.radius = radius;
	return s;
}

static inline cd3Shape Segment(cd3Vec p1, cd3Vec p2)
{
	cd3Shape s;
	memset(&s, 0, sizeof(s));
	s.type = CD3_SHAPE_SEGMENT;
	s.segment.p1 = p1;
	s.segment.p2 = p2;
	return s;
}

static inline cd3Shape Triangle(cd3Vec a, cd3Vec b, cd3Vec c)
{
	cd3Shape s;
	memset(&s, 0, sizeof(s));
	s.type = CD3_SHAPE_TRIANGLE;
	s.triangle.a = a;
	s.triangle.b = b;
	s.triangle.c = c;
	return s;
}

static inline cd3Shape Plane(cd3Vec normal, cdReal offset)
{
	cd3Shape s;
	memset(&s, 0, sizeof(s));
	s.type = CD3_SHAPE_PLANE;
	s.plane.normal = normal;
	s.plane.offset = offset;
	return s;
}

static inline cd3Shape Box(cd3Vec center, cd3Vec half, cd3Quat rotation)
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

#endif
