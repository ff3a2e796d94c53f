/* collide_bench: random valid inputs for the benchmark cases.
 *
 * Every shape has a "center" drawn in a 20-unit cube and a size between about 0.1 and 1. The
 * second shape (or the query point, or the ray's aim point) lies within `spread` of the first
 * shape's center, so one number moves the fraction of overlaps and hits from all to none. */
#include "bench.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct BenchRng
{
	uint64_t state;
} BenchRng;

/* splitmix64: tiny, fast and good enough to scatter inputs. */
static uint64_t NextU64(BenchRng* rng)
{
	uint64_t z = (rng->state += 0x9E3779B97F4A7C15ull);
	z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
	z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
	return z ^ (z >> 31);
}

/* Uniform in [0, 1). */
static double NextUnit(BenchRng* rng)
{
	return (double)(NextU64(rng) >> 11) * (1.0 / 9007199254740992.0);
}

static double Uniform(BenchRng* rng, double lower, double upper)
{
	return lower + (upper - lower) * NextUnit(rng);
}

static int UniformInt(BenchRng* rng, int lower, int upper)
{
	return lower + (int)(NextU64(rng) % (uint64_t)(upper - lower + 1));
}

static cdReal R(double x)
{
	return (cdReal)x;
}

/* ---- 3D ------------------------------------------------------------------------------------- */

typedef struct Dvec3
{
	double x, y, z;
} Dvec3;

static Dvec3 InBall3(BenchRng* rng, double radius)
{
	for (;;)
	{
		Dvec3 v = {Uniform(rng, -1.0, 1.0), Uniform(rng, -1.0, 1.0), Uniform(rng, -1.0, 1.0)};
		double lengthSquared = v.x * v.x + v.y * v.y + v.z * v.z;
		if (lengthSquared <= 1.0)
		{
			Dvec3 r = {v.x * radius, v.y * radius, v.z * radius};
			return r;
		}
	}
}

static Dvec3 UnitVector3(BenchRng* rng)
{
	for (;;)
	{
		Dvec3 v = InBall3(rng, 1.0);
		double length = sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
		if (length > 0.1)
		{
			Dvec3 r = {v.x / length, v.y / length, v.z / length};
			return r;
		}
	}
}

static cd3Vec ToVec3(Dvec3 v)
{
	return cd3MakeVec(R(v.x), R(v.y), R(v.z));
}

static Dvec3 Add3(Dvec3 a, Dvec3 b)
{
	Dvec3 r = {a.x + b.x, a.y + b.y, a.z + b.z};
	return r;
}

static Dvec3 Scale3(double s, Dvec3 a)
{
	Dvec3 r = {s * a.x, s * a.y, s * a.z};
	return r;
}

static cd3Quat RandomQuat(BenchRng* rng)
{
	for (;;)
	{
		double x = Uniform(rng, -1.0, 1.0), y = Uniform(rng, -1.0, 1.0);
		double z = Uniform(rng, -1.0, 1.0), w = Uniform(rng, -1.0, 1.0);
		double length = sqrt(x * x + y * y + z * z + w * w);
		if (length > 0.1 && length <= 1.0)
		{
			return cd3NormalizeQuat(cd3MakeQuat(R(x / length), R(y / length), R(z / length), R(w / length)));
		}
	}
}

static cd3Vec RandomHalfExtents3(BenchRng* rng)
{
	return cd3MakeVec(R(Uniform(rng, 0.1, 1.0)), R(Uniform(rng, 0.1, 1.0)), R(Uniform(rng, 0.1, 1.0)));
}

/* Hulls are built once (cd3ComputeHull allocates) and shared by the shapes that place them. */
#define BENCH_HULL_POOL 32
static cd3Hull* g_hullPool[BENCH_HULL_POOL];

static void CreateHullPool(void)
{
	BenchRng rng = {0x4855115EEDull};
	for (int h = 0; h < BENCH_HULL_POOL; ++h)
	{
		cd3Vec points[32];
		int count = UniformInt(&rng, 8, 32);
		double radius = Uniform(&rng, 0.3, 1.0);
		for (int i = 0; i < count; ++i)
		{
			points[i] = ToVec3(Scale3(radius, UnitVector3(&rng)));
		}
		if (cd3ComputeHull(points, count, &g_hullPool[h]) != CD_OK)
		{
			fprintf(stderr, "collide_bench: cd3ComputeHull failed on random points\n");
			exit(1);
		}
	}
}

static void DestroyHullPool(void)
{
	for (int h = 0; h < BENCH_HULL_POOL; ++h)
	{
		cd3DestroyHull(g_hullPool[h]);
		g_hullPool[h] = NULL;
	}
}

