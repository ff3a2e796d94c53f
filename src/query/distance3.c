/* Distance and closest points between any two 3D shapes: GJK on the shapes' cores (support3.h)
 * with a Voronoi-region sub-algorithm, then the radii are taken off. The half-space is handled
 * in closed form, since it has no finite support in most directions. */
#include "collide/query3.h"

#include "distance3.h"
#include "support3.h"
#include "wide3.h"

#include <math.h>
#include <string.h>

/* GJK converges in a handful of iterations on these small point sets; the cap only guards
 * against cycling caused by round-off. */
#define GJK_MAX_ITERATIONS 64

/* Relative gap between the upper bound |v| and the support plane's lower bound at which the
 * distance is final: round-off in the support values is of this order. */
#define GJK_GAP_TOLERANCE (CD_R(8.0) * CD_REAL_EPSILON)

/* Steps in a row without getting closer before GJK settles for the closest simplex seen. */
#define GJK_MAX_STALLS 4

/* A simplex this flat (sine of its angle, or volume relative to its edge lengths) gives
 * barycentric coordinates dominated by round-off; it is then treated through its faces/edges. */
#define GJK_DEGENERATE_TOLERANCE (CD_R(16.0) * CD_REAL_EPSILON)

/* The origin counts as touching the simplex when the closest point is within this many
 * epsilons of the largest coordinate of its support points: below it the distance is round-off. */
#define GJK_TOUCH_TOLERANCE (CD_R(16.0) * CD_REAL_EPSILON)
/* A triangle simplex within this many touching tolerances of the origin whose next support repeats
 * a vertex may have the origin on its plane by round-off only: its normal is tried (GjkCores).
 * Farther out the repeated support is convergence. */
#define GJK_FACE_NORMAL_BAND CD_R(64.0)

static cdReal MaxAbsComponent(cd3Vec v)
{
	return cd3MaxAbs(v);
}

typedef cd3GjkVertex GjkVertex;
typedef cd3GjkSimplex GjkSimplex;

/* The edge from vertex p to vertex q of the difference, (a_q - a_p) - (b_q - b_p): exact to the
 * round-off of the shapes' own edges, where w_q - w_p keeps only that of |w| (SolverInput). */
static cd3Vec SupportEdge(const GjkVertex* p, const GjkVertex* q)
{
	return cd3Sub(cd3Sub(q->a, p->a), cd3Sub(q->b, p->b));
}

#if CD_DOUBLE
/* a * b - c * d to about one rounding of the result (Dekker's exact products: no fused
 * multiply-add needed), for operands of unit scale (the splits must not overflow). */
static double SplitHigh(double x)
{
	double scaled = 134217729.0 * x; /* 2^27 + 1 */
	return scaled - (scaled - x);
}

static double ProductError(double a, double b, double product)
{
	double aHigh = SplitHigh(a), aLow = a - aHigh, bHigh = SplitHigh(b), bLow = b - bHigh;
	return ((aHigh * bHigh - product) + aHigh * bLow + aLow * bHigh) + aLow * bLow;
}

static double ProductDifference(double a, double b, double c, double d)
{
	double ab = a * b, cd = c * d;
	return (ab - cd) + (ProductError(a, b, ab) - ProductError(c, d, cd));
}
#endif

/* a x b of unit-scale vectors. Two nearly parallel edges (a sliver face: a needle's vertices
 * nearly in line, 2.8e8 and 7e9 long at an angle of 4.5e-8) cancel in each component, whose
 * round-off (epsilon of the products) then tilts the normal by epsilon over the angle's sine: the
 * face's plane missed a point it holds by 0.28, 3.4e9 out (double build). There the components
 * are taken from exact products; in the float build the products of float coordinates are exact
 * in double already. */
static WideVec FaceCross(WideVec a, WideVec b)
{
	WideVec n = WideCross(a, b);
#if CD_DOUBLE
	if (WideDot(n, n) < 1e-6 * WideDot(a, a) * WideDot(b, b))
	{
		n.x = ProductDifference(a.y, b.z, a.z, b.y);
		n.y = ProductDifference(a.z, b.x, a.x, b.z);
		n.z = ProductDifference(a.x, b.y, a.y, b.x);
	}
#endif
	return n;
}

/* What the sub-algorithm solves on: the simplex's vertices w = a - b scaled to unit size, and its
 * edges edge[i][j] = w[j] - w[i] taken from the support points as (a[j] - a[i]) - (b[j] - b[i])
 * (same scale). On a long, thin difference (a segment 1e9 long against a box of size 10) the
 * vertices lie far from the origin and from each other along the needle, and w[j] - w[i] of two
 * vertices at the same end keeps only the round-off of |w| (epsilon times the length) of a short
 * edge: its direction, and so the faces' normals and the search direction, tilt by that over the
 * edge's length, which at the needle's length moves a support plane by more than the gap (1e9 x
 * 2.2e-16 / 13 x 2e9 = 34 in double). From the support points, an edge between two vertices with
 * the same point of A is B's own edge, exact to its own round-off. */
typedef struct SolverInput
{
	cd3Vec w[4];
	cd3Vec edge[4][4];
} SolverInput;

