/* Triangle meshes: input checks, the binned SAH build of the static BVH, edge flags for internal
 * edges, stats and the validator. The queries are in src/query/mesh_query3.c and
 * mesh_manifold3.c. */
#include "geometry/mesh3_internal.h"

#include <math.h>
#include <string.h>

#define SAH_BINS 16
#define MAX_LEAF_SIZE 8
/* Relative cost of visiting a node against testing one triangle. */
#define TRAVERSAL_COST 1.0

/* ---- float bounds rounded outward ------------------------------------------------------------- */

static float FloatDown(cdReal x)
{
	float f = (float)x;
	return (cdReal)f > x ? nextafterf(f, -FLT_MAX) : f;
}

static float FloatUp(cdReal x)
{
	float f = (float)x;
	return (cdReal)f < x ? nextafterf(f, FLT_MAX) : f;
}

static cdReal MaxAbs(cd3Vec v)
{
	return cdMax(cdAbs(v.x), cdMax(cdAbs(v.y), cdAbs(v.z)));
}

/* A triangle's bounds grown by the tolerances of the ray, overlap and point queries against it
 * (cd3RaycastTriangle: 4 double epsilons, the overlap tests: 16 epsilons of the coordinates), so
 * an answer the triangle routine gives is never culled. */
static cd3Aabb PaddedTriangleBounds(cd3Triangle t)
{
	cd3Aabb b = cd3ComputeTriangleAabb(t);
	cdReal magnitude = cdMax(MaxAbs(b.min), MaxAbs(b.max));
	return cd3AabbInflate(b, CD_R(64.0) * CD_REAL_EPSILON * magnitude);
}

/* ---- the build ---------------------------------------------------------------------------------- */

typedef struct BuildTriangle
{
	cd3Aabb bounds;
	cd3Vec centroid;
	int32_t slot; /* index in the kept-triangle arrays before reordering */
} BuildTriangle;

typedef struct BuildNode
{
	cd3Aabb bounds;
	int32_t first;
	int32_t count;
	int32_t leaves;				  /* leaves in the subtree, for the wide collapse */
	int32_t spanFirst, spanCount; /* the subtree's triangles */
} BuildNode;

typedef struct Bin
{
	cd3Aabb bounds;
	int count;
} Bin;

static cd3Aabb EmptyAabb(void)
{
	cd3Aabb b = {{CD_REAL_MAX, CD_REAL_MAX, CD_REAL_MAX}, {-CD_REAL_MAX, -CD_REAL_MAX, -CD_REAL_MAX}};
	return b;
}

/* Area with the empty box counting zero (its extents are negative). */
static double Area(cd3Aabb b)
{
	if (!(b.min.x <= b.max.x))
	{
		return 0.0;
	}
	double dx = (double)b.max.x - (double)b.min.x;
	double dy = (double)b.max.y - (double)b.min.y;
	double dz = (double)b.max.z - (double)b.min.z;
	return 2.0 * (dx * dy + dy * dz + dz * dx);
}

typedef struct Split
{
	int axis; /* -1: none better than a leaf */
	int bin;  /* left side: bins 0..bin */
	double cost;
	cdReal lower, scale;
	int binCount;
} Split;

static int BinOf(cd3Vec centroid, int axis, cdReal lower, cdReal scale, int binCount)
{
	/* In double and tested before the conversion: with coordinates near the largest floats a
	 * centroid or the centroids' extent overflows, and (inf - lower) * 0 is NaN, which no int
	 * conversion may see. Such triangles all land in bin 0 (the build falls back to halving). */
	double t = ((double)cd3GetComponent(centroid, axis) - (double)lower) * (double)scale;
	if (!(t > 0.0))
	{
		return 0;
	}
	return t >= (double)binCount ? binCount - 1 : (int)t;
}

/* One pass over the triangles bins them on all three axes at once (each axis over the
 * centroids' extent), then each axis's sweeps find its best split. */
