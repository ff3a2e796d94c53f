/* The JavaScript binding's C export layer (bindings/js/src/) built natively, so that the
 * sanitizer build runs it under AddressSanitizer and UBSan: inside wasm an out-of-bounds write
 * lands in the module's own memory and goes unseen, and a float-to-int conversion out of range
 * traps the page. A seeded random sequence of calls plays a careless JavaScript caller: worlds,
 * bodies, shapes, chains and joints created and destroyed, stale and made-up ids, definitions and
 * shape records full of NaN, infinities, huge values and wrong type codes, buffers of the exact
 * size claimed, snapshots restored whole, truncated and corrupted. Checks: no sanitizer report;
 * new worlds and bodies valid, destroyed worlds stale, one body at most gone per body2Destroy.
 *
 * The collision exports too: 2D and 3D shape records (hull records holding live, destroyed and
 * made-up hull handles), hulls, triangle meshes and chains built from careless points and indices,
 * and every query on them through live, destroyed and made-up handles. */
#include <collide/collide.h>
#include <collide/world2.h>

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* exports.c */
float* cdjsScratch(void);
int cdjs2ShapeAabb(void);
int cdjs2PolygonMake(void);
int cdjs2Mass(float density);
int cdjs2Overlap(void);
int cdjs2PointIn(float x, float y);
int cdjs2ClosestPoint(float x, float y);
int cdjs2Raycast(float ox, float oy, float tx, float ty);
int cdjs2Distance(void);
int cdjs2Collide(float speculativeDistance);
int cdjs2ShapeCast(float tx, float ty);
int cdjs2TimeOfImpact(float targetSeparation, float tolerance);
int cdjs3ShapeAabb(void);
int cdjs3Mass(float density);
int cdjs3Overlap(void);
int cdjs3PointIn(float x, float y, float z);
int cdjs3ClosestPoint(float x, float y, float z);
int cdjs3Raycast(float ox, float oy, float oz, float tx, float ty, float tz);
int cdjs3Distance(void);
int cdjs3Collide(float speculativeDistance);
int cdjs3ShapeCast(float tx, float ty, float tz);
int cdjs3TimeOfImpact(float targetSeparation, float tolerance);
int cdjs3HullCreate(int kind, const float* points, int count);
void cdjs3HullDestroy(int32_t handle);
const float* cdjs3HullInfo(int32_t handle);
int cdjs3MeshCreate(const float* vertices, int vertexCount, const int* indices, int triangleCount);
void cdjs3MeshDestroy(int32_t handle);
int cdjs3MeshInfo(int32_t handle);
int cdjs3MeshTriangle(int32_t handle, int index);
int cdjs3MeshRaycast(int32_t handle, float ox, float oy, float oz, float tx, float ty, float tz, int anyHit);
int cdjs3MeshQueryAabb(int32_t handle, float minX, float minY, float minZ, float maxX, float maxY, float maxZ,
					   int32_t* out, int capacity);
int cdjs3MeshOverlap(int32_t handle);
int cdjs3MeshClosestPoint(int32_t handle, float px, float py, float pz, float maxDistance);
int cdjs3MeshCollide(int32_t handle, float speculativeDistance, float* out, int capacity);
int cdjs2ChainBuild(const float* points, int count, int isLoop);
void cdjs2ChainFree(int32_t handle);
const float* cdjs2ChainInfo(int32_t handle);
int cdjs2ChainSegment(int32_t handle, int index);
int cdjs2ChainRaycast(int32_t handle, float ox, float oy, float tx, float ty);
int cdjs2ChainQueryAabb(int32_t handle, float minX, float minY, float maxX, float maxY, int32_t* out,
						int capacity);
int cdjs2ChainCollide(int32_t handle, float speculativeDistance, float* out, int capacity);
int cdjsBatch(int kind, const float* data, int count, int32_t* out);

