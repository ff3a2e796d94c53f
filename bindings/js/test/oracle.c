/* The C library's answers for the JavaScript tests (test/api.test.mjs): builds random shapes of
 * every kind from a fixed seed, runs each query through the native library, and prints inputs
 * and answers as one JSON document. The JavaScript side replays the same inputs through the wasm
 * module and compares. Compiled natively by the test (float build of the library). */
#include <collide/collide.h>

#include <stdio.h>
#include <stdint.h>

static uint32_t g_state = 0x12345678u;

static uint32_t nextU32(void)
{
	g_state ^= g_state << 13;
	g_state ^= g_state >> 17;
	g_state ^= g_state << 5;
	return g_state;
}

static float rnd(float lo, float hi)
{
	return lo + (hi - lo) * (float)(nextU32() >> 8) * (1.0f / 16777216.0f);
}

static int g_first = 1;
static void sep(void)
{
	if (!g_first)
		printf(",");
	g_first = 0;
}

static void pf(const char* key, float v)
{
	printf("\"%s\":%.9g", key, (double)v);
}
static void pv2(const char* key, cd2Vec v)
{
	printf("\"%s\":{\"x\":%.9g,\"y\":%.9g}", key, (double)v.x, (double)v.y);
}
static void pv3(const char* key, cd3Vec v)
{
	printf("\"%s\":{\"x\":%.9g,\"y\":%.9g,\"z\":%.9g}", key, (double)v.x, (double)v.y, (double)v.z);
}
static void pq(const char* key, cd3Quat q)
{
	printf("\"%s\":{\"x\":%.9g,\"y\":%.9g,\"z\":%.9g,\"w\":%.9g}", key, (double)q.x, (double)q.y, (double)q.z,
		   (double)q.w);
}

/* ---- 2D ---- */

typedef struct Shape2Case
{
	cd2Shape shape;
	float angle;	  /* box */
	cd2Vec points[8]; /* polygon input */
	int count;
	float radius;
} Shape2Case;

static Shape2Case randomShape2(int type)
{
	Shape2Case c = {0};
	cd2Vec center = {rnd(-2.0f, 2.0f), rnd(-2.0f, 2.0f)};
	switch (type)
	{
		case 0:
			c.shape = cd2MakeCircleShape((cd2Circle){center, rnd(0.2f, 1.5f)});
			break;
		case 1:
			c.shape = cd2MakeCapsuleShape((cd2Capsule){
				center, {center.x + rnd(-1.5f, 1.5f), center.y + rnd(-1.5f, 1.5f)}, rnd(0.1f, 0.8f)});
			break;
		case 2:
			c.shape =
				cd2MakeAabbShape((cd2Aabb){center, {center.x + rnd(0.1f, 2.0f), center.y + rnd(0.1f, 2.0f)}});
			break;
		case 3:
			c.angle = rnd(-3.0f, 3.0f);
			c.shape =
				cd2MakeBoxShape((cd2Box){center, {rnd(0.1f, 1.5f), rnd(0.1f, 1.5f)}, cd2MakeRot(c.angle)});
			break;
		case 4:
		{
			c.count = 3 + (int)(nextU32() % 6);
			c.radius = (nextU32() % 2) ? rnd(0.05f, 0.3f) : 0.0f;
			float r = rnd(0.4f, 1.5f);
			for (int i = 0; i < c.count; ++i)
			{
				float a = 6.2831853f * ((float)i + rnd(0.0f, 0.6f)) / (float)c.count;
				c.points[i] = (cd2Vec){center.x + r * cosf(a), center.y + r * sinf(a)};
			}
			cd2Polygon p;
			cdResult result = c.radius > 0.0f ? cd2MakeRoundedPolygon(c.points, c.count, c.radius, &p)
											  : cd2MakePolygon(c.points, c.count, &p);
			if (result != CD_OK)
			{
				return randomShape2(0);
			}
			c.shape = cd2MakePolygonShape(&p);
			break;
		}
		default:
			c.shape = cd2MakeSegmentShape(
				(cd2Segment){center, {center.x + rnd(-2.0f, 2.0f), center.y + rnd(-2.0f, 2.0f)}});
			break;
	}
	return c;
}

