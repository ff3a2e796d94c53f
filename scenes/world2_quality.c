#include "world2_quality.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Step counts and sub-steps of Box2D v3's benchmark/main.c for its scenes; the pyramids of bases 20
 * and 40 and the card house stand 10 s after 1 s of settling, large_pyramid 5.3 s after 3 s. */
static const World2SceneInfo world2Scenes[WORLD2_SCENE_COUNT] = {
	{"pyramid_20", 660, 4, false, 60},	  {"pyramid_40", 660, 4, false, 60},
	{"large_pyramid", 500, 4, true, 180}, {"many_pyramids", 200, 4, true, 60},
	{"joint_grid", 500, 4, true, 0},	  {"rain", 1000, 4, true, 0},
	{"smash", 300, 4, true, 0},			  {"spinner", 500, 4, true, 0},
	{"tumbler", 750, 4, true, 0},		  {"card_house", 660, 4, false, 60},
	{"ramp", 120, 4, false, 0},			  {"bullets", 120, 4, false, 0},
	{"side_scroller", 900, 4, false, 0},  {"slingshot", 600, 4, false, 0},
	{"chains", 600, 4, false, 0},
};

const World2SceneInfo* world2SceneInfo(World2SceneId id)
{
	if ((int)id < 0 || id >= WORLD2_SCENE_COUNT)
	{
		return NULL;
	}
	return &world2Scenes[id];
}

World2SceneId world2SceneFind(const char* name)
{
	for (int i = 0; i < WORLD2_SCENE_COUNT; ++i)
	{
		if (name != NULL && strcmp(world2Scenes[i].name, name) == 0)
		{
			return (World2SceneId)i;
		}
	}
	return WORLD2_SCENE_COUNT;
}

bool world2SnapshotAdd(World2Snapshot* snapshot, const World2Body* body)
{
	if (snapshot->count == snapshot->capacity)
	{
		int capacity = snapshot->capacity < 64 ? 64 : 2 * snapshot->capacity;
		World2Body* bodies = (World2Body*)realloc(snapshot->bodies, (size_t)capacity * sizeof(World2Body));
		if (bodies == NULL)
		{
			return false;
		}
		snapshot->bodies = bodies;
		snapshot->capacity = capacity;
	}
	snapshot->bodies[snapshot->count++] = *body;
	return true;
}

void world2SnapshotClear(World2Snapshot* snapshot)
{
	snapshot->count = 0;
}

void world2SnapshotFree(World2Snapshot* snapshot)
{
	free(snapshot->bodies);
	snapshot->bodies = NULL;
	snapshot->count = 0;
	snapshot->capacity = 0;
}

static bool bodyFinite(const World2Body* b)
{
	return isfinite(b->x) && isfinite(b->y) && isfinite(b->angle) && isfinite(b->vx) && isfinite(b->vy) &&
		   isfinite(b->w);
}

static int countNonFinite(const World2Snapshot* s)
{
	int n = 0;
	for (int i = 0; i < s->count; ++i)
	{
		n += bodyFinite(&s->bodies[i]) ? 0 : 1;
	}
	return n;
}

static int compareKeys(const void* a, const void* b)
{
	uint64_t ka = ((const World2Body*)a)->key;
	uint64_t kb = ((const World2Body*)b)->key;
	return ka < kb ? -1 : (ka > kb ? 1 : 0);
}

/* The body of the end snapshot with the key of the start body (sorted copy of end). */
static const World2Body* findKey(const World2Body* sorted, int count, uint64_t key)
{
	int lo = 0, hi = count - 1;
	while (lo <= hi)
	{
		int mid = (lo + hi) / 2;
		if (sorted[mid].key == key)
		{
			return &sorted[mid];
		}
		if (sorted[mid].key < key)
		{
			lo = mid + 1;
		}
		else
		{
			hi = mid - 1;
		}
	}
	return NULL;
}

