/* collide: the separating axis test between polytopes (Gregorius, "The Separating Axis Test
 * between Convex Polyhedra", GDC 2013). Everything runs in A's local frame: B's vertices are
 * carried there by the relative transform. Face axes take the support vertex of the other
 * polytope; edge axes are kept only for the edge pairs whose arcs cross on the Gauss map (the
 * pairs that build a face of the Minkowski difference), so a pair's separation is simply the
 * distance between its two edges along the cross product. Flat polytopes (triangles) have
 * half-circle arcs, so their edge pairs are tested by projecting both polytopes instead. */
#include "sat3.h"

#include <string.h>

#include "sat3_box.h"
#include "sat3_support.h"

/* For rare branches kept out of the hot functions' code. */
#if defined(__GNUC__) || defined(__clang__)
#define SAT_NOINLINE __attribute__((noinline))
#else
#define SAT_NOINLINE
#endif

/* Edge pairs whose cross product is shorter than this fraction of |eA| |eB| are parallel: their
 * axis is a face normal (or does not exist) and is covered by the face queries. */
#define PARALLEL_SINE CD_R(1.0e-5)

/* An edge supports its polytope along an axis when its projection is this close (relative to the
 * sizes) to the extreme. */
#define SUPPORT_TOLERANCE (CD_R(64.0) * CD_REAL_EPSILON)

/* A triangle whose |cross(b - a, c - a)| is below this fraction of its longest edge squared is
 * collinear. */
#define DEGENERATE_SINE (CD_R(256.0) * CD_REAL_EPSILON)

/* The box's half-edge topology: vertex i is (+-x, +-y, +-z) with bit 0, 1, 2 of i set for +;
 * faces -x, +x, -y, +y, -z, +z, each with 4 half-edges counter-clockwise from outside. */
static const cd3HullHalfEdge BOX_EDGES[24] = {
	{1, 17, 2, 0},	{2, 8, 0, 0},  {3, 20, 4, 0},  {0, 13, 6, 0},  {5, 10, 5, 1}, {6, 19, 1, 1},
	{7, 15, 3, 1},	{4, 22, 7, 1}, {9, 1, 4, 2},   {10, 16, 0, 2}, {11, 4, 1, 2}, {8, 21, 5, 2},
	{13, 18, 3, 3}, {14, 3, 2, 3}, {15, 23, 6, 3}, {12, 6, 7, 3},  {17, 9, 1, 4}, {18, 0, 0, 4},
	{19, 12, 2, 4}, {16, 5, 3, 4}, {21, 2, 6, 5},  {22, 11, 4, 5}, {23, 7, 5, 5}, {20, 14, 7, 5}};
static const int32_t BOX_FACE_EDGES[6] = {0, 4, 8, 12, 16, 20};

/* Front face a-b-c and back face a-c-b. */
static const cd3HullHalfEdge TRIANGLE_EDGES[6] = {{1, 3, 0, 0}, {2, 4, 1, 0}, {0, 5, 2, 0},
												  {5, 0, 1, 1}, {3, 1, 2, 1}, {4, 2, 0, 1}};
static const int32_t TRIANGLE_FACE_EDGES[2] = {0, 3};

void cd3InitBoxPolytope(cd3Polytope* p, cd3Box box)
{
	cd3Vec h = box.halfExtents;
	for (int i = 0; i < 8; ++i)
	{
		p->vertexStorage[i] = cd3MakeVec((i & 1) ? h.x : -h.x, (i & 2) ? h.y : -h.y, (i & 4) ? h.z : -h.z);
	}
	for (int axis = 0; axis < 3; ++axis)
	{
		cd3Vec n = {CD_R(0.0), CD_R(0.0), CD_R(0.0)};
		if (axis == 0)
		{
			n.x = CD_R(1.0);
		}
		else if (axis == 1)
		{
			n.y = CD_R(1.0);
		}
		else
		{
			n.z = CD_R(1.0);
		}
		cdReal extent = cd3GetComponent(h, axis);
		p->planeStorage[2 * axis].normal = cd3Neg(n);
		p->planeStorage[2 * axis].offset = extent;
		p->planeStorage[2 * axis + 1].normal = n;
		p->planeStorage[2 * axis + 1].offset = extent;
	}
	p->vertices = p->vertexStorage;
	p->edges = BOX_EDGES;
	p->faceEdges = BOX_FACE_EDGES;
	p->planes = p->planeStorage;
	p->vertexCount = 8;
	p->edgeCount = 24;
	p->edgeAxisCount = 24;
	p->faceCount = 6;
	p->centroid = cd3MakeVec(CD_R(0.0), CD_R(0.0), CD_R(0.0));
	p->query = NULL;
	p->transform.p = box.center;
	p->transform.q = box.rotation;
	p->flat = false;
	p->size = CD_R(2.0) * cd3Length(h);
	p->shape.type = CD3_SHAPE_BOX;
	p->shape.box = box;
}

void cd3InitHullPolytope(cd3Polytope* p, cd3HullShape hull)
{
	const cd3Hull* h = hull.hull;
	p->vertices = h->vertices;
	p->edges = h->edges;
	p->faceEdges = h->faceEdges;
	p->planes = h->planes;
	p->vertexCount = h->vertexCount;
	p->edgeCount = h->edgeCount;
	p->edgeAxisCount = h->edgeCount;
	p->faceCount = h->faceCount;
	p->centroid = h->centroid;
	p->transform = hull.transform;
	p->query = (const cd3HullQueryData*)h->queryData;
	p->flat = false;
	p->size = cd3Length(cd3Sub(h->bounds.max, h->bounds.min));
	p->shape.type = CD3_SHAPE_HULL;
	p->shape.hull = hull;
}

/* The unit-scaled normal cross product of a sliver triangle whose tip is a, from the two shorter
 * edges, at the corner opposite the longest edge (c when a-b is the longest, else b). At a's tip
 * the two edges, nearly parallel, give a cross product whose round-off is epsilon over the sine of
 * the tip's angle (a triangle 2e18 long and 5e8 across: its normal off by 1e-6 rad, its plane 2e12
 * off at the other end, and a face contact 6e10 off it); the corner of the largest angle gives a
 * few epsilon. Used below a sine of 1/1024 at a (above, a's round-off stays within 1024 epsilon,
 * and the common path is left as it was). (b - a) x (c - a) = (c - b) x (a - b) =
 * (a - c) x (b - c): the same normal. Out of line: rare. */
SAT_NOINLINE static cd3Vec SliverCross(cd3Triangle t, bool atC, cdReal unit)
{
	if (atC)
	{
		return cd3Cross(cd3Scale(unit, cd3Sub(t.a, t.c)), cd3Scale(unit, cd3Sub(t.b, t.c)));
	}
	return cd3Cross(cd3Scale(unit, cd3Sub(t.c, t.b)), cd3Scale(unit, cd3Sub(t.a, t.b)));
}

void cd3InitTrianglePolytope(cd3Polytope* p, cd3Triangle t)
{
	cd3Vec ab = cd3Sub(t.b, t.a), bc = cd3Sub(t.c, t.b), ca = cd3Sub(t.a, t.c);
	cdReal lab = cd3LengthSquared(ab), lbc = cd3LengthSquared(bc), lca = cd3LengthSquared(ca);
	/* The cross product of the edges scaled to the longest one: a triangle of size 1e-7 has a
	 * cross product of length 1e-14, below what cd3Normalize accepts (an absolute threshold). */
	cdReal longest = cdMax(lab, cdMax(lbc, lca));
	cdReal unit = longest > CD_R(0.0) ? CD_R(1.0) / cdSqrt(longest) : CD_R(0.0);
	cd3Vec cross = cd3Cross(cd3Scale(unit, ab), cd3Scale(-unit, ca));
	cdReal crossLength = cd3Length(cross);
	if (crossLength < CD_R(1.0) / CD_R(1024.0) && lbc != longest)
	{
		cross = SliverCross(t, lab == longest, unit);
		crossLength = cd3Length(cross);
	}
	/* A collinear triangle (within round-off) is the segment of its longest edge: its normal
	 * would be noise, so it gets zero normals (face axes skipped) and one edge axis, with the
	 * longest edge moved to a-b. */
	bool collinear = !(crossLength > DEGENERATE_SINE);
	if (collinear && lbc == longest)
	{
		cd3Vec a = t.a;
		t.a = t.b;
		t.b = t.c;
		t.c = a;
	}
	else if (collinear && lca == longest)
	{
		cd3Vec a = t.a;
		t.a = t.c;
		t.c = t.b;
		t.b = a;
	}
	p->vertexStorage[0] = t.a;
	p->vertexStorage[1] = t.b;
	p->vertexStorage[2] = t.c;
	cd3Vec n =
		collinear ? cd3MakeVec(CD_R(0.0), CD_R(0.0), CD_R(0.0)) : cd3Scale(CD_R(1.0) / crossLength, cross);
	p->edgeAxisCount = collinear ? 1 : 6;
	p->planeStorage[0].normal = n;
	p->planeStorage[0].offset = cd3Dot(n, t.a);
	p->planeStorage[1].normal = cd3Neg(n);
	p->planeStorage[1].offset = -cd3Dot(n, t.a);
	p->vertices = p->vertexStorage;
	p->edges = TRIANGLE_EDGES;
	p->faceEdges = TRIANGLE_FACE_EDGES;
	p->planes = p->planeStorage;
	p->vertexCount = 3;
	p->edgeCount = 6;
	p->faceCount = 2;
	p->centroid = cd3Scale(CD_R(1.0) / CD_R(3.0), cd3Add(t.a, cd3Add(t.b, t.c)));
	p->transform = CD3_TRANSFORM_IDENTITY;
	p->query = NULL;
	p->flat = true;
	p->size =
		cdMax(cd3Length(cd3Sub(t.b, t.a)), cdMax(cd3Length(cd3Sub(t.c, t.b)), cd3Length(cd3Sub(t.a, t.c))));
	p->shape.type = CD3_SHAPE_TRIANGLE;
	p->shape.triangle = t;
}

