/* collide: GJK (boolean) followed by the expanding polytope algorithm. The EPA polytope lives in
 * fixed arrays; its horizon is found by collecting the edges of the faces the new support point
 * sees that belong to only one of them. */
#include "epa3.h"

#include "sat3_support.h"
#include "wide3.h"

#include <math.h>

#define MAX_VERTICES (CD3_EPA_MAX_ITERATIONS + 8)
#define MAX_FACES (2 * MAX_VERTICES)
#define MAX_HORIZON (3 * MAX_FACES)

typedef struct Vertex
{
	cd3Vec w, a, b; /* w = a - b */
} Vertex;

typedef struct Face
{
	int v[3];
	cd3Vec normal;
	cdReal distance;
} Face;

cd3Vec cd3PolytopeSupport(const void* polytope, cd3Vec direction)
{
	const cd3Polytope* p = (const cd3Polytope*)polytope;
	cd3Vec local = cd3InvRotateVector(p->transform.q, direction);
	int best = cd3SupportIndex(p->vertices, p->vertexCount, local);
	return cd3TransformPoint(p->transform, p->vertices[best]);
}

/* Two polytopes (the common case) are worked on in A's frame: A's support is a bare scan, B's
 * takes one rotation by the relative matrix each way; the answer goes back to world space at the
 * end. Other shapes go through their support functions in world space. */
typedef struct Context
{
	const void* a;
	const void* b;
	cd3SupportFcn* supportA;
	cd3SupportFcn* supportB;
	const cd3Polytope* polytopeA; /* both set: the polytope path */
	const cd3Polytope* polytopeB;
	cd3Mat33 rotationB; /* B local -> A local */
	cd3Vec translationB;
	const cd3SoaPoints* pointsA; /* both set: A's points and B's (in A's frame) as arrays */
	const cd3SoaPoints* pointsB;
} Context;

static Vertex Support(const Context* c, cd3Vec d)
{
	Vertex v;
	if (c->pointsA != NULL)
	{
		v.a = cd3SoaPoint(c->pointsA, cd3SoaSupportIndex(c->pointsA, d));
		v.b = cd3SoaPoint(c->pointsB, cd3SoaSupportIndex(c->pointsB, cd3Neg(d)));
	}
	else if (c->polytopeA != NULL)
	{
		const cd3Polytope* pa = c->polytopeA;
		const cd3Polytope* pb = c->polytopeB;
		v.a = pa->vertices[cd3SupportIndex(pa->vertices, pa->vertexCount, d)];
		cd3Vec inB = cd3Neg(cd3MulMTV(c->rotationB, d));
		cd3Vec vb = pb->vertices[cd3SupportIndex(pb->vertices, pb->vertexCount, inB)];
		v.b = cd3Add(cd3MulMV(c->rotationB, vb), c->translationB);
	}
	else
	{
		v.a = c->supportA(c->a, d);
		v.b = c->supportB(c->b, cd3Neg(d));
	}
	v.w = cd3Sub(v.a, v.b);
	return v;
}

/* ---- GJK for intersection: the simplex nearest the origin, the search direction toward it ---- */

static bool SameDirection(cd3Vec a, cd3Vec b)
{
	return cd3Dot(a, b) > CD_R(0.0);
}

/* Reduces the simplex to the feature nearest the origin and sets the next direction; true when the
 * tetrahedron contains the origin. */
