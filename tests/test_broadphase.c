/* Broadphase tests: every structure that can be created, in 2D and 3D, against brute force
 * (tests/broad_oracle.h) over random operation sequences and degenerate sets. */
#include "broad_oracle.h"
#include "test.h"

#include "collide/broad.h"

/* Internal functions of src/broad/broad_internal.h (enlarge mode and the split pair search that the
 * 2D world uses; that header needs the library's own include path). */
void cd2BroadPhase_SetEnlargeMoves(cd2BroadPhase* broadPhase, bool flag);
int cd2BroadPhase_BeginMovedPairs(cd2BroadPhase* broadPhase);
void cd2BroadPhase_QueryMovedPairs(const cd2BroadPhase* broadPhase, int start, int end, cdBroadPairFcn* fcn,
								   void* context);
void cd2BroadPhase_EndMovedPairs(cd2BroadPhase* broadPhase, bool forgetMoves);
int cd2BroadPhase_BeginRebuild(cd2BroadPhase* broadPhase);
void cd2BroadPhase_RebuildJobs(cd2BroadPhase* broadPhase, int start, int end);
void cd2BroadPhase_EndRebuild(cd2BroadPhase* broadPhase);

#include <limits.h>

static int s_typesTested[2][CD_BROADPHASE_TYPE_COUNT];

/* Runs one oracle step; on a mismatch prints the reason with the context and returns false. */
#define ORACLE_CHECK(o, call, what)                                                                          \
	do                                                                                                       \
	{                                                                                                        \
		bool okCall_ = (call);                                                                               \
		TEST_CHECKF(okCall_, "%s %dD %s: %s", cdGetBroadPhaseTypeName((o)->type), (o)->dim, (o)->error,      \
					what);                                                                                   \
		if (!okCall_)                                                                                        \
		{                                                                                                    \
			return false;                                                                                    \
		}                                                                                                    \
	} while (0)

static cdReal R(TestRng* rng, double lo, double hi)
{
	return (cdReal)TestRngRange(rng, lo, hi);
}

/* A random box in [lo, hi]^dim with sizes up to maxSize (sometimes zero). */
static OBox RandomBox(TestRng* rng, int dim, double lo, double hi, double maxSize)
{
	OBox b;
	memset(&b, 0, sizeof(b));
	bool point = TestRngInt(rng, 10) == 0;
	for (int i = 0; i < dim; ++i)
	{
		b.min[i] = R(rng, lo, hi);
		b.max[i] = point ? b.min[i] : (cdReal)(b.min[i] + TestRngRange(rng, 0.0, maxSize));
	}
	return b;
}

static OBox Shift(OBox b, int dim, const cdReal* d)
{
	for (int i = 0; i < dim; ++i)
	{
		b.min[i] += d[i];
		b.max[i] += d[i];
	}
	return b;
}

typedef struct Scene
{
	double lo, hi, maxSize, smallMove;
} Scene;

/* Random rays: long, short, axis-aligned, zero translation. */
static void RandomRay(TestRng* rng, int dim, const Scene* s, cdReal* origin, cdReal* translation)
{
	int kind = TestRngInt(rng, 6);
	double span = s->hi - s->lo;
	for (int i = 0; i < 3; ++i)
	{
		origin[i] = i < dim ? R(rng, s->lo - 0.1 * span, s->hi + 0.1 * span) : CD_R(0.0);
		translation[i] = i < dim ? R(rng, -span, span) : CD_R(0.0);
		if (kind == 1)
		{
			translation[i] = (cdReal)(translation[i] * 0.05);
		}
	}
	if (kind == 2)
	{
		int keep = TestRngInt(rng, dim);
		for (int i = 0; i < dim; ++i)
		{
			translation[i] = i == keep ? translation[i] : CD_R(0.0);
		}
	}
	if (kind == 3)
	{
		translation[0] = translation[1] = translation[2] = CD_R(0.0);
	}
}

/* Checks every answer of the broadphase against brute force. */
static bool CheckAll(Oracle* o, TestRng* rng, const Scene* s, bool updatePairs)
{
	ORACLE_CHECK(o, OracleValidate(o), "validate");
	ORACLE_CHECK(o, OracleFindAllPairs(o), "find all pairs");
	if (updatePairs)
	{
		ORACLE_CHECK(o, OracleUpdatePairs(o), "update pairs");
		ORACLE_CHECK(o, OracleUpdatePairs(o), "second update pairs (nothing moved)");
	}
	for (int q = 0; q < 6; ++q)
	{
		OBox box = RandomBox(rng, o->dim, s->lo, s->hi, 0.3 * (s->hi - s->lo));
		ORACLE_CHECK(o, OracleQueryBox(o, box, q == 5 ? 1 + TestRngInt(rng, 3) : 0), "query");
	}
	for (int r = 0; r < 8; ++r)
	{
		cdReal origin[3], translation[3];
		RandomRay(rng, o->dim, s, origin, translation);
		ORACLE_CHECK(o, OracleRayCast(o, origin, translation, r == 7), "ray");
	}
	return true;
}

/* Random inserts, small moves, teleports, removals, re-inserts and rebuilds; checks everything
 * after each batch and validates after every operation. */
