// collide broadphase benchmark: the scene every structure sees and the adapter each structure
// (ours and the peers) implements. C++ only because the peers are C++ libraries.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "broad_scene.h"

namespace bench
{

// The boxes, rays and scene are the shared C scene (scenes/broad_scene.h), which the `collide
// broad` tool command runs too.
using Box = BroadBox;
using Ray = BroadRay;

// Closed boxes: touching counts, as in collide. In 2D the z range is the same for every box.
inline bool Overlap(const Box& a, const Box& b)
{
	return broadBoxesOverlap(&a, &b);
}

// Slab test of the segment origin + t * translation, t in [0, 1], against a closed box.
inline bool RayHitsBox(const Ray& ray, const Box& box)
{
	return broadRayHitsBox(&ray, &box);
}

enum class SceneKind
{
	Moving, // every box moves a little every frame
	Mix		// 90% still, 9% moving, 1% teleporting every frame
};

// A read-only view of one of the scene's arrays.
template <typename T> struct View
{
	const T* data = nullptr;
	size_t count = 0;
	const T& operator[](size_t i) const
	{
		return data[i];
	}
	const T* begin() const
	{
		return data;
	}
	const T* end() const
	{
		return data + count;
	}
	size_t size() const
	{
		return count;
	}
};

// The deterministic scene of scenes/broad_scene.h: boxes of edge 0.5..1.5 m in a cube (square in
// 2D) sized so that each box overlaps about one other on average, whatever N.
class Scene
{
  public:
	int dim = 3;
	int n = 0;
	SceneKind kind = SceneKind::Moving;
	float worldSize = 0.0f;
	View<Box> boxes;
	View<float> displacement; // 3 per box: predicted displacement for the next frame
	View<int> moved;		  // boxes moved by the last Step
	View<Box> queries;
	View<Ray> rays;

	Scene() = default;
	Scene(const Scene&) = delete;
	Scene& operator=(const Scene&) = delete;
	~Scene()
	{
		broadSceneFree(&scene_);
	}
	void Init(int dimension, int count, SceneKind sceneKind, uint64_t seed);
	void Step(int frame);
	Box WorldBounds() const
	{
		return broadSceneWorldBounds(&scene_);
	}
	size_t ReferencePairCount() const
	{
		return broadSceneCountPairs(&scene_);
	}

  private:
	BroadScene scene_ = {};
};

// Every adapter's frame walks scene.moved and reads, for each moved box i, its box, its
// displacement and the adapter's handle of it. At 1,000,000 boxes those lie scattered over some
// 40 MB, so each read would be a main-memory miss waited for in turn, a cost of the harness that
// is no part of any broadphase. So every adapter's loop (peers and collide alike) calls this for
// entry k: it starts loading entry k + kMovedAhead's data.
constexpr size_t kMovedAhead = 16;
template <typename Handle>
inline void PrefetchMovedInputs(const Scene& scene, size_t k, const Handle* handles)
{
#if defined(__GNUC__) || defined(__clang__)
	if (k + kMovedAhead < scene.moved.count)
	{
		size_t i = size_t(scene.moved[k + kMovedAhead]);
		__builtin_prefetch(&scene.boxes[i]);
		__builtin_prefetch(&scene.displacement[i * 3]);
		__builtin_prefetch(&handles[i]);
	}
#else
	(void)scene;
	(void)k;
	(void)handles;
#endif
}

// The complete set of overlapping pairs for structures that report, per frame, every pair that
// involves a moved proxy (collide's and Box2D's UpdatePairs), as a physics engine keeps its
// contact list: the shared C pair list (scenes/broad_scene.h), which the tool uses too.
class PairList
{
  public:
	PairList() = default;
	PairList(const PairList&) = delete;
	PairList& operator=(const PairList&) = delete;
	~PairList()
	{
		broadPairListFree(&list_);
	}
	// Starts an empty list for the boxes of a scene.
	void Reset(int boxCount);
	void MarkMoved(int index)
	{
		broadPairListMarkMoved(&list_, index);
	}
	void Add(int a, int b)
	{
		broadPairListAdd(&list_, a, b);
	}
	// Drops the pairs with a moved side, appends the reported ones and forgets the moves.
	// Returns the number of pairs whose tight boxes overlap.
	// The scene's moved boxes are the ones whose tight boxes changed: when they are few (the mix
	// scene), only their kept pairs are compared again; when most moved, every pair is.
	size_t EndFrame(const Scene& scene)
	{
		if (8 * scene.moved.count < scene.boxes.count)
		{
			for (int i : scene.moved)
			{
				broadPairListMarkChanged(&list_, i);
			}
		}
		return broadPairListEndFrame(&list_, scene.boxes.data);
	}
	size_t Bytes() const
	{
		return broadPairListBytes(&list_);
	}

  private:
	BroadPairList list_ = {};
};

struct FrameCounts
{
	size_t pairs = 0; // pairs whose tight boxes overlap (the complete set)
};

class Adapter
{
  public:
	virtual ~Adapter() = default;
	virtual std::string Name() const = 0;
	virtual bool SupportsDim(int dim) const = 0;
	virtual bool SupportsRay() const
	{
		return true;
	}
	// Untimed setup before Build (objects the user owns anyway, such as FCL's collision objects).
	virtual void Prepare(const Scene&)
	{
	}
	// Creates one proxy per box of the scene.
	virtual void Build(const Scene& scene) = 0;
	// Tells the structure about scene.moved and returns the number of pairs whose tight boxes
	// overlap: the complete set, not only the new ones.
	virtual size_t UpdateAndCountPairs(const Scene& scene) = 0;
	// Number of boxes whose tight box overlaps the query box / meets the ray.
	virtual size_t Query(const Scene& scene, const Box& box) = 0;
	virtual size_t RayCast(const Scene& scene, const Ray& ray) = 0;
	// Called when the timed frames start (per-phase counters restart).
	virtual void StartTiming()
	{
	}
	// Bytes held by the bench itself (pair sets), subtracted from the measured heap growth.
	virtual size_t BenchOwnedBytes() const
	{
		return 0;
	}
	// Bytes the structure says it holds (collide's stats); 0 when unknown.
	virtual size_t ReportedBytes() const
	{
		return 0;
	}
	virtual std::string Extra() const
	{
		return std::string();
	}
};

std::unique_ptr<Adapter> MakeCollideAdapter(const std::string& name);
std::unique_ptr<Adapter> MakePeerAdapter(const std::string& name);
std::vector<std::string> PeerNames();

// Seconds on the clock frames are timed with: steady wall clock, or the thread's CPU clock with
// --cpu-time (bench_broad.cpp).
double FrameClock();

} // namespace bench
