/* collide: the command-line tool.
 *
 *   collide query FILE.json [--svg OUT.svg]
 *   collide broad [options]      (broad.c: the broadphase benchmark scene)
 *   collide run SCENE.json [...] (tools/run: steps a physics scene, docs/SCENES.md)
 *
 * Reads a scene file (format: scene_load.c, examples/README.md), runs the overlap test and the
 * closest-point query of every pair of shapes within each scene, prints a table, and optionally
 * draws the scenes into an SVG picture. Exit codes: 0 success, 2 any error (usage, unreadable or
 * invalid file, unwritable picture). Errors go to stderr as "FILE:LINE: reason". */
#include "broad.h"
#include "run.h"
#include "scene.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TOOL_EXIT_ERROR 2

static const char* const s_usage =
	"usage: collide query FILE.json [--svg OUT.svg]\n"
	"       collide run SCENE.json [--steps N] [--svg OUT.svg] [--png DIR] [--csv OUT.csv] ...\n"
	"       collide broad [--dim 2|3] [--n N] [--structure NAME|all] [--scene moving|mix]\n"
	"                     [--frames K] [--warmup W]\n"
	"       collide --help | --version\n";

static void printHelp(void)
{
	fputs(s_usage, stdout);
	fputs("\n"
		  "Runs every pairwise overlap test and closest-point query of the shapes in each scene of\n"
		  "FILE.json and prints one row per pair: scene, the two shapes, whether they overlap\n"
		  "(touching counts), their distance and the closest point on each.\n"
		  "\n"
		  "  --svg OUT.svg   also draw each scene (3D scenes in an oblique projection), with\n"
		  "                  overlapping shapes filled and the closest points of separated pairs\n"
		  "                  joined by a thin line\n"
		  "  --help          show this help\n"
		  "  --version       show the version of the tool and of the collide library\n"
		  "\n"
		  "`collide run` steps a physics scene file (docs/SCENES.md) and writes frames and body\n"
		  "states (`collide run --help`).\n"
		  "\n"
		  "`collide broad` runs the broadphase benchmark scene on the chosen structures and prints\n"
		  "their figures (`collide broad --help`).\n"
		  "\n"
		  "The file format is described in examples/README.md. Exit status: 0 on success, 2 on a\n"
		  "usage error or an invalid file (reported as FILE:LINE: reason).\n",
		  stdout);
}

static int usageError(const char* reason)
{
	fprintf(stderr, "collide: %s\n%s", reason, s_usage);
	return TOOL_EXIT_ERROR;
}

static int runQuery(const char* path, const char* svgPath)
{
	ToolDocument document;
	ToolError error;
	if (!toolLoadDocument(path, &document, &error))
	{
		if (error.line > 0)
		{
			fprintf(stderr, "%s:%d: %s\n", path, error.line, error.message);
		}
		else
		{
			fprintf(stderr, "%s: %s\n", path, error.message);
		}
		return TOOL_EXIT_ERROR;
	}
	if (svgPath == NULL)
	{
		/* The report alone: streamed, each pair printed as soon as it is computed. */
		int status = toolStreamReport(stdout, &document, toolStderrIsTerminal()) ? 0 : TOOL_EXIT_ERROR;
		if (status != 0)
		{
			fprintf(stderr, "collide: out of memory\n");
		}
		toolFreeDocument(&document);
		if (fflush(stdout) != 0 && status == 0)
		{
			fprintf(stderr, "collide: cannot write the report: %s\n", strerror(errno));
			status = TOOL_EXIT_ERROR;
		}
		return status;
	}
	/* With the picture, which draws every pair's answer: all results kept. */
	ToolSceneResult* results = calloc((size_t)document.sceneCount, sizeof(ToolSceneResult));
	bool ok = results != NULL;
	for (int s = 0; ok && s < document.sceneCount; ++s)
	{
		ok = toolQueryScene(&document.scenes[s], &results[s]);
	}
	int status = 0;
	if (!ok)
	{
		fprintf(stderr, "collide: out of memory\n");
		status = TOOL_EXIT_ERROR;
	}
	else
	{
		toolPrintReport(stdout, results, document.sceneCount);
		if (svgPath != NULL)
		{
			if (toolWriteSvg(svgPath, results, document.sceneCount))
			{
				printf("\npicture: %s\n", svgPath);
			}
			else
			{
				fprintf(stderr, "%s: cannot write: %s\n", svgPath, strerror(errno));
				status = TOOL_EXIT_ERROR;
			}
		}
	}
	for (int s = 0; results != NULL && s < document.sceneCount; ++s)
	{
		toolFreeSceneResult(&results[s]);
	}
	free(results);
	toolFreeDocument(&document);
	if (fflush(stdout) != 0 && status == 0)
	{
		fprintf(stderr, "collide: cannot write the report: %s\n", strerror(errno));
		status = TOOL_EXIT_ERROR;
	}
	return status;
}

int main(int argc, char** argv)
{
	if (argc < 2)
	{
		return usageError("missing command");
	}
	const char* command = argv[1];
	if (strcmp(command, "--help") == 0 || strcmp(command, "-h") == 0 || strcmp(command, "help") == 0)
	{
		printHelp();
		return 0;
	}
	if (strcmp(command, "--version") == 0)
	{
		cdVersion version = cdGetVersion();
		printf("collide %d.%d.%d (library %d.%d.%d, %s)\n", CD_VERSION_MAJOR, CD_VERSION_MINOR,
			   CD_VERSION_PATCH, version.major, version.minor, version.patch,
			   cdGetRealIsDouble() ? "double" : "float");
		return 0;
	}
	if (strcmp(command, "broad") == 0)
	{
		return toolBroadMain(argc - 1, argv + 1);
	}
	if (strcmp(command, "run") == 0)
	{
		return toolRunMain(argc - 1, argv + 1);
	}
	if (strcmp(command, "query") != 0)
	{
		char reason[128];
		snprintf(reason, sizeof reason, "unknown command '%.64s'", command);
		return usageError(reason);
	}
	const char* path = NULL;
	const char* svgPath = NULL;
	bool optionsEnded = false;
	for (int i = 2; i < argc; ++i)
	{
		const char* arg = argv[i];
		if (!optionsEnded && (strcmp(arg, "--help") == 0 || strcmp(arg, "-h") == 0))
		{
			printHelp();
			return 0;
		}
		if (!optionsEnded && strcmp(arg, "--") == 0)
		{
			optionsEnded = true;
		}
		else if (!optionsEnded && strcmp(arg, "--svg") == 0)
		{
			if (i + 1 >= argc || argv[i + 1][0] == 0)
			{
				return usageError("--svg needs a file name");
			}
			svgPath = argv[++i];
		}
		else if (!optionsEnded && strncmp(arg, "--svg=", 6) == 0)
		{
			if (arg[6] == 0)
			{
				return usageError("--svg needs a file name");
			}
			svgPath = arg + 6;
		}
		else if (!optionsEnded && arg[0] == '-' && arg[1] != 0)
		{
			char reason[128];
			snprintf(reason, sizeof reason, "unknown option '%.64s'", arg);
			return usageError(reason);
		}
		else if (path == NULL)
		{
			path = arg;
		}
		else
		{
			char reason[128];
			snprintf(reason, sizeof reason, "unexpected argument '%.64s'", arg);
			return usageError(reason);
		}
	}
	if (path == NULL)
	{
		return usageError("query needs a scene file");
	}
	return runQuery(path, svgPath);
}
