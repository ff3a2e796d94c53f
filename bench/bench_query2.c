/* collide_bench: the 2D rows: every overlap pair, point containment, closest points, ray casts,
 * the generic dispatchers, cd2Distance for every pair of shape types, and the polygon builders. */
#include "bench.h"

#define CIRCLE CD2_SHAPE_CIRCLE
#define CAPSULE CD2_SHAPE_CAPSULE
#define AABB CD2_SHAPE_AABB
#define BOX CD2_SHAPE_BOX
#define POLYGON CD2_SHAPE_POLYGON
#define SEGMENT CD2_SHAPE_SEGMENT

/* How a function takes a shape: by value, or (polygons) by const pointer. */
#define VAL(x) (x)
#define PTR(x) (&(x))

/* X(function, type of A, type of B, enum of A, enum of B, passing of A, passing of B) */
#define OVERLAP2_LIST(X)                                                                                     \
	X(cd2OverlapAabbAabb, cd2Aabb, cd2Aabb, AABB, AABB, VAL, VAL)                                            \
	X(cd2OverlapCircleCircle, cd2Circle, cd2Circle, CIRCLE, CIRCLE, VAL, VAL)                                \
	X(cd2OverlapPolygonPolygon, cd2Polygon, cd2Polygon, POLYGON, POLYGON, PTR, PTR)                          \
	X(cd2OverlapCircleCapsule, cd2Circle, cd2Capsule, CIRCLE, CAPSULE, VAL, VAL)                             \
	X(cd2OverlapCircleAabb, cd2Circle, cd2Aabb, CIRCLE, AABB, VAL, VAL)                                      \
	X(cd2OverlapCircleBox, cd2Circle, cd2Box, CIRCLE, BOX, VAL, VAL)                                         \
	X(cd2OverlapCirclePolygon, cd2Circle, cd2Polygon, CIRCLE, POLYGON, VAL, PTR)                             \
	X(cd2OverlapCircleSegment, cd2Circle, cd2Segment, CIRCLE, SEGMENT, VAL, VAL)                             \
	X(cd2OverlapCapsuleCapsule, cd2Capsule, cd2Capsule, CAPSULE, CAPSULE, VAL, VAL)                          \
	X(cd2OverlapCapsuleAabb, cd2Capsule, cd2Aabb, CAPSULE, AABB, VAL, VAL)                                   \
	X(cd2OverlapCapsuleBox, cd2Capsule, cd2Box, CAPSULE, BOX, VAL, VAL)                                      \
	X(cd2OverlapCapsulePolygon, cd2Capsule, cd2Polygon, CAPSULE, POLYGON, VAL, PTR)                          \
	X(cd2OverlapCapsuleSegment, cd2Capsule, cd2Segment, CAPSULE, SEGMENT, VAL, VAL)                          \
	X(cd2OverlapAabbBox, cd2Aabb, cd2Box, AABB, BOX, VAL, VAL)                                               \
	X(cd2OverlapAabbPolygon, cd2Aabb, cd2Polygon, AABB, POLYGON, VAL, PTR)                                   \
	X(cd2OverlapAabbSegment, cd2Aabb, cd2Segment, AABB, SEGMENT, VAL, VAL)                                   \
	X(cd2OverlapBoxBox, cd2Box, cd2Box, BOX, BOX, VAL, VAL)                                                  \
	X(cd2OverlapBoxPolygon, cd2Box, cd2Polygon, BOX, POLYGON, VAL, PTR)                                      \
	X(cd2OverlapBoxSegment, cd2Box, cd2Segment, BOX, SEGMENT, VAL, VAL)                                      \
	X(cd2OverlapPolygonSegment, cd2Polygon, cd2Segment, POLYGON, SEGMENT, PTR, VAL)                          \
	X(cd2OverlapSegmentSegment, cd2Segment, cd2Segment, SEGMENT, SEGMENT, VAL, VAL)

/* X(function, shape type, shape enum, passing): bool function(cd2Vec p, shape) */
#define POINT_IN2_LIST(X)                                                                                    \
	X(cd2PointInAabb, cd2Aabb, AABB, VAL)                                                                    \
	X(cd2PointInCircle, cd2Circle, CIRCLE, VAL)                                                              \
	X(cd2PointInCapsule, cd2Capsule, CAPSULE, VAL)                                                           \
	X(cd2PointInBox, cd2Box, BOX, VAL)                                                                       \
	X(cd2PointInPolygon, cd2Polygon, POLYGON, PTR)

