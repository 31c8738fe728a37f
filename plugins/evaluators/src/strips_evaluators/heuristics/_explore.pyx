# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True
"""The relaxed explorations of hadd, hFF and hmax, compiled.

The same algorithms as the pure-Python reference (:func:`.additive.additive_exploration`
and :func:`.ff.relaxed_plan`, :func:`.hmax.max_exploration`) over the same
:class:`~.relaxation.RelaxedTask`, laid out once as C arrays (compressed rows for the
operators of each fact and the effects of each operator). The queue pops facts by cost,
last in first out among equal costs, which is the order of the reference's bucket queue,
so supporters, relaxed plans and hence preferred operators and search expansions are the
same; a differential test checks that on every shared domain.
"""

from libc.stdlib cimport free, malloc, realloc

import math

ctypedef unsigned long long u64

cdef long long INFINITE = (<long long> 1) << 62
#: Supporter of a fact that holds in the state (the reference's IN_STATE).
cdef int IN_STATE = -1
#: Pushes are numbered in a queue key's low 32 bits, counting down from this.
cdef u64 LAST_ORDER = 0xFFFFFFFF


cdef int* _ints(values) except NULL:
    cdef Py_ssize_t n = len(values)
    cdef int* array = <int*> malloc(max(n, 1) * sizeof(int))
    if array == NULL:
        raise MemoryError()
    for i in range(n):
        array[i] = values[i]
    return array


def _bits(mask):
    """The fact numbers set in ``mask``, ascending."""
    facts = []
    position = 0
    while mask:
        if mask & 1:
            facts.append(position)
        mask >>= 1
        position += 1
    return facts


