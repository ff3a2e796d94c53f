/* collide for JavaScript: the thin export layer between the wasm module and the lib/ modules.
 *
 * Flat functions of numbers and pointers only. Shapes arrive as small float records written by
 * the JavaScript side into a static scratch block (layout below); every shape is decoded into
 * the library's tagged cd2Shape / cd3Shape and checked with the library's own validators before
 * any query runs, so bad values from JavaScript give an error code, never a wrong memory access.
 * Results are written back into the scratch block. Nothing here computes geometry itself: every
 * answer comes from the library's functions.
 *
 * 2D shape record (floats): [type, ...]
 *   circle  0: cx cy r              capsule 1: p1x p1y p2x p2y r     aabb 2: minx miny maxx maxy
 *   box     3: cx cy hx hy angle    polygon 4: count radius x0 y0 x1 y1 ... (up to 8 points)
 *   segment 5: p1x p1y p2x p2y
 * 3D shape record (floats): [type, ...]
 *   sphere 0: cx cy cz r           capsule 1: p1 p2 r               aabb 2: min max
 *   box 3: c h qx qy qz qw         triangle 4: a b c                plane 5: nx ny nz offset
 *   segment 6: p1 p2               hull 7: px py pz qx qy qz qw, then (int32) hull pointer
 * Error codes: a negative return is -(cdResult) for the first shape, -(32 + cdResult) for the
 * second. */
#include <collide/collide.h>

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Outside wasm (tests/js_exports: the layer under the native sanitizers) plain functions. */
#if defined(__wasm__)
#define EXPORT(name) __attribute__((export_name(name)))
#else
#define EXPORT(name)
#endif

#define SCRATCH_FLOATS 4096
#define SLOT_FLOATS 64

static float g_scratch[SCRATCH_FLOATS] __attribute__((aligned(16)));

/* Scratch layout: slot A at 0, slot B at 64, input/output area from 128. */
#define SLOT_A (g_scratch)
#define SLOT_B (g_scratch + SLOT_FLOATS)
#define IO (g_scratch + 2 * SLOT_FLOATS)

/* A type code or count sent as a float: -1 for NaN and for values beyond int (a plain cast is
 * undefined there and traps in wasm); the callers refuse -1. Shared with world2_exports.c. */
int cdjsFloatToInt(float value);
int cdjsFloatToInt(float value)
{
	return value >= -2147483648.0f && value < 2147483648.0f ? (int)value : -1;
}

EXPORT("scratch") float* cdjsScratch(void)
{
	return g_scratch;
}

EXPORT("malloc") void* cdjsMalloc(int size)
{
	if (size <= 0)
	{
		return NULL;
	}
	return malloc((size_t)size);
}

EXPORT("free") void cdjsFree(void* memory)
{
	free(memory);
}

/* 1 in the build compiled for wasm SIMD (-msimd128), 0 in the scalar build. */
EXPORT("isSimd") int cdjsIsSimd(void)
{
#ifdef __wasm_simd128__
	return 1;
#else
	return 0;
#endif
}

EXPORT("isDouble") int cdjsIsDouble(void)
{
	return cdGetRealIsDouble();
}

static void putInt(float* where, int32_t value)
{
	memcpy(where, &value, sizeof value);
}

static void putU32(float* where, uint32_t value)
{
	memcpy(where, &value, sizeof value);
}

static int32_t getInt(const float* where)
{
	int32_t value;
	memcpy(&value, where, sizeof value);
	return value;
}

static cd2Vec v2(const float* p)
{
	return (cd2Vec){p[0], p[1]};
}

static cd3Vec v3(const float* p)
{
	return (cd3Vec){p[0], p[1], p[2]};
}

static cd3Quat q3(const float* p)
{
	return (cd3Quat){p[0], p[1], p[2], p[3]};
}

static void put2(float* out, cd2Vec v)
{
	out[0] = v.x;
	out[1] = v.y;
}

static void put3(float* out, cd3Vec v)
{
	out[0] = v.x;
	out[1] = v.y;
	out[2] = v.z;
}

static int finiteAll(const float* p, int n)
{
	for (int i = 0; i < n; ++i)
	{
		if (!isfinite(p[i]))
		{
			return 0;
		}
	}
	return 1;
}

/* ==== handles of the objects JavaScript holds ================================================ *
 * Hulls, meshes and chains cross to JavaScript as handles, not pointers: a slot index and the
 * slot's generation in one positive int32 (20 bits of index + 1, 11 of generation). A destroyed
 * object's handle, a handle of another kind or a made-up number is refused (the call returns its
 * bad-input code) instead of reaching freed or foreign memory, and the layer keeps working where
 * pointers are 64 bits wide (tests/js_exports runs it natively under the sanitizers). A slot's
 * generation wraps after 2,048 reuses; the package's classes never pass a destroyed object's
 * handle in the first place. */

typedef enum JsKind
{
	JS_HULL = 1,
	JS_MESH,
	JS_CHAIN
} JsKind;

typedef struct JsSlot
{
	void* object; /* NULL while free */
	uint32_t generation;
	int kind;
	int nextFree;
} JsSlot;

#define JS_HANDLE_INDEX_BITS 20
#define JS_HANDLE_INDEX_MASK ((1u << JS_HANDLE_INDEX_BITS) - 1u)
#define JS_HANDLE_GENERATION_MASK 0x7ffu

static JsSlot* s_slots = NULL;
static int s_slotCount = 0, s_slotCapacity = 0, s_freeSlot = -1;

/* The handle of a new slot holding `object`; 0 when out of memory or slots. */
static int32_t jsHandleAdd(void* object, JsKind kind)
{
	int index;
	if (s_freeSlot >= 0)
	{
		index = s_freeSlot;
		s_freeSlot = s_slots[index].nextFree;
	}
	else
	{
		const int maxSlots = (int)JS_HANDLE_INDEX_MASK; /* index + 1 fits the index bits */
		if (s_slotCount == s_slotCapacity)
		{
			if (s_slotCapacity >= maxSlots)
			{
				return 0;
			}
			int capacity = s_slotCapacity > 0 ? 2 * s_slotCapacity : 64;
			capacity = capacity < maxSlots ? capacity : maxSlots;
			JsSlot* grown = (JsSlot*)realloc(s_slots, (size_t)capacity * sizeof(JsSlot));
			if (grown == NULL)
			{
				return 0;
			}
			s_slots = grown;
			s_slotCapacity = capacity;
		}
		index = s_slotCount++;
		s_slots[index].generation = 0;
	}
	JsSlot* slot = s_slots + index;
	slot->object = object;
	slot->kind = (int)kind;
	slot->nextFree = -1;
	return (int32_t)(((slot->generation & JS_HANDLE_GENERATION_MASK) << JS_HANDLE_INDEX_BITS) |
					 (uint32_t)(index + 1));
}

