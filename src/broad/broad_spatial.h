/* collide: the quadtree (2D) / octree (3D) backend (spatial_tree.inc, built as
 * spatial_tree2.c and spatial_tree3.c). Included by broad_internal.h, after the backend types. */
#ifndef COLLIDE_BROAD_SPATIAL_H
#define COLLIDE_BROAD_SPATIAL_H

#define CD_BROAD_HAVE_SPATIAL_TREE 1

extern const cd2BroadBackend cd2BroadSpatialTreeBackend;
extern const cd3BroadBackend cd3BroadSpatialTreeBackend;

#endif