static bool RunRandom(int dim, cdBroadPhaseType type, uint64_t seed, const Scene* s, int maxProxies,
					  int batches)
{
	Oracle* o = (Oracle*)malloc(sizeof(Oracle));
	TestRng rng = TestRngMake(seed);
	cdReal margin = TestRngInt(&rng, 3) == 0 ? CD_R(0.0) : (cdReal)(0.02 * s->maxSize + 0.01);
	if (!OracleInit(o, dim, type, margin, CD_R(4.0)))
	{
		free(o);
		return true; /* not available yet */
	}
	s_typesTested[dim - 2][type] = 1;
	int ids[ORACLE_MAX_PROXIES];
	OBox tight[ORACLE_MAX_PROXIES];
	int live = 0;
	bool ok = true;
	for (int batch = 0; batch < batches && ok; ++batch)
	{
		int ops = 1 + TestRngInt(&rng, 40);
		for (int op = 0; op < ops && ok; ++op)
		{
			int kind = TestRngInt(&rng, 10);
			if (live == 0 || (kind < 3 && live < maxProxies))
			{
				OBox b = RandomBox(&rng, dim, s->lo, s->hi, s->maxSize);
				int id;
				ok = OracleCreate(o, b, TestRngNext(&rng), &id);
				if (ok && id >= 0)
				{
					ids[live] = id;
					tight[id] = b;
					++live;
				}
			}
			else if (kind < 6)
			{
				int id = ids[TestRngInt(&rng, live)];
				cdReal d[3] = {CD_R(0.0), CD_R(0.0), CD_R(0.0)};
				for (int i = 0; i < dim; ++i)
				{
					d[i] = R(&rng, -s->smallMove, s->smallMove);
				}
				OBox b = Shift(tight[id], dim, d);
				ok = OracleMove(o, id, b, d);
				tight[id] = b;
			}
			else if (kind < 7)
			{
				/* A few moves at once through MoveProxies (ids may repeat). */
				enum
				{
					MOST = 24
				};
				int batchIds[MOST];
				OBox boxes[MOST];
				cdReal d[MOST][3];
				int count = 1 + TestRngInt(&rng, MOST);
				for (int k = 0; k < count; ++k)
				{
					int id = ids[TestRngInt(&rng, live)];
					for (int i = 0; i < 3; ++i)
					{
						d[k][i] = i < dim ? R(&rng, -s->smallMove, s->smallMove) : CD_R(0.0);
					}
					boxes[k] = TestRngInt(&rng, 6) == 0 ? RandomBox(&rng, dim, s->lo, s->hi, s->maxSize)
														: Shift(tight[id], dim, d[k]);
					batchIds[k] = id;
					tight[id] = boxes[k];
				}
				ok = OracleMoveMany(o, count, batchIds, boxes, (const cdReal(*)[3])d);
			}
			else if (kind < 8)
			{
				/* Teleport, with a random displacement prediction. */
				int id = ids[TestRngInt(&rng, live)];
				OBox b = RandomBox(&rng, dim, s->lo, s->hi, s->maxSize);
				cdReal d[3] = {CD_R(0.0), CD_R(0.0), CD_R(0.0)};
				for (int i = 0; i < dim; ++i)
				{
					d[i] = TestRngInt(&rng, 2) ? R(&rng, -s->smallMove, s->smallMove) : CD_R(0.0);
				}
				ok = OracleMove(o, id, b, d);
				tight[id] = b;
			}
			else if (kind < 9 || TestRngInt(&rng, 8) != 0)
			{
				int k = TestRngInt(&rng, live);
				ok = OracleDestroy(o, ids[k]);
				ids[k] = ids[--live];
			}
			else
			{
				ok = OracleRebuild(o);
			}
			if (ok)
			{
				ok = OracleValidate(o);
			}
			TEST_CHECKF(ok, "%s %dD seed %llu batch %d op %d: %s", cdGetBroadPhaseTypeName(type), dim,
						(unsigned long long)seed, batch, op, o->error);
		}
		if (ok)
		{
			ok = CheckAll(o, &rng, s, TestRngInt(&rng, 4) != 0);
		}
	}
	OracleFree(o);
	free(o);
	return ok;
}

static const Scene kScenes[] = {
	{0.0, 100.0, 6.0, 0.5}, /* sparse-ish, small boxes */
	{0.0, 20.0, 6.0, 1.0},	/* dense: many pairs */
	{-1.0, 1.0, 0.0, 0.01}, /* points only (zero-size boxes) */
};

static void TestRandomOperations(void)
{
	for (int dim = 2; dim <= 3; ++dim)
	{
		for (int type = 0; type < CD_BROADPHASE_TYPE_COUNT; ++type)
		{
			for (int sc = 0; sc < (int)(sizeof(kScenes) / sizeof(kScenes[0])); ++sc)
			{
				uint64_t seed = 0xB40AD000u + (uint64_t)(100 * dim + 10 * type + sc);
				RunRandom(dim, (cdBroadPhaseType)type, seed, &kScenes[sc], 200, 25);
			}
		}
	}
	for (int type = 0; type < CD_BROADPHASE_TYPE_COUNT; ++type)
	{
		printf("%s: %s\n", cdGetBroadPhaseTypeName((cdBroadPhaseType)type),
			   s_typesTested[0][type] && s_typesTested[1][type] ? "tested in 2D and 3D" : "not available");
	}
	TEST_CHECK(s_typesTested[0][CD_BROADPHASE_TREE] && s_typesTested[1][CD_BROADPHASE_TREE]);
	TEST_CHECK(s_typesTested[0][CD_BROADPHASE_SAP] && s_typesTested[1][CD_BROADPHASE_SAP]);
}

/* Bulk creation then checks; also a bulk load followed by churn. */
static bool RunBulk(int dim, cdBroadPhaseType type, const OBox* boxes, int count, const Scene* s,
					uint64_t seed)
{
	Oracle* o = (Oracle*)malloc(sizeof(Oracle));
	TestRng rng = TestRngMake(seed);
	if (!OracleInit(o, dim, type, CD_R(0.05), CD_R(4.0)))
	{
		free(o);
		return true;
	}
	bool ok = true;
	if (TestRngInt(&rng, 2) == 0)
	{
		for (int i = 0; i < count && ok; ++i)
		{
			int id;
			ok = OracleCreate(o, boxes[i], (uint64_t)i * 7u, &id);
			TEST_CHECKF(ok, "%s %dD create %d: %s", cdGetBroadPhaseTypeName(type), dim, i, o->error);
		}
	}
	else
	{
		/* Through the bulk entry point; the oracle mirrors it. */
		cd2Aabb* b2 = (cd2Aabb*)malloc((size_t)count * sizeof(cd2Aabb));
		cd3Aabb* b3 = (cd3Aabb*)malloc((size_t)count * sizeof(cd3Aabb));
		uint64_t* data = (uint64_t*)malloc((size_t)count * sizeof(uint64_t));
		int* ids = (int*)malloc((size_t)count * sizeof(int));
		for (int i = 0; i < count; ++i)
		{
			b2[i] = OracleTo2(boxes[i]);
			b3[i] = OracleTo3(boxes[i]);
			data[i] = (uint64_t)i * 7u;
		}
		int created = dim == 2 ? cd2BroadPhase_CreateProxies(o->bp2, b2, data, count, ids)
							   : cd3BroadPhase_CreateProxies(o->bp3, b3, data, count, ids);
		int valid = 0;
		cdReal zero[3] = {CD_R(0.0), CD_R(0.0), CD_R(0.0)};
		for (int i = 0; i < count; ++i)
		{
			if (!OracleBoxValid(o, boxes[i]))
			{
				TEST_CHECK(ids[i] == CD_NULL_PROXY);
				continue;
			}
			++valid;
			int id = ids[i];
			TEST_CHECKF(id >= 0 && id < ORACLE_MAX_PROXIES && !o->alive[id], "bulk id %d", id);
			if (id >= 0 && id < ORACLE_MAX_PROXIES)
			{
				o->alive[id] = true;
				o->moved[id] = true;
				o->fat[id] = OracleFat(o, boxes[i], zero, CD_R(1.0));
				o->userData[id] = data[i];
				o->idCapacity = id + 1 > o->idCapacity ? id + 1 : o->idCapacity;
			}
		}
		TEST_CHECK(created == valid);
		free(b2);
		free(b3);
		free(data);
		free(ids);
	}
	if (ok)
	{
		ok = CheckAll(o, &rng, s, true);
	}
	if (ok)
	{
		OracleRebuild(o);
		ok = CheckAll(o, &rng, s, true);
	}
	cdBroadPhaseStats stats = OracleStats(o);
	int live = 0;
	for (int id = 0; id < o->idCapacity; ++id)
	{
		live += o->alive[id] ? 1 : 0;
	}
	TEST_CHECK(stats.proxyCount == live);
	TEST_CHECK(stats.memoryBytes > 0);
	if (type == CD_BROADPHASE_TREE && live > 1)
	{
		/* n leaves hang under n - 1 internal nodes; a SAH build of any set stays shallow. */
		int logN = 0;
		while ((1 << logN) < live)
		{
			++logN;
		}
		TEST_CHECKF(stats.nodeCount == live - 1, "nodes %d for %d proxies", stats.nodeCount, live);
		TEST_CHECKF(stats.height >= logN && stats.height <= 3 * logN + 2, "height %d for %d proxies",
					stats.height, live);
		TEST_CHECKF(stats.sahCost >= 1.0 || stats.sahCost == 0.0, "sah %g", stats.sahCost);
	}
	OracleFree(o);
	free(o);
	return ok;
}