/* X(function, shape type, shape enum, passing): cd2Vec function(shape, cd2Vec p) */
#define CLOSEST2_LIST(X)                                                                                     \
	X(cd2ClosestPointOnCircle, cd2Circle, CIRCLE, VAL)                                                       \
	X(cd2ClosestPointOnCapsule, cd2Capsule, CAPSULE, VAL)                                                    \
	X(cd2ClosestPointOnAabb, cd2Aabb, AABB, VAL)                                                             \
	X(cd2ClosestPointOnBox, cd2Box, BOX, VAL)                                                                \
	X(cd2ClosestPointOnPolygon, cd2Polygon, POLYGON, PTR)                                                    \
	X(cd2ClosestPointOnSegment, cd2Segment, SEGMENT, VAL)

/* X(function, shape type, shape enum, passing): bool function(shape, cd2Ray, cd2RayHit*) */
#define RAYCAST2_LIST(X)                                                                                     \
	X(cd2RaycastCircle, cd2Circle, CIRCLE, VAL)                                                              \
	X(cd2RaycastCapsule, cd2Capsule, CAPSULE, VAL)                                                           \
	X(cd2RaycastAabb, cd2Aabb, AABB, VAL)                                                                    \
	X(cd2RaycastBox, cd2Box, BOX, VAL)                                                                       \
	X(cd2RaycastPolygon, cd2Polygon, POLYGON, PTR)                                                           \
	X(cd2RaycastSegment, cd2Segment, SEGMENT, VAL)

/* X(enum of A, name of A, enum of B, name of B): every unordered pair of shape types. */
#define DISTANCE2_LIST(X)                                                                                    \
	X(CIRCLE, circle, CIRCLE, circle)                                                                        \
	X(CIRCLE, circle, CAPSULE, capsule)                                                                      \
	X(CIRCLE, circle, AABB, aabb)                                                                            \
	X(CIRCLE, circle, BOX, box)                                                                              \
	X(CIRCLE, circle, POLYGON, polygon)                                                                      \
	X(CIRCLE, circle, SEGMENT, segment)                                                                      \
	X(CAPSULE, capsule, CAPSULE, capsule)                                                                    \
	X(CAPSULE, capsule, AABB, aabb)                                                                          \
	X(CAPSULE, capsule, BOX, box)                                                                            \
	X(CAPSULE, capsule, POLYGON, polygon)                                                                    \
	X(CAPSULE, capsule, SEGMENT, segment)                                                                    \
	X(AABB, aabb, AABB, aabb)                                                                                \
	X(AABB, aabb, BOX, box)                                                                                  \
	X(AABB, aabb, POLYGON, polygon)                                                                          \
	X(AABB, aabb, SEGMENT, segment)                                                                          \
	X(BOX, box, BOX, box)                                                                                    \
	X(BOX, box, POLYGON, polygon)                                                                            \
	X(BOX, box, SEGMENT, segment)                                                                            \
	X(POLYGON, polygon, POLYGON, polygon)                                                                    \
	X(POLYGON, polygon, SEGMENT, segment)                                                                    \
	X(SEGMENT, segment, SEGMENT, segment)

/* ---- run functions -------------------------------------------------------------------------- */

#define DEFINE_OVERLAP_RUN(fn, TA, TB, ea, eb, passA, passB)                                                 \
	static int64_t Run_##fn(const BenchBatch* batch, int reps)                                               \
	{                                                                                                        \
		const TA* a = (const TA*)batch->packA;                                                               \
		const TB* b = (const TB*)batch->packB;                                                               \
		int64_t trueCount = 0;                                                                               \
		for (int r = 0; r < reps; ++r)                                                                       \
		{                                                                                                    \
			for (int i = 0; i < batch->count; ++i)                                                           \
			{                                                                                                \
				trueCount += fn(passA(a[i]), passB(b[i]));                                                   \
			}                                                                                                \
		}                                                                                                    \
		return trueCount;                                                                                    \
	}
OVERLAP2_LIST(DEFINE_OVERLAP_RUN)