static void printShape2(const char* key, const Shape2Case* c)
{
	const cd2Shape* s = &c->shape;
	printf("\"%s\":{", key);
	switch (s->type)
	{
		case CD2_SHAPE_CIRCLE:
			printf("\"type\":\"circle\",");
			pv2("center", s->circle.center);
			printf(",");
			pf("radius", s->circle.radius);
			break;
		case CD2_SHAPE_CAPSULE:
			printf("\"type\":\"capsule\",");
			pv2("p1", s->capsule.p1);
			printf(",");
			pv2("p2", s->capsule.p2);
			printf(",");
			pf("radius", s->capsule.radius);
			break;
		case CD2_SHAPE_AABB:
			printf("\"type\":\"aabb\",");
			pv2("min", s->aabb.min);
			printf(",");
			pv2("max", s->aabb.max);
			break;
		case CD2_SHAPE_BOX:
			printf("\"type\":\"box\",");
			pv2("center", s->box.center);
			printf(",");
			pv2("halfExtents", s->box.halfExtents);
			printf(",");
			pf("angle", c->angle);
			break;
		case CD2_SHAPE_POLYGON:
			printf("\"type\":\"polygon\",\"vertices\":[");
			for (int i = 0; i < c->count; ++i)
			{
				printf("%s{\"x\":%.9g,\"y\":%.9g}", i ? "," : "", (double)c->points[i].x,
					   (double)c->points[i].y);
			}
			printf("],");
			pf("radius", c->radius);
			break;
		default:
			printf("\"type\":\"segment\",");
			pv2("p1", s->segment.p1);
			printf(",");
			pv2("p2", s->segment.p2);
			break;
	}
	printf("}");
}

static void cases2(int n)
{
	printf("\"cases2\":[");
	g_first = 1;
	for (int i = 0; i < n; ++i)
	{
		Shape2Case a = randomShape2((int)(nextU32() % 6));
		Shape2Case b = randomShape2((int)(nextU32() % 6));
		cd2Vec p = {rnd(-3.0f, 3.0f), rnd(-3.0f, 3.0f)};
		cd2Ray ray = {{rnd(-5.0f, 5.0f), rnd(-5.0f, 5.0f)}, {rnd(-8.0f, 8.0f), rnd(-8.0f, 8.0f)}};
		cd2Vec translation = {rnd(-6.0f, 6.0f), rnd(-6.0f, 6.0f)};
		sep();
		printf("{");
		printShape2("a", &a);
		printf(",");
		printShape2("b", &b);
		printf(",");
		pv2("p", p);
		printf(",\"ray\":{");
		pv2("origin", ray.origin);
		printf(",");
		pv2("translation", ray.translation);
		printf("},");
		pv2("translation", translation);
		printf(",\"overlap\":%s", cd2Overlap(&a.shape, &b.shape) ? "true" : "false");
		printf(",\"contains\":%s", cd2PointInShape(&a.shape, p) ? "true" : "false");
		printf(",");
		pv2("closest", cd2ClosestPointOnShape(&a.shape, p));
		cd2RayHit hit;
		if (cd2Raycast(&a.shape, ray, &hit))
		{
			printf(",\"ray_hit\":{");
			pf("fraction", hit.fraction);
			printf(",");
			pv2("point", hit.point);
			printf(",");
			pv2("normal", hit.normal);
			printf("}");
		}
		else
		{
			printf(",\"ray_hit\":null");
		}
		cd2ClosestPoints cp = cd2Distance(&a.shape, &b.shape);
		printf(",\"distance\":{");
		pv2("pointA", cp.pointA);
		printf(",");
		pv2("pointB", cp.pointB);
		printf(",");
		pf("distance", cp.distance);
		printf("}");
		cd2Manifold m = cd2Collide(&a.shape, &b.shape, 0.05f);
		printf(",\"manifold\":{");
		pv2("normal", m.normal);
		printf(",\"points\":[");
		for (int k = 0; k < m.pointCount; ++k)
		{
			printf("%s{", k ? "," : "");
			pv2("point", m.points[k].point);
			printf(",");
			pf("separation", m.points[k].separation);
			printf(",\"id\":%u}", (unsigned)m.points[k].id);
		}
		printf("]}");
		cd2CastOutput c = cd2ShapeCast(&a.shape, &b.shape, translation);
		printf(",\"cast\":{\"hit\":%s,", c.hit ? "true" : "false");
		pf("fraction", c.fraction);
		printf(",");
		pv2("point", c.point);
		printf(",");
		pv2("normal", c.normal);
		printf("}");
		cd2Sweep sa = {{0.0f, 0.0f}, {-4.0f, 0.0f}, {4.0f, 0.5f}, 0.0f, rnd(-2.0f, 2.0f)};
		cd2Sweep sb = {{0.0f, 0.0f}, {0.0f, 0.0f}, {0.0f, 0.0f}, 0.0f, 0.0f};
		cdToiOutput t = cd2TimeOfImpact(&a.shape, &sa, &b.shape, &sb, 0.005f, 0.00125f);
		printf(",\"toi\":{\"angle1\":%.9g,\"state\":%d,", (double)sa.angle1, (int)t.state);
		pf("t", t.t);
		printf("}");
		cd2Aabb box = cd2ComputeShapeAabb(&a.shape);
		printf(",\"aabb\":{");
		pv2("min", box.min);
		printf(",");
		pv2("max", box.max);
		printf("}");
		cd2MassData md = cd2ComputeShapeMass(&a.shape, 2.0f);
		printf(",\"mass\":{");
		pf("mass", md.mass);
		printf(",");
		pv2("center", md.center);
		printf(",");
		pf("rotationalInertia", md.rotationalInertia);
		printf("}}");
	}
	printf("]");
}

