/* collide: closest points on 3D primitives (Ericson, Real-Time Collision Detection, ch. 5).
 *
 * Robustness: the routines that multiply dot products together (triangle regions, segment pairs)
 * first divide their relative vectors by the largest component, so that the products neither
 * overflow at 1e9 nor underflow at 1e-9 in float; the resulting parameters are scale-free and the
 * points are rebuilt from the unscaled vectors. Degenerate inputs (zero-length segments,
 * zero-area triangles) take explicit branches instead of dividing by zero. */
#include "collide/query3.h"

#include "wide3.h"

static cdReal MaxAbsComponent(cd3Vec v)
{
	return cdMax(cdAbs(v.x), cdMax(cdAbs(v.y), cdAbs(v.z)));
}

/* numerator / denominator clamped to [0, 1]; 0 when the denominator is not positive. */
static cdReal ClampedRatio(cdReal numerator, cdReal denominator)
{
	if (!(denominator > CD_R(0.0)) || numerator <= CD_R(0.0))
	{
		return CD_R(0.0);
	}
	if (numerator >= denominator)
	{
		return CD_R(1.0);
	}
	return numerator / denominator;
}

cd3Vec cd3ClosestPointOnSphere(cd3Sphere s, cd3Vec p)
{
	cd3Vec offset = cd3Sub(p, s.center);
	cdReal distanceSquared = cd3LengthSquared(offset);
	if (distanceSquared <= s.radius * s.radius)
	{
		return p;
	}
	/* distanceSquared > radius^2 >= 0, so the length is positive. */
	cdReal distance = cdSqrt(distanceSquared);
	if (!(distance > CD_R(0.0)) || !cdIsValidReal(distance))
	{
		/* Only reachable through underflow/overflow of the squared length. */
		cd3Vec direction = cd3Normalize(offset);
		return cd3MulAdd(s.center, s.radius, direction);
	}
	return cd3MulAdd(s.center, s.radius / distance, offset);
}

cd3Vec cd3ClosestPointOnSegment(cd3Segment g, cd3Vec p)
{
	cd3Vec direction = cd3Sub(g.p2, g.p1);
	cd3Vec offset = cd3Sub(p, g.p1);
	cdReal scale = cdMax(MaxAbsComponent(direction), MaxAbsComponent(offset));
	if (!(scale > CD_R(0.0)))
	{
		return g.p1;
	}
	cdReal inverse = CD_R(1.0) / scale;
	cd3Vec d = cd3Scale(inverse, direction);
	cdReal numerator = cd3Dot(cd3Scale(inverse, offset), d);
	cdReal denominator = cd3Dot(d, d);
	if (numerator <= CD_R(0.0) || !(denominator > CD_R(0.0)))
	{
		return g.p1;
	}
	if (numerator >= denominator)
	{
		return g.p2;
	}
	return cd3MulAdd(g.p1, numerator / denominator, direction);
}

cd3Vec cd3ClosestPointOnCapsule(cd3Capsule c, cd3Vec p)
{
	cd3Segment axis = {c.p1, c.p2};
	cd3Sphere sphere = {cd3ClosestPointOnSegment(axis, p), c.radius};
	return cd3ClosestPointOnSphere(sphere, p);
}

cd3Vec cd3ClosestPointOnAabb(cd3Aabb b, cd3Vec p)
{
	return cd3Clamp(p, b.min, b.max);
}

cd3Vec cd3ClosestPointOnBox(cd3Box b, cd3Vec p)
{
	cd3Quat q = cd3NormalizeQuat(b.rotation);
	cd3Vec local = cd3InvRotateVector(q, cd3Sub(p, b.center));
	cd3Vec h = b.halfExtents;
	cd3Vec clamped = cd3Clamp(local, cd3Neg(h), h);
	if (cd3VecEqual(clamped, local))
	{
		/* Inside: the point itself, not its rotated round trip. */
		return p;
	}
	return cd3Add(b.center, cd3RotateVector(q, clamped));
}

cd3Vec cd3ClosestPointOnPlane(cd3Plane plane, cd3Vec p)
{
	cdReal height = cd3Dot(plane.normal, p) - plane.offset;
	if (height <= CD_R(0.0))
	{
		return p;
	}
	/* Divide by |n|^2 so that a normal within the validator's unit tolerance still lands on the
	 * boundary. */
	cdReal normalSquared = cd3LengthSquared(plane.normal);
	if (!(normalSquared > CD_R(0.0)))
	{
		return p;
	}
	return cd3MulSub(p, height / normalSquared, plane.normal);
}

