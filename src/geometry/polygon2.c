/* collide: the convex polygon builders cd2MakePolygon and cd2MakeBoxPolygon.
 *
 * The hull is Andrew's monotone chain over at most CD2_MAX_POLYGON_VERTICES points. Every
 * intermediate quantity (differences, cross products, lengths, the centroid) is computed in double
 * whatever cdReal is: it costs nothing at this size and keeps float polygons far from the origin
 * exact enough that the validator accepts them. Output vertices are always input points. */
#include "collide/geometry2.h"

cdReal cd2GetPolygonWeldTolerance(cdReal maxAbsCoordinate)
{
	return cdMax(CD2_POLYGON_WELD_TOLERANCE, CD_R(64.0) * CD_REAL_EPSILON * cdAbs(maxAbsCoordinate));
}

/* Twice the signed area of the triangle o, a, b: positive when o -> a -> b turns left. */
static double Orient(cd2Vec o, cd2Vec a, cd2Vec b)
{
	double ax = (double)a.x - (double)o.x, ay = (double)a.y - (double)o.y;
	double bx = (double)b.x - (double)o.x, by = (double)b.y - (double)o.y;
	return ax * by - ay * bx;
}

static double DistanceDouble(cd2Vec a, cd2Vec b)
{
	double dx = (double)b.x - (double)a.x, dy = (double)b.y - (double)a.y;
	return sqrt(dx * dx + dy * dy);
}

/* Distance from p to the segment a-b, in double. */
static double DistanceToSegment(cd2Vec p, cd2Vec a, cd2Vec b)
{
	double abx = (double)b.x - (double)a.x, aby = (double)b.y - (double)a.y;
	double apx = (double)p.x - (double)a.x, apy = (double)p.y - (double)a.y;
	double lengthSquared = abx * abx + aby * aby;
	double t = lengthSquared > 0.0 ? (apx * abx + apy * aby) / lengthSquared : 0.0;
	t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
	double dx = apx - t * abx, dy = apy - t * aby;
	return sqrt(dx * dx + dy * dy);
}

/* Whether p lies within tolerance of the convex counter-clockwise polygon hull[0..count) without
 * vertex `removed`: inside every edge's line, or within tolerance of its boundary. The distance to
 * the boundary, not to one edge's line: in a sharp corner a point can be within tolerance of both
 * edges' lines and still far from the corner. */
static bool WithinHullWithout(const cd2Vec* hull, int count, int removed, cd2Vec p, double tolerance)
{
	bool inside = true;
	double nearest = INFINITY;
	for (int k = 0; k < count; ++k)
	{
		if (k == removed)
		{
			continue;
		}
		int next = k + 1 < count ? k + 1 : 0;
		next = next == removed ? (next + 1 < count ? next + 1 : 0) : next;
		inside = inside && Orient(hull[k], hull[next], p) >= 0.0;
		double d = DistanceToSegment(p, hull[k], hull[next]);
		nearest = d < nearest ? d : nearest;
	}
	return inside || nearest <= tolerance;
}

static bool LexicographicLess(cd2Vec a, cd2Vec b)
{
	return a.x < b.x || (a.x == b.x && a.y < b.y);
}

/* Fills normals and centroid of the counter-clockwise vertices and checks the result with the
 * validator, so that no broken polygon ever leaves a builder; *out is written only on success. */