/* ---- 3D ---- */

typedef struct Shape3Case
{
	cd3Shape shape;
	cd3Vec points[12];
	int hullIndex;
} Shape3Case;

static cd3Hull* g_hulls[64];
static cd3Vec g_hullPoints[64][12];
static int g_hullCount;

static cd3Quat randomQuat(void)
{
	cd3Vec axis = {rnd(-1.0f, 1.0f), rnd(-1.0f, 1.0f), rnd(-1.0f, 1.0f)};
	if (cd3Length(axis) < 0.1f)
		axis = (cd3Vec){0.0f, 1.0f, 0.0f};
	return cd3MakeQuatAxisAngle(axis, rnd(-3.0f, 3.0f));
}

static Shape3Case randomShape3(int type)
{
	Shape3Case c = {0};
	c.hullIndex = -1;
	cd3Vec center = {rnd(-2.0f, 2.0f), rnd(-2.0f, 2.0f), rnd(-2.0f, 2.0f)};
	switch (type)
	{
		case 0:
			c.shape = cd3MakeSphereShape((cd3Sphere){center, rnd(0.2f, 1.5f)});
			break;
		case 1:
			c.shape = cd3MakeCapsuleShape((cd3Capsule){
				center,
				{center.x + rnd(-1.5f, 1.5f), center.y + rnd(-1.5f, 1.5f), center.z + rnd(-1.5f, 1.5f)},
				rnd(0.1f, 0.8f)});
			break;
		case 2:
			c.shape = cd3MakeAabbShape((cd3Aabb){
				center,
				{center.x + rnd(0.1f, 2.0f), center.y + rnd(0.1f, 2.0f), center.z + rnd(0.1f, 2.0f)}});
			break;
		case 3:
			c.shape = cd3MakeBoxShape((cd3Box){
				center, {rnd(0.1f, 1.5f), rnd(0.1f, 1.5f), rnd(0.1f, 1.5f)}, cd3NormalizeQuat(randomQuat())});
			break;
		case 4:
			c.shape = cd3MakeTriangleShape((cd3Triangle){
				center,
				{center.x + rnd(0.5f, 2.0f), center.y + rnd(-0.5f, 0.5f), center.z + rnd(-0.5f, 0.5f)},
				{center.x + rnd(-0.5f, 0.5f), center.y + rnd(0.5f, 2.0f), center.z + rnd(-0.5f, 0.5f)}});
			break;
		case 5:
			c.shape = cd3MakeSegmentShape((cd3Segment){
				center,
				{center.x + rnd(-2.0f, 2.0f), center.y + rnd(-2.0f, 2.0f), center.z + rnd(-2.0f, 2.0f)}});
			break;
		default:
		{
			if (g_hullCount == 64)
				return randomShape3(0);
			int k = g_hullCount;
			for (int i = 0; i < 12; ++i)
				g_hullPoints[k][i] = (cd3Vec){rnd(-1.0f, 1.0f), rnd(-1.0f, 1.0f), rnd(-1.0f, 1.0f)};
			if (cd3ComputeHull(g_hullPoints[k], 12, &g_hulls[k]) != CD_OK)
				return randomShape3(0);
			g_hullCount++;
			c.hullIndex = k;
			c.shape = cd3MakeHullShape(g_hulls[k], (cd3Transform){center, cd3NormalizeQuat(randomQuat())});
			break;
		}
	}
	return c;
}

