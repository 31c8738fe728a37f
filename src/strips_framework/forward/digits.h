/* A non-negative Python int's digits read in place, for the compiled modules that take
   ground states (int bitsets): CPython stores an int as 30-bit digits, lowest first,
   and their number; the layout moved in 3.12. Another digit size fails to compile, and
   the pure-Python references run instead. */
#ifndef STRIPS_DIGITS_H
#define STRIPS_DIGITS_H
#include <Python.h>
#include <stdint.h>

#if PyLong_SHIFT != 30
#error "strips_framework.forward reads 30-bit int digits"
#endif

#define STRIPS_DIGIT_BITS 30

/* The digits of the int x and, in *size, their number: -1 when x is negative (no
   state). */
static inline uint32_t* strips_digits(PyObject* x, Py_ssize_t* size) {
#if PY_VERSION_HEX >= 0x030C0000
    uintptr_t tag = ((PyLongObject*) x)->long_value.lv_tag;
    *size = (tag & 3) == 2 ? -1 : (Py_ssize_t) (tag >> 3);
    return (uint32_t*) ((PyLongObject*) x)->long_value.ob_digit;
#else
    *size = Py_SIZE(x) < 0 ? -1 : Py_SIZE(x);
    return (uint32_t*) ((PyLongObject*) x)->ob_digit;
#endif
}

/* Make x, made by strips_new_int, `size` digits long (its top digit non-zero, or
   size 0: the int 0). */
static inline void strips_set_size(PyObject* x, Py_ssize_t size) {
#if PY_VERSION_HEX >= 0x030C0000
    ((PyLongObject*) x)->long_value.lv_tag = ((uintptr_t) size << 3) | (size == 0 ? 1 : 0);
#else
    Py_SET_SIZE(x, size);
#endif
}

/* A new int of `size` digits, all zero (the caller sets them; the top one must end
   up non-zero). */
static inline PyObject* strips_new_int(Py_ssize_t size) {
    Py_ssize_t ignored;
    PyObject* x = (PyObject*) _PyLong_New(size);
    if (x != NULL) {
        memset(strips_digits(x, &ignored), 0, size * sizeof(uint32_t));
    }
    return x;
}
#endif
