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
#endif
