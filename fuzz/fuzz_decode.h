/* Shape decoding shared by the manifold and cast fuzzers (fuzz_manifold2.c, fuzz_manifold3.c,
 * fuzz_cast.c): valid shapes only (the validators are fuzzed by fuzz_query2/3), clamped into the
 * documented range (fuzz_common.h), plus the helpers their checks need: scale, printing, moving a
 * shape by a translation or a rigid transform, closest-point distance of a point to a shape. */
#ifndef COLLIDE_FUZZ_DECODE_H
#define COLLIDE_FUZZ_DECODE_H

#include "fuzz_common.h"

/* ---- open findings ------------------------------------------------------------------------------ */

/* true when `list` (comma-separated) names `check`. */
static inline bool FuzzInList(const char* list, const char* check)
{
	size_t length = strlen(check);
	for (const char* at = list; at != NULL && *at != 0;)
	{
		const char* end = strchr(at, ',');
		size_t n = end != NULL ? (size_t)(end - at) : strlen(at);
		if (n == length && strncmp(at, check, n) == 0)
		{
			return true;
		}
		at = end != NULL ? end + 1 : NULL;
	}
	return false;
}

/* A check to pass over: named in FUZZ_SKIP, or one of the target's open findings (checks that
 * fail on inputs its short CI run reaches, each with a file and a row in fuzz/crashes/README.md),
 * unless FUZZ_STRICT is set. Passing over an open finding is said aloud once per process, so it is
 * never silent; a name leaves the list when its bug is fixed. */
static inline bool FuzzPassOver(const char* target, const char* openFindings, const char* check)
{
	if (FuzzSkipped(check))
	{
		return true;
	}
	if (getenv("FUZZ_STRICT") != NULL || !FuzzInList(openFindings, check))
	{
		return false;
	}
	static bool announced = false;
	if (!announced)
	{
		fprintf(stderr,
				"%s: passing over the open findings %s (fuzz/crashes/README.md; FUZZ_STRICT=1 checks them)\n",
				target, openFindings);
		announced = true;
	}
	return true;
}

/* ---- 3D -------------------------------------------------------------------------------------- */

enum
{
	FUZZ_DECODE_MAX_HULL_POINTS = 12
};

/* The hulls of the two shapes of an input (built from 4 to 12 decoded points, freed at its end). */
typedef struct FuzzHullSlot
{
	cd3Hull* hull;
	cd3Vec points[FUZZ_DECODE_MAX_HULL_POINTS];
	int count;
} FuzzHullSlot;

static FuzzHullSlot s_fuzzHulls[2];

static inline void FuzzFreeHulls(void)
{
	for (int i = 0; i < 2; ++i)
	{
		cd3DestroyHull(s_fuzzHulls[i].hull);
		s_fuzzHulls[i].hull = NULL;
		s_fuzzHulls[i].count = 0;
	}
}

static inline cd3Vec FuzzVec3(FuzzReader* r)
{
	cdReal x = FuzzClampReal(FuzzRawReal(r)), y = FuzzClampReal(FuzzRawReal(r)),
		   z = FuzzClampReal(FuzzRawReal(r));
	return cd3MakeVec(x, y, z);
}

static inline cd3Quat FuzzQuat(FuzzReader* r)
{
	cdReal x = FuzzClampReal(FuzzRawReal(r)), y = FuzzClampReal(FuzzRawReal(r)),
		   z = FuzzClampReal(FuzzRawReal(r)), w = FuzzClampReal(FuzzRawReal(r));
	return cd3NormalizeQuat(cd3MakeQuat(x, y, z, w));
}

/* One valid shape of the type chosen by a byte among `types` (count of them), false when the
 * decoded data gives none (a hull that cd3ComputeHull refuses, a zero-area triangle). */
