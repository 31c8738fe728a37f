"""Each forward strategy on hand-built ground tasks: valid plans, optimal costs where
promised, the right status when there is no plan, and limits that stop the search."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from strips_framework.forward.budget import Budget
from strips_framework.grounding import ground
from strips_framework.grounding.task import GroundTask
from strips_framework.limits import Clock, LimitReached, Limits
from strips_framework.pddl import find_domain, load_task
from strips_framework.result import Result

STRATEGIES = ["astar", "wastar", "gbfs", "lazy-gbfs", "ehc", "breadth-first"]
COMPLETE = [s for s in STRATEGIES if s != "ehc"]


def search(registry, task: GroundTask, strategy: str, heuristic: str = "ff",
           limits: Limits | None = None, **options: object) -> Result:
    searcher = registry.get("ground-strategy", strategy).cls(**options)
    estimator = registry.get("heuristic", heuristic).cls().for_task(task)
    return searcher.search_task(task, estimator, limits or Limits())


def replay(task: GroundTask, plan: tuple[str, ...]) -> int:
    """Apply the plan step by step (each step must be applicable); return its cost."""
    by_name = {op.name: op for op in task.operators}
    state, cost = task.init, 0
    for step in plan:
        op = by_name[step]
        assert op.applicable(state), f"{step} is not applicable"
        state, cost = op.apply(state), cost + op.cost
    assert task.is_goal(state)
    return cost


@pytest.mark.parametrize("strategy", STRATEGIES)
@pytest.mark.parametrize("name", ["gripper-3", "toll-roads"])
def test_every_strategy_finds_a_valid_plan(registry, tasks, strategy, name):
    task = tasks[name]
    result = search(registry, task, strategy)
    assert result.solved, result.status
    assert replay(task, result.plan) == result.cost
    assert result.limit is None
    statistics = result.statistics
    assert statistics.facts == len(task.facts) and statistics.operators == len(task.operators)
    assert statistics.generated >= len(result.plan)


@pytest.mark.parametrize("heuristic", ["blind", "hmax", "lmcut"])
@pytest.mark.parametrize("balls", [1, 2, 3, 4])
def test_astar_with_an_admissible_heuristic_matches_breadth_first_lengths(
    registry, tasks, heuristic, balls
):
    task = tasks[f"gripper-{balls}"]
    shortest = search(registry, task, "breadth-first")
    optimal = search(registry, task, "astar", heuristic)
    assert optimal.solved and len(optimal.plan) == len(shortest.plan)


@pytest.mark.parametrize("heuristic", ["blind", "hmax", "lmcut"])
def test_astar_minimizes_cost_not_length(registry, tasks, heuristic):
    result = search(registry, tasks["toll-roads"], "astar", heuristic)
    assert result.cost == 4 and len(result.plan) == 4
    assert len(search(registry, tasks["toll-roads"], "breadth-first").plan) == 1


def test_negative_preconditions_are_respected(registry, tasks):
    for strategy in COMPLETE:
        result = search(registry, tasks["one-way-trap"], strategy)
        assert result.plan == ("(reset alarm)", "(open door)", "(walk through)"), strategy


@pytest.mark.parametrize("strategy", COMPLETE)
def test_complete_strategies_prove_unsolvability(registry, tasks, strategy):
    result = search(registry, tasks["unsolvable"], strategy, "goal-count")
    assert result.status == "unsolvable" and result.plan is None and result.cost is None


def test_hill_climbing_gives_up_as_incomplete(registry, tasks):
    result = search(registry, tasks["greedy-trap"], "ehc", "goal-count")
    assert result.status == "exhausted"
    assert search(registry, tasks["greedy-trap"], "gbfs", "goal-count").solved


def test_hill_climbing_follows_every_operator_without_preferred_ones(registry, tasks):
    # goal-count names no preferred operators: helpful-action pruning must not leave nothing.
    assert search(registry, tasks["gripper-2"], "ehc", "goal-count").solved


def test_dead_end_initial_state(registry, tasks):
    result = search(registry, tasks["unsolvable"], "lazy-gbfs", "ff")
    assert result.status == "unsolvable"
    assert result.statistics.dead_ends == 1 and result.statistics.expanded == 0


@pytest.mark.parametrize("strategy", STRATEGIES)
def test_expansion_limit_stops_with_the_statistics_so_far(registry, tasks, strategy):
    result = search(registry, tasks["gripper-4"], strategy, "goal-count", Limits(expansions=5),
                    **({"preferred": False} if strategy == "ehc" else {}))
    assert result.status == "expansion-limit" and result.limit == "expansions"
    assert result.statistics.expanded == 5 and result.plan is None


def test_time_limit_counts_from_the_start_of_the_run(registry, tasks):
    searcher = registry.get("ground-strategy", "breadth-first").cls()
    task = tasks["gripper-3"]
    result = searcher.search_task(task, None, Limits(time=1), Clock(1, started=-math.inf))
    assert result.status == "time-limit" and result.statistics.expanded == 0


def test_memory_limit_is_checked_against_the_resident_set():
    budget = Budget(Limits(memory=1), Clock(60))
    with pytest.raises(LimitReached) as stop:
        budget.check(0)
    assert stop.value.status == "memory-limit"


def test_wastar_weight_one_is_astar(registry, tasks):
    task = tasks["gripper-3"]
    astar = search(registry, task, "astar", "hmax")
    wastar = search(registry, task, "wastar", "hmax", weight=1.0)
    assert (wastar.plan, wastar.statistics.expanded) == (astar.plan, astar.statistics.expanded)


def test_lazy_search_evaluates_each_expanded_state_once(registry, tasks):
    result = search(registry, tasks["gripper-3"], "lazy-gbfs", "ff")
    statistics = result.statistics
    assert statistics.evaluated == statistics.expanded + 1  # the goal is evaluated, not expanded


@pytest.mark.parametrize("heuristic", ["blind", "lmcut"])
def test_astar_on_pddl_matches_breadth_first(registry, heuristic):
    problem = Path(__file__).resolve().parents[2] / "examples" / "pddl" / "blocksworld" / "p4.pddl"
    task = ground(load_task(find_domain(problem), problem))
    shortest = search(registry, task, "breadth-first")
    optimal = search(registry, task, "astar", heuristic)
    assert optimal.solved and len(optimal.plan) == len(shortest.plan) == optimal.cost
    assert replay(task, optimal.plan) == optimal.cost


def test_lazy_search_boosts_on_each_new_best_h_but_not_at_the_initial_state(
    registry, tasks, monkeypatch
):
    """As Fast Downward: the initial state's h only sets the mark to beat. Checked on the
    reference loop, whose open list can be watched (the compiled loop is compared with it
    in test_compiled_lazy.py)."""
    from strips_framework.compiled import PURE_PYTHON_SWITCH
    from strips_framework.forward import lazy
    from strips_framework.forward.openlists import AlternationOpenList

    monkeypatch.setenv(PURE_PYTHON_SWITCH, "1")
    boosts = []

    class RecordingList(AlternationOpenList):
        def reward_progress(self) -> None:
            boosts.append(True)
            super().reward_progress()

    monkeypatch.setattr(lazy, "open_list", lambda preferred, boost: RecordingList(boost))
    task = tasks["gripper-3"]
    ff = registry.get("heuristic", "ff").cls().for_task(task)
    values = []

    class Recording:
        def estimate(self, state: int) -> float:
            return ff.estimate(state)

        def estimate_with_preferred(self, state: int) -> tuple[float, list[int]]:
            h, preferred = ff.estimate_with_preferred(state)
            values.append(h)
            return h, preferred

    result = lazy.LazyGreedySearch().search_task(task, Recording(), Limits())
    assert result.solved
    expanded = values[:-1]  # the last one evaluated is the goal
    new_lows = sum(h < min(expanded[:i]) for i, h in enumerate(expanded) if i)
    assert new_lows > 0 and len(boosts) == new_lows
