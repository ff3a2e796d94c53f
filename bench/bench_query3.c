/* collide_bench: the 3D rows: every overlap pair, point containment, closest points, ray casts,
 * the generic dispatchers and cd3Distance for every pair of shape types. */
#include "bench.h"

#define SPHERE CD3_SHAPE_SPHERE
#define CAPSULE CD3_SHAPE_CAPSULE
#define AABB CD3_SHAPE_AABB
#define BOX CD3_SHAPE_BOX
#define TRIANGLE CD3_SHAPE_TRIANGLE
#define PLANE CD3_SHAPE_PLANE
#define SEGMENT CD3_SHAPE_SEGMENT
#define HULL CD3_SHAPE_HULL

/* X(function, type of A, type of B, shape enum of A, shape enum of B) */
#define OVERLAP3_LIST(X)                                                                                     \
	X(cd3OverlapAabbAabb, cd3Aabb, cd3Aabb, AABB, AABB)                                                      \
	X(cd3OverlapSphereSphere, cd3Sphere, cd3Sphere, SPHERE, SPHERE)                                          \
	X(cd3OverlapSphereAabb, cd3Sphere, cd3Aabb, SPHERE, AABB)                                                \
	X(cd3OverlapSphereCapsule, cd3Sphere, cd3Capsule, SPHERE, CAPSULE)                                       \
	X(cd3OverlapSphereBox, cd3Sphere, cd3Box, SPHERE, BOX)                                                   \
	X(cd3OverlapSphereTriangle, cd3Sphere, cd3Triangle, SPHERE, TRIANGLE)                                    \
	X(cd3OverlapSpherePlane, cd3Sphere, cd3Plane, SPHERE, PLANE)                                             \
	X(cd3OverlapSphereSegment, cd3Sphere, cd3Segment, SPHERE, SEGMENT)                                       \
	X(cd3OverlapCapsuleCapsule, cd3Capsule, cd3Capsule, CAPSULE, CAPSULE)                                    \
	X(cd3OverlapCapsuleAabb, cd3Capsule, cd3Aabb, CAPSULE, AABB)                                             \
	X(cd3OverlapCapsuleBox, cd3Capsule, cd3Box, CAPSULE, BOX)                                                \
	X(cd3OverlapCapsuleTriangle, cd3Capsule, cd3Triangle, CAPSULE, TRIANGLE)                                 \
	X(cd3OverlapCapsulePlane, cd3Capsule, cd3Plane, CAPSULE, PLANE)                                          \
	X(cd3OverlapCapsuleSegment, cd3Capsule, cd3Segment, CAPSULE, SEGMENT)                                    \
	X(cd3OverlapAabbBox, cd3Aabb, cd3Box, AABB, BOX)                                                         \
	X(cd3OverlapAabbTriangle, cd3Aabb, cd3Triangle, AABB, TRIANGLE)                                          \
	X(cd3OverlapAabbPlane, cd3Aabb, cd3Plane, AABB, PLANE)                                                   \
	X(cd3OverlapAabbSegment, cd3Aabb, cd3Segment, AABB, SEGMENT)                                             \
	X(cd3OverlapBoxBox, cd3Box, cd3Box, BOX, BOX)                                                            \
	X(cd3OverlapBoxTriangle, cd3Box, cd3Triangle, BOX, TRIANGLE)                                             \
	X(cd3OverlapBoxPlane, cd3Box, cd3Plane, BOX, PLANE)                                                      \
	X(cd3OverlapBoxSegment, cd3Box, cd3Segment, BOX, SEGMENT)                                                \
	X(cd3OverlapTriangleTriangle, cd3Triangle, cd3Triangle, TRIANGLE, TRIANGLE)                              \
	X(cd3OverlapTrianglePlane, cd3Triangle, cd3Plane, TRIANGLE, PLANE)                                       \
	X(cd3OverlapTriangleSegment, cd3Triangle, cd3Segment, TRIANGLE, SEGMENT)                                 \
	X(cd3OverlapPlanePlane, cd3Plane, cd3Plane, PLANE, PLANE)                                                \
	X(cd3OverlapPlaneSegment, cd3Plane, cd3Segment, PLANE, SEGMENT)                                          \
	X(cd3OverlapSegmentSegment, cd3Segment, cd3Segment, SEGMENT, SEGMENT)

/* X(function, shape type, shape enum): bool function(cd3Vec p, shape) */
#define POINT_IN3_LIST(X)                                                                                    \
	X(cd3PointInAabb, cd3Aabb, AABB)                                                                         \
	X(cd3PointInSphere, cd3Sphere, SPHERE)                                                                   \
	X(cd3PointInCapsule, cd3Capsule, CAPSULE)                                                                \
	X(cd3PointInBox, cd3Box, BOX)                                                                            \
	X(cd3PointInPlane, cd3Plane, PLANE)                                                                      \
	X(cd3PointInHull, cd3HullShape, HULL)