static bool IsZero(cd3Vec v)
{
	return v.x == CD_R(0.0) && v.y == CD_R(0.0) && v.z == CD_R(0.0);
}

/* Polytopes of at most this many vertices and faces take the column loops below: q's vertices
 * carried into p's frame once, then every face plane against every vertex, the faces four or
 * eight at a time (the loops vectorize). Larger ones search q's support vertex per face. */
#define SMALL_POLYTOPE 64

/* Vertices of the other polytope carried into a polytope's frame, as columns (for the pruning). */
#define PRUNE_VERTICES 64

typedef struct CarriedVertices
{
#if CD3_SUPPORT_SSE
	__m128 align; /* the columns 16-byte aligned (PRUNE_VERTICES is a multiple of 4) */
#endif
	cdReal x[PRUNE_VERTICES], y[PRUNE_VERTICES], z[PRUNE_VERTICES];
} CarriedVertices;

/* Largest separation over p's face normals against q, whose local points map into p's frame by
 * `rel`. With `carried` (when q has at most PRUNE_VERTICES vertices and both are small), q's
 * vertices in p's frame are kept there. */
static cdReal QueryFaces(const cd3Polytope* p, const cd3Polytope* q, cd3Transform rel, int* bestFace,
						 CarriedVertices* carried)
{
	cdReal best = -CD_REAL_MAX;
	*bestFace = -1;
	/* The rotation as a matrix once: two quaternion rotations per face cost more than this. */
	cd3Mat33 rotation = cd3MakeMatFromQuat(rel.q);
	if (p->faceCount <= SMALL_POLYTOPE && q->vertexCount <= SMALL_POLYTOPE)
	{
		/* Each face's separation is the smallest of its plane's distances to q's vertices (q's
		 * support along the reversed normal), each computed as cd3Dot(normal, vertex in p's frame)
		 * - offset. */
		int faceCount = p->faceCount;
		int padded = (faceCount + 3) & ~3; /* zero normals beyond the faces */
#if CD3_SUPPORT_SSE
		__m128 columns[4 * SMALL_POLYTOPE / 4];
		float* cx = (float*)(void*)columns;
		float* cy = cx + SMALL_POLYTOPE;
		float* cz = cy + SMALL_POLYTOPE;
		float* low = cz + SMALL_POLYTOPE;
#else
		cdReal cx[SMALL_POLYTOPE], cy[SMALL_POLYTOPE], cz[SMALL_POLYTOPE], low[SMALL_POLYTOPE];
#endif
		const cdReal *nx = cx, *ny = cy, *nz = cz;
		if (p->query != NULL)
		{
			/* The hull's own columns (the same values). */
			nx = cd3HullQueryFaces(p->query);
			ny = nx + padded;
			nz = ny + padded;
		}
		for (int f = 0; f < padded; ++f)
		{
			if (p->query == NULL)
			{
				cd3Vec n = f < faceCount ? p->planes[f].normal : CD3_VEC_ZERO;
				cx[f] = n.x;
				cy[f] = n.y;
				cz[f] = n.z;
			}
			low[f] = CD_REAL_MAX;
		}
		for (int i = 0; i < q->vertexCount; ++i)
		{
			cd3Vec v = cd3Add(cd3MulMV(rotation, q->vertices[i]), rel.p);
			if (carried != NULL)
			{
				carried->x[i] = v.x;
				carried->y[i] = v.y;
				carried->z[i] = v.z;
			}
#if CD3_SUPPORT_SSE
			__m128 vx = _mm_set1_ps(v.x), vy = _mm_set1_ps(v.y), vz = _mm_set1_ps(v.z);
			for (int f = 0; f < padded; f += 4)
			{
				__m128 d = _mm_add_ps(
					_mm_add_ps(_mm_mul_ps(_mm_load_ps(nx + f), vx), _mm_mul_ps(_mm_load_ps(ny + f), vy)),
					_mm_mul_ps(_mm_load_ps(nz + f), vz));
				_mm_store_ps(low + f, _mm_min_ps(d, _mm_load_ps(low + f)));
			}
#else
			for (int f = 0; f < padded; ++f)
			{
				cdReal d = nx[f] * v.x + ny[f] * v.y + nz[f] * v.z;
				low[f] = d < low[f] ? d : low[f];
			}
#endif
		}
		for (int f = 0; f < faceCount; ++f)
		{
			cd3Plane plane = p->planes[f];
			cdReal separation = low[f] - plane.offset;
			if (separation > best && !IsZero(plane.normal))
			{
				best = separation;
				*bestFace = f;
			}
		}
		return best;
	}
	for (int f = 0; f < p->faceCount; ++f)
	{
		cd3Plane plane = p->planes[f];
		if (IsZero(plane.normal))
		{
			continue;
		}
		cd3Vec inQ = cd3MulMTV(rotation, plane.normal);
		int support = cd3SupportIndex(q->vertices, q->vertexCount, cd3Neg(inQ));
		cd3Vec supportInP = cd3Add(cd3MulMV(rotation, q->vertices[support]), rel.p);
		cdReal separation = cd3Dot(plane.normal, supportInP) - plane.offset;
		if (separation > best)
		{
			best = separation;
			*bestFace = f;
		}
	}
	return best;
}

/* Edge pruning (cd3SatPolytopesPruned). Along any axis n on an edge's arc (n = (s na + t nb) / |s na
 * + t nb|, s, t >= 0, na and nb its faces' unit normals) the edge supports its polytope P, so an edge
 * pair of it separates along n by at most dot(n, x - p) for any point x of the other polytope Q and p
 * on the edge. With da and db x's distances to the two face planes (both through p), that is
 * (s da + t db) / |s na + t nb| <= max(da, db) when both are negative (the numerator is at most
 * (s + t) max(da, db), the length at most s + t). So an edge of P with a vertex of Q below both its
 * faces' planes by more than -floor (floor negative) separates by less than floor in every edge pair
 * it forms. */

/* Bits i of below[f] for each face f of p: q's vertex i (`carried` into p's frame by QueryFaces)
 * lies below the face's plane by more than -floor: dot(normal, v) - offset < floor. */
static void FacesBelow(const cd3Polytope* p, int vertexCount, CarriedVertices* carried, cdReal floor,
					   uint64_t* below)
{
#if CD3_SUPPORT_SSE
	int padded = (vertexCount + 3) & ~3;
	for (int i = vertexCount; i < padded; ++i)
	{
		/* Lanes past the count repeat vertex 0 (their bits are masked off below). */
		carried->x[i] = carried->x[0];
		carried->y[i] = carried->y[0];
		carried->z[i] = carried->z[0];
	}
	uint64_t valid = vertexCount >= 64 ? ~(uint64_t)0 : (((uint64_t)1 << vertexCount) - 1u);
	for (int f = 0; f < p->faceCount; ++f)
	{
		cd3Plane plane = p->planes[f];
		__m128 nx = _mm_set1_ps(plane.normal.x), ny = _mm_set1_ps(plane.normal.y),
			   nz = _mm_set1_ps(plane.normal.z);
		__m128 level = _mm_set1_ps(plane.offset + floor);
		uint64_t bits = 0u;
		for (int i = 0; i < padded; i += 4)
		{
			__m128 d = _mm_add_ps(_mm_add_ps(_mm_mul_ps(nx, _mm_load_ps(carried->x + i)),
											 _mm_mul_ps(ny, _mm_load_ps(carried->y + i))),
								  _mm_mul_ps(nz, _mm_load_ps(carried->z + i)));
			bits |= (uint64_t)_mm_movemask_ps(_mm_cmplt_ps(d, level)) << i;
		}
		below[f] = bits & valid;
	}
#else
	for (int f = 0; f < p->faceCount; ++f)
	{
		cd3Plane plane = p->planes[f];
		cdReal level = plane.offset + floor;
		uint64_t bits = 0u;
		for (int i = 0; i < vertexCount; ++i)
		{
			cdReal d = plane.normal.x * carried->x[i] + plane.normal.y * carried->y[i] +
					   plane.normal.z * carried->z[i];
			bits |= (uint64_t)(d < level) << i;
		}
		below[f] = bits;
	}
#endif
}

/* Whether p's edge of half-edge i is pruned: a vertex of the other polytope lies below both its
 * faces (FacesBelow). */
static inline bool EdgePruned(const cd3Polytope* p, const uint64_t* below, int i)
{
	const cd3HullHalfEdge* e = &p->edges[i];
	return (below[e->face] & below[p->edges[e->twin].face]) != 0u;
}

static void Project(const cd3Polytope* p, cd3Transform rel, cd3Vec axis, cdReal* lo, cdReal* hi)
{
	cd3Vec local = cd3InvRotateVector(rel.q, axis);
	cdReal offset = cd3Dot(axis, rel.p);
	cdReal mn = cd3Dot(local, p->vertices[0]);
	cdReal mx = mn;
	for (int i = 1; i < p->vertexCount; ++i)
	{
		cdReal d = cd3Dot(local, p->vertices[i]);
		mn = cdMin(mn, d);
		mx = cdMax(mx, d);
	}
	*lo = mn + offset;
	*hi = mx + offset;
}

