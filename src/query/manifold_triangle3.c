/* collide: contact manifold between two triangles (two-sided, not solid).
 *
 * Pairs that some axis (box axes, face normals, edge-edge axes) separates beyond the speculative
 * distance return at once. Crossing pairs (cd3OverlapTriangleTriangle) go to the separating axis
 * test below; the others are sorted by their exact distance (the closest of the six
 * edge-against-triangle pairs):
 * - apart by more than a small fraction of their size: the normal is the direction between the
 *   closest points. When it is (nearly) a face normal, the other triangle is clipped against that
 *   face's side planes and its points within the speculative distance are kept (a face contact);
 *   otherwise the contact is the one closest pair (an edge or a vertex).
 * - touching, crossing or nearly so: the separating axis test over both face normals, the nine
 *   edge-edge axes (and, for parallel faces, the in-plane edge normals) picks the axis of least
 *   penetration, each axis read in the direction B lies on. A face axis clips the other triangle
 *   against that face; an edge axis gives the edges' closest points; an in-plane axis the
 *   closest points. A's face is preferred over B's, faces over the other axes, within a bias of
 *   1e-4 of the triangles' size, so the choice does not flicker between frames.
 * Up to 6 clipped points are reduced to 4: the deepest, the farthest from it, then the two that
 * span the most area on either side. Degenerate triangles (zero area) lose their face axis and
 * behave as the segment or point they are. */
#include "collide/manifold3.h"

/* Fraction of the triangles' size: below it the closest-point direction is too uncertain to be
 * the normal (the separating axis test decides), and the bias of the axis choice. */
#define DIRECT_PATH_FRACTION CD_R(1.0e-3)
#define AXIS_BIAS_FRACTION CD_R(1.0e-4)
/* Cosine above which the closest-point direction counts as a face normal. */
#define FACE_ALIGNMENT CD_R(0.9999)
/* Sine of the angle between two edges below which their cross product is not an axis. */
#define PARALLEL_SINE CD_R(1.0e-5)

#define ID_CLIPPED 0x100u
#define ID_CLOSEST 0x200u

typedef struct Triangle
{
	cd3Vec v[3];
	cd3Vec e[3];	/* e[i] = v[i + 1] - v[i] */
	cd3Vec winding; /* the unit normal of the winding (zero for a degenerate triangle) */
	cd3Vec normal;	/* unit, zero for a degenerate triangle */
} Triangle;

static void SetEdges(Triangle* t)
{
	for (int i = 0; i < 3; ++i)
	{
		t->e[i] = cd3Sub(t->v[(i + 1) % 3], t->v[i]);
	}
}

/* The unit vector along cross(a1 - a0, b1 - b0), computed in double from the coordinates (zero
 * when the cross product is). In float, the differences and the cross product of a sliver's edges
 * lose the digits its normal lives on: a 1e-5 sliver's normal was off by 1e-2 rad, and a face
 * contact's separation by 3e-4. *length gets the cross product's length, *sineSquared the square
 * of the sine of the angle between the two edges (0 when one has no length). */
static cd3Vec UnitCross(cd3Vec a0, cd3Vec a1, cd3Vec b0, cd3Vec b1, double* length, double* sineSquared)
{
	double ax = (double)a1.x - (double)a0.x, ay = (double)a1.y - (double)a0.y,
		   az = (double)a1.z - (double)a0.z;
	double bx = (double)b1.x - (double)b0.x, by = (double)b1.y - (double)b0.y,
		   bz = (double)b1.z - (double)b0.z;
	double cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
	double cc = cx * cx + cy * cy + cz * cz;
	double product = (ax * ax + ay * ay + az * az) * (bx * bx + by * by + bz * bz);
	*sineSquared = product > 0.0 ? cc / product : 0.0;
	double l = sqrt(cc);
	*length = l;
	if (!(l > 0.0))
	{
		return cd3MakeVec(CD_R(0.0), CD_R(0.0), CD_R(0.0));
	}
	return cd3MakeVec((cdReal)(cx / l), (cdReal)(cy / l), (cdReal)(cz / l));
}

