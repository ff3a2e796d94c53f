/* collide: 3D contact manifolds.
 *
 * Two routines cover the pairs:
 * - polytope against polytope (boxes, hulls, triangles): the separating axis test picks the
 *   reference face (A's unless B's separates noticeably more) or an edge pair (only when it
 *   separates noticeably more than both faces, so the choice does not flicker). A face contact
 *   clips the incident face (the other polytope's face most anti-parallel to the reference
 *   normal) against the reference face's side planes (Sutherland-Hodgman), keeps the points below
 *   the reference face plus the speculative distance and reduces them to 4; an edge contact is
 *   one point at the closest points of the two edges. When the polytopes are apart and no SAT
 *   axis realizes their distance (closest features vertex-vertex or vertex-edge), the GJK closest
 *   points give one point along the gap.
 * - rounded core (sphere: a point, capsule: a segment) against a polytope: GJK between the core
 *   and the polytope when the core is outside (normal along the closest points); when the core
 *   touches or enters the polytope, the separating axis test over the polytope's faces and the
 *   segment-edge crosses. A capsule parallel to the contact face gets 2 points: its segment
 *   clipped to the face's side planes.
 * Sphere and capsule pairs among themselves are closed-form. Points are reported midway between
 * the surfaces; the normal points from A to B. */
#include "collide/manifold3.h"

#include "epa3.h"
#include "pairs3.h"
#include "sat3.h"
#include "sat3_box.h"
#include "sat3_support.h"

#include <stddef.h>

/* Tie tolerances, as fractions of the pair's size: B's face is preferred over A's, and an edge
 * pair over the faces, only when it separates by this much more. */
#define FACE_BIAS CD_R(1.0e-4)
#define EDGE_BIAS CD_R(1.0e-4)
/* A separated pair whose best SAT separation is within this fraction of the size of the GJK
 * distance is a face or edge contact; otherwise the closest features are vertices. */
#define REALIZED_TOLERANCE CD_R(1.0e-4)
/* A capsule counts as lying on a face when the sine of its tilt is below this: the clipped
 * points are then on the capsule's surface within 5e-5 of its radius. */
#define PARALLEL_CAPSULE CD_R(1.0e-2)
/* The closest-point normal is aligned with a face when their cosine exceeds this. */
#define FACE_ALIGNED CD_R(0.9999)
/* Round-off of a point computed from the shapes' coordinates, relative to their magnitude. */
#define ROUND_OFF_TOLERANCE (CD_R(64.0) * CD_REAL_EPSILON)

/* Clip buffers: the incident face's vertices plus one per reference side. Faces of more vertices
 * (cylinder caps of hundreds of segments) lose the vertices beyond the buffer. */
#define MAX_CLIP 128
#define SIDE_TAG 64u

#define ID_VERTEX_PAIR 0x3fffffffu

/* Out of line: the polytope path is cd3CollideBoxBox's rare fallback, and inlined there it would
 * crowd the common box-box manifold's hot path (code layout; bench/manifold3 shows it). */
#if defined(__GNUC__) || defined(__clang__)
#define MANIFOLD_NOINLINE __attribute__((noinline))
#else
#define MANIFOLD_NOINLINE
#endif
/* Inlined into its hot caller even when a rare one calls it too (FaceContact's clip loop). */
#if defined(__GNUC__) || defined(__clang__)
#define MANIFOLD_INLINE inline __attribute__((always_inline))
#else
#define MANIFOLD_INLINE inline
#endif

typedef struct ClipVertex
{
	cd3Vec p;
	uint32_t tag; /* the line the polygon follows from this vertex to the next */
} ClipVertex;

/* Zero-initialized: an empty manifold copied in a few wide moves (field stores, or a memset that
 * compiles to rep stos, cost more than a box-box contact's SAT). */
static const cd3Manifold EMPTY_MANIFOLD;

static cd3Manifold EmptyManifold(void)
{
	return EMPTY_MANIFOLD;
}

static void AddPoint(cd3Manifold* m, cd3Vec point, cdReal separation, uint32_t id)
{
	cd3ManifoldPoint* p = &m->points[m->pointCount++];
	p->point = point;
	p->separation = separation;
	p->id = id;
}

/* Round-off of the points at p and of the shapes of sizes `size`. */
static cdReal RoundOff(cd3Vec p, cdReal size)
{
	cd3Vec abs = cd3Abs(p);
	return ROUND_OFF_TOLERANCE * (size + cdMax(abs.x, cdMax(abs.y, abs.z)));
}

/* p lies in the solid shape s, or on the triangle s, within `tolerance` (per face plane). */
static bool InsideShape(const cd3Shape* s, cd3Vec p, cdReal tolerance)
{
	switch (s->type)
	{
		case CD3_SHAPE_AABB:
			return p.x >= s->aabb.min.x - tolerance && p.x <= s->aabb.max.x + tolerance &&
				   p.y >= s->aabb.min.y - tolerance && p.y <= s->aabb.max.y + tolerance &&
				   p.z >= s->aabb.min.z - tolerance && p.z <= s->aabb.max.z + tolerance;
		case CD3_SHAPE_BOX:
		{
			cd3Vec l = cd3InvRotateVector(s->box.rotation, cd3Sub(p, s->box.center));
			cd3Vec h = s->box.halfExtents;
			return cdAbs(l.x) <= h.x + tolerance && cdAbs(l.y) <= h.y + tolerance &&
				   cdAbs(l.z) <= h.z + tolerance;
		}
		case CD3_SHAPE_HULL:
		{
			const cd3Hull* hull = s->hull.hull;
			cd3Vec l = cd3InvTransformPoint(s->hull.transform, p);
			for (int i = 0; i < hull->faceCount; ++i)
			{
				if (!(cd3Dot(hull->planes[i].normal, l) - hull->planes[i].offset <= tolerance))
				{
					return false;
				}
			}
			return true;
		}
		case CD3_SHAPE_TRIANGLE:
			return cd3VecDistance(cd3ClosestPointOnTriangle(s->triangle, p), p) <= tolerance;
		default:
			return false;
	}
}

/* The reference feature is chosen with a bias for stability from frame to frame (FACE_BIAS,
 * EDGE_BIAS), so a face contact can be deeper along its normal than the exact (smallest) depth by
 * up to the bias; and clipping can lose the deepest vertex at a tie of incident faces. A mismatch
 * between the smallest separation and the exact signed separation the separating axis test (or
 * EPA) proves (`exact`, within `limit` of the manifold's; a larger mismatch is a different contact
 * and is left alone) is removed only within round-off of the coordinates. Beyond it the points
 * keep their separations along the reported normal: that is the depth B must move along that
 * normal to stop overlapping (lifting the deepest point to the smallest depth, as this code once
 * did, left a pair moved by the reported depth along the biased normal still overlapping by up to
 * the bias, 3e-4 for unit shapes, and the solver under-resolved it). Returns the mismatch
 * exact - deepest (zero: nothing to do). */
static cdReal DepthMismatch(const cd3Manifold* m, cdReal exact, cdReal limit)
{
	if (m->pointCount == 0)
	{
		return CD_R(0.0);
	}
	cdReal deepest = m->points[0].separation;
	for (int i = 1; i < m->pointCount; ++i)
	{
		deepest = cdMin(deepest, m->points[i].separation);
	}
	cdReal delta = exact - deepest;
	return cdAbs(delta) <= limit ? delta : CD_R(0.0);
}

/* Every point shifted by delta along the normal, A's side staying in place. */
static void ShiftDepth(cd3Manifold* m, cdReal delta)
{
	for (int i = 0; i < m->pointCount; ++i)
	{
		m->points[i].separation += delta;
		m->points[i].point = cd3MulAdd(m->points[i].point, CD_R(0.5) * delta, m->normal);
	}
}

/* A mismatch within the round-off of the points' coordinates (the SAT's closed form and the
 * clipping's arithmetic differ in their last bits): any side may move. */
static bool DepthWithinRoundOff(const cd3Manifold* m, cdReal delta, cdReal size)
{
	cdReal bound = ROUND_OFF_TOLERANCE * size;
	if (cdAbs(delta) <= bound)
	{
		return true; /* the common case, without the coordinates */
	}
	cd3Vec abs = cd3Abs(m->points[0].point);
	return cdAbs(delta) <= bound + ROUND_OFF_TOLERANCE * cdMax(abs.x, cdMax(abs.y, abs.z));
}

/* MatchDepth for a nonzero mismatch delta: out of line (rare beyond round-off). */
MANIFOLD_NOINLINE static void MatchDepthBy(cd3Manifold* m, cdReal delta, const cd3Polytope* a,
										   const cd3Polytope* b)
{
	if (DepthWithinRoundOff(m, delta, a->size + b->size))
	{
		ShiftDepth(m, delta);
	}
}

static void MatchDepth(cd3Manifold* m, cdReal exact, cdReal limit, const cd3Polytope* a, const cd3Polytope* b)
{
	cdReal delta = DepthMismatch(m, exact, limit);
	if (delta != CD_R(0.0))
	{
		MatchDepthBy(m, delta, a, b);
	}
}

static cdReal ManifoldMinSeparation(const cd3Manifold* m)
{
	cdReal s = CD_REAL_MAX;
	for (int i = 0; i < m->pointCount; ++i)
	{
		s = cdMin(s, m->points[i].separation);
	}
	return s;
}

/* MatchDepth for two boxes (cd3CollideBoxBox), called when the deepest point is not at the exact
 * depth: out of line, with the size and the shapes for the checks built only then. False when the
 * contact missed the overlap (every point farther apart than the SAT's separation allows, as in
 * CollidePolytopesSat): a flat box's rim as the reference face, the other box's face beside it
 * (float: points at separation +3e6 for boxes that overlap by 3.75e6). */
MANIFOLD_NOINLINE static bool MatchBoxDepth(cd3Manifold* m, cdReal exact, const cd3Box* a, const cd3Box* b)
{
	/* The size bound from the 1-norms: no square roots. */
	cdReal size = CD_R(2.0) * (cdAbs(a->halfExtents.x) + cdAbs(a->halfExtents.y) + cdAbs(a->halfExtents.z) +
							   cdAbs(b->halfExtents.x) + cdAbs(b->halfExtents.y) + cdAbs(b->halfExtents.z));
	cdReal limit = (FACE_BIAS + EDGE_BIAS) * size;
	/* Nor may the deepest point be apart beyond round-off, as in CollidePolytopesSat: a box reduced
	 * to a segment 2 long through a box 1e-4 across (double) took its face within the bias of the
	 * sizes' sum, whose clip of the other box kept only points at separation +2.7e-5 for boxes
	 * that overlap by 3.2e-5. The polytope path's ties follow the smaller box. */
	cdReal smallest = ManifoldMinSeparation(m);
	if (smallest > exact + limit || smallest > RoundOff(m->points[0].point, size))
	{
		return false;
	}
	cdReal delta = DepthMismatch(m, exact, limit);
	if (delta == CD_R(0.0))
	{
		return true;
	}
	if (DepthWithinRoundOff(m, delta, size))
	{
		ShiftDepth(m, delta);
	}
	return true;
}

static cd3Manifold Flipped(cd3Manifold m)
{
	m.normal = cd3Neg(m.normal);
	return m;
}

/* A unit vector for coincident centres: up. */
static cd3Vec DefaultNormal(void)
{
	return cd3MakeVec(CD_R(0.0), CD_R(1.0), CD_R(0.0));
}

/* ---- reduction to 4 points ------------------------------------------------------------------ */

typedef struct Candidate
{
	cd3Vec point;
	cdReal separation;
	uint32_t id;
} Candidate;

/* Keeps the deepest point, the point farthest from it, the point that makes the largest triangle
 * with those two, and the point that adds the most area on the other side of the triangle. */
static int ReducePoints(Candidate* c, int count, cd3Vec normal, Candidate* out)
{
	if (count <= 4)
	{
		for (int i = 0; i < count; ++i)
		{
			out[i] = c[i];
		}
		return count;
	}
	int i0 = 0;
	for (int i = 1; i < count; ++i)
	{
		if (c[i].separation < c[i0].separation)
		{
			i0 = i;
		}
	}
	int i1 = -1;
	cdReal best = -CD_R(1.0);
	for (int i = 0; i < count; ++i)
	{
		cdReal d = cd3LengthSquared(cd3Sub(c[i].point, c[i0].point));
		if (i != i0 && d > best)
		{
			best = d;
			i1 = i;
		}
	}
	int i2 = -1;
	best = -CD_REAL_MAX;
	cdReal bestSigned = CD_R(0.0);
	cd3Vec e01 = cd3Sub(c[i1].point, c[i0].point);
	for (int i = 0; i < count; ++i)
	{
		if (i == i0 || i == i1)
		{
			continue;
		}
		cdReal area = cd3Dot(normal, cd3Cross(e01, cd3Sub(c[i].point, c[i0].point)));
		if (cdAbs(area) > best)
		{
			best = cdAbs(area);
			bestSigned = area;
			i2 = i;
		}
	}
	/* The fourth point lies on the other side: it adds the most area to the edges of the
	 * triangle i0-i1-i2 it faces. */
	cdReal orientation = bestSigned >= CD_R(0.0) ? CD_R(1.0) : -CD_R(1.0);
	int i3 = -1;
	best = -CD_REAL_MAX;
	int tri[3] = {i0, i1, i2};
	for (int i = 0; i < count; ++i)
	{
		if (i == i0 || i == i1 || i == i2)
		{
			continue;
		}
		cdReal gain = -CD_REAL_MAX;
		for (int k = 0; k < 3; ++k)
		{
			cd3Vec p = c[tri[k]].point;
			cd3Vec q = c[tri[(k + 1) % 3]].point;
			cdReal area = -orientation * cd3Dot(normal, cd3Cross(cd3Sub(q, p), cd3Sub(c[i].point, p)));
			gain = cdMax(gain, area);
		}
		if (gain > best)
		{
			best = gain;
			i3 = i;
		}
	}
	out[0] = c[i0];
	out[1] = c[i1];
	out[2] = c[i2];
	out[3] = c[i3];
	return 4;
}

/* ---- polytope against polytope --------------------------------------------------------------- */

static cd3Vec WorldVertex(const cd3Polytope* p, int vertex)
{
	return cd3TransformPoint(p->transform, p->vertices[vertex]);
}

static int IncidentFace(const cd3Polytope* p, cd3Vec worldNormal)
{
	cd3Vec local = cd3InvRotateVector(p->transform.q, worldNormal);
	cdReal dot;
	return cd3PlaneSupportIndex(p->planes, p->faceCount, cd3Neg(local), &dot);
}

/* The incident face for a reference normal: among the faces around the polytope's deepest vertex
 * along -normal, the most anti-parallel. The deepest vertex then belongs to the incident polygon,
 * and when the reference face is the axis of least penetration it projects inside the reference
 * face, so the clipped manifold keeps the exact depth. */
