/* libFuzzer target for the 3D queries. The input decodes into two shapes of any type (hulls
 * through cd3ComputeHull from 4 to 12 decoded points, placed by a decoded transform), a point
 * and a ray (fuzz_common.h). The validators see the raw shapes (NaN, infinities, negative sizes and
 * all) and must agree with each other; the queries see the copies clamped into the documented
 * range (sizes made non-negative, quaternions and normals normalized) that the validator accepts,
 * plus zero-area triangles, which the validator rejects but the queries must still handle.
 *
 * Checked, with aborts on violation: overlap symmetric; distance finite, non-negative, symmetric,
 * equal to |pointB - pointA|, witnesses on their shapes, pointA == pointB at distance 0; overlap
 * agrees with distance == 0 away from the boundary (FUZZ_BAND); closest point and point
 * containment consistent with each other and with the distance to a point; ray hits in range,
 * finite, on the ray and on the surface, unit or zero normal, *hit untouched on a miss, rays from
 * clearly inside a solid hit at fraction 0; the segment/segment and triangle/segment closest
 * points agree with the generic distance. */
#include "fuzz_common.h"
#include "fuzz_decode.h"

/* Open findings (fuzz/crashes/README.md, FuzzPassOver): the checks this target's CI run still
 * fails on; FUZZ_STRICT=1 checks them. Empty: the CI runs (seed 1, 100000 inputs) pass with
 * FUZZ_STRICT=1 in the float and the double build. */
#define OPEN_FINDINGS ""

static struct
{
	cd3Shape a, b;
	cd3Vec point;
	cd3Ray ray;
} s_case;

/* Hulls of the two shapes (built per input from 4 to 12 decoded points, freed at its end). */
enum
{
	FUZZ_MAX_HULL_POINTS = 12
};
static struct
{
	cd3Hull* hull;
	cd3Vec points[FUZZ_MAX_HULL_POINTS];
	int count;
} s_hulls[2];

/* The reals of a shape, in memory order: for a hull, those of its transform (p, then q). */
static int RealCount(cd3ShapeType type)
{
	static const int counts[] = {4, 7, 6, 10, 9, 4, 6, 7};
	_Static_assert(sizeof counts / sizeof counts[0] == CD3_SHAPE_TYPE_COUNT, "one count per shape type");
	return (unsigned)type < (unsigned)CD3_SHAPE_TYPE_COUNT ? counts[type] : 0;
}

static const cdReal* Reals(const cd3Shape* s)
{
	return s->type == CD3_SHAPE_HULL ? &s->hull.transform.p.x : &s->sphere.center.x;
}

static void PrintShape(const char* label, const cd3Shape* s)
{
	FuzzPrintReals(label, cd3GetShapeTypeName(s->type), Reals(s), RealCount(s->type));
	for (int i = 0; i < 2 && s->type == CD3_SHAPE_HULL; ++i)
	{
		if (s->hull.hull != NULL && s->hull.hull == s_hulls[i].hull)
		{
			FuzzPrintReals("  hull of the points", "(x y z ...)", &s_hulls[i].points[0].x,
						   3 * s_hulls[i].count);
		}
	}
}

/* Reports a failed check (named, so that FUZZ_SKIP can pass over it) and aborts. */
static void Fail(const char* check, const char* format, ...)
{
	if (FuzzPassOver("fuzz_query3", OPEN_FINDINGS, check))
	{
		return;
	}
	va_list args;
	va_start(args, format);
	fprintf(stderr, "fuzz_query3: [%s] ", check);
	vfprintf(stderr, format, args);
	fprintf(stderr, "\n");
	va_end(args);
	PrintShape("a", &s_case.a);
	PrintShape("b", &s_case.b);
	FuzzPrintReals("point", "", &s_case.point.x, 3);
	FuzzPrintReals("ray", "origin, translation", &s_case.ray.origin.x, 6);
	FuzzFail("see above");
}

/* ---- decoding -------------------------------------------------------------------------------- */

static cd3Vec RawVec(FuzzReader* r)
{
	cdReal x = FuzzRawReal(r), y = FuzzRawReal(r), z = FuzzRawReal(r);
	return cd3MakeVec(x, y, z);
}

