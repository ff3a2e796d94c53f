/* collide tool: finds where a value sits in the text of a JSON file, so that messages about a
 * value that cJSON parsed (which keeps no positions) can name its line. */
#ifndef COLLIDE_TOOL_JSON_LOCATE_H
#define COLLIDE_TOOL_JSON_LOCATE_H

#include <stdbool.h>
#include <stddef.h>

/* One step of a path from the root value: a member of an object (key != NULL) or an element of
 * an array (key == NULL, index). */
typedef struct JsonPathStep
{
	const char* key;
	int index;
} JsonPathStep;

/* Offset of the first character of the value at `path` in text[0, length), or false when the
 * path does not lead anywhere (the text is scanned defensively: it never reads past length). */
bool jsonLocate(const char* text, size_t length, const JsonPathStep* path, int depth, size_t* offset);

/* 1-based line number of the byte at offset (lines end with '\n'). */
int jsonLineOfOffset(const char* text, size_t length, size_t offset);

/* What cJSON accepts but JSON (RFC 8259) or the tool does not: a number with leading zeros
 * ("0001") and the escape \u0000 in a string (cJSON ends the C string there, so "circle\u0000zz"
 * would read as "circle"). false with the offset and the reason of the first one. */
bool jsonCheckLexical(const char* text, size_t length, size_t* offset, const char** reason);

/* The deepest nesting of arrays and objects outside strings, and the offset of the first bracket
 * that goes deeper than `limit` (when the depth exceeds it). */
int jsonMaxDepth(const char* text, size_t length, int limit, size_t* firstTooDeep);

#endif
