# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True
"""Successor generation compiled: which operators apply in a state.

The reference is :class:`~strips_framework.forward.successors.SuccessorGenerator`; this
class takes its layout (the operators filed under their key facts, the unkeyed ones) and
lays it out as C arrays, so that a state's applicable operators come out in the same
order: the unkeyed operators, then by key fact, then in bucket order. Search expansions
are therefore the same whichever implementation runs (``tests/search_forward`` compares
them operator list by operator list and search by search).

A state is a Python int; it is turned into bytes once per call and its set bits are
walked byte by byte, so the work is one step per true fact plus one bit test per
precondition of the operators filed under true facts.
"""

from array import array


cdef class SuccessorGenerator:
    """The applicable operators of a state, from the reference generator's layout."""

    cdef int num_bytes, num_unkeyed
    # Per fact: its bucket's entries, bucket_start[fact]..bucket_start[fact + 1] (the
    # unkeyed entries come first, before bucket_start[0]). Per entry: the operator and
    # its positive and negative preconditions (compressed rows).
    cdef int[::1] bucket_start, entry_op, pre_start, pre, neg_start, neg
    cdef readonly object keep, add, effects

    def __cinit__(self, reference, task):
        operators = task.operators
        self.num_bytes = (len(task.facts) + 7) // 8
        entries = list(reference.unkeyed)
        self.num_unkeyed = len(entries)
        starts = [len(entries)]
        buckets = reference.buckets
        for fact in range(len(task.facts)):
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
        self.keep, self.add, self.effects = reference.keep, reference.add, reference.effects

    cdef inline bint _applies(self, int entry, const unsigned char* data):
        cdef int i, fact
        for i in range(self.pre_start[entry], self.pre_start[entry + 1]):
            fact = self.pre[i]
            if not (data[fact >> 3] >> (fact & 7)) & 1:
                return False
        for i in range(self.neg_start[entry], self.neg_start[entry + 1]):
            fact = self.neg[i]
            if (data[fact >> 3] >> (fact & 7)) & 1:
                return False
        return True

    def applicable(self, state):
        """The numbers of the operators applicable in ``state``, in the reference's order."""
        cdef bytes packed = state.to_bytes(self.num_bytes, "little")
        cdef const unsigned char* data = packed
        cdef list found = []
        cdef int entry, i, bit, fact
        cdef unsigned char byte
        for entry in range(self.num_unkeyed):
            if self._applies(entry, data):
                found.append(self.entry_op[entry])
        for i in range(self.num_bytes):
            byte = data[i]
            while byte:
                bit = 0
                while not (byte >> bit) & 1:
                    bit += 1
                byte &= byte - 1
                fact = i * 8 + bit
                for entry in range(self.bucket_start[fact], self.bucket_start[fact + 1]):
                    if self._applies(entry, data):
                        found.append(self.entry_op[entry])
        return found
