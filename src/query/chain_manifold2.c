/* collide: a one-sided chain segment (shape A) against a polygon (rounded or not), a capsule or a
 * circle (shape B).
 *
 * The answer is the one manifold2.c gives (see the comment at its top): the segment's two-sided
 * core against the polygon's core by the separating axis test, the closest-feature path for cores
 * apart by more than a tenth of a linear slop, then the chain's check of the normal against the
 * directions the ghosts allow, falling back to the contact seen from the segment's own face. The
 * same decisions are taken in the same order with the same tolerances, so points, separations,
 * normals and feature ids match; what changes is the work:
 * - the segment's two normals need no core: one pass over the polygon's vertices gives its two
 *   separations and the polygon's own;
 * - clipping is written once per reference side: the segment's face (the polygon's edge facing
 *   it is incident) or a polygon edge (the segment is incident);
 * - where a separating axis keeps the two cores clearly apart (by more than the round-off of the
 *   orientation tests), the closest points come from the four-candidate segment-segment test:
 *   no crossing to look for. The candidates, their order and the search over the edges are the
 *   generic path's, so its choices on near ties are kept. */
#include "chain_manifold2.h"
#include "incident_tie2.h"

/* The tolerances of manifold2.c, which this routine must follow to take the same decisions. */
#define SEPARATED_SLOPS CD_R(0.1)
#define FLIP_SLOPS CD_R(0.1)
#define CHAIN_FLAT_TOLERANCE CD_R(1.0e-4)
#define VERTEX_FEATURE 0x100u
#define CODE_VERTEX_VERTEX 4u
#define CODE_EDGE_A 1u
#define CODE_EDGE_B 2u

/* The shape's core: a polygon's own arrays, or a capsule's segment as a two-sided core of two
 * vertices with the normals n and -n (its radius rounds it either way). */
typedef struct Core
{
	const cd2Vec* vertices;
	const cd2Vec* normals;
	int count;
	cdReal radius;
} Core;

typedef struct Pair
{
	cd2Vec p1, p2;
	cd2Vec n; /* the segment's front normal (unit); its back normal is -n */
	const Core* polygon;
	cdReal speculativeDistance;
	/* The shape is a segment core (a capsule): two segments always take the closest-feature path
	 * (collinear ones are apart along their common direction, which is neither one's normal). */
	bool segments;
} Pair;

static cd2Manifold EmptyManifold(void)
{
	cd2Manifold manifold = {{CD_R(0.0), CD_R(0.0)}, {{{CD_R(0.0), CD_R(0.0)}, CD_R(0.0), 0u}}, 0};
	return manifold;
}

static void AddPoint(cd2Manifold* manifold, cd2Vec point, cdReal separation, uint32_t id)
{
	cd2ManifoldPoint* p = &manifold->points[manifold->pointCount++];
	p->point = point;
	p->separation = separation;
	p->id = id;
}

static cdReal SmallestSeparation(const cd2Manifold* manifold)
{
	cdReal smallest = CD_REAL_MAX;
	for (int i = 0; i < manifold->pointCount; ++i)
	{
		smallest = cdMin(smallest, manifold->points[i].separation);
	}
	return smallest;
}

/* A bound on the rounding of positions along an edge computed from these points. */
static cdReal RoundingSlack(cd2Vec p, cd2Vec q, cd2Vec r)
{
	cdReal magnitude = cdAbs(p.x) + cdAbs(p.y) + cdAbs(q.x) + cdAbs(q.y) + cdAbs(r.x) + cdAbs(r.y);
	return CD_R(8.0) * CD_REAL_EPSILON * magnitude;
}

static int NextVertex(const Core* polygon, int i)
{
	return i + 1 < polygon->count ? i + 1 : 0;
}

/* ---- clipping --------------------------------------------------------------------------------- */

