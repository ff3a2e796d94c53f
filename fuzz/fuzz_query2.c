/* libFuzzer target for the 2D queries, the twin of fuzz_query3.c. The input decodes into two
 * shapes of any type (polygons through cd2MakeRoundedPolygon from 3 to 8 decoded points, half of
 * them with a rounding radius), a point and a ray. The validators see the raw shapes (NaN, infinities,
 * negative sizes, polygons with any count and unchecked vertices) and must agree with each other; the queries
 * see the copies clamped into the documented range that the validator accepts.
 *
 * Checked, with aborts on violation: overlap symmetric; distance finite, non-negative, symmetric,
 * equal to |pointB - pointA|, witnesses on their shapes, pointA == pointB at distance 0; overlap
 * agrees with distance == 0 away from the boundary (FUZZ_BAND); closest point and point
 * containment consistent with each other and with the distance to a point; ray hits in range,
 * finite, on the ray and on the surface, unit or zero normal, *hit untouched on a miss, rays from
 * clearly inside a solid hit at fraction 0; the segment/segment closest points agree with the
 * generic distance. Every failure names its check; FUZZ_SKIP=check,... passes over known ones. */
#include "fuzz_common.h"

static struct
{
	cd2Shape a, b;
	cd2Vec point;
	cd2Ray ray;
} s_case;

static int RealCount(cd2ShapeType type)
{
	static const int counts[CD2_SHAPE_TYPE_COUNT] = {3, 5, 4, 6, 0, 4};
	return (unsigned)type < (unsigned)CD2_SHAPE_TYPE_COUNT ? counts[type] : 0;
}

static void PrintShape(const char* label, const cd2Shape* s)
{
	if (s->type == CD2_SHAPE_POLYGON)
	{
		int count = s->polygon.count;
		fprintf(stderr, "  %s polygon of %d vertices, radius %.9g (x y ...):", label, count,
				(double)s->polygon.radius);
		count = count < 0 ? 0 : (count > CD2_MAX_POLYGON_VERTICES ? CD2_MAX_POLYGON_VERTICES : count);
		FuzzPrintReals("", "", &s->polygon.vertices[0].x, 2 * count);
		return;
	}
	FuzzPrintReals(label, cd2GetShapeTypeName(s->type), (const cdReal*)&s->circle, RealCount(s->type));
}

/* Reports a failed check (named, so that FUZZ_SKIP can pass over it) and aborts. */
static void Fail(const char* check, const char* format, ...)
{
	if (FuzzSkipped(check))
	{
		return;
	}
	va_list args;
	va_start(args, format);
	fprintf(stderr, "fuzz_query2: [%s] ", check);
	vfprintf(stderr, format, args);
	fprintf(stderr, "\n");
	va_end(args);
	PrintShape("a", &s_case.a);
	PrintShape("b", &s_case.b);
	FuzzPrintReals("point", "", &s_case.point.x, 2);
	FuzzPrintReals("ray", "origin, translation", &s_case.ray.origin.x, 4);
	FuzzFail("see above");
}

/* ---- decoding -------------------------------------------------------------------------------- */

static cd2Vec RawVec(FuzzReader* r)
{
	cdReal x = FuzzRawReal(r), y = FuzzRawReal(r);
	return cd2MakeVec(x, y);
}

static cd2Vec ClampVec(cd2Vec v)
{
	return cd2MakeVec(FuzzClampReal(v.x), FuzzClampReal(v.y));
}

/* Reads one shape as written (raw) and its usable copy (clean). A polygon whose points
 * cd2MakePolygon rejects gets count 0, which the validator rejects. */
