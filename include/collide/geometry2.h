/* collide: 2D shapes, their builders, validators and bounds. */
#ifndef COLLIDE_GEOMETRY2_H
#define COLLIDE_GEOMETRY2_H

#include "collide/math2.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Most vertices a cd2Polygon holds. */
#define CD2_MAX_POLYGON_VERTICES 8

/* Axis-aligned rectangle, closed. A zero-size box is a point and is valid. */
typedef struct cd2Aabb
{
	cd2Vec min, max;
} cd2Aabb;

/* Solid disk. radius 0 is a point. */
typedef struct cd2Circle
{
	cd2Vec center;
	cdReal radius;
} cd2Circle;

/* Solid capsule (stadium): the points within `radius` of segment p1-p2. */
typedef struct cd2Capsule
{
	cd2Vec p1, p2;
	cdReal radius;
} cd2Capsule;

/* Line segment (not solid). p1 == p2 is a point. */
typedef struct cd2Segment
{
	cd2Vec p1, p2;
} cd2Segment;

/* Solid oriented rectangle: center + rotation * (local point with |local| <= halfExtents). */
typedef struct cd2Box
{
	cd2Vec center;
	cd2Vec halfExtents;
	cd2Rot rotation;
} cd2Box;

/* Solid convex polygon with counter-clockwise vertices and outward unit edge normals:
 * normals[i] belongs to the edge vertices[i] -> vertices[(i + 1) % count]. Build it with
 * cd2MakePolygon (or cd2MakeBoxPolygon); never fill it by hand unless you keep these rules.
 * A rounded polygon is the set of points within `radius` of the core polygon the vertices span
 * (radius 0: a sharp polygon; cd2MakeRoundedPolygon sets it). */
typedef struct cd2Polygon
{
	cd2Vec vertices[CD2_MAX_POLYGON_VERTICES];
	cd2Vec normals[CD2_MAX_POLYGON_VERTICES];
	cd2Vec centroid;
	int count;
	cdReal radius;
} cd2Polygon;

/* Ray: the points origin + t * translation for t in [0, 1]. */
typedef struct cd2Ray
{
	cd2Vec origin;
	cd2Vec translation;
} cd2Ray;

/* The shape types in canonical order: pair functions name their two shapes in this order. */
typedef enum cd2ShapeType
{
	CD2_SHAPE_CIRCLE,
	CD2_SHAPE_CAPSULE,
	CD2_SHAPE_AABB,
	CD2_SHAPE_BOX,
	CD2_SHAPE_POLYGON,
	CD2_SHAPE_SEGMENT,
	CD2_SHAPE_TYPE_COUNT
} cd2ShapeType;

/* A tagged shape for the generic dispatchers (cd2Overlap, cd2Raycast, cd2Distance, ...). */
typedef struct cd2Shape
{
	cd2ShapeType type;
	union
	{
		cd2Circle circle;
		cd2Capsule capsule;
		cd2Aabb aabb;
		cd2Box box;
		cd2Polygon polygon;
		cd2Segment segment;
	};
} cd2Shape;

/* Lower-case name of a shape type ("circle", "capsule", ...), "unknown" when out of range. */
CD_API const char* cd2GetShapeTypeName(cd2ShapeType type);

CD_API cd2Shape cd2MakeCircleShape(cd2Circle circle);
CD_API cd2Shape cd2MakeCapsuleShape(cd2Capsule capsule);
CD_API cd2Shape cd2MakeAabbShape(cd2Aabb aabb);
CD_API cd2Shape cd2MakeBoxShape(cd2Box box);
CD_API cd2Shape cd2MakePolygonShape(const cd2Polygon* polygon);
CD_API cd2Shape cd2MakeSegmentShape(cd2Segment segment);