static int IncidentFaceAtSupport(const cd3Polytope* p, cd3Vec worldNormal)
{
	cd3Vec local = cd3InvRotateVector(p->transform.q, worldNormal);
	int deepest = cd3SupportIndex(p->vertices, p->vertexCount, cd3Neg(local));
	int start = -1;
	for (int e = 0; e < p->edgeCount; ++e)
	{
		if (p->edges[e].origin == deepest)
		{
			start = e;
			break;
		}
	}
	if (start < 0)
	{
		return IncidentFace(p, worldNormal);
	}
	int best = p->edges[start].face;
	cdReal bestDot = CD_REAL_MAX;
	int e = start;
	int guard = 0;
	do
	{
		int f = p->edges[e].face;
		cdReal d = cd3Dot(p->planes[f].normal, local);
		if (d < bestDot)
		{
			bestDot = d;
			best = f;
		}
		e = p->edges[p->edges[e].twin].next;
	} while (e != start && ++guard < p->edgeCount);
	return best;
}

static MANIFOLD_INLINE int ClipToPlane(const ClipVertex* in, int count, cd3Vec normal, cd3Vec origin,
									   uint32_t tag, ClipVertex* out)
{
	int n = 0;
	for (int i = 0; i < count && n + 2 <= MAX_CLIP; ++i)
	{
		ClipVertex p = in[i];
		ClipVertex q = in[i + 1 < count ? i + 1 : 0];
		cdReal dp = cd3Dot(normal, cd3Sub(p.p, origin));
		cdReal dq = cd3Dot(normal, cd3Sub(q.p, origin));
		if (dp <= CD_R(0.0))
		{
			out[n++] = p;
		}
		if ((dp <= CD_R(0.0)) != (dq <= CD_R(0.0)))
		{
			cdReal t = dp / (dp - dq);
			ClipVertex x;
			x.p = cd3Lerp(p.p, q.p, t);
			/* Going out, the polygon follows the side line; coming back in, the rest of p-q. */
			x.tag = dp <= CD_R(0.0) ? tag : p.tag;
			out[n++] = x;
		}
	}
	return n;
}

static uint32_t PackFaceId(int reference, int incident, uint32_t inTag, uint32_t outTag, bool flip)
{
	uint32_t id = ((uint32_t)reference & 0xffu) | (((uint32_t)incident & 0xffu) << 8) |
				  ((inTag & 0x7fu) << 16) | ((outTag & 0x7fu) << 23);
	return flip ? id | CD3_FEATURE_FLIP : id;
}

/* The mean of the face's vertices (world). */
static cd3Vec FaceCentre(const cd3Polytope* p, int face)
{
	cd3Vec sum = cd3MakeVec(CD_R(0.0), CD_R(0.0), CD_R(0.0));
	int count = 0;
	int e = p->faceEdges[face];
	do
	{
		sum = cd3Add(sum, WorldVertex(p, p->edges[e].origin));
		++count;
		e = p->edges[e].next;
	} while (e != p->faceEdges[face] && count < p->edgeCount);
	return cd3Scale(CD_R(1.0) / (cdReal)count, sum);
}

/* The ends of a face with no area (a box with zero extents): its first vertex and the vertex
 * farthest from it (the same vertex for a face that is a point). */
static void FaceEnds(const cd3Polytope* p, int face, cd3Vec* r0, cd3Vec* r1)
{
	int e = p->faceEdges[face];
	*r0 = WorldVertex(p, p->edges[e].origin);
	*r1 = *r0;
	cdReal farthest = CD_R(0.0);
	int guard = 0;
	do
	{
		cd3Vec v = WorldVertex(p, p->edges[e].origin);
		cdReal d = cd3LengthSquared(cd3Sub(v, *r0));
		if (d > farthest)
		{
			farthest = d;
			*r1 = v;
		}
		e = p->edges[e].next;
	} while (e != p->faceEdges[face] && ++guard < p->edgeCount);
}

/* An edge of a face in world coordinates shorter than this, relative to the magnitude of the
 * coordinates, is round-off (each world vertex carries a few epsilon of it from the rotation):
 * its direction, and so its side plane, is noise (a box 2.5e-4 wide at 1e9 in float had a face
 * edge 6e-8 long, in a direction the box does not have). One epsilon: a face a few units of the
 * last place wide still clips as a face (a box of size 2 at 1e7 in float keeps its 4 points), and
 * a hull's edges (at least the builder's weld distance, 16 epsilon of its extent) stay above it
 * unless the hull lies 10 extents from the origin. */
#define EDGE_ROUND_OFF CD_REAL_EPSILON

/* The square of that length for a face with vertex v of a polytope of the given size: from the
 * Euclidean magnitudes, (size + |v|)^2 <= 2 (size^2 + |v|^2), without branches (hot path). */
static cdReal EdgeFloorSquared(cd3Vec v, cdReal size)
{
	return CD_R(2.0) * EDGE_ROUND_OFF * EDGE_ROUND_OFF * (size * size + cd3LengthSquared(v));
}

/* The face (world normal n) lies within sqrt(floorSquared) of a segment (or a point) in world
 * coordinates: a box with zero extents, or one tiny against its coordinates (2.5e-4 at 1e9 in
 * float, whose rotated face is a segment with round-off edges 6e-8 long). */
static bool FaceIsThin(const cd3Polytope* p, int face, cdReal floorSquared)
{
	cd3Vec r0, r1;
	FaceEnds(p, face, &r0, &r1);
	cd3Vec axis = cd3Sub(r1, r0);
	cdReal length2 = cd3LengthSquared(axis);
	if (!(length2 > floorSquared))
	{
		return true;
	}
	int guard = 0;
	int e = p->faceEdges[face];
	do
	{
		/* |cross(v - r0, axis)| / |axis|: the distance from the line, compared squared. */
		cd3Vec v = WorldVertex(p, p->edges[e].origin);
		if (cd3LengthSquared(cd3Cross(cd3Sub(v, r0), axis)) > floorSquared * length2)
		{
			return false;
		}
		e = p->edges[e].next;
	} while (e != p->faceEdges[face] && ++guard < p->edgeCount);
	return true;
}

/* The incident face of SegmentFaceContact has no area either (FaceIsThin with the floor of its
 * own coordinates): a face of a box with zero extents, or of a box tiny against its coordinates
 * (2.5e-4 at 1e9 in float, whose world vertices differ by round-off only: clipped as a face, it
 * gave a point 8.4e6 off the box). */
static bool FaceHasNoArea(const cd3Polytope* p, int face)
{
	return FaceIsThin(p, face,
					  EdgeFloorSquared(WorldVertex(p, p->edges[p->faceEdges[face]].origin), p->size));
}

/* Narrows [*lo, *hi] to the t with start + t * rate <= limit. */
static void ClipInterval(cdReal start, cdReal rate, cdReal limit, cdReal* lo, cdReal* hi)
{
	if (rate > CD_R(0.0))
	{
		*hi = cdMin(*hi, (limit - start) / rate);
	}
	else if (rate < CD_R(0.0))
	{
		*lo = cdMax(*lo, (limit - start) / rate);
	}
	else if (!(start <= limit))
	{
		*lo = CD_R(1.0);
		*hi = CD_R(0.0);
	}
}

/* A reference face with no area (a box with zero extents): the segment r0-r1, or the point r0
 * when r1 == r0. Its side planes would be a slab of zero width, which round-off of the incident
 * polygon's coordinates crosses, and its ends have zero-length edges, so clipping the incident
 * polygon does not work. Instead the segment is clipped to where the lines along the face normal
 * n cross the incident face: up to two points, none when every line passes beside it (the
 * callers then try the other features, or the distance). A point's line may pass within a slack
 * of the shapes' size (REALIZED_TOLERANCE) beside the face; a segment clips exactly: at 1e9 the
 * slack is 1e5, enough to take a point well outside a triangle. flip: ref is B. */
static cd3Manifold SegmentFaceContact(const cd3Polytope* ref, cd3Vec r0, cd3Vec r1, cd3Vec n, int face,
									  const cd3Polytope* inc, int incident, bool flip,
									  cdReal speculativeDistance, cdReal size)
{
	cd3Manifold m = EmptyManifold();
	cd3Plane local = inc->planes[incident];
	cd3Vec incNormal = cd3RotateVector(inc->transform.q, local.normal);
	cdReal incOffset = local.offset + cd3Dot(incNormal, inc->transform.p);
	cdReal rate = cd3Dot(incNormal, n);
	if (!(rate < CD_R(0.0)))
	{
		return m;
	}
	if (FaceHasNoArea(inc, incident))
	{
		/* The incident face is a segment or a point too (two boxes with zero extents): its side
		 * planes bound nothing. The closest points of the two, when they lie along n within
		 * round-off (otherwise the SAT's axis is not the contact's: none). */
		cd3Segment reference = {r0, r1}, other;
		FaceEnds(inc, incident, &other.p1, &other.p2);
		cd3ClosestPoints cp = cd3ClosestPointsSegmentSegment(reference, other);
		cd3Vec gap = cd3Sub(cp.pointB, cp.pointA);
		cdReal separation = cd3Dot(n, gap);
		cdReal magnitude = size + cdMax(cd3Length(cp.pointA), cd3Length(cp.pointB));
		if (separation <= speculativeDistance &&
			cd3Length(cd3MulSub(gap, separation, n)) <= ROUND_OFF_TOLERANCE * magnitude)
		{
			AddPoint(&m, cd3MulAdd(cp.pointA, CD_R(0.5) * separation, n), separation,
					 PackFaceId(face, incident, 0u, 0u, flip));
			m.normal = flip ? cd3Neg(n) : n;
		}
		return m;
	}
	/* Along the segment (t in [0, 1]) the separation to the incident plane is s0 + t * sRate and
	 * the crossing c0 + t * dc. */
	cd3Vec d = cd3Sub(r1, r0);
	cdReal s0 = (incOffset - cd3Dot(incNormal, r0)) / rate;
	cdReal sRate = -cd3Dot(incNormal, d) / rate;
	if (!(s0 <= speculativeDistance) && !(s0 + sRate <= speculativeDistance))
	{
		return m;
	}
	cd3Vec c0 = cd3MulAdd(r0, s0, n);
	cd3Vec dc = cd3MulAdd(d, sRate, n);
	cdReal lo = CD_R(0.0), hi = CD_R(1.0);
	cdReal slackLo = CD_R(0.0), slackHi = CD_R(1.0);
	cdReal exactLo = CD_R(0.0), exactHi = CD_R(1.0);
	int guard = 0;
	int e = inc->faceEdges[incident];
	do
	{
		cd3Vec v0 = WorldVertex(inc, inc->edges[e].origin);
		cd3Vec v1 = WorldVertex(inc, inc->edges[inc->edges[e].next].origin);
		cd3Vec edge = cd3Sub(v1, v0);
		cd3Vec side = cd3Cross(edge, incNormal);
		cdReal start = cd3Dot(side, cd3Sub(c0, v0));
		cdReal along = cd3Dot(side, dc);
		/* Within round-off of the side (8 epsilon of the magnitudes: start's own error is a few):
		 * a segment that grazes it (lying along the edge as seen along n) has start and rate both
		 * round-off, whose ratio would cut it anywhere (a segment touching a triangle's corner
		 * was cut 1.6e6 from it, in float at 1.2e6). */
		cd3Vec abs = cd3Abs(v0);
		cdReal slack = CD_R(8.0) * CD_REAL_EPSILON * (size + cdMax(abs.x, cdMax(abs.y, abs.z)));
		ClipInterval(start, along, slack * cd3Length(edge), &lo, &hi);
		ClipInterval(start, along, REALIZED_TOLERANCE * size * cd3Length(edge), &slackLo, &slackHi);
		ClipInterval(start, along, CD_R(0.0), &exactLo, &exactHi);
		e = inc->edges[e].next;
	} while (e != inc->faceEdges[incident] && ++guard < inc->edgeCount);
	if (!(lo <= hi))
	{
		if (cd3LengthSquared(d) > CD_R(0.0) || !(slackLo <= slackHi))
		{
			return m;
		}
		lo = CD_R(0.5) * (slackLo + slackHi);
		hi = lo;
	}
	cdReal ts[2] = {lo, hi};
	int count = hi > lo && cd3LengthSquared(d) > CD_R(0.0) ? 2 : 1;
	for (int i = 0; i < count; ++i)
	{
		cdReal separation = s0 + ts[i] * sRate;
		cd3Vec onReference = cd3MulAdd(r0, ts[i], d);
		cd3Vec onIncident = cd3MulAdd(onReference, separation, n);
		/* The slack is a distance across each side, and a segment crossing a side at a shallow
		 * angle goes that over the angle's sine farther along before it is cut: by a sharp corner
		 * of the incident face, beyond it (float: a flat AABB's face 1e9 long, a segment, crossing
		 * a hull's sliver face 1.5e9 long whose tip has an angle of 1.1e-3; the slack of 3.6e3
		 * took the end 2.8e6 beyond the tip). An end that far from the incident shape is cut at
		 * the sides themselves; when the segment misses the face without the slack (the face's
		 * tip over the reference face beside its segment), or the cut is still off, the incident
		 * shape's nearest point, taken along n onto the reference plane, if that lies on the
		 * reference shape (off the hot path: thin reference faces only). */
		cdReal tolerance = RoundOff(onIncident, size);
		cd3Vec nearest = cd3ClosestPointOnShape(&inc->shape, onIncident);
		if (cd3VecDistance(nearest, onIncident) > tolerance && exactLo <= exactHi)
		{
			cdReal t = cdMin(cdMax(ts[i], exactLo), exactHi);
			separation = s0 + t * sRate;
			onReference = cd3MulAdd(r0, t, d);
			onIncident = cd3MulAdd(onReference, separation, n);
			tolerance = RoundOff(onIncident, size);
			nearest = cd3ClosestPointOnShape(&inc->shape, onIncident);
		}
		if (cd3VecDistance(nearest, onIncident) > tolerance)
		{
			separation = cd3Dot(n, cd3Sub(nearest, r0));
			onIncident = nearest;
			onReference = cd3MulSub(nearest, separation, n);
			if (!InsideShape(&ref->shape, onReference, RoundOff(onReference, size)) ||
				(m.pointCount == 1 && cd3VecDistance(cd3MulAdd(onReference, CD_R(0.5) * separation, n),
													 m.points[0].point) <= RoundOff(onReference, size)))
			{
				continue; /* off the reference shape, or the point already taken */
			}
		}
		/* The point's incident side must lie on the incident face: the incident plane of a needle
		 * (a triangle 2.4e21 long and 1e9 across, in double) is tilted by 6e-4 rad in round-off,
		 * and an end crossed it 5e19 beyond the triangle. Such an end is dropped (the reference
		 * side lies on the segment by construction, or on the reference shape by the test above). */
		if (separation <= speculativeDistance &&
			InsideShape(&inc->shape, onIncident, RoundOff(onIncident, size)))
		{
			AddPoint(&m, cd3MulAdd(onReference, CD_R(0.5) * separation, n), separation,
					 PackFaceId(face, incident, (uint32_t)i, (uint32_t)i, flip));
		}
	}
	if (m.pointCount > 0)
	{
		m.normal = flip ? cd3Neg(n) : n;
	}
	return m;
}

