/* 3D shape cast and time of impact: the shape moves of cast.inc. */
#include "collide/cast.h"

#include "sat3.h"
#include "support3.h"

#include <string.h>

/* The dimension of cast.inc (base/dim.h: CD_DIM_NAME, CD_VEC, CD_SHAPE, CD_SWEEP,
 * CD_TRANSFORM) and the most contact axes a pair of shapes can have. */
#define CD_DIM 3
#include "base/dim.h"
#define CAST_MAX_AXES 8

/* Half-spaces have no core: their casts take the advancement. */
static bool MakeCastCore(const cd3Shape* shape, cd3Core* core)
{
	return cd3MakeCore(shape, core);
}

static cd3Vec CastCorePoint(const cd3Core* core, int i)
{
	return cd3CorePoint(core, i);
}

static cd3Vec CastCoreCenter(const cd3Core* core)
{
	return cd3CoreCenter(core);
}

static int CastCoreSupport(const cd3Core* core, cd3Vec direction, int start)
{
	(void)start;
	return cd3CoreSupport(core, direction);
}

/* |a x b|^2: by Lagrange's identity |a|^2 |b|^2 - (a.b)^2 without its cancellation. */
static cdReal CrossLengthSquared(cd3Vec a, cd3Vec b)
{
	return cd3LengthSquared(cd3Cross(a, b));
}

static cdReal MaxAbs(cd3Vec v)
{
	return cdMax(cdAbs(v.x), cdMax(cdAbs(v.y), cdAbs(v.z)));
}

static cdReal StripRadius(cd3Shape* shape)
{
	cdReal radius = CD_R(0.0);
	switch (shape->type)
	{
#define STRIP_RADIUS(Name, Radius)                                                                           \
	case CD3_TYPE_##Name:                                                                                    \
		radius = Radius(shape);                                                                              \
		Radius(shape) = CD_R(0.0);                                                                           \
		break;
#define STRIP_RADIUS_CASE(Name, PointIn, ClosestPointOn, Raycast, TypeName, Validate, ComputeAabb,           \
						  ComputeMass, MakeCore, Radius)                                                     \
	CD_SHAPE_HAS(Radius, STRIP_RADIUS)(Name, Radius)
		CD3_SHAPE_TABLE(STRIP_RADIUS_CASE)
#undef STRIP_RADIUS_CASE
#undef STRIP_RADIUS
		default:
			break;
	}
	return radius;
}

static cd3Shape TranslateShape(const cd3Shape* shape, cd3Vec d)
{
	cd3Shape s = *shape;
	switch (shape->type)
	{
		case CD3_SHAPE_SPHERE:
			s.sphere.center = cd3Add(s.sphere.center, d);
			break;
		case CD3_SHAPE_CAPSULE:
			s.capsule.p1 = cd3Add(s.capsule.p1, d);
			s.capsule.p2 = cd3Add(s.capsule.p2, d);
			break;
		case CD3_SHAPE_AABB:
			s.aabb.min = cd3Add(s.aabb.min, d);
			s.aabb.max = cd3Add(s.aabb.max, d);
			break;
		case CD3_SHAPE_BOX:
			s.box.center = cd3Add(s.box.center, d);
			break;
		case CD3_SHAPE_TRIANGLE:
			s.triangle.a = cd3Add(s.triangle.a, d);
			s.triangle.b = cd3Add(s.triangle.b, d);
			s.triangle.c = cd3Add(s.triangle.c, d);
			break;
		case CD3_SHAPE_PLANE:
			s.plane.offset += cd3Dot(s.plane.normal, d);
			break;
		case CD3_SHAPE_SEGMENT:
			s.segment.p1 = cd3Add(s.segment.p1, d);
			s.segment.p2 = cd3Add(s.segment.p2, d);
			break;
		case CD3_SHAPE_HULL:
			s.hull.transform.p = cd3Add(s.hull.transform.p, d);
			break;
		default:
			break;
	}
	return s;
}

