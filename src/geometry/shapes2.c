/* collide: 2D shapes: type names, tagged-shape constructors, validators and bounds. */
#include "collide/geometry2.h"

#include "query/pairs2.h"

const char* cd2GetShapeTypeName(cd2ShapeType type)
{
	switch (type)
	{
#define CD2_TYPE_NAME_CASE(Name, PointIn, ClosestPointOn, Raycast, TypeName, ...)                            \
	case CD2_TYPE_##Name:                                                                                    \
		return TypeName;
		CD2_SHAPE_TABLE(CD2_TYPE_NAME_CASE)
#undef CD2_TYPE_NAME_CASE
		case CD2_SHAPE_TYPE_COUNT:
			break;
	}
	return "unknown";
}

cd2Shape cd2MakeCircleShape(cd2Circle circle)
{
	cd2Shape shape = {.type = CD2_SHAPE_CIRCLE, .circle = circle};
	return shape;
}

cd2Shape cd2MakeCapsuleShape(cd2Capsule capsule)
{
	cd2Shape shape = {.type = CD2_SHAPE_CAPSULE, .capsule = capsule};
	return shape;
}

cd2Shape cd2MakeAabbShape(cd2Aabb aabb)
{
	cd2Shape shape = {.type = CD2_SHAPE_AABB, .aabb = aabb};
	return shape;
}

cd2Shape cd2MakeBoxShape(cd2Box box)
{
	cd2Shape shape = {.type = CD2_SHAPE_BOX, .box = box};
	return shape;
}

cd2Shape cd2MakePolygonShape(const cd2Polygon* polygon)
{
	CD_ASSERT(polygon != NULL);
	cd2Shape shape = {.type = CD2_SHAPE_POLYGON, .polygon = *polygon};
	return shape;
}

cd2Shape cd2MakeSegmentShape(cd2Segment segment)
{
	cd2Shape shape = {.type = CD2_SHAPE_SEGMENT, .segment = segment};
	return shape;
}

/* ---- validators ------------------------------------------------------------------------------ */

static cdResult ValidateRadius(cdReal radius)
{
	if (!cdIsValidReal(radius))
	{
		return CD_ERROR_NOT_FINITE;
	}
	return radius < CD_R(0.0) ? CD_ERROR_NEGATIVE_SIZE : CD_OK;
}

static cdResult ValidateAabb(cd2Aabb aabb)
{
	if (!cd2IsValidVec(aabb.min) || !cd2IsValidVec(aabb.max))
	{
		return CD_ERROR_NOT_FINITE;
	}
	return aabb.min.x <= aabb.max.x && aabb.min.y <= aabb.max.y ? CD_OK : CD_ERROR_NEGATIVE_SIZE;
}

static cdResult ValidateCircle(cd2Circle circle)
{
	return cd2IsValidVec(circle.center) ? ValidateRadius(circle.radius) : CD_ERROR_NOT_FINITE;
}

static cdResult ValidateCapsule(cd2Capsule capsule)
{
	if (!cd2IsValidVec(capsule.p1) || !cd2IsValidVec(capsule.p2))
	{
		return CD_ERROR_NOT_FINITE;
	}
	return ValidateRadius(capsule.radius);
}

static cdResult ValidateSegment(cd2Segment segment)
{
	return cd2IsValidVec(segment.p1) && cd2IsValidVec(segment.p2) ? CD_OK : CD_ERROR_NOT_FINITE;
}

static cdResult ValidateBox(cd2Box box)
{
	if (!cd2IsValidVec(box.center) || !cd2IsValidVec(box.halfExtents) || !cdIsValidReal(box.rotation.c) ||
		!cdIsValidReal(box.rotation.s))
	{
		return CD_ERROR_NOT_FINITE;
	}
	if (box.halfExtents.x < CD_R(0.0) || box.halfExtents.y < CD_R(0.0))
	{
		return CD_ERROR_NEGATIVE_SIZE;
	}
	return cd2IsValidRot(box.rotation) ? CD_OK : CD_ERROR_NOT_NORMALIZED;
}

/* Unit length within the tolerance cd2IsValidRot uses for rotations. */
static bool IsUnitVec(cd2Vec v)
{
	double lengthSquared = (double)v.x * (double)v.x + (double)v.y * (double)v.y;
#if CD_DOUBLE
	return fabs(lengthSquared - 1.0) < 1e-9;
#else
	return fabs(lengthSquared - 1.0) < 1e-4;
#endif
}