static Split FindSplit(const BuildTriangle* tris, int first, int count, double parentArea, cd3Aabb centroids)
{
	Split best = {-1, 0, 0.0, CD_R(0.0), CD_R(0.0), 0};
	best.cost = (double)count; /* a leaf */
	Bin bins[3][SAH_BINS];
	/* Small nodes get as many bins as triangles: the sweeps cost per bin, and most nodes are small. */
	int binCount = count < SAH_BINS ? (count < 4 ? 4 : count) : SAH_BINS;
	cdReal lower[3], scale[3];
	bool usable[3];
	bool any = false;
	for (int axis = 0; axis < 3; ++axis)
	{
		lower[axis] = cd3GetComponent(centroids.min, axis);
		cdReal extent = cd3GetComponent(centroids.max, axis) - lower[axis];
		scale[axis] = extent > CD_R(0.0) ? (cdReal)binCount / extent : CD_R(0.0);
		usable[axis] = extent > CD_R(0.0) && cdIsValidReal(scale[axis]);
		any = any || usable[axis];
		for (int b = 0; b < binCount; ++b)
		{
			bins[axis][b].bounds = EmptyAabb();
			bins[axis][b].count = 0;
		}
	}
	if (!any)
	{
		return best;
	}
	for (int i = first; i < first + count; ++i)
	{
		for (int axis = 0; axis < 3; ++axis)
		{
			if (usable[axis])
			{
				Bin* bin = &bins[axis][BinOf(tris[i].centroid, axis, lower[axis], scale[axis], binCount)];
				bin->bounds = cd3AabbUnion(bin->bounds, tris[i].bounds);
				++bin->count;
			}
		}
	}
	for (int axis = 0; axis < 3; ++axis)
	{
		if (!usable[axis])
		{
			continue;
		}
		double rightArea[SAH_BINS];
		int rightCount[SAH_BINS];
		cd3Aabb sweep = EmptyAabb();
		int n = 0;
		for (int b = binCount - 1; b > 0; --b)
		{
			sweep = cd3AabbUnion(sweep, bins[axis][b].bounds);
			n += bins[axis][b].count;
			rightArea[b] = Area(sweep);
			rightCount[b] = n;
		}
		sweep = EmptyAabb();
		n = 0;
		for (int b = 0; b < binCount - 1; ++b)
		{
			sweep = cd3AabbUnion(sweep, bins[axis][b].bounds);
			n += bins[axis][b].count;
			if (n == 0 || rightCount[b + 1] == 0)
			{
				continue;
			}
			double cost = TRAVERSAL_COST + (Area(sweep) * n + rightArea[b + 1] * rightCount[b + 1]) /
											   (parentArea > 0.0 ? parentArea : 1.0);
			if (cost < best.cost)
			{
				best.axis = axis;
				best.bin = b;
				best.cost = cost;
				best.lower = lower[axis];
				best.scale = scale[axis];
				best.binCount = binCount;
			}
		}
	}
	return best;
}

/* Splits the range at `mid`, or returns false when the node becomes a leaf. */
static bool SplitRange(BuildTriangle* tris, int first, int count, cd3Aabb bounds, cd3Aabb centroids,
					   int depth, int* mid)
{
	if (count <= 1)
	{
		return false;
	}
	if (depth < CD3_MESH_SAH_DEPTH)
	{
		Split split = FindSplit(tris, first, count, Area(bounds), centroids);
		if (split.axis >= 0)
		{
			int i = first, j = first + count - 1;
			while (i <= j)
			{
				if (BinOf(tris[i].centroid, split.axis, split.lower, split.scale, split.binCount) <=
					split.bin)
				{
					++i;
				}
				else
				{
					BuildTriangle t = tris[i];
					tris[i] = tris[j];
					tris[j] = t;
					--j;
				}
			}
			if (i > first && i < first + count)
			{
				*mid = i;
				return true;
			}
		}
	}
	if (count <= MAX_LEAF_SIZE)
	{
		return false;
	}
	/* No useful SAH split (coincident centroids) or too deep: halves by index keep the depth
	 * logarithmic. */
	*mid = first + count / 2;
	return true;
}

typedef struct BuildTask
{
	int node;
	int depth;
} BuildTask;

/* Builds into `nodes` (room for 2 n - 1) and returns the node count. */
static int BuildTree(BuildTriangle* tris, int n, BuildNode* nodes, int* depthOut, int* leafCountOut,
					 double* sahOut)
{
	BuildTask stack[2 * CD3_MESH_MAX_DEPTH + 8];
	int top = 0;
	int nodeCount = 1;
	int leafCount = 0;
	int maxDepth = 0;
	double sah = 0.0;
	nodes[0].first = 0;
	nodes[0].count = n;
	stack[top++] = (BuildTask){0, 1};
	double rootArea = 0.0;
	while (top > 0)
	{
		BuildTask task = stack[--top];
		BuildNode* node = nodes + task.node;
		cd3Aabb bounds = EmptyAabb(), centroids = EmptyAabb();
		for (int i = node->first; i < node->first + node->count; ++i)
		{
			bounds = cd3AabbUnion(bounds, tris[i].bounds);
			centroids.min = cd3Min(centroids.min, tris[i].centroid);
			centroids.max = cd3Max(centroids.max, tris[i].centroid);
		}
		node->bounds = bounds;
		if (task.node == 0)
		{
			rootArea = Area(bounds) > 0.0 ? Area(bounds) : 1.0;
		}
		maxDepth = task.depth > maxDepth ? task.depth : maxDepth;
		int mid;
		if (!SplitRange(tris, node->first, node->count, bounds, centroids, task.depth, &mid))
		{
			++leafCount;
			sah += Area(bounds) / rootArea * node->count;
			continue;
		}
		sah += TRAVERSAL_COST * Area(bounds) / rootArea;
		int left = nodeCount;
		nodeCount += 2;
		nodes[left].first = node->first;
		nodes[left].count = mid - node->first;
		nodes[left + 1].first = mid;
		nodes[left + 1].count = node->first + node->count - mid;
		node->first = left;
		node->count = 0;
		stack[top++] = (BuildTask){left + 1, task.depth + 1};
		stack[top++] = (BuildTask){left, task.depth + 1};
	}
	*depthOut = maxDepth;
	*leafCountOut = leafCount;
	*sahOut = sah;
	return nodeCount;
}

/* ---- the wide tree ------------------------------------------------------------------------------- */

