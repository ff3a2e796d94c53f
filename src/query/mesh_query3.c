/* Queries on triangle meshes: ray casts (closest and any hit), bounds queries, overlap with a
 * convex shape and closest point, all walking the BVH of src/geometry/mesh3.c with a fixed stack.
 * Queries run in the mesh's frame where only bounds are compared, and on world-space triangles
 * where a primitive routine decides, so that the answers are those of the primitive routines. */
#include "base/real_bits.h"
#include "geometry/mesh3_internal.h"
#include "query/mesh_query3.h"

#include <string.h>

#if !CD_DOUBLE && defined(__SSE2__) && !defined(COLLIDE_NO_SIMD)
#include <emmintrin.h>
#define CD_MESH_SSE 1
#else
#define CD_MESH_SSE 0
#endif

#if defined(__GNUC__) || defined(__clang__)
#define CD_MESH_PREFETCH(p) __builtin_prefetch(p)
#else
#define CD_MESH_PREFETCH(p) ((void)(p))
#endif

/* The index of the lowest set bit of a non-zero mask. */
static inline int LowestBit(unsigned mask)
{
#if defined(__GNUC__) || defined(__clang__)
	return __builtin_ctz(mask);
#else
	int i = 0;
	while ((mask & 1u) == 0)
	{
		mask >>= 1;
		++i;
	}
	return i;
#endif
}

/* Stack room for a depth-first walk that pushes up to CD3_MESH_WIDTH children per node:
 * CD3_MESH_WIDTH - 1 per level and a few. */
#define STACK_SIZE ((CD3_MESH_WIDTH - 1) * CD3_MESH_MAX_DEPTH + 8)

/* ---- ray against node bounds -------------------------------------------------------------------- */

typedef struct RayBox
{
	/* Per axis: the bounds row the ray meets first (min when it runs towards +) and last, the
	 * origin shifted by the pad towards each, and 1 / translation (infinite on a zero component). */
	int nearRow[3], farRow[3];
	cdReal nearOrigin[3], farOrigin[3];
	cdReal inverse[3];
#if CD_MESH_SSE
	__m128 nearOrigin4[3], farOrigin4[3], inverse4[3]; /* the same in all four lanes */
#endif
} RayBox;