static void TestDegenerateSets(void)
{
	enum
	{
		N = 300
	};
	static OBox boxes[N];
	Scene s = {0.0, 10.0, 1.0, 0.1};
	for (int dim = 2; dim <= 3; ++dim)
	{
		for (int type = 0; type < CD_BROADPHASE_TYPE_COUNT; ++type)
		{
			cdBroadPhaseType t = (cdBroadPhaseType)type;
			/* All identical. */
			for (int i = 0; i < N; ++i)
			{
				OBox b = {{CD_R(1.0), CD_R(2.0), CD_R(3.0)}, {CD_R(1.5), CD_R(2.5), CD_R(3.5)}};
				boxes[i] = b;
			}
			RunBulk(dim, t, boxes, N / 3, &s, 11);
			/* All on a line, in order (the worst insertion order for a naive tree). */
			for (int i = 0; i < N; ++i)
			{
				OBox b = {{(cdReal)(0.03 * i), CD_R(1.0), CD_R(1.0)},
						  {(cdReal)(0.03 * i + 0.05), CD_R(1.0), CD_R(1.0)}};
				boxes[i] = b;
			}
			RunBulk(dim, t, boxes, N, &s, 12);
			/* Zero-size boxes, many coincident. */
			TestRng rng = TestRngMake(13);
			for (int i = 0; i < N; ++i)
			{
				OBox b;
				memset(&b, 0, sizeof(b));
				for (int k = 0; k < dim; ++k)
				{
					b.min[k] = b.max[k] = (cdReal)TestRngInt(&rng, 5);
				}
				boxes[i] = b;
			}
			RunBulk(dim, t, boxes, N, &s, 14);
			/* Huge coordinates, 1e6..1e9, sizes to match. */
			Scene huge = {1e6, 1e9, 1e7, 1e5};
			for (int i = 0; i < N; ++i)
			{
				boxes[i] = RandomBox(&rng, dim, huge.lo, huge.hi, huge.maxSize);
			}
			RunBulk(dim, t, boxes, N, &huge, 15);
			RunRandom(dim, t, 16, &huge, 120, 12);
			/* Invalid boxes mixed in: rejected with CD_NULL_PROXY by both entry points. */
			for (int i = 0; i < 40; ++i)
			{
				boxes[i] = RandomBox(&rng, dim, 0.0, 10.0, 1.0);
				int k = TestRngInt(&rng, dim);
				switch (i % 5)
				{
					case 0:
						boxes[i].min[k] = NAN;
						break;
					case 1:
						boxes[i].max[k] = INFINITY;
						break;
					case 2:
						boxes[i].min[k] = -INFINITY;
						break;
					case 3:
						boxes[i].min[k] = boxes[i].max[k] + CD_R(1.0);
						break;
					default:
						break;
				}
			}
			RunBulk(dim, t, boxes, 40, &s, 17);
			RunBulk(dim, t, boxes, 40, &s, 18);
		}
	}
}

/* Bad arguments: definitions, invalid moves, types not built yet. */
static void TestArguments(void)
{
	cd3BroadPhaseDef def = cd3DefaultBroadPhaseDef();
	cd3BroadPhase* bp = NULL;
	TEST_CHECK(def.type == CD_BROADPHASE_TREE && def.margin > CD_R(0.0) &&
			   def.displacementMultiplier == CD_R(4.0));
	def.margin = -CD_R(1.0);
	TEST_CHECK(cd3CreateBroadPhase(&def, &bp) == CD_ERROR_INVALID_ARGUMENT);
	def = cd3DefaultBroadPhaseDef();
	def.margin = NAN;
	TEST_CHECK(cd3CreateBroadPhase(&def, &bp) == CD_ERROR_INVALID_ARGUMENT);
	def = cd3DefaultBroadPhaseDef();
	def.type = CD_BROADPHASE_TYPE_COUNT;
	TEST_CHECK(cd3CreateBroadPhase(&def, &bp) == CD_ERROR_INVALID_ARGUMENT);
	TEST_CHECK(cd3CreateBroadPhase(NULL, &bp) == CD_ERROR_INVALID_ARGUMENT);
	TEST_CHECK(strcmp(cdGetBroadPhaseTypeName(CD_BROADPHASE_SAP), "sap") == 0);
	TEST_CHECK(strcmp(cdGetBroadPhaseTypeName(CD_BROADPHASE_TYPE_COUNT), "unknown") == 0);

	for (int type = 0; type < CD_BROADPHASE_TYPE_COUNT; ++type)
	{
		def = cd3DefaultBroadPhaseDef();
		def.type = (cdBroadPhaseType)type;
		def.capacity = 10;
		def.margin = CD_R(0.0); /* fat box = tight box, so touching is exact */
		cdResult result = cd3CreateBroadPhase(&def, &bp);
		TEST_CHECK(result == CD_OK || (result == CD_ERROR_INVALID_ARGUMENT && type >= CD_BROADPHASE_GRID));
		if (result != CD_OK)
		{
			continue;
		}
		cd3Aabb box = {{CD_R(0.0), CD_R(0.0), CD_R(0.0)}, {CD_R(1.0), CD_R(1.0), CD_R(1.0)}};
		int id = cd3BroadPhase_CreateProxy(bp, box, 42);
		TEST_CHECK(id == 0);
		cd3Aabb fat = cd3BroadPhase_GetFatAabb(bp, id);
		cd3Aabb bad = box;
		bad.max.y = NAN;
		TEST_CHECK(!cd3BroadPhase_MoveProxy(bp, id, bad, CD3_VEC_ZERO));
		cd3Vec nanDisplacement = {NAN, CD_R(0.0), CD_R(0.0)};
		cd3Aabb far = {{CD_R(50.0), CD_R(0.0), CD_R(0.0)}, {CD_R(51.0), CD_R(1.0), CD_R(1.0)}};
		TEST_CHECK(!cd3BroadPhase_MoveProxy(bp, id, far, nanDisplacement));
		TEST_CHECK(cd3BroadPhase_GetFatAabb(bp, id).max.x == fat.max.x);
		TEST_CHECK(cd3BroadPhase_UpdatePairs(bp, NULL, NULL) == 0);
		int other = cd3BroadPhase_CreateProxy(bp, box, 43);
		TEST_CHECK(other == 1);
		TEST_CHECK(cd3BroadPhase_UpdatePairs(bp, NULL, NULL) == 1);
		TEST_CHECK(cd3BroadPhase_UpdatePairs(bp, NULL, NULL) == 0);
		TEST_CHECK(cd3BroadPhase_FindAllPairs(bp, NULL, NULL) == 1);
		/* Touching boxes overlap (closed sets). */
		cd3Aabb touching = {{CD_R(1.0), CD_R(0.0), CD_R(0.0)}, {CD_R(3.0), CD_R(1.0), CD_R(1.0)}};
		int third = cd3BroadPhase_CreateProxy(bp, touching, 44);
		TEST_CHECK(cd3BroadPhase_UpdatePairs(bp, NULL, NULL) == 2);
		cd3BroadPhase_DestroyProxy(bp, other);
		TEST_CHECK(cd3BroadPhase_CreateProxy(bp, box, 45) == other); /* ids are reused */
		TEST_CHECK(cd3BroadPhase_GetUserData(bp, third) == 44);
		TEST_CHECK(cd3BroadPhase_Validate(bp));
		cd3DestroyBroadPhase(bp);
	}
}

