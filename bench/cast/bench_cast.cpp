// collide_bench_cast: ns per call of cd2TimeOfImpact and cd2ShapeCast, with Box2D 2.4's
// b2TimeOfImpact and b2ShapeCast on the same pairs in the same run, and of cd3ShapeCast and
// cd3TimeOfImpact (no peer).
//
// 2D pairs: random convex polygons (3-8 vertices, unit size) not overlapping at the start.
// TOI: each body moves about 3 units towards the other while turning up to 2 radians (about
// half the pairs hit); Box2D's polygons are rounded by b2_polygonRadius and collide takes the
// sharp cores with Box2D's target (1 linear slop) and tolerance (0.25 slop): the same problem
// (see tests/diff/diff_box2d_toi.cpp). Shape cast: A moves by about 4 units towards B; both
// libraries see polygons rounded by b2_polygonRadius; collide takes world-space shapes, Box2D
// local proxies and transforms (its API). Each figure is the median of 9 runs of about 20 ms,
// collide's and Box2D's runs alternating so that both see the same machine load.
// Usage: collide_bench_cast [--quick | --profile-cast | --profile-toi] (the last two: one 2D query,
// fastest of 100 alternating runs of each library, for profilers and A/B checks)
#include <box2d/b2_distance.h>
#include <box2d/b2_time_of_impact.h>
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
const double kSlop = (double)b2_linearSlop;

struct Pair2
{
	cd2Shape coreA, coreB;	 // sharp polygons in the body frames (TOI)
	cd2Sweep sweepA, sweepB; // collide sweeps
	b2PolygonShape polygonA, polygonB;
	b2Sweep b2sweepA, b2sweepB;
	cd2Shape worldA, worldB; // rounded by b2_polygonRadius, placed at t = 0 (shape cast)
	cd2Vec translation;		 // of A
	b2Transform xfA, xfB;
};

b2PolygonShape RandomPolygon(std::mt19937_64& rng)
{
	std::uniform_real_distribution<double> u(0.0, 1.0);
	int count = 3 + (int)(u(rng) * 6.0);
	count = std::min(count, 8);
	b2Vec2 points[b2_maxPolygonVertices];
	double rx = 0.2 + 0.6 * u(rng), ry = 0.2 + 0.6 * u(rng);
	for (int i = 0; i < count; ++i)
	{
		double angle = 2.0 * M_PI * (i + 0.1 + 0.8 * u(rng)) / count;
		points[i].Set((float)(rx * std::cos(angle)), (float)(ry * std::sin(angle)));
	}
	b2PolygonShape polygon;
	polygon.Set(points, count);
	return polygon;
}

cd2Polygon ToCollide(const b2PolygonShape& p, double radius)
{
	cd2Vec vertices[CD2_MAX_POLYGON_VERTICES];
	for (int i = 0; i < p.m_count; ++i)
	{
		vertices[i] = cd2MakeVec((cdReal)p.m_vertices[i].x, (cdReal)p.m_vertices[i].y);
	}
	cd2Polygon polygon;
	cd2MakeRoundedPolygon(vertices, p.m_count, (cdReal)radius, &polygon);
	return polygon;
}

cd2Shape Placed(const cd2Polygon& local, const b2Transform& xf)
{
	cd2Polygon out = local;
	for (int i = 0; i < local.count; ++i)
	{
		b2Vec2 v = b2Mul(xf, b2Vec2((float)local.vertices[i].x, (float)local.vertices[i].y));
		b2Vec2 n = b2Mul(xf.q, b2Vec2((float)local.normals[i].x, (float)local.normals[i].y));
		out.vertices[i] = cd2MakeVec((cdReal)v.x, (cdReal)v.y);
		out.normals[i] = cd2MakeVec((cdReal)n.x, (cdReal)n.y);
	}
	b2Vec2 c = b2Mul(xf, b2Vec2((float)local.centroid.x, (float)local.centroid.y));
	out.centroid = cd2MakeVec((cdReal)c.x, (cdReal)c.y);
	return cd2MakePolygonShape(&out);
}

