/* collide: 2D ray casts against the primitive shapes, and the dispatcher on tagged shapes.
 *
 * Same conventions as the 3D casts (see raycast3.c and query3.h): fraction in [0, 1], point =
 * origin + fraction * translation, outward unit normal; an origin inside a solid shape (boundary
 * included) hits at fraction 0 with normal -normalize(translation), the zero vector for a zero
 * translation; zero-length rays never hit the non-solid segment; *hit is untouched on a miss. */
#include "collide/query2.h"

#define CD_DIM 2
#include "query/raycast_common.h"
#include "query/pairs2.h"

/* Unit direction and length of the translation; false for a zero (or non-finite) length. */
static bool cd2GetRayDirection(cd2Vec translation, cd2Vec* direction, cdReal* length)
{
	cdReal l = cd2Length(translation);
	if (!(l > CD_R(0.0)) || !cdIsValidReal(l))
	{
		return false;
	}
	*length = l;
	*direction = cd2Scale(CD_R(1.0) / l, translation);
	return true;
}

static bool cd2HitFromInside(cd2Ray ray, cd2RayHit* hit)
{
	hit->fraction = CD_R(0.0);
	hit->point = ray.origin;
	hit->normal = cd2Neg(cd2Normalize(ray.translation));
	return true;
}

static bool cd2HitAtFraction(cd2Ray ray, cdReal fraction, cd2Vec normal, cd2RayHit* hit)
{
	fraction = cdClamp(fraction, CD_R(0.0), CD_R(1.0));
	hit->fraction = fraction;
	hit->point = cd2MulAdd(ray.origin, fraction, ray.translation);
	hit->normal = normal;
	return true;
}

/* Entry into a disk whose center is `offset` = origin - center away from the ray origin, for an
 * origin outside it; the normal falls back to -direction through the center of a zero radius. */
static bool cd2RayEntryIntoCircle(cd2Vec offset, cdReal radius, cd2Vec direction, cdReal length,
								  cdReal* distance, cd2Vec* normal)
{
	cdReal outside = cd2Dot(offset, offset) - radius * radius;
	cdReal lineOffset = cd2Cross(direction, offset);
	cdReal halfChord;
	if (!cdRayEntryIntoBall(cd2Dot(offset, direction), outside, radius * radius, lineOffset * lineOffset,
							length, distance, &halfChord))
	{
		return false;
	}
	/* The center's foot on the line, moved back by the half chord (see the 3D sphere). */
	cd2Vec foot = cd2Scale(lineOffset, cd2LeftPerp(direction));
	*normal = cd2Normalize(cd2MulSub(foot, halfChord, direction));
	if (cd2LengthSquared(*normal) == CD_R(0.0))
	{
		*normal = cd2Neg(direction);
	}
	return true;
}

bool cd2RaycastCircle(cd2Circle c, cd2Ray ray, cd2RayHit* hit)
{
	cd2Vec offset = cd2Sub(ray.origin, c.center);
	if (cd2Dot(offset, offset) <= c.radius * c.radius)
	{
		return cd2HitFromInside(ray, hit);
	}
	cd2Vec direction, normal;
	cdReal length, distance;
	if (!cd2GetRayDirection(ray.translation, &direction, &length) ||
		!cd2RayEntryIntoCircle(offset, c.radius, direction, length, &distance, &normal))
	{
		return false;
	}
	return cd2HitAtFraction(ray, distance / length, normal, hit);
}

/* A stadium is the union of its two end disks and the rectangle between them (see the 3D capsule):
 * the first entry is the earliest of the entry into the infinite band around the axis, when it
 * lies between the ends, and the entries into the two disks. */
