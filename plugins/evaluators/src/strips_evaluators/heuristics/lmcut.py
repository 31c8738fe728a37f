"""The LM-cut heuristic (Helmert & Domshlak 2009), as Fast Downward computes it.

LM-cut finds disjunctive action landmarks one at a time and adds up their costs:

1. hmax with *supporters*: each operator's supporter is its costliest precondition
   (the last one reached). An artificial goal operator (cost 0) needs the goal facts and
   adds the artificial goal fact; operators without preconditions need an always-true fact.
2. The *goal zone*: facts from which the artificial goal is reached through zero-cost
   operators in the justification graph (supporter -> effect edges). A zero-cost
   operator's supporter may be changed here to a tied precondition on the zone's border
   or in it (Fast Downward's goal-zone and border detection, see ``_goal_zone``).
3. The *cut*: operators whose supporter is reachable from the state without entering the
   goal zone and that add a goal-zone fact. Every plan uses one of them (a landmark).
4. The cheapest cut operator's cost is added to h and taken off every cut operator; hmax
   is updated incrementally and the loop repeats until the goal's hmax is 0.

The landmarks are cost-disjoint (each operator's cost is shared out among them), so the
sum never exceeds the optimal plan cost: admissible.

Conditional effects are relaxed operators of their own (see :mod:`.relaxation`); a cut
then stands for the set of real operators its relaxed operators come from, every plan uses
one of them, and the cut's cost is taken off all relaxed operators of those operators.
That keeps the sum admissible (one application of an operator can cross several cuts
through different effects, but pays for them from one cost), as the basic extension of
Röger, Pommerening & Helmert (2014); Fast Downward's LM-cut refuses such tasks.

This module is the reference; ``_explore.LMCut`` computes the same values compiled, and
:meth:`LMCutHeuristic.for_task` takes it when it is built (``STRIPS_PURE_PYTHON=1``: the
reference).
"""

from __future__ import annotations

import math
from heapq import heappop, heappush
from typing import Any, ClassVar


from strips_evaluators.heuristics.exploration import compiled_module, max_exploration
from strips_evaluators.heuristics.relaxation import AXIOM, RelaxedTask, facts_in, relax
from strips_framework.grounding.task import GroundTask
from strips_framework.options import Configurable
from strips_framework.records import Record

NO_SUPPORTER = -1
#: ``only_effect`` entry of an operator with several add effects.
MANY_EFFECTS = -1


