/* collide: queries on 2D chains: box query, one-sided ray cast and contact manifolds.
 *
 * Queries work in the chain's local frame: the shape, ray or box is brought into it once, the
 * bounding hierarchy (see geometry/chain2.c) is walked depth first, left child first, so leaves
 * come out in increasing segment order, and results go back to world space. */
#include "../geometry/chain2_internal.h"
#include "chain_manifold2.h"

/* A depth-first walk pushes at most CHAIN_BRANCH - 1 siblings per level besides the one it
 * descends into. */
#define STACK_SIZE (CHAIN_BRANCH * CHAIN_MAX_LEVELS)

typedef struct Node
{
	int level, index;
	cdReal entry; /* ray casts: the fraction where the ray enters the node's box */
} Node;

static bool BoxesOverlap(cd2Aabb a, cd2Aabb b)
{
	return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y;
}

/* The local box that encloses the world box `bounds` seen from the chain's frame. */
static cd2Aabb LocalBounds(cd2Transform t, cd2Aabb bounds)
{
	cd2Vec center = cd2InvTransformPoint(t, cd2AabbCenter(bounds));
	cd2Vec half = cd2AabbHalfExtents(bounds);
	cdReal c = cdAbs(t.q.c), s = cdAbs(t.q.s);
	cd2Vec extent = {c * half.x + s * half.y, s * half.x + c * half.y};
	cd2Aabb local = {cd2Sub(center, extent), cd2Add(center, extent)};
	return local;
}

/* Visits the segments whose boxes overlap `box` in increasing order until fcn returns false.
 * Children are tested together (their boxes share a cache line) and only overlapping ones are
 * pushed, last child first so that the walk visits them in order. */
static void Query(const cd2Chain* chain, cd2Aabb box, cd2ChainQueryFcn* fcn, void* context)
{
	int rootLevel = chain->levelCount - 1;
	if (!BoxesOverlap(chain->bounds[chain->levelOffset[rootLevel]], box))
	{
		return;
	}
	if (rootLevel == 0)
	{
		fcn(0, context);
		return;
	}
	Node stack[STACK_SIZE];
	int top = 0;
	stack[top++] = (Node){rootLevel, 0, CD_R(0.0)};
	while (top > 0)
	{
		Node node = stack[--top];
		int level = node.level - 1;
		const cd2Aabb* children = chain->bounds + chain->levelOffset[level];
		int first = CHAIN_BRANCH * node.index;
		int last =
			first + CHAIN_BRANCH < chain->levelSize[level] ? first + CHAIN_BRANCH : chain->levelSize[level];
		if (level == 0)
		{
			for (int i = first; i < last; ++i)
			{
				if (BoxesOverlap(children[i], box) && !fcn(i, context))
				{
					return;
				}
			}
			continue;
		}
		for (int i = last - 1; i >= first; --i)
		{
			if (BoxesOverlap(children[i], box))
			{
				stack[top++] = (Node){level, i, CD_R(0.0)};
			}
		}
	}
}

void cd2Chain_QueryAabb(const cd2Chain* chain, cd2Transform chainTransform, cd2Aabb bounds,
						cd2ChainQueryFcn* fcn, void* context)
{
	CD_ASSERT(chain != NULL && fcn != NULL);
	Query(chain, LocalBounds(chainTransform, bounds), fcn, context);
}

/* ---- ray cast ----------------------------------------------------------------------------------- */

/* A ray in the chain's frame, with what the slab test needs precomputed. */
typedef struct LocalRay
{
	cd2Vec origin, d;
	cdReal inverse[2]; /* 1 / d per axis, 0 where d is zero (or too small to invert) */
	cdReal slack[2];   /* the round-off of a slab's fractions for any box of the chain, per axis */
} LocalRay;

