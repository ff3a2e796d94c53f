/* collide: 2D point containment and overlap tests between every pair of primitive shapes.
 *
 * Shapes are closed, so touching counts as overlapping. AabbAabb, CircleCircle, CircleAabb and the
 * point tests on AABBs and circles are exact comparisons (squared distances, no square root). Every
 * other test involves a rotation, a projection or a square root, and accepts touching within
 * round-off: a gap of up to OverlapTolerance(scale) = 8 * CD_REAL_EPSILON * scale still counts as
 * overlap, where scale is the largest magnitude among the coordinates and radii compared.
 *
 * Box, AABB, polygon and segment pairs use the separating axis test on their vertex sets; pairs
 * with a circle or a capsule compare the distance to the core point or segment with the radius. */
#include "collide/query2.h"

#include "support2.h"

#include <string.h>

static cdReal OverlapTolerance(cdReal scale)
{
	return CD_R(8.0) * CD_REAL_EPSILON * scale;
}

static cdReal MaxAbs(cd2Vec v)
{
	return cdMax(cdAbs(v.x), cdAbs(v.y));
}

/* distance <= radius + tolerance, on squared values. */
static bool WithinRadius(cdReal distanceSquared, cdReal radius, cdReal scale)
{
	cdReal limit = radius + OverlapTolerance(scale);
	return distanceSquared <= limit * limit;
}

/* Pairs of the same type are put in one order (by their bytes) before computing, so that the
 * answer is exactly the same for (a, b) and (b, a) (docs/API.md): the separating axis test and the
 * segment distance are not symmetric in their round-off (projections are taken relative to a point
 * of the first shape), and near touching that decided the answer. Circle and AABB pairs are
 * symmetric as written. */
static bool ShouldSwap(const void* a, const void* b, size_t size)
{
	return memcmp(a, b, size) > 0;
}

/* ---- convex vertex sets for the separating axis test ------------------------------------------ */

/* A convex polygon, possibly degenerate (a segment or a point), with the axes that, together with
 * the other shape's, are enough to separate it from any convex polygon it does not touch: the edge
 * normals for a polygon, both local axes for a box or AABB (which also covers zero-size ones), and
 * the normal and direction of a segment. A zero-length segment has no axis of its own. */
typedef struct ConvexSet
{
	cd2Vec points[CD2_MAX_POLYGON_VERTICES];
	cd2Vec axes[CD2_MAX_POLYGON_VERTICES];
	int count;
	int axisCount;
	cdReal scale;
	cdReal radius; /* the set grown by this radius: a rounded polygon, a capsule */
} ConvexSet;

static void UpdateScale(ConvexSet* set)
{
	set->radius = CD_R(0.0);
	set->scale = CD_R(0.0);
	for (int i = 0; i < set->count; ++i)
	{
		set->scale = cdMax(set->scale, MaxAbs(set->points[i]));
	}
}

static ConvexSet MakeAabbSet(cd2Aabb b)
{
	ConvexSet set;
	set.count = 4;
	set.points[0] = b.min;
	set.points[1] = cd2MakeVec(b.max.x, b.min.y);
	set.points[2] = b.max;
	set.points[3] = cd2MakeVec(b.min.x, b.max.y);
	set.axisCount = 2;
	set.axes[0] = cd2MakeVec(CD_R(1.0), CD_R(0.0));
	set.axes[1] = cd2MakeVec(CD_R(0.0), CD_R(1.0));
	UpdateScale(&set);
	return set;
}

static ConvexSet MakeBoxSet(cd2Box b)
{
	ConvexSet set;
	cd2Rot q = cd2NormalizeRot(b.rotation);
	cd2Vec axisX = cd2MakeVec(q.c, q.s);
	cd2Vec axisY = cd2MakeVec(-q.s, q.c);
	cd2Vec ex = cd2Scale(b.halfExtents.x, axisX);
	cd2Vec ey = cd2Scale(b.halfExtents.y, axisY);
	set.count = 4;
	set.points[0] = cd2Sub(cd2Sub(b.center, ex), ey);
	set.points[1] = cd2Sub(cd2Add(b.center, ex), ey);
	set.points[2] = cd2Add(cd2Add(b.center, ex), ey);
	set.points[3] = cd2Add(cd2Sub(b.center, ex), ey);
	set.axisCount = 2;
	set.axes[0] = axisX;
	set.axes[1] = axisY;
	UpdateScale(&set);
	return set;
}

