/* libFuzzer target for the 2D polygon builders. cd2MakePolygon gets 0 to 16 points of any value
 * (lattice values, so that points weld and lie on lines, raw float bit patterns, NaN,
 * infinities, the ends of the range); cd2MakeBoxPolygon gets a raw box and its clamped copy.
 *
 * Checked, with aborts on violation: the result code is one of the documented ones (more than
 * CD2_MAX_POLYGON_VERTICES points: too many; a NaN or infinity: not finite; fewer than 3:
 * degenerate); on error *out is untouched; on success the polygon passes cd2IsValidPolygon, its
 * vertices are input points, and every input point lies in the polygon or within twice the weld
 * tolerance of it (one weld plus one dropped nearly collinear vertex), plus round-off; bounds
 * and centroid are finite; cd2MakeRoundedPolygon gives the same polygon plus a valid radius and
 * rejects an invalid one.
 * Every failure names its check; FUZZ_SKIP=check,... passes over known ones. */
#include "fuzz_common.h"

enum
{
	FUZZ_MAX_POINTS = 16
};

static cd2Vec s_points[FUZZ_MAX_POINTS];
static int s_count;

static void Fail(const char* check, const char* format, ...)
{
	if (FuzzSkipped(check))
	{
		return;
	}
	va_list args;
	va_start(args, format);
	fprintf(stderr, "fuzz_polygon2: [%s] ", check);
	vfprintf(stderr, format, args);
	fprintf(stderr, "\n");
	va_end(args);
	FuzzPrintReals("points", "(x y ...)", &s_points[0].x, 2 * s_count);
	FuzzFail("see above");
}

static bool FiniteVec(cd2Vec v)
{
	return FuzzFinite(v.x) && FuzzFinite(v.y);
}

/* Euclidean distance from p to the convex polygon (0 inside), in double from the vertices. */
static double DistanceToPolygon(const cd2Polygon* polygon, cd2Vec p)
{
	double px = (double)p.x, py = (double)p.y;
	bool inside = true;
	double best = INFINITY;
	for (int i = 0; i < polygon->count; ++i)
	{
		cd2Vec v1 = polygon->vertices[i];
		cd2Vec v2 = polygon->vertices[i + 1 < polygon->count ? i + 1 : 0];
		double ax = (double)v1.x, ay = (double)v1.y;
		double ex = (double)v2.x - ax, ey = (double)v2.y - ay;
		double dx = px - ax, dy = py - ay;
		if (ex * dy - ey * dx < 0.0)
		{
			inside = false; /* right of a counter-clockwise edge */
		}
		double lengthSquared = ex * ex + ey * ey;
		double t = lengthSquared > 0.0 ? (dx * ex + dy * ey) / lengthSquared : 0.0;
		t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
		double qx = dx - t * ex, qy = dy - t * ey;
		double d = sqrt(qx * qx + qy * qy);
		best = d < best ? d : best;
	}
	return inside ? 0.0 : best;
}

static void CheckMakePolygon(void)
{
	cd2Polygon out, before;
	memset(&out, 0xa5, sizeof out);
	before = out;
	cdResult result = cd2MakePolygon(s_points, s_count, &out);

	bool finite = true;
	double maxAbs = 0.0;
	for (int i = 0; i < s_count; ++i)
	{
		finite = finite && FiniteVec(s_points[i]);
		maxAbs = FuzzMaxAbs(FuzzMaxAbs(maxAbs, s_points[i].x), s_points[i].y);
	}
	if ((unsigned)result >= (unsigned)CD_RESULT_COUNT)
	{
		Fail("result", "unknown result code %d", (int)result);
	}
	if (s_count > CD2_MAX_POLYGON_VERTICES && result != CD_ERROR_TOO_MANY_POINTS)
	{
		Fail("result", "%d points gave %s, not too many points", s_count, cdGetResultString(result));
	}
	if (s_count <= CD2_MAX_POLYGON_VERTICES && !finite && result != CD_ERROR_NOT_FINITE)
	{
		Fail("result", "a NaN or infinity gave %s", cdGetResultString(result));
	}
	if (finite && s_count < 3 && result != CD_ERROR_DEGENERATE)
	{
		Fail("result", "%d points gave %s, not degenerate", s_count, cdGetResultString(result));
	}
	if (result != CD_OK)
	{
		if (memcmp(&out, &before, sizeof out) != 0)
		{
			Fail("untouched", "%s, but the output polygon changed", cdGetResultString(result));
		}
		return;
	}

	if (!cd2IsValidPolygon(&out) || out.count < 3 || out.count > CD2_MAX_POLYGON_VERTICES)
	{
		Fail("valid", "the polygon of %d vertices fails cd2IsValidPolygon", out.count);
	}
	for (int i = 0; i < out.count; ++i)
	{
		bool found = false;
		for (int j = 0; j < s_count && !found; ++j)
		{
			found = cd2VecEqual(out.vertices[i], s_points[j]);
		}
		if (!found)
		{
			Fail("vertices", "vertex %d (%.9g %.9g) is not an input point", i, (double)out.vertices[i].x,
				 (double)out.vertices[i].y);
		}
	}
	double tolerance =
		2.0 * (double)cd2GetPolygonWeldTolerance((cdReal)maxAbs) + 16.0 * (double)CD_REAL_EPSILON * maxAbs;
	for (int i = 0; i < s_count; ++i)
	{
		double d = DistanceToPolygon(&out, s_points[i]);
		if (d > tolerance)
		{
			Fail("contains", "input point %d (%.9g %.9g) is %.9g outside the polygon (tolerance %.3g)", i,
				 (double)s_points[i].x, (double)s_points[i].y, d, tolerance);
		}
	}
	cd2Aabb bounds = cd2ComputePolygonAabb(&out);
	if (!FiniteVec(bounds.min) || !FiniteVec(bounds.max) || !FiniteVec(out.centroid))
	{
		Fail("finite", "bounds or centroid (%.9g %.9g) not finite", (double)out.centroid.x,
			 (double)out.centroid.y);
	}
}

