/* collide tool: reads a physics scene file and builds its world (`collide run`).
 *
 *   { "world": { "gravity": [0, -10], "timeStep": 0.0166667, "subSteps": 4, ...,
 *                "bodies": [ BODY, ... ], "joints": [ JOINT, ... ] } }
 *
 * The full format is in docs/SCENES.md and docs/scene-schema.json. Validation is strict: unknown
 * or repeated fields, wrong types, NaN (not JSON anyway), numbers beyond the supported range,
 * unknown body names and counts out of range are errors, and so is every definition the world
 * API refuses (its refusal reason, caught through the assert hook, becomes the message). Each
 * error names the line of the offending value (json_locate.c walks the text along its path). */
#include "json_read.h"
#include "world_scene.h"

#include <cjson/cJSON.h>

#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct WLoader
{
	JsonReader json;   /* the text and the path being read */
	char context[160]; /* "body \"crate\"", "joint #3", ... prefixed to messages */
	ToolWorld* out;
	int* nameOrder; /* indices of the named bodies, sorted by name (for joints' look-ups) */
	int namedCount;
} WLoader;

/* ---- the world API's refusals ---------------------------------------------------------------- */

int toolOneWayTag;

static char s_refusal[256];

static bool recordRefusal(const char* condition, const char* fileName, int lineNumber)
{
	(void)fileName;
	(void)lineNumber;
	if (s_refusal[0] == 0)
	{
		snprintf(s_refusal, sizeof s_refusal, "%s", condition);
	}
	return false; /* go on: the API returns a null id */
}

/* ---- paths and messages ---------------------------------------------------------------------- */

#if defined(__GNUC__)
__attribute__((format(printf, 3, 4)))
#endif
static bool
failAt(WLoader* loader, const char* key, const char* format, ...)
{
	char reason[320];
	va_list args;
	va_start(args, format);
	vsnprintf(reason, sizeof reason, format, args);
	va_end(args);
	ToolError* error = loader->json.error;
	error->line = jsonReaderLine(&loader->json, key);
	if (loader->context[0] != 0)
	{
		snprintf(error->message, sizeof error->message, "%s: %s", loader->context, reason);
	}
	else
	{
		snprintf(error->message, sizeof error->message, "%s", reason);
	}
	return false;
}

/* ---- fields ---------------------------------------------------------------------------------- */

typedef enum FieldKind
{
	FIELD_REAL, /* any number in range */
	FIELD_BOOL,
	FIELD_VEC,	  /* [x, y] */
	FIELD_ANGLE,  /* radians; the key "...Degrees" variant is not offered: use "angle"/"degrees" */
	FIELD_SPECIAL /* read by the caller */
} FieldKind;

typedef struct Field
{
	const char* key;
	FieldKind kind;
	size_t offset;
} Field;

/* Rejects keys not in `fields` (which ends with a NULL key) and repeated keys; "comment" is
 * always allowed. */
static bool checkFields(WLoader* loader, const cJSON* object, const Field* fields)
{
	char reason[320];
	const char* key = jsonFindBadKey(object, fields, sizeof fields[0], reason, sizeof reason);
	return key == NULL || failAt(loader, key, "%s", reason);
}

static bool checkNumber(WLoader* loader, const char* key, double value)
{
	if (!isfinite(value))
	{
		return failAt(loader, key, "\"%s\" is not a finite number", key);
	}
	if (fabs(value) > TOOL_MAX_MAGNITUDE)
	{
		return failAt(loader, key, "\"%s\" = %g is outside the supported range [-%g, %g]", key, value,
					  TOOL_MAX_MAGNITUDE, TOOL_MAX_MAGNITUDE);
	}
	return true;
}

static bool numberItem(WLoader* loader, const cJSON* item, const char* key, double* out)
{
	if (!cJSON_IsNumber(item))
	{
		return failAt(loader, key, "\"%s\" must be a number, not %s", key, jsonTypeName(item));
	}
	if (!checkNumber(loader, key, item->valuedouble))
	{
		return false;
	}
	*out = item->valuedouble;
	return true;
}

/* [x, y] at item; `key` names it in messages and locates it (NULL: the current path). */
static bool vecItem(WLoader* loader, const cJSON* item, const char* key, const char* what, cd2Vec* out)
{
	double v[2];
	int n = 0;
	if (!cJSON_IsArray(item))
	{
		return failAt(loader, key, "%s must be an array of 2 numbers, not %s", what, jsonTypeName(item));
	}
	for (const cJSON* element = item->child; element != NULL; element = element->next, ++n)
	{
		if (n >= 2 || !cJSON_IsNumber(element))
		{
			return failAt(loader, key, "%s must be an array of 2 numbers", what);
		}
		if (!isfinite(element->valuedouble) || fabs(element->valuedouble) > TOOL_MAX_MAGNITUDE)
		{
			return failAt(loader, key, "%s has a number outside the supported range [-%g, %g]", what,
						  TOOL_MAX_MAGNITUDE, TOOL_MAX_MAGNITUDE);
		}
		v[n] = element->valuedouble;
	}
	if (n != 2)
	{
		return failAt(loader, key, "%s must be an array of 2 numbers, not %d", what, n);
	}
	*out = cd2MakeVec((cdReal)v[0], (cdReal)v[1]);
	return true;
}

/* Reads every field of the table present in `object` into the struct at `base`. */
static bool readFields(WLoader* loader, const cJSON* object, const Field* fields, void* base)
{
	for (int i = 0; fields[i].key != NULL; ++i)
	{
		const Field* field = &fields[i];
		if (field->kind == FIELD_SPECIAL)
		{
			continue;
		}
		const cJSON* item = cJSON_GetObjectItemCaseSensitive(object, field->key);
		if (item == NULL)
		{
			continue;
		}
		char* target = (char*)base + field->offset;
		if (field->kind == FIELD_BOOL)
		{
			if (!cJSON_IsBool(item))
			{
				return failAt(loader, field->key, "\"%s\" must be true or false, not %s", field->key,
							  jsonTypeName(item));
			}
			bool value = cJSON_IsTrue(item);
			memcpy(target, &value, sizeof value);
		}
		else if (field->kind == FIELD_VEC)
		{
			char what[64];
			snprintf(what, sizeof what, "\"%s\"", field->key);
			cd2Vec value;
			if (!vecItem(loader, item, field->key, what, &value))
			{
				return false;
			}
			memcpy(target, &value, sizeof value);
		}
		else
		{
			double number;
			if (!numberItem(loader, item, field->key, &number))
			{
				return false;
			}
			cdReal value = (cdReal)number;
			memcpy(target, &value, sizeof value);
		}
	}
	return true;
}

/* An optional integer field in [min, max]; *out unchanged when absent. */
static bool readInt(WLoader* loader, const cJSON* object, const char* key, int min, int max, int* out)
{
	const cJSON* item = cJSON_GetObjectItemCaseSensitive(object, key);
	if (item == NULL)
	{
		return true;
	}
	double value = 0.0;
	if (!numberItem(loader, item, key, &value))
	{
		return false;
	}
	if (value != floor(value) || value < (double)min || value > (double)max)
	{
		return failAt(loader, key, "\"%s\" must be a whole number from %d to %d, not %g", key, min, max,
					  value);
	}
	*out = (int)value;
	return true;
}

/* "angle" (radians) or "degrees", at most one; *radians unchanged when both are absent. */
static bool readAngle(WLoader* loader, const cJSON* object, const char* radiansKey, const char* degreesKey,
					  double* radians)
{
	const cJSON* r = cJSON_GetObjectItemCaseSensitive(object, radiansKey);
	const cJSON* d = cJSON_GetObjectItemCaseSensitive(object, degreesKey);
	if (r != NULL && d != NULL)
	{
		return failAt(loader, degreesKey, "give \"%s\" or \"%s\", not both", radiansKey, degreesKey);
	}
	double value = 0.0;
	if (r != NULL)
	{
		if (!numberItem(loader, r, radiansKey, &value))
		{
			return false;
		}
		*radians = value;
	}
	else if (d != NULL)
	{
		if (!numberItem(loader, d, degreesKey, &value))
		{
			return false;
		}
		*radians = value * (3.14159265358979323846 / 180.0);
	}
	return true;
}

