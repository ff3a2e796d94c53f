/* collide: 2D joints: creation and destruction, the body lists, the dispatch to the per-kind
 * solvers (distance_joint2.c, revolute_joint2.c, ...) and the reaction forces. Joints are soft
 * constraints like contacts: the point and angle constraints use the world's joint softness, and
 * springs their own hertz and damping ratio. */
#include "joint_solver2.h"

cd2Joint* cd2GetJoint(cd2World* world, cd2JointId id)
{
	if (world == NULL || id.index1 <= 0 || id.index1 > world->joints.count)
	{
		return NULL;
	}
	cd2Joint* joint = world->joints.data + (id.index1 - 1);
	if (!joint->inUse || joint->generation != id.generation)
	{
		return NULL;
	}
	return joint;
}

static cd2Joint* cd2LookupJoint(cd2JointId id, cd2World** outWorld, bool mutating)
{
	cd2World* world = cd2GetWorldFromIndex(id.world0);
	cd2Joint* joint = cd2GetJoint(world, id);
	if (joint == NULL)
	{
		CD2_REFUSE("stale or null joint id");
		return NULL;
	}
	if (mutating && world->locked)
	{
		CD2_REFUSE("the world is locked during the step");
		return NULL;
	}
	*outWorld = world;
	return joint;
}

static void cd2LinkJointEdge(cd2World* world, int jointIndex, int side, int bodyIndex)
{
	cd2Joint* joint = world->joints.data + jointIndex;
	cd2Body* body = world->bodies.data + bodyIndex;
	int key = (jointIndex << 1) | side;
	joint->prevKey[side] = CD2_NULL_INDEX;
	joint->nextKey[side] = body->headJointKey;
	if (body->headJointKey != CD2_NULL_INDEX)
	{
		world->joints.data[body->headJointKey >> 1].prevKey[body->headJointKey & 1] = key;
	}
	body->headJointKey = key;
}

static void cd2UnlinkJointEdge(cd2World* world, int jointIndex, int side, int bodyIndex)
{
	cd2Joint* joint = world->joints.data + jointIndex;
	int prev = joint->prevKey[side], next = joint->nextKey[side];
	if (prev != CD2_NULL_INDEX)
	{
		world->joints.data[prev >> 1].nextKey[prev & 1] = next;
	}
	else
	{
		world->bodies.data[bodyIndex].headJointKey = next;
	}
	if (next != CD2_NULL_INDEX)
	{
		world->joints.data[next >> 1].prevKey[next & 1] = prev;
	}
}

/* Creates the joint record with its bodies; the kind fills data. NULL on refusal. */
static cd2Joint* cd2CreateJointRecord(cd2WorldId worldId, cd2BodyId idA, cd2BodyId idB, cd2JointType type,
									  bool collideConnected, void* userData, bool valid, cd2JointId* outId)
{
	*outId = CD2_NULL_JOINT_ID;
	cd2World* world = cd2GetWorld(worldId);
	if (world == NULL)
	{
		return NULL;
	}
	if (world->locked)
	{
		CD2_REFUSE("joint creation: the world is locked during the step");
		return NULL;
	}
	cd2Body* a = cd2GetBody(world, idA);
	cd2Body* b = cd2GetBody(world, idB);
	if (a == NULL || b == NULL || idA.index1 == idB.index1 || idA.world0 != world->index ||
		idB.world0 != world->index || !valid)
	{
		CD2_REFUSE(
			"joint creation: stale body ids, the same body twice, or a bad definition (NaN, negative)");
		return NULL;
	}
	int index = cdIdPool_Alloc(&world->jointPool);
	if (index < 0 || !cdArrayReserveFor(world->joints, index + 1))
	{
		if (index >= 0)
		{
			cdIdPool_Free(&world->jointPool, index);
		}
		return NULL;
	}
	if (index >= world->joints.count)
	{
		world->joints.count = index + 1;
	}
	cd2Joint* joint = world->joints.data + index;
	memset(joint, 0, sizeof(*joint));
	joint->generation = cd2NextGeneration(world);
	joint->inUse = true;
	joint->type = type;
	joint->bodyA = idA.index1 - 1;
	joint->bodyB = idB.index1 - 1;
	joint->collideConnected = collideConnected;
	joint->userData = userData;
	cd2LinkJointEdge(world, index, 0, joint->bodyA);
	cd2LinkJointEdge(world, index, 1, joint->bodyB);
	/* Contacts between the bodies go when the joint says so. */
	if (!collideConnected)
	{
		int key = world->bodies.data[joint->bodyA].headContactKey;
		while (key != CD2_NULL_INDEX)
		{
			cd2Contact* contact = world->contacts.data + cd2EdgeContact(key);
			int next = contact->nextKey[cd2EdgeSide(key)];
			int other = cd2EdgeSide(key) == 0 ? contact->bodyB : contact->bodyA;
			if (other == joint->bodyB && (contact->flags & CD2_CONTACT_SENSOR) == 0)
			{
				cd2DestroyContact(world, cd2EdgeContact(key), false);
			}
			key = next;
		}
	}
	cd2WakeBody(world, joint->bodyA);
	cd2WakeBody(world, joint->bodyB);
	if (type != CD2_FILTER_JOINT)
	{
		cd2AwakeSets_Link(world, joint->bodyA, joint->bodyB);
	}
	cd2JointId id = {index + 1, world->index, joint->generation};
	*outId = id;
	return joint;
}

static bool cd2Finite(cdReal a)
{
	return cdIsValidReal(a);
}

static bool cd2NonNeg(cdReal a)
{
	return cdIsValidReal(a) && a >= CD_R(0.0);
}

/* Joint event thresholds: zero (none) or positive, finite or not. */
static bool cd2ValidThresholds(cdReal force, cdReal torque)
{
	return !(force != force) && !(torque != torque) && force >= CD_R(0.0) && torque >= CD_R(0.0);
}

static void cd2InitThresholds(cd2Joint* joint, cdReal force, cdReal torque)
{
	if (joint != NULL)
	{
		joint->forceThreshold = force;
		joint->torqueThreshold = torque;
	}
}

static void cd2InitConstraintTuning(cd2Joint* joint, cdReal hertz, cdReal dampingRatio)
{
	if (joint != NULL)
	{
		joint->data.constraintHertz = hertz;
		joint->data.constraintDampingRatio = dampingRatio;
	}
}

/* ---- defaults ---------------------------------------------------------------------------------- */
cd2DistanceJointDef cd2DefaultDistanceJointDef(void)
{
	cd2DistanceJointDef def;
	memset(&def, 0, sizeof(def));
	def.length = CD_R(1.0);
	def.maxLength = CD_REAL_MAX;
	return def;
}

