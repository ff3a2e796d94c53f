/* collide: 2D contact manifolds.
 *
 * Every shape becomes a rounded convex core: a point (circle), a two-sided segment (capsule,
 * segment, zero-width box) or a polygon, grown by a radius. Three routines cover all pairs:
 * - point against core: the closest feature of the core, one point;
 * - core against core: the separating axis test over both cores' edge normals finds the
 *   reference edge (A's unless B's separates by more than a tolerance, so the choice does not
 *   flicker); the incident edge of the other core, the one facing it most, is clipped to the
 *   reference edge's side lines and its points below the speculative distance are kept. When the
 *   cores are apart, the closest points of the two max-separation edges decide between a face
 *   contact (clip as above, when a closest point lies inside an edge and the clip keeps points
 *   over that face) and one point along the gap, normal along it (vertex against vertex, or a
 *   face that is not what is closest): the separation along a direction is unimodal where it is
 *   positive, so a core whose max separation is positive has its closest feature on its
 *   max-separation edge; the other core's edges are all searched when its own max separation is
 *   not positive. Either way every point lies midway between the two surfaces along the
 *   manifold's normal (manifold2.h), far speculative contacts included.
 * - chain segment: the two-sided segment's manifold, with its normal checked against the
 *   directions the chain allows (see cd2ChainSegment).
 * Points are reported midway between the surfaces; the normal points from A to B. */
#include "collide/manifold2.h"

#include "incident_tie2.h"
#include "pairs2.h"
#include "sat2_separation.h"

#include <stddef.h>
#include <string.h>

/* Cores apart by more than this many linear slops take the closest-feature path (and
 * vertex-vertex normals are then safe to normalize); below it the separating axis answer is used
 * as is. B's reference edge is preferred over A's only when it separates by this many slops more:
 * a stable choice from frame to frame (the same rule as Box2D's). */
#define SEPARATED_SLOPS CD_R(0.1)
#define FLIP_SLOPS CD_R(0.1)

/* Sine of the turn at a chain vertex below which it counts as flat. */
#define CHAIN_FLAT_TOLERANCE CD_R(1.0e-4)

/* A statement the compiler must keep where it stands: in the body of an if, it keeps the branch
 * (GCC and clang otherwise turn a small if into selects). */
#if defined(__GNUC__) || defined(__clang__)
#define KEEP_BRANCH() __asm__ volatile("")
/* A condition that is almost never true: its code is laid out away from the common path. */
#define RARELY(condition) __builtin_expect(!!(condition), 0)
#else
#define KEEP_BRANCH() ((void)0)
#define RARELY(condition) (condition)
#endif

#define VERTEX_FEATURE 0x100u
/* Feature codes (bits 16+) of a single point along the gap between separated cores: vertex
 * against vertex, plus these when A's or B's closest point lies inside an edge (the id then holds
 * that edge's index instead of a vertex's). */
#define CODE_VERTEX_VERTEX 4u
#define CODE_EDGE_A 1u
#define CODE_EDGE_B 2u

typedef struct Core
{
	const cd2Vec* vertices;
	const cd2Vec* normals;
	int count; /* 1: point, 2: two-sided segment (normals[1] = -normals[0]), 3+: polygon */
	cdReal radius;
	cd2Vec storage[2 * 4]; /* vertices and normals of the cores that are not polygons */
} Core;

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

static cd2Manifold Flipped(cd2Manifold manifold)
{
	manifold.normal = cd2Neg(manifold.normal);
	return manifold;
}

/* ---- cores (set up in place: a polygon's core points into the polygon) ------------------------ */

static void InitPointCore(Core* core, cd2Vec point, cdReal radius)
{
	core->storage[0] = point;
	core->storage[1] = cd2MakeVec(CD_R(0.0), CD_R(1.0));
	core->vertices = core->storage;
	core->normals = core->storage + 1;
	core->count = 1;
	core->radius = radius;
}

/* A segment core; a zero-length (or underflowing) one is a point. */
static void InitSegmentCore(Core* core, cd2Vec p1, cd2Vec p2, cdReal radius)
{
	cd2Vec direction = cd2Normalize(cd2Sub(p2, p1));
	if (direction.x == CD_R(0.0) && direction.y == CD_R(0.0))
	{
		InitPointCore(core, p1, radius);
		return;
	}
	core->storage[0] = p1;
	core->storage[1] = p2;
	core->storage[2] = cd2RightPerp(direction);
	core->storage[3] = cd2LeftPerp(direction);
	core->vertices = core->storage;
	core->normals = core->storage + 2;
	core->count = 2;
	core->radius = radius;
}

static void InitPolygonCore(Core* core, const cd2Polygon* polygon)
{
	CD_ASSERT(polygon != NULL && polygon->count >= 3 && polygon->count <= CD2_MAX_POLYGON_VERTICES);
	core->vertices = polygon->vertices;
	core->normals = polygon->normals;
	core->count = polygon->count;
	core->radius = polygon->radius;
}

/* An oriented rectangle center +- axisX * hx +- axisY * hy; zero sizes give a segment or a point. */
static void InitRectangleCore(Core* core, cd2Vec center, cd2Vec axisX, cd2Vec axisY, cdReal hx, cdReal hy)
{
	cd2Vec ex = cd2Scale(hx, axisX), ey = cd2Scale(hy, axisY);
	if (hx == CD_R(0.0) || hy == CD_R(0.0))
	{
		cd2Vec e = hx == CD_R(0.0) ? ey : ex;
		InitSegmentCore(core, cd2Sub(center, e), cd2Add(center, e), CD_R(0.0));
		return;
	}
	core->storage[0] = cd2Sub(cd2Sub(center, ex), ey);
	core->storage[1] = cd2Sub(cd2Add(center, ex), ey);
	core->storage[2] = cd2Add(cd2Add(center, ex), ey);
	core->storage[3] = cd2Add(cd2Sub(center, ex), ey);
	core->storage[4] = cd2Neg(axisY);
	core->storage[5] = axisX;
	core->storage[6] = axisY;
	core->storage[7] = cd2Neg(axisX);
	core->vertices = core->storage;
	core->normals = core->storage + 4;
	core->count = 4;
	core->radius = CD_R(0.0);
}

/* ---- point against core ----------------------------------------------------------------------- */

static cd2Manifold CollidePoints(const Core* a, const Core* b, cdReal speculativeDistance)
{
	cd2Manifold manifold = EmptyManifold();
	cd2Vec delta = cd2Sub(b->vertices[0], a->vertices[0]);
	cdReal distance;
	cd2Vec normal = cd2GetLengthAndNormalize(&distance, delta);
	if (normal.x == CD_R(0.0) && normal.y == CD_R(0.0))
	{
		normal = cd2MakeVec(CD_R(0.0), CD_R(1.0));
		distance = CD_R(0.0);
	}
	cdReal separation = distance - a->radius - b->radius;
	if (separation > speculativeDistance)
	{
		return manifold;
	}
	cd2Vec onA = cd2MulAdd(a->vertices[0], a->radius, normal);
	cd2Vec onB = cd2MulSub(b->vertices[0], b->radius, normal);
	manifold.normal = normal;
	AddPoint(&manifold, cd2Scale(CD_R(0.5), cd2Add(onA, onB)), separation, 0u);
	return manifold;
}

/* cd2Length without the library call that sets errno on a negative argument (a sum of squares
 * never is): in the float build on SSE2 the square root instruction alone, the same bits. The
 * call's path, even never taken, made the compiler keep values on the stack around it. */
static inline cdReal LengthNoErrno(cd2Vec v)
{
#if CD2_SEPARATION_SSE
	/* _mm_set1_ps, not _mm_set_ss: only lane 0 counts, and zeroing the others took the value
	 * through an integer register on the way to the square root. */
	return _mm_cvtss_f32(_mm_sqrt_ss(_mm_set1_ps(v.x * v.x + v.y * v.y)));
#else
	return cd2Length(v);
#endif
}

/* The point `center` grown by pointRadius against the segment or polygon core k; the normal
 * points from k to the point. Takes the point's fields rather than a point core so that
 * cd2CollideCirclePolygon, whose whole cost is this function, builds no cores. */
/* The one contact of a point against a core, as plain values: built into a manifold by value
 * only at the end, so that the manifold is not assembled on the stack and copied out (the copy's
 * wide loads of narrow stores waited on store forwarding). normal points from k to the point. */
typedef struct CenterContact
{
	cd2Vec normal;
	cd2Vec point;
	cdReal separation;
	uint32_t id;
	bool hit;
} CenterContact;

/* The contact of the point `center` grown by pointRadius with the core k, given the first edge of
 * the largest separation of the point from k's edge lines and that separation; polygon: k is
 * known to be a polygon core (not a segment). */
static inline CenterContact CenterContactOnEdge(const Core* k, cd2Vec center, cdReal pointRadius,
												cdReal speculativeDistance, int edge, cdReal edgeSeparation,
												bool polygon)
{
	CenterContact contact = {{CD_R(0.0), CD_R(0.0)}, {CD_R(0.0), CD_R(0.0)}, CD_R(0.0), 0u, false};
	cdReal total = k->radius + pointRadius;
	cdReal limit = total + speculativeDistance;
	/* No contact when the largest separation is beyond the limit (the scans that stop at the
	 * first edge beyond it return the same). */
	if (edgeSeparation > limit)
	{
		return contact;
	}
	int next = edge + 1 < k->count ? edge + 1 : 0;
	cd2Vec v1 = k->vertices[edge];
	cd2Vec v2 = k->vertices[next];
	cd2Vec normal = k->normals[edge];
	cdReal coreSeparation = edgeSeparation;
	uint32_t id = (uint32_t)edge;
	/* Inside a polygon core the face is the answer; a segment core has no inside. Outside, the
	 * point is in the region of v1 or v2 when it projects beyond that end of the edge. Measured
	 * along the normal's own tangent, not the edge v2 - v1: the face point is the centre moved
	 * along the normal, and at large coordinates the rounded vertices of a small polygon can make
	 * an edge that is not square to its normal (a box of size 2 at x = 1e9 in float is a
	 * vertical segment whatever its rotation), which put points far off to the side in the face
	 * region. */
	if (edgeSeparation > CD_R(0.0) || (!polygon && k->count == 2))
	{
		cd2Vec tangent = cd2LeftPerp(normal);
		cdReal along = cd2Dot(tangent, cd2Sub(center, v1));
		int vertex = along <= CD_R(0.0) ? edge : along >= cd2Dot(tangent, cd2Sub(v2, v1)) ? next : -1;
		if (vertex >= 0)
		{
			/* cd2GetLengthAndNormalize inline: a length it accepts (at least CD_REAL_EPSILON^2 and
			 * finite) gives a direction whose larger component is at least 0.7, never zero. */
			cd2Vec offset = cd2Sub(center, k->vertices[vertex]);
			cdReal distance = LengthNoErrno(offset);
			if (distance >= CD_REAL_EPSILON * CD_REAL_EPSILON && distance <= CD_REAL_MAX)
			{
				cd2Vec direction = cd2Scale(CD_R(1.0) / distance, offset);
				normal = direction;
				coreSeparation = distance;
				id = VERTEX_FEATURE | (uint32_t)vertex;
			}
		}
	}
	cdReal separation = coreSeparation - total;
	if (separation > speculativeDistance)
	{
		return contact;
	}
	contact.normal = normal;
	contact.point = cd2MulAdd(center, CD_R(0.5) * (k->radius - pointRadius - coreSeparation), normal);
	contact.separation = separation;
	contact.id = id;
	contact.hit = true;
	return contact;
}

