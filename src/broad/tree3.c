/* collide: the 3D dynamic AABB tree (shared body in tree.inc). */
#define CD_DIM 3
#include "broad/tree.inc"
