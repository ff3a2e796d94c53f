/* collide run: steps a physics scene file (world_load.c) and writes frames, a CSV and a summary. */
#ifndef COLLIDE_TOOL_RUN_H
#define COLLIDE_TOOL_RUN_H

/* argv[0] is "run". Returns the exit status (0, or 2 for any error). */
int toolRunMain(int argc, char** argv);

#endif
