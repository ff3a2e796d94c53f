/* collide: the distance joint: keeps two anchor points at a rest length, rigidly or as a spring,
 * optionally within [minLength, maxLength] and with a motor along the axis. */
#include "joint_solver2.h"

static cdReal cd2AxialMass(const cd2SolverBody* a, const cd2SolverBody* b, cd2Vec rA, cd2Vec rB, cd2Vec axis)
{
	cdReal crA = cd2Cross(rA, axis), crB = cd2Cross(rB, axis);
	cdReal k = a->invMass + b->invMass + a->invInertia * crA * crA + b->invInertia * crB * crB;
	return k > CD_R(0.0) ? CD_R(1.0) / k : CD_R(0.0);
}

void cd2PrepareDistanceJoint(cd2JointSolverArgs* args)
{
	cd2JointData* d = args->data;
	cd2Vec delta = cd2Add(d->deltaCenter, cd2Sub(d->anchorB, d->anchorA));
	d->axisA = cd2Normalize(delta);
	d->axialMass = cd2AxialMass(args->a, args->b, d->anchorA, d->anchorB, d->axisA);
	d->springSoftness = cd2MakeSoft(d->hertz, d->dampingRatio, args->context->h);
}

cd2JointImpulse cd2WarmStartDistanceJoint(const cd2JointSolverArgs* args)
{
	const cd2JointData* d = args->data;
	cd2Vec rA = cd2RotateVector(args->a->deltaRotation, d->anchorA);
	cd2Vec rB = cd2RotateVector(args->b->deltaRotation, d->anchorB);
	cd2Vec axis = cd2Normalize(cd2AnchorSeparation(args->a, args->b, rA, rB, d->deltaCenter));
	cdReal axial = d->impulse + d->lowerImpulse - d->upperImpulse + d->motorImpulse;
	return cd2MakeJointImpulse(rA, rB, cd2Scale(axial, axis), CD_R(0.0));
}

/* One-sided soft row along axis: keeps C >= 0 (C = length - min, or max - length with sign -1). */
static void cd2SolveDistanceLimit(cd2JointSolverArgs* args, cd2Vec rA, cd2Vec rB, cd2Vec axis, cdReal C,
								  cdReal sign, cdReal* accumulated, bool useBias)
{
	cd2JointData* d = args->data;
	cdReal bias = CD_R(0.0), massScale = CD_R(1.0), impulseScale = CD_R(0.0);
	if (C > CD_R(0.0))
	{
		bias = C * args->context->inv_h;
	}
	else if (useBias)
	{
		bias = d->jointSoftness.biasRate * C;
		massScale = d->jointSoftness.massScale;
		impulseScale = d->jointSoftness.impulseScale;
	}
	cdReal Cdot = sign * cd2Dot(axis, cd2AnchorVelocity(args->a, args->b, rA, rB));
	cdReal impulse = -d->axialMass * massScale * (Cdot + bias) - impulseScale * *accumulated;
	cdReal newImpulse = cdMax(*accumulated + impulse, CD_R(0.0));
	impulse = newImpulse - *accumulated;
	*accumulated = newImpulse;
	cd2ApplyJointImpulse(args->a, args->b, rA, rB, cd2Scale(sign * impulse, axis), CD_R(0.0));
}

void cd2SolveDistanceJoint(cd2JointSolverArgs* args, bool useBias)
{
	cd2JointData* d = args->data;
	cd2SolverBody* a = args->a;
	cd2SolverBody* b = args->b;
	cd2Vec rA = cd2RotateVector(a->deltaRotation, d->anchorA);
	cd2Vec rB = cd2RotateVector(b->deltaRotation, d->anchorB);
	cd2Vec delta = cd2AnchorSeparation(a, b, rA, rB, d->deltaCenter);
	cdReal length = cd2Length(delta);
	cd2Vec axis = length > CD_R(0.0) ? cd2Scale(CD_R(1.0) / length, delta) : d->axisA;
	d->axisA = axis;
	/* The effective mass along the current axis and lever arms: a spinning body turns them far
	 * within a step, and the step-start mass would then overshoot. */
	d->axialMass = cd2AxialMass(a, b, rA, rB, axis);
	bool rigid = !d->enableSpring || d->minLength == d->maxLength;
	if (rigid)
	{
		cdReal C = length - d->length;
		cdReal bias = CD_R(0.0), massScale = CD_R(1.0), impulseScale = CD_R(0.0);
		if (useBias)
		{
			bias = d->jointSoftness.biasRate * C;
			massScale = d->jointSoftness.massScale;
			impulseScale = d->jointSoftness.impulseScale;
		}
		cdReal Cdot = cd2Dot(axis, cd2AnchorVelocity(a, b, rA, rB));
		cdReal impulse = -massScale * d->axialMass * (Cdot + bias) - impulseScale * d->impulse;
		d->impulse += impulse;
		cd2ApplyJointImpulse(a, b, rA, rB, cd2Scale(impulse, axis), CD_R(0.0));
	}
	else
	{
		if (d->hertz > CD_R(0.0))
		{
			cdReal C = length - d->length;
			cdReal bias = d->springSoftness.biasRate * C;
			cdReal massScale = d->springSoftness.massScale, impulseScale = d->springSoftness.impulseScale;
			cdReal Cdot = cd2Dot(axis, cd2AnchorVelocity(a, b, rA, rB));
			cdReal impulse = -massScale * d->axialMass * (Cdot + bias) - impulseScale * d->impulse;
			d->impulse += impulse;
			cd2ApplyJointImpulse(a, b, rA, rB, cd2Scale(impulse, axis), CD_R(0.0));
		}
		if (d->enableLimit)
		{
			cd2SolveDistanceLimit(args, rA, rB, axis, length - d->minLength, CD_R(1.0), &d->lowerImpulse,
								  useBias);
			cd2SolveDistanceLimit(args, rA, rB, axis, d->maxLength - length, CD_R(-1.0), &d->upperImpulse,
								  useBias);
		}
	}
	if (d->enableMotor)
	{
		cdReal Cdot = cd2Dot(axis, cd2AnchorVelocity(a, b, rA, rB));
		cdReal impulse = d->axialMass * (d->motorSpeed - Cdot);
		cdReal maxImpulse = d->maxMotorForce * args->context->h;
		cdReal newImpulse = cdClamp(d->motorImpulse + impulse, -maxImpulse, maxImpulse);
		impulse = newImpulse - d->motorImpulse;
		d->motorImpulse = newImpulse;
		cd2ApplyJointImpulse(a, b, rA, rB, cd2Scale(impulse, axis), CD_R(0.0));
	}
}