/* The reference edge v1 -> v2 (outward unit normal n, rounded by referenceRadius) against the
 * incident core edge core0 -> core1 (rounded by incidentRadius along incidentNormal): the clip of
 * manifold2.c, step for step (its comments explain the choices). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void
ClipEdges(cd2Manifold* manifold, cd2Vec n, cd2Vec v1, cd2Vec v2, cdReal referenceRadius, cd2Vec core0,
		  cd2Vec core1, cd2Vec incidentNormal, cdReal incidentRadius, uint32_t base, bool flip,
		  cdReal speculativeDistance, bool keepOutside)
{
	/* Scalars, not two-element arrays indexed by a variable: those lived on the stack. */
	*manifold = EmptyManifold();
	cd2Vec offset = cd2Scale(incidentRadius, incidentNormal);
	cd2Vec w0 = cd2Add(core0, offset), w1 = cd2Add(core1, offset);
	uint32_t code0 = 0u, code1 = 1u;

	cd2Vec tangent = cd2LeftPerp(n);
	cdReal upper = cd2Dot(tangent, cd2Sub(v2, v1));
	cdReal along0 = cd2Dot(tangent, cd2Sub(w0, v1)), along1 = cd2Dot(tangent, cd2Sub(w1, v1));
	int pointCount = 2;
	if ((along0 < CD_R(0.0) && along1 < CD_R(0.0)) || (along0 > upper && along1 > upper))
	{
		if (!keepOutside)
		{
			return;
		}
		/* Beyond one side line: the core end nearer to the reference edge's extent, the deeper one
		 * on a tie within round-off. */
		bool below = along0 < CD_R(0.0);
		cdReal position0 = cd2Dot(tangent, cd2Sub(core0, v1)), position1 = cd2Dot(tangent, cd2Sub(core1, v1));
		cdReal beyond0 = cdMax(below ? -position0 : position0 - upper, CD_R(0.0));
		cdReal beyond1 = cdMax(below ? -position1 : position1 - upper, CD_R(0.0));
		bool keepSecond;
		if (cdAbs(beyond0 - beyond1) <= RoundingSlack(core0, core1, v1))
		{
			keepSecond = cd2Dot(n, cd2Sub(core0, core1)) > CD_R(0.0);
		}
		else
		{
			keepSecond = !(beyond0 < beyond1);
		}
		if (keepSecond)
		{
			w0 = w1;
			core0 = core1;
			code0 = code1;
		}
		pointCount = 1;
	}
	else
	{
		/* along0 != along1 here: one end is inside the extent, the other outside it. */
		cd2Vec clipped0 = w0, clipped1 = w1;
		if (along0 < CD_R(0.0))
		{
			clipped0 = cd2Lerp(w0, w1, (CD_R(0.0) - along0) / (along1 - along0));
			code0 = 2u;
		}
		else if (along0 > upper)
		{
			clipped0 = cd2Lerp(w0, w1, (upper - along0) / (along1 - along0));
			code0 = 3u;
		}
		if (along1 < CD_R(0.0))
		{
			clipped1 = cd2Lerp(w1, w0, (CD_R(0.0) - along1) / (along0 - along1));
			code1 = 2u;
		}
		else if (along1 > upper)
		{
			clipped1 = cd2Lerp(w1, w0, (upper - along1) / (along0 - along1));
			code1 = 3u;
		}
		w0 = clipped0;
		w1 = clipped1;
	}

	/* The deepest core vertex's surface point straight against n, when it stays over the edge. */
	bool deepestSecond = pointCount == 2 && cd2Dot(n, cd2Sub(core0, core1)) > CD_R(0.0);
	cd2Vec straight = cd2MulSub(deepestSecond ? core1 : core0, incidentRadius, n);
	cdReal t = cd2Dot(tangent, cd2Sub(straight, v1));
	bool over = pointCount == 1 || (CD_R(0.0) <= t && t <= upper);
	if (!over)
	{
		cdReal slack = RoundingSlack(straight, v1, v2);
		over = -slack <= t && t <= upper + slack;
	}
	if (over)
	{
		if (deepestSecond)
		{
			w1 = straight;
			code1 = 1u;
		}
		else
		{
			w0 = straight;
			code0 = pointCount == 1 ? code0 : 0u;
		}
	}

	cdReal separation0 = cd2Dot(n, cd2Sub(w0, v1)) - referenceRadius;
	if (separation0 <= speculativeDistance)
	{
		AddPoint(manifold, cd2MulSub(w0, CD_R(0.5) * separation0, n), separation0, base | code0 << 16);
	}
	if (pointCount == 2)
	{
		cdReal separation1 = cd2Dot(n, cd2Sub(w1, v1)) - referenceRadius;
		if (separation1 <= speculativeDistance)
		{
			AddPoint(manifold, cd2MulSub(w1, CD_R(0.5) * separation1, n), separation1, base | code1 << 16);
		}
	}
	if (manifold->pointCount > 0)
	{
		manifold->normal = flip ? cd2Neg(n) : n;
	}
}

/* The segment's face is the reference: side 0 is the front (p1 -> p2, normal n), side 1 the back
 * (p2 -> p1, normal -n); the polygon's edge facing it most is incident. */
static void ClipOnSegment(cd2Manifold* manifold, const Pair* pair, int side, bool keepOutside)
{
	const Core* polygon = pair->polygon;
	cd2Vec n = side == 0 ? pair->n : cd2Neg(pair->n);
	int incident = 0;
	cdReal lowest = CD_REAL_MAX;
	for (int i = 0; i < polygon->count; ++i)
	{
		cdReal d = cd2Dot(n, polygon->normals[i]);
		bool lower = d < lowest;
		incident = lower ? i : incident;
		lowest = lower ? d : lowest;
	}
	cd2Vec v1 = side == 0 ? pair->p1 : pair->p2;
	cd2Vec v2 = side == 0 ? pair->p2 : pair->p1;
	if (polygon->count > 2)
	{
		/* The tie rule of manifold2.c's clipping (incident_tie2.h), on the same surface ends. */
		cd2Vec tangent = cd2LeftPerp(n);
		cdReal upper = cd2Dot(tangent, cd2Sub(v2, v1));
		cd2Vec shift = cd2Scale(polygon->radius, polygon->normals[incident]);
		cdReal along0 = cd2Dot(tangent, cd2Sub(cd2Add(polygon->vertices[incident], shift), v1));
		cdReal along1 =
			cd2Dot(tangent, cd2Sub(cd2Add(polygon->vertices[NextVertex(polygon, incident)], shift), v1));
		if ((along0 < CD_R(0.0) && along1 < CD_R(0.0)) || (along0 > upper && along1 > upper))
		{
			incident = cd2TiedIncidentEdge(polygon->vertices, polygon->normals, polygon->count, n, lowest,
										   incident, tangent, v1, upper);
		}
	}
	uint32_t base = (uint32_t)side | (uint32_t)incident << 8;
	ClipEdges(manifold, n, v1, v2, CD_R(0.0), polygon->vertices[incident],
			  polygon->vertices[NextVertex(polygon, incident)], polygon->normals[incident], polygon->radius,
			  base, false, pair->speculativeDistance, keepOutside);
}