/* The triangle query runs in double even when cdReal is float (wide3.h). A thin triangle's
 * normal carries a relative error of epsilon / sin(smallest angle), which in float spoils the
 * closest point of valid slivers by far more than the tolerance of the queries built on it; the
 * products of float inputs are exact in double, so the float build gets the answer to nearly
 * float precision. */
static double WideClampedRatio(double numerator, double denominator)
{
	if (!(denominator > 0.0) || numerator <= 0.0)
	{
		return 0.0;
	}
	return numerator >= denominator ? 1.0 : numerator / denominator;
}

/* Closest point of segment a-b to p, all relative to the same origin. */
static WideVec WideClosestOnSegment(WideVec a, WideVec b, WideVec p)
{
	WideVec d = WideSub(b, a);
	return WideMulAdd(a, WideClampedRatio(WideDot(WideSub(p, a), d), WideDot(d, d)), d);
}

/* Nearest of the three edges: what a degenerate triangle is. Relative to vertex a. */
static cd3Vec ClosestPointOnTriangleEdges(cd3Vec origin, WideVec b, WideVec c, WideVec p)
{
	WideVec zero = {0.0, 0.0, 0.0};
	WideVec candidates[3] = {WideClosestOnSegment(zero, b, p), WideClosestOnSegment(b, c, p),
							 WideClosestOnSegment(c, zero, p)};
	int best = 0;
	double bestDistance = WideDot(WideSub(candidates[0], p), WideSub(candidates[0], p));
	for (int i = 1; i < 3; ++i)
	{
		double distance = WideDot(WideSub(candidates[i], p), WideSub(candidates[i], p));
		if (distance < bestDistance)
		{
			bestDistance = distance;
			best = i;
		}
	}
	return Narrow(WideMulAdd(Widen(origin), 1.0, candidates[best]));
}