static JsSlot* jsHandleSlot(int32_t handle, JsKind kind)
{
	if (handle <= 0)
	{
		return NULL;
	}
	uint32_t bits = (uint32_t)handle;
	int index = (int)(bits & JS_HANDLE_INDEX_MASK) - 1;
	if (index < 0 || index >= s_slotCount)
	{
		return NULL;
	}
	JsSlot* slot = s_slots + index;
	if (slot->object == NULL || slot->kind != (int)kind ||
		(slot->generation & JS_HANDLE_GENERATION_MASK) != bits >> JS_HANDLE_INDEX_BITS)
	{
		return NULL;
	}
	return slot;
}

/* The live object of `handle`, or NULL. */
static void* jsHandleGet(int32_t handle, JsKind kind)
{
	JsSlot* slot = jsHandleSlot(handle, kind);
	return slot != NULL ? slot->object : NULL;
}

/* Frees the slot of `handle` and returns its object (for the caller to destroy), or NULL. */
static void* jsHandleRemove(int32_t handle, JsKind kind)
{
	JsSlot* slot = jsHandleSlot(handle, kind);
	if (slot == NULL)
	{
		return NULL;
	}
	void* object = slot->object;
	slot->object = NULL;
	slot->generation++;
	slot->nextFree = s_freeSlot;
	s_freeSlot = (int)(slot - s_slots);
	return object;
}

/* ==== 2D ==================================================================================== */

static cdResult decode2(const float* s, cd2Shape* out)
{
	memset(out, 0, sizeof *out);
	int type = cdjsFloatToInt(s[0]);
	switch (type)
	{
		case CD2_SHAPE_CIRCLE:
			*out = cd2MakeCircleShape((cd2Circle){v2(s + 1), s[3]});
			break;
		case CD2_SHAPE_CAPSULE:
			*out = cd2MakeCapsuleShape((cd2Capsule){v2(s + 1), v2(s + 3), s[5]});
			break;
		case CD2_SHAPE_AABB:
			*out = cd2MakeAabbShape((cd2Aabb){v2(s + 1), v2(s + 3)});
			break;
		case CD2_SHAPE_BOX:
			if (!finiteAll(s + 1, 5))
			{
				return CD_ERROR_NOT_FINITE;
			}
			*out = cd2MakeBoxShape((cd2Box){v2(s + 1), v2(s + 3), cd2MakeRot(s[5])});
			break;
		case CD2_SHAPE_POLYGON:
		{
			int count = cdjsFloatToInt(s[1]);
			if (count < 1 || count > CD2_MAX_POLYGON_VERTICES)
			{
				return count > CD2_MAX_POLYGON_VERTICES ? CD_ERROR_TOO_MANY_POINTS : CD_ERROR_DEGENERATE;
			}
			cd2Vec points[CD2_MAX_POLYGON_VERTICES];
			for (int i = 0; i < count; ++i)
			{
				points[i] = v2(s + 3 + 2 * i);
			}
			cd2Polygon polygon;
			cdResult result = s[2] > 0.0f ? cd2MakeRoundedPolygon(points, count, s[2], &polygon)
										  : cd2MakePolygon(points, count, &polygon);
			if (result != CD_OK)
			{
				return result;
			}
			*out = cd2MakePolygonShape(&polygon);
			break;
		}
		case CD2_SHAPE_SEGMENT:
			*out = cd2MakeSegmentShape((cd2Segment){v2(s + 1), v2(s + 3)});
			break;
		default:
			return CD_ERROR_INVALID_ARGUMENT;
	}
	return cd2ValidateShape(out);
}

#define DECODE2_AB                                                                                           \
	cd2Shape a, b;                                                                                           \
	cdResult ra = decode2(SLOT_A, &a);                                                                       \
	if (ra != CD_OK)                                                                                         \
	{                                                                                                        \
		return -(int)ra;                                                                                     \
	}                                                                                                        \
	cdResult rb = decode2(SLOT_B, &b);                                                                       \
	if (rb != CD_OK)                                                                                         \
	{                                                                                                        \
		return -(32 + (int)rb);                                                                              \
	}

#define DECODE2_A                                                                                            \
	cd2Shape a;                                                                                              \
	cdResult ra = decode2(SLOT_A, &a);                                                                       \
	if (ra != CD_OK)                                                                                         \
	{                                                                                                        \
		return -(int)ra;                                                                                     \
	}

/* Validates shape A; on success writes its bounds to IO[0..3]. */
EXPORT("shape2Aabb") int cdjs2ShapeAabb(void)
{
	DECODE2_A
	cd2Aabb box = cd2ComputeShapeAabb(&a);
	put2(IO, box.min);
	put2(IO + 2, box.max);
	return 1;
}

/* Builds the polygon of shape A (type 4) and writes it: IO[0] count, IO[1] radius, IO[2..3]
 * centroid, then count vertices and count normals. */
EXPORT("polygon2Make") int cdjs2PolygonMake(void)
{
	DECODE2_A
	if (a.type != CD2_SHAPE_POLYGON)
	{
		return -(int)CD_ERROR_INVALID_ARGUMENT;
	}
	const cd2Polygon* p = &a.polygon;
	IO[0] = (float)p->count;
	IO[1] = p->radius;
	put2(IO + 2, p->centroid);
	for (int i = 0; i < p->count; ++i)
	{
		put2(IO + 4 + 2 * i, p->vertices[i]);
		put2(IO + 4 + 2 * p->count + 2 * i, p->normals[i]);
	}
	return 1;
}

EXPORT("mass2") int cdjs2Mass(float density)
{
	DECODE2_A
	cd2MassData m = cd2ComputeShapeMass(&a, density);
	IO[0] = m.mass;
	put2(IO + 1, m.center);
	IO[3] = m.rotationalInertia;
	return 1;
}

EXPORT("overlap2") int cdjs2Overlap(void)
{
	DECODE2_AB
	return cd2Overlap(&a, &b) ? 1 : 0;
}

EXPORT("pointIn2") int cdjs2PointIn(float x, float y)
{
	DECODE2_A
	return cd2PointInShape(&a, (cd2Vec){x, y}) ? 1 : 0;
}

