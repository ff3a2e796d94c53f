/* collide: the 2D shape table and pair table (internal). Every shape type has one row in
 * CD2_SHAPE_TABLE and every unordered pair of shape types one row in CD2_PAIR_TABLE, in the
 * canonical order of cd2ShapeType (the order pair functions name their shapes). The generic
 * dispatchers expand them (dispatch2.c, raycast2.c, manifold2.c,
 * geometry/shapes2.c, geometry/mass2.c), so do the 2D world's contacts (dynamics/contact2.c)
 * and the matrix tests, so adding a shape
 * means writing its functions and adding its rows (CONTRIBUTING.md, "Adding a shape").
 *
 * Per shape, besides its table row: CD2_TYPE_<Name> (its cd2ShapeType) and CD2_ARG_OF_<Name>(s)
 * (how its functions take it from a const cd2Shape* s: the union member by value or by pointer).
 *
 * CD2_SHAPE_TABLE(X): X(Name, PointIn, ClosestPointOn, Raycast, TypeName, Validate, ComputeAabb,
 *                       ComputeMass, MakeCore, Radius)
 *   Name     the shape's name in function names (Circle);
 *   PointIn  the containment test, called PointIn(p, shape) (a shape with no inside names the
 *            dispatcher's tolerance test); ClosestPointOn(shape, p); Raycast(shape, ray, hit);
 *   TypeName the string of cd2GetShapeTypeName; Validate(shape) its cdResult check (static in
 *            geometry/shapes2.c); ComputeAabb(shape) its bounds (geometry/shapes2.c);
 *            ComputeMass(shape, density) its mass (geometry/mass2.c; zero mass for a segment);
 *   MakeCore the shape as GJK sees it (its support function: the points its support is taken
 *            over), MakeCore(shape, core) filling the
 *            core's points and count (support2.h: cd2MakeCore, and through it GJK, the casts and
 *            cd2Distance);
 *   Radius   the rounding radius as an lvalue macro, Radius(const cd2Shape* s) (support2.h), or
 *            NONE for a sharp shape: the core's radius, and what the casts strip (cast2.c).
 *   A column is expanded only in the file that holds its functions, so static helpers are fine.
 *
 * CD2_PAIR_TABLE(X): X(NameA, NameB, Overlap, Distance, Collide)
 *   Overlap   the pair's overlap test, Overlap(ARG_A(a), ARG_B(b));
 *   Distance  GJK: cd2Distance runs GJK on the cores; CLOSED_FORM: GJK too, and the pair also has
 *             a public closed-form closest-points function (cd2ClosestPoints<A><B>); or the name
 *             of a closed-form distance (distance2.c) that cd2Distance calls instead of GJK,
 *             Distance(ARG_A(a), ARG_B(b)), with GJK's answer bit for bit (two circles);
 *   Collide   the contact manifold: the typed pair function cd2Collide<A><B> (and its ...Local
 *             form), or CORE when only cd2Collide handles the pair (AABBs and boxes collide as
 *             polygons). */
#ifndef COLLIDE_PAIRS2_H
#define COLLIDE_PAIRS2_H

#include "pair_table.h"

#define CD2_SHAPE_TABLE(X)                                                                                   \
	X(Circle, cd2PointInCircle, cd2ClosestPointOnCircle, cd2RaycastCircle, "circle", ValidateCircle,         \
	  cd2ComputeCircleAabb, cd2ComputeCircleMass, cd2MakeCircleCore, CD2_CIRCLE_RADIUS)                      \
	X(Capsule, cd2PointInCapsule, cd2ClosestPointOnCapsule, cd2RaycastCapsule, "capsule", ValidateCapsule,   \
	  cd2ComputeCapsuleAabb, cd2ComputeCapsuleMass, cd2MakeCapsuleCore, CD2_CAPSULE_RADIUS)                  \
	X(Aabb, cd2PointInAabb, cd2ClosestPointOnAabb, cd2RaycastAabb, "aabb", ValidateAabb, AabbOfAabb,         \
	  cd2ComputeAabbMass, cd2MakeAabbCore, NONE)                                                             \
	X(Box, cd2PointInBox, cd2ClosestPointOnBox, cd2RaycastBox, "box", ValidateBox, cd2ComputeBoxAabb,        \
	  cd2ComputeBoxMass, cd2MakeBoxCore, NONE)                                                               \
	X(Polygon, cd2PointInPolygon, cd2ClosestPointOnPolygon, cd2RaycastPolygon, "polygon", ValidatePolygon,   \
	  cd2ComputePolygonAabb, cd2ComputePolygonMass, cd2MakePolygonCore, CD2_POLYGON_RADIUS)                  \
	X(Segment, PointOnSegment2, cd2ClosestPointOnSegment, cd2RaycastSegment, "segment", ValidateSegment,     \
	  cd2ComputeSegmentAabb, SegmentMass, cd2MakeSegmentCore, NONE)