static void printShape3(const char* key, const Shape3Case* c)
{
	const cd3Shape* s = &c->shape;
	printf("\"%s\":{", key);
	switch (s->type)
	{
		case CD3_SHAPE_SPHERE:
			printf("\"type\":\"sphere\",");
			pv3("center", s->sphere.center);
			printf(",");
			pf("radius", s->sphere.radius);
			break;
		case CD3_SHAPE_CAPSULE:
			printf("\"type\":\"capsule\",");
			pv3("p1", s->capsule.p1);
			printf(",");
			pv3("p2", s->capsule.p2);
			printf(",");
			pf("radius", s->capsule.radius);
			break;
		case CD3_SHAPE_AABB:
			printf("\"type\":\"aabb\",");
			pv3("min", s->aabb.min);
			printf(",");
			pv3("max", s->aabb.max);
			break;
		case CD3_SHAPE_BOX:
			printf("\"type\":\"box\",");
			pv3("center", s->box.center);
			printf(",");
			pv3("halfExtents", s->box.halfExtents);
			printf(",");
			pq("rotation", s->box.rotation);
			break;
		case CD3_SHAPE_TRIANGLE:
			printf("\"type\":\"triangle\",");
			pv3("a", s->triangle.a);
			printf(",");
			pv3("b", s->triangle.b);
			printf(",");
			pv3("c", s->triangle.c);
			break;
		case CD3_SHAPE_SEGMENT:
			printf("\"type\":\"segment\",");
			pv3("p1", s->segment.p1);
			printf(",");
			pv3("p2", s->segment.p2);
			break;
		default:
			printf("\"type\":\"hull\",\"hullPoints\":[");
			for (int i = 0; i < 12; ++i)
			{
				cd3Vec p = g_hullPoints[c->hullIndex][i];
				printf("%s%.9g,%.9g,%.9g", i ? "," : "", (double)p.x, (double)p.y, (double)p.z);
			}
			printf("],");
			pv3("position", s->hull.transform.p);
			printf(",");
			pq("rotation", s->hull.transform.q);
			break;
	}
	printf("}");
}

static int isSolid3(const cd3Shape* s)
{
	return s->type != CD3_SHAPE_TRIANGLE && s->type != CD3_SHAPE_SEGMENT && s->type != CD3_SHAPE_PLANE;
}

