# The declarations of digits.h (see there) for the compiled modules that read states.
from libc.stdint cimport uint32_t


cdef extern from "digits.h":
    const int STRIPS_DIGIT_BITS
    uint32_t* strips_digits(object x, Py_ssize_t* size)
    object strips_new_int(Py_ssize_t size)
