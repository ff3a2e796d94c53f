/* collide: broadphase. Keeps the bounding boxes of many objects ("proxies") and answers which
 * pairs overlap, what lies in a box and what a ray meets, so that exact tests run only there.
 *
 * One interface, several structures, chosen at creation (cdBroadPhaseType):
 *   CD_BROADPHASE_TREE          dynamic AABB tree (SAH insertion with rotations, full rebuild)
 *   CD_BROADPHASE_SAP           sweep-and-prune along one axis
 *   CD_BROADPHASE_GRID          uniform hash grid, for many objects of similar size
 *   CD_BROADPHASE_SPATIAL_TREE  quadtree (2D) / octree (3D)
 * Every structure gives the same answers (tests compare each with brute force); they differ in
 * speed and memory per scene (docs/BROADPHASE.md says which suits what).
 *
 * Proxies store a fat box: the tight box grown by a margin and stretched along the predicted
 * displacement, so that most small moves change nothing. Queries, ray casts and pairs work on
 * the fat boxes (a superset of the tight ones: the exact tests that follow filter).
 * Proxy ids are small non-negative ints, reused after destruction.
 * Not thread-safe for writes; const queries may run concurrently. */
#ifndef COLLIDE_BROAD_H
#define COLLIDE_BROAD_H

#include "collide/geometry2.h"
#include "collide/geometry3.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum cdBroadPhaseType
{
	CD_BROADPHASE_TREE,
	CD_BROADPHASE_SAP,
	CD_BROADPHASE_GRID,
	CD_BROADPHASE_SPATIAL_TREE,
	CD_BROADPHASE_TYPE_COUNT
} cdBroadPhaseType;

/* "tree", "sap", "grid", "quadtree/octree"; "unknown" when out of range. */
CD_API const char* cdGetBroadPhaseTypeName(cdBroadPhaseType type);

#define CD_NULL_PROXY (-1)

typedef struct cdBroadPhaseStats
{
	int proxyCount;
	int nodeCount;		/* tree nodes, grid cells in use, spatial-tree nodes, SAP endpoints */
	int height;			/* tree height / spatial-tree depth; 0 for flat structures */
	size_t memoryBytes; /* bytes allocated by the structure */
	double sahCost; /* tree: sum of internal node areas / root area (surface area heuristic); 0 otherwise */
} cdBroadPhaseStats;

/* A pair of proxies with overlapping fat boxes, proxyA < proxyB. */
typedef struct cdProxyPair
{
	int proxyA, proxyB;
} cdProxyPair;

/* Called for each pair found by UpdatePairs. */
typedef void cdBroadPairFcn(int proxyA, int proxyB, uint64_t userDataA, uint64_t userDataB, void* context);

/* ==== 3D ==================================================================================== */

typedef struct cd3BroadPhaseDef
{
	cdBroadPhaseType type;
	/* Fat-box margin added on every side (default 0.1 m, scaled by the length units). */
	cdReal margin;
	/* Predicted displacement is multiplied by this before stretching the fat box (default 4). */
	cdReal displacementMultiplier;
	/* Grid cell edge length; 0 picks one from the first proxies (about twice their mean size). */
	cdReal cellSize;
	/* Octree root region; proxies outside it are kept in the root (default +-1000 m). */
	cd3Aabb bounds;
	/* Proxies to reserve room for (default 0). */
	int capacity;
} cd3BroadPhaseDef;

CD_API cd3BroadPhaseDef cd3DefaultBroadPhaseDef(void);

typedef struct cd3BroadPhase cd3BroadPhase;

/* Returns CD_ERROR_INVALID_ARGUMENT for a bad def (unknown type, negative or NaN margin, ...),
 * CD_ERROR_OUT_OF_MEMORY, or CD_OK with *out set. */
CD_API cdResult cd3CreateBroadPhase(const cd3BroadPhaseDef* def, cd3BroadPhase** out);
CD_API void cd3DestroyBroadPhase(cd3BroadPhase* broadPhase);

/* Adds a proxy with the tight box `aabb`; returns its id, or CD_NULL_PROXY when the box is
 * invalid (NaN/Inf, min > max) or memory runs out. A new proxy counts as moved. */
CD_API int cd3BroadPhase_CreateProxy(cd3BroadPhase* broadPhase, cd3Aabb aabb, uint64_t userData);
CD_API void cd3BroadPhase_DestroyProxy(cd3BroadPhase* broadPhase, int proxyId);

