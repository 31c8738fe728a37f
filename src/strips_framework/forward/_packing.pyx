# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True
"""Ground states packed and unpacked, compiled: the reference is
:mod:`~strips_framework.forward.packing`. A state's digits are read and made in place
(``digits.h``), so packing costs one step per 30 facts (a word compared with zero) and
one per true fact, and unpacking one per digit (zeroed) and one per true fact; the
reference goes through a binary string and a byte string as long as the state.
:class:`HeldCounter` reads one digit per fact it counts (or, given a packing,
searches it once per fact). :func:`code_of` and :func:`patch` are the Zobrist code of a
packing and a stored change applied to one (runs of facts between the changes copied
whole)."""

from cpython.bytes cimport PyBytes_AS_STRING, PyBytes_FromStringAndSize
from array import array

from libc.stdint cimport uint32_t, uint64_t
from libc.string cimport memcpy

from strips_framework.forward.digits cimport (
    STRIPS_DIGIT_BITS,
    __builtin_ctz,
    __builtin_popcount,
    strips_digits,
    strips_fact_code,
    strips_first_at_or_after,
    strips_new_int,
)


def pack(state):
    """The numbers of the facts true in ``state``, ascending, as 4-byte integers."""
    if not isinstance(state, int):
        raise TypeError("a state is an int")
    cdef Py_ssize_t size, i, count = 0
    cdef uint32_t* digits = strips_digits(state, &size)
    if size < 0:
        raise ValueError("a state is a non-negative int")
    for i in range(size):
        if digits[i]:
            count += __builtin_popcount(digits[i])
    cdef bytes packed = PyBytes_FromStringAndSize(NULL, count * 4)
    cdef uint32_t* out = <uint32_t*> PyBytes_AS_STRING(packed)
    cdef uint32_t digit
    cdef Py_ssize_t at = 0
    for i in range(size):
        digit = digits[i]
        while digit:
            out[at] = <uint32_t> (i * STRIPS_DIGIT_BITS + __builtin_ctz(digit))
            at += 1
            digit &= digit - 1
    return packed


def unpack(bytes packed):
    """The state (bitset) whose true facts ``packed`` lists."""
    cdef Py_ssize_t count = len(packed) // 4, i, size, at
    if count == 0:
        return 0
    cdef const uint32_t* facts = <const uint32_t*> PyBytes_AS_STRING(packed)
    cdef uint32_t fact, top = 0
    for i in range(count):  # the highest fact, wherever it is: no write out of bounds
        if facts[i] > top:
            top = facts[i]
    state = strips_new_int(top // STRIPS_DIGIT_BITS + 1)
    cdef uint32_t* digits = strips_digits(state, &size)
    for i in range(count):
        fact = facts[i]
        at = fact // STRIPS_DIGIT_BITS
        digits[at] |= (<uint32_t> 1) << (fact - at * STRIPS_DIGIT_BITS)
    return state


def code_of(bytes packed):
    """The Zobrist code of the state packed as ``packed``: its facts' codes XORed."""
    cdef Py_ssize_t count = len(packed) // 4, i
    cdef const uint32_t* facts = <const uint32_t*> PyBytes_AS_STRING(packed)
    cdef uint64_t code = 0
    for i in range(count):
        code ^= strips_fact_code(facts[i])
    return code


def patch(bytes packed, bytes change):
    """The packing of the state packed as ``packed`` after ``change`` (the count of lost
    facts, the lost ones and the gained ones, each ascending): a merge."""
    cdef Py_ssize_t count = len(packed) // 4, size = len(change) // 4
    if size < 1:
        raise ValueError("a change starts with the count of facts lost")
    cdef const uint32_t* facts = <const uint32_t*> PyBytes_AS_STRING(packed)
    cdef const uint32_t* numbers = <const uint32_t*> PyBytes_AS_STRING(change)
    cdef Py_ssize_t lost = numbers[0]
    if lost > size - 1 or lost > count:
        raise ValueError("a change loses more facts than it lists or the state holds")
    cdef Py_ssize_t gained = size - 1 - lost
    cdef bytes made = PyBytes_FromStringAndSize(NULL, (count - lost + gained) * 4)
    cdef uint32_t* out = <uint32_t*> PyBytes_AS_STRING(made)
    cdef const uint32_t* cut = numbers + 1
    cdef const uint32_t* add = numbers + 1 + lost
    cdef Py_ssize_t read = 0, written = 0, c = 0, a = 0, at
    cdef uint32_t fact
    cdef bint adding
    while c < lost or a < gained:
        adding = c == lost or (a < gained and add[a] < cut[c])
        fact = add[a] if adding else cut[c]
        at = strips_first_at_or_after(facts, read, count, fact)
        if written + (at - read) + adding > count - lost + gained:
            raise ValueError("not a change of this state")
        memcpy(out + written, facts + read, (at - read) * sizeof(uint32_t))
        written += at - read
        read = at
        if adding:
            if read < count and facts[read] == fact:
                raise ValueError("a change gains a fact the state holds")
            out[written] = fact
            written += 1
            a += 1
        else:
            if read == count or facts[read] != fact:
                raise ValueError("a change loses a fact the state lacks")
            read += 1
            c += 1
    if written + (count - read) != count - lost + gained:
        raise ValueError("not a change of this state")
    memcpy(out + written, facts + read, (count - read) * sizeof(uint32_t))
    return made


cdef class HeldCounter:
    """Called with a state: how many of the facts it was made with hold in it."""

    cdef int[::1] facts
    cdef Py_ssize_t count

    def __cinit__(self, facts):
        self.count = len(facts)
        self.facts = array("i", facts or [0])

    def __reduce__(self):
        return HeldCounter, ([self.facts[i] for i in range(self.count)],)

    def __call__(self, state):
        if isinstance(state, bytes):
            return self._in_packing(state)
        if not isinstance(state, int):
            raise TypeError("a state is an int or its packing")
        cdef Py_ssize_t size, at, i, count = 0
        cdef const uint32_t* digits = strips_digits(state, &size)
        if size < 0:
            raise ValueError("a state is a non-negative int")
        cdef int fact
        for i in range(self.count):
            fact = self.facts[i]
            at = fact // STRIPS_DIGIT_BITS
            if at < size and (digits[at] >> (fact - at * STRIPS_DIGIT_BITS)) & 1:
                count += 1
        return count

    cdef Py_ssize_t _in_packing(self, bytes packed):
        """The count over a packing: a binary search per fact."""
        cdef const uint32_t* facts = <const uint32_t*> PyBytes_AS_STRING(packed)
        cdef Py_ssize_t length = len(packed) // 4, i, low, count = 0
        cdef uint32_t fact
        for i in range(self.count):
            fact = <uint32_t> self.facts[i]
            low = strips_first_at_or_after(facts, 0, length, fact)
            if low < length and facts[low] == fact:
                count += 1
        return count
