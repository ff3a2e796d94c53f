/* Tests aimed at the hash grid and the quadtree/octree: the cases their cell arithmetic can get
 * wrong (huge coordinates, boxes spanning many cells, the overflow lists, the automatic cell
 * size, deep splits of coincident points, proxies leaving the tree's region, rays along cell
 * planes and rays crossing many cells). Every answer is compared with brute force through the
 * shared oracle (tests/broad_oracle.h); ray casts are also checked to report each proxy at most
 * once and every proxy the ray truly meets. */
#include "broad_oracle.h"
#include "test.h"

typedef struct CellCase
{
	int dim;
	cdBroadPhaseType type;
	cdReal cellSize;   /* grid: 0 = automatic */
	cdReal regionHalf; /* spatial tree: region +-regionHalf */
	cdReal margin;
} CellCase;

/* Replaces the oracle's broadphase (made from the default def) by one with our cell settings. */
static bool OpenCase(Oracle* o, const CellCase* c)
{
	if (!OracleInit(o, c->dim, c->type, c->margin, CD_R(2.0)))
	{
		return false;
	}
	OracleFree(o);
	cdResult result;
	if (c->dim == 2)
	{
		cd2BroadPhaseDef def = cd2DefaultBroadPhaseDef();
		def.type = c->type;
		def.margin = c->margin;
		def.displacementMultiplier = CD_R(2.0);
		def.cellSize = c->cellSize;
		def.bounds.min = cd2MakeVec(-c->regionHalf, -c->regionHalf);
		def.bounds.max = cd2MakeVec(c->regionHalf, c->regionHalf);
		result = cd2CreateBroadPhase(&def, &o->bp2);
	}
	else
	{
		cd3BroadPhaseDef def = cd3DefaultBroadPhaseDef();
		def.type = c->type;
		def.margin = c->margin;
		def.displacementMultiplier = CD_R(2.0);
		def.cellSize = c->cellSize;
		def.bounds.min = cd3MakeVec(-c->regionHalf, -c->regionHalf, -c->regionHalf);
		def.bounds.max = cd3MakeVec(c->regionHalf, c->regionHalf, c->regionHalf);
		result = cd3CreateBroadPhase(&def, &o->bp3);
	}
	return result == CD_OK;
}

static const char* CaseName(const CellCase* c)
{
	static char name[96];
	snprintf(name, sizeof(name), "%dD %s cell %g region %g", c->dim, cdGetBroadPhaseTypeName(c->type),
			 (double)c->cellSize, (double)c->regionHalf);
	return name;
}

/* ---- ray candidates: each proxy at most once, every true hit present -------------------------- */

typedef struct RayCandidates
{
	Oracle* o;
	int count[ORACLE_MAX_PROXIES];
	bool bad;
} RayCandidates;

static cdReal CollectRay(RayCandidates* r, int id, cdReal maxFraction)
{
	if (id < 0 || id >= ORACLE_MAX_PROXIES || !r->o->alive[id])
	{
		r->bad = true;
		return maxFraction;
	}
	r->count[id]++;
	return maxFraction;
}

static cdReal CollectRay2(cd2Ray ray, cdReal maxFraction, int id, uint64_t userData, void* context)
{
	(void)ray;
	(void)userData;
	return CollectRay((RayCandidates*)context, id, maxFraction);
}

static cdReal CollectRay3(cd3Ray ray, cdReal maxFraction, int id, uint64_t userData, void* context)
{
	(void)ray;
	(void)userData;
	return CollectRay((RayCandidates*)context, id, maxFraction);
}

static RayCandidates s_candidates;

