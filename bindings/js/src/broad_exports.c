/* collide for JavaScript: the broadphase structures behind BroadPhase2 / BroadPhase3.
 *
 * A handle wraps a cd2BroadPhase or cd3BroadPhase with what JavaScript needs on top: a table of
 * live proxy ids (so a stale or made-up id from JavaScript is refused instead of reaching the
 * structure) and growable result arrays (pairs, query hits, ray hits) that JavaScript reads in
 * one piece. Boxes are passed as the library's own layouts: cd2Aabb = 4 floats (min x y, max x y),
 * cd3Aabb = 6 floats. */
#include <collide/collide.h>

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Outside wasm (tests/js_exports: the layer under the native sanitizers) plain functions. */
#if defined(__wasm__)
#define EXPORT(name) __attribute__((export_name(name)))
#else
#define EXPORT(name)
#endif

typedef struct cdjsBroad
{
	int dim;
	cd2BroadPhase* bp2;
	cd3BroadPhase* bp3;
	uint8_t* live;
	int liveCapacity;
	int32_t* ints; /* pairs (2 per pair) or ids */
	int intCount, intCapacity;
	float* fractions;
	int fractionCapacity;
	int outOfMemory;
	cd3Ray ray3;
	cd2Ray ray2;
} cdjsBroad;

static int growLive(cdjsBroad* h, int id)
{
	if (id < h->liveCapacity)
	{
		return 1;
	}
	int capacity = h->liveCapacity > 0 ? h->liveCapacity : 64;
	while (capacity <= id)
	{
		capacity *= 2;
	}
	uint8_t* live = realloc(h->live, (size_t)capacity);
	if (live == NULL)
	{
		return 0;
	}
	memset(live + h->liveCapacity, 0, (size_t)(capacity - h->liveCapacity));
	h->live = live;
	h->liveCapacity = capacity;
	return 1;
}

static int isLive(const cdjsBroad* h, int id)
{
	return id >= 0 && id < h->liveCapacity && h->live[id] != 0;
}

static void pushInt(cdjsBroad* h, int32_t value)
{
	if (h->intCount == h->intCapacity)
	{
		int capacity = h->intCapacity > 0 ? 2 * h->intCapacity : 256;
		int32_t* ints = realloc(h->ints, (size_t)capacity * sizeof *ints);
		if (ints == NULL)
		{
			h->outOfMemory = 1;
			return;
		}
		h->ints = ints;
		h->intCapacity = capacity;
	}
	h->ints[h->intCount++] = value;
}

/* Creates a broadphase. def: type, margin, displacementMultiplier, cellSize, capacity, bounds
 * (4 or 6 floats); negative margin etc. mean "default". Returns the handle or NULL (IO-less: the
 * cdResult goes to *outResult). */
EXPORT("bpCreate")
cdjsBroad* cdjsBroadCreate(int dim, int type, float margin, float displacementMultiplier, float cellSize,
						   int capacity, const float* bounds, int* outResult)
{
	*outResult = CD_OK;
	cdjsBroad* h = calloc(1, sizeof *h);
	if (h == NULL)
	{
		*outResult = CD_ERROR_OUT_OF_MEMORY;
		return NULL;
	}
	h->dim = dim;
	cdResult result;
	if (dim == 2)
	{
		cd2BroadPhaseDef def = cd2DefaultBroadPhaseDef();
		def.type = (cdBroadPhaseType)type;
		if (margin >= 0.0f)
			def.margin = margin;
		if (displacementMultiplier >= 0.0f)
			def.displacementMultiplier = displacementMultiplier;
		if (cellSize >= 0.0f)
			def.cellSize = cellSize;
		if (capacity >= 0)
			def.capacity = capacity;
		if (bounds != NULL)
			def.bounds = (cd2Aabb){{bounds[0], bounds[1]}, {bounds[2], bounds[3]}};
		result = cd2BroadPhase_Create(&def, &h->bp2);
	}
	else
	{
		cd3BroadPhaseDef def = cd3DefaultBroadPhaseDef();
		def.type = (cdBroadPhaseType)type;
		if (margin >= 0.0f)
			def.margin = margin;
		if (displacementMultiplier >= 0.0f)
			def.displacementMultiplier = displacementMultiplier;
		if (cellSize >= 0.0f)
			def.cellSize = cellSize;
		if (capacity >= 0)
			def.capacity = capacity;
		if (bounds != NULL)
			def.bounds = (cd3Aabb){{bounds[0], bounds[1], bounds[2]}, {bounds[3], bounds[4], bounds[5]}};
		result = cd3BroadPhase_Create(&def, &h->bp3);
	}
	if (result != CD_OK)
	{
		free(h);
		*outResult = (int)result;
		return NULL;
	}
	return h;
}

