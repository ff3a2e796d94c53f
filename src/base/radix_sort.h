/* collide: a reusable sort of 64-bit keys (internal, not installed). The broadphase sorts its
 * pair keys and its proxy order with it; any module that orders ids by a packed key (the
 * world's islands, contact lists ...) can use it the same way.
 *
 *   uint64_t* sorted = cdRadixSortKeys(keys, scratch, count);
 *
 * It is an LSD radix sort over the bits the keys use (11 bits per pass, passes whose digit all
 * keys share are skipped), and an insertion sort below 48 keys. It allocates nothing: `scratch`
 * holds `count` keys, and the result lands in either buffer. */
#ifndef COLLIDE_RADIX_SORT_H
#define COLLIDE_RADIX_SORT_H

#include <stdint.h>

/* Sorts `count` keys ascending. `scratch` holds `count` keys. Returns the buffer (`keys` or
 * `scratch`) that holds the result. */
uint64_t* cdRadixSortKeys(uint64_t* keys, uint64_t* scratch, int count);

/* The same, ordering by the bits from `lowestBit` up only (keys equal there keep their order;
 * below the radix-sort size the whole key is compared). */
uint64_t* cdRadixSortKeysFrom(uint64_t* keys, uint64_t* scratch, int count, int lowestBit);

#endif