/* ---- polygon builders ----------------------------------------------------------------------
 * cd2MakePolygon computes the convex hull of `points`, welds points closer than the weld
 * tolerance (CD2_POLYGON_WELD_TOLERANCE, see docs/API.md), drops collinear points, and orders
 * the result counter-clockwise. It fails, leaving *out untouched, with:
 *   CD_ERROR_INVALID_ARGUMENT  points or out is NULL, or count < 0
 *   CD_ERROR_NOT_FINITE        a coordinate is NaN or infinite
 *   CD_ERROR_TOO_MANY_POINTS   count > CD2_MAX_POLYGON_VERTICES, or a hull with more vertices
 *   CD_ERROR_DEGENERATE        fewer than 3 distinct points, or all points collinear
 *   CD_ERROR_OUT_OF_RANGE      a coordinate beyond +-CD2_POLYGON_MAX_COORDINATE */
CD_API cdResult cd2MakePolygon(const cd2Vec* points, int count, cd2Polygon* out);

/* Largest |coordinate| cd2MakePolygon accepts: the documented range of the library (docs/API.md,
 * "Semantics"), 1e9 in float and 1e30 in double. Beyond it the hull's round-off (64 epsilons of
 * the coordinates) can drop an input point by more than the weld tolerance (a point 1.3e5 outside
 * a polygon built from points up to 7e9 in float). */
#if CD_DOUBLE
#define CD2_POLYGON_MAX_COORDINATE CD_R(1e30)
#else
#define CD2_POLYGON_MAX_COORDINATE CD_R(1e9)
#endif

/* Weld and collinearity tolerance of cd2MakePolygon at ordinary coordinates: half a linear slop. */
#define CD2_POLYGON_WELD_TOLERANCE (CD_R(0.5) * CD_LINEAR_SLOP)

/* The tolerance cd2MakePolygon uses for points whose largest |coordinate| is maxAbsCoordinate:
 * max(CD2_POLYGON_WELD_TOLERANCE, 64 * CD_REAL_EPSILON * maxAbsCoordinate), so that welding and
 * collinearity still make sense where round-off exceeds the slop (huge coordinates). Points
 * closer than this are welded; a vertex closer than this to the line through its neighbours is
 * dropped. */
CD_API cdReal cd2GetPolygonWeldTolerance(cdReal maxAbsCoordinate);

/* The 4-vertex polygon of an oriented box (never fails for a valid box with non-zero area;
 * returns CD_ERROR_DEGENERATE for a zero-area box and the validator's errors otherwise). No
 * welding: boxes smaller than the weld tolerance work. The one exception is a box so small
 * against its center's coordinates that its corners round together in cdReal: that box is
 * CD_ERROR_DEGENERATE too, never a broken polygon. */
CD_API cdResult cd2MakeBoxPolygon(cd2Box box, cd2Polygon* out);

/* cd2MakePolygon with a rounding radius (a finite radius >= 0, else CD_ERROR_NOT_FINITE or
 * CD_ERROR_NEGATIVE_SIZE, *out untouched). The vertices are those of the core polygon. */
CD_API cdResult cd2MakeRoundedPolygon(const cd2Vec* points, int count, cdReal radius, cd2Polygon* out);

/* cd2MakeBoxPolygon with a rounding radius: the box's corners rounded by `radius` (the core box is
 * the given box, so the rounded box reaches `radius` beyond it). */
CD_API cdResult cd2MakeRoundedBoxPolygon(cd2Box box, cdReal radius, cd2Polygon* out);

/* ---- validators ----------------------------------------------------------------------------
 * Each rejects NaN/Inf anywhere, negative radii and sizes, non-unit rotations. Zero sizes are
 * valid. cd2IsValidPolygon also checks count, convexity, CCW order, unit normals and a finite
 * radius >= 0. */
