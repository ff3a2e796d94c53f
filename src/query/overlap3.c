/* collide: 3D overlap and point-containment tests on primitives.
 *
 * Tolerance. The source texts' tests (point/AABB, AABB/AABB, point/sphere, sphere/sphere,
 * sphere/AABB) compare exactly, with squared distances and no square root. Every other test
 * goes through a rotation, a projection or a computed closest point, whose round-off would turn
 * exact touching into a miss; those accept a gap up to
 *     CD_OVERLAP_TOLERANCE * (largest coordinate magnitude involved, measured relative to the
 *     first shape's reference point),
 * i.e. 16 epsilon relative (about 2e-6 in float, 4e-15 in double). Projections onto unnormalized
 * separating axes scale this by the axis' 1-norm. Computations that multiply coordinates are
 * done on coordinates relative to one of the shapes (and scaled where products could overflow),
 * so huge offsets from the origin cost no more precision than the input itself carries. The
 * half-space tests are the exception: a plane's offset is measured from the world origin, so
 * their magnitude is that of the offset and of the other shape's coordinates. Same-type pairs are
 * evaluated in one fixed order, so (a, b) and (b, a) agree to the bit. */
#include "collide/query3.h"

#include "distance3.h"
#include "support3.h"

#include <string.h>

#define CD_OVERLAP_TOLERANCE (CD_R(16.0) * CD_REAL_EPSILON)

static cdReal MaxAbsComponent(cd3Vec v)
{
	return cdMax(cdAbs(v.x), cdMax(cdAbs(v.y), cdAbs(v.z)));
}

static cdReal Tolerance(cdReal magnitude)
{
	return CD_OVERLAP_TOLERANCE * magnitude;
}

static cdReal AbsSum(cd3Vec v)
{
	return cdAbs(v.x) + cdAbs(v.y) + cdAbs(v.z);
}

/* Pairs of the same type are put in one order (by their bytes) before computing, so that the
 * answer is exactly the same for (a, b) and (b, a): the computations below are not symmetric in
 * their round-off. */
static bool ShouldSwap(const void* a, const void* b, size_t size)
{
	return memcmp(a, b, size) > 0;
}

/* ---- the source texts' tests ------------------------------------------------------------- */

bool cd3PointInAabb(cd3Vec p, cd3Aabb b)
{
	return b.min.x <= p.x && p.x <= b.max.x && b.min.y <= p.y && p.y <= b.max.y && b.min.z <= p.z &&
		   p.z <= b.max.z;
}

bool cd3OverlapAabbAabb(cd3Aabb a, cd3Aabb b)
{
	return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y &&
		   a.min.z <= b.max.z && b.min.z <= a.max.z;
}

bool cd3PointInSphere(cd3Vec p, cd3Sphere s)
{
	return cd3VecDistanceSquared(p, s.center) <= s.radius * s.radius;
}

bool cd3OverlapSphereSphere(cd3Sphere a, cd3Sphere b)
{
	cdReal radius = a.radius + b.radius;
	return cd3VecDistanceSquared(a.center, b.center) <= radius * radius;
}

/* Arvo: squared distance from the center to the box, accumulated per axis. */
bool cd3OverlapSphereAabb(cd3Sphere s, cd3Aabb b)
{
	cd3Vec closest = cd3Clamp(s.center, b.min, b.max);
	return cd3VecDistanceSquared(s.center, closest) <= s.radius * s.radius;
}

/* ---- helpers on segments ------------------------------------------------------------------- */

/* Squared distance from the origin to segment p1-p2, and the magnitude that scales its
 * round-off. The caller has already moved the query point to the origin. */
static cdReal OriginSegmentDistanceSquared(cd3Vec p1, cd3Vec p2, cdReal* magnitude)
{
	cd3Segment segment = {p1, p2};
	cd3Vec closest = cd3ClosestPointOnSegment(segment, CD3_VEC_ZERO);
	*magnitude = cdMax(MaxAbsComponent(p1), MaxAbsComponent(p2));
	return cd3LengthSquared(closest);
}

/* Distance between two segments, computed relative to a.p1. */
static cdReal SegmentSegmentDistanceSquared(cd3Segment a, cd3Segment b, cdReal* magnitude)
{
	cd3Vec origin = a.p1;
	cd3Segment la = {CD3_VEC_ZERO, cd3Sub(a.p2, origin)};
	cd3Segment lb = {cd3Sub(b.p1, origin), cd3Sub(b.p2, origin)};
	*magnitude = cdMax(MaxAbsComponent(la.p2), cdMax(MaxAbsComponent(lb.p1), MaxAbsComponent(lb.p2)));
	cd3ClosestPoints pair = cd3ClosestPointsSegmentSegment(la, lb);
	return cd3VecDistanceSquared(pair.pointA, pair.pointB);
}

