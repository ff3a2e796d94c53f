/* collide: bump arena for per-step scratch memory. */
#include "container.h"

void* cdArena_AllocUncleared(cdArena* arena, size_t size)
{
	if (size == 0)
	{
		return NULL;
	}
	size = (size + 31u) & ~(size_t)31u;
	void* memory;
	if (arena->used + size <= arena->capacity)
	{
		memory = arena->base + arena->used;
	}
	else
	{
		if (!cdArrayReserve((void**)&arena->overflow, &arena->overflowCapacity, arena->overflowCount + 1,
							sizeof(void*)))
		{
			return NULL;
		}
		memory = cdAlloc(size);
		if (memory == NULL)
		{
			return NULL;
		}
		arena->overflow[arena->overflowCount++] = memory;
	}
	arena->used += size;
	if (arena->used > arena->peak)
	{
		arena->peak = arena->used;
	}
	return memory;
}

void* cdArena_Alloc(cdArena* arena, size_t size)
{
	void* memory = cdArena_AllocUncleared(arena, size);
	if (memory != NULL)
	{
		memset(memory, 0, (size + 31u) & ~(size_t)31u);
	}
	return memory;
}

void cdArena_Reset(cdArena* arena)
{
	for (int i = 0; i < arena->overflowCount; ++i)
	{
		cdFree(arena->overflow[i]);
	}
	if (arena->overflowCount > 0)
	{
		size_t capacity = arena->peak + arena->peak / 2;
		char* base = (char*)cdAlloc(capacity);
		if (base != NULL)
		{
			cdFree(arena->base);
			arena->base = base;
			arena->capacity = capacity;
		}
	}
	arena->overflowCount = 0;
	arena->used = 0;
	arena->peak = 0;
}

void cdArena_Destroy(cdArena* arena)
{
	cdArena_Reset(arena);
	cdFree(arena->base);
	cdFree(arena->overflow);
	memset(arena, 0, sizeof(*arena));
}