EXPORT("closestPoint2") int cdjs2ClosestPoint(float x, float y)
{
	DECODE2_A
	put2(IO, cd2ClosestPointOnShape(&a, (cd2Vec){x, y}));
	return 1;
}

/* IO: fraction, point, normal. */
EXPORT("raycast2") int cdjs2Raycast(float ox, float oy, float tx, float ty)
{
	DECODE2_A
	cd2RayHit hit;
	if (!cd2Raycast(&a, (cd2Ray){{ox, oy}, {tx, ty}}, &hit))
	{
		return 0;
	}
	IO[0] = hit.fraction;
	put2(IO + 1, hit.point);
	put2(IO + 3, hit.normal);
	return 1;
}

/* IO: pointA, pointB, distance, iterations, hitIterationCap. */
EXPORT("distance2") int cdjs2Distance(void)
{
	DECODE2_AB
	cdDistanceStatus status;
	cd2ClosestPoints cp = cd2DistanceWithStatus(&a, &b, &status);
	put2(IO, cp.pointA);
	put2(IO + 2, cp.pointB);
	IO[4] = cp.distance;
	IO[5] = (float)status.iterations;
	IO[6] = status.hitIterationCap ? 1.0f : 0.0f;
	return 1;
}

/* IO: normal, then per point: point(2), separation, id (uint32 bits); returns the point count. */
EXPORT("collide2") int cdjs2Collide(float speculativeDistance)
{
	DECODE2_AB
	if (!(speculativeDistance >= 0.0f) || !isfinite(speculativeDistance))
	{
		return -64;
	}
	cd2Manifold m = cd2Collide(&a, &b, speculativeDistance);
	put2(IO, m.normal);
	for (int i = 0; i < m.pointCount; ++i)
	{
		float* o = IO + 2 + 4 * i;
		put2(o, m.points[i].point);
		o[2] = m.points[i].separation;
		putU32(o + 3, m.points[i].id);
	}
	return m.pointCount;
}

/* IO: hit, hitIterationCap, fraction, point, normal, iterations. */
EXPORT("shapeCast2") int cdjs2ShapeCast(float tx, float ty)
{
	DECODE2_AB
	cd2CastOutput c = cd2ShapeCast(&a, &b, (cd2Vec){tx, ty});
	IO[0] = c.hit ? 1.0f : 0.0f;
	IO[1] = c.hitIterationCap ? 1.0f : 0.0f;
	IO[2] = c.fraction;
	put2(IO + 3, c.point);
	put2(IO + 5, c.normal);
	IO[7] = (float)c.iterations;
	return 1;
}

static cd2Sweep sweep2(const float* s)
{
	return (cd2Sweep){v2(s), v2(s + 2), v2(s + 4), s[6], s[7]};
}

/* Sweeps in IO[0..7] (A) and IO[8..15] (B). IO out: state, t, iterations. */
EXPORT("timeOfImpact2") int cdjs2TimeOfImpact(float targetSeparation, float tolerance)
{
	DECODE2_AB
	if (!finiteAll(IO, 16) || !isfinite(targetSeparation) || !isfinite(tolerance) ||
		targetSeparation < 0.0f || tolerance <= 0.0f)
	{
		return -64;
	}
	cd2Sweep sa = sweep2(IO), sb = sweep2(IO + 8);
	cdToiOutput t = cd2TimeOfImpact(&a, &sa, &b, &sb, targetSeparation, tolerance);
	IO[0] = (float)t.state;
	IO[1] = t.t;
	IO[2] = (float)t.iterations;
	return 1;
}

/* ==== 3D ==================================================================================== */

static cdResult decode3(const float* s, cd3Shape* out)
{
	memset(out, 0, sizeof *out);
	int type = cdjsFloatToInt(s[0]);
	switch (type)
	{
		case CD3_SHAPE_SPHERE:
			*out = cd3MakeSphereShape((cd3Sphere){v3(s + 1), s[4]});
			break;
		case CD3_SHAPE_CAPSULE:
			*out = cd3MakeCapsuleShape((cd3Capsule){v3(s + 1), v3(s + 4), s[7]});
			break;
		case CD3_SHAPE_AABB:
			*out = cd3MakeAabbShape((cd3Aabb){v3(s + 1), v3(s + 4)});
			break;
		case CD3_SHAPE_BOX:
			*out = cd3MakeBoxShape((cd3Box){v3(s + 1), v3(s + 4), q3(s + 7)});
			break;
		case CD3_SHAPE_TRIANGLE:
			*out = cd3MakeTriangleShape((cd3Triangle){v3(s + 1), v3(s + 4), v3(s + 7)});
			break;
		case CD3_SHAPE_PLANE:
			*out = cd3MakePlaneShape((cd3Plane){v3(s + 1), s[4]});
			break;
		case CD3_SHAPE_SEGMENT:
			*out = cd3MakeSegmentShape((cd3Segment){v3(s + 1), v3(s + 4)});
			break;
		case CD3_SHAPE_HULL:
		{
			const cd3Hull* hull = (const cd3Hull*)jsHandleGet(getInt(s + 8), JS_HULL);
			if (hull == NULL)
			{
				return CD_ERROR_INVALID_ARGUMENT;
			}
			*out = cd3MakeHullShape(hull, (cd3Transform){v3(s + 1), q3(s + 4)});
			if (!cd3IsValidHullShape(out->hull))
			{
				return CD_ERROR_INVALID_ARGUMENT;
			}
			return CD_OK;
		}
		default:
			return CD_ERROR_INVALID_ARGUMENT;
	}
	return cd3ValidateShape(out);
}

#define DECODE3_AB                                                                                           \
	cd3Shape a, b;                                                                                           \
	cdResult ra = decode3(SLOT_A, &a);                                                                       \
	if (ra != CD_OK)                                                                                         \
	{                                                                                                        \
		return -(int)ra;                                                                                     \
	}                                                                                                        \
	cdResult rb = decode3(SLOT_B, &b);                                                                       \
	if (rb != CD_OK)                                                                                         \
	{                                                                                                        \
		return -(32 + (int)rb);                                                                              \
	}

#define DECODE3_A                                                                                            \
	cd3Shape a;                                                                                              \
	cdResult ra = decode3(SLOT_A, &a);                                                                       \
	if (ra != CD_OK)                                                                                         \
	{                                                                                                        \
		return -(int)ra;                                                                                     \
	}

EXPORT("shape3Aabb") int cdjs3ShapeAabb(void)
{
	DECODE3_A
	cd3Aabb box = cd3ComputeShapeAabb(&a);
	put3(IO, box.min);
	put3(IO + 3, box.max);
	return 1;
}

