/* libFuzzer target for the 2D contact manifolds (cd2Collide), the twin of fuzz_manifold2.c. The
 * input decodes into two valid shapes among circle, capsule, AABB, box, polygon
 * (cd2MakeRoundedPolygon of 3 to 8 decoded points, half of them rounded) and segment, clamped into the
 * documented range (fuzz_decode.h), and a speculative distance.
 *
 * Checked, each under its own name (FUZZ_SKIP=name,... passes over a known one):
 *   manifold-valid      at most 2 points, everything finite, unit normal, no separation beyond
 *                       the speculative distance;
 *   manifold-empty-normal  the normal is zero when there are no points (manifold2.h);
 *   manifold-surface    each point minus/plus half its separation along the normal lies on A / B
 *                       (manifold-surface-speculative for points of positive separation)
 *                       (within the band: not outside the solid, on the segment);
 *   manifold-overlap    a manifold exists when the shapes overlap deeply, none when cd2Distance
 *                       exceeds the speculative distance by the band;
 *   manifold-separation the smallest separation lies in [0, cd2Distance] for separated pairs (a
 *                       face contact measures along its normal), at most the band for
 *                       overlapping ones;
 *   manifold-symmetry   cd2Collide(b, a): shapes of different kinds give the same points,
 *                       separations and ids with the opposite normal; shapes of one kind (AABB, box
 *                       and polygon are one) agree on whether there is contact away from the boundary;
 *   manifold-frames     a polygon A and a circle B, each taken as given in its body frame, with
 *                       decoded body transforms: cd2CollidePolygonCircleLocal and
 *                       cd2CollidePolygonCircleBodies give, value for value, cd2CollidePolygonCircle
 *                       on the circle's centre placed as their contracts say (manifold2.h).
 * The band is FUZZ_BAND times the largest magnitude of the case plus 0.1 linear slop: the 2D
 * manifolds decide with absolute tolerances of that size (manifold2.h: B's reference edge is taken
 * only when it separates by 0.1 slop more; cores within 0.1 slop take the clipping path), which
 * dominate at small scales. */
#include "fuzz_decode.h"

static struct
{
	cd2Shape a, b;
	cdReal speculative;
	cd2Transform xfA, xfB; /* body transforms of the manifold-frames check */
} s_case;

/* Open findings (fuzz/crashes/README.md, FuzzPassOver): the checks this target's CI run still
 * fails on; FUZZ_STRICT=1 checks them. */
#define OPEN_FINDINGS ""

static void Fail(const char* check, const char* format, ...)
{
	if (FuzzPassOver("fuzz_manifold2", OPEN_FINDINGS, check))
	{
		return;
	}
	va_list args;
	va_start(args, format);
	fprintf(stderr, "fuzz_manifold2: [%s] ", check);
	vfprintf(stderr, format, args);
	fprintf(stderr, "\n");
	va_end(args);
	FuzzPrintShape2("a", &s_case.a);
	FuzzPrintShape2("b", &s_case.b);
	fprintf(stderr, "  speculative distance %.9g\n", (double)s_case.speculative);
	fprintf(stderr,
			"  body transforms (frames check): A (%.9g %.9g) rotation (%.9g %.9g), B (%.9g %.9g) rotation "
			"(%.9g %.9g)\n",
			(double)s_case.xfA.p.x, (double)s_case.xfA.p.y, (double)s_case.xfA.q.c, (double)s_case.xfA.q.s,
			(double)s_case.xfB.p.x, (double)s_case.xfB.p.y, (double)s_case.xfB.q.c, (double)s_case.xfB.q.s);
	FuzzFail("see above");
}

static int Kind(cd2ShapeType type)
{
	return type == CD2_SHAPE_AABB || type == CD2_SHAPE_BOX ? CD2_SHAPE_POLYGON : (int)type;
}

static double MinSeparation(const cd2Manifold* m)
{
	double s = INFINITY;
	for (int i = 0; i < m->pointCount; ++i)
	{
		s = fmin(s, (double)m->points[i].separation);
	}
	return s;
}

