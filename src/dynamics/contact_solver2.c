/* collide: the soft contact solver (the soft step). Each contact point is a soft constraint with
 * the world's contact hertz and damping ratio, solved with "bias" (pushing overlap apart at a
 * limited speed) in the main pass of each sub-step and without it in the relax pass, so that the
 * push never adds kinetic energy. Separation is tracked from the bodies' position deltas since
 * the start of the step, with anchors fixed at the step's start (no narrowphase per sub-step).
 * Points that are still apart are speculative: they only stop the gap from closing within the
 * sub-step. Restitution runs once after the sub-steps and reverses the fastest approach speed each
 * point saw before it was reached (so a speculative contact that catches a falling ball at the
 * surface bounces it with its impact speed, not with its speed at the start of the step). */
#include "world2_internal.h"

static cd2SolverBody s_staticBody = {{CD_R(0.0), CD_R(0.0)}, CD_R(0.0), {CD_R(0.0), CD_R(0.0)},
									 {CD_R(1.0), CD_R(0.0)}, CD_R(0.0), CD_R(0.0)};

static inline cd2SolverBody* cd2SolverBodyAt(cd2StepContext* context, int index, cd2SolverBody* scratch)
{
	if (index < 0)
	{
		*scratch = s_staticBody;
		return scratch;
	}
	return context->bodies + index;
}

bool cd2PrepareContacts(const cd2World* world, cd2StepContext* context, int start, int end)
{
	bool bounces = false;
	for (int i = start; i < end; ++i)
	{
		cd2ContactConstraint* c = context->constraints + (i - context->overflowStart);
		cd2PrepareContactConstraint(world, context, context->pairs + i, c);
		bounces = bounces || c->restitution != CD_R(0.0);
	}
	return bounces;
}

void cd2WarmStartContacts(cd2StepContext* context)
{
	cd2SolverBody scratchA, scratchB;
	for (int i = context->overflowStart; i < context->constraintCount; ++i)
	{
		cd2ContactConstraint* c = context->constraints + (i - context->overflowStart);
		cd2SolverBody* a = cd2SolverBodyAt(context, c->indexA, &scratchA);
		cd2SolverBody* b = cd2SolverBodyAt(context, c->indexB, &scratchB);
		cd2Vec n = c->normal, t = cd2RightPerp(n);
		cd2Vec vA = a->linearVelocity, vB = b->linearVelocity;
		cdReal wA = a->angularVelocity, wB = b->angularVelocity;
		for (int k = 0; k < c->pointCount; ++k)
		{
			const cd2ContactConstraintPoint* cp = c->points + k;
			cd2Vec P = cd2Add(cd2Scale(cp->normalImpulse, n), cd2Scale(cp->tangentImpulse, t));
			wA -= c->invIA * cd2Cross(cp->anchorA, P);
			vA = cd2MulSub(vA, c->invMassA, P);
			wB += c->invIB * cd2Cross(cp->anchorB, P);
			vB = cd2MulAdd(vB, c->invMassB, P);
		}
		wA -= c->invIA * c->rollingImpulse;
		wB += c->invIB * c->rollingImpulse;
		if (c->indexA >= 0)
		{
			a->linearVelocity = vA;
			a->angularVelocity = wA;
		}
		if (c->indexB >= 0)
		{
			b->linearVelocity = vB;
			b->angularVelocity = wB;
		}
	}
}

