// collide's own structures behind the bench adapter, through the public C API only.
#include "bench_broad.h"

#include <collide/broad.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <cstdio>
#include <string>
#include <vector>

#ifdef CD_BROAD_COUNT_OPS
// The library's debug operation counters (src/broad/broad_internal.h, same macro).
extern "C" unsigned long long cdBroadOpCounts[8];
#endif

namespace bench
{
namespace
{

cd3Aabb To3(const Box& b)
{
	cd3Aabb a;
	a.min = {cdReal(b.min[0]), cdReal(b.min[1]), cdReal(b.min[2])};
	a.max = {cdReal(b.max[0]), cdReal(b.max[1]), cdReal(b.max[2])};
	return a;
}

cd2Aabb To2(const Box& b)
{
	cd2Aabb a;
	a.min = {cdReal(b.min[0]), cdReal(b.min[1])};
	a.max = {cdReal(b.max[0]), cdReal(b.max[1])};
	return a;
}

struct QueryContext
{
	const Scene* scene;
	const Box* box;
	const Ray* ray;
	size_t hits;
};

bool Query3(int, uint64_t userData, void* context)
{
	QueryContext* q = static_cast<QueryContext*>(context);
	q->hits += Overlap(q->scene->boxes[size_t(userData)], *q->box) ? 1 : 0;
	return true;
}

bool Query2(int proxyId, uint64_t userData, void* context)
{
	return Query3(proxyId, userData, context);
}

cdReal Ray3(cd3Ray, cdReal maxFraction, int, uint64_t userData, void* context)
{
	QueryContext* q = static_cast<QueryContext*>(context);
	q->hits += RayHitsBox(*q->ray, q->scene->boxes[size_t(userData)]) ? 1 : 0;
	return maxFraction; // every box the ray meets, no clipping
}

cdReal Ray2(cd2Ray, cdReal maxFraction, int, uint64_t userData, void* context)
{
	return Ray3(cd3Ray(), maxFraction, 0, userData, context);
}

void AddPair(int, int, uint64_t userDataA, uint64_t userDataB, void* context)
{
	static_cast<PairList*>(context)->Add(int(userDataA), int(userDataB));
}

class CollideAdapter : public Adapter
{
  public:
	CollideAdapter(const std::string& name, cdBroadPhaseType type, bool oneByOne, bool batch)
		: name_(name), type_(type), oneByOne_(oneByOne), batch_(batch)
	{
	}
	~CollideAdapter() override
	{
		if (bp3_)
		{
			cd3DestroyBroadPhase(bp3_);
		}
		if (bp2_)
		{
			cd2DestroyBroadPhase(bp2_);
		}
	}
	std::string Name() const override
	{
		return name_;
	}
	bool SupportsDim(int) const override
	{
		return true;
	}

	void Build(const Scene& scene) override
	{
		dim_ = scene.dim;
		Box world = scene.WorldBounds();
		proxies_.resize(size_t(scene.n));
		pairs_.Reset(scene.n);
		if (dim_ == 3)
		{
			cd3BroadPhaseDef def = cd3DefaultBroadPhaseDef();
			def.type = type_;
			def.bounds = To3(world);
			def.capacity = scene.n;
			if (cd3CreateBroadPhase(&def, &bp3_) != CD_OK)
			{
				std::fprintf(stderr, "%s: cd3CreateBroadPhase failed\n", name_.c_str());
				std::exit(2);
			}
			// The scene is loaded at once: the bulk API builds the structure in one pass (the tree
			// by a top-down SAH build). "tree-inc" / "sap-inc" create the proxies one by one instead
			// (in the scene's random order), to measure the incremental path.
			std::vector<cd3Aabb> boxes(size_t(scene.n));
			std::vector<uint64_t> userData(size_t(scene.n));
			for (int i = 0; i < scene.n; ++i)
			{
				boxes[size_t(i)] = To3(scene.boxes[size_t(i)]);
				userData[size_t(i)] = uint64_t(i);
			}
			if (oneByOne_)
			{
				for (int i = 0; i < scene.n; ++i)
				{
					proxies_[size_t(i)] = cd3BroadPhase_CreateProxy(bp3_, boxes[size_t(i)], uint64_t(i));
				}
			}
			else if (cd3BroadPhase_CreateProxies(bp3_, boxes.data(), userData.data(), scene.n,
												 proxies_.data()) != scene.n)
			{
				std::fprintf(stderr, "%s: cd3BroadPhase_CreateProxies failed\n", name_.c_str());
				std::exit(2);
			}
		}
		else
		{
			cd2BroadPhaseDef def = cd2DefaultBroadPhaseDef();
			def.type = type_;
			def.bounds = To2(world);
			def.capacity = scene.n;
			if (cd2CreateBroadPhase(&def, &bp2_) != CD_OK)
			{
				std::fprintf(stderr, "%s: cd2CreateBroadPhase failed\n", name_.c_str());
				std::exit(2);
			}
			std::vector<cd2Aabb> boxes(size_t(scene.n));
			std::vector<uint64_t> userData(size_t(scene.n));
			for (int i = 0; i < scene.n; ++i)
			{
				boxes[size_t(i)] = To2(scene.boxes[size_t(i)]);
				userData[size_t(i)] = uint64_t(i);
			}
			if (oneByOne_)
			{
				for (int i = 0; i < scene.n; ++i)
				{
					proxies_[size_t(i)] = cd2BroadPhase_CreateProxy(bp2_, boxes[size_t(i)], uint64_t(i));
				}
			}
			else if (cd2BroadPhase_CreateProxies(bp2_, boxes.data(), userData.data(), scene.n,
												 proxies_.data()) != scene.n)
			{
				std::fprintf(stderr, "%s: cd2BroadPhase_CreateProxies failed\n", name_.c_str());
				std::exit(2);
			}
		}
	}