/* world2_exports.c */
int cdjsWorld2Create(void);
void cdjsWorld2Destroy(int world0);
int cdjsWorld2Valid(int world0);
int cdjsWorld2Step(int world0, float timeStep, int subStepCount);
void cdjsWorld2SetGravity(int world0, float x, float y);
void cdjsWorld2GetGravity(int world0);
void cdjsWorld2EnableSleeping(int world0, int flag);
void cdjsWorld2EnableContinuous(int world0, int flag);
void cdjsWorld2Counters(int world0);
int cdjsBody2Create(int world0);
int cdjsBody2Destroy(int world0, int slot);
int cdjsBody2Valid(int world0, int index1, int generation);
float* cdjsWorld2Transforms(int world0);
float* cdjsWorld2States(int world0);
int cdjsBody2Get(int world0, int index1, int generation);
int cdjsBody2Transform(int world0, int index1, int generation);
int cdjsBody2Velocity(int world0, int index1, int generation);
int cdjsBody2Set(int world0, int index1, int generation, int what);
int cdjsShape2Create(int world0, int index1, int generation);
int cdjsChain2Create(int world0, int index1, int generation, const float* points, int count);
int cdjsChain2SegmentCount(int world0, int index1, int generation);
int cdjsChain2Destroy(int world0, int index1, int generation);
float* cdjsBody2Shapes(int world0, int index1, int generation);
int cdjsShape2Destroy(int world0, int index1, int generation);
int cdjsShape2Get(int world0, int index1, int generation);
int cdjsShape2Set(int world0, int index1, int generation, int what);
int cdjsJoint2Create(int world0);
int cdjsJoint2Destroy(int world0, int index1, int generation);
int cdjsJoint2Get(int world0, int index1, int generation);
int cdjsJoint2Set(int world0, int index1, int generation, int what);
float* cdjsWorld2Events(int world0);
void cdjsWorld2SetPreSolve(int world0, int on);
void cdjsWorld2SetCustomFilter(int world0, int on);
float* cdjsWorld2OverlapAabb(int world0);
float* cdjsWorld2OverlapShape(int world0);
int cdjsWorld2RaycastClosest(int world0);
float* cdjsWorld2Raycast(int world0);
float* cdjsWorld2ShapeCast(int world0);
int cdjsWorld2StateSize(int world0);
int cdjsWorld2SaveState(int world0, void* buffer, int capacity);
int cdjsWorld2RestoreState(int world0, const void* buffer, int size);
float* cdjsMover2Collide(int world0);
float cdjsMover2Cast(int world0);
int cdjsMover2Planes(int what);
float* cdjsMover2Move(int world0);

/* ---- a seeded generator of careless arguments ------------------------------------------------ */

static uint64_t s_state = 0x9e3779b97f4a7c15u;

static uint32_t Next(void)
{
	/* splitmix64 */
	uint64_t z = (s_state += 0x9e3779b97f4a7c15u);
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
	return (uint32_t)((z ^ (z >> 31)) >> 32);
}

static int Below(int n)
{
	return (int)(Next() % (uint32_t)n);
}

static float Uniform(float lo, float hi)
{
	return lo + (hi - lo) * (float)(Next() >> 8) * (1.0f / 16777216.0f);
}

/* Mostly sane, now and then what a caller should never pass. */
static float AnyFloat(void)
{
	switch (Below(20))
	{
		case 0:
			return NAN;
		case 1:
			return Below(2) ? INFINITY : -INFINITY;
		case 2:
			return Below(2) ? 1e30f : -1e30f;
		case 3:
			return 1e-30f;
		case 4:
		case 5:
			return 0.0f;
		case 6:
			return 1.0f;
		case 7:
			return (float)Below(9);
		case 8:
			return Uniform(-1000.0f, 1000.0f);
		default:
			return Uniform(-5.0f, 5.0f);
	}
}

static int AnyInt(void)
{
	switch (Below(10))
	{
		case 0:
			return -1;
		case 1:
			return (int)Next();
		case 2:
			return 1 << 20;
		default:
			return Below(10);
	}
}

static void PutInt(float* where, int32_t value)
{
	memcpy(where, &value, sizeof value);
}

static int32_t GetInt(const float* where)
{
	int32_t value;
	memcpy(&value, where, sizeof value);
	return value;
}

/* ---- what the sequence holds ----------------------------------------------------------------- */

enum
{
	MAX_WORLDS = 4,
	MAX_IDS = 96,
	IO_OFFSET = 128
};

typedef struct Handle
{
	int world0, index1, generation;
} Handle;

static int s_worlds[MAX_WORLDS]; /* world0 + 1, 0 for none */
static Handle s_bodies[MAX_IDS], s_shapes[MAX_IDS], s_joints[MAX_IDS];
static int s_bodyCount, s_shapeCount, s_jointCount;
static int s_failures;
static int s_made[6]; /* worlds, bodies, shapes, chains, joints, restores */

/* The collision objects' handles: live, then destroyed (kept to be passed again). */
enum
{
	MAX_OBJECTS = 16
};
typedef struct ObjectList
{
	int32_t handles[MAX_OBJECTS];
	bool live[MAX_OBJECTS];
	int count;
	int made;
} ObjectList;
static ObjectList s_hulls, s_meshes, s_chains;

static void Check(bool condition, const char* what, int step)
{
	if (!condition)
	{
		fprintf(stderr, "exports_native: step %d: %s\n", step, what);
		++s_failures;
	}
}

static void Remember(Handle* list, int* count, Handle h)
{
	/* A restored snapshot hands out the ids it took back again: hold each once. */
	for (int i = 0; i < *count; ++i)
	{
		if (list[i].world0 == h.world0 && list[i].index1 == h.index1 && list[i].generation == h.generation)
		{
			return;
		}
	}
	if (*count < MAX_IDS)
	{
		list[(*count)++] = h;
	}
	else
	{
		list[Below(MAX_IDS)] = h;
	}
}