/* The binary children gathered under one wide node, in order (a child replaced by its two
 * children in place keeps the leaves in order). A subtree of at most CD3_MESH_WIDTH leaves is
 * flattened into one node. Above that, the inner child of largest area among those with more
 * than CD3_MESH_WIDTH leaves is opened while there is room, so that the subtrees left below
 * fill their nodes; then the smallest inner children are opened into the room left, which
 * lifts their leaves into this node instead of making nearly empty nodes of them. */
static int GatherChildren(const BuildNode* nodes, int binary, int kids[CD3_MESH_WIDTH])
{
	int n = 0;
	if (nodes[binary].count > 0)
	{
		kids[n++] = binary; /* a root that is a leaf */
		return n;
	}
	kids[n++] = nodes[binary].first;
	kids[n++] = nodes[binary].first + 1;
	while (n < CD3_MESH_WIDTH)
	{
		int pick = -1;
		double best = -1.0;
		for (int i = 0; i < n; ++i)
		{
			const BuildNode* kid = nodes + kids[i];
			if (kid->count == 0 && kid->leaves > CD3_MESH_WIDTH && Area(kid->bounds) > best)
			{
				best = Area(kid->bounds);
				pick = i;
			}
		}
		if (pick < 0)
		{
			int fewest = 0;
			for (int i = 0; i < n; ++i)
			{
				const BuildNode* kid = nodes + kids[i];
				if (kid->count == 0 && (pick < 0 || kid->leaves < fewest))
				{
					fewest = kid->leaves;
					pick = i;
				}
			}
			/* Opening it must leave room for its leaves or be worth a node: a subtree that
			 * does not fit whole stays one node. */
			if (pick < 0 || n - 1 + fewest > CD3_MESH_WIDTH)
			{
				break;
			}
		}
		int left = nodes[kids[pick]].first;
		for (int i = n; i > pick + 1; --i)
		{
			kids[i] = kids[i - 1];
		}
		kids[pick] = left;
		kids[pick + 1] = left + 1;
		++n;
	}
	return n;
}

static void SetChildBounds(cd3MeshNode* node, int j, cd3Aabb b)
{
	node->bounds[0][j] = FloatDown(b.min.x);
	node->bounds[1][j] = FloatDown(b.min.y);
	node->bounds[2][j] = FloatDown(b.min.z);
	node->bounds[3][j] = FloatUp(b.max.x);
	node->bounds[4][j] = FloatUp(b.max.y);
	node->bounds[5][j] = FloatUp(b.max.z);
}

typedef struct CollapseTask
{
	int binary; /* the binary inner node (or leaf root) this wide node stands for */
	int parent; /* the wide parent, -1 for the root */
	int slot;
	int depth;
} CollapseTask;

/* Collapses the binary tree into `wide` in depth-first order (or only counts, when `wide` is NULL); returns
 * the node count and the depth (levels of nodes plus the leaf level) and SAH cost of the wide tree (node
 * visits cost TRAVERSAL_COST, triangles 1, weighted by area). */
static int CollapseTree(const BuildNode* nodes, cd3MeshNode* wide, int* depthOut, double* sahOut)
{
	CollapseTask stack[(CD3_MESH_WIDTH - 1) * CD3_MESH_MAX_DEPTH + 8];
	int top = 0;
	int count = 0;
	int maxDepth = 0;
	double rootArea = Area(nodes[0].bounds) > 0.0 ? Area(nodes[0].bounds) : 1.0;
	double sah = 0.0;
	stack[top++] = (CollapseTask){0, -1, 0, 1};
	while (top > 0)
	{
		CollapseTask task = stack[--top];
		int index = count++;
		cd3MeshNode scratch;
		cd3MeshNode* node = wide != NULL ? wide + index : &scratch;
		if (wide != NULL && task.parent >= 0)
		{
			wide[task.parent].child[task.slot] = index;
		}
		sah += TRAVERSAL_COST * Area(nodes[task.binary].bounds) / rootArea;
		int kids[CD3_MESH_WIDTH];
		int n = GatherChildren(nodes, task.binary, kids);
		node->used = n;
		node->firstTriangle = nodes[task.binary].spanFirst;
		for (int j = 0; j < CD3_MESH_WIDTH; ++j)
		{
			node->childOffset[j] = 0xffffu;
			node->childSpan[j] = 255u;
			if (j < n)
			{
				int32_t offset = nodes[kids[j]].spanFirst - node->firstTriangle;
				int32_t span = nodes[kids[j]].spanCount;
				node->childOffset[j] = (uint16_t)(offset < 0xffff ? offset : 0xffff);
				node->childSpan[j] = (uint8_t)(span < 255 ? span : 255);
			}
		}
		for (int j = 0; j < CD3_MESH_WIDTH; ++j)
		{
			if (j >= n)
			{
				node->child[j] = CD3_MESH_EMPTY;
				for (int r = 0; r < 3; ++r)
				{
					node->bounds[r][j] = FLT_MAX;
					node->bounds[3 + r][j] = -FLT_MAX;
				}
				continue;
			}
			const BuildNode* kid = nodes + kids[j];
			SetChildBounds(node, j, kid->bounds);
			if (kid->count > 0)
			{
				node->child[j] = cd3MeshLeafChild(kid->first, kid->count);
				sah += Area(kid->bounds) / rootArea * kid->count;
				maxDepth = task.depth + 1 > maxDepth ? task.depth + 1 : maxDepth;
			}
			else
			{
				node->child[j] = CD3_MESH_EMPTY; /* set when the child is made */
			}
		}
		/* Pushed last to first: the first child is made next, so that nodes follow in depth-first
		 * order. */
		for (int j = n - 1; j >= 0; --j)
		{
			if (nodes[kids[j]].count == 0)
			{
				stack[top++] = (CollapseTask){kids[j], index, j, task.depth + 1};
			}
		}
	}
	*depthOut = maxDepth;
	*sahOut = sah;
	return count;
}

