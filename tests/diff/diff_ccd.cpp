// Differential test of the 3D overlap and penetration depth against libccd 2.1 (libccd-dev):
// ccdGJKIntersect, ccdGJKPenetration (GJK + EPA) and ccdMPRPenetration, on thousands of random
// sphere, capsule, box and hull pairs (rotated), with the exact signed distance of exact3.h
// (double) as the referee.
//
// collide is held to the reference: cd3Overlap and cd3Collide's point count must give the
// reference's answer away from the boundary (|distance| > 1e-3 of the pair's size), and
// cd3Collide's deepest separation must be the exact depth within 1e-4 relative (1e-5 absolute for
// shallow pairs); at a face/edge tie it may be deeper by collide's documented bias (1e-3 of the
// pair's size). libccd is a peer, not the referee: its answers are counted and printed. Its EPA
// stops when the expanding polytope is within epa_tolerance (1e-4, absolute) of the boundary, which
// on curved shapes leaves it well inside the sphere (depths a few per cent short), and it reports a
// zero depth when GJK's last simplex is a segment or triangle through the origin; MPR returns the
// depth along its portal direction, which is not the minimal one (exact on two spheres only). The
// test asserts what those algorithms guarantee, which also proves the adapters and the reference:
// GJK's overlap answer matches away from the boundary on nearly every pair, EPA's depth is never
// beyond the exact one by more than its tolerance, MPR's never below it, and between polytopes
// EPA is within 1e-2 relative on most pairs.
#include <ccd/ccd.h>

#include "collide/collide.h"
#include "exact3.h"
#include "random_shapes3.h"
#include "test.h"

#include <cstdio>
#include <cstring>
#include <vector>

