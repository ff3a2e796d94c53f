/* collide: 2D sweep-and-prune (shared body in sap.inc). */
#define CD_DIM 2
#include "broad/sap.inc"