static bool CheckRayCandidates(Oracle* o, const cdReal* origin, const cdReal* translation)
{
	RayCandidates* r = &s_candidates;
	memset(r, 0, sizeof(*r));
	r->o = o;
	if (o->dim == 2)
	{
		cd2Ray ray = {{origin[0], origin[1]}, {translation[0], translation[1]}};
		cd2BroadPhase_Raycast(o->bp2, ray, CollectRay2, r);
	}
	else
	{
		cd3Ray ray = {{origin[0], origin[1], origin[2]}, {translation[0], translation[1], translation[2]}};
		cd3BroadPhase_Raycast(o->bp3, ray, CollectRay3, r);
	}
	if (r->bad)
	{
		ORACLE_FAIL(o, "ray cast reported a dead or bad id");
	}
	for (int id = 0; id < o->idCapacity; ++id)
	{
		if (r->count[id] > 1)
		{
			ORACLE_FAIL(o, "ray cast reported proxy %d %d times", id, r->count[id]);
		}
		if (o->alive[id] && r->count[id] == 0 && OracleRayHit(o, o->fat[id], origin, translation) >= 0.0)
		{
			ORACLE_FAIL(o, "ray cast missed proxy %d that the ray meets", id);
		}
	}
	return true;
}

/* ---- one full check of every answer ------------------------------------------------------------- */

static void CheckAll(Oracle* o, TestRng* rng, cdReal spread, const char* where)
{
	TEST_CHECKF(OracleValidate(o), "%s: %s", where, o->error);
	TEST_CHECKF(OracleFindAllPairs(o), "%s: %s", where, o->error);
	TEST_CHECKF(OracleUpdatePairs(o), "%s: %s", where, o->error);
	for (int q = 0; q < 6; ++q)
	{
		OBox box;
		memset(&box, 0, sizeof(box));
		for (int a = 0; a < o->dim; ++a)
		{
			cdReal center = (cdReal)TestRngRange(rng, -(double)spread, (double)spread);
			cdReal half =
				(cdReal)TestRngRange(rng, 0.0, q == 5 ? 4.0 * (double)spread : 0.2 * (double)spread);
			box.min[a] = center - half;
			box.max[a] = center + half;
		}
		TEST_CHECKF(OracleQueryBox(o, box, 0), "%s: query %d: %s", where, q, o->error);
	}
	for (int q = 0; q < 6; ++q)
	{
		cdReal origin[3] = {0, 0, 0}, translation[3] = {0, 0, 0};
		for (int a = 0; a < o->dim; ++a)
		{
			origin[a] = (cdReal)TestRngRange(rng, -(double)spread, (double)spread);
			/* short, long, axis-aligned and zero-length rays */
			double reach = q == 0 ? 0.0 : (q < 3 ? 0.1 : 3.0) * (double)spread;
			translation[a] = (cdReal)(q == 3 && a > 0 ? 0.0 : TestRngRange(rng, -reach, reach));
		}
		TEST_CHECKF(CheckRayCandidates(o, origin, translation), "%s: ray %d: %s", where, q, o->error);
		TEST_CHECKF(OracleRayCast(o, origin, translation, false), "%s: closest ray %d: %s", where, q,
					o->error);
	}
}

/* Random creates, moves (small, large, teleports) and destroys of boxes whose sizes span
 * `scales` orders of magnitude from `smallest`, centered within +-spread. */