static void MakeTriangle(Triangle* t, cd3Triangle source, cdReal size)
{
	t->v[0] = source.a;
	t->v[1] = source.b;
	t->v[2] = source.c;
	SetEdges(t);
	double area2, sineSquared;
	cd3Vec normal = UnitCross(t->v[0], t->v[1], t->v[0], t->v[2], &area2, &sineSquared);
	/* Zero area up to round-off of the size: no face axis. */
	if (area2 > 64.0 * (double)CD_REAL_EPSILON * (double)size * (double)size)
	{
		t->normal = normal;
		t->winding = normal;
		return;
	}
	t->normal = cd3MakeVec(CD_R(0.0), CD_R(0.0), CD_R(0.0));
	t->winding = t->normal;
	/* The segment it is: its longest edge, the third vertex on an end. Otherwise a shorter edge
	 * of the three collinear ones could be taken for the contact edge. */
	int longest = 0;
	for (int i = 1; i < 3; ++i)
	{
		longest = cd3LengthSquared(t->e[i]) > cd3LengthSquared(t->e[longest]) ? i : longest;
	}
	cd3Vec p = t->v[longest], q = t->v[(longest + 1) % 3];
	t->v[0] = p;
	t->v[1] = q;
	t->v[2] = q;
	SetEdges(t);
}

/* Clipped points closer than this are one point. */
static cdReal WeldTolerance(cdReal size)
{
	return CD_R(1.0e-6) * size;
}

static cd3Manifold EmptyManifold(void)
{
	cd3Manifold m;
	m.normal = cd3MakeVec(CD_R(0.0), CD_R(0.0), CD_R(0.0));
	m.pointCount = 0;
	for (int i = 0; i < 4; ++i)
	{
		m.points[i].point = m.normal;
		m.points[i].separation = CD_R(0.0);
		m.points[i].id = 0u;
	}
	return m;
}

static void Interval(const Triangle* t, cd3Vec axis, cdReal* lower, cdReal* upper)
{
	cdReal d0 = cd3Dot(t->v[0], axis), d1 = cd3Dot(t->v[1], axis), d2 = cd3Dot(t->v[2], axis);
	*lower = cdMin(d0, cdMin(d1, d2));
	*upper = cdMax(d0, cdMax(d1, d2));
}

/* Separation of the triangles along a unit axis, read in the direction B lies on: *normal gets
 * axis or -axis (from A to B). */
static cdReal AxisSeparation(const Triangle* a, const Triangle* b, cd3Vec axis, cd3Vec* normal)
{
	cdReal aLower, aUpper, bLower, bUpper;
	Interval(a, axis, &aLower, &aUpper);
	Interval(b, axis, &bLower, &bUpper);
	cdReal positive = bLower - aUpper, negative = aLower - bUpper;
	if (positive >= negative)
	{
		*normal = axis;
		return positive;
	}
	*normal = cd3Neg(axis);
	return negative;
}

/* ---- clipping --------------------------------------------------------------------------------- */

typedef struct ClipVertex
{
	cd3Vec p;
	uint32_t id;   /* incident vertex index, or ID_CLIPPED | edge source << 4 | plane */
	uint32_t edge; /* source of the edge from this vertex to the next: incident edge 0-2, plane 3-5 */
} ClipVertex;

/* Keeps the part of the polygon where dot(inward, p - origin) >= 0 (Sutherland-Hodgman). */
static int ClipPolygon(const ClipVertex* in, int count, cd3Vec origin, cd3Vec inward, uint32_t plane,
					   ClipVertex* out)
{
	int n = 0;
	for (int i = 0; i < count; ++i)
	{
		const ClipVertex* p = &in[i];
		const ClipVertex* q = &in[(i + 1) % count];
		cdReal dp = cd3Dot(inward, cd3Sub(p->p, origin));
		cdReal dq = cd3Dot(inward, cd3Sub(q->p, origin));
		if (dp >= CD_R(0.0))
		{
			out[n++] = *p;
		}
		if ((dp >= CD_R(0.0)) != (dq >= CD_R(0.0)))
		{
			cdReal t = dp / (dp - dq);
			ClipVertex v;
			v.p = cd3Lerp(p->p, q->p, t);
			v.id = ID_CLIPPED | (p->edge << 4) | plane;
			/* Leaving: the polygon runs along the plane from here; entering: along the cut edge. */
			v.edge = dp >= CD_R(0.0) ? 3u + plane : p->edge;
			out[n++] = v;
		}
	}
	return n;
}

