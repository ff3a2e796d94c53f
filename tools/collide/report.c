/* collide tool: the text report. One table row per pair with fixed-width columns, one summary
 * line per scene, then a table of the contact manifolds of the 2D pairs that have one. */
#include "scene.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#if !defined(_WIN32)
#include <unistd.h>
#endif

const char* toolFormatNumber(double value, char* buffer, size_t size)
{
	double magnitude = fabs(value);
	if (magnitude >= 1e6 || (magnitude < 1e-3 && magnitude > 0.0))
	{
		snprintf(buffer, size, "%.4g", value);
		return buffer;
	}
	snprintf(buffer, size, "%.4f", value);
	/* Trim trailing zeros (and the point) so that 2.5000 reads 2.5 and 3.0000 reads 3. */
	char* point = strchr(buffer, '.');
	if (point != NULL)
	{
		char* end = buffer + strlen(buffer) - 1;
		while (end > point && *end == '0')
		{
			*end-- = 0;
		}
		if (end == point)
		{
			*end = 0;
		}
	}
	if (strcmp(buffer, "-0") == 0)
	{
		snprintf(buffer, size, "0");
	}
	return buffer;
}

/* Coordinates a million times smaller than the point's largest one are round-off of the float
 * queries (4.5e-08 next to 1.5); they print as 0 so that the table stays readable. */
static void formatPoint(const double p[3], int dimension, char* buffer, size_t size)
{
	double largest = fmax(fabs(p[0]), fmax(fabs(p[1]), dimension == 3 ? fabs(p[2]) : 0.0));
	double shown[3];
	for (int i = 0; i < 3; ++i)
	{
		shown[i] = fabs(p[i]) < 1e-6 * largest ? 0.0 : p[i];
	}
	char x[32], y[32], z[32];
	toolFormatNumber(shown[0], x, sizeof x);
	toolFormatNumber(shown[1], y, sizeof y);
	if (dimension == 2)
	{
		snprintf(buffer, size, "(%s, %s)", x, y);
	}
	else
	{
		snprintf(buffer, size, "(%s, %s, %s)", x, y, toolFormatNumber(shown[2], z, sizeof z));
	}
}

/* Width on a terminal: one column per UTF-8 code point (names are checked to be valid UTF-8). */
static int displayWidth(const char* s)
{
	int width = 0;
	for (const unsigned char* p = (const unsigned char*)s; *p != 0; ++p)
	{
		width += (*p & 0xc0) != 0x80 ? 1 : 0;
	}
	return width;
}

static void printCell(FILE* out, const char* text, int width, bool last)
{
	fputs(text, out);
	if (!last)
	{
		for (int i = displayWidth(text); i < width + 2; ++i)
		{
			fputc(' ', out);
		}
	}
}

enum
{
	COLUMN_SCENE,
	COLUMN_A,
	COLUMN_B,
	COLUMN_OVERLAP,
	COLUMN_DISTANCE,
	COLUMN_POINT_A,
	COLUMN_POINT_B,
	COLUMN_COUNT
};

typedef struct Row
{
	char cells[COLUMN_COUNT][96];
} Row;

static void fillRow(const ToolSceneResult* result, const ToolPairResult* pair, Row* row)
{
	const ToolScene* scene = result->scene;
	snprintf(row->cells[COLUMN_SCENE], sizeof row->cells[0], "%s", scene->name);
	snprintf(row->cells[COLUMN_A], sizeof row->cells[0], "%s", scene->shapes[pair->a].name);
	snprintf(row->cells[COLUMN_B], sizeof row->cells[0], "%s", scene->shapes[pair->b].name);
	snprintf(row->cells[COLUMN_OVERLAP], sizeof row->cells[0], "%s", pair->overlap ? "yes" : "no");
	toolFormatNumber(pair->distance, row->cells[COLUMN_DISTANCE], sizeof row->cells[0]);
	formatPoint(pair->pointA, scene->dimension, row->cells[COLUMN_POINT_A], sizeof row->cells[0]);
	formatPoint(pair->pointB, scene->dimension, row->cells[COLUMN_POINT_B], sizeof row->cells[0]);
}