cd2FilterJointDef cd2DefaultFilterJointDef(void)
{
	cd2FilterJointDef def;
	memset(&def, 0, sizeof(def));
	return def;
}

cd2MotorJointDef cd2DefaultMotorJointDef(void)
{
	cd2MotorJointDef def;
	memset(&def, 0, sizeof(def));
	def.maxForce = CD_R(1.0);
	def.maxTorque = CD_R(1.0);
	def.correctionFactor = CD_R(0.3);
	return def;
}

cd2MouseJointDef cd2DefaultMouseJointDef(void)
{
	cd2MouseJointDef def;
	memset(&def, 0, sizeof(def));
	def.hertz = CD_R(4.0);
	def.dampingRatio = CD_R(1.0);
	def.maxForce = CD_R(1.0);
	return def;
}

cd2PrismaticJointDef cd2DefaultPrismaticJointDef(void)
{
	cd2PrismaticJointDef def;
	memset(&def, 0, sizeof(def));
	def.localAxisA = cd2MakeVec(CD_R(1.0), CD_R(0.0));
	return def;
}

cd2RevoluteJointDef cd2DefaultRevoluteJointDef(void)
{
	cd2RevoluteJointDef def;
	memset(&def, 0, sizeof(def));
	return def;
}

cd2WeldJointDef cd2DefaultWeldJointDef(void)
{
	cd2WeldJointDef def;
	memset(&def, 0, sizeof(def));
	return def;
}

cd2WheelJointDef cd2DefaultWheelJointDef(void)
{
	cd2WheelJointDef def;
	memset(&def, 0, sizeof(def));
	def.localAxisA = cd2MakeVec(CD_R(0.0), CD_R(1.0));
	def.enableSpring = true;
	def.hertz = CD_R(1.0);
	def.dampingRatio = CD_R(0.7);
	return def;
}

/* ---- creation ---------------------------------------------------------------------------------- */
cd2JointId cd2CreateDistanceJoint(cd2WorldId worldId, const cd2DistanceJointDef* def)
{
	cd2JointId id = CD2_NULL_JOINT_ID;
	bool valid = def != NULL && cd2IsValidVec(def->localAnchorA) && cd2IsValidVec(def->localAnchorB) &&
				 cd2NonNeg(def->length) && cd2NonNeg(def->minLength) && !(def->maxLength != def->maxLength) &&
				 def->maxLength >= def->minLength && cd2NonNeg(def->hertz) && cd2NonNeg(def->dampingRatio) &&
				 cd2NonNeg(def->maxMotorForce) && cd2Finite(def->motorSpeed);
	if (def == NULL)
	{
		CD2_REFUSE("cd2CreateDistanceJoint: NULL def");
		return id;
	}
	cd2Joint* joint = cd2CreateJointRecord(
		worldId, def->bodyIdA, def->bodyIdB, CD2_DISTANCE_JOINT, def->collideConnected, def->userData,
		valid && cd2ValidThresholds(def->forceThreshold, def->torqueThreshold) &&
			cd2NonNeg(def->constraintHertz) && cd2NonNeg(def->constraintDampingRatio),
		&id);
	cd2InitThresholds(joint, def->forceThreshold, def->torqueThreshold);
	cd2InitConstraintTuning(joint, def->constraintHertz, def->constraintDampingRatio);
	if (joint != NULL)
	{
		cd2JointData* d = &joint->data;
		d->localAnchorA = def->localAnchorA;
		d->localAnchorB = def->localAnchorB;
		d->length = cdMax(def->length, CD_LINEAR_SLOP);
		d->minLength = def->minLength;
		d->maxLength = def->maxLength;
		d->enableSpring = def->enableSpring;
		d->hertz = def->hertz;
		d->dampingRatio = def->dampingRatio;
		d->enableLimit = def->enableLimit;
		d->enableMotor = def->enableMotor;
		d->maxMotorForce = def->maxMotorForce;
		d->motorSpeed = def->motorSpeed;
	}
	return id;
}

cd2JointId cd2CreateFilterJoint(cd2WorldId worldId, const cd2FilterJointDef* def)
{
	cd2JointId id = CD2_NULL_JOINT_ID;
	if (def == NULL)
	{
		CD2_REFUSE("cd2CreateFilterJoint: NULL def");
		return id;
	}
	cd2CreateJointRecord(worldId, def->bodyIdA, def->bodyIdB, CD2_FILTER_JOINT, false, def->userData, true,
						 &id);
	return id;
}

cd2JointId cd2CreateMotorJoint(cd2WorldId worldId, const cd2MotorJointDef* def)
{
	cd2JointId id = CD2_NULL_JOINT_ID;
	if (def == NULL)
	{
		CD2_REFUSE("cd2CreateMotorJoint: NULL def");
		return id;
	}
	bool valid = cd2IsValidVec(def->linearOffset) && cd2Finite(def->angularOffset) &&
				 cd2NonNeg(def->maxForce) && cd2NonNeg(def->maxTorque) && cd2NonNeg(def->correctionFactor) &&
				 def->correctionFactor <= CD_R(1.0);
	cd2Joint* joint = cd2CreateJointRecord(
		worldId, def->bodyIdA, def->bodyIdB, CD2_MOTOR_JOINT, def->collideConnected, def->userData,
		valid && cd2ValidThresholds(def->forceThreshold, def->torqueThreshold), &id);
	cd2InitThresholds(joint, def->forceThreshold, def->torqueThreshold);
	if (joint != NULL)
	{
		joint->data.linearOffset = def->linearOffset;
		joint->data.angularOffset = def->angularOffset;
		joint->data.maxForce = def->maxForce;
		joint->data.maxTorque = def->maxTorque;
		joint->data.correctionFactor = def->correctionFactor;
	}
	return id;
}

cd2JointId cd2CreateMouseJoint(cd2WorldId worldId, const cd2MouseJointDef* def)
{
	cd2JointId id = CD2_NULL_JOINT_ID;
	if (def == NULL)
	{
		CD2_REFUSE("cd2CreateMouseJoint: NULL def");
		return id;
	}
	bool valid = cd2IsValidVec(def->target) && cd2NonNeg(def->hertz) && cd2NonNeg(def->dampingRatio) &&
				 cd2NonNeg(def->maxForce);
	cd2Joint* joint = cd2CreateJointRecord(
		worldId, def->bodyIdA, def->bodyIdB, CD2_MOUSE_JOINT, def->collideConnected, def->userData,
		valid && cd2ValidThresholds(def->forceThreshold, def->torqueThreshold), &id);
	cd2InitThresholds(joint, def->forceThreshold, def->torqueThreshold);
	if (joint != NULL)
	{
		cd2World* world = cd2GetWorld(worldId);
		const cd2Body* b = world->bodies.data + joint->bodyB;
		joint->data.target = def->target;
		joint->data.localAnchorB = cd2InvTransformPoint(b->transform, def->target);
		joint->data.hertz = def->hertz;
		joint->data.dampingRatio = def->dampingRatio;
		joint->data.maxForce = def->maxForce;
	}
	return id;
}

