/* Distance and closest points between any two 2D shapes: GJK on the shapes' cores (support2.h)
 * with a Voronoi-region sub-algorithm, then the radii are taken off. */
#include "collide/query2.h"

#include "pairs2.h"
#include "support2.h"

/* GJK converges in a handful of iterations on these small point sets; the cap only guards
 * against cycling caused by round-off. */
#define GJK_MAX_ITERATIONS 64

/* Relative gap between the upper bound |v| and the support line's lower bound at which the
 * distance is final: round-off in the support values is of this order. */
#define GJK_GAP_TOLERANCE (CD_R(8.0) * CD_REAL_EPSILON)

/* Steps in a row without getting closer before GJK settles for the closest simplex seen. */
#define GJK_MAX_STALLS 4

/* A triangle this flat (sine of its angle) gives barycentric coordinates dominated by
 * round-off; it is then treated through its edges. */
#define GJK_DEGENERATE_TOLERANCE (CD_R(16.0) * CD_REAL_EPSILON)

/* The origin counts as touching the simplex when the closest point is within this many
 * epsilons of the simplex's own size: below it the distance is round-off. */
#define GJK_TOUCH_TOLERANCE (CD_R(16.0) * CD_REAL_EPSILON)

typedef cd2GjkVertex GjkVertex;
typedef cd2GjkSimplex GjkSimplex;

/* Barycentric coordinates of the point of segment w0-w1 closest to the origin. */
static void SolveSegment(cd2Vec w0, cd2Vec w1, cdReal* l0, cdReal* l1)
{
	cd2Vec e = cd2Sub(w1, w0);
	cdReal d1 = -cd2Dot(w0, e);
	cdReal d2 = cd2Dot(w1, e);
	if (d1 <= CD_R(0.0))
	{
		*l0 = CD_R(1.0);
		*l1 = CD_R(0.0);
	}
	else if (d2 <= CD_R(0.0))
	{
		*l0 = CD_R(0.0);
		*l1 = CD_R(1.0);
	}
	else
	{
		cdReal sum = d1 + d2;
		*l0 = d2 / sum;
		*l1 = d1 / sum;
	}
}

/* Most steps of iterative refinement of the weights of a triangle enclosing the origin (see
 * RefineEnclosedWeights): each step shrinks the residual by about eps |e1| |e2| / area, which the
 * flatness tolerance keeps below 1/16, so at least 4 bits a step down to the round-off of the
 * vertices themselves: 6 steps cover float's 24 bits, 14 double's 53 (a box 4.8e15 long and 25
 * wide took 8). The loop stops as soon as a step gains nothing. */
#define GJK_REFINE_STEPS 16

/* The residual (in units of the largest vertex coordinate) below which refinement cannot gain:
 * the round-off of the residual sum itself. */
#define GJK_REFINE_FLOOR (CD_R(2.0) * CD_REAL_EPSILON)

static cdReal ResidualLengthSquared(const cd2Vec* w, const cdReal* l, cd2Vec* residual)
{
	*residual = cd2Add(cd2Add(cd2Scale(l[0], w[0]), cd2Scale(l[1], w[1])), cd2Scale(l[2], w[2]));
	return cd2LengthSquared(*residual);
}

/* The weights of the origin in a thin triangle are ill-conditioned: the sub-areas, cross products
 * of vertices of size |w|, carry round-off eps |w|^2 while the area may be small, so the weights
 * can be off by eps |w|^2 / area. The shapes' common point, the same weights applied to the
 * support points of each shape, then lies off the other shape by the residual sum l_i w_i
 * (2.2e-4 for a point in a box 5e-5 thin; 18 in double with |w| ~ 1e7). Iterative refinement
 * removes it: the correction solves the same system for the residual, whose own round-off is
 * relative to the (small) residual. Returns false when the refined weights put the origin outside
 * the triangle after all (the sign test was decided by round-off). */