void MakeSweep(std::mt19937_64& rng, b2Vec2 from, b2Vec2 to, b2Sweep* b2s, cd2Sweep* s)
{
	std::uniform_real_distribution<double> u(0.0, 1.0);
	b2s->localCenter.Set((float)(0.2 * u(rng) - 0.1), (float)(0.2 * u(rng) - 0.1));
	b2s->c0 = from;
	b2s->c = to;
	b2s->a0 = (float)(6.28 * u(rng));
	b2s->a = b2s->a0 + (float)(4.0 * u(rng) - 2.0);
	b2s->alpha0 = 0.0f;
	s->localCenter = cd2MakeVec((cdReal)b2s->localCenter.x, (cdReal)b2s->localCenter.y);
	s->center0 = cd2MakeVec((cdReal)from.x, (cdReal)from.y);
	s->center1 = cd2MakeVec((cdReal)to.x, (cdReal)to.y);
	s->angle0 = (cdReal)b2s->a0;
	s->angle1 = (cdReal)b2s->a;
}

std::vector<Pair2> MakePairs2(uint64_t seed)
{
	std::mt19937_64 rng(seed);
	std::uniform_real_distribution<double> u(0.0, 1.0);
	std::vector<Pair2> pairs;
	while ((int)pairs.size() < kPairs)
	{
		Pair2 p;
		p.polygonA = RandomPolygon(rng);
		p.polygonB = RandomPolygon(rng);
		cd2Polygon coreA = ToCollide(p.polygonA, 0.0), coreB = ToCollide(p.polygonB, 0.0);
		p.coreA = cd2MakePolygonShape(&coreA);
		p.coreB = cd2MakePolygonShape(&coreB);
		double angle = 6.28 * u(rng);
		b2Vec2 dir((float)std::cos(angle), (float)std::sin(angle));
		b2Vec2 side(-dir.y, dir.x);
		float miss = (float)(1.6 * u(rng) - 0.8);
		b2Vec2 startA = -2.0f * dir, startB = 2.0f * dir;
		MakeSweep(rng, startA, startA + 3.0f * dir + miss * side, &p.b2sweepA, &p.sweepA);
		MakeSweep(rng, startB, startB - 3.0f * dir, &p.b2sweepB, &p.sweepB);
		cdToiOutput check =
			cd2TimeOfImpact(&p.coreA, &p.sweepA, &p.coreB, &p.sweepB, (cdReal)kSlop, (cdReal)(0.25 * kSlop));
		if (check.state == CD_TOI_OVERLAPPED)
		{
			continue;
		}
		// Shape cast: A placed at its start, B at its start, A moving by 4 units towards B.
		p.b2sweepA.GetTransform(&p.xfA, 0.0f);
		p.b2sweepB.GetTransform(&p.xfB, 0.0f);
		cd2Polygon roundA = ToCollide(p.polygonA, (double)b2_polygonRadius);
		cd2Polygon roundB = ToCollide(p.polygonB, (double)b2_polygonRadius);
		p.worldA = Placed(roundA, p.xfA);
		p.worldB = Placed(roundB, p.xfB);
		b2Vec2 t = 4.0f * dir + miss * side;
		p.translation = cd2MakeVec((cdReal)t.x, (cdReal)t.y);
		pairs.push_back(p);
	}
	return pairs;
}

using Clock = std::chrono::steady_clock;

template <typename F> double NsPerCall(F&& body, double seconds)
{
	long long calls = 0;
	auto start = Clock::now();
	double elapsed = 0.0;
	volatile double sink = 0.0;
	do
	{
		for (int i = 0; i < kPairs; ++i)
		{
			sink = sink + body(i);
		}
		calls += kPairs;
		elapsed = std::chrono::duration<double>(Clock::now() - start).count();
	} while (elapsed < seconds);
	return 1e9 * elapsed / (double)calls;
}