/* An array field with 0..max elements (absent: 0). */
static bool readArray(WLoader* loader, const cJSON* object, const char* key, int min, int max,
					  const cJSON** array, int* count)
{
	*array = cJSON_GetObjectItemCaseSensitive(object, key);
	*count = 0;
	if (*array == NULL)
	{
		if (min > 0)
		{
			return failAt(loader, NULL, "missing field \"%s\"", key);
		}
		return true;
	}
	if (!cJSON_IsArray(*array))
	{
		return failAt(loader, key, "\"%s\" must be an array, not %s", key, jsonTypeName(*array));
	}
	int n = 0;
	for (const cJSON* item = (*array)->child; item != NULL; item = item->next)
	{
		if (++n > max)
		{
			return failAt(loader, key, "\"%s\" has more than %d elements", key, max);
		}
	}
	if (n < min)
	{
		return failAt(loader, key, "\"%s\" needs at least %d elements, not %d", key, min, n);
	}
	*count = n;
	return true;
}

/* ---- filters --------------------------------------------------------------------------------- */

/* A bit mask: a whole number 0..2^53 or a string of hexadecimal digits "0x..." (all 64 bits). */
static bool readBits(WLoader* loader, const cJSON* item, const char* key, uint64_t* out)
{
	if (cJSON_IsNumber(item))
	{
		double v = item->valuedouble;
		if (!(v >= 0.0) || v > 9007199254740992.0 || v != floor(v))
		{
			return failAt(loader, key, "\"%s\" must be a whole number from 0 to 2^53, or a \"0x...\" string",
						  key);
		}
		*out = (uint64_t)v;
		return true;
	}
	if (cJSON_IsString(item))
	{
		const char* s = item->valuestring;
		if ((s[0] != '0' || (s[1] != 'x' && s[1] != 'X')) || s[2] == 0 || strlen(s) > 18)
		{
			return failAt(loader, key, "\"%s\" must be \"0x\" and 1 to 16 hexadecimal digits", key);
		}
		uint64_t value = 0;
		for (const char* p = s + 2; *p != 0; ++p)
		{
			int digit;
			if (*p >= '0' && *p <= '9')
			{
				digit = *p - '0';
			}
			else if (*p >= 'a' && *p <= 'f')
			{
				digit = *p - 'a' + 10;
			}
			else if (*p >= 'A' && *p <= 'F')
			{
				digit = *p - 'A' + 10;
			}
			else
			{
				return failAt(loader, key, "\"%s\" must be \"0x\" and 1 to 16 hexadecimal digits", key);
			}
			value = (value << 4) | (uint64_t)digit;
		}
		*out = value;
		return true;
	}
	return failAt(loader, key, "\"%s\" must be a number or a \"0x...\" string, not %s", key,
				  jsonTypeName(item));
}

static bool readFilter(WLoader* loader, const cJSON* object, cd2Filter* filter)
{
	const cJSON* item = cJSON_GetObjectItemCaseSensitive(object, "filter");
	if (item == NULL)
	{
		return true;
	}
	if (!cJSON_IsObject(item))
	{
		return failAt(loader, "filter", "\"filter\" must be an object, not %s", jsonTypeName(item));
	}
	static const Field fields[] = {{"categoryBits", FIELD_SPECIAL, 0},
								   {"maskBits", FIELD_SPECIAL, 0},
								   {"groupIndex", FIELD_SPECIAL, 0},
								   {NULL, FIELD_SPECIAL, 0}};
	jsonReaderPushKey(&loader->json, "filter");
	bool ok = checkFields(loader, item, fields);
	const cJSON* bits = cJSON_GetObjectItemCaseSensitive(item, "categoryBits");
	if (ok && bits != NULL)
	{
		ok = readBits(loader, bits, "categoryBits", &filter->categoryBits);
	}
	bits = cJSON_GetObjectItemCaseSensitive(item, "maskBits");
	if (ok && bits != NULL)
	{
		ok = readBits(loader, bits, "maskBits", &filter->maskBits);
	}
	if (ok)
	{
		ok = readInt(loader, item, "groupIndex", -1000000000, 1000000000, &filter->groupIndex);
	}
	jsonReaderPop(&loader->json);
	return ok;
}

/* ---- shapes ---------------------------------------------------------------------------------- */

static const Field s_shapeDefFields[] = {
	{"density", FIELD_REAL, offsetof(cd2ShapeDef, density)},
	{"friction", FIELD_REAL, offsetof(cd2ShapeDef, friction)},
	{"restitution", FIELD_REAL, offsetof(cd2ShapeDef, restitution)},
	{"rollingResistance", FIELD_REAL, offsetof(cd2ShapeDef, rollingResistance)},
	{"tangentSpeed", FIELD_REAL, offsetof(cd2ShapeDef, tangentSpeed)},
	{"sensor", FIELD_BOOL, offsetof(cd2ShapeDef, isSensor)},
	{"sensorEvents", FIELD_BOOL, offsetof(cd2ShapeDef, enableSensorEvents)},
	{"contactEvents", FIELD_BOOL, offsetof(cd2ShapeDef, enableContactEvents)},
	{"hitEvents", FIELD_BOOL, offsetof(cd2ShapeDef, enableHitEvents)},
	{"oneWay", FIELD_SPECIAL, 0},
	{"filter", FIELD_SPECIAL, 0},
	{"type", FIELD_SPECIAL, 0},
	{NULL, FIELD_SPECIAL, 0},
};
/* Without the terminator. */
#define SHAPE_DEF_FIELD_COUNT (sizeof s_shapeDefFields / sizeof s_shapeDefFields[0] - 1)

/* The geometry keys of each shape type (besides the common keys above). */
typedef struct ShapeType
{
	const char* name;
	const char* keys[6];
} ShapeType;

static const ShapeType s_shapeTypes[] = {
	{"circle", {"center", "radius", NULL}},
	{"capsule", {"p1", "p2", "radius", NULL}},
	{"box", {"center", "halfExtents", "angle", "degrees", "radius", NULL}},
	{"polygon", {"points", "radius", NULL}},
	{"segment", {"p1", "p2", NULL}},
};

static bool readRequiredVec(WLoader* loader, const cJSON* object, const char* key, cd2Vec* out)
{
	const cJSON* item = cJSON_GetObjectItemCaseSensitive(object, key);
	if (item == NULL)
	{
		return failAt(loader, NULL, "missing field \"%s\"", key);
	}
	char what[64];
	snprintf(what, sizeof what, "\"%s\"", key);
	return vecItem(loader, item, key, what, out);
}

static bool readOptionalVec(WLoader* loader, const cJSON* object, const char* key, cd2Vec* out)
{
	const cJSON* item = cJSON_GetObjectItemCaseSensitive(object, key);
	if (item == NULL)
	{
		return true;
	}
	char what[64];
	snprintf(what, sizeof what, "\"%s\"", key);
	return vecItem(loader, item, key, what, out);
}

static bool readRequiredNumber(WLoader* loader, const cJSON* object, const char* key, double* out)
{
	const cJSON* item = cJSON_GetObjectItemCaseSensitive(object, key);
	if (item == NULL)
	{
		return failAt(loader, NULL, "missing field \"%s\"", key);
	}
	return numberItem(loader, item, key, out);
}