static bool RefineEnclosedWeights(const cd2Vec* w, cdReal area, cdReal* l)
{
	cd2Vec e1 = cd2Sub(w[1], w[0]), e2 = cd2Sub(w[2], w[0]);
	cdReal inverseArea = CD_R(1.0) / area;
	cd2Vec residual;
	cdReal residualSquared = ResidualLengthSquared(w, l, &residual);
	/* A residual within the round-off of computing it (about eps times the largest coordinate)
	 * is as small as float weights make it: no step can gain, so none is tried (most triangles of
	 * well-separated vertices end here, and a step was a tenth of a query that overlaps). */
	cdReal largest = cdMax(cdMax(cd2MaxAbs(w[0]), cd2MaxAbs(w[1])), cd2MaxAbs(w[2]));
	cdReal floor = GJK_REFINE_FLOOR * largest;
	if (residualSquared <= floor * floor)
	{
		return true; /* the weights are those of the sign test, all >= 0 */
	}
	for (int step = 0; step < GJK_REFINE_STEPS && residualSquared > CD_R(0.0); ++step)
	{
		/* d1 e1 + d2 e2 = -residual, keeping the sum of the weights. */
		cdReal d1 = cd2Cross(e2, residual) * inverseArea;
		cdReal d2 = cd2Cross(residual, e1) * inverseArea;
		cdReal refined[3] = {l[0] - d1 - d2, l[1] + d1, l[2] + d2};
		cd2Vec refinedResidual;
		cdReal refinedSquared = ResidualLengthSquared(w, refined, &refinedResidual);
		if (!(refinedSquared < residualSquared))
		{
			break;
		}
		for (int i = 0; i < 3; ++i)
		{
			l[i] = refined[i];
		}
		residual = refinedResidual;
		residualSquared = refinedSquared;
	}
	return l[0] >= CD_R(0.0) && l[1] >= CD_R(0.0) && l[2] >= CD_R(0.0);
}

/* Barycentric coordinates of the point of triangle w[0..2] closest to the origin; returns true
 * when the origin lies inside it. w[2] is the support point just added: when the origin is
 * outside, the closest point lies on an edge through it. In exact arithmetic the closest point of
 * the old edge w0-w1 (which GJK only extends when the support line shows it can get closer) is
 * beaten by a point of the new edges; in round-off the two can tie, and choosing the old edge
 * again dropped the new support point, found it again, and stalled (two long segments sharing an
 * end point at distance 116250 instead of 0). */
static bool SolveTriangle(const cd2Vec* w, cdReal* l)
{
	cd2Vec e1 = cd2Sub(w[1], w[0]);
	cd2Vec e2 = cd2Sub(w[2], w[0]);
	cdReal area = cd2Cross(e1, e2);
	/* |area| > tolerance * |e1| |e2|, squared (the vertices are scaled to unit size). */
	if (area * area >
		GJK_DEGENERATE_TOLERANCE * GJK_DEGENERATE_TOLERANCE * cd2LengthSquared(e1) * cd2LengthSquared(e2))
	{
		/* The weights are the sub-areas over the area: inside when all share its sign. */
		cdReal c0 = cd2Cross(w[1], w[2]);
		cdReal c1 = cd2Cross(w[2], w[0]);
		cdReal c2 = cd2Cross(w[0], w[1]);
		if (c0 * area >= CD_R(0.0) && c1 * area >= CD_R(0.0) && c2 * area >= CD_R(0.0))
		{
			cdReal inverse = CD_R(1.0) / (c0 + c1 + c2);
			l[0] = c0 * inverse;
			l[1] = c1 * inverse;
			l[2] = c2 * inverse;
			if (RefineEnclosedWeights(w, area, l))
			{
				return true;
			}
		}
	}

	/* Outside (or flat): the closest point lies on an edge through w[2]. */
	cdReal bestDistanceSquared = CD_REAL_MAX;
	for (int i = 1; i < 3; ++i)
	{
		int j = (i + 1) % 3, k = (i + 2) % 3;
		cdReal li, lj;
		SolveSegment(w[i], w[j], &li, &lj);
		cdReal distanceSquared = cd2LengthSquared(cd2Add(cd2Scale(li, w[i]), cd2Scale(lj, w[j])));
		if (distanceSquared < bestDistanceSquared)
		{
			bestDistanceSquared = distanceSquared;
			l[i] = li;
			l[j] = lj;
			l[k] = CD_R(0.0);
		}
	}
	return false;
}

