# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True
"""The loop of lazy greedy best-first search, compiled.

The reference is :meth:`~strips_framework.forward.lazy.LazyGreedySearch.reference_run`,
with :class:`~strips_framework.forward.openlists.AlternationOpenList`; this is the same
loop, statement for statement, with the open lists' buckets as C arrays of entries (an
entry packs the parent's state number and the operator into one integer). Keys are the
heuristic's values, whatever numbers it returns: a dict finds a key's bucket and a heap
orders the keys, as in the reference, so ties and the order of pops are the same and so
are the expansions (``tests/search_forward/test_compiled_lazy.py`` checks it search by
search). The heuristic, the successor generator and the state registry are called as
they are, so heuristics written in Python work unchanged.
"""

from heapq import heappop, heappush
from libc.stdlib cimport free, malloc, realloc
from libc.string cimport memmove

import math

ctypedef long long entry_t


cdef class _Bucket:
    """A FIFO of entries: a C array with a read position."""

    cdef entry_t* data
    cdef Py_ssize_t head, tail, capacity

    def __cinit__(self):
        self.capacity = 64
        self.data = <entry_t*> malloc(self.capacity * sizeof(entry_t))
        if self.data == NULL:
            raise MemoryError()

    def __dealloc__(self):
        free(self.data)

    cdef int append(self, entry_t entry) except -1:
        cdef entry_t* grown
        if self.tail == self.capacity:
            if self.head * 2 >= self.capacity:  # half of it is read: reuse that room
                memmove(self.data, self.data + self.head, (self.tail - self.head) * sizeof(entry_t))
                self.tail -= self.head
                self.head = 0
            else:
                grown = <entry_t*> realloc(self.data, 2 * self.capacity * sizeof(entry_t))
                if grown == NULL:
                    raise MemoryError()
                self.data, self.capacity = grown, 2 * self.capacity
        self.data[self.tail] = entry
        self.tail += 1
        return 0


cdef class _Queue:
    """Entries by key: a bucket per key in use, the keys in a heap (lowest first)."""

    cdef dict buckets
    cdef list keys
    cdef Py_ssize_t size

    def __cinit__(self):
        self.buckets = {}
        self.keys = []
        self.size = 0

    cdef _Bucket bucket(self, key):
        cdef _Bucket found = self.buckets.get(key)
        if found is None:
            found = self.buckets[key] = _Bucket()
            heappush(self.keys, key)
        return found

    cdef entry_t pop(self) except? -1:
        key = self.keys[0]
        cdef _Bucket bucket = self.buckets[key]
        cdef entry_t entry = bucket.data[bucket.head]
        bucket.head += 1
        if bucket.head == bucket.tail:
            del self.buckets[key]
            heappop(self.keys)
        self.size -= 1
        return entry


def lazy_greedy(run, evaluate, bint use_preferred, long long boost):
    """Lazy greedy search over ``run`` with ``evaluate(state) -> (h, preferred)``; the
    number of a goal state, or None when out of states."""
    cdef _Queue every = _Queue(), chosen = _Queue()
    cdef _Bucket bucket
    cdef long long turns_every = 0, turns_chosen = 0, width, base, number, parent, op
    cdef entry_t entry
    cdef Py_ssize_t i, count
    task, space, budget = run.task, run.space, run.budget
    applicable, successor = space.successors.applicable, space.successor
    ids, states, add, goal = space.ids, space.states, space.add, task.goal_mask
    width = max(len(task.operators), 1)
    best_h = math.inf
    parent, op, state = -1, -1, task.init
    while True:
        number = add(state, parent, op)
        h, preferred = evaluate(state)
        run.evaluated += 1
        if h == math.inf:
            run.dead_ends += 1
        elif state & goal == goal:
            return number
        else:
            budget.check(run.expanded)
            run.expanded += 1
            if h < best_h:
                if best_h != math.inf:  # the initial state's h only sets the mark
                    turns_chosen -= boost
                best_h = h
            successors = applicable(state)
            count = len(successors)
            run.generated += count
            base = number * width
            if count:
                bucket = every.bucket(h)
                for i in range(count):
                    bucket.append(base + <long long> successors[i])
                every.size += count
                if use_preferred and preferred:
                    marked = set(preferred)
                    picked = [op for op in successors if op in marked]
                    if picked:
                        bucket = chosen.bucket(h)
                        for op in picked:
                            bucket.append(base + op)
                        chosen.size += len(picked)
        while True:
            if every.size == 0 and chosen.size == 0:
                return None
            if chosen.size and (turns_chosen < turns_every or not every.size):
                turns_chosen += 1
                entry = chosen.pop()
            else:
                turns_every += 1
                entry = every.pop()
            parent = entry // width
            op = entry - parent * width
            state = successor(states[parent], op)
            if state not in ids:
                break