static void printRow(FILE* out, const Row* row, const int* widths)
{
	for (int c = 0; c < COLUMN_COUNT; ++c)
	{
		printCell(out, row->cells[c], widths[c], c == COLUMN_COUNT - 1);
	}
	fputc('\n', out);
}

/* ---- contacts: a second table of the 2D pairs with a contact manifold ---- */

enum
{
	CONTACT_SCENE,
	CONTACT_A,
	CONTACT_B,
	CONTACT_COUNT_COLUMN,
	CONTACT_NORMAL,
	CONTACT_POINTS,
	CONTACT_DEEPEST,
	CONTACT_COLUMN_COUNT
};

typedef struct ContactRow
{
	char cells[CONTACT_COLUMN_COUNT][128];
} ContactRow;

static void fillContactRow(const ToolSceneResult* result, const ToolPairResult* pair, ContactRow* row)
{
	const ToolScene* scene = result->scene;
	snprintf(row->cells[CONTACT_SCENE], sizeof row->cells[0], "%s", scene->name);
	snprintf(row->cells[CONTACT_A], sizeof row->cells[0], "%s", scene->shapes[pair->a].name);
	snprintf(row->cells[CONTACT_B], sizeof row->cells[0], "%s", scene->shapes[pair->b].name);
	snprintf(row->cells[CONTACT_COUNT_COLUMN], sizeof row->cells[0], "%d", pair->contactCount);
	double normal[3] = {pair->contactNormal[0], pair->contactNormal[1], 0.0};
	formatPoint(normal, 2, row->cells[CONTACT_NORMAL], sizeof row->cells[0]);
	char first[48], second[48];
	double p0[3] = {pair->contactPoints[0][0], pair->contactPoints[0][1], 0.0};
	double p1[3] = {pair->contactPoints[1][0], pair->contactPoints[1][1], 0.0};
	formatPoint(p0, 2, first, sizeof first);
	formatPoint(p1, 2, second, sizeof second);
	snprintf(row->cells[CONTACT_POINTS], sizeof row->cells[0], "%s%s%s", first,
			 pair->contactCount > 1 ? " " : "", pair->contactCount > 1 ? second : "");
	toolFormatNumber(pair->deepestSeparation, row->cells[CONTACT_DEEPEST], sizeof row->cells[0]);
}

static void printContactRow(FILE* out, const ContactRow* row, const int* widths)
{
	for (int c = 0; c < CONTACT_COLUMN_COUNT; ++c)
	{
		printCell(out, row->cells[c], widths[c], c == CONTACT_COLUMN_COUNT - 1);
	}
	fputc('\n', out);
}

/* The rows end with a number, never with a point: scripts tell the pair rows of the first table
 * by their closing parenthesis. */
static void printContacts(FILE* out, const ToolSceneResult* results, int sceneCount)
{
	ContactRow header = {
		{"scene", "A", "B", "points", "normal (A to B)", "contact points", "deepest separation"}};
	int widths[CONTACT_COLUMN_COUNT];
	for (int c = 0; c < CONTACT_COLUMN_COUNT; ++c)
	{
		widths[c] = displayWidth(header.cells[c]);
	}
	int rows = 0;
	for (int s = 0; s < sceneCount; ++s)
	{
		for (int p = 0; p < results[s].pairCount; ++p)
		{
			if (!results[s].pairs[p].hasContact)
			{
				continue;
			}
			ContactRow row;
			fillContactRow(&results[s], &results[s].pairs[p], &row);
			for (int c = 0; c < CONTACT_COLUMN_COUNT; ++c)
			{
				int width = displayWidth(row.cells[c]);
				widths[c] = width > widths[c] ? width : widths[c];
			}
			++rows;
		}
	}
	if (rows == 0)
	{
		return;
	}
	char distance[32];
	fprintf(out,
			"\ncontacts of the 2D pairs that touch or are apart by at most %s (cd2Collide; separation < 0 "
			"is depth):\n",
			toolFormatNumber(TOOL_CONTACT_SPECULATIVE_DISTANCE, distance, sizeof distance));
	printContactRow(out, &header, widths);
	ContactRow rule;
	for (int c = 0; c < CONTACT_COLUMN_COUNT; ++c)
	{
		int width = widths[c] < (int)sizeof rule.cells[c] - 1 ? widths[c] : (int)sizeof rule.cells[c] - 1;
		memset(rule.cells[c], '-', (size_t)width);
		rule.cells[c][width] = 0;
	}
	printContactRow(out, &rule, widths);
	for (int s = 0; s < sceneCount; ++s)
	{
		for (int p = 0; p < results[s].pairCount; ++p)
		{
			if (results[s].pairs[p].hasContact)
			{
				ContactRow row;
				fillContactRow(&results[s], &results[s].pairs[p], &row);
				printContactRow(out, &row, widths);
			}
		}
	}
}

