"""The compiled loops of lazy greedy and eager best-first search (``forward/_search.pyx``)
against their pure-Python references (``reference_run``): the same status, plan and
counts, with and without preferred operators, for lazy greedy search, A*, weighted A* and
eager greedy search, on the hand-written PDDL tasks and the first two tasks of every
IPC domain (``../shared``, or the repository's copy of those tasks).

Expansions depend on every tie the open lists break and on when the preferred list is
boosted, so any difference in the order of pops shows. The estimator is goal counting
with the applicable operators that add a missing goal fact as preferred: cheap, with
long plateaus (many ties) and progress often enough to boost. The compiled module is
built by ``pip install``; a missing build fails here rather than passing unnoticed."""

from __future__ import annotations

from pathlib import Path

import pytest
from shared_bench import small_bench

from strips_framework.forward.base import ForwardStrategy, SearchRun
from strips_framework.forward.eager import AStarSearch, GreedySearch, WeightedAStarSearch
from strips_framework.forward.lazy import LazyGreedySearch
from strips_framework.forward.successors import SuccessorGenerator
from strips_framework.grounding import ground
from strips_framework.grounding.task import GroundTask
from strips_framework.limits import Limits
from strips_framework.pddl import find_domain, load_task

DATA = Path(__file__).resolve().parents[1] / "pddl" / "data"
LOCAL = ["briefcase-2", "elevator-1", "switches-1", "rooms-2", "crates-3", "lamps-1", "blocks-3"]
IPC = small_bench("ipc")
IPC_TASKS = [(p.name, n) for p in sorted(IPC.iterdir()) if p.is_dir() for n in (1, 2)]


class GoalCount:
    """Goal facts missing; preferred: applicable operators adding one of them."""

    def __init__(self, task: GroundTask) -> None:
        self.task = task
        self.applicable = SuccessorGenerator(task).applicable

    def estimate(self, state: int) -> float:
        return sum(1 for fact in self.task.goal if not state >> fact & 1)

    def estimate_with_preferred(self, state: int) -> tuple[float, list[int]]:
        missing = sum(1 << fact for fact in self.task.goal if not state >> fact & 1)
        operators = self.task.operators
        return self.estimate(state), [
            op for op in self.applicable(state) if operators[op].add_mask & missing
        ]


def reference(strategy: ForwardStrategy) -> ForwardStrategy:
    """``strategy`` with its pure-Python loop."""
    class Reference(type(strategy)):  # type: ignore[misc]
        def run(self, run: SearchRun) -> int | None:
            return self.reference_run(run)

    return Reference(**{name: getattr(strategy, name) for name in strategy.FIELDS})


STRATEGIES = [
    LazyGreedySearch(),
    LazyGreedySearch(preferred=True, boost=3),
    LazyGreedySearch(preferred=False, boost=0),
    AStarSearch(),
    WeightedAStarSearch(weight=3.0),
    GreedySearch(),
    GreedySearch(preferred=True, boost=5),
    GreedySearch(preferred=False),
]


def assert_same_search(task: GroundTask) -> None:
    for strategy in STRATEGIES:
        results = [
            search.search_task(task, GoalCount(task), Limits(time=60, expansions=1500))
            for search in (strategy, reference(strategy))
        ]
        compiled, python = (
            (r.status, r.plan, r.statistics.expanded, r.statistics.evaluated,
             r.statistics.generated, r.statistics.dead_ends, r.statistics.reopened)
            for r in results
        )
        assert compiled == python, strategy


def test_the_compiled_loops_are_built():
    from strips_framework.forward import _search  # noqa: F401


@pytest.mark.parametrize("name", LOCAL)
def test_local_tasks_search_alike(name):
    domain = DATA / f"{name.split('-')[0]}-domain.pddl"
    assert_same_search(ground(load_task(domain, DATA / f"{name}.pddl")))


@pytest.mark.parametrize(("domain", "number"), IPC_TASKS)
def test_ipc_tasks_search_alike(domain, number):
    problem = IPC / domain / f"task{number:02d}.pddl"
    assert_same_search(ground(load_task(find_domain(problem), problem)))