/* A world slot: one the sequence made (live or destroyed), or any integer. */
static int AnyWorld(void)
{
	if (Below(8) == 0)
	{
		return AnyInt();
	}
	int k = Below(MAX_WORLDS);
	return s_worlds[k] > 0 ? s_worlds[k] - 1 : Below(CD2_MAX_WORLDS);
}

static Handle AnyHandle(const Handle* list, int count)
{
	if (count == 0 || Below(10) == 0)
	{
		Handle h = {AnyWorld(), AnyInt(), AnyInt()};
		return h;
	}
	Handle h = list[Below(count)];
	/* Bodies: mostly a live one, so that shapes and joints reach the world. */
	for (int tries = 0; list == s_bodies && tries < 8 && !cdjsBody2Valid(h.world0, h.index1, h.generation);
		 ++tries)
	{
		h = list[Below(count)];
	}
	return h;
}

/* IO: definitions whose fields are floats, small ints, NaN (the default) or parts of real ids. */
static void FillIo(void)
{
	float* io = cdjsScratch() + IO_OFFSET;
	if (Below(4) != 0)
	{
		/* Mostly what a careful caller sends: defaults (NaN) with a few sane fields. */
		for (int i = 0; i < 64; ++i)
		{
			io[i] = NAN;
		}
		for (int k = 0; k < 3; ++k)
		{
			io[Below(24)] = Uniform(-5.0f, 5.0f);
		}
	}
	else
	{
		for (int i = 0; i < 64; ++i)
		{
			switch (Below(8))
			{
				case 0:
				case 1:
					io[i] = NAN;
					break;
				case 2:
					PutInt(io + i, Below(9));
					break;
				case 3:
				{
					Handle h = AnyHandle(s_bodies, s_bodyCount);
					PutInt(io + i, Below(2) ? h.index1 : h.generation);
					break;
				}
				default:
					io[i] = AnyFloat();
					break;
			}
		}
	}
}

/* A 2D shape record (exports.c): a type code, then fields; sometimes a wrong code or count. */
static void FillShape(float* slot)
{
	for (int i = 0; i < 64; ++i)
	{
		slot[i] = Below(4) ? Uniform(-2.0f, 2.0f) : AnyFloat();
	}
	slot[0] = Below(12) ? (float)Below(6) : AnyFloat();
	if (slot[0] == 4.0f && Below(4))
	{
		slot[1] = (float)(1 + Below(8)); /* polygon count */
		slot[2] = Below(2) ? 0.0f : Uniform(0.0f, 0.5f);
	}
	if ((slot[0] == 0.0f || slot[0] == 1.0f) && Below(4))
	{
		slot[slot[0] == 0.0f ? 3 : 5] = Uniform(0.05f, 1.0f); /* radius */
	}
}

static int32_t AnyObject(const ObjectList* list);

/* A 3D shape record (lib/shapes3.js): type, then the shape's floats; a hull record's handle at
 * float 8 is a held hull (live or destroyed), another kind's handle or any integer. */
static void FillShape3(float* slot)
{
	for (int i = 0; i < 64; ++i)
	{
		slot[i] = Below(4) ? Uniform(-2.0f, 2.0f) : AnyFloat();
	}
	slot[0] = Below(12) ? (float)Below(8) : AnyFloat();
	if (slot[0] == 7.0f)
	{
		/* hull: position (3), rotation (4, mostly the identity), handle */
		if (Below(4))
		{
			slot[4] = slot[5] = slot[6] = 0.0f;
			slot[7] = 1.0f;
		}
		PutInt(slot + 8, AnyObject(&s_hulls));
	}
	else if (slot[0] == 3.0f && Below(4))
	{
		/* box: centre, half extents, rotation (mostly the identity) */
		slot[7] = slot[8] = slot[9] = 0.0f;
		slot[10] = 1.0f;
	}
	else if ((slot[0] == 0.0f || slot[0] == 1.0f) && Below(4))
	{
		slot[slot[0] == 0.0f ? 4 : 7] = Uniform(0.05f, 1.0f); /* radius */
	}
}

static void CreateWorld(int step)
{
	FillIo();
	int made = cdjsWorld2Create();
	if (made > 0)
	{
		int k = Below(MAX_WORLDS);
		if (s_worlds[k] > 0 && Below(16) != 0)
		{
			cdjsWorld2Destroy(made - 1); /* keep the worlds that have bodies a while longer */
			return;
		}
		if (s_worlds[k] > 0 && s_worlds[k] != made)
		{
			cdjsWorld2Destroy(s_worlds[k] - 1);
			Check(!cdjsWorld2Valid(s_worlds[k] - 1), "a destroyed world is valid", step);
		}
		s_worlds[k] = made;
		++s_made[0];
		Check(cdjsWorld2Valid(made - 1) == 1, "a new world is not valid", step);
	}
}

