/* libFuzzer target for the shape casts and times of impact, 2D and 3D (cast.h). The first byte
 * after the scale chooses the dimension and the query; then come two valid shapes clamped into the
 * documented range (fuzz_decode.h) and the motion: a translation for a shape cast, two sweeps
 * (local centre, centres and rotations at both ends), a target separation and a tolerance for a
 * time of impact. 2D sweep angles are kept within +-64 rad.
 *
 * Checked, each under its own name (FUZZ_SKIP=name,... passes over a known one); the band is
 * FUZZ_BAND times the largest magnitude of the case, plus the query's own tolerance where the
 * contract has one:
 *   cast-valid    fraction in [0, 1], finite point and normal; a hit's normal is unit (or zero for
 *                 a zero translation at fraction 0); no hit: fraction 1, zero point and normal
 *                 (unless the iteration cap stopped it);
 *   cast-start    shapes that overlap deeply at fraction 0 hit at fraction 0;
 *   cast-hit      at the reported fraction the shapes are within CD_CAST_TOLERANCE (plus the band)
 *                 of touching, and the hit point lies on B;
 *   cast-free     no sampled fraction before the reported one (all of [0, 1] without a hit) has
 *                 the shapes overlapping deeply;
 *   toi-valid     a known state, t in [0, 1], t = 0 when overlapped, t = 1 when separated;
 *   toi-start     shapes that overlap deeply at t = 0 are reported overlapped;
 *   toi-hit       a hit's distance at t lies within [target, target + tolerance] (plus the band),
 *                 or below it at t = 0 (already closer than the target at the start);
 *   toi-free      no sampled time before t (all of [0, 1] when separated) has the distance below
 *                 the target by more than the band. */
#include "fuzz_decode.h"

#include "collide/cast.h"

enum
{
	SAMPLES = 16
};

static struct
{
	bool is3d, isToi;
	cd3Shape a3, b3;
	cd2Shape a2, b2;
	cd3Vec translation3;
	cd2Vec translation2;
	cd3Sweep sweepA3, sweepB3;
	cd2Sweep sweepA2, sweepB2;
	cdReal target, tolerance;
} s_case;

/* Open findings (fuzz/crashes/README.md, FuzzPassOver): checks that inputs within reach of the CI
 * run still fail; FUZZ_STRICT=1 checks them. Empty: the CI runs (seed 1, 100000 inputs) pass with
 * FUZZ_STRICT=1 in the float and the double build. */
#define OPEN_FINDINGS ""

static void Fail(const char* check, const char* format, ...)
{
	if (FuzzPassOver("fuzz_cast", OPEN_FINDINGS, check))
	{
		return;
	}
	va_list args;
	va_start(args, format);
	fprintf(stderr, "fuzz_cast: [%s] ", check);
	vfprintf(stderr, format, args);
	fprintf(stderr, "\n");
	va_end(args);
	if (s_case.is3d)
	{
		FuzzPrintShape3("a", &s_case.a3);
		FuzzPrintShape3("b", &s_case.b3);
		if (s_case.isToi)
		{
			FuzzPrintReals("sweep a", "localCenter center0 center1 rotation0 rotation1",
						   &s_case.sweepA3.localCenter.x, 17);
			FuzzPrintReals("sweep b", "localCenter center0 center1 rotation0 rotation1",
						   &s_case.sweepB3.localCenter.x, 17);
		}
		else
		{
			FuzzPrintReals("translation of a", "", &s_case.translation3.x, 3);
		}
	}
	else
	{
		FuzzPrintShape2("a", &s_case.a2);
		FuzzPrintShape2("b", &s_case.b2);
		if (s_case.isToi)
		{
			FuzzPrintReals("sweep a", "localCenter center0 center1 angle0 angle1",
						   &s_case.sweepA2.localCenter.x, 8);
			FuzzPrintReals("sweep b", "localCenter center0 center1 angle0 angle1",
						   &s_case.sweepB2.localCenter.x, 8);
		}
		else
		{
			FuzzPrintReals("translation of a", "", &s_case.translation2.x, 2);
		}
	}
	if (s_case.isToi)
	{
		fprintf(stderr, "  target %.9g tolerance %.9g\n", (double)s_case.target, (double)s_case.tolerance);
	}
	FuzzFail("see above");
}

