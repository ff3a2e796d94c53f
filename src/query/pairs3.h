/* collide: the 3D shape table and pair tables (internal). Every shape type has one row in
 * CD3_SHAPE_TABLE and every unordered pair of shape types one row in CD3_PAIR_TABLE (pairs with a
 * closed-form overlap test) or CD3_HULL_PAIR_TABLE (pairs with a hull: overlap by GJK), in the
 * canonical order of cd3ShapeType (the order pair functions name their shapes). The generic
 * dispatchers expand them (dispatch3.c, raycast3.c, manifold3.c,
 * geometry/shapes3.c, geometry/mass3.c) and so do the matrix tests, so adding a shape
 * means writing its functions and adding its rows (CONTRIBUTING.md, "Adding a shape").
 *
 * Per shape, besides its table row: CD3_TYPE_<Name> (its cd3ShapeType) and CD3_ARG_OF_<Name>(s)
 * (how its functions take it from a const cd3Shape* s: the union member).
 *
 * CD3_SHAPE_TABLE(X): X(Name, PointIn, ClosestPointOn, Raycast, TypeName, Validate, ComputeAabb,
 *                       ComputeMass, MakeCore, Radius)
 *   PointIn(p, shape) (a shape with no inside names the dispatcher's tolerance test),
 *   ClosestPointOn(shape, p), Raycast(shape, ray, hit); TypeName the string of
 *   cd3GetShapeTypeName; Validate(shape) (static in geometry/shapes3.c), ComputeAabb(shape)
 *   (geometry/shapes3.c), ComputeMass(shape, density) (geometry/mass3.c; zero mass at the
 *   centroid for shapes without volume); MakeCore(shape, core) fills the shape's GJK core (its
 *   support function: the points its support is taken over; support3.h: cd3MakeCore, and
 *   through it cd3Distance, the casts and time of impact), NONE for the half-space (no finite
 *   core: its users handle it apart); Radius(const cd3Shape* s)
 *   the rounding radius as an lvalue macro (support3.h), NONE for a sharp shape: the core's
 *   radius, and what the casts strip (cast3.c). A column is expanded only in the file that holds
 *   its functions, so static helpers are fine.
 *
 * CD3_PAIR_TABLE(X) and CD3_HULL_PAIR_TABLE(X): X(NameA, NameB, Overlap, Distance, Collide)
 *   Overlap   the pair's overlap test, Overlap(ARG_A(a), ARG_B(b)); GJK for the hull pairs
 *             (cd3Overlap runs the boolean GJK on the tagged shapes);
 *   Distance  GJK: cd3Distance runs GJK on the cores; CLOSED_FORM: a pair with a public
 *             closed-form closest-points function (cd3ClosestPoints<A><B>) or an exact half-space
 *             path in cd3Distance; or the name of a closed-form distance (distance3.c) that
 *             cd3Distance calls instead of GJK, Distance(ARG_A(a), ARG_B(b)), with GJK's answer
 *             bit for bit (two spheres);
 *   Collide   the contact manifold: the typed pair function cd3Collide<A><B> (and its ...Local
 *             form), CORE when only cd3Collide handles the pair (an AABB collides as a box), or
 *             NONE (planes and segments have no manifold). */
#ifndef COLLIDE_PAIRS3_H
#define COLLIDE_PAIRS3_H

#include "pair_table.h"

#define CD3_SHAPE_TABLE(X)                                                                                   \
	X(Sphere, cd3PointInSphere, cd3ClosestPointOnSphere, cd3RaycastSphere, "sphere", ValidateSphere,         \
	  cd3ComputeSphereAabb, cd3ComputeSphereMass, cd3MakeSphereCore, CD3_SPHERE_RADIUS)                      \
	X(Capsule, cd3PointInCapsule, cd3ClosestPointOnCapsule, cd3RaycastCapsule, "capsule", ValidateCapsule,   \
	  cd3ComputeCapsuleAabb, cd3ComputeCapsuleMass, cd3MakeCapsuleCore, CD3_CAPSULE_RADIUS)                  \
	X(Aabb, cd3PointInAabb, cd3ClosestPointOnAabb, cd3RaycastAabb, "aabb", ValidateAabb, AabbOfAabb,         \
	  cd3ComputeAabbMass, cd3MakeAabbCore, NONE)                                                             \
	X(Box, cd3PointInBox, cd3ClosestPointOnBox, cd3RaycastBox, "box", ValidateBox, cd3ComputeBoxAabb,        \
	  cd3ComputeBoxMass, cd3MakeBoxCore, NONE)                                                               \
	X(Triangle, PointOnTriangle3, cd3ClosestPointOnTriangle, cd3RaycastTriangle, "triangle",                 \
	  ValidateTriangle, cd3ComputeTriangleAabb, TriangleMass, cd3MakeTriangleCore, NONE)                     \
	X(Plane, cd3PointInPlane, cd3ClosestPointOnPlane, cd3RaycastPlane, "plane", ValidatePlane,               \
	  cd3ComputePlaneAabb, PlaneMass, NONE, NONE)                                                            \
	X(Segment, PointOnSegment3, cd3ClosestPointOnSegment, cd3RaycastSegment, "segment", ValidateSegment,     \
	  cd3ComputeSegmentAabb, SegmentMass, cd3MakeSegmentCore, NONE)                                          \
	X(Hull, cd3PointInHull, cd3ClosestPointOnHull, cd3RaycastHull, "hull", ValidateHullShape,                \
	  cd3ComputeHullShapeAabb, cd3ComputeHullMass, cd3MakeHullCore, NONE)

