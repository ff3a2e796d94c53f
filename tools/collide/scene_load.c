/* collide tool: reads a scene file.
 *
 * Format (JSON). A file holds several scenes, or is one scene:
 *
 *   { "scenes": [ SCENE, ... ] }        or        SCENE
 *
 *   SCENE = { "name": "side-scroller",   optional (default "scene1", "scene2", ...)
 *             "dimension": 2,            required: 2 or 3
 *             "shapes": [ SHAPE, ... ] } required; pairs are tested within a scene only
 *
 *   SHAPE = { "name": "player", "type": "aabb", ...fields of the type... }
 *
 * Shape names are required and unique within their scene (1 to 64 bytes of UTF-8, no control
 * characters). Vectors are arrays of 2 numbers in a 2D scene and 3 in a 3D scene. Fields:
 *
 *   type      dimension  fields
 *   point     2, 3       "at": V
 *   circle    2          "center": V, "radius": r
 *   sphere    3          "center": V, "radius": r
 *   capsule   2, 3       "p1": V, "p2": V, "radius": r      (the points within r of segment p1-p2)
 *   aabb      2, 3       "min": V, "max": V
 *   box       2          "center": V, "halfExtents": V, optional "angle" (radians, CCW) or "degrees",
 *                        optional "radius" r (rounded corners: the points within r of the box;
 *                        needs a non-zero area)
 *   box       3          "center": V, "halfExtents": V, optional "rotation": [x, y, z, w] (unit
 *                        quaternion) or "axis": V with "angle" (radians) or "degrees"
 *   polygon   2          "points": [V, V, V, ...] convex, 3 to 8 corners in order (CCW or CW),
 *                        optional "radius" r (rounded: the points within r of the polygon)
 *   triangle  3          "points": [V, V, V]
 *   plane     3          "normal": V (unit length), "offset": d   (the solid half-space n.x <= d)
 *   segment   2, 3       "p1": V, "p2": V
 *   hull      3          "points": [V, V, V, V, ...] 4 to 1024 points, not all in one plane; the
 *                        solid convex hull of them (cd3ComputeHull), placed by optional
 *                        "position": V and "rotation" or "axis" with "angle"/"degrees" (as boxes)
 *
 * Any object may also hold a "comment" (ignored). Unknown fields are errors (they are usually
 * typos). Numbers must be finite and within the library's documented range (|x| <= 1e9 in the
 * float build, 1e30 in the double build).
 *
 * Every error names the file, the line where it was found and the reason. cJSON keeps no
 * positions, so after a semantic error the loader finds the line by walking the text along the
 * path of the offending value (json_locate.c). */
#include "json_read.h"
#include "scene.h"
#include "world_scene.h"

#include <cjson/cJSON.h>

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct Loader
{
	JsonReader json; /* the text and the path being read */
	int dimension;
	const char* shapeName; /* for messages; NULL before the shape's name is known */
	int shapeIndex;
	const char* sceneName; /* for messages about a scene itself */
} Loader;

/* Records an error about the value at the current path (plus `key`). Always returns false. */
#if defined(__GNUC__)
__attribute__((format(printf, 3, 4)))
#endif
static bool
failAt(Loader* loader, const char* key, const char* format, ...)
{
	char reason[384];
	va_list args;
	va_start(args, format);
	vsnprintf(reason, sizeof reason, format, args);
	va_end(args);
	/* An error about a whole shape points at its name: that is where a reader looks for it. */
	ToolError* error = loader->json.error;
	error->line = jsonReaderLine(&loader->json, key == NULL && loader->shapeName != NULL ? "name" : key);
	if (loader->shapeName != NULL)
	{
		snprintf(error->message, sizeof error->message, "shape \"%s\": %s", loader->shapeName, reason);
	}
	else if (loader->shapeIndex >= 0)
	{
		snprintf(error->message, sizeof error->message, "shape #%d: %s", loader->shapeIndex + 1, reason);
	}
	else if (loader->sceneName != NULL)
	{
		snprintf(error->message, sizeof error->message, "scene \"%s\": %s", loader->sceneName, reason);
	}
	else
	{
		snprintf(error->message, sizeof error->message, "%s", reason);
	}
	return false;
}

/* ---- fields ---------------------------------------------------------------------------------- */

/* Rejects unknown and repeated keys (comment is always allowed). `allowed` ends with NULL. */
static bool checkKeys(Loader* loader, const cJSON* object, const char* const* allowed)
{
	char reason[384];
	const char* key = jsonFindBadKey(object, allowed, sizeof allowed[0], reason, sizeof reason);
	return key == NULL || failAt(loader, key, "%s", reason);
}

static bool checkNumber(Loader* loader, const char* key, const char* what, double value)
{
	if (!isfinite(value))
	{
		return failAt(loader, key, "%s is not a finite number", what);
	}
	if (fabs(value) > TOOL_MAX_MAGNITUDE)
	{
		/* The value with every digit it needs (%g rounded 1000000001 to the limit 1e+09). */
		char digits[40];
		for (int precision = 6; precision <= 17; ++precision)
		{
			snprintf(digits, sizeof digits, "%.*g", precision, value);
			if (strtod(digits, NULL) == value)
			{
				break;
			}
		}
		return failAt(loader, key, "%s = %s is outside the supported range [-%g, %g]", what, digits,
					  TOOL_MAX_MAGNITUDE, TOOL_MAX_MAGNITUDE);
	}
	return true;
}

static bool readNumber(Loader* loader, const cJSON* object, const char* key, double* out)
{
	const cJSON* item = cJSON_GetObjectItemCaseSensitive(object, key);
	if (item == NULL)
	{
		return failAt(loader, NULL, "missing field \"%s\"", key);
	}
	if (!cJSON_IsNumber(item))
	{
		return failAt(loader, key, "\"%s\" must be a number, not %s", key, jsonTypeName(item));
	}
	char what[80];
	snprintf(what, sizeof what, "\"%s\"", key);
	if (!checkNumber(loader, key, what, item->valuedouble))
	{
		return false;
	}
	*out = item->valuedouble;
	return true;
}