static cdResult FinishPolygon(const cd2Vec* vertices, int count, cd2Polygon* out)
{
	cd2Polygon polygon = {0};
	polygon.count = count;
	double twiceArea = 0.0, centroidX = 0.0, centroidY = 0.0;
	for (int i = 0; i < count; ++i)
	{
		cd2Vec v1 = vertices[i];
		cd2Vec v2 = vertices[i + 1 < count ? i + 1 : 0];
		double length = DistanceDouble(v1, v2);
		if (!(length > 0.0) || !isfinite(length))
		{
			return CD_ERROR_DEGENERATE;
		}
		double ex = (double)v2.x - (double)v1.x, ey = (double)v2.y - (double)v1.y;
		polygon.vertices[i] = v1;
		polygon.normals[i] = cd2MakeVec((cdReal)(ey / length), (cdReal)(-ex / length));

		/* Fan triangles from vertex 0, relative to it so that far-away polygons keep precision. */
		if (i >= 1 && i + 1 < count)
		{
			double weight = Orient(vertices[0], v1, v2);
			twiceArea += weight;
			centroidX +=
				weight * (((double)v1.x - (double)vertices[0].x) + ((double)v2.x - (double)vertices[0].x));
			centroidY +=
				weight * (((double)v1.y - (double)vertices[0].y) + ((double)v2.y - (double)vertices[0].y));
		}
	}
	if (!(twiceArea > 0.0) || !isfinite(twiceArea))
	{
		return CD_ERROR_DEGENERATE;
	}
	polygon.centroid = cd2MakeVec((cdReal)((double)vertices[0].x + centroidX / (3.0 * twiceArea)),
								  (cdReal)((double)vertices[0].y + centroidY / (3.0 * twiceArea)));
	if (!cd2IsValidPolygon(&polygon))
	{
		return CD_ERROR_DEGENERATE;
	}
	*out = polygon;
	return CD_OK;
}

cdResult cd2MakePolygon(const cd2Vec* points, int count, cd2Polygon* out)
{
	if (points == NULL || out == NULL || count < 0)
	{
		return CD_ERROR_INVALID_ARGUMENT;
	}
	if (count > CD2_MAX_POLYGON_VERTICES)
	{
		return CD_ERROR_TOO_MANY_POINTS;
	}
	cdReal maxAbs = CD_R(0.0);
	for (int i = 0; i < count; ++i)
	{
		if (!cd2IsValidVec(points[i]))
		{
			return CD_ERROR_NOT_FINITE;
		}
		maxAbs = cdMax(maxAbs, cdMax(cdAbs(points[i].x), cdAbs(points[i].y)));
	}
	if (count < 3)
	{
		return CD_ERROR_DEGENERATE;
	}
	if (maxAbs > CD2_POLYGON_MAX_COORDINATE)
	{
		return CD_ERROR_OUT_OF_RANGE;
	}
	double tolerance = (double)cd2GetPolygonWeldTolerance(maxAbs);

	/* Weld: keep the first of every group of points closer than the tolerance. */
	cd2Vec unique[CD2_MAX_POLYGON_VERTICES];
	int uniqueCount = 0;
	for (int i = 0; i < count; ++i)
	{
		bool welded = false;
		for (int j = 0; j < uniqueCount && !welded; ++j)
		{
			welded = DistanceDouble(points[i], unique[j]) <= tolerance;
		}
		if (!welded)
		{
			unique[uniqueCount++] = points[i];
		}
	}
	if (uniqueCount < 3)
	{
		return CD_ERROR_DEGENERATE;
	}

	/* Sort by x, then y (insertion sort: at most 8 points). */
	for (int i = 1; i < uniqueCount; ++i)
	{
		cd2Vec key = unique[i];
		int j = i - 1;
		while (j >= 0 && LexicographicLess(key, unique[j]))
		{
			unique[j + 1] = unique[j];
			--j;
		}
		unique[j + 1] = key;
	}

	/* Monotone chain: lower hull left to right, then upper hull right to left, keeping only strict
	 * left turns. The last point of each chain is the first of the other, hence `- 1`. */
	cd2Vec hull[2 * CD2_MAX_POLYGON_VERTICES];
	int hullCount = 0;
	for (int i = 0; i < uniqueCount; ++i)
	{
		while (hullCount >= 2 && Orient(hull[hullCount - 2], hull[hullCount - 1], unique[i]) <= 0.0)
		{
			--hullCount;
		}
		hull[hullCount++] = unique[i];
	}
	int lowerCount = hullCount + 1;
	for (int i = uniqueCount - 2; i >= 0; --i)
	{
		while (hullCount >= lowerCount && Orient(hull[hullCount - 2], hull[hullCount - 1], unique[i]) <= 0.0)
		{
			--hullCount;
		}
		hull[hullCount++] = unique[i];
	}
	--hullCount;

	/* Drop nearly collinear vertices, the flattest first, while some vertex stands within the
	 * tolerance of the line through its neighbours. Removing a vertex of a convex polygon keeps it
	 * convex; a removal is skipped if it would leave any input point farther than the tolerance
	 * from the polygon (not only from the new edge's line: past a sharp corner the two differ), so
	 * drops never accumulate beyond the tolerance. */
	while (hullCount >= 3)
	{
		int flattest = -1;
		double flattestHeight = tolerance;
		for (int i = 0; i < hullCount; ++i)
		{
			cd2Vec previous = hull[i == 0 ? hullCount - 1 : i - 1];
			cd2Vec next = hull[i + 1 < hullCount ? i + 1 : 0];
			double base = DistanceDouble(previous, next);
			double height = base > 0.0 ? Orient(previous, next, hull[i]) / -base : 0.0;
			if (height > flattestHeight)
			{
				continue;
			}
			bool keepsPointsInside = true;
			for (int j = 0; j < uniqueCount && keepsPointsInside; ++j)
			{
				keepsPointsInside = WithinHullWithout(hull, hullCount, i, unique[j], tolerance);
			}
			if (keepsPointsInside)
			{
				flattest = i;
				flattestHeight = height;
			}
		}
		if (flattest < 0)
		{
			break;
		}
		for (int i = flattest; i + 1 < hullCount; ++i)
		{
			hull[i] = hull[i + 1];
		}
		--hullCount;
	}
	if (hullCount < 3)
	{
		return CD_ERROR_DEGENERATE;
	}
	if (hullCount > CD2_MAX_POLYGON_VERTICES)
	{
		return CD_ERROR_TOO_MANY_POINTS;
	}
	return FinishPolygon(hull, hullCount, out);
}

