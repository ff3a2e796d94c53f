/* collide: 3D ray casts against the primitive shapes, and the dispatcher on tagged shapes.
 *
 * Conventions (query3.h): the ray is origin + t * translation with t in [0, 1]; a hit reports the
 * entry fraction, the point origin + fraction * translation and the outward unit normal there.
 * A ray whose origin lies in a solid shape (boundary included) hits at fraction 0 with normal
 * -normalize(translation), the zero vector for a zero translation. A zero translation hits only
 * such solid shapes: it never hits the non-solid triangle and segment. *hit is untouched on a miss.
 *
 * Curved shapes work in distance units along the unit ray direction, which keeps every
 * intermediate product of the order of the squared coordinates (no overflow for coordinates up to
 * 1e9 in float) and lets the entry formulas avoid cancellation (see cdRayEntryIntoBall). */
#include "collide/query3.h"

#include "query/pairs3.h"
#define CD_DIM 3
#include "query/raycast_common.h"
#include "query/wide3.h"

#include <float.h>
#include <math.h>

/* |a| as a max, one instruction where cdAbs compares and branches on a sign that is random from
 * call to call; it differs from cdAbs only in the sign of a zero (and of a NaN), which the
 * magnitudes below, only compared or multiplied into tolerances, never show. */
static inline cdReal AbsNoBranch(cdReal a)
{
	return cdMax(a, -a);
}

static cdReal MaxAbsComponent(cd3Vec v)
{
	return cdMax(AbsNoBranch(v.x), cdMax(AbsNoBranch(v.y), AbsNoBranch(v.z)));
}

/* Unit direction and length of the translation; false for a zero (or non-finite) length. */
static bool cd3GetRayDirection(cd3Vec translation, cd3Vec* direction, cdReal* length)
{
	cdReal l = cd3Length(translation);
	if (!(l > CD_R(0.0)) || !cdIsValidReal(l))
	{
		return false;
	}
	*length = l;
	*direction = cd3Scale(CD_R(1.0) / l, translation);
	return true;
}

static bool cd3HitFromInside(cd3Ray ray, cd3RayHit* hit)
{
	hit->fraction = CD_R(0.0);
	hit->point = ray.origin;
	hit->normal = cd3Neg(cd3Normalize(ray.translation));
	return true;
}

/* Fills *hit for an entry `distance` along the unit direction of a ray of length `length`. */
static bool cd3HitAtDistance(cd3Ray ray, cdReal distance, cdReal length, cd3Vec normal, cd3RayHit* hit)
{
	cdReal fraction = cdClamp(distance / length, CD_R(0.0), CD_R(1.0));
	hit->fraction = fraction;
	hit->point = cd3MulAdd(ray.origin, fraction, ray.translation);
	hit->normal = normal;
	return true;
}

/* Entry into a ball whose center is `offset` = origin - center away from the ray origin, for an
 * origin outside it. The normal is built from the center's foot on the line, (u x offset) x u, and
 * the half chord, each accurate relative to the radius: offset + distance * u would carry a
 * round-off of the order of |offset|, which can swamp a small radius and turn the normal around.
 * It falls back to -direction when the ray passes through the center of a zero-radius ball. */
static bool cd3RayEntryIntoSphere(cd3Vec offset, cdReal radius, cd3Vec direction, cdReal length,
								  cdReal* distance, cd3Vec* normal)
{
	cdReal outside = cd3Dot(offset, offset) - radius * radius;
	cd3Vec lineOffset = cd3Cross(direction, offset);
	cdReal halfChord;
	if (!cdRayEntryIntoBall(cd3Dot(offset, direction), outside, radius * radius, cd3LengthSquared(lineOffset),
							length, distance, &halfChord))
	{
		return false;
	}
	cd3Vec foot = cd3Cross(lineOffset, direction);
	*normal = cd3Normalize(cd3MulSub(foot, halfChord, direction));
	if (cd3LengthSquared(*normal) == CD_R(0.0))
	{
		*normal = cd3Neg(direction);
	}
	return true;
}

