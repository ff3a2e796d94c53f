/* Tests of the 2D world's joints, events, callbacks, filters, queries, chains and continuous
 * collision. */
#include "test.h"

#include <collide/collide.h>

#include <stdlib.h>
#include <string.h>

#define DT (CD_R(1.0) / CD_R(60.0))

static cd2BodyId MakeStaticBox(cd2WorldId world, cd2Vec position, cdReal hx, cdReal hy)
{
	cd2BodyDef bd = cd2DefaultBodyDef();
	bd.position = position;
	cd2BodyId body = cd2CreateBody(world, &bd);
	cd2ShapeDef sd = cd2DefaultShapeDef();
	cd2Polygon box;
	cd2MakeBoxPolygon((cd2Box){{CD_R(0.0), CD_R(0.0)}, {hx, hy}, {CD_R(1.0), CD_R(0.0)}}, &box);
	cd2CreatePolygonShape(body, &sd, &box);
	return body;
}

static cd2BodyId MakeBall(cd2WorldId world, cd2Vec position, cdReal radius, bool bullet)
{
	cd2BodyDef bd = cd2DefaultBodyDef();
	bd.type = CD_DYNAMIC_BODY;
	bd.position = position;
	bd.isBullet = bullet;
	cd2BodyId body = cd2CreateBody(world, &bd);
	cd2ShapeDef sd = cd2DefaultShapeDef();
	cd2Circle circle = {{CD_R(0.0), CD_R(0.0)}, radius};
	cd2CreateCircleShape(body, &sd, &circle);
	return body;
}

/* A pendulum: a 1 kg ball on a massless revolute arm keeps its energy within 1% over 10 s. */
static void TestPendulumEnergy(void)
{
	cd2WorldDef wd = cd2DefaultWorldDef();
	wd.enableSleep = false;
	cd2WorldId world = cd2CreateWorld(&wd);
	cd2BodyDef bd = cd2DefaultBodyDef();
	cd2BodyId ground = cd2CreateBody(world, &bd);
	cdReal length = CD_R(2.0);
	/* Start horizontal. */
	cd2BodyId bob = MakeBall(world, cd2MakeVec(length, CD_R(0.0)), CD_R(0.25), false);
	cd2RevoluteJointDef jd = cd2DefaultRevoluteJointDef();
	jd.bodyIdA = ground;
	jd.bodyIdB = bob;
	jd.localAnchorA = CD2_VEC_ZERO;
	jd.localAnchorB = cd2MakeVec(-length, CD_R(0.0));
	cd2JointId joint = cd2CreateRevoluteJoint(world, &jd);
	TEST_CHECK(cd2Joint_IsValid(joint));
	cdReal m = cd2Body_GetMass(bob), I = cd2Body_GetRotationalInertia(bob);
	cdReal g = CD_R(10.0);
	double e0 = 0.0; /* at rest at height 0 */
	double worst = 0.0;
	for (int i = 0; i < 600; ++i)
	{
		cd2World_Step(world, DT, 4);
		cd2Vec p = cd2Body_GetPosition(bob);
		cd2Vec v = cd2Body_GetLinearVelocity(bob);
		cdReal w = cd2Body_GetAngularVelocity(bob);
		double e = 0.5 * (double)m * (double)cd2Dot(v, v) + 0.5 * (double)I * (double)w * (double)w +
				   (double)m * (double)g * (double)p.y;
		/* relative to the largest energy in play, m g L */
		double drift = fabs(e - e0) / ((double)m * (double)g * (double)length);
		worst = drift > worst ? drift : worst;
		TEST_CHECK(fabs((double)cd2Length(p) - (double)length) < 0.01);
	}
	TEST_CHECKF(worst < 0.01, "energy drift %g of m g L", worst);
	/* At the bottom the arm carries the weight and the centripetal force: reaction along the arm. */
	cd2Vec f = cd2Joint_GetConstraintForce(joint);
	TEST_CHECK(cdIsValidReal(f.x) && cdIsValidReal(f.y) && cd2Length(f) > CD_R(0.0));
	cd2DestroyWorld(world);
}

/* A chain of five revolute links released from horizontal: it whips and folds, and keeps its
 * energy within 1% over 10 s with the setting docs/DYNAMICS.md gives for pendulum chains (joints as
 * stiff as the sub-step rate allows, 32 sub-steps). At the defaults (60 Hz joints, 4 sub-steps) the
 * joints stretch under the chain's tension and each sub-step's relax pass drops that stretch's
 * energy: 38% goes over the same 10 s. */
static void TestRevoluteChainEnergy(void)
{
	enum
	{
		LINKS = 5
	};
	cd2WorldDef wd = cd2DefaultWorldDef();
	wd.enableSleep = false;
	wd.jointHertz = CD_R(1.0e6); /* capped at a quarter of the sub-step rate: 480 Hz */
	cd2WorldId world = cd2CreateWorld(&wd);
	cd2BodyDef bd = cd2DefaultBodyDef();
	cd2BodyId previous = cd2CreateBody(world, &bd);
	cd2BodyId links[LINKS];
	cd2JointId joints[LINKS];
	cdReal length = CD_R(1.0);
	double scale = 0.0; /* the potential energy the chain gives up hanging straight down */
	for (int i = 0; i < LINKS; ++i)
	{
		cd2BodyDef def = cd2DefaultBodyDef();
		def.type = CD_DYNAMIC_BODY;
		def.position = cd2MakeVec(length * ((cdReal)i + CD_R(0.5)), CD_R(0.0));
		links[i] = cd2CreateBody(world, &def);
		cd2ShapeDef sd = cd2DefaultShapeDef();
		sd.filter.groupIndex = -1; /* the links pass through each other */
		cd2Capsule capsule = {{CD_R(-0.5) * length, CD_R(0.0)}, {CD_R(0.5) * length, CD_R(0.0)}, CD_R(0.1)};
		cd2CreateCapsuleShape(links[i], &sd, &capsule);
		cd2RevoluteJointDef jd = cd2DefaultRevoluteJointDef();
		jd.bodyIdA = previous;
		jd.bodyIdB = links[i];
		jd.localAnchorA = i == 0 ? CD2_VEC_ZERO : cd2MakeVec(CD_R(0.5) * length, CD_R(0.0));
		jd.localAnchorB = cd2MakeVec(CD_R(-0.5) * length, CD_R(0.0));
		joints[i] = cd2CreateRevoluteJoint(world, &jd);
		TEST_CHECK(cd2Joint_IsValid(joints[i]));
		previous = links[i];
		scale += (double)cd2Body_GetMass(links[i]) * 10.0 * ((double)i + 0.5) * (double)length;
	}
	double worst = 0.0, worstGap = 0.0, lowest = 0.0;
	for (int step = 0; step < 600; ++step)
	{
		cd2World_Step(world, DT, 32);
		double e = 0.0; /* zero at the start: at rest at height 0 */
		for (int i = 0; i < LINKS; ++i)
		{
			cd2Vec p = cd2Body_GetWorldCenterOfMass(links[i]);
			cd2Vec v = cd2Body_GetLinearVelocity(links[i]);
			double w = (double)cd2Body_GetAngularVelocity(links[i]);
			double m = (double)cd2Body_GetMass(links[i]), I = (double)cd2Body_GetRotationalInertia(links[i]);
			e += 0.5 * m * (double)cd2Dot(v, v) + 0.5 * I * w * w + m * 10.0 * (double)p.y;
			lowest = (double)p.y < lowest ? (double)p.y : lowest;
			if (i > 0)
			{
				cd2Vec tip = cd2Body_GetWorldPoint(links[i - 1], cd2MakeVec(CD_R(0.5) * length, CD_R(0.0)));
				cd2Vec root = cd2Body_GetWorldPoint(links[i], cd2MakeVec(CD_R(-0.5) * length, CD_R(0.0)));
				double gap = (double)cd2VecDistance(tip, root);
				worstGap = gap > worstGap ? gap : worstGap;
			}
		}
		double drift = fabs(e) / scale;
		worst = drift > worst ? drift : worst;
	}
	TEST_CHECKF(worst < 0.01, "chain energy drift %g of its potential drop", worst);
	TEST_CHECKF(worstGap < 0.01, "joint gap %g m", worstGap);
	TEST_CHECKF(lowest < -4.0, "the chain swung down (lowest centre %g m)", lowest); /* it moved */
	cd2DestroyWorld(world);
}

/* A hanging box on a revolute joint at rest: the reaction force is its weight. */
static void TestJointReaction(void)
{
	cd2WorldDef wd = cd2DefaultWorldDef();
	wd.enableSleep = false;
	cd2WorldId world = cd2CreateWorld(&wd);
	cd2BodyDef bd = cd2DefaultBodyDef();
	cd2BodyId ground = cd2CreateBody(world, &bd);
	cd2BodyId bob = MakeBall(world, cd2MakeVec(CD_R(0.0), CD_R(-1.0)), CD_R(0.25), false);
	cd2RevoluteJointDef jd = cd2DefaultRevoluteJointDef();
	jd.bodyIdA = ground;
	jd.bodyIdB = bob;
	jd.localAnchorB = cd2MakeVec(CD_R(0.0), CD_R(1.0));
	cd2JointId joint = cd2CreateRevoluteJoint(world, &jd);
	for (int i = 0; i < 120; ++i)
	{
		cd2World_Step(world, DT, 4);
	}
	cdReal weight = cd2Body_GetMass(bob) * CD_R(10.0);
	cd2Vec f = cd2Joint_GetConstraintForce(joint);
	TEST_CHECK_NEAR(f.y, weight, 0.01 * weight);
	TEST_CHECK_NEAR(f.x, 0.0, 0.01 * weight);
	cd2DestroyWorld(world);
}

static int g_thresholdRefusals = 0;

static bool CountThresholdRefusal(const char* condition, const char* fileName, int lineNumber)
{
	(void)condition;
	(void)fileName;
	(void)lineNumber;
	++g_thresholdRefusals;
	return false;
}

/* Joint events: a ball hanging from a revolute joint with a force threshold of twice its weight
 * raises none while it hangs, one per step while a push drives the reaction over the threshold, and
 * the joint destroyed on its event (a breakable joint) lets the ball fall. A weld joint holding a
 * beam out from a wall reports its torque against a torque threshold below it, and none above. */