void cd2SolveContacts(cd2StepContext* context, bool useBias)
{
	cd2SolverBody scratchA, scratchB;
	cdReal inv_h = context->inv_h;
	cdReal maxPush = context->contactPushMaxVelocity;
	for (int i = context->overflowStart; i < context->constraintCount; ++i)
	{
		cd2ContactConstraint* c = context->constraints + (i - context->overflowStart);
		cd2SolverBody* a = cd2SolverBodyAt(context, c->indexA, &scratchA);
		cd2SolverBody* b = cd2SolverBodyAt(context, c->indexB, &scratchB);
		cdReal mA = c->invMassA, iA = c->invIA, mB = c->invMassB, iB = c->invIB;
		cd2Vec vA = a->linearVelocity, vB = b->linearVelocity;
		cdReal wA = a->angularVelocity, wB = b->angularVelocity;
		cd2Vec dpA = a->deltaPosition, dpB = b->deltaPosition;
		cd2Rot dqA = a->deltaRotation, dqB = b->deltaRotation;
		cd2Vec n = c->normal, t = cd2RightPerp(n);
		cdReal totalNormalImpulse = CD_R(0.0);

		for (int k = 0; k < c->pointCount; ++k)
		{
			cd2ContactConstraintPoint* cp = c->points + k;
			cd2Vec rA = cp->anchorA, rB = cp->anchorB;
			/* Current separation from the position deltas. */
			cd2Vec prA = cd2Add(dpA, cd2RotateVector(dqA, rA));
			cd2Vec prB = cd2Add(dpB, cd2RotateVector(dqB, rB));
			cdReal s = cd2Dot(cd2Sub(prB, prA), n) + cp->baseSeparation;
			cdReal bias = CD_R(0.0), massScale = CD_R(1.0), impulseScale = CD_R(0.0);
			if (s > CD_R(0.0))
			{
				bias = s * inv_h; /* speculative: close at most the gap */
			}
			else if (useBias)
			{
				massScale = c->softness.massScale;
				impulseScale = c->softness.impulseScale;
				bias = cdMax(massScale * c->softness.biasRate * s, -maxPush);
			}
			cd2Vec dv = cd2Sub(cd2Add(vB, cd2CrossSV(wB, rB)), cd2Add(vA, cd2CrossSV(wA, rA)));
			cdReal vn = cd2Dot(dv, n);
			if (useBias && vn < cp->relativeVelocity)
			{
				/* The approach speed when the point is reached (gravity of the sub-steps before it
				 * included): what restitution reverses. */
				cp->relativeVelocity = vn;
			}
			cdReal impulse = -cp->normalMass * (massScale * vn + bias) - impulseScale * cp->normalImpulse;
			cdReal newImpulse = cdMax(cp->normalImpulse + impulse, CD_R(0.0));
			impulse = newImpulse - cp->normalImpulse;
			cp->normalImpulse = newImpulse;
			cp->maxNormalImpulse = cdMax(cp->maxNormalImpulse, impulse);
			totalNormalImpulse += newImpulse;
			cd2Vec P = cd2Scale(impulse, n);
			vA = cd2MulSub(vA, mA, P);
			wA -= iA * cd2Cross(rA, P);
			vB = cd2MulAdd(vB, mB, P);
			wB += iB * cd2Cross(rB, P);
		}

		/* Friction and rolling resistance in the relax pass only, on the normal impulses the biased
		 * pass found: friction then never fights the push-out. */
		for (int k = 0; k < c->pointCount && !useBias; ++k)
		{
			cd2ContactConstraintPoint* cp = c->points + k;
			cd2Vec rA = cp->anchorA, rB = cp->anchorB;
			cd2Vec dv = cd2Sub(cd2Add(vB, cd2CrossSV(wB, rB)), cd2Add(vA, cd2CrossSV(wA, rA)));
			cdReal vt = cd2Dot(dv, t) - c->tangentSpeed;
			cdReal impulse = -cp->tangentMass * vt;
			cdReal maxFriction = c->friction * cp->normalImpulse;
			cdReal newImpulse = cdClamp(cp->tangentImpulse + impulse, -maxFriction, maxFriction);
			impulse = newImpulse - cp->tangentImpulse;
			cp->tangentImpulse = newImpulse;
			cd2Vec P = cd2Scale(impulse, t);
			vA = cd2MulSub(vA, mA, P);
			wA -= iA * cd2Cross(rA, P);
			vB = cd2MulAdd(vB, mB, P);
			wB += iB * cd2Cross(rB, P);
		}

		if (c->rollingResistance > CD_R(0.0) && !useBias)
		{
			cdReal maxLambda = c->rollingResistance * totalNormalImpulse;
			cdReal lambda = -c->rollingMass * (wB - wA);
			cdReal newLambda = cdClamp(c->rollingImpulse + lambda, -maxLambda, maxLambda);
			lambda = newLambda - c->rollingImpulse;
			c->rollingImpulse = newLambda;
			wA -= iA * lambda;
			wB += iB * lambda;
		}

		if (c->indexA >= 0)
		{
			a->linearVelocity = vA;
			a->angularVelocity = wA;
		}
		if (c->indexB >= 0)
		{
			b->linearVelocity = vB;
			b->angularVelocity = wB;
		}
	}
}

