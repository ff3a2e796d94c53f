// The peers from Debian packages behind the bench adapter: Bullet (btDbvtBroadphase,
// bt32BitAxisSweep3), FCL (DynamicAABBTreeCollisionManager) and Box2D 2.4 (b2BroadPhase).
// Each is used as its documentation says; each reports candidate pairs on its own (fat or
// quantized) boxes and the bench counts those whose tight boxes overlap, so every structure must
// produce a superset of the true pairs for the counts to agree.
#include "bench_broad.h"

#include <cmath>
#include <cstdio>

#if BENCH_HAVE_BULLET
#include <BulletCollision/BroadphaseCollision/btAxisSweep3.h>
#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/BroadphaseCollision/btOverlappingPairCache.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionDispatch/btDefaultCollisionConfiguration.h>
#endif
#if BENCH_HAVE_FCL
#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/narrowphase/collision_object.h>
#endif
#if BENCH_HAVE_BOX2D
#include <box2d/b2_broad_phase.h>
#endif

namespace bench
{
namespace
{

#if BENCH_HAVE_BULLET
btVector3 Min3(const Box& b)
{
	return btVector3(b.min[0], b.min[1], b.min[2]);
}

btVector3 Max3(const Box& b)
{
	return btVector3(b.max[0], b.max[1], b.max[2]);
}

int IndexOf(const btBroadphaseProxy* proxy)
{
	return int(reinterpret_cast<intptr_t>(proxy->m_clientObject));
}

struct BulletQueryCallback : btBroadphaseAabbCallback
{
	const Scene* scene;
	Box box;
	size_t hits = 0;
	bool process(const btBroadphaseProxy* proxy) override
	{
		hits += Overlap(scene->boxes[size_t(IndexOf(proxy))], box) ? 1 : 0;
		return true;
	}
};

struct BulletRayCallback : btBroadphaseRayCallback
{
	const Scene* scene;
	Ray ray;
	size_t hits = 0;
	BulletRayCallback(const Scene& s, const Ray& r) : scene(&s), ray(r)
	{
		// The ray callback caches what btDbvt's ray test needs; btCollisionWorld does the same.
		btVector3 direction(r.translation[0], r.translation[1], r.translation[2]);
		btScalar length = direction.length();
		direction = length > 0 ? direction / length : btVector3(1, 0, 0);
		for (int axis = 0; axis < 3; ++axis)
		{
			m_rayDirectionInverse[axis] =
				direction[axis] == btScalar(0) ? btScalar(BT_LARGE_FLOAT) : btScalar(1) / direction[axis];
			m_signs[axis] = m_rayDirectionInverse[axis] < 0;
		}
		m_lambda_max = length;
	}
	bool process(const btBroadphaseProxy* proxy) override
	{
		hits += RayHitsBox(ray, scene->boxes[size_t(IndexOf(proxy))]) ? 1 : 0;
		return true;
	}
};

class BulletAdapter : public Adapter
{
  public:
	explicit BulletAdapter(bool sweep) : sweep_(sweep), dispatcher_(&configuration_)
	{
	}
	~BulletAdapter() override
	{
		if (broadphase_)
		{
			// destroyProxy scans the whole pair cache for each proxy (O(N * pairs): hours at 1M), so
			// large runs leave the proxies to the process exit.
			if (proxies_.size() <= 100000)
			{
				for (btBroadphaseProxy* proxy : proxies_)
				{
					broadphase_->destroyProxy(proxy, &dispatcher_);
				}
				delete broadphase_;
			}
		}
	}
	std::string Name() const override
	{
		return sweep_ ? "bullet-sap" : "bullet-dbvt";
	}
	bool SupportsDim(int) const override
	{
		return true; // 2D: every box has the same z range
	}
	void Build(const Scene& scene) override
	{
		if (sweep_)
		{
			// Default construction, as Bullet users get it: includes the btDbvt ray-cast
			// accelerator, which also serves aabbTest.
			Box world = scene.WorldBounds();
			broadphase_ = new bt32BitAxisSweep3(Min3(world) - btVector3(2, 2, 2),
												Max3(world) + btVector3(2, 2, 2), unsigned(scene.n + 16));
		}
		else
		{
			broadphase_ = new btDbvtBroadphase();
		}
		proxies_.resize(size_t(scene.n));
		for (int i = 0; i < scene.n; ++i)
		{
			const Box& b = scene.boxes[size_t(i)];
			proxies_[size_t(i)] = broadphase_->createProxy(
				Min3(b), Max3(b), 0, reinterpret_cast<void*>(intptr_t(i)), 1, -1, &dispatcher_);
		}
	}
	size_t UpdateAndCountPairs(const Scene& scene) override
	{
		for (size_t k = 0; k < scene.moved.count; ++k)
		{
			PrefetchMovedInputs(scene, k, proxies_.data());
			size_t i = size_t(scene.moved[k]);
			const Box& b = scene.boxes[i];
			broadphase_->setAabb(proxies_[i], Min3(b), Max3(b), &dispatcher_);
		}
		broadphase_->calculateOverlappingPairs(&dispatcher_);
		// The pair cache holds every pair whose (fat / quantized) boxes overlapped when last
		// checked; btDbvt removes stale pairs lazily, so filter with the tight boxes.
		btBroadphasePairArray& pairs = broadphase_->getOverlappingPairCache()->getOverlappingPairArray();
		size_t count = 0;
		for (int k = 0; k < pairs.size(); ++k)
		{
			const btBroadphasePair& pair = pairs[k];
			count += Overlap(scene.boxes[size_t(IndexOf(pair.m_pProxy0))],
							 scene.boxes[size_t(IndexOf(pair.m_pProxy1))])
						 ? 1
						 : 0;
		}
		return count;
	}
	size_t Query(const Scene& scene, const Box& box) override
	{
		BulletQueryCallback callback;
		callback.scene = &scene;
		callback.box = box;
		broadphase_->aabbTest(Min3(box), Max3(box), callback);
		return callback.hits;
	}
	size_t RayCast(const Scene& scene, const Ray& ray) override
	{
		BulletRayCallback callback(scene, ray);
		btVector3 from(ray.origin[0], ray.origin[1], ray.origin[2]);
		btVector3 to = from + btVector3(ray.translation[0], ray.translation[1], ray.translation[2]);
		broadphase_->rayTest(from, to, callback);
		return callback.hits;
	}

