/* Brute-force oracle for the broadphase, shared by tests/test_broadphase.c and
 * fuzz/fuzz_broadphase.c. It drives a cd2/cd3 broadphase through one dimension-free interface,
 * mirrors every operation on a plain list of fat boxes, and compares the answers.
 *
 * Fat boxes are recomputed here from the documented rule (tight box grown by the margin, then
 * stretched by multiplier * displacement; kept while the new tight box fits and the old fat box
 * is not larger than the rule with 4x margin and displacement would give), in cdReal with the
 * same operation order as the library, so they must agree to the bit. */
#ifndef COLLIDE_BROAD_ORACLE_H
#define COLLIDE_BROAD_ORACLE_H

#include "collide/broad.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define ORACLE_MAX_PROXIES 4096

typedef struct OBox
{
	cdReal min[3], max[3];
} OBox;

typedef struct Oracle
{
	int dim;
	cdBroadPhaseType type;
	cdReal margin, multiplier;
	cd2BroadPhase* bp2;
	cd3BroadPhase* bp3;
	bool alive[ORACLE_MAX_PROXIES];
	bool moved[ORACLE_MAX_PROXIES];
	OBox fat[ORACLE_MAX_PROXIES];
	uint64_t userData[ORACLE_MAX_PROXIES];
	int idCapacity; /* ids below this were handed out at some point */
	/* scratch for answers */
	int found[ORACLE_MAX_PROXIES];
	int foundCount;
	int pairs[2 * ORACLE_MAX_PROXIES * 8];
	int pairCount;
	bool pairOverflow;
	char error[256];
} Oracle;

static inline cd2Aabb OracleTo2(OBox b)
{
	cd2Aabb a = {{b.min[0], b.min[1]}, {b.max[0], b.max[1]}};
	return a;
}

static inline cd3Aabb OracleTo3(OBox b)
{
	cd3Aabb a = {{b.min[0], b.min[1], b.min[2]}, {b.max[0], b.max[1], b.max[2]}};
	return a;
}

static inline OBox OracleFrom2(cd2Aabb a)
{
	OBox b = {{a.min.x, a.min.y, CD_R(0.0)}, {a.max.x, a.max.y, CD_R(0.0)}};
	return b;
}

static inline OBox OracleFrom3(cd3Aabb a)
{
	OBox b = {{a.min.x, a.min.y, a.min.z}, {a.max.x, a.max.y, a.max.z}};
	return b;
}

static inline bool OracleBoxValid(const Oracle* o, OBox b)
{
	for (int i = 0; i < o->dim; ++i)
	{
		if (!isfinite(b.min[i]) || !isfinite(b.max[i]) || !(b.min[i] <= b.max[i]))
		{
			return false;
		}
	}
	return true;
}

static inline bool OracleOverlap(const Oracle* o, OBox a, OBox b)
{
	for (int i = 0; i < o->dim; ++i)
	{
		if (a.min[i] > b.max[i] || b.min[i] > a.max[i])
		{
			return false;
		}
	}
	return true;
}

static inline bool OracleContains(const Oracle* o, OBox outer, OBox inner)
{
	for (int i = 0; i < o->dim; ++i)
	{
		if (!(outer.min[i] <= inner.min[i] && inner.max[i] <= outer.max[i]))
		{
			return false;
		}
	}
	return true;
}

static inline bool OracleBoxEqual(const Oracle* o, OBox a, OBox b)
{
	for (int i = 0; i < o->dim; ++i)
	{
		if (a.min[i] != b.min[i] || a.max[i] != b.max[i])
		{
			return false;
		}
	}
	return true;
}

static inline OBox OracleFat(const Oracle* o, OBox tight, const cdReal* displacement, cdReal scale)
{
	OBox f = tight;
	cdReal m = scale * o->margin;
	for (int i = 0; i < o->dim; ++i)
	{
		cdReal d = (scale * o->multiplier) * displacement[i];
		f.min[i] = (tight.min[i] - m) + (d < CD_R(0.0) ? d : CD_R(0.0));
		f.max[i] = (tight.max[i] + m) + (d > CD_R(0.0) ? d : CD_R(0.0));
		f.min[i] = cdClamp(f.min[i], -CD_REAL_MAX, CD_REAL_MAX);
		f.max[i] = cdClamp(f.max[i], -CD_REAL_MAX, CD_REAL_MAX);
	}
	return f;
}