static World2Body* sortedCopy(const World2Snapshot* s)
{
	World2Body* c = (World2Body*)malloc((size_t)(s->count > 0 ? s->count : 1) * sizeof(World2Body));
	if (c != NULL && s->count > 0)
	{
		memcpy(c, s->bodies, (size_t)s->count * sizeof(World2Body));
		qsort(c, (size_t)s->count, sizeof(World2Body), compareKeys);
	}
	return c;
}

static double displacement(const World2Body* a, const World2Body* b)
{
	return hypot(b->x - a->x, b->y - a->y);
}

static World2Quality fail(const char* text)
{
	World2Quality q;
	memset(&q, 0, sizeof(q));
	q.computed = true;
	q.pass = false;
	snprintf(q.text, sizeof(q.text), "%s", text);
	return q;
}

/* Apexes: dynamic boxes with no dynamic body resting on them at the start (nothing within 0.6 m
 * sideways and 0.6-1.4 box heights above). Worst apex displacement < 2 cm. */
static World2Quality checkPyramids(const World2Snapshot* start, const World2Snapshot* end,
								   const World2Body* sortedEnd)
{
	World2Quality q;
	memset(&q, 0, sizeof(q));
	q.computed = true;
	q.limit = 0.02;
	int apexCount = 0, fallen = 0, dynamicCount = 0;
	double worst = 0.0, worstDx = 0.0, worstDy = 0.0;
	/* Bucket the dynamic bodies by rows of 1 m for the "resting on" search. */
	for (int i = 0; i < start->count; ++i)
	{
		const World2Body* b = &start->bodies[i];
		if (b->type != WORLD2_DYNAMIC)
		{
			continue;
		}
		++dynamicCount;
		const World2Body* e = findKey(sortedEnd, end->count, b->key);
		if (e == NULL || !bodyFinite(e))
		{
			return fail("a box vanished or is not finite");
		}
		double d = displacement(b, e);
		if (d > 0.1)
		{
			++fallen;
		}
		bool covered = false;
		for (int j = 0; j < start->count && !covered; ++j)
		{
			const World2Body* o = &start->bodies[j];
			double dy = o->y - b->y;
			covered =
				(j != i && o->type == WORLD2_DYNAMIC && dy > 0.6 && dy < 1.4 && fabs(o->x - b->x) < 0.6);
		}
		if (!covered)
		{
			++apexCount;
			if (d > worst)
			{
				worst = d;
				worstDx = e->x - b->x;
				worstDy = e->y - b->y;
			}
		}
	}
	q.value = worst;
	q.pass = apexCount > 0 && worst < q.limit;
	snprintf(q.text, sizeof(q.text),
			 "worst of %d apexes moved %.2f cm (x %+.2f, y %+.2f); %d of %d boxes moved > 10 cm", apexCount,
			 100.0 * worst, 100.0 * worstDx, 100.0 * worstDy, fallen, dynamicCount);
	return q;
}

/* Pyramids need the "resting on" search over all boxes: quadratic, so it uses a grid by rows for
 * the big scenes. Rows are 1 m apart (unit boxes), columns 0.5 m. */