  private:
	bool sweep_;
	btDefaultCollisionConfiguration configuration_;
	btCollisionDispatcher dispatcher_;
	btBroadphaseInterface* broadphase_ = nullptr;
	std::vector<btBroadphaseProxy*> proxies_;
};
#endif

#if BENCH_HAVE_FCL
using FclObject = fcl::CollisionObject<double>;

struct FclPairData
{
	const Scene* scene;
	size_t count;
};

bool FclPairCallback(FclObject* a, FclObject* b, void* data)
{
	FclPairData* d = static_cast<FclPairData*>(data);
	int ia = int(reinterpret_cast<intptr_t>(a->getUserData()));
	int ib = int(reinterpret_cast<intptr_t>(b->getUserData()));
	d->count += Overlap(d->scene->boxes[size_t(ia)], d->scene->boxes[size_t(ib)]) ? 1 : 0;
	return false; // go on
}

struct FclQueryData
{
	const Scene* scene;
	const Box* box;
	size_t hits;
};

bool FclQueryCallback(FclObject* a, FclObject* b, void* data)
{
	FclQueryData* d = static_cast<FclQueryData*>(data);
	intptr_t ia = reinterpret_cast<intptr_t>(a->getUserData());
	intptr_t ib = reinterpret_cast<intptr_t>(b->getUserData());
	intptr_t index = ia >= 0 ? ia : ib; // the query object carries -1
	d->hits += Overlap(d->scene->boxes[size_t(index)], *d->box) ? 1 : 0;
	return false;
}

std::shared_ptr<fcl::Boxd> FclShape(const Box& b)
{
	return std::make_shared<fcl::Boxd>(double(b.max[0]) - b.min[0], double(b.max[1]) - b.min[1],
									   double(b.max[2]) - b.min[2]);
}

fcl::Vector3d FclCenter(const Box& b)
{
	return fcl::Vector3d(0.5 * (double(b.min[0]) + b.max[0]), 0.5 * (double(b.min[1]) + b.max[1]),
						 0.5 * (double(b.min[2]) + b.max[2]));
}

class FclAdapter : public Adapter
{
  public:
	std::string Name() const override
	{
		return "fcl-dtree";
	}
	bool SupportsDim(int dim) const override
	{
		return dim == 3;
	}
	bool SupportsRay() const override
	{
		return false; // FCL's broadphase managers have no ray cast
	}
	// FCL works on collision objects the user owns; making them is setup, not build.
	void Prepare(const Scene& scene) override
	{
		objects_.clear();
		objects_.reserve(size_t(scene.n));
		for (int i = 0; i < scene.n; ++i)
		{
			const Box& b = scene.boxes[size_t(i)];
			FclObject* object = new FclObject(FclShape(b));
			object->setTranslation(FclCenter(b));
			object->computeAABB();
			object->setUserData(reinterpret_cast<void*>(intptr_t(i)));
			objects_.push_back(object);
		}
	}
	~FclAdapter() override
	{
		manager_.reset();
		for (FclObject* object : objects_)
		{
			delete object;
		}
	}
	void Build(const Scene&) override
	{
		manager_.reset(new fcl::DynamicAABBTreeCollisionManager<double>());
		manager_->registerObjects(objects_);
		manager_->setup();
	}
	size_t UpdateAndCountPairs(const Scene& scene) override
	{
		updated_.clear();
		for (size_t k = 0; k < scene.moved.count; ++k)
		{
			PrefetchMovedInputs(scene, k, objects_.data());
			size_t i = size_t(scene.moved[k]);
			FclObject* object = objects_[i];
			object->setTranslation(FclCenter(scene.boxes[i]));
			object->computeAABB();
			updated_.push_back(object);
		}
		manager_->update(updated_);
		FclPairData data{&scene, 0};
		manager_->collide(&data, FclPairCallback);
		return data.count;
	}
	size_t Query(const Scene& scene, const Box& box) override
	{
		FclObject query(FclShape(box));
		query.setTranslation(FclCenter(box));
		query.computeAABB();
		query.setUserData(reinterpret_cast<void*>(intptr_t(-1)));
		FclQueryData data{&scene, &box, 0};
		manager_->collide(&query, &data, FclQueryCallback);
		return data.hits;
	}
	size_t RayCast(const Scene&, const Ray&) override
	{
		return 0;
	}
	size_t BenchOwnedBytes() const override
	{
		return updated_.capacity() * sizeof(FclObject*);
	}