/* A cheap exact rejection before the closest points of a triangle and a segment: true when they
 * are certainly farther apart than `radius` plus the overlap tolerance, so that the full test would
 * say "apart" too. Relative to the triangle's first vertex, as the full test. Two tests:
 * - bounding boxes: their gap along an axis is a lower bound of the distance; the subtraction
 *   rounds by epsilon times the gap, far below the margin of one more overlap tolerance;
 * - the triangle's plane: both segment ends on one side, higher than radius plus margin times
 *   |n|, with n = b x c computed on b and c divided by their largest component (so |n| <= 2 and
 *   no underflow at tiny scales). The rounding of n (which can turn a sliver's normal) moves the
 *   heights and margin |n| by less than 32 epsilon (magnitude + margin); a normal below
 *   epsilon^2 (a sliver flatter than round-off) rejects nothing. */
static bool TriangleSegmentApart(cd3Triangle t, cd3Segment g, cdReal radius)
{
	cd3Vec b = cd3Sub(t.b, t.a), c = cd3Sub(t.c, t.a);
	cd3Vec p1 = cd3Sub(g.p1, t.a), p2 = cd3Sub(g.p2, t.a);
	cdReal sideMagnitude = cdMax(MaxAbsComponent(b), MaxAbsComponent(c));
	cdReal magnitude = cdMax(sideMagnitude, cdMax(MaxAbsComponent(p1), MaxAbsComponent(p2)));
	cdReal margin = radius + CD_R(2.0) * Tolerance(magnitude + radius);
	cd3Vec triangleMin = cd3Min(CD3_VEC_ZERO, cd3Min(b, c)), triangleMax = cd3Max(CD3_VEC_ZERO, cd3Max(b, c));
	cd3Vec segmentMin = cd3Min(p1, p2), segmentMax = cd3Max(p1, p2);
	cd3Vec below = cd3Sub(triangleMin, segmentMax), above = cd3Sub(segmentMin, triangleMax);
	if (cdMax(cdMax(below.x, below.y), below.z) > margin || cdMax(cdMax(above.x, above.y), above.z) > margin)
	{
		return true;
	}
	if (!(sideMagnitude > CD_R(0.0)))
	{
		return false;
	}
	cdReal inverse = CD_R(1.0) / sideMagnitude;
	cd3Vec n = cd3Cross(cd3Scale(inverse, b), cd3Scale(inverse, c));
	cdReal lengthSquared = cd3Dot(n, n);
	cdReal flattest = CD_REAL_EPSILON * CD_REAL_EPSILON * CD_REAL_EPSILON * CD_REAL_EPSILON;
	if (!(lengthSquared > flattest))
	{
		return false;
	}
	cdReal h1 = cd3Dot(n, p1), h2 = cd3Dot(n, p2);
	cdReal limit = margin * cdSqrt(lengthSquared) + CD_R(32.0) * CD_REAL_EPSILON * (magnitude + margin);
	/* An infinite or NaN limit compares false: no rejection. */
	return (h1 > limit && h2 > limit) || (-h1 > limit && -h2 > limit);
}

static cdReal TriangleSegmentDistanceSquared(cd3Triangle t, cd3Segment g, cdReal* magnitude)
{
	cd3Vec origin = t.a;
	cd3Triangle lt = {CD3_VEC_ZERO, cd3Sub(t.b, origin), cd3Sub(t.c, origin)};
	cd3Segment lg = {cd3Sub(g.p1, origin), cd3Sub(g.p2, origin)};
	*magnitude = cdMax(cdMax(MaxAbsComponent(lt.b), MaxAbsComponent(lt.c)),
					   cdMax(MaxAbsComponent(lg.p1), MaxAbsComponent(lg.p2)));
	cd3ClosestPoints pair = cd3ClosestPointsTriangleSegment(lt, lg);
	return cd3VecDistanceSquared(pair.pointA, pair.pointB);
}

/* distanceSquared <= (radius + tolerance)^2 */
static bool WithinRadius(cdReal distanceSquared, cdReal radius, cdReal magnitude)
{
	cdReal limit = radius + Tolerance(magnitude + radius);
	return distanceSquared <= limit * limit;
}

/* The AABB's center relative to `origin` (a point of the other shape) and its half extents:
 * working relative to the other shape keeps the rounding of the center at epsilon times their
 * separation instead of epsilon times the distance from the world origin. `magnitude` is the
 * size that this rounding scales with. */
static cd3Vec RelativeAabbCenter(cd3Aabb a, cd3Vec origin, cd3Vec* halfExtents, cdReal* magnitude)
{
	cd3Vec lower = cd3Sub(a.min, origin);
	cd3Vec upper = cd3Sub(a.max, origin);
	*halfExtents = cd3Scale(CD_R(0.5), cd3Sub(a.max, a.min));
	*magnitude = cdMax(MaxAbsComponent(lower), MaxAbsComponent(upper));
	return cd3Scale(CD_R(0.5), cd3Add(lower, upper));
}

/* ---- helpers on boxes in their local frame (centered at the origin, half extents h) -------- */

/* Separating-axis test of segment p1-p2 against the centered box (Ericson 5.3.3): the three box
 * axes and the three cross products of the segment direction with them. */