static inline bool OracleInit(Oracle* o, int dim, cdBroadPhaseType type, cdReal margin, cdReal multiplier)
{
	memset(o, 0, sizeof(*o));
	o->dim = dim;
	o->type = type;
	o->margin = margin;
	o->multiplier = multiplier;
	cdResult result;
	if (dim == 2)
	{
		cd2BroadPhaseDef def = cd2DefaultBroadPhaseDef();
		def.type = type;
		def.margin = margin;
		def.displacementMultiplier = multiplier;
		result = cd2CreateBroadPhase(&def, &o->bp2);
	}
	else
	{
		cd3BroadPhaseDef def = cd3DefaultBroadPhaseDef();
		def.type = type;
		def.margin = margin;
		def.displacementMultiplier = multiplier;
		result = cd3CreateBroadPhase(&def, &o->bp3);
	}
	return result == CD_OK;
}

static inline void OracleFree(Oracle* o)
{
	if (o->bp2 != NULL)
	{
		cd2DestroyBroadPhase(o->bp2);
	}
	if (o->bp3 != NULL)
	{
		cd3DestroyBroadPhase(o->bp3);
	}
	o->bp2 = NULL;
	o->bp3 = NULL;
}

#define ORACLE_FAIL(o, ...)                                                                                  \
	do                                                                                                       \
	{                                                                                                        \
		snprintf((o)->error, sizeof((o)->error), __VA_ARGS__);                                               \
		return false;                                                                                        \
	} while (0)

static inline bool OracleValidate(Oracle* o)
{
	bool ok = o->dim == 2 ? cd2BroadPhase_Validate(o->bp2) : cd3BroadPhase_Validate(o->bp3);
	if (!ok)
	{
		ORACLE_FAIL(o, "Validate() failed");
	}
	int live = 0;
	for (int id = 0; id < o->idCapacity; ++id)
	{
		live += o->alive[id] ? 1 : 0;
	}
	int count = o->dim == 2 ? cd2BroadPhase_GetProxyCount(o->bp2) : cd3BroadPhase_GetProxyCount(o->bp3);
	if (count != live)
	{
		ORACLE_FAIL(o, "proxy count %d, expected %d", count, live);
	}
	return true;
}

static inline OBox OracleGetFat(const Oracle* o, int id)
{
	return o->dim == 2 ? OracleFrom2(cd2BroadPhase_GetFatAabb(o->bp2, id))
					   : OracleFrom3(cd3BroadPhase_GetFatAabb(o->bp3, id));
}

/* Creates a proxy; checks the id (fresh or reused, never a live one) and the fat box. Returns
 * the id (or CD_NULL_PROXY) through *outId; false on a mismatch. */
static inline bool OracleCreate(Oracle* o, OBox tight, uint64_t userData, int* outId)
{
	int id = o->dim == 2 ? cd2BroadPhase_CreateProxy(o->bp2, OracleTo2(tight), userData)
						 : cd3BroadPhase_CreateProxy(o->bp3, OracleTo3(tight), userData);
	*outId = id;
	if (!OracleBoxValid(o, tight))
	{
		if (id != CD_NULL_PROXY)
		{
			ORACLE_FAIL(o, "invalid box accepted as proxy %d", id);
		}
		return true;
	}
	if (id < 0 || id >= ORACLE_MAX_PROXIES || o->alive[id])
	{
		ORACLE_FAIL(o, "bad new id %d", id);
	}
	cdReal zero[3] = {CD_R(0.0), CD_R(0.0), CD_R(0.0)};
	o->alive[id] = true;
	o->moved[id] = true;
	o->fat[id] = OracleFat(o, tight, zero, CD_R(1.0));
	o->userData[id] = userData;
	if (id >= o->idCapacity)
	{
		o->idCapacity = id + 1;
	}
	if (!OracleBoxEqual(o, OracleGetFat(o, id), o->fat[id]))
	{
		ORACLE_FAIL(o, "fat box of new proxy %d differs from the rule", id);
	}
	uint64_t stored =
		o->dim == 2 ? cd2BroadPhase_GetUserData(o->bp2, id) : cd3BroadPhase_GetUserData(o->bp3, id);
	if (stored != userData)
	{
		ORACLE_FAIL(o, "user data of proxy %d lost", id);
	}
	return true;
}