  private:
	std::vector<FclObject*> objects_;
	std::vector<FclObject*> updated_;
	std::unique_ptr<fcl::DynamicAABBTreeCollisionManager<double>> manager_;
};
#endif

#if BENCH_HAVE_BOX2D
class Box2dAdapter : public Adapter
{
  public:
	std::string Name() const override
	{
		return "box2d";
	}
	bool SupportsDim(int dim) const override
	{
		return dim == 2;
	}
	void Build(const Scene& scene) override
	{
		proxies_.resize(size_t(scene.n));
		pairs_.Reset(scene.n);
		for (int i = 0; i < scene.n; ++i)
		{
			proxies_[size_t(i)] =
				broadphase_.CreateProxy(ToB2(scene.boxes[size_t(i)]), reinterpret_cast<void*>(intptr_t(i)));
		}
	}
	// b2BroadPhase::UpdatePairs calls this for each pair that involves a moved proxy.
	void AddPair(void* a, void* b)
	{
		pairs_.Add(int(reinterpret_cast<intptr_t>(a)), int(reinterpret_cast<intptr_t>(b)));
	}
	size_t UpdateAndCountPairs(const Scene& scene) override
	{
		for (size_t k = 0; k < scene.moved.count; ++k)
		{
			PrefetchMovedInputs(scene, k, proxies_.data());
			int i = scene.moved[k];
			const float* d = &scene.displacement[size_t(i) * 3];
			int32 proxy = proxies_[size_t(i)];
			b2AABB before = broadphase_.GetFatAABB(proxy);
			broadphase_.MoveProxy(proxy, ToB2(scene.boxes[size_t(i)]), b2Vec2(d[0], d[1]));
			// MoveProxy says nothing; a changed fat box is what makes UpdatePairs report the proxy.
			const b2AABB& after = broadphase_.GetFatAABB(proxy);
			if (!(before.lowerBound == after.lowerBound && before.upperBound == after.upperBound))
			{
				pairs_.MarkMoved(i);
			}
		}
		broadphase_.UpdatePairs(this);
		size_t count = pairs_.EndFrame(scene);
		return count;
	}
	struct B2Callback
	{
		const Scene* scene;
		const b2BroadPhase* broadphase;
		const Box* box;
		const Ray* ray;
		size_t hits;
		bool QueryCallbackImpl(int32 proxyId)
		{
			int index = int(reinterpret_cast<intptr_t>(broadphase->GetUserData(proxyId)));
			hits += Overlap(scene->boxes[size_t(index)], *box) ? 1 : 0;
			return true;
		}
		// b2BroadPhase::Query calls QueryCallback(proxyId).
		bool QueryCallback(int32 proxyId)
		{
			return QueryCallbackImpl(proxyId);
		}
		float RayCastCallback(const b2RayCastInput& input, int32 proxyId)
		{
			int index = int(reinterpret_cast<intptr_t>(broadphase->GetUserData(proxyId)));
			hits += RayHitsBox(*ray, scene->boxes[size_t(index)]) ? 1 : 0;
			return input.maxFraction;
		}
	};
	size_t Query(const Scene& scene, const Box& box) override
	{
		B2Callback callback{&scene, &broadphase_, &box, nullptr, 0};
		broadphase_.Query(&callback, ToB2(box));
		return callback.hits;
	}
	size_t RayCast(const Scene& scene, const Ray& ray) override
	{
		B2Callback callback{&scene, &broadphase_, nullptr, &ray, 0};
		b2RayCastInput input;
		input.p1.Set(ray.origin[0], ray.origin[1]);
		input.p2.Set(ray.origin[0] + ray.translation[0], ray.origin[1] + ray.translation[1]);
		input.maxFraction = 1.0f;
		broadphase_.RayCast(&callback, input);
		return callback.hits;
	}
	size_t BenchOwnedBytes() const override
	{
		return pairs_.Bytes() + proxies_.capacity() * sizeof(int32);
	}
	std::string Extra() const override
	{
		char text[64];
		std::snprintf(text, sizeof text, "height=%d", int(broadphase_.GetTreeHeight()));
		return text;
	}