static bool SegmentOverlapsCenteredBox(cd3Vec p1, cd3Vec p2, cd3Vec h, cdReal magnitude)
{
	cd3Vec mid = cd3Scale(CD_R(0.5), cd3Add(p1, p2));
	cd3Vec half = cd3Scale(CD_R(0.5), cd3Sub(p2, p1));
	cd3Vec absHalf = cd3Abs(half);
	/* mid and half are rounded relative to the endpoints, so their magnitude counts too. */
	cdReal scale =
		cdMax(cdMax(magnitude, MaxAbsComponent(half)), cdMax(MaxAbsComponent(mid), MaxAbsComponent(h)));
	cdReal tolerance = Tolerance(scale + MaxAbsComponent(half));
	if (cdAbs(mid.x) > h.x + absHalf.x + tolerance || cdAbs(mid.y) > h.y + absHalf.y + tolerance ||
		cdAbs(mid.z) > h.z + absHalf.z + tolerance)
	{
		return false;
	}
	/* The axes half x e_i: each term is a product of two coordinates, each known to the round-off
	 * `coordinate` of the largest magnitude, so a term's error is that times the other factor.
	 * A bound from the largest components instead (scale times |half|) read, for a segment nearly
	 * parallel to a box edge, as a band of round-off / sine far beyond the true gap. */
	cdReal coordinate = Tolerance(scale);
	cd3Vec absMid = cd3Abs(mid);
	cd3Vec factor = cd3Add(cd3Add(absMid, absHalf), h);
	if (cdAbs(mid.y * half.z - mid.z * half.y) >
		h.y * absHalf.z + h.z * absHalf.y + CD_R(2.0) * coordinate * (factor.y + factor.z))
	{
		return false;
	}
	if (cdAbs(mid.z * half.x - mid.x * half.z) >
		h.x * absHalf.z + h.z * absHalf.x + CD_R(2.0) * coordinate * (factor.x + factor.z))
	{
		return false;
	}
	if (cdAbs(mid.x * half.y - mid.y * half.x) >
		h.x * absHalf.y + h.y * absHalf.x + CD_R(2.0) * coordinate * (factor.x + factor.y))
	{
		return false;
	}
	return true;
}

/* Squared distance between a segment that does not cross the centered box and the box: the
 * closest pair involves a segment endpoint or one of the twelve box edges. */
static cdReal SegmentCenteredBoxDistanceSquared(cd3Vec p1, cd3Vec p2, cd3Vec h)
{
	cd3Vec negativeH = cd3Neg(h);
	cdReal best = cd3VecDistanceSquared(p1, cd3Clamp(p1, negativeH, h));
	best = cdMin(best, cd3VecDistanceSquared(p2, cd3Clamp(p2, negativeH, h)));
	cd3Segment segment = {p1, p2};
	for (int axis = 0; axis < 3; ++axis)
	{
		for (int corner = 0; corner < 4; ++corner)
		{
			cdReal s1 = (corner & 1) ? CD_R(1.0) : CD_R(-1.0);
			cdReal s2 = (corner & 2) ? CD_R(1.0) : CD_R(-1.0);
			cd3Vec from, to;
			if (axis == 0)
			{
				from = cd3MakeVec(-h.x, s1 * h.y, s2 * h.z);
				to = cd3MakeVec(h.x, s1 * h.y, s2 * h.z);
			}
			else if (axis == 1)
			{
				from = cd3MakeVec(s1 * h.x, -h.y, s2 * h.z);
				to = cd3MakeVec(s1 * h.x, h.y, s2 * h.z);
			}
			else
			{
				from = cd3MakeVec(s1 * h.x, s2 * h.y, -h.z);
				to = cd3MakeVec(s1 * h.x, s2 * h.y, h.z);
			}
			cd3Segment edge = {from, to};
			cd3ClosestPoints pair = cd3ClosestPointsSegmentSegment(edge, segment);
			best = cdMin(best, cd3VecDistanceSquared(pair.pointA, pair.pointB));
		}
	}
	return best;
}

static bool CapsuleOverlapsCenteredBox(cd3Vec p1, cd3Vec p2, cdReal radius, cd3Vec h, cdReal magnitude)
{
	/* Cheap rejection first: the box grown by the radius on every side contains every point
	 * within the radius of the box. */
	cd3Vec grown = cd3Add(h, cd3MakeVec(radius, radius, radius));
	if (!SegmentOverlapsCenteredBox(p1, p2, grown, magnitude))
	{
		return false;
	}
	if (SegmentOverlapsCenteredBox(p1, p2, h, magnitude))
	{
		return true;
	}
	cdReal scale =
		cdMax(magnitude, cdMax(MaxAbsComponent(p1), cdMax(MaxAbsComponent(p2), MaxAbsComponent(h))));
	return WithinRadius(SegmentCenteredBoxDistanceSquared(p1, p2, h), radius, scale);
}

/* Separating-axis test of a triangle against the centered box (Akenine-Moller): the three box
 * axes, the triangle normal and the nine cross products of box axes and triangle edges. A
 * degenerate triangle loses only its normal axis, and the remaining axes are the complete set
 * for the segment or point it collapsed to. */