static void TestJointEvents(void)
{
	cd2WorldDef wd = cd2DefaultWorldDef();
	wd.enableSleep = false;
	cd2WorldId world = cd2CreateWorld(&wd);
	cd2BodyDef bd = cd2DefaultBodyDef();
	cd2BodyId ground = cd2CreateBody(world, &bd);
	cd2BodyId bob = MakeBall(world, cd2MakeVec(CD_R(0.0), CD_R(-1.0)), CD_R(0.25), false);
	cdReal weight = cd2Body_GetMass(bob) * CD_R(10.0);
	cd2RevoluteJointDef jd = cd2DefaultRevoluteJointDef();
	TEST_CHECK(jd.forceThreshold == CD_R(0.0) && jd.torqueThreshold == CD_R(0.0));
	jd.bodyIdA = ground;
	jd.bodyIdB = bob;
	jd.localAnchorB = cd2MakeVec(CD_R(0.0), CD_R(1.0));
	jd.forceThreshold = CD_R(2.0) * weight;
	jd.userData = &g_thresholdRefusals;
	cd2JointId joint = cd2CreateRevoluteJoint(world, &jd);
	TEST_CHECK(cd2Joint_GetForceThreshold(joint) == CD_R(2.0) * weight);
	int quietEvents = 0;
	for (int i = 0; i < 60; ++i)
	{
		cd2World_Step(world, DT, 4);
		quietEvents += cd2World_GetJointEvents(world).count;
	}
	TEST_CHECK(quietEvents == 0);
	/* A downward push of 5 weights for one step: the joint holds the ball against it. */
	cd2Body_ApplyForceToCenter(bob, cd2MakeVec(CD_R(0.0), -CD_R(5.0) * weight), true);
	cd2World_Step(world, DT, 4);
	cd2JointEvents events = cd2World_GetJointEvents(world);
	TEST_CHECK(events.count == 1);
	bool broke = false;
	for (int i = 0; i < events.count; ++i)
	{
		const cd2JointEvent* e = events.jointEvents + i;
		TEST_CHECK(e->jointId.index1 == joint.index1 && e->jointId.generation == joint.generation);
		TEST_CHECK(e->userData == &g_thresholdRefusals);
		TEST_CHECKF(cd2Length(e->force) > CD_R(2.0) * weight, "force %g, weight %g",
					(double)cd2Length(e->force), (double)weight);
		TEST_CHECK(e->force.x == cd2Joint_GetConstraintForce(joint).x &&
				   e->force.y == cd2Joint_GetConstraintForce(joint).y);
		cd2DestroyJoint(e->jointId);
		broke = true;
	}
	TEST_CHECK(broke && !cd2Joint_IsValid(joint));
	cd2World_Step(world, DT, 4);
	TEST_CHECK(cd2World_GetJointEvents(world).count == 0);
	cdReal y0 = cd2Body_GetPosition(bob).y;
	for (int i = 0; i < 30; ++i)
	{
		cd2World_Step(world, DT, 4);
	}
	TEST_CHECKF(cd2Body_GetPosition(bob).y < y0 - CD_R(1.0), "fell from %g to %g", (double)y0,
				(double)cd2Body_GetPosition(bob).y);

	/* A 2 m beam (1 kg/m^2, 0.2 m thick) welded to the ground at its end: torque m g L / 2. */
	cd2BodyDef beamDef = cd2DefaultBodyDef();
	beamDef.type = CD_DYNAMIC_BODY;
	beamDef.position = cd2MakeVec(CD_R(1.0), CD_R(5.0));
	cd2BodyId beam = cd2CreateBody(world, &beamDef);
	cd2ShapeDef sd = cd2DefaultShapeDef();
	cd2Polygon box;
	cd2MakeBoxPolygon((cd2Box){{CD_R(0.0), CD_R(0.0)}, {CD_R(1.0), CD_R(0.1)}, {CD_R(1.0), CD_R(0.0)}}, &box);
	cd2CreatePolygonShape(beam, &sd, &box);
	cdReal torque = cd2Body_GetMass(beam) * CD_R(10.0) * CD_R(1.0);
	cd2WeldJointDef wj = cd2DefaultWeldJointDef();
	wj.bodyIdA = ground;
	wj.bodyIdB = beam;
	wj.localAnchorA = cd2MakeVec(CD_R(0.0), CD_R(5.0));
	wj.localAnchorB = cd2MakeVec(-CD_R(1.0), CD_R(0.0));
	wj.torqueThreshold = CD_R(0.9) * torque;
	cd2JointId weld = cd2CreateWeldJoint(world, &wj);
	int beamEvents = 0;
	for (int i = 0; i < 60; ++i)
	{
		cd2World_Step(world, DT, 4);
		events = cd2World_GetJointEvents(world);
		beamEvents += events.count;
		if (i == 59)
		{
			TEST_CHECK(events.count == 1);
			TEST_CHECKF(events.count == 1 &&
							cdAbs(cdAbs(events.jointEvents[0].torque) - torque) < CD_R(0.02) * torque,
						"torque %g, expected %g",
						events.count == 1 ? (double)events.jointEvents[0].torque : 0.0, (double)torque);
		}
	}
	TEST_CHECK(beamEvents == 60);
	cd2Joint_SetTorqueThreshold(weld, CD_R(1.1) * torque);
	TEST_CHECK(cd2Joint_GetTorqueThreshold(weld) == CD_R(1.1) * torque);
	cd2World_Step(world, DT, 4);
	TEST_CHECK(cd2World_GetJointEvents(world).count == 0);
	cd2Joint_SetTorqueThreshold(weld, CD_R(0.0));
	cd2Joint_SetForceThreshold(weld, CD_R(0.5) * cd2Body_GetMass(beam) * CD_R(10.0));
	cd2World_Step(world, DT, 4);
	TEST_CHECK(cd2World_GetJointEvents(world).count == 1);

	/* Bad thresholds are refused and change nothing; a filter joint has none. */
	cdSetAssertFcn(CountThresholdRefusal);
	g_thresholdRefusals = 0;
	cdReal before = cd2Joint_GetForceThreshold(weld);
	cd2Joint_SetForceThreshold(weld, -CD_R(1.0));
	cd2Joint_SetTorqueThreshold(weld, CD_R(0.0) / CD_R(0.0));
	TEST_CHECK(g_thresholdRefusals == 2 && cd2Joint_GetForceThreshold(weld) == before &&
			   cd2Joint_GetTorqueThreshold(weld) == CD_R(0.0));
	wj.torqueThreshold = -CD_R(1.0);
	TEST_CHECK(!cd2Joint_IsValid(cd2CreateWeldJoint(world, &wj)));
	cd2FilterJointDef fj = cd2DefaultFilterJointDef();
	fj.bodyIdA = ground;
	fj.bodyIdB = beam;
	cd2JointId filter = cd2CreateFilterJoint(world, &fj);
	cd2Joint_SetForceThreshold(filter, CD_R(1.0));
	TEST_CHECK(g_thresholdRefusals == 4 && cd2Joint_GetForceThreshold(filter) == CD_R(0.0));
	cdSetAssertFcn(NULL);
	cd2DestroyWorld(world);
}

/* A joint's own constraint softness: a ball hanging from a revolute joint tuned to 4 Hz (critically
 * damped) settles g / (2 pi f)^2 = 1.58 cm below its anchor, the sag of a spring of that frequency
 * (the soft step's steady state); the same joint with the world's softness (60 Hz) sags by under a
 * millimetre. */
static cdReal HangingSag(cdReal hertz, cdReal dampingRatio)
{
	cd2WorldDef wd = cd2DefaultWorldDef();
	wd.enableSleep = false;
	cd2WorldId world = cd2CreateWorld(&wd);
	cd2BodyDef bd = cd2DefaultBodyDef();
	cd2BodyId ground = cd2CreateBody(world, &bd);
	cd2BodyId bob = MakeBall(world, cd2MakeVec(CD_R(0.0), -CD_R(1.0)), CD_R(0.25), false);
	cd2RevoluteJointDef jd = cd2DefaultRevoluteJointDef();
	jd.bodyIdA = ground;
	jd.bodyIdB = bob;
	jd.localAnchorB = cd2MakeVec(CD_R(0.0), CD_R(1.0));
	jd.constraintHertz = hertz;
	jd.constraintDampingRatio = dampingRatio;
	cd2JointId joint = cd2CreateRevoluteJoint(world, &jd);
	TEST_CHECK(cd2Joint_GetConstraintHertz(joint) == hertz &&
			   cd2Joint_GetConstraintDampingRatio(joint) == dampingRatio);
	for (int i = 0; i < 240; ++i)
	{
		cd2World_Step(world, DT, 4);
	}
	cdReal sag = -CD_R(1.0) - cd2Body_GetPosition(bob).y;
	cd2DestroyWorld(world);
	return sag;
}

static void TestJointConstraintTuning(void)
{
	cdReal soft = HangingSag(CD_R(4.0), CD_R(1.0));
	cdReal expected = CD_R(10.0) / ((CD_R(2.0) * CD_PI * CD_R(4.0)) * (CD_R(2.0) * CD_PI * CD_R(4.0)));
	TEST_CHECKF(cdAbs(soft - expected) < CD_R(0.01) * expected, "sag %g, expected %g", (double)soft,
				(double)expected);
	cdReal rigid = HangingSag(CD_R(0.0), CD_R(0.0));
	TEST_CHECKF(cdAbs(rigid) < CD_R(1e-3), "sag with the world's softness %g", (double)rigid);

	/* Tuning is refused for a motor joint and for bad numbers; the joint keeps its own. */
	cdSetAssertFcn(CountThresholdRefusal);
	g_thresholdRefusals = 0;
	cd2WorldDef wd = cd2DefaultWorldDef();
	cd2WorldId world = cd2CreateWorld(&wd);
	cd2BodyDef bd = cd2DefaultBodyDef();
	cd2BodyId ground = cd2CreateBody(world, &bd);
	cd2BodyId ball = MakeBall(world, CD2_VEC_ZERO, CD_R(0.3), false);
	cd2WeldJointDef wj = cd2DefaultWeldJointDef();
	wj.bodyIdA = ground;
	wj.bodyIdB = ball;
	cd2JointId weld = cd2CreateWeldJoint(world, &wj);
	cd2Joint_SetConstraintTuning(weld, CD_R(10.0), CD_R(0.5));
	TEST_CHECK(cd2Joint_GetConstraintHertz(weld) == CD_R(10.0) &&
			   cd2Joint_GetConstraintDampingRatio(weld) == CD_R(0.5));
	cd2Joint_SetConstraintTuning(weld, -CD_R(1.0), CD_R(0.5));
	cd2Joint_SetConstraintTuning(weld, CD_R(1.0), CD_R(0.0) / CD_R(0.0));
	cd2MotorJointDef mj = cd2DefaultMotorJointDef();
	mj.bodyIdA = ground;
	mj.bodyIdB = ball;
	cd2Joint_SetConstraintTuning(cd2CreateMotorJoint(world, &mj), CD_R(10.0), CD_R(1.0));
	wj.constraintHertz = -CD_R(2.0);
	TEST_CHECK(!cd2Joint_IsValid(cd2CreateWeldJoint(world, &wj)));
	TEST_CHECK(g_thresholdRefusals == 4 && cd2Joint_GetConstraintHertz(weld) == CD_R(10.0));
	cdSetAssertFcn(NULL);
	cd2DestroyWorld(world);
}

static void TestJointKinds(void)
{
	cd2WorldDef wd = cd2DefaultWorldDef();
	wd.enableSleep = false;
	cd2WorldId world = cd2CreateWorld(&wd);
	cd2BodyDef bd = cd2DefaultBodyDef();
	cd2BodyId ground = cd2CreateBody(world, &bd);

	/* Distance joint, rigid: the length holds. */
	cd2BodyId a = MakeBall(world, cd2MakeVec(CD_R(-10.0), CD_R(-3.0)), CD_R(0.2), false);
	cd2DistanceJointDef dj = cd2DefaultDistanceJointDef();
	dj.bodyIdA = ground;
	dj.bodyIdB = a;
	dj.localAnchorA = cd2MakeVec(CD_R(-10.0), CD_R(0.0));
	dj.length = CD_R(3.0);
	cd2Body_SetLinearVelocity(a, cd2MakeVec(CD_R(5.0), CD_R(0.0)));
	cd2JointId distance = cd2CreateDistanceJoint(world, &dj);

	/* Distance joint as a rope: at most 2 m, may be shorter. */
	cd2BodyId rope = MakeBall(world, cd2MakeVec(CD_R(-5.0), CD_R(-1.0)), CD_R(0.2), false);
	dj.localAnchorA = cd2MakeVec(CD_R(-5.0), CD_R(0.0));
	dj.bodyIdB = rope;
	dj.enableSpring = true;
	dj.hertz = CD_R(0.0);
	dj.enableLimit = true;
	dj.minLength = CD_R(0.0);
	dj.maxLength = CD_R(2.0);
	cd2CreateDistanceJoint(world, &dj);

	/* Weld: a box welded to the ground stays put. */
	cd2BodyId welded = MakeBall(world, cd2MakeVec(CD_R(0.0), CD_R(-1.0)), CD_R(0.3), false);
	cd2WeldJointDef wj = cd2DefaultWeldJointDef();
	wj.bodyIdA = ground;
	wj.bodyIdB = welded;
	wj.localAnchorA = cd2MakeVec(CD_R(0.0), CD_R(-1.0));
	cd2CreateWeldJoint(world, &wj);

	/* Prismatic along x with limits [-1, 1]: gravity cannot move it, a push stops at the limit. */
	cd2BodyId slider = MakeBall(world, cd2MakeVec(CD_R(5.0), CD_R(0.0)), CD_R(0.3), false);
	cd2PrismaticJointDef pj = cd2DefaultPrismaticJointDef();
	pj.bodyIdA = ground;
	pj.bodyIdB = slider;
	pj.localAnchorA = cd2MakeVec(CD_R(5.0), CD_R(0.0));
	pj.enableLimit = true;
	pj.lowerTranslation = -CD_R(1.0);
	pj.upperTranslation = CD_R(1.0);
	cd2CreatePrismaticJoint(world, &pj);
	cd2Body_SetLinearVelocity(slider, cd2MakeVec(CD_R(4.0), CD_R(0.0)));

	/* Mouse joint pulls a ball to the target. */
	cd2BodyId dragged = MakeBall(world, cd2MakeVec(CD_R(10.0), CD_R(0.0)), CD_R(0.3), false);
	cd2MouseJointDef mj = cd2DefaultMouseJointDef();
	mj.bodyIdA = ground;
	mj.bodyIdB = dragged;
	mj.target = cd2MakeVec(CD_R(10.0), CD_R(0.0));
	mj.hertz = CD_R(5.0);
	mj.dampingRatio = CD_R(0.7);
	mj.maxForce = CD_R(1000.0) * cd2Body_GetMass(dragged);
	cd2JointId mouse = cd2CreateMouseJoint(world, &mj);
	cd2MouseJoint_SetTarget(mouse, cd2MakeVec(CD_R(12.0), CD_R(1.0)));

	/* Motor joint drives a ball to an offset from the ground. */
	cd2BodyId driven = MakeBall(world, cd2MakeVec(CD_R(15.0), CD_R(0.0)), CD_R(0.3), false);
	cd2MotorJointDef tj = cd2DefaultMotorJointDef();
	tj.bodyIdA = ground;
	tj.bodyIdB = driven;
	tj.linearOffset = cd2MakeVec(CD_R(16.0), CD_R(1.0));
	tj.maxForce = CD_R(500.0);
	tj.maxTorque = CD_R(100.0);
	cd2CreateMotorJoint(world, &tj);

	/* Wheel joint: the wheel hangs on its suspension spring below the anchor, free to spin. */
	cd2BodyId wheel = MakeBall(world, cd2MakeVec(CD_R(20.0), CD_R(0.0)), CD_R(0.3), false);
	cd2WheelJointDef hj = cd2DefaultWheelJointDef();
	hj.bodyIdA = ground;
	hj.bodyIdB = wheel;
	hj.localAnchorA = cd2MakeVec(CD_R(20.0), CD_R(0.0));
	hj.hertz = CD_R(2.0);
	hj.enableMotor = true;
	hj.motorSpeed = CD_R(3.0);
	hj.maxMotorTorque = CD_R(100.0);
	cd2CreateWheelJoint(world, &hj);

	/* Revolute with motor: spins at the motor speed; with limit: stops at the limit. */
	cd2BodyId spinner = MakeBall(world, cd2MakeVec(CD_R(25.0), CD_R(0.0)), CD_R(0.3), false);
	cd2RevoluteJointDef rj = cd2DefaultRevoluteJointDef();
	rj.bodyIdA = ground;
	rj.bodyIdB = spinner;
	rj.localAnchorA = cd2MakeVec(CD_R(25.0), CD_R(0.0));
	rj.enableMotor = true;
	rj.motorSpeed = CD_R(2.0);
	rj.maxMotorTorque = CD_R(1000.0);
	cd2CreateRevoluteJoint(world, &rj);
	cd2BodyId limited = MakeBall(world, cd2MakeVec(CD_R(31.0), CD_R(0.0)), CD_R(0.3), false);
	rj.bodyIdB = limited;
	rj.localAnchorA = cd2MakeVec(CD_R(30.0), CD_R(0.0));
	rj.localAnchorB = cd2MakeVec(CD_R(-1.0), CD_R(0.0));
	rj.enableMotor = false;
	rj.enableLimit = true;
	rj.lowerAngle = -CD_R(0.5);
	rj.upperAngle = CD_R(0.5);
	cd2JointId limitJoint = cd2CreateRevoluteJoint(world, &rj);

	for (int i = 0; i < 180; ++i)
	{
		cd2World_Step(world, DT, 4);
	}
	TEST_CHECK_NEAR(cd2DistanceJoint_GetCurrentLength(distance), 3.0, 0.01);
	cd2Vec ropeEnd = cd2Body_GetPosition(rope);
	TEST_CHECK_NEAR(cd2VecDistance(ropeEnd, cd2MakeVec(CD_R(-5.0), CD_R(0.0))), 2.0, 0.02);
	TEST_CHECK_NEAR(cd2Body_GetPosition(welded).y, -1.0, 0.01);
	cd2Vec s = cd2Body_GetPosition(slider);
	TEST_CHECK_NEAR(s.y, 0.0, 0.01);
	TEST_CHECK(s.x <= CD_R(6.0) + CD_R(0.01) && s.x >= CD_R(3.99));
	cd2Vec d = cd2Body_GetPosition(dragged);
	TEST_CHECKF(cd2VecDistance(d, cd2MakeVec(CD_R(12.0), CD_R(1.0))) < CD_R(0.1), "dragged to %g %g",
				(double)d.x, (double)d.y);
	cd2Vec m = cd2Body_GetPosition(driven);
	TEST_CHECKF(cd2VecDistance(m, cd2MakeVec(CD_R(16.0), CD_R(1.0))) < CD_R(0.05), "driven to %g %g",
				(double)m.x, (double)m.y);
	cd2Vec w = cd2Body_GetPosition(wheel);
	TEST_CHECK_NEAR(w.x, 20.0, 0.01);
	TEST_CHECK(w.y < CD_R(0.0));
	TEST_CHECK_NEAR(cd2Body_GetAngularVelocity(wheel), 3.0, 0.05);
	TEST_CHECK_NEAR(cd2Body_GetAngularVelocity(spinner), 2.0, 0.01);
	TEST_CHECK_NEAR(cd2Body_GetPosition(spinner).x, 25.0, 0.01);
	cdReal angle = cd2RevoluteJoint_GetAngle(limitJoint);
	TEST_CHECKF(angle >= -CD_R(0.52) && angle <= -CD_R(0.45), "limited angle %g", (double)angle);
	cd2DestroyWorld(world);
}