static inline bool FuzzDecodeShape3(FuzzReader* r, int slot, const cd3ShapeType* types, int typeCount,
									cd3Shape* s)
{
	memset(s, 0, sizeof *s);
	s->type = types[FuzzByte(r) % typeCount];
	switch (s->type)
	{
		case CD3_SHAPE_SPHERE:
			s->sphere.center = FuzzVec3(r);
			s->sphere.radius = FuzzClampSize(FuzzRawReal(r));
			break;
		case CD3_SHAPE_CAPSULE:
			s->capsule.p1 = FuzzVec3(r);
			s->capsule.p2 = FuzzVec3(r);
			s->capsule.radius = FuzzClampSize(FuzzRawReal(r));
			break;
		case CD3_SHAPE_AABB:
		{
			cd3Vec p = FuzzVec3(r), q = FuzzVec3(r);
			s->aabb.min = cd3Min(p, q);
			s->aabb.max = cd3Max(p, q);
			break;
		}
		case CD3_SHAPE_BOX:
			s->box.center = FuzzVec3(r);
			s->box.halfExtents = cd3Abs(FuzzVec3(r));
			s->box.rotation = FuzzQuat(r);
			break;
		case CD3_SHAPE_TRIANGLE:
			s->triangle.a = FuzzVec3(r);
			s->triangle.b = FuzzVec3(r);
			s->triangle.c = FuzzVec3(r);
			break;
		case CD3_SHAPE_PLANE:
		{
			cd3Vec n = cd3Normalize(FuzzVec3(r));
			s->plane.normal =
				cd3LengthSquared(n) > CD_R(0.0) ? n : cd3MakeVec(CD_R(0.0), CD_R(0.0), CD_R(1.0));
			s->plane.offset = FuzzClampReal(FuzzRawReal(r));
			break;
		}
		case CD3_SHAPE_SEGMENT:
			s->segment.p1 = FuzzVec3(r);
			s->segment.p2 = FuzzVec3(r);
			break;
		default:
		{
			s->type = CD3_SHAPE_HULL;
			s->hull.transform.p = FuzzVec3(r);
			s->hull.transform.q = FuzzQuat(r);
			FuzzHullSlot* h = &s_fuzzHulls[slot];
			h->count = 4 + FuzzByte(r) % (FUZZ_DECODE_MAX_HULL_POINTS - 3);
			for (int i = 0; i < h->count; ++i)
			{
				h->points[i] = FuzzVec3(r);
			}
			if (cd3ComputeHull(h->points, h->count, &h->hull) != CD_OK)
			{
				return false;
			}
			s->hull.hull = h->hull;
			break;
		}
	}
	return cd3ValidateShape(s) == CD_OK;
}

static inline double FuzzVec3MaxAbs(double m, cd3Vec v)
{
	return FuzzMaxAbs(FuzzMaxAbs(FuzzMaxAbs(m, v.x), v.y), v.z);
}

static inline bool FuzzFiniteVec3(cd3Vec v)
{
	return FuzzFinite(v.x) && FuzzFinite(v.y) && FuzzFinite(v.z);
}

static inline double FuzzDistance3(cd3Vec a, cd3Vec b)
{
	double dx = (double)b.x - (double)a.x, dy = (double)b.y - (double)a.y, dz = (double)b.z - (double)a.z;
	return sqrt(dx * dx + dy * dy + dz * dz);
}

/* The largest magnitude of the shape's positions and sizes. */
static inline double FuzzShapeScale3(const cd3Shape* s)
{
	switch (s->type)
	{
		case CD3_SHAPE_SPHERE:
			return FuzzMaxAbs(FuzzVec3MaxAbs(0.0, s->sphere.center), s->sphere.radius);
		case CD3_SHAPE_CAPSULE:
			return FuzzMaxAbs(FuzzVec3MaxAbs(FuzzVec3MaxAbs(0.0, s->capsule.p1), s->capsule.p2),
							  s->capsule.radius);
		case CD3_SHAPE_AABB:
			return FuzzVec3MaxAbs(FuzzVec3MaxAbs(0.0, s->aabb.min), s->aabb.max);
		case CD3_SHAPE_BOX:
			return FuzzVec3MaxAbs(0.0, s->box.center) + 2.0 * FuzzVec3MaxAbs(0.0, s->box.halfExtents);
		case CD3_SHAPE_TRIANGLE:
			return FuzzVec3MaxAbs(FuzzVec3MaxAbs(FuzzVec3MaxAbs(0.0, s->triangle.a), s->triangle.b),
								  s->triangle.c);
		case CD3_SHAPE_PLANE:
			return fabs((double)s->plane.offset);
		case CD3_SHAPE_SEGMENT:
			return FuzzVec3MaxAbs(FuzzVec3MaxAbs(0.0, s->segment.p1), s->segment.p2);
		default:
		{
			const cd3Hull* h = s->hull.hull;
			return FuzzVec3MaxAbs(0.0, s->hull.transform.p) +
				   2.0 * FuzzVec3MaxAbs(FuzzVec3MaxAbs(0.0, h->bounds.min), h->bounds.max);
		}
	}
}