/* The outward normal of the side plane through edge v0-v1 of face `face` (world normal n). False
 * for an edge of length at most sqrt(floorSquared) (zero: a box with zero extents; see
 * EDGE_ROUND_OFF). */
static bool FaceSideNormal(cd3Vec v0, cd3Vec v1, cd3Vec n, cdReal floorSquared, cd3Vec* side)
{
	*side = cd3Cross(cd3Sub(v1, v0), n);
	return cd3LengthSquared(*side) > floorSquared;
}

/* The side plane of the face's edge `edge` when the edge has round-off length (out of line:
 * rare; returned by value, so the hot loop's normal stays in registers). thin: the face has no
 * area (SegmentFaceContact). Otherwise the edge is too short for its direction to bound the
 * face: the normal is the sum of its neighbours' unit side normals, a direction within the face's
 * normal cone at that corner, so the plane through the edge's origin supports the face there (a
 * plane across the face from its centre need not: it cuts a parallelogram's obtuse corner).
 * Neighbours of round-off length too: no plane (zero normal). */
typedef struct RoundOffPlane
{
	cd3Vec side;
	bool thin;
} RoundOffPlane;

MANIFOLD_NOINLINE static RoundOffPlane RoundOffSide(const cd3Polytope* p, int face, int edge, cd3Vec n,
													cdReal floorSquared)
{
	RoundOffPlane plane = {cd3MakeVec(CD_R(0.0), CD_R(0.0), CD_R(0.0)), FaceIsThin(p, face, floorSquared)};
	if (plane.thin)
	{
		return plane;
	}
	int previous = edge;
	int guard = 0;
	while (p->edges[previous].next != edge && ++guard < p->edgeCount)
	{
		previous = p->edges[previous].next;
	}
	int next = p->edges[edge].next;
	cd3Vec v0 = WorldVertex(p, p->edges[edge].origin);
	cd3Vec v1 = WorldVertex(p, p->edges[next].origin);
	cd3Vec sidePrevious = cd3Cross(cd3Sub(v0, WorldVertex(p, p->edges[previous].origin)), n);
	cd3Vec sideNext = cd3Cross(cd3Sub(WorldVertex(p, p->edges[p->edges[next].next].origin), v1), n);
	if (cd3LengthSquared(sidePrevious) > floorSquared)
	{
		plane.side = cd3Normalize(sidePrevious);
	}
	if (cd3LengthSquared(sideNext) > floorSquared)
	{
		plane.side = cd3Add(plane.side, cd3Normalize(sideNext));
	}
	return plane;
}

/* A corner of a reference face is sharp when the sine of its angle is below this: its side
 * planes meet at the angle, so their round-off moves the corner of the clip region along the
 * face by that over the sine. Such a corner gets one more plane across it (SharpCornerClip). */
#define SHARP_CORNER_SINE CD_R(0.0625)

/* The two side normals (outward, any length; l0 and l1 their squared lengths) s0 and s1 of
 * consecutive edges meet at a corner sharper than SHARP_CORNER_SINE: antiparallel within that
 * sine. */
static bool SharpCorner(cd3Vec s0, cd3Vec s1, cdReal l0, cdReal l1)
{
	cdReal d = cd3Dot(s0, s1);
	return d < CD_R(0.0) && d * d > (CD_R(1.0) - SHARP_CORNER_SINE * SHARP_CORNER_SINE) * l0 * l1;
}

/* Clips the polygon against the plane through the sharp corner whose normal is the sum of its
 * sides' unit normals: the face lies behind it, and the polygon no longer reaches beyond the
 * corner where the nearly parallel side planes cross within their round-off (a sliver face 1 long
 * whose corner's angle was 2.6e-9, double: a clipped point 5e-9 beyond the corner, off the hull).
 * Out of line: rare. Returns the count, the result in `out`. */
MANIFOLD_NOINLINE static int SharpCornerClip(const ClipVertex* in, int count, cd3Vec s0, cd3Vec s1,
											 cd3Vec corner, uint32_t tag, ClipVertex* out)
{
	cd3Vec cap = cd3Add(cd3Normalize(s0), cd3Normalize(s1));
	return ClipToPlane(in, count, cap, corner, tag, out);
}

/* Face contact with `ref`'s face `face` as reference. flip: ref is B. */
static cd3Manifold FaceContact(const cd3Polytope* ref, int face, const cd3Polytope* inc, bool flip,
							   cdReal speculativeDistance)
{
	cd3Manifold m = EmptyManifold();
	cd3Plane local = ref->planes[face];
	cd3Vec n = cd3RotateVector(ref->transform.q, local.normal);
	cdReal offset = local.offset + cd3Dot(n, ref->transform.p);
	int incident = IncidentFaceAtSupport(inc, n);

	ClipVertex bufferA[MAX_CLIP], bufferB[MAX_CLIP];
	int count = 0;
	int e = inc->faceEdges[incident];
	do
	{
		bufferA[count].p = WorldVertex(inc, inc->edges[e].origin);
		bufferA[count].tag = (uint32_t)(count < (int)SIDE_TAG - 1 ? count : (int)SIDE_TAG - 1);
		++count;
		e = inc->edges[e].next;
	} while (e != inc->faceEdges[incident] && count < MAX_CLIP / 2);

	ClipVertex* in = bufferA;
	ClipVertex* out = bufferB;
	int side = 0;
	e = ref->faceEdges[face];
	cd3Vec first = WorldVertex(ref, ref->edges[e].origin);
	cd3Vec v1 = first;
	cdReal floorSquared = EdgeFloorSquared(first, ref->size);
	/* The first and the previous side's normal and squared length: their corners' sharpness. */
	cd3Vec firstSide = cd3MakeVec(CD_R(0.0), CD_R(0.0), CD_R(0.0)), previousSide = firstSide;
	cdReal firstSquared = CD_R(0.0), previousSquared = CD_R(0.0);
	do
	{
		cd3Vec v0 = v1;
		int next = ref->edges[e].next;
		v1 = next == ref->faceEdges[face] ? first : WorldVertex(ref, ref->edges[next].origin);
		cd3Vec sideNormal = cd3Cross(cd3Sub(v1, v0), n); /* FaceSideNormal, with its length kept */
		cdReal sideSquared = cd3LengthSquared(sideNormal);
		if (!(sideSquared > floorSquared))
		{
			RoundOffPlane plane = RoundOffSide(ref, face, e, n, floorSquared);
			sideNormal = plane.side;
			sideSquared = cd3LengthSquared(sideNormal);
			if (plane.thin)
			{
				cd3Vec r0, r1;
				FaceEnds(ref, face, &r0, &r1);
				return SegmentFaceContact(ref, r0, r1, n, face, inc, incident, flip, speculativeDistance,
										  ref->size + inc->size);
			}
		}
		uint32_t tag = SIDE_TAG + (uint32_t)(side < (int)SIDE_TAG - 1 ? side : (int)SIDE_TAG - 1);
		count = ClipToPlane(in, count, sideNormal, v0, tag, out);
		ClipVertex* t = in;
		in = out;
		out = t;
		if (side == 0)
		{
			firstSide = sideNormal;
			firstSquared = sideSquared;
		}
		else if (SharpCorner(previousSide, sideNormal, previousSquared, sideSquared) && count > 0)
		{
			count = SharpCornerClip(in, count, previousSide, sideNormal, v0, tag, out);
			t = in;
			in = out;
			out = t;
		}
		previousSide = sideNormal;
		previousSquared = sideSquared;
		++side;
		e = ref->edges[e].next;
	} while (e != ref->faceEdges[face] && count > 0);
	if (count > 0 && SharpCorner(previousSide, firstSide, previousSquared, firstSquared))
	{
		count = SharpCornerClip(in, count, previousSide, firstSide, first, SIDE_TAG, out);
		in = out;
	}

	Candidate candidates[MAX_CLIP];
	int kept = 0;
	for (int i = 0; i < count; ++i)
	{
		cdReal separation = cd3Dot(n, in[i].p) - offset;
		if (separation <= speculativeDistance)
		{
			candidates[kept].point = cd3MulSub(in[i].p, CD_R(0.5) * separation, n);
			candidates[kept].separation = separation;
			candidates[kept].id =
				PackFaceId(face, incident, in[i > 0 ? i - 1 : count - 1].tag, in[i].tag, flip);
			++kept;
		}
	}
	if (kept == 0)
	{
		return m;
	}
	Candidate reduced[4];
	int reducedCount = ReducePoints(candidates, kept, n, reduced);
	for (int i = 0; i < reducedCount; ++i)
	{
		AddPoint(&m, reduced[i].point, reduced[i].separation, reduced[i].id);
	}
	m.normal = flip ? cd3Neg(n) : n;
	return m;
}

static cd3Segment WorldEdge(const cd3Polytope* p, int edge)
{
	cd3Segment s;
	s.p1 = WorldVertex(p, p->edges[edge].origin);
	s.p2 = WorldVertex(p, p->edges[p->edges[edge].twin].origin);
	return s;
}

static cd3Manifold VertexContact(cd3ClosestPoints cp)
{
	cd3Manifold m = EmptyManifold();
	m.normal = cd3Normalize(cd3Sub(cp.pointB, cp.pointA));
	if (cd3LengthSquared(m.normal) == CD_R(0.0))
	{
		m.normal = DefaultNormal();
	}
	AddPoint(&m, cd3Lerp(cp.pointA, cp.pointB, CD_R(0.5)), cp.distance, ID_VERTEX_PAIR);
	return m;
}

/* realized: the edges' closest points lie along the axis (they are |separation| apart within
 * `tolerance`), i.e. the edges cross as seen along it. An edge pair of a flat polytope's plane (a
 * segment box lying in a triangle's plane) has the plane's normal for axis and need not: its
 * separation is that of the face, and the pair can be apart in the plane. */
static cd3Manifold EdgeContact(const cd3Polytope* a, const cd3Polytope* b, const cd3SatResult* sat,
							   cdReal tolerance, bool* realized)
{
	cd3ClosestPoints cp = cd3ClosestPointsSegmentSegment(WorldEdge(a, sat->edgeA), WorldEdge(b, sat->edgeB));
	/* Also within the round-off of the closest points: the tolerance, relative to the sizes, can
	 * be far above the round-off of shapes 1e22 across in double (2e18 against a band of 8e12),
	 * and the point, midway between the closest points, lies off both surfaces by half their
	 * lateral offset. The coordinates' part only when the sizes' is not enough (hot path). */
	cdReal lateral = cp.distance - cdAbs(sat->edgeSeparation);
	cdReal sizeRoundOff = ROUND_OFF_TOLERANCE * (a->size + b->size);
	*realized = lateral <= cdMin(tolerance, sizeRoundOff) ||
				(lateral <= tolerance && lateral <= RoundOff(cp.pointA, a->size + b->size));
	cd3Manifold m = EmptyManifold();
	m.normal = cd3Normalize(sat->edgeNormal);
	uint32_t id =
		CD3_FEATURE_EDGES | ((uint32_t)sat->edgeA & 0x7fffu) | (((uint32_t)sat->edgeB & 0x7fffu) << 15);
	AddPoint(&m, cd3Lerp(cp.pointA, cp.pointB, CD_R(0.5)), sat->edgeSeparation, id);
	return m;
}

/* The size FACE_BIAS is relative to when choosing between A's face and B's: twice the smaller
 * polytope's (the sum for two of one size), at least the round-off of both. Both faces touch the
 * contact, which is no larger than the smaller polytope, and so are their separations' differences;
 * relative to the sum, a needle 1 long made the faces of a contact 1e-7 across a tie (a face 4e-8
 * deeper than the other was taken, its point 7e-9 off the needle; double build). */
static cdReal FaceTieSize(const cd3Polytope* a, const cd3Polytope* b)
{
	return cdMax(CD_R(2.0) * cdMin(a->size, b->size),
				 (ROUND_OFF_TOLERANCE / FACE_BIAS) * (a->size + b->size));
}

/* The size EDGE_BIAS is relative to when choosing an edge pair over the faces: the sum, unless it
 * is more than 16 times the smaller polytope's size (then that), at least the round-off of both.
 * With the smaller size alone, boxes resting on triangles a few times larger took one-point edge
 * contacts for face contacts (8 of 2000 pairs near contact); with the sum alone, a needle 1 long
 * against a hull 2.4e-7 across took a face 1e-8 worse than the edge pair (the exact axis), and
 * its deepest point was clipped away. */
static cdReal EdgeTieSize(const cd3Polytope* a, const cd3Polytope* b)
{
	cdReal sum = a->size + b->size;
	return cdMax(cdMin(sum, CD_R(16.0) * cdMin(a->size, b->size)), (ROUND_OFF_TOLERANCE / EDGE_BIAS) * sum);
}

/* The manifold the separating axis test picks: a face contact, or an edge contact when an edge
 * pair separates noticeably more (or the face's incident polygon clips away). checkEdges: an edge
 * pair whose edges do not cross along its axis (EdgeContact) gives no contact (the caller then
 * takes the distance); without it, its closest points stand. */
static cd3Manifold SatContact(const cd3Polytope* a, const cd3Polytope* b, const cd3SatResult* sat,
							  cdReal speculativeDistance, bool checkEdges, bool pruned);

/* SatContact on a pruned SAT result (cd3SatPolytopesPruned) once the edge pairs it skipped may
 * matter (the face's incident polygon clipped away): the full test, then the same steps. */
MANIFOLD_NOINLINE static cd3Manifold SatContactUnpruned(const cd3Polytope* a, const cd3Polytope* b,
														cdReal speculativeDistance, bool checkEdges)
{
	cd3SatResult full = cd3SatPolytopesWithin(a, b, speculativeDistance);
	return SatContact(a, b, &full, speculativeDistance, checkEdges, false);
}

static cd3Manifold SatContact(const cd3Polytope* a, const cd3Polytope* b, const cd3SatResult* sat,
							  cdReal speculativeDistance, bool checkEdges, bool pruned)
{
	cdReal size = a->size + b->size;
	bool useB =
		sat->faceA < 0 ||
		(sat->faceB >= 0 && sat->faceSeparationB > sat->faceSeparationA + FACE_BIAS * FaceTieSize(a, b));
	int face = useB ? sat->faceB : sat->faceA;
	int other = useB ? sat->faceA : sat->faceB;
	bool otherTried = false;
	cdReal faceSeparation = useB ? sat->faceSeparationB : sat->faceSeparationA;
	bool edges = sat->edgeA >= 0;
	bool useEdges =
		edges && (face < 0 || sat->edgeSeparation > faceSeparation + EDGE_BIAS * EdgeTieSize(a, b));
	bool realized = true;
	cd3Manifold edge;
	if (useEdges && sat->edgeSeparation <= speculativeDistance)
	{
		edge = EdgeContact(a, b, sat, REALIZED_TOLERANCE * size, &realized);
		if (realized || !checkEdges)
		{
			return edge;
		}
		/* Not an edge contact after all: the faces decide. */
		edges = false;
		useEdges = false;
	}
	if (!useEdges && face >= 0)
	{
		cd3Manifold m = useB ? FaceContact(b, face, a, true, speculativeDistance)
							 : FaceContact(a, face, b, false, speculativeDistance);
		if (m.pointCount == 0 && pruned)
		{
			return SatContactUnpruned(a, b, speculativeDistance, checkEdges);
		}
		if (m.pointCount == 0 && !edges && other >= 0)
		{
			/* The incident polygon clipped away against a sliver of a face (a box 1e-9 thin whose
			 * side planes round-off of the incident coordinates crosses): the other shape's face. */
			m = useB ? FaceContact(a, other, b, false, speculativeDistance)
					 : FaceContact(b, other, a, true, speculativeDistance);
			otherTried = true;
		}
		if (m.pointCount > 0 || !edges)
		{
			return m;
		}
	}
	if (pruned)
	{
		return SatContactUnpruned(a, b, speculativeDistance, checkEdges);
	}
	if (!edges || sat->edgeSeparation > speculativeDistance)
	{
		return EmptyManifold();
	}
	edge = EdgeContact(a, b, sat, REALIZED_TOLERANCE * size, &realized);
	if (realized || !checkEdges)
	{
		return edge;
	}
	/* The face clipped away and the edges do not cross: the other shape's face, which the bias
	 * (relative to the pair's size) can pass over though it separates the most (a box of size 1
	 * whose face is a sliver in float coordinates, against a triangle of size 1e9 whose face is
	 * the axis). */
	if (!otherTried && face >= 0 && other >= 0)
	{
		return useB ? FaceContact(a, other, b, false, speculativeDistance)
					: FaceContact(b, other, a, true, speculativeDistance);
	}
	return EmptyManifold();
}