/* A's edge data for the Gauss-map test, in A's frame. */
typedef struct EdgeData
{
	cd3Vec na, nb, bxa; /* the adjacent face normals and cross(nb, na) */
	cd3Vec origin, direction;
	cdReal lengthSquared;
	int index;
} EdgeData;

/* Edges of A cached on the stack for the inner loop; larger polytopes recompute them. */
#define EDGE_CACHE 192

static inline EdgeData MakeEdgeData(const cd3Polytope* a, int i)
{
	const cd3HullHalfEdge* ea = &a->edges[i];
	EdgeData e;
	e.na = a->planes[ea->face].normal;
	e.nb = a->planes[a->edges[ea->twin].face].normal;
	e.bxa = cd3Cross(e.nb, e.na);
	e.origin = a->vertices[ea->origin];
	e.direction = cd3Sub(a->vertices[a->edges[ea->twin].origin], e.origin);
	e.lengthSquared = cd3LengthSquared(e.direction);
	e.index = i;
	return e;
}

/* The Gauss-map arcs of A's cached edges as columns (all x, then all y, then all z), so that the
 * test of one edge of B against all of them runs without branches (and vectorizes): the pairs
 * that pass are few, the ones that fail are many and fail unpredictably. */
typedef struct ArcColumns
{
#if CD3_SUPPORT_SSE
	__m128 align; /* the columns 16-byte aligned for the SSE loads (EDGE_CACHE is a multiple of 4) */
#endif
	cdReal nax[EDGE_CACHE], nay[EDGE_CACHE], naz[EDGE_CACHE];
	cdReal nbx[EDGE_CACHE], nby[EDGE_CACHE], nbz[EDGE_CACHE];
	cdReal bxax[EDGE_CACHE], bxay[EDGE_CACHE], bxaz[EDGE_CACHE];
} ArcColumns;

/* The indices k of A's cached arcs a-b that cross B's arc c-d (dxc = cross(d, c)), in `out`;
 * returns their count. The test of Gregorius' talk: c and d on either side of a-b's plane, a and
 * b on either side of c-d's, and both on one hemisphere. */
static int CrossingArcs(const ArcColumns* arcs, int count, cd3Vec c, cd3Vec d, cd3Vec dxc, int* out)
{
#if CD3_SUPPORT_SSE
	/* Four arcs at a time over the columns padded with zero arcs (which never pass), and the few
	 * that pass gathered from the lane masks. */
	__m128 cx = _mm_set1_ps(c.x), cy = _mm_set1_ps(c.y), cz = _mm_set1_ps(c.z);
	__m128 dx = _mm_set1_ps(d.x), dy = _mm_set1_ps(d.y), dz = _mm_set1_ps(d.z);
	__m128 ex = _mm_set1_ps(dxc.x), ey = _mm_set1_ps(dxc.y), ez = _mm_set1_ps(dxc.z);
	__m128 zero = _mm_setzero_ps();
	int n = 0;
	for (int k = 0; k < count; k += 4)
	{
		__m128 bx = _mm_load_ps(arcs->bxax + k), by = _mm_load_ps(arcs->bxay + k),
			   bz = _mm_load_ps(arcs->bxaz + k);
		__m128 cba = _mm_add_ps(_mm_add_ps(_mm_mul_ps(cx, bx), _mm_mul_ps(cy, by)), _mm_mul_ps(cz, bz));
		__m128 dba = _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, bx), _mm_mul_ps(dy, by)), _mm_mul_ps(dz, bz));
		__m128 adc = _mm_add_ps(_mm_add_ps(_mm_mul_ps(_mm_load_ps(arcs->nax + k), ex),
										   _mm_mul_ps(_mm_load_ps(arcs->nay + k), ey)),
								_mm_mul_ps(_mm_load_ps(arcs->naz + k), ez));
		__m128 bdc = _mm_add_ps(_mm_add_ps(_mm_mul_ps(_mm_load_ps(arcs->nbx + k), ex),
										   _mm_mul_ps(_mm_load_ps(arcs->nby + k), ey)),
								_mm_mul_ps(_mm_load_ps(arcs->nbz + k), ez));
		__m128 pass = _mm_and_ps(
			_mm_and_ps(_mm_cmplt_ps(_mm_mul_ps(cba, dba), zero), _mm_cmplt_ps(_mm_mul_ps(adc, bdc), zero)),
			_mm_cmpgt_ps(_mm_mul_ps(cba, bdc), zero));
		int mask = _mm_movemask_ps(pass);
		/* Without branches: the lanes that pass are few and unpredictable. */
		out[n] = k;
		n += mask & 1;
		out[n] = k + 1;
		n += (mask >> 1) & 1;
		out[n] = k + 2;
		n += (mask >> 2) & 1;
		out[n] = k + 3;
		n += (mask >> 3) & 1;
	}
	return n;
#else
	/* The test in one loop the compiler vectorizes, the gathering of the few that pass in another. */
	int pass[EDGE_CACHE];
	for (int k = 0; k < count; ++k)
	{
		cdReal cba = c.x * arcs->bxax[k] + c.y * arcs->bxay[k] + c.z * arcs->bxaz[k];
		cdReal dba = d.x * arcs->bxax[k] + d.y * arcs->bxay[k] + d.z * arcs->bxaz[k];
		cdReal adc = arcs->nax[k] * dxc.x + arcs->nay[k] * dxc.y + arcs->naz[k] * dxc.z;
		cdReal bdc = arcs->nbx[k] * dxc.x + arcs->nby[k] * dxc.y + arcs->nbz[k] * dxc.z;
		pass[k] = (cba * dba < CD_R(0.0)) & (adc * bdc < CD_R(0.0)) & (cba * bdc > CD_R(0.0));
	}
	int n = 0;
	for (int k = 0; k < count; ++k)
	{
		out[n] = k;
		n += pass[k];
	}
	return n;
#endif
}

/* A with at most this many edges and faces takes the Gauss-map test as bit masks: the four sides
 * of a pair (c and d against A's arc plane, A's normals a and b against B's) are signs of dot
 * products that depend on one edge and one face, so they are computed once per face (B's faces
 * against A's arc planes, A's faces against each B arc plane) instead of once per edge pair, and
 * the test of one B edge against all of A's is a few mask operations. A pair passes when the
 * products of CrossingArcs have the signs it asks for, that is when the factors have (a product
 * of two nonzero factors that underflows to zero is the one difference: such a pair passes here,
 * which costs a separation, never a wrong one). */
#define MASK_ARCS 32
#define MASK_FACES 16

/* Bits k (k < padded, a multiple of 4) where v . (x[k], y[k], z[k]) is positive, and negative; the
 * sums in the order of CrossingArcs'. */
static void SideMasks(const cdReal* x, const cdReal* y, const cdReal* z, int padded, cd3Vec v,
					  uint32_t* positive, uint32_t* negative)
{
	uint32_t p = 0u, n = 0u;
#if CD3_SUPPORT_SSE
	__m128 vx = _mm_set1_ps(v.x), vy = _mm_set1_ps(v.y), vz = _mm_set1_ps(v.z);
	__m128 zero = _mm_setzero_ps();
	for (int k = 0; k < padded; k += 4)
	{
		__m128 d =
			_mm_add_ps(_mm_add_ps(_mm_mul_ps(vx, _mm_load_ps(x + k)), _mm_mul_ps(vy, _mm_load_ps(y + k))),
					   _mm_mul_ps(vz, _mm_load_ps(z + k)));
		p |= (uint32_t)_mm_movemask_ps(_mm_cmpgt_ps(d, zero)) << k;
		n |= (uint32_t)_mm_movemask_ps(_mm_cmplt_ps(d, zero)) << k;
	}
#else
	for (int k = 0; k < padded; ++k)
	{
		cdReal d = v.x * x[k] + v.y * y[k] + v.z * z[k];
		p |= (uint32_t)(d > CD_R(0.0)) << k;
		n |= (uint32_t)(d < CD_R(0.0)) << k;
	}
#endif
	*positive = p;
	*negative = n;
}

/* The edges of A (bits of its cached arcs) whose first face is among `faces` (bits of A's faces)
 * in the low 32 bits, those whose second face is in the high 32, from tables of 16 entries per 4
 * faces (unused tables map every index to no edge). */
static inline uint64_t EdgesOfFaces(const uint64_t* const* table, uint32_t faces)
{
	return table[0][faces & 15u] | table[1][(faces >> 4) & 15u] | table[2][(faces >> 8) & 15u] |
		   table[3][(faces >> 12) & 15u];
}

/* EdgesOfFaces' tables of `tableCount` groups of 4 faces for the edges `unique` (half-edge
 * indices; at most MASK_ARCS). */
static void BuildFaceTables(const cd3HullHalfEdge* edges, const int32_t* unique, int count, int tableCount,
							uint64_t (*tables)[16])
{
	uint64_t of[MASK_FACES];
	for (int g = 0; g < MASK_FACES; ++g)
	{
		of[g] = 0u;
	}
	for (int k = 0; k < count; ++k)
	{
		const cd3HullHalfEdge* e = &edges[unique[k]];
		of[e->face] |= (uint64_t)1u << k;
		of[edges[e->twin].face] |= (uint64_t)1u << (k + 32);
	}
	for (int i = 0; i < tableCount; ++i)
	{
		tables[i][0] = 0u;
		for (unsigned v = 1u; v < 16u; ++v)
		{
			tables[i][v] = tables[i][v & (v - 1u)] | of[4 * i + cd3LowestBit(v)];
		}
	}
}

