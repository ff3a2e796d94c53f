/* libFuzzer target for the collide tool's scene loader (tools/collide/scene_load.c) and what the
 * tool does with a loaded file: every pairwise query, the report and the SVG picture (both
 * written to /dev/null). The loader reads from a path only, so each input is written to a
 * scratch file first.
 *
 * Checked, with aborts on violation: no crash or sanitizer report; a failed load leaves the
 * document empty and gives a NUL-terminated message with a line >= 0; a loaded document holds
 * only what the format allows (dimension 2 or 3, names within the limit, at most
 * TOOL_MAX_SCENES scenes and TOOL_MAX_SHAPES_PER_SCENE shapes each, finite points, shapes the
 * library's validator accepts, each hull shape with the hull the document owns); every pair's
 * answer is finite with a non-negative distance, and a 2D contact has 1 or 2 points, a unit
 * normal and finite separations. */
#include "fuzz_scratch.h"
#include "scene.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static FILE* s_null;

static void Fail(const char* what, int scene, int shape)
{
	fprintf(stderr, "fuzz_scene: %s (scene %d, shape %d)\n", what, scene, shape);
	fflush(stderr);
	abort();
}

static void CheckDocument(const ToolDocument* document)
{
	if (document->sceneCount < 0 || document->sceneCount > TOOL_MAX_SCENES ||
		(document->sceneCount > 0 && document->scenes == NULL))
	{
		Fail("bad scene count", document->sceneCount, -1);
	}
	for (int s = 0; s < document->sceneCount; ++s)
	{
		const ToolScene* scene = &document->scenes[s];
		if ((scene->dimension != 2 && scene->dimension != 3) || scene->shapeCount < 0 ||
			scene->shapeCount > TOOL_MAX_SHAPES_PER_SCENE ||
			memchr(scene->name, 0, sizeof scene->name) == NULL)
		{
			Fail("bad scene", s, -1);
		}
		for (int i = 0; i < scene->shapeCount; ++i)
		{
			const ToolShape* shape = &scene->shapes[i];
			if (memchr(shape->name, 0, sizeof shape->name) == NULL || shape->name[0] == 0)
			{
				Fail("bad shape name", s, i);
			}
			bool valid;
			if (shape->isPoint)
			{
				valid = scene->dimension == 2 ? cd2IsValidVec(shape->point2) : cd3IsValidVec(shape->point3);
			}
			else
			{
				valid =
					scene->dimension == 2 ? cd2IsValidShape(&shape->shape2) : cd3IsValidShape(&shape->shape3);
			}
			if (!valid)
			{
				Fail("the loader accepted a shape the library's validator rejects", s, i);
			}
			/* The document owns exactly the hulls its hull shapes use (freed with it: the
			 * sanitizer's leak check sees any that is not). */
			bool isHull = scene->dimension == 3 && !shape->isPoint && shape->shape3.type == CD3_SHAPE_HULL;
			if (isHull ? (shape->hull == NULL || shape->shape3.hull.hull != shape->hull)
					   : shape->hull != NULL)
			{
				Fail("a hull shape without its own hull, or a hull on another shape", s, i);
			}
		}
	}
}

static void CheckResult(const ToolSceneResult* result, int s)
{
	for (int k = 0; k < result->pairCount; ++k)
	{
		const ToolPairResult* pair = &result->pairs[k];
		bool finite = isfinite(pair->distance) && pair->distance >= 0.0;
		for (int j = 0; j < 3; ++j)
		{
			finite = finite && isfinite(pair->pointA[j]) && isfinite(pair->pointB[j]);
		}
		if (pair->hasContact)
		{
			double normalLength = hypot(pair->contactNormal[0], pair->contactNormal[1]);
			finite = finite && (pair->contactCount == 1 || pair->contactCount == 2) &&
					 fabs(normalLength - 1.0) < 1e-3 && isfinite(pair->deepestSeparation);
			for (int j = 0; j < pair->contactCount * 2; ++j)
			{
				finite = finite && isfinite(pair->contactPoints[j / 2][j % 2]);
			}
		}
		if (!finite)
		{
			fprintf(
				stderr,
				"fuzz_scene: pair %d-%d: distance %.9g, pointA (%.9g %.9g %.9g), pointB (%.9g %.9g %.9g)\n",
				pair->a, pair->b, pair->distance, pair->pointA[0], pair->pointA[1], pair->pointA[2],
				pair->pointB[0], pair->pointB[1], pair->pointB[2]);
			Fail("non-finite or negative answer", s, pair->a);
		}
	}
}

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	const char* path = WriteScratchFile("fuzz_scene", data, size);
	if (s_null == NULL && (s_null = fopen("/dev/null", "w")) == NULL)
	{
		fprintf(stderr, "fuzz_scene: cannot open /dev/null\n");
		abort();
	}
	ToolDocument document;
	ToolError error;
	memset(&error, 0x5a, sizeof error);
	if (!toolLoadDocument(path, &document, &error))
	{
		if (document.sceneCount != 0 || document.scenes != NULL)
		{
			Fail("a failed load left scenes behind", document.sceneCount, -1);
		}
		if (error.line < 0 || memchr(error.message, 0, sizeof error.message) == NULL || error.message[0] == 0)
		{
			Fail("a failed load without a message or with a negative line", 0, -1);
		}
		return 0;
	}
	CheckDocument(&document);
	ToolSceneResult* results = calloc((size_t)document.sceneCount + 1, sizeof(ToolSceneResult));
	if (results == NULL)
	{
		abort();
	}
	for (int s = 0; s < document.sceneCount; ++s)
	{
		if (!toolQueryScene(&document.scenes[s], &results[s]))
		{
			Fail("out of memory in toolQueryScene", s, -1);
		}
		CheckResult(&results[s], s);
	}
	toolPrintReport(s_null, results, document.sceneCount);
	if (!toolWriteSvg("/dev/null", results, document.sceneCount))
	{
		Fail("cannot write the picture to /dev/null", -1, -1);
	}
	for (int s = 0; s < document.sceneCount; ++s)
	{
		toolFreeSceneResult(&results[s]);
	}
	free(results);
	toolFreeDocument(&document);
	return 0;
}