/* A larger scene, moved frame by frame like a simulation, with a rebuild in the middle. */
static void TestFrames(void)
{
	for (int dim = 2; dim <= 3; ++dim)
	{
		for (int type = 0; type < CD_BROADPHASE_TYPE_COUNT; ++type)
		{
			Oracle* o = (Oracle*)malloc(sizeof(Oracle));
			if (!OracleInit(o, dim, (cdBroadPhaseType)type, CD_R(0.1), CD_R(4.0)))
			{
				free(o);
				continue;
			}
			TestRng rng = TestRngMake(77 + (uint64_t)(dim * 10 + type));
			Scene s = {0.0, 60.0, 2.0, 0.2};
			enum
			{
				COUNT = 1000
			};
			static OBox tight[COUNT];
			static cdReal velocity[COUNT][3];
			bool ok = true;
			for (int i = 0; i < COUNT && ok; ++i)
			{
				tight[i] = RandomBox(&rng, dim, s.lo, s.hi, s.maxSize);
				for (int k = 0; k < 3; ++k)
				{
					velocity[i][k] = k < dim ? R(&rng, -0.2, 0.2) : CD_R(0.0);
				}
				int id;
				ok = OracleCreate(o, tight[i], (uint64_t)i, &id);
				ok = ok && id == i;
			}
			for (int frame = 0; frame < 12 && ok; ++frame)
			{
				for (int i = 0; i < COUNT && ok; ++i)
				{
					tight[i] = Shift(tight[i], dim, velocity[i]);
					ok = OracleMove(o, i, tight[i], velocity[i]);
				}
				if (frame == 6)
				{
					OracleRebuild(o);
				}
				ok = ok && OracleValidate(o) && OracleUpdatePairs(o);
				TEST_CHECKF(ok, "%s %dD frame %d: %s", cdGetBroadPhaseTypeName((cdBroadPhaseType)type), dim,
							frame, o->error);
			}
			if (ok)
			{
				ok = CheckAll(o, &rng, &s, true);
			}
			OracleFree(o);
			free(o);
		}
	}
}

/* Creates `count` random boxes of scene s one by one (proxy i for box i); false on any failure. */
static bool CreateRandomBoxes(Oracle* o, TestRng* rng, int dim, const Scene* s, OBox* tight, int count)
{
	bool ok = true;
	for (int i = 0; i < count && ok; ++i)
	{
		tight[i] = RandomBox(rng, dim, s->lo, s->hi, s->maxSize);
		int id;
		ok = OracleCreate(o, tight[i], (uint64_t)i, &id) && id == i;
	}
	return ok;
}

/* More proxies created one by one than the tree's self-rebuild threshold (1024), then frames in
 * which a tenth of them teleport (sweep-and-prune: tombstone + tail merge instead of long shifts;
 * tree: reinsertion from the root). The tree, mostly built by single insertions, must come out
 * of the first pair update rebuilt: exactly the tree an explicit rebuild gives (same SAH cost). */
static void TestTeleportFrames(void)
{
	for (int dim = 2; dim <= 3; ++dim)
	{
		for (int type = 0; type < CD_BROADPHASE_TYPE_COUNT; ++type)
		{
			Oracle* o = (Oracle*)malloc(sizeof(Oracle));
			if (!OracleInit(o, dim, (cdBroadPhaseType)type, CD_R(0.1), CD_R(4.0)))
			{
				free(o);
				continue;
			}
			TestRng rng = TestRngMake(991 + (uint64_t)(dim * 10 + type));
			Scene s = {0.0, 80.0, 2.0, 0.2};
			enum
			{
				COUNT = 1100
			};
			static OBox tight[COUNT];
			bool ok = CreateRandomBoxes(o, &rng, dim, &s, tight, COUNT);
			ok = ok && OracleUpdatePairs(o) && OracleValidate(o);
			TEST_CHECKF(ok, "%s %dD first pairs: %s", cdGetBroadPhaseTypeName((cdBroadPhaseType)type), dim,
						o->error);
			if (ok && type == CD_BROADPHASE_TREE)
			{
				cdBroadPhaseStats before =
					dim == 2 ? cd2BroadPhase_GetStats(o->bp2) : cd3BroadPhase_GetStats(o->bp3);
				OracleRebuild(o);
				cdBroadPhaseStats after =
					dim == 2 ? cd2BroadPhase_GetStats(o->bp2) : cd3BroadPhase_GetStats(o->bp3);
				TEST_CHECKF(before.sahCost == after.sahCost && before.height == after.height,
							"tree %dD not rebuilt by the first pair update: SAH %g height %d, rebuilt %g %d",
							dim, before.sahCost, before.height, after.sahCost, after.height);
			}
			for (int frame = 0; frame < 3 && ok; ++frame)
			{
				for (int i = 0; i < COUNT && ok; ++i)
				{
					cdReal d[3] = {CD_R(0.0), CD_R(0.0), CD_R(0.0)};
					if (TestRngInt(&rng, 10) == 0)
					{
						tight[i] = RandomBox(&rng, dim, s.lo, s.hi, s.maxSize);
					}
					else
					{
						for (int k = 0; k < dim; ++k)
						{
							d[k] = R(&rng, -s.smallMove, s.smallMove);
						}
						tight[i] = Shift(tight[i], dim, d);
					}
					ok = OracleMove(o, i, tight[i], d);
				}
				ok = ok && OracleValidate(o) && OracleUpdatePairs(o);
				TEST_CHECKF(ok, "%s %dD frame %d: %s", cdGetBroadPhaseTypeName((cdBroadPhaseType)type), dim,
							frame, o->error);
			}
			if (ok)
			{
				ok = CheckAll(o, &rng, &s, true);
			}
			OracleFree(o);
			free(o);
		}
	}
}