static World2Quality checkPyramidsFast(const World2Snapshot* start, const World2Snapshot* end,
									   const World2Body* sortedEnd)
{
	if (start->count < 2000)
	{
		return checkPyramids(start, end, sortedEnd);
	}
	/* Hash each dynamic body by its half-metre cell; a body is covered when a body lies in the
	 * cells above it (row + 2, columns -1..+1). */
	size_t tableSize = 1;
	while (tableSize < (size_t)start->count * 4u)
	{
		tableSize <<= 1;
	}
	int* table = (int*)malloc(tableSize * sizeof(int));
	if (table == NULL)
	{
		return fail("out of memory");
	}
	for (size_t i = 0; i < tableSize; ++i)
	{
		table[i] = -1;
	}
#define W2_CELL(v) ((long long)floor((v) / 0.5))
#define W2_HASH(cx, cy)                                                                                      \
	((size_t)(((uint64_t)(cx)*0x9E3779B97F4A7C15ull) ^ ((uint64_t)(cy)*0xC2B2AE3D27D4EB4Full)))
	for (int i = 0; i < start->count; ++i)
	{
		const World2Body* b = &start->bodies[i];
		if (b->type != WORLD2_DYNAMIC)
		{
			continue;
		}
		size_t h = W2_HASH(W2_CELL(b->x), W2_CELL(b->y)) & (tableSize - 1);
		while (table[h] != -1)
		{
			h = (h + 1) & (tableSize - 1);
		}
		table[h] = i;
	}
	World2Quality q;
	memset(&q, 0, sizeof(q));
	q.computed = true;
	q.limit = 0.02;
	int apexCount = 0, fallen = 0, dynamicCount = 0;
	double worst = 0.0, worstDx = 0.0, worstDy = 0.0;
	for (int i = 0; i < start->count; ++i)
	{
		const World2Body* b = &start->bodies[i];
		if (b->type != WORLD2_DYNAMIC)
		{
			continue;
		}
		++dynamicCount;
		const World2Body* e = findKey(sortedEnd, end->count, b->key);
		if (e == NULL || !bodyFinite(e))
		{
			free(table);
			return fail("a box vanished or is not finite");
		}
		double d = displacement(b, e);
		fallen += d > 0.1 ? 1 : 0;
		bool covered = false;
		long long cx = W2_CELL(b->x), cy = W2_CELL(b->y);
		for (long long dyc = 1; dyc <= 3 && !covered; ++dyc)
		{
			for (long long dxc = -2; dxc <= 2 && !covered; ++dxc)
			{
				size_t h = W2_HASH(cx + dxc, cy + dyc) & (tableSize - 1);
				while (table[h] != -1 && !covered)
				{
					const World2Body* o = &start->bodies[table[h]];
					double dy = o->y - b->y;
					covered = dy > 0.6 && dy < 1.4 && fabs(o->x - b->x) < 0.6;
					h = (h + 1) & (tableSize - 1);
				}
			}
		}
		if (!covered)
		{
			++apexCount;
			if (d > worst)
			{
				worst = d;
				worstDx = e->x - b->x;
				worstDy = e->y - b->y;
			}
		}
	}
#undef W2_CELL
#undef W2_HASH
	free(table);
	q.value = worst;
	q.pass = apexCount > 0 && worst < q.limit;
	snprintf(q.text, sizeof(q.text),
			 "worst of %d apexes moved %.2f cm (x %+.2f, y %+.2f); %d of %d boxes moved > 10 cm", apexCount,
			 100.0 * worst, 100.0 * worstDx, 100.0 * worstDy, fallen, dynamicCount);
	return q;
}

/* Joint grid: bodies start on the integer grid (k, -i), k, i in [0, n); joints link neighbours
 * at (0, -0.5)/(0, 0.5) (vertical) and (0.5, 0)/(-0.5, 0) (horizontal) in the bodies' frames. */