static bool readOptionalNumber(WLoader* loader, const cJSON* object, const char* key, double* out)
{
	const cJSON* item = cJSON_GetObjectItemCaseSensitive(object, key);
	return item == NULL || numberItem(loader, item, key, out);
}

static const char* resultReason(cdResult result)
{
	switch (result)
	{
		case CD_ERROR_NOT_FINITE:
			return "a coordinate is not finite";
		case CD_ERROR_TOO_MANY_POINTS:
			return "too many points";
		case CD_ERROR_DEGENERATE:
			return "degenerate (fewer than 3 distinct points, collinear points, or zero area)";
		case CD_ERROR_NEGATIVE_SIZE:
			return "negative size";
		default:
			return "invalid";
	}
}

/* The shape at the current path (an element of "shapes"), on body `body`. */
static bool readShape(WLoader* loader, const cJSON* object, cd2BodyId body)
{
	if (!cJSON_IsObject(object))
	{
		return failAt(loader, NULL, "a shape must be an object, not %s", jsonTypeName(object));
	}
	const cJSON* typeItem = cJSON_GetObjectItemCaseSensitive(object, "type");
	if (typeItem == NULL)
	{
		return failAt(loader, NULL, "missing field \"type\"");
	}
	if (!cJSON_IsString(typeItem))
	{
		return failAt(loader, "type", "\"type\" must be a string, not %s", jsonTypeName(typeItem));
	}
	const ShapeType* type = NULL;
	for (size_t i = 0; i < sizeof s_shapeTypes / sizeof s_shapeTypes[0]; ++i)
	{
		if (strcmp(typeItem->valuestring, s_shapeTypes[i].name) == 0)
		{
			type = &s_shapeTypes[i];
		}
	}
	if (type == NULL)
	{
		char shown[48];
		return failAt(loader, "type",
					  "unknown shape type \"%s\" (expected circle, capsule, box, polygon or segment)",
					  jsonPrintable(typeItem->valuestring, shown, sizeof shown));
	}
	Field fields[SHAPE_DEF_FIELD_COUNT + 7];
	size_t fieldCount = 0;
	for (size_t i = 0; i < SHAPE_DEF_FIELD_COUNT; ++i)
	{
		fields[fieldCount++] = s_shapeDefFields[i];
	}
	for (int i = 0; type->keys[i] != NULL; ++i)
	{
		fields[fieldCount++] = (Field){type->keys[i], FIELD_SPECIAL, 0};
	}
	fields[fieldCount] = (Field){NULL, FIELD_SPECIAL, 0};
	if (!checkFields(loader, object, fields))
	{
		return false;
	}
	cd2ShapeDef def = cd2DefaultShapeDef();
	if (!readFields(loader, object, s_shapeDefFields, &def) || !readFilter(loader, object, &def.filter))
	{
		return false;
	}
	const cJSON* oneWay = cJSON_GetObjectItemCaseSensitive(object, "oneWay");
	if (oneWay != NULL)
	{
		if (!cJSON_IsBool(oneWay))
		{
			return failAt(loader, "oneWay", "\"oneWay\" must be true or false, not %s", jsonTypeName(oneWay));
		}
		if (cJSON_IsTrue(oneWay))
		{
			/* The tool's pre-solve callback lets bodies through from below (tools/run). */
			def.enablePreSolveEvents = true;
			def.userData = &toolOneWayTag;
			loader->out->oneWayCount += 1;
		}
	}

	s_refusal[0] = 0;
	cd2ShapeId id = CD2_NULL_SHAPE_ID;
	const char* name = type->name;
	double radius = 0.0;
	if (strcmp(name, "circle") == 0)
	{
		cd2Circle circle = {CD2_VEC_ZERO, 0};
		if (!readOptionalVec(loader, object, "center", &circle.center) ||
			!readRequiredNumber(loader, object, "radius", &radius))
		{
			return false;
		}
		circle.radius = (cdReal)radius;
		id = cd2CreateCircleShape(body, &def, &circle);
	}
	else if (strcmp(name, "capsule") == 0)
	{
		cd2Capsule capsule;
		if (!readRequiredVec(loader, object, "p1", &capsule.p1) ||
			!readRequiredVec(loader, object, "p2", &capsule.p2) ||
			!readRequiredNumber(loader, object, "radius", &radius))
		{
			return false;
		}
		capsule.radius = (cdReal)radius;
		id = cd2CreateCapsuleShape(body, &def, &capsule);
	}
	else if (strcmp(name, "segment") == 0)
	{
		cd2Segment segment;
		if (!readRequiredVec(loader, object, "p1", &segment.p1) ||
			!readRequiredVec(loader, object, "p2", &segment.p2))
		{
			return false;
		}
		id = cd2CreateSegmentShape(body, &def, &segment);
	}
	else
	{
		cd2Polygon polygon;
		cdResult result;
		if (!readOptionalNumber(loader, object, "radius", &radius))
		{
			return false;
		}
		if (strcmp(name, "box") == 0)
		{
			cd2Box box;
			box.center = CD2_VEC_ZERO;
			double angle = 0.0;
			if (!readOptionalVec(loader, object, "center", &box.center) ||
				!readRequiredVec(loader, object, "halfExtents", &box.halfExtents) ||
				!readAngle(loader, object, "angle", "degrees", &angle))
			{
				return false;
			}
			box.rotation = cd2MakeRot((cdReal)angle);
			result = cd2MakeRoundedBoxPolygon(box, (cdReal)radius, &polygon);
		}
		else
		{
			const cJSON* points;
			int count;
			if (!readArray(loader, object, "points", 3, CD2_MAX_POLYGON_VERTICES, &points, &count))
			{
				return false;
			}
			cd2Vec vertices[CD2_MAX_POLYGON_VERTICES];
			jsonReaderPushKey(&loader->json, "points");
			int index = 0;
			for (const cJSON* point = points->child; point != NULL; point = point->next, ++index)
			{
				char what[48];
				snprintf(what, sizeof what, "point #%d", index + 1);
				jsonReaderPushIndex(&loader->json, index);
				bool ok = vecItem(loader, point, NULL, what, &vertices[index]);
				jsonReaderPop(&loader->json);
				if (!ok)
				{
					jsonReaderPop(&loader->json);
					return false;
				}
			}
			jsonReaderPop(&loader->json);
			result = cd2MakeRoundedPolygon(vertices, count, (cdReal)radius, &polygon);
		}
		if (result != CD_OK)
		{
			return failAt(loader, NULL, "invalid %s: %s", name, resultReason(result));
		}
		id = cd2CreatePolygonShape(body, &def, &polygon);
	}
	if (cd2IsNullShapeId(id))
	{
		return failAt(loader, NULL, "refused by the world: %s",
					  s_refusal[0] != 0 ? s_refusal : "invalid shape");
	}
	loader->out->shapeCount += 1;
	return true;
}