/* An array of `count` numbers (count is the scene's dimension for points and vectors). */
static bool readNumbers(Loader* loader, const cJSON* item, const char* key, const char* what, int count,
						double* out)
{
	if (!cJSON_IsArray(item))
	{
		return failAt(loader, key, "%s must be an array of %d numbers, not %s", what, count,
					  jsonTypeName(item));
	}
	int n = 0;
	for (const cJSON* element = item->child; element != NULL; element = element->next, ++n)
	{
		if (n >= count || !cJSON_IsNumber(element))
		{
			return failAt(loader, key, "%s must be an array of %d numbers", what, count);
		}
		if (!checkNumber(loader, key, what, element->valuedouble))
		{
			return false;
		}
		out[n] = element->valuedouble;
	}
	if (n != count)
	{
		return failAt(loader, key, "%s must be an array of %d numbers, not %d", what, count, n);
	}
	return true;
}

static bool readVector(Loader* loader, const cJSON* object, const char* key, double out[3])
{
	const cJSON* item = cJSON_GetObjectItemCaseSensitive(object, key);
	if (item == NULL)
	{
		return failAt(loader, NULL, "missing field \"%s\"", key);
	}
	char what[80];
	snprintf(what, sizeof what, "\"%s\"", key);
	out[2] = 0.0;
	return readNumbers(loader, item, key, what, loader->dimension, out);
}

static cd2Vec toVec2(const double v[3])
{
	return cd2MakeVec((cdReal)v[0], (cdReal)v[1]);
}

static cd3Vec toVec3(const double v[3])
{
	return cd3MakeVec((cdReal)v[0], (cdReal)v[1], (cdReal)v[2]);
}

/* Valid UTF-8 without control characters: names go into a terminal table and into XML. */
static bool isPrintableUtf8(const char* s)
{
	const unsigned char* p = (const unsigned char*)s;
	while (*p != 0)
	{
		unsigned c = *p;
		if (c < 0x20 || c == 0x7f)
		{
			return false;
		}
		int extra = c < 0x80				   ? 0
					: (c >= 0xc2 && c <= 0xdf) ? 1
					: (c >= 0xe0 && c <= 0xef) ? 2
					: (c >= 0xf0 && c <= 0xf4) ? 3
											   : -1;
		if (extra < 0)
		{
			return false;
		}
		unsigned codePoint = extra == 0 ? c : c & (0x3fu >> extra);
		++p;
		for (int i = 0; i < extra; ++i, ++p)
		{
			if ((*p & 0xc0) != 0x80)
			{
				return false;
			}
			codePoint = (codePoint << 6) | (*p & 0x3fu);
		}
		bool overlong = (extra == 2 && codePoint < 0x800) || (extra == 3 && codePoint < 0x10000);
		if (overlong || codePoint > 0x10ffff || (codePoint >= 0xd800 && codePoint <= 0xdfff) ||
			(codePoint >= 0x80 && codePoint < 0xa0))
		{
			return false;
		}
	}
	return true;
}

static bool readName(Loader* loader, const cJSON* object, bool required, char out[TOOL_MAX_NAME + 1])
{
	const cJSON* item = cJSON_GetObjectItemCaseSensitive(object, "name");
	if (item == NULL)
	{
		return required ? failAt(loader, NULL, "missing field \"name\"") : true;
	}
	if (!cJSON_IsString(item) || item->valuestring == NULL)
	{
		return failAt(loader, "name", "\"name\" must be a string, not %s", jsonTypeName(item));
	}
	size_t length = strlen(item->valuestring);
	if (length == 0 || length > TOOL_MAX_NAME)
	{
		return failAt(loader, "name", "\"name\" must be 1 to %d bytes long", TOOL_MAX_NAME);
	}
	if (!isPrintableUtf8(item->valuestring))
	{
		return failAt(loader, "name", "\"name\" must be UTF-8 text without control characters");
	}
	memcpy(out, item->valuestring, length + 1);
	return true;
}

/* ---- shapes ---------------------------------------------------------------------------------- */

typedef enum ShapeKind
{
	KIND_POINT,
	KIND_CIRCLE, /* circle in 2D, sphere in 3D */
	KIND_CAPSULE,
	KIND_AABB,
	KIND_BOX,
	KIND_POLYGON,
	KIND_TRIANGLE,
	KIND_PLANE,
	KIND_SEGMENT,
	KIND_HULL
} ShapeKind;

typedef struct ShapeTypeInfo
{
	const char* name;
	int dimensions; /* bit 2: 2D, bit 3: 3D */
	ShapeKind kind;
	const char* fields[10]; /* ends with NULL */
} ShapeTypeInfo;

#define DIM2 (1 << 2)
#define DIM3 (1 << 3)

static const ShapeTypeInfo s_shapeTypes[] = {
	{"point", DIM2 | DIM3, KIND_POINT, {"name", "type", "at", NULL}},
	{"circle", DIM2, KIND_CIRCLE, {"name", "type", "center", "radius", NULL}},
	{"sphere", DIM3, KIND_CIRCLE, {"name", "type", "center", "radius", NULL}},
	{"capsule", DIM2 | DIM3, KIND_CAPSULE, {"name", "type", "p1", "p2", "radius", NULL}},
	{"aabb", DIM2 | DIM3, KIND_AABB, {"name", "type", "min", "max", NULL}},
	{"box", DIM2, KIND_BOX, {"name", "type", "center", "halfExtents", "angle", "degrees", "radius", NULL}},
	{"box",
	 DIM3,
	 KIND_BOX,
	 {"name", "type", "center", "halfExtents", "rotation", "axis", "angle", "degrees", NULL}},
	{"polygon", DIM2, KIND_POLYGON, {"name", "type", "points", "radius", NULL}},
	{"triangle", DIM3, KIND_TRIANGLE, {"name", "type", "points", NULL}},
	{"plane", DIM3, KIND_PLANE, {"name", "type", "normal", "offset", NULL}},
	{"segment", DIM2 | DIM3, KIND_SEGMENT, {"name", "type", "p1", "p2", NULL}},
	{"hull",
	 DIM3,
	 KIND_HULL,
	 {"name", "type", "points", "position", "rotation", "axis", "angle", "degrees", NULL}},
};