static World2Quality checkJointGrid(const World2Snapshot* start, const World2Body* sortedEnd, int endCount)
{
	int n = (int)floor(sqrt((double)start->count) + 0.5);
	if (n < 2 || n * n != start->count)
	{
		return fail("not a square grid of bodies");
	}
	const World2Body** grid = (const World2Body**)calloc((size_t)(n * n), sizeof(World2Body*));
	if (grid == NULL)
	{
		return fail("out of memory");
	}
	for (int j = 0; j < start->count; ++j)
	{
		const World2Body* b = &start->bodies[j];
		int k = (int)floor(b->x + 0.5), i = (int)floor(-b->y + 0.5);
		if (k < 0 || k >= n || i < 0 || i >= n)
		{
			free(grid);
			return fail("a body is off the grid");
		}
		grid[k * n + i] = findKey(sortedEnd, endCount, b->key);
	}
	World2Quality q;
	memset(&q, 0, sizeof(q));
	q.computed = true;
	q.limit = 0.5;
	double worst = 0.0, lowest = 0.0;
	for (int k = 0; k < n; ++k)
	{
		for (int i = 0; i < n; ++i)
		{
			const World2Body* b = grid[k * n + i];
			if (b == NULL || !bodyFinite(b))
			{
				free(grid);
				return fail("a body vanished or is not finite");
			}
			lowest = b->y < lowest ? b->y : lowest;
			for (int side = 0; side < 2; ++side)
			{
				const World2Body* a = NULL;
				double ax = 0, ay = 0, bx = 0, by = 0;
				if (side == 0 && i > 0)
				{
					a = grid[k * n + i - 1];
					ay = -0.5;
					by = 0.5;
				}
				else if (side == 1 && k > 0)
				{
					a = grid[(k - 1) * n + i];
					ax = 0.5;
					bx = -0.5;
				}
				if (a == NULL)
				{
					continue;
				}
				double pax = a->x + cos(a->angle) * ax - sin(a->angle) * ay;
				double pay = a->y + sin(a->angle) * ax + cos(a->angle) * ay;
				double pbx = b->x + cos(b->angle) * bx - sin(b->angle) * by;
				double pby = b->y + sin(b->angle) * bx + cos(b->angle) * by;
				double gap = hypot(pax - pbx, pay - pby);
				worst = gap > worst ? gap : worst;
			}
		}
	}
	free(grid);
	q.value = worst;
	q.pass = worst < q.limit;
	snprintf(q.text, sizeof(q.text), "%dx%d grid hangs, lowest body at y = %.1f m; largest joint gap %.2f cm",
			 n, n, lowest, 100.0 * worst);
	return q;
}

static World2Quality checkRain(const World2Snapshot* end)
{
	World2Quality q;
	memset(&q, 0, sizeof(q));
	q.computed = true;
	q.limit = -1.0;
	int below = 0, dynamicCount = 0;
	double lowest = 1e30;
	for (int i = 0; i < end->count; ++i)
	{
		const World2Body* b = &end->bodies[i];
		if (b->type != WORLD2_DYNAMIC)
		{
			continue;
		}
		++dynamicCount;
		lowest = b->y < lowest ? b->y : lowest;
		below += (b->y < q.limit || !bodyFinite(b)) ? 1 : 0;
	}
	q.value = lowest;
	q.pass = dynamicCount > 0 && below == 0;
	snprintf(q.text, sizeof(q.text), "%d ragdoll bodies, %d below the lowest floor, lowest at y = %.2f m",
			 dynamicCount, below, lowest);
	return q;
}

static World2Quality checkSmash(const World2Snapshot* start, const World2Snapshot* end)
{
	double p0x = 0, p0y = 0, p1x = 0, p1y = 0;
	for (int i = 0; i < start->count; ++i)
	{
		p0x += start->bodies[i].mass * start->bodies[i].vx;
		p0y += start->bodies[i].mass * start->bodies[i].vy;
	}
	int moving = 0;
	for (int i = 0; i < end->count; ++i)
	{
		p1x += end->bodies[i].mass * end->bodies[i].vx;
		p1y += end->bodies[i].mass * end->bodies[i].vy;
		moving += hypot(end->bodies[i].vx, end->bodies[i].vy) > 0.1 ? 1 : 0;
	}
	World2Quality q;
	memset(&q, 0, sizeof(q));
	q.computed = true;
	q.limit = 0.01;
	double p0 = hypot(p0x, p0y);
	q.value = p0 > 0.0 ? hypot(p1x - p0x, p1y - p0y) / p0 : 1.0;
	q.pass = isfinite(q.value) && q.value < q.limit;
	snprintf(q.text, sizeof(q.text), "momentum kept within %.3f%%; %d of %d bodies moving > 0.1 m/s",
			 100.0 * q.value, moving, end->count);
	return q;
}