static cdReal TriangleArea2(cd3Vec a, cd3Vec b, cd3Vec c, cd3Vec normal)
{
	return cd3Dot(cd3Cross(cd3Sub(b, a), cd3Sub(c, a)), normal);
}

/* Face contact: the incident triangle clipped against the reference face's side planes. m is the
 * unit normal from the reference toward the incident triangle, n the manifold's (from A to B). */
static cd3Manifold ClipFace(const Triangle* reference, const Triangle* incident, cd3Vec m, cd3Vec n,
							bool flip, cdReal weld, cdReal speculativeDistance)
{
	ClipVertex buffers[2][9];
	int count = 3;
	for (int i = 0; i < 3; ++i)
	{
		buffers[0][i].p = incident->v[i];
		buffers[0][i].id = (uint32_t)i;
		buffers[0][i].edge = (uint32_t)i;
	}
	int current = 0;
	for (int s = 0; s < 3 && count > 0; ++s)
	{
		cd3Vec inward = cd3Cross(reference->winding, reference->e[s]);
		count =
			ClipPolygon(buffers[current], count, reference->v[s], inward, (uint32_t)s, buffers[1 - current]);
		current = 1 - current;
	}

	ClipVertex kept[9];
	cdReal separations[9];
	int keptCount = 0;
	for (int i = 0; i < count; ++i)
	{
		cdReal separation = cd3Dot(cd3Sub(buffers[current][i].p, reference->v[0]), m);
		/* A vertex on a side plane comes out twice, a degenerate incident triangle three times. */
		bool duplicate = false;
		for (int k = 0; k < keptCount && !duplicate; ++k)
		{
			duplicate = cd3VecDistanceSquared(kept[k].p, buffers[current][i].p) <= weld * weld;
		}
		if (separation <= speculativeDistance && !duplicate)
		{
			separations[keptCount] = separation;
			kept[keptCount++] = buffers[current][i];
		}
	}
	cd3Manifold manifold = EmptyManifold();
	if (keptCount == 0)
	{
		return manifold;
	}

	int chosen[4];
	int chosenCount;
	if (keptCount <= 4)
	{
		chosenCount = keptCount;
		for (int i = 0; i < keptCount; ++i)
		{
			chosen[i] = i;
		}
	}
	else
	{
		int deepest = 0;
		for (int i = 1; i < keptCount; ++i)
		{
			deepest = separations[i] < separations[deepest] ? i : deepest;
		}
		int farthest = deepest == 0 ? 1 : 0;
		for (int i = 0; i < keptCount; ++i)
		{
			if (cd3VecDistanceSquared(kept[i].p, kept[deepest].p) >
				cd3VecDistanceSquared(kept[farthest].p, kept[deepest].p))
			{
				farthest = i;
			}
		}
		int left = -1, right = -1;
		cdReal leftArea = CD_R(0.0), rightArea = CD_R(0.0);
		for (int i = 0; i < keptCount; ++i)
		{
			cdReal area = TriangleArea2(kept[deepest].p, kept[farthest].p, kept[i].p, m);
			if (area > leftArea)
			{
				leftArea = area;
				left = i;
			}
			if (area < rightArea)
			{
				rightArea = area;
				right = i;
			}
		}
		chosenCount = 0;
		chosen[chosenCount++] = deepest;
		chosen[chosenCount++] = farthest;
		if (left >= 0)
		{
			chosen[chosenCount++] = left;
		}
		if (right >= 0)
		{
			chosen[chosenCount++] = right;
		}
	}

	manifold.normal = n;
	for (int k = 0; k < chosenCount; ++k)
	{
		int i = chosen[k];
		cd3ManifoldPoint* point = &manifold.points[manifold.pointCount++];
		point->point = cd3MulSub(kept[i].p, CD_R(0.5) * separations[i], m);
		point->separation = separations[i];
		point->id = kept[i].id | (flip ? CD3_FEATURE_FLIP : 0u);
	}
	return manifold;
}