static cd3Vec ClampVec(cd3Vec v)
{
	return cd3MakeVec(FuzzClampReal(v.x), FuzzClampReal(v.y), FuzzClampReal(v.z));
}

static cd3Vec ClampSizes(cd3Vec v)
{
	return cd3MakeVec(FuzzClampSize(v.x), FuzzClampSize(v.y), FuzzClampSize(v.z));
}

/* The hull of 4 to 12 decoded points (clamped into the range), or NULL when cd3ComputeHull
 * refuses them. The raw points (NaN and all) go to cd3ComputeHull first, which must refuse any
 * non-finite one. */
static cd3Hull* DecodeHull(FuzzReader* r, int slot)
{
	int count = 4 + FuzzByte(r) % (FUZZ_MAX_HULL_POINTS - 3);
	cd3Vec raw[FUZZ_MAX_HULL_POINTS];
	bool finite = true;
	for (int i = 0; i < count; ++i)
	{
		cdReal x = FuzzRawReal(r), y = FuzzRawReal(r), z = FuzzRawReal(r);
		raw[i] = cd3MakeVec(x, y, z);
		finite = finite && cd3IsValidVec(raw[i]);
		s_hulls[slot].points[i] = cd3MakeVec(FuzzClampReal(x), FuzzClampReal(y), FuzzClampReal(z));
	}
	s_hulls[slot].count = count;
	cd3Hull* hull = NULL;
	cdResult result = cd3ComputeHull(raw, count, &hull);
	if ((result == CD_OK) != (hull != NULL) || (result == CD_OK && !finite))
	{
		Fail("validators", "cd3ComputeHull on raw points: %s, hull %p", cdGetResultString(result),
			 (const void*)hull);
	}
	cd3DestroyHull(hull);
	hull = NULL;
	result = cd3ComputeHull(s_hulls[slot].points, count, &hull);
	if ((result == CD_OK) != (hull != NULL) || (result == CD_OK && cd3ValidateHull(hull) != CD_OK))
	{
		Fail("validators", "cd3ComputeHull: %s, but the hull is %s", cdGetResultString(result),
			 hull == NULL ? "NULL" : "invalid");
	}
	s_hulls[slot].hull = hull;
	return hull;
}

/* Reads one shape as written (raw) and its usable copy (clean). */
static void DecodeShape(FuzzReader* r, int slot, cd3Shape* raw, cd3Shape* clean)
{
	memset(raw, 0, sizeof *raw);
	raw->type = (cd3ShapeType)(FuzzByte(r) % CD3_SHAPE_TYPE_COUNT);
	cdReal* values = (cdReal*)Reals(raw);
	for (int i = 0; i < RealCount(raw->type); ++i)
	{
		values[i] = FuzzRawReal(r);
	}
	if (raw->type == CD3_SHAPE_HULL)
	{
		raw->hull.hull = DecodeHull(r, slot);
	}
	*clean = *raw;
	switch (raw->type)
	{
		case CD3_SHAPE_SPHERE:
			clean->sphere.center = ClampVec(raw->sphere.center);
			clean->sphere.radius = FuzzClampSize(raw->sphere.radius);
			break;
		case CD3_SHAPE_CAPSULE:
			clean->capsule.p1 = ClampVec(raw->capsule.p1);
			clean->capsule.p2 = ClampVec(raw->capsule.p2);
			clean->capsule.radius = FuzzClampSize(raw->capsule.radius);
			break;
		case CD3_SHAPE_AABB:
		{
			cd3Vec p = ClampVec(raw->aabb.min), q = ClampVec(raw->aabb.max);
			clean->aabb.min = cd3Min(p, q);
			clean->aabb.max = cd3Max(p, q);
			break;
		}
		case CD3_SHAPE_BOX:
		{
			cd3Quat q = raw->box.rotation;
			clean->box.center = ClampVec(raw->box.center);
			clean->box.halfExtents = ClampSizes(raw->box.halfExtents);
			clean->box.rotation = cd3NormalizeQuat(
				cd3MakeQuat(FuzzClampReal(q.x), FuzzClampReal(q.y), FuzzClampReal(q.z), FuzzClampReal(q.w)));
			break;
		}
		case CD3_SHAPE_TRIANGLE:
			clean->triangle.a = ClampVec(raw->triangle.a);
			clean->triangle.b = ClampVec(raw->triangle.b);
			clean->triangle.c = ClampVec(raw->triangle.c);
			break;
		case CD3_SHAPE_PLANE:
		{
			cd3Vec n = cd3Normalize(ClampVec(raw->plane.normal));
			clean->plane.normal =
				cd3LengthSquared(n) > CD_R(0.0) ? n : cd3MakeVec(CD_R(0.0), CD_R(0.0), CD_R(1.0));
			clean->plane.offset = FuzzClampReal(raw->plane.offset);
			break;
		}
		case CD3_SHAPE_HULL:
		{
			cd3Quat q = raw->hull.transform.q;
			clean->hull.transform.p = ClampVec(raw->hull.transform.p);
			clean->hull.transform.q = cd3NormalizeQuat(
				cd3MakeQuat(FuzzClampReal(q.x), FuzzClampReal(q.y), FuzzClampReal(q.z), FuzzClampReal(q.w)));
			break;
		}
		default:
			clean->segment.p1 = ClampVec(raw->segment.p1);
			clean->segment.p2 = ClampVec(raw->segment.p2);
			break;
	}
}

