/* collide: the 2D broadphase frontend (shared body in broadphase.inc). */
#define CD_DIM 2
#include "broad/broadphase.inc"