#define SHAPE_TYPE_COUNT ((int)(sizeof s_shapeTypes / sizeof s_shapeTypes[0]))

static const ShapeTypeInfo* findShapeType(const char* name, int dimension)
{
	for (int i = 0; i < SHAPE_TYPE_COUNT; ++i)
	{
		if ((s_shapeTypes[i].dimensions & (1 << dimension)) != 0 && strcmp(s_shapeTypes[i].name, name) == 0)
		{
			return &s_shapeTypes[i];
		}
	}
	return NULL;
}

static void listShapeTypes(int dimension, char* buffer, size_t size)
{
	buffer[0] = 0;
	for (int i = 0; i < SHAPE_TYPE_COUNT; ++i)
	{
		if ((s_shapeTypes[i].dimensions & (1 << dimension)) != 0)
		{
			size_t used = strlen(buffer);
			snprintf(buffer + used, size - used, "%s%s", used > 0 ? ", " : "", s_shapeTypes[i].name);
		}
	}
}

static bool readRadius(Loader* loader, const cJSON* object, cdReal* radius)
{
	double value;
	if (!readNumber(loader, object, "radius", &value))
	{
		return false;
	}
	*radius = (cdReal)value;
	return true;
}

/* Optional rounding "radius" of polygons and 2D boxes; 0 when absent. A negative one is reported
 * at its own line, in the words the library's validators use. */
static bool readRoundingRadius(Loader* loader, const cJSON* object, const char* typeName, cdReal* radius)
{
	*radius = CD_R(0.0);
	if (cJSON_GetObjectItemCaseSensitive(object, "radius") == NULL)
	{
		return true;
	}
	double value;
	if (!readNumber(loader, object, "radius", &value))
	{
		return false;
	}
	if (value < 0.0)
	{
		return failAt(loader, "radius", "invalid %s: %s (\"radius\" = %g)", typeName,
					  cdGetResultString(CD_ERROR_NEGATIVE_SIZE), value);
	}
	*radius = (cdReal)value;
	return true;
}

/* Optional "angle" (radians) or "degrees"; 0 when neither is given. */
static bool readAngle(Loader* loader, const cJSON* object, bool* present, double* radians)
{
	bool hasAngle = cJSON_GetObjectItemCaseSensitive(object, "angle") != NULL;
	bool hasDegrees = cJSON_GetObjectItemCaseSensitive(object, "degrees") != NULL;
	*present = hasAngle || hasDegrees;
	*radians = 0.0;
	if (hasAngle && hasDegrees)
	{
		return failAt(loader, "degrees", "give either \"angle\" (radians) or \"degrees\", not both");
	}
	if (hasAngle)
	{
		return readNumber(loader, object, "angle", radians);
	}
	if (hasDegrees)
	{
		double degrees;
		if (!readNumber(loader, object, "degrees", &degrees))
		{
			return false;
		}
		*radians = degrees * (3.14159265358979323846 / 180.0);
	}
	return true;
}

static bool readAabbBounds(Loader* loader, const cJSON* object, double min[3], double max[3])
{
	if (!readVector(loader, object, "min", min) || !readVector(loader, object, "max", max))
	{
		return false;
	}
	static const char* const axes[3] = {"x", "y", "z"};
	for (int i = 0; i < loader->dimension; ++i)
	{
		if (min[i] > max[i])
		{
			return failAt(loader, "min", "\"min\" is greater than \"max\" on the %s axis (%g > %g)", axes[i],
						  min[i], max[i]);
		}
	}
	return true;
}

/* The corners must already form a convex polygon in order: cd2MakePolygon would quietly turn a
 * non-convex or scrambled point list into its hull, and the user would get answers for a shape
 * they did not write. Collinear and repeated corners are allowed (the builder drops them). */
static bool checkConvexOrder(Loader* loader, const double (*points)[3], int count)
{
	/* All corners on one line: the builder reports that as degenerate, which says it best. */
	int distinct = 1;
	while (distinct < count && points[distinct][0] == points[0][0] && points[distinct][1] == points[0][1])
	{
		++distinct;
	}
	bool collinear = true;
	for (int i = distinct + 1; i < count && collinear; ++i)
	{
		collinear = (points[distinct][0] - points[0][0]) * (points[i][1] - points[0][1]) ==
					(points[distinct][1] - points[0][1]) * (points[i][0] - points[0][0]);
	}
	if (collinear)
	{
		return true;
	}
	int sign = 0;
	double turning = 0.0;
	for (int i = 0; i < count; ++i)
	{
		const double* p0 = points[i];
		const double* p1 = points[(i + 1) % count];
		const double* p2 = points[(i + 2) % count];
		double e1x = p1[0] - p0[0], e1y = p1[1] - p0[1];
		double e2x = p2[0] - p1[0], e2y = p2[1] - p1[1];
		double cross = e1x * e2y - e1y * e2x;
		double dot = e1x * e2x + e1y * e2y;
		if (cross != 0.0)
		{
			int s = cross > 0.0 ? 1 : -1;
			if (sign != 0 && s != sign)
			{
				return failAt(loader, "points", "polygon is not convex: it turns the other way at corner %d",
							  (i + 1) % count + 1);
			}
			sign = s;
		}
		else if (dot < 0.0)
		{
			return failAt(loader, "points", "polygon is not convex: it folds back on itself at corner %d",
						  (i + 1) % count + 1);
		}
		turning += atan2(cross, dot);
	}
	/* A simple convex polygon turns once around (2 pi); a star like a pentagram turns twice. */
	if (sign != 0 && fabs(turning) > 3.0 * 3.14159265358979323846)
	{
		return failAt(loader, "points", "polygon is not convex: its edges cross each other");
	}
	return true;
}