/* ---- helpers --------------------------------------------------------------------------------- */

static double VecMaxAbs(double m, cd3Vec v)
{
	return FuzzMaxAbs(FuzzMaxAbs(FuzzMaxAbs(m, v.x), v.y), v.z);
}

static bool FiniteVec(cd3Vec v)
{
	return FuzzFinite(v.x) && FuzzFinite(v.y) && FuzzFinite(v.z);
}

static double Distance(cd3Vec a, cd3Vec b)
{
	double dx = (double)b.x - (double)a.x, dy = (double)b.y - (double)a.y, dz = (double)b.z - (double)a.z;
	return sqrt(dx * dx + dy * dy + dz * dz);
}

/* The largest magnitude of the shape's positions and sizes (unit quaternions and normals aside). */
static double ShapeScale(const cd3Shape* s)
{
	switch (s->type)
	{
		case CD3_SHAPE_BOX:
			return VecMaxAbs(VecMaxAbs(0.0, s->box.center), s->box.halfExtents);
		case CD3_SHAPE_PLANE:
			return fabs((double)s->plane.offset);
		case CD3_SHAPE_HULL:
		{
			/* Every vertex lies within |p| + the largest local coordinate (a rotation keeps lengths). */
			double local = s->hull.hull == NULL ? 0.0
												: VecMaxAbs(VecMaxAbs(0.0, s->hull.hull->bounds.min),
															s->hull.hull->bounds.max);
			return VecMaxAbs(0.0, s->hull.transform.p) + sqrt(3.0) * local;
		}
		default:
		{
			double m = 0.0;
			const cdReal* values = Reals(s);
			for (int i = 0; i < RealCount(s->type); ++i)
			{
				m = FuzzMaxAbs(m, values[i]);
			}
			return m;
		}
	}
}

static bool IsSolid(cd3ShapeType type)
{
	return type != CD3_SHAPE_TRIANGLE && type != CD3_SHAPE_SEGMENT;
}

static cd3Shape Translated(const cd3Shape* shape, cd3Vec d)
{
	cd3Shape s = *shape;
	switch (s.type)
	{
		case CD3_SHAPE_SPHERE:
			s.sphere.center = cd3Add(s.sphere.center, d);
			break;
		case CD3_SHAPE_CAPSULE:
			s.capsule.p1 = cd3Add(s.capsule.p1, d);
			s.capsule.p2 = cd3Add(s.capsule.p2, d);
			break;
		case CD3_SHAPE_AABB:
			s.aabb.min = cd3Add(s.aabb.min, d);
			s.aabb.max = cd3Add(s.aabb.max, d);
			break;
		case CD3_SHAPE_BOX:
			s.box.center = cd3Add(s.box.center, d);
			break;
		case CD3_SHAPE_TRIANGLE:
			s.triangle.a = cd3Add(s.triangle.a, d);
			s.triangle.b = cd3Add(s.triangle.b, d);
			s.triangle.c = cd3Add(s.triangle.c, d);
			break;
		case CD3_SHAPE_PLANE:
			s.plane.offset += cd3Dot(s.plane.normal, d);
			break;
		case CD3_SHAPE_HULL:
			s.hull.transform.p = cd3Add(s.hull.transform.p, d);
			break;
		default:
			s.segment.p1 = cd3Add(s.segment.p1, d);
			s.segment.p2 = cd3Add(s.segment.p2, d);
			break;
	}
	return s;
}