static void CreateBody(int step)
{
	int world0 = AnyWorld();
	FillIo();
	float* io = cdjsScratch() + IO_OFFSET;
	if (Below(2))
	{
		io[0] = (float)Below(3); /* static, kinematic, dynamic */
	}
	int index1 = cdjsBody2Create(world0);
	if (index1 > 0)
	{
		Handle h = {world0, index1, GetInt(io)};
		Check(cdjsBody2Valid(h.world0, h.index1, h.generation) == 1, "a new body is not valid", step);
		Remember(s_bodies, &s_bodyCount, h);
		++s_made[1];
	}
}

static void CreateShape(int step)
{
	Handle body = AnyHandle(s_bodies, s_bodyCount);
	FillShape(cdjsScratch());
	FillIo();
	int index1 = cdjsShape2Create(body.world0, body.index1, body.generation);
	if (index1 > 0)
	{
		Handle h = {body.world0, index1, GetInt(cdjsScratch() + IO_OFFSET)};
		Remember(s_shapes, &s_shapeCount, h);
		++s_made[2];
	}
	(void)step;
}

static void CreateChain(void)
{
	Handle body = AnyHandle(s_bodies, s_bodyCount);
	int count = Below(12);
	/* Exactly the floats claimed: an over-read is the sanitizer's to see. */
	float* points = (float*)malloc((size_t)(2 * count + 1) * sizeof(float));
	if (points == NULL)
	{
		return;
	}
	for (int i = 0; i < 2 * count; ++i)
	{
		points[i] = Below(8) ? (float)i * 0.5f + Uniform(-0.1f, 0.1f) : AnyFloat();
	}
	FillIo();
	int index1 = cdjsChain2Create(body.world0, body.index1, body.generation, points, count);
	if (index1 > 0)
	{
		int generation = GetInt(cdjsScratch() + IO_OFFSET);
		++s_made[3];
		cdjsChain2SegmentCount(body.world0, index1, generation);
		if (Below(3) == 0)
		{
			cdjsChain2Destroy(body.world0, index1, generation);
			cdjsChain2Destroy(body.world0, index1, generation); /* twice: stale */
		}
	}
	free(points);
}

static void CreateJoint(void)
{
	int world0 = s_bodyCount > 0 && Below(4) ? s_bodies[Below(s_bodyCount)].world0 : AnyWorld();
	FillIo();
	/* A type, then two bodies (of this world, most of the time). */
	if (Below(8) != 0 && s_bodyCount > 0)
	{
		float* io = cdjsScratch() + IO_OFFSET;
		Handle a = s_bodies[Below(s_bodyCount)], b = s_bodies[Below(s_bodyCount)];
		for (int tries = 0; tries < 8 && (a.world0 != world0 || b.world0 != world0); ++tries)
		{
			a = a.world0 == world0 ? a : s_bodies[Below(s_bodyCount)];
			b = b.world0 == world0 ? b : s_bodies[Below(s_bodyCount)];
		}
		PutInt(io, Below(8));
		PutInt(io + 1, a.index1);
		PutInt(io + 2, a.generation);
		PutInt(io + 3, b.index1);
		PutInt(io + 4, b.generation);
	}
	int index1 = cdjsJoint2Create(world0);
	if (index1 > 0)
	{
		Handle h = {world0, index1, GetInt(cdjsScratch() + IO_OFFSET)};
		Remember(s_joints, &s_jointCount, h);
		++s_made[4];
	}
}

/* Save, step, restore: whole, truncated or with flipped bytes. */
static void Snapshot(void)
{
	int world0 = AnyWorld();
	int size = cdjsWorld2StateSize(world0);
	if (size <= 0)
	{
		cdjsWorld2RestoreState(world0, NULL, 0);
		return;
	}
	unsigned char* buffer = (unsigned char*)malloc((size_t)size);
	if (buffer == NULL)
	{
		return;
	}
	int saved = cdjsWorld2SaveState(world0, buffer, Below(4) ? size : size / 2);
	if (saved == CD_OK)
	{
		cdjsWorld2Step(world0, 1.0f / 60.0f, 2);
		int length = size;
		switch (Below(4))
		{
			case 0:
				length = Below(size + 1);
				break;
			case 1:
				for (int i = 0; i < 8; ++i)
				{
					buffer[Below(size)] ^= (unsigned char)(1u << Below(8));
				}
				break;
			default:
				break;
		}
		s_made[5] += cdjsWorld2RestoreState(world0, buffer, length) == CD_OK;
	}
	free(buffer);
}

