/* collide: the 2D step's solve: the dense arrays of awake bodies and touching contacts, the
 * sub-stepped soft step (integrate velocities, warm start, solve with bias, integrate positions,
 * relax without bias; restitution last), then finalize (transforms, bounds, continuous collision,
 * hit and move events, sleep). Integration, the wide solve (colour by colour) and the first part of
 * finalize run as tasks over index ranges on the world's workers (cd2RunTask); each item writes
 * only its own body or block, so the same input gives the same bits for any worker count. The
 * contacts are prepared in index order, then sorted by graph colour; the coloured ones are solved
 * four at a time (contact_solver_wide2.c), the overflow colour and the joints one by one. */
#include "world2_internal.h"

#include "../base/graph_color.h"
#include "../base/thread_pool.h"

cd2Softness cd2MakeSoft(cdReal hertz, cdReal zeta, cdReal h)
{
	cd2Softness soft = {CD_R(0.0), CD_R(1.0), CD_R(0.0)};
	if (hertz == CD_R(0.0))
	{
		return soft;
	}
	cdReal omega = CD_R(2.0) * CD_PI * hertz;
	cdReal a1 = CD_R(2.0) * zeta + h * omega;
	cdReal a2 = h * omega * a1;
	cdReal a3 = CD_R(1.0) / (CD_R(1.0) + a2);
	soft.biasRate = omega / a1;
	soft.massScale = a2 * a3;
	soft.impulseScale = a3;
	return soft;
}

cd2Rot cd2IntegrateRotation(cd2Rot q, cdReal deltaAngle)
{
	cd2Rot q2 = {q.c - deltaAngle * q.s, q.s + deltaAngle * q.c};
	cdReal mag = cdSqrt(q2.s * q2.s + q2.c * q2.c);
	cdReal invMag = mag > CD_R(0.0) ? CD_R(1.0) / mag : CD_R(0.0);
	cd2Rot out = {q2.c * invMag, q2.s * invMag};
	return out;
}

/* A stage of the step run as a task over an index range (bodies or wide blocks). Every item
 * writes only its own body or block, so the split between workers cannot change the results. */
typedef struct cd2StageContext
{
	cd2World* world;
	cd2StepContext* step;
	int blockStart; /* the colour's first wide block */
	bool useBias;
} cd2StageContext;

static void cd2IntegrateVelocities(int start, int end, uint32_t workerIndex, void* taskContext)
{
	(void)workerIndex;
	cd2StepContext* context = ((cd2StageContext*)taskContext)->step;
	cdReal maxLinear = context->maxLinearVelocity;
	cdReal maxAngular = CD2_MAX_ROTATION * context->inv_h;
	for (int i = start; i < end; ++i)
	{
		const cd2SolverBodyParams* p = context->params + i;
		cd2SolverBody* s = context->bodies + i;
		if (!p->dynamic)
		{
			continue;
		}
		cd2Vec v = s->linearVelocity;
		cdReal w = s->angularVelocity;
		/* Damping as an implicit factor: stable for any damping and step. */
		v = cd2MulAdd(p->deltaV, p->linearDamping, v);
		w = p->deltaW + w / p->angularDamping;
		if (cd2Dot(v, v) > maxLinear * maxLinear)
		{
			v = cd2Scale(maxLinear / cd2Length(v), v);
		}
		if (w * w > maxAngular * maxAngular)
		{
			w = w > CD_R(0.0) ? maxAngular : -maxAngular;
		}
		s->linearVelocity = v;
		s->angularVelocity = w;
	}
}

static void cd2IntegratePositions(int start, int end, uint32_t workerIndex, void* taskContext)
{
	(void)workerIndex;
	cd2StepContext* context = ((cd2StageContext*)taskContext)->step;
	cdReal h = context->h;
	cdReal maxLinear = context->maxLinearVelocity;
	cdReal maxAngular = CD2_MAX_ROTATION * context->inv_h;
	for (int i = start; i < end; ++i)
	{
		cd2SolverBody* s = context->bodies + i;
		/* The speed caps hold after the constraints too: conflicting joints (a loop of rigid joints
		 * that cannot all hold) must not run away. */
		if (cd2Dot(s->linearVelocity, s->linearVelocity) > maxLinear * maxLinear)
		{
			s->linearVelocity = cd2Scale(maxLinear / cd2Length(s->linearVelocity), s->linearVelocity);
		}
		if (s->angularVelocity * s->angularVelocity > maxAngular * maxAngular)
		{
			s->angularVelocity = s->angularVelocity > CD_R(0.0) ? maxAngular : -maxAngular;
		}
		s->deltaRotation = cd2IntegrateRotation(s->deltaRotation, h * s->angularVelocity);
		s->deltaPosition = cd2MulAdd(s->deltaPosition, h, s->linearVelocity);
	}
}