static cd3Shape RandomShape3(BenchRng* rng, cd3ShapeType type, Dvec3 center)
{
	cd3Shape shape;
	memset(&shape, 0, sizeof(shape));
	shape.type = type;
	switch (type)
	{
		case CD3_SHAPE_SPHERE:
			shape.sphere.center = ToVec3(center);
			shape.sphere.radius = R(Uniform(rng, 0.25, 1.0));
			break;
		case CD3_SHAPE_CAPSULE:
		{
			Dvec3 half = Scale3(Uniform(rng, 0.0, 1.0), UnitVector3(rng));
			shape.capsule.p1 = ToVec3(Add3(center, half));
			shape.capsule.p2 = ToVec3(Add3(center, Scale3(-1.0, half)));
			shape.capsule.radius = R(Uniform(rng, 0.1, 0.5));
			break;
		}
		case CD3_SHAPE_AABB:
		{
			cd3Vec c = ToVec3(center), h = RandomHalfExtents3(rng);
			shape.aabb.min = cd3Sub(c, h);
			shape.aabb.max = cd3Add(c, h);
			break;
		}
		case CD3_SHAPE_BOX:
			shape.box.center = ToVec3(center);
			shape.box.halfExtents = RandomHalfExtents3(rng);
			shape.box.rotation = RandomQuat(rng);
			break;
		case CD3_SHAPE_TRIANGLE:
			for (;;)
			{
				Dvec3 a = InBall3(rng, 1.0), b = InBall3(rng, 1.0), c = InBall3(rng, 1.0);
				Dvec3 e1 = {b.x - a.x, b.y - a.y, b.z - a.z}, e2 = {c.x - a.x, c.y - a.y, c.z - a.z};
				Dvec3 n = {e1.y * e2.z - e1.z * e2.y, e1.z * e2.x - e1.x * e2.z, e1.x * e2.y - e1.y * e2.x};
				/* Keep triangles fat enough that the validator would accept them. */
				if (n.x * n.x + n.y * n.y + n.z * n.z > 0.05)
				{
					/* Centered on its centroid, so that rays and shapes aimed at the center meet it. */
					Dvec3 offset = Add3(center, Scale3(-1.0 / 3.0, Add3(a, Add3(b, c))));
					shape.triangle.a = ToVec3(Add3(offset, a));
					shape.triangle.b = ToVec3(Add3(offset, b));
					shape.triangle.c = ToVec3(Add3(offset, c));
					break;
				}
			}
			break;
		case CD3_SHAPE_PLANE:
		{
			/* The half-space whose boundary passes through the center. */
			cd3Vec normal = cd3Normalize(ToVec3(UnitVector3(rng)));
			shape.plane.normal = normal;
			shape.plane.offset = cd3Dot(normal, ToVec3(center));
			break;
		}
		case CD3_SHAPE_SEGMENT:
		{
			Dvec3 half = Scale3(Uniform(rng, 0.25, 1.0), UnitVector3(rng));
			shape.segment.p1 = ToVec3(Add3(center, half));
			shape.segment.p2 = ToVec3(Add3(center, Scale3(-1.0, half)));
			break;
		}
		case CD3_SHAPE_HULL:
			shape.hull.hull = g_hullPool[UniformInt(rng, 0, BENCH_HULL_POOL - 1)];
			shape.hull.transform.p = ToVec3(center);
			shape.hull.transform.q = RandomQuat(rng);
			break;
		case CD3_SHAPE_TYPE_COUNT:
			break;
	}
	return shape;
}

/* Copies the active member of each shape into a compact typed array. */
static void Pack3(void* destination, const cd3Shape* shapes, int count)
{
	for (int i = 0; i < count; ++i)
	{
		switch (shapes[i].type)
		{
			case CD3_SHAPE_SPHERE:
				((cd3Sphere*)destination)[i] = shapes[i].sphere;
				break;
			case CD3_SHAPE_CAPSULE:
				((cd3Capsule*)destination)[i] = shapes[i].capsule;
				break;
			case CD3_SHAPE_AABB:
				((cd3Aabb*)destination)[i] = shapes[i].aabb;
				break;
			case CD3_SHAPE_BOX:
				((cd3Box*)destination)[i] = shapes[i].box;
				break;
			case CD3_SHAPE_TRIANGLE:
				((cd3Triangle*)destination)[i] = shapes[i].triangle;
				break;
			case CD3_SHAPE_PLANE:
				((cd3Plane*)destination)[i] = shapes[i].plane;
				break;
			case CD3_SHAPE_SEGMENT:
				((cd3Segment*)destination)[i] = shapes[i].segment;
				break;
			case CD3_SHAPE_HULL:
				((cd3HullShape*)destination)[i] = shapes[i].hull;
				break;
			case CD3_SHAPE_TYPE_COUNT:
				break;
		}
	}
}