/* ---- welding and edge flags --------------------------------------------------------------------- */

/* Vertex ids ordered by position, then by id (a merge sort: qsort takes no context in C11). */
static bool VertexBefore(const cd3Vec* vertices, int32_t ia, int32_t ib)
{
	cd3Vec a = vertices[ia], b = vertices[ib];
	if (a.x != b.x)
	{
		return a.x < b.x;
	}
	if (a.y != b.y)
	{
		return a.y < b.y;
	}
	if (a.z != b.z)
	{
		return a.z < b.z;
	}
	return ia < ib;
}

static void MergeSortVertices(int32_t* items, int32_t* scratch, int count, const cd3Vec* vertices)
{
	for (int width = 1; width < count; width *= 2)
	{
		for (int lo = 0; lo < count; lo += 2 * width)
		{
			int mid = lo + width < count ? lo + width : count;
			int hi = lo + 2 * width < count ? lo + 2 * width : count;
			int i = lo, j = mid, k = lo;
			while (i < mid && j < hi)
			{
				scratch[k++] = VertexBefore(vertices, items[j], items[i]) ? items[j++] : items[i++];
			}
			while (i < mid)
			{
				scratch[k++] = items[i++];
			}
			while (j < hi)
			{
				scratch[k++] = items[j++];
			}
		}
		memcpy(items, scratch, (size_t)count * sizeof(int32_t));
	}
}

typedef struct EdgeKey
{
	uint64_t key;	  /* smaller canonical vertex << 32 | larger */
	int32_t slotEdge; /* 3 * slot + edge */
} EdgeKey;

static void MergeSortEdges(EdgeKey* items, EdgeKey* scratch, int count)
{
	for (int width = 1; width < count; width *= 2)
	{
		for (int lo = 0; lo < count; lo += 2 * width)
		{
			int mid = lo + width < count ? lo + width : count;
			int hi = lo + 2 * width < count ? lo + 2 * width : count;
			int i = lo, j = mid, k = lo;
			while (i < mid && j < hi)
			{
				scratch[k++] = items[j].key < items[i].key ? items[j++] : items[i++];
			}
			while (i < mid)
			{
				scratch[k++] = items[i++];
			}
			while (j < hi)
			{
				scratch[k++] = items[j++];
			}
		}
		memcpy(items, scratch, (size_t)count * sizeof(EdgeKey));
	}
}

static cd3Vec Corner(cd3Triangle t, int k)
{
	return k == 0 ? t.a : (k == 1 ? t.b : t.c);
}

/* Flags of edge k of t whose neighbour's far vertex is w: active seen from a side where the
 * neighbour bends away (convex), internal where it continues flat (within the sine
 * CD3_MESH_FLAT_EDGE_SINE) or bends towards that side (concave). Computed in double. */
static uint8_t EdgeFlagsAgainst(cd3Triangle t, int k, cd3Vec w)
{
	cd3Vec p = Corner(t, k), q = Corner(t, (k + 1) % 3), r = Corner(t, (k + 2) % 3);
	double e[3] = {(double)q.x - p.x, (double)q.y - p.y, (double)q.z - p.z};
	double ab[3] = {(double)t.b.x - t.a.x, (double)t.b.y - t.a.y, (double)t.b.z - t.a.z};
	double ac[3] = {(double)t.c.x - t.a.x, (double)t.c.y - t.a.y, (double)t.c.z - t.a.z};
	double n[3] = {ab[1] * ac[2] - ab[2] * ac[1], ab[2] * ac[0] - ab[0] * ac[2],
				   ab[0] * ac[1] - ab[1] * ac[0]};
	/* In the plane, across the edge, away from r. */
	double u[3] = {e[1] * n[2] - e[2] * n[1], e[2] * n[0] - e[0] * n[2], e[0] * n[1] - e[1] * n[0]};
	double toR[3] = {(double)r.x - p.x, (double)r.y - p.y, (double)r.z - p.z};
	if (u[0] * toR[0] + u[1] * toR[1] + u[2] * toR[2] > 0.0)
	{
		u[0] = -u[0];
		u[1] = -u[1];
		u[2] = -u[2];
	}
	double nl = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
	double ul = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
	double toW[3] = {(double)w.x - p.x, (double)w.y - p.y, (double)w.z - p.z};
	double h = (n[0] * toW[0] + n[1] * toW[1] + n[2] * toW[2]) / nl;
	double a = (u[0] * toW[0] + u[1] * toW[1] + u[2] * toW[2]) / ul;
	double sine = (double)CD3_MESH_FLAT_EDGE_SINE;
	bool nearPlane = fabs(h) <= sine * sqrt(a * a + h * h);
	uint8_t front = (uint8_t)CD3_MESH_EDGE_FRONT(k), back = (uint8_t)CD3_MESH_EDGE_BACK(k);
	if (nearPlane)
	{
		/* Flat continuation: internal from both sides; folded back onto t: a sharp edge both ways. */
		return a > 0.0 ? (uint8_t)0 : (uint8_t)(front | back);
	}
	return h < 0.0 ? front : back;
}

