/* Contact manifolds of convex shapes against triangle meshes, one per triangle, with the internal
 * edges removed.
 *
 * Why internal edges need care: a box sliding over a floor made of many triangles meets each
 * triangle as a separate thin plate. Near a triangle's edge the separating axis test may find that
 * pushing the box sideways (off the edge) is shorter than pushing it up, and report a sideways
 * normal: the box stumbles on an edge the floor does not have. The builder marks each edge, for
 * each side of the triangle, as active (convex, boundary, non-manifold) or internal (flat or
 * concave); here a contact whose normal is not the face normal, and whose points all lie on
 * internal edges or vertices (or inside the face), is recomputed along the face normal. This is
 * the idea of Jolt's active edges and Bullet's btAdjustInternalEdgeContacts, done by
 * recomputing the contact (the shape's supporting face clipped to the triangle's prism) rather
 * than only turning the normal, so that the depths and points fit the new normal. */
#include "geometry/mesh3_internal.h"
#include "query/mesh_query3.h"

/* A contact normal within this sine of the face normal is a face contact (the round-off of two
 * normals computed differently, far below any real tilt of a contact). */
#define FACE_NORMAL_SINE CD_R(1.0e-5)
/* A contact point within this fraction of the longest edge from an edge lies on that edge. */
#define ON_EDGE_FRACTION CD_R(1.0e-3)
/* Capsules within this sine of parallel to the face touch it along their segment. */
#define PARALLEL_SINE CD_R(0.02)
/* Larger faces of hulls stand for their supporting vertex alone (clip buffers are fixed). */
#define MAX_FACE_VERTICES 32
#define MAX_CLIP (MAX_FACE_VERTICES + 4)
/* Marks the ids of recomputed contacts: the triangle's face against a face of the shape. */
#define MESH_FACE_CONTACT (1u << 29)

typedef struct ClipPoint
{
	cd3Vec p;
	uint32_t tag;
} ClipPoint;

static cd3Manifold EmptyManifold(void)
{
	cd3Manifold m;
	m.normal = CD3_VEC_ZERO;
	m.pointCount = 0;
	for (int i = 0; i < 4; ++i)
	{
		m.points[i].point = CD3_VEC_ZERO;
		m.points[i].separation = CD_R(0.0);
		m.points[i].id = 0u;
	}
	return m;
}

static cd3Vec Corner(cd3Triangle t, int k)
{
	return k == 0 ? t.a : (k == 1 ? t.b : t.c);
}

static cd3Vec ShapeCenter(const cd3Shape* s)
{
	switch (s->type)
	{
		case CD3_SHAPE_SPHERE:
			return s->sphere.center;
		case CD3_SHAPE_CAPSULE:
			return cd3Lerp(s->capsule.p1, s->capsule.p2, CD_R(0.5));
		case CD3_SHAPE_AABB:
			return cd3AabbCenter(s->aabb);
		case CD3_SHAPE_BOX:
			return s->box.center;
		case CD3_SHAPE_HULL:
			return cd3TransformPoint(s->hull.transform, s->hull.hull->centroid);
		default:
			return CD3_VEC_ZERO;
	}
}

/* ---- the shape's supporting feature along a direction ------------------------------------------- */

/* The core polygon (or segment, or point) of the shape farthest along `direction`, and the radius
 * around it. Returns the vertex count; *feature is an id for the feature. */