cdef class Explorer:
    """hadd, hmax and the hFF relaxed plan of a relaxed task, per state."""

    cdef int num_facts, num_ops, true_fact, num_goals, num_bytes, shared_costs
    cdef int* pre_start
    cdef int* pre_ops
    cdef int* add_start
    cdef int* add_facts
    cdef int* pre_list_start
    cdef int* pre_list
    cdef int* op_cost
    cdef int* pre_count
    cdef int* goal
    cdef int* is_goal
    cdef int* operator
    # Per relaxed operator, the facts a state must hold and lack for its effect to
    # happen (its real operator's precondition and the effect's condition).
    cdef int* need_start
    cdef int* need
    cdef int* lack_start
    cdef int* lack
    cdef bytes state_bytes
    # Per exploration (reused): costs, supporters, counters, the queue, plan marks.
    cdef long long* cost
    cdef int* supporter
    cdef long long* accumulated
    cdef int* remaining
    cdef u64* heap
    cdef int* heap_fact
    cdef Py_ssize_t heap_capacity, fact_capacity
    cdef char* marked
    cdef char* counted
    cdef int* stack
    cdef int num_real

    def __cinit__(self, relaxed):
        self.num_facts = relaxed.num_facts
        self.num_ops = len(relaxed.pre)
        self.true_fact = relaxed.true_fact
        self.num_bytes = (relaxed.true_fact + 7) // 8
        self.shared_costs = relaxed.shared_costs
        starts, ops = [0], []
        for listed in relaxed.pre_of:
            ops.extend(listed)
            starts.append(len(ops))
        self.pre_start, self.pre_ops = _ints(starts), _ints(ops)
        starts, facts = [0], []
        for effects in relaxed.add:
            facts.extend(effects)
            starts.append(len(facts))
        self.add_start, self.add_facts = _ints(starts), _ints(facts)
        starts, facts = [0], []
        for conditions in relaxed.pre:
            facts.extend(conditions)
            starts.append(len(facts))
        self.pre_list_start, self.pre_list = _ints(starts), _ints(facts)
        self.op_cost = _ints(relaxed.cost)
        self.pre_count = _ints(relaxed.pre_count)
        self.goal = _ints(relaxed.goal)
        self.num_goals = len(relaxed.goal)
        self.is_goal = _ints([1 if flag else 0 for flag in relaxed.is_goal])
        self.operator = _ints(relaxed.operator)
        starts, facts_needed = [0], []
        for mask in relaxed.pre_mask:
            facts_needed.extend(_bits(mask))
            starts.append(len(facts_needed))
        self.need_start, self.need = _ints(starts), _ints(facts_needed)
        starts, facts_lacking = [0], []
        for mask in relaxed.neg_mask:
            facts_lacking.extend(_bits(mask))
            starts.append(len(facts_lacking))
        self.lack_start, self.lack = _ints(starts), _ints(facts_lacking)
        self.num_real = max([index + 1 for index in relaxed.operator] + [1])
        self.cost = <long long*> malloc(max(self.num_facts, 1) * sizeof(long long))
        self.supporter = <int*> malloc(max(self.num_facts, 1) * sizeof(int))
        self.accumulated = <long long*> malloc(max(self.num_ops, 1) * sizeof(long long))
        self.remaining = <int*> malloc(max(self.num_ops, 1) * sizeof(int))
        self.heap_capacity = max(self.num_facts, 16)
        self.heap = <u64*> malloc(self.heap_capacity * sizeof(u64))
        self.fact_capacity = self.heap_capacity
        self.heap_fact = <int*> malloc(self.fact_capacity * sizeof(int))
        self.marked = <char*> malloc(max(self.num_ops, 1))
        self.counted = <char*> malloc(self.num_real)
        self.stack = <int*> malloc(max(self.num_facts + len(facts), 1) * sizeof(int))
        if (self.cost == NULL or self.supporter == NULL or self.accumulated == NULL
                or self.remaining == NULL or self.heap == NULL or self.heap_fact == NULL
                or self.marked == NULL or self.counted == NULL or self.stack == NULL):
            raise MemoryError()

    def __dealloc__(self):
        free(self.pre_start)
        free(self.pre_ops)
        free(self.add_start)
        free(self.add_facts)
        free(self.pre_list_start)
        free(self.pre_list)
        free(self.op_cost)
        free(self.pre_count)
        free(self.goal)
        free(self.is_goal)
        free(self.operator)
        free(self.need_start)
        free(self.need)
        free(self.lack_start)
        free(self.lack)
        free(self.cost)
        free(self.supporter)
        free(self.accumulated)
        free(self.remaining)
        free(self.heap)
        free(self.heap_fact)
        free(self.marked)
        free(self.counted)
        free(self.stack)

    cdef int _push(self, Py_ssize_t* size, u64* order, long long value, int fact) except -1:
        """Queue ``fact`` at ``value``; ties pop last in, first out (the key's low bits
        count ``order`` down)."""
        cdef Py_ssize_t i, parent
        cdef u64 key
        if size[0] == self.heap_capacity:
            self.heap_capacity *= 2
            self.heap = <u64*> realloc(self.heap, self.heap_capacity * sizeof(u64))
            if self.heap == NULL:
                raise MemoryError()
        if order[0] == <u64> self.fact_capacity:
            self.fact_capacity *= 2
            self.heap_fact = <int*> realloc(self.heap_fact, self.fact_capacity * sizeof(int))
            if self.heap_fact == NULL:
                raise MemoryError()
        self.heap_fact[order[0]] = fact
        key = (<u64> value << 32) | (LAST_ORDER - order[0])
        order[0] += 1
        i = size[0]
        size[0] += 1
        while i > 0:
            parent = (i - 1) >> 1
            if self.heap[parent] <= key:
                break
            self.heap[i] = self.heap[parent]
            i = parent
        self.heap[i] = key
        return 0

    cdef u64 _pop(self, Py_ssize_t* size):
        cdef u64 top = self.heap[0]
        cdef u64 last
        cdef Py_ssize_t i = 0, child
        size[0] -= 1
        if size[0] > 0:
            last = self.heap[size[0]]
            while True:
                child = 2 * i + 1
                if child >= size[0]:
                    break
                if child + 1 < size[0] and self.heap[child + 1] < self.heap[child]:
                    child += 1
                if last <= self.heap[child]:
                    break
                self.heap[i] = self.heap[child]
                i = child
            self.heap[i] = last
        return top

    cdef int _explore(self, object state, bint additive) except -1:
        """Fact costs (``self.cost``) and supporters from ``state``: sums of
        precondition costs when ``additive``, else maxima. Returns 1 when every goal
        fact was reached (the exploration stops once they are all settled)."""
        cdef Py_ssize_t size = 0
        cdef u64 order = 0, key
        cdef int fact, op, effect, goals_left = self.num_goals, i, j, bit
        cdef long long level, value
        cdef bytes packed = state.to_bytes(self.num_bytes, "little")
        cdef const unsigned char* data = packed
        self.state_bytes = packed
        cdef unsigned char byte
        for i in range(self.num_facts):
            self.cost[i] = INFINITE
            self.supporter[i] = IN_STATE
        for i in range(self.num_ops):
            self.remaining[i] = self.pre_count[i]
            self.accumulated[i] = self.op_cost[i] if additive else 0
        for i in range(self.num_bytes):
            byte = data[i]
            while byte:
                bit = 0
                while not (byte >> bit) & 1:
                    bit += 1
                byte &= byte - 1
                fact = i * 8 + bit
                self.cost[fact] = 0
                self._push(&size, &order, 0, fact)
        self.cost[self.true_fact] = 0
        self._push(&size, &order, 0, self.true_fact)
        while size:
            key = self._pop(&size)
            level = <long long> (key >> 32)
            fact = self.heap_fact[LAST_ORDER - (key & LAST_ORDER)]
            if self.cost[fact] != level:
                continue
            if self.is_goal[fact]:
                goals_left -= 1
                if not goals_left:
                    return 1
            for i in range(self.pre_start[fact], self.pre_start[fact + 1]):
                op = self.pre_ops[i]
                if additive:
                    self.accumulated[op] += level
                self.remaining[op] -= 1
                if self.remaining[op]:
                    continue
                value = self.accumulated[op] if additive else level + self.op_cost[op]
                for j in range(self.add_start[op], self.add_start[op + 1]):
                    effect = self.add_facts[j]
                    if value < self.cost[effect]:
                        self.cost[effect] = value
                        self.supporter[effect] = op
                        self._push(&size, &order, value, effect)
        return goals_left == 0

    def hadd(self, state):
        """The sum of the goal facts' additive costs (``math.inf``: a relaxed dead end)."""
        return self._goal_value(state, True)

    def hmax(self, state):
        """The costliest goal fact's cost under the max relaxation."""
        return self._goal_value(state, False)

    cdef object _goal_value(self, object state, bint additive):
        """The goal facts' costs summed (``additive``) or their maximum."""
        cdef long long total = 0, value
        cdef int i
        if not self._explore(state, additive):
            return math.inf
        for i in range(self.num_goals):
            value = self.cost[self.goal[i]]
            if additive:
                total += value
            elif value > total:
                total = value
        return total

    def relaxed_plan(self, state):
        """hFF and the relaxed operators of the relaxed plan from hadd best supporters
        (each real operator's cost counted once)."""
        cdef list plan = []
        total = self._plan(state, plan)
        return total, plan

    def preferred(self, state):
        """hFF and the preferred operators: the real operators of the relaxed plan whose
        relaxed operator's precondition holds in ``state``, ascending."""
        cdef list plan = []
        cdef int op, i, ok
        cdef const unsigned char* data
        total = self._plan(state, plan)
        if not plan:
            return total, []
        data = self.state_bytes
        chosen = set()
        for op in plan:
            if self.operator[op] < 0:
                continue
            ok = 1
            for i in range(self.need_start[op], self.need_start[op + 1]):
                if not (data[self.need[i] >> 3] >> (self.need[i] & 7)) & 1:
                    ok = 0
                    break
            if ok:
                for i in range(self.lack_start[op], self.lack_start[op + 1]):
                    if (data[self.lack[i] >> 3] >> (self.lack[i] & 7)) & 1:
                        ok = 0
                        break
            if ok:
                chosen.add(self.operator[op])
        return total, sorted(chosen)

    cdef object _plan(self, object state, list plan):
        """hFF, with the relaxed plan's operators appended to ``plan``."""
        cdef int top = 0, op, i, real
        cdef long long total = 0
        if not self._explore(state, True):
            return math.inf
        for i in range(self.num_ops):
            self.marked[i] = 0
        for i in range(self.num_real):
            self.counted[i] = 0
        for i in range(self.num_goals):
            self.stack[top] = self.goal[i]
            top += 1
        while top:
            top -= 1
            op = self.supporter[self.stack[top]]
            if op < 0 or self.marked[op]:
                continue
            self.marked[op] = 1
            plan.append(op)
            real = self.operator[op]
            if not self.shared_costs or real < 0:
                total += self.op_cost[op]
            elif not self.counted[real]:
                self.counted[real] = 1
                total += self.op_cost[op]
            for i in range(self.pre_list_start[op], self.pre_list_start[op + 1]):
                self.stack[top] = self.pre_list[i]
                top += 1
        return total