/* Reduces the simplex to the vertices that support its point closest to the origin, sets their
 * weights and returns true when the origin is enclosed by a triangle. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline bool
SolveSimplex(GjkSimplex* simplex)
{
	if (simplex->count == 1)
	{
		simplex->lambda[0] = CD_R(1.0); /* a point is its own closest point */
		return false;
	}
	cd2Vec w[3];
	cdReal l[3] = {CD_R(1.0), CD_R(0.0), CD_R(0.0)};
	/* The weights do not depend on scale: solve on vertices scaled to unit size, so that the
	 * products of up to four coordinates neither overflow nor underflow at extreme sizes. */
	cdReal largest = CD_R(0.0);
	for (int i = 0; i < simplex->count; ++i)
	{
		w[i] = simplex->v[i].w;
		largest = cdMax(largest, cd2MaxAbs(w[i]));
	}
	/* Within these bounds the products (up to the eighth power of a coordinate times the small
	 * tolerances) neither overflow nor underflow: no scaling needed. */
#if CD_DOUBLE
	const cdReal safeLow = 0x1p-100, safeHigh = 0x1p100;
#else
	const cdReal safeLow = 0x1p-16f, safeHigh = 0x1p16f;
#endif
	if (largest > CD_R(0.0) && (largest < safeLow || largest > safeHigh))
	{
		cdReal inverse = CD_R(1.0) / largest;
		for (int i = 0; i < simplex->count; ++i)
		{
			w[i] = cd2Scale(inverse, w[i]);
		}
	}
	bool enclosed = false;
	if (simplex->count == 2)
	{
		SolveSegment(w[0], w[1], &l[0], &l[1]);
	}
	else if (simplex->count == 3)
	{
		enclosed = SolveTriangle(w, l);
	}

	int kept = 0;
	for (int i = 0; i < simplex->count; ++i)
	{
		if (l[i] > CD_R(0.0) || (kept == 0 && i == simplex->count - 1))
		{
			simplex->v[kept] = simplex->v[i];
			simplex->lambda[kept] = l[i] > CD_R(0.0) ? l[i] : CD_R(1.0);
			++kept;
		}
	}
	simplex->count = kept;
	return enclosed;
}

/* The direction from the simplex towards the origin. For a segment it is the edge's normal
 * (Catto's trick): -v, a sum of large, cancelling terms when the shapes are large compared with
 * their distance, can point off by far more than its length error and make GJK stop at a tie
 * between support points. */
static cd2Vec SearchDirection(const GjkSimplex* simplex, cd2Vec v, cdReal vLengthSquared,
							  cdReal* lengthSquared)
{
	if (simplex->count == 2)
	{
		cd2Vec e = cd2Sub(simplex->v[1].w, simplex->v[0].w);
		cd2Vec direction =
			cd2Cross(e, cd2Neg(simplex->v[0].w)) > CD_R(0.0) ? cd2LeftPerp(e) : cd2RightPerp(e);
		/* The construction fails only when the origin is (nearly) on the segment's line, where -v
		 * is as good a direction as any. */
		cdReal directionLengthSquared = cd2LengthSquared(direction);
		if (directionLengthSquared > CD_R(0.0) && cdIsValidReal(directionLengthSquared) &&
			cd2Dot(direction, v) < CD_R(0.0))
		{
			*lengthSquared = directionLengthSquared;
			return direction;
		}
	}
	*lengthSquared = vLengthSquared;
	return cd2Neg(v);
}

static GjkVertex MakeVertex(const cd2Core* a, const cd2Core* b, int indexA, int indexB)
{
	GjkVertex vertex;
	vertex.indexA = indexA;
	vertex.indexB = indexB;
	vertex.a = a->points[indexA];
	vertex.b = b->points[indexB];
	vertex.w = cd2Sub(vertex.a, vertex.b);
	return vertex;
}

/* The size of a simplex (length of a segment, area of a triangle), which a warm start compares
 * with the cached one: a simplex that grew or shrank by more than a factor of 2 belongs to shapes
 * that moved too much for it to help (Catto). */
bool cd2SolveGjkSimplex(cd2GjkSimplex* simplex)
{
	return SolveSimplex(simplex);
}

cd2Vec cd2GjkSearchDirection(const cd2GjkSimplex* simplex, cd2Vec v)
{
	cdReal lengthSquared;
	return SearchDirection(simplex, v, cd2LengthSquared(v), &lengthSquared);
}

static cdReal SimplexMetric(const GjkSimplex* simplex)
{
	if (simplex->count == 2)
	{
		return cd2Length(cd2Sub(simplex->v[1].w, simplex->v[0].w));
	}
	if (simplex->count == 3)
	{
		return cdAbs(
			cd2Cross(cd2Sub(simplex->v[1].w, simplex->v[0].w), cd2Sub(simplex->v[2].w, simplex->v[0].w)));
	}
	return CD_R(0.0);
}