/* Checks in double. Convexity allows a vertex to stand up to 64 * CD_REAL_EPSILON * (largest
 * |coordinate|) outside an edge's line (the round-off of storing the vertices), and no more than
 * 4 * CD_REAL_EPSILON of its offset from the edge's nearer end (so that cd2PointInPolygon, whose
 * tolerance is relative to that offset, finds every vertex inside: an absolute tolerance alone
 * lets a vertex near a sharp tip stand far out in relative terms). Each normal may deviate from
 * its edge's outward unit perpendicular by the unit-length tolerance. */
static cdResult ValidatePolygon(const cd2Polygon* polygon)
{
	if (polygon == NULL)
	{
		return CD_ERROR_INVALID_ARGUMENT;
	}
	int count = polygon->count;
	if (count > CD2_MAX_POLYGON_VERTICES)
	{
		return CD_ERROR_TOO_MANY_POINTS;
	}
	if (count < 3)
	{
		return CD_ERROR_DEGENERATE;
	}
	double maxAbs = 0.0;
	for (int i = 0; i < count; ++i)
	{
		if (!cd2IsValidVec(polygon->vertices[i]) || !cd2IsValidVec(polygon->normals[i]))
		{
			return CD_ERROR_NOT_FINITE;
		}
		maxAbs =
			fmax(maxAbs, fmax(fabs((double)polygon->vertices[i].x), fabs((double)polygon->vertices[i].y)));
	}
	if (!cd2IsValidVec(polygon->centroid))
	{
		return CD_ERROR_NOT_FINITE;
	}
	cdResult radiusResult = ValidateRadius(polygon->radius);
	if (radiusResult != CD_OK)
	{
		return radiusResult;
	}
	for (int i = 0; i < count; ++i)
	{
		if (!IsUnitVec(polygon->normals[i]))
		{
			return CD_ERROR_NOT_NORMALIZED;
		}
	}

	double tolerance = 64.0 * (double)CD_REAL_EPSILON * maxAbs;
#if CD_DOUBLE
	const double alignmentTolerance = 1e-9;
#else
	const double alignmentTolerance = 1e-4;
#endif
	double twiceArea = 0.0;
	for (int i = 0; i < count; ++i)
	{
		cd2Vec v1 = polygon->vertices[i];
		cd2Vec v2 = polygon->vertices[i + 1 < count ? i + 1 : 0];
		double ex = (double)v2.x - (double)v1.x, ey = (double)v2.y - (double)v1.y;
		double length = sqrt(ex * ex + ey * ey);
		if (!(length > 0.0) || !isfinite(length))
		{
			return CD_ERROR_DEGENERATE;
		}
		double nx = (double)polygon->normals[i].x, ny = (double)polygon->normals[i].y;
		if ((nx * ey - ny * ex) / length < 1.0 - alignmentTolerance)
		{
			return CD_ERROR_DEGENERATE;
		}
		for (int j = 0; j < count; ++j)
		{
			double dx = (double)polygon->vertices[j].x - (double)v1.x;
			double dy = (double)polygon->vertices[j].y - (double)v1.y;
			if (nx * dx + ny * dy > tolerance)
			{
				return CD_ERROR_DEGENERATE;
			}
			/* Every vertex must pass cd2PointInPolygon's test of this edge: measured from the edge's
			 * nearer end, within a tolerance relative to that offset (half of the query's, which
			 * leaves room for the query's own round-off). */
			double fx = (double)polygon->vertices[j].x - (double)v2.x;
			double fy = (double)polygon->vertices[j].y - (double)v2.y;
			double offset = fmax(fabs(dx), fabs(dy)), offsetFromEnd = fmax(fabs(fx), fabs(fy));
			if (offsetFromEnd < offset)
			{
				dx = fx;
				dy = fy;
				offset = offsetFromEnd;
			}
			if (nx * dx + ny * dy > 4.0 * (double)CD_REAL_EPSILON * offset)
			{
				return CD_ERROR_DEGENERATE;
			}
		}
		double cx = (double)polygon->centroid.x - (double)v1.x,
			   cy = (double)polygon->centroid.y - (double)v1.y;
		if (nx * cx + ny * cy > tolerance)
		{
			return CD_ERROR_DEGENERATE;
		}
		double ox = (double)v1.x - (double)polygon->vertices[0].x,
			   oy = (double)v1.y - (double)polygon->vertices[0].y;
		double px = (double)v2.x - (double)polygon->vertices[0].x,
			   py = (double)v2.y - (double)polygon->vertices[0].y;
		twiceArea += ox * py - oy * px;
	}
	return twiceArea > 0.0 ? CD_OK : CD_ERROR_DEGENERATE;
}

bool cd2IsValidAabb(cd2Aabb aabb)
{
	return ValidateAabb(aabb) == CD_OK;
}

