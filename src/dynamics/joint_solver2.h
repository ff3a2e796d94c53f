/* collide: helpers shared by the per-kind 2D joint solvers. */
#ifndef COLLIDE_JOINT_SOLVER2_H
#define COLLIDE_JOINT_SOLVER2_H

#include "world2_internal.h"

/* Angle of B relative to A over the sub-steps (small: the step's own rotation). */
static inline cdReal cd2RelativeAngle(cd2Rot a, cd2Rot b)
{
	return cd2RotGetAngle(cd2InvMulRot(a, b));
}

/* Applies P at rA on A (negative) and at rB on B (positive), plus an angular impulse L. */
static inline void cd2ApplyJointImpulse(cd2SolverBody* a, cd2SolverBody* b, cd2Vec rA, cd2Vec rB, cd2Vec P,
										cdReal L)
{
	a->linearVelocity = cd2MulSub(a->linearVelocity, a->invMass, P);
	a->angularVelocity -= a->invInertia * (cd2Cross(rA, P) + L);
	b->linearVelocity = cd2MulAdd(b->linearVelocity, b->invMass, P);
	b->angularVelocity += b->invInertia * (cd2Cross(rB, P) + L);
}

/* The warm-start impulse of P at rA on A (negative) and at rB on B (positive), plus an angular
 * impulse L. */
static inline cd2JointImpulse cd2MakeJointImpulse(cd2Vec rA, cd2Vec rB, cd2Vec P, cdReal L)
{
	cd2JointImpulse out = {P, P, cd2Cross(rA, P) + L, cd2Cross(rB, P) + L};
	return out;
}

/* The revolute joint's warm start (inline: the commonest joint, in chains, ragdolls and grids). */
static inline cd2JointImpulse cd2WarmStartRevoluteJoint(const cd2JointSolverArgs* args)
{
	const cd2JointData* d = args->data;
	cd2Vec rA = cd2RotateVector(args->a->deltaRotation, d->anchorA);
	cd2Vec rB = cd2RotateVector(args->b->deltaRotation, d->anchorB);
	cdReal axial = d->springImpulse + d->motorImpulse + d->lowerImpulse - d->upperImpulse;
	return cd2MakeJointImpulse(rA, rB, d->linearImpulse, axial);
}

/* The relative velocity of the anchor points. */
static inline cd2Vec cd2AnchorVelocity(const cd2SolverBody* a, const cd2SolverBody* b, cd2Vec rA, cd2Vec rB)
{
	return cd2Sub(cd2Add(b->linearVelocity, cd2CrossSV(b->angularVelocity, rB)),
				  cd2Add(a->linearVelocity, cd2CrossSV(a->angularVelocity, rA)));
}

/* A symmetric 2x2 effective mass with its determinant. k11 k22 - k12^2 loses every digit when a
 * light body hangs on a long lever arm (a 0.008 kg body 1,700 m from its anchor: the two products
 * are 3e16 apart by 1e7, float rounding is 3e9), and a determinant of the wrong sign turns the
 * solve into an amplifier that overflows within a few sub-steps. Each joint writes its own
 * determinant in a form that is a sum of non-negative terms. */
typedef struct cd2Mass22
{
	cdReal k11, k12, k22, det;
} cd2Mass22;

/* Solves K x = b; the zero vector when K is singular (no body can move along the constraint). */
static inline cd2Vec cd2SolveMass22(cd2Mass22 m, cd2Vec b)
{
	if (!(m.det > CD_R(0.0)))
	{
		return CD2_VEC_ZERO;
	}
	cdReal invDet = CD_R(1.0) / m.det;
	return cd2MakeVec(invDet * (m.k22 * b.x - m.k12 * b.y), invDet * (m.k11 * b.y - m.k12 * b.x));
}

/* The point constraint's effective mass, K = (mA + mB) I + iA rA' rA'^T + iB rB' rB'^T with r' the
 * perpendicular of r; det K = m^2 + m (iA |rA|^2 + iB |rB|^2) + iA iB (rA x rB)^2
 * = m (k11 + k22 - m) + iA iB (rA x rB)^2. */
static inline cd2Mass22 cd2PointMassOf(cdReal m, cdReal iA, cdReal iB, cd2Vec rA, cd2Vec rB)
{
	cd2Mass22 k;
	k.k11 = m + rA.y * rA.y * iA + rB.y * rB.y * iB;
	k.k12 = -rA.y * rA.x * iA - rB.y * rB.x * iB;
	k.k22 = m + rA.x * rA.x * iA + rB.x * rB.x * iB;
	/* The plain form while it keeps three digits (short lever arms: nearly every joint). */
	k.det = k.k11 * k.k22 - k.k12 * k.k12;
	if (k.det < CD_R(1e-3) * k.k11 * k.k22)
	{
		cdReal cross = cd2Cross(rA, rB);
		k.det = m * (k.k11 + k.k22 - m) + iA * iB * cross * cross;
	}
	return k;
}

static inline cd2Mass22 cd2PointMass(const cd2SolverBody* a, const cd2SolverBody* b, cd2Vec rA, cd2Vec rB)
{
	return cd2PointMassOf(a->invMass + b->invMass, a->invInertia, b->invInertia, rA, rB);
}

/* The current separation of the anchors (from the step's start plus the position deltas). */
static inline cd2Vec cd2AnchorSeparation(const cd2SolverBody* a, const cd2SolverBody* b, cd2Vec rA, cd2Vec rB,
										 cd2Vec deltaCenter)
{
	return cd2Add(cd2Add(cd2Sub(b->deltaPosition, a->deltaPosition), cd2Sub(rB, rA)), deltaCenter);
}

/* One side of a limit (lower or upper) of mass `mass`: C is the distance to the limit (positive
 * while inside it) and Cdot the rate at which C grows. Speculative while C > 0 (stops exactly at
 * the limit), soft with the joint's softness when pushing out with bias. Accumulates into
 * *accumulated, which stays non-negative, and returns the impulse to apply along the side. */
static inline cdReal cd2SolveLimitSide(const cd2JointData* d, const cd2StepContext* context, bool useBias,
									   cdReal mass, cdReal C, cdReal Cdot, cdReal* accumulated)
{
	cdReal bias = CD_R(0.0), massScale = CD_R(1.0), impulseScale = CD_R(0.0);
	if (C > CD_R(0.0))
	{
		bias = C * context->inv_h;
	}
	else if (useBias)
	{
		bias = d->jointSoftness.biasRate * C;
		massScale = d->jointSoftness.massScale;
		impulseScale = d->jointSoftness.impulseScale;
	}
	cdReal impulse = -mass * massScale * (Cdot + bias) - impulseScale * *accumulated;
	cdReal newImpulse = cdMax(*accumulated + impulse, CD_R(0.0));
	impulse = newImpulse - *accumulated;
	*accumulated = newImpulse;
	return impulse;
}

#endif