/* Neighbours through equal edge keys: the entries are bucketed by their smaller vertex (a counting
 * sort, linear), then each bucket, a vertex's few edges, is sorted by the larger. */
static void ComputeEdgeFlags(const cd3Triangle* triangles, const int32_t* canonical, int n, int vertexCount,
							 uint8_t* flags, EdgeKey* edges, EdgeKey* scratch, int32_t* bucket)
{
	memset(bucket, 0, (size_t)(vertexCount + 1) * sizeof(int32_t));
	for (int s = 0; s < n; ++s)
	{
		flags[s] = 0;
		for (int k = 0; k < 3; ++k)
		{
			uint32_t v0 = (uint32_t)canonical[3 * s + k], v1 = (uint32_t)canonical[3 * s + (k + 1) % 3];
			uint32_t lo = v0 < v1 ? v0 : v1, hi = v0 < v1 ? v1 : v0;
			scratch[3 * s + k].key = (uint64_t)lo << 32 | hi;
			scratch[3 * s + k].slotEdge = 3 * s + k;
			++bucket[lo + 1];
		}
	}
	int count = 3 * n;
	for (int v = 0; v < vertexCount; ++v)
	{
		bucket[v + 1] += bucket[v];
	}
	for (int i = 0; i < count; ++i)
	{
		edges[bucket[scratch[i].key >> 32]++] = scratch[i];
	}
	/* bucket[v] is now the end of v's entries. */
	for (int v = 0, start = 0; v < vertexCount; ++v)
	{
		if (bucket[v] - start > 1)
		{
			MergeSortEdges(edges + start, scratch, bucket[v] - start);
		}
		start = bucket[v];
	}
	for (int i = 0; i < count;)
	{
		int j = i + 1;
		while (j < count && edges[j].key == edges[i].key)
		{
			++j;
		}
		if (j - i == 2)
		{
			for (int side = 0; side < 2; ++side)
			{
				int self = edges[i + side].slotEdge, other = edges[i + 1 - side].slotEdge;
				int s = self / 3, k = self % 3;
				int os = other / 3, ok = other % 3;
				cd3Vec far = Corner(triangles[os], (ok + 2) % 3);
				flags[s] |= EdgeFlagsAgainst(triangles[s], k, far);
			}
		}
		else
		{
			/* A boundary, or shared by more than two triangles: active from both sides. */
			for (int m = i; m < j; ++m)
			{
				int s = edges[m].slotEdge / 3, k = edges[m].slotEdge % 3;
				flags[s] |= (uint8_t)(CD3_MESH_EDGE_FRONT(k) | CD3_MESH_EDGE_BACK(k));
			}
		}
		i = j;
	}
}

/* ---- create ------------------------------------------------------------------------------------ */

static size_t AlignUp(size_t n)
{
	return (n + 31u) & ~(size_t)31u;
}