/* X(function, shape type, shape enum): cd3Vec function(shape, cd3Vec p) */
#define CLOSEST3_LIST(X)                                                                                     \
	X(cd3ClosestPointOnSphere, cd3Sphere, SPHERE)                                                            \
	X(cd3ClosestPointOnCapsule, cd3Capsule, CAPSULE)                                                         \
	X(cd3ClosestPointOnAabb, cd3Aabb, AABB)                                                                  \
	X(cd3ClosestPointOnBox, cd3Box, BOX)                                                                     \
	X(cd3ClosestPointOnTriangle, cd3Triangle, TRIANGLE)                                                      \
	X(cd3ClosestPointOnPlane, cd3Plane, PLANE)                                                               \
	X(cd3ClosestPointOnSegment, cd3Segment, SEGMENT)                                                         \
	X(cd3ClosestPointOnHull, cd3HullShape, HULL)

/* X(function, type of A, type of B, enum of A, enum of B): cd3ClosestPoints function(a, b) */
#define CLOSEST_PAIR3_LIST(X)                                                                                \
	X(cd3ClosestPointsSegmentSegment, cd3Segment, cd3Segment, SEGMENT, SEGMENT)                              \
	X(cd3ClosestPointsTriangleSegment, cd3Triangle, cd3Segment, TRIANGLE, SEGMENT)

/* X(function, shape type, shape enum): bool function(shape, cd3Ray, cd3RayHit*) */
#define RAYCAST3_LIST(X)                                                                                     \
	X(cd3RaycastSphere, cd3Sphere, SPHERE)                                                                   \
	X(cd3RaycastCapsule, cd3Capsule, CAPSULE)                                                                \
	X(cd3RaycastAabb, cd3Aabb, AABB)                                                                         \
	X(cd3RaycastBox, cd3Box, BOX)                                                                            \
	X(cd3RaycastTriangle, cd3Triangle, TRIANGLE)                                                             \
	X(cd3RaycastPlane, cd3Plane, PLANE)                                                                      \
	X(cd3RaycastHull, cd3HullShape, HULL)

/* X(enum of A, name of A, enum of B, name of B): every unordered pair of shape types. */
#define DISTANCE3_LIST(X)                                                                                    \
	X(SPHERE, sphere, SPHERE, sphere)                                                                        \
	X(SPHERE, sphere, CAPSULE, capsule)                                                                      \
	X(SPHERE, sphere, AABB, aabb)                                                                            \
	X(SPHERE, sphere, BOX, box)                                                                              \
	X(SPHERE, sphere, TRIANGLE, triangle)                                                                    \
	X(SPHERE, sphere, PLANE, plane)                                                                          \
	X(SPHERE, sphere, SEGMENT, segment)                                                                      \
	X(CAPSULE, capsule, CAPSULE, capsule)                                                                    \
	X(CAPSULE, capsule, AABB, aabb)                                                                          \
	X(CAPSULE, capsule, BOX, box)                                                                            \
	X(CAPSULE, capsule, TRIANGLE, triangle)                                                                  \
	X(CAPSULE, capsule, PLANE, plane)                                                                        \
	X(CAPSULE, capsule, SEGMENT, segment)                                                                    \
	X(AABB, aabb, AABB, aabb)                                                                                \
	X(AABB, aabb, BOX, box)                                                                                  \
	X(AABB, aabb, TRIANGLE, triangle)                                                                        \
	X(AABB, aabb, PLANE, plane)                                                                              \
	X(AABB, aabb, SEGMENT, segment)                                                                          \
	X(BOX, box, BOX, box)                                                                                    \
	X(BOX, box, TRIANGLE, triangle)                                                                          \
	X(BOX, box, PLANE, plane)                                                                                \
	X(BOX, box, SEGMENT, segment)                                                                            \
	X(TRIANGLE, triangle, TRIANGLE, triangle)                                                                \
	X(TRIANGLE, triangle, PLANE, plane)                                                                      \
	X(TRIANGLE, triangle, SEGMENT, segment)                                                                  \
	X(PLANE, plane, PLANE, plane)                                                                            \
	X(PLANE, plane, SEGMENT, segment)                                                                        \
	X(SEGMENT, segment, SEGMENT, segment)                                                                    \
	X(SPHERE, sphere, HULL, hull)                                                                            \
	X(CAPSULE, capsule, HULL, hull)                                                                          \
	X(AABB, aabb, HULL, hull)                                                                                \
	X(BOX, box, HULL, hull)                                                                                  \
	X(TRIANGLE, triangle, HULL, hull)                                                                        \
	X(PLANE, plane, HULL, hull)                                                                              \
	X(SEGMENT, segment, HULL, hull)                                                                          \
	X(HULL, hull, HULL, hull)

