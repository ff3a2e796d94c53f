/* collide: 3D shapes: type names, tagged-shape makers, validators and bounds. */
#include "collide/geometry3.h"

#include "query/pairs3.h"

const char* cd3GetShapeTypeName(cd3ShapeType type)
{
	switch (type)
	{
#define CD3_TYPE_NAME_CASE(Name, PointIn, ClosestPointOn, Raycast, TypeName, ...)                            \
	case CD3_TYPE_##Name:                                                                                    \
		return TypeName;
		CD3_SHAPE_TABLE(CD3_TYPE_NAME_CASE)
#undef CD3_TYPE_NAME_CASE
		case CD3_SHAPE_TYPE_COUNT:
			break;
	}
	return "unknown";
}

cd3Shape cd3MakeSphereShape(cd3Sphere sphere)
{
	cd3Shape shape;
	shape.type = CD3_SHAPE_SPHERE;
	shape.sphere = sphere;
	return shape;
}

cd3Shape cd3MakeCapsuleShape(cd3Capsule capsule)
{
	cd3Shape shape;
	shape.type = CD3_SHAPE_CAPSULE;
	shape.capsule = capsule;
	return shape;
}

cd3Shape cd3MakeAabbShape(cd3Aabb aabb)
{
	cd3Shape shape;
	shape.type = CD3_SHAPE_AABB;
	shape.aabb = aabb;
	return shape;
}

cd3Shape cd3MakeBoxShape(cd3Box box)
{
	cd3Shape shape;
	shape.type = CD3_SHAPE_BOX;
	shape.box = box;
	return shape;
}

cd3Shape cd3MakeTriangleShape(cd3Triangle triangle)
{
	cd3Shape shape;
	shape.type = CD3_SHAPE_TRIANGLE;
	shape.triangle = triangle;
	return shape;
}

cd3Shape cd3MakePlaneShape(cd3Plane plane)
{
	cd3Shape shape;
	shape.type = CD3_SHAPE_PLANE;
	shape.plane = plane;
	return shape;
}

cd3Shape cd3MakeHullShape(const cd3Hull* hull, cd3Transform transform)
{
	cd3Shape shape;
	shape.type = CD3_SHAPE_HULL;
	shape.hull.hull = hull;
	shape.hull.transform = transform;
	return shape;
}

cd3Shape cd3MakeSegmentShape(cd3Segment segment)
{
	cd3Shape shape;
	shape.type = CD3_SHAPE_SEGMENT;
	shape.segment = segment;
	return shape;
}

/* ---- validators ---------------------------------------------------------------------------- */

/* The same unit-length tolerance as cd3IsValidQuat, applied to a squared length. */
static bool IsUnitLengthSquared(cdReal lengthSquared)
{
#if CD_DOUBLE
	return cdAbs(lengthSquared - 1.0) < 1e-9;
#else
	return cdAbs(lengthSquared - 1.0f) < 1e-4f;
#endif
}

static bool IsQuatFinite(cd3Quat q)
{
	return cdIsValidReal(q.x) && cdIsValidReal(q.y) && cdIsValidReal(q.z) && cdIsValidReal(q.w);
}

static cdReal MaxAbsComponent(cd3Vec v)
{
	return cdMax(cdAbs(v.x), cdMax(cdAbs(v.y), cdAbs(v.z)));
}

/* Zero area, judged on edges scaled to unit size so that neither huge nor tiny triangles overflow
 * or underflow: degenerate when the sine of the angle at `a` is within a few epsilon of zero. */
static bool IsTriangleDegenerate(cd3Triangle t)
{
	cd3Vec ab = cd3Sub(t.b, t.a);
	cd3Vec ac = cd3Sub(t.c, t.a);
	cdReal scale = cdMax(MaxAbsComponent(ab), MaxAbsComponent(ac));
	if (!(scale > CD_R(0.0)) || !cdIsValidReal(scale))
	{
		return true;
	}
	cdReal inverse = CD_R(1.0) / scale;
	ab = cd3Scale(inverse, ab);
	ac = cd3Scale(inverse, ac);
	cdReal crossSquared = cd3LengthSquared(cd3Cross(ab, ac));
	cdReal limit = CD_R(4.0) * CD_REAL_EPSILON;
	return crossSquared <= limit * limit * cd3LengthSquared(ab) * cd3LengthSquared(ac);
}