	size_t UpdateAndCountPairs(const Scene& scene) override
	{
		size_t count = 0;
#ifdef CD_BROAD_COUNT_OPS
		unsigned long long opsBefore[8];
		std::copy(cdBroadOpCounts, cdBroadOpCounts + 8, opsBefore);
#endif
		double t0 = FrameClock(), t1, t2;
		size_t movedNow = 0;
		size_t movedCount = scene.moved.count;
		ids_.resize(movedCount);
		if (changedCapacity_ < movedCount)
		{
			changed_.reset(new bool[movedCount]);
			changedCapacity_ = movedCount;
		}
		if (dim_ == 3)
		{
			if (batch_)
			{
				// All moved boxes in one call (the way a physics step hands over its bodies).
				boxes3_.resize(movedCount);
				displacements3_.resize(movedCount);
				for (size_t k = 0; k < movedCount; ++k)
				{
					PrefetchMovedInputs(scene, k, proxies_.data());
					size_t i = size_t(scene.moved[k]);
					const float* d = &scene.displacement[i * 3];
					ids_[k] = proxies_[i];
					boxes3_[k] = To3(scene.boxes[i]);
					displacements3_[k] = cd3Vec{cdReal(d[0]), cdReal(d[1]), cdReal(d[2])};
				}
				cd3BroadPhase_MoveProxies(bp3_, int(movedCount), ids_.data(), boxes3_.data(),
										  displacements3_.data(), changed_.get());
			}
			else
			{
				for (size_t k = 0; k < movedCount; ++k)
				{
					PrefetchMovedInputs(scene, k, proxies_.data());
					size_t i = size_t(scene.moved[k]);
					const float* d = &scene.displacement[i * 3];
					ids_[k] = proxies_[i];
					changed_[k] = cd3BroadPhase_MoveProxy(bp3_, ids_[k], To3(scene.boxes[i]),
														  cd3Vec{cdReal(d[0]), cdReal(d[1]), cdReal(d[2])});
				}
			}
		}
		else
		{
			if (batch_)
			{
				boxes2_.resize(movedCount);
				displacements2_.resize(movedCount);
				for (size_t k = 0; k < movedCount; ++k)
				{
					PrefetchMovedInputs(scene, k, proxies_.data());
					size_t i = size_t(scene.moved[k]);
					const float* d = &scene.displacement[i * 3];
					ids_[k] = proxies_[i];
					boxes2_[k] = To2(scene.boxes[i]);
					displacements2_[k] = cd2Vec{cdReal(d[0]), cdReal(d[1])};
				}
				cd2BroadPhase_MoveProxies(bp2_, int(movedCount), ids_.data(), boxes2_.data(),
										  displacements2_.data(), changed_.get());
			}
			else
			{
				for (size_t k = 0; k < movedCount; ++k)
				{
					PrefetchMovedInputs(scene, k, proxies_.data());
					size_t i = size_t(scene.moved[k]);
					const float* d = &scene.displacement[i * 3];
					ids_[k] = proxies_[i];
					changed_[k] = cd2BroadPhase_MoveProxy(bp2_, ids_[k], To2(scene.boxes[i]),
														  cd2Vec{cdReal(d[0]), cdReal(d[1])});
				}
			}
		}
		for (size_t k = 0; k < movedCount; ++k)
		{
			if (changed_[k])
			{
				pairs_.MarkMoved(scene.moved[k]);
				++movedNow;
			}
		}
		t1 = FrameClock();
		if (dim_ == 3)
		{
			cd3BroadPhase_UpdatePairs(bp3_, AddPair, &pairs_);
		}
		else
		{
			cd2BroadPhase_UpdatePairs(bp2_, AddPair, &pairs_);
		}
		t2 = FrameClock();
		count = pairs_.EndFrame(scene);
		double t3 = FrameClock();
		{
			moveSeconds_ += t1 - t0;
			pairSeconds_ += t2 - t1;
			sweepSeconds_ += t3 - t2;
			fastestMove_ = std::min(fastestMove_, t1 - t0);
			fastestPairs_ = std::min(fastestPairs_, t2 - t1);
			fastestSweep_ = std::min(fastestSweep_, t3 - t2);
			moved_ += movedNow;
			++frames_;
		}
#ifdef CD_BROAD_COUNT_OPS
		for (int k = 0; k < 8; ++k)
		{
			ops_[k] += cdBroadOpCounts[k] - opsBefore[k];
		}
#endif
		return count;
	}