/* A ray aimed at a point within `spread` of the center, from up to 4 units away, reaching the
 * aim point at a fraction between 1/4 and 1: short rays start inside, long ones outside. */
static cd3Ray AimedRay3(BenchRng* rng, Dvec3 center, double spread)
{
	Dvec3 aim = Add3(center, InBall3(rng, spread));
	Dvec3 direction = UnitVector3(rng);
	double reach = 4.0;
	cd3Ray ray;
	ray.origin = ToVec3(Add3(aim, Scale3(-reach * Uniform(rng, 0.25, 1.0), direction)));
	ray.translation = ToVec3(Scale3(reach, direction));
	return ray;
}

static void Generate3(BenchBatch* batch, const BenchCase* benchCase, double spread, BenchRng* rng)
{
	bool mixed = benchCase->input == BENCH_MIXED_PAIR3 || benchCase->input == BENCH_MIXED_POINT3 ||
				 benchCase->input == BENCH_MIXED_RAY3;
	for (int i = 0; i < batch->count; ++i)
	{
		Dvec3 center = {Uniform(rng, -10.0, 10.0), Uniform(rng, -10.0, 10.0), Uniform(rng, -10.0, 10.0)};
		cd3ShapeType typeA = mixed ? (cd3ShapeType)UniformInt(rng, 0, CD3_SHAPE_TYPE_COUNT - 1)
								   : (cd3ShapeType)benchCase->typeA;
		cd3ShapeType typeB = mixed ? (cd3ShapeType)UniformInt(rng, 0, CD3_SHAPE_TYPE_COUNT - 1)
								   : (cd3ShapeType)benchCase->typeB;
		batch->shapeA3[i] = RandomShape3(rng, typeA, center);
		switch (benchCase->input)
		{
			case BENCH_PAIR3:
			case BENCH_MIXED_PAIR3:
				batch->shapeB3[i] = RandomShape3(rng, typeB, Add3(center, InBall3(rng, spread)));
				break;
			case BENCH_POINT3:
			case BENCH_MIXED_POINT3:
				batch->point3[i] = ToVec3(Add3(center, InBall3(rng, spread)));
				break;
			default:
				batch->ray3[i] = AimedRay3(rng, center, spread);
				break;
		}
	}
	if (!mixed)
	{
		Pack3(batch->packA, batch->shapeA3, batch->count);
		if (benchCase->input == BENCH_PAIR3)
		{
			Pack3(batch->packB, batch->shapeB3, batch->count);
		}
	}
}

/* ---- 2D ------------------------------------------------------------------------------------- */

typedef struct Dvec2
{
	double x, y;
} Dvec2;

static Dvec2 InDisk(BenchRng* rng, double radius)
{
	for (;;)
	{
		Dvec2 v = {Uniform(rng, -1.0, 1.0), Uniform(rng, -1.0, 1.0)};
		if (v.x * v.x + v.y * v.y <= 1.0)
		{
			Dvec2 r = {v.x * radius, v.y * radius};
			return r;
		}
	}
}

static Dvec2 UnitVector2(BenchRng* rng)
{
	double angle = Uniform(rng, 0.0, 6.283185307179586);
	Dvec2 v = {cos(angle), sin(angle)};
	return v;
}

static cd2Vec ToVec2(Dvec2 v)
{
	return cd2MakeVec(R(v.x), R(v.y));
}

static Dvec2 Add2(Dvec2 a, Dvec2 b)
{
	Dvec2 r = {a.x + b.x, a.y + b.y};
	return r;
}

static Dvec2 Scale2(double s, Dvec2 a)
{
	Dvec2 r = {s * a.x, s * a.y};
	return r;
}

static cd2Vec RandomHalfExtents2(BenchRng* rng)
{
	return cd2MakeVec(R(Uniform(rng, 0.1, 1.0)), R(Uniform(rng, 0.1, 1.0)));
}

static cd2Box RandomBox2(BenchRng* rng, Dvec2 center)
{
	cd2Box box;
	box.center = ToVec2(center);
	box.halfExtents = RandomHalfExtents2(rng);
	box.rotation = cd2NormalizeRot(cd2MakeRot(R(Uniform(rng, -3.14159, 3.14159))));
	return box;
}