static World2Quality checkSpinner(const World2Snapshot* end)
{
	World2Quality q;
	memset(&q, 0, sizeof(q));
	q.computed = true;
	q.limit = 40.0;
	int escaped = 0, dynamicCount = 0;
	double farthest = 0.0, spinnerAngle = 0.0, spinnerMass = 0.0;
	for (int i = 0; i < end->count; ++i)
	{
		const World2Body* b = &end->bodies[i];
		if (b->type != WORLD2_DYNAMIC)
		{
			continue;
		}
		if (b->mass > spinnerMass)
		{
			spinnerMass = b->mass;
			spinnerAngle = b->angle;
		}
		++dynamicCount;
		double r = hypot(b->x, b->y - 32.0);
		farthest = r > farthest ? r : farthest;
		escaped += (r > q.limit || !bodyFinite(b)) ? 1 : 0;
	}
	q.value = farthest;
	q.pass = dynamicCount > 0 && escaped == 0;
	snprintf(q.text, sizeof(q.text),
			 "%d bodies, %d escaped the ring, farthest %.2f m from its centre; spinner at %.2f rad",
			 dynamicCount, escaped, farthest, spinnerAngle);
	return q;
}

static World2Quality checkTumbler(const World2Snapshot* end)
{
	const World2Body* drum = NULL;
	for (int i = 0; i < end->count; ++i)
	{
		const World2Body* b = &end->bodies[i];
		if (b->type == WORLD2_DYNAMIC && (drum == NULL || b->mass > drum->mass))
		{
			drum = b;
		}
	}
	if (drum == NULL || !bodyFinite(drum))
	{
		return fail("no tumbler body");
	}
	World2Quality q;
	memset(&q, 0, sizeof(q));
	q.computed = true;
	q.limit = 9.5;
	int escaped = 0, count = 0;
	double worst = 0.0;
	double c = cos(drum->angle), s = sin(drum->angle);
	for (int i = 0; i < end->count; ++i)
	{
		const World2Body* b = &end->bodies[i];
		if (b == drum || b->type != WORLD2_DYNAMIC)
		{
			continue;
		}
		++count;
		double dx = b->x - drum->x, dy = b->y - drum->y;
		double lx = c * dx + s * dy, ly = -s * dx + c * dy;
		double m = fabs(lx) > fabs(ly) ? fabs(lx) : fabs(ly);
		worst = m > worst ? m : worst;
		escaped += (m > q.limit || !bodyFinite(b)) ? 1 : 0;
	}
	q.value = worst;
	q.pass = count > 0 && escaped == 0;
	snprintf(q.text, sizeof(q.text),
			 "%d boxes, %d escaped the drum (turned %.2f rad), outermost at %.2f m of 9.5", count, escaped,
			 drum->angle, worst);
	return q;
}

/* The top body at the start (highest y) moved less than limit. */
static World2Quality checkTop(const World2Snapshot* start, const World2Body* sortedEnd, int endCount,
							  double limit, const char* what)
{
	const World2Body* top = NULL;
	for (int i = 0; i < start->count; ++i)
	{
		const World2Body* b = &start->bodies[i];
		if (b->type == WORLD2_DYNAMIC && (top == NULL || b->y > top->y))
		{
			top = b;
		}
	}
	const World2Body* e = top != NULL ? findKey(sortedEnd, endCount, top->key) : NULL;
	if (e == NULL || !bodyFinite(e))
	{
		return fail("no top body at the end");
	}
	World2Quality q;
	memset(&q, 0, sizeof(q));
	q.computed = true;
	q.limit = limit;
	q.value = displacement(top, e);
	q.pass = q.value < limit;
	snprintf(q.text, sizeof(q.text), "%s moved %.2f cm (from y = %.3f m to %.3f m)", what, 100.0 * q.value,
			 top->y, e->y);
	return q;
}

