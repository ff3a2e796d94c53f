/* collide: the revolute joint: a shared point, with an optional rotational spring, motor and
 * angle limits. */
#include "joint_solver2.h"

void cd2PrepareRevoluteJoint(cd2JointSolverArgs* args)
{
	cd2JointData* d = args->data;
	cdReal k = args->a->invInertia + args->b->invInertia;
	d->axialMass = k > CD_R(0.0) ? CD_R(1.0) / k : CD_R(0.0);
	d->springSoftness = cd2MakeSoft(d->hertz, d->dampingRatio, args->context->h);
}

/* The bodies' velocities are read once into locals and written back once at the end. */
void cd2SolveRevoluteJoint(cd2JointSolverArgs* args, bool useBias)
{
	cd2JointData* d = args->data;
	cd2SolverBody* a = args->a;
	cd2SolverBody* b = args->b;
	const cd2StepContext* context = args->context;
	cdReal mA = a->invMass, mB = b->invMass, iA = a->invInertia, iB = b->invInertia;
	cd2Vec vA = a->linearVelocity, vB = b->linearVelocity;
	cdReal wA = a->angularVelocity, wB = b->angularVelocity;
	bool fixedRotation = iA + iB == CD_R(0.0);

	if ((d->enableSpring || d->enableMotor || d->enableLimit) && !fixedRotation)
	{
		/* Only the spring and the limits need the angle. */
		cdReal jointAngle = d->enableSpring || d->enableLimit
								? d->deltaAngle + cd2RelativeAngle(a->deltaRotation, b->deltaRotation)
								: CD_R(0.0);
		if (d->enableSpring)
		{
			cdReal C = jointAngle;
			cdReal bias = d->springSoftness.biasRate * C;
			cdReal massScale = d->springSoftness.massScale, impulseScale = d->springSoftness.impulseScale;
			cdReal Cdot = wB - wA;
			cdReal impulse = -massScale * d->axialMass * (Cdot + bias) - impulseScale * d->springImpulse;
			d->springImpulse += impulse;
			wA -= iA * impulse;
			wB += iB * impulse;
		}
		if (d->enableMotor)
		{
			cdReal Cdot = wB - wA - d->motorSpeed;
			cdReal impulse = -d->axialMass * Cdot;
			cdReal maxImpulse = d->maxMotorForce * context->h;
			cdReal newImpulse = cdClamp(d->motorImpulse + impulse, -maxImpulse, maxImpulse);
			impulse = newImpulse - d->motorImpulse;
			d->motorImpulse = newImpulse;
			wA -= iA * impulse;
			wB += iB * impulse;
		}
		if (d->enableLimit)
		{
			/* lower */
			cdReal impulse = cd2SolveLimitSide(d, context, useBias, d->axialMass, jointAngle - d->lower,
											   wB - wA, &d->lowerImpulse);
			wA -= iA * impulse;
			wB += iB * impulse;
			/* upper: the same with the sign flipped */
			impulse = cd2SolveLimitSide(d, context, useBias, d->axialMass, d->upper - jointAngle, wA - wB,
										&d->upperImpulse);
			wA += iA * impulse;
			wB -= iB * impulse;
		}
	}
	/* The point. */
	{
		cd2Vec rA = cd2RotateVector(a->deltaRotation, d->anchorA);
		cd2Vec rB = cd2RotateVector(b->deltaRotation, d->anchorB);
		cd2Vec Cdot = cd2Sub(cd2Add(vB, cd2CrossSV(wB, rB)), cd2Add(vA, cd2CrossSV(wA, rA)));
		cd2Vec bias = CD2_VEC_ZERO;
		cdReal massScale = CD_R(1.0), impulseScale = CD_R(0.0);
		if (useBias)
		{
			cd2Vec separation = cd2AnchorSeparation(a, b, rA, rB, d->deltaCenter);
			bias = cd2Scale(d->jointSoftness.biasRate, separation);
			massScale = d->jointSoftness.massScale;
			impulseScale = d->jointSoftness.impulseScale;
		}
		cd2Vec x = cd2SolveMass22(cd2PointMassOf(mA + mB, iA, iB, rA, rB), cd2Add(Cdot, bias));
		cd2Vec impulse = cd2Sub(cd2Scale(-massScale, x), cd2Scale(impulseScale, d->linearImpulse));
		d->linearImpulse = cd2Add(d->linearImpulse, impulse);
		vA = cd2MulSub(vA, mA, impulse);
		wA -= iA * cd2Cross(rA, impulse);
		vB = cd2MulAdd(vB, mB, impulse);
		wB += iB * cd2Cross(rB, impulse);
	}
	a->linearVelocity = vA;
	a->angularVelocity = wA;
	b->linearVelocity = vB;
	b->angularVelocity = wB;
}
