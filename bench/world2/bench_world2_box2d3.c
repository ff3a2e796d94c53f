/* The Box2D v3 column: its own benchmark scenes (shared/benchmarks.c of its source snapshot) and
 * the pyramids of bases 20 and 40 built like its large_pyramid. Worlds as in its benchmark app:
 * b2DefaultWorldDef (continuous on), workerCount workers on its built-in scheduler. */
#include "bench_world2.h"

#include "benchmarks.h"

#include "box2d/box2d.h"

#include <stdlib.h>

static bool box2d3Supports(World2SceneId scene)
{
	return scene <= WORLD2_TUMBLER || scene == WORLD2_CHAINS;
}

/* large_pyramid's layout with another base: unit boxes touching, on a 200 m x 2 m ground box. */
static void createPyramid(b2WorldId worldId, int baseCount)
{
	b2World_EnableSleeping(worldId, false);
	b2BodyDef groundDef = b2DefaultBodyDef();
	groundDef.position = (b2Pos){0.0f, -1.0f};
	b2BodyId groundId = b2CreateBody(worldId, &groundDef);
	b2Polygon ground = b2MakeBox(100.0f, 1.0f);
	b2ShapeDef groundShape = b2DefaultShapeDef();
	b2CreatePolygonShape(groundId, &groundShape, &ground);

	b2BodyDef bodyDef = b2DefaultBodyDef();
	bodyDef.type = b2_dynamicBody;
	b2ShapeDef shapeDef = b2DefaultShapeDef();
	shapeDef.density = 1.0f;
	float a = 0.5f;
	b2Polygon box = b2MakeSquare(a);
	for (int i = 0; i < baseCount; ++i)
	{
		float y = (2.0f * (float)i + 1.0f) * a;
		for (int j = i; j < baseCount; ++j)
		{
			float x = ((float)i + 1.0f) * a + 2.0f * (float)(j - i) * a - a * (float)baseCount;
			bodyDef.position = (b2Pos){x, y};
			b2BodyId bodyId = b2CreateBody(worldId, &bodyDef);
			b2CreatePolygonShape(bodyId, &shapeDef, &box);
		}
	}
}

/* The chains scene (scenes/world2_quality.h), joints at Box2D v3's defaults. */
static void createChains(b2WorldId worldId)
{
	b2World_EnableSleeping(worldId, false);
	float length = (float)WORLD2_CHAIN_LINK_LENGTH;
	b2Capsule capsule = {{-0.5f * length, 0.0f}, {0.5f * length, 0.0f}, (float)WORLD2_CHAIN_LINK_RADIUS};
	b2ShapeDef shapeDef = b2DefaultShapeDef();
	shapeDef.density = 1.0f;
	shapeDef.filter.groupIndex = -1;
	for (int k = 0; k < WORLD2_CHAIN_COUNT; ++k)
	{
		float x0 = (float)(WORLD2_CHAIN_SPACING * (double)k);
		b2BodyDef pivotDef = b2DefaultBodyDef();
		pivotDef.position = (b2Pos){x0, 0.0f};
		b2BodyId previous = b2CreateBody(worldId, &pivotDef);
		for (int i = 0; i < world2ChainLinks(k); ++i)
		{
			b2BodyDef bodyDef = b2DefaultBodyDef();
			bodyDef.type = b2_dynamicBody;
			bodyDef.position = (b2Pos){x0 + length * ((float)i + 0.5f), 0.0f};
			b2BodyId link = b2CreateBody(worldId, &bodyDef);
			b2CreateCapsuleShape(link, &shapeDef, &capsule);
			b2RevoluteJointDef jointDef = b2DefaultRevoluteJointDef();
			jointDef.base.bodyIdA = previous;
			jointDef.base.bodyIdB = link;
			jointDef.base.localFrameA.p = i == 0 ? (b2Vec2){0.0f, 0.0f} : (b2Vec2){0.5f * length, 0.0f};
			jointDef.base.localFrameB.p = (b2Vec2){-0.5f * length, 0.0f};
			b2CreateRevoluteJoint(worldId, &jointDef);
			previous = link;
		}
	}
}

typedef struct Box2d3World
{
	b2WorldId id;
} Box2d3World;

static void* box2d3Create(World2SceneId scene, int workerCount)
{
	b2WorldDef def = b2DefaultWorldDef();
	def.workerCount = workerCount;
	b2WorldId id = b2CreateWorld(&def);
	switch (scene)
	{
		case WORLD2_PYRAMID_20:
			createPyramid(id, 20);
			break;
		case WORLD2_PYRAMID_40:
			createPyramid(id, 40);
			break;
		case WORLD2_LARGE_PYRAMID:
			CreateLargePyramid(id);
			break;
		case WORLD2_MANY_PYRAMIDS:
			CreateManyPyramids(id);
			break;
		case WORLD2_JOINT_GRID:
			CreateJointGrid(id);
			break;
		case WORLD2_RAIN:
			CreateRain(id);
			break;
		case WORLD2_SMASH:
			CreateSmash(id);
			break;
		case WORLD2_SPINNER:
			CreateSpinner(id);
			break;
		case WORLD2_TUMBLER:
			CreateTumbler(id);
			break;
		case WORLD2_CHAINS:
			createChains(id);
			break;
		default:
			b2DestroyWorld(id);
			return NULL;
	}
	Box2d3World* w = (Box2d3World*)malloc(sizeof(Box2d3World));
	if (w == NULL)
	{
		b2DestroyWorld(id);
		return NULL;
	}
	w->id = id;
	return w;
}

