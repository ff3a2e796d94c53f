/* collide (internal): penetration depth of two convex shapes given by support functions: GJK finds
 * a tetrahedron of the Minkowski difference A - B around the origin, EPA expands it to the face
 * nearest the origin. On polytopes the support points are vertices, so the final face is a face of
 * the Minkowski difference and the depth is exact up to round-off. Allocates nothing. */
#ifndef COLLIDE_EPA3_H
#define COLLIDE_EPA3_H

#include "sat3.h"

/* The point of the shape farthest along `direction` (world space). */
typedef cd3Vec cd3SupportFcn(const void* shape, cd3Vec direction);

typedef struct cd3Penetration
{
	bool overlapping;	  /* false: GJK found a separating direction; the rest is unset */
	cdReal depth;		  /* >= 0: translating B by depth * normal makes the shapes touch */
	cd3Vec normal;		  /* unit, from A to B */
	cd3Vec pointA;		  /* deepest point of A inside B (world) */
	cd3Vec pointB;		  /* pointA + ... : pointB - pointA = -depth * normal */
	int iterations;		  /* GJK and EPA iterations used */
	bool hitIterationCap; /* GJK or EPA stopped at the cap: the answer is the best so far (after a
							 GJK cap, overlapping may be wrong: check with cd3Distance) */
	cdReal gap;			  /* not overlapping: a lower bound of the distance (the separation along
							 GJK's separating direction); 0 otherwise */
} cd3Penetration;

#define CD3_EPA_MAX_ITERATIONS 64

cd3Penetration cd3Epa(const void* a, cd3SupportFcn* supportA, const void* b, cd3SupportFcn* supportB);

/* Support function of a cd3Polytope (its vertex farthest along the direction). */
cd3Vec cd3PolytopeSupport(const void* polytope, cd3Vec direction);

#endif
