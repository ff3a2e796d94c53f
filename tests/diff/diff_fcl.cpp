// Differential test of the 3D distance and overlap against FCL 0.7 (libfcl-dev): fcl::distance and
// fcl::collide with both of FCL's GJK solvers (GST_LIBCCD and GST_INDEP) on thousands of random
// sphere, capsule, box and convex-hull pairs (rotated), with the exact signed distance of exact3.h
// (double) as the referee.
//
// collide is held to the reference: cd3Distance within 1e-4 relative (1e-5 absolute for short
// distances) on every separated pair, cd3Overlap's answer on every pair away from the boundary
// (|distance| > 1e-3 of the pair's size). FCL is a peer: its answers are counted and printed, not
// asserted pair by pair. FCL's own GJK (GST_INDEP) is wrong on a few polytope pairs in a thousand
// (boxes and fcl::Convex hulls: distances too long by up to tens of per cent, an overlap missed);
// with the libccd solver its distances stop at libccd's tolerance (up to a few 1e-4 relative, more
// now and then on curved-against-flat pairs). On the pairs without a hull FCL must agree nearly
// everywhere, which also proves the adapters (shape and transform conversion) right.
#include <fcl/fcl.h>

#include "collide/collide.h"
#include "exact3.h"
#include "random_shapes3.h"
#include "test.h"

#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>