static bool readPolygon(Loader* loader, const cJSON* object, cd2Polygon* polygon)
{
	cdReal radius;
	if (!readRoundingRadius(loader, object, "polygon", &radius))
	{
		return false;
	}
	const cJSON* item = cJSON_GetObjectItemCaseSensitive(object, "points");
	if (item == NULL)
	{
		return failAt(loader, NULL, "missing field \"points\"");
	}
	if (!cJSON_IsArray(item))
	{
		return failAt(loader, "points", "\"points\" must be an array of [x, y] points, not %s",
					  jsonTypeName(item));
	}
	int count = 0;
	for (const cJSON* element = item->child; element != NULL; element = element->next)
	{
		++count;
		if (count > TOOL_MAX_POLYGON_INPUT_POINTS)
		{
			return failAt(loader, "points", "\"points\" has more than %d points",
						  TOOL_MAX_POLYGON_INPUT_POINTS);
		}
	}
	if (count < 3)
	{
		return failAt(loader, "points", "a polygon needs at least 3 points, not %d", count);
	}
	double(*points)[3] = malloc((size_t)count * sizeof *points);
	cd2Vec* vertices = malloc((size_t)count * sizeof *vertices);
	bool ok = points != NULL && vertices != NULL;
	if (!ok)
	{
		failAt(loader, NULL, "out of memory");
	}
	int n = 0;
	for (const cJSON* element = item->child; ok && element != NULL; element = element->next, ++n)
	{
		char what[48];
		snprintf(what, sizeof what, "point %d of \"points\"", n + 1);
		ok = readNumbers(loader, element, "points", what, 2, points[n]);
		if (ok)
		{
			vertices[n] = toVec2(points[n]);
		}
	}
	ok = ok && checkConvexOrder(loader, (const double(*)[3])points, count);
	if (ok)
	{
		cdResult result = cd2MakeRoundedPolygon(vertices, count, radius, polygon);
		if (result != CD_OK)
		{
			char limit[48] = "";
			if (result == CD_ERROR_TOO_MANY_POINTS)
			{
				snprintf(limit, sizeof limit, " (at most %d corners)", CD2_MAX_POLYGON_VERTICES);
			}
			ok = failAt(loader, "points", "invalid polygon: %s%s", cdGetResultString(result), limit);
		}
	}
	free(points);
	free(vertices);
	return ok;
}

static bool readTriangle(Loader* loader, const cJSON* object, cd3Triangle* triangle)
{
	const cJSON* item = cJSON_GetObjectItemCaseSensitive(object, "points");
	if (item == NULL)
	{
		return failAt(loader, NULL, "missing field \"points\"");
	}
	if (!cJSON_IsArray(item) || cJSON_GetArraySize(item) != 3)
	{
		return failAt(loader, "points", "\"points\" must be an array of 3 points [x, y, z]");
	}
	double p[3][3];
	int n = 0;
	for (const cJSON* element = item->child; element != NULL; element = element->next, ++n)
	{
		char what[48];
		snprintf(what, sizeof what, "point %d of \"points\"", n + 1);
		if (!readNumbers(loader, element, "points", what, 3, p[n]))
		{
			return false;
		}
	}
	triangle->a = toVec3(p[0]);
	triangle->b = toVec3(p[1]);
	triangle->c = toVec3(p[2]);
	return true;
}

static bool readBox3Rotation(Loader* loader, const cJSON* object, cd3Quat* rotation)
{
	const cJSON* quat = cJSON_GetObjectItemCaseSensitive(object, "rotation");
	const cJSON* axisItem = cJSON_GetObjectItemCaseSensitive(object, "axis");
	bool hasAngle;
	double radians;
	if (!readAngle(loader, object, &hasAngle, &radians))
	{
		return false;
	}
	*rotation = CD3_QUAT_IDENTITY;
	if (quat != NULL)
	{
		if (axisItem != NULL || hasAngle)
		{
			return failAt(loader, "rotation",
						  "give either \"rotation\" or \"axis\" with \"angle\"/\"degrees\"");
		}
		double q[4];
		if (!readNumbers(loader, quat, "rotation", "\"rotation\" (a quaternion x, y, z, w)", 4, q))
		{
			return false;
		}
		*rotation = cd3MakeQuat((cdReal)q[0], (cdReal)q[1], (cdReal)q[2], (cdReal)q[3]);
		return true;
	}
	if (axisItem == NULL)
	{
		return hasAngle ? failAt(loader, NULL, "an \"angle\" or \"degrees\" needs an \"axis\"") : true;
	}
	double axis[3];
	if (!readVector(loader, object, "axis", axis))
	{
		return false;
	}
	if (!hasAngle)
	{
		return failAt(loader, "axis", "an \"axis\" needs an \"angle\" (radians) or \"degrees\"");
	}
	if (axis[0] == 0.0 && axis[1] == 0.0 && axis[2] == 0.0)
	{
		return failAt(loader, "axis", "\"axis\" must not be zero");
	}
	*rotation = cd3MakeQuatAxisAngle(toVec3(axis), (cdReal)radians);
	return true;
}

/* The hull is built here and owned by the shape from then on (also when a later check fails:
 * readScene and toolFreeDocument destroy it). */