static int SupportFeature(const cd3Shape* s, cd3Vec direction, cd3Vec* out, cdReal* radius, uint32_t* feature)
{
	*radius = CD_R(0.0);
	*feature = 0u;
	switch (s->type)
	{
		case CD3_SHAPE_SPHERE:
			out[0] = s->sphere.center;
			*radius = s->sphere.radius;
			return 1;
		case CD3_SHAPE_CAPSULE:
		{
			cd3Capsule c = s->capsule;
			*radius = c.radius;
			cd3Vec axis = cd3Sub(c.p2, c.p1);
			cdReal along = cd3Dot(axis, direction);
			if (cdAbs(along) <= PARALLEL_SINE * cd3Length(axis) && cd3LengthSquared(axis) > CD_R(0.0))
			{
				out[0] = c.p1;
				out[1] = c.p2;
				*feature = 3u;
				return 2;
			}
			out[0] = along > CD_R(0.0) ? c.p2 : c.p1;
			*feature = along > CD_R(0.0) ? 2u : 1u;
			return 1;
		}
		case CD3_SHAPE_AABB:
		case CD3_SHAPE_BOX:
		{
			cd3Box b;
			if (s->type == CD3_SHAPE_AABB)
			{
				b.center = cd3AabbCenter(s->aabb);
				b.halfExtents = cd3AabbHalfExtents(s->aabb);
				b.rotation = CD3_QUAT_IDENTITY;
			}
			else
			{
				b = s->box;
			}
			cd3Vec local = cd3InvRotateVector(b.rotation, direction);
			cdReal l[3] = {local.x, local.y, local.z};
			int axis = 0;
			for (int k = 1; k < 3; ++k)
			{
				axis = cdAbs(l[k]) > cdAbs(l[axis]) ? k : axis;
			}
			cdReal sign = l[axis] >= CD_R(0.0) ? CD_R(1.0) : -CD_R(1.0);
			int u = (axis + 1) % 3, v = (axis + 2) % 3;
			cdReal h[3] = {b.halfExtents.x, b.halfExtents.y, b.halfExtents.z};
			static const cdReal su[4] = {-1, 1, 1, -1};
			static const cdReal sv[4] = {-1, -1, 1, 1};
			for (int i = 0; i < 4; ++i)
			{
				cdReal c[3];
				c[axis] = sign * h[axis];
				c[u] = su[i] * h[u];
				c[v] = sv[i] * h[v];
				out[i] = cd3Add(b.center, cd3RotateVector(b.rotation, cd3MakeVec(c[0], c[1], c[2])));
			}
			*feature = (uint32_t)(2 * axis + (sign > CD_R(0.0) ? 1 : 0));
			return 4;
		}
		case CD3_SHAPE_HULL:
		{
			const cd3Hull* hull = s->hull.hull;
			cd3Vec local = cd3InvRotateVector(s->hull.transform.q, direction);
			int face = 0;
			cdReal best = -CD_REAL_MAX;
			for (int f = 0; f < hull->faceCount; ++f)
			{
				cdReal d = cd3Dot(hull->planes[f].normal, local);
				if (d > best)
				{
					best = d;
					face = f;
				}
			}
			int count = 0;
			int e = hull->faceEdges[face];
			for (int guard = 0; guard < hull->edgeCount && count <= MAX_FACE_VERTICES; ++guard)
			{
				if (count < MAX_FACE_VERTICES)
				{
					out[count] = cd3TransformPoint(s->hull.transform, hull->vertices[hull->edges[e].origin]);
				}
				++count;
				e = hull->edges[e].next;
				if (e == hull->faceEdges[face])
				{
					break;
				}
			}
			*feature = (uint32_t)face;
			if (count <= MAX_FACE_VERTICES)
			{
				return count;
			}
			int vertex = 0;
			best = -CD_REAL_MAX;
			for (int i = 0; i < hull->vertexCount; ++i)
			{
				cdReal d = cd3Dot(hull->vertices[i], local);
				if (d > best)
				{
					best = d;
					vertex = i;
				}
			}
			out[0] = cd3TransformPoint(s->hull.transform, hull->vertices[vertex]);
			*feature = 0xffu;
			return 1;
		}
		default:
			return 0;
	}
}

/* ---- clipping to the triangle's prism and reduction ---------------------------------------------- */

/* Keeps the part of the polygon (or segment, or point) with dot(normal, x) <= offset. */
static int ClipPolygon(const ClipPoint* in, int count, cd3Vec normal, cdReal offset, uint32_t tag,
					   ClipPoint* out)
{
	if (count == 1)
	{
		if (cd3Dot(normal, in[0].p) <= offset)
		{
			out[0] = in[0];
			return 1;
		}
		return 0;
	}
	int n = 0;
	/* A segment is the polygon p0 p1 walked once: its closing edge would double the clip points. */
	int edges = count == 2 ? 1 : count;
	for (int i = 0; i < count; ++i)
	{
		ClipPoint p = in[i];
		cdReal dp = cd3Dot(normal, p.p) - offset;
		if (dp <= CD_R(0.0))
		{
			out[n++] = p;
		}
		if (i >= edges)
		{
			continue;
		}
		ClipPoint q = in[(i + 1) % count];
		cdReal dq = cd3Dot(normal, q.p) - offset;
		if ((dp <= CD_R(0.0)) != (dq <= CD_R(0.0)))
		{
			ClipPoint x;
			x.p = cd3Lerp(p.p, q.p, dp / (dp - dq));
			x.tag = (dp <= CD_R(0.0) ? q.tag : p.tag) | tag;
			out[n++] = x;
		}
	}
	return n;
}

