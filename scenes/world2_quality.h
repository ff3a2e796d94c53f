/* The 2D world scenes' list and their quality criteria, independent of any engine.
 *
 * Each engine (collide in scenes/world2_scenes.c, the peers in bench/world2/) builds a scene,
 * takes a snapshot of its bodies before the first step and after the last, and the criterion
 * judges the two snapshots, so that every engine is held to the same rule (the first snapshot is
 * taken after settleStepCount steps: stacks of touching boxes first sink by the solver's allowed
 * penetration, which is not what "standing" means):
 *
 *   pyramid_20, pyramid_40, large_pyramid, many_pyramids: every apex (a box with no box resting
 *     on it at the start) moved less than 2 cm (the text gives the worst apex's x and y moves: a
 *     tall stack of soft contacts sinks into them and is pushed back up slowly, which moves the
 *     apex up; a toppling one moves it sideways). large_pyramid's 100 rows sink about 73 cm at the
 *     apex in the first second and are pushed back up by about 7 cm during the next one, in Box2D
 *     v3 as in collide, most of it within the next second: its first snapshot is taken at 3 s;
 *   joint_grid: the grid does not tear: every revolute joint's anchors (the grid's neighbours,
 *     1 m apart) are less than half a link (0.5 m) apart at the end (10,000 discs hanging from 7
 *     stretch the soft joints by some 40 cm in Box2D v3 and in collide);
 *   rain: no body is below the lowest floor (y < -1 m) or non-finite;
 *   smash: the total linear momentum (no gravity) is kept within 1%;
 *   spinner: no body escaped the 40 m ring;
 *   tumbler: no small box escaped the rotating box (|x|, |y| < 9.5 m in its frame);
 *   card_house: the top card moved less than 2 cm;
 *   ramp: the block on the gentle ramp (below atan(friction)) moved less than 1 cm and the block
 *     on the steep ramp slid at g (sin a - friction cos a) within 2%;
 *   bullets: no bullet is beyond the thin wall;
 *   side_scroller and slingshot: judged by scenes/world2_scenes.c (they need the scene's events);
 *   chains: the energy lost over 10 s, as a share of the chains' potential drop (the sum over nine
 *     chains of 2 to 12 links: a single chain's motion is chaotic, so one chain says little).
 *
 * Every criterion also fails on a non-finite position or velocity. Plain C, usable from C++. */
#ifndef COLLIDE_SCENES_WORLD2_QUALITY_H
#define COLLIDE_SCENES_WORLD2_QUALITY_H

#include <stdbool.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum World2SceneId
{
	WORLD2_PYRAMID_20,
	WORLD2_PYRAMID_40,
	WORLD2_LARGE_PYRAMID,
	WORLD2_MANY_PYRAMIDS,
	WORLD2_JOINT_GRID,
	WORLD2_RAIN,
	WORLD2_SMASH,
	WORLD2_SPINNER,
	WORLD2_TUMBLER,
	WORLD2_CARD_HOUSE,
	WORLD2_RAMP,
	WORLD2_BULLETS,
	WORLD2_SIDE_SCROLLER,
	WORLD2_SLINGSHOT,
	WORLD2_CHAINS,
	WORLD2_SCENE_COUNT
} World2SceneId;

/* A scene's name, step count and sub-step count (the peers' harness: 60 Hz, 4 sub-steps). */
typedef struct World2SceneInfo
{
	const char* name;
	int stepCount;
	int subStepCount;
	bool box2dScene; /* one of Box2D v3's own benchmark scenes (its shared/benchmarks.c) */
	/* The first snapshot is taken after this many steps (the stacks' first settling under gravity
	 * is not judged: 1 s for the pyramids and the card house, 3 s for large_pyramid, 0 elsewhere). */
	int settleStepCount;
} World2SceneInfo;

const World2SceneInfo* world2SceneInfo(World2SceneId id);
/* WORLD2_SCENE_COUNT when the name is unknown. */
World2SceneId world2SceneFind(const char* name);

/* The ramp scene: both ramps and blocks have this friction; the gentle ramp is below
 * atan(friction) = 26.6 degrees, the steep one above. Gravity is 10 m/s^2 in every scene. */
#define WORLD2_RAMP_FRICTION 0.5
#define WORLD2_RAMP_GENTLE_DEGREES 20.0
#define WORLD2_RAMP_STEEP_DEGREES 40.0
/* The chains scene: WORLD2_CHAIN_COUNT pendulum chains of capsule links (segment
 * WORLD2_CHAIN_LINK_LENGTH long, radius WORLD2_CHAIN_LINK_RADIUS, density 1), each hanging by a
 * revolute joint from a static pivot at (WORLD2_CHAIN_SPACING * k, 0) and released at rest lying
 * along +x; neighbouring links are jointed end to end and never collide with each other, and the
 * chains are too far apart to touch. Joints at the engine's defaults, sleep off. */
#define WORLD2_CHAIN_COUNT 9
#define WORLD2_CHAIN_LINK_LENGTH 1.0
#define WORLD2_CHAIN_LINK_RADIUS 0.1
#define WORLD2_CHAIN_SPACING 20.0
/* The links of chain k. */
int world2ChainLinks(int chain);

/* The bullets scene: the wall is 0.1 m thick, centred on x = 0; its far face is at this x. */
#define WORLD2_BULLET_WALL_X 0.05

typedef enum World2BodyType
{
	WORLD2_STATIC = 0,
	WORLD2_KINEMATIC = 1,
	WORLD2_DYNAMIC = 2
} World2BodyType;

/* One body of a snapshot. key is the engine's stable id of the body (the same body has the same
 * key in the first and the last snapshot); the rest in metres, radians, kilograms. */
typedef struct World2Body
{
	uint64_t key;
	double x, y, angle;
	double vx, vy, w;
	double mass;
	int type; /* World2BodyType */
} World2Body;

typedef struct World2Snapshot
{
	World2Body* bodies;
	int count;
	int capacity;
} World2Snapshot;

/* Appends one body (grows the array); false when out of memory. */
bool world2SnapshotAdd(World2Snapshot* snapshot, const World2Body* body);
void world2SnapshotClear(World2Snapshot* snapshot);
void world2SnapshotFree(World2Snapshot* snapshot);

typedef struct World2Quality
{
	bool computed; /* false: the criterion does not apply to these snapshots */
	bool pass;
	double value; /* the measured figure (metres, ratio, count: see text) */
	double limit;
	char text[200]; /* the final state in words, e.g. "apex moved 0.3 cm; 0 of 210 boxes fell" */
} World2Quality;

/* Judges a scene from its first and last snapshot; time is the simulated time between them (s). */
World2Quality world2CheckQuality(World2SceneId id, const World2Snapshot* start, const World2Snapshot* end,
								 double time);

#ifdef __cplusplus
}
#endif

#endif