static const uint64_t NO_EDGES[16] = {0u};

/* A's side of the masked test, built once per query (or read from the hull's query data). */
typedef struct ArcMasks
{
#if CD3_SUPPORT_SSE
	__m128 align;
#endif
	cdReal ownX[MASK_FACES], ownY[MASK_FACES], ownZ[MASK_FACES]; /* A's face normals, zero padded */
	uint64_t ownTables[MASK_FACES / 4][16];
	const cdReal *fx, *fy, *fz;				   /* A's face normals as columns, zero padded */
	const uint64_t* faceEdges[MASK_FACES / 4]; /* EdgesOfFaces' tables */
	int facePadded;
	uint32_t positive[SMALL_POLYTOPE], negative[SMALL_POLYTOPE]; /* B's faces against A's arc planes */
} ArcMasks;

/* `unique`: A's cached edges' half-edge indices; arcX, arcY, arcZ: their arcs' columns, padded. */
static void InitArcMasks(ArcMasks* m, const cd3Polytope* a, const cd3Polytope* b, const int32_t* unique,
						 int cached, const cdReal* arcX, const cdReal* arcY, const cdReal* arcZ,
						 const cd3Vec* carriedNormals)
{
	int faces = a->faceCount;
	m->facePadded = (faces + 3) & ~3;
	if (a->query != NULL)
	{
		m->fx = cd3HullQueryFaces(a->query);
		m->fy = m->fx + m->facePadded;
		m->fz = m->fy + m->facePadded;
		const uint64_t(*tables)[16] = cd3HullQueryTables(a->query);
		for (int i = 0; i < MASK_FACES / 4; ++i)
		{
			m->faceEdges[i] = 4 * i < m->facePadded ? tables[i] : NO_EDGES;
		}
	}
	else
	{
		for (int g = 0; g < m->facePadded; ++g)
		{
			cd3Vec n = g < faces ? a->planes[g].normal : CD3_VEC_ZERO;
			m->ownX[g] = n.x;
			m->ownY[g] = n.y;
			m->ownZ[g] = n.z;
		}
		m->fx = m->ownX;
		m->fy = m->ownY;
		m->fz = m->ownZ;
		BuildFaceTables(a->edges, unique, cached, MASK_FACES / 4, m->ownTables);
		for (int i = 0; i < MASK_FACES / 4; ++i)
		{
			m->faceEdges[i] = m->ownTables[i];
		}
	}
	int padded = (cached + 3) & ~3;
	for (int f = 0; f < b->faceCount; ++f)
	{
		SideMasks(arcX, arcY, arcZ, padded, carriedNormals[f], &m->positive[f], &m->negative[f]);
	}
}

size_t cd3HullQueryDataSize(int halfEdgeCount, int faceCount)
{
	if (halfEdgeCount / 2 > CD3_HULL_QUERY_EDGES || faceCount > CD3_HULL_QUERY_FACES)
	{
		return 0;
	}
	size_t edgePadded = (size_t)((halfEdgeCount / 2 + 3) & ~3), facePadded = (size_t)((faceCount + 3) & ~3);
	return sizeof(cd3HullQueryData) + 3 * (edgePadded + facePadded) * sizeof(cdReal) +
		   facePadded / 4 * 16 * sizeof(uint64_t) + 3 * edgePadded * sizeof(int32_t);
}

void cd3BuildHullQueryData(const cd3Hull* hull, void* memory)
{
	size_t size = cd3HullQueryDataSize(hull->edgeCount, hull->faceCount);
	memset(memory, 0, size);
	cd3HullQueryData* q = (cd3HullQueryData*)memory;
	q->edgeCount = hull->edgeCount / 2;
	q->edgePadded = (q->edgeCount + 3) & ~3;
	q->faceCount = hull->faceCount;
	q->facePadded = (hull->faceCount + 3) & ~3;
	int32_t* unique = (int32_t*)(void*)cd3HullQueryEdges(q);
	int count = 0;
	for (int i = 0; i < hull->edgeCount && count < q->edgeCount; ++i)
	{
		if (hull->edges[i].twin > i)
		{
			unique[count++] = i;
		}
	}
	int32_t* faces2 = (int32_t*)(void*)cd3HullQueryEdgeFaces(q);
	for (int k = 0; k < count; ++k)
	{
		const cd3HullHalfEdge* e = &hull->edges[unique[k]];
		faces2[2 * k] = e->face;
		faces2[2 * k + 1] = hull->edges[e->twin].face;
	}
	cdReal* arcs = (cdReal*)(void*)cd3HullQueryArcs(q);
	for (int k = 0; k < count; ++k)
	{
		const cd3HullHalfEdge* e = &hull->edges[unique[k]];
		cd3Vec bxa = cd3Cross(hull->planes[hull->edges[e->twin].face].normal, hull->planes[e->face].normal);
		arcs[k] = bxa.x;
		arcs[q->edgePadded + k] = bxa.y;
		arcs[2 * q->edgePadded + k] = bxa.z;
	}
	cdReal* faces = (cdReal*)(void*)cd3HullQueryFaces(q);
	for (int f = 0; f < hull->faceCount; ++f)
	{
		faces[f] = hull->planes[f].normal.x;
		faces[q->facePadded + f] = hull->planes[f].normal.y;
		faces[2 * q->facePadded + f] = hull->planes[f].normal.z;
	}
	BuildFaceTables(hull->edges, unique, count, q->facePadded / 4,
					(uint64_t(*)[16])(void*)cd3HullQueryTables(q));
}

/* CrossingArcs for B's edge between its faces fc (normal c) and fd (d), dxc = cross(d, c), among
 * A's arcs `keep` (bits). */
static int CrossingArcsMasked(const ArcMasks* m, int fc, int fd, uint32_t keep, cd3Vec dxc, int* out)
{
	uint32_t up, down;
	SideMasks(m->fx, m->fy, m->fz, m->facePadded, dxc, &up, &down);
	uint64_t edgesUp = EdgesOfFaces(m->faceEdges, up), edgesDown = EdgesOfFaces(m->faceEdges, down);
	uint32_t aUp = (uint32_t)edgesUp, aDown = (uint32_t)edgesDown;
	uint32_t bUp = (uint32_t)(edgesUp >> 32), bDown = (uint32_t)(edgesDown >> 32);
	uint32_t cUp = m->positive[fc], cDown = m->negative[fc];
	uint32_t dUp = m->positive[fd], dDown = m->negative[fd];
	uint32_t pass = ((cUp & dDown) | (cDown & dUp)) & ((aUp & bDown) | (aDown & bUp)) &
					((cUp & bUp) | (cDown & bDown)) & keep;
	int n = 0;
	while (pass != 0u)
	{
		out[n++] = cd3LowestBit(pass);
		pass &= pass - 1u;
	}
	return n;
}

/* One edge pair that passed the Gauss-map test: its separation along the cross of the edges,
 * kept when it beats the best so far. */
static void TestEdgePair(const cd3Polytope* a, const cd3Polytope* b, cd3Transform relB, const EdgeData* e,
						 int j, cd3Vec qb0, cd3Vec edgeB, cdReal edgeB2, cd3SatResult* r, cd3Vec* bestAxis)
{
	cdReal parallel2 = PARALLEL_SINE * PARALLEL_SINE;
	cd3Vec axis = cd3Cross(e->direction, edgeB);
	cdReal axis2 = cd3LengthSquared(axis);
	if (!(axis2 > parallel2 * e->lengthSquared * edgeB2))
	{
		return;
	}
	axis = cd3Scale(CD_R(1.0) / cdSqrt(axis2), axis);
	/* The axis lies within A's arc na-nb: on the side of its bisector (robust for flat and
	 * needle-like boxes, where a centroid test is ambiguous). */
	if (cd3Dot(axis, cd3Add(e->na, e->nb)) < CD_R(0.0))
	{
		axis = cd3Neg(axis);
	}
	cdReal separation = cd3Dot(axis, cd3Sub(qb0, e->origin));
	if (separation > r->edgeSeparation)
	{
		/* The separation along the axis from the projections, whatever supports it: the
		 * edges' own difference is the separation only when the Gauss-map test is right,
		 * and round-off of a needle's face normals can pass a pair whose edges do not
		 * support the axis (a box against a hull with a vertex at -1e9 in float: +4.8e8
		 * for shapes that overlap). Only for a new best, so rarely. */
		cdReal loA, hiA, loB, hiB;
		Project(a, CD3_TRANSFORM_IDENTITY, axis, &loA, &hiA);
		Project(b, relB, axis, &loB, &hiB);
		separation = cdMin(separation, loB - hiA);
	}
	if (separation > r->edgeSeparation)
	{
		r->edgeSeparation = separation;
		r->edgeA = e->index;
		r->edgeB = j;
		*bestAxis = axis;
	}
}

/* Edge pairs that passed the Gauss-map test, waiting for their separations: A's cached edge, B's
 * half-edge and B's edge in A's frame. */
#define PENDING_PAIRS 256