static ConvexSet MakePolygonSet(const cd2Polygon* polygon)
{
	CD_ASSERT(polygon != NULL && polygon->count >= 1 && polygon->count <= CD2_MAX_POLYGON_VERTICES);
	ConvexSet set;
	set.count = polygon->count;
	set.axisCount = polygon->count;
	for (int i = 0; i < polygon->count; ++i)
	{
		set.points[i] = polygon->vertices[i];
		set.axes[i] = polygon->normals[i];
	}
	UpdateScale(&set);
	set.radius = polygon->radius;
	set.scale = cdMax(set.scale, set.radius);
	return set;
}

static ConvexSet MakeSegmentSet(cd2Segment g)
{
	ConvexSet set;
	set.count = 2;
	set.points[0] = g.p1;
	set.points[1] = g.p2;
	cd2Vec direction = cd2Normalize(cd2Sub(g.p2, g.p1));
	set.axisCount = 0;
	if (!cd2VecEqual(direction, CD2_VEC_ZERO))
	{
		set.axisCount = 2;
		set.axes[0] = direction;
		set.axes[1] = cd2LeftPerp(direction);
	}
	UpdateScale(&set);
	return set;
}

/* The gap between the projections of the two sets on the axis (negative when they overlap).
 * Projections are taken relative to a point of `a`, which keeps them small (and their round-off
 * small) for shapes far from the origin. */
static cdReal GapOnAxis(const ConvexSet* a, const ConvexSet* b, cd2Vec axis)
{
	cd2Vec origin = a->points[0];
	cdReal minA = CD_R(0.0), maxA = CD_R(0.0);
	for (int i = 1; i < a->count; ++i)
	{
		cdReal projection = cd2Dot(axis, cd2Sub(a->points[i], origin));
		minA = cdMin(minA, projection);
		maxA = cdMax(maxA, projection);
	}
	cdReal minB = CD_REAL_MAX, maxB = -CD_REAL_MAX;
	for (int i = 0; i < b->count; ++i)
	{
		cdReal projection = cd2Dot(axis, cd2Sub(b->points[i], origin));
		minB = cdMin(minB, projection);
		maxB = cdMax(maxB, projection);
	}
	return cdMax(minB - maxA, minA - maxB);
}

/* Whether the two sets, each grown by its radius, meet. The separating axis test decides for the
 * cores; cores apart by less than the radii are then compared by their true distance: the closest
 * pair of two disjoint convex polygons in the plane includes a vertex of one of them, so that
 * distance is the smallest between the boundary edges of one and of the other. */
static bool OverlapSets(const ConvexSet* a, const ConvexSet* b)
{
	cdReal radius = a->radius + b->radius;
	cdReal tolerance = OverlapTolerance(cdMax(a->scale, b->scale));
	cdReal largestGap = -CD_REAL_MAX;
	for (int i = 0; i < a->axisCount; ++i)
	{
		largestGap = cdMax(largestGap, GapOnAxis(a, b, a->axes[i]));
	}
	for (int i = 0; i < b->axisCount; ++i)
	{
		largestGap = cdMax(largestGap, GapOnAxis(a, b, b->axes[i]));
	}
	if (largestGap <= tolerance)
	{
		return true;
	}
	if (largestGap > radius + tolerance)
	{
		return false;
	}
	cdReal best = CD_REAL_MAX;
	for (int i = 0; i < a->count; ++i)
	{
		cd2Segment edgeA = {a->points[i], a->points[i + 1 < a->count ? i + 1 : 0]};
		for (int j = 0; j < b->count; ++j)
		{
			cd2Segment edgeB = {b->points[j], b->points[j + 1 < b->count ? j + 1 : 0]};
			best = cdMin(best, cd2ClosestPointsSegmentSegment(edgeA, edgeB).distance);
		}
	}
	return best <= radius + tolerance;
}

/* Whether the segment inflated by radius (a capsule) meets the convex set. */
static bool OverlapCapsuleSet(cd2Segment core, cdReal radius, const ConvexSet* set)
{
	ConvexSet segmentSet = MakeSegmentSet(core);
	segmentSet.radius = radius;
	segmentSet.scale = cdMax(segmentSet.scale, radius);
	return OverlapSets(&segmentSet, set);
}