/* A polygon edge is the reference; the segment's side facing it is incident. */
static void ClipOnPolygon(cd2Manifold* manifold, const Pair* pair, int edge, bool keepOutside)
{
	const Core* polygon = pair->polygon;
	cd2Vec n = polygon->normals[edge];
	/* The back side (normal -n) faces n more exactly when the front one faces away from it. */
	int incident = cd2Dot(n, pair->n) > CD_R(0.0) ? 1 : 0;
	cd2Vec core0 = incident == 0 ? pair->p1 : pair->p2;
	cd2Vec core1 = incident == 0 ? pair->p2 : pair->p1;
	cd2Vec incidentNormal = incident == 0 ? pair->n : cd2Neg(pair->n);
	uint32_t base = (uint32_t)edge | (uint32_t)incident << 8 | CD2_FEATURE_FLIP;
	ClipEdges(manifold, n, polygon->vertices[edge], polygon->vertices[NextVertex(polygon, edge)],
			  polygon->radius, core0, core1, incidentNormal, CD_R(0.0), base, true, pair->speculativeDistance,
			  keepOutside);
}

/* ---- closest features of cores that are apart ------------------------------------------------- */

static int EndpointIndex(cd2Vec first, cd2Vec second, int edge, int next, cd2Vec p)
{
	if (cd2VecEqual(p, first))
	{
		return edge;
	}
	return cd2VecEqual(p, second) ? next : -1;
}

static int SegmentEndpoint(const Pair* pair, cd2Vec p)
{
	return cd2VecEqual(p, pair->p1) ? 0 : cd2VecEqual(p, pair->p2) ? 1 : -1;
}

static int PolygonEndpoint(const Core* polygon, int edge, cd2Vec p)
{
	int next = NextVertex(polygon, edge);
	return EndpointIndex(polygon->vertices[edge], polygon->vertices[next], edge, next, p);
}

static cd2Segment PolygonEdge(const Core* polygon, int edge)
{
	cd2Segment segment = {polygon->vertices[edge], polygon->vertices[NextVertex(polygon, edge)]};
	return segment;
}

static cd2Segment SegmentSide(const Pair* pair, int side)
{
	cd2Segment segment = {side == 0 ? pair->p1 : pair->p2, side == 0 ? pair->p2 : pair->p1};
	return segment;
}

/* cd2ClosestPointOnSegment (closest2.c), the same arithmetic in this file so that it inlines. */
static cd2Vec ClosestOnSegment(cd2Segment g, cd2Vec p)
{
	cd2Vec d = cd2Sub(g.p2, g.p1);
	cdReal lengthSquared = cd2Dot(d, d);
	cdReal t = cd2Dot(cd2Sub(p, g.p1), d);
	if (t <= CD_R(0.0) || lengthSquared <= CD_R(0.0))
	{
		return g.p1;
	}
	if (t >= lengthSquared)
	{
		return g.p2;
	}
	return cd2MulAdd(g.p1, t / lengthSquared, d);
}

/* cd2ClosestPointsSegmentSegment(a, b) for segments that do not cross because b lies on one side
 * of a's line (neither end strictly on the other side): the same candidates in the same order,
 * without the orientation tests that look for a crossing. */
static cd2ClosestPoints ClosestNotCrossing(cd2Segment a, cd2Segment b)
{
	/* Scalars in the candidates' order (a's ends, then b's), the first strict least kept. */
	cd2Vec onB1 = ClosestOnSegment(b, a.p1), onB2 = ClosestOnSegment(b, a.p2);
	cd2Vec onA1 = ClosestOnSegment(a, b.p1), onA2 = ClosestOnSegment(a, b.p2);
	cd2ClosestPoints result = {a.p1, onB1, CD_R(0.0)};
	cdReal best = cd2VecDistanceSquared(a.p1, onB1);
	cdReal s = cd2VecDistanceSquared(a.p2, onB2);
	if (s < best)
	{
		best = s;
		result.pointA = a.p2;
		result.pointB = onB2;
	}
	s = cd2VecDistanceSquared(onA1, b.p1);
	if (s < best)
	{
		best = s;
		result.pointA = onA1;
		result.pointB = b.p1;
	}
	s = cd2VecDistanceSquared(onA2, b.p2);
	if (s < best)
	{
		best = s;
		result.pointA = onA2;
		result.pointB = b.p2;
	}
	result.distance = cdSqrt(best);
	return result;
}

/* The search of the generic path over the core's edges for a core wholly and clearly on the front
 * of the segment's side `side` (size: the coordinate differences' extent): the four-candidate
 * test per edge, and the answer the generic path's scan in edge order gives (the smallest
 * distance, the first edge on a tie). Edges are visited from the one ending at the lowest vertex,
 * whose distance is near the answer, and an edge is skipped when its lower vertex stands higher
 * above the line than the best distance so far by more than the rounding of the candidates'
 * distances and of the heights (64 epsilons of the coordinates' size): every candidate of it is
 * then farther than the best, so it can neither win nor tie. For a box resting just above the
 * segment that skips the top edge and usually the far side. */
