// collide_bench_manifold2: ns per call of the 2D contact manifolds and distance, with Box2D 2.4's
// b2CollidePolygons, b2CollidePolygonAndCircle and b2Distance on the same pairs in the same run.
//
// Pairs are near contact (overlapping by up to 0.05 or apart by up to 0.01, unit-size shapes)
// for the manifolds, apart by 0.1 to 1 for the distance. collide's world-space rows take
// world-space shapes; Box2D takes local shapes and transforms (its API), so its figure includes
// applying the transforms. The "local frame" rows call collide the same way (shapes in body frames,
// the relative transform computed from the two body transforms in each call): what a solver runs.
// Both report contacts up to Box2D's polygon radius apart (collide: speculative distance
// 2 * b2_polygonRadius on sharp polygons). Each figure is the median of 9 runs of about 20 ms,
// collide's and Box2D's runs alternating so that both see the same machine load.
// Usage: collide_bench_manifold2 [--quick] [--filter TEXT]   (only the rows whose name holds TEXT)
//        collide_bench_manifold2 --once ROW   (ROW: box, octagon, circle-octagon, circle-box)
// --once calls collide's and Box2D's function of that row once per pair and prints nothing else:
// run it under `valgrind --tool=callgrind` and divide the inclusive instruction counts of the two
// functions by the pair count for instructions per call (repeatable on a loaded machine, where
// the timings are not).
#include <box2d/b2_distance.h>
#include <box2d/box2d.h>

#include "collide/collide.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <vector>

