/* collide: the uniform hash grid backend (grid.inc, built as grid2.c and grid3.c). Included by
 * broad_internal.h, after the backend types it uses. */
#ifndef COLLIDE_BROAD_GRID_H
#define COLLIDE_BROAD_GRID_H

#define CD_BROAD_HAVE_GRID 1

extern const cd2BroadBackend cd2BroadGridBackend;
extern const cd3BroadBackend cd3BroadGridBackend;

#endif
