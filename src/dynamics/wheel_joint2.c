/* collide: the wheel joint: B's anchor stays on a line fixed in A (a suspension axis) while B
 * turns freely, with a spring along the line, translation limits and a rotational motor. */
#include "joint_solver2.h"

void cd2SolveAxialRows(cd2JointSolverArgs* args, bool useBias, bool motorIsLinear);

void cd2PrepareWheelJoint(cd2JointSolverArgs* args)
{
	cd2JointData* d = args->data;
	cdReal k = args->a->invInertia + args->b->invInertia;
	d->axialMass = k > CD_R(0.0) ? CD_R(1.0) / k : CD_R(0.0);
	d->springSoftness = cd2MakeSoft(d->hertz, d->dampingRatio, args->context->h);
}

static void cd2WheelFrame(const cd2JointSolverArgs* args, cd2Vec* rA, cd2Vec* rB, cd2Vec* dd, cd2Vec* axis)
{
	const cd2JointData* d = args->data;
	*rA = cd2RotateVector(args->a->deltaRotation, d->anchorA);
	*rB = cd2RotateVector(args->b->deltaRotation, d->anchorB);
	*dd = cd2AnchorSeparation(args->a, args->b, *rA, *rB, d->deltaCenter);
	*axis = cd2RotateVector(args->a->deltaRotation, d->axisA);
}

cd2JointImpulse cd2WarmStartWheelJoint(const cd2JointSolverArgs* args)
{
	const cd2JointData* d = args->data;
	cd2Vec rA, rB, dd, axis;
	cd2WheelFrame(args, &rA, &rB, &dd, &axis);
	cd2Vec perp = cd2LeftPerp(axis);
	cdReal a1 = cd2Cross(cd2Add(dd, rA), axis), a2 = cd2Cross(rB, axis);
	cdReal s1 = cd2Cross(cd2Add(dd, rA), perp), s2 = cd2Cross(rB, perp);
	cdReal axial = d->springImpulse + d->lowerImpulse - d->upperImpulse;
	cd2Vec P = cd2Add(cd2Scale(axial, axis), cd2Scale(d->impulse, perp));
	cdReal LA = axial * a1 + d->impulse * s1 + d->motorImpulse;
	cdReal LB = axial * a2 + d->impulse * s2 + d->motorImpulse;
	cd2JointImpulse out = {P, P, LA, LB};
	return out;
}

void cd2SolveWheelJoint(cd2JointSolverArgs* args, bool useBias)
{
	cd2JointData* d = args->data;
	cd2SolverBody* a = args->a;
	cd2SolverBody* b = args->b;
	cdReal mA = a->invMass, mB = b->invMass, iA = a->invInertia, iB = b->invInertia;
	if (d->enableMotor)
	{
		cdReal Cdot = b->angularVelocity - a->angularVelocity - d->motorSpeed;
		cdReal impulse = -d->axialMass * Cdot;
		cdReal maxImpulse = d->maxMotorForce * args->context->h;
		cdReal newImpulse = cdClamp(d->motorImpulse + impulse, -maxImpulse, maxImpulse);
		impulse = newImpulse - d->motorImpulse;
		d->motorImpulse = newImpulse;
		a->angularVelocity -= iA * impulse;
		b->angularVelocity += iB * impulse;
	}
	cd2SolveAxialRows(args, useBias, false);
	/* The point on the line. */
	cd2Vec rA, rB, dd, axis;
	cd2WheelFrame(args, &rA, &rB, &dd, &axis);
	cd2Vec perp = cd2LeftPerp(axis);
	cdReal s1 = cd2Cross(cd2Add(dd, rA), perp), s2 = cd2Cross(rB, perp);
	cdReal k = mA + mB + iA * s1 * s1 + iB * s2 * s2;
	cdReal perpMass = k > CD_R(0.0) ? CD_R(1.0) / k : CD_R(0.0);
	cdReal bias = CD_R(0.0), massScale = CD_R(1.0), impulseScale = CD_R(0.0);
	if (useBias)
	{
		bias = d->jointSoftness.biasRate * cd2Dot(perp, dd);
		massScale = d->jointSoftness.massScale;
		impulseScale = d->jointSoftness.impulseScale;
	}
	cdReal Cdot = cd2Dot(perp, cd2Sub(b->linearVelocity, a->linearVelocity)) + s2 * b->angularVelocity -
				  s1 * a->angularVelocity;
	cdReal impulse = -perpMass * massScale * (Cdot + bias) - impulseScale * d->impulse;
	d->impulse += impulse;
	cd2Vec P = cd2Scale(impulse, perp);
	a->linearVelocity = cd2MulSub(a->linearVelocity, mA, P);
	a->angularVelocity -= iA * impulse * s1;
	b->linearVelocity = cd2MulAdd(b->linearVelocity, mB, P);
	b->angularVelocity += iB * impulse * s2;
}