static void DecodeShape(FuzzReader* r, cd2Shape* raw, cd2Shape* clean)
{
	memset(raw, 0, sizeof *raw);
	raw->type = (cd2ShapeType)(FuzzByte(r) % CD2_SHAPE_TYPE_COUNT);
	if (raw->type == CD2_SHAPE_POLYGON)
	{
		uint8_t head = FuzzByte(r);
		int count = 3 + head % 6;
		cd2Vec points[CD2_MAX_POLYGON_VERTICES];
		for (int i = 0; i < count; ++i)
		{
			raw->polygon.vertices[i] = RawVec(r);
			points[i] = ClampVec(raw->polygon.vertices[i]);
		}
		/* The raw polygon: the points as given, naive edge normals, and a count that may be out
		 * of range, for the validator. */
		for (int i = 0; i < count; ++i)
		{
			cd2Vec edge = cd2Sub(raw->polygon.vertices[(i + 1) % count], raw->polygon.vertices[i]);
			raw->polygon.normals[i] = cd2Normalize(cd2RightPerp(edge));
		}
		raw->polygon.count = (head & 0x80) ? (int)(head >> 3 & 15) - 2 : count;
		/* Every other polygon is rounded. */
		raw->polygon.radius = (head & 0x40) ? FuzzRawReal(r) : CD_R(0.0);
		memset(clean, 0, sizeof *clean);
		clean->type = CD2_SHAPE_POLYGON;
		if (cd2MakeRoundedPolygon(points, count, FuzzClampSize(raw->polygon.radius), &clean->polygon) !=
			CD_OK)
		{
			clean->polygon.count = 0;
		}
		return;
	}
	cdReal* values = (cdReal*)&raw->circle;
	for (int i = 0; i < RealCount(raw->type); ++i)
	{
		values[i] = FuzzRawReal(r);
	}
	*clean = *raw;
	switch (raw->type)
	{
		case CD2_SHAPE_CIRCLE:
			clean->circle.center = ClampVec(raw->circle.center);
			clean->circle.radius = FuzzClampSize(raw->circle.radius);
			break;
		case CD2_SHAPE_CAPSULE:
			clean->capsule.p1 = ClampVec(raw->capsule.p1);
			clean->capsule.p2 = ClampVec(raw->capsule.p2);
			clean->capsule.radius = FuzzClampSize(raw->capsule.radius);
			break;
		case CD2_SHAPE_AABB:
		{
			cd2Vec p = ClampVec(raw->aabb.min), q = ClampVec(raw->aabb.max);
			clean->aabb.min = cd2Min(p, q);
			clean->aabb.max = cd2Max(p, q);
			break;
		}
		case CD2_SHAPE_BOX:
		{
			cd2Rot q = {FuzzClampReal(raw->box.rotation.c), FuzzClampReal(raw->box.rotation.s)};
			clean->box.center = ClampVec(raw->box.center);
			clean->box.halfExtents =
				cd2MakeVec(FuzzClampSize(raw->box.halfExtents.x), FuzzClampSize(raw->box.halfExtents.y));
			clean->box.rotation = cd2NormalizeRot(q);
			break;
		}
		default:
			clean->segment.p1 = ClampVec(raw->segment.p1);
			clean->segment.p2 = ClampVec(raw->segment.p2);
			break;
	}
}

/* ---- helpers --------------------------------------------------------------------------------- */

static double VecMaxAbs(double m, cd2Vec v)
{
	return FuzzMaxAbs(FuzzMaxAbs(m, v.x), v.y);
}

static bool FiniteVec(cd2Vec v)
{
	return FuzzFinite(v.x) && FuzzFinite(v.y);
}

static double Distance(cd2Vec a, cd2Vec b)
{
	double dx = (double)b.x - (double)a.x, dy = (double)b.y - (double)a.y;
	return sqrt(dx * dx + dy * dy);
}

/* The largest magnitude of the shape's positions and sizes (the unit rotation aside). */
static double ShapeScale(const cd2Shape* s)
{
	switch (s->type)
	{
		case CD2_SHAPE_BOX:
			return VecMaxAbs(VecMaxAbs(0.0, s->box.center), s->box.halfExtents);
		case CD2_SHAPE_POLYGON:
		{
			double m = fabs((double)s->polygon.radius);
			for (int i = 0; i < s->polygon.count; ++i)
			{
				m = VecMaxAbs(m, s->polygon.vertices[i]);
			}
			return m;
		}
		default:
		{
			double m = 0.0;
			const cdReal* values = (const cdReal*)&s->circle;
			for (int i = 0; i < RealCount(s->type); ++i)
			{
				m = FuzzMaxAbs(m, values[i]);
			}
			return m;
		}
	}
}