void cd2ApplyRestitution(cd2StepContext* context)
{
	cd2SolverBody scratchA, scratchB;
	cdReal threshold = context->restitutionThreshold;
	for (int i = context->overflowStart; i < context->constraintCount; ++i)
	{
		cd2ContactConstraint* c = context->constraints + (i - context->overflowStart);
		if (c->restitution == CD_R(0.0))
		{
			continue;
		}
		cd2SolverBody* a = cd2SolverBodyAt(context, c->indexA, &scratchA);
		cd2SolverBody* b = cd2SolverBodyAt(context, c->indexB, &scratchB);
		cdReal mA = c->invMassA, iA = c->invIA, mB = c->invMassB, iB = c->invIB;
		cd2Vec vA = a->linearVelocity, vB = b->linearVelocity;
		cdReal wA = a->angularVelocity, wB = b->angularVelocity;
		cd2Vec n = c->normal;
		for (int k = 0; k < c->pointCount; ++k)
		{
			cd2ContactConstraintPoint* cp = c->points + k;
			/* Only points that were approaching fast enough and actually pushed bounce. */
			if (cp->relativeVelocity > -threshold || cp->maxNormalImpulse == CD_R(0.0))
			{
				continue;
			}
			cd2Vec rA = cp->anchorA, rB = cp->anchorB;
			cd2Vec dv = cd2Sub(cd2Add(vB, cd2CrossSV(wB, rB)), cd2Add(vA, cd2CrossSV(wA, rA)));
			cdReal vn = cd2Dot(dv, n);
			/* The approach was recorded at the start of the sub-step that reached the point, after
			 * that sub-step's acceleration; the bounce leaves before the next one's: add one
			 * sub-step of acceleration so that the flight up mirrors the flight down. */
			cdReal approach = cdMin(cp->relativeVelocity + context->h * c->normalAcceleration, CD_R(0.0));
			cdReal impulse = -cp->normalMass * (vn + c->restitution * approach);
			cdReal newImpulse = cdMax(cp->normalImpulse + impulse, CD_R(0.0));
			impulse = newImpulse - cp->normalImpulse;
			cp->normalImpulse = newImpulse;
			cp->maxNormalImpulse = cdMax(cp->maxNormalImpulse, impulse);
			cd2Vec P = cd2Scale(impulse, n);
			vA = cd2MulSub(vA, mA, P);
			wA -= iA * cd2Cross(rA, P);
			vB = cd2MulAdd(vB, mB, P);
			wB += iB * cd2Cross(rB, P);
		}
		if (c->indexA >= 0)
		{
			a->linearVelocity = vA;
			a->angularVelocity = wA;
		}
		if (c->indexB >= 0)
		{
			b->linearVelocity = vB;
			b->angularVelocity = wB;
		}
	}
}

void cd2StoreImpulses(cd2World* world, const cd2StepContext* context, int start, int end)
{
	for (int i = start; i < end; ++i)
	{
		const cd2ContactConstraint* c = context->constraints + (i - context->overflowStart);
		cd2Contact* contact = world->contacts.data + c->contact;
		contact->rollingImpulse = c->rollingImpulse;
		for (int k = 0; k < c->pointCount; ++k)
		{
			contact->points[k].normalImpulse = c->points[k].normalImpulse;
			contact->points[k].tangentImpulse = c->points[k].tangentImpulse;
			contact->points[k].maxNormalImpulse = c->points[k].maxNormalImpulse;
			contact->cache[k].relativeVelocity = c->points[k].relativeVelocity;
		}
	}
}