typedef struct Candidate
{
	cd3Vec point;
	cdReal separation;
	uint32_t id;
} Candidate;

/* At most 4 of the candidates: the deepest, the farthest from it, the one making the largest
 * triangle with those, and the one adding the most area beyond that triangle. */
static int Reduce(const Candidate* c, int count, cd3Vec normal, Candidate* out)
{
	if (count <= 4)
	{
		for (int i = 0; i < count; ++i)
		{
			out[i] = c[i];
		}
		return count;
	}
	int i0 = 0;
	for (int i = 1; i < count; ++i)
	{
		i0 = c[i].separation < c[i0].separation ? i : i0;
	}
	int i1 = i0 == 0 ? 1 : 0;
	for (int i = 0; i < count; ++i)
	{
		if (i != i0 &&
			cd3VecDistanceSquared(c[i].point, c[i0].point) > cd3VecDistanceSquared(c[i1].point, c[i0].point))
		{
			i1 = i;
		}
	}
	int i2 = -1;
	cdReal bestArea = -CD_REAL_MAX;
	for (int i = 0; i < count; ++i)
	{
		if (i == i0 || i == i1)
		{
			continue;
		}
		cdReal area = cdAbs(
			cd3Dot(normal, cd3Cross(cd3Sub(c[i1].point, c[i0].point), cd3Sub(c[i].point, c[i0].point))));
		if (area > bestArea)
		{
			bestArea = area;
			i2 = i;
		}
	}
	/* The fourth on the other side of the triangle's edges: the largest area added. */
	int i3 = -1;
	bestArea = -CD_REAL_MAX;
	int tri[3] = {i0, i1, i2};
	for (int i = 0; i < count; ++i)
	{
		if (i == i0 || i == i1 || i == i2)
		{
			continue;
		}
		cdReal added = -CD_REAL_MAX;
		for (int e = 0; e < 3; ++e)
		{
			cd3Vec p = c[tri[e]].point, q = c[tri[(e + 1) % 3]].point;
			cdReal area = -cd3Dot(normal, cd3Cross(cd3Sub(q, p), cd3Sub(c[i].point, p)));
			cdReal signedTri =
				cd3Dot(normal, cd3Cross(cd3Sub(c[i1].point, c[i0].point), cd3Sub(c[i2].point, c[i0].point)));
			area = signedTri < CD_R(0.0) ? -area : area;
			added = cdMax(added, area);
		}
		if (added > bestArea)
		{
			bestArea = added;
			i3 = i;
		}
	}
	out[0] = c[i0];
	out[1] = c[i1];
	out[2] = c[i2];
	int n = 3;
	if (i3 >= 0)
	{
		out[n++] = c[i3];
	}
	return n;
}

/* The contact of the shape with the triangle along the face normal `up` (pointing to the shape):
 * the shape's supporting feature clipped to the triangle's prism, each point at its height. */
static cd3Manifold FaceContact(const cd3Shape* s, cd3Triangle t, cd3Vec up, cdReal speculativeDistance)
{
	cd3Manifold m = EmptyManifold();
	cd3Vec feature[MAX_FACE_VERTICES];
	cdReal radius;
	uint32_t featureId;
	int count = SupportFeature(s, cd3Neg(up), feature, &radius, &featureId);
	ClipPoint bufferA[MAX_CLIP], bufferB[MAX_CLIP];
	ClipPoint* in = bufferA;
	ClipPoint* out = bufferB;
	for (int i = 0; i < count; ++i)
	{
		in[i].p = feature[i];
		in[i].tag = (uint32_t)i;
	}
	for (int k = 0; k < 3 && count > 0; ++k)
	{
		cd3Vec p = Corner(t, k), q = Corner(t, (k + 1) % 3);
		/* Outward across edge k, in the face's plane (the face is counter-clockwise about up or
		 * clockwise: the sign comes from the third corner). */
		cd3Vec side = cd3Normalize(cd3Cross(cd3Sub(q, p), up));
		if (cd3Dot(side, cd3Sub(Corner(t, (k + 2) % 3), p)) > CD_R(0.0))
		{
			side = cd3Neg(side);
		}
		count = ClipPolygon(in, count, side, cd3Dot(side, p), 1u << (5 + k), out);
		ClipPoint* swap = in;
		in = out;
		out = swap;
	}
	Candidate candidates[MAX_CLIP];
	int kept = 0;
	for (int i = 0; i < count; ++i)
	{
		cdReal separation = cd3Dot(up, cd3Sub(in[i].p, t.a)) - radius;
		if (separation <= speculativeDistance)
		{
			cd3Vec onShape = cd3MulSub(in[i].p, radius, up);
			candidates[kept].point = cd3MulSub(onShape, CD_R(0.5) * separation, up);
			candidates[kept].separation = separation;
			candidates[kept].id = MESH_FACE_CONTACT | (featureId & 0xffu) << 8 | (in[i].tag & 0xffffu) << 16;
			++kept;
		}
	}
	Candidate reduced[4];
	int n = Reduce(candidates, kept, up, reduced);
	for (int i = 0; i < n; ++i)
	{
		m.points[i].point = reduced[i].point;
		m.points[i].separation = reduced[i].separation;
		m.points[i].id = reduced[i].id;
	}
	m.pointCount = n;
	m.normal = n > 0 ? cd3Neg(up) : CD3_VEC_ZERO;
	return m;
}