/* Slab test of the segment origin + t * d, t in [0, maxFraction], against a closed box. */
static bool RayHitsBox(cd2Aabb box, const LocalRay* ray, cdReal maxFraction, cdReal* entry)
{
	cdReal lower = CD_R(0.0), upper = maxFraction;
	const cdReal o[2] = {ray->origin.x, ray->origin.y};
	const cdReal lo[2] = {box.min.x, box.min.y}, hi[2] = {box.max.x, box.max.y};
	for (int axis = 0; axis < 2; ++axis)
	{
		if (ray->inverse[axis] == CD_R(0.0))
		{
			if (o[axis] < lo[axis] || o[axis] > hi[axis])
			{
				return false;
			}
			continue;
		}
		cdReal t1 = (lo[axis] - o[axis]) * ray->inverse[axis], t2 = (hi[axis] - o[axis]) * ray->inverse[axis];
		/* Widened by the round-off so that a ray through the end of a flat run of segments (a box
		 * of zero height) is kept. */
		lower = cdMax(lower, cdMin(t1, t2) - ray->slack[axis]);
		upper = cdMin(upper, cdMax(t1, t2) + ray->slack[axis]);
		if (lower > upper)
		{
			return false;
		}
	}
	*entry = lower;
	return true;
}

/* One-sided hit of origin + t * d on p1 -> p2: the ray must move against the segment's right
 * normal, start on the free side (or on the segment), and cross it within both ends (closed).
 * Writes the fraction and the unit normal. Everything is in cross products of the inputs, so
 * nothing divides before the hit is certain. */
static bool RaycastSegment(cd2Vec p1, cd2Vec p2, cd2Vec origin, cd2Vec d, cdReal maxFraction,
						   cdReal* fraction, cd2Vec* normal)
{
	cd2Vec e = cd2Sub(p2, p1);
	cdReal denominator = -cd2Cross(d, e); /* |e| * (speed against the normal) */
	if (!(denominator > CD_R(0.0)))
	{
		return false;
	}
	cd2Vec r = cd2Sub(origin, p1);
	cdReal along = cd2Cross(r, e); /* |e| * height of the origin above the segment's line */
	if (along < CD_R(0.0) || along > maxFraction * denominator)
	{
		return false;
	}
	cdReal across = cd2Cross(r, d); /* denominator * (where along e the ray crosses, 0..1) */
	if (across < CD_R(0.0) || across > denominator)
	{
		return false;
	}
	cdReal t = cdMin(along / denominator, maxFraction);
	/* For a ray almost along the segment's line, across and denominator are both round-off and
	 * their ratio says nothing (fuzz_chain2: a ray along a segment's line, 1e9 short of it, hit at
	 * fraction 0); so the hit point itself must lie over the segment, within its round-off. */
	cd2Vec hit = cd2MulAdd(r, t, d); /* relative to p1 */
	cdReal position = cd2Dot(hit, e);
	cdReal lengthSquared = cd2Dot(e, e);
	cdReal slack = CD_R(8.0) * CD_REAL_EPSILON *
				   (cdAbs(r.x) + cdAbs(r.y) + cdAbs(d.x) + cdAbs(d.y) + cdAbs(e.x) + cdAbs(e.y)) *
				   (cdAbs(e.x) + cdAbs(e.y));
	if (position < -slack || position > lengthSquared + slack)
	{
		return false;
	}
	*fraction = t;
	*normal = cd2Normalize(cd2RightPerp(e));
	return true;
}

/* Keeps segment `index`'s hit when it is nearer than the best so far (the lower index on a tie). */
static void TestSegment(const cd2Chain* chain, const LocalRay* ray, int index, cdReal* best, int* bestIndex,
						cd2Vec* bestNormal)
{
	cdReal fraction;
	cd2Vec normal;
	if (RaycastSegment(chain->points[index], cd2ChainPoint(chain, index + 1), ray->origin, ray->d, *best,
					   &fraction, &normal) &&
		(*bestIndex < 0 || fraction < *best || (fraction == *best && index < *bestIndex)))
	{
		*best = fraction;
		*bestIndex = index;
		*bestNormal = normal;
	}
}

