"""The delete relaxation of a ground task, laid out for fast per-state explorations.

Relaxed heuristics (hmax, hadd, hFF, LM-cut, landmarks) ignore delete effects and negative
preconditions; an axiom becomes a zero-cost relaxed operator from its positive body to its
head. A conditional effect becomes a relaxed operator of its own whose preconditions are
the operator's and the effect's condition, at the operator's cost, as in Fast Downward's
relaxation heuristics; such siblings share their operator's cost (hFF counts an operator
once, LM-cut lowers their costs together).

Everything is stored as flat lists indexed by relaxed-operator or fact number, so that an
exploration touches only Python lists and small ints: its inner loop runs once per
(fact, operator it is a precondition of) pair, and a counter per operator says when
all its preconditions are reached. Operators without preconditions get the artificial
fact :attr:`RelaxedTask.true_fact`, which holds in every state, so that explorations
need no special case for them.
"""

from __future__ import annotations

import math

from strips_evaluators.heuristics.causal_order import causal_order
from strips_evaluators.heuristics.factoring import factor_shared_pairs
from strips_framework.allocation import collection_paused
from strips_framework.grounding.task import GroundTask, facts_in
from strips_framework.records import Record

#: ``operator`` entry of a relaxed operator that comes from an axiom.
AXIOM = -1
#: ``operator`` entry of a conjunction made by :func:`factor_shared_pairs`.
CONJUNCTION = -2


class RelaxedTask(Record):
    """Relaxed operators ``0..len(pre)-1``: real operators with add effects and their
    conditional effects with adds (in task order), then axioms. Operators without add
    effects are left out: they reach nothing."""

    num_facts: int
    pre: list[tuple[int, ...]]
    add: list[tuple[int, ...]]
    cost: list[int]
    #: Index into ``task.operators``, or :data:`AXIOM` or :data:`CONJUNCTION` (negative).
    operator: list[int]
    #: Per relaxed operator, the facts a state must hold and lack for its effect to
    #: happen: the operator's preconditions and, for a conditional effect, its condition
    #: (none for axioms and conjunctions). Preferred operators are tested with them.
    #: Fact tuples rather than masks: a mask costs as much as the task has facts.
    need: list[tuple[int, ...]]
    lack: list[tuple[int, ...]]
    #: True when some operator has several relaxed operators (conditional effects).
    shared_costs: bool
    #: Number of preconditions of each relaxed operator: the template of the counters.
    pre_count: list[int]
    #: For each fact, the relaxed operators it is a precondition of.
    pre_of: list[list[int]]
    #: The artificial fact that holds in every state, precondition of the operators
    #: that have none.
    true_fact: int
    goal: tuple[int, ...]
    is_goal: list[bool]
    #: True when every operator costs 1 (axioms and conjunctions cost 0): breadth-first
    #: layers then suffice.
    unit_cost: bool
    #: hadd's per-operator accumulator, initial values: the cost so far in the high bits
    #: (the operator's own cost to start with), preconditions left in the low
    #: ``count_bits`` bits. One add per reached precondition updates both.
    accumulator: list[int]
    count_bits: int
    #: Per fact, its place in the order hadd's exploration pushes a state's facts in:
    #: causal-graph order (:mod:`.causal_order`), the always-true fact last.
    start_rank: list[int]

    __slots__ = (
        "num_facts",
        "pre",
        "add",
        "cost",
        "operator",
        "need",
        "lack",
        "shared_costs",
        "pre_count",
        "pre_of",
        "true_fact",
        "goal",
        "is_goal",
        "unit_cost",
        "accumulator",
        "count_bits",
        "start_rank",
    )

    def __init__(
        self,
        num_facts: int,
        pre: list[tuple[int, ...]],
        add: list[tuple[int, ...]],
        cost: list[int],
        operator: list[int],
        need: list[tuple[int, ...]],
        lack: list[tuple[int, ...]],
        shared_costs: bool,
        pre_count: list[int],
        pre_of: list[list[int]],
        true_fact: int,
        goal: tuple[int, ...],
        is_goal: list[bool],
        unit_cost: bool,
        accumulator: list[int],
        count_bits: int,
        start_rank: list[int],
    ) -> None:
        self.num_facts = num_facts
        self.pre = pre
        self.add = add
        self.cost = cost
        self.operator = operator
        self.need = need
        self.lack = lack
        self.shared_costs = shared_costs
        self.pre_count = pre_count
        self.pre_of = pre_of
        self.true_fact = true_fact
        self.goal = goal
        self.is_goal = is_goal
        self.unit_cost = unit_cost
        self.accumulator = accumulator
        self.count_bits = count_bits
        self.start_rank = start_rank


