/* collide: the 2D rigid-body world. Bodies carry shapes; each step finds the touching pairs (the
 * broadphase tree), computes their manifolds (cd2Collide, warm-started by feature id) and moves
 * the bodies with a sub-stepped soft-constraint solver (see docs/DYNAMICS.md).
 *
 * Objects are reached through small value ids (index, world, generation). A destroyed object's id
 * is stale: cd2Body_IsValid and friends return false for it, and every other function given a
 * stale id asserts in debug builds and does nothing (returns zero / a null id) in release builds.
 * Definitions are plain structs: start from cd2Default*Def() so that new fields keep defaults.
 * NaN/Inf or negative sizes in a definition or a setter are refused: the call reports through the
 * assert hook (cdSetAssertFcn) and returns a null id or changes nothing.
 * The world is locked during cd2World_Step: calls that change it from a callback are refused. */
#ifndef COLLIDE_WORLD2_H
#define COLLIDE_WORLD2_H

#include "collide/broad.h"
#include "collide/cast.h"
#include "collide/chain2.h"
#include "collide/manifold2.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- ids -------------------------------------------------------------------------------------
 * index1 is the slot + 1, so a zero-filled id is null. */
typedef struct cd2WorldId
{
	uint16_t index1;
	uint16_t generation;
} cd2WorldId;

typedef struct cd2BodyId
{
	int32_t index1;
	uint16_t world0;
	uint32_t generation;
} cd2BodyId;

typedef struct cd2ShapeId
{
	int32_t index1;
	uint16_t world0;
	uint32_t generation;
} cd2ShapeId;

typedef struct cd2JointId
{
	int32_t index1;
	uint16_t world0;
	uint32_t generation;
} cd2JointId;

typedef struct cd2ChainId
{
	int32_t index1;
	uint16_t world0;
	uint32_t generation;
} cd2ChainId;

#define CD2_NULL_WORLD_ID ((cd2WorldId){0, 0})
#define CD2_NULL_BODY_ID ((cd2BodyId){0, 0, 0})
#define CD2_NULL_SHAPE_ID ((cd2ShapeId){0, 0, 0})
#define CD2_NULL_JOINT_ID ((cd2JointId){0, 0, 0})
#define CD2_NULL_CHAIN_ID ((cd2ChainId){0, 0, 0})

/* Most worlds alive at once. */
#define CD2_MAX_WORLDS 128

static inline bool cd2IsNullBodyId(cd2BodyId id)
{
	return id.index1 == 0;
}
static inline bool cd2IsNullShapeId(cd2ShapeId id)
{
	return id.index1 == 0;
}
static inline bool cd2IsNullJointId(cd2JointId id)
{
	return id.index1 == 0;
}
static inline bool cd2BodyIdEqual(cd2BodyId a, cd2BodyId b)
{
	return a.index1 == b.index1 && a.world0 == b.world0 && a.generation == b.generation;
}
static inline bool cd2ShapeIdEqual(cd2ShapeId a, cd2ShapeId b)
{
	return a.index1 == b.index1 && a.world0 == b.world0 && a.generation == b.generation;
}

/* ---- task system --------------------------------------------------------------------------------
 * With workerCount > 1 the step runs some of its stages (integration, the contact solver colour by
 * colour, finalizing the bodies) as tasks over index ranges. The solver is one task per step of
 * workerCount - 1 items: each item works through the solver's stages together with the stepping
 * thread, and may wait (spinning, then yielding) for work another running item has taken, never for
 * an item that has not started; run the items at the same time to gain speed (any order and any
 * delay are correct). A part of the step with little work (a small world's solver, a few hundred
 * contacts to update) is not handed out: it runs on the calling thread, where it costs less than
 * the handing out would. Give enqueueTask and finishTask to let
 * your own job system run them, or neither for the built-in pool (workerCount - 1 threads, started
 * by cd2CreateWorld and joined by cd2DestroyWorld; none in WebAssembly builds).
 * enqueueTask must make task(start, end, workerIndex, taskContext) run over ranges that cover
 * [0, itemCount) exactly once, each at least minRange items long unless it is the last, on any
 * threads, with workerIndex < workerCount distinct among the calls running at the same moment; it
 * returns a handle that the step passes to finishTask, which returns once every range is done (a
 * NULL handle means the task already ran, and finishTask is not called). The results are the same
 * bits for any worker count and any split. */
typedef void cdTaskCallback(int startIndex, int endIndex, uint32_t workerIndex, void* taskContext);
typedef void* cdEnqueueTaskCallback(cdTaskCallback* task, int itemCount, int minRange, void* taskContext,
									void* userContext);
typedef void cdFinishTaskCallback(void* userTask, void* userContext);

/* ---- world ---------------------------------------------------------------------------------- */
typedef struct cd2WorldDef
{
	cd2Vec gravity;				   /* m/s^2, default (0, -10) */
	cdReal restitutionThreshold;   /* approach speeds below this do not bounce (1 m/s) */
	cdReal hitEventThreshold;	   /* approach speed that makes a hit event (1 m/s) */
	cdReal contactHertz;		   /* contact stiffness (30 Hz, capped at an eighth of the sub-step rate) */
	cdReal contactDampingRatio;	   /* 10 */
	cdReal contactPushMaxVelocity; /* most speed at which overlap is pushed apart (3 m/s) */
	cdReal jointHertz;			   /* 60 (capped at a quarter of the sub-step rate) */
	cdReal jointDampingRatio;	   /* 2 */
	cdReal maximumLinearSpeed;	   /* 400 m/s (scaled by the length units) */
	cdReal lengthUnitsPerMeter;	   /* 0: keep cdGetLengthUnitsPerMeter(); else set it */
	/* Contact recycling (0.02 m, scaled by the length units; 0 turns it off): while two bodies in
	 * contact have moved less than this relative to each other (rotation counted at the bodies'
	 * extent) since their manifold was computed, the manifold's points stay attached to the bodies
	 * and only their separations are updated, instead of running the narrowphase again. Fast
	 * bodies and bullets are never recycled. Results are deterministic either way. */
	cdReal contactRecycleDistance;
	bool enableSleep;
	bool enableContinuous;
	int workerCount; /* 1: the step runs on the calling thread (see the task system above) */
	cdEnqueueTaskCallback* enqueueTask;
	cdFinishTaskCallback* finishTask;
	void* userTaskContext;
	void* userData;
} cd2WorldDef;