static cd3Manifold SinglePoint(cd3Vec onA, cd3Vec onB, cd3Vec n, cdReal separation, uint32_t id)
{
	cd3Manifold manifold = EmptyManifold();
	manifold.normal = n;
	manifold.pointCount = 1;
	manifold.points[0].point = cd3Lerp(onA, onB, CD_R(0.5));
	manifold.points[0].separation = separation;
	manifold.points[0].id = id;
	return manifold;
}

/* ---- the two paths ---------------------------------------------------------------------------- */

/* Closest points of the two triangles over the six edge-against-triangle pairs; *pair says which
 * (0-2: edge of A against B, 3-5: edge of B against A). */
static cdReal ClosestPoints(cd3Triangle a, cd3Triangle b, const Triangle* ta, const Triangle* tb, cd3Vec* onA,
							cd3Vec* onB, int* pair)
{
	cdReal best = CD_REAL_MAX;
	for (int k = 0; k < 6; ++k)
	{
		const Triangle* edges = k < 3 ? ta : tb;
		int i = k % 3;
		cd3Segment segment = {edges->v[i], edges->v[(i + 1) % 3]};
		cd3ClosestPoints cp = cd3ClosestPointsTriangleSegment(k < 3 ? b : a, segment);
		if (cp.distance < best)
		{
			best = cp.distance;
			*pair = k;
			/* pointA is on the triangle, pointB on the segment. */
			*onA = k < 3 ? cp.pointB : cp.pointA;
			*onB = k < 3 ? cp.pointA : cp.pointB;
		}
	}
	return best;
}

/* The closest points, computed on first use: crossing triangles need them only in rare cases. */
typedef struct Closest
{
	cd3Triangle a, b;
	const Triangle *ta, *tb;
	cd3Vec onA, onB;
	cdReal distance;
	int pair;
	bool known;
} Closest;

static const Closest* GetClosest(Closest* c)
{
	if (!c->known)
	{
		c->distance = ClosestPoints(c->a, c->b, c->ta, c->tb, &c->onA, &c->onB, &c->pair);
		c->known = true;
	}
	return c;
}

static cd3Manifold SeparatedContact(const Triangle* a, const Triangle* b, cd3Vec onA, cd3Vec onB,
									cdReal distance, int pair, cdReal size, cdReal speculativeDistance)
{
	cdReal weld = WeldTolerance(size);
	cd3Vec n = cd3Scale(CD_R(1.0) / distance, cd3Sub(onB, onA));
	cdReal alignA = cd3Dot(n, a->normal), alignB = cd3Dot(n, b->normal);
	if (cdAbs(alignA) >= FACE_ALIGNMENT)
	{
		cd3Vec m = alignA > CD_R(0.0) ? a->normal : cd3Neg(a->normal);
		cd3Manifold manifold = ClipFace(a, b, m, m, false, weld, speculativeDistance);
		if (manifold.pointCount > 0)
		{
			return manifold;
		}
	}
	else if (cdAbs(alignB) >= FACE_ALIGNMENT)
	{
		cd3Vec m = alignB < CD_R(0.0) ? b->normal : cd3Neg(b->normal);
		cd3Manifold manifold = ClipFace(b, a, m, cd3Neg(m), true, weld, speculativeDistance);
		if (manifold.pointCount > 0)
		{
			return manifold;
		}
	}
	return SinglePoint(onA, onB, n, distance, ID_CLOSEST | (uint32_t)pair);
}

typedef enum AxisKind
{
	AXIS_NONE,
	AXIS_FACE_A,
	AXIS_FACE_B,
	AXIS_EDGES,
	AXIS_IN_PLANE
} AxisKind;