static inline bool OracleDestroy(Oracle* o, int id)
{
	if (o->dim == 2)
	{
		cd2BroadPhase_DestroyProxy(o->bp2, id);
	}
	else
	{
		cd3BroadPhase_DestroyProxy(o->bp3, id);
	}
	o->alive[id] = false;
	o->moved[id] = false;
	return true;
}

static inline bool OracleMove(Oracle* o, int id, OBox tight, const cdReal* displacement)
{
	bool changed;
	if (o->dim == 2)
	{
		cd2Vec d = {displacement[0], displacement[1]};
		changed = cd2BroadPhase_MoveProxy(o->bp2, id, OracleTo2(tight), d);
	}
	else
	{
		cd3Vec d = {displacement[0], displacement[1], displacement[2]};
		changed = cd3BroadPhase_MoveProxy(o->bp3, id, OracleTo3(tight), d);
	}
	bool validDisplacement = true;
	for (int i = 0; i < o->dim; ++i)
	{
		validDisplacement = validDisplacement && isfinite(displacement[i]);
	}
	bool expected = false;
	if (OracleBoxValid(o, tight) && validDisplacement)
	{
		OBox old = o->fat[id];
		expected = !(OracleContains(o, old, tight) &&
					 OracleContains(o, OracleFat(o, tight, displacement, CD_R(4.0)), old));
		if (expected)
		{
			o->fat[id] = OracleFat(o, tight, displacement, CD_R(1.0));
			o->moved[id] = true;
		}
	}
	if (changed != expected)
	{
		ORACLE_FAIL(o, "MoveProxy(%d) returned %d, expected %d", id, (int)changed, (int)expected);
	}
	if (!OracleBoxEqual(o, OracleGetFat(o, id), o->fat[id]))
	{
		ORACLE_FAIL(o, "fat box of proxy %d after a move differs from the rule", id);
	}
	return true;
}

/* MoveProxies over `count` moves (ids may repeat): every entry must answer what MoveProxy would
 * have answered in turn, and the return value must count the changed entries. */