/* cd2MakeRoundedPolygon is cd2MakePolygon plus a radius: the same vertices when both succeed. */
static void CheckMakeRoundedPolygon(cdReal radius)
{
	cd2Polygon sharp, rounded, before;
	memset(&rounded, 0xa5, sizeof rounded);
	before = rounded;
	cdResult sharpResult = cd2MakePolygon(s_points, s_count, &sharp);
	cdResult result = cd2MakeRoundedPolygon(s_points, s_count, radius, &rounded);
	bool radiusValid = FuzzFinite(radius) && radius >= CD_R(0.0);
	if (result != CD_OK)
	{
		if (memcmp(&rounded, &before, sizeof rounded) != 0)
		{
			Fail("untouched", "rounded: %s, but the output polygon changed", cdGetResultString(result));
		}
		if (sharpResult == CD_OK && radiusValid)
		{
			Fail("rounded", "radius %.9g: %s where cd2MakePolygon succeeds", (double)radius,
				 cdGetResultString(result));
		}
		return;
	}
	if (!radiusValid || sharpResult != CD_OK)
	{
		Fail("rounded", "radius %.9g accepted (cd2MakePolygon: %s)", (double)radius,
			 cdGetResultString(sharpResult));
		return;
	}
	if (rounded.radius != radius || rounded.count != sharp.count || !cd2IsValidPolygon(&rounded) ||
		memcmp(rounded.vertices, sharp.vertices, sizeof sharp.vertices[0] * (size_t)sharp.count) != 0)
	{
		Fail("rounded", "radius %.9g: not the sharp polygon plus the radius", (double)radius);
	}
}

static void CheckMakeBoxPolygon(cd2Box box)
{
	cd2Polygon out, before;
	memset(&out, 0xa5, sizeof out);
	before = out;
	cdResult result = cd2MakeBoxPolygon(box, &out);
	bool valid = cd2IsValidBox(box);
	if ((unsigned)result >= (unsigned)CD_RESULT_COUNT || (!valid && result == CD_OK))
	{
		Fail("box", "an invalid box gave %d", (int)result);
	}
	if (result != CD_OK)
	{
		if (memcmp(&out, &before, sizeof out) != 0)
		{
			Fail("untouched", "box: %s, but the output polygon changed", cdGetResultString(result));
		}
		if (valid && result != CD_ERROR_DEGENERATE)
		{
			Fail("box", "a valid box gave %s", cdGetResultString(result));
		}
		return;
	}
	if (out.count != 4 || !cd2IsValidPolygon(&out))
	{
		Fail("box", "the box polygon of %d vertices fails cd2IsValidPolygon", out.count);
	}
}

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	FuzzReader r = FuzzBegin(data, size);
	s_count = FuzzByte(&r) % (FUZZ_MAX_POINTS + 1);
	for (int i = 0; i < s_count; ++i)
	{
		cdReal x = FuzzRawReal(&r), y = FuzzRawReal(&r);
		s_points[i] = cd2MakeVec(x, y);
	}
	CheckMakePolygon();

	/* The same points clamped into the documented range: the builder must take them (or say
	 * degenerate / too many). */
	for (int i = 0; i < s_count; ++i)
	{
		s_points[i] = cd2MakeVec(FuzzClampReal(s_points[i].x), FuzzClampReal(s_points[i].y));
	}
	CheckMakePolygon();
	CheckMakeRoundedPolygon(FuzzRawReal(&r));

	cd2Box box;
	box.center = cd2MakeVec(FuzzRawReal(&r), FuzzRawReal(&r));
	box.halfExtents = cd2MakeVec(FuzzRawReal(&r), FuzzRawReal(&r));
	box.rotation.c = FuzzRawReal(&r);
	box.rotation.s = FuzzRawReal(&r);
	CheckMakeBoxPolygon(box);
	box.center = cd2MakeVec(FuzzClampReal(box.center.x), FuzzClampReal(box.center.y));
	box.halfExtents = cd2MakeVec(FuzzClampSize(box.halfExtents.x), FuzzClampSize(box.halfExtents.y));
	box.rotation = cd2NormalizeRot((cd2Rot){FuzzClampReal(box.rotation.c), FuzzClampReal(box.rotation.s)});
	CheckMakeBoxPolygon(box);
	return 0;
}