bool cd2RaycastCapsule(cd2Capsule c, cd2Ray ray, cd2RayHit* hit)
{
	cd2Vec axis = cd2Sub(c.p2, c.p1);
	cd2Vec offset = cd2Sub(ray.origin, c.p1);
	cdReal radiusSquared = c.radius * c.radius;

	cdReal axisLengthSquared = cd2Dot(axis, axis);
	cdReal along = cd2Dot(offset, axis);
	cd2Vec fromAxis = offset;
	if (along >= axisLengthSquared)
	{
		fromAxis = cd2Sub(ray.origin, c.p2);
	}
	else if (along > CD_R(0.0))
	{
		fromAxis = cd2MulSub(offset, along / axisLengthSquared, axis);
	}
	if (cd2Dot(fromAxis, fromAxis) <= radiusSquared)
	{
		return cd2HitFromInside(ray, hit);
	}

	cd2Vec direction;
	cdReal length;
	if (!cd2GetRayDirection(ray.translation, &direction, &length))
	{
		return false;
	}

	bool found = false;
	cdReal best = length;
	cd2Vec bestNormal = CD2_VEC_ZERO;
	cdReal distance;
	cd2Vec normal;

	cdReal axisLength;
	cd2Vec unitAxis = cd2GetLengthAndNormalize(&axisLength, axis);
	if (cd2LengthSquared(unitAxis) > CD_R(0.0))
	{
		/* Signed distance from the axis line (positive on the left) and its rate along the ray. */
		cdReal side = cd2Cross(unitAxis, offset);
		cdReal rate = cd2Cross(unitAxis, direction);
		bool approaching = (side > CD_R(0.0) && rate < CD_R(0.0)) || (side < CD_R(0.0) && rate > CD_R(0.0));
		cdReal gap = cdAbs(side) - c.radius;
		/* gap <= best * |rate| before dividing: a nearly parallel ray never divides by ~0. A gap
		 * at or below zero is an origin on the side that the inside test above rounded the other
		 * way (at the 1e9 scale, a ray from the surface into the capsule missed): it enters at 0. */
		if (approaching && gap <= best * cdAbs(rate))
		{
			cdReal t = gap > CD_R(0.0) ? gap / cdAbs(rate) : CD_R(0.0);
			cdReal hitAlong = cd2Dot(offset, unitAxis) + t * cd2Dot(direction, unitAxis);
			if (CD_R(0.0) <= hitAlong && hitAlong <= axisLength)
			{
				found = true;
				best = t;
				bestNormal = side > CD_R(0.0) ? cd2LeftPerp(unitAxis) : cd2RightPerp(unitAxis);
			}
		}
	}

	if (cd2RayEntryIntoCircle(offset, c.radius, direction, length, &distance, &normal) && distance <= best)
	{
		found = true;
		best = distance;
		bestNormal = normal;
	}
	if (cd2RayEntryIntoCircle(cd2Sub(ray.origin, c.p2), c.radius, direction, length, &distance, &normal) &&
		distance <= best)
	{
		found = true;
		best = distance;
		bestNormal = normal;
	}
	if (!found)
	{
		return false;
	}
	return cd2HitAtFraction(ray, best / length, bestNormal, hit);
}

/* Slab test in a frame where the box is lower..upper; fills the fraction and the local normal. */
static cdSlabResult cd2RaycastLocalBox(cd2Vec lower, cd2Vec upper, cd2Vec origin, cd2Vec translation,
									   cdReal* fraction, cd2Vec* normal)
{
	cdReal o[2] = {origin.x, origin.y};
	cdReal d[2] = {translation.x, translation.y};
	cdReal lo[2] = {lower.x, lower.y};
	cdReal hi[2] = {upper.x, upper.y};
	int axis = 0;
	cdSlabResult result = cd2RaycastSlabs(o, d, lo, hi, fraction, &axis);
	if (result == CD_SLAB_HIT)
	{
		cdReal sign = d[axis] > CD_R(0.0) ? CD_R(-1.0) : CD_R(1.0);
		*normal = axis == 0 ? cd2MakeVec(sign, CD_R(0.0)) : cd2MakeVec(CD_R(0.0), sign);
	}
	return result;
}

bool cd2RaycastAabb(cd2Aabb b, cd2Ray ray, cd2RayHit* hit)
{
	cdReal fraction = CD_R(0.0);
	cd2Vec normal = CD2_VEC_ZERO;
	switch (cd2RaycastLocalBox(b.min, b.max, ray.origin, ray.translation, &fraction, &normal))
	{
		case CD_SLAB_MISS:
			return false;
		case CD_SLAB_INSIDE:
			return cd2HitFromInside(ray, hit);
		case CD_SLAB_HIT:
			break;
	}
	/* Keep the point on the box against round-off: clamp it, and put it exactly on the entry side. */
	cd2Vec point = cd2Clamp(cd2MulAdd(ray.origin, fraction, ray.translation), b.min, b.max);
	if (normal.x != CD_R(0.0))
	{
		point.x = normal.x < CD_R(0.0) ? b.min.x : b.max.x;
	}
	else
	{
		point.y = normal.y < CD_R(0.0) ? b.min.y : b.max.y;
	}
	hit->fraction = fraction;
	hit->point = point;
	hit->normal = normal;
	return true;
}