	void StartTiming() override
	{
		frames_ = 0;
		moved_ = 0;
		moveSeconds_ = pairSeconds_ = sweepSeconds_ = 0.0;
		fastestMove_ = fastestPairs_ = fastestSweep_ = 1e30;
#ifdef CD_BROAD_COUNT_OPS
		std::fill(ops_, ops_ + 8, 0ull);
#endif
	}

	size_t Query(const Scene& scene, const Box& box) override
	{
		QueryContext q{&scene, &box, nullptr, 0};
		if (dim_ == 3)
		{
			cd3BroadPhase_Query(bp3_, To3(box), Query3, &q);
		}
		else
		{
			cd2BroadPhase_Query(bp2_, To2(box), Query2, &q);
		}
		return q.hits;
	}

	size_t RayCast(const Scene& scene, const Ray& ray) override
	{
		QueryContext q{&scene, nullptr, &ray, 0};
		if (dim_ == 3)
		{
			cd3Ray r;
			r.origin = {cdReal(ray.origin[0]), cdReal(ray.origin[1]), cdReal(ray.origin[2])};
			r.translation = {cdReal(ray.translation[0]), cdReal(ray.translation[1]),
							 cdReal(ray.translation[2])};
			cd3BroadPhase_Raycast(bp3_, r, Ray3, &q);
		}
		else
		{
			cd2Ray r;
			r.origin = {cdReal(ray.origin[0]), cdReal(ray.origin[1])};
			r.translation = {cdReal(ray.translation[0]), cdReal(ray.translation[1])};
			cd2BroadPhase_Raycast(bp2_, r, Ray2, &q);
		}
		return q.hits;
	}

	size_t BenchOwnedBytes() const override
	{
		return pairs_.Bytes() + proxies_.capacity() * sizeof(int);
	}

	size_t ReportedBytes() const override
	{
		cdBroadPhaseStats stats = dim_ == 3 ? cd3BroadPhase_GetStats(bp3_) : cd2BroadPhase_GetStats(bp2_);
		return stats.memoryBytes;
	}