/* Polytopes with more edge pairs than this take the GJK/EPA path: the SAT edge query costs
 * O(edges of A x edges of B), EPA a few dozen support calls. */
#define SAT_EDGE_PAIR_LIMIT 1024

/* The face of p whose world normal is most aligned with `direction`, and that cosine. */
static int AlignedFace(const cd3Polytope* p, cd3Vec direction, cdReal* cosine)
{
	cd3Vec local = cd3InvRotateVector(p->transform.q, direction);
	return cd3PlaneSupportIndex(p->planes, p->faceCount, local, cosine);
}

/* Large polytopes: the depth and normal from GJK (apart) or EPA (overlapping, exact on polytopes
 * up to round-off), then a face contact on the face aligned with that normal (A's preferred), or
 * one point at the witnesses when no face is (an edge or vertex contact). */
static cd3Manifold CollidePolytopesGjkEpa(const cd3Polytope* a, const cd3Polytope* b,
										  cdReal speculativeDistance)
{
	cdReal size = a->size + b->size;
	cdReal tolerance = REALIZED_TOLERANCE * size;
	cd3Vec normal;
	cdReal separation;
	cd3Vec pointA, pointB;
	/* EPA's own GJK answers overlap first, so overlapping pairs run GJK once. */
	cd3Penetration epa = cd3Epa(a, cd3PolytopeSupport, b, cd3PolytopeSupport);
	if (epa.overlapping && epa.hitIterationCap && cd3Distance(&a->shape, &b->shape).distance > tolerance)
	{
		epa.overlapping = false;
	}
	if (epa.overlapping)
	{
		normal = epa.normal;
		separation = -epa.depth;
		pointA = epa.pointA;
		pointB = epa.pointB;
	}
	else
	{
		if (epa.gap > speculativeDistance + ROUND_OFF_TOLERANCE * size)
		{
			return EmptyManifold(); /* GJK's separating direction shows them farther apart */
		}
		cd3ClosestPoints cp = cd3Distance(&a->shape, &b->shape);
		if (!(cp.distance <= speculativeDistance))
		{
			return EmptyManifold();
		}
		normal = cd3Normalize(cd3Sub(cp.pointB, cp.pointA));
		if (cd3LengthSquared(normal) == CD_R(0.0))
		{
			normal = epa.normal;
		}
		separation = cp.distance;
		pointA = cp.pointA;
		pointB = cp.pointB;
	}
	cdReal alignA, alignB;
	int faceA = AlignedFace(a, normal, &alignA);
	int faceB = AlignedFace(b, cd3Neg(normal), &alignB);
	if (faceA >= 0 && faceB >= 0 && cdMax(alignA, alignB) >= FACE_ALIGNED)
	{
		bool useB = alignB > alignA + CD_R(1.0e-6);
		cd3Manifold m = useB ? FaceContact(b, faceB, a, true, speculativeDistance)
							 : FaceContact(a, faceA, b, false, speculativeDistance);
		if (m.pointCount > 0 && cdAbs(ManifoldMinSeparation(&m) - separation) <= tolerance)
		{
			if (epa.overlapping)
			{
				MatchDepth(&m, separation, tolerance, a, b);
			}
			return m;
		}
	}
	cd3Manifold m = EmptyManifold();
	m.normal = normal;
	AddPoint(&m, cd3Lerp(pointA, pointB, CD_R(0.5)), separation, ID_VERTEX_PAIR);
	return m;
}

/* Every point's A side lies in A and its B side in B, within round-off. */
static bool PointsOnShapes(const cd3Manifold* m, const cd3Polytope* a, const cd3Polytope* b)
{
	for (int i = 0; i < m->pointCount; ++i)
	{
		const cd3ManifoldPoint* p = &m->points[i];
		cdReal tolerance = RoundOff(p->point, a->size + b->size);
		if (!InsideShape(&a->shape, cd3MulSub(p->point, CD_R(0.5) * p->separation, m->normal), tolerance) ||
			!InsideShape(&b->shape, cd3MulAdd(p->point, CD_R(0.5) * p->separation, m->normal), tolerance))
		{
			return false;
		}
	}
	return true;
}

/* Drops the points whose sides are not on their shapes within round-off. Only for polytopes of
 * very different sizes (the caller's test, off the hot path): clipping a face 4.3e8 long against a
 * sliver face (float) lerps along the long edges with an error of their length times epsilon, and
 * kept a point 3.7e7 beyond a hull that reaches 1.65e6. */
static void DropPointsOffShapes(cd3Manifold* m, const cd3Polytope* a, const cd3Polytope* b)
{
	int kept = 0;
	for (int i = 0; i < m->pointCount; ++i)
	{
		/* By the distance to each shape: a point beyond a needle's tip lies within the planes'
		 * round-off of its long faces, extended, though far from it. */
		const cd3ManifoldPoint* p = &m->points[i];
		cdReal tolerance = CD_R(4.0) * RoundOff(p->point, a->size + b->size);
		cd3Vec onA = cd3MulSub(p->point, CD_R(0.5) * p->separation, m->normal);
		cd3Vec onB = cd3MulAdd(p->point, CD_R(0.5) * p->separation, m->normal);
		if (cd3VecDistance(cd3ClosestPointOnShape(&a->shape, onA), onA) <= tolerance &&
			cd3VecDistance(cd3ClosestPointOnShape(&b->shape, onB), onB) <= tolerance)
		{
			m->points[kept++] = m->points[i];
		}
	}
	m->pointCount = kept;
	if (kept == 0)
	{
		m->normal = cd3MakeVec(CD_R(0.0), CD_R(0.0), CD_R(0.0));
	}
}

/* The world normal (from A to B) of the SAT's axis of largest separation. */
static cd3Vec SatNormal(const cd3Polytope* a, const cd3Polytope* b, const cd3SatResult* sat)
{
	cdReal separation = cd3SatSeparation(sat);
	if (sat->faceA >= 0 && sat->faceSeparationA == separation)
	{
		return cd3RotateVector(a->transform.q, a->planes[sat->faceA].normal);
	}
	if (sat->faceB >= 0 && sat->faceSeparationB == separation)
	{
		return cd3Neg(cd3RotateVector(b->transform.q, b->planes[sat->faceB].normal));
	}
	return cd3Normalize(sat->edgeNormal);
}

/* One point on the SAT's face axis of largest separation (from the face's side, the axis the
 * separation is exact on): the other polytope's deepest vertex against the face (its support
 * along the normal) and that vertex moved onto the face's plane by the separation. For an
 * interior vertex the nearest face plane's projection lies on its face, so the point is on both
 * shapes; empty when the axis is an edge pair or a side is off its shape beyond round-off. */
static cd3Manifold SupportContact(const cd3Polytope* a, const cd3Polytope* b, const cd3SatResult* sat)
{
	cd3Manifold m = EmptyManifold();
	cdReal separation = cd3SatSeparation(sat);
	bool faceA = sat->faceA >= 0 && sat->faceSeparationA == separation;
	bool faceB = !faceA && sat->faceB >= 0 && sat->faceSeparationB == separation;
	if (!faceA && !faceB)
	{
		return m;
	}
	cd3Vec n = SatNormal(a, b, sat); /* from A to B */
	cd3Vec onA, onB;
	if (faceA)
	{
		onB = cd3PolytopeSupport(b, cd3Neg(n));
		onA = cd3MulSub(onB, separation, n);
	}
	else
	{
		onA = cd3PolytopeSupport(a, n);
		onB = cd3MulAdd(onA, separation, n);
	}
	m.normal = n;
	AddPoint(&m, cd3Lerp(onA, onB, CD_R(0.5)), separation, ID_VERTEX_PAIR);
	return PointsOnShapes(&m, a, b) ? m : EmptyManifold();
}

/* Overlapping or touching polytopes (GJK's distance 0) whose SAT features give no contact on both
 * surfaces: the incident polygon clipped away in round-off and the edge pair's edges do not cross
 * (at 1e9 in float, a triangle's vertex touching a box's face, or its edge a box's edge, within
 * the coordinates' round-off: the edges' closest points were 1e9 apart, the point 5e8 off both).
 * One point where they meet: touching (the SAT's separation within round-off of zero), GJK's
 * point, on both shapes, with the SAT's axis and separation; deeper, EPA's witnesses and depth.
 * Empty when EPA fails too. */
static cd3Manifold WitnessContact(const cd3Polytope* a, const cd3Polytope* b, const cd3SatResult* sat,
								  cd3ClosestPoints cp)
{
	cd3Manifold m = EmptyManifold();
	cdReal separation = cd3SatSeparation(sat);
	cd3Vec point = cd3Lerp(cp.pointA, cp.pointB, CD_R(0.5));
	if (separation >= -RoundOff(point, a->size + b->size))
	{
		m.normal = SatNormal(a, b, sat);
		if (cd3LengthSquared(m.normal) > CD_R(0.0))
		{
			AddPoint(&m, point, separation, ID_VERTEX_PAIR);
			return m;
		}
		m.normal = cd3MakeVec(CD_R(0.0), CD_R(0.0), CD_R(0.0));
	}
	cd3Penetration epa = cd3Epa(a, cd3PolytopeSupport, b, cd3PolytopeSupport);
	/* An answer EPA gave at its iteration cap stands when its depth is the SAT's (exact between
	 * polytopes) within round-off: its face then lies on the Minkowski difference's boundary. Two
	 * hulls 2e-4 across overlapping by 8.7e-7 (float) took EPA to the cap with that depth, and the
	 * manifold came out empty. */
	if (epa.overlapping &&
		(!epa.hitIterationCap || cdAbs(epa.depth + separation) <= RoundOff(point, a->size + b->size)))
	{
		m.normal = epa.normal;
		/* Every caller has GJK's word that the shapes touch within round-off (cp). When EPA's depth
		 * is round-off too, GJK's closest points are the contact: EPA's witnesses come from a
		 * polytope as thin as the round-off and can lie anywhere along it (a point box touching
		 * a triangle 5.5e26 long and 1e11 wide, double: 2.75e26 from the box). */
		cd3Vec deepest = epa.depth <= RoundOff(point, a->size + b->size)
							 ? point
							 : cd3Lerp(epa.pointA, epa.pointB, CD_R(0.5));
		AddPoint(&m, deepest, -epa.depth, ID_VERTEX_PAIR);
		return m;
	}
	/* EPA failed or stopped at its cap short of the SAT's depth (a point box 5.5e-9 inside a hull
	 * of size 1.7, double: 3.1e-13 short, beyond the round-off of 3.8e-14): the SAT's face axis. */
	return SupportContact(a, b, sat);
}

MANIFOLD_NOINLINE static cd3Manifold CollidePolytopesSat(const cd3Polytope* a, const cd3Polytope* b,
														 cd3SatResult sat, bool pruned,
														 cdReal speculativeDistance);

static cd3Manifold CollidePolytopes(const cd3Polytope* a, const cd3Polytope* b, cdReal speculativeDistance)
{
	/* Small hulls stay on the separating-axis test: GJK/EPA between hulls of 8 vertices costs a
	 * third of it, but in float its contacts between hulls of 1e-8 and of 1e9 came out beyond the
	 * speculative distance and off the shapes (the CI fuzz runs), where the SAT's hold. */
	int edgePairs = (a->edgeAxisCount / 2) * (b->edgeAxisCount / 2);
	if (!a->flat && !b->flat && edgePairs > SAT_EDGE_PAIR_LIMIT)
	{
		cd3Manifold m = CollidePolytopesGjkEpa(a, b, speculativeDistance);
		if (m.pointCount == 0 || cd3LengthSquared(m.normal) > CD_R(0.0))
		{
			return m;
		}
		/* EPA gave no direction (hulls of 6 vertices at 1e9 in float: overlapping, depth 0 and a
		 * zero normal): the separating-axis test, whatever its cost, has an axis. */
		return CollidePolytopesSat(a, b, cd3SatPolytopes(a, b), false, speculativeDistance);
	}
	/* Beyond the speculative distance the SAT's answer is empty whatever the exact separation: it
	 * may stop at the first axis that shows it. The contact takes an edge pair over the faces only
	 * when it separates more than the face SatContact picks, which is within FACE_BIAS of the best
	 * face: edge pairs below that may be skipped (SatContact runs the full test when it needs them). */
	bool pruned;
	cd3SatResult sat =
		cd3SatPolytopesPruned(a, b, speculativeDistance, FACE_BIAS * FaceTieSize(a, b), &pruned);
	return CollidePolytopesSat(a, b, sat, pruned, speculativeDistance);
}

