/* collide: the 2D world's internal data. Everything a snapshot saves is plain data (indices, no
 * pointers except user data), so the state is a set of arrays; see snapshot2.c. */
#ifndef COLLIDE_WORLD2_INTERNAL_H
#define COLLIDE_WORLD2_INTERNAL_H

#include "collide/world2.h"

#include <stddef.h>

#include "../base/container.h"
#include "../base/graph_color.h"
#include "wide2.h"

/* The step's profile (cd2World_GetProfile): while world->profiling is on, the wall time since the
 * last mark is added to world->profile.field (ms). */
double cd2ProfileNow(void); /* seconds */
#define CD2_PROFILE_MARK(world, field)                                                                       \
	do                                                                                                       \
	{                                                                                                        \
		if ((world)->profiling)                                                                              \
		{                                                                                                    \
			double cd2ProfileT_ = cd2ProfileNow();                                                           \
			(world)->profile.field += (float)(1000.0 * (cd2ProfileT_ - (world)->profileMark));               \
			(world)->profileMark = cd2ProfileT_;                                                             \
		}                                                                                                    \
	} while (0)

#define CD2_NULL_INDEX (-1)

/* Seconds a body must stay below its sleep threshold before its island may sleep. */
#define CD2_TIME_TO_SLEEP CD_R(0.5)
/* Fat-box margin of shapes (scaled by the length units). */
#define CD2_AABB_MARGIN (CD_R(0.1) * cdGetLengthUnitsPerMeter())
/* A shape's fat-box margin is this fraction of its extent (centre to farthest point), at most
 * CD2_AABB_MARGIN. */
#ifndef CD2_AABB_MARGIN_FRACTION
#define CD2_AABB_MARGIN_FRACTION CD_R(0.125)
#endif
/* Most rotation per sub-step (radians), so the small-angle rotation update stays accurate. */
#define CD2_MAX_ROTATION (CD_R(0.25) * CD_PI)

/* ---- bodies ---------------------------------------------------------------------------------- */
typedef struct cd2Body
{
	uint32_t generation;
	/* What the step's setup reads and writes of every body, in its first cache line. */
	bool inUse, awake, enabled;
	cd2BodyType type;
	int solverIndex;		/* in the step's dense awake arrays, or CD2_NULL_INDEX */
	cd2Transform transform; /* of the body origin */
	cd2Vec center;			/* world centre of mass */
	cd2Vec center0;			/* at the start of the step (continuous collision) */
	cd2Rot rotation0;
	cd2Vec localCenter;
	cd2Vec linearVelocity;
	cdReal angularVelocity;
	cd2Vec force;
	cdReal torque;
	cdReal mass, invMass, inertia, invInertia;
	cdReal linearDamping, angularDamping, gravityScale, sleepThreshold, sleepTime;
	cdReal minExtent, maxExtent; /* of the shapes about the centre of mass */
	bool enableSleep, fixedRotation, isBullet, customMass, isFast;
	int headShape, shapeCount;
	int headContactKey; /* contact edge key: contactIndex << 1 | side */
	int headJointKey;
	int islandId; /* sleeping island, or CD2_NULL_INDEX */
	int islandNext;
	void* userData;
} cd2Body;

/* ---- shapes ---------------------------------------------------------------------------------- */
typedef struct cd2WorldShape
{
	uint32_t generation;
	bool inUse;
	cd2WorldShapeType type;
	int body;
	int nextShape; /* in the body's list */
	int chain;	   /* CD2_NULL_INDEX unless a chain segment */
	int nextChainShape;
	union
	{
		cd2Circle circle;
		cd2Capsule capsule;
		cd2Polygon polygon;
		cd2Segment segment;
		cd2ChainSegment chainSegment;
	} geometry; /* body frame */
	cdReal density, friction, restitution, rollingResistance, tangentSpeed;
	cd2Filter filter;
	bool isSensor, enableSensorEvents, enableContactEvents, enableHitEvents, enablePreSolveEvents;
	int proxyId;
	int staticProxyId; /* a static body's shape: its proxy in world->staticBroadPhase too */
	cd2Aabb aabb;	   /* tight, world */
	cd2Aabb fatAabb;   /* what the broadphase holds */
	void* userData;
} cd2WorldShape;

typedef struct cd2ChainRec
{
	uint32_t generation;
	bool inUse;
	int body;
	int headShape;
	int segmentCount;
	void* userData;
} cd2ChainRec;

/* ---- contacts -------------------------------------------------------------------------------- */
/* A contact point as the solver reads and writes it (the prepare and the store): kept apart from the
 * narrowphase's data below so that a contact's solver fields share few cache lines. */
typedef struct cd2ContactPoint
{
	cd2Vec anchorA, anchorB; /* from the centres of mass to the point, world orientation */
	cdReal separation;
	cdReal normalImpulse, tangentImpulse, maxNormalImpulse;
} cd2ContactPoint;

/* The rest of a contact point: its world point and feature id, the approach speed for hit events,
 * and for recycling (see cd2UpdateContacts) the point in A's and in B's body frame and its
 * separation when the narrowphase last ran. */
typedef struct cd2ContactPointCache
{
	cd2Vec point; /* world, at the last update */
	uint32_t id;
	cdReal relativeVelocity; /* normal approach speed at the start of the step (negative: closing) */
	cd2Vec localPointA, localPointB;
	cdReal baseSeparation;
} cd2ContactPointCache;

