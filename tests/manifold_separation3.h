/* The smallest separation of a 3D contact manifold, for the manifold tests. Header-only. */
#ifndef COLLIDE_TEST_MANIFOLD_SEPARATION3_H
#define COLLIDE_TEST_MANIFOLD_SEPARATION3_H

#include "collide/manifold3.h"

#include <math.h>

/* INFINITY for a manifold without points. */
static inline double MinSeparation(const cd3Manifold* m)
{
	double s = INFINITY;
	for (int i = 0; i < m->pointCount; ++i)
	{
		s = fmin(s, (double)m->points[i].separation);
	}
	return s;
}

#endif