static bool DoSimplex(Vertex* s, int* count, cd3Vec* d)
{
	if (*count == 2)
	{
		cd3Vec ab = cd3Sub(s[0].w, s[1].w), ao = cd3Neg(s[1].w);
		if (SameDirection(ab, ao))
		{
			*d = cd3Cross(cd3Cross(ab, ao), ab);
		}
		else
		{
			s[0] = s[1];
			*count = 1;
			*d = ao;
		}
		return false;
	}
	if (*count == 3)
	{
		Vertex A = s[2], B = s[1], C = s[0];
		cd3Vec ab = cd3Sub(B.w, A.w), ac = cd3Sub(C.w, A.w), ao = cd3Neg(A.w);
		cd3Vec abc = cd3Cross(ab, ac);
		if (SameDirection(cd3Cross(abc, ac), ao))
		{
			if (SameDirection(ac, ao))
			{
				s[0] = C;
				s[1] = A;
				*count = 2;
				*d = cd3Cross(cd3Cross(ac, ao), ac);
			}
			else
			{
				s[0] = B;
				s[1] = A;
				*count = 2;
				return DoSimplex(s, count, d);
			}
		}
		else if (SameDirection(cd3Cross(ab, abc), ao))
		{
			s[0] = B;
			s[1] = A;
			*count = 2;
			return DoSimplex(s, count, d);
		}
		else if (SameDirection(abc, ao))
		{
			*d = abc;
		}
		else
		{
			s[0] = B;
			s[1] = C;
			s[2] = A;
			*d = cd3Neg(abc);
		}
		return false;
	}
	/* Tetrahedron: s[3] is the newest point. */
	Vertex A = s[3], B = s[2], C = s[1], D = s[0];
	cd3Vec ao = cd3Neg(A.w);
	cd3Vec ab = cd3Sub(B.w, A.w), ac = cd3Sub(C.w, A.w), ad = cd3Sub(D.w, A.w);
	cd3Vec abc = cd3Cross(ab, ac), acd = cd3Cross(ac, ad), adb = cd3Cross(ad, ab);
	/* Orient each face normal away from the opposite vertex. */
	if (SameDirection(abc, ad))
	{
		abc = cd3Neg(abc);
	}
	if (SameDirection(acd, ab))
	{
		acd = cd3Neg(acd);
	}
	if (SameDirection(adb, ac))
	{
		adb = cd3Neg(adb);
	}
	if (SameDirection(abc, ao))
	{
		s[0] = C;
		s[1] = B;
		s[2] = A;
		*count = 3;
		return DoSimplex(s, count, d);
	}
	if (SameDirection(acd, ao))
	{
		s[0] = D;
		s[1] = C;
		s[2] = A;
		*count = 3;
		return DoSimplex(s, count, d);
	}
	if (SameDirection(adb, ao))
	{
		s[0] = B;
		s[1] = D;
		s[2] = A;
		*count = 3;
		return DoSimplex(s, count, d);
	}
	return true;
}

/* ---- EPA ------------------------------------------------------------------------------------- */

/* A face of the expanding polytope, its normal pointing away from `inside`, a point strictly
 * inside the polytope (the first tetrahedron's centroid: the polytope only grows). Orienting by
 * the origin instead failed when the origin lies on a face (two hulls whose first GJK segment
 * passed exactly through it, 2e-4 across in float): a face at distance 0 kept an inward normal
 * and EPA cycled to its cap. The distance of the origin may then be 0 or, for a blown-up
 * simplex whose origin lies outside, negative. */
/* The edge from vertex p to vertex q of the difference from the support points, (a_q - a_p) -
 * (b_q - b_p): exact to the round-off of the shapes' own edges, where w_q - w_p of two vertices
 * far out along a needle keeps only that of |w| (distance3.c, SolverInput). */
static WideVec VertexEdge(const Vertex* p, const Vertex* q)
{
	return WideSub(WideSub(Widen(q->a), Widen(p->a)), WideSub(Widen(q->b), Widen(p->b)));
}

/* The normal is the cross product of the face's two shorter edges (they meet at its largest
 * angle; on a needle's sliver faces the two long ones cancel), in double whatever cdReal is, and
 * the distance is taken at the vertex where they meet. A face whose angle at vertex i is not
 * small (sine above 1e-3) keeps the cheaper product of the vertices' differences from i. */
static bool MakeFace(const Vertex* v, int i, int j, int k, cd3Vec inside, Face* f)
{
	cd3Vec dj = cd3Sub(v[j].w, v[i].w), dk = cd3Sub(v[k].w, v[i].w);
	cd3Vec quick = cd3Cross(dj, dk);
	double quickSquared = (double)cd3LengthSquared(quick);
	if (quickSquared > 1e-6 * (double)cd3LengthSquared(dj) * (double)cd3LengthSquared(dk) &&
		quickSquared < INFINITY)
	{
		cd3Vec n = cd3Scale(CD_R(1.0) / cd3Length(quick), quick);
		f->v[0] = i;
		f->v[1] = j;
		f->v[2] = k;
		if (cd3Dot(n, cd3Sub(v[i].w, inside)) < CD_R(0.0))
		{
			f->v[1] = k;
			f->v[2] = j;
			n = cd3Neg(n);
		}
		f->normal = n;
		f->distance = cd3Dot(n, v[i].w);
		return true;
	}
	WideVec eij = VertexEdge(&v[i], &v[j]), eik = VertexEdge(&v[i], &v[k]), ejk = VertexEdge(&v[j], &v[k]);
	double lij = WideDot(eij, eij), lik = WideDot(eik, eik), ljk = WideDot(ejk, ejk);
	/* Each is (w_j - w_i) x (w_k - w_i). */
	WideVec wide;
	int base;
	if (ljk >= lij && ljk >= lik)
	{
		wide = WideCross(eij, eik);
		base = i;
	}
	else if (lik >= lij)
	{
		wide = WideCross(eij, ejk);
		base = j;
	}
	else
	{
		wide = WideCross(eik, ejk);
		base = k;
	}
	double length = sqrt(WideDot(wide, wide));
	if (!(length > 0.0) || !(length < INFINITY))
	{
		return false;
	}
	cd3Vec n = Narrow(WideScale(1.0 / length, wide));
	f->v[0] = i;
	f->v[1] = j;
	f->v[2] = k;
	if (cd3Dot(n, cd3Sub(v[base].w, inside)) < CD_R(0.0))
	{
		f->v[1] = k;
		f->v[2] = j;
		n = cd3Neg(n);
	}
	cdReal distance = cd3Dot(n, v[base].w);
	f->normal = n;
	f->distance = distance;
	return true;
}

