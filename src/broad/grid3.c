/* collide: the 3D uniform hash grid (shared body in grid.inc). */
#define CD_DIM 3
#include "broad/grid.inc"