CD_API cd2WorldDef cd2DefaultWorldDef(void);

/* Returns CD2_NULL_WORLD_ID for a bad def (NaN gravity, negative hertz, ...) or when
 * CD2_MAX_WORLDS worlds exist or memory runs out. */
CD_API cd2WorldId cd2CreateWorld(const cd2WorldDef* def);
CD_API void cd2DestroyWorld(cd2WorldId worldId);
CD_API bool cd2World_IsValid(cd2WorldId worldId);

/* Advances by timeStep seconds (> 0, finite; 0 only updates contacts) in subStepCount sub-steps
 * (1 to CD2_MAX_SUB_STEPS; 4 is the usual choice). Events of the previous step are cleared at the
 * start. */
#define CD2_MAX_SUB_STEPS 1000
CD_API void cd2World_Step(cd2WorldId worldId, cdReal timeStep, int subStepCount);

CD_API void cd2World_SetGravity(cd2WorldId worldId, cd2Vec gravity);
CD_API cd2Vec cd2World_GetGravity(cd2WorldId worldId);
CD_API void cd2World_EnableSleeping(cd2WorldId worldId, bool flag);
CD_API void cd2World_EnableContinuous(cd2WorldId worldId, bool flag);
CD_API void* cd2World_GetUserData(cd2WorldId worldId);
CD_API void cd2World_SetUserData(cd2WorldId worldId, void* userData);

typedef struct cd2Counters
{
	int bodyCount, shapeCount, contactCount, touchingContactCount, jointCount, awakeBodyCount,
		islandCount; /* islandCount: sleeping islands */
} cd2Counters;

CD_API cd2Counters cd2World_GetCounters(cd2WorldId worldId);

/* Where the last step's time went: wall time on the stepping thread, in milliseconds, recorded
 * while profiling is on (cd2World_EnableProfiling; off by default: it reads the clock at every
 * stage). With workers, a stage's time includes waiting for the other workers to finish it. The
 * solve's fields from prepareConstraints to storeImpulses are summed over the sub-steps. */
typedef struct cd2Profile
{
	float step;				   /* the whole cd2World_Step */
	float rebuildTree;		   /* the broadphase tree, rebuilt where last step's moves grew it */
	float pairs;			   /* new pairs of the moved proxies, new contacts */
	float collide;			   /* manifolds and the contacts' begin/end of touch */
	float solve;			   /* everything below up to sleepIslands */
	float solverSetup;		   /* awake lists, colouring, solver bodies, wide layout */
	float prepareConstraints;  /* contact and joint constraints (and packing them four wide) */
	float integrateVelocities; /* per sub-step */
	float warmStart;
	float solveImpulses;	  /* with bias */
	float integratePositions; /* per sub-step */
	float relaxImpulses;	  /* without bias */
	float applyRestitution;
	float storeImpulses; /* impulses back into the contacts and joints */
	float finalize;		 /* transforms, sleep times, tight boxes of each body */
	float jointEvents;	 /* joints over their force or torque threshold */
	float refit;		 /* kinematic wakes, bullets, broadphase moves */
	float hitEvents;
	float sleepIslands;
	float sensors;
} cd2Profile;

CD_API void cd2World_EnableProfiling(cd2WorldId worldId, bool flag);
/* The last step's profile; all zero while profiling is off. */
CD_API cd2Profile cd2World_GetProfile(cd2WorldId worldId);

/* ---- bodies --------------------------------------------------------------------------------- */
typedef enum cd2BodyType
{
	CD_STATIC_BODY = 0,
	CD_KINEMATIC_BODY = 1,
	CD_DYNAMIC_BODY = 2
} cd2BodyType;

typedef struct cd2BodyDef
{
	cd2BodyType type;
	cd2Vec position; /* of the body origin */
	cd2Rot rotation;
	cd2Vec linearVelocity; /* of the centre of mass */
	cdReal angularVelocity;
	cdReal linearDamping;
	cdReal angularDamping;
	cdReal gravityScale;
	cdReal sleepThreshold; /* speed below which the body may sleep (0.05 m/s) */
	bool enableSleep;
	bool isAwake; /* false: made asleep, and stays asleep as shapes are added until touched */
	bool fixedRotation;
	bool isBullet;
	bool isEnabled;
	void* userData;
} cd2BodyDef;

CD_API cd2BodyDef cd2DefaultBodyDef(void);

/* Returns CD2_NULL_BODY_ID for a bad def (NaN, non-unit rotation, negative damping, unknown
 * type) or a locked world. */
CD_API cd2BodyId cd2CreateBody(cd2WorldId worldId, const cd2BodyDef* def);
/* Destroys the body, its shapes, chains, contacts and joints. */
CD_API void cd2DestroyBody(cd2BodyId bodyId);
CD_API bool cd2Body_IsValid(cd2BodyId bodyId);