/* A removal shrinks the tree's recorded boxes only a few levels up (CD_TREE_SHRINK_LEVELS in
 * tree.inc): the records above may stay larger than their subtrees. After 30 frames in which a
 * tenth of a bulk-built tree's proxies teleport, the tree must be valid (records bound their
 * subtrees), answer exactly, and cost (SAH) at most 1.1 times what a rebuild of the same boxes
 * costs: the loose records must not pile up. (Measured: 1.02 in 2D, 1.05 in 3D; 1.03 and 1.08
 * when removals shrink no record above the grandparent, 1.02 and 1.05 with exact records.) */
static void TestTreeAfterManyRemovals(void)
{
	for (int dim = 2; dim <= 3; ++dim)
	{
		Oracle* o = (Oracle*)malloc(sizeof(Oracle));
		bool ready = o != NULL && OracleInit(o, dim, CD_BROADPHASE_TREE, CD_R(0.1), CD_R(4.0));
		TEST_CHECK(ready);
		if (!ready)
		{
			free(o);
			continue;
		}
		TestRng rng = TestRngMake(4242 + (uint64_t)dim);
		Scene s = {0.0, 60.0, 2.0, 0.2};
		enum
		{
			COUNT = 2000
		};
		static OBox tight[COUNT];
		bool ok = CreateRandomBoxes(o, &rng, dim, &s, tight, COUNT);
		OracleRebuild(o);
		ok = ok && OracleUpdatePairs(o) && OracleValidate(o);
		for (int frame = 0; frame < 30 && ok; ++frame)
		{
			for (int i = 0; i < COUNT && ok; ++i)
			{
				if (TestRngInt(&rng, 10) == 0)
				{
					cdReal still[3] = {CD_R(0.0), CD_R(0.0), CD_R(0.0)};
					tight[i] = RandomBox(&rng, dim, s.lo, s.hi, s.maxSize);
					ok = OracleMove(o, i, tight[i], still);
				}
			}
			ok = ok && OracleValidate(o) && OracleUpdatePairs(o);
		}
		TEST_CHECKF(ok, "tree %dD teleport frames: %s", dim, o->error);
		if (ok)
		{
			ok = CheckAll(o, &rng, &s, true);
			cdBroadPhaseStats loose =
				dim == 2 ? cd2BroadPhase_GetStats(o->bp2) : cd3BroadPhase_GetStats(o->bp3);
			OracleRebuild(o);
			cdBroadPhaseStats rebuilt =
				dim == 2 ? cd2BroadPhase_GetStats(o->bp2) : cd3BroadPhase_GetStats(o->bp3);
			TEST_CHECKF(loose.sahCost > 0.0 && loose.sahCost <= 1.1 * rebuilt.sahCost,
						"tree %dD after teleports: SAH %g, rebuilt %g", dim, loose.sahCost, rebuilt.sahCost);
			printf("    tree %dD after 30 teleport frames: SAH cost %.2f, rebuilt %.2f\n", dim, loose.sahCost,
				   rebuilt.sahCost);
		}
		OracleFree(o);
		free(o);
	}
}

/* Frames moved through MoveProxies with enough changed boxes (hundreds) that the structure takes
 * them in curve order: every proxy moves each frame, half of them teleport; duplicates (whose
 * later entries see the earlier ones' fat boxes) and invalid entries are mixed in. The answers
 * must match MoveProxy called in turn, and the structure must stay exact. */
static void TestBatchMoves(void)
{
	for (int dim = 2; dim <= 3; ++dim)
	{
		for (int type = 0; type < CD_BROADPHASE_TYPE_COUNT; ++type)
		{
			Oracle* o = (Oracle*)malloc(sizeof(Oracle));
			if (!OracleInit(o, dim, (cdBroadPhaseType)type, CD_R(0.1), CD_R(4.0)))
			{
				free(o);
				continue;
			}
			TestRng rng = TestRngMake(4242 + (uint64_t)(dim * 10 + type));
			Scene s = {0.0, 60.0, 2.0, 0.3};
			enum
			{
				COUNT = 600,
				EXTRA = 40,
				MOVES = COUNT + EXTRA
			};
			static OBox tight[COUNT];
			static int batchIds[MOVES];
			static OBox boxes[MOVES];
			static cdReal d[MOVES][3];
			bool ok = true;
			for (int i = 0; i < COUNT && ok; ++i)
			{
				tight[i] = RandomBox(&rng, dim, s.lo, s.hi, s.maxSize);
				int id;
				ok = OracleCreate(o, tight[i], (uint64_t)i, &id);
				ok = ok && id == i;
			}
			ok = ok && OracleUpdatePairs(o);
			int changedMost = 0;
			for (int frame = 0; frame < 3 && ok; ++frame)
			{
				for (int k = 0; k < MOVES; ++k)
				{
					/* All proxies in id order, then random repeats. */
					int id = k < COUNT ? k : TestRngInt(&rng, COUNT);
					for (int i = 0; i < 3; ++i)
					{
						d[k][i] = i < dim ? R(&rng, -s.smallMove, s.smallMove) : CD_R(0.0);
					}
					if (TestRngInt(&rng, 2) == 0)
					{
						tight[id] = RandomBox(&rng, dim, s.lo, s.hi, s.maxSize);
					}
					else if (TestRngInt(&rng, 4) != 0)
					{
						tight[id] = Shift(tight[id], dim, d[k]);
					}
					batchIds[k] = id;
					boxes[k] = tight[id];
					if (k >= COUNT && TestRngInt(&rng, 10) == 0)
					{
						boxes[k].min[0] = (cdReal)NAN; /* ignored entry */
					}
				}
				int before = 0;
				for (int id = 0; id < COUNT; ++id)
				{
					before += o->moved[id] ? 1 : 0;
				}
				ok = OracleMoveMany(o, MOVES, batchIds, boxes, (const cdReal(*)[3])d);
				int after = 0;
				for (int id = 0; id < COUNT; ++id)
				{
					after += o->moved[id] ? 1 : 0;
				}
				changedMost = after - before > changedMost ? after - before : changedMost;
				if (frame == 2)
				{
					/* A query between the moves and the pair update sees the new boxes. */
					OBox box = RandomBox(&rng, dim, s.lo, s.hi, 0.3 * (s.hi - s.lo));
					ok = ok && OracleQueryBox(o, box, 0);
				}
				ok = ok && OracleValidate(o) && OracleUpdatePairs(o);
				TEST_CHECKF(ok, "%s %dD batch frame %d: %s", cdGetBroadPhaseTypeName((cdBroadPhaseType)type),
							dim, frame, o->error);
			}
			/* The curve-ordered path runs from 256 changed boxes on. */
			TEST_CHECKF(changedMost >= 256, "%s %dD: only %d proxies changed in a batch",
						cdGetBroadPhaseTypeName((cdBroadPhaseType)type), dim, changedMost);
			if (ok)
			{
				ok = CheckAll(o, &rng, &s, true);
			}
			OracleFree(o);
			free(o);
		}
	}
}