/* The generic joint setters: a prismatic slider driven by its motor stops at its limit. */
static void TestJointSetters(void)
{
	cd2WorldDef wd = cd2DefaultWorldDef();
	wd.gravity = CD2_VEC_ZERO;
	cd2WorldId world = cd2CreateWorld(&wd);
	cd2BodyDef bd = cd2DefaultBodyDef();
	cd2BodyId ground = cd2CreateBody(world, &bd);
	cd2BodyId slider = MakeBall(world, CD2_VEC_ZERO, CD_R(0.3), false);
	cd2PrismaticJointDef pj = cd2DefaultPrismaticJointDef();
	pj.bodyIdA = ground;
	pj.bodyIdB = slider;
	cd2JointId joint = cd2CreatePrismaticJoint(world, &pj);
	cd2Joint_EnableMotor(joint, true);
	cd2Joint_SetMaxMotor(joint, CD_R(100.0));
	cd2Joint_SetMotorSpeed(joint, CD_R(1.0));
	for (int i = 0; i < 60; ++i)
	{
		cd2World_Step(world, DT, 4);
	}
	TEST_CHECK_NEAR(cd2Joint_GetTranslation(joint), 1.0, 0.02);
	TEST_CHECK_NEAR(cd2Body_GetLinearVelocity(slider).x, 1.0, 0.01);
	cd2Joint_SetLimits(joint, -CD_R(0.5), CD_R(1.5));
	cd2Joint_EnableLimit(joint, true);
	for (int i = 0; i < 60; ++i)
	{
		cd2World_Step(world, DT, 4);
	}
	TEST_CHECK_NEAR(cd2Joint_GetTranslation(joint), 1.5, 0.01);
	/* Reverse: it runs back to the lower limit. */
	cd2Joint_SetMotorSpeed(joint, -CD_R(2.0));
	for (int i = 0; i < 90; ++i)
	{
		cd2World_Step(world, DT, 4);
	}
	TEST_CHECK_NEAR(cd2Joint_GetTranslation(joint), -0.5, 0.01);
	TEST_CHECK_NEAR(cd2Body_GetPosition(slider).y, 0.0, 1e-3);
	/* A spring pulls it back to 0 once the motor is off. */
	cd2Joint_EnableMotor(joint, false);
	cd2Joint_EnableSpring(joint, true);
	cd2Joint_SetSpringHertz(joint, CD_R(2.0));
	cd2Joint_SetSpringDampingRatio(joint, CD_R(1.0));
	for (int i = 0; i < 180; ++i)
	{
		cd2World_Step(world, DT, 4);
	}
	TEST_CHECK_NEAR(cd2Joint_GetTranslation(joint), 0.0, 0.01);
	cd2DestroyWorld(world);
}

/* Filter joint and collideConnected: bodies that would collide do not. */
static void TestFilterJointAndFilters(void)
{
	cd2WorldDef wd = cd2DefaultWorldDef();
	cd2WorldId world = cd2CreateWorld(&wd);
	cd2BodyId ground = MakeStaticBox(world, cd2MakeVec(CD_R(0.0), CD_R(-1.0)), CD_R(50.0), CD_R(1.0));
	cd2BodyId ghost = MakeBall(world, cd2MakeVec(CD_R(0.0), CD_R(2.0)), CD_R(0.5), false);
	cd2FilterJointDef fj = cd2DefaultFilterJointDef();
	fj.bodyIdA = ground;
	fj.bodyIdB = ghost;
	cd2JointId filter = cd2CreateFilterJoint(world, &fj);
	TEST_CHECK(cd2Joint_IsValid(filter));
	/* Category/mask: this ball does not see category 2. */
	cd2BodyDef bd = cd2DefaultBodyDef();
	bd.type = CD_DYNAMIC_BODY;
	bd.position = cd2MakeVec(CD_R(5.0), CD_R(2.0));
	cd2BodyId masked = cd2CreateBody(world, &bd);
	cd2ShapeDef sd = cd2DefaultShapeDef();
	sd.filter.categoryBits = 4;
	sd.filter.maskBits = ~(uint64_t)1;
	cd2Circle circle = {{CD_R(0.0), CD_R(0.0)}, CD_R(0.5)};
	cd2CreateCircleShape(masked, &sd, &circle);
	/* Same negative group: never collide; positive: always. */
	cd2BodyId g1 = MakeBall(world, cd2MakeVec(CD_R(10.0), CD_R(0.5)), CD_R(0.5), false);
	cd2ShapeId g1s[1];
	cd2Body_GetShapes(g1, g1s, 1);
	bd.position = cd2MakeVec(CD_R(10.0), CD_R(3.0));
	cd2BodyId g2 = cd2CreateBody(world, &bd);
	sd = cd2DefaultShapeDef();
	sd.filter.groupIndex = -3;
	cd2CreateCircleShape(g2, &sd, &circle);
	cd2Filter f = cd2Shape_GetFilter(g1s[0]);
	f.groupIndex = -3;
	cd2Shape_SetFilter(g1s[0], f);
	for (int i = 0; i < 90; ++i)
	{
		cd2World_Step(world, DT, 4);
	}
	TEST_CHECK(cd2Body_GetPosition(ghost).y < CD_R(-1.0)); /* fell through the ground */
	TEST_CHECK(cd2Body_GetPosition(masked).y < CD_R(-1.0));
	TEST_CHECK_NEAR(cd2Body_GetPosition(g1).y, 0.5, 0.02); /* on the ground */
	TEST_CHECK_NEAR(cd2Body_GetPosition(g2).y, 0.5, 0.02); /* through g1 onto the ground, not on g1 */
	/* Destroying the filter joint lets the ground catch the next ball that way. */
	cd2DestroyJoint(filter);
	TEST_CHECK(!cd2Joint_IsValid(filter));
	cd2DestroyWorld(world);
}

static int g_hits;

/* A world without gravity holding a 2 x 2 m sensor box at the origin and a kinematic ball of radius
 * 0.25 at (x, 0) moving at vx: the sensor scenes below. */
static cd2WorldId CreateSensorScene(cdReal x, cdReal vx, cd2ShapeId* zone, cd2BodyId* visitor,
									cd2ShapeId* visitorShape)
{
	cd2WorldDef wd = cd2DefaultWorldDef();
	wd.gravity = CD2_VEC_ZERO;
	cd2WorldId world = cd2CreateWorld(&wd);
	cd2BodyDef bd = cd2DefaultBodyDef();
	cd2BodyId zoneBody = cd2CreateBody(world, &bd);
	cd2ShapeDef sd = cd2DefaultShapeDef();
	sd.isSensor = true;
	cd2Polygon box;
	cd2MakeBoxPolygon((cd2Box){{CD_R(0.0), CD_R(0.0)}, {CD_R(1.0), CD_R(1.0)}, {CD_R(1.0), CD_R(0.0)}}, &box);
	*zone = cd2CreatePolygonShape(zoneBody, &sd, &box);
	bd.type = CD_KINEMATIC_BODY;
	bd.position = cd2MakeVec(x, CD_R(0.0));
	bd.linearVelocity = cd2MakeVec(vx, CD_R(0.0));
	*visitor = cd2CreateBody(world, &bd);
	sd = cd2DefaultShapeDef();
	cd2Circle circle = {{CD_R(0.0), CD_R(0.0)}, CD_R(0.25)};
	*visitorShape = cd2CreateCircleShape(*visitor, &sd, &circle);
	return world;
}

/* Sensor events fire exactly once per entry and per exit. */
static void TestSensorEvents(void)
{
	/* A ball passes through the sensor back and forth (turned round at x = +-5). */
	cdReal speed = CD_R(4.0);
	cd2ShapeId zone, visitorShape;
	cd2BodyId visitor;
	cd2WorldId world = CreateSensorScene(CD_R(-5.0), speed, &zone, &visitor, &visitorShape);
	int begins = 0, ends = 0, wrong = 0;
	for (int i = 0; i < 600; ++i)
	{
		cdReal x = cd2Body_GetPosition(visitor).x;
		if (x > CD_R(5.0))
		{
			cd2Body_SetLinearVelocity(visitor, cd2MakeVec(-speed, CD_R(0.0)));
		}
		else if (x < CD_R(-5.0))
		{
			cd2Body_SetLinearVelocity(visitor, cd2MakeVec(speed, CD_R(0.0)));
		}
		cd2World_Step(world, DT, 4);
		cd2SensorEvents se = cd2World_GetSensorEvents(world);
		for (int k = 0; k < se.beginCount; ++k)
		{
			wrong += !cd2ShapeIdEqual(se.beginEvents[k].sensorShapeId, zone) ||
					 !cd2ShapeIdEqual(se.beginEvents[k].visitorShapeId, visitorShape);
		}
		begins += se.beginCount;
		ends += se.endCount;
		/* Inside means between the begin and the end. */
		cdReal now = cd2Body_GetPosition(visitor).x;
		bool inside = cdAbs(now) < CD_R(1.25);
		TEST_CHECK(inside == (begins > ends));
	}
	/* 600 steps at 4 m/s = 40 m of travel over a 10 m course: 4 crossings. */
	TEST_CHECKF(begins == 4 && ends == 4, "begins %d ends %d", begins, ends);
	TEST_CHECK(wrong == 0);
	/* Destroying the visitor while inside reports its exit at the next step. */
	cd2Body_SetTransform(visitor, CD2_VEC_ZERO, CD2_ROT_IDENTITY);
	cd2Body_SetLinearVelocity(visitor, CD2_VEC_ZERO);
	cd2World_Step(world, DT, 4);
	TEST_CHECK(cd2World_GetSensorEvents(world).beginCount == 1);
	cd2DestroyBody(visitor);
	cd2World_Step(world, DT, 4);
	TEST_CHECK(cd2World_GetSensorEvents(world).endCount == 1);
	cd2World_Step(world, DT, 4);
	TEST_CHECK(cd2World_GetSensorEvents(world).endCount == 0);
	cd2DestroyWorld(world);
}

/* A saved state with a visitor inside a sensor, restored into a new world: the sensor's end event
 * comes when the visitor leaves, as in the world that saved it (the restored world knows it has
 * sensor contacts to look at). */