static inline CenterContact CoreCenterContact(const Core* k, cd2Vec center, cdReal pointRadius,
											  cdReal speculativeDistance)
{
	CenterContact contact = {{CD_R(0.0), CD_R(0.0)}, {CD_R(0.0), CD_R(0.0)}, CD_R(0.0), 0u, false};
	cdReal total = k->radius + pointRadius;
	cdReal limit = total + speculativeDistance;

	/* The edge whose line the point stands farthest outside of; for a point outside the core the
	 * closest feature is on it (or at one of its ends). The first maximum is found by a tree of
	 * pairwise comparisons (the right one wins only when strictly larger, so the first of equal
	 * values wins, as in a scan from -CD_REAL_MAX) over 4 or 8 values, the missing ones -CD_REAL_MAX:
	 * three levels instead of a chain of eight compare-and-branch steps, whose winner a branch
	 * predictor cannot know (the 8-gon row of collide_bench_manifold2 ran 0.87 -> 0.69 of Box2D). */
	cdReal s[CD2_MAX_POLYGON_VERTICES];
	int width = k->count > 4 ? CD2_MAX_POLYGON_VERTICES : 4;
	for (int i = 0; i < 4; ++i)
	{
		s[i] = i < k->count ? cd2Dot(k->normals[i], cd2Sub(center, k->vertices[i])) : -CD_REAL_MAX;
	}
	/* A point beyond the limit along one of the first four edges has no contact whatever the
	 * others give (the maximum is beyond it too): half of a broadphase's pairs end here. */
	if ((s[0] > limit) | (s[1] > limit) | (s[2] > limit) | (s[3] > limit))
	{
		return contact;
	}
	for (int i = 4; i < width; ++i)
	{
		s[i] = i < k->count ? cd2Dot(k->normals[i], cd2Sub(center, k->vertices[i])) : -CD_REAL_MAX;
	}
	int edge = s[1] > s[0] ? 1 : 0;
	cdReal edgeSeparation = s[1] > s[0] ? s[1] : s[0];
	int e23 = s[3] > s[2] ? 3 : 2;
	cdReal s23 = s[3] > s[2] ? s[3] : s[2];
	edge = s23 > edgeSeparation ? e23 : edge;
	edgeSeparation = s23 > edgeSeparation ? s23 : edgeSeparation;
	if (width > 4)
	{
		int e45 = s[5] > s[4] ? 5 : 4, e67 = s[7] > s[6] ? 7 : 6;
		cdReal s45 = s[5] > s[4] ? s[5] : s[4], s67 = s[7] > s[6] ? s[7] : s[6];
		int e47 = s67 > s45 ? e67 : e45;
		cdReal s47 = s67 > s45 ? s67 : s45;
		edge = s47 > edgeSeparation ? e47 : edge;
		edgeSeparation = s47 > edgeSeparation ? s47 : edgeSeparation;
	}
	if (!(edgeSeparation > -CD_REAL_MAX))
	{
		edge = 0;
		edgeSeparation = -CD_REAL_MAX;
	}
	return CenterContactOnEdge(k, center, pointRadius, speculativeDistance, edge, edgeSeparation, false);
}

/* CoreCenterContact by a scan that stops at the first edge the point is beyond the limit of, the
 * same contact bit for bit on finite input (the first edge of the largest separation, ties to the
 * first; a NaN centre gives edge 0 at -CD_REAL_MAX, as there). On the 2D world's mix of polygons of 3 to 8
 * edges, about half of them apart, the scan's single exit branch mispredicts less than the tree's branches on
 * the count and on the first four edges, and it executes fewer instructions;
 * cd2CollideCirclePolygonLocal uses it where SSE2 is not (the float build on SSE2 runs PairScanEdge
 * instead). For polygon cores. */
#if !CD2_SEPARATION_SSE
static inline CenterContact ScanCenterContact(const Core* k, cd2Vec center, cdReal pointRadius,
											  cdReal speculativeDistance)
{
	CD_ASSERT(k->count >= 3);
	cdReal limit = k->radius + pointRadius + speculativeDistance;
	int edge = 0;
	cdReal edgeSeparation = -CD_REAL_MAX;
	for (int i = 0; i < k->count; ++i)
	{
		cdReal s = cd2Dot(k->normals[i], cd2Sub(center, k->vertices[i]));
		/* The limit is tested only on a new largest separation: the largest so far is within it
		 * (or is the start value, which CenterContactOnEdge's own limit test then rejects), so an
		 * edge beyond it is always a new largest, and the edges that are not cost one branch
		 * instead of two (collide_bench_scenes' circle-polygon row: 1.26 -> 1.23 of Box2D 2.4).
		 * A branch, not a select: a select makes the edge, and so the loads of its vertices and
		 * normal after the loop, wait for every separation; a predicted branch lets them start at
		 * once (the same row ran 1.26 -> 1.46 with a select). */
		if (s > edgeSeparation)
		{
			if (s > limit)
			{
				CenterContact none = {{CD_R(0.0), CD_R(0.0)}, {CD_R(0.0), CD_R(0.0)}, CD_R(0.0), 0u, false};
				return none;
			}
			edge = i;
			edgeSeparation = s;
			KEEP_BRANCH();
		}
	}
	return CenterContactOnEdge(k, center, pointRadius, speculativeDistance, edge, edgeSeparation, true);
}
#endif

static inline cd2Manifold CollideCoreCenter(const Core* k, cd2Vec center, cdReal pointRadius,
											cdReal speculativeDistance, bool flip)
{
	CenterContact contact = CoreCenterContact(k, center, pointRadius, speculativeDistance);
	cd2Manifold manifold = EmptyManifold();
	if (contact.hit)
	{
		manifold.normal = flip ? cd2Neg(contact.normal) : contact.normal;
		manifold.points[0].point = contact.point;
		manifold.points[0].separation = contact.separation;
		manifold.points[0].id = contact.id;
		manifold.pointCount = 1;
	}
	return manifold;
}

/* The point core p against the segment or polygon core k; the normal points from k to p. */
static cd2Manifold CollideCorePoint(const Core* k, const Core* p, cdReal speculativeDistance, bool flip)
{
	return CollideCoreCenter(k, p->vertices[0], p->radius, speculativeDistance, flip);
}

/* ---- core against core ------------------------------------------------------------------------ */

/* The largest separation of b from a over a's edge normals, and its edge (sat2_separation.h: all
 * edges scanned without branches; the callers only compare the answer with their limit). */
static cdReal MaxSeparation(const Core* a, const Core* b, int* edge)
{
	return cd2MaxSeparation(a->normals, a->vertices, a->count, b->vertices, b->count, edge);
}

/* A bound on the rounding of positions along an edge computed from these points: closer than
 * this they count as equal. */
static cdReal RoundingSlack(cd2Vec p, cd2Vec q, cd2Vec r)
{
	cdReal magnitude = cdAbs(p.x) + cdAbs(p.y) + cdAbs(q.x) + cdAbs(q.y) + cdAbs(r.x) + cdAbs(r.y);
	return CD_R(8.0) * CD_REAL_EPSILON * magnitude;
}

/* Clips the incident edge of `incident` (the one facing the reference normal most) to the side
 * lines of the reference edge and keeps the points within the speculative distance. `flip` says
 * that the reference is B. Without `keepOutside`, an incident edge entirely beyond one side line
 * gives no contact; with it, the core end nearer to the reference edge's extent is kept (its
 * point then projects off the face: for cores that are apart the caller takes the gap point).
 *
 * Points lie on both surfaces: the incident surface is its core edge moved out by the incident
 * radius along the edge's normal, and that segment is what gets clipped; the reference surface
 * point is the incident one's projection on the reference edge moved out by its radius. The one
 * exception is the incident core's deepest vertex (its support against the normal), whose surface
 * point is taken straight against the normal: there the separation is exactly the separating-axis
 * value, rounded incident shapes included. */
