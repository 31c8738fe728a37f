# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True
"""Successor generation compiled: which operators apply in a state.

The reference is :class:`~strips_framework.forward.successors.SuccessorGenerator`; this
class takes its layout (the operators filed under their key facts, the unkeyed ones) and
lays it out as C arrays, so that a state's applicable operators come out in the same
order: the unkeyed operators, then by key fact, then in bucket order. Search expansions
are therefore the same whichever implementation runs (``tests/search_forward`` compares
them operator list by operator list and search by search).

A state is a Python int, read in place: its 30-bit digits are walked, zero digits
skipped, and a precondition is one digit's bit. Turning the int into bytes first (as
this module did) cost a copy and a walk of every byte, a tenth of a millisecond per
state at a million facts (blocks with 1,000 blocks) however few facts hold; now a state
costs one step per 30 facts for the walk (a word compared with zero) plus one step per
true fact and one bit test per precondition of the operators filed under true facts.
The digits are read as ``digits.h`` says.

A successor (:meth:`SuccessorGenerator.apply`, for operators without conditional
effects) is made the same way: the state's digits copied, the operator's deletes
cleared and its adds set, one bit each, instead of three operations with masks as long
as the state.
"""

from array import array

from libc.stdint cimport uint32_t
from libc.string cimport memcpy

from strips_framework.forward.digits cimport (
    STRIPS_DIGIT_BITS,
    __builtin_ctz,
    strips_digits,
    strips_new_int,
    strips_set_size,
)


cdef class SuccessorGenerator:
    """The applicable operators of a state, from the reference generator's layout."""

    cdef int num_facts, num_digits, num_unkeyed
    # Per fact: its bucket's entries, bucket_start[fact]..bucket_start[fact + 1] (the
    # unkeyed entries come first, before bucket_start[0]). Per entry: the operator and
    # its positive and negative preconditions (compressed rows).
    cdef int[::1] bucket_start, entry_op, pre_start, pre, neg_start, neg
    # Per operator number: its unconditional adds and deletes (compressed rows).
    cdef int[::1] add_start, adds, delete_start, deletes
    cdef readonly object delete, add, effects

    def __cinit__(self, reference, task):
        operators = task.operators
        self.num_facts = len(task.facts)
        # A state's bits beyond the facts (up to its top digit's end) file no operator.
        self.num_digits = (self.num_facts + STRIPS_DIGIT_BITS - 1) // STRIPS_DIGIT_BITS
        entries = list(reference.unkeyed)
        self.num_unkeyed = len(entries)
        starts = [len(entries)]
        buckets = reference.buckets
        for fact in range(self.num_digits * STRIPS_DIGIT_BITS):
            entries.extend(buckets.get(fact, ()))
            starts.append(len(entries))
        pre_starts, pre, neg_starts, neg = [0], [], [0], []
        for index in entries:
            pre.extend(operators[index].pre)
            pre_starts.append(len(pre))
            neg.extend(operators[index].pre_neg)
            neg_starts.append(len(neg))
        self.bucket_start, self.entry_op = array("i", starts), array("i", entries or [0])
        self.pre_start, self.pre = array("i", pre_starts), array("i", pre or [0])
        self.neg_start, self.neg = array("i", neg_starts), array("i", neg or [0])
        add_starts, adds, delete_starts, deletes = [0], [], [0], []
        for op in operators:
            adds.extend(op.add)
            add_starts.append(len(adds))
            deletes.extend(op.delete)
            delete_starts.append(len(deletes))
        self.add_start, self.adds = array("i", add_starts), array("i", adds or [0])
        self.delete_start, self.deletes = array("i", delete_starts), array("i", deletes or [0])
        self.delete, self.add, self.effects = reference.delete, reference.add, reference.effects

    cdef inline bint _applies(self, int entry, const uint32_t* digits, Py_ssize_t size):
        cdef int i
        for i in range(self.pre_start[entry], self.pre_start[entry + 1]):
            if not _holds(digits, size, self.pre[i]):
                return False
        for i in range(self.neg_start[entry], self.neg_start[entry + 1]):
            if _holds(digits, size, self.neg[i]):
                return False
        return True

    def applicable(self, state):
        """The numbers of the operators applicable in ``state``, in the reference's order."""
        if not isinstance(state, int):
            raise TypeError("a state is an int")
        cdef Py_ssize_t size, i
        cdef const uint32_t* digits = strips_digits(state, &size)
        if size < 0 or size > self.num_digits:
            raise ValueError(f"not a state of {self.num_facts} facts")
        cdef list found = []
        cdef int entry, fact
        cdef uint32_t digit
        for entry in range(self.num_unkeyed):
            if self._applies(entry, digits, size):
                found.append(self.entry_op[entry])
        for i in range(size):
            digit = digits[i]
            while digit:
                fact = i * STRIPS_DIGIT_BITS + __builtin_ctz(digit)
                digit &= digit - 1
                for entry in range(self.bucket_start[fact], self.bucket_start[fact + 1]):
                    if self._applies(entry, digits, size):
                        found.append(self.entry_op[entry])
        return found

    def apply(self, state, int operator):
        """The state ``operator`` makes of ``state`` without its conditional effects
        and axioms: the deletes cleared, then the adds set."""
        if not isinstance(state, int):
            raise TypeError("a state is an int")
        cdef Py_ssize_t size, top, i, at
        cdef const uint32_t* digits = strips_digits(state, &size)
        if size < 0 or size > self.num_digits:
            raise ValueError(f"not a state of {self.num_facts} facts")
        if operator < 0 or operator >= len(self.add_start) - 1:
            raise IndexError(f"no operator {operator}")
        cdef int fact, first = self.add_start[operator], last = self.add_start[operator + 1]
        top = size
        for i in range(first, last):
            at = self.adds[i] // STRIPS_DIGIT_BITS + 1
            if at > top:
                top = at
        child = strips_new_int(top)
        cdef uint32_t* made = strips_digits(child, &at)
        memcpy(made, digits, size * sizeof(uint32_t))
        for i in range(self.delete_start[operator], self.delete_start[operator + 1]):
            fact = self.deletes[i]
            at = fact // STRIPS_DIGIT_BITS
            if at < size:
                made[at] &= ~((<uint32_t> 1) << (fact - at * STRIPS_DIGIT_BITS))
        for i in range(first, last):
            fact = self.adds[i]
            at = fact // STRIPS_DIGIT_BITS
            made[at] |= (<uint32_t> 1) << (fact - at * STRIPS_DIGIT_BITS)
        while top > 0 and made[top - 1] == 0:
            top -= 1
        strips_set_size(child, top)
        return child


cdef inline bint _holds(const uint32_t* digits, Py_ssize_t size, int fact):
    """Whether bit ``fact`` of the int with these digits is set."""
    cdef Py_ssize_t at = fact // STRIPS_DIGIT_BITS
    return at < size and (digits[at] >> (fact - at * STRIPS_DIGIT_BITS)) & 1