/* Rebuilds the cached simplex from the current shapes; false (no warm start) for a cache that is
 * empty, garbage (count or indices out of range, a vertex repeated, a size that is not a finite
 * positive number) or stale (size changed by more than a factor of 2). Any simplex of support
 * points is a valid start for GJK, so a cache that passes can change the iterations but not the
 * answer. */
static bool ReadCache(const cd2SimplexCache* cache, const cd2Core* a, const cd2Core* b, GjkSimplex* simplex)
{
	if (cache == NULL || cache->count < 1 || cache->count > 3)
	{
		return false;
	}
	int count = cache->count;
	for (int i = 0; i < count; ++i)
	{
		int indexA = cache->indexA[i], indexB = cache->indexB[i];
		if (indexA < 0 || indexA >= a->count || indexB < 0 || indexB >= b->count)
		{
			return false;
		}
		for (int j = 0; j < i; ++j)
		{
			if (simplex->v[j].indexA == indexA && simplex->v[j].indexB == indexB)
			{
				return false;
			}
		}
		simplex->v[i] = MakeVertex(a, b, indexA, indexB);
		simplex->lambda[i] = CD_R(0.0);
	}
	simplex->count = count;
	if (count > 1)
	{
		cdReal metric = SimplexMetric(simplex), cached = cache->metric;
		if (!(metric > CD_R(0.0) && metric >= CD_R(0.5) * cached && metric <= CD_R(2.0) * cached))
		{
			return false;
		}
	}
	return true;
}

static void WriteCache(cd2SimplexCache* cache, const GjkSimplex* simplex)
{
	if (cache == NULL)
	{
		return;
	}
	cache->count = simplex->count;
	for (int i = 0; i < 3; ++i)
	{
		cache->indexA[i] = i < simplex->count ? simplex->v[i].indexA : 0;
		cache->indexB[i] = i < simplex->count ? simplex->v[i].indexB : 0;
	}
	cache->metric = SimplexMetric(simplex);
}

/* GJK's simplex as named values rather than an array indexed by its count: the compiler keeps
 * them in registers, where the array went through the stack at every step (the solve's copies of
 * the vertices read back 8 bytes that had been stored 4 at a time, and waited on store
 * forwarding). */
typedef struct GjkState
{
	GjkVertex v0, v1, v2;
	cdReal l0, l1, l2;
	cdReal m0, m1, m2; /* cd2MaxAbs of each vertex's w, computed once per vertex */
	int count;
} GjkState;

/* Reduces the state's simplex to the vertices that support its point closest to the origin and
 * sets their weights, as SolveSimplex (the same arithmetic in the same order, so the same
 * weights bit for bit); true when the origin is enclosed by the triangle. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline bool
SolveState(GjkState* s)
{
	if (s->count == 1)
	{
		s->l0 = CD_R(1.0);
		return false;
	}
	cd2Vec w[3];
	cdReal l[3] = {CD_R(1.0), CD_R(0.0), CD_R(0.0)};
	w[0] = s->v0.w;
	w[1] = s->v1.w;
	w[2] = s->v2.w;
	cdReal largest = cdMax(CD_R(0.0), s->m0);
	largest = cdMax(largest, s->m1);
	if (s->count == 3)
	{
		largest = cdMax(largest, s->m2);
	}
#if CD_DOUBLE
	const cdReal safeLow = 0x1p-100, safeHigh = 0x1p100;
#else
	const cdReal safeLow = 0x1p-16f, safeHigh = 0x1p16f;
#endif
	if (largest > CD_R(0.0) && (largest < safeLow || largest > safeHigh))
	{
		cdReal inverse = CD_R(1.0) / largest;
		for (int i = 0; i < 3; ++i)
		{
			w[i] = cd2Scale(inverse, w[i]);
		}
	}
	bool enclosed = false;
	if (s->count == 2)
	{
		SolveSegment(w[0], w[1], &l[0], &l[1]);
	}
	else
	{
		enclosed = SolveTriangle(w, l);
	}
	/* Keep the vertices of positive weight in order; none (round-off) keeps the last one. */
	GjkState out = *s;
	int kept = 0;
	if (l[0] > CD_R(0.0))
	{
		out.v0 = s->v0;
		out.l0 = l[0];
		out.m0 = s->m0;
		kept = 1;
	}
	if (l[1] > CD_R(0.0) || (kept == 0 && s->count == 2))
	{
		cdReal weight = l[1] > CD_R(0.0) ? l[1] : CD_R(1.0);
		if (kept == 0)
		{
			out.v0 = s->v1;
			out.l0 = weight;
			out.m0 = s->m1;
		}
		else
		{
			out.v1 = s->v1;
			out.l1 = weight;
			out.m1 = s->m1;
		}
		++kept;
	}
	if (s->count == 3 && (l[2] > CD_R(0.0) || kept == 0))
	{
		cdReal weight = l[2] > CD_R(0.0) ? l[2] : CD_R(1.0);
		if (kept == 0)
		{
			out.v0 = s->v2;
			out.l0 = weight;
			out.m0 = s->m2;
		}
		else if (kept == 1)
		{
			out.v1 = s->v2;
			out.l1 = weight;
			out.m1 = s->m2;
		}
		else
		{
			out.v2 = s->v2;
			out.l2 = weight;
			out.m2 = s->m2;
		}
		++kept;
	}
	out.count = kept;
	*s = out;
	return enclosed;
}

