/* 2D shape cast and time of impact: the shape moves of cast.inc. */
#include "collide/cast.h"

#include "support2.h"

#include <string.h>

/* The dimension of cast.inc (base/dim.h: CD_DIM_NAME, CD_VEC, CD_SHAPE, CD_SWEEP,
 * CD_TRANSFORM) and the most contact axes a pair of shapes can have. */
#define CD_DIM 2
#include "base/dim.h"
#define CAST_MAX_AXES (2 + 2 * CD2_MAX_POLYGON_VERTICES)

static bool MakeCastCore(const cd2Shape* shape, cd2Core* core)
{
	return cd2MakeCore(shape, core);
}

static cd2Vec CastCorePoint(const cd2Core* core, int i)
{
	return core->points[i];
}

static cd2Vec CastCoreCenter(const cd2Core* core)
{
	return cd2CoreCenter(core);
}

static int CastCoreSupport(const cd2Core* core, cd2Vec direction, int start)
{
	return cd2CoreSupportFrom(core, direction, start);
}

/* The support values of the time of impact's steps along a fixed axis: the largest value by lanes
 * (support2.h), without the hill climb's data-dependent branches, which a turning body's supports
 * defeat, and without going back to the support point (the start is not needed). */
#define CAST_AXIS_SUPPORT_VALUE cd2CoreSupportValueLanes

/* |a x b|^2: by Lagrange's identity |a|^2 |b|^2 - (a.b)^2 without its cancellation. */
static cdReal CrossLengthSquared(cd2Vec a, cd2Vec b)
{
	cdReal cross = cd2Cross(a, b);
	return cross * cross;
}

static cdReal MaxAbs(cd2Vec v)
{
	return cd2MaxAbs(v);
}

static cdReal StripRadius(cd2Shape* shape)
{
	cdReal radius = CD_R(0.0);
	switch (shape->type)
	{
#define STRIP_RADIUS(Name, Radius)                                                                           \
	case CD2_TYPE_##Name:                                                                                    \
		radius = Radius(shape);                                                                              \
		Radius(shape) = CD_R(0.0);                                                                           \
		break;
#define STRIP_RADIUS_CASE(Name, PointIn, ClosestPointOn, Raycast, TypeName, Validate, ComputeAabb,           \
						  ComputeMass, MakeCore, Radius)                                                     \
	CD_SHAPE_HAS(Radius, STRIP_RADIUS)(Name, Radius)
		CD2_SHAPE_TABLE(STRIP_RADIUS_CASE)
#undef STRIP_RADIUS_CASE
#undef STRIP_RADIUS
		default:
			break;
	}
	return radius;
}

static cd2Shape TranslateShape(const cd2Shape* shape, cd2Vec d)
{
	cd2Shape s = *shape;
	switch (shape->type)
	{
		case CD2_SHAPE_CIRCLE:
			s.circle.center = cd2Add(s.circle.center, d);
			break;
		case CD2_SHAPE_CAPSULE:
			s.capsule.p1 = cd2Add(s.capsule.p1, d);
			s.capsule.p2 = cd2Add(s.capsule.p2, d);
			break;
		case CD2_SHAPE_AABB:
			s.aabb.min = cd2Add(s.aabb.min, d);
			s.aabb.max = cd2Add(s.aabb.max, d);
			break;
		case CD2_SHAPE_BOX:
			s.box.center = cd2Add(s.box.center, d);
			break;
		case CD2_SHAPE_POLYGON:
			for (int i = 0; i < s.polygon.count; ++i)
			{
				s.polygon.vertices[i] = cd2Add(s.polygon.vertices[i], d);
			}
			s.polygon.centroid = cd2Add(s.polygon.centroid, d);
			break;
		case CD2_SHAPE_SEGMENT:
			s.segment.p1 = cd2Add(s.segment.p1, d);
			s.segment.p2 = cd2Add(s.segment.p2, d);
			break;
		default:
			break;
	}
	return s;
}

