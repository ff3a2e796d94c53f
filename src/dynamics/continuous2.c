/* collide: continuous collision for the 2D world. A fast body (one that moved more than half its
 * inner extent in the step) is swept from its start to its end pose against static shapes (the
 * world's static broadphase, which holds only those), and a bullet also against the other moving
 * bodies' final poses (the whole broadphase), with cd2TimeOfImpact; it is then put
 * back at the first time of impact (its velocity is kept, so the next step's contact stops it).
 * This is what keeps a fast ball from tunnelling through a thin wall. */
#include "world2_internal.h"

/* The core of a shape for continuous collision, as a fraction of its body's inner extent. */
#define CD2_CORE_FRACTION CD_R(0.25)

/* A shape's centroid in its body's frame. */
static cd2Vec cd2WorldShapeCentroid(const cd2WorldShape* shape)
{
	switch (shape->type)
	{
		case CD2_WORLD_SHAPE_CIRCLE:
			return shape->geometry.circle.center;
		case CD2_WORLD_SHAPE_CAPSULE:
			return cd2Lerp(shape->geometry.capsule.p1, shape->geometry.capsule.p2, CD_R(0.5));
		case CD2_WORLD_SHAPE_POLYGON:
			return shape->geometry.polygon.centroid;
		case CD2_WORLD_SHAPE_SEGMENT:
			return cd2Lerp(shape->geometry.segment.p1, shape->geometry.segment.p2, CD_R(0.5));
		case CD2_WORLD_SHAPE_CHAIN_SEGMENT:
			return cd2Lerp(shape->geometry.chainSegment.p1, shape->geometry.chainSegment.p2, CD_R(0.5));
	}
	return CD2_VEC_ZERO;
}

typedef struct cd2ContinuousContext
{
	cd2World* world;
	int bodyIndex;
	int shapeIndex;
	bool isBullet;
	cd2Sweep sweep;
	cd2Vec centroid1; /* the shape's centroid at the end of the step */
	cdReal fraction;
} cd2ContinuousContext;

static bool cd2ContinuousCallback(int proxyId, uint64_t userData, void* context)
{
	(void)proxyId;
	cd2ContinuousContext* c = (cd2ContinuousContext*)context;
	/* Only bullets sweep against moving bodies: the others skip them unread. */
	if ((userData & CD2_PROXY_STATIC) == 0 && !c->isBullet)
	{
		return true;
	}
	cd2World* world = c->world;
	int otherIndex = cd2ProxyShape(userData);
	const cd2WorldShape* shape = world->shapes.data + c->shapeIndex;
	const cd2WorldShape* other = world->shapes.data + otherIndex;
	const cd2Body* body = world->bodies.data + c->bodyIndex;
	const cd2Body* otherBody = world->bodies.data + other->body;
	if (other->body == c->bodyIndex || other->isSensor ||
		!cd2ShouldShapesCollide(shape->filter, other->filter))
	{
		return true;
	}
	if (otherBody->type != CD_STATIC_BODY)
	{
		/* Only bullets sweep against moving bodies, and never against other bullets. */
		if (!body->isBullet || otherBody->isBullet ||
			!cd2ShouldBodiesCollide(world, c->bodyIndex, other->body))
		{
			return true;
		}
	}
	cd2Transform otherXf = otherBody->transform;
	if (other->type == CD2_WORLD_SHAPE_CHAIN_SEGMENT)
	{
		/* One-sided: a body that starts behind the segment passes. So does a shape whose centroid
		 * ends the step at least half the body's inner extent in front of the segment's line: it
		 * has not gone through, what overlaps is the contact's to push out, and its core (see
		 * below) starts the next step clear of the segment. The common case: a body sliding along
		 * a wall. */
		cd2Vec p1 = cd2TransformPoint(otherXf, other->geometry.chainSegment.p1);
		cd2Vec p2 = cd2TransformPoint(otherXf, other->geometry.chainSegment.p2);
		cd2Vec normal = cd2RightPerp(cd2Sub(p2, p1));
		if (cd2Dot(normal, cd2Sub(c->sweep.center0, p1)) < CD_R(0.0) ||
			cd2Dot(normal, cd2Sub(c->centroid1, p1)) > CD_R(0.5) * body->minExtent * cd2Length(normal))
		{
			return true;
		}
	}
	cd2Shape a = cd2MakeTaggedShape(shape, CD2_TRANSFORM_IDENTITY);
	cd2Shape b = cd2MakeTaggedShape(other, CD2_TRANSFORM_IDENTITY);
	cdReal angle = cd2RotGetAngle(otherXf.q);
	cd2Sweep otherSweep = {otherBody->localCenter, otherBody->center, otherBody->center, angle, angle};
	cdToiOutput out =
		cd2TimeOfImpact(&a, &c->sweep, &b, &otherSweep, CD_LINEAR_SLOP, CD_R(0.25) * CD_LINEAR_SLOP);
	if ((out.state == CD_TOI_HIT || out.state == CD_TOI_FAILED) && CD_R(0.0) < out.t && out.t < c->fraction)
	{
		c->fraction = out.t;
	}
	else if (out.t <= CD_R(0.0) && body->minExtent > CD_R(0.0))
	{
		/* Already touching at the start (a body pressed against a wall and then hit hard): the
		 * whole shape gives no time of impact, so sweep its core instead, a small disc at its
		 * centroid. Without this the body is free to pass through the wall in one step. */
		cd2Shape core;
		core.type = CD2_SHAPE_CIRCLE;
		core.circle.center = cd2WorldShapeCentroid(shape);
		core.circle.radius = CD2_CORE_FRACTION * body->minExtent;
		out = cd2TimeOfImpact(&core, &c->sweep, &b, &otherSweep, CD_LINEAR_SLOP, CD_R(0.25) * CD_LINEAR_SLOP);
		if ((out.state == CD_TOI_HIT || out.state == CD_TOI_FAILED) && CD_R(0.0) < out.t &&
			out.t < c->fraction)
		{
			c->fraction = out.t;
		}
	}
	return true;
}