cdResult cd3CreateMesh(const cd3Vec* vertices, int vertexCount, const int* indices, int triangleCount,
					   cd3Mesh** mesh)
{
	if (mesh == NULL)
	{
		return CD_ERROR_INVALID_ARGUMENT;
	}
	*mesh = NULL;
	if (vertices == NULL || indices == NULL || vertexCount <= 0 || triangleCount <= 0)
	{
		return CD_ERROR_INVALID_ARGUMENT;
	}
	if (vertexCount > CD3_MAX_MESH_VERTICES || triangleCount > CD3_MAX_MESH_TRIANGLES)
	{
		return CD_ERROR_TOO_MANY_POINTS;
	}
	for (int i = 0; i < vertexCount; ++i)
	{
		if (!cd3IsValidVec(vertices[i]))
		{
			return CD_ERROR_NOT_FINITE;
		}
	}
	for (int i = 0; i < vertexCount; ++i)
	{
		if (MaxAbs(vertices[i]) > CD3_MESH_MAX_COORDINATE)
		{
			return CD_ERROR_OUT_OF_RANGE;
		}
	}
	for (int i = 0; i < 3 * triangleCount; ++i)
	{
		if (indices[i] < 0 || indices[i] >= vertexCount)
		{
			return CD_ERROR_INVALID_ARGUMENT;
		}
	}
	int kept = 0;
	for (int t = 0; t < triangleCount; ++t)
	{
		cd3Triangle tri = {vertices[indices[3 * t]], vertices[indices[3 * t + 1]],
						   vertices[indices[3 * t + 2]]};
		kept += cd3IsValidTriangle(tri) ? 1 : 0;
	}
	if (kept == 0)
	{
		return CD_ERROR_DEGENERATE;
	}

	/* Scratch: build triangles, build nodes, canonical vertex ids, edge keys. */
	size_t scratchBytes =
		AlignUp((size_t)kept * sizeof(BuildTriangle)) + AlignUp((size_t)(2 * kept - 1) * sizeof(BuildNode)) +
		AlignUp((size_t)vertexCount * sizeof(int32_t)) * 3 +
		AlignUp((size_t)(vertexCount + 1) * sizeof(int32_t)) + AlignUp((size_t)kept * 3 * sizeof(int32_t)) +
		AlignUp((size_t)kept * 3 * sizeof(EdgeKey)) * 2;
	char* scratch = (char*)cdAlloc(scratchBytes);
	if (scratch == NULL)
	{
		return CD_ERROR_OUT_OF_MEMORY;
	}
	char* cursor = scratch;
	BuildTriangle* tris = (BuildTriangle*)cursor;
	cursor += AlignUp((size_t)kept * sizeof(BuildTriangle));
	BuildNode* buildNodes = (BuildNode*)cursor;
	cursor += AlignUp((size_t)(2 * kept - 1) * sizeof(BuildNode));
	int32_t* order = (int32_t*)cursor;
	cursor += AlignUp((size_t)vertexCount * sizeof(int32_t));
	int32_t* orderScratch = (int32_t*)cursor;
	cursor += AlignUp((size_t)vertexCount * sizeof(int32_t));
	int32_t* weld = (int32_t*)cursor;
	cursor += AlignUp((size_t)vertexCount * sizeof(int32_t));
	int32_t* buckets = (int32_t*)cursor;
	cursor += AlignUp((size_t)(vertexCount + 1) * sizeof(int32_t));
	int32_t* canonical = (int32_t*)cursor;
	cursor += AlignUp((size_t)kept * 3 * sizeof(int32_t));
	EdgeKey* edges = (EdgeKey*)cursor;
	cursor += AlignUp((size_t)kept * 3 * sizeof(EdgeKey));
	EdgeKey* edgeScratch = (EdgeKey*)cursor;

	for (int i = 0; i < vertexCount; ++i)
	{
		order[i] = i;
	}
	MergeSortVertices(order, orderScratch, vertexCount, vertices);
	for (int i = 0; i < vertexCount; ++i)
	{
		bool same = i > 0 && vertices[order[i]].x == vertices[order[i - 1]].x &&
					vertices[order[i]].y == vertices[order[i - 1]].y &&
					vertices[order[i]].z == vertices[order[i - 1]].z;
		weld[order[i]] = same ? weld[order[i - 1]] : order[i];
	}

	/* Kept triangles in input order. */
	int slotCount = 0;
	for (int t = 0; t < triangleCount; ++t)
	{
		cd3Triangle tri = {vertices[indices[3 * t]], vertices[indices[3 * t + 1]],
						   vertices[indices[3 * t + 2]]};
		if (!cd3IsValidTriangle(tri))
		{
			continue;
		}
		tris[slotCount].bounds = PaddedTriangleBounds(tri);
		tris[slotCount].centroid = cd3AabbCenter(cd3ComputeTriangleAabb(tri));
		tris[slotCount].slot = t; /* the input index until the reorder */
		++slotCount;
	}

	int depth = 0, leafCount = 0;
	double sah = 0.0;
	int nodeCountBinary = BuildTree(tris, kept, buildNodes, &depth, &leafCount, &sah);

	/* Children come after their parents: leaf counts from the last node back. */
	for (int i = nodeCountBinary - 1; i >= 0; --i)
	{
		BuildNode* b = buildNodes + i;
		b->leaves = b->count > 0 ? 1 : buildNodes[b->first].leaves + buildNodes[b->first + 1].leaves;
		b->spanFirst = b->count > 0 ? b->first : buildNodes[b->first].spanFirst;
		b->spanCount =
			b->count > 0 ? b->count : buildNodes[b->first].spanCount + buildNodes[b->first + 1].spanCount;
	}
	int wideDepth = 0;
	double wideSah = 0.0;
	int wideCount = CollapseTree(buildNodes, NULL, &wideDepth, &wideSah);

	/* The nodes start on a 64-byte boundary (two cache lines each): the block gets 64 bytes of
	 * slack for that. */
	size_t headerBytes = AlignUp(sizeof(cd3Mesh));
	size_t nodeBytes = AlignUp((size_t)wideCount * sizeof(cd3MeshNode)) + 64u;
	size_t triangleBytes = AlignUp((size_t)kept * sizeof(cd3Triangle));
	size_t inputBytes = AlignUp((size_t)kept * sizeof(int32_t));
	size_t flagBytes = AlignUp((size_t)kept * sizeof(uint8_t));
	size_t slotBytes = AlignUp((size_t)triangleCount * sizeof(int32_t));
	size_t total = headerBytes + nodeBytes + triangleBytes + inputBytes + flagBytes + slotBytes;
	char* block = (char*)cdAlloc(total);
	if (block == NULL)
	{
		cdFree(scratch);
		return CD_ERROR_OUT_OF_MEMORY;
	}
	cd3Mesh* m = (cd3Mesh*)block;
	memset(m, 0, sizeof(cd3Mesh));
	uintptr_t nodeAddress = ((uintptr_t)(block + headerBytes) + 63u) & ~(uintptr_t)63u;
	m->nodes = (cd3MeshNode*)(block + headerBytes + (size_t)(nodeAddress - (uintptr_t)(block + headerBytes)));
	m->triangles = (cd3Triangle*)(block + headerBytes + nodeBytes);
	m->inputIndex = (int32_t*)(block + headerBytes + nodeBytes + triangleBytes);
	m->edgeFlags = (uint8_t*)(block + headerBytes + nodeBytes + triangleBytes + inputBytes);
	m->slotOfInput = (int32_t*)(block + headerBytes + nodeBytes + triangleBytes + inputBytes + flagBytes);
	m->triangleCount = kept;
	m->inputTriangleCount = triangleCount;
	m->vertexCount = vertexCount;
	m->droppedTriangleCount = triangleCount - kept;
	m->nodeCount = CollapseTree(buildNodes, m->nodes, &wideDepth, &wideSah);
	m->leafCount = leafCount;
	m->depth = wideDepth;
	m->sahCost = wideSah;
	m->bytes = total;
	m->bounds = buildNodes[0].bounds;

	for (int i = 0; i < triangleCount; ++i)
	{
		m->slotOfInput[i] = -1;
	}
	for (int s = 0; s < kept; ++s)
	{
		int t = tris[s].slot;
		m->inputIndex[s] = t;
		m->slotOfInput[t] = s;
		m->triangles[s].a = vertices[indices[3 * t]];
		m->triangles[s].b = vertices[indices[3 * t + 1]];
		m->triangles[s].c = vertices[indices[3 * t + 2]];
		for (int k = 0; k < 3; ++k)
		{
			canonical[3 * s + k] = weld[indices[3 * t + k]];
		}
	}
	ComputeEdgeFlags(m->triangles, canonical, kept, vertexCount, m->edgeFlags, edges, edgeScratch, buckets);
	int active = 0;
	for (int s = 0; s < kept; ++s)
	{
		for (int k = 0; k < 6; ++k)
		{
			active += (m->edgeFlags[s] >> k) & 1;
		}
	}
	m->activeEdgeCount = active;
	cdFree(scratch);
	*mesh = m;
	return CD_OK;
}

