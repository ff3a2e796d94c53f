/* collide tool: a physics scene file (the "world" section, docs/SCENES.md) loaded into a live
 * cd2 world, for `collide run`. */
#ifndef COLLIDE_TOOL_WORLD_SCENE_H
#define COLLIDE_TOOL_WORLD_SCENE_H

#include "scene.h"

/* Limits that keep a hostile file from exhausting memory or time. */
#define TOOL_MAX_WORLD_BODIES 100000
#define TOOL_MAX_WORLD_JOINTS 100000
#define TOOL_MAX_BODY_SHAPES 256
#define TOOL_MAX_BODY_CHAINS 64
#define TOOL_MAX_CHAIN_POINTS 100000
#define TOOL_MAX_SUB_STEPS 64

typedef struct ToolWorldBody
{
	char name[TOOL_MAX_NAME + 1]; /* "" when the file gives none */
	cd2BodyId id;
} ToolWorldBody;

typedef struct ToolWorld
{
	cd2WorldId world; /* null when not loaded */
	ToolWorldBody* bodies;
	int bodyCount, shapeCount, chainCount, jointCount;
	double timeStep; /* seconds, from the file or 1/60 */
	int subSteps;	 /* from the file or 4 */
	bool hasView;	 /* "view": the drawn rectangle; otherwise fit to the shapes */
	double viewMin[2], viewMax[2];
	int oneWayCount; /* shapes marked "oneWay" (platforms passable from below) */
} ToolWorld;

/* Reads a scene file with a "world" section, validates it and builds the world (through the
 * world API, whose refusals become errors at the offending object's line). On failure fills
 * *error, destroys whatever was built and leaves *world empty. */
/* The user data of shapes marked "oneWay": their address. */
extern int toolOneWayTag;

bool toolLoadWorld(const char* path, ToolWorld* world, ToolError* error);
void toolFreeWorld(ToolWorld* world);

/* Reads a JSON file with the checks of the scene loader (size, NUL bytes, nesting, syntax with
 * line numbers). On success *root (a cJSON*) and *text (the text, for line lookups) are owned
 * by the caller: cJSON_Delete and free. */
bool toolReadJsonFile(const char* path, char** text, size_t* length, void** root, ToolError* error);

#endif
