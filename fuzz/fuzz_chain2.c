/* libFuzzer target for 2D chains (chain2.h): the builder on raw points (NaN, infinities, runs of
 * coincident points, collinear runs), then the queries on the clamped points under a decoded
 * chain transform, each against a loop over the chain's segments.
 *
 * Checked, each under its own name (FUZZ_SKIP=name,... passes over a known one):
 *   chain-build     non-finite input gives CD_ERROR_NOT_FINITE; a built chain validates, has at
 *                   most count points, count - 1 segments (count for a loop) and its points'
 *                   bounds;
 *   chain-ray       a hit has a fraction in [0, 1], lies on its segment, carries that segment's
 *                   front normal and moves against it; no segment is hit from its free side
 *                   clearly earlier, and a miss leaves no clear front hit (away from the ends
 *                   of the segment and of the ray, and from grazing);
 *   chain-query     the box query reports segments in increasing order; untransformed, every
 *                   segment whose bounds clearly overlap the box and none whose bounds are
 *                   clearly apart; turned, every segment that clearly meets the box;
 *   chain-manifold  per manifold at most 2 points, finite values, a unit normal, separations at
 *                   most the speculative distance, segment indices increasing; each point minus /
 *                   plus half its separation along the normal lies on the segment / the shape;
 *                   untransformed, each manifold's points are points of that segment's own
 *                   cd2CollideChainSegment* manifold (same id, position, separation, normal)
 *                   for circles, capsules, segments and polygons.
 * The band is FUZZ_BAND times the largest magnitude of the case plus 0.1 linear slop, as in
 * fuzz_manifold2.c. */
#include "collide/chain2.h"
#include "fuzz_decode.h"

enum
{
	CHAIN_FUZZ_MAX_POINTS = 16,
	CHAIN_FUZZ_MAX_MANIFOLDS = CHAIN_FUZZ_MAX_POINTS + 1
};

static struct
{
	cd2Vec points[CHAIN_FUZZ_MAX_POINTS];
	int count;
	bool isLoop;
	cd2Transform transform;
	cd2Shape shape;
	cdReal speculative;
	cd2Ray ray;
	cd2Aabb box;
} s_case;

static void Fail(const char* check, const char* format, ...)
{
	if (FuzzSkipped(check))
	{
		return;
	}
	va_list args;
	va_start(args, format);
	fprintf(stderr, "fuzz_chain2: [%s] ", check);
	vfprintf(stderr, format, args);
	fprintf(stderr, "\n");
	va_end(args);
	fprintf(stderr, "  chain of %d points%s:", s_case.count, s_case.isLoop ? " (loop)" : "");
	FuzzPrintReals("", "(x y ...)", &s_case.points[0].x, 2 * s_case.count);
	FuzzPrintReals("transform", "(px py c s)", &s_case.transform.p.x, 4);
	FuzzPrintShape2("shape", &s_case.shape);
	fprintf(stderr, "  speculative distance %.9g\n", (double)s_case.speculative);
	FuzzPrintReals("ray", "(ox oy tx ty)", &s_case.ray.origin.x, 4);
	FuzzPrintReals("box", "(minx miny maxx maxy)", &s_case.box.min.x, 4);
	FuzzFail("see above");
}

/* Segment `index` in world space (the chain's points under its transform). */
static cd2ChainSegment WorldSegment(const cd2Chain* chain, int index)
{
	cd2ChainSegment s = cd2Chain_GetSegment(chain, index);
	cd2Transform t = s_case.transform;
	s.ghost1 = cd2TransformPoint(t, s.ghost1);
	s.p1 = cd2TransformPoint(t, s.p1);
	s.p2 = cd2TransformPoint(t, s.p2);
	s.ghost2 = cd2TransformPoint(t, s.ghost2);
	return s;
}

/* The world front normal of segment `index`, from its local points (the world points carry the
 * transform's round-off, which far from the origin turns a short segment noticeably). */