static cd2Shape Translated(const cd2Shape* shape, cd2Vec d)
{
	cd2Shape s = *shape;
	switch (s.type)
	{
		case CD2_SHAPE_CIRCLE:
			s.circle.center = cd2Add(s.circle.center, d);
			break;
		case CD2_SHAPE_CAPSULE:
			s.capsule.p1 = cd2Add(s.capsule.p1, d);
			s.capsule.p2 = cd2Add(s.capsule.p2, d);
			break;
		case CD2_SHAPE_AABB:
			s.aabb.min = cd2Add(s.aabb.min, d);
			s.aabb.max = cd2Add(s.aabb.max, d);
			break;
		case CD2_SHAPE_BOX:
			s.box.center = cd2Add(s.box.center, d);
			break;
		case CD2_SHAPE_POLYGON:
			for (int i = 0; i < s.polygon.count; ++i)
			{
				s.polygon.vertices[i] = cd2Add(s.polygon.vertices[i], d);
			}
			s.polygon.centroid = cd2Add(s.polygon.centroid, d);
			break;
		default:
			s.segment.p1 = cd2Add(s.segment.p1, d);
			s.segment.p2 = cd2Add(s.segment.p2, d);
			break;
	}
	return s;
}

/* 8 unit directions: the axes and the diagonals. */
static cd2Vec Direction(int i)
{
	if (i < 4)
	{
		cdReal sign = (i & 1) ? CD_R(-1.0) : CD_R(1.0);
		return cd2MakeVec(i < 2 ? sign : CD_R(0.0), i < 2 ? CD_R(0.0) : sign);
	}
	cdReal c = CD_R(0.70710678118654752);
	return cd2MakeVec((i & 1) ? -c : c, (i & 2) ? -c : c);
}

/* The pair still overlaps (distance exactly 0) after b moves by `band` in any of 8 directions:
 * a penetration of about band / sqrt(2) at least, far beyond round-off. */
static bool DeeplyOverlapping(const cd2Shape* a, const cd2Shape* b, double band)
{
	for (int i = 0; i < 8; ++i)
	{
		cd2Shape moved = Translated(b, cd2Scale((cdReal)band, Direction(i)));
		if (cd2Distance(a, &moved).distance != CD_R(0.0))
		{
			return false;
		}
	}
	return true;
}

/* p and its 4 neighbours at distance `band` along the axes are all inside the solid shape. */
static bool ClearlyInside(const cd2Shape* s, cd2Vec p, double band)
{
	if (s->type == CD2_SHAPE_SEGMENT || !cd2PointInShape(s, p))
	{
		return false;
	}
	for (int i = 0; i < 4; ++i)
	{
		if (!cd2PointInShape(s, cd2Add(p, cd2Scale((cdReal)band, Direction(i)))))
		{
			return false;
		}
	}
	return true;
}

/* ---- checks ---------------------------------------------------------------------------------- */

static bool HasNonFinite(const cd2Shape* s)
{
	if (s->type == CD2_SHAPE_POLYGON)
	{
		int count = s->polygon.count < 0 ? 0 : cdMinInt(s->polygon.count, CD2_MAX_POLYGON_VERTICES);
		bool finite = FiniteVec(s->polygon.centroid) && FuzzFinite(s->polygon.radius);
		for (int i = 0; i < count; ++i)
		{
			finite = finite && FiniteVec(s->polygon.vertices[i]) && FiniteVec(s->polygon.normals[i]);
		}
		return !finite;
	}
	const cdReal* values = (const cdReal*)&s->circle;
	for (int i = 0; i < RealCount(s->type); ++i)
	{
		if (!FuzzFinite(values[i]))
		{
			return true;
		}
	}
	return false;
}