void toolPrintReport(FILE* out, const ToolSceneResult* results, int sceneCount)
{
	Row header = {{"scene", "A", "B", "overlap", "distance", "closest point on A", "closest point on B"}};
	int widths[COLUMN_COUNT];
	for (int c = 0; c < COLUMN_COUNT; ++c)
	{
		widths[c] = displayWidth(header.cells[c]);
	}
	/* Two passes (measure, then print) so that every column lines up across all scenes. */
	for (int s = 0; s < sceneCount; ++s)
	{
		for (int p = 0; p < results[s].pairCount; ++p)
		{
			Row row;
			fillRow(&results[s], &results[s].pairs[p], &row);
			for (int c = 0; c < COLUMN_COUNT; ++c)
			{
				int width = displayWidth(row.cells[c]);
				widths[c] = width > widths[c] ? width : widths[c];
			}
		}
	}
	printRow(out, &header, widths);
	Row rule;
	for (int c = 0; c < COLUMN_COUNT; ++c)
	{
		int width = widths[c] < (int)sizeof rule.cells[c] - 1 ? widths[c] : (int)sizeof rule.cells[c] - 1;
		memset(rule.cells[c], '-', (size_t)width);
		rule.cells[c][width] = 0;
	}
	printRow(out, &rule, widths);
	for (int s = 0; s < sceneCount; ++s)
	{
		for (int p = 0; p < results[s].pairCount; ++p)
		{
			Row row;
			fillRow(&results[s], &results[s].pairs[p], &row);
			printRow(out, &row, widths);
		}
	}
	fputc('\n', out);
	for (int s = 0; s < sceneCount; ++s)
	{
		const ToolScene* scene = results[s].scene;
		fprintf(out, "%s (%dD): %d shape%s, %d pair%s, %d overlapping\n", scene->name, scene->dimension,
				scene->shapeCount, scene->shapeCount == 1 ? "" : "s", results[s].pairCount,
				results[s].pairCount == 1 ? "" : "s", results[s].overlapCount);
	}
	printContacts(out, results, sceneCount);
}

/* The widest text toolFormatNumber prints: "-999999.9999" (fixed point below 1e6), the exponent
 * form "-1.234e+30" being shorter. */
#define NUMBER_WIDTH 12

/* Pairs between two progress lines. */
#define PROGRESS_STEP 65536

