/* collide tool: the SVG picture. Each scene gets a panel with a title; shapes are outlined, the
 * shapes of overlapping pairs are filled in a highlight colour, separated pairs get a thin dashed
 * line between their closest points, and every shape is labelled with its name.
 *
 * World coordinates have y up; SVG has y down, so the mapping flips y. 3D scenes are drawn in an
 * orthographic axonometric view from the (+x, +y, +z) side (yaw 35 degrees, pitch 25 degrees),
 * shapes sorted back to front, with a small axis gizmo in the corner. Half-spaces are drawn as a
 * square patch of their boundary plane around the other shapes, with an arrow along the normal
 * (pointing out of the solid side).
 *
 * Every panel is drawn twice through the same code: once to measure the bounds of what will be
 * drawn, once to write it scaled into the panel. */
#include "scene.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PANEL_WIDTH 560.0
#define PANEL_HEIGHT 440.0
#define PANEL_GAP 16.0
#define PANEL_TITLE 46.0
#define PANEL_MARGIN 24.0
#define HEADER_HEIGHT 40.0
#define CIRCLE_SEGMENTS 48
#define MAX_CLOSEST_LINES 120
#define PI_D 3.14159265358979323846

#define STROKE_COLOR "#2c3e50"
#define FILL_NORMAL "fill=\"#cfe0f3\" fill-opacity=\"0.55\""
#define FILL_HIGHLIGHT "fill=\"#ff7043\" fill-opacity=\"0.6\""
#define STROKE_NORMAL "stroke=\"" STROKE_COLOR "\" stroke-width=\"1.5\""
#define STROKE_HIGHLIGHT "stroke=\"#b71c1c\" stroke-width=\"2\""

typedef struct V2
{
	double x, y;
} V2;

typedef struct Rect
{
	double x0, y0, x1, y1;
} Rect;

typedef struct Canvas
{
	FILE* out; /* NULL while measuring */
	int dimension;
	double right[3], up[3], toward[3]; /* 3D view basis */
	/* measuring: bounds of everything drawn, in projected world units */
	bool hasBounds;
	double minX, minY, maxX, maxY;
	/* drawing: pixel = ((x - minX) * scale + originX, originY - (y - minY) * scale) */
	double scale, originX, originY;
	/* pixel bounds of the shape being drawn, for its label */
	bool hasShapeRect;
	Rect shapeRect;
	const char* fill;
	const char* stroke;
} Canvas;

/* ---- small helpers ----------------------------------------------------------------------------- */

static double finiteOr0(double v)
{
	return isfinite(v) ? v : 0.0;
}

static void writeEscaped(FILE* out, const char* text)
{
	for (const char* p = text; *p != 0; ++p)
	{
		switch (*p)
		{
			case '<':
				fputs("&lt;", out);
				break;
			case '>':
				fputs("&gt;", out);
				break;
			case '&':
				fputs("&amp;", out);
				break;
			case '"':
				fputs("&quot;", out);
				break;
			default:
				fputc(*p, out);
		}
	}
}

