/* The 2D world's scenes built in a collide world through the public API (collide/world2.h), shared
 * by the tests, bench/world2 (collide_bench_world2), the tool and the web demos, like Box2D's
 * shared/ folder. The scene list, step counts and quality criteria are in world2_quality.h.
 *
 * Box2D v3's benchmark scenes (large_pyramid, many_pyramids, joint_grid, rain, smash, spinner,
 * tumbler) are rebuilt with the same bodies, shapes, parameters and per-step code as its
 * shared/benchmarks.c (rain's ragdolls as its shared/human.c); pyramid_20 and pyramid_40 are
 * large_pyramid with bases 20 and 40. The rest are collide's own:
 *
 *   card_house: three floors of leaning card pairs with flat cards between them;
 *   ramp: two blocks on two ramps with friction 0.5, one below atan(0.5) and one above;
 *   bullets: 20 small bullets (0.1 m discs) at 300-1000 m/s against a 0.1 m static wall;
 *   side_scroller: ground with a pit bridged by a moving kinematic platform, a static platform, a
 *     one-way platform (pre-solve callback), five pick-up sensors and a walking, jumping character;
 *   slingshot: a projectile launched into two towers of blocks and a jointed rope bridge.
 *
 * Usage: world2SceneCreate, then world2SceneStep stepCount times, world2SceneSnapshot before and
 * after, world2SceneQuality, world2SceneDestroy. Plain C, usable from C++. */
#ifndef COLLIDE_SCENES_WORLD2_SCENES_H
#define COLLIDE_SCENES_WORLD2_SCENES_H

#include "world2_quality.h"

#include "collide/world2.h"

#ifdef __cplusplus
extern "C" {
#endif

#define WORLD2_RAIN_ROWS 5
#define WORLD2_RAIN_COLUMNS 40
#define WORLD2_RAIN_GROUP 5
#define WORLD2_HUMAN_BONES 11
#define WORLD2_PICKUPS 5

typedef struct World2Human
{
	cd2BodyId bodies[WORLD2_HUMAN_BONES];
	cd2JointId joints[WORLD2_HUMAN_BONES]; /* joints[0] unused: the hip has no parent */
	bool spawned;
} World2Human;

typedef struct World2Scene
{
	World2SceneId id;
	cd2WorldId world;
	/* Every body the scene made (destroyed ones are skipped by the snapshot). */
	cd2BodyId* bodies;
	int bodyCount, bodyCapacity;
	bool outOfMemory;

	/* spinner */
	cd2JointId spinnerJoint;
	/* rain: one group of WORLD2_RAIN_GROUP ragdolls per row and column */
	World2Human* rain; /* WORLD2_RAIN_ROWS * WORLD2_RAIN_COLUMNS * WORLD2_RAIN_GROUP */
	int rainColumnCount, rainColumnIndex;
	/* side_scroller */
	cd2BodyId character, mover;
	cd2ShapeId characterShape, oneWayShape;
	cd2ShapeId pickups[WORLD2_PICKUPS];
	int pickupBegin[WORLD2_PICKUPS], pickupEnd[WORLD2_PICKUPS];
	bool jumped, landedOnOneWay;
	double lowestCharacterY;
	/* slingshot: the bridge's joints and anchors */
	cd2JointId bridgeJoints[16];
	cd2Vec bridgeAnchorA[16], bridgeAnchorB[16];
	int bridgeJointCount;
} World2Scene;

/* Builds the scene in a new world (workerCount workers). false when the world or a body could not
 * be made (then the scene is already destroyed). */
bool world2SceneCreate(World2Scene* scene, World2SceneId id, int workerCount);
/* The scene's own per-step code (rain's ragdolls, the character, the moving platform), then one
 * cd2World_Step at 60 Hz with the scene's sub-step count. stepIndex counts from 0. */
void world2SceneStep(World2Scene* scene, int stepIndex);
/* Appends every live body to out (key: index and generation of its id). */
bool world2SceneSnapshot(const World2Scene* scene, World2Snapshot* out);
/* world2CheckQuality, and for side_scroller and slingshot the scene's own criterion. */
World2Quality world2SceneQuality(const World2Scene* scene, const World2Snapshot* start,
								 const World2Snapshot* end, double time);
void world2SceneDestroy(World2Scene* scene);

#ifdef __cplusplus
}
#endif

#endif