static cd2Vec FrontNormal(const cd2Chain* chain, int index)
{
	cd2ChainSegment s = cd2Chain_GetSegment(chain, index);
	return cd2RotateVector(s_case.transform.q, cd2Normalize(cd2RightPerp(cd2Sub(s.p2, s.p1))));
}

static double OffSegment(const cd2ChainSegment* s, cd2Vec p)
{
	cd2Segment g = {s->p1, s->p2};
	return FuzzDistance2(cd2ClosestPointOnSegment(g, p), p);
}

static double Dot(cd2Vec a, cd2Vec b)
{
	return (double)a.x * (double)b.x + (double)a.y * (double)b.y;
}

static void CheckBuild(const cd2Chain* chain, int count)
{
	if (cd2ValidateChain(chain) != CD_OK)
	{
		Fail("chain-build", "the built chain does not validate (%d)", (int)cd2ValidateChain(chain));
	}
	int points = cd2Chain_GetPointCount(chain), segments = cd2Chain_GetSegmentCount(chain);
	bool loop = cd2Chain_IsLoop(chain);
	if (points < (loop ? 3 : 2) || points > count || loop != s_case.isLoop ||
		segments != (loop ? points : points - 1))
	{
		Fail("chain-build", "%d points in, %d points and %d segments out (loop %d)", count, points, segments,
			 (int)loop);
	}
	cd2Aabb bounds = cd2Chain_GetBounds(chain);
	const cd2Vec* p = cd2Chain_GetPoints(chain);
	for (int i = 0; i < points; ++i)
	{
		if (!cd2PointInAabb(p[i], bounds))
		{
			Fail("chain-build", "point %d (%.9g %.9g) outside the chain bounds", i, (double)p[i].x,
				 (double)p[i].y);
		}
	}
}

static void CheckRay(const cd2Chain* chain, double band)
{
	cd2Ray ray = s_case.ray;
	double length = FuzzDistance2(cd2MakeVec(CD_R(0.0), CD_R(0.0)), ray.translation);
	cd2RayHit hit = {CD_R(-1.0), {CD_R(0.0), CD_R(0.0)}, {CD_R(0.0), CD_R(0.0)}};
	int index = -1;
	bool hits = cd2RaycastChain(chain, s_case.transform, ray, &hit, &index);
	int segments = cd2Chain_GetSegmentCount(chain);
	if (hits)
	{
		if (index < 0 || index >= segments || !(hit.fraction >= CD_R(0.0) && hit.fraction <= CD_R(1.0)) ||
			!FuzzFiniteVec2(hit.point) || !FuzzFiniteVec2(hit.normal))
		{
			Fail("chain-ray", "hit segment %d at fraction %.9g", index, (double)hit.fraction);
		}
		cd2ChainSegment s = WorldSegment(chain, index);
		cd2Vec front = FrontNormal(chain, index);
		if (OffSegment(&s, hit.point) > band || FuzzDistance2(hit.normal, front) > 1e-3 ||
			Dot(hit.normal, ray.translation) > band * length)
		{
			Fail("chain-ray",
				 "hit segment %d at (%.9g %.9g), normal (%.9g %.9g): %.3g off it, front (%.9g %.9g)", index,
				 (double)hit.point.x, (double)hit.point.y, (double)hit.normal.x, (double)hit.normal.y,
				 OffSegment(&s, hit.point), (double)front.x, (double)front.y);
		}
	}
	if (length == 0.0)
	{
		return;
	}
	/* Clear front hits of the segments one by one: away from the ends, not grazing. */
	for (int i = 0; i < segments; ++i)
	{
		cd2ChainSegment s = WorldSegment(chain, i);
		cd2Vec front = FrontNormal(chain, i);
		cd2Segment g = {s.p1, s.p2};
		cd2RayHit h;
		if (!cd2RaycastSegment(g, ray, &h) || Dot(front, ray.translation) > -1e-2 * length ||
			FuzzDistance2(h.point, s.p1) < band || FuzzDistance2(h.point, s.p2) < band ||
			Dot(front, cd2Sub(ray.origin, s.p1)) < band)
		{
			continue;
		}
		/* A ray whose end only reaches the segment within the band may go either way. */
		double slack = band / length;
		if ((double)h.fraction > 1.0 - slack)
		{
			continue;
		}
		if (!hits || (double)h.fraction < (double)hit.fraction - slack)
		{
			Fail("chain-ray",
				 "segment %d is hit from its free side at fraction %.9g; the chain reports %s %.9g", i,
				 (double)h.fraction, hits ? "a hit at" : "a miss", hits ? (double)hit.fraction : 0.0);
		}
	}
}