EXPORT("mass3") int cdjs3Mass(float density)
{
	DECODE3_A
	if (a.type == CD3_SHAPE_TRIANGLE || a.type == CD3_SHAPE_PLANE || a.type == CD3_SHAPE_SEGMENT)
	{
		return -(int)CD_ERROR_INVALID_ARGUMENT;
	}
	cd3MassData m = cd3ComputeShapeMass(&a, density);
	IO[0] = m.mass;
	put3(IO + 1, m.center);
	put3(IO + 4, m.inertia.cx);
	put3(IO + 7, m.inertia.cy);
	put3(IO + 10, m.inertia.cz);
	return 1;
}

EXPORT("overlap3") int cdjs3Overlap(void)
{
	DECODE3_AB
	return cd3Overlap(&a, &b) ? 1 : 0;
}

EXPORT("pointIn3") int cdjs3PointIn(float x, float y, float z)
{
	DECODE3_A
	return cd3PointInShape(&a, (cd3Vec){x, y, z}) ? 1 : 0;
}

EXPORT("closestPoint3") int cdjs3ClosestPoint(float x, float y, float z)
{
	DECODE3_A
	put3(IO, cd3ClosestPointOnShape(&a, (cd3Vec){x, y, z}));
	return 1;
}

EXPORT("raycast3") int cdjs3Raycast(float ox, float oy, float oz, float tx, float ty, float tz)
{
	DECODE3_A
	cd3RayHit hit;
	if (!cd3Raycast(&a, (cd3Ray){{ox, oy, oz}, {tx, ty, tz}}, &hit))
	{
		return 0;
	}
	IO[0] = hit.fraction;
	put3(IO + 1, hit.point);
	put3(IO + 4, hit.normal);
	return 1;
}

EXPORT("distance3") int cdjs3Distance(void)
{
	DECODE3_AB
	cdDistanceStatus status;
	cd3ClosestPoints cp = cd3DistanceWithStatus(&a, &b, &status);
	put3(IO, cp.pointA);
	put3(IO + 3, cp.pointB);
	IO[6] = cp.distance;
	IO[7] = (float)status.iterations;
	IO[8] = status.hitIterationCap ? 1.0f : 0.0f;
	return 1;
}

/* IO: normal, then per point: point(3), separation, id (uint32 bits). */
EXPORT("collide3") int cdjs3Collide(float speculativeDistance)
{
	DECODE3_AB
	if (!(speculativeDistance >= 0.0f) || !isfinite(speculativeDistance))
	{
		return -64;
	}
	cd3Manifold m = cd3Collide(&a, &b, speculativeDistance);
	put3(IO, m.normal);
	for (int i = 0; i < m.pointCount; ++i)
	{
		float* o = IO + 3 + 5 * i;
		put3(o, m.points[i].point);
		o[3] = m.points[i].separation;
		putU32(o + 4, m.points[i].id);
	}
	return m.pointCount;
}

EXPORT("shapeCast3") int cdjs3ShapeCast(float tx, float ty, float tz)
{
	DECODE3_AB
	cd3CastOutput c = cd3ShapeCast(&a, &b, (cd3Vec){tx, ty, tz});
	IO[0] = c.hit ? 1.0f : 0.0f;
	IO[1] = c.hitIterationCap ? 1.0f : 0.0f;
	IO[2] = c.fraction;
	put3(IO + 3, c.point);
	put3(IO + 6, c.normal);
	IO[9] = (float)c.iterations;
	return 1;
}

static cd3Sweep sweep3(const float* s)
{
	return (cd3Sweep){v3(s), v3(s + 3), v3(s + 6), q3(s + 9), q3(s + 13)};
}

/* Sweeps in IO[0..16] (A) and IO[17..33] (B). IO out: state, t, iterations. */
EXPORT("timeOfImpact3") int cdjs3TimeOfImpact(float targetSeparation, float tolerance)
{
	DECODE3_AB
	if (!finiteAll(IO, 34) || !isfinite(targetSeparation) || !isfinite(tolerance) ||
		targetSeparation < 0.0f || tolerance <= 0.0f)
	{
		return -64;
	}
	cd3Sweep sa = sweep3(IO), sb = sweep3(IO + 17);
	if (!cd3IsValidQuat(sa.rotation0) || !cd3IsValidQuat(sa.rotation1) || !cd3IsValidQuat(sb.rotation0) ||
		!cd3IsValidQuat(sb.rotation1))
	{
		return -65;
	}
	cdToiOutput t = cd3TimeOfImpact(&a, &sa, &b, &sb, targetSeparation, tolerance);
	IO[0] = (float)t.state;
	IO[1] = t.t;
	IO[2] = (float)t.iterations;
	return 1;
}

/* ---- hulls ---- */

/* kind 0: hull of `count` points at `points`; 1: box hull (IO[0..2] half extents); 2: cylinder,
 * 3: cone (IO[0] half height, IO[1] radius, count = segments). Writes the hull's handle into
 * IO[0] (int32 bits; 0 on failure) and returns CD_OK or the cdResult. */
EXPORT("hullCreate") int cdjs3HullCreate(int kind, const float* points, int count)
{
	cd3Hull* hull = NULL;
	cdResult result;
	switch (kind)
	{
		case 0:
			if (points == NULL || count < 0)
			{
				putInt(IO, 0);
				return CD_ERROR_INVALID_ARGUMENT;
			}
			result = cd3ComputeHull((const cd3Vec*)(const void*)points, count, &hull);
			break;
		case 1:
			result = cd3MakeBoxHull(v3(IO), &hull);
			break;
		case 2:
			result = cd3MakeCylinderHull(IO[0], IO[1], count, &hull);
			break;
		case 3:
			result = cd3MakeConeHull(IO[0], IO[1], count, &hull);
			break;
		default:
			putInt(IO, 0);
			return CD_ERROR_INVALID_ARGUMENT;
	}
	int32_t handle = 0;
	if (result == CD_OK)
	{
		handle = jsHandleAdd(hull, JS_HULL);
		if (handle == 0)
		{
			cd3DestroyHull(hull);
			result = CD_ERROR_OUT_OF_MEMORY;
		}
	}
	putInt(IO, handle);
	return (int)result;
}

/* A stale or unknown handle: nothing happens. */
EXPORT("hullDestroy") void cdjs3HullDestroy(int32_t handle)
{
	cd3Hull* hull = (cd3Hull*)jsHandleRemove(handle, JS_HULL);
	if (hull != NULL)
	{
		cd3DestroyHull(hull);
	}
}