static void cases3(int n)
{
	printf("\"cases3\":[");
	g_first = 1;
	for (int i = 0; i < n; ++i)
	{
		Shape3Case a = randomShape3((int)(nextU32() % 7));
		Shape3Case b = randomShape3((int)(nextU32() % 7));
		cd3Vec p = {rnd(-3.0f, 3.0f), rnd(-3.0f, 3.0f), rnd(-3.0f, 3.0f)};
		cd3Ray ray = {{rnd(-5.0f, 5.0f), rnd(-5.0f, 5.0f), rnd(-5.0f, 5.0f)},
					  {rnd(-8.0f, 8.0f), rnd(-8.0f, 8.0f), rnd(-8.0f, 8.0f)}};
		cd3Vec translation = {rnd(-6.0f, 6.0f), rnd(-6.0f, 6.0f), rnd(-6.0f, 6.0f)};
		sep();
		printf("{");
		printShape3("a", &a);
		printf(",");
		printShape3("b", &b);
		printf(",");
		pv3("p", p);
		printf(",\"ray\":{");
		pv3("origin", ray.origin);
		printf(",");
		pv3("translation", ray.translation);
		printf("},");
		pv3("translation", translation);
		printf(",\"overlap\":%s", cd3Overlap(&a.shape, &b.shape) ? "true" : "false");
		printf(",\"contains\":%s", cd3PointInShape(&a.shape, p) ? "true" : "false");
		printf(",");
		pv3("closest", cd3ClosestPointOnShape(&a.shape, p));
		cd3RayHit hit;
		if (cd3Raycast(&a.shape, ray, &hit))
		{
			printf(",\"ray_hit\":{");
			pf("fraction", hit.fraction);
			printf(",");
			pv3("point", hit.point);
			printf(",");
			pv3("normal", hit.normal);
			printf("}");
		}
		else
		{
			printf(",\"ray_hit\":null");
		}
		cd3ClosestPoints cp = cd3Distance(&a.shape, &b.shape);
		printf(",\"distance\":{");
		pv3("pointA", cp.pointA);
		printf(",");
		pv3("pointB", cp.pointB);
		printf(",");
		pf("distance", cp.distance);
		printf("}");
		cd3Manifold m = cd3Collide(&a.shape, &b.shape, 0.05f);
		printf(",\"manifold\":{");
		pv3("normal", m.normal);
		printf(",\"points\":[");
		for (int k = 0; k < m.pointCount; ++k)
		{
			printf("%s{", k ? "," : "");
			pv3("point", m.points[k].point);
			printf(",");
			pf("separation", m.points[k].separation);
			printf(",\"id\":%u}", (unsigned)m.points[k].id);
		}
		printf("]}");
		cd3CastOutput c = cd3ShapeCast(&a.shape, &b.shape, translation);
		printf(",\"cast\":{\"hit\":%s,", c.hit ? "true" : "false");
		pf("fraction", c.fraction);
		printf(",");
		pv3("point", c.point);
		printf(",");
		pv3("normal", c.normal);
		printf("}");
		cd3Quat r1 = cd3NormalizeQuat(randomQuat());
		cd3Sweep sa = {
			{0.0f, 0.0f, 0.0f}, {-4.0f, 0.0f, 0.0f}, {4.0f, 0.5f, 0.0f}, {0.0f, 0.0f, 0.0f, 1.0f}, r1};
		cd3Sweep sb = {{0.0f, 0.0f, 0.0f},
					   {0.0f, 0.0f, 0.0f},
					   {0.0f, 0.0f, 0.0f},
					   {0.0f, 0.0f, 0.0f, 1.0f},
					   {0.0f, 0.0f, 0.0f, 1.0f}};
		cdToiOutput t = cd3TimeOfImpact(&a.shape, &sa, &b.shape, &sb, 0.005f, 0.00125f);
		printf(",\"toi\":{");
		pq("rotation1", r1);
		printf(",\"state\":%d,", (int)t.state);
		pf("t", t.t);
		printf("}");
		cd3Aabb box = cd3ComputeShapeAabb(&a.shape);
		printf(",\"aabb\":{");
		pv3("min", box.min);
		printf(",");
		pv3("max", box.max);
		printf("}");
		if (isSolid3(&a.shape))
		{
			cd3MassData md = cd3ComputeShapeMass(&a.shape, 2.0f);
			printf(",\"mass\":{");
			pf("mass", md.mass);
			printf(",");
			pv3("center", md.center);
			printf(",\"inertia\":[%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g]}", (double)md.inertia.cx.x,
				   (double)md.inertia.cx.y, (double)md.inertia.cx.z, (double)md.inertia.cy.x,
				   (double)md.inertia.cy.y, (double)md.inertia.cy.z, (double)md.inertia.cz.x,
				   (double)md.inertia.cz.y, (double)md.inertia.cz.z);
		}
		printf("}");
	}
	printf("]");
}