bool cd2RaycastChain(const cd2Chain* chain, cd2Transform chainTransform, cd2Ray ray, cd2RayHit* hit,
					 int* segmentIndex)
{
	CD_ASSERT(chain != NULL && hit != NULL);
	LocalRay local;
	local.origin = cd2InvTransformPoint(chainTransform, ray.origin);
	local.d = cd2InvRotateVector(chainTransform.q, ray.translation);
	/* A direction component whose inverse overflows (denormal) counts as zero: the ray moves by
	 * less than the smallest normal number along that axis. */
	local.inverse[0] = cdAbs(local.d.x) * CD_REAL_MAX >= CD_R(1.0) ? CD_R(1.0) / local.d.x : CD_R(0.0);
	local.inverse[1] = cdAbs(local.d.y) * CD_REAL_MAX >= CD_R(1.0) ? CD_R(1.0) / local.d.y : CD_R(0.0);
	/* A slab fraction (lo - o) / d is off by a few ulps of |lo| + |o|: bound |lo| by the chain's
	 * bounds once per ray instead of per box. */
	cd2Aabb root = cd2Chain_GetBounds(chain);
	cdReal extentX = cdMax(cdAbs(root.min.x), cdAbs(root.max.x)) + cdAbs(local.origin.x);
	cdReal extentY = cdMax(cdAbs(root.min.y), cdAbs(root.max.y)) + cdAbs(local.origin.y);
	local.slack[0] = CD_R(8.0) * CD_REAL_EPSILON * extentX * cdAbs(local.inverse[0]);
	local.slack[1] = CD_R(8.0) * CD_REAL_EPSILON * extentY * cdAbs(local.inverse[1]);
	cdReal best = CD_R(1.0);
	int bestIndex = -1;
	cd2Vec bestNormal = CD2_VEC_ZERO;

	int rootLevel = chain->levelCount - 1;
	Node stack[STACK_SIZE];
	int top = 0;
	cdReal rootEntry;
	if (RayHitsBox(chain->bounds[chain->levelOffset[rootLevel]], &local, best, &rootEntry))
	{
		stack[top++] = (Node){rootLevel, 0, rootEntry};
	}
	while (top > 0)
	{
		Node node = stack[--top];
		if (node.entry > best)
		{
			continue; /* a nearer hit came after this node was pushed */
		}
		if (node.level == 0)
		{
			/* Only a one-segment chain gets here: its root is the segment's box. */
			TestSegment(chain, &local, node.index, &best, &bestIndex, &bestNormal);
			continue;
		}
		int level = node.level - 1;
		const cd2Aabb* children = chain->bounds + chain->levelOffset[level];
		int first = CHAIN_BRANCH * node.index;
		int last =
			first + CHAIN_BRANCH < chain->levelSize[level] ? first + CHAIN_BRANCH : chain->levelSize[level];
		if (level == 0)
		{
			/* A segment test costs no more than its box's: no box test here. */
			for (int i = first; i < last; ++i)
			{
				TestSegment(chain, &local, i, &best, &bestIndex, &bestNormal);
			}
			continue;
		}
		/* The children the ray enters, pushed farthest first: the nearest is walked first and its
		 * hit shortens the ray for the others. */
		Node hits[CHAIN_BRANCH];
		int count = 0;
		for (int i = first; i < last; ++i)
		{
			cdReal entry;
			if (RayHitsBox(children[i], &local, best, &entry))
			{
				int k = count++;
				while (k > 0 && hits[k - 1].entry < entry)
				{
					hits[k] = hits[k - 1];
					--k;
				}
				hits[k] = (Node){level, i, entry};
			}
		}
		for (int k = 0; k < count; ++k)
		{
			stack[top++] = hits[k];
		}
	}
	if (bestIndex < 0)
	{
		return false;
	}
	hit->fraction = best;
	hit->point = cd2MulAdd(ray.origin, best, ray.translation);
	hit->normal = cd2RotateVector(chainTransform.q, bestNormal);
	if (segmentIndex != NULL)
	{
		*segmentIndex = bestIndex;
	}
	return true;
}

