/* The layout of cd3Mesh, shared by the builder (src/geometry/mesh3.c) and the queries
 * (src/query/mesh_query3.c, mesh_manifold3.c). Not installed. */
#ifndef COLLIDE_MESH3_INTERNAL_H
#define COLLIDE_MESH3_INTERNAL_H

#include "collide/mesh3.h"

/* An 8-wide node, 256 bytes (four cache lines) in both builds: the bounds of its children side by
 * side (row r of bounds is min x, min y, min z, max x, max y, max z; column j is child j), in
 * float rounded outward from the triangles' cdReal bounds, so that a ray tests four children with
 * one 4-lane operation per row. child[j] is an inner node's index (>= 1, the root is 0), a leaf
 * (negative, see below) or CD3_MESH_EMPTY; the `used` children come first, and an empty child's
 * bounds are min FLT_MAX, max -FLT_MAX. A leaf holds the triangles first .. first + count - 1 of
 * the reordered arrays. The nodes are in depth-first order (a child after its parent). */
#define CD3_MESH_WIDTH 8

typedef struct cd3MeshNode
{
	float bounds[6][CD3_MESH_WIDTH];
	int32_t child[CD3_MESH_WIDTH];
	int32_t used;		   /* children in use: child[0 .. used - 1] */
	int32_t firstTriangle; /* the subtree's triangles are firstTriangle .. (leaf order) */
	/* Child j's triangles start at firstTriangle + childOffset[j] and number childSpan[j]; 0xffff
	 * and 255 when they do not fit. Only hints for prefetching. */
	uint16_t childOffset[CD3_MESH_WIDTH];
	uint8_t childSpan[CD3_MESH_WIDTH];
} cd3MeshNode;

#define CD3_MESH_EMPTY (-1)

/* A leaf child: ~(first << 4 | count), with 1 <= count <= 15 and first < 2^24. */
static inline int32_t cd3MeshLeafChild(int32_t first, int32_t count)
{
	return ~(int32_t)((uint32_t)first << 4 | (uint32_t)count);
}

static inline bool cd3MeshIsLeaf(int32_t child)
{
	return child < CD3_MESH_EMPTY;
}

static inline int32_t cd3MeshLeafFirst(int32_t child)
{
	return (int32_t)((uint32_t)~child >> 4);
}

static inline int32_t cd3MeshLeafCount(int32_t child)
{
	return (int32_t)((uint32_t)~child & 15u);
}

/* Deepest tree the builder makes: below depth CD3_MESH_SAH_DEPTH it splits at the median index,
 * which adds at most log2(CD3_MAX_MESH_TRIANGLES) = 24 levels. The wide tree collapses that
 * binary tree and is no deeper. Query stacks are sized by it: a walk that pushes up to
 * CD3_MESH_WIDTH children per node holds at most CD3_MESH_WIDTH - 1 entries per level plus one. */
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
	int nodeCount; /* wide nodes */
	int leafCount;
	int depth;
	int activeEdgeCount;
	double sahCost;
	size_t bytes;
	cd3Aabb bounds;
	cd3MeshNode* nodes;		/* nodeCount, root at 0, 64-byte aligned */
	cd3Triangle* triangles; /* triangleCount, in leaf order */
	int32_t* inputIndex;	/* triangleCount: the input index of each */
	uint8_t* edgeFlags;		/* triangleCount */
	int32_t* slotOfInput;	/* inputTriangleCount: where each input triangle went, -1 when dropped */
};

#endif