static cd2ClosestPoints ClosestClearSide(const Pair* pair, cd2Segment side, int sideIndex, cdReal size,
										 int* edgeB)
{
	const Core* polygon = pair->polygon;
	int count = polygon->count;
	cd2Vec normal = sideIndex == 0 ? pair->n : cd2Neg(pair->n);
	cdReal heights[CD2_MAX_POLYGON_VERTICES] = {CD_R(0.0)};
	int lowest = 0;
	for (int j = 0; j < count; ++j)
	{
		heights[j] = cd2Dot(normal, cd2Sub(polygon->vertices[j], side.p1));
		lowest = heights[j] < heights[lowest] ? j : lowest;
	}
	cdReal margin = CD_R(32.0) * CD_REAL_EPSILON * (cdAbs(side.p1.x) + cdAbs(side.p1.y) + size);
	int first = lowest == 0 ? count - 1 : lowest - 1;
	/* Each vertex's candidate (its projection on the side) serves the two edges it ends. */
	cd2Vec projections[CD2_MAX_POLYGON_VERTICES];
	cdReal squares[CD2_MAX_POLYGON_VERTICES];
	for (int j = 0; j < count; ++j)
	{
		projections[j] = ClosestOnSegment(side, polygon->vertices[j]);
		squares[j] = cd2VecDistanceSquared(projections[j], polygon->vertices[j]);
	}
	cd2ClosestPoints best = {{CD_R(0.0), CD_R(0.0)}, {CD_R(0.0), CD_R(0.0)}, CD_REAL_MAX};
	int bestEdge = count;
	for (int k = 0; k < count; ++k)
	{
		int i = k == 0 ? first : (k <= first ? k - 1 : k); /* first, then the others in order */
		int next = NextVertex(polygon, i);
		if (k > 0 && cdMin(heights[i], heights[next]) - margin > best.distance)
		{
			continue;
		}
		/* ClosestNotCrossing(side, edge i): the candidates in its order, the first strict least. */
		cd2Segment edge = PolygonEdge(polygon, i);
		cd2Vec onEdge1 = ClosestOnSegment(edge, side.p1), onEdge2 = ClosestOnSegment(edge, side.p2);
		cd2Vec pointA = side.p1, pointB = onEdge1;
		cdReal square = cd2VecDistanceSquared(side.p1, onEdge1);
		cdReal s1 = cd2VecDistanceSquared(side.p2, onEdge2);
		if (s1 < square)
		{
			square = s1;
			pointA = side.p2;
			pointB = onEdge2;
		}
		if (squares[i] < square)
		{
			square = squares[i];
			pointA = projections[i];
			pointB = polygon->vertices[i];
		}
		if (squares[next] < square)
		{
			square = squares[next];
			pointA = projections[next];
			pointB = polygon->vertices[next];
		}
		cdReal distance = cdSqrt(square);
		if (distance < best.distance || (distance == best.distance && i < bestEdge))
		{
			best.pointA = pointA;
			best.pointB = pointB;
			best.distance = distance;
			bestEdge = i;
		}
	}
	*edgeB = bestEdge;
	return best;
}

/* The closest points of the two cores (pointA on the segment) and the edges holding them (in: the
 * max-separation edges), as manifold2.c's ClosestCores finds them. */
static cd2ClosestPoints ClosestCores(const Pair* pair, cdReal separationA, cdReal separationB, int* edgeA,
									 int* edgeB)
{
	const Core* polygon = pair->polygon;
	/* The cores are apart along an axis by clearly more than the round-off of the orientation
	 * tests: the edge that gives it has the other core's edge wholly on one side of its line, so the
	 * segment-segment test finds no crossing and its four candidates suffice. Those tests and the
	 * separations share the differences of the coordinates (rounded alike in both); what differs is
	 * rounded relative to the differences' size, bounded here by the segment, the polygon edge and
	 * the offset between them. */
	cd2Vec d = cd2Sub(pair->p2, pair->p1);
	cd2Vec e = cd2Sub(polygon->vertices[NextVertex(polygon, *edgeB)], polygon->vertices[*edgeB]);
	cd2Vec offset = cd2Sub(polygon->vertices[*edgeB], pair->p1);
	cdReal scale = cdAbs(d.x) + cdAbs(d.y) + cdAbs(e.x) + cdAbs(e.y) + cdAbs(offset.x) + cdAbs(offset.y);
	bool clear = cdMax(separationA, separationB) > CD_R(64.0) * CD_REAL_EPSILON * scale;
	if (separationA > CD_R(0.0) && separationB > CD_R(0.0))
	{
		cd2Segment side = SegmentSide(pair, *edgeA), edge = PolygonEdge(polygon, *edgeB);
		return clear ? ClosestNotCrossing(side, edge) : cd2ClosestPointsSegmentSegment(side, edge);
	}
	if (separationA >= separationB)
	{
		/* The segment's side separates the whole core: no core edge crosses its line, so the
		 * four-candidate test stands for the segment-segment test against each edge when that
		 * separation clearly exceeds the round-off of the orientation tests, here relative to the
		 * farthest vertex. The generic path's search, candidate for candidate and edge for edge:
		 * its choices on near ties (which end of a capsule, which vertex of a flat bottom) are
		 * the same. A core crossing or touching the line (a capsule) takes the full test. */
		cd2Segment side = SegmentSide(pair, *edgeA);
		bool sideClear = false;
		cdReal size = CD_R(0.0);
		if (separationA > CD_R(0.0))
		{
			cdReal farthest = CD_R(0.0);
			for (int j = 0; j < polygon->count; ++j)
			{
				cd2Vec r = cd2Sub(polygon->vertices[j], side.p1);
				farthest = cdMax(farthest, cdAbs(r.x) + cdAbs(r.y));
			}
			size = cdAbs(d.x) + cdAbs(d.y) + farthest;
			sideClear = separationA > CD_R(64.0) * CD_REAL_EPSILON * size;
		}
		if (sideClear)
		{
			return ClosestClearSide(pair, side, *edgeA, size, edgeB);
		}
		cd2ClosestPoints best = cd2ClosestPointsSegmentSegment(side, PolygonEdge(polygon, 0));
		*edgeB = 0;
		for (int i = 1; i < polygon->count; ++i)
		{
			cd2ClosestPoints candidate = cd2ClosestPointsSegmentSegment(side, PolygonEdge(polygon, i));
			if (candidate.distance < best.distance)
			{
				best = candidate;
				*edgeB = i;
			}
		}
		return best;
	}
	/* The polygon's edge separates more: its closest feature is on that edge. Both sides of the
	 * segment (the same points in either order) are tried, as the generic path does: they differ
	 * only by rounding, which decides near a crossing (a capsule's end on the segment's end at
	 * coordinates of 1e9 is 6e-4 away one way and 6e-10 the other). */
	cd2Segment edge = PolygonEdge(polygon, *edgeB), front = SegmentSide(pair, 0), back = SegmentSide(pair, 1);
	cd2ClosestPoints closest =
		clear ? ClosestNotCrossing(edge, front) : cd2ClosestPointsSegmentSegment(edge, front);
	cd2ClosestPoints reversed =
		clear ? ClosestNotCrossing(edge, back) : cd2ClosestPointsSegmentSegment(edge, back);
	*edgeA = 0;
	if (reversed.distance < closest.distance)
	{
		closest = reversed;
		*edgeA = 1;
	}
	cd2Vec swap = closest.pointA;
	closest.pointA = closest.pointB;
	closest.pointB = swap;
	return closest;
}

