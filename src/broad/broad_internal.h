/* collide: broadphase internals shared by the frontend (broadphase*.c) and the structures
 * behind it (tree, sweep-and-prune, hash grid, quadtree/octree).
 *
 * The frontend owns the proxy table (fat boxes, user data, move buffer, free list) and the pair
 * bookkeeping. A structure ("backend") only indexes proxy ids by their fat boxes and answers
 * box queries, ray casts and, optionally, the full pair set. It is plugged in through a small
 * vtable per dimension (cd2BroadBackend / cd3BroadBackend below).
 *
 * Writing a backend once for both dimensions: define CD_DIM to 2 or 3 and include "base/dim.h"
 * (the one mechanism for code shared by 2D and 3D); CD_DIM_NAME(BroadBoxOverlap) is then
 * cd2BroadBoxOverlap or cd3BroadBoxOverlap, CD_AABB, CD_VEC, CD_RAY the types of that dimension.
 * Then include a shared .inc body from a 2D and a 3D .c file (see tree2.c / tree3.c). */
#ifndef COLLIDE_BROAD_INTERNAL_H
#define COLLIDE_BROAD_INTERNAL_H

#include "collide/broad.h"

#include "base/radix_sort.h"

#include <string.h>

/* Debug operation counters (off unless built with -DCD_BROAD_COUNT_OPS): how many tree nodes
 * moves and pair queries touch, to tell algorithmic growth from cache misses in benchmarks. */
#ifdef CD_BROAD_COUNT_OPS
enum
{
	CD_BROAD_OP_TREE_MOVES,		  /* TreeMoveProxy calls */
	CD_BROAD_OP_TREE_REINSERTS,	  /* of which removed and reinserted */
	CD_BROAD_OP_TREE_DESCENT,	  /* nodes read by the SAH sibling search */
	CD_BROAD_OP_TREE_REFIT,		  /* refit steps after insertions and in-place moves (each rotates) */
	CD_BROAD_OP_TREE_QUERIES,	  /* TreeQuery calls */
	CD_BROAD_OP_TREE_QUERY_NODES, /* nodes read by queries */
	CD_BROAD_OP_GRID_CELLS,		  /* grid cells looked up by queries */
	CD_BROAD_OP_GRID_ENTRIES,	  /* grid entries read by queries */
	CD_BROAD_OP_COUNT
};
extern unsigned long long cdBroadOpCounts[CD_BROAD_OP_COUNT];
#define CD_BROAD_COUNT(op, k) (cdBroadOpCounts[op] += (unsigned long long)(k))
#else
#define CD_BROAD_COUNT(op, k) ((void)0)
#endif

/* Starts loading the cache line at p without waiting for it (a hint; nothing elsewhere). At 1M
 * proxies the tree's nodes and the proxy table no longer fit the last-level cache, so a node
 * read is a main-memory miss: issuing the reads of both children (or of the next query's box)
 * before they are needed lets several misses overlap instead of waiting for each in turn. */
#if defined(__GNUC__) || defined(__clang__)
#define CD_BROAD_PREFETCH(p) __builtin_prefetch(p)
#else
#define CD_BROAD_PREFETCH(p) ((void)0)
#endif

/* ---- callbacks from a backend to the frontend ------------------------------------------------- */

/* Box query hit: return false to stop. */
typedef bool cdBroadIdFcn(int proxyId, void* context);

/* Ray-cast hit on a proxy whose fat box the ray may meet. The return value follows the public
 * contract: 0 stops, a value in (0, maxFraction) becomes the new clip, a negative value or
 * maxFraction (or more) goes on unchanged. The backend keeps the clip and prunes with it. */
typedef cdReal cdBroadRayIdFcn(int proxyId, cdReal maxFraction, void* context);

/* Applies a ray callback's answer to the clip; true when the ray cast must stop. */
static inline bool cdBroadApplyRayAnswer(cdReal answer, cdReal* maxFraction)
{
	if (answer == CD_R(0.0))
	{
		return true;
	}
	if (answer > CD_R(0.0) && answer < *maxFraction)
	{
		*maxFraction = answer;
	}
	return false;
}

/* Overlapping pair (either order; each unordered pair exactly once per call). */
typedef void cdBroadPairSinkFcn(int proxyA, int proxyB, void* context);

/* Relative slack of the conservative ray/box slab test: a box is reported when the ray meets it
 * within a few ulps, so a backend never prunes a box an exact test in the callback would hit. */