/* ---- allocation failures ------------------------------------------------------------------------ */

/* The calls the run below makes, for either dimension. */
static int OomCreate(Oracle* o, OBox box, uint64_t userData)
{
	return o->dim == 2 ? cd2BroadPhase_CreateProxy(o->bp2, OracleTo2(box), userData)
					   : cd3BroadPhase_CreateProxy(o->bp3, OracleTo3(box), userData);
}

static void OomMoveMany(Oracle* o, int count, const int* ids, const OBox* boxes, bool* changed)
{
	enum
	{
		MOST = 256
	};
	cd2Aabb boxes2[MOST];
	cd3Aabb boxes3[MOST];
	count = count < MOST ? count : MOST;
	for (int i = 0; i < count; ++i)
	{
		boxes2[i] = OracleTo2(boxes[i]);
		boxes3[i] = OracleTo3(boxes[i]);
	}
	if (o->dim == 2)
	{
		cd2BroadPhase_MoveProxies(o->bp2, count, ids, boxes2, NULL, changed);
	}
	else
	{
		cd3BroadPhase_MoveProxies(o->bp3, count, ids, boxes3, NULL, changed);
	}
}

static void OomCountPair(int a, int b, uint64_t userDataA, uint64_t userDataB, void* context)
{
	(void)a;
	(void)b;
	(void)userDataA;
	(void)userDataB;
	++*(int*)context;
}

/* One broadphase whose allocations fail after `budget` of them: proxies are created, moved in
 * batches and one by one (small moves and teleports), destroyed, and pairs updated, all while
 * memory runs out. Calls may fail (an invalid id, a move reported unchanged, no pairs), but
 * nothing may crash. Then memory comes back: the structure must be valid, report exactly the
 * overlapping pairs of the fat boxes it holds, and free every block when destroyed.
 * *sawFailure: whether an allocation failed at all (false once the budget covers the run). */
static bool RunOutOfMemory(Oracle* o, int dim, cdBroadPhaseType type, long budget, bool* sawFailure)
{
	enum
	{
		COUNT = 160
	};
	TestBudgetReset(budget);
	cdSetAllocator(TestBudgetAlloc, TestBudgetFree);
	bool created = OracleInit(o, dim, type, CD_R(0.1), CD_R(4.0));
	bool ok = true;
	if (created)
	{
		TestRng rng = TestRngMake(0x00AA11u + (uint64_t)(10 * dim + (int)type));
		const Scene scene = {0.0, 20.0, 3.0, 1.0};
		int ids[COUNT];
		OBox boxes[COUNT];
		bool changed[COUNT];
		int pairs = 0;
		for (int i = 0; i < COUNT; ++i)
		{
			boxes[i] = RandomBox(&rng, dim, scene.lo, scene.hi, scene.maxSize);
			ids[i] = OomCreate(o, boxes[i], (uint64_t)i);
			if (i == COUNT / 2)
			{
				(void)(dim == 2 ? cd2BroadPhase_UpdatePairs(o->bp2, OomCountPair, &pairs)
								: cd3BroadPhase_UpdatePairs(o->bp3, OomCountPair, &pairs));
			}
		}
		for (int frame = 0; frame < 4; ++frame)
		{
			int moving[COUNT], count = 0;
			OBox moved[COUNT];
			for (int i = 0; i < COUNT; ++i)
			{
				if (ids[i] < 0)
				{
					continue;
				}
				cdReal step[3] = {R(&rng, -0.5, 0.5), R(&rng, -0.5, 0.5), R(&rng, -0.5, 0.5)};
				bool teleport = TestRngNext(&rng) % 8 == 0;
				moved[count] = teleport ? RandomBox(&rng, dim, scene.lo, scene.hi, scene.maxSize)
										: Shift(boxes[i], dim, step);
				moving[count++] = ids[i];
			}
			if (frame % 2 == 0)
			{
				OomMoveMany(o, count, moving, moved, changed);
			}
			else
			{
				for (int k = 0; k < count; ++k)
				{
					changed[k] = dim == 2
									 ? cd2BroadPhase_MoveProxy(o->bp2, moving[k], OracleTo2(moved[k]),
															   cd2MakeVec(CD_R(0.0), CD_R(0.0)))
									 : cd3BroadPhase_MoveProxy(o->bp3, moving[k], OracleTo3(moved[k]),
															   cd3MakeVec(CD_R(0.0), CD_R(0.0), CD_R(0.0)));
				}
			}
			/* A move reported done holds the new box (one that failed kept the old fat box, which
			 * the caller learns from the false it got). */
			for (int k = 0; k < count && ok; ++k)
			{
				ok = !changed[k] || OracleContains(o, OracleGetFat(o, moving[k]), moved[k]);
				TEST_CHECKF(ok, "%s %dD, budget %ld, frame %d: proxy %d reported moved without its new box",
							cdGetBroadPhaseTypeName(type), dim, budget, frame, moving[k]);
			}
			for (int k = 0, i = 0; i < COUNT; ++i)
			{
				boxes[i] = ids[i] >= 0 ? moved[k++] : boxes[i];
			}
			/* A few go and come back (a fresh id or a failed creation). */
			for (int i = frame; i < COUNT; i += 17)
			{
				if (ids[i] >= 0)
				{
					dim == 2 ? cd2BroadPhase_DestroyProxy(o->bp2, ids[i])
							 : cd3BroadPhase_DestroyProxy(o->bp3, ids[i]);
				}
				ids[i] = OomCreate(o, boxes[i], (uint64_t)i);
			}
			(void)(dim == 2 ? cd2BroadPhase_UpdatePairs(o->bp2, OomCountPair, &pairs)
							: cd3BroadPhase_UpdatePairs(o->bp3, OomCountPair, &pairs));
		}
		/* Memory is back: the oracle learns the boxes the structure holds and checks it. */
		*sawFailure = g_testBudget.failed > 0;
		g_testBudget.left = LONG_MAX;
		for (int i = 0; i < COUNT; ++i)
		{
			if (ids[i] < 0)
			{
				continue;
			}
			ok = ok && ids[i] < ORACLE_MAX_PROXIES && !o->alive[ids[i]];
			if (!ok)
			{
				break;
			}
			o->alive[ids[i]] = true;
			o->userData[ids[i]] = (uint64_t)i;
			o->fat[ids[i]] = OracleGetFat(o, ids[i]);
			o->idCapacity = ids[i] >= o->idCapacity ? ids[i] + 1 : o->idCapacity;
		}
		TEST_CHECKF(ok, "%s %dD, budget %ld: a proxy id repeats or is out of range",
					cdGetBroadPhaseTypeName(type), dim, budget);
		ok = ok && OracleValidate(o) && OracleFindAllPairs(o);
		TEST_CHECKF(ok, "%s %dD, budget %ld: %s", cdGetBroadPhaseTypeName(type), dim, budget, o->error);
	}
	else
	{
		*sawFailure = true;
		TEST_CHECKF(o->bp2 == NULL && o->bp3 == NULL, "%s %dD, budget %ld: failed Create left a broadphase",
					cdGetBroadPhaseTypeName(type), dim, budget);
	}
	OracleFree(o);
	TEST_CHECKF(g_testBudget.live == 0, "%s %dD, budget %ld: %d blocks leaked", cdGetBroadPhaseTypeName(type),
				dim, budget, g_testBudget.live);
	cdSetAllocator(NULL, NULL);
	return ok && g_testBudget.live == 0;
}

