/* collide: the prismatic joint: B slides along an axis fixed in A without turning relative to
 * it, with an optional spring, motor and translation limits. */
#include "joint_solver2.h"

/* The axial row's geometry: the offset d between the anchors and the lever arms on the axis. */
typedef struct cd2AxisFrame
{
	cd2Vec rA, rB, d, axis;
	cdReal a1, a2, translation;
} cd2AxisFrame;

static cd2AxisFrame cd2MakeAxisFrame(const cd2JointSolverArgs* args)
{
	const cd2JointData* d = args->data;
	cd2AxisFrame f;
	f.rA = cd2RotateVector(args->a->deltaRotation, d->anchorA);
	f.rB = cd2RotateVector(args->b->deltaRotation, d->anchorB);
	f.d = cd2AnchorSeparation(args->a, args->b, f.rA, f.rB, d->deltaCenter);
	f.axis = cd2RotateVector(args->a->deltaRotation, d->axisA);
	f.translation = cd2Dot(f.axis, f.d);
	f.a1 = cd2Cross(cd2Add(f.d, f.rA), f.axis);
	f.a2 = cd2Cross(f.rB, f.axis);
	return f;
}

static void cd2ApplyAxial(cd2JointSolverArgs* args, const cd2AxisFrame* f, cdReal impulse)
{
	cd2SolverBody* a = args->a;
	cd2SolverBody* b = args->b;
	cd2Vec P = cd2Scale(impulse, f->axis);
	a->linearVelocity = cd2MulSub(a->linearVelocity, a->invMass, P);
	a->angularVelocity -= a->invInertia * impulse * f->a1;
	b->linearVelocity = cd2MulAdd(b->linearVelocity, b->invMass, P);
	b->angularVelocity += b->invInertia * impulse * f->a2;
}

static cdReal cd2AxialVelocity(const cd2JointSolverArgs* args, const cd2AxisFrame* f)
{
	const cd2SolverBody* a = args->a;
	const cd2SolverBody* b = args->b;
	return cd2Dot(f->axis, cd2Sub(b->linearVelocity, a->linearVelocity)) + f->a2 * b->angularVelocity -
		   f->a1 * a->angularVelocity;
}

void cd2PreparePrismaticJoint(cd2JointSolverArgs* args)
{
	cd2JointData* d = args->data;
	/* axisA is stored in world orientation at the step's start. */
	d->springSoftness = cd2MakeSoft(d->hertz, d->dampingRatio, args->context->h);
}

cd2JointImpulse cd2WarmStartPrismaticJoint(const cd2JointSolverArgs* args)
{
	const cd2JointData* d = args->data;
	cd2AxisFrame f = cd2MakeAxisFrame(args);
	cd2Vec perp = cd2LeftPerp(f.axis);
	cdReal s1 = cd2Cross(cd2Add(f.d, f.rA), perp), s2 = cd2Cross(f.rB, perp);
	cdReal axial = d->springImpulse + d->motorImpulse + d->lowerImpulse - d->upperImpulse;
	cd2Vec P = cd2Add(cd2Scale(axial, f.axis), cd2Scale(d->linearImpulse.x, perp));
	cdReal LA = axial * f.a1 + d->linearImpulse.x * s1 + d->linearImpulse.y;
	cdReal LB = axial * f.a2 + d->linearImpulse.x * s2 + d->linearImpulse.y;
	cd2JointImpulse out = {P, P, LA, LB};
	return out;
}

/* The axial spring, motor and limits shared with the wheel joint (motorIsLinear: prismatic). */
void cd2SolveAxialRows(cd2JointSolverArgs* args, bool useBias, bool motorIsLinear);