static inline void FuzzPrintShape3(const char* label, const cd3Shape* s)
{
	fprintf(stderr, "  %s %s:", label, cd3GetShapeTypeName(s->type));
	switch (s->type)
	{
		case CD3_SHAPE_SPHERE:
			FuzzPrintReals("center radius", "", &s->sphere.center.x, 4);
			break;
		case CD3_SHAPE_CAPSULE:
			FuzzPrintReals("p1 p2 radius", "", &s->capsule.p1.x, 7);
			break;
		case CD3_SHAPE_AABB:
			FuzzPrintReals("min max", "", &s->aabb.min.x, 6);
			break;
		case CD3_SHAPE_BOX:
			FuzzPrintReals("center halfExtents q", "", &s->box.center.x, 10);
			break;
		case CD3_SHAPE_TRIANGLE:
			FuzzPrintReals("a b c", "", &s->triangle.a.x, 9);
			break;
		case CD3_SHAPE_PLANE:
			FuzzPrintReals("normal offset", "", &s->plane.normal.x, 4);
			break;
		case CD3_SHAPE_SEGMENT:
			FuzzPrintReals("p1 p2", "", &s->segment.p1.x, 6);
			break;
		default:
			FuzzPrintReals("p q", "", &s->hull.transform.p.x, 7);
			for (int i = 0; i < 2; ++i)
			{
				if (s->hull.hull == s_fuzzHulls[i].hull)
				{
					FuzzPrintReals("hull of the points", "(x y z ...)", &s_fuzzHulls[i].points[0].x,
								   3 * s_fuzzHulls[i].count);
				}
			}
			break;
	}
}

/* The shape moved by x -> q x + p. AABBs, which cannot turn, only when q is the identity. */
static inline cd3Shape FuzzTransformShape3(const cd3Shape* shape, cd3Transform t)
{
	cd3Shape s = *shape;
	switch (s.type)
	{
		case CD3_SHAPE_SPHERE:
			s.sphere.center = cd3TransformPoint(t, s.sphere.center);
			break;
		case CD3_SHAPE_CAPSULE:
			s.capsule.p1 = cd3TransformPoint(t, s.capsule.p1);
			s.capsule.p2 = cd3TransformPoint(t, s.capsule.p2);
			break;
		case CD3_SHAPE_AABB:
			s.aabb.min = cd3Add(s.aabb.min, t.p);
			s.aabb.max = cd3Add(s.aabb.max, t.p);
			break;
		case CD3_SHAPE_BOX:
			s.box.center = cd3TransformPoint(t, s.box.center);
			s.box.rotation = cd3NormalizeQuat(cd3MulQuat(t.q, s.box.rotation));
			break;
		case CD3_SHAPE_TRIANGLE:
			s.triangle.a = cd3TransformPoint(t, s.triangle.a);
			s.triangle.b = cd3TransformPoint(t, s.triangle.b);
			s.triangle.c = cd3TransformPoint(t, s.triangle.c);
			break;
		case CD3_SHAPE_PLANE:
			s.plane.normal = cd3RotateVector(t.q, s.plane.normal);
			s.plane.offset += cd3Dot(s.plane.normal, t.p);
			break;
		case CD3_SHAPE_SEGMENT:
			s.segment.p1 = cd3TransformPoint(t, s.segment.p1);
			s.segment.p2 = cd3TransformPoint(t, s.segment.p2);
			break;
		default:
			s.hull.transform = cd3MulTransforms(t, s.hull.transform);
			s.hull.transform.q = cd3NormalizeQuat(s.hull.transform.q);
			break;
	}
	return s;
}

static inline cd3Shape FuzzTranslateShape3(const cd3Shape* shape, cd3Vec d)
{
	cd3Transform t = {d, CD3_QUAT_IDENTITY};
	return FuzzTransformShape3(shape, t);
}

/* 14 unit directions: the axes and the cube diagonals. */
static inline cd3Vec FuzzDirection3(int i)
{
	if (i < 6)
	{
		cdReal sign = (i & 1) ? CD_R(-1.0) : CD_R(1.0);
		return cd3MakeVec(i / 2 == 0 ? sign : CD_R(0.0), i / 2 == 1 ? sign : CD_R(0.0),
						  i / 2 == 2 ? sign : CD_R(0.0));
	}
	int k = i - 6;
	cdReal c = CD_R(0.57735026918962576);
	return cd3MakeVec((k & 1) ? -c : c, (k & 2) ? -c : c, (k & 4) ? -c : c);
}

