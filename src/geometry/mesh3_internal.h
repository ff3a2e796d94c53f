/* The layout of cd3Mesh, shared by the builder (src/geometry/mesh3.c) and the queries
 * (src/query/mesh_query3.c, mesh_manifold3.c). Not installed. */
#ifndef COLLIDE_MESH3_INTERNAL_H
#define COLLIDE_MESH3_INTERNAL_H

#include "collide/mesh3.h"

/* 32 bytes in both builds: bounds (min x y z, max x y z) in float, rounded outward from the
 * triangles' cdReal bounds. An inner node (count 0) has its children at first and first + 1; a
 * leaf holds the triangles first .. first + count - 1 of the reordered arrays. */
typedef struct cd3MeshNode
{
	float bounds[6];
	int32_t first;
	int32_t count;
} cd3MeshNode;

/* Deepest tree the builder makes: below depth CD3_MESH_SAH_DEPTH it splits at the median index,
 * which adds at most log2(CD3_MAX_MESH_TRIANGLES) = 24 levels. Query stacks are sized by it. */
#define CD3_MESH_SAH_DEPTH 40
#define CD3_MESH_MAX_DEPTH 72

/* Edge flags of a triangle: edge k runs from vertex k to vertex (k + 1) % 3 (a-b, b-c, c-a). Bit k:
 * active seen from the front (the side the face normal points to), bit 3 + k: from the back. */
#define CD3_MESH_EDGE_FRONT(k) (1u << (k))
#define CD3_MESH_EDGE_BACK(k) (1u << (3 + (k)))

struct cd3Mesh
{
	int triangleCount;
	int inputTriangleCount;
	int vertexCount;
	int droppedTriangleCount;
	int nodeCount;
	int leafCount;
	int depth;
	int activeEdgeCount;
	double sahCost;
	size_t bytes;
	cd3Aabb bounds;
	cd3MeshNode* nodes;		/* nodeCount, root at 0 */
	cd3Triangle* triangles; /* triangleCount, in leaf order */
	int32_t* inputIndex;	/* triangleCount: the input index of each */
	uint8_t* edgeFlags;		/* triangleCount */
	int32_t* slotOfInput;	/* inputTriangleCount: where each input triangle went, -1 when dropped */
};

#endif