cd2JointId cd2CreatePrismaticJoint(cd2WorldId worldId, const cd2PrismaticJointDef* def)
{
	cd2JointId id = CD2_NULL_JOINT_ID;
	if (def == NULL)
	{
		CD2_REFUSE("cd2CreatePrismaticJoint: NULL def");
		return id;
	}
	cdReal axisLength = cd2Length(def->localAxisA);
	bool valid = cd2IsValidVec(def->localAnchorA) && cd2IsValidVec(def->localAnchorB) &&
				 cd2IsValidVec(def->localAxisA) && axisLength > CD_R(0.0) && cd2Finite(def->referenceAngle) &&
				 cd2NonNeg(def->hertz) && cd2NonNeg(def->dampingRatio) && cd2Finite(def->lowerTranslation) &&
				 cd2Finite(def->upperTranslation) && def->lowerTranslation <= def->upperTranslation &&
				 cd2NonNeg(def->maxMotorForce) && cd2Finite(def->motorSpeed);
	cd2Joint* joint = cd2CreateJointRecord(
		worldId, def->bodyIdA, def->bodyIdB, CD2_PRISMATIC_JOINT, def->collideConnected, def->userData,
		valid && cd2ValidThresholds(def->forceThreshold, def->torqueThreshold) &&
			cd2NonNeg(def->constraintHertz) && cd2NonNeg(def->constraintDampingRatio),
		&id);
	cd2InitThresholds(joint, def->forceThreshold, def->torqueThreshold);
	cd2InitConstraintTuning(joint, def->constraintHertz, def->constraintDampingRatio);
	if (joint != NULL)
	{
		cd2JointData* d = &joint->data;
		d->localAnchorA = def->localAnchorA;
		d->localAnchorB = def->localAnchorB;
		d->localAxisA = cd2Normalize(def->localAxisA);
		d->referenceAngle = def->referenceAngle;
		d->enableSpring = def->enableSpring;
		d->hertz = def->hertz;
		d->dampingRatio = def->dampingRatio;
		d->enableLimit = def->enableLimit;
		d->lower = def->lowerTranslation;
		d->upper = def->upperTranslation;
		d->enableMotor = def->enableMotor;
		d->maxMotorForce = def->maxMotorForce;
		d->motorSpeed = def->motorSpeed;
	}
	return id;
}

cd2JointId cd2CreateRevoluteJoint(cd2WorldId worldId, const cd2RevoluteJointDef* def)
{
	cd2JointId id = CD2_NULL_JOINT_ID;
	if (def == NULL)
	{
		CD2_REFUSE("cd2CreateRevoluteJoint: NULL def");
		return id;
	}
	bool valid = cd2IsValidVec(def->localAnchorA) && cd2IsValidVec(def->localAnchorB) &&
				 cd2Finite(def->referenceAngle) && cd2NonNeg(def->hertz) && cd2NonNeg(def->dampingRatio) &&
				 cd2Finite(def->lowerAngle) && cd2Finite(def->upperAngle) &&
				 def->lowerAngle <= def->upperAngle && cd2NonNeg(def->maxMotorTorque) &&
				 cd2Finite(def->motorSpeed);
	cd2Joint* joint = cd2CreateJointRecord(
		worldId, def->bodyIdA, def->bodyIdB, CD2_REVOLUTE_JOINT, def->collideConnected, def->userData,
		valid && cd2ValidThresholds(def->forceThreshold, def->torqueThreshold) &&
			cd2NonNeg(def->constraintHertz) && cd2NonNeg(def->constraintDampingRatio),
		&id);
	cd2InitThresholds(joint, def->forceThreshold, def->torqueThreshold);
	cd2InitConstraintTuning(joint, def->constraintHertz, def->constraintDampingRatio);
	if (joint != NULL)
	{
		cd2JointData* d = &joint->data;
		d->localAnchorA = def->localAnchorA;
		d->localAnchorB = def->localAnchorB;
		d->referenceAngle = def->referenceAngle;
		d->enableSpring = def->enableSpring;
		d->hertz = def->hertz;
		d->dampingRatio = def->dampingRatio;
		d->enableLimit = def->enableLimit;
		d->lower = cdClamp(def->lowerAngle, -CD_PI, CD_PI);
		d->upper = cdClamp(def->upperAngle, -CD_PI, CD_PI);
		d->enableMotor = def->enableMotor;
		d->maxMotorForce = def->maxMotorTorque;
		d->motorSpeed = def->motorSpeed;
	}
	return id;
}

cd2JointId cd2CreateWeldJoint(cd2WorldId worldId, const cd2WeldJointDef* def)
{
	cd2JointId id = CD2_NULL_JOINT_ID;
	if (def == NULL)
	{
		CD2_REFUSE("cd2CreateWeldJoint: NULL def");
		return id;
	}
	bool valid = cd2IsValidVec(def->localAnchorA) && cd2IsValidVec(def->localAnchorB) &&
				 cd2Finite(def->referenceAngle) && cd2NonNeg(def->linearHertz) &&
				 cd2NonNeg(def->angularHertz) && cd2NonNeg(def->linearDampingRatio) &&
				 cd2NonNeg(def->angularDampingRatio);
	cd2Joint* joint = cd2CreateJointRecord(
		worldId, def->bodyIdA, def->bodyIdB, CD2_WELD_JOINT, def->collideConnected, def->userData,
		valid && cd2ValidThresholds(def->forceThreshold, def->torqueThreshold) &&
			cd2NonNeg(def->constraintHertz) && cd2NonNeg(def->constraintDampingRatio),
		&id);
	cd2InitThresholds(joint, def->forceThreshold, def->torqueThreshold);
	cd2InitConstraintTuning(joint, def->constraintHertz, def->constraintDampingRatio);
	if (joint != NULL)
	{
		cd2JointData* d = &joint->data;
		d->localAnchorA = def->localAnchorA;
		d->localAnchorB = def->localAnchorB;
		d->referenceAngle = def->referenceAngle;
		d->hertz = def->linearHertz;
		d->dampingRatio = def->linearDampingRatio;
		d->angularHertz = def->angularHertz;
		d->angularDampingRatio = def->angularDampingRatio;
	}
	return id;
}