/* ---- the source texts' tests ------------------------------------------------------------------ */

bool cd2PointInAabb(cd2Vec p, cd2Aabb b)
{
	return b.min.x <= p.x && p.x <= b.max.x && b.min.y <= p.y && p.y <= b.max.y;
}

bool cd2OverlapAabbAabb(cd2Aabb a, cd2Aabb b)
{
	return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y;
}

bool cd2OverlapCircleCircle(cd2Circle a, cd2Circle b)
{
	cdReal radiusSum = a.radius + b.radius;
	return cd2VecDistanceSquared(a.center, b.center) <= radiusSum * radiusSum;
}

bool cd2OverlapPolygonPolygon(const cd2Polygon* a, const cd2Polygon* b)
{
	if (ShouldSwap(a, b, sizeof(cd2Polygon)))
	{
		const cd2Polygon* swapped = a;
		a = b;
		b = swapped;
	}
	ConvexSet setA = MakePolygonSet(a);
	ConvexSet setB = MakePolygonSet(b);
	return OverlapSets(&setA, &setB);
}

/* ---- point containment ----------------------------------------------------------------------- */

bool cd2PointInCircle(cd2Vec p, cd2Circle c)
{
	return cd2VecDistanceSquared(p, c.center) <= c.radius * c.radius;
}

bool cd2PointInCapsule(cd2Vec p, cd2Capsule c)
{
	cd2Segment core = {c.p1, c.p2};
	cd2Vec closest = cd2ClosestPointOnSegment(core, p);
	cdReal scale = cdMax(cdMax(MaxAbs(p), c.radius), cdMax(MaxAbs(c.p1), MaxAbs(c.p2)));
	return WithinRadius(cd2VecDistanceSquared(p, closest), c.radius, scale);
}

bool cd2PointInBox(cd2Vec p, cd2Box b)
{
	cd2Vec local = cd2InvRotateVector(cd2NormalizeRot(b.rotation), cd2Sub(p, b.center));
	cdReal tolerance = OverlapTolerance(cdMax(cdMax(MaxAbs(p), MaxAbs(b.center)), MaxAbs(b.halfExtents)));
	return cdAbs(local.x) <= b.halfExtents.x + tolerance && cdAbs(local.y) <= b.halfExtents.y + tolerance;
}

/* Containment in a sharp (radius 0) polygon. Each edge's half-plane is tested from the edge's end
 * point nearer to p with a tolerance relative to p's offset from it (the magnitude compared: the
 * round-off of the normal and of the offset is of that order), never to the largest coordinate.
 * An absolute tolerance gets out of hand at a sharp vertex: there a point far beyond the vertex
 * stays within it of both edge lines (a sliver polygon 1e9 long, angle 8e-5, took in a point
 * 157500 beyond its tip). A point within round-off of an edge line is either near the boundary
 * (inside or touching) or beyond the end of that edge, so its distance to the polygon decides:
 * an inside point lies no farther from the boundary than from that line. */
bool cd2PointInPolygon(cd2Vec p, const cd2Polygon* polygon)
{
	CD_ASSERT(polygon != NULL);
	if (polygon->radius > CD_R(0.0))
	{
		/* Within the radius of the core, up to the round-off of the core distance (relative to p's
		 * offset from the nearest edge's nearer end) and of the radius. */
		cdReal distanceSquared, offsetScale;
		cd2ClosestPointOnCore(polygon, p, &distanceSquared, &offsetScale);
		return WithinRadius(distanceSquared, polygon->radius, cdMax(offsetScale, polygon->radius));
	}
	int count = polygon->count;
	bool nearEdgeLine = false;
	cdReal nearTolerance = CD_REAL_MAX;
	for (int i = 0; i < count; ++i)
	{
		cd2Vec offset = cd2Sub(p, polygon->vertices[i]);
		cd2Vec offsetFromEnd = cd2Sub(p, polygon->vertices[i + 1 < count ? i + 1 : 0]);
		cdReal scale = MaxAbs(offset), scaleFromEnd = MaxAbs(offsetFromEnd);
		if (scaleFromEnd < scale)
		{
			offset = offsetFromEnd;
			scale = scaleFromEnd;
		}
		cdReal tolerance = OverlapTolerance(scale);
		cdReal separation = cd2Dot(polygon->normals[i], offset);
		if (separation > tolerance)
		{
			return false;
		}
		if (separation > -tolerance)
		{
			nearEdgeLine = true;
			nearTolerance = cdMin(nearTolerance, tolerance);
		}
	}
	if (!nearEdgeLine)
	{
		return true;
	}
	/* Inside, p would be within the tolerance of that line, plus the line test's own round-off
	 * (below the tolerance). */
	cdReal limit = CD_R(2.0) * nearTolerance;
	for (int i = 0; i < count; ++i)
	{
		cd2Vec closest;
		cdReal scale;
		if (cd2EdgeDistanceSquared(polygon->vertices[i], polygon->vertices[i + 1 < count ? i + 1 : 0], p,
								   &closest, &scale) <= limit * limit)
		{
			return true;
		}
	}
	return false;
}