bool cd3RaycastSphere(cd3Sphere s, cd3Ray ray, cd3RayHit* hit)
{
	cd3Vec offset = cd3Sub(ray.origin, s.center);
	if (cd3Dot(offset, offset) <= s.radius * s.radius)
	{
		return cd3HitFromInside(ray, hit);
	}
	cd3Vec direction;
	cdReal length, distance;
	cd3Vec normal;
	if (!cd3GetRayDirection(ray.translation, &direction, &length) ||
		!cd3RayEntryIntoSphere(offset, s.radius, direction, length, &distance, &normal))
	{
		return false;
	}
	return cd3HitAtDistance(ray, distance, length, normal, hit);
}

/* A capsule is the union of its two end balls and the finite cylinder between them. The first
 * entry into the union is the earliest of: the entry into the infinite cylinder when that point
 * lies between the end planes, and the entries into the two balls (a ray entering the finite
 * cylinder through an end disk is already inside that end's ball). Rays parallel to the axis
 * never meet the side and are handled by the balls. */
bool cd3RaycastCapsule(cd3Capsule c, cd3Ray ray, cd3RayHit* hit)
{
	cd3Vec axis = cd3Sub(c.p2, c.p1);
	cd3Vec offset = cd3Sub(ray.origin, c.p1);
	cdReal radiusSquared = c.radius * c.radius;

	/* Squared distance from the origin to the axis segment, for the inside test. */
	cdReal axisLengthSquared = cd3Dot(axis, axis);
	cdReal along = cd3Dot(offset, axis);
	cd3Vec fromAxis = offset;
	if (along >= axisLengthSquared)
	{
		fromAxis = cd3Sub(ray.origin, c.p2);
	}
	else if (along > CD_R(0.0))
	{
		fromAxis = cd3MulSub(offset, along / axisLengthSquared, axis);
	}
	if (cd3Dot(fromAxis, fromAxis) <= radiusSquared)
	{
		return cd3HitFromInside(ray, hit);
	}

	cd3Vec direction;
	cdReal length;
	if (!cd3GetRayDirection(ray.translation, &direction, &length))
	{
		return false;
	}

	bool found = false;
	cdReal best = length;
	cd3Vec bestNormal = CD3_VEC_ZERO;
	cdReal distance;
	cd3Vec normal;

	cdReal axisLength;
	cd3Vec unitAxis = cd3GetLengthAndNormalize(&axisLength, axis);
	if (cd3LengthSquared(unitAxis) > CD_R(0.0))
	{
		cdReal offsetAlong = cd3Dot(offset, unitAxis);
		cdReal directionAlong = cd3Dot(direction, unitAxis);
		cd3Vec offsetPerp = cd3MulSub(offset, offsetAlong, unitAxis);
		cd3Vec directionPerp = cd3MulSub(direction, directionAlong, unitAxis);
		cdReal a = cd3Dot(directionPerp, directionPerp);
		cdReal b = cd3Dot(offsetPerp, directionPerp);
		cdReal outside = cd3Dot(offsetPerp, offsetPerp) - radiusSquared;
		/* |directionPerp x offsetPerp| = |det(direction, offset, unitAxis)|: the discriminant
		 * b^2 - a * outside rewritten as a * r^2 - det^2 without cancellation. */
		cdReal det = cd3Dot(cd3Cross(direction, offset), unitAxis);
		cdReal disc = a * radiusSquared - det * det;
		/* A ray whose sideways part is below cd3Normalize's threshold (CD_REAL_EPSILON^2) drifts
		 * sideways by less than the round-off of its coordinates: left to the end balls. */
		cd3Vec across = cd3Normalize(directionPerp);
		bool sideways = cd3LengthSquared(across) > CD_R(0.0);
		/* An outside at or below zero is an origin on the side that the inside test above rounded
		 * the other way (as in 2D, a ray from the surface into the capsule missed): it enters at 0. */
		if (sideways && b < CD_R(0.0) && disc >= CD_R(0.0))
		{
			cdReal t = outside > CD_R(0.0) ? outside / (-b + cdSqrt(disc)) : CD_R(0.0);
			cdReal hitAlong = offsetAlong + t * directionAlong;
			/* The perpendicular parts carry a round-off of epsilon times the coordinates: for a
			 * radius below it (a zero-radius capsule at the 1e9 scale) t is noise, and a hit
			 * 2.4e8 from the axis came out. The point must lie at the radius from the axis
			 * within the segment ray cast's tolerance (64 epsilon of the coordinates). */
			cd3Vec offAxis = cd3MulAdd(offsetPerp, t, directionPerp);
			cd3Vec end = cd3Add(ray.origin, ray.translation);
			cdReal magnitude = cdMax(cdMax(MaxAbsComponent(c.p1), MaxAbsComponent(c.p2)),
									 cdMax(MaxAbsComponent(ray.origin), MaxAbsComponent(end)));
			bool onSide = cdAbs(cd3Length(offAxis) - c.radius) <= CD_R(64.0) * CD_REAL_EPSILON * magnitude;
			if (onSide && t <= best && CD_R(0.0) <= hitAlong && hitAlong <= axisLength)
			{
				found = true;
				best = t;
				/* As for the ball: the axis's foot on the ray's projection into the plane across
				 * the axis, moved back by the half chord, accurate relative to the radius. */
				cd3Vec foot = cd3Cross(cd3Cross(across, offsetPerp), across);
				bestNormal = cd3Normalize(cd3MulSub(foot, cdSqrt(disc / a), across));
				if (cd3LengthSquared(bestNormal) == CD_R(0.0))
				{
					bestNormal = cd3Neg(across);
				}
			}
		}
	}

	if (cd3RayEntryIntoSphere(offset, c.radius, direction, length, &distance, &normal) && distance <= best)
	{
		found = true;
		best = distance;
		bestNormal = normal;
	}
	if (cd3RayEntryIntoSphere(cd3Sub(ray.origin, c.p2), c.radius, direction, length, &distance, &normal) &&
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
	return cd3HitAtDistance(ray, best, length, bestNormal, hit);
}

/* Slab test in a frame where the box is lower..upper; fills the fraction and the local normal. */
static cdSlabResult cd3RaycastLocalBox(cd3Vec lower, cd3Vec upper, cd3Vec origin, cd3Vec translation,
									   cdReal* fraction, cd3Vec* normal)
{
	cdReal o[3] = {origin.x, origin.y, origin.z};
	cdReal d[3] = {translation.x, translation.y, translation.z};
	cdReal lo[3] = {lower.x, lower.y, lower.z};
	cdReal hi[3] = {upper.x, upper.y, upper.z};
	int axis = 0;
	cdSlabResult result = cd3RaycastSlabs(o, d, lo, hi, fraction, &axis);
	if (result == CD_SLAB_HIT)
	{
		cdReal n[3] = {CD_R(0.0), CD_R(0.0), CD_R(0.0)};
		n[axis] = d[axis] > CD_R(0.0) ? CD_R(-1.0) : CD_R(1.0);
		*normal = cd3MakeVec(n[0], n[1], n[2]);
	}
	return result;
}

bool cd3RaycastAabb(cd3Aabb b, cd3Ray ray, cd3RayHit* hit)
{
	cdReal fraction = CD_R(0.0);
	cd3Vec normal = CD3_VEC_ZERO;
	switch (cd3RaycastLocalBox(b.min, b.max, ray.origin, ray.translation, &fraction, &normal))
	{
		case CD_SLAB_MISS:
			return false;
		case CD_SLAB_INSIDE:
			return cd3HitFromInside(ray, hit);
		case CD_SLAB_HIT:
			break;
	}
	/* Keep the point on the box against round-off: clamp it, and put it exactly on the entry face. */
	cd3Vec point = cd3Clamp(cd3MulAdd(ray.origin, fraction, ray.translation), b.min, b.max);
	if (normal.x != CD_R(0.0))
	{
		point.x = normal.x < CD_R(0.0) ? b.min.x : b.max.x;
	}
	else if (normal.y != CD_R(0.0))
	{
		point.y = normal.y < CD_R(0.0) ? b.min.y : b.max.y;
	}
	else
	{
		point.z = normal.z < CD_R(0.0) ? b.min.z : b.max.z;
	}
	hit->fraction = fraction;
	hit->point = point;
	hit->normal = normal;
	return true;
}

bool cd3RaycastBox(cd3Box b, cd3Ray ray, cd3RayHit* hit)
{
	cd3Vec origin = cd3InvRotateVector(b.rotation, cd3Sub(ray.origin, b.center));
	cd3Vec translation = cd3InvRotateVector(b.rotation, ray.translation);
	cdReal fraction = CD_R(0.0);
	cd3Vec normal = CD3_VEC_ZERO;
	switch (cd3RaycastLocalBox(cd3Neg(b.halfExtents), b.halfExtents, origin, translation, &fraction, &normal))
	{
		case CD_SLAB_MISS:
			return false;
		case CD_SLAB_INSIDE:
			return cd3HitFromInside(ray, hit);
		case CD_SLAB_HIT:
			break;
	}
	hit->fraction = fraction;
	hit->point = cd3MulAdd(ray.origin, fraction, ray.translation);
	/* Normalized because validators accept quaternions up to 1e-4 (float) off unit length. */
	hit->normal = cd3Normalize(cd3RotateVector(b.rotation, normal));
	return true;
}

/* WideMaxAbs with |x| as a max (no branch on the sign): the same value but for the sign of a zero
 * (and of a NaN), which the size test below (> 0) does not see. */
static inline double WideMaxAbsNoBranch(WideVec v)
{
	double x = v.x > -v.x ? v.x : -v.x, y = v.y > -v.y ? v.y : -v.y, z = v.z > -v.z ? v.z : -v.z;
	return x > y ? (x > z ? x : z) : (y > z ? y : z);
}

/* Squared distance from p to the segment a-b, in double. */
static double WideSegmentDistanceSquared(WideVec a, WideVec b, WideVec p)
{
	WideVec e = WideSub(b, a);
	double ee = WideDot(e, e);
	double s = ee > 0.0 ? WideDot(WideSub(p, a), e) / ee : 0.0;
	s = s < 0.0 ? 0.0 : (s > 1.0 ? 1.0 : s);
	WideVec offset = WideSub(p, WideMulAdd(a, s, e));
	return WideDot(offset, offset);
}

/* Two-sided triangle: the fraction comes from the plane, then the hit point's barycentric
 * coordinates decide, everything relative to vertex a and in double (wide3.h) when cdReal is
 * float. Deciding "inside" apart from the fraction (by triple products relative to the ray
 * origin) was inconsistent: relative to a far origin the vertices round to one vector and every
 * ray "passed inside", and a ray grazing the plane got a fraction spoiled by float round-off
 * while its line did pass through the triangle. Testing the very point reported keeps both
 * honest: a hit point lies on the closed triangle, inflated by 4 double epsilons of the largest
 * coordinate involved (the round-off of that point before it is rounded to cdReal). A ray
 * parallel to the plane, in it or not, and a zero-area triangle never hit (docs/API.md). */
bool cd3RaycastTriangle(cd3Triangle t, cd3Ray ray, cd3RayHit* hit)
{
	WideVec a = Widen(t.a);
	WideVec ab = WideSub(Widen(t.b), a);
	WideVec ac = WideSub(Widen(t.c), a);
	WideVec bc = WideSub(Widen(t.c), Widen(t.b));
	/* Scaled to the triangle's size, so that products of up to four lengths stay in range. */
	double size =
		WideMaxAbsNoBranch(ab) > WideMaxAbsNoBranch(ac) ? WideMaxAbsNoBranch(ab) : WideMaxAbsNoBranch(ac);
	if (!(size > 0.0))
	{
		return false;
	}
	double inverse = 1.0 / size;
	ab = WideScale(inverse, ab);
	ac = WideScale(inverse, ac);
	bc = WideScale(inverse, bc);
	WideVec n = WideTriangleNormal(ab, ac, bc);
	double nn = WideDot(n, n);
	double abab = WideDot(ab, ab), acac = WideDot(ac, ac);
	double limit = 4.0 * (double)CD_REAL_EPSILON;
	if (!(nn > limit * limit * abab * acac))
	{
		return false; /* zero area: a segment or a point, which a ray meets with probability zero */
	}
	WideVec start = WideScale(inverse, WideSub(Widen(ray.origin), a));
	WideVec d = WideScale(inverse, Widen(ray.translation));
	double height = WideDot(n, start); /* times |n|: positive on the side n points to */
	double speed = WideDot(n, d);
	/* fraction = -height / speed in [0, 1], tested before dividing. */
	if (speed == 0.0 || (speed < 0.0 ? (height < 0.0 || height > -speed) : (height > 0.0 || -height > speed)))
	{
		return false;
	}
	double fraction = -height / speed;
	fraction = fraction < 0.0 ? 0.0 : (fraction > 1.0 ? 1.0 : fraction);
	WideVec q = WideMulAdd(start, fraction, d); /* the hit point relative to a */

	/* Distances of q inside the three edges, times |n|: n.(q x ac) / |ac| from edge ac, and so on. */
	cd3Vec end = cd3Add(ray.origin, ray.translation);
	cdReal magnitude =
		cdMax(cdMax(MaxAbsComponent(t.a), MaxAbsComponent(t.b)),
			  cdMax(MaxAbsComponent(t.c), cdMax(MaxAbsComponent(ray.origin), MaxAbsComponent(end))));
	/* The round-off of q: 4 epsilon of the arithmetic used here (double, also in the float build). */
	double normalLength = sqrt(nn);
	double tolerance = 4.0 * DBL_EPSILON * (double)magnitude * inverse * normalLength;
	double insideAc = WideDot(n, WideCross(q, ac));
	double insideAb = WideDot(n, WideCross(ab, q));
	double insideBc = WideDot(n, WideCross(bc, WideSub(q, ab)));
	/* A point inside all three edges (the common case of a hit) is accepted without the
	 * distances: a numerator >= 0 over a positive length is >= 0, so the tests below would pass
	 * (unless the tolerance is NaN, which rejects). */
	if (!(insideAc >= 0.0 && insideAb >= 0.0 && insideBc >= 0.0 && tolerance == tolerance))
	{
		double fromAc = insideAc / sqrt(acac);
		double fromAb = insideAb / sqrt(abab);
		double fromBc = insideBc / sqrt(WideDot(bc, bc));
		if (fromAc < -tolerance || fromAb < -tolerance || !(fromBc >= -tolerance))
		{
			return false;
		}
		if (fromAc < 0.0 || fromAb < 0.0 || fromBc < 0.0)
		{
			/* Within the tolerance of an edge's line, but that is not the edge: beyond the tip
			 * of a needle every point near its axis is close to both long edges' lines (a hit 16
			 * lengths past one was accepted). The distance to the nearest edge decides. */
			WideVec zero = {0.0, 0.0, 0.0};
			double reach = tolerance / normalLength;
			if (WideSegmentDistanceSquared(zero, ab, q) > reach * reach &&
				WideSegmentDistanceSquared(zero, ac, q) > reach * reach &&
				WideSegmentDistanceSquared(ab, ac, q) > reach * reach)
			{
				return false;
			}
		}
	}

	cd3Vec unitNormal = Narrow(WideScale(1.0 / normalLength, n));
	hit->fraction = (cdReal)fraction;
	hit->point = cd3MulAdd(ray.origin, hit->fraction, ray.translation);
	/* Two-sided: the normal faces the ray origin. */
	hit->normal = cd3Normalize(speed > 0.0 ? cd3Neg(unitNormal) : unitNormal);
	return true;
}

bool cd3RaycastPlane(cd3Plane plane, cd3Ray ray, cd3RayHit* hit)
{
	cdReal height = cd3Dot(plane.normal, ray.origin) - plane.offset;
	if (height <= CD_R(0.0))
	{
		return cd3HitFromInside(ray, hit);
	}
	cdReal approach = -cd3Dot(plane.normal, ray.translation);
	if (approach <= CD_R(0.0) || height > approach)
	{
		return false;
	}
	cdReal fraction = cdClamp(height / approach, CD_R(0.0), CD_R(1.0));
	hit->fraction = fraction;
	hit->point = cd3MulAdd(ray.origin, fraction, ray.translation);
	hit->normal = plane.normal;
	return true;
}

/* Squared distance between the ray point at `distance` (relative to the origin) and the segment
 * start + [0, segmentLength] * unitSegment (also relative to the origin). */
static cdReal cd3RayPointSegmentDistanceSquared(cd3Vec direction, cdReal distance, cd3Vec start,
												cd3Vec unitSegment, cdReal segmentLength)
{
	cd3Vec point = cd3Scale(distance, direction);
	cdReal along = cdClamp(cd3Dot(cd3Sub(point, start), unitSegment), CD_R(0.0), segmentLength);
	return cd3LengthSquared(cd3Sub(point, cd3MulAdd(start, along, unitSegment)));
}

/* A segment has no interior and a ray meets it with probability zero, so the ray hits when it
 * passes within a tolerance of it: 64 CD_REAL_EPSILON times the largest coordinate magnitude of the
 * segment and the ray's end points (the round-off of the closest-point computation). The hit is
 * the earliest of the candidate points within the tolerance: the closest approach of the two
 * lines, the first ray point level with the segment (for rays along it) and the origin. The normal
 * is perpendicular to the segment and faces the ray origin, -normalize(translation) when that is
 * undefined (a ray along the segment, a zero-length segment). Zero-length rays never hit. */
static bool cd3RaycastSegment(cd3Segment g, cd3Ray ray, cd3RayHit* hit)
{
	cd3Vec direction;
	cdReal length;
	if (!cd3GetRayDirection(ray.translation, &direction, &length))
	{
		return false;
	}
	cd3Vec end = cd3Add(ray.origin, ray.translation);
	cd3Vec magnitude = cd3Max(cd3Max(cd3Abs(ray.origin), cd3Abs(end)), cd3Max(cd3Abs(g.p1), cd3Abs(g.p2)));
	cdReal tolerance = CD_R(64.0) * CD_REAL_EPSILON * cdMax(magnitude.x, cdMax(magnitude.y, magnitude.z));
	cdReal toleranceSquared = tolerance * tolerance;

	cdReal segmentLength;
	cd3Vec unitSegment = cd3GetLengthAndNormalize(&segmentLength, cd3Sub(g.p2, g.p1));
	cd3Vec start = cd3Sub(g.p1, ray.origin);
	cdReal cosine = cd3Dot(direction, unitSegment);
	cdReal startAlongRay = cd3Dot(direction, start);

	cdReal candidates[3];
	int candidateCount = 0;
	candidates[candidateCount++] = CD_R(0.0);
	cdReal endAlongRay = startAlongRay + segmentLength * cosine;
	candidates[candidateCount++] = cdClamp(cdMin(startAlongRay, endAlongRay), CD_R(0.0), length);
	cd3Vec across = cd3Cross(direction, unitSegment);
	cdReal sineSquared = cd3LengthSquared(across);
	if (sineSquared > CD_R(0.0))
	{
		/* Closest approach of the two lines, dot(start x a, u x a) / |u x a|^2: unlike the textbook
		 * (dot(u, start) - cos dot(a, start)) / sin^2 it does not cancel for nearly parallel lines. */
		cdReal s = cd3Dot(cd3Cross(start, unitSegment), across) / sineSquared;
		candidates[candidateCount++] = cdClamp(s, CD_R(0.0), length);
	}

	bool found = false;
	cdReal best = length;
	for (int i = 0; i < candidateCount; ++i)
	{
		if (candidates[i] <= best &&
			cd3RayPointSegmentDistanceSquared(direction, candidates[i], start, unitSegment, segmentLength) <=
				toleranceSquared)
		{
			found = true;
			best = candidates[i];
		}
	}
	if (!found)
	{
		return false;
	}
	cd3Vec normal = cd3Neg(cd3Normalize(cd3MulSub(direction, cosine, unitSegment)));
	if (cd3LengthSquared(normal) == CD_R(0.0))
	{
		normal = cd3Neg(direction);
	}
	return cd3HitAtDistance(ray, best, length, normal, hit);
}

/* Cyrus-Beck: the ray in the hull's frame is clipped by each face's half-space; the last entry
 * is the hit. The origin test is cd3PointInHull's, so a ray starting on the boundary (within the
 * planes' round-off) hits at fraction 0 like every solid shape. */
bool cd3RaycastHull(cd3HullShape shape, cd3Ray ray, cd3RayHit* hit)
{
	CD_ASSERT(shape.hull != NULL && hit != NULL);
	if (cd3PointInHull(ray.origin, shape))
	{
		return cd3HitFromInside(ray, hit);
	}
	const cd3Hull* hull = shape.hull;
	cd3Vec origin = cd3InvTransformPoint(shape.transform, ray.origin);
	cd3Vec translation = cd3InvRotateVector(shape.transform.q, ray.translation);
	cdReal enter = CD_R(0.0), leave = CD_R(1.0);
	int enterFace = -1;
	for (int i = 0; i < hull->faceCount; ++i)
	{
		cd3Plane plane = hull->planes[i];
		cdReal inside = plane.offset - cd3Dot(plane.normal, origin); /* >= 0 below the plane */
		cdReal speed = cd3Dot(plane.normal, translation);
		if (speed == CD_R(0.0))
		{
			if (inside < CD_R(0.0))
			{
				return false; /* parallel to the face and outside it */
			}
			continue;
		}
		cdReal t = inside / speed;
		if (speed < CD_R(0.0))
		{
			if (t > enter)
			{
				enter = t;
				enterFace = i;
			}
		}
		else if (t < leave)
		{
			leave = t;
		}
		if (enter > leave)
		{
			return false;
		}
	}
	if (enterFace < 0)
	{
		return cd3HitFromInside(ray, hit); /* below every plane: inside after all */
	}
	hit->fraction = enter;
	hit->point = cd3MulAdd(ray.origin, enter, ray.translation);
	hit->normal = cd3RotateVector(shape.transform.q, hull->planes[enterFace].normal);
	return true;
}

bool cd3Raycast(const cd3Shape* shape, cd3Ray ray, cd3RayHit* hit)
{
	CD_ASSERT(shape != NULL && hit != NULL);
	switch (shape->type)
	{
#define CD3_RAYCAST_CASE(Name, PointIn, ClosestPointOn, Raycast, ...)                                        \
	case CD3_TYPE_##Name:                                                                                    \
		return Raycast(CD3_SHAPE_ARG(Name, shape), ray, hit);
		CD3_SHAPE_TABLE(CD3_RAYCAST_CASE)
#undef CD3_RAYCAST_CASE
		default:
			break;
	}
	return false;
}
