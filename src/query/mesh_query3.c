/* Queries on triangle meshes: ray casts (closest and any hit), bounds queries, overlap with a
 * convex shape and closest point, all walking the BVH of src/geometry/mesh3.c with a fixed stack.
 * Queries run in the mesh's frame where only bounds are compared, and on world-space triangles
 * where a primitive routine decides, so that the answers are those of the primitive routines. */
#include "geometry/mesh3_internal.h"
#include "query/mesh_query3.h"

/* Stack room for a depth-first walk that pushes both children: depth + 1 entries. */
#define STACK_SIZE (CD3_MESH_MAX_DEPTH + 4)

/* ---- ray against node bounds -------------------------------------------------------------------- */

typedef struct RayBox
{
	/* Per axis: the node bound the ray meets first (min when it runs towards +) and last, as
	 * indices into cd3MeshNode.bounds, the origin shifted by the pad towards each, and
	 * 1 / translation (infinite on a zero component). */
	int nearIndex[3], farIndex[3];
	cdReal nearOrigin[3], farOrigin[3];
	cdReal inverse[3];
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
		 * every t), and the comparisons in EnterNode skip NaN. */
		r.inverse[k] = CD_R(1.0) / d[k];
		bool positive = !(r.inverse[k] < CD_R(0.0)); /* the inverse's sign: -0 gives -infinity */
		r.nearIndex[k] = positive ? k : 3 + k;
		r.farIndex[k] = positive ? 3 + k : k;
		/* bound - pad - origin for the min, bound + pad - origin for the max. */
		r.nearOrigin[k] = positive ? o[k] + pad : o[k] - pad;
		r.farOrigin[k] = positive ? o[k] - pad : o[k] + pad;
	}
	return r;
}

