/* collide tool: a scene file in memory, the answers of its pairwise queries, and the parts of the
 * tool that produce and print them. The file format is described in scene_load.c and
 * examples/README.md. */
#ifndef COLLIDE_TOOL_SCENE_H
#define COLLIDE_TOOL_SCENE_H

#include <collide/collide.h>

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

/* Longest shape or scene name, in bytes (names are printed in table columns and SVG labels). */
#define TOOL_MAX_NAME 64
/* Limits that keep a hostile file from making the tool run for hours or print gigabytes. */
#define TOOL_MAX_SCENES 256
#define TOOL_MAX_SHAPES_PER_SCENE 1000
#define TOOL_MAX_POLYGON_INPUT_POINTS 256
#define TOOL_MAX_HULL_INPUT_POINTS 1024
#define TOOL_MAX_FILE_BYTES (64u * 1024u * 1024u)
#define TOOL_MAX_NESTING 32

/* The documented range of the library's queries (docs: magnitudes up to 1e9 in float, 1e30 in
 * double); the loader rejects larger numbers instead of producing answers nobody promised. */
#if CD_DOUBLE
#define TOOL_MAX_MAGNITUDE 1e30
#else
#define TOOL_MAX_MAGNITUDE 1e9
#endif

typedef struct ToolShape
{
	char name[TOOL_MAX_NAME + 1];
	const char* typeName; /* as written in the file: "point", "circle", "box", ... */
	int line;			  /* line of the shape in the file, for messages */
	bool isPoint;		  /* points are not library shapes: the tool tests them itself */
	cd2Vec point2;
	cd3Vec point3;
	cd2Shape shape2;
	cd3Shape shape3;
	cd3Hull* hull; /* owned: the hull shape3 refers to (NULL for other shapes) */
} ToolShape;

typedef struct ToolScene
{
	char name[TOOL_MAX_NAME + 1];
	int dimension; /* 2 or 3 */
	ToolShape* shapes;
	int shapeCount;
} ToolScene;

typedef struct ToolDocument
{
	ToolScene* scenes;
	int sceneCount;
} ToolDocument;

/* Where and why loading failed. line is 0 when unknown (the file could not be read at all). */
typedef struct ToolError
{
	int line;
	char message[512];
} ToolError;

/* Reads and validates a scene file. On failure fills *error and leaves *document empty. The
 * document owns the hulls of its hull shapes: toolFreeDocument destroys them. */
bool toolLoadDocument(const char* path, ToolDocument* document, ToolError* error);
void toolFreeDocument(ToolDocument* document);

/* Shapes apart by up to this much (world units) still get a contact row: the speculative
 * distance passed to cd2Collide. */
#define TOOL_CONTACT_SPECULATIVE_DISTANCE 0.1

/* The answer for one pair of shapes (indices into the scene's shapes, a < b). Points are stored
 * with three coordinates; z is 0 in 2D scenes. */
typedef struct ToolPairResult
{
	int a, b;
	bool overlap;
	double distance;
	double pointA[3];
	double pointB[3];
	/* 2D pairs of library shapes only: the contact manifold (cd2Collide with
	 * TOOL_CONTACT_SPECULATIVE_DISTANCE); hasContact is false when it has no points. */
	bool hasContact;
	int contactCount;
	double contactNormal[2];
	double contactPoints[2][2];
	double deepestSeparation;
} ToolPairResult;

typedef struct ToolSceneResult
{
	const ToolScene* scene;
	ToolPairResult* pairs;
	int pairCount;
	int overlapCount;
} ToolSceneResult;

/* Runs every pairwise overlap test and closest-point query of a scene. false when out of memory. */
bool toolQueryScene(const ToolScene* scene, ToolSceneResult* result);
void toolFreeSceneResult(ToolSceneResult* result);

/* One pair (shapes i < j of the scene). */
void toolQueryPair(const ToolScene* scene, int i, int j, ToolPairResult* pair);

/* The table of every pair and one summary line per scene. */
void toolPrintReport(FILE* out, const ToolSceneResult* results, int sceneCount);

/* The same report, streamed: each pair is computed and printed at once (the columns take the
 * widths of the longest names and of the widest numbers the format can print, so no pass over
 * the results is needed), keeping only the 2D contacts for their table at the end. With
 * `progress`, a line on stderr counts the pairs of each large scene. false when out of memory. */
bool toolStreamReport(FILE* out, const ToolDocument* document, bool progress);

/* Whether stderr is a terminal (progress lines go there only then). */
bool toolStderrIsTerminal(void);

/* Writes the picture; false (with errno set by stdio) when the file cannot be written. */
bool toolWriteSvg(const char* path, const ToolSceneResult* results, int sceneCount);

/* Formats a number for people: fixed point with up to 4 decimals, exponent form when very large
 * or very small, never "-0". Returns buffer. */
const char* toolFormatNumber(double value, char* buffer, size_t size);

#endif
