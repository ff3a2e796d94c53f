/* A real's bits as an unsigned integer of its width: tests such as "all +0" or "exactly 1" on
 * several reals combine into one integer test, without the flags of a float comparison per value
 * (a -0 fails a test for +0, which callers use only where the sign of a zero does not matter). */
#ifndef COLLIDE_BASE_REAL_BITS_H
#define COLLIDE_BASE_REAL_BITS_H

#include <collide/base.h>

#include <stdint.h>
#include <string.h>

#if CD_DOUBLE
typedef uint64_t cdRealBits;
#else
typedef uint32_t cdRealBits;
#endif

static inline cdRealBits cdGetRealBits(cdReal x)
{
	cdRealBits bits;
	memcpy(&bits, &x, sizeof bits);
	return bits;
}

#endif