static bool TriangleOverlapsCenteredBox(cd3Vec v0, cd3Vec v1, cd3Vec v2, cd3Vec h, cdReal magnitude)
{
	cdReal scale =
		cdMax(magnitude, cdMax(MaxAbsComponent(h),
							   cdMax(MaxAbsComponent(v0), cdMax(MaxAbsComponent(v1), MaxAbsComponent(v2)))));
	cdReal tolerance = Tolerance(scale);

	/* Box face axes: the triangle's bounds against the box. */
	for (int axis = 0; axis < 3; ++axis)
	{
		cdReal a = cd3GetComponent(v0, axis), b = cd3GetComponent(v1, axis), c = cd3GetComponent(v2, axis);
		cdReal extent = cd3GetComponent(h, axis);
		if (cdMin(a, cdMin(b, c)) > extent + tolerance || cdMax(a, cdMax(b, c)) < -extent - tolerance)
		{
			return false;
		}
	}

	/* The products below are of coordinates; divide by the scale so they cannot overflow. */
	if (!(scale > CD_R(0.0)))
	{
		return true;
	}
	cdReal inverse = CD_R(1.0) / scale;
	v0 = cd3Scale(inverse, v0);
	v1 = cd3Scale(inverse, v1);
	v2 = cd3Scale(inverse, v2);
	h = cd3Scale(inverse, h);

	cd3Vec edges[3] = {cd3Sub(v1, v0), cd3Sub(v2, v1), cd3Sub(v0, v2)};
	cd3Vec unitAxes[3] = {{CD_R(1.0), CD_R(0.0), CD_R(0.0)},
						  {CD_R(0.0), CD_R(1.0), CD_R(0.0)},
						  {CD_R(0.0), CD_R(0.0), CD_R(1.0)}};
	for (int i = 0; i < 3; ++i)
	{
		for (int j = 0; j < 3; ++j)
		{
			cd3Vec axis = cd3Cross(unitAxes[i], edges[j]);
			cdReal p0 = cd3Dot(axis, v0), p1 = cd3Dot(axis, v1), p2 = cd3Dot(axis, v2);
			cdReal radius = cd3Dot(h, cd3Abs(axis));
			cdReal axisTolerance = CD_OVERLAP_TOLERANCE * AbsSum(axis);
			if (cdMin(p0, cdMin(p1, p2)) > radius + axisTolerance ||
				cdMax(p0, cdMax(p1, p2)) < -radius - axisTolerance)
			{
				return false;
			}
		}
	}

	/* The triangle's own interval on its normal, not just one vertex's projection: on a thin
	 * triangle the computed normal is off, and the vertices then project apart. */
	cd3Vec normal = cd3Cross(edges[0], edges[1]);
	cdReal p0 = cd3Dot(normal, v0), p1 = cd3Dot(normal, v1), p2 = cd3Dot(normal, v2);
	cdReal radius = cd3Dot(h, cd3Abs(normal));
	cdReal normalTolerance = CD_OVERLAP_TOLERANCE * AbsSum(normal) * CD_R(2.0);
	return cdMin(p0, cdMin(p1, p2)) <= radius + normalTolerance &&
		   cdMax(p0, cdMax(p1, p2)) >= -radius - normalTolerance;
}

/* What the box SAT says: apart, overlapping, or overlapping only within the tolerance on a cross
 * axis (BOXES_UNDECIDED). */
typedef enum BoxesOverlapResult
{
	BOXES_APART,
	BOXES_OVERLAP,
	BOXES_UNDECIDED
} BoxesOverlapResult;

/* Gottschalk's 15-axis separating-axis test. rotation's columns are box B's axes in A's frame,
 * translation is B's center in A's frame. The tolerance absorbs the round-off of the rotation
 * entries, which matters most on the nearly null cross axes of (nearly) parallel edges: there
 * the entries, each within epsilon, give the axis only to epsilon over the sine of the edges'
 * angle, and a gap that much times the sizes passes (two segment boxes 2 long, 1.2e-7 rad apart
 * and 1.8e-9 apart, double: the gap is 1e-9 of the size, the band 4e-8). A cross axis that passes
 * only within the tolerance leaves the answer to the caller (BOXES_UNDECIDED): GJK on the
 * corners, exact to their own round-off. */