namespace
{
using exact3::V3;

std::vector<cd3Hull*> MakeHullPool(int count)
{
	TestRng rng = {0xfc1fc1u};
	std::vector<cd3Hull*> pool;
	while ((int)pool.size() < count)
	{
		cd3Hull* hull = nullptr;
		double a = TestRngRange(&rng, 0.3, 1.2), b = TestRngRange(&rng, 0.3, 1.2),
			   c = TestRngRange(&rng, 0.3, 1.2);
		if (pool.size() % 3 == 0)
		{
			cd3MakeCylinderHull((cdReal)a, (cdReal)b, 3 + TestRngInt(&rng, 14), &hull);
		}
		else
		{
			int n = 8 + TestRngInt(&rng, 25);
			std::vector<cd3Vec> points;
			for (int i = 0; i < n; ++i)
			{
				points.push_back(cd3MakeVec((cdReal)(a * TestRngRange(&rng, -1, 1)),
											(cdReal)(b * TestRngRange(&rng, -1, 1)),
											(cdReal)(c * TestRngRange(&rng, -1, 1))));
			}
			cd3ComputeHull(points.data(), n, &hull);
		}
		if (hull != nullptr)
		{
			pool.push_back(hull);
		}
	}
	return pool;
}

cd3Shape RandomShape(TestRng* rng, cd3ShapeType type, const std::vector<cd3Hull*>& pool)
{
	cd3Shape s;
	std::memset(&s, 0, sizeof s);
	s.type = type;
	cd3Vec center = RandomVec(rng, 1.5);
	switch (type)
	{
		case CD3_SHAPE_SPHERE:
			s.sphere.center = center;
			s.sphere.radius = (cdReal)TestRngRange(rng, 0.1, 1.2);
			break;
		case CD3_SHAPE_CAPSULE:
		{
			cd3Vec half = RandomVec(rng, 0.8);
			s.capsule.p1 = cd3Sub(center, half);
			s.capsule.p2 = cd3Add(center, half);
			s.capsule.radius = (cdReal)TestRngRange(rng, 0.1, 0.8);
			break;
		}
		case CD3_SHAPE_BOX:
			s.box.center = center;
			s.box.halfExtents =
				cd3MakeVec((cdReal)TestRngRange(rng, 0.1, 1.2), (cdReal)TestRngRange(rng, 0.1, 1.2),
						   (cdReal)TestRngRange(rng, 0.1, 1.2));
			s.box.rotation = RandomQuat(rng);
			break;
		default:
			s.type = CD3_SHAPE_HULL;
			s.hull.hull = pool[(size_t)TestRngInt(rng, (int)pool.size())];
			s.hull.transform.p = center;
			s.hull.transform.q = RandomQuat(rng);
			break;
	}
	return s;
}

// ---- FCL adapters -----------------------------------------------------------------------------

fcl::Transform3d Placement(cd3Vec p, cd3Quat q)
{
	fcl::Transform3d t = fcl::Transform3d::Identity();
	t.translation() = fcl::Vector3d((double)p.x, (double)p.y, (double)p.z);
	t.linear() =
		fcl::Quaterniond((double)q.w, (double)q.x, (double)q.y, (double)q.z).normalized().toRotationMatrix();
	return t;
}

struct FclShape
{
	std::shared_ptr<fcl::CollisionGeometryd> geometry;
	fcl::Transform3d transform;
};

FclShape ToFcl(const cd3Shape& s)
{
	FclShape f;
	switch (s.type)
	{
		case CD3_SHAPE_SPHERE:
			f.geometry = std::make_shared<fcl::Sphered>((double)s.sphere.radius);
			f.transform = fcl::Transform3d::Identity();
			f.transform.translation() = fcl::Vector3d((double)s.sphere.center.x, (double)s.sphere.center.y,
													  (double)s.sphere.center.z);
			break;
		case CD3_SHAPE_CAPSULE:
		{
			// FCL's capsule lies along its local z axis, centred, of length lz between the caps' centres.
			V3 p1 = exact3::FromVec(s.capsule.p1), p2 = exact3::FromVec(s.capsule.p2);
			V3 axis = p2 - p1;
			double length = exact3::Length(axis);
			f.geometry = std::make_shared<fcl::Capsuled>((double)s.capsule.radius, length);
			f.transform = fcl::Transform3d::Identity();
			V3 c = 0.5 * (p1 + p2);
			f.transform.translation() = fcl::Vector3d(c.x, c.y, c.z);
			if (length > 0.0)
			{
				f.transform.linear() = fcl::Quaterniond::FromTwoVectors(fcl::Vector3d(0, 0, 1),
																		fcl::Vector3d(axis.x, axis.y, axis.z))
										   .toRotationMatrix();
			}
			break;
		}
		case CD3_SHAPE_BOX:
			f.geometry = std::make_shared<fcl::Boxd>(2.0 * (double)s.box.halfExtents.x,
													 2.0 * (double)s.box.halfExtents.y,
													 2.0 * (double)s.box.halfExtents.z);
			f.transform = Placement(s.box.center, s.box.rotation);
			break;
		default:
		{
			const cd3Hull* h = s.hull.hull;
			auto vertices = std::make_shared<std::vector<fcl::Vector3d>>();
			for (int i = 0; i < h->vertexCount; ++i)
			{
				vertices->emplace_back((double)h->vertices[i].x, (double)h->vertices[i].y,
									   (double)h->vertices[i].z);
			}
			// Faces as FCL wants them: vertex count, then the vertices counter-clockwise seen from outside.
			auto faces = std::make_shared<std::vector<int>>();
			for (int face = 0; face < h->faceCount; ++face)
			{
				size_t countAt = faces->size();
				faces->push_back(0);
				int first = h->faceEdges[face], e = first;
				do
				{
					faces->push_back(h->edges[e].origin);
					++(*faces)[countAt];
					e = h->edges[e].next;
				} while (e != first);
			}
			auto convex = std::make_shared<fcl::Convexd>(vertices, h->faceCount, faces);
			convex->computeLocalAABB();
			f.geometry = convex;
			f.transform = Placement(s.hull.transform.p, s.hull.transform.q);
			break;
		}
	}
	f.geometry->computeLocalAABB();
	return f;
}

struct Tally
{
	int pairs = 0, compared = 0, separated = 0;
	double collideMaxRel = 0, collideSumRel = 0;
	int fclWrongOverlap[2] = {0, 0}, fclOff[2] = {0, 0}, fclFar[2] = {0, 0};
	double fclMaxRel[2] = {0, 0}, fclSumRel[2] = {0, 0};
};

const char* kSolverNames[2] = {"libccd", "indep"};

void ComparePair(const cd3Shape& a, const cd3Shape& b, int index, Tally* t)
{
	exact3::Signed ref = exact3::SignedDistance(a, b);
	++t->pairs;
	if (std::fabs(ref.distance) <= 1e-3 * ref.size)
	{
		return;
	}
	++t->compared;
	const char* na = cd3GetShapeTypeName(a.type);
	const char* nb = cd3GetShapeTypeName(b.type);
	bool overlapping = ref.distance < 0.0;
	TEST_CHECKF(cd3Overlap(&a, &b) == overlapping, "%s-%s #%d: cd3Overlap %d, exact distance %.9g", na, nb,
				index, (int)cd3Overlap(&a, &b), ref.distance);
	double mine = (double)cd3Distance(&a, &b).distance;
	double tol = 1e-4 * std::max(std::fabs(ref.distance), 0.1);
	if (overlapping)
	{
		TEST_CHECKF(mine == 0.0, "%s-%s #%d: cd3Distance %.9g, exact: overlapping by %.9g", na, nb, index,
					mine, -ref.distance);
	}
	else
	{
		++t->separated;
		TEST_CHECKF(std::fabs(mine - ref.distance) <= tol, "%s-%s #%d: cd3Distance %.9g, exact %.9g", na, nb,
					index, mine, ref.distance);
		double rel = std::fabs(mine - ref.distance) / ref.distance;
		t->collideMaxRel = std::max(t->collideMaxRel, rel);
		t->collideSumRel += rel;
	}

	FclShape fa = ToFcl(a), fb = ToFcl(b);
	for (int solver = 0; solver < 2; ++solver)
	{
		fcl::GJKSolverType type = solver == 0 ? fcl::GST_LIBCCD : fcl::GST_INDEP;
		fcl::CollisionRequestd creq;
		creq.gjk_solver_type = type;
		fcl::CollisionResultd cres;
		fcl::collide(fa.geometry.get(), fa.transform, fb.geometry.get(), fb.transform, creq, cres);
		if (cres.isCollision() != overlapping)
		{
			if (++t->fclWrongOverlap[solver] <= 2)
			{
				std::printf("  fcl::collide (%s) %s-%s #%d: %d, exact distance %.9g\n", kSolverNames[solver],
							na, nb, index, (int)cres.isCollision(), ref.distance);
			}
		}
		if (overlapping)
		{
			continue;
		}
		fcl::DistanceRequestd dreq;
		dreq.gjk_solver_type = type;
		fcl::DistanceResultd dres;
		fcl::distance(fa.geometry.get(), fa.transform, fb.geometry.get(), fb.transform, dreq, dres);
		double theirs = dres.min_distance;
		double rel = std::fabs(theirs - ref.distance) / ref.distance;
		t->fclMaxRel[solver] = std::max(t->fclMaxRel[solver], rel);
		t->fclSumRel[solver] += rel;
		if (std::fabs(theirs - ref.distance) > tol)
		{
			++t->fclOff[solver];
			if (rel > 1e-2 && ++t->fclFar[solver] <= 2)
			{
				std::printf("  fcl::distance (%s) %s-%s #%d: %.9g, exact %.9g, collide %.9g\n",
							kSolverNames[solver], na, nb, index, theirs, ref.distance, mine);
			}
		}
	}
}

void TestPairs()
{
	std::vector<cd3Hull*> pool = MakeHullPool(18);
	const cd3ShapeType types[] = {CD3_SHAPE_SPHERE, CD3_SHAPE_CAPSULE, CD3_SHAPE_BOX, CD3_SHAPE_HULL};
	TestRng rng = TestRngMake(0xfc1u);
	for (cd3ShapeType ta : types)
	{
		for (cd3ShapeType tb : types)
		{
			if (tb < ta)
			{
				continue;
			}
			Tally t;
			const int count = 400;
			for (int n = 0; n < count; ++n)
			{
				cd3Shape a = RandomShape(&rng, ta, pool), b = RandomShape(&rng, tb, pool);
				ComparePair(a, b, n, &t);
			}
			std::printf("%s-%s: %d pairs, %d away from the boundary, %d separated; collide distance max rel "
						"%.2e mean "
						"%.2e",
						cd3GetShapeTypeName(ta), cd3GetShapeTypeName(tb), t.pairs, t.compared, t.separated,
						t.collideMaxRel, t.separated ? t.collideSumRel / t.separated : 0.0);
			for (int s = 0; s < 2; ++s)
			{
				std::printf(
					"; FCL %s: overlap wrong %d, distance off >1e-4 %d (>1e-2 %d), max rel %.2e mean %.2e",
					kSolverNames[s], t.fclWrongOverlap[s], t.fclOff[s], t.fclFar[s], t.fclMaxRel[s],
					t.separated ? t.fclSumRel[s] / t.separated : 0.0);
			}
			std::printf("\n");
			TEST_CHECK(t.compared > count / 2);
			TEST_CHECK(t.separated > count / 10);
			// Pairs without a hull: FCL must agree nearly everywhere (this proves the adapters); with
			// hulls its answers are only counted.
			if (ta != CD3_SHAPE_HULL && tb != CD3_SHAPE_HULL)
			{
				for (int s = 0; s < 2; ++s)
				{
					TEST_CHECKF(t.fclWrongOverlap[s] * 50 < t.compared,
								"%s-%s: FCL %s overlap wrong on %d of %d", cd3GetShapeTypeName(ta),
								cd3GetShapeTypeName(tb), kSolverNames[s], t.fclWrongOverlap[s], t.compared);
					TEST_CHECKF(t.fclFar[s] * 50 < t.separated,
								"%s-%s: FCL %s distance off by 1e-2 on %d of %d", cd3GetShapeTypeName(ta),
								cd3GetShapeTypeName(tb), kSolverNames[s], t.fclFar[s], t.separated);
				}
			}
		}
	}
	for (cd3Hull* h : pool)
	{
		cd3DestroyHull(h);
	}
}
} // namespace

int main()
{
	TEST_RUN(TestPairs);
	return TEST_SUMMARY();
}
