/* Internal: 3D shapes as GJK sees them. Every finite shape is the convex hull of "core" points
 * grown by a radius (a sphere is a point, a capsule a segment, a box its eight corners). A
 * convex hull's vertices (any number up to CD3_MAX_HULL_POINTS) stay in the hull's own frame:
 * the support search rotates the direction instead of moving every vertex. The half-space has
 * no finite core and is handled separately by its users. */
#ifndef COLLIDE_SUPPORT3_H
#define COLLIDE_SUPPORT3_H

#include "collide/geometry3.h"
#include "collide/query3.h"

#include "pairs3.h"
#include "sat3_support.h"

#define CD3_CORE_MAX_POINTS 8

typedef struct cd3Core
{
	cd3Vec points[CD3_CORE_MAX_POINTS];
	int count;
	cdReal radius;
	const cd3Vec* localPoints;	/* a hull's vertices (count of them), or NULL */
	const cdReal* localColumns; /* the same vertices as columns (cd3Hull.vertexColumns), or NULL */
	bool box;					/* corner i = centre +- axes[0] +- axes[1] +- axes[2], bit k of i: + */
	bool lazyBox;				/* an oriented box: its corners are made on demand from centre, axes */
	bool orientedBox;			/* an oriented box whose points hold its corners (centre, axes valid) */
	cd3Vec center;
	cd3Vec axes[3];
	cd3Mat33 rotation; /* world = rotation * local + translation, for localPoints */
	cd3Vec translation;
} cd3Core;

/* The shape table's support columns (pairs3.h: MakeCore and Radius, one row per shape). Each
 * MakeCore(shape, core) fills the core's points (or the hull's local vertices) and count from the
 * tagged shape; cd3MakeCore has cleared the other fields and takes the radius from the Radius
 * column. */
#define CD3_SPHERE_RADIUS(s) ((s)->sphere.radius)
#define CD3_CAPSULE_RADIUS(s) ((s)->capsule.radius)

static inline bool cd3MakeSphereCore(const cd3Shape* shape, cd3Core* core)
{
	core->points[0] = shape->sphere.center;
	core->count = 1;
	return true;
}

static inline bool cd3MakeCapsuleCore(const cd3Shape* shape, cd3Core* core)
{
	core->points[0] = shape->capsule.p1;
	core->points[1] = shape->capsule.p2;
	core->count = 2;
	return true;
}

static inline bool cd3MakeAabbCore(const cd3Shape* shape, cd3Core* core)
{
	cd3Vec lo = shape->aabb.min, hi = shape->aabb.max;
	for (int i = 0; i < 8; ++i)
	{
		core->points[i] = cd3MakeVec((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z);
	}
	core->count = 8;
	core->box = true;
	core->axes[0] = cd3MakeVec(hi.x - lo.x, CD_R(0.0), CD_R(0.0));
	core->axes[1] = cd3MakeVec(CD_R(0.0), hi.y - lo.y, CD_R(0.0));
	core->axes[2] = cd3MakeVec(CD_R(0.0), CD_R(0.0), hi.z - lo.z);
	return true;
}

static inline bool cd3MakeBoxCore(const cd3Shape* shape, cd3Core* core)
{
	const cd3Box* box = &shape->box;
	/* The rotation's matrix once, its columns scaled: cheaper than three rotations. */
	cd3Mat33 rotation = cd3MakeMatFromQuat(box->rotation);
	cd3Vec axisX = cd3Scale(box->halfExtents.x, rotation.cx);
	cd3Vec axisY = cd3Scale(box->halfExtents.y, rotation.cy);
	cd3Vec axisZ = cd3Scale(box->halfExtents.z, rotation.cz);
	/* All eight corners at once, sharing their partial sums (the same bits as cd3BoxCorner):
	 * cheaper than building the handful GJK reads one by one. */
	core->count = 8;
	core->box = true;
	core->orientedBox = true;
	core->center = box->center;
	core->axes[0] = axisX;
	core->axes[1] = axisY;
	core->axes[2] = axisZ;
	cd3Vec alongX[2] = {cd3Sub(box->center, axisX), cd3Add(box->center, axisX)};
	cd3Vec alongXY[4];
	for (int i = 0; i < 4; ++i)
	{
		alongXY[i] = (i & 2) ? cd3Add(alongX[i & 1], axisY) : cd3Sub(alongX[i & 1], axisY);
	}
	for (int i = 0; i < 8; ++i)
	{
		core->points[i] = (i & 4) ? cd3Add(alongXY[i & 3], axisZ) : cd3Sub(alongXY[i & 3], axisZ);
	}
	return true;
}

static inline bool cd3MakeTriangleCore(const cd3Shape* shape, cd3Core* core)
{
	core->points[0] = shape->triangle.a;
	core->points[1] = shape->triangle.b;
	core->points[2] = shape->triangle.c;
	core->count = 3;
	return true;
}

static inline bool cd3MakeSegmentCore(const cd3Shape* shape, cd3Core* core)
{
	core->points[0] = shape->segment.p1;
	core->points[1] = shape->segment.p2;
	core->count = 2;
	return true;
}

static inline bool cd3MakeHullCore(const cd3Shape* shape, cd3Core* core)
{
	core->localPoints = shape->hull.hull->vertices;
	core->localColumns = shape->hull.hull->vertexColumns;
	core->count = shape->hull.hull->vertexCount;
	core->rotation = cd3MakeMatFromQuat(shape->hull.transform.q);
	core->translation = shape->hull.transform.p;
	return true;
}

/* Fills *core from the shape table for every shape type except the half-space (returns false for
 * it and for an unknown type). */
static inline bool cd3MakeCore(const cd3Shape* shape, cd3Core* core)
{
	core->radius = CD_R(0.0);
	core->localPoints = NULL;
	core->localColumns = NULL;
	core->box = false;
	core->lazyBox = false;
	core->orientedBox = false;
	switch (shape->type)
	{
#define CD3_CORE_RADIUS(Radius) core->radius = Radius(shape);
#define CD3_CORE(Name, MakeCore, Radius)                                                                     \
	case CD3_TYPE_##Name:                                                                                    \
	{                                                                                                        \
		bool made = MakeCore(shape, core);                                                                   \
		CD_SHAPE_HAS(Radius, CD3_CORE_RADIUS)(Radius) return made;                                           \
	}
#define CD3_CORE_CASE(Name, PointIn, ClosestPointOn, Raycast, TypeName, Validate, ComputeAabb, ComputeMass,  \
					  MakeCore, Radius)                                                                      \
	CD_SHAPE_HAS(MakeCore, CD3_CORE)(Name, MakeCore, Radius)
		CD3_SHAPE_TABLE(CD3_CORE_CASE)
#undef CD3_CORE_CASE
#undef CD3_CORE
#undef CD3_CORE_RADIUS
		default:
			core->count = 0;
			return false;
	}
}

