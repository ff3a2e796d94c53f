/* collide for JavaScript: the 2D world's export layer (lib/world2.js is its only caller).
 *
 * Flat functions of numbers; records go through the scratch block of exports.c (slot A holds a
 * shape in the 2D shape record format documented there, the I/O area holds definitions and
 * results). Ids cross as (world index, index1, generation): world0 is the world's slot, index1
 * and generation are the C id's fields. Every function given an id checks it with the library's
 * *_IsValid first and returns 0 (or -1) for a stale one, so lib/world2.js can throw; the library
 * itself is never given a stale id.
 *
 * Definitions: a NaN field means "the library's default" (cd2Default*Def), so the JavaScript side
 * never repeats the defaults. Each world keeps the list of its bodies in creation order (with
 * swap-removal on destroy, mirrored by lib/world2.js) for the batch transform call.
 *
 * Callbacks (pre-solve, custom filter) call the functions the module imports from "collide". */
#include <collide/collide.h>
#include <collide/world2.h>

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Outside wasm (tests/js_exports: the layer under the native sanitizers) plain functions. */
#if defined(__wasm__)
#define EXPORT(name) __attribute__((export_name(name)))
#define IMPORT(name) __attribute__((import_module("collide"), import_name(name)))
#else
#define EXPORT(name)
#define IMPORT(name)
#endif

float* cdjsScratch(void);
int cdjsFloatToInt(float value);

#define SLOT_A (cdjsScratch())
#define IO (cdjsScratch() + 128)

IMPORT("preSolve") int cdjsImportPreSolve(int world0, int ia, int ga, int ib, int gb, const float* manifold);
IMPORT("customFilter") int cdjsImportCustomFilter(int world0, int ia, int ga, int ib, int gb);

typedef struct JsWorld
{
	cd2WorldId id;
	cd2BodyId* bodies;
	int bodyCount, bodyCapacity;
	float* transforms;
	int transformCapacity;
	bool preSolve, customFilter;
} JsWorld;

static JsWorld g_worlds[CD2_MAX_WORLDS];

/* A growable output buffer for variable-length results (events, query hits, snapshots). */
static float* g_out = NULL;
static int g_outCapacity = 0;
static int g_outCount = 0;

static bool outReserve(int floats)
{
	if (g_outCount + floats <= g_outCapacity)
	{
		return true;
	}
	int capacity = g_outCapacity < 1024 ? 1024 : g_outCapacity;
	while (capacity < g_outCount + floats)
	{
		capacity *= 2;
	}
	float* out = (float*)realloc(g_out, (size_t)capacity * sizeof(float));
	if (out == NULL)
	{
		return false;
	}
	g_out = out;
	g_outCapacity = capacity;
	return true;
}

static void putInt(float* where, int32_t value)
{
	memcpy(where, &value, sizeof value);
}

static int32_t getInt(const float* where)
{
	int32_t value;
	memcpy(&value, where, sizeof value);
	return value;
}

static uint64_t getU64(const float* where)
{
	uint32_t lo, hi;
	memcpy(&lo, where, sizeof lo);
	memcpy(&hi, where + 1, sizeof hi);
	return (uint64_t)lo | ((uint64_t)hi << 32);
}

static void putU64(float* where, uint64_t value)
{
	uint32_t lo = (uint32_t)value, hi = (uint32_t)(value >> 32);
	memcpy(where, &lo, sizeof lo);
	memcpy(where + 1, &hi, sizeof hi);
}

static void putShape(float* o, cd2ShapeId id)
{
	putInt(o, id.index1);
	putInt(o + 1, (int32_t)id.generation);
}

static float orDefault(float value, float fallback)
{
	return isnan(value) ? fallback : value;
}

static bool flagOr(float value, bool fallback)
{
	return isnan(value) ? fallback : value != 0.0f;
}

static JsWorld* getWorld(int world0)
{
	if (world0 < 0 || world0 >= CD2_MAX_WORLDS)
	{
		return NULL;
	}
	JsWorld* w = g_worlds + world0;
	return w->id.index1 != 0 && cd2World_IsValid(w->id) ? w : NULL;
}

static cd2BodyId bodyId(int world0, int index1, int generation)
{
	cd2BodyId id = {index1, (uint16_t)world0, (uint32_t)generation};
	return id;
}

static cd2ShapeId shapeId(int world0, int index1, int generation)
{
	cd2ShapeId id = {index1, (uint16_t)world0, (uint32_t)generation};
	return id;
}

static cd2JointId jointId(int world0, int index1, int generation)
{
	cd2JointId id = {index1, (uint16_t)world0, (uint32_t)generation};
	return id;
}

static bool validBody(int world0, int index1, int generation, cd2BodyId* out)
{
	if (world0 < 0 || world0 >= CD2_MAX_WORLDS || index1 <= 0)
	{
		return false;
	}
	*out = bodyId(world0, index1, generation);
	return cd2Body_IsValid(*out);
}

static bool validShape(int world0, int index1, int generation, cd2ShapeId* out)
{
	if (world0 < 0 || world0 >= CD2_MAX_WORLDS || index1 <= 0)
	{
		return false;
	}
	*out = shapeId(world0, index1, generation);
	return cd2Shape_IsValid(*out);
}

static bool validJoint(int world0, int index1, int generation, cd2JointId* out)
{
	if (world0 < 0 || world0 >= CD2_MAX_WORLDS || index1 <= 0)
	{
		return false;
	}
	*out = jointId(world0, index1, generation);
	return cd2Joint_IsValid(*out);
}

/* ---- worlds ----------------------------------------------------------------------------------
 * IO in: gravity x y, enableSleep, enableContinuous, contactHertz, contactDampingRatio,
 * jointHertz, jointDampingRatio, restitutionThreshold, hitEventThreshold, maximumLinearSpeed,
 * contactPushMaxVelocity, contactRecycleDistance (NaN: default). Returns world0 + 1, 0 on failure. */
EXPORT("world2Create") int cdjsWorld2Create(void)
{
	const float* in = IO;
	cd2WorldDef def = cd2DefaultWorldDef();
	def.gravity.x = orDefault(in[0], def.gravity.x);
	def.gravity.y = orDefault(in[1], def.gravity.y);
	def.enableSleep = flagOr(in[2], def.enableSleep);
	def.enableContinuous = flagOr(in[3], def.enableContinuous);
	def.contactHertz = orDefault(in[4], def.contactHertz);
	def.contactDampingRatio = orDefault(in[5], def.contactDampingRatio);
	def.jointHertz = orDefault(in[6], def.jointHertz);
	def.jointDampingRatio = orDefault(in[7], def.jointDampingRatio);
	def.restitutionThreshold = orDefault(in[8], def.restitutionThreshold);
	def.hitEventThreshold = orDefault(in[9], def.hitEventThreshold);
	def.maximumLinearSpeed = orDefault(in[10], def.maximumLinearSpeed);
	def.contactPushMaxVelocity = orDefault(in[11], def.contactPushMaxVelocity);
	def.contactRecycleDistance = orDefault(in[12], def.contactRecycleDistance);
	cd2WorldId id = cd2CreateWorld(&def);
	if (id.index1 == 0)
	{
		return 0;
	}
	JsWorld* w = g_worlds + (id.index1 - 1);
	memset(w, 0, sizeof *w);
	w->id = id;
	return id.index1;
}

EXPORT("world2Destroy") void cdjsWorld2Destroy(int world0)
{
	JsWorld* w = getWorld(world0);
	if (w == NULL)
	{
		return;
	}
	cd2DestroyWorld(w->id);
	free(w->bodies);
	free(w->transforms);
	memset(w, 0, sizeof *w);
}

EXPORT("world2Valid") int cdjsWorld2Valid(int world0)
{
	return getWorld(world0) != NULL;
}

EXPORT("world2Step") int cdjsWorld2Step(int world0, float timeStep, int subStepCount)
{
	JsWorld* w = getWorld(world0);
	if (w == NULL)
	{
		return 0;
	}
	cd2World_Step(w->id, timeStep, subStepCount);
	return 1;
}

EXPORT("world2SetGravity") void cdjsWorld2SetGravity(int world0, float x, float y)
{
	JsWorld* w = getWorld(world0);
	if (w != NULL)
	{
		cd2World_SetGravity(w->id, (cd2Vec){x, y});
	}
}

/* IO out: gravity x y. */
EXPORT("world2GetGravity") void cdjsWorld2GetGravity(int world0)
{
	JsWorld* w = getWorld(world0);
	if (w != NULL)
	{
		cd2Vec g = cd2World_GetGravity(w->id);
		IO[0] = g.x;
		IO[1] = g.y;
	}
}

