/* collide tool: `collide broad`, the broadphase benchmark scene (scenes/broad_scene.h) run on the
 * chosen structures, with a table of the figures. */
#ifndef COLLIDE_TOOL_BROAD_H
#define COLLIDE_TOOL_BROAD_H

/* The usage line of `collide broad` (ends with a newline). */
extern const char* const toolBroadUsage;

/* argv[0] is "broad". Returns the exit status: 0 success, 1 structures disagree (pair, query or
 * ray counts, or a failed validation), 2 usage error or out of memory. */
int toolBroadMain(int argc, char** argv);

#endif