/* A turned AABB is a box. */
static cd3Shape PlaceShape(const cd3Shape* shape, cd3Transform xf)
{
	cd3Shape s = *shape;
	switch (shape->type)
	{
		case CD3_SHAPE_SPHERE:
			s.sphere.center = cd3TransformPoint(xf, s.sphere.center);
			break;
		case CD3_SHAPE_CAPSULE:
			s.capsule.p1 = cd3TransformPoint(xf, s.capsule.p1);
			s.capsule.p2 = cd3TransformPoint(xf, s.capsule.p2);
			break;
		case CD3_SHAPE_AABB:
		{
			cd3Box box = {cd3TransformPoint(xf, cd3AabbCenter(shape->aabb)), cd3AabbHalfExtents(shape->aabb),
						  xf.q};
			s = cd3MakeBoxShape(box);
			break;
		}
		case CD3_SHAPE_BOX:
			s.box.center = cd3TransformPoint(xf, s.box.center);
			s.box.rotation = cd3NormalizeQuat(cd3MulQuat(xf.q, s.box.rotation));
			break;
		case CD3_SHAPE_TRIANGLE:
			s.triangle.a = cd3TransformPoint(xf, s.triangle.a);
			s.triangle.b = cd3TransformPoint(xf, s.triangle.b);
			s.triangle.c = cd3TransformPoint(xf, s.triangle.c);
			break;
		case CD3_SHAPE_PLANE:
			s.plane.normal = cd3RotateVector(xf.q, s.plane.normal);
			s.plane.offset += cd3Dot(s.plane.normal, xf.p);
			break;
		case CD3_SHAPE_SEGMENT:
			s.segment.p1 = cd3TransformPoint(xf, s.segment.p1);
			s.segment.p2 = cd3TransformPoint(xf, s.segment.p2);
			break;
		case CD3_SHAPE_HULL:
			s.hull.transform = cd3MulTransforms(xf, s.hull.transform);
			s.hull.transform.q = cd3NormalizeQuat(s.hull.transform.q);
			break;
		default:
			break;
	}
	return s;
}

static bool ShapeExtent(const cd3Shape* shape, cd3Vec center, cdReal* extent)
{
	*extent = CD_R(0.0);
	if (shape->type == CD3_SHAPE_PLANE)
	{
		return false;
	}
	cd3Core core;
	if (!cd3MakeCore(shape, &core))
	{
		return true; /* unknown type: cd3Distance asserts on it */
	}
	cdReal farthestSquared = CD_R(0.0);
	for (int i = 0; i < core.count; ++i)
	{
		farthestSquared = cdMax(farthestSquared, cd3VecDistanceSquared(cd3CorePoint(&core, i), center));
	}
	*extent = cdSqrt(farthestSquared) + core.radius;
	return true;
}

/* The rotation q(t) = rotation0 * exp(t * angle * axis / 2): constant angular speed `angle`. */
/* A body-frame core moved into the world (radius dropped: the casts grow by the radii). A hull's
 * vertices stay in its frame: only its rotation and translation change. */
typedef struct PlacedCore
{
	cd3Core core;
} PlacedCore;
#define PLACED_CORE PlacedCore

static void PlaceCore(const cd3Core* local, cd3Transform xf, PlacedCore* placed)
{
	cd3Core* core = &placed->core;
	core->count = local->count;
	core->radius = CD_R(0.0);
	core->localPoints = local->localPoints;
	core->localColumns = local->localColumns;
	core->box = local->box;
	core->lazyBox = local->lazyBox || local->orientedBox;
	core->orientedBox = false;
	if (local->box)
	{
		for (int k = 0; k < 3; ++k)
		{
			core->axes[k] = cd3RotateVector(xf.q, local->axes[k]);
		}
	}
	if (core->lazyBox)
	{
		core->center = cd3TransformPoint(xf, local->center);
		return;
	}
	if (local->localPoints != NULL)
	{
		cd3Mat33 rotation = cd3MakeMatFromQuat(xf.q);
		core->rotation = cd3MulMM(rotation, local->rotation);
		core->translation = cd3TransformPoint(xf, local->translation);
		return;
	}
	for (int i = 0; i < local->count; ++i)
	{
		core->points[i] = cd3TransformPoint(xf, local->points[i]);
	}
}

