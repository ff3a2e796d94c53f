/* collide run: the world's debug drawing as SVG (plain text) and PNG (cairo, when built with
 * COLLIDE_TOOL_CAIRO). Both go through cd2World_Draw, so they show what any renderer given the
 * same callbacks would show. */
#include "frame.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#ifdef COLLIDE_TOOL_CAIRO
#include <cairo.h>
#endif

/* ---- the view ---------------------------------------------------------------------------------- */

typedef struct BoundsContext
{
	double minX, minY, maxX, maxY;
	bool any;
} BoundsContext;

/* ---- a drawing surface with two back ends ------------------------------------------------------ */

typedef struct Canvas
{
	const ToolView* view;
	double scale; /* pixels per world unit */
	FILE* svg;
#ifdef COLLIDE_TOOL_CAIRO
	cairo_t* cr;
#endif
} Canvas;

static double toX(const Canvas* c, double x)
{
	return (x - c->view->minX) * c->scale;
}

static double toY(const Canvas* c, double y)
{
	return (c->view->maxY - y) * c->scale;
}

static void grow(BoundsContext* b, double x, double y, double r)
{
	if (!b->any)
	{
		b->minX = x - r;
		b->maxX = x + r;
		b->minY = y - r;
		b->maxY = y + r;
		b->any = true;
		return;
	}
	b->minX = fmin(b->minX, x - r);
	b->maxX = fmax(b->maxX, x + r);
	b->minY = fmin(b->minY, y - r);
	b->maxY = fmax(b->maxY, y + r);
}

static void svgColor(char out[8], uint32_t color)
{
	snprintf(out, 8, "#%06x", (unsigned)(color & 0xffffffu));
}

#ifdef COLLIDE_TOOL_CAIRO
static void cairoColor(cairo_t* cr, uint32_t color, double alpha)
{
	cairo_set_source_rgba(cr, (double)((color >> 16) & 0xff) / 255.0, (double)((color >> 8) & 0xff) / 255.0,
						  (double)(color & 0xff) / 255.0, alpha);
}

/* Fills the current path lightly and strokes it in the full colour. */
static void cairoFillStroke(cairo_t* cr, uint32_t color)
{
	cairoColor(cr, color, 0.45);
	cairo_fill_preserve(cr);
	cairoColor(cr, color, 1.0);
	cairo_set_line_width(cr, 1.0);
	cairo_stroke(cr);
}
#endif

static void drawPolygon(const cd2Vec* vertices, int count, cdReal radius, uint32_t color, void* context)
{
	Canvas* c = context;
	double r = (double)radius * c->scale;
	if (c->svg != NULL)
	{
		char col[8];
		svgColor(col, color);
		fprintf(c->svg, "<polygon points=\"");
		for (int i = 0; i < count; ++i)
		{
			fprintf(c->svg, "%s%.2f,%.2f", i > 0 ? " " : "", toX(c, (double)vertices[i].x),
					toY(c, (double)vertices[i].y));
		}
		if (r > 0.0)
		{
			/* A rounded polygon: its core stroked as wide as the rounding, with round joins. */
			fprintf(c->svg,
					"\" fill=\"%s\" fill-opacity=\"0.45\" stroke=\"%s\" stroke-width=\"%.2f\" "
					"stroke-linejoin=\"round\" stroke-opacity=\"0.8\"/>\n",
					col, col, 2.0 * r);
		}
		else
		{
			fprintf(c->svg, "\" fill=\"%s\" fill-opacity=\"0.45\" stroke=\"%s\" stroke-width=\"1\"/>\n", col,
					col);
		}
		return;
	}
#ifdef COLLIDE_TOOL_CAIRO
	cairo_t* cr = c->cr;
	cairo_new_path(cr);
	for (int i = 0; i < count; ++i)
	{
		cairo_line_to(cr, toX(c, (double)vertices[i].x), toY(c, (double)vertices[i].y));
	}
	cairo_close_path(cr);
	if (r > 0.0)
	{
		cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
		cairoColor(cr, color, 0.45);
		cairo_fill_preserve(cr);
		cairo_set_line_width(cr, 2.0 * r);
		cairo_stroke(cr);
		cairo_set_line_join(cr, CAIRO_LINE_JOIN_MITER);
	}
	else
	{
		cairoFillStroke(cr, color);
	}
#endif
}