static void CheckValidators(const cd2Shape* s, const char* label)
{
	cdResult result = cd2ValidateShape(s);
	bool valid = cd2IsValidShape(s);
	if ((unsigned)result >= (unsigned)CD_RESULT_COUNT || valid != (result == CD_OK))
	{
		Fail("validators", "%s: cd2ValidateShape = %d but cd2IsValidShape = %d", label, (int)result,
			 (int)valid);
	}
	bool typed;
	switch (s->type)
	{
		case CD2_SHAPE_CIRCLE:
			typed = cd2IsValidCircle(s->circle);
			break;
		case CD2_SHAPE_CAPSULE:
			typed = cd2IsValidCapsule(s->capsule);
			break;
		case CD2_SHAPE_AABB:
			typed = cd2IsValidAabb(s->aabb);
			break;
		case CD2_SHAPE_BOX:
			typed = cd2IsValidBox(s->box);
			break;
		case CD2_SHAPE_POLYGON:
			typed = cd2IsValidPolygon(&s->polygon);
			break;
		default:
			typed = cd2IsValidSegment(s->segment);
			break;
	}
	if (typed != valid)
	{
		Fail("validators", "%s: the %s validator says %d, cd2IsValidShape %d", label,
			 cd2GetShapeTypeName(s->type), (int)typed, (int)valid);
	}
	if (valid && HasNonFinite(s))
	{
		Fail("validators", "%s: a shape with NaN or infinity passes the validator", label);
	}
	if (valid && s->type == CD2_SHAPE_POLYGON &&
		(s->polygon.count < 3 || s->polygon.count > CD2_MAX_POLYGON_VERTICES))
	{
		Fail("validators", "%s: a polygon of %d vertices passes the validator", label, s->polygon.count);
	}
	if (valid && ((s->type == CD2_SHAPE_CIRCLE && s->circle.radius < CD_R(0.0)) ||
				  (s->type == CD2_SHAPE_CAPSULE && s->capsule.radius < CD_R(0.0)) ||
				  (s->type == CD2_SHAPE_POLYGON && s->polygon.radius < CD_R(0.0))))
	{
		Fail("validators", "%s: a negative radius passes the validator", label);
	}
}

static void CheckClosestPoints(cd2ClosestPoints r, const cd2Shape* a, const cd2Shape* b, double scale,
							   const char* what)
{
	if (!FuzzFinite(r.distance) || !FiniteVec(r.pointA) || !FiniteVec(r.pointB) || r.distance < CD_R(0.0))
	{
		Fail("closest-finite", "%s: distance %.9g, pointA (%.9g %.9g), pointB (%.9g %.9g)", what,
			 (double)r.distance, (double)r.pointA.x, (double)r.pointA.y, (double)r.pointB.x,
			 (double)r.pointB.y);
	}
	double tol = FUZZ_TOL * VecMaxAbs(VecMaxAbs(scale, r.pointA), r.pointB);
	double gap = Distance(r.pointA, r.pointB);
	if (fabs(gap - (double)r.distance) > tol)
	{
		Fail("closest-gap", "%s: distance %.9g but |pointB - pointA| = %.9g", what, (double)r.distance, gap);
	}
	/* Gaps whose square underflows (below sqrt of the smallest normal cdReal) read as 0. */
	if (r.distance == CD_R(0.0) && !cd2VecEqual(r.pointA, r.pointB) && gap > FUZZ_UNDERFLOW_GAP)
	{
		Fail("closest-same-point", "%s: distance 0 with different points (%.3g apart)", what, gap);
	}
	double offA = Distance(cd2ClosestPointOnShape(a, r.pointA), r.pointA);
	double offB = Distance(cd2ClosestPointOnShape(b, r.pointB), r.pointB);
	if (offA > tol || offB > tol)
	{
		Fail("closest-witness",
			 "%s: witnesses off their shapes: pointA by %.3g, pointB by %.3g (tolerance %.3g)", what, offA,
			 offB, tol);
	}
}

