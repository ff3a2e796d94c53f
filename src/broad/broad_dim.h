/* collide: dimension-generic names for broadphase code written once for 2D and 3D.
 * Define CD_BROAD_DIM to 2 or 3, then include this header (it may be included again after
 * redefining CD_BROAD_DIM). Not include-guarded on purpose. */
#include "broad/broad_internal.h"

#undef BD
#undef BD_CAT
#undef BD_CAT2
#undef BD_AXES
#undef bdVec
#undef bdAabb
#undef bdRay
#undef bdRayData
#undef bdBoxOverlap
#undef bdBoxCost
#undef bdBoxValid
#undef bdBoxEqual
#undef bdBoxUnion
#undef bdBoxContains
#undef bdComponent
#undef bdPrepareRay
#undef bdRayBox

#define BD_CAT2(a, b) a##b
#define BD_CAT(a, b) BD_CAT2(a, b)

#if CD_BROAD_DIM == 2
#define BD(name) BD_CAT(cd2, name)
#define BD_AXES 2
#define bdVec cd2Vec
#define bdAabb cd2Aabb
#define bdRay cd2Ray
#define bdRayData cd2BroadRayData
#define bdBoxOverlap cd2BroadBoxOverlap
#define bdBoxCost cd2BroadBoxCost
#define bdBoxValid cd2BroadBoxValid
#define bdBoxEqual cd2BroadBoxEqual
#define bdBoxUnion cd2AabbUnion
#define bdBoxContains cd2AabbContains
#define bdComponent cd2BroadComponent
#define bdPrepareRay cd2BroadPrepareRay
#define bdRayBox cd2BroadRayBox
#elif CD_BROAD_DIM == 3
#define BD(name) BD_CAT(cd3, name)
#define BD_AXES 3
#define bdVec cd3Vec
#define bdAabb cd3Aabb
#define bdRay cd3Ray
#define bdRayData cd3BroadRayData
#define bdBoxOverlap cd3BroadBoxOverlap
#define bdBoxCost cd3BroadBoxCost
#define bdBoxValid cd3BroadBoxValid
#define bdBoxEqual cd3BroadBoxEqual
#define bdBoxUnion cd3AabbUnion
#define bdBoxContains cd3AabbContains
#define bdComponent cd3BroadComponent
#define bdPrepareRay cd3BroadPrepareRay
#define bdRayBox cd3BroadRayBox
#else
#error "define CD_BROAD_DIM to 2 or 3 before including broad_dim.h"
#endif

#undef bdAdd
#undef bdSub
#undef bdScale
#undef bdVecMin
#undef bdVecMax
#undef bdClampVec
#undef bdIsValidVec
#undef bdVecZero
#if CD_BROAD_DIM == 2
#define bdAdd cd2Add
#define bdSub cd2Sub
#define bdScale cd2Scale
#define bdVecMin cd2Min
#define bdVecMax cd2Max
#define bdClampVec cd2Clamp
#define bdIsValidVec cd2IsValidVec
#define bdVecZero CD2_VEC_ZERO
#else
#define bdAdd cd3Add
#define bdSub cd3Sub
#define bdScale cd3Scale
#define bdVecMin cd3Min
#define bdVecMax cd3Max
#define bdClampVec cd3Clamp
#define bdIsValidVec cd3IsValidVec
#define bdVecZero CD3_VEC_ZERO
#endif