/* ---- batch queries: the indices of the boxes, spheres and points that pass ---- */

static void batch(void)
{
	enum
	{
		N = 500
	};
	static float boxes[N][6], spheres[N][4], points[N][3];
	for (int i = 0; i < N; ++i)
	{
		float x = rnd(-10.0f, 10.0f), y = rnd(-10.0f, 10.0f), z = rnd(-10.0f, 10.0f);
		boxes[i][0] = x, boxes[i][1] = y, boxes[i][2] = z;
		boxes[i][3] = x + rnd(0.0f, 2.0f), boxes[i][4] = y + rnd(0.0f, 2.0f),
		boxes[i][5] = z + rnd(0.0f, 2.0f);
		spheres[i][0] = rnd(-10.0f, 10.0f), spheres[i][1] = rnd(-10.0f, 10.0f),
		spheres[i][2] = rnd(-10.0f, 10.0f);
		spheres[i][3] = rnd(0.0f, 1.5f);
		points[i][0] = rnd(-10.0f, 10.0f), points[i][1] = rnd(-10.0f, 10.0f),
		points[i][2] = rnd(-10.0f, 10.0f);
	}
	cd3Aabb qb = {{-3.0f, -2.0f, -4.0f}, {4.0f, 3.0f, 2.5f}};
	cd3Sphere qs = {{1.0f, -1.0f, 0.5f}, 4.0f};
	printf("\"batch\":{\"boxes\":[");
	for (int i = 0; i < N; ++i)
		printf("%s%.9g,%.9g,%.9g,%.9g,%.9g,%.9g", i ? "," : "", (double)boxes[i][0], (double)boxes[i][1],
			   (double)boxes[i][2], (double)boxes[i][3], (double)boxes[i][4], (double)boxes[i][5]);
	printf("],\"spheres\":[");
	for (int i = 0; i < N; ++i)
		printf("%s%.9g,%.9g,%.9g,%.9g", i ? "," : "", (double)spheres[i][0], (double)spheres[i][1],
			   (double)spheres[i][2], (double)spheres[i][3]);
	printf("],\"points\":[");
	for (int i = 0; i < N; ++i)
		printf("%s%.9g,%.9g,%.9g", i ? "," : "", (double)points[i][0], (double)points[i][1],
			   (double)points[i][2]);
	printf("],\"queryBox\":{\"minX\":-3,\"minY\":-2,\"minZ\":-4,\"maxX\":4,\"maxY\":3,\"maxZ\":2.5}");
	printf(",\"querySphere\":{\"x\":1,\"y\":-1,\"z\":0.5,\"radius\":4}");
	const char* names[6] = {"pointsInsideAABB",		"pointsInsideSphere",	  "aabbsIntersectAABB",
							"aabbsIntersectSphere", "spheresIntersectSphere", "spheresIntersectAABB"};
	for (int kind = 0; kind < 6; ++kind)
	{
		printf(",\"%s\":[", names[kind]);
		int first = 1;
		for (int i = 0; i < N; ++i)
		{
			cd3Vec p = {points[i][0], points[i][1], points[i][2]};
			cd3Aabb b = {{boxes[i][0], boxes[i][1], boxes[i][2]}, {boxes[i][3], boxes[i][4], boxes[i][5]}};
			cd3Sphere s = {{spheres[i][0], spheres[i][1], spheres[i][2]}, spheres[i][3]};
			bool in = false;
			switch (kind)
			{
				case 0:
					in = cd3PointInAabb(p, qb);
					break;
				case 1:
					in = cd3PointInSphere(p, qs);
					break;
				case 2:
					in = cd3OverlapAabbAabb(b, qb);
					break;
				case 3:
					in = cd3OverlapSphereAabb(qs, b);
					break;
				case 4:
					in = cd3OverlapSphereSphere(s, qs);
					break;
				default:
					in = cd3OverlapSphereAabb(s, qb);
					break;
			}
			if (in)
			{
				printf("%s%d", first ? "" : ",", i);
				first = 0;
			}
		}
		printf("]");
	}
	printf("}");
}