/* 14 unit directions: the axes and the cube diagonals. */
static cd3Vec Direction(int i)
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

/* The pair still overlaps (distance exactly 0) after b moves by `band` in any of 14 directions:
 * a penetration of about band / sqrt(3) at least, far beyond round-off. */
static bool DeeplyOverlapping(const cd3Shape* a, const cd3Shape* b, double band)
{
	for (int i = 0; i < 14; ++i)
	{
		cd3Shape moved = Translated(b, cd3Scale((cdReal)band, Direction(i)));
		if (cd3Distance(a, &moved).distance != CD_R(0.0))
		{
			return false;
		}
	}
	return true;
}

/* p and its 6 neighbours at distance `band` along the axes are all inside the solid shape. */
static bool ClearlyInside(const cd3Shape* s, cd3Vec p, double band)
{
	if (!IsSolid(s->type) || !cd3PointInShape(s, p))
	{
		return false;
	}
	for (int i = 0; i < 6; ++i)
	{
		if (!cd3PointInShape(s, cd3Add(p, cd3Scale((cdReal)band, Direction(i)))))
		{
			return false;
		}
	}
	return true;
}

/* ---- checks ---------------------------------------------------------------------------------- */

static void CheckValidators(const cd3Shape* s, const char* label)
{
	cdResult result = cd3ValidateShape(s);
	bool valid = cd3IsValidShape(s);
	if ((unsigned)result >= (unsigned)CD_RESULT_COUNT || valid != (result == CD_OK))
	{
		Fail("validators", "%s: cd3ValidateShape = %d but cd3IsValidShape = %d", label, (int)result,
			 (int)valid);
	}
	bool typed = false;
	switch (s->type)
	{
		case CD3_SHAPE_SPHERE:
			typed = cd3IsValidSphere(s->sphere);
			break;
		case CD3_SHAPE_CAPSULE:
			typed = cd3IsValidCapsule(s->capsule);
			break;
		case CD3_SHAPE_AABB:
			typed = cd3IsValidAabb(s->aabb);
			break;
		case CD3_SHAPE_BOX:
			typed = cd3IsValidBox(s->box);
			break;
		case CD3_SHAPE_TRIANGLE:
			typed = cd3IsValidTriangle(s->triangle);
			break;
		case CD3_SHAPE_PLANE:
			typed = cd3IsValidPlane(s->plane);
			break;
		case CD3_SHAPE_HULL:
			typed = cd3IsValidHullShape(s->hull);
			break;
		default:
			typed = cd3IsValidSegment(s->segment);
			break;
	}
	if (typed != valid)
	{
		Fail("validators", "%s: the %s validator says %d, cd3IsValidShape %d", label,
			 cd3GetShapeTypeName(s->type), (int)typed, (int)valid);
	}
	const cdReal* values = Reals(s);
	for (int i = 0; i < RealCount(s->type); ++i)
	{
		if (!FuzzFinite(values[i]) && valid)
		{
			Fail("validators", "%s: a shape with NaN or infinity passes the validator", label);
		}
	}
	if (s->type == CD3_SHAPE_SPHERE || s->type == CD3_SHAPE_CAPSULE)
	{
		cdReal radius = s->type == CD3_SHAPE_SPHERE ? s->sphere.radius : s->capsule.radius;
		if (radius < CD_R(0.0) && valid)
		{
			Fail("validators", "%s: a negative radius passes the validator", label);
		}
	}
}

/* Valid, or a zero-area triangle (rejected, but the queries must still take it). */
static bool Usable(const cd3Shape* s)
{
	cdResult result = cd3ValidateShape(s);
	return result == CD_OK || (s->type == CD3_SHAPE_TRIANGLE && result == CD_ERROR_DEGENERATE);
}