static bool readChain(WLoader* loader, const cJSON* object, cd2BodyId body)
{
	if (!cJSON_IsObject(object))
	{
		return failAt(loader, NULL, "a chain must be an object, not %s", jsonTypeName(object));
	}
	static const Field fields[] = {{"points", FIELD_SPECIAL, 0},
								   {"loop", FIELD_BOOL, offsetof(cd2ChainDef, isLoop)},
								   {"friction", FIELD_REAL, offsetof(cd2ChainDef, friction)},
								   {"restitution", FIELD_REAL, offsetof(cd2ChainDef, restitution)},
								   {"sensorEvents", FIELD_BOOL, offsetof(cd2ChainDef, enableSensorEvents)},
								   {"filter", FIELD_SPECIAL, 0},
								   {NULL, FIELD_SPECIAL, 0}};
	cd2ChainDef def = cd2DefaultChainDef();
	if (!checkFields(loader, object, fields) || !readFields(loader, object, fields, &def) ||
		!readFilter(loader, object, &def.filter))
	{
		return false;
	}
	const cJSON* points;
	int count;
	if (!readArray(loader, object, "points", 2, TOOL_MAX_CHAIN_POINTS, &points, &count))
	{
		return false;
	}
	cd2Vec* vertices = malloc((size_t)count * sizeof(cd2Vec));
	if (vertices == NULL)
	{
		return failAt(loader, NULL, "out of memory");
	}
	jsonReaderPushKey(&loader->json, "points");
	int index = 0;
	for (const cJSON* point = points->child; point != NULL; point = point->next, ++index)
	{
		char what[48];
		snprintf(what, sizeof what, "point #%d", index + 1);
		jsonReaderPushIndex(&loader->json, index);
		bool ok = vecItem(loader, point, NULL, what, &vertices[index]);
		jsonReaderPop(&loader->json);
		if (!ok)
		{
			jsonReaderPop(&loader->json);
			free(vertices);
			return false;
		}
	}
	jsonReaderPop(&loader->json);
	def.points = vertices;
	def.count = count;
	s_refusal[0] = 0;
	cd2ChainId id = cd2CreateChainShape(body, &def);
	free(vertices);
	if (id.index1 == 0)
	{
		return failAt(loader, "points", "refused by the world: %s",
					  s_refusal[0] != 0 ? s_refusal : "invalid chain");
	}
	loader->out->chainCount += 1;
	loader->out->shapeCount += cd2ChainShape_GetSegmentCount(id);
	return true;
}

/* ---- bodies ---------------------------------------------------------------------------------- */

static bool readName(WLoader* loader, const cJSON* object, char out[TOOL_MAX_NAME + 1])
{
	out[0] = 0;
	const cJSON* item = cJSON_GetObjectItemCaseSensitive(object, "name");
	if (item == NULL)
	{
		return true;
	}
	if (!cJSON_IsString(item))
	{
		return failAt(loader, "name", "\"name\" must be a string, not %s", jsonTypeName(item));
	}
	size_t length = strlen(item->valuestring);
	if (length == 0 || length > TOOL_MAX_NAME)
	{
		return failAt(loader, "name", "\"name\" must have 1 to %d bytes", TOOL_MAX_NAME);
	}
	for (const unsigned char* p = (const unsigned char*)item->valuestring; *p != 0; ++p)
	{
		/* Names go into CSV headers and messages: printable ASCII without quotes and commas. */
		if (*p < 0x20 || *p >= 0x7f || *p == '"' || *p == ',' || *p == '\\')
		{
			return failAt(loader, "name", "\"name\" may hold printable ASCII except '\"', ',' and '\\'");
		}
	}
	memcpy(out, item->valuestring, length + 1);
	return true;
}

static const Field s_bodyFields[] = {
	{"name", FIELD_SPECIAL, 0},
	{"type", FIELD_SPECIAL, 0},
	{"position", FIELD_VEC, offsetof(cd2BodyDef, position)},
	{"angle", FIELD_SPECIAL, 0},
	{"degrees", FIELD_SPECIAL, 0},
	{"linearVelocity", FIELD_VEC, offsetof(cd2BodyDef, linearVelocity)},
	{"angularVelocity", FIELD_REAL, offsetof(cd2BodyDef, angularVelocity)},
	{"linearDamping", FIELD_REAL, offsetof(cd2BodyDef, linearDamping)},
	{"angularDamping", FIELD_REAL, offsetof(cd2BodyDef, angularDamping)},
	{"gravityScale", FIELD_REAL, offsetof(cd2BodyDef, gravityScale)},
	{"sleepThreshold", FIELD_REAL, offsetof(cd2BodyDef, sleepThreshold)},
	{"enableSleep", FIELD_BOOL, offsetof(cd2BodyDef, enableSleep)},
	{"awake", FIELD_BOOL, offsetof(cd2BodyDef, isAwake)},
	{"fixedRotation", FIELD_BOOL, offsetof(cd2BodyDef, fixedRotation)},
	{"bullet", FIELD_BOOL, offsetof(cd2BodyDef, isBullet)},
	{"enabled", FIELD_BOOL, offsetof(cd2BodyDef, isEnabled)},
	{"shapes", FIELD_SPECIAL, 0},
	{"chains", FIELD_SPECIAL, 0},
	{NULL, FIELD_SPECIAL, 0},
};

static bool readBody(WLoader* loader, const cJSON* object, int index)
{
	snprintf(loader->context, sizeof loader->context, "body #%d", index + 1);
	if (!cJSON_IsObject(object))
	{
		return failAt(loader, NULL, "a body must be an object, not %s", jsonTypeName(object));
	}
	ToolWorldBody* entry = &loader->out->bodies[index];
	if (!readName(loader, object, entry->name))
	{
		return false;
	}
	if (entry->name[0] != 0)
	{
		snprintf(loader->context, sizeof loader->context, "body \"%s\"", entry->name);
	}
	if (!checkFields(loader, object, s_bodyFields))
	{
		return false;
	}
	cd2BodyDef def = cd2DefaultBodyDef();
	const cJSON* type = cJSON_GetObjectItemCaseSensitive(object, "type");
	if (type == NULL)
	{
		return failAt(loader, NULL, "missing field \"type\" (static, kinematic or dynamic)");
	}
	if (!cJSON_IsString(type))
	{
		return failAt(loader, "type", "\"type\" must be a string, not %s", jsonTypeName(type));
	}
	if (strcmp(type->valuestring, "static") == 0)
	{
		def.type = CD_STATIC_BODY;
	}
	else if (strcmp(type->valuestring, "kinematic") == 0)
	{
		def.type = CD_KINEMATIC_BODY;
	}
	else if (strcmp(type->valuestring, "dynamic") == 0)
	{
		def.type = CD_DYNAMIC_BODY;
	}
	else
	{
		char shown[48];
		return failAt(loader, "type", "unknown body type \"%s\" (expected static, kinematic or dynamic)",
					  jsonPrintable(type->valuestring, shown, sizeof shown));
	}
	double angle = 0.0;
	if (!readFields(loader, object, s_bodyFields, &def) ||
		!readAngle(loader, object, "angle", "degrees", &angle))
	{
		return false;
	}
	def.rotation = cd2MakeRot((cdReal)angle);
	const cJSON* shapes;
	const cJSON* chains;
	int shapeCount, chainCount;
	if (!readArray(loader, object, "shapes", 0, TOOL_MAX_BODY_SHAPES, &shapes, &shapeCount) ||
		!readArray(loader, object, "chains", 0, TOOL_MAX_BODY_CHAINS, &chains, &chainCount))
	{
		return false;
	}
	s_refusal[0] = 0;
	cd2BodyId id = cd2CreateBody(loader->out->world, &def);
	if (cd2IsNullBodyId(id))
	{
		return failAt(loader, NULL, "refused by the world: %s",
					  s_refusal[0] != 0 ? s_refusal : "invalid body");
	}
	entry->id = id;
	loader->out->bodyCount = index + 1;
	char bodyContext[sizeof loader->context];
	memcpy(bodyContext, loader->context, sizeof bodyContext);
	const char* const lists[2] = {"shapes", "chains"};
	const cJSON* const arrays[2] = {shapes, chains};
	for (int list = 0; list < 2; ++list)
	{
		if (arrays[list] == NULL)
		{
			continue;
		}
		jsonReaderPushKey(&loader->json, lists[list]);
		int k = 0;
		for (const cJSON* item = arrays[list]->child; item != NULL; item = item->next, ++k)
		{
			if (snprintf(loader->context, sizeof loader->context, "%s, %s #%d", bodyContext,
						 list == 0 ? "shape" : "chain", k + 1) >= (int)sizeof loader->context)
			{
				/* A cut context still names the body; the message stays readable. */
			}
			jsonReaderPushIndex(&loader->json, k);
			bool ok = list == 0 ? readShape(loader, item, id) : readChain(loader, item, id);
			jsonReaderPop(&loader->json);
			if (!ok)
			{
				jsonReaderPop(&loader->json);
				return false;
			}
		}
		jsonReaderPop(&loader->json);
	}
	return true;
}