/* GJK's steps from the start in *state to its end, left in *state. Round-off can make a step gain
 * nothing (or lose a little) while the next ones still gain: with track, the closest simplex seen
 * is kept and GJK stops after a few steps without progress, ending on that simplex. Without track
 * nothing is kept (the copy of the simplex at every step was a tenth of a query) and GJK gives up
 * at the first step without progress, setting *stalled: the caller then runs it again from the
 * same start with track, which repeats the same steps and so gives the tracked answer bit for bit.
 * Returns the number of iterations. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline int
GjkRun(const cd2Core* a, const cd2Core* b, const cd2CoreLanes* lanesA, const cd2CoreLanes* lanesB,
	   GjkState* state, bool track, bool* touching, bool* hitIterationCap, bool* stalled)
{
	GjkState s = *state;
	GjkState best = s;
	cdReal bestDistanceSquared = CD_REAL_MAX;
	int stalls = 0;
	*touching = false;
	*stalled = false;
	int iteration = 0;
	for (; iteration < GJK_MAX_ITERATIONS; ++iteration)
	{
		if (SolveState(&s))
		{
			*touching = true;
			break;
		}
		/* sqrt(2) * the largest |coordinate|: at least the largest |w|. */
		cd2Vec v = cd2MulAdd(CD2_VEC_ZERO, s.l0, s.v0.w);
		cdReal size = cdMax(CD_R(0.0), s.m0);
		if (s.count > 1)
		{
			v = cd2MulAdd(v, s.l1, s.v1.w);
			size = cdMax(size, s.m1);
		}
		CD_ASSERT(s.count <= 2); /* a triangle either encloses the origin or loses a vertex */
		cdReal distanceSquared = cd2LengthSquared(v);
		cdReal touch = GJK_TOUCH_TOLERANCE * CD_R(1.4142136) * size;
		if (distanceSquared <= touch * touch)
		{
			*touching = true;
			break;
		}
		if (distanceSquared < bestDistanceSquared)
		{
			if (track)
			{
				best = s;
			}
			bestDistanceSquared = distanceSquared;
			stalls = 0;
		}
		else if (!track)
		{
			*stalled = true;
			return iteration;
		}
		else if (++stalls > GJK_MAX_STALLS)
		{
			break;
		}

		/* The direction from the simplex towards the origin (SearchDirection). */
		cd2Vec direction = cd2Neg(v);
		cdReal directionLengthSquared = distanceSquared;
		if (s.count == 2)
		{
			cd2Vec e = cd2Sub(s.v1.w, s.v0.w);
			cd2Vec normal = cd2Cross(e, cd2Neg(s.v0.w)) > CD_R(0.0) ? cd2LeftPerp(e) : cd2RightPerp(e);
			cdReal normalLengthSquared = cd2LengthSquared(normal);
			if (normalLengthSquared > CD_R(0.0) && cdIsValidReal(normalLengthSquared) &&
				cd2Dot(normal, v) < CD_R(0.0))
			{
				direction = normal;
				directionLengthSquared = normalLengthSquared;
			}
		}
		/* The supports by lanes (support2.h): which point wins is as random as the direction, and
		 * a compare-and-branch per point, a select per point in a loop over the count or a hill
		 * climb from the last support all spent their time in mispredicted branches. */
		int indexA = cd2CoreLanesSupport(lanesA, direction);
		int indexB = cd2CoreLanesSupport(lanesB, cd2Neg(direction));
		/* A support pair already in the simplex, by bit operations (a loop over the count with
		 * short-circuit tests mispredicted about three branches a query). */
		int same = ((s.v0.indexA ^ indexA) | (s.v0.indexB ^ indexB)) == 0;
		same |= (s.count > 1) & (((s.v1.indexA ^ indexA) | (s.v1.indexB ^ indexB)) == 0);
		if (same)
		{
			break;
		}
		GjkVertex vertex = MakeVertex(a, b, indexA, indexB);
		/* The support line bounds the distance from below: stop when it meets |v|. */
		/* lower = -dot(direction, w) / |direction| >= (1 - tolerance) * upper, squared and in double
		 * (no square root per iteration; the fourth powers overflow no float range). */
		double lowerTimesLength = -(double)cd2Dot(direction, vertex.w);
		double enough = (1.0 - (double)GJK_GAP_TOLERANCE) * (1.0 - (double)GJK_GAP_TOLERANCE) *
						(double)distanceSquared * (double)directionLengthSquared;
		if (lowerTimesLength > 0.0 && lowerTimesLength * lowerTimesLength >= enough)
		{
			break;
		}
		cdReal vertexSize = cd2MaxAbs(vertex.w);
		if (s.count == 1)
		{
			s.v1 = vertex;
			s.l1 = CD_R(0.0);
			s.m1 = vertexSize;
		}
		else
		{
			s.v2 = vertex;
			s.l2 = CD_R(0.0);
			s.m2 = vertexSize;
		}
		++s.count;
	}
	/* Every convergence test leaves the loop by break: running off its end is the cap. */
	*hitIterationCap = iteration == GJK_MAX_ITERATIONS;
	/* Without track no step lost ground, so the last simplex is the closest. */
	*state = track && !*touching ? best : s;
	return iteration;
}