/* 3 to 8 points scattered around a circle, as a level editor or a convex decomposition would
 * produce them: mostly on the hull, sometimes with points inside. */
static int RandomCloud2(BenchRng* rng, Dvec2 center, cd2Vec* points)
{
	int count = UniformInt(rng, 3, CD2_MAX_POLYGON_VERTICES);
	double radius = Uniform(rng, 0.3, 1.0);
	for (int i = 0; i < count; ++i)
	{
		Dvec2 p = Scale2(radius * Uniform(rng, 0.6, 1.0), UnitVector2(rng));
		points[i] = ToVec2(Add2(center, p));
	}
	return count;
}

static cd2Shape RandomShape2(BenchRng* rng, cd2ShapeType type, Dvec2 center)
{
	cd2Shape shape;
	memset(&shape, 0, sizeof(shape));
	shape.type = type;
	switch (type)
	{
		case CD2_SHAPE_CIRCLE:
			shape.circle.center = ToVec2(center);
			shape.circle.radius = R(Uniform(rng, 0.25, 1.0));
			break;
		case CD2_SHAPE_CAPSULE:
		{
			Dvec2 half = Scale2(Uniform(rng, 0.0, 1.0), UnitVector2(rng));
			shape.capsule.p1 = ToVec2(Add2(center, half));
			shape.capsule.p2 = ToVec2(Add2(center, Scale2(-1.0, half)));
			shape.capsule.radius = R(Uniform(rng, 0.1, 0.5));
			break;
		}
		case CD2_SHAPE_AABB:
		{
			cd2Vec c = ToVec2(center), h = RandomHalfExtents2(rng);
			shape.aabb.min = cd2Sub(c, h);
			shape.aabb.max = cd2Add(c, h);
			break;
		}
		case CD2_SHAPE_BOX:
			shape.box = RandomBox2(rng, center);
			break;
		case CD2_SHAPE_POLYGON:
			for (;;)
			{
				cd2Vec points[CD2_MAX_POLYGON_VERTICES];
				int count = RandomCloud2(rng, center, points);
				if (cd2MakePolygon(points, count, &shape.polygon) == CD_OK)
				{
					break;
				}
			}
			break;
		case CD2_SHAPE_SEGMENT:
		{
			Dvec2 half = Scale2(Uniform(rng, 0.25, 1.0), UnitVector2(rng));
			shape.segment.p1 = ToVec2(Add2(center, half));
			shape.segment.p2 = ToVec2(Add2(center, Scale2(-1.0, half)));
			break;
		}
		case CD2_SHAPE_TYPE_COUNT:
			break;
	}
	return shape;
}

static void Pack2(void* destination, const cd2Shape* shapes, int count)
{
	for (int i = 0; i < count; ++i)
	{
		switch (shapes[i].type)
		{
			case CD2_SHAPE_CIRCLE:
				((cd2Circle*)destination)[i] = shapes[i].circle;
				break;
			case CD2_SHAPE_CAPSULE:
				((cd2Capsule*)destination)[i] = shapes[i].capsule;
				break;
			case CD2_SHAPE_AABB:
				((cd2Aabb*)destination)[i] = shapes[i].aabb;
				break;
			case CD2_SHAPE_BOX:
				((cd2Box*)destination)[i] = shapes[i].box;
				break;
			case CD2_SHAPE_POLYGON:
				((cd2Polygon*)destination)[i] = shapes[i].polygon;
				break;
			case CD2_SHAPE_SEGMENT:
				((cd2Segment*)destination)[i] = shapes[i].segment;
				break;
			case CD2_SHAPE_TYPE_COUNT:
				break;
		}
	}
}

static cd2Ray AimedRay2(BenchRng* rng, Dvec2 center, double spread)
{
	Dvec2 aim = Add2(center, InDisk(rng, spread));
	Dvec2 direction = UnitVector2(rng);
	double reach = 4.0;
	cd2Ray ray;
	ray.origin = ToVec2(Add2(aim, Scale2(-reach * Uniform(rng, 0.25, 1.0), direction)));
	ray.translation = ToVec2(Scale2(reach, direction));
	return ray;
}