static BoxesOverlapResult CenteredBoxesOverlap(cd3Vec hA, cd3Vec hB, cd3Mat33 rotation, cd3Vec translation)
{
	cdReal a[3] = {hA.x, hA.y, hA.z};
	cdReal b[3] = {hB.x, hB.y, hB.z};
	cdReal t[3] = {translation.x, translation.y, translation.z};
	cdReal r[3][3], absR[3][3];
	cd3Vec columns[3] = {rotation.cx, rotation.cy, rotation.cz};
	for (int j = 0; j < 3; ++j)
	{
		for (int i = 0; i < 3; ++i)
		{
			r[i][j] = cd3GetComponent(columns[j], i);
			absR[i][j] = cdAbs(r[i][j]);
		}
	}
	cdReal tolerance = Tolerance(MaxAbsComponent(translation) + MaxAbsComponent(hA) + MaxAbsComponent(hB));

	for (int i = 0; i < 3; ++i)
	{
		cdReal rb = b[0] * absR[i][0] + b[1] * absR[i][1] + b[2] * absR[i][2];
		if (cdAbs(t[i]) > a[i] + rb + tolerance)
		{
			return BOXES_APART;
		}
	}
	for (int j = 0; j < 3; ++j)
	{
		cdReal ra = a[0] * absR[0][j] + a[1] * absR[1][j] + a[2] * absR[2][j];
		cdReal projection = t[0] * r[0][j] + t[1] * r[1][j] + t[2] * r[2][j];
		if (cdAbs(projection) > ra + b[j] + tolerance)
		{
			return BOXES_APART;
		}
	}
	/* Axis A_i x B_j. */
	BoxesOverlapResult result = BOXES_OVERLAP;
	for (int i = 0; i < 3; ++i)
	{
		int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
		for (int j = 0; j < 3; ++j)
		{
			int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
			cdReal ra = a[i1] * absR[i2][j] + a[i2] * absR[i1][j];
			cdReal rb = b[j1] * absR[i][j2] + b[j2] * absR[i][j1];
			cdReal projection = t[i2] * r[i1][j] - t[i1] * r[i2][j];
			if (cdAbs(projection) > ra + rb + tolerance)
			{
				return BOXES_APART;
			}
			if (cdAbs(projection) > ra + rb)
			{
				result = BOXES_UNDECIDED;
			}
		}
	}
	return result;
}

/* ---- point containment --------------------------------------------------------------------- */

bool cd3PointInCapsule(cd3Vec p, cd3Capsule c)
{
	cdReal magnitude;
	cdReal distanceSquared = OriginSegmentDistanceSquared(cd3Sub(c.p1, p), cd3Sub(c.p2, p), &magnitude);
	return WithinRadius(distanceSquared, c.radius, magnitude);
}

bool cd3PointInBox(cd3Vec p, cd3Box b)
{
	cd3Vec offset = cd3Sub(p, b.center);
	cd3Vec local = cd3InvRotateVector(cd3NormalizeQuat(b.rotation), offset);
	cdReal tolerance = Tolerance(MaxAbsComponent(offset));
	cd3Vec h = b.halfExtents;
	return cdAbs(local.x) <= h.x + tolerance && cdAbs(local.y) <= h.y + tolerance &&
		   cdAbs(local.z) <= h.z + tolerance;
}

bool cd3PointInPlane(cd3Vec p, cd3Plane plane)
{
	cdReal height = cd3Dot(plane.normal, p) - plane.offset;
	return height <= Tolerance(cdMax(MaxAbsComponent(p), cdAbs(plane.offset)));
}

/* ---- sphere pairs -------------------------------------------------------------------------- */

bool cd3OverlapSphereCapsule(cd3Sphere s, cd3Capsule c)
{
	cdReal magnitude;
	cdReal distanceSquared =
		OriginSegmentDistanceSquared(cd3Sub(c.p1, s.center), cd3Sub(c.p2, s.center), &magnitude);
	return WithinRadius(distanceSquared, s.radius + c.radius, magnitude);
}

bool cd3OverlapSphereBox(cd3Sphere s, cd3Box b)
{
	cd3Vec offset = cd3Sub(s.center, b.center);
	cd3Vec local = cd3InvRotateVector(cd3NormalizeQuat(b.rotation), offset);
	cd3Vec h = b.halfExtents;
	cd3Vec outside = cd3Sub(local, cd3Clamp(local, cd3Neg(h), h));
	return WithinRadius(cd3LengthSquared(outside), s.radius, MaxAbsComponent(offset));
}

bool cd3OverlapSphereTriangle(cd3Sphere s, cd3Triangle t)
{
	cd3Triangle local = {cd3Sub(t.a, s.center), cd3Sub(t.b, s.center), cd3Sub(t.c, s.center)};
	cd3Vec closest = cd3ClosestPointOnTriangle(local, CD3_VEC_ZERO);
	cdReal magnitude =
		cdMax(MaxAbsComponent(local.a), cdMax(MaxAbsComponent(local.b), MaxAbsComponent(local.c)));
	return WithinRadius(cd3LengthSquared(closest), s.radius, magnitude);
}

bool cd3OverlapSpherePlane(cd3Sphere s, cd3Plane p)
{
	cdReal height = cd3Dot(p.normal, s.center) - p.offset;
	return height <= s.radius + Tolerance(cdMax(MaxAbsComponent(s.center), cdAbs(p.offset)) + s.radius);
}

bool cd3OverlapSphereSegment(cd3Sphere s, cd3Segment g)
{
	cdReal magnitude;
	cdReal distanceSquared =
		OriginSegmentDistanceSquared(cd3Sub(g.p1, s.center), cd3Sub(g.p2, s.center), &magnitude);
	return WithinRadius(distanceSquared, s.radius, magnitude);
}

/* ---- capsule pairs ------------------------------------------------------------------------- */

bool cd3OverlapCapsuleCapsule(cd3Capsule a, cd3Capsule b)
{
	if (ShouldSwap(&a, &b, sizeof(cd3Capsule)))
	{
		cd3Capsule swapped = a;
		a = b;
		b = swapped;
	}
	cd3Segment sa = {a.p1, a.p2};
	cd3Segment sb = {b.p1, b.p2};
	cdReal magnitude;
	cdReal distanceSquared = SegmentSegmentDistanceSquared(sa, sb, &magnitude);
	return WithinRadius(distanceSquared, a.radius + b.radius, magnitude);
}