/* A turned AABB is a box. */
static cd2Shape PlaceShape(const cd2Shape* shape, cd2Transform xf)
{
	cd2Shape s = *shape;
	switch (shape->type)
	{
		case CD2_SHAPE_CIRCLE:
			s.circle.center = cd2TransformPoint(xf, s.circle.center);
			break;
		case CD2_SHAPE_CAPSULE:
			s.capsule.p1 = cd2TransformPoint(xf, s.capsule.p1);
			s.capsule.p2 = cd2TransformPoint(xf, s.capsule.p2);
			break;
		case CD2_SHAPE_AABB:
		{
			cd2Box box = {cd2TransformPoint(xf, cd2AabbCenter(shape->aabb)), cd2AabbHalfExtents(shape->aabb),
						  xf.q};
			s = cd2MakeBoxShape(box);
			break;
		}
		case CD2_SHAPE_BOX:
			s.box.center = cd2TransformPoint(xf, s.box.center);
			s.box.rotation = cd2MulRot(xf.q, s.box.rotation);
			break;
		case CD2_SHAPE_POLYGON:
			for (int i = 0; i < s.polygon.count; ++i)
			{
				s.polygon.vertices[i] = cd2TransformPoint(xf, s.polygon.vertices[i]);
				s.polygon.normals[i] = cd2RotateVector(xf.q, s.polygon.normals[i]);
			}
			s.polygon.centroid = cd2TransformPoint(xf, s.polygon.centroid);
			break;
		case CD2_SHAPE_SEGMENT:
			s.segment.p1 = cd2TransformPoint(xf, s.segment.p1);
			s.segment.p2 = cd2TransformPoint(xf, s.segment.p2);
			break;
		default:
			break;
	}
	return s;
}

static bool ShapeExtent(const cd2Shape* shape, cd2Vec center, cdReal* extent)
{
	cd2Core core;
	*extent = CD_R(0.0);
	if (!cd2MakeCore(shape, &core))
	{
		return true; /* unknown type: cd2Distance asserts on it */
	}
	cdReal farthestSquared = CD_R(0.0);
	for (int i = 0; i < core.count; ++i)
	{
		farthestSquared = cdMax(farthestSquared, cd2VecDistanceSquared(core.points[i], center));
	}
	*extent = cdSqrt(farthestSquared) + core.radius;
	return true;
}

/* A body-frame core moved into the world (radius dropped: the casts grow by the radii). */
typedef struct PlacedCore
{
	cd2Core core;
	cd2Vec points[CD2_CORE_MAX_POINTS];
} PlacedCore;
#define PLACED_CORE PlacedCore

static void PlaceCore(const cd2Core* local, cd2Transform xf, PlacedCore* placed)
{
	placed->core.count = local->count;
	placed->core.radius = CD_R(0.0);
	for (int i = 0; i < local->count; ++i)
	{
		placed->points[i] = cd2TransformPoint(xf, local->points[i]);
	}
	placed->core.points = placed->points;
}

typedef struct SweepMotion
{
	cd2Vec localCenter, center0, velocity;
	cdReal angle0, angularVelocity, angularSpeed;
	cd2Rot restRotation; /* the rotation at every t when the sweep does not turn */
} SweepMotion;

static SweepMotion MakeMotion(const cd2Sweep* sweep)
{
	SweepMotion m;
	m.localCenter = sweep->localCenter;
	m.center0 = sweep->center0;
	m.velocity = cd2Sub(sweep->center1, sweep->center0);
	m.angle0 = sweep->angle0;
	m.angularVelocity = sweep->angle1 - sweep->angle0;
	m.angularSpeed = cdAbs(m.angularVelocity);
	/* Without turning, angle0 + t * angularVelocity is angle0 + angularVelocity (a zero of the
	 * same sign) for every t >= 0: one sine and cosine for the whole sweep instead of one per
	 * evaluation (they were a fifth of a time of impact against a body at rest). */
	m.restRotation = cd2MakeRot(m.angularVelocity == CD_R(0.0) ? m.angle0 + m.angularVelocity : CD_R(0.0));
	return m;
}

/* Always inlined: a call here spilled the time of impact's loop registers. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline cd2Transform
MotionTransform(const SweepMotion* m, cdReal t)
{
	cd2Transform xf;
	xf.q = m->angularVelocity == CD_R(0.0) ? m->restRotation : cd2MakeRot(m->angle0 + t * m->angularVelocity);
	xf.p = cd2Sub(cd2MulAdd(m->center0, t, m->velocity), cd2RotateVector(xf.q, m->localCenter));
	return xf;
}

/* A sweep that neither moves nor turns: MotionTransform gives the same transform at every t >= 0
 * (t times a zero is a zero of one sign for all of them). */