/* Voronoi regions of the vertices, then the edges, then the face (Ericson 5.1.5). */
cd3Vec cd3ClosestPointOnTriangle(cd3Triangle t, cd3Vec p)
{
	WideVec origin = Widen(t.a);
	WideVec ab = WideSub(Widen(t.b), origin);
	WideVec ac = WideSub(Widen(t.c), origin);
	WideVec ap = WideSub(Widen(p), origin);
	/* Scaled so that the products below neither overflow nor underflow. */
	double scale = WideMaxAbs(ab);
	scale = WideMaxAbs(ac) > scale ? WideMaxAbs(ac) : scale;
	scale = WideMaxAbs(ap) > scale ? WideMaxAbs(ap) : scale;
	if (!(scale > 0.0))
	{
		return t.a;
	}
	double inverse = 1.0 / scale;
	WideVec sab = WideScale(inverse, ab);
	WideVec sac = WideScale(inverse, ac);
	WideVec sap = WideScale(inverse, ap);

	/* A (nearly) zero-area triangle has no face region, and its edge regions can be empty: it is
	 * the segment or point it collapsed to. Same threshold as cd3IsValidTriangle. */
	WideVec normal = WideTriangleNormal(sab, sac, WideScale(inverse, WideSub(Widen(t.c), Widen(t.b))));
	double normalSquared = WideDot(normal, normal);
	double limit = 4.0 * (double)CD_REAL_EPSILON;
	if (normalSquared <= limit * limit * WideDot(sab, sab) * WideDot(sac, sac))
	{
		return ClosestPointOnTriangleEdges(t.a, ab, ac, ap);
	}

	/* The quantities below come from the edges ab, ac and the one offset ap (those along bc
	 * from bc, bp and cp taken from the inputs): bp = ap - ab and cp = ap - ac, formed as
	 * rounded vectors, lose the short edge of a needle entirely when p is far from it
	 * (bp == ap), which made the point at vertex c of a needle fall into the region of its short
	 * edge ab. Ericson's d3 and d6 are the same dot products expanded (ab.bp = ab.ap - ab.ab,
	 * ac.cp = ac.ap - ac.ac), and the weights of c and b are n.(ap x bp) = n.(ab x ap) and
	 * n.(cp x ap) = n.(ap x ac). */
	double d1 = WideDot(sab, sap);
	double d2 = WideDot(sac, sap);
	if (d1 <= 0.0 && d2 <= 0.0)
	{
		return t.a;
	}

	/* Along the edge bc, from the inputs relative to b and c: Ericson's d4 - d3 = bc.bp and
	 * d5 - d6 = -bc.cp. As differences of the large d's they vanish in round-off on a needle
	 * whose short edge is bc (p past b along the long edges made d4 <= d3 by rounding, and the
	 * face point 1e7 away came back as vertex b, 1.1e8 away, in the double build). */
	WideVec sbc = WideScale(inverse, WideSub(Widen(t.c), Widen(t.b)));
	WideVec sbp = WideScale(inverse, WideSub(Widen(p), Widen(t.b)));
	WideVec scp = WideScale(inverse, WideSub(Widen(p), Widen(t.c)));
	double fromB = WideDot(sbc, sbp);
	double towardC = WideDot(sbc, scp);

	/* Ericson's d3 = ab.bp and d6 = ac.cp from bp and cp taken from the inputs, each within
	 * epsilon of |ab| |bp| (|ac| |cp|). As d1 - ab.ab (d2 - ac.ac), differences of two products of
	 * the long edge with itself and with ap, their sign was round-off for a point near b on a
	 * sliver 2e30 long and 2e21 wide (double): a point on the long edge ac came back as vertex b,
	 * 1.05e21 away. The segment ratios divide by the squared edge lengths, exact to epsilon. */
	double abab = WideDot(sab, sab), acac = WideDot(sac, sac);
	double d3 = WideDot(sab, sbp);
	if (d3 >= 0.0 && fromB <= 0.0)
	{
		return t.b;
	}

	/* The barycentric weights va, vb, vc are Ericson's d3*d6 - d5*d4 and so on, written by the
	 * Lagrange identity as n . (bp x cp) etc.: the cross products keep the relative error at
	 * epsilon / sin(angle) instead of epsilon / sin^2 on thin triangles. */
	double vc = WideDot(normal, WideCross(sab, sap));
	if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
	{
		return Narrow(WideMulAdd(origin, WideClampedRatio(d1, abab), ab));
	}

	double d6 = WideDot(sac, scp);
	if (d6 >= 0.0 && towardC >= 0.0)
	{
		return t.c;
	}

	double vb = WideDot(normal, WideCross(sap, sac));
	if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
	{
		return Narrow(WideMulAdd(origin, WideClampedRatio(d2, acac), ac));
	}

	double va = WideDot(normal, WideCross(sbc, sbp));
	if (va <= 0.0 && fromB >= 0.0 && towardC <= 0.0)
	{
		WideVec b = Widen(t.b);
		return Narrow(WideMulAdd(b, WideClampedRatio(fromB, fromB - towardC), WideSub(Widen(t.c), b)));
	}

	if (va > 0.0 && vb > 0.0 && vc > 0.0)
	{
		/* Project p onto the plane rather than rebuilding the point from its barycentric
		 * coordinates: for p near the triangle the error then stays at epsilon times |ap|. */
		double height = WideDot(normal, sap) / normalSquared;
		return Narrow(WideMulAdd(Widen(p), -height * scale, normal));
	}

	/* Round-off on a nearly degenerate triangle can leave no region: fall back to the edges. */
	return ClosestPointOnTriangleEdges(t.a, ab, ac, ap);
}

/* Shapes that meet report distance 0 and one common point (query3.h). Crossing segments only
 * meet within round-off, so a gap below the overlap tests' tolerance (16 epsilon relative to the
 * pair's extent, see overlap3.c) counts as meeting. */
static void SnapTouching(cd3ClosestPoints* pair, cdReal magnitude)
{
	if (pair->distance <= CD_R(16.0) * CD_REAL_EPSILON * magnitude)
	{
		pair->pointB = pair->pointA;
		pair->distance = CD_R(0.0);
	}
}