static void RunRandom(const CellCase* c, uint64_t seed, int steps, cdReal spread, cdReal smallest,
					  double scales, int hugeEvery)
{
	Oracle* o = (Oracle*)calloc(1, sizeof(Oracle));
	TEST_CHECK(o != NULL);
	if (o == NULL)
	{
		return;
	}
	bool opened = OpenCase(o, c);
	TEST_CHECKF(opened, "%s: create failed", CaseName(c));
	if (!opened)
	{
		free(o);
		return;
	}
	TestRng rng = TestRngMake(seed);
	int ids[512];
	OBox tight[512];
	int count = 0;
	for (int step = 0; step < steps; ++step)
	{
		int action = TestRngInt(&rng, 10);
		if (count < 20 || (action < 4 && count < 512))
		{
			OBox b;
			memset(&b, 0, sizeof(b));
			double size = (double)smallest * pow(10.0, TestRngRange(&rng, 0.0, scales));
			if (hugeEvery > 0 && TestRngInt(&rng, hugeEvery) == 0)
			{
				size = 2.5 * (double)spread;
			}
			for (int a = 0; a < c->dim; ++a)
			{
				double center = TestRngRange(&rng, -(double)spread, (double)spread);
				b.min[a] = (cdReal)(center - 0.5 * size);
				b.max[a] = (cdReal)(center + 0.5 * size);
			}
			int id;
			TEST_CHECKF(OracleCreate(o, b, (uint64_t)step * 7u + 1u, &id), "%s: %s", CaseName(c), o->error);
			if (id >= 0)
			{
				ids[count] = id;
				tight[count++] = b;
			}
		}
		else if (action < 8)
		{
			int k = TestRngInt(&rng, count);
			OBox b = tight[k];
			cdReal d[3] = {0, 0, 0};
			bool teleport = TestRngInt(&rng, 8) == 0;
			for (int a = 0; a < c->dim; ++a)
			{
				double extent = (double)(b.max[a] - b.min[a]);
				double shift = teleport
								   ? TestRngRange(&rng, -(double)spread, (double)spread) - (double)b.min[a]
								   : TestRngRange(&rng, -0.3, 0.3) * (extent + (double)smallest);
				b.min[a] = (cdReal)((double)b.min[a] + shift);
				b.max[a] = (cdReal)((double)b.min[a] + extent);
				d[a] = teleport ? CD_R(0.0) : (cdReal)shift;
			}
			tight[k] = b;
			TEST_CHECKF(OracleMove(o, ids[k], b, d), "%s: %s", CaseName(c), o->error);
		}
		else
		{
			int k = TestRngInt(&rng, count);
			TEST_CHECKF(OracleDestroy(o, ids[k]), "%s: %s", CaseName(c), o->error);
			ids[k] = ids[--count];
			tight[k] = tight[count];
		}
		TEST_CHECKF(OracleValidate(o), "%s step %d: %s", CaseName(c), step, o->error);
		if (step % 50 == 49)
		{
			CheckAll(o, &rng, spread, CaseName(c));
		}
		if (step == steps / 2)
		{
			OracleRebuild(o);
			CheckAll(o, &rng, spread, CaseName(c));
		}
	}
	CheckAll(o, &rng, spread, CaseName(c));
	OracleFree(o);
	free(o);
}

static const cdBroadPhaseType s_types[2] = {CD_BROADPHASE_GRID, CD_BROADPHASE_SPATIAL_TREE};

/* Boxes of similar size: the grid's home ground, with the automatic and a fixed cell size. */
static void TestSimilarSizes(void)
{
	for (int dim = 2; dim <= 3; ++dim)
	{
		for (int t = 0; t < 2; ++t)
		{
			CellCase c = {dim, s_types[t], CD_R(0.0), CD_R(100.0), CD_R(0.05)};
			RunRandom(&c, 11u + (uint64_t)dim, 400, CD_R(30.0), CD_R(0.5), 0.5, 0);
			c.cellSize = CD_R(2.0);
			RunRandom(&c, 21u + (uint64_t)dim, 300, CD_R(30.0), CD_R(0.5), 0.5, 0);
		}
	}
}

/* Sizes over six orders of magnitude, some boxes larger than the whole scene: the grid's
 * overflow list (spans over the cap) and the tree's big proxies near the root. */
static void TestMixedScalesAndHugeBoxes(void)
{
	for (int dim = 2; dim <= 3; ++dim)
	{
		for (int t = 0; t < 2; ++t)
		{
			CellCase c = {dim, s_types[t], CD_R(1.0), CD_R(50.0), CD_R(0.0)};
			RunRandom(&c, 31u + (uint64_t)dim, 400, CD_R(40.0), CD_R(0.001), 4.0, 10);
		}
	}
}

/* A tiny cell size: almost every box spans more cells than the cap and lives in the overflow
 * list; moves shrink and grow boxes across the cap. */
static void TestTinyCells(void)
{
	for (int dim = 2; dim <= 3; ++dim)
	{
		CellCase c = {dim, CD_BROADPHASE_GRID, CD_R(0.05), CD_R(100.0), CD_R(0.0)};
		RunRandom(&c, 41u + (uint64_t)dim, 300, CD_R(5.0), CD_R(0.01), 2.0, 0);
	}
}

/* Coordinates up to 1e9 (the float build's documented range) with cells of 1: cell indices
 * would overflow the packed keys without clamping; the tree's region is tiny in comparison,
 * so nearly everything is in its overflow list. */