#define DEFINE_POINT_IN_RUN(fn, T, e, pass)                                                                  \
	static int64_t Run_##fn(const BenchBatch* batch, int reps)                                               \
	{                                                                                                        \
		const T* shapes = (const T*)batch->packA;                                                            \
		int64_t trueCount = 0;                                                                               \
		for (int r = 0; r < reps; ++r)                                                                       \
		{                                                                                                    \
			for (int i = 0; i < batch->count; ++i)                                                           \
			{                                                                                                \
				trueCount += fn(batch->point2[i], pass(shapes[i]));                                          \
			}                                                                                                \
		}                                                                                                    \
		return trueCount;                                                                                    \
	}
POINT_IN2_LIST(DEFINE_POINT_IN_RUN)

/* "true" for a closest-point query: the point was inside, so the answer is the point itself. */
#define DEFINE_CLOSEST_RUN(fn, T, e, pass)                                                                   \
	static int64_t Run_##fn(const BenchBatch* batch, int reps)                                               \
	{                                                                                                        \
		const T* shapes = (const T*)batch->packA;                                                            \
		int64_t trueCount = 0;                                                                               \
		for (int r = 0; r < reps; ++r)                                                                       \
		{                                                                                                    \
			for (int i = 0; i < batch->count; ++i)                                                           \
			{                                                                                                \
				trueCount += cd2VecEqual(fn(pass(shapes[i]), batch->point2[i]), batch->point2[i]);           \
			}                                                                                                \
		}                                                                                                    \
		return trueCount;                                                                                    \
	}
CLOSEST2_LIST(DEFINE_CLOSEST_RUN)

static int64_t Run_cd2ClosestPointsSegmentSegment(const BenchBatch* batch, int reps)
{
	const cd2Segment* a = (const cd2Segment*)batch->packA;
	const cd2Segment* b = (const cd2Segment*)batch->packB;
	int64_t trueCount = 0;
	for (int r = 0; r < reps; ++r)
	{
		for (int i = 0; i < batch->count; ++i)
		{
			trueCount += cd2ClosestPointsSegmentSegment(a[i], b[i]).distance == CD_R(0.0);
		}
	}
	return trueCount;
}

#define DEFINE_RAYCAST_RUN(fn, T, e, pass)                                                                   \
	static int64_t Run_##fn(const BenchBatch* batch, int reps)                                               \
	{                                                                                                        \
		const T* shapes = (const T*)batch->packA;                                                            \
		int64_t trueCount = 0;                                                                               \
		cd2RayHit hit = {CD_R(0.0), {CD_R(0.0), CD_R(0.0)}, {CD_R(0.0), CD_R(0.0)}};                         \
		for (int r = 0; r < reps; ++r)                                                                       \
		{                                                                                                    \
			for (int i = 0; i < batch->count; ++i)                                                           \
			{                                                                                                \
				trueCount += fn(pass(shapes[i]), batch->ray2[i], &hit);                                      \
			}                                                                                                \
		}                                                                                                    \
		return trueCount + (hit.fraction > CD_R(2.0));                                                       \
	}
RAYCAST2_LIST(DEFINE_RAYCAST_RUN)

static int64_t RunOverlapDispatch(const BenchBatch* batch, int reps)
{
	int64_t trueCount = 0;
	for (int r = 0; r < reps; ++r)
	{
		for (int i = 0; i < batch->count; ++i)
		{
			trueCount += cd2Overlap(batch->shapeA2 + i, batch->shapeB2 + i);
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
			trueCount += cd2PointInShape(batch->shapeA2 + i, batch->point2[i]);
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
				cd2VecEqual(cd2ClosestPointOnShape(batch->shapeA2 + i, batch->point2[i]), batch->point2[i]);
		}
	}
	return trueCount;
}

static int64_t RunRaycastDispatch(const BenchBatch* batch, int reps)
{
	int64_t trueCount = 0;
	cd2RayHit hit = {CD_R(0.0), {CD_R(0.0), CD_R(0.0)}, {CD_R(0.0), CD_R(0.0)}};
	for (int r = 0; r < reps; ++r)
	{
		for (int i = 0; i < batch->count; ++i)
		{
			trueCount += cd2Raycast(batch->shapeA2 + i, batch->ray2[i], &hit);
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
			trueCount += cd2Distance(batch->shapeA2 + i, batch->shapeB2 + i).distance == CD_R(0.0);
		}
	}
	return trueCount;
}