/* ---- manifolds ---------------------------------------------------------------------------------- */

typedef enum LocalKind
{
	LOCAL_CIRCLE,
	LOCAL_CAPSULE,
	LOCAL_POLYGON
} LocalKind;

/* The shape in the chain's frame, as one of the three kinds the chain segment functions take. */
typedef struct LocalShape
{
	LocalKind kind;
	cd2Circle circle;
	cd2Capsule capsule;
	cd2Polygon polygon;
	cd2Aabb bounds;
} LocalShape;

/* A rectangle center +- ax * hx +- ay * hy as a polygon; a zero size makes it a segment (a
 * zero-radius capsule, which is a point when both sizes are zero). */
static void SetRectangle(LocalShape* local, cd2Vec center, cd2Vec ax, cd2Vec ay, cdReal hx, cdReal hy)
{
	cd2Vec ex = cd2Scale(hx, ax), ey = cd2Scale(hy, ay);
	if (hx == CD_R(0.0) || hy == CD_R(0.0))
	{
		cd2Vec e = hx == CD_R(0.0) ? ey : ex;
		local->kind = LOCAL_CAPSULE;
		local->capsule = (cd2Capsule){cd2Sub(center, e), cd2Add(center, e), CD_R(0.0)};
		return;
	}
	cd2Polygon* p = &local->polygon;
	local->kind = LOCAL_POLYGON;
	p->vertices[0] = cd2Sub(cd2Sub(center, ex), ey);
	p->vertices[1] = cd2Sub(cd2Add(center, ex), ey);
	p->vertices[2] = cd2Add(cd2Add(center, ex), ey);
	p->vertices[3] = cd2Add(cd2Sub(center, ex), ey);
	p->normals[0] = cd2Neg(ay);
	p->normals[1] = ax;
	p->normals[2] = ay;
	p->normals[3] = cd2Neg(ax);
	p->centroid = center;
	p->count = 4;
	p->radius = CD_R(0.0);
}

static void ToLocal(LocalShape* local, const cd2Shape* shape, cd2Transform t)
{
	switch (shape->type)
	{
		case CD2_SHAPE_CIRCLE:
			local->kind = LOCAL_CIRCLE;
			local->circle.center = cd2InvTransformPoint(t, shape->circle.center);
			local->circle.radius = shape->circle.radius;
			break;
		case CD2_SHAPE_CAPSULE:
			local->kind = LOCAL_CAPSULE;
			local->capsule.p1 = cd2InvTransformPoint(t, shape->capsule.p1);
			local->capsule.p2 = cd2InvTransformPoint(t, shape->capsule.p2);
			local->capsule.radius = shape->capsule.radius;
			break;
		case CD2_SHAPE_SEGMENT:
			local->kind = LOCAL_CAPSULE;
			local->capsule.p1 = cd2InvTransformPoint(t, shape->segment.p1);
			local->capsule.p2 = cd2InvTransformPoint(t, shape->segment.p2);
			local->capsule.radius = CD_R(0.0);
			break;
		case CD2_SHAPE_AABB:
		{
			cd2Vec ax = cd2InvRotateVector(t.q, cd2MakeVec(CD_R(1.0), CD_R(0.0)));
			SetRectangle(local, cd2InvTransformPoint(t, cd2AabbCenter(shape->aabb)), ax, cd2LeftPerp(ax),
						 CD_R(0.5) * (shape->aabb.max.x - shape->aabb.min.x),
						 CD_R(0.5) * (shape->aabb.max.y - shape->aabb.min.y));
			break;
		}
		case CD2_SHAPE_BOX:
		{
			/* Normalized because validators accept rotations slightly off unit length. */
			cd2Rot q = cd2InvMulRot(t.q, cd2NormalizeRot(shape->box.rotation));
			cd2Vec ax = cd2MakeVec(q.c, q.s);
			SetRectangle(local, cd2InvTransformPoint(t, shape->box.center), ax, cd2LeftPerp(ax),
						 shape->box.halfExtents.x, shape->box.halfExtents.y);
			break;
		}
		default:
		{
			const cd2Polygon* world = &shape->polygon;
			cd2Polygon* p = &local->polygon;
			local->kind = LOCAL_POLYGON;
			for (int i = 0; i < world->count; ++i)
			{
				p->vertices[i] = cd2InvTransformPoint(t, world->vertices[i]);
				p->normals[i] = cd2InvRotateVector(t.q, world->normals[i]);
			}
			p->centroid = cd2InvTransformPoint(t, world->centroid);
			p->count = world->count;
			p->radius = world->radius;
			break;
		}
	}

	switch (local->kind)
	{
		case LOCAL_CIRCLE:
			local->bounds = cd2ComputeCircleAabb(local->circle);
			break;
		case LOCAL_CAPSULE:
			local->bounds = cd2ComputeCapsuleAabb(local->capsule);
			break;
		default:
			local->bounds = cd2ComputePolygonAabb(&local->polygon);
			break;
	}
}

