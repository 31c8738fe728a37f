# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True
"""The relaxed explorations of hadd, hFF and hmax, and LM-cut, compiled.

The same algorithms as the pure-Python reference (:func:`.additive.additive_exploration`
and :func:`.ff.relaxed_plan`, :func:`.hmax.max_exploration`) over the same
:class:`~.relaxation.RelaxedTask`, laid out once as C arrays (compressed rows for the
operators of each fact and the effects of each operator). The queue pops facts by cost,
last in first out among equal costs, which is the order of the reference's bucket queue,
so supporters, relaxed plans and hence preferred operators and search expansions are the
same; a differential test checks that on every shared domain. :class:`LMCut` is
:class:`~.lmcut.LMCutEstimator` over the same arrays (see its docstring).
"""

from libc.stdlib cimport calloc, free, malloc, realloc

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
    # The task's facts in the order _explore pushes a state's (RelaxedTask.start_rank).
    cdef int* start_order
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
    # The last relaxed plan's operators (``plan_len`` of them), and per real operator
    # whether ``preferred`` picked it: C arrays, as a Python list and set cost a third
    # of an hFF evaluation on small tasks.
    cdef int* plan_ops
    cdef int plan_len
    cdef char* chosen
    cdef int* picked

    def __cinit__(self, relaxed, *extra):  # a subclass's arguments follow ``relaxed``
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
        order = sorted(range(relaxed.true_fact), key=relaxed.start_rank.__getitem__)
        self.start_order = _ints(order)
        starts, facts_needed = [0], []
        for needed in relaxed.need:
            facts_needed.extend(needed)
            starts.append(len(facts_needed))
        self.need_start, self.need = _ints(starts), _ints(facts_needed)
        starts, facts_lacking = [0], []
        for lacking in relaxed.lack:
            facts_lacking.extend(lacking)
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
        self.plan_ops = <int*> malloc(max(self.num_ops, 1) * sizeof(int))
        self.chosen = <char*> calloc(self.num_real, 1)
        self.picked = <int*> malloc(self.num_real * sizeof(int))
        if (self.cost == NULL or self.supporter == NULL or self.accumulated == NULL
                or self.remaining == NULL or self.heap == NULL or self.heap_fact == NULL
                or self.marked == NULL or self.counted == NULL or self.stack == NULL
                or self.plan_ops == NULL or self.chosen == NULL or self.picked == NULL):
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
        free(self.start_order)
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
        free(self.plan_ops)
        free(self.chosen)
        free(self.picked)

    cdef int _push(self, Py_ssize_t* size, u64* order, long long value, int fact,
                   bint fifo=False) except -1:
        """Queue ``fact`` at ``value``; ties pop last in, first out (the key's low bits
        count ``order`` down), or first in, first out with ``fifo`` (they count it up)."""
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
        key = (<u64> value << 32) | (order[0] if fifo else LAST_ORDER - order[0])
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
        for i in range(self.true_fact):  # in causal order, as the reference
            fact = self.start_order[i]
            if (data[fact >> 3] >> (fact & 7)) & 1:
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
        total = self._plan(state)
        return total, [self.plan_ops[i] for i in range(self.plan_len)]

    def preferred(self, state):
        """hFF and the preferred operators: the real operators of the relaxed plan whose
        relaxed operator's precondition holds in ``state``, ascending."""
        cdef int op, i, k, ok, real, count = 0
        cdef const unsigned char* data
        total = self._plan(state)
        data = self.state_bytes
        for k in range(self.plan_len):
            op = self.plan_ops[k]
            real = self.operator[op]
            if real < 0 or self.chosen[real]:
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
                self.chosen[real] = 1
                self.picked[count] = real
                count += 1
        for k in range(count):
            self.chosen[self.picked[k]] = 0
        return total, sorted([self.picked[k] for k in range(count)])

    cdef object _plan(self, object state):
        """hFF, with the relaxed plan's operators in ``plan_ops``."""
        cdef int top = 0, op, i, real
        cdef long long total = 0
        self.plan_len = 0
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
            self.plan_ops[self.plan_len] = op
            self.plan_len += 1
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