static void Clip(cd2Manifold* manifold, const Core* reference, int referenceEdge, const Core* incident,
				 bool flip, cdReal speculativeDistance, bool keepOutside)
{
	/* Written in place: a manifold returned by value through the callers cost store-forwarding
	 * stalls on every copy. */
	*manifold = EmptyManifold();
	cd2Vec n = reference->normals[referenceEdge];
	cd2Vec v1 = reference->vertices[referenceEdge];
	cd2Vec v2 = reference->vertices[referenceEdge + 1 < reference->count ? referenceEdge + 1 : 0];

	/* The incident edge by a kept branch, not a select (KEEP_BRANCH): its vertices' loads then
	 * start as soon as the branch is predicted, not after every dot product. */
	int incidentEdge = 0;
	cdReal lowest = CD_REAL_MAX;
	for (int i = 0; i < incident->count; ++i)
	{
		cdReal d = cd2Dot(n, incident->normals[i]);
		if (d < lowest)
		{
			lowest = d;
			incidentEdge = i;
			KEEP_BRANCH();
		}
	}
	cd2Vec core[2] = {incident->vertices[incidentEdge],
					  incident->vertices[incidentEdge + 1 < incident->count ? incidentEdge + 1 : 0]};
	cd2Vec offset = cd2Scale(incident->radius, incident->normals[incidentEdge]);
	cd2Vec w[2] = {cd2Add(core[0], offset), cd2Add(core[1], offset)};
	uint32_t code[2] = {0u, 1u};

	cd2Vec tangent = cd2LeftPerp(n);
	cdReal upper = cd2Dot(tangent, cd2Sub(v2, v1));
	cdReal along[2] = {cd2Dot(tangent, cd2Sub(w[0], v1)), cd2Dot(tangent, cd2Sub(w[1], v1))};
	int pointCount = 2;
	bool whollyBeyond =
		(along[0] < CD_R(0.0) && along[1] < CD_R(0.0)) || (along[0] > upper && along[1] > upper);
	if (RARELY(whollyBeyond && incident->count > 2))
	{
		/* A tie within round-off may leave the first edge far from the contact (incident_tie2.h).
		 * The arrays are refilled here, not by a helper taking them: the common path keeps them in
		 * registers. */
		int tied = cd2TiedIncidentEdge(incident->vertices, incident->normals, incident->count, n, lowest,
									   incidentEdge, tangent, v1, upper);
		if (tied != incidentEdge)
		{
			incidentEdge = tied;
			core[0] = incident->vertices[tied];
			core[1] = incident->vertices[tied + 1 < incident->count ? tied + 1 : 0];
			cd2Vec shift = cd2Scale(incident->radius, incident->normals[tied]);
			for (int i = 0; i < 2; ++i)
			{
				w[i] = cd2Add(core[i], shift);
				along[i] = cd2Dot(tangent, cd2Sub(w[i], v1));
			}
			whollyBeyond =
				(along[0] < CD_R(0.0) && along[1] < CD_R(0.0)) || (along[0] > upper && along[1] > upper);
		}
	}
	if (whollyBeyond)
	{
		if (!keepOutside)
		{
			return;
		}
		/* Beyond one side line: keep the core end nearer to the reference edge's extent (it is
		 * where the incident edge enters the face region), the deeper one when both are equally
		 * near within round-off. Measured on the core ends, not on the surface ends: a rounded
		 * incident edge tilted from the reference face has its surface offset along the face by
		 * up to its radius (sideways for a capsule standing upright on the face's end, where the
		 * tie then took the far end of capsules meeting at a common end point: no contact). */
		bool below = along[0] < CD_R(0.0);
		cdReal beyond[2];
		for (int i = 0; i < 2; ++i)
		{
			cdReal position = cd2Dot(tangent, cd2Sub(core[i], v1));
			beyond[i] = cdMax(below ? -position : position - upper, CD_R(0.0));
		}
		int keep;
		if (cdAbs(beyond[0] - beyond[1]) <= RoundingSlack(core[0], core[1], v1))
		{
			keep = cd2Dot(n, cd2Sub(core[0], core[1])) <= CD_R(0.0) ? 0 : 1;
		}
		else
		{
			keep = beyond[0] < beyond[1] ? 0 : 1;
		}
		w[0] = w[keep];
		core[0] = core[keep];
		code[0] = code[keep];
		pointCount = 1;
	}
	else
	{
		cd2Vec clipped[2] = {w[0], w[1]};
		for (int i = 0; i < 2; ++i)
		{
			/* along[0] != along[1] here: one end is inside the extent, the other outside it. */
			if (along[i] < CD_R(0.0))
			{
				clipped[i] = cd2Lerp(w[i], w[1 - i], (CD_R(0.0) - along[i]) / (along[1 - i] - along[i]));
				code[i] = 2u;
			}
			else if (along[i] > upper)
			{
				clipped[i] = cd2Lerp(w[i], w[1 - i], (upper - along[i]) / (along[1 - i] - along[i]));
				code[i] = 3u;
			}
		}
		w[0] = clipped[0];
		w[1] = clipped[1];
	}

	/* The deepest core vertex: its surface point straight against n, if that stays over the
	 * reference edge (up to its rounding: a vertex right at the edge's end, such as an upright
	 * capsule's end standing on it, comes out a rounding error beyond it, and its sideways surface
	 * point would be reported instead, up to a radius too shallow). Also when its surface point
	 * was clipped: an incident edge square to the reference one has its surface offset sideways,
	 * beyond a side line while the vertex is not, and clipped within rounding of a side line an
	 * upright sharp edge's point runs along it to its far end. */
	int deepest = pointCount == 1 ? 0 : cd2Dot(n, cd2Sub(core[0], core[1])) <= CD_R(0.0) ? 0 : 1;
	cd2Vec straight = cd2MulSub(core[deepest], incident->radius, n);
	cdReal t = cd2Dot(tangent, cd2Sub(straight, v1));
	cdReal slack = RoundingSlack(straight, v1, v2);
	if (pointCount == 1 || (-slack <= t && t <= upper + slack))
	{
		w[deepest] = straight;
		code[deepest] = pointCount == 1 ? code[0] : (uint32_t)deepest;
	}

	uint32_t base = (uint32_t)referenceEdge | (uint32_t)incidentEdge << 8 | (flip ? CD2_FEATURE_FLIP : 0u);
	for (int i = 0; i < pointCount; ++i)
	{
		cdReal separation = cd2Dot(n, cd2Sub(w[i], v1)) - reference->radius;
		if (separation <= speculativeDistance)
		{
			AddPoint(manifold, cd2MulSub(w[i], CD_R(0.5) * separation, n), separation, base | code[i] << 16);
		}
	}
	if (manifold->pointCount > 0)
	{
		manifold->normal = flip ? cd2Neg(n) : n;
	}
}

/* The one point of the incident core's deepest vertex against the reference edge's normal, its
 * surface point straight against the normal (as in Clip), whatever the side lines. */
static void DeepestContact(cd2Manifold* manifold, const Core* reference, int referenceEdge,
						   const Core* incident, bool flip, cdReal speculativeDistance)
{
	*manifold = EmptyManifold();
	cd2Vec n = reference->normals[referenceEdge];
	cd2Vec v1 = reference->vertices[referenceEdge];
	int deepest = 0;
	for (int i = 1; i < incident->count; ++i)
	{
		deepest = cd2Dot(n, incident->vertices[i]) < cd2Dot(n, incident->vertices[deepest]) ? i : deepest;
	}
	cd2Vec straight = cd2MulSub(incident->vertices[deepest], incident->radius, n);
	cdReal separation = cd2Dot(n, cd2Sub(straight, v1)) - reference->radius;
	if (separation <= speculativeDistance)
	{
		uint32_t id = (uint32_t)referenceEdge | (uint32_t)deepest << 8 | (flip ? CD2_FEATURE_FLIP : 0u);
		AddPoint(manifold, cd2MulSub(straight, CD_R(0.5) * separation, n), separation, id);
		manifold->normal = flip ? cd2Neg(n) : n;
	}
}

/* Index of the endpoint of edge (i, i + 1) that p is exactly, or -1. */
static int EndpointIndex(const Core* core, int edge, cd2Vec p)
{
	int next = edge + 1 < core->count ? edge + 1 : 0;
	if (cd2VecEqual(p, core->vertices[edge]))
	{
		return edge;
	}
	return cd2VecEqual(p, core->vertices[next]) ? next : -1;
}

/* The edge of a two-sided segment core facing direction u, or `edge` for a polygon. */
static int FacingEdge(const Core* core, int edge, cd2Vec u)
{
	if (core->count == 2)
	{
		return cd2Dot(core->normals[0], u) >= CD_R(0.0) ? 0 : 1;
	}
	return edge;
}

static cd2Segment EdgeSegment(const Core* core, int edge)
{
	cd2Segment segment = {core->vertices[edge], core->vertices[edge + 1 < core->count ? edge + 1 : 0]};
	return segment;
}

/* The edge of `core` closest to edge `ownerEdge` of `owner` (the first of the closest ones, in
 * index order); pointA on the owner's edge, pointB on the core's.
 *
 * The answer is that of cd2ClosestPointsSegmentSegment against every edge, but most edges are
 * ruled out without it: seen along the owner edge's normal n, every point of a core edge lies at
 * least min(h_i, h_i+1) above the owner edge's line (h_j the height of vertex j), and every point
 * of the owner edge at most max(0, n . (s2 - s1)), so the two are at least that gap apart divided
 * by |n| <= |n.x| + |n.y|. The gap is reduced by a bound on the rounding of everything involved
 * (heights, the closest points' positions, which lie within a few ulps of the coordinates'
 * magnitude of their segments; at most 30 ulps of magnitude * |n|, 128 taken), and the distance
 * an edge would report differs from the true one by a few ulps more (64 taken). An edge whose gap
 * exceeds the best distance found so far is therefore skipped: it would have reported a larger
 * distance, and so could not have been chosen. The two edges at the lowest vertex go first (the
 * closest feature is nearly always there), so that the best distance is small from the start;
 * ties go to the lower index, as in a scan in index order. */