CD_API cd2BodyType cd2Body_GetType(cd2BodyId bodyId);
CD_API void cd2Body_SetType(cd2BodyId bodyId, cd2BodyType type);
CD_API cd2Vec cd2Body_GetPosition(cd2BodyId bodyId);
CD_API cd2Rot cd2Body_GetRotation(cd2BodyId bodyId);
CD_API cd2Transform cd2Body_GetTransform(cd2BodyId bodyId);
/* Teleports the body (wakes it). */
CD_API void cd2Body_SetTransform(cd2BodyId bodyId, cd2Vec position, cd2Rot rotation);
CD_API cd2Vec cd2Body_GetLocalPoint(cd2BodyId bodyId, cd2Vec worldPoint);
CD_API cd2Vec cd2Body_GetWorldPoint(cd2BodyId bodyId, cd2Vec localPoint);
CD_API cd2Vec cd2Body_GetLocalVector(cd2BodyId bodyId, cd2Vec worldVector);
CD_API cd2Vec cd2Body_GetWorldVector(cd2BodyId bodyId, cd2Vec localVector);
CD_API cd2Vec cd2Body_GetWorldCenterOfMass(cd2BodyId bodyId);
CD_API cd2Vec cd2Body_GetLocalCenterOfMass(cd2BodyId bodyId);
CD_API cd2Vec cd2Body_GetLinearVelocity(cd2BodyId bodyId);
CD_API void cd2Body_SetLinearVelocity(cd2BodyId bodyId, cd2Vec velocity);
CD_API cdReal cd2Body_GetAngularVelocity(cd2BodyId bodyId);
CD_API void cd2Body_SetAngularVelocity(cd2BodyId bodyId, cdReal angularVelocity);
/* Forces act over the next step and are then cleared; impulses change the velocity at once.
 * wake: wake a sleeping body (otherwise a sleeping body ignores the call). */
CD_API void cd2Body_ApplyForce(cd2BodyId bodyId, cd2Vec force, cd2Vec worldPoint, bool wake);
CD_API void cd2Body_ApplyForceToCenter(cd2BodyId bodyId, cd2Vec force, bool wake);
CD_API void cd2Body_ApplyTorque(cd2BodyId bodyId, cdReal torque, bool wake);
CD_API void cd2Body_ApplyLinearImpulse(cd2BodyId bodyId, cd2Vec impulse, cd2Vec worldPoint, bool wake);
CD_API void cd2Body_ApplyLinearImpulseToCenter(cd2BodyId bodyId, cd2Vec impulse, bool wake);
CD_API void cd2Body_ApplyAngularImpulse(cd2BodyId bodyId, cdReal impulse, bool wake);
CD_API cdReal cd2Body_GetMass(cd2BodyId bodyId);
CD_API cdReal cd2Body_GetRotationalInertia(cd2BodyId bodyId); /* about the centre of mass */
CD_API cd2MassData cd2Body_GetMassData(cd2BodyId bodyId);
/* Overrides the mass from the shapes (until the next shape change with updateBodyMass or
 * cd2Body_ApplyMassFromShapes). Mass and inertia must be finite and >= 0. */
CD_API void cd2Body_SetMassData(cd2BodyId bodyId, cd2MassData massData);
CD_API void cd2Body_ApplyMassFromShapes(cd2BodyId bodyId);
CD_API cdReal cd2Body_GetLinearDamping(cd2BodyId bodyId);
CD_API void cd2Body_SetLinearDamping(cd2BodyId bodyId, cdReal linearDamping);
CD_API cdReal cd2Body_GetAngularDamping(cd2BodyId bodyId);
CD_API void cd2Body_SetAngularDamping(cd2BodyId bodyId, cdReal angularDamping);
CD_API cdReal cd2Body_GetGravityScale(cd2BodyId bodyId);
CD_API void cd2Body_SetGravityScale(cd2BodyId bodyId, cdReal gravityScale);
CD_API void cd2Body_SetFixedRotation(cd2BodyId bodyId, bool flag);
CD_API bool cd2Body_IsFixedRotation(cd2BodyId bodyId);
CD_API void cd2Body_SetBullet(cd2BodyId bodyId, bool flag);
CD_API bool cd2Body_IsBullet(cd2BodyId bodyId);
CD_API bool cd2Body_IsAwake(cd2BodyId bodyId);
/* Wakes the body's island, or puts it to sleep with its island. */
CD_API void cd2Body_SetAwake(cd2BodyId bodyId, bool awake);
CD_API void cd2Body_EnableSleep(cd2BodyId bodyId, bool enableSleep);
CD_API bool cd2Body_IsEnabled(cd2BodyId bodyId);
/* A disabled body keeps its shapes and joints but leaves the simulation (no contacts). */
CD_API void cd2Body_Disable(cd2BodyId bodyId);
CD_API void cd2Body_Enable(cd2BodyId bodyId);
CD_API void* cd2Body_GetUserData(cd2BodyId bodyId);
CD_API void cd2Body_SetUserData(cd2BodyId bodyId, void* userData);
CD_API cd2WorldId cd2Body_GetWorld(cd2BodyId bodyId);
CD_API int cd2Body_GetShapeCount(cd2BodyId bodyId);
/* Writes up to capacity shape ids; returns how many it wrote. */
CD_API int cd2Body_GetShapes(cd2BodyId bodyId, cd2ShapeId* shapeArray, int capacity);

/* ---- shapes --------------------------------------------------------------------------------- */
/* Two shapes collide when (a.categoryBits & b.maskBits) && (b.categoryBits & a.maskBits), unless
 * they share a non-zero groupIndex: positive always collides, negative never. */
typedef struct cd2Filter
{
	uint64_t categoryBits;
	uint64_t maskBits;
	int groupIndex;
} cd2Filter;

CD_API cd2Filter cd2DefaultFilter(void);