/* ---- internal edges -------------------------------------------------------------------------- */

static cdReal SegmentDistanceSquared(cd3Vec p, cd3Vec q, cd3Vec x)
{
	cd3Segment s = {p, q};
	return cd3VecDistanceSquared(cd3ClosestPointOnSegment(s, x), x);
}

/* The contact, or its recomputation along the face normal when it comes from internal features. */
static cd3Manifold FixInternalEdges(const cd3Shape* s, cd3Triangle t, uint32_t flags, cd3Manifold m,
									cdReal speculativeDistance)
{
	cd3Vec face = cd3Normalize(cd3Cross(cd3Sub(t.b, t.a), cd3Sub(t.c, t.a)));
	cd3Vec outward = cd3Neg(m.normal); /* from the triangle to the shape */
	cdReal alignment = cd3Dot(outward, face);
	if (cd3LengthSquared(cd3Cross(outward, face)) <= FACE_NORMAL_SINE * FACE_NORMAL_SINE ||
		cd3LengthSquared(face) == CD_R(0.0))
	{
		return m;
	}
	/* The side of the triangle the shape is on: its centre's, else the contact normal's. */
	cdReal height = cd3Dot(face, cd3Sub(ShapeCenter(s), t.a));
	bool front = height != CD_R(0.0) ? height > CD_R(0.0) : alignment >= CD_R(0.0);
	uint32_t active = front ? (flags & 7u) : ((flags >> 3) & 7u);
	cdReal longest = cdMax(cd3VecDistanceSquared(t.a, t.b),
						   cdMax(cd3VecDistanceSquared(t.b, t.c), cd3VecDistanceSquared(t.c, t.a)));
	cdReal reach = ON_EDGE_FRACTION * ON_EDGE_FRACTION * longest;
	for (int i = 0; i < m.pointCount; ++i)
	{
		/* The point on the triangle's surface. */
		cd3Vec q = cd3MulAdd(m.points[i].point, CD_R(0.5) * m.points[i].separation, m.normal);
		for (int k = 0; k < 3; ++k)
		{
			if (((active >> k) & 1u) != 0u &&
				SegmentDistanceSquared(Corner(t, k), Corner(t, (k + 1) % 3), q) <= reach)
			{
				return m; /* an active edge or one of its vertices: the edge normal is real */
			}
		}
	}
	return FaceContact(s, t, front ? face : cd3Neg(face), speculativeDistance);
}

/* ---- the mesh ------------------------------------------------------------------------------------ */

static int ContactKind(cd3Triangle t, const cd3Manifold* m);
#define KIND_SHIFT 24

typedef struct CollideContext
{
	const cd3Mesh* mesh;
	const cd3Shape* shape;
	cd3Transform xf;
	bool identity; /* the placement moves nothing: the triangles are used as stored */
	cdReal speculativeDistance;
	cd3MeshManifold* out;
	int capacity;
	int count;
} CollideContext;