bool cd3OverlapCapsuleAabb(cd3Capsule c, cd3Aabb b)
{
	cd3Vec h;
	cdReal magnitude;
	cd3Vec center = RelativeAabbCenter(b, c.p1, &h, &magnitude);
	cd3Vec p2 = cd3Sub(c.p2, c.p1);
	return CapsuleOverlapsCenteredBox(cd3Neg(center), cd3Sub(p2, center), c.radius, h, magnitude);
}

bool cd3OverlapCapsuleBox(cd3Capsule c, cd3Box b)
{
	cd3Quat q = cd3NormalizeQuat(b.rotation);
	cd3Vec p1 = cd3InvRotateVector(q, cd3Sub(c.p1, b.center));
	cd3Vec p2 = cd3InvRotateVector(q, cd3Sub(c.p2, b.center));
	return CapsuleOverlapsCenteredBox(p1, p2, c.radius, b.halfExtents, CD_R(0.0));
}

bool cd3OverlapCapsuleTriangle(cd3Capsule c, cd3Triangle t)
{
	cd3Segment axis = {c.p1, c.p2};
	if (TriangleSegmentApart(t, axis, c.radius))
	{
		return false;
	}
	cdReal magnitude;
	cdReal distanceSquared = TriangleSegmentDistanceSquared(t, axis, &magnitude);
	return WithinRadius(distanceSquared, c.radius, magnitude);
}

bool cd3OverlapCapsulePlane(cd3Capsule c, cd3Plane p)
{
	cdReal height = cdMin(cd3Dot(p.normal, c.p1), cd3Dot(p.normal, c.p2)) - p.offset;
	cdReal magnitude = cdMax(cdMax(MaxAbsComponent(c.p1), MaxAbsComponent(c.p2)), cdAbs(p.offset));
	return height <= c.radius + Tolerance(magnitude + c.radius);
}

bool cd3OverlapCapsuleSegment(cd3Capsule c, cd3Segment g)
{
	cd3Segment axis = {c.p1, c.p2};
	cdReal magnitude;
	cdReal distanceSquared = SegmentSegmentDistanceSquared(axis, g, &magnitude);
	return WithinRadius(distanceSquared, c.radius, magnitude);
}

/* ---- AABB pairs ---------------------------------------------------------------------------- */

bool cd3OverlapAabbBox(cd3Aabb a, cd3Box b)
{
	cd3Vec hA;
	cdReal magnitude;
	cd3Vec center = RelativeAabbCenter(a, b.center, &hA, &magnitude);
	cd3Mat33 rotation = cd3MakeMatFromQuat(cd3NormalizeQuat(b.rotation));
	/* Pad A by the round-off of its relative center. */
	cdReal pad = Tolerance(magnitude);
	hA = cd3Add(hA, cd3MakeVec(pad, pad, pad));
	BoxesOverlapResult result = CenteredBoxesOverlap(hA, b.halfExtents, rotation, cd3Neg(center));
	if (result == BOXES_UNDECIDED)
	{
		cd3Shape aabbShape = cd3MakeAabbShape(a), boxShape = cd3MakeBoxShape(b);
		return cd3OverlapGjk(&aabbShape, &boxShape);
	}
	return result == BOXES_OVERLAP;
}

bool cd3OverlapAabbTriangle(cd3Aabb a, cd3Triangle t)
{
	cd3Vec h;
	cdReal magnitude;
	cd3Vec center = RelativeAabbCenter(a, t.a, &h, &magnitude);
	cd3Vec b = cd3Sub(t.b, t.a), c = cd3Sub(t.c, t.a);
	return TriangleOverlapsCenteredBox(cd3Neg(center), cd3Sub(b, center), cd3Sub(c, center), h, magnitude);
}

/* The corner that reaches deepest against the normal decides. */
bool cd3OverlapAabbPlane(cd3Aabb a, cd3Plane p)
{
	cd3Vec n = p.normal;
	cd3Vec deepest = cd3MakeVec(n.x > CD_R(0.0) ? a.min.x : a.max.x, n.y > CD_R(0.0) ? a.min.y : a.max.y,
								n.z > CD_R(0.0) ? a.min.z : a.max.z);
	return cd3Dot(n, deepest) <= p.offset + Tolerance(cdMax(MaxAbsComponent(deepest), cdAbs(p.offset)));
}

bool cd3OverlapAabbSegment(cd3Aabb a, cd3Segment g)
{
	cd3Vec h;
	cdReal magnitude;
	cd3Vec center = RelativeAabbCenter(a, g.p1, &h, &magnitude);
	return SegmentOverlapsCenteredBox(cd3Neg(center), cd3Sub(cd3Sub(g.p2, g.p1), center), h, magnitude);
}

/* ---- box pairs ----------------------------------------------------------------------------- */

