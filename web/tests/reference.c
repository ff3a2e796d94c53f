/* The C library's answer for the browser tests: reads queries from stdin, one per line, and
 * prints one JSON object per line. The browser tests feed it the pose a page shows and compare
 * the page's answer (computed by the wasm build through the JavaScript API) with this native
 * build's.
 *
 *   collide2 SHAPE2 SHAPE2 SPECULATIVE     -> cd2Collide
 * {"pointCount","normal","points":[{"point","separation","id"}]} distance2 SHAPE2 SHAPE2                ->
 * cd2Distance  {"distance","pointA","pointB"} collide3 SHAPE3 SHAPE3 SPECULATIVE     -> cd3Collide distance3
 * SHAPE3 SHAPE3                -> cd3Distance overlap3 SHAPE3 SHAPE3                 -> cd3Overlap
 * {"overlap":true|false} pointin3 X Y Z SHAPE3                  -> cd3PointInShape {"inside":true|false}
 *
 *   SHAPE2: circle X Y R | capsule X1 Y1 X2 Y2 R | box X Y HX HY ANGLE (radians)
 *         | polygon N X1 Y1 ... XN YN RADIUS (world vertices) | segment X1 Y1 X2 Y2
 *   SHAPE3: sphere X Y Z R | capsule X1 Y1 Z1 X2 Y2 Z2 R | aabb MINX MINY MINZ MAXX MAXY MAXZ
 *         | box X Y Z HX HY HZ QX QY QZ QW | hull N X1 Y1 Z1 ... (local points) PX PY PZ QX QY QZ QW
 *
 * A bad line prints {"error": "..."} and the program goes on. */
#include <collide/collide.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct Reader
{
	char* next;
	int failed;
} Reader;

static const char* ReadWord(Reader* r)
{
	char* s = r->next;
	while (*s == ' ' || *s == '\t')
		++s;
	if (*s == '\0' || *s == '\n')
	{
		r->failed = 1;
		return "";
	}
	char* start = s;
	while (*s != '\0' && *s != ' ' && *s != '\t' && *s != '\n')
		++s;
	if (*s != '\0')
		*s++ = '\0';
	r->next = s;
	return start;
}

static cdReal ReadReal(Reader* r)
{
	const char* w = ReadWord(r);
	char* end = NULL;
	double v = strtod(w, &end);
	if (r->failed || end == w || *end != '\0')
	{
		r->failed = 1;
		return 0;
	}
	return (cdReal)v;
}

static int ReadCount(Reader* r, int max)
{
	cdReal v = ReadReal(r);
	int n = (int)v;
	if ((cdReal)n != v || n < 1 || n > max)
	{
		r->failed = 1;
		return 0;
	}
	return n;
}

static int ReadShape2(Reader* r, cd2Shape* shape)
{
	const char* kind = ReadWord(r);
	if (strcmp(kind, "circle") == 0)
	{
		cd2Circle c;
		c.center.x = ReadReal(r);
		c.center.y = ReadReal(r);
		c.radius = ReadReal(r);
		*shape = cd2MakeCircleShape(c);
	}
	else if (strcmp(kind, "capsule") == 0)
	{
		cd2Capsule c;
		c.p1.x = ReadReal(r);
		c.p1.y = ReadReal(r);
		c.p2.x = ReadReal(r);
		c.p2.y = ReadReal(r);
		c.radius = ReadReal(r);
		*shape = cd2MakeCapsuleShape(c);
	}
	else if (strcmp(kind, "box") == 0)
	{
		cd2Box b;
		b.center.x = ReadReal(r);
		b.center.y = ReadReal(r);
		b.halfExtents.x = ReadReal(r);
		b.halfExtents.y = ReadReal(r);
		b.rotation = cd2MakeRot(ReadReal(r));
		*shape = cd2MakeBoxShape(b);
	}
	else if (strcmp(kind, "polygon") == 0)
	{
		cd2Vec points[CD2_MAX_POLYGON_VERTICES];
		int n = ReadCount(r, CD2_MAX_POLYGON_VERTICES);
		for (int i = 0; i < n; ++i)
		{
			points[i].x = ReadReal(r);
			points[i].y = ReadReal(r);
		}
		cdReal radius = ReadReal(r);
		if (r->failed)
			return 0;
		cd2Polygon polygon;
		cdResult made = radius > 0 ? cd2MakeRoundedPolygon(points, n, radius, &polygon)
								   : cd2MakePolygon(points, n, &polygon);
		if (made != CD_OK)
			return 0;
		*shape = cd2MakePolygonShape(&polygon);
	}
	else if (strcmp(kind, "segment") == 0)
	{
		cd2Segment g;
		g.p1.x = ReadReal(r);
		g.p1.y = ReadReal(r);
		g.p2.x = ReadReal(r);
		g.p2.y = ReadReal(r);
		*shape = cd2MakeSegmentShape(g);
	}
	else
	{
		return 0;
	}
	return !r->failed && cd2ValidateShape(shape) == CD_OK;
}

static cd3Vec ReadVec3(Reader* r)
{
	cd3Vec v;
	v.x = ReadReal(r);
	v.y = ReadReal(r);
	v.z = ReadReal(r);
	return v;
}

static cd3Quat ReadQuat(Reader* r)
{
	cd3Quat q;
	q.x = ReadReal(r);
	q.y = ReadReal(r);
	q.z = ReadReal(r);
	q.w = ReadReal(r);
	return q;
}

/* Hulls built for a line; freed after it. */
static cd3Hull* g_hulls[2];
static int g_hullCount;