static const char* StateName(cdToiState state)
{
	switch (state)
	{
		case CD_TOI_HIT:
			return "hit";
		case CD_TOI_SEPARATED:
			return "separated";
		case CD_TOI_OVERLAPPED:
			return "overlapped";
		case CD_TOI_FAILED:
			return "failed";
		default:
			return "?";
	}
}

/* The sampled fractions strictly before `end` (SAMPLES of them, from 0). */
static cdReal Sample(int i, cdReal end)
{
	return end * (cdReal)i / (cdReal)SAMPLES;
}

/* ---- 3D ---------------------------------------------------------------------------------------- */

static double Distance3At(const cd3Shape* a, cd3Vec da, const cd3Shape* b)
{
	cd3Shape moved = FuzzTranslateShape3(a, da);
	return (double)cd3Distance(&moved, b).distance;
}

static void CheckShapeCast3(void)
{
	const cd3Shape* a = &s_case.a3;
	const cd3Shape* b = &s_case.b3;
	cd3Vec d = s_case.translation3;
	cd3Shape end = FuzzTranslateShape3(a, d);
	/* The cast works at the magnitude of the translation too (a half-space's offset can stay small). */
	double scale = fmax(fmax(FuzzShapeScale3(a), FuzzShapeScale3(&end)),
						fmax(FuzzShapeScale3(b), FuzzVec3MaxAbs(0.0, d)));
	double band = FUZZ_BAND * scale;
	cd3CastOutput out = cd3ShapeCast(a, b, d);
	if (!(out.fraction >= CD_R(0.0) && out.fraction <= CD_R(1.0)) || !FuzzFiniteVec3(out.point) ||
		!FuzzFiniteVec3(out.normal))
	{
		Fail("cast-valid", "fraction %.9g, point (%.9g %.9g %.9g), normal (%.9g %.9g %.9g)",
			 (double)out.fraction, (double)out.point.x, (double)out.point.y, (double)out.point.z,
			 (double)out.normal.x, (double)out.normal.y, (double)out.normal.z);
	}
	double length = FuzzDistance3(CD3_VEC_ZERO, out.normal);
	bool zeroMotion = cd3LengthSquared(d) == CD_R(0.0);
	if (out.hit &&
		!(fabs(length - 1.0) <= FUZZ_UNIT_TOL || (length == 0.0 && zeroMotion && out.fraction == 0)))
	{
		Fail("cast-valid", "hit with a normal of length %.9g", length);
	}
	if (!out.hit && !out.hitIterationCap &&
		(out.fraction != CD_R(1.0) || !cd3VecEqual(out.point, CD3_VEC_ZERO) || length != 0.0))
	{
		Fail("cast-valid", "no hit, but fraction %.9g and a point or normal", (double)out.fraction);
	}
	if (out.hit && out.hitIterationCap)
	{
		Fail("cast-valid", "a hit that also reports the iteration cap");
	}
	if (cd3Distance(a, b).distance == CD_R(0.0) && FuzzDeeplyOverlapping3(a, b, band) &&
		!(out.hit && out.fraction == CD_R(0.0)))
	{
		Fail("cast-start", "the shapes overlap at the start: hit %d at fraction %.9g", (int)out.hit,
			 (double)out.fraction);
	}
	if (out.hit)
	{
		double gap = Distance3At(a, cd3Scale(out.fraction, d), b);
		if (gap > (double)CD_CAST_TOLERANCE + band)
		{
			Fail("cast-hit", "at fraction %.9g the shapes are %.9g apart", (double)out.fraction, gap);
		}
		double off = FuzzDistance3(cd3ClosestPointOnShape(b, out.point), out.point);
		if (off > band + (double)CD_CAST_TOLERANCE)
		{
			Fail("cast-hit", "the hit point (%.9g %.9g %.9g) is %.9g off B", (double)out.point.x,
				 (double)out.point.y, (double)out.point.z, off);
		}
	}
	for (int i = 0; i <= SAMPLES; ++i)
	{
		if (i == SAMPLES && (out.hit || out.hitIterationCap))
		{
			break;
		}
		/* A hit, or the iteration cap, vouches only for the fractions before the one reported. */
		bool stopped = out.hit || out.hitIterationCap;
		cdReal s = i == SAMPLES ? CD_R(1.0) : Sample(i, stopped ? out.fraction : CD_R(1.0));
		if (stopped && s >= out.fraction)
		{
			break;
		}
		cd3Shape moved = FuzzTranslateShape3(a, cd3Scale(s, d));
		if (cd3Distance(&moved, b).distance == CD_R(0.0) && FuzzDeeplyOverlapping3(&moved, b, band))
		{
			Fail("cast-free", "%s at fraction %.9g, but the shapes overlap deeply at %.9g",
				 out.hit ? "hit" : (out.hitIterationCap ? "iteration cap" : "no hit"), (double)out.fraction,
				 (double)s);
		}
	}
}

