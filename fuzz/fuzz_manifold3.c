/* libFuzzer target for the 3D contact manifolds (cd3Collide). The input decodes into two valid
 * shapes among sphere, capsule, AABB, box, hull (cd3ComputeHull of 4 to 12 decoded points) and
 * triangle, clamped into the documented range (fuzz_decode.h), and a speculative distance.
 *
 * Checked, each under its own name (FUZZ_SKIP=name,... passes over a known one):
 *   manifold-valid      at most 4 points, everything finite, unit normal, no separation beyond
 *                       the speculative distance;
 *   manifold-empty-normal  the normal is zero when there are no points (manifold3.h);
 *   manifold-surface    each point minus/plus half its separation along the normal lies on A / B
 *                       (manifold-surface-speculative for points of positive separation)
 *                       (within the band: not outside the solid, on the triangle);
 *   manifold-overlap    a manifold exists when the shapes overlap deeply, none when cd3Distance
 *                       exceeds the speculative distance by the band;
 *   manifold-separation the smallest separation is cd3Distance (within 1e-3 of the scale) for
 *                       separated pairs, at most the band for overlapping ones;
 *   manifold-symmetry   cd3Collide(b, a): shapes of different kinds give the same points,
 *                       separations and ids with the opposite normal; shapes of one kind (AABB and
 *                       box are one) agree on whether there is contact away from the boundary.
 * Pairs with a triangle report under the check's name followed by "-triangle".
 * The band is FUZZ_BAND times the largest magnitude of the case. */
#include "fuzz_decode.h"

static struct
{
	cd3Shape a, b;
	cdReal speculative;
} s_case;

/* Open findings (fuzz/crashes/README.md, FuzzPassOver): the checks this target's CI run still
 * fails on; FUZZ_STRICT=1 checks them. manifold-valid itself (point count, finiteness, unit
 * normal) is never passed over. A new finding gets a crash file, a README row and its check's
 * name here only until it is fixed. Empty: the CI runs (seed 1, 100000 inputs) pass with
 * FUZZ_STRICT=1 in the float and the double build. The checks failing between shapes whose
 * magnitudes differ by more than DISPARATE_SCALE report under their own names
 * (manifold-surface-disparate, manifold-beyond-speculative-disparate). */
#define OPEN_FINDINGS ""
#define DISPARATE_SCALE 1000.0

/* Pairs with a triangle (their own code path, manifold_triangle3.c) fail under the check's name
 * followed by "-triangle". */
static void Fail(const char* baseCheck, const char* format, ...)
{
	char check[64];
	bool triangle = s_case.a.type == CD3_SHAPE_TRIANGLE || s_case.b.type == CD3_SHAPE_TRIANGLE;
	snprintf(check, sizeof check, "%s%s", baseCheck, triangle ? "-triangle" : "");
	if (FuzzPassOver("fuzz_manifold3", OPEN_FINDINGS, check))
	{
		return;
	}
	va_list args;
	va_start(args, format);
	fprintf(stderr, "fuzz_manifold3: [%s] ", check);
	vfprintf(stderr, format, args);
	fprintf(stderr, "\n");
	va_end(args);
	FuzzPrintShape3("a", &s_case.a);
	FuzzPrintShape3("b", &s_case.b);
	fprintf(stderr, "  speculative distance %.9g\n", (double)s_case.speculative);
	FuzzFail("see above");
}

static int Kind(cd3ShapeType type)
{
	return type == CD3_SHAPE_AABB ? CD3_SHAPE_BOX : (int)type;
}

static double MinSeparation(const cd3Manifold* m)
{
	double s = INFINITY;
	for (int i = 0; i < m->pointCount; ++i)
	{
		s = fmin(s, (double)m->points[i].separation);
	}
	return s;
}

static double OffShape(const cd3Shape* s, cd3Vec p)
{
	return FuzzDistance3(cd3ClosestPointOnShape(s, p), p);
}