static void CheckClosestPoints(cd3ClosestPoints r, const cd3Shape* a, const cd3Shape* b, double scale,
							   const char* what)
{
	if (!FuzzFinite(r.distance) || !FiniteVec(r.pointA) || !FiniteVec(r.pointB) || r.distance < CD_R(0.0))
	{
		Fail("closest-finite", "%s: distance %.9g, pointA (%.9g %.9g %.9g), pointB (%.9g %.9g %.9g)", what,
			 (double)r.distance, (double)r.pointA.x, (double)r.pointA.y, (double)r.pointA.z,
			 (double)r.pointB.x, (double)r.pointB.y, (double)r.pointB.z);
	}
	/* Witnesses of half-spaces may lie farther out than either shape. */
	double tol = FUZZ_TOL * VecMaxAbs(VecMaxAbs(scale, r.pointA), r.pointB);
	double gap = Distance(r.pointA, r.pointB);
	if (fabs(gap - (double)r.distance) > tol)
	{
		Fail("closest-gap", "%s: distance %.9g but |pointB - pointA| = %.9g", what, (double)r.distance, gap);
	}
	/* Gaps whose square underflows (below sqrt of the smallest normal cdReal) read as 0. */
	if (r.distance == CD_R(0.0) && !cd3VecEqual(r.pointA, r.pointB) && gap > FUZZ_UNDERFLOW_GAP)
	{
		Fail("closest-same-point", "%s: distance 0 with different points (%.3g apart)", what, gap);
	}
	double offA = Distance(cd3ClosestPointOnShape(a, r.pointA), r.pointA);
	double offB = Distance(cd3ClosestPointOnShape(b, r.pointB), r.pointB);
	if (offA > tol || offB > tol)
	{
		Fail("closest-witness",
			 "%s: witnesses off their shapes: pointA by %.3g, pointB by %.3g (tolerance %.3g)", what, offA,
			 offB, tol);
	}
}

static void CheckPair(const cd3Shape* a, const cd3Shape* b)
{
	bool ab = cd3Overlap(a, b), ba = cd3Overlap(b, a);
	if (ab != ba)
	{
		Fail("overlap-symmetry", "overlap(a, b) = %d but overlap(b, a) = %d", (int)ab, (int)ba);
	}
	double scale = fmax(ShapeScale(a), ShapeScale(b));
	cd3ClosestPoints dab = cd3Distance(a, b), dba = cd3Distance(b, a);
	CheckClosestPoints(dab, a, b, scale, "distance(a, b)");
	CheckClosestPoints(dba, b, a, scale, "distance(b, a)");
	if (fabs((double)dab.distance - (double)dba.distance) > FUZZ_TOL * scale)
	{
		Fail("distance-symmetry", "distance(a, b) = %.9g but distance(b, a) = %.9g", (double)dab.distance,
			 (double)dba.distance);
	}
	double band = FUZZ_BAND * scale;
	/* Two half-spaces have their own check name: their tolerances live apart from the others. */
	const char* agreement = a->type == CD3_SHAPE_PLANE && b->type == CD3_SHAPE_PLANE
								? "overlap-distance-planes"
								: "overlap-distance";
	if (ab && (double)dab.distance > band)
	{
		Fail(agreement, "overlap says true but the distance is %.9g (band %.3g)", (double)dab.distance, band);
	}
	if (!ab && dab.distance == CD_R(0.0) && DeeplyOverlapping(a, b, band))
	{
		Fail(agreement, "overlap says false but the shapes overlap by more than %.3g", band);
	}

	/* The dedicated closest-point routines against the generic distance. */
	if (a->type == CD3_SHAPE_SEGMENT && b->type == CD3_SHAPE_SEGMENT)
	{
		cd3ClosestPoints r = cd3ClosestPointsSegmentSegment(a->segment, b->segment);
		CheckClosestPoints(r, a, b, scale, "cd3ClosestPointsSegmentSegment");
		if (fabs((double)r.distance - (double)dab.distance) > FUZZ_TOL * scale)
		{
			Fail("closest-dedicated", "cd3ClosestPointsSegmentSegment distance %.9g, cd3Distance %.9g",
				 (double)r.distance, (double)dab.distance);
		}
	}
	const cd3Shape* triangle = a->type == CD3_SHAPE_TRIANGLE ? a : (b->type == CD3_SHAPE_TRIANGLE ? b : NULL);
	const cd3Shape* segment = a->type == CD3_SHAPE_SEGMENT ? a : (b->type == CD3_SHAPE_SEGMENT ? b : NULL);
	if (triangle != NULL && segment != NULL)
	{
		cd3ClosestPoints r = cd3ClosestPointsTriangleSegment(triangle->triangle, segment->segment);
		CheckClosestPoints(r, triangle, segment, scale, "cd3ClosestPointsTriangleSegment");
		if (fabs((double)r.distance - (double)dab.distance) > FUZZ_TOL * scale)
		{
			Fail("closest-dedicated", "cd3ClosestPointsTriangleSegment distance %.9g, cd3Distance %.9g",
				 (double)r.distance, (double)dab.distance);
		}
	}
}