static void Generate2(BenchBatch* batch, const BenchCase* benchCase, double spread, BenchRng* rng)
{
	bool mixed = benchCase->input == BENCH_MIXED_PAIR2 || benchCase->input == BENCH_MIXED_POINT2 ||
				 benchCase->input == BENCH_MIXED_RAY2;
	for (int i = 0; i < batch->count; ++i)
	{
		Dvec2 center = {Uniform(rng, -10.0, 10.0), Uniform(rng, -10.0, 10.0)};
		if (benchCase->input == BENCH_POINT_CLOUD2)
		{
			cd2Vec* points = batch->cloud + (size_t)i * CD2_MAX_POLYGON_VERTICES;
			batch->cloudCount[i] = RandomCloud2(rng, center, points);
			continue;
		}
		if (benchCase->input == BENCH_BOX2)
		{
			batch->box2[i] = RandomBox2(rng, center);
			continue;
		}
		cd2ShapeType typeA = mixed ? (cd2ShapeType)UniformInt(rng, 0, CD2_SHAPE_TYPE_COUNT - 1)
								   : (cd2ShapeType)benchCase->typeA;
		cd2ShapeType typeB = mixed ? (cd2ShapeType)UniformInt(rng, 0, CD2_SHAPE_TYPE_COUNT - 1)
								   : (cd2ShapeType)benchCase->typeB;
		batch->shapeA2[i] = RandomShape2(rng, typeA, center);
		switch (benchCase->input)
		{
			case BENCH_PAIR2:
			case BENCH_MIXED_PAIR2:
				batch->shapeB2[i] = RandomShape2(rng, typeB, Add2(center, InDisk(rng, spread)));
				break;
			case BENCH_POINT2:
			case BENCH_MIXED_POINT2:
				batch->point2[i] = ToVec2(Add2(center, InDisk(rng, spread)));
				break;
			default:
				batch->ray2[i] = AimedRay2(rng, center, spread);
				break;
		}
	}
	if (!mixed && benchCase->input != BENCH_POINT_CLOUD2 && benchCase->input != BENCH_BOX2)
	{
		Pack2(batch->packA, batch->shapeA2, batch->count);
		if (benchCase->input == BENCH_PAIR2)
		{
			Pack2(batch->packB, batch->shapeB2, batch->count);
		}
	}
}

/* ---- batches -------------------------------------------------------------------------------- */

void BenchGenerate(BenchBatch* batch, const BenchCase* benchCase, int count, double spread, uint64_t seed)
{
	BenchRng rng = {seed};
	batch->count = cdMinInt(count, BENCH_BATCH_MAX);
	if (benchCase->input <= BENCH_MIXED_RAY3)
	{
		Generate3(batch, benchCase, spread, &rng);
	}
	else
	{
		Generate2(batch, benchCase, spread, &rng);
	}
}

static void* AllocateOrDie(size_t size)
{
	void* memory = calloc(1, size);
	if (memory == NULL)
	{
		fprintf(stderr, "collide_bench: out of memory\n");
		exit(1);
	}
	return memory;
}

BenchBatch* BenchCreateBatch(void)
{
	size_t n = BENCH_BATCH_MAX;
	size_t largest = sizeof(cd2Polygon);
	largest = sizeof(cd3Box) > largest ? sizeof(cd3Box) : largest;
	largest = sizeof(cd3HullShape) > largest ? sizeof(cd3HullShape) : largest;
	BenchBatch* batch = AllocateOrDie(sizeof(BenchBatch));
	batch->shapeA3 = AllocateOrDie(n * sizeof(cd3Shape));
	batch->shapeB3 = AllocateOrDie(n * sizeof(cd3Shape));
	batch->point3 = AllocateOrDie(n * sizeof(cd3Vec));
	batch->ray3 = AllocateOrDie(n * sizeof(cd3Ray));
	batch->shapeA2 = AllocateOrDie(n * sizeof(cd2Shape));
	batch->shapeB2 = AllocateOrDie(n * sizeof(cd2Shape));
	batch->point2 = AllocateOrDie(n * sizeof(cd2Vec));
	batch->ray2 = AllocateOrDie(n * sizeof(cd2Ray));
	batch->cloud = AllocateOrDie(n * CD2_MAX_POLYGON_VERTICES * sizeof(cd2Vec));
	batch->cloudCount = AllocateOrDie(n * sizeof(int));
	batch->box2 = AllocateOrDie(n * sizeof(cd2Box));
	batch->packA = AllocateOrDie(n * largest);
	batch->packB = AllocateOrDie(n * largest);
	CreateHullPool();
	return batch;
}

void BenchDestroyBatch(BenchBatch* batch)
{
	free(batch->shapeA3);
	free(batch->shapeB3);
	free(batch->point3);
	free(batch->ray3);
	free(batch->shapeA2);
	free(batch->shapeB2);
	free(batch->point2);
	free(batch->ray2);
	free(batch->cloud);
	free(batch->cloudCount);
	free(batch->box2);
	free(batch->packA);
	free(batch->packB);
	free(batch);
	DestroyHullPool();
}
