/* collide: the revolute joint: a shared point, with an optional rotational spring, motor and
 * angle limits. */
#include "joint_solver2.h"

void cd2PrepareRevoluteJoint(cd2JointSolverArgs* args)
{
	cd2JointData* d = &args->joint->data;
	cdReal k = args->a->invInertia + args->b->invInertia;
	d->axialMass = k > CD_R(0.0) ? CD_R(1.0) / k : CD_R(0.0);
	d->springSoftness = cd2MakeSoft(d->hertz, d->dampingRatio, args->context->h);
}

void cd2WarmStartRevoluteJoint(cd2JointSolverArgs* args)
{
	cd2JointData* d = &args->joint->data;
	cd2Vec rA = cd2RotateVector(args->a->deltaRotation, d->anchorA);
	cd2Vec rB = cd2RotateVector(args->b->deltaRotation, d->anchorB);
	cdReal axial = d->springImpulse + d->motorImpulse + d->lowerImpulse - d->upperImpulse;
	cd2ApplyJointImpulse(args->a, args->b, rA, rB, d->linearImpulse, axial);
}

void cd2SolveRevoluteJoint(cd2JointSolverArgs* args, bool useBias)
{
	cd2JointData* d = &args->joint->data;
	cd2SolverBody* a = args->a;
	cd2SolverBody* b = args->b;
	const cd2StepContext* context = args->context;
	cdReal h = context->h;
	cdReal iA = a->invInertia, iB = b->invInertia;
	bool fixedRotation = iA + iB == CD_R(0.0);
	/* Only the spring and the limits need the angle. */
	cdReal jointAngle = (d->enableSpring || d->enableLimit) && !fixedRotation
							? d->deltaAngle + cd2RelativeAngle(a->deltaRotation, b->deltaRotation)
							: CD_R(0.0);

	if (d->enableSpring && !fixedRotation)
	{
		cdReal C = jointAngle;
		cdReal bias = d->springSoftness.biasRate * C;
		cdReal massScale = d->springSoftness.massScale, impulseScale = d->springSoftness.impulseScale;
		cdReal Cdot = b->angularVelocity - a->angularVelocity;
		cdReal impulse = -massScale * d->axialMass * (Cdot + bias) - impulseScale * d->springImpulse;
		d->springImpulse += impulse;
		a->angularVelocity -= iA * impulse;
		b->angularVelocity += iB * impulse;
	}
	if (d->enableMotor && !fixedRotation)
	{
		cdReal Cdot = b->angularVelocity - a->angularVelocity - d->motorSpeed;
		cdReal impulse = -d->axialMass * Cdot;
		cdReal maxImpulse = d->maxMotorForce * h;
		cdReal newImpulse = cdClamp(d->motorImpulse + impulse, -maxImpulse, maxImpulse);
		impulse = newImpulse - d->motorImpulse;
		d->motorImpulse = newImpulse;
		a->angularVelocity -= iA * impulse;
		b->angularVelocity += iB * impulse;
	}
	if (d->enableLimit && !fixedRotation)
	{
		/* lower */
		cdReal impulse = cd2SolveLimitSide(d, context, useBias, d->axialMass, jointAngle - d->lower,
										   b->angularVelocity - a->angularVelocity, &d->lowerImpulse);
		a->angularVelocity -= iA * impulse;
		b->angularVelocity += iB * impulse;
		/* upper: the same with the sign flipped */
		impulse = cd2SolveLimitSide(d, context, useBias, d->axialMass, d->upper - jointAngle,
									a->angularVelocity - b->angularVelocity, &d->upperImpulse);
		a->angularVelocity += iA * impulse;
		b->angularVelocity -= iB * impulse;
	}
	/* The point. */
	{
		cd2Vec rA = cd2RotateVector(a->deltaRotation, d->anchorA);
		cd2Vec rB = cd2RotateVector(b->deltaRotation, d->anchorB);
		cd2Vec Cdot = cd2AnchorVelocity(a, b, rA, rB);
		cd2Vec bias = CD2_VEC_ZERO;
		cdReal massScale = CD_R(1.0), impulseScale = CD_R(0.0);
		if (useBias)
		{
			cd2Vec separation = cd2AnchorSeparation(a, b, rA, rB, d->deltaCenter);
			bias = cd2Scale(d->jointSoftness.biasRate, separation);
			massScale = d->jointSoftness.massScale;
			impulseScale = d->jointSoftness.impulseScale;
		}
		cd2Vec x = cd2SolveMass22(cd2PointMass(a, b, rA, rB), cd2Add(Cdot, bias));
		cd2Vec impulse = cd2Sub(cd2Scale(-massScale, x), cd2Scale(impulseScale, d->linearImpulse));
		d->linearImpulse = cd2Add(d->linearImpulse, impulse);
		cd2ApplyJointImpulse(a, b, rA, rB, impulse, CD_R(0.0));
	}
}