EXPORT("bpDestroy") void cdjsBroadDestroy(cdjsBroad* h)
{
	if (h == NULL)
	{
		return;
	}
	if (h->bp2 != NULL)
		cd2BroadPhase_Destroy(h->bp2);
	if (h->bp3 != NULL)
		cd3BroadPhase_Destroy(h->bp3);
	free(h->live);
	free(h->ints);
	free(h->fractions);
	free(h);
}

static cd2Aabb box2(const float* p)
{
	return (cd2Aabb){{p[0], p[1]}, {p[2], p[3]}};
}

static cd3Aabb box3(const float* p)
{
	return (cd3Aabb){{p[0], p[1], p[2]}, {p[3], p[4], p[5]}};
}

/* Returns the new id, or -1 for an invalid box, -2 when out of memory. */
EXPORT("bpCreateProxy") int cdjsBroadCreateProxy(cdjsBroad* h, const float* aabb)
{
	int id = h->dim == 2 ? cd2BroadPhase_CreateProxy(h->bp2, box2(aabb), 0)
						 : cd3BroadPhase_CreateProxy(h->bp3, box3(aabb), 0);
	if (id < 0)
	{
		return -1;
	}
	if (!growLive(h, id))
	{
		if (h->dim == 2)
			cd2BroadPhase_DestroyProxy(h->bp2, id);
		else
			cd3BroadPhase_DestroyProxy(h->bp3, id);
		return -2;
	}
	h->live[id] = 1;
	return id;
}

/* Creates `count` proxies from consecutive boxes; outIds[i] = id or -1. Returns the number made. */
EXPORT("bpCreateProxies")
int cdjsBroadCreateProxies(cdjsBroad* h, const float* boxes, int count, int32_t* outIds)
{
	int made =
		h->dim == 2
			? cd2BroadPhase_CreateProxies(h->bp2, (const cd2Aabb*)(const void*)boxes, NULL, count, outIds)
			: cd3BroadPhase_CreateProxies(h->bp3, (const cd3Aabb*)(const void*)boxes, NULL, count, outIds);
	for (int i = 0; i < count; ++i)
	{
		int id = outIds[i];
		if (id < 0)
		{
			continue;
		}
		if (!growLive(h, id))
		{
			if (h->dim == 2)
				cd2BroadPhase_DestroyProxy(h->bp2, id);
			else
				cd3BroadPhase_DestroyProxy(h->bp3, id);
			outIds[i] = -1;
			--made;
			continue;
		}
		h->live[id] = 1;
	}
	return made;
}

/* 1 when destroyed, 0 when the id is not a live proxy. */
EXPORT("bpDestroyProxy") int cdjsBroadDestroyProxy(cdjsBroad* h, int id)
{
	if (!isLive(h, id))
	{
		return 0;
	}
	if (h->dim == 2)
		cd2BroadPhase_DestroyProxy(h->bp2, id);
	else
		cd3BroadPhase_DestroyProxy(h->bp3, id);
	h->live[id] = 0;
	return 1;
}

EXPORT("bpIsLive") int cdjsBroadIsLive(const cdjsBroad* h, int id)
{
	return isLive(h, id);
}

/* 1 moved (fat box changed), 0 unchanged, -1 not a live id. displacement may be NULL. */
EXPORT("bpMoveProxy")
int cdjsBroadMoveProxy(cdjsBroad* h, int id, const float* aabb, const float* displacement)
{
	if (!isLive(h, id))
	{
		return -1;
	}
	if (h->dim == 2)
	{
		cd2Vec d = displacement != NULL ? (cd2Vec){displacement[0], displacement[1]} : (cd2Vec){0.0f, 0.0f};
		return cd2BroadPhase_MoveProxy(h->bp2, id, box2(aabb), d) ? 1 : 0;
	}
	cd3Vec d = displacement != NULL ? (cd3Vec){displacement[0], displacement[1], displacement[2]}
									: (cd3Vec){0.0f, 0.0f, 0.0f};
	return cd3BroadPhase_MoveProxy(h->bp3, id, box3(aabb), d) ? 1 : 0;
}