cd3ClosestPoints cd3ClosestPointsSegmentSegment(cd3Segment a, cd3Segment b)
{
	cd3Vec d1 = cd3Sub(a.p2, a.p1);
	cd3Vec d2 = cd3Sub(b.p2, b.p1);
	cd3Vec r = cd3Sub(a.p1, b.p1);
	cd3ClosestPoints result;
	cdReal scale = cdMax(MaxAbsComponent(d1), cdMax(MaxAbsComponent(d2), MaxAbsComponent(r)));
	if (!(scale > CD_R(0.0)))
	{
		result.pointA = a.p1;
		result.pointB = b.p1;
		result.distance = CD_R(0.0);
		return result;
	}
	cdReal inverse = CD_R(1.0) / scale;
	cd3Vec u = cd3Scale(inverse, d1);
	cd3Vec v = cd3Scale(inverse, d2);
	cd3Vec w = cd3Scale(inverse, r);

	/* Scaled so that the largest component is 1: a squared length below epsilon^2 is a point at
	 * this precision. */
	const cdReal tiny = CD_REAL_EPSILON * CD_REAL_EPSILON;
	cdReal lengthA = cd3Dot(u, u);
	cdReal lengthB = cd3Dot(v, v);
	cdReal f = cd3Dot(v, w);
	cdReal s, t;
	if (lengthA <= tiny && lengthB <= tiny)
	{
		s = CD_R(0.0);
		t = CD_R(0.0);
	}
	else if (lengthA <= tiny)
	{
		s = CD_R(0.0);
		t = ClampedRatio(f, lengthB);
	}
	else
	{
		cdReal c = cd3Dot(u, w);
		if (lengthB <= tiny)
		{
			t = CD_R(0.0);
			s = ClampedRatio(-c, lengthA);
		}
		else
		{
			cdReal bb = cd3Dot(u, v);
			/* denominator = |u x v|^2 and numerator = (u x v).(v x w) are the Lagrange-identity
			 * forms of Ericson's a*e - b*b and b*f - c*e: the cross products avoid the
			 * cancellation that makes nearly parallel segments lose half their digits. */
			cd3Vec n = cd3Cross(u, v);
			cdReal denominator = cd3Dot(n, n);
			cdReal parallelLimit = CD_R(16.0) * CD_REAL_EPSILON * CD_REAL_EPSILON * lengthA * lengthB;
			if (denominator > parallelLimit)
			{
				s = ClampedRatio(cd3Dot(n, cd3Cross(v, w)), denominator);
			}
			else
			{
				/* Parallel: every s on the overlap is as good; start from s = 0 and let the
				 * clamping below pick the right pair. */
				s = CD_R(0.0);
			}
			cdReal tNumerator = bb * s + f;
			if (tNumerator <= CD_R(0.0))
			{
				t = CD_R(0.0);
				s = ClampedRatio(-c, lengthA);
			}
			else if (tNumerator >= lengthB)
			{
				t = CD_R(1.0);
				s = ClampedRatio(bb - c, lengthA);
			}
			else
			{
				t = tNumerator / lengthB;
			}
		}
	}
	result.pointA = cd3MulAdd(a.p1, s, d1);
	result.pointB = cd3MulAdd(b.p1, t, d2);
	result.distance = cd3VecDistance(result.pointA, result.pointB);
	SnapTouching(&result, scale);
	return result;
}

static void KeepCloser(cd3ClosestPoints* best, cdReal* bestDistanceSquared, cd3Vec onTriangle,
					   cd3Vec onSegment)
{
	cdReal distanceSquared = cd3VecDistanceSquared(onTriangle, onSegment);
	if (distanceSquared < *bestDistanceSquared)
	{
		*bestDistanceSquared = distanceSquared;
		best->pointA = onTriangle;
		best->pointB = onSegment;
	}
}

/* The closest pair is either where the segment pierces the triangle, or involves a segment
 * endpoint against the triangle, or a triangle edge against the segment. */
cd3ClosestPoints cd3ClosestPointsTriangleSegment(cd3Triangle t, cd3Segment g)
{
	cd3ClosestPoints best;
	best.pointA = t.a;
	best.pointB = g.p1;
	cdReal bestDistanceSquared = CD_REAL_MAX;

	/* Piercing point: where the segment crosses the triangle's plane, in double (wide3.h) with
	 * the face normal from the two shorter edges. From a float normal of a sliver (relative
	 * error epsilon / sin(angle)) the crossing landed 3e-5 off the plane of a triangle it pierced
	 * well inside, beyond the touching tolerance. The normal is left unnormalized; only the signs
	 * and the ratio of the heights matter. */
	cd3Vec ab = cd3Sub(t.b, t.a);
	cd3Vec ac = cd3Sub(t.c, t.a);
	cdReal scale = cdMax(MaxAbsComponent(ab), MaxAbsComponent(ac));
	if (scale > CD_R(0.0))
	{
		double inverse = 1.0 / (double)scale;
		WideVec a = Widen(t.a);
		WideVec n = WideTriangleNormal(WideScale(inverse, WideSub(Widen(t.b), a)),
									   WideScale(inverse, WideSub(Widen(t.c), a)),
									   WideScale(inverse, WideSub(Widen(t.c), Widen(t.b))));
		WideVec p1 = Widen(g.p1), p2 = Widen(g.p2);
		double h1 = WideDot(n, WideSub(p1, a));
		double h2 = WideDot(n, WideSub(p2, a));
		if ((h1 <= 0.0 && h2 >= 0.0) || (h1 >= 0.0 && h2 <= 0.0))
		{
			double difference = h1 - h2;
			if (difference != 0.0)
			{
				double fraction = h1 / difference;
				fraction = fraction < 0.0 ? 0.0 : (fraction > 1.0 ? 1.0 : fraction);
				cd3Vec crossing = Narrow(WideMulAdd(p1, fraction, WideSub(p2, p1)));
				KeepCloser(&best, &bestDistanceSquared, cd3ClosestPointOnTriangle(t, crossing), crossing);
			}
		}
	}

	KeepCloser(&best, &bestDistanceSquared, cd3ClosestPointOnTriangle(t, g.p1), g.p1);
	KeepCloser(&best, &bestDistanceSquared, cd3ClosestPointOnTriangle(t, g.p2), g.p2);

	cd3Segment edges[3] = {{t.a, t.b}, {t.b, t.c}, {t.c, t.a}};
	for (int i = 0; i < 3; ++i)
	{
		cd3ClosestPoints pair = cd3ClosestPointsSegmentSegment(edges[i], g);
		KeepCloser(&best, &bestDistanceSquared, pair.pointA, pair.pointB);
	}
	best.distance = cd3VecDistance(best.pointA, best.pointB);
	cdReal magnitude =
		cdMax(scale, cdMax(MaxAbsComponent(cd3Sub(g.p1, t.a)), MaxAbsComponent(cd3Sub(g.p2, t.a))));
	SnapTouching(&best, magnitude);
	return best;
}