typedef struct PendingPairs
{
#if CD3_SUPPORT_SSE
	__m128 align; /* the columns 16-byte aligned (PENDING_PAIRS is a multiple of 4) */
#endif
	/* Per pair, as columns: A's edge direction and its squared length, the sum of its face
	 * normals and its origin; B's edge origin, direction and squared length; then the pair's unit
	 * axis and separation along it. */
	cdReal ax[PENDING_PAIRS], ay[PENDING_PAIRS], az[PENDING_PAIRS], aLength2[PENDING_PAIRS];
	cdReal nx[PENDING_PAIRS], ny[PENDING_PAIRS], nz[PENDING_PAIRS];
	cdReal ox[PENDING_PAIRS], oy[PENDING_PAIRS], oz[PENDING_PAIRS];
	cdReal px[PENDING_PAIRS], py[PENDING_PAIRS], pz[PENDING_PAIRS];
	cdReal bx[PENDING_PAIRS], by[PENDING_PAIRS], bz[PENDING_PAIRS], bLength2[PENDING_PAIRS];
	cdReal axisX[PENDING_PAIRS], axisY[PENDING_PAIRS], axisZ[PENDING_PAIRS];
	cdReal separation[PENDING_PAIRS];
	int edge[PENDING_PAIRS];
	int edgeB[PENDING_PAIRS];
	int count;
	int order; /* pairs flushed before: the position of the first pending pair in test order */
	int bestOrder;
} PendingPairs;

/* Appends A's cached edge e against B's edge j (origin qb0, direction edgeB). */
static inline void AddPendingPair(PendingPairs* p, const EdgeData* e, int k, int j, cd3Vec qb0, cd3Vec edgeB,
								  cdReal edgeB2)
{
	int i = p->count++;
	cd3Vec sum = cd3Add(e->na, e->nb);
	p->ax[i] = e->direction.x;
	p->ay[i] = e->direction.y;
	p->az[i] = e->direction.z;
	p->aLength2[i] = e->lengthSquared;
	p->nx[i] = sum.x;
	p->ny[i] = sum.y;
	p->nz[i] = sum.z;
	p->ox[i] = e->origin.x;
	p->oy[i] = e->origin.y;
	p->oz[i] = e->origin.z;
	p->px[i] = qb0.x;
	p->py[i] = qb0.y;
	p->pz[i] = qb0.z;
	p->bx[i] = edgeB.x;
	p->by[i] = edgeB.y;
	p->bz[i] = edgeB.z;
	p->bLength2[i] = edgeB2;
	p->edge[i] = k;
	p->edgeB[i] = j;
}

/* Every pending pair's unit axis and separation along it (-CD_REAL_MAX for parallel edges): the
 * arithmetic of TestEdgePair, operation for operation (so bit for bit), four pairs at a time in
 * the float build on SSE2. */
static void PendingSeparations(PendingPairs* p)
{
	cdReal parallel2 = PARALLEL_SINE * PARALLEL_SINE;
#if CD3_SUPPORT_SSE
	__m128 limit = _mm_set1_ps(parallel2), one = _mm_set1_ps(1.0f), zero = _mm_setzero_ps();
	__m128 signBit = _mm_set1_ps(-0.0f), lowest = _mm_set1_ps(-CD_REAL_MAX);
	/* The last group's lanes past the count: zero edges (their results are never read). */
	for (int i = p->count; (i & 3) != 0; ++i)
	{
		p->ax[i] = p->ay[i] = p->az[i] = p->aLength2[i] = 0.0f;
		p->nx[i] = p->ny[i] = p->nz[i] = 0.0f;
		p->ox[i] = p->oy[i] = p->oz[i] = 0.0f;
		p->px[i] = p->py[i] = p->pz[i] = 0.0f;
		p->bx[i] = p->by[i] = p->bz[i] = p->bLength2[i] = 0.0f;
	}
	for (int i = 0; i < p->count; i += 4)
	{
		__m128 ax = _mm_load_ps(p->ax + i), ay = _mm_load_ps(p->ay + i), az = _mm_load_ps(p->az + i);
		__m128 bx = _mm_load_ps(p->bx + i), by = _mm_load_ps(p->by + i), bz = _mm_load_ps(p->bz + i);
		__m128 cx = _mm_sub_ps(_mm_mul_ps(ay, bz), _mm_mul_ps(az, by));
		__m128 cy = _mm_sub_ps(_mm_mul_ps(az, bx), _mm_mul_ps(ax, bz));
		__m128 cz = _mm_sub_ps(_mm_mul_ps(ax, by), _mm_mul_ps(ay, bx));
		__m128 axis2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(cx, cx), _mm_mul_ps(cy, cy)), _mm_mul_ps(cz, cz));
		__m128 bound =
			_mm_mul_ps(_mm_mul_ps(limit, _mm_load_ps(p->aLength2 + i)), _mm_load_ps(p->bLength2 + i));
		__m128 valid = _mm_cmpgt_ps(axis2, bound);
		__m128 length2 = _mm_or_ps(_mm_and_ps(valid, axis2), _mm_andnot_ps(valid, one));
		__m128 inverse = _mm_div_ps(one, _mm_sqrt_ps(length2));
		cx = _mm_mul_ps(inverse, cx);
		cy = _mm_mul_ps(inverse, cy);
		cz = _mm_mul_ps(inverse, cz);
		__m128 side = _mm_add_ps(
			_mm_add_ps(_mm_mul_ps(cx, _mm_load_ps(p->nx + i)), _mm_mul_ps(cy, _mm_load_ps(p->ny + i))),
			_mm_mul_ps(cz, _mm_load_ps(p->nz + i)));
		__m128 flip = _mm_and_ps(_mm_cmplt_ps(side, zero), signBit);
		cx = _mm_xor_ps(cx, flip);
		cy = _mm_xor_ps(cy, flip);
		cz = _mm_xor_ps(cz, flip);
		__m128 dx = _mm_sub_ps(_mm_load_ps(p->px + i), _mm_load_ps(p->ox + i));
		__m128 dy = _mm_sub_ps(_mm_load_ps(p->py + i), _mm_load_ps(p->oy + i));
		__m128 dz = _mm_sub_ps(_mm_load_ps(p->pz + i), _mm_load_ps(p->oz + i));
		__m128 separation =
			_mm_add_ps(_mm_add_ps(_mm_mul_ps(cx, dx), _mm_mul_ps(cy, dy)), _mm_mul_ps(cz, dz));
		_mm_store_ps(p->axisX + i, cx);
		_mm_store_ps(p->axisY + i, cy);
		_mm_store_ps(p->axisZ + i, cz);
		_mm_store_ps(p->separation + i,
					 _mm_or_ps(_mm_and_ps(valid, separation), _mm_andnot_ps(valid, lowest)));
	}
#else
	for (int i = 0; i < p->count; ++i)
	{
		cd3Vec axis =
			cd3Cross(cd3MakeVec(p->ax[i], p->ay[i], p->az[i]), cd3MakeVec(p->bx[i], p->by[i], p->bz[i]));
		cdReal axis2 = cd3LengthSquared(axis);
		bool valid = axis2 > parallel2 * p->aLength2[i] * p->bLength2[i];
		axis = cd3Scale(CD_R(1.0) / cdSqrt(valid ? axis2 : CD_R(1.0)), axis);
		if (cd3Dot(axis, cd3MakeVec(p->nx[i], p->ny[i], p->nz[i])) < CD_R(0.0))
		{
			axis = cd3Neg(axis);
		}
		cdReal separation = cd3Dot(
			axis, cd3Sub(cd3MakeVec(p->px[i], p->py[i], p->pz[i]), cd3MakeVec(p->ox[i], p->oy[i], p->oz[i])));
		p->axisX[i] = axis.x;
		p->axisY[i] = axis.y;
		p->axisZ[i] = axis.z;
		p->separation[i] = valid ? separation : -CD_REAL_MAX;
	}
#endif
}

/* The pending pairs' separations, as TestEdgePair takes them one by one in test order, but with
 * the unpredictable branches out of the arithmetic: first every pair's separation along its axis
 * (independent chains the processor overlaps), then the pairs from the largest separation down,
 * each checked by projection as TestEdgePair checks a new best, until one is below the best. The
 * best (largest separation, ties to the first pair in test order) is TestEdgePair's, bit for bit. */
static void FlushPairs(const cd3Polytope* a, const cd3Polytope* b, cd3Transform relB, const EdgeData* cache,
					   PendingPairs* pending, cd3SatResult* r, cd3Vec* bestAxis)
{
	int count = pending->count;
	PendingSeparations(pending);
	for (;;)
	{
		int top = -1;
		cdReal highest = -CD_REAL_MAX;
		for (int i = 0; i < count; ++i)
		{
			bool higher = pending->separation[i] > highest;
			top = higher ? i : top;
			highest = higher ? pending->separation[i] : highest;
		}
		if (top < 0 || highest < r->edgeSeparation)
		{
			break;
		}
		pending->separation[top] = -CD_REAL_MAX;
		int order = pending->order + top;
		/* At a tie with the best the pair can only matter as an earlier one of equal separation. */
		bool tie = !(highest > r->edgeSeparation);
		if (tie && !(pending->bestOrder >= 0 && order < pending->bestOrder))
		{
			continue;
		}
		cd3Vec axis = cd3MakeVec(pending->axisX[top], pending->axisY[top], pending->axisZ[top]);
		cdReal loA, hiA, loB, hiB;
		Project(a, CD3_TRANSFORM_IDENTITY, axis, &loA, &hiA);
		Project(b, relB, axis, &loB, &hiB);
		cdReal separation = cdMin(highest, loB - hiA);
		if (separation > r->edgeSeparation ||
			(separation == r->edgeSeparation && pending->bestOrder >= 0 && order < pending->bestOrder))
		{
			r->edgeSeparation = separation;
			r->edgeA = cache[pending->edge[top]].index;
			r->edgeB = pending->edgeB[top];
			*bestAxis = axis;
			pending->bestOrder = order;
		}
	}
	pending->order += count;
	pending->count = 0;
}

/* At most this many edge pairs left by the pruning take QueryEdgesFew. */
#define FEW_PAIRS 24