/* Closest points of the cores of a and b (whose points lanesA and lanesB hold, support2.h);
 * *touching is set when the cores overlap (then *pointA and *pointB coincide up to round-off).
 * Warm-started from *cache when it is usable, and writes the final simplex back to it (cache may
 * be NULL). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline int
GjkCoresLanes(const cd2Core* a, const cd2Core* b, const cd2CoreLanes* lanesA, const cd2CoreLanes* lanesB,
			  cd2SimplexCache* cache, cd2Vec* pointA, cd2Vec* pointB, bool* touching, bool* hitIterationCap)
{
	GjkState start;
	{
		GjkSimplex cached;
		cached.count = 0;
		bool warm = cache != NULL && ReadCache(cache, a, b, &cached);
		if (warm)
		{
			start.v0 = cached.v[0];
			start.v1 = cached.count > 1 ? cached.v[1] : cached.v[0];
			start.v2 = cached.count > 2 ? cached.v[2] : cached.v[0];
			start.count = cached.count;
		}
		else
		{
			/* A cold start from the first points, without a support: the supports along the line
			 * between the cores' middles cost a pair of supports in every call and saved fewer
			 * (collide_bench_scenes' polygon pairs: 3.0 support pairs per overlapping pair with
			 * them, 2.25 without; 3.8 and 3.7 for the separated ones). */
			start.v0 = MakeVertex(a, b, 0, 0);
			start.v1 = start.v0;
			start.v2 = start.v0;
			start.count = 1;
		}
		/* The weights of a cached simplex are 0 until solved; a cold start's point has weight 1. */
		start.l0 = warm ? CD_R(0.0) : CD_R(1.0);
		start.l1 = CD_R(0.0);
		start.l2 = CD_R(0.0);
		start.m0 = cd2MaxAbs(start.v0.w);
		start.m1 = cd2MaxAbs(start.v1.w);
		start.m2 = cd2MaxAbs(start.v2.w);
	}

	GjkState s = start;
	bool stalled;
	int iteration = GjkRun(a, b, lanesA, lanesB, &s, false, touching, hitIterationCap, &stalled);
	if (stalled)
	{
		s = start;
		iteration = GjkRun(a, b, lanesA, lanesB, &s, true, touching, hitIterationCap, &stalled);
	}
	if (cache != NULL)
	{
		GjkSimplex simplex;
		simplex.v[0] = s.v0;
		simplex.v[1] = s.v1;
		simplex.v[2] = s.v2;
		simplex.count = s.count;
		WriteCache(cache, &simplex);
	}

	cd2Vec pa = cd2MulAdd(CD2_VEC_ZERO, s.l0, s.v0.a);
	cd2Vec pb = cd2MulAdd(CD2_VEC_ZERO, s.l0, s.v0.b);
	if (s.count > 1)
	{
		pa = cd2MulAdd(pa, s.l1, s.v1.a);
		pb = cd2MulAdd(pb, s.l1, s.v1.b);
	}
	if (s.count > 2)
	{
		pa = cd2MulAdd(pa, s.l2, s.v2.a);
		pb = cd2MulAdd(pb, s.l2, s.v2.b);
	}
	*pointA = pa;
	*pointB = pb;
	return *hitIterationCap ? iteration : iteration + 1;
}