bool cd2RaycastBox(cd2Box b, cd2Ray ray, cd2RayHit* hit)
{
	cd2Vec origin = cd2InvRotateVector(b.rotation, cd2Sub(ray.origin, b.center));
	cd2Vec translation = cd2InvRotateVector(b.rotation, ray.translation);
	cdReal fraction = CD_R(0.0);
	cd2Vec normal = CD2_VEC_ZERO;
	switch (cd2RaycastLocalBox(cd2Neg(b.halfExtents), b.halfExtents, origin, translation, &fraction, &normal))
	{
		case CD_SLAB_MISS:
			return false;
		case CD_SLAB_INSIDE:
			return cd2HitFromInside(ray, hit);
		case CD_SLAB_HIT:
			break;
	}
	/* Normalized because validators accept rotations up to 1e-4 (float) off unit length. */
	return cd2HitAtFraction(ray, fraction, cd2Normalize(cd2RotateVector(b.rotation, normal)), hit);
}

/* Clipping against the edge half-planes (Ericson 5.3.8): dot(n, origin + t d - v) <= 0 reads
 * t * dot(n, d) <= dot(n, v - origin). Fractions are compared as products before dividing, so a
 * nearly parallel edge never divides to an overflowing quotient that matters. */
/* A rounded polygon is the union of its core polygon and the capsules around its edges. From an
 * origin outside it, the ray crosses an edge capsule before it can reach the core, so the first
 * entry is the earliest entry into an edge capsule, and that capsule's normal is the union's. */
static bool RaycastSharpPolygon(const cd2Polygon* polygon, cd2Ray ray, cd2RayHit* hit);

static bool RaycastRoundedPolygon(const cd2Polygon* polygon, cd2Ray ray, cd2RayHit* hit)
{
	if (cd2PointInPolygon(ray.origin, polygon))
	{
		return cd2HitFromInside(ray, hit);
	}
	bool found = false;
	cd2RayHit best = {CD_R(2.0), CD2_VEC_ZERO, CD2_VEC_ZERO};
	int count = polygon->count;
	for (int i = 0; i < count; ++i)
	{
		cd2Capsule edge = {polygon->vertices[i], polygon->vertices[i + 1 < count ? i + 1 : 0],
						   polygon->radius};
		cd2RayHit edgeHit;
		if (cd2RaycastCapsule(edge, ray, &edgeHit) && edgeHit.fraction < best.fraction)
		{
			best = edgeHit;
			found = true;
		}
	}
	if (found)
	{
		*hit = best;
		return true;
	}
	/* A ray into the core passes through the rounded rim first, but a rim thinner than the
	 * round-off of the edges' coordinates (a radius of 1 on edges 1e9 long in float) can be missed
	 * by every edge's capsule: the core's own hit, on or inside the shape, is then the answer. */
	return RaycastSharpPolygon(polygon, ray, hit);
}

/* The ray against the polygon's core (its radius ignored). */
static bool RaycastSharpPolygon(const cd2Polygon* polygon, cd2Ray ray, cd2RayHit* hit)
{
	int count = polygon->count;
	/* Inside or on the boundary within round-off, as cd2PointInPolygon decides (robust also beyond
	 * a sharp vertex, where the origin can be within round-off of both edge lines far from the
	 * polygon). */
	if (cd2PointInPolygon(ray.origin, polygon))
	{
		return cd2HitFromInside(ray, hit);
	}

	cdReal lower = CD_R(0.0), upper = CD_R(1.0);
	int index = -1;
	for (int i = 0; i < count; ++i)
	{
		/* The origin's side of the edge line, measured from the nearer end of the edge: the round-off
		 * of the normal then grows with the origin's offset from the edge, not from its far end. */
		cd2Vec toStart = cd2Sub(polygon->vertices[i], ray.origin);
		cd2Vec toEnd = cd2Sub(polygon->vertices[i + 1 < count ? i + 1 : 0], ray.origin);
		cd2Vec toEdge = cd2LengthSquared(toEnd) < cd2LengthSquared(toStart) ? toEnd : toStart;
		cdReal numerator = cd2Dot(polygon->normals[i], toEdge);
		cdReal denominator = cd2Dot(polygon->normals[i], ray.translation);
		if (denominator == CD_R(0.0))
		{
			if (numerator < CD_R(0.0))
			{
				return false; /* parallel to this edge and outside it */
			}
		}
		else if (denominator < CD_R(0.0) && numerator < lower * denominator)
		{
			lower = numerator / denominator;
			index = i;
		}
		else if (denominator > CD_R(0.0) && numerator < upper * denominator)
		{
			upper = numerator / denominator;
		}
		if (upper < lower)
		{
			return false;
		}
	}
	/* The origin is outside some edge; the ray enters through it or through a later one. */
	if (index < 0)
	{
		return false;
	}
	return cd2HitAtFraction(ray, lower, polygon->normals[index], hit);
}