cd2JointId cd2CreateWheelJoint(cd2WorldId worldId, const cd2WheelJointDef* def)
{
	cd2JointId id = CD2_NULL_JOINT_ID;
	if (def == NULL)
	{
		CD2_REFUSE("cd2CreateWheelJoint: NULL def");
		return id;
	}
	cdReal axisLength = cd2Length(def->localAxisA);
	bool valid = cd2IsValidVec(def->localAnchorA) && cd2IsValidVec(def->localAnchorB) &&
				 cd2IsValidVec(def->localAxisA) && axisLength > CD_R(0.0) && cd2NonNeg(def->hertz) &&
				 cd2NonNeg(def->dampingRatio) && cd2Finite(def->lowerTranslation) &&
				 cd2Finite(def->upperTranslation) && def->lowerTranslation <= def->upperTranslation &&
				 cd2NonNeg(def->maxMotorTorque) && cd2Finite(def->motorSpeed);
	cd2Joint* joint = cd2CreateJointRecord(
		worldId, def->bodyIdA, def->bodyIdB, CD2_WHEEL_JOINT, def->collideConnected, def->userData,
		valid && cd2ValidThresholds(def->forceThreshold, def->torqueThreshold) &&
			cd2NonNeg(def->constraintHertz) && cd2NonNeg(def->constraintDampingRatio),
		&id);
	cd2InitThresholds(joint, def->forceThreshold, def->torqueThreshold);
	cd2InitConstraintTuning(joint, def->constraintHertz, def->constraintDampingRatio);
	if (joint != NULL)
	{
		cd2JointData* d = &joint->data;
		d->localAnchorA = def->localAnchorA;
		d->localAnchorB = def->localAnchorB;
		d->localAxisA = cd2Normalize(def->localAxisA);
		d->enableSpring = def->enableSpring;
		d->hertz = def->hertz;
		d->dampingRatio = def->dampingRatio;
		d->enableLimit = def->enableLimit;
		d->lower = def->lowerTranslation;
		d->upper = def->upperTranslation;
		d->enableMotor = def->enableMotor;
		d->maxMotorForce = def->maxMotorTorque;
		d->motorSpeed = def->motorSpeed;
	}
	return id;
}

void cd2DestroyJointInternal(cd2World* world, int jointIndex, bool wakeBodies)
{
	cd2Joint* joint = world->joints.data + jointIndex;
	int a = joint->bodyA, b = joint->bodyB;
	bool refilter = !joint->collideConnected;
	bool linked = joint->type != CD2_FILTER_JOINT;
	cd2UnlinkJointEdge(world, jointIndex, 0, a);
	cd2UnlinkJointEdge(world, jointIndex, 1, b);
	joint->inUse = false;
	joint->generation = 0;
	cdIdPool_Free(&world->jointPool, jointIndex);
	if (wakeBodies)
	{
		cd2WakeBody(world, a);
		cd2WakeBody(world, b);
	}
	if (linked)
	{
		cd2AwakeSets_Unlink(world, a, b);
	}
	/* The bodies may collide now: let the broadphase report their pairs again. */
	if (refilter)
	{
		cd2Body* body = world->bodies.data + b;
		for (int s = body->headShape; s != CD2_NULL_INDEX; s = world->shapes.data[s].nextShape)
		{
			cd2WorldShape* shape = world->shapes.data + s;
			if (shape->proxyId != CD_NULL_PROXY)
			{
				cd2DestroyShapeProxy(world, shape);
				cd2UpdateShapeBounds(world, s, false);
			}
		}
	}
}

void cd2DestroyJoint(cd2JointId jointId)
{
	cd2World* world = NULL;
	cd2Joint* joint = cd2LookupJoint(jointId, &world, true);
	if (joint != NULL)
	{
		cd2DestroyJointInternal(world, jointId.index1 - 1, true);
	}
}

bool cd2Joint_IsValid(cd2JointId jointId)
{
	return cd2GetJoint(cd2GetWorldFromIndex(jointId.world0), jointId) != NULL;
}

cd2JointType cd2Joint_GetType(cd2JointId jointId)
{
	cd2World* world = NULL;
	cd2Joint* joint = cd2LookupJoint(jointId, &world, false);
	return joint != NULL ? joint->type : CD2_DISTANCE_JOINT;
}

cd2BodyId cd2Joint_GetBodyA(cd2JointId jointId)
{
	cd2World* world = NULL;
	cd2Joint* joint = cd2LookupJoint(jointId, &world, false);
	return joint != NULL ? cd2MakeBodyId(world, joint->bodyA) : CD2_NULL_BODY_ID;
}

cd2BodyId cd2Joint_GetBodyB(cd2JointId jointId)
{
	cd2World* world = NULL;
	cd2Joint* joint = cd2LookupJoint(jointId, &world, false);
	return joint != NULL ? cd2MakeBodyId(world, joint->bodyB) : CD2_NULL_BODY_ID;
}

cd2Vec cd2Joint_GetConstraintForce(cd2JointId jointId)
{
	cd2World* world = NULL;
	cd2Joint* joint = cd2LookupJoint(jointId, &world, false);
	return joint != NULL ? joint->constraintForce : CD2_VEC_ZERO;
}

cdReal cd2Joint_GetConstraintTorque(cd2JointId jointId)
{
	cd2World* world = NULL;
	cd2Joint* joint = cd2LookupJoint(jointId, &world, false);
	return joint != NULL ? joint->constraintTorque : CD_R(0.0);
}

static bool cd2HasConstraintTuning(cd2JointType type)
{
	return type == CD2_DISTANCE_JOINT || type == CD2_PRISMATIC_JOINT || type == CD2_REVOLUTE_JOINT ||
		   type == CD2_WELD_JOINT || type == CD2_WHEEL_JOINT;
}

void cd2Joint_SetConstraintTuning(cd2JointId jointId, cdReal hertz, cdReal dampingRatio)
{
	cd2World* world = NULL;
	cd2Joint* joint = cd2LookupJoint(jointId, &world, true);
	if (joint == NULL)
	{
		return;
	}
	if (!cd2HasConstraintTuning(joint->type) || !cd2NonNeg(hertz) || !cd2NonNeg(dampingRatio))
	{
		CD2_REFUSE("cd2Joint_SetConstraintTuning: a motor, mouse or filter joint, or not numbers >= 0");
		return;
	}
	joint->data.constraintHertz = hertz;
	joint->data.constraintDampingRatio = dampingRatio;
}

cdReal cd2Joint_GetConstraintHertz(cd2JointId jointId)
{
	cd2World* world = NULL;
	cd2Joint* joint = cd2LookupJoint(jointId, &world, false);
	return joint != NULL ? joint->data.constraintHertz : CD_R(0.0);
}

cdReal cd2Joint_GetConstraintDampingRatio(cd2JointId jointId)
{
	cd2World* world = NULL;
	cd2Joint* joint = cd2LookupJoint(jointId, &world, false);
	return joint != NULL ? joint->data.constraintDampingRatio : CD_R(0.0);
}

