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

:meth:`SuccessorGenerator.next_applicable` takes a state's applicable operators one at
a time, from a position in that order, and takes the state as its packing too (the
sorted numbers of its true facts, :mod:`~strips_framework.forward.packing`): then it
walks the true facts listed there and tests a precondition by binary search, so it
costs what the state holds, not what the task has; :meth:`SuccessorGenerator.step_packed`
makes a successor's packing from its parent's by a merge with the operator's sorted
deletes and adds, and with it the change (the facts lost and gained) and the
successor's Zobrist code from its parent's.
"""

from array import array

from cpython.bytes cimport PyBytes_AS_STRING, PyBytes_FromStringAndSize
from libc.stdint cimport uint32_t, uint64_t
from libc.string cimport memcpy

from strips_framework.forward.digits cimport (
    STRIPS_DIGIT_BITS,
    __builtin_ctz,
    strips_digits,
    strips_fact_code,
    strips_first_at_or_after,
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
    # Per entry: its key fact (-1 for the unkeyed ones); per operator: its entry.
    cdef int[::1] entry_key, position
    cdef readonly tuple order
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
        self.order = tuple(entries)
        self.entry_key = array("i", [-1]) * max(len(entries), 1)
        self.position = array("i", [0]) * max(len(operators), 1)
        cdef Py_ssize_t entry, key
        for key in range(len(starts) - 1):
            for entry in range(self.bucket_start[key], self.bucket_start[key + 1]):
                self.entry_key[entry] = key
        for entry in range(len(entries)):
            self.position[self.entry_op[entry]] = entry
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
        for entry in range(len(operators)):  # each operator's sorted, for step_packed's merge
            _sort(self.adds, self.add_start[entry], self.add_start[entry + 1])
            _sort(self.deletes, self.delete_start[entry], self.delete_start[entry + 1])
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

    cdef inline bint _applies_packed(self, int entry, const uint32_t* facts, Py_ssize_t count):
        cdef int i
        for i in range(self.pre_start[entry], self.pre_start[entry + 1]):
            if not _listed(facts, count, self.pre[i]):
                return False
        for i in range(self.neg_start[entry], self.neg_start[entry + 1]):
            if _listed(facts, count, self.neg[i]):
                return False
        return True

    def next_applicable(self, state, Py_ssize_t position):
        """The position (in :attr:`order`) of the first operator applicable in ``state``
        (an int, or its packing as bytes) at ``position`` or after, or -1 if none."""
        if isinstance(state, bytes):
            return self._next_packed(state, position)
        if not isinstance(state, int):
            raise TypeError("a state is an int or its packing")
        cdef Py_ssize_t size, i, entries = len(self.order)
        cdef const uint32_t* digits = strips_digits(state, &size)
        if size < 0 or size > self.num_digits:
            raise ValueError(f"not a state of {self.num_facts} facts")
        if position < 0:
            position = 0
        while position < self.num_unkeyed:
            if self._applies(position, digits, size):
                return position
            position += 1
        if position >= entries:
            return -1
        cdef int fact = self.entry_key[position], entry
        if _holds(digits, size, fact):
            for entry in range(position, self.bucket_start[fact + 1]):
                if self._applies(entry, digits, size):
                    return entry
        # The facts after ``fact``: the rest of its digit, then the digits above.
        cdef Py_ssize_t at = (fact + 1) // STRIPS_DIGIT_BITS
        cdef int shift = (fact + 1) - at * STRIPS_DIGIT_BITS
        cdef uint32_t digit
        for i in range(at, size):
            digit = digits[i]
            if i == at:
                digit &= ~((<uint32_t> 1 << shift) - 1)
            while digit:
                fact = i * STRIPS_DIGIT_BITS + __builtin_ctz(digit)
                digit &= digit - 1
                for entry in range(self.bucket_start[fact], self.bucket_start[fact + 1]):
                    if self._applies(entry, digits, size):
                        return entry
        return -1

    cdef Py_ssize_t _next_packed(self, bytes state, Py_ssize_t position) except -2:
        cdef Py_ssize_t count = len(state) // 4, entries = len(self.order), low, middle
        cdef const uint32_t* facts = <const uint32_t*> PyBytes_AS_STRING(state)
        if count and facts[count - 1] >= <uint32_t> self.num_facts:
            raise ValueError(f"not a state of {self.num_facts} facts")
        if position < 0:
            position = 0
        while position < self.num_unkeyed:
            if self._applies_packed(position, facts, count):
                return position
            position += 1
        if position >= entries:
            return -1
        cdef int fact = self.entry_key[position], entry
        low = strips_first_at_or_after(facts, 0, count, fact)  # the first true fact from ``fact``
        if low < count and facts[low] == <uint32_t> fact:
            for entry in range(position, self.bucket_start[fact + 1]):
                if self._applies_packed(entry, facts, count):
                    return entry
            low += 1
        for middle in range(low, count):
            fact = facts[middle]
            for entry in range(self.bucket_start[fact], self.bucket_start[fact + 1]):
                if self._applies_packed(entry, facts, count):
                    return entry
        return -1

    def ordered(self, state, operators):
        """Those of ``operators`` applicable in ``state`` (an int, or its packing), once
        each, in the order :meth:`applicable` lists them."""
        cdef Py_ssize_t size
        cdef const uint32_t* digits = NULL
        cdef const uint32_t* facts = NULL
        cdef bint packed = isinstance(state, bytes)
        if packed:
            facts = <const uint32_t*> PyBytes_AS_STRING(state)
            size = len(state) // 4
        elif isinstance(state, int):
            digits = strips_digits(state, &size)
            if size < 0 or size > self.num_digits:
                raise ValueError(f"not a state of {self.num_facts} facts")
        else:
            raise TypeError("a state is an int or its packing")
        cdef int op, entry
        cdef set found = set()
        for op in operators:
            if op < 0 or op >= len(self.order):
                raise IndexError(f"no operator {op}")
            entry = self.position[op]
            if self._applies_packed(entry, facts, size) if packed else self._applies(entry, digits, size):
                found.add(entry)
        return [self.entry_op[entry] for entry in sorted(found)]

    def step_packed(self, bytes packed, int operator, code):
        """The packing of what :meth:`apply` makes of the state packed as ``packed``
        (its facts without the operator's deletes, with its adds, in order: the runs of
        facts between two changes copied whole, a change's place found by binary
        search, so a successor costs a copy of its parent's packing), the change from
        ``packed`` to it (the count of facts lost, the lost and the gained facts, 4
        bytes each) and its Zobrist code, ``code`` (``packed``'s) XORed with the
        changed facts' codes: the change and the code cost what the operator touches."""
        if operator < 0 or operator >= len(self.add_start) - 1:
            raise IndexError(f"no operator {operator}")
        cdef Py_ssize_t count = len(packed) // 4
        cdef const uint32_t* facts = <const uint32_t*> PyBytes_AS_STRING(packed)
        cdef int touched = (self.add_start[operator + 1] - self.add_start[operator]
                            + self.delete_start[operator + 1] - self.delete_start[operator])
        cdef bytes change = PyBytes_FromStringAndSize(NULL, (touched + 1) * 4)
        cdef uint32_t* numbers = <uint32_t*> PyBytes_AS_STRING(change)
        cdef uint32_t* gained = numbers + 1 + (self.delete_start[operator + 1] - self.delete_start[operator])
        cdef Py_ssize_t lost_count = 0, gained_count = 0
        cdef bytes made = PyBytes_FromStringAndSize(NULL, self._merge(facts, count, operator, NULL) * 4)
        self._merge(
            facts, count, operator, <uint32_t*> PyBytes_AS_STRING(made),
            numbers + 1, &lost_count, gained, &gained_count,
        )
        cdef uint64_t zobrist = <uint64_t> code
        cdef Py_ssize_t i
        for i in range(lost_count):
            zobrist ^= strips_fact_code(numbers[1 + i])
        for i in range(gained_count):
            zobrist ^= strips_fact_code(gained[i])
            numbers[1 + lost_count + i] = gained[i]  # after the lost ones, moved down
        numbers[0] = <uint32_t> lost_count
        return made, change[:(1 + lost_count + gained_count) * 4], zobrist

    cdef Py_ssize_t _merge(
        self, const uint32_t* facts, Py_ssize_t count, int operator, uint32_t* out,
        uint32_t* lost=NULL, Py_ssize_t* lost_count=NULL,
        uint32_t* gained=NULL, Py_ssize_t* gained_count=NULL,
    ):
        """Write the successor's facts to ``out`` (just count them when it is NULL): the
        changes in ascending order, at each the run of facts below it copied, then the
        added fact written or the deleted one skipped (an add wins). Given ``lost``
        and ``gained``, the facts that the successor lacks and its parent held, and the
        other way round, are written there (ascending) and counted."""
        cdef Py_ssize_t made = 0, read = 0, at
        cdef int add = self.add_start[operator], add_end = self.add_start[operator + 1]
        cdef int cut = self.delete_start[operator], cut_end = self.delete_start[operator + 1]
        cdef uint32_t fact
        cdef bint adding, present
        while add < add_end or cut < cut_end:
            adding = cut == cut_end or (add < add_end and self.adds[add] <= self.deletes[cut])
            fact = self.adds[add] if adding else self.deletes[cut]
            at = strips_first_at_or_after(facts, read, count, fact)
            if out != NULL:
                memcpy(out + made, facts + read, (at - read) * sizeof(uint32_t))
            made += at - read
            read = at
            present = read < count and facts[read] == fact
            if present:
                read += 1  # present: dropped if deleted, written again if added
            if adding:
                if out != NULL:
                    out[made] = fact
                made += 1
                if gained != NULL and not present:
                    gained[gained_count[0]] = fact
                    gained_count[0] += 1
            elif lost != NULL and present:
                lost[lost_count[0]] = fact
                lost_count[0] += 1
            while add < add_end and <uint32_t> self.adds[add] == fact:  # repeats too
                add += 1
            while cut < cut_end and <uint32_t> self.deletes[cut] == fact:
                cut += 1
        if out != NULL:
            memcpy(out + made, facts + read, (count - read) * sizeof(uint32_t))
        return made + count - read

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


cdef inline void _sort(int[::1] values, Py_ssize_t start, Py_ssize_t end):
    """Sort ``values[start:end]`` in place (insertion: an operator has a few effects)."""
    cdef Py_ssize_t i, j
    cdef int value
    for i in range(start + 1, end):
        value = values[i]
        j = i
        while j > start and values[j - 1] > value:
            values[j] = values[j - 1]
            j -= 1
        values[j] = value


cdef inline bint _listed(const uint32_t* facts, Py_ssize_t count, int fact):
    """Whether ``fact`` is among the ``count`` sorted ``facts``."""
    cdef Py_ssize_t at = strips_first_at_or_after(facts, 0, count, <uint32_t> fact)
    return at < count and facts[at] == <uint32_t> fact


cdef inline bint _holds(const uint32_t* digits, Py_ssize_t size, int fact):
    """Whether bit ``fact`` of the int with these digits is set."""
    cdef Py_ssize_t at = fact // STRIPS_DIGIT_BITS
    return at < size and (digits[at] >> (fact - at * STRIPS_DIGIT_BITS)) & 1