/* The pair still overlaps (distance exactly 0) after b moves by `band` in any of 14 directions. */
static inline bool FuzzDeeplyOverlapping3(const cd3Shape* a, const cd3Shape* b, double band)
{
	for (int i = 0; i < 14; ++i)
	{
		cd3Shape moved = FuzzTranslateShape3(b, cd3Scale((cdReal)band, FuzzDirection3(i)));
		if (cd3Distance(a, &moved).distance != CD_R(0.0))
		{
			return false;
		}
	}
	return true;
}

/* ---- 2D -------------------------------------------------------------------------------------- */

static inline cd2Vec FuzzVec2(FuzzReader* r)
{
	cdReal x = FuzzClampReal(FuzzRawReal(r)), y = FuzzClampReal(FuzzRawReal(r));
	return cd2MakeVec(x, y);
}

static inline bool FuzzDecodeShape2(FuzzReader* r, const cd2ShapeType* types, int typeCount, cd2Shape* s)
{
	memset(s, 0, sizeof *s);
	s->type = types[FuzzByte(r) % typeCount];
	switch (s->type)
	{
		case CD2_SHAPE_CIRCLE:
			s->circle.center = FuzzVec2(r);
			s->circle.radius = FuzzClampSize(FuzzRawReal(r));
			break;
		case CD2_SHAPE_CAPSULE:
			s->capsule.p1 = FuzzVec2(r);
			s->capsule.p2 = FuzzVec2(r);
			s->capsule.radius = FuzzClampSize(FuzzRawReal(r));
			break;
		case CD2_SHAPE_AABB:
		{
			cd2Vec p = FuzzVec2(r), q = FuzzVec2(r);
			s->aabb.min = cd2Min(p, q);
			s->aabb.max = cd2Max(p, q);
			break;
		}
		case CD2_SHAPE_BOX:
		{
			s->box.center = FuzzVec2(r);
			s->box.halfExtents = cd2Abs(FuzzVec2(r));
			cd2Rot q = {FuzzClampReal(FuzzRawReal(r)), FuzzClampReal(FuzzRawReal(r))};
			s->box.rotation = cd2NormalizeRot(q);
			break;
		}
		case CD2_SHAPE_POLYGON:
		{
			uint8_t head = FuzzByte(r);
			int count = 3 + head % 6;
			cd2Vec points[CD2_MAX_POLYGON_VERTICES];
			for (int i = 0; i < count; ++i)
			{
				points[i] = FuzzVec2(r);
			}
			cdReal radius = (head & 0x40) ? FuzzClampSize(FuzzRawReal(r)) : CD_R(0.0);
			if (cd2MakeRoundedPolygon(points, count, radius, &s->polygon) != CD_OK)
			{
				return false;
			}
			s->type = CD2_SHAPE_POLYGON;
			break;
		}
		default:
			s->type = CD2_SHAPE_SEGMENT;
			s->segment.p1 = FuzzVec2(r);
			s->segment.p2 = FuzzVec2(r);
			break;
	}
	return cd2ValidateShape(s) == CD_OK;
}

static inline double FuzzVec2MaxAbs(double m, cd2Vec v)
{
	return FuzzMaxAbs(FuzzMaxAbs(m, v.x), v.y);
}

static inline bool FuzzFiniteVec2(cd2Vec v)
{
	return FuzzFinite(v.x) && FuzzFinite(v.y);
}

static inline double FuzzDistance2(cd2Vec a, cd2Vec b)
{
	double dx = (double)b.x - (double)a.x, dy = (double)b.y - (double)a.y;
	return sqrt(dx * dx + dy * dy);
}