/* Barycentric coordinates of the point of segment w[i]-w[j] closest to the origin. */
static void SolveSegment(const SolverInput* s, int i, int j, cdReal* l0, cdReal* l1)
{
	cd3Vec w0 = s->w[i], w1 = s->w[j], e = s->edge[i][j];
	cdReal d1 = -cd3Dot(w0, e);
	cdReal d2 = cd3Dot(w1, e);
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

static cd3Vec Combine(const cd3Vec* w, const cdReal* l, int count)
{
	cd3Vec v = cd3Scale(l[0], w[0]);
	for (int i = 1; i < count; ++i)
	{
		v = cd3MulAdd(v, l[i], w[i]);
	}
	return v;
}

/* Among candidate sub-simplices, the one whose closest point to the origin is taken. In exact
 * arithmetic a support point that passed the progress test (its support plane below |v|) always
 * belongs to the next reduced simplex: the old simplex's closest point is v, so any closer point
 * needs the new vertex. In floating point the gain can be below the resolution of the distances
 * (a far new vertex, a thin shape whose face-normal support ties between corners), and a plain
 * "smallest distance" choice then falls back to the old sub-simplex: GJK sees the same simplex
 * and the same direction again and stalls far from the answer. So a candidate that gives the
 * newest vertex (the last one) a positive weight wins unless it is farther by more than the
 * round-off of these distances, GJK_TIE_TOLERANCE on the unit-scaled vertices. */
#define GJK_TIE_TOLERANCE (CD_R(16.0) * CD_REAL_EPSILON)

typedef struct SubSimplexChoice
{
	cdReal distanceSquared;
	bool keepsNewest;
	bool found;
} SubSimplexChoice;

static bool IsBetterSubSimplex(const SubSimplexChoice* best, cdReal distanceSquared, bool keepsNewest)
{
	if (!best->found)
	{
		return true;
	}
	if (keepsNewest == best->keepsNewest)
	{
		return distanceSquared < best->distanceSquared;
	}
	cdReal distance = cdSqrt(distanceSquared), bestDistance = cdSqrt(best->distanceSquared);
	return keepsNewest ? distance <= bestDistance + GJK_TIE_TOLERANCE
					   : distance + GJK_TIE_TOLERANCE < bestDistance;
}

/* The vertex of triangle index[0..2] of s where its two shorter edges meet (the largest angle),
 * as a position 0..2 in index; *edgeProductSquared: the product of their squared lengths. */
static int TriangleBase(const SolverInput* s, const int* index, double* edgeProductSquared)
{
	/* Squared lengths: the products compare the same (in double, where the product of two
	 * squares of float lengths cannot underflow). */
	double l01 = (double)cd3LengthSquared(s->edge[index[0]][index[1]]),
		   l02 = (double)cd3LengthSquared(s->edge[index[0]][index[2]]),
		   l12 = (double)cd3LengthSquared(s->edge[index[1]][index[2]]);
	if (l12 >= l01 && l12 >= l02)
	{
		*edgeProductSquared = l01 * l02;
		return 0;
	}
	if (l02 >= l01)
	{
		*edgeProductSquared = l01 * l12;
		return 1;
	}
	*edgeProductSquared = l02 * l12;
	return 2;
}

/* Barycentric coordinates l[0..2] of the point of triangle w[index[0..2]] closest to the origin;
 * index[2] is the newest vertex. */
static void SolveTriangle(const SolverInput* s, const int* index, cdReal* l)
{
	/* The normal from the two shorter edges, which meet at the largest angle: from the two long
	 * edges of a needle (one vertex far from the others) it would cancel, and the needle would
	 * pass for flat. The vertex where they meet is the base of the face weights below. The edges
	 * from the base to the next vertices in cyclic order: ei x ej is (w1 - w0) x (w2 - w0) for
	 * every base. In double whatever cdReal is: the products below of float coordinates are then
	 * exact or nearly, and their squares cannot underflow. */
	double edgeProductSquared;
	int base = TriangleBase(s, index, &edgeProductSquared);
	int next = base == 2 ? 0 : base + 1, previous = base == 0 ? 2 : base - 1;
	WideVec ei = Widen(s->edge[index[base]][index[next]]), ej = Widen(s->edge[index[base]][index[previous]]);
	WideVec n = FaceCross(ei, ej);
	double normalSquared = WideDot(n, n);
	bool flat = !(normalSquared >
				  (double)GJK_DEGENERATE_TOLERANCE * (double)GJK_DEGENERATE_TOLERANCE * edgeProductSquared);
	if (!flat)
	{
		/* The origin as o = wb + li ei + lj ej (plus a part along n): li = n.(o' x ej) / |n|^2,
		 * lj = n.(ei x o') / |n|^2 with o' = -wb. Measured from the vertex at the largest angle,
		 * along its two shorter edges, the weights err by about epsilon times |wb| over those
		 * edges. The former sub-areas of the triangles the origin makes with each edge, products
		 * of two vertices, erred by epsilon |w|^2 over the face's area: on a needle 7e9 long and
		 * 15 wide (relative width 2e-9) they were all round-off, a vertex the closest point needs
		 * got the weight 0, and GJK stopped 7.7 from a point it touched (double build). */
		WideVec o = WideScale(-1.0, Widen(s->w[index[base]]));
		double li = WideDot(n, WideCross(o, ej));
		double lj = WideDot(n, WideCross(ei, o));
		double lb = normalSquared - li - lj;
		if (li >= 0.0 && lj >= 0.0 && lb >= 0.0)
		{
			double inverse = 1.0 / normalSquared;
			l[base] = (cdReal)(lb * inverse);
			l[next] = (cdReal)(li * inverse);
			l[previous] = (cdReal)(lj * inverse);
			return;
		}
	}

	/* Outside the face (or a flat triangle): the closest point lies on an edge. The edges with
	 * the newest vertex come first, so that they also win exact ties. */
	static const int edges[3][2] = {{1, 2}, {2, 0}, {0, 1}};
	SubSimplexChoice best = {CD_REAL_MAX, false, false};
	for (int e = 0; e < 3; ++e)
	{
		int i = edges[e][0], j = edges[e][1], k = 3 - i - j;
		cdReal li, lj;
		SolveSegment(s, index[i], index[j], &li, &lj);
		cdReal distanceSquared =
			cd3LengthSquared(cd3Add(cd3Scale(li, s->w[index[i]]), cd3Scale(lj, s->w[index[j]])));
		bool keepsNewest = (i == 2 && li > CD_R(0.0)) || (j == 2 && lj > CD_R(0.0));
		if (IsBetterSubSimplex(&best, distanceSquared, keepsNewest))
		{
			best.distanceSquared = distanceSquared;
			best.keepsNewest = keepsNewest;
			best.found = true;
			l[i] = li;
			l[j] = lj;
			l[k] = CD_R(0.0);
		}
	}
}

/* Barycentric coordinates of the point of tetrahedron w[0..3] closest to the origin; returns
 * true when the origin lies inside it. */
static bool SolveTetrahedron(const SolverInput* s, cdReal* l)
{
	const cd3Vec* w = s->w;
	/* The weights are solved along three edges that join the four vertices (a spanning tree of
	 * the tetrahedron: a star from one vertex or a path through all four), the tree whose edges
	 * have the smallest product: their determinant is six times the volume whichever tree, and
	 * the solve errs by epsilon times |w| over the volume relative to that product. From a single
	 * vertex, a needle's tetrahedron (two vertices at each end) has two long, nearly parallel
	 * edges and the solve kept no digit; its path short edge - long edge - short edge is as well
	 * conditioned as the needle is thick. Six squared edge lengths, once: products of squares
	 * compare like products of lengths (in double, where products of three squares of float
	 * lengths cannot underflow). */
	static const int trees[16][3][2] = {
		{{0, 1}, {0, 2}, {0, 3}}, {{1, 0}, {1, 2}, {1, 3}}, {{2, 0}, {2, 1}, {2, 3}},
		{{3, 0}, {3, 1}, {3, 2}}, {{0, 1}, {1, 2}, {2, 3}}, {{0, 1}, {1, 3}, {3, 2}},
		{{0, 2}, {2, 1}, {1, 3}}, {{0, 2}, {2, 3}, {3, 1}}, {{0, 3}, {3, 1}, {1, 2}},
		{{0, 3}, {3, 2}, {2, 1}}, {{1, 0}, {0, 2}, {2, 3}}, {{1, 0}, {0, 3}, {3, 2}},
		{{1, 2}, {2, 0}, {0, 3}}, {{1, 3}, {3, 0}, {0, 2}}, {{2, 0}, {0, 1}, {1, 3}},
		{{2, 1}, {1, 0}, {0, 3}}};
	double edgeSquared[4][4];
	for (int i = 0; i < 4; ++i)
	{
		edgeSquared[i][i] = 1.0;
		for (int j = i + 1; j < 4; ++j)
		{
			edgeSquared[i][j] = edgeSquared[j][i] = (double)cd3LengthSquared(s->edge[i][j]);
		}
	}
	int tree = 0;
	double smallest = (double)CD_REAL_MAX * (double)CD_REAL_MAX;
	for (int t = 0; t < 16; ++t)
	{
		double product = edgeSquared[trees[t][0][0]][trees[t][0][1]] *
						 edgeSquared[trees[t][1][0]][trees[t][1][1]] *
						 edgeSquared[trees[t][2][0]][trees[t][2][1]];
		if (product < smallest)
		{
			smallest = product;
			tree = t;
		}
	}
	const int(*treeEdges)[2] = trees[tree];
	int base = treeEdges[0][0];
	cd3Vec e1 = s->edge[treeEdges[0][0]][treeEdges[0][1]];
	cd3Vec e2 = s->edge[treeEdges[1][0]][treeEdges[1][1]];
	cd3Vec e3 = s->edge[treeEdges[2][0]][treeEdges[2][1]];
	cdReal volume = cd3Dot(cd3Cross(e1, e2), e3);
	/* The enclosing weights, when all are non-negative, and how far from the origin they rebuild
	 * the point (CD_REAL_MAX when there are none). */
	cdReal enclosing[4] = {CD_R(0.0), CD_R(0.0), CD_R(0.0), CD_R(0.0)};
	cdReal residual = CD_REAL_MAX;
	if ((double)cdAbs(volume) > (double)GJK_DEGENERATE_TOLERANCE * sqrt(smallest))
	{
		/* The origin from the base, o = -w[base], as m1 e1 + m2 e2 + m3 e3 (Cramer); each tree edge
		 * moves its coefficient from its first vertex to its second. */
		cd3Vec o = cd3Neg(w[base]);
		cdReal m[3] = {cd3Dot(cd3Cross(o, e2), e3) / volume, cd3Dot(cd3Cross(e1, o), e3) / volume,
					   cd3Dot(cd3Cross(e1, e2), o) / volume};
		cdReal weights[4] = {CD_R(0.0), CD_R(0.0), CD_R(0.0), CD_R(0.0)};
		weights[base] = CD_R(1.0);
		for (int k = 0; k < 3; ++k)
		{
			weights[treeEdges[k][0]] -= m[k];
			weights[treeEdges[k][1]] += m[k];
		}
		if (weights[0] >= CD_R(0.0) && weights[1] >= CD_R(0.0) && weights[2] >= CD_R(0.0) &&
			weights[3] >= CD_R(0.0))
		{
			cdReal sum = weights[0] + weights[1] + weights[2] + weights[3];
			for (int i = 0; i < 4; ++i)
			{
				enclosing[i] = weights[i] / sum;
			}
			/* On a thin tetrahedron (just above the flatness tolerance) the weights carry a
			 * round-off of epsilon over its flatness: the point they rebuild can be far from the
			 * origin (1e-3 of the size at the 1e9 scale, which made a common point 1e6 off a
			 * hull). Iterative refinement: the weights of the rebuilt point r, by the same
			 * (linear) formulas, are taken off; the residual, computed accurately, shrinks by
			 * the solve's relative error at each pass. */
			bool inside = true;
			residual = cd3Length(Combine(w, enclosing, 4));
			for (int pass = 0; pass < 2 && residual > GJK_TOUCH_TOLERANCE; ++pass)
			{
				cd3Vec r = Combine(w, enclosing, 4);
				cdReal d[3] = {cd3Dot(cd3Cross(r, e2), e3) / volume, cd3Dot(cd3Cross(e1, r), e3) / volume,
							   cd3Dot(cd3Cross(e1, e2), r) / volume};
				for (int k = 0; k < 3; ++k)
				{
					enclosing[treeEdges[k][0]] += d[k];
					enclosing[treeEdges[k][1]] -= d[k];
				}
				inside = enclosing[0] >= CD_R(0.0) && enclosing[1] >= CD_R(0.0) &&
						 enclosing[2] >= CD_R(0.0) && enclosing[3] >= CD_R(0.0);
				residual = inside ? cd3Length(Combine(w, enclosing, 4)) : CD_REAL_MAX;
			}
		}
	}
	/* The origin counts as enclosed when the weights rebuild it within the touching tolerance of
	 * these unit-scaled vertices, or at least closer than the nearest face does; otherwise the
	 * faces decide. */
	if (residual <= GJK_TOUCH_TOLERANCE)
	{
		for (int i = 0; i < 4; ++i)
		{
			l[i] = enclosing[i];
		}
		return true;
	}

	/* Outside (or flat): the closest point lies on a face. The faces list the newest vertex, 3,
	 * last (SolveTriangle's newest) and come before the old face {0, 1, 2}. */
	static const int faces[4][3] = {{1, 2, 3}, {2, 0, 3}, {0, 1, 3}, {0, 1, 2}};
	SubSimplexChoice best = {CD_REAL_MAX, false, false};
	for (int f = 0; f < 4; ++f)
	{
		cd3Vec face[3] = {w[faces[f][0]], w[faces[f][1]], w[faces[f][2]]};
		cdReal faceLambda[3];
		SolveTriangle(s, faces[f], faceLambda);
		cdReal distanceSquared = cd3LengthSquared(Combine(face, faceLambda, 3));
		bool keepsNewest = faces[f][2] == 3 && faceLambda[2] > CD_R(0.0);
		if (IsBetterSubSimplex(&best, distanceSquared, keepsNewest))
		{
			best.distanceSquared = distanceSquared;
			best.keepsNewest = keepsNewest;
			best.found = true;
			for (int i = 0; i < 4; ++i)
			{
				l[i] = CD_R(0.0);
			}
			for (int i = 0; i < 3; ++i)
			{
				l[faces[f][i]] = faceLambda[i];
			}
		}
	}
	if (residual < cdSqrt(best.distanceSquared))
	{
		for (int i = 0; i < 4; ++i)
		{
			l[i] = enclosing[i];
		}
		return true;
	}
	return false;
}

/* Reduces the simplex to the vertices that support its point closest to the origin, sets their
 * weights and returns true when the origin is enclosed by a tetrahedron. */
static bool SolveSimplex(GjkSimplex* simplex)
{
	SolverInput input;
	cdReal l[4] = {CD_R(1.0), CD_R(0.0), CD_R(0.0), CD_R(0.0)};
	/* The weights do not depend on scale: solve on vertices scaled to unit size, so that the
	 * products of up to four coordinates neither overflow nor underflow at extreme sizes. */
	cdReal largest = CD_R(0.0);
	int count = simplex->count;
	for (int i = 0; i < count; ++i)
	{
		largest = cdMax(largest, cd3MaxAbs(simplex->v[i].w));
	}
	cdReal inverse = largest > CD_R(0.0) ? CD_R(1.0) / largest : CD_R(1.0);
	for (int i = 0; i < count; ++i)
	{
		input.w[i] = cd3Scale(inverse, simplex->v[i].w);
		input.edge[i][i] = CD3_VEC_ZERO;
		for (int j = i + 1; j < count; ++j)
		{
			cd3Vec edge = cd3Scale(inverse, SupportEdge(&simplex->v[i], &simplex->v[j]));
			input.edge[i][j] = edge;
			input.edge[j][i] = cd3Neg(edge);
		}
	}
	bool enclosed = false;
	if (count == 2)
	{
		SolveSegment(&input, 0, 1, &l[0], &l[1]);
	}
	else if (count == 3)
	{
		static const int all[3] = {0, 1, 2};
		SolveTriangle(&input, all, l);
	}
	else if (count == 4)
	{
		enclosed = SolveTetrahedron(&input, l);
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

static cd3Vec SimplexPoint(const GjkSimplex* simplex)
{
	cd3Vec v = CD3_VEC_ZERO;
	for (int i = 0; i < simplex->count; ++i)
	{
		v = cd3MulAdd(v, simplex->lambda[i], simplex->v[i].w);
	}
	return v;
}

/* The point of a triangle's plane closest to the origin (the simplex's point when its weights
 * hold the face), from the normal of its two shorter edges (SupportEdge, scaled to unit size) and
 * one vertex: exact to the round-off of the vertices across the face. The weighted sum of the
 * vertices also carries the weights' error along the face, epsilon times |w| over the face's
 * width times its length: on a needle face whose vertices lie 3e9 out and 12.5 apart across, 15
 * along it, and a point touching the hull's surface stayed 3.4 from it (double build). */
static cd3Vec FacePoint(const GjkSimplex* simplex)
{
	const GjkVertex* v = simplex->v;
	cdReal largest = cdMax(cd3MaxAbs(v[0].w), cdMax(cd3MaxAbs(v[1].w), cd3MaxAbs(v[2].w)));
	if (!(largest > CD_R(0.0)))
	{
		return SimplexPoint(simplex);
	}
	double inverse = 1.0 / (double)largest;
	WideVec e01 = WideScale(inverse, Widen(SupportEdge(&v[0], &v[1])));
	WideVec e02 = WideScale(inverse, Widen(SupportEdge(&v[0], &v[2])));
	WideVec e12 = WideScale(inverse, Widen(SupportEdge(&v[1], &v[2])));
	double l01 = WideDot(e01, e01), l02 = WideDot(e02, e02), l12 = WideDot(e12, e12);
	WideVec n = l12 >= l01 && l12 >= l02 ? FaceCross(e01, e02)
										 : (l02 >= l01 ? FaceCross(e01, e12) : FaceCross(e02, e12));
	double normalSquared = WideDot(n, n);
	if (!(normalSquared > 0.0))
	{
		return SimplexPoint(simplex);
	}
	WideVec w0 = Widen(v[0].w);
	return Narrow(WideScale(WideDot(n, w0) / normalSquared, n));
}

/* The direction from the simplex towards the origin. For a segment or a triangle it is built
 * from the simplex's own edges (Catto's trick): -v, a sum of large, cancelling terms when the
 * shapes are large compared with their distance, can point off by far more than its length error
 * and make GJK stop at a tie between support points. */
static cd3Vec SearchDirection(const GjkSimplex* simplex, cd3Vec v)
{
	/* A tetrahedron (the shape cast can ask with one that round-off kept from enclosing the
	 * origin) has no edge construction: -v. */
	if (simplex->count < 2 || simplex->count > 3)
	{
		return cd3Neg(v);
	}
	/* On unit-scaled vertices: the products of three coordinates must not under/overflow. The
	 * edges from the support points (SupportEdge): on a needle, w1 - w0 of two vertices at one
	 * end tilts the direction by epsilon times the length over the edge, and the support along
	 * it can then pick the wrong end of the needle. */
	cd3Vec w0 = simplex->v[0].w;
	cd3Vec e01 = SupportEdge(&simplex->v[0], &simplex->v[1]);
	cd3Vec e02 = CD3_VEC_ZERO, e12 = CD3_VEC_ZERO;
	cdReal largest = cdMax(cd3MaxAbs(w0), cd3MaxAbs(simplex->v[1].w));
	if (simplex->count == 3)
	{
		e02 = SupportEdge(&simplex->v[0], &simplex->v[2]);
		e12 = SupportEdge(&simplex->v[1], &simplex->v[2]);
		largest = cdMax(largest, cd3MaxAbs(simplex->v[2].w));
	}
	/* Within these bounds the direction (products of up to three coordinates) and its squared
	 * length (six) neither overflow nor underflow: no scaling needed (the direction's length does
	 * not matter). A squared length that underflowed to zero made the gap test stop GJK at once
	 * (0.2% off at the 1e-8 scale in float). */
#if CD_DOUBLE
	const cdReal safeLow = 0x1p-160, safeHigh = 0x1p160;
#else
	const cdReal safeLow = 0x1p-20f, safeHigh = 0x1p20f;
#endif
	if (largest < safeLow || largest > safeHigh)
	{
		cdReal inverse = CD_R(1.0) / largest;
		w0 = cd3Scale(inverse, w0);
		e01 = cd3Scale(inverse, e01);
		e02 = cd3Scale(inverse, e02);
		e12 = cd3Scale(inverse, e12);
	}
	cd3Vec direction;
	if (simplex->count == 2)
	{
		direction = cd3Cross(cd3Cross(e01, cd3Neg(w0)), e01);
	}
	else
	{
		/* The normal from the two shorter edges (SolveTriangle). */
		cdReal l01 = cd3LengthSquared(e01), l02 = cd3LengthSquared(e02), l12 = cd3LengthSquared(e12);
		WideVec a = Widen(e01), b = Widen(e02), c = Widen(e12);
		if (l12 >= l01 && l12 >= l02)
		{
			direction = Narrow(FaceCross(a, b));
		}
		else if (l02 >= l01)
		{
			direction = Narrow(FaceCross(a, c));
		}
		else
		{
			direction = Narrow(FaceCross(b, c));
		}
		if (cd3Dot(direction, w0) > CD_R(0.0))
		{
			direction = cd3Neg(direction);
		}
	}
	/* The constructions vanish only when the origin is (nearly) on the simplex's line or plane,
	 * where -v is as good a direction as any. */
	/* The squared length decides as the length would (its square root is positive, finite or NaN
	 * exactly when it is), without a square root per iteration. */
	cdReal lengthSquared = cd3LengthSquared(direction);
	return lengthSquared > CD_R(0.0) && cdIsValidReal(lengthSquared) && cd3Dot(direction, v) < CD_R(0.0)
			   ? direction
			   : cd3Neg(v);
}

static GjkVertex MakeVertex(const cd3Core* a, const cd3Core* b, int indexA, int indexB)
{
	GjkVertex vertex;
	vertex.indexA = indexA;
	vertex.indexB = indexB;
	vertex.a = cd3CorePoint(a, indexA);
	vertex.b = cd3CorePoint(b, indexB);
	vertex.w = cd3Sub(vertex.a, vertex.b);
	return vertex;
}

/* The size of a simplex (length, area or volume), which a warm start compares with the cached
 * one: a simplex that grew or shrank by more than a factor of 2 belongs to shapes that moved too
 * much for it to help (Catto). */
bool cd3SolveGjkSimplex(cd3GjkSimplex* simplex)
{
	return SolveSimplex(simplex);
}

cd3Vec cd3GjkSearchDirection(const cd3GjkSimplex* simplex, cd3Vec v)
{
	return SearchDirection(simplex, v);
}

static cdReal SimplexMetric(const GjkSimplex* simplex)
{
	const GjkVertex* v = simplex->v;
	switch (simplex->count)
	{
		case 2:
			return cd3Length(cd3Sub(v[1].w, v[0].w));
		case 3:
			return cd3Length(cd3Cross(cd3Sub(v[1].w, v[0].w), cd3Sub(v[2].w, v[0].w)));
		case 4:
			return cdAbs(
				cd3Dot(cd3Cross(cd3Sub(v[1].w, v[0].w), cd3Sub(v[2].w, v[0].w)), cd3Sub(v[3].w, v[0].w)));
		default:
			return CD_R(0.0);
	}
}

/* Rebuilds the cached simplex from the current shapes; false (no warm start) for a cache that is
 * empty, garbage (count or indices out of range, a vertex repeated, a size that is not a finite
 * positive number) or stale (size changed by more than a factor of 2). Any simplex of support
 * points is a valid start for GJK, so a cache that passes can change the iterations but not the
 * answer. */
static bool ReadCache(const cd3SimplexCache* cache, const cd3Core* a, const cd3Core* b, GjkSimplex* simplex)
{
	if (cache == NULL || cache->count < 1 || cache->count > 4)
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

static void WriteCache(cd3SimplexCache* cache, const GjkSimplex* simplex)
{
	if (cache == NULL)
	{
		return;
	}
	cache->count = simplex->count;
	for (int i = 0; i < 4; ++i)
	{
		cache->indexA[i] = i < simplex->count ? simplex->v[i].indexA : 0;
		cache->indexB[i] = i < simplex->count ? simplex->v[i].indexB : 0;
	}
	cache->metric = SimplexMetric(simplex);
}

/* ---- The lean solver ----
 * Most steps are well-conditioned: a unit-scale simplex, not flat, whose closest point holds the
 * newest vertex. For them GJK runs a lean solver (Ericson, Real-Time Collision Detection 5.1.5 and
 * 5.1.6): the Voronoi regions are told apart by a few dot products, and of a tetrahedron only the
 * three faces with the newest vertex are examined (the search direction put the origin on the
 * newest vertex's side of the old face). A step that the lean solver cannot vouch for (a triangle
 * or tetrahedron nearly flat, coordinates beyond a safe range, a closest feature without the
 * newest vertex, an enclosed origin, a cached simplex whose vertices are all old) goes to the
 * robust solver above, with its tie rules, tolerances and refinement. */

/* How fat a triangle must be for the lean solver (LeanTriangle): about the sine of its angles,
 * relative to the scale of its coordinates. Its weights then round at about epsilon / 0.01 of
 * that scale: moved within its plane by that much, the closest point is farther by the square of
 * it over twice the distance, below the float tolerances above the touching distance. */
#define GJK_LEAN_FAT CD_R(0.1)

/* Volume of a tetrahedron relative to the product of three edges below which the lean solver
 * leaves it to the robust one. The lean tetrahedron only reads signs (which side of each face the
 * origin lies) and hands its faces to LeanTriangle: a wrong sign where the origin is within
 * round-off of a face costs nothing (that face's point is then as close, or the robust solver
 * checks an enclosure), so a sign needs only to be well above the volume's round-off. */
#define GJK_LEAN_THIN_VOLUME CD_R(1.0e-3)

/* Round-off of a support value relative to the largest coordinate of the support points (w = a -
 * b and its dot product each round at about one epsilon of their largest terms). */
#define GJK_GAP_ROUNDOFF (CD_R(4.0) * CD_REAL_EPSILON)

/* Range of the largest |coordinate| of a simplex's support points for the lean solver: products of
 * up to six coordinates of w (a tetrahedron's squared volume, times a squared tolerance) do not
 * overflow below the top. Below the bottom the shapes are small enough for underflow to matter;
 * a vertex w much smaller than its support points only makes the flatness tests (strict
 * comparisons, false for products that underflow to zero) hand the step to the robust solver. */
#if CD_DOUBLE
#define GJK_LEAN_HIGH 0x1p100
#define GJK_LEAN_LOW 0x1p-100
#else
#define GJK_LEAN_HIGH 0x1p16f
#define GJK_LEAN_LOW 0x1p-12f
#endif

/* The simplex's point closest to the origin: the vertices that support it (indices into the
 * simplex), their weights, the point v and the search direction (towards the origin, any length). */
typedef struct LeanSolution
{
	cd3Vec v, direction;
	cdReal lambda[3];
	int index[3];
	int count;
	bool usesNewest; /* the closest feature holds the newest vertex */
} LeanSolution;

static void LeanVertex(const GjkVertex* s, int i, LeanSolution* out)
{
	out->count = 1;
	out->index[0] = i;
	out->lambda[0] = CD_R(1.0);
	out->v = s[i].w;
	out->direction = cd3Neg(s[i].w);
}

/* Edge p-q at parameter t (from p). The direction is built from the edge (Catto): the part of
 * -p perpendicular to the edge, exact to round-off even where -v cancels. */
static void LeanEdge(const GjkVertex* s, int p, int q, cdReal t, LeanSolution* out)
{
	/* A zero-length edge (two index pairs with the same difference) gives 0/0: its first end. */
	t = t >= CD_R(0.0) && t <= CD_R(1.0) ? t : CD_R(0.0);
	cd3Vec wp = s[p].w, e = cd3Sub(s[q].w, wp);
	out->count = 2;
	out->index[0] = p;
	out->index[1] = q;
	out->lambda[0] = CD_R(1.0) - t;
	out->lambda[1] = t;
	out->v = cd3MulAdd(wp, t, e);
	out->direction = cd3Cross(cd3Cross(e, cd3Neg(wp)), e);
}

/* Closest point of the segment p-q, q the newest vertex. */
static void LeanSegment(const GjkVertex* s, int p, int q, LeanSolution* out)
{
	cd3Vec wp = s[p].w, wq = s[q].w, e = cd3Sub(wq, wp);
	cdReal towardQ = -cd3Dot(wp, e); /* |e|^2 times the parameter of the origin's projection */
	cdReal beyondQ = cd3Dot(wq, e);
	if (towardQ <= CD_R(0.0))
	{
		LeanVertex(s, p, out);
		out->usesNewest = false;
	}
	else if (beyondQ <= CD_R(0.0))
	{
		LeanVertex(s, q, out);
		out->usesNewest = true;
	}
	else
	{
		LeanEdge(s, p, q, towardQ / (towardQ + beyondQ), out);
		out->usesNewest = true;
	}
}

/* Closest point of the triangle a-b-c, c the newest vertex (Ericson's region tests with the
 * origin as the query point); false when the triangle is too thin for them. Their products of dot
 * products round at about epsilon times the largest edge squared times the largest squared length
 * of an edge or a vertex, while the face weights they give add up to |ab x ac|^2: the tests are
 * trusted when that sum exceeds GJK_LEAN_FAT^2 times this scale (a needle, or a triangle far from
 * the origin compared with its size, goes to the robust solver: fuzz_query3 found a needle of
 * 0.0025 by 1 whose face weights came out wrong and made GJK stop 4e-4 off). */
static bool LeanTriangle(const GjkVertex* s, int ia, int ib, int ic, LeanSolution* out)
{
	cd3Vec a = s[ia].w, b = s[ib].w, c = s[ic].w;
	cd3Vec ab = cd3Sub(b, a), ac = cd3Sub(c, a), bc = cd3Sub(c, b);
	cdReal d1 = -cd3Dot(ab, a), d2 = -cd3Dot(ac, a);
	cdReal d3 = -cd3Dot(ab, b), d4 = -cd3Dot(ac, b);
	cdReal d5 = -cd3Dot(ab, c), d6 = -cd3Dot(ac, c);
	cdReal va = d3 * d6 - d5 * d4, vb = d5 * d2 - d1 * d6, vc = d1 * d4 - d3 * d2;
	cdReal longestEdge = cdMax(cd3LengthSquared(ab), cdMax(cd3LengthSquared(ac), cd3LengthSquared(bc)));
	cdReal farthest = cdMax(cd3LengthSquared(a), cdMax(cd3LengthSquared(b), cd3LengthSquared(c)));
	cdReal sum = va + vb + vc;
	if (!(sum > GJK_LEAN_FAT * GJK_LEAN_FAT * longestEdge * cdMax(longestEdge, farthest)))
	{
		return false;
	}
	if (d1 <= CD_R(0.0) && d2 <= CD_R(0.0))
	{
		LeanVertex(s, ia, out);
		out->usesNewest = false;
		return true;
	}
	if (d3 >= CD_R(0.0) && d4 <= d3)
	{
		LeanVertex(s, ib, out);
		out->usesNewest = false;
		return true;
	}
	if (vc <= CD_R(0.0) && d1 >= CD_R(0.0) && d3 <= CD_R(0.0))
	{
		LeanEdge(s, ia, ib, d1 / (d1 - d3), out);
		out->usesNewest = false;
		return true;
	}
	out->usesNewest = true;
	if (d6 >= CD_R(0.0) && d5 <= d6)
	{
		LeanVertex(s, ic, out);
		return true;
	}
	if (vb <= CD_R(0.0) && d2 >= CD_R(0.0) && d6 <= CD_R(0.0))
	{
		LeanEdge(s, ia, ic, d2 / (d2 - d6), out);
		return true;
	}
	if (va <= CD_R(0.0) && d4 - d3 >= CD_R(0.0) && d5 - d6 >= CD_R(0.0))
	{
		LeanEdge(s, ib, ic, (d4 - d3) / ((d4 - d3) + (d5 - d6)), out);
		return true;
	}
	/* The face: the weights va, vb, vc (non-negative here up to round-off). */
	if (!(va >= CD_R(0.0) && vb >= CD_R(0.0) && vc >= CD_R(0.0)))
	{
		return false;
	}
	cdReal inverse = CD_R(1.0) / sum;
	out->count = 3;
	out->index[0] = ia;
	out->index[1] = ib;
	out->index[2] = ic;
	out->lambda[0] = va * inverse;
	out->lambda[1] = vb * inverse;
	out->lambda[2] = vc * inverse;
	out->v =
		cd3Add(cd3Add(cd3Scale(out->lambda[0], a), cd3Scale(out->lambda[1], b)), cd3Scale(out->lambda[2], c));
	cd3Vec n = cd3Cross(ab, ac);
	out->direction = cd3Dot(n, a) > CD_R(0.0) ? cd3Neg(n) : n;
	return true;
}

typedef enum LeanStatus
{
	LEAN_SOLVED,
	LEAN_ENCLOSED,
	LEAN_GIVE_UP
} LeanStatus;

/* Closest point of the tetrahedron s[0..3], s[3] the newest vertex. */
static LeanStatus LeanTetrahedron(const GjkVertex* s, LeanSolution* out)
{
	cd3Vec a = s[0].w, b = s[1].w, c = s[2].w, d = s[3].w;
	cd3Vec ab = cd3Sub(b, a), ac = cd3Sub(c, a), ad = cd3Sub(d, a);
	cd3Vec abc = cd3Cross(ab, ac);
	cdReal volume = cd3Dot(abc, ad);
	cdReal edgeProduct = cd3LengthSquared(ab) * cd3LengthSquared(ac) * cd3LengthSquared(ad);
	if (!(volume * volume > GJK_LEAN_THIN_VOLUME * GJK_LEAN_THIN_VOLUME * edgeProduct))
	{
		return LEAN_GIVE_UP;
	}
	/* The origin beyond the old face: impossible in exact arithmetic. */
	if (cd3Dot(abc, a) * volume > CD_R(0.0))
	{
		return LEAN_GIVE_UP;
	}
	/* The faces with the newest vertex (old vertices in ascending order, as the compaction of the
	 * simplex expects), each with the vertex opposite it. */
	static const int faces[3][3] = {{0, 1, 2}, {1, 2, 0}, {0, 2, 1}};
	bool found = false;
	cdReal bestDistanceSquared = CD_REAL_MAX;
	for (int f = 0; f < 3; ++f)
	{
		int i = faces[f][0], j = faces[f][1], opposite = faces[f][2];
		cd3Vec wi = s[i].w;
		cd3Vec n = cd3Cross(cd3Sub(s[j].w, wi), cd3Sub(d, wi));
		cdReal originSide = -cd3Dot(n, wi), oppositeSide = cd3Dot(n, cd3Sub(s[opposite].w, wi));
		if (!(originSide * oppositeSide < CD_R(0.0)))
		{
			continue;
		}
		LeanSolution face;
		if (!LeanTriangle(s, i, j, 3, &face))
		{
			return LEAN_GIVE_UP;
		}
		cdReal distanceSquared = cd3LengthSquared(face.v);
		if (distanceSquared < bestDistanceSquared)
		{
			bestDistanceSquared = distanceSquared;
			*out = face;
			found = true;
		}
	}
	if (!found)
	{
		return LEAN_ENCLOSED;
	}
	return out->usesNewest ? LEAN_SOLVED : LEAN_GIVE_UP;
}

/* One solver step on the lean path: LEAN_SOLVED when it applies (then the simplex is reduced, its
 * weights set, and *v and *direction written); otherwise the simplex is left as it was, for the
 * robust solver (which also gives the enclosing weights when the lean one finds the origin
 * enclosed, LEAN_ENCLOSED). */
static LeanStatus SolveLean(GjkSimplex* simplex, cdReal* size, cdReal bestDistanceSquared, cd3Vec* v,
							cd3Vec* direction)
{
	LeanSolution solution;
	if (simplex->count == 2)
	{
		LeanSegment(simplex->v, 0, 1, &solution);
	}
	else if (simplex->count == 3)
	{
		if (!LeanTriangle(simplex->v, 0, 1, 2, &solution))
		{
			return LEAN_GIVE_UP;
		}
	}
	else
	{
		LeanStatus status = LeanTetrahedron(simplex->v, &solution);
		if (status != LEAN_SOLVED)
		{
			return status;
		}
	}
	/* Exact GJK gets closer at every step: a lean step that does not is round-off, which the
	 * robust solver (its tie rules) handles. */
	if (!solution.usesNewest || !(cd3LengthSquared(solution.v) < bestDistanceSquared))
	{
		return LEAN_GIVE_UP;
	}
	/* The indices ascend: moving each kept vertex down never overwrites one still to move. */
	for (int i = 0; i < solution.count; ++i)
	{
		int from = solution.index[i];
		if (from != i)
		{
			simplex->v[i] = simplex->v[from];
			size[i] = size[from];
		}
		simplex->lambda[i] = solution.lambda[i];
	}
	simplex->count = solution.count;
	*v = solution.v;
	/* The edge and face constructions vanish only with the origin (nearly) on the simplex's line
	 * or plane, where -v is as good a direction as any. */
	*direction = cd3Dot(solution.direction, solution.v) < CD_R(0.0) ? solution.direction : cd3Neg(solution.v);
	return LEAN_SOLVED;
}

/* The largest |coordinate| of a vertex's support points a and b: the scale of the tolerances,
 * and (w = a - b being at most twice as large) of the lean solver's range. */
static cdReal VertexSize(const GjkVertex* vertex)
{
	return cdMax(MaxAbsComponent(vertex->a), MaxAbsComponent(vertex->b));
}

/* For a triangle simplex whose next support repeats one of its vertices: a support along the
 * triangle's normal, either way (the origin's side first), that lies beyond the triangle's plane
 * by more than the round-off of its points. Sets *direction and the support's indices and returns
 * true when there is one. */
static bool FaceNormalSupport(const cd3Core* a, const cd3Core* b, const GjkSimplex* simplex, cdReal size,
							  cd3Vec* direction, int* indexA, int* indexB)
{
	cd3Vec w0 = simplex->v[0].w;
	cd3Vec normal = cd3Cross(cd3Sub(simplex->v[1].w, w0), cd3Sub(simplex->v[2].w, w0));
	cdReal length = cd3Length(normal);
	if (!(length > CD_R(0.0)))
	{
		return false;
	}
	normal = cd3Scale(CD_R(1.0) / length, normal);
	if (cd3Dot(normal, w0) > CD_R(0.0))
	{
		normal = cd3Neg(normal); /* towards the origin's side of the plane */
	}
	for (int side = 0; side < 2; ++side)
	{
		cd3Vec d = side == 0 ? normal : cd3Neg(normal);
		int ia = cd3CoreSupport(a, d), ib = cd3CoreSupport(b, cd3Neg(d));
		bool repeated = false;
		for (int i = 0; i < 3; ++i)
		{
			repeated = repeated || (simplex->v[i].indexA == ia && simplex->v[i].indexB == ib);
		}
		cd3Vec w = cd3Sub(cd3CorePoint(a, ia), cd3CorePoint(b, ib));
		cdReal roundOff = GJK_TOUCH_TOLERANCE * cdMax(size, cdMax(MaxAbsComponent(cd3CorePoint(a, ia)),
																  MaxAbsComponent(cd3CorePoint(b, ib))));
		if (!repeated && cd3Dot(d, cd3Sub(w, w0)) > roundOff)
		{
			*direction = d;
			*indexA = ia;
			*indexB = ib;
			return true;
		}
	}
	return false;
}

/* Closest points of the cores of a and b; *touching is set when the cores overlap (then
 * *pointA and *pointB coincide up to round-off). Warm-started from *cache when it is usable, and
 * writes the final simplex back to it (cache may be NULL). */
static int GjkCores(const cd3Core* a, const cd3Core* b, cd3SimplexCache* cache, cdReal overlapRadius,
					cd3Vec* pointA, cd3Vec* pointB, bool* touching, bool* hitIterationCap)
{
	bool overlapQuery = overlapRadius >= CD_R(0.0);
	GjkSimplex simplex;
	memset(&simplex, 0, sizeof(simplex));
	bool cached = ReadCache(cache, a, b, &simplex);
	if (!cached)
	{
		/* A cold start from the supports along the line between the cores' centres (or first
		 * points) is usually a step or two closer than an arbitrary pair of points. */
		cd3Vec toB = cd3Sub(cd3CoreCenter(b), cd3CoreCenter(a));
		bool usable = cd3LengthSquared(toB) > CD_R(0.0);
		simplex.count = 1;
		simplex.v[0] = MakeVertex(a, b, usable ? cd3CoreSupport(a, toB) : 0,
								  usable ? cd3CoreSupport(b, cd3Neg(toB)) : 0);
		simplex.lambda[0] = CD_R(1.0);
	}
	cdReal size[4];
	for (int i = 0; i < simplex.count; ++i)
	{
		size[i] = VertexSize(&simplex.v[i]);
	}

	/* Round-off can make a step gain nothing (or lose a little) while the next ones still gain:
	 * keep the closest simplex seen, and stop after a few steps without progress. */
	GjkSimplex best;
	best.count = 0;
	cdReal bestDistanceSquared = CD_REAL_MAX;
	int stalls = 0;
	*touching = false;
	/* The lean solver needs to know the newest vertex: not on a cached simplex. */
	bool leanApplies = !cached;
	/* The largest vertex size of the simplex about to be solved: that of the last solve's simplex
	 * and of the vertex appended to it (set at each append; the lean path runs only after one).
	 * Kept as it goes: a loop over the simplex's changing count mispredicted its exit. */
	cdReal appendedSize = CD_R(0.0);
	bool normalTried = false;
	int iteration = 0;
	for (; iteration < GJK_MAX_ITERATIONS; ++iteration)
	{
		cd3Vec v, direction;
		bool solved = false;
		if (simplex.count == 1)
		{
			simplex.lambda[0] = CD_R(1.0);
			v = simplex.v[0].w;
			direction = cd3Neg(v);
			solved = true;
		}
		else if (leanApplies)
		{
			if (appendedSize <= GJK_LEAN_HIGH && appendedSize >= GJK_LEAN_LOW)
			{
				LeanStatus status = SolveLean(&simplex, size, bestDistanceSquared, &v, &direction);
				if (status == LEAN_ENCLOSED && overlapQuery)
				{
					*touching = true; /* no weights needed for a yes */
					break;
				}
				solved = status == LEAN_SOLVED;
			}
		}
		if (!solved)
		{
			/* A segment and the vertex just appended to it, kept for the direction below. */
			bool fromSegment = appendedSize > CD_R(0.0) && simplex.count == 3;
			GjkSimplex triangle;
			if (fromSegment)
			{
				triangle.count = 3;
				for (int i = 0; i < 3; ++i)
				{
					triangle.v[i] = simplex.v[i];
				}
			}
			if (SolveSimplex(&simplex))
			{
				*touching = true;
				break;
			}
			for (int i = 0; i < simplex.count; ++i)
			{
				size[i] = VertexSize(&simplex.v[i]);
			}
			v = simplex.count == 3 ? FacePoint(&simplex) : SimplexPoint(&simplex);
			/* The new vertex dropped again (round-off: in exact arithmetic it belongs to the next
			 * simplex) leaves the segment, its direction and its support as they were, and GJK
			 * stalls. That happens when the new vertex is far out compared with the gain it
			 * brings: a hull 7e9 across whose face through the point ran between a vertex
			 * next to it and two far ones, the point 1.29 from the near edge (double build).
			 * The triangle's normal then points at the face the support plane has not seen. */
			bool dropped =
				fromSegment && simplex.count == 2 &&
				!(simplex.v[1].indexA == triangle.v[2].indexA && simplex.v[1].indexB == triangle.v[2].indexB);
			direction = SearchDirection(dropped ? &triangle : &simplex, v);
		}
		cdReal distanceSquared = cd3LengthSquared(v);
		/* The largest coordinate of the support points, as the documented tolerance reads (16
		 * epsilon of the largest coordinate involved): |w| = |a - b| can be 2 sqrt(3) times
		 * larger and would call shapes that far apart touching. */
		cdReal simplexSize = size[0];
		for (int i = 1; i < simplex.count; ++i)
		{
			simplexSize = cdMax(simplexSize, size[i]);
		}
		cdReal touch = GJK_TOUCH_TOLERANCE * simplexSize;
		if (distanceSquared <= touch * touch)
		{
			*touching = true;
			break;
		}
		/* An overlap query stops as soon as a point of the cores' difference lies within the
		 * radii (and the touching tolerance) of the origin. */
		if (overlapQuery && distanceSquared <= (overlapRadius + touch) * (overlapRadius + touch))
		{
			*touching = true;
			break;
		}
		if (distanceSquared < bestDistanceSquared)
		{
			/* Three vertices, live or not, in a copy of fixed size (a whole-struct copy each step,
			 * or one of the live vertices only, went through memcpy calls: a tenth of the time). */
			best.count = simplex.count;
			for (int i = 0; i < 3; ++i)
			{
				best.v[i] = simplex.v[i];
				best.lambda[i] = simplex.lambda[i];
			}
			bestDistanceSquared = distanceSquared;
			stalls = 0;
		}
		else if (++stalls > GJK_MAX_STALLS)
		{
			break;
		}

		int indexA = cd3CoreSupport(a, direction);
		int indexB = cd3CoreSupport(b, cd3Neg(direction));
		/* Against the (at most three) vertices without a branch per vertex: the slots past the count
		 * hold defined, masked-out values (the simplex starts zeroed). */
		int duplicate = 0;
		for (int i = 0; i < 3; ++i)
		{
			duplicate |=
				(i < simplex.count) & (simplex.v[i].indexA == indexA) & (simplex.v[i].indexB == indexB);
		}
		if (duplicate)
		{
			/* A triangle whose plane passes through the origin within round-off: -v is round-off,
			 * and its support can repeat a vertex although the cores' difference reaches beyond
			 * the plane (the origin deep inside it: a triangle's corner on a hull's vertex makes
			 * a point of the difference at the origin). Once per call, when the triangle is that
			 * close, the plane's normal, the origin's side first, looks for a vertex beyond the
			 * plane by more than round-off. */
			cdReal nearOrigin = GJK_FACE_NORMAL_BAND * touch;
			if (simplex.count != 3 || normalTried || distanceSquared > nearOrigin * nearOrigin ||
				!FaceNormalSupport(a, b, &simplex, simplexSize, &direction, &indexA, &indexB))
			{
				break;
			}
			normalTried = true;
		}
		/* Built in place, in the free slot after the simplex's vertices (at most three remain
		 * after a solve that does not enclose the origin). */
		GjkVertex* vertex = &simplex.v[simplex.count];
		vertex->indexA = indexA;
		vertex->indexB = indexB;
		vertex->a = cd3CorePoint(a, indexA);
		vertex->b = cd3CorePoint(b, indexB);
		vertex->w = cd3Sub(vertex->a, vertex->b);
		cdReal vertexSize = VertexSize(vertex);
		/* The support plane bounds the distance from below, |v| from above: stop when they meet
		 * within GJK_GAP_TOLERANCE of |v| plus the round-off of the support values
		 * (GJK_GAP_ROUNDOFF of the largest coordinate of the support points). Below that the
		 * bound cannot tell support points apart: without it, pairs near contact (a gap far below
		 * their size) stepped between ties until stalled. In double, where the squares and
		 * products of any float range fit. */
		double lowerTimesLength = -(double)cd3Dot(direction, vertex->w);
		double directionX = (double)direction.x, directionY = (double)direction.y,
			   directionZ = (double)direction.z;
		double directionLength =
			sqrt(directionX * directionX + directionY * directionY + directionZ * directionZ);
		double enough = directionLength * (sqrt((double)distanceSquared) * (1.0 - (double)GJK_GAP_TOLERANCE) -
										   (double)GJK_GAP_ROUNDOFF * (double)cdMax(simplexSize, vertexSize));
		if (lowerTimesLength > 0.0 && lowerTimesLength >= enough)
		{
			break;
		}
		/* ... and as soon as a support plane keeps the cores farther apart than that: the
		 * closest simplex so far then lies beyond it too, and the caller's test says no. */
		if (overlapQuery && lowerTimesLength > directionLength * ((double)overlapRadius +
																  (double)GJK_TOUCH_TOLERANCE *
																	  (double)cdMax(simplexSize, vertexSize)))
		{
			break;
		}
		simplex.lambda[simplex.count] = CD_R(0.0);
		size[simplex.count] = vertexSize;
		appendedSize = cdMax(simplexSize, vertexSize);
		++simplex.count;
		leanApplies = true;
	}
	/* Every convergence test leaves the loop by break: running off its end is the cap. */
	*hitIterationCap = iteration == GJK_MAX_ITERATIONS;
	if (!*touching && best.count > 0)
	{
		simplex = best;
	}
	WriteCache(cache, &simplex);

	cd3Vec pa = CD3_VEC_ZERO, pb = CD3_VEC_ZERO;
	for (int i = 0; i < simplex.count; ++i)
	{
		pa = cd3MulAdd(pa, simplex.lambda[i], simplex.v[i].a);
		pb = cd3MulAdd(pb, simplex.lambda[i], simplex.v[i].b);
	}
	*pointA = pa;
	*pointB = pb;
	return *hitIterationCap ? iteration : iteration + 1;
}

static cd3ClosestPoints Touching(cd3Vec point)
{
	cd3ClosestPoints result = {point, point, CD_R(0.0)};
	return result;
}

/* Half-space (dot(n, x) <= offset) against a finite shape given by its core. */
static cd3ClosestPoints DistancePlaneCore(cd3Plane plane, const cd3Core* core)
{
	cd3Vec n = plane.normal;
	cd3Vec deepest = cd3MulSub(cd3CorePoint(core, cd3CoreSupport(core, cd3Neg(n))), core->radius, n);
	cdReal separation = cd3Dot(n, deepest) - plane.offset;
	if (separation <= CD_R(0.0))
	{
		return Touching(deepest);
	}
	cd3ClosestPoints result = {cd3MulSub(deepest, separation, n), deepest, separation};
	return result;
}

/* Two half-spaces meet unless cd3HalfSpacesApart (support3.h, shared with the overlap test) says
 * otherwise; then a common point, built so that its residuals stay at the round-off of its own
 * coordinates. Nearly parallel normals (cosine >= 1/2) take t * a.normal with t = min(a.offset,
 * b.offset / cosine), in both by construction; nearly opposite ones the middle of the slab
 * between them on the line of a.normal when there is one. Otherwise the point a.offset *
 * a.normal of a's boundary moves along that boundary, in the direction w perpendicular to
 * a.normal that b.normal points against, until it reaches b's boundary. The former 2x2 solve
 * for the line where the boundaries meet cancelled terms of size gap / sine^2 and, for nearly
 * parallel or opposite normals, landed far outside both. */
static cd3ClosestPoints DistancePlanePlane(cd3Plane a, cd3Plane b)
{
	cdReal gap;
	if (cd3HalfSpacesApart(a, b, &gap))
	{
		cd3ClosestPoints result = {cd3Scale(a.offset, a.normal), cd3Scale(a.offset + gap, a.normal), gap};
		return result;
	}
	cdReal c = cd3Dot(a.normal, b.normal);
	if (c >= CD_R(0.5))
	{
		return Touching(cd3Scale(cdMin(a.offset, b.offset / c), a.normal));
	}
	cdReal sineSquared = cd3LengthSquared(cd3Cross(a.normal, b.normal));
	if (c <= CD_R(-0.5))
	{
		/* x = t * a.normal is in both when b.offset / c <= t <= a.offset; opposite normals that
		 * touch within the tolerance take the middle of their gap. */
		cdReal lower = b.offset / c;
		if (lower <= a.offset || sineSquared <= CD3_OPPOSITE_SINE_LIMIT * CD3_OPPOSITE_SINE_LIMIT)
		{
			return Touching(cd3Scale(CD_R(0.5) * (lower + a.offset), a.normal));
		}
	}
	cd3Vec start = cd3Scale(a.offset, a.normal);
	cdReal needed = cd3Dot(b.normal, start) - b.offset;
	if (needed <= CD_R(0.0))
	{
		return Touching(start);
	}
	/* w: made perpendicular to a.normal once more after normalizing, so that moving along it
	 * leaves a's boundary by round-off only; b.normal . w is about -sine, below -16 epsilon. */
	cd3Vec w = cd3Normalize(cd3MulSub(cd3Scale(c, a.normal), CD_R(1.0), b.normal));
	w = cd3Normalize(cd3MulSub(w, cd3Dot(a.normal, w), a.normal));
	cdReal approach = -cd3Dot(b.normal, w);
	if (!(approach > CD_R(0.0)))
	{
		return Touching(start); /* unreachable for normals that are not opposite */
	}
	return Touching(cd3MulAdd(start, needed / approach, w));
}

static cd3ClosestPoints Swap(cd3ClosestPoints result)
{
	cd3ClosestPoints swapped = {result.pointB, result.pointA, result.distance};
	return swapped;
}

cd3ClosestPoints cd3Distance(const cd3Shape* a, const cd3Shape* b)
{
	return cd3DistanceCached(a, b, NULL, NULL);
}

cd3ClosestPoints cd3DistanceWithStatus(const cd3Shape* a, const cd3Shape* b, cdDistanceStatus* status)
{
	return cd3DistanceCached(a, b, NULL, status);
}

/* The closest points of the shapes from those of their cores (radiusA, radiusB around them). */
static cd3ClosestPoints AddRadiusValues(cd3Vec pointA, cd3Vec pointB, bool touching, cdReal radiusA,
										cdReal radiusB)
{
	cd3ClosestPoints result;
	cdReal radius = radiusA + radiusB;
	cd3Vec delta = cd3Sub(pointB, pointA);
	cdReal coreDistance = cd3Length(delta);
	if (touching)
	{
		result = Touching(pointA);
	}
	else if (coreDistance <= radius)
	{
		/* Only the rounded parts overlap: this point is within rA of pointA and rB of pointB. */
		cdReal t = radius > CD_R(0.0) ? radiusA / radius : CD_R(0.0);
		result = Touching(cd3MulAdd(pointA, t, delta));
	}
	else
	{
		cd3Vec normal = cd3Scale(CD_R(1.0) / coreDistance, delta);
		result.pointA = cd3MulAdd(pointA, radiusA, normal);
		result.pointB = cd3MulSub(pointB, radiusB, normal);
		result.distance = coreDistance - radius;
	}
	return result;
}

static cd3ClosestPoints AddRadii(const cd3Core* coreA, const cd3Core* coreB, cd3Vec pointA, cd3Vec pointB,
								 bool touching)
{
	return AddRadiusValues(pointA, pointB, touching, coreA->radius, coreB->radius);
}

/* Closed-form distances: the pair table's Distance column (pairs3.h) when it names a function
 * instead of GJK. Each gives GJK's answer on the pair's cores bit for bit (test_distance3 checks
 * it) without building the cores: two spheres are two points, whose closest points are
 * themselves. */
static cd3ClosestPoints DistanceSphereSphere(cd3Sphere a, cd3Sphere b)
{
	/* GJK's one-vertex simplex: its touching test (relative to the larger centre), and its
	 * closest points as weighted sums from zero (0 + 1 * centre, which turns -0 into +0). */
	cd3Vec w = cd3Sub(a.center, b.center);
	cdReal touch = GJK_TOUCH_TOLERANCE * cdMax(MaxAbsComponent(a.center), MaxAbsComponent(b.center));
	bool touching = cd3LengthSquared(w) <= touch * touch;
	cd3Vec pointA = cd3MulAdd(CD3_VEC_ZERO, CD_R(1.0), a.center);
	cd3Vec pointB = cd3MulAdd(CD3_VEC_ZERO, CD_R(1.0), b.center);
	return AddRadiusValues(pointA, pointB, touching, a.radius, b.radius);
}

cd3ClosestPoints cd3DistanceCores(const cd3Core* coreA, const cd3Core* coreB, cd3SimplexCache* cache,
								  cdDistanceStatus* status)
{
	cd3Vec pointA, pointB;
	bool touching, hitIterationCap;
	int iterations = GjkCores(coreA, coreB, cache, CD_R(-1.0), &pointA, &pointB, &touching, &hitIterationCap);
	if (status != NULL)
	{
		status->iterations = iterations;
		status->hitIterationCap = hitIterationCap;
	}
	return AddRadii(coreA, coreB, pointA, pointB, touching);
}

cd3ClosestPoints cd3DistanceCached(const cd3Shape* a, const cd3Shape* b, cd3SimplexCache* cache,
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
#define CD3_DISTANCE_CASE(A, B, Distance)                                                                    \
	if (a->type == CD3_TYPE_##A && b->type == CD3_TYPE_##B)                                                  \
	{                                                                                                        \
		return Distance(CD3_SHAPE_ARG(A, a), CD3_SHAPE_ARG(B, b));                                           \
	}                                                                                                        \
	if (CD3_TYPE_##A != CD3_TYPE_##B && a->type == CD3_TYPE_##B && b->type == CD3_TYPE_##A)                  \
	{                                                                                                        \
		return Swap(Distance(CD3_SHAPE_ARG(A, b), CD3_SHAPE_ARG(B, a)));                                     \
	}
#define CD3_DISTANCE_ROW(A, B, Overlap, Distance, Collide)                                                   \
	CD_PAIR_CLOSED(Distance, CD3_DISTANCE_CASE)(A, B, Distance)
		CD3_PAIR_TABLE(CD3_DISTANCE_ROW)
		CD3_HULL_PAIR_TABLE(CD3_DISTANCE_ROW)
#undef CD3_DISTANCE_ROW
#undef CD3_DISTANCE_CASE
	}
	cd3Core coreA, coreB;
	bool finiteA = cd3MakeCore(a, &coreA);
	bool finiteB = cd3MakeCore(b, &coreB);
	if (!finiteA || !finiteB)
	{
		if (a->type == CD3_SHAPE_PLANE && b->type == CD3_SHAPE_PLANE)
		{
			return DistancePlanePlane(a->plane, b->plane);
		}
		if (a->type == CD3_SHAPE_PLANE && finiteB)
		{
			return DistancePlaneCore(a->plane, &coreB);
		}
		if (b->type == CD3_SHAPE_PLANE && finiteA)
		{
			return Swap(DistancePlaneCore(b->plane, &coreA));
		}
		CD_ASSERT(false);
		cd3ClosestPoints none = {CD3_VEC_ZERO, CD3_VEC_ZERO, CD_REAL_MAX};
		return none;
	}
	return cd3DistanceCores(&coreA, &coreB, cache, status);
}

/* Overlap decided from closest points: touching within CD3_GJK_OVERLAP_TOLERANCE of the largest
 * coordinate of the points, the round-off of the support points (as in the other rotated tests,
 * docs/API.md). */
static bool OverlapFromClosestPoints(cd3ClosestPoints r)
{
	if (r.distance <= CD_R(0.0))
	{
		return true;
	}
	cdReal magnitude = cdMax(MaxAbsComponent(r.pointA), MaxAbsComponent(r.pointB));
	return r.distance <= CD3_GJK_OVERLAP_TOLERANCE * magnitude;
}

bool cd3OverlapGjk(const cd3Shape* a, const cd3Shape* b)
{
	CD_ASSERT(a != NULL && b != NULL);
	cd3Core coreA, coreB;
	if (!cd3MakeCore(a, &coreA) || !cd3MakeCore(b, &coreB))
	{
		return OverlapFromClosestPoints(cd3Distance(a, b)); /* a half-space: closed form */
	}
	/* GJK stops at the first point of the cores' difference within the radii (yes) or the first
	 * support plane beyond them (no); the decision on the points it returns is then the one the
	 * full distance would give, away from the touching tolerance. */
	cd3Vec pointA, pointB;
	bool touching, hitIterationCap;
	GjkCores(&coreA, &coreB, NULL, coreA.radius + coreB.radius, &pointA, &pointB, &touching,
			 &hitIterationCap);
	return touching || OverlapFromClosestPoints(AddRadii(&coreA, &coreB, pointA, pointB, false));
}
