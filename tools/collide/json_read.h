/* collide tool: the parts of reading a JSON file that the scene loader (scene_load.c) and the
 * world loader (world_load.c) share: the path to the value being read (so that a message can name
 * its line), the names of JSON types and of users' strings in messages, and the check of an
 * object's keys. */
#ifndef COLLIDE_TOOL_JSON_READ_H
#define COLLIDE_TOOL_JSON_READ_H

#include "json_locate.h"
#include "scene.h"

#include <cjson/cJSON.h>

#include <stdbool.h>
#include <stddef.h>

#define JSON_READ_MAX_PATH 8

/* The text being read and the path from its root to the value being read. Deeper paths than
 * JSON_READ_MAX_PATH are counted but not recorded (lines are then found for the recorded part). */
typedef struct JsonReader
{
	const char* text;
	size_t length;
	ToolError* error;
	JsonPathStep path[JSON_READ_MAX_PATH];
	int depth;
} JsonReader;

void jsonReaderPushKey(JsonReader* reader, const char* key);
void jsonReaderPushIndex(JsonReader* reader, int index);
void jsonReaderPop(JsonReader* reader);

/* The line of the current path plus `key` (when not NULL), or of the nearest enclosing value that
 * can be found; 0 when none can. */
int jsonReaderLine(const JsonReader* reader, const char* key);

/* "an object", "an array", "a string", ... for messages. */
const char* jsonTypeName(const cJSON* item);

/* A user's string, safe to quote in a one-line message: control characters and bytes outside
 * ASCII become '?', and it is cut after 40 characters. Returns buffer. */
const char* jsonPrintable(const char* text, char* buffer, size_t size);

/* Checks the keys of `object`: each must be "comment" or one of the allowed keys, and none may
 * repeat. The allowed keys are read from `keys`, one every `stride` bytes (a table of strings, or
 * of structs whose first member is the key), up to a NULL key. Returns NULL when every key is
 * fine, otherwise the first bad key, with the reason in reason[size]. */
const char* jsonFindBadKey(const cJSON* object, const void* keys, size_t stride, char* reason, size_t size);

#endif