#define CD_BROAD_RAY_SLACK (CD_R(16.0) * CD_REAL_EPSILON)

/* ---- proxy table ------------------------------------------------------------------------------ */
/* Owned by the frontend; a backend keeps the pointer it got at creation and reads the arrays
 * through it (they move when the table grows). Indexed by proxy id, size `capacity`. */
#define CD_BROAD_DECLARE_PROXY_TABLE(P, AABB)                                                                \
	typedef struct P##BroadProxyTable                                                                        \
	{                                                                                                        \
		AABB* fatBoxes;		/* current fat box of every live proxy */                                        \
		uint64_t* userData; /* user data of every live proxy */                                              \
		int* backendSlots;	/* one int per live proxy that the backend may use as it likes */                \
		int* moveIndex;		/* frontend: index in the move buffer, -1 when not moved, -2 when free */        \
		int capacity;		/* entries allocated */                                                          \
		int proxyCount;		/* live proxies */                                                               \
	} P##BroadProxyTable;

CD_BROAD_DECLARE_PROXY_TABLE(cd2, cd2Aabb)
CD_BROAD_DECLARE_PROXY_TABLE(cd3, cd3Aabb)

#define CD_BROAD_PROXY_NOT_MOVED (-1)
#define CD_BROAD_PROXY_FREE (-2)

/* ---- backend vtable --------------------------------------------------------------------------- */
/* Every function receives the backend's own state `self` (from create). Inserting, removing and
 * moving happen after the frontend has updated the proxy table: on insert and move
 * table->fatBoxes[proxyId] already holds the new box (the old one is passed to move); on remove
 * it still holds the box the proxy was inserted with. Functions returning bool report success
 * (false = out of memory; the frontend then undoes its own change). Optional entries may be NULL. */