/* IO: vertexCount, faceCount, edgeCount, volume, centroid(3), bounds(6); returns the pointer to
 * the vertices (vertexCount cd3Vec), NULL for a stale or unknown handle. */
EXPORT("hullInfo") const float* cdjs3HullInfo(int32_t handle)
{
	const cd3Hull* hull = (const cd3Hull*)jsHandleGet(handle, JS_HULL);
	if (hull == NULL)
	{
		return NULL;
	}
	IO[0] = (float)hull->vertexCount;
	IO[1] = (float)hull->faceCount;
	IO[2] = (float)hull->edgeCount;
	IO[3] = hull->volume;
	put3(IO + 4, hull->centroid);
	put3(IO + 7, hull->bounds.min);
	put3(IO + 10, hull->bounds.max);
	return &hull->vertices[0].x;
}

/* ==== batch queries ========================================================================= *
 * `data` holds `count` records of `stride` floats; the query volume is in IO. Writes the indices
 * of the records that overlap the query into `out` (room for count) and returns how many, or
 * -(i + 1) when record i holds a NaN or infinity. */

enum
{
	BATCH3_POINTS_IN_AABB,
	BATCH3_POINTS_IN_SPHERE,
	BATCH3_AABBS_AABB,
	BATCH3_AABBS_SPHERE,
	BATCH3_SPHERES_SPHERE,
	BATCH3_SPHERES_AABB,
	BATCH2_POINTS_IN_AABB,
	BATCH2_POINTS_IN_CIRCLE,
	BATCH2_AABBS_AABB,
	BATCH2_AABBS_CIRCLE,
	BATCH2_CIRCLES_CIRCLE,
	BATCH2_CIRCLES_AABB,
	BATCH_KIND_COUNT
};

static const int g_batchStride[BATCH_KIND_COUNT] = {3, 3, 6, 6, 4, 4, 2, 2, 4, 4, 3, 3};

/* Non-finite values (NaN, infinities) are the ones whose bits without the sign are at least
 * 0x7f800000. A maximum over the whole array has no branch and no dependence between elements, so
 * it vectorizes; only when it finds one does a second pass look for the first bad record. */
static int anyNonFinite(const float* data, size_t count)
{
	uint32_t largest = 0;
#if defined(__clang__)
#pragma clang loop vectorize_width(4) interleave_count(4)
#endif
	for (size_t i = 0; i < count; ++i)
	{
		uint32_t bits;
		memcpy(&bits, data + i, sizeof bits);
		bits &= 0x7fffffffu;
		largest = bits > largest ? bits : largest;
	}
	return largest >= 0x7f800000u;
}

static int firstNonFinite(const float* data, int count, int stride)
{
	for (int i = 0; i < count; ++i)
	{
		if (!finiteAll(data + (size_t)i * (size_t)stride, stride))
		{
			return i;
		}
	}
	return -1;
}

/* The test runs over blocks of records into a mask (a loop without branches or stores that depend
 * on earlier records, which the compiler can vectorize), then the indices of the set entries are
 * written out. */
#define BATCH_BLOCK 256
#define BATCH_LOOP(test)                                                                                     \
	for (int base = 0; base < count; base += BATCH_BLOCK)                                                    \
	{                                                                                                        \
		int m = count - base < BATCH_BLOCK ? count - base : BATCH_BLOCK;                                     \
		const float* block = data + (size_t)base * (size_t)stride;                                           \
		for (int j = 0; j < m; ++j)                                                                          \
		{                                                                                                    \
			const float* r = block + (size_t)j * (size_t)stride;                                             \
			mask[j] = (uint8_t)((test) ? 1 : 0);                                                             \
		}                                                                                                    \
		for (int j = m; j < ((m + 7) & ~7); ++j)                                                             \
		{                                                                                                    \
			mask[j] = 0;                                                                                     \
		}                                                                                                    \
		for (int j = 0; j < m; j += 8)                                                                       \
		{                                                                                                    \
			uint64_t eight;                                                                                  \
			memcpy(&eight, mask + j, sizeof eight);                                                          \
			if (eight == 0)                                                                                  \
			{                                                                                                \
				continue;                                                                                    \
			}                                                                                                \
			for (int k = j; k < j + 8; ++k)                                                                  \
			{                                                                                                \
				out[n] = base + k;                                                                           \
				n += mask[k];                                                                                \
			}                                                                                                \
		}                                                                                                    \
	}

EXPORT("batch") int cdjsBatch(int kind, const float* data, int count, int32_t* out)
{
	if (kind < 0 || kind >= BATCH_KIND_COUNT || count < 0 || (count > 0 && (data == NULL || out == NULL)))
	{
		return -(1 << 30);
	}
	const int stride = g_batchStride[kind];
	const float* q = IO;
	int n = 0;
	uint8_t mask[BATCH_BLOCK];
	if (anyNonFinite(data, (size_t)count * (size_t)stride))
	{
		return -(firstNonFinite(data, count, stride) + 1);
	}
	switch (kind)
	{
		case BATCH3_POINTS_IN_AABB:
		{
			cd3Aabb box = {v3(q), v3(q + 3)};
			BATCH_LOOP(cd3PointInAabb(v3(r), box))
			break;
		}
		case BATCH3_POINTS_IN_SPHERE:
		{
			cd3Sphere s = {v3(q), q[3]};
			BATCH_LOOP(cd3PointInSphere(v3(r), s))
			break;
		}
		case BATCH3_AABBS_AABB:
		{
			cd3Aabb box = {v3(q), v3(q + 3)};
			BATCH_LOOP(cd3OverlapAabbAabb((cd3Aabb){v3(r), v3(r + 3)}, box))
			break;
		}
		case BATCH3_AABBS_SPHERE:
		{
			cd3Sphere s = {v3(q), q[3]};
			BATCH_LOOP(cd3OverlapSphereAabb(s, (cd3Aabb){v3(r), v3(r + 3)}))
			break;
		}
		case BATCH3_SPHERES_SPHERE:
		{
			cd3Sphere s = {v3(q), q[3]};
			BATCH_LOOP(cd3OverlapSphereSphere((cd3Sphere){v3(r), r[3]}, s))
			break;
		}
		case BATCH3_SPHERES_AABB:
		{
			cd3Aabb box = {v3(q), v3(q + 3)};
			BATCH_LOOP(cd3OverlapSphereAabb((cd3Sphere){v3(r), r[3]}, box))
			break;
		}
		case BATCH2_POINTS_IN_AABB:
		{
			cd2Aabb box = {v2(q), v2(q + 2)};
			BATCH_LOOP(cd2PointInAabb(v2(r), box))
			break;
		}
		case BATCH2_POINTS_IN_CIRCLE:
		{
			cd2Circle c = {v2(q), q[2]};
			BATCH_LOOP(cd2PointInCircle(v2(r), c))
			break;
		}
		case BATCH2_AABBS_AABB:
		{
			cd2Aabb box = {v2(q), v2(q + 2)};
			BATCH_LOOP(cd2OverlapAabbAabb((cd2Aabb){v2(r), v2(r + 2)}, box))
			break;
		}
		case BATCH2_AABBS_CIRCLE:
		{
			cd2Circle c = {v2(q), q[2]};
			BATCH_LOOP(cd2OverlapCircleAabb(c, (cd2Aabb){v2(r), v2(r + 2)}))
			break;
		}
		case BATCH2_CIRCLES_CIRCLE:
		{
			cd2Circle c = {v2(q), q[2]};
			BATCH_LOOP(cd2OverlapCircleCircle((cd2Circle){v2(r), r[2]}, c))
			break;
		}
		case BATCH2_CIRCLES_AABB:
		{
			cd2Aabb box = {v2(q), v2(q + 2)};
			BATCH_LOOP(cd2OverlapCircleAabb((cd2Circle){v2(r), r[2]}, box))
			break;
		}
		default:
			break;
	}
	return n;
}

