/* collide: 3D triangle meshes. An indexed triangle mesh with a static bounding volume hierarchy,
 * built once and immutable afterwards (one mesh can be shared by many threads), with ray casts,
 * bounds queries, overlap, closest point and contact manifolds of convex shapes against it.
 *
 * A mesh is not a cd3ShapeType: it has its own functions, each taking the mesh's placement in the
 * world (a rigid transform). Everything else is in world space, like the rest of the query API.
 * Triangles are the two-sided surface of cd3Triangle (a mesh need not be closed). See
 * docs/MESHES.md for the build, the tolerances and the internal-edge rule. */
#ifndef COLLIDE_MESH3_H
#define COLLIDE_MESH3_H

#include "collide/manifold3.h"

#ifdef __cplusplus
extern "C" {
#endif

/* At most this many vertices and this many triangles (the BVH packs indices in 24 bits). */
#define CD3_MAX_MESH_VERTICES (1 << 24)
#define CD3_MAX_MESH_TRIANGLES (1 << 24)

/* Vertex coordinates must lie within +-CD3_MESH_MAX_COORDINATE. The BVH stores float bounds
 * padded outward, so a coordinate near FLT_MAX would have no finite bound; in the float build
 * the limit also keeps squared distances finite. Both limits are far beyond the range in which
 * queries keep their documented precision (1e9 float, 1e30 double, docs/API.md). */
#if CD_DOUBLE
#define CD3_MESH_MAX_COORDINATE 1e30
#else
#define CD3_MESH_MAX_COORDINATE 1e18f
#endif

/* Opaque: one block from cdAlloc, released by cd3DestroyMesh. */
typedef struct cd3Mesh cd3Mesh;

typedef struct cd3MeshStats
{
	int triangleCount;		  /* triangles kept */
	int droppedTriangleCount; /* zero-area input triangles dropped by the builder */
	int vertexCount;		  /* input vertices */
	int nodeCount;			  /* BVH nodes (8-wide, 256 bytes each) */
	int leafCount;			  /* BVH leaves (children of nodes holding up to 8 triangles) */
	int depth;				  /* longest root-to-leaf path in nodes and leaf, root over a leaf being 2 */
	int activeEdgeCount;	  /* triangle edges that are convex, boundary or non-manifold on a side */
	double sahCost; /* SAH cost of the wide tree: sum over nodes of area/root area, leaves times their size */
	size_t bytes;	/* the whole block */
	cd3Aabb bounds; /* of the kept triangles, mesh space */
} cd3MeshStats;

/* Builds a mesh from `vertexCount` vertices and `triangleCount` triangles (3 indices each,
 * counter-clockwise seen from the front). Triangles of zero area (by the tolerance of
 * cd3IsValidTriangle) are dropped and counted in the stats; the others keep their input index,
 * which the queries report. Neighbouring triangles are found through shared vertex indices and
 * vertices at exactly the same position. On success *mesh receives a new mesh (free it with
 * cd3DestroyMesh); on failure *mesh is NULL and the result says why: CD_ERROR_INVALID_ARGUMENT
 * (NULL pointer, count <= 0, an index out of range), CD_ERROR_TOO_MANY_POINTS (a count above
 * its limit), CD_ERROR_NOT_FINITE,
 * CD_ERROR_OUT_OF_RANGE (a coordinate beyond CD3_MESH_MAX_COORDINATE), CD_ERROR_DEGENERATE (every triangle
 * has zero area), CD_ERROR_OUT_OF_MEMORY. */
CD_API cdResult cd3CreateMesh(const cd3Vec* vertices, int vertexCount, const int* indices, int triangleCount,
							  cd3Mesh** mesh);
CD_API void cd3DestroyMesh(cd3Mesh* mesh);

/* Checks the BVH (every triangle in exactly one leaf, children inside their parents' bounds,
 * bounds enclosing their triangles, depth within the limit), finite data and edge flags. O(n). */
CD_API cdResult cd3ValidateMesh(const cd3Mesh* mesh);

CD_API cd3MeshStats cd3Mesh_GetStats(const cd3Mesh* mesh);

/* Number of kept triangles, and a triangle by its input index (in mesh space). A dropped or
 * out-of-range index gives false. */
CD_API int cd3Mesh_GetTriangleCount(const cd3Mesh* mesh);
CD_API bool cd3Mesh_GetTriangle(const cd3Mesh* mesh, int triangleIndex, cd3Triangle* triangle);

/* A ray hit on a mesh: the cd3RayHit of cd3RaycastTriangle on the triangle hit (world space) and
 * that triangle's input index. */
typedef struct cd3MeshRayHit
{
	cd3RayHit hit;
	int triangleIndex;
} cd3MeshRayHit;

/* The first hit along the ray (closest fraction; the lowest input index among equal fractions).
 * true and *hit filled on a hit; *hit untouched on a miss. */
CD_API bool cd3RaycastMesh(const cd3Mesh* mesh, cd3Transform meshTransform, cd3Ray ray, cd3MeshRayHit* hit);

/* Whether the ray hits any triangle (stops at the first found; for shadow and line-of-sight tests). */
CD_API bool cd3RaycastMeshAny(const cd3Mesh* mesh, cd3Transform meshTransform, cd3Ray ray);

/* Calls `callback` with the input index of every triangle whose bounds overlap `bounds` (mesh
 * space), until it returns false. Returns false when the callback stopped the query. */
typedef bool cd3MeshQueryFcn(int triangleIndex, void* context);
CD_API bool cd3Mesh_QueryAabb(const cd3Mesh* mesh, cd3Aabb bounds, cd3MeshQueryFcn* callback, void* context);

/* true when the shape (world space, any type) touches a triangle of the mesh: the OR of cd3Overlap
 * over the triangles. */
CD_API bool cd3OverlapMesh(const cd3Shape* shape, const cd3Mesh* mesh, cd3Transform meshTransform);

/* The closest point of the mesh to p (world space). */
typedef struct cd3MeshClosestPoint
{
	cd3Vec point;
	cdReal distance;
	int triangleIndex;
} cd3MeshClosestPoint;

/* Branch and bound on the BVH: nearer children first, nodes farther than the best so far skipped.
 * Ties go to the lowest input index. Only points farther than maxDistance are missed (false);
 * pass CD_REAL_MAX for no limit. */
CD_API bool cd3ClosestPointOnMesh(const cd3Mesh* mesh, cd3Transform meshTransform, cd3Vec p,
								  cdReal maxDistance, cd3MeshClosestPoint* result);

/* ---- manifolds ---------------------------------------------------------------------------------
 * One manifold per triangle in contact, with the convex shape as A and the triangle as B (normal
 * from the shape to the triangle), from cd3Collide*Triangle, with ids as that function gives them:
 * (triangleIndex, id) is the key that stays the same from frame to frame.
 *
 * Internal edges: each triangle edge knows, for each side of the triangle, whether it is active
 * (convex seen from that side, or a boundary, or shared by more than two triangles) or internal
 * (flat within CD3_MESH_FLAT_EDGE_SINE, or concave). A contact whose normal is not the triangle's
 * face normal and whose points all lie on internal edges and vertices (a vertex is internal when
 * both its edges in the triangle are) is recomputed along the face normal: the shape's supporting
 * face clipped to the triangle, so a shape sliding over a flat tessellated floor only ever gets
 * the floor's normal. */
#define CD3_MESH_FLAT_EDGE_SINE CD_R(0.01)

typedef struct cd3MeshManifold
{
	cd3Manifold manifold;
	int triangleIndex;
} cd3MeshManifold;

/* Supports the shapes of cd3Collide against a triangle: sphere, capsule, AABB, box and hull.
 * Writes at most `capacity` manifolds (those of the triangles met first in the BVH when there are
 * more) and returns how many it wrote; 0 for unsupported shapes. */
CD_API int cd3CollideMesh(const cd3Shape* shape, const cd3Mesh* mesh, cd3Transform meshTransform,
						  cdReal speculativeDistance, cd3MeshManifold* manifolds, int capacity);

/* Former names (before the naming rule of CONTRIBUTING.md), kept as aliases for one release so
 * that code written against them still builds; tests/check_names.py accepts exactly these. */
#define cd3GetMeshStats cd3Mesh_GetStats
#define cd3GetMeshTriangleCount cd3Mesh_GetTriangleCount
#define cd3GetMeshTriangle cd3Mesh_GetTriangle

#ifdef __cplusplus
}
#endif

#endif