enum
{
	CD2_CONTACT_TOUCHING = 1 << 0,
	CD2_CONTACT_SENSOR = 1 << 1,
	CD2_CONTACT_DISABLED = 1 << 2, /* by the pre-solve callback, this step */
	CD2_CONTACT_EVENTS = 1 << 3,
	CD2_CONTACT_HIT_EVENTS = 1 << 4,
	CD2_CONTACT_PRESOLVE = 1 << 5,
	CD2_CONTACT_CACHE_VALID = 1 << 6, /* localNormal, the points' local data and cachedPose are set */
	/* Set by the parallel pass of cd2UpdateContacts for its serial merge, cleared by the merge. */
	CD2_CONTACT_SIM_DISJOINT = 1 << 7,
	CD2_CONTACT_SIM_UPDATED = 1 << 8
};

/* A contact record is CD2_CONTACT_BYTES long, a multiple of 64, and starts with the fields the
 * solver's prepare and store read and write: in the float build they are 96 bytes, so in an array
 * aligned to 32 bytes (cdAlloc) they always lie in two cache lines. The solver visits the records
 * colour by colour, far apart; fewer lines per record is most of its prepare's time. */
#if CD_DOUBLE
#define CD2_CONTACT_BYTES 448
#else
#define CD2_CONTACT_BYTES 256
#endif

typedef struct cd2Contact
{
	union
	{
		struct
		{
			/* What the solver reads and writes, together. */
			cd2Vec normal; /* world, from A to B */
			int pointCount;
			cdReal rollingImpulse;
			cdReal friction, restitution, rollingResistance, tangentSpeed;
			cd2ContactPoint points[2];
			/* The rest. */
			cd2ContactPointCache cache[2]; /* of points[k] */
			bool inUse;
			uint32_t flags;
			int shapeA, shapeB, bodyA, bodyB;
			int prevKey[2], nextKey[2]; /* edges in bodyA's (0) and bodyB's (1) lists */
			/* Recycling: the normal in A's body frame, B's body frame in A's and the speculative
			 * distance when the narrowphase last ran. */
			cd2Vec localNormal;
			cd2Transform cachedPose;
			cdReal cachedSpeculative;
		};
		unsigned char bytes[CD2_CONTACT_BYTES];
	};
} cd2Contact;

_Static_assert(sizeof(cd2Contact) == CD2_CONTACT_BYTES, "cd2Contact: the fields outgrew CD2_CONTACT_BYTES");
_Static_assert(CD_DOUBLE || offsetof(cd2Contact, cache) == 96,
			   "cd2Contact: the solver's fields must be 96 bytes");

/* ---- joints ---------------------------------------------------------------------------------- */
typedef struct cd2Softness
{
	cdReal biasRate, massScale, impulseScale;
} cd2Softness;

typedef struct cd2JointData
{
	/* The sub-steps' data first, together (a joint's solve reads the first two cache lines). */
	bool enableSpring, enableLimit, enableMotor;
	/* accumulated impulses (warm starting) */
	cd2Vec linearImpulse;
	cdReal impulse, angularImpulse, springImpulse, motorImpulse, lowerImpulse, upperImpulse;
	/* the step's solver data */
	cd2Vec anchorA, anchorB, deltaCenter, axisA;
	cdReal deltaAngle, axialMass;
	cd2Softness jointSoftness, springSoftness, angularSoftness;
	/* definition */
	cd2Vec localAnchorA, localAnchorB; /* body frames, from the body origins */
	cd2Vec localAxisA;
	cdReal referenceAngle;
	cdReal length, minLength, maxLength;
	cdReal hertz, dampingRatio;						/* spring */
	cdReal constraintHertz, constraintDampingRatio; /* 0: the world's jointHertz, jointDampingRatio */
	cdReal angularHertz, angularDampingRatio;
	cdReal lower, upper;			  /* limit (angle or translation) */
	cdReal motorSpeed, maxMotorForce; /* force or torque */
	cdReal maxForce, maxTorque, correctionFactor;
	cd2Vec target, linearOffset;
	cdReal angularOffset;
} cd2JointData;

typedef struct cd2Joint
{
	uint32_t generation;
	bool inUse;
	cd2JointType type;
	int bodyA, bodyB;
	int prevKey[2], nextKey[2];
	bool collideConnected;
	/* Joint events when the reaction exceeds them (0: none); read as the step lists the joints. */
	cdReal forceThreshold, torqueThreshold;
	cd2JointData data;
	cd2Vec constraintForce; /* last step */
	cdReal constraintTorque;
	void* userData;
} cd2Joint;

/* ---- islands (sleeping groups) --------------------------------------------------------------- */
typedef struct cd2Island
{
	bool inUse;
	int headBody;
	int bodyCount;
} cd2Island;

/* ---- awake sets (island.c) ---------------------------------------------------------------------
 * The awake dynamic bodies (enabled, in use) in persistent sets, kept so that the step's sleep
 * check never groups the whole world: two bodies joined by a touching non-sensor contact or a joint
 * (not a filter joint) are always in the same set; sets merge when such a link appears (a touch
 * begins, a joint is made, a body wakes) and are split only when one may hold a group that can
 * sleep. A set that lost a link or a body since it was built (dirty) may hold several groups; a
 * clean one is exactly one group. Derived state: not saved, rebuilt after a restore or a failed
 * allocation (valid false). */