EXPORT("world2EnableSleeping") void cdjsWorld2EnableSleeping(int world0, int flag)
{
	JsWorld* w = getWorld(world0);
	if (w != NULL)
	{
		cd2World_EnableSleeping(w->id, flag != 0);
	}
}

EXPORT("world2EnableContinuous") void cdjsWorld2EnableContinuous(int world0, int flag)
{
	JsWorld* w = getWorld(world0);
	if (w != NULL)
	{
		cd2World_EnableContinuous(w->id, flag != 0);
	}
}

/* IO out (ints): bodyCount shapeCount contactCount touchingContactCount jointCount awakeBodyCount
 * islandCount. */
EXPORT("world2Counters") void cdjsWorld2Counters(int world0)
{
	JsWorld* w = getWorld(world0);
	if (w == NULL)
	{
		return;
	}
	cd2Counters c = cd2World_GetCounters(w->id);
	int values[7] = {c.bodyCount,  c.shapeCount,	 c.contactCount, c.touchingContactCount,
					 c.jointCount, c.awakeBodyCount, c.islandCount};
	for (int i = 0; i < 7; ++i)
	{
		putInt(IO + i, values[i]);
	}
}

/* ---- bodies ----------------------------------------------------------------------------------
 * IO in: type, x, y, angle, vx, vy, angularVelocity, linearDamping, angularDamping, gravityScale,
 * sleepThreshold, enableSleep, isAwake, fixedRotation, isBullet, isEnabled (NaN: default).
 * Returns index1 (0 on failure: a bad def); IO[0] out: generation. The body joins the world's
 * list at the end. */
EXPORT("body2Create") int cdjsBody2Create(int world0)
{
	JsWorld* w = getWorld(world0);
	if (w == NULL)
	{
		return 0;
	}
	if (w->bodyCount == w->bodyCapacity)
	{
		int capacity = w->bodyCapacity < 64 ? 64 : 2 * w->bodyCapacity;
		cd2BodyId* bodies = (cd2BodyId*)realloc(w->bodies, (size_t)capacity * sizeof(cd2BodyId));
		if (bodies == NULL)
		{
			return 0;
		}
		w->bodies = bodies;
		w->bodyCapacity = capacity;
	}
	const float* in = IO;
	cd2BodyDef def = cd2DefaultBodyDef();
	def.type = isnan(in[0]) ? def.type : (cd2BodyType)cdjsFloatToInt(in[0]);
	def.position.x = orDefault(in[1], def.position.x);
	def.position.y = orDefault(in[2], def.position.y);
	if (!isnan(in[3]))
	{
		def.rotation = cd2MakeRot(in[3]);
	}
	def.linearVelocity.x = orDefault(in[4], def.linearVelocity.x);
	def.linearVelocity.y = orDefault(in[5], def.linearVelocity.y);
	def.angularVelocity = orDefault(in[6], def.angularVelocity);
	def.linearDamping = orDefault(in[7], def.linearDamping);
	def.angularDamping = orDefault(in[8], def.angularDamping);
	def.gravityScale = orDefault(in[9], def.gravityScale);
	def.sleepThreshold = orDefault(in[10], def.sleepThreshold);
	def.enableSleep = flagOr(in[11], def.enableSleep);
	def.isAwake = flagOr(in[12], def.isAwake);
	def.fixedRotation = flagOr(in[13], def.fixedRotation);
	def.isBullet = flagOr(in[14], def.isBullet);
	def.isEnabled = flagOr(in[15], def.isEnabled);
	cd2BodyId id = cd2CreateBody(w->id, &def);
	if (id.index1 == 0)
	{
		return 0;
	}
	w->bodies[w->bodyCount++] = id;
	putInt(IO, (int32_t)id.generation);
	return id.index1;
}

/* Removes the body at `slot` of the world's list (the last body moves into the slot) and
 * destroys it unless it is already stale (restored snapshots). Returns 1, or 0 for a bad slot. */
EXPORT("body2Destroy") int cdjsBody2Destroy(int world0, int slot)
{
	JsWorld* w = getWorld(world0);
	if (w == NULL || slot < 0 || slot >= w->bodyCount)
	{
		return 0;
	}
	cd2BodyId id = w->bodies[slot];
	if (cd2Body_IsValid(id))
	{
		cd2DestroyBody(id);
	}
	w->bodies[slot] = w->bodies[w->bodyCount - 1];
	w->bodyCount -= 1;
	return 1;
}

EXPORT("body2Valid") int cdjsBody2Valid(int world0, int index1, int generation)
{
	cd2BodyId id;
	return validBody(world0, index1, generation, &id);
}

/* The world's bodies as 4 floats each (x, y, cos, sin of the body origin's transform), in list
 * order. Returns a byte pointer (valid until the next call that may allocate), 0 on failure. */
EXPORT("world2Transforms") float* cdjsWorld2Transforms(int world0)
{
	JsWorld* w = getWorld(world0);
	if (w == NULL)
	{
		return NULL;
	}
	if (w->transformCapacity < w->bodyCapacity || w->transforms == NULL)
	{
		int capacity = w->bodyCapacity < 16 ? 16 : w->bodyCapacity;
		float* t = (float*)realloc(w->transforms, (size_t)capacity * 4 * sizeof(float));
		if (t == NULL)
		{
			return NULL;
		}
		w->transforms = t;
		w->transformCapacity = capacity;
	}
	float* t = w->transforms;
	for (int i = 0; i < w->bodyCount; ++i)
	{
		cd2Transform xf = cd2Body_GetTransform(w->bodies[i]);
		t[4 * i] = xf.p.x;
		t[4 * i + 1] = xf.p.y;
		t[4 * i + 2] = xf.q.c;
		t[4 * i + 3] = xf.q.s;
	}
	return t;
}

/* The world's bodies as 7 floats each: x, y, cos, sin, vx, vy, angular velocity (for the
 * two-machines comparison and for snapshots of motion). Returns a byte pointer. */
EXPORT("world2States") float* cdjsWorld2States(int world0)
{
	JsWorld* w = getWorld(world0);
	g_outCount = 0;
	if (w == NULL || !outReserve(7 * w->bodyCount + 1))
	{
		return NULL;
	}
	for (int i = 0; i < w->bodyCount; ++i)
	{
		cd2Transform xf = cd2Body_GetTransform(w->bodies[i]);
		cd2Vec v = cd2Body_GetLinearVelocity(w->bodies[i]);
		float* o = g_out + 7 * i;
		o[0] = xf.p.x;
		o[1] = xf.p.y;
		o[2] = xf.q.c;
		o[3] = xf.q.s;
		o[4] = v.x;
		o[5] = v.y;
		o[6] = cd2Body_GetAngularVelocity(w->bodies[i]);
	}
	return g_out;
}

#define BODY_OR(ret)                                                                                         \
	cd2BodyId id;                                                                                            \
	if (!validBody(world0, index1, generation, &id))                                                         \
	{                                                                                                        \
		return ret;                                                                                          \
	}

/* IO out: x, y, cos, sin, vx, vy, angular velocity, mass, inertia, type, awake, enabled,
 * fixedRotation, bullet, gravityScale, linearDamping, angularDamping, centre x, centre y. */
EXPORT("body2Get") int cdjsBody2Get(int world0, int index1, int generation)
{
	BODY_OR(0)
	float* o = IO;
	cd2Transform xf = cd2Body_GetTransform(id);
	cd2Vec v = cd2Body_GetLinearVelocity(id);
	cd2Vec c = cd2Body_GetWorldCenterOfMass(id);
	o[0] = xf.p.x;
	o[1] = xf.p.y;
	o[2] = xf.q.c;
	o[3] = xf.q.s;
	o[4] = v.x;
	o[5] = v.y;
	o[6] = cd2Body_GetAngularVelocity(id);
	o[7] = cd2Body_GetMass(id);
	o[8] = cd2Body_GetRotationalInertia(id);
	o[9] = (float)cd2Body_GetType(id);
	o[10] = cd2Body_IsAwake(id) ? 1.0f : 0.0f;
	o[11] = cd2Body_IsEnabled(id) ? 1.0f : 0.0f;
	o[12] = cd2Body_IsFixedRotation(id) ? 1.0f : 0.0f;
	o[13] = cd2Body_IsBullet(id) ? 1.0f : 0.0f;
	o[14] = cd2Body_GetGravityScale(id);
	o[15] = cd2Body_GetLinearDamping(id);
	o[16] = cd2Body_GetAngularDamping(id);
	o[17] = c.x;
	o[18] = c.y;
	return 1;
}

