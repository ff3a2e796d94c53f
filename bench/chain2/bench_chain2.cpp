// collide_bench_chain2: ns per call of collide's 2D chain queries on a 10k-segment terrain, with
// Box2D 2.4's b2ChainShape on the same terrain, boxes and rays in the same run.
//
// The terrain is a bumpy polyline of 10,000 segments about 1 m long. Box2D has no whole-chain
// query: a b2World puts each child edge of a chain in its broadphase tree and then collides the
// pairs it finds, so its "whole chain" figure is the same work done by hand: a b2DynamicTree over
// the child edges (built like a world's: CreateProxy per child, fattened boxes), a tree query per
// box, and GetChildEdge + b2CollideEdgeAndPolygon per edge found. Its ray cast is the tree's ray
// cast calling b2ChainShape::RayCast per child. The "same edge" rows time one edge manifold on
// the very edges that touch each box, without any search.
// Boxes (1 x 1, slightly rotated) rest on the terrain sunk by up to 0.02; contacts are reported up
// to 2 * b2_polygonRadius apart (collide: that speculative distance). Each figure is the median of
// 9 runs of about 20 ms of thread CPU time (3 with --quick), collide's and Box2D's runs alternating.
// The edge rows time cd2CollideChainSegmentPolygonDirect (the dedicated routine cd2CollideChain
// runs) and, for comparison, the public cd2CollideChainSegmentPolygon (manifold2.c's generic path).
// Usage: collide_bench_chain2 [--quick | --profile <chain|edge|ray>-<collide|box2d> | --profile
// edge-generic | --profile circle-<collide|box2d> | --profile capsule-collide | --profile none]
#include <box2d/box2d.h>

#include "collide/chain2.h"
#include "query/chain_manifold2.h" // internal: the dedicated segment-polygon manifold

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <random>
#include <string>
#include <vector>

