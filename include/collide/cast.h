/* collide: shape casts and time of impact (the basis of continuous collision), 2D and 3D.
 * Queries allocate nothing and every loop has a cap. See docs/API.md, "Shape casts and time of
 * impact".
 *
 * Shape cast: shape A moves by a translation against a static shape B, both tagged shapes in
 * world space. van den Bergen's GJK ray cast of the origin against the Minkowski difference of
 * the cores grown by the radii: one GJK simplex lives through the whole cast, and a support plane
 * that separates the shapes moves A along the translation until that plane is half a tolerance
 * short of contact, so no earlier fraction overlaps. It stops when the shapes are within the cast
 * tolerance. Radii (circles, capsules, rounded polygons) are exact. Half-spaces, and the rare
 * case where round-off stalls the ray cast, go on by conservative advancement on the GJK
 * distance from the contact-free fraction reached. See docs/CASTS.md.
 *
 * Time of impact: both shapes move rigidly over the step (a sweep: linear motion of the centre,
 * rotation at constant angular speed about it). Conservative advancement (Mirtich): each step
 * advances t by (distance - target) over a bound on the approach speed, the relative speed along
 * the closest-point normal plus |angular speed| times each shape's largest distance from its
 * sweep centre. It never steps past a time where the distance falls below the target. The
 * bounding circles (spheres) about the sweep centres skip the far part of the step, and between
 * GJK calls a few cheap steps advance on the separation along one axis (a lower bound on the
 * distance, with the same kind of speed bound): both keep the guarantee. The axis is the last
 * closest-point normal (3D), or in 2D the axis of the last closest features turning with the
 * bodies (the normal of the closest edge, or the direction between the closest vertices), whose
 * points also show when the distance is within the tolerance without another GJK call. Each GJK
 * call is warm-started from the previous one's simplex (cd2SimplexCache / cd3SimplexCache). */
#ifndef COLLIDE_CAST_H
#define COLLIDE_CAST_H

#include "collide/query2.h"
#include "collide/query3.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Most GJK iterations of a shape cast's ray cast (and as many distance evaluations of the
 * advancement after it), and most GJK distance evaluations of a time of impact. */
#define CD_CAST_MAX_ITERATIONS 64
#define CD_TOI_MAX_ITERATIONS 64

/* A shape cast stops when the shapes are closer than this (a small fraction of the linear slop,
 * or 64 epsilons of the coordinates when that is larger): the contact fraction is then within
 * this distance over the approach speed of the exact one, never past it. */
#define CD_CAST_TOLERANCE (CD_R(0.001) * CD_LINEAR_SLOP)

/* Result of a shape cast. On a hit: fraction in [0, 1] of the translation at first contact,
 * point on B's surface where A touches it, normal = unit outward normal of B's surface there
 * (pointing from B towards A, opposite to the direction A moves in): the contact normal of the
 * touching features (a face normal or the cross product of two edges for polytopes, the surface
 * normal of a round shape), so that the plane through point with this normal separates the
 * shapes at fraction to within the cast tolerance (not the direction between two closest points
 * a tolerance apart, which round-off turns by up to 1e-2 rad in float). Shapes that already touch
 * or overlap at fraction 0 hit at fraction 0 with point = a common point and normal =
 * -normalize(translation) (zero for a zero translation), like a ray starting inside a shape.
 * No hit: hit false, fraction 1, point and normal zero. hitIterationCap: the cap stopped the
 * cast first (hit false, fraction = the fraction reached, which is free of contact). */
typedef struct cd2CastOutput
{
	bool hit;
	bool hitIterationCap;
	cdReal fraction;
	cd2Vec point;
	cd2Vec normal;
	int iterations; /* GJK iterations of the ray cast (plus distance evaluations of the advancement
					   when it takes over) */
} cd2CastOutput;

typedef struct cd3CastOutput
{
	bool hit;
	bool hitIterationCap;
	cdReal fraction;
	cd3Vec point;
	cd3Vec normal;
	int iterations;
} cd3CastOutput;

/* A moves by translationA (the points a + s * translationA, s in [0, 1]); B stays. Either shape
 * may be any type (3D: a half-space too). */
CD_API cd2CastOutput cd2ShapeCast(const cd2Shape* a, const cd2Shape* b, cd2Vec translationA);
CD_API cd3CastOutput cd3ShapeCast(const cd3Shape* a, const cd3Shape* b, cd3Vec translationA);

/* ---- time of impact ----------------------------------------------------------------------- */

/* The motion of a body over one step, t in [0, 1]. The shape is given in the body's frame; the
 * body's centre (localCenter in that frame, usually the centre of mass) moves linearly from
 * center0 to center1 while the body turns at constant speed from angle0 to angle1 (radians,
 * counter-clockwise; more than a turn is allowed) about it. The body's transform at t is
 * q = rot(angle(t)), p = center(t) - q * localCenter (cd2GetSweepTransform). */
typedef struct cd2Sweep
{
	cd2Vec localCenter;
	cd2Vec center0, center1;
	cdReal angle0, angle1;
} cd2Sweep;

/* 3D: the rotation goes from rotation0 to rotation1 (unit quaternions) along the shorter arc at
 * constant angular speed (slerp). */
typedef struct cd3Sweep
{
	cd3Vec localCenter;
	cd3Vec center0, center1;
	cd3Quat rotation0, rotation1;
} cd3Sweep;

CD_API cd2Transform cd2GetSweepTransform(const cd2Sweep* sweep, cdReal t);
CD_API cd3Transform cd3GetSweepTransform(const cd3Sweep* sweep, cdReal t);

/* How a time of impact ended. */
typedef enum cdToiState
{
	CD_TOI_HIT,		   /* distance within [target, target + tolerance] at t (t may be 0) */
	CD_TOI_SEPARATED,  /* the distance stays above the target over the whole step (t = 1) */
	CD_TOI_OVERLAPPED, /* the shapes touch or overlap at t = 0 (distance 0; t = 0) */
	CD_TOI_FAILED	   /* the iteration cap was reached; t is the time reached, free of contact */
} cdToiState;

typedef struct cdToiOutput
{
	cdToiState state;
	cdReal t;		/* time fraction in [0, 1] */
	int iterations; /* GJK distance evaluations (0 when the bounding circles never get close) */
} cdToiOutput;

/* First time in [0, 1] at which the distance between the moving shapes falls to
 * targetSeparation (>= 0, e.g. CD_LINEAR_SLOP), found to within tolerance (> 0, e.g. a quarter
 * of a slop; raised to 64 CD_REAL_EPSILON times the largest coordinate when smaller). The
 * distance is that of cd2Distance / cd3Distance (radii included). A half-space (3D) may move
 * but not rotate: a rotating half-space gives CD_TOI_FAILED. Symmetric: swapping the shapes
 * with their sweeps gives the same answer up to round-off. */
CD_API cdToiOutput cd2TimeOfImpact(const cd2Shape* a, const cd2Sweep* sweepA, const cd2Shape* b,
								   const cd2Sweep* sweepB, cdReal targetSeparation, cdReal tolerance);
CD_API cdToiOutput cd3TimeOfImpact(const cd3Shape* a, const cd3Sweep* sweepA, const cd3Shape* b,
								   const cd3Sweep* sweepB, cdReal targetSeparation, cdReal tolerance);

#ifdef __cplusplus
}
#endif

#endif
