"""The compiled successor generator (``forward/_successors.pyx``) against the pure-Python
reference: the same applicable operators, in the same order, and the same successor of
every operator, on every state of a breadth-first walk, and the same expansions and
plans when a search runs on it.

The order matters as much as the set: lazy search puts successors into its open list in
generation order, so a different order is a different search. The compiled module is
built by ``pip install``; a missing build fails here rather than passing unnoticed.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from shared_bench import small_bench

from strips_framework.compiled import PURE_PYTHON_SWITCH
from strips_framework.forward.breadth_first import BreadthFirstSearch
from strips_framework.forward.components import StateEstimator
from strips_framework.forward.packing import pack
from strips_framework.forward.successors import SuccessorGenerator, successor_generator
from strips_framework.grounding import ground
from strips_framework.grounding.axioms import AxiomEvaluator
from strips_framework.grounding.task import GroundOperator, GroundTask, mask_of
from strips_framework.limits import Limits
from strips_framework.pddl import find_domain, load_task

DATA = Path(__file__).resolve().parents[1] / "pddl" / "data"
LOCAL = [
    ("briefcase-domain.pddl", "briefcase-2.pddl"),  # conditional effects
    ("elevator-domain.pddl", "elevator-1.pddl"),
    ("switches-domain.pddl", "switches-1.pddl"),  # negative preconditions
    ("rooms-domain.pddl", "rooms-2.pddl"),
    ("crates-domain.pddl", "crates-3.pddl"),
    ("lamps-domain.pddl", "lamps-1.pddl"),
    ("blocks-domain.pddl", "blocks-3.pddl"),
]
IPC = small_bench("ipc")
IPC_DOMAINS = sorted(p.name for p in IPC.iterdir() if p.is_dir())
STATES = 400


def walk(task: GroundTask) -> list[int]:
    """Up to :data:`STATES` states, breadth-first, applying operators the plain way."""
    derive = AxiomEvaluator(task).evaluate
    states, seen = [task.init], {task.init}
    for state in states:
        for op in task.operators:
            if op.applicable(state) and len(states) < STATES:
                child = derive(op.apply(state))
                if child not in seen:
                    seen.add(child)
                    states.append(child)
    return states


def assert_same_successors(task: GroundTask) -> None:
    reference = successor_generator(task, compiled=False)
    compiled = successor_generator(task, compiled=True)
    assert type(reference) is SuccessorGenerator and type(compiled) is not SuccessorGenerator
    for state in walk(task):
        expected = [i for i, op in enumerate(task.operators) if op.applicable(state)]
        found = compiled.applicable(state)
        assert found == reference.applicable(state), task.facts_of(state)
        assert sorted(found) == expected
        for op in range(len(task.operators)):  # applicable or not: the same masks' result
            assert compiled.apply(state, op) == reference.apply(state, op), task.operators[op].name
        packed = pack(state)
        for generator in (reference, compiled):  # drawn one at a time, from either form
            for form in (state, packed):
                drawn, position = [], generator.next_applicable(form, 0)
                while position >= 0:
                    drawn.append(generator.order[position])
                    position = generator.next_applicable(form, position + 1)
                assert drawn == found, task.facts_of(state)
                # Preferred operators (repeated, unordered, some not applicable) come out
                # as the full list gives them.
                assert (
                    generator.ordered(form, [*reversed(range(len(task.operators))), *found])
                    == found
                )
            for op in range(len(task.operators)):  # deletes absent, adds present too
                assert generator.step_packed(packed, op, 0)[0] == pack(generator.apply(state, op))


def test_the_compiled_module_is_built(tasks):
    generator = successor_generator(tasks["gripper-3"])
    assert type(generator).__module__ == "strips_framework.forward._successors"


def test_the_switch_picks_the_reference(tasks, monkeypatch):
    monkeypatch.setenv(PURE_PYTHON_SWITCH, "1")
    assert type(successor_generator(tasks["gripper-3"])) is SuccessorGenerator


def test_hand_written_tasks_generate_alike(tasks):
    for name in ("gripper-1", "gripper-3"):
        assert_same_successors(tasks[name])
    b = tasks.builder()  # no positive preconditions: tested in every state
    b.op("(start)", [], ["running"], pre_neg=["running"])
    b.op("(stop)", ["running"], [], ["running"])
    assert_same_successors(b.task("switch", [], ["running"]))


@pytest.mark.parametrize(("domain", "problem"), LOCAL)
def test_local_tasks_generate_alike(domain, problem):
    assert_same_successors(ground(load_task(DATA / domain, DATA / problem)))


@pytest.mark.parametrize("domain", IPC_DOMAINS)
def test_ipc_first_tasks_generate_alike(domain):
    problem = IPC / domain / "task01.pddl"
    assert_same_successors(ground(load_task(find_domain(problem), problem)))


class _Blind(StateEstimator):
    def estimate(self, state: int) -> float:
        return 0

    def estimate_with_preferred(self, state: int) -> tuple[float, list[int]]:
        return 0, []


@pytest.mark.parametrize(("domain", "problem"), LOCAL)
def test_searches_expand_alike(monkeypatch, domain, problem):
    """Breadth-first search, whose expansions follow generation order only."""
    task = ground(load_task(DATA / domain, DATA / problem))
    results = []
    for pure in ("", "1"):
        monkeypatch.setenv(PURE_PYTHON_SWITCH, pure)
        results.append(BreadthFirstSearch().search_task(task, _Blind(), Limits(time=60)))
    compiled, python = results
    assert (compiled.status, compiled.plan) == (python.status, python.plan)
    assert compiled.statistics.expanded == python.statistics.expanded


def test_a_packed_successor_takes_effects_in_any_order_and_repeated():
    """Effects listed unsorted, repeated, deleted and added at once (the add wins), or
    deleted while absent: the packing of the bitset successor, compiled and reference."""
    op = GroundOperator("(op)", (), (64, 3, 64, 31), (31, 90, 2, 90, 3))
    task = GroundTask(
        "t", tuple(f"(f{i})" for i in range(100)), (op,), mask_of((2, 31, 40, 90)), (3,)
    )
    for compiled in (False, True):
        generator = successor_generator(task, compiled=compiled)
        for state in (task.init, 0, mask_of((3, 64)), mask_of((1, 2, 31, 99))):
            assert generator.step_packed(pack(state), 0, 0)[0] == pack(generator.apply(state, 0))