namespace
{
const int kPairs = 1024;

struct Pair
{
	cd2Polygon a, b;	   // world space
	cd2Circle circle;	   // world space
	cd2Shape sa, sb;	   // a and b as tagged shapes, for cd2Distance
	b2PolygonShape pa, pb; // local
	b2CircleShape pc;	   // local (centered)
	b2Transform xa, xb, xc;
	cd2Polygon la, lb;			// local, for the local-frame form (what a solver calls)
	cd2Circle lc;				// local (centered)
	cd2Transform xfA, xfB, xfC; // the bodies' transforms, the same as xa, xb, xc
};

cd2Transform FromBox2D(const b2Transform& x)
{
	cd2Transform t;
	t.p = cd2MakeVec((cdReal)x.p.x, (cdReal)x.p.y);
	t.q.c = (cdReal)x.q.c;
	t.q.s = (cdReal)x.q.s;
	return t;
}

// Box2D's distance between the pair's polygons, from a cold cache (as the benchmark times it).
b2DistanceOutput Box2dDistance(const Pair& p)
{
	b2DistanceInput input;
	input.proxyA.Set(&p.pa, 0);
	input.proxyB.Set(&p.pb, 0);
	input.transformA = p.xa;
	input.transformB = p.xb;
	input.useRadii = false;
	b2SimplexCache cache;
	cache.count = 0;
	b2DistanceOutput output;
	b2Distance(&output, &cache, &input);
	return output;
}

cd2Polygon LocalPolygon(int sides, double radius, std::mt19937_64& rng, bool box)
{
	std::uniform_real_distribution<double> u(0.0, 1.0);
	cd2Vec points[CD2_MAX_POLYGON_VERTICES];
	if (box)
	{
		double hx = 0.3 + 0.4 * u(rng), hy = 0.3 + 0.4 * u(rng);
		points[0] = cd2MakeVec((cdReal)-hx, (cdReal)-hy);
		points[1] = cd2MakeVec((cdReal)hx, (cdReal)-hy);
		points[2] = cd2MakeVec((cdReal)hx, (cdReal)hy);
		points[3] = cd2MakeVec((cdReal)-hx, (cdReal)hy);
		sides = 4;
	}
	else
	{
		for (int i = 0; i < sides; ++i)
		{
			double angle = 2.0 * M_PI * (i + 0.3 * u(rng)) / sides;
			points[i] = cd2MakeVec((cdReal)(radius * std::cos(angle)), (cdReal)(radius * std::sin(angle)));
		}
	}
	cd2Polygon polygon;
	cd2MakePolygon(points, sides, &polygon);
	return polygon;
}

b2PolygonShape ToBox2D(const cd2Polygon& p)
{
	b2Vec2 points[b2_maxPolygonVertices];
	for (int i = 0; i < p.count; ++i)
	{
		points[i].Set((float)p.vertices[i].x, (float)p.vertices[i].y);
	}
	b2PolygonShape shape;
	shape.Set(points, p.count);
	return shape;
}

cd2Polygon Transformed(const cd2Polygon& p, const b2Transform& x)
{
	cd2Polygon out = p;
	for (int i = 0; i < p.count; ++i)
	{
		b2Vec2 v = b2Mul(x, b2Vec2((float)p.vertices[i].x, (float)p.vertices[i].y));
		b2Vec2 n = b2Mul(x.q, b2Vec2((float)p.normals[i].x, (float)p.normals[i].y));
		out.vertices[i] = cd2MakeVec((cdReal)v.x, (cdReal)v.y);
		out.normals[i] = cd2MakeVec((cdReal)n.x, (cdReal)n.y);
	}
	b2Vec2 c = b2Mul(x, b2Vec2((float)p.centroid.x, (float)p.centroid.y));
	out.centroid = cd2MakeVec((cdReal)c.x, (cdReal)c.y);
	return out;
}

// Pairs of the given polygon kind, B moved along the gap between them to a random gap.
std::vector<Pair> MakePairs(int sides, bool box, double gapLow, double gapHigh, uint64_t seed)
{
	std::mt19937_64 rng(seed);
	std::uniform_real_distribution<double> u(0.0, 1.0);
	std::vector<Pair> pairs(kPairs);
	for (Pair& pair : pairs)
	{
		cd2Polygon la = LocalPolygon(sides, 0.5, rng, box), lb = LocalPolygon(sides, 0.5, rng, box);
		pair.xa.Set(b2Vec2((float)(u(rng) * 4 - 2), (float)(u(rng) * 4 - 2)), (float)(u(rng) * 6.28));
		double angle = u(rng) * 6.28;
		b2Vec2 offset((float)std::cos(angle), (float)std::sin(angle));
		pair.xb.Set(pair.xa.p + offset, (float)(u(rng) * 6.28));
		pair.a = Transformed(la, pair.xa);
		pair.b = Transformed(lb, pair.xb);
		cd2Shape sa = cd2MakePolygonShape(&pair.a), sb = cd2MakePolygonShape(&pair.b);
		cd2ClosestPoints closest = cd2Distance(&sa, &sb);
		if (closest.distance > (cdReal)0)
		{
			double gap = gapLow + (gapHigh - gapLow) * u(rng);
			cd2Vec n = cd2Normalize(cd2Sub(closest.pointB, closest.pointA));
			double move = gap - (double)closest.distance;
			pair.xb.p += b2Vec2((float)(move * (double)n.x), (float)(move * (double)n.y));
			pair.b = Transformed(lb, pair.xb);
		}
		pair.sa = cd2MakePolygonShape(&pair.a);
		pair.sb = cd2MakePolygonShape(&pair.b);
		pair.pa = ToBox2D(la);
		pair.pb = ToBox2D(lb);
		pair.la = la;
		pair.lb = lb;
		pair.xfA = FromBox2D(pair.xa);
		pair.xfB = FromBox2D(pair.xb);

		// A circle near contact with polygon a.
		double radius = 0.2 + 0.3 * u(rng);
		double around = u(rng) * 6.28;
		cd2Vec far = cd2Add(pair.a.centroid,
							cd2MakeVec((cdReal)(3 * std::cos(around)), (cdReal)(3 * std::sin(around))));
		cd2Vec onA = cd2ClosestPointOnPolygon(&pair.a, far);
		cd2Vec out = cd2Normalize(cd2Sub(far, onA));
		double gap = gapLow + (gapHigh - gapLow) * u(rng);
		pair.circle.center = cd2MulAdd(onA, (cdReal)(radius + gap), out);
		pair.circle.radius = (cdReal)radius;
		pair.pc.m_p.SetZero();
		pair.pc.m_radius = (float)radius;
		pair.xc.Set(b2Vec2((float)pair.circle.center.x, (float)pair.circle.center.y), 0.0f);
		pair.lc.center = cd2MakeVec((cdReal)0, (cdReal)0);
		pair.lc.radius = pair.circle.radius;
		pair.xfC = FromBox2D(pair.xc);
	}
	return pairs;
}

long g_sink = 0;

template <typename F> double TimeOnce(const std::vector<Pair>& pairs, F f, int reps)
{
	using Clock = std::chrono::steady_clock;
	auto start = Clock::now();
	for (int r = 0; r < reps; ++r)
	{
		for (const Pair& p : pairs)
		{
			g_sink += f(p);
		}
	}
	double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
	return elapsed * 1e9 / ((double)reps * (double)pairs.size());
}

template <typename F> int Calibrate(const std::vector<Pair>& pairs, F f, double seconds)
{
	int reps = 1;
	while (reps < (1 << 20) &&
		   TimeOnce(pairs, f, reps) * 1e-9 * (double)reps * (double)pairs.size() < seconds)
	{
		reps *= 2;
	}
	return reps;
}

double Median(std::vector<double> samples)
{
	std::sort(samples.begin(), samples.end());
	return samples[samples.size() / 2];
}

struct Figures
{
	double mine, theirs;
};

// The two functions timed in alternation, run after run, so that both see the same machine load.
template <typename F, typename G>
Figures Compare(const std::vector<Pair>& pairs, F mine, G theirs, int runs, double seconds)
{
	int repsMine = Calibrate(pairs, mine, seconds), repsTheirs = Calibrate(pairs, theirs, seconds);
	std::vector<double> a, b;
	for (int run = 0; run < runs; ++run)
	{
		a.push_back(TimeOnce(pairs, mine, repsMine));
		b.push_back(TimeOnce(pairs, theirs, repsTheirs));
	}
	return Figures{Median(a), Median(b)};
}
} // namespace