static bool readHull(Loader* loader, const cJSON* object, ToolShape* shape)
{
	const cJSON* item = cJSON_GetObjectItemCaseSensitive(object, "points");
	if (item == NULL)
	{
		return failAt(loader, NULL, "missing field \"points\"");
	}
	if (!cJSON_IsArray(item))
	{
		return failAt(loader, "points", "\"points\" must be an array of [x, y, z] points, not %s",
					  jsonTypeName(item));
	}
	int count = 0;
	for (const cJSON* element = item->child; element != NULL; element = element->next)
	{
		if (++count > TOOL_MAX_HULL_INPUT_POINTS)
		{
			return failAt(loader, "points", "\"points\" has more than %d points", TOOL_MAX_HULL_INPUT_POINTS);
		}
	}
	if (count < 4)
	{
		return failAt(loader, "points", "a hull needs at least 4 points (not all in one plane), not %d",
					  count);
	}
	double position[3] = {0.0, 0.0, 0.0};
	cd3Quat rotation;
	if ((cJSON_GetObjectItemCaseSensitive(object, "position") != NULL &&
		 !readVector(loader, object, "position", position)) ||
		!readBox3Rotation(loader, object, &rotation))
	{
		return false;
	}
	cd3Vec* points = malloc((size_t)count * sizeof *points);
	if (points == NULL)
	{
		return failAt(loader, NULL, "out of memory");
	}
	bool ok = true;
	int n = 0;
	for (const cJSON* element = item->child; ok && element != NULL; element = element->next, ++n)
	{
		char what[48];
		double p[3];
		snprintf(what, sizeof what, "point %d of \"points\"", n + 1);
		ok = readNumbers(loader, element, "points", what, 3, p);
		if (ok)
		{
			points[n] = toVec3(p);
		}
	}
	if (ok)
	{
		cdResult result = cd3ComputeHull(points, count, &shape->hull);
		if (result != CD_OK)
		{
			const char* why =
				result == CD_ERROR_DEGENERATE ? " (the points must not all lie in one plane)" : "";
			ok = failAt(loader, "points", "invalid hull: %s%s", cdGetResultString(result), why);
		}
	}
	free(points);
	if (ok)
	{
		cd3Transform transform = {toVec3(position), rotation};
		shape->shape3 = cd3MakeHullShape(shape->hull, transform);
	}
	return ok;
}

static bool readShape2(Loader* loader, const cJSON* object, ShapeKind kind, ToolShape* shape)
{
	double a[3], b[3];
	switch (kind)
	{
		case KIND_POINT:
			if (!readVector(loader, object, "at", a))
			{
				return false;
			}
			shape->isPoint = true;
			shape->point2 = toVec2(a);
			return true;
		case KIND_CIRCLE:
		{
			cd2Circle circle;
			if (!readVector(loader, object, "center", a) || !readRadius(loader, object, &circle.radius))
			{
				return false;
			}
			circle.center = toVec2(a);
			shape->shape2 = cd2MakeCircleShape(circle);
			return true;
		}
		case KIND_CAPSULE:
		{
			cd2Capsule capsule;
			if (!readVector(loader, object, "p1", a) || !readVector(loader, object, "p2", b) ||
				!readRadius(loader, object, &capsule.radius))
			{
				return false;
			}
			capsule.p1 = toVec2(a);
			capsule.p2 = toVec2(b);
			shape->shape2 = cd2MakeCapsuleShape(capsule);
			return true;
		}
		case KIND_AABB:
		{
			if (!readAabbBounds(loader, object, a, b))
			{
				return false;
			}
			cd2Aabb aabb = {toVec2(a), toVec2(b)};
			shape->shape2 = cd2MakeAabbShape(aabb);
			return true;
		}
		case KIND_BOX:
		{
			bool hasAngle;
			double radians;
			cdReal radius;
			if (!readVector(loader, object, "center", a) || !readVector(loader, object, "halfExtents", b) ||
				!readAngle(loader, object, &hasAngle, &radians) ||
				!readRoundingRadius(loader, object, "box", &radius))
			{
				return false;
			}
			cd2Box box = {toVec2(a), toVec2(b), cd2MakeRot((cdReal)radians)};
			shape->shape2 = cd2MakeBoxShape(box);
			if (radius > CD_R(0.0))
			{
				/* A rounded box is a rounded polygon for the library. */
				cd2Polygon polygon;
				cdResult result = cd2MakeRoundedBoxPolygon(box, radius, &polygon);
				if (result != CD_OK)
				{
					const char* why =
						result == CD_ERROR_DEGENERATE ? " (a rounded box needs a non-zero area)" : "";
					return failAt(loader, NULL, "invalid box: %s%s", cdGetResultString(result), why);
				}
				shape->shape2 = cd2MakePolygonShape(&polygon);
			}
			return true;
		}
		case KIND_POLYGON:
		{
			cd2Polygon polygon;
			if (!readPolygon(loader, object, &polygon))
			{
				return false;
			}
			shape->shape2 = cd2MakePolygonShape(&polygon);
			return true;
		}
		case KIND_SEGMENT:
		{
			if (!readVector(loader, object, "p1", a) || !readVector(loader, object, "p2", b))
			{
				return false;
			}
			cd2Segment segment = {toVec2(a), toVec2(b)};
			shape->shape2 = cd2MakeSegmentShape(segment);
			return true;
		}
		case KIND_TRIANGLE:
		case KIND_PLANE:
		case KIND_HULL:
			break;
	}
	return failAt(loader, "type", "shape type not available in 2D");
}