static World2Quality checkRamp(const World2Snapshot* start, const World2Body* sortedEnd, int endCount,
							   double time)
{
	/* Layout of scenes/world2_scenes.c: the gentle ramp's block starts at x < 0, the steep one's at
	 * x > 0; both dynamic bodies are the only ones of the scene. */
	const double g = 10.0, friction = WORLD2_RAMP_FRICTION;
	const double steep = WORLD2_RAMP_STEEP_DEGREES * 3.14159265358979323846 / 180.0;
	const World2Body *gentle0 = NULL, *steep0 = NULL;
	for (int i = 0; i < start->count; ++i)
	{
		const World2Body* b = &start->bodies[i];
		if (b->type == WORLD2_DYNAMIC)
		{
			if (b->x < 0.0)
			{
				gentle0 = b;
			}
			else
			{
				steep0 = b;
			}
		}
	}
	const World2Body* gentle1 = gentle0 != NULL ? findKey(sortedEnd, endCount, gentle0->key) : NULL;
	const World2Body* steep1 = steep0 != NULL ? findKey(sortedEnd, endCount, steep0->key) : NULL;
	if (gentle1 == NULL || steep1 == NULL || !bodyFinite(gentle1) || !bodyFinite(steep1) || time <= 0.0)
	{
		return fail("a ramp block is missing or not finite");
	}
	double rest = displacement(gentle0, gentle1);
	double slid = displacement(steep0, steep1);
	double expected = g * (sin(steep) - friction * cos(steep));
	double measured = 2.0 * slid / (time * time);
	World2Quality q;
	memset(&q, 0, sizeof(q));
	q.computed = true;
	q.limit = 0.02;
	q.value = fabs(measured / expected - 1.0);
	q.pass = rest < 0.01 && q.value < q.limit;
	snprintf(
		q.text, sizeof(q.text),
		"gentle-ramp block moved %.2f cm; steep-ramp block slid at %.3f m/s^2 (expected %.3f, error %.2f%%)",
		100.0 * rest, measured, expected, 100.0 * q.value);
	return q;
}

static World2Quality checkBullets(const World2Snapshot* end)
{
	World2Quality q;
	memset(&q, 0, sizeof(q));
	q.computed = true;
	q.limit = WORLD2_BULLET_WALL_X;
	int crossed = 0, count = 0;
	double farthest = -1e30;
	for (int i = 0; i < end->count; ++i)
	{
		const World2Body* b = &end->bodies[i];
		if (b->type != WORLD2_DYNAMIC)
		{
			continue;
		}
		++count;
		farthest = b->x > farthest ? b->x : farthest;
		crossed += (b->x > q.limit || !bodyFinite(b)) ? 1 : 0;
	}
	q.value = farthest;
	q.pass = count > 0 && crossed == 0;
	snprintf(q.text, sizeof(q.text), "%d bullets, %d crossed the wall, farthest at x = %.3f m", count,
			 crossed, farthest);
	return q;
}

int world2ChainLinks(int chain)
{
	static const int links[WORLD2_CHAIN_COUNT] = {2, 3, 4, 5, 6, 7, 8, 10, 12};
	return chain >= 0 && chain < WORLD2_CHAIN_COUNT ? links[chain] : 0;
}

/* A link's moment of inertia about its centre over its mass: the capsule as a rectangle 2r x L
 * and two half discs, each half disc moved from its own centroid (4r / 3 pi from its flat side)
 * to its place at L/2 beyond the centre. */
static double chainLinkInertiaPerMass(void)
{
	const double pi = 3.14159265358979323846;
	double L = WORLD2_CHAIN_LINK_LENGTH, r = WORLD2_CHAIN_LINK_RADIUS;
	double rect = 2.0 * r * L, disc = pi * r * r;
	double total = rect + disc;
	double rectI = rect * (L * L + 4.0 * r * r) / 12.0;
	double d = 4.0 * r / (3.0 * pi);
	double halfDisc = 0.5 * disc;
	double halfI = halfDisc * (0.5 * r * r - d * d + (0.5 * L + d) * (0.5 * L + d));
	return (rectI + 2.0 * halfI) / total;
}