static void Query(void)
{
	int world0 = AnyWorld();
	FillIo();
	switch (Below(8))
	{
		case 0:
			cdjsWorld2OverlapAabb(world0);
			break;
		case 1:
			FillShape(cdjsScratch());
			cdjsWorld2OverlapShape(world0);
			break;
		case 2:
			cdjsWorld2RaycastClosest(world0);
			break;
		case 3:
			cdjsWorld2Raycast(world0);
			break;
		case 4:
			FillShape(cdjsScratch());
			cdjsWorld2ShapeCast(world0);
			break;
		case 5:
			cdjsMover2Collide(world0);
			cdjsMover2Cast(world0);
			break;
		case 6:
			cdjsMover2Collide(world0);
			FillIo();
			PutInt(cdjsScratch() + IO_OFFSET, Below(4) ? Below(8) : AnyInt()); /* plane count */
			cdjsMover2Planes(Below(3));
			break;
		default:
			cdjsMover2Move(world0);
			break;
	}
}

/* The stateless 2D queries of exports.c on two shape records. */
static void ShapeQuery(void)
{
	float* scratch = cdjsScratch();
	FillShape(scratch);
	FillShape(scratch + 64);
	switch (Below(11))
	{
		case 0:
			cdjs2ShapeAabb();
			break;
		case 1:
			cdjs2PolygonMake();
			break;
		case 2:
			cdjs2Mass(AnyFloat());
			break;
		case 3:
			cdjs2Overlap();
			break;
		case 4:
			cdjs2PointIn(AnyFloat(), AnyFloat());
			break;
		case 5:
			cdjs2ClosestPoint(AnyFloat(), AnyFloat());
			break;
		case 6:
			cdjs2Raycast(AnyFloat(), AnyFloat(), AnyFloat(), AnyFloat());
			break;
		case 7:
			cdjs2Distance();
			break;
		case 8:
			cdjs2Collide(AnyFloat());
			break;
		case 9:
			cdjs2ShapeCast(AnyFloat(), AnyFloat());
			break;
		default:
			cdjs2TimeOfImpact(AnyFloat(), AnyFloat());
			break;
	}
}

/* ---- collision objects: hulls, meshes, chains ------------------------------------------------- */

static void Hold(ObjectList* list, int32_t handle)
{
	list->made++;
	int k = list->count < MAX_OBJECTS ? list->count++ : Below(MAX_OBJECTS);
	if (list->count == MAX_OBJECTS && list->live[k])
	{
		/* The slot's old object is lost to the sequence: destroy it first. */
		if (list == &s_hulls)
		{
			cdjs3HullDestroy(list->handles[k]);
		}
		else if (list == &s_meshes)
		{
			cdjs3MeshDestroy(list->handles[k]);
		}
		else
		{
			cdjs2ChainFree(list->handles[k]);
		}
	}
	list->handles[k] = handle;
	list->live[k] = true;
}

/* A held handle (live or destroyed), a handle of another kind, or any integer. */
static int32_t AnyObject(const ObjectList* list)
{
	switch (Below(10))
	{
		case 0:
			return AnyInt();
		case 1:
			return s_meshes.count > 0 ? s_meshes.handles[Below(s_meshes.count)] : 0;
		case 2:
			return s_chains.count > 0 ? s_chains.handles[Below(s_chains.count)] : AnyInt();
		default:
			return list->count > 0 ? list->handles[Below(list->count)] : AnyInt();
	}
}

/* Points: mostly a cloud in a few units, now and then careless values. */
static void FillPoints(float* points, int floats)
{
	for (int i = 0; i < floats; ++i)
	{
		points[i] = Below(16) ? Uniform(-3.0f, 3.0f) : AnyFloat();
	}
}

static void DestroyObject(ObjectList* list, int step)
{
	if (list->count == 0)
	{
		return;
	}
	int k = Below(list->count);
	int32_t handle = list->handles[k];
	if (list == &s_hulls)
	{
		cdjs3HullDestroy(handle);
		Check(cdjs3HullInfo(handle) == NULL, "a destroyed hull's handle still answers", step);
	}
	else if (list == &s_meshes)
	{
		cdjs3MeshDestroy(handle);
		Check(cdjs3MeshInfo(handle) != 0, "a destroyed mesh's handle still answers", step);
	}
	else
	{
		cdjs2ChainFree(handle);
		Check(cdjs2ChainInfo(handle) == NULL, "a destroyed chain's handle still answers", step);
	}
	list->live[k] = false;
}