void cd2Joint_SetForceThreshold(cd2JointId jointId, cdReal force)
{
	cd2World* world = NULL;
	cd2Joint* joint = cd2LookupJoint(jointId, &world, true);
	if (joint == NULL)
	{
		return;
	}
	if (joint->type == CD2_FILTER_JOINT || !cd2ValidThresholds(force, CD_R(0.0)))
	{
		CD2_REFUSE("cd2Joint_SetForceThreshold: a filter joint, or not a number >= 0");
		return;
	}
	joint->forceThreshold = force;
}

cdReal cd2Joint_GetForceThreshold(cd2JointId jointId)
{
	cd2World* world = NULL;
	cd2Joint* joint = cd2LookupJoint(jointId, &world, false);
	return joint != NULL ? joint->forceThreshold : CD_R(0.0);
}

void cd2Joint_SetTorqueThreshold(cd2JointId jointId, cdReal torque)
{
	cd2World* world = NULL;
	cd2Joint* joint = cd2LookupJoint(jointId, &world, true);
	if (joint == NULL)
	{
		return;
	}
	if (joint->type == CD2_FILTER_JOINT || !cd2ValidThresholds(CD_R(0.0), torque))
	{
		CD2_REFUSE("cd2Joint_SetTorqueThreshold: a filter joint, or not a number >= 0");
		return;
	}
	joint->torqueThreshold = torque;
}

cdReal cd2Joint_GetTorqueThreshold(cd2JointId jointId)
{
	cd2World* world = NULL;
	cd2Joint* joint = cd2LookupJoint(jointId, &world, false);
	return joint != NULL ? joint->torqueThreshold : CD_R(0.0);
}

void* cd2Joint_GetUserData(cd2JointId jointId)
{
	cd2World* world = NULL;
	cd2Joint* joint = cd2LookupJoint(jointId, &world, false);
	return joint != NULL ? joint->userData : NULL;
}

void cd2Joint_SetUserData(cd2JointId jointId, void* userData)
{
	cd2World* world = NULL;
	cd2Joint* joint = cd2LookupJoint(jointId, &world, false);
	if (joint != NULL)
	{
		joint->userData = userData;
	}
}

void cd2Joint_WakeBodies(cd2JointId jointId)
{
	cd2World* world = NULL;
	cd2Joint* joint = cd2LookupJoint(jointId, &world, true);
	if (joint != NULL)
	{
		cd2WakeBody(world, joint->bodyA);
		cd2WakeBody(world, joint->bodyB);
	}
}

/* A joint of the given type for a setter (wakes its bodies), or NULL with a refusal. */
static cd2Joint* cd2JointForSet(cd2JointId jointId, cd2JointType type, bool valid)
{
	cd2World* world = NULL;
	cd2Joint* joint = cd2LookupJoint(jointId, &world, true);
	if (joint == NULL)
	{
		return NULL;
	}
	if (joint->type != type || !valid)
	{
		CD2_REFUSE("joint setter: wrong joint type or NaN/Inf/negative value");
		return NULL;
	}
	cd2WakeBody(world, joint->bodyA);
	cd2WakeBody(world, joint->bodyB);
	return joint;
}

/* The bodies of the setters shared by the typed ones (cd2RevoluteJoint_...) and the generic ones
 * (cd2Joint_...); `joint` is NULL when the setter refused. Turning a motor or a limit on or off
 * drops its accumulated impulse: warm starting must not keep a removed constraint. */
static void cd2ApplyEnableMotor(cd2Joint* joint, bool flag)
{
	if (joint != NULL)
	{
		if (joint->data.enableMotor != flag)
		{
			joint->data.motorImpulse = CD_R(0.0);
		}
		joint->data.enableMotor = flag;
	}
}

static void cd2ApplyEnableLimit(cd2Joint* joint, bool flag)
{
	if (joint != NULL)
	{
		if (joint->data.enableLimit != flag)
		{
			joint->data.lowerImpulse = CD_R(0.0);
			joint->data.upperImpulse = CD_R(0.0);
		}
		joint->data.enableLimit = flag;
	}
}

/* A revolute joint's limits are angles, kept within [-pi, pi]. */
static void cd2ApplyLimits(cd2Joint* joint, cdReal lower, cdReal upper)
{
	if (joint->type == CD2_REVOLUTE_JOINT)
	{
		lower = cdClamp(lower, -CD_PI, CD_PI);
		upper = cdClamp(upper, -CD_PI, CD_PI);
	}
	joint->data.lower = lower;
	joint->data.upper = upper;
}

void cd2RevoluteJoint_EnableMotor(cd2JointId jointId, bool flag)
{
	cd2ApplyEnableMotor(cd2JointForSet(jointId, CD2_REVOLUTE_JOINT, true), flag);
}

void cd2RevoluteJoint_SetMotorSpeed(cd2JointId jointId, cdReal motorSpeed)
{
	cd2Joint* joint = cd2JointForSet(jointId, CD2_REVOLUTE_JOINT, cd2Finite(motorSpeed));
	if (joint != NULL)
	{
		joint->data.motorSpeed = motorSpeed;
	}
}

void cd2RevoluteJoint_SetMaxMotorTorque(cd2JointId jointId, cdReal torque)
{
	cd2Joint* joint = cd2JointForSet(jointId, CD2_REVOLUTE_JOINT, cd2NonNeg(torque));
	if (joint != NULL)
	{
		joint->data.maxMotorForce = torque;
	}
}

void cd2RevoluteJoint_EnableLimit(cd2JointId jointId, bool flag)
{
	cd2ApplyEnableLimit(cd2JointForSet(jointId, CD2_REVOLUTE_JOINT, true), flag);
}

void cd2RevoluteJoint_SetLimits(cd2JointId jointId, cdReal lower, cdReal upper)
{
	cd2Joint* joint =
		cd2JointForSet(jointId, CD2_REVOLUTE_JOINT, cd2Finite(lower) && cd2Finite(upper) && lower <= upper);
	if (joint != NULL)
	{
		cd2ApplyLimits(joint, lower, upper);
	}
}

cdReal cd2RevoluteJoint_GetAngle(cd2JointId jointId)
{
	cd2World* world = NULL;
	cd2Joint* joint = cd2LookupJoint(jointId, &world, false);
	if (joint == NULL || joint->type != CD2_REVOLUTE_JOINT)
	{
		return CD_R(0.0);
	}
	cd2Rot qA = world->bodies.data[joint->bodyA].transform.q,
		   qB = world->bodies.data[joint->bodyB].transform.q;
	cdReal angle = cd2RotGetAngle(cd2InvMulRot(qA, qB)) - joint->data.referenceAngle;
	while (angle > CD_PI)
	{
		angle -= CD_R(2.0) * CD_PI;
	}
	while (angle < -CD_PI)
	{
		angle += CD_R(2.0) * CD_PI;
	}
	return angle;
}