void cd3DestroyMesh(cd3Mesh* mesh)
{
	cdFree(mesh);
}

/* ---- accessors, stats, validation --------------------------------------------------------------- */

int cd3Mesh_GetTriangleCount(const cd3Mesh* mesh)
{
	return mesh != NULL ? mesh->triangleCount : 0;
}

bool cd3Mesh_GetTriangle(const cd3Mesh* mesh, int triangleIndex, cd3Triangle* triangle)
{
	if (mesh == NULL || triangle == NULL || triangleIndex < 0 || triangleIndex >= mesh->inputTriangleCount)
	{
		return false;
	}
	int32_t slot = mesh->slotOfInput[triangleIndex];
	if (slot < 0)
	{
		return false;
	}
	*triangle = mesh->triangles[slot];
	return true;
}

cd3MeshStats cd3Mesh_GetStats(const cd3Mesh* mesh)
{
	cd3MeshStats stats;
	memset(&stats, 0, sizeof(stats));
	if (mesh == NULL)
	{
		return stats;
	}
	stats.triangleCount = mesh->triangleCount;
	stats.droppedTriangleCount = mesh->droppedTriangleCount;
	stats.vertexCount = mesh->vertexCount;
	stats.nodeCount = mesh->nodeCount;
	stats.leafCount = mesh->leafCount;
	stats.depth = mesh->depth;
	stats.activeEdgeCount = mesh->activeEdgeCount;
	stats.sahCost = mesh->sahCost;
	stats.bytes = mesh->bytes;
	stats.bounds = mesh->bounds;
	return stats;
}

/* Child `inner` of node `in` lies inside child `outer` of node `out`. */
static bool ChildContains(const cd3MeshNode* out, int outer, const cd3MeshNode* in, int inner)
{
	for (int k = 0; k < 3; ++k)
	{
		if (!(out->bounds[k][outer] <= in->bounds[k][inner] &&
			  in->bounds[3 + k][inner] <= out->bounds[3 + k][outer]))
		{
			return false;
		}
	}
	return true;
}

static bool ChildContainsBox(const cd3MeshNode* node, int j, cd3Aabb b)
{
	return (cdReal)node->bounds[0][j] <= b.min.x && (cdReal)node->bounds[1][j] <= b.min.y &&
		   (cdReal)node->bounds[2][j] <= b.min.z && b.max.x <= (cdReal)node->bounds[3][j] &&
		   b.max.y <= (cdReal)node->bounds[4][j] && b.max.z <= (cdReal)node->bounds[5][j];
}

