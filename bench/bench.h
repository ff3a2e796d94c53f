/* collide_bench: the harness shared by the benchmark files.
 *
 * A benchmark case is one row of the table: a function under test, the kind of input it takes
 * and a run function that calls it over a pre-generated batch. Peers (other libraries doing the
 * same job) register cases with the same row name and their own `impl`; the table then shows
 * them as extra columns next to collide's figure, measured on the very same inputs. */
#ifndef COLLIDE_BENCH_H
#define COLLIDE_BENCH_H

#include "collide/query2.h"
#include "collide/query3.h"

#include <stdint.h>

/* Inputs per batch: large enough that branch predictors cannot learn the answers, small enough
 * that a batch of the largest shape (a 2D polygon) stays within the L2/L3 caches. */
#define BENCH_BATCH_MAX 4096

/* What a case's inputs are. A, B: shapes of the case's typeA/typeB (MIXED: a random type per
 * input); POINT: a query point; RAY: a ray; POINT_CLOUD2: point sets for the polygon builder. */
typedef enum BenchInput
{
	BENCH_PAIR3,
	BENCH_POINT3,
	BENCH_RAY3,
	BENCH_MIXED_PAIR3,
	BENCH_MIXED_POINT3,
	BENCH_MIXED_RAY3,
	BENCH_PAIR2,
	BENCH_POINT2,
	BENCH_RAY2,
	BENCH_MIXED_PAIR2,
	BENCH_MIXED_POINT2,
	BENCH_MIXED_RAY2,
	BENCH_POINT_CLOUD2,
	BENCH_BOX2
} BenchInput;

/* One batch of inputs. The tagged shapes serve the generic dispatchers; packA/packB hold the
 * same shapes as compact arrays of the active member (cd3Sphere[], cd2Polygon[], ...), so that
 * the pair functions read contiguous data of their own size as a real caller would. */
typedef struct BenchBatch
{
	int count;
	cd3Shape* shapeA3;
	cd3Shape* shapeB3;
	cd3Vec* point3;
	cd3Ray* ray3;
	cd2Shape* shapeA2;
	cd2Shape* shapeB2;
	cd2Vec* point2;
	cd2Ray* ray2;
	cd2Vec* cloud; /* count * CD2_MAX_POLYGON_VERTICES points */
	int* cloudCount;
	cd2Box* box2;
	void* packA;
	void* packB;
} BenchBatch;

/* Calls the function under test `reps` times over the batch and returns how many calls
 * answered "true" (overlap, hit, point inside, zero distance, builder success). Using every
 * answer keeps the compiler from dropping the calls. */
typedef int64_t BenchRunFcn(const BenchBatch* batch, int reps);

typedef struct BenchCase
{
	const char* group; /* table section, e.g. "3D overlap" */
	const char* name;  /* row: the function (and shape pair for dispatchers) */
	const char* impl;  /* "collide", or the peer library measured in this row's extra column */
	BenchInput input;
	int typeA, typeB; /* cd3ShapeType / cd2ShapeType of the inputs, where the input has them */
	BenchRunFcn* run;
} BenchCase;

#define BENCH_IMPL_COLLIDE "collide"

/* The case tables, in table order. */
extern const BenchCase g_bench3Cases[];
extern const int g_bench3CaseCount;
extern const BenchCase g_bench2Cases[];
extern const int g_bench2CaseCount;

/* Fills the batch with `count` inputs for the case. `spread` scales how far the second input
 * lies from the first one (larger spread: fewer overlaps and hits); the harness searches it so
 * that about half the answers are true. The same seed gives the same inputs. */
void BenchGenerate(BenchBatch* batch, const BenchCase* benchCase, int count, double spread, uint64_t seed);

BenchBatch* BenchCreateBatch(void);
void BenchDestroyBatch(BenchBatch* batch);

#endif