int main(int argc, char** argv)
{
	bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
	const char* once = argc > 2 && std::strcmp(argv[1], "--once") == 0 ? argv[2] : nullptr;
	const char* filter = nullptr;
	for (int i = 1; i + 1 < argc; ++i)
	{
		if (std::strcmp(argv[i], "--filter") == 0)
		{
			filter = argv[i + 1];
		}
	}
	int runs = quick ? 3 : 9;
	double seconds = quick ? 0.002 : 0.02;
	const cdReal speculative = (cdReal)(2.0 * b2_polygonRadius);

	std::vector<Pair> boxes = MakePairs(4, true, -0.05, 0.01, 1);
	std::vector<Pair> octagons = MakePairs(8, false, -0.05, 0.01, 2);
	std::vector<Pair> apart = once != nullptr ? std::vector<Pair>() : MakePairs(8, false, 0.1, 1.0, 3);

	std::printf("collide_bench_manifold2 (%s, cdReal = %s): ns per call, median of %d runs, %d pairs\n",
				quick ? "quick" : "full", sizeof(cdReal) == sizeof(double) ? "double" : "float", runs,
				kPairs);
	std::printf("%-44s %10s %10s %8s\n", "case", "collide", "box2d 2.4", "ratio");

	auto row = [&](const char* name, auto compare) {
		if (filter != nullptr && std::strstr(name, filter) == nullptr)
		{
			return;
		}
		Figures f = compare();
		std::printf("%-44s %10.1f %10.1f %8.2f\n", name, f.mine, f.theirs, f.mine / f.theirs);
	};

	auto collidePolygons = [&](const Pair& p) {
		return cd2CollidePolygonPolygon(&p.a, &p.b, speculative).pointCount;
	};
	auto box2dPolygons = [&](const Pair& p) {
		b2Manifold m;
		b2CollidePolygons(&m, &p.pa, p.xa, &p.pb, p.xb);
		return m.pointCount;
	};
	// The local-frame form as a solver calls it: shapes in body frames, the relative transform
	// computed from the two body transforms on every call (as Box2D does inside b2CollidePolygons).
	auto collidePolygonsLocal = [&](const Pair& p) {
		cd2Transform xf = cd2InvMulTransforms(p.xfA, p.xfB);
		return cd2CollidePolygonPolygonLocal(&p.la, &p.lb, xf, speculative).pointCount;
	};
	auto collideCircleLocal = [&](const Pair& p) {
		cd2Transform xf = cd2InvMulTransforms(p.xfC, p.xfA);
		return cd2CollideCirclePolygonLocal(p.lc, &p.la, xf, (cdReal)0).pointCount;
	};
	auto collideCircle = [&](const Pair& p) {
		return cd2CollideCirclePolygon(p.circle, &p.a, (cdReal)0).pointCount;
	};
	auto box2dCircle = [&](const Pair& p) {
		b2Manifold m;
		b2CollidePolygonAndCircle(&m, &p.pa, p.xa, &p.pc, p.xc);
		return m.pointCount;
	};
	auto collideDistance = [&](const Pair& p) {
		return (int)(cd2Distance(&p.sa, &p.sb).distance > (cdReal)0.5);
	};
	auto box2dDistance = [&](const Pair& p) { return (int)(Box2dDistance(p).distance > 0.5f); };

	if (once != nullptr)
	{
		bool box = std::strcmp(once, "box") == 0 || std::strcmp(once, "circle-box") == 0;
		bool circle = std::strncmp(once, "circle", 6) == 0;
		const std::vector<Pair>& pairs = box ? boxes : octagons;
		for (const Pair& p : pairs)
		{
			g_sink += circle ? collideCircle(p) : collidePolygons(p);
			g_sink += circle ? box2dCircle(p) : box2dPolygons(p);
		}
		std::printf("%s: %zu pairs, %ld points\n", once, pairs.size(), g_sink);
		return 0;
	}
	row("polygon manifold, box-box",
		[&] { return Compare(boxes, collidePolygons, box2dPolygons, runs, seconds); });
	row("polygon manifold, 8-gon-8-gon",
		[&] { return Compare(octagons, collidePolygons, box2dPolygons, runs, seconds); });
	row("circle-polygon manifold, circle-8-gon",
		[&] { return Compare(octagons, collideCircle, box2dCircle, runs, seconds); });
	row("circle-polygon manifold, circle-box",
		[&] { return Compare(boxes, collideCircle, box2dCircle, runs, seconds); });
	row("polygon manifold local frame, box-box",
		[&] { return Compare(boxes, collidePolygonsLocal, box2dPolygons, runs, seconds); });
	row("polygon manifold local frame, 8-gon-8-gon",
		[&] { return Compare(octagons, collidePolygonsLocal, box2dPolygons, runs, seconds); });
	row("circle-polygon local frame, circle-8-gon",
		[&] { return Compare(octagons, collideCircleLocal, box2dCircle, runs, seconds); });
	row("distance (GJK), 8-gon-8-gon apart",
		[&] { return Compare(apart, collideDistance, box2dDistance, runs, seconds); });
	if (filter == nullptr || std::strstr("distance", filter) != nullptr)
	{
		long iterationsMine = 0, iterationsTheirs = 0;
		for (const Pair& p : apart)
		{
			cdDistanceStatus status;
			cd2DistanceWithStatus(&p.sa, &p.sb, &status);
			iterationsMine += status.iterations;
			iterationsTheirs += Box2dDistance(p).iterations;
		}
		std::printf("GJK iterations per call: collide %.2f, box2d %.2f\n",
					(double)iterationsMine / (double)apart.size(),
					(double)iterationsTheirs / (double)apart.size());
	}
	if (g_sink == 42)
	{
		std::printf("\n");
	}
	return 0;
}