static void TestHugeCoordinates(void)
{
	for (int dim = 2; dim <= 3; ++dim)
	{
		for (int t = 0; t < 2; ++t)
		{
			CellCase c = {dim, s_types[t], CD_R(1.0), CD_R(1000.0), CD_R(0.0)};
			RunRandom(&c, 51u + (uint64_t)dim, 300, CD_R(1e9), CD_R(1.0), 8.0, 0);
		}
	}
}

/* A region that covers only part of the scene: proxies move in and out of the tree. */
static void TestRegionBoundary(void)
{
	for (int dim = 2; dim <= 3; ++dim)
	{
		CellCase c = {dim, CD_BROADPHASE_SPATIAL_TREE, CD_R(0.0), CD_R(10.0), CD_R(0.1)};
		RunRandom(&c, 61u + (uint64_t)dim, 400, CD_R(14.0), CD_R(0.05), 1.5, 0);
	}
}

/* Many coincident points and zero-size boxes: the tree splits down to its depth limit, the grid
 * piles them into one cell; both must stay valid and exact. */
static void TestCoincidentPoints(void)
{
	for (int dim = 2; dim <= 3; ++dim)
	{
		for (int t = 0; t < 2; ++t)
		{
			CellCase c = {dim, s_types[t], CD_R(0.0), CD_R(100.0), CD_R(0.0)};
			Oracle* o = (Oracle*)calloc(1, sizeof(Oracle));
			TEST_CHECK(o != NULL && OpenCase(o, &c));
			if (o == NULL || (o->bp2 == NULL && o->bp3 == NULL))
			{
				free(o);
				continue;
			}
			TestRng rng = TestRngMake(71u + (uint64_t)dim);
			for (int i = 0; i < 200; ++i)
			{
				OBox b;
				memset(&b, 0, sizeof(b));
				for (int a = 0; a < dim; ++a)
				{
					/* half exactly on one point, half on a tiny cluster */
					b.min[a] = b.max[a] =
						i % 2 == 0 ? CD_R(3.25) : (cdReal)TestRngRange(&rng, 3.0, 3.0 + 1e-6);
				}
				int id;
				TEST_CHECKF(OracleCreate(o, b, (uint64_t)i, &id), "%s: %s", CaseName(&c), o->error);
				TEST_CHECKF(OracleValidate(o), "%s: %s", CaseName(&c), o->error);
			}
			cdBroadPhaseStats stats = OracleStats(o);
			TEST_CHECKF(stats.proxyCount == 200, "%s: %d proxies", CaseName(&c), stats.proxyCount);
			TEST_CHECKF(stats.memoryBytes > 0 && stats.nodeCount > 0, "%s: stats", CaseName(&c));
			if (c.type == CD_BROADPHASE_SPATIAL_TREE)
			{
				/* 100 coincident points cannot be separated: the splits stop at the depth limit. */
				TEST_CHECKF(stats.height > 1 && stats.height <= 21, "%s: height %d", CaseName(&c),
							stats.height);
			}
			CheckAll(o, &rng, CD_R(4.0), CaseName(&c));
			OracleFree(o);
			free(o);
		}
	}
}