static cd3Shape ShapeAt3(const cd3Shape* s, const cd3Sweep* sweep, cdReal t)
{
	return FuzzTransformShape3(s, cd3GetSweepTransform(sweep, t));
}

static double DistanceAtTime3(cdReal t)
{
	cd3Shape a = ShapeAt3(&s_case.a3, &s_case.sweepA3, t), b = ShapeAt3(&s_case.b3, &s_case.sweepB3, t);
	return (double)cd3Distance(&a, &b).distance;
}

static double SweepScale3(const cd3Shape* s, const cd3Sweep* sweep)
{
	cd3Shape s0 = ShapeAt3(s, sweep, CD_R(0.0)), s1 = ShapeAt3(s, sweep, CD_R(1.0));
	double m = fmax(FuzzShapeScale3(&s0), FuzzShapeScale3(&s1));
	/* Every point of the body stays within |centre| + its arm about the centre. */
	double arm = FuzzShapeScale3(s) + FuzzVec3MaxAbs(0.0, sweep->localCenter);
	double reach = fmax(FuzzVec3MaxAbs(0.0, sweep->center0), FuzzVec3MaxAbs(0.0, sweep->center1));
	return fmax(m, reach + 2.0 * arm);
}

static void CheckToi(cdToiOutput out, double scale, double (*distanceAt)(cdReal), bool deepAtStart)
{
	double band = FUZZ_BAND * scale;
	double target = (double)s_case.target;
	if ((unsigned)out.state > (unsigned)CD_TOI_FAILED || !(out.t >= CD_R(0.0) && out.t <= CD_R(1.0)) ||
		(out.state == CD_TOI_OVERLAPPED && out.t != CD_R(0.0)) ||
		(out.state == CD_TOI_SEPARATED && out.t != CD_R(1.0)))
	{
		Fail("toi-valid", "state %d (%s), t %.9g", (int)out.state, StateName(out.state), (double)out.t);
	}
	if (deepAtStart && out.state != CD_TOI_OVERLAPPED)
	{
		Fail("toi-start", "the shapes overlap at t = 0, but the state is %s at t %.9g", StateName(out.state),
			 (double)out.t);
	}
	if (out.state == CD_TOI_HIT)
	{
		/* At t = 0 the shapes may already be closer than the target (but apart): a hit at once. */
		double d = distanceAt(out.t);
		if ((out.t > CD_R(0.0) && d < target - band) || d > target + (double)s_case.tolerance + band)
		{
			Fail("toi-hit", "hit at t %.9g with the distance %.9g (target %.9g, band %.3g)", (double)out.t, d,
				 target, band);
		}
	}
	if (out.state == CD_TOI_OVERLAPPED)
	{
		return;
	}
	cdReal end = out.state == CD_TOI_SEPARATED ? CD_R(1.0) : out.t;
	for (int i = 0; i <= SAMPLES; ++i)
	{
		if (i == SAMPLES && out.state != CD_TOI_SEPARATED)
		{
			break;
		}
		cdReal s = i == SAMPLES ? CD_R(1.0) : Sample(i, end);
		if (out.state != CD_TOI_SEPARATED && s >= out.t)
		{
			break;
		}
		double d = distanceAt(s);
		if (d < target - band)
		{
			Fail("toi-free", "%s at t %.9g, but the distance at %.9g is %.9g (target %.9g, band %.3g)",
				 StateName(out.state), (double)out.t, (double)s, d, target, band);
		}
	}
}

