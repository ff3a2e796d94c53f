/* collide: debug drawing of a 2D world through user callbacks (shapes, joints, contacts, AABBs). */
#include "world2_internal.h"

enum
{
	CD2_COLOR_STATIC = 0x8c8c8c,
	CD2_COLOR_KINEMATIC = 0x4f8fd8,
	CD2_COLOR_DYNAMIC = 0xf0902c,
	CD2_COLOR_SLEEPING = 0x9a7a5a,
	CD2_COLOR_SENSOR = 0xe8d040,
	CD2_COLOR_JOINT = 0x30b0a0,
	CD2_COLOR_CONTACT = 0xe03030,
	CD2_COLOR_NORMAL = 0x30c030,
	CD2_COLOR_AABB = 0xa050d0
};

cd2DebugDraw cd2DefaultDebugDraw(void)
{
	cd2DebugDraw draw;
	memset(&draw, 0, sizeof(draw));
	draw.drawShapes = true;
	draw.drawJoints = true;
	return draw;
}

static uint32_t cd2ShapeColor(const cd2Body* body, const cd2WorldShape* shape)
{
	if (shape->isSensor)
	{
		return CD2_COLOR_SENSOR;
	}
	switch (body->type)
	{
		case CD_STATIC_BODY:
			return CD2_COLOR_STATIC;
		case CD_KINEMATIC_BODY:
			return CD2_COLOR_KINEMATIC;
		default:
			return body->awake ? CD2_COLOR_DYNAMIC : CD2_COLOR_SLEEPING;
	}
}

static void cd2DrawShape(const cd2DebugDraw* draw, const cd2WorldShape* shape, cd2Transform xf,
						 uint32_t color)
{
	switch (shape->type)
	{
		case CD2_WORLD_SHAPE_CIRCLE:
			if (draw->drawCircle != NULL)
			{
				cd2Transform t = {cd2TransformPoint(xf, shape->geometry.circle.center), xf.q};
				draw->drawCircle(t, shape->geometry.circle.radius, color, draw->context);
			}
			break;
		case CD2_WORLD_SHAPE_CAPSULE:
			if (draw->drawCapsule != NULL)
			{
				draw->drawCapsule(cd2TransformPoint(xf, shape->geometry.capsule.p1),
								  cd2TransformPoint(xf, shape->geometry.capsule.p2),
								  shape->geometry.capsule.radius, color, draw->context);
			}
			break;
		case CD2_WORLD_SHAPE_POLYGON:
			if (draw->drawPolygon != NULL)
			{
				const cd2Polygon* p = &shape->geometry.polygon;
				cd2Vec vertices[CD2_MAX_POLYGON_VERTICES];
				for (int i = 0; i < p->count; ++i)
				{
					vertices[i] = cd2TransformPoint(xf, p->vertices[i]);
				}
				draw->drawPolygon(vertices, p->count, p->radius, color, draw->context);
			}
			break;
		case CD2_WORLD_SHAPE_SEGMENT:
			if (draw->drawSegment != NULL)
			{
				draw->drawSegment(cd2TransformPoint(xf, shape->geometry.segment.p1),
								  cd2TransformPoint(xf, shape->geometry.segment.p2), color, draw->context);
			}
			break;
		case CD2_WORLD_SHAPE_CHAIN_SEGMENT:
			if (draw->drawSegment != NULL)
			{
				draw->drawSegment(cd2TransformPoint(xf, shape->geometry.chainSegment.p1),
								  cd2TransformPoint(xf, shape->geometry.chainSegment.p2), color,
								  draw->context);
			}
			break;
	}
}

void cd2World_Draw(cd2WorldId worldId, const cd2DebugDraw* draw)
{
	cd2World* world = cd2GetWorld(worldId);
	if (world == NULL || draw == NULL)
	{
		return;
	}
	if (world->locked)
	{
		CD2_REFUSE("cd2World_Draw: not during the step");
		return;
	}
	for (int i = 0; i < world->shapes.count && (draw->drawShapes || draw->drawAabbs); ++i)
	{
		const cd2WorldShape* shape = world->shapes.data + i;
		if (!shape->inUse)
		{
			continue;
		}
		const cd2Body* body = world->bodies.data + shape->body;
		if (draw->drawShapes)
		{
			cd2DrawShape(draw, shape, body->transform, cd2ShapeColor(body, shape));
		}
		if (draw->drawAabbs && draw->drawSegment != NULL)
		{
			cd2Aabb b = shape->fatAabb;
			cd2Vec c[4] = {b.min, {b.max.x, b.min.y}, b.max, {b.min.x, b.max.y}};
			for (int k = 0; k < 4; ++k)
			{
				draw->drawSegment(c[k], c[(k + 1) % 4], CD2_COLOR_AABB, draw->context);
			}
		}
	}
	if (draw->drawJoints && draw->drawSegment != NULL)
	{
		for (int i = 0; i < world->joints.count; ++i)
		{
			const cd2Joint* joint = world->joints.data + i;
			if (!joint->inUse || joint->type == CD2_FILTER_JOINT)
			{
				continue;
			}
			const cd2Body* a = world->bodies.data + joint->bodyA;
			const cd2Body* b = world->bodies.data + joint->bodyB;
			cd2Vec pA = joint->type == CD2_MOUSE_JOINT
							? joint->data.target
							: cd2TransformPoint(a->transform, joint->data.localAnchorA);
			if (joint->type == CD2_MOTOR_JOINT)
			{
				pA = cd2TransformPoint(a->transform, joint->data.linearOffset);
			}
			cd2Vec pB = cd2TransformPoint(
				b->transform, joint->type == CD2_MOTOR_JOINT ? CD2_VEC_ZERO : joint->data.localAnchorB);
			draw->drawSegment(a->center, pA, CD2_COLOR_JOINT, draw->context);
			draw->drawSegment(pA, pB, CD2_COLOR_JOINT, draw->context);
			draw->drawSegment(pB, b->center, CD2_COLOR_JOINT, draw->context);
		}
	}
	if (draw->drawContacts)
	{
		cdReal scale = CD_R(0.3) * cdGetLengthUnitsPerMeter();
		for (int i = 0; i < world->contacts.count; ++i)
		{
			const cd2Contact* contact = world->contacts.data + i;
			if (!contact->inUse || (contact->flags & CD2_CONTACT_TOUCHING) == 0 ||
				(contact->flags & CD2_CONTACT_SENSOR) != 0)
			{
				continue;
			}
			for (int k = 0; k < contact->pointCount; ++k)
			{
				cd2Vec p = contact->cache[k].point;
				if (draw->drawPoint != NULL)
				{
					draw->drawPoint(p, CD_R(5.0), CD2_COLOR_CONTACT, draw->context);
				}
				if (draw->drawSegment != NULL)
				{
					draw->drawSegment(p, cd2MulAdd(p, scale, contact->normal), CD2_COLOR_NORMAL,
									  draw->context);
				}
			}
		}
	}
}