bool cd2IsValidCircle(cd2Circle circle)
{
	return ValidateCircle(circle) == CD_OK;
}

bool cd2IsValidCapsule(cd2Capsule capsule)
{
	return ValidateCapsule(capsule) == CD_OK;
}

bool cd2IsValidSegment(cd2Segment segment)
{
	return ValidateSegment(segment) == CD_OK;
}

bool cd2IsValidBox(cd2Box box)
{
	return ValidateBox(box) == CD_OK;
}

bool cd2IsValidPolygon(const cd2Polygon* polygon)
{
	return ValidatePolygon(polygon) == CD_OK;
}

bool cd2IsValidRay(cd2Ray ray)
{
	return cd2IsValidVec(ray.origin) && cd2IsValidVec(ray.translation);
}

cdResult cd2ValidateShape(const cd2Shape* shape)
{
	if (shape == NULL)
	{
		return CD_ERROR_INVALID_ARGUMENT;
	}
	switch (shape->type)
	{
#define CD2_VALIDATE_CASE(Name, PointIn, ClosestPointOn, Raycast, TypeName, Validate, ...)                   \
	case CD2_TYPE_##Name:                                                                                    \
		return Validate(CD2_SHAPE_ARG(Name, shape));
		CD2_SHAPE_TABLE(CD2_VALIDATE_CASE)
#undef CD2_VALIDATE_CASE
		case CD2_SHAPE_TYPE_COUNT:
			break;
	}
	return CD_ERROR_INVALID_ARGUMENT;
}

bool cd2IsValidShape(const cd2Shape* shape)
{
	return cd2ValidateShape(shape) == CD_OK;
}

/* ---- bounds ---------------------------------------------------------------------------------- */

cd2Aabb cd2ComputeCircleAabb(cd2Circle circle)
{
	cd2Vec r = {circle.radius, circle.radius};
	cd2Aabb aabb = {cd2Sub(circle.center, r), cd2Add(circle.center, r)};
	return aabb;
}

cd2Aabb cd2ComputeCapsuleAabb(cd2Capsule capsule)
{
	cd2Vec r = {capsule.radius, capsule.radius};
	cd2Aabb aabb = {cd2Sub(cd2Min(capsule.p1, capsule.p2), r), cd2Add(cd2Max(capsule.p1, capsule.p2), r)};
	return aabb;
}

cd2Aabb cd2ComputeBoxAabb(cd2Box box)
{
	cdReal c = cdAbs(box.rotation.c), s = cdAbs(box.rotation.s);
	cd2Vec extent = {c * box.halfExtents.x + s * box.halfExtents.y,
					 s * box.halfExtents.x + c * box.halfExtents.y};
	cd2Aabb aabb = {cd2Sub(box.center, extent), cd2Add(box.center, extent)};
	return aabb;
}

cd2Aabb cd2ComputePolygonAabb(const cd2Polygon* polygon)
{
	CD_ASSERT(polygon != NULL && polygon->count > 0);
	cd2Aabb aabb = {polygon->vertices[0], polygon->vertices[0]};
	for (int i = 1; i < polygon->count; ++i)
	{
		aabb.min = cd2Min(aabb.min, polygon->vertices[i]);
		aabb.max = cd2Max(aabb.max, polygon->vertices[i]);
	}
	return cd2AabbInflate(aabb, polygon->radius);
}

cd2Aabb cd2ComputeSegmentAabb(cd2Segment segment)
{
	cd2Aabb aabb = {cd2Min(segment.p1, segment.p2), cd2Max(segment.p1, segment.p2)};
	return aabb;
}

/* An AABB shape is its own bounds (the shape table's ComputeAabb for Aabb). */
static cd2Aabb AabbOfAabb(cd2Aabb aabb)
{
	return aabb;
}

cd2Aabb cd2ComputeShapeAabb(const cd2Shape* shape)
{
	CD_ASSERT(shape != NULL);
	switch (shape->type)
	{
#define CD2_AABB_CASE(Name, PointIn, ClosestPointOn, Raycast, TypeName, Validate, ComputeAabb, ...)          \
	case CD2_TYPE_##Name:                                                                                    \
		return ComputeAabb(CD2_SHAPE_ARG(Name, shape));
		CD2_SHAPE_TABLE(CD2_AABB_CASE)
#undef CD2_AABB_CASE
		case CD2_SHAPE_TYPE_COUNT:
			break;
	}
	CD_ASSERT(false);
	cd2Aabb empty = {CD2_VEC_ZERO, CD2_VEC_ZERO};
	return empty;
}