/* ---- hulls ----------------------------------------------------------------------------------- */

/* Each plane's offset was rounded once and the test rounds again: 16 epsilons of the magnitudes
 * compared, as in the other rotated tests (docs/API.md). */
#define CD_HULL_PLANE_TOLERANCE (CD_R(16.0) * CD_REAL_EPSILON)

bool cd3PointInHull(cd3Vec p, cd3HullShape shape)
{
	CD_ASSERT(shape.hull != NULL);
	const cd3Hull* hull = shape.hull;
	cd3Vec local = cd3InvTransformPoint(shape.transform, p);
	cdReal magnitude = cdMax(cdAbs(local.x), cdMax(cdAbs(local.y), cdAbs(local.z)));
	cdReal largestOffset = CD_R(0.0);
	bool withinTolerance = false;
	for (int i = 0; i < hull->faceCount; ++i)
	{
		cd3Plane plane = hull->planes[i];
		cdReal tolerance = CD_HULL_PLANE_TOLERANCE * (cdAbs(plane.offset) + magnitude);
		cdReal height = cd3Dot(plane.normal, local) - plane.offset;
		if (height > tolerance)
		{
			return false;
		}
		withinTolerance = withinTolerance || height > -tolerance;
		largestOffset = cdMax(largestOffset, cdAbs(plane.offset));
	}
	if (!withinTolerance)
	{
		return true;
	}
	/* Within the tolerance of some face (on either side: the heights themselves carry that
	 * round-off). Near an edge where two faces meet at a small angle (a sliver), a height that
	 * small can still be far from the hull: 198 above both faces of a 1e-4 rad wedge is 1.8e6
	 * beyond its edge, and 22 above a 5e-6 rad one 4.2e6. The distance decides, with the same
	 * tolerance, widened by the distance's own round-off: GJK's simplex across a hull thinner
	 * than that band (a sheet a few dozen epsilons thick, whose centroid lies 1.5e-8 below both
	 * faces in a float case of fuzz_hull3) reports a distance of about 16 epsilons for a point
	 * inside. */
	cd3Shape hullShape;
	hullShape.type = CD3_SHAPE_HULL;
	hullShape.hull = shape;
	cd3Shape point = cd3MakeSphereShape((cd3Sphere){p, CD_R(0.0)});
	cdReal distance = cd3Distance(&hullShape, &point).distance;
	return distance <= CD_R(4.0) * CD_HULL_PLANE_TOLERANCE * (largestOffset + magnitude);
}

cd3Vec cd3ClosestPointOnHull(cd3HullShape shape, cd3Vec p)
{
	if (cd3PointInHull(p, shape))
	{
		return p;
	}
	cd3Shape hull;
	hull.type = CD3_SHAPE_HULL;
	hull.hull = shape;
	cd3Shape point;
	point.type = CD3_SHAPE_SPHERE;
	point.sphere.center = p;
	point.sphere.radius = CD_R(0.0);
	return cd3Distance(&hull, &point).pointA;
}