/* One point along the gap between the closest points, normal from the segment to the polygon. */
static void GapContact(cd2Manifold* manifold, const Pair* pair, cd2ClosestPoints closest, int edgeA,
					   int edgeB)
{
	*manifold = EmptyManifold();
	cd2Vec u = cd2GetLengthAndNormalize(&closest.distance, cd2Sub(closest.pointB, closest.pointA));
	if (u.x == CD_R(0.0) && u.y == CD_R(0.0))
	{
		return;
	}
	const Core* polygon = pair->polygon;
	int vertexA = SegmentEndpoint(pair, closest.pointA);
	int vertexB = PolygonEndpoint(polygon, edgeB, closest.pointB);
	cd2Vec onB = cd2MulSub(closest.pointB, polygon->radius, u);
	uint32_t featureA = vertexA >= 0 ? (uint32_t)vertexA : (uint32_t)edgeA;
	uint32_t featureB = vertexB >= 0 ? (uint32_t)vertexB : (uint32_t)edgeB;
	uint32_t code = CODE_VERTEX_VERTEX + (vertexA < 0 ? CODE_EDGE_A : 0u) + (vertexB < 0 ? CODE_EDGE_B : 0u);
	manifold->normal = u;
	AddPoint(manifold, cd2Scale(CD_R(0.5), cd2Add(closest.pointA, onB)), closest.distance - polygon->radius,
			 featureA | featureB << 8 | code << 16);
}

/* ---- the two-sided segment core against the polygon ------------------------------------------- */

/* Writes the manifold in place (*out): returned by value through the callers, the copies cost
 * store-forwarding stalls. */