static void CollisionObjects(int step)
{
	float points[3 * 64];
	int indices[3 * 48];
	float* io = cdjsScratch() + IO_OFFSET;
	switch (Below(6))
	{
		case 0:
		{
			int kind = Below(10) ? Below(4) : AnyInt();
			int count = Below(8) ? 4 + Below(60) : AnyInt();
			FillPoints(points, 3 * 64);
			io[0] = Below(4) ? Uniform(0.1f, 2.0f) : AnyFloat();
			io[1] = Below(4) ? Uniform(0.1f, 2.0f) : AnyFloat();
			io[2] = Below(4) ? Uniform(0.1f, 2.0f) : AnyFloat();
			int segments = kind >= 2 && Below(4) ? 3 + Below(30) : count;
			bool sane = count >= 0 && count <= 64;
			int result =
				cdjs3HullCreate(kind, kind == 0 && !sane ? NULL : points, kind == 0 ? count : segments);
			int32_t handle = GetInt(io);
			Check((result == 0) == (handle != 0), "hullCreate's result and handle disagree", step);
			if (result == 0)
			{
				const float* vertices = cdjs3HullInfo(handle);
				Check(vertices != NULL && io[0] >= 4.0f, "a new hull's info", step);
				Hold(&s_hulls, handle);
			}
			break;
		}
		case 1:
		{
			int vertexCount = Below(8) ? 3 + Below(61) : AnyInt();
			int triangleCount = Below(8) ? 1 + Below(48) : AnyInt();
			FillPoints(points, 3 * 64);
			int safeVertices = vertexCount >= 0 && vertexCount <= 64 ? vertexCount : 0;
			for (int i = 0; i < 3 * 48; ++i)
			{
				indices[i] = Below(16) && safeVertices > 0 ? Below(safeVertices) : AnyInt();
			}
			bool sane = vertexCount >= 0 && vertexCount <= 64 && triangleCount >= 0 && triangleCount <= 48;
			int result = sane ? cdjs3MeshCreate(points, vertexCount, indices, triangleCount)
							  : cdjs3MeshCreate(NULL, vertexCount, NULL, triangleCount);
			int32_t handle = GetInt(io);
			Check((result == 0) == (handle != 0), "mesh3Create's result and handle disagree", step);
			if (result == 0)
			{
				Check(cdjs3MeshInfo(handle) == 0, "a new mesh does not validate", step);
				Hold(&s_meshes, handle);
			}
			break;
		}
		case 2:
		{
			int count = Below(8) ? 2 + Below(62) : AnyInt();
			FillPoints(points, 2 * 64);
			bool sane = count >= 0 && count <= 64;
			int result = cdjs2ChainBuild(sane ? points : NULL, count, Below(2));
			int32_t handle = GetInt(io);
			Check((result == 0) == (handle != 0), "chain2Build's result and handle disagree", step);
			if (result == 0)
			{
				Check(cdjs2ChainInfo(handle) != NULL, "a new chain's info", step);
				Hold(&s_chains, handle);
			}
			break;
		}
		case 3:
		{
			int pick = Below(3);
			DestroyObject(pick == 0 ? &s_hulls : pick == 1 ? &s_meshes : &s_chains, step);
			/* Made-up handles: nothing happens. */
			cdjs3HullDestroy(AnyInt());
			cdjs3MeshDestroy(AnyInt());
			cdjs2ChainFree(AnyInt());
			break;
		}
		case 4:
		{
			int32_t mesh = AnyObject(&s_meshes);
			int32_t out[64];
			float manifolds[25 * 8];
			for (int i = 0; i < 7; ++i)
			{
				io[i] = Below(8) ? (i == 6 ? 1.0f : 0.0f) : AnyFloat(); /* the mesh's transform */
			}
			cdjs3MeshInfo(mesh);
			cdjs3MeshTriangle(mesh, Below(4) ? Below(48) : AnyInt());
			cdjs3MeshRaycast(mesh, AnyFloat(), AnyFloat(), Uniform(3.0f, 5.0f), AnyFloat(), AnyFloat(),
							 Uniform(-9.0f, -1.0f), Below(2));
			int capacity = Below(8) ? Below(64) : AnyInt();
			cdjs3MeshQueryAabb(mesh, -AnyFloat(), -AnyFloat(), -AnyFloat(), AnyFloat(), AnyFloat(),
							   AnyFloat(), capacity >= 0 && capacity <= 64 ? out : NULL, capacity);
			cdjs3MeshClosestPoint(mesh, AnyFloat(), AnyFloat(), AnyFloat(), Below(2) ? INFINITY : AnyFloat());
			FillShape3(cdjsScratch());
			cdjs3MeshOverlap(mesh);
			capacity = Below(8) ? Below(8) : AnyInt();
			cdjs3MeshCollide(mesh, Below(4) ? 0.1f : AnyFloat(),
							 capacity >= 0 && capacity <= 8 ? manifolds : NULL, capacity);
			break;
		}
		default:
		{
			int32_t chain = AnyObject(&s_chains);
			int32_t out[64];
			float manifolds[12 * 8];
			for (int i = 0; i < 3; ++i)
			{
				io[i] = Below(8) ? 0.0f : AnyFloat(); /* the chain's transform */
			}
			cdjs2ChainInfo(chain);
			cdjs2ChainSegment(chain, Below(4) ? Below(64) : AnyInt());
			cdjs2ChainRaycast(chain, AnyFloat(), AnyFloat(), AnyFloat(), AnyFloat());
			int capacity = Below(8) ? Below(64) : AnyInt();
			cdjs2ChainQueryAabb(chain, -AnyFloat(), -AnyFloat(), AnyFloat(), AnyFloat(),
								capacity >= 0 && capacity <= 64 ? out : NULL, capacity);
			FillShape(cdjsScratch());
			capacity = Below(8) ? Below(8) : AnyInt();
			cdjs2ChainCollide(chain, Below(4) ? 0.1f : AnyFloat(),
							  capacity >= 0 && capacity <= 8 ? manifolds : NULL, capacity);
			break;
		}
	}
}

