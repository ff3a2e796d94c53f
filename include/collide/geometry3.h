/* collide: 3D shapes, their validators and their bounds. */
#ifndef COLLIDE_GEOMETRY3_H
#define COLLIDE_GEOMETRY3_H

#include "collide/math3.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Axis-aligned box, closed: the points with min <= p <= max. A zero-size box (min == max) is a
 * point and is valid. */
typedef struct cd3Aabb
{
	cd3Vec min, max;
} cd3Aabb;

/* Solid ball. radius 0 is a point. */
typedef struct cd3Sphere
{
	cd3Vec center;
	cdReal radius;
} cd3Sphere;

/* Solid capsule: the points within `radius` of segment p1-p2. p1 == p2 is a sphere. */
typedef struct cd3Capsule
{
	cd3Vec p1, p2;
	cdReal radius;
} cd3Capsule;

/* Line segment (not solid: it has no interior). p1 == p2 is a point. */
typedef struct cd3Segment
{
	cd3Vec p1, p2;
} cd3Segment;

/* Triangle: the flat, two-sided, closed surface a-b-c. Its face normal is
 * normalize(cross(b - a, c - a)) (counter-clockwise winding faces the viewer). */
typedef struct cd3Triangle
{
	cd3Vec a, b, c;
} cd3Triangle;

/* Solid half-space: the points x with dot(normal, x) <= offset. normal is unit length. */
typedef struct cd3Plane
{
	cd3Vec normal;
	cdReal offset;
} cd3Plane;

/* Solid oriented box: center + rotation * (local point with |local| <= halfExtents). */
typedef struct cd3Box
{
	cd3Vec center;
	cd3Vec halfExtents;
	cd3Quat rotation;
} cd3Box;

/* Ray: the points origin + t * translation for t in [0, 1]. The translation's length is the
 * ray's reach, so a ray is also a swept point. */
typedef struct cd3Ray
{
	cd3Vec origin;
	cd3Vec translation;
} cd3Ray;

/* ---- convex hulls ---------------------------------------------------------------------------
 * A convex polyhedron: vertices, faces (each with its outward plane) and half-edge adjacency.
 * Built by cd3ComputeHull (quickhull) in one block from cdAlloc, released by cd3DestroyHull;
 * immutable afterwards, so one hull can be shared by many shapes and threads.
 *
 * Tolerances (the one statement of them; docs/HULLS.md links here), all relative to the point
 * cloud: with E the diagonal of the points' bounding box and eps = CD_REAL_EPSILON,
 * - quickhull visibility: 1e-12 E in the float build (double arithmetic on float input),
 *   1024 eps E in the double build;
 * - face merging: faces whose vertices lie within 4 eps E (4096 eps E in double) of a common
 *   plane are merged into one polygon;
 * - welding: points closer than 16 eps E (16384 eps E in double) are welded, and a set that flat
 *   (or collinear, or coincident) is CD_ERROR_DEGENERATE;
 * - cd3Hull_GetTolerance (validation, containment of the input): 64 eps E (65536 eps E in
 *   double) plus 16 eps times the largest coordinate; the hull contains every input point within
 *   it. */

/* At most this many input points (and so at most this many hull vertices). */
#define CD3_MAX_HULL_POINTS 16384

/* A half-edge bounds the face on its left seen from outside: next runs counter-clockwise
 * around that face, twin is the same edge seen from the neighbouring face. */
typedef struct cd3HullHalfEdge
{
	int32_t next;
	int32_t twin;
	int32_t origin; /* vertex the half-edge starts at */
	int32_t face;
} cd3HullHalfEdge;

typedef struct cd3Hull
{
	int vertexCount;
	int edgeCount; /* half-edges: twice the number of edges */
	int faceCount;
	const cd3Vec* vertices;
	const cd3HullHalfEdge* edges;
	const int32_t* faceEdges; /* one half-edge of each face */
	const cd3Plane* planes;	  /* each face's plane: unit outward normal, dot(normal, x) <= offset inside */
	cd3Vec centroid;		  /* centre of volume */
	cdReal volume;
	cd3Aabb bounds; /* tight bounds of the vertices */
	/* The vertices again as three columns (all x, then all y, then all z), each of
	 * CD3_HULL_COLUMN_STRIDE(vertexCount) entries, the padding repeating vertex 0: support
	 * searches read them four vertices at a time. Must match `vertices` (cd3ValidateHull checks);
	 * NULL in a hull assembled by hand, which the searches then read from `vertices`. */
	const cdReal* vertexColumns;
	/* What the pair queries would otherwise derive from the edges and faces on every call (the
	 * unique edges, their Gauss-map arcs, the face normals as columns), computed once by
	 * cd3ComputeHull for hulls of at most 16 faces and 32 edges; internal layout. Must match the
	 * hull (cd3ValidateHull checks); NULL for larger hulls and in a hull assembled by hand, whose
	 * queries then derive it per call. */
	const void* queryData;
} cd3Hull;

