/* collide: the mouse joint: a soft spring pulling a point of body B towards a world target, with
 * a force cap (dragging bodies with the mouse or a finger). Body A is only the ground. */
#include "joint_solver2.h"

void cd2PrepareMouseJoint(cd2JointSolverArgs* args)
{
	cd2JointData* d = args->data;
	/* (cd2PrepareJointRange set deltaCenter to centre of B - target.) */
	d->springSoftness = cd2MakeSoft(d->hertz, d->dampingRatio, args->context->h);
}

cd2JointImpulse cd2WarmStartMouseJoint(const cd2JointSolverArgs* args)
{
	const cd2JointData* d = args->data;
	cd2Vec rB = cd2RotateVector(args->b->deltaRotation, d->anchorB);
	cd2JointImpulse out = {CD2_VEC_ZERO, d->linearImpulse, CD_R(0.0), cd2Cross(rB, d->linearImpulse)};
	return out;
}

void cd2SolveMouseJoint(cd2JointSolverArgs* args, bool useBias)
{
	(void)useBias; /* a spring: always soft */
	cd2JointData* d = args->data;
	cd2SolverBody* b = args->b;
	cdReal h = args->context->h;
	cd2Vec rB = cd2RotateVector(b->deltaRotation, d->anchorB);
	cd2Vec Cdot = cd2Add(b->linearVelocity, cd2CrossSV(b->angularVelocity, rB));
	/* deltaCenter holds centreB - target at the step's start (see cd2PrepareJointRange). */
	cd2Vec separation = cd2Add(cd2Add(d->deltaCenter, b->deltaPosition), rB);
	cd2Vec bias = cd2Scale(d->springSoftness.biasRate, separation);
	cdReal massScale = d->springSoftness.massScale, impulseScale = d->springSoftness.impulseScale;
	cdReal mB = b->invMass, iB = b->invInertia;
	cd2Mass22 K;
	K.k11 = mB + iB * rB.y * rB.y;
	K.k12 = -iB * rB.x * rB.y;
	K.k22 = mB + iB * rB.x * rB.x;
	K.det = mB * (mB + iB * cd2Dot(rB, rB));
	cd2Vec x = cd2SolveMass22(K, cd2Add(Cdot, bias));
	cd2Vec impulse = cd2Sub(cd2Scale(-massScale, x), cd2Scale(impulseScale, d->linearImpulse));
	cd2Vec old = d->linearImpulse;
	d->linearImpulse = cd2Add(d->linearImpulse, impulse);
	cdReal maxImpulse = d->maxForce * h;
	cdReal len2 = cd2Dot(d->linearImpulse, d->linearImpulse);
	if (len2 > maxImpulse * maxImpulse)
	{
		d->linearImpulse = cd2Scale(maxImpulse / cdSqrt(len2), d->linearImpulse);
	}
	impulse = cd2Sub(d->linearImpulse, old);
	b->linearVelocity = cd2MulAdd(b->linearVelocity, mB, impulse);
	b->angularVelocity += iB * cd2Cross(rB, impulse);
}
