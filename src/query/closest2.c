/* collide: closest point on a 2D shape to a point, and closest points between two segments.
 * A point inside a solid shape is its own closest point. */
#include "collide/query2.h"

#include "support2.h"

cd2Vec cd2ClosestPointOnSegment(cd2Segment g, cd2Vec p)
{
	cd2Vec d = cd2Sub(g.p2, g.p1);
	cdReal lengthSquared = cd2Dot(d, d);
	cdReal t = cd2Dot(cd2Sub(p, g.p1), d);
	/* The clamps come first so that a zero-length (or underflowing) segment never divides by 0. */
	if (t <= CD_R(0.0) || lengthSquared <= CD_R(0.0))
	{
		return g.p1;
	}
	if (t >= lengthSquared)
	{
		return g.p2;
	}
	return cd2MulAdd(g.p1, t / lengthSquared, d);
}

/* The point at `radius` from `center` towards p, or p itself when it lies within the radius. */
static cd2Vec ClosestPointOnDisk(cd2Vec center, cdReal radius, cd2Vec p)
{
	cd2Vec d = cd2Sub(p, center);
	cdReal distanceSquared = cd2Dot(d, d);
	if (distanceSquared <= radius * radius)
	{
		return p;
	}
	/* distance > radius >= 0, so the ratio is finite and below 1. */
	cdReal distance = cdSqrt(distanceSquared);
	return cd2MulAdd(center, radius / distance, d);
}

cd2Vec cd2ClosestPointOnCircle(cd2Circle c, cd2Vec p)
{
	return ClosestPointOnDisk(c.center, c.radius, p);
}

cd2Vec cd2ClosestPointOnCapsule(cd2Capsule c, cd2Vec p)
{
	cd2Segment core = {c.p1, c.p2};
	return ClosestPointOnDisk(cd2ClosestPointOnSegment(core, p), c.radius, p);
}

cd2Vec cd2ClosestPointOnAabb(cd2Aabb b, cd2Vec p)
{
	return cd2Clamp(p, b.min, b.max);
}

cd2Vec cd2ClosestPointOnBox(cd2Box b, cd2Vec p)
{
	cd2Rot q = cd2NormalizeRot(b.rotation);
	cd2Vec local = cd2InvRotateVector(q, cd2Sub(p, b.center));
	if (cdAbs(local.x) <= b.halfExtents.x && cdAbs(local.y) <= b.halfExtents.y)
	{
		return p;
	}
	cd2Vec clamped = cd2Clamp(local, cd2Neg(b.halfExtents), b.halfExtents);
	return cd2Add(b.center, cd2RotateVector(q, clamped));
}

cd2Vec cd2ClosestPointOnPolygon(const cd2Polygon* polygon, cd2Vec p)
{
	CD_ASSERT(polygon != NULL && polygon->count >= 1);
	cdReal distanceSquared, offsetScale;
	cd2Vec core = cd2ClosestPointOnCore(polygon, p, &distanceSquared, &offsetScale);
	cdReal radius = polygon->radius;
	if (radius <= CD_R(0.0))
	{
		return core;
	}
	/* The core distance computed from the nearest edge's nearer end decides: recomputed from the
	 * core point's coordinates it carries their round-off. */
	return distanceSquared <= radius * radius ? p : ClosestPointOnDisk(core, radius, p);
}

/* Closest points between two 2D segments: either they cross (distance 0 at the crossing) or one of
 * the four endpoints is part of a closest pair. Orientation signs pick the crossing case, which
 * avoids the division by the near-zero determinant of parallel segments; zero-length segments need
 * no special case. Round-off can make nearly collinear segments look crossing, so the computed
 * crossing counts only when it lies on both segments within round-off (16 * CD_REAL_EPSILON of the
 * largest coordinate); otherwise it is one more candidate pair, and the nearest candidate wins.
 * Every candidate is a true pair of points on a and b. */
cd2ClosestPoints cd2ClosestPointsSegmentSegment(cd2Segment a, cd2Segment b)
{
	cd2Vec da = cd2Sub(a.p2, a.p1);
	cd2Vec db = cd2Sub(b.p2, b.p1);
	cdReal b1Side = cd2Cross(da, cd2Sub(b.p1, a.p1));
	cdReal b2Side = cd2Cross(da, cd2Sub(b.p2, a.p1));
	cdReal a1Side = cd2Cross(db, cd2Sub(a.p1, b.p1));
	cdReal a2Side = cd2Cross(db, cd2Sub(a.p2, b.p1));
	bool bStraddles =
		(b1Side > CD_R(0.0) && b2Side < CD_R(0.0)) || (b1Side < CD_R(0.0) && b2Side > CD_R(0.0));
	bool aStraddles =
		(a1Side > CD_R(0.0) && a2Side < CD_R(0.0)) || (a1Side < CD_R(0.0) && a2Side > CD_R(0.0));

	cd2Vec candidatesA[5] = {a.p1, a.p2, cd2ClosestPointOnSegment(a, b.p1),
							 cd2ClosestPointOnSegment(a, b.p2)};
	cd2Vec candidatesB[5] = {cd2ClosestPointOnSegment(b, a.p1), cd2ClosestPointOnSegment(b, a.p2), b.p1,
							 b.p2};
	int candidateCount = 4;
	cd2ClosestPoints result;
	if (aStraddles && bStraddles)
	{
		/* a1Side and a2Side have opposite signs: the fraction lies inside [0, 1]. */
		cdReal t = cdClamp(a1Side / (a1Side - a2Side), CD_R(0.0), CD_R(1.0));
		cd2Vec crossing = cd2MulAdd(a.p1, t, da);
		cd2Vec onB = cd2ClosestPointOnSegment(b, crossing);
		cdReal scale = cdMax(cdMax(cdMax(cdAbs(a.p1.x), cdAbs(a.p1.y)), cdMax(cdAbs(a.p2.x), cdAbs(a.p2.y))),
							 cdMax(cdMax(cdAbs(b.p1.x), cdAbs(b.p1.y)), cdMax(cdAbs(b.p2.x), cdAbs(b.p2.y))));
		cdReal tolerance = CD_R(16.0) * CD_REAL_EPSILON * scale;
		if (cd2VecDistanceSquared(crossing, onB) <= tolerance * tolerance)
		{
			result.pointA = crossing;
			result.pointB = crossing;
			result.distance = CD_R(0.0);
			return result;
		}
		candidatesA[4] = crossing;
		candidatesB[4] = onB;
		candidateCount = 5;
	}

	int best = 0;
	cdReal bestDistanceSquared = cd2VecDistanceSquared(candidatesA[0], candidatesB[0]);
	for (int i = 1; i < candidateCount; ++i)
	{
		cdReal distanceSquared = cd2VecDistanceSquared(candidatesA[i], candidatesB[i]);
		if (distanceSquared < bestDistanceSquared)
		{
			best = i;
			bestDistanceSquared = distanceSquared;
		}
	}
	result.pointA = candidatesA[best];
	result.pointB = candidatesB[best];
	result.distance = cdSqrt(bestDistanceSquared);
	return result;
}