static void cd2FinalizeBodies(int start, int end, uint32_t workerIndex, void* taskContext)
{
	(void)workerIndex;
	cd2World* world = ((cd2StageContext*)taskContext)->world;
	const cd2StepContext* context = ((cd2StageContext*)taskContext)->step;
	bool sleepAllowed = world->enableSleep;
	cdReal timeStep = context->dt;
	for (int k = start; k < end; ++k)
	{
		cd2Body* body = world->bodies.data + context->bodyIndices[k];
		const cd2SolverBody* s = context->bodies + k;
		body->linearVelocity = s->linearVelocity;
		body->angularVelocity = s->angularVelocity;
		/* The relax pass and restitution come after the last position update: cap once more. */
		if (cd2Dot(body->linearVelocity, body->linearVelocity) >
			context->maxLinearVelocity * context->maxLinearVelocity)
		{
			body->linearVelocity =
				cd2Scale(context->maxLinearVelocity / cd2Length(body->linearVelocity), body->linearVelocity);
		}
		body->center = cd2Add(body->center, s->deltaPosition);
		body->transform.q = cd2NormalizeRot(cd2MulRot(s->deltaRotation, body->transform.q));
		body->transform.p = cd2Sub(body->center, cd2RotateVector(body->transform.q, body->localCenter));
		body->force = CD2_VEC_ZERO;
		body->torque = CD_R(0.0);
		cdReal speed = cd2Length(body->linearVelocity);
		cdReal sleepVelocity = cdMax(body->maxExtent * cdAbs(body->angularVelocity), speed);
		if (!sleepAllowed || !body->enableSleep || sleepVelocity > body->sleepThreshold)
		{
			body->sleepTime = CD_R(0.0);
		}
		else
		{
			body->sleepTime += timeStep;
		}
		if (world->enableContinuous && body->type == CD_DYNAMIC_BODY)
		{
			/* Fast: it may have moved through something thinner than half its inner extent. */
			cdReal travel = speed * timeStep + cdAbs(body->angularVelocity) * timeStep * body->maxExtent;
			body->isFast = body->isBullet || CD_R(0.5) * body->minExtent < travel;
		}
	}
}

static void cd2WarmStartWideTask(int start, int end, uint32_t workerIndex, void* taskContext)
{
	(void)workerIndex;
	const cd2StageContext* stage = (const cd2StageContext*)taskContext;
	cd2WarmStartContactsWide(stage->step, stage->blockStart + start, stage->blockStart + end);
}

static void cd2SolveWideTask(int start, int end, uint32_t workerIndex, void* taskContext)
{
	(void)workerIndex;
	const cd2StageContext* stage = (const cd2StageContext*)taskContext;
	cd2SolveContactsWide(stage->step, stage->blockStart + start, stage->blockStart + end, stage->useBias);
}

/* The wide blocks colour by colour: the blocks of one colour share no movable body, so they may run
 * in any order and on any worker; each colour starts when the one before has finished. */
static void cd2RunWide(cd2World* world, cd2StageContext* stage, cdTaskCallback* task, bool useBias)
{
	const cd2StepContext* context = stage->step;
	stage->useBias = useBias;
	for (int c = 0; c < context->colorCount; ++c)
	{
		stage->blockStart = context->colorBlockStart[c];
		cd2RunTask(world, task, context->colorBlockStart[c + 1] - stage->blockStart, 4, stage);
	}
}

/* Hit events: touching contacts whose approach speed exceeded the threshold and that pushed. */
static void cd2ReportHits(cd2World* world, cd2StepContext* context)
{
	/* In contact index order: the contacts are read front to back. */
	for (int i = 0; i < context->constraintCount; ++i)
	{
		const cd2Contact* contact = world->contacts.data + context->indexOrder[i].contact;
		if ((contact->flags & CD2_CONTACT_HIT_EVENTS) == 0)
		{
			continue;
		}
		cd2ContactHitEvent event;
		memset(&event, 0, sizeof(event));
		event.approachSpeed = world->hitEventThreshold;
		bool hit = false;
		for (int k = 0; k < contact->pointCount; ++k)
		{
			cdReal approach = -contact->points[k].relativeVelocity;
			if (approach > event.approachSpeed && contact->points[k].maxNormalImpulse > CD_R(0.0))
			{
				event.approachSpeed = approach;
				event.point = contact->points[k].point;
				hit = true;
			}
		}
		if (hit)
		{
			event.normal = contact->normal;
			event.shapeIdA = cd2MakeShapeId(world, contact->shapeA);
			event.shapeIdB = cd2MakeShapeId(world, contact->shapeB);
			if (!cdArrayPush(world->hitEvents, event))
			{
				world->outOfMemory = true;
			}
		}
	}
}