/* Corner i of a box core, centre +- axes in this order (the same bits whenever it is built: a
 * product by +-1 is exact). The signs come from the index bits by integer arithmetic: written as
 * a choice, GCC 12 branched on each bit, and the bits of a support corner are as good as random
 * (so those branches mispredict half the time). */
static inline cd3Vec cd3BoxCorner(const cd3Core* core, int i)
{
	cdReal signX = (cdReal)(((i & 1) << 1) - 1);
	cdReal signY = (cdReal)((i & 2) - 1);
	cdReal signZ = (cdReal)(((i & 4) >> 1) - 1);
	cd3Vec p = cd3MulAdd(core->center, signX, core->axes[0]);
	p = cd3MulAdd(p, signY, core->axes[1]);
	return cd3MulAdd(p, signZ, core->axes[2]);
}

/* Core point i in world space. */
static inline cd3Vec cd3CorePoint(const cd3Core* core, int i)
{
	if (core->localPoints != NULL)
	{
		return cd3Add(cd3MulMV(core->rotation, core->localPoints[i]), core->translation);
	}
	if (core->lazyBox)
	{
		return cd3BoxCorner(core, i);
	}
	return core->points[i];
}

/* A point of the core's hull near its middle (a box's centre, a hull's origin, else the first
 * point): GJK's cold start looks for supports along the line between two of them. */
static inline cd3Vec cd3CoreCenter(const cd3Core* core)
{
	if (core->lazyBox || core->orientedBox)
	{
		return core->center;
	}
	if (core->localPoints != NULL)
	{
		return core->translation;
	}
	return core->points[0];
}

/* Largest |coordinate| without a branch per coordinate (max(x, -x) is a max instruction; a
 * branchy absolute value mispredicts in GJK's hot loops, whose signs are as good as random). */
static inline cdReal cd3MaxAbs(cd3Vec v)
{
	return cdMax(cdMax(cdMax(v.x, -v.x), cdMax(v.y, -v.y)), cdMax(v.z, -v.z));
}

/* Index of the point farthest along `direction` (the first one on ties): sat3_support.h's scan,
 * four vertices at a time without branches in the float build on SSE2 (the same index, bit for
 * bit, as a plain first-maximum loop, whose branch on every new maximum mispredicts). */
static inline int cd3SupportScan(const cd3Vec* points, int count, cd3Vec direction)
{
	return cd3SupportIndex(points, count, direction);
}

/* `inline`, and always inlined where the compiler allows forcing it: the supports below run in
 * GJK's loop, where a call spills the loop's SSE registers. */