/* ---- joints ---------------------------------------------------------------------------------- */

#define JOINT_COMMON_FIELDS                                                                                  \
	{"type", FIELD_SPECIAL, 0}, {"name", FIELD_SPECIAL, 0}, {"bodyA", FIELD_SPECIAL, 0},                     \
		{"bodyB", FIELD_SPECIAL, 0},                                                                         \
	{                                                                                                        \
		"anchor", FIELD_SPECIAL, 0                                                                           \
	}

static const Field s_distanceFields[] = {
	JOINT_COMMON_FIELDS,
	{"anchorB", FIELD_SPECIAL, 0},
	{"localAnchorA", FIELD_VEC, offsetof(cd2DistanceJointDef, localAnchorA)},
	{"localAnchorB", FIELD_VEC, offsetof(cd2DistanceJointDef, localAnchorB)},
	{"length", FIELD_REAL, offsetof(cd2DistanceJointDef, length)},
	{"enableSpring", FIELD_BOOL, offsetof(cd2DistanceJointDef, enableSpring)},
	{"hertz", FIELD_REAL, offsetof(cd2DistanceJointDef, hertz)},
	{"dampingRatio", FIELD_REAL, offsetof(cd2DistanceJointDef, dampingRatio)},
	{"enableLimit", FIELD_BOOL, offsetof(cd2DistanceJointDef, enableLimit)},
	{"minLength", FIELD_REAL, offsetof(cd2DistanceJointDef, minLength)},
	{"maxLength", FIELD_REAL, offsetof(cd2DistanceJointDef, maxLength)},
	{"enableMotor", FIELD_BOOL, offsetof(cd2DistanceJointDef, enableMotor)},
	{"maxMotorForce", FIELD_REAL, offsetof(cd2DistanceJointDef, maxMotorForce)},
	{"motorSpeed", FIELD_REAL, offsetof(cd2DistanceJointDef, motorSpeed)},
	{"collideConnected", FIELD_BOOL, offsetof(cd2DistanceJointDef, collideConnected)},
	{"forceThreshold", FIELD_REAL, offsetof(cd2DistanceJointDef, forceThreshold)},
	{"torqueThreshold", FIELD_REAL, offsetof(cd2DistanceJointDef, torqueThreshold)},
	{"constraintHertz", FIELD_REAL, offsetof(cd2DistanceJointDef, constraintHertz)},
	{"constraintDampingRatio", FIELD_REAL, offsetof(cd2DistanceJointDef, constraintDampingRatio)},
	{NULL, FIELD_SPECIAL, 0},
};

static const Field s_filterFields[] = {
	JOINT_COMMON_FIELDS,
	{NULL, FIELD_SPECIAL, 0},
};

static const Field s_motorFields[] = {
	JOINT_COMMON_FIELDS,
	{"linearOffset", FIELD_VEC, offsetof(cd2MotorJointDef, linearOffset)},
	{"angularOffset", FIELD_REAL, offsetof(cd2MotorJointDef, angularOffset)},
	{"maxForce", FIELD_REAL, offsetof(cd2MotorJointDef, maxForce)},
	{"maxTorque", FIELD_REAL, offsetof(cd2MotorJointDef, maxTorque)},
	{"correctionFactor", FIELD_REAL, offsetof(cd2MotorJointDef, correctionFactor)},
	{"collideConnected", FIELD_BOOL, offsetof(cd2MotorJointDef, collideConnected)},
	{"forceThreshold", FIELD_REAL, offsetof(cd2MotorJointDef, forceThreshold)},
	{"torqueThreshold", FIELD_REAL, offsetof(cd2MotorJointDef, torqueThreshold)},
	{NULL, FIELD_SPECIAL, 0},
};

static const Field s_mouseFields[] = {
	JOINT_COMMON_FIELDS,
	{"target", FIELD_VEC, offsetof(cd2MouseJointDef, target)},
	{"hertz", FIELD_REAL, offsetof(cd2MouseJointDef, hertz)},
	{"dampingRatio", FIELD_REAL, offsetof(cd2MouseJointDef, dampingRatio)},
	{"maxForce", FIELD_REAL, offsetof(cd2MouseJointDef, maxForce)},
	{"collideConnected", FIELD_BOOL, offsetof(cd2MouseJointDef, collideConnected)},
	{"forceThreshold", FIELD_REAL, offsetof(cd2MouseJointDef, forceThreshold)},
	{"torqueThreshold", FIELD_REAL, offsetof(cd2MouseJointDef, torqueThreshold)},
	{NULL, FIELD_SPECIAL, 0},
};

static const Field s_prismaticFields[] = {
	JOINT_COMMON_FIELDS,
	{"localAnchorA", FIELD_VEC, offsetof(cd2PrismaticJointDef, localAnchorA)},
	{"localAnchorB", FIELD_VEC, offsetof(cd2PrismaticJointDef, localAnchorB)},
	{"localAxisA", FIELD_VEC, offsetof(cd2PrismaticJointDef, localAxisA)},
	{"referenceAngle", FIELD_REAL, offsetof(cd2PrismaticJointDef, referenceAngle)},
	{"enableSpring", FIELD_BOOL, offsetof(cd2PrismaticJointDef, enableSpring)},
	{"hertz", FIELD_REAL, offsetof(cd2PrismaticJointDef, hertz)},
	{"dampingRatio", FIELD_REAL, offsetof(cd2PrismaticJointDef, dampingRatio)},
	{"enableLimit", FIELD_BOOL, offsetof(cd2PrismaticJointDef, enableLimit)},
	{"lowerTranslation", FIELD_REAL, offsetof(cd2PrismaticJointDef, lowerTranslation)},
	{"upperTranslation", FIELD_REAL, offsetof(cd2PrismaticJointDef, upperTranslation)},
	{"enableMotor", FIELD_BOOL, offsetof(cd2PrismaticJointDef, enableMotor)},
	{"maxMotorForce", FIELD_REAL, offsetof(cd2PrismaticJointDef, maxMotorForce)},
	{"motorSpeed", FIELD_REAL, offsetof(cd2PrismaticJointDef, motorSpeed)},
	{"collideConnected", FIELD_BOOL, offsetof(cd2PrismaticJointDef, collideConnected)},
	{"forceThreshold", FIELD_REAL, offsetof(cd2PrismaticJointDef, forceThreshold)},
	{"torqueThreshold", FIELD_REAL, offsetof(cd2PrismaticJointDef, torqueThreshold)},
	{"constraintHertz", FIELD_REAL, offsetof(cd2PrismaticJointDef, constraintHertz)},
	{"constraintDampingRatio", FIELD_REAL, offsetof(cd2PrismaticJointDef, constraintDampingRatio)},
	{NULL, FIELD_SPECIAL, 0},
};

