/* collide: the 2D loose quadtree (shared body in spatial_tree.inc). */
#define CD_DIM 2
#include "broad/spatial_tree.inc"