class LMCutEstimator(Record):
    """``relaxed`` ends with the artificial goal operator, which adds ``goal_fact``."""

    relaxed: RelaxedTask
    goal_mask: int
    goal_fact: int
    #: For each fact, the relaxed operators that add it.
    achievers: list[list[int]]
    #: Each operator's add effect when it has just one (most do), else MANY_EFFECTS:
    #: the cut search then needs no loop over effects.
    only_effect: list[int]
    #: Per relaxed operator, the relaxed operators of the same real operator (itself
    #: included), which share its cost; None when each real operator has one.
    siblings: list[tuple[int, ...]] | None

    __slots__ = ("relaxed", "goal_mask", "goal_fact", "achievers", "only_effect", "siblings")

    def __init__(
        self,
        relaxed: RelaxedTask,
        goal_mask: int,
        goal_fact: int,
        achievers: list[list[int]],
        only_effect: list[int],
        siblings: list[tuple[int, ...]] | None,
    ) -> None:
        self.relaxed = relaxed
        self.goal_mask = goal_mask
        self.goal_fact = goal_fact
        self.achievers = achievers
        self.only_effect = only_effect
        self.siblings = siblings

    def estimate_with_preferred(self, state: int) -> tuple[float, tuple[int, ...]]:
        return self.estimate(state), ()

    def estimate(self, state: int) -> float:
        if state & self.goal_mask == self.goal_mask:
            return 0
        relaxed, goal_fact = self.relaxed, self.goal_fact
        op_cost = relaxed.cost[:]
        supporter = [NO_SUPPORTER] * len(relaxed.pre)
        supporter_cost = [0] * len(relaxed.pre)
        hmax = max_exploration(relaxed, state, op_cost, supporter, supporter_cost)
        if hmax[goal_fact] == math.inf:
            return math.inf
        # The justification graph's edges out of each fact: the operators it supports.
        # Entries go stale when an operator changes supporter; users check supporter[op].
        supported: list[list[int]] = [[] for _ in range(relaxed.num_facts)]
        for op, fact in enumerate(supporter):
            if fact != NO_SUPPORTER:
                supported[fact].append(op)
        start = facts_in(state)
        start.append(relaxed.true_fact)
        total = 0
        while hmax[goal_fact]:
            goal_zone = self._goal_zone(hmax, op_cost, supporter, supporter_cost, supported)
            cut = self._cut(start, goal_zone, supporter, supported)
            cut_cost = min(op_cost[op] for op in cut)
            total += cut_cost
            siblings = self.siblings
            if siblings is not None:
                cut = list(dict.fromkeys(other for op in cut for other in siblings[op]))
            for op in cut:
                op_cost[op] -= cut_cost
            reached = [op for op in cut if supporter[op] != NO_SUPPORTER]
            self._lower_hmax(reached, hmax, op_cost, supporter, supporter_cost, supported)
        return total

    def _goal_zone(
        self,
        hmax: list[float],
        op_cost: list[int],
        supporter: list[int],
        supporter_cost: list[int],
        supported: list[list[int]],
    ) -> bytearray:
        """Facts from which the artificial goal is reached by zero-cost justifications,
        marked depth first from the goal as Fast Downward's ``mark_goal_plateau`` does.

        A zero-cost operator met on the way whose supporter ties (same hmax) with other
        preconditions first takes a tied one that no zero-cost operator adds (the
        *border*: the zone cannot grow past it) or one already in the zone (Fast
        Downward's goal-zone and border detection). Otherwise the first tied
        precondition, an accident of the exploration order, can pull facts behind
        zero-cost operators into the zone, and the cut in front of it comes out cheaper
        than need be: h stays admissible but lower (13 against 10 on elevators task01's
        initial state)."""
        achievers, pre = self.achievers, self.relaxed.pre
        zone = bytearray(self.relaxed.num_facts)
        zone[self.goal_fact] = 1
        # One iterator over a fact's achievers per level of the depth-first search, so
        # that after a subgoal's zone is marked its parent's loop continues where it was.
        stack = [iter(achievers[self.goal_fact])]
        while stack:
            for op in stack[-1]:
                if op_cost[op] or supporter[op] == NO_SUPPORTER:
                    continue
                level = supporter_cost[op]
                for condition in pre[op]:
                    if hmax[condition] == level and (
                        zone[condition] or all(op_cost[o] for o in achievers[condition])
                    ):
                        if condition != supporter[op]:
                            supporter[op] = condition
                            supported[condition].append(op)
                        break
                fact = supporter[op]
                if not zone[fact]:
                    zone[fact] = 1
                    stack.append(iter(achievers[fact]))
                    break
            else:
                stack.pop()
        return zone

    def _cut(
        self,
        start: list[int],
        goal_zone: bytearray,
        supporter: list[int],
        supported: list[list[int]],
    ) -> list[int]:
        """The operators whose supporter is reachable from ``start`` in the justification
        graph without entering the goal zone, and that add a goal-zone fact, each once
        (an operator that got back a former supporter is on its list twice)."""
        add, only_effect = self.relaxed.add, self.only_effect
        cut = []
        seen = bytearray(goal_zone)  # goal-zone facts are never entered
        stack = start[:]
        for fact in stack:
            seen[fact] = 1
        while stack:
            fact = stack.pop()
            for op in supported[fact]:
                if supporter[op] != fact:
                    continue
                effect = only_effect[op]
                if effect != MANY_EFFECTS:
                    if goal_zone[effect]:
                        cut.append(op)
                    elif not seen[effect]:
                        seen[effect] = 1
                        stack.append(effect)
                    continue
                effects = add[op]
                for effect in effects:
                    if goal_zone[effect]:
                        cut.append(op)
                        break
                else:
                    for effect in effects:
                        if not seen[effect]:
                            seen[effect] = 1
                            stack.append(effect)
        return list(dict.fromkeys(cut))

    def _lower_hmax(
        self,
        cut: list[int],
        hmax: list[float],
        op_cost: list[int],
        supporter: list[int],
        supporter_cost: list[int],
        supported: list[list[int]],
    ) -> None:
        """Propagate the decreases the cheaper ``cut`` operators cause: only operators whose
        supporter got cheaper can get cheaper, and then they may take a new supporter."""
        relaxed = self.relaxed
        pre, add = relaxed.pre, relaxed.add
        buckets: dict[int, list[int]] = {}
        levels: list[int] = []
        lowered = [(supporter_cost[op] + op_cost[op], add[op]) for op in cut]
        while lowered or levels:
            for reached, effects in lowered:
                for effect in effects:
                    if reached < hmax[effect]:
                        hmax[effect] = reached
                        bucket = buckets.setdefault(reached, [])
                        if not bucket:
                            heappush(levels, reached)
                        bucket.append(effect)
            lowered = []
            if not levels:
                break
            level = heappop(levels)
            for fact in buckets.pop(level):
                if hmax[fact] != level:
                    continue
                for op in supported[fact]:
                    if supporter[op] != fact or supporter_cost[op] <= level:
                        continue
                    best, best_cost = fact, level
                    for condition in pre[op]:
                        if hmax[condition] > best_cost:
                            best, best_cost = condition, hmax[condition]
                    old_cost = supporter_cost[op]
                    if best != fact:
                        supporter[op] = best
                        supported[best].append(op)
                    supporter_cost[op] = best_cost
                    if best_cost != old_cost:
                        lowered.append((best_cost + op_cost[op], add[op]))


