/* collide: the motor joint: drives B's origin to linearOffset in A's frame and B's angle to
 * angularOffset relative to A, with a force and torque cap (platform paths, top-down friction). */
#include "joint_solver2.h"

void cd2PrepareMotorJoint(cd2JointSolverArgs* args)
{
	/* (cd2PrepareJointRange placed the anchors at the offset on A and at B's origin.) */
	cd2JointData* d = args->data;
	cdReal k = args->a->invInertia + args->b->invInertia;
	d->axialMass = k > CD_R(0.0) ? CD_R(1.0) / k : CD_R(0.0);
}

cd2JointImpulse cd2WarmStartMotorJoint(const cd2JointSolverArgs* args)
{
	const cd2JointData* d = args->data;
	cd2Vec rA = cd2RotateVector(args->a->deltaRotation, d->anchorA);
	cd2Vec rB = cd2RotateVector(args->b->deltaRotation, d->anchorB);
	return cd2MakeJointImpulse(rA, rB, d->linearImpulse, d->angularImpulse);
}

void cd2SolveMotorJoint(cd2JointSolverArgs* args, bool useBias)
{
	(void)useBias; /* a motor: the correction is part of the drive */
	cd2JointData* d = args->data;
	cd2SolverBody* a = args->a;
	cd2SolverBody* b = args->b;
	const cd2StepContext* context = args->context;
	cdReal h = context->h, inv_h = context->inv_h;
	/* angular */
	{
		cdReal C = d->deltaAngle + cd2RelativeAngle(a->deltaRotation, b->deltaRotation) - d->angularOffset;
		cdReal bias = d->correctionFactor * inv_h * C;
		cdReal Cdot = b->angularVelocity - a->angularVelocity;
		cdReal impulse = -d->axialMass * (Cdot + bias);
		cdReal maxImpulse = d->maxTorque * h;
		cdReal newImpulse = cdClamp(d->angularImpulse + impulse, -maxImpulse, maxImpulse);
		impulse = newImpulse - d->angularImpulse;
		d->angularImpulse = newImpulse;
		a->angularVelocity -= a->invInertia * impulse;
		b->angularVelocity += b->invInertia * impulse;
	}
	/* linear */
	{
		cd2Vec rA = cd2RotateVector(a->deltaRotation, d->anchorA);
		cd2Vec rB = cd2RotateVector(b->deltaRotation, d->anchorB);
		cd2Vec C = cd2AnchorSeparation(a, b, rA, rB, d->deltaCenter);
		cd2Vec bias = cd2Scale(d->correctionFactor * inv_h, C);
		cd2Vec Cdot = cd2AnchorVelocity(a, b, rA, rB);
		cd2Vec impulse = cd2Neg(cd2SolveMass22(cd2PointMass(a, b, rA, rB), cd2Add(Cdot, bias)));
		cd2Vec old = d->linearImpulse;
		d->linearImpulse = cd2Add(d->linearImpulse, impulse);
		cdReal maxImpulse = d->maxForce * h;
		cdReal len2 = cd2Dot(d->linearImpulse, d->linearImpulse);
		if (len2 > maxImpulse * maxImpulse)
		{
			d->linearImpulse = cd2Scale(maxImpulse / cdSqrt(len2), d->linearImpulse);
		}
		impulse = cd2Sub(d->linearImpulse, old);
		cd2ApplyJointImpulse(a, b, rA, rB, impulse, CD_R(0.0));
	}
}