static bool readShape3(Loader* loader, const cJSON* object, ShapeKind kind, ToolShape* shape)
{
	double a[3], b[3];
	switch (kind)
	{
		case KIND_POINT:
			if (!readVector(loader, object, "at", a))
			{
				return false;
			}
			shape->isPoint = true;
			shape->point3 = toVec3(a);
			return true;
		case KIND_CIRCLE:
		{
			cd3Sphere sphere;
			if (!readVector(loader, object, "center", a) || !readRadius(loader, object, &sphere.radius))
			{
				return false;
			}
			sphere.center = toVec3(a);
			shape->shape3 = cd3MakeSphereShape(sphere);
			return true;
		}
		case KIND_CAPSULE:
		{
			cd3Capsule capsule;
			if (!readVector(loader, object, "p1", a) || !readVector(loader, object, "p2", b) ||
				!readRadius(loader, object, &capsule.radius))
			{
				return false;
			}
			capsule.p1 = toVec3(a);
			capsule.p2 = toVec3(b);
			shape->shape3 = cd3MakeCapsuleShape(capsule);
			return true;
		}
		case KIND_AABB:
		{
			if (!readAabbBounds(loader, object, a, b))
			{
				return false;
			}
			cd3Aabb aabb = {toVec3(a), toVec3(b)};
			shape->shape3 = cd3MakeAabbShape(aabb);
			return true;
		}
		case KIND_BOX:
		{
			cd3Box box;
			if (!readVector(loader, object, "center", a) || !readVector(loader, object, "halfExtents", b) ||
				!readBox3Rotation(loader, object, &box.rotation))
			{
				return false;
			}
			box.center = toVec3(a);
			box.halfExtents = toVec3(b);
			shape->shape3 = cd3MakeBoxShape(box);
			return true;
		}
		case KIND_TRIANGLE:
		{
			cd3Triangle triangle;
			if (!readTriangle(loader, object, &triangle))
			{
				return false;
			}
			shape->shape3 = cd3MakeTriangleShape(triangle);
			return true;
		}
		case KIND_PLANE:
		{
			double offset;
			if (!readVector(loader, object, "normal", a) || !readNumber(loader, object, "offset", &offset))
			{
				return false;
			}
			cd3Plane plane = {toVec3(a), (cdReal)offset};
			shape->shape3 = cd3MakePlaneShape(plane);
			return true;
		}
		case KIND_SEGMENT:
		{
			if (!readVector(loader, object, "p1", a) || !readVector(loader, object, "p2", b))
			{
				return false;
			}
			cd3Segment segment = {toVec3(a), toVec3(b)};
			shape->shape3 = cd3MakeSegmentShape(segment);
			return true;
		}
		case KIND_HULL:
			return readHull(loader, object, shape);
		case KIND_POLYGON:
			break;
	}
	return failAt(loader, "type", "shape type not available in 3D");
}

static bool readShape(Loader* loader, const cJSON* object, ToolShape* shape)
{
	if (!cJSON_IsObject(object))
	{
		return failAt(loader, NULL, "a shape must be an object, not %s", jsonTypeName(object));
	}
	memset(shape, 0, sizeof *shape);
	if (!readName(loader, object, true, shape->name))
	{
		return false;
	}
	loader->shapeName = shape->name;
	shape->line = jsonReaderLine(&loader->json, "name");

	const cJSON* typeItem = cJSON_GetObjectItemCaseSensitive(object, "type");
	if (typeItem == NULL)
	{
		return failAt(loader, NULL, "missing field \"type\"");
	}
	char types[160];
	listShapeTypes(loader->dimension, types, sizeof types);
	if (!cJSON_IsString(typeItem) || typeItem->valuestring == NULL)
	{
		return failAt(loader, "type", "\"type\" must be a string (one of %s)", types);
	}
	const ShapeTypeInfo* info = findShapeType(typeItem->valuestring, loader->dimension);
	if (info == NULL)
	{
		char shown[48];
		return failAt(loader, "type", "unknown shape type \"%s\" in a %dD scene (expected one of %s)",
					  jsonPrintable(typeItem->valuestring, shown, sizeof shown), loader->dimension, types);
	}
	shape->typeName = info->name;
	if (!checkKeys(loader, object, info->fields))
	{
		return false;
	}
	bool ok = loader->dimension == 2 ? readShape2(loader, object, info->kind, shape)
									 : readShape3(loader, object, info->kind, shape);
	if (!ok || shape->isPoint)
	{
		return ok;
	}
	/* The library's validator has the last word (non-unit rotations and normals, negative sizes,
	 * degenerate triangles, ...). */
	cdResult result =
		loader->dimension == 2 ? cd2ValidateShape(&shape->shape2) : cd3ValidateShape(&shape->shape3);
	if (result != CD_OK)
	{
		return failAt(loader, NULL, "invalid %s: %s", info->name, cdGetResultString(result));
	}
	return true;
}

/* ---- scenes and the document ----------------------------------------------------------------- */