/* The edge pairs of A's edges `keptA` and B's edges `keptB` (half-edge indices, in the order of
 * QueryEdgesGauss, which is the test order), without the tables: the Gauss-map test of the
 * uncached path and TestEdgePair, pair by pair (the arithmetic of the tables' path). */
static void QueryEdgesFew(const cd3Polytope* a, const cd3Polytope* b, cd3Transform relB, cdReal limit,
						  const int* keptA, int countA, const int* keptB, int countB, cd3SatResult* r,
						  cd3Vec* bestAxis)
{
	EdgeData edges[FEW_PAIRS];
	for (int k = 0; k < countA; ++k)
	{
		edges[k] = MakeEdgeData(a, keptA[k]);
	}
	for (int u = 0; u < countB; ++u)
	{
		int j = keptB[u];
		const cd3HullHalfEdge* eb = &b->edges[j];
		const cd3HullHalfEdge* twin = &b->edges[eb->twin];
		cd3Vec qb0 = cd3TransformPoint(relB, b->vertices[eb->origin]);
		cd3Vec qb1 = cd3TransformPoint(relB, b->vertices[twin->origin]);
		cd3Vec c = cd3Neg(cd3RotateVector(relB.q, b->planes[eb->face].normal));
		cd3Vec d = cd3Neg(cd3RotateVector(relB.q, b->planes[twin->face].normal));
		cd3Vec edgeB = cd3Sub(qb1, qb0);
		cdReal edgeB2 = cd3LengthSquared(edgeB);
		cd3Vec dxc = cd3Cross(d, c);
		for (int k = 0; k < countA; ++k)
		{
			const EdgeData* e = &edges[k];
			cdReal cba = cd3Dot(c, e->bxa);
			cdReal dba = cd3Dot(d, e->bxa);
			cdReal adc = cd3Dot(e->na, dxc);
			cdReal bdc = cd3Dot(e->nb, dxc);
			if (cba * dba < CD_R(0.0) && adc * bdc < CD_R(0.0) && cba * bdc > CD_R(0.0))
			{
				TestEdgePair(a, b, relB, e, j, qb0, edgeB, edgeB2, r, bestAxis);
			}
		}
		if (r->edgeSeparation > limit)
		{
			return;
		}
	}
}

/* p's edges (the hull's list, or the half-edges below their twins, as QueryEdgesGauss lists them)
 * that the pruning keeps (EdgePruned): the first FEW_PAIRS in `kept`, in order (room for one
 * more), and with `keep`, each edge's flag (the first EDGE_CACHE edges) and the first 32 as bits
 * of *mask. Returns how many are kept; *all: how many there are. */
static int KeptEdges(const cd3Polytope* p, const uint64_t* below, int* kept, bool* keep, uint32_t* mask,
					 int* all)
{
	int n = 0;
	uint32_t bits = 0u;
	if (p->query != NULL)
	{
		/* The hull's edges and their faces as lists: no walk through the half-edges. */
		const int32_t* list = cd3HullQueryEdges(p->query);
		const int32_t* faces = cd3HullQueryEdgeFaces(p->query);
		int count = p->query->edgeCount;
		for (int k = 0; k < count; ++k)
		{
			bool kept1 = (below[faces[2 * k]] & below[faces[2 * k + 1]]) == 0u;
			if (kept1)
			{
				kept[n < FEW_PAIRS ? n : FEW_PAIRS] = list[k];
				++n;
			}
			bits |= (uint32_t)kept1 << (k & 31);
			if (keep != NULL && k < EDGE_CACHE)
			{
				keep[k] = kept1;
			}
		}
		*all = count;
		if (count > 32)
		{
			bits = ~0u; /* only the masked test reads the bits, on at most 32 edges */
		}
	}
	else
	{
		int unique = 0;
		for (int i = 0; i < p->edgeAxisCount; ++i)
		{
			if (p->edges[i].twin < i)
			{
				continue;
			}
			bool kept1 = !EdgePruned(p, below, i);
			if (kept1)
			{
				kept[n < FEW_PAIRS ? n : FEW_PAIRS] = i;
				++n;
			}
			if (unique < 32)
			{
				bits |= (uint32_t)kept1 << unique;
			}
			if (keep != NULL && unique < EDGE_CACHE)
			{
				keep[unique] = kept1;
			}
			++unique;
		}
		*all = unique;
	}
	if (mask != NULL)
	{
		*mask = bits;
	}
	return n;
}

/* Edge pairs of two solid polytopes, pruned on the Gauss map: the arcs a-b (A's edge) and c-d
 * (B's edge, normals negated) cross exactly when the pair builds a face of the Minkowski
 * difference, whose normal is the cross of the edges oriented within A's arc. Stops early once an
 * edge pair separates by more than `limit` (the answer is then only known to exceed it). With
 * belowA and belowB (FacesBelow of A against B and of B against A), the pruned edges are skipped,
 * and *pruned tells whether there were any. */
static void QueryEdgesGauss(const cd3Polytope* a, const cd3Polytope* b, cd3Transform relB, cdReal limit,
							const uint64_t* belowA, const uint64_t* belowB, bool* pruned, cd3SatResult* r,
							cd3Vec* bestAxis)
{
	/* The edges left by the pruning, in test order (A's as listed below). */
	bool keepA[EDGE_CACHE];
	uint32_t keepMaskA = ~0u;
	if (belowA != NULL)
	{
		int keptA[FEW_PAIRS + 1], keptB[FEW_PAIRS + 1];
		int allA, allB;
		int countA = KeptEdges(a, belowA, keptA, keepA, &keepMaskA, &allA);
		int countB = KeptEdges(b, belowB, keptB, NULL, NULL, &allB);
		*pruned = countA < allA || countB < allB;
		if (countA == 0 || countB == 0)
		{
			return; /* no edge pair left */
		}
		if (countA * countB <= FEW_PAIRS)
		{
			QueryEdgesFew(a, b, relB, limit, keptA, countA, keptB, countB, r, bestAxis);
			return;
		}
	}
	else
	{
		*pruned = false;
	}

	EdgeData cache[EDGE_CACHE];
	ArcColumns arcs;
	int crossing[EDGE_CACHE];
	PendingPairs pending;
	pending.count = 0;
	pending.order = 0;
	pending.bestOrder = -1;
	int cached = 0;
	bool useCache = a->edgeAxisCount / 2 <= EDGE_CACHE;
	/* B's vertices and reversed face normals in A's frame, once each rather than once per edge end
	 * and edge side (the same values). */
	cd3Vec carriedVertices[SMALL_POLYTOPE], carriedNormals[SMALL_POLYTOPE];
	bool carry = b->vertexCount <= SMALL_POLYTOPE && b->faceCount <= SMALL_POLYTOPE;
	/* A's edges (the half-edges below their twins): the hull's list, or listed here without
	 * branches (which half-edge of a pair comes first follows no pattern the processor learns). */
	int32_t listA[EDGE_CACHE];
	const int32_t* uniqueA = listA;
	if (a->query != NULL)
	{
		uniqueA = cd3HullQueryEdges(a->query);
		cached = a->query->edgeCount;
	}
	else
	{
		for (int i = 0; useCache && i < a->edgeAxisCount && cached < EDGE_CACHE; ++i)
		{
			listA[cached] = i;
			cached += a->edges[i].twin > i;
		}
	}
	bool masked = useCache && carry && cached <= MASK_ARCS && a->faceCount <= MASK_FACES;
	/* The arcs' columns: the masked test reads only cross(nb, na), which a hull keeps. */
	bool ownArcs = useCache && !(masked && a->query != NULL);
	const cdReal *arcX = arcs.bxax, *arcY = arcs.bxay, *arcZ = arcs.bxaz;
	if (!ownArcs && useCache)
	{
		arcX = cd3HullQueryArcs(a->query);
		arcY = arcX + a->query->edgePadded;
		arcZ = arcY + a->query->edgePadded;
	}
	for (int k = 0; useCache && k < cached; ++k)
	{
		EdgeData e;
		if (ownArcs)
		{
			e = MakeEdgeData(a, uniqueA[k]);
			arcs.nax[k] = e.na.x;
			arcs.nay[k] = e.na.y;
			arcs.naz[k] = e.na.z;
			arcs.nbx[k] = e.nb.x;
			arcs.nby[k] = e.nb.y;
			arcs.nbz[k] = e.nb.z;
			arcs.bxax[k] = e.bxa.x;
			arcs.bxay[k] = e.bxa.y;
			arcs.bxaz[k] = e.bxa.z;
		}
		else
		{
			/* MakeEdgeData with the hull's cross(nb, na) (the same value). */
			const cd3HullHalfEdge* ea = &a->edges[uniqueA[k]];
			e.na = a->planes[ea->face].normal;
			e.nb = a->planes[a->edges[ea->twin].face].normal;
			e.bxa = cd3MakeVec(arcX[k], arcY[k], arcZ[k]);
			e.origin = a->vertices[ea->origin];
			e.direction = cd3Sub(a->vertices[a->edges[ea->twin].origin], e.origin);
			e.lengthSquared = cd3LengthSquared(e.direction);
			e.index = uniqueA[k];
		}
		cache[k] = e;
	}
	/* Zero arcs up to a multiple of 4: their products are zero, so they never pass. */
	for (int k = cached; ownArcs && (k & 3) != 0; ++k)
	{
		arcs.nax[k] = arcs.nay[k] = arcs.naz[k] = CD_R(0.0);
		arcs.nbx[k] = arcs.nby[k] = arcs.nbz[k] = CD_R(0.0);
		arcs.bxax[k] = arcs.bxay[k] = arcs.bxaz[k] = CD_R(0.0);
	}
	for (int i = 0; carry && i < b->vertexCount; ++i)
	{
		carriedVertices[i] = cd3TransformPoint(relB, b->vertices[i]);
	}
	for (int f = 0; carry && f < b->faceCount; ++f)
	{
		carriedNormals[f] = cd3Neg(cd3RotateVector(relB.q, b->planes[f].normal));
	}
	ArcMasks masks;
	if (masked)
	{
		InitArcMasks(&masks, a, b, uniqueA, cached, arcX, arcY, arcZ, carriedNormals);
	}
	/* B's edges: the hull's list, or every half-edge above its twin. */
	const int32_t* uniqueB = b->query != NULL ? cd3HullQueryEdges(b->query) : NULL;
	int edgesB = b->query != NULL ? b->query->edgeCount : b->edgeAxisCount;
	for (int u = 0; u < edgesB; ++u)
	{
		int j = uniqueB != NULL ? uniqueB[u] : u;
		const cd3HullHalfEdge* eb = &b->edges[j];
		if (eb->twin < j || (belowB != NULL && EdgePruned(b, belowB, j)))
		{
			continue;
		}
		const cd3HullHalfEdge* twin = &b->edges[eb->twin];
		cd3Vec qb0, qb1, c, d;
		if (carry)
		{
			qb0 = carriedVertices[eb->origin];
			qb1 = carriedVertices[twin->origin];
			c = carriedNormals[eb->face];
			d = carriedNormals[twin->face];
		}
		else
		{
			qb0 = cd3TransformPoint(relB, b->vertices[eb->origin]);
			qb1 = cd3TransformPoint(relB, b->vertices[twin->origin]);
			c = cd3Neg(cd3RotateVector(relB.q, b->planes[eb->face].normal));
			d = cd3Neg(cd3RotateVector(relB.q, b->planes[twin->face].normal));
		}
		cd3Vec edgeB = cd3Sub(qb1, qb0);
		cdReal edgeB2 = cd3LengthSquared(edgeB);
		cd3Vec dxc = cd3Cross(d, c);
		if (useCache)
		{
			if (pending.count + cached > PENDING_PAIRS)
			{
				FlushPairs(a, b, relB, cache, &pending, r, bestAxis);
				if (r->edgeSeparation > limit)
				{
					return;
				}
			}
			int n = masked ? CrossingArcsMasked(&masks, eb->face, twin->face, keepMaskA, dxc, crossing)
						   : CrossingArcs(&arcs, cached, c, d, dxc, crossing);
			for (int k = 0; k < n; ++k)
			{
				if (belowA == NULL || keepA[crossing[k]])
				{
					AddPendingPair(&pending, &cache[crossing[k]], crossing[k], j, qb0, edgeB, edgeB2);
				}
			}
			continue;
		}
		else
		{
			for (int k = 0; k < a->edgeAxisCount; ++k)
			{
				if (a->edges[k].twin < k || (belowA != NULL && EdgePruned(a, belowA, k)))
				{
					continue;
				}
				EdgeData e = MakeEdgeData(a, k);
				cdReal cba = cd3Dot(c, e.bxa);
				cdReal dba = cd3Dot(d, e.bxa);
				cdReal adc = cd3Dot(e.na, dxc);
				cdReal bdc = cd3Dot(e.nb, dxc);
				if (cba * dba < CD_R(0.0) && adc * bdc < CD_R(0.0) && cba * bdc > CD_R(0.0))
				{
					TestEdgePair(a, b, relB, &e, j, qb0, edgeB, edgeB2, r, bestAxis);
				}
			}
		}
		if (r->edgeSeparation > limit)
		{
			return;
		}
	}
	if (useCache)
	{
		FlushPairs(a, b, relB, cache, &pending, r, bestAxis);
	}
}