static double chainEnergy(const World2Body* b)
{
	double inertia = chainLinkInertiaPerMass() * b->mass;
	return 0.5 * b->mass * (b->vx * b->vx + b->vy * b->vy) + 0.5 * inertia * b->w * b->w +
		   10.0 * b->mass * b->y;
}

/* Energy lost between the snapshots over the potential the links give up hanging straight down
 * (each link's initial distance from its chain's pivot is how far its centre can drop). */
static World2Quality checkChains(const World2Snapshot* start, const World2Body* sortedEnd, int endCount)
{
	World2Quality q;
	memset(&q, 0, sizeof(q));
	q.computed = true;
	q.limit = 0.4;
	double before = 0.0, after = 0.0, drop = 0.0;
	int links = 0, missing = 0;
	for (int i = 0; i < start->count; ++i)
	{
		const World2Body* b = &start->bodies[i];
		if (b->type != WORLD2_DYNAMIC)
		{
			continue;
		}
		const World2Body* e = findKey(sortedEnd, endCount, b->key);
		if (e == NULL)
		{
			++missing;
			continue;
		}
		double pivot = WORLD2_CHAIN_SPACING * floor(b->x / WORLD2_CHAIN_SPACING);
		before += chainEnergy(b);
		after += chainEnergy(e);
		drop += 10.0 * b->mass * (b->x - pivot);
		++links;
	}
	q.value = drop > 0.0 ? (before - after) / drop : 1.0;
	q.pass = links > 0 && missing == 0 && fabs(q.value) < q.limit;
	snprintf(q.text, sizeof(q.text), "%d chains of %d links: %.1f%% of the potential drop lost over the run",
			 WORLD2_CHAIN_COUNT, links, 100.0 * q.value);
	return q;
}

World2Quality world2CheckQuality(World2SceneId id, const World2Snapshot* start, const World2Snapshot* end,
								 double time)
{
	World2Quality q;
	memset(&q, 0, sizeof(q));
	if (start == NULL || end == NULL || (int)id < 0 || id >= WORLD2_SCENE_COUNT)
	{
		return q;
	}
	int bad = countNonFinite(end);
	if (bad > 0)
	{
		char text[64];
		snprintf(text, sizeof(text), "%d bodies are not finite", bad);
		return fail(text);
	}
	World2Body* sortedEnd = sortedCopy(end);
	if (sortedEnd == NULL)
	{
		return fail("out of memory");
	}
	switch (id)
	{
		case WORLD2_PYRAMID_20:
		case WORLD2_PYRAMID_40:
		case WORLD2_LARGE_PYRAMID:
		case WORLD2_MANY_PYRAMIDS:
			q = checkPyramidsFast(start, end, sortedEnd);
			break;
		case WORLD2_JOINT_GRID:
			q = checkJointGrid(start, sortedEnd, end->count);
			break;
		case WORLD2_RAIN:
			q = checkRain(end);
			break;
		case WORLD2_SMASH:
			q = checkSmash(start, end);
			break;
		case WORLD2_SPINNER:
			q = checkSpinner(end);
			break;
		case WORLD2_TUMBLER:
			q = checkTumbler(end);
			break;
		case WORLD2_CARD_HOUSE:
			q = checkTop(start, sortedEnd, end->count, 0.02, "top card");
			break;
		case WORLD2_RAMP:
			q = checkRamp(start, sortedEnd, end->count, time);
			break;
		case WORLD2_BULLETS:
			q = checkBullets(end);
			break;
		case WORLD2_CHAINS:
			q = checkChains(start, sortedEnd, end->count);
			break;
		default:
			break; /* side_scroller, slingshot: scenes/world2_scenes.c */
	}
	free(sortedEnd);
	return q;
}