/* Tells the proxy its new tight box and its predicted displacement for the next step. Returns
 * true when the fat box had to change (the proxy then counts as moved), false when the new box
 * still fits in the old fat box and that fat box is not too large (nothing to do). The fat box
 * also changes, and the call returns true, when the new box still fits but the old fat box sticks
 * out of the box it would get with 4 times the margin and 4 times the displacement stretch (it
 * was stretched by a fast move that has stopped): it is then rebuilt around the new box, so that
 * it does not report needless pairs forever. An invalid box is ignored (returns false). */
CD_API bool cd3BroadPhase_MoveProxy(cd3BroadPhase* broadPhase, int proxyId, cd3Aabb aabb,
									cd3Vec displacement);

/* Moves `count` proxies at once: the same fat boxes, return values (in outChanged[i], when not
 * NULL) and pairs as calling MoveProxy(proxyIds[i], aabbs[i], displacements[i]) for i = 0, 1, ...
 * in turn (an id may appear more than once; displacements may be NULL: all zero), but the
 * structure takes the changed boxes in spatial order, which finds far more of it in cache when
 * there are many (a physics step's all bodies at once). Returns how many calls changed a fat box.
 * When memory runs out inside the structure, a proxy whose update fails keeps the fat box it had
 * before the call and its last changing entry reports false. */
CD_API int cd3BroadPhase_MoveProxies(cd3BroadPhase* broadPhase, int count, const int* proxyIds,
									 const cd3Aabb* aabbs, const cd3Vec* displacements, bool* outChanged);

CD_API cd3Aabb cd3BroadPhase_GetFatAabb(const cd3BroadPhase* broadPhase, int proxyId);
CD_API uint64_t cd3BroadPhase_GetUserData(const cd3BroadPhase* broadPhase, int proxyId);
CD_API int cd3BroadPhase_GetProxyCount(const cd3BroadPhase* broadPhase);

/* Return false to stop the query early. */
typedef bool cd3BroadQueryFcn(int proxyId, uint64_t userData, void* context);

/* Calls fcn for every proxy whose fat box overlaps `aabb` (closed boxes), until it returns false. */
CD_API void cd3BroadPhase_Query(const cd3BroadPhase* broadPhase, cd3Aabb aabb, cd3BroadQueryFcn* fcn,
								void* context);

/* Ray-cast callback: `ray` is the caller's ray and maxFraction the current clip. Return
 *   0                     to stop the ray cast (any-hit),
 *   f in (0, maxFraction) to clip the ray to f (closest-hit: return the exact hit fraction),
 *   maxFraction           to go on unchanged (missed, or no clipping wanted),
 *   a negative value      to ignore this proxy and go on. */
typedef cdReal cd3BroadRayFcn(cd3Ray ray, cdReal maxFraction, int proxyId, uint64_t userData, void* context);

/* Calls fcn for the proxies whose fat box the ray (clipped to the current max fraction) meets,
 * nearest boxes first where the structure allows. */
CD_API void cd3BroadPhase_Raycast(const cd3BroadPhase* broadPhase, cd3Ray ray, cd3BroadRayFcn* fcn,
								  void* context);

/* Reports every pair of proxies whose fat boxes overlap and at least one of which moved (was
 * created or had its fat box changed) since the last call; each pair once, proxyA < proxyB,
 * sorted by (proxyA, proxyB) so that the order depends only on the operations. Then forgets
 * the moves. Returns the number of pairs. fcn may be NULL (only count). */
CD_API int cd3BroadPhase_UpdatePairs(cd3BroadPhase* broadPhase, cdBroadPairFcn* fcn, void* context);

/* Reports every pair of proxies whose fat boxes overlap, moved or not, in the same order as
 * UpdatePairs (each pair once, proxyA < proxyB, sorted). Leaves the moves alone. Returns the
 * number of pairs; fcn may be NULL. (For comparisons with libraries that report full sets.) */
CD_API int cd3BroadPhase_FindAllPairs(cd3BroadPhase* broadPhase, cdBroadPairFcn* fcn, void* context);

/* Adds `count` proxies at once (faster than one by one: an empty tree is bulk-built).
 * outIds[i] receives the id of boxes[i], or CD_NULL_PROXY for an invalid box. userData may be
 * NULL (all zero). Returns the number of proxies created. */
CD_API int cd3BroadPhase_CreateProxies(cd3BroadPhase* broadPhase, const cd3Aabb* boxes,
									   const uint64_t* userData, int count, int* outIds);

/* Rebuilds the structure from scratch for the current boxes (tree: a fast top-down SAH build,
 * best after bulk loading or for static sets; others: re-sort/re-bin). Queries give the same
 * answers before and after. */