static cd2ClosestPoints ClosestEdge(const Core* owner, int ownerEdge, const Core* core, int* edge)
{
	cd2Segment segment = EdgeSegment(owner, ownerEdge);
	cd2Vec n = owner->normals[ownerEdge];
	int count = core->count;
	cdReal height[CD2_MAX_POLYGON_VERTICES];
	cdReal magnitude = cdMax(cdMax(cdAbs(segment.p1.x), cdAbs(segment.p1.y)),
							 cdMax(cdAbs(segment.p2.x), cdAbs(segment.p2.y)));
	int lowest = 0;
	for (int j = 0; j < count; ++j)
	{
		cd2Vec v = core->vertices[j];
		height[j] = cd2Dot(n, cd2Sub(v, segment.p1));
		magnitude = cdMax(magnitude, cdMax(cdAbs(v.x), cdAbs(v.y)));
		lowest = height[j] < height[lowest] ? j : lowest;
	}
	cdReal rise = cdMax(cd2Dot(n, cd2Sub(segment.p2, segment.p1)), CD_R(0.0));
	cdReal normBound = cdAbs(n.x) + cdAbs(n.y);
	cdReal slack = CD_R(128.0) * CD_REAL_EPSILON * magnitude * normBound;
	cdReal shrink = CD_R(1.0) - CD_R(64.0) * CD_REAL_EPSILON;

	int before = lowest > 0 ? lowest - 1 : count - 1; /* the edge that ends at the lowest vertex */
	cd2ClosestPoints best = cd2ClosestPointsSegmentSegment(segment, EdgeSegment(core, before));
	int bestEdge = before;
	for (int k = 0; k < count; ++k)
	{
		/* lowest first, then every other edge but `before` */
		int i = k == 0 ? lowest : k <= lowest ? k - 1 : k;
		if (i == before)
		{
			continue;
		}
		int next = i + 1 < count ? i + 1 : 0;
		cdReal gap = cdMin(height[i], height[next]) - rise - slack;
		if (gap * shrink > best.distance * normBound)
		{
			continue;
		}
		cd2ClosestPoints candidate = cd2ClosestPointsSegmentSegment(segment, EdgeSegment(core, i));
		if (candidate.distance < best.distance || (candidate.distance == best.distance && i < bestEdge))
		{
			best = candidate;
			bestEdge = i;
		}
	}
	*edge = bestEdge;
	return best;
}

/* One point along the gap between the closest points of two cores that are apart: midway between
 * their surfaces, normal from a to b (normalized here: for a gap of a rounding error the distance
 * the closest points report is not the length of their difference). No point when the gap
 * vanishes. */
