"""Relevance pruning keeps what the goal can need: optimal plan lengths are unchanged
and the plans found on the pruned task are valid."""

from __future__ import annotations

from collections import deque
from pathlib import Path

import pytest
from shared_bench import small_bench

from strips_framework.grounding import ground
from strips_framework.grounding.axioms import AxiomEvaluator
from strips_framework.grounding.task import GroundTask
from strips_framework.pddl import PddlTask, find_domain, load_task
from strips_framework.pddl.validate import validate_plan

DATA = Path(__file__).parents[1] / "pddl" / "data"
IPC = small_bench("ipc")


def shortest_plan(task: GroundTask) -> list[str] | None:
    """Breadth-first search: a shortest plan, or None."""
    evaluate = AxiomEvaluator(task).evaluate
    parents: dict[int, tuple[int, str] | None] = {task.init: None}
    queue = deque([task.init])
    while queue:
        state = queue.popleft()
        if task.is_goal(state):
            plan = []
            while (link := parents[state]) is not None:
                state, name = link
                plan.append(name)
            return plan[::-1]
        for op in task.operators:
            if op.applicable(state):
                child = evaluate(op.apply(state))
                if child not in parents:
                    parents[child] = (state, op.name)
                    queue.append(child)
    return None


def tasks() -> list[PddlTask]:
    found = [
        load_task(DATA / "rooms-domain.pddl", DATA / "rooms-1.pddl"),
        load_task(DATA / "rooms-domain.pddl", DATA / "rooms-2.pddl"),
        load_task(DATA / "blocks-domain.pddl", DATA / "blocks-3.pddl"),
        load_task(DATA / "crates-domain.pddl", DATA / "crates-3.pddl"),
    ]
    for domain in ("gripper", "miconic", "satellite", "blocks"):
        problem = IPC / domain / "task01.pddl"
        found.append(load_task(find_domain(problem), problem))
    return found


@pytest.mark.parametrize("task", tasks(), ids=lambda task: task.name)
def test_pruning_keeps_optimal_plan_length(task):
    pruned, full = ground(task), ground(task, prune_irrelevant=False)
    assert len(pruned.facts) <= len(full.facts)
    plan, reference = shortest_plan(pruned), shortest_plan(full)
    assert plan is not None and len(plan) == len(reference)
    check = validate_plan(task, plan)
    assert check.valid, check.message


def test_irrelevant_facts_and_operators_are_dropped():
    task = load_task(DATA / "rooms-domain.pddl", DATA / "rooms-1.pddl")
    pruned, full = ground(task), ground(task, prune_irrelevant=False)
    # The goal is (cleaned r2) and (at hall1): cleaning r1 and visiting hall1 are useless.
    assert "(cleaned r1)" in full.facts and "(cleaned r1)" not in pruned.facts
    assert "(visited hall1)" not in pruned.facts
    assert "(clean r1)" not in {op.name for op in pruned.operators}
    assert list(pruned.facts) == sorted(pruned.facts)