static void CheckPair(const cd2Shape* a, const cd2Shape* b)
{
	bool ab = cd2Overlap(a, b), ba = cd2Overlap(b, a);
	if (ab != ba)
	{
		Fail("overlap-symmetry", "overlap(a, b) = %d but overlap(b, a) = %d", (int)ab, (int)ba);
	}
	double scale = fmax(ShapeScale(a), ShapeScale(b));
	cd2ClosestPoints dab = cd2Distance(a, b), dba = cd2Distance(b, a);
	CheckClosestPoints(dab, a, b, scale, "distance(a, b)");
	CheckClosestPoints(dba, b, a, scale, "distance(b, a)");
	if (fabs((double)dab.distance - (double)dba.distance) > FUZZ_TOL * scale)
	{
		Fail("distance-symmetry", "distance(a, b) = %.9g but distance(b, a) = %.9g", (double)dab.distance,
			 (double)dba.distance);
	}
	double band = FUZZ_BAND * scale;
	if (ab && (double)dab.distance > band)
	{
		Fail("overlap-distance", "overlap says true but the distance is %.9g (band %.3g)",
			 (double)dab.distance, band);
	}
	if (!ab && dab.distance == CD_R(0.0) && DeeplyOverlapping(a, b, band))
	{
		Fail("overlap-distance", "overlap says false but the shapes overlap by more than %.3g", band);
	}
	if (a->type == CD2_SHAPE_SEGMENT && b->type == CD2_SHAPE_SEGMENT)
	{
		cd2ClosestPoints r = cd2ClosestPointsSegmentSegment(a->segment, b->segment);
		CheckClosestPoints(r, a, b, scale, "cd2ClosestPointsSegmentSegment");
		if (fabs((double)r.distance - (double)dab.distance) > FUZZ_TOL * scale)
		{
			Fail("closest-dedicated", "cd2ClosestPointsSegmentSegment distance %.9g, cd2Distance %.9g",
				 (double)r.distance, (double)dab.distance);
		}
	}
}

static void CheckPoint(const cd2Shape* s, cd2Vec p)
{
	cd2Vec closest = cd2ClosestPointOnShape(s, p);
	if (!FiniteVec(closest))
	{
		Fail("point-finite", "closest point on %s not finite", cd2GetShapeTypeName(s->type));
	}
	double scale = VecMaxAbs(ShapeScale(s), p);
	double tol = FUZZ_TOL * scale;
	double away = Distance(closest, p);
	if (cd2PointInShape(s, p) && away > tol)
	{
		Fail("point-inside", "point in %s, but its closest point is %.9g away", cd2GetShapeTypeName(s->type),
			 away);
	}
	cd2Shape point = cd2MakeCircleShape((cd2Circle){p, CD_R(0.0)});
	cd2ClosestPoints r = cd2Distance(s, &point);
	CheckClosestPoints(r, s, &point, scale, "distance(shape, point)");
	if (fabs((double)r.distance - away) > tol)
	{
		Fail("point-distance", "%s: closest point %.9g away, distance to the point %.9g",
			 cd2GetShapeTypeName(s->type), away, (double)r.distance);
	}
	cd2Aabb bounds = cd2ComputeShapeAabb(s);
	if (!FiniteVec(bounds.min) || !FiniteVec(bounds.max) ||
		!cd2PointInAabb(closest, cd2AabbInflate(bounds, (cdReal)tol)))
	{
		Fail("point-bounds", "%s: closest point outside the bounds", cd2GetShapeTypeName(s->type));
	}
}