/* The texts' single tests with plain numbers (no memory traffic). */
EXPORT("pointInAabb3")
int cdjs3PointInAabb(float px, float py, float pz, float minX, float minY, float minZ, float maxX, float maxY,
					 float maxZ)
{
	return cd3PointInAabb((cd3Vec){px, py, pz}, (cd3Aabb){{minX, minY, minZ}, {maxX, maxY, maxZ}}) ? 1 : 0;
}

EXPORT("overlapAabbAabb3")
int cdjs3OverlapAabbAabb(float aMinX, float aMinY, float aMinZ, float aMaxX, float aMaxY, float aMaxZ,
						 float bMinX, float bMinY, float bMinZ, float bMaxX, float bMaxY, float bMaxZ)
{
	return cd3OverlapAabbAabb((cd3Aabb){{aMinX, aMinY, aMinZ}, {aMaxX, aMaxY, aMaxZ}},
							  (cd3Aabb){{bMinX, bMinY, bMinZ}, {bMaxX, bMaxY, bMaxZ}})
			   ? 1
			   : 0;
}

EXPORT("pointInSphere3")
int cdjs3PointInSphere(float px, float py, float pz, float cx, float cy, float cz, float r)
{
	return cd3PointInSphere((cd3Vec){px, py, pz}, (cd3Sphere){{cx, cy, cz}, r}) ? 1 : 0;
}

EXPORT("overlapSphereSphere3")
int cdjs3OverlapSphereSphere(float ax, float ay, float az, float ar, float bx, float by, float bz, float br)
{
	return cd3OverlapSphereSphere((cd3Sphere){{ax, ay, az}, ar}, (cd3Sphere){{bx, by, bz}, br}) ? 1 : 0;
}

EXPORT("overlapSphereAabb3")
int cdjs3OverlapSphereAabb(float cx, float cy, float cz, float r, float minX, float minY, float minZ,
						   float maxX, float maxY, float maxZ)
{
	return cd3OverlapSphereAabb((cd3Sphere){{cx, cy, cz}, r},
								(cd3Aabb){{minX, minY, minZ}, {maxX, maxY, maxZ}})
			   ? 1
			   : 0;
}

/* ==== 3D triangle meshes (lib/mesh3.js) ======================================================
 * A mesh crosses as its handle. Calls that place the mesh take its transform from IO[0..6]
 * (position x y z, rotation x y z w), read before any result is written. Variable-length results
 * go to a buffer of the caller's (out, capacity) and the return value is the full count, so the
 * caller can grow the buffer and ask again. */

static bool meshTransform(cd3Transform* t)
{
	if (!finiteAll(IO, 7))
	{
		return false;
	}
	*t = (cd3Transform){v3(IO), q3(IO + 3)};
	return true;
}

/* Builds a mesh from `vertexCount` x y z triples and `triangleCount` index triples; the mesh's
 * handle goes to IO[0] (0 on failure). Returns the cdResult. */
EXPORT("mesh3Create")
int cdjs3MeshCreate(const float* vertices, int vertexCount, const int* indices, int triangleCount)
{
	cd3Mesh* mesh = NULL;
	cdResult result =
		cd3CreateMesh((const cd3Vec*)(const void*)vertices, vertexCount, indices, triangleCount, &mesh);
	int32_t handle = 0;
	if (result == CD_OK)
	{
		handle = jsHandleAdd(mesh, JS_MESH);
		if (handle == 0)
		{
			cd3DestroyMesh(mesh);
			result = CD_ERROR_OUT_OF_MEMORY;
		}
	}
	putInt(IO, handle);
	return (int)result;
}

EXPORT("mesh3Destroy") void cdjs3MeshDestroy(int32_t handle)
{
	cd3Mesh* mesh = (cd3Mesh*)jsHandleRemove(handle, JS_MESH);
	if (mesh != NULL)
	{
		cd3DestroyMesh(mesh);
	}
}

/* The mesh of `handle` as `mesh`; a stale or unknown handle returns `refused` from the export. */
#define MESH_OF(handle, refused)                                                                             \
	const cd3Mesh* mesh = (const cd3Mesh*)jsHandleGet(handle, JS_MESH);                                      \
	if (mesh == NULL)                                                                                        \
	{                                                                                                        \
		return refused;                                                                                      \
	}

/* IO: triangleCount, droppedTriangleCount, vertexCount, nodeCount, leafCount, depth,
 * activeEdgeCount, bounds min (3), max (3), bytes; returns cd3ValidateMesh's result. */
EXPORT("mesh3Info") int cdjs3MeshInfo(int32_t handle)
{
	MESH_OF(handle, (int)CD_ERROR_INVALID_ARGUMENT)
	cd3MeshStats s = cd3Mesh_GetStats(mesh);
	IO[0] = (float)s.triangleCount;
	IO[1] = (float)s.droppedTriangleCount;
	IO[2] = (float)s.vertexCount;
	IO[3] = (float)s.nodeCount;
	IO[4] = (float)s.leafCount;
	IO[5] = (float)s.depth;
	IO[6] = (float)s.activeEdgeCount;
	put3(IO + 7, s.bounds.min);
	put3(IO + 10, s.bounds.max);
	IO[13] = (float)s.bytes;
	return (int)cd3ValidateMesh(mesh);
}