/* IO out: x, y, cos, sin. */
EXPORT("body2Transform") int cdjsBody2Transform(int world0, int index1, int generation)
{
	BODY_OR(0)
	cd2Transform xf = cd2Body_GetTransform(id);
	IO[0] = xf.p.x;
	IO[1] = xf.p.y;
	IO[2] = xf.q.c;
	IO[3] = xf.q.s;
	return 1;
}

/* IO out: vx, vy, angular velocity. */
EXPORT("body2Velocity") int cdjsBody2Velocity(int world0, int index1, int generation)
{
	BODY_OR(0)
	cd2Vec v = cd2Body_GetLinearVelocity(id);
	IO[0] = v.x;
	IO[1] = v.y;
	IO[2] = cd2Body_GetAngularVelocity(id);
	return 1;
}

/* what: 0 transform (x, y, angle), 1 linear velocity (x, y), 2 angular velocity (a),
 * 3 force at point (x, y, px, py, wake), 4 force at centre (x, y, wake), 5 torque (a, wake),
 * 6 impulse at point, 7 impulse at centre, 8 angular impulse, 9 type (a), 10 awake (a),
 * 11 enabled (a), 12 fixed rotation (a), 13 bullet (a), 14 gravity scale (a), 15 linear damping,
 * 16 angular damping, 17 enable sleep (a). Arguments in IO. Returns 1, 0 for a stale body. */
EXPORT("body2Set") int cdjsBody2Set(int world0, int index1, int generation, int what)
{
	BODY_OR(0)
	const float* a = IO;
	switch (what)
	{
		case 0:
			cd2Body_SetTransform(id, (cd2Vec){a[0], a[1]}, cd2MakeRot(a[2]));
			break;
		case 1:
			cd2Body_SetLinearVelocity(id, (cd2Vec){a[0], a[1]});
			break;
		case 2:
			cd2Body_SetAngularVelocity(id, a[0]);
			break;
		case 3:
			cd2Body_ApplyForce(id, (cd2Vec){a[0], a[1]}, (cd2Vec){a[2], a[3]}, a[4] != 0.0f);
			break;
		case 4:
			cd2Body_ApplyForceToCenter(id, (cd2Vec){a[0], a[1]}, a[2] != 0.0f);
			break;
		case 5:
			cd2Body_ApplyTorque(id, a[0], a[1] != 0.0f);
			break;
		case 6:
			cd2Body_ApplyLinearImpulse(id, (cd2Vec){a[0], a[1]}, (cd2Vec){a[2], a[3]}, a[4] != 0.0f);
			break;
		case 7:
			cd2Body_ApplyLinearImpulseToCenter(id, (cd2Vec){a[0], a[1]}, a[2] != 0.0f);
			break;
		case 8:
			cd2Body_ApplyAngularImpulse(id, a[0], a[1] != 0.0f);
			break;
		case 9:
			cd2Body_SetType(id, (cd2BodyType)cdjsFloatToInt(a[0]));
			break;
		case 10:
			cd2Body_SetAwake(id, a[0] != 0.0f);
			break;
		case 11:
			if (a[0] != 0.0f)
			{
				cd2Body_Enable(id);
			}
			else
			{
				cd2Body_Disable(id);
			}
			break;
		case 12:
			cd2Body_SetFixedRotation(id, a[0] != 0.0f);
			break;
		case 13:
			cd2Body_SetBullet(id, a[0] != 0.0f);
			break;
		case 14:
			cd2Body_SetGravityScale(id, a[0]);
			break;
		case 15:
			cd2Body_SetLinearDamping(id, a[0]);
			break;
		case 16:
			cd2Body_SetAngularDamping(id, a[0]);
			break;
		case 17:
			cd2Body_EnableSleep(id, a[0] != 0.0f);
			break;
		default:
			return 0;
	}
	return 1;
}

/* ---- shapes ----------------------------------------------------------------------------------
 * Geometry in slot A (exports.c's 2D record: circle, capsule, aabb, box, polygon, segment), in the
 * body frame. IO in: density, friction, restitution, rollingResistance, tangentSpeed,
 * categoryBits (2 words), maskBits (2 words), groupIndex (int), flags (int: 1 sensor, 2 sensor
 * events, 4 contact events, 8 hit events, 16 pre-solve events, 32 flags given). Returns index1;
 * IO[0] out: generation. 0: stale body; -1: bad geometry or def. */
EXPORT("shape2Create") int cdjsShape2Create(int world0, int index1, int generation)
{
	BODY_OR(0)
	const float* in = IO;
	cd2ShapeDef def = cd2DefaultShapeDef();
	def.density = orDefault(in[0], def.density);
	def.friction = orDefault(in[1], def.friction);
	def.restitution = orDefault(in[2], def.restitution);
	def.rollingResistance = orDefault(in[3], def.rollingResistance);
	def.tangentSpeed = orDefault(in[4], def.tangentSpeed);
	def.filter.categoryBits = getU64(in + 5);
	def.filter.maskBits = getU64(in + 7);
	def.filter.groupIndex = getInt(in + 9);
	int flags = getInt(in + 10);
	if (flags & 32)
	{
		def.isSensor = (flags & 1) != 0;
		def.enableSensorEvents = (flags & 2) != 0;
		def.enableContactEvents = (flags & 4) != 0;
		def.enableHitEvents = (flags & 8) != 0;
		def.enablePreSolveEvents = (flags & 16) != 0;
	}
	const float* s = SLOT_A;
	cd2ShapeId shape = CD2_NULL_SHAPE_ID;
	for (int i = 1; i < 20; ++i)
	{
		if (!isfinite(s[i]))
		{
			return -1;
		}
	}
	switch (cdjsFloatToInt(s[0]))
	{
		case 0:
		{
			cd2Circle c = {{s[1], s[2]}, s[3]};
			shape = cd2CreateCircleShape(id, &def, &c);
			break;
		}
		case 1:
		{
			cd2Capsule c = {{s[1], s[2]}, {s[3], s[4]}, s[5]};
			shape = cd2CreateCapsuleShape(id, &def, &c);
			break;
		}
		case 2:
		case 3:
		{
			cd2Box box;
			if (cdjsFloatToInt(s[0]) == 2)
			{
				box.center = (cd2Vec){0.5f * (s[1] + s[3]), 0.5f * (s[2] + s[4])};
				box.halfExtents = (cd2Vec){0.5f * (s[3] - s[1]), 0.5f * (s[4] - s[2])};
				box.rotation = cd2MakeRot(0.0f);
			}
			else
			{
				box.center = (cd2Vec){s[1], s[2]};
				box.halfExtents = (cd2Vec){s[3], s[4]};
				box.rotation = cd2MakeRot(s[5]);
			}
			cd2Polygon polygon;
			memset(&polygon, 0, sizeof polygon);
			if (cd2MakeBoxPolygon(box, &polygon) != CD_OK)
			{
				return -1;
			}
			shape = cd2CreatePolygonShape(id, &def, &polygon);
			break;
		}
		case 4:
		{
			int count = cdjsFloatToInt(s[1]);
			if (count < 3 || count > CD2_MAX_POLYGON_VERTICES)
			{
				return -1;
			}
			cd2Vec points[CD2_MAX_POLYGON_VERTICES];
			for (int i = 0; i < count; ++i)
			{
				points[i] = (cd2Vec){s[3 + 2 * i], s[4 + 2 * i]};
			}
			cd2Polygon polygon;
			cdResult r = s[2] > 0.0f ? cd2MakeRoundedPolygon(points, count, s[2], &polygon)
									 : cd2MakePolygon(points, count, &polygon);
			if (r != CD_OK)
			{
				return -1;
			}
			shape = cd2CreatePolygonShape(id, &def, &polygon);
			break;
		}
		case 5:
		{
			cd2Segment seg = {{s[1], s[2]}, {s[3], s[4]}};
			shape = cd2CreateSegmentShape(id, &def, &seg);
			break;
		}
		default:
			return -1;
	}
	if (shape.index1 == 0)
	{
		return -1;
	}
	putInt(IO, (int32_t)shape.generation);
	return shape.index1;
}

/* A loop or open chain on the body (cd2CreateChainShape): `count` points (x y pairs, body frame)
 * at `points`; IO holds isLoop, friction, restitution (NaN: default), categoryBits (2 words),
 * maskBits (2 words), groupIndex (int), enableSensorEvents. Returns the chain's index1 with its
 * generation in IO[0] and its segment count in IO[1]; 0 for a stale body, -cdResult for bad points.
 * The chain's segment shapes are the body's new shapes (body2Shapes). */
