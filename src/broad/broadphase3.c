/* collide: the 3D broadphase frontend (shared body in broadphase.inc). */
#define CD_DIM 3
#include "broad/broadphase.inc"