cdef int* _rows(lists, int** starts) except NULL:
    """``lists`` as compressed rows: ``starts[0][i]`` .. ``starts[0][i + 1]`` index row i."""
    bounds, flat = [0], []
    for row in lists:
        flat.extend(row)
        bounds.append(len(flat))
    starts[0] = _ints(bounds)
    return _ints(flat)


cdef class LMCut(Explorer):
    """LM-cut over the relaxed task with the artificial goal operator, as
    :class:`~.lmcut.LMCutEstimator` computes it: the same hmax exploration (last in,
    first out among equal costs), goal zones, cuts and incremental hmax updates (first
    in, first out within a cost level, a level's facts before the updates they cause), so
    the values are the reference's; ``tests/test_compiled.py`` compares them."""

    cdef int goal_fact, has_siblings
    cdef int* ach_start
    cdef int* ach_ops
    cdef int* only_effect
    cdef int* sib_start
    cdef int* sib_ops
    # Per state (reused): operator costs left, supporters and their hmax, fact hmax.
    cdef long long* left
    cdef int* sup
    cdef long long* sup_cost
    cdef long long* hmax
    cdef char* zone
    cdef char* seen
    cdef char* in_cut
    cdef int* cut
    cdef int* cut_more
    cdef int* facts
    cdef int* zone_fact
    cdef int* zone_pos
    # The justification graph's edges out of each fact (stale ones are skipped).
    cdef int** supported
    cdef int* supported_len
    cdef int* supported_cap
    cdef long long* lowered_value
    cdef int* lowered_op
    cdef Py_ssize_t lowered_cap

    def __cinit__(self, relaxed, goal_fact, achievers, only_effect, siblings):
        cdef int n = max(self.num_facts, 1), m = max(self.num_ops, 1), i
        self.goal_fact = goal_fact
        self.ach_ops = _rows(achievers, &self.ach_start)
        self.only_effect = _ints(only_effect)
        self.has_siblings = siblings is not None
        self.sib_ops = _rows(siblings if siblings is not None else [], &self.sib_start)
        self.left = <long long*> malloc(m * sizeof(long long))
        self.sup = <int*> malloc(m * sizeof(int))
        self.sup_cost = <long long*> malloc(m * sizeof(long long))
        self.hmax = <long long*> malloc(n * sizeof(long long))
        self.zone = <char*> malloc(n)
        self.seen = <char*> malloc(n)
        self.in_cut = <char*> malloc(m)
        self.cut = <int*> malloc(m * sizeof(int))
        self.cut_more = <int*> malloc(m * sizeof(int))
        self.facts = <int*> malloc(n * sizeof(int))
        self.zone_fact = <int*> malloc(n * sizeof(int))
        self.zone_pos = <int*> malloc(n * sizeof(int))
        self.supported = <int**> malloc(n * sizeof(int*))
        self.supported_len = <int*> malloc(n * sizeof(int))
        self.supported_cap = <int*> malloc(n * sizeof(int))
        self.lowered_cap = m
        self.lowered_value = <long long*> malloc(m * sizeof(long long))
        self.lowered_op = <int*> malloc(m * sizeof(int))
        if (self.left == NULL or self.sup == NULL or self.sup_cost == NULL
                or self.hmax == NULL or self.zone == NULL or self.seen == NULL
                or self.in_cut == NULL or self.cut == NULL or self.cut_more == NULL
                or self.facts == NULL or self.zone_fact == NULL or self.zone_pos == NULL
                or self.supported == NULL or self.supported_len == NULL
                or self.supported_cap == NULL or self.lowered_value == NULL
                or self.lowered_op == NULL):
            raise MemoryError()
        for i in range(n):
            self.supported[i] = NULL
            self.supported_cap[i] = 0
            self.supported_len[i] = 0

    def __dealloc__(self):
        cdef int i
        if self.supported != NULL:
            for i in range(max(self.num_facts, 1)):
                free(self.supported[i])
        free(self.ach_start)
        free(self.ach_ops)
        free(self.only_effect)
        free(self.sib_start)
        free(self.sib_ops)
        free(self.left)
        free(self.sup)
        free(self.sup_cost)
        free(self.hmax)
        free(self.zone)
        free(self.seen)
        free(self.in_cut)
        free(self.cut)
        free(self.cut_more)
        free(self.facts)
        free(self.zone_fact)
        free(self.zone_pos)
        free(self.supported)
        free(self.supported_len)
        free(self.supported_cap)
        free(self.lowered_value)
        free(self.lowered_op)

    cdef int _support(self, int fact, int op) except -1:
        """Append ``op`` to the operators ``fact`` supports."""
        cdef int length = self.supported_len[fact]
        if length == self.supported_cap[fact]:
            self.supported_cap[fact] = max(4, 2 * length)
            self.supported[fact] = <int*> realloc(
                self.supported[fact], self.supported_cap[fact] * sizeof(int))
            if self.supported[fact] == NULL:
                raise MemoryError()
        self.supported[fact][length] = op
        self.supported_len[fact] = length + 1
        return 0

    cdef int _lower(self, Py_ssize_t* count, long long value, int op) except -1:
        """Note that ``op``'s effects may now be reached at ``value``."""
        if count[0] == self.lowered_cap:
            self.lowered_cap *= 2
            self.lowered_value = <long long*> realloc(
                self.lowered_value, self.lowered_cap * sizeof(long long))
            self.lowered_op = <int*> realloc(self.lowered_op, self.lowered_cap * sizeof(int))
            if self.lowered_value == NULL or self.lowered_op == NULL:
                raise MemoryError()
        self.lowered_value[count[0]] = value
        self.lowered_op[count[0]] = op
        count[0] += 1
        return 0

    cdef int _max_explore(self, int num_start) except -1:
        """hmax of every fact under the costs ``left`` from the ``num_start`` facts in
        ``facts``, with each reached operator's supporter (its last precondition out of
        the queue) and that supporter's hmax."""
        cdef Py_ssize_t size = 0
        cdef u64 order = 0, key
        cdef int fact, op, effect, i, j
        cdef long long level, reached
        for i in range(self.num_facts):
            self.hmax[i] = INFINITE
        for i in range(self.num_ops):
            self.remaining[i] = self.pre_count[i]
        for i in range(num_start):
            self.hmax[self.facts[i]] = 0
            self._push(&size, &order, 0, self.facts[i])
        while size:
            key = self._pop(&size)
            level = <long long> (key >> 32)
            fact = self.heap_fact[LAST_ORDER - (key & LAST_ORDER)]
            if self.hmax[fact] != level:
                continue
            for i in range(self.pre_start[fact], self.pre_start[fact + 1]):
                op = self.pre_ops[i]
                self.remaining[op] -= 1
                if self.remaining[op]:
                    continue
                self.sup[op] = fact
                self.sup_cost[op] = level
                reached = level + self.left[op]
                for j in range(self.add_start[op], self.add_start[op + 1]):
                    effect = self.add_facts[j]
                    if reached < self.hmax[effect]:
                        self.hmax[effect] = reached
                        self._push(&size, &order, reached, effect)
        return 0

    cdef bint _unreached_by_free(self, int fact):
        """True when every operator adding ``fact`` still costs something."""
        cdef int i
        for i in range(self.ach_start[fact], self.ach_start[fact + 1]):
            if not self.left[self.ach_ops[i]]:
                return False
        return True

    cdef int _goal_zone(self) except -1:
        """:meth:`.lmcut.LMCutEstimator._goal_zone`: ``zone`` marks the facts from which
        the goal is reached by zero-cost justifications (depth first, one position per
        level in a fact's achievers)."""
        cdef int top = 0, fact, op, i, condition, end
        cdef long long level
        cdef bint pushed
        for i in range(self.num_facts):
            self.zone[i] = 0
        self.zone[self.goal_fact] = 1
        self.zone_fact[0] = self.goal_fact
        self.zone_pos[0] = self.ach_start[self.goal_fact]
        top = 1
        while top:
            fact = self.zone_fact[top - 1]
            end = self.ach_start[fact + 1]
            pushed = False
            while self.zone_pos[top - 1] < end:
                op = self.ach_ops[self.zone_pos[top - 1]]
                self.zone_pos[top - 1] += 1
                if self.left[op] or self.sup[op] < 0:
                    continue
                level = self.sup_cost[op]
                for i in range(self.pre_list_start[op], self.pre_list_start[op + 1]):
                    condition = self.pre_list[i]
                    if self.hmax[condition] == level and (
                            self.zone[condition] or self._unreached_by_free(condition)):
                        if condition != self.sup[op]:
                            self.sup[op] = condition
                            self._support(condition, op)
                        break
                condition = self.sup[op]
                if not self.zone[condition]:
                    self.zone[condition] = 1
                    self.zone_fact[top] = condition
                    self.zone_pos[top] = self.ach_start[condition]
                    top += 1
                    pushed = True
                    break
            if not pushed:
                top -= 1
        return 0

    cdef int _cut(self, int num_start) except -1:
        """:meth:`.lmcut.LMCutEstimator._cut` into ``cut``; returns its length."""
        cdef int top = 0, count = 0, fact, op, effect, i, j
        cdef bint hits
        for i in range(self.num_facts):
            self.seen[i] = self.zone[i]
        for i in range(self.num_ops):
            self.in_cut[i] = 0
        for i in range(num_start):
            self.seen[self.facts[i]] = 1
        # ``zone_fact`` is free again: the depth-first stack of this search.
        for i in range(num_start):
            self.zone_fact[top] = self.facts[i]
            top += 1
        while top:
            top -= 1
            fact = self.zone_fact[top]
            for i in range(self.supported_len[fact]):
                op = self.supported[fact][i]
                if self.sup[op] != fact:
                    continue
                effect = self.only_effect[op]
                if effect >= 0:
                    if self.zone[effect]:
                        if not self.in_cut[op]:
                            self.in_cut[op] = 1
                            self.cut[count] = op
                            count += 1
                    elif not self.seen[effect]:
                        self.seen[effect] = 1
                        self.zone_fact[top] = effect
                        top += 1
                    continue
                hits = False
                for j in range(self.add_start[op], self.add_start[op + 1]):
                    if self.zone[self.add_facts[j]]:
                        hits = True
                        break
                if hits:
                    if not self.in_cut[op]:
                        self.in_cut[op] = 1
                        self.cut[count] = op
                        count += 1
                    continue
                for j in range(self.add_start[op], self.add_start[op + 1]):
                    effect = self.add_facts[j]
                    if not self.seen[effect]:
                        self.seen[effect] = 1
                        self.zone_fact[top] = effect
                        top += 1
        return count

    cdef int _lower_hmax(self, int count) except -1:
        """:meth:`.lmcut.LMCutEstimator._lower_hmax` for the ``count`` operators in ``cut``
        that have a supporter."""
        cdef Py_ssize_t size = 0, lowered = 0, k
        cdef u64 order = 0, key, boundary
        cdef int op, effect, fact, condition, best, i, j
        cdef long long level, reached, best_cost, old_cost
        for i in range(count):
            op = self.cut[i]
            self._lower(&lowered, self.sup_cost[op] + self.left[op], op)
        while True:
            for k in range(lowered):
                reached = self.lowered_value[k]
                op = self.lowered_op[k]
                for j in range(self.add_start[op], self.add_start[op + 1]):
                    effect = self.add_facts[j]
                    if reached < self.hmax[effect]:
                        self.hmax[effect] = reached
                        self._push(&size, &order, reached, effect, True)
            lowered = 0
            if not size:
                break
            # One level's facts as queued so far, then the decreases they cause.
            level = <long long> (self.heap[0] >> 32)
            boundary = order
            while size and <long long> (self.heap[0] >> 32) == level and (
                    self.heap[0] & LAST_ORDER) < boundary:
                key = self._pop(&size)
                fact = self.heap_fact[key & LAST_ORDER]
                if self.hmax[fact] != level:
                    continue
                for i in range(self.supported_len[fact]):
                    op = self.supported[fact][i]
                    if self.sup[op] != fact or self.sup_cost[op] <= level:
                        continue
                    best, best_cost = fact, level
                    for j in range(self.pre_list_start[op], self.pre_list_start[op + 1]):
                        condition = self.pre_list[j]
                        if self.hmax[condition] > best_cost:
                            best, best_cost = condition, self.hmax[condition]
                    old_cost = self.sup_cost[op]
                    if best != fact:
                        self.sup[op] = best
                        self._support(best, op)
                    self.sup_cost[op] = best_cost
                    if best_cost != old_cost:
                        self._lower(&lowered, best_cost + self.left[op], op)
        return 0

    def lmcut(self, state):
        """The LM-cut value of ``state`` (``math.inf`` at a relaxed dead end; goal states
        are the caller's)."""
        cdef int num_start = 0, i, j, op, count, more, bit, other
        cdef long long total = 0, cut_cost
        cdef bytes packed = state.to_bytes(self.num_bytes, "little")
        cdef const unsigned char* data = packed
        cdef unsigned char byte
        for i in range(self.num_bytes):
            byte = data[i]
            bit = 0
            while byte:
                if byte & 1:
                    self.facts[num_start] = i * 8 + bit
                    num_start += 1
                byte >>= 1
                bit += 1
        self.facts[num_start] = self.true_fact
        num_start += 1
        for i in range(self.num_ops):
            self.left[i] = self.op_cost[i]
            self.sup[i] = -1
            self.sup_cost[i] = 0
        self._max_explore(num_start)
        if self.hmax[self.goal_fact] == INFINITE:
            return math.inf
        for i in range(self.num_facts):
            self.supported_len[i] = 0
        for op in range(self.num_ops):
            if self.sup[op] >= 0:
                self._support(self.sup[op], op)
        while self.hmax[self.goal_fact]:
            self._goal_zone()
            count = self._cut(num_start)
            if not count:  # never with a goal still costing something: a bug, not a value
                raise RuntimeError("LM-cut: an empty cut in front of a goal zone")
            cut_cost = self.left[self.cut[0]]
            for i in range(1, count):
                if self.left[self.cut[i]] < cut_cost:
                    cut_cost = self.left[self.cut[i]]
            total += cut_cost
            if self.has_siblings:
                # Every relaxed operator of a cut operator's real operator, first seen first.
                for i in range(self.num_ops):
                    self.in_cut[i] = 0
                more = 0
                for i in range(count):
                    op = self.cut[i]
                    for j in range(self.sib_start[op], self.sib_start[op + 1]):
                        other = self.sib_ops[j]
                        if not self.in_cut[other]:
                            self.in_cut[other] = 1
                            self.cut_more[more] = other
                            more += 1
                for i in range(more):
                    self.cut[i] = self.cut_more[i]
                count = more
            for i in range(count):
                self.left[self.cut[i]] -= cut_cost
            more = 0
            for i in range(count):
                if self.sup[self.cut[i]] >= 0:
                    self.cut[more] = self.cut[i]
                    more += 1
            self._lower_hmax(more)
        return total