EXPORT("chain2Create")
int cdjsChain2Create(int world0, int index1, int generation, const float* points, int count)
{
	BODY_OR(0)
	const float* in = IO;
	cd2ChainDef def = cd2DefaultChainDef();
	def.points = (const cd2Vec*)(const void*)points;
	def.count = count;
	def.isLoop = in[0] != 0.0f;
	def.friction = orDefault(in[1], def.friction);
	def.restitution = orDefault(in[2], def.restitution);
	def.filter.categoryBits = getU64(in + 3);
	def.filter.maskBits = getU64(in + 5);
	def.filter.groupIndex = getInt(in + 7);
	def.enableSensorEvents = in[8] != 0.0f;
	if (points == NULL || count < 0)
	{
		return -(int)CD_ERROR_INVALID_ARGUMENT;
	}
	/* The same checks as cd2CreateChain, for a precise error (the world only says "null id"). */
	cd2Chain* probe = NULL;
	cdResult result = cd2CreateChain(def.points, count, def.isLoop, &probe);
	cd2DestroyChain(probe);
	if (result != CD_OK)
	{
		return -(int)result;
	}
	cd2ChainId chain = cd2CreateChainShape(id, &def);
	if (chain.index1 == 0)
	{
		return -(int)CD_ERROR_INVALID_ARGUMENT;
	}
	putInt(IO, (int32_t)chain.generation);
	IO[1] = (float)cd2ChainShape_GetSegmentCount(chain);
	return chain.index1;
}

static bool validChain(int world0, int index1, int generation, cd2ChainId* out)
{
	if (world0 < 0 || world0 >= CD2_MAX_WORLDS || index1 <= 0 || getWorld(world0) == NULL)
	{
		return false;
	}
	*out = (cd2ChainId){index1, (uint16_t)world0, (uint32_t)generation};
	return cd2ChainShape_IsValid(*out);
}

/* The chain's segment count, 0 for a stale chain. */
EXPORT("chain2SegmentCount") int cdjsChain2SegmentCount(int world0, int index1, int generation)
{
	cd2ChainId chain;
	return validChain(world0, index1, generation, &chain) ? cd2ChainShape_GetSegmentCount(chain) : 0;
}

/* Destroys the chain and its segment shapes; 0 for a stale chain. */
EXPORT("chain2Destroy") int cdjsChain2Destroy(int world0, int index1, int generation)
{
	cd2ChainId chain;
	if (!validChain(world0, index1, generation, &chain))
	{
		return 0;
	}
	cd2DestroyChainShape(chain);
	return 1;
}

/* The body's shape ids into the output list (index1, generation each); count in IO[0]. */
EXPORT("body2Shapes") float* cdjsBody2Shapes(int world0, int index1, int generation)
{
	g_outCount = 0;
	putInt(IO, 0);
	BODY_OR(NULL)
	int count = cd2Body_GetShapeCount(id);
	cd2ShapeId* ids = (cd2ShapeId*)malloc((size_t)(count > 0 ? count : 1) * sizeof(cd2ShapeId));
	if (ids == NULL || !outReserve(2 * count))
	{
		free(ids);
		return NULL;
	}
	count = cd2Body_GetShapes(id, ids, count);
	for (int i = 0; i < count; ++i)
	{
		putShape(g_out + 2 * i, ids[i]);
	}
	free(ids);
	putInt(IO, count);
	return g_out;
}

EXPORT("shape2Destroy") int cdjsShape2Destroy(int world0, int index1, int generation)
{
	cd2ShapeId id;
	if (!validShape(world0, index1, generation, &id))
	{
		return 0;
	}
	cd2DestroyShape(id, true);
	return 1;
}

/* IO out: type, body index1, body generation (ints), density, friction, restitution, sensor,
 * aabb min x, min y, max x, max y, categoryBits (2 words), maskBits (2 words), groupIndex. */
EXPORT("shape2Get") int cdjsShape2Get(int world0, int index1, int generation)
{
	cd2ShapeId id;
	if (!validShape(world0, index1, generation, &id))
	{
		return 0;
	}
	float* o = IO;
	cd2BodyId body = cd2Shape_GetBody(id);
	putInt(o, (int32_t)cd2Shape_GetType(id));
	putInt(o + 1, body.index1);
	putInt(o + 2, (int32_t)body.generation);
	o[3] = cd2Shape_GetDensity(id);
	o[4] = cd2Shape_GetFriction(id);
	o[5] = cd2Shape_GetRestitution(id);
	o[6] = cd2Shape_IsSensor(id) ? 1.0f : 0.0f;
	cd2Aabb box = cd2Shape_GetAabb(id);
	o[7] = box.min.x;
	o[8] = box.min.y;
	o[9] = box.max.x;
	o[10] = box.max.y;
	cd2Filter f = cd2Shape_GetFilter(id);
	putU64(o + 11, f.categoryBits);
	putU64(o + 13, f.maskBits);
	putInt(o + 15, f.groupIndex);
	return 1;
}

/* what: 0 density (a, updateMass), 1 friction, 2 restitution, 3 filter (category 2 words, mask 2
 * words, group int), 4 sensor events, 5 contact events, 6 hit events, 7 pre-solve events. */
EXPORT("shape2Set") int cdjsShape2Set(int world0, int index1, int generation, int what)
{
	cd2ShapeId id;
	if (!validShape(world0, index1, generation, &id))
	{
		return 0;
	}
	const float* a = IO;
	switch (what)
	{
		case 0:
			cd2Shape_SetDensity(id, a[0], a[1] != 0.0f);
			break;
		case 1:
			cd2Shape_SetFriction(id, a[0]);
			break;
		case 2:
			cd2Shape_SetRestitution(id, a[0]);
			break;
		case 3:
		{
			cd2Filter f = {getU64(a), getU64(a + 2), getInt(a + 4)};
			cd2Shape_SetFilter(id, f);
			break;
		}
		case 4:
			cd2Shape_EnableSensorEvents(id, a[0] != 0.0f);
			break;
		case 5:
			cd2Shape_EnableContactEvents(id, a[0] != 0.0f);
			break;
		case 6:
			cd2Shape_EnableHitEvents(id, a[0] != 0.0f);
			break;
		case 7:
			cd2Shape_EnablePreSolveEvents(id, a[0] != 0.0f);
			break;
		default:
			return 0;
	}
	return 1;
}

/* ---- joints ----------------------------------------------------------------------------------
 * IO in: type (cd2JointType), bodyA index1, generation, bodyB index1, generation (ints), then
 * anchorA x y, anchorB x y (body frames), axis x y, referenceAngle, enableSpring, hertz,
 * dampingRatio, enableLimit, lower, upper, enableMotor, maxMotor, motorSpeed, collideConnected,
 * length, target x y, maxForce, maxTorque, linearOffset x y, angularOffset, correctionFactor,
 * angularHertz, angularDampingRatio, forceThreshold, torqueThreshold, constraintHertz,
 * constraintDampingRatio (NaN: default). Returns index1
 * (IO[0] out: generation), 0 for a stale body, -1 for a bad def. */
