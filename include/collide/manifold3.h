/* collide: 3D contact manifolds between spheres, capsules, boxes, convex hulls and triangles.
 *
 * Every function takes its shapes in world space (like the rest of the query API) and a
 * speculative distance (>= 0): contact points whose surfaces are still apart by up to that
 * distance are reported with a positive separation; points farther apart are dropped. The
 * manifold's normal is a unit vector pointing from shape A (the first argument) to shape B. Each
 * point lies midway between the two surfaces: point - separation/2 * normal is on A's surface and
 * point + separation/2 * normal on B's. A pair with pointCount 0 has no contact (its normal is
 * zero). At most 4 points: a larger clipped polygon is reduced to its deepest point and the points
 * that keep the most area.
 *
 * Depth: for penetrating pairs the smallest separation is minus the penetration depth, found by
 * the separating axis test (face normals and the edge pairs that form faces of the Minkowski
 * difference), which is exact for polytopes (EPA for polytopes with many edge pairs).
 *
 * Face bias (the one statement of this rule; docs/API.md links here): the reference feature is
 * chosen with a bias for stability from frame to frame. A's face is kept unless B's face separates
 * by more than 1e-4 of twice the smaller shape's size; a face is kept unless an edge pair separates
 * by more than 1e-4 of the two shapes' summed size (at most 16 times the smaller's). Both sizes are
 * at least the round-off of the coordinates (src/query/manifold3.c: FACE_BIAS, EDGE_BIAS,
 * FaceTieSize, EdgeTieSize). The separations are the depths along the reported normal: B moved by
 * minus the smallest separation along the normal just touches A (within round-off), so a solver
 * pushing along the normal by the depth resolves the overlap exactly. When the bias took a normal
 * other than the axis of least overlap, that depth exceeds the exact SAT/EPA depth by at most the
 * bias (2e-4 of the size); otherwise the smallest separation is the exact depth. For separated
 * pairs the smallest separation is the distance (cd3Distance).
 *
 * Thresholds (the one statement of them; docs/API.md links here): pairs of solid polytopes with
 * more than 1024 edge pairs (two hulls of 32 vertices) take GJK and EPA for the depth and normal
 * instead of the edge query, then clip the face of A (or B) whose normal is within 1e-4 in cosine
 * of that normal, else report one point at the EPA witnesses. A capsule lies on a face, and gets 2 points,
 * when the sine of its axis's tilt to the face plane is below 0.01. Faces of more than 64
 * vertices are clipped with their first 64 vertices.
 *
 * Triangles are the two-sided surface of cd3Triangle (not solid); triangle against triangle
 * resolves crossing triangles along their axis of least overlap. Functions name their shapes in the
 * canonical order of cd3ShapeType (Sphere, Capsule, Box, Triangle, Hull); cd3Collide takes tagged
 * shapes in either order. */
#ifndef COLLIDE_MANIFOLD3_H
#define COLLIDE_MANIFOLD3_H

#include "collide/query3.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct cd3ManifoldPoint
{
	cd3Vec point;	   /* world, midway between the surfaces */
	cdReal separation; /* negative when penetrating */
	uint32_t id;	   /* feature id: the same while the same features touch (for warm starting) */
} cd3ManifoldPoint;

typedef struct cd3Manifold
{
	cd3Vec normal; /* from A to B, unit (zero when pointCount is 0) */
	cd3ManifoldPoint points[4];
	int pointCount;
} cd3Manifold;

/* Feature ids of face contacts between polytopes pack (reference face & 0xff) | (incident face &
 * 0xff) << 8 | (the two clip lines through the point, 7 bits each) << 16, with CD3_FEATURE_FLIP
 * when the reference face belongs to B. Edge-edge contacts are CD3_FEATURE_EDGES | (edge of A &
 * 0x7fff) | (edge of B & 0x7fff) << 15. Contacts of spheres and capsules use the face or edge of
 * the other shape and the capsule end. */
