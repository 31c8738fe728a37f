"""Shorter plans before learning: greedy action elimination (Fink & Yang 1992; Nakhost &
Müller 2010).

A MACROP inherits every detour of the plan it was learned from (the paper's six-step
"turn on the light" climbs on and off the box for nothing), and every later use pays for
it. For each step in turn, drop it and every later step that no longer applies; if the goal
still holds at the end, keep the shorter plan. The checks are the simulator's.
"""

from __future__ import annotations

from collections.abc import Sequence

from strips_framework.macrops.table import Step
from strips_framework.worldmodel.problem import Problem
from strips_framework.worldmodel.simulate import Simulator, State


def eliminate(problem: Problem, steps: Sequence[Step]) -> list[Step]:
    """``steps`` less the steps a valid plan can do without (the result is valid when
    ``steps`` is)."""
    simulator = Simulator(problem)
    plan = list(steps)
    i = 0
    while i < len(plan):
        shorter = _without(simulator, plan, i)
        if shorter is None:
            i += 1
        else:
            plan = shorter
    return plan


def _without(simulator: Simulator, plan: list[Step], skip: int) -> list[Step] | None:
    state: State = frozenset(simulator.problem.facts)
    kept: list[Step] = []
    for index, step in enumerate(plan):
        if index == skip:
            continue
        binding = step.binding()
        if index > skip and not simulator.holds(step.schema.precondition, binding,
                                                simulator.close(state)):
            continue
        state = simulator.apply(step.schema, binding, state)
        kept.append(step)
    if simulator.holds(simulator.problem.goal, {}, simulator.close(state)):
        return kept
    return None
