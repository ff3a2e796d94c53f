/* The broadphase benchmark scene, shared by bench/broad (collide_bench_broad, with the peers) and
 * the `collide broad` tool command, so that every figure is about the same boxes and the same
 * moves (docs/BROADPHASE.md, "How it is measured").
 *
 * N boxes with edges of 0.5-1.5 m in a cube of side 2*N^(1/3) m (a square of side 2*N^(1/2) m in
 * 2D; at least 8 m), so that each box overlaps about one other whatever N. Velocities up to 1 m/s
 * per axis, 60 frames per second, boxes bounce off the walls. Scene "moving": every box moves
 * every frame; "mix": 90% still, 9% moving, 1% teleporting to a random place every frame.
 * Deterministic: the same dimension, N, kind and seed give the same bits.
 *
 * Boxes are float whatever cdReal is: the peers are float libraries, and every structure must see
 * the same numbers. In 2D the z range is [0, 1] for every box. Plain C, usable from C++. */
#ifndef COLLIDE_SCENES_BROAD_SCENE_H
#define COLLIDE_SCENES_BROAD_SCENE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct BroadBox
{
	float min[3];
	float max[3];
} BroadBox;

/* The segment origin + t * translation, t in [0, 1]. */
typedef struct BroadRay
{
	float origin[3];
	float translation[3];
} BroadRay;

typedef enum BroadSceneKind
{
	BROAD_SCENE_MOVING, /* every box moves a little every frame */
	BROAD_SCENE_MIX		/* 90% still, 9% moving, 1% teleporting every frame */
} BroadSceneKind;

typedef struct BroadScene
{
	int dim;
	int n;
	BroadSceneKind kind;
	float worldSize; /* side of the cube (square) holding the boxes, from 0 */
	float timeStep;
	BroadBox* boxes;	 /* n tight boxes */
	float* velocity;	 /* 3 per box */
	float* displacement; /* 3 per box: predicted displacement for the next frame */
	int* moved;			 /* indices of the boxes moved by the last step */
	int movedCount;
	/* Random query boxes (half extents 1-3 m) and rays (length min(20 m, world size)). */
	BroadBox* queries;
	BroadRay* rays;
	int queryCount; /* of each: min(1000, max(50, n)) */

	/* Motion state; read only through the fields above. */
	float* center;
	float* half;
	uint8_t* motion;
	uint64_t rngState;
} BroadScene;

/* The seed the benchmark and the tool use for a dimension and N. */
uint64_t broadSceneSeed(int dim, int n);

/* Builds the scene; false when dim is not 2 or 3, n < 1, or memory runs out (nothing to free
 * then). */
bool broadSceneInit(BroadScene* scene, int dim, int n, BroadSceneKind kind, uint64_t seed);
void broadSceneFree(BroadScene* scene);

/* Advances one frame: moves the boxes of the scene kind and lists them in moved. */
void broadSceneStep(BroadScene* scene);

/* The region the boxes stay in (z is [0, 1] in 2D). */
BroadBox broadSceneWorldBounds(const BroadScene* scene);

/* "moving" or "mix". */
const char* broadSceneKindName(BroadSceneKind kind);

/* Closed boxes: touching counts, as in collide. */
static inline bool broadBoxesOverlap(const BroadBox* a, const BroadBox* b)
{
	return a->min[0] <= b->max[0] && b->min[0] <= a->max[0] && a->min[1] <= b->max[1] &&
		   b->min[1] <= a->max[1] && a->min[2] <= b->max[2] && b->min[2] <= a->max[2];
}

/* Slab test of the ray (t in [0, 1]) against a closed box. */
bool broadRayHitsBox(const BroadRay* ray, const BroadBox* box);

/* Reference: the number of pairs of the scene's tight boxes that overlap (sort and sweep along
 * x); SIZE_MAX when memory runs out. */
size_t broadSceneCountPairs(const BroadScene* scene);

/* The complete set of overlapping pairs for structures that report, per frame, the pairs that
 * involve a moved proxy (collide's and Box2D's UpdatePairs), kept the way a physics engine keeps
 * its contact list: pairs of two unmoved proxies stay as they were (their fat boxes did not
 * change), pairs with a moved side are dropped and come back among the reported ones if they
 * still overlap. Plain arrays, no lookups. Indices are the scene's box indices.
 */
typedef struct BroadPair
{
	int a;
	/* The second box, or ~(second box) when the tight boxes overlapped when last compared: 8 bytes
	 * a pair instead of 12, and at 1M boxes each frame streams the whole list through memory. */
	int bOrOverlap;
} BroadPair;

typedef struct BroadPairList
{
	BroadPair* pairs;
	size_t pairCount, pairCapacity;
	BroadPair* fresh;
	size_t freshCount, freshCapacity;
	uint8_t* flags;	  /* per box: BROAD_PAIR_MOVED, BROAD_PAIR_CHANGED */
	int* flaggedList; /* the boxes with flags set, to clear them */
	int flaggedCount, boxCount;
	bool tracksChanges; /* MarkChanged was used this frame: unchanged pairs reuse their comparison */
	bool failed;		/* memory ran out: counts are no longer complete */
} BroadPairList;

/* false when memory runs out. */
bool broadPairListInit(BroadPairList* list, int boxCount);
void broadPairListFree(BroadPairList* list);
/* The structure reported box `index` as moved: its pairs are dropped and come back reported. */
void broadPairListMarkMoved(BroadPairList* list, int index);
/* The tight box `index` changed this frame (moved or not in the structure): its kept pairs are
 * compared again. A caller that marks one changed box in a frame must mark all of them in that
 * frame: the other kept pairs then reuse their last comparison. In a frame without marks every
 * pair is compared (cheaper when most boxes changed: no marks to set). */
void broadPairListMarkChanged(BroadPairList* list, int index);
/* A reported pair of the scene's box indices; an index outside the scene marks the list failed. */
void broadPairListAdd(BroadPairList* list, int a, int b);
/* Drops the pairs with a moved side, appends the reported ones and forgets the marks. Returns
 * the number of pairs whose tight boxes overlap (SIZE_MAX once memory has run out). One linear
 * pass; with marks, only pairs with a changed box read the boxes (reading both boxes of every
 * pair costs a cache miss per pair at 1M boxes). */
size_t broadPairListEndFrame(BroadPairList* list, const BroadBox* boxes);
/* Bytes the list holds (the bench subtracts them from the structure's heap growth). */
size_t broadPairListBytes(const BroadPairList* list);

#ifdef __cplusplus
}
#endif

#endif