bool cd3OverlapBoxBox(cd3Box a, cd3Box b)
{
	if (ShouldSwap(&a, &b, sizeof(cd3Box)))
	{
		cd3Box swapped = a;
		a = b;
		b = swapped;
	}
	cd3Mat33 ma = cd3MakeMatFromQuat(cd3NormalizeQuat(a.rotation));
	cd3Mat33 mb = cd3MakeMatFromQuat(cd3NormalizeQuat(b.rotation));
	cd3Mat33 rotation = cd3MulMM(cd3Transpose(ma), mb);
	cd3Vec translation = cd3MulMTV(ma, cd3Sub(b.center, a.center));
	BoxesOverlapResult result = CenteredBoxesOverlap(a.halfExtents, b.halfExtents, rotation, translation);
	if (result == BOXES_UNDECIDED)
	{
		cd3Shape shapeA = cd3MakeBoxShape(a), shapeB = cd3MakeBoxShape(b);
		return cd3OverlapGjk(&shapeA, &shapeB);
	}
	return result == BOXES_OVERLAP;
}

bool cd3OverlapBoxTriangle(cd3Box b, cd3Triangle t)
{
	cd3Quat q = cd3NormalizeQuat(b.rotation);
	cd3Vec v0 = cd3InvRotateVector(q, cd3Sub(t.a, b.center));
	cd3Vec v1 = cd3InvRotateVector(q, cd3Sub(t.b, b.center));
	cd3Vec v2 = cd3InvRotateVector(q, cd3Sub(t.c, b.center));
	return TriangleOverlapsCenteredBox(v0, v1, v2, b.halfExtents, CD_R(0.0));
}

/* Projected radius of the box on the normal. */
bool cd3OverlapBoxPlane(cd3Box b, cd3Plane p)
{
	cd3Vec localNormal = cd3InvRotateVector(cd3NormalizeQuat(b.rotation), p.normal);
	cdReal radius = cd3Dot(b.halfExtents, cd3Abs(localNormal));
	cdReal height = cd3Dot(p.normal, b.center) - p.offset;
	cdReal magnitude = cdMax(MaxAbsComponent(b.center), cdAbs(p.offset)) + MaxAbsComponent(b.halfExtents);
	return height - radius <= Tolerance(magnitude);
}

bool cd3OverlapBoxSegment(cd3Box b, cd3Segment g)
{
	cd3Quat q = cd3NormalizeQuat(b.rotation);
	cd3Vec p1 = cd3InvRotateVector(q, cd3Sub(g.p1, b.center));
	cd3Vec p2 = cd3InvRotateVector(q, cd3Sub(g.p2, b.center));
	return SegmentOverlapsCenteredBox(p1, p2, b.halfExtents, CD_R(0.0));
}

/* ---- triangle pairs ------------------------------------------------------------------------ */

static bool IsNearlyDegenerate(cd3Vec e0, cd3Vec e1, cd3Vec normal)
{
	cdReal limit = CD_R(4.0) * CD_REAL_EPSILON;
	return cd3LengthSquared(normal) <= limit * limit * cd3LengthSquared(e0) * cd3LengthSquared(e1);
}

static cd3Segment LongestEdge(cd3Vec a, cd3Vec b, cd3Vec c)
{
	cdReal ab = cd3VecDistanceSquared(a, b), bc = cd3VecDistanceSquared(b, c),
		   ca = cd3VecDistanceSquared(c, a);
	cd3Segment segment = {a, b};
	if (bc >= ab && bc >= ca)
	{
		segment.p1 = b;
		segment.p2 = c;
	}
	else if (ca >= ab && ca >= bc)
	{
		segment.p1 = c;
		segment.p2 = a;
	}
	return segment;
}

static bool SeparatedOnAxis(cd3Vec axis, const cd3Vec* a, const cd3Vec* b)
{
	cdReal minA = CD_REAL_MAX, maxA = -CD_REAL_MAX, minB = CD_REAL_MAX, maxB = -CD_REAL_MAX;
	for (int i = 0; i < 3; ++i)
	{
		cdReal pa = cd3Dot(axis, a[i]);
		cdReal pb = cd3Dot(axis, b[i]);
		minA = cdMin(minA, pa);
		maxA = cdMax(maxA, pa);
		minB = cdMin(minB, pb);
		maxB = cdMax(maxB, pb);
	}
	/* Coordinates are scaled to at most 1, so the projections' round-off is relative to |axis|. */
	cdReal tolerance = CD_OVERLAP_TOLERANCE * AbsSum(axis);
	return minB > maxA + tolerance || minA > maxB + tolerance;
}

/* Separating axes: both face normals, the nine edge-edge cross products, and the six in-plane
 * edge normals, which separate coplanar and parallel-edge configurations that the first eleven
 * miss. Every axis is a valid separating direction, so the extra ones cost no correctness. A
 * (nearly) zero-area triangle has no usable normal; it is handled as its longest edge. */