/* Vertices of B carried into A's frame once per query for the projections below, when B has at
 * most this many (triangles and boxes; larger hulls project through the relative transform). */
#define CARRIED_VERTICES 16

/* The extent of A along an axis of A's frame: a box in closed form, the sum its extreme vertex
 * gives term by term (so bit for bit the vertex loop's maximum); otherwise the vertex loop. */
static void ProjectA(const cd3Polytope* a, cd3Vec axis, cdReal* lo, cdReal* hi)
{
	if (a->edges == BOX_EDGES)
	{
		cd3Vec h = a->vertices[7]; /* (+hx, +hy, +hz) */
		cdReal r = cdAbs(axis.x) * h.x + cdAbs(axis.y) * h.y + cdAbs(axis.z) * h.z;
		*lo = -r;
		*hi = r;
		return;
	}
	cdReal mn = cd3Dot(axis, a->vertices[0]);
	cdReal mx = mn;
	for (int i = 1; i < a->vertexCount; ++i)
	{
		cdReal d = cd3Dot(axis, a->vertices[i]);
		mn = cdMin(mn, d);
		mx = cdMax(mx, d);
	}
	*lo = mn;
	*hi = mx;
}

static void ProjectPoints(const cd3Vec* points, int count, cd3Vec axis, cdReal* lo, cdReal* hi)
{
	cdReal mn = cd3Dot(axis, points[0]);
	cdReal mx = mn;
	for (int i = 1; i < count; ++i)
	{
		cdReal d = cd3Dot(axis, points[i]);
		mn = cdMin(mn, d);
		mx = cdMax(mx, d);
	}
	*lo = mn;
	*hi = mx;
}

/* B's side of the projected edge pairs: its vertices (carried into A's frame when few) and the
 * current edge of B in A's frame. */
typedef struct ProjectedB
{
	const cd3Polytope* polytope;
	cd3Transform rel;
	const cd3Vec* carried; /* NULL: project through rel */
	cd3Vec origin, edge;
	cdReal parallel; /* PARALLEL_SINE * |edge| */
	int index;
} ProjectedB;

/* A's edges parallel to edgeA (`members`, half-edge indices) against B's current edge: one
 * projection on their common axis, then the first member that supports A along it. */
static void TestProjectedPair(const cd3Polytope* a, cd3Vec edgeA, const int* members, int memberCount,
							  const ProjectedB* pb, cd3SatResult* r, cd3Vec* bestAxis)
{
	/* Unnormalized: projections, separation and slack all scale with |axis|, so the one division
	 * waits for a pair that beats the best so far. */
	cd3Vec axis = cd3Cross(edgeA, pb->edge);
	cdReal axisLength = cd3Length(axis);
	if (!(axisLength > pb->parallel * cd3Length(edgeA)))
	{
		return;
	}
	cdReal loA, hiA, loB, hiB;
	ProjectA(a, axis, &loA, &hiA);
	if (pb->carried != NULL)
	{
		ProjectPoints(pb->carried, pb->polytope->vertexCount, axis, &loB, &hiB);
	}
	else
	{
		Project(pb->polytope, pb->rel, axis, &loB, &hiB);
	}
	cdReal separation = loB - hiA;
	cdReal extremeA = hiA, extremeB = loB;
	cdReal sign = CD_R(1.0);
	if (loA - hiB > separation)
	{
		separation = loA - hiB;
		sign = CD_R(-1.0);
		extremeA = -loA;
		extremeB = -hiB;
	}
	if (!(r->edgeA < 0 || separation > r->edgeSeparation * axisLength))
	{
		return;
	}
	/* Projection does not tell parallel edges apart: keep the pair only when both edges support
	 * their polytopes along the axis, so the contact lies on them. */
	cdReal slack =
		SUPPORT_TOLERANCE * ((a->size + pb->polytope->size) * axisLength + cdAbs(extremeA) + cdAbs(extremeB));
	if (sign * cd3Dot(axis, pb->origin) > extremeB + slack)
	{
		return;
	}
	for (int m = 0; m < memberCount; ++m)
	{
		if (sign * cd3Dot(axis, a->vertices[a->edges[members[m]].origin]) >= extremeA - slack)
		{
			cdReal inverse = CD_R(1.0) / axisLength;
			r->edgeSeparation = separation * inverse;
			r->edgeA = members[m];
			r->edgeB = pb->index;
			*bestAxis = cd3Scale(sign * inverse, axis);
			return;
		}
	}
}

/* Edge pairs when a polytope is flat (a triangle's arcs are half circles): every pair, by
 * projecting both polytopes on the cross product. A box's twelve edges run in three directions,
 * and a pair's axis and projections depend only on the direction, so a box projects three times
 * per edge of B instead of twelve. */