static void drawCircle(cd2Transform transform, cdReal radius, uint32_t color, void* context)
{
	Canvas* c = context;
	double x = (double)transform.p.x, y = (double)transform.p.y;
	double r = (double)radius * c->scale;
	/* A radius line shows the rotation. */
	double ex = x + (double)radius * (double)transform.q.c, ey = y + (double)radius * (double)transform.q.s;
	if (c->svg != NULL)
	{
		char col[8];
		svgColor(col, color);
		fprintf(c->svg,
				"<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%.2f\" fill=\"%s\" fill-opacity=\"0.45\" stroke=\"%s\" "
				"stroke-width=\"1\"/>\n<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"%s\" "
				"stroke-width=\"1\"/>\n",
				toX(c, x), toY(c, y), r, col, col, toX(c, x), toY(c, y), toX(c, ex), toY(c, ey), col);
		return;
	}
#ifdef COLLIDE_TOOL_CAIRO
	cairo_t* cr = c->cr;
	cairo_new_path(cr);
	cairo_arc(cr, toX(c, x), toY(c, y), r, 0.0, 2.0 * 3.14159265358979323846);
	cairoFillStroke(cr, color);
	cairo_move_to(cr, toX(c, x), toY(c, y));
	cairo_line_to(cr, toX(c, ex), toY(c, ey));
	cairo_stroke(cr);
#endif
}

static void drawCapsule(cd2Vec p1, cd2Vec p2, cdReal radius, uint32_t color, void* context)
{
	Canvas* c = context;
	double r = (double)radius * c->scale;
	if (c->svg != NULL)
	{
		char col[8];
		svgColor(col, color);
		fprintf(c->svg,
				"<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"%s\" stroke-opacity=\"0.6\" "
				"stroke-width=\"%.2f\" stroke-linecap=\"round\"/>\n",
				toX(c, (double)p1.x), toY(c, (double)p1.y), toX(c, (double)p2.x), toY(c, (double)p2.y), col,
				2.0 * r);
		return;
	}
#ifdef COLLIDE_TOOL_CAIRO
	cairo_t* cr = c->cr;
	cairo_new_path(cr);
	cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
	cairo_set_line_width(cr, 2.0 * r);
	cairoColor(cr, color, 0.6);
	cairo_move_to(cr, toX(c, (double)p1.x), toY(c, (double)p1.y));
	cairo_line_to(cr, toX(c, (double)p2.x), toY(c, (double)p2.y));
	cairo_stroke(cr);
	cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
#endif
}

static void drawSegment(cd2Vec p1, cd2Vec p2, uint32_t color, void* context)
{
	Canvas* c = context;
	if (c->svg != NULL)
	{
		char col[8];
		svgColor(col, color);
		fprintf(
			c->svg,
			"<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"%s\" stroke-width=\"1.5\"/>\n",
			toX(c, (double)p1.x), toY(c, (double)p1.y), toX(c, (double)p2.x), toY(c, (double)p2.y), col);
		return;
	}
#ifdef COLLIDE_TOOL_CAIRO
	cairo_t* cr = c->cr;
	cairo_new_path(cr);
	cairo_set_line_width(cr, 1.5);
	cairoColor(cr, color, 1.0);
	cairo_move_to(cr, toX(c, (double)p1.x), toY(c, (double)p1.y));
	cairo_line_to(cr, toX(c, (double)p2.x), toY(c, (double)p2.y));
	cairo_stroke(cr);
#endif
}

static void drawPoint(cd2Vec p, cdReal size, uint32_t color, void* context)
{
	Canvas* c = context;
	double r = fmax(1.0, 0.5 * (double)size);
	if (c->svg != NULL)
	{
		char col[8];
		svgColor(col, color);
		fprintf(c->svg, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%.2f\" fill=\"%s\"/>\n", toX(c, (double)p.x),
				toY(c, (double)p.y), r, col);
		return;
	}
#ifdef COLLIDE_TOOL_CAIRO
	cairo_t* cr = c->cr;
	cairo_new_path(cr);
	cairo_arc(cr, toX(c, (double)p.x), toY(c, (double)p.y), r, 0.0, 2.0 * 3.14159265358979323846);
	cairoColor(cr, color, 1.0);
	cairo_fill(cr);
#endif
}