typedef struct cd2ShapeDef
{
	cdReal density;			  /* kg/m^2, default 1 */
	cdReal friction;		  /* Coulomb coefficient, default 0.6 */
	cdReal restitution;		  /* 0..1 (more is allowed), default 0 */
	cdReal rollingResistance; /* default 0 */
	cdReal tangentSpeed;	  /* conveyor belt speed along the surface (m/s), default 0 */
	cd2Filter filter;
	bool isSensor; /* no collision response; reports sensor events */
	bool enableSensorEvents;
	bool enableContactEvents; /* default true */
	bool enableHitEvents;	  /* default false */
	bool enablePreSolveEvents;
	void* userData;
} cd2ShapeDef;

CD_API cd2ShapeDef cd2DefaultShapeDef(void);

/* Geometry in the body frame. Each returns CD2_NULL_SHAPE_ID for invalid geometry (the shape
 * validators), a bad def (NaN, negative density or friction) or a locked world. The body's mass is
 * recomputed from its shapes. */
CD_API cd2ShapeId cd2CreateCircleShape(cd2BodyId bodyId, const cd2ShapeDef* def, const cd2Circle* circle);
CD_API cd2ShapeId cd2CreateCapsuleShape(cd2BodyId bodyId, const cd2ShapeDef* def, const cd2Capsule* capsule);
CD_API cd2ShapeId cd2CreatePolygonShape(cd2BodyId bodyId, const cd2ShapeDef* def, const cd2Polygon* polygon);
CD_API cd2ShapeId cd2CreateSegmentShape(cd2BodyId bodyId, const cd2ShapeDef* def, const cd2Segment* segment);
CD_API void cd2DestroyShape(cd2ShapeId shapeId, bool updateBodyMass);
CD_API bool cd2Shape_IsValid(cd2ShapeId shapeId);

/* The shape types of the world: the geometric ones plus one segment of a chain. */
typedef enum cd2WorldShapeType
{
	CD2_WORLD_SHAPE_CIRCLE,
	CD2_WORLD_SHAPE_CAPSULE,
	CD2_WORLD_SHAPE_POLYGON,
	CD2_WORLD_SHAPE_SEGMENT,
	CD2_WORLD_SHAPE_CHAIN_SEGMENT
} cd2WorldShapeType;

CD_API cd2WorldShapeType cd2Shape_GetType(cd2ShapeId shapeId);
CD_API cd2BodyId cd2Shape_GetBody(cd2ShapeId shapeId);
/* The shape as a tagged shape in world space (a chain segment as its segment). */
CD_API cd2Shape cd2Shape_GetWorldShape(cd2ShapeId shapeId);
CD_API cd2Aabb cd2Shape_GetAabb(cd2ShapeId shapeId);
CD_API bool cd2Shape_IsSensor(cd2ShapeId shapeId);
CD_API cdReal cd2Shape_GetDensity(cd2ShapeId shapeId);
CD_API void cd2Shape_SetDensity(cd2ShapeId shapeId, cdReal density, bool updateBodyMass);
CD_API cdReal cd2Shape_GetFriction(cd2ShapeId shapeId);
CD_API void cd2Shape_SetFriction(cd2ShapeId shapeId, cdReal friction);
CD_API cdReal cd2Shape_GetRestitution(cd2ShapeId shapeId);
CD_API void cd2Shape_SetRestitution(cd2ShapeId shapeId, cdReal restitution);
CD_API cd2Filter cd2Shape_GetFilter(cd2ShapeId shapeId);
/* Changes the filter; existing contacts are re-checked at the next step. */
CD_API void cd2Shape_SetFilter(cd2ShapeId shapeId, cd2Filter filter);
CD_API void* cd2Shape_GetUserData(cd2ShapeId shapeId);
CD_API void cd2Shape_SetUserData(cd2ShapeId shapeId, void* userData);
CD_API void cd2Shape_EnableSensorEvents(cd2ShapeId shapeId, bool flag);
CD_API void cd2Shape_EnableContactEvents(cd2ShapeId shapeId, bool flag);
CD_API void cd2Shape_EnableHitEvents(cd2ShapeId shapeId, bool flag);
CD_API void cd2Shape_EnablePreSolveEvents(cd2ShapeId shapeId, bool flag);

/* ---- chains: one-sided terrain (see chain2.h for the winding rule) -------------------------- */
typedef struct cd2ChainDef
{
	const cd2Vec* points; /* body frame, copied */
	int count;
	bool isLoop;
	cdReal friction;
	cdReal restitution;
	cd2Filter filter;
	bool enableSensorEvents;
	void* userData;
} cd2ChainDef;

CD_API cd2ChainDef cd2DefaultChainDef(void);
/* One shape per segment (type CD2_WORLD_SHAPE_CHAIN_SEGMENT). Returns CD2_NULL_CHAIN_ID for bad
 * points (the errors of chain2.h's cd2CreateChain, whose name this function cannot take: in C the
 * geometric chain builder already owns it). */
CD_API cd2ChainId cd2CreateChainShape(cd2BodyId bodyId, const cd2ChainDef* def);
CD_API void cd2DestroyChainShape(cd2ChainId chainId);
CD_API bool cd2ChainShape_IsValid(cd2ChainId chainId);
CD_API int cd2ChainShape_GetSegmentCount(cd2ChainId chainId);

/* ---- joints --------------------------------------------------------------------------------- */
typedef enum cd2JointType
{
	CD2_DISTANCE_JOINT,
	CD2_FILTER_JOINT,
	CD2_MOTOR_JOINT,
	CD2_MOUSE_JOINT,
	CD2_PRISMATIC_JOINT,
	CD2_REVOLUTE_JOINT,
	CD2_WELD_JOINT,
	CD2_WHEEL_JOINT
} cd2JointType;

