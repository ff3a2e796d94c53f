/* collide: 3D sweep-and-prune (shared body in sap.inc). */
#define CD_DIM 3
#include "broad/sap.inc"