static cd2DebugDraw makeDraw(Canvas* canvas, ToolDrawFlags flags)
{
	cd2DebugDraw draw = cd2DefaultDebugDraw();
	draw.drawPolygon = drawPolygon;
	draw.drawCircle = drawCircle;
	draw.drawCapsule = drawCapsule;
	draw.drawSegment = drawSegment;
	draw.drawPoint = drawPoint;
	draw.drawShapes = flags.shapes;
	draw.drawJoints = flags.joints;
	draw.drawContacts = flags.contacts;
	draw.drawAabbs = flags.aabbs;
	draw.context = canvas;
	return draw;
}

static ToolView finishView(double minX, double minY, double maxX, double maxY, int width, int height)
{
	ToolView view;
	double w = maxX - minX, h = maxY - minY;
	if (!(w > 0.0))
	{
		minX -= 1.0;
		maxX += 1.0;
		w = 2.0;
	}
	if (!(h > 0.0))
	{
		minY -= 1.0;
		maxY += 1.0;
		h = 2.0;
	}
	view.minX = minX;
	view.minY = minY;
	view.maxX = maxX;
	view.maxY = maxY;
	view.width = width;
	if (height > 0)
	{
		view.height = height;
	}
	else
	{
		double pixels = (double)width * h / w;
		view.height = pixels < 16.0 ? 16 : pixels > 4096.0 ? 4096 : (int)lround(pixels);
	}
	/* Keep the aspect: widen the rectangle along the axis with room to spare. */
	double sx = (double)view.width / w, sy = (double)view.height / h;
	if (sx > sy)
	{
		double extra = ((double)view.width / sy - w) * 0.5;
		view.minX -= extra;
		view.maxX += extra;
	}
	else
	{
		double extra = ((double)view.height / sx - h) * 0.5;
		view.minY -= extra;
		view.maxY += extra;
	}
	return view;
}

/* Grows b by every shape box of the bodies (only the non-static ones when movingOnly). */
static void growByBodies(BoundsContext* b, const cd2BodyId* bodies, int count, bool movingOnly)
{
	cd2ShapeId shapes[64];
	for (int i = 0; i < count; ++i)
	{
		if (!cd2Body_IsValid(bodies[i]) || (movingOnly && cd2Body_GetType(bodies[i]) == CD_STATIC_BODY))
		{
			continue;
		}
		int total = cd2Body_GetShapeCount(bodies[i]);
		int n = cd2Body_GetShapes(bodies[i], shapes, 64);
		for (int k = 0; k < n; ++k)
		{
			cd2Aabb box = cd2Shape_GetAabb(shapes[k]);
			grow(b, (double)box.min.x, (double)box.min.y, 0.0);
			grow(b, (double)box.max.x, (double)box.max.y, 0.0);
		}
		if (total > n)
		{
			/* A body with very many shapes (a long chain): its position stands for the rest. */
			cd2Vec p = cd2Body_GetPosition(bodies[i]);
			grow(b, (double)p.x, (double)p.y, 0.0);
		}
	}
}

/* The moving bodies' shapes (static ground often reaches far beyond the action), or every
 * shape when nothing moves; grown by 10% and 1 m on each side. */
static ToolView viewFromBodies(const cd2BodyId* bodies, int count, int width, int height)
{
	BoundsContext bounds = {0, 0, 0, 0, false};
	growByBodies(&bounds, bodies, count, true);
	if (!bounds.any)
	{
		growByBodies(&bounds, bodies, count, false);
	}
	if (!bounds.any)
	{
		return finishView(-10.0, -10.0, 10.0, 10.0, width, height);
	}
	double mx = 0.1 * (bounds.maxX - bounds.minX) + 1.0, my = 0.1 * (bounds.maxY - bounds.minY) + 1.0;
	return finishView(bounds.minX - mx, bounds.minY - my, bounds.maxX + mx, bounds.maxY + my, width, height);
}

