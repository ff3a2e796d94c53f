/* collide run: draws the world (cd2World_Draw's debug-draw callbacks) into an SVG file or, with
 * cairo, a PNG file. */
#ifndef COLLIDE_TOOL_FRAME_H
#define COLLIDE_TOOL_FRAME_H

#include <collide/collide.h>

#include <stdbool.h>

/* What world rectangle maps to the picture (y up in the world, down in the picture). */
typedef struct ToolView
{
	double minX, minY, maxX, maxY;
	int width, height; /* pixels */
} ToolView;

/* The rectangle of the file's "view", or else the boxes of the moving bodies' shapes (of all
 * shapes when nothing moves) grown by 10% and 1 m; widened to the picture's aspect. The height
 * (0: from the rectangle's aspect for the given width, within [16, 4096]) and width in pixels. */
ToolView toolMakeView(const cd2BodyId* bodies, int bodyCount, const double* viewMin, const double* viewMax,
					  int width, int height);

/* The flags of cd2DebugDraw to use (shapes, joints, contacts, aabbs). */
typedef struct ToolDrawFlags
{
	bool shapes, joints, contacts, aabbs;
} ToolDrawFlags;

/* false with errno set when the file cannot be written. `title` goes into the SVG. */
bool toolWriteFrameSvg(const char* path, cd2WorldId world, const ToolView* view, ToolDrawFlags flags,
					   const char* title);

/* 1 when the tool was built with cairo (PNG frames), 0 otherwise. */
int toolHasPng(void);
/* false with a message in `reason` when the file cannot be written (or without cairo). */
bool toolWriteFramePng(const char* path, cd2WorldId world, const ToolView* view, ToolDrawFlags flags,
					   char* reason, size_t reasonSize);

#endif