typedef struct cd2AwakeSet
{
	int headBody; /* members through cd2AwakeLink.next */
	int bodyCount;
	int restlessStamp; /* == the sleep check's stamp: holds a body that has not rested */
	int queuedStamp;   /* == the sleep check's stamp: already queued for the check */
	bool dirty;
} cd2AwakeSet;

typedef struct cd2AwakeLink
{
	int set; /* CD2_NULL_INDEX: in no set */
	int prev, next;
} cd2AwakeLink;

typedef struct cd2AwakeSets
{
	CD_ARRAY(cd2AwakeSet) sets;
	CD_ARRAY(int) freeSets;
	CD_ARRAY(cd2AwakeLink) links; /* per body index; count: entries set up so far */
	int stamp;
	bool valid;
} cd2AwakeSets;

/* ---- solver scratch -------------------------------------------------------------------------- */
typedef struct cd2SolverBody
{
	cd2Vec linearVelocity;
	cdReal angularVelocity;
	cd2Vec deltaPosition;
	cd2Rot deltaRotation;
	cdReal invMass, invInertia;
} cd2SolverBody;

/* Starts loading the cache line at p without waiting for it (a hint; nothing elsewhere). The joint
 * loops read records far apart in memory, one after another: the load of the next ones overlaps
 * the work on this one. */
#if defined(__GNUC__) || defined(__clang__)
#define CD2_PREFETCH(p) __builtin_prefetch(p)
#else
#define CD2_PREFETCH(p) ((void)0)
#endif

/* A joint in the solver's order: its data and the solver indices of its bodies (negative for an
 * immovable one). */
typedef struct cd2JointRef
{
	cd2JointData* data;
	cd2JointType type;
	int indexA, indexB;
} cd2JointRef;

/* What the velocity integration needs of a solver body, per sub-step, dense. */
typedef struct cd2SolverBodyParams
{
	cd2Vec deltaV;		   /* from gravity and force over a sub-step */
	cdReal deltaW;		   /* from torque over a sub-step */
	cdReal linearDamping;  /* implicit factor 1 / (1 + h damping) */
	cdReal angularDamping; /* its divisor 1 + h damping */
	bool dynamic;
} cd2SolverBodyParams;

typedef struct cd2ContactConstraintPoint
{
	cd2Vec anchorA, anchorB;
	cdReal baseSeparation;
	cdReal relativeVelocity;
	cdReal normalImpulse, tangentImpulse, maxNormalImpulse;
	cdReal normalMass, tangentMass;
} cd2ContactConstraintPoint;

/* A touching contact's pair of solver bodies, what a constraint is prepared from. */
typedef struct cd2ConstraintPair
{
	int contact;
	int indexA, indexB; /* solver bodies, CD2_NULL_INDEX for static (or sleeping) */
} cd2ConstraintPair;

typedef struct cd2ContactConstraint
{
	int contact;
	int indexA, indexB; /* solver bodies, CD2_NULL_INDEX for static (or sleeping) */
	cd2Vec normal;
	cdReal invMassA, invIA, invMassB, invIB;
	cdReal friction, restitution, rollingResistance, tangentSpeed;
	cdReal rollingImpulse, rollingMass;
	cdReal normalAcceleration; /* of B relative to A from gravity and forces, along the normal */
	cd2Softness softness;
	int pointCount;
	cd2ContactConstraintPoint points[2];
} cd2ContactConstraint;

/* Up to CD_W contact constraints of one colour side by side (no two share a movable body), one per
 * lane; empty lanes have zero masses and point at the zero body. */
typedef struct cd2ContactPointWide
{
	cdW anchorAx, anchorAy, anchorBx, anchorBy;
	cdW baseSeparation, relativeVelocity;
	cdW normalImpulse, tangentImpulse, maxNormalImpulse;
	cdW normalMass, tangentMass;
} cd2ContactPointWide;

typedef struct cd2ContactConstraintWide
{
	cdW invMassA, invIA, invMassB, invIB;
	cdW normalX, normalY;
	cdW friction, tangentSpeed, rollingResistance, rollingMass, rollingImpulse;
	cdW biasRate, massScale, impulseScale;
	cdW restitution;
	cd2ContactPointWide points[2];
	int indexA[CD_W], indexB[CD_W]; /* solver bodies; the zero body (index bodyCount) when immovable */
	/* 1 when the lane's body can move (its velocity is written back): immovable bodies (the zero
	 * body, kinematic bodies) are shared between blocks of one colour and only read. */
	unsigned char movesA[CD_W], movesB[CD_W];
	unsigned char pointCount[CD_W];
	bool bounces;	   /* some lane has restitution */
	int contact[CD_W]; /* the lane's contact, -1 for an empty lane */
} cd2ContactConstraintWide;

/* A body's shape that the finalize stage found out of its fat box: the shape, its proxy and its new
 * fat box (cd2ComputeShapeFatBox), computed there so that the serial move reads neither the body
 * nor the shape's geometry, and knows which proxies come next (to load their records early). */
typedef struct cd2FinalSync
{
	int shape;
	int proxy;
	cd2Aabb fat;
} cd2FinalSync;