EXPORT("joint2Create") int cdjsJoint2Create(int world0)
{
	JsWorld* w = getWorld(world0);
	if (w == NULL)
	{
		return 0;
	}
	const float* in = IO;
	cd2BodyId a, b;
	if (!validBody(world0, getInt(in + 1), getInt(in + 2), &a) ||
		!validBody(world0, getInt(in + 3), getInt(in + 4), &b))
	{
		return 0;
	}
	const float* p = in + 5;
	cd2Vec anchorA = {orDefault(p[0], 0.0f), orDefault(p[1], 0.0f)};
	cd2Vec anchorB = {orDefault(p[2], 0.0f), orDefault(p[3], 0.0f)};
	cd2Vec axis = {orDefault(p[4], 1.0f), orDefault(p[5], 0.0f)};
	float referenceAngle = orDefault(p[6], 0.0f);
	cd2JointId id = CD2_NULL_JOINT_ID;
	switch (getInt(in))
	{
		case CD2_DISTANCE_JOINT:
		{
			cd2DistanceJointDef d = cd2DefaultDistanceJointDef();
			d.bodyIdA = a;
			d.bodyIdB = b;
			d.localAnchorA = anchorA;
			d.localAnchorB = anchorB;
			d.enableSpring = flagOr(p[7], d.enableSpring);
			d.hertz = orDefault(p[8], d.hertz);
			d.dampingRatio = orDefault(p[9], d.dampingRatio);
			d.enableLimit = flagOr(p[10], d.enableLimit);
			d.minLength = orDefault(p[11], d.minLength);
			d.maxLength = orDefault(p[12], d.maxLength);
			d.enableMotor = flagOr(p[13], d.enableMotor);
			d.maxMotorForce = orDefault(p[14], d.maxMotorForce);
			d.motorSpeed = orDefault(p[15], d.motorSpeed);
			d.collideConnected = flagOr(p[16], d.collideConnected);
			if (isnan(p[17]))
			{
				cd2Vec pa = cd2Body_GetWorldPoint(a, anchorA), pb = cd2Body_GetWorldPoint(b, anchorB);
				d.length = cd2Length(cd2Sub(pb, pa));
			}
			else
			{
				d.length = p[17];
			}
			id = cd2CreateDistanceJoint(w->id, &d);
			break;
		}
		case CD2_FILTER_JOINT:
		{
			cd2FilterJointDef d = cd2DefaultFilterJointDef();
			d.bodyIdA = a;
			d.bodyIdB = b;
			id = cd2CreateFilterJoint(w->id, &d);
			break;
		}
		case CD2_MOTOR_JOINT:
		{
			cd2MotorJointDef d = cd2DefaultMotorJointDef();
			d.bodyIdA = a;
			d.bodyIdB = b;
			d.linearOffset = (cd2Vec){orDefault(p[22], d.linearOffset.x), orDefault(p[23], d.linearOffset.y)};
			d.angularOffset = orDefault(p[24], d.angularOffset);
			d.maxForce = orDefault(p[20], d.maxForce);
			d.maxTorque = orDefault(p[21], d.maxTorque);
			d.correctionFactor = orDefault(p[25], d.correctionFactor);
			d.collideConnected = flagOr(p[16], d.collideConnected);
			id = cd2CreateMotorJoint(w->id, &d);
			break;
		}
		case CD2_MOUSE_JOINT:
		{
			cd2MouseJointDef d = cd2DefaultMouseJointDef();
			d.bodyIdA = a;
			d.bodyIdB = b;
			d.target = (cd2Vec){orDefault(p[18], 0.0f), orDefault(p[19], 0.0f)};
			d.hertz = orDefault(p[8], d.hertz);
			d.dampingRatio = orDefault(p[9], d.dampingRatio);
			d.maxForce = orDefault(p[20], d.maxForce);
			d.collideConnected = flagOr(p[16], d.collideConnected);
			id = cd2CreateMouseJoint(w->id, &d);
			break;
		}
		case CD2_PRISMATIC_JOINT:
		case CD2_WHEEL_JOINT:
		{
			if (getInt(in) == CD2_PRISMATIC_JOINT)
			{
				cd2PrismaticJointDef d = cd2DefaultPrismaticJointDef();
				d.bodyIdA = a;
				d.bodyIdB = b;
				d.localAnchorA = anchorA;
				d.localAnchorB = anchorB;
				d.localAxisA = axis;
				d.referenceAngle = referenceAngle;
				d.enableSpring = flagOr(p[7], d.enableSpring);
				d.hertz = orDefault(p[8], d.hertz);
				d.dampingRatio = orDefault(p[9], d.dampingRatio);
				d.enableLimit = flagOr(p[10], d.enableLimit);
				d.lowerTranslation = orDefault(p[11], d.lowerTranslation);
				d.upperTranslation = orDefault(p[12], d.upperTranslation);
				d.enableMotor = flagOr(p[13], d.enableMotor);
				d.maxMotorForce = orDefault(p[14], d.maxMotorForce);
				d.motorSpeed = orDefault(p[15], d.motorSpeed);
				d.collideConnected = flagOr(p[16], d.collideConnected);
				id = cd2CreatePrismaticJoint(w->id, &d);
			}
			else
			{
				cd2WheelJointDef d = cd2DefaultWheelJointDef();
				d.bodyIdA = a;
				d.bodyIdB = b;
				d.localAnchorA = anchorA;
				d.localAnchorB = anchorB;
				d.localAxisA = axis;
				d.enableSpring = flagOr(p[7], d.enableSpring);
				d.hertz = orDefault(p[8], d.hertz);
				d.dampingRatio = orDefault(p[9], d.dampingRatio);
				d.enableLimit = flagOr(p[10], d.enableLimit);
				d.lowerTranslation = orDefault(p[11], d.lowerTranslation);
				d.upperTranslation = orDefault(p[12], d.upperTranslation);
				d.enableMotor = flagOr(p[13], d.enableMotor);
				d.maxMotorTorque = orDefault(p[14], d.maxMotorTorque);
				d.motorSpeed = orDefault(p[15], d.motorSpeed);
				d.collideConnected = flagOr(p[16], d.collideConnected);
				id = cd2CreateWheelJoint(w->id, &d);
			}
			break;
		}
		case CD2_REVOLUTE_JOINT:
		{
			cd2RevoluteJointDef d = cd2DefaultRevoluteJointDef();
			d.bodyIdA = a;
			d.bodyIdB = b;
			d.localAnchorA = anchorA;
			d.localAnchorB = anchorB;
			d.referenceAngle = referenceAngle;
			d.enableSpring = flagOr(p[7], d.enableSpring);
			d.hertz = orDefault(p[8], d.hertz);
			d.dampingRatio = orDefault(p[9], d.dampingRatio);
			d.enableLimit = flagOr(p[10], d.enableLimit);
			d.lowerAngle = orDefault(p[11], d.lowerAngle);
			d.upperAngle = orDefault(p[12], d.upperAngle);
			d.enableMotor = flagOr(p[13], d.enableMotor);
			d.maxMotorTorque = orDefault(p[14], d.maxMotorTorque);
			d.motorSpeed = orDefault(p[15], d.motorSpeed);
			d.collideConnected = flagOr(p[16], d.collideConnected);
			id = cd2CreateRevoluteJoint(w->id, &d);
			break;
		}
		case CD2_WELD_JOINT:
		{
			cd2WeldJointDef d = cd2DefaultWeldJointDef();
			d.bodyIdA = a;
			d.bodyIdB = b;
			d.localAnchorA = anchorA;
			d.localAnchorB = anchorB;
			d.referenceAngle = referenceAngle;
			d.linearHertz = orDefault(p[8], d.linearHertz);
			d.linearDampingRatio = orDefault(p[9], d.linearDampingRatio);
			d.angularHertz = orDefault(p[26], d.angularHertz);
			d.angularDampingRatio = orDefault(p[27], d.angularDampingRatio);
			d.collideConnected = flagOr(p[16], d.collideConnected);
			id = cd2CreateWeldJoint(w->id, &d);
			break;
		}
		default:
			return -1;
	}
	if (id.index1 == 0)
	{
		return -1;
	}
	/* The thresholds (checked >= 0 by the JavaScript side) on every kind but the filter joint. */
	if (getInt(in) != CD2_FILTER_JOINT)
	{
		cd2Joint_SetForceThreshold(id, orDefault(p[28], 0.0f));
		cd2Joint_SetTorqueThreshold(id, orDefault(p[29], 0.0f));
	}
	if (p[30] == p[30] || p[31] == p[31])
	{
		cd2Joint_SetConstraintTuning(id, orDefault(p[30], 0.0f), orDefault(p[31], 0.0f));
	}
	putInt(IO, (int32_t)id.generation);
	return id.index1;
}

EXPORT("joint2Destroy") int cdjsJoint2Destroy(int world0, int index1, int generation)
{
	cd2JointId id;
	if (!validJoint(world0, index1, generation, &id))
	{
		return 0;
	}
	cd2DestroyJoint(id);
	return 1;
}

/* IO out: type, bodyA index1, generation, bodyB index1, generation (ints), force x y, torque,
 * revolute angle, translation (prismatic, wheel), current length (distance), force threshold,
 * torque threshold, constraint hertz, constraint damping ratio. */