/* Every structure with its allocations failing from the first one on, then one later each time,
 * until a run needs no more than it is given. */
static void TestOutOfMemory(void)
{
	Oracle* o = (Oracle*)malloc(sizeof(Oracle));
	TEST_CHECK(o != NULL);
	for (int dim = 2; dim <= 3 && o != NULL; ++dim)
	{
		for (int type = 0; type < CD_BROADPHASE_TYPE_COUNT; ++type)
		{
			bool sawFailure = true;
			long budget = 0;
			for (; sawFailure && budget < 2000; ++budget)
			{
				if (!RunOutOfMemory(o, dim, (cdBroadPhaseType)type, budget, &sawFailure))
				{
					break;
				}
			}
			TEST_CHECKF(!sawFailure, "%s %dD: still failing at budget %ld",
						cdGetBroadPhaseTypeName((cdBroadPhaseType)type), dim, budget);
		}
	}
	free(o);
}

/* ---- enlarge mode and the split pair search (what the 2D world uses) ---------------------------- */

typedef struct KeyList
{
	uint64_t* keys;
	int count, capacity;
	bool ordered; /* every pair came with proxyA < proxyB */
} KeyList;

static void CollectKey(int proxyA, int proxyB, uint64_t userDataA, uint64_t userDataB, void* context)
{
	KeyList* list = (KeyList*)context;
	list->ordered = list->ordered && proxyA < proxyB && userDataA == (uint64_t)proxyA + 1000u &&
					userDataB == (uint64_t)proxyB + 1000u;
	if (list->count == list->capacity)
	{
		int capacity = list->capacity > 0 ? 2 * list->capacity : 1024;
		uint64_t* keys = (uint64_t*)realloc(list->keys, (size_t)capacity * sizeof(uint64_t));
		if (keys == NULL)
		{
			return;
		}
		list->keys = keys;
		list->capacity = capacity;
	}
	list->keys[list->count++] = ((uint64_t)(uint32_t)proxyA << 32) | (uint32_t)proxyB;
}

static int CompareInts(const void* a, const void* b)
{
	int x = *(const int*)a, y = *(const int*)b;
	return x < y ? -1 : (x > y ? 1 : 0);
}

static int CompareKeys(const void* a, const void* b)
{
	uint64_t x = *(const uint64_t*)a, y = *(const uint64_t*)b;
	return x < y ? -1 : (x > y ? 1 : 0);
}

static cd2Aabb RandomBox2(TestRng* rng, double extent, double maxSize)
{
	cd2Aabb b;
	b.min = cd2MakeVec(R(rng, -extent, extent), R(rng, -extent, extent));
	b.max = cd2MakeVec(b.min.x + R(rng, 0.0, maxSize), b.min.y + R(rng, 0.0, maxSize));
	return b;
}

/* Two 2D trees get the same operations; one moves proxies the usual way and reports pairs with
 * UpdatePairs, the other is in enlarge mode and finds its pairs with BeginMovedPairs, ranges of
 * QueryMovedPairs in a random split and order (as worker threads would take them) and
 * EndMovedPairs. Frames alternate between many moves (the whole-tree sweep) and few (one query per
 * moved proxy), with teleports, destructions and creations: the pairs must be the same, each
 * once, and both trees valid throughout. */