#if defined(__GNUC__) || defined(__clang__)
#define CD3_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define CD3_ALWAYS_INLINE inline
#endif

/* A hull core's support: its vertex farthest along the direction carried into its frame. */
static CD3_ALWAYS_INLINE int cd3HullCoreSupport(const cd3Core* core, cd3Vec direction)
{
	cd3Vec local = cd3MulMTV(core->rotation, direction);
	if (core->localColumns == NULL)
	{
		return cd3SupportScan(core->localPoints, core->count, local);
	}
	int stride = CD3_HULL_COLUMN_STRIDE(core->count);
	const cdReal* xs = core->localColumns;
	return cd3ColumnsSupportIndex(xs, xs + stride, xs + 2 * stride, core->count, stride, local);
}

/* Index of the core point farthest along `direction` (the first one on ties). A box's corner is
 * chosen by the signs of its three axes along the direction (three products instead of eight;
 * a zero product, a tie, keeps the lower corner as the scan would). Always inlined: with the
 * hull's scan in it, GCC 12 stopped inlining it into GJK's loop, and a call there costs the box
 * path more than the scan saves the hull path. */
static CD3_ALWAYS_INLINE int cd3CoreSupport(const cd3Core* core, cd3Vec direction)
{
	if (core->box)
	{
		return (cd3Dot(core->axes[0], direction) > CD_R(0.0) ? 1 : 0) |
			   (cd3Dot(core->axes[1], direction) > CD_R(0.0) ? 2 : 0) |
			   (cd3Dot(core->axes[2], direction) > CD_R(0.0) ? 4 : 0);
	}
	if (core->localPoints != NULL)
	{
		return cd3HullCoreSupport(core, direction);
	}
	int best = 0;
	cdReal bestValue = cd3Dot(core->points[0], direction);
	for (int i = 1; i < core->count; ++i)
	{
		cdReal value = cd3Dot(core->points[i], direction);
		if (value > bestValue)
		{
			best = i;
			bestValue = value;
		}
	}
	return best;
}

/* Two half-spaces dot(n, x) <= offset (unit normals) are apart exactly when their normals are
 * opposite and -offset_b > offset_a; *gap = -(offset_a + offset_b) is then their distance. The
 * one decision that cd3OverlapPlanePlane and cd3Distance share, so that overlap holds exactly when
 * the distance is zero. Normals count as opposite when the sine of their angle is at most 16
 * epsilon (the tolerance of the rotated tests, docs/API.md): boundaries that close to antiparallel
 * meet only around gap / sine >= gap / (16 epsilon) from the origin, where the spacing of the
 * coordinates exceeds the gap itself. A gap up to 16 epsilon of the offsets is touching. Symmetric
 * in its arguments to the bit. */
#define CD3_OPPOSITE_SINE_LIMIT (CD_R(16.0) * CD_REAL_EPSILON)

static inline bool cd3HalfSpacesApart(cd3Plane a, cd3Plane b, cdReal* gap)
{
	const cdReal limit = CD3_OPPOSITE_SINE_LIMIT;
	cdReal cosine = cd3Dot(a.normal, b.normal);
	cdReal sineSquared = cd3LengthSquared(cd3Cross(a.normal, b.normal));
	*gap = -(a.offset + b.offset);
	if (cosine >= CD_R(0.0) || sineSquared > limit * limit)
	{
		return false;
	}
	return *gap > limit * cdMax(cdAbs(a.offset), cdAbs(b.offset));
}

/* GJK's simplex, shared by the distance (distance3.c) and the shape cast (cast.inc). */
typedef struct cd3GjkVertex
{
	cd3Vec a, b, w; /* support points on A and B, w = a - b */
	int indexA, indexB;
} cd3GjkVertex;

typedef struct cd3GjkSimplex
{
	cd3GjkVertex v[4];
	cdReal lambda[4];
	int count;
} cd3GjkSimplex;

/* Reduces the simplex to the vertices that support its point closest to the origin and sets
 * their weights (lambda, summing to 1); true when the origin is enclosed (the shapes touch). */
bool cd3SolveGjkSimplex(cd3GjkSimplex* simplex);

/* The direction from the simplex (closest point v) towards the origin, of any length, built from
 * the simplex's edges where -v, a sum of large cancelling terms, would point off (distance3.c). */
cd3Vec cd3GjkSearchDirection(const cd3GjkSimplex* simplex, cd3Vec v);

/* GJK distance of two cores (distance3.c), radii included, warm-started from *cache and
 * updating it (cache and status may be NULL). */
cd3ClosestPoints cd3DistanceCores(const cd3Core* coreA, const cd3Core* coreB, cd3SimplexCache* cache,
								  cdDistanceStatus* status);

#endif
