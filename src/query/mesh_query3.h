/* Internal helpers shared by the mesh queries (mesh_query3.c) and manifolds (mesh_manifold3.c). */
#ifndef COLLIDE_MESH_QUERY3_H
#define COLLIDE_MESH_QUERY3_H

#include "geometry/mesh3_internal.h"

/* Called with the slot (index in the reordered arrays) of each triangle whose node bounds overlap;
 * returns false to stop. */
typedef bool cd3MeshSlotFcn(int slot, void* context);

/* Visits the leaves' triangles overlapping `bounds` (mesh space). false when a visit stopped it. */
bool cd3MeshVisitSlots(const cd3Mesh* mesh, cd3Aabb bounds, cd3MeshSlotFcn* visit, void* context);

/* Bounds in the mesh's frame of a world box, padded for round-off; everything when the box is
 * unbounded. */
cd3Aabb cd3MeshBoundsOfWorldAabb(cd3Transform meshTransform, cd3Aabb world);

#endif
