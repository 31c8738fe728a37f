"""The state estimator's protocol as the searches use it: ``estimate`` is all an estimator
must have; ``estimate_with_preferred`` is optional, under every strategy and option."""

from __future__ import annotations

from pathlib import Path
from typing import ClassVar

import pytest

from strips_framework import Planner
from strips_framework.options import Configurable
from strips_framework.plugin.hookspecs import hookimpl

BLOCKS = Path(__file__).resolve().parents[2] / "examples" / "pddl" / "blocksworld"


class _GoalsLeft:
    def __init__(self, task) -> None:
        self.goal = task.goal_mask

    def estimate(self, state: int) -> float:
        return bin(self.goal & ~state).count("1")


class OnlyEstimate(Configurable):
    """Goal atoms not yet true, from an estimator with ``estimate`` alone."""

    name: ClassVar[str] = "only-estimate"
    admissible: ClassVar[bool] = False
    capabilities: ClassVar[frozenset[str]] = frozenset()

    def for_task(self, task):
        return _GoalsLeft(task)


class _Plugin:
    @hookimpl
    def strips_register_heuristics(self) -> list[type]:
        return [OnlyEstimate]


@pytest.mark.parametrize("strategy", [
    {"name": "lazy-gbfs"}, {"name": "gbfs", "preferred": True}, {"name": "ehc"}, {"name": "astar"},
])
def test_an_estimator_without_preferred_operators_works_under_every_strategy(strategy):
    planner = Planner.create({"strategy": strategy, "heuristic": "only-estimate"}, [_Plugin()])
    result = planner.run(BLOCKS / "p4.pddl", BLOCKS / "domain.pddl")
    assert result.solved, result.status
