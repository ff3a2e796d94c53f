/* collide: growable array storage for the containers of container.h. */
#include "container.h"

bool cdArrayReserve(void** data, int* capacity, int needed, size_t elementSize)
{
	if (needed <= *capacity)
	{
		return true;
	}
	if (needed < 0 || (size_t)needed > ((size_t)1 << 30) / (elementSize > 0 ? elementSize : 1) * 4)
	{
		return false;
	}
	int newCapacity = *capacity < 8 ? 8 : *capacity;
	while (newCapacity < needed)
	{
		newCapacity += newCapacity / 2;
	}
	char* memory = (char*)cdAlloc((size_t)newCapacity * elementSize);
	if (memory == NULL)
	{
		return false;
	}
	if (*capacity > 0)
	{
		memcpy(memory, *data, (size_t)*capacity * elementSize);
	}
	memset(memory + (size_t)*capacity * elementSize, 0, (size_t)(newCapacity - *capacity) * elementSize);
	cdFree(*data);
	*data = memory;
	*capacity = newCapacity;
	return true;
}
