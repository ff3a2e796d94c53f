/* Needles for the 3D query tests: a segment far longer than the box it passes over, whose
 * Minkowski difference with the box is a sliver. Shared by the distance and the cast tests, which
 * check different queries on the same placement. Header-only. */
#ifndef COLLIDE_TEST_NEEDLE_CASES3_H
#define COLLIDE_TEST_NEEDLE_CASES3_H

#include "collide/query3.h"
#include "test.h"

#include <math.h>

typedef struct NeedleCase
{
	cd3Box box;
	cd3Segment segment;
	cd3Vec normal; /* outward normal of the face the segment lies over */
} NeedleCase;

/* A box of size 2-20 within 10 of the origin, turned at random, and a segment `length` long in the
 * plane `gap` above one of its faces, passing over a point of the face's inner part in a random
 * direction of that plane: the exact distance between them is `gap`. */
static inline NeedleCase MakeNeedleOverBox(TestRng* rng, double length, double gap)
{
	NeedleCase c;
	double x = TestRngRange(rng, -10.0, 10.0), y = TestRngRange(rng, -10.0, 10.0),
		   z = TestRngRange(rng, -10.0, 10.0);
	double qx = TestRngRange(rng, -1.0, 1.0), qy = TestRngRange(rng, -1.0, 1.0),
		   qz = TestRngRange(rng, -1.0, 1.0), qw = TestRngRange(rng, -1.0, 1.0);
	double qn = sqrt(qx * qx + qy * qy + qz * qz + qw * qw);
	c.box.center = cd3MakeVec((cdReal)x, (cdReal)y, (cdReal)z);
	c.box.halfExtents = cd3MakeVec((cdReal)TestRngRange(rng, 1.0, 10.0), (cdReal)TestRngRange(rng, 1.0, 10.0),
								   (cdReal)TestRngRange(rng, 1.0, 10.0));
	c.box.rotation = cd3MakeQuat((cdReal)(qx / qn), (cdReal)(qy / qn), (cdReal)(qz / qn), (cdReal)(qw / qn));

	cd3Mat33 rotation = cd3MakeMatFromQuat(c.box.rotation);
	cd3Vec axes[3] = {rotation.cx, rotation.cy, rotation.cz};
	cdReal half[3] = {c.box.halfExtents.x, c.box.halfExtents.y, c.box.halfExtents.z};
	int axis = TestRngInt(rng, 3), u = (axis + 1) % 3, v = (axis + 2) % 3;
	c.normal = TestRngInt(rng, 2) ? axes[axis] : cd3Neg(axes[axis]);
	cd3Vec over = cd3Add(c.box.center, cd3Scale(half[axis] + (cdReal)gap, c.normal));
	over = cd3MulAdd(over, (cdReal)TestRngRange(rng, -0.8, 0.8) * half[u], axes[u]);
	over = cd3MulAdd(over, (cdReal)TestRngRange(rng, -0.8, 0.8) * half[v], axes[v]);
	double angle = TestRngRange(rng, 0.0, 6.283185307179586);
	cd3Vec direction = cd3Add(cd3Scale((cdReal)cos(angle), axes[u]), cd3Scale((cdReal)sin(angle), axes[v]));
	double start = -TestRngRange(rng, 0.1, 0.9) * length;
	c.segment.p1 = cd3MulAdd(over, (cdReal)start, direction);
	c.segment.p2 = cd3MulAdd(over, (cdReal)(start + length), direction);
	return c;
}

#endif