static void CheckPoint(const cd3Shape* s, cd3Vec p)
{
	cd3Vec closest = cd3ClosestPointOnShape(s, p);
	if (!FiniteVec(closest))
	{
		Fail("point-finite", "closest point on %s not finite", cd3GetShapeTypeName(s->type));
	}
	double scale = VecMaxAbs(ShapeScale(s), p);
	double tol = FUZZ_TOL * scale;
	double away = Distance(closest, p);
	if (cd3PointInShape(s, p) && away > tol)
	{
		Fail("point-inside", "point in %s, but its closest point is %.9g away", cd3GetShapeTypeName(s->type),
			 away);
	}
	cd3Shape point = cd3MakeSphereShape((cd3Sphere){p, CD_R(0.0)});
	cd3ClosestPoints r = cd3Distance(s, &point);
	CheckClosestPoints(r, s, &point, scale, "distance(shape, point)");
	if (fabs((double)r.distance - away) > tol)
	{
		Fail("point-distance", "%s: closest point %.9g away, distance to the point %.9g",
			 cd3GetShapeTypeName(s->type), away, (double)r.distance);
	}
	cd3Aabb bounds = cd3ComputeShapeAabb(s);
	if (!FiniteVec(bounds.min) || !FiniteVec(bounds.max) ||
		!cd3PointInAabb(closest, cd3AabbInflate(bounds, (cdReal)tol)))
	{
		Fail("point-bounds", "%s: closest point outside the bounds", cd3GetShapeTypeName(s->type));
	}
}