bool cd3OverlapTriangleTriangle(cd3Triangle ta, cd3Triangle tb)
{
	if (ShouldSwap(&ta, &tb, sizeof(cd3Triangle)))
	{
		cd3Triangle swapped = ta;
		ta = tb;
		tb = swapped;
	}
	cd3Vec origin = ta.a;
	cd3Vec a[3] = {CD3_VEC_ZERO, cd3Sub(ta.b, origin), cd3Sub(ta.c, origin)};
	cd3Vec b[3] = {cd3Sub(tb.a, origin), cd3Sub(tb.b, origin), cd3Sub(tb.c, origin)};
	cdReal scale = 0;
	for (int i = 0; i < 3; ++i)
	{
		scale = cdMax(scale, cdMax(MaxAbsComponent(a[i]), MaxAbsComponent(b[i])));
	}
	if (!(scale > CD_R(0.0)))
	{
		return true;
	}
	cdReal inverse = CD_R(1.0) / scale;
	for (int i = 0; i < 3; ++i)
	{
		a[i] = cd3Scale(inverse, a[i]);
		b[i] = cd3Scale(inverse, b[i]);
	}
	cd3Vec ea[3] = {cd3Sub(a[1], a[0]), cd3Sub(a[2], a[1]), cd3Sub(a[0], a[2])};
	cd3Vec eb[3] = {cd3Sub(b[1], b[0]), cd3Sub(b[2], b[1]), cd3Sub(b[0], b[2])};
	cd3Vec na = cd3Cross(ea[0], ea[1]);
	cd3Vec nb = cd3Cross(eb[0], eb[1]);
	bool degenerateA = IsNearlyDegenerate(ea[0], ea[1], na);
	bool degenerateB = IsNearlyDegenerate(eb[0], eb[1], nb);
	if (degenerateA || degenerateB)
	{
		cdReal magnitude;
		cdReal distanceSquared;
		if (degenerateA && degenerateB)
		{
			distanceSquared = SegmentSegmentDistanceSquared(LongestEdge(a[0], a[1], a[2]),
															LongestEdge(b[0], b[1], b[2]), &magnitude);
		}
		else if (degenerateA)
		{
			cd3Triangle triangle = {b[0], b[1], b[2]};
			distanceSquared =
				TriangleSegmentDistanceSquared(triangle, LongestEdge(a[0], a[1], a[2]), &magnitude);
		}
		else
		{
			cd3Triangle triangle = {a[0], a[1], a[2]};
			distanceSquared =
				TriangleSegmentDistanceSquared(triangle, LongestEdge(b[0], b[1], b[2]), &magnitude);
		}
		return WithinRadius(distanceSquared, CD_R(0.0), magnitude);
	}

	if (SeparatedOnAxis(na, a, b) || SeparatedOnAxis(nb, a, b))
	{
		return false;
	}
	for (int i = 0; i < 3; ++i)
	{
		for (int j = 0; j < 3; ++j)
		{
			if (SeparatedOnAxis(cd3Cross(ea[i], eb[j]), a, b))
			{
				return false;
			}
		}
	}
	for (int i = 0; i < 3; ++i)
	{
		if (SeparatedOnAxis(cd3Cross(na, ea[i]), a, b) || SeparatedOnAxis(cd3Cross(nb, eb[i]), a, b))
		{
			return false;
		}
	}
	return true;
}

bool cd3OverlapTrianglePlane(cd3Triangle t, cd3Plane p)
{
	cd3Vec n = p.normal;
	cdReal lowest = cdMin(cd3Dot(n, t.a), cdMin(cd3Dot(n, t.b), cd3Dot(n, t.c)));
	cdReal magnitude = cdMax(cdMax(MaxAbsComponent(t.a), MaxAbsComponent(t.b)),
							 cdMax(MaxAbsComponent(t.c), cdAbs(p.offset)));
	return lowest <= p.offset + Tolerance(magnitude);
}

bool cd3OverlapTriangleSegment(cd3Triangle t, cd3Segment g)
{
	if (TriangleSegmentApart(t, g, CD_R(0.0)))
	{
		return false;
	}
	cdReal magnitude;
	cdReal distanceSquared = TriangleSegmentDistanceSquared(t, g, &magnitude);
	return WithinRadius(distanceSquared, CD_R(0.0), magnitude);
}

/* ---- plane and segment pairs --------------------------------------------------------------- */

/* Shared with cd3Distance (support3.h): opposite normals within 16 epsilon, a gap beyond the
 * tolerance. */
bool cd3OverlapPlanePlane(cd3Plane a, cd3Plane b)
{
	cdReal gap;
	return !cd3HalfSpacesApart(a, b, &gap);
}

bool cd3OverlapPlaneSegment(cd3Plane p, cd3Segment g)
{
	cdReal lowest = cdMin(cd3Dot(p.normal, g.p1), cd3Dot(p.normal, g.p2));
	cdReal magnitude = cdMax(cdMax(MaxAbsComponent(g.p1), MaxAbsComponent(g.p2)), cdAbs(p.offset));
	return lowest <= p.offset + Tolerance(magnitude);
}

bool cd3OverlapSegmentSegment(cd3Segment a, cd3Segment b)
{
	if (ShouldSwap(&a, &b, sizeof(cd3Segment)))
	{
		cd3Segment swapped = a;
		a = b;
		b = swapped;
	}
	cdReal magnitude;
	cdReal distanceSquared = SegmentSegmentDistanceSquared(a, b, &magnitude);
	return WithinRadius(distanceSquared, CD_R(0.0), magnitude);
}