typedef struct cd2DistanceJointDef
{
	cd2BodyId bodyIdA, bodyIdB;
	cd2Vec localAnchorA, localAnchorB; /* body frames */
	cdReal length;					   /* rest length (> 0) */
	bool enableSpring;				   /* soft length (hertz, dampingRatio); rigid otherwise */
	cdReal hertz, dampingRatio;
	bool enableLimit; /* keep the length in [minLength, maxLength] */
	cdReal minLength, maxLength;
	bool enableMotor;
	cdReal maxMotorForce, motorSpeed;
	cdReal constraintHertz, constraintDampingRatio; /* own softness; 0: the world's (jointHertz...) */
	cdReal forceThreshold, torqueThreshold;			/* joint events; 0: none (see cd2JointEvent) */
	bool collideConnected;
	void* userData;
} cd2DistanceJointDef;

typedef struct cd2FilterJointDef
{
	cd2BodyId bodyIdA, bodyIdB;
	void* userData;
} cd2FilterJointDef;

/* Drives B towards a target offset relative to A (linear and angular), with most force/torque. */
typedef struct cd2MotorJointDef
{
	cd2BodyId bodyIdA, bodyIdB;
	cd2Vec linearOffset; /* of B's origin in A's frame */
	cdReal angularOffset;
	cdReal maxForce, maxTorque;
	cdReal correctionFactor;				/* 0..1, default 0.3 */
	cdReal forceThreshold, torqueThreshold; /* joint events; 0: none (see cd2JointEvent) */
	bool collideConnected;
	void* userData;
} cd2MotorJointDef;

/* Pulls a point of B towards a world target with a soft spring (bodyIdA is a static ground). */
typedef struct cd2MouseJointDef
{
	cd2BodyId bodyIdA, bodyIdB;
	cd2Vec target; /* world; the anchor on B is the target at creation */
	cdReal hertz, dampingRatio, maxForce;
	cdReal forceThreshold, torqueThreshold; /* joint events; 0: none (see cd2JointEvent) */
	bool collideConnected;
	void* userData;
} cd2MouseJointDef;

typedef struct cd2PrismaticJointDef
{
	cd2BodyId bodyIdA, bodyIdB;
	cd2Vec localAnchorA, localAnchorB;
	cd2Vec localAxisA; /* unit, A's frame */
	cdReal referenceAngle;
	bool enableSpring;
	cdReal hertz, dampingRatio;
	bool enableLimit;
	cdReal lowerTranslation, upperTranslation;
	bool enableMotor;
	cdReal maxMotorForce, motorSpeed;
	cdReal constraintHertz, constraintDampingRatio; /* own softness; 0: the world's (jointHertz...) */
	cdReal forceThreshold, torqueThreshold;			/* joint events; 0: none (see cd2JointEvent) */
	bool collideConnected;
	void* userData;
} cd2PrismaticJointDef;

typedef struct cd2RevoluteJointDef
{
	cd2BodyId bodyIdA, bodyIdB;
	cd2Vec localAnchorA, localAnchorB;
	cdReal referenceAngle; /* angle B - angle A at rest */
	bool enableSpring;	   /* rotational spring towards the reference angle */
	cdReal hertz, dampingRatio;
	bool enableLimit;
	cdReal lowerAngle, upperAngle; /* radians, lower <= upper */
	bool enableMotor;
	cdReal maxMotorTorque, motorSpeed;
	cdReal constraintHertz, constraintDampingRatio; /* own softness; 0: the world's (jointHertz...) */
	cdReal forceThreshold, torqueThreshold;			/* joint events; 0: none (see cd2JointEvent) */
	bool collideConnected;
	void* userData;
} cd2RevoluteJointDef;

typedef struct cd2WeldJointDef
{
	cd2BodyId bodyIdA, bodyIdB;
	cd2Vec localAnchorA, localAnchorB;
	cdReal referenceAngle;
	cdReal linearHertz, angularHertz; /* 0: rigid */
	cdReal linearDampingRatio, angularDampingRatio;
	cdReal constraintHertz, constraintDampingRatio; /* own softness; 0: the world's (jointHertz...) */
	cdReal forceThreshold, torqueThreshold;			/* joint events; 0: none (see cd2JointEvent) */
	bool collideConnected;
	void* userData;
} cd2WeldJointDef;

typedef struct cd2WheelJointDef
{
	cd2BodyId bodyIdA, bodyIdB;
	cd2Vec localAnchorA, localAnchorB;
	cd2Vec localAxisA;
	bool enableSpring;
	cdReal hertz, dampingRatio;
	bool enableLimit;
	cdReal lowerTranslation, upperTranslation;
	bool enableMotor;
	cdReal maxMotorTorque, motorSpeed;
	cdReal constraintHertz, constraintDampingRatio; /* own softness; 0: the world's (jointHertz...) */
	cdReal forceThreshold, torqueThreshold;			/* joint events; 0: none (see cd2JointEvent) */
	bool collideConnected;
	void* userData;
} cd2WheelJointDef;

CD_API cd2DistanceJointDef cd2DefaultDistanceJointDef(void);
CD_API cd2FilterJointDef cd2DefaultFilterJointDef(void);
CD_API cd2MotorJointDef cd2DefaultMotorJointDef(void);
CD_API cd2MouseJointDef cd2DefaultMouseJointDef(void);
CD_API cd2PrismaticJointDef cd2DefaultPrismaticJointDef(void);
CD_API cd2RevoluteJointDef cd2DefaultRevoluteJointDef(void);
CD_API cd2WeldJointDef cd2DefaultWeldJointDef(void);
CD_API cd2WheelJointDef cd2DefaultWheelJointDef(void);

