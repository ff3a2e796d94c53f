// collide_bench_hull_peers: ms per convex hull build, collide's cd3ComputeHull against Bullet's
// btConvexHullComputer (Debian libbullet-dev) and, when found, qhull (libqhull-dev, reentrant
// qh_new_qhull with its default options, which merge coplanar facets), on the same point sets in
// the same run. Each row prints the hull's vertex and face counts per library, to show that they
// build the same hull (counts may differ by a few where triangles are coplanar within one
// library's tolerance and not another's), and collide's time relative to Bullet's.
//
// Each figure is the median of 5 rounds; a round builds the hull of the same points enough times
// to take about 10 ms, and the libraries' rounds are interleaved so that all see the same load.
// Usage: collide_bench_hull_peers [--quick]
#include <LinearMath/btConvexHullComputer.h>
#ifdef COLLIDE_BENCH_HAVE_QHULL
extern "C" {
#include <libqhull_r/qhull_ra.h>
}
#endif

#include "collide/collide.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace
{
struct PointSet
{
	std::string name;
	std::vector<cd3Vec> points;
};

struct Result
{
	double ms = 0.0;
	int vertices = 0;
	int faces = 0;
	bool ok = true;
};

cd3Vec Vec(double x, double y, double z)
{
	return cd3MakeVec((cdReal)x, (cdReal)y, (cdReal)z);
}

cd3Vec InBall(std::mt19937_64& rng)
{
	std::uniform_real_distribution<double> u(-1.0, 1.0);
	for (;;)
	{
		double x = u(rng), y = u(rng), z = u(rng);
		if (x * x + y * y + z * z <= 1.0)
		{
			return Vec(x, y, z);
		}
	}
}

cd3Vec OnSphere(std::mt19937_64& rng)
{
	std::normal_distribution<double> g(0.0, 1.0);
	for (;;)
	{
		double x = g(rng), y = g(rng), z = g(rng);
		double n = std::sqrt(x * x + y * y + z * z);
		if (n > 1e-6)
		{
			return Vec(x / n, y / n, z / n);
		}
	}
}

std::vector<PointSet> MakeSets()
{
	std::mt19937_64 rng(0x5eed1234u);
	std::vector<PointSet> sets;
	PointSet cube{"cube, 8 corners", {}};
	for (int i = 0; i < 8; ++i)
	{
		cube.points.push_back(Vec((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0));
	}
	sets.push_back(cube);
	for (int n : {100, 1000, 10000})
	{
		PointSet s{"in ball, " + std::to_string(n), {}};
		for (int i = 0; i < n; ++i)
		{
			s.points.push_back(InBall(rng));
		}
		sets.push_back(s);
	}
	for (int n : {256, 4096, 16384})
	{
		PointSet s{"on sphere, " + std::to_string(n), {}};
		for (int i = 0; i < n; ++i)
		{
			s.points.push_back(OnSphere(rng));
		}
		sets.push_back(s);
	}
	{
		/* Two rings of 128 and 1000 points inside: many coplanar points on the caps. */
		PointSet s{"cylinder, 2x128 + 1000 in", {}};
		std::uniform_real_distribution<double> u(-1.0, 1.0);
		for (int i = 0; i < 128; ++i)
		{
			double a = 2.0 * 3.14159265358979323846 * i / 128.0;
			s.points.push_back(Vec(std::cos(a), -1.0, std::sin(a)));
			s.points.push_back(Vec(std::cos(a), 1.0, std::sin(a)));
		}
		for (int i = 0; i < 1000; ++i)
		{
			cd3Vec p = InBall(rng);
			s.points.push_back(Vec(0.99 * (double)p.x, u(rng), 0.99 * (double)p.z));
		}
		sets.push_back(s);
	}
	{
		/* A disc of radius 1 and thickness 1e-3: nearly flat. */
		PointSet s{"nearly flat, 1000", {}};
		for (int i = 0; i < 1000; ++i)
		{
			cd3Vec p = OnSphere(rng);
			s.points.push_back(Vec((double)p.x, 5e-4 * (double)p.y, (double)p.z));
		}
		sets.push_back(s);
	}
	{
		/* 200 points on a sphere, each given 10 times, shuffled. */
		PointSet s{"duplicates, 200 x 10", {}};
		std::vector<cd3Vec> base;
		for (int i = 0; i < 200; ++i)
		{
			base.push_back(OnSphere(rng));
		}
		for (int k = 0; k < 10; ++k)
		{
			s.points.insert(s.points.end(), base.begin(), base.end());
		}
		std::shuffle(s.points.begin(), s.points.end(), rng);
		sets.push_back(s);
	}
	return sets;
}

using Clock = std::chrono::steady_clock;

/* One build; returns false on failure and fills the counts. */
using Builder = std::function<bool(const PointSet&, int& vertices, int& faces)>;

bool BuildCollide(const PointSet& s, int& vertices, int& faces)
{
	cd3Hull* hull = nullptr;
	if (cd3ComputeHull(s.points.data(), (int)s.points.size(), &hull) != CD_OK)
	{
		return false;
	}
	vertices = hull->vertexCount;
	faces = hull->faceCount;
	cd3DestroyHull(hull);
	return true;
}

btConvexHullComputer g_bullet;

bool BuildBullet(const PointSet& s, int& vertices, int& faces)
{
	btScalar r = g_bullet.compute(&s.points[0].x, (int)sizeof(cd3Vec), (int)s.points.size(), 0, 0);
	vertices = g_bullet.vertices.size();
	faces = g_bullet.faces.size();
	return r >= 0 && faces > 0;
}

#ifdef COLLIDE_BENCH_HAVE_QHULL
std::vector<coordT> g_qhullCoords;

bool BuildQhull(const PointSet& s, int& vertices, int& faces)
{
	/* qhull reads doubles; the conversion is part of its cost as it would be for a caller. */
	g_qhullCoords.resize(3 * s.points.size());
	for (size_t i = 0; i < s.points.size(); ++i)
	{
		g_qhullCoords[3 * i] = (coordT)s.points[i].x;
		g_qhullCoords[3 * i + 1] = (coordT)s.points[i].y;
		g_qhullCoords[3 * i + 2] = (coordT)s.points[i].z;
	}
	qhT state;
	qhT* qh = &state;
	qh_zero(qh, stderr);
	char flags[] = "qhull";
	int exitCode =
		qh_new_qhull(qh, 3, (int)s.points.size(), g_qhullCoords.data(), False, flags, nullptr, stderr);
	if (exitCode == 0)
	{
		vertices = qh->num_vertices;
		faces = qh->num_facets;
	}
	qh_freeqhull(qh, !qh_ALL);
	int currentLong = 0, totalLong = 0;
	qh_memfreeshort(qh, &currentLong, &totalLong);
	return exitCode == 0;
}
#endif

/* Builds the hull `repeats` times; ms per build. */
double TimeBuilds(const Builder& build, const PointSet& s, int repeats, Result& result)
{
	auto start = Clock::now();
	for (int r = 0; r < repeats; ++r)
	{
		int v = 0, f = 0;
		if (!build(s, v, f))
		{
			result.ok = false;
		}
		result.vertices = v;
		result.faces = f;
	}
	std::chrono::duration<double, std::milli> elapsed = Clock::now() - start;
	return elapsed.count() / repeats;
}

double Median(std::vector<double> v)
{
	std::sort(v.begin(), v.end());
	return v[v.size() / 2];
}
} // namespace

int main(int argc, char** argv)
{
	bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
	std::vector<std::pair<const char*, Builder>> peers = {{"collide", BuildCollide}, {"Bullet", BuildBullet}};
#ifdef COLLIDE_BENCH_HAVE_QHULL
	peers.push_back({"qhull", BuildQhull});
#endif
	std::printf("collide hull build benchmark (%s, cdReal = %s): ms per build, median of %d rounds\n\n",
				quick ? "quick: one build each, no timing claims" : "timed",
				cdGetRealIsDouble() ? "double" : "float", quick ? 1 : 5);
	std::printf("| point set                  |");
	for (auto& peer : peers)
	{
		std::printf(" %-8s ms |  V / F      |", peer.first);
	}
	std::printf(" collide/Bullet |\n|----------------------------|");
	for (size_t i = 0; i < peers.size(); ++i)
	{
		std::printf("-------------|-------------|");
	}
	std::printf("----------------|\n");
	int failures = 0;
	for (const PointSet& s : MakeSets())
	{
		std::vector<Result> results(peers.size());
		std::vector<int> repeats(peers.size(), 1);
		if (!quick)
		{
			/* Calibrate each peer to about 10 ms per round. */
			for (size_t p = 0; p < peers.size(); ++p)
			{
				double once = TimeBuilds(peers[p].second, s, 1, results[p]);
				once = TimeBuilds(peers[p].second, s, 1, results[p]);
				repeats[p] = std::max(1, std::min(2000, (int)(10.0 / std::max(once, 1e-4))));
			}
		}
		std::vector<std::vector<double>> rounds(peers.size());
		for (int round = 0; round < (quick ? 1 : 5); ++round)
		{
			for (size_t p = 0; p < peers.size(); ++p)
			{
				rounds[p].push_back(TimeBuilds(peers[p].second, s, repeats[p], results[p]));
			}
		}
		std::printf("| %-26s |", s.name.c_str());
		for (size_t p = 0; p < peers.size(); ++p)
		{
			results[p].ms = Median(rounds[p]);
			if (results[p].ok)
			{
				std::printf(" %11.3f | %5d/%-5d |", results[p].ms, results[p].vertices, results[p].faces);
			}
			else
			{
				std::printf(" %11s | %11s |", "failed", "");
				failures += p == 0;
			}
		}
		std::printf(" %14.2f |\n", results[0].ms / results[1].ms);
	}
	return failures == 0 ? 0 : 1;
}