#define CAST_MOTION_STILL(m)                                                                                 \
	((m)->angularVelocity == CD_R(0.0) && (m)->velocity.x == CD_R(0.0) && (m)->velocity.y == CD_R(0.0))

cd2Transform cd2GetSweepTransform(const cd2Sweep* sweep, cdReal t)
{
	SweepMotion m = MakeMotion(sweep);
	return MotionTransform(&m, t);
}

/* The normals of the core's edges as axes from A towards B: a polygon's outward normals
 * (counter-clockwise: right of each edge) for A, inward for B (sign -1); both normals of a
 * capsule's or segment's line. */
static int AppendEdgeAxes(const cd2Core* core, cdReal sign, cd2Vec* axes, int count)
{
	int edges = core->count == 2 ? 1 : (core->count > 2 ? core->count : 0);
	for (int i = 0; i < edges && count + 2 <= CAST_MAX_AXES; ++i)
	{
		cd2Vec edge = cd2Sub(core->points[(i + 1) % core->count], core->points[i]);
		cdReal length = cd2Length(edge);
		if (length > CD_R(0.0))
		{
			cd2Vec normal = cd2Scale(sign / length, cd2RightPerp(edge));
			axes[count++] = normal;
			if (core->count == 2)
			{
				axes[count++] = cd2Neg(normal);
			}
		}
	}
	return count;
}

/* The edge normals of both cores, the candidate contact normals of cast.inc. */
static int ContactAxes(const cd2Shape* a, const cd2Shape* b, cd2Vec* axes, int count)
{
	cd2Core coreA, coreB;
	if (cd2MakeCore(a, &coreA))
	{
		count = AppendEdgeAxes(&coreA, CD_R(1.0), axes, count);
	}
	if (cd2MakeCore(b, &coreB))
	{
		count = AppendEdgeAxes(&coreB, CD_R(-1.0), axes, count);
	}
	return count;
}

/* The time of impact's axis between GJK calls (cast.inc): the features of the last GJK simplex
 * (its cache, on the body-frame cores) moved with the bodies. One point of each core: the
 * direction between them; an edge of one core (two of its points) against a point or an edge of
 * the other: the edge's normal, turning with its body. Any unit axis gives a separation at most
 * the distance, so the choice changes how fast the steps go, never their bound. */
typedef enum FeatureAxisType
{
	FEATURE_AXIS_FIXED,	 /* the closest-point normal, fixed in the world */
	FEATURE_AXIS_POINTS, /* pointB - pointA, normalized */
	FEATURE_AXIS_EDGE_A, /* an edge normal of A, in A's frame */
	FEATURE_AXIS_EDGE_B	 /* an edge normal of B, in B's frame */
} FeatureAxisType;

typedef struct FeatureAxis
{
	FeatureAxisType type;
	int countA, countB; /* the features' points: 1 or 2 on each core (index 1 = index 0 for 1) */
	int indexA[2], indexB[2];
	cd2Vec normal; /* FIXED: the world axis; EDGE_A / EDGE_B: the axis in that body's frame */
} FeatureAxis;
#define CAST_FEATURE_AXIS

/* The unit normal of the edge p0-p1 (local points) in that body's frame, signed so that turned
 * by q it points along the closest-point normal; false when the edge is degenerate or does not
 * face that normal (a cache of no edge). */
static bool EdgeAxis(cd2Vec p0, cd2Vec p1, cd2Rot q, cd2Vec normal, cd2Vec* axis)
{
	cd2Vec n = cd2Normalize(cd2RightPerp(cd2Sub(p1, p0)));
	cdReal facing = cd2Dot(cd2RotateVector(q, n), normal);
	if (cdAbs(facing) < CD_R(0.99))
	{
		return false;
	}
	*axis = facing > CD_R(0.0) ? n : cd2Neg(n);
	return true;
}