#define CD3_PAIR_TABLE(X)                                                                                    \
	X(Sphere, Sphere, cd3OverlapSphereSphere, DistanceSphereSphere, cd3CollideSphereSphere)                  \
	X(Sphere, Capsule, cd3OverlapSphereCapsule, GJK, cd3CollideSphereCapsule)                                \
	X(Sphere, Aabb, cd3OverlapSphereAabb, GJK, CORE)                                                         \
	X(Sphere, Box, cd3OverlapSphereBox, GJK, cd3CollideSphereBox)                                            \
	X(Sphere, Triangle, cd3OverlapSphereTriangle, GJK, cd3CollideSphereTriangle)                             \
	X(Sphere, Plane, cd3OverlapSpherePlane, CLOSED_FORM, NONE)                                               \
	X(Sphere, Segment, cd3OverlapSphereSegment, GJK, NONE)                                                   \
	X(Capsule, Capsule, cd3OverlapCapsuleCapsule, GJK, cd3CollideCapsuleCapsule)                             \
	X(Capsule, Aabb, cd3OverlapCapsuleAabb, GJK, CORE)                                                       \
	X(Capsule, Box, cd3OverlapCapsuleBox, GJK, cd3CollideCapsuleBox)                                         \
	X(Capsule, Triangle, cd3OverlapCapsuleTriangle, GJK, cd3CollideCapsuleTriangle)                          \
	X(Capsule, Plane, cd3OverlapCapsulePlane, CLOSED_FORM, NONE)                                             \
	X(Capsule, Segment, cd3OverlapCapsuleSegment, GJK, NONE)                                                 \
	X(Aabb, Aabb, cd3OverlapAabbAabb, GJK, CORE)                                                             \
	X(Aabb, Box, cd3OverlapAabbBox, GJK, CORE)                                                               \
	X(Aabb, Triangle, cd3OverlapAabbTriangle, GJK, CORE)                                                     \
	X(Aabb, Plane, cd3OverlapAabbPlane, CLOSED_FORM, NONE)                                                   \
	X(Aabb, Segment, cd3OverlapAabbSegment, GJK, NONE)                                                       \
	X(Box, Box, cd3OverlapBoxBox, GJK, cd3CollideBoxBox)                                                     \
	X(Box, Triangle, cd3OverlapBoxTriangle, GJK, cd3CollideBoxTriangle)                                      \
	X(Box, Plane, cd3OverlapBoxPlane, CLOSED_FORM, NONE)                                                     \
	X(Box, Segment, cd3OverlapBoxSegment, GJK, NONE)                                                         \
	X(Triangle, Triangle, cd3OverlapTriangleTriangle, GJK, cd3CollideTriangleTriangle)                       \
	X(Triangle, Plane, cd3OverlapTrianglePlane, CLOSED_FORM, NONE)                                           \
	X(Triangle, Segment, cd3OverlapTriangleSegment, CLOSED_FORM, NONE)                                       \
	X(Plane, Plane, cd3OverlapPlanePlane, CLOSED_FORM, NONE)                                                 \
	X(Plane, Segment, cd3OverlapPlaneSegment, CLOSED_FORM, NONE)                                             \
	X(Segment, Segment, cd3OverlapSegmentSegment, CLOSED_FORM, NONE)

#define CD3_HULL_PAIR_TABLE(X)                                                                               \
	X(Sphere, Hull, GJK, GJK, cd3CollideSphereHull)                                                          \
	X(Capsule, Hull, GJK, GJK, cd3CollideCapsuleHull)                                                        \
	X(Aabb, Hull, GJK, GJK, CORE)                                                                            \
	X(Box, Hull, GJK, GJK, cd3CollideBoxHull)                                                                \
	X(Triangle, Hull, GJK, GJK, cd3CollideTriangleHull)                                                      \
	X(Plane, Hull, GJK, CLOSED_FORM, NONE)                                                                   \
	X(Segment, Hull, GJK, GJK, NONE)                                                                         \
	X(Hull, Hull, GJK, GJK, cd3CollideHullHull)

#define CD3_TYPE_Sphere CD3_SHAPE_SPHERE
#define CD3_TYPE_Capsule CD3_SHAPE_CAPSULE
#define CD3_TYPE_Aabb CD3_SHAPE_AABB
#define CD3_TYPE_Box CD3_SHAPE_BOX
#define CD3_TYPE_Triangle CD3_SHAPE_TRIANGLE
#define CD3_TYPE_Plane CD3_SHAPE_PLANE
#define CD3_TYPE_Segment CD3_SHAPE_SEGMENT
#define CD3_TYPE_Hull CD3_SHAPE_HULL
#define CD3_PAIR_KEY(typeA, typeB) ((int)(typeA) * (int)CD3_SHAPE_TYPE_COUNT + (int)(typeB))

#define CD3_ARG_OF_Sphere(s) ((s)->sphere)
#define CD3_ARG_OF_Capsule(s) ((s)->capsule)
#define CD3_ARG_OF_Aabb(s) ((s)->aabb)
#define CD3_ARG_OF_Box(s) ((s)->box)
#define CD3_ARG_OF_Triangle(s) ((s)->triangle)
#define CD3_ARG_OF_Plane(s) ((s)->plane)
#define CD3_ARG_OF_Segment(s) ((s)->segment)
#define CD3_ARG_OF_Hull(s) ((s)->hull)
#define CD3_SHAPE_ARG(Name, s) CD3_ARG_OF_##Name(s)

#endif