/* ---- run functions -------------------------------------------------------------------------- */

#define DEFINE_OVERLAP_RUN(fn, TA, TB, ea, eb)                                                               \
	static int64_t Run_##fn(const BenchBatch* batch, int reps)                                               \
	{                                                                                                        \
		const TA* a = (const TA*)batch->packA;                                                               \
		const TB* b = (const TB*)batch->packB;                                                               \
		int64_t trueCount = 0;                                                                               \
		for (int r = 0; r < reps; ++r)                                                                       \
		{                                                                                                    \
			for (int i = 0; i < batch->count; ++i)                                                           \
			{                                                                                                \
				trueCount += fn(a[i], b[i]);                                                                 \
			}                                                                                                \
		}                                                                                                    \
		return trueCount;                                                                                    \
	}
OVERLAP3_LIST(DEFINE_OVERLAP_RUN)

#define DEFINE_POINT_IN_RUN(fn, T, e)                                                                        \
	static int64_t Run_##fn(const BenchBatch* batch, int reps)                                               \
	{                                                                                                        \
		const T* shapes = (const T*)batch->packA;                                                            \
		int64_t trueCount = 0;                                                                               \
		for (int r = 0; r < reps; ++r)                                                                       \
		{                                                                                                    \
			for (int i = 0; i < batch->count; ++i)                                                           \
			{                                                                                                \
				trueCount += fn(batch->point3[i], shapes[i]);                                                \
			}                                                                                                \
		}                                                                                                    \
		return trueCount;                                                                                    \
	}
POINT_IN3_LIST(DEFINE_POINT_IN_RUN)

/* "true" for a closest-point query: the point was inside, so the answer is the point itself. */
#define DEFINE_CLOSEST_RUN(fn, T, e)                                                                         \
	static int64_t Run_##fn(const BenchBatch* batch, int reps)                                               \
	{                                                                                                        \
		const T* shapes = (const T*)batch->packA;                                                            \
		int64_t trueCount = 0;                                                                               \
		for (int r = 0; r < reps; ++r)                                                                       \
		{                                                                                                    \
			for (int i = 0; i < batch->count; ++i)                                                           \
			{                                                                                                \
				trueCount += cd3VecEqual(fn(shapes[i], batch->point3[i]), batch->point3[i]);                 \
			}                                                                                                \
		}                                                                                                    \
		return trueCount;                                                                                    \
	}
CLOSEST3_LIST(DEFINE_CLOSEST_RUN)

#define DEFINE_CLOSEST_PAIR_RUN(fn, TA, TB, ea, eb)                                                          \
	static int64_t Run_##fn(const BenchBatch* batch, int reps)                                               \
	{                                                                                                        \
		const TA* a = (const TA*)batch->packA;                                                               \
		const TB* b = (const TB*)batch->packB;                                                               \
		int64_t trueCount = 0;                                                                               \
		for (int r = 0; r < reps; ++r)                                                                       \
		{                                                                                                    \
			for (int i = 0; i < batch->count; ++i)                                                           \
			{                                                                                                \
				trueCount += fn(a[i], b[i]).distance == CD_R(0.0);                                           \
			}                                                                                                \
		}                                                                                                    \
		return trueCount;                                                                                    \
	}
CLOSEST_PAIR3_LIST(DEFINE_CLOSEST_PAIR_RUN)

#define DEFINE_RAYCAST_RUN(fn, T, e)                                                                         \
	static int64_t Run_##fn(const BenchBatch* batch, int reps)                                               \
	{                                                                                                        \
		const T* shapes = (const T*)batch->packA;                                                            \
		int64_t trueCount = 0;                                                                               \
		cd3RayHit hit = {CD_R(0.0), {CD_R(0.0), CD_R(0.0), CD_R(0.0)}, {CD_R(0.0), CD_R(0.0), CD_R(0.0)}};   \
		for (int r = 0; r < reps; ++r)                                                                       \
		{                                                                                                    \
			for (int i = 0; i < batch->count; ++i)                                                           \
			{                                                                                                \
				trueCount += fn(shapes[i], batch->ray3[i], &hit);                                            \
			}                                                                                                \
		}                                                                                                    \
		return trueCount + (hit.fraction > CD_R(2.0));                                                       \
	}
RAYCAST3_LIST(DEFINE_RAYCAST_RUN)

static int64_t RunOverlapDispatch(const BenchBatch* batch, int reps)
{
	int64_t trueCount = 0;
	for (int r = 0; r < reps; ++r)
	{
		for (int i = 0; i < batch->count; ++i)
		{
			trueCount += cd3Overlap(batch->shapeA3 + i, batch->shapeB3 + i);
		}
	}
	return trueCount;
}