static void QueryEdgesProjected(const cd3Polytope* a, const cd3Polytope* b, cd3Transform relB,
								cd3SatResult* r, cd3Vec* bestAxis)
{
	cd3Vec carried[CARRIED_VERTICES];
	ProjectedB pb = {b, relB, NULL, CD3_VEC_ZERO, CD3_VEC_ZERO, CD_R(0.0), -1};
	if (b->vertexCount <= CARRIED_VERTICES)
	{
		for (int i = 0; i < b->vertexCount; ++i)
		{
			carried[i] = cd3TransformPoint(relB, b->vertices[i]);
		}
		pb.carried = carried;
	}
	/* The box's unique half-edges by direction: their end vertices differ in bit 0, 1 or 2. */
	bool box = a->edges == BOX_EDGES;
	int groups[3][4];
	int groupSize[3] = {0, 0, 0};
	for (int i = 0; box && i < 24; ++i)
	{
		int twin = BOX_EDGES[i].twin;
		if (twin > i)
		{
			int bit = BOX_EDGES[i].origin ^ BOX_EDGES[twin].origin;
			int k = bit == 1 ? 0 : (bit == 2 ? 1 : 2);
			groups[k][groupSize[k]++] = i;
		}
	}
	for (int j = 0; j < b->edgeAxisCount; ++j)
	{
		const cd3HullHalfEdge* eb = &b->edges[j];
		if (eb->twin < j)
		{
			continue;
		}
		pb.origin = cd3TransformPoint(relB, b->vertices[eb->origin]);
		pb.edge = cd3Sub(cd3TransformPoint(relB, b->vertices[b->edges[eb->twin].origin]), pb.origin);
		pb.parallel = PARALLEL_SINE * cd3Length(pb.edge);
		pb.index = j;
		for (int k = 0; box && k < 3; ++k)
		{
			const cd3HullHalfEdge* ea = &a->edges[groups[k][0]];
			cd3Vec edgeA = cd3Sub(a->vertices[a->edges[ea->twin].origin], a->vertices[ea->origin]);
			TestProjectedPair(a, edgeA, groups[k], groupSize[k], &pb, r, bestAxis);
		}
		for (int i = 0; !box && i < a->edgeAxisCount; ++i)
		{
			const cd3HullHalfEdge* ea = &a->edges[i];
			if (ea->twin > i)
			{
				cd3Vec edgeA = cd3Sub(a->vertices[a->edges[ea->twin].origin], a->vertices[ea->origin]);
				TestProjectedPair(a, edgeA, &i, 1, &pb, r, bestAxis);
			}
		}
	}
}

/* cd3SatPolytopesWithin, and with prune cd3SatPolytopesPruned. */
static cd3SatResult SatPolytopes(const cd3Polytope* a, const cd3Polytope* b, cdReal limit, bool prune,
								 cdReal slack, bool* pruned)
{
	cd3SatResult r;
	cd3Transform relB = cd3InvMulTransforms(a->transform, b->transform); /* B local -> A local */
	cd3Transform relA = cd3InvMulTransforms(b->transform, a->transform);
	/* The pruning needs each polytope's vertices in the other's frame: QueryFaces keeps them. */
	bool canPrune = prune && !a->flat && !b->flat && a->vertexCount <= PRUNE_VERTICES &&
					b->vertexCount <= PRUNE_VERTICES && a->faceCount <= SMALL_POLYTOPE &&
					b->faceCount <= SMALL_POLYTOPE;
	CarriedVertices bInA, aInB; /* B's vertices in A's frame, A's in B's */
	r.faceSeparationA = QueryFaces(a, b, relB, &r.faceA, canPrune ? &bInA : NULL);
	r.faceSeparationB = -CD_REAL_MAX;
	r.faceB = -1;
	r.edgeSeparation = -CD_REAL_MAX;
	r.edgeA = -1;
	r.edgeB = -1;
	r.edgeNormal = cd3MakeVec(CD_R(0.0), CD_R(0.0), CD_R(0.0));
	*pruned = false;
	if (r.faceSeparationA > limit)
	{
		return r;
	}
	r.faceSeparationB = QueryFaces(b, a, relA, &r.faceB, canPrune ? &aInB : NULL);
	if (r.faceSeparationB > limit)
	{
		return r;
	}
	cd3Vec bestAxis = cd3MakeVec(CD_R(0.0), CD_R(0.0), CD_R(0.0));
	if (a->flat || b->flat)
	{
		QueryEdgesProjected(a, b, relB, &r, &bestAxis);
	}
	else if (canPrune)
	{
		/* The floor below every face separation that matters to the caller, less the round-off of
		 * the plane distances (coordinates of the sizes and of the offset between the frames). */
		cdReal best = cdMax(r.faceSeparationA, r.faceSeparationB);
		cdReal roundOff = SUPPORT_TOLERANCE * (a->size + b->size + cd3Length(relB.p));
		cdReal floor = cdMin(best - slack, CD_R(0.0)) - roundOff;
		uint64_t belowA[SMALL_POLYTOPE], belowB[SMALL_POLYTOPE];
		FacesBelow(a, b->vertexCount, &bInA, floor, belowA);
		FacesBelow(b, a->vertexCount, &aInB, floor, belowB);
		QueryEdgesGauss(a, b, relB, limit, belowA, belowB, pruned, &r, &bestAxis);
	}
	else
	{
		QueryEdgesGauss(a, b, relB, limit, NULL, NULL, pruned, &r, &bestAxis);
	}
	r.edgeNormal = cd3RotateVector(a->transform.q, bestAxis);
	return r;
}

cd3SatResult cd3SatPolytopesWithin(const cd3Polytope* a, const cd3Polytope* b, cdReal limit)
{
	bool pruned;
	return SatPolytopes(a, b, limit, false, CD_R(0.0), &pruned);
}

cd3SatResult cd3SatPolytopesPruned(const cd3Polytope* a, const cd3Polytope* b, cdReal limit, cdReal slack,
								   bool* pruned)
{
	return SatPolytopes(a, b, limit, true, slack, pruned);
}

cd3SatResult cd3SatPolytopes(const cd3Polytope* a, const cd3Polytope* b)
{
	return cd3SatPolytopesWithin(a, b, CD_REAL_MAX);
}

cd3SatFeature cd3SatSegmentPolytope(cd3Vec p1, cd3Vec p2, const cd3Polytope* b, cd3SatResult* r)
{
	/* Work in B's local frame. */
	cd3Vec s1 = cd3InvTransformPoint(b->transform, p1);
	cd3Vec s2 = cd3InvTransformPoint(b->transform, p2);
	cd3Vec segment = cd3Sub(s2, s1);
	r->faceSeparationA = -CD_REAL_MAX;
	r->faceA = -1;
	r->faceSeparationB = -CD_REAL_MAX;
	r->faceB = -1;
	for (int f = 0; f < b->faceCount; ++f)
	{
		cd3Plane plane = b->planes[f];
		if (IsZero(plane.normal))
		{
			continue;
		}
		/* Axis -n from the segment to B: B's lowest point is -offset, the segment's highest is
		 * -min(n.s). */
		cdReal separation = cdMin(cd3Dot(plane.normal, s1), cd3Dot(plane.normal, s2)) - plane.offset;
		if (separation > r->faceSeparationB)
		{
			r->faceSeparationB = separation;
			r->faceB = f;
		}
	}
	r->edgeSeparation = -CD_REAL_MAX;
	r->edgeA = -1;
	r->edgeB = -1;
	cd3Vec bestAxis = cd3MakeVec(CD_R(0.0), CD_R(0.0), CD_R(0.0));
	cdReal segmentLength = cd3Length(segment);
	if (segmentLength > CD_R(0.0))
	{
		cd3Transform identity = CD3_TRANSFORM_IDENTITY;
		for (int j = 0; j < b->edgeAxisCount; ++j)
		{
			const cd3HullHalfEdge* eb = &b->edges[j];
			if (eb->twin < j)
			{
				continue;
			}
			cd3Vec edgeB = cd3Sub(b->vertices[b->edges[eb->twin].origin], b->vertices[eb->origin]);
			cd3Vec axis = cd3Cross(segment, edgeB);
			cdReal axisLength = cd3Length(axis);
			if (!(axisLength > PARALLEL_SINE * segmentLength * cd3Length(edgeB)))
			{
				continue;
			}
			axis = cd3Scale(CD_R(1.0) / axisLength, axis);
			cdReal loB, hiB;
			Project(b, identity, axis, &loB, &hiB);
			cdReal d1 = cd3Dot(axis, s1), d2 = cd3Dot(axis, s2);
			cdReal loS = cdMin(d1, d2), hiS = cdMax(d1, d2);
			cdReal separation = loB - hiS;
			cdReal extremeB = loB;
			if (loS - hiB > separation)
			{
				separation = loS - hiB;
				axis = cd3Neg(axis);
				extremeB = -hiB;
			}
			cdReal slack = SUPPORT_TOLERANCE * (b->size + segmentLength + cdAbs(extremeB));
			if (cd3Dot(axis, b->vertices[eb->origin]) > extremeB + slack)
			{
				continue; /* a parallel edge of B supports it along this axis */
			}
			if (separation > r->edgeSeparation)
			{
				r->edgeSeparation = separation;
				r->edgeB = j;
				bestAxis = axis;
			}
		}
	}
	r->edgeNormal = cd3RotateVector(b->transform.q, bestAxis);
	return r->edgeSeparation > r->faceSeparationB ? CD3_SAT_EDGES : CD3_SAT_FACE_B;
}

cd3SatResult cd3SatBoxes(cd3Box a, cd3Box b, cd3Mat33* rotation, cd3Vec* translation)
{
	cd3SatResult r;
	cd3SatBoxesInPlace(&a, &b, &r, rotation, translation, CD_REAL_MAX, NULL);
	return r;
}

void cd3BoxEdgeLocal(cd3Vec halfExtents, int edge, cd3Vec* p1, cd3Vec* p2)
{
	int v1 = BOX_EDGES[edge].origin, v2 = BOX_EDGES[BOX_EDGES[edge].twin].origin;
	*p1 = cd3MakeVec((v1 & 1) ? halfExtents.x : -halfExtents.x, (v1 & 2) ? halfExtents.y : -halfExtents.y,
					 (v1 & 4) ? halfExtents.z : -halfExtents.z);
	*p2 = cd3MakeVec((v2 & 1) ? halfExtents.x : -halfExtents.x, (v2 & 2) ? halfExtents.y : -halfExtents.y,
					 (v2 & 4) ? halfExtents.z : -halfExtents.z);
}