static int ReadShape3(Reader* r, cd3Shape* shape)
{
	const char* kind = ReadWord(r);
	if (strcmp(kind, "sphere") == 0)
	{
		cd3Sphere s;
		s.center = ReadVec3(r);
		s.radius = ReadReal(r);
		*shape = cd3MakeSphereShape(s);
	}
	else if (strcmp(kind, "capsule") == 0)
	{
		cd3Capsule c;
		c.p1 = ReadVec3(r);
		c.p2 = ReadVec3(r);
		c.radius = ReadReal(r);
		*shape = cd3MakeCapsuleShape(c);
	}
	else if (strcmp(kind, "aabb") == 0)
	{
		cd3Aabb b;
		b.min = ReadVec3(r);
		b.max = ReadVec3(r);
		*shape = cd3MakeAabbShape(b);
	}
	else if (strcmp(kind, "box") == 0)
	{
		cd3Box b;
		b.center = ReadVec3(r);
		b.halfExtents = ReadVec3(r);
		b.rotation = ReadQuat(r);
		*shape = cd3MakeBoxShape(b);
	}
	else if (strcmp(kind, "hull") == 0)
	{
		static cd3Vec points[256];
		int n = ReadCount(r, 256);
		for (int i = 0; i < n; ++i)
			points[i] = ReadVec3(r);
		cd3Transform t;
		t.p = ReadVec3(r);
		t.q = ReadQuat(r);
		if (r->failed || g_hullCount == 2)
			return 0;
		cd3Hull* hull = NULL;
		if (cd3ComputeHull(points, n, &hull) != CD_OK)
			return 0;
		g_hulls[g_hullCount++] = hull;
		*shape = cd3MakeHullShape(hull, t);
	}
	else
	{
		return 0;
	}
	return !r->failed && cd3ValidateShape(shape) == CD_OK;
}

static void PrintReal(cdReal v)
{
	printf("%.9g", (double)v);
}

static void PrintVec2(cd2Vec v)
{
	printf("[");
	PrintReal(v.x);
	printf(",");
	PrintReal(v.y);
	printf("]");
}

static void PrintVec3(cd3Vec v)
{
	printf("[");
	PrintReal(v.x);
	printf(",");
	PrintReal(v.y);
	printf(",");
	PrintReal(v.z);
	printf("]");
}

static int Run(char* line)
{
	Reader r = {line, 0};
	const char* query = ReadWord(&r);
	if (strcmp(query, "collide2") == 0 || strcmp(query, "distance2") == 0)
	{
		cd2Shape a, b;
		if (!ReadShape2(&r, &a) || !ReadShape2(&r, &b))
			return 0;
		if (query[0] == 'c')
		{
			cdReal speculative = ReadReal(&r);
			if (r.failed)
				return 0;
			cd2Manifold m = cd2Collide(&a, &b, speculative);
			printf("{\"pointCount\":%d,\"normal\":", m.pointCount);
			PrintVec2(m.normal);
			printf(",\"points\":[");
			for (int i = 0; i < m.pointCount; ++i)
			{
				printf(i ? ",{\"point\":" : "{\"point\":");
				PrintVec2(m.points[i].point);
				printf(",\"separation\":");
				PrintReal(m.points[i].separation);
				printf(",\"id\":%u}", (unsigned)m.points[i].id);
			}
			printf("]}\n");
		}
		else
		{
			cd2ClosestPoints d = cd2Distance(&a, &b);
			printf("{\"distance\":");
			PrintReal(d.distance);
			printf(",\"pointA\":");
			PrintVec2(d.pointA);
			printf(",\"pointB\":");
			PrintVec2(d.pointB);
			printf("}\n");
		}
		return 1;
	}
	if (strcmp(query, "collide3") == 0 || strcmp(query, "distance3") == 0 || strcmp(query, "overlap3") == 0)
	{
		cd3Shape a, b;
		if (!ReadShape3(&r, &a) || !ReadShape3(&r, &b))
			return 0;
		if (query[0] == 'c')
		{
			cdReal speculative = ReadReal(&r);
			if (r.failed)
				return 0;
			cd3Manifold m = cd3Collide(&a, &b, speculative);
			printf("{\"pointCount\":%d,\"normal\":", m.pointCount);
			PrintVec3(m.normal);
			printf(",\"points\":[");
			for (int i = 0; i < m.pointCount; ++i)
			{
				printf(i ? ",{\"point\":" : "{\"point\":");
				PrintVec3(m.points[i].point);
				printf(",\"separation\":");
				PrintReal(m.points[i].separation);
				printf(",\"id\":%u}", (unsigned)m.points[i].id);
			}
			printf("]}\n");
		}
		else if (query[0] == 'd')
		{
			cd3ClosestPoints d = cd3Distance(&a, &b);
			printf("{\"distance\":");
			PrintReal(d.distance);
			printf(",\"pointA\":");
			PrintVec3(d.pointA);
			printf(",\"pointB\":");
			PrintVec3(d.pointB);
			printf("}\n");
		}
		else
		{
			printf("{\"overlap\":%s}\n", cd3Overlap(&a, &b) ? "true" : "false");
		}
		return 1;
	}
	if (strcmp(query, "pointin3") == 0)
	{
		cd3Vec p = ReadVec3(&r);
		cd3Shape shape;
		if (r.failed || !ReadShape3(&r, &shape))
			return 0;
		printf("{\"inside\":%s}\n", cd3PointInShape(&shape, p) ? "true" : "false");
		return 1;
	}
	return 0;
}

int main(void)
{
	static char line[65536];
	while (fgets(line, (int)sizeof line, stdin) != NULL)
	{
		if (line[0] == '\n' || line[0] == '#')
			continue;
		g_hullCount = 0;
		if (!Run(line))
			printf("{\"error\":\"bad query or invalid shape\"}\n");
		for (int i = 0; i < g_hullCount; ++i)
			cd3DestroyHull(g_hulls[i]);
		fflush(stdout);
	}
	return 0;
}