static bool CollideSlot(int slot, void* context)
{
	CollideContext* c = (CollideContext*)context;
	cd3Triangle local = c->mesh->triangles[slot];
	cd3Triangle t = local;
	if (!c->identity)
	{
		t.a = cd3TransformPoint(c->xf, local.a);
		t.b = cd3TransformPoint(c->xf, local.b);
		t.c = cd3TransformPoint(c->xf, local.c);
	}
	cd3Shape triangle = cd3MakeTriangleShape(t);
	cd3Manifold m = cd3Collide(c->shape, &triangle, c->speculativeDistance);
	if (m.pointCount == 0)
	{
		return true;
	}
	m = FixInternalEdges(c->shape, t, c->mesh->edgeFlags[slot], m, c->speculativeDistance);
	if (m.pointCount == 0)
	{
		return true;
	}
	c->out[c->count].manifold = m;
	c->out[c->count].triangleIndex = c->mesh->inputIndex[slot] | ContactKind(t, &m) << KIND_SHIFT;
	++c->count;
	return c->count < c->capacity;
}

/* ---- duplicates at shared vertices ----------------------------------------------------------------
 * A vertex or edge contact on an active feature can still be a ghost: at the end of a triangle's
 * ridge edge the ridge goes on in the next triangle, which reports the real contact, while the
 * first sees only its corner and reports a normal tilted along the ridge. As in Jolt's
 * InternalEdgeRemovingCollector, face contacts are taken first, then the others deepest first,
 * and a contact whose features' vertices all belong to triangles already taken is dropped. */

static bool IsFaceContact(cd3Triangle t, const cd3Manifold* m)
{
	cd3Vec face = cd3Normalize(cd3Cross(cd3Sub(t.b, t.a), cd3Sub(t.c, t.a)));
	return cd3LengthSquared(cd3Cross(m->normal, face)) <= FACE_NORMAL_SINE * FACE_NORMAL_SINE;
}

static cdReal Deepest(const cd3Manifold* m)
{
	cdReal d = CD_REAL_MAX;
	for (int i = 0; i < m->pointCount; ++i)
	{
		d = cdMin(d, m->points[i].separation);
	}
	return d;
}

static bool HasCorner(cd3Triangle t, cd3Vec v)
{
	return cd3VecEqual(t.a, v) || cd3VecEqual(t.b, v) || cd3VecEqual(t.c, v);
}

/* Whether every contact point's feature (the corners within reach of it; none inside the face)
 * has all its corners in triangles taken before. `world` is the triangle in world space, `local`
 * in the mesh's frame, where corners are compared exactly (welded vertices are equal there). */
static bool AllFeaturesTaken(const cd3Mesh* mesh, const cd3MeshManifold* taken, int takenCount,
							 cd3Triangle world, cd3Triangle local, const cd3Manifold* m)
{
	cdReal longest =
		cdMax(cd3VecDistanceSquared(world.a, world.b),
			  cdMax(cd3VecDistanceSquared(world.b, world.c), cd3VecDistanceSquared(world.c, world.a)));
	cdReal reach = ON_EDGE_FRACTION * ON_EDGE_FRACTION * longest;
	for (int i = 0; i < m->pointCount; ++i)
	{
		cd3Vec q = cd3MulAdd(m->points[i].point, CD_R(0.5) * m->points[i].separation, m->normal);
		bool onFeature = false;
		for (int k = 0; k < 3; ++k)
		{
			cd3Vec p0 = Corner(world, k), p1 = Corner(world, (k + 1) % 3);
			if (SegmentDistanceSquared(p0, p1, q) > reach)
			{
				continue;
			}
			onFeature = true;
			/* The edge, or only its nearer corner when q is at a corner. */
			bool atP0 = cd3VecDistanceSquared(p0, q) <= reach, atP1 = cd3VecDistanceSquared(p1, q) <= reach;
			for (int end = 0; end < 2; ++end)
			{
				if ((end == 0 && atP1 && !atP0) || (end == 1 && atP0 && !atP1))
				{
					continue;
				}
				cd3Vec corner = Corner(local, end == 0 ? k : (k + 1) % 3);
				bool found = false;
				for (int j = 0; j < takenCount && !found; ++j)
				{
					found = HasCorner(mesh->triangles[mesh->slotOfInput[taken[j].triangleIndex]], corner);
				}
				if (!found)
				{
					return false;
				}
			}
		}
		if (!onFeature)
		{
			return false;
		}
	}
	return true;
}

static cd3Triangle WorldTriangle(const cd3Mesh* mesh, cd3Transform xf, int triangleIndex, cd3Triangle* local)
{
	*local = mesh->triangles[mesh->slotOfInput[triangleIndex]];
	cd3Triangle t = {cd3TransformPoint(xf, local->a), cd3TransformPoint(xf, local->b),
					 cd3TransformPoint(xf, local->c)};
	return t;
}