static cd3Manifold TouchingContact(const Triangle* a, const Triangle* b, Closest* closest, cdReal size,
								   cdReal speculativeDistance)
{
	cdReal bias = AXIS_BIAS_FRACTION * size;
	AxisKind kind = AXIS_NONE;
	cdReal best = -CD_REAL_MAX;
	cd3Vec normal = cd3MakeVec(CD_R(0.0), CD_R(0.0), CD_R(1.0));
	int edgeA = 0, edgeB = 0;

	bool faceA = cd3LengthSquared(a->normal) > CD_R(0.0), faceB = cd3LengthSquared(b->normal) > CD_R(0.0);
	if (faceA)
	{
		best = AxisSeparation(a, b, a->normal, &normal);
		kind = AXIS_FACE_A;
	}
	if (faceB)
	{
		cd3Vec candidate;
		cdReal s = AxisSeparation(a, b, b->normal, &candidate);
		if (kind == AXIS_NONE || s > best + bias)
		{
			best = s;
			normal = candidate;
			kind = AXIS_FACE_B;
		}
	}
	cdReal faceBest = best;
	for (int i = 0; i < 3; ++i)
	{
		for (int j = 0; j < 3; ++j)
		{
			double length, sineSquared;
			cd3Vec axis =
				UnitCross(a->v[i], a->v[(i + 1) % 3], b->v[j], b->v[(j + 1) % 3], &length, &sineSquared);
			if (!(sineSquared > (double)PARALLEL_SINE * (double)PARALLEL_SINE))
			{
				continue;
			}
			cd3Vec candidate;
			cdReal s = AxisSeparation(a, b, axis, &candidate);
			bool beats =
				kind == AXIS_NONE || (kind == AXIS_EDGES ? s > best : s > faceBest + bias && s > best);
			if (beats)
			{
				best = s;
				normal = candidate;
				kind = AXIS_EDGES;
				edgeA = i;
				edgeB = j;
			}
		}
	}
	/* Parallel faces: the in-plane edge normals separate triangles apart within their plane. */
	cd3Vec planeNormal = faceA ? a->normal : b->normal;
	if ((faceA || faceB) && cd3Length(cd3Cross(a->normal, b->normal)) <= PARALLEL_SINE * CD_R(100.0))
	{
		for (int k = 0; k < 6; ++k)
		{
			const Triangle* t = k < 3 ? a : b;
			cd3Vec axis = cd3Normalize(cd3Cross(planeNormal, t->e[k % 3]));
			if (cd3LengthSquared(axis) == CD_R(0.0))
			{
				continue;
			}
			cd3Vec candidate;
			cdReal s = AxisSeparation(a, b, axis, &candidate);
			if (s > best + bias)
			{
				best = s;
				normal = candidate;
				kind = AXIS_IN_PLANE;
			}
		}
	}

	if (best > speculativeDistance)
	{
		return EmptyManifold();
	}
	switch (kind)
	{
		case AXIS_FACE_A:
		case AXIS_FACE_B:
		{
			cd3Manifold manifold =
				kind == AXIS_FACE_A
					? ClipFace(a, b, normal, normal, false, WeldTolerance(size), speculativeDistance)
					: ClipFace(b, a, cd3Neg(normal), normal, true, WeldTolerance(size), speculativeDistance);
			if (manifold.pointCount > 0)
			{
				return manifold;
			}
			/* Nothing of the other triangle over the face (it touches just beside an edge): the
			 * closest pair, at the distance. */
			const Closest* c = GetClosest(closest);
			return SinglePoint(c->onA, c->onB, normal,
							   c->distance > CD_R(0.0) ? c->distance : cdMin(best, CD_R(0.0)),
							   ID_CLOSEST | (uint32_t)c->pair);
		}
		case AXIS_EDGES:
		{
			cd3Segment sa = {a->v[edgeA], a->v[(edgeA + 1) % 3]};
			cd3Segment sb = {b->v[edgeB], b->v[(edgeB + 1) % 3]};
			cd3ClosestPoints cp = cd3ClosestPointsSegmentSegment(sa, sb);
			return SinglePoint(cp.pointA, cp.pointB, normal, best,
							   CD3_FEATURE_EDGES | (uint32_t)edgeA | ((uint32_t)edgeB << 15));
		}
		case AXIS_IN_PLANE:
		{
			const Closest* c = GetClosest(closest);
			return SinglePoint(c->onA, c->onB, normal, best, ID_CLOSEST | (uint32_t)c->pair);
		}
		default:
		{
			/* Two collinear segments or points touching: no axis; any unit normal will do, one
			 * across A's direction so that it is at least perpendicular to the contact. */
			cd3Vec along = cd3Add(a->e[0], cd3Neg(a->e[2]));
			cd3Vec n = cd3LengthSquared(along) > CD_R(0.0)
						   ? cd3Normalize(cd3Perpendicular(cd3Normalize(along)))
						   : cd3MakeVec(CD_R(0.0), CD_R(0.0), CD_R(1.0));
			if (cd3LengthSquared(n) == CD_R(0.0))
			{
				n = cd3MakeVec(CD_R(0.0), CD_R(0.0), CD_R(1.0));
			}
			const Closest* c = GetClosest(closest);
			return SinglePoint(c->onA, c->onB, n, cdMin(best, CD_R(0.0)), ID_CLOSEST | (uint32_t)c->pair);
		}
	}
}

