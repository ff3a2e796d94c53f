/* collide: the one mechanism for source written once for 2D and 3D.
 *
 * Define CD_DIM to 2 or 3, then include this header. It may be included again after redefining
 * CD_DIM (it is not include-guarded on purpose: every macro is #undef'd and redefined). It gives:
 *
 *   CD_DIM_NAME(Name)   cd2Name or cd3Name: a function or type of the current dimension, also
 *                       the small vector operations of math2.h / math3.h, which have the same
 *                       names in both (CD_DIM_NAME(Add), Sub, Scale, Dot, Min, Max, Clamp,
 *                       Normalize, IsValidVec, AabbUnion, AabbContains ...)
 *   CD_DIM_UPPER(NAME)  CD2_NAME or CD3_NAME: a constant or macro of the current dimension
 *   CD_VEC, CD_AABB, CD_RAY, CD_SHAPE, CD_TRANSFORM, CD_SWEEP
 *                       the value types of the current dimension
 *   CD_VEC_ZERO         the zero vector of the current dimension
 *
 * The value of CD_DIM itself is the number of axes (loops `for (int i = 0; i < CD_DIM; ++i)`).
 * A template file (broadphase.inc, cast.inc ...) is included by a two-line file per dimension:
 *
 *     #define CD_DIM 2
 *     #include "broad/tree.inc"      (which includes "base/dim.h")
 *
 * Everything expands to the names a hand-written 2D or 3D file would use, so the object code is
 * the same as that of such a file. */
#include "collide/geometry2.h"
#include "collide/geometry3.h"

#undef CD_DIM_CAT
#undef CD_DIM_CAT2
#undef CD_DIM_NAME
#undef CD_DIM_UPPER
#undef CD_VEC
#undef CD_AABB
#undef CD_RAY
#undef CD_SHAPE
#undef CD_TRANSFORM
#undef CD_SWEEP
#undef CD_VEC_ZERO

#define CD_DIM_CAT2(a, b) a##b
#define CD_DIM_CAT(a, b) CD_DIM_CAT2(a, b)

#if CD_DIM == 2
#define CD_DIM_NAME(name) CD_DIM_CAT(cd2, name)
#define CD_DIM_UPPER(name) CD_DIM_CAT(CD2_, name)
#define CD_VEC cd2Vec
#define CD_AABB cd2Aabb
#define CD_RAY cd2Ray
#define CD_SHAPE cd2Shape
#define CD_TRANSFORM cd2Transform
#define CD_SWEEP cd2Sweep
#define CD_VEC_ZERO CD2_VEC_ZERO
#elif CD_DIM == 3
#define CD_DIM_NAME(name) CD_DIM_CAT(cd3, name)
#define CD_DIM_UPPER(name) CD_DIM_CAT(CD3_, name)
#define CD_VEC cd3Vec
#define CD_AABB cd3Aabb
#define CD_RAY cd3Ray
#define CD_SHAPE cd3Shape
#define CD_TRANSFORM cd3Transform
#define CD_SWEEP cd3Sweep
#define CD_VEC_ZERO CD3_VEC_ZERO
#else
#error "define CD_DIM to 2 or 3 before including base/dim.h"
#endif