static double OffShape(const cd2Shape* s, cd2Vec p)
{
	return FuzzDistance2(cd2ClosestPointOnShape(s, p), p);
}

static void CheckManifold(const cd2Manifold* m, const cd2Shape* a, const cd2Shape* b, double band,
						  const char* what)
{
	if (m->pointCount < 0 || m->pointCount > 2)
	{
		Fail("manifold-valid", "%s: %d points", what, m->pointCount);
	}
	if (!FuzzFiniteVec2(m->normal))
	{
		Fail("manifold-valid", "%s: normal not finite", what);
	}
	double length = FuzzDistance2(cd2MakeVec(CD_R(0.0), CD_R(0.0)), m->normal);
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
		const cd2ManifoldPoint* p = &m->points[i];
		if (!FuzzFiniteVec2(p->point) || !FuzzFinite(p->separation))
		{
			Fail("manifold-valid", "%s: point %d not finite", what, i);
		}
		if ((double)p->separation > (double)s_case.speculative + band)
		{
			Fail("manifold-valid", "%s: point %d separation %.9g beyond the speculative distance", what, i,
				 (double)p->separation);
		}
		cd2Vec onA = cd2MulAdd(p->point, CD_R(-0.5) * p->separation, m->normal);
		cd2Vec onB = cd2MulAdd(p->point, CD_R(0.5) * p->separation, m->normal);
		double offA = OffShape(a, onA), offB = OffShape(b, onB);
		if (offA > band || offB > band)
		{
			Fail(p->separation > CD_R(0.0) ? "manifold-surface-speculative" : "manifold-surface",
				 "%s: point %d (%.9g %.9g) separation %.9g: %.3g off A, %.3g off B (band %.3g)", what, i,
				 (double)p->point.x, (double)p->point.y, (double)p->separation, offA, offB, band);
		}
	}
}

/* A body transform: a turn of k/64 of a circle (k = 0 the identity, multiples of 16 exact quarter
 * turns) and a translation in the documented range. */