  private:
	static b2AABB ToB2(const Box& b)
	{
		b2AABB a;
		a.lowerBound.Set(b.min[0], b.min[1]);
		a.upperBound.Set(b.max[0], b.max[1]);
		return a;
	}
	b2BroadPhase broadphase_;
	std::vector<int32> proxies_;
	PairList pairs_;
};
#endif

} // namespace

std::vector<std::string> PeerNames()
{
	std::vector<std::string> names;
#if BENCH_HAVE_BULLET
	names.push_back("bullet-dbvt");
	names.push_back("bullet-sap");
#endif
#if BENCH_HAVE_FCL
	names.push_back("fcl-dtree");
#endif
#if BENCH_HAVE_BOX2D
	names.push_back("box2d");
#endif
	return names;
}

std::unique_ptr<Adapter> MakePeerAdapter(const std::string& name)
{
#if BENCH_HAVE_BULLET
	if (name == "bullet-dbvt")
	{
		return std::unique_ptr<Adapter>(new BulletAdapter(false));
	}
	if (name == "bullet-sap")
	{
		return std::unique_ptr<Adapter>(new BulletAdapter(true));
	}
#endif
#if BENCH_HAVE_FCL
	if (name == "fcl-dtree")
	{
		return std::unique_ptr<Adapter>(new FclAdapter());
	}
#endif
#if BENCH_HAVE_BOX2D
	if (name == "box2d")
	{
		return std::unique_ptr<Adapter>(new Box2dAdapter());
	}
#endif
	(void)name;
	return nullptr;
}

} // namespace bench
