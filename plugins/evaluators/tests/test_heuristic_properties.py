"""Properties every heuristic must have, checked on every reachable state of small tasks
against the true cost to the goal (a backward Dijkstra over the explicit state space).

The tasks are IPC first tasks (grounded from PDDL) and seeded random tasks with action
costs (zero-cost operators included), negative preconditions and axioms, half of them with
conditional effects.
"""

from __future__ import annotations

import math

import pytest
from random_tasks import random_task
from shared_bench import small_bench

from strips_evaluators import plugin
from strips_evaluators.heuristics.exploration import (
    additive_exploration,
    max_exploration,
    unit_cost_hmax,
)
from strips_evaluators.heuristics.relaxation import RelaxedTask, relax
from strips_framework.grounding import ground
from strips_framework.grounding.task import GroundTask
from strips_framework.limits import Limits
from strips_framework.pddl import find_domain, load_task
from strips_framework.plugin.registry import Registry
from strips_framework.testing.ground_space import TaskSpace

IPC = small_bench("ipc")  # ../shared, or the repository's copy of the tasks named here
PDDL_DOMAINS = ["blocks", "gripper", "depot", "zenotravel", "transport", "miconic", "pegsol"]
# This plugin's state heuristics and the core's builtin blind one, as a run finds them.
_REGISTRY = Registry.from_plugins()
HEURISTICS = {name: _REGISTRY.get("heuristic", name).cls for name in _REGISTRY.names("heuristic")}


def ipc_task(domain: str) -> GroundTask:
    problem = IPC / domain / "task01.pddl"
    return ground(load_task(find_domain(problem), problem))


def optimal_costs(task: GroundTask) -> dict[int, float]:
    """h* of every state reachable from the initial state (``math.inf``: dead end), from
    the conformance kit's exhaustive exploration."""
    return TaskSpace(task, max_states=1_000_000).cost_to_go


#: Unit-cost tasks without negative conditions (the IPC first tasks are such).
PLAIN_TASKS = [
    *(f"ipc:{domain}" for domain in PDDL_DOMAINS),
    *(f"plain:{seed}" for seed in range(20)),
]
TASKS = [
    *PLAIN_TASKS,
    *(f"random:{seed}" for seed in range(40)),
    *(f"conditional:{seed}" for seed in range(40)),
]


@pytest.fixture(scope="module", params=TASKS)
def task_and_costs(request) -> tuple[GroundTask, dict[int, float]]:
    kind, name = request.param.split(":")
    if kind == "ipc":
        task = ipc_task(name)
    else:
        task = random_task(int(name), conditional=kind == "conditional", plain=kind == "plain")
    return task, optimal_costs(task)


def values(task: GroundTask, name: str, states) -> dict[int, float]:
    estimator = HEURISTICS[name]().for_task(task)
    return {state: estimator.estimate(state) for state in states}


def test_admissible_heuristics_never_overestimate(task_and_costs) -> None:
    task, optimal = task_and_costs
    for name, cls in HEURISTICS.items():
        if cls.admissible:
            for state, value in values(task, name, optimal).items():
                assert value <= optimal[state], (name, task.facts_of(state))


def test_dead_ends_are_real_and_goals_score_zero(task_and_costs) -> None:
    task, optimal = task_and_costs
    for name in HEURISTICS:
        for state, value in values(task, name, optimal).items():
            if value == math.inf:
                assert optimal[state] == math.inf, (name, task.facts_of(state))
            if task.is_goal(state):
                assert value == 0, name


def test_relaxation_bounds_are_ordered(task_and_costs) -> None:
    """hmax <= LM-cut <= h+ <= hFF, and hmax <= hadd; all relaxed heuristics agree on
    which states are relaxed dead ends. With conditional effects LM-cut can fall below
    hmax (a cut lowers the cost of its operators' other effects too), not below 0."""
    task, optimal = task_and_costs
    h = {name: values(task, name, optimal) for name in ("hmax", "hadd", "ff", "lmcut")}
    conditional = any(op.effects for op in task.operators)
    for state in optimal:
        assert h["lmcut"][state] <= h["ff"][state], task.facts_of(state)
        assert conditional or h["hmax"][state] <= h["lmcut"][state], task.facts_of(state)
        assert h["hmax"][state] <= h["hadd"][state]
        assert len({h[name][state] == math.inf for name in h}) == 1