/* Barycentric coordinates of p's projection on the plane of triangle a-b-c (vertex a when the
 * triangle is degenerate). Measured from the vertex where the two shorter edges meet, along
 * them (in double whatever cdReal is): EPA's faces on a needle are slivers, and the former
 * normal equations from one vertex (a Gram determinant of its two edges, a difference of
 * products of squared lengths) cancelled to nothing in float on a sliver 2e9 long and 1.4e5 wide
 * and sent both witnesses to the needle's far end, 5e8 from the contact. */
static void Barycentric(cd3Vec a, cd3Vec b, cd3Vec c, cd3Vec p, cdReal* u, cdReal* v, cdReal* w)
{
	WideVec x[3] = {Widen(a), Widen(b), Widen(c)};
	WideVec e01 = WideSub(x[1], x[0]), e02 = WideSub(x[2], x[0]), e12 = WideSub(x[2], x[1]);
	double l01 = WideDot(e01, e01), l02 = WideDot(e02, e02), l12 = WideDot(e12, e12);
	int base = l12 >= l01 && l12 >= l02 ? 0 : (l02 >= l01 ? 1 : 2);
	int next = base == 2 ? 0 : base + 1, previous = base == 0 ? 2 : base - 1;
	WideVec ei = WideSub(x[next], x[base]), ej = WideSub(x[previous], x[base]);
	WideVec n = WideCross(ei, ej);
	double normalSquared = WideDot(n, n);
	if (!(normalSquared > 0.0))
	{
		*u = CD_R(1.0);
		*v = CD_R(0.0);
		*w = CD_R(0.0);
		return;
	}
	WideVec o = WideSub(Widen(p), x[base]);
	double weights[3];
	weights[next] = WideDot(n, WideCross(o, ej)) / normalSquared;
	weights[previous] = WideDot(n, WideCross(ei, o)) / normalSquared;
	weights[base] = 1.0 - weights[next] - weights[previous];
	*u = (cdReal)weights[0];
	*v = (cdReal)weights[1];
	*w = (cdReal)weights[2];
}