#define CD_BROAD_DECLARE_BACKEND(P, AABB, RAY, DEF)                                                          \
	typedef struct P##BroadBackend                                                                           \
	{                                                                                                        \
		const char* name;                                                                                    \
		/* NULL when out of memory. def has been validated by the frontend. */                               \
		void* (*create)(const DEF* def, P##BroadProxyTable* table);                                          \
		void (*destroy)(void* self);                                                                         \
		bool (*insertProxy)(void* self, int proxyId);                                                        \
		void (*removeProxy)(void* self, int proxyId);                                                        \
		/* oldFatBox: the box the backend holds for the proxy (a backend may know it already). */            \
		bool (*moveProxy)(void* self, int proxyId, const AABB* oldFatBox);                                   \
		/* Calls fcn once per proxy whose fat box overlaps box (closed) until fcn returns false. */          \
		void (*query)(const void* self, AABB box, cdBroadIdFcn* fcn, void* context);                         \
		/* Calls fcn for proxies whose fat box the ray (t in [0, maxFraction]) may meet (conservative:       \
		 * never skip a box the ray meets; extra candidates are fine), keeping the clip fcn returns. */      \
		void (*rayCast)(const void* self, RAY ray, cdReal maxFraction, cdBroadRayIdFcn* fcn, void* context); \
		/* Optional: every overlapping pair once. NULL: the frontend queries each proxy. */                  \
		void (*findPairs)(const void* self, cdBroadPairSinkFcn* fcn, void* context);                         \
		/* Optional: called before pair finding, so deferred work (sorting) can be done. */                  \
		void (*flush)(void* self);                                                                           \
		/* Rebuilds from scratch over exactly the table's live proxies (moveIndex != FREE), including        \
		 * ones never inserted (bulk loading: the frontend fills the table, then rebuilds an empty           \
		 * backend). false = out of memory; the old structure then stays valid and unchanged. */             \
		bool (*rebuild)(void* self);                                                                         \
		/* Fills nodeCount, height, memoryBytes, sahCost (proxyCount is set by the frontend). */             \
		void (*getStats)(const void* self, cdBroadPhaseStats* stats);                                        \
		/* Checks every invariant, including agreement with the proxy table. */                              \
		bool (*validate)(const void* self);                                                                  \
		/* Optional cache hint: starts loading what moveProxy(proxyId) will read first (stage 0), then,      \
		 * called again a few moves later each time, what it reads next (stages 1 to 4). The proxy's         \
		 * table entries were requested a few moves before stage 0. */                                       \
		void (*prefetchMove)(const void* self, int proxyId, int stage);                                      \
		/* Optional: the box query of each proxyIds[i] with its own fat box, calling fcn(proxyIds[i],        \
		 * other, context) for every proxy `other` whose fat box overlaps it (itself included), in any       \
		 * order. NULL: the frontend calls query once per proxy. */                                          \
		void (*queryMany)(const void* self, const int* proxyIds, int count, cdBroadPairSinkFcn* fcn,         \
						  void* context);                                                                    \
		/* Optional: a move in enlarge mode (SetEnlargeMoves): table->fatBoxes[proxyId] holds the new        \
		 * box; the structure may only grow what holds it and restructure at the next flush. NULL: moves     \
		 * go to moveProxy in any mode. false = out of memory, as for moveProxy. */                          \
		bool (*enlargeProxy)(void* self, int proxyId);                                                       \
		/* Optional, both or neither: findPairs split into items [0, pairItemCount) (tree: nodes), any       \
		 * split of which over concurrent calls of findPairsRange reports each pair exactly once. */         \
		int (*pairItemCount)(const void* self);                                                              \
		void (*findPairsRange)(const void* self, int start, int end, cdBroadPairSinkFcn* fcn,                \
							   void* context);                                                               \
		/* Optional, all three or none: the flush's deferred restructuring in jobs [0, prepareRebuild())     \
		 * that may run at the same time on distinct jobs (rebuildJobs), then finishRebuild. */              \
		int (*prepareRebuild)(void* self);                                                                   \
		void (*rebuildJobs)(void* self, int start, int end);                                                 \
		void (*finishRebuild)(void* self);                                                                   \
	} P##BroadBackend;

CD_BROAD_DECLARE_BACKEND(cd2, cd2Aabb, cd2Ray, cd2BroadPhaseDef)
CD_BROAD_DECLARE_BACKEND(cd3, cd3Aabb, cd3Ray, cd3BroadPhaseDef)

/* The backends. The frontend picks one per cdBroadPhaseType. */
extern const cd2BroadBackend cd2BroadTreeBackend;
extern const cd3BroadBackend cd3BroadTreeBackend;
extern const cd2BroadBackend cd2BroadSapBackend;
extern const cd3BroadBackend cd3BroadSapBackend;

/* The hash grid and the quadtree/octree live in their own files; their headers define
 * CD_BROAD_HAVE_GRID / CD_BROAD_HAVE_SPATIAL_TREE and declare cd2BroadGridBackend,
 * cd3BroadGridBackend / cd2BroadSpatialTreeBackend, cd3BroadSpatialTreeBackend. */
#include "broad/broad_grid.h"
#include "broad/broad_spatial.h"

/* ---- small shared helpers --------------------------------------------------------------------- */

/* Growable array helper: makes *array hold at least `needed` elements of `elementSize` bytes,
 * growing by half again. Keeps the contents. false when out of memory (array unchanged). */
bool cdBroadReserve(void** array, int* capacity, int needed, size_t elementSize);

/* Asks the OS to back the whole 2 MB pages inside a large, freshly allocated block with huge
 * pages (Linux transparent huge pages in "madvise" mode; nothing elsewhere). At 1M proxies the
 * tree's nodes take 64 MB: with 4 KB pages nearly every node read at random also misses the TLB
 * and walks the page table. Call before the block is first written. */
void cdBroadAdviseLarge(void* memory, size_t bytes);

/* Number of bits needed for values below `count` (at least 1). */
int cdBroadBitsFor(int count);

/* A pair key that sorts like (min, max) of two proxy ids below 2^shift. */
static inline uint64_t cdBroadPairKey(int a, int b, int shift)
{
	uint64_t lo = (uint64_t)(a < b ? a : b), hi = (uint64_t)(a < b ? b : a);
	return (lo << shift) | hi;
}

/* ---- per-dimension box primitives (the only code that differs between 2D and 3D) ------------- */

static inline bool cd2BroadBoxOverlap(cd2Aabb a, cd2Aabb b)
{
	return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y;
}

static inline bool cd3BroadBoxOverlap(cd3Aabb a, cd3Aabb b)
{
	return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y &&
		   a.min.z <= b.max.z && b.min.z <= a.max.z;
}

/* The SAH measure: perimeter in 2D, surface area in 3D. */
static inline cdReal cd2BroadBoxCost(cd2Aabb a)
{
	return cd2AabbPerimeter(a);
}

static inline cdReal cd3BroadBoxCost(cd3Aabb a)
{
	return cd3AabbSurfaceArea(a);
}

/* Finite and min <= max on every axis. */
static inline bool cd2BroadBoxValid(cd2Aabb a)
{
	return cd2IsValidVec(a.min) && cd2IsValidVec(a.max) && a.min.x <= a.max.x && a.min.y <= a.max.y;
}

static inline bool cd3BroadBoxValid(cd3Aabb a)
{
	return cd3IsValidVec(a.min) && cd3IsValidVec(a.max) && a.min.x <= a.max.x && a.min.y <= a.max.y &&
		   a.min.z <= a.max.z;
}

static inline bool cd2BroadBoxEqual(cd2Aabb a, cd2Aabb b)
{
	return cd2VecEqual(a.min, b.min) && cd2VecEqual(a.max, b.max);
}

static inline bool cd3BroadBoxEqual(cd3Aabb a, cd3Aabb b)
{
	return cd3VecEqual(a.min, b.min) && cd3VecEqual(a.max, b.max);
}

static inline cdReal cd2BroadComponent(cd2Vec v, int axis)
{
	return axis == 0 ? v.x : v.y;
}

static inline cdReal cd3BroadComponent(cd3Vec v, int axis)
{
	return axis == 0 ? v.x : (axis == 1 ? v.y : v.z);
}

/* A ray prepared for many slab tests: inverse translation (infinite for a zero component). */
typedef struct cd2BroadRayData
{
	cd2Vec origin, translation, inverse;
} cd2BroadRayData;

typedef struct cd3BroadRayData
{
	cd3Vec origin, translation, inverse;
} cd3BroadRayData;

/* 1/d clamped to the finite range (1/d overflows for tiny d); unused when d == 0. */
static inline cdReal cdBroadSafeInverse(cdReal d)
{
	return d != CD_R(0.0) ? cdClamp(CD_R(1.0) / d, -CD_REAL_MAX, CD_REAL_MAX) : CD_REAL_MAX;
}

static inline cd2BroadRayData cd2BroadPrepareRay(cd2Ray ray)
{
	cd2BroadRayData r = {ray.origin,
						 ray.translation,
						 {cdBroadSafeInverse(ray.translation.x), cdBroadSafeInverse(ray.translation.y)}};
	return r;
}

static inline cd3BroadRayData cd3BroadPrepareRay(cd3Ray ray)
{
	cd3BroadRayData r = {ray.origin,
						 ray.translation,
						 {cdBroadSafeInverse(ray.translation.x), cdBroadSafeInverse(ray.translation.y),
						  cdBroadSafeInverse(ray.translation.z)}};
	return r;
}

/* One slab of the conservative ray/box test: narrows [*enter, *exit] by the slab [lo, hi] along an
 * axis where the ray starts at o and moves by d (inverse inv). Entry values are lowered and exit
 * values raised by CD_BROAD_RAY_SLACK of their magnitude, which covers the rounding of
 * (bound - o) * inv (a few ulps relative to the result). */
static inline void cdBroadSlab(cdReal o, cdReal d, cdReal inv, cdReal lo, cdReal hi, cdReal* enter,
							   cdReal* exit)
{
	if (d == CD_R(0.0))
	{
		if (o < lo || o > hi)
		{
			*enter = CD_REAL_MAX;
			*exit = -CD_REAL_MAX;
		}
		return;
	}
	cdReal t1 = (lo - o) * inv, t2 = (hi - o) * inv;
	cdReal tNear = cdMin(t1, t2), tFar = cdMax(t1, t2);
	tNear -= cdAbs(tNear) * CD_BROAD_RAY_SLACK;
	tFar += cdAbs(tFar) * CD_BROAD_RAY_SLACK;
	*enter = cdMax(*enter, tNear);
	*exit = cdMin(*exit, tFar);
}

/* Conservative test of the ray segment t in [0, maxFraction] against a box; on a possible hit
 * returns true and the (slightly lowered) entry fraction, clamped to >= 0. */
static inline bool cd2BroadRayBox(const cd2BroadRayData* r, cd2Aabb box, cdReal maxFraction, cdReal* entry)
{
	cdReal enter = -CD_REAL_MAX, exit = CD_REAL_MAX;
	cdBroadSlab(r->origin.x, r->translation.x, r->inverse.x, box.min.x, box.max.x, &enter, &exit);
	cdBroadSlab(r->origin.y, r->translation.y, r->inverse.y, box.min.y, box.max.y, &enter, &exit);
	if (enter > exit || exit < CD_R(0.0) || enter > maxFraction)
	{
		return false;
	}
	*entry = cdMax(enter, CD_R(0.0));
	return true;
}

static inline bool cd3BroadRayBox(const cd3BroadRayData* r, cd3Aabb box, cdReal maxFraction, cdReal* entry)
{
	cdReal enter = -CD_REAL_MAX, exit = CD_REAL_MAX;
	cdBroadSlab(r->origin.x, r->translation.x, r->inverse.x, box.min.x, box.max.x, &enter, &exit);
	cdBroadSlab(r->origin.y, r->translation.y, r->inverse.y, box.min.y, box.max.y, &enter, &exit);
	cdBroadSlab(r->origin.z, r->translation.z, r->inverse.z, box.min.z, box.max.z, &enter, &exit);
	if (enter > exit || exit < CD_R(0.0) || enter > maxFraction)
	{
		return false;
	}
	*entry = cdMax(enter, CD_R(0.0));
	return true;
}

/* ---- the moved proxies' pair search, split into ranges that may run on several threads --------
 * (for the 2D/3D worlds; the same pairs as UpdatePairs, in no particular order).
 *   n = BeginMovedPairs(bp)          flushes deferred work; returns the number of work items (the
 *                                    moved proxies' queries, or parts of a sweep over the whole
 *                                    structure when a good share of the proxies moved), 0: none
 *   QueryMovedPairs(bp, start, end)  reports the pairs found by items [start, end): any split of
 *                                    [0, n) over any threads reports each pair with a moved side
 *                                    exactly once, proxyA < proxyB; fcn runs on the calling
 *                                    thread, in an order that depends on the range only
 *   EndMovedPairs(bp, forget)        ends the search; forget: forgets the moves (as UpdatePairs
 *                                    does at its end), else keeps them for the next search
 * Between Begin and End the broadphase must not change (no create, destroy or move). */
/* Enlarge mode (the worlds'): a move of a proxy out of its fat box only grows the boxes that hold
 * it in the structure, which restructures the moved part in one go before the next pair search
 * (a tree: a binned SAH rebuild of the grown nodes); off by default. Answers are the same in both
 * modes; only the cost moves from each move to the pair update. */
void cd2BroadPhase_SetEnlargeMoves(cd2BroadPhase* broadPhase, bool flag);
void cd3BroadPhase_SetEnlargeMoves(cd3BroadPhase* broadPhase, bool flag);

/* A hint before a coming MoveProxy of proxyId, for a caller that knows its next moves: stage 0
 * loads the proxy's table entries, stage s > 0 the structure's records the move reads at depth s
 * (each stage reads what the one before loaded: call them in order, several moves apart). Does
 * nothing to the broadphase's state; an invalid id is ignored. */
void cd2BroadPhase_PrefetchMove(const cd2BroadPhase* broadPhase, int proxyId, int stage);
void cd3BroadPhase_PrefetchMove(const cd3BroadPhase* broadPhase, int proxyId, int stage);

/* The deferred restructuring of enlarge mode in jobs that may run on several threads, before
 * BeginMovedPairs (whose flush otherwise does it on the calling thread):
 *   n = BeginRebuild(bp); RebuildJobs(bp, start, end) over any split of [0, n), at the same time on
 *   distinct ranges; EndRebuild(bp). The result is the same for every split. */
int cd2BroadPhase_BeginRebuild(cd2BroadPhase* broadPhase);
void cd2BroadPhase_RebuildJobs(cd2BroadPhase* broadPhase, int start, int end);
void cd2BroadPhase_EndRebuild(cd2BroadPhase* broadPhase);
int cd3BroadPhase_BeginRebuild(cd3BroadPhase* broadPhase);
void cd3BroadPhase_RebuildJobs(cd3BroadPhase* broadPhase, int start, int end);
void cd3BroadPhase_EndRebuild(cd3BroadPhase* broadPhase);

int cd2BroadPhase_BeginMovedPairs(cd2BroadPhase* broadPhase);
void cd2BroadPhase_QueryMovedPairs(const cd2BroadPhase* broadPhase, int start, int end, cdBroadPairFcn* fcn,
								   void* context);
void cd2BroadPhase_EndMovedPairs(cd2BroadPhase* broadPhase, bool forgetMoves);
int cd3BroadPhase_BeginMovedPairs(cd3BroadPhase* broadPhase);
void cd3BroadPhase_QueryMovedPairs(const cd3BroadPhase* broadPhase, int start, int end, cdBroadPairFcn* fcn,
								   void* context);
void cd3BroadPhase_EndMovedPairs(cd3BroadPhase* broadPhase, bool forgetMoves);

#endif