static inline bool OracleMoveMany(Oracle* o, int count, const int* ids, const OBox* tight,
								  const cdReal (*displacement)[3])
{
	enum
	{
		MOST = 2 * ORACLE_MAX_PROXIES
	};
	static cd2Aabb boxes2[MOST];
	static cd3Aabb boxes3[MOST];
	static cd2Vec d2[MOST];
	static cd3Vec d3[MOST];
	static bool changed[MOST];
	if (count > MOST)
	{
		ORACLE_FAIL(o, "OracleMoveMany: %d moves, at most %d", count, (int)MOST);
	}
	int returned;
	for (int i = 0; i < count; ++i)
	{
		boxes2[i] = OracleTo2(tight[i]);
		boxes3[i] = OracleTo3(tight[i]);
		d2[i] = cd2MakeVec(displacement[i][0], displacement[i][1]);
		d3[i] = cd3MakeVec(displacement[i][0], displacement[i][1], displacement[i][2]);
		changed[i] = !(i & 1); /* overwritten */
	}
	if (o->dim == 2)
	{
		returned = cd2BroadPhase_MoveProxies(o->bp2, count, ids, boxes2, d2, changed);
	}
	else
	{
		returned = cd3BroadPhase_MoveProxies(o->bp3, count, ids, boxes3, d3, changed);
	}
	int expectedCount = 0;
	for (int i = 0; i < count; ++i)
	{
		int id = ids[i];
		bool validDisplacement = true;
		for (int k = 0; k < o->dim; ++k)
		{
			validDisplacement = validDisplacement && isfinite(displacement[i][k]);
		}
		bool expected = false;
		if (OracleBoxValid(o, tight[i]) && validDisplacement)
		{
			OBox old = o->fat[id];
			expected = !(OracleContains(o, old, tight[i]) &&
						 OracleContains(o, OracleFat(o, tight[i], displacement[i], CD_R(4.0)), old));
			if (expected)
			{
				o->fat[id] = OracleFat(o, tight[i], displacement[i], CD_R(1.0));
				o->moved[id] = true;
			}
		}
		expectedCount += expected ? 1 : 0;
		if (changed[i] != expected)
		{
			ORACLE_FAIL(o, "MoveProxies entry %d (proxy %d) reported %d, expected %d", i, id, (int)changed[i],
						(int)expected);
		}
	}
	if (returned != expectedCount)
	{
		ORACLE_FAIL(o, "MoveProxies returned %d, expected %d", returned, expectedCount);
	}
	for (int i = 0; i < count; ++i)
	{
		if (!OracleBoxEqual(o, OracleGetFat(o, ids[i]), o->fat[ids[i]]))
		{
			ORACLE_FAIL(o, "fat box of proxy %d after MoveProxies differs from the rule", ids[i]);
		}
	}
	return true;
}

static void OraclePairFcn(int a, int b, uint64_t userDataA, uint64_t userDataB, void* context)
{
	Oracle* o = (Oracle*)context;
	if (o->pairCount >= ORACLE_MAX_PROXIES * 8)
	{
		o->pairOverflow = true;
		return;
	}
	bool dataOk = a >= 0 && b >= 0 && a < ORACLE_MAX_PROXIES && b < ORACLE_MAX_PROXIES &&
				  userDataA == o->userData[a] && userDataB == o->userData[b];
	o->pairs[2 * o->pairCount] = dataOk ? a : -1;
	o->pairs[2 * o->pairCount + 1] = b;
	o->pairCount++;
}

/* Compares the reported pairs with the brute-force list in order (sorted by (a, b)). */
static inline bool OracleComparePairs(Oracle* o, int returned, bool movedOnly, const char* what)
{
	if (o->pairOverflow)
	{
		return true; /* too many pairs for the scratch list: nothing to compare */
	}
	if (returned != o->pairCount)
	{
		ORACLE_FAIL(o, "%s returned %d but reported %d pairs", what, returned, o->pairCount);
	}
	int k = 0;
	for (int a = 0; a < o->idCapacity; ++a)
	{
		if (!o->alive[a])
		{
			continue;
		}
		for (int b = a + 1; b < o->idCapacity; ++b)
		{
			if (!o->alive[b] || (movedOnly && !o->moved[a] && !o->moved[b]) ||
				!OracleOverlap(o, o->fat[a], o->fat[b]))
			{
				continue;
			}
			if (k >= o->pairCount || o->pairs[2 * k] != a || o->pairs[2 * k + 1] != b)
			{
				ORACLE_FAIL(o, "%s: pair %d is (%d, %d), expected (%d, %d)", what, k,
							k < o->pairCount ? o->pairs[2 * k] : -1,
							k < o->pairCount ? o->pairs[2 * k + 1] : -1, a, b);
			}
			++k;
		}
	}
	if (k != o->pairCount)
	{
		ORACLE_FAIL(o, "%s reported %d pairs, expected %d", what, o->pairCount, k);
	}
	return true;
}

static inline bool OracleUpdatePairs(Oracle* o)
{
	o->pairCount = 0;
	o->pairOverflow = false;
	int n = o->dim == 2 ? cd2BroadPhase_UpdatePairs(o->bp2, OraclePairFcn, o)
						: cd3BroadPhase_UpdatePairs(o->bp3, OraclePairFcn, o);
	bool ok = OracleComparePairs(o, n, true, "UpdatePairs");
	memset(o->moved, 0, sizeof(o->moved));
	return ok;
}