typedef struct SweepMotion
{
	cd3Vec localCenter, center0, velocity;
	cd3Quat rotation0;
	cd3Vec axis; /* in the body frame */
	cdReal angle, angularSpeed;
} SweepMotion;

static SweepMotion MakeMotion(const cd3Sweep* sweep)
{
	SweepMotion m;
	m.localCenter = sweep->localCenter;
	m.center0 = sweep->center0;
	m.velocity = cd3Sub(sweep->center1, sweep->center0);
	m.rotation0 = sweep->rotation0;
	cd3Quat relative = cd3InvMulQuat(sweep->rotation0, sweep->rotation1);
	if (relative.w < CD_R(0.0)) /* the shorter arc */
	{
		relative = cd3MakeQuat(-relative.x, -relative.y, -relative.z, -relative.w);
	}
	cd3Vec v = cd3MakeVec(relative.x, relative.y, relative.z);
	cdReal sine;
	m.axis = cd3GetLengthAndNormalize(&sine, v);
#if CD_DOUBLE
	m.angle = 2.0 * atan2(sine, relative.w);
#else
	m.angle = 2.0f * atan2f(sine, relative.w);
#endif
	if (cd3LengthSquared(m.axis) == CD_R(0.0))
	{
		m.angle = CD_R(0.0);
	}
	m.angularSpeed = m.angle;
	return m;
}

static cd3Transform MotionTransform(const SweepMotion* m, cdReal t)
{
	cd3Transform xf;
	if (m->angle > CD_R(0.0))
	{
		cdReal half = CD_R(0.5) * t * m->angle;
#if CD_DOUBLE
		cdReal s = sin(half), c = cos(half);
#else
		cdReal s = sinf(half), c = cosf(half);
#endif
		cd3Quat step = cd3MakeQuat(s * m->axis.x, s * m->axis.y, s * m->axis.z, c);
		xf.q = cd3NormalizeQuat(cd3MulQuat(m->rotation0, step));
	}
	else
	{
		xf.q = m->rotation0;
	}
	xf.p = cd3Sub(cd3MulAdd(m->center0, t, m->velocity), cd3RotateVector(xf.q, m->localCenter));
	return xf;
}

cd3Transform cd3GetSweepTransform(const cd3Sweep* sweep, cdReal t)
{
	SweepMotion m = MakeMotion(sweep);
	return MotionTransform(&m, t);
}

/* The shape as a polytope (boxes, AABBs, hulls, triangles). */
static bool MakePolytope(const cd3Shape* s, cd3Polytope* p)
{
	switch (s->type)
	{
		case CD3_SHAPE_BOX:
			cd3InitBoxPolytope(p, s->box);
			return true;
		case CD3_SHAPE_AABB:
		{
			cd3Box box = {cd3AabbCenter(s->aabb), cd3AabbHalfExtents(s->aabb), CD3_QUAT_IDENTITY};
			cd3InitBoxPolytope(p, box);
			return true;
		}
		case CD3_SHAPE_HULL:
			cd3InitHullPolytope(p, s->hull);
			return true;
		case CD3_SHAPE_TRIANGLE:
			cd3InitTrianglePolytope(p, s->triangle);
			return true;
		default:
			return false;
	}
}

/* The shape as a segment core (spheres: a point). */
static bool CoreSegment(const cd3Shape* s, cd3Vec* p1, cd3Vec* p2)
{
	switch (s->type)
	{
		case CD3_SHAPE_SPHERE:
			*p1 = *p2 = s->sphere.center;
			return true;
		case CD3_SHAPE_CAPSULE:
			*p1 = s->capsule.p1;
			*p2 = s->capsule.p2;
			return true;
		case CD3_SHAPE_SEGMENT:
			*p1 = s->segment.p1;
			*p2 = s->segment.p2;
			return true;
		default:
			return false;
	}
}