EXPORT("joint2Get") int cdjsJoint2Get(int world0, int index1, int generation)
{
	cd2JointId id;
	if (!validJoint(world0, index1, generation, &id))
	{
		return 0;
	}
	float* o = IO;
	cd2JointType type = cd2Joint_GetType(id);
	cd2BodyId a = cd2Joint_GetBodyA(id), b = cd2Joint_GetBodyB(id);
	putInt(o, (int32_t)type);
	putInt(o + 1, a.index1);
	putInt(o + 2, (int32_t)a.generation);
	putInt(o + 3, b.index1);
	putInt(o + 4, (int32_t)b.generation);
	cd2Vec f = cd2Joint_GetConstraintForce(id);
	o[5] = f.x;
	o[6] = f.y;
	o[7] = cd2Joint_GetConstraintTorque(id);
	o[8] = type == CD2_REVOLUTE_JOINT ? cd2RevoluteJoint_GetAngle(id) : 0.0f;
	o[9] = type == CD2_PRISMATIC_JOINT || type == CD2_WHEEL_JOINT ? cd2Joint_GetTranslation(id) : 0.0f;
	o[10] = type == CD2_DISTANCE_JOINT ? cd2DistanceJoint_GetCurrentLength(id) : 0.0f;
	o[11] = cd2Joint_GetForceThreshold(id);
	o[12] = cd2Joint_GetTorqueThreshold(id);
	o[13] = cd2Joint_GetConstraintHertz(id);
	o[14] = cd2Joint_GetConstraintDampingRatio(id);
	return 1;
}

/* what: 0 motor on/off (a), 1 motor speed (a), 2 max motor (a), 3 limit on/off (a), 4 limits
 * (lower, upper), 5 spring on/off (a), 6 spring hertz (a), 7 spring damping ratio (a), 8 mouse
 * target (x, y), 9 distance length (a), 10 motor joint linear offset (x, y), 11 motor joint
 * angular offset (a), 12 wake bodies, 13 force threshold (a), 14 torque threshold (a), 15
 * constraint tuning (hertz, damping ratio). Returns 1, 0 stale, -1 wrong joint type for the call. */
EXPORT("joint2Set") int cdjsJoint2Set(int world0, int index1, int generation, int what)
{
	cd2JointId id;
	if (!validJoint(world0, index1, generation, &id))
	{
		return 0;
	}
	const float* a = IO;
	cd2JointType type = cd2Joint_GetType(id);
	bool motorType = type == CD2_DISTANCE_JOINT || type == CD2_REVOLUTE_JOINT ||
					 type == CD2_PRISMATIC_JOINT || type == CD2_WHEEL_JOINT;
	switch (what)
	{
		case 0:
		case 1:
		case 2:
		case 3:
		case 4:
		case 5:
		case 6:
		case 7:
			if (!motorType)
			{
				return -1;
			}
			if (what == 0)
			{
				cd2Joint_EnableMotor(id, a[0] != 0.0f);
			}
			else if (what == 1)
			{
				cd2Joint_SetMotorSpeed(id, a[0]);
			}
			else if (what == 2)
			{
				cd2Joint_SetMaxMotor(id, a[0]);
			}
			else if (what == 3)
			{
				cd2Joint_EnableLimit(id, a[0] != 0.0f);
			}
			else if (what == 4)
			{
				if (type == CD2_DISTANCE_JOINT)
				{
					cd2DistanceJoint_SetLengthRange(id, a[0], a[1]);
				}
				else
				{
					cd2Joint_SetLimits(id, a[0], a[1]);
				}
			}
			else if (what == 5)
			{
				cd2Joint_EnableSpring(id, a[0] != 0.0f);
			}
			else if (what == 6)
			{
				cd2Joint_SetSpringHertz(id, a[0]);
			}
			else
			{
				cd2Joint_SetSpringDampingRatio(id, a[0]);
			}
			break;
		case 8:
			if (type != CD2_MOUSE_JOINT)
			{
				return -1;
			}
			cd2MouseJoint_SetTarget(id, (cd2Vec){a[0], a[1]});
			break;
		case 9:
			if (type != CD2_DISTANCE_JOINT)
			{
				return -1;
			}
			cd2DistanceJoint_SetLength(id, a[0]);
			break;
		case 10:
			if (type != CD2_MOTOR_JOINT)
			{
				return -1;
			}
			cd2MotorJoint_SetLinearOffset(id, (cd2Vec){a[0], a[1]});
			break;
		case 11:
			if (type != CD2_MOTOR_JOINT)
			{
				return -1;
			}
			cd2MotorJoint_SetAngularOffset(id, a[0]);
			break;
		case 12:
			cd2Joint_WakeBodies(id);
			break;
		case 13:
		case 14:
			if (type == CD2_FILTER_JOINT)
			{
				return -1;
			}
			if (what == 13)
			{
				cd2Joint_SetForceThreshold(id, a[0]);
			}
			else
			{
				cd2Joint_SetTorqueThreshold(id, a[0]);
			}
			break;
		case 15:
			if (type != CD2_DISTANCE_JOINT && type != CD2_PRISMATIC_JOINT && type != CD2_REVOLUTE_JOINT &&
				type != CD2_WELD_JOINT && type != CD2_WHEEL_JOINT)
			{
				return -1;
			}
			cd2Joint_SetConstraintTuning(id, a[0], a[1]);
			break;
		default:
			return -1;
	}
	return 1;
}

/* ---- events ----------------------------------------------------------------------------------
 * All events of the last step in one record list; returns a byte pointer to it:
 * counts (ints): contact begin, end, hit, sensor begin, end, body moves, joint events; then
 * contact begin: a index1 gen, b index1 gen (ints), normal x y, pointCount (int), then two points
 *   (x, y, separation) = 13 floats (a one-point manifold repeats its point);
 * contact end: a index1 gen, b index1 gen = 4;
 * hit: a, b (4 ints), point x y, normal x y, approachSpeed = 9;
 * sensor begin / end: sensor index1 gen, visitor index1 gen = 4;
 * body move: body index1 gen (ints), x, y, cos, sin, fellAsleep = 7;
 * joint event: joint index1 gen (ints), force x y, torque = 5. */
EXPORT("world2Events") float* cdjsWorld2Events(int world0)
{
	JsWorld* w = getWorld(world0);
	g_outCount = 0;
	if (w == NULL)
	{
		return NULL;
	}
	cd2ContactEvents c = cd2World_GetContactEvents(w->id);
	cd2SensorEvents s = cd2World_GetSensorEvents(w->id);
	cd2BodyEvents b = cd2World_GetBodyEvents(w->id);
	cd2JointEvents j = cd2World_GetJointEvents(w->id);
	int total = 7 + 13 * c.beginCount + 4 * c.endCount + 9 * c.hitCount + 4 * (s.beginCount + s.endCount) +
				7 * b.moveCount + 5 * j.count;
	if (!outReserve(total))
	{
		return NULL;
	}
	float* o = g_out;
	putInt(o, c.beginCount);
	putInt(o + 1, c.endCount);
	putInt(o + 2, c.hitCount);
	putInt(o + 3, s.beginCount);
	putInt(o + 4, s.endCount);
	putInt(o + 5, b.moveCount);
	putInt(o + 6, j.count);
	o += 7;
	for (int i = 0; i < c.beginCount; ++i, o += 13)
	{
		const cd2ContactBeginTouchEvent* e = c.beginEvents + i;
		putShape(o, e->shapeIdA);
		putShape(o + 2, e->shapeIdB);
		o[4] = e->manifold.normal.x;
		o[5] = e->manifold.normal.y;
		putInt(o + 6, e->manifold.pointCount);
		const cd2ManifoldPoint* p0 = e->manifold.points;
		const cd2ManifoldPoint* p1 = e->manifold.points + (e->manifold.pointCount > 1 ? 1 : 0);
		o[7] = p0->point.x;
		o[8] = p0->point.y;
		o[9] = p0->separation;
		o[10] = p1->point.x;
		o[11] = p1->point.y;
		o[12] = p1->separation;
	}
	for (int i = 0; i < c.endCount; ++i, o += 4)
	{
		putShape(o, c.endEvents[i].shapeIdA);
		putShape(o + 2, c.endEvents[i].shapeIdB);
	}
	for (int i = 0; i < c.hitCount; ++i, o += 9)
	{
		const cd2ContactHitEvent* e = c.hitEvents + i;
		putShape(o, e->shapeIdA);
		putShape(o + 2, e->shapeIdB);
		o[4] = e->point.x;
		o[5] = e->point.y;
		o[6] = e->normal.x;
		o[7] = e->normal.y;
		o[8] = e->approachSpeed;
	}
	for (int i = 0; i < s.beginCount; ++i, o += 4)
	{
		putShape(o, s.beginEvents[i].sensorShapeId);
		putShape(o + 2, s.beginEvents[i].visitorShapeId);
	}
	for (int i = 0; i < s.endCount; ++i, o += 4)
	{
		putShape(o, s.endEvents[i].sensorShapeId);
		putShape(o + 2, s.endEvents[i].visitorShapeId);
	}
	for (int i = 0; i < b.moveCount; ++i, o += 7)
	{
		const cd2BodyMoveEvent* e = b.moveEvents + i;
		putInt(o, e->bodyId.index1);
		putInt(o + 1, (int32_t)e->bodyId.generation);
		o[2] = e->transform.p.x;
		o[3] = e->transform.p.y;
		o[4] = e->transform.q.c;
		o[5] = e->transform.q.s;
		o[6] = e->fellAsleep ? 1.0f : 0.0f;
	}
	for (int i = 0; i < j.count; ++i, o += 5)
	{
		const cd2JointEvent* e = j.jointEvents + i;
		putInt(o, e->jointId.index1);
		putInt(o + 1, (int32_t)e->jointId.generation);
		o[2] = e->force.x;
		o[3] = e->force.y;
		o[4] = e->torque;
	}
	return g_out;
}