static void TestSensorEventsAfterRestore(void)
{
	cd2ShapeId zone, visitorShape;
	cd2BodyId visitor;
	cd2WorldId world = CreateSensorScene(CD_R(-3.0), CD_R(4.0), &zone, &visitor, &visitorShape);
	int begins = 0;
	for (int i = 0; i < 120 && begins == 0; ++i)
	{
		cd2World_Step(world, DT, 4);
		begins += cd2World_GetSensorEvents(world).beginCount;
	}
	TEST_CHECK(begins == 1);
	size_t size = cd2World_GetStateSize(world);
	unsigned char* buffer = (unsigned char*)malloc(size);
	TEST_CHECK(buffer != NULL && cd2World_SaveState(world, buffer, size) == CD_OK);
	/* The saving world: steps until the visitor has left. */
	int endStep = -1;
	for (int i = 0; i < 120 && endStep < 0; ++i)
	{
		cd2World_Step(world, DT, 4);
		endStep = cd2World_GetSensorEvents(world).endCount > 0 ? i : -1;
	}
	TEST_CHECK(endStep > 0);
	cd2DestroyWorld(world);
	/* A new world without a shape, given the saved state: the same end at the same step. */
	cd2WorldDef wd = cd2DefaultWorldDef();
	wd.gravity = CD2_VEC_ZERO;
	cd2WorldId restored = cd2CreateWorld(&wd);
	TEST_CHECK(buffer != NULL && cd2World_RestoreState(restored, buffer, size) == CD_OK);
	int restoredEnd = -1;
	for (int i = 0; i < 120 && restoredEnd < 0; ++i)
	{
		cd2World_Step(restored, DT, 4);
		restoredEnd = cd2World_GetSensorEvents(restored).endCount > 0 ? i : -1;
	}
	TEST_CHECKF(restoredEnd == endStep, "end event at step %d after the restore, %d in the saving world",
				restoredEnd, endStep);
	cd2DestroyWorld(restored);
	free(buffer);
}

static void TestContactAndHitEvents(void)
{
	cd2WorldDef wd = cd2DefaultWorldDef();
	wd.hitEventThreshold = CD_R(2.0);
	cd2WorldId world = cd2CreateWorld(&wd);
	cd2BodyId ground = MakeStaticBox(world, cd2MakeVec(CD_R(0.0), CD_R(-1.0)), CD_R(50.0), CD_R(1.0));
	(void)ground;
	cd2BodyDef bd = cd2DefaultBodyDef();
	bd.type = CD_DYNAMIC_BODY;
	bd.position = cd2MakeVec(CD_R(0.0), CD_R(5.0));
	cd2BodyId ball = cd2CreateBody(world, &bd);
	cd2ShapeDef sd = cd2DefaultShapeDef();
	sd.enableHitEvents = true;
	cd2Circle circle = {{CD_R(0.0), CD_R(0.0)}, CD_R(0.5)};
	cd2ShapeId ballShape = cd2CreateCircleShape(ball, &sd, &circle);
	int begins = 0, hits = 0, moves = 0;
	cdReal approach = CD_R(0.0);
	for (int i = 0; i < 120; ++i)
	{
		cd2World_Step(world, DT, 4);
		cd2ContactEvents ce = cd2World_GetContactEvents(world);
		for (int k = 0; k < ce.beginCount; ++k)
		{
			const cd2ContactBeginTouchEvent* e = ce.beginEvents + k;
			bool ballIsB = cd2ShapeIdEqual(e->shapeIdB, ballShape);
			TEST_CHECK(ballIsB || cd2ShapeIdEqual(e->shapeIdA, ballShape));
			TEST_CHECK(e->manifold.pointCount == 1);
			/* normal from A to B: up when the ball is B */
			TEST_CHECK_NEAR(e->manifold.normal.y, ballIsB ? 1.0 : -1.0, 1e-4);
			TEST_CHECK(cdAbs(e->manifold.points[0].point.y) < CD_R(0.2));
		}
		begins += ce.beginCount;
		for (int k = 0; k < ce.hitCount; ++k)
		{
			approach = ce.hitEvents[k].approachSpeed;
		}
		hits += ce.hitCount;
		moves += cd2World_GetBodyEvents(world).moveCount;
	}
	g_hits = hits;
	TEST_CHECK(begins == 1);
	TEST_CHECK(hits == 1);
	/* Falling 4.5 m: sqrt(2 g h) = 9.49 m/s. */
	TEST_CHECK_NEAR(approach, 9.49, 0.2);
	TEST_CHECK(moves > 30 && moves <= 120);
	/* Destroying the ball reports the end of its touch. */
	cd2DestroyBody(ball);
	cd2World_Step(world, DT, 4);
	TEST_CHECK(cd2World_GetContactEvents(world).endCount == 1);
	cd2DestroyWorld(world);
}

/* One-way platform: the pre-solve callback disables contacts where the body comes from below. */
static bool OneWay(cd2ShapeId shapeIdA, cd2ShapeId shapeIdB, const cd2Manifold* manifold, void* context)
{
	cd2ShapeId platform = *(const cd2ShapeId*)context;
	cdReal sign;
	if (cd2ShapeIdEqual(shapeIdA, platform))
	{
		sign = CD_R(1.0);
	}
	else if (cd2ShapeIdEqual(shapeIdB, platform))
	{
		sign = -CD_R(1.0);
	}
	else
	{
		return true;
	}
	/* Solid only when the normal from the platform to the other points up. */
	return sign * manifold->normal.y > CD_R(0.5);
}

static bool RejectAll(cd2ShapeId a, cd2ShapeId b, void* context)
{
	(void)a;
	(void)b;
	*(int*)context += 1;
	return false;
}

typedef struct LockProbe
{
	cd2WorldId world;
	cd2BodyId body;
	int calls;
} LockProbe;

static int g_lockRefusals;

static bool CountLockRefusal(const char* condition, const char* fileName, int lineNumber)
{
	(void)condition;
	(void)fileName;
	(void)lineNumber;
	++g_lockRefusals;
	return false;
}

/* Tries to change the world from inside the step. */
static bool MutateDuringStep(cd2ShapeId shapeIdA, cd2ShapeId shapeIdB, const cd2Manifold* manifold,
							 void* context)
{
	(void)shapeIdA;
	(void)shapeIdB;
	(void)manifold;
	LockProbe* probe = (LockProbe*)context;
	probe->calls += 1;
	cd2BodyDef bd = cd2DefaultBodyDef();
	TEST_CHECK(cd2IsNullBodyId(cd2CreateBody(probe->world, &bd)));
	cd2Body_SetLinearVelocity(probe->body, cd2MakeVec(CD_R(100.0), CD_R(0.0)));
	cd2DestroyBody(probe->body);
	cd2World_Step(probe->world, CD_R(1.0) / CD_R(60.0), 4);
	return true;
}

/* The world is locked during the step: calls from a callback are refused. */
static void TestLockedWorld(void)
{
	cdSetAssertFcn(CountLockRefusal);
	g_lockRefusals = 0;
	cd2WorldDef wd = cd2DefaultWorldDef();
	cd2WorldId world = cd2CreateWorld(&wd);
	cd2BodyDef bd = cd2DefaultBodyDef();
	cd2BodyId ground = cd2CreateBody(world, &bd);
	cd2ShapeDef sd = cd2DefaultShapeDef();
	sd.enablePreSolveEvents = true;
	cd2Polygon box;
	cd2MakeBoxPolygon((cd2Box){{CD_R(0.0), CD_R(-1.0)}, {CD_R(10.0), CD_R(1.0)}, {CD_R(1.0), CD_R(0.0)}},
					  &box);
	cd2CreatePolygonShape(ground, &sd, &box);
	cd2BodyId ball = MakeBall(world, cd2MakeVec(CD_R(0.0), CD_R(0.5)), CD_R(0.5), false);
	LockProbe probe = {world, ball, 0};
	cd2World_SetPreSolveCallback(world, MutateDuringStep, &probe);
	cd2World_Step(world, CD_R(1.0) / CD_R(60.0), 4);
	TEST_CHECK(probe.calls == 1);
	TEST_CHECK(g_lockRefusals == 4);
	TEST_CHECK(cd2Body_IsValid(ball));
	TEST_CHECK(cdAbs(cd2Body_GetLinearVelocity(ball).x) < CD_R(0.01));
	TEST_CHECK(cd2World_GetCounters(world).bodyCount == 2);
	cd2World_SetPreSolveCallback(world, NULL, NULL);
	cd2DestroyWorld(world);
	cdSetAssertFcn(NULL);
}

static void TestPreSolveAndCustomFilter(void)
{
	cd2WorldDef wd = cd2DefaultWorldDef();
	cd2WorldId world = cd2CreateWorld(&wd);
	cd2BodyDef bd = cd2DefaultBodyDef();
	bd.position = cd2MakeVec(CD_R(0.0), CD_R(3.0));
	cd2BodyId platformBody = cd2CreateBody(world, &bd);
	cd2ShapeDef sd = cd2DefaultShapeDef();
	sd.enablePreSolveEvents = true;
	cd2Polygon box;
	cd2MakeBoxPolygon((cd2Box){{CD_R(0.0), CD_R(0.0)}, {CD_R(3.0), CD_R(0.1)}, {CD_R(1.0), CD_R(0.0)}}, &box);
	cd2ShapeId platform = cd2CreatePolygonShape(platformBody, &sd, &box);
	cd2World_SetPreSolveCallback(world, OneWay, &platform);
	/* Launched up from below, the ball passes the platform and lands on top of it. */
	cd2BodyId ball = MakeBall(world, cd2MakeVec(CD_R(0.0), CD_R(0.0)), CD_R(0.25), false);
	cd2Body_SetLinearVelocity(ball, cd2MakeVec(CD_R(0.0), CD_R(10.0)));
	for (int i = 0; i < 180; ++i)
	{
		cd2World_Step(world, DT, 4);
	}
	TEST_CHECK_NEAR(cd2Body_GetPosition(ball).y, 3.35, 0.02);

	/* A custom filter that rejects every pair: a ball dropped on the platform falls through. */
	int calls = 0;
	cd2World_SetCustomFilterCallback(world, RejectAll, &calls);
	cd2BodyId other = MakeBall(world, cd2MakeVec(CD_R(2.0), CD_R(5.0)), CD_R(0.25), false);
	for (int i = 0; i < 90; ++i)
	{
		cd2World_Step(world, DT, 4);
	}
	TEST_CHECK(calls >= 1);
	TEST_CHECK(cd2Body_GetPosition(other).y < CD_R(2.0));
	cd2DestroyWorld(world);
}

static bool CountOverlap(cd2ShapeId shapeId, void* context)
{
	(void)shapeId;
	*(int*)context += 1;
	return true;
}

static cdReal CollectAll(cd2ShapeId shapeId, cd2Vec point, cd2Vec normal, cdReal fraction, void* context)
{
	(void)shapeId;
	(void)point;
	(void)normal;
	(void)fraction;
	*(int*)context += 1;
	return CD_R(1.0);
}

static void TestQueries(void)
{
	cd2WorldDef wd = cd2DefaultWorldDef();
	cd2WorldId world = cd2CreateWorld(&wd);
	MakeStaticBox(world, cd2MakeVec(CD_R(0.0), CD_R(-1.0)), CD_R(50.0), CD_R(1.0));
	for (int i = 0; i < 5; ++i)
	{
		MakeStaticBox(world, cd2MakeVec((cdReal)(3 * i), CD_R(2.0)), CD_R(0.5), CD_R(0.5));
	}
	cd2QueryFilter filter = cd2DefaultQueryFilter();
	cd2RayResult r = cd2World_RaycastClosest(world, cd2MakeVec(CD_R(3.0), CD_R(10.0)),
											 cd2MakeVec(CD_R(0.0), CD_R(-20.0)), filter);
	TEST_CHECK(r.hit);
	TEST_CHECK_NEAR(r.point.y, 2.5, 1e-4);
	TEST_CHECK_NEAR(r.normal.y, 1.0, 1e-5);
	TEST_CHECK_NEAR(r.fraction, 7.5 / 20.0, 1e-5);
	r = cd2World_RaycastClosest(world, cd2MakeVec(CD_R(1.5), CD_R(10.0)), cd2MakeVec(CD_R(0.0), CD_R(-20.0)),
								filter);
	TEST_CHECK(r.hit);
	TEST_CHECK_NEAR(r.point.y, 0.0, 1e-4);
	int count = 0;
	cd2World_Raycast(world, cd2MakeVec(CD_R(-5.0), CD_R(2.0)), cd2MakeVec(CD_R(30.0), CD_R(0.0)), filter,
					 CollectAll, &count);
	TEST_CHECK(count == 5);
	count = 0;
	cd2Aabb box = {{CD_R(-1.0), CD_R(1.0)}, {CD_R(4.0), CD_R(3.0)}};
	cd2World_OverlapAabb(world, box, filter, CountOverlap, &count);
	TEST_CHECK(count == 2);
	count = 0;
	cd2Shape circle = cd2MakeCircleShape((cd2Circle){{CD_R(1.5), CD_R(2.0)}, CD_R(1.2)});
	cd2World_OverlapShape(world, &circle, filter, CountOverlap, &count);
	TEST_CHECK(count == 2);
	count = 0;
	circle.circle.radius = CD_R(0.9);
	cd2World_OverlapShape(world, &circle, filter, CountOverlap, &count);
	TEST_CHECK(count == 0);
	count = 0;
	cd2World_ShapeCast(world, &circle, cd2MakeVec(CD_R(0.0), CD_R(-5.0)), filter, CollectAll, &count);
	TEST_CHECK(count == 1); /* only the ground */
	/* A filter that excludes the default category sees nothing. */
	cd2QueryFilter none = {1u, 2u};
	r = cd2World_RaycastClosest(world, cd2MakeVec(CD_R(3.0), CD_R(10.0)), cd2MakeVec(CD_R(0.0), CD_R(-20.0)),
								none);
	TEST_CHECK(!r.hit);
	cd2DestroyWorld(world);
}

