// The Box2D 2.4 column (Debian's libbox2d-dev): the pyramids of bases 20 and 40 only, laid out like
// Box2D v3's large_pyramid (unit boxes touching, density 1, friction 0.6, on a 200 m x 2 m ground
// box). Box2D 2.4 has no sub-steps: one Step per frame with 8 velocity and 3 position iterations
// (its documented defaults); sleeping off as in the other columns. No threads.
#include "bench_world2.h"

#include <box2d/box2d.h>

#include <cstdint>
#include <new>

static bool box2d24Supports(World2SceneId scene)
{
	return scene == WORLD2_PYRAMID_20 || scene == WORLD2_PYRAMID_40;
}

static void* box2d24Create(World2SceneId scene, int workerCount)
{
	(void)workerCount;
	int baseCount = scene == WORLD2_PYRAMID_20 ? 20 : 40;
	b2World* world = new (std::nothrow) b2World(b2Vec2(0.0f, -10.0f));
	if (world == nullptr)
	{
		return nullptr;
	}
	world->SetAllowSleeping(false);
	b2BodyDef groundDef;
	groundDef.position.Set(0.0f, -1.0f);
	b2Body* ground = world->CreateBody(&groundDef);
	b2PolygonShape groundBox;
	groundBox.SetAsBox(100.0f, 1.0f);
	ground->CreateFixture(&groundBox, 0.0f);

	b2PolygonShape box;
	box.SetAsBox(0.5f, 0.5f);
	b2FixtureDef fixture;
	fixture.shape = &box;
	fixture.density = 1.0f;
	fixture.friction = 0.6f;
	const float a = 0.5f;
	for (int i = 0; i < baseCount; ++i)
	{
		float y = (2.0f * (float)i + 1.0f) * a;
		for (int j = i; j < baseCount; ++j)
		{
			float x = ((float)i + 1.0f) * a + 2.0f * (float)(j - i) * a - a * (float)baseCount;
			b2BodyDef bd;
			bd.type = b2_dynamicBody;
			bd.position.Set(x, y);
			world->CreateBody(&bd)->CreateFixture(&fixture);
		}
	}
	return world;
}

static void box2d24Step(void* world, World2SceneId scene, int stepIndex, float timeStep, int subStepCount)
{
	(void)scene;
	(void)stepIndex;
	(void)subStepCount;
	static_cast<b2World*>(world)->Step(timeStep, 8, 3);
}

static bool box2d24Snapshot(void* world, World2Snapshot* out)
{
	for (b2Body* body = static_cast<b2World*>(world)->GetBodyList(); body != nullptr; body = body->GetNext())
	{
		World2Body b;
		b.key = (uint64_t)(uintptr_t)body;
		b.x = body->GetPosition().x;
		b.y = body->GetPosition().y;
		b.angle = body->GetAngle();
		b.vx = body->GetLinearVelocity().x;
		b.vy = body->GetLinearVelocity().y;
		b.w = body->GetAngularVelocity();
		b.mass = body->GetMass();
		b.type = body->GetType() == b2_dynamicBody
					 ? WORLD2_DYNAMIC
					 : (body->GetType() == b2_kinematicBody ? WORLD2_KINEMATIC : WORLD2_STATIC);
		if (!world2SnapshotAdd(out, &b))
		{
			return false;
		}
	}
	return true;
}

static void box2d24Counts(void* world, int* bodyCount, int* contactCount)
{
	b2World* w = static_cast<b2World*>(world);
	*bodyCount = w->GetBodyCount();
	*contactCount = w->GetContactCount();
}

static void box2d24Destroy(void* world)
{
	delete static_cast<b2World*>(world);
}

extern "C" const World2Engine world2EngineBox2d24 = {
	"box2d-2.4",
	"Box2D 2.4.1 (Debian libbox2d-dev), pyramids only, 1 step per frame, 8 velocity + 3 position iterations, "
	"no threads",
	1,
	box2d24Supports,
	box2d24Create,
	box2d24Step,
	box2d24Snapshot,
	box2d24Counts,
	box2d24Destroy,
	nullptr,
	nullptr,
	nullptr,
};