/* ---- callbacks -------------------------------------------------------------------------------- */
static float g_manifold[8];

static bool preSolveThunk(cd2ShapeId a, cd2ShapeId b, const cd2Manifold* m, void* context)
{
	(void)context;
	g_manifold[0] = m->normal.x;
	g_manifold[1] = m->normal.y;
	putInt(g_manifold + 2, m->pointCount);
	for (int k = 0; k < 2; ++k)
	{
		g_manifold[3 + 2 * k] = m->points[k].point.x;
		g_manifold[4 + 2 * k] = m->points[k].point.y;
	}
	g_manifold[7] = m->pointCount > 0 ? m->points[0].separation : 0.0f;
	return cdjsImportPreSolve(a.world0, a.index1, (int)a.generation, b.index1, (int)b.generation,
							  g_manifold) != 0;
}

static bool customFilterThunk(cd2ShapeId a, cd2ShapeId b, void* context)
{
	(void)context;
	return cdjsImportCustomFilter(a.world0, a.index1, (int)a.generation, b.index1, (int)b.generation) != 0;
}

EXPORT("world2SetPreSolve") void cdjsWorld2SetPreSolve(int world0, int on)
{
	JsWorld* w = getWorld(world0);
	if (w != NULL)
	{
		cd2World_SetPreSolveCallback(w->id, on ? preSolveThunk : NULL, NULL);
	}
}

EXPORT("world2SetCustomFilter") void cdjsWorld2SetCustomFilter(int world0, int on)
{
	JsWorld* w = getWorld(world0);
	if (w != NULL)
	{
		cd2World_SetCustomFilterCallback(w->id, on ? customFilterThunk : NULL, NULL);
	}
}

/* ---- queries ---------------------------------------------------------------------------------
 * Hits collect into the output list (index1, generation per shape; ray hits add point x y, normal
 * x y, fraction). Each returns a byte pointer; the count is in IO[0] (int). */
static bool collectShape(cd2ShapeId id, void* context)
{
	(void)context;
	if (!outReserve(2))
	{
		return false;
	}
	putShape(g_out + g_outCount, id);
	g_outCount += 2;
	return true;
}

static cdReal collectRay(cd2ShapeId id, cd2Vec point, cd2Vec normal, cdReal fraction, void* context)
{
	(void)context;
	if (!outReserve(7))
	{
		return 0;
	}
	float* o = g_out + g_outCount;
	putShape(o, id);
	o[2] = point.x;
	o[3] = point.y;
	o[4] = normal.x;
	o[5] = normal.y;
	o[6] = fraction;
	g_outCount += 7;
	return CD_R(1.0);
}

static cd2QueryFilter queryFilter(const float* in)
{
	cd2QueryFilter f = {getU64(in), getU64(in + 2)};
	return f;
}

/* IO in: min x y, max x y, filter (category 2 words, mask 2 words). */
EXPORT("world2OverlapAabb") float* cdjsWorld2OverlapAabb(int world0)
{
	JsWorld* w = getWorld(world0);
	g_outCount = 0;
	putInt(IO, 0);
	if (w == NULL)
	{
		return NULL;
	}
	const float* in = IO;
	cd2Aabb box = {{in[0], in[1]}, {in[2], in[3]}};
	cd2World_OverlapAabb(w->id, box, queryFilter(in + 4), collectShape, NULL);
	putInt(IO, g_outCount / 2);
	return g_out;
}

/* Shape in slot A (world space; exports.c's record for circle, capsule, box, polygon, segment),
 * IO in: filter. Returns NULL (count -1) for bad geometry. */
static bool decodeWorldShape(const float* s, cd2Shape* out)
{
	memset(out, 0, sizeof *out);
	for (int i = 1; i < 20; ++i)
	{
		if (!isfinite(s[i]))
		{
			return false;
		}
	}
	switch (cdjsFloatToInt(s[0]))
	{
		case 0:
			*out = cd2MakeCircleShape((cd2Circle){{s[1], s[2]}, s[3]});
			break;
		case 1:
			*out = cd2MakeCapsuleShape((cd2Capsule){{s[1], s[2]}, {s[3], s[4]}, s[5]});
			break;
		case 2:
			*out = cd2MakeAabbShape((cd2Aabb){{s[1], s[2]}, {s[3], s[4]}});
			break;
		case 3:
			*out = cd2MakeBoxShape((cd2Box){{s[1], s[2]}, {s[3], s[4]}, cd2MakeRot(s[5])});
			break;
		case 4:
		{
			int count = cdjsFloatToInt(s[1]);
			if (count < 3 || count > CD2_MAX_POLYGON_VERTICES)
			{
				return false;
			}
			cd2Vec points[CD2_MAX_POLYGON_VERTICES];
			for (int i = 0; i < count; ++i)
			{
				points[i] = (cd2Vec){s[3 + 2 * i], s[4 + 2 * i]};
			}
			cd2Polygon polygon;
			cdResult r = s[2] > 0.0f ? cd2MakeRoundedPolygon(points, count, s[2], &polygon)
									 : cd2MakePolygon(points, count, &polygon);
			if (r != CD_OK)
			{
				return false;
			}
			*out = cd2MakePolygonShape(&polygon);
			break;
		}
		case 5:
			*out = cd2MakeSegmentShape((cd2Segment){{s[1], s[2]}, {s[3], s[4]}});
			break;
		default:
			return false;
	}
	return cd2ValidateShape(out) == CD_OK;
}

EXPORT("world2OverlapShape") float* cdjsWorld2OverlapShape(int world0)
{
	JsWorld* w = getWorld(world0);
	g_outCount = 0;
	cd2QueryFilter filter = queryFilter(IO);
	putInt(IO, 0);
	if (w == NULL)
	{
		return NULL;
	}
	cd2Shape shape;
	if (!decodeWorldShape(SLOT_A, &shape))
	{
		putInt(IO, -1);
		return NULL;
	}
	cd2World_OverlapShape(w->id, &shape, filter, collectShape, NULL);
	putInt(IO, g_outCount / 2);
	return g_out;
}

/* IO in: origin x y, translation x y, filter. IO out: hit (int), shape index1 gen (ints), point
 * x y, normal x y, fraction. */
EXPORT("world2RaycastClosest") int cdjsWorld2RaycastClosest(int world0)
{
	JsWorld* w = getWorld(world0);
	if (w == NULL)
	{
		return 0;
	}
	const float* in = IO;
	cd2RayResult r =
		cd2World_RaycastClosest(w->id, (cd2Vec){in[0], in[1]}, (cd2Vec){in[2], in[3]}, queryFilter(in + 4));
	float* o = IO;
	putInt(o, r.hit ? 1 : 0);
	putShape(o + 1, r.shapeId);
	o[3] = r.point.x;
	o[4] = r.point.y;
	o[5] = r.normal.x;
	o[6] = r.normal.y;
	o[7] = r.fraction;
	return r.hit ? 1 : 0;
}

/* Every hit along the ray (unordered). IO in as world2RaycastClosest; count out in IO[0]. */
EXPORT("world2Raycast") float* cdjsWorld2Raycast(int world0)
{
	JsWorld* w = getWorld(world0);
	g_outCount = 0;
	if (w == NULL)
	{
		putInt(IO, 0);
		return NULL;
	}
	const float* in = IO;
	cd2Vec origin = {in[0], in[1]}, translation = {in[2], in[3]};
	cd2QueryFilter filter = queryFilter(in + 4);
	cd2World_Raycast(w->id, origin, translation, filter, collectRay, NULL);
	putInt(IO, g_outCount / 7);
	return g_out;
}