typedef struct cd2StepContext
{
	cdReal dt, inv_dt, h, inv_h;
	int subStepCount;
	cd2Softness contactSoftness, staticSoftness, jointSoftness;
	cdReal restitutionThreshold, maxLinearVelocity, contactPushMaxVelocity;
	cd2SolverBody* bodies; /* dense, awake (dynamic and kinematic) */
	int* bodyIndices;	   /* world body index of each solver body */
	cd2SolverBodyParams* params;
	cd2Vec* accelerations; /* of each solver body from gravity and forces (restitution) */
	int bodyCount;
	cd2ContactConstraint* constraints;	 /* the overflow colour's, from overflowStart on */
	const cd2ConstraintPair* pairs;		 /* of each constraint (colour order), for cd2PrepareContacts */
	const cd2ConstraintPair* indexOrder; /* the same in contact index order */
	int constraintCount;
	/* The coloured constraints in wide blocks, colour by colour; the constraints from
	 * overflowStart on (the overflow colour) are solved one by one after them. */
	cd2ContactConstraintWide* wide;
	int wideCount;
	int overflowStart;
	/* The blocks of colour c are [colorBlockStart[c], colorBlockStart[c + 1]). */
	int colorBlockStart[CD_GRAPH_COLOR_COUNT + 1];
	/* The constraints of colour c are [colorConstraintStart[c], colorConstraintStart[c + 1]). */
	int colorConstraintStart[CD_GRAPH_COLOR_COUNT + 1];
	int colorCount;
	int* colorOfConstraint; /* colour of each (sorted) constraint, NULL when not coloured */
	int* joints;
	int jointCount;
	int thresholdJointCount; /* of `joints`, those with a force or torque threshold */
	/* The joints sorted by graph colour (see graph_color.h): the joints of colour c are
	 * [jointColorStart[c], jointColorStart[c + 1]); the last colour is the overflow, solved in
	 * order on one thread. */
	int jointColorStart[CD_GRAPH_COLOR_COUNT + 2];
	/* One per joint of `joints`, set by cd2PrepareJoints: what the sub-steps read of it, so that
	 * they never read the joint or body records. */
	cd2JointRef* jointRefs;
	/* The slots of `joints` in joint index order (memory order), for the prepare stage (set with the
	 * joints' colouring). */
	int* jointIndexOrder;
	bool enableWarmStarting;
	/* Some touching contact has hit events: the store writes the points' approach speeds (only hit
	 * events read them; without any the store leaves that line of the records alone). */
	bool storeApproach;
	/* Per solver body, what the finalize stage left for the serial pass after it (CD2_FINAL_*). */
	uint8_t* finalFlags;
	/* Per solver body with CD2_FINAL_SYNC_PROXY: its first shape to move in the broadphase. */
	cd2FinalSync* finalSync;
	/* The step's move events, one per solver body, written by index (NULL: out of memory). */
	cd2BodyMoveEvent* moveEvents;
} cd2StepContext;

/* The finalize stage's notes per body for the serial pass: a shape's box left its fat box (or
 * has no proxy), so the broadphase must move it; a fast bullet, whose sweep, boxes and move event
 * wait for the other bodies' final poses; a kinematic body, which wakes what it touches when moving;
 * a body that has rested long enough to fall asleep (no such body: no island can sleep). */
#define CD2_FINAL_SYNC_PROXY 1u
#define CD2_FINAL_BULLET 2u
#define CD2_FINAL_KINEMATIC 4u
#define CD2_FINAL_RESTED 8u
/* More than one of the body's shapes left its fat box (cd2FinalSync holds the first only). */
#define CD2_FINAL_SYNC_SEVERAL 16u

/* ---- events ---------------------------------------------------------------------------------- */
typedef CD_ARRAY(cd2ContactBeginTouchEvent) cd2BeginEventArray;
typedef CD_ARRAY(cd2ContactEndTouchEvent) cd2EndEventArray;
typedef CD_ARRAY(cd2ContactHitEvent) cd2HitEventArray;
typedef CD_ARRAY(cd2SensorBeginTouchEvent) cd2SensorBeginArray;
typedef CD_ARRAY(cd2SensorEndTouchEvent) cd2SensorEndArray;
typedef CD_ARRAY(cd2BodyMoveEvent) cd2MoveEventArray;
typedef CD_ARRAY(cd2JointEvent) cd2JointEventArray;

/* What the solver needs of a contact, written by cd2UpdateContacts for each contact index (so that
 * the solver's setup reads a small array, not every contact record): its two bodies when it is
 * touching, enabled and not a sensor (else bodyA is CD2_NULL_INDEX), and its flags. */
typedef struct cd2ContactSolveEntry
{
	int bodyA, bodyB;
	uint32_t flags;
} cd2ContactSolveEntry;

/* The last colouring of the solver's contacts (or joints), kept between steps: a step whose
 * constraints have the same colouring bodies in the same order (a settled stack, a resting chain)
 * takes the colours and the order from here instead of colouring again. The colouring depends on
 * nothing else, so the result is the same bits. Derived data: not part of the saved state. */
typedef struct cd2ColorCache
{
	int* bodyA; /* the colouring's bodies of each constraint */
	int* bodyB;
	int* colors;
	int* order;
	int count; /* constraints coloured (0: none) */
	int capacity;
} cd2ColorCache;