static cd3Manifold CollidePolytopesSat(const cd3Polytope* a, const cd3Polytope* b, cd3SatResult sat,
									   bool pruned, cdReal speculativeDistance)
{
	cdReal separation = cd3SatSeparation(&sat);
	if (!(separation <= speculativeDistance))
	{
		return EmptyManifold();
	}
	if (separation <= CD_R(0.0))
	{
		/* Between polytopes of very different sizes the SAT's axes can miss the separating one:
		 * the cross axis of a needle's edge nearly parallel to the other's long edge (a hull 1.6e6
		 * long beside an AABB 4.3e8 long, 3 apart, double) is too short for its separation to
		 * be trusted, and the SAT called them overlapping by 12.5. There GJK's distance decides
		 * whether they are apart (these pairs already pay for DropPointsOffShapes). */
		bool disparate = cdMax(a->size, b->size) > CD_R(16.0) * cdMin(a->size, b->size);
		if (disparate)
		{
			cd3ClosestPoints apart = cd3Distance(&a->shape, &b->shape);
			if (apart.distance > ROUND_OFF_TOLERANCE * (a->size + b->size))
			{
				return apart.distance <= speculativeDistance ? VertexContact(apart) : EmptyManifold();
			}
		}
		cd3Manifold m = SatContact(a, b, &sat, speculativeDistance, true, pruned);
		if (m.pointCount > 0 && disparate)
		{
			DropPointsOffShapes(&m, a, b);
		}
		cdReal limit = (FACE_BIAS + EDGE_BIAS) * (a->size + b->size);
		/* A contact whose points all lie farther apart than the SAT's separation allows missed the
		 * overlap: a triangle 1e9 long and 1e-4 across clipped, in float, against a box's face
		 * 1e-4 wide (lerps along its edges need 1e-13 of precision) kept only its far part, at
		 * separation 2.7e8 for shapes that overlap. */
		/* Nor may the deepest point be apart beyond round-off: overlapping by the SAT, no axis
		 * separates the shapes. The limit above, relative to the sizes, allowed an AABB 4.3e8 long
		 * crossing a needle hull 1.6e6 long (double) a contact at separation 1.15 on an axis the
		 * bias had preferred to the one along which they overlap. */
		bool missed =
			m.pointCount > 0 && (ManifoldMinSeparation(&m) > separation + limit ||
								 ManifoldMinSeparation(&m) > RoundOff(m.points[0].point, a->size + b->size));
		if (m.pointCount == 0 || missed)
		{
			/* No contact on the SAT's axis: a degenerate polytope (a point box against a triangle,
			 * a segment box in a triangle's plane) can lack the separating axis, so the distance
			 * decides; overlapping, the SAT's edge pair stands. */
			cd3ClosestPoints cp = cd3Distance(&a->shape, &b->shape);
			if (cp.distance > CD_R(0.0))
			{
				return cp.distance <= speculativeDistance ? VertexContact(cp) : EmptyManifold();
			}
			if (missed)
			{
				return WitnessContact(a, b, &sat, cp);
			}
			m = SatContact(a, b, &sat, speculativeDistance, false, pruned);
			if (m.pointCount > 0 && cdMax(a->size, b->size) > CD_R(16.0) * cdMin(a->size, b->size))
			{
				DropPointsOffShapes(&m, a, b);
			}
			if (m.pointCount == 0 || !PointsOnShapes(&m, a, b))
			{
				return WitnessContact(a, b, &sat, cp);
			}
		}
		if (m.pointCount > 0)
		{
			MatchDepth(&m, separation, limit, a, b);
		}
		return m;
	}
	/* Apart: the SAT separation only bounds the distance from below. The SAT manifold stands when
	 * its deepest point realizes the distance (closest features face-vertex or edge-edge);
	 * otherwise the closest points (vertex-vertex, vertex-edge) give one point along the gap. */
	cd3ClosestPoints cp = cd3Distance(&a->shape, &b->shape);
	if (cp.distance > speculativeDistance)
	{
		return EmptyManifold();
	}
	/* Relative to the smaller polytope, as the face bias (FaceTieSize): a point box 5.4e-5 from a
	 * needle triangle 1 long took the SAT's contact at separation 4.2e-5, 1.6e-5 off the triangle,
	 * for realizing the distance within 1e-4 of the size sum. */
	cdReal tolerance =
		REALIZED_TOLERANCE * CD_R(2.0) * cdMin(a->size, b->size) + ROUND_OFF_TOLERANCE * (a->size + b->size);
	/* Touching within round-off (GJK's distance): the SAT contact must touch too. A needle AABB
	 * 2e18 long whose end touches a triangle 5e20 across (double): the AABB's face contact lay
	 * 1.6e14 apart, within the tolerance (the needle is the smaller polytope), though the shapes
	 * touch. Then the witnesses: GJK's point on the SAT's axis. (The coordinates' round-off is
	 * computed only near touching: hot path.) */
	bool touching = cp.distance <= ROUND_OFF_TOLERANCE * (a->size + b->size) ||
					(cp.distance <= tolerance && cp.distance <= RoundOff(cp.pointA, a->size + b->size));
	if (cp.distance <= separation + tolerance)
	{
		cd3Manifold m = SatContact(a, b, &sat, speculativeDistance, true, pruned);
		if (m.pointCount > 0 && cdMax(a->size, b->size) > CD_R(16.0) * cdMin(a->size, b->size))
		{
			/* A face 4.3e8 long clipped against a needle's face 1.6e6 long (float) kept points
			 * off the shapes, one of them deeper than the separating axis allows. */
			DropPointsOffShapes(&m, a, b);
		}
		cdReal smallest = ManifoldMinSeparation(&m);
		/* Never farther apart than the distance beyond round-off: B moved by the smallest
		 * separation along the normal must not overlap A (a hull(8)-box pair apart by 0.062725
		 * reported 0.063158 on a face whose deepest vertex the clipping had lost). */
		if (m.pointCount > 0 && cdAbs(smallest - cp.distance) <= tolerance &&
			smallest <= cp.distance + RoundOff(cp.pointA, a->size + b->size))
		{
			if (m.pointCount == 1 && (m.points[0].id & CD3_FEATURE_EDGES) != 0u && cp.distance > tolerance)
			{
				/* Edges apart: the SAT axis only bounds the distance within the tolerance, and the
				 * edges' closest points need not lie along it (a point off both surfaces by half
				 * the lateral offset). The closest points, with the edge pair's id; touching edges
				 * keep the SAT axis (the closest points give no direction). */
				uint32_t id = m.points[0].id;
				m = VertexContact(cp);
				m.points[0].id = id;
			}
			return m;
		}
	}
	return touching ? WitnessContact(a, b, &sat, cp) : VertexContact(cp);
}

/* ---- rounded core against polytope ------------------------------------------------------------ */

/* Clips segment p1-p2 to the side planes of polytope face `face` (world). A zero-length edge
 * of a face that is a segment (a box with zero extents) bounds it at that end: its plane is
 * across the face, through the end. A face that is a point has no side planes: false. */
static bool ClipSegmentToFace(const cd3Polytope* p, int face, cd3Vec n, cd3Vec* p1, cd3Vec* p2)
{
	cdReal t0 = CD_R(0.0), t1 = CD_R(1.0);
	cd3Vec d = cd3Sub(*p2, *p1);
	int e = p->faceEdges[face];
	do
	{
		cd3Vec v0 = WorldVertex(p, p->edges[e].origin);
		cd3Vec v1 = WorldVertex(p, p->edges[p->edges[e].next].origin);
		cd3Vec side;
		if (!FaceSideNormal(v0, v1, n, CD_R(0.0), &side))
		{
			cd3Vec outward = cd3Sub(v0, FaceCentre(p, face));
			side = cd3MulSub(outward, cd3Dot(outward, n), n);
			if (!(cd3LengthSquared(side) > CD_R(0.0)))
			{
				return false;
			}
		}
		cdReal start = cd3Dot(side, cd3Sub(*p1, v0));
		cdReal rate = cd3Dot(side, d);
		if (rate == CD_R(0.0))
		{
			if (start > CD_R(0.0))
			{
				return false;
			}
		}
		else
		{
			cdReal t = -start / rate;
			if (rate > CD_R(0.0))
			{
				t1 = cdMin(t1, t);
			}
			else
			{
				t0 = cdMax(t0, t);
			}
		}
		e = p->edges[e].next;
	} while (e != p->faceEdges[face]);
	if (t0 > t1)
	{
		return false;
	}
	cd3Vec start = *p1;
	*p1 = cd3MulAdd(start, t0, d);
	*p2 = cd3MulAdd(start, t1, d);
	return true;
}

/* Face contact of the core segment p1-p2 (radius r) with face `face` of b; normal -n (world) from
 * the core to b. Returns false when the segment clips away. */
static bool CoreFaceContact(cd3Vec p1, cd3Vec p2, cdReal r, const cd3Polytope* b, int face,
							cdReal speculativeDistance, bool twoPoints, cdReal tolerance, cd3Vec nearest,
							cd3Manifold* m)
{
	cd3Plane local = b->planes[face];
	cd3Vec n = cd3RotateVector(b->transform.q, local.normal);
	cdReal offset = local.offset + cd3Dot(n, b->transform.p);
	cd3Vec q[2] = {p1, p2};
	int count = 2;
	if (twoPoints)
	{
		if (!ClipSegmentToFace(b, face, n, &q[0], &q[1]))
		{
			return false;
		}
	}
	else
	{
		/* One point: the deepest along n of the segment's part over the face, when it is as deep
		 * as the deepest end within `tolerance`. The deepest end can lie beside the face when an
		 * edge axis separates within EDGE_BIAS of it (a capsule's end past the face's side, at a
		 * slant): its projection on the face plane is then off the face. The part over the face
		 * can also lie far outside the polytope (a long segment at a slant, whose SAT face is
		 * round-off): the deepest end stays then. A segment that passes beside the face (or a face
		 * that is a point: a zero-size box) gives the core's point nearest b (`nearest`, GJK's):
		 * the deepest end can be 1e9 away along a long core that the SAT calls touching a point
		 * 70 away (the SAT path's tolerance is relative to the core's length). */
		count = 1;
		if (cd3Dot(n, p2) < cd3Dot(n, p1))
		{
			q[0] = p2;
		}
		cd3Vec c1 = p1, c2 = p2;
		if (ClipSegmentToFace(b, face, n, &c1, &c2))
		{
			cd3Vec c = cd3Dot(n, c2) < cd3Dot(n, c1) ? c2 : c1;
			if (cd3Dot(n, c) - cd3Dot(n, q[0]) <= tolerance)
			{
				q[0] = c;
			}
		}
		else
		{
			q[0] = nearest;
		}
	}
	*m = EmptyManifold();
	for (int i = 0; i < count; ++i)
	{
		cdReal separation = cd3Dot(n, q[i]) - offset - r;
		if (separation <= speculativeDistance)
		{
			uint32_t id = ((uint32_t)face & 0xffffu) | ((uint32_t)i << 16);
			AddPoint(m, cd3MulSub(q[i], r + CD_R(0.5) * separation, n), separation, id);
		}
	}
	if (m->pointCount > 0)
	{
		m->normal = cd3Neg(n); /* an empty manifold keeps the zero normal */
	}
	return true;
}

/* A core much longer than its reach to b keeps only the part within that reach of b's centroid:
 * the rest lies farther than r + speculativeDistance from every point of b (b lies within its
 * size of the centroid), so the contact is the same. Along a core 1e9 long beside a unit box
 * (1e14 in double), GJK and the SAT's edge axes are round-off, and every tolerance relative to
 * the pair's size (REALIZED_TOLERANCE) would take gaps of 1e5 for touching. False when no part
 * is within reach. Ordinary cores are left as they are. */
static bool TrimCore(cd3Vec* p1, cd3Vec* p2, cdReal r, const cd3Polytope* b, cdReal speculativeDistance)
{
	cd3Vec axis = cd3Sub(*p2, *p1);
	cdReal length = cd3Length(axis);
	cdReal reach = CD_R(2.0) * b->size + r + cdMax(speculativeDistance, CD_R(0.0));
	if (!(length > CD_R(4.0) * reach))
	{
		return true;
	}
	cd3Vec u = cd3Scale(CD_R(1.0) / length, axis);
	cd3Vec centre = cd3TransformPoint(b->transform, b->centroid);
	cdReal along = cd3Dot(cd3Sub(centre, *p1), u);
	cdReal lo = cdMax(along - reach, CD_R(0.0));
	cdReal hi = cdMin(along + reach, length);
	if (!(lo < hi))
	{
		return false;
	}
	/* Each cut from the nearer end: its round-off is then that of the short distance. */
	cd3Vec start = *p1, end = *p2;
	*p1 = lo <= CD_R(0.5) * length ? cd3MulAdd(start, lo, u) : cd3MulSub(end, length - lo, u);
	*p2 = hi <= CD_R(0.5) * length ? cd3MulAdd(start, hi, u) : cd3MulSub(end, length - hi, u);
	return true;
}

/* The edge contact of core p1-p2 (radius r) and b's SAT edge: one point at the closest points of
 * the segment and the edge (empty beyond the speculative distance). */
static cd3Manifold CoreEdgeContact(cd3Vec p1, cd3Vec p2, cdReal r, const cd3Polytope* b,
								   const cd3SatResult* sat, cdReal speculativeDistance)
{
	cd3Manifold m = EmptyManifold();
	cd3Segment segment = {p1, p2};
	cd3ClosestPoints ecp = cd3ClosestPointsSegmentSegment(segment, WorldEdge(b, sat->edgeB));
	cdReal separation = sat->edgeSeparation - r;
	if (separation > speculativeDistance)
	{
		return m;
	}
	m.normal = cd3Normalize(sat->edgeNormal);
	AddPoint(&m, cd3MulAdd(ecp.pointA, r + CD_R(0.5) * separation, m.normal), separation,
			 CD3_FEATURE_EDGES | ((uint32_t)sat->edgeB & 0x7fffu));
	return m;
}

/* Every point's polytope side lies in b within round-off (the normal points from the core to b):
 * within each face plane and, as the planes of a sliver's two large faces meet at its edge at a
 * small angle (1e-3 rad), by the distance to b too (as DropPointsOffShapes): a capsule's end 6e6
 * beyond the edge of a hull 1e9 across and 1e6 thick (float) was within 6e3 of both planes. */
static bool CorePointOnPolytope(const cd3Manifold* m, const cd3Polytope* b, cdReal size)
{
	for (int i = 0; i < m->pointCount; ++i)
	{
		cd3Vec onB = cd3MulAdd(m->points[i].point, CD_R(0.5) * m->points[i].separation, m->normal);
		cdReal tolerance = RoundOff(onB, size);
		if (!InsideShape(&b->shape, onB, tolerance) ||
			cd3VecDistance(cd3ClosestPointOnShape(&b->shape, onB), onB) > CD_R(4.0) * tolerance)
		{
			return false;
		}
	}
	return true;
}