#define CD3_FEATURE_FLIP (1u << 31)
#define CD3_FEATURE_EDGES (1u << 30)

CD_API cd3Manifold cd3CollideSphereSphere(cd3Sphere a, cd3Sphere b, cdReal speculativeDistance);
CD_API cd3Manifold cd3CollideSphereCapsule(cd3Sphere a, cd3Capsule b, cdReal speculativeDistance);
CD_API cd3Manifold cd3CollideSphereBox(cd3Sphere a, cd3Box b, cdReal speculativeDistance);
CD_API cd3Manifold cd3CollideSphereHull(cd3Sphere a, cd3HullShape b, cdReal speculativeDistance);
CD_API cd3Manifold cd3CollideSphereTriangle(cd3Sphere a, cd3Triangle b, cdReal speculativeDistance);
/* Up to 2 points when the capsules are parallel and their segments overlap along the axis. */
CD_API cd3Manifold cd3CollideCapsuleCapsule(cd3Capsule a, cd3Capsule b, cdReal speculativeDistance);
/* 2 points when the capsule lies on a face (its segment clipped to the face's side planes). */
CD_API cd3Manifold cd3CollideCapsuleBox(cd3Capsule a, cd3Box b, cdReal speculativeDistance);
CD_API cd3Manifold cd3CollideCapsuleHull(cd3Capsule a, cd3HullShape b, cdReal speculativeDistance);
CD_API cd3Manifold cd3CollideCapsuleTriangle(cd3Capsule a, cd3Triangle b, cdReal speculativeDistance);
CD_API cd3Manifold cd3CollideBoxBox(cd3Box a, cd3Box b, cdReal speculativeDistance);
CD_API cd3Manifold cd3CollideBoxHull(cd3Box a, cd3HullShape b, cdReal speculativeDistance);
CD_API cd3Manifold cd3CollideBoxTriangle(cd3Box a, cd3Triangle b, cdReal speculativeDistance);
CD_API cd3Manifold cd3CollideHullHull(cd3HullShape a, cd3HullShape b, cdReal speculativeDistance);
/* The triangle is A: the normal points from the triangle to the hull. */
CD_API cd3Manifold cd3CollideTriangleHull(cd3Triangle a, cd3HullShape b, cdReal speculativeDistance);
/* Two two-sided triangles, the normal from A to B: up to 4 points of a face clipped against the
 * other (parallel or crossing faces), one point for edge or vertex contacts. Crossing triangles
 * get the axis of least overlap (face normals, edge-edge axes) as normal, read in the direction
 * B lies on. Degenerate triangles collide as their segment or point. */
CD_API cd3Manifold cd3CollideTriangleTriangle(cd3Triangle a, cd3Triangle b, cdReal speculativeDistance);

/* Any two tagged shapes among sphere, capsule, AABB (as a box), box, hull and triangle, in either
 * order. Shapes of different kinds run the pair function in the order above and flip the normal
 * when a and b were swapped, so cd3Collide(b, a) reports the same points, separations and ids with
 * the opposite normal. Two shapes of the same kind run in the given order. Unsupported pairs
 * (planes, segments) return an empty manifold. */
CD_API cd3Manifold cd3Collide(const cd3Shape* a, const cd3Shape* b, cdReal speculativeDistance);

/* ---- local-frame forms ---------------------------------------------------------------------
 * What a solver calls: shape A in its own (body) frame, shape B in its own frame, and xfB, the
 * transform of B's frame in A's frame (cd3InvMulTransforms(xfA, xfB) of the two body transforms).
 * The manifold comes back in A's frame: cd3TransformManifold(xfA, m) gives the world manifold.
 * Each function is named after its world-space form with the suffix Local and gives, bit for bit,
 * the same points (in A's frame), normal, separations and feature ids as the world-space form
 * called on a and on b transformed by xfB (points by cd3TransformPoint, rotations and hull
 * transforms by cd3MulQuat / cd3MulTransforms, no normalization): B is placed in A's frame on the
 * stack (a hull only composes its transform, its vertices are never copied), A is used as given. Contacts far
 * from the origin keep their precision, since the shapes' coordinates stay those of their body frames. An
 * AABB given as B is read as a box in its own frame (rotated by xfB). */
