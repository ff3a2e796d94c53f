/* 3D convex hulls: quickhull in double precision on a triangulated surface, then triangles that
 * are coplanar within a tolerance are merged into convex polygons (Gregorius, "Implementing
 * Quickhull", GDC 2014, gives the reasons: slivers and near-coplanar faces are what breaks hulls).
 *
 * Why triangles first and merging afterwards: the triangulation is exact to double round-off,
 * far below the merge tolerance of a float hull, so every merge decision looks at a clean convex
 * surface; merged regions of a convex surface are discs, so their boundaries are simple loops. */
#include "collide/geometry3.h"

#include "../query/sat3.h"

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

static void* AllocArray(size_t count, size_t size)
{
	return count == 0 ? NULL : cdAlloc(count * size);
}

/* ---- scratch memory ------------------------------------------------------------------------------ */

/* Pieces of one allocation, each rounded up to 32 bytes. */
static size_t AlignUp(size_t size)
{
	return (size + 31u) & ~(size_t)31u;
}

/* One block carved into the build's scratch arrays: a build allocates it and the hull, nothing
 * else. Measured first (base NULL), then carved. */
typedef struct Arena
{
	char* base;
	size_t used;
} Arena;

static void* ArenaTake(Arena* arena, size_t count, size_t size)
{
	void* memory = arena->base != NULL ? arena->base + arena->used : NULL;
	arena->used += AlignUp(count * size);
	return memory;
}

/* ---- sorting ------------------------------------------------------------------------------------- */

typedef struct SortKey
{
	uint64_t key;
	int index;
} SortKey;

/* Bits of a double that sort as unsigned integers in the order of the values (-0 as +0). */
static uint64_t OrderedBits(double x)
{
	x = x + 0.0;
	uint64_t bits;
	memcpy(&bits, &x, sizeof(bits));
	return (bits >> 63) != 0 ? ~bits : bits | 0x8000000000000000ull;
}

/* Stable sort by key (equal keys keep their order): insertion sort for a few keys, else a radix
 * sort by bytes that skips the digits every key shares. Returns the sorted array, which
 * is `keys` or `spare`. */
static SortKey* SortKeys(SortKey* keys, SortKey* spare, int count)
{
	if (count < 64)
	{
		for (int i = 1; i < count; ++i)
		{
			SortKey k = keys[i];
			int j = i;
			for (; j > 0 && keys[j - 1].key > k.key; --j)
			{
				keys[j] = keys[j - 1];
			}
			keys[j] = k;
		}
		return keys;
	}
	enum
	{
		DIGIT_BITS = 8,
		DIGITS = 8,
		BUCKETS = 1 << DIGIT_BITS
	};
	static const uint64_t mask = BUCKETS - 1;
	int histogram[DIGITS][BUCKETS];
	memset(histogram, 0, sizeof(histogram));
	for (int i = 0; i < count; ++i)
	{
		uint64_t key = keys[i].key;
		for (int d = 0; d < DIGITS; ++d)
		{
			++histogram[d][(key >> (d * DIGIT_BITS)) & mask];
		}
	}
	SortKey* from = keys;
	SortKey* to = spare;
	for (int d = 0; d < DIGITS; ++d)
	{
		int* h = histogram[d];
		if (h[(from[0].key >> (d * DIGIT_BITS)) & mask] == count)
		{
			continue; /* every key has this digit */
		}
		int sum = 0;
		for (int bucket = 0; bucket < BUCKETS; ++bucket)
		{
			int c = h[bucket];
			h[bucket] = sum;
			sum += c;
		}
		for (int i = 0; i < count; ++i)
		{
			to[h[(from[i].key >> (d * DIGIT_BITS)) & mask]++] = from[i];
		}
		SortKey* swap = from;
		from = to;
		to = swap;
	}
	return from;
}

/* ---- quickhull on triangles -------------------------------------------------------------------- */

typedef struct HFace
{
	HVec normal;
	double offset;
	double farthestDistance; /* of the conflict list's farthest point */
	int v[3];
	int adj[3];	  /* face across edge v[i] -> v[(i + 1) % 3]; adj[0] links the free list when dead */
	int conflict; /* first point of the conflict list, -1 when empty */
	int farthest; /* its farthest point */
	int mark;	  /* visit stamp of the horizon search */
	bool visible;
	bool alive;
	bool queued; /* on the pending ring (kept when the slot is reused) */
} HFace;

/* Dead faces are recycled before new ones are made, so that the slots in use never exceed the
 * faces of the final triangulation: 2 V - 4 for V points, whatever the insertion order. */
typedef struct Builder
{
	const HVec* p;
	int n;
	int* nextConflict;
	HFace* faces;
	int faceCount; /* slots ever used */
	int faceCapacity;
	int freeFace;
	int* pending; /* ring of faces with conflict points, each once (queued) */
	int pendingHead;
	int pendingCount;
	int* stack;
	int* visibleFaces;
	int* horizonFace; /* per horizon edge: its visible face, then the face beyond it */
	int* horizonEdge;
	int* horizonFrom;
	int* horizonTo;
	int* newFaces;
	int* orphans; /* the conflict points of the faces an eye point removes */
	int* startAt; /* per vertex: new face whose horizon edge starts there, -1 */
	int* endAt;
	double tol;
} Builder;

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