/* Boxes touching cell planes exactly, and rays running along those planes. */
static void TestCellPlanes(void)
{
	for (int dim = 2; dim <= 3; ++dim)
	{
		for (int t = 0; t < 2; ++t)
		{
			CellCase c = {dim, s_types[t], CD_R(1.0), CD_R(8.0), CD_R(0.0)};
			Oracle* o = (Oracle*)calloc(1, sizeof(Oracle));
			TEST_CHECK(o != NULL && OpenCase(o, &c));
			if (o == NULL || (o->bp2 == NULL && o->bp3 == NULL))
			{
				free(o);
				continue;
			}
			/* unit boxes on the integer lattice: neighbours touch along cell planes */
			int made = 0;
			for (int i = -3; i <= 3; ++i)
			{
				for (int j = -3; j <= 3; ++j)
				{
					for (int k = (dim == 3 ? -1 : 0); k <= (dim == 3 ? 1 : 0); ++k)
					{
						OBox b;
						memset(&b, 0, sizeof(b));
						int cell[3] = {i, j, k};
						for (int a = 0; a < dim; ++a)
						{
							b.min[a] = (cdReal)cell[a];
							b.max[a] = (cdReal)(cell[a] + 1);
						}
						int id;
						TEST_CHECKF(OracleCreate(o, b, (uint64_t)made++, &id), "%s: %s", CaseName(&c),
									o->error);
					}
				}
			}
			TEST_CHECKF(OracleValidate(o), "%s: %s", CaseName(&c), o->error);
			TEST_CHECKF(OracleFindAllPairs(o), "%s: %s", CaseName(&c), o->error);
			/* rays along lattice planes and through lattice corners */
			const cdReal rays[][6] = {{-5, 0, 0, 10, 0, 0},		{0, -5, 0, 0, 10, 0},  {-5, -5, 0, 10, 10, 0},
									  {-5, 1, 1, 10, 0, 0},		{2, 2, -1, -6, -6, 2}, {3, -4, 0, -6, 8, 0},
									  {0.5, 0.5, 0.5, 0, 0, 0}, {-4, 0, -4, 8, 0, 8}};
			for (size_t r = 0; r < sizeof(rays) / sizeof(rays[0]); ++r)
			{
				TEST_CHECKF(CheckRayCandidates(o, rays[r], rays[r] + 3), "%s ray %d: %s", CaseName(&c),
							(int)r, o->error);
				TEST_CHECKF(OracleRayCast(o, rays[r], rays[r] + 3, false), "%s ray %d: %s", CaseName(&c),
							(int)r, o->error);
			}
			OBox query;
			memset(&query, 0, sizeof(query));
			for (int a = 0; a < dim; ++a)
			{
				query.min[a] = CD_R(1.0);
				query.max[a] = CD_R(1.0);
			}
			TEST_CHECKF(OracleQueryBox(o, query, 0), "%s: point query on a lattice corner: %s", CaseName(&c),
						o->error);
			OracleFree(o);
			free(o);
		}
	}
}

/* The automatic grid cell size waits for a sample of proxies: before that every proxy is in the
 * overflow list (no cells), after it the cells are in use. */
static void TestAutomaticCellSize(void)
{
	for (int dim = 2; dim <= 3; ++dim)
	{
		CellCase c = {dim, CD_BROADPHASE_GRID, CD_R(0.0), CD_R(100.0), CD_R(0.0)};
		Oracle* o = (Oracle*)calloc(1, sizeof(Oracle));
		TEST_CHECK(o != NULL && OpenCase(o, &c));
		if (o == NULL || (o->bp2 == NULL && o->bp3 == NULL))
		{
			free(o);
			continue;
		}
		TestRng rng = TestRngMake(81u + (uint64_t)dim);
		for (int i = 0; i < 40; ++i)
		{
			OBox b;
			memset(&b, 0, sizeof(b));
			for (int a = 0; a < dim; ++a)
			{
				b.min[a] = (cdReal)TestRngRange(&rng, -10.0, 10.0);
				b.max[a] = b.min[a] + CD_R(1.0);
			}
			int id;
			TEST_CHECKF(OracleCreate(o, b, (uint64_t)i, &id), "%s", o->error);
			cdBroadPhaseStats stats = OracleStats(o);
			if (i == 5)
			{
				TEST_CHECKF(stats.nodeCount == 0, "%dD: %d cells before the sample is complete", dim,
							stats.nodeCount);
				CheckAll(o, &rng, CD_R(10.0), "auto cell size, waiting");
			}
		}
		cdBroadPhaseStats stats = OracleStats(o);
		TEST_CHECKF(stats.nodeCount > 0, "%dD: no cells after 40 proxies", dim);
		CheckAll(o, &rng, CD_R(10.0), "auto cell size, chosen");
		OracleFree(o);
		free(o);
	}
}

int main(void)
{
	TEST_RUN(TestSimilarSizes);
	TEST_RUN(TestMixedScalesAndHugeBoxes);
	TEST_RUN(TestTinyCells);
	TEST_RUN(TestHugeCoordinates);
	TEST_RUN(TestRegionBoundary);
	TEST_RUN(TestCoincidentPoints);
	TEST_RUN(TestCellPlanes);
	TEST_RUN(TestAutomaticCellSize);
	return TEST_SUMMARY();
}