static inline double FuzzShapeScale2(const cd2Shape* s)
{
	switch (s->type)
	{
		case CD2_SHAPE_CIRCLE:
			return FuzzMaxAbs(FuzzVec2MaxAbs(0.0, s->circle.center), s->circle.radius);
		case CD2_SHAPE_CAPSULE:
			return FuzzMaxAbs(FuzzVec2MaxAbs(FuzzVec2MaxAbs(0.0, s->capsule.p1), s->capsule.p2),
							  s->capsule.radius);
		case CD2_SHAPE_AABB:
			return FuzzVec2MaxAbs(FuzzVec2MaxAbs(0.0, s->aabb.min), s->aabb.max);
		case CD2_SHAPE_BOX:
			return FuzzVec2MaxAbs(0.0, s->box.center) + 2.0 * FuzzVec2MaxAbs(0.0, s->box.halfExtents);
		case CD2_SHAPE_POLYGON:
		{
			double m = fabs((double)s->polygon.radius);
			for (int i = 0; i < s->polygon.count; ++i)
			{
				m = FuzzVec2MaxAbs(m, s->polygon.vertices[i]);
			}
			return m;
		}
		default:
			return FuzzVec2MaxAbs(FuzzVec2MaxAbs(0.0, s->segment.p1), s->segment.p2);
	}
}

static inline void FuzzPrintShape2(const char* label, const cd2Shape* s)
{
	if (s->type == CD2_SHAPE_POLYGON)
	{
		fprintf(stderr, "  %s polygon of %d vertices, radius %.9g:", label, s->polygon.count,
				(double)s->polygon.radius);
		FuzzPrintReals("", "(x y ...)", &s->polygon.vertices[0].x, 2 * s->polygon.count);
		return;
	}
	static const int counts[CD2_SHAPE_TYPE_COUNT] = {3, 5, 4, 6, 0, 4};
	FuzzPrintReals(label, cd2GetShapeTypeName(s->type), &s->circle.center.x, counts[s->type]);
}

/* The shape moved by x -> q x + p. AABBs, which cannot turn, only when q is the identity. */
static inline cd2Shape FuzzTransformShape2(const cd2Shape* shape, cd2Transform t)
{
	cd2Shape s = *shape;
	switch (s.type)
	{
		case CD2_SHAPE_CIRCLE:
			s.circle.center = cd2TransformPoint(t, s.circle.center);
			break;
		case CD2_SHAPE_CAPSULE:
			s.capsule.p1 = cd2TransformPoint(t, s.capsule.p1);
			s.capsule.p2 = cd2TransformPoint(t, s.capsule.p2);
			break;
		case CD2_SHAPE_AABB:
			s.aabb.min = cd2Add(s.aabb.min, t.p);
			s.aabb.max = cd2Add(s.aabb.max, t.p);
			break;
		case CD2_SHAPE_BOX:
			s.box.center = cd2TransformPoint(t, s.box.center);
			s.box.rotation = cd2NormalizeRot(cd2MulRot(t.q, s.box.rotation));
			break;
		case CD2_SHAPE_POLYGON:
			for (int i = 0; i < s.polygon.count; ++i)
			{
				s.polygon.vertices[i] = cd2TransformPoint(t, s.polygon.vertices[i]);
				s.polygon.normals[i] = cd2RotateVector(t.q, s.polygon.normals[i]);
			}
			s.polygon.centroid = cd2TransformPoint(t, s.polygon.centroid);
			break;
		default:
			s.segment.p1 = cd2TransformPoint(t, s.segment.p1);
			s.segment.p2 = cd2TransformPoint(t, s.segment.p2);
			break;
	}
	return s;
}

static inline cd2Shape FuzzTranslateShape2(const cd2Shape* shape, cd2Vec d)
{
	cd2Transform t = {d, {CD_R(1.0), CD_R(0.0)}};
	return FuzzTransformShape2(shape, t);
}

static inline cd2Vec FuzzDirection2(int i)
{
	if (i < 4)
	{
		cdReal sign = (i & 1) ? CD_R(-1.0) : CD_R(1.0);
		return cd2MakeVec(i < 2 ? sign : CD_R(0.0), i < 2 ? CD_R(0.0) : sign);
	}
	cdReal c = CD_R(0.70710678118654752);
	return cd2MakeVec((i & 1) ? -c : c, (i & 2) ? -c : c);
}

static inline bool FuzzDeeplyOverlapping2(const cd2Shape* a, const cd2Shape* b, double band)
{
	for (int i = 0; i < 8; ++i)
	{
		cd2Shape moved = FuzzTranslateShape2(b, cd2Scale((cdReal)band, FuzzDirection2(i)));
		if (cd2Distance(a, &moved).distance != CD_R(0.0))
		{
			return false;
		}
	}
	return true;
}

#endif
