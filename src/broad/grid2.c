/* collide: the 2D uniform hash grid (shared body in grid.inc). */
#define CD_DIM 2
#include "broad/grid.inc"