static int AppendAxis(cd3Vec* axes, int count, cd3Vec axis)
{
	cdReal length = cd3Length(axis);
	if (length > CD_R(0.0) && count < CAST_MAX_AXES)
	{
		axes[count++] = cd3Scale(CD_R(1.0) / length, axis);
	}
	return count;
}

/* The separating axis test's best axes of the features (see cast.inc): the best face of each
 * polytope and the best edge pair, the best face or edge cross of a polytope against a segment
 * core, the cross product of two segment cores. */
static int ContactAxes(const cd3Shape* a, const cd3Shape* b, cd3Vec* axes, int count)
{
	cd3Polytope pa, pb;
	bool polytopeA = MakePolytope(a, &pa), polytopeB = MakePolytope(b, &pb);
	cd3Vec a1, a2, b1, b2;
	if (polytopeA && polytopeB)
	{
		cd3SatResult sat;
		bool boxes = (a->type == CD3_SHAPE_BOX || a->type == CD3_SHAPE_AABB) &&
					 (b->type == CD3_SHAPE_BOX || b->type == CD3_SHAPE_AABB);
		if (boxes)
		{
			/* The fifteen axes in closed form (face indices those of the box polytopes). */
			cd3Mat33 rotation;
			cd3Vec translation;
			cd3Box boxA = {pa.transform.p, pa.vertexStorage[7], pa.transform.q};
			cd3Box boxB = {pb.transform.p, pb.vertexStorage[7], pb.transform.q};
			sat = cd3SatBoxes(boxA, boxB, &rotation, &translation);
		}
		else
		{
			sat = cd3SatPolytopes(&pa, &pb);
		}
		if (sat.faceA >= 0)
		{
			count = AppendAxis(axes, count, cd3RotateVector(pa.transform.q, pa.planes[sat.faceA].normal));
		}
		if (sat.faceB >= 0)
		{
			count =
				AppendAxis(axes, count, cd3Neg(cd3RotateVector(pb.transform.q, pb.planes[sat.faceB].normal)));
		}
		if (sat.edgeA >= 0)
		{
			count = AppendAxis(axes, count, sat.edgeNormal);
		}
	}
	else if (polytopeB && CoreSegment(a, &a1, &a2))
	{
		cd3SatResult sat;
		cd3SatFeature feature = cd3SatSegmentPolytope(a1, a2, &pb, &sat);
		if (feature == CD3_SAT_EDGES && sat.edgeB >= 0)
		{
			count = AppendAxis(axes, count, sat.edgeNormal);
		}
		if (sat.faceB >= 0)
		{
			count =
				AppendAxis(axes, count, cd3Neg(cd3RotateVector(pb.transform.q, pb.planes[sat.faceB].normal)));
		}
	}
	else if (polytopeA && CoreSegment(b, &b1, &b2))
	{
		cd3SatResult sat;
		cd3SatFeature feature = cd3SatSegmentPolytope(b1, b2, &pa, &sat);
		if (feature == CD3_SAT_EDGES && sat.edgeB >= 0)
		{
			count = AppendAxis(axes, count, cd3Neg(sat.edgeNormal));
		}
		if (sat.faceB >= 0)
		{
			count = AppendAxis(axes, count, cd3RotateVector(pa.transform.q, pa.planes[sat.faceB].normal));
		}
	}
	else if (CoreSegment(a, &a1, &a2) && CoreSegment(b, &b1, &b2))
	{
		cd3Vec cross = cd3Cross(cd3Sub(a2, a1), cd3Sub(b2, b1));
		count = AppendAxis(axes, count, cross);
		count = AppendAxis(axes, count, cd3Neg(cross));
	}
	return count;
}

#include "cast.inc"