#define CD2_PAIR_TABLE(X)                                                                                    \
	X(Circle, Circle, cd2OverlapCircleCircle, DistanceCircleCircle, cd2CollideCircleCircle)                  \
	X(Circle, Capsule, cd2OverlapCircleCapsule, GJK, cd2CollideCircleCapsule)                                \
	X(Circle, Aabb, cd2OverlapCircleAabb, GJK, CORE)                                                         \
	X(Circle, Box, cd2OverlapCircleBox, GJK, CORE)                                                           \
	X(Circle, Polygon, cd2OverlapCirclePolygon, GJK, cd2CollideCirclePolygon)                                \
	X(Circle, Segment, cd2OverlapCircleSegment, GJK, cd2CollideCircleSegment)                                \
	X(Capsule, Capsule, cd2OverlapCapsuleCapsule, GJK, cd2CollideCapsuleCapsule)                             \
	X(Capsule, Aabb, cd2OverlapCapsuleAabb, GJK, CORE)                                                       \
	X(Capsule, Box, cd2OverlapCapsuleBox, GJK, CORE)                                                         \
	X(Capsule, Polygon, cd2OverlapCapsulePolygon, GJK, cd2CollideCapsulePolygon)                             \
	X(Capsule, Segment, cd2OverlapCapsuleSegment, GJK, cd2CollideCapsuleSegment)                             \
	X(Aabb, Aabb, cd2OverlapAabbAabb, GJK, CORE)                                                             \
	X(Aabb, Box, cd2OverlapAabbBox, GJK, CORE)                                                               \
	X(Aabb, Polygon, cd2OverlapAabbPolygon, GJK, CORE)                                                       \
	X(Aabb, Segment, cd2OverlapAabbSegment, GJK, CORE)                                                       \
	X(Box, Box, cd2OverlapBoxBox, GJK, CORE)                                                                 \
	X(Box, Polygon, cd2OverlapBoxPolygon, GJK, CORE)                                                         \
	X(Box, Segment, cd2OverlapBoxSegment, GJK, CORE)                                                         \
	X(Polygon, Polygon, cd2OverlapPolygonPolygon, GJK, cd2CollidePolygonPolygon)                             \
	X(Polygon, Segment, cd2OverlapPolygonSegment, GJK, cd2CollidePolygonSegment)                             \
	X(Segment, Segment, cd2OverlapSegmentSegment, CLOSED_FORM, cd2CollideSegmentSegment)

/* The cd2ShapeType of a table name, and the key of an ordered pair of types (a switch label). */
#define CD2_TYPE_Circle CD2_SHAPE_CIRCLE
#define CD2_TYPE_Capsule CD2_SHAPE_CAPSULE
#define CD2_TYPE_Aabb CD2_SHAPE_AABB
#define CD2_TYPE_Box CD2_SHAPE_BOX
#define CD2_TYPE_Polygon CD2_SHAPE_POLYGON
#define CD2_TYPE_Segment CD2_SHAPE_SEGMENT
#define CD2_PAIR_KEY(typeA, typeB) ((int)(typeA) * (int)CD2_SHAPE_TYPE_COUNT + (int)(typeB))

/* How a shape's functions take it from a const cd2Shape* s: CD2_SHAPE_ARG(Polygon, s) is
 * &s->polygon. */
#define CD2_ARG_OF_Circle(s) ((s)->circle)
#define CD2_ARG_OF_Capsule(s) ((s)->capsule)
#define CD2_ARG_OF_Aabb(s) ((s)->aabb)
#define CD2_ARG_OF_Box(s) ((s)->box)
#define CD2_ARG_OF_Polygon(s) (&(s)->polygon)
#define CD2_ARG_OF_Segment(s) ((s)->segment)
#define CD2_SHAPE_ARG(Name, s) CD2_ARG_OF_##Name(s)

#endif