void cd2MouseJoint_SetTarget(cd2JointId jointId, cd2Vec target)
{
	cd2Joint* joint = cd2JointForSet(jointId, CD2_MOUSE_JOINT, cd2IsValidVec(target));
	if (joint != NULL)
	{
		joint->data.target = target;
	}
}

void cd2MotorJoint_SetLinearOffset(cd2JointId jointId, cd2Vec linearOffset)
{
	cd2Joint* joint = cd2JointForSet(jointId, CD2_MOTOR_JOINT, cd2IsValidVec(linearOffset));
	if (joint != NULL)
	{
		joint->data.linearOffset = linearOffset;
	}
}

void cd2MotorJoint_SetAngularOffset(cd2JointId jointId, cdReal angularOffset)
{
	cd2Joint* joint = cd2JointForSet(jointId, CD2_MOTOR_JOINT, cd2Finite(angularOffset));
	if (joint != NULL)
	{
		joint->data.angularOffset = angularOffset;
	}
}

void cd2DistanceJoint_SetLength(cd2JointId jointId, cdReal length)
{
	cd2Joint* joint = cd2JointForSet(jointId, CD2_DISTANCE_JOINT, cd2NonNeg(length));
	if (joint != NULL)
	{
		joint->data.length = cdMax(length, CD_LINEAR_SLOP);
	}
}

cdReal cd2DistanceJoint_GetCurrentLength(cd2JointId jointId)
{
	cd2World* world = NULL;
	cd2Joint* joint = cd2LookupJoint(jointId, &world, false);
	if (joint == NULL || joint->type != CD2_DISTANCE_JOINT)
	{
		return CD_R(0.0);
	}
	cd2Vec pA = cd2TransformPoint(world->bodies.data[joint->bodyA].transform, joint->data.localAnchorA);
	cd2Vec pB = cd2TransformPoint(world->bodies.data[joint->bodyB].transform, joint->data.localAnchorB);
	return cd2VecDistance(pA, pB);
}

void cd2DistanceJoint_SetLengthRange(cd2JointId jointId, cdReal minLength, cdReal maxLength)
{
	cd2Joint* joint =
		cd2JointForSet(jointId, CD2_DISTANCE_JOINT,
					   cd2NonNeg(minLength) && !(maxLength != maxLength) && minLength <= maxLength);
	if (joint != NULL)
	{
		joint->data.minLength = minLength;
		joint->data.maxLength = maxLength;
	}
}

/* A joint of one of the kinds that have springs, motors or limits, for a setter. */
static cd2Joint* cd2JointForOption(cd2JointId jointId, bool valid, bool allowWeld)
{
	cd2World* world = NULL;
	cd2Joint* joint = cd2LookupJoint(jointId, &world, true);
	if (joint == NULL)
	{
		return NULL;
	}
	bool kind = joint->type == CD2_DISTANCE_JOINT || joint->type == CD2_REVOLUTE_JOINT ||
				joint->type == CD2_PRISMATIC_JOINT || joint->type == CD2_WHEEL_JOINT ||
				(allowWeld && joint->type == CD2_WELD_JOINT);
	if (!kind || !valid)
	{
		CD2_REFUSE("joint setter: this joint kind has no such option, or a NaN/Inf/negative value");
		return NULL;
	}
	cd2WakeBody(world, joint->bodyA);
	cd2WakeBody(world, joint->bodyB);
	return joint;
}

void cd2Joint_EnableSpring(cd2JointId jointId, bool flag)
{
	cd2Joint* joint = cd2JointForOption(jointId, true, false);
	if (joint != NULL)
	{
		if (joint->data.enableSpring != flag)
		{
			joint->data.springImpulse = CD_R(0.0); /* warm starting must not keep a removed spring */
		}
		joint->data.enableSpring = flag;
	}
}

void cd2Joint_SetSpringHertz(cd2JointId jointId, cdReal hertz)
{
	cd2Joint* joint = cd2JointForOption(jointId, cd2NonNeg(hertz), true);
	if (joint != NULL)
	{
		joint->data.hertz = hertz;
	}
}

void cd2Joint_SetSpringDampingRatio(cd2JointId jointId, cdReal dampingRatio)
{
	cd2Joint* joint = cd2JointForOption(jointId, cd2NonNeg(dampingRatio), true);
	if (joint != NULL)
	{
		joint->data.dampingRatio = dampingRatio;
	}
}

void cd2Joint_EnableMotor(cd2JointId jointId, bool flag)
{
	cd2ApplyEnableMotor(cd2JointForOption(jointId, true, false), flag);
}

void cd2Joint_SetMotorSpeed(cd2JointId jointId, cdReal motorSpeed)
{
	cd2Joint* joint = cd2JointForOption(jointId, cd2Finite(motorSpeed), false);
	if (joint != NULL)
	{
		joint->data.motorSpeed = motorSpeed;
	}
}

void cd2Joint_SetMaxMotor(cd2JointId jointId, cdReal maxForceOrTorque)
{
	cd2Joint* joint = cd2JointForOption(jointId, cd2NonNeg(maxForceOrTorque), false);
	if (joint != NULL)
	{
		joint->data.maxMotorForce = maxForceOrTorque;
	}
}

void cd2Joint_EnableLimit(cd2JointId jointId, bool flag)
{
	cd2ApplyEnableLimit(cd2JointForOption(jointId, true, false), flag);
}

void cd2Joint_SetLimits(cd2JointId jointId, cdReal lower, cdReal upper)
{
	cd2Joint* joint =
		cd2JointForOption(jointId, cd2Finite(lower) && cd2Finite(upper) && lower <= upper, false);
	if (joint == NULL)
	{
		return;
	}
	if (joint->type == CD2_DISTANCE_JOINT)
	{
		CD2_REFUSE("cd2Joint_SetLimits: use cd2DistanceJoint_SetLengthRange for distance joints");
		return;
	}
	cd2ApplyLimits(joint, lower, upper);
}

cdReal cd2Joint_GetTranslation(cd2JointId jointId)
{
	cd2World* world = NULL;
	cd2Joint* joint = cd2LookupJoint(jointId, &world, false);
	if (joint == NULL || (joint->type != CD2_PRISMATIC_JOINT && joint->type != CD2_WHEEL_JOINT))
	{
		return CD_R(0.0);
	}
	const cd2Body* a = world->bodies.data + joint->bodyA;
	const cd2Body* b = world->bodies.data + joint->bodyB;
	cd2Vec pA = cd2TransformPoint(a->transform, joint->data.localAnchorA);
	cd2Vec pB = cd2TransformPoint(b->transform, joint->data.localAnchorB);
	return cd2Dot(cd2RotateVector(a->transform.q, joint->data.localAxisA), cd2Sub(pB, pA));
}