static void ShapeQuery3(void)
{
	float* scratch = cdjsScratch();
	FillShape3(scratch);
	FillShape3(scratch + 64);
	float* io = scratch + IO_OFFSET;
	for (int i = 0; i < 16; ++i)
	{
		io[i] = Below(4) ? Uniform(-2.0f, 2.0f) : AnyFloat(); /* sweeps of the time of impact */
	}
	switch (Below(11))
	{
		case 0:
			cdjs3ShapeAabb();
			break;
		case 1:
		{
			/* Batch queries over careless records. */
			float data[6 * 32];
			int32_t out[32];
			int count = Below(8) ? Below(32) : AnyInt();
			FillPoints(data, 6 * 32);
			for (int i = 0; i < 8; ++i)
			{
				io[i] = AnyFloat();
			}
			bool sane = count >= 0 && count <= 32;
			cdjsBatch(Below(8) ? Below(12) : AnyInt(), sane ? data : NULL, count, sane ? out : NULL);
			break;
		}
		case 2:
			cdjs3Mass(AnyFloat());
			break;
		case 3:
			cdjs3Overlap();
			break;
		case 4:
			cdjs3PointIn(AnyFloat(), AnyFloat(), AnyFloat());
			break;
		case 5:
			cdjs3ClosestPoint(AnyFloat(), AnyFloat(), AnyFloat());
			break;
		case 6:
			cdjs3Raycast(AnyFloat(), AnyFloat(), AnyFloat(), AnyFloat(), AnyFloat(), AnyFloat());
			break;
		case 7:
			cdjs3Distance();
			break;
		case 8:
			cdjs3Collide(AnyFloat());
			break;
		case 9:
			cdjs3ShapeCast(AnyFloat(), AnyFloat(), AnyFloat());
			break;
		default:
			cdjs3TimeOfImpact(AnyFloat(), AnyFloat());
			break;
	}
}

static bool s_preSolveAnswer = true;

int cdjsImportPreSolve(int world0, int ia, int ga, int ib, int gb, const float* manifold);
int cdjsImportCustomFilter(int world0, int ia, int ga, int ib, int gb);

int cdjsImportPreSolve(int world0, int ia, int ga, int ib, int gb, const float* manifold)
{
	(void)world0, (void)ia, (void)ga, (void)ib, (void)gb;
	volatile float read = manifold[0]; /* the record is readable */
	(void)read;
	s_preSolveAnswer = !s_preSolveAnswer;
	return s_preSolveAnswer;
}

int cdjsImportCustomFilter(int world0, int ia, int ga, int ib, int gb)
{
	(void)world0, (void)ia, (void)ga, (void)ib, (void)gb;
	return (ia + ib) % 3 != 0;
}

static bool IgnoreAssert(const char* condition, const char* fileName, int lineNumber)
{
	(void)condition, (void)fileName, (void)lineNumber;
	return false; /* refused, not fatal: a careless caller is what this plays */
}

