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

// The complete set of overlapping pairs for structures that report, per frame, every pair that
// involves a moved proxy (collide's and Box2D's UpdatePairs), as a physics engine keeps its
// contact list: pairs of two unmoved proxies stay as they were (their fat boxes did not change),
// pairs with a moved side are dropped and come back among the reported ones if they still
// overlap. A plain array suffices, no lookups.
class PairList
{
  public:
	void MarkMoved(int index)
	{
		if (index >= int(moved_.size()))
		{
			moved_.resize(size_t(index) + 1, 0);
		}
		if (!moved_[size_t(index)])
		{
			moved_[size_t(index)] = 1;
			movedList_.push_back(index);
		}
	}
	void Add(int a, int b)
	{
		fresh_.push_back(Pair{a, b});
	}
	// Drops the pairs with a moved side, appends the reported ones and forgets the moves.
	// Returns the number of pairs whose tight boxes overlap.
	size_t EndFrame(const std::vector<Box>& boxes);
	size_t Bytes() const
	{
		return (pairs_.capacity() + fresh_.capacity()) * sizeof(Pair) + moved_.capacity() +
			   movedList_.capacity() * sizeof(int);
	}

  private:
	struct Pair
	{
		int a, b;
	};
	std::vector<Pair> pairs_, fresh_;
	std::vector<uint8_t> moved_;
	std::vector<int> movedList_;
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

} // namespace bench
