"""The kit's PDDL tasks for heuristics and ground-task strategies, read from the package's
data, grounded once and explored exactly once per test session."""

from __future__ import annotations

from functools import cache
from importlib import resources
from pathlib import Path

from strips_framework.grounding import ground
from strips_framework.grounding.task import GroundTask
from strips_framework.pddl import PddlTask, load_task
from strips_framework.testing.ground_space import TaskSpace

#: Solvable tasks, each small enough to explore whole: blocks (4 blocks), gripper (3 balls),
#: delivery (action costs: the cheapest plan is not the shortest), fuel (a tank that cannot
#: be refilled: most states are dead ends) and circuit (derived predicates, negative
#: preconditions and a negative goal).
TASKS = ("blocks-4", "gripper-3", "delivery-2", "fuel-4", "circuit-1")
#: A task without a plan that relaxed reachability cannot tell: too little fuel.
UNSOLVABLE = "fuel-2"


@cache
def pddl_task(name: str) -> PddlTask:
    """Task ``name`` (one of :data:`TASKS` or :data:`UNSOLVABLE`) with its domain, which
    is named after the part of the name before the last '-' (``fuel-2``: ``fuel-domain``)."""
    domain = name.rsplit("-", 1)[0]
    with resources.as_file(resources.files(__package__) / "tasks") as folder:
        return load_task(Path(folder) / f"{domain}-domain.pddl", Path(folder) / f"{name}.pddl")


@cache
def ground_task(name: str) -> GroundTask:
    return ground(pddl_task(name))


@cache
def task_space(name: str) -> TaskSpace:
    return TaskSpace(ground_task(name))