static double dot3(const double a[3], const double b[3])
{
	return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void setupView(Canvas* canvas, int dimension)
{
	canvas->dimension = dimension;
	double yaw = 35.0 * PI_D / 180.0, pitch = 25.0 * PI_D / 180.0;
	double toward[3] = {sin(yaw) * cos(pitch), sin(pitch), cos(yaw) * cos(pitch)};
	double right[3] = {cos(yaw), 0.0, -sin(yaw)};
	/* up = toward x right */
	double up[3] = {toward[1] * right[2] - toward[2] * right[1], toward[2] * right[0] - toward[0] * right[2],
					toward[0] * right[1] - toward[1] * right[0]};
	memcpy(canvas->toward, toward, sizeof toward);
	memcpy(canvas->right, right, sizeof right);
	memcpy(canvas->up, up, sizeof up);
}

static V2 project(const Canvas* canvas, const double p[3])
{
	if (canvas->dimension == 2)
	{
		V2 v = {p[0], p[1]};
		return v;
	}
	V2 v = {dot3(p, canvas->right), dot3(p, canvas->up)};
	return v;
}

static V2 project2(cd2Vec p)
{
	V2 v = {(double)p.x, (double)p.y};
	return v;
}

static V2 project3(const Canvas* canvas, cd3Vec p)
{
	double q[3] = {(double)p.x, (double)p.y, (double)p.z};
	return project(canvas, q);
}

static V2 toPixels(const Canvas* canvas, V2 world)
{
	V2 px = {finiteOr0((world.x - canvas->minX) * canvas->scale + canvas->originX),
			 finiteOr0(canvas->originY - (world.y - canvas->minY) * canvas->scale)};
	return px;
}

static void includeWorld(Canvas* canvas, V2 p)
{
	if (!isfinite(p.x) || !isfinite(p.y))
	{
		return;
	}
	if (!canvas->hasBounds)
	{
		canvas->minX = canvas->maxX = p.x;
		canvas->minY = canvas->maxY = p.y;
		canvas->hasBounds = true;
		return;
	}
	canvas->minX = fmin(canvas->minX, p.x);
	canvas->maxX = fmax(canvas->maxX, p.x);
	canvas->minY = fmin(canvas->minY, p.y);
	canvas->maxY = fmax(canvas->maxY, p.y);
}

static void includeShapePixels(Canvas* canvas, V2 px, double radius)
{
	Rect r = {px.x - radius, px.y - radius, px.x + radius, px.y + radius};
	if (!canvas->hasShapeRect)
	{
		canvas->shapeRect = r;
		canvas->hasShapeRect = true;
		return;
	}
	canvas->shapeRect.x0 = fmin(canvas->shapeRect.x0, r.x0);
	canvas->shapeRect.y0 = fmin(canvas->shapeRect.y0, r.y0);
	canvas->shapeRect.x1 = fmax(canvas->shapeRect.x1, r.x1);
	canvas->shapeRect.y1 = fmax(canvas->shapeRect.y1, r.y1);
}

/* ---- primitives (measure or draw) ------------------------------------------------------------- */

static void drawPolyline(Canvas* canvas, const V2* points, int count, bool closed, bool filled,
						 const char* extra)
{
	if (canvas->out == NULL)
	{
		for (int i = 0; i < count; ++i)
		{
			includeWorld(canvas, points[i]);
		}
		return;
	}
	fprintf(canvas->out, "<%s points=\"", closed ? "polygon" : "polyline");
	for (int i = 0; i < count; ++i)
	{
		V2 px = toPixels(canvas, points[i]);
		includeShapePixels(canvas, px, 0.0);
		fprintf(canvas->out, "%s%.2f,%.2f", i > 0 ? " " : "", px.x, px.y);
	}
	fprintf(canvas->out, "\" %s %s stroke-linejoin=\"round\"%s/>\n", filled ? canvas->fill : "fill=\"none\"",
			canvas->stroke, extra != NULL ? extra : "");
}

static void drawLine(Canvas* canvas, V2 a, V2 b, const char* attributes)
{
	if (canvas->out == NULL)
	{
		includeWorld(canvas, a);
		includeWorld(canvas, b);
		return;
	}
	V2 pa = toPixels(canvas, a), pb = toPixels(canvas, b);
	fprintf(canvas->out, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" %s/>\n", pa.x, pa.y, pb.x,
			pb.y, attributes);
}

static void drawCircle(Canvas* canvas, V2 center, double radius)
{
	if (canvas->out == NULL)
	{
		V2 lo = {center.x - radius, center.y - radius}, hi = {center.x + radius, center.y + radius};
		includeWorld(canvas, lo);
		includeWorld(canvas, hi);
		return;
	}
	V2 px = toPixels(canvas, center);
	double r = finiteOr0(radius * canvas->scale);
	includeShapePixels(canvas, px, r);
	fprintf(canvas->out, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%.2f\" %s %s/>\n", px.x, px.y, r, canvas->fill,
			canvas->stroke);
}

/* A dot of a fixed size in pixels (points, segment ends). */
static void drawDot(Canvas* canvas, V2 center, double pixels, const char* fill)
{
	if (canvas->out == NULL)
	{
		includeWorld(canvas, center);
		return;
	}
	V2 px = toPixels(canvas, center);
	includeShapePixels(canvas, px, pixels);
	fprintf(canvas->out,
			"<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%.1f\" fill=\"%s\" stroke=\"white\" stroke-width=\"1\"/>\n",
			px.x, px.y, pixels, fill);
}

/* A rounded convex polygon (counter-clockwise corners, outward edge normals): each edge pushed out
 * by the radius, joined by arcs around the corners, with the core polygon dashed inside. */
static void drawRoundedPolygon(Canvas* canvas, const V2* corners, const V2* normals, int count, double radius)
{
	if (canvas->out == NULL)
	{
		for (int i = 0; i < count; ++i)
		{
			V2 lo = {corners[i].x - radius, corners[i].y - radius};
			V2 hi = {corners[i].x + radius, corners[i].y + radius};
			includeWorld(canvas, lo);
			includeWorld(canvas, hi);
		}
		return;
	}
	double r = finiteOr0(radius * canvas->scale);
	fputs("<path d=\"", canvas->out);
	for (int i = 0; i < count; ++i)
	{
		int next = (i + 1) % count;
		V2 start = {corners[i].x + radius * normals[i].x, corners[i].y + radius * normals[i].y};
		V2 end = {corners[next].x + radius * normals[i].x, corners[next].y + radius * normals[i].y};
		V2 arcEnd = {corners[next].x + radius * normals[next].x, corners[next].y + radius * normals[next].y};
		V2 ps = toPixels(canvas, start), pe = toPixels(canvas, end), pa = toPixels(canvas, arcEnd);
		if (i == 0)
		{
			fprintf(canvas->out, "M%.2f,%.2f ", ps.x, ps.y);
		}
		/* the picture shows y up, so the world's counter-clockwise turn stays counter-clockwise
		 * on the page, which is the negative-angle direction of SVG's y-down coordinates:
		 * sweep flag 0 */
		fprintf(canvas->out, "L%.2f,%.2f A%.2f,%.2f 0 0 0 %.2f,%.2f ", pe.x, pe.y, r, r, pa.x, pa.y);
		includeShapePixels(canvas, toPixels(canvas, corners[i]), r);
	}
	fprintf(canvas->out, "Z\" %s %s stroke-linejoin=\"round\"/>\n", canvas->fill, canvas->stroke);
	const char* stroke = canvas->stroke;
	canvas->stroke = "stroke=\"" STROKE_COLOR "\" stroke-width=\"0.8\" stroke-dasharray=\"3 3\"";
	drawPolyline(canvas, corners, count, true, false, NULL);
	canvas->stroke = stroke;
}

/* Convex hull (Andrew's monotone chain), counter-clockwise; returns the count written to hull
 * (room for count + 1 points). */
static int compareV2(const void* a, const void* b)
{
	const V2* p = a;
	const V2* q = b;
	if (p->x != q->x)
	{
		return p->x < q->x ? -1 : 1;
	}
	return p->y < q->y ? -1 : (p->y > q->y ? 1 : 0);
}

static double turn(V2 o, V2 a, V2 b)
{
	return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

static int convexHull(V2* points, int count, V2* hull)
{
	if (count < 3)
	{
		memcpy(hull, points, (size_t)count * sizeof(V2));
		return count;
	}
	qsort(points, (size_t)count, sizeof(V2), compareV2);
	int k = 0;
	for (int i = 0; i < count; ++i)
	{
		while (k >= 2 && turn(hull[k - 2], hull[k - 1], points[i]) <= 0.0)
		{
			--k;
		}
		hull[k++] = points[i];
	}
	for (int i = count - 2, lower = k + 1; i >= 0; --i)
	{
		while (k >= lower && turn(hull[k - 2], hull[k - 1], points[i]) <= 0.0)
		{
			--k;
		}
		hull[k++] = points[i];
	}
	return k - 1;
}

/* Filled hull of projected points plus optional outline edges drawn on top. */
static void drawHull(Canvas* canvas, V2* points, int count)
{
	V2 hull[2 * CIRCLE_SEGMENTS + 2];
	int n = convexHull(points, count, hull);
	if (n >= 3)
	{
		drawPolyline(canvas, hull, n, true, true, NULL);
	}
	else if (n == 2)
	{
		drawPolyline(canvas, hull, 2, false, false, NULL);
	}
}

/* ---- shapes ------------------------------------------------------------------------------------ */

static void circlePoints(V2 center, double radius, V2* out)
{
	for (int i = 0; i < CIRCLE_SEGMENTS; ++i)
	{
		double angle = 2.0 * PI_D * i / CIRCLE_SEGMENTS;
		out[i].x = center.x + radius * cos(angle);
		out[i].y = center.y + radius * sin(angle);
	}
}

static void drawCapsule(Canvas* canvas, V2 p1, V2 p2, double radius)
{
	V2 points[2 * CIRCLE_SEGMENTS];
	circlePoints(p1, radius, points);
	circlePoints(p2, radius, points + CIRCLE_SEGMENTS);
	drawHull(canvas, points, 2 * CIRCLE_SEGMENTS);
	drawLine(canvas, p1, p2, "stroke=\"" STROKE_COLOR "\" stroke-width=\"0.8\" stroke-dasharray=\"3 3\"");
}

static void drawSegment(Canvas* canvas, V2 p1, V2 p2, bool highlighted)
{
	drawLine(canvas, p1, p2,
			 highlighted ? "stroke=\"#d84315\" stroke-width=\"3\" stroke-linecap=\"round\""
						 : "stroke=\"" STROKE_COLOR "\" stroke-width=\"2.5\" stroke-linecap=\"round\"");
	if (canvas->out != NULL)
	{
		includeShapePixels(canvas, toPixels(canvas, p1), 2.0);
		includeShapePixels(canvas, toPixels(canvas, p2), 2.0);
	}
}

static void drawShape2(Canvas* canvas, const ToolShape* shape, bool highlighted)
{
	if (shape->isPoint)
	{
		drawDot(canvas, project2(shape->point2), 4.0, highlighted ? "#d84315" : STROKE_COLOR);
		return;
	}
	const cd2Shape* s = &shape->shape2;
	switch (s->type)
	{
		case CD2_SHAPE_CIRCLE:
			drawCircle(canvas, project2(s->circle.center), (double)s->circle.radius);
			break;
		case CD2_SHAPE_CAPSULE:
			drawCapsule(canvas, project2(s->capsule.p1), project2(s->capsule.p2), (double)s->capsule.radius);
			break;
		case CD2_SHAPE_AABB:
		{
			V2 lo = project2(s->aabb.min), hi = project2(s->aabb.max);
			V2 corners[4] = {{lo.x, lo.y}, {hi.x, lo.y}, {hi.x, hi.y}, {lo.x, hi.y}};
			drawPolyline(canvas, corners, 4, true, true, NULL);
			break;
		}
		case CD2_SHAPE_BOX:
		{
			V2 corners[4];
			static const double signs[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
			for (int i = 0; i < 4; ++i)
			{
				cd2Vec local = cd2MakeVec((cdReal)signs[i][0] * s->box.halfExtents.x,
										  (cdReal)signs[i][1] * s->box.halfExtents.y);
				corners[i] = project2(cd2Add(s->box.center, cd2RotateVector(s->box.rotation, local)));
			}
			drawPolyline(canvas, corners, 4, true, true, NULL);
			break;
		}
		case CD2_SHAPE_POLYGON:
		{
			V2 corners[CD2_MAX_POLYGON_VERTICES], normals[CD2_MAX_POLYGON_VERTICES];
			int count = cdMinInt(cdMaxInt(s->polygon.count, 0), CD2_MAX_POLYGON_VERTICES);
			for (int i = 0; i < count; ++i)
			{
				corners[i] = project2(s->polygon.vertices[i]);
				normals[i] = project2(s->polygon.normals[i]);
			}
			if (s->polygon.radius > CD_R(0.0))
			{
				drawRoundedPolygon(canvas, corners, normals, count, (double)s->polygon.radius);
			}
			else
			{
				drawPolyline(canvas, corners, count, true, true, NULL);
			}
			break;
		}
		case CD2_SHAPE_SEGMENT:
			drawSegment(canvas, project2(s->segment.p1), project2(s->segment.p2), highlighted);
			break;
		case CD2_SHAPE_TYPE_COUNT:
			break;
	}
}

static void boxCorners3(const Canvas* canvas, cd3Vec center, cd3Vec halfExtents, cd3Quat rotation,
						V2 corners[8])
{
	for (int i = 0; i < 8; ++i)
	{
		cd3Vec local =
			cd3MakeVec((i & 1) ? halfExtents.x : -halfExtents.x, (i & 2) ? halfExtents.y : -halfExtents.y,
					   (i & 4) ? halfExtents.z : -halfExtents.z);
		corners[i] = project3(canvas, cd3Add(center, cd3RotateVector(rotation, local)));
	}
}

static void drawBox3(Canvas* canvas, V2 corners[8])
{
	V2 hullInput[8];
	memcpy(hullInput, corners, sizeof hullInput);
	drawHull(canvas, hullInput, 8);
	/* the 12 edges join corners whose indices differ in one bit */
	for (int i = 0; i < 8; ++i)
	{
		for (int bit = 1; bit < 8; bit <<= 1)
		{
			if ((i & bit) == 0)
			{
				drawLine(canvas, corners[i], corners[i | bit],
						 "stroke=\"" STROKE_COLOR "\" stroke-width=\"0.9\" stroke-opacity=\"0.8\"");
			}
		}
	}
}

typedef struct PlanePatch
{
	double center[3]; /* a point of the plane near the other shapes */
	double halfSize;
} PlanePatch;

static void drawPlane(Canvas* canvas, cd3Plane plane, const PlanePatch* patch)
{
	double n[3] = {(double)plane.normal.x, (double)plane.normal.y, (double)plane.normal.z};
	double lengthSquared = dot3(n, n);
	if (!(lengthSquared > 0.0))
	{
		return;
	}
	double c[3];
	double along = (dot3(n, patch->center) - (double)plane.offset) / lengthSquared;
	for (int i = 0; i < 3; ++i)
	{
		c[i] = patch->center[i] - along * n[i];
	}
	/* two tangents: cross with the axis least aligned with the normal */
	double axis[3] = {0.0, 0.0, 0.0};
	int smallest =
		fabs(n[0]) <= fabs(n[1]) ? (fabs(n[0]) <= fabs(n[2]) ? 0 : 2) : (fabs(n[1]) <= fabs(n[2]) ? 1 : 2);
	axis[smallest] = 1.0;
	double t1[3] = {n[1] * axis[2] - n[2] * axis[1], n[2] * axis[0] - n[0] * axis[2],
					n[0] * axis[1] - n[1] * axis[0]};
	double t1Length = sqrt(dot3(t1, t1));
	for (int i = 0; i < 3; ++i)
	{
		t1[i] /= t1Length;
	}
	double t2[3] = {n[1] * t1[2] - n[2] * t1[1], n[2] * t1[0] - n[0] * t1[2], n[0] * t1[1] - n[1] * t1[0]};
	double t2Length = sqrt(dot3(t2, t2));
	V2 corners[4];
	static const double signs[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
	double h = patch->halfSize;
	for (int k = 0; k < 4; ++k)
	{
		double p[3];
		for (int i = 0; i < 3; ++i)
		{
			p[i] = c[i] + h * (signs[k][0] * t1[i] + signs[k][1] * t2[i] / t2Length);
		}
		corners[k] = project(canvas, p);
	}
	drawPolyline(canvas, corners, 4, true, true, " stroke-dasharray=\"6 3\"");
	double tip[3];
	double nLength = sqrt(lengthSquared);
	for (int i = 0; i < 3; ++i)
	{
		tip[i] = c[i] + 0.35 * h * n[i] / nLength;
	}
	drawLine(canvas, project(canvas, c), project(canvas, tip),
			 "stroke=\"" STROKE_COLOR "\" stroke-width=\"1.5\" marker-end=\"url(#arrow)\"");
}

/* A convex hull: the faces turned toward the viewer filled (they tile the outline, so the fill
 * reads like the other shapes'), then every edge of the half-edge structure: solid when it
 * borders a visible face, dashed and faint when it is hidden behind the hull. */
static void drawHull3(Canvas* canvas, const cd3HullShape* shape, bool highlighted)
{
	const cd3Hull* hull = shape->hull;
	if (hull == NULL)
	{
		return;
	}
	bool* facing = calloc((size_t)cdMaxInt(hull->faceCount, 1), sizeof(bool));
	V2* projected = malloc((size_t)cdMaxInt(hull->vertexCount, 1) * sizeof(V2));
	V2* face = malloc((size_t)cdMaxInt(hull->edgeCount, 1) * sizeof(V2));
	if (facing == NULL || projected == NULL || face == NULL)
	{
		free(facing);
		free(projected);
		free(face);
		return;
	}
	for (int v = 0; v < hull->vertexCount; ++v)
	{
		projected[v] = project3(canvas, cd3TransformPoint(shape->transform, hull->vertices[v]));
	}
	const char* stroke = canvas->stroke;
	canvas->stroke = "stroke=\"none\"";
	for (int f = 0; f < hull->faceCount; ++f)
	{
		cd3Vec normal = cd3RotateVector(shape->transform.q, hull->planes[f].normal);
		double n[3] = {(double)normal.x, (double)normal.y, (double)normal.z};
		facing[f] = dot3(n, canvas->toward) > 0.0;
		if (!facing[f])
		{
			continue;
		}
		/* walk the face's loop; the bound keeps a broken loop from running forever */
		int count = 0;
		int e = hull->faceEdges[f];
		do
		{
			face[count++] = projected[hull->edges[e].origin];
			e = hull->edges[e].next;
		} while (e != hull->faceEdges[f] && count < hull->edgeCount);
		drawPolyline(canvas, face, count, true, true, NULL);
	}
	canvas->stroke = stroke;
	for (int e = 0; e < hull->edgeCount; ++e)
	{
		const cd3HullHalfEdge* edge = &hull->edges[e];
		if (edge->twin < e)
		{
			continue; /* each edge once */
		}
		const cd3HullHalfEdge* twin = &hull->edges[edge->twin];
		bool visible = facing[edge->face] || facing[twin->face];
		const char* attributes =
			visible
				? (highlighted ? "stroke=\"#b71c1c\" stroke-width=\"1.6\" stroke-linecap=\"round\""
							   : "stroke=\"" STROKE_COLOR "\" stroke-width=\"1.2\" stroke-linecap=\"round\"")
				: "stroke=\"" STROKE_COLOR "\" stroke-width=\"0.7\" stroke-opacity=\"0.45\" "
				  "stroke-dasharray=\"3 3\"";
		V2 a = projected[edge->origin], b = projected[twin->origin];
		drawLine(canvas, a, b, attributes);
		if (canvas->out != NULL)
		{
			includeShapePixels(canvas, toPixels(canvas, a), 0.0);
			includeShapePixels(canvas, toPixels(canvas, b), 0.0);
		}
	}
	free(facing);
	free(projected);
	free(face);
}

static void drawShape3(Canvas* canvas, const ToolShape* shape, bool highlighted, const PlanePatch* patch)
{
	if (shape->isPoint)
	{
		drawDot(canvas, project3(canvas, shape->point3), 4.0, highlighted ? "#d84315" : STROKE_COLOR);
		return;
	}
	const cd3Shape* s = &shape->shape3;
	switch (s->type)
	{
		case CD3_SHAPE_SPHERE:
		{
			V2 center = project3(canvas, s->sphere.center);
			double r = (double)s->sphere.radius;
			drawCircle(canvas, center, r);
			/* the equator, so that a sphere reads as a ball and not a disk */
			V2 equator[CIRCLE_SEGMENTS];
			for (int i = 0; i < CIRCLE_SEGMENTS; ++i)
			{
				double angle = 2.0 * PI_D * i / CIRCLE_SEGMENTS;
				double p[3] = {(double)s->sphere.center.x + r * cos(angle), (double)s->sphere.center.y,
							   (double)s->sphere.center.z + r * sin(angle)};
				equator[i] = project(canvas, p);
			}
			const char* stroke = canvas->stroke;
			canvas->stroke = "stroke=\"" STROKE_COLOR "\" stroke-width=\"0.7\" stroke-opacity=\"0.6\"";
			drawPolyline(canvas, equator, CIRCLE_SEGMENTS, true, false, NULL);
			canvas->stroke = stroke;
			break;
		}
		case CD3_SHAPE_CAPSULE:
			drawCapsule(canvas, project3(canvas, s->capsule.p1), project3(canvas, s->capsule.p2),
						(double)s->capsule.radius);
			break;
		case CD3_SHAPE_AABB:
		{
			V2 corners[8];
			cd3Box box = {cd3AabbCenter(s->aabb), cd3AabbHalfExtents(s->aabb), CD3_QUAT_IDENTITY};
			boxCorners3(canvas, box.center, box.halfExtents, box.rotation, corners);
			drawBox3(canvas, corners);
			break;
		}
		case CD3_SHAPE_BOX:
		{
			V2 corners[8];
			boxCorners3(canvas, s->box.center, s->box.halfExtents, s->box.rotation, corners);
			drawBox3(canvas, corners);
			break;
		}
		case CD3_SHAPE_TRIANGLE:
		{
			V2 corners[3] = {project3(canvas, s->triangle.a), project3(canvas, s->triangle.b),
							 project3(canvas, s->triangle.c)};
			drawPolyline(canvas, corners, 3, true, true, NULL);
			break;
		}
		case CD3_SHAPE_PLANE:
			drawPlane(canvas, s->plane, patch);
			break;
		case CD3_SHAPE_SEGMENT:
			drawSegment(canvas, project3(canvas, s->segment.p1), project3(canvas, s->segment.p2),
						highlighted);
			break;
		case CD3_SHAPE_HULL:
			drawHull3(canvas, &s->hull, highlighted);
			break;
		case CD3_SHAPE_TYPE_COUNT:
			break;
	}
}

static bool isPlane(const ToolScene* scene, int index)
{
	return scene->dimension == 3 && !scene->shapes[index].isPoint &&
		   scene->shapes[index].shape3.type == CD3_SHAPE_PLANE;
}

/* Where planes are drawn: around the bounded shapes (or the origin when there are none). */
static PlanePatch computePlanePatch(const ToolScene* scene)
{
	PlanePatch patch = {{0.0, 0.0, 0.0}, 2.0};
	bool any = false;
	double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
	for (int i = 0; i < scene->shapeCount && scene->dimension == 3; ++i)
	{
		if (isPlane(scene, i))
		{
			continue;
		}
		const ToolShape* shape = &scene->shapes[i];
		cd3Aabb box =
			shape->isPoint ? (cd3Aabb){shape->point3, shape->point3} : cd3ComputeShapeAabb(&shape->shape3);
		double bmin[3] = {(double)box.min.x, (double)box.min.y, (double)box.min.z};
		double bmax[3] = {(double)box.max.x, (double)box.max.y, (double)box.max.z};
		for (int k = 0; k < 3; ++k)
		{
			lo[k] = any ? fmin(lo[k], bmin[k]) : bmin[k];
			hi[k] = any ? fmax(hi[k], bmax[k]) : bmax[k];
		}
		any = true;
	}
	if (any)
	{
		double extent = 0.0;
		for (int k = 0; k < 3; ++k)
		{
			patch.center[k] = 0.5 * (lo[k] + hi[k]);
			extent = fmax(extent, 0.5 * (hi[k] - lo[k]));
		}
		patch.halfSize = extent > 0.0 ? 1.2 * extent : 1.0;
	}
	return patch;
}

/* ---- labels ------------------------------------------------------------------------------------ */

typedef struct LabelSet
{
	Rect placed[TOOL_MAX_SHAPES_PER_SCENE];
	int count;
} LabelSet;

static bool rectsOverlap(Rect a, Rect b)
{
	return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

static int utf8Length(const char* s)
{
	int n = 0;
	for (const unsigned char* p = (const unsigned char*)s; *p != 0; ++p)
	{
		n += (*p & 0xc0) != 0x80 ? 1 : 0;
	}
	return n;
}

/* Places the name above the shape (else below, else further down), avoiding earlier labels. */
static void placeLabel(FILE* out, LabelSet* labels, const char* name, Rect shape, bool isDot, Rect panel)
{
	double width = 7.0 * utf8Length(name) + 4.0, height = 14.0;
	double cx = 0.5 * (shape.x0 + shape.x1);
	Rect candidates[8];
	int count = 0;
	if (isDot)
	{
		candidates[count++] = (Rect){shape.x1 + 3.0, 0.5 * (shape.y0 + shape.y1) - 0.5 * height,
									 shape.x1 + 3.0 + width, 0.5 * (shape.y0 + shape.y1) + 0.5 * height};
	}
	candidates[count++] = (Rect){cx - 0.5 * width, shape.y0 - height - 2.0, cx + 0.5 * width, shape.y0 - 2.0};
	candidates[count++] = (Rect){cx - 0.5 * width, shape.y1 + 2.0, cx + 0.5 * width, shape.y1 + 2.0 + height};
	double cy = 0.5 * (shape.y0 + shape.y1);
	candidates[count++] = (Rect){cx - 0.5 * width, cy - 0.5 * height, cx + 0.5 * width, cy + 0.5 * height};
	Rect chosen = candidates[0];
	bool found = false;
	for (int step = 0; step < 6 && !found; ++step)
	{
		for (int i = 0; i < count && !found; ++i)
		{
			Rect r = candidates[i];
			r.y0 += step * height;
			r.y1 += step * height;
			/* keep inside the panel */
			double dx = fmax(0.0, panel.x0 - r.x0) - fmax(0.0, r.x1 - panel.x1);
			double dy = fmax(0.0, panel.y0 - r.y0) - fmax(0.0, r.y1 - panel.y1);
			r.x0 += dx;
			r.x1 += dx;
			r.y0 += dy;
			r.y1 += dy;
			bool isFree = true;
			for (int k = 0; k < labels->count && isFree; ++k)
			{
				isFree = !rectsOverlap(r, labels->placed[k]);
			}
			if (isFree)
			{
				chosen = r;
				found = true;
			}
		}
	}
	if (labels->count < TOOL_MAX_SHAPES_PER_SCENE)
	{
		labels->placed[labels->count++] = chosen;
	}
	double x = 0.5 * (chosen.x0 + chosen.x1), y = chosen.y1 - 3.0;
	/* drawn twice: a white halo under the dark text keeps it readable over any shape */
	for (int pass = 0; pass < 2; ++pass)
	{
		fprintf(out, "<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"middle\" %s>", finiteOr0(x), finiteOr0(y),
				pass == 0 ? "stroke=\"white\" stroke-width=\"3\" stroke-linejoin=\"round\" fill=\"white\""
						  : "fill=\"#111\"");
		writeEscaped(out, name);
		fputs("</text>\n", out);
	}
}

/* ---- panels ------------------------------------------------------------------------------------ */

typedef struct DrawOrder
{
	int index;
	double depth;
} DrawOrder;

static int compareDepth(const void* a, const void* b)
{
	const DrawOrder* p = a;
	const DrawOrder* q = b;
	if (p->depth != q->depth)
	{
		return p->depth < q->depth ? -1 : 1;
	}
	return p->index - q->index;
}

static void drawShape(Canvas* canvas, const ToolScene* scene, int index, const bool* highlighted,
					  const PlanePatch* patch)
{
	canvas->fill = highlighted[index] ? FILL_HIGHLIGHT : FILL_NORMAL;
	canvas->stroke = highlighted[index] ? STROKE_HIGHLIGHT : STROKE_NORMAL;
	if (isPlane(scene, index))
	{
		canvas->fill = highlighted[index] ? "fill=\"#ff7043\" fill-opacity=\"0.25\""
										  : "fill=\"#90a4ae\" fill-opacity=\"0.2\"";
	}
	if (scene->dimension == 2)
	{
		drawShape2(canvas, &scene->shapes[index], highlighted[index]);
	}
	else
	{
		drawShape3(canvas, &scene->shapes[index], highlighted[index], patch);
	}
}

static double shapeDepth(const Canvas* canvas, const ToolShape* shape)
{
	if (shape->isPoint)
	{
		double p[3] = {(double)shape->point3.x, (double)shape->point3.y, (double)shape->point3.z};
		return dot3(p, canvas->toward);
	}
	if (shape->shape3.type == CD3_SHAPE_PLANE)
	{
		return -HUGE_VAL;
	}
	cd3Vec c = cd3AabbCenter(cd3ComputeShapeAabb(&shape->shape3));
	double p[3] = {(double)c.x, (double)c.y, (double)c.z};
	return dot3(p, canvas->toward);
}

static void drawGizmo(FILE* out, const Canvas* canvas, double x, double y)
{
	static const char* const names[3] = {"x", "y", "z"};
	static const char* const colors[3] = {"#c62828", "#2e7d32", "#1565c0"};
	for (int axis = 0; axis < 3; ++axis)
	{
		double e[3] = {0.0, 0.0, 0.0};
		e[axis] = 1.0;
		double dx = 22.0 * dot3(e, canvas->right), dy = -22.0 * dot3(e, canvas->up);
		fprintf(out,
				"<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"%s\" stroke-width=\"1.5\"/>\n"
				"<text x=\"%.2f\" y=\"%.2f\" font-size=\"10\" fill=\"%s\" text-anchor=\"middle\">%s</text>\n",
				x, y, x + dx, y + dy, colors[axis], x + 1.3 * dx, y + 1.3 * dy + 3.5, colors[axis],
				names[axis]);
	}
}

static bool drawPanel(FILE* out, const ToolSceneResult* result, int panelIndex, double x0, double y0)
{
	const ToolScene* scene = result->scene;
	bool* highlighted = calloc((size_t)(scene->shapeCount > 0 ? scene->shapeCount : 1), sizeof(bool));
	DrawOrder* order = calloc((size_t)(scene->shapeCount > 0 ? scene->shapeCount : 1), sizeof(DrawOrder));
	LabelSet* labels = calloc(1, sizeof(LabelSet));
	if (highlighted == NULL || order == NULL || labels == NULL)
	{
		free(highlighted);
		free(order);
		free(labels);
		return false;
	}
	for (int p = 0; p < result->pairCount; ++p)
	{
		if (result->pairs[p].overlap)
		{
			highlighted[result->pairs[p].a] = true;
			highlighted[result->pairs[p].b] = true;
		}
	}

	Canvas canvas;
	memset(&canvas, 0, sizeof canvas);
	setupView(&canvas, scene->dimension);
	PlanePatch patch = computePlanePatch(scene);
	for (int i = 0; i < scene->shapeCount; ++i)
	{
		order[i].index = i;
		order[i].depth = scene->dimension == 3 ? shapeDepth(&canvas, &scene->shapes[i]) : 0.0;
	}
	qsort(order, (size_t)scene->shapeCount, sizeof(DrawOrder), compareDepth);

	/* measure */
	for (int i = 0; i < scene->shapeCount; ++i)
	{
		drawShape(&canvas, scene, i, highlighted, &patch);
	}
	if (!canvas.hasBounds)
	{
		canvas.minX = canvas.minY = -1.0;
		canvas.maxX = canvas.maxY = 1.0;
	}
	double width = canvas.maxX - canvas.minX, height = canvas.maxY - canvas.minY;
	double extent = fmax(fmax(width, height), 1e-30);
	if (width < 1e-6 * extent || height < 1e-6 * extent)
	{
		/* a flat scene (all on one line) still gets some room across */
		double pad = 0.25 * extent;
		canvas.minX -= width < 1e-6 * extent ? pad : 0.0;
		canvas.maxX += width < 1e-6 * extent ? pad : 0.0;
		canvas.minY -= height < 1e-6 * extent ? pad : 0.0;
		canvas.maxY += height < 1e-6 * extent ? pad : 0.0;
		width = canvas.maxX - canvas.minX;
		height = canvas.maxY - canvas.minY;
	}
	double areaX = x0 + PANEL_MARGIN, areaY = y0 + PANEL_TITLE + 22.0; /* room for labels above */
	double areaWidth = PANEL_WIDTH - 2.0 * PANEL_MARGIN,
		   areaHeight = PANEL_HEIGHT - PANEL_TITLE - 22.0 - PANEL_MARGIN;
	canvas.scale = fmin(areaWidth / width, areaHeight / height);
	canvas.originX = areaX + 0.5 * (areaWidth - width * canvas.scale);
	canvas.originY = areaY + areaHeight - 0.5 * (areaHeight - height * canvas.scale);

	/* frame and title */
	fprintf(out,
			"<g id=\"scene-%d\">\n<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" rx=\"6\" "
			"fill=\"#fbfbfb\" "
			"stroke=\"#b0bec5\"/>\n",
			panelIndex + 1, x0, y0, PANEL_WIDTH, PANEL_HEIGHT);
	fprintf(out, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"15\" font-weight=\"bold\" fill=\"#111\">",
			x0 + 12.0, y0 + 20.0);
	writeEscaped(out, scene->name);
	fprintf(out,
			" <tspan font-weight=\"normal\" fill=\"#555\">(%dD, %d shapes, %d of %d pairs "
			"overlap)</tspan></text>\n",
			scene->dimension, scene->shapeCount, result->overlapCount, result->pairCount);
	/* the overlapping pairs, as many as fit on one line */
	fprintf(out, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"11\" fill=\"#b71c1c\">", x0 + 12.0, y0 + 37.0);
	int written = 0, shown = 0;
	for (int p = 0; p < result->pairCount; ++p)
	{
		const ToolPairResult* pair = &result->pairs[p];
		if (!pair->overlap)
		{
			continue;
		}
		int length = utf8Length(scene->shapes[pair->a].name) + utf8Length(scene->shapes[pair->b].name) + 5;
		if (written + length > 80)
		{
			fprintf(out, "%s+%d more", shown > 0 ? ", " : "", result->overlapCount - shown);
			break;
		}
		fputs(shown == 0 ? "overlapping: " : ", ", out);
		writeEscaped(out, scene->shapes[pair->a].name);
		fputs(" \xE2\x80\x93 ", out); /* en dash */
		writeEscaped(out, scene->shapes[pair->b].name);
		written += length;
		++shown;
	}
	if (result->overlapCount == 0)
	{
		fputs("no overlapping pairs", out);
	}
	fputs("</text>\n", out);
	fprintf(
		out,
		"<clipPath id=\"clip-%d\"><rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\"/></clipPath>\n",
		panelIndex + 1, x0 + 1.0, y0 + PANEL_TITLE, PANEL_WIDTH - 2.0, PANEL_HEIGHT - PANEL_TITLE - 1.0);
	fprintf(
		out,
		"<g clip-path=\"url(#clip-%d)\" font-family=\"DejaVu Sans, Arial, sans-serif\" font-size=\"12\">\n",
		panelIndex + 1);

	/* shapes, back to front; remember each one's pixel bounds for its label */
	canvas.out = out;
	Rect* shapeRects = calloc((size_t)(scene->shapeCount > 0 ? scene->shapeCount : 1), sizeof(Rect));
	for (int k = 0; k < scene->shapeCount; ++k)
	{
		int i = order[k].index;
		canvas.hasShapeRect = false;
		drawShape(&canvas, scene, i, highlighted, &patch);
		/* A zero-size shape (radius 0, min == max, p1 == p2) would be invisible: mark it. */
		if (canvas.hasShapeRect && canvas.shapeRect.x1 - canvas.shapeRect.x0 < 3.0 &&
			canvas.shapeRect.y1 - canvas.shapeRect.y0 < 3.0 && !scene->shapes[i].isPoint)
		{
			V2 center = {0.5 * (canvas.shapeRect.x0 + canvas.shapeRect.x1),
						 0.5 * (canvas.shapeRect.y0 + canvas.shapeRect.y1)};
			fprintf(out, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"3\" fill=\"none\" %s/>\n", center.x, center.y,
					canvas.stroke);
			includeShapePixels(&canvas, center, 3.0);
		}
		if (shapeRects != NULL)
		{
			shapeRects[i] = canvas.hasShapeRect ? canvas.shapeRect : (Rect){x0, y0, x0, y0};
		}
	}
	/* closest points of separated pairs */
	if (result->pairCount <= MAX_CLOSEST_LINES)
	{
		for (int p = 0; p < result->pairCount; ++p)
		{
			const ToolPairResult* pair = &result->pairs[p];
			if (pair->overlap)
			{
				continue;
			}
			V2 a = project(&canvas, pair->pointA), b = project(&canvas, pair->pointB);
			drawLine(&canvas, a, b, "stroke=\"#607d8b\" stroke-width=\"0.9\" stroke-dasharray=\"4 3\"");
			V2 pa = toPixels(&canvas, a), pb = toPixels(&canvas, b);
			fprintf(out,
					"<circle cx=\"%.2f\" cy=\"%.2f\" r=\"1.8\" fill=\"#607d8b\"/><circle cx=\"%.2f\" "
					"cy=\"%.2f\" r=\"1.8\" "
					"fill=\"#607d8b\"/>\n",
					pa.x, pa.y, pb.x, pb.y);
		}
	}
	/* labels on top of everything */
	Rect panelRect = {x0 + 4.0, y0 + PANEL_TITLE + 2.0, x0 + PANEL_WIDTH - 4.0, y0 + PANEL_HEIGHT - 4.0};
	for (int i = 0; i < scene->shapeCount && shapeRects != NULL; ++i)
	{
		const ToolShape* shape = &scene->shapes[i];
		bool isDot = shape->isPoint;
		placeLabel(out, labels, shape->name, shapeRects[i], isDot, panelRect);
	}
	fputs("</g>\n", out);
	if (scene->dimension == 3)
	{
		drawGizmo(out, &canvas, x0 + 34.0, y0 + PANEL_HEIGHT - 30.0);
	}
	fputs("</g>\n", out);
	bool ok = shapeRects != NULL;
	free(shapeRects);
	free(highlighted);
	free(order);
	free(labels);
	return ok;
}

bool toolWriteSvg(const char* path, const ToolSceneResult* results, int sceneCount)
{
	FILE* out = fopen(path, "wb");
	if (out == NULL)
	{
		return false;
	}
	int columns = sceneCount > 1 ? 2 : 1;
	int rows = (sceneCount + columns - 1) / columns;
	double width = columns * PANEL_WIDTH + (columns + 1) * PANEL_GAP;
	double height = HEADER_HEIGHT + rows * (PANEL_HEIGHT + PANEL_GAP) + PANEL_GAP;
	fprintf(
		out,
		"<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\" "
		"font-family=\"DejaVu Sans, Arial, sans-serif\">\n",
		width, height, width, height);
	fputs("<defs><marker id=\"arrow\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"7\" "
		  "markerHeight=\"7\" "
		  "orient=\"auto\"><path d=\"M0,0 L10,5 L0,10 z\" fill=\"" STROKE_COLOR "\"/></marker></defs>\n",
		  out);
	fprintf(out, "<rect width=\"%.0f\" height=\"%.0f\" fill=\"white\"/>\n", width, height);
	fprintf(out,
			"<text x=\"%.1f\" y=\"26\" font-size=\"13\" fill=\"#333\">collide query: shapes of overlapping "
			"pairs are "
			"<tspan fill=\"#d84315\" font-weight=\"bold\">filled orange</tspan>; dashed lines join the "
			"closest points "
			"of separated pairs; y is up.</text>\n",
			PANEL_GAP);
	bool ok = true;
	for (int s = 0; s < sceneCount && ok; ++s)
	{
		double x0 = PANEL_GAP + (s % columns) * (PANEL_WIDTH + PANEL_GAP);
		double y0 = HEADER_HEIGHT + (s / columns) * (PANEL_HEIGHT + PANEL_GAP);
		ok = drawPanel(out, &results[s], s, x0, y0);
	}
	fputs("</svg>\n", out);
	if (ferror(out))
	{
		ok = false;
	}
	if (fclose(out) != 0)
	{
		ok = false;
	}
	return ok;
}
