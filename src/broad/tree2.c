/* collide: the 2D dynamic AABB tree (shared body in tree.inc). */
#define CD_DIM 2
#include "broad/tree.inc"