static cd3Manifold CollideCorePolytope(cd3Vec p1, cd3Vec p2, cdReal r, const cd3Polytope* b,
									   cdReal speculativeDistance)
{
	if (!TrimCore(&p1, &p2, r, b, speculativeDistance))
	{
		return EmptyManifold();
	}
	cd3Capsule coreCapsule = {p1, p2, CD_R(0.0)};
	cd3Shape core = cd3MakeCapsuleShape(coreCapsule);
	cd3ClosestPoints cp = cd3Distance(&core, &b->shape);
	if (!(cp.distance <= r + speculativeDistance))
	{
		return EmptyManifold();
	}
	cd3Vec axis = cd3Sub(p2, p1);
	cdReal axisLength = cd3Length(axis);
	bool capsule = axisLength > CD_R(0.0);
	cd3Vec gap = cd3Sub(cp.pointB, cp.pointA);
	cdReal size = b->size + axisLength + r;
	cd3Manifold m = EmptyManifold();
	/* The core is apart from b when GJK's distance exceeds the round-off of the coordinates of the
	 * core and b (the radius plays no part in where they are): their closest points then give the
	 * normal; the SAT below is for a core that touches or enters b. The bound was 1e-4 of the
	 * size, radius included: a sphere's centre 1.43 outside a hull of size 4.6e7 (double) took the
	 * SAT's nearest face plane, whose projection lay 1.08 beside the face, and a radius of 2.5e14
	 * took a core 4.5e6 from a box of size 1e7 for touching (a point 3e6 off the box). */
	if (cp.distance > RoundOff(cp.pointB, b->size + axisLength) && cd3LengthSquared(gap) > CD_R(0.0))
	{
		cd3Vec u = cd3Normalize(gap);
		if (capsule)
		{
			int face = IncidentFace(b, u); /* the face whose normal is closest to -u */
			cd3Vec n = cd3RotateVector(b->transform.q, b->planes[face].normal);
			if (cd3Dot(n, u) <= -FACE_ALIGNED && cdAbs(cd3Dot(n, axis)) <= PARALLEL_CAPSULE * axisLength &&
				CoreFaceContact(p1, p2, r, b, face, speculativeDistance, true, CD_R(0.0), p1, &m) &&
				m.pointCount == 2)
			{
				return m;
			}
			m = EmptyManifold();
		}
		m.normal = u;
		cdReal separation = cp.distance - r;
		AddPoint(&m, cd3MulAdd(cp.pointA, CD_R(0.5) * (cp.distance + r), u), separation, ID_VERTEX_PAIR);
		return m;
	}

	cd3SatResult sat;
	cd3SatFeature feature = cd3SatSegmentPolytope(p1, p2, b, &sat);
	bool edges = feature == CD3_SAT_EDGES && sat.edgeB >= 0;
	if (edges && (sat.faceB < 0 || sat.edgeSeparation > sat.faceSeparationB + EDGE_BIAS * size))
	{
		return CoreEdgeContact(p1, p2, r, b, &sat, speculativeDistance);
	}
	if (sat.faceB < 0)
	{
		/* A degenerate triangle with no axis (collinear: its longest edge a-b is all of it): the
		 * closest points, along the gap, or across the edge (and the core's axis) when they
		 * touch. The point is midway between the surfaces, as everywhere (it was the core's
		 * point, r / 2 off both surfaces: 5e8 for a sphere of radius 1e9). */
		cd3Vec u = cd3Normalize(gap);
		if (cd3LengthSquared(u) == CD_R(0.0))
		{
			cd3Vec edge = cd3Sub(WorldVertex(b, 1), WorldVertex(b, 0));
			u = cd3Normalize(cd3Cross(axis, edge));
			u = cd3LengthSquared(u) > CD_R(0.0) ? u : cd3Perpendicular(edge);
			u = cd3LengthSquared(u) > CD_R(0.0) ? u : DefaultNormal();
		}
		m.normal = u;
		cdReal separation = cp.distance - r;
		AddPoint(&m, cd3MulAdd(cp.pointA, r + CD_R(0.5) * separation, u), separation, ID_VERTEX_PAIR);
		return m;
	}
	cd3Vec n = cd3RotateVector(b->transform.q, b->planes[sat.faceB].normal);
	bool parallel = capsule && cdAbs(cd3Dot(n, axis)) <= PARALLEL_CAPSULE * axisLength;
	if (parallel && CoreFaceContact(p1, p2, r, b, sat.faceB, speculativeDistance, true, CD_R(0.0), p1, &m) &&
		m.pointCount > 0)
	{
		return m;
	}
	CoreFaceContact(p1, p2, r, b, sat.faceB, speculativeDistance, false, RoundOff(p1, size), cp.pointA, &m);
	if (edges && m.pointCount > 0 && !CorePointOnPolytope(&m, b, size))
	{
		/* The face won within EDGE_BIAS of the sizes, but its point lies beside it (a capsule
		 * 3.3e7 long crossing a hull 4.6e7 long near their small ends, in double: the edge axis
		 * separated 10 more, the bias was 7.9e3, and the point lay 10 off the hull): the edge
		 * pair's contact, which lies on both. */
		return CoreEdgeContact(p1, p2, r, b, &sat, speculativeDistance);
	}
	return m;
}

/* ---- spheres and capsules ---------------------------------------------------------------------- */

static cd3Manifold CollidePoints(cd3Vec a, cdReal ra, cd3Vec b, cdReal rb, cdReal speculativeDistance,
								 uint32_t id)
{
	cd3Manifold m = EmptyManifold();
	cdReal reach = ra + rb + speculativeDistance;
	cd3Vec d = cd3Sub(b, a);
	if (!(cd3LengthSquared(d) <= reach * reach))
	{
		return m;
	}
	cdReal distance;
	cd3Vec n = cd3GetLengthAndNormalize(&distance, d);
	if (cd3LengthSquared(n) == CD_R(0.0))
	{
		n = DefaultNormal();
		distance = CD_R(0.0);
	}
	cdReal separation = distance - ra - rb;
	m.normal = n;
	AddPoint(&m, cd3MulAdd(a, ra + CD_R(0.5) * separation, n), separation, id);
	return m;
}

cd3Manifold cd3CollideSphereSphere(cd3Sphere a, cd3Sphere b, cdReal speculativeDistance)
{
	return CollidePoints(a.center, a.radius, b.center, b.radius, speculativeDistance, 0u);
}

cd3Manifold cd3CollideSphereCapsule(cd3Sphere a, cd3Capsule b, cdReal speculativeDistance)
{
	cd3Segment s = {b.p1, b.p2};
	cd3Vec closest = cd3ClosestPointOnSegment(s, a.center);
	cd3Manifold m = CollidePoints(a.center, a.radius, closest, b.radius, speculativeDistance, 0u);
	cdReal scale = cdMax(cd3Length(cd3Abs(a.center)), cd3Length(cd3Sub(b.p2, b.p1)));
	if (m.pointCount > 0 && cd3VecDistance(closest, a.center) <= CD_R(16.0) * CD_REAL_EPSILON * scale)
	{
		/* Centre on the axis: any direction across the axis. */
		cd3Vec n = cd3Perpendicular(cd3Sub(b.p2, b.p1));
		if (cd3LengthSquared(n) > CD_R(0.0))
		{
			m.normal = n;
			m.points[0].point = cd3MulAdd(a.center, a.radius + CD_R(0.5) * m.points[0].separation, n);
		}
	}
	return m;
}

cd3Manifold cd3CollideCapsuleCapsule(cd3Capsule a, cd3Capsule b, cdReal speculativeDistance)
{
	cd3Segment sa = {a.p1, a.p2};
	cd3Segment sb = {b.p1, b.p2};
	cd3ClosestPoints cp = cd3ClosestPointsSegmentSegment(sa, sb);
	cd3Manifold m = CollidePoints(cp.pointA, a.radius, cp.pointB, b.radius, speculativeDistance, 0u);
	if (m.pointCount == 0)
	{
		return m;
	}
	cd3Vec da = cd3Sub(a.p2, a.p1);
	cd3Vec db = cd3Sub(b.p2, b.p1);
	cdReal la2 = cd3LengthSquared(da), lb2 = cd3LengthSquared(db);
	cd3Vec crossAxes = cd3Cross(da, db);
	cdReal sin2 = cd3LengthSquared(crossAxes);
	if (cp.distance == CD_R(0.0))
	{
		/* Crossing axes: the common perpendicular separates them by the two radii. */
		cd3Vec n = cd3Normalize(crossAxes);
		if (cd3LengthSquared(n) == CD_R(0.0))
		{
			n = cd3Perpendicular(la2 > CD_R(0.0) ? da : db);
		}
		if (cd3LengthSquared(n) > CD_R(0.0))
		{
			cd3Vec towardB = cd3Sub(cd3Lerp(b.p1, b.p2, CD_R(0.5)), cd3Lerp(a.p1, a.p2, CD_R(0.5)));
			m.normal = cd3Dot(n, towardB) < CD_R(0.0) ? cd3Neg(n) : n;
			m.points[0].point = cd3MulAdd(cp.pointA, a.radius + CD_R(0.5) * m.points[0].separation, m.normal);
		}
	}
	if (!(la2 > CD_R(0.0) && lb2 > CD_R(0.0) && sin2 <= CD_R(1.0e-6) * la2 * lb2))
	{
		return m;
	}
	/* Parallel: B's extent along A's axis, clipped to A's segment. */
	cdReal t1 = cd3Dot(cd3Sub(b.p1, a.p1), da) / la2;
	cdReal t2 = cd3Dot(cd3Sub(b.p2, a.p1), da) / la2;
	cdReal lo = cdMax(CD_R(0.0), cdMin(t1, t2));
	cdReal hi = cdMin(CD_R(1.0), cdMax(t1, t2));
	if (!(hi - lo > CD_R(1.0e-3)))
	{
		return m;
	}
	cd3Manifold two = EmptyManifold();
	two.normal = m.normal;
	cdReal ts[2] = {lo, hi};
	for (int i = 0; i < 2; ++i)
	{
		cd3Vec pa = cd3MulAdd(a.p1, ts[i], da);
		cd3Vec pb = cd3ClosestPointOnSegment(sb, pa);
		cd3Vec gap = cd3Sub(pb, pa);
		cdReal along = cd3Dot(two.normal, gap);
		/* The axes may drift apart across the normal (up to 1e-3 rad): the line along the normal
		 * from pa passes `lateral` from B's axis point pb and meets B's surface at
		 * along - sqrt(rb^2 - lateral^2), not at along - rb (which lay outside B by about
		 * lateral^2 / 2 rb: 4e-8 for unit capsules 1e-4 rad apart, beyond the double build's
		 * round-off; 4.5e16 for axes 4.5e19 long against a radius of 7.5e6). A line that misses B
		 * (beyond round-off) leaves the one closest point. */
		cdReal lateral2 = cd3LengthSquared(cd3MulSub(gap, along, two.normal));
		cdReal roundOff = RoundOff(pa, cdSqrt(la2) + cdSqrt(lb2) + a.radius + b.radius);
		cdReal radius2 = b.radius * b.radius;
		if (!(lateral2 <= radius2 + roundOff * roundOff))
		{
			return m;
		}
		cdReal separation = along - cdSqrt(cdMax(radius2 - lateral2, CD_R(0.0))) - a.radius;
		if (separation <= speculativeDistance)
		{
			AddPoint(&two, cd3MulAdd(pa, a.radius + CD_R(0.5) * separation, two.normal), separation,
					 (uint32_t)i + 1u);
		}
	}
	return two.pointCount > 0 ? two : m;
}

/* ---- pair functions --------------------------------------------------------------------------- */

cd3Manifold cd3CollideSphereBox(cd3Sphere a, cd3Box b, cdReal speculativeDistance)
{
	cd3Polytope pb;
	cd3InitBoxPolytope(&pb, b);
	return CollideCorePolytope(a.center, a.center, a.radius, &pb, speculativeDistance);
}

cd3Manifold cd3CollideSphereHull(cd3Sphere a, cd3HullShape b, cdReal speculativeDistance)
{
	cd3Polytope pb;
	cd3InitHullPolytope(&pb, b);
	return CollideCorePolytope(a.center, a.center, a.radius, &pb, speculativeDistance);
}

cd3Manifold cd3CollideSphereTriangle(cd3Sphere a, cd3Triangle b, cdReal speculativeDistance)
{
	cd3Polytope pb;
	cd3InitTrianglePolytope(&pb, b);
	return CollideCorePolytope(a.center, a.center, a.radius, &pb, speculativeDistance);
}

cd3Manifold cd3CollideCapsuleBox(cd3Capsule a, cd3Box b, cdReal speculativeDistance)
{
	cd3Polytope pb;
	cd3InitBoxPolytope(&pb, b);
	return CollideCorePolytope(a.p1, a.p2, a.radius, &pb, speculativeDistance);
}

cd3Manifold cd3CollideCapsuleHull(cd3Capsule a, cd3HullShape b, cdReal speculativeDistance)
{
	cd3Polytope pb;
	cd3InitHullPolytope(&pb, b);
	return CollideCorePolytope(a.p1, a.p2, a.radius, &pb, speculativeDistance);
}

cd3Manifold cd3CollideCapsuleTriangle(cd3Capsule a, cd3Triangle b, cdReal speculativeDistance)
{
	cd3Polytope pb;
	cd3InitTrianglePolytope(&pb, b);
	return CollideCorePolytope(a.p1, a.p2, a.radius, &pb, speculativeDistance);
}

/* The vertices of each box face in the order of the box polytope's half-edge loops (so the ids
 * match the polytope path's). */
static const int BOX_FACE_VERTICES[6][4] = {{2, 0, 4, 6}, {5, 1, 3, 7}, {4, 0, 1, 5},
											{3, 2, 6, 7}, {1, 0, 2, 3}, {6, 4, 5, 7}};

static cdReal Component(cd3Vec v, int axis)
{
	return axis == 0 ? v.x : (axis == 1 ? v.y : v.z);
}

static cd3Vec AxisVector(int axis, cdReal value)
{
	return cd3MakeVec(axis == 0 ? value : CD_R(0.0), axis == 1 ? value : CD_R(0.0),
					  axis == 2 ? value : CD_R(0.0));
}

/* A clip vertex of the box path: the coordinates as an array, so that a side picks its axis by
 * index. */
typedef struct BoxClipVertex
{
	cdReal x[3];
	uint32_t tag;
} BoxClipVertex;

/* ClipToPlane for the plane sign * x[axis] <= limit (the same arithmetic, vertex by vertex). */
static int ClipToSlab(const BoxClipVertex* in, int count, int axis, cdReal sign, cdReal limit, uint32_t tag,
					  BoxClipVertex* out)
{
	int n = 0;
	cdReal dp = sign * in[0].x[axis] - limit;
	for (int i = 0; i < count; ++i)
	{
		const BoxClipVertex* p = &in[i];
		const BoxClipVertex* q = &in[i + 1 < count ? i + 1 : 0];
		cdReal dq = sign * q->x[axis] - limit;
		bool inside = dp <= CD_R(0.0);
		if (inside)
		{
			out[n++] = *p;
		}
		if (inside != (dq <= CD_R(0.0)))
		{
			cdReal s = dp / (dp - dq);
			BoxClipVertex* x = &out[n++];
			for (int c = 0; c < 3; ++c)
			{
				x->x[c] = p->x[c] + s * (q->x[c] - p->x[c]);
			}
			x->tag = inside ? tag : p->tag;
		}
		dp = dq;
	}
	return n;
}

/* FaceContact for two boxes, in the reference box's frame: its side planes are axis-aligned and
 * the incident box's corners come from one rotation matrix (rot, t: the incident box's frame in
 * the reference's). Writes the points and normal into *m, which the caller has emptied: the
 * manifold is built in place, not returned through copies. */
