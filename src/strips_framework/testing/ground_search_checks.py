"""Checks of a ground-task strategy on the kit's PDDL tasks, with installed heuristics.

A run goes through :meth:`~strips_framework.planner.Planner.solve_task` like a user's
PDDL run after grounding, so the config-time capability check applies. Every plan is
checked by the lifted validator (:mod:`strips_framework.pddl.validate`), which shares
nothing with the grounder or the search but the reader; its cost is compared with the
exact optimum of :mod:`~strips_framework.testing.ground_space` when the strategy declares
``optimal`` and the heuristic ``admissible``.
"""

from __future__ import annotations

import warnings
from collections.abc import Mapping
from types import MappingProxyType
from typing import Any

from strips_framework.capabilities import ADMISSIBLE, OPTIMAL, declared
from strips_framework.pddl.validate import validate_plan
from strips_framework.planner import GROUND_STRATEGY, Planner
from strips_framework.result import Result, Status
from strips_framework.testing.declaration import ConformanceFailure
from strips_framework.testing.ground_tasks import UNSOLVABLE as UNSOLVABLE_TASK
from strips_framework.testing.ground_tasks import ground_task, pddl_task, task_space
from strips_framework.testing.search_checks import planner_for

#: Limits of a kit run: each task has at most a few hundred reachable states.
TASK_LIMITS: Mapping[str, float] = MappingProxyType({"time": 120, "expansions": 10_000})


def ground_planner(
    kind: str,
    cls: type,
    choices: Mapping[str, str],
    options: Mapping[str, Any] = MappingProxyType({}),
    limits: Mapping[str, float] = TASK_LIMITS,
) -> Planner:
    """:func:`~strips_framework.testing.search_checks.planner_for` with the kit's task
    limits. The warning an optimal strategy gives with an inadmissible heuristic is
    expected here: the kit runs every pairing on purpose."""
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", message=".* needs a state heuristic with 'admissible'")
        return planner_for(kind, cls, choices, options, limits)


def solve_task(planner: Planner, name: str) -> Result:
    """Kit task ``name`` searched by the planner's strategy and heuristic."""
    return planner.solve_task(ground_task(name))


def check_solves_task(planner: Planner, name: str) -> Result:
    """The planner solves kit task ``name`` (unless its strategy says it is incomplete and
    reports so), with a plan the lifted validator accepts at the cost the strategy
    reports; an 'optimal' strategy with an 'admissible' heuristic finds a cheapest plan."""
    result = solve_task(planner, name)
    what = _describe(planner, name)
    strategy = _chosen(planner, GROUND_STRATEGY)
    if not result.solved:
        if result.status == Status.EXHAUSTED and not getattr(strategy, "complete", True):
            return result
        raise ConformanceFailure(
            f"{what}: {result.status} after {result.statistics.expanded} expansions; the task "
            f"has a plan of cost {task_space(name).optimum}"
        )
    plan = list(result.plan or ())
    check = validate_plan(pddl_task(name), plan)
    if not check.valid:
        raise ConformanceFailure(f"{what}: the plan {plan} is not valid: {check.message}")
    if check.cost != result.cost:
        raise ConformanceFailure(
            f"{what}: reports cost {result.cost} for a plan that costs {check.cost}: {plan}"
        )
    heuristic = _chosen(planner, "heuristic")
    if OPTIMAL in (declared(strategy, GROUND_STRATEGY) or ()) and ADMISSIBLE in (
        declared(heuristic, "heuristic") or ()
    ):
        optimum = task_space(name).optimum
        if check.cost != optimum:
            raise ConformanceFailure(
                f"{what}: a plan of cost {check.cost} {plan}, but the cheapest costs {optimum}; "
                "an 'optimal' strategy with an 'admissible' heuristic must find one"
            )
    return result


def check_unsolvable(planner: Planner) -> Result:
    """On the kit's unsolvable task the strategy returns no plan and says why: a complete
    strategy that it ran out of states ('unsolvable'), an incomplete one may say it gave
    up ('exhausted')."""
    result = solve_task(planner, UNSOLVABLE_TASK)
    strategy = _chosen(planner, GROUND_STRATEGY)
    expected = (
        {Status.UNSOLVABLE}
        if getattr(strategy, "complete", True)
        else {Status.UNSOLVABLE, Status.EXHAUSTED}
    )
    if result.status not in expected or result.plan is not None:
        raise ConformanceFailure(
            f"{_describe(planner, UNSOLVABLE_TASK)}: status {result.status!r} with plan "
            f"{result.plan}; the task has no plan, so expected {sorted(expected)} and none"
        )
    return result


def check_expansion_limit(planner: Planner, name: str, unlimited: Result) -> Result:
    """With the planner's expansion limit (``[limits] expansions``), kit task ``name`` is
    searched again: it must stop within the limit, and say so ('expansion-limit') when the
    ``unlimited`` run of the same strategy and heuristic needed more."""
    limit = planner.config.limits.expansions
    assert limit is not None, "the planner must have an expansion limit"
    result = solve_task(planner, name)
    expanded = result.statistics.expanded
    if expanded > limit or (
        unlimited.statistics.expanded > limit and result.status != Status.EXPANSION_LIMIT
    ):
        raise ConformanceFailure(
            f"{_describe(planner, name)} with expansions = {limit}: status {result.status!r} "
            f"after {expanded} expansions (without the limit: {unlimited.status!r} after "
            f"{unlimited.statistics.expanded}); expected {Status.EXPANSION_LIMIT!r} within the limit"
        )
    return result


def _chosen(planner: Planner, kind: str) -> type:
    return planner.registry.get(kind, planner.config.choice(kind).name).cls


def _describe(planner: Planner, name: str) -> str:
    choices = planner.config.choices
    return (
        f"strategy {choices['strategy'].name!r}, heuristic {choices['heuristic'].name!r} on {name}"
    )