/* A ball rolls down a chain slope and rests in its valley, never falling through. */
static void TestChain(void)
{
	cd2WorldDef wd = cd2DefaultWorldDef();
	cd2WorldId world = cd2CreateWorld(&wd);
	cd2BodyDef bd = cd2DefaultBodyDef();
	cd2BodyId terrain = cd2CreateBody(world, &bd);
	/* A V-shaped valley, running right to left (free side up). */
	cd2Vec points[21];
	for (int i = 0; i < 21; ++i)
	{
		cdReal x = (cdReal)(10 - i);
		points[i] = cd2MakeVec(x, CD_R(0.2) * cdAbs(x));
	}
	cd2ChainDef cd = cd2DefaultChainDef();
	cd.points = points;
	cd.count = 21;
	cd2ChainId chain = cd2CreateChainShape(terrain, &cd);
	TEST_CHECK(cd2ChainShape_IsValid(chain));
	TEST_CHECK(cd2ChainShape_GetSegmentCount(chain) == 20);
	cd2BodyId ball = MakeBall(world, cd2MakeVec(CD_R(6.0), CD_R(3.0)), CD_R(0.25), false);
	cd2BodyId box;
	{
		bd.type = CD_DYNAMIC_BODY;
		bd.position = cd2MakeVec(CD_R(-6.0), CD_R(3.0));
		box = cd2CreateBody(world, &bd);
		cd2ShapeDef sd = cd2DefaultShapeDef();
		sd.friction = CD_R(0.0);
		cd2Polygon poly;
		cd2MakeBoxPolygon((cd2Box){{CD_R(0.0), CD_R(0.0)}, {CD_R(0.3), CD_R(0.2)}, {CD_R(1.0), CD_R(0.0)}},
						  &poly);
		cd2CreatePolygonShape(box, &sd, &poly);
	}
	cd2Body_SetAngularDamping(ball, CD_R(1.0));
	cd2Body_SetLinearDamping(box, CD_R(1.0));
	for (int i = 0; i < 900; ++i)
	{
		cd2World_Step(world, DT, 4);
		TEST_CHECK(cd2Body_GetPosition(ball).y > CD_R(0.0));
	}
	cd2Vec p = cd2Body_GetPosition(ball);
	TEST_CHECKF(cdAbs(p.x) < CD_R(0.5) && p.y < CD_R(0.5), "ball at %g %g", (double)p.x, (double)p.y);
	p = cd2Body_GetPosition(box);
	TEST_CHECKF(cdAbs(p.x) < CD_R(1.0) && p.y > CD_R(0.0) && p.y < CD_R(0.6), "box at %g %g", (double)p.x,
				(double)p.y);
	cd2DestroyChainShape(chain);
	TEST_CHECK(!cd2ChainShape_IsValid(chain));
	cd2DestroyWorld(world);
}

/* Fast small bodies never tunnel through a thin static wall: bullets at 1000 m/s (against the
 * wall, through continuous collision) and fast ordinary bodies. */
static void TestContinuous(void)
{
	TestRng rng = TestRngMake(11);
	cd2WorldDef wd = cd2DefaultWorldDef();
	wd.gravity = CD2_VEC_ZERO;
	cd2WorldId world = cd2CreateWorld(&wd);
	MakeStaticBox(world, cd2MakeVec(CD_R(0.0), CD_R(0.0)), CD_R(0.05), CD_R(20.0));
	int crossed = 0, shots = 10000;
	for (int s = 0; s < shots; ++s)
	{
		cdReal y = (cdReal)TestRngRange(&rng, -10.0, 10.0);
		cdReal x = (cdReal)TestRngRange(&rng, -30.0, -2.0);
		cdReal vy = (cdReal)TestRngRange(&rng, -50.0, 50.0);
		cd2BodyId bullet = MakeBall(world, cd2MakeVec(x, y), CD_R(0.05), s % 2 == 0);
		cd2Body_SetLinearVelocity(bullet, cd2MakeVec(CD_R(1000.0), vy));
		for (int i = 0; i < 10; ++i)
		{
			cd2World_Step(world, DT, 4);
		}
		crossed += cd2Body_GetPosition(bullet).x > CD_R(0.0);
		cd2DestroyBody(bullet);
	}
	TEST_CHECKF(crossed == 0, "%d of %d crossed", crossed, shots);
	/* A bullet against a thin dynamic plank (continuous against moving bodies). */
	cd2BodyDef bd = cd2DefaultBodyDef();
	bd.type = CD_DYNAMIC_BODY;
	bd.position = cd2MakeVec(-CD_R(5.0), CD_R(0.0));
	cd2BodyId plank = cd2CreateBody(world, &bd);
	cd2ShapeDef sd = cd2DefaultShapeDef();
	sd.density = CD_R(10.0);
	cd2Polygon box;
	cd2MakeBoxPolygon((cd2Box){{CD_R(0.0), CD_R(0.0)}, {CD_R(0.05), CD_R(2.0)}, {CD_R(1.0), CD_R(0.0)}},
					  &box);
	cd2CreatePolygonShape(plank, &sd, &box);
	cd2BodyId bullet = MakeBall(world, cd2MakeVec(-CD_R(20.0), CD_R(0.0)), CD_R(0.05), true);
	cd2Body_SetLinearVelocity(bullet, cd2MakeVec(CD_R(600.0), CD_R(0.0)));
	for (int i = 0; i < 3; ++i)
	{
		cd2World_Step(world, DT, 4);
	}
	TEST_CHECK(cd2Body_GetPosition(bullet).x < cd2Body_GetPosition(plank).x);
	TEST_CHECK(cd2Body_GetLinearVelocity(plank).x > CD_R(0.0)); /* it was hit */
	cd2DestroyWorld(world);
}

/* Fast ordinary bodies against a one-sided chain floor (free side up): shot down steeply, shot at a
 * grazing angle, resting on it and then shot down hard, and shot so that the first step ends with
 * the centre just in front of the chain, deep in it, before going on down (the sweep skips a shape
 * whose centroid ends well in front of a segment, and only then). None may end behind the chain. */
static void TestContinuousOneSidedChain(void)
{
	TestRng rng = TestRngMake(23);
	cd2WorldDef wd = cd2DefaultWorldDef();
	cd2WorldId world = cd2CreateWorld(&wd);
	cd2BodyDef bd = cd2DefaultBodyDef();
	cd2BodyId terrain = cd2CreateBody(world, &bd);
	cd2Vec points[41];
	for (int i = 0; i < 41; ++i)
	{
		points[i] = cd2MakeVec((cdReal)(20 - i), CD_R(0.0)); /* right to left: free side up */
	}
	cd2ChainDef cd = cd2DefaultChainDef();
	cd.points = points;
	cd.count = 41;
	cd2CreateChainShape(terrain, &cd);
	int below = 0, shots = 1200, skimmed = 0;
	for (int s = 0; s < shots; ++s)
	{
		int kind = s % 4;
		cdReal x = (cdReal)TestRngRange(&rng, -10.0, 10.0);
		cdReal radius = CD_R(0.05) + CD_R(0.3) * (cdReal)TestRngRange(&rng, 0.0, 1.0);
		cdReal y = kind == 2 ? radius : CD_R(3.0);
		/* kind 3: the centre ends the first step between 0.1 and 0.45 radii above the chain */
		cdReal depth = radius * (cdReal)TestRngRange(&rng, 0.1, 0.45);
		cd2BodyId body = MakeBall(world, cd2MakeVec(x, y), radius, false);
		cd2Vec v = kind == 0   ? cd2MakeVec((cdReal)TestRngRange(&rng, -100.0, 100.0), -CD_R(600.0))
				   : kind == 1 ? cd2MakeVec((cdReal)TestRngRange(&rng, 100.0, 200.0), -CD_R(120.0))
				   : kind == 3 ? cd2MakeVec(CD_R(0.0), -(y - depth) / DT)
							   : CD2_VEC_ZERO;
		cd2Body_SetLinearVelocity(body, v);
		cdReal lowest = CD_R(1.0);
		for (int i = 0; i < 12; ++i)
		{
			if (kind == 2 && i == 4)
			{
				/* Resting on the floor: now down hard and sideways. */
				cd2Body_SetLinearVelocity(
					body, cd2MakeVec((cdReal)TestRngRange(&rng, -300.0, 300.0), -CD_R(900.0)));
			}
			cd2World_Step(world, DT, 4);
			cd2Vec p = cd2Body_GetPosition(body);
			if (cdAbs(p.x) < CD_R(19.0)) /* over the chain (a grazing shot leaves it sideways) */
			{
				lowest = cdMin(lowest, p.y);
				skimmed += kind == 1 && p.y < CD_R(2.0) * radius ? 1 : 0;
			}
		}
		below += lowest < CD_R(0.0) ? 1 : 0;
		cd2DestroyBody(body);
	}
	TEST_CHECKF(below == 0, "%d of %d ended behind the chain", below, shots);
	TEST_CHECK(skimmed > 0); /* grazing shots reached the floor over the chain */
	cd2DestroyWorld(world);
}

/* Fast non-bullet balls shot at the wall (at x = wallX, from 10 m before it); how many ended beyond it. */
static int ShootAtWallAt(cd2WorldId world, int shots, TestRng* rng, cdReal wallX)
{
	int crossed = 0;
	for (int s = 0; s < shots; ++s)
	{
		cdReal y = (cdReal)TestRngRange(rng, -5.0, 5.0);
		/* It crosses the wall in its first step, before any contact: only the sweep stops it. */
		cd2BodyId ball = MakeBall(world, cd2MakeVec(wallX - CD_R(10.0), y), CD_R(0.05), false);
		cd2Body_SetLinearVelocity(ball, cd2MakeVec(CD_R(800.0), CD_R(0.0)));
		for (int i = 0; i < 4; ++i)
		{
			cd2World_Step(world, DT, 4);
		}
		crossed += cd2Body_GetPosition(ball).x > wallX;
		cd2DestroyBody(ball);
	}
	return crossed;
}

static int ShootAtWall(cd2WorldId world, int shots, TestRng* rng)
{
	return ShootAtWallAt(world, shots, rng, CD_R(0.0));
}

/* A fast ordinary body sweeps against static shapes only (the world's static broadphase; none: no
 * sweep). The static shapes are followed through every way a shape enters, leaves or moves in the
 * static set (made static, a body made dynamic and static again, disabled and enabled, destroyed,
 * the state restored, the body moved), and the wall stops the balls after each. */
static void TestContinuousStaticCount(void)
{
	TestRng rng = TestRngMake(5);
	cd2WorldDef wd = cd2DefaultWorldDef();
	wd.gravity = CD2_VEC_ZERO;
	cd2WorldId world = cd2CreateWorld(&wd);
	/* No static shape: a fast ball meets nothing and flies on. */
	TEST_CHECK(ShootAtWall(world, 1, &rng) == 1);
	cd2BodyId wall = MakeStaticBox(world, CD2_VEC_ZERO, CD_R(0.02), CD_R(10.0));
	TEST_CHECKF(ShootAtWall(world, 20, &rng) == 0, "static wall");
	cd2Body_SetType(wall, CD_DYNAMIC_BODY);
	cd2Body_SetType(wall, CD_STATIC_BODY);
	TEST_CHECKF(ShootAtWall(world, 20, &rng) == 0, "wall made dynamic and static again");
	cd2Body_Disable(wall);
	TEST_CHECK(ShootAtWall(world, 1, &rng) == 1);
	cd2Body_Enable(wall);
	TEST_CHECKF(ShootAtWall(world, 20, &rng) == 0, "wall disabled and enabled");
	size_t size = cd2World_GetStateSize(world);
	void* state = malloc(size);
	TEST_CHECK(state != NULL && cd2World_SaveState(world, state, size) == CD_OK);
	cd2DestroyBody(wall);
	TEST_CHECK(ShootAtWall(world, 1, &rng) == 1);
	TEST_CHECK(state != NULL && cd2World_RestoreState(world, state, size) == CD_OK);
	TEST_CHECKF(ShootAtWall(world, 20, &rng) == 0, "state with the wall restored");
	/* Moved away and back (a static body's shapes move with it). */
	TEST_CHECK(cd2Body_IsValid(wall));
	cd2Body_SetTransform(wall, cd2MakeVec(CD_R(20.0), CD_R(0.0)), CD2_ROT_IDENTITY);
	TEST_CHECKF(ShootAtWallAt(world, 20, &rng, CD_R(20.0)) == 0, "wall moved");
	cd2Body_SetTransform(wall, CD2_VEC_ZERO, CD2_ROT_IDENTITY);
	TEST_CHECKF(ShootAtWall(world, 20, &rng) == 0, "wall moved away and back");
	free(state);
	cd2DestroyWorld(world);
}

/* The end of the step with every kind of body it treats apart (fast bodies swept against static
 * shapes, a bullet swept against a moving plank, a moving kinematic body that wakes what it
 * touches, boxes that fall asleep): every move event carries its body's pose after the step and
 * says whether it fell asleep, every shape's box holds the shape, and the events, poses and boxes
 * are the same bits for 1, 2 and 4 workers. */
typedef struct FinalizeRun
{
	uint64_t hash;
	int moveEvents, fellAsleep, badEvents, badBoxes;
	cdReal bulletX, plankX, lowestBall;
} FinalizeRun;

static void HashBytes(uint64_t* h, const void* data, size_t size)
{
	const unsigned char* bytes = (const unsigned char*)data;
	for (size_t i = 0; i < size; ++i)
	{
		*h = (*h ^ bytes[i]) * 1099511628211ull;
	}
}