@collection_paused()
def relax(task: GroundTask, extra_facts: int = 0, factor_sharing: int = 0) -> RelaxedTask:
    """The relaxed task; ``extra_facts`` reserves fact numbers after the task's own and
    :attr:`RelaxedTask.true_fact` for artificial facts a heuristic adds. With
    ``factor_sharing`` > 0, precondition pairs shared by at least that many operators
    become conjunction facts (see :mod:`.factoring`)."""
    pre: list[tuple[int, ...]] = []
    add: list[tuple[int, ...]] = []
    cost: list[int] = []
    operator: list[int] = []
    need: list[tuple[int, ...]] = []
    lack: list[tuple[int, ...]] = []
    true_fact = len(task.facts)
    for index, op in enumerate(task.operators):
        if op.add:
            pre.append(_unique(op.pre) or (true_fact,))
            add.append(_unique(op.add))
            cost.append(op.cost)
            operator.append(index)
            need.append(op.pre)
            lack.append(op.pre_neg)
        for effect in op.effects:
            if effect.add:
                pre.append(_unique(op.pre + effect.condition) or (true_fact,))
                add.append(_unique(effect.add))
                cost.append(op.cost)
                operator.append(index)
                need.append(op.pre + effect.condition)
                lack.append(op.pre_neg + effect.condition_neg)
    shared_costs = len(set(operator)) < len(operator)
    for axiom in task.axioms:
        pre.append(_unique(axiom.body) or (true_fact,))
        add.append((axiom.head,))
        cost.append(0)
        operator.append(AXIOM)
        need.append(())
        lack.append(())
    num_facts = true_fact + 1 + extra_facts
    if factor_sharing:
        pre, conjunctions = factor_shared_pairs(pre, num_facts, factor_sharing)
        num_facts += len(conjunctions)
        pre.extend(conjunctions)
        add.extend((node,) for node in range(num_facts - len(conjunctions), num_facts))
        cost.extend(0 for _ in conjunctions)
        operator.extend(CONJUNCTION for _ in conjunctions)
        need.extend(() for _ in conjunctions)
        lack.extend(() for _ in conjunctions)
    pre_of: list[list[int]] = [[] for _ in range(num_facts)]
    for op, facts in enumerate(pre):
        for fact in facts:
            pre_of[fact].append(op)
    pre_count = [len(facts) for facts in pre]
    count_bits = max(pre_count, default=0).bit_length() + 1
    goal = _unique(task.goal)
    is_goal = [False] * num_facts
    for fact in goal:
        is_goal[fact] = True
    start_rank = list(range(num_facts))
    for rank, fact in enumerate(causal_order(task)):
        start_rank[fact] = rank
    return RelaxedTask(
        num_facts=num_facts,
        pre=pre,
        add=add,
        cost=cost,
        operator=operator,
        need=need,
        lack=lack,
        shared_costs=shared_costs,
        pre_count=pre_count,
        pre_of=pre_of,
        true_fact=true_fact,
        goal=goal,
        is_goal=is_goal,
        unit_cost=all(c == 1 for c, o in zip(cost, operator) if o >= 0),
        accumulator=[c << count_bits | n for c, n in zip(cost, pre_count)],
        count_bits=count_bits,
        start_rank=start_rank,
    )


def start_exploration(relaxed: RelaxedTask, state: int) -> tuple[list[int], list[float]]:
    """The facts an exploration starts from (those of ``state`` and the always-true fact:
    the cost-0 bucket) and the fact costs, 0 for them and ``math.inf`` for the others."""
    start = facts_in(state)
    start.append(relaxed.true_fact)
    cost: list[float] = [math.inf] * relaxed.num_facts
    for fact in start:
        cost[fact] = 0
    return start, cost


def _unique(facts: tuple[int, ...]) -> tuple[int, ...]:
    return tuple(dict.fromkeys(facts))