cdResult cd2MakeBoxPolygon(cd2Box box, cd2Polygon* out)
{
	if (out == NULL)
	{
		return CD_ERROR_INVALID_ARGUMENT;
	}
	cd2Shape shape = cd2MakeBoxShape(box);
	cdResult result = cd2ValidateShape(&shape);
	if (result != CD_OK)
	{
		return result;
	}
	if (box.halfExtents.x == CD_R(0.0) || box.halfExtents.y == CD_R(0.0))
	{
		return CD_ERROR_DEGENERATE;
	}
	/* Corners in double so that only the final rounding to cdReal remains; the normals are then
	 * recomputed from the rounded corners, which keeps the polygon exactly consistent with its
	 * vertices even where that rounding is visible (tiny boxes far from the origin). */
	double length = sqrt((double)box.rotation.c * (double)box.rotation.c +
						 (double)box.rotation.s * (double)box.rotation.s);
	double c = (double)box.rotation.c / length, s = (double)box.rotation.s / length;
	double hx = (double)box.halfExtents.x, hy = (double)box.halfExtents.y;
	static const double signs[4][2] = {{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}};
	cd2Vec corners[4];
	for (int i = 0; i < 4; ++i)
	{
		double lx = signs[i][0] * hx, ly = signs[i][1] * hy;
		corners[i] = cd2MakeVec((cdReal)((double)box.center.x + (c * lx - s * ly)),
								(cdReal)((double)box.center.y + (s * lx + c * ly)));
	}
	return FinishPolygon(corners, 4, out);
}

static cdResult ValidateRoundingRadius(cdReal radius)
{
	if (!cdIsValidReal(radius))
	{
		return CD_ERROR_NOT_FINITE;
	}
	return radius < CD_R(0.0) ? CD_ERROR_NEGATIVE_SIZE : CD_OK;
}

cdResult cd2MakeRoundedPolygon(const cd2Vec* points, int count, cdReal radius, cd2Polygon* out)
{
	cd2Polygon polygon;
	cdResult result = out == NULL ? CD_ERROR_INVALID_ARGUMENT : cd2MakePolygon(points, count, &polygon);
	if (result == CD_OK)
	{
		result = ValidateRoundingRadius(radius);
	}
	if (result != CD_OK)
	{
		return result;
	}
	polygon.radius = radius;
	*out = polygon;
	return CD_OK;
}

cdResult cd2MakeRoundedBoxPolygon(cd2Box box, cdReal radius, cd2Polygon* out)
{
	cd2Polygon polygon;
	cdResult result = out == NULL ? CD_ERROR_INVALID_ARGUMENT : cd2MakeBoxPolygon(box, &polygon);
	if (result == CD_OK)
	{
		result = ValidateRoundingRadius(radius);
	}
	if (result != CD_OK)
	{
		return result;
	}
	polygon.radius = radius;
	*out = polygon;
	return CD_OK;
}