static RayBox MakeRayBox(cd3Ray ray)
{
	RayBox r;
	cdReal o[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
	cdReal d[3] = {ray.translation.x, ray.translation.y, ray.translation.z};
	/* cd3RaycastTriangle accepts hits within 4 double epsilons of the largest coordinate of the
	 * triangle and the ray's ends from the triangle; the build pads node bounds for the triangle's
	 * own coordinates, this pad for the ray's (a far ray may count a tiny triangle as hit). */
	cd3Vec end = cd3Add(ray.origin, ray.translation);
	cdReal magnitude = cdMax(cdMax(cdAbs(ray.origin.x), cdMax(cdAbs(ray.origin.y), cdAbs(ray.origin.z))),
							 cdMax(cdAbs(end.x), cdMax(cdAbs(end.y), cdAbs(end.z))));
	cdReal pad = CD_R(8.0) * CD_REAL_EPSILON * magnitude;
	for (int k = 0; k < 3; ++k)
	{
		/* IEEE division: a zero component gives an infinite inverse, whose products below are
		 * infinite (origin outside the slab: no t) or NaN (origin on a slab plane, inside it for
		 * every t), and the comparisons in EnterChildren skip NaN. */
		r.inverse[k] = CD_R(1.0) / d[k];
		bool positive = !(r.inverse[k] < CD_R(0.0)); /* the inverse's sign: -0 gives -infinity */
		r.nearRow[k] = positive ? k : 3 + k;
		r.farRow[k] = positive ? 3 + k : k;
		/* bound - pad - origin for the min, bound + pad - origin for the max. */
		r.nearOrigin[k] = positive ? o[k] + pad : o[k] - pad;
		r.farOrigin[k] = positive ? o[k] - pad : o[k] + pad;
#if CD_MESH_SSE
		r.nearOrigin4[k] = _mm_set1_ps(r.nearOrigin[k]);
		r.farOrigin4[k] = _mm_set1_ps(r.farOrigin[k]);
		r.inverse4[k] = _mm_set1_ps(r.inverse[k]);
#endif
	}
	return r;
}

/* The ray against the children's boxes (lane j is child j; SSE2 in the float build, four at a
 * time): each child's entry fraction within [0, limit] and a bit per child met, among the used
 * ones (empty children's bounds are never met in the SSE code either, but only the used are
 * looked at). */
static unsigned EnterChildren(const RayBox* r, const cd3MeshNode* node, cdReal limit,
							  cdReal enter[CD3_MESH_WIDTH])
{
#if CD_MESH_SSE
	/* The same operations lane by lane: max(t, lo) keeps lo where t is NaN, like the scalar code's
	 * t > lo ? t : lo, and min likewise. */
	/* Four children at a time, as many as in use (bottom nodes often hold four or fewer). */
	unsigned mask = 0;
	int used = node->used;
	for (int h = 0; h < used; h += 4)
	{
		__m128 lo = _mm_setzero_ps();
		__m128 hi = _mm_set1_ps(limit);
		for (int k = 0; k < 3; ++k)
		{
			__m128 tNear = _mm_mul_ps(
				_mm_sub_ps(_mm_load_ps(node->bounds[r->nearRow[k]] + h), r->nearOrigin4[k]), r->inverse4[k]);
			__m128 tFar = _mm_mul_ps(
				_mm_sub_ps(_mm_load_ps(node->bounds[r->farRow[k]] + h), r->farOrigin4[k]), r->inverse4[k]);
			lo = _mm_max_ps(tNear, lo);
			hi = _mm_min_ps(tFar, hi);
		}
		_mm_storeu_ps(enter + h, lo);
		mask |= (unsigned)_mm_movemask_ps(_mm_cmple_ps(lo, hi)) << h;
	}
	return mask;
#else
	cdReal lo[CD3_MESH_WIDTH], hi[CD3_MESH_WIDTH];
	for (int j = 0; j < CD3_MESH_WIDTH; ++j)
	{
		lo[j] = CD_R(0.0);
		hi[j] = limit;
	}
	for (int k = 0; k < 3; ++k)
	{
		const float* nearBound = node->bounds[r->nearRow[k]];
		const float* farBound = node->bounds[r->farRow[k]];
		cdReal nearOrigin = r->nearOrigin[k], farOrigin = r->farOrigin[k], inverse = r->inverse[k];
		for (int j = 0; j < CD3_MESH_WIDTH; ++j)
		{
			cdReal tNear = ((cdReal)nearBound[j] - nearOrigin) * inverse;
			cdReal tFar = ((cdReal)farBound[j] - farOrigin) * inverse;
			lo[j] = tNear > lo[j] ? tNear : lo[j];
			hi[j] = tFar < hi[j] ? tFar : hi[j];
		}
	}
	unsigned mask = 0;
	for (int j = 0; j < CD3_MESH_WIDTH; ++j)
	{
		enter[j] = lo[j];
		mask |= (lo[j] <= hi[j] ? 1u : 0u) << j;
	}
	return mask;
#endif
}

static cd3Ray RayToMesh(cd3Transform xf, cd3Ray ray)
{
	cd3Ray local;
	local.origin = cd3InvTransformPoint(xf, ray.origin);
	local.translation = cd3InvRotateVector(xf.q, ray.translation);
	return local;
}

static cd3Triangle TriangleToWorld(cd3Transform xf, cd3Triangle t)
{
	cd3Triangle w = {cd3TransformPoint(xf, t.a), cd3TransformPoint(xf, t.b), cd3TransformPoint(xf, t.c)};
	return w;
}

/* |a| for the margins of MayHitTriangle, where the sign of a zero does not matter: one masking
 * instruction (cdAbs keeps -0, which takes a compare and a blend). */
static inline cdReal MarginAbs(cdReal a)
{
#if CD_DOUBLE
	return fabs(a);
#else
	return fabsf(a);
#endif
}

static cdReal SumAbs(cd3Vec v)
{
	return MarginAbs(v.x) + MarginAbs(v.y) + MarginAbs(v.z);
}

/* The largest |component|, for the margins of MayHitTriangle. */
static cdReal MaxAbs3(cd3Vec v)
{
	return cdMax(MarginAbs(v.x), cdMax(MarginAbs(v.y), MarginAbs(v.z)));
}

/* False only when cd3RaycastTriangle(t, ray) certainly misses: a cdReal test of the ray line
 * against the closed triangle (barycentric numerators and the fraction, all times the
 * determinant), each compared with a margin of 32 epsilons of a bound on its terms. That bound
 * covers the round-off of these products (a few epsilons: each term is a product of three
 * rounded differences) and the tolerance of cd3RaycastTriangle, which accepts hit points within
 * 4 double epsilons of the largest coordinate of the triangle and the ray's ends (`magnitude` is
 * at least that: TriangleMagnitude, or the mesh's for all its triangles): a point that far
 * outside an edge moves a numerator by at most that distance times |d| times the other edge's
 * length. A larger magnitude only widens the margins. NaN and infinite products never reject. */
static bool MayHitTriangle(cd3Triangle t, cd3Ray ray, cdReal magnitude)
{
	cd3Vec d = ray.translation;
	cd3Vec e1 = cd3Sub(t.b, t.a), e2 = cd3Sub(t.c, t.a), s = cd3Sub(ray.origin, t.a);
	cd3Vec p = cd3Cross(d, e2);
	cd3Vec q = cd3Cross(s, e1);
	cdReal det = cd3Dot(e1, p);
	cdReal u = cd3Dot(s, p);
	cdReal v = cd3Dot(d, q);
	cdReal w = cd3Dot(e2, q); /* the fraction times det */
	cdReal ds = SumAbs(d), e1s = SumAbs(e1), e2s = SumAbs(e2), ss = SumAbs(s) + magnitude;
	cdReal k = CD_R(32.0) * CD_REAL_EPSILON;
	cdReal marginDet = k * e1s * ds * e2s;
	cdReal marginU = k * ss * ds * e2s;
	cdReal marginV = k * ds * ss * e1s;
	cdReal marginW = k * e2s * ss * e1s;
	if (det < CD_R(0.0))
	{
		det = -det;
		u = -u;
		v = -v;
		w = -w;
	}
	if (!(det > marginDet))
	{
		return true; /* nearly parallel: the exact routine decides */
	}
	return !(u < -marginU || v < -marginV || u + v > det + marginU + marginV + marginDet || w < -marginW ||
			 w > det + marginW + marginDet);
}

/* The largest coordinate of the triangle and the ray's ends, for MayHitTriangle. */
static cdReal TriangleMagnitude(cd3Triangle t, cdReal rayMagnitude)
{
	return cdMax(rayMagnitude, cdMax(MaxAbs3(t.a), cdMax(MaxAbs3(t.b), MaxAbs3(t.c))));
}

/* The identity transform with +0 zeros: one integer test instead of seven comparisons. */
static inline bool IsIdentityBits(cd3Transform xf)
{
	return (cdGetRealBits(xf.p.x) | cdGetRealBits(xf.p.y) | cdGetRealBits(xf.p.z) | cdGetRealBits(xf.q.x) |
			cdGetRealBits(xf.q.y) | cdGetRealBits(xf.q.z) |
			(cdGetRealBits(xf.q.w) ^ cdGetRealBits(CD_R(1.0)))) == 0;
}

/* Node fractions are those of the mesh-space ray; the triangle casts run in world space on the
 * world triangles, like a loop over cd3RaycastTriangle. The margin covers the difference between
 * the two fractions (a few epsilons). */
#define FRACTION_MARGIN (CD_R(64.0) * CD_REAL_EPSILON)

static bool RaycastMesh(const cd3Mesh* mesh, cd3Transform xf, cd3Ray ray, bool any, cd3MeshRayHit* out)
{
	if (mesh == NULL)
	{
		return false;
	}
	/* The identity (the common case of a static mesh placed in world space) moves nothing. Its
	 * exact bits are tested first, in one integer test; the comparisons take the other zeros. */
	bool identity = IsIdentityBits(xf) || (xf.p.x == CD_R(0.0) && xf.p.y == CD_R(0.0) &&
										   xf.p.z == CD_R(0.0) && xf.q.x == CD_R(0.0) &&
										   xf.q.y == CD_R(0.0) && xf.q.z == CD_R(0.0) && xf.q.w == CD_R(1.0));
	RayBox box = MakeRayBox(identity ? ray : RayToMesh(xf, ray));
	cd3Vec rayEnd = cd3Add(ray.origin, ray.translation);
	cdReal rayMagnitude = cdMax(MaxAbs3(ray.origin), MaxAbs3(rayEnd));
	/* With the identity the stored triangles are the ones cast against, and the mesh's bounds
	 * (the union of the padded triangle bounds) bound every coordinate of them: one magnitude
	 * for all (a world placement computes each world triangle's own). */
	cdReal meshMagnitude = cdMax(rayMagnitude, cdMax(MaxAbs3(mesh->bounds.min), MaxAbs3(mesh->bounds.max)));
	bool found = false;
	cd3RayHit best;
	int bestSlot = 0;
	cdReal limit = CD_R(1.0) + FRACTION_MARGIN;
	/* Entries are children (nodes or leaves) with their entry fractions, so that those behind the
	 * closest hit found since they were pushed are dropped when popped, without testing their
	 * triangles or children. The walk goes on with the nearest child met and pushes the others
	 * farthest first. */
	int32_t stack[STACK_SIZE];
	cdReal enterStack[STACK_SIZE];
	int top = 0;
	int32_t current = 0;
	for (;;)
	{
		if (cd3MeshIsLeaf(current))
		{
			int first = cd3MeshLeafFirst(current), end = first + cd3MeshLeafCount(current);
			for (int s = first; s < end; ++s)
			{
				cd3RayHit hit;
				cd3Triangle t = identity ? mesh->triangles[s] : TriangleToWorld(xf, mesh->triangles[s]);
				cdReal magnitude = identity ? meshMagnitude : TriangleMagnitude(t, rayMagnitude);
				if (!MayHitTriangle(t, ray, magnitude) || !cd3RaycastTriangle(t, ray, &hit))
				{
					continue;
				}
				/* The input index (another array) is only read on a tie and for the answer. */
				if (!found || hit.fraction < best.fraction ||
					(hit.fraction == best.fraction && mesh->inputIndex[s] < mesh->inputIndex[bestSlot]))
				{
					found = true;
					best = hit;
					bestSlot = s;
					CD_MESH_PREFETCH(mesh->inputIndex + s);
					limit = cdMin(best.fraction + FRACTION_MARGIN, limit);
					if (any)
					{
						return true;
					}
				}
			}
		}
		else
		{
			const cd3MeshNode* node = mesh->nodes + current;
			cdReal enter[CD3_MESH_WIDTH];
			unsigned mask = EnterChildren(&box, node, limit, enter);
			/* The children met (empty ones never are: the mask keeps the used ones), nearest first
			 * (an insertion sort of a few). */
			mask &= (1u << node->used) - 1u;
			int32_t child[CD3_MESH_WIDTH];
			cdReal at[CD3_MESH_WIDTH];
			int n = 0;
			while (mask != 0)
			{
				int j = LowestBit(mask);
				mask &= mask - 1u;
				int32_t c = node->child[j];
				int i = n++;
				while (i > 0 && at[i - 1] > enter[j])
				{
					at[i] = at[i - 1];
					child[i] = child[i - 1];
					--i;
				}
				at[i] = enter[j];
				child[i] = c;
				/* Fetched while the walk goes on: the nearest child is visited next, the others
				 * maybe later. */
				if (cd3MeshIsLeaf(c))
				{
					CD_MESH_PREFETCH(mesh->triangles + cd3MeshLeafFirst(c));
					CD_MESH_PREFETCH(mesh->inputIndex + cd3MeshLeafFirst(c));
				}
				else
				{
					for (size_t line = 0; line < sizeof(cd3MeshNode); line += 64)
					{
						CD_MESH_PREFETCH((const char*)(mesh->nodes + c) + line);
					}
					/* A small subtree (a bottom node): its triangles too, so that they do not wait
					 * for the node. */
					if (node->childSpan[j] <= 16u && node->childOffset[j] != 0xffffu)
					{
						const char* from =
							(const char*)(mesh->triangles + node->firstTriangle + node->childOffset[j]);
						size_t bytes = (size_t)node->childSpan[j] * sizeof(cd3Triangle);
						for (size_t line = 0; line < bytes; line += 64)
						{
							CD_MESH_PREFETCH(from + line);
						}
					}
				}
			}
			if (n > 0)
			{
				for (int i = n - 1; i > 0; --i)
				{
					stack[top] = child[i];
					enterStack[top++] = at[i];
				}
				current = child[0];
				continue;
			}
		}
		/* The next child on the stack not entered beyond the best hit. */
		while (top > 0 && enterStack[top - 1] > limit)
		{
			--top;
		}
		if (top == 0)
		{
			break;
		}
		current = stack[--top];
	}
	if (found && out != NULL)
	{
		out->hit = best;
		out->triangleIndex = mesh->inputIndex[bestSlot];
	}
	return found;
}

bool cd3RaycastMesh(const cd3Mesh* mesh, cd3Transform meshTransform, cd3Ray ray, cd3MeshRayHit* hit)
{
	return RaycastMesh(mesh, meshTransform, ray, false, hit);
}

bool cd3RaycastMeshAny(const cd3Mesh* mesh, cd3Transform meshTransform, cd3Ray ray)
{
	return RaycastMesh(mesh, meshTransform, ray, true, NULL);
}

/* ---- bounds queries ------------------------------------------------------------------------------ */

static bool ChildOverlaps(const cd3MeshNode* node, int j, cd3Aabb b)
{
	return (cdReal)node->bounds[0][j] <= b.max.x && b.min.x <= (cdReal)node->bounds[3][j] &&
		   (cdReal)node->bounds[1][j] <= b.max.y && b.min.y <= (cdReal)node->bounds[4][j] &&
		   (cdReal)node->bounds[2][j] <= b.max.z && b.min.z <= (cdReal)node->bounds[5][j];
}

bool cd3MeshVisitSlots(const cd3Mesh* mesh, cd3Aabb bounds, cd3MeshSlotFcn* visit, void* context)
{
	/* Children that overlap go on the stack last to first, leaves too, so that the triangles come
	 * in leaf order. */
	int32_t stack[STACK_SIZE];
	int top = 0;
	stack[top++] = 0;
	while (top > 0)
	{
		int32_t current = stack[--top];
		if (cd3MeshIsLeaf(current))
		{
			int first = cd3MeshLeafFirst(current), end = first + cd3MeshLeafCount(current);
			for (int s = first; s < end; ++s)
			{
				/* A leaf holds up to 8 triangles: each one's own bounds first. */
				cd3Aabb tb = cd3ComputeTriangleAabb(mesh->triangles[s]);
				cd3Vec big = cd3Max(cd3Abs(tb.min), cd3Abs(tb.max));
				cdReal magnitude = cdMax(big.x, cdMax(big.y, big.z)); /* as the build pads */
				if (!cd3OverlapAabbAabb(cd3AabbInflate(tb, CD_R(64.0) * CD_REAL_EPSILON * magnitude), bounds))
				{
					continue;
				}
				if (!visit(s, context))
				{
					return false;
				}
			}
			continue;
		}
		const cd3MeshNode* node = mesh->nodes + current;
		for (int j = CD3_MESH_WIDTH - 1; j >= 0; --j)
		{
			if (node->child[j] != CD3_MESH_EMPTY && ChildOverlaps(node, j, bounds))
			{
				stack[top++] = node->child[j];
			}
		}
	}
	return true;
}

typedef struct QueryContext
{
	const cd3Mesh* mesh;
	cd3MeshQueryFcn* callback;
	void* context;
} QueryContext;

static bool ForwardSlot(int slot, void* context)
{
	QueryContext* q = (QueryContext*)context;
	return q->callback(q->mesh->inputIndex[slot], q->context);
}

bool cd3Mesh_QueryAabb(const cd3Mesh* mesh, cd3Aabb bounds, cd3MeshQueryFcn* callback, void* context)
{
	if (mesh == NULL || callback == NULL)
	{
		return true;
	}
	QueryContext q = {mesh, callback, context};
	return cd3MeshVisitSlots(mesh, bounds, ForwardSlot, &q);
}

cd3Aabb cd3MeshBoundsOfWorldAabb(cd3Transform xf, cd3Aabb world)
{
	cd3Vec extent = cd3AabbHalfExtents(world);
	/* Unbounded or overflowing boxes (a half-space) cover the whole mesh. */
	cdReal huge = CD_REAL_MAX / CD_R(8.0);
	if (!(cd3Length(cd3Abs(extent)) < huge) || !(cd3Length(cd3Abs(world.min)) < huge) ||
		!(cd3Length(cd3Abs(world.max)) < huge))
	{
		cd3Aabb all = {{-CD_REAL_MAX, -CD_REAL_MAX, -CD_REAL_MAX}, {CD_REAL_MAX, CD_REAL_MAX, CD_REAL_MAX}};
		return all;
	}
	cd3Vec center = cd3InvTransformPoint(xf, cd3AabbCenter(world));
	cd3Mat33 r = cd3MakeMatFromQuat(cd3Conjugate(xf.q));
	cd3Vec e = {cdAbs(r.cx.x) * extent.x + cdAbs(r.cy.x) * extent.y + cdAbs(r.cz.x) * extent.z,
				cdAbs(r.cx.y) * extent.x + cdAbs(r.cy.y) * extent.y + cdAbs(r.cz.y) * extent.z,
				cdAbs(r.cx.z) * extent.x + cdAbs(r.cy.z) * extent.y + cdAbs(r.cz.z) * extent.z};
	/* Round-off of the rotation and of the centre, relative to the magnitudes involved. */
	cdReal magnitude = cd3Length(cd3Abs(center)) + cd3Length(e) + cd3Length(cd3Abs(xf.p));
	cdReal pad = CD_R(16.0) * CD_REAL_EPSILON * magnitude;
	cd3Aabb local = {cd3Sub(center, e), cd3Add(center, e)};
	return cd3AabbInflate(local, pad);
}

/* ---- overlap ------------------------------------------------------------------------------------- */

typedef struct OverlapContext
{
	const cd3Mesh* mesh;
	const cd3Shape* shape;
	cd3Transform xf;
	bool hit;
} OverlapContext;

static bool OverlapSlot(int slot, void* context)
{
	OverlapContext* o = (OverlapContext*)context;
	cd3Shape triangle = cd3MakeTriangleShape(TriangleToWorld(o->xf, o->mesh->triangles[slot]));
	if (cd3Overlap(o->shape, &triangle))
	{
		o->hit = true;
		return false;
	}
	return true;
}

bool cd3OverlapMesh(const cd3Shape* shape, const cd3Mesh* mesh, cd3Transform meshTransform)
{
	if (shape == NULL || mesh == NULL)
	{
		return false;
	}
	cd3Aabb world = cd3ComputeShapeAabb(shape);
	/* Shapes whose overlap tests accept touching within a tolerance: grow the box by it. */
	cdReal magnitude = cdMax(cd3Length(cd3Abs(world.min)), cd3Length(cd3Abs(world.max)));
	world = cd3AabbInflate(world, CD_R(64.0) * CD_REAL_EPSILON * cdMin(magnitude, CD_REAL_MAX / CD_R(256.0)));
	OverlapContext o = {mesh, shape, meshTransform, false};
	cd3MeshVisitSlots(mesh, cd3MeshBoundsOfWorldAabb(meshTransform, world), OverlapSlot, &o);
	return o.hit;
}

/* ---- closest point -------------------------------------------------------------------------------- */

static cdReal ChildDistanceSquared(const cd3MeshNode* node, int j, cd3Vec p)
{
	cdReal c[3] = {p.x, p.y, p.z};
	cdReal sum = CD_R(0.0);
	for (int k = 0; k < 3; ++k)
	{
		cdReal d = CD_R(0.0);
		if (c[k] < (cdReal)node->bounds[k][j])
		{
			d = (cdReal)node->bounds[k][j] - c[k];
		}
		else if (c[k] > (cdReal)node->bounds[3 + k][j])
		{
			d = c[k] - (cdReal)node->bounds[3 + k][j];
		}
		sum += d * d;
	}
	return sum;
}

bool cd3ClosestPointOnMesh(const cd3Mesh* mesh, cd3Transform meshTransform, cd3Vec p, cdReal maxDistance,
						   cd3MeshClosestPoint* result)
{
	if (mesh == NULL || result == NULL)
	{
		return false;
	}
	cd3Vec local = cd3InvTransformPoint(meshTransform, p);
	/* Pruning compares squared distances in the mesh frame; triangles are measured in the same
	 * frame and the winner's point is moved back to the world. The bound is kept a little loose
	 * (relative 1e-3 of the squared distance) so round-off never prunes a tie. */
	cdReal bestSquared = maxDistance < CD_REAL_MAX ? maxDistance * maxDistance : CD_REAL_MAX;
	if (!(bestSquared < CD_REAL_MAX))
	{
		bestSquared = CD_REAL_MAX;
	}
	bool found = false;
	int bestIndex = 0;
	cd3Vec bestPoint = local;
	cdReal bestTrue = CD_REAL_MAX;
	/* Entries are children with their squared distances, checked again when popped. */
	int32_t stack[STACK_SIZE];
	cdReal distanceStack[STACK_SIZE];
	int top = 0;
	stack[top] = 0;
	distanceStack[top++] = CD_R(0.0);
	while (top > 0)
	{
		--top;
		if (distanceStack[top] > bestSquared)
		{
			continue;
		}
		int32_t current = stack[top];
		if (cd3MeshIsLeaf(current))
		{
			int first = cd3MeshLeafFirst(current), end = first + cd3MeshLeafCount(current);
			for (int s = first; s < end; ++s)
			{
				cd3Vec q = cd3ClosestPointOnTriangle(mesh->triangles[s], local);
				cdReal d2 = cd3VecDistanceSquared(q, local);
				int index = mesh->inputIndex[s];
				if (!(d2 <= bestSquared))
				{
					continue;
				}
				if (!found || d2 < bestTrue || (d2 == bestTrue && index < bestIndex))
				{
					found = true;
					bestTrue = d2;
					bestIndex = index;
					bestPoint = q;
					bestSquared = cdMin(bestSquared, d2 * (CD_R(1.0) + CD_R(1.0e-3)));
				}
			}
			continue;
		}
		/* The children within reach, pushed farthest first so that the nearest comes off next. */
		const cd3MeshNode* node = mesh->nodes + current;
		int32_t child[CD3_MESH_WIDTH];
		cdReal at[CD3_MESH_WIDTH];
		int n = 0;
		for (int j = 0; j < CD3_MESH_WIDTH; ++j)
		{
			if (node->child[j] == CD3_MESH_EMPTY)
			{
				continue;
			}
			cdReal d2 = ChildDistanceSquared(node, j, local);
			if (d2 > bestSquared)
			{
				continue;
			}
			int i = n++;
			while (i > 0 && at[i - 1] < d2)
			{
				at[i] = at[i - 1];
				child[i] = child[i - 1];
				--i;
			}
			at[i] = d2;
			child[i] = node->child[j];
		}
		for (int i = 0; i < n; ++i)
		{
			stack[top] = child[i];
			distanceStack[top++] = at[i];
		}
	}
	if (!found)
	{
		return false;
	}
	result->point = cd3TransformPoint(meshTransform, bestPoint);
	result->distance = cd3VecDistance(result->point, p);
	result->triangleIndex = bestIndex;
	return true;
}