static cd2ClosestPoints Touching(cd2Vec point)
{
	cd2ClosestPoints result = {point, point, CD_R(0.0)};
	return result;
}

cd2ClosestPoints cd2Distance(const cd2Shape* a, const cd2Shape* b)
{
	return cd2DistanceCached(a, b, NULL, NULL);
}

cd2ClosestPoints cd2DistanceWithStatus(const cd2Shape* a, const cd2Shape* b, cdDistanceStatus* status)
{
	return cd2DistanceCached(a, b, NULL, status);
}

/* The closest points of the shapes from those of their cores (radiusA, radiusB around them). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline cd2ClosestPoints
AddRadii(cd2Vec pointA, cd2Vec pointB, bool touching, cdReal radiusA, cdReal radiusB)
{
	if (touching)
	{
		return Touching(pointA); /* before the square root, which only the others need */
	}
	cd2ClosestPoints result;
	cdReal radius = radiusA + radiusB;
	cd2Vec delta = cd2Sub(pointB, pointA);
	cdReal coreDistance = cd2Length(delta);
	if (coreDistance <= radius)
	{
		/* Only the rounded parts overlap: this point is within rA of pointA and rB of pointB. */
		cdReal t = radius > CD_R(0.0) ? radiusA / radius : CD_R(0.0);
		result = Touching(cd2MulAdd(pointA, t, delta));
	}
	else if (radius == CD_R(0.0))
	{
		/* Sharp cores (polygons, segments, a time of impact's stripped cores): the closest points
		 * are the cores' own, without the normal, whose division ended every such query's chain
		 * of dependent operations (moving them by 0 along it changed at most the sign of a zero
		 * coordinate). */
		result.pointA = pointA;
		result.pointB = pointB;
		result.distance = coreDistance;
	}
	else
	{
		cd2Vec normal = cd2Scale(CD_R(1.0) / coreDistance, delta);
		result.pointA = cd2MulAdd(pointA, radiusA, normal);
		result.pointB = cd2MulSub(pointB, radiusB, normal);
		result.distance = coreDistance - radius;
	}
	return result;
}

cd2ClosestPoints cd2DistanceCores(const cd2Core* coreA, const cd2Core* coreB, cd2SimplexCache* cache,
								  cdDistanceStatus* status)
{
	cd2Vec pointA, pointB;
	bool touching, hitIterationCap;
	cd2CoreLanes lanesA, lanesB;
	cd2MakeCoreLanes(coreA, &lanesA);
	cd2MakeCoreLanes(coreB, &lanesB);
	int iterations =
		GjkCoresLanes(coreA, coreB, &lanesA, &lanesB, cache, &pointA, &pointB, &touching, &hitIterationCap);
	cd2ClosestPoints result = AddRadii(pointA, pointB, touching, coreA->radius, coreB->radius);
	if (status != NULL)
	{
		status->iterations = iterations;
		status->hitIterationCap = hitIterationCap;
	}
	return result;
}

/* Closed-form distances: the pair table's Distance column (pairs2.h) when it names a function
 * instead of GJK. Each gives GJK's answer on the pair's cores bit for bit (test_distance2 checks
 * it) without building the cores: two circles are two points, whose closest points are
 * themselves. */