ToolView toolMakeView(const cd2BodyId* bodies, int bodyCount, const double* viewMin, const double* viewMax,
					  int width, int height)
{
	if (viewMin != NULL && viewMax != NULL)
	{
		return finishView(viewMin[0], viewMin[1], viewMax[0], viewMax[1], width, height);
	}
	return viewFromBodies(bodies, bodyCount, width, height);
}

static double viewScale(const ToolView* view)
{
	return (double)view->width / (view->maxX - view->minX);
}

bool toolWriteFrameSvg(const char* path, cd2WorldId world, const ToolView* view, ToolDrawFlags flags,
					   const char* title)
{
	FILE* file = fopen(path, "w");
	if (file == NULL)
	{
		return false;
	}
	Canvas canvas;
	memset(&canvas, 0, sizeof canvas);
	canvas.view = view;
	canvas.scale = viewScale(view);
	canvas.svg = file;
	fprintf(file,
			"<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
			"<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" viewBox=\"0 0 %d %d\">\n"
			"<title>",
			view->width, view->height, view->width, view->height);
	for (const char* p = title; *p != 0; ++p)
	{
		/* The title is a file name: escape what XML needs. */
		if (*p == '<')
		{
			fputs("&lt;", file);
		}
		else if (*p == '>')
		{
			fputs("&gt;", file);
		}
		else if (*p == '&')
		{
			fputs("&amp;", file);
		}
		else
		{
			fputc((unsigned char)*p >= 0x20 ? *p : '?', file);
		}
	}
	fprintf(file, "</title>\n<rect width=\"100%%\" height=\"100%%\" fill=\"#202020\"/>\n");
	cd2DebugDraw draw = makeDraw(&canvas, flags);
	cd2World_Draw(world, &draw);
	fputs("</svg>\n", file);
	bool ok = !ferror(file);
	int savedErrno = errno;
	if (fclose(file) != 0)
	{
		ok = false;
	}
	else if (!ok)
	{
		errno = savedErrno;
	}
	return ok;
}

#ifdef COLLIDE_TOOL_CAIRO
int toolHasPng(void)
{
	return 1;
}

bool toolWriteFramePng(const char* path, cd2WorldId world, const ToolView* view, ToolDrawFlags flags,
					   char* reason, size_t reasonSize)
{
	cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, view->width, view->height);
	if (cairo_surface_status(surface) != CAIRO_STATUS_SUCCESS)
	{
		snprintf(reason, reasonSize, "cairo: %s", cairo_status_to_string(cairo_surface_status(surface)));
		cairo_surface_destroy(surface);
		return false;
	}
	cairo_t* cr = cairo_create(surface);
	cairo_set_source_rgb(cr, 0x20 / 255.0, 0x20 / 255.0, 0x20 / 255.0);
	cairo_paint(cr);
	Canvas canvas;
	memset(&canvas, 0, sizeof canvas);
	canvas.view = view;
	canvas.scale = viewScale(view);
	canvas.cr = cr;
	cd2DebugDraw draw = makeDraw(&canvas, flags);
	cd2World_Draw(world, &draw);
	cairo_destroy(cr);
	cairo_surface_flush(surface);
	cairo_status_t status = cairo_surface_write_to_png(surface, path);
	cairo_surface_destroy(surface);
	if (status != CAIRO_STATUS_SUCCESS)
	{
		snprintf(reason, reasonSize, "cannot write (%s)", cairo_status_to_string(status));
		return false;
	}
	return true;
}
#else
int toolHasPng(void)
{
	return 0;
}

bool toolWriteFramePng(const char* path, cd2WorldId world, const ToolView* view, ToolDrawFlags flags,
					   char* reason, size_t reasonSize)
{
	(void)path;
	(void)world;
	(void)view;
	(void)flags;
	snprintf(reason, reasonSize,
			 "this collide was built without cairo: no PNG output (install libcairo2-dev "
			 "and rebuild)");
	return false;
}
#endif