/* -1 when no slot is left (cannot happen on a simple triangulated sphere; checked anyway). */
static int AddFace(Builder* b, int v0, int v1, int v2)
{
	int index = b->freeFace;
	if (index >= 0)
	{
		b->freeFace = b->faces[index].adj[0];
	}
	else
	{
		if (b->faceCount == b->faceCapacity)
		{
			return -1;
		}
		index = b->faceCount++;
		b->faces[index].queued = false;
	}
	HFace* f = &b->faces[index];
	f->v[0] = v0;
	f->v[1] = v1;
	f->v[2] = v2;
	f->adj[0] = f->adj[1] = f->adj[2] = -1;
	f->conflict = -1;
	f->farthest = -1;
	f->farthestDistance = 0.0;
	f->mark = -1;
	f->visible = false;
	f->alive = true;
	SetPlane(b, f);
	return index;
}

static void FreeFace(Builder* b, int index)
{
	HFace* f = &b->faces[index];
	f->alive = false;
	f->conflict = -1;
	f->adj[0] = b->freeFace;
	b->freeFace = index;
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
		HFace* f = &b->faces[best];
		if (f->conflict < 0 || bestDistance > f->farthestDistance)
		{
			f->farthest = point;
			f->farthestDistance = bestDistance;
		}
		b->nextConflict[point] = f->conflict;
		f->conflict = point;
		if (!f->queued)
		{
			f->queued = true;
			int tail = b->pendingHead + b->pendingCount++;
			b->pending[tail < b->faceCapacity ? tail : tail - b->faceCapacity] = best;
		}
	}
}

static int EdgeIndex(const int* v, int from, int to)
{
	for (int i = 0; i < 3; ++i)
	{
		if (v[i] == from && v[(i + 1) % 3] == to)
		{
			return i;
		}
	}
	return -1;
}

/* One quickhull step: adds the farthest conflict point of face `start`. Degenerate when the
 * horizon is not a simple loop (round-off beyond anything double should produce). */