static void CheckTimeOfImpact3(void)
{
	double scale = fmax(SweepScale3(&s_case.a3, &s_case.sweepA3), SweepScale3(&s_case.b3, &s_case.sweepB3));
	cdToiOutput out = cd3TimeOfImpact(&s_case.a3, &s_case.sweepA3, &s_case.b3, &s_case.sweepB3, s_case.target,
									  s_case.tolerance);
	cd3Shape a0 = ShapeAt3(&s_case.a3, &s_case.sweepA3, CD_R(0.0)),
			 b0 = ShapeAt3(&s_case.b3, &s_case.sweepB3, CD_R(0.0));
	bool deep =
		cd3Distance(&a0, &b0).distance == CD_R(0.0) && FuzzDeeplyOverlapping3(&a0, &b0, FUZZ_BAND * scale);
	CheckToi(out, scale, DistanceAtTime3, deep);
}

/* ---- 2D ---------------------------------------------------------------------------------------- */

static void CheckShapeCast2(void)
{
	const cd2Shape* a = &s_case.a2;
	const cd2Shape* b = &s_case.b2;
	cd2Vec d = s_case.translation2;
	cd2Shape end = FuzzTranslateShape2(a, d);
	double scale = fmax(fmax(FuzzShapeScale2(a), FuzzShapeScale2(&end)),
						fmax(FuzzShapeScale2(b), FuzzVec2MaxAbs(0.0, d)));
	double band = FUZZ_BAND * scale;
	cd2CastOutput out = cd2ShapeCast(a, b, d);
	if (!(out.fraction >= CD_R(0.0) && out.fraction <= CD_R(1.0)) || !FuzzFiniteVec2(out.point) ||
		!FuzzFiniteVec2(out.normal))
	{
		Fail("cast-valid", "fraction %.9g, point (%.9g %.9g), normal (%.9g %.9g)", (double)out.fraction,
			 (double)out.point.x, (double)out.point.y, (double)out.normal.x, (double)out.normal.y);
	}
	double length = FuzzDistance2(cd2MakeVec(CD_R(0.0), CD_R(0.0)), out.normal);
	bool zeroMotion = cd2LengthSquared(d) == CD_R(0.0);
	if (out.hit &&
		!(fabs(length - 1.0) <= FUZZ_UNIT_TOL || (length == 0.0 && zeroMotion && out.fraction == 0)))
	{
		Fail("cast-valid", "hit with a normal of length %.9g", length);
	}
	if (!out.hit && !out.hitIterationCap &&
		(out.fraction != CD_R(1.0) || out.point.x != CD_R(0.0) || out.point.y != CD_R(0.0) || length != 0.0))
	{
		Fail("cast-valid", "no hit, but fraction %.9g and a point or normal", (double)out.fraction);
	}
	if (out.hit && out.hitIterationCap)
	{
		Fail("cast-valid", "a hit that also reports the iteration cap");
	}
	if (cd2Distance(a, b).distance == CD_R(0.0) && FuzzDeeplyOverlapping2(a, b, band) &&
		!(out.hit && out.fraction == CD_R(0.0)))
	{
		Fail("cast-start", "the shapes overlap at the start: hit %d at fraction %.9g", (int)out.hit,
			 (double)out.fraction);
	}
	if (out.hit)
	{
		cd2Shape moved = FuzzTranslateShape2(a, cd2Scale(out.fraction, d));
		double gap = (double)cd2Distance(&moved, b).distance;
		if (gap > (double)CD_CAST_TOLERANCE + band)
		{
			Fail("cast-hit", "at fraction %.9g the shapes are %.9g apart", (double)out.fraction, gap);
		}
		double off = FuzzDistance2(cd2ClosestPointOnShape(b, out.point), out.point);
		if (off > band + (double)CD_CAST_TOLERANCE)
		{
			Fail("cast-hit", "the hit point (%.9g %.9g) is %.9g off B", (double)out.point.x,
				 (double)out.point.y, off);
		}
	}
	for (int i = 0; i <= SAMPLES; ++i)
	{
		if (i == SAMPLES && (out.hit || out.hitIterationCap))
		{
			break;
		}
		/* A hit, or the iteration cap, vouches only for the fractions before the one reported. */
		bool stopped = out.hit || out.hitIterationCap;
		cdReal s = i == SAMPLES ? CD_R(1.0) : Sample(i, stopped ? out.fraction : CD_R(1.0));
		if (stopped && s >= out.fraction)
		{
			break;
		}
		cd2Shape moved = FuzzTranslateShape2(a, cd2Scale(s, d));
		if (cd2Distance(&moved, b).distance == CD_R(0.0) && FuzzDeeplyOverlapping2(&moved, b, band))
		{
			Fail("cast-free", "%s at fraction %.9g, but the shapes overlap deeply at %.9g",
				 out.hit ? "hit" : (out.hitIterationCap ? "iteration cap" : "no hit"), (double)out.fraction,
				 (double)s);
		}
	}
}