typedef struct CollideContext
{
	const cd2Chain* chain;
	const LocalShape* shape;
	cd2Transform transform;
	cdReal speculativeDistance;
	cd2Manifold* manifolds;
	int* segmentIndices;
	int capacity;
	int count;
	/* The last and the first manifold kept, in the chain's frame, for removing shared vertices. */
	cd2Manifold previous, first;
	int previousIndex, firstIndex;
} CollideContext;

/* Drops the points of m that `earlier` (a neighbouring segment's manifold) already reports: at a
 * convex vertex both segments allow the same fan of normals and both report the vertex contact.
 * The lower segment keeps it (the loop's last segment yields to segment 0), so the owner does not
 * change while both touch. */
static void RemoveSharedPoints(cd2Manifold* m, const cd2Manifold* earlier)
{
	if (cd2Dot(m->normal, earlier->normal) < CD_R(1.0) - CD_R(1.0e-4))
	{
		return;
	}
	int kept = 0;
	for (int i = 0; i < m->pointCount; ++i)
	{
		cd2Vec p = m->points[i].point;
		cdReal tolerance =
			CD_R(0.01) * CD_LINEAR_SLOP + CD_R(8.0) * CD_REAL_EPSILON * cdMax(cdAbs(p.x), cdAbs(p.y));
		bool shared = false;
		for (int j = 0; j < earlier->pointCount && !shared; ++j)
		{
			shared = cd2VecDistanceSquared(p, earlier->points[j].point) <= tolerance * tolerance;
		}
		if (!shared)
		{
			m->points[kept++] = m->points[i];
		}
	}
	m->pointCount = kept;
}

/* Whether the whole shape lies above the segment's line by more than the speculative distance
 * (plus a margin for round-off): then the segment's manifold has no point, and this test, a few
 * cross products, saves the manifold's work for the segments a box query finds near the shape. */