void cd2SolveAxialRows(cd2JointSolverArgs* args, bool useBias, bool motorIsLinear)
{
	cd2JointData* d = args->data;
	const cd2StepContext* context = args->context;
	cd2AxisFrame f = cd2MakeAxisFrame(args);
	cdReal k = args->a->invMass + args->b->invMass + args->a->invInertia * f.a1 * f.a1 +
			   args->b->invInertia * f.a2 * f.a2;
	cdReal axialMass = k > CD_R(0.0) ? CD_R(1.0) / k : CD_R(0.0);
	if (d->enableSpring)
	{
		cdReal C = f.translation;
		cdReal bias = d->springSoftness.biasRate * C;
		cdReal Cdot = cd2AxialVelocity(args, &f);
		cdReal impulse = -axialMass * d->springSoftness.massScale * (Cdot + bias) -
						 d->springSoftness.impulseScale * d->springImpulse;
		d->springImpulse += impulse;
		cd2ApplyAxial(args, &f, impulse);
	}
	if (d->enableMotor && motorIsLinear)
	{
		cdReal Cdot = cd2AxialVelocity(args, &f);
		cdReal impulse = axialMass * (d->motorSpeed - Cdot);
		cdReal maxImpulse = d->maxMotorForce * context->h;
		cdReal newImpulse = cdClamp(d->motorImpulse + impulse, -maxImpulse, maxImpulse);
		impulse = newImpulse - d->motorImpulse;
		d->motorImpulse = newImpulse;
		cd2ApplyAxial(args, &f, impulse);
	}
	if (d->enableLimit)
	{
		for (int side = 0; side < 2; ++side)
		{
			cdReal sign = side == 0 ? CD_R(1.0) : CD_R(-1.0);
			cdReal C = side == 0 ? f.translation - d->lower : d->upper - f.translation;
			cdReal* accumulated = side == 0 ? &d->lowerImpulse : &d->upperImpulse;
			cdReal Cdot = sign * cd2AxialVelocity(args, &f);
			cdReal impulse = cd2SolveLimitSide(d, context, useBias, axialMass, C, Cdot, accumulated);
			cd2ApplyAxial(args, &f, sign * impulse);
		}
	}
}

void cd2SolvePrismaticJoint(cd2JointSolverArgs* args, bool useBias)
{
	cd2JointData* d = args->data;
	cd2SolveAxialRows(args, useBias, true);
	/* Point on the line and no relative rotation, solved together (2x2). */
	cd2SolverBody* a = args->a;
	cd2SolverBody* b = args->b;
	cd2AxisFrame f = cd2MakeAxisFrame(args);
	cd2Vec perp = cd2LeftPerp(f.axis);
	cdReal s1 = cd2Cross(cd2Add(f.d, f.rA), perp), s2 = cd2Cross(f.rB, perp);
	cd2Vec Cdot = {cd2Dot(perp, cd2Sub(b->linearVelocity, a->linearVelocity)) + s2 * b->angularVelocity -
					   s1 * a->angularVelocity,
				   b->angularVelocity - a->angularVelocity};
	cd2Vec bias = CD2_VEC_ZERO;
	cdReal massScale = CD_R(1.0), impulseScale = CD_R(0.0);
	if (useBias)
	{
		cd2Vec C = {cd2Dot(perp, f.d), d->deltaAngle + cd2RelativeAngle(a->deltaRotation, b->deltaRotation)};
		bias = cd2Scale(d->jointSoftness.biasRate, C);
		massScale = d->jointSoftness.massScale;
		impulseScale = d->jointSoftness.impulseScale;
	}
	cdReal mA = a->invMass, mB = b->invMass, iA = a->invInertia, iB = b->invInertia;
	/* det K = (mA + mB)(iA + iB) + iA iB (s1 - s2)^2 (see cd2Mass22). With no rotation possible
	 * the angular row is inert: K = diag(k11, 1). */
	cd2Mass22 K;
	K.k11 = mA + mB + iA * s1 * s1 + iB * s2 * s2;
	K.k12 = iA * s1 + iB * s2;
	K.k22 = iA + iB;
	cdReal ds = s1 - s2;
	K.det = (mA + mB) * K.k22 + iA * iB * ds * ds;
	if (K.k22 == CD_R(0.0))
	{
		K.k22 = CD_R(1.0);
		K.det = K.k11;
	}
	cd2Vec x = cd2SolveMass22(K, cd2Add(Cdot, bias));
	cd2Vec impulse = cd2Sub(cd2Scale(-massScale, x), cd2Scale(impulseScale, d->linearImpulse));
	d->linearImpulse = cd2Add(d->linearImpulse, impulse);
	cd2Vec P = cd2Scale(impulse.x, perp);
	cdReal LA = impulse.x * s1 + impulse.y;
	cdReal LB = impulse.x * s2 + impulse.y;
	a->linearVelocity = cd2MulSub(a->linearVelocity, mA, P);
	a->angularVelocity -= iA * LA;
	b->linearVelocity = cd2MulAdd(b->linearVelocity, mB, P);
	b->angularVelocity += iB * LB;
}