static const Field s_revoluteFields[] = {
	JOINT_COMMON_FIELDS,
	{"localAnchorA", FIELD_VEC, offsetof(cd2RevoluteJointDef, localAnchorA)},
	{"localAnchorB", FIELD_VEC, offsetof(cd2RevoluteJointDef, localAnchorB)},
	{"referenceAngle", FIELD_REAL, offsetof(cd2RevoluteJointDef, referenceAngle)},
	{"enableSpring", FIELD_BOOL, offsetof(cd2RevoluteJointDef, enableSpring)},
	{"hertz", FIELD_REAL, offsetof(cd2RevoluteJointDef, hertz)},
	{"dampingRatio", FIELD_REAL, offsetof(cd2RevoluteJointDef, dampingRatio)},
	{"enableLimit", FIELD_BOOL, offsetof(cd2RevoluteJointDef, enableLimit)},
	{"lowerAngle", FIELD_REAL, offsetof(cd2RevoluteJointDef, lowerAngle)},
	{"upperAngle", FIELD_REAL, offsetof(cd2RevoluteJointDef, upperAngle)},
	{"enableMotor", FIELD_BOOL, offsetof(cd2RevoluteJointDef, enableMotor)},
	{"maxMotorTorque", FIELD_REAL, offsetof(cd2RevoluteJointDef, maxMotorTorque)},
	{"motorSpeed", FIELD_REAL, offsetof(cd2RevoluteJointDef, motorSpeed)},
	{"collideConnected", FIELD_BOOL, offsetof(cd2RevoluteJointDef, collideConnected)},
	{"forceThreshold", FIELD_REAL, offsetof(cd2RevoluteJointDef, forceThreshold)},
	{"torqueThreshold", FIELD_REAL, offsetof(cd2RevoluteJointDef, torqueThreshold)},
	{"constraintHertz", FIELD_REAL, offsetof(cd2RevoluteJointDef, constraintHertz)},
	{"constraintDampingRatio", FIELD_REAL, offsetof(cd2RevoluteJointDef, constraintDampingRatio)},
	{NULL, FIELD_SPECIAL, 0},
};

static const Field s_weldFields[] = {
	JOINT_COMMON_FIELDS,
	{"localAnchorA", FIELD_VEC, offsetof(cd2WeldJointDef, localAnchorA)},
	{"localAnchorB", FIELD_VEC, offsetof(cd2WeldJointDef, localAnchorB)},
	{"referenceAngle", FIELD_REAL, offsetof(cd2WeldJointDef, referenceAngle)},
	{"linearHertz", FIELD_REAL, offsetof(cd2WeldJointDef, linearHertz)},
	{"angularHertz", FIELD_REAL, offsetof(cd2WeldJointDef, angularHertz)},
	{"linearDampingRatio", FIELD_REAL, offsetof(cd2WeldJointDef, linearDampingRatio)},
	{"angularDampingRatio", FIELD_REAL, offsetof(cd2WeldJointDef, angularDampingRatio)},
	{"collideConnected", FIELD_BOOL, offsetof(cd2WeldJointDef, collideConnected)},
	{"forceThreshold", FIELD_REAL, offsetof(cd2WeldJointDef, forceThreshold)},
	{"torqueThreshold", FIELD_REAL, offsetof(cd2WeldJointDef, torqueThreshold)},
	{"constraintHertz", FIELD_REAL, offsetof(cd2WeldJointDef, constraintHertz)},
	{"constraintDampingRatio", FIELD_REAL, offsetof(cd2WeldJointDef, constraintDampingRatio)},
	{NULL, FIELD_SPECIAL, 0},
};

static const Field s_wheelFields[] = {
	JOINT_COMMON_FIELDS,
	{"localAnchorA", FIELD_VEC, offsetof(cd2WheelJointDef, localAnchorA)},
	{"localAnchorB", FIELD_VEC, offsetof(cd2WheelJointDef, localAnchorB)},
	{"localAxisA", FIELD_VEC, offsetof(cd2WheelJointDef, localAxisA)},
	{"enableSpring", FIELD_BOOL, offsetof(cd2WheelJointDef, enableSpring)},
	{"hertz", FIELD_REAL, offsetof(cd2WheelJointDef, hertz)},
	{"dampingRatio", FIELD_REAL, offsetof(cd2WheelJointDef, dampingRatio)},
	{"enableLimit", FIELD_BOOL, offsetof(cd2WheelJointDef, enableLimit)},
	{"lowerTranslation", FIELD_REAL, offsetof(cd2WheelJointDef, lowerTranslation)},
	{"upperTranslation", FIELD_REAL, offsetof(cd2WheelJointDef, upperTranslation)},
	{"enableMotor", FIELD_BOOL, offsetof(cd2WheelJointDef, enableMotor)},
	{"maxMotorTorque", FIELD_REAL, offsetof(cd2WheelJointDef, maxMotorTorque)},
	{"motorSpeed", FIELD_REAL, offsetof(cd2WheelJointDef, motorSpeed)},
	{"collideConnected", FIELD_BOOL, offsetof(cd2WheelJointDef, collideConnected)},
	{"forceThreshold", FIELD_REAL, offsetof(cd2WheelJointDef, forceThreshold)},
	{"torqueThreshold", FIELD_REAL, offsetof(cd2WheelJointDef, torqueThreshold)},
	{"constraintHertz", FIELD_REAL, offsetof(cd2WheelJointDef, constraintHertz)},
	{"constraintDampingRatio", FIELD_REAL, offsetof(cd2WheelJointDef, constraintDampingRatio)},
	{NULL, FIELD_SPECIAL, 0},
};

static bool findBody(WLoader* loader, const cJSON* object, const char* key, cd2BodyId* out)
{
	const cJSON* item = cJSON_GetObjectItemCaseSensitive(object, key);
	if (item == NULL)
	{
		return failAt(loader, NULL, "missing field \"%s\"", key);
	}
	if (!cJSON_IsString(item))
	{
		return failAt(loader, key, "\"%s\" must be the name of a body, not %s", key, jsonTypeName(item));
	}
	int lo = 0, hi = loader->namedCount;
	while (lo < hi)
	{
		int mid = lo + (hi - lo) / 2;
		int body = loader->nameOrder[mid];
		int order = strcmp(loader->out->bodies[body].name, item->valuestring);
		if (order == 0)
		{
			*out = loader->out->bodies[body].id;
			return true;
		}
		if (order < 0)
		{
			lo = mid + 1;
		}
		else
		{
			hi = mid;
		}
	}
	char shown[48];
	return failAt(loader, key, "\"%s\": no body is named \"%s\"", key,
				  jsonPrintable(item->valuestring, shown, sizeof shown));
}