double Median(std::vector<double> samples)
{
	std::sort(samples.begin(), samples.end());
	return samples[samples.size() / 2];
}

struct Figures
{
	double ours, peer;
};

template <typename A, typename B> Figures Compare(A&& ours, B&& peer, int runs, double seconds)
{
	std::vector<double> a, b;
	for (int r = 0; r < runs; ++r)
	{
		a.push_back(NsPerCall(ours, seconds));
		b.push_back(NsPerCall(peer, seconds));
	}
	return Figures{Median(a), Median(b)};
}

template <typename A> double Alone(A&& ours, int runs, double seconds)
{
	std::vector<double> a;
	for (int r = 0; r < runs; ++r)
	{
		a.push_back(NsPerCall(ours, seconds));
	}
	return Median(a);
}

struct Pair3
{
	cd3Shape a, b; // body frames
	cd3Sweep sa, sb;
	cd3Shape worldA, worldB;
	cd3Vec translation;
};

cd3Quat RandomQuat(std::mt19937_64& rng)
{
	std::normal_distribution<double> n(0.0, 1.0);
	double x = n(rng), y = n(rng), z = n(rng), w = n(rng);
	double l = std::sqrt(x * x + y * y + z * z + w * w);
	return cd3MakeQuat((cdReal)(x / l), (cdReal)(y / l), (cdReal)(z / l), (cdReal)(w / l));
}

std::vector<Pair3> MakePairs3(uint64_t seed, const cd3Hull* hull)
{
	std::mt19937_64 rng(seed);
	std::uniform_real_distribution<double> u(0.0, 1.0);
	std::vector<Pair3> pairs(kPairs);
	for (Pair3& p : pairs)
	{
		cd3Box box = {CD3_VEC_ZERO,
					  cd3MakeVec((cdReal)(0.2 + 0.5 * u(rng)), (cdReal)(0.2 + 0.5 * u(rng)),
								 (cdReal)(0.2 + 0.5 * u(rng))),
					  CD3_QUAT_IDENTITY};
		p.a = cd3MakeBoxShape(box);
		p.b = hull != nullptr && u(rng) < 0.5 ? cd3MakeHullShape(hull, CD3_TRANSFORM_IDENTITY) : p.a;
		cd3Vec dir =
			cd3Normalize(cd3MakeVec((cdReal)(u(rng) - 0.5), (cdReal)(u(rng) - 0.5), (cdReal)(u(rng) - 0.5)));
		p.sa.localCenter = p.sb.localCenter = CD3_VEC_ZERO;
		p.sa.center0 = cd3Scale((cdReal)-2.0, dir);
		p.sa.center1 = cd3Scale((cdReal)1.0, dir);
		p.sb.center0 = cd3Scale((cdReal)2.0, dir);
		p.sb.center1 = cd3Scale((cdReal)-1.0, dir);
		p.sa.rotation0 = RandomQuat(rng);
		p.sa.rotation1 = RandomQuat(rng);
		p.sb.rotation0 = RandomQuat(rng);
		p.sb.rotation1 = p.sb.rotation0;
		p.worldA = p.a;
		p.worldA.box.center = p.sa.center0;
		p.worldA.box.rotation = p.sa.rotation0;
		p.worldB = p.a;
		p.worldB.box.center = p.sb.center0;
		p.worldB.box.rotation = p.sb.rotation0;
		p.translation = cd3Scale((cdReal)4.0, dir);
	}
	return pairs;
}
} // namespace