/* ---- broadphase: a scripted sequence per structure, pairs and queries after each frame ---- */

static void printPair(int a, int b, uint64_t ua, uint64_t ub, void* context)
{
	(void)ua;
	(void)ub;
	int* first = context;
	printf("%s%d,%d", *first ? "" : ",", a, b);
	*first = 0;
}

static bool printId(int id, uint64_t userData, void* context)
{
	(void)userData;
	int* first = context;
	printf("%s%d", *first ? "" : ",", id);
	*first = 0;
	return true;
}

static void broad(void)
{
	enum
	{
		N = 300,
		FRAMES = 3
	};
	static float boxes[FRAMES][N][6];
	for (int f = 0; f < FRAMES; ++f)
		for (int i = 0; i < N; ++i)
		{
			float x = rnd(-20.0f, 20.0f), y = rnd(-20.0f, 20.0f), z = rnd(-20.0f, 20.0f);
			float* b = boxes[f][i];
			b[0] = x, b[1] = y, b[2] = z, b[3] = x + rnd(0.2f, 3.0f), b[4] = y + rnd(0.2f, 3.0f),
			b[5] = z + rnd(0.2f, 3.0f);
		}
	printf("\"broad\":{\"boxes\":[");
	for (int f = 0; f < FRAMES; ++f)
		for (int i = 0; i < N; ++i)
			printf("%s%.9g,%.9g,%.9g,%.9g,%.9g,%.9g", (f || i) ? "," : "", (double)boxes[f][i][0],
				   (double)boxes[f][i][1], (double)boxes[f][i][2], (double)boxes[f][i][3],
				   (double)boxes[f][i][4], (double)boxes[f][i][5]);
	printf("],\"n\":%d,\"frames\":%d,\"runs\":[", N, FRAMES);
	cd3Aabb q = {{-5.0f, -5.0f, -5.0f}, {5.0f, 5.0f, 5.0f}};
	for (int type = 0; type < CD_BROADPHASE_TYPE_COUNT; ++type)
	{
		cd3BroadPhaseDef def = cd3DefaultBroadPhaseDef();
		def.type = (cdBroadPhaseType)type;
		cd3BroadPhase* bp;
		if (cd3BroadPhase_Create(&def, &bp) != CD_OK)
			return;
		int ids[N];
		for (int i = 0; i < N; ++i)
			ids[i] = cd3BroadPhase_CreateProxy(bp,
											   (cd3Aabb){{boxes[0][i][0], boxes[0][i][1], boxes[0][i][2]},
														 {boxes[0][i][3], boxes[0][i][4], boxes[0][i][5]}},
											   0);
		printf("%s{\"type\":%d,\"frames\":[", type ? "," : "", type);
		for (int f = 0; f < FRAMES; ++f)
		{
			if (f > 0)
				cd3BroadPhase_MoveProxies(bp, N, ids, (const cd3Aabb*)(const void*)boxes[f], NULL, NULL);
			int first = 1;
			printf("%s{\"pairs\":[", f ? "," : "");
			cd3BroadPhase_UpdatePairs(bp, printPair, &first);
			first = 1;
			printf("],\"all\":[");
			cd3BroadPhase_FindAllPairs(bp, printPair, &first);
			first = 1;
			printf("],\"query\":[");
			cd3BroadPhase_Query(bp, q, printId, &first);
			printf("]}");
		}
		printf("]}");
		cd3BroadPhase_Destroy(bp);
	}
	printf("]}");
}

int main(void)
{
	printf("{");
	cases2(400);
	printf(",");
	cases3(300);
	printf(",");
	batch();
	printf(",");
	broad();
	printf("}\n");
	for (int i = 0; i < g_hullCount; ++i)
		cd3DestroyHull(g_hulls[i]);
	return 0;
}
