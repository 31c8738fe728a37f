# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True
"""The loops of lazy greedy search and of eager best-first search (A*, weighted A*,
greedy), compiled.

The references are :meth:`~strips_framework.forward.lazy.LazyGreedySearch.reference_run`
and :meth:`~strips_framework.forward.eager.EagerSearch.reference_run`, with the open lists
of :mod:`~strips_framework.forward.openlists`; these are the same loops, statement for
statement, with the open lists' buckets as C arrays of entries (a lazy entry packs the
parent's state number and the operator into one integer, an eager one is a state
number). Keys are whatever the strategy makes of g and h: a dict finds a key's bucket
and a heap orders the keys, as in the reference, so ties and the order of pops are the
same and so are the expansions (``tests/search_forward/test_compiled_search.py`` checks
it search by search). The heuristic, the successor generator, the state registry and
the strategy's key are called as they are, so heuristics written in Python work
unchanged.
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

    cdef int push(self, key, entry_t entry) except -1:
        self.bucket(key).append(entry)
        self.size += 1
        return 0

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


cdef class _Alternation:
    """Every entry, and the preferred ones again; the list that has had fewer turns
    goes next (the full one on a tie), and progress gives the preferred one ``boost``
    extra turns (:class:`~strips_framework.forward.openlists.AlternationOpenList`)."""

    cdef _Queue every, chosen
    cdef long long turns_every, turns_chosen, boost

    def __cinit__(self, long long boost):
        self.every, self.chosen, self.boost = _Queue(), _Queue(), boost

    cdef bint empty(self):
        return self.every.size == 0 and self.chosen.size == 0

    cdef entry_t pop(self) except? -1:
        if self.chosen.size and (self.turns_chosen < self.turns_every or not self.every.size):
            self.turns_chosen += 1
            return self.chosen.pop()
        self.turns_every += 1
        return self.every.pop()

    cdef void reward_progress(self):
        self.turns_chosen -= self.boost


def lazy_greedy(run, evaluate, bint use_preferred, long long boost):
    """Lazy greedy search over ``run`` with ``evaluate(state) -> (h, preferred)``; the
    number of a goal state, or None when out of states.

    A full-list entry is a cursor: the expanded state's number and the position (in the
    successor generator's order) of its next applicable operator; popped, it gives that
    operator and stays at the head of its bucket with the next position while there is
    one. A preferred-list entry is the state's number and the operator."""
    cdef _Alternation frontier = _Alternation(boost)
    cdef _Queue every = frontier.every
    cdef _Bucket bucket
    cdef long long width, number, parent, op, position, following
    cdef entry_t entry
    cdef bint packed, merges
    task, space, budget = run.task, run.space, run.budget
    successors = space.successors
    following_of, ordered, order = successors.next_applicable, successors.ordered, successors.order
    take, stored, add, is_goal = space.take, space.stored, space.add, space.is_goal
    successor, state_of, find, goal = space.successor, space.state, space.number, task.goal_mask
    packed, merges = space.packed, space.merges
    # Where the space merges, a state's packing is mostly among those it keeps.
    kept = space.kept.get if merges else None
    width = max(len(task.operators), 1)
    best_h = math.inf
    number = add(task.init, -1, -1)
    state = stored(number) if merges else task.init  # as the loop takes states
    while True:
        h, preferred = evaluate(state)
        run.evaluated += 1
        if h == math.inf:
            run.dead_ends += 1
        elif (is_goal(state) if packed else state & goal == goal):
            return number
        else:
            budget.check(run.expanded)
            run.expanded += 1
            if h < best_h:
                if best_h != math.inf:  # the initial state's h only sets the mark
                    frontier.reward_progress()
                best_h = h
            position = following_of(state if merges else stored(number), 0)
            if position >= 0:
                every.push(h, number * width + position)
                if use_preferred and preferred:
                    picked = ordered(state, preferred)
                    if picked:
                        bucket = frontier.chosen.bucket(h)
                        for op in picked:
                            bucket.append(number * width + op)
                        frontier.chosen.size += len(picked)
        while True:
            if frontier.empty():
                return None
            if frontier.chosen.size and (frontier.turns_chosen < frontier.turns_every or not every.size):
                frontier.turns_chosen += 1
                entry = frontier.chosen.pop()
                parent = entry // width
                op = entry - parent * width
            else:
                frontier.turns_every += 1
                bucket = every.buckets[every.keys[0]]
                entry = bucket.data[bucket.head]
                parent = entry // width
                position = entry - parent * width
                op = order[position]
                found = kept(parent) if merges else None
                following = following_of(stored(parent) if found is None else found, position + 1)
                if following >= 0:
                    bucket.data[bucket.head] = parent * width + following
                else:
                    every.pop()
            run.generated += 1
            if merges:
                number = take(parent, op)
                if number < 0:
                    continue
                state = kept(number) or stored(number)  # kept: just stored
                break
            else:  # space.take's other way, without a call in between
                state = successor(state_of(parent), op)
                if find(state) is not None:
                    continue
            number = add(state, parent, op)
            break


def eager(run, estimate, preferred_of, key, bint reopen, long long boost):
    """Eager best-first search over ``run``: ``key(g, h)`` orders the open list,
    ``preferred_of`` (or None) gives a state's preferred operators, ``reopen`` says
    whether a cheaper path to a known state replaces the old one. The number of a goal
    state, or None when out of states."""
    cdef _Alternation frontier = _Alternation(boost)
    cdef long long number, known, op
    cdef bytearray closed = bytearray(1)
    task, space, budget = run.task, run.space, run.budget
    applicable, successor = space.successors.applicable, space.successor
    find, state_of, costs, goal = space.number, space.state, space.costs, task.goal_mask
    add, reparent = space.add, space.reparent
    h0 = estimate(task.init)
    run.evaluated += 1
    if h0 == math.inf:
        run.dead_ends += 1
        return None
    add(task.init, -1, -1)
    cdef list g = [0], h = [h0]
    frontier.every.push(key(0, h0), 0)
    best_h = h0
    no_preferred = frozenset()
    while not frontier.empty():
        number = frontier.pop()
        if closed[number]:
            continue
        closed[number] = 1
        budget.check(run.expanded)
        run.expanded += 1  # counted before the goal test, as Fast Downward counts
        state = state_of(number)
        if state & goal == goal:
            return number
        preferred = frozenset(preferred_of(state)[1]) if preferred_of else no_preferred
        base = g[number]
        for op in applicable(state):
            child = successor(state, op)
            run.generated += 1
            child_g = base + costs[op]
            found = find(child)
            if found is None:
                child_h = estimate(child)
                run.evaluated += 1
                add(child, number, op)
                g.append(child_g)
                h.append(child_h)
                if child_h == math.inf:
                    run.dead_ends += 1
                    closed.append(1)
                    continue
                closed.append(0)
                child_key = key(child_g, child_h)
                frontier.every.push(child_key, len(g) - 1)
                if op in preferred:
                    frontier.chosen.push(child_key, len(g) - 1)
                if child_h < best_h:
                    best_h = child_h
                    frontier.reward_progress()
                continue
            known = found
            if reopen and child_g < g[known] and h[known] != math.inf:
                if closed[known]:
                    closed[known] = 0
                    run.reopened += 1
                g[known] = child_g
                reparent(known, number, op)
                child_key = key(child_g, h[known])
                frontier.every.push(child_key, known)
                if op in preferred:
                    frontier.chosen.push(child_key, known)
    return None