namespace
{
const int kBoxes = 1024;
const int kRays = 1024;

double TerrainHeight(double x)
{
	return 2.0 * std::sin(0.05 * x) + 0.3 * std::sin(0.7 * x) + 0.1 * std::sin(2.3 * x);
}

// Right to left (collide's and Box2D's one-sided chains both face the right of each segment).
std::vector<cd2Vec> TerrainPoints(int segments)
{
	std::vector<cd2Vec> points;
	double half = 0.5 * segments;
	for (int i = 0; i <= segments; ++i)
	{
		double x = half - i;
		points.push_back(cd2MakeVec((cdReal)x, (cdReal)TerrainHeight(x)));
	}
	return points;
}

struct Scene
{
	cd2Chain* chain = nullptr;
	b2ChainShape b2chain;
	b2DynamicTree tree;
	std::vector<cd2Shape> boxes;
	std::vector<b2PolygonShape> b2boxes;
	std::vector<b2Transform> b2boxTransforms;
	std::vector<cd2Ray> rays;
	std::vector<b2RayCastInput> b2rays;
	// The (box, edge) pairs in contact, for the per-edge rows.
	std::vector<int> pairBox, pairEdge;
	std::vector<cd2Polygon> boxPolygons;
};

void BuildScene(Scene& scene, int segments, std::mt19937_64& rng)
{
	std::uniform_real_distribution<double> u(0.0, 1.0);
	std::vector<cd2Vec> points = TerrainPoints(segments);
	if (cd2CreateChain(points.data(), (int)points.size(), false, &scene.chain) != CD_OK)
	{
		std::fprintf(stderr, "cd2CreateChain failed\n");
		std::exit(1);
	}
	std::vector<b2Vec2> b2points;
	for (const cd2Vec& p : points)
	{
		b2points.push_back(b2Vec2((float)p.x, (float)p.y));
	}
	b2Vec2 before = b2points[0] + (b2points[0] - b2points[1]);
	b2Vec2 after = b2points.back() + (b2points.back() - b2points[b2points.size() - 2]);
	scene.b2chain.CreateChain(b2points.data(), (int32)b2points.size(), before, after);
	b2Transform identity;
	identity.SetIdentity();
	for (int32 i = 0; i < scene.b2chain.GetChildCount(); ++i)
	{
		b2AABB box;
		scene.b2chain.ComputeAABB(&box, identity, i);
		scene.tree.CreateProxy(box, (void*)(intptr_t)i);
	}

	double half = 0.5 * segments - 2.0;
	for (int i = 0; i < kBoxes; ++i)
	{
		double x = -half + 2.0 * half * u(rng);
		double angle = (u(rng) - 0.5) * 0.2;
		double sink = 0.02 * u(rng);
		// Rest the box on the terrain: lift its bottom face until it clears the terrain everywhere
		// along it (sampled), then sink it a little.
		double c = std::cos(angle), s = std::sin(angle);
		double lift = -1e30;
		for (int k = 0; k <= 64; ++k)
		{
			double along = -0.5 + k / 64.0;
			double bx = x + along * c + 0.5 * s,
				   by = along * s - 0.5 * c; // bottom edge, box centre at (x, 0)
			lift = std::max(lift, TerrainHeight(bx) - by);
		}
		double y = lift - sink;
		cd2Box box = {cd2MakeVec((cdReal)x, (cdReal)y), cd2MakeVec(CD_R(0.5), CD_R(0.5)),
					  cd2MakeRot((cdReal)angle)};
		scene.boxes.push_back(cd2MakeBoxShape(box));
		cd2Polygon polygon;
		cd2MakeBoxPolygon(box, &polygon);
		scene.boxPolygons.push_back(polygon);
		b2PolygonShape shape;
		shape.SetAsBox(0.5f, 0.5f);
		scene.b2boxes.push_back(shape);
		b2Transform xf;
		xf.Set(b2Vec2((float)x, (float)y), (float)angle);
		scene.b2boxTransforms.push_back(xf);
	}
	for (int i = 0; i < kRays; ++i)
	{
		double x = -half + 2.0 * half * u(rng);
		double angle = -0.5 * M_PI + (u(rng) - 0.5) * 2.0;
		double length = 5.0 + 15.0 * u(rng);
		cd2Ray ray = {cd2MakeVec((cdReal)x, (cdReal)(TerrainHeight(x) + 3.0)),
					  cd2MakeVec((cdReal)(length * std::cos(angle)), (cdReal)(length * std::sin(angle)))};
		scene.rays.push_back(ray);
		b2RayCastInput input;
		input.p1 = b2Vec2((float)ray.origin.x, (float)ray.origin.y);
		input.p2 = input.p1 + b2Vec2((float)ray.translation.x, (float)ray.translation.y);
		input.maxFraction = 1.0f;
		scene.b2rays.push_back(input);
	}
}

volatile int64_t g_sink = 0;

bool CountSegment(int, void* context)
{
	++*(int*)context;
	return true;
}

// CPU time of this thread: on a machine shared with other jobs, the time the thread was not
// running does not count (wall-clock figures there were 2-4 times too high and erratic).
double ThreadSeconds()
{
	timespec t;
	clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
	return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

template <typename F> double TimeOnce(int count, F f, int reps)
{
	double start = ThreadSeconds();
	int64_t sum = 0;
	for (int r = 0; r < reps; ++r)
	{
		for (int i = 0; i < count; ++i)
		{
			sum += f(i);
		}
	}
	double elapsed = ThreadSeconds() - start;
	g_sink += sum;
	return elapsed * 1e9 / ((double)reps * (double)count);
}

template <typename F> int Calibrate(int count, F f, double seconds)
{
	int reps = 1;
	while (reps < (1 << 20) && TimeOnce(count, f, reps) * 1e-9 * (double)reps * (double)count < seconds)
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

template <typename F, typename G> Figures Compare(int count, F mine, G theirs, int runs, double seconds)
{
	int repsMine = Calibrate(count, mine, seconds), repsTheirs = Calibrate(count, theirs, seconds);
	std::vector<double> a, b;
	for (int run = 0; run < runs; ++run)
	{
		a.push_back(TimeOnce(count, mine, repsMine));
		b.push_back(TimeOnce(count, theirs, repsTheirs));
	}
	return Figures{Median(a), Median(b)};
}

template <typename F> double TimeAlone(int count, F f, int runs, double seconds)
{
	int reps = Calibrate(count, f, seconds);
	std::vector<double> a;
	for (int run = 0; run < runs; ++run)
	{
		a.push_back(TimeOnce(count, f, reps));
	}
	return Median(a);
}

struct EdgeQuery
{
	const b2ChainShape* chain;
	const b2DynamicTree* tree;
	const b2PolygonShape* box;
	b2Transform boxTransform, identity;
	int points;
	bool QueryCallback(int32 proxyId)
	{
		int32 child = (int32)(intptr_t)tree->GetUserData(proxyId);
		b2EdgeShape edge;
		chain->GetChildEdge(&edge, child);
		b2Manifold manifold;
		b2CollideEdgeAndPolygon(&manifold, &edge, identity, box, boxTransform);
		points += manifold.pointCount;
		return true;
	}
};

struct RayQuery
{
	const b2ChainShape* chain;
	const b2DynamicTree* tree;
	b2Transform identity;
	float best;
	float RayCastCallback(const b2RayCastInput& input, int32 proxyId)
	{
		int32 child = (int32)(intptr_t)tree->GetUserData(proxyId);
		b2RayCastOutput output;
		if (chain->RayCast(&output, input, identity, child))
		{
			best = output.fraction;
			return output.fraction;
		}
		return input.maxFraction;
	}
};
} // namespace

int main(int argc, char** argv)
{
	bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
	const char* profile = argc > 2 && std::strcmp(argv[1], "--profile") == 0 ? argv[2] : nullptr;
	int runs = quick ? 3 : 9;
	double seconds = quick ? 0.002 : 0.02;
	const cdReal speculative = (cdReal)(2.0 * b2_polygonRadius);
	const cd2Transform identity = {cd2MakeVec(CD_R(0.0), CD_R(0.0)), cd2MakeRot(CD_R(0.0))};
	b2Transform b2identity;
	b2identity.SetIdentity();

	std::mt19937_64 rng(7);
	Scene scene;
	BuildScene(scene, 10000, rng);

	// The touching (box, edge) pairs, found by collide (Box2D finds the same edges: checked below).
	int collidePoints = 0;
	for (int i = 0; i < kBoxes; ++i)
	{
		cd2Manifold manifolds[16];
		int segments[16];
		int count = cd2CollideChain(scene.chain, identity, &scene.boxes[(size_t)i], speculative, manifolds,
									16, segments);
		for (int k = 0; k < count; ++k)
		{
			scene.pairBox.push_back(i);
			scene.pairEdge.push_back(segments[k]);
			collidePoints += manifolds[k].pointCount;
		}
	}
	int candidates = 0;
	for (int i = 0; i < kBoxes; ++i)
	{
		cd2Aabb bounds = cd2AabbInflate(cd2ComputeShapeAabb(&scene.boxes[(size_t)i]), speculative);
		cd2Chain_QueryAabb(scene.chain, identity, bounds, CountSegment, &candidates);
	}
	int box2dPoints = 0;
	for (int i = 0; i < kBoxes; ++i)
	{
		EdgeQuery query = {&scene.b2chain,
						   &scene.tree,
						   &scene.b2boxes[(size_t)i],
						   scene.b2boxTransforms[(size_t)i],
						   b2identity,
						   0};
		b2AABB box;
		scene.b2boxes[(size_t)i].ComputeAABB(&box, scene.b2boxTransforms[(size_t)i], 0);
		scene.tree.Query(&query, box);
		box2dPoints += query.points;
	}

	std::printf("collide_bench_chain2 (%s, cdReal = %s): ns of thread CPU time per call, median of %d runs\n",
				quick ? "quick" : "full", sizeof(cdReal) == sizeof(double) ? "double" : "float", runs);
	std::printf(
		"terrain: %d segments; %d boxes touch %zu edges (%.2f candidate edges per box), %d contact points "
		"(box2d: %d); box2d tree height %d\n",
		cd2Chain_GetSegmentCount(scene.chain), kBoxes, scene.pairEdge.size(), (double)candidates / kBoxes,
		collidePoints, box2dPoints, scene.tree.GetHeight());
	auto collideChain = [&](int i) {
		cd2Manifold manifolds[16];
		return cd2CollideChain(scene.chain, identity, &scene.boxes[(size_t)i], speculative, manifolds, 16,
							   nullptr);
	};
	auto box2dChain = [&](int i) {
		EdgeQuery query = {&scene.b2chain,
						   &scene.tree,
						   &scene.b2boxes[(size_t)i],
						   scene.b2boxTransforms[(size_t)i],
						   b2identity,
						   0};
		b2AABB box;
		scene.b2boxes[(size_t)i].ComputeAABB(&box, scene.b2boxTransforms[(size_t)i], 0);
		scene.tree.Query(&query, box);
		return query.points;
	};
	auto collideEdge = [&](int k) {
		cd2ChainSegment segment = cd2Chain_GetSegment(scene.chain, scene.pairEdge[(size_t)k]);
		return cd2CollideChainSegmentPolygonDirect(
				   &segment, &scene.boxPolygons[(size_t)scene.pairBox[(size_t)k]], speculative)
			.pointCount;
	};
	auto collideEdgeGeneric = [&](int k) {
		cd2ChainSegment segment = cd2Chain_GetSegment(scene.chain, scene.pairEdge[(size_t)k]);
		return cd2CollideChainSegmentPolygon(&segment, &scene.boxPolygons[(size_t)scene.pairBox[(size_t)k]],
											 speculative)
			.pointCount;
	};
	auto box2dEdge = [&](int k) {
		b2EdgeShape edge;
		scene.b2chain.GetChildEdge(&edge, scene.pairEdge[(size_t)k]);
		b2Manifold manifold;
		size_t box = (size_t)scene.pairBox[(size_t)k];
		b2CollideEdgeAndPolygon(&manifold, &edge, b2identity, &scene.b2boxes[box],
								scene.b2boxTransforms[box]);
		return manifold.pointCount;
	};
	// Circles and capsules on the same edges: the circle inscribed in each box, the capsule along
	// its bottom half (Box2D 2.4 has circles, not capsules: the capsule row compares collide's
	// dedicated routine with its generic path).
	auto circleOf = [&](int k) {
		const cd2Box& box = scene.boxes[(size_t)scene.pairBox[(size_t)k]].box;
		cd2Circle circle = {box.center, CD_R(0.5)};
		return circle;
	};
	auto capsuleOf = [&](int k) {
		const cd2Box& box = scene.boxes[(size_t)scene.pairBox[(size_t)k]].box;
		cd2Vec axis = cd2RotateVector(box.rotation, cd2MakeVec(CD_R(0.25), CD_R(0.0)));
		cd2Capsule capsule = {cd2Sub(box.center, axis), cd2Add(box.center, axis), CD_R(0.5)};
		return capsule;
	};
	auto collideCircleEdge = [&](int k) {
		cd2ChainSegment segment = cd2Chain_GetSegment(scene.chain, scene.pairEdge[(size_t)k]);
		return cd2CollideChainSegmentCircleDirect(&segment, circleOf(k), speculative).pointCount;
	};
	auto box2dCircleEdge = [&](int k) {
		b2EdgeShape edge;
		scene.b2chain.GetChildEdge(&edge, scene.pairEdge[(size_t)k]);
		b2CircleShape circle;
		circle.m_radius = 0.5f;
		b2Transform xf;
		cd2Circle c = circleOf(k);
		xf.Set(b2Vec2((float)c.center.x, (float)c.center.y), 0.0f);
		b2Manifold manifold;
		b2CollideEdgeAndCircle(&manifold, &edge, b2identity, &circle, xf);
		return manifold.pointCount;
	};
	auto collideCircleEdgeGeneric = [&](int k) {
		cd2ChainSegment segment = cd2Chain_GetSegment(scene.chain, scene.pairEdge[(size_t)k]);
		return cd2CollideChainSegmentCircle(&segment, circleOf(k), speculative).pointCount;
	};
	auto collideCapsuleEdge = [&](int k) {
		cd2ChainSegment segment = cd2Chain_GetSegment(scene.chain, scene.pairEdge[(size_t)k]);
		return cd2CollideChainSegmentCapsuleDirect(&segment, capsuleOf(k), speculative).pointCount;
	};
	auto collideCapsuleEdgeGeneric = [&](int k) {
		cd2ChainSegment segment = cd2Chain_GetSegment(scene.chain, scene.pairEdge[(size_t)k]);
		return cd2CollideChainSegmentCapsule(&segment, capsuleOf(k), speculative).pointCount;
	};
	auto collideRay = [&](int i) {
		cd2RayHit hit;
		return (int)cd2RaycastChain(scene.chain, identity, scene.rays[(size_t)i], &hit, nullptr);
	};
	auto box2dRay = [&](int i) {
		RayQuery query = {&scene.b2chain, &scene.tree, b2identity, -1.0f};
		scene.tree.RayCast(&query, scene.b2rays[(size_t)i]);
		return (int)(query.best >= 0.0f);
	};
	int pairs = (int)scene.pairEdge.size();

	// --profile <case>: run one function a fixed number of times and nothing else (for perf).
	if (profile != nullptr)
	{
		const int reps = 2000;
		std::string which = profile;
		double ns = 0.0;
		if (which == "chain-collide")
			ns = TimeOnce(kBoxes, collideChain, reps);
		else if (which == "chain-box2d")
			ns = TimeOnce(kBoxes, box2dChain, reps);
		else if (which == "edge-collide")
			ns = TimeOnce(pairs, collideEdge, reps);
		else if (which == "edge-generic")
			ns = TimeOnce(pairs, collideEdgeGeneric, reps);
		else if (which == "circle-collide")
			ns = TimeOnce(pairs, collideCircleEdge, reps);
		else if (which == "circle-box2d")
			ns = TimeOnce(pairs, box2dCircleEdge, reps);
		else if (which == "capsule-collide")
			ns = TimeOnce(pairs, collideCapsuleEdge, reps);
		else if (which == "edge-box2d")
			ns = TimeOnce(pairs, box2dEdge, reps);
		else if (which == "ray-collide")
			ns = TimeOnce(kRays, collideRay, reps);
		else if (which == "ray-box2d")
			ns = TimeOnce(kRays, box2dRay, reps);
		std::printf("profile %s: %.1f ns per call (thread CPU time)\n", profile, ns);
		cd2DestroyChain(scene.chain);
		return 0;
	}

	std::printf("%-52s %10s %10s %8s\n", "case", "collide", "box2d 2.4", "ratio");
	auto row = [&](const char* name, Figures f) {
		std::printf("%-52s %10.1f %10.1f %8.2f\n", name, f.mine, f.theirs, f.mine / f.theirs);
	};
	// Whole chain: search + one manifold per touching edge.
	row("box vs 10k-segment chain (search + manifolds)",
		Compare(kBoxes, collideChain, box2dChain, runs, seconds));
	// One manifold on the same child edge.
	row("box vs one chain edge (same edges)", Compare(pairs, collideEdge, box2dEdge, runs, seconds));
	row("  same, previous generic core-core path",
		Compare(pairs, collideEdgeGeneric, box2dEdge, runs, seconds));
	row("circle vs one chain edge (same edges)",
		Compare(pairs, collideCircleEdge, box2dCircleEdge, runs, seconds));
	row("  same, previous generic path",
		Compare(pairs, collideCircleEdgeGeneric, box2dCircleEdge, runs, seconds));
	{
		Figures f = Compare(pairs, collideCapsuleEdge, collideCapsuleEdgeGeneric, runs, seconds);
		std::printf("%-52s %10.1f %10.1f %8.2f  (second column: collide's previous generic path)\n",
					"capsule vs one chain edge (same edges)", f.mine, f.theirs, f.mine / f.theirs);
	}
	// Ray casts: closest hit on the whole chain.
	row("ray cast vs 10k-segment chain", Compare(kRays, collideRay, box2dRay, runs, seconds));

	// Scaling of the whole-chain query with the chain's length (collide only).
	std::printf("\nscaling (collide only): box vs chain, ns per call\n");
	for (int segments : {1000, 10000, 100000})
	{
		std::mt19937_64 sceneRng(11);
		Scene s;
		BuildScene(s, segments, sceneRng);
		double ns = TimeAlone(
			kBoxes,
			[&](int i) {
				cd2Manifold manifolds[16];
				return cd2CollideChain(s.chain, identity, &s.boxes[(size_t)i], speculative, manifolds, 16,
									   nullptr);
			},
			runs, seconds);
		double rayNs = TimeAlone(
			kRays,
			[&](int i) {
				cd2RayHit hit;
				return (int)cd2RaycastChain(s.chain, identity, s.rays[(size_t)i], &hit, nullptr);
			},
			runs, seconds);
		std::printf("%7d segments: collide %8.1f  ray cast %8.1f\n", segments, ns, rayNs);
		cd2DestroyChain(s.chain);
	}
	cd2DestroyChain(scene.chain);
	return 0;
}
