# The declarations of digits.h and packed.h (see there) for the compiled modules that
# read states.
from libc.stdint cimport uint32_t, uint64_t


cdef extern from "digits.h":
    const int STRIPS_DIGIT_BITS
    uint32_t* strips_digits(object x, Py_ssize_t* size)
    object strips_new_int(Py_ssize_t size)
    void strips_set_size(object x, Py_ssize_t size)


cdef extern from *:
    # The lowest set bit's place and the set bits' count of a non-zero digit (GCC, Clang).
    int __builtin_ctz(unsigned int x)
    int __builtin_popcount(unsigned int x)


cdef extern from "packed.h":
    # See packed.h: a binary search in a packing's facts.
    Py_ssize_t strips_first_at_or_after(const uint32_t* facts, Py_ssize_t low, Py_ssize_t high, uint32_t fact)
    # See packed.h: a fact's Zobrist code.
    uint64_t strips_fact_code(uint32_t fact)