static cdResult ValidateAabb(cd3Aabb aabb)
{
	if (!cd3IsValidVec(aabb.min) || !cd3IsValidVec(aabb.max))
	{
		return CD_ERROR_NOT_FINITE;
	}
	if (aabb.min.x > aabb.max.x || aabb.min.y > aabb.max.y || aabb.min.z > aabb.max.z)
	{
		return CD_ERROR_NEGATIVE_SIZE;
	}
	return CD_OK;
}

static cdResult ValidateSphere(cd3Sphere sphere)
{
	if (!cd3IsValidVec(sphere.center) || !cdIsValidReal(sphere.radius))
	{
		return CD_ERROR_NOT_FINITE;
	}
	return sphere.radius < CD_R(0.0) ? CD_ERROR_NEGATIVE_SIZE : CD_OK;
}

static cdResult ValidateCapsule(cd3Capsule capsule)
{
	if (!cd3IsValidVec(capsule.p1) || !cd3IsValidVec(capsule.p2) || !cdIsValidReal(capsule.radius))
	{
		return CD_ERROR_NOT_FINITE;
	}
	return capsule.radius < CD_R(0.0) ? CD_ERROR_NEGATIVE_SIZE : CD_OK;
}

static cdResult ValidateSegment(cd3Segment segment)
{
	return cd3IsValidVec(segment.p1) && cd3IsValidVec(segment.p2) ? CD_OK : CD_ERROR_NOT_FINITE;
}

static cdResult ValidateTriangle(cd3Triangle triangle)
{
	if (!cd3IsValidVec(triangle.a) || !cd3IsValidVec(triangle.b) || !cd3IsValidVec(triangle.c))
	{
		return CD_ERROR_NOT_FINITE;
	}
	return IsTriangleDegenerate(triangle) ? CD_ERROR_DEGENERATE : CD_OK;
}

static cdResult ValidatePlane(cd3Plane plane)
{
	if (!cd3IsValidVec(plane.normal) || !cdIsValidReal(plane.offset))
	{
		return CD_ERROR_NOT_FINITE;
	}
	return IsUnitLengthSquared(cd3LengthSquared(plane.normal)) ? CD_OK : CD_ERROR_NOT_NORMALIZED;
}

static cdResult ValidateBox(cd3Box box)
{
	if (!cd3IsValidVec(box.center) || !cd3IsValidVec(box.halfExtents) || !IsQuatFinite(box.rotation))
	{
		return CD_ERROR_NOT_FINITE;
	}
	if (box.halfExtents.x < CD_R(0.0) || box.halfExtents.y < CD_R(0.0) || box.halfExtents.z < CD_R(0.0))
	{
		return CD_ERROR_NEGATIVE_SIZE;
	}
	if (!cd3IsValidQuat(box.rotation))
	{
		return CD_ERROR_NOT_NORMALIZED;
	}
	/* The supported range (geometry3.h): largest half extent over the smallest non-zero one. */
	cd3Vec h = box.halfExtents;
	cdReal largest = cdMax(h.x, cdMax(h.y, h.z));
	cdReal thinnest = largest;
	thinnest = h.x > CD_R(0.0) ? cdMin(thinnest, h.x) : thinnest;
	thinnest = h.y > CD_R(0.0) ? cdMin(thinnest, h.y) : thinnest;
	thinnest = h.z > CD_R(0.0) ? cdMin(thinnest, h.z) : thinnest;
	if ((double)largest > CD3_MAX_ASPECT_RATIO * (double)thinnest)
	{
		return CD_ERROR_OUT_OF_RANGE;
	}
	return CD_OK;
}

