"""Per-state relaxed explorations of a lifted task: hadd and hmax fact costs with best
supporters, by a generalized Dijkstra over ground facts whose rule instances are found by
semi-naive joins (see :mod:`.program`).

This is the pure-Python reference. A fact's cost is final when it leaves the queue
(*settled*); it then joins the indexes the plans look facts up in, and every plan it
triggers is joined with the facts settled so far, so each rule instance is found exactly
once, when its last body fact is settled, with every body cost final. As in the ground
explorations (:mod:`strips_evaluators.heuristics.exploration`) the search stops once every
goal fact is settled, so the goal's values equal the ground heuristics' on the grounded
task; the supporter of a fact is the first instance to reach its final cost.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Collection
from heapq import heappop, heappush
from itertools import product

from strips_evaluators.lifted.matching import CompiledPlan, compiled
from strips_evaluators.lifted.program import AXIOM, Plan, Rule, RuleProgram
from strips_framework.lifted.components import ActionInstance, GroundAtom

#: A rule instance that achieved a fact: the rule, its fluent body facts, its slots.
Supporter = tuple[Rule, tuple[GroundAtom, ...], tuple[str, ...]]
Index = dict[tuple[str, ...], list[GroundAtom]]


class Exploration:
    """The explorations of one task; :meth:`costs` runs one per state."""

    def __init__(self, program: RuleProgram) -> None:
        self.program = program
        #: Instances of rules without fluent body atoms, the same in every state:
        #: ``(cost, heads, supporter)``.
        self.unconditional: list[tuple[int, list[GroundAtom], Supporter]] = []
        for plan in program.unconditional:
            join(program, plan, None, {}, self._collect)
        #: The plans each predicate triggers, with their compiled tests (but for rules
        #: without heads, such as an action whose adds are all conditional: they reach
        #: nothing).
        self._triggers: dict[str, list[tuple[Plan, CompiledPlan]]] = {
            predicate: [(plan, compiled(program, plan)) for plan in plans if plan.rule.heads]
            for predicate, plans in program.triggers.items()
        }

    def _collect(self, plan: Plan, slots: list[str], matched: list[GroundAtom]) -> None:
        rule = plan.rule
        heads = [(name, *[slots[s] for s in terms]) for name, terms in rule.heads]
        self.unconditional.append(
            (self.program.cost_of(rule, slots), heads, (rule, (), tuple(slots)))
        )

    def costs(
        self,
        state: Collection[GroundAtom],
        additive: bool,
        until: Collection[GroundAtom] | None = None,
    ) -> tuple[dict[GroundAtom, float], dict[GroundAtom, Supporter]]:
        """The hadd (``additive``) or hmax costs of the facts reached before every fact
        of ``until`` (by default the goal's) is settled, and their best supporters (none
        for the state's facts); with an empty ``until``, of every fact reachable."""
        program = self.program
        cost: dict[GroundAtom, float] = {}
        supporter: dict[GroundAtom, Supporter] = {}
        # The queue: facts by cost, first in first out within a cost, and a heap of the
        # costs that have facts (comparing costs, not facts: ties are the rule here).
        buckets: dict[float, list[GroundAtom]] = {0: sorted(state)}
        keys: list[float] = [0]
        for fact in buckets[0]:
            cost[fact] = 0
        for value, heads, support in self.unconditional:
            for head in heads:
                if value < cost.get(head, math.inf):
                    cost[head] = value
                    supporter[head] = support
                    bucket = buckets.get(value)
                    if bucket is None:
                        buckets[value] = [head]
                        heappush(keys, value)
                    else:
                        bucket.append(head)
        indexes: dict[str, list[tuple[tuple[int, ...], Index]]] = {
            predicate: [(positions, {}) for positions in all_positions]
            for predicate, all_positions in program.fluent_indexes.items()
        }
        lookup: dict[tuple[str, tuple[int, ...]], Index] = {
            (predicate, positions): index
            for predicate, pairs in indexes.items()
            for positions, index in pairs
        }
        goal = set(program.fluent_goal if until is None else until)
        if until is None and not goal:
            return cost, supporter  # nothing to reach
        goals_left = len(goal) if goal else -1  # -1: never counts down to 0

        triggers = self._triggers

        cost_get = cost.get
        cost_of = program.cost_of
        inf = math.inf
        # No fact dearer than every goal fact's cost so far is settled before the
        # exploration stops: instances above it are not completed.
        limit = max([cost_get(fact, inf) for fact in goal]) if goal else inf
        unreached = sum(1 for fact in goal if fact not in cost)  # (limit is inf until 0)

        def fire(plan: Plan, slots: list[str], matched: list[GroundAtom], body: float) -> float:
            nonlocal limit, unreached
            rule = plan.rule
            value = body + (rule.cost if rule.cost is not None else cost_of(rule, slots))
            support = None  # made once, for the first head it improves
            for make in rule.makers:
                head = make(slots)
                old = cost_get(head)
                if old is None or value < old:
                    if support is None:
                        support = (rule, tuple(matched), tuple(slots))
                    cost[head] = value
                    supporter[head] = support
                    bucket = buckets.get(value)
                    if bucket is None:
                        buckets[value] = [head]
                        heappush(keys, value)
                    else:
                        bucket.append(head)
                    if head in goal and (old is None or old == limit):
                        # the dearest goal fact got cheaper, or the last one was reached
                        unreached -= old is None
                        if not unreached:
                            limit = max([cost_get(fact, inf) for fact in goal])
            return value

        while keys:
            value = keys[0]
            bucket = buckets[value]
            done = 0
            while done < len(bucket):  # zero-cost rules add to it as it is read
                fact = bucket[done]
                done += 1
                if cost[fact] != value:
                    continue  # reached more cheaply after it was queued
                if fact in goal:
                    goals_left -= 1
                    if not goals_left:
                        return cost, supporter
                predicate = fact[0]
                for positions, index in indexes.get(predicate, ()):
                    key = tuple([fact[i] for i in positions])
                    found = index.get(key)
                    if found is None:
                        index[key] = [fact]
                    else:
                        found.append(fact)
                for plan, functions in triggers.get(predicate, ()):
                    costed_join(program, plan, fact, lookup, cost, fire, functions, additive, limit)
            del buckets[value]
            heappop(keys)
        return cost, supporter


def join(
    program: RuleProgram,
    plan: Plan,
    fact: GroundAtom | None,
    lookup: dict[tuple[str, tuple[int, ...]], Index],
    emit: Callable[[Plan, list, list[GroundAtom]], None],
    functions: CompiledPlan | None = None,
) -> None:
    """Every completion of ``plan`` with its trigger bound to ``fact`` (no trigger when
    None), fluent atoms matched in ``lookup`` (indexes by ``(predicate, positions)``):
    ``emit(plan, slots, matched)`` with the fluent facts matched, trigger first. Each
    candidate fact is matched by the step's compiled function (``functions``, made
    here when not given: :mod:`.matching`)."""
    if functions is None:
        functions = compiled(program, plan)
    slots: list = list(plan.rule.template)
    for slot, value in functions.preset:
        slots[slot] = value
    matched: list[GroundAtom] = []
    if fact is not None:
        if not functions.trigger(fact, slots):  # type: ignore[misc]
            return
        matched.append(fact)
    steps = plan.steps
    final = functions.final
    free = functions.free
    if not steps and not free:  # one atom: nothing to join
        if final is None or final(slots):
            emit(plan, slots, matched)
        return
    matchers = functions.steps
    last = len(steps)
    static_indexes = program.static_indexes
    simple = not free and final is None
    probes = plan.probes

    def extend(depth: int) -> None:
        if depth == last:
            if simple:
                emit(plan, slots, matched)
            elif not free:
                if final(slots):  # type: ignore[misc]
                    emit(plan, slots, matched)
            else:  # every assignment of the free slots over their types' objects
                for values in product(*functions.domains):
                    for slot, value in zip(free, values):
                        slots[slot] = value
                    if final is None or final(slots):
                        emit(plan, slots, matched)
            return
        for later in probes[depth]:
            probe = steps[later]
            index = lookup.get((probe.predicate, probe.positions))
            if not index or tuple([slots[s] for s in probe.key]) not in index:
                return
        step = steps[depth]
        where = (step.predicate, step.positions)
        index = lookup.get(where) if step.fluent else static_indexes[where]
        if not index:
            return
        candidates = index.get(tuple([slots[s] for s in step.key]))
        if not candidates:
            return
        match = matchers[depth]
        skip = fact if step.before_trigger else None
        if step.fluent:
            for candidate in candidates:
                if candidate is not skip and candidate != skip and match(candidate, slots):
                    matched.append(candidate)
                    extend(depth + 1)
                    matched.pop()
        else:
            for candidate in candidates:
                if match(candidate, slots):
                    extend(depth + 1)

    extend(0)


def costed_join(
    program: RuleProgram,
    plan: Plan,
    fact: GroundAtom,
    lookup: dict[tuple[str, tuple[int, ...]], Index],
    cost: dict[GroundAtom, float],
    fire: Callable[[Plan, list, list[GroundAtom], float], float],
    functions: CompiledPlan,
    additive: bool,
    limit: float = math.inf,
) -> None:
    """The completions of ``plan`` with its trigger bound to ``fact`` that improve the
    cost of one of their heads: ``fire(plan, slots, matched, body)`` with ``body`` the
    sum (``additive``) or maximum of the costs of the distinct fluent facts matched, which
    returns the instance's value. The join is :func:`join`'s, with branch and bound: a
    partial binding's body cost only grows as it is completed, so once its heads are bound
    (``plan.heads_at``) a branch whose cost plus the rule's constant cost reaches the
    dearest head's cost so far cannot improve any head, and is cut. That keeps the
    values exact, and only the cheapest of the instances that share heads is completed
    (organic synthesis: thousands of instances per head, one relabelling of the
    molecule's substituents each). Branches whose value would exceed ``limit`` are cut
    too."""
    rule = plan.rule
    slots: list = list(rule.template)
    for slot, value in functions.preset:
        slots[slot] = value
    if not functions.trigger(fact, slots):  # type: ignore[misc]
        return
    matched = [fact]
    base = rule.cost or 0  # a cost per instance is at least 0
    makers = rule.makers
    steps = plan.steps
    final = functions.final
    free = functions.free
    # Heads bound only by the last step: ``fire`` compares them, a cap would again.
    heads_at = plan.heads_at if plan.heads_at < len(plan.steps) else math.inf
    inf = math.inf
    cost_get = cost.get
    start = cost[fact]
    above = limit - base  # a body dearer than this is cut
    if start > above:
        return
    if not steps and not free:  # one atom: nothing to join (``fire`` compares the heads)
        if final is None or final(slots):
            fire(plan, slots, matched, start)
        return
    matchers = functions.steps
    last = len(steps)
    static_indexes = program.static_indexes
    probes = plan.probes
    repeated = rule.repeated_predicates
    domains = functions.domains

    def extend(depth: int, body: float, cap: float) -> float:
        """Completes the binding of ``steps[:depth]`` at cost ``body``; returns ``cap``,
        the cost at or above which a completion improves no head, as the completions
        left it (meaningful once the heads are bound)."""
        if depth == heads_at:
            cap = max([cost_get(make(slots), inf) for make in makers])
            if base + body >= cap:
                return cap
        if depth == last:
            if not free:
                if final is None or final(slots):
                    value = fire(plan, slots, matched, body)
                    if value < cap:  # noqa: PLR1730 (min() is a call, here per instance)
                        cap = value
            else:  # every assignment of the free slots over their types' objects
                for values in product(*domains):
                    for slot, value in zip(free, values):
                        slots[slot] = value
                    if final is not None and not final(slots):
                        continue
                    if base + body < cap:
                        value = fire(plan, slots, matched, body)
                        if value < cap and heads_at < last:  # else free slots vary heads
                            cap = value
            return cap
        for later in probes[depth]:
            probe = steps[later]
            index = lookup.get((probe.predicate, probe.positions))
            if not index or tuple([slots[s] for s in probe.key]) not in index:
                return cap
        step = steps[depth]
        where = (step.predicate, step.positions)
        index = lookup.get(where) if step.fluent else static_indexes[where]
        if not index:
            return cap
        candidates = index.get(tuple([slots[s] for s in step.key]))
        if not candidates:
            return cap
        match = matchers[depth]
        keep = depth >= heads_at  # the children's cap holds for this binding's heads too
        if step.fluent:
            skip = fact if step.before_trigger else None
            for candidate in candidates:
                if candidate is skip or candidate == skip:
                    continue
                if repeated and candidate in matched:
                    more = body  # the instance's body is a set: counted once
                elif additive:
                    more = body + cost[candidate]
                else:
                    more = max(body, cost[candidate])
                if more > above or base + more >= cap or not match(candidate, slots):
                    continue
                matched.append(candidate)
                found = extend(depth + 1, more, cap)
                matched.pop()
                if keep:
                    cap = found
        else:
            for candidate in candidates:
                if match(candidate, slots):
                    found = extend(depth + 1, body, cap)
                    if keep:
                        cap = found
        return cap

    extend(0, start, inf)


def relaxed_plan(
    program: RuleProgram,
    cost: dict[GroundAtom, float],
    supporter: dict[GroundAtom, Supporter],
    goal: Collection[GroundAtom] | None = None,
    achieved: set[GroundAtom] | None = None,
) -> tuple[float, dict[tuple, Supporter]]:
    """hFF: the cost of the relaxed plan the best supporters give, walking back from the
    goal (by default the task's), and its rule instances by ``(rule number, slots)``; a
    ground operator used for several of its effects counts once (as in the ground hFF).
    ``achieved``, when given, receives the facts the plan achieves: each subgoal it
    found a supporter for (derived and auxiliary facts among them)."""
    if goal is None:
        goal = program.fluent_goal
    if program.static_goal_missing or any(fact not in cost for fact in goal):
        return math.inf, {}
    plan: dict[tuple, Supporter] = {}
    operators: dict[tuple, int] = {}
    subgoals = list(goal)
    while subgoals:
        subgoal = subgoals.pop()
        support = supporter.get(subgoal)
        if support is None:
            continue
        if achieved is not None:
            achieved.add(subgoal)
        if support[0].parts:
            support = expand(support, supporter)
        rule, body, slots = support
        if rule.aliases:  # the variables merged into another term take its value
            full = list(slots)
            for slot, other in rule.aliases:
                full[slot] = full[other]
            slots = tuple(full)
            support = (rule, body, slots)
        key = (rule.number, slots)
        if key in plan:
            continue
        plan[key] = support
        if rule.action != AXIOM:
            identity = (rule.action, rule.operator, slots[: rule.identity])
            operators[identity] = program.cost_of(rule, list(slots))
        subgoals.extend(body)
    return sum(operators.values()), plan


def expand(support: Supporter, supporter: dict[GroundAtom, Supporter]) -> Supporter:
    """The instance of the unsplit rule behind ``support`` of a split rule (see
    :meth:`.program.Program._add_split`): its auxiliary body facts replaced by their
    parts' body facts, and the slots the parts bound filled in from their supporters."""
    rule, body, slots = support
    if not rule.parts:
        return support
    full = list(slots)
    facts: list[GroundAtom] = []
    for fact in body:
        pairs = rule.parts.get(fact[0])
        if pairs is None:
            facts.append(fact)
            continue
        _, part_body, part_slots = expand(supporter[fact], supporter)
        for part_slot, rule_slot in pairs:
            full[rule_slot] = part_slots[part_slot]
        facts.extend(part_body)
    return rule, tuple(facts), tuple(full)


def action_instance(program: RuleProgram, rule: Rule, slots: tuple[str, ...]) -> ActionInstance:
    return program.action_names[rule.action], slots[: rule.arity]