/* Entry fraction of the ray into the node's box within [0, limit], or a negative value on a miss. */
static cdReal EnterNode(const RayBox* r, const cd3MeshNode* node, cdReal limit)
{
	cdReal enter = CD_R(0.0), exit = limit;
	for (int k = 0; k < 3; ++k)
	{
		cdReal tNear = ((cdReal)node->bounds[r->nearIndex[k]] - r->nearOrigin[k]) * r->inverse[k];
		cdReal tFar = ((cdReal)node->bounds[r->farIndex[k]] - r->farOrigin[k]) * r->inverse[k];
		enter = tNear > enter ? tNear : enter;
		exit = tFar < exit ? tFar : exit;
	}
	return enter <= exit ? enter : -CD_R(1.0);
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
	/* The identity (the common case of a static mesh placed in world space) moves nothing. */
	bool identity = xf.p.x == CD_R(0.0) && xf.p.y == CD_R(0.0) && xf.p.z == CD_R(0.0) &&
					xf.q.x == CD_R(0.0) && xf.q.y == CD_R(0.0) && xf.q.z == CD_R(0.0) && xf.q.w == CD_R(1.0);
	RayBox box = MakeRayBox(identity ? ray : RayToMesh(xf, ray));
	bool found = false;
	cd3RayHit best;
	int bestIndex = 0;
	cdReal limit = CD_R(1.0) + FRACTION_MARGIN;
	/* Each entry keeps the node's entry fraction, so that nodes behind the closest hit found since
	 * they were pushed are dropped when popped, without testing their triangles or children. */
	int stack[STACK_SIZE];
	cdReal enterStack[STACK_SIZE];
	int top = 0;
	cdReal rootEnter = EnterNode(&box, mesh->nodes, limit);
	if (rootEnter < CD_R(0.0))
	{
		return false;
	}
	stack[top] = 0;
	enterStack[top++] = rootEnter;
	while (top > 0)
	{
		--top;
		if (enterStack[top] > limit)
		{
			continue;
		}
		const cd3MeshNode* node = mesh->nodes + stack[top];
		if (node->count > 0)
		{
			for (int s = node->first; s < node->first + node->count; ++s)
			{
				cd3RayHit hit;
				cd3Triangle t = identity ? mesh->triangles[s] : TriangleToWorld(xf, mesh->triangles[s]);
				if (!cd3RaycastTriangle(t, ray, &hit))
				{
					continue;
				}
				int index = mesh->inputIndex[s];
				if (!found || hit.fraction < best.fraction ||
					(hit.fraction == best.fraction && index < bestIndex))
				{
					found = true;
					best = hit;
					bestIndex = index;
					limit = cdMin(best.fraction + FRACTION_MARGIN, limit);
					if (any)
					{
						return true;
					}
				}
			}
			continue;
		}
		int left = node->first;
		cdReal tl = EnterNode(&box, mesh->nodes + left, limit);
		cdReal tr = EnterNode(&box, mesh->nodes + left + 1, limit);
		/* The nearer child on top of the stack. */
		if (tl >= CD_R(0.0) && tr >= CD_R(0.0))
		{
			if (tl <= tr)
			{
				stack[top] = left + 1;
				enterStack[top++] = tr;
				stack[top] = left;
				enterStack[top++] = tl;
			}
			else
			{
				stack[top] = left;
				enterStack[top++] = tl;
				stack[top] = left + 1;
				enterStack[top++] = tr;
			}
		}
		else if (tl >= CD_R(0.0))
		{
			stack[top] = left;
			enterStack[top++] = tl;
		}
		else if (tr >= CD_R(0.0))
		{
			stack[top] = left + 1;
			enterStack[top++] = tr;
		}
	}
	if (found && out != NULL)
	{
		out->hit = best;
		out->triangleIndex = bestIndex;
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

static bool NodeOverlaps(const cd3MeshNode* node, cd3Aabb b)
{
	return (cdReal)node->bounds[0] <= b.max.x && b.min.x <= (cdReal)node->bounds[3] &&
		   (cdReal)node->bounds[1] <= b.max.y && b.min.y <= (cdReal)node->bounds[4] &&
		   (cdReal)node->bounds[2] <= b.max.z && b.min.z <= (cdReal)node->bounds[5];
}

bool cd3MeshVisitSlots(const cd3Mesh* mesh, cd3Aabb bounds, cd3MeshSlotFcn* visit, void* context)
{
	int stack[STACK_SIZE];
	int top = 0;
	stack[top++] = 0;
	while (top > 0)
	{
		const cd3MeshNode* node = mesh->nodes + stack[--top];
		if (!NodeOverlaps(node, bounds))
		{
			continue;
		}
		if (node->count > 0)
		{
			for (int s = node->first; s < node->first + node->count; ++s)
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
		stack[top++] = node->first + 1;
		stack[top++] = node->first;
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

static cdReal NodeDistanceSquared(const cd3MeshNode* node, cd3Vec p)
{
	cdReal c[3] = {p.x, p.y, p.z};
	cdReal sum = CD_R(0.0);
	for (int k = 0; k < 3; ++k)
	{
		cdReal d = CD_R(0.0);
		if (c[k] < (cdReal)node->bounds[k])
		{
			d = (cdReal)node->bounds[k] - c[k];
		}
		else if (c[k] > (cdReal)node->bounds[3 + k])
		{
			d = c[k] - (cdReal)node->bounds[3 + k];
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
	int stack[STACK_SIZE];
	int top = 0;
	stack[top++] = 0;
	while (top > 0)
	{
		const cd3MeshNode* node = mesh->nodes + stack[--top];
		if (NodeDistanceSquared(node, local) > bestSquared)
		{
			continue;
		}
		if (node->count > 0)
		{
			for (int s = node->first; s < node->first + node->count; ++s)
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
		int left = node->first;
		cdReal dl = NodeDistanceSquared(mesh->nodes + left, local);
		cdReal dr = NodeDistanceSquared(mesh->nodes + left + 1, local);
		if (dl <= dr)
		{
			stack[top++] = left + 1;
			stack[top++] = left;
		}
		else
		{
			stack[top++] = left;
			stack[top++] = left + 1;
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