bool cd3IsValidAabb(cd3Aabb aabb)
{
	return ValidateAabb(aabb) == CD_OK;
}

bool cd3IsValidSphere(cd3Sphere sphere)
{
	return ValidateSphere(sphere) == CD_OK;
}

bool cd3IsValidCapsule(cd3Capsule capsule)
{
	return ValidateCapsule(capsule) == CD_OK;
}

bool cd3IsValidSegment(cd3Segment segment)
{
	return ValidateSegment(segment) == CD_OK;
}

bool cd3IsValidTriangle(cd3Triangle triangle)
{
	return ValidateTriangle(triangle) == CD_OK;
}

bool cd3IsValidPlane(cd3Plane plane)
{
	return ValidatePlane(plane) == CD_OK;
}

bool cd3IsValidBox(cd3Box box)
{
	return ValidateBox(box) == CD_OK;
}

bool cd3IsValidRay(cd3Ray ray)
{
	return cd3IsValidVec(ray.origin) && cd3IsValidVec(ray.translation);
}

static cdResult ValidateHullShape(cd3HullShape hull)
{
	if (hull.hull == NULL)
	{
		return CD_ERROR_INVALID_ARGUMENT;
	}
	if (!cd3IsValidVec(hull.transform.p))
	{
		return CD_ERROR_NOT_FINITE;
	}
	cd3Quat q = hull.transform.q;
	if (!cdIsValidReal(q.x) || !cdIsValidReal(q.y) || !cdIsValidReal(q.z) || !cdIsValidReal(q.w))
	{
		return CD_ERROR_NOT_FINITE;
	}
	if (!cd3IsValidQuat(q))
	{
		return CD_ERROR_NOT_NORMALIZED;
	}
	return cd3ValidateHull(hull.hull);
}

bool cd3IsValidHullShape(cd3HullShape hull)
{
	return ValidateHullShape(hull) == CD_OK;
}

cdResult cd3ValidateShape(const cd3Shape* shape)
{
	if (shape == NULL)
	{
		return CD_ERROR_INVALID_ARGUMENT;
	}
	switch (shape->type)
	{
#define CD3_VALIDATE_CASE(Name, PointIn, ClosestPointOn, Raycast, TypeName, Validate, ...)                   \
	case CD3_TYPE_##Name:                                                                                    \
		return Validate(CD3_SHAPE_ARG(Name, shape));
		CD3_SHAPE_TABLE(CD3_VALIDATE_CASE)
#undef CD3_VALIDATE_CASE
		case CD3_SHAPE_TYPE_COUNT:
			break;
	}
	return CD_ERROR_INVALID_ARGUMENT;
}

bool cd3IsValidShape(const cd3Shape* shape)
{
	return cd3ValidateShape(shape) == CD_OK;
}

/* ---- bounds -------------------------------------------------------------------------------- */

cd3Aabb cd3ComputeSphereAabb(cd3Sphere sphere)
{
	cd3Vec r = {sphere.radius, sphere.radius, sphere.radius};
	cd3Aabb aabb = {cd3Sub(sphere.center, r), cd3Add(sphere.center, r)};
	return aabb;
}

cd3Aabb cd3ComputeCapsuleAabb(cd3Capsule capsule)
{
	cd3Vec r = {capsule.radius, capsule.radius, capsule.radius};
	cd3Aabb aabb = {cd3Sub(cd3Min(capsule.p1, capsule.p2), r), cd3Add(cd3Max(capsule.p1, capsule.p2), r)};
	return aabb;
}

/* The extent along each world axis is the absolute rotation matrix times the half extents. The
 * quaternion is renormalized so that the validator's unit-length tolerance cannot shrink the box. */
cd3Aabb cd3ComputeBoxAabb(cd3Box box)
{
	cd3Mat33 m = cd3MakeMatFromQuat(cd3NormalizeQuat(box.rotation));
	cd3Vec h = box.halfExtents;
	cd3Vec extent =
		cd3Add(cd3Add(cd3Scale(h.x, cd3Abs(m.cx)), cd3Scale(h.y, cd3Abs(m.cy))), cd3Scale(h.z, cd3Abs(m.cz)));
	cd3Aabb aabb = {cd3Sub(box.center, extent), cd3Add(box.center, extent)};
	return aabb;
}