/* Entries per column of cd3Hull.vertexColumns: the vertex count rounded up to a multiple of 4. */
#define CD3_HULL_COLUMN_STRIDE(vertexCount) (((vertexCount) + 3) & ~3)

/* The convex hull of `count` points. On success *hull receives a new hull (free it with
 * cd3DestroyHull); on failure *hull is NULL and the result says why: CD_ERROR_INVALID_ARGUMENT
 * (NULL pointer, negative count), CD_ERROR_NOT_FINITE, CD_ERROR_TOO_MANY_POINTS (more than
 * CD3_MAX_HULL_POINTS), CD_ERROR_DEGENERATE (fewer than 4 points that are not coplanar within
 * the tolerance above), CD_ERROR_OUT_OF_RANGE (a needle or sheet beyond CD3_MAX_HULL_ASPECT_RATIO,
 * double build), CD_ERROR_OUT_OF_MEMORY. A hull it returns always passes cd3ValidateHull. */
CD_API cdResult cd3ComputeHull(const cd3Vec* points, int count, cd3Hull** hull);
CD_API void cd3DestroyHull(cd3Hull* hull);

/* The box |x| <= halfExtents as a hull (6 faces). Zero extents are CD_ERROR_DEGENERATE. These
 * builders return what cd3ComputeHull does, CD_ERROR_OUT_OF_RANGE included. */
CD_API cdResult cd3MakeBoxHull(cd3Vec halfExtents, cd3Hull** hull);

/* A cylinder about the y axis, |y| <= halfHeight, approximated by a prism of `segments`
 * (3..1024) sides whose vertices lie on the circle of the given radius. */
CD_API cdResult cd3MakeCylinderHull(cdReal halfHeight, cdReal radius, int segments, cd3Hull** hull);

/* A cone about the y axis: base circle (`segments` sides) at y = -halfHeight, apex at +halfHeight. */
CD_API cdResult cd3MakeConeHull(cdReal halfHeight, cdReal radius, int segments, cd3Hull** hull);

/* Distance within which the hull's vertices count as lying on its face planes (the value:
 * "Tolerances" above). */
CD_API cdReal cd3Hull_GetTolerance(const cd3Hull* hull);

/* Checks a hull: finite data, indices in range, vertexColumns (when not NULL) equal to the
 * vertices, a closed 2-manifold (twins consistent, each
 * face a cycle, V - E + F = 2), unit outward normals, planar convex faces, and every vertex
 * below every face plane, all within cd3Hull_GetTolerance. CD_OK, CD_ERROR_INVALID_ARGUMENT
 * (NULL, broken indices or topology), CD_ERROR_NOT_FINITE, CD_ERROR_NOT_NORMALIZED,
 * CD_ERROR_DEGENERATE (not convex, not planar, inward or empty) or CD_ERROR_OUT_OF_RANGE (beyond
 * CD3_MAX_HULL_ASPECT_RATIO). */
CD_API cdResult cd3ValidateHull(const cd3Hull* hull);

/* The shape types in canonical order: pair functions name their two shapes in this order. */
typedef enum cd3ShapeType
{
	CD3_SHAPE_SPHERE,
	CD3_SHAPE_CAPSULE,
	CD3_SHAPE_AABB,
	CD3_SHAPE_BOX,
	CD3_SHAPE_TRIANGLE,
	CD3_SHAPE_PLANE,
	CD3_SHAPE_SEGMENT,
	CD3_SHAPE_HULL,
	CD3_SHAPE_TYPE_COUNT
} cd3ShapeType;

/* A solid convex hull placed in the world: the points transform * x for x in *hull. The hull
 * is not owned: it must outlive every shape that refers to it. */
typedef struct cd3HullShape
{
	const cd3Hull* hull;
	cd3Transform transform;
} cd3HullShape;