static int64_t RunMakePolygon(const BenchBatch* batch, int reps)
{
	int64_t trueCount = 0;
	cd2Polygon polygon;
	polygon.count = 0;
	for (int r = 0; r < reps; ++r)
	{
		for (int i = 0; i < batch->count; ++i)
		{
			const cd2Vec* points = batch->cloud + (size_t)i * CD2_MAX_POLYGON_VERTICES;
			trueCount += cd2MakePolygon(points, batch->cloudCount[i], &polygon) == CD_OK;
		}
	}
	return trueCount + (polygon.count > CD2_MAX_POLYGON_VERTICES);
}

static int64_t RunMakeBoxPolygon(const BenchBatch* batch, int reps)
{
	int64_t trueCount = 0;
	cd2Polygon polygon;
	polygon.count = 0;
	for (int r = 0; r < reps; ++r)
	{
		for (int i = 0; i < batch->count; ++i)
		{
			trueCount += cd2MakeBoxPolygon(batch->box2[i], &polygon) == CD_OK;
		}
	}
	return trueCount + (polygon.count > CD2_MAX_POLYGON_VERTICES);
}

/* ---- the table ------------------------------------------------------------------------------ */

#define OVERLAP_CASE(fn, TA, TB, ea, eb, passA, passB)                                                       \
	{"2D overlap", #fn, BENCH_IMPL_COLLIDE, BENCH_PAIR2, ea, eb, Run_##fn},
#define POINT_IN_CASE(fn, T, e, pass)                                                                        \
	{"2D point containment", #fn, BENCH_IMPL_COLLIDE, BENCH_POINT2, e, 0, Run_##fn},
#define CLOSEST_CASE(fn, T, e, pass)                                                                         \
	{"2D closest point", #fn, BENCH_IMPL_COLLIDE, BENCH_POINT2, e, 0, Run_##fn},
#define RAYCAST_CASE(fn, T, e, pass) {"2D ray cast", #fn, BENCH_IMPL_COLLIDE, BENCH_RAY2, e, 0, Run_##fn},
#define DISTANCE_CASE(ea, na, eb, nb)                                                                        \
	{"2D distance (GJK)", "cd2Distance " #na "-" #nb, BENCH_IMPL_COLLIDE, BENCH_PAIR2, ea, eb, RunDistance},

const BenchCase g_bench2Cases[] = {
	OVERLAP2_LIST(OVERLAP_CASE) POINT_IN2_LIST(POINT_IN_CASE)
		CLOSEST2_LIST(CLOSEST_CASE){"2D closest point", "cd2ClosestPointsSegmentSegment", BENCH_IMPL_COLLIDE,
									BENCH_PAIR2, SEGMENT, SEGMENT, Run_cd2ClosestPointsSegmentSegment},
	RAYCAST2_LIST(RAYCAST_CASE){"2D dispatch (random shape types)", "cd2Overlap", BENCH_IMPL_COLLIDE,
								BENCH_MIXED_PAIR2, 0, 0, RunOverlapDispatch},
	{"2D dispatch (random shape types)", "cd2PointInShape", BENCH_IMPL_COLLIDE, BENCH_MIXED_POINT2, 0, 0,
	 RunPointInDispatch},
	{"2D dispatch (random shape types)", "cd2ClosestPointOnShape", BENCH_IMPL_COLLIDE, BENCH_MIXED_POINT2, 0,
	 0, RunClosestDispatch},
	{"2D dispatch (random shape types)", "cd2Raycast", BENCH_IMPL_COLLIDE, BENCH_MIXED_RAY2, 0, 0,
	 RunRaycastDispatch},
	{"2D dispatch (random shape types)", "cd2Distance", BENCH_IMPL_COLLIDE, BENCH_MIXED_PAIR2, 0, 0,
	 RunDistance},
	DISTANCE2_LIST(DISTANCE_CASE){"2D polygon builders", "cd2MakePolygon", BENCH_IMPL_COLLIDE,
								  BENCH_POINT_CLOUD2, 0, 0, RunMakePolygon},
	{"2D polygon builders", "cd2MakeBoxPolygon", BENCH_IMPL_COLLIDE, BENCH_BOX2, 0, 0, RunMakeBoxPolygon},
};

const int g_bench2CaseCount = (int)(sizeof(g_bench2Cases) / sizeof(g_bench2Cases[0]));