/* Whether some axis (the bounding boxes' axes, the face normals, the edge-edge axes) separates
 * the triangles by more than the speculative distance: then the distance does too, and the exact
 * closest points (the costly part) are not needed. The margin covers the round-off of the unit
 * axes at the coordinates' magnitude. */
static bool ClearlyApart(const Triangle* a, const Triangle* b, cdReal speculativeDistance)
{
	cdReal magnitude = CD_R(0.0);
	cd3Vec aLow = a->v[0], aHigh = a->v[0], bLow = b->v[0], bHigh = b->v[0];
	for (int i = 0; i < 3; ++i)
	{
		aLow = cd3Min(aLow, a->v[i]);
		aHigh = cd3Max(aHigh, a->v[i]);
		bLow = cd3Min(bLow, b->v[i]);
		bHigh = cd3Max(bHigh, b->v[i]);
		cd3Vec m = cd3Max(cd3Abs(a->v[i]), cd3Abs(b->v[i]));
		magnitude = cdMax(magnitude, cdMax(m.x, cdMax(m.y, m.z)));
	}
	cdReal limit = speculativeDistance + CD_R(16.0) * CD_REAL_EPSILON * magnitude;
	cd3Vec gap = cd3Max(cd3Sub(bLow, aHigh), cd3Sub(aLow, bHigh));
	if (gap.x > speculativeDistance || gap.y > speculativeDistance || gap.z > speculativeDistance)
	{
		return true;
	}
	cd3Vec normal;
	if (cd3LengthSquared(a->normal) > CD_R(0.0) && AxisSeparation(a, b, a->normal, &normal) > limit)
	{
		return true;
	}
	if (cd3LengthSquared(b->normal) > CD_R(0.0) && AxisSeparation(a, b, b->normal, &normal) > limit)
	{
		return true;
	}
	for (int i = 0; i < 3; ++i)
	{
		for (int j = 0; j < 3; ++j)
		{
			/* Any unit axis bounds the distance: the float cross product will do here. */
			cd3Vec axis = cd3Normalize(cd3Cross(a->e[i], b->e[j]));
			if (cd3LengthSquared(axis) > CD_R(0.5) && AxisSeparation(a, b, axis, &normal) > limit)
			{
				return true;
			}
		}
	}
	return false;
}

cd3Manifold cd3CollideTriangleTriangle(cd3Triangle a, cd3Triangle b, cdReal speculativeDistance)
{
	CD_ASSERT(speculativeDistance >= CD_R(0.0));
	/* The size: the longest edge of either triangle. */
	cd3Vec points[6] = {a.a, a.b, a.c, b.a, b.b, b.c};
	cdReal size = CD_R(0.0);
	for (int k = 0; k < 6; ++k)
	{
		int base = k < 3 ? 0 : 3;
		size = cdMax(size, cd3VecDistance(points[k], points[base + (k + 1) % 3]));
	}
	Triangle ta, tb;
	MakeTriangle(&ta, a, size);
	MakeTriangle(&tb, b, size);
	if (ClearlyApart(&ta, &tb, speculativeDistance))
	{
		return EmptyManifold();
	}

	Closest closest;
	closest.a = a;
	closest.b = b;
	closest.ta = &ta;
	closest.tb = &tb;
	closest.known = false;
	/* Crossing triangles go straight to the separating axis test. */
	if (!cd3OverlapTriangleTriangle(a, b))
	{
		const Closest* c = GetClosest(&closest);
		if (c->distance > speculativeDistance)
		{
			return EmptyManifold();
		}
		if (c->distance > DIRECT_PATH_FRACTION * size)
		{
			return SeparatedContact(&ta, &tb, c->onA, c->onB, c->distance, c->pair, size,
									speculativeDistance);
		}
	}
	return TouchingContact(&ta, &tb, &closest, size, speculativeDistance);
}