/* Returns how many fat boxes changed, or -(i + 1) when ids[i] is not live (nothing moved then). */
EXPORT("bpMoveProxies")
int cdjsBroadMoveProxies(cdjsBroad* h, int count, const int32_t* ids, const float* boxes,
						 const float* displacements)
{
	for (int i = 0; i < count; ++i)
	{
		if (!isLive(h, ids[i]))
		{
			return -(i + 1);
		}
	}
	if (h->dim == 2)
	{
		return cd2BroadPhase_MoveProxies(h->bp2, count, ids, (const cd2Aabb*)(const void*)boxes,
										 (const cd2Vec*)(const void*)displacements, NULL);
	}
	return cd3BroadPhase_MoveProxies(h->bp3, count, ids, (const cd3Aabb*)(const void*)boxes,
									 (const cd3Vec*)(const void*)displacements, NULL);
}

static void collectPair(int proxyA, int proxyB, uint64_t userDataA, uint64_t userDataB, void* context)
{
	(void)userDataA;
	(void)userDataB;
	cdjsBroad* h = context;
	pushInt(h, proxyA);
	pushInt(h, proxyB);
}

/* Pairs into the int array (2 per pair); returns the pair count, or -1 when out of memory. */
EXPORT("bpUpdatePairs") int cdjsBroadUpdatePairs(cdjsBroad* h, int all)
{
	h->intCount = 0;
	h->outOfMemory = 0;
	if (h->dim == 2)
	{
		if (all)
			cd2BroadPhase_FindAllPairs(h->bp2, collectPair, h);
		else
			cd2BroadPhase_UpdatePairs(h->bp2, collectPair, h);
	}
	else
	{
		if (all)
			cd3BroadPhase_FindAllPairs(h->bp3, collectPair, h);
		else
			cd3BroadPhase_UpdatePairs(h->bp3, collectPair, h);
	}
	return h->outOfMemory ? -1 : h->intCount / 2;
}

EXPORT("bpInts") const int32_t* cdjsBroadInts(const cdjsBroad* h)
{
	return h->ints;
}

EXPORT("bpFractions") const float* cdjsBroadFractions(const cdjsBroad* h)
{
	return h->fractions;
}

static bool collectId(int proxyId, uint64_t userData, void* context)
{
	(void)userData;
	cdjsBroad* h = context;
	pushInt(h, proxyId);
	return h->outOfMemory == 0;
}

/* Ids of the proxies whose fat box overlaps the box; returns the count, -1 when out of memory. */
EXPORT("bpQuery") int cdjsBroadQuery(cdjsBroad* h, const float* aabb)
{
	h->intCount = 0;
	h->outOfMemory = 0;
	if (h->dim == 2)
		cd2BroadPhase_Query(h->bp2, box2(aabb), collectId, h);
	else
		cd3BroadPhase_Query(h->bp3, box3(aabb), collectId, h);
	return h->outOfMemory ? -1 : h->intCount;
}

static float rayHit2(cd2Ray ray, float maxFraction, int proxyId, uint64_t userData, void* context)
{
	(void)ray;
	(void)userData;
	cdjsBroad* h = context;
	pushInt(h, proxyId);
	return h->outOfMemory ? 0.0f : maxFraction;
}

static float rayHit3(cd3Ray ray, float maxFraction, int proxyId, uint64_t userData, void* context)
{
	(void)ray;
	(void)userData;
	cdjsBroad* h = context;
	pushInt(h, proxyId);
	return h->outOfMemory ? 0.0f : maxFraction;
}

/* Ray cast against the fat boxes: the ids of every proxy the ray meets, sorted by the fraction at
 * which the ray enters its fat box (from cd2RaycastAabb / cd3RaycastAabb; 0 when it starts
 * inside), the fractions alongside. Returns the count, -1 when out of memory. */