static inline bool OracleFindAllPairs(Oracle* o)
{
	o->pairCount = 0;
	o->pairOverflow = false;
	int n = o->dim == 2 ? cd2BroadPhase_FindAllPairs(o->bp2, OraclePairFcn, o)
						: cd3BroadPhase_FindAllPairs(o->bp3, OraclePairFcn, o);
	return OracleComparePairs(o, n, false, "FindAllPairs");
}

typedef struct OracleQuery
{
	Oracle* o;
	int stopAfter; /* 0: never stop */
	bool badData;
} OracleQuery;

static bool OracleQueryFcn(OracleQuery* q, int id, uint64_t userData)
{
	Oracle* o = q->o;
	if (id < 0 || id >= ORACLE_MAX_PROXIES || userData != o->userData[id])
	{
		q->badData = true;
	}
	if (o->foundCount < ORACLE_MAX_PROXIES)
	{
		o->found[o->foundCount++] = id;
	}
	return q->stopAfter == 0 || o->foundCount < q->stopAfter;
}

static bool OracleQuery2(int id, uint64_t userData, void* context)
{
	return OracleQueryFcn((OracleQuery*)context, id, userData);
}

static bool OracleQuery3(int id, uint64_t userData, void* context)
{
	return OracleQueryFcn((OracleQuery*)context, id, userData);
}

static int OracleCompareInts(const void* a, const void* b)
{
	int x = *(const int*)a, y = *(const int*)b;
	return (x > y) - (x < y);
}

/* Box query: the set equals brute force; with stopAfter > 0, exactly min(stopAfter, expected)
 * calls, each a true overlap. */
static inline bool OracleQueryBox(Oracle* o, OBox box, int stopAfter)
{
	OracleQuery q = {o, stopAfter, false};
	o->foundCount = 0;
	if (o->dim == 2)
	{
		cd2BroadPhase_Query(o->bp2, OracleTo2(box), OracleQuery2, &q);
	}
	else
	{
		cd3BroadPhase_Query(o->bp3, OracleTo3(box), OracleQuery3, &q);
	}
	if (q.badData)
	{
		ORACLE_FAIL(o, "query reported a bad id or user data");
	}
	int expected = 0;
	for (int id = 0; id < o->idCapacity; ++id)
	{
		expected += o->alive[id] && OracleOverlap(o, o->fat[id], box) ? 1 : 0;
	}
	qsort(o->found, (size_t)o->foundCount, sizeof(int), OracleCompareInts);
	for (int i = 0; i < o->foundCount; ++i)
	{
		int id = o->found[i];
		if (!o->alive[id] || !OracleOverlap(o, o->fat[id], box) || (i > 0 && o->found[i - 1] == id))
		{
			ORACLE_FAIL(o, "query reported proxy %d wrongly (dead, disjoint or twice)", id);
		}
	}
	int wanted = stopAfter > 0 && stopAfter < expected ? stopAfter : expected;
	if (o->foundCount != wanted)
	{
		ORACLE_FAIL(o, "query found %d proxies, expected %d (stop after %d)", o->foundCount, wanted,
					stopAfter);
	}
	return true;
}

/* Exact entry fraction of the ray segment t in [0, 1] into a closed box, in double; -1 on a miss. */
static inline double OracleRayHit(const Oracle* o, OBox box, const cdReal* origin, const cdReal* translation)
{
	double enter = 0.0, exit = 1.0;
	for (int i = 0; i < o->dim; ++i)
	{
		double p = origin[i], d = translation[i], lo = box.min[i], hi = box.max[i];
		if (d == 0.0)
		{
			if (p < lo || p > hi)
			{
				return -1.0;
			}
			continue;
		}
		double t1 = (lo - p) / d, t2 = (hi - p) / d;
		if (t1 > t2)
		{
			double swap = t1;
			t1 = t2;
			t2 = swap;
		}
		enter = t1 > enter ? t1 : enter;
		exit = t2 < exit ? t2 : exit;
		if (enter > exit)
		{
			return -1.0;
		}
	}
	return enter;
}