cd3Aabb cd3ComputeTriangleAabb(cd3Triangle triangle)
{
	cd3Aabb aabb = {cd3Min(triangle.a, cd3Min(triangle.b, triangle.c)),
					cd3Max(triangle.a, cd3Max(triangle.b, triangle.c))};
	return aabb;
}

cd3Aabb cd3ComputeSegmentAabb(cd3Segment segment)
{
	cd3Aabb aabb = {cd3Min(segment.p1, segment.p2), cd3Max(segment.p1, segment.p2)};
	return aabb;
}

cd3Aabb cd3ComputePlaneAabb(cd3Plane plane)
{
	cd3Aabb aabb = {{-CD_REAL_MAX, -CD_REAL_MAX, -CD_REAL_MAX}, {CD_REAL_MAX, CD_REAL_MAX, CD_REAL_MAX}};
	cd3Vec n = plane.normal;
	int axis = -1;
	if (n.y == CD_R(0.0) && n.z == CD_R(0.0) && n.x != CD_R(0.0))
	{
		axis = 0;
	}
	else if (n.x == CD_R(0.0) && n.z == CD_R(0.0) && n.y != CD_R(0.0))
	{
		axis = 1;
	}
	else if (n.x == CD_R(0.0) && n.y == CD_R(0.0) && n.z != CD_R(0.0))
	{
		axis = 2;
	}
	if (axis < 0)
	{
		return aabb;
	}
	cdReal component = cd3GetComponent(n, axis);
	cdReal bound = cdClamp(plane.offset / component, -CD_REAL_MAX, CD_REAL_MAX);
	cdReal* target;
	if (component > CD_R(0.0))
	{
		target = axis == 0 ? &aabb.max.x : (axis == 1 ? &aabb.max.y : &aabb.max.z);
	}
	else
	{
		target = axis == 0 ? &aabb.min.x : (axis == 1 ? &aabb.min.y : &aabb.min.z);
	}
	*target = bound;
	return aabb;
}

/* Every vertex moved into place: exact, and cheap next to any query on the hull. */
cd3Aabb cd3ComputeHullShapeAabb(cd3HullShape hull)
{
	CD_ASSERT(hull.hull != NULL);
	cd3Mat33 m = cd3MakeMatFromQuat(hull.transform.q);
	cd3Vec first = cd3Add(cd3MulMV(m, hull.hull->vertices[0]), hull.transform.p);
	cd3Aabb aabb = {first, first};
	for (int i = 1; i < hull.hull->vertexCount; ++i)
	{
		cd3Vec p = cd3Add(cd3MulMV(m, hull.hull->vertices[i]), hull.transform.p);
		aabb.min = cd3Min(aabb.min, p);
		aabb.max = cd3Max(aabb.max, p);
	}
	return aabb;
}

/* An AABB shape is its own bounds (the shape table's ComputeAabb for Aabb). */
static cd3Aabb AabbOfAabb(cd3Aabb aabb)
{
	return aabb;
}

cd3Aabb cd3ComputeShapeAabb(const cd3Shape* shape)
{
	CD_ASSERT(shape != NULL);
	switch (shape->type)
	{
#define CD3_AABB_CASE(Name, PointIn, ClosestPointOn, Raycast, TypeName, Validate, ComputeAabb, ...)          \
	case CD3_TYPE_##Name:                                                                                    \
		return ComputeAabb(CD3_SHAPE_ARG(Name, shape));
		CD3_SHAPE_TABLE(CD3_AABB_CASE)
#undef CD3_AABB_CASE
		case CD3_SHAPE_TYPE_COUNT:
			break;
	}
	CD_ASSERT(false);
	cd3Aabb empty = {CD3_VEC_ZERO, CD3_VEC_ZERO};
	return empty;
}
