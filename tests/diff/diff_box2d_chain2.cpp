// Differential test of the one-sided chain segment against a polygon: collide's
// cd2CollideChainSegmentPolygonDirect (what cd2CollideChain runs) against Box2D 2.4's
// b2CollideEdgeAndPolygon on a one-sided b2EdgeShape (SetOneSided with the same ghosts), on
// thousands of random segments, ghost turns and polygons.
//
// Box2D 2.4 rounds the edge and the polygon by b2_polygonRadius each and keeps clip points whose
// cores are apart by up to that total; the equivalent collide call is the sharp polygon with a
// speculative distance of 2 * b2_polygonRadius. Compared: whether the pair touches, and the
// normal (within 1e-3) where both touch through a face. The rules differ on purpose in a few
// places, which are skipped (counted, and the counts bounded):
// - the cut: a centroid within 1e-3 of the segment's line (one-sidedness), a true core distance
//   or a face separation within 1e-3 of the total radius, and separated cores whose face
//   separation is within the radius while their true distance is not (Box2D 2.4 still reports a
//   face contact there, collide reports by distance);
// - deep pairs, where the segment's back face separates best or the best axis turns away from the
//   segment's front (dot with its normal below 0.1): collide then takes the contact seen from the
//   segment's face, Box2D 2.4 runs its region tests on that axis (and often drops the contact);
// - separated cores whose closest features meet along a gap (collide reports the gap's
//   direction, Box2D 2.4 a face normal, and may clip it away near the segment's ends);
// - the reference face: Box2D takes the polygon's face when it separates by more than 0.98 of
//   the edge's separation plus 0.001 (below the radius), collide when it separates by 0.1 slop
//   more (cores in contact) or when it holds the closest feature (cores apart): pairs where the
//   two rules disagree or come within 1e-3 of their thresholds;
// - a convex corner's fan: Box2D admits normals up to 0.1 (sine) past the neighbour's normal,
//   collide up to the neighbour's normal (the neighbour segment reports the rest): candidate
//   normals from 0.02 inside to 0.12 past the neighbour's normal.
// Ghost turns are kept clear of straight (|turn| >= 0.05 rad): Box2D counts any left turn as
// convex, collide a turn above 1e-4 (a straight chain's rounding decides Box2D's side there).
#include <box2d/box2d.h>

#include "collide/collide.h"
#include "query/chain_manifold2.h" // internal: the dedicated segment-polygon manifold
#include "test.h"

#include <cmath>
#include <cstdio>

