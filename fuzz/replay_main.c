/* Replays fuzz inputs through a fuzz target's LLVMFuzzerTestOneInput without libFuzzer, so that
 * any compiler can run the corpora as regression tests (CTest: fuzz_replay_<target>, every check
 * strict). Arguments: files, or folders whose files are replayed in name order. A failed check
 * aborts (fuzz_common.h); the input being replayed is then named on stderr. Exit status 0 when
 * every input passed, 1 when a file could not be read or no input was found. */
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#if defined(_WIN32)
#error "replay_main.c reads folders with POSIX dirent: not available on Windows"
#endif
#include <dirent.h>
#include <unistd.h>

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

static char g_current[4096];

static void OnAbort(int signal)
{
	static const char prefix[] = "fuzz replay: the failing input is ";
	(void)signal;
	(void)!write(2, prefix, sizeof(prefix) - 1);
	(void)!write(2, g_current, strlen(g_current));
	(void)!write(2, "\n", 1);
}

static int ReplayFile(const char* path)
{
	FILE* file = fopen(path, "rb");
	if (file == NULL)
	{
		fprintf(stderr, "fuzz replay: cannot open %s\n", path);
		return -1;
	}
	size_t capacity = 4096, size = 0;
	uint8_t* data = (uint8_t*)malloc(capacity);
	size_t got;
	while (data != NULL && (got = fread(data + size, 1, capacity - size, file)) > 0)
	{
		size += got;
		if (size == capacity)
		{
			capacity *= 2;
			uint8_t* grown = (uint8_t*)realloc(data, capacity);
			if (grown == NULL)
			{
				free(data);
			}
			data = grown;
		}
	}
	fclose(file);
	if (data == NULL)
	{
		fprintf(stderr, "fuzz replay: out of memory reading %s\n", path);
		return -1;
	}
	snprintf(g_current, sizeof(g_current), "%s", path);
	LLVMFuzzerTestOneInput(data, size);
	free(data);
	return 1;
}

static int CompareNames(const void* a, const void* b)
{
	return strcmp(*(const char* const*)a, *(const char* const*)b);
}

/* Replays every regular file of the folder in name order; returns the count or -1. */
static int ReplayFolder(const char* folder)
{
	DIR* dir = opendir(folder);
	if (dir == NULL)
	{
		fprintf(stderr, "fuzz replay: cannot open the folder %s\n", folder);
		return -1;
	}
	char** names = NULL;
	int count = 0, capacity = 0;
	struct dirent* entry;
	while ((entry = readdir(dir)) != NULL)
	{
		if (entry->d_name[0] == '.')
		{
			continue;
		}
		if (count == capacity)
		{
			capacity = capacity ? 2 * capacity : 64;
			char** grown = (char**)realloc(names, (size_t)capacity * sizeof(char*));
			if (grown == NULL)
			{
				break;
			}
			names = grown;
		}
		size_t length = strlen(folder) + strlen(entry->d_name) + 2;
		names[count] = (char*)malloc(length);
		if (names[count] == NULL)
		{
			break;
		}
		snprintf(names[count], length, "%s/%s", folder, entry->d_name);
		++count;
	}
	closedir(dir);
	qsort(names, (size_t)count, sizeof(char*), CompareNames);
	int replayed = 0;
	for (int i = 0; i < count; ++i)
	{
		struct stat info;
		if (stat(names[i], &info) == 0 && S_ISREG(info.st_mode))
		{
			int r = ReplayFile(names[i]);
			replayed = (r < 0 || replayed < 0) ? -1 : replayed + r;
		}
		free(names[i]);
	}
	free(names);
	return replayed;
}

int main(int argc, char** argv)
{
	signal(SIGABRT, OnAbort);
	int total = 0;
	for (int i = 1; i < argc; ++i)
	{
		struct stat info;
		int r = -1;
		if (stat(argv[i], &info) == 0)
		{
			r = S_ISDIR(info.st_mode) ? ReplayFolder(argv[i]) : ReplayFile(argv[i]);
		}
		else
		{
			fprintf(stderr, "fuzz replay: no such file or folder %s\n", argv[i]);
		}
		if (r < 0)
		{
			return 1;
		}
		total += r;
	}
	printf("fuzz replay: %d inputs passed\n", total);
	return total > 0 ? 0 : 1;
}
