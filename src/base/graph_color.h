/* collide: greedy graph colouring of constraints (dimension-free). Two constraints of one colour
 * never share a movable body, so a colour can be solved in any order, in SIMD lanes or on several
 * threads with the same result. The sequential solver already runs in colour order, so that the
 * wide and parallel solvers to come keep its results (on the pyramids the colour order and the
 * plain index order hold equally well, docs/DYNAMICS.md). */
#ifndef COLLIDE_GRAPH_COLOR_H
#define COLLIDE_GRAPH_COLOR_H

#include "container.h"

/* Colours tried before a constraint goes to the overflow colour (solved last, sequentially). */
#define CD_GRAPH_COLOR_COUNT 24
/* The last colours, kept for constraints with an immovable body. */
#define CD_GRAPH_IMMOVABLE_COLORS 4

/* bodyA[i], bodyB[i]: dense indices of the constraint's movable bodies in [0, bodyCount), or -1
 * for an immovable one (static, or asleep this step), which takes no colour. Writes each
 * constraint's colour (0 .. CD_GRAPH_COLOR_COUNT, the last being the overflow) to colors and
 * reorders order[0..count) to run colour by colour, keeping the index order within a colour.
 * Constraints with one immovable body (a body on the ground, on a wall) take colours from the last
 * one down to colour 1, and the pairs of movable bodies colours from 0 up to the last
 * CD_GRAPH_IMMOVABLE_COLORS, so that within each pass a body's contact with a wall is solved after
 * its contacts with the bodies pressing it there: a crowd pushed against a wall cannot push one of
 * its bodies through it. The constraints are coloured in index order. Scratch memory comes from
 * the arena; returns false when it runs out (order is then the index order). */
bool cdColorConstraints(const int* bodyA, const int* bodyB, int count, int bodyCount, int* colors, int* order,
						cdArena* arena);
/* The same, with the constraints coloured in blocks of 256 consecutive indices, each block in a
 * fixed pseudo-random order, so that the colours of a regular structure (a pyramid's contacts)
 * mix its kinds of constraint instead of holding one kind each (graph_color.c); the contacts'
 * colouring. The result depends only on the arguments. */
bool cdColorConstraintsMixed(const int* bodyA, const int* bodyB, int count, int bodyCount, int* colors,
							 int* order, cdArena* arena);
/* Either of the two (mixed: cdColorConstraintsMixed's order) with the caller's scratch, so that it
 * allocates nothing and can run on any thread: used holds bodyCount words and start
 * CD_GRAPH_COLOR_COUNT + 2 ints, their contents overwritten. The same colours and order. */
void cdColorConstraintsScratch(const int* bodyA, const int* bodyB, int count, int bodyCount, int* colors,
							   int* order, bool mixed, uint32_t* used, int* start);

#endif
