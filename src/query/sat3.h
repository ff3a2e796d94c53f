/* collide (internal): polytopes (boxes, hulls, triangles) in one form, and the separating axis test
 * between two of them or between a point/segment core and one. Not installed. */
#ifndef COLLIDE_SAT3_H
#define COLLIDE_SAT3_H

#include "collide/geometry3.h"

/* cd3Hull.queryData: a header, then the columns (cdReal) of the unique edges' arcs cross(nb, na)
 * (x, y, z, each edgePadded entries), of the face normals (x, y, z, each facePadded entries), then
 * EdgesOfFaces' tables (facePadded / 4 of 16 uint64_t), then the unique edges' half-edge indices
 * (the half-edge below its twin, in index order; edgePadded int32_t), then their faces (the
 * half-edge's, then its twin's; 2 edgePadded int32_t). Padding is zero. */
#define CD3_HULL_QUERY_EDGES 32
#define CD3_HULL_QUERY_FACES 16

typedef struct cd3HullQueryData
{
	int32_t edgeCount, edgePadded, faceCount, facePadded;
} cd3HullQueryData;

static inline const cdReal* cd3HullQueryArcs(const cd3HullQueryData* q)
{
	return (const cdReal*)(const void*)(q + 1);
}

static inline const cdReal* cd3HullQueryFaces(const cd3HullQueryData* q)
{
	return cd3HullQueryArcs(q) + 3 * q->edgePadded;
}

static inline const uint64_t (*cd3HullQueryTables(const cd3HullQueryData* q))[16]
{
	return (const uint64_t(*)[16])(const void*)(cd3HullQueryFaces(q) + 3 * q->facePadded);
}

static inline const int32_t* cd3HullQueryEdges(const cd3HullQueryData* q)
{
	return (const int32_t*)(const void*)(cd3HullQueryTables(q) + q->facePadded / 4);
}

static inline const int32_t* cd3HullQueryEdgeFaces(const cd3HullQueryData* q)
{
	return cd3HullQueryEdges(q) + q->edgePadded;
}

/* Bytes of the query data of a hull with these counts (a multiple of 16), 0 when it gets none. */
size_t cd3HullQueryDataSize(int halfEdgeCount, int faceCount);

/* Fills `memory` (cd3HullQueryDataSize bytes, 16-byte aligned) from the hull's edges, planes and
 * counts, which must be valid. */
void cd3BuildHullQueryData(const cd3Hull* hull, void* memory);

/* A polytope placed in the world: the half-edge data of a hull in its local frame plus the
 * transform. Boxes and triangles keep their vertices and planes in the storage arrays, so a
 * polytope must not be copied after it is initialized. A triangle is flat: two faces (front and
 * back) sharing three edges; its edge axes are tested by projection, not by Gauss-map pruning. */
typedef struct cd3Polytope
{
	const cd3Vec* vertices;
	const cd3HullHalfEdge* edges;
	const int32_t* faceEdges;
	const cd3Plane* planes;
	int vertexCount, edgeCount, faceCount;
	int edgeAxisCount; /* half-edges the edge axes come from: 1 for a collinear triangle */
	cd3Vec centroid;   /* local, strictly inside unless flat */
	cd3Transform transform;
	const cd3HullQueryData* query; /* the hull's precomputed data, or NULL */
	bool flat;
	cdReal size; /* diagonal of the local bounds: the scale of tolerances */
	cd3Shape shape;
	cd3Vec vertexStorage[8];
	cd3Plane planeStorage[6];
} cd3Polytope;

void cd3InitBoxPolytope(cd3Polytope* polytope, cd3Box box);
void cd3InitHullPolytope(cd3Polytope* polytope, cd3HullShape hull);
void cd3InitTrianglePolytope(cd3Polytope* polytope, cd3Triangle triangle);

typedef enum cd3SatFeature
{
	CD3_SAT_FACE_A,
	CD3_SAT_FACE_B,
	CD3_SAT_EDGES
} cd3SatFeature;

/* Best axis of each kind. separation is the largest over face normals of A, of B and over edge
 * pairs (the exact signed depth is the largest of the three; -CD_REAL_MAX when a kind has no valid
 * axis). Face indices and half-edge indices refer to the polytopes; edgeNormal is in world space,
 * pointing from A to B. */
typedef struct cd3SatResult
{
	cdReal faceSeparationA, faceSeparationB, edgeSeparation;
	int faceA, faceB;
	int edgeA, edgeB;
	cd3Vec edgeNormal;
} cd3SatResult;

cd3SatResult cd3SatPolytopes(const cd3Polytope* a, const cd3Polytope* b);

/* The same, but it may stop as soon as one axis separates the polytopes by more than `limit`:
 * then cd3SatSeparation of the result exceeds `limit` and nothing else in it is exact. Exact when
 * the separation is at most `limit`. */
cd3SatResult cd3SatPolytopesWithin(const cd3Polytope* a, const cd3Polytope* b, cdReal limit);

/* cd3SatPolytopesWithin that skips the edge pairs that cannot separate the polytopes by more than
 * the best face axis less `slack` (nor by more than zero), when the other polytope has a vertex that
 * far below both faces of one of their edges. The separation (cd3SatSeparation) stays exact and so
 * does the best edge pair when it separates by more than that floor; below it, the edge pair
 * reported may be a lesser one or none (edgeA -1). *pruned tells whether any edge was skipped: the
 * result is then cd3SatPolytopesWithin's in every field only above the floor. Solid polytopes only
 * (flat ones take every edge pair). */
cd3SatResult cd3SatPolytopesPruned(const cd3Polytope* a, const cd3Polytope* b, cdReal limit, cdReal slack,
								   bool* pruned);

/* The same for two boxes, with the fifteen axes in closed form; face and half-edge indices are
 * those of cd3InitBoxPolytope. Edge axes that do not beat the best face axis are not reported
 * (edgeA is then -1): the overall separation is still exact. Also gives B's frame in A's: rotation (B's axes
 * as columns) and translation. */
cd3SatResult cd3SatBoxes(cd3Box a, cd3Box b, cd3Mat33* rotation, cd3Vec* translation);

/* The exact signed separation of the SAT result (the largest of its three). */
static inline cdReal cd3SatSeparation(const cd3SatResult* r)
{
	return cdMax(r->edgeSeparation, cdMax(r->faceSeparationA, r->faceSeparationB));
}

/* The separating axis test between the segment p1-p2 (a point when p1 == p2; world space) and a
 * polytope: the polytope's faces and the crosses of the segment with its edges. Separation of the
 * bare segment (no radius). Feature: CD3_SAT_FACE_B with faceB, or CD3_SAT_EDGES with edgeB and
 * edgeNormal (world, from the segment to the polytope). Returns the feature kind. */
cd3SatFeature cd3SatSegmentPolytope(cd3Vec p1, cd3Vec p2, const cd3Polytope* b, cd3SatResult* result);

#endif