CD_API void cd3BroadPhase_Rebuild(cd3BroadPhase* broadPhase);

CD_API cdBroadPhaseStats cd3BroadPhase_GetStats(const cd3BroadPhase* broadPhase);

/* Checks every invariant of the structure (parent/child links, boxes containing children,
 * heights, free lists, sortedness, cell membership, ...); true when all hold. Allocates nothing,
 * except for a degenerate tree deeper than 254 levels (false if that memory is not there). */
CD_API bool cd3BroadPhase_Validate(const cd3BroadPhase* broadPhase);

/* ==== 2D (the same contract with 2D boxes) ================================================== */

typedef struct cd2BroadPhaseDef
{
	cdBroadPhaseType type;
	cdReal margin;
	cdReal displacementMultiplier;
	cdReal cellSize;
	cd2Aabb bounds; /* quadtree root region */
	int capacity;
} cd2BroadPhaseDef;

CD_API cd2BroadPhaseDef cd2DefaultBroadPhaseDef(void);

typedef struct cd2BroadPhase cd2BroadPhase;

CD_API cdResult cd2CreateBroadPhase(const cd2BroadPhaseDef* def, cd2BroadPhase** out);
CD_API void cd2DestroyBroadPhase(cd2BroadPhase* broadPhase);
CD_API int cd2BroadPhase_CreateProxy(cd2BroadPhase* broadPhase, cd2Aabb aabb, uint64_t userData);
CD_API void cd2BroadPhase_DestroyProxy(cd2BroadPhase* broadPhase, int proxyId);
CD_API bool cd2BroadPhase_MoveProxy(cd2BroadPhase* broadPhase, int proxyId, cd2Aabb aabb,
									cd2Vec displacement);
CD_API int cd2BroadPhase_MoveProxies(cd2BroadPhase* broadPhase, int count, const int* proxyIds,
									 const cd2Aabb* aabbs, const cd2Vec* displacements, bool* outChanged);
CD_API cd2Aabb cd2BroadPhase_GetFatAabb(const cd2BroadPhase* broadPhase, int proxyId);
CD_API uint64_t cd2BroadPhase_GetUserData(const cd2BroadPhase* broadPhase, int proxyId);
CD_API int cd2BroadPhase_GetProxyCount(const cd2BroadPhase* broadPhase);

typedef bool cd2BroadQueryFcn(int proxyId, uint64_t userData, void* context);
CD_API void cd2BroadPhase_Query(const cd2BroadPhase* broadPhase, cd2Aabb aabb, cd2BroadQueryFcn* fcn,
								void* context);

typedef cdReal cd2BroadRayFcn(cd2Ray ray, cdReal maxFraction, int proxyId, uint64_t userData, void* context);
CD_API void cd2BroadPhase_Raycast(const cd2BroadPhase* broadPhase, cd2Ray ray, cd2BroadRayFcn* fcn,
								  void* context);

CD_API int cd2BroadPhase_UpdatePairs(cd2BroadPhase* broadPhase, cdBroadPairFcn* fcn, void* context);
CD_API int cd2BroadPhase_FindAllPairs(cd2BroadPhase* broadPhase, cdBroadPairFcn* fcn, void* context);
CD_API int cd2BroadPhase_CreateProxies(cd2BroadPhase* broadPhase, const cd2Aabb* boxes,
									   const uint64_t* userData, int count, int* outIds);
CD_API void cd2BroadPhase_Rebuild(cd2BroadPhase* broadPhase);
CD_API cdBroadPhaseStats cd2BroadPhase_GetStats(const cd2BroadPhase* broadPhase);
CD_API bool cd2BroadPhase_Validate(const cd2BroadPhase* broadPhase);

/* Former names (before the naming rule of CONTRIBUTING.md), kept as aliases for one release so
 * that code written against them still builds; tests/check_names.py accepts exactly these. */
#define cd2BroadPhase_Create cd2CreateBroadPhase
#define cd2BroadPhase_Destroy cd2DestroyBroadPhase
#define cd3BroadPhase_Create cd3CreateBroadPhase
#define cd3BroadPhase_Destroy cd3DestroyBroadPhase
#define cd2BroadPhase_RayCast cd2BroadPhase_Raycast
#define cd3BroadPhase_RayCast cd3BroadPhase_Raycast
#define cdBroadPhaseTypeName cdGetBroadPhaseTypeName

#ifdef __cplusplus
}
#endif

#endif