static bool readJoint(WLoader* loader, const cJSON* object, int index)
{
	snprintf(loader->context, sizeof loader->context, "joint #%d", index + 1);
	if (!cJSON_IsObject(object))
	{
		return failAt(loader, NULL, "a joint must be an object, not %s", jsonTypeName(object));
	}
	char name[TOOL_MAX_NAME + 1];
	if (!readName(loader, object, name))
	{
		return false;
	}
	if (name[0] != 0)
	{
		snprintf(loader->context, sizeof loader->context, "joint \"%s\"", name);
	}
	const cJSON* typeItem = cJSON_GetObjectItemCaseSensitive(object, "type");
	if (typeItem == NULL)
	{
		return failAt(loader, NULL, "missing field \"type\"");
	}
	if (!cJSON_IsString(typeItem))
	{
		return failAt(loader, "type", "\"type\" must be a string, not %s", jsonTypeName(typeItem));
	}
	static const struct
	{
		const char* name;
		const Field* fields;
	} types[] = {{"distance", s_distanceFields},   {"filter", s_filterFields},
				 {"motor", s_motorFields},		   {"mouse", s_mouseFields},
				 {"prismatic", s_prismaticFields}, {"revolute", s_revoluteFields},
				 {"weld", s_weldFields},		   {"wheel", s_wheelFields}};
	int kind = -1;
	for (int i = 0; i < (int)(sizeof types / sizeof types[0]); ++i)
	{
		if (strcmp(typeItem->valuestring, types[i].name) == 0)
		{
			kind = i;
		}
	}
	if (kind < 0)
	{
		char shown[48];
		return failAt(
			loader, "type",
			"unknown joint type \"%s\" (expected distance, filter, motor, mouse, prismatic, revolute, "
			"weld or wheel)",
			jsonPrintable(typeItem->valuestring, shown, sizeof shown));
	}
	const Field* fields = types[kind].fields;
	cd2BodyId bodyA, bodyB;
	if (!checkFields(loader, object, fields) || !findBody(loader, object, "bodyA", &bodyA) ||
		!findBody(loader, object, "bodyB", &bodyB))
	{
		return false;
	}
	/* "anchor": a world point that sets both local anchors (and the distance joint's second end
	 * with "anchorB"); the local anchors given explicitly win. */
	bool hasAnchor = false, hasAnchorB = false;
	cd2Vec anchor = CD2_VEC_ZERO, anchorB = CD2_VEC_ZERO;
	if (!readOptionalVec(loader, object, "anchor", &anchor))
	{
		return false;
	}
	hasAnchor = cJSON_GetObjectItemCaseSensitive(object, "anchor") != NULL;
	if (kind == 0)
	{
		if (!readOptionalVec(loader, object, "anchorB", &anchorB))
		{
			return false;
		}
		hasAnchorB = cJSON_GetObjectItemCaseSensitive(object, "anchorB") != NULL;
	}
	if (hasAnchor && kind != 0 && kind != 4 && kind != 5 && kind != 6 && kind != 7)
	{
		return failAt(loader, "anchor",
					  "\"anchor\" is for distance, prismatic, revolute, weld and wheel joints");
	}
	if (hasAnchorB && !hasAnchor)
	{
		return failAt(loader, "anchorB", "\"anchorB\" needs \"anchor\"");
	}
	cd2Vec localA = cd2Body_GetLocalPoint(bodyA, anchor);
	cd2Vec localB = cd2Body_GetLocalPoint(bodyB, hasAnchorB ? anchorB : anchor);
	cdReal referenceAngle =
		cd2RotGetAngle(cd2Body_GetRotation(bodyB)) - cd2RotGetAngle(cd2Body_GetRotation(bodyA));
	s_refusal[0] = 0;
	cd2WorldId world = loader->out->world;
	cd2JointId id = CD2_NULL_JOINT_ID;
	switch (kind)
	{
		case 0:
		{
			cd2DistanceJointDef def = cd2DefaultDistanceJointDef();
			def.bodyIdA = bodyA;
			def.bodyIdB = bodyB;
			if (hasAnchor)
			{
				def.localAnchorA = localA;
				def.localAnchorB = localB;
				def.length = cd2Length(cd2Sub(hasAnchorB ? anchorB : anchor, anchor));
			}
			if (!readFields(loader, object, fields, &def))
			{
				return false;
			}
			id = cd2CreateDistanceJoint(world, &def);
			break;
		}
		case 1:
		{
			cd2FilterJointDef def = cd2DefaultFilterJointDef();
			def.bodyIdA = bodyA;
			def.bodyIdB = bodyB;
			id = cd2CreateFilterJoint(world, &def);
			break;
		}
		case 2:
		{
			cd2MotorJointDef def = cd2DefaultMotorJointDef();
			def.bodyIdA = bodyA;
			def.bodyIdB = bodyB;
			if (!readFields(loader, object, fields, &def))
			{
				return false;
			}
			id = cd2CreateMotorJoint(world, &def);
			break;
		}
		case 3:
		{
			cd2MouseJointDef def = cd2DefaultMouseJointDef();
			def.bodyIdA = bodyA;
			def.bodyIdB = bodyB;
			def.target = cd2Body_GetPosition(bodyB);
			if (!readFields(loader, object, fields, &def))
			{
				return false;
			}
			id = cd2CreateMouseJoint(world, &def);
			break;
		}
		case 4:
		{
			cd2PrismaticJointDef def = cd2DefaultPrismaticJointDef();
			def.bodyIdA = bodyA;
			def.bodyIdB = bodyB;
			if (hasAnchor)
			{
				def.localAnchorA = localA;
				def.localAnchorB = localB;
				def.referenceAngle = referenceAngle;
			}
			if (!readFields(loader, object, fields, &def))
			{
				return false;
			}
			id = cd2CreatePrismaticJoint(world, &def);
			break;
		}
		case 5:
		{
			cd2RevoluteJointDef def = cd2DefaultRevoluteJointDef();
			def.bodyIdA = bodyA;
			def.bodyIdB = bodyB;
			if (hasAnchor)
			{
				def.localAnchorA = localA;
				def.localAnchorB = localB;
				def.referenceAngle = referenceAngle;
			}
			if (!readFields(loader, object, fields, &def))
			{
				return false;
			}
			id = cd2CreateRevoluteJoint(world, &def);
			break;
		}
		case 6:
		{
			cd2WeldJointDef def = cd2DefaultWeldJointDef();
			def.bodyIdA = bodyA;
			def.bodyIdB = bodyB;
			if (hasAnchor)
			{
				def.localAnchorA = localA;
				def.localAnchorB = localB;
				def.referenceAngle = referenceAngle;
			}
			if (!readFields(loader, object, fields, &def))
			{
				return false;
			}
			id = cd2CreateWeldJoint(world, &def);
			break;
		}
		default:
		{
			cd2WheelJointDef def = cd2DefaultWheelJointDef();
			def.bodyIdA = bodyA;
			def.bodyIdB = bodyB;
			if (hasAnchor)
			{
				def.localAnchorA = localA;
				def.localAnchorB = localB;
			}
			if (!readFields(loader, object, fields, &def))
			{
				return false;
			}
			id = cd2CreateWheelJoint(world, &def);
			break;
		}
	}
	if (cd2IsNullJointId(id))
	{
		return failAt(loader, NULL, "refused by the world: %s",
					  s_refusal[0] != 0 ? s_refusal : "invalid joint");
	}
	loader->out->jointCount += 1;
	return true;
}

/* ---- body names: sorted once, so that duplicates and joints' look-ups cost n log n ----------- */

static const ToolWorldBody* s_sortBodies;

static int compareBodyNames(const void* a, const void* b)
{
	int ia = *(const int*)a, ib = *(const int*)b;
	int order = strcmp(s_sortBodies[ia].name, s_sortBodies[ib].name);
	return order != 0 ? order : (ia > ib) - (ia < ib);
}

/* Sorts the named bodies; a name used twice is an error at its second use (the earliest such
 * use in the file). Called with the path at "world". */
static bool indexBodyNames(WLoader* loader)
{
	const ToolWorld* out = loader->out;
	loader->nameOrder = malloc((size_t)(out->bodyCount > 0 ? out->bodyCount : 1) * sizeof(int));
	if (loader->nameOrder == NULL)
	{
		return failAt(loader, NULL, "out of memory");
	}
	int n = 0;
	for (int i = 0; i < out->bodyCount; ++i)
	{
		if (out->bodies[i].name[0] != 0)
		{
			loader->nameOrder[n++] = i;
		}
	}
	loader->namedCount = n;
	s_sortBodies = out->bodies;
	qsort(loader->nameOrder, (size_t)n, sizeof(int), compareBodyNames);
	int second = -1, first = -1;
	for (int k = 1; k < n; ++k)
	{
		int a = loader->nameOrder[k - 1], b = loader->nameOrder[k];
		if (strcmp(out->bodies[a].name, out->bodies[b].name) == 0 && (second < 0 || b < second))
		{
			/* Equal names sort by index: a is the earlier use (or a later duplicate of the first). */
			int k0 = k - 1;
			while (k0 > 0 && strcmp(out->bodies[loader->nameOrder[k0 - 1]].name, out->bodies[b].name) == 0)
			{
				--k0;
			}
			second = b;
			first = loader->nameOrder[k0];
		}
	}
	if (second >= 0)
	{
		snprintf(loader->context, sizeof loader->context, "body \"%s\"", out->bodies[second].name);
		jsonReaderPushKey(&loader->json, "bodies");
		jsonReaderPushIndex(&loader->json, second);
		failAt(loader, "name", "the name is already used by body #%d", first + 1);
		jsonReaderPop(&loader->json);
		jsonReaderPop(&loader->json);
		return false;
	}
	return true;
}