CD_API bool cd2IsValidAabb(cd2Aabb aabb); /* also min <= max on both axes */
CD_API bool cd2IsValidCircle(cd2Circle circle);
CD_API bool cd2IsValidCapsule(cd2Capsule capsule);
CD_API bool cd2IsValidSegment(cd2Segment segment);
CD_API bool cd2IsValidBox(cd2Box box);
CD_API bool cd2IsValidPolygon(const cd2Polygon* polygon);
CD_API bool cd2IsValidRay(cd2Ray ray);
CD_API bool cd2IsValidShape(const cd2Shape* shape);

/* Like cd2IsValidShape, with the reason (see cd3ValidateShape). */
CD_API cdResult cd2ValidateShape(const cd2Shape* shape);

/* ---- bounds ------------------------------------------------------------------------------- */
CD_API cd2Aabb cd2ComputeCircleAabb(cd2Circle circle);
CD_API cd2Aabb cd2ComputeCapsuleAabb(cd2Capsule capsule);
CD_API cd2Aabb cd2ComputeBoxAabb(cd2Box box);
CD_API cd2Aabb cd2ComputePolygonAabb(const cd2Polygon* polygon);
CD_API cd2Aabb cd2ComputeSegmentAabb(cd2Segment segment);
CD_API cd2Aabb cd2ComputeShapeAabb(const cd2Shape* shape);

/* ---- AABB helpers ------------------------------------------------------------------------- */
static inline cd2Aabb cd2AabbUnion(cd2Aabb a, cd2Aabb b)
{
	cd2Aabb c = {cd2Min(a.min, b.min), cd2Max(a.max, b.max)};
	return c;
}

static inline cd2Vec cd2AabbCenter(cd2Aabb a)
{
	return cd2Scale(CD_R(0.5), cd2Add(a.min, a.max));
}

static inline cd2Vec cd2AabbHalfExtents(cd2Aabb a)
{
	return cd2Scale(CD_R(0.5), cd2Sub(a.max, a.min));
}

static inline cdReal cd2AabbPerimeter(cd2Aabb a)
{
	return CD_R(2.0) * ((a.max.x - a.min.x) + (a.max.y - a.min.y));
}

static inline bool cd2AabbContains(cd2Aabb outer, cd2Aabb inner)
{
	return outer.min.x <= inner.min.x && outer.min.y <= inner.min.y && inner.max.x <= outer.max.x &&
		   inner.max.y <= outer.max.y;
}

static inline cd2Aabb cd2AabbInflate(cd2Aabb a, cdReal margin)
{
	cd2Vec m = {margin, margin};
	cd2Aabb b = {cd2Sub(a.min, m), cd2Add(a.max, m)};
	return b;
}

/* ---- mass properties (src/geometry/mass2.c) ------------------------------------------------
 * Mass, centre of mass and rotational inertia about the centre of mass, for a uniform density
 * (kg per square length unit). A segment has no area: mass 0 at its midpoint. */
typedef struct cd2MassData
{
	cdReal mass;
	cd2Vec center;
	cdReal rotationalInertia; /* about center */
} cd2MassData;

CD_API cd2MassData cd2ComputeCircleMass(cd2Circle circle, cdReal density);
/* A rectangle plus two half disks (each placed with the parallel-axis theorem). */
CD_API cd2MassData cd2ComputeCapsuleMass(cd2Capsule capsule, cdReal density);
CD_API cd2MassData cd2ComputeAabbMass(cd2Aabb aabb, cdReal density);
CD_API cd2MassData cd2ComputeBoxMass(cd2Box box, cdReal density);
/* Triangle fan; a rounding radius adds the exact rounded rim (edge strips and corner sectors). */
CD_API cd2MassData cd2ComputePolygonMass(const cd2Polygon* polygon, cdReal density);
CD_API cd2MassData cd2ComputeShapeMass(const cd2Shape* shape, cdReal density);

/* Former names (before the naming rule of CONTRIBUTING.md), kept as aliases for one release so
 * that code written against them still builds; tests/check_names.py accepts exactly these. */
#define cd2ShapeTypeName cd2GetShapeTypeName

#ifdef __cplusplus
}
#endif

#endif