static cd2Shape ShapeAt2(const cd2Shape* s, const cd2Sweep* sweep, cdReal t)
{
	return FuzzTransformShape2(s, cd2GetSweepTransform(sweep, t));
}

static double DistanceAtTime2(cdReal t)
{
	cd2Shape a = ShapeAt2(&s_case.a2, &s_case.sweepA2, t), b = ShapeAt2(&s_case.b2, &s_case.sweepB2, t);
	return (double)cd2Distance(&a, &b).distance;
}

static double SweepScale2(const cd2Shape* s, const cd2Sweep* sweep)
{
	cd2Shape s0 = ShapeAt2(s, sweep, CD_R(0.0)), s1 = ShapeAt2(s, sweep, CD_R(1.0));
	double m = fmax(FuzzShapeScale2(&s0), FuzzShapeScale2(&s1));
	double arm = FuzzShapeScale2(s) + FuzzVec2MaxAbs(0.0, sweep->localCenter);
	double reach = fmax(FuzzVec2MaxAbs(0.0, sweep->center0), FuzzVec2MaxAbs(0.0, sweep->center1));
	return fmax(m, reach + 2.0 * arm);
}

static void CheckTimeOfImpact2(void)
{
	double scale = fmax(SweepScale2(&s_case.a2, &s_case.sweepA2), SweepScale2(&s_case.b2, &s_case.sweepB2));
	cdToiOutput out = cd2TimeOfImpact(&s_case.a2, &s_case.sweepA2, &s_case.b2, &s_case.sweepB2, s_case.target,
									  s_case.tolerance);
	cd2Shape a0 = ShapeAt2(&s_case.a2, &s_case.sweepA2, CD_R(0.0)),
			 b0 = ShapeAt2(&s_case.b2, &s_case.sweepB2, CD_R(0.0));
	bool deep =
		cd2Distance(&a0, &b0).distance == CD_R(0.0) && FuzzDeeplyOverlapping2(&a0, &b0, FUZZ_BAND * scale);
	CheckToi(out, scale, DistanceAtTime2, deep);
}

/* ---- decoding ---------------------------------------------------------------------------------- */

static cd3Sweep DecodeSweep3(FuzzReader* r)
{
	cd3Sweep s;
	s.localCenter = FuzzVec3(r);
	s.center0 = FuzzVec3(r);
	s.center1 = FuzzVec3(r);
	s.rotation0 = FuzzQuat(r);
	s.rotation1 = FuzzQuat(r);
	return s;
}

static cdReal DecodeAngle(FuzzReader* r)
{
	cdReal angle = FuzzClampReal(FuzzRawReal(r));
	return cdClamp(angle, CD_R(-64.0), CD_R(64.0));
}