static cd2Manifold GapContact(const Core* a, const Core* b, cd2ClosestPoints closest, int edgeA, int edgeB)
{
	cd2Manifold manifold = EmptyManifold();
	cd2Vec u = cd2GetLengthAndNormalize(&closest.distance, cd2Sub(closest.pointB, closest.pointA));
	if (u.x == CD_R(0.0) && u.y == CD_R(0.0))
	{
		return manifold;
	}
	int vertexA = EndpointIndex(a, edgeA, closest.pointA);
	int vertexB = EndpointIndex(b, edgeB, closest.pointB);
	cd2Vec onA = cd2MulAdd(closest.pointA, a->radius, u);
	cd2Vec onB = cd2MulSub(closest.pointB, b->radius, u);
	uint32_t featureA = vertexA >= 0 ? (uint32_t)vertexA : (uint32_t)edgeA;
	uint32_t featureB = vertexB >= 0 ? (uint32_t)vertexB : (uint32_t)edgeB;
	uint32_t code = CODE_VERTEX_VERTEX + (vertexA < 0 ? CODE_EDGE_A : 0u) + (vertexB < 0 ? CODE_EDGE_B : 0u);
	manifold.normal = u;
	AddPoint(&manifold, cd2Scale(CD_R(0.5), cd2Add(onA, onB)), closest.distance - (a->radius + b->radius),
			 featureA | featureB << 8 | code << 16);
	return manifold;
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

/* The closest points of two cores and the edges that hold them (in: the max-separation edges).
 * With both separations positive, each max-separation edge holds its core's closest feature (the
 * unimodality above); when only one is, the other core's edges are searched. */
static cd2ClosestPoints ClosestCores(const Core* a, const Core* b, cdReal separationA, cdReal separationB,
									 int* edgeA, int* edgeB)
{
	if (separationA > CD_R(0.0) && separationB > CD_R(0.0))
	{
		return cd2ClosestPointsSegmentSegment(EdgeSegment(a, *edgeA), EdgeSegment(b, *edgeB));
	}
	if (separationA >= separationB)
	{
		return ClosestEdge(a, *edgeA, b, edgeB);
	}
	cd2ClosestPoints closest = ClosestEdge(b, *edgeB, a, edgeA);
	cd2Vec swap = closest.pointA;
	closest.pointA = closest.pointB;
	closest.pointB = swap;
	return closest;
}

/* CollideCores once A's edges have been scanned (separationA, edgeA: MaxSeparation(a, b)) and
 * found within the limit. */
static cd2Manifold CollideCoresFrom(const Core* a, const Core* b, cdReal speculativeDistance,
									cdReal separationA, int edgeA)
{
	cdReal total = a->radius + b->radius;
	int edgeB;
	cdReal limit = total + speculativeDistance;
	cdReal separationB;
	if (!cd2MaxSeparationWithin(b->normals, b->vertices, b->count, a->vertices, a->count, limit, &edgeB,
								&separationB))
	{
		return EmptyManifold();
	}

	/* Two segments need the closest-feature path even when their normals see no gap: collinear
	 * segments are separated along their common direction, which is neither one's normal. */
	cdReal slop = CD_LINEAR_SLOP;
	cdReal separatedTolerance = SEPARATED_SLOPS * slop;
	bool segments = a->count == 2 && b->count == 2;
	cd2ClosestPoints closest = {{CD_R(0.0), CD_R(0.0)}, {CD_R(0.0), CD_R(0.0)}, CD_R(0.0)};
	/* Own copies: the search below may move them, and the separating-axis path after this block
	 * (cores within the tolerance) needs the max-separation edges themselves. */
	int closestEdgeA = edgeA, closestEdgeB = edgeB;
	bool haveClosest = false;
	if (segments || cdMax(separationA, separationB) > separatedTolerance)
	{
		closest = ClosestCores(a, b, separationA, separationB, &closestEdgeA, &closestEdgeB);
		haveClosest = true;
		if (closest.distance > separatedTolerance)
		{
			if (closest.distance - total > speculativeDistance)
			{
				return EmptyManifold();
			}
			cd2Vec u = cd2Scale(CD_R(1.0) / closest.distance, cd2Sub(closest.pointB, closest.pointA));
			int vertexA = EndpointIndex(a, closestEdgeA, closest.pointA);
			int vertexB = EndpointIndex(b, closestEdgeB, closest.pointB);
			/* A closest point inside an edge makes a face contact, unless the incident edge lies
			 * wholly beyond the face's side lines (or its points beyond the speculative distance),
			 * or the clipped points do not reach the gap: then the face is not what is closest (a
			 * face made degenerate by round-off at large coordinates, a box of size 1e-9 whose
			 * closest point is inside an edge by rounding, an incident edge far from the closest
			 * vertex), its separation along the face normal misses the gap, and the one point
			 * along the gap is the contact. */
			/* A face whose normal does not face the other core is not what is closest either:
			 * at coordinates whose round-off exceeds the shapes' sizes, the closest points tie
			 * between edges, and the one taken may face away. */
			int faceA = vertexA < 0 ? FacingEdge(a, closestEdgeA, u) : 0;
			int faceB = vertexA < 0 ? 0 : FacingEdge(b, closestEdgeB, cd2Neg(u));
			bool facing = vertexA < 0 ? cd2Dot(a->normals[faceA], u) >= CD_R(0.0)
									  : cd2Dot(b->normals[faceB], u) <= CD_R(0.0);
			if ((vertexA < 0 || vertexB < 0) && facing)
			{
				cd2Manifold face;
				if (vertexA < 0)
				{
					Clip(&face, a, faceA, b, false, speculativeDistance, false);
				}
				else
				{
					Clip(&face, b, faceB, a, true, speculativeDistance, false);
				}
				if (face.pointCount > 0 &&
					SmallestSeparation(&face) <= closest.distance - total + separatedTolerance)
				{
					return face;
				}
			}
			return GapContact(a, b, closest, closestEdgeA, closestEdgeB);
		}
	}

	/* On a near tie between the two faces (A's preferred), the incident edge may lie wholly beyond
	 * the preferred face's side lines, where its one kept point would project off that face: the
	 * other face, nearly as good an axis, then holds the contact if its clip keeps points. */
	cdReal flipTolerance = FLIP_SLOPS * slop;
	bool flip = separationB > separationA + flipTolerance;
	cd2Manifold manifold;
	if (flip)
	{
		Clip(&manifold, b, edgeB, a, true, speculativeDistance, false);
	}
	else
	{
		Clip(&manifold, a, edgeA, b, false, speculativeDistance, false);
	}
	if (manifold.pointCount == 0 && !flip && separationB >= separationA - flipTolerance)
	{
		Clip(&manifold, b, edgeB, a, true, speculativeDistance, false);
	}
	bool keptOutside = manifold.pointCount == 0;
	if (keptOutside)
	{
		if (flip)
		{
			Clip(&manifold, b, edgeB, a, true, speculativeDistance, true);
		}
		else
		{
			Clip(&manifold, a, edgeA, b, false, speculativeDistance, true);
		}
	}
	/* Cores within the tolerance that do not overlap: their separation is exactly the gap minus
	 * the radii. The clipped face misses it when the incident edge stands nearly square to a short
	 * reference edge and just short of its end (clipped at the side line, the point runs out to
	 * the incident edge's far end, beyond the separating-axis value), and a point kept beyond the
	 * side lines projects off the face: then the one point along the gap is the contact. */
	bool apart = segments || cdMax(separationA, separationB) > CD_R(0.0);
	bool missed =
		keptOutside || manifold.pointCount == 0 ||
		SmallestSeparation(&manifold) > cdMax(separationA, separationB) - total + separatedTolerance;
	if (!apart && missed && manifold.pointCount > 0)
	{
		/* Overlapping cores whose clipped points lie above the separating-axis value by more than
		 * the smaller shape's size and the round-off of their coordinates (a segment far longer
		 * than the shape it crosses, whose side distances round to the wrong side): the one point
		 * of the reference normal's deepest incident vertex, whose separation is that value. A
		 * smaller miss is the clip of rounded surfaces, kept. */
		const Core* reference = flip ? b : a;
		const Core* incident = flip ? a : b;
		int referenceEdge = flip ? edgeB : edgeA;
		cdReal magnitude = CD_R(0.0), sizeA = CD_R(0.0), sizeB = CD_R(0.0);
		for (int i = 0; i < a->count; ++i)
		{
			magnitude = cdMax(magnitude, cdAbs(a->vertices[i].x) + cdAbs(a->vertices[i].y));
			sizeA = cdMax(sizeA, cdAbs(a->vertices[i].x - a->vertices[0].x) +
									 cdAbs(a->vertices[i].y - a->vertices[0].y));
		}
		for (int i = 0; i < b->count; ++i)
		{
			magnitude = cdMax(magnitude, cdAbs(b->vertices[i].x) + cdAbs(b->vertices[i].y));
			sizeB = cdMax(sizeB, cdAbs(b->vertices[i].x - b->vertices[0].x) +
									 cdAbs(b->vertices[i].y - b->vertices[0].y));
		}
		cdReal satSeparation = (flip ? separationB : separationA) - total;
		cdReal allowed =
			cdMax(separatedTolerance + CD_R(64.0) * CD_REAL_EPSILON * magnitude, cdMin(sizeA, sizeB) + total);
		if (SmallestSeparation(&manifold) > satSeparation + allowed)
		{
			DeepestContact(&manifold, reference, referenceEdge, incident, flip, speculativeDistance);
		}
	}
	if (apart && missed)
	{
		if (!haveClosest)
		{
			closest = ClosestCores(a, b, separationA, separationB, &closestEdgeA, &closestEdgeB);
		}
		if (closest.distance > CD_R(0.0))
		{
			if (closest.distance - total > speculativeDistance)
			{
				return EmptyManifold();
			}
			if (keptOutside || manifold.pointCount == 0 ||
				SmallestSeparation(&manifold) > closest.distance - total + separatedTolerance)
			{
				cd2Manifold gap = GapContact(a, b, closest, closestEdgeA, closestEdgeB);
				if (gap.pointCount > 0 && gap.points[0].separation <= speculativeDistance)
				{
					return gap;
				}
			}
		}
	}
	return manifold;
}

static cd2Manifold CollideCores(const Core* a, const Core* b, cdReal speculativeDistance)
{
	int edgeA;
	cdReal separationA = MaxSeparation(a, b, &edgeA);
	if (separationA > a->radius + b->radius + speculativeDistance)
	{
		return EmptyManifold();
	}
	return CollideCoresFrom(a, b, speculativeDistance, separationA, edgeA);
}

/* Any two cores, normal from a to b. */
static cd2Manifold CollideAny(const Core* a, const Core* b, cdReal speculativeDistance)
{
	if (a->count == 1 && b->count == 1)
	{
		return CollidePoints(a, b, speculativeDistance);
	}
	if (a->count == 1)
	{
		return CollideCorePoint(b, a, speculativeDistance, true);
	}
	if (b->count == 1)
	{
		return CollideCorePoint(a, b, speculativeDistance, false);
	}
	return CollideCores(a, b, speculativeDistance);
}

/* ---- pair functions --------------------------------------------------------------------------- */

cd2Manifold cd2CollideCircleCircle(cd2Circle a, cd2Circle b, cdReal speculativeDistance)
{
	Core coreA, coreB;
	InitPointCore(&coreA, a.center, a.radius);
	InitPointCore(&coreB, b.center, b.radius);
	return CollidePoints(&coreA, &coreB, speculativeDistance);
}

cd2Manifold cd2CollideCircleCapsule(cd2Circle a, cd2Capsule b, cdReal speculativeDistance)
{
	Core coreA, coreB;
	InitPointCore(&coreA, a.center, a.radius);
	InitSegmentCore(&coreB, b.p1, b.p2, b.radius);
	return CollideAny(&coreA, &coreB, speculativeDistance);
}

cd2Manifold cd2CollideCirclePolygon(cd2Circle a, const cd2Polygon* b, cdReal speculativeDistance)
{
	Core coreB;
	InitPolygonCore(&coreB, b);
	return CollideCoreCenter(&coreB, a.center, a.radius, speculativeDistance, true);
}

cd2Manifold cd2CollideCircleSegment(cd2Circle a, cd2Segment b, cdReal speculativeDistance)
{
	Core coreA, coreB;
	InitPointCore(&coreA, a.center, a.radius);
	InitSegmentCore(&coreB, b.p1, b.p2, CD_R(0.0));
	return CollideAny(&coreA, &coreB, speculativeDistance);
}

cd2Manifold cd2CollideCapsuleCapsule(cd2Capsule a, cd2Capsule b, cdReal speculativeDistance)
{
	Core coreA, coreB;
	InitSegmentCore(&coreA, a.p1, a.p2, a.radius);
	InitSegmentCore(&coreB, b.p1, b.p2, b.radius);
	return CollideAny(&coreA, &coreB, speculativeDistance);
}

cd2Manifold cd2CollideCapsulePolygon(cd2Capsule a, const cd2Polygon* b, cdReal speculativeDistance)
{
	Core coreA, coreB;
	InitSegmentCore(&coreA, a.p1, a.p2, a.radius);
	InitPolygonCore(&coreB, b);
	return CollideAny(&coreA, &coreB, speculativeDistance);
}

cd2Manifold cd2CollideCapsuleSegment(cd2Capsule a, cd2Segment b, cdReal speculativeDistance)
{
	Core coreA, coreB;
	InitSegmentCore(&coreA, a.p1, a.p2, a.radius);
	InitSegmentCore(&coreB, b.p1, b.p2, CD_R(0.0));
	return CollideAny(&coreA, &coreB, speculativeDistance);
}

cd2Manifold cd2CollidePolygonPolygon(const cd2Polygon* a, const cd2Polygon* b, cdReal speculativeDistance)
{
	Core coreA, coreB;
	InitPolygonCore(&coreA, a);
	InitPolygonCore(&coreB, b);
	return CollideCores(&coreA, &coreB, speculativeDistance);
}

/* ---- local-frame forms of the commonest contacts (the others: manifold_local2.c) --------------- */

#if CD2_SEPARATION_SSE
/* The two floats of v in lanes 0 and 1 of a vector (upper lanes zero). Through a double: a
 * cd2Vec or cd2Rot argument arrives in one vector register, and this keeps it there, where
 * reading its fields split it through the stack or the integer registers. */
static inline __m128 PairLanes(cd2Vec pair)
{
	double bits;
	memcpy(&bits, &pair, sizeof bits);
	return _mm_castpd_ps(_mm_set_sd(bits));
}

/* The two floats of v in lanes 0 and 1 and again in 2 and 3: one shuffle of the argument register. */
static inline __m128 DoubledPairLanes(cd2Vec pair)
{
	double bits;
	memcpy(&bits, &pair, sizeof bits);
	return _mm_castpd_ps(_mm_set1_pd(bits));
}

/* A rotation's cosine and sine, each in every lane (for RotateLanes). */
static inline void RotationLanes(cd2Rot q, __m128* cosine, __m128* sine)
{
	__m128 rotation = PairLanes(cd2MakeVec(q.c, q.s));
	*cosine = _mm_shuffle_ps(rotation, rotation, _MM_SHUFFLE(0, 0, 0, 0));
	*sine = _mm_shuffle_ps(rotation, rotation, _MM_SHUFFLE(1, 1, 1, 1));
}

/* cosine * v + sine * swap(v) in lanes 0 and 1 (and 2 and 3, for a second pair or the same pair
 * again): with sine = (-s, s) the rotation of v by (c, s),
 * c * x - s * y and c * y + s * x, and with sine = (s, -s) the inverse rotation, c * x + s * y and
 * c * y - s * x: cd2RotateVector's and cd2InvRotateVector's values bit for bit (each lane is one
 * product plus or minus another, and addition commutes exactly). */
static inline __m128 RotateLanes(__m128 cosine, __m128 sine, __m128 v)
{
	return _mm_add_ps(_mm_mul_ps(cosine, v), _mm_mul_ps(sine, _mm_shuffle_ps(v, v, _MM_SHUFFLE(2, 3, 0, 1))));
}
#endif

/* in[0..count) placed by xf into out (points: rotated and moved; else only rotated), bit for bit
 * as cd2TransformPoint / cd2RotateVector. In the float build on SSE2 two vectors per lane group,
 * with xf kept in registers: spilling a cd2Transform argument and reading it back 16 bytes at a
 * time waited on store forwarding, a quarter of the cost of the whole local-frame call. */
static inline void PlaceVectors(cd2Vec* out, const cd2Vec* in, int count, cd2Transform xf, bool points)
{
	CD_ASSERT(0 <= count && count <= CD2_MAX_POLYGON_VERTICES);
#if CD2_SEPARATION_SSE
	/* c * x + (-s) * y is c * x - s * y exactly, and s * x + c * y is c * y + s * x. */
	/* Built by shuffles of the argument registers, xf.q's pair and xf.p's pair: a _mm_setr_ps of
	 * the fields went through the stack, and broadcasting the fields one at a time took them
	 * through the integer registers (a few cycles before the first placed vertex). */
	__m128 c, sine;
	RotationLanes(xf.q, &c, &sine);
	__m128 s = _mm_xor_ps(sine, _mm_setr_ps(-0.0f, 0.0f, -0.0f, 0.0f)); /* (-s, s, -s, s) */
	__m128 p = DoubledPairLanes(xf.p);
	int i = 0;
	for (; i + 2 <= count; i += 2)
	{
		__m128 v = _mm_loadu_ps(&in[i].x);
		__m128 r = _mm_add_ps(_mm_mul_ps(c, v), _mm_mul_ps(s, _mm_shuffle_ps(v, v, _MM_SHUFFLE(2, 3, 0, 1))));
		_mm_storeu_ps(&out[i].x, points ? _mm_add_ps(r, p) : r);
	}
	if (i < count)
	{
		__m128 v = _mm_loadl_pi(_mm_setzero_ps(), (const __m64*)(const void*)&in[i]);
		__m128 r = _mm_add_ps(_mm_mul_ps(c, v), _mm_mul_ps(s, _mm_shuffle_ps(v, v, _MM_SHUFFLE(2, 3, 0, 1))));
		_mm_storel_pi((__m64*)(void*)&out[i], points ? _mm_add_ps(r, p) : r);
	}
#else
	for (int i = 0; i < count; ++i)
	{
		out[i] = points ? cd2TransformPoint(xf, in[i]) : cd2RotateVector(xf.q, in[i]);
	}
#endif
}

/* B's vertices and normals placed in A's frame on the stack (no polygon copy: the cores need no
 * centroid), then the cores as in cd2CollidePolygonPolygon: the same manifold bit for bit as that
 * function on B placed by cd2TransformPoint. */
cd2Manifold cd2CollidePolygonPolygonLocal(const cd2Polygon* a, const cd2Polygon* b, cd2Transform xfB,
										  cdReal speculativeDistance)
{
	CD_ASSERT(a != NULL && b != NULL);
	cd2Vec vertices[CD2_MAX_POLYGON_VERTICES], normals[CD2_MAX_POLYGON_VERTICES];
	int count = b->count;
	CD_ASSERT(count >= 3 && count <= CD2_MAX_POLYGON_VERTICES);
	PlaceVectors(vertices, b->vertices, count, xfB, true);
	/* A's edges first, on B's placed vertices only: pairs apart along one of them (half of what
	 * a broadphase reports) end here, before B's normals are placed or the cores are set up. */
	int edgeA;
	cdReal separationA;
	if (!cd2MaxSeparationWithin(a->normals, a->vertices, a->count, vertices, count,
								a->radius + b->radius + speculativeDistance, &edgeA, &separationA))
	{
		return EmptyManifold();
	}
	PlaceVectors(normals, b->normals, count, xfB, false);
	Core coreA, coreB;
	InitPolygonCore(&coreA, a);
	coreB.vertices = vertices;
	coreB.normals = normals;
	coreB.count = count;
	coreB.radius = b->radius;
	return CollideCoresFrom(&coreA, &coreB, speculativeDistance, separationA, edgeA);
}

#if CD2_SEPARATION_SSE
/* ScanCenterContact's edge for a centre given as (x, y, x, y) in the float build on SSE2, two edges to
 * a vector: false when the centre is beyond the limit along some edge (no contact), else the first
 * edge of the largest separation and that separation, bit for bit as the scan on finite input.
 * Edges i and i + 1 (vertices and normals adjacent in memory) take one subtraction, one product
 * and one swap-and-add, each lane pair holding cd2Dot(normal, centre - vertex) in cd2Dot's order
 * (the swapped lane adds the same two products the other way round: the same value, since addition
 * commutes exactly). Either edge beyond the limit means no contact, as the scan's early exit: the
 * largest separation is then beyond it too. The first edge of the largest separation is kept by
 * the scan's branches. An odd last edge is loaded alone (the arrays hold CD2_MAX_POLYGON_VERTICES
 * entries, but those past the count are not the polygon's). */
static inline bool PairScanEdge(const cd2Polygon* b, __m128 centre, cdReal limitValue, int* edgeOut,
								cdReal* separationOut)
{
	int count = b->count;
	CD_ASSERT(count >= 3 && count <= CD2_MAX_POLYGON_VERTICES);
	__m128 limit = _mm_set1_ps(limitValue);
	/* One index for both arrays and for the edge found (a polygon has at least one pair). */
	size_t pairs = (size_t)count & ~(size_t)1;
	size_t edge = 0;
	cdReal edgeSeparation;
	size_t i = 0;
	{
		/* The first pair: edge 0 is the largest so far when its separation is above the start
		 * value -CD_REAL_MAX, which is what the maximum of the two gives (max_ss takes its second
		 * operand when the first is NaN), without a compare and branch. */
		__m128 d = _mm_sub_ps(centre, _mm_loadu_ps(&b->vertices[0].x));
		__m128 p = _mm_mul_ps(_mm_loadu_ps(&b->normals[0].x), d);
		__m128 sep = _mm_add_ps(p, _mm_shuffle_ps(p, p, _MM_SHUFFLE(2, 3, 0, 1)));
		if (_mm_movemask_ps(_mm_cmpgt_ps(sep, limit)) != 0)
		{
			return false;
		}
		edgeSeparation = _mm_cvtss_f32(_mm_max_ss(sep, _mm_set_ss(-CD_REAL_MAX)));
		cdReal s1 = _mm_cvtss_f32(_mm_movehl_ps(sep, sep));
		if (s1 > edgeSeparation)
		{
			edge = 1;
			edgeSeparation = s1;
			KEEP_BRANCH();
		}
		i = 2;
	}
	while (i < pairs)
	{
		__m128 d = _mm_sub_ps(centre, _mm_loadu_ps(&b->vertices[i].x));
		__m128 p = _mm_mul_ps(_mm_loadu_ps(&b->normals[i].x), d);
		__m128 sep = _mm_add_ps(p, _mm_shuffle_ps(p, p, _MM_SHUFFLE(2, 3, 0, 1)));
		if (_mm_movemask_ps(_mm_cmpgt_ps(sep, limit)) != 0)
		{
			return false;
		}
		cdReal s0 = _mm_cvtss_f32(sep);
		cdReal s1 = _mm_cvtss_f32(_mm_movehl_ps(sep, sep));
		if (s0 > edgeSeparation)
		{
			edge = i;
			edgeSeparation = s0;
			KEEP_BRANCH();
		}
		if (s1 > edgeSeparation)
		{
			edge = i + 1;
			edgeSeparation = s1;
			KEEP_BRANCH();
		}
		i += 2;
	}
	if (i < (size_t)count)
	{
		__m128 v = _mm_loadl_pi(_mm_setzero_ps(), (const __m64*)(const void*)&b->vertices[i]);
		__m128 n = _mm_loadl_pi(_mm_setzero_ps(), (const __m64*)(const void*)&b->normals[i]);
		__m128 p = _mm_mul_ps(n, _mm_sub_ps(centre, v));
		cdReal s0 = _mm_cvtss_f32(_mm_add_ps(p, _mm_shuffle_ps(p, p, _MM_SHUFFLE(2, 3, 0, 1))));
		if (s0 > limitValue)
		{
			return false;
		}
		if (s0 > edgeSeparation)
		{
			edge = i;
			edgeSeparation = s0;
			KEEP_BRANCH();
		}
	}
	*edgeOut = (int)edge;
	*separationOut = edgeSeparation;
	return true;
}
#endif

#if CD2_SEPARATION_SSE
/* The contact of a circle whose centre is given as (x, y, x, y) in a polygon's frame, in vector
 * lanes (float build on SSE2): CenterContactOnEdge's steps on a polygon core after PairScanEdge,
 * the same values bit for bit (each lane computes its scalar expression in the same order).
 * Returns whether there is a contact; then normal (lanes 0 and 1: from the polygon to the centre)
 * and point (lanes 0 and 1, and again in 2 and 3) are in the polygon's frame. Shared by the two
 * local forms, which differ only in where the centre comes from and where the contact goes. */
static inline bool PolygonCentreLanes(const cd2Polygon* b, __m128 centre, cdReal circleRadius,
									  cdReal speculativeDistance, __m128* normalOut, __m128* pointOut,
									  cdReal* separationOut, uint32_t* idOut)
{
	cdReal total = b->radius + circleRadius;
	int edgeFound;
	cdReal edgeSeparation;
	bool hit = PairScanEdge(b, centre, total + speculativeDistance, &edgeFound, &edgeSeparation);
	if (hit)
	{
		size_t edge = (size_t)edgeFound;
		size_t next = edge + 1 < (size_t)b->count ? edge + 1 : 0;
		/* (v1, v2): the edge's vertices; the normal in lanes 0 and 1. */
		__m128 ends =
			_mm_loadh_pi(_mm_loadl_pi(_mm_setzero_ps(), (const __m64*)(const void*)&b->vertices[edge]),
						 (const __m64*)(const void*)&b->vertices[next]);
		__m128 normal = _mm_loadl_pi(_mm_setzero_ps(), (const __m64*)(const void*)&b->normals[edge]);
		/* The core separation in lanes 0 and 1, so that the point's offset below needs no
		 * broadcast on the way from a vertex's distance. */
		__m128 coreSeparation = _mm_set1_ps(edgeSeparation);
		uint32_t id = (uint32_t)edge;
		if (edgeSeparation > CD_R(0.0))
		{
			/* (centre - v1, centre - v2), and along the tangent cd2LeftPerp(normal) = (-ny, nx):
			 * cd2Dot(tangent, centre - v1) in lane 0, cd2Dot(tangent, v2 - v1) in lane 2. */
			__m128 offsets = _mm_sub_ps(centre, ends);
			__m128 edgeVector = _mm_sub_ps(ends, _mm_movelh_ps(ends, ends)); /* lanes 2, 3: v2 - v1 */
			__m128 tangent = _mm_xor_ps(_mm_shuffle_ps(normal, normal, _MM_SHUFFLE(0, 1, 0, 1)),
										_mm_setr_ps(-0.0f, 0.0f, -0.0f, 0.0f));
			__m128 products =
				_mm_mul_ps(tangent, _mm_shuffle_ps(offsets, edgeVector, _MM_SHUFFLE(3, 2, 1, 0)));
			__m128 dots = _mm_add_ps(products, _mm_shuffle_ps(products, products, _MM_SHUFFLE(2, 3, 0, 1)));
			cdReal along = _mm_cvtss_f32(dots);
			cdReal extent = _mm_cvtss_f32(_mm_movehl_ps(dots, dots));
			/* The region of v1 (along <= 0) or of v2 (along >= extent); a NaN is in neither. */
			if (along <= CD_R(0.0) || along >= extent)
			{
				bool first = along <= CD_R(0.0);
				size_t vertex = first ? edge : next;
				/* LengthNoErrno and cd2Scale(1 / distance, offset), as CenterContactOnEdge, in
				 * lanes 0 and 1: each lane's sum adds the same two squares (lane 1 the other way
				 * round, the same value), so the square root, the quotient and the products are
				 * those of the scalar steps, without broadcasting a scalar between them. */
				__m128 offset = first ? offsets : _mm_movehl_ps(offsets, offsets);
				__m128 squares = _mm_mul_ps(offset, offset);
				__m128 distances = _mm_sqrt_ps(
					_mm_add_ps(squares, _mm_shuffle_ps(squares, squares, _MM_SHUFFLE(2, 3, 0, 1))));
				cdReal distance = _mm_cvtss_f32(distances);
				if (distance >= CD_REAL_EPSILON * CD_REAL_EPSILON && distance <= CD_REAL_MAX)
				{
					normal = _mm_mul_ps(_mm_div_ps(_mm_set1_ps(CD_R(1.0)), distances), offset);
					coreSeparation = distances;
					id = VERTEX_FEATURE | (uint32_t)vertex;
				}
			}
		}
		cdReal separation = _mm_cvtss_f32(coreSeparation) - total;
		hit = !(separation > speculativeDistance);
		/* The point centre + 0.5 * (polygon radius - circle radius - core separation) * normal. */
		__m128 half = _mm_mul_ps(_mm_set1_ps(CD_R(0.5)),
								 _mm_sub_ps(_mm_set1_ps(b->radius - circleRadius), coreSeparation));
		*pointOut = _mm_add_ps(centre, _mm_mul_ps(half, normal));
		*normalOut = normal;
		*separationOut = separation;
		*idOut = id;
	}
	return hit;
}
#endif

/* The circle's centre into the polygon's frame, the manifold built there and mapped back in
 * place (a manifold returned by one call and copied by the next waited on store forwarding). */
cd2Manifold cd2CollideCirclePolygonLocal(cd2Circle a, const cd2Polygon* b, cd2Transform xfB,
										 cdReal speculativeDistance)
{
	CD_ASSERT(b != NULL);
	/* The centre in B's frame, cd2InvTransformPoint(xfB, centre): one subtraction and one
	 * rotation on the way to the first edge test, whose branch every pair waits on (building the
	 * inverse transform first and placing the centre by it adds work before that branch). */
#if CD2_SEPARATION_SSE
	/* In the float build on SSE2 the whole contact in vector lanes, from the argument registers'
	 * pairs as they arrive (centre, xfB.p and xfB.q two floats each) to the stored normal and
	 * point (PolygonCentreLanes, then the mapping back), without moving scalars between registers
	 * and vectors on the way (on collide_bench_scenes' circle-polygon row those moves and a spill
	 * of the tangent cost more than the arithmetic). */
	__m128 cosine, sine;
	RotationLanes(xfB.q, &cosine, &sine);
	__m128 origin = PairLanes(xfB.p);
	__m128 inverseSine = _mm_xor_ps(sine, _mm_setr_ps(0.0f, -0.0f, 0.0f, -0.0f)); /* (s, -s) */
	__m128 placed = RotateLanes(cosine, inverseSine, _mm_sub_ps(PairLanes(a.center), origin));
	__m128 centre = _mm_movelh_ps(placed, placed); /* (x, y, x, y) */
	cd2Manifold m;
	__m128 normal = _mm_setzero_ps(), point = _mm_setzero_ps();
	cdReal separation = CD_R(0.0);
	uint32_t id = 0u;
	bool hit =
		PolygonCentreLanes(b, centre, a.radius, speculativeDistance, &normal, &point, &separation, &id);
	__m128 mapped = _mm_setzero_ps();
	if (hit)
	{
		/* The normal (negated: from the circle to the polygon) rotated and the point rotated and
		 * moved, in one vector: cd2RotateVector(q, cd2Neg(normal)) and cd2TransformPoint(xfB, point). */
		__m128 pair = _mm_movelh_ps(_mm_xor_ps(normal, _mm_set1_ps(-0.0f)), point);
		__m128 forwardSine = _mm_xor_ps(sine, _mm_setr_ps(-0.0f, 0.0f, -0.0f, 0.0f)); /* (-s, s) */
		mapped = RotateLanes(cosine, forwardSine, pair);
		/* Plus -0 in the normal's lanes: x + -0 is x for every x, signed zeros included. */
		mapped = _mm_add_ps(mapped, _mm_movelh_ps(_mm_set1_ps(-0.0f), origin));
	}
	/* One exit, the manifold written once: with a return per case GCC built it on the stack and
	 * copied it out, and the copy's wide loads of narrow stores waited on store forwarding. */
	m = EmptyManifold();
	if (hit)
	{
		/* The normal and the first point are adjacent (checked below the function). */
		_mm_storeu_ps(&m.normal.x, mapped);
		m.points[0].separation = separation;
		m.points[0].id = id;
		m.pointCount = 1;
	}
	return m;
#else
	cd2Rot q = xfB.q;
	cd2Vec center = cd2InvRotateVector(q, cd2Sub(a.center, xfB.p));
	cd2Manifold m;
	Core coreB;
	InitPolygonCore(&coreB, b);
	CenterContact contact = ScanCenterContact(&coreB, center, a.radius, speculativeDistance);
	m = EmptyManifold();
	if (contact.hit)
	{
		m.normal = cd2RotateVector(q, cd2Neg(contact.normal));
		m.points[0].point = cd2TransformPoint(xfB, contact.point);
		m.points[0].separation = contact.separation;
		m.points[0].id = contact.id;
		m.pointCount = 1;
	}
	return m;
#endif
}

cd2Manifold cd2CollidePolygonCircle(const cd2Polygon* a, cd2Circle b, cdReal speculativeDistance)
{
	CD_ASSERT(a != NULL);
	Core coreA;
	InitPolygonCore(&coreA, a);
	return CollideCoreCenter(&coreA, b.center, b.radius, speculativeDistance, false);
}

#if CD2_SEPARATION_SSE
/* cd2TransformPoint(xf, centre) as (x, y, x, y): the rotation, then the translation added. The
 * translation and the centre are read as (x, y, x, y) by one shuffle of their argument registers.
 * A circle centred on its body (the common case) lands on xf.p: the rotated zero centre (zeros)
 * plus a non-zero translation is the translation exactly, and skipping the rotation takes xf.q
 * (composed last by the caller) off the path to the first edge test. Tested in lanes: both centre
 * coordinates zero and both translation coordinates non-zero (a zero translation coordinate takes
 * the sum, whose zero sign can differ). */
static inline __m128 PlacedCentreLanes(cd2Transform xf, cd2Vec centre)
{
	__m128 origin = DoubledPairLanes(xf.p);
	__m128 local = DoubledPairLanes(centre);
	__m128 zero = _mm_setzero_ps();
	if ((_mm_movemask_ps(_mm_and_ps(_mm_cmpeq_ps(local, zero), _mm_cmpneq_ps(origin, zero))) & 3) == 3)
	{
		return origin;
	}
	__m128 cosine, sine;
	RotationLanes(xf.q, &cosine, &sine);
	__m128 forwardSine = _mm_xor_ps(sine, _mm_setr_ps(-0.0f, 0.0f, -0.0f, 0.0f)); /* (-s, s) */
	return _mm_add_ps(RotateLanes(cosine, forwardSine, local), origin);
}
#else
/* The polygon-first contact of a circle whose centre is given in the polygon's frame, written into
 * m (left as it is when there is none): the edge scan and the contact on a polygon core, nothing
 * mapped back. */
static inline void PolygonCentreManifold(cd2Manifold* m, const cd2Polygon* a, cd2Vec centre, cdReal radius,
										 cdReal speculativeDistance)
{
	Core coreA;
	InitPolygonCore(&coreA, a);
	CenterContact contact = ScanCenterContact(&coreA, centre, radius, speculativeDistance);
	if (contact.hit)
	{
		m->normal = contact.normal;
		m->points[0].point = contact.point;
		m->points[0].separation = contact.separation;
		m->points[0].id = contact.id;
		m->pointCount = 1;
	}
}
#endif

/* The circle's centre placed in the polygon's frame by xfB (cd2TransformPoint) and the manifold
 * built there: nothing to map back, the polygon being A. */
cd2Manifold cd2CollidePolygonCircleLocal(const cd2Polygon* a, cd2Circle b, cd2Transform xfB,
										 cdReal speculativeDistance)
{
	CD_ASSERT(a != NULL);
#if CD2_SEPARATION_SSE
	__m128 centre = PlacedCentreLanes(xfB, b.center);
	/* The manifold is written here, in the returned object, by both polygon-first forms: built by
	 * a shared helper, GCC assembled it on the stack and copied it out in 16-byte pieces read from
	 * narrower stores, waiting on store forwarding (15.9 ns a call instead of 10.8). */
	cd2Manifold m;
	__m128 normal = _mm_setzero_ps(), point = _mm_setzero_ps();
	cdReal separation = CD_R(0.0);
	uint32_t id = 0u;
	bool hit =
		PolygonCentreLanes(a, centre, b.radius, speculativeDistance, &normal, &point, &separation, &id);
	m = EmptyManifold();
	if (hit)
	{
		/* The normal and the first point are adjacent (checked below the functions). */
		_mm_storeu_ps(&m.normal.x, _mm_movelh_ps(normal, point));
		m.points[0].separation = separation;
		m.points[0].id = id;
		m.pointCount = 1;
	}
	return m;
#else
	cd2Manifold m = EmptyManifold();
	PolygonCentreManifold(&m, a, cd2TransformPoint(xfB, b.center), b.radius, speculativeDistance);
	return m;
#endif
}

/* The centre placed by xfB into the world and from there by xfA into the polygon's frame, as
 * cd2InvTransformPoint(xfA, cd2TransformPoint(xfB, centre)): for a circle no relative transform
 * (a rotation composed with another) is needed, only its centre, and nothing is composed and
 * passed by the caller. */
cd2Manifold cd2CollidePolygonCircleBodies(const cd2Polygon* a, cd2Transform xfA, cd2Circle b,
										  cd2Transform xfB, cdReal speculativeDistance)
{
	CD_ASSERT(a != NULL);
#if CD2_SEPARATION_SSE
	__m128 world = PlacedCentreLanes(xfB, b.center);
	__m128 cosine, sine;
	RotationLanes(xfA.q, &cosine, &sine);
	__m128 inverseSine = _mm_xor_ps(sine, _mm_setr_ps(0.0f, -0.0f, 0.0f, -0.0f)); /* (s, -s) */
	__m128 centre = RotateLanes(cosine, inverseSine, _mm_sub_ps(world, DoubledPairLanes(xfA.p)));
	/* Written here as in cd2CollidePolygonCircleLocal (see there). */
	cd2Manifold m;
	__m128 normal = _mm_setzero_ps(), point = _mm_setzero_ps();
	cdReal separation = CD_R(0.0);
	uint32_t id = 0u;
	bool hit =
		PolygonCentreLanes(a, centre, b.radius, speculativeDistance, &normal, &point, &separation, &id);
	m = EmptyManifold();
	if (hit)
	{
		_mm_storeu_ps(&m.normal.x, _mm_movelh_ps(normal, point));
		m.points[0].separation = separation;
		m.points[0].id = id;
		m.pointCount = 1;
	}
	return m;
#else
	cd2Manifold m = EmptyManifold();
	PolygonCentreManifold(&m, a, cd2InvTransformPoint(xfA, cd2TransformPoint(xfB, b.center)), b.radius,
						  speculativeDistance);
	return m;
#endif
}

#if CD2_SEPARATION_SSE
_Static_assert(offsetof(cd2Manifold, points) == 2 * sizeof(cdReal) &&
				   offsetof(cd2ManifoldPoint, point) == 0 && sizeof(cd2Vec) == 2 * sizeof(cdReal),
			   "the circle-polygon local forms store the normal and the first point as four adjacent floats");
#endif

cd2Manifold cd2CollidePolygonSegment(const cd2Polygon* a, cd2Segment b, cdReal speculativeDistance)
{
	Core coreA, coreB;
	InitPolygonCore(&coreA, a);
	InitSegmentCore(&coreB, b.p1, b.p2, CD_R(0.0));
	return CollideAny(&coreA, &coreB, speculativeDistance);
}

cd2Manifold cd2CollideSegmentSegment(cd2Segment a, cd2Segment b, cdReal speculativeDistance)
{
	Core coreA, coreB;
	InitSegmentCore(&coreA, a.p1, a.p2, CD_R(0.0));
	InitSegmentCore(&coreB, b.p1, b.p2, CD_R(0.0));
	return CollideAny(&coreA, &coreB, speculativeDistance);
}

/* ---- chain segments --------------------------------------------------------------------------- */

/* Whether the chain turns left (a convex corner, seen from the free side) from the unit direction
 * u1 to u2. */
static bool IsConvexTurn(cd2Vec u1, cd2Vec u2)
{
	return cd2Cross(u1, u2) > CHAIN_FLAT_TOLERANCE;
}

static cd2Manifold CollideChain(const cd2ChainSegment* chain, const Core* shape, cd2Vec shapeCenter,
								cdReal speculativeDistance)
{
	cd2Vec edge = cd2Sub(chain->p2, chain->p1);
	Core segment;
	InitSegmentCore(&segment, chain->p1, chain->p2, CD_R(0.0));
	if (segment.count != 2)
	{
		return EmptyManifold(); /* a zero-length chain segment has no side */
	}
	cd2Vec n = segment.normals[0];
	cd2Vec direction = cd2LeftPerp(n); /* the normalized edge, exactly */
	if (cd2Dot(n, cd2Sub(shapeCenter, chain->p1)) < CD_R(0.0))
	{
		return EmptyManifold(); /* behind the one-sided segment */
	}
	cd2Manifold manifold = CollideAny(&segment, shape, speculativeDistance);
	if (manifold.pointCount == 0)
	{
		return manifold;
	}

	cd2Vec m = manifold.normal;
	cdReal side = cd2Cross(n, m); /* > 0: tilted towards p2, < 0: towards p1 */
	bool admissible;
	if (cd2Dot(m, n) < CD_R(0.0))
	{
		admissible = false;
	}
	else if (side > CD_R(0.0))
	{
		cd2Vec next = cd2Normalize(cd2Sub(chain->ghost2, chain->p2));
		bool convex = IsConvexTurn(direction, next);
		admissible = convex && cd2Cross(m, cd2RightPerp(next)) >= CD_R(0.0);
		/* Past the next segment's normal at a convex corner: that segment reports the contact. */
		if (convex && !admissible)
		{
			return EmptyManifold();
		}
	}
	else if (side < CD_R(0.0))
	{
		cd2Vec previous = cd2Normalize(cd2Sub(chain->p1, chain->ghost1));
		bool convex = IsConvexTurn(previous, direction);
		admissible = convex && cd2Cross(cd2RightPerp(previous), m) >= CD_R(0.0);
		if (convex && !admissible)
		{
			return EmptyManifold();
		}
	}
	else
	{
		admissible = true;
	}
	if (admissible)
	{
		return manifold;
	}

	/* Only the segment's own normal is allowed here: the contact seen from its face, within its
	 * extent (beyond an end, a flat or concave neighbour's face takes over). */
	if (shape->count == 1)
	{
		cd2Vec center = shape->vertices[0];
		cdReal along = cd2Dot(cd2Sub(center, chain->p1), edge);
		if (along < CD_R(0.0) || along > cd2Dot(edge, edge))
		{
			return EmptyManifold();
		}
		cdReal coreSeparation = cd2Dot(n, cd2Sub(center, chain->p1));
		cdReal separation = coreSeparation - shape->radius;
		cd2Manifold faceManifold = EmptyManifold();
		if (separation <= speculativeDistance)
		{
			faceManifold.normal = n;
			AddPoint(&faceManifold, cd2MulSub(center, CD_R(0.5) * (shape->radius + coreSeparation), n),
					 separation, 0u);
		}
		return faceManifold;
	}
	cd2Manifold faceManifold;
	Clip(&faceManifold, &segment, 0, shape, false, speculativeDistance, false);
	return faceManifold;
}

cd2Manifold cd2CollideChainSegmentCircle(const cd2ChainSegment* a, cd2Circle b, cdReal speculativeDistance)
{
	CD_ASSERT(a != NULL);
	Core core;
	InitPointCore(&core, b.center, b.radius);
	return CollideChain(a, &core, b.center, speculativeDistance);
}

cd2Manifold cd2CollideChainSegmentCapsule(const cd2ChainSegment* a, cd2Capsule b, cdReal speculativeDistance)
{
	CD_ASSERT(a != NULL);
	Core core;
	InitSegmentCore(&core, b.p1, b.p2, b.radius);
	return CollideChain(a, &core, cd2Lerp(b.p1, b.p2, CD_R(0.5)), speculativeDistance);
}

cd2Manifold cd2CollideChainSegmentPolygon(const cd2ChainSegment* a, const cd2Polygon* b,
										  cdReal speculativeDistance)
{
	CD_ASSERT(a != NULL && b != NULL);
	Core core;
	InitPolygonCore(&core, b);
	return CollideChain(a, &core, b->centroid, speculativeDistance);
}

/* ---- dispatcher ------------------------------------------------------------------------------- */

/* Rank in the canonical order of the pair functions: Circle, Capsule, Polygon (AABB, box), Segment. */
static int CanonicalRank(cd2ShapeType type)
{
	switch (type)
	{
		case CD2_SHAPE_CIRCLE:
			return 0;
		case CD2_SHAPE_CAPSULE:
			return 1;
		case CD2_SHAPE_AABB:
		case CD2_SHAPE_BOX:
		case CD2_SHAPE_POLYGON:
			return 2;
		default:
			return 3;
	}
}

static void InitShapeCore(Core* core, const cd2Shape* shape)
{
	switch (shape->type)
	{
		case CD2_SHAPE_CIRCLE:
			InitPointCore(core, shape->circle.center, shape->circle.radius);
			break;
		case CD2_SHAPE_CAPSULE:
			InitSegmentCore(core, shape->capsule.p1, shape->capsule.p2, shape->capsule.radius);
			break;
		case CD2_SHAPE_AABB:
			InitRectangleCore(core, cd2AabbCenter(shape->aabb), cd2MakeVec(CD_R(1.0), CD_R(0.0)),
							  cd2MakeVec(CD_R(0.0), CD_R(1.0)),
							  CD_R(0.5) * (shape->aabb.max.x - shape->aabb.min.x),
							  CD_R(0.5) * (shape->aabb.max.y - shape->aabb.min.y));
			break;
		case CD2_SHAPE_BOX:
		{
			/* Normalized because validators accept rotations slightly off unit length. */
			cd2Rot q = cd2NormalizeRot(shape->box.rotation);
			InitRectangleCore(core, shape->box.center, cd2MakeVec(q.c, q.s), cd2MakeVec(-q.s, q.c),
							  shape->box.halfExtents.x, shape->box.halfExtents.y);
			break;
		}
		case CD2_SHAPE_POLYGON:
			InitPolygonCore(core, &shape->polygon);
			break;
		default:
			InitSegmentCore(core, shape->segment.p1, shape->segment.p2, CD_R(0.0));
			break;
	}
}

cd2Manifold cd2Collide(const cd2Shape* a, const cd2Shape* b, cdReal speculativeDistance)
{
	CD_ASSERT(a != NULL && b != NULL);
	/* A pair with a typed function in the pair table (pairs2.h) calls it, in the table's (enum)
	 * order; the CORE pairs (AABBs and boxes, which collide as polygons) take the cores below. */
	{
		bool flip = a->type > b->type;
		const cd2Shape* first = flip ? b : a;
		const cd2Shape* second = flip ? a : b;
		switch (CD2_PAIR_KEY(first->type, second->type))
		{
#define CD2_COLLIDE_TYPED_CASE(A, B, Collide)                                                                \
	case CD2_PAIR_KEY(CD2_TYPE_##A, CD2_TYPE_##B):                                                           \
	{                                                                                                        \
		cd2Manifold typed = Collide(CD2_SHAPE_ARG(A, first), CD2_SHAPE_ARG(B, second), speculativeDistance); \
		return flip ? Flipped(typed) : typed;                                                                \
	}
#define CD2_COLLIDE_CASE(A, B, Overlap, Distance, Collide)                                                   \
	CD_PAIR_TYPED(Collide, CD2_COLLIDE_TYPED_CASE)(A, B, Collide)
			CD2_PAIR_TABLE(CD2_COLLIDE_CASE)
#undef CD2_COLLIDE_CASE
#undef CD2_COLLIDE_TYPED_CASE
			default:
				break;
		}
	}
	bool swap = CanonicalRank(a->type) > CanonicalRank(b->type);
	if (swap)
	{
		const cd2Shape* t = a;
		a = b;
		b = t;
	}
	Core coreA, coreB;
	InitShapeCore(&coreA, a);
	InitShapeCore(&coreB, b);
	cd2Manifold manifold = CollideAny(&coreA, &coreB, speculativeDistance);
	return swap ? Flipped(manifold) : manifold;
}