static void TestEnlargeAndSplitPairs(void)
{
	enum
	{
		COUNT = 700
	};
	TestRng rng = TestRngMake(4242);
	cd2BroadPhaseDef def = cd2DefaultBroadPhaseDef();
	def.margin = CD_R(0.05);
	def.displacementMultiplier = CD_R(2.0);
	cd2BroadPhase* reference = NULL;
	cd2BroadPhase* enlarged = NULL;
	TEST_CHECK(cd2CreateBroadPhase(&def, &reference) == CD_OK &&
			   cd2CreateBroadPhase(&def, &enlarged) == CD_OK);
	if (reference == NULL || enlarged == NULL)
	{
		cd2DestroyBroadPhase(reference);
		cd2DestroyBroadPhase(enlarged);
		return;
	}
	cd2BroadPhase_SetEnlargeMoves(enlarged, true);
	static cd2Aabb boxes[COUNT];
	static int ids[COUNT];
	for (int i = 0; i < COUNT; ++i)
	{
		boxes[i] = RandomBox2(&rng, 20.0, 1.5);
		ids[i] = cd2BroadPhase_CreateProxy(reference, boxes[i], (uint64_t)i + 1000u);
		int other = cd2BroadPhase_CreateProxy(enlarged, boxes[i], (uint64_t)i + 1000u);
		TEST_CHECK(ids[i] == i && other == i);
	}
	KeyList a = {NULL, 0, 0, true}, b = {NULL, 0, 0, true};
	int sweepFrames = 0, queryFrames = 0, rebuildJobs = 0;
	for (int frame = 0; frame < 40; ++frame)
	{
		/* Every third frame moves most proxies, the others a few. */
		int percent = frame % 3 == 0 ? 70 : 4;
		int movedCount = 0;
		for (int i = 0; i < COUNT; ++i)
		{
			if (TestRngInt(&rng, 100) >= percent)
			{
				continue;
			}
			int action = TestRngInt(&rng, 50);
			if (action == 0)
			{
				/* Destroy and create again (ids are reused lowest first in both). */
				cd2BroadPhase_DestroyProxy(reference, ids[i]);
				cd2BroadPhase_DestroyProxy(enlarged, ids[i]);
				boxes[i] = RandomBox2(&rng, 20.0, 1.5);
				int x = cd2BroadPhase_CreateProxy(reference, boxes[i], (uint64_t)ids[i] + 1000u);
				int y = cd2BroadPhase_CreateProxy(enlarged, boxes[i], (uint64_t)ids[i] + 1000u);
				TEST_CHECK(x == ids[i] && y == ids[i]);
				++movedCount;
				continue;
			}
			cd2Vec d = action == 1 ? cd2MakeVec(R(&rng, -15.0, 15.0), R(&rng, -15.0, 15.0))
								   : cd2MakeVec(R(&rng, -0.3, 0.3), R(&rng, -0.3, 0.3));
			boxes[i].min = cd2Add(boxes[i].min, d);
			boxes[i].max = cd2Add(boxes[i].max, d);
			bool x = cd2BroadPhase_MoveProxy(reference, ids[i], boxes[i], d);
			bool y = cd2BroadPhase_MoveProxy(enlarged, ids[i], boxes[i], d);
			TEST_CHECK(x == y);
			movedCount += x ? 1 : 0;
		}
		for (int i = 0; i < COUNT; i += 37)
		{
			cd2Aabb fa = cd2BroadPhase_GetFatAabb(reference, ids[i]),
					fb = cd2BroadPhase_GetFatAabb(enlarged, ids[i]);
			TEST_CHECK(cd2VecEqual(fa.min, fb.min) && cd2VecEqual(fa.max, fb.max));
		}
		TEST_CHECKF(cd2BroadPhase_Validate(enlarged), "frame %d: enlarged tree invalid after the moves",
					frame);
		a.count = b.count = 0;
		int expected = cd2BroadPhase_UpdatePairs(reference, CollectKey, &a);
		TEST_CHECK(expected == a.count);
		if (frame % 2 == 0)
		{
			/* The deferred rebuild in jobs, taken last to first (as threads might), half of the frames;
			 * the others leave it to the flush. */
			int jobs = cd2BroadPhase_BeginRebuild(enlarged);
			TEST_CHECK(jobs >= 0 && jobs <= 64);
			rebuildJobs = jobs > rebuildJobs ? jobs : rebuildJobs;
			for (int j = jobs - 1; j >= 0; --j)
			{
				cd2BroadPhase_RebuildJobs(enlarged, j, j + 1);
			}
			cd2BroadPhase_EndRebuild(enlarged);
			TEST_CHECKF(cd2BroadPhase_Validate(enlarged), "frame %d: enlarged tree invalid after the rebuild",
						frame);
		}
		int items = cd2BroadPhase_BeginMovedPairs(enlarged);
		TEST_CHECKF(cd2BroadPhase_Validate(enlarged), "frame %d: enlarged tree invalid after the flush",
					frame);
		/* Many moves: the sweep's items (tree nodes); few: one query per moved proxy. */
		if (4 * movedCount >= COUNT)
		{
			++sweepFrames;
			TEST_CHECK(items == 0 || items != movedCount);
		}
		else
		{
			++queryFrames;
			TEST_CHECK(items == movedCount);
		}
		/* Random ranges, taken in a random order. */
		enum
		{
			MAX_RANGES = 64
		};
		int cuts[MAX_RANGES + 1];
		int rangeCount = 1 + TestRngInt(&rng, MAX_RANGES);
		cuts[0] = 0;
		for (int k = 1; k < rangeCount; ++k)
		{
			cuts[k] = TestRngInt(&rng, items + 1);
		}
		cuts[rangeCount] = items;
		qsort(cuts + 1, (size_t)(rangeCount - 1), sizeof(int), CompareInts);
		int order[MAX_RANGES];
		for (int k = 0; k < rangeCount; ++k)
		{
			order[k] = k;
		}
		for (int k = rangeCount - 1; k > 0; --k)
		{
			int j = TestRngInt(&rng, k + 1), t = order[k];
			order[k] = order[j];
			order[j] = t;
		}
		for (int k = 0; k < rangeCount; ++k)
		{
			cd2BroadPhase_QueryMovedPairs(enlarged, cuts[order[k]], cuts[order[k] + 1], CollectKey, &b);
		}
		cd2BroadPhase_EndMovedPairs(enlarged, true);
		TEST_CHECK(a.ordered && b.ordered);
		if (b.count > 1)
		{
			qsort(b.keys, (size_t)b.count, sizeof(uint64_t), CompareKeys);
		}
		bool same = a.count == b.count;
		for (int k = 0; same && k < a.count; ++k)
		{
			same = a.keys[k] == b.keys[k];
		}
		TEST_CHECKF(same, "frame %d: %d pairs from UpdatePairs, %d from the split search (%d items)", frame,
					a.count, b.count, items);
		TEST_CHECK(cd2BroadPhase_Validate(enlarged));
		/* Nothing is left moved: a second search finds nothing. */
		TEST_CHECK(cd2BroadPhase_BeginMovedPairs(enlarged) == 0);
		cd2BroadPhase_EndMovedPairs(enlarged, true);
	}
	TEST_CHECK(sweepFrames > 0 && queryFrames > 0);
	TEST_CHECKF(rebuildJobs > 1, "the rebuild never split into jobs (%d)", rebuildJobs);
	/* Keeping the moves: the same pairs again on the next search. */
	boxes[0].min = cd2Add(boxes[0].min, cd2MakeVec(5.0f, 0.0f));
	boxes[0].max = cd2Add(boxes[0].max, cd2MakeVec(5.0f, 0.0f));
	TEST_CHECK(cd2BroadPhase_MoveProxy(enlarged, 0, boxes[0], CD2_VEC_ZERO));
	b.count = 0;
	int items = cd2BroadPhase_BeginMovedPairs(enlarged);
	TEST_CHECK(items == 1);
	cd2BroadPhase_QueryMovedPairs(enlarged, 0, items, CollectKey, &b);
	cd2BroadPhase_EndMovedPairs(enlarged, false);
	int first = b.count;
	b.count = 0;
	TEST_CHECK(cd2BroadPhase_BeginMovedPairs(enlarged) == 1);
	cd2BroadPhase_QueryMovedPairs(enlarged, 0, 1, CollectKey, &b);
	cd2BroadPhase_EndMovedPairs(enlarged, true);
	TEST_CHECK(b.count == first);
	free(a.keys);
	free(b.keys);
	cd2DestroyBroadPhase(reference);
	cd2DestroyBroadPhase(enlarged);
}

int main(void)
{
	TEST_RUN(TestArguments);
	TEST_RUN(TestRandomOperations);
	TEST_RUN(TestDegenerateSets);
	TEST_RUN(TestFrames);
	TEST_RUN(TestTeleportFrames);
	TEST_RUN(TestTreeAfterManyRemovals);
	TEST_RUN(TestBatchMoves);
	TEST_RUN(TestOutOfMemory);
	TEST_RUN(TestEnlargeAndSplitPairs);
	return TEST_SUMMARY();
}
