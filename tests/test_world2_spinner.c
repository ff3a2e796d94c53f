/* The 2D world's spinner: Box2D v3's "spinner" benchmark scene (a ring of a 360-point chain loop and
 * a 40 m bar on a revolute motor stirring small bodies at up to 100 m/s at its tips), smaller: fewer
 * bodies and steps, so that it runs in seconds in the sanitizer build. No body may leave the ring.
 * The crowd the bar drives presses the bodies on the ring against it far harder than their own
 * speed; before the constraints against immovable bodies were solved last in each pass (graph
 * colours, src/base/graph_color.h) this scene lost bodies through the ring in the first second. */
#include "test.h"

#include <collide/collide.h>

#include <float.h>
#include <stdlib.h>

#ifndef SPINNER_BODY_COUNT
#define SPINNER_BODY_COUNT 3000
#endif
#ifndef SPINNER_STEPS
#define SPINNER_STEPS 45
#endif

static const cdReal kRingRadius = CD_R(40.0);
static const cdReal kRingCenterY = CD_R(32.0);

static void TestSpinnerKeepsBodiesInside(void)
{
	enum
	{
		POINT_COUNT = 360
	};
	cd2WorldDef wd = cd2DefaultWorldDef();
	cd2WorldId world = cd2CreateWorld(&wd);
	cd2BodyDef groundDef = cd2DefaultBodyDef();
	cd2BodyId ground = cd2CreateBody(world, &groundDef);
	cd2Vec points[POINT_COUNT];
	cd2Rot q = cd2MakeRot(CD_R(-2.0) * CD_PI / (cdReal)POINT_COUNT); /* clockwise: the ring faces in */
	cd2Vec p = cd2MakeVec(kRingRadius, CD_R(0.0));
	for (int i = 0; i < POINT_COUNT; ++i)
	{
		points[i] = cd2MakeVec(p.x, p.y + kRingCenterY);
		p = cd2RotateVector(q, p);
	}
	cd2ChainDef chain = cd2DefaultChainDef();
	chain.points = points;
	chain.count = POINT_COUNT;
	chain.isLoop = true;
	chain.friction = CD_R(0.1);
	cd2ChainId ring = cd2CreateChainShape(ground, &chain);
	TEST_CHECK(cd2ChainShape_IsValid(ring));

	cd2BodyDef def = cd2DefaultBodyDef();
	def.type = CD_DYNAMIC_BODY;
	def.position = cd2MakeVec(CD_R(0.0), CD_R(12.0));
	def.enableSleep = false;
	cd2BodyId spinner = cd2CreateBody(world, &def);
	cd2Polygon bar;
	TEST_CHECK(cd2MakeRoundedBoxPolygon(
				   (cd2Box){{CD_R(0.0), CD_R(0.0)}, {CD_R(0.4), CD_R(20.0)}, {CD_R(1.0), CD_R(0.0)}},
				   CD_R(0.2), &bar) == CD_OK);
	cd2ShapeDef barShape = cd2DefaultShapeDef();
	barShape.friction = CD_R(0.0);
	cd2CreatePolygonShape(spinner, &barShape, &bar);
	cd2RevoluteJointDef jd = cd2DefaultRevoluteJointDef();
	jd.bodyIdA = ground;
	jd.bodyIdB = spinner;
	jd.localAnchorA = def.position;
	jd.enableMotor = true;
	jd.motorSpeed = CD_R(5.0);
	jd.maxMotorTorque = (cdReal)FLT_MAX;
	cd2CreateRevoluteJoint(world, &jd);

	cd2Capsule capsule = {{CD_R(-0.25), CD_R(0.0)}, {CD_R(0.25), CD_R(0.0)}, CD_R(0.25)};
	cd2Circle circle = {{CD_R(0.0), CD_R(0.0)}, CD_R(0.35)};
	cd2Polygon square;
	cd2MakeBoxPolygon((cd2Box){{CD_R(0.0), CD_R(0.0)}, {CD_R(0.35), CD_R(0.35)}, {CD_R(1.0), CD_R(0.0)}},
					  &square);
	cd2BodyDef bodyDef = cd2DefaultBodyDef();
	bodyDef.type = CD_DYNAMIC_BODY;
	cd2ShapeDef shape = cd2DefaultShapeDef();
	shape.friction = CD_R(0.1);
	shape.restitution = CD_R(0.1);
	shape.density = CD_R(0.25);
	cd2BodyId* bodies = (cd2BodyId*)malloc(SPINNER_BODY_COUNT * sizeof(cd2BodyId));
	TEST_CHECK(bodies != NULL);
	if (bodies == NULL)
	{
		cd2DestroyWorld(world);
		return;
	}
	cdReal x = CD_R(-23.0), y = CD_R(2.0);
	for (int i = 0; i < SPINNER_BODY_COUNT; ++i)
	{
		bodyDef.position = cd2MakeVec(x, y);
		bodies[i] = cd2CreateBody(world, &bodyDef);
		if (i % 3 == 0)
		{
			cd2CreateCapsuleShape(bodies[i], &shape, &capsule);
		}
		else if (i % 3 == 1)
		{
			cd2CreateCircleShape(bodies[i], &shape, &circle);
		}
		else
		{
			cd2CreatePolygonShape(bodies[i], &shape, &square);
		}
		x += CD_R(0.5);
		if (x >= CD_R(23.0))
		{
			x = CD_R(-23.0);
			y += CD_R(0.5);
		}
	}

	int escaped = 0, firstEscapeStep = -1;
	double deepest = -(double)kRingRadius; /* how far past the ring any body's centre got */
	cdReal fastest = CD_R(0.0);
	for (int step = 0; step < SPINNER_STEPS; ++step)
	{
		cd2World_Step(world, CD_R(1.0) / CD_R(60.0), 4);
		escaped = 0;
		for (int i = 0; i < SPINNER_BODY_COUNT; ++i)
		{
			cd2Vec c = cd2Body_GetPosition(bodies[i]);
			double r = (double)cd2Length(cd2MakeVec(c.x, c.y - kRingCenterY));
			deepest = r - (double)kRingRadius > deepest ? r - (double)kRingRadius : deepest;
			/* Outside: the centre beyond the ring by more than the largest half-size (0.5 m). */
			escaped += r > (double)kRingRadius + 0.5 ? 1 : 0;
			fastest = cdMax(fastest, cd2Length(cd2Body_GetLinearVelocity(bodies[i])));
		}
		if (escaped > 0 && firstEscapeStep < 0)
		{
			firstEscapeStep = step;
		}
	}
	TEST_CHECKF(escaped == 0 && firstEscapeStep < 0, "%d bodies outside the ring, the first at step %d",
				escaped, firstEscapeStep);
	TEST_CHECKF(deepest < 0.0, "a centre got %g m past the ring", deepest);

	/* The bar did stir: the bodies it hit flew at tens of m/s. */
	TEST_CHECKF(fastest > CD_R(20.0), "fastest body %g m/s", (double)fastest);
	free(bodies);
	cd2DestroyWorld(world);
}

int main(void)
{
	TEST_RUN(TestSpinnerKeepsBodiesInside);
	return TEST_SUMMARY();
}