/* Each returns CD2_NULL_JOINT_ID for a bad def (stale body ids, the same body twice, NaN, ...). */
CD_API cd2JointId cd2CreateDistanceJoint(cd2WorldId worldId, const cd2DistanceJointDef* def);
CD_API cd2JointId cd2CreateFilterJoint(cd2WorldId worldId, const cd2FilterJointDef* def);
CD_API cd2JointId cd2CreateMotorJoint(cd2WorldId worldId, const cd2MotorJointDef* def);
CD_API cd2JointId cd2CreateMouseJoint(cd2WorldId worldId, const cd2MouseJointDef* def);
CD_API cd2JointId cd2CreatePrismaticJoint(cd2WorldId worldId, const cd2PrismaticJointDef* def);
CD_API cd2JointId cd2CreateRevoluteJoint(cd2WorldId worldId, const cd2RevoluteJointDef* def);
CD_API cd2JointId cd2CreateWeldJoint(cd2WorldId worldId, const cd2WeldJointDef* def);
CD_API cd2JointId cd2CreateWheelJoint(cd2WorldId worldId, const cd2WheelJointDef* def);
CD_API void cd2DestroyJoint(cd2JointId jointId);
CD_API bool cd2Joint_IsValid(cd2JointId jointId);
CD_API cd2JointType cd2Joint_GetType(cd2JointId jointId);
CD_API cd2BodyId cd2Joint_GetBodyA(cd2JointId jointId);
CD_API cd2BodyId cd2Joint_GetBodyB(cd2JointId jointId);
/* Reaction on B of the last step (N and N*m): the joint's accumulated impulse over the step time. */
CD_API cd2Vec cd2Joint_GetConstraintForce(cd2JointId jointId);
CD_API cdReal cd2Joint_GetConstraintTorque(cd2JointId jointId);
/* The softness of the joint's point, angle and length constraints (not of its springs): hertz and
 * damping ratio >= 0, each 0 for the world's jointHertz / jointDampingRatio. Distance, prismatic,
 * revolute, weld and wheel joints; refused for the others, which have their own tuning. */
CD_API void cd2Joint_SetConstraintTuning(cd2JointId jointId, cdReal hertz, cdReal dampingRatio);
CD_API cdReal cd2Joint_GetConstraintHertz(cd2JointId jointId);
CD_API cdReal cd2Joint_GetConstraintDampingRatio(cd2JointId jointId);
/* Thresholds of the joint events (>= 0; 0: none). Refused for a filter joint, which has no force. */
CD_API void cd2Joint_SetForceThreshold(cd2JointId jointId, cdReal force);
CD_API cdReal cd2Joint_GetForceThreshold(cd2JointId jointId);
CD_API void cd2Joint_SetTorqueThreshold(cd2JointId jointId, cdReal torque);
CD_API cdReal cd2Joint_GetTorqueThreshold(cd2JointId jointId);
CD_API void* cd2Joint_GetUserData(cd2JointId jointId);
CD_API void cd2Joint_SetUserData(cd2JointId jointId, void* userData);
CD_API void cd2Joint_WakeBodies(cd2JointId jointId);
CD_API void cd2RevoluteJoint_EnableMotor(cd2JointId jointId, bool flag);
CD_API void cd2RevoluteJoint_SetMotorSpeed(cd2JointId jointId, cdReal motorSpeed);
CD_API void cd2RevoluteJoint_SetMaxMotorTorque(cd2JointId jointId, cdReal torque);
CD_API void cd2RevoluteJoint_EnableLimit(cd2JointId jointId, bool flag);
CD_API void cd2RevoluteJoint_SetLimits(cd2JointId jointId, cdReal lower, cdReal upper);
CD_API cdReal cd2RevoluteJoint_GetAngle(cd2JointId jointId);
CD_API void cd2MouseJoint_SetTarget(cd2JointId jointId, cd2Vec target);
CD_API void cd2MotorJoint_SetLinearOffset(cd2JointId jointId, cd2Vec linearOffset);
CD_API void cd2MotorJoint_SetAngularOffset(cd2JointId jointId, cdReal angularOffset);
CD_API void cd2DistanceJoint_SetLength(cd2JointId jointId, cdReal length);
CD_API cdReal cd2DistanceJoint_GetCurrentLength(cd2JointId jointId);
CD_API void cd2DistanceJoint_SetLengthRange(cd2JointId jointId, cdReal minLength, cdReal maxLength);
/* Springs (distance, revolute, prismatic, wheel): on/off, stiffness and damping ratio. */
CD_API void cd2Joint_EnableSpring(cd2JointId jointId, bool flag);
CD_API void cd2Joint_SetSpringHertz(cd2JointId jointId, cdReal hertz);
CD_API void cd2Joint_SetSpringDampingRatio(cd2JointId jointId, cdReal dampingRatio);
/* Motors (distance, revolute, prismatic, wheel): maxMotor is a force (distance, prismatic) or a
 * torque (revolute, wheel); the speed is linear or angular likewise. */
CD_API void cd2Joint_EnableMotor(cd2JointId jointId, bool flag);
CD_API void cd2Joint_SetMotorSpeed(cd2JointId jointId, cdReal motorSpeed);
CD_API void cd2Joint_SetMaxMotor(cd2JointId jointId, cdReal maxForceOrTorque);
/* Limits (distance: use cd2DistanceJoint_SetLengthRange; revolute: angles; prismatic and wheel:
 * translations), lower <= upper. */
CD_API void cd2Joint_EnableLimit(cd2JointId jointId, bool flag);
CD_API void cd2Joint_SetLimits(cd2JointId jointId, cdReal lower, cdReal upper);
/* Translation of B's anchor along the axis from A's (prismatic and wheel joints). */
CD_API cdReal cd2Joint_GetTranslation(cd2JointId jointId);