bool cd2RaycastPolygon(const cd2Polygon* polygon, cd2Ray ray, cd2RayHit* hit)
{
	CD_ASSERT(polygon != NULL && hit != NULL);
	int count = polygon->count;
	if (count < 1 || count > CD2_MAX_POLYGON_VERTICES)
	{
		return false;
	}
	if (polygon->radius > CD_R(0.0))
	{
		return RaycastRoundedPolygon(polygon, ray, hit);
	}
	return RaycastSharpPolygon(polygon, ray, hit);
}

static cdReal RayMaxAbs(cd2Vec v)
{
	return cdMax(cdAbs(v.x), cdAbs(v.y));
}

/* Two-sided. The segment p1 + s e meets the ray's line where the end points' sides of that line,
 * h = cross(d, p - origin), change sign: s = h1 / (h1 - h2). Each side is decided only beyond its
 * round-off (8 epsilons of |d| times the offset |p - origin|); within it the end point counts as
 * on the line. A segment with both ends on the line is collinear with the ray and is hit at the
 * first point it shares with it, with normal -normalize(translation) (a zero-radius capsule). So a
 * nearly collinear ray is never decided by the crossing of two lines that round-off cannot tell
 * apart (a ray moving away from a segment's end reported a hit 3e-3 off the segment). The crossing
 * point, origin + (start + s e), gives the fraction by projection on the ray. */
bool cd2RaycastSegment(cd2Segment g, cd2Ray ray, cd2RayHit* hit)
{
	cd2Vec d = ray.translation;
	if (d.x == CD_R(0.0) && d.y == CD_R(0.0))
	{
		return false;
	}
	cd2Vec e = cd2Sub(g.p2, g.p1);
	cd2Vec start = cd2Sub(g.p1, ray.origin);
	cd2Vec finish = cd2Sub(g.p2, ray.origin);
	cdReal lengthSquared = cd2Dot(d, d);
	cdReal roundOff = CD_R(8.0) * CD_REAL_EPSILON * RayMaxAbs(d);
	cdReal side1 = cd2Cross(d, start), side2 = cd2Cross(d, finish);
	bool onLine1 = cdAbs(side1) <= roundOff * RayMaxAbs(start);
	bool onLine2 = cdAbs(side2) <= roundOff * RayMaxAbs(finish);
	if (onLine1 && onLine2)
	{
		cdReal startAlong = cd2Dot(start, d), finishAlong = cd2Dot(finish, d);
		cdReal first = cdMin(startAlong, finishAlong), last = cdMax(startAlong, finishAlong);
		if (last < CD_R(0.0) || first > lengthSquared)
		{
			return false;
		}
		return cd2HitAtFraction(ray, cdMax(first, CD_R(0.0)) / lengthSquared, cd2Neg(cd2Normalize(d)), hit);
	}
	/* Ends on opposite sides (as computed) cross the line in between; on one side, the segment
	 * touches it only at an end within round-off of it. */
	bool oneSide = (side1 > CD_R(0.0) && side2 > CD_R(0.0)) || (side1 < CD_R(0.0) && side2 < CD_R(0.0));
	cd2Vec crossing;
	if (!oneSide)
	{
		/* Not both 0 (both would be on the line), so side1 - side2 is not 0. */
		crossing = cd2MulAdd(start, side1 / (side1 - side2), e);
	}
	else if (onLine1 || onLine2)
	{
		crossing = onLine1 ? start : finish;
	}
	else
	{
		return false;
	}
	cdReal along = cd2Dot(crossing, d);
	/* Within round-off of the ray's ends counts (closed sets). */
	cdReal alongRoundOff = roundOff * RayMaxAbs(crossing);
	if (along < -alongRoundOff || along > lengthSquared + alongRoundOff)
	{
		return false;
	}
	cd2Vec normal = cd2LeftPerp(cd2Normalize(e));
	if (cd2Dot(normal, d) > CD_R(0.0))
	{
		normal = cd2Neg(normal);
	}
	return cd2HitAtFraction(ray, along / lengthSquared, normal, hit);
}

bool cd2Raycast(const cd2Shape* shape, cd2Ray ray, cd2RayHit* hit)
{
	CD_ASSERT(shape != NULL && hit != NULL);
	switch (shape->type)
	{
#define CD2_RAYCAST_CASE(Name, PointIn, ClosestPointOn, Raycast, ...)                                        \
	case CD2_TYPE_##Name:                                                                                    \
		return Raycast(CD2_SHAPE_ARG(Name, shape), ray, hit);
		CD2_SHAPE_TABLE(CD2_RAYCAST_CASE)
#undef CD2_RAYCAST_CASE
		default:
			break;
	}
	return false;
}