static void BoxFaceContact(const cd3Box* ref, int face, const cd3Box* inc, const cd3Mat33* rot, cd3Vec t,
						   const cd3Mat33* refFrame, bool flip, cdReal speculativeDistance, cd3Manifold* m)
{
	int k = face / 2;
	cdReal sign = (face & 1) ? CD_R(1.0) : -CD_R(1.0);
	cdReal hr[3] = {ref->halfExtents.x, ref->halfExtents.y, ref->halfExtents.z};
	cdReal hi[3] = {inc->halfExtents.x, inc->halfExtents.y, inc->halfExtents.z};
	cdReal along[3] = {Component(rot->cx, k), Component(rot->cy, k), Component(rot->cz, k)};
	int j = 0;
	for (int axis = 1; axis < 3; ++axis)
	{
		if (cd3AbsNoBranch(along[axis]) > cd3AbsNoBranch(along[j]))
		{
			j = axis;
		}
	}
	/* The incident face's outward normal +-column j points against n. */
	int incident = 2 * j + (sign * along[j] > CD_R(0.0) ? 0 : 1);

	BoxClipVertex bufferA[8], bufferB[8];
	BoxClipVertex* in = bufferA;
	BoxClipVertex* out = bufferB;
	int count = 4;
	/* The incident box's axes scaled by its half extents: each corner is t + (+-ex +- ey) +- ez, the
	 * products of cd3MulMV(*rot, corner) with their signs (the same sums, bit for bit), made once. */
	cd3Vec ex = cd3Scale(hi[0], rot->cx), ey = cd3Scale(hi[1], rot->cy), ez = cd3Scale(hi[2], rot->cz);
	for (int v = 0; v < 4; ++v)
	{
		int corner = BOX_FACE_VERTICES[incident][v];
		cd3Vec p = cd3Add(t, cd3Add(cd3Add((corner & 1) ? ex : cd3Neg(ex), (corner & 2) ? ey : cd3Neg(ey)),
									(corner & 4) ? ez : cd3Neg(ez)));
		in[v].x[0] = p.x;
		in[v].x[1] = p.y;
		in[v].x[2] = p.z;
		in[v].tag = (uint32_t)v;
	}
	for (int side = 0; side < 4 && count > 0; ++side)
	{
		int v0 = BOX_FACE_VERTICES[face][side], v1 = BOX_FACE_VERTICES[face][(side + 1) & 3];
		/* The side's plane: the axis other than k on which both corners agree. */
		int axis = (k + 1) % 3;
		if (((v0 ^ v1) >> axis) & 1)
		{
			axis = (k + 2) % 3;
		}
		cdReal sideSign = ((v0 >> axis) & 1) ? CD_R(1.0) : -CD_R(1.0);
		count = ClipToSlab(in, count, axis, sideSign, hr[axis], SIDE_TAG + (uint32_t)side, out);
		BoxClipVertex* swap = in;
		in = out;
		out = swap;
	}
	Candidate candidates[8];
	int kept = 0;
	for (int i = 0; i < count; ++i)
	{
		cdReal separation = sign * in[i].x[k] - hr[k];
		if (separation <= speculativeDistance)
		{
			/* Midway between the surfaces: only the coordinate along the normal moves. */
			cdReal x[3] = {in[i].x[0], in[i].x[1], in[i].x[2]};
			x[k] -= CD_R(0.5) * separation * sign;
			candidates[kept].point = cd3MakeVec(x[0], x[1], x[2]);
			candidates[kept].separation = separation;
			candidates[kept].id =
				PackFaceId(face, incident, in[i > 0 ? i - 1 : count - 1].tag, in[i].tag, flip);
			++kept;
		}
	}
	if (kept == 0)
	{
		return;
	}
	cd3Vec n = AxisVector(k, sign);
	Candidate reduced[4];
	const Candidate* chosen = candidates;
	int chosenCount = kept;
	if (kept > 4)
	{
		chosenCount = ReducePoints(candidates, kept, n, reduced);
		chosen = reduced;
	}
	cd3Vec worldNormal = n;
	if (refFrame == NULL)
	{
		/* The reference box's frame is the world's up to its centre (a box in its body's frame
		 * in the local form): the points and the normal as they are. */
		for (int i = 0; i < chosenCount; ++i)
		{
			AddPoint(m, cd3Add(ref->center, chosen[i].point), chosen[i].separation, chosen[i].id);
		}
	}
	else
	{
		for (int i = 0; i < chosenCount; ++i)
		{
			AddPoint(m, cd3Add(ref->center, cd3MulMV(*refFrame, chosen[i].point)), chosen[i].separation,
					 chosen[i].id);
		}
		worldNormal = cd3MulMV(*refFrame, n);
	}
	m->normal = flip ? cd3Neg(worldNormal) : worldNormal;
}

/* EdgeContact for two boxes: the closest points of the two edges in A's frame (rot, t: B's frame
 * in A's). Edge A runs along A's axis i through cA, edge B along B's axis j (column j of rot)
 * through cB: with w = cA - cB, b = rot[i][j], d = w[i] and e = column j . w, the lines' closest
 * parameters solve s = b t - d and t = b s + e, so s (1 - b^2) = b e - d, where 1 - b^2 is the
 * squared length of A_i x B_j, taken as the sum of the squares of the column's two other
 * entries (exact for nearly parallel edges, unlike 1 - b^2). Each parameter is then clamped to
 * its edge as for segments (Ericson 5.1.9): the edges an edge axis selects cross within both
 * segments but for round-off, so the clamping only guards. */
static void BoxEdgeContact(const cd3Box* a, const cd3Box* b, const cd3SatResult* sat, const cd3Mat33* rot,
						   cd3Vec t, cd3Manifold* m)
{
	cd3Vec p1, p2, q1, q2;
	cd3BoxEdgeLocal(a->halfExtents, sat->edgeA, &p1, &p2);
	cd3BoxEdgeLocal(b->halfExtents, sat->edgeB, &q1, &q2);
	int i = p1.x != p2.x ? 0 : (p1.y != p2.y ? 1 : 2);
	int j = q1.x != q2.x ? 0 : (q1.y != q2.y ? 1 : 2);
	cdReal ha = Component(a->halfExtents, i), hb = Component(b->halfExtents, j);
	/* The edges' midpoints: the endpoints with the coordinate along the edge set to zero. */
	cdReal ca[3] = {p1.x, p1.y, p1.z};
	ca[i] = CD_R(0.0);
	cdReal cbLocal[3] = {q1.x, q1.y, q1.z};
	cbLocal[j] = CD_R(0.0);
	cd3Vec cb = cd3Add(t, cd3MulMV(*rot, cd3MakeVec(cbLocal[0], cbLocal[1], cbLocal[2])));
	cd3Vec v = j == 0 ? rot->cx : (j == 1 ? rot->cy : rot->cz);
	cdReal vc[3] = {v.x, v.y, v.z};
	cdReal w[3] = {ca[0] - cb.x, ca[1] - cb.y, ca[2] - cb.z};
	cdReal along = vc[i];
	cdReal d = w[i];
	cdReal e = vc[0] * w[0] + vc[1] * w[1] + vc[2] * w[2];
	cdReal v1 = vc[(i + 1) % 3], v2 = vc[(i + 2) % 3];
	cdReal sine2 = v1 * v1 + v2 * v2;
	cdReal s = CD_R(0.0);
	if (sine2 > CD3_BOX_PARALLEL_SINE * CD3_BOX_PARALLEL_SINE)
	{
		s = cdClamp((along * e - d) / sine2, -ha, ha);
	}
	cdReal u = along * s + e;
	if (u < -hb || u > hb)
	{
		u = cdClamp(u, -hb, hb);
		s = cdClamp(along * u - d, -ha, ha);
	}
	/* Midway between the edges' closest points. */
	cdReal mid[3] = {ca[0] + cb.x + u * vc[0], ca[1] + cb.y + u * vc[1], ca[2] + cb.z + u * vc[2]};
	mid[i] += s;
	cd3Vec local = cd3MakeVec(CD_R(0.5) * mid[0], CD_R(0.5) * mid[1], CD_R(0.5) * mid[2]);
	cd3Quat qa = a->rotation;
	bool identityA = cd3IsIdentityQuatBits(qa);
	cd3Transform frame = {a->center, qa};
	cd3Vec normal = cd3Normalize(sat->edgeNormal);
	uint32_t id =
		CD3_FEATURE_EDGES | ((uint32_t)sat->edgeA & 0x7fffu) | (((uint32_t)sat->edgeB & 0x7fffu) << 15);
	cd3Vec point = identityA ? cd3Add(a->center, local) : cd3TransformPoint(frame, local);
#if CD3_BOX_FACES_SSE
	/* The manifold (empty on entry) written in the 16-byte pieces its caller copies it by, each
	 * from one store: the normal and x, then y, z, the separation and the id, and the count at the
	 * end (field stores read back 16 bytes at a time stalled on store forwarding). */
	_Static_assert(sizeof(cd3Manifold) == 96 && offsetof(cd3Manifold, points) == 12 &&
					   offsetof(cd3Manifold, pointCount) == 92 && sizeof(cd3ManifoldPoint) == 20,
				   "cd3Manifold layout (float build)");
	uint32_t yBits, zBits, separationBits;
	memcpy(&yBits, &point.y, sizeof yBits);
	memcpy(&zBits, &point.z, sizeof zBits);
	memcpy(&separationBits, &sat->edgeSeparation, sizeof separationBits);
	char* bytes = (char*)m;
	_mm_storeu_ps((float*)(void*)bytes, _mm_setr_ps(normal.x, normal.y, normal.z, point.x));
	_mm_storeu_si128((__m128i*)(void*)(bytes + 16),
					 _mm_setr_epi32((int)yBits, (int)zBits, (int)separationBits, (int)id));
	_mm_storeu_si128((__m128i*)(void*)(bytes + 80), _mm_setr_epi32(0, 0, 0, 1));
#else
	m->normal = normal;
	AddPoint(m, point, sat->edgeSeparation, id);
#endif
}

/* The box-box manifold on boxes passed by address: the public functions take them by value, and
 * the local-frame form's placed box passed on by value again was written and read back through
 * the stack (store-forwarding stalls) on every call. */
static cd3Manifold CollideBoxes(const cd3Box* boxA, const cd3Box* boxB, const cd3BoxFaces* faces,
								cdReal speculativeDistance)
{
	const cd3Box* a = boxA;
	const cd3Box* b = boxB;
	cd3Mat33 rot;
	cd3Vec t;
	cd3SatResult sat;
	/* Edge axes only when no face normal already puts the boxes beyond the speculative distance:
	 * the answer is then empty whatever they give. */
	cd3SatBoxesInPlace(a, b, &sat, &rot, &t, speculativeDistance, faces);
	cdReal separation = cd3SatSeparation(&sat);
	/* Every path returns m, so that it is built in the caller's result. */
	cd3Manifold m = EmptyManifold();
	if (!(separation <= speculativeDistance))
	{
		return m;
	}
	if (separation <= CD_R(0.0))
	{
		/* The choice of SatContact, with the box clipping; the size for the tie bias only when a
		 * tie is possible. */
		cdReal size = -CD_R(1.0);
		/* Above this bound of size (its 1-norm form, which is at least the 2-norms) a lead decides
		 * without the square roots of size, which sat on the path to the choice's branch. */
		cdReal sizeBound = CD_R(2.02) * (cd3AbsNoBranch(a->halfExtents.x) + cd3AbsNoBranch(a->halfExtents.y) +
										 cd3AbsNoBranch(a->halfExtents.z) + cd3AbsNoBranch(b->halfExtents.x) +
										 cd3AbsNoBranch(b->halfExtents.y) + cd3AbsNoBranch(b->halfExtents.z));
		bool useB = false;
		if (sat.faceSeparationB > sat.faceSeparationA)
		{
			useB = sat.faceSeparationB > sat.faceSeparationA + FACE_BIAS * sizeBound;
			if (!useB)
			{
				size = CD_R(2.0) * (cd3Length(a->halfExtents) + cd3Length(b->halfExtents));
				useB = sat.faceSeparationB > sat.faceSeparationA + FACE_BIAS * size;
			}
		}
		cdReal faceSeparation = useB ? sat.faceSeparationB : sat.faceSeparationA;
		bool useEdges = false;
		if (sat.edgeA >= 0 && sat.edgeSeparation > faceSeparation)
		{
			useEdges = sat.edgeSeparation > faceSeparation + EDGE_BIAS * sizeBound;
			if (!useEdges)
			{
				size = size < CD_R(0.0) ? CD_R(2.0) * (cd3Length(a->halfExtents) + cd3Length(b->halfExtents))
										: size;
				useEdges = sat.edgeSeparation > faceSeparation + EDGE_BIAS * size;
			}
		}
		if (useEdges)
		{
			BoxEdgeContact(a, b, &sat, &rot, t, &m);
			return m;
		}
		/* The reference box's frame in the world: with A's rotation the identity (a box in its
		 * body's frame, the local form), none for A and the rotation already in hand for B. */
		cd3Quat qa = a->rotation;
		bool identityA = cd3IsIdentityQuatBits(qa);
		cd3Mat33 frame;
		if (useB)
		{
			/* A's frame in B's: the transposed rotation. */
			cd3Mat33 inverse = cd3Transpose(rot);
			cd3Vec back = cd3Neg(cd3MulMV(inverse, t));
			frame = identityA ? rot : cd3MakeMatFromQuat(b->rotation);
			BoxFaceContact(b, sat.faceB, a, &inverse, back, &frame, true, speculativeDistance, &m);
		}
		else
		{
			if (!identityA)
			{
				frame = cd3MakeMatFromQuat(qa);
			}
			BoxFaceContact(a, sat.faceA, b, &rot, t, identityA ? NULL : &frame, false, speculativeDistance,
						   &m);
		}
		if (m.pointCount > 0)
		{
			cdReal deepest = m.points[0].separation;
			for (int i = 1; i < m.pointCount; ++i)
			{
				deepest = cdMin(deepest, m.points[i].separation);
			}
			if (deepest == separation || MatchBoxDepth(&m, separation, a, b))
			{
				return m;
			}
		}
	}
	/* Apart (the GJK distance decides the features), or the incident face clipped away or missed
	 * the overlap: the polytope path, with every edge pair in the second case. */
	cd3Polytope pa, pb;
	cd3InitBoxPolytope(&pa, *a);
	cd3InitBoxPolytope(&pb, *b);
	m = CollidePolytopesSat(&pa, &pb, separation <= CD_R(0.0) ? cd3SatPolytopes(&pa, &pb) : sat, false,
							speculativeDistance);
	return m;
}

cd3Manifold cd3CollideBoxBox(cd3Box a, cd3Box b, cdReal speculativeDistance)
{
	return CollideBoxes(&a, &b, NULL, speculativeDistance);
}

/* B placed in A's frame as manifold_local3.c places it (the same answer as cd3CollideBoxBox on
 * the placed box, bit for bit), handed on by address. */