/* ---- the world ------------------------------------------------------------------------------- */
typedef struct cd2World
{
	uint16_t index;
	uint16_t generation;
	bool locked;
	/* settings (saved with the state) */
	cd2Vec gravity;
	cdReal restitutionThreshold, hitEventThreshold, contactHertz, contactDampingRatio, contactPushMaxVelocity,
		jointHertz, jointDampingRatio, maximumLinearSpeed;
	cdReal contactRecycleDistance; /* meters (times the length units at use); 0: never recycle */
	bool enableSleep, enableContinuous;
	/* objects */
	CD_ARRAY(cd2Body) bodies;
	CD_ARRAY(cd2WorldShape) shapes;
	CD_ARRAY(cd2ChainRec) chains;
	CD_ARRAY(cd2Contact) contacts;
	CD_ARRAY(cd2Joint) joints;
	CD_ARRAY(cd2Island) islands;
	cdIdPool bodyPool, shapePool, chainPool, contactPool, jointPool, islandPool;
	cd2AwakeSets awakeSets; /* derived (not saved) */
	cdPairSet pairs;		/* shape pair -> contact index */
	int sensorContactCount; /* live contacts flagged CD2_CONTACT_SENSOR (derived, not saved) */
	int staticProxyCount;	/* broadphase proxies flagged CD2_PROXY_STATIC (derived, not saved) */
	cd2BroadPhase* broadPhase;
	/* The static shapes' proxies again (same boxes and user data), for continuous collision: a
	 * fast non-bullet sweeps against static shapes only (derived, rebuilt on restore). */
	cd2BroadPhase* staticBroadPhase;
	uint32_t generationCounter; /* never restored, so ids from a discarded future stay stale */
	/* callbacks (not part of the state) */
	cd2PreSolveFcn* preSolveFcn;
	void* preSolveContext;
	cd2CustomFilterFcn* customFilterFcn;
	void* customFilterContext;
	void* userData;
	/* events of the last step */
	cd2BeginEventArray beginEvents;
	cd2EndEventArray endEvents;
	cd2HitEventArray hitEvents;
	cd2SensorBeginArray sensorBeginEvents;
	cd2SensorEndArray sensorEndEvents;
	cd2MoveEventArray moveEvents;
	cd2JointEventArray jointEvents;
	/* End events recorded by the last step; those appended after it (a shape destroyed between
	 * steps) are kept for the next step's arrays. */
	int stepEndEventCount, stepSensorEndEventCount;
	cdReal stepTimeStep; /* of the step in progress (0 outside a step) */
	/* cd2UpdateContacts' entries for the step's solve (step scratch; NULL: read the contacts) */
	cd2ContactSolveEntry* stepSolveEntries;
	cdArena arena;
	/* tasks: the user's callbacks, or the built-in pool's (see cd2RunTask) */
	int workerCount;
	cdEnqueueTaskCallback* enqueueTask;
	cdFinishTaskCallback* finishTask;
	void* userTaskContext;
	struct cdThreadPool* threadPool;
	/* Hand work to the workers however little there is (tests of the task paths; see
	 * cd2SetAlwaysParallel). */
	bool alwaysParallel;
	bool outOfMemory;
	/* The solver's last colourings (solver2.c). */
	cd2ColorCache contactColorCache;
	cd2ColorCache jointColorCache;
	/* cd2World_GetProfile: the last step's, and the time of the last mark (seconds). */
	bool profiling;
	cd2Profile profile;
	double profileMark;
} cd2World;

/* ---- world2.c -------------------------------------------------------------------------------- */
cd2World* cd2GetWorld(cd2WorldId id);	   /* NULL (and an assert) when stale */
cd2World* cd2GetWorldQuiet(cd2WorldId id); /* NULL when stale, no assert */
cd2World* cd2GetWorldFromIndex(uint16_t world0);
/* Reports a refused call through the assert hook (debug builds abort by default). */
void cd2Refuse(const char* reason, const char* file, int line);
#define CD2_REFUSE(reason) cd2Refuse(reason, __FILE__, __LINE__)
uint32_t cd2NextGeneration(cd2World* world);

/* Frees a colour cache's arrays (cd2DestroyWorld). */
void cd2ColorCache_Destroy(cd2ColorCache* cache);

/* ---- body2.c --------------------------------------------------------------------------------- */
cd2Body* cd2GetBody(cd2World* world, cd2BodyId id); /* NULL when stale */
cd2BodyId cd2MakeBodyId(const cd2World* world, int index);
void cd2UpdateBodyMass(cd2World* world, int bodyIndex);
void cd2WakeBody(cd2World* world, int bodyIndex);
bool cd2ShouldBodiesCollide(const cd2World* world, int bodyA, int bodyB); /* joints */

/* ---- shape2.c -------------------------------------------------------------------------------- */
cd2WorldShape* cd2GetShape(cd2World* world, cd2ShapeId id);
cd2ShapeId cd2MakeShapeId(const cd2World* world, int index);
/* The shape as a tagged shape, transformed by xf (body frame when xf is the identity). */
cd2Shape cd2MakeTaggedShape(const cd2WorldShape* shape, cd2Transform xf);
cd2Aabb cd2ComputeWorldShapeAabb(const cd2WorldShape* shape, cd2Transform xf);
bool cd2ShouldShapesCollide(cd2Filter a, cd2Filter b);
void cd2DestroyShapeInternal(cd2World* world, int shapeIndex, bool wakeBodies);
/* A broadphase proxy's user data: the shape index, plus CD2_PROXY_STATIC for a shape of a static
 * body (set when the proxy is made; a body that changes type remakes its proxies), so that
 * continuous collision passes over moving shapes without reading their records. */