/* ---- events: arrays valid until the next step -------------------------------------------------- */
typedef struct cd2ContactBeginTouchEvent
{
	cd2ShapeId shapeIdA, shapeIdB;
	cd2Manifold manifold; /* world space, normal from A to B */
} cd2ContactBeginTouchEvent;

typedef struct cd2ContactEndTouchEvent
{
	cd2ShapeId shapeIdA, shapeIdB;
} cd2ContactEndTouchEvent;

typedef struct cd2ContactHitEvent
{
	cd2ShapeId shapeIdA, shapeIdB;
	cd2Vec point, normal;
	cdReal approachSpeed; /* > the world's hitEventThreshold */
} cd2ContactHitEvent;

typedef struct cd2ContactEvents
{
	const cd2ContactBeginTouchEvent* beginEvents;
	const cd2ContactEndTouchEvent* endEvents;
	const cd2ContactHitEvent* hitEvents;
	int beginCount, endCount, hitCount;
} cd2ContactEvents;

typedef struct cd2SensorBeginTouchEvent
{
	cd2ShapeId sensorShapeId, visitorShapeId;
} cd2SensorBeginTouchEvent;

typedef struct cd2SensorEndTouchEvent
{
	cd2ShapeId sensorShapeId, visitorShapeId;
} cd2SensorEndTouchEvent;

typedef struct cd2SensorEvents
{
	const cd2SensorBeginTouchEvent* beginEvents;
	const cd2SensorEndTouchEvent* endEvents;
	int beginCount, endCount;
} cd2SensorEvents;

typedef struct cd2BodyMoveEvent
{
	cd2Transform transform;
	cd2BodyId bodyId;
	void* userData;
	bool fellAsleep;
} cd2BodyMoveEvent;

typedef struct cd2BodyEvents
{
	const cd2BodyMoveEvent* moveEvents;
	int moveCount;
} cd2BodyEvents;

/* A joint whose reaction force (N) or torque (N m) over the last step exceeded its threshold
 * (forceThreshold, torqueThreshold of its def or cd2Joint_SetForceThreshold / SetTorqueThreshold;
 * 0, the default, raises none). One event per joint and step, in a deterministic order, for the
 * awake joints; a breakable joint is one the user destroys on its event. */
typedef struct cd2JointEvent
{
	cd2JointId jointId;
	void* userData;
	cd2Vec force;  /* the reaction force on B, as cd2Joint_GetConstraintForce */
	cdReal torque; /* as cd2Joint_GetConstraintTorque */
} cd2JointEvent;

typedef struct cd2JointEvents
{
	const cd2JointEvent* jointEvents;
	int count;
} cd2JointEvents;

CD_API cd2ContactEvents cd2World_GetContactEvents(cd2WorldId worldId);
CD_API cd2SensorEvents cd2World_GetSensorEvents(cd2WorldId worldId);
CD_API cd2BodyEvents cd2World_GetBodyEvents(cd2WorldId worldId);
CD_API cd2JointEvents cd2World_GetJointEvents(cd2WorldId worldId);

/* Called during the step for touching contacts of shapes with enablePreSolveEvents (manifold in
 * world space); return false to disable the contact for this step (one-way platforms). Must not
 * change the world. */
typedef bool cd2PreSolveFcn(cd2ShapeId shapeIdA, cd2ShapeId shapeIdB, const cd2Manifold* manifold,
							void* context);
/* Called when a new pair of shapes passes the category/group filter; return false to keep them
 * from colliding (for as long as their boxes keep overlapping). Must not change the world. */
typedef bool cd2CustomFilterFcn(cd2ShapeId shapeIdA, cd2ShapeId shapeIdB, void* context);

CD_API void cd2World_SetPreSolveCallback(cd2WorldId worldId, cd2PreSolveFcn* fcn, void* context);
CD_API void cd2World_SetCustomFilterCallback(cd2WorldId worldId, cd2CustomFilterFcn* fcn, void* context);

/* ---- queries -------------------------------------------------------------------------------- */
typedef struct cd2QueryFilter
{
	uint64_t categoryBits; /* of the query: shapes whose maskBits miss it are skipped */
	uint64_t maskBits;	   /* shapes whose categoryBits miss it are skipped */
} cd2QueryFilter;

CD_API cd2QueryFilter cd2DefaultQueryFilter(void);

/* Return false to stop. */
typedef bool cd2OverlapResultFcn(cd2ShapeId shapeId, void* context);
/* Return like cd2BroadRayFcn: 0 stops, the fraction clips (closest), 1 goes on, -1 ignores. */
typedef cdReal cd2CastResultFcn(cd2ShapeId shapeId, cd2Vec point, cd2Vec normal, cdReal fraction,
								void* context);

typedef struct cd2RayResult
{
	cd2ShapeId shapeId;
	cd2Vec point, normal;
	cdReal fraction;
	bool hit;
} cd2RayResult;

/* Shapes whose bounding box overlaps aabb (sensors included). */
CD_API void cd2World_OverlapAabb(cd2WorldId worldId, cd2Aabb aabb, cd2QueryFilter filter,
								 cd2OverlapResultFcn* fcn, void* context);
/* Shapes that overlap the world-space shape (exact test). */
CD_API void cd2World_OverlapShape(cd2WorldId worldId, const cd2Shape* shape, cd2QueryFilter filter,
								  cd2OverlapResultFcn* fcn, void* context);
/* Ray origin + t * translation, t in [0, 1]; sensors are skipped; chains one-sided. */
CD_API cd2RayResult cd2World_RaycastClosest(cd2WorldId worldId, cd2Vec origin, cd2Vec translation,
											cd2QueryFilter filter);
