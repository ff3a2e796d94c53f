/* collide: helpers for expanding the pair tables (pairs2.h, pairs3.h; internal).
 *
 * A Collide column names either a typed pair function, CORE (only the generic cd2Collide /
 * cd3Collide handles the pair) or NONE (no manifold). CD_PAIR_TYPED(Collide, MACRO) expands to
 * MACRO for a typed pair and to CD_PAIR_SKIP (which swallows its arguments) for CORE and NONE,
 * so a row macro can write
 *
 *     CD_PAIR_TYPED(Collide, MY_TYPED_CASE)(A, B, Collide)
 *
 * and never calls CORE or NONE as a function. (The test pastes the column to CD_PAIR_PROBE_: only
 * CD_PAIR_PROBE_CORE and CD_PAIR_PROBE_NONE are macros, and they add an argument.) */
#ifndef COLLIDE_PAIR_TABLE_H
#define COLLIDE_PAIR_TABLE_H

#define CD_PAIR_CAT(a, b) CD_PAIR_CAT_I(a, b)
#define CD_PAIR_CAT_I(a, b) a##b
#define CD_PAIR_SECOND(a, b, ...) b
#define CD_PAIR_SECOND_I(...) CD_PAIR_SECOND(__VA_ARGS__)
#define CD_PAIR_PROBE_CORE ~, 1
#define CD_PAIR_PROBE_NONE ~, 1

/* 1 when column is CORE or NONE, 0 when it names a typed function. */
#define CD_PAIR_IS_UNTYPED(column) CD_PAIR_SECOND_I(CD_PAIR_CAT(CD_PAIR_PROBE_, column), 0, ~)

#define CD_PAIR_SKIP(...)
#define CD_PAIR_SELECT_0(macro) macro
#define CD_PAIR_SELECT_1(macro) CD_PAIR_SKIP
#define CD_PAIR_TYPED(column, macro) CD_PAIR_CAT(CD_PAIR_SELECT_, CD_PAIR_IS_UNTYPED(column))(macro)

/* A Distance column is GJK (cd2Distance / cd3Distance run GJK on the pair's cores), CLOSED_FORM
 * (GJK too, and the pair also has a public closest-points function or, in 3D, an exact half-space
 * path) or the name of a closed-form distance function that the dispatcher calls instead of GJK.
 * CD_PAIR_CLOSED(Distance, MACRO) expands MACRO for such a name only. */
#define CD_PAIR_DPROBE_GJK ~, 1
#define CD_PAIR_DPROBE_CLOSED_FORM ~, 1
#define CD_PAIR_IS_GJK(column) CD_PAIR_SECOND_I(CD_PAIR_CAT(CD_PAIR_DPROBE_, column), 0, ~)
#define CD_PAIR_CLOSED(column, macro) CD_PAIR_CAT(CD_PAIR_SELECT_, CD_PAIR_IS_GJK(column))(macro)

/* The same for a shape table column that may be NONE (MakeCore, Radius): CD_SHAPE_HAS(Radius,
 * MACRO)(args) expands MACRO(args) when the column names something, nothing for NONE. */
#define CD_SHAPE_HAS(column, macro) CD_PAIR_TYPED(column, macro)

#endif