typedef struct QueryLog
{
	int indices[CHAIN_FUZZ_MAX_MANIFOLDS];
	int count;
	bool ordered;
} QueryLog;

static bool LogSegment(int segmentIndex, void* context)
{
	QueryLog* log = (QueryLog*)context;
	if (log->count > 0 && segmentIndex <= log->indices[log->count - 1])
	{
		log->ordered = false;
	}
	if (log->count < CHAIN_FUZZ_MAX_MANIFOLDS)
	{
		log->indices[log->count++] = segmentIndex;
	}
	return true;
}

static bool Reported(const QueryLog* log, int index)
{
	for (int i = 0; i < log->count; ++i)
	{
		if (log->indices[i] == index)
		{
			return true;
		}
	}
	return false;
}

static void CheckQuery(const cd2Chain* chain, double band, bool identity)
{
	QueryLog log = {{0}, 0, true};
	cd2Chain_QueryAabb(chain, s_case.transform, s_case.box, LogSegment, &log);
	if (!log.ordered)
	{
		Fail("chain-query", "segments reported out of order");
	}
	cd2Aabb box = s_case.box;
	for (int i = 0; i < cd2Chain_GetSegmentCount(chain); ++i)
	{
		cd2ChainSegment s = WorldSegment(chain, i);
		cd2Vec lo = cd2Min(s.p1, s.p2), hi = cd2Max(s.p1, s.p2);
		/* Gaps along x and y between the segment's bounds and the box (negative: overlap). */
		double gap = fmax(fmax((double)box.min.x - (double)hi.x, (double)lo.x - (double)box.max.x),
						  fmax((double)box.min.y - (double)hi.y, (double)lo.y - (double)box.max.y));
		/* Untransformed, the query tests the segment's bounds; turned, a local box around the
		 * world box, which holds every segment that meets the box itself. */
		cd2Aabb inner = {{(cdReal)((double)box.min.x + band), (cdReal)((double)box.min.y + band)},
						 {(cdReal)((double)box.max.x - band), (cdReal)((double)box.max.y - band)}};
		cd2Segment g = {s.p1, s.p2};
		bool mustReport = identity ? gap < -band
								   : inner.min.x <= inner.max.x && inner.min.y <= inner.max.y &&
										 cd2OverlapAabbSegment(inner, g);
		if (mustReport && !Reported(&log, i))
		{
			Fail("chain-query", "segment %d meets the box (bounds overlap %.3g) but is not reported", i,
				 -gap);
		}
		if (identity && gap > band && Reported(&log, i))
		{
			Fail("chain-query", "segment %d is %.3g from the box but reported", i, gap);
		}
	}
}

/* The manifold of one segment against a circle, capsule, segment or polygon, as cd2CollideChain
 * documents it. */
static cd2Manifold SegmentManifold(const cd2ChainSegment* s, const cd2Shape* shape)
{
	switch (shape->type)
	{
		case CD2_SHAPE_CIRCLE:
			return cd2CollideChainSegmentCircle(s, shape->circle, s_case.speculative);
		case CD2_SHAPE_CAPSULE:
			return cd2CollideChainSegmentCapsule(s, shape->capsule, s_case.speculative);
		case CD2_SHAPE_SEGMENT:
		{
			cd2Capsule c = {shape->segment.p1, shape->segment.p2, CD_R(0.0)};
			return cd2CollideChainSegmentCapsule(s, c, s_case.speculative);
		}
		default:
			return cd2CollideChainSegmentPolygon(s, &shape->polygon, s_case.speculative);
	}
}