typedef struct OracleRay
{
	Oracle* o;
	cdReal origin[3], translation[3];
	bool anyHit;
	double best;
	int hits; /* callbacks on a proxy the ray truly meets */
	int callsAfterStop;
	bool stopped;
	bool bad;
} OracleRay;

static cdReal OracleRayFcn(OracleRay* r, cdReal maxFraction, int id)
{
	Oracle* o = r->o;
	if (r->stopped)
	{
		r->callsAfterStop++;
	}
	if (id < 0 || id >= o->idCapacity || !o->alive[id] || !(maxFraction > CD_R(0.0)) ||
		maxFraction > CD_R(1.0))
	{
		r->bad = true;
		return CD_R(-1.0);
	}
	double t = OracleRayHit(o, o->fat[id], r->origin, r->translation);
	if (t < 0.0)
	{
		return CD_R(-1.0);
	}
	r->hits++;
	if (t < r->best)
	{
		r->best = t;
	}
	if (r->anyHit || t == 0.0)
	{
		r->stopped = true;
		return CD_R(0.0);
	}
	return (cdReal)t;
}

static cdReal OracleRay2(cd2Ray ray, cdReal maxFraction, int id, uint64_t userData, void* context)
{
	(void)ray;
	(void)userData;
	return OracleRayFcn((OracleRay*)context, maxFraction, id);
}

static cdReal OracleRay3(cd3Ray ray, cdReal maxFraction, int id, uint64_t userData, void* context)
{
	(void)ray;
	(void)userData;
	return OracleRayFcn((OracleRay*)context, maxFraction, id);
}

/* Closest hit equals the brute-force nearest entry; any-hit stops at the first hit. */
static inline bool OracleRayCast(Oracle* o, const cdReal* origin, const cdReal* translation, bool anyHit)
{
	OracleRay r;
	memset(&r, 0, sizeof(r));
	r.o = o;
	memcpy(r.origin, origin, sizeof(r.origin));
	memcpy(r.translation, translation, sizeof(r.translation));
	r.anyHit = anyHit;
	r.best = 2.0;
	if (o->dim == 2)
	{
		cd2Ray ray = {{origin[0], origin[1]}, {translation[0], translation[1]}};
		cd2BroadPhase_Raycast(o->bp2, ray, OracleRay2, &r);
	}
	else
	{
		cd3Ray ray = {{origin[0], origin[1], origin[2]}, {translation[0], translation[1], translation[2]}};
		cd3BroadPhase_Raycast(o->bp3, ray, OracleRay3, &r);
	}
	double expected = 2.0;
	for (int id = 0; id < o->idCapacity; ++id)
	{
		if (o->alive[id])
		{
			double t = OracleRayHit(o, o->fat[id], origin, translation);
			if (t >= 0.0 && t < expected)
			{
				expected = t;
			}
		}
	}
	if (r.bad || r.callsAfterStop > 0)
	{
		ORACLE_FAIL(o, "ray cast: bad callback arguments or calls after a stop");
	}
	if (anyHit)
	{
		if ((expected <= 1.0) != (r.hits == 1))
		{
			ORACLE_FAIL(o, "any-hit ray: %d hits, brute force %s", r.hits,
						expected <= 1.0 ? "hits" : "misses");
		}
		return true;
	}
	if (r.best != expected)
	{
		ORACLE_FAIL(o, "closest ray hit %.17g, brute force %.17g", r.best, expected);
	}
	return true;
}

static inline bool OracleRebuild(Oracle* o)
{
	if (o->dim == 2)
	{
		cd2BroadPhase_Rebuild(o->bp2);
	}
	else
	{
		cd3BroadPhase_Rebuild(o->bp3);
	}
	return true;
}

static inline cdBroadPhaseStats OracleStats(const Oracle* o)
{
	return o->dim == 2 ? cd2BroadPhase_GetStats(o->bp2) : cd3BroadPhase_GetStats(o->bp3);
}

#endif