/* GJK and EPA in the context's frame. */
static cd3Penetration Run(const Context* c)
{
	cd3Penetration out;
	out.overlapping = false;
	out.depth = CD_R(0.0);
	out.normal = cd3MakeVec(CD_R(0.0), CD_R(1.0), CD_R(0.0));
	out.pointA = out.pointB = cd3MakeVec(CD_R(0.0), CD_R(0.0), CD_R(0.0));
	out.iterations = 0;
	out.hitIterationCap = false;
	out.gap = CD_R(0.0);

	Vertex simplex[4];
	int count = 1;
	cd3Vec d = cd3MakeVec(CD_R(1.0), CD_R(0.0), CD_R(0.0));
	simplex[0] = Support(c, d);
	d = cd3Neg(simplex[0].w);
	bool enclosed = false;
	int gjkIteration = 0;
	for (; gjkIteration < CD3_EPA_MAX_ITERATIONS; ++gjkIteration)
	{
		++out.iterations;
		if (cd3LengthSquared(d) == CD_R(0.0))
		{
			break; /* the origin is on the simplex: touching, or inside a flat simplex */
		}
		Vertex v = Support(c, d);
		cdReal reach = cd3Dot(v.w, d);
		if (reach < CD_R(0.0))
		{
			/* Separated along d: no point of A - B reaches past the plane w.d = reach. */
			out.gap = -reach / cd3Length(d);
			return out;
		}
		simplex[count++] = v;
		if (DoSimplex(simplex, &count, &d))
		{
			enclosed = true;
			break;
		}
	}
	out.overlapping = true;
	if (gjkIteration == CD3_EPA_MAX_ITERATIONS)
	{
		/* GJK cycled (round-off near a face of the Minkowski difference): the overlap answer is
		 * uncertain, said by the cap flag; the caller checks with a distance query. */
		out.hitIterationCap = true;
	}

	/* Blow a smaller simplex up to a tetrahedron with support points along the missing
	 * directions (the origin lies on the smaller simplex: the shapes touch or nearly so). */
	Vertex vertices[MAX_VERTICES];
	int vertexCount = count;
	for (int i = 0; i < count; ++i)
	{
		vertices[i] = simplex[i];
	}
	if (!enclosed || vertexCount < 4)
	{
		static const cdReal axes[6][3] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
										  {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
		for (int k = 0; k < 6 && vertexCount < 4; ++k)
		{
			Vertex v = Support(c, cd3MakeVec(axes[k][0], axes[k][1], axes[k][2]));
			bool fresh = true;
			for (int i = 0; i < vertexCount; ++i)
			{
				fresh = fresh && cd3VecDistance(vertices[i].w, v.w) > CD_R(0.0);
			}
			if (vertexCount >= 2)
			{
				cd3Vec e = cd3Sub(vertices[1].w, vertices[0].w);
				cd3Vec n = cd3Cross(e, cd3Sub(v.w, vertices[0].w));
				fresh = fresh && cd3LengthSquared(n) > CD_R(0.0);
				if (vertexCount == 3)
				{
					cd3Vec plane = cd3Cross(e, cd3Sub(vertices[2].w, vertices[0].w));
					fresh = fresh && cd3Dot(plane, cd3Sub(v.w, vertices[0].w)) != CD_R(0.0);
				}
			}
			if (fresh)
			{
				vertices[vertexCount++] = v;
			}
		}
		if (vertexCount < 4)
		{
			/* A flat Minkowski difference: no depth. */
			out.pointA = vertices[0].a;
			out.pointB = vertices[0].b;
			return out;
		}
	}

	Face faces[MAX_FACES];
	int faceCount = 0;
	static const int tetra[4][3] = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
	cd3Vec inside = cd3Scale(
		CD_R(0.25), cd3Add(cd3Add(vertices[0].w, vertices[1].w), cd3Add(vertices[2].w, vertices[3].w)));
	for (int i = 0; i < 4; ++i)
	{
		if (MakeFace(vertices, tetra[i][0], tetra[i][1], tetra[i][2], inside, &faces[faceCount]))
		{
			++faceCount;
		}
	}
	if (faceCount < 4)
	{
		out.pointA = vertices[0].a;
		out.pointB = vertices[0].b;
		return out;
	}
	/* A tetrahedron whose origin lies outside (a blown-up simplex) still converges: EPA expands
	 * toward the closest face either way. */
	int best = 0;
	for (int iteration = 0;; ++iteration)
	{
		best = 0;
		for (int i = 1; i < faceCount; ++i)
		{
			if (faces[i].distance < faces[best].distance)
			{
				best = i;
			}
		}
		if (iteration >= CD3_EPA_MAX_ITERATIONS || vertexCount >= MAX_VERTICES)
		{
			out.hitIterationCap = true;
			break;
		}
		++out.iterations;
		Face f = faces[best];
		Vertex w = Support(c, f.normal);
		cdReal gain = cd3Dot(f.normal, w.w) - f.distance;
		cdReal scale = cdMax(cd3Length(cd3Abs(w.w)), f.distance);
		if (gain <= CD_R(64.0) * CD_REAL_EPSILON * scale)
		{
			break; /* the face is a face of the Minkowski difference */
		}
		/* Remove the faces w sees; keep their edges that only one of them has (the horizon). */
		int horizon[MAX_HORIZON][2];
		int horizonCount = 0;
		int kept = 0;
		for (int i = 0; i < faceCount; ++i)
		{
			const Face* g = &faces[i];
			if (cd3Dot(g->normal, cd3Sub(w.w, vertices[g->v[0]].w)) > CD_R(0.0))
			{
				for (int e = 0; e < 3; ++e)
				{
					int p = g->v[e], q = g->v[(e + 1) % 3];
					int found = -1;
					for (int h = 0; h < horizonCount; ++h)
					{
						if (horizon[h][0] == q && horizon[h][1] == p)
						{
							found = h;
							break;
						}
					}
					if (found >= 0)
					{
						horizon[found][0] = horizon[horizonCount - 1][0];
						horizon[found][1] = horizon[horizonCount - 1][1];
						--horizonCount;
					}
					else if (horizonCount < MAX_HORIZON)
					{
						horizon[horizonCount][0] = p;
						horizon[horizonCount][1] = q;
						++horizonCount;
					}
				}
			}
			else
			{
				if (kept != i)
				{
					faces[kept] = *g;
				}
				++kept;
			}
		}
		faceCount = kept;
		int index = vertexCount++;
		vertices[index] = w;
		for (int h = 0; h < horizonCount && faceCount < MAX_FACES; ++h)
		{
			if (MakeFace(vertices, horizon[h][0], horizon[h][1], index, inside, &faces[faceCount]))
			{
				++faceCount;
			}
		}
		if (faceCount == 0)
		{
			faces[0] = f;
			faceCount = 1;
			break;
		}
	}
	Face f = faces[best < faceCount ? best : 0];
	out.depth = f.distance;
	out.normal = f.normal;
	cd3Vec p = cd3Scale(f.distance, f.normal);
	cdReal u, v, t;
	Barycentric(vertices[f.v[0]].w, vertices[f.v[1]].w, vertices[f.v[2]].w, p, &u, &v, &t);
	/* The closest plane can hold several faces (a facet of the difference split into triangles,
	 * at a tie in their distances), and the foot p of the perpendicular can lie in another one
	 * than the face taken: this one's weights then extrapolate and the witnesses land off the
	 * shapes (float: a segment 2e9 long through a hull at 1e9, the witness on the segment 2.8e8
	 * beyond its end). The face of the polytope whose plane passes within round-off of p and whose
	 * weights are the least negative gives them. */
	if (cdMin(u, cdMin(v, t)) < CD_R(0.0))
	{
		cdReal least = cdMin(u, cdMin(v, t));
		for (int i = 0; i < faceCount; ++i)
		{
			const Face* g = &faces[i];
			cd3Vec w0 = vertices[g->v[0]].w, w1 = vertices[g->v[1]].w, w2 = vertices[g->v[2]].w;
			cdReal scale = cdMax(cd3Length(w0), cdMax(cd3Length(w1), cd3Length(w2)));
			if (!(cdAbs(cd3Dot(g->normal, p) - g->distance) <= CD_R(64.0) * CD_REAL_EPSILON * scale))
			{
				continue;
			}
			cdReal gu, gv, gt;
			Barycentric(w0, w1, w2, p, &gu, &gv, &gt);
			cdReal smallest = cdMin(gu, cdMin(gv, gt));
			if (smallest > least)
			{
				least = smallest;
				f = *g;
				u = gu;
				v = gv;
				t = gt;
			}
		}
	}
	out.pointA = cd3Add(cd3Add(cd3Scale(u, vertices[f.v[0]].a), cd3Scale(v, vertices[f.v[1]].a)),
						cd3Scale(t, vertices[f.v[2]].a));
	out.pointB = cd3Add(cd3Add(cd3Scale(u, vertices[f.v[0]].b), cd3Scale(v, vertices[f.v[1]].b)),
						cd3Scale(t, vertices[f.v[2]].b));
	return out;
}

cd3Penetration cd3Epa(const void* a, cd3SupportFcn* supportA, const void* b, cd3SupportFcn* supportB)
{
	Context c;
	c.a = a;
	c.b = b;
	c.supportA = supportA;
	c.supportB = supportB;
	c.polytopeA = c.polytopeB = NULL;
	c.pointsA = c.pointsB = NULL;
	if (supportA != cd3PolytopeSupport || supportB != cd3PolytopeSupport)
	{
		return Run(&c);
	}
	c.polytopeA = (const cd3Polytope*)a;
	c.polytopeB = (const cd3Polytope*)b;
	cd3Transform rel = cd3InvMulTransforms(c.polytopeA->transform, c.polytopeB->transform);
	c.rotationB = cd3MakeMatFromQuat(rel.q);
	c.translationB = rel.p;
	cd3SoaPoints pointsA, pointsB;
	if (c.polytopeA->vertexCount <= CD3_SOA_MAX_POINTS && c.polytopeB->vertexCount <= CD3_SOA_MAX_POINTS)
	{
		cd3CopySoaPoints(&pointsA, c.polytopeA->vertices, c.polytopeA->vertexCount);
		cd3MakeSoaPoints(&pointsB, c.polytopeB->vertices, c.polytopeB->vertexCount, c.rotationB,
						 c.translationB);
		c.pointsA = &pointsA;
		c.pointsB = &pointsB;
	}
	cd3Penetration out = Run(&c);
	cd3Transform frame = c.polytopeA->transform;
	out.normal = cd3RotateVector(frame.q, out.normal);
	out.pointA = cd3TransformPoint(frame, out.pointA);
	out.pointB = cd3TransformPoint(frame, out.pointB);
	return out;
}