CD_API void cd2World_Raycast(cd2WorldId worldId, cd2Vec origin, cd2Vec translation, cd2QueryFilter filter,
							 cd2CastResultFcn* fcn, void* context);
/* The world-space shape moved by translation; normal and point of each hit as cd2ShapeCast. */
CD_API void cd2World_ShapeCast(cd2WorldId worldId, const cd2Shape* shape, cd2Vec translation,
							   cd2QueryFilter filter, cd2CastResultFcn* fcn, void* context);

/* ---- kinematic character mover ---------------------------------------------------------------
 * A character moved by your code, not by the solver: a capsule that casts along its path, collects
 * the planes of what it touches, and slides along them (walks up slopes, stops at walls, stands on
 * platforms). One frame, in the spirit of Box2D v3's mover:
 *
 *     target = cd2Add(position, cd2Scale(dt, velocity));
 *     for (int i = 0; i < 4; ++i) {          // collect the planes around the target, solve them
 *         planeCount = 0;
 *         cd2World_CollideMover(world, &capsuleAtTarget, filter, CollectPlane, &planes);
 *         target = cd2Add(target, cd2SolvePlanes(CD2_VEC_ZERO, planes, planeCount));
 *     }
 *     cdReal t = cd2World_CastMover(world, &capsuleAtPosition, cd2Sub(target, position), filter);
 *     position = cd2Lerp(position, target, t);
 *     velocity = cd2ClipVector(velocity, planes, planeCount);
 *
 * (tests/test_world2_features.c, TestMover, is this loop in full.) */
typedef struct cd2PlaneResult
{
	cd2ShapeId shapeId;
	cd2Vec normal;	   /* unit, from the shape to the mover */
	cdReal separation; /* along normal: > 0 apart (within the speculative distance), < 0 overlapping */
	cd2Vec point;	   /* the deepest contact point */
} cd2PlaneResult;

/* Return false to stop. */
typedef bool cd2PlaneResultFcn(const cd2PlaneResult* plane, void* context);

/* The planes of the non-sensor shapes touching (or within CD_SPECULATIVE_DISTANCE of) the capsule. */
CD_API void cd2World_CollideMover(cd2WorldId worldId, const cd2Capsule* mover, cd2QueryFilter filter,
								  cd2PlaneResultFcn* fcn, void* context);
/* The fraction in [0, 1] of translation the capsule can move before it touches a non-sensor shape
 * that it does not already overlap (1 when nothing is in the way). */
CD_API cdReal cd2World_CastMover(cd2WorldId worldId, const cd2Capsule* mover, cd2Vec translation,
								 cd2QueryFilter filter);
/* The smallest change of targetDelta (iteratively, every plane in turn) after which the mover
 * moved by the result overlaps no plane: separation + dot(normal, result) >= 0 for each. */
CD_API cd2Vec cd2SolvePlanes(cd2Vec targetDelta, const cd2PlaneResult* planes, int count);
/* The vector without its components into the planes the mover touches (separation below the
 * linear slop): a velocity that slides along walls and floors instead of pushing into them. */
CD_API cd2Vec cd2ClipVector(cd2Vec vector, const cd2PlaneResult* planes, int count);

/* ---- debug draw ------------------------------------------------------------------------------
 * cd2World_Draw calls these for what the flags select, in world coordinates; any callback may be
 * NULL. Colours are 0xRRGGBB: static bodies grey, kinematic blue, awake dynamic bodies orange,
 * sleeping ones dim, sensors yellow, joints teal, contact points red (normals green), AABBs
 * purple. For the tool's SVG/PNG frames, the web demos and your own renderer. */
typedef struct cd2DebugDraw
{
	/* A solid convex polygon (its vertices) grown by radius (0: sharp). */
	void (*drawPolygon)(const cd2Vec* vertices, int count, cdReal radius, uint32_t color, void* context);
	void (*drawCircle)(cd2Transform transform, cdReal radius, uint32_t color, void* context);
	void (*drawCapsule)(cd2Vec p1, cd2Vec p2, cdReal radius, uint32_t color, void* context);
	void (*drawSegment)(cd2Vec p1, cd2Vec p2, uint32_t color, void* context);
	void (*drawPoint)(cd2Vec p, cdReal size, uint32_t color, void* context);
	bool drawShapes, drawJoints, drawAabbs, drawContacts;
	void* context;
} cd2DebugDraw;

CD_API cd2DebugDraw cd2DefaultDebugDraw(void); /* no callbacks; shapes and joints on */
CD_API void cd2World_Draw(cd2WorldId worldId, const cd2DebugDraw* draw);

/* ---- snapshots ---------------------------------------------------------------------------------
 * The whole simulation state (bodies, shapes, contacts with their warm-start impulses, joints,
 * sleeping islands, the broadphase's boxes) in a flat buffer. Restoring it into the same world
 * and stepping gives the same bits as the original run on the same build. Callbacks, user data
 * pointers and event arrays are not part of the state (user data is kept as the pointer values
 * saved). The buffer is only meaningful to the same build of the library (float/double, version). */
CD_API size_t cd2World_GetStateSize(cd2WorldId worldId);
/* CD_ERROR_INVALID_ARGUMENT for a stale world, a NULL buffer, a locked world or a too small
 * capacity. */
CD_API cdResult cd2World_SaveState(cd2WorldId worldId, void* buffer, size_t capacity);
/* CD_ERROR_PARSE for a buffer that is not a state of this build, CD_ERROR_OUT_OF_MEMORY. Ids of
 * objects created after the save become stale. */
CD_API cdResult cd2World_RestoreState(cd2WorldId worldId, const void* buffer, size_t size);

#ifdef __cplusplus
}
#endif

#endif