/* IO: a b c of the triangle with input index `index` (mesh space); 0 for a dropped or unknown index. */
EXPORT("mesh3Triangle") int cdjs3MeshTriangle(int32_t handle, int index)
{
	MESH_OF(handle, 0)
	cd3Triangle t;
	if (!cd3Mesh_GetTriangle(mesh, index, &t))
	{
		return 0;
	}
	put3(IO, t.a);
	put3(IO + 3, t.b);
	put3(IO + 6, t.c);
	return 1;
}

/* anyHit 0: IO gets fraction, point, normal, triangleIndex (int); 1: only whether it hits.
 * Returns 1 on a hit, 0 on a miss, -64 for a non-finite transform or ray. */
EXPORT("mesh3Raycast")
int cdjs3MeshRaycast(int32_t handle, float ox, float oy, float oz, float tx, float ty, float tz, int anyHit)
{
	MESH_OF(handle, -64)
	cd3Transform t;
	const float ray[6] = {ox, oy, oz, tx, ty, tz};
	if (!meshTransform(&t) || !finiteAll(ray, 6))
	{
		return -64;
	}
	cd3Ray r = {{ox, oy, oz}, {tx, ty, tz}};
	if (anyHit)
	{
		return cd3RaycastMeshAny(mesh, t, r) ? 1 : 0;
	}
	cd3MeshRayHit hit;
	if (!cd3RaycastMesh(mesh, t, r, &hit))
	{
		return 0;
	}
	IO[0] = hit.hit.fraction;
	put3(IO + 1, hit.hit.point);
	put3(IO + 4, hit.hit.normal);
	putInt(IO + 7, hit.triangleIndex);
	return 1;
}

typedef struct JsIndexList
{
	int32_t* out;
	int capacity, count;
} JsIndexList;

static bool meshQueryCollect(int triangleIndex, void* context)
{
	JsIndexList* list = (JsIndexList*)context;
	if (list->count < list->capacity)
	{
		list->out[list->count] = triangleIndex;
	}
	list->count++;
	return true;
}

/* Input indices of the triangles whose bounds overlap the box (mesh space) into out (at most
 * capacity); returns how many there are. */
EXPORT("mesh3QueryAabb")
int cdjs3MeshQueryAabb(int32_t handle, float minX, float minY, float minZ, float maxX, float maxY, float maxZ,
					   int32_t* out, int capacity)
{
	MESH_OF(handle, -64)
	const float box[6] = {minX, minY, minZ, maxX, maxY, maxZ};
	if (capacity < 0 || (capacity > 0 && out == NULL) || !finiteAll(box, 6))
	{
		return -64;
	}
	JsIndexList list = {out, capacity, 0};
	cd3Mesh_QueryAabb(mesh, (cd3Aabb){{minX, minY, minZ}, {maxX, maxY, maxZ}}, meshQueryCollect, &list);
	return list.count;
}

/* Shape A against the mesh: 1 when they touch. */
EXPORT("mesh3Overlap") int cdjs3MeshOverlap(int32_t handle)
{
	MESH_OF(handle, -64)
	cd3Transform t;
	if (!meshTransform(&t))
	{
		return -64;
	}
	DECODE3_A
	return cd3OverlapMesh(&a, mesh, t) ? 1 : 0;
}

/* IO: point, distance, triangleIndex (int). Returns 1, or 0 when nothing is within maxDistance. */
EXPORT("mesh3ClosestPoint")
int cdjs3MeshClosestPoint(int32_t handle, float px, float py, float pz, float maxDistance)
{
	MESH_OF(handle, -64)
	cd3Transform t;
	const float p[3] = {px, py, pz};
	if (!meshTransform(&t) || !finiteAll(p, 3) || !(maxDistance >= 0.0f))
	{
		return -64;
	}
	cd3MeshClosestPoint result;
	if (!cd3ClosestPointOnMesh(mesh, t, (cd3Vec){px, py, pz},
							   isfinite(maxDistance) ? maxDistance : CD_REAL_MAX, &result))
	{
		return 0;
	}
	put3(IO, result.point);
	IO[3] = result.distance;
	putInt(IO + 4, result.triangleIndex);
	return 1;
}

/* Shape A against the mesh: at most `capacity` manifolds into out, 25 floats each: triangleIndex
 * (int), normal (3), pointCount, then 4 points of point (3), separation, id (uint32). Returns how
 * many were written (cd3CollideMesh keeps the first `capacity` it meets). */
#define MESH_MANIFOLD_FLOATS 25
EXPORT("mesh3Collide")
int cdjs3MeshCollide(int32_t handle, float speculativeDistance, float* out, int capacity)
{
	MESH_OF(handle, -64)
	cd3Transform t;
	if (!meshTransform(&t) || !(speculativeDistance >= 0.0f) || !isfinite(speculativeDistance) ||
		capacity < 0 || (capacity > 0 && out == NULL))
	{
		return -64;
	}
	DECODE3_A
	if (capacity == 0)
	{
		return 0;
	}
	cd3MeshManifold* manifolds = (cd3MeshManifold*)malloc((size_t)capacity * sizeof(cd3MeshManifold));
	if (manifolds == NULL)
	{
		return -(int)CD_ERROR_OUT_OF_MEMORY;
	}
	int n = cd3CollideMesh(&a, mesh, t, speculativeDistance, manifolds, capacity);
	for (int k = 0; k < n; ++k)
	{
		const cd3Manifold* m = &manifolds[k].manifold;
		float* o = out + MESH_MANIFOLD_FLOATS * k;
		memset(o, 0, MESH_MANIFOLD_FLOATS * sizeof(float));
		putInt(o, manifolds[k].triangleIndex);
		put3(o + 1, m->normal);
		o[4] = (float)m->pointCount;
		for (int i = 0; i < m->pointCount; ++i)
		{
			float* q = o + 5 + 5 * i;
			put3(q, m->points[i].point);
			q[3] = m->points[i].separation;
			putU32(q + 4, m->points[i].id);
		}
	}
	free(manifolds);
	return n;
}

/* ==== 2D chains (lib/chain2.js) ==============================================================
 * As meshes: the chain crosses as its handle, placed by IO[0..2] (position x y, angle). */