	std::string Extra() const override
	{
		cdBroadPhaseStats stats = dim_ == 3 ? cd3BroadPhase_GetStats(bp3_) : cd2BroadPhase_GetStats(bp2_);
		bool valid = dim_ == 3 ? cd3BroadPhase_Validate(bp3_) : cd2BroadPhase_Validate(bp2_);
		char text[256];
		double frames = frames_ > 0 ? double(frames_) : 1.0;
		std::snprintf(text, sizeof text,
					  "nodes=%d height=%d valid=%s | mean per timed frame: %.0f fat boxes changed, move %.2f "
					  "ms, UpdatePairs %.2f ms, "
					  "pair-set sweep %.2f ms",
					  stats.nodeCount, stats.height, valid ? "yes" : "NO", double(moved_) / frames,
					  1e3 * moveSeconds_ / frames, 1e3 * pairSeconds_ / frames, 1e3 * sweepSeconds_ / frames);
		std::string extra = text;
		// On a shared machine a frame's time only grows with interference: each phase's fastest
		// frame compares two builds more steadily than the means do.
		if (frames_ > 0)
		{
			std::snprintf(text, sizeof text,
						  " | fastest frame per phase: move %.2f ms, UpdatePairs %.2f ms, sweep %.2f ms",
						  1e3 * fastestMove_, 1e3 * fastestPairs_, 1e3 * fastestSweep_);
			extra += text;
		}
#ifdef CD_BROAD_COUNT_OPS
		if (ops_[0] > 0 || ops_[4] > 0)
		{
			auto per = [](unsigned long long a, unsigned long long b) {
				return b > 0 ? double(a) / double(b) : 0.0;
			};
			std::snprintf(text, sizeof text,
						  " | ops per frame: tree moves %.0f (reinserted %.0f), descent nodes/reinsert %.2f, "
						  "refit steps/move %.2f, queries %.0f, nodes/query %.2f",
						  per(ops_[0], frames_), per(ops_[1], frames_), per(ops_[2], ops_[1]),
						  per(ops_[3], ops_[0]), per(ops_[4], frames_), per(ops_[5], ops_[4]));
			extra += text;
		}
		if (ops_[6] > 0)
		{
			// Grid queries are one per moved proxy in UpdatePairs (the structure-wide sweep is not
			// counted): per changed fat box.
			double perMoved = moved_ > 0 ? 1.0 / double(moved_) : 0.0;
			std::snprintf(text, sizeof text, " | grid per changed box: cells %.2f, entries %.2f",
						  double(ops_[6]) * perMoved, double(ops_[7]) * perMoved);
			extra += text;
		}
#endif
		return extra;
	}

  private:
	std::string name_;
	cdBroadPhaseType type_;
	bool oneByOne_;
	bool batch_; // moves through MoveProxies (else one MoveProxy call per box)
	int dim_ = 3;
	std::vector<int> ids_;
	std::unique_ptr<bool[]> changed_; // (std::vector<bool> has no bool array to hand over)
	size_t changedCapacity_ = 0;
	std::vector<cd3Aabb> boxes3_;
	std::vector<cd3Vec> displacements3_;
	std::vector<cd2Aabb> boxes2_;
	std::vector<cd2Vec> displacements2_;
	cd3BroadPhase* bp3_ = nullptr;
	cd2BroadPhase* bp2_ = nullptr;
	std::vector<int> proxies_;
	PairList pairs_;
	int frames_ = 0;
	size_t moved_ = 0;
	double moveSeconds_ = 0, pairSeconds_ = 0, sweepSeconds_ = 0;
	double fastestMove_ = 1e30, fastestPairs_ = 1e30, fastestSweep_ = 1e30;
#ifdef CD_BROAD_COUNT_OPS
	unsigned long long ops_[8] = {};
#endif
};

} // namespace

std::unique_ptr<Adapter> MakeCollideAdapter(const std::string& name)
{
	static const struct
	{
		const char* name;
		cdBroadPhaseType type;
		bool oneByOne;
		bool batch;
	} kTypes[] = {{"tree", CD_BROADPHASE_TREE, false, true},
				  {"sap", CD_BROADPHASE_SAP, false, true},
				  {"grid", CD_BROADPHASE_GRID, false, true},
				  {"octree", CD_BROADPHASE_SPATIAL_TREE, false, true},
				  // The incremental path: proxies created one by one in the scene's (random) order.
				  {"tree-inc", CD_BROADPHASE_TREE, true, true},
				  {"sap-inc", CD_BROADPHASE_SAP, true, true},
				  // Moves one MoveProxy call at a time, in the scene's order (no batch).
				  {"tree-single", CD_BROADPHASE_TREE, false, false},
				  {"grid-single", CD_BROADPHASE_GRID, false, false}};
	for (const auto& t : kTypes)
	{
		if (name == t.name)
		{
			return std::unique_ptr<Adapter>(new CollideAdapter(name, t.type, t.oneByOne, t.batch));
		}
	}
	return nullptr;
}

} // namespace bench