static cd2Sweep DecodeSweep2(FuzzReader* r)
{
	cd2Sweep s;
	s.localCenter = FuzzVec2(r);
	s.center0 = FuzzVec2(r);
	s.center1 = FuzzVec2(r);
	s.angle0 = DecodeAngle(r);
	s.angle1 = DecodeAngle(r);
	return s;
}

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	static const cd3ShapeType castTypes3[] = {CD3_SHAPE_SPHERE,	 CD3_SHAPE_CAPSULE, CD3_SHAPE_AABB,
											  CD3_SHAPE_BOX,	 CD3_SHAPE_HULL,	CD3_SHAPE_TRIANGLE,
											  CD3_SHAPE_SEGMENT, CD3_SHAPE_PLANE};
	/* Moving bodies turn: no AABB (it cannot turn) and no half-space (it may not turn). */
	static const cd3ShapeType toiTypes3[] = {CD3_SHAPE_SPHERE, CD3_SHAPE_CAPSULE,  CD3_SHAPE_BOX,
											 CD3_SHAPE_HULL,   CD3_SHAPE_TRIANGLE, CD3_SHAPE_SEGMENT};
	static const cd2ShapeType castTypes2[] = {CD2_SHAPE_CIRCLE, CD2_SHAPE_CAPSULE, CD2_SHAPE_AABB,
											  CD2_SHAPE_BOX,	CD2_SHAPE_POLYGON, CD2_SHAPE_SEGMENT};
	static const cd2ShapeType toiTypes2[] = {CD2_SHAPE_CIRCLE, CD2_SHAPE_CAPSULE, CD2_SHAPE_BOX,
											 CD2_SHAPE_POLYGON, CD2_SHAPE_SEGMENT};
	FuzzReader r = FuzzBegin(data, size);
	uint8_t mode = FuzzByte(&r);
	memset(&s_case, 0, sizeof s_case);
	s_case.is3d = (mode & 1) != 0;
	s_case.isToi = (mode & 2) != 0;
	bool usable;
	if (s_case.is3d)
	{
		const cd3ShapeType* types = s_case.isToi ? toiTypes3 : castTypes3;
		int count = s_case.isToi ? 6 : 8;
		usable = FuzzDecodeShape3(&r, 0, types, count, &s_case.a3);
		usable = FuzzDecodeShape3(&r, 1, types, count, &s_case.b3) && usable;
	}
	else
	{
		const cd2ShapeType* types = s_case.isToi ? toiTypes2 : castTypes2;
		int count = s_case.isToi ? 5 : 6;
		usable = FuzzDecodeShape2(&r, types, count, &s_case.a2);
		usable = FuzzDecodeShape2(&r, types, count, &s_case.b2) && usable;
	}
	if (s_case.isToi)
	{
		if (s_case.is3d)
		{
			s_case.sweepA3 = DecodeSweep3(&r);
			s_case.sweepB3 = DecodeSweep3(&r);
		}
		else
		{
			s_case.sweepA2 = DecodeSweep2(&r);
			s_case.sweepB2 = DecodeSweep2(&r);
		}
		s_case.target = (mode & 4) ? FuzzClampSize(FuzzRawReal(&r)) : CD_R(0.0);
		s_case.tolerance = (mode & 8) ? FuzzClampSize(FuzzRawReal(&r)) : CD_R(0.0);
		if (s_case.tolerance == CD_R(0.0))
		{
			s_case.tolerance = CD_R(0.25) * CD_LINEAR_SLOP;
		}
	}
	else if (s_case.is3d)
	{
		s_case.translation3 = FuzzVec3(&r);
	}
	else
	{
		s_case.translation2 = FuzzVec2(&r);
	}
	if (usable)
	{
		if (s_case.is3d)
		{
			s_case.isToi ? CheckTimeOfImpact3() : CheckShapeCast3();
		}
		else
		{
			s_case.isToi ? CheckTimeOfImpact2() : CheckShapeCast2();
		}
	}
	FuzzFreeHulls();
	return 0;
}