/* ---- solver dispatch ----------------------------------------------------------------------------- */
static const cd2SolverBody s_jointStaticBody = {{CD_R(0.0), CD_R(0.0)}, CD_R(0.0), {CD_R(0.0), CD_R(0.0)},
												{CD_R(1.0), CD_R(0.0)}, CD_R(0.0), CD_R(0.0)};

/* The solver's view of a joint; an immovable body is a zero-mass copy in the caller's scratch
 * (written by the solve, never shared between threads). */
static inline void cd2MakeArgs(const cd2StepContext* context, const cd2JointRef* ref,
							   cd2JointSolverArgs* args, cd2SolverBody* scratchA, cd2SolverBody* scratchB)
{
	args->data = ref->data;
	if (ref->indexA >= 0)
	{
		args->a = context->bodies + ref->indexA;
	}
	else
	{
		*scratchA = s_jointStaticBody;
		args->a = scratchA;
	}
	if (ref->indexB >= 0)
	{
		args->b = context->bodies + ref->indexB;
	}
	else
	{
		*scratchB = s_jointStaticBody;
		args->b = scratchB;
	}
	args->context = context;
}

/* How many joints ahead the joint loops prefetch the hot part of the data (its first two cache lines). */
#define CD2_JOINT_PREFETCH_AHEAD 4

static inline void cd2PrefetchJoint(const cd2StepContext* context, int i, int end)
{
	if (i + CD2_JOINT_PREFETCH_AHEAD < end)
	{
		const char* p = (const char*)context->jointRefs[i + CD2_JOINT_PREFETCH_AHEAD].data;
		CD2_PREFETCH(p);
		CD2_PREFETCH(p + 64);
	}
}

static cdReal cd2UnwindAngle(cdReal angle)
{
	if (angle < -CD_PI)
	{
		return angle + CD_R(2.0) * CD_PI;
	}
	if (angle > CD_PI)
	{
		return angle - CD_R(2.0) * CD_PI;
	}
	return angle;
}

bool cd2PrepareJoints(cd2World* world, cd2StepContext* context)
{
	if (context->jointCount == 0)
	{
		return true;
	}
	context->jointRefs = (cd2JointRef*)cdArena_AllocUncleared(&world->arena, (size_t)context->jointCount *
																				 sizeof(cd2JointRef));
	/* (jointIndexOrder: set by the colouring, see cd2StepContext.) */
	return context->jointRefs != NULL && context->jointIndexOrder != NULL;
}

void cd2PrepareJointRange(cd2World* world, cd2StepContext* context, int start, int end)
{
	cd2SolverBody scratchA, scratchB;
	for (int k = start; k < end; ++k)
	{
		int i = context->jointIndexOrder[k];
		int index = context->joints[i];
		cd2Joint* joint = world->joints.data + index;
		const cd2Body* a = world->bodies.data + joint->bodyA;
		const cd2Body* b = world->bodies.data + joint->bodyB;
		cd2JointRef* ref = context->jointRefs + i;
		ref->data = &joint->data;
		ref->type = joint->type;
		ref->indexA = a->solverIndex;
		ref->indexB = b->solverIndex;
		cd2JointData* d = &joint->data;
		if (joint->type == CD2_MOTOR_JOINT)
		{
			d->localAnchorA = d->linearOffset;
			d->localAnchorB = CD2_VEC_ZERO;
		}
		d->anchorA = cd2RotateVector(a->transform.q, cd2Sub(d->localAnchorA, a->localCenter));
		d->anchorB = cd2RotateVector(b->transform.q, cd2Sub(d->localAnchorB, b->localCenter));
		d->deltaCenter = cd2Sub(b->center, a->center);
		d->deltaAngle =
			cd2UnwindAngle(cd2RotGetAngle(cd2InvMulRot(a->transform.q, b->transform.q)) - d->referenceAngle);
		d->jointSoftness = context->jointSoftness;
		if (d->constraintHertz > CD_R(0.0) || d->constraintDampingRatio > CD_R(0.0))
		{
			/* The joint's own tuning, capped like the world's at a quarter of the sub-step rate. */
			cdReal hertz = d->constraintHertz > CD_R(0.0) ? d->constraintHertz : world->jointHertz;
			cdReal ratio =
				d->constraintDampingRatio > CD_R(0.0) ? d->constraintDampingRatio : world->jointDampingRatio;
			d->jointSoftness = cd2MakeSoft(cdMin(hertz, CD_R(0.25) * context->inv_h), ratio, context->h);
		}
		if (joint->type == CD2_PRISMATIC_JOINT || joint->type == CD2_WHEEL_JOINT)
		{
			d->axisA = cd2RotateVector(a->transform.q, d->localAxisA);
		}
		if (joint->type == CD2_MOUSE_JOINT)
		{
			d->deltaCenter = cd2Sub(b->center, d->target);
		}
		cd2JointSolverArgs args;
		cd2MakeArgs(context, ref, &args, &scratchA, &scratchB);
		switch (joint->type)
		{
			case CD2_DISTANCE_JOINT:
				cd2PrepareDistanceJoint(&args);
				break;
			case CD2_REVOLUTE_JOINT:
				cd2PrepareRevoluteJoint(&args);
				break;
			case CD2_WELD_JOINT:
				cd2PrepareWeldJoint(&args);
				break;
			case CD2_MOUSE_JOINT:
				cd2PrepareMouseJoint(&args);
				break;
			case CD2_MOTOR_JOINT:
				cd2PrepareMotorJoint(&args);
				break;
			case CD2_PRISMATIC_JOINT:
				cd2PreparePrismaticJoint(&args);
				break;
			case CD2_WHEEL_JOINT:
				cd2PrepareWheelJoint(&args);
				break;
			case CD2_FILTER_JOINT:
				break;
		}
	}
}

/* The factor (at most 1) that keeps the velocity change of one body, by `linear` times invMass and
 * `angular` times invInertia, within twice the speed caps. */
static inline cdReal cd2WarmStartScale(cd2Vec linear, cdReal angular, const cd2SolverBody* body,
									   cdReal maxLinear, cdReal maxAngular, cdReal scale)
{
	cdReal dv2 = body->invMass * body->invMass * cd2Dot(linear, linear);
	cdReal dw = body->invInertia * cdAbs(angular);
	if (dv2 > CD_R(4.0) * maxLinear * maxLinear)
	{
		scale = cdMin(scale, CD_R(2.0) * maxLinear / cdSqrt(dv2));
	}
	if (dw > CD_R(2.0) * maxAngular)
	{
		scale = cdMin(scale, CD_R(2.0) * maxAngular / dw);
	}
	return scale;
}