static void CheckManifolds(const cd2Chain* chain, double band, bool identity)
{
	cd2Manifold manifolds[CHAIN_FUZZ_MAX_MANIFOLDS];
	int segmentIndices[CHAIN_FUZZ_MAX_MANIFOLDS];
	int segments = cd2Chain_GetSegmentCount(chain);
	int count = cd2CollideChain(chain, s_case.transform, &s_case.shape, s_case.speculative, manifolds,
								CHAIN_FUZZ_MAX_MANIFOLDS, segmentIndices);
	if (count < 0 || count > segments)
	{
		Fail("chain-manifold", "%d manifolds for %d segments", count, segments);
	}
	for (int k = 0; k < count; ++k)
	{
		const cd2Manifold* m = &manifolds[k];
		int index = segmentIndices[k];
		if (index < 0 || index >= segments || (k > 0 && index <= segmentIndices[k - 1]))
		{
			Fail("chain-manifold", "manifold %d has segment index %d", k, index);
		}
		double normalLength = FuzzDistance2(cd2MakeVec(CD_R(0.0), CD_R(0.0)), m->normal);
		if (m->pointCount < 1 || m->pointCount > 2 || !FuzzFiniteVec2(m->normal) ||
			fabs(normalLength - 1.0) > FUZZ_UNIT_TOL)
		{
			Fail("chain-manifold", "segment %d: %d points, normal of length %.9g", index, m->pointCount,
				 normalLength);
		}
		cd2ChainSegment s = WorldSegment(chain, index);
		for (int i = 0; i < m->pointCount; ++i)
		{
			const cd2ManifoldPoint* p = &m->points[i];
			if (!FuzzFiniteVec2(p->point) || !FuzzFinite(p->separation) ||
				(double)p->separation > (double)s_case.speculative + band)
			{
				Fail("chain-manifold", "segment %d point %d: separation %.9g", index, i,
					 (double)p->separation);
			}
			cd2Vec onA = cd2MulAdd(p->point, CD_R(-0.5) * p->separation, m->normal);
			cd2Vec onB = cd2MulAdd(p->point, CD_R(0.5) * p->separation, m->normal);
			double offA = OffSegment(&s, onA);
			double offB = FuzzDistance2(cd2ClosestPointOnShape(&s_case.shape, onB), onB);
			if (offA > band || offB > band)
			{
				Fail("chain-manifold",
					 "segment %d point %d (%.9g %.9g) separation %.9g: %.3g off the segment, %.3g off the "
					 "shape (band %.3g)",
					 index, i, (double)p->point.x, (double)p->point.y, (double)p->separation, offA, offB,
					 band);
			}
		}
		if (!identity)
		{
			continue;
		}
		/* Boxes and AABBs become the chain's own rectangle (a segment when flat), which
		 * cd2MakeBoxPolygon may weld or order differently: only the other shapes reach the
		 * segment function unchanged, so only they are compared, exactly. */
		if (s_case.shape.type == CD2_SHAPE_BOX || s_case.shape.type == CD2_SHAPE_AABB)
		{
			continue;
		}
		cd2Manifold own = SegmentManifold(&s, &s_case.shape);
		bool same = cd2VecEqual(own.normal, m->normal);
		for (int i = 0; same && i < m->pointCount; ++i)
		{
			bool found = false;
			for (int j = 0; j < own.pointCount; ++j)
			{
				const cd2ManifoldPoint *a = &own.points[j], *b = &m->points[i];
				found = found ||
						(a->id == b->id && cd2VecEqual(a->point, b->point) && a->separation == b->separation);
			}
			same = found;
		}
		if (!same)
		{
			Fail("chain-manifold",
				 "segment %d: the chain's manifold (%d points, normal %.9g %.9g) is not part of "
				 "the segment's own (%d points, normal %.9g %.9g)",
				 index, m->pointCount, (double)m->normal.x, (double)m->normal.y, own.pointCount,
				 (double)own.normal.x, (double)own.normal.y);
		}
	}
}

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	FuzzReader r = FuzzBegin(data, size);
	uint8_t head = FuzzByte(&r);
	int count = 2 + head % (CHAIN_FUZZ_MAX_POINTS - 1);
	s_case.isLoop = (head & 0x80) != 0;
	s_case.count = count;
	/* Raw values go to the builder once, to check its errors; the queries get clamped ones. */
	cd2Vec raw[CHAIN_FUZZ_MAX_POINTS];
	bool finite = true;
	for (int i = 0; i < count; ++i)
	{
		raw[i].x = FuzzRawReal(&r);
		raw[i].y = FuzzRawReal(&r);
		finite = finite && FuzzFiniteVec2(raw[i]);
		s_case.points[i] = cd2MakeVec(FuzzClampReal(raw[i].x), FuzzClampReal(raw[i].y));
	}
	uint8_t flags = FuzzByte(&r);
	bool identity = (flags & 1) == 0;
	s_case.transform = CD2_TRANSFORM_IDENTITY;
	if (!identity)
	{
		s_case.transform.p = FuzzVec2(&r);
		cd2Rot q = {FuzzClampReal(FuzzRawReal(&r)), FuzzClampReal(FuzzRawReal(&r))};
		q = cd2NormalizeRot(q);
		s_case.transform.q = cd2IsValidRot(q) ? q : CD2_ROT_IDENTITY;
	}
	s_case.speculative = (flags & 2) ? FuzzClampSize(FuzzRawReal(&r)) : CD_R(0.0);
	s_case.ray.origin = FuzzVec2(&r);
	s_case.ray.translation = FuzzVec2(&r);
	cd2Vec c1 = FuzzVec2(&r), c2 = FuzzVec2(&r);
	s_case.box.min = cd2Min(c1, c2);
	s_case.box.max = cd2Max(c1, c2);
	static const cd2ShapeType types[] = {CD2_SHAPE_CIRCLE, CD2_SHAPE_CAPSULE, CD2_SHAPE_AABB,
										 CD2_SHAPE_BOX,	   CD2_SHAPE_POLYGON, CD2_SHAPE_SEGMENT};
	bool shapeUsable = FuzzDecodeShape2(&r, types, 6, &s_case.shape);

	cd2Chain* chain = NULL;
	cdResult result = cd2CreateChain(raw, count, s_case.isLoop, &chain);
	if (!finite)
	{
		if (result != CD_ERROR_NOT_FINITE || chain != NULL)
		{
			Fail("chain-build", "non-finite points gave result %d", (int)result);
		}
		return 0;
	}
	cd2DestroyChain(chain);
	chain = NULL;
	result = cd2CreateChain(s_case.points, count, s_case.isLoop, &chain);
	if (result != CD_OK)
	{
		if (result != CD_ERROR_DEGENERATE || chain != NULL)
		{
			Fail("chain-build", "finite points gave result %d", (int)result);
		}
		return 0;
	}
	CheckBuild(chain, count);

	double scale = FuzzVec2MaxAbs(FuzzVec2MaxAbs(0.0, s_case.transform.p), s_case.ray.origin);
	scale = FuzzVec2MaxAbs(FuzzVec2MaxAbs(FuzzVec2MaxAbs(scale, s_case.ray.translation), s_case.box.min),
						   s_case.box.max);
	for (int i = 0; i < count; ++i)
	{
		scale = FuzzVec2MaxAbs(scale, s_case.points[i]);
	}
	if (shapeUsable)
	{
		scale = fmax(fmax(scale, FuzzShapeScale2(&s_case.shape)), (double)s_case.speculative);
	}
	/* The chain's points move by the transform: its translation plus their rotated magnitude. */
	double band = FUZZ_BAND * 2.0 * scale + 0.1 * (double)CD_LINEAR_SLOP;

	CheckRay(chain, band);
	CheckQuery(chain, band, identity);
	if (shapeUsable)
	{
		CheckManifolds(chain, band, identity);
	}
	cd2DestroyChain(chain);
	return 0;
}