namespace
{
const double kRadius = 2.0 * (double)b2_polygonRadius;
const double kBand = 1e-3;

struct Case
{
	cd2ChainSegment segment;
	cd2Polygon polygon;
};

double Float(double x)
{
	return (double)(float)x;
}

cd2Vec FloatVec(double x, double y)
{
	return cd2MakeVec((cdReal)Float(x), (cdReal)Float(y));
}

cd2Polygon RandomPolygon(TestRng* rng, double cx, double cy, double size)
{
	for (;;)
	{
		cd2Vec points[CD2_MAX_POLYGON_VERTICES];
		int count = 3 + TestRngInt(rng, 6);
		if (TestRngInt(rng, 2) == 0)
		{
			double hx = TestRngRange(rng, 0.1, 1.0) * size, hy = TestRngRange(rng, 0.1, 1.0) * size;
			double angle = TestRngRange(rng, -3.2, 3.2), c = std::cos(angle), s = std::sin(angle);
			const double corners[4][2] = {{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}};
			count = 4;
			for (int i = 0; i < 4; ++i)
			{
				points[i] = FloatVec(cx + c * corners[i][0] - s * corners[i][1],
									 cy + s * corners[i][0] + c * corners[i][1]);
			}
		}
		else
		{
			for (int i = 0; i < count; ++i)
			{
				points[i] =
					FloatVec(cx + TestRngRange(rng, -size, size), cy + TestRngRange(rng, -size, size));
			}
		}
		cd2Polygon polygon;
		if (cd2MakePolygon(points, count, &polygon) == CD_OK)
		{
			return polygon;
		}
	}
}

Case RandomCase(TestRng* rng)
{
	Case c;
	double angle = TestRngRange(rng, -3.2, 3.2);
	double length = TestRngRange(rng, 0.3, 3.0);
	double x = TestRngRange(rng, -5, 5), y = TestRngRange(rng, -5, 5);
	c.segment.p1 = FloatVec(x, y);
	c.segment.p2 = FloatVec(x + length * std::cos(angle), y + length * std::sin(angle));
	for (int end = 0; end < 2; ++end)
	{
		double turn = TestRngRange(rng, 0.05, 1.3) * (TestRngInt(rng, 2) == 0 ? 1.0 : -1.0);
		double ghostLength = TestRngRange(rng, 0.3, 3.0);
		if (end == 0)
		{
			double a = angle - turn;
			c.segment.ghost1 = FloatVec((double)c.segment.p1.x - ghostLength * std::cos(a),
										(double)c.segment.p1.y - ghostLength * std::sin(a));
		}
		else
		{
			double a = angle + turn;
			c.segment.ghost2 = FloatVec((double)c.segment.p2.x + ghostLength * std::cos(a),
										(double)c.segment.p2.y + ghostLength * std::sin(a));
		}
	}
	double size = TestRngRange(rng, 0.1, 1.0);
	double along = TestRngRange(rng, -0.3, 1.3);
	double height = TestRngRange(rng, -0.2, 1.5) * size;
	double nx = std::sin(angle), ny = -std::cos(angle);
	c.polygon = RandomPolygon(rng, x + along * length * std::cos(angle) + height * nx,
							  y + along * length * std::sin(angle) + height * ny, size);
	return c;
}

struct Vec
{
	double x, y;
};

Vec D(cd2Vec v)
{
	return Vec{(double)v.x, (double)v.y};
}
Vec Sub(Vec a, Vec b)
{
	return Vec{a.x - b.x, a.y - b.y};
}
double Dot(Vec a, Vec b)
{
	return a.x * b.x + a.y * b.y;
}
double Cross(Vec a, Vec b)
{
	return a.x * b.y - a.y * b.x;
}
Vec Unit(Vec a)
{
	double l = std::sqrt(Dot(a, a));
	return Vec{a.x / l, a.y / l};
}
Vec RightPerp(Vec a)
{
	return Vec{a.y, -a.x};
}

double PointSegmentDistance(Vec p, Vec a, Vec b)
{
	Vec d = Sub(b, a);
	double t = std::fmin(std::fmax(Dot(Sub(p, a), d) / Dot(d, d), 0.0), 1.0);
	Vec q{a.x + t * d.x, a.y + t * d.y};
	return std::sqrt(Dot(Sub(p, q), Sub(p, q)));
}

// Distance between the segment and the polygon's core (0 when they overlap).
double CoreDistance(Vec p1, Vec p2, const cd2Polygon& polygon)
{
	int n = polygon.count;
	bool inside1 = true, inside2 = true;
	for (int i = 0; i < n; ++i)
	{
		Vec normal = D(polygon.normals[i]), v = D(polygon.vertices[i]);
		inside1 = inside1 && Dot(normal, Sub(p1, v)) <= 0.0;
		inside2 = inside2 && Dot(normal, Sub(p2, v)) <= 0.0;
	}
	if (inside1 || inside2)
	{
		return 0.0;
	}
	double best = 1e300;
	for (int i = 0; i < n; ++i)
	{
		Vec a = D(polygon.vertices[i]), b = D(polygon.vertices[i + 1 < n ? i + 1 : 0]);
		// Crossing edges: distance 0.
		double s1 = Cross(Sub(p2, p1), Sub(a, p1)), s2 = Cross(Sub(p2, p1), Sub(b, p1));
		double t1 = Cross(Sub(b, a), Sub(p1, a)), t2 = Cross(Sub(b, a), Sub(p2, a));
		if (((s1 < 0.0) != (s2 < 0.0)) && ((t1 < 0.0) != (t2 < 0.0)))
		{
			return 0.0;
		}
		best = std::fmin(best, PointSegmentDistance(p1, a, b));
		best = std::fmin(best, PointSegmentDistance(p2, a, b));
		best = std::fmin(best, PointSegmentDistance(a, p1, p2));
	}
	return best;
}

// Within `band` of the convex corner's fan edge on either side (the candidate normal m).
bool NearFanEdge(const cd2ChainSegment& s, Vec m)
{
	Vec p1 = D(s.p1), p2 = D(s.p2);
	Vec edge1 = Unit(Sub(p2, p1));
	Vec edge0 = Unit(Sub(p1, D(s.ghost1))), edge2 = Unit(Sub(D(s.ghost2), p2));
	bool near = false;
	if (Cross(edge0, edge1) > 0.0)
	{
		double t1 = Cross(m, RightPerp(edge0)); // > 0: past the previous segment's normal
		near = near || (t1 > -0.02 && t1 < 0.12);
	}
	if (Cross(edge1, edge2) > 0.0)
	{
		double t2 = Cross(RightPerp(edge2), m);
		near = near || (t2 > -0.02 && t2 < 0.12);
	}
	return near;
}

void TestChainSegmentPolygon()
{
	TestRng rng = TestRngMake(0xB2C4);
	const int cases = 20000;
	int compared = 0, touching = 0, normalsCompared = 0;
	int skippedCut = 0, skippedDeep = 0, skippedGap = 0, skippedFace = 0, skippedFan = 0;
	b2Transform identity;
	identity.SetIdentity();
	for (int trial = 0; trial < cases; ++trial)
	{
		Case c = RandomCase(&rng);
		const cd2ChainSegment& s = c.segment;
		const cd2Polygon& polygon = c.polygon;
		cd2Manifold mine = cd2CollideChainSegmentPolygonDirect(&s, &polygon, (cdReal)kRadius);

		b2EdgeShape edge;
		edge.SetOneSided(b2Vec2((float)s.ghost1.x, (float)s.ghost1.y), b2Vec2((float)s.p1.x, (float)s.p1.y),
						 b2Vec2((float)s.p2.x, (float)s.p2.y), b2Vec2((float)s.ghost2.x, (float)s.ghost2.y));
		b2PolygonShape shape;
		shape.m_count = polygon.count;
		for (int i = 0; i < polygon.count; ++i)
		{
			shape.m_vertices[i].Set((float)polygon.vertices[i].x, (float)polygon.vertices[i].y);
			shape.m_normals[i].Set((float)polygon.normals[i].x, (float)polygon.normals[i].y);
		}
		shape.m_centroid.Set((float)polygon.centroid.x, (float)polygon.centroid.y);
		b2Manifold theirs;
		b2CollideEdgeAndPolygon(&theirs, &edge, identity, &shape, identity);
		b2WorldManifold world;
		world.Initialize(&theirs, identity, edge.m_radius, identity, shape.m_radius);

		// Separating axis values in double: the segment's two normals and the polygon's faces.
		Vec p1 = D(s.p1), p2 = D(s.p2);
		Vec n = RightPerp(Unit(Sub(p2, p1)));
		double front = 1e300, back = 1e300, faceB = -1e300;
		int faceIndex = 0;
		for (int j = 0; j < polygon.count; ++j)
		{
			Vec v = D(polygon.vertices[j]);
			front = std::fmin(front, Dot(n, Sub(v, p1)));
			back = std::fmin(back, -Dot(n, Sub(v, p2)));
			Vec normal = D(polygon.normals[j]);
			double e = std::fmin(Dot(normal, Sub(p1, v)), Dot(normal, Sub(p2, v)));
			if (e > faceB)
			{
				faceB = e;
				faceIndex = j;
			}
		}
		double faceA = std::fmax(front, back);
		double largest = std::fmax(faceA, faceB);
		double distance = CoreDistance(p1, p2, polygon);
		double offset = Dot(n, Sub(D(polygon.centroid), p1));

		if (std::fabs(offset) < kBand || std::fabs(distance - kRadius) < kBand ||
			std::fabs(largest - kRadius) < kBand || (distance > kRadius && largest <= kRadius))
		{
			++skippedCut;
			continue;
		}
		if (back >= front - kBand)
		{
			++skippedDeep;
			continue;
		}
		bool gap = mine.pointCount > 0 && (mine.points[0].id >> 16) >= 4u;
		if (gap || (distance > 0.1 * 0.005 && mine.pointCount == 0 && theirs.pointCount > 0 &&
					largest <= kRadius && distance <= kRadius))
		{
			++skippedGap;
			continue;
		}
		// The two reference-face rules: Box2D's hysteresis and collide's tolerance (in contact) or
		// closest feature (apart).
		bool box2dPolygonFace = faceB - kRadius > 0.98 * (faceA - kRadius) + 0.001;
		double box2dMargin = std::fabs((faceB - kRadius) - (0.98 * (faceA - kRadius) + 0.001));
		bool collidePolygonFace = faceB > faceA + 0.1 * 0.005;
		double collideMargin = std::fabs(faceB - (faceA + 0.1 * 0.005));
		if (box2dPolygonFace != collidePolygonFace || box2dMargin < kBand || collideMargin < kBand ||
			(largest > 0.1 * 0.005 && std::fabs(faceA - faceB) < 0.05))
		{
			++skippedFace;
			continue;
		}
		Vec candidate = collidePolygonFace ? Vec{-(double)polygon.normals[faceIndex].x,
												 -(double)polygon.normals[faceIndex].y}
										   : (front >= back ? n : Vec{-n.x, -n.y});
		if (Dot(candidate, n) < 0.1)
		{
			++skippedDeep; /* the best axis turns away from the front: deep inside, each its own rule */
			continue;
		}
		if (NearFanEdge(s, candidate))
		{
			++skippedFan;
			continue;
		}
		++compared;
		bool mineTouches = mine.pointCount > 0, theirsTouch = theirs.pointCount > 0;
		TEST_CHECKF(mineTouches == theirsTouch,
					"trial %d: collide %d points, box2d %d (distance %.6g, faces %.6g %.6g, offset %.6g)",
					trial, mine.pointCount, theirs.pointCount, distance, faceA, faceB, offset);
		if (mineTouches && theirsTouch)
		{
			++touching;
			double dx = (double)mine.normal.x - (double)world.normal.x;
			double dy = (double)mine.normal.y - (double)world.normal.y;
			TEST_CHECKF(
				std::sqrt(dx * dx + dy * dy) <= 1e-3,
				"trial %d: collide normal (%.7g %.7g), box2d (%.7g %.7g) (distance %.6g, faces %.6g %.6g)",
				trial, (double)mine.normal.x, (double)mine.normal.y, (double)world.normal.x,
				(double)world.normal.y, distance, faceA, faceB);
			++normalsCompared;
		}
	}
	std::printf(
		"chain segment vs polygon: %d of %d compared (%d touching, %d normals); skipped: %d at the cut, "
		"%d deep, %d along a gap, %d near a face tie, %d at a fan's edge\n",
		compared, cases, touching, normalsCompared, skippedCut, skippedDeep, skippedGap, skippedFace,
		skippedFan);
	TEST_CHECK(compared > cases / 2 && touching > cases / 10);
	TEST_CHECK(skippedCut + skippedDeep + skippedGap + skippedFace + skippedFan < cases / 2);
}
} // namespace

int main()
{
	TEST_RUN(TestChainSegmentPolygon);
	return TEST_SUMMARY();
}