EXPORT("bpRayCast") int cdjsBroadRayCast(cdjsBroad* h, const float* ray)
{
	h->intCount = 0;
	h->outOfMemory = 0;
	if (h->dim == 2)
	{
		cd2Ray r = {{ray[0], ray[1]}, {ray[2], ray[3]}};
		cd2BroadPhase_RayCast(h->bp2, r, rayHit2, h);
	}
	else
	{
		cd3Ray r = {{ray[0], ray[1], ray[2]}, {ray[3], ray[4], ray[5]}};
		cd3BroadPhase_RayCast(h->bp3, r, rayHit3, h);
	}
	if (h->outOfMemory)
	{
		return -1;
	}
	if (h->intCount > h->fractionCapacity)
	{
		float* fractions = realloc(h->fractions, (size_t)h->intCount * sizeof *fractions);
		if (fractions == NULL)
		{
			return -1;
		}
		h->fractions = fractions;
		h->fractionCapacity = h->intCount;
	}
	/* Entry fractions, keeping only the boxes the ray really meets, then an insertion sort (the
	 * structures visit near boxes first, so the list is nearly sorted). */
	int kept = 0;
	for (int i = 0; i < h->intCount; ++i)
	{
		int id = h->ints[i];
		float fraction = -1.0f;
		if (h->dim == 2)
		{
			cd2Ray r = {{ray[0], ray[1]}, {ray[2], ray[3]}};
			cd2Aabb fat = cd2BroadPhase_GetFatAabb(h->bp2, id);
			cd2RayHit hit;
			if (cd2PointInAabb(r.origin, fat))
				fraction = 0.0f;
			else if (cd2RaycastAabb(fat, r, &hit))
				fraction = hit.fraction;
		}
		else
		{
			cd3Ray r = {{ray[0], ray[1], ray[2]}, {ray[3], ray[4], ray[5]}};
			cd3Aabb fat = cd3BroadPhase_GetFatAabb(h->bp3, id);
			cd3RayHit hit;
			if (cd3PointInAabb(r.origin, fat))
				fraction = 0.0f;
			else if (cd3RaycastAabb(fat, r, &hit))
				fraction = hit.fraction;
		}
		if (fraction < 0.0f)
		{
			continue;
		}
		int j = kept++;
		while (j > 0 &&
			   (h->fractions[j - 1] > fraction || (h->fractions[j - 1] == fraction && h->ints[j - 1] > id)))
		{
			h->fractions[j] = h->fractions[j - 1];
			h->ints[j] = h->ints[j - 1];
			--j;
		}
		h->fractions[j] = fraction;
		h->ints[j] = id;
	}
	h->intCount = kept;
	return kept;
}

/* Writes the fat box of a live proxy to out; returns 0 for a stale id. */
EXPORT("bpFatAabb") int cdjsBroadFatAabb(const cdjsBroad* h, int id, float* out)
{
	if (!isLive(h, id))
	{
		return 0;
	}
	if (h->dim == 2)
	{
		cd2Aabb b = cd2BroadPhase_GetFatAabb(h->bp2, id);
		out[0] = b.min.x, out[1] = b.min.y, out[2] = b.max.x, out[3] = b.max.y;
	}
	else
	{
		cd3Aabb b = cd3BroadPhase_GetFatAabb(h->bp3, id);
		out[0] = b.min.x, out[1] = b.min.y, out[2] = b.min.z;
		out[3] = b.max.x, out[4] = b.max.y, out[5] = b.max.z;
	}
	return 1;
}

EXPORT("bpProxyCount") int cdjsBroadProxyCount(const cdjsBroad* h)
{
	return h->dim == 2 ? cd2BroadPhase_GetProxyCount(h->bp2) : cd3BroadPhase_GetProxyCount(h->bp3);
}

EXPORT("bpRebuild") void cdjsBroadRebuild(cdjsBroad* h)
{
	if (h->dim == 2)
		cd2BroadPhase_Rebuild(h->bp2);
	else
		cd3BroadPhase_Rebuild(h->bp3);
}

EXPORT("bpValidate") int cdjsBroadValidate(const cdjsBroad* h)
{
	return (h->dim == 2 ? cd2BroadPhase_Validate(h->bp2) : cd3BroadPhase_Validate(h->bp3)) ? 1 : 0;
}

/* out: proxyCount, nodeCount, height, memoryBytes, sahCost. */
EXPORT("bpStats") void cdjsBroadStats(const cdjsBroad* h, double* out)
{
	cdBroadPhaseStats s = h->dim == 2 ? cd2BroadPhase_GetStats(h->bp2) : cd3BroadPhase_GetStats(h->bp3);
	out[0] = s.proxyCount;
	out[1] = s.nodeCount;
	out[2] = s.height;
	out[3] = (double)s.memoryBytes;
	out[4] = s.sahCost;
}