static void CollideCores(const Pair* pair, cd2Manifold* out)
{
	const Core* polygon = pair->polygon;
	const cd2Vec* vertices = polygon->vertices;
	const cd2Vec* normals = polygon->normals;
	int count = polygon->count;
	cdReal total = polygon->radius;
	cdReal speculativeDistance = pair->speculativeDistance;
	cdReal limit = total + speculativeDistance;
	cd2Vec p1 = pair->p1, p2 = pair->p2, n = pair->n;

	/* One pass over the polygon for the three separations: the segment's front normal (the
	 * polygon's lowest vertex above the line), its back normal (measured from p2, as the generic
	 * core does) and the polygon's edge normals (the segment's lower end against each edge). The
	 * generic core stops a scan early once it can no longer win or is beyond the limit; the
	 * answers are the same when the full scans are compared after the loop, which has no branch
	 * to mispredict (selects, not branches: which vertex is lowest is data, not a pattern). */
	cd2Vec back = cd2Neg(n);
	cdReal separationA = CD_REAL_MAX, separationBack = CD_REAL_MAX, separationB = -CD_REAL_MAX;
	int edgeB = 0;
	for (int j = 0; j < count; ++j)
	{
		cd2Vec v = vertices[j];
		separationA = cdMin(separationA, cd2Dot(n, cd2Sub(v, p1)));
		separationBack = cdMin(separationBack, cd2Dot(back, cd2Sub(v, p2)));
		cdReal s = cdMin(cd2Dot(normals[j], cd2Sub(p1, v)), cd2Dot(normals[j], cd2Sub(p2, v)));
		bool higher = s > separationB;
		edgeB = higher ? j : edgeB;
		separationB = higher ? s : separationB;
	}
	int edgeA = 0;
	if (separationBack > separationA)
	{
		separationA = separationBack;
		edgeA = 1;
	}
	if (separationA > limit || separationB > limit)
	{
		*out = EmptyManifold();
		return;
	}

	cdReal slop = CD_LINEAR_SLOP;
	cdReal separatedTolerance = SEPARATED_SLOPS * slop;
	cd2ClosestPoints closest = {{CD_R(0.0), CD_R(0.0)}, {CD_R(0.0), CD_R(0.0)}, CD_R(0.0)};
	int closestEdgeA = edgeA, closestEdgeB = edgeB;
	bool haveClosest = false;
	cdReal largest = cdMax(separationA, separationB);
	if (pair->segments || largest > separatedTolerance)
	{
		closest = ClosestCores(pair, separationA, separationB, &closestEdgeA, &closestEdgeB);
		haveClosest = true;
		if (closest.distance > separatedTolerance)
		{
			if (closest.distance - total > speculativeDistance)
			{
				*out = EmptyManifold();
				return;
			}
			int vertexA = SegmentEndpoint(pair, closest.pointA);
			int vertexB = PolygonEndpoint(polygon, closestEdgeB, closest.pointB);
			if (vertexA < 0 || vertexB < 0)
			{
				if (vertexA < 0)
				{
					/* The segment side facing the gap u = gap / distance. Scaling by 1 / distance keeps
					 * the sign of the dot product unless it is within rounding of zero: only then is u
					 * formed. */
					cd2Vec gap = cd2Sub(closest.pointB, closest.pointA);
					cdReal facing = cd2Dot(n, gap);
					if (cdAbs(facing) <= CD_R(8.0) * CD_REAL_EPSILON * (cdAbs(gap.x) + cdAbs(gap.y)))
					{
						facing = cd2Dot(n, cd2Scale(CD_R(1.0) / closest.distance, gap));
					}
					ClipOnSegment(out, pair, facing >= CD_R(0.0) ? 0 : 1, false);
				}
				else
				{
					/* The shape's face holding its closest point; of a capsule's two-sided core, the
					 * side facing the gap (against u), as the generic path picks it. A polygon face
					 * whose normal does not face the segment is not what is closest (the closest
					 * points tie between edges at coordinates whose round-off exceeds the shapes'
					 * sizes): the generic path then takes the gap contact, and so does this one. */
					cd2Vec u = cd2Scale(CD_R(1.0) / closest.distance, cd2Sub(closest.pointB, closest.pointA));
					int face = closestEdgeB;
					if (pair->segments)
					{
						face = cd2Dot(polygon->normals[0], cd2Neg(u)) >= CD_R(0.0) ? 0 : 1;
					}
					if (cd2Dot(polygon->normals[face], u) <= CD_R(0.0))
					{
						ClipOnPolygon(out, pair, face, false);
					}
					else
					{
						out->pointCount = 0;
					}
				}
				if (out->pointCount > 0 &&
					SmallestSeparation(out) <= closest.distance - total + separatedTolerance)
				{
					return;
				}
			}
			GapContact(out, pair, closest, closestEdgeA, closestEdgeB);
			return;
		}
	}

	cdReal flipTolerance = FLIP_SLOPS * slop;
	bool flip = separationB > separationA + flipTolerance;
	if (flip)
	{
		ClipOnPolygon(out, pair, edgeB, false);
	}
	else
	{
		ClipOnSegment(out, pair, edgeA, false);
	}
	if (out->pointCount == 0 && !flip && separationB >= separationA - flipTolerance)
	{
		ClipOnPolygon(out, pair, edgeB, false);
	}
	bool keptOutside = out->pointCount == 0;
	if (keptOutside)
	{
		if (flip)
		{
			ClipOnPolygon(out, pair, edgeB, true);
		}
		else
		{
			ClipOnSegment(out, pair, edgeA, true);
		}
	}
	bool apart = pair->segments || largest > CD_R(0.0);
	if (!apart)
	{
		return;
	}
	bool missed =
		keptOutside || out->pointCount == 0 || SmallestSeparation(out) > largest - total + separatedTolerance;
	if (missed)
	{
		if (!haveClosest)
		{
			closest = ClosestCores(pair, separationA, separationB, &closestEdgeA, &closestEdgeB);
		}
		if (closest.distance > CD_R(0.0))
		{
			if (closest.distance - total > speculativeDistance)
			{
				*out = EmptyManifold();
				return;
			}
			if (keptOutside || out->pointCount == 0 ||
				SmallestSeparation(out) > closest.distance - total + separatedTolerance)
			{
				cd2Manifold gap;
				GapContact(&gap, pair, closest, closestEdgeA, closestEdgeB);
				if (gap.pointCount > 0 && gap.points[0].separation <= speculativeDistance)
				{
					*out = gap;
				}
			}
		}
	}
}

/* ---- the chain's directions ------------------------------------------------------------------- */

/* The unit direction of the ghost edge `e` when the chain turns left from `from` to it (a convex
 * corner) by more than the flat tolerance, in the order given (first: the turn's first direction);
 * zero otherwise. A turn that is clearly flat or concave is told without the square root (the sine
 * times |e| against the tolerance, squared, with a factor 2 of room for the round-off of the test
 * on the normalized edge that decides the close cases). */