static FeatureAxis MakeFeatureAxis(const cd2Core* localA, const cd2Core* localB, const cd2SimplexCache* cache,
								   cd2Transform xfA, cd2Transform xfB, cd2Vec normal)
{
	FeatureAxis f;
	f.type = FEATURE_AXIS_FIXED;
	f.normal = normal;
	f.countA = f.countB = 1;
	f.indexA[0] = f.indexA[1] = f.indexB[0] = f.indexB[1] = 0;
	if (cache->count < 1 || cache->count > 2)
	{
		return f;
	}
	/* The distinct points of each core in the simplex (GJK's cache holds valid indices). */
	f.indexA[0] = cache->indexA[0];
	f.indexB[0] = cache->indexB[0];
	if (cache->count == 2)
	{
		if (cache->indexA[1] != cache->indexA[0])
		{
			f.indexA[f.countA++] = cache->indexA[1];
		}
		if (cache->indexB[1] != cache->indexB[0])
		{
			f.indexB[f.countB++] = cache->indexB[1];
		}
	}
	f.indexA[1] = f.indexA[f.countA - 1];
	f.indexB[1] = f.indexB[f.countB - 1];
	CD_ASSERT(f.indexA[0] < localA->count && f.indexA[1] < localA->count && f.indexB[0] < localB->count &&
			  f.indexB[1] < localB->count);
	cd2Vec axis;
	if (f.countA == 2 &&
		EdgeAxis(localA->points[f.indexA[0]], localA->points[f.indexA[1]], xfA.q, normal, &axis))
	{
		f.type = FEATURE_AXIS_EDGE_A;
		f.normal = axis;
	}
	else if (f.countB == 2 &&
			 EdgeAxis(localB->points[f.indexB[0]], localB->points[f.indexB[1]], xfB.q, normal, &axis))
	{
		f.type = FEATURE_AXIS_EDGE_B;
		f.normal = axis;
	}
	else if (f.countA == 1 && f.countB == 1)
	{
		f.type = FEATURE_AXIS_POINTS;
	}
	return f;
}

#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline cd2Vec
FeatureAxisAt(const FeatureAxis* f, const cd2Core* localA, const cd2Core* localB, cd2Transform xfA,
			  cd2Transform xfB)
{
	switch (f->type)
	{
		case FEATURE_AXIS_POINTS:
			return cd2Normalize(cd2Sub(cd2TransformPoint(xfB, localB->points[f->indexB[0]]),
									   cd2TransformPoint(xfA, localA->points[f->indexA[0]])));
		case FEATURE_AXIS_EDGE_A:
			return cd2RotateVector(xfA.q, f->normal);
		case FEATURE_AXIS_EDGE_B:
			return cd2RotateVector(xfB.q, f->normal);
		default:
			return f->normal;
	}
}

/* |p - segment p0-p1|^2 <= limit^2. */
static bool PointNearSegment(cd2Vec p, cd2Vec p0, cd2Vec p1, cdReal limitSquared)
{
	cd2Vec e = cd2Sub(p1, p0), d = cd2Sub(p, p0);
	cdReal along = cd2Dot(d, e), lengthSquared = cd2LengthSquared(e);
	if (along > CD_R(0.0))
	{
		d = along >= lengthSquared ? cd2Sub(p, p1) : cd2MulSub(d, along / lengthSquared, e);
	}
	return cd2LengthSquared(d) <= limitSquared;
}

static bool FeatureAxisWithin(const FeatureAxis* f, const cd2Core* localA, const cd2Core* localB,
							  cd2Transform xfA, cd2Transform xfB, cdReal limit)
{
	if (f->type == FEATURE_AXIS_FIXED)
	{
		return false;
	}
	cd2Vec a0 = cd2TransformPoint(xfA, localA->points[f->indexA[0]]);
	cd2Vec a1 = cd2TransformPoint(xfA, localA->points[f->indexA[1]]);
	cd2Vec b0 = cd2TransformPoint(xfB, localB->points[f->indexB[0]]);
	cd2Vec b1 = cd2TransformPoint(xfB, localB->points[f->indexB[1]]);
	/* Each feature is a point or a segment of its core: a point of one within limit of the
	 * other's segment is a pair of points of the cores within limit. */
	cdReal limitSquared = limit * limit;
	return PointNearSegment(b0, a0, a1, limitSquared) || PointNearSegment(a0, b0, b1, limitSquared) ||
		   (f->countB == 2 && PointNearSegment(b1, a0, a1, limitSquared)) ||
		   (f->countA == 2 && PointNearSegment(a1, b0, b1, limitSquared));
}

#include "cast.inc"