static cdResult AddEyePoint(Builder* b, int start, int stamp)
{
	HFace* f0 = &b->faces[start];
	int eye = f0->farthest;

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
		int e = b->horizonEdge[k];
		int a = f->v[e];
		b->horizonFrom[k] = a;
		b->horizonTo[k] = f->v[(e + 1) % 3];
		simple = simple && b->startAt[a] < 0;
		b->startAt[a] = k;
	}
	if (simple && horizonCount >= 3)
	{
		int steps = 0, k = 0;
		do
		{
			k = b->startAt[b->horizonTo[k]];
			++steps;
		} while (k >= 0 && k != 0 && steps <= horizonCount);
		simple = k == 0 && steps == horizonCount;
	}
	if (!simple || horizonCount < 3)
	{
		for (int k = 0; k < horizonCount; ++k)
		{
			b->startAt[b->horizonFrom[k]] = -1;
		}
		return CD_ERROR_DEGENERATE;
	}
	for (int k = 0; k < horizonCount; ++k)
	{
		b->horizonFace[k] = b->faces[b->horizonFace[k]].adj[b->horizonEdge[k]];
	}

	/* The visible faces go first, so that the cone reuses their slots; their points wait. */
	int orphanCount = 0;
	for (int i = 0; i < visibleCount; ++i)
	{
		int fi = b->visibleFaces[i];
		for (int q = b->faces[fi].conflict; q >= 0; q = b->nextConflict[q])
		{
			if (q != eye)
			{
				b->orphans[orphanCount++] = q;
			}
		}
		FreeFace(b, fi);
	}

	/* A cone of new faces from the eye to the horizon. */
	for (int k = 0; k < horizonCount; ++k)
	{
		int a = b->horizonFrom[k], c = b->horizonTo[k], g = b->horizonFace[k];
		int nf = AddFace(b, a, c, eye);
		HFace* other = &b->faces[g];
		int j = EdgeIndex(other->v, c, a);
		if (nf < 0 || j < 0)
		{
			return CD_ERROR_DEGENERATE;
		}
		b->newFaces[k] = nf;
		other->adj[j] = nf;
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
		b->startAt[b->horizonFrom[k]] = -1;
		b->endAt[b->horizonTo[k]] = -1;
	}

	/* The removed faces' points find a new face or lie inside. */
	for (int i = 0; i < orphanCount; ++i)
	{
		AssignPoint(b, b->newFaces, horizonCount, b->orphans[i]);
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
	/* Squared distances while searching, one square root for the decision. */
	double best = -1.0;
	for (int i = 0; i < 6; ++i)
	{
		for (int j = i + 1; j < 6; ++j)
		{
			HVec d = HSub(b->p[extremes[i]], b->p[extremes[j]]);
			double squared = HDot(d, d);
			if (squared > best)
			{
				best = squared;
				out[0] = extremes[i];
				out[1] = extremes[j];
			}
		}
	}
	if (sqrt(best) <= weld)
	{
		return CD_ERROR_DEGENERATE; /* all points coincide */
	}
	HVec axis = HNormalize(HSub(b->p[out[1]], b->p[out[0]]));
	best = -1.0;
	for (int i = 0; i < b->n; ++i)
	{
		HVec d = HSub(b->p[i], b->p[out[0]]);
		HVec off = HSub(d, HScale(HDot(d, axis), axis));
		double squared = HDot(off, off);
		if (squared > best)
		{
			best = squared;
			out[2] = i;
		}
	}
	if (sqrt(best) <= weld)
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
	int all[4];
	all[0] = AddFace(b, s[0], s[1], s[2]);
	all[1] = AddFace(b, s[0], s[3], s[1]);
	all[2] = AddFace(b, s[1], s[3], s[2]);
	all[3] = AddFace(b, s[2], s[3], s[0]);
	for (int i = 0; i < 4; ++i)
	{
		for (int e = 0; e < 3; ++e)
		{
			HFace* f = &b->faces[all[i]];
			int from = f->v[e], to = f->v[(e + 1) % 3];
			for (int j = 0; j < 4; ++j)
			{
				if (j != i && EdgeIndex(b->faces[all[j]].v, to, from) >= 0)
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

	/* Each step adds one point for good, so there are at most n steps. */
	int stamp = 0;
	while (b->pendingCount > 0)
	{
		int f = b->pending[b->pendingHead];
		b->pendingHead = b->pendingHead + 1 < b->faceCapacity ? b->pendingHead + 1 : 0;
		--b->pendingCount;
		b->faces[f].queued = false;
		if (b->faces[f].alive && b->faces[f].conflict >= 0)
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

/* Arrays sized by the face slots (F) and points (n) of the triangulation, from the arena. */
typedef struct HTri
{
	int v[3];
	int adj[3];
} HTri;

typedef struct Merged
{
	HTri* tris; /* the live triangles, renumbered in breadth-first order (neighbours nearby) */
	HVec* triNormal;
	double* triOffset;
	int triCount;
	int* group; /* per face: merged face index */
	int groupCount;
	int* loopNext;	  /* per boundary slot (face * 3 + edge): next boundary slot of the group */
	int* groupStart;  /* per group: one boundary slot */
	int* vertexFaces; /* per vertex: number of merged faces around it */
	SortKey* order;	  /* the live triangles, largest first */
	int orderCount;
	SortKey* orderSpare;
	int* queue;
	int* slotsInGroup;
	int* groupSlots;
	int* groupFirst; /* F + 1 */
	int* groupOrder; /* 3 F */
	int* vertexMap;	 /* n */
	int* slotEdge;	 /* 3 F */
	int* lastSlot;	 /* 3 F */
	int* firstSlot;	 /* 3 F */
} Merged;

static void TakeMerged(Arena* arena, Merged* m, size_t faces, size_t points)
{
	m->tris = (HTri*)ArenaTake(arena, faces, sizeof(HTri));
	m->triNormal = (HVec*)ArenaTake(arena, faces, sizeof(HVec));
	m->triOffset = (double*)ArenaTake(arena, faces, sizeof(double));
	m->group = (int*)ArenaTake(arena, faces, sizeof(int));
	m->loopNext = (int*)ArenaTake(arena, 3 * faces, sizeof(int));
	m->groupStart = (int*)ArenaTake(arena, faces, sizeof(int));
	m->vertexFaces = (int*)ArenaTake(arena, points, sizeof(int));
	m->order = (SortKey*)ArenaTake(arena, faces, sizeof(SortKey));
	m->orderSpare = (SortKey*)ArenaTake(arena, faces, sizeof(SortKey));
	m->queue = (int*)ArenaTake(arena, faces, sizeof(int));
	m->slotsInGroup = (int*)ArenaTake(arena, faces, sizeof(int));
	m->groupSlots = (int*)ArenaTake(arena, faces, sizeof(int));
	m->groupFirst = (int*)ArenaTake(arena, faces + 1, sizeof(int));
	m->groupOrder = (int*)ArenaTake(arena, 3 * faces, sizeof(int));
	m->vertexMap = (int*)ArenaTake(arena, points, sizeof(int));
	m->slotEdge = (int*)ArenaTake(arena, 3 * faces, sizeof(int));
	m->lastSlot = (int*)ArenaTake(arena, 3 * faces, sizeof(int));
	m->firstSlot = (int*)ArenaTake(arena, 3 * faces, sizeof(int));
}

/* Copies the live triangles into a dense array in breadth-first order from the first one, so that
 * the walks along merged faces touch nearby memory (quickhull's recycled slots are scattered);
 * then orders the merge seeds, once for every merge attempt: largest area first, ties by index. */
static void CompactTriangles(Builder* b, Merged* m)
{
	int first = 0;
	while (!b->faces[first].alive)
	{
		++first;
	}
	for (int f = 0; f < b->faceCount; ++f)
	{
		b->faces[f].mark = -1; /* the new index */
	}
	int* queue = m->queue;
	int head = 0, tail = 0;
	queue[tail++] = first;
	b->faces[first].mark = 0;
	while (head < tail)
	{
		const HFace* f = &b->faces[queue[head++]];
		for (int e = 0; e < 3; ++e)
		{
			HFace* g = &b->faces[f->adj[e]];
			if (g->mark < 0)
			{
				g->mark = tail;
				queue[tail++] = f->adj[e];
			}
		}
	}
	m->triCount = tail;
	for (int t = 0; t < tail; ++t)
	{
		const HFace* f = &b->faces[queue[t]];
		HTri* tri = &m->tris[t];
		for (int k = 0; k < 3; ++k)
		{
			tri->v[k] = f->v[k];
			tri->adj[k] = b->faces[f->adj[k]].mark;
		}
		m->triNormal[t] = f->normal;
		m->triOffset[t] = f->offset;
		HVec a = b->p[f->v[0]];
		double area = HLength(HCross(HSub(b->p[f->v[1]], a), HSub(b->p[f->v[2]], a)));
		m->order[t].key = ~OrderedBits(area);
		m->order[t].index = t;
	}
	m->order = SortKeys(m->order, m->orderSpare, tail);
	m->orderCount = tail;
}

/* Grows each face from the largest unmerged triangle through neighbours whose three vertices lie
 * within `mergeTolerance` of the seed's plane. */
static void MergeTriangles(const Builder* b, double mergeTolerance, Merged* m)
{
	int* queue = m->queue;
	for (int f = 0; f < m->triCount; ++f)
	{
		m->group[f] = -1;
	}
	m->groupCount = 0;
	for (int i = 0; i < m->orderCount; ++i)
	{
		int seed = m->order[i].index;
		if (m->group[seed] >= 0)
		{
			continue;
		}
		int g = m->groupCount++;
		HVec n = m->triNormal[seed];
		double d = m->triOffset[seed];
		int head = 0, tail = 0;
		queue[tail++] = seed;
		m->group[seed] = g;
		while (head < tail)
		{
			const HTri* f = &m->tris[queue[head++]];
			for (int e = 0; e < 3; ++e)
			{
				int other = f->adj[e];
				if (m->group[other] >= 0)
				{
					continue;
				}
				/* No test of the normal: a sliver's normal is noise, its vertices are not. (The
				 * far side of a slab this thin was rejected as flat.) Only the vertex opposite the
				 * shared edge is tested: the edge's vertices are f's, already within the tolerance
				 * (the seed's own to round-off, and a negative tolerance merges nothing anyway). */
				const HTri* o = &m->tris[other];
				int a = f->v[e], c = f->v[e == 2 ? 0 : e + 1];
				int opposite = o->v[0] != a && o->v[0] != c
								   ? o->v[0]
								   : (o->v[1] != a && o->v[1] != c ? o->v[1] : o->v[2]);
				if (fabs(HDot(n, b->p[opposite]) - d) <= mergeTolerance)
				{
					m->group[other] = g;
					queue[tail++] = other;
				}
			}
		}
	}
}

/* Links each merged face's boundary (triangle edges whose neighbour is in another group) into one
 * loop, and counts the merged faces around each vertex. A group whose boundary is not one simple
 * loop cannot come from a convex surface; it is reported as degenerate. */
static cdResult LinkBoundaries(const Builder* b, Merged* m, int* startAt)
{
	int total = m->triCount;
	for (int g = 0; g < m->groupCount; ++g)
	{
		m->groupStart[g] = -1;
	}
	for (int i = 0; i < b->n; ++i)
	{
		m->vertexFaces[i] = 0;
	}
	int* groupSlots = m->groupSlots;
	int* slotsInGroup = m->slotsInGroup;
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
		for (int e = 0; e < 3; ++e)
		{
			if (m->group[m->tris[f].adj[e]] != m->group[f])
			{
				++slotsInGroup[m->group[f]];
				++m->vertexFaces[m->tris[f].v[e]];
			}
		}
	}

	cdResult result = CD_OK;
	/* Per group: map each boundary edge's start vertex to its slot, then link a -> b to the edge
	 * starting at b. startAt is a per-vertex scratch array of -1s, restored before moving on. */
	int* groupOrder = m->groupOrder;
	int* groupFirst = m->groupFirst;
	groupFirst[0] = 0;
	for (int g = 0; g < m->groupCount; ++g)
	{
		groupFirst[g + 1] = groupFirst[g] + slotsInGroup[g];
		groupSlots[g] = groupFirst[g];
	}
	for (int f = 0; f < total; ++f)
	{
		for (int e = 0; e < 3; ++e)
		{
			if (m->group[m->tris[f].adj[e]] != m->group[f])
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
			int a = m->tris[slot / 3].v[slot % 3];
			if (startAt[a] >= 0)
			{
				result = CD_ERROR_DEGENERATE; /* two boundary edges leave one vertex: pinched */
			}
			startAt[a] = slot;
		}
		for (int s = first; s < last && result == CD_OK; ++s)
		{
			int slot = groupOrder[s];
			int to = m->tris[slot / 3].v[(slot % 3 + 1) % 3];
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
			startAt[m->tris[slot / 3].v[slot % 3]] = -1;
		}
	}
	return result;
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
	int total = m->triCount;
	/* Kept vertices: those where at least three merged faces meet (-2 until numbered in the
	 * order the faces reach them, for locality). A vertex between only two lies on their common
	 * edge and is dropped (-1). */
	int* vertexMap = m->vertexMap;
	int vertexCount = 0;
	for (int i = 0; i < b->n; ++i)
	{
		bool kept = m->vertexFaces[i] >= 3;
		vertexMap[i] = kept ? -2 : -1;
		vertexCount += kept;
	}
	int halfEdgeCount = 0;
	for (int f = 0; f < total; ++f)
	{
		for (int e = 0; e < 3; ++e)
		{
			int slot = 3 * f + e;
			if (m->loopNext[slot] >= 0 && vertexMap[m->tris[f].v[e]] != -1)
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
	size_t columnsSize = AlignUp(3 * (size_t)CD3_HULL_COLUMN_STRIDE(vertexCount) * sizeof(cdReal));
	size_t queryDataSize = AlignUp(cd3HullQueryDataSize(halfEdgeCount, faceCount));
	char* memory = (char*)cdAlloc(headerSize + verticesSize + edgesSize + faceEdgesSize + planesSize +
								  columnsSize + queryDataSize);
	/* Each half-edge covers a chain of boundary slots (the dropped vertices in between); its
	 * twin is the half-edge covering the twin of its chain's last slot. */
	int* slotEdge = m->slotEdge;
	int* lastSlot = m->lastSlot;
	int* firstSlot = m->firstSlot;
	if (memory == NULL)
	{
		return CD_ERROR_OUT_OF_MEMORY;
	}
	cd3Hull* hull = (cd3Hull*)memory;
	cd3Vec* vertices = (cd3Vec*)(memory + headerSize);
	cd3HullHalfEdge* edges = (cd3HullHalfEdge*)(memory + headerSize + verticesSize);
	int32_t* faceEdges = (int32_t*)(memory + headerSize + verticesSize + edgesSize);
	cd3Plane* planes = (cd3Plane*)(memory + headerSize + verticesSize + edgesSize + faceEdgesSize);
	cdReal* columns = (cdReal*)(memory + headerSize + verticesSize + edgesSize + faceEdgesSize + planesSize);
	memset(hull, 0, sizeof(*hull));
	int numbered = 0;

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
			int point = m->tris[slot / 3].v[slot % 3];
			int v = vertexMap[point];
			if (v == -2)
			{
				v = vertexMap[point] = numbered++;
				vertices[v] = input[inputIndex[point]];
			}
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
		const HTri* lastFace = &m->tris[last / 3];
		HVec from = b->p[m->tris[slot / 3].v[slot % 3]], to = b->p[lastFace->v[(last % 3 + 1) % 3]];
		for (; slot != last && ok; slot = m->loopNext[slot])
		{
			const HTri* f = &m->tris[slot / 3];
			ok = LineDistance(b->p[f->v[(slot % 3 + 1) % 3]], from, to) <= collinearTolerance;
		}
	}
	if (ok)
	{
		for (int e = 0; e < halfEdgeCount && ok; ++e)
		{
			int slot = lastSlot[e];
			const HTri* f = &m->tris[slot / 3];
			int other = f->adj[slot % 3];
			int j = EdgeIndex(m->tris[other].v, f->v[(slot % 3 + 1) % 3], f->v[slot % 3]);
			ok = j >= 0 && slotEdge[3 * other + j] >= 0;
			if (ok)
			{
				edges[e].twin = slotEdge[3 * other + j];
			}
		}
	}
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

	int stride = CD3_HULL_COLUMN_STRIDE(vertexCount);
	for (int i = 0; i < stride; ++i)
	{
		cd3Vec v = vertices[i < vertexCount ? i : 0];
		columns[i] = v.x;
		columns[stride + i] = v.y;
		columns[2 * stride + i] = v.z;
	}
	hull->vertexColumns = columns;
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
	if (queryDataSize > 0)
	{
		void* queryData =
			memory + headerSize + verticesSize + edgesSize + faceEdgesSize + planesSize + columnsSize;
		cd3BuildHullQueryData(hull, queryData);
		hull->queryData = queryData;
	}
	*out = hull;
	return CD_OK;
}

/* ---- welding ------------------------------------------------------------------------------------ */

/* Keeps one point of every cluster closer than `weld` (sweep along x); returns the count kept and
 * their input indices in `kept`. The first point (in input order among equal x) wins. */
static int WeldPoints(const HVec* p, int count, double weld, SortKey* keys, SortKey* spare, bool* removed,
					  int* kept)
{
	for (int i = 0; i < count; ++i)
	{
		keys[i].key = OrderedBits(p[i].x);
		keys[i].index = i;
		removed[i] = false;
	}
	const SortKey* sorted = SortKeys(keys, spare, count);
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
		for (int j = i + 1; j < count && p[sorted[j].index].x - p[a].x <= weld; ++j)
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

static cdResult ValidateHull(const cd3Hull* hull, bool global, int* vertexScratch);

/* Every input point below every face plane within the hull's tolerance, checked when there are at
 * most 131072 point-face pairs (a fraction of the build's cost; as the global plane test of
 * CheckBuiltHull): a sheet 1e30 wide in the double build (fuzz_hull3) lost its extreme point, 9
 * tolerances above a face; the build is then retried like any other that fails its checks. */
static bool ContainsPoints(const cd3Hull* hull, const cd3Vec* points, int count)
{
	if ((long)count * (long)hull->faceCount > 131072)
	{
		return true;
	}
	double tolerance = (double)cd3Hull_GetTolerance(hull);
	for (int f = 0; f < hull->faceCount; ++f)
	{
		cd3Plane plane = hull->planes[f];
		for (int i = 0; i < count; ++i)
		{
			double height = (double)plane.normal.x * (double)points[i].x +
							(double)plane.normal.y * (double)points[i].y +
							(double)plane.normal.z * (double)points[i].z - (double)plane.offset;
			if (height > tolerance)
			{
				return false;
			}
		}
	}
	return true;
}

/* The supported range (geometry3.h): the diagonal of the bounds over the smallest width across a
 * face (the depth of the hull below that face's plane), in double. A face is done as soon as one
 * vertex lies deep enough below it: a few vertices for nearly every face. */
static bool WithinAspectRatio(const cd3Hull* hull)
{
	cd3Vec d = cd3Sub(hull->bounds.max, hull->bounds.min);
	double diagonal = sqrt((double)d.x * (double)d.x + (double)d.y * (double)d.y + (double)d.z * (double)d.z);
	double needed = diagonal / (double)CD3_MAX_HULL_ASPECT_RATIO;
	for (int f = 0; f < hull->faceCount; ++f)
	{
		cd3Plane plane = hull->planes[f];
		bool deep = false;
		for (int i = 0; i < hull->vertexCount && !deep; ++i)
		{
			cd3Vec v = hull->vertices[i];
			double below = (double)plane.offset -
						   ((double)plane.normal.x * (double)v.x + (double)plane.normal.y * (double)v.y +
							(double)plane.normal.z * (double)v.z);
			deep = below >= needed;
		}
		if (!deep)
		{
			return false;
		}
	}
	return true;
}
static cdResult CheckBuiltHull(const cd3Hull* hull, int* vertexScratch);

/* The scratch of a build of `count` points, carved from one arena. */
typedef struct Scratch
{
	HVec* shifted;
	HVec* welded;
	SortKey* keys;
	SortKey* spareKeys;
	bool* removed;
	int* kept;
	Builder b;
	Merged m;
} Scratch;

static size_t TakeScratch(Arena* arena, Scratch* s, int count)
{
	size_t n = (size_t)count;
	/* A triangulated sphere on V <= n vertices has 2 V - 4 faces; slots are recycled. */
	size_t faces = 2 * n + 8;
	s->shifted = (HVec*)ArenaTake(arena, n, sizeof(HVec));
	s->welded = (HVec*)ArenaTake(arena, n, sizeof(HVec));
	s->keys = (SortKey*)ArenaTake(arena, n, sizeof(SortKey));
	s->spareKeys = (SortKey*)ArenaTake(arena, n, sizeof(SortKey));
	s->removed = (bool*)ArenaTake(arena, n, sizeof(bool));
	s->kept = (int*)ArenaTake(arena, n, sizeof(int));
	Builder* b = &s->b;
	b->faceCapacity = (int)faces;
	b->faces = (HFace*)ArenaTake(arena, faces, sizeof(HFace));
	b->nextConflict = (int*)ArenaTake(arena, n, sizeof(int));
	b->startAt = (int*)ArenaTake(arena, n, sizeof(int));
	b->endAt = (int*)ArenaTake(arena, n, sizeof(int));
	b->orphans = (int*)ArenaTake(arena, n, sizeof(int));
	b->pending = (int*)ArenaTake(arena, faces, sizeof(int));
	b->stack = (int*)ArenaTake(arena, faces, sizeof(int));
	b->visibleFaces = (int*)ArenaTake(arena, faces, sizeof(int));
	b->newFaces = (int*)ArenaTake(arena, 3 * faces, sizeof(int));
	b->horizonFace = (int*)ArenaTake(arena, 3 * faces, sizeof(int));
	b->horizonEdge = (int*)ArenaTake(arena, 3 * faces, sizeof(int));
	b->horizonFrom = (int*)ArenaTake(arena, 3 * faces, sizeof(int));
	b->horizonTo = (int*)ArenaTake(arena, 3 * faces, sizeof(int));
	TakeMerged(arena, &s->m, faces, n);
	return arena->used;
}

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

	Scratch s;
	memset(&s, 0, sizeof(s));
	Arena arena = {NULL, 0};
	size_t scratchSize = TakeScratch(&arena, &s, count);
	arena.base = (char*)cdAlloc(scratchSize);
	if (arena.base == NULL)
	{
		return CD_ERROR_OUT_OF_MEMORY;
	}
	arena.used = 0;
	TakeScratch(&arena, &s, count);
	Builder* b = &s.b;
	Merged* m = &s.m;
	b->freeFace = -1;

	for (int i = 0; i < count; ++i)
	{
		s.shifted[i] = HSub(HMake((double)points[i].x, (double)points[i].y, (double)points[i].z), center);
	}
	int keptCount =
		WeldPoints(s.shifted, count, HULL_WELD_REL * extent, s.keys, s.spareKeys, s.removed, s.kept);
	for (int i = 0; i < keptCount; ++i)
	{
		s.welded[i] = s.shifted[s.kept[i]];
		b->startAt[i] = -1;
		b->endAt[i] = -1;
		b->nextConflict[i] = -1;
	}
	b->p = s.welded;
	b->n = keptCount;
	b->tol = HULL_BUILD_REL * extent;
	cdResult result = keptCount < 4 ? CD_ERROR_DEGENERATE : RunQuickhull(b, HULL_WELD_REL * extent);
	if (result == CD_OK)
	{
		CompactTriangles(b, m);
	}
	/* Greedy merging can leave a face notched by a nearly coplanar neighbour when points sit
	 * right at the merge tolerance. Such a merge is retried with smaller tolerances, and at last
	 * without merging: the bare triangulation is convex to round-off, which the validator's
	 * tolerance covers. */
	const double mergeScales[4] = {1.0, 1.0 / 64.0, 0.0, -1.0};
	for (int attempt = 0; attempt < 4 && result == CD_OK; ++attempt)
	{
		double mergeTolerance = HULL_MERGE_REL * extent * mergeScales[attempt];
		mergeTolerance = mergeScales[attempt] < 0.0 ? -1.0 : cdMaxDouble(mergeTolerance, 4.0 * b->tol);
		MergeTriangles(b, mergeTolerance, m);
		result = LinkBoundaries(b, m, b->startAt);
		if (result == CD_OK)
		{
			result = BuildHull(b, m, points, s.kept, cdMaxDouble(mergeTolerance, 4.0 * b->tol), hull);
		}
		if (result == CD_OK)
		{
			/* The arena's per-vertex scratch is free by now. */
			cdResult valid = CheckBuiltHull(*hull, m->vertexMap);
			if (valid == CD_OK && !ContainsPoints(*hull, points, count))
			{
				valid = CD_ERROR_DEGENERATE;
			}
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
	cdFree(arena.base);
	if (result == CD_OK && !WithinAspectRatio(*hull))
	{
		cd3DestroyHull(*hull);
		*hull = NULL;
		result = CD_ERROR_OUT_OF_RANGE;
	}
	return result;
}

void cd3DestroyHull(cd3Hull* hull)
{
	cdFree(hull);
}

cdReal cd3Hull_GetTolerance(const cd3Hull* hull)
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

static bool IsFinite(const cd3Hull* hull)
{
	for (int i = 0; i < hull->vertexCount; ++i)
	{
		if (!cd3IsValidVec(hull->vertices[i]))
		{
			return false;
		}
	}
	for (int i = 0; i < hull->faceCount; ++i)
	{
		if (!cd3IsValidVec(hull->planes[i].normal) || !cdIsValidReal(hull->planes[i].offset))
		{
			return false;
		}
	}
	return cd3IsValidVec(hull->centroid) && cdIsValidReal(hull->volume) && cd3IsValidVec(hull->bounds.min) &&
		   cd3IsValidVec(hull->bounds.max);
}

/* Unit normal; planar and convex: vertices on the plane, each corner turning counter-clockwise
 * about the outward normal (this also rejects inward normals). */
static cdResult CheckFace(const cd3Hull* hull, int face, cdReal tolerance)
{
	cd3Plane plane = hull->planes[face];
	if (cdAbs(cd3Length(plane.normal) - CD_R(1.0)) > CD_R(64.0) * CD_REAL_EPSILON)
	{
		return CD_ERROR_NOT_NORMALIZED;
	}
	int start = hull->faceEdges[face], h = start;
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
	return CD_OK;
}

/* The vertices of the faces around `face` lie below its plane: on a closed manifold whose every
 * face passes, that makes the hull convex up to round-off. */
static bool NeighboursBelow(const cd3Hull* hull, int face, cdReal tolerance)
{
	cd3Plane plane = hull->planes[face];
	int start = hull->faceEdges[face], h = start;
	do
	{
		int t = hull->edges[h].twin, k = t;
		do
		{
			if (cd3Dot(plane.normal, hull->vertices[hull->edges[k].origin]) - plane.offset > tolerance)
			{
				return false;
			}
			k = hull->edges[k].next;
		} while (k != t);
		h = hull->edges[h].next;
	} while (h != start);
	return true;
}

/* Twice the area (Newell) over the longest edge, the polygon's height in the thin direction, below
 * 64 tolerances (compared squared: an overflow counts as thin, which only costs time). */
static bool IsThin(const cd3Hull* hull, int face, cdReal tolerance)
{
	int start = hull->faceEdges[face], h = start;
	cd3Vec origin = hull->vertices[hull->edges[start].origin];
	cd3Vec newell = CD3_VEC_ZERO;
	cdReal longestSquared = CD_R(0.0);
	do
	{
		cd3Vec p = cd3Sub(hull->vertices[hull->edges[h].origin], origin);
		cd3Vec q = cd3Sub(hull->vertices[hull->edges[hull->edges[h].next].origin], origin);
		newell = cd3Add(newell, cd3Cross(p, q));
		cd3Vec edge = cd3Sub(q, p);
		longestSquared = cdMax(longestSquared, cd3Dot(edge, edge));
		h = hull->edges[h].next;
	} while (h != start);
	cdReal height = CD_R(64.0) * tolerance;
	return cd3Dot(newell, newell) <= height * height * longestSquared;
}

static bool AllBelow(const cd3Hull* hull, int face, cdReal tolerance)
{
	cd3Plane plane = hull->planes[face];
	for (int k = 0; k < hull->vertexCount; ++k)
	{
		if (cd3Dot(plane.normal, hull->vertices[k]) - plane.offset > tolerance)
		{
			return false;
		}
	}
	return true;
}

/* Outward: the centre of volume lies strictly below every face. */
static cdResult CheckOutward(const cd3Hull* hull)
{
	if (!(hull->volume > CD_R(0.0)))
	{
		return CD_ERROR_DEGENERATE;
	}
	for (int i = 0; i < hull->faceCount; ++i)
	{
		if (cd3Dot(hull->planes[i].normal, hull->centroid) - hull->planes[i].offset >= CD_R(0.0))
		{
			return CD_ERROR_DEGENERATE;
		}
	}
	return CD_OK;
}

/* The check of a hull just built: finite figures (the volume of a hull near the largest floats
 * overflows) and the local geometry of every face (merging can notch a face, and a bare sliver
 * triangle's plane is noise). Its topology holds by construction: every merged
 * face is a disc with one simple boundary loop, so the faces, twins and fans form a sphere (the
 * full validation confirms it in debug builds). */
static cdResult CheckBuiltHull(const cd3Hull* hull, int* vertexScratch)
{
	if (!IsFinite(hull))
	{
		return CD_ERROR_NOT_FINITE;
	}
	cdReal tolerance = cd3Hull_GetTolerance(hull);
	/* A thin face's plane, tilted by round-off, can pass its neighbours and not a far vertex
	 * (fuzz_hull3, double build: slivers 1e-10 high and 100 long in lattices far from the origin,
	 * a vertex up to twice the tolerance above; also a face that is not thin, of a lattice hull of
	 * 36 vertices, 1.2 tolerances below a far vertex): thin faces, and every face of a hull of at
	 * most 131072 vertex-face pairs (about 250 vertices, a fraction of the build's cost), get the
	 * global test (every vertex below the plane). */
	bool small = (long)hull->vertexCount * (long)hull->faceCount <= 131072;
	for (int i = 0; i < hull->faceCount; ++i)
	{
		cdResult result = CheckFace(hull, i, tolerance);
		if (result != CD_OK)
		{
			return result;
		}
		bool global = small || IsThin(hull, i, tolerance);
		if (!(global ? AllBelow(hull, i, tolerance) : NeighboursBelow(hull, i, tolerance)))
		{
			return CD_ERROR_DEGENERATE;
		}
	}
	cdResult result = CheckOutward(hull);
#if !defined(NDEBUG) || defined(CD_ENABLE_ASSERT)
	if (result == CD_OK)
	{
		result = ValidateHull(hull, false, vertexScratch);
		CD_ASSERT(result == CD_OK);
	}
#else
	(void)vertexScratch;
#endif
	return result;
}

static bool ValidIndex(int32_t index, int count)
{
	return index >= 0 && index < count;
}

/* `global`: every vertex against every plane (O(V F)); otherwise only the vertices of each face's
 * neighbours, which on a closed manifold with convex edges implies the same up to round-off.
 * `vertexScratch`: room for one int per vertex, or NULL to allocate it. */
static cdResult ValidateHull(const cd3Hull* hull, bool global, int* vertexScratch)
{
	if (hull == NULL || hull->vertices == NULL || hull->edges == NULL || hull->faceEdges == NULL ||
		hull->planes == NULL || hull->vertexCount < 4 || hull->faceCount < 4 || hull->edgeCount < 12 ||
		(hull->edgeCount & 1) != 0)
	{
		return CD_ERROR_INVALID_ARGUMENT;
	}
	int v = hull->vertexCount, e = hull->edgeCount, f = hull->faceCount;
	if (!IsFinite(hull))
	{
		return CD_ERROR_NOT_FINITE;
	}
	/* The support searches read the columns, the rest the vertices: they must say the same. */
	if (hull->vertexColumns != NULL)
	{
		int stride = CD3_HULL_COLUMN_STRIDE(v);
		for (int i = 0; i < stride; ++i)
		{
			cd3Vec p = hull->vertices[i < v ? i : 0];
			if (!(hull->vertexColumns[i] == p.x && hull->vertexColumns[stride + i] == p.y &&
				  hull->vertexColumns[2 * stride + i] == p.z))
			{
				return CD_ERROR_INVALID_ARGUMENT;
			}
		}
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
	int* fan = vertexScratch != NULL ? vertexScratch : (int*)AllocArray((size_t)v, sizeof(int));
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
	/* Around the origin: twin(h) ends at the origin, next(twin(h)) leaves it again. That step
	 * permutes the half-edges leaving a vertex (next and twin are permutations), so they form one
	 * fan exactly when the orbit of any one of them holds all of them. A walked vertex's count
	 * turns negative. */
	bool manifold = true;
	for (int i = 0; i < e && manifold; ++i)
	{
		int origin = hull->edges[i].origin;
		if (fan[origin] <= 0)
		{
			continue;
		}
		int steps = 0, h = i;
		do
		{
			h = hull->edges[hull->edges[h].twin].next;
			++steps;
		} while (h != i && steps <= e);
		manifold = h == i && steps == fan[origin] && steps >= 3;
		fan[origin] = -steps;
	}
	for (int i = 0; i < v && manifold; ++i)
	{
		manifold = fan[i] < 0; /* every vertex used */
	}
	if (vertexScratch == NULL)
	{
		cdFree(fan);
	}
	if (!manifold)
	{
		return CD_ERROR_INVALID_ARGUMENT;
	}
	/* The queries read the precomputed data instead of the edges and planes: it must be theirs. */
	if (hull->queryData != NULL)
	{
		union
		{
			uint64_t align;
			unsigned char bytes[4096]; /* the largest query data: 2,064 bytes (double) */
		} expected;
		size_t size = cd3HullQueryDataSize(e, f);
		if (size == 0 || size > sizeof(expected.bytes))
		{
			return CD_ERROR_INVALID_ARGUMENT;
		}
		cd3BuildHullQueryData(hull, expected.bytes);
		if (memcmp(expected.bytes, hull->queryData, size) != 0)
		{
			return CD_ERROR_INVALID_ARGUMENT;
		}
	}

	cdReal tolerance = cd3Hull_GetTolerance(hull);
	for (int i = 0; i < f; ++i)
	{
		cdResult result = CheckFace(hull, i, tolerance);
		if (result != CD_OK)
		{
			return result;
		}
		if (!(global ? AllBelow(hull, i, tolerance) : NeighboursBelow(hull, i, tolerance)))
		{
			return CD_ERROR_DEGENERATE;
		}
	}
	return CheckOutward(hull);
}

cdResult cd3ValidateHull(const cd3Hull* hull)
{
	cdResult result = ValidateHull(hull, true, NULL);
	return result == CD_OK && !WithinAspectRatio(hull) ? CD_ERROR_OUT_OF_RANGE : result;
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