static bool readScene(Loader* loader, const cJSON* object, int sceneIndex, ToolScene* scene)
{
	static const char* const sceneFields[] = {"name", "dimension", "shapes", NULL};
	loader->shapeName = NULL;
	loader->shapeIndex = -1;
	loader->sceneName = NULL;
	if (!cJSON_IsObject(object))
	{
		return failAt(loader, NULL, "a scene must be an object, not %s", jsonTypeName(object));
	}
	if (!checkKeys(loader, object, sceneFields))
	{
		return false;
	}
	snprintf(scene->name, sizeof scene->name, "scene%d", sceneIndex + 1);
	if (!readName(loader, object, false, scene->name))
	{
		return false;
	}
	loader->sceneName = scene->name;
	double dimension;
	if (!readNumber(loader, object, "dimension", &dimension))
	{
		return false;
	}
	if (dimension != 2.0 && dimension != 3.0)
	{
		return failAt(loader, "dimension", "\"dimension\" must be 2 or 3, not %g", dimension);
	}
	scene->dimension = (int)dimension;
	loader->dimension = scene->dimension;

	const cJSON* shapes = cJSON_GetObjectItemCaseSensitive(object, "shapes");
	if (shapes == NULL)
	{
		return failAt(loader, NULL, "missing field \"shapes\"");
	}
	if (!cJSON_IsArray(shapes))
	{
		return failAt(loader, "shapes", "\"shapes\" must be an array, not %s", jsonTypeName(shapes));
	}
	int count = 0;
	for (const cJSON* item = shapes->child; item != NULL; item = item->next)
	{
		if (++count > TOOL_MAX_SHAPES_PER_SCENE)
		{
			return failAt(loader, "shapes", "more than %d shapes", TOOL_MAX_SHAPES_PER_SCENE);
		}
	}
	scene->shapes = count > 0 ? calloc((size_t)count, sizeof(ToolShape)) : NULL;
	if (count > 0 && scene->shapes == NULL)
	{
		return failAt(loader, NULL, "out of memory");
	}
	jsonReaderPushKey(&loader->json, "shapes");
	int index = 0;
	for (const cJSON* item = shapes->child; item != NULL; item = item->next, ++index)
	{
		jsonReaderPushIndex(&loader->json, index);
		loader->shapeName = NULL;
		loader->shapeIndex = index;
		bool ok = readShape(loader, item, &scene->shapes[index]);
		if (ok)
		{
			for (int other = 0; other < index; ++other)
			{
				if (strcmp(scene->shapes[other].name, scene->shapes[index].name) == 0)
				{
					ok = failAt(loader, "name", "the name is already used by shape #%d of scene \"%s\"",
								other + 1, scene->name);
					break;
				}
			}
		}
		jsonReaderPop(&loader->json);
		if (!ok)
		{
			/* Not counted in shapeCount, so toolFreeDocument would not see its hull. */
			cd3DestroyHull(scene->shapes[index].hull);
			scene->shapes[index].hull = NULL;
			jsonReaderPop(&loader->json);
			return false;
		}
		++scene->shapeCount;
	}
	jsonReaderPop(&loader->json);
	loader->shapeName = NULL;
	loader->shapeIndex = -1;
	return true;
}

static bool readDocument(Loader* loader, const cJSON* root, ToolDocument* document)
{
	if (!cJSON_IsObject(root))
	{
		return failAt(loader, NULL, "the top level must be an object with \"scenes\" or \"shapes\", not %s",
					  jsonTypeName(root));
	}
	const cJSON* scenes = cJSON_GetObjectItemCaseSensitive(root, "scenes");
	if (scenes == NULL)
	{
		if (cJSON_GetObjectItemCaseSensitive(root, "world") != NULL)
		{
			return failAt(
				loader, "world",
				"this is a physics scene (\"world\"): run it with `collide run`, see docs/SCENES.md");
		}
		if (cJSON_GetObjectItemCaseSensitive(root, "shapes") == NULL)
		{
			return failAt(loader, NULL,
						  "the top level needs \"scenes\" (a list of scenes) or \"shapes\" (one scene)");
		}
		document->scenes = calloc(1, sizeof(ToolScene));
		if (document->scenes == NULL)
		{
			return failAt(loader, NULL, "out of memory");
		}
		document->sceneCount = 1;
		return readScene(loader, root, 0, &document->scenes[0]);
	}
	static const char* const rootFields[] = {"scenes", NULL};
	if (!checkKeys(loader, root, rootFields))
	{
		return false;
	}
	if (!cJSON_IsArray(scenes))
	{
		return failAt(loader, "scenes", "\"scenes\" must be an array, not %s", jsonTypeName(scenes));
	}
	int count = 0;
	for (const cJSON* item = scenes->child; item != NULL; item = item->next)
	{
		if (++count > TOOL_MAX_SCENES)
		{
			return failAt(loader, "scenes", "more than %d scenes", TOOL_MAX_SCENES);
		}
	}
	if (count == 0)
	{
		return failAt(loader, "scenes", "\"scenes\" is empty");
	}
	document->scenes = calloc((size_t)count, sizeof(ToolScene));
	if (document->scenes == NULL)
	{
		return failAt(loader, NULL, "out of memory");
	}
	jsonReaderPushKey(&loader->json, "scenes");
	int index = 0;
	for (const cJSON* item = scenes->child; item != NULL; item = item->next, ++index)
	{
		jsonReaderPushIndex(&loader->json, index);
		document->sceneCount = index + 1;
		bool ok = readScene(loader, item, index, &document->scenes[index]);
		jsonReaderPop(&loader->json);
		if (!ok)
		{
			jsonReaderPop(&loader->json);
			return false;
		}
	}
	jsonReaderPop(&loader->json);
	return true;
}

/* ---- the file -------------------------------------------------------------------------------- */

static bool fail(ToolError* error, int line, const char* reason)
{
	error->line = line;
	snprintf(error->message, sizeof error->message, "%s", reason);
	return false;
}

/* Reads the whole file into a NUL-terminated buffer. */
static bool readFile(const char* path, char** text, size_t* length, ToolError* error)
{
	FILE* file = fopen(path, "rb");
	if (file == NULL)
	{
		char reason[256];
		snprintf(reason, sizeof reason, "cannot open: %s", strerror(errno));
		return fail(error, 0, reason);
	}
	size_t capacity = 1 << 16, used = 0;
	char* buffer = malloc(capacity);
	bool ok = buffer != NULL;
	if (!ok)
	{
		fail(error, 0, "out of memory");
	}
	while (ok)
	{
		/* Room for one byte past the limit (to see it) and the NUL, never more. */
		const size_t most = (size_t)TOOL_MAX_FILE_BYTES + 2;
		if (used + 1 >= capacity)
		{
			size_t next = capacity * 2 < most ? capacity * 2 : most;
			char* bigger = realloc(buffer, next);
			if (bigger == NULL)
			{
				ok = fail(error, 0, "out of memory");
				break;
			}
			buffer = bigger;
			capacity = next;
		}
		size_t got = fread(buffer + used, 1, capacity - 1 - used, file);
		used += got;
		if (used > TOOL_MAX_FILE_BYTES)
		{
			char reason[128];
			snprintf(reason, sizeof reason, "file is larger than %u MiB", TOOL_MAX_FILE_BYTES >> 20);
			ok = fail(error, 0, reason);
			break;
		}
		if (got == 0)
		{
			if (ferror(file))
			{
				char reason[256];
				snprintf(reason, sizeof reason, "cannot read: %s", strerror(errno));
				ok = fail(error, 0, reason);
			}
			break;
		}
	}
	fclose(file);
	if (!ok)
	{
		free(buffer);
		return false;
	}
	buffer[used] = 0;
	*text = buffer;
	*length = used;
	return true;
}

