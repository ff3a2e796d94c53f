/* collide: the weld joint: a shared point and a fixed relative angle, rigid (the world's joint
 * softness) or soft (its own linear and angular hertz). */
#include "joint_solver2.h"

void cd2PrepareWeldJoint(cd2JointSolverArgs* args)
{
	cd2JointData* d = args->data;
	cdReal h = args->context->h;
	cdReal k = args->a->invInertia + args->b->invInertia;
	d->axialMass = k > CD_R(0.0) ? CD_R(1.0) / k : CD_R(0.0);
	d->springSoftness = d->hertz == CD_R(0.0) ? d->jointSoftness : cd2MakeSoft(d->hertz, d->dampingRatio, h);
	d->angularSoftness = d->angularHertz == CD_R(0.0)
							 ? d->jointSoftness
							 : cd2MakeSoft(d->angularHertz, d->angularDampingRatio, h);
}

cd2JointImpulse cd2WarmStartWeldJoint(const cd2JointSolverArgs* args)
{
	const cd2JointData* d = args->data;
	cd2Vec rA = cd2RotateVector(args->a->deltaRotation, d->anchorA);
	cd2Vec rB = cd2RotateVector(args->b->deltaRotation, d->anchorB);
	return cd2MakeJointImpulse(rA, rB, d->linearImpulse, d->angularImpulse);
}

void cd2SolveWeldJoint(cd2JointSolverArgs* args, bool useBias)
{
	cd2JointData* d = args->data;
	cd2SolverBody* a = args->a;
	cd2SolverBody* b = args->b;
	/* angular */
	{
		cdReal bias = CD_R(0.0), massScale = CD_R(1.0), impulseScale = CD_R(0.0);
		if (useBias || d->angularHertz > CD_R(0.0))
		{
			cdReal C = d->deltaAngle + cd2RelativeAngle(a->deltaRotation, b->deltaRotation);
			bias = d->angularSoftness.biasRate * C;
			massScale = d->angularSoftness.massScale;
			impulseScale = d->angularSoftness.impulseScale;
		}
		cdReal Cdot = b->angularVelocity - a->angularVelocity;
		cdReal impulse = -d->axialMass * massScale * (Cdot + bias) - impulseScale * d->angularImpulse;
		d->angularImpulse += impulse;
		a->angularVelocity -= a->invInertia * impulse;
		b->angularVelocity += b->invInertia * impulse;
	}
	/* linear */
	{
		cd2Vec rA = cd2RotateVector(a->deltaRotation, d->anchorA);
		cd2Vec rB = cd2RotateVector(b->deltaRotation, d->anchorB);
		cd2Vec bias = CD2_VEC_ZERO;
		cdReal massScale = CD_R(1.0), impulseScale = CD_R(0.0);
		if (useBias || d->hertz > CD_R(0.0))
		{
			cd2Vec C = cd2AnchorSeparation(a, b, rA, rB, d->deltaCenter);
			bias = cd2Scale(d->springSoftness.biasRate, C);
			massScale = d->springSoftness.massScale;
			impulseScale = d->springSoftness.impulseScale;
		}
		cd2Vec Cdot = cd2AnchorVelocity(a, b, rA, rB);
		cd2Vec x = cd2SolveMass22(cd2PointMass(a, b, rA, rB), cd2Add(Cdot, bias));
		cd2Vec impulse = cd2Sub(cd2Scale(-massScale, x), cd2Scale(impulseScale, d->linearImpulse));
		d->linearImpulse = cd2Add(d->linearImpulse, impulse);
		cd2ApplyJointImpulse(a, b, rA, rB, impulse, CD_R(0.0));
	}
}