static FinalizeRun RunFinalizeScene(int workerCount)
{
	enum
	{
		BALLS = 12,
		RESTING = 10,
		BODIES = BALLS + RESTING + 3
	};
	static int tags[BODIES];
	FinalizeRun run;
	memset(&run, 0, sizeof(run));
	run.hash = 14695981039346656037ull;
	cd2WorldDef wd = cd2DefaultWorldDef();
	wd.workerCount = workerCount;
	cd2WorldId world = cd2CreateWorld(&wd);
	MakeStaticBox(world, cd2MakeVec(CD_R(0.0), -CD_R(0.5)), CD_R(60.0), CD_R(0.5));
	cd2BodyId bodies[BODIES];
	cd2ShapeId shapes[BODIES];
	cdReal radii[BODIES];
	cd2ShapeDef sd = cd2DefaultShapeDef();
	cd2BodyDef bd = cd2DefaultBodyDef();
	int n = 0;
	/* Fast non-bullets: small balls thrown down hard onto the ground. */
	for (int i = 0; i < BALLS; ++i, ++n)
	{
		bodies[n] =
			MakeBall(world, cd2MakeVec(-CD_R(20.0) + CD_R(1.5) * (cdReal)i, CD_R(6.0)), CD_R(0.1), false);
		cd2Body_SetLinearVelocity(bodies[n], cd2MakeVec(CD_R(0.0), -CD_R(60.0) - CD_R(5.0) * (cdReal)i));
		radii[n] = CD_R(0.1);
	}
	/* Boxes resting on the ground; the kinematic pusher reaches the last ones. */
	cd2Polygon box;
	cd2MakeBoxPolygon((cd2Box){{CD_R(0.0), CD_R(0.0)}, {CD_R(0.25), CD_R(0.25)}, {CD_R(1.0), CD_R(0.0)}},
					  &box);
	for (int i = 0; i < RESTING; ++i, ++n)
	{
		bd = cd2DefaultBodyDef();
		bd.type = CD_DYNAMIC_BODY;
		bd.position = cd2MakeVec(CD_R(2.0) + CD_R(0.6) * (cdReal)i, CD_R(0.25));
		bodies[n] = cd2CreateBody(world, &bd);
		shapes[n] = cd2CreatePolygonShape(bodies[n], &sd, &box);
		radii[n] = CD_R(0.0);
	}
	bd = cd2DefaultBodyDef();
	bd.type = CD_KINEMATIC_BODY;
	bd.position = cd2MakeVec(CD_R(8.6), CD_R(0.6));
	bd.linearVelocity = cd2MakeVec(-CD_R(0.5), CD_R(0.0));
	bodies[n] = cd2CreateBody(world, &bd);
	shapes[n] = cd2CreatePolygonShape(bodies[n], &sd, &box);
	radii[n++] = CD_R(0.0);
	/* A bullet at a thin standing plank. */
	bd = cd2DefaultBodyDef();
	bd.type = CD_DYNAMIC_BODY;
	bd.position = cd2MakeVec(CD_R(30.0), CD_R(2.0));
	int plank = n;
	bodies[n] = cd2CreateBody(world, &bd);
	cd2Polygon thin;
	cd2MakeBoxPolygon((cd2Box){{CD_R(0.0), CD_R(0.0)}, {CD_R(0.05), CD_R(2.0)}, {CD_R(1.0), CD_R(0.0)}},
					  &thin);
	shapes[n] = cd2CreatePolygonShape(bodies[n], &sd, &thin);
	radii[n++] = CD_R(0.0);
	int bullet = n;
	bodies[n] = MakeBall(world, cd2MakeVec(CD_R(20.0), CD_R(2.5)), CD_R(0.05), true);
	cd2Body_SetLinearVelocity(bodies[n], cd2MakeVec(CD_R(500.0), CD_R(0.0)));
	radii[n++] = CD_R(0.05);
	for (int i = 0; i < n; ++i)
	{
		tags[i] = i;
		cd2Body_SetUserData(bodies[i], tags + i);
		if (radii[i] > CD_R(0.0))
		{
			cd2ShapeId one[1];
			TEST_CHECK(cd2Body_GetShapes(bodies[i], one, 1) == 1);
			shapes[i] = one[0];
		}
	}
	for (int step = 0; step < 150; ++step)
	{
		cd2World_Step(world, DT, 4);
		if (step == 2)
		{
			run.bulletX = cd2Body_GetPosition(bodies[bullet]).x;
			run.plankX = cd2Body_GetPosition(bodies[plank]).x;
		}
		cd2BodyEvents events = cd2World_GetBodyEvents(world);
		run.moveEvents += events.moveCount;
		for (int e = 0; e < events.moveCount; ++e)
		{
			const cd2BodyMoveEvent* event = events.moveEvents + e;
			int tag = event->userData != NULL ? *(const int*)event->userData : -1;
			cd2Transform xf = cd2Body_GetTransform(event->bodyId);
			bool ok = tag >= 0 && tag < n && cd2BodyIdEqual(event->bodyId, bodies[tag]) &&
					  memcmp(&xf.p, &event->transform.p, sizeof(xf.p)) == 0 &&
					  memcmp(&xf.q, &event->transform.q, sizeof(xf.q)) == 0 &&
					  event->fellAsleep == !cd2Body_IsAwake(event->bodyId);
			run.badEvents += ok ? 0 : 1;
			run.fellAsleep += event->fellAsleep ? 1 : 0;
			HashBytes(&run.hash, &tag, sizeof(tag));
			HashBytes(&run.hash, &event->transform.p, sizeof(event->transform.p));
			HashBytes(&run.hash, &event->transform.q, sizeof(event->transform.q));
			HashBytes(&run.hash, &event->fellAsleep, sizeof(event->fellAsleep));
		}
		for (int i = 0; i < n; ++i)
		{
			cd2Aabb a = cd2Shape_GetAabb(shapes[i]);
			HashBytes(&run.hash, &a, sizeof(a));
			/* The box holds the shape where its body ended the step (a ball: its disc). */
			cd2Vec p = cd2Body_GetPosition(bodies[i]);
			cdReal r = radii[i];
			if (!(a.min.x <= p.x - r && a.min.y <= p.y - r && p.x + r <= a.max.x && p.y + r <= a.max.y))
			{
				run.badBoxes += 1;
			}
		}
	}
	run.lowestBall = CD_REAL_MAX;
	for (int i = 0; i < BALLS; ++i)
	{
		run.lowestBall = cdMin(run.lowestBall, cd2Body_GetPosition(bodies[i]).y);
	}
	cd2DestroyWorld(world);
	return run;
}

static void TestFinalizeAcrossWorkers(void)
{
	FinalizeRun one = RunFinalizeScene(1);
	TEST_CHECKF(one.badEvents == 0, "%d move events off their body", one.badEvents);
	TEST_CHECKF(one.badBoxes == 0, "%d shape boxes miss their shape", one.badBoxes);
	TEST_CHECK(one.fellAsleep > 0);
	TEST_CHECK(one.moveEvents > 150);
	/* Swept, not tunnelled: the balls stay above the ground, the bullet in front of the plank. */
	TEST_CHECKF(one.lowestBall > CD_R(0.0), "lowest ball at %g", (double)one.lowestBall);
	TEST_CHECKF(one.bulletX < one.plankX, "bullet at %g, plank at %g", (double)one.bulletX,
				(double)one.plankX);
	int counts[2] = {2, 4};
	for (int k = 0; k < 2; ++k)
	{
		FinalizeRun other = RunFinalizeScene(counts[k]);
		TEST_CHECKF(other.hash == one.hash, "%d workers: hash %llx, 1 worker %llx", counts[k],
					(unsigned long long)other.hash, (unsigned long long)one.hash);
		TEST_CHECK(other.badEvents == 0 && other.badBoxes == 0);
		TEST_CHECK(other.moveEvents == one.moveEvents && other.fellAsleep == one.fellAsleep);
	}
}

/* Joints of one colour share no awake body and are solved at the same time with more workers:
 * chains hanging from the ground (a static body takes no colour), chains hung from one moving
 * kinematic body (which does), welded and distance-jointed pairs, and chains that fall onto each
 * other. Poses, velocities and joint forces are the same bits for 1, 2 and 4 workers. */
static uint64_t RunJointColors(int workerCount, int* awakeOut)
{
	enum
	{
		CHAINS = 16,
		LINKS = 6
	};
	cd2WorldDef wd = cd2DefaultWorldDef();
	wd.workerCount = workerCount;
	cd2WorldId world = cd2CreateWorld(&wd);
	cd2BodyId ground = MakeStaticBox(world, cd2MakeVec(CD_R(0.0), -CD_R(0.5)), CD_R(60.0), CD_R(0.5));
	cd2BodyDef bd = cd2DefaultBodyDef();
	bd.type = CD_KINEMATIC_BODY;
	bd.position = cd2MakeVec(CD_R(10.0), CD_R(12.0));
	bd.linearVelocity = cd2MakeVec(CD_R(1.0), CD_R(0.0));
	bd.angularVelocity = CD_R(0.5);
	cd2BodyId mover = cd2CreateBody(world, &bd);
	cd2ShapeDef sd = cd2DefaultShapeDef();
	cd2Capsule link = {{-CD_R(0.4), CD_R(0.0)}, {CD_R(0.4), CD_R(0.0)}, CD_R(0.1)};
	cd2JointId joints[CHAINS * (LINKS + 1)];
	int jointCount = 0;
	cd2BodyId bodies[CHAINS * LINKS];
	int bodyCount = 0;
	for (int c = 0; c < CHAINS; ++c)
	{
		/* Chains 0-3 hang from the kinematic body, the others from the ground (static), the odd
		 * ones of those lower so that they fall onto the ground and onto each other. */
		bool fromMover = c < 4;
		cdReal x = fromMover ? CD_R(10.0) : -CD_R(30.0) + CD_R(3.0) * (cdReal)c;
		cdReal y = fromMover ? CD_R(12.0) : (c % 2 == 0 ? CD_R(9.0) : CD_R(4.0));
		cd2BodyId previous = fromMover ? mover : ground;
		cd2Vec anchor = fromMover ? CD2_VEC_ZERO : cd2MakeVec(x, y);
		for (int l = 0; l < LINKS; ++l)
		{
			bd = cd2DefaultBodyDef();
			bd.type = CD_DYNAMIC_BODY;
			bd.position = cd2MakeVec(x + CD_R(0.8) * (cdReal)l + CD_R(0.4), y);
			cd2BodyId body = cd2CreateBody(world, &bd);
			cd2CreateCapsuleShape(body, &sd, &link);
			bodies[bodyCount++] = body;
			if (c % 4 == 3 && l > 0)
			{
				cd2WeldJointDef wj = cd2DefaultWeldJointDef();
				wj.bodyIdA = previous;
				wj.bodyIdB = body;
				wj.localAnchorA = cd2MakeVec(CD_R(0.4), CD_R(0.0));
				wj.localAnchorB = cd2MakeVec(-CD_R(0.4), CD_R(0.0));
				wj.angularHertz = CD_R(5.0);
				joints[jointCount++] = cd2CreateWeldJoint(world, &wj);
			}
			else if (c % 4 == 2 && l > 0)
			{
				cd2DistanceJointDef dj = cd2DefaultDistanceJointDef();
				dj.bodyIdA = previous;
				dj.bodyIdB = body;
				dj.localAnchorA = cd2MakeVec(CD_R(0.4), CD_R(0.0));
				dj.localAnchorB = cd2MakeVec(-CD_R(0.4), CD_R(0.0));
				dj.length = CD_R(0.05);
				joints[jointCount++] = cd2CreateDistanceJoint(world, &dj);
			}
			else
			{
				cd2RevoluteJointDef rj = cd2DefaultRevoluteJointDef();
				rj.bodyIdA = previous;
				rj.bodyIdB = body;
				rj.localAnchorA = l == 0 ? anchor : cd2MakeVec(CD_R(0.4), CD_R(0.0));
				rj.localAnchorB = cd2MakeVec(-CD_R(0.4), CD_R(0.0));
				rj.enableLimit = c % 3 == 0;
				rj.lowerAngle = -CD_R(0.5);
				rj.upperAngle = CD_R(0.5);
				joints[jointCount++] = cd2CreateRevoluteJoint(world, &rj);
			}
			previous = body;
		}
	}
	uint64_t hash = 14695981039346656037ull;
	for (int step = 0; step < 90; ++step)
	{
		cd2World_Step(world, DT, 4);
	}
	int awake = 0;
	for (int i = 0; i < bodyCount; ++i)
	{
		cd2Transform xf = cd2Body_GetTransform(bodies[i]);
		cd2Vec v = cd2Body_GetLinearVelocity(bodies[i]);
		cdReal w = cd2Body_GetAngularVelocity(bodies[i]);
		HashBytes(&hash, &xf.p, sizeof(xf.p));
		HashBytes(&hash, &xf.q, sizeof(xf.q));
		HashBytes(&hash, &v, sizeof(v));
		HashBytes(&hash, &w, sizeof(w));
		awake += cd2Body_IsAwake(bodies[i]) ? 1 : 0;
	}
	for (int j = 0; j < jointCount; ++j)
	{
		cd2Vec f = cd2Joint_GetConstraintForce(joints[j]);
		HashBytes(&hash, &f, sizeof(f));
	}
	*awakeOut = awake;
	cd2DestroyWorld(world);
	return hash;
}

static void TestJointColorsAcrossWorkers(void)
{
	int awake1 = 0, awake = 0;
	uint64_t one = RunJointColors(1, &awake1);
	/* The chains are still moving (the hash covers a moving scene, not a resting one). */
	TEST_CHECK(awake1 > 0);
	int counts[2] = {2, 4};
	for (int k = 0; k < 2; ++k)
	{
		uint64_t other = RunJointColors(counts[k], &awake);
		TEST_CHECKF(other == one, "%d workers: hash %llx, 1 worker %llx", counts[k],
					(unsigned long long)other, (unsigned long long)one);
		TEST_CHECK(awake == awake1);
	}
}

/* A body made asleep (isAwake false) stays asleep when its shapes are added and through steps, like
 * a grid of resting boxes waiting to be hit, and wakes when an awake body touches it. */