#define CD2_PROXY_STATIC ((uint64_t)1 << 32)

static inline uint64_t cd2ProxyUserData(int shapeIndex, bool isStatic)
{
	return (uint64_t)(uint32_t)shapeIndex | (isStatic ? CD2_PROXY_STATIC : 0u);
}

static inline int cd2ProxyShape(uint64_t userData)
{
	return (int)(uint32_t)userData;
}

/* Removes the shape's proxy from the broadphase (if it has one), keeping the static count. */
void cd2DestroyShapeProxy(cd2World* world, cd2WorldShape* shape);

/* Brings the broadphase box up to date after a move; teleport: the body jumped. */
void cd2UpdateShapeBounds(cd2World* world, int shapeIndex, bool forceMove);
/* cd2UpdateShapeBounds in two halves, so that the step can compute the boxes on the workers and
 * move the proxies on one thread: the shape's tight box (speculative margin, a bullet's reach)
 * from its body's transform, read-only; whether the broadphase must hear of shape->aabb (no proxy
 * yet, or out of its fat box); and the broadphase half (not thread-safe; enabled bodies only). */
cd2Aabb cd2ComputeShapeBounds(const cd2World* world, const cd2WorldShape* shape);
bool cd2ShapeProxyNeedsSync(const cd2WorldShape* shape);
void cd2SyncShapeProxy(cd2World* world, int shapeIndex, bool forceMove);
/* cd2SyncShapeProxy in two halves, for a shape whose box left its fat box: the new fat box
 * (shape->aabb with the shape's margin; read-only, any thread), then the move with that box (what
 * cd2SyncShapeProxy does without forceMove, not thread-safe). */
cd2Aabb cd2ComputeShapeFatBox(const cd2World* world, const cd2WorldShape* shape);
void cd2SyncShapeProxyTo(cd2World* world, int shapeIndex, cd2Aabb fat);

/* ---- contact2.c ------------------------------------------------------------------------------ */
void cd2UpdateBroadPhasePairs(cd2World* world);
void cd2UpdateContacts(cd2World* world, cdReal timeStep);
void cd2SetContactSolveEntry(cd2ContactSolveEntry* entry, const cd2Contact* contact);
/* Sensor overlaps at the end of the step, with their begin and end events. */
void cd2UpdateSensors(cd2World* world);
void cd2DestroyContact(cd2World* world, int contactIndex, bool wakeBodies);
/* The single place where a pair's manifold is computed: shapes in their body frames, B's
 * transform in A's frame; the manifold comes back in A's frame. */
cd2Manifold cd2ContactCollide(const cd2WorldShape* shapeA, const cd2WorldShape* shapeB, cd2Transform xfAB,
							  cdReal speculativeDistance);

/* ---- contact_solver2.c ----------------------------------------------------------------------- */
/* Fills a constraint from its pair, its contact and the dense solver bodies (reads nothing else). */
static inline void cd2PrepareContactConstraint(const cd2World* world, const cd2StepContext* context,
											   const cd2ConstraintPair* pair, cd2ContactConstraint* c)
{
	static const cd2SolverBody zeroBody = {{CD_R(0.0), CD_R(0.0)}, CD_R(0.0), {CD_R(0.0), CD_R(0.0)},
										   {CD_R(1.0), CD_R(0.0)}, CD_R(0.0), CD_R(0.0)};
	c->contact = pair->contact;
	c->indexA = pair->indexA;
	c->indexB = pair->indexB;
	const cd2Contact* contact = world->contacts.data + c->contact;
	/* A sleeping or static body is immovable for this step. */
	const cd2SolverBody* bodyA = c->indexA < 0 ? &zeroBody : context->bodies + c->indexA;
	const cd2SolverBody* bodyB = c->indexB < 0 ? &zeroBody : context->bodies + c->indexB;
	c->invMassA = bodyA->invMass;
	c->invIA = bodyA->invInertia;
	c->invMassB = bodyB->invMass;
	c->invIB = bodyB->invInertia;
	c->softness = (c->invMassA == CD_R(0.0) || c->invMassB == CD_R(0.0)) ? context->staticSoftness
																		 : context->contactSoftness;
	c->normal = contact->normal;
	c->friction = contact->friction;
	c->restitution = contact->restitution;
	c->rollingResistance = contact->rollingResistance;
	c->tangentSpeed = contact->tangentSpeed;
	c->rollingImpulse = contact->rollingImpulse;
	cdReal iSum = c->invIA + c->invIB;
	c->rollingMass = iSum > CD_R(0.0) ? CD_R(1.0) / iSum : CD_R(0.0);
	c->pointCount = contact->pointCount;
	cd2Vec n = c->normal, t = cd2RightPerp(n);
	cd2Vec accA = c->indexA < 0 ? CD2_VEC_ZERO : context->accelerations[c->indexA];
	cd2Vec accB = c->indexB < 0 ? CD2_VEC_ZERO : context->accelerations[c->indexB];
	c->normalAcceleration = cd2Dot(n, cd2Sub(accB, accA));
	cd2Vec vA = bodyA->linearVelocity, vB = bodyB->linearVelocity;
	cdReal wA = bodyA->angularVelocity, wB = bodyB->angularVelocity;
	for (int k = 0; k < c->pointCount; ++k)
	{
		const cd2ContactPoint* mp = contact->points + k;
		cd2ContactConstraintPoint* cp = c->points + k;
		cp->anchorA = mp->anchorA;
		cp->anchorB = mp->anchorB;
		cp->baseSeparation = mp->separation - cd2Dot(cd2Sub(mp->anchorB, mp->anchorA), n);
		cp->normalImpulse = context->enableWarmStarting ? mp->normalImpulse : CD_R(0.0);
		cp->tangentImpulse = context->enableWarmStarting ? mp->tangentImpulse : CD_R(0.0);
		cp->maxNormalImpulse = CD_R(0.0);
		cdReal rnA = cd2Cross(cp->anchorA, n), rnB = cd2Cross(cp->anchorB, n);
		cdReal kNormal = c->invMassA + c->invMassB + c->invIA * rnA * rnA + c->invIB * rnB * rnB;
		cp->normalMass = kNormal > CD_R(0.0) ? CD_R(1.0) / kNormal : CD_R(0.0);
		cdReal rtA = cd2Cross(cp->anchorA, t), rtB = cd2Cross(cp->anchorB, t);
		cdReal kTangent = c->invMassA + c->invMassB + c->invIA * rtA * rtA + c->invIB * rtB * rtB;
		cp->tangentMass = kTangent > CD_R(0.0) ? CD_R(1.0) / kTangent : CD_R(0.0);
		cd2Vec vrA = cd2Add(vA, cd2CrossSV(wA, cp->anchorA));
		cd2Vec vrB = cd2Add(vB, cd2CrossSV(wB, cp->anchorB));
		cp->relativeVelocity = cd2Dot(n, cd2Sub(vrB, vrA));
	}
}
/* Constraints [start, end): each reads its contact and bodies and writes only itself. true when
 * one of them has restitution. */