cdResult cd3ValidateMesh(const cd3Mesh* mesh)
{
	/* Every wide node but a root over a single leaf has two children or more. */
	if (mesh == NULL || mesh->triangleCount <= 0 || mesh->leafCount <= 0 ||
		mesh->leafCount > mesh->triangleCount || mesh->nodeCount <= 0 ||
		mesh->nodeCount > (mesh->leafCount > 1 ? mesh->leafCount - 1 : 1) || mesh->depth > CD3_MESH_MAX_DEPTH)
	{
		return CD_ERROR_INVALID_ARGUMENT;
	}
	for (int s = 0; s < mesh->triangleCount; ++s)
	{
		cd3Triangle t = mesh->triangles[s];
		if (!cd3IsValidVec(t.a) || !cd3IsValidVec(t.b) || !cd3IsValidVec(t.c))
		{
			return CD_ERROR_NOT_FINITE;
		}
		if (cdMax(MaxAbs(t.a), cdMax(MaxAbs(t.b), MaxAbs(t.c))) > CD3_MESH_MAX_COORDINATE)
		{
			return CD_ERROR_OUT_OF_RANGE;
		}
		if (!cd3IsValidTriangle(t))
		{
			return CD_ERROR_DEGENERATE;
		}
		int32_t input = mesh->inputIndex[s];
		if (input < 0 || input >= mesh->inputTriangleCount || mesh->slotOfInput[input] != s ||
			(mesh->edgeFlags[s] & ~0x3fu) != 0)
		{
			return CD_ERROR_INVALID_ARGUMENT;
		}
	}
	int dropped = 0;
	for (int i = 0; i < mesh->inputTriangleCount; ++i)
	{
		dropped += mesh->slotOfInput[i] < 0 ? 1 : 0;
	}
	if (dropped != mesh->droppedTriangleCount)
	{
		return CD_ERROR_INVALID_ARGUMENT;
	}
	/* Walk the tree in slot order: each leaf's range must tile 0..n-1 in order, each child inside
	 * its parent's slot, each triangle inside its leaf's. A stack entry is a child (node or leaf),
	 * its parent and the parent's slot holding it. */
	enum
	{
		VALIDATE_STACK = (CD3_MESH_WIDTH - 1) * CD3_MESH_MAX_DEPTH + 8
	};
	int32_t stack[VALIDATE_STACK];
	int parentOf[VALIDATE_STACK];
	int slotOf[VALIDATE_STACK];
	int depthOf[VALIDATE_STACK];
	int top = 0;
	stack[top] = 0;
	parentOf[top] = -1;
	slotOf[top] = 0;
	depthOf[top++] = 1;
	int nextTriangle = 0;
	int visited = 0;
	int leaves = 0;
	while (top > 0)
	{
		--top;
		int32_t ref = stack[top];
		int depth = depthOf[top];
		int slot = slotOf[top];
		const cd3MeshNode* parent = parentOf[top] >= 0 ? mesh->nodes + parentOf[top] : NULL;
		if (depth > CD3_MESH_MAX_DEPTH)
		{
			return CD_ERROR_INVALID_ARGUMENT;
		}
		if (cd3MeshIsLeaf(ref))
		{
			int first = cd3MeshLeafFirst(ref), count = cd3MeshLeafCount(ref);
			if (parent == NULL || count <= 0 || first != nextTriangle ||
				count > mesh->triangleCount - nextTriangle)
			{
				return CD_ERROR_INVALID_ARGUMENT;
			}
			for (int s = first; s < first + count; ++s)
			{
				if (!ChildContainsBox(parent, slot, cd3ComputeTriangleAabb(mesh->triangles[s])))
				{
					return CD_ERROR_INVALID_ARGUMENT;
				}
			}
			nextTriangle += count;
			++leaves;
			continue;
		}
		int index = ref;
		if (index < 0 || index >= mesh->nodeCount || (parent != NULL && index <= parentOf[top]) ||
			++visited > mesh->nodeCount)
		{
			return CD_ERROR_INVALID_ARGUMENT;
		}
		const cd3MeshNode* node = mesh->nodes + index;
		int used = 0;
		while (used < CD3_MESH_WIDTH && node->child[used] != CD3_MESH_EMPTY)
		{
			++used;
		}
		if (used < (index == 0 ? 1 : 2) || used != node->used || top + used > VALIDATE_STACK ||
			node->firstTriangle != nextTriangle)
		{
			return CD_ERROR_INVALID_ARGUMENT;
		}
		/* The prefetch hints stay inside the triangles. */
		for (int j = 0; j < used; ++j)
		{
			if (node->childOffset[j] != 0xffffu && node->childSpan[j] != 255u &&
				(int64_t)node->firstTriangle + node->childOffset[j] + node->childSpan[j] >
					mesh->triangleCount)
			{
				return CD_ERROR_INVALID_ARGUMENT;
			}
		}
		for (int j = used; j < CD3_MESH_WIDTH; ++j)
		{
			if (node->child[j] != CD3_MESH_EMPTY)
			{
				return CD_ERROR_INVALID_ARGUMENT;
			}
		}
		for (int j = 0; j < used; ++j)
		{
			for (int r = 0; r < 6; ++r)
			{
				if (!isfinite(node->bounds[r][j]))
				{
					return CD_ERROR_NOT_FINITE;
				}
			}
			if (parent != NULL && !ChildContains(parent, slot, node, j))
			{
				return CD_ERROR_INVALID_ARGUMENT;
			}
		}
		/* Last to first, so that the first slot comes off the stack first. */
		for (int j = used - 1; j >= 0; --j)
		{
			stack[top] = node->child[j];
			parentOf[top] = index;
			slotOf[top] = j;
			depthOf[top++] = depth + 1;
		}
	}
	if (leaves != mesh->leafCount)
	{
		return CD_ERROR_INVALID_ARGUMENT;
	}
	if (nextTriangle != mesh->triangleCount || visited != mesh->nodeCount)
	{
		return CD_ERROR_INVALID_ARGUMENT;
	}
	return CD_OK;
}