int main(int argc, char** argv)
{
	int steps = argc > 1 ? atoi(argv[1]) : 20000;
	cdSetAssertFcn(IgnoreAssert);
	for (int step = 0; step < steps; ++step)
	{
		int op = Below(28);
		switch (op)
		{
			case 0:
				CreateWorld(step);
				break;
			case 1:
				if (Below(20) == 0)
				{
					int k = Below(MAX_WORLDS);
					if (s_worlds[k] > 0)
					{
						cdjsWorld2Destroy(s_worlds[k] - 1);
						Check(!cdjsWorld2Valid(s_worlds[k] - 1), "a destroyed world is valid", step);
						s_worlds[k] = 0;
					}
				}
				cdjsWorld2Destroy(AnyInt()); /* made-up slots */
				break;
			case 2:
			case 3:
				cdjsWorld2Step(AnyWorld(), Below(8) ? 1.0f / 60.0f : AnyFloat(),
							   Below(8) ? 1 + Below(4) : AnyInt());
				break;
			case 4:
				cdjsWorld2SetGravity(AnyWorld(), AnyFloat(), AnyFloat());
				cdjsWorld2GetGravity(AnyWorld());
				cdjsWorld2EnableSleeping(AnyWorld(), Below(2));
				cdjsWorld2EnableContinuous(AnyWorld(), Below(2));
				cdjsWorld2Counters(AnyWorld());
				break;
			case 5:
			case 6:
				CreateBody(step);
				break;
			case 7:
			{
				/* By list slot, as lib/world2.js does; mark every held handle of that body stale. */
				int world0 = AnyWorld();
				int slot = Below(4) ? Below(8) : AnyInt();
				float* transforms = cdjsWorld2Transforms(world0);
				(void)transforms;
				int before = 0, after = 0;
				for (int i = 0; i < s_bodyCount; ++i)
				{
					before += cdjsBody2Valid(s_bodies[i].world0, s_bodies[i].index1, s_bodies[i].generation);
				}
				int destroyed = cdjsBody2Destroy(world0, slot);
				for (int i = 0; i < s_bodyCount; ++i)
				{
					after += cdjsBody2Valid(s_bodies[i].world0, s_bodies[i].index1, s_bodies[i].generation);
				}
				/* One body at most goes stale, and only when the call says it destroyed one. */
				Check(before - after == 0 || (destroyed == 1 && before - after == 1),
					  "body2Destroy changed the wrong number of bodies", step);
				break;
			}
			case 8:
			{
				Handle h = AnyHandle(s_bodies, s_bodyCount);
				cdjsBody2Get(h.world0, h.index1, h.generation);
				cdjsBody2Transform(h.world0, h.index1, h.generation);
				cdjsBody2Velocity(h.world0, h.index1, h.generation);
				cdjsBody2Shapes(h.world0, h.index1, h.generation);
				cdjsWorld2States(h.world0);
				break;
			}
			case 9:
			case 10:
			{
				Handle h = AnyHandle(s_bodies, s_bodyCount);
				FillIo();
				cdjsBody2Set(h.world0, h.index1, h.generation, Below(8) ? Below(24) : AnyInt());
				break;
			}
			case 11:
			case 12:
				CreateShape(step);
				break;
			case 13:
			{
				Handle h = AnyHandle(s_shapes, s_shapeCount);
				FillIo();
				switch (Below(3))
				{
					case 0:
						cdjsShape2Get(h.world0, h.index1, h.generation);
						break;
					case 1:
						cdjsShape2Set(h.world0, h.index1, h.generation, Below(8) ? Below(16) : AnyInt());
						break;
					default:
						cdjsShape2Destroy(h.world0, h.index1, h.generation);
						break;
				}
				break;
			}
			case 14:
				CreateChain();
				break;
			case 15:
			case 16:
				CreateJoint();
				break;
			case 17:
			{
				Handle h = AnyHandle(s_joints, s_jointCount);
				FillIo();
				switch (Below(3))
				{
					case 0:
						cdjsJoint2Get(h.world0, h.index1, h.generation);
						break;
					case 1:
						cdjsJoint2Set(h.world0, h.index1, h.generation, Below(8) ? Below(24) : AnyInt());
						break;
					default:
						cdjsJoint2Destroy(h.world0, h.index1, h.generation);
						break;
				}
				break;
			}
			case 18:
				cdjsWorld2Events(AnyWorld());
				cdjsWorld2SetPreSolve(AnyWorld(), Below(2));
				cdjsWorld2SetCustomFilter(AnyWorld(), Below(2));
				break;
			case 19:
			case 20:
				Query();
				break;
			case 21:
				Snapshot();
				break;
			case 24:
			case 25:
				CollisionObjects(step);
				break;
			case 26:
				ShapeQuery3();
				break;
			default:
				ShapeQuery();
				break;
		}
	}
	for (int k = 0; k < MAX_WORLDS; ++k)
	{
		if (s_worlds[k] > 0)
		{
			cdjsWorld2Destroy(s_worlds[k] - 1);
		}
	}
	for (int k = 0; k < MAX_OBJECTS; ++k)
	{
		if (k < s_hulls.count && s_hulls.live[k])
		{
			cdjs3HullDestroy(s_hulls.handles[k]);
		}
		if (k < s_meshes.count && s_meshes.live[k])
		{
			cdjs3MeshDestroy(s_meshes.handles[k]);
		}
		if (k < s_chains.count && s_chains.live[k])
		{
			cdjs2ChainFree(s_chains.handles[k]);
		}
	}
	cdSetAssertFcn(NULL);
	printf("exports_native: %d steps of calls; made %d worlds, %d bodies, %d shapes, %d chains, %d joints; "
		   "%d snapshots restored; %d hulls, %d meshes, %d chain objects; %d failures\n",
		   steps, s_made[0], s_made[1], s_made[2], s_made[3], s_made[4], s_made[5], s_hulls.made,
		   s_meshes.made, s_chains.made, s_failures);
	/* A sequence that never got a body or a joint into a world, or never built a hull, a mesh and
	 * a chain, tested nothing of them. */
	if (s_made[1] == 0 || s_made[2] == 0 || s_made[4] == 0 || s_hulls.made == 0 || s_meshes.made == 0 ||
		s_chains.made == 0)
	{
		return 1;
	}
	return s_failures == 0 ? 0 : 1;
}