def test_preferred_operators_are_applicable_and_come_with_the_estimate(task_and_costs) -> None:
    task, optimal = task_and_costs
    for name, cls in HEURISTICS.items():
        estimator = cls().for_task(task)
        for state in optimal:
            value, preferred = estimator.estimate_with_preferred(state)
            assert value == estimator.estimate(state)
            assert list(preferred) == sorted(set(preferred))
            assert all(task.operators[i].applicable(state) for i in preferred), name


@pytest.mark.parametrize("task_and_costs", PLAIN_TASKS, indirect=True)
def test_ff_prefers_some_operator_unless_at_a_goal_or_dead_end(task_and_costs) -> None:
    """Without negative conditions, a relaxed plan always starts with an operator that
    is applicable in the state."""
    task, optimal = task_and_costs
    assert not any(op.pre_neg or any(e.condition_neg for e in op.effects) for op in task.operators)
    estimator = HEURISTICS["ff"]().for_task(task)
    for state in optimal:
        value, preferred = estimator.estimate_with_preferred(state)
        assert bool(preferred) == (0 < value < math.inf)


@pytest.mark.parametrize("task_and_costs", PLAIN_TASKS, indirect=True)
def test_unit_cost_layers_agree_with_the_dijkstra_exploration(task_and_costs) -> None:
    task, optimal = task_and_costs
    relaxed = relax(task)
    assert relaxed.unit_cost
    unused = [0] * len(relaxed.pre)
    for state in optimal:
        cost = max_exploration(relaxed, state, relaxed.cost, unused, unused[:])
        expected = max(cost[fact] for fact in relaxed.goal)
        assert unit_cost_hmax(relaxed, state) == expected


@pytest.mark.parametrize("heuristic", ["lmcut", "hmax", "blind"])
def test_astar_with_an_admissible_heuristic_finds_optimal_plans(task_and_costs, heuristic) -> None:
    """A* (the search helper's, from the registry) with each admissible heuristic returns
    a plan of the optimal cost, or proves the task unsolvable."""
    task, optimal = task_and_costs
    strategy = Registry.from_plugins().get("ground-strategy", "astar").cls()
    estimator = HEURISTICS[heuristic]().for_task(task)
    result = strategy.search_task(task, estimator, Limits(time=60))
    if optimal[task.init] == math.inf:
        assert not result.solved
    else:
        assert result.solved and result.cost == optimal[task.init]


def relaxed_values(relaxed: RelaxedTask, state: int) -> tuple[float, float]:
    """hadd and hmax of ``state`` in ``relaxed``."""
    cost, _ = additive_exploration(relaxed, state)
    unused = [0] * len(relaxed.pre)
    highest = max_exploration(relaxed, state, relaxed.cost, unused, unused[:])
    return sum(cost[fact] for fact in relaxed.goal), max(highest[f] for f in relaxed.goal)


def test_factoring_shared_preconditions_keeps_hmax_and_hadd(task_and_costs) -> None:
    """Even factoring every pair shared by two operators changes no hmax or hadd value."""
    task, optimal = task_and_costs
    plain, factored = relax(task), relax(task, factor_sharing=2)
    for state in optimal:
        assert relaxed_values(factored, state) == relaxed_values(plain, state)


@pytest.mark.parametrize("domain", ["depot", "transport"])
def test_lmcut_stays_between_hmax_and_ff_on_larger_tasks(domain) -> None:
    """States where LM-cut's incremental hmax moves operators back to a former supporter
    (the second tasks of these domains have many)."""
    problem = IPC / domain / "task02.pddl"
    task = ground(load_task(find_domain(problem), problem))
    estimators = {name: HEURISTICS[name]().for_task(task) for name in ("hmax", "lmcut", "ff")}
    states, frontier = {task.init}, [task.init]
    while frontier and len(states) < 400:
        state = frontier.pop(0)
        h = {name: estimator.estimate(state) for name, estimator in estimators.items()}
        assert h["hmax"] <= h["lmcut"] <= h["ff"], task.facts_of(state)
        for op in task.operators:
            if op.applicable(state) and op.apply(state) not in states:
                states.add(op.apply(state))
                frontier.append(op.apply(state))
