/* collide: base layer implementation: result strings, version, assert and allocator hooks,
 * length units. The only global state in the library lives here, and it is all hooks. */
#include "collide/base.h"

#include <stdio.h>
#include <stdlib.h>

const char* cdGetResultString(cdResult result)
{
	switch (result)
	{
		case CD_OK:
			return "ok";
		case CD_ERROR_INVALID_ARGUMENT:
			return "invalid argument";
		case CD_ERROR_NOT_FINITE:
			return "NaN or infinite value";
		case CD_ERROR_NEGATIVE_SIZE:
			return "negative size or radius";
		case CD_ERROR_DEGENERATE:
			return "degenerate shape (too few distinct points, collinear or zero area)";
		case CD_ERROR_TOO_MANY_POINTS:
			return "too many points";
		case CD_ERROR_NOT_NORMALIZED:
			return "rotation or normal is not unit length";
		case CD_ERROR_OUT_OF_MEMORY:
			return "out of memory";
		case CD_ERROR_PARSE:
			return "malformed input";
		case CD_ERROR_OUT_OF_RANGE:
			return "coordinate beyond the documented range";
		case CD_RESULT_COUNT:
			break;
	}
	return "unknown result code";
}

cdVersion cdGetVersion(void)
{
	cdVersion version = {CD_VERSION_MAJOR, CD_VERSION_MINOR, CD_VERSION_PATCH};
	return version;
}

int cdGetRealIsDouble(void)
{
	return CD_DOUBLE;
}

/* ---- assert ---------------------------------------------------------------------------------- */

static bool cdDefaultAssertFcn(const char* condition, const char* fileName, int lineNumber)
{
	fprintf(stderr, "collide: assertion failed: %s, %s:%d\n", condition, fileName, lineNumber);
	return true;
}

static cdAssertFcn* s_assertFcn = cdDefaultAssertFcn;

void cdSetAssertFcn(cdAssertFcn* assertFcn)
{
	s_assertFcn = assertFcn != NULL ? assertFcn : cdDefaultAssertFcn;
}

bool cdInternalAssert(const char* condition, const char* fileName, int lineNumber)
{
	return s_assertFcn(condition, fileName, lineNumber);
}

/* ---- allocator ------------------------------------------------------------------------------- */

enum
{
	CD_ALLOC_ALIGNMENT = 32
};

/* The default allocator over-allocates and stores the offset back to malloc's pointer in the
 * byte before the aligned block, so that it needs nothing beyond C11's malloc/free (MSVC has no
 * aligned_alloc, and aligned_alloc demands size be a multiple of the alignment). */
static void* cdDefaultAlloc(size_t size, size_t alignment)
{
	if (alignment < 1 || alignment > 128 || size > SIZE_MAX - alignment)
	{
		return NULL;
	}
	unsigned char* raw = (unsigned char*)malloc(size + alignment);
	if (raw == NULL)
	{
		return NULL;
	}
	size_t offset = alignment - ((uintptr_t)raw & (alignment - 1));
	unsigned char* aligned = raw + offset;
	aligned[-1] = (unsigned char)offset;
	return aligned;
}

static void cdDefaultFree(void* memory)
{
	unsigned char* aligned = (unsigned char*)memory;
	free(aligned - aligned[-1]);
}

static cdAllocFcn* s_allocFcn = cdDefaultAlloc;
static cdFreeFcn* s_freeFcn = cdDefaultFree;

void cdSetAllocator(cdAllocFcn* allocFcn, cdFreeFcn* freeFcn)
{
	if (allocFcn != NULL && freeFcn != NULL)
	{
		s_allocFcn = allocFcn;
		s_freeFcn = freeFcn;
	}
	else
	{
		s_allocFcn = cdDefaultAlloc;
		s_freeFcn = cdDefaultFree;
	}
}

void* cdAlloc(size_t size)
{
	if (size == 0)
	{
		return NULL;
	}
	return s_allocFcn(size, CD_ALLOC_ALIGNMENT);
}

void cdFree(void* memory)
{
	if (memory != NULL)
	{
		s_freeFcn(memory);
	}
}

/* ---- length units ---------------------------------------------------------------------------- */

static cdReal s_lengthUnitsPerMeter = CD_R(1.0);

void cdSetLengthUnitsPerMeter(cdReal lengthUnits)
{
	CD_ASSERT(cdIsValidReal(lengthUnits) && lengthUnits > CD_R(0.0));
	if (cdIsValidReal(lengthUnits) && lengthUnits > CD_R(0.0))
	{
		s_lengthUnitsPerMeter = lengthUnits;
	}
}

cdReal cdGetLengthUnitsPerMeter(void)
{
	return s_lengthUnitsPerMeter;
}