static void TestCreatedAsleep(void)
{
	cd2WorldDef wd = cd2DefaultWorldDef();
	cd2WorldId world = cd2CreateWorld(&wd);
	cd2BodyDef bd = cd2DefaultBodyDef();
	bd.type = CD_DYNAMIC_BODY;
	bd.isAwake = false;
	bd.position = cd2MakeVec(CD_R(0.0), CD_R(5.0));
	cd2BodyId sleeper = cd2CreateBody(world, &bd);
	cd2ShapeDef sd = cd2DefaultShapeDef();
	cd2Polygon box;
	cd2MakeBoxPolygon((cd2Box){{CD_R(0.0), CD_R(0.0)}, {CD_R(0.5), CD_R(0.5)}, {CD_R(1.0), CD_R(0.0)}}, &box);
	cd2CreatePolygonShape(sleeper, &sd, &box);
	TEST_CHECK(!cd2Body_IsAwake(sleeper));
	for (int i = 0; i < 10; ++i)
	{
		cd2World_Step(world, DT, 4);
	}
	TEST_CHECK(!cd2Body_IsAwake(sleeper));
	TEST_CHECK_NEAR(cd2Body_GetPosition(sleeper).y, 5.0, 1e-6); /* asleep in the air: it did not fall */
	TEST_CHECK(cd2World_GetCounters(world).awakeBodyCount == 0);
	/* A ball dropped onto it wakes it at the touch, and then it falls. */
	cd2BodyId ball = MakeBall(world, cd2MakeVec(CD_R(0.0), CD_R(6.0)), CD_R(0.25), false);
	bool woke = false;
	for (int i = 0; i < 60 && !woke; ++i)
	{
		cd2World_Step(world, DT, 4);
		woke = cd2Body_IsAwake(sleeper);
	}
	TEST_CHECK(woke);
	for (int i = 0; i < 30; ++i)
	{
		cd2World_Step(world, DT, 4);
	}
	TEST_CHECK(cd2Body_GetPosition(sleeper).y < CD_R(4.5));
	TEST_CHECK(cd2Body_IsValid(ball));
	cd2DestroyWorld(world);
}

/* cd2Body_SetAwake(body, false) puts the body's group to sleep: the bodies it touches or is jointed
 * to, through any chain of them, and no other body (a static ground joins nothing). */
static void TestSetAwakeFalseSleepsGroup(void)
{
	cd2WorldDef wd = cd2DefaultWorldDef();
	cd2WorldId world = cd2CreateWorld(&wd);
	MakeStaticBox(world, cd2MakeVec(CD_R(0.0), CD_R(-1.0)), CD_R(50.0), CD_R(1.0));
	/* A stack of three balls, a lone ball on the same ground, and a jointed pair in the air. */
	cd2BodyId stack[3];
	for (int i = 0; i < 3; ++i)
	{
		stack[i] =
			MakeBall(world, cd2MakeVec(CD_R(0.0), CD_R(0.5) + CD_R(1.0) * (cdReal)i), CD_R(0.5), false);
	}
	cd2BodyId lone = MakeBall(world, cd2MakeVec(CD_R(10.0), CD_R(0.5)), CD_R(0.5), false);
	cd2BodyId pair[2] = {MakeBall(world, cd2MakeVec(CD_R(-10.0), CD_R(20.0)), CD_R(0.5), false),
						 MakeBall(world, cd2MakeVec(CD_R(-12.0), CD_R(20.0)), CD_R(0.5), false)};
	cd2RevoluteJointDef jd = cd2DefaultRevoluteJointDef();
	jd.bodyIdA = pair[0];
	jd.bodyIdB = pair[1];
	jd.localAnchorB = cd2MakeVec(CD_R(2.0), CD_R(0.0));
	cd2CreateRevoluteJoint(world, &jd);
	for (int i = 0; i < 5; ++i)
	{
		cd2World_Step(world, DT, 4);
	}
	TEST_CHECK(cd2World_GetCounters(world).awakeBodyCount == 6);

	cd2Body_SetAwake(stack[1], false);
	for (int i = 0; i < 3; ++i)
	{
		TEST_CHECKF(!cd2Body_IsAwake(stack[i]), "stack ball %d awake", i);
	}
	TEST_CHECK(cd2Body_IsAwake(lone) && cd2Body_IsAwake(pair[0]) && cd2Body_IsAwake(pair[1]));
	cd2Body_SetAwake(pair[1], false);
	TEST_CHECK(!cd2Body_IsAwake(pair[0]) && !cd2Body_IsAwake(pair[1]));
	cdReal pairY = cd2Body_GetPosition(pair[0]).y;
	cd2World_Step(world, DT, 4);
	TEST_CHECK(cd2World_GetCounters(world).awakeBodyCount == 1);
	TEST_CHECK(cd2Body_GetPosition(pair[0]).y == pairY); /* asleep in the air: it did not fall */
	/* Waking one body of a sleeping group wakes the group. */
	cd2Body_SetAwake(stack[2], true);
	TEST_CHECK(cd2Body_IsAwake(stack[0]) && cd2Body_IsAwake(stack[1]));
	cd2DestroyWorld(world);
}

/* Disable/enable, set type, set transform, mass data. */
static void TestBodyControls(void)
{
	cd2WorldDef wd = cd2DefaultWorldDef();
	cd2WorldId world = cd2CreateWorld(&wd);
	MakeStaticBox(world, cd2MakeVec(CD_R(0.0), CD_R(-1.0)), CD_R(50.0), CD_R(1.0));
	cd2BodyId ball = MakeBall(world, cd2MakeVec(CD_R(0.0), CD_R(2.0)), CD_R(0.5), false);
	cd2MassData md = cd2Body_GetMassData(ball);
	TEST_CHECK_NEAR(md.mass, 3.14159265 * 0.25, 1e-4);
	md.mass = CD_R(10.0);
	cd2Body_SetMassData(ball, md);
	TEST_CHECK_NEAR(cd2Body_GetMass(ball), 10.0, 0.0);
	cd2Body_ApplyMassFromShapes(ball);
	TEST_CHECK_NEAR(cd2Body_GetMass(ball), 3.14159265 * 0.25, 1e-4);
	cd2Body_Disable(ball);
	for (int i = 0; i < 60; ++i)
	{
		cd2World_Step(world, DT, 4);
	}
	TEST_CHECK(!cd2Body_IsEnabled(ball));
	TEST_CHECK_NEAR(cd2Body_GetPosition(ball).y, 2.0, 0.0);
	cd2Body_Enable(ball);
	for (int i = 0; i < 120; ++i)
	{
		cd2World_Step(world, DT, 4);
	}
	TEST_CHECK_NEAR(cd2Body_GetPosition(ball).y, 0.5, 0.02);
	cd2Body_SetType(ball, CD_KINEMATIC_BODY);
	cd2Body_SetLinearVelocity(ball, cd2MakeVec(CD_R(1.0), CD_R(0.0)));
	for (int i = 0; i < 60; ++i)
	{
		cd2World_Step(world, DT, 4);
	}
	TEST_CHECK_NEAR(cd2Body_GetPosition(ball).x, 1.0, 1e-3);
	TEST_CHECK(cd2Body_GetType(ball) == CD_KINEMATIC_BODY);
	cd2Body_SetTransform(ball, cd2MakeVec(CD_R(3.0), CD_R(4.0)), cd2MakeRot(CD_R(0.5)));
	TEST_CHECK_NEAR(cd2Body_GetPosition(ball).x, 3.0, 0.0);
	TEST_CHECK_NEAR(cd2RotGetAngle(cd2Body_GetRotation(ball)), 0.5, 1e-5);
	cd2Vec wp = cd2Body_GetWorldPoint(ball, cd2MakeVec(CD_R(1.0), CD_R(0.0)));
	cd2Vec lp = cd2Body_GetLocalPoint(ball, wp);
	TEST_CHECK_NEAR(lp.x, 1.0, 1e-5);
	TEST_CHECK_NEAR(lp.y, 0.0, 1e-5);
	cd2DestroyWorld(world);
}

/* The small accessors: each one read back or seen to act. */
static void TestAccessors(void)
{
	int tag = 7;
	cd2WorldDef wd = cd2DefaultWorldDef();
	cd2WorldId world = cd2CreateWorld(&wd);
	cd2World_SetUserData(world, &tag);
	TEST_CHECK(cd2World_GetUserData(world) == &tag);
	cd2World_EnableContinuous(world, true);
	cd2BodyId ground = MakeStaticBox(world, cd2MakeVec(CD_R(0.0), CD_R(-1.0)), CD_R(50.0), CD_R(1.0));

	/* Body accessors. */
	cd2BodyId b = MakeBall(world, cd2MakeVec(CD_R(0.0), CD_R(5.0)), CD_R(0.5), false);
	TEST_CHECK(cd2World_IsValid(cd2Body_GetWorld(b)));
	cd2Body_SetUserData(b, &tag);
	TEST_CHECK(cd2Body_GetUserData(b) == &tag);
	cd2Body_SetLinearDamping(b, CD_R(0.5));
	cd2Body_SetAngularDamping(b, CD_R(0.25));
	cd2Body_SetGravityScale(b, CD_R(0.0));
	TEST_CHECK_NEAR(cd2Body_GetLinearDamping(b), 0.5, 0.0);
	TEST_CHECK_NEAR(cd2Body_GetAngularDamping(b), 0.25, 0.0);
	TEST_CHECK_NEAR(cd2Body_GetGravityScale(b), 0.0, 0.0);
	cd2Body_SetBullet(b, true);
	TEST_CHECK(cd2Body_IsBullet(b));
	cd2Body_SetBullet(b, false);
	cd2Body_EnableSleep(b, false);
	for (int i = 0; i < 120; ++i)
	{
		cd2World_Step(world, DT, 4);
	}
	TEST_CHECK_NEAR(cd2Body_GetPosition(b).y, 5.0, 1e-6); /* no gravity */
	TEST_CHECK(cd2Body_IsAwake(b));						  /* sleep disabled for it */
	cd2Body_SetTransform(b, cd2MakeVec(CD_R(0.0), CD_R(5.0)), cd2MakeRot(CD_R(0.5)));
	cd2Vec wv = cd2Body_GetWorldVector(b, cd2MakeVec(CD_R(1.0), CD_R(0.0)));
	TEST_CHECK_NEAR(wv.x, cos(0.5), 1e-5);
	cd2Vec lv = cd2Body_GetLocalVector(b, wv);
	TEST_CHECK_NEAR(lv.x, 1.0, 1e-5);
	TEST_CHECK_NEAR(cd2Body_GetWorldCenterOfMass(b).y, 5.0, 1e-5);
	TEST_CHECK_NEAR(cd2Body_GetLocalCenterOfMass(b).x, 0.0, 0.0);
	/* A force off the centre turns it; a fixed-rotation body does not turn. */
	cd2Body_ApplyForce(b, cd2MakeVec(CD_R(0.0), CD_R(10.0)), cd2MakeVec(CD_R(1.0), CD_R(5.0)), true);
	cd2Body_ApplyAngularImpulse(b, CD_R(0.1), true);
	cd2World_Step(world, DT, 4);
	TEST_CHECK(cd2Body_GetAngularVelocity(b) > CD_R(0.0));
	cd2Body_SetFixedRotation(b, true);
	TEST_CHECK(cd2Body_IsFixedRotation(b));
	cd2Body_ApplyAngularImpulse(b, CD_R(1.0), true);
	TEST_CHECK_NEAR(cd2Body_GetAngularVelocity(b), 0.0, 0.0);
	cd2Body_SetFixedRotation(b, false);

	/* Shape accessors. */
	cd2ShapeId shape;
	TEST_CHECK(cd2Body_GetShapes(b, &shape, 1) == 1);
	TEST_CHECK(cd2Shape_GetType(shape) == CD2_WORLD_SHAPE_CIRCLE);
	TEST_CHECK(cd2BodyIdEqual(cd2Shape_GetBody(shape), b));
	TEST_CHECK(!cd2Shape_IsSensor(shape));
	cd2Shape_SetUserData(shape, &tag);
	TEST_CHECK(cd2Shape_GetUserData(shape) == &tag);
	cd2Shape_SetFriction(shape, CD_R(0.3));
	cd2Shape_SetRestitution(shape, CD_R(0.2));
	TEST_CHECK_NEAR(cd2Shape_GetFriction(shape), 0.3, 1e-6);
	TEST_CHECK_NEAR(cd2Shape_GetRestitution(shape), 0.2, 1e-6);
	TEST_CHECK_NEAR(cd2Shape_GetDensity(shape), 1.0, 0.0);
	cdReal mass = cd2Body_GetMass(b);
	cd2Shape_SetDensity(shape, CD_R(2.0), true);
	TEST_CHECK_NEAR(cd2Body_GetMass(b), 2.0 * (double)mass, 1e-5);
	cd2Shape ws = cd2Shape_GetWorldShape(shape);
	TEST_CHECK(ws.type == CD2_SHAPE_CIRCLE);
	TEST_CHECK_NEAR(ws.circle.center.y, cd2Body_GetPosition(b).y, 1e-6);
	cd2Aabb box = cd2Shape_GetAabb(shape);
	TEST_CHECK_NEAR(box.max.y - box.min.y, 1.0, 1e-5);
	TEST_CHECK(cd2DefaultFilter().categoryBits == 1u && cd2DefaultFilter().maskBits == UINT64_MAX);
	/* Without contact events on either shape, a landing reports nothing; with hit events, a hit. */
	cd2Shape_EnableContactEvents(shape, false);
	cd2ShapeId groundShape;
	cd2Body_GetShapes(ground, &groundShape, 1);
	cd2Shape_EnableContactEvents(groundShape, false);
	cd2Shape_EnableHitEvents(shape, true);
	cd2Shape_EnableSensorEvents(shape, true);
	cd2Shape_EnablePreSolveEvents(shape, false);
	cd2Body_SetGravityScale(b, CD_R(1.0));
	int begins = 0, hits = 0;
	for (int i = 0; i < 120; ++i)
	{
		cd2World_Step(world, DT, 4);
		begins += cd2World_GetContactEvents(world).beginCount;
		hits += cd2World_GetContactEvents(world).hitCount;
	}
	TEST_CHECK(begins == 0);
	TEST_CHECKF(hits >= 1 && hits <= 3, "hits %d",
				hits); /* restitution 0.2: a bounce or two after the landing */

	/* Joint accessors and setters. */
	cd2BodyId arm = MakeBall(world, cd2MakeVec(CD_R(10.0), CD_R(5.0)), CD_R(0.3), false);
	cd2RevoluteJointDef rj = cd2DefaultRevoluteJointDef();
	rj.bodyIdA = ground;
	rj.bodyIdB = arm;
	rj.localAnchorA = cd2MakeVec(CD_R(10.0), CD_R(6.0));
	rj.localAnchorB = cd2MakeVec(CD_R(0.0), CD_R(0.0));
	rj.userData = &tag;
	cd2JointId joint = cd2CreateRevoluteJoint(world, &rj);
	TEST_CHECK(cd2Joint_GetType(joint) == CD2_REVOLUTE_JOINT);
	TEST_CHECK(cd2BodyIdEqual(cd2Joint_GetBodyA(joint), ground) &&
			   cd2BodyIdEqual(cd2Joint_GetBodyB(joint), arm));
	TEST_CHECK(cd2Joint_GetUserData(joint) == &tag);
	cd2Joint_SetUserData(joint, NULL);
	TEST_CHECK(cd2Joint_GetUserData(joint) == NULL);
	cd2RevoluteJoint_EnableMotor(joint, true);
	cd2RevoluteJoint_SetMaxMotorTorque(joint, CD_R(1000.0));
	cd2RevoluteJoint_SetMotorSpeed(joint, CD_R(0.0));
	cd2RevoluteJoint_SetLimits(joint, -CD_R(0.2), CD_R(0.2));
	cd2RevoluteJoint_EnableLimit(joint, true);
	cd2World_EnableSleeping(world, false);
	for (int i = 0; i < 60; ++i)
	{
		cd2World_Step(world, DT, 4);
	}
	cd2Joint_WakeBodies(joint);
	/* The motor holds the arm (anchored 1 m above its centre) horizontal... it is straight below:
	 * no torque needed; the reaction is its weight. */
	TEST_CHECK_NEAR(cd2Joint_GetConstraintTorque(joint), 0.0, 0.05);
	TEST_CHECK_NEAR(cd2Joint_GetConstraintForce(joint).y, cd2Body_GetMass(arm) * CD_R(10.0), 0.05);
	cd2DestroyJoint(joint);

	cd2BodyId driven = MakeBall(world, cd2MakeVec(CD_R(20.0), CD_R(5.0)), CD_R(0.3), false);
	cd2MotorJointDef mj = cd2DefaultMotorJointDef();
	mj.bodyIdA = ground;
	mj.bodyIdB = driven;
	mj.linearOffset = cd2MakeVec(CD_R(20.0), CD_R(5.0));
	mj.maxForce = CD_R(500.0);
	mj.maxTorque = CD_R(50.0);
	cd2JointId motor = cd2CreateMotorJoint(world, &mj);
	cd2MotorJoint_SetLinearOffset(motor, cd2MakeVec(CD_R(21.0), CD_R(5.0)));
	cd2MotorJoint_SetAngularOffset(motor, CD_R(0.5));
	cd2BodyId pair = MakeBall(world, cd2MakeVec(CD_R(30.0), CD_R(5.0)), CD_R(0.3), false);
	cd2DistanceJointDef dj = cd2DefaultDistanceJointDef();
	dj.bodyIdA = ground;
	dj.bodyIdB = pair;
	dj.localAnchorA = cd2MakeVec(CD_R(30.0), CD_R(7.0));
	dj.length = CD_R(2.0);
	cd2JointId distance = cd2CreateDistanceJoint(world, &dj);
	cd2DistanceJoint_SetLength(distance, CD_R(1.0));
	for (int i = 0; i < 120; ++i)
	{
		cd2World_Step(world, DT, 4);
	}
	TEST_CHECK_NEAR(cd2Body_GetPosition(driven).x, 21.0, 0.02);
	TEST_CHECK_NEAR(cd2RotGetAngle(cd2Body_GetRotation(driven)), 0.5, 0.02);
	TEST_CHECK_NEAR(cd2DistanceJoint_GetCurrentLength(distance), 1.0, 0.01);
	/* As a rope of 0.5 to 3 m with a soft spring of rest length 1 m it hangs lower. */
	cd2Joint_EnableSpring(distance, true);
	cd2Joint_SetSpringHertz(distance, CD_R(1.0));
	cd2DistanceJoint_SetLengthRange(distance, CD_R(0.5), CD_R(3.0));
	cd2Joint_EnableLimit(distance, true);
	for (int i = 0; i < 240; ++i)
	{
		cd2World_Step(world, DT, 4);
	}
	cdReal hanging = cd2DistanceJoint_GetCurrentLength(distance);
	TEST_CHECKF(hanging > CD_R(1.1) && hanging <= CD_R(3.01), "length %g", (double)hanging);
	cd2DestroyWorld(world);
}