static cd2Transform DecodeTransform(FuzzReader* r)
{
	cd2Transform xf;
	uint8_t turn = FuzzByte(r);
	xf.q =
		(turn & 15) == 0 ? cd2MakeRot(CD_R(0.0)) : cd2MakeRot((cdReal)((double)(turn & 63) * (CD_PI / 32.0)));
	if ((turn & 15) == 0)
	{
		static const cdReal quarter[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
		xf.q.c = quarter[(turn >> 4) & 3][0];
		xf.q.s = quarter[(turn >> 4) & 3][1];
	}
	xf.p = FuzzVec2(r);
	return xf;
}

static bool SameManifold(const cd2Manifold* m, const cd2Manifold* n)
{
	bool same = m->pointCount == n->pointCount && cd2VecEqual(m->normal, n->normal);
	for (int i = 0; same && i < m->pointCount; ++i)
	{
		same = cd2VecEqual(m->points[i].point, n->points[i].point) &&
			   m->points[i].separation == n->points[i].separation && m->points[i].id == n->points[i].id;
	}
	return same;
}

/* manifold-frames: the polygon-first circle forms against their contracts. */
static void CheckFrames(const cd2Polygon* polygon, cd2Circle circle)
{
	cdReal d = s_case.speculative;
	cd2Circle placed = circle;
	placed.center = cd2TransformPoint(s_case.xfB, circle.center);
	cd2Manifold local = cd2CollidePolygonCircleLocal(polygon, circle, s_case.xfB, d);
	cd2Manifold expected = cd2CollidePolygonCircle(polygon, placed, d);
	if (!SameManifold(&local, &expected))
	{
		Fail("manifold-frames", "cd2CollidePolygonCircleLocal: %d points, world form %d", local.pointCount,
			 expected.pointCount);
	}
	placed.center = cd2InvTransformPoint(s_case.xfA, placed.center);
	cd2Manifold bodies = cd2CollidePolygonCircleBodies(polygon, s_case.xfA, circle, s_case.xfB, d);
	expected = cd2CollidePolygonCircle(polygon, placed, d);
	if (!SameManifold(&bodies, &expected))
	{
		Fail("manifold-frames", "cd2CollidePolygonCircleBodies: %d points, world form %d", bodies.pointCount,
			 expected.pointCount);
	}
}

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	static const cd2ShapeType types[] = {CD2_SHAPE_CIRCLE, CD2_SHAPE_CAPSULE, CD2_SHAPE_AABB,
										 CD2_SHAPE_BOX,	   CD2_SHAPE_POLYGON, CD2_SHAPE_SEGMENT};
	FuzzReader r = FuzzBegin(data, size);
	bool usable = FuzzDecodeShape2(&r, types, 6, &s_case.a);
	usable = FuzzDecodeShape2(&r, types, 6, &s_case.b) && usable;
	uint8_t flags = FuzzByte(&r);
	s_case.speculative = (flags & 1) ? FuzzClampSize(FuzzRawReal(&r)) : CD_R(0.0);
	s_case.xfA = DecodeTransform(&r);
	s_case.xfB = DecodeTransform(&r);
	if (!usable)
	{
		return 0;
	}
	const cd2Shape* a = &s_case.a;
	const cd2Shape* b = &s_case.b;
	double scale = fmax(fmax(FuzzShapeScale2(a), FuzzShapeScale2(b)), (double)s_case.speculative);
	double band = FUZZ_BAND * scale + 0.1 * (double)CD_LINEAR_SLOP;

	if (a->type == CD2_SHAPE_POLYGON && b->type == CD2_SHAPE_CIRCLE)
	{
		CheckFrames(&a->polygon, b->circle);
	}
	else if (b->type == CD2_SHAPE_POLYGON && a->type == CD2_SHAPE_CIRCLE)
	{
		CheckFrames(&b->polygon, a->circle);
	}

	cd2Manifold ab = cd2Collide(a, b, s_case.speculative);
	cd2Manifold ba = cd2Collide(b, a, s_case.speculative);
	CheckManifold(&ab, a, b, band, "collide(a, b)");
	CheckManifold(&ba, b, a, band, "collide(b, a)");

	double distance = (double)cd2Distance(a, b).distance;
	if (ab.pointCount > 0 && distance > (double)s_case.speculative + band)
	{
		Fail("manifold-overlap", "%d points, but the distance %.9g exceeds the speculative distance",
			 ab.pointCount, distance);
	}
	if (ab.pointCount == 0 && distance == 0.0 && FuzzDeeplyOverlapping2(a, b, band))
	{
		Fail("manifold-overlap", "no points, but the shapes overlap by more than %.3g", band);
	}
	if (ab.pointCount > 0)
	{
		double smallest = MinSeparation(&ab);
		/* A face contact of separated shapes measures along the reference normal, which may
		 * underestimate the distance (manifold2.h promises no more): never above it, never below 0. */
		if (distance > band && (smallest > distance + band || smallest < -band))
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
		cd2Manifold flipped = ba;
		flipped.normal = cd2Neg(ba.normal);
		if (!SameManifold(&ab, &flipped))
		{
			Fail("manifold-symmetry",
				 "collide(a, b): %d points, normal (%.9g %.9g); collide(b, a): %d points, "
				 "normal (%.9g %.9g)",
				 ab.pointCount, (double)ab.normal.x, (double)ab.normal.y, ba.pointCount, (double)ba.normal.x,
				 (double)ba.normal.y);
		}
	}
	else if ((ab.pointCount > 0) != (ba.pointCount > 0) &&
			 (distance > (double)s_case.speculative + band ||
			  (distance == 0.0 && FuzzDeeplyOverlapping2(a, b, band))))
	{
		Fail("manifold-symmetry", "collide(a, b) has %d points, collide(b, a) %d (distance %.9g)",
			 ab.pointCount, ba.pointCount, distance);
	}
	return 0;
}