void cd2SolveContinuous(cd2World* world, int bodyIndex)
{
	cd2Body* body = world->bodies.data + bodyIndex;
	/* A non-bullet sweeps against static shapes only: none, nothing to sweep against. */
	if (!body->isBullet && world->staticProxyCount == 0)
	{
		return;
	}
	cd2ContinuousContext c;
	c.world = world;
	c.bodyIndex = bodyIndex;
	c.isBullet = body->isBullet;
	c.fraction = CD_R(1.0);
	cdReal angle0 = cd2RotGetAngle(body->rotation0);
	c.sweep.localCenter = body->localCenter;
	c.sweep.center0 = body->center0;
	c.sweep.center1 = body->center;
	c.sweep.angle0 = angle0;
	c.sweep.angle1 = angle0 + cd2RotGetAngle(cd2InvMulRot(body->rotation0, body->transform.q));
	cd2Transform xf0 = {cd2Sub(body->center0, cd2RotateVector(body->rotation0, body->localCenter)),
						body->rotation0};
	for (int s = body->headShape; s != CD2_NULL_INDEX; s = world->shapes.data[s].nextShape)
	{
		const cd2WorldShape* shape = world->shapes.data + s;
		if (shape->isSensor)
		{
			continue;
		}
		c.shapeIndex = s;
		c.centroid1 = cd2TransformPoint(body->transform, cd2WorldShapeCentroid(shape));
		cd2Aabb box = cd2AabbUnion(cd2ComputeWorldShapeAabb(shape, xf0),
								   cd2ComputeWorldShapeAabb(shape, body->transform));
		/* A bullet against every shape, the others against the static ones (their own tree). */
		cd2BroadPhase_Query(c.isBullet ? world->broadPhase : world->staticBroadPhase, box,
							cd2ContinuousCallback, &c);
	}
	if (c.fraction < CD_R(1.0))
	{
		cd2Transform xf = cd2GetSweepTransform(&c.sweep, c.fraction);
		body->transform = xf;
		body->center = cd2TransformPoint(xf, body->localCenter);
	}
}