class CompiledLMCutEstimator(Record):
    """LM-cut by the compiled ``_explore.LMCut``: the values of :class:`LMCutEstimator`
    (``tests/test_compiled.py`` compares them), several times faster."""

    lmcut: Any
    goal_mask: int

    __slots__ = ("lmcut", "goal_mask")

    def __init__(self, lmcut: Any, goal_mask: int) -> None:
        self.lmcut = lmcut
        self.goal_mask = goal_mask

    def estimate_with_preferred(self, state: int) -> tuple[float, tuple[int, ...]]:
        return self.estimate(state), ()

    def estimate(self, state: int) -> float:
        if state & self.goal_mask == self.goal_mask:
            return 0
        return self.lmcut.lmcut(state)


class LMCutHeuristic(Configurable):
    """LM-cut (Helmert & Domshlak 2009): sum of cost-disjoint landmark costs. Admissible.

    The action landmarks are found by repeated hmax cuts. Always >= hmax, and the
    heuristic of choice for optimal A*. Each state costs a few hmax explorations (one per
    landmark, incremental after the first); no preferred operators."""

    name: ClassVar[str] = "lmcut"
    admissible: ClassVar[bool] = True

    def for_task(
        self, task: GroundTask, compiled: bool | None = None
    ) -> LMCutEstimator | CompiledLMCutEstimator:
        """The estimator for ``task``: the compiled one when it is built (see
        :func:`~.exploration.compiled_module`; ``compiled=False`` gives the reference)."""
        relaxed = relax(task, extra_facts=1)
        goal_fact = relaxed.true_fact + 1
        goal_op = len(relaxed.pre)
        pre_of = [ops[:] for ops in relaxed.pre_of]
        for fact in relaxed.goal:
            pre_of[fact].append(goal_op)
        relaxed = relaxed._replace(
            pre=[*relaxed.pre, relaxed.goal],
            add=[*relaxed.add, (goal_fact,)],
            cost=[*relaxed.cost, 0],
            operator=[*relaxed.operator, AXIOM],
            need=[*relaxed.need, ()],
            lack=[*relaxed.lack, ()],
            pre_count=[*relaxed.pre_count, len(relaxed.goal)],
            pre_of=pre_of,
        )
        achievers: list[list[int]] = [[] for _ in range(relaxed.num_facts)]
        for op, effects in enumerate(relaxed.add):
            for fact in effects:
                achievers[fact].append(op)
        only_effect = [effects[0] if len(effects) == 1 else MANY_EFFECTS for effects in relaxed.add]
        siblings = None
        if relaxed.shared_costs:
            of_operator: dict[int, list[int]] = {}
            for op, index in enumerate(relaxed.operator):
                of_operator.setdefault(index, []).append(op)
            siblings = [
                tuple(of_operator[index]) if index >= 0 else (op,)
                for op, index in enumerate(relaxed.operator)
            ]
        module = compiled_module(compiled)
        if module is not None:
            lmcut = module.LMCut(relaxed, goal_fact, achievers, only_effect, siblings)
            return CompiledLMCutEstimator(lmcut, task.goal_mask)
        return LMCutEstimator(relaxed, task.goal_mask, goal_fact, achievers, only_effect, siblings)