static cd2Vec ConvexGhostDirection(cd2Vec first, cd2Vec second, bool ghostIsSecond)
{
	cd2Vec zero = {CD_R(0.0), CD_R(0.0)};
	cd2Vec e = ghostIsSecond ? second : first;
	cdReal c = cd2Cross(first, second);
	if (c <= CD_R(0.0) || CD_R(2.0) * c * c < CHAIN_FLAT_TOLERANCE * CHAIN_FLAT_TOLERANCE * cd2Dot(e, e))
	{
		return zero;
	}
	cd2Vec u = cd2Normalize(e);
	bool convex = ghostIsSecond ? cd2Cross(first, u) > CHAIN_FLAT_TOLERANCE
								: cd2Cross(u, second) > CHAIN_FLAT_TOLERANCE;
	return convex ? u : zero;
}

/* The chain's check of a contact normal m: the segment's own, or at a convex vertex one in the
 * fan up to the neighbour's normal, is allowed; past the neighbour's normal at a convex vertex the
 * contact is dropped (the neighbour reports it); anything else (tilted at a flat or concave vertex,
 * or facing back) is replaced by the contact seen from the segment's face. */
typedef enum NormalCheck
{
	NORMAL_ALLOWED,
	NORMAL_DROPPED,
	NORMAL_FACE
} NormalCheck;

static NormalCheck CheckNormal(const cd2ChainSegment* a, cd2Vec direction, cd2Vec m)
{
	cd2Vec n = cd2RightPerp(direction);
	cdReal side = cd2Cross(n, m); /* > 0: tilted towards p2, < 0: towards p1 */
	if (cd2Dot(m, n) < CD_R(0.0))
	{
		return NORMAL_FACE;
	}
	if (side > CD_R(0.0))
	{
		cd2Vec next = ConvexGhostDirection(direction, cd2Sub(a->ghost2, a->p2), true);
		if (next.x == CD_R(0.0) && next.y == CD_R(0.0))
		{
			return NORMAL_FACE;
		}
		return cd2Cross(m, cd2RightPerp(next)) >= CD_R(0.0) ? NORMAL_ALLOWED : NORMAL_DROPPED;
	}
	if (side < CD_R(0.0))
	{
		cd2Vec previous = ConvexGhostDirection(cd2Sub(a->p1, a->ghost1), direction, false);
		if (previous.x == CD_R(0.0) && previous.y == CD_R(0.0))
		{
			return NORMAL_FACE;
		}
		return cd2Cross(cd2RightPerp(previous), m) >= CD_R(0.0) ? NORMAL_ALLOWED : NORMAL_DROPPED;
	}
	return NORMAL_ALLOWED;
}

/* The chain segment against a polygon or a capsule's segment core; `center` decides the side. */
static void CollideChainSegment(const cd2ChainSegment* a, const Core* core, bool segments, cd2Vec center,
								cdReal speculativeDistance, cd2Manifold* manifold)
{
	cd2Vec direction = cd2Normalize(cd2Sub(a->p2, a->p1));
	if (direction.x == CD_R(0.0) && direction.y == CD_R(0.0))
	{
		*manifold = EmptyManifold();
		return; /* a zero-length chain segment has no side */
	}
	Pair pair;
	pair.p1 = a->p1;
	pair.p2 = a->p2;
	pair.n = cd2RightPerp(direction);
	pair.polygon = core;
	pair.speculativeDistance = speculativeDistance;
	pair.segments = segments;
	if (cd2Dot(pair.n, cd2Sub(center, a->p1)) < CD_R(0.0))
	{
		*manifold = EmptyManifold();
		return; /* behind the one-sided segment */
	}
	CollideCores(&pair, manifold);
	if (manifold->pointCount == 0)
	{
		return;
	}
	NormalCheck check = CheckNormal(a, direction, manifold->normal);
	if (check == NORMAL_DROPPED)
	{
		*manifold = EmptyManifold();
	}
	else if (check == NORMAL_FACE)
	{
		/* Only the segment's own normal is allowed: the contact seen from its face, within its
		 * extent. */
		ClipOnSegment(manifold, &pair, 0, false);
	}
}

static cd2Manifold OnePoint(cd2Vec normal, cd2Vec point, cdReal separation, uint32_t id)
{
	cd2Manifold manifold = {normal, {{point, separation, id}, {{CD_R(0.0), CD_R(0.0)}, CD_R(0.0), 0u}}, 1};
	return manifold;
}

/* The chain segment against a point core (a circle, or a capsule of zero length) whose centre
 * also decides the side (`center`: the capsule's midpoint). The generic path's point-core
 * contact: the segment's normal over its extent, the end vertex's direction beyond it. Returned
 * by value, built in the return slot (no scratch manifold to copy). */
