/* The Chipmunk column (Debian's libchipmunk-dev, Chipmunk 7): the pyramids of bases 20 and 40 only,
 * laid out like Box2D v3's large_pyramid (unit boxes touching, density 1, friction 0.6, on a
 * 200 m x 2 m ground box). Chipmunk has no sub-steps: one cpHastySpaceStep per frame, 10 solver
 * iterations (its default), collision slop 0.005 m (Box2D's linear slop; Chipmunk's default of
 * 0.1 is meant for pixels); cpHastySpace with 1 or 2 solver threads; sleeping off (its default). */
#include "bench_world2.h"

#include <chipmunk/chipmunk.h>
#include <chipmunk/cpHastySpace.h>

#include <stdint.h>
#include <stdlib.h>

static bool chipmunkSupports(World2SceneId scene)
{
	return scene == WORLD2_PYRAMID_20 || scene == WORLD2_PYRAMID_40;
}

static void* chipmunkCreate(World2SceneId scene, int workerCount)
{
	int baseCount = scene == WORLD2_PYRAMID_20 ? 20 : 40;
	cpSpace* space = cpHastySpaceNew();
	if (space == NULL)
	{
		return NULL;
	}
	cpHastySpaceSetThreads(space, (unsigned long)workerCount);
	cpSpaceSetGravity(space, cpv(0.0, -10.0));
	cpSpaceSetIterations(space, 10);
	cpSpaceSetCollisionSlop(space, 0.005);
	cpShape* ground = cpBoxShapeNew2(cpSpaceGetStaticBody(space), cpBBNew(-100.0, -2.0, 100.0, 0.0), 0.0);
	cpShapeSetFriction(ground, 0.6);
	cpSpaceAddShape(space, ground);
	const double a = 0.5, mass = 1.0;
	for (int i = 0; i < baseCount; ++i)
	{
		double y = (2.0 * i + 1.0) * a;
		for (int j = i; j < baseCount; ++j)
		{
			double x = (i + 1.0) * a + 2.0 * (j - i) * a - a * baseCount;
			cpBody* body = cpSpaceAddBody(space, cpBodyNew(mass, cpMomentForBox(mass, 1.0, 1.0)));
			cpBodySetPosition(body, cpv(x, y));
			cpShape* shape = cpSpaceAddShape(space, cpBoxShapeNew(body, 1.0, 1.0, 0.0));
			cpShapeSetFriction(shape, 0.6);
		}
	}
	return space;
}

static void chipmunkStep(void* world, World2SceneId scene, int stepIndex, float timeStep, int subStepCount)
{
	(void)scene;
	(void)stepIndex;
	(void)subStepCount;
	cpHastySpaceStep((cpSpace*)world, timeStep);
}

typedef struct ChipmunkSnapshot
{
	World2Snapshot* out;
	bool ok;
} ChipmunkSnapshot;

static void addBody(cpBody* body, void* data)
{
	ChipmunkSnapshot* c = (ChipmunkSnapshot*)data;
	cpVect p = cpBodyGetPosition(body), v = cpBodyGetVelocity(body);
	World2Body b;
	b.key = (uint64_t)(uintptr_t)body;
	b.x = p.x;
	b.y = p.y;
	b.angle = cpBodyGetAngle(body);
	b.vx = v.x;
	b.vy = v.y;
	b.w = cpBodyGetAngularVelocity(body);
	b.mass = cpBodyGetType(body) == CP_BODY_TYPE_DYNAMIC ? cpBodyGetMass(body) : 0.0;
	b.type = cpBodyGetType(body) == CP_BODY_TYPE_DYNAMIC
				 ? WORLD2_DYNAMIC
				 : (cpBodyGetType(body) == CP_BODY_TYPE_KINEMATIC ? WORLD2_KINEMATIC : WORLD2_STATIC);
	c->ok = c->ok && world2SnapshotAdd(c->out, &b);
}

static bool chipmunkSnapshot(void* world, World2Snapshot* out)
{
	ChipmunkSnapshot c = {out, true};
	cpSpaceEachBody((cpSpace*)world, addBody, &c);
	return c.ok;
}

typedef struct ChipmunkCount
{
	int bodies;
	double contacts;
} ChipmunkCount;

static void countArbiter(cpBody* body, cpArbiter* arbiter, void* data)
{
	(void)body;
	CP_ARBITER_GET_BODIES(arbiter, a, b);
	bool shared = cpBodyGetType(a) == CP_BODY_TYPE_DYNAMIC && cpBodyGetType(b) == CP_BODY_TYPE_DYNAMIC;
	((ChipmunkCount*)data)->contacts += shared ? 0.5 : 1.0; /* seen from both bodies */
}

static void countBody(cpBody* body, void* data)
{
	((ChipmunkCount*)data)->bodies += 1;
	cpBodyEachArbiter(body, countArbiter, data);
}

static void chipmunkCounts(void* world, int* bodyCount, int* contactCount)
{
	ChipmunkCount c = {0, 0.0};
	cpSpaceEachBody((cpSpace*)world, countBody, &c);
	*bodyCount = c.bodies;
	*contactCount = (int)(c.contacts + 0.5);
}

typedef struct ChipmunkList
{
	void** items;
	int count, capacity;
} ChipmunkList;

static void listAdd(ChipmunkList* list, void* item)
{
	if (list->count == list->capacity)
	{
		int capacity = list->capacity < 64 ? 64 : 2 * list->capacity;
		void** items = (void**)realloc(list->items, (size_t)capacity * sizeof(void*));
		if (items == NULL)
		{
			return; /* leaks the rest: out of memory at teardown */
		}
		list->items = items;
		list->capacity = capacity;
	}
	list->items[list->count++] = item;
}

static void listShape(cpShape* shape, void* data)
{
	listAdd((ChipmunkList*)data, shape);
}

static void listBody(cpBody* body, void* data)
{
	listAdd((ChipmunkList*)data, body);
}

/* The space cannot be changed while it iterates: list everything first, then free it. */
static void chipmunkDestroy(void* world)
{
	cpSpace* space = (cpSpace*)world;
	ChipmunkList shapes = {NULL, 0, 0}, bodies = {NULL, 0, 0};
	cpSpaceEachShape(space, listShape, &shapes);
	cpSpaceEachBody(space, listBody, &bodies);
	for (int i = 0; i < shapes.count; ++i)
	{
		cpSpaceRemoveShape(space, (cpShape*)shapes.items[i]);
		cpShapeFree((cpShape*)shapes.items[i]);
	}
	for (int i = 0; i < bodies.count; ++i)
	{
		cpSpaceRemoveBody(space, (cpBody*)bodies.items[i]);
		cpBodyFree((cpBody*)bodies.items[i]);
	}
	free(shapes.items);
	free(bodies.items);
	cpHastySpaceFree(space);
}

const World2Engine world2EngineChipmunk = {
	"chipmunk",
	"Chipmunk 7.0.3 (Debian libchipmunk-dev), pyramids only, 1 step per frame, 10 iterations, slop 0.005 m, "
	"cpHastySpace with 1 or 2 threads",
	2,
	chipmunkSupports,
	chipmunkCreate,
	chipmunkStep,
	chipmunkSnapshot,
	chipmunkCounts,
	chipmunkDestroy,
	NULL,
	NULL,
	NULL,
};