/* A tagged shape for the generic dispatchers (cd3Overlap, cd3Raycast, cd3Distance, ...). */
typedef struct cd3Shape
{
	cd3ShapeType type;
	union
	{
		cd3Sphere sphere;
		cd3Capsule capsule;
		cd3Aabb aabb;
		cd3Box box;
		cd3Triangle triangle;
		cd3Plane plane;
		cd3Segment segment;
		cd3HullShape hull;
	};
} cd3Shape;

/* Lower-case name of a shape type ("sphere", "capsule", ...), "unknown" when out of range. */
CD_API const char* cd3GetShapeTypeName(cd3ShapeType type);

CD_API cd3Shape cd3MakeSphereShape(cd3Sphere sphere);
CD_API cd3Shape cd3MakeCapsuleShape(cd3Capsule capsule);
CD_API cd3Shape cd3MakeAabbShape(cd3Aabb aabb);
CD_API cd3Shape cd3MakeBoxShape(cd3Box box);
CD_API cd3Shape cd3MakeTriangleShape(cd3Triangle triangle);
CD_API cd3Shape cd3MakePlaneShape(cd3Plane plane);
CD_API cd3Shape cd3MakeSegmentShape(cd3Segment segment);
CD_API cd3Shape cd3MakeHullShape(const cd3Hull* hull, cd3Transform transform);

/* ---- supported range -----------------------------------------------------------------------
 * A rotated box whose longest extent exceeds CD3_MAX_ASPECT_RATIO times its thinnest
 * (a needle or a sheet) is beyond the supported range in the double build: there, its rotated
 * corners are known only to the round-off of its length, which is more than the double build's
 * tolerances allow across its width, and GJK's simplices along such a needle lose the accuracy
 * the queries promise. cd3IsValidBox / cd3ValidateShape refuse such a box with
 * CD_ERROR_OUT_OF_RANGE (largest half extent over smallest non-zero one; zero extents stay valid:
 * a box flat to exactly zero is the rectangle, segment or point it is), cd3ComputeHull and
 * cd3ValidateHull a hull beyond CD3_MAX_HULL_ASPECT_RATIO (diagonal of its bounds over its
 * smallest width across a face; 1e9: the contact manifolds are tested on needle hulls up to 1.2e8,
 * and GJK failed on hulls from 1.1e9). Queries are specified for shapes that validate. The float
 * build's round-off is coarse enough that its tolerances cover needles across the whole
 * coordinate range: no limit there (1e30, beyond the range's 1e18). */
#if CD_DOUBLE
#define CD3_MAX_ASPECT_RATIO 1e6
#define CD3_MAX_HULL_ASPECT_RATIO 1e9
#else
#define CD3_MAX_ASPECT_RATIO 1e30
#define CD3_MAX_HULL_ASPECT_RATIO 1e30
#endif

/* ---- validators ----------------------------------------------------------------------------
 * Each rejects NaN/Inf anywhere, negative radii and sizes, non-unit quaternions and normals
 * (tolerance as in cd3IsValidQuat). Zero sizes are valid (a point-like sphere, a flat box).
 * cd3IsValidBox also rejects a box beyond CD3_MAX_ASPECT_RATIO (see above). */
CD_API bool cd3IsValidAabb(cd3Aabb aabb); /* also min <= max on every axis */
CD_API bool cd3IsValidSphere(cd3Sphere sphere);
CD_API bool cd3IsValidCapsule(cd3Capsule capsule);
CD_API bool cd3IsValidSegment(cd3Segment segment);
CD_API bool cd3IsValidTriangle(cd3Triangle triangle); /* also rejects zero-area (degenerate) */
CD_API bool cd3IsValidPlane(cd3Plane plane);
CD_API bool cd3IsValidBox(cd3Box box);
CD_API bool cd3IsValidRay(cd3Ray ray);
CD_API bool cd3IsValidShape(const cd3Shape* shape);
/* A non-NULL hull that passes cd3ValidateHull (O(V F): validate once, not per query), a finite
 * transform with a unit quaternion. */
CD_API bool cd3IsValidHullShape(cd3HullShape hull);

/* Like cd3IsValidShape, with the reason: CD_ERROR_NOT_FINITE, CD_ERROR_NEGATIVE_SIZE,
 * CD_ERROR_NOT_NORMALIZED, CD_ERROR_DEGENERATE, CD_ERROR_INVALID_ARGUMENT (bad type, NULL hull,
 * or a hull whose topology is broken), CD_ERROR_OUT_OF_RANGE (a box beyond
 * CD3_MAX_ASPECT_RATIO, a hull beyond CD3_MAX_HULL_ASPECT_RATIO). */
