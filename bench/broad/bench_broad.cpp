// collide_bench_broad: collide's broadphase structures against Bullet, FCL and Box2D on the same
// deterministic scenes. For each dimension, N and scene every structure gets the same boxes and
// the same moves; per frame it is told the moved boxes and must produce the complete set of
// overlapping pairs, counted on the tight boxes. The counts must agree (and match a reference
// sweep for N <= 100,000), else the program exits with status 1.
#include "bench_broad.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <malloc.h>
#include <time.h>
#include <map>
#include <sstream>

namespace bench
{

// ---- scene and pair list (the shared C module) -------------------------------------------------

void Scene::Init(int dimension, int count, SceneKind sceneKind, uint64_t seed)
{
	broadSceneFree(&scene_);
	if (!broadSceneInit(&scene_, dimension, count,
						sceneKind == SceneKind::Mix ? BROAD_SCENE_MIX : BROAD_SCENE_MOVING, seed))
	{
		std::fprintf(stderr, "cannot build a %dD scene of %d boxes\n", dimension, count);
		std::exit(2);
	}
	dim = scene_.dim;
	n = scene_.n;
	kind = sceneKind;
	worldSize = scene_.worldSize;
	boxes = View<Box>{scene_.boxes, size_t(scene_.n)};
	displacement = View<float>{scene_.displacement, size_t(scene_.n) * 3};
	moved = View<int>{scene_.moved, 0};
	queries = View<Box>{scene_.queries, size_t(scene_.queryCount)};
	rays = View<Ray>{scene_.rays, size_t(scene_.queryCount)};
}

void Scene::Step(int)
{
	broadSceneStep(&scene_);
	moved.count = size_t(scene_.movedCount);
}

void PairList::Reset(int boxCount)
{
	broadPairListFree(&list_);
	if (!broadPairListInit(&list_, boxCount))
	{
		std::fprintf(stderr, "out of memory for the pair list of %d boxes\n", boxCount);
		std::exit(2);
	}
}

// --cpu-time: frames are timed by the thread's CPU clock, which leaves out the time the thread
// waits for a core while other programs share the machine (the cache they evict still counts).
bool gCpuTime = false;

double FrameClock()
{
	if (gCpuTime)
	{
		timespec now;
		clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
		return double(now.tv_sec) + 1e-9 * double(now.tv_nsec);
	}
	return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

size_t HeapBytes()
{
	struct mallinfo2 info = mallinfo2();
	return info.uordblks + info.hblkhd;
}

} // namespace bench

// ---- harness ---------------------------------------------------------------------------------

namespace
{

using namespace bench;
using Clock = std::chrono::steady_clock;

double Seconds(Clock::time_point a, Clock::time_point b)
{
	return std::chrono::duration<double>(b - a).count();
}

struct Result
{
	int dim = 3;
	int n = 0;
	SceneKind kind = SceneKind::Moving;
	std::string name;
	bool peer = false;
	double buildMs = 0, frameMs = 0, queryUs = 0, rayUs = 0;
	// Mean and slowest of the timed frames: a structure whose work comes in bursts (Bullet's dbvt
	// optimizes its trees by stages) can show a median well below its cost per frame over time.
	double frameMeanMs = 0, frameMaxMs = 0;
	double heapBytesPerProxy = 0, reportedBytesPerProxy = 0;
	size_t pairs = 0, queryHits = 0, rayHits = 0;
	bool rayMeasured = false;
	int framesRun = 0;
	std::string extra;
};

struct Options
{
	std::vector<int> dims = {3};
	std::vector<int> ns = {10000};
	std::vector<SceneKind> scenes = {SceneKind::Moving};
	std::vector<std::string> structures;
	int frames = 10;
	int warmup = 30; // untimed frames first, so that fat boxes reach their steady state
	double maxFrameSeconds = 20.0;
	// --evict-mb: megabytes of other memory read after each (untimed) scene step; see EvictCaches.
	int evictMegabytes = 0;
	std::string svgPath, csvPath, markdownPath;
	std::string frameTimesPath;			 // appends each row's timed frames, one line per row
	std::vector<std::string> mergePaths; // earlier --csv outputs to include in the SVG and CSV
};

std::vector<std::string> Split(const std::string& text)
{
	std::vector<std::string> parts;
	std::stringstream stream(text);
	std::string part;
	while (std::getline(stream, part, ','))
	{
		if (!part.empty())
		{
			parts.push_back(part);
		}
	}
	return parts;
}

const char* SceneName(SceneKind kind)
{
	return kind == SceneKind::Moving ? "moving" : "mix";
}

void Usage()
{
	std::printf(
		"usage: collide_bench_broad [--dim 2|3|2,3] [--n N[,N...]] [--scene moving|mix|moving,mix]\n"
		"                           [--structures a,b,...] [--frames K] [--warmup W] "
		"[--max-frame-seconds S]\n"
		"                           [--cpu-time] [--quick] [--svg file] [--csv file] [--markdown file] "
		"[--merge-csv a.csv,b.csv]\n"
		"                           [--frame-times file (appends every timed frame of each row)]\n"
		"                           [--evict-mb M (reads M MB of other memory before each frame, untimed)]\n"
		"structures: tree sap grid octree (tree-inc sap-inc: created one by one; tree-single grid-single: "
		"moved by one MoveProxy call per box instead of MoveProxies)");
	for (const std::string& name : PeerNames())
	{
		std::printf(" %s", name.c_str());
	}
	std::printf("\n");
}

std::unique_ptr<Adapter> MakeAdapter(const std::string& name, bool* peer)
{
	std::unique_ptr<Adapter> adapter = MakeCollideAdapter(name);
	*peer = false;
	if (!adapter)
	{
		adapter = MakePeerAdapter(name);
		*peer = adapter != nullptr;
	}
	return adapter;
}

// The cost per frame the plot and the tables show: the mean over the timed frames (rows from an
// older CSV without it: the median).
double FrameCost(const Result& r)
{
	return r.frameMeanMs > 0 ? r.frameMeanMs : r.frameMs;
}

double Median(std::vector<double> values)
{
	if (values.empty())
	{
		return 0.0;
	}
	std::sort(values.begin(), values.end());
	size_t mid = values.size() / 2;
	return values.size() % 2 ? values[mid] : 0.5 * (values[mid - 1] + values[mid]);
}

// Per dimension and structure: the largest N run so far and its time per frame (ms).
std::map<std::string, std::pair<int, double>> gSlowest;

// One line per row: "dim n scene structure" and then every timed frame in ms. The scene is
// deterministic, so frame k does the same work in every run: the fastest of frame k over several
// runs estimates its cost on a quiet machine, frame by frame (scripts/bench-growth.sh).
void AppendFrameTimes(const std::string& path, const Result& result, const std::vector<double>& frameSeconds)
{
	FILE* file = std::fopen(path.c_str(), "a");
	if (file == nullptr)
	{
		std::fprintf(stderr, "cannot append to %s\n", path.c_str());
		std::exit(2);
	}
	std::fprintf(file, "%d %d %s %s", result.dim, result.n, SceneName(result.kind), result.name.c_str());
	for (double seconds : frameSeconds)
	{
		std::fprintf(file, " %.4f", 1e3 * seconds);
	}
	std::fprintf(file, "\n");
	std::fclose(file);
}

// Reads `bytes` of memory no structure uses, one load per cache line, so that a frame starts with
// the caches full of other data, as in a physics engine, where the narrowphase, the solver and
// the game read far more than the last-level cache between two broadphase updates. Without it
// a 100,000-box scene keeps its whole structure (about 12 MB) in a 33 MB L3 from one frame to the
// next, where no engine frame would leave it, while a 1,000,000-box one cannot. Reads, not writes,
// so that the timed frame pays no write-backs of dirty lines it never touched.
volatile unsigned gEvictSink; // keeps EvictCaches' loads

void EvictCaches(size_t bytes)
{
	static std::vector<unsigned char> memory;
	if (memory.size() < bytes)
	{
		memory.assign(bytes, 1);
	}
	unsigned sum = 0;
	for (size_t i = 0; i < bytes; i += 64)
	{
		sum += memory[i];
	}
	gEvictSink = sum;
}

bool RunCase(const Options& options, int dim, int n, SceneKind kind, std::vector<Result>& results)
{
	bool ok = true;
	std::vector<size_t> expectedCounts;
	size_t expectedQueryHits = 0, expectedRayHits = 0;
	bool haveQueryHits = false, haveRayHits = false;
	std::string firstName;
	bool checkReference = n <= 100000;
	std::printf("\n== %dD, N = %d, scene %s, %d frames after %d untimed%s ==\n", dim, n, SceneName(kind),
				options.frames, options.warmup,
				options.evictMegabytes > 0 ? ", caches evicted before each frame (--evict-mb)" : "");
	std::printf("%-12s %10s %10s %10s %10s %9s %9s %10s  %s\n", "structure", "build ms", "frame ms",
				"query us", "ray us", "B/proxy", "B/p stat", "pairs", "notes");
	for (const std::string& name : options.structures)
	{
		bool peer = false;
		std::unique_ptr<Adapter> adapter = MakeAdapter(name, &peer);
		if (!adapter || !adapter->SupportsDim(dim))
		{
			continue;
		}
		// bt32BitAxisSweep3 inserts each proxy into sorted endpoint arrays (O(N) per insert):
		// building 100,000 proxies takes minutes (O(N^2)), so it runs up to 20,000 only.
		if (name == "bullet-sap" && n > 20000)
		{
			std::printf(
				"%-12s skipped above N = 20,000 (one-by-one insertion is O(N^2): 505 s to build 100,000)\n",
				name.c_str());
			continue;
		}
		// A structure slower than 2 s per frame at a smaller N is not run at a larger one.
		auto slow = gSlowest.find(std::to_string(dim) + name);
		if (slow != gSlowest.end() && slow->second.first < n && slow->second.second > 2000.0)
		{
			std::printf("%-12s skipped: %.0f ms per frame at N = %d already\n", name.c_str(),
						slow->second.second, slow->second.first);
			continue;
		}
		Scene scene;
		scene.Init(dim, n, kind, broadSceneSeed(dim, n));
		adapter->Prepare(scene);

		Result result;
		result.dim = dim;
		result.n = n;
		result.kind = kind;
		result.name = adapter->Name();
		result.peer = peer;

		size_t heapBefore = HeapBytes();
		Clock::time_point t0 = Clock::now();
		adapter->Build(scene);
		Clock::time_point t1 = Clock::now();
		result.buildMs = 1e3 * Seconds(t0, t1);

		std::vector<size_t> counts;
		counts.push_back(adapter->UpdateAndCountPairs(scene)); // frame 0: the initial pairs
		size_t heapAfter = HeapBytes();
		size_t owned = adapter->BenchOwnedBytes();
		result.heapBytesPerProxy =
			double(heapAfter > heapBefore + owned ? heapAfter - heapBefore - owned : 0) / double(n);
		result.reportedBytesPerProxy = double(adapter->ReportedBytes()) / double(n);

		std::vector<double> frameSeconds;
		for (int frame = 1; frame <= options.warmup + options.frames; ++frame)
		{
			if (frame == options.warmup + 1)
			{
				adapter->StartTiming();
			}
			scene.Step(frame);
			if (options.evictMegabytes > 0)
			{
				EvictCaches(size_t(options.evictMegabytes) << 20);
			}
			double a = FrameClock();
			counts.push_back(adapter->UpdateAndCountPairs(scene));
			double b = FrameClock();
			if (frame <= options.warmup)
			{
				if (b - a > options.maxFrameSeconds)
				{
					frameSeconds.push_back(b - a);
					break; // too slow even to warm up; the row says it ran 1 frame
				}
				continue;
			}
			frameSeconds.push_back(b - a);
			if (frameSeconds.back() > options.maxFrameSeconds)
			{
				break; // too slow to finish in reasonable time; the row says how many frames ran
			}
		}
		result.framesRun = int(frameSeconds.size());
		if (!options.frameTimesPath.empty())
		{
			AppendFrameTimes(options.frameTimesPath, result, frameSeconds);
		}
		result.frameMs = 1e3 * Median(frameSeconds);
		if (!frameSeconds.empty())
		{
			double sum = 0.0, slowest = 0.0;
			for (double seconds : frameSeconds)
			{
				sum += seconds;
				slowest = std::max(slowest, seconds);
			}
			result.frameMeanMs = 1e3 * sum / double(frameSeconds.size());
			result.frameMaxMs = 1e3 * slowest;
		}
		gSlowest[std::to_string(dim) + name] = std::make_pair(n, result.frameMs);
		result.pairs = counts.back();
		// A structure stopped early saw fewer moves: its last-frame figures are not comparable.
		bool complete = counts.size() == size_t(1 + options.warmup + options.frames);

		if (checkReference && (name == options.structures.front() || firstName.empty()))
		{
			size_t reference = scene.ReferencePairCount();
			if (reference != counts.back())
			{
				std::printf("MISMATCH: %s reports %zu pairs in the last frame, reference sweep %zu\n",
							result.name.c_str(), counts.back(), reference);
				ok = false;
			}
		}
		if (firstName.empty())
		{
			firstName = result.name;
			expectedCounts = counts;
		}
		else
		{
			for (size_t f = 0; f < counts.size() && f < expectedCounts.size(); ++f)
			{
				if (counts[f] != expectedCounts[f])
				{
					std::printf("MISMATCH: frame %zu: %s reports %zu pairs, %s %zu\n", f, result.name.c_str(),
								counts[f], firstName.c_str(), expectedCounts[f]);
					ok = false;
					break;
				}
			}
		}

		Clock::time_point q0 = Clock::now();
		for (const Box& query : scene.queries)
		{
			result.queryHits += adapter->Query(scene, query);
		}
		Clock::time_point q1 = Clock::now();
		result.queryUs = 1e6 * Seconds(q0, q1) / double(scene.queries.size());
		if (complete && haveQueryHits && result.queryHits != expectedQueryHits)
		{
			std::printf("MISMATCH: %s query hits %zu, expected %zu\n", result.name.c_str(), result.queryHits,
						expectedQueryHits);
			ok = false;
		}
		if (complete)
		{
			expectedQueryHits = result.queryHits;
			haveQueryHits = true;
		}

		if (adapter->SupportsRay())
		{
			Clock::time_point r0 = Clock::now();
			for (const Ray& ray : scene.rays)
			{
				result.rayHits += adapter->RayCast(scene, ray);
			}
			Clock::time_point r1 = Clock::now();
			result.rayUs = 1e6 * Seconds(r0, r1) / double(scene.rays.size());
			result.rayMeasured = true;
			if (complete && haveRayHits && result.rayHits != expectedRayHits)
			{
				std::printf("MISMATCH: %s ray hits %zu, expected %zu\n", result.name.c_str(), result.rayHits,
							expectedRayHits);
				ok = false;
			}
			if (complete)
			{
				expectedRayHits = result.rayHits;
				haveRayHits = true;
			}
		}
		result.extra = adapter->Extra();
		if (options.evictMegabytes > 0)
		{
			// (The CSV rows say it too: such frames are not comparable with warm ones.)
			result.extra += " (caches evicted before each frame: --evict-mb " +
							std::to_string(options.evictMegabytes) + ")";
		}
		if (result.framesRun < options.frames)
		{
			result.extra += " (stopped after " + std::to_string(result.framesRun) + " frames: too slow)";
		}
		char ray[32] = "n/a";
		if (result.rayMeasured)
		{
			std::snprintf(ray, sizeof ray, "%.2f", result.rayUs);
		}
		char stat[32] = "-";
		if (result.reportedBytesPerProxy > 0)
		{
			std::snprintf(stat, sizeof stat, "%.0f", result.reportedBytesPerProxy);
		}
		std::printf(
			"%-12s %10.2f %10.3f %10.2f %10s %9.0f %9s %10zu  frames: mean %.3f ms, slowest %.3f ms%s%s\n",
			result.name.c_str(), result.buildMs, result.frameMs, result.queryUs, ray,
			result.heapBytesPerProxy, stat, result.pairs, result.frameMeanMs, result.frameMaxMs,
			result.extra.empty() ? "" : " |", result.extra.c_str());
		std::fflush(stdout);
		adapter.reset();
		results.push_back(result);
	}
	return ok;
}

// ---- SVG scaling plot ------------------------------------------------------------------------

const char* kColors[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e",
						 "#8c564b", "#e377c2", "#7f7f7f", "#17becf", "#bcbd22"};

void WriteSvg(const std::string& path, const std::vector<Result>& results, SceneKind kind)
{
	FILE* file = std::fopen(path.c_str(), "w");
	if (!file)
	{
		std::fprintf(stderr, "cannot write %s\n", path.c_str());
		return;
	}
	const double panelW = 420, panelH = 320, left = 80, top = 40, gap = 90;
	std::vector<int> dims;
	std::vector<std::string> names;
	double minN = 1e30, maxN = 0, minT = 1e30, maxT = 0;
	for (const Result& r : results)
	{
		if (r.kind != kind || FrameCost(r) <= 0)
		{
			continue;
		}
		if (std::find(dims.begin(), dims.end(), r.dim) == dims.end())
		{
			dims.push_back(r.dim);
		}
		if (std::find(names.begin(), names.end(), r.name) == names.end())
		{
			names.push_back(r.name);
		}
		minN = std::min(minN, double(r.n));
		maxN = std::max(maxN, double(r.n));
		minT = std::min(minT, FrameCost(r));
		maxT = std::max(maxT, FrameCost(r));
	}
	std::sort(dims.begin(), dims.end());
	if (dims.empty())
	{
		std::fclose(file);
		return;
	}
	double lx0 = std::floor(std::log10(minN)), lx1 = std::ceil(std::log10(maxN));
	double ly0 = std::floor(std::log10(minT)), ly1 = std::ceil(std::log10(maxT));
	lx1 = std::max(lx1, lx0 + 1);
	ly1 = std::max(ly1, ly0 + 1);
	double width = left + double(dims.size()) * (panelW + gap) + 140, height = top + panelH + 70;
	std::fprintf(file,
				 "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" "
				 "font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%%\" height=\"100%%\" "
				 "fill=\"white\"/>\n",
				 width, height);
	std::fprintf(
		file,
		"<text x=\"%.0f\" y=\"20\" font-size=\"15\">Broadphase: update + all pairs per frame (scene: %s), "
		"log-log</text>\n",
		left, SceneName(kind));
	for (size_t p = 0; p < dims.size(); ++p)
	{
		double x0 = left + double(p) * (panelW + gap), y0 = top;
		auto X = [&](double n) { return x0 + panelW * (std::log10(n) - lx0) / (lx1 - lx0); };
		auto Y = [&](double t) { return y0 + panelH - panelH * (std::log10(t) - ly0) / (ly1 - ly0); };
		std::fprintf(
			file,
			"<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"none\" stroke=\"black\"/>\n",
			x0, y0, panelW, panelH);
		std::fprintf(file, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"14\">%dD</text>\n", x0 + 8, y0 + 18,
					 dims[p]);
		for (double e = lx0; e <= lx1; e += 1)
		{
			std::fprintf(file,
						 "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#ddd\"/>"
						 "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\">1e%.0f</text>\n",
						 X(std::pow(10, e)), y0, X(std::pow(10, e)), y0 + panelH, X(std::pow(10, e)),
						 y0 + panelH + 16, e);
		}
		for (double e = ly0; e <= ly1; e += 1)
		{
			std::fprintf(file,
						 "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#ddd\"/>"
						 "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"end\">%g ms</text>\n",
						 x0, Y(std::pow(10, e)), x0 + panelW, Y(std::pow(10, e)), x0 - 4,
						 Y(std::pow(10, e)) + 4, std::pow(10, e));
		}
		std::fprintf(file, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\">N (boxes)</text>\n",
					 x0 + panelW / 2, y0 + panelH + 34);
		for (size_t s = 0; s < names.size(); ++s)
		{
			std::vector<const Result*> line;
			for (const Result& r : results)
			{
				if (r.kind == kind && r.dim == dims[p] && r.name == names[s] && FrameCost(r) > 0)
				{
					line.push_back(&r);
				}
			}
			std::sort(line.begin(), line.end(), [](const Result* a, const Result* b) { return a->n < b->n; });
			if (line.empty())
			{
				continue;
			}
			const char* color = kColors[s % (sizeof kColors / sizeof kColors[0])];
			std::fprintf(file, "<polyline fill=\"none\" stroke=\"%s\" stroke-width=\"2\"%s points=\"", color,
						 line.front()->peer ? " stroke-dasharray=\"6,3\"" : "");
			for (const Result* r : line)
			{
				std::fprintf(file, "%.1f,%.1f ", X(r->n), Y(FrameCost(*r)));
			}
			std::fprintf(file, "\"/>\n");
			for (const Result* r : line)
			{
				std::fprintf(file, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"3\" fill=\"%s\"/>\n", X(r->n),
							 Y(FrameCost(*r)), color);
			}
		}
	}
	double lx = left + double(dims.size()) * (panelW + gap) - gap + 20;
	for (size_t s = 0; s < names.size(); ++s)
	{
		const char* color = kColors[s % (sizeof kColors / sizeof kColors[0])];
		bool peer = false;
		for (const Result& r : results)
		{
			if (r.name == names[s])
			{
				peer = r.peer;
			}
		}
		double y = top + 14 + 20 * double(s);
		std::fprintf(
			file,
			"<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\" stroke-width=\"2\"%s/>"
			"<text x=\"%.1f\" y=\"%.1f\">%s</text>\n",
			lx, y, lx + 24, y, color, peer ? " stroke-dasharray=\"6,3\"" : "", lx + 30, y + 4,
			names[s].c_str());
	}
	std::fprintf(
		file,
		"<text x=\"%.0f\" y=\"%.0f\" fill=\"#555\">solid: collide; dashed: peers. Mean time per frame; "
		"pair counts checked equal across structures (see docs/BROADPHASE.md).</text>\n</svg>\n",
		left, height - 8);
	std::fclose(file);
}

// Tables for docs: time per frame against N for each dimension and scene, then every figure at
// the largest N below 1,000,000 (or the largest run).
void WriteMarkdown(const std::string& path, const std::vector<Result>& results)
{
	FILE* file = std::fopen(path.c_str(), "w");
	if (!file)
	{
		std::fprintf(stderr, "cannot write %s\n", path.c_str());
		return;
	}
	std::vector<int> dims, ns;
	std::vector<std::string> names;
	for (const Result& r : results)
	{
		if (std::find(dims.begin(), dims.end(), r.dim) == dims.end())
		{
			dims.push_back(r.dim);
		}
		if (std::find(ns.begin(), ns.end(), r.n) == ns.end())
		{
			ns.push_back(r.n);
		}
		if (std::find(names.begin(), names.end(), r.name) == names.end())
		{
			names.push_back(r.name);
		}
	}
	std::sort(dims.begin(), dims.end());
	std::sort(ns.begin(), ns.end());
	auto find = [&](int dim, SceneKind kind, const std::string& name, int n) -> const Result* {
		for (const Result& r : results)
		{
			if (r.dim == dim && r.kind == kind && r.name == name && r.n == n)
			{
				return &r;
			}
		}
		return nullptr;
	};
	for (int dim : dims)
	{
		for (SceneKind kind : {SceneKind::Moving, SceneKind::Mix})
		{
			std::fprintf(
				file, "\n**%dD, scene %s: mean ms per frame (update + complete pair set)**\n\n| structure |",
				dim, SceneName(kind));
			for (int n : ns)
			{
				std::fprintf(file, " N = %d |", n);
			}
			std::fprintf(file, "\n|---|");
			for (size_t i = 0; i < ns.size(); ++i)
			{
				std::fprintf(file, "---:|");
			}
			std::fprintf(file, "\n");
			for (const std::string& name : names)
			{
				bool any = false;
				for (int n : ns)
				{
					any = any || find(dim, kind, name, n) != nullptr;
				}
				if (!any)
				{
					continue;
				}
				const Result* first = nullptr;
				for (int n : ns)
				{
					first = first ? first : find(dim, kind, name, n);
				}
				std::fprintf(file, "| %s%s |", name.c_str(), first && first->peer ? " (peer)" : "");
				for (int n : ns)
				{
					const Result* r = find(dim, kind, name, n);
					if (r)
					{
						std::fprintf(file, " %.3g%s |", FrameCost(*r), r->framesRun <= 1 ? "*" : "");
					}
					else
					{
						std::fprintf(file, " - |");
					}
				}
				std::fprintf(file, "\n");
			}
			std::fprintf(file, "| pairs |");
			for (int n : ns)
			{
				size_t pairs = 0;
				for (const std::string& name : names)
				{
					const Result* r = find(dim, kind, name, n);
					pairs = r && (r->framesRun > 1 || pairs == 0) ? r->pairs : pairs;
				}
				if (pairs > 0)
				{
					std::fprintf(file, " %zu |", pairs);
				}
				else
				{
					std::fprintf(file, " - |");
				}
			}
			std::fprintf(file, "\n");
			if (std::any_of(results.begin(), results.end(), [&](const Result& r) {
					return r.dim == dim && r.kind == kind && r.framesRun <= 1;
				}))
			{
				std::fprintf(file, "\n\\* one frame only: slower per frame than the run's "
								   "--max-frame-seconds (default 20 s), stopped.\n");
			}
		}
	}
	// Details at the largest N below 1,000,000 that has about as many rows as the best covered N.
	auto rowsAt = [&](int n) {
		return size_t(
			std::count_if(results.begin(), results.end(), [n](const Result& r) { return r.n == n; }));
	};
	size_t mostRows = 0;
	for (int n : ns)
	{
		mostRows = std::max(mostRows, rowsAt(n));
	}
	int detailN = ns.empty() ? 0 : ns.front();
	for (int n : ns)
	{
		if (n < 1000000 && 4 * rowsAt(n) >= 3 * mostRows)
		{
			detailN = n;
		}
	}
	for (int dim : dims)
	{
		for (SceneKind kind : {SceneKind::Moving, SceneKind::Mix})
		{
			std::fprintf(
				file,
				"\n**%dD, scene %s, N = %d**\n\n| structure | build ms | mean frame ms | query us | ray us | "
				"bytes/proxy (heap) | bytes/proxy (stats) | pairs "
				"|\n|---|---:|---:|---:|---:|---:|---:|---:|\n",
				dim, SceneName(kind), detailN);
			for (const std::string& name : names)
			{
				const Result* r = find(dim, kind, name, detailN);
				if (!r)
				{
					continue;
				}
				char ray[32] = "n/a", stat[32] = "-";
				if (r->rayMeasured)
				{
					std::snprintf(ray, sizeof ray, "%.2f", r->rayUs);
				}
				if (r->reportedBytesPerProxy > 0)
				{
					std::snprintf(stat, sizeof stat, "%.0f", r->reportedBytesPerProxy);
				}
				std::fprintf(file, "| %s%s | %.1f | %.3g | %.2f | %s | %.0f | %s | %zu |\n", r->name.c_str(),
							 r->peer ? " (peer)" : "", r->buildMs, FrameCost(*r), r->queryUs, ray,
							 r->heapBytesPerProxy, stat, r->pairs);
			}
		}
	}
	std::fclose(file);
}

// Reads rows written by WriteCsv (the fields the plot and the table need).
void ReadCsv(const std::string& path, std::vector<Result>& results)
{
	FILE* file = std::fopen(path.c_str(), "r");
	if (!file)
	{
		std::fprintf(stderr, "cannot read %s\n", path.c_str());
		return;
	}
	char line[1024];
	bool header = true;
	size_t fixed = 13; // fields before the notes; 15 when the mean and slowest frame are there
	while (std::fgets(line, sizeof line, file))
	{
		if (header)
		{
			header = false;
			fixed = std::strstr(line, "frame_mean_ms") != nullptr ? 15 : 13;
			continue;
		}
		std::vector<std::string> f;
		std::string field;
		for (const char* c = line; *c && *c != '\n'; ++c)
		{
			if (*c == ',' && f.size() < fixed)
			{
				f.push_back(field);
				field.clear();
			}
			else
			{
				field += *c;
			}
		}
		f.push_back(field);
		if (f.size() < fixed)
		{
			continue;
		}
		Result r;
		r.dim = std::atoi(f[0].c_str());
		r.n = std::atoi(f[1].c_str());
		r.kind = f[2] == "mix" ? SceneKind::Mix : SceneKind::Moving;
		r.name = f[3];
		r.peer = f[4] == "1";
		r.buildMs = std::atof(f[5].c_str());
		r.frameMs = std::atof(f[6].c_str());
		r.queryUs = std::atof(f[7].c_str());
		r.rayMeasured = !f[8].empty();
		r.rayUs = std::atof(f[8].c_str());
		r.heapBytesPerProxy = std::atof(f[9].c_str());
		r.reportedBytesPerProxy = std::atof(f[10].c_str());
		r.pairs = size_t(std::atoll(f[11].c_str()));
		r.framesRun = std::atoi(f[12].c_str());
		if (fixed == 15)
		{
			r.frameMeanMs = std::atof(f[13].c_str());
			r.frameMaxMs = std::atof(f[14].c_str());
		}
		results.push_back(r);
	}
	std::fclose(file);
}

void WriteCsv(const std::string& path, const std::vector<Result>& results)
{
	FILE* file = std::fopen(path.c_str(), "w");
	if (!file)
	{
		return;
	}
	std::fprintf(file, "dim,n,scene,structure,peer,build_ms,frame_ms,query_us,ray_us,heap_bytes_per_proxy,"
					   "stats_bytes_per_proxy,pairs,frames,frame_mean_ms,frame_slowest_ms,notes\n");
	for (const Result& r : results)
	{
		std::fprintf(file, "%d,%d,%s,%s,%d,%.3f,%.4f,%.3f,%s,%.1f,%.1f,%zu,%d,%.4f,%.4f,\"%s\"\n", r.dim, r.n,
					 SceneName(r.kind), r.name.c_str(), r.peer ? 1 : 0, r.buildMs, r.frameMs, r.queryUs,
					 r.rayMeasured ? std::to_string(r.rayUs).c_str() : "", r.heapBytesPerProxy,
					 r.reportedBytesPerProxy, r.pairs, r.framesRun, r.frameMeanMs, r.frameMaxMs,
					 r.extra.c_str());
	}
	std::fclose(file);
}

} // namespace

int main(int argc, char** argv)
{
	Options options;
	options.structures = {"tree", "sap", "grid", "octree"};
	for (const std::string& peer : PeerNames())
	{
		options.structures.push_back(peer);
	}
	bool quick = false;
	for (int i = 1; i < argc; ++i)
	{
		std::string arg = argv[i];
		auto value = [&]() -> std::string {
			if (i + 1 >= argc)
			{
				Usage();
				std::exit(2);
			}
			return argv[++i];
		};
		if (arg == "--dim")
		{
			options.dims.clear();
			for (const std::string& d : Split(value()))
			{
				options.dims.push_back(std::atoi(d.c_str()));
			}
		}
		else if (arg == "--n")
		{
			options.ns.clear();
			for (const std::string& n : Split(value()))
			{
				options.ns.push_back(int(std::atof(n.c_str())));
			}
		}
		else if (arg == "--scene")
		{
			options.scenes.clear();
			for (const std::string& s : Split(value()))
			{
				options.scenes.push_back(s == "mix" ? SceneKind::Mix : SceneKind::Moving);
			}
		}
		else if (arg == "--structures")
		{
			options.structures = Split(value());
		}
		else if (arg == "--frames")
		{
			options.frames = std::max(1, std::atoi(value().c_str()));
		}
		else if (arg == "--warmup")
		{
			options.warmup = std::max(0, std::atoi(value().c_str()));
		}
		else if (arg == "--max-frame-seconds")
		{
			options.maxFrameSeconds = std::atof(value().c_str());
		}
		else if (arg == "--evict-mb")
		{
			options.evictMegabytes = std::max(0, std::atoi(value().c_str()));
		}
		else if (arg == "--svg")
		{
			options.svgPath = value();
		}
		else if (arg == "--csv")
		{
			options.csvPath = value();
		}
		else if (arg == "--frame-times")
		{
			options.frameTimesPath = value();
		}
		else if (arg == "--markdown")
		{
			options.markdownPath = value();
		}
		else if (arg == "--merge-csv")
		{
			options.mergePaths = Split(value());
		}
		else if (arg == "--cpu-time")
		{
			gCpuTime = true;
		}
		else if (arg == "--quick")
		{
			quick = true;
		}
		else if (arg == "--no-run")
		{
			options.dims.clear(); // only merge earlier CSVs into the outputs
		}
		else if (arg == "--list")
		{
			Usage();
			return 0;
		}
		else
		{
			Usage();
			return 2;
		}
	}
	if (quick)
	{
		options.dims = {2, 3};
		options.ns = {300};
		options.scenes = {SceneKind::Moving, SceneKind::Mix};
		options.frames = 2;
		options.warmup = 1;
	}
	for (const std::string& name : options.structures)
	{
		bool peer = false;
		if (!MakeAdapter(name, &peer))
		{
			std::fprintf(stderr, "unknown structure '%s'\n", name.c_str());
			Usage();
			return 2;
		}
	}
	std::printf(
		"collide_bench_broad: median time per frame of (move the boxes' proxies + complete set of\n"
		"overlapping pairs, counted on the tight boxes), and in the notes the mean and slowest frame\n"
		"(bursts: fat boxes expiring together, Bullet's staged tree optimization; compare means over\n"
		"many frames for the cost over time); query/ray: mean per call over %s calls.\n"
		"B/proxy: heap growth (glibc mallinfo2) over build + first frame, minus the bench's own pair set.\n",
		"up to 1000");
	bool ok = true;
	std::vector<Result> results;
	for (int dim : options.dims)
	{
		for (SceneKind kind : options.scenes)
		{
			for (int n : options.ns)
			{
				ok = RunCase(options, dim, n, kind, results) && ok;
				if (!options.csvPath.empty())
				{
					WriteCsv(options.csvPath, results); // after every case, so a long run keeps what it has
				}
			}
		}
	}
	for (const std::string& path : options.mergePaths)
	{
		ReadCsv(path, results);
	}
	if (!options.svgPath.empty())
	{
		WriteSvg(options.svgPath, results, options.scenes.front());
	}
	if (!options.csvPath.empty())
	{
		WriteCsv(options.csvPath, results);
	}
	if (!options.markdownPath.empty())
	{
		WriteMarkdown(options.markdownPath, results);
	}
	std::printf(ok ? "\nall pair, query and ray counts agree\n" : "\nCOUNTS DISAGREE\n");
	return ok ? 0 : 1;
}