/* Warm starting is linear in the stored impulses, so a joint whose impulses would change a body's
 * velocity by more than twice the speed caps (no solve can need more: velocities are capped on
 * both sides of it) has them scaled down to that before they are applied. Rigid joints that cannot
 * all hold (bodies pulled apart by kinematic ones, a light body on a lever arm of a kilometre,
 * where float round-off of the effective mass feeds back) otherwise grow their impulses a
 * hundredfold per sub-step until they overflow. The check is on the impulse, not on the resulting
 * velocities: one pass, nothing to undo. NaN impulses fail every comparison and stay as they are,
 * as they would without the cap. */
void cd2WarmStartJoints(cd2World* world, cd2StepContext* context, int start, int end)
{
	(void)world;
	cd2SolverBody scratchA, scratchB;
	cdReal maxLinear = context->maxLinearVelocity;
	cdReal maxAngular = CD2_MAX_ROTATION * context->inv_h;
	for (int i = start; i < end; ++i)
	{
		cd2PrefetchJoint(context, i, end);
		const cd2JointRef* ref = context->jointRefs + i;
		cd2JointSolverArgs args;
		cd2MakeArgs(context, ref, &args, &scratchA, &scratchB);
		cd2JointImpulse p;
		switch (ref->type)
		{
			case CD2_DISTANCE_JOINT:
				p = cd2WarmStartDistanceJoint(&args);
				break;
			case CD2_REVOLUTE_JOINT:
				p = cd2WarmStartRevoluteJoint(&args);
				break;
			case CD2_WELD_JOINT:
				p = cd2WarmStartWeldJoint(&args);
				break;
			case CD2_MOUSE_JOINT:
				p = cd2WarmStartMouseJoint(&args);
				break;
			case CD2_MOTOR_JOINT:
				p = cd2WarmStartMotorJoint(&args);
				break;
			case CD2_PRISMATIC_JOINT:
				p = cd2WarmStartPrismaticJoint(&args);
				break;
			case CD2_WHEEL_JOINT:
				p = cd2WarmStartWheelJoint(&args);
				break;
			default:
				continue;
		}
		cd2SolverBody* a = args.a;
		cd2SolverBody* b = args.b;
		cdReal scale = cd2WarmStartScale(p.linearA, p.angularA, a, maxLinear, maxAngular, CD_R(1.0));
		scale = cd2WarmStartScale(p.linearB, p.angularB, b, maxLinear, maxAngular, scale);
		if (scale < CD_R(1.0))
		{
			cd2JointData* d = args.data;
			d->linearImpulse = cd2Scale(scale, d->linearImpulse);
			d->impulse *= scale;
			d->angularImpulse *= scale;
			d->springImpulse *= scale;
			d->motorImpulse *= scale;
			d->lowerImpulse *= scale;
			d->upperImpulse *= scale;
			p.linearA = cd2Scale(scale, p.linearA);
			p.linearB = cd2Scale(scale, p.linearB);
			p.angularA *= scale;
			p.angularB *= scale;
		}
		a->linearVelocity = cd2MulSub(a->linearVelocity, a->invMass, p.linearA);
		a->angularVelocity -= a->invInertia * p.angularA;
		b->linearVelocity = cd2MulAdd(b->linearVelocity, b->invMass, p.linearB);
		b->angularVelocity += b->invInertia * p.angularB;
	}
}

void cd2SolveJoints(cd2World* world, cd2StepContext* context, int start, int end, bool useBias)
{
	(void)world;
	cd2SolverBody scratchA, scratchB;
	for (int i = start; i < end; ++i)
	{
		cd2PrefetchJoint(context, i, end);
		const cd2JointRef* ref = context->jointRefs + i;
		cd2JointSolverArgs args;
		cd2MakeArgs(context, ref, &args, &scratchA, &scratchB);
		switch (ref->type)
		{
			case CD2_DISTANCE_JOINT:
				cd2SolveDistanceJoint(&args, useBias);
				break;
			case CD2_REVOLUTE_JOINT:
				cd2SolveRevoluteJoint(&args, useBias);
				break;
			case CD2_WELD_JOINT:
				cd2SolveWeldJoint(&args, useBias);
				break;
			case CD2_MOUSE_JOINT:
				cd2SolveMouseJoint(&args, useBias);
				break;
			case CD2_MOTOR_JOINT:
				cd2SolveMotorJoint(&args, useBias);
				break;
			case CD2_PRISMATIC_JOINT:
				cd2SolvePrismaticJoint(&args, useBias);
				break;
			case CD2_WHEEL_JOINT:
				cd2SolveWheelJoint(&args, useBias);
				break;
			case CD2_FILTER_JOINT:
				break;
		}
	}
}

void cd2StoreJointReactions(cd2World* world, cd2StepContext* context, int start, int end)
{
	cdReal inv_h = context->inv_h;
	for (int i = start; i < end; ++i)
	{
		cd2Joint* joint = world->joints.data + context->joints[i];
		const cd2JointData* d = &joint->data;
		cd2Vec force = CD2_VEC_ZERO;
		cdReal torque = CD_R(0.0);
		switch (joint->type)
		{
			case CD2_DISTANCE_JOINT:
				force = cd2Scale(d->impulse + d->lowerImpulse - d->upperImpulse + d->motorImpulse, d->axisA);
				break;
			case CD2_REVOLUTE_JOINT:
				force = d->linearImpulse;
				torque = d->springImpulse + d->motorImpulse + d->lowerImpulse - d->upperImpulse;
				break;
			case CD2_WELD_JOINT:
			case CD2_MOTOR_JOINT:
				force = d->linearImpulse;
				torque = d->angularImpulse;
				break;
			case CD2_MOUSE_JOINT:
				force = d->linearImpulse;
				break;
			case CD2_PRISMATIC_JOINT:
			{
				cdReal axial = d->springImpulse + d->motorImpulse + d->lowerImpulse - d->upperImpulse;
				force =
					cd2Add(cd2Scale(d->linearImpulse.x, cd2LeftPerp(d->axisA)), cd2Scale(axial, d->axisA));
				torque = d->linearImpulse.y;
				break;
			}
			case CD2_WHEEL_JOINT:
			{
				cdReal axial = d->springImpulse + d->lowerImpulse - d->upperImpulse;
				force = cd2Add(cd2Scale(d->impulse, cd2LeftPerp(d->axisA)), cd2Scale(axial, d->axisA));
				torque = d->motorImpulse;
				break;
			}
			case CD2_FILTER_JOINT:
				break;
		}
		joint->constraintForce = cd2Scale(inv_h, force);
		joint->constraintTorque = inv_h * torque;
	}
}