static cd2Manifold CollideChainSegmentPoint(const cd2ChainSegment* a, cd2Vec point, cdReal radius,
											cd2Vec center, cdReal speculativeDistance)
{
	cd2Vec edge = cd2Sub(a->p2, a->p1);
	cd2Vec direction = cd2Normalize(edge);
	if (direction.x == CD_R(0.0) && direction.y == CD_R(0.0))
	{
		return EmptyManifold();
	}
	cd2Vec n = cd2RightPerp(direction);
	if (cd2Dot(n, cd2Sub(center, a->p1)) < CD_R(0.0))
	{
		return EmptyManifold();
	}
	cdReal limit = radius + speculativeDistance;
	/* The segment core's two edges: the front one (normal n from p1) and the back one (-n from p2);
	 * the point's closest feature is on the one it stands farther outside of. */
	cdReal frontSeparation = cd2Dot(n, cd2Sub(point, a->p1));
	if (frontSeparation > limit)
	{
		return EmptyManifold();
	}
	cd2Vec back = cd2LeftPerp(direction);
	cdReal backSeparation = cd2Dot(back, cd2Sub(point, a->p2));
	bool front = !(backSeparation > frontSeparation);
	if (!front && backSeparation > limit)
	{
		return EmptyManifold();
	}
	cd2Vec v1 = front ? a->p1 : a->p2, v2 = front ? a->p2 : a->p1;
	cd2Vec normal = front ? n : back;
	cdReal coreSeparation = front ? frontSeparation : backSeparation;
	uint32_t id = front ? 0u : 1u;
	/* Beyond an end along the normal's own tangent: that vertex's direction. */
	cd2Vec tangent = cd2LeftPerp(normal);
	cdReal along = cd2Dot(tangent, cd2Sub(point, v1));
	int vertex = along <= CD_R(0.0)							? (front ? 0 : 1)
				 : along >= cd2Dot(tangent, cd2Sub(v2, v1)) ? (front ? 1 : 0)
															: -1;
	if (vertex >= 0)
	{
		cdReal distance;
		cd2Vec toPoint = cd2GetLengthAndNormalize(&distance, cd2Sub(point, vertex == 0 ? a->p1 : a->p2));
		if (toPoint.x != CD_R(0.0) || toPoint.y != CD_R(0.0))
		{
			normal = toPoint;
			coreSeparation = distance;
			id = VERTEX_FEATURE | (uint32_t)vertex;
		}
	}
	cdReal separation = coreSeparation - radius;
	if (separation > speculativeDistance)
	{
		return EmptyManifold();
	}
	NormalCheck check = CheckNormal(a, direction, normal);
	if (check == NORMAL_ALLOWED)
	{
		return OnePoint(normal, cd2MulAdd(point, CD_R(0.5) * (CD_R(0.0) - radius - coreSeparation), normal),
						separation, id);
	}
	if (check == NORMAL_DROPPED)
	{
		return EmptyManifold();
	}
	/* The face contact within the segment's extent. */
	cdReal onEdge = cd2Dot(cd2Sub(point, a->p1), edge);
	if (onEdge < CD_R(0.0) || onEdge > cd2Dot(edge, edge))
	{
		return EmptyManifold();
	}
	coreSeparation = cd2Dot(n, cd2Sub(point, a->p1));
	separation = coreSeparation - radius;
	if (separation > speculativeDistance)
	{
		return EmptyManifold();
	}
	return OnePoint(n, cd2MulSub(point, CD_R(0.5) * (radius + coreSeparation), n), separation, 0u);
}

/* Copied field by field into a local whose address is never taken, so that it is built in the
 * caller's return slot: a whole-struct copy of the scratch manifold loads 16 bytes at a time
 * across the narrower stores just made into it, which the store buffer cannot forward (a stall of
 * about a tenth of the polygon routine's time). */
static cd2Manifold Returned(const cd2Manifold* scratch)
{
	cd2Manifold result;
	result.normal.x = scratch->normal.x;
	result.normal.y = scratch->normal.y;
	for (int i = 0; i < 2; ++i)
	{
		result.points[i].point.x = scratch->points[i].point.x;
		result.points[i].point.y = scratch->points[i].point.y;
		result.points[i].separation = scratch->points[i].separation;
		result.points[i].id = scratch->points[i].id;
	}
	result.pointCount = scratch->pointCount;
	return result;
}

cd2Manifold cd2CollideChainSegmentPolygonDirect(const cd2ChainSegment* a, const cd2Polygon* b,
												cdReal speculativeDistance)
{
	CD_ASSERT(a != NULL && b != NULL);
	CD_ASSERT(b->count >= 3 && b->count <= CD2_MAX_POLYGON_VERTICES);
	Core core = {b->vertices, b->normals, b->count, b->radius};
	cd2Manifold scratch;
	CollideChainSegment(a, &core, false, b->centroid, speculativeDistance, &scratch);
	return Returned(&scratch);
}

cd2Manifold cd2CollideChainSegmentCapsuleDirect(const cd2ChainSegment* a, cd2Capsule b,
												cdReal speculativeDistance)
{
	CD_ASSERT(a != NULL);
	cd2Vec center = cd2Lerp(b.p1, b.p2, CD_R(0.5));
	cd2Vec direction = cd2Normalize(cd2Sub(b.p2, b.p1));
	if (direction.x == CD_R(0.0) && direction.y == CD_R(0.0))
	{
		return CollideChainSegmentPoint(a, b.p1, b.radius, center, speculativeDistance);
	}
	cd2Vec vertices[2] = {b.p1, b.p2};
	cd2Vec normals[2] = {cd2RightPerp(direction), cd2LeftPerp(direction)};
	Core core = {vertices, normals, 2, b.radius};
	cd2Manifold scratch;
	CollideChainSegment(a, &core, true, center, speculativeDistance, &scratch);
	return Returned(&scratch);
}

cd2Manifold cd2CollideChainSegmentCircleDirect(const cd2ChainSegment* a, cd2Circle b,
											   cdReal speculativeDistance)
{
	CD_ASSERT(a != NULL);
	return CollideChainSegmentPoint(a, b.center, b.radius, b.center, speculativeDistance);
}