static void CheckRay(const cd3Shape* s, cd3Ray ray)
{
	cd3RayHit hit, before;
	memset(&hit, 0x5a, sizeof hit);
	before = hit;
	bool got = cd3Raycast(s, ray, &hit);
	cd3Vec end = cd3Add(ray.origin, ray.translation);
	double scale = VecMaxAbs(VecMaxAbs(ShapeScale(s), ray.origin), end);
	double band = FUZZ_BAND * scale;
	if (!got)
	{
		if (memcmp(&hit, &before, sizeof hit) != 0)
		{
			Fail("ray-miss", "%s ray cast: *hit changed on a miss", cd3GetShapeTypeName(s->type));
		}
		if (ClearlyInside(s, ray.origin, band) || ClearlyInside(s, end, band))
		{
			Fail("ray-miss", "%s ray cast: a miss, but the ray starts or ends clearly inside",
				 cd3GetShapeTypeName(s->type));
		}
		return;
	}
	if (!(hit.fraction >= CD_R(0.0) && hit.fraction <= CD_R(1.0)) || !FiniteVec(hit.point) ||
		!FiniteVec(hit.normal))
	{
		Fail("ray-finite", "%s ray cast: fraction %.9g, point (%.9g %.9g %.9g), normal (%.9g %.9g %.9g)",
			 cd3GetShapeTypeName(s->type), (double)hit.fraction, (double)hit.point.x, (double)hit.point.y,
			 (double)hit.point.z, (double)hit.normal.x, (double)hit.normal.y, (double)hit.normal.z);
	}
	double length = Distance(CD3_VEC_ZERO, hit.normal);
	if (length != 0.0 && fabs(length - 1.0) > FUZZ_UNIT_TOL)
	{
		Fail("ray-normal", "%s ray cast: normal of length %.9g", cd3GetShapeTypeName(s->type), length);
	}
	double t = (double)hit.fraction;
	double ex = (double)ray.origin.x + t * (double)ray.translation.x;
	double ey = (double)ray.origin.y + t * (double)ray.translation.y;
	double ez = (double)ray.origin.z + t * (double)ray.translation.z;
	double offRay = sqrt((ex - (double)hit.point.x) * (ex - (double)hit.point.x) +
						 (ey - (double)hit.point.y) * (ey - (double)hit.point.y) +
						 (ez - (double)hit.point.z) * (ez - (double)hit.point.z));
	if (offRay > FUZZ_TOL * scale)
	{
		Fail("ray-on-ray", "%s ray cast: the hit point is %.9g off the ray", cd3GetShapeTypeName(s->type),
			 offRay);
	}
	double offShape = Distance(cd3ClosestPointOnShape(s, hit.point), hit.point);
	if (offShape > band)
	{
		Fail("ray-on-surface", "%s ray cast: the hit point is %.9g off the shape (band %.3g)",
			 cd3GetShapeTypeName(s->type), offShape, band);
	}
	if (ClearlyInside(s, ray.origin, band))
	{
		cd3Vec expected = cd3Scale(CD_R(-1.0), cd3Normalize(ray.translation));
		if (hit.fraction != CD_R(0.0) || Distance(hit.normal, expected) > 4.0 * FUZZ_UNIT_TOL)
		{
			Fail("ray-inside", "%s ray cast from inside: fraction %.9g, normal (%.9g %.9g %.9g)",
				 cd3GetShapeTypeName(s->type), (double)hit.fraction, (double)hit.normal.x,
				 (double)hit.normal.y, (double)hit.normal.z);
		}
	}
}

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	FuzzReader r = FuzzBegin(data, size);
	cd3Shape rawA, rawB;
	DecodeShape(&r, 0, &rawA, &s_case.a);
	DecodeShape(&r, 1, &rawB, &s_case.b);
	cd3Vec rawPoint = RawVec(&r);
	cd3Ray rawRay = {RawVec(&r), RawVec(&r)};
	s_case.point = ClampVec(rawPoint);
	s_case.ray.origin = ClampVec(rawRay.origin);
	s_case.ray.translation = ClampVec(rawRay.translation);
	/* Keep the ray's end in the range too. */
	cdReal* origin = &s_case.ray.origin.x;
	cdReal* translation = &s_case.ray.translation.x;
	for (int i = 0; i < 3; ++i)
	{
		double end = (double)origin[i] + (double)translation[i];
		if (fabs(end) > FUZZ_MAX_MAGNITUDE)
		{
			translation[i] =
				(cdReal)((end < 0.0 ? -FUZZ_MAX_MAGNITUDE : FUZZ_MAX_MAGNITUDE) - (double)origin[i]);
		}
	}

	CheckValidators(&rawA, "raw a");
	CheckValidators(&rawB, "raw b");
	CheckValidators(&s_case.a, "a");
	CheckValidators(&s_case.b, "b");
	if (cd3IsValidRay(rawRay) && !(FiniteVec(rawRay.origin) && FiniteVec(rawRay.translation)))
	{
		Fail("validators", "a ray with NaN or infinity passes the validator");
	}
	if (!cd3IsValidRay(s_case.ray))
	{
		Fail("validators", "a finite ray fails the validator");
	}

	const cd3Shape* shapes[2] = {&s_case.a, &s_case.b};
	bool usable[2];
	for (int i = 0; i < 2; ++i)
	{
		usable[i] = Usable(shapes[i]);
		if (usable[i])
		{
			CheckPoint(shapes[i], s_case.point);
			CheckRay(shapes[i], s_case.ray);
		}
	}
	if (usable[0] && usable[1])
	{
		CheckPair(&s_case.a, &s_case.b);
	}
	for (int i = 0; i < 2; ++i)
	{
		cd3DestroyHull(s_hulls[i].hull);
		s_hulls[i].hull = NULL;
		s_hulls[i].count = 0;
	}
	return 0;
}