bool cd2PrepareContacts(const cd2World* world, cd2StepContext* context, int start, int end);
void cd2WarmStartContacts(cd2StepContext* context);
void cd2SolveContacts(cd2StepContext* context, bool useBias);
void cd2ApplyRestitution(cd2StepContext* context);
/* Runs task over [0, itemCount) on the world's workers (in pieces of at least minRange items) and
 * returns when it is done; on the calling thread when there is one worker or fewer than
 * minParallel items (too little work to pay for handing it out: a small world steps as fast with
 * two workers as with one). */
void cd2RunTask(cd2World* world, cdTaskCallback* task, int itemCount, int minRange, int minParallel,
				void* taskContext);
/* The smallest amounts of work that go to the workers: contacts to update (a recycled manifold
 * costs tens of nanoseconds), moved proxies' pair queries, shapes in the world for the
 * broadphase's rebuild, and the solver's work per sub-step in constraints (a joint counts as 2, a
 * body as 1/4; below it every stage runs on the stepping thread). */
/* For tests of the task paths on small worlds: alwaysParallel true hands every task to the workers
 * whatever its size (the results are the same bits either way). */
void cd2SetAlwaysParallel(cd2WorldId worldId, bool alwaysParallel);
#define CD2_PARALLEL_MIN_CONTACTS 1024
#define CD2_PARALLEL_MIN_PAIR_ITEMS 128
#define CD2_PARALLEL_MIN_SHAPES 1024
#define CD2_PARALLEL_MIN_SOLVE 1200
/* Lays the coloured constraints out in wide blocks (colorBlockStart, overflowStart) and allocates
 * them; cd2PackContactsWide then prepares the constraints of blocks [start, end)
 * (cd2PrepareContactConstraint's values) straight into the blocks, true when one has restitution. */
bool cd2PrepareContactsWide(cd2World* world, cd2StepContext* context);
bool cd2PackContactsWide(const cd2World* world, cd2StepContext* context, int startBlock, int endBlock);
/* Blocks [start, end) of the wide constraints (one colour at most, see colorBlockStart). */
void cd2WarmStartContactsWide(cd2StepContext* context, int start, int end);
void cd2SolveContactsWide(cd2StepContext* context, int start, int end, bool useBias);
/* Restitution of blocks [start, end) (one colour at most); cd2ApplyRestitution then does the
 * overflow colour's constraints. */
void cd2ApplyRestitutionWide(cd2StepContext* context, int start, int end);
/* Blocks [start, end) back into their contacts. */
void cd2StoreContactsWide(cd2World* world, cd2StepContext* context, int startBlock, int endBlock);
void cd2StoreImpulses(cd2World* world, const cd2StepContext* context, int start, int end);

/* ---- solver2.c ------------------------------------------------------------------------------- */
void cd2Solve(cd2World* world, cdReal timeStep, int subStepCount);
cd2Softness cd2MakeSoft(cdReal hertz, cdReal zeta, cdReal h);
cd2Rot cd2IntegrateRotation(cd2Rot q, cdReal deltaAngle);