typedef struct PlaneList
{
	cd2PlaneResult planes[16];
	int count;
} PlaneList;

static bool CollectPlane(const cd2PlaneResult* plane, void* context)
{
	PlaneList* list = (PlaneList*)context;
	if (list->count < 16)
	{
		list->planes[list->count++] = *plane;
	}
	return true;
}

static cd2Capsule MoverAt(cd2Vec bottom)
{
	cd2Capsule c = {cd2Add(bottom, cd2MakeVec(CD_R(0.0), CD_R(0.3))),
					cd2Add(bottom, cd2MakeVec(CD_R(0.0), CD_R(1.0))), CD_R(0.3)};
	return c;
}

/* One frame of the character mover loop of world2.h. */
static void MoveCharacter(cd2WorldId world, cd2Vec* position, cd2Vec* velocity, cdReal dt)
{
	cd2QueryFilter filter = cd2DefaultQueryFilter();
	cd2Vec target = cd2MulAdd(*position, dt, *velocity);
	PlaneList list;
	list.count = 0;
	for (int i = 0; i < 4; ++i)
	{
		list.count = 0;
		cd2Capsule atTarget = MoverAt(target);
		cd2World_CollideMover(world, &atTarget, filter, CollectPlane, &list);
		target = cd2Add(target, cd2SolvePlanes(CD2_VEC_ZERO, list.planes, list.count));
	}
	cd2Capsule atPosition = MoverAt(*position);
	cdReal t = cd2World_CastMover(world, &atPosition, cd2Sub(target, *position), filter);
	*position = cd2Lerp(*position, target, t);
	*velocity = cd2ClipVector(*velocity, list.planes, list.count);
}

/* The mover walks along the ground into a wall and stops there; walks up a 20 degree slope. */
static void TestMover(void)
{
	cd2WorldDef wd = cd2DefaultWorldDef();
	cd2WorldId world = cd2CreateWorld(&wd);
	MakeStaticBox(world, cd2MakeVec(CD_R(0.0), CD_R(-1.0)), CD_R(50.0), CD_R(1.0));
	MakeStaticBox(world, cd2MakeVec(CD_R(5.0), CD_R(1.5)), CD_R(0.5), CD_R(1.5)); /* wall face at x = 4.5 */
	cdReal slope = (cdReal)tan(20.0 * 3.14159265358979 / 180.0);
	{
		cd2BodyDef bd = cd2DefaultBodyDef();
		cd2BodyId ramp = cd2CreateBody(world, &bd);
		cd2Vec points[3] = {
			{-CD_R(3.0), CD_R(0.0)}, {-CD_R(13.0), CD_R(0.0)}, {-CD_R(13.0), CD_R(10.0) * slope}};
		cd2Polygon triangle;
		TEST_CHECK(cd2MakePolygon(points, 3, &triangle) == CD_OK);
		cd2ShapeDef sd = cd2DefaultShapeDef();
		cd2CreatePolygonShape(ramp, &sd, &triangle);
	}
	cdReal dt = CD_R(1.0) / CD_R(60.0);
	cd2Vec position = cd2MakeVec(CD_R(0.0), CD_R(0.5)); /* starts in the air: falls to the ground */
	cd2Vec velocity = CD2_VEC_ZERO;
	for (int i = 0; i < 180; ++i)
	{
		velocity.x = CD_R(3.0);
		velocity.y -= CD_R(10.0) * dt;
		MoveCharacter(world, &position, &velocity, dt);
		TEST_CHECK(position.y > -CD_R(0.02));
	}
	TEST_CHECK_NEAR(position.x, 4.2, 0.03);
	TEST_CHECK_NEAR(position.y, 0.0, 0.03);
	TEST_CHECK(cdAbs(velocity.y) < CD_R(0.2)); /* standing, not accumulating a fall */
	/* Back to the left and up the slope. */
	position = cd2MakeVec(-CD_R(2.0), CD_R(0.0));
	velocity = CD2_VEC_ZERO;
	for (int i = 0; i < 120; ++i)
	{
		velocity.x = -CD_R(3.0);
		velocity.y -= CD_R(10.0) * dt;
		MoveCharacter(world, &position, &velocity, dt);
	}
	cdReal ground = (-CD_R(3.0) - position.x) * slope;
	TEST_CHECKF(position.x < -CD_R(6.0) && position.y > CD_R(1.0), "mover at %g %g", (double)position.x,
				(double)position.y);
	TEST_CHECK_NEAR(position.y, ground, 0.05);
	cd2DestroyWorld(world);
}

typedef struct DrawCount
{
	int polygons, circles, capsules, segments, points;
} DrawCount;

static void CountPolygon(const cd2Vec* vertices, int count, cdReal radius, uint32_t color, void* context)
{
	(void)vertices;
	(void)radius;
	(void)color;
	TEST_CHECK(count == 4);
	((DrawCount*)context)->polygons += 1;
}

static void CountCircle(cd2Transform transform, cdReal radius, uint32_t color, void* context)
{
	(void)transform;
	(void)color;
	TEST_CHECK_NEAR(radius, 0.5, 0.0);
	((DrawCount*)context)->circles += 1;
}

static void CountSegment(cd2Vec p1, cd2Vec p2, uint32_t color, void* context)
{
	(void)p1;
	(void)p2;
	(void)color;
	((DrawCount*)context)->segments += 1;
}

static void CountPoint(cd2Vec p, cdReal size, uint32_t color, void* context)
{
	(void)p;
	(void)size;
	(void)color;
	((DrawCount*)context)->points += 1;
}

static void TestDebugDraw(void)
{
	cd2WorldDef wd = cd2DefaultWorldDef();
	cd2WorldId world = cd2CreateWorld(&wd);
	MakeStaticBox(world, cd2MakeVec(CD_R(0.0), CD_R(-1.0)), CD_R(50.0), CD_R(1.0));
	cd2BodyId ball = MakeBall(world, cd2MakeVec(CD_R(0.0), CD_R(0.5)), CD_R(0.5), false);
	cd2BodyDef bd = cd2DefaultBodyDef();
	cd2BodyId anchor = cd2CreateBody(world, &bd);
	cd2DistanceJointDef dj = cd2DefaultDistanceJointDef();
	dj.bodyIdA = anchor;
	dj.bodyIdB = ball;
	dj.length = CD_R(3.0);
	cd2CreateDistanceJoint(world, &dj);
	cd2World_Step(world, DT, 4);
	DrawCount count;
	memset(&count, 0, sizeof(count));
	cd2DebugDraw draw = cd2DefaultDebugDraw();
	draw.drawPolygon = CountPolygon;
	draw.drawCircle = CountCircle;
	draw.drawSegment = CountSegment;
	draw.drawPoint = CountPoint;
	draw.drawContacts = true;
	draw.drawAabbs = true;
	draw.context = &count;
	cd2World_Draw(world, &draw);
	TEST_CHECK(count.polygons == 1);
	TEST_CHECK(count.circles == 1);
	TEST_CHECK(count.points == 1);				 /* the ball's contact with the ground */
	TEST_CHECK(count.segments == 2 * 4 + 3 + 1); /* two boxes, the joint, the contact normal */
	cd2DestroyWorld(world);
}

int main(void)
{
	TEST_RUN(TestPendulumEnergy);
	TEST_RUN(TestRevoluteChainEnergy);
	TEST_RUN(TestJointReaction);
	TEST_RUN(TestJointEvents);
	TEST_RUN(TestJointConstraintTuning);
	TEST_RUN(TestJointKinds);
	TEST_RUN(TestJointSetters);
	TEST_RUN(TestFilterJointAndFilters);
	TEST_RUN(TestSensorEvents);
	TEST_RUN(TestSensorEventsAfterRestore);
	TEST_RUN(TestContactAndHitEvents);
	TEST_RUN(TestPreSolveAndCustomFilter);
	TEST_RUN(TestLockedWorld);
	TEST_RUN(TestQueries);
	TEST_RUN(TestChain);
	TEST_RUN(TestContinuous);
	TEST_RUN(TestContinuousStaticCount);
	TEST_RUN(TestContinuousOneSidedChain);
	TEST_RUN(TestFinalizeAcrossWorkers);
	TEST_RUN(TestJointColorsAcrossWorkers);
	TEST_RUN(TestCreatedAsleep);
	TEST_RUN(TestSetAwakeFalseSleepsGroup);
	TEST_RUN(TestBodyControls);
	TEST_RUN(TestDebugDraw);
	TEST_RUN(TestMover);
	TEST_RUN(TestAccessors);
	return TEST_SUMMARY();
}
