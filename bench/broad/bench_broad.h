// collide broadphase benchmark: the scene every structure sees and the adapter each structure
// (ours and the peers) implements. C++ only because the peers are C++ libraries.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace bench
{

struct Box
{
	float min[3];
	float max[3];
};

// Closed boxes: touching counts, as in collide. In 2D the z range is the same for every box.
inline bool Overlap(const Box& a, const Box& b)
{
	return a.min[0] <= b.max[0] && b.min[0] <= a.max[0] && a.min[1] <= b.max[1] && b.min[1] <= a.max[1] &&
		   a.min[2] <= b.max[2] && b.min[2] <= a.max[2];
}

struct Ray
{
	float origin[3];
	float translation[3];
};

// Slab test of the segment origin + t * translation, t in [0, 1], against a closed box.
bool RayHitsBox(const Ray& ray, const Box& box);

enum class SceneKind
{
	Moving, // every box moves a little every frame
	Mix		// 90% still, 9% moving, 1% teleporting every frame
};

// Deterministic scene: boxes of edge 0.5..1.5 m in a cube (square in 2D) sized so that each box
// overlaps about one other on average, whatever N.
struct Scene
{
	int dim = 3;
	int n = 0;
	SceneKind kind = SceneKind::Moving;
	float worldSize = 0.0f;
	float timeStep = 1.0f / 60.0f;
	std::vector<Box> boxes;
	std::vector<float> velocity;	 // 3 per box
	std::vector<float> displacement; // 3 per box: predicted displacement for the next frame
	std::vector<int> moved;			 // boxes moved by the last Step
	std::vector<Box> queries;
	std::vector<Ray> rays;
	uint64_t rngState = 0;

	void Init(int dimension, int count, SceneKind sceneKind, uint64_t seed);
	void Step(int frame);
	Box WorldBounds() const;
};

// Collects the pairs of one frame. Incremental structures (collide, Box2D) report only the pairs
// that involve a moved proxy, so they keep a persistent set of candidate pairs like a physics
// engine's contact list: new pairs are added, pairs whose fat boxes no longer overlap are dropped.
class PairSet
{
  public:
	// Returns true if the pair was new.
	bool Insert(int a, int b);
	template <typename StillOverlaps> void RemoveIf(StillOverlaps&& keep);
	template <typename Fn> void ForEach(Fn&& fn) const;
	size_t Count() const
	{
		return count_;
	}
	size_t Bytes() const
	{
		return slots_.size() * sizeof(uint64_t);
	}
	void Clear();

  private:
	static constexpr uint64_t kEmpty = ~uint64_t(0);
	static uint64_t Key(int a, int b)
	{
		return a < b ? (uint64_t(uint32_t(a)) << 32) | uint32_t(b)
					 : (uint64_t(uint32_t(b)) << 32) | uint32_t(a);
	}
	static size_t Hash(uint64_t key)
	{
		key ^= key >> 33;
		key *= 0xff51afd7ed558ccdULL;
		key ^= key >> 33;
		return size_t(key);
	}
	void Grow();
	void EraseSlot(size_t slot);
	std::vector<uint64_t> slots_;
	size_t count_ = 0;
};

template <typename Fn> void PairSet::ForEach(Fn&& fn) const
{
	for (uint64_t key : slots_)
	{
		if (key != kEmpty)
		{
			fn(int(key >> 32), int(key & 0xffffffffu));
		}
	}
}

// Linear probing with backward-shift deletion. The sweep starts just after an empty slot so that
// no cluster wraps past the start: every element is visited exactly once even while deleting.
template <typename StillOverlaps> void PairSet::RemoveIf(StillOverlaps&& keep)
{
	if (count_ == 0)
	{
		return;
	}
	size_t mask = slots_.size() - 1;
	size_t start = 0;
	while (slots_[start] != kEmpty)
	{
		++start;
	}
	for (size_t step = 1; step <= slots_.size(); ++step)
	{
		size_t slot = (start + step) & mask;
		while (slots_[slot] != kEmpty)
		{
			uint64_t key = slots_[slot];
			if (keep(int(key >> 32), int(key & 0xffffffffu)))
			{
				break;
			}
			EraseSlot(slot); // may pull a later element into this slot: look again
		}
	}
}

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

} // namespace bench