static void box2d3Step(void* world, World2SceneId scene, int stepIndex, float timeStep, int subStepCount)
{
	Box2d3World* w = (Box2d3World*)world;
	if (scene == WORLD2_RAIN)
	{
		StepRain(w->id, stepIndex);
	}
	else if (scene == WORLD2_SPINNER)
	{
		(void)StepSpinner(w->id, stepIndex);
	}
	b2World_Step(w->id, timeStep, subStepCount);
}

typedef struct SnapshotContext
{
	World2Snapshot* out;
	bool ok;
} SnapshotContext;

/* Every body once: through its first shape. */
static bool collectShape(b2ShapeId shapeId, void* context)
{
	SnapshotContext* c = (SnapshotContext*)context;
	b2BodyId body = b2Shape_GetBody(shapeId);
	b2BodyType type = b2Body_GetType(body);
	b2ShapeId first;
	if (b2Body_GetShapes(body, &first, 1) < 1 || first.index1 != shapeId.index1 ||
		first.generation != shapeId.generation)
	{
		return true;
	}
	b2Pos p = b2Body_GetPosition(body);
	b2Vec2 v = b2Body_GetLinearVelocity(body);
	World2Body b;
	b.key = (uint64_t)(uint32_t)body.index1 | ((uint64_t)body.generation << 32);
	b.x = p.x;
	b.y = p.y;
	b.angle = b2Rot_GetAngle(b2Body_GetRotation(body));
	b.vx = v.x;
	b.vy = v.y;
	b.w = b2Body_GetAngularVelocity(body);
	b.mass = b2Body_GetMass(body);
	b.type = type == b2_dynamicBody ? WORLD2_DYNAMIC
									: (type == b2_kinematicBody ? WORLD2_KINEMATIC : WORLD2_STATIC);
	c->ok = c->ok && world2SnapshotAdd(c->out, &b);
	return true;
}

static bool box2d3Snapshot(void* world, World2Snapshot* out)
{
	Box2d3World* w = (Box2d3World*)world;
	SnapshotContext c = {out, true};
	b2AABB all = {{-1.0e6f, -1.0e6f}, {1.0e6f, 1.0e6f}};
	b2World_OverlapAABB(w->id, b2Pos_zero, all, b2DefaultQueryFilter(), collectShape, &c);
	return c.ok;
}

static void box2d3Counts(void* world, int* bodyCount, int* contactCount)
{
	b2Counters c = b2World_GetCounters(((Box2d3World*)world)->id);
	*bodyCount = c.bodyCount;
	*contactCount = c.contactCount;
}

static void box2d3Destroy(void* world)
{
	Box2d3World* w = (Box2d3World*)world;
	b2DestroyWorld(w->id);
	free(w);
}

static void box2d3EnableProfile(void* world)
{
	(void)world; /* always on in Box2D v3 */
}

/* b2Profile lined up with collide's rows: v3 times no tree rebuild of its own (its rebuild is part
 * of another row); events are v3's hit, sensor hit and joint events; sleep is v3's sleep islands
 * and split islands. */
static void box2d3Profile(void* world, double* rows)
{
	b2Profile p = b2World_GetProfile(((Box2d3World*)world)->id);
	rows[W2P_STEP] = p.step;
	rows[W2P_PAIRS] = p.pairs;
	rows[W2P_COLLIDE] = p.collide;
	rows[W2P_SOLVE] = p.solve;
	rows[W2P_SOLVER_SETUP] = p.solverSetup;
	rows[W2P_PREPARE] = p.prepareConstraints;
	rows[W2P_INTEGRATE_VELOCITIES] = p.integrateVelocities;
	rows[W2P_WARM_START] = p.warmStart;
	rows[W2P_SOLVE_IMPULSES] = p.solveImpulses;
	rows[W2P_INTEGRATE_POSITIONS] = p.integratePositions;
	rows[W2P_RELAX] = p.relaxImpulses;
	rows[W2P_RESTITUTION] = p.applyRestitution;
	/* The constraint stages' time beyond the named ones (starting the workers, the split island
	 * task) goes to store. */
	double named = (double)p.prepareConstraints + p.integrateVelocities + p.warmStart + p.solveImpulses +
				   p.integratePositions + p.relaxImpulses + p.applyRestitution + p.storeImpulses;
	rows[W2P_STORE] = p.storeImpulses + ((double)p.constraints > named ? (double)p.constraints - named : 0.0);
	rows[W2P_FINALIZE] = p.transforms;
	rows[W2P_REFIT] = (double)p.refit + p.bullets;
	rows[W2P_EVENTS] = (double)p.hitEvents + p.sensorHits + p.jointEvents;
	rows[W2P_SLEEP] = (double)p.sleepIslands + p.splitIslands;
	rows[W2P_SENSORS] = p.sensors;
}

const World2Engine world2EngineBox2d3 = {
	"box2d-v3",
	"Box2D v3 (source snapshot, its benchmark scenes), 4 sub-steps, continuous on, built-in scheduler for 2 "
	"workers",
	2,
	box2d3Supports,
	box2d3Create,
	box2d3Step,
	box2d3Snapshot,
	box2d3Counts,
	box2d3Destroy,
	NULL,
	box2d3EnableProfile,
	box2d3Profile,
};
