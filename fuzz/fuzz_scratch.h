/* The scratch file of the fuzz targets whose code under test reads from a path only
 * (fuzz_scene.c, fuzz_world_scene.c): each input is written to it before the load. Header-only:
 * each target is one translation unit. */
#ifndef COLLIDE_FUZZ_SCRATCH_H
#define COLLIDE_FUZZ_SCRATCH_H

#define _POSIX_C_SOURCE 200809L /* mkstemp */

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

static char s_scratchPath[256];

static void RemoveScratchFile(void)
{
	if (s_scratchPath[0] != 0)
	{
		remove(s_scratchPath);
	}
}

/* Creates the scratch file once, in $TMPDIR (default /tmp), named `name`_XXXXXX; removed at exit. */
static bool CreateScratchFile(const char* name)
{
	if (s_scratchPath[0] != 0)
	{
		return true;
	}
	const char* dir = getenv("TMPDIR");
	snprintf(s_scratchPath, sizeof s_scratchPath, "%s/%s_XXXXXX", dir != NULL && dir[0] != 0 ? dir : "/tmp",
			 name);
	int fd = mkstemp(s_scratchPath);
	if (fd < 0)
	{
		s_scratchPath[0] = 0;
		return false;
	}
	close(fd);
	atexit(RemoveScratchFile);
	return true;
}

/* Writes the input to the scratch file and returns its path; aborts, naming the target, when it
 * cannot. */
static const char* WriteScratchFile(const char* name, const uint8_t* data, size_t size)
{
	bool ok = CreateScratchFile(name);
	FILE* file = ok ? fopen(s_scratchPath, "wb") : NULL;
	if (file != NULL)
	{
		ok = fwrite(data, 1, size, file) == size;
		ok = fclose(file) == 0 && ok;
	}
	if (file == NULL || !ok)
	{
		fprintf(stderr, "%s: cannot write the scratch file %s\n", name, s_scratchPath);
		abort();
	}
	return s_scratchPath;
}

#endif
