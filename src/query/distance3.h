/* Internal: the boolean GJK test of distance3.c, for the overlap dispatcher. */
#ifndef COLLIDE_DISTANCE3_H
#define COLLIDE_DISTANCE3_H

#include "collide/query3.h"

/* Relative gap below which GJK's distance counts as touching for an overlap test: the round-off
 * of the support points, as in the other rotated tests (docs/API.md). */
#define CD3_GJK_OVERLAP_TOLERANCE (CD_R(16.0) * CD_REAL_EPSILON)

/* cd3Overlap for any pair by GJK: true exactly when cd3Distance's answer is within
 * CD3_GJK_OVERLAP_TOLERANCE of the largest coordinate of its closest points (away from that
 * tolerance), but stopping at the first point within reach or the first separating support plane
 * instead of converging to the distance. */
bool cd3OverlapGjk(const cd3Shape* a, const cd3Shape* b);

#endif