/* ---- the world ------------------------------------------------------------------------------- */

static const Field s_worldFields[] = {
	{"gravity", FIELD_VEC, offsetof(cd2WorldDef, gravity)},
	{"restitutionThreshold", FIELD_REAL, offsetof(cd2WorldDef, restitutionThreshold)},
	{"hitEventThreshold", FIELD_REAL, offsetof(cd2WorldDef, hitEventThreshold)},
	{"contactHertz", FIELD_REAL, offsetof(cd2WorldDef, contactHertz)},
	{"contactDampingRatio", FIELD_REAL, offsetof(cd2WorldDef, contactDampingRatio)},
	{"contactPushMaxVelocity", FIELD_REAL, offsetof(cd2WorldDef, contactPushMaxVelocity)},
	{"contactRecycleDistance", FIELD_REAL, offsetof(cd2WorldDef, contactRecycleDistance)},
	{"jointHertz", FIELD_REAL, offsetof(cd2WorldDef, jointHertz)},
	{"jointDampingRatio", FIELD_REAL, offsetof(cd2WorldDef, jointDampingRatio)},
	{"maximumLinearSpeed", FIELD_REAL, offsetof(cd2WorldDef, maximumLinearSpeed)},
	{"enableSleep", FIELD_BOOL, offsetof(cd2WorldDef, enableSleep)},
	{"enableContinuous", FIELD_BOOL, offsetof(cd2WorldDef, enableContinuous)},
	{"timeStep", FIELD_SPECIAL, 0},
	{"subSteps", FIELD_SPECIAL, 0},
	{"view", FIELD_SPECIAL, 0},
	{"bodies", FIELD_SPECIAL, 0},
	{"joints", FIELD_SPECIAL, 0},
	{NULL, FIELD_SPECIAL, 0},
};

static bool readView(WLoader* loader, const cJSON* object, ToolWorld* out)
{
	const cJSON* view = cJSON_GetObjectItemCaseSensitive(object, "view");
	if (view == NULL)
	{
		return true;
	}
	if (!cJSON_IsObject(view))
	{
		return failAt(loader, "view", "\"view\" must be an object with \"min\" and \"max\", not %s",
					  jsonTypeName(view));
	}
	static const Field fields[] = {
		{"min", FIELD_SPECIAL, 0}, {"max", FIELD_SPECIAL, 0}, {NULL, FIELD_SPECIAL, 0}};
	jsonReaderPushKey(&loader->json, "view");
	cd2Vec lo, hi;
	bool ok = checkFields(loader, view, fields) && readRequiredVec(loader, view, "min", &lo) &&
			  readRequiredVec(loader, view, "max", &hi);
	if (ok && !(lo.x < hi.x && lo.y < hi.y))
	{
		ok = failAt(loader, "max", "\"view\": \"max\" must be greater than \"min\" on both axes");
	}
	jsonReaderPop(&loader->json);
	if (ok)
	{
		out->hasView = true;
		out->viewMin[0] = (double)lo.x;
		out->viewMin[1] = (double)lo.y;
		out->viewMax[0] = (double)hi.x;
		out->viewMax[1] = (double)hi.y;
	}
	return ok;
}

static bool readWorld(WLoader* loader, const cJSON* root, ToolWorld* out)
{
	if (!cJSON_IsObject(root))
	{
		return failAt(loader, NULL, "the top level must be an object with \"world\", not %s",
					  jsonTypeName(root));
	}
	static const Field rootFields[] = {{"world", FIELD_SPECIAL, 0}, {NULL, FIELD_SPECIAL, 0}};
	if (!checkFields(loader, root, rootFields))
	{
		return false;
	}
	const cJSON* object = cJSON_GetObjectItemCaseSensitive(root, "world");
	if (object == NULL)
	{
		return failAt(loader, NULL,
					  "the top level needs \"world\" (a physics scene; `collide query` reads shape scenes)");
	}
	if (!cJSON_IsObject(object))
	{
		return failAt(loader, "world", "\"world\" must be an object, not %s", jsonTypeName(object));
	}
	jsonReaderPushKey(&loader->json, "world");
	cd2WorldDef def = cd2DefaultWorldDef();
	double timeStep = 1.0 / 60.0;
	const cJSON* bodies;
	const cJSON* joints;
	int bodyCount, jointCount;
	if (!checkFields(loader, object, s_worldFields) || !readFields(loader, object, s_worldFields, &def) ||
		!readOptionalNumber(loader, object, "timeStep", &timeStep) ||
		!readInt(loader, object, "subSteps", 1, TOOL_MAX_SUB_STEPS, &out->subSteps) ||
		!readView(loader, object, out) ||
		!readArray(loader, object, "bodies", 0, TOOL_MAX_WORLD_BODIES, &bodies, &bodyCount) ||
		!readArray(loader, object, "joints", 0, TOOL_MAX_WORLD_JOINTS, &joints, &jointCount))
	{
		return false;
	}
	if (!(timeStep > 0.0 && timeStep <= 1.0))
	{
		return failAt(loader, "timeStep", "\"timeStep\" must be in (0, 1] seconds, not %g", timeStep);
	}
	out->timeStep = timeStep;
	s_refusal[0] = 0;
	out->world = cd2CreateWorld(&def);
	if (!cd2World_IsValid(out->world))
	{
		return failAt(loader, NULL, "refused by the world: %s",
					  s_refusal[0] != 0 ? s_refusal : "cannot create the world (too many worlds?)");
	}
	out->bodies = calloc((size_t)(bodyCount > 0 ? bodyCount : 1), sizeof(ToolWorldBody));
	if (out->bodies == NULL)
	{
		return failAt(loader, NULL, "out of memory");
	}
	const char* const lists[2] = {"bodies", "joints"};
	const cJSON* const arrays[2] = {bodies, joints};
	for (int list = 0; list < 2; ++list)
	{
		if (list == 1 && !indexBodyNames(loader))
		{
			return false;
		}
		if (arrays[list] == NULL)
		{
			continue;
		}
		jsonReaderPushKey(&loader->json, lists[list]);
		int index = 0;
		for (const cJSON* item = arrays[list]->child; item != NULL; item = item->next, ++index)
		{
			jsonReaderPushIndex(&loader->json, index);
			bool ok = list == 0 ? readBody(loader, item, index) : readJoint(loader, item, index);
			jsonReaderPop(&loader->json);
			if (!ok)
			{
				return false;
			}
		}
		jsonReaderPop(&loader->json);
	}
	loader->context[0] = 0;
	jsonReaderPop(&loader->json);
	return true;
}

bool toolLoadWorld(const char* path, ToolWorld* world, ToolError* error)
{
	memset(world, 0, sizeof *world);
	world->subSteps = 4;
	char* text;
	size_t length;
	void* root;
	if (!toolReadJsonFile(path, &text, &length, &root, error))
	{
		return false;
	}
	WLoader loader;
	memset(&loader, 0, sizeof loader);
	loader.json.text = text;
	loader.json.length = length;
	loader.json.error = error;
	loader.out = world;
	s_refusal[0] = 0;
	cdSetAssertFcn(recordRefusal);
	bool ok = readWorld(&loader, root, world);
	cdSetAssertFcn(NULL);
	free(loader.nameOrder);
	cJSON_Delete(root);
	free(text);
	if (!ok)
	{
		toolFreeWorld(world);
	}
	return ok;
}

void toolFreeWorld(ToolWorld* world)
{
	if (world->world.index1 != 0 && cd2World_IsValid(world->world))
	{
		cd2DestroyWorld(world->world);
	}
	free(world->bodies);
	memset(world, 0, sizeof *world);
}