bool toolStreamReport(FILE* out, const ToolDocument* document, bool progress)
{
	Row header = {{"scene", "A", "B", "overlap", "distance", "closest point on A", "closest point on B"}};
	int widths[COLUMN_COUNT];
	for (int c = 0; c < COLUMN_COUNT; ++c)
	{
		widths[c] = displayWidth(header.cells[c]);
	}
	/* Every width known before the first pair: the names', and the widest numbers and points. */
	int dimension = 2;
	for (int s = 0; s < document->sceneCount; ++s)
	{
		const ToolScene* scene = &document->scenes[s];
		int width = displayWidth(scene->name);
		widths[COLUMN_SCENE] = width > widths[COLUMN_SCENE] ? width : widths[COLUMN_SCENE];
		dimension = scene->dimension > dimension ? scene->dimension : dimension;
		for (int i = 0; i < scene->shapeCount; ++i)
		{
			width = displayWidth(scene->shapes[i].name);
			widths[COLUMN_A] = width > widths[COLUMN_A] ? width : widths[COLUMN_A];
			widths[COLUMN_B] = width > widths[COLUMN_B] ? width : widths[COLUMN_B];
		}
	}
	widths[COLUMN_DISTANCE] = NUMBER_WIDTH > widths[COLUMN_DISTANCE] ? NUMBER_WIDTH : widths[COLUMN_DISTANCE];
	int pointWidth = 2 + dimension * NUMBER_WIDTH + 2 * (dimension - 1); /* "(x, y, z)" */
	for (int c = COLUMN_POINT_A; c <= COLUMN_POINT_B; ++c)
	{
		widths[c] = pointWidth > widths[c] ? pointWidth : widths[c];
	}
	printRow(out, &header, widths);
	Row rule;
	for (int c = 0; c < COLUMN_COUNT; ++c)
	{
		int width = widths[c] < (int)sizeof rule.cells[c] - 1 ? widths[c] : (int)sizeof rule.cells[c] - 1;
		memset(rule.cells[c], '-', (size_t)width);
		rule.cells[c][width] = 0;
	}
	printRow(out, &rule, widths);

	/* Per scene: the counts of the summary, and the 2D contacts kept for their table. */
	ToolSceneResult* kept =
		calloc((size_t)(document->sceneCount > 0 ? document->sceneCount : 1), sizeof *kept);
	if (kept == NULL)
	{
		return false;
	}
	bool ok = true;
	int capacity = 0;
	for (int s = 0; ok && s < document->sceneCount; ++s)
	{
		const ToolScene* scene = &document->scenes[s];
		ToolSceneResult* result = &kept[s];
		result->scene = scene;
		capacity = 0;
		long long total = (long long)scene->shapeCount * (scene->shapeCount - 1) / 2, done = 0;
		bool showProgress = progress && total >= PROGRESS_STEP;
		for (int i = 0; ok && i < scene->shapeCount; ++i)
		{
			for (int j = i + 1; ok && j < scene->shapeCount; ++j)
			{
				ToolPairResult pair;
				toolQueryPair(scene, i, j, &pair);
				result->overlapCount += pair.overlap ? 1 : 0;
				Row row;
				fillRow(result, &pair, &row);
				printRow(out, &row, widths);
				if (pair.hasContact)
				{
					if (result->pairCount == capacity)
					{
						int grown = capacity ? 2 * capacity : 64;
						ToolPairResult* bigger = realloc(result->pairs, (size_t)grown * sizeof *bigger);
						if (bigger == NULL)
						{
							ok = false;
							break;
						}
						result->pairs = bigger;
						capacity = grown;
					}
					result->pairs[result->pairCount++] = pair;
				}
				if (showProgress && ++done % PROGRESS_STEP == 0)
				{
					fflush(out);
					fprintf(stderr, "\r%s: %lld of %lld pairs", scene->name, done, total);
				}
			}
		}
		if (showProgress)
		{
			fprintf(stderr, "\r%*s\r", (int)strlen(scene->name) + 48, "");
		}
	}
	if (ok)
	{
		fputc('\n', out);
		for (int s = 0; s < document->sceneCount; ++s)
		{
			const ToolScene* scene = &document->scenes[s];
			int pairs = scene->shapeCount * (scene->shapeCount - 1) / 2;
			fprintf(out, "%s (%dD): %d shape%s, %d pair%s, %d overlapping\n", scene->name, scene->dimension,
					scene->shapeCount, scene->shapeCount == 1 ? "" : "s", pairs, pairs == 1 ? "" : "s",
					kept[s].overlapCount);
		}
		printContacts(out, kept, document->sceneCount);
	}
	for (int s = 0; s < document->sceneCount; ++s)
	{
		free(kept[s].pairs);
	}
	free(kept);
	return ok;
}

bool toolStderrIsTerminal(void)
{
#if defined(_WIN32)
	return false;
#else
	return isatty(STDERR_FILENO) != 0;
#endif
}
