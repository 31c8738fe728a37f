"""The compiled relaxed explorations and LM-cut (``_explore.pyx``) against the pure-Python
reference: the same hadd, hmax, hFF and LM-cut values and relaxed plans on every state of
a breadth-first walk, and the same expansions, plans and preferred operators when a
search uses them.

The tasks: the hand-written PDDL tasks of the core's tests (conditional effects, derived
predicates, negative preconditions), seeded random tasks, and the first tasks of every
IPC domain (``../shared``, or the repository's copy of those tasks). The compiled module is built by
``pip install``; a missing build fails here rather than passing unnoticed.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from random_tasks import random_task
from shared_bench import small_bench

from strips_evaluators.heuristics.exploration import explorer
from strips_evaluators.heuristics.ff import FFHeuristic
from strips_evaluators.heuristics.lmcut import CompiledLMCutEstimator, LMCutHeuristic
from strips_evaluators.heuristics.relaxation import relax
from strips_framework.compiled import PURE_PYTHON_SWITCH
from strips_framework.forward.eager import AStarSearch, GreedySearch
from strips_framework.forward.lazy import LazyGreedySearch
from strips_framework.grounding import ground
from strips_framework.grounding.task import GroundTask
from strips_framework.limits import Limits
from strips_framework.pddl import find_domain, load_task
from strips_framework.testing.ground_space import TaskSpace, TooLarge

CORE_DATA = Path(__file__).resolve().parents[3] / "tests" / "pddl" / "data"
LOCAL = [
    ("briefcase-domain.pddl", "briefcase-2.pddl"),
    ("elevator-domain.pddl", "elevator-1.pddl"),
    ("switches-domain.pddl", "switches-1.pddl"),
    ("rooms-domain.pddl", "rooms-2.pddl"),
    ("crates-domain.pddl", "crates-3.pddl"),
    ("blocks-domain.pddl", "blocks-3.pddl"),
]
IPC = small_bench("ipc")
IPC_DOMAINS = sorted(p.name for p in IPC.iterdir() if p.is_dir())
STATES = 300


def local_task(domain: str, problem: str) -> GroundTask:
    return ground(load_task(CORE_DATA / domain, CORE_DATA / problem))


def ipc_task(domain: str, number: int = 1) -> GroundTask:
    problem = IPC / domain / f"task{number:02d}.pddl"
    return ground(load_task(find_domain(problem), problem))


def some_states(task: GroundTask) -> list[int]:
    """Up to :data:`STATES` states, breadth-first from the initial one."""
    try:
        return TaskSpace(task, max_states=STATES).states
    except TooLarge:
        states, seen = [task.init], {task.init}
        for state in states:
            for op in task.operators:
                if op.applicable(state):
                    child = op.apply(state)
                    if child not in seen and len(states) < STATES:
                        seen.add(child)
                        states.append(child)
        return states


def assert_same_explorations(task: GroundTask) -> None:
    for sharing in (0, 2, 8):
        relaxed = relax(task, factor_sharing=sharing)
        python, compiled = explorer(relaxed, compiled=False), explorer(relaxed, compiled=True)
        for state in some_states(task):
            if task.is_goal(state):
                continue
            assert compiled.hadd(state) == python.hadd(state), task.facts_of(state)
            assert compiled.hmax(state) == python.hmax(state), task.facts_of(state)
            value, plan = compiled.relaxed_plan(state)
            expected_value, expected_plan = python.relaxed_plan(state)
            assert (value, sorted(plan)) == (expected_value, sorted(expected_plan))
            assert compiled.preferred(state) == python.preferred(state)


def assert_same_lmcut(task: GroundTask) -> None:
    python = LMCutHeuristic().for_task(task, compiled=False)
    compiled = LMCutHeuristic().for_task(task, compiled=True)
    for state in some_states(task):
        assert compiled.estimate(state) == python.estimate(state), task.facts_of(state)


def test_the_compiled_module_is_built():
    relaxed = relax(random_task(0))
    assert type(explorer(relaxed)).__module__ == "strips_evaluators.heuristics._explore"
    assert type(LMCutHeuristic().for_task(random_task(0))) is CompiledLMCutEstimator


#: The explorations (hadd, hmax, hFF) and LM-cut, each compared state by state.
CHECKS = pytest.mark.parametrize(
    "check", [assert_same_explorations, assert_same_lmcut], ids=["explorations", "lmcut"]
)


@CHECKS
@pytest.mark.parametrize(("domain", "problem"), LOCAL)
def test_local_tasks_explore_alike(check, domain, problem):
    check(local_task(domain, problem))


@CHECKS
@pytest.mark.parametrize("seed", range(20))
@pytest.mark.parametrize("conditional", [False, True])
def test_random_tasks_explore_alike(check, seed, conditional):
    check(random_task(seed, conditional))


@CHECKS
@pytest.mark.parametrize("domain", IPC_DOMAINS)
def test_ipc_first_tasks_explore_alike(check, domain):
    check(ipc_task(domain))


def run_both(monkeypatch, task: GroundTask, strategy, heuristic: object = None) -> None:
    """The strategy with hFF (or ``heuristic``), compiled and pure Python: the same
    counts and plan."""
    results = []
    for pure in ("", "1"):
        monkeypatch.setenv(PURE_PYTHON_SWITCH, pure)
        estimator = (heuristic or FFHeuristic()).for_task(task)  # type: ignore[attr-defined]
        results.append(strategy.search_task(task, estimator, Limits(time=120, expansions=3000)))
    compiled, python = results
    assert compiled.status == python.status
    assert compiled.plan == python.plan
    assert compiled.statistics.expanded == python.statistics.expanded
    assert compiled.statistics.evaluated == python.statistics.evaluated


@pytest.mark.parametrize(("domain", "problem"), LOCAL)
def test_local_searches_expand_alike(monkeypatch, domain, problem):
    task = local_task(domain, problem)
    run_both(monkeypatch, task, LazyGreedySearch())
    run_both(monkeypatch, task, GreedySearch())


@pytest.mark.parametrize("domain", IPC_DOMAINS)
def test_ipc_searches_expand_alike(monkeypatch, domain):
    """Lazy greedy search with preferred operators on the second task of each domain (up
    to 3000 expansions): expansions depend on every value and preferred operator."""
    run_both(monkeypatch, ipc_task(domain, 2), LazyGreedySearch())


@pytest.mark.parametrize("domain", IPC_DOMAINS)
def test_ipc_astar_lmcut_expands_alike(monkeypatch, domain):
    """A* with LM-cut on the first task of each domain (up to 3000 expansions)."""
    run_both(monkeypatch, ipc_task(domain), AStarSearch(), LMCutHeuristic())