static bool chainTransform(cd2Transform* t)
{
	if (!finiteAll(IO, 3))
	{
		return false;
	}
	*t = (cd2Transform){v2(IO), cd2MakeRot(IO[2])};
	return true;
}

/* Builds a chain of `count` x y pairs; its handle goes to IO[0] (0 on failure). Returns the cdResult. */
EXPORT("chain2Build") int cdjs2ChainBuild(const float* points, int count, int isLoop)
{
	cd2Chain* chain = NULL;
	cdResult result = cd2CreateChain((const cd2Vec*)(const void*)points, count, isLoop != 0, &chain);
	int32_t handle = 0;
	if (result == CD_OK)
	{
		handle = jsHandleAdd(chain, JS_CHAIN);
		if (handle == 0)
		{
			cd2DestroyChain(chain);
			result = CD_ERROR_OUT_OF_MEMORY;
		}
	}
	putInt(IO, handle);
	return (int)result;
}

EXPORT("chain2Free") void cdjs2ChainFree(int32_t handle)
{
	cd2Chain* chain = (cd2Chain*)jsHandleRemove(handle, JS_CHAIN);
	if (chain != NULL)
	{
		cd2DestroyChain(chain);
	}
}

/* The chain of `handle` as `chain`; a stale or unknown handle returns `refused` from the export. */
#define CHAIN_OF(handle, refused)                                                                            \
	const cd2Chain* chain = (const cd2Chain*)jsHandleGet(handle, JS_CHAIN);                                  \
	if (chain == NULL)                                                                                       \
	{                                                                                                        \
		return refused;                                                                                      \
	}

/* IO: segmentCount, pointCount, isLoop, bounds min (2), max (2); returns the points (x y pairs,
 * after welding), NULL for a stale or unknown handle. */
EXPORT("chain2Info") const float* cdjs2ChainInfo(int32_t handle)
{
	CHAIN_OF(handle, NULL)
	IO[0] = (float)cd2Chain_GetSegmentCount(chain);
	IO[1] = (float)cd2Chain_GetPointCount(chain);
	IO[2] = cd2Chain_IsLoop(chain) ? 1.0f : 0.0f;
	cd2Aabb b = cd2Chain_GetBounds(chain);
	put2(IO + 3, b.min);
	put2(IO + 5, b.max);
	return &cd2Chain_GetPoints(chain)[0].x;
}

/* IO: ghost1, p1, p2, ghost2 of segment `index`; 0 when index is out of range. */
EXPORT("chain2Segment") int cdjs2ChainSegment(int32_t handle, int index)
{
	CHAIN_OF(handle, 0)
	if (index < 0 || index >= cd2Chain_GetSegmentCount(chain))
	{
		return 0;
	}
	cd2ChainSegment s = cd2Chain_GetSegment(chain, index);
	put2(IO, s.ghost1);
	put2(IO + 2, s.p1);
	put2(IO + 4, s.p2);
	put2(IO + 6, s.ghost2);
	return 1;
}

/* IO: fraction, point, normal, segmentIndex (int). 1 on a hit, 0 on a miss, -64 for bad input. */
EXPORT("chain2Raycast") int cdjs2ChainRaycast(int32_t handle, float ox, float oy, float tx, float ty)
{
	CHAIN_OF(handle, -64)
	cd2Transform t;
	const float ray[4] = {ox, oy, tx, ty};
	if (!chainTransform(&t) || !finiteAll(ray, 4))
	{
		return -64;
	}
	cd2RayHit hit;
	int segment = -1;
	if (!cd2RaycastChain(chain, t, (cd2Ray){{ox, oy}, {tx, ty}}, &hit, &segment))
	{
		return 0;
	}
	IO[0] = hit.fraction;
	put2(IO + 1, hit.point);
	put2(IO + 3, hit.normal);
	putInt(IO + 5, segment);
	return 1;
}

/* Segments whose bounds overlap the box (world space) into out (at most capacity); returns how
 * many there are, -64 for bad input. */
EXPORT("chain2QueryAabb")
int cdjs2ChainQueryAabb(int32_t handle, float minX, float minY, float maxX, float maxY, int32_t* out,
						int capacity)
{
	CHAIN_OF(handle, -64)
	cd2Transform t;
	const float box[4] = {minX, minY, maxX, maxY};
	if (!chainTransform(&t) || !finiteAll(box, 4) || capacity < 0 || (capacity > 0 && out == NULL))
	{
		return -64;
	}
	JsIndexList list = {out, capacity, 0};
	cd2Chain_QueryAabb(chain, t, (cd2Aabb){{minX, minY}, {maxX, maxY}}, meshQueryCollect, &list);
	return list.count;
}

/* The chain (A) against shape A of the scratch block (B): at most `capacity` manifolds into out,
 * 12 floats each: segmentIndex (int), normal (2), pointCount, then 2 points of point (2),
 * separation, id (uint32). Returns how many were written. */
#define CHAIN_MANIFOLD_FLOATS 12
EXPORT("chain2Collide")
int cdjs2ChainCollide(int32_t handle, float speculativeDistance, float* out, int capacity)
{
	CHAIN_OF(handle, -64)
	cd2Transform t;
	if (!chainTransform(&t) || !(speculativeDistance >= 0.0f) || !isfinite(speculativeDistance) ||
		capacity < 0 || (capacity > 0 && out == NULL))
	{
		return -64;
	}
	DECODE2_A
	if (capacity == 0)
	{
		return 0;
	}
	cd2Manifold* manifolds = (cd2Manifold*)malloc((size_t)capacity * sizeof(cd2Manifold));
	int* segments = (int*)malloc((size_t)capacity * sizeof(int));
	if (manifolds == NULL || segments == NULL)
	{
		free(manifolds);
		free(segments);
		return -(int)CD_ERROR_OUT_OF_MEMORY;
	}
	int n = cd2CollideChain(chain, t, &a, speculativeDistance, manifolds, capacity, segments);
	for (int k = 0; k < n; ++k)
	{
		const cd2Manifold* m = manifolds + k;
		float* o = out + CHAIN_MANIFOLD_FLOATS * k;
		memset(o, 0, CHAIN_MANIFOLD_FLOATS * sizeof(float));
		putInt(o, segments[k]);
		put2(o + 1, m->normal);
		o[3] = (float)m->pointCount;
		for (int i = 0; i < m->pointCount; ++i)
		{
			float* q = o + 4 + 4 * i;
			put2(q, m->points[i].point);
			q[2] = m->points[i].separation;
			putU32(q + 3, m->points[i].id);
		}
	}
	free(manifolds);
	free(segments);
	return n;
}