static cd2ClosestPoints DistanceCircleCircle(cd2Circle a, cd2Circle b)
{
	/* GJK's one-vertex simplex: its touching test, and its closest points as weighted sums from
	 * zero (0 + 1 * centre, which turns -0 into +0). */
	cd2Vec w = cd2MulAdd(CD2_VEC_ZERO, CD_R(1.0), cd2Sub(a.center, b.center));
	cdReal touch = GJK_TOUCH_TOLERANCE * CD_R(1.4142136) * cd2MaxAbs(w);
	bool touching = cd2LengthSquared(w) <= touch * touch;
	cd2Vec pointA = cd2MulAdd(CD2_VEC_ZERO, CD_R(1.0), a.center);
	cd2Vec pointB = cd2MulAdd(CD2_VEC_ZERO, CD_R(1.0), b.center);
	return AddRadii(pointA, pointB, touching, a.radius, b.radius);
}

static cd2ClosestPoints SwapPoints(cd2ClosestPoints result)
{
	cd2ClosestPoints swapped = {result.pointB, result.pointA, result.distance};
	return swapped;
}

cd2ClosestPoints cd2DistanceCached(const cd2Shape* a, const cd2Shape* b, cd2SimplexCache* cache,
								   cdDistanceStatus* status)
{
	if (status != NULL)
	{
		status->iterations = 0;
		status->hitIterationCap = false;
	}
	CD_ASSERT(a != NULL && b != NULL);
	if (cache == NULL && status == NULL)
	{
		/* The pairs with a closed form (the Distance column names it), in either order. */
#define CD2_DISTANCE_CASE(A, B, Distance)                                                                    \
	if (a->type == CD2_TYPE_##A && b->type == CD2_TYPE_##B)                                                  \
	{                                                                                                        \
		return Distance(CD2_SHAPE_ARG(A, a), CD2_SHAPE_ARG(B, b));                                           \
	}                                                                                                        \
	if (CD2_TYPE_##A != CD2_TYPE_##B && a->type == CD2_TYPE_##B && b->type == CD2_TYPE_##A)                  \
	{                                                                                                        \
		return SwapPoints(Distance(CD2_SHAPE_ARG(A, b), CD2_SHAPE_ARG(B, a)));                               \
	}
#define CD2_DISTANCE_ROW(A, B, Overlap, Distance, Collide)                                                   \
	CD_PAIR_CLOSED(Distance, CD2_DISTANCE_CASE)(A, B, Distance)
		CD2_PAIR_TABLE(CD2_DISTANCE_ROW)
#undef CD2_DISTANCE_ROW
#undef CD2_DISTANCE_CASE
	}
	cd2Core coreA, coreB;
	if (!cd2MakeCore(a, &coreA) || !cd2MakeCore(b, &coreB))
	{
		CD_ASSERT(false);
		cd2ClosestPoints none = {CD2_VEC_ZERO, CD2_VEC_ZERO, CD_REAL_MAX};
		return none;
	}
	return cd2DistanceCores(&coreA, &coreB, cache, status);
}

cd2ClosestPoints cd2DistanceLocal(const cd2Shape* a, const cd2Shape* b, cd2Transform xfB)
{
	CD_ASSERT(a != NULL && b != NULL);
	cd2Core coreA, coreB;
	if (!cd2MakeCore(a, &coreA) || !cd2MakeCore(b, &coreB))
	{
		CD_ASSERT(false);
		cd2ClosestPoints none = {CD2_VEC_ZERO, CD2_VEC_ZERO, CD_REAL_MAX};
		return none;
	}
	/* Only B's core points move into A's frame (no copy of the shape, its normals or centroid),
	 * straight into the lanes of its supports where the build has them. */
	cd2Vec placed[CD2_CORE_MAX_POINTS];
	cd2CoreLanes lanesA, lanesB;
	cd2MakeCoreLanes(&coreA, &lanesA);
#if CD2_SEPARATION_SSE
	cd2MakePlacedCoreLanes(&coreB, xfB, placed, &lanesB);
	coreB.points = placed;
#else
	for (int i = 0; i < coreB.count; ++i)
	{
		placed[i] = cd2TransformPoint(xfB, coreB.points[i]);
	}
	coreB.points = placed;
	cd2MakeCoreLanes(&coreB, &lanesB);
#endif
	cd2Vec pointA, pointB;
	bool touching, hitIterationCap;
	GjkCoresLanes(&coreA, &coreB, &lanesA, &lanesB, NULL, &pointA, &pointB, &touching, &hitIterationCap);
	return AddRadii(pointA, pointB, touching, coreA.radius, coreB.radius);
}
