/* A state's packing read in place, for the compiled modules that take packed states:
   the sorted numbers of its true facts, 4 bytes each (packing.py). */
#ifndef STRIPS_PACKED_H
#define STRIPS_PACKED_H
#include <stddef.h>
#include <stdint.h>

/* The first place in facts[low:high] (sorted) holding `fact` or more: high if none. */
static inline ptrdiff_t strips_first_at_or_after(
    const uint32_t* facts, ptrdiff_t low, ptrdiff_t high, uint32_t fact) {
    while (low < high) {
        ptrdiff_t middle = low + (high - low) / 2;
        if (facts[middle] < fact) {
            low = middle + 1;
        } else {
            high = middle;
        }
    }
    return low;
}

/* A fact's Zobrist code (packing.py's fact_code): splitmix64 of its number, the top bit
   dropped (63 bits). A function, not a table: no set-up as long as the task has facts. */
static inline uint64_t strips_fact_code(uint32_t fact) {
    uint64_t z = (uint64_t)fact + 0x9E3779B97F4A7C15ULL;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return (z ^ (z >> 31)) >> 1;
}
#endif