/* ---- circle pairs ---------------------------------------------------------------------------- */

bool cd2OverlapCircleCapsule(cd2Circle a, cd2Capsule b)
{
	cd2Segment core = {b.p1, b.p2};
	cd2Vec closest = cd2ClosestPointOnSegment(core, a.center);
	cdReal radius = a.radius + b.radius;
	cdReal scale = cdMax(cdMax(MaxAbs(a.center), radius), cdMax(MaxAbs(b.p1), MaxAbs(b.p2)));
	return WithinRadius(cd2VecDistanceSquared(a.center, closest), radius, scale);
}

bool cd2OverlapCircleAabb(cd2Circle a, cd2Aabb b)
{
	cd2Vec closest = cd2Clamp(a.center, b.min, b.max);
	return cd2VecDistanceSquared(a.center, closest) <= a.radius * a.radius;
}

bool cd2OverlapCircleBox(cd2Circle a, cd2Box b)
{
	cd2Vec local = cd2InvRotateVector(cd2NormalizeRot(b.rotation), cd2Sub(a.center, b.center));
	cd2Vec closest = cd2Clamp(local, cd2Neg(b.halfExtents), b.halfExtents);
	cdReal scale = cdMax(cdMax(MaxAbs(a.center), a.radius), cdMax(MaxAbs(b.center), MaxAbs(b.halfExtents)));
	return WithinRadius(cd2VecDistanceSquared(local, closest), a.radius, scale);
}

bool cd2OverlapCirclePolygon(cd2Circle a, const cd2Polygon* b)
{
	ConvexSet set = MakePolygonSet(b);
	/* The closest point on the rounded polygon: its distance is the core distance minus b's radius. */
	cd2Vec closest = cd2ClosestPointOnPolygon(b, a.center);
	cdReal scale = cdMax(cdMax(MaxAbs(a.center), a.radius), set.scale);
	return WithinRadius(cd2VecDistanceSquared(a.center, closest), a.radius, scale);
}

bool cd2OverlapCircleSegment(cd2Circle a, cd2Segment b)
{
	cd2Vec closest = cd2ClosestPointOnSegment(b, a.center);
	cdReal scale = cdMax(cdMax(MaxAbs(a.center), a.radius), cdMax(MaxAbs(b.p1), MaxAbs(b.p2)));
	return WithinRadius(cd2VecDistanceSquared(a.center, closest), a.radius, scale);
}

/* ---- capsule pairs --------------------------------------------------------------------------- */

bool cd2OverlapCapsuleCapsule(cd2Capsule a, cd2Capsule b)
{
	if (ShouldSwap(&a, &b, sizeof(cd2Capsule)))
	{
		cd2Capsule swapped = a;
		a = b;
		b = swapped;
	}
	cd2Segment coreA = {a.p1, a.p2};
	cd2Segment coreB = {b.p1, b.p2};
	cd2ClosestPoints closest = cd2ClosestPointsSegmentSegment(coreA, coreB);
	cdReal radius = a.radius + b.radius;
	cdReal scale = cdMax(cdMax(cdMax(MaxAbs(a.p1), MaxAbs(a.p2)), cdMax(MaxAbs(b.p1), MaxAbs(b.p2))), radius);
	return closest.distance <= radius + OverlapTolerance(scale);
}