cd3Manifold cd3CollideBoxBoxLocal(cd3Box a, cd3Box b, cd3Transform xfB, cdReal speculativeDistance)
{
	/* A box centred in its body's frame (the common case) is placed by xfB alone: the products with
	 * the zero centre and the identity rotation give xfB's own components (up to the sign of a zero). */
	bool centred = cd3AreZeroBits(b.center.x, b.center.y, b.center.z);
	bool aligned = cd3IsIdentityQuatBits(b.rotation);
	cd3Box placed;
#if CD3_BOX_FACES_SSE
	/* Both boxes in their bodies' frames (the common case): B's frame and the face separations
	 * from xfB at once, and the pairs apart along a face normal (most of those a broadphase
	 * reports apart) end here, before anything is stored. The SAT takes the rest on from them. */
	if (((int)centred & (int)aligned & (int)cd3IsIdentityQuatBits(a.rotation)) != 0)
	{
		cd3BoxFaces faces;
		if (cd3ComputeBoxFaces(&faces, a.halfExtents, b.halfExtents, xfB.q, cd3Sub(xfB.p, a.center),
							   speculativeDistance, true))
		{
			return EmptyManifold();
		}
		placed.halfExtents = b.halfExtents;
		placed.center = xfB.p;
		placed.rotation = xfB.q;
		return CollideBoxes(&a, &placed, &faces, speculativeDistance);
	}
#endif
	placed.halfExtents = b.halfExtents;
	placed.center = centred ? xfB.p : cd3TransformPoint(xfB, b.center);
	placed.rotation = aligned ? xfB.q : cd3MulQuat(xfB.q, b.rotation);
	return CollideBoxes(&a, &placed, NULL, speculativeDistance);
}

/* ---- hulls that are boxes --------------------------------------------------------------------- */

/* Face normals of a box hull are parallel or orthogonal to within this cosine: round-off of
 * hulls computed from a box's corners, far below the manifold's tolerances. */
#define BOX_HULL_TOLERANCE (CD_R(64.0) * CD_REAL_EPSILON)

/* The quaternion of a rotation matrix with orthonormal columns (Shepperd's choice of the largest
 * diagonal term, for precision). */
static cd3Quat QuatFromColumns(cd3Vec cx, cd3Vec cy, cd3Vec cz)
{
	cdReal trace = cx.x + cy.y + cz.z;
	cd3Quat q;
	if (trace > CD_R(0.0))
	{
		cdReal s = CD_R(2.0) * cdSqrt(trace + CD_R(1.0));
		q = cd3MakeQuat((cy.z - cz.y) / s, (cz.x - cx.z) / s, (cx.y - cy.x) / s, CD_R(0.25) * s);
	}
	else if (cx.x > cy.y && cx.x > cz.z)
	{
		cdReal s = CD_R(2.0) * cdSqrt(CD_R(1.0) + cx.x - cy.y - cz.z);
		q = cd3MakeQuat(CD_R(0.25) * s, (cy.x + cx.y) / s, (cz.x + cx.z) / s, (cy.z - cz.y) / s);
	}
	else if (cy.y > cz.z)
	{
		cdReal s = CD_R(2.0) * cdSqrt(CD_R(1.0) + cy.y - cx.x - cz.z);
		q = cd3MakeQuat((cy.x + cx.y) / s, CD_R(0.25) * s, (cz.y + cy.z) / s, (cz.x - cx.z) / s);
	}
	else
	{
		cdReal s = CD_R(2.0) * cdSqrt(CD_R(1.0) + cz.z - cx.x - cy.y);
		q = cd3MakeQuat((cz.x + cx.z) / s, (cz.y + cy.z) / s, CD_R(0.25) * s, (cx.y - cy.x) / s);
	}
	return cd3NormalizeQuat(q);
}

/* A hull that is a box (8 vertices, 6 faces along three orthogonal axes) as that box in the world, for the
 * box-box path: a box handed in as a hull (as cd3MakeBoxHull makes, or the hull of a box's corners) collides
 * as fast as a cd3Box. */
static bool HullAsBox(cd3HullShape shape, cd3Box* box)
{
	const cd3Hull* h = shape.hull;
	if (h->vertexCount != 8 || h->faceCount != 6 || h->edgeCount != 24)
	{
		return false;
	}
	const cd3Plane* planes = h->planes;
	/* The common case first: the faces exactly along the hull frame's axes (cd3MakeBoxHull, or the
	 * hull of a box's corners given in its frame). */
	cdReal offsets[6] = {0};
	int filled = 0;
	for (int f = 0; f < 6; ++f)
	{
		cd3Vec n = planes[f].normal;
		int onX = cdAbs(n.x) == CD_R(1.0), onY = cdAbs(n.y) == CD_R(1.0), onZ = cdAbs(n.z) == CD_R(1.0);
		int axis = onY + 2 * onZ;
		cdReal along = onX ? n.x : onY ? n.y : n.z;
		int slot = 2 * axis + (along < CD_R(0.0));
		filled |= (onX + onY + onZ == 1) << slot;
		offsets[slot] = planes[f].offset;
	}
	if (filled == 63)
	{
		cd3Vec half = cd3MakeVec(CD_R(0.5) * (offsets[0] + offsets[1]), CD_R(0.5) * (offsets[2] + offsets[3]),
								 CD_R(0.5) * (offsets[4] + offsets[5]));
		if (!(cdMin(half.x, cdMin(half.y, half.z)) > CD_R(0.0)))
		{
			return false;
		}
		cd3Vec centre =
			cd3MakeVec(CD_R(0.5) * (offsets[0] - offsets[1]), CD_R(0.5) * (offsets[2] - offsets[3]),
					   CD_R(0.5) * (offsets[4] - offsets[5]));
		box->center = cd3TransformPoint(shape.transform, centre);
		box->halfExtents = half;
		box->rotation = shape.transform.q;
		return true;
	}
	/* The axes: the normal most along x, then the one orthogonal to it most along y (the identity
	 * for an axis-aligned box, exactly). Selects, not branches: the faces come in any order. */
	int ix = 0;
	for (int f = 1; f < 6; ++f)
	{
		ix = planes[f].normal.x > planes[ix].normal.x ? f : ix;
	}
	cd3Vec ax = planes[ix].normal;
	int iy = -1;
	cdReal bestY = -CD_REAL_MAX;
	for (int f = 0; f < 6; ++f)
	{
		cd3Vec n = planes[f].normal;
		bool candidate = cdAbs(cd3Dot(n, ax)) <= BOX_HULL_TOLERANCE && n.y > bestY;
		iy = candidate ? f : iy;
		bestY = candidate ? n.y : bestY;
	}
	if (iy < 0)
	{
		return false;
	}
	cd3Vec ay = planes[iy].normal, az;
	cd3Quat rotation;
	if (ax.x == CD_R(1.0) && ax.y == CD_R(0.0) && ax.z == CD_R(0.0) && ay.x == CD_R(0.0) &&
		ay.y == CD_R(1.0) && ay.z == CD_R(0.0))
	{
		/* Axis-aligned (cd3MakeBoxHull, or the hull of a box's corners in its frame). */
		az = cd3MakeVec(CD_R(0.0), CD_R(0.0), CD_R(1.0));
		rotation = shape.transform.q;
	}
	else
	{
		az = cd3Normalize(cd3Cross(ax, ay));
		ay = cd3Cross(az, ax);
		rotation = cd3MulQuat(shape.transform.q, QuatFromColumns(ax, ay, az));
	}
	/* Each face along one axis, one face on each side of each: the box between those planes (the
	 * hull's vertices lie on its planes, so on the box's corners). */
	cdReal aligned = CD_R(1.0) - BOX_HULL_TOLERANCE;
	filled = 0;
	bool valid = true;
	for (int f = 0; f < 6; ++f)
	{
		cd3Vec n = planes[f].normal;
		cdReal c[3] = {cd3Dot(n, ax), cd3Dot(n, ay), cd3Dot(n, az)};
		int onX = cdAbs(c[0]) >= aligned, onY = cdAbs(c[1]) >= aligned, onZ = cdAbs(c[2]) >= aligned;
		valid = valid && onX + onY + onZ == 1;
		int axis = onY + 2 * onZ;
		int slot = 2 * axis + (c[axis] < CD_R(0.0));
		filled |= 1 << slot;
		offsets[slot] = planes[f].offset;
	}
	cd3Vec half = cd3MakeVec(CD_R(0.5) * (offsets[0] + offsets[1]), CD_R(0.5) * (offsets[2] + offsets[3]),
							 CD_R(0.5) * (offsets[4] + offsets[5]));
	cd3Vec extent = cd3Sub(h->bounds.max, h->bounds.min);
	cdReal tolerance = BOX_HULL_TOLERANCE * (extent.x + extent.y + extent.z);
	if (!valid || filled != 63 || !(cdMin(half.x, cdMin(half.y, half.z)) > tolerance))
	{
		return false;
	}
	cd3Vec centre = cd3Add(cd3Add(cd3Scale(CD_R(0.5) * (offsets[0] - offsets[1]), ax),
								  cd3Scale(CD_R(0.5) * (offsets[2] - offsets[3]), ay)),
						   cd3Scale(CD_R(0.5) * (offsets[4] - offsets[5]), az));
	box->center = cd3TransformPoint(shape.transform, centre);
	box->halfExtents = half;
	box->rotation = rotation;
	return true;
}

cd3Manifold cd3CollideBoxHull(cd3Box a, cd3HullShape b, cdReal speculativeDistance)
{
	cd3Box boxB;
	if (HullAsBox(b, &boxB))
	{
		return cd3CollideBoxBox(a, boxB, speculativeDistance);
	}
	cd3Polytope pa, pb;
	cd3InitBoxPolytope(&pa, a);
	cd3InitHullPolytope(&pb, b);
	return CollidePolytopes(&pa, &pb, speculativeDistance);
}

cd3Manifold cd3CollideBoxTriangle(cd3Box a, cd3Triangle b, cdReal speculativeDistance)
{
	cd3Polytope pa, pb;
	cd3InitBoxPolytope(&pa, a);
	cd3InitTrianglePolytope(&pb, b);
	return CollidePolytopes(&pa, &pb, speculativeDistance);
}

cd3Manifold cd3CollideHullHull(cd3HullShape a, cd3HullShape b, cdReal speculativeDistance)
{
	cd3Box boxA, boxB;
	if (HullAsBox(a, &boxA) && HullAsBox(b, &boxB))
	{
		return cd3CollideBoxBox(boxA, boxB, speculativeDistance);
	}
	cd3Polytope pa, pb;
	cd3InitHullPolytope(&pa, a);
	cd3InitHullPolytope(&pb, b);
	return CollidePolytopes(&pa, &pb, speculativeDistance);
}

cd3Manifold cd3CollideHullTriangle(cd3HullShape a, cd3Triangle b, cdReal speculativeDistance)
{
	cd3Polytope pa, pb;
	cd3InitHullPolytope(&pa, a);
	cd3InitTrianglePolytope(&pb, b);
	return CollidePolytopes(&pa, &pb, speculativeDistance);
}

/* ---- dispatch --------------------------------------------------------------------------------- */

/* Rank in the manifold order Sphere, Capsule, Box (and AABB), Hull, Triangle; -1: unsupported. */
static int Rank(cd3ShapeType type)
{
	switch (type)
	{
		case CD3_SHAPE_SPHERE:
			return 0;
		case CD3_SHAPE_CAPSULE:
			return 1;
		case CD3_SHAPE_AABB:
		case CD3_SHAPE_BOX:
			return 2;
		case CD3_SHAPE_HULL:
			return 3;
		case CD3_SHAPE_TRIANGLE:
			return 4;
		default:
			return -1;
	}
}

static cd3Box ShapeBox(const cd3Shape* s)
{
	if (s->type == CD3_SHAPE_BOX)
	{
		return s->box;
	}
	cd3Box box;
	box.center = cd3AabbCenter(s->aabb);
	box.halfExtents = cd3AabbHalfExtents(s->aabb);
	box.rotation = CD3_QUAT_IDENTITY;
	return box;
}

static void InitPolytope(cd3Polytope* p, const cd3Shape* s)
{
	if (s->type == CD3_SHAPE_HULL)
	{
		cd3InitHullPolytope(p, s->hull);
	}
	else if (s->type == CD3_SHAPE_TRIANGLE)
	{
		cd3InitTrianglePolytope(p, s->triangle);
	}
	else
	{
		cd3InitBoxPolytope(p, ShapeBox(s));
	}
}

cd3Manifold cd3Collide(const cd3Shape* a, const cd3Shape* b, cdReal speculativeDistance)
{
	CD_ASSERT(a != NULL && b != NULL);
	/* A pair with a typed function in the pair tables (pairs3.h) calls it, in the tables' (enum)
	 * order; the CORE pairs (an AABB collides as a box) take the polytopes below, and the NONE
	 * pairs (planes, segments) have no manifold. */
	{
		bool flip = a->type > b->type;
		const cd3Shape* first = flip ? b : a;
		const cd3Shape* second = flip ? a : b;
		switch (CD3_PAIR_KEY(first->type, second->type))
		{
#define CD3_COLLIDE_TYPED_CASE(A, B, Collide)                                                                \
	case CD3_PAIR_KEY(CD3_TYPE_##A, CD3_TYPE_##B):                                                           \
	{                                                                                                        \
		cd3Manifold typed = Collide(CD3_SHAPE_ARG(A, first), CD3_SHAPE_ARG(B, second), speculativeDistance); \
		return flip ? Flipped(typed) : typed;                                                                \
	}
#define CD3_COLLIDE_CASE(A, B, Overlap, Distance, Collide)                                                   \
	CD_PAIR_TYPED(Collide, CD3_COLLIDE_TYPED_CASE)(A, B, Collide)
			CD3_PAIR_TABLE(CD3_COLLIDE_CASE)
			CD3_HULL_PAIR_TABLE(CD3_COLLIDE_CASE)
#undef CD3_COLLIDE_CASE
#undef CD3_COLLIDE_TYPED_CASE
			default:
				break;
		}
	}
	int rankA = Rank(a->type), rankB = Rank(b->type);
	if (rankA < 0 || rankB < 0)
	{
		return EmptyManifold();
	}
	if (rankA == 4 && rankB == 4)
	{
		return cd3CollideTriangleTriangle(a->triangle, b->triangle, speculativeDistance);
	}
	bool swap = rankA > rankB;
	if (swap)
	{
		const cd3Shape* t = a;
		a = b;
		b = t;
		int r = rankA;
		rankA = rankB;
		rankB = r;
	}
	cd3Manifold m;
	if (rankB <= 1)
	{
		if (rankB == 0)
		{
			m = cd3CollideSphereSphere(a->sphere, b->sphere, speculativeDistance);
		}
		else if (rankA == 0)
		{
			m = cd3CollideSphereCapsule(a->sphere, b->capsule, speculativeDistance);
		}
		else
		{
			m = cd3CollideCapsuleCapsule(a->capsule, b->capsule, speculativeDistance);
		}
	}
	else
	{
		cd3Polytope pb;
		InitPolytope(&pb, b);
		if (rankA == 0)
		{
			m = CollideCorePolytope(a->sphere.center, a->sphere.center, a->sphere.radius, &pb,
									speculativeDistance);
		}
		else if (rankA == 1)
		{
			m = CollideCorePolytope(a->capsule.p1, a->capsule.p2, a->capsule.radius, &pb,
									speculativeDistance);
		}
		else if (rankA == 2 && rankB == 2)
		{
			m = cd3CollideBoxBox(ShapeBox(a), ShapeBox(b), speculativeDistance);
		}
		else
		{
			cd3Polytope pa;
			InitPolytope(&pa, a);
			m = CollidePolytopes(&pa, &pb, speculativeDistance);
		}
	}
	return swap ? Flipped(m) : m;
}