/* ---- island.c -------------------------------------------------------------------------------- */
void cd2WakeIsland(cd2World* world, int islandId);
/* Puts to sleep each group of awake dynamic bodies (joined by touching contacts and joints) whose
 * bodies have all rested for CD2_TIME_TO_SLEEP, and each kinematic body that has; returns how many
 * bodies it put to sleep. bodyIndices[0, count) are the step's awake bodies (every awake dynamic
 * body, in increasing index order) and flags[k] their CD2_FINAL_* flags. */
int cd2UpdateSleep(cd2World* world, const int* bodyIndices, const uint8_t* flags, int count);
/* The awake sets' bookkeeping: after a body may have started or stopped being an awake dynamic
 * body (created, destroyed, woken, put to sleep, enabled, disabled, type changed); after a link
 * (touching non-sensor contact, joint other than a filter joint) between two bodies appeared or
 * went; and to drop the sets (a restore), so that the next sleep check rebuilds them. */
void cd2AwakeSets_SyncBody(cd2World* world, int bodyIndex);
void cd2AwakeSets_Link(cd2World* world, int bodyA, int bodyB);
void cd2AwakeSets_Unlink(cd2World* world, int bodyA, int bodyB);
void cd2AwakeSets_Invalidate(cd2World* world);
void cd2AwakeSets_Destroy(cd2World* world);
#ifdef CD2_VALIDATE_AWAKE_SETS
/* Aborts when the sets break their rules (a test build's check). */
void cd2AwakeSets_Validate(cd2World* world);
#endif
/* Puts the body's connected group to sleep now. */
void cd2SleepBodyGroup(cd2World* world, int bodyIndex);
void cd2RemoveBodyFromIsland(cd2World* world, int bodyIndex);

/* ---- joint2.c -------------------------------------------------------------------------------- */
cd2Joint* cd2GetJoint(cd2World* world, cd2JointId id);
void cd2DestroyJointInternal(cd2World* world, int jointIndex, bool wakeBodies);
/* False when out of scratch memory. */
/* The joints' references and their order; false when out of scratch memory. The joints themselves
 * are prepared by cd2PrepareJointRange over [0, jointCount) (in index order, any split). */
bool cd2PrepareJoints(cd2World* world, cd2StepContext* context);
void cd2PrepareJointRange(cd2World* world, cd2StepContext* context, int start, int end);
/* Joints [start, end) of context->joints. */
void cd2WarmStartJoints(cd2World* world, cd2StepContext* context, int start, int end);
void cd2SolveJoints(cd2World* world, cd2StepContext* context, int start, int end, bool useBias);
/* Joints [start, end) of context->joints: each writes only its own reaction. */
void cd2StoreJointReactions(cd2World* world, cd2StepContext* context, int start, int end);

/* The per-kind solvers (one file each). */
typedef struct cd2JointSolverArgs
{
	cd2JointData* data;
	cd2SolverBody* a; /* a zero body for static ones */
	cd2SolverBody* b;
	const cd2StepContext* context;
} cd2JointSolverArgs;

/* What warm starting a joint applies: A's velocities change by -invMass linearA and
 * -invInertia angularA, B's by +invMass linearB and +invInertia angularB. The per-kind warm start
 * computes it; cd2WarmStartJoints caps and applies it. */
typedef struct cd2JointImpulse
{
	cd2Vec linearA, linearB;
	cdReal angularA, angularB;
} cd2JointImpulse;

void cd2PrepareDistanceJoint(cd2JointSolverArgs* args);
cd2JointImpulse cd2WarmStartDistanceJoint(const cd2JointSolverArgs* args);
void cd2SolveDistanceJoint(cd2JointSolverArgs* args, bool useBias);
void cd2PrepareRevoluteJoint(cd2JointSolverArgs* args);
void cd2SolveRevoluteJoint(cd2JointSolverArgs* args, bool useBias);
void cd2PrepareWeldJoint(cd2JointSolverArgs* args);
cd2JointImpulse cd2WarmStartWeldJoint(const cd2JointSolverArgs* args);
void cd2SolveWeldJoint(cd2JointSolverArgs* args, bool useBias);
void cd2PrepareMouseJoint(cd2JointSolverArgs* args);
cd2JointImpulse cd2WarmStartMouseJoint(const cd2JointSolverArgs* args);
void cd2SolveMouseJoint(cd2JointSolverArgs* args, bool useBias);
void cd2PrepareMotorJoint(cd2JointSolverArgs* args);
cd2JointImpulse cd2WarmStartMotorJoint(const cd2JointSolverArgs* args);
void cd2SolveMotorJoint(cd2JointSolverArgs* args, bool useBias);
void cd2PreparePrismaticJoint(cd2JointSolverArgs* args);
cd2JointImpulse cd2WarmStartPrismaticJoint(const cd2JointSolverArgs* args);
void cd2SolvePrismaticJoint(cd2JointSolverArgs* args, bool useBias);
void cd2PrepareWheelJoint(cd2JointSolverArgs* args);
cd2JointImpulse cd2WarmStartWheelJoint(const cd2JointSolverArgs* args);
void cd2SolveWheelJoint(cd2JointSolverArgs* args, bool useBias);

/* ---- continuous2.c --------------------------------------------------------------------------- */
void cd2SolveContinuous(cd2World* world, int bodyIndex);

/* Contact edge keys. */
static inline int cd2EdgeContact(int key)
{
	return key >> 1;
}
static inline int cd2EdgeSide(int key)
{
	return key & 1;
}

#endif