/* Shape in slot A (world space) moved by IO's translation x y; IO in: translation, filter. Hits as
 * world2Raycast. */
EXPORT("world2ShapeCast") float* cdjsWorld2ShapeCast(int world0)
{
	JsWorld* w = getWorld(world0);
	g_outCount = 0;
	cd2Vec translation = {IO[0], IO[1]};
	cd2QueryFilter filter = queryFilter(IO + 2);
	putInt(IO, 0);
	if (w == NULL)
	{
		return NULL;
	}
	cd2Shape shape;
	if (!decodeWorldShape(SLOT_A, &shape))
	{
		putInt(IO, -1);
		return NULL;
	}
	cd2World_ShapeCast(w->id, &shape, translation, filter, collectRay, NULL);
	putInt(IO, g_outCount / 7);
	return g_out;
}

/* ---- snapshots -------------------------------------------------------------------------------- */
EXPORT("world2StateSize") int cdjsWorld2StateSize(int world0)
{
	JsWorld* w = getWorld(world0);
	return w == NULL ? -1 : (int)cd2World_GetStateSize(w->id);
}

/* Writes the state into buffer (capacity bytes). Returns the cdResult. */
EXPORT("world2SaveState") int cdjsWorld2SaveState(int world0, void* buffer, int capacity)
{
	JsWorld* w = getWorld(world0);
	if (w == NULL || capacity < 0)
	{
		return CD_ERROR_INVALID_ARGUMENT;
	}
	return (int)cd2World_SaveState(w->id, buffer, (size_t)capacity);
}

EXPORT("world2RestoreState") int cdjsWorld2RestoreState(int world0, const void* buffer, int size)
{
	JsWorld* w = getWorld(world0);
	if (w == NULL || size < 0)
	{
		return CD_ERROR_INVALID_ARGUMENT;
	}
	return (int)cd2World_RestoreState(w->id, buffer, (size_t)size);
}

/* ---- kinematic character mover (world2.h) ------------------------------------------------------
 * Planes as 7 floats: shape index1 gen (ints), normal x y, separation, point x y. */
#define MOVER_MAX_PLANES 32

typedef struct MoverPlanes
{
	cd2PlaneResult planes[MOVER_MAX_PLANES];
	int count;
	uint64_t oneWayBits;
} MoverPlanes;

/* One-way shapes (category in oneWayBits) only hold the mover up from above: their planes count
 * when the normal points up and the mover is not already deep inside. */
static bool collectPlane(const cd2PlaneResult* plane, void* context)
{
	MoverPlanes* list = (MoverPlanes*)context;
	if (list->oneWayBits != 0 && (cd2Shape_GetFilter(plane->shapeId).categoryBits & list->oneWayBits) != 0)
	{
		if (plane->normal.y < 0.7f || plane->separation < -0.05f)
		{
			return true;
		}
	}
	if (list->count < MOVER_MAX_PLANES)
	{
		list->planes[list->count++] = *plane;
	}
	return true;
}

static void putPlanes(const MoverPlanes* list)
{
	g_outCount = 0;
	if (!outReserve(7 * list->count + 1))
	{
		putInt(IO, 0);
		return;
	}
	for (int i = 0; i < list->count; ++i)
	{
		const cd2PlaneResult* p = list->planes + i;
		float* o = g_out + 7 * i;
		putShape(o, p->shapeId);
		o[2] = p->normal.x;
		o[3] = p->normal.y;
		o[4] = p->separation;
		o[5] = p->point.x;
		o[6] = p->point.y;
	}
	putInt(IO, list->count);
}

static bool readCapsule(const float* in, cd2Capsule* out)
{
	for (int i = 0; i < 5; ++i)
	{
		if (!isfinite(in[i]))
		{
			return false;
		}
	}
	*out = (cd2Capsule){{in[0], in[1]}, {in[2], in[3]}, in[4]};
	return in[4] > 0.0f;
}

/* IO in: capsule (p1 x y, p2 x y, radius; world), filter (4 words). Planes to the output list,
 * count in IO[0]; returns the list's byte pointer (NULL for a stale world or bad capsule). */
EXPORT("mover2Collide") float* cdjsMover2Collide(int world0)
{
	JsWorld* w = getWorld(world0);
	cd2Capsule capsule;
	if (w == NULL || !readCapsule(IO, &capsule))
	{
		putInt(IO, -1);
		return NULL;
	}
	MoverPlanes list;
	list.count = 0;
	list.oneWayBits = 0;
	cd2World_CollideMover(w->id, &capsule, queryFilter(IO + 5), collectPlane, &list);
	putPlanes(&list);
	return g_out;
}

/* IO in: capsule (5), translation x y, filter (4 words). Returns the fraction, -1 on bad input. */
EXPORT("mover2Cast") float cdjsMover2Cast(int world0)
{
	JsWorld* w = getWorld(world0);
	cd2Capsule capsule;
	if (w == NULL || !readCapsule(IO, &capsule) || !isfinite(IO[5]) || !isfinite(IO[6]))
	{
		return -1.0f;
	}
	return cd2World_CastMover(w->id, &capsule, (cd2Vec){IO[5], IO[6]}, queryFilter(IO + 7));
}

/* IO in: planes count (int), then planes (7 floats each, from the output list layout), then the
 * vector x y; what: 0 cd2SolvePlanes, 1 cd2ClipVector. IO out: x y. */
EXPORT("mover2Planes") int cdjsMover2Planes(int what)
{
	int count = getInt(IO);
	if (count < 0 || count > MOVER_MAX_PLANES)
	{
		return 0;
	}
	cd2PlaneResult planes[MOVER_MAX_PLANES];
	const float* p = IO + 1;
	for (int i = 0; i < count; ++i, p += 7)
	{
		planes[i].shapeId = CD2_NULL_SHAPE_ID;
		planes[i].normal = (cd2Vec){p[2], p[3]};
		planes[i].separation = p[4];
		planes[i].point = (cd2Vec){p[5], p[6]};
	}
	cd2Vec v = {p[0], p[1]};
	cd2Vec r = what == 0 ? cd2SolvePlanes(v, planes, count) : cd2ClipVector(v, planes, count);
	IO[0] = r.x;
	IO[1] = r.y;
	return 1;
}

/* One frame of world2.h's mover loop. IO in: capsule in the character's frame (p1 x y, p2 x y,
 * radius), position x y, velocity x y, dt, filter (4 words), oneWayBits (2 words). IO out:
 * position x y, velocity x y, then the planes of the target (output list, count in IO[4]).
 * Returns the output list's byte pointer, NULL on bad input. */
EXPORT("mover2Move") float* cdjsMover2Move(int world0)
{
	JsWorld* w = getWorld(world0);
	const float* in = IO;
	cd2Capsule local;
	if (w == NULL || !readCapsule(in, &local))
	{
		return NULL;
	}
	for (int i = 5; i < 10; ++i)
	{
		if (!isfinite(in[i]))
		{
			return NULL;
		}
	}
	cd2Vec position = {in[5], in[6]}, velocity = {in[7], in[8]};
	float dt = in[9];
	cd2QueryFilter filter = queryFilter(in + 10);
	MoverPlanes list;
	list.count = 0;
	list.oneWayBits = getU64(in + 14);
	cd2Vec target = cd2MulAdd(position, dt, velocity);
	for (int i = 0; i < 4; ++i)
	{
		list.count = 0;
		cd2Capsule at = {cd2Add(target, local.p1), cd2Add(target, local.p2), local.radius};
		cd2World_CollideMover(w->id, &at, filter, collectPlane, &list);
		target = cd2Add(target, cd2SolvePlanes(CD2_VEC_ZERO, list.planes, list.count));
	}
	cd2Capsule here = {cd2Add(position, local.p1), cd2Add(position, local.p2), local.radius};
	cd2Vec delta = cd2Sub(target, position);
	cd2QueryFilter castFilter = filter;
	if (list.oneWayBits != 0)
	{
		/* Rising or overlapping a one-way shape: it must not stop the cast. */
		if (delta.y >= 0.0f)
		{
			castFilter.maskBits &= ~list.oneWayBits;
		}
	}
	float t = cd2World_CastMover(w->id, &here, delta, castFilter);
	position = cd2Lerp(position, target, t);
	velocity = cd2ClipVector(velocity, list.planes, list.count);
	putPlanes(&list);
	float* o = IO;
	int count = getInt(IO);
	o[0] = position.x;
	o[1] = position.y;
	o[2] = velocity.x;
	o[3] = velocity.y;
	putInt(o + 4, count);
	return g_out;
}