static void CheckManifold(const cd3Manifold* m, const cd3Shape* a, const cd3Shape* b, double band,
						  const char* what)
{
	if (m->pointCount < 0 || m->pointCount > 4)
	{
		Fail("manifold-valid", "%s: %d points", what, m->pointCount);
	}
	if (!FuzzFiniteVec3(m->normal))
	{
		Fail("manifold-valid", "%s: normal not finite", what);
	}
	double length = FuzzDistance3(CD3_VEC_ZERO, m->normal);
	if (m->pointCount > 0 && fabs(length - 1.0) > FUZZ_UNIT_TOL)
	{
		Fail("manifold-valid", "%s: %d points, normal of length %.9g", what, m->pointCount, length);
	}
	if (m->pointCount == 0 && length != 0.0)
	{
		Fail("manifold-empty-normal", "%s: no points, but a normal of length %.9g", what, length);
	}
	for (int i = 0; i < m->pointCount; ++i)
	{
		const cd3ManifoldPoint* p = &m->points[i];
		if (!FuzzFiniteVec3(p->point) || !FuzzFinite(p->separation))
		{
			Fail("manifold-valid", "%s: point %d not finite", what, i);
		}
		if ((double)p->separation > (double)s_case.speculative + band)
		{
			double scaleA = FuzzShapeScale3(a), scaleB = FuzzShapeScale3(b);
			bool disparate = fmax(scaleA, scaleB) > DISPARATE_SCALE * fmin(scaleA, scaleB);
			Fail(disparate ? "manifold-beyond-speculative-disparate" : "manifold-beyond-speculative",
				 "%s: point %d separation %.9g beyond the speculative distance", what, i,
				 (double)p->separation);
		}
		cd3Vec onA = cd3MulAdd(p->point, CD_R(-0.5) * p->separation, m->normal);
		cd3Vec onB = cd3MulAdd(p->point, CD_R(0.5) * p->separation, m->normal);
		double offA = OffShape(a, onA), offB = OffShape(b, onB);
		if (offA > band || offB > band)
		{
			double scaleA = FuzzShapeScale3(a), scaleB = FuzzShapeScale3(b);
			bool disparate = fmax(scaleA, scaleB) > DISPARATE_SCALE * fmin(scaleA, scaleB);
			Fail(disparate
					 ? "manifold-surface-disparate"
					 : (p->separation > CD_R(0.0) ? "manifold-surface-speculative" : "manifold-surface"),
				 "%s: point %d (%.9g %.9g %.9g) separation %.9g: %.3g off A, %.3g off B (band %.3g)", what, i,
				 (double)p->point.x, (double)p->point.y, (double)p->point.z, (double)p->separation, offA,
				 offB, band);
		}
	}
}

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	static const cd3ShapeType types[] = {CD3_SHAPE_SPHERE, CD3_SHAPE_CAPSULE, CD3_SHAPE_AABB,
										 CD3_SHAPE_BOX,	   CD3_SHAPE_HULL,	  CD3_SHAPE_TRIANGLE};
	FuzzReader r = FuzzBegin(data, size);
	bool usable = FuzzDecodeShape3(&r, 0, types, 6, &s_case.a);
	usable = FuzzDecodeShape3(&r, 1, types, 6, &s_case.b) && usable;
	uint8_t flags = FuzzByte(&r);
	s_case.speculative = (flags & 1) ? FuzzClampSize(FuzzRawReal(&r)) : CD_R(0.0);
	if (!usable || (s_case.a.type == CD3_SHAPE_TRIANGLE && s_case.b.type == CD3_SHAPE_TRIANGLE))
	{
		FuzzFreeHulls();
		return 0;
	}
	const cd3Shape* a = &s_case.a;
	const cd3Shape* b = &s_case.b;
	double scale = fmax(fmax(FuzzShapeScale3(a), FuzzShapeScale3(b)), (double)s_case.speculative);
	double band = FUZZ_BAND * scale;

	cd3Manifold ab = cd3Collide(a, b, s_case.speculative);
	cd3Manifold ba = cd3Collide(b, a, s_case.speculative);
	CheckManifold(&ab, a, b, band, "collide(a, b)");
	CheckManifold(&ba, b, a, band, "collide(b, a)");

	double distance = (double)cd3Distance(a, b).distance;
	if (ab.pointCount > 0 && distance > (double)s_case.speculative + band)
	{
		Fail("manifold-overlap", "%d points, but the distance %.9g exceeds the speculative distance",
			 ab.pointCount, distance);
	}
	if (ab.pointCount == 0 && distance == 0.0 && FuzzDeeplyOverlapping3(a, b, band))
	{
		Fail("manifold-overlap", "no points, but the shapes overlap by more than %.3g", band);
	}
	if (ab.pointCount > 0)
	{
		double smallest = MinSeparation(&ab);
		/* manifold3.h: a separated pair keeps its SAT manifold when the deepest point realizes the
		 * distance within a small fraction of the size; 1e-3 of the scale covers it (and is the
		 * band of the float build). */
		double realized = fmax(band, 1e-3 * scale);
		if (distance > band && fabs(smallest - distance) > realized)
		{
			Fail("manifold-separation", "smallest separation %.9g, distance %.9g", smallest, distance);
		}
		if (distance == 0.0 && smallest > band)
		{
			Fail("manifold-separation", "the shapes overlap but the smallest separation is %.9g", smallest);
		}
	}

	if (Kind(a->type) != Kind(b->type))
	{
		bool same = ab.pointCount == ba.pointCount && cd3VecEqual(ab.normal, cd3Neg(ba.normal));
		for (int i = 0; same && i < ab.pointCount; ++i)
		{
			same = cd3VecEqual(ab.points[i].point, ba.points[i].point) &&
				   ab.points[i].separation == ba.points[i].separation && ab.points[i].id == ba.points[i].id;
		}
		if (!same)
		{
			Fail("manifold-symmetry",
				 "collide(a, b): %d points, normal (%.9g %.9g %.9g); collide(b, a): %d points, "
				 "normal (%.9g %.9g %.9g)",
				 ab.pointCount, (double)ab.normal.x, (double)ab.normal.y, (double)ab.normal.z, ba.pointCount,
				 (double)ba.normal.x, (double)ba.normal.y, (double)ba.normal.z);
		}
	}
	else if ((ab.pointCount > 0) != (ba.pointCount > 0) &&
			 (distance > (double)s_case.speculative + band ||
			  (distance == 0.0 && FuzzDeeplyOverlapping3(a, b, band))))
	{
		Fail("manifold-symmetry", "collide(a, b) has %d points, collide(b, a) %d (distance %.9g)",
			 ab.pointCount, ba.pointCount, distance);
	}
	FuzzFreeHulls();
	return 0;
}