CD_API cd3Manifold cd3CollideSphereSphereLocal(cd3Sphere a, cd3Sphere b, cd3Transform xfB,
											   cdReal speculativeDistance);
CD_API cd3Manifold cd3CollideSphereCapsuleLocal(cd3Sphere a, cd3Capsule b, cd3Transform xfB,
												cdReal speculativeDistance);
CD_API cd3Manifold cd3CollideSphereBoxLocal(cd3Sphere a, cd3Box b, cd3Transform xfB,
											cdReal speculativeDistance);
CD_API cd3Manifold cd3CollideSphereHullLocal(cd3Sphere a, cd3HullShape b, cd3Transform xfB,
											 cdReal speculativeDistance);
CD_API cd3Manifold cd3CollideSphereTriangleLocal(cd3Sphere a, cd3Triangle b, cd3Transform xfB,
												 cdReal speculativeDistance);
CD_API cd3Manifold cd3CollideCapsuleCapsuleLocal(cd3Capsule a, cd3Capsule b, cd3Transform xfB,
												 cdReal speculativeDistance);
CD_API cd3Manifold cd3CollideCapsuleBoxLocal(cd3Capsule a, cd3Box b, cd3Transform xfB,
											 cdReal speculativeDistance);
CD_API cd3Manifold cd3CollideCapsuleHullLocal(cd3Capsule a, cd3HullShape b, cd3Transform xfB,
											  cdReal speculativeDistance);
CD_API cd3Manifold cd3CollideCapsuleTriangleLocal(cd3Capsule a, cd3Triangle b, cd3Transform xfB,
												  cdReal speculativeDistance);
CD_API cd3Manifold cd3CollideBoxBoxLocal(cd3Box a, cd3Box b, cd3Transform xfB, cdReal speculativeDistance);
CD_API cd3Manifold cd3CollideBoxHullLocal(cd3Box a, cd3HullShape b, cd3Transform xfB,
										  cdReal speculativeDistance);
CD_API cd3Manifold cd3CollideBoxTriangleLocal(cd3Box a, cd3Triangle b, cd3Transform xfB,
											  cdReal speculativeDistance);
CD_API cd3Manifold cd3CollideHullHullLocal(cd3HullShape a, cd3HullShape b, cd3Transform xfB,
										   cdReal speculativeDistance);
CD_API cd3Manifold cd3CollideTriangleHullLocal(cd3Triangle a, cd3HullShape b, cd3Transform xfB,
											   cdReal speculativeDistance);
CD_API cd3Manifold cd3CollideTriangleTriangleLocal(cd3Triangle a, cd3Triangle b, cd3Transform xfB,
												   cdReal speculativeDistance);
/* cd3Collide in A's frame: either order, as cd3Collide. */
CD_API cd3Manifold cd3CollideLocal(const cd3Shape* a, const cd3Shape* b, cd3Transform xfB,
								   cdReal speculativeDistance);

/* The manifold m (in the frame of transform xf) in the outer frame: points transformed, normal
 * rotated; separations and ids unchanged. */
static inline cd3Manifold cd3TransformManifold(cd3Transform xf, cd3Manifold m)
{
	m.normal = cd3RotateVector(xf.q, m.normal);
	for (int i = 0; i < m.pointCount; ++i)
	{
		m.points[i].point = cd3TransformPoint(xf, m.points[i].point);
	}
	return m;
}

/* Former name and order (hull first, normal from the hull to the triangle), kept for one release:
 * cd3CollideHullTriangle(h, t, d) is cd3CollideTriangleHull(t, h, d) with the opposite normal. */
CD_API cd3Manifold cd3CollideHullTriangle(cd3HullShape a, cd3Triangle b, cdReal speculativeDistance);

#ifdef __cplusplus
}
#endif

#endif
