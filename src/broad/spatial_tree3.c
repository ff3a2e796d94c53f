/* collide: the 3D loose octree (shared body in spatial_tree.inc). */
#define CD_DIM 3
#include "broad/spatial_tree.inc"