static int64_t RunPointInDispatch(const BenchBatch* batch, int reps)
{
	int64_t trueCount = 0;
	for (int r = 0; r < reps; ++r)
	{
		for (int i = 0; i < batch->count; ++i)
		{
			trueCount += cd3PointInShape(batch->shapeA3 + i, batch->point3[i]);
		}
	}
	return trueCount;
}

static int64_t RunClosestDispatch(const BenchBatch* batch, int reps)
{
	int64_t trueCount = 0;
	for (int r = 0; r < reps; ++r)
	{
		for (int i = 0; i < batch->count; ++i)
		{
			trueCount +=
				cd3VecEqual(cd3ClosestPointOnShape(batch->shapeA3 + i, batch->point3[i]), batch->point3[i]);
		}
	}
	return trueCount;
}

static int64_t RunRaycastDispatch(const BenchBatch* batch, int reps)
{
	int64_t trueCount = 0;
	cd3RayHit hit = {CD_R(0.0), {CD_R(0.0), CD_R(0.0), CD_R(0.0)}, {CD_R(0.0), CD_R(0.0), CD_R(0.0)}};
	for (int r = 0; r < reps; ++r)
	{
		for (int i = 0; i < batch->count; ++i)
		{
			trueCount += cd3Raycast(batch->shapeA3 + i, batch->ray3[i], &hit);
		}
	}
	return trueCount + (hit.fraction > CD_R(2.0));
}

static int64_t RunDistance(const BenchBatch* batch, int reps)
{
	int64_t trueCount = 0;
	for (int r = 0; r < reps; ++r)
	{
		for (int i = 0; i < batch->count; ++i)
		{
			trueCount += cd3Distance(batch->shapeA3 + i, batch->shapeB3 + i).distance == CD_R(0.0);
		}
	}
	return trueCount;
}

/* ---- the table ------------------------------------------------------------------------------ */

#define OVERLAP_CASE(fn, TA, TB, ea, eb)                                                                     \
	{"3D overlap", #fn, BENCH_IMPL_COLLIDE, BENCH_PAIR3, ea, eb, Run_##fn},
#define POINT_IN_CASE(fn, T, e)                                                                              \
	{"3D point containment", #fn, BENCH_IMPL_COLLIDE, BENCH_POINT3, e, 0, Run_##fn},
#define CLOSEST_CASE(fn, T, e) {"3D closest point", #fn, BENCH_IMPL_COLLIDE, BENCH_POINT3, e, 0, Run_##fn},
#define CLOSEST_PAIR_CASE(fn, TA, TB, ea, eb)                                                                \
	{"3D closest point", #fn, BENCH_IMPL_COLLIDE, BENCH_PAIR3, ea, eb, Run_##fn},
#define RAYCAST_CASE(fn, T, e) {"3D ray cast", #fn, BENCH_IMPL_COLLIDE, BENCH_RAY3, e, 0, Run_##fn},
#define DISTANCE_CASE(ea, na, eb, nb)                                                                        \
	{"3D distance (GJK)", "cd3Distance " #na "-" #nb, BENCH_IMPL_COLLIDE, BENCH_PAIR3, ea, eb, RunDistance},

const BenchCase g_bench3Cases[] = {
	OVERLAP3_LIST(OVERLAP_CASE) POINT_IN3_LIST(POINT_IN_CASE) CLOSEST3_LIST(CLOSEST_CASE)
		CLOSEST_PAIR3_LIST(CLOSEST_PAIR_CASE)
			RAYCAST3_LIST(RAYCAST_CASE){"3D dispatch (random shape types)", "cd3Overlap", BENCH_IMPL_COLLIDE,
										BENCH_MIXED_PAIR3, 0, 0, RunOverlapDispatch},
	{"3D dispatch (random shape types)", "cd3PointInShape", BENCH_IMPL_COLLIDE, BENCH_MIXED_POINT3, 0, 0,
	 RunPointInDispatch},
	{"3D dispatch (random shape types)", "cd3ClosestPointOnShape", BENCH_IMPL_COLLIDE, BENCH_MIXED_POINT3, 0,
	 0, RunClosestDispatch},
	{"3D dispatch (random shape types)", "cd3Raycast", BENCH_IMPL_COLLIDE, BENCH_MIXED_RAY3, 0, 0,
	 RunRaycastDispatch},
	{"3D dispatch (random shape types)", "cd3Distance", BENCH_IMPL_COLLIDE, BENCH_MIXED_PAIR3, 0, 0,
	 RunDistance},
	DISTANCE3_LIST(DISTANCE_CASE)};

const int g_bench3CaseCount = (int)(sizeof(g_bench3Cases) / sizeof(g_bench3Cases[0]));