/* A short, printable excerpt of the text at offset, for syntax error messages. */
static void excerpt(const char* text, size_t length, size_t offset, char* out, size_t size)
{
	size_t n = 0;
	for (size_t i = offset; i < length && n + 1 < size && n < 20; ++i)
	{
		unsigned char c = (unsigned char)text[i];
		if (c == '\n' || c == '\r')
		{
			break;
		}
		out[n++] = (c >= 0x20 && c < 0x7f) ? (char)c : '?';
	}
	out[n] = 0;
}

static bool syntaxError(const char* text, size_t length, size_t offset, ToolError* error)
{
	int line = jsonLineOfOffset(text, length, offset);
	size_t rest = offset;
	while (rest < length && strchr(" \t\r\n", text[rest]) != NULL)
	{
		++rest;
	}
	if (rest >= length)
	{
		size_t last = length;
		while (last > 0 && strchr(" \t\r\n", text[last - 1]) != NULL)
		{
			--last;
		}
		return fail(error, jsonLineOfOffset(text, length, last > 0 ? last - 1 : 0),
					"JSON syntax error: unexpected end of file (unclosed bracket, brace or string?)");
	}
	char near[32];
	excerpt(text, length, offset, near, sizeof near);
	static const char* const nonNumbers[] = {"NaN", "nan", "-NaN", "Infinity", "-Infinity", "inf", "-inf"};
	for (size_t i = 0; i < sizeof nonNumbers / sizeof nonNumbers[0]; ++i)
	{
		if (strncmp(near, nonNumbers[i], strlen(nonNumbers[i])) == 0)
		{
			return fail(error, line, "NaN and infinity are not numbers in JSON (and not valid in a shape)");
		}
	}
	char reason[128];
	snprintf(reason, sizeof reason, "JSON syntax error near '%s'", near);
	return fail(error, line, reason);
}

bool toolReadJsonFile(const char* path, char** textOut, size_t* lengthOut, void** rootOut, ToolError* error)
{
	error->line = 0;
	error->message[0] = 0;
	*textOut = NULL;
	*lengthOut = 0;
	*rootOut = NULL;

	char* text;
	size_t length;
	if (!readFile(path, &text, &length, error))
	{
		return false;
	}
	const char* start = text;
	size_t startLength = length;
	/* A UTF-8 byte order mark is harmless; cJSON does not expect it. */
	if (length >= 3 && memcmp(text, "\xEF\xBB\xBF", 3) == 0)
	{
		memset(text, ' ', 3);
	}
	bool ok = true;
	const char* nul = memchr(start, 0, startLength);
	size_t tooDeep = 0;
	size_t blank = strspn(start, " \t\r\n");
	if (nul != NULL)
	{
		ok = fail(error, jsonLineOfOffset(start, startLength, (size_t)(nul - start)),
				  "the file contains a NUL byte (not a text file?)");
	}
	else if (blank == startLength)
	{
		ok = fail(error, 0, "the file is empty");
	}
	else if (jsonMaxDepth(start, startLength, TOOL_MAX_NESTING, &tooDeep) > TOOL_MAX_NESTING)
	{
		char reason[96];
		snprintf(reason, sizeof reason, "arrays and objects are nested deeper than %d levels",
				 TOOL_MAX_NESTING);
		ok = fail(error, jsonLineOfOffset(start, startLength, tooDeep), reason);
	}
	size_t lexicalOffset = 0;
	const char* lexicalReason = NULL;
	if (ok && !jsonCheckLexical(start, startLength, &lexicalOffset, &lexicalReason))
	{
		ok = fail(error, jsonLineOfOffset(start, startLength, lexicalOffset), lexicalReason);
	}
	cJSON* root = NULL;
	if (ok)
	{
		/* The length includes the terminating NUL: cJSON's require_null_terminated check looks for it. */
		root = cJSON_ParseWithLengthOpts(start, startLength + 1, NULL, 1);
		if (root == NULL)
		{
			const char* where = cJSON_GetErrorPtr();
			size_t offset = (where != NULL && where >= start && where <= start + startLength)
								? (size_t)(where - start)
								: startLength;
			ok = syntaxError(start, startLength, offset, error);
		}
	}
	if (!ok)
	{
		cJSON_Delete(root);
		free(text);
		return false;
	}
	*textOut = text;
	*lengthOut = startLength;
	*rootOut = root;
	return true;
}

bool toolLoadDocument(const char* path, ToolDocument* document, ToolError* error)
{
	memset(document, 0, sizeof *document);
	char* text;
	size_t length;
	void* rootPointer;
	if (!toolReadJsonFile(path, &text, &length, &rootPointer, error))
	{
		return false;
	}
	cJSON* root = rootPointer;
	Loader loader;
	memset(&loader, 0, sizeof loader);
	loader.json.text = text;
	loader.json.length = length;
	loader.json.error = error;
	loader.shapeIndex = -1;
	bool ok = readDocument(&loader, root, document);
	cJSON_Delete(root);
	free(text);
	if (!ok)
	{
		toolFreeDocument(document);
	}
	return ok;
}

void toolFreeDocument(ToolDocument* document)
{
	for (int i = 0; i < document->sceneCount; ++i)
	{
		ToolScene* scene = &document->scenes[i];
		for (int k = 0; k < scene->shapeCount; ++k)
		{
			cd3DestroyHull(scene->shapes[k].hull);
		}
		free(scene->shapes);
	}
	free(document->scenes);
	document->scenes = NULL;
	document->sceneCount = 0;
}
