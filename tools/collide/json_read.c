/* collide tool: JSON reading helpers shared by the scene and the world loaders (json_read.h). */
#include "json_read.h"

#include <stdio.h>
#include <string.h>

void jsonReaderPushKey(JsonReader* reader, const char* key)
{
	if (reader->depth < JSON_READ_MAX_PATH)
	{
		reader->path[reader->depth].key = key;
		reader->path[reader->depth].index = 0;
	}
	++reader->depth;
}

void jsonReaderPushIndex(JsonReader* reader, int index)
{
	if (reader->depth < JSON_READ_MAX_PATH)
	{
		reader->path[reader->depth].key = NULL;
		reader->path[reader->depth].index = index;
	}
	++reader->depth;
}

void jsonReaderPop(JsonReader* reader)
{
	--reader->depth;
}

int jsonReaderLine(const JsonReader* reader, const char* key)
{
	JsonPathStep path[JSON_READ_MAX_PATH + 1];
	int depth = reader->depth < JSON_READ_MAX_PATH ? reader->depth : JSON_READ_MAX_PATH;
	memcpy(path, reader->path, (size_t)depth * sizeof(JsonPathStep));
	if (key != NULL)
	{
		path[depth].key = key;
		path[depth].index = 0;
		++depth;
	}
	for (; depth >= 0; --depth)
	{
		size_t offset;
		if (jsonLocate(reader->text, reader->length, path, depth, &offset))
		{
			return jsonLineOfOffset(reader->text, reader->length, offset);
		}
	}
	return 0;
}

const char* jsonTypeName(const cJSON* item)
{
	if (cJSON_IsObject(item))
	{
		return "an object";
	}
	if (cJSON_IsArray(item))
	{
		return "an array";
	}
	if (cJSON_IsString(item))
	{
		return "a string";
	}
	if (cJSON_IsNumber(item))
	{
		return "a number";
	}
	if (cJSON_IsBool(item))
	{
		return "a boolean";
	}
	if (cJSON_IsNull(item))
	{
		return "null";
	}
	return "an unknown value";
}

const char* jsonPrintable(const char* text, char* buffer, size_t size)
{
	size_t n = 0;
	const unsigned char* p = (const unsigned char*)text;
	for (; *p != 0 && n + 4 < size && n < 40; ++p)
	{
		buffer[n++] = (*p >= 0x20 && *p < 0x7f) ? (char)*p : '?';
	}
	if (*p != 0 && n + 4 < size)
	{
		memcpy(buffer + n, "...", 3);
		n += 3;
	}
	buffer[n] = 0;
	return buffer;
}

static const char* keyAt(const void* keys, size_t stride, int i)
{
	const char* key;
	memcpy(&key, (const char*)keys + (size_t)i * stride, sizeof key);
	return key;
}

const char* jsonFindBadKey(const cJSON* object, const void* keys, size_t stride, char* reason, size_t size)
{
	for (const cJSON* child = object->child; child != NULL; child = child->next)
	{
		const char* key = child->string != NULL ? child->string : "";
		bool known = strcmp(key, "comment") == 0;
		for (int i = 0; !known && keyAt(keys, stride, i) != NULL; ++i)
		{
			known = strcmp(key, keyAt(keys, stride, i)) == 0;
		}
		char shown[48];
		if (!known)
		{
			char list[600] = "";
			for (int i = 0; keyAt(keys, stride, i) != NULL; ++i)
			{
				size_t used = strlen(list);
				snprintf(list + used, sizeof list - used, "%s\"%s\"", i > 0 ? ", " : "",
						 keyAt(keys, stride, i));
			}
			snprintf(reason, size, "unknown field \"%s\" (expected %s)",
					 jsonPrintable(key, shown, sizeof shown), list);
			return key;
		}
		for (const cJSON* other = object->child; other != child; other = other->next)
		{
			if (other->string != NULL && strcmp(other->string, key) == 0)
			{
				snprintf(reason, size, "field \"%s\" appears twice", jsonPrintable(key, shown, sizeof shown));
				return key;
			}
		}
	}
	return NULL;
}