static void CheckRay(const cd2Shape* s, cd2Ray ray)
{
	cd2RayHit hit, before;
	memset(&hit, 0x5a, sizeof hit);
	before = hit;
	bool got = cd2Raycast(s, ray, &hit);
	cd2Vec end = cd2Add(ray.origin, ray.translation);
	double scale = VecMaxAbs(VecMaxAbs(ShapeScale(s), ray.origin), end);
	double band = FUZZ_BAND * scale;
	const char* name = cd2GetShapeTypeName(s->type);
	if (!got)
	{
		if (memcmp(&hit, &before, sizeof hit) != 0)
		{
			Fail("ray-miss", "%s ray cast: *hit changed on a miss", name);
		}
		if (ClearlyInside(s, ray.origin, band) || ClearlyInside(s, end, band))
		{
			Fail("ray-miss", "%s ray cast: a miss, but the ray starts or ends clearly inside", name);
		}
		return;
	}
	if (!(hit.fraction >= CD_R(0.0) && hit.fraction <= CD_R(1.0)) || !FiniteVec(hit.point) ||
		!FiniteVec(hit.normal))
	{
		Fail("ray-finite", "%s ray cast: fraction %.9g, point (%.9g %.9g), normal (%.9g %.9g)", name,
			 (double)hit.fraction, (double)hit.point.x, (double)hit.point.y, (double)hit.normal.x,
			 (double)hit.normal.y);
	}
	double length = Distance(CD2_VEC_ZERO, hit.normal);
	if (length != 0.0 && fabs(length - 1.0) > FUZZ_UNIT_TOL)
	{
		Fail("ray-normal", "%s ray cast: normal of length %.9g", name, length);
	}
	double t = (double)hit.fraction;
	double ex = (double)ray.origin.x + t * (double)ray.translation.x;
	double ey = (double)ray.origin.y + t * (double)ray.translation.y;
	double offRay = sqrt((ex - (double)hit.point.x) * (ex - (double)hit.point.x) +
						 (ey - (double)hit.point.y) * (ey - (double)hit.point.y));
	if (offRay > FUZZ_TOL * scale)
	{
		Fail("ray-on-ray", "%s ray cast: the hit point is %.9g off the ray", name, offRay);
	}
	double offShape = Distance(cd2ClosestPointOnShape(s, hit.point), hit.point);
	if (offShape > band)
	{
		Fail("ray-on-surface", "%s ray cast: the hit point is %.9g off the shape (band %.3g)", name, offShape,
			 band);
	}
	if (ClearlyInside(s, ray.origin, band))
	{
		cd2Vec expected = cd2Scale(CD_R(-1.0), cd2Normalize(ray.translation));
		if (hit.fraction != CD_R(0.0) || Distance(hit.normal, expected) > 4.0 * FUZZ_UNIT_TOL)
		{
			Fail("ray-inside", "%s ray cast from inside: fraction %.9g, normal (%.9g %.9g)", name,
				 (double)hit.fraction, (double)hit.normal.x, (double)hit.normal.y);
		}
	}
}

static bool Usable(const cd2Shape* s)
{
	return cd2ValidateShape(s) == CD_OK;
}

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	FuzzReader r = FuzzBegin(data, size);
	cd2Shape rawA, rawB;
	DecodeShape(&r, &rawA, &s_case.a);
	DecodeShape(&r, &rawB, &s_case.b);
	cd2Vec rawPoint = RawVec(&r);
	cd2Ray rawRay = {RawVec(&r), RawVec(&r)};
	s_case.point = ClampVec(rawPoint);
	s_case.ray.origin = ClampVec(rawRay.origin);
	s_case.ray.translation = ClampVec(rawRay.translation);
	/* Keep the ray's end in the range too. */
	cdReal* origin = &s_case.ray.origin.x;
	cdReal* translation = &s_case.ray.translation.x;
	for (int i = 0; i < 2; ++i)
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
	if (cd2IsValidRay(rawRay) && !(FiniteVec(rawRay.origin) && FiniteVec(rawRay.translation)))
	{
		Fail("validators", "a ray with NaN or infinity passes the validator");
	}
	if (!cd2IsValidRay(s_case.ray))
	{
		Fail("validators", "a finite ray fails the validator");
	}

	const cd2Shape* shapes[2] = {&s_case.a, &s_case.b};
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
	return 0;
}