bool cd2OverlapCapsuleAabb(cd2Capsule a, cd2Aabb b)
{
	cd2Segment core = {a.p1, a.p2};
	ConvexSet set = MakeAabbSet(b);
	return OverlapCapsuleSet(core, a.radius, &set);
}

bool cd2OverlapCapsuleBox(cd2Capsule a, cd2Box b)
{
	cd2Segment core = {a.p1, a.p2};
	ConvexSet set = MakeBoxSet(b);
	return OverlapCapsuleSet(core, a.radius, &set);
}

bool cd2OverlapCapsulePolygon(cd2Capsule a, const cd2Polygon* b)
{
	cd2Segment core = {a.p1, a.p2};
	ConvexSet set = MakePolygonSet(b);
	return OverlapCapsuleSet(core, a.radius, &set);
}

bool cd2OverlapCapsuleSegment(cd2Capsule a, cd2Segment b)
{
	cd2Segment core = {a.p1, a.p2};
	cd2ClosestPoints closest = cd2ClosestPointsSegmentSegment(core, b);
	cdReal scale =
		cdMax(cdMax(cdMax(MaxAbs(a.p1), MaxAbs(a.p2)), cdMax(MaxAbs(b.p1), MaxAbs(b.p2))), a.radius);
	return closest.distance <= a.radius + OverlapTolerance(scale);
}

/* ---- AABB, box, polygon and segment pairs: separating axes ----------------------------------- */

bool cd2OverlapAabbBox(cd2Aabb a, cd2Box b)
{
	ConvexSet setA = MakeAabbSet(a);
	ConvexSet setB = MakeBoxSet(b);
	return OverlapSets(&setA, &setB);
}

bool cd2OverlapAabbPolygon(cd2Aabb a, const cd2Polygon* b)
{
	ConvexSet setA = MakeAabbSet(a);
	ConvexSet setB = MakePolygonSet(b);
	return OverlapSets(&setA, &setB);
}

bool cd2OverlapAabbSegment(cd2Aabb a, cd2Segment b)
{
	ConvexSet setA = MakeAabbSet(a);
	ConvexSet setB = MakeSegmentSet(b);
	return OverlapSets(&setA, &setB);
}

bool cd2OverlapBoxBox(cd2Box a, cd2Box b)
{
	if (ShouldSwap(&a, &b, sizeof(cd2Box)))
	{
		cd2Box swapped = a;
		a = b;
		b = swapped;
	}
	ConvexSet setA = MakeBoxSet(a);
	ConvexSet setB = MakeBoxSet(b);
	return OverlapSets(&setA, &setB);
}

bool cd2OverlapBoxPolygon(cd2Box a, const cd2Polygon* b)
{
	ConvexSet setA = MakeBoxSet(a);
	ConvexSet setB = MakePolygonSet(b);
	return OverlapSets(&setA, &setB);
}

bool cd2OverlapBoxSegment(cd2Box a, cd2Segment b)
{
	ConvexSet setA = MakeBoxSet(a);
	ConvexSet setB = MakeSegmentSet(b);
	return OverlapSets(&setA, &setB);
}

bool cd2OverlapPolygonSegment(const cd2Polygon* a, cd2Segment b)
{
	ConvexSet setA = MakePolygonSet(a);
	ConvexSet setB = MakeSegmentSet(b);
	return OverlapSets(&setA, &setB);
}

bool cd2OverlapSegmentSegment(cd2Segment a, cd2Segment b)
{
	if (ShouldSwap(&a, &b, sizeof(cd2Segment)))
	{
		cd2Segment swapped = a;
		a = b;
		b = swapped;
	}
	ConvexSet setA = MakeSegmentSet(a);
	ConvexSet setB = MakeSegmentSet(b);
	if (setA.axisCount == 0 && setB.axisCount == 0)
	{
		/* Two points: no edge gives an axis, so compare them directly. */
		cdReal tolerance = OverlapTolerance(cdMax(setA.scale, setB.scale));
		cd2Vec gap = cd2Abs(cd2Sub(a.p1, b.p1));
		return gap.x <= tolerance && gap.y <= tolerance;
	}
	return OverlapSets(&setA, &setB);
}