CD_API cdResult cd3ValidateShape(const cd3Shape* shape);

/* ---- bounds ------------------------------------------------------------------------------- */
CD_API cd3Aabb cd3ComputeSphereAabb(cd3Sphere sphere);
CD_API cd3Aabb cd3ComputeCapsuleAabb(cd3Capsule capsule);
CD_API cd3Aabb cd3ComputeBoxAabb(cd3Box box);
CD_API cd3Aabb cd3ComputeTriangleAabb(cd3Triangle triangle);
CD_API cd3Aabb cd3ComputeSegmentAabb(cd3Segment segment);
/* A half-space is unbounded: its box spans -CD_REAL_MAX..CD_REAL_MAX except along an
 * axis-aligned normal, where the solid side is bounded by the offset. */
CD_API cd3Aabb cd3ComputePlaneAabb(cd3Plane plane);
CD_API cd3Aabb cd3ComputeHullShapeAabb(cd3HullShape hull); /* tight: O(vertices) */
CD_API cd3Aabb cd3ComputeShapeAabb(const cd3Shape* shape);

/* ---- mass properties ----------------------------------------------------------------------
 * Mass, centre of mass and inertia tensor about the centre of mass in world axes, for a uniform
 * density (kg per cubic length unit). Non-solid shapes (triangle, segment) and the unbounded
 * half-space have no volume: mass 0, zero inertia, centre at their centroid (the origin for a
 * half-space). */
typedef struct cd3MassData
{
	cdReal mass;
	cd3Vec center;
	cd3Mat33 inertia; /* about center, world axes */
} cd3MassData;

CD_API cd3MassData cd3ComputeSphereMass(cd3Sphere sphere, cdReal density);
/* A cylinder plus two hemispheres (each placed with the parallel-axis theorem). */
CD_API cd3MassData cd3ComputeCapsuleMass(cd3Capsule capsule, cdReal density);
CD_API cd3MassData cd3ComputeAabbMass(cd3Aabb aabb, cdReal density);
CD_API cd3MassData cd3ComputeBoxMass(cd3Box box, cdReal density);
/* Polyhedral mass properties: the hull as tetrahedra from an inner point, integrated exactly
 * (in double). */
CD_API cd3MassData cd3ComputeHullMass(cd3HullShape hull, cdReal density);
CD_API cd3MassData cd3ComputeShapeMass(const cd3Shape* shape, cdReal density);

/* ---- AABB helpers (inline: the broadphase lives on them) ---------------------------------- */
static inline cd3Aabb cd3AabbUnion(cd3Aabb a, cd3Aabb b)
{
	cd3Aabb c = {cd3Min(a.min, b.min), cd3Max(a.max, b.max)};
	return c;
}

static inline cd3Vec cd3AabbCenter(cd3Aabb a)
{
	return cd3Scale(CD_R(0.5), cd3Add(a.min, a.max));
}

static inline cd3Vec cd3AabbHalfExtents(cd3Aabb a)
{
	return cd3Scale(CD_R(0.5), cd3Sub(a.max, a.min));
}

static inline cdReal cd3AabbSurfaceArea(cd3Aabb a)
{
	cd3Vec d = cd3Sub(a.max, a.min);
	return CD_R(2.0) * (d.x * d.y + d.y * d.z + d.z * d.x);
}

/* true when `outer` contains `inner` (closed). */
static inline bool cd3AabbContains(cd3Aabb outer, cd3Aabb inner)
{
	return outer.min.x <= inner.min.x && outer.min.y <= inner.min.y && outer.min.z <= inner.min.z &&
		   inner.max.x <= outer.max.x && inner.max.y <= outer.max.y && inner.max.z <= outer.max.z;
}

/* The box grown by `margin` on every side. */
static inline cd3Aabb cd3AabbInflate(cd3Aabb a, cdReal margin)
{
	cd3Vec m = {margin, margin, margin};
	cd3Aabb b = {cd3Sub(a.min, m), cd3Add(a.max, m)};
	return b;
}

/* Former names (before the naming rule of CONTRIBUTING.md), kept as aliases for one release so
 * that code written against them still builds; tests/check_names.py accepts exactly these. */
#define cd3GetHullTolerance cd3Hull_GetTolerance
#define cd3ShapeTypeName cd3GetShapeTypeName

#ifdef __cplusplus
}
#endif

#endif