static bool ClearlyAbove(const LocalShape* shape, cd2Vec p1, cd2Vec p2, cdReal speculativeDistance)
{
	cd2Vec e = cd2Sub(p2, p1);
	const cd2Vec* vertices;
	cd2Vec ends[2];
	int count;
	cdReal radius;
	switch (shape->kind)
	{
		case LOCAL_CIRCLE:
			vertices = &shape->circle.center;
			count = 1;
			radius = shape->circle.radius;
			break;
		case LOCAL_CAPSULE:
			ends[0] = shape->capsule.p1;
			ends[1] = shape->capsule.p2;
			vertices = ends;
			count = 2;
			radius = shape->capsule.radius;
			break;
		default:
			vertices = shape->polygon.vertices;
			count = shape->polygon.count;
			radius = shape->polygon.radius;
			break;
	}
	/* cross(v - p1, e) is |e| times the height of v above the line (the free side is positive). */
	cdReal lowest = CD_REAL_MAX;
	for (int i = 0; i < count; ++i)
	{
		lowest = cdMin(lowest, cd2Cross(cd2Sub(vertices[i], p1), e));
	}
	cdReal scale = cdMax(cdMax(cdAbs(p1.x), cdAbs(p1.y)), cdMax(cdAbs(vertices[0].x), cdAbs(vertices[0].y)));
	cdReal margin =
		speculativeDistance + radius + CD_R(0.1) * CD_LINEAR_SLOP + CD_R(64.0) * CD_REAL_EPSILON * scale;
	/* Squared, without the square root of |e| (lowest > 0 first; an overflow to infinity still
	 * compares right: only a shape far above the line overflows). */
	return lowest > CD_R(0.0) && lowest * lowest > margin * margin * cd2Dot(e, e);
}

static bool CollideSegment(int index, void* userContext)
{
	CollideContext* context = (CollideContext*)userContext;
	cd2ChainSegment segment = cd2Chain_GetSegment(context->chain, index);
	const LocalShape* shape = context->shape;
	if (ClearlyAbove(shape, segment.p1, segment.p2, context->speculativeDistance))
	{
		return true;
	}
	cd2Manifold m;
	switch (shape->kind)
	{
		case LOCAL_CIRCLE:
			m = cd2CollideChainSegmentCircleDirect(&segment, shape->circle, context->speculativeDistance);
			break;
		case LOCAL_CAPSULE:
			m = cd2CollideChainSegmentCapsuleDirect(&segment, shape->capsule, context->speculativeDistance);
			break;
		default:
			m = cd2CollideChainSegmentPolygonDirect(&segment, &shape->polygon, context->speculativeDistance);
			break;
	}
	if (m.pointCount == 0)
	{
		return true;
	}
	if (context->count > 0 && context->previousIndex == index - 1)
	{
		RemoveSharedPoints(&m, &context->previous);
	}
	if (context->count > 0 && context->firstIndex == 0 && index == context->chain->segmentCount - 1 &&
		context->chain->isLoop && index > 0)
	{
		RemoveSharedPoints(&m, &context->first);
	}
	if (m.pointCount == 0)
	{
		return true;
	}
	if (context->count == 0)
	{
		context->first = m;
		context->firstIndex = index;
	}
	context->previous = m;
	context->previousIndex = index;

	cd2Transform t = context->transform;
	m.normal = cd2RotateVector(t.q, m.normal);
	for (int i = 0; i < m.pointCount; ++i)
	{
		m.points[i].point = cd2TransformPoint(t, m.points[i].point);
	}
	context->manifolds[context->count] = m;
	if (context->segmentIndices != NULL)
	{
		context->segmentIndices[context->count] = index;
	}
	return ++context->count < context->capacity;
}

int cd2CollideChain(const cd2Chain* chain, cd2Transform chainTransform, const cd2Shape* shape,
					cdReal speculativeDistance, cd2Manifold* manifolds, int capacity, int* segmentIndices)
{
	CD_ASSERT(chain != NULL && shape != NULL && speculativeDistance >= CD_R(0.0));
	if (capacity <= 0 || manifolds == NULL)
	{
		return 0;
	}
	LocalShape local;
	ToLocal(&local, shape, chainTransform);
	CollideContext context;
	context.chain = chain;
	context.shape = &local;
	context.transform = chainTransform;
	context.speculativeDistance = speculativeDistance;
	context.manifolds = manifolds;
	context.segmentIndices = segmentIndices;
	context.capacity = capacity;
	context.count = 0;
	context.previousIndex = context.firstIndex = -2;
	Query(chain, cd2AabbInflate(local.bounds, speculativeDistance), CollideSegment, &context);
	return context.count;
}