namespace
{
using exact3::Core;
using exact3::V3;

// ---- libccd adapters: support and centre of a core inflated by its radius ------------------

void Support(const void* object, const ccd_vec3_t* direction, ccd_vec3_t* out)
{
	const Core* core = static_cast<const Core*>(object);
	V3 d = {direction->v[0], direction->v[1], direction->v[2]};
	V3 best = core->vertices[0];
	double bestDot = exact3::Dot(best, d);
	for (V3 v : core->vertices)
	{
		double dot = exact3::Dot(v, d);
		if (dot > bestDot)
		{
			best = v;
			bestDot = dot;
		}
	}
	double length = exact3::Length(d);
	if (core->radius > 0.0 && length > 0.0)
	{
		best = best + (core->radius / length) * d;
	}
	ccdVec3Set(out, best.x, best.y, best.z);
}

void Center(const void* object, ccd_vec3_t* out)
{
	const Core* core = static_cast<const Core*>(object);
	V3 sum = {0, 0, 0};
	for (V3 v : core->vertices)
	{
		sum = sum + v;
	}
	sum = (1.0 / (double)core->vertices.size()) * sum;
	ccdVec3Set(out, sum.x, sum.y, sum.z);
}

ccd_t MakeCcd()
{
	ccd_t ccd;
	CCD_INIT(&ccd);
	ccd.support1 = Support;
	ccd.support2 = Support;
	ccd.center1 = Center;
	ccd.center2 = Center;
	ccd.max_iterations = 500;
	return ccd;
}

// ---- random shapes ----------------------------------------------------------------------------

// A pool of hulls: random clouds in a box or on an ellipsoid (8 to 32 points), cylinders, cones.
std::vector<cd3Hull*> MakeHullPool(int count)
{
	TestRng rng = {0xcc0de5u};
	std::vector<cd3Hull*> pool;
	while ((int)pool.size() < count)
	{
		cd3Hull* hull = nullptr;
		double a = TestRngRange(&rng, 0.3, 1.2), b = TestRngRange(&rng, 0.3, 1.2),
			   c = TestRngRange(&rng, 0.3, 1.2);
		switch (pool.size() % 4)
		{
			case 0:
				cd3MakeCylinderHull((cdReal)a, (cdReal)b, 3 + TestRngInt(&rng, 14), &hull);
				break;
			case 1:
				cd3MakeConeHull((cdReal)a, (cdReal)b, 3 + TestRngInt(&rng, 14), &hull);
				break;
			default:
			{
				int n = 8 + TestRngInt(&rng, 25);
				bool onEllipsoid = pool.size() % 4 == 3;
				std::vector<cd3Vec> points;
				for (int i = 0; i < n; ++i)
				{
					double x = TestRngRange(&rng, -1, 1), y = TestRngRange(&rng, -1, 1),
						   z = TestRngRange(&rng, -1, 1);
					double length = std::sqrt(x * x + y * y + z * z);
					if (onEllipsoid && length > 1e-3)
					{
						x /= length;
						y /= length;
						z /= length;
					}
					points.push_back(cd3MakeVec((cdReal)(a * x), (cdReal)(b * y), (cdReal)(c * z)));
				}
				cd3ComputeHull(points.data(), n, &hull);
				break;
			}
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
	cd3Vec center = RandomVec(rng, 1.0);
	switch (type)
	{
		case CD3_SHAPE_SPHERE:
			s.sphere.center = center;
			s.sphere.radius = (cdReal)TestRngRange(rng, 0.1, 1.2);
			break;
		case CD3_SHAPE_CAPSULE:
		{
			cd3Vec half = RandomVec(rng, 0.8);
			// One capsule in ten has zero length (a sphere through the capsule code).
			if (TestRngInt(rng, 10) == 0)
			{
				half = CD3_VEC_ZERO;
			}
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

double MinSeparation(const cd3Manifold& m)
{
	double s = INFINITY;
	for (int i = 0; i < m.pointCount; ++i)
	{
		s = std::min(s, (double)m.points[i].separation);
	}
	return s;
}

struct Stats
{
	int pairs = 0, compared = 0, penetrating = 0;
	int gjkWrong = 0;
	int epaCount = 0, epaZero = 0, epaMeasured = 0, epaOff = 0, epaBeyond = 0;
	double epaMaxRel = 0, epaSumRel = 0;
	int mprCount = 0, mprOff = 0, mprBelow = 0;
	double mprMaxRel = 0, mprSumRel = 0;
	double collideMaxRel = 0, collideSumRel = 0;
	int collideDepthCount = 0, collideTies = 0;
};

const double kRelative = 1e-4;
const double kCcdTolerance = 1e-4; // epa_tolerance and mpr_tolerance of CCD_INIT

void ComparePair(const cd3Shape& a, const cd3Shape& b, int index, Stats* st)
{
	Core ca = exact3::FromShape(a), cb = exact3::FromShape(b);
	exact3::Signed ref = exact3::SignedDistance(ca, cb);
	++st->pairs;
	double band = 1e-3 * ref.size;
	if (std::fabs(ref.distance) <= band)
	{
		return;
	}
	++st->compared;
	bool overlapping = ref.distance < 0.0;
	const char* na = cd3GetShapeTypeName(a.type);
	const char* nb = cd3GetShapeTypeName(b.type);

	TEST_CHECKF(cd3Overlap(&a, &b) == overlapping, "%s-%s #%d: cd3Overlap %d, exact distance %.9g", na, nb,
				index, (int)cd3Overlap(&a, &b), ref.distance);
	cd3Manifold m = cd3Collide(&a, &b, CD_R(0.0));
	TEST_CHECKF((m.pointCount > 0) == overlapping, "%s-%s #%d: cd3Collide %d points, exact distance %.9g", na,
				nb, index, m.pointCount, ref.distance);

	ccd_t ccd = MakeCcd();
	bool gjk = ccdGJKIntersect(&ca, &cb, &ccd) != 0;
	if (gjk != overlapping)
	{
		if (++st->gjkWrong <= 5)
		{
			std::printf("  ccdGJKIntersect %s-%s #%d: %d, exact distance %.9g\n", na, nb, index, (int)gjk,
						ref.distance);
		}
	}
	if (!overlapping)
	{
		return;
	}
	++st->penetrating;
	double exactDepth = -ref.distance;
	double tol = kRelative * std::max(exactDepth, 0.1);
	if (m.pointCount > 0)
	{
		double mine = -MinSeparation(m);
		bool tie = ref.tieGap < 1e-3 * ref.size;
		double lowest = exactDepth - tol, highest = exactDepth + tol + (tie ? 1e-3 * ref.size : 0.0);
		TEST_CHECKF(mine >= lowest && mine <= highest, "%s-%s #%d: cd3Collide depth %.9g, exact %.9g%s", na,
					nb, index, mine, exactDepth, tie ? " (face/edge tie)" : "");
		if (tie)
		{
			++st->collideTies;
		}
		else
		{
			double rel = std::fabs(mine - exactDepth) / exactDepth;
			st->collideMaxRel = std::max(st->collideMaxRel, rel);
			st->collideSumRel += rel;
			++st->collideDepthCount;
		}
	}

	ccd_real_t depth = 0;
	ccd_vec3_t dir, pos;
	if (ccdGJKPenetration(&ca, &cb, &ccd, &depth, &dir, &pos) == 0)
	{
		double d = (double)depth, rel = std::fabs(d - exactDepth) / exactDepth;
		++st->epaCount;
		if (d <= 1e-9 * exactDepth)
		{
			// libccd 2.1 reports a zero depth ("touching") when GJK's final simplex is a segment or a
			// triangle through the origin, however deep the shapes overlap.
			++st->epaZero;
		}
		else
		{
			++st->epaMeasured;
			st->epaMaxRel = std::max(st->epaMaxRel, rel);
			st->epaSumRel += rel;
			if (rel > 1e-2)
			{
				++st->epaOff;
			}
		}
		// EPA's polytope lies inside the Minkowski difference: its depth cannot exceed the exact one.
		if (d > exactDepth + kCcdTolerance + tol)
		{
			if (++st->epaBeyond <= 5)
			{
				std::printf("  ccdGJKPenetration %s-%s #%d: depth %.9g beyond the exact %.9g\n", na, nb,
							index, d, exactDepth);
			}
		}
	}
	if (ccdMPRPenetration(&ca, &cb, &ccd, &depth, &dir, &pos) == 0)
	{
		double d = (double)depth, rel = std::fabs(d - exactDepth) / exactDepth;
		++st->mprCount;
		st->mprMaxRel = std::max(st->mprMaxRel, rel);
		st->mprSumRel += rel;
		if (rel > 1e-2)
		{
			++st->mprOff;
		}
		// MPR's depth is measured along one direction: never below the minimal depth.
		if (d < exactDepth - kCcdTolerance - tol)
		{
			if (++st->mprBelow <= 5)
			{
				std::printf("  ccdMPRPenetration %s-%s #%d: depth %.9g below the exact %.9g\n", na, nb, index,
							d, exactDepth);
			}
		}
	}
}

void TestPairs()
{
	std::vector<cd3Hull*> pool = MakeHullPool(24);
	const cd3ShapeType types[] = {CD3_SHAPE_SPHERE, CD3_SHAPE_CAPSULE, CD3_SHAPE_BOX, CD3_SHAPE_HULL};
	TestRng rng = TestRngMake(0xccd0ccd0u);
	Stats total;
	for (cd3ShapeType ta : types)
	{
		for (cd3ShapeType tb : types)
		{
			if (tb < ta)
			{
				continue;
			}
			Stats st;
			int count = ta == CD3_SHAPE_HULL && tb == CD3_SHAPE_HULL ? 600 : 400;
			for (int n = 0; n < count; ++n)
			{
				cd3Shape a = RandomShape(&rng, ta, pool), b = RandomShape(&rng, tb, pool);
				ComparePair(a, b, n, &st);
			}
			std::printf(
				"%s-%s: %d pairs, %d away from the boundary, %d penetrating; collide depth max rel err %.2e "
				"mean %.2e (%d ties skipped); ccdGJKIntersect wrong %d; EPA n=%d, zero depth %d, max rel "
				"%.2e "
				"mean %.2e, off >1e-2: %d, beyond exact: %d; MPR n=%d max rel %.2e mean %.2e, off >1e-2: %d, "
				"below exact: %d\n",
				cd3GetShapeTypeName(ta), cd3GetShapeTypeName(tb), st.pairs, st.compared, st.penetrating,
				st.collideMaxRel, st.collideDepthCount ? st.collideSumRel / st.collideDepthCount : 0.0,
				st.collideTies, st.gjkWrong, st.epaCount, st.epaZero, st.epaMaxRel,
				st.epaMeasured ? st.epaSumRel / st.epaMeasured : 0.0, st.epaOff, st.epaBeyond, st.mprCount,
				st.mprMaxRel, st.mprCount ? st.mprSumRel / st.mprCount : 0.0, st.mprOff, st.mprBelow);
			TEST_CHECK(st.compared > count / 2);
			TEST_CHECK(st.penetrating > count / 10);
			total.compared += st.compared;
			total.penetrating += st.penetrating;
			total.gjkWrong += st.gjkWrong;
			total.epaCount += st.epaCount;
			total.epaZero += st.epaZero;
			if (ta != CD3_SHAPE_SPHERE && ta != CD3_SHAPE_CAPSULE)
			{
				// Between polytopes EPA converges to the exact depth (up to its tolerance).
				total.epaMeasured += st.epaMeasured;
				total.epaOff += st.epaOff;
			}
			total.epaBeyond += st.epaBeyond;
			total.mprBelow += st.mprBelow;
			// Both libccd algorithms must report (nearly) every penetrating pair.
			TEST_CHECK(st.epaCount * 100 >= st.penetrating * 99);
			TEST_CHECK(st.mprCount * 100 >= st.penetrating * 99);
		}
	}
	// libccd is a peer: its GJK must agree on nearly every pair away from the boundary, its EPA on
	// most depths, within what the algorithms guarantee. A broken adapter or reference fails here.
	TEST_CHECKF(total.gjkWrong * 200 < total.compared, "ccdGJKIntersect wrong on %d of %d", total.gjkWrong,
				total.compared);
	TEST_CHECKF(total.epaOff * 10 < total.epaMeasured,
				"EPA (polytope pairs) off by more than 1e-2 on %d of %d", total.epaOff, total.epaMeasured);
	std::printf("libccd: %d of %d penetrating pairs away from the boundary reported at zero depth by EPA\n",
				total.epaZero, total.epaCount);
	TEST_CHECKF(total.epaBeyond * 100 < total.epaCount, "EPA beyond the exact depth on %d of %d",
				total.epaBeyond, total.epaCount);
	TEST_CHECKF(total.mprBelow * 100 < total.epaCount, "MPR below the exact depth on %d of %d",
				total.mprBelow, total.epaCount);
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
