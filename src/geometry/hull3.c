/* 3D convex hulls: quickhull in double precision on a triangulated surface, then triangles that
 * are coplanar within a tolerance are merged into convex polygons (Gregorius, "Implementing
 * Quickhull", GDC 2014, gives the reasons: slivers and near-coplanar faces are what breaks hulls).
 *
 * Why triangles first and merging afterwards: the triangulation is exact to double round-off,
 * far below the merge tolerance of a float hull, so every merge decision looks at a clean convex
 * surface; merged regions of a convex surface are discs, so their boundaries are simple loops. */
#include "collide/geometry3.h"

#include <string.h>

typedef struct HVec
{
	double x, y, z;
} HVec;

static HVec HMake(double x, double y, double z)
{
	HVec v = {x, y, z};
	return v;
}
static HVec HSub(HVec a, HVec b)
{
	return HMake(a.x - b.x, a.y - b.y, a.z - b.z);
}
static HVec HAdd(HVec a, HVec b)
{
	return HMake(a.x + b.x, a.y + b.y, a.z + b.z);
}
static HVec HScale(double s, HVec a)
{
	return HMake(s * a.x, s * a.y, s * a.z);
}
static double HDot(HVec a, HVec b)
{
	return a.x * b.x + a.y * b.y + a.z * b.z;
}
static HVec HCross(HVec a, HVec b)
{
	return HMake(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static double HLength(HVec a)
{
	return sqrt(HDot(a, a));
}
static HVec HNormalize(HVec a)
{
	double length = HLength(a);
	return length > 0.0 ? HScale(1.0 / length, a) : HMake(0.0, 0.0, 0.0);
}

/* Tolerances relative to the diagonal of the input's bounding box (see geometry3.h). */
#if CD_DOUBLE
/* Double input computed in double: round-off is of the input's own order, so the tolerances
 * keep three orders of magnitude above it (the float build keeps more, for free). */
#define HULL_BUILD_REL (1024.0 * DBL_EPSILON)
#define HULL_MERGE_REL (4096.0 * DBL_EPSILON)
#define HULL_WELD_REL (16384.0 * DBL_EPSILON)
#define HULL_VALID_REL (65536.0 * DBL_EPSILON)
#else
/* The triangulation runs in double on float input: its own tolerance can be tiny. */
#define HULL_BUILD_REL 1e-12
#define HULL_MERGE_REL (4.0 * (double)FLT_EPSILON)
#define HULL_WELD_REL (16.0 * (double)FLT_EPSILON)
#define HULL_VALID_REL (64.0 * (double)FLT_EPSILON)
#endif

static double cdMaxDouble(double a, double b)
{
	return a > b ? a : b;
}

/* ---- allocation ------------------------------------------------------------------------------- */

static void* AllocArray(size_t count, size_t size)
{
	return count == 0 ? NULL : cdAlloc(count * size);
}

/* ---- quickhull on triangles -------------------------------------------------------------------- */

typedef struct HFace
{
	int v[3];
	int adj[3]; /* face across edge v[i] -> v[(i + 1) % 3] */
	HVec normal;
	double offset;
	int conflict; /* first point of the conflict list, -1 when empty */
	int mark;	  /* visit stamp of the horizon search */
	bool visible;
	bool alive;
} HFace;

typedef struct Builder
{
	const HVec* p;
	int n;
	int* nextConflict;
	HFace* faces;
	int faceCount, faceCapacity;
	int* stack;
	int* visibleFaces;
	int* horizonFace;
	int* horizonEdge;
	int* startAt; /* per vertex: new face whose horizon edge starts there */
	int* endAt;
	int* newFaces;
	int scratchCapacity;
	double tol;
} Builder;

static bool GrowFaces(Builder* b, int extra)
{
	if (b->faceCount + extra <= b->faceCapacity)
	{
		return true;
	}
	int capacity = b->faceCapacity * 2;
	while (capacity < b->faceCount + extra)
	{
		capacity *= 2;
	}
	HFace* faces = (HFace*)AllocArray((size_t)capacity, sizeof(HFace));
	if (faces == NULL)
	{
		return false;
	}
	memcpy(faces, b->faces, (size_t)b->faceCount * sizeof(HFace));
	cdFree(b->faces);
	b->faces = faces;
	b->faceCapacity = capacity;
	return true;
}

/* Scratch arrays sized by the number of faces (stack, visible set, horizon). */
static bool GrowScratch(Builder* b, int needed)
{
	if (needed <= b->scratchCapacity)
	{
		return true;
	}
	int capacity = cdMaxInt(needed, 2 * b->scratchCapacity);
	int** arrays[] = {&b->stack, &b->visibleFaces, &b->horizonFace, &b->horizonEdge, &b->newFaces};
	for (int i = 0; i < 5; ++i)
	{
		int* grown = (int*)AllocArray((size_t)capacity, sizeof(int));
		if (grown == NULL)
		{
			return false;
		}
		cdFree(*arrays[i]);
		*arrays[i] = grown;
	}
	b->scratchCapacity = capacity;
	return true;
}

static void SetPlane(Builder* b, HFace* f)
{
	HVec a = b->p[f->v[0]], c1 = b->p[f->v[1]], c2 = b->p[f->v[2]];
	f->normal = HNormalize(HCross(HSub(c1, a), HSub(c2, a)));
	f->offset = (HDot(f->normal, a) + HDot(f->normal, c1) + HDot(f->normal, c2)) / 3.0;
}

static double FaceDistance(const Builder* b, const HFace* f, int point)
{
	return HDot(f->normal, b->p[point]) - f->offset;
}

static int AddFace(Builder* b, int v0, int v1, int v2)
{
	int index = b->faceCount++;
	HFace* f = &b->faces[index];
	f->v[0] = v0;
	f->v[1] = v1;
	f->v[2] = v2;
	f->adj[0] = f->adj[1] = f->adj[2] = -1;
	f->conflict = -1;
	f->mark = -1;
	f->visible = false;
	f->alive = true;
	SetPlane(b, f);
	return index;
}

/* Puts `point` on the conflict list of the face among `faces` it is farthest above (by more than
 * the tolerance); a point above none of them lies inside and is dropped. */
static void AssignPoint(Builder* b, const int* faces, int count, int point)
{
	int best = -1;
	double bestDistance = b->tol;
	for (int i = 0; i < count; ++i)
	{
		double d = FaceDistance(b, &b->faces[faces[i]], point);
		if (d > bestDistance)
		{
			bestDistance = d;
			best = faces[i];
		}
	}
	if (best >= 0)
	{
		b->nextConflict[point] = b->faces[best].conflict;
		b->faces[best].conflict = point;
	}
}

static int EdgeIndex(const HFace* f, int from, int to)
{
	for (int i = 0; i < 3; ++i)
	{
		if (f->v[i] == from && f->v[(i + 1) % 3] == to)
		{
			return i;
		}
	}
	return -1;
}

/* One quickhull step: adds the farthest conflict point of face `start`. False when the horizon
 * is not a simple loop (round-off beyond anything double should produce) or memory runs out. */
static cdResult AddEyePoint(Builder* b, int start, int stamp)
{
	HFace* f0 = &b->faces[start];
	int eye = f0->conflict;
	double farthest = FaceDistance(b, f0, eye);
	for (int q = b->nextConflict[eye]; q >= 0; q = b->nextConflict[q])
	{
		double d = FaceDistance(b, f0, q);
		if (d > farthest)
		{
			farthest = d;
			eye = q;
		}
	}
	if (!GrowScratch(b, 3 * b->faceCount + 8))
	{
		return CD_ERROR_OUT_OF_MEMORY;
	}

	/* Depth-first search of the faces the eye sees; the horizon is where it stops. */
	int visibleCount = 0, horizonCount = 0, top = 0;
	f0->mark = stamp;
	f0->visible = true;
	b->stack[top++] = start;
	while (top > 0)
	{
		int fi = b->stack[--top];
		b->visibleFaces[visibleCount++] = fi;
		for (int e = 0; e < 3; ++e)
		{
			int g = b->faces[fi].adj[e];
			HFace* gf = &b->faces[g];
			if (gf->mark != stamp)
			{
				gf->mark = stamp;
				gf->visible = FaceDistance(b, gf, eye) > b->tol;
				if (gf->visible)
				{
					b->stack[top++] = g;
					continue;
				}
			}
			if (!gf->visible)
			{
				b->horizonFace[horizonCount] = fi;
				b->horizonEdge[horizonCount] = e;
				++horizonCount;
			}
		}
	}

	/* The horizon must be one simple loop: every vertex starts exactly one of its edges. */
	bool simple = true;
	for (int k = 0; k < horizonCount; ++k)
	{
		const HFace* f = &b->faces[b->horizonFace[k]];
		int a = f->v[b->horizonEdge[k]];
		simple = simple && b->startAt[a] < 0;
		b->startAt[a] = k;
	}
	if (simple && horizonCount >= 3)
	{
		int steps = 0, k = 0;
		do
		{
			const HFace* f = &b->faces[b->horizonFace[k]];
			int next = f->v[(b->horizonEdge[k] + 1) % 3];
			k = b->startAt[next];
			++steps;
		} while (k >= 0 && k != 0 && steps <= horizonCount);
		simple = k == 0 && steps == horizonCount;
	}
	if (!simple || horizonCount < 3)
	{
		for (int k = 0; k < horizonCount; ++k)
		{
			b->startAt[b->faces[b->horizonFace[k]].v[b->horizonEdge[k]]] = -1;
		}
		return CD_ERROR_DEGENERATE;
	}

	if (!GrowFaces(b, horizonCount))
	{
		return CD_ERROR_OUT_OF_MEMORY;
	}
	/* A cone of new faces from the eye to the horizon. */
	for (int k = 0; k < horizonCount; ++k)
	{
		HFace* f = &b->faces[b->horizonFace[k]];
		int e = b->horizonEdge[k];
		int a = f->v[e], c = f->v[(e + 1) % 3], g = f->adj[e];
		int nf = AddFace(b, a, c, eye);
		b->newFaces[k] = nf;
		HFace* other = &b->faces[g];
		other->adj[EdgeIndex(other, c, a)] = nf;
		b->faces[nf].adj[0] = g;
		b->startAt[a] = nf;
		b->endAt[c] = nf;
	}
	for (int k = 0; k < horizonCount; ++k)
	{
		HFace* nf = &b->faces[b->newFaces[k]];
		nf->adj[1] = b->startAt[nf->v[1]]; /* edge c -> eye, twin of eye -> c */
		nf->adj[2] = b->endAt[nf->v[0]];   /* edge eye -> a, twin of a -> eye */
	}
	for (int k = 0; k < horizonCount; ++k)
	{
		HFace* nf = &b->faces[b->newFaces[k]];
		b->startAt[nf->v[0]] = -1;
		b->endAt[nf->v[1]] = -1;
	}

	/* The visible faces go; their points find a new face or lie inside. */
	for (int i = 0; i < visibleCount; ++i)
	{
		HFace* f = &b->faces[b->visibleFaces[i]];
		f->alive = false;
		int q = f->conflict;
		f->conflict = -1;
		while (q >= 0)
		{
			int next = b->nextConflict[q];
			if (q != eye)
			{
				AssignPoint(b, b->newFaces, horizonCount, q);
			}
			q = next;
		}
	}
	return CD_OK;
}

/* The initial tetrahedron: the two most distant axis extremes, the point farthest from their
 * line and the point farthest from their plane. */
static cdResult InitialSimplex(Builder* b, double weld, int* out)
{
	int extremes[6] = {0, 0, 0, 0, 0, 0};
	for (int i = 1; i < b->n; ++i)
	{
		const HVec* p = &b->p[i];
		if (p->x < b->p[extremes[0]].x)
			extremes[0] = i;
		if (p->x > b->p[extremes[1]].x)
			extremes[1] = i;
		if (p->y < b->p[extremes[2]].y)
			extremes[2] = i;
		if (p->y > b->p[extremes[3]].y)
			extremes[3] = i;
		if (p->z < b->p[extremes[4]].z)
			extremes[4] = i;
		if (p->z > b->p[extremes[5]].z)
			extremes[5] = i;
	}
	double best = -1.0;
	for (int i = 0; i < 6; ++i)
	{
		for (int j = i + 1; j < 6; ++j)
		{
			double d = HLength(HSub(b->p[extremes[i]], b->p[extremes[j]]));
			if (d > best)
			{
				best = d;
				out[0] = extremes[i];
				out[1] = extremes[j];
			}
		}
	}
	if (best <= weld)
	{
		return CD_ERROR_DEGENERATE; /* all points coincide */
	}
	HVec axis = HNormalize(HSub(b->p[out[1]], b->p[out[0]]));
	best = -1.0;
	for (int i = 0; i < b->n; ++i)
	{
		HVec d = HSub(b->p[i], b->p[out[0]]);
		double distance = HLength(HSub(d, HScale(HDot(d, axis), axis)));
		if (distance > best)
		{
			best = distance;
			out[2] = i;
		}
	}
	if (best <= weld)
	{
		return CD_ERROR_DEGENERATE; /* collinear */
	}
	HVec normal = HNormalize(HCross(HSub(b->p[out[1]], b->p[out[0]]), HSub(b->p[out[2]], b->p[out[0]])));
	best = 0.0;
	out[3] = -1;
	for (int i = 0; i < b->n; ++i)
	{
		double distance = HDot(normal, HSub(b->p[i], b->p[out[0]]));
		if (fabs(distance) > fabs(best))
		{
			best = distance;
			out[3] = i;
		}
	}
	if (fabs(best) <= weld)
	{
		return CD_ERROR_DEGENERATE; /* coplanar */
	}
	if (best > 0.0)
	{
		/* Make (0, 1, 2) face away from the fourth point. */
		int swap = out[1];
		out[1] = out[2];
		out[2] = swap;
	}
	return CD_OK;
}

static cdResult RunQuickhull(Builder* b, double weld)
{
	int s[4] = {0, 1, 2, 3};
	cdResult result = InitialSimplex(b, weld, s);
	if (result != CD_OK)
	{
		return result;
	}
	/* Faces of the tetrahedron, counter-clockwise from outside; (s0, s1, s2) faces away from s3. */
	int f0 = AddFace(b, s[0], s[1], s[2]);
	int f1 = AddFace(b, s[0], s[3], s[1]);
	int f2 = AddFace(b, s[1], s[3], s[2]);
	int f3 = AddFace(b, s[2], s[3], s[0]);
	int all[4] = {f0, f1, f2, f3};
	for (int i = 0; i < 4; ++i)
	{
		for (int e = 0; e < 3; ++e)
		{
			HFace* f = &b->faces[all[i]];
			int from = f->v[e], to = f->v[(e + 1) % 3];
			for (int j = 0; j < 4; ++j)
			{
				if (j != i && EdgeIndex(&b->faces[all[j]], to, from) >= 0)
				{
					f->adj[e] = all[j];
				}
			}
		}
	}
	for (int i = 0; i < b->n; ++i)
	{
		if (i != s[0] && i != s[1] && i != s[2] && i != s[3])
		{
			AssignPoint(b, all, 4, i);
		}
	}

	int stamp = 0;
	for (int f = 0; f < b->faceCount; ++f)
	{
		while (b->faces[f].alive && b->faces[f].conflict >= 0)
		{
			result = AddEyePoint(b, f, stamp++);
			if (result != CD_OK)
			{
				return result;
			}
		}
	}
	return CD_OK;
}

/* ---- merging triangles into faces and building the half-edge hull ---------------------------- */

typedef struct AreaOrder
{
	double area;
	int face;
} AreaOrder;

static int CompareAreasDescending(const void* a, const void* b)
{
	double x = ((const AreaOrder*)a)->area, y = ((const AreaOrder*)b)->area;
	if (x != y)
	{
		return x > y ? -1 : 1;
	}
	int i = ((const AreaOrder*)a)->face, j = ((const AreaOrder*)b)->face;
	return i < j ? -1 : (i > j ? 1 : 0);
}

typedef struct Merged
{
	int* group; /* per face: merged face index */
	int groupCount;
	int* loopNext;	  /* per boundary slot (face * 3 + edge): next boundary slot of the group */
	int* groupStart;  /* per group: one boundary slot */
	int* vertexFaces; /* per vertex: number of merged faces around it */
} Merged;

/* Grows each face from the largest unmerged triangle through neighbours whose three vertices lie
 * within `mergeTolerance` of the seed's plane. */
static cdResult MergeTriangles(const Builder* b, double mergeTolerance, Merged* m)
{
	int total = b->faceCount;
	AreaOrder* order = (AreaOrder*)AllocArray((size_t)total, sizeof(AreaOrder));
	int* queue = (int*)AllocArray((size_t)total, sizeof(int));
	if (order == NULL || queue == NULL)
	{
		cdFree(order);
		cdFree(queue);
		return CD_ERROR_OUT_OF_MEMORY;
	}
	int aliveCount = 0;
	for (int f = 0; f < total; ++f)
	{
		m->group[f] = -1;
		if (b->faces[f].alive)
		{
			const HFace* face = &b->faces[f];
			HVec a = b->p[face->v[0]];
			order[aliveCount].area = HLength(HCross(HSub(b->p[face->v[1]], a), HSub(b->p[face->v[2]], a)));
			order[aliveCount].face = f;
			++aliveCount;
		}
	}
	qsort(order, (size_t)aliveCount, sizeof(AreaOrder), CompareAreasDescending);
	m->groupCount = 0;
	for (int i = 0; i < aliveCount; ++i)
	{
		int seed = order[i].face;
		if (m->group[seed] >= 0)
		{
			continue;
		}
		int g = m->groupCount++;
		HVec n = b->faces[seed].normal;
		double d = b->faces[seed].offset;
		int head = 0, tail = 0;
		queue[tail++] = seed;
		m->group[seed] = g;
		while (head < tail)
		{
			const HFace* f = &b->faces[queue[head++]];
			for (int e = 0; e < 3; ++e)
			{
				int other = f->adj[e];
				if (m->group[other] >= 0)
				{
					continue;
				}
				const HFace* o = &b->faces[other];
				/* No test of the normal: a sliver's normal is noise, its vertices are not. (The
				 * far side of a slab this thin was rejected as flat.) */
				bool coplanar = true;
				for (int k = 0; k < 3 && coplanar; ++k)
				{
					coplanar = fabs(HDot(n, b->p[o->v[k]]) - d) <= mergeTolerance;
				}
				if (coplanar)
				{
					m->group[other] = g;
					queue[tail++] = other;
				}
			}
		}
	}
	cdFree(order);
	cdFree(queue);
	return CD_OK;
}

/* Links each merged face's boundary (triangle edges whose neighbour is in another group) into one
 * loop, and counts the merged faces around each vertex. A group whose boundary is not one simple
 * loop cannot come from a convex surface; it is reported as degenerate. */
static cdResult LinkBoundaries(const Builder* b, Merged* m, int* startAt)
{
	int total = b->faceCount;
	for (int g = 0; g < m->groupCount; ++g)
	{
		m->groupStart[g] = -1;
	}
	for (int i = 0; i < b->n; ++i)
	{
		m->vertexFaces[i] = 0;
	}
	int* groupSlots = (int*)AllocArray((size_t)m->groupCount, sizeof(int));
	int* slotsInGroup = (int*)AllocArray((size_t)m->groupCount, sizeof(int));
	if (groupSlots == NULL || slotsInGroup == NULL)
	{
		cdFree(groupSlots);
		cdFree(slotsInGroup);
		return CD_ERROR_OUT_OF_MEMORY;
	}
	for (int g = 0; g < m->groupCount; ++g)
	{
		slotsInGroup[g] = 0;
	}
	for (int f = 0; f < total; ++f)
	{
		for (int e = 0; e < 3; ++e)
		{
			m->loopNext[3 * f + e] = -1;
		}
		if (!b->faces[f].alive)
		{
			continue;
		}
		for (int e = 0; e < 3; ++e)
		{
			if (m->group[b->faces[f].adj[e]] != m->group[f])
			{
				++slotsInGroup[m->group[f]];
				++m->vertexFaces[b->faces[f].v[e]];
			}
		}
	}

	cdResult result = CD_OK;
	/* Per group: map each boundary edge's start vertex to its slot, then link a -> b to the edge
	 * starting at b. startAt is a per-vertex scratch array of -1s, restored before moving on. */
	int* groupOrder = (int*)AllocArray((size_t)total * 3, sizeof(int));
	int* groupFirst = (int*)AllocArray((size_t)m->groupCount + 1, sizeof(int));
	if (groupOrder == NULL || groupFirst == NULL)
	{
		cdFree(groupSlots);
		cdFree(slotsInGroup);
		cdFree(groupOrder);
		cdFree(groupFirst);
		return CD_ERROR_OUT_OF_MEMORY;
	}
	groupFirst[0] = 0;
	for (int g = 0; g < m->groupCount; ++g)
	{
		groupFirst[g + 1] = groupFirst[g] + slotsInGroup[g];
		groupSlots[g] = groupFirst[g];
	}
	for (int f = 0; f < total; ++f)
	{
		if (!b->faces[f].alive)
		{
			continue;
		}
		for (int e = 0; e < 3; ++e)
		{
			if (m->group[b->faces[f].adj[e]] != m->group[f])
			{
				groupOrder[groupSlots[m->group[f]]++] = 3 * f + e;
			}
		}
	}
	for (int g = 0; g < m->groupCount && result == CD_OK; ++g)
	{
		int first = groupFirst[g], last = groupFirst[g + 1];
		if (last - first < 3)
		{
			result = CD_ERROR_DEGENERATE;
			break;
		}
		for (int s = first; s < last && result == CD_OK; ++s)
		{
			int slot = groupOrder[s];
			int a = b->faces[slot / 3].v[slot % 3];
			if (startAt[a] >= 0)
			{
				result = CD_ERROR_DEGENERATE; /* two boundary edges leave one vertex: pinched */
			}
			startAt[a] = slot;
		}
		for (int s = first; s < last && result == CD_OK; ++s)
		{
			int slot = groupOrder[s];
			int to = b->faces[slot / 3].v[(slot % 3 + 1) % 3];
			m->loopNext[slot] = startAt[to];
			if (startAt[to] < 0)
			{
				result = CD_ERROR_DEGENERATE;
			}
		}
		if (result == CD_OK)
		{
			/* One loop through every boundary edge: no holes. */
			int slot = groupOrder[first], steps = 0;
			do
			{
				slot = m->loopNext[slot];
				++steps;
			} while (slot != groupOrder[first] && steps <= last - first);
			if (steps != last - first)
			{
				result = CD_ERROR_DEGENERATE;
			}
			m->groupStart[g] = groupOrder[first];
		}
		for (int s = first; s < last; ++s)
		{
			int slot = groupOrder[s];
			startAt[b->faces[slot / 3].v[slot % 3]] = -1;
		}
	}
	cdFree(groupSlots);
	cdFree(slotsInGroup);
	cdFree(groupOrder);
	cdFree(groupFirst);
	return result;
}

/* Sizes of the pieces of the hull's single allocation, each rounded up to 32 bytes. */
static size_t AlignUp(size_t size)
{
	return (size + 31u) & ~(size_t)31u;
}

/* Distance from p to the line through a and b (to a when they coincide). */
static double LineDistance(HVec p, HVec a, HVec b)
{
	HVec d = HSub(b, a), q = HSub(p, a);
	double dd = HDot(d, d);
	return dd > 0.0 ? HLength(HSub(q, HScale(HDot(q, d) / dd, d))) : HLength(q);
}

/* `collinearTolerance`: how far a dropped vertex may lie from the edge that replaces it. Two
 * nearly parallel faces are both within the merge tolerance of points far from their common
 * edge; such a merge is refused (and retried with a smaller tolerance), not allowed to cut a
 * corner off the hull. */
static cdResult BuildHull(const Builder* b, const Merged* m, const cd3Vec* input, const int* inputIndex,
						  double collinearTolerance, cd3Hull** out)
{
	int total = b->faceCount;
	/* Kept vertices: those where at least three merged faces meet. A vertex between only two
	 * lies on their common edge and is dropped. */
	int* vertexMap = (int*)AllocArray((size_t)b->n, sizeof(int));
	if (vertexMap == NULL)
	{
		return CD_ERROR_OUT_OF_MEMORY;
	}
	int vertexCount = 0;
	for (int i = 0; i < b->n; ++i)
	{
		vertexMap[i] = m->vertexFaces[i] >= 3 ? vertexCount++ : -1;
	}
	int halfEdgeCount = 0;
	for (int f = 0; f < total; ++f)
	{
		for (int e = 0; e < 3; ++e)
		{
			int slot = 3 * f + e;
			if (m->loopNext[slot] >= 0 && vertexMap[b->faces[f].v[e]] >= 0)
			{
				++halfEdgeCount;
			}
		}
	}
	int faceCount = m->groupCount;

	size_t headerSize = AlignUp(sizeof(cd3Hull));
	size_t verticesSize = AlignUp((size_t)vertexCount * sizeof(cd3Vec));
	size_t edgesSize = AlignUp((size_t)halfEdgeCount * sizeof(cd3HullHalfEdge));
	size_t faceEdgesSize = AlignUp((size_t)faceCount * sizeof(int32_t));
	size_t planesSize = AlignUp((size_t)faceCount * sizeof(cd3Plane));
	char* memory = (char*)cdAlloc(headerSize + verticesSize + edgesSize + faceEdgesSize + planesSize);
	/* Each half-edge covers a chain of boundary slots (the dropped vertices in between); its
	 * twin is the half-edge covering the twin of its chain's last slot. */
	int* slotEdge = (int*)AllocArray((size_t)total * 3, sizeof(int));
	int* lastSlot = (int*)AllocArray((size_t)halfEdgeCount, sizeof(int));
	int* firstSlot = (int*)AllocArray((size_t)halfEdgeCount, sizeof(int));
	if (memory == NULL || slotEdge == NULL || lastSlot == NULL || firstSlot == NULL)
	{
		cdFree(memory);
		cdFree(slotEdge);
		cdFree(lastSlot);
		cdFree(firstSlot);
		cdFree(vertexMap);
		return CD_ERROR_OUT_OF_MEMORY;
	}
	cd3Hull* hull = (cd3Hull*)memory;
	cd3Vec* vertices = (cd3Vec*)(memory + headerSize);
	cd3HullHalfEdge* edges = (cd3HullHalfEdge*)(memory + headerSize + verticesSize);
	int32_t* faceEdges = (int32_t*)(memory + headerSize + verticesSize + edgesSize);
	cd3Plane* planes = (cd3Plane*)(memory + headerSize + verticesSize + edgesSize + faceEdgesSize);
	memset(hull, 0, sizeof(*hull));
	for (int i = 0; i < b->n; ++i)
	{
		if (vertexMap[i] >= 0)
		{
			vertices[vertexMap[i]] = input[inputIndex[i]];
		}
	}

	/* Faces: walk each boundary loop, keeping the slots that start at a kept vertex. */
	int edgeIndex = 0;
	bool ok = true;
	for (int g = 0; g < faceCount && ok; ++g)
	{
		int start = m->groupStart[g];
		int slot = start;
		int first = -1, previous = -1, count = 0;
		do
		{
			int v = vertexMap[b->faces[slot / 3].v[slot % 3]];
			if (v >= 0)
			{
				cd3HullHalfEdge* edge = &edges[edgeIndex];
				firstSlot[edgeIndex] = slot;
				edge->origin = v;
				edge->face = g;
				edge->twin = -1;
				edge->next = -1;
				if (previous >= 0)
				{
					edges[previous].next = edgeIndex;
				}
				else
				{
					first = edgeIndex;
				}
				previous = edgeIndex;
				++edgeIndex;
				++count;
			}
			slotEdge[slot] = previous;
			if (previous >= 0)
			{
				lastSlot[previous] = slot;
			}
			slot = m->loopNext[slot];
		} while (slot != start);
		if (count < 3)
		{
			ok = false;
			break;
		}
		/* Slots before the first kept vertex end the last half-edge's chain. */
		for (slot = start; slotEdge[slot] < 0; slot = m->loopNext[slot])
		{
			slotEdge[slot] = previous;
			lastSlot[previous] = slot;
		}
		edges[previous].next = first;
		faceEdges[g] = first;
	}
	for (int e = 0; e < halfEdgeCount && ok; ++e)
	{
		/* The dropped vertices of this half-edge's chain lie on it. */
		int slot = firstSlot[e], last = lastSlot[e];
		const HFace* lastFace = &b->faces[last / 3];
		HVec from = b->p[b->faces[slot / 3].v[slot % 3]], to = b->p[lastFace->v[(last % 3 + 1) % 3]];
		for (; slot != last && ok; slot = m->loopNext[slot])
		{
			const HFace* f = &b->faces[slot / 3];
			ok = LineDistance(b->p[f->v[(slot % 3 + 1) % 3]], from, to) <= collinearTolerance;
		}
	}
	if (ok)
	{
		for (int e = 0; e < halfEdgeCount && ok; ++e)
		{
			int slot = lastSlot[e];
			const HFace* f = &b->faces[slot / 3];
			int other = f->adj[slot % 3];
			int j = EdgeIndex(&b->faces[other], f->v[(slot % 3 + 1) % 3], f->v[slot % 3]);
			ok = j >= 0 && slotEdge[3 * other + j] >= 0;
			if (ok)
			{
				edges[e].twin = slotEdge[3 * other + j];
			}
		}
	}
	cdFree(slotEdge);
	cdFree(lastSlot);
	cdFree(firstSlot);
	cdFree(vertexMap);
	if (!ok)
	{
		cdFree(memory);
		return CD_ERROR_DEGENERATE;
	}

	/* Planes: Newell's normal of the polygon, offset through its highest vertex, in double on
	 * the stored (cdReal) vertices; then rounded. */
	for (int g = 0; g < faceCount; ++g)
	{
		HVec normal = HMake(0.0, 0.0, 0.0);
		int e = faceEdges[g];
		cd3Vec o = vertices[edges[e].origin];
		HVec origin = HMake((double)o.x, (double)o.y, (double)o.z);
		do
		{
			cd3Vec pv = vertices[edges[e].origin], qv = vertices[edges[edges[e].next].origin];
			HVec p = HSub(HMake((double)pv.x, (double)pv.y, (double)pv.z), origin);
			HVec q = HSub(HMake((double)qv.x, (double)qv.y, (double)qv.z), origin);
			normal.x += (p.y - q.y) * (p.z + q.z);
			normal.y += (p.z - q.z) * (p.x + q.x);
			normal.z += (p.x - q.x) * (p.y + q.y);
			e = edges[e].next;
		} while (e != faceEdges[g]);
		normal = HNormalize(normal);
		cd3Vec n = cd3Normalize(cd3MakeVec((cdReal)normal.x, (cdReal)normal.y, (cdReal)normal.z));
		double offset = -DBL_MAX;
		e = faceEdges[g];
		do
		{
			cd3Vec p = vertices[edges[e].origin];
			double h = (double)n.x * (double)p.x + (double)n.y * (double)p.y + (double)n.z * (double)p.z;
			offset = h > offset ? h : offset;
			e = edges[e].next;
		} while (e != faceEdges[g]);
		planes[g].normal = n;
		planes[g].offset = (cdReal)offset;
	}

	/* Volume and centroid: tetrahedra from a point inside (the vertex mean) to each face's fan. */
	HVec reference = HMake(0.0, 0.0, 0.0);
	cd3Aabb bounds = {vertices[0], vertices[0]};
	for (int i = 0; i < vertexCount; ++i)
	{
		reference =
			HAdd(reference, HMake((double)vertices[i].x, (double)vertices[i].y, (double)vertices[i].z));
		bounds.min = cd3Min(bounds.min, vertices[i]);
		bounds.max = cd3Max(bounds.max, vertices[i]);
	}
	reference = HScale(1.0 / (double)vertexCount, reference);
	double volume = 0.0;
	HVec moment = HMake(0.0, 0.0, 0.0);
	for (int g = 0; g < faceCount; ++g)
	{
		int e0 = faceEdges[g];
		cd3Vec v0 = vertices[edges[e0].origin];
		HVec a = HSub(HMake((double)v0.x, (double)v0.y, (double)v0.z), reference);
		for (int e = edges[e0].next; edges[e].next != e0; e = edges[e].next)
		{
			cd3Vec v1 = vertices[edges[e].origin], v2 = vertices[edges[edges[e].next].origin];
			HVec p1 = HSub(HMake((double)v1.x, (double)v1.y, (double)v1.z), reference);
			HVec p2 = HSub(HMake((double)v2.x, (double)v2.y, (double)v2.z), reference);
			double six = HDot(a, HCross(p1, p2));
			volume += six;
			moment = HAdd(moment, HScale(six, HAdd(a, HAdd(p1, p2))));
		}
	}
	HVec centroid = volume > 0.0 ? HAdd(reference, HScale(1.0 / (4.0 * volume), moment)) : reference;

	hull->vertexCount = vertexCount;
	hull->edgeCount = halfEdgeCount;
	hull->faceCount = faceCount;
	hull->vertices = vertices;
	hull->edges = edges;
	hull->faceEdges = faceEdges;
	hull->planes = planes;
	hull->centroid = cd3MakeVec((cdReal)centroid.x, (cdReal)centroid.y, (cdReal)centroid.z);
	hull->volume = (cdReal)(volume / 6.0);
	hull->bounds = bounds;
	*out = hull;
	return CD_OK;
}

/* ---- welding ------------------------------------------------------------------------------------ */

typedef struct SortedPoint
{
	double x;
	int index;
} SortedPoint;

static int CompareSortedPoints(const void* a, const void* b)
{
	const SortedPoint* p = (const SortedPoint*)a;
	const SortedPoint* q = (const SortedPoint*)b;
	if (p->x != q->x)
	{
		return p->x < q->x ? -1 : 1;
	}
	return p->index < q->index ? -1 : (p->index > q->index ? 1 : 0);
}

/* Keeps one point of every cluster closer than `weld` (sweep along x); returns the count kept and
 * their input indices in `kept`. The first point (in input order among equal x) wins. */
static int WeldPoints(const HVec* p, int count, double weld, SortedPoint* sorted, bool* removed, int* kept)
{
	for (int i = 0; i < count; ++i)
	{
		sorted[i].x = p[i].x;
		sorted[i].index = i;
		removed[i] = false;
	}
	qsort(sorted, (size_t)count, sizeof(SortedPoint), CompareSortedPoints);
	double weldSquared = weld * weld;
	int keptCount = 0;
	for (int i = 0; i < count; ++i)
	{
		int a = sorted[i].index;
		if (removed[a])
		{
			continue;
		}
		kept[keptCount++] = a;
		for (int j = i + 1; j < count && sorted[j].x - sorted[i].x <= weld; ++j)
		{
			int c = sorted[j].index;
			HVec d = HSub(p[c], p[a]);
			if (!removed[c] && HDot(d, d) <= weldSquared)
			{
				removed[c] = true;
			}
		}
	}
	return keptCount;
}

static cdResult ValidateHull(const cd3Hull* hull, bool global);

/* ---- public -------------------------------------------------------------------------------------- */

cdResult cd3ComputeHull(const cd3Vec* points, int count, cd3Hull** hull)
{
	if (hull == NULL)
	{
		return CD_ERROR_INVALID_ARGUMENT;
	}
	*hull = NULL;
	if (points == NULL || count < 0)
	{
		return CD_ERROR_INVALID_ARGUMENT;
	}
	for (int i = 0; i < count; ++i)
	{
		if (!cd3IsValidVec(points[i]))
		{
			return CD_ERROR_NOT_FINITE;
		}
	}
	if (count > CD3_MAX_HULL_POINTS)
	{
		return CD_ERROR_TOO_MANY_POINTS;
	}
	if (count < 4)
	{
		return CD_ERROR_DEGENERATE;
	}

	/* Work relative to the centre of the bounding box: differences of nearby coordinates far
	 * from the origin stay exact. */
	cd3Vec lo = points[0], hi = points[0];
	for (int i = 1; i < count; ++i)
	{
		lo = cd3Min(lo, points[i]);
		hi = cd3Max(hi, points[i]);
	}
	HVec center = HMake(0.5 * ((double)lo.x + (double)hi.x), 0.5 * ((double)lo.y + (double)hi.y),
						0.5 * ((double)lo.z + (double)hi.z));
	HVec diagonal =
		HMake((double)hi.x - (double)lo.x, (double)hi.y - (double)lo.y, (double)hi.z - (double)lo.z);
	double extent = HLength(diagonal);
	if (!(extent > 0.0) || !isfinite(extent))
	{
		return CD_ERROR_DEGENERATE;
	}

	size_t n = (size_t)count;
	HVec* shifted = (HVec*)AllocArray(n, sizeof(HVec));
	HVec* welded = (HVec*)AllocArray(n, sizeof(HVec));
	SortedPoint* sorted = (SortedPoint*)AllocArray(n, sizeof(SortedPoint));
	bool* removed = (bool*)AllocArray(n, sizeof(bool));
	int* kept = (int*)AllocArray(n, sizeof(int));
	int* nextConflict = (int*)AllocArray(n, sizeof(int));
	int* startAt = (int*)AllocArray(n, sizeof(int));
	int* endAt = (int*)AllocArray(n, sizeof(int));
	Builder b;
	memset(&b, 0, sizeof(b));
	b.faceCapacity = 64;
	b.faces = (HFace*)AllocArray((size_t)b.faceCapacity, sizeof(HFace));
	cdResult result = CD_OK;
	if (shifted == NULL || welded == NULL || sorted == NULL || removed == NULL || kept == NULL ||
		nextConflict == NULL || startAt == NULL || endAt == NULL || b.faces == NULL)
	{
		result = CD_ERROR_OUT_OF_MEMORY;
	}
	Merged m;
	memset(&m, 0, sizeof(m));
	if (result == CD_OK)
	{
		for (int i = 0; i < count; ++i)
		{
			shifted[i] = HSub(HMake((double)points[i].x, (double)points[i].y, (double)points[i].z), center);
		}
		int keptCount = WeldPoints(shifted, count, HULL_WELD_REL * extent, sorted, removed, kept);
		for (int i = 0; i < keptCount; ++i)
		{
			welded[i] = shifted[kept[i]];
			startAt[i] = -1;
			endAt[i] = -1;
			nextConflict[i] = -1;
		}
		b.p = welded;
		b.n = keptCount;
		b.nextConflict = nextConflict;
		b.startAt = startAt;
		b.endAt = endAt;
		b.tol = HULL_BUILD_REL * extent;
		result = keptCount < 4 ? CD_ERROR_DEGENERATE : RunQuickhull(&b, HULL_WELD_REL * extent);
	}
	if (result == CD_OK)
	{
		size_t total = (size_t)b.faceCount;
		m.group = (int*)AllocArray(total, sizeof(int));
		m.loopNext = (int*)AllocArray(3 * total, sizeof(int));
		m.groupStart = (int*)AllocArray(total, sizeof(int));
		m.vertexFaces = (int*)AllocArray((size_t)b.n, sizeof(int));
		if (m.group == NULL || m.loopNext == NULL || m.groupStart == NULL || m.vertexFaces == NULL)
		{
			result = CD_ERROR_OUT_OF_MEMORY;
		}
	}
	/* Greedy merging can leave a face notched by a nearly coplanar neighbour when points sit
	 * right at the merge tolerance. Such a merge is retried with smaller tolerances, and at last
	 * without merging: the bare triangulation is convex to round-off, which the validator's
	 * tolerance covers. */
	const double mergeScales[4] = {1.0, 1.0 / 64.0, 0.0, -1.0};
	for (int attempt = 0; attempt < 4 && result == CD_OK; ++attempt)
	{
		double mergeTolerance = HULL_MERGE_REL * extent * mergeScales[attempt];
		mergeTolerance = mergeScales[attempt] < 0.0 ? -1.0 : cdMaxDouble(mergeTolerance, 4.0 * b.tol);
		result = MergeTriangles(&b, mergeTolerance, &m);
		if (result == CD_OK)
		{
			result = LinkBoundaries(&b, &m, startAt);
		}
		if (result == CD_OK)
		{
			result = BuildHull(&b, &m, points, kept, cdMaxDouble(mergeTolerance, 4.0 * b.tol), hull);
		}
		if (result == CD_OK)
		{
			cdResult valid = ValidateHull(*hull, false);
			if (valid != CD_OK)
			{
				/* Never hand out a broken hull. */
				cd3DestroyHull(*hull);
				*hull = NULL;
				result = valid == CD_ERROR_OUT_OF_MEMORY ? valid : CD_ERROR_DEGENERATE;
			}
		}
		if (result != CD_ERROR_DEGENERATE || attempt == 3)
		{
			break;
		}
		result = CD_OK;
	}

	cdFree(m.group);
	cdFree(m.loopNext);
	cdFree(m.groupStart);
	cdFree(m.vertexFaces);
	cdFree(b.faces);
	cdFree(b.stack);
	cdFree(b.visibleFaces);
	cdFree(b.horizonFace);
	cdFree(b.horizonEdge);
	cdFree(b.newFaces);
	cdFree(shifted);
	cdFree(welded);
	cdFree(sorted);
	cdFree(removed);
	cdFree(kept);
	cdFree(nextConflict);
	cdFree(startAt);
	cdFree(endAt);
	return result;
}

void cd3DestroyHull(cd3Hull* hull)
{
	cdFree(hull);
}

cdReal cd3GetHullTolerance(const cd3Hull* hull)
{
	CD_ASSERT(hull != NULL);
	cd3Vec lo = hull->bounds.min, hi = hull->bounds.max;
	double extent = (double)cd3Length(cd3Sub(hi, lo));
	cd3Vec far = cd3Max(cd3Abs(lo), cd3Abs(hi));
	double magnitude = (double)cdMax(far.x, cdMax(far.y, far.z));
	/* The merged faces' flatness scales with the extent; the rounding of planes and of the test
	 * itself with the coordinates' magnitude. */
	return (cdReal)(HULL_VALID_REL * extent + 16.0 * (double)CD_REAL_EPSILON * magnitude);
}

static bool ValidIndex(int32_t index, int count)
{
	return index >= 0 && index < count;
}

/* `global`: every vertex against every plane (O(V F)); otherwise only the vertices of each face's
 * neighbours, which on a closed manifold with convex edges implies the same up to round-off. */
static cdResult ValidateHull(const cd3Hull* hull, bool global)
{
	if (hull == NULL || hull->vertices == NULL || hull->edges == NULL || hull->faceEdges == NULL ||
		hull->planes == NULL || hull->vertexCount < 4 || hull->faceCount < 4 || hull->edgeCount < 12 ||
		(hull->edgeCount & 1) != 0)
	{
		return CD_ERROR_INVALID_ARGUMENT;
	}
	int v = hull->vertexCount, e = hull->edgeCount, f = hull->faceCount;
	for (int i = 0; i < v; ++i)
	{
		if (!cd3IsValidVec(hull->vertices[i]))
		{
			return CD_ERROR_NOT_FINITE;
		}
	}
	for (int i = 0; i < f; ++i)
	{
		if (!cd3IsValidVec(hull->planes[i].normal) || !cdIsValidReal(hull->planes[i].offset))
		{
			return CD_ERROR_NOT_FINITE;
		}
	}
	if (!cd3IsValidVec(hull->centroid) || !cdIsValidReal(hull->volume) || !cd3IsValidVec(hull->bounds.min) ||
		!cd3IsValidVec(hull->bounds.max))
	{
		return CD_ERROR_NOT_FINITE;
	}
	/* Topology: indices in range, twins paired, each face a cycle of its own half-edges. */
	for (int i = 0; i < e; ++i)
	{
		const cd3HullHalfEdge* h = &hull->edges[i];
		if (!ValidIndex(h->next, e) || !ValidIndex(h->twin, e) || !ValidIndex(h->origin, v) ||
			!ValidIndex(h->face, f))
		{
			return CD_ERROR_INVALID_ARGUMENT;
		}
		const cd3HullHalfEdge* t = &hull->edges[h->twin];
		if (h->twin == i || t->twin != i || t->origin != hull->edges[h->next].origin ||
			hull->edges[h->next].face != h->face || t->face == h->face)
		{
			return CD_ERROR_INVALID_ARGUMENT;
		}
	}
	int counted = 0;
	for (int i = 0; i < f; ++i)
	{
		int start = hull->faceEdges[i];
		if (!ValidIndex(start, e) || hull->edges[start].face != i)
		{
			return CD_ERROR_INVALID_ARGUMENT;
		}
		int steps = 0, h = start;
		do
		{
			h = hull->edges[h].next;
			++steps;
		} while (h != start && steps <= e);
		if (steps > e || steps < 3)
		{
			return CD_ERROR_INVALID_ARGUMENT;
		}
		counted += steps;
	}
	/* Every half-edge is on exactly one face cycle, and the surface is a sphere. */
	if (counted != e || v - e / 2 + f != 2)
	{
		return CD_ERROR_INVALID_ARGUMENT;
	}
	/* Every vertex is used, and the half-edges around each vertex form one fan (a manifold). */
	int* fan = (int*)AllocArray((size_t)v, sizeof(int));
	if (fan == NULL)
	{
		return CD_ERROR_OUT_OF_MEMORY;
	}
	for (int i = 0; i < v; ++i)
	{
		fan[i] = 0;
	}
	for (int i = 0; i < e; ++i)
	{
		++fan[hull->edges[i].origin];
	}
	bool manifold = true;
	for (int i = 0; i < e && manifold; ++i)
	{
		/* Around the origin: twin(h) ends at origin, next(twin(h)) leaves it again. */
		int steps = 0, h = i;
		do
		{
			h = hull->edges[hull->edges[h].twin].next;
			++steps;
		} while (h != i && steps <= e);
		manifold = h == i && steps == fan[hull->edges[i].origin];
	}
	for (int i = 0; i < v && manifold; ++i)
	{
		manifold = fan[i] >= 3;
	}
	cdFree(fan);
	if (!manifold)
	{
		return CD_ERROR_INVALID_ARGUMENT;
	}

	cdReal tolerance = cd3GetHullTolerance(hull);
	for (int i = 0; i < f; ++i)
	{
		cd3Plane plane = hull->planes[i];
		if (cdAbs(cd3Length(plane.normal) - CD_R(1.0)) > CD_R(64.0) * CD_REAL_EPSILON)
		{
			return CD_ERROR_NOT_NORMALIZED;
		}
		/* Planar and convex: vertices on the plane, each corner turning counter-clockwise about
		 * the outward normal (this also rejects inward normals). */
		int start = hull->faceEdges[i], h = start;
		do
		{
			const cd3HullHalfEdge* edge = &hull->edges[h];
			cd3Vec p0 = hull->vertices[edge->origin];
			cd3Vec p1 = hull->vertices[hull->edges[edge->next].origin];
			cd3Vec p2 = hull->vertices[hull->edges[hull->edges[edge->next].next].origin];
			if (cdAbs(cd3Dot(plane.normal, p0) - plane.offset) > tolerance)
			{
				return CD_ERROR_DEGENERATE;
			}
			/* The corner at p1 bends away from the face's interior by less than the tolerance:
			 * p2 lies on the inner side of the line p0-p1 within the plane. */
			cd3Vec inward = cd3Normalize(cd3Cross(plane.normal, cd3Sub(p1, p0)));
			if (cd3Dot(inward, cd3Sub(p2, p0)) < -tolerance)
			{
				return CD_ERROR_DEGENERATE;
			}
			h = edge->next;
		} while (h != start);
		if (global)
		{
			for (int k = 0; k < v; ++k)
			{
				if (cd3Dot(plane.normal, hull->vertices[k]) - plane.offset > tolerance)
				{
					return CD_ERROR_DEGENERATE;
				}
			}
			continue;
		}
		h = start;
		do
		{
			int t = hull->edges[h].twin, k = t;
			do
			{
				if (cd3Dot(plane.normal, hull->vertices[hull->edges[k].origin]) - plane.offset > tolerance)
				{
					return CD_ERROR_DEGENERATE;
				}
				k = hull->edges[k].next;
			} while (k != t);
			h = hull->edges[h].next;
		} while (h != start);
	}
	/* Outward: the centre of volume lies strictly below every face. */
	if (!(hull->volume > CD_R(0.0)))
	{
		return CD_ERROR_DEGENERATE;
	}
	for (int i = 0; i < f; ++i)
	{
		if (cd3Dot(hull->planes[i].normal, hull->centroid) - hull->planes[i].offset >= CD_R(0.0))
		{
			return CD_ERROR_DEGENERATE;
		}
	}
	return CD_OK;
}

cdResult cd3ValidateHull(const cd3Hull* hull)
{
	return ValidateHull(hull, true);
}

/* ---- convenience builders ----------------------------------------------------------------------- */

static cdResult CheckSize(cdReal size)
{
	if (!cdIsValidReal(size))
	{
		return CD_ERROR_NOT_FINITE;
	}
	if (size < CD_R(0.0))
	{
		return CD_ERROR_NEGATIVE_SIZE;
	}
	return size == CD_R(0.0) ? CD_ERROR_DEGENERATE : CD_OK;
}

cdResult cd3MakeBoxHull(cd3Vec halfExtents, cd3Hull** hull)
{
	if (hull == NULL)
	{
		return CD_ERROR_INVALID_ARGUMENT;
	}
	*hull = NULL;
	cdResult result = CheckSize(halfExtents.x);
	result = result != CD_OK ? result : CheckSize(halfExtents.y);
	result = result != CD_OK ? result : CheckSize(halfExtents.z);
	if (result != CD_OK)
	{
		return result;
	}
	cd3Vec corners[8];
	for (int i = 0; i < 8; ++i)
	{
		corners[i] =
			cd3MakeVec((i & 1) ? halfExtents.x : -halfExtents.x, (i & 2) ? halfExtents.y : -halfExtents.y,
					   (i & 4) ? halfExtents.z : -halfExtents.z);
	}
	return cd3ComputeHull(corners, 8, hull);
}

#define CD3_MAX_HULL_SEGMENTS 1024

static cdResult MakeRevolvedHull(cdReal halfHeight, cdReal radius, int segments, bool cone, cd3Hull** hull)
{
	if (hull == NULL)
	{
		return CD_ERROR_INVALID_ARGUMENT;
	}
	*hull = NULL;
	if (segments < 3 || segments > CD3_MAX_HULL_SEGMENTS)
	{
		return CD_ERROR_INVALID_ARGUMENT;
	}
	cdResult result = CheckSize(halfHeight);
	result = result != CD_OK ? result : CheckSize(radius);
	if (result != CD_OK)
	{
		return result;
	}
	cd3Vec* points = (cd3Vec*)cdAlloc((size_t)(2 * segments) * sizeof(cd3Vec));
	if (points == NULL)
	{
		return CD_ERROR_OUT_OF_MEMORY;
	}
	int count = 0;
	for (int i = 0; i < segments; ++i)
	{
		double angle = 2.0 * 3.14159265358979323846 * (double)i / (double)segments;
		cdReal x = (cdReal)((double)radius * cos(angle)), z = (cdReal)((double)radius * sin(angle));
		points[count++] = cd3MakeVec(x, -halfHeight, z);
		if (!cone)
		{
			points[count++] = cd3MakeVec(x, halfHeight, z);
		}
	}
	if (cone)
	{
		points[count++] = cd3MakeVec(CD_R(0.0), halfHeight, CD_R(0.0));
	}
	result = cd3ComputeHull(points, count, hull);
	cdFree(points);
	return result;
}

cdResult cd3MakeCylinderHull(cdReal halfHeight, cdReal radius, int segments, cd3Hull** hull)
{
	return MakeRevolvedHull(halfHeight, radius, segments, false, hull);
}

cdResult cd3MakeConeHull(cdReal halfHeight, cdReal radius, int segments, cd3Hull** hull)
{
	return MakeRevolvedHull(halfHeight, radius, segments, true, hull);
}