void cd2RunTask(cd2World* world, cdTaskCallback* task, int itemCount, int minRange, void* taskContext)
{
	if (itemCount <= 0)
	{
		return;
	}
	if (world->workerCount <= 1 || world->enqueueTask == NULL || itemCount <= minRange)
	{
		task(0, itemCount, 0, taskContext);
		return;
	}
	/* NULL: the task system ran the task already (on this thread). */
	void* userTask = world->enqueueTask(task, itemCount, minRange, taskContext, world->userTaskContext);
	if (userTask != NULL)
	{
		world->finishTask(userTask, world->userTaskContext);
	}
}

void cd2Solve(cd2World* world, cdReal timeStep, int subStepCount)
{
	cd2StepContext context;
	memset(&context, 0, sizeof(context));
	context.dt = timeStep;
	context.inv_dt = CD_R(1.0) / timeStep;
	context.subStepCount = subStepCount;
	context.h = timeStep / (cdReal)subStepCount;
	context.inv_h = (cdReal)subStepCount * context.inv_dt;
	/* Stiffer than an eighth of the sub-step rate would ring. */
	cdReal contactHertz = cdMin(world->contactHertz, CD_R(0.125) * context.inv_h);
	context.contactSoftness = cd2MakeSoft(contactHertz, world->contactDampingRatio, context.h);
	context.staticSoftness = cd2MakeSoft(CD_R(2.0) * contactHertz, world->contactDampingRatio, context.h);
	/* Joints: the world's joint stiffness, capped at a quarter of the sub-step rate. */
	cdReal jointHertz = cdMin(world->jointHertz, CD_R(0.25) * context.inv_h);
	context.jointSoftness = cd2MakeSoft(jointHertz, world->jointDampingRatio, context.h);
	context.restitutionThreshold = world->restitutionThreshold;
	context.maxLinearVelocity = world->maximumLinearSpeed * cdGetLengthUnitsPerMeter();
	context.contactPushMaxVelocity = world->contactPushMaxVelocity * cdGetLengthUnitsPerMeter();
	context.enableWarmStarting = true;

	/* The awake bodies, dense. */
	int bodyCapacity = world->bodies.count;
	/* One more: the zero body the wide contact solver points immovable bodies at. */
	context.bodies = (cd2SolverBody*)cdArena_AllocUncleared(&world->arena, (size_t)(bodyCapacity + 1) *
																			   sizeof(cd2SolverBody));
	context.bodyIndices = (int*)cdArena_AllocUncleared(&world->arena, (size_t)bodyCapacity * sizeof(int));
	context.params = (cd2SolverBodyParams*)cdArena_AllocUncleared(
		&world->arena, (size_t)bodyCapacity * sizeof(cd2SolverBodyParams));
	if (bodyCapacity > 0 && (context.bodies == NULL || context.bodyIndices == NULL || context.params == NULL))
	{
		world->outOfMemory = true;
		return;
	}
	for (int i = 0; i < world->bodies.count; ++i)
	{
		cd2Body* body = world->bodies.data + i;
		body->solverIndex = CD2_NULL_INDEX;
		if (!body->inUse || !body->enabled || !body->awake || body->type == CD_STATIC_BODY)
		{
			continue;
		}
		int k = context.bodyCount++;
		body->solverIndex = k;
		body->center0 = body->center;
		body->rotation0 = body->transform.q;
		body->isFast = false;
		context.bodyIndices[k] = i;
		cd2SolverBody* s = context.bodies + k;
		s->linearVelocity = body->linearVelocity;
		s->angularVelocity = body->angularVelocity;
		s->deltaPosition = CD2_VEC_ZERO;
		s->deltaRotation = CD2_ROT_IDENTITY;
		s->invMass = body->invMass;
		s->invInertia = body->invInertia;
		cd2SolverBodyParams* p = context.params + k;
		cdReal h = context.h;
		p->dynamic = body->type == CD_DYNAMIC_BODY;
		p->deltaV = cd2Scale(h * body->invMass,
							 cd2MulAdd(body->force, body->mass * body->gravityScale, world->gravity));
		p->deltaW = h * body->invInertia * body->torque;
		p->linearDamping = CD_R(1.0) / (CD_R(1.0) + h * body->linearDamping);
		p->angularDamping = CD_R(1.0) + h * body->angularDamping;
	}

	{
		cd2SolverBody* zero = context.bodies + context.bodyCount;
		memset(zero, 0, sizeof(*zero));
		zero->deltaRotation = CD2_ROT_IDENTITY;
	}

	/* Per world body: its solver index, and the same for dynamic bodies only (the colouring's;
	 * kinematic bodies are immovable for the solver and take no colour). Small arrays, so that
	 * the contact loops below do not visit the bodies. */
	int* solverOf = (int*)cdArena_AllocUncleared(&world->arena, (size_t)bodyCapacity * sizeof(int));
	int* colorBodyOf = (int*)cdArena_AllocUncleared(&world->arena, (size_t)bodyCapacity * sizeof(int));
	context.accelerations =
		(cd2Vec*)cdArena_AllocUncleared(&world->arena, (size_t)(bodyCapacity + 1) * sizeof(cd2Vec));
	if (bodyCapacity > 0 && (solverOf == NULL || colorBodyOf == NULL || context.accelerations == NULL))
	{
		world->outOfMemory = true;
		return;
	}
	for (int i = 0; i < world->bodies.count; ++i)
	{
		const cd2Body* body = world->bodies.data + i;
		solverOf[i] = body->solverIndex;
		colorBodyOf[i] = body->type == CD_DYNAMIC_BODY ? body->solverIndex : CD2_NULL_INDEX;
		if (body->solverIndex >= 0)
		{
			context.accelerations[body->solverIndex] =
				body->invMass > CD_R(0.0)
					? cd2MulAdd(cd2Scale(body->invMass, body->force), body->gravityScale, world->gravity)
					: CD2_VEC_ZERO;
		}
	}

	/* Touching contacts with an awake body, prepared in index order. */
	int hitCandidates = 0;
	int contactCapacity = world->contacts.count;
	context.constraints = (cd2ContactConstraint*)cdArena_AllocUncleared(
		&world->arena, (size_t)contactCapacity * sizeof(cd2ContactConstraint));
	for (int i = 0; i < world->contacts.count && context.constraints != NULL; ++i)
	{
		const cd2Contact* contact = world->contacts.data + i;
		if (!contact->inUse || contact->pointCount == 0 ||
			(contact->flags & (CD2_CONTACT_SENSOR | CD2_CONTACT_DISABLED)) != 0 ||
			(contact->flags & CD2_CONTACT_TOUCHING) == 0)
		{
			continue;
		}
		int indexA = solverOf[contact->bodyA], indexB = solverOf[contact->bodyB];
		if (indexA < 0 && indexB < 0)
		{
			continue;
		}
		hitCandidates += (contact->flags & CD2_CONTACT_HIT_EVENTS) != 0 ? 1 : 0;
		cd2ContactConstraint* c = context.constraints + context.constraintCount++;
		c->contact = i;
		c->indexA = indexA;
		c->indexB = indexB;
	}
	cd2PrepareContacts(world, &context);
	context.indexOrder = context.constraints;
	/* Colour order (see graph_color.h). */
	if (context.constraintCount > 1)
	{
		int n = context.constraintCount;
		int* bodyA = (int*)cdArena_AllocUncleared(&world->arena, (size_t)n * sizeof(int));
		int* bodyB = (int*)cdArena_AllocUncleared(&world->arena, (size_t)n * sizeof(int));
		int* colors = (int*)cdArena_AllocUncleared(&world->arena, (size_t)n * sizeof(int));
		int* order = (int*)cdArena_AllocUncleared(&world->arena, (size_t)n * sizeof(int));
		cd2ContactConstraint* sorted = (cd2ContactConstraint*)cdArena_AllocUncleared(
			&world->arena, (size_t)n * sizeof(cd2ContactConstraint));
		if (bodyA != NULL && bodyB != NULL && colors != NULL && order != NULL && sorted != NULL)
		{
			for (int i = 0; i < n; ++i)
			{
				const cd2Contact* contact = world->contacts.data + context.constraints[i].contact;
				bodyA[i] = colorBodyOf[contact->bodyA];
				bodyB[i] = colorBodyOf[contact->bodyB];
			}
			if (cdColorConstraints(bodyA, bodyB, n, context.bodyCount, colors, order, &world->arena))
			{
				for (int i = 0; i < n; ++i)
				{
					sorted[i] = context.constraints[order[i]];
					bodyA[i] = colors[order[i]];
				}
				context.constraints = sorted;
				context.colorOfConstraint = bodyA;
			}
		}
	}
	context.joints = (int*)cdArena_Alloc(&world->arena, (size_t)world->joints.count * sizeof(int));
	for (int i = 0; i < world->joints.count && context.joints != NULL; ++i)
	{
		const cd2Joint* joint = world->joints.data + i;
		if (!joint->inUse || joint->type == CD2_FILTER_JOINT)
		{
			continue;
		}
		const cd2Body* a = world->bodies.data + joint->bodyA;
		const cd2Body* b = world->bodies.data + joint->bodyB;
		if (!a->enabled || !b->enabled || (a->solverIndex < 0 && b->solverIndex < 0))
		{
			continue;
		}
		context.joints[context.jointCount++] = i;
	}

	if (!cd2PrepareContactsWide(world, &context))
	{
		/* Out of scratch memory: every constraint one by one. */
		context.wideCount = 0;
		context.overflowStart = 0;
	}
	cd2PrepareJoints(world, &context);
	cd2StageContext stage = {world, &context, 0, false};
	for (int step = 0; step < subStepCount; ++step)
	{
		cd2RunTask(world, cd2IntegrateVelocities, context.bodyCount, 64, &stage);
		cd2WarmStartJoints(world, &context);
		cd2RunWide(world, &stage, cd2WarmStartWideTask, false);
		cd2WarmStartContacts(&context);
		cd2SolveJoints(world, &context, true);
		cd2RunWide(world, &stage, cd2SolveWideTask, true);
		cd2SolveContacts(&context, true);
		cd2RunTask(world, cd2IntegratePositions, context.bodyCount, 64, &stage);
		cd2SolveJoints(world, &context, false);
		cd2RunWide(world, &stage, cd2SolveWideTask, false);
		cd2SolveContacts(&context, false);
	}
	cd2StoreContactsWide(&context);
	cd2ApplyRestitution(&context);
	cd2StoreImpulses(world, &context);
	cd2StoreJointReactions(world, &context);

	/* Finalize: velocities and transforms back into the bodies. */
	bool sleepAllowed = world->enableSleep;
	cd2RunTask(world, cd2FinalizeBodies, context.bodyCount, 64, &stage);
	/* A moving kinematic body keeps what touches it awake. */
	for (int k = 0; k < context.bodyCount; ++k)
	{
		cd2Body* body = world->bodies.data + context.bodyIndices[k];
		if (body->type != CD_KINEMATIC_BODY || body->sleepTime > CD_R(0.0))
		{
			continue;
		}
		for (int key = body->headContactKey; key != CD2_NULL_INDEX;)
		{
			const cd2Contact* contact = world->contacts.data + cd2EdgeContact(key);
			int other = cd2EdgeSide(key) == 0 ? contact->bodyB : contact->bodyA;
			if ((contact->flags & CD2_CONTACT_TOUCHING) != 0 && (contact->flags & CD2_CONTACT_SENSOR) == 0)
			{
				world->bodies.data[other].sleepTime = CD_R(0.0);
			}
			key = contact->nextKey[cd2EdgeSide(key)];
		}
	}
	/* Continuous collision: non-bullets first (against static), then bullets (against static and
	 * the others' final positions). */
	for (int pass = 0; pass < 2; ++pass)
	{
		for (int k = 0; k < context.bodyCount; ++k)
		{
			int index = context.bodyIndices[k];
			cd2Body* body = world->bodies.data + index;
			if (body->isFast && body->isBullet == (pass == 1))
			{
				cd2SolveContinuous(world, index);
			}
		}
	}
	for (int k = 0; k < context.bodyCount; ++k)
	{
		cd2Body* body = world->bodies.data + context.bodyIndices[k];
		for (int s = body->headShape; s != CD2_NULL_INDEX; s = world->shapes.data[s].nextShape)
		{
			cd2UpdateShapeBounds(world, s, false);
		}
	}
	if (hitCandidates > 0)
	{
		cd2ReportHits(world, &context);
	}
	if (sleepAllowed)
	{
		cd2UpdateSleep(world);
	}
	for (int k = 0; k < context.bodyCount; ++k)
	{
		int index = context.bodyIndices[k];
		cd2Body* body = world->bodies.data + index;
		cd2BodyMoveEvent event;
		event.transform = body->transform;
		event.bodyId = cd2MakeBodyId(world, index);
		event.userData = body->userData;
		event.fellAsleep = !body->awake;
		if (!cdArrayPush(world->moveEvents, event))
		{
			world->outOfMemory = true;
		}
	}
}