int main(int argc, char** argv)
{
	bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
	int runs = quick ? 3 : 9;
	double seconds = quick ? 0.002 : 0.02;
	std::vector<Pair2> pairs = MakePairs2(42);

	int hits = 0, box2dHits = 0, castHits = 0, failed = 0, box2dFailed = 0;
	long long toiIterations = 0, castIterations = 0, box2dCastIterations = 0;
	int box2dCastHits = 0;
	for (const Pair2& p : pairs)
	{
		cdToiOutput ours =
			cd2TimeOfImpact(&p.coreA, &p.sweepA, &p.coreB, &p.sweepB, (cdReal)kSlop, (cdReal)(0.25 * kSlop));
		hits += ours.state == CD_TOI_HIT;
		failed += ours.state == CD_TOI_FAILED;
		toiIterations += ours.iterations;
		b2TOIInput input;
		input.proxyA.Set(&p.polygonA, 0);
		input.proxyB.Set(&p.polygonB, 0);
		input.sweepA = p.b2sweepA;
		input.sweepB = p.b2sweepB;
		input.tMax = 1.0f;
		b2TOIOutput output;
		b2TimeOfImpact(&output, &input);
		box2dHits += output.state == b2TOIOutput::e_touching;
		box2dFailed += output.state == b2TOIOutput::e_failed;
		b2ShapeCastInput castInput;
		castInput.proxyA.Set(&p.polygonB, 0);
		castInput.proxyB.Set(&p.polygonA, 0);
		castInput.transformA = p.xfB;
		castInput.transformB = p.xfA;
		castInput.translationB.Set((float)p.translation.x, (float)p.translation.y);
		b2ShapeCastOutput castOutput;
		box2dCastHits += b2ShapeCast(&castOutput, &castInput);
		box2dCastIterations += castOutput.iterations;
		cd2CastOutput castOut = cd2ShapeCast(&p.worldA, &p.worldB, p.translation);
		castHits += castOut.hit;
		castIterations += castOut.iterations;
	}

	// --profile-cast / --profile-toi: only that 2D query, for a profiler and for A/B checks on a
	// loaded machine: 100 alternating runs of 10 ms of collide and Box2D, the fastest of each (the
	// least disturbed by other processes).
	bool profileCast = argc > 1 && std::strcmp(argv[1], "--profile-cast") == 0;
	bool profileToi = argc > 1 && std::strcmp(argv[1], "--profile-toi") == 0;
	if (profileCast || profileToi)
	{
		auto collideCast = [&](int i) {
			const Pair2& p = pairs[i];
			return (double)cd2ShapeCast(&p.worldA, &p.worldB, p.translation).fraction;
		};
		auto box2dCast = [&](int i) {
			const Pair2& p = pairs[i];
			b2ShapeCastInput input;
			input.proxyA.Set(&p.polygonB, 0);
			input.proxyB.Set(&p.polygonA, 0);
			input.transformA = p.xfB;
			input.transformB = p.xfA;
			input.translationB.Set((float)p.translation.x, (float)p.translation.y);
			b2ShapeCastOutput output;
			return b2ShapeCast(&output, &input) ? (double)output.lambda : 1.0;
		};
		auto collideToi = [&](int i) {
			const Pair2& p = pairs[i];
			return (double)cd2TimeOfImpact(&p.coreA, &p.sweepA, &p.coreB, &p.sweepB, (cdReal)kSlop,
										   (cdReal)(0.25 * kSlop))
				.t;
		};
		auto box2dToi = [&](int i) {
			const Pair2& p = pairs[i];
			b2TOIInput input;
			input.proxyA.Set(&p.polygonA, 0);
			input.proxyB.Set(&p.polygonB, 0);
			input.sweepA = p.b2sweepA;
			input.sweepB = p.b2sweepB;
			input.tMax = 1.0f;
			b2TOIOutput output;
			b2TimeOfImpact(&output, &input);
			return (double)output.t;
		};
		double ours = 1e30, peer = 1e30;
		for (int r = 0; r < 100; ++r)
		{
			ours = std::min(ours, profileCast ? NsPerCall(collideCast, 0.01) : NsPerCall(collideToi, 0.01));
			peer = std::min(peer, profileCast ? NsPerCall(box2dCast, 0.01) : NsPerCall(box2dToi, 0.01));
		}
		std::printf("2D %s: fastest runs collide %.1f ns, Box2D %.1f ns, ratio %.2f\n",
					profileCast ? "shape cast" : "time of impact", ours, peer, ours / peer);
		return 0;
	}

	Figures toi = Compare(
		[&](int i) {
			const Pair2& p = pairs[i];
			return (double)cd2TimeOfImpact(&p.coreA, &p.sweepA, &p.coreB, &p.sweepB, (cdReal)kSlop,
										   (cdReal)(0.25 * kSlop))
				.t;
		},
		[&](int i) {
			const Pair2& p = pairs[i];
			b2TOIInput input;
			input.proxyA.Set(&p.polygonA, 0);
			input.proxyB.Set(&p.polygonB, 0);
			input.sweepA = p.b2sweepA;
			input.sweepB = p.b2sweepB;
			input.tMax = 1.0f;
			b2TOIOutput output;
			b2TimeOfImpact(&output, &input);
			return (double)output.t;
		},
		runs, seconds);

	Figures cast = Compare(
		[&](int i) {
			const Pair2& p = pairs[i];
			return (double)cd2ShapeCast(&p.worldA, &p.worldB, p.translation).fraction;
		},
		[&](int i) {
			const Pair2& p = pairs[i];
			b2ShapeCastInput input;
			input.proxyA.Set(&p.polygonB, 0); // static
			input.proxyB.Set(&p.polygonA, 0); // moving
			input.transformA = p.xfB;
			input.transformB = p.xfA;
			input.translationB.Set((float)p.translation.x, (float)p.translation.y);
			b2ShapeCastOutput output;
			bool hit = b2ShapeCast(&output, &input);
			return hit ? (double)output.lambda : 1.0;
		},
		runs, seconds);

	cd3Hull* hull = nullptr;
	cd3MakeCylinderHull((cdReal)0.4, (cdReal)0.4, 16, &hull);
	std::vector<Pair3> pairs3 = MakePairs3(7, hull);
	double cast3 = Alone(
		[&](int i) {
			const Pair3& p = pairs3[i];
			return (double)cd3ShapeCast(&p.worldA, &p.worldB, p.translation).fraction;
		},
		runs, seconds);
	double toi3 = Alone(
		[&](int i) {
			const Pair3& p = pairs3[i];
			return (double)cd3TimeOfImpact(&p.a, &p.sa, &p.b, &p.sb, (cdReal)kSlop, (cdReal)(0.25 * kSlop)).t;
		},
		runs, seconds);
	cd3DestroyHull(hull);

	std::printf("collide_bench_cast (%s, %d pairs, median of %d runs)\n",
				sizeof(cdReal) == 8 ? "double" : "float", kPairs, runs);
	std::printf(
		"2D TOI hits: collide %d, Box2D %d; failed: collide %d, Box2D %d; collide's mean iterations %.1f\n",
		hits, box2dHits, failed, box2dFailed, (double)toiIterations / kPairs);
	std::printf("2D shape cast hits: collide %d, Box2D %d; mean iterations: collide %.1f, Box2D %.1f\n",
				castHits, box2dCastHits, (double)castIterations / kPairs,
				(double)box2dCastIterations / kPairs);
	std::printf("%-36s %10s %10s %8s\n", "query", "collide", "Box2D", "ratio");
	std::printf("%-36s %10.1f %10.1f %8.2f\n", "2D time of impact (polygons)", toi.ours, toi.peer,
				toi.ours / toi.peer);
	std::printf("%-36s %10.1f %10.1f %8.2f\n", "2D shape cast (rounded polygons)", cast.ours, cast.peer,
				cast.ours / cast.peer);
	std::printf("%-36s %10.1f %10s %8s\n", "3D shape cast (box, box)", cast3, "-", "-");
	std::printf("%-36s %10.1f %10s %8s\n", "3D time of impact (box, box/hull16)", toi3, "-", "-");
	return 0;
}