/* 0: a face contact (face normal, not all at one corner), 1: an edge contact, 2: all points at one
 * corner of the triangle (the likeliest ghost, so judged last). */
static int ContactKind(cd3Triangle t, const cd3Manifold* m)
{
	cdReal longest = cdMax(cd3VecDistanceSquared(t.a, t.b),
						   cdMax(cd3VecDistanceSquared(t.b, t.c), cd3VecDistanceSquared(t.c, t.a)));
	cdReal reach = ON_EDGE_FRACTION * ON_EDGE_FRACTION * longest;
	for (int k = 0; k < 3; ++k)
	{
		bool all = true;
		for (int i = 0; i < m->pointCount && all; ++i)
		{
			cd3Vec q = cd3MulAdd(m->points[i].point, CD_R(0.5) * m->points[i].separation, m->normal);
			all = cd3VecDistanceSquared(q, Corner(t, k)) <= reach;
		}
		if (all)
		{
			return 2;
		}
	}
	return IsFaceContact(t, m) ? 0 : 1;
}

/* During the ghost removal each manifold's kind rides in the bits of its triangle index above the
 * 24 an index needs (CD3_MAX_MESH_TRIANGLES, KIND_SHIFT above). */
#define INDEX_MASK ((1 << KIND_SHIFT) - 1)

static int RemoveGhosts(const cd3Mesh* mesh, cd3Transform xf, cd3MeshManifold* m, int count)
{
	/* By kind, then deepest first (a stable insertion sort of the manifolds found, at most the
	 * caller's capacity); face contacts are all kept. */
	for (int i = 1; i < count; ++i)
	{
		cd3MeshManifold x = m[i];
		int kind = x.triangleIndex >> KIND_SHIFT;
		cdReal depth = Deepest(&x.manifold);
		int j = i;
		while (j > 0)
		{
			int yKind = m[j - 1].triangleIndex >> KIND_SHIFT;
			if (yKind < kind || (yKind == kind && (kind == 0 || Deepest(&m[j - 1].manifold) <= depth)))
			{
				break;
			}
			m[j] = m[j - 1];
			--j;
		}
		m[j] = x;
	}
	int kept = 0;
	for (int i = 0; i < count; ++i)
	{
		int kind = m[i].triangleIndex >> KIND_SHIFT;
		m[i].triangleIndex &= INDEX_MASK;
		bool keep = kind == 0;
		if (!keep)
		{
			cd3Triangle local;
			cd3Triangle world = WorldTriangle(mesh, xf, m[i].triangleIndex, &local);
			keep = !AllFeaturesTaken(mesh, m, kept, world, local, &m[i].manifold);
		}
		if (keep)
		{
			m[kept++] = m[i];
		}
	}
	return kept;
}

int cd3CollideMesh(const cd3Shape* shape, const cd3Mesh* mesh, cd3Transform meshTransform,
				   cdReal speculativeDistance, cd3MeshManifold* manifolds, int capacity)
{
	if (shape == NULL || mesh == NULL || manifolds == NULL || capacity <= 0)
	{
		return 0;
	}
	switch (shape->type)
	{
		case CD3_SHAPE_SPHERE:
		case CD3_SHAPE_CAPSULE:
		case CD3_SHAPE_AABB:
		case CD3_SHAPE_BOX:
		case CD3_SHAPE_HULL:
			break;
		default:
			return 0;
	}
	cdReal margin = cdMax(speculativeDistance, CD_R(0.0));
	cd3Aabb world = cd3AabbInflate(cd3ComputeShapeAabb(shape), margin);
	bool identity = meshTransform.p.x == CD_R(0.0) && meshTransform.p.y == CD_R(0.0) &&
					meshTransform.p.z == CD_R(0.0) && meshTransform.q.x == CD_R(0.0) &&
					meshTransform.q.y == CD_R(0.0) && meshTransform.q.z == CD_R(0.0) &&
					meshTransform.q.w == CD_R(1.0);
	CollideContext c = {mesh, shape, meshTransform, identity, speculativeDistance, manifolds, capacity, 0};
	cd3MeshVisitSlots(mesh, cd3MeshBoundsOfWorldAabb(meshTransform, world), CollideSlot, &c);
	return RemoveGhosts(mesh, meshTransform, manifolds, c.count);
}
