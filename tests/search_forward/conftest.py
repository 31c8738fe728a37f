"""Small ground tasks built by hand, so forward search is tested without a PDDL reader.
Tests get them through the ``tasks`` fixture: ``tasks["gripper-3"]``, ``tasks.builder()``."""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import ClassVar

import pytest

from strips_framework.grounding.task import GroundOperator, GroundTask, mask_of


class TaskBuilder:
    """Names facts as they are first mentioned and collects operators."""

    def __init__(self) -> None:
        self.facts: dict[str, int] = {}
        self.operators: list[GroundOperator] = []

    def fact(self, name: str) -> int:
        return self.facts.setdefault(name, len(self.facts))

    def facts_of(self, names: Iterable[str]) -> tuple[int, ...]:
        return tuple(self.fact(name) for name in names)

    def op(self, name: str, pre: Iterable[str], add: Iterable[str], delete: Iterable[str] = (),
           cost: int = 1, pre_neg: Iterable[str] = ()) -> None:
        self.operators.append(GroundOperator(
            name, self.facts_of(pre), self.facts_of(add), self.facts_of(delete), cost,
            self.facts_of(pre_neg),
        ))

    def task(self, name: str, init: Iterable[str], goal: Iterable[str],
             uses_costs: bool = False) -> GroundTask:
        init_facts, goal_facts = self.facts_of(init), self.facts_of(goal)
        operators = tuple(sorted(self.operators, key=lambda op: op.name))
        return GroundTask(name, tuple(self.facts), operators, mask_of(init_facts), goal_facts,
                          uses_costs=uses_costs)


def gripper(balls: int) -> GroundTask:
    """The IPC gripper domain: carry ``balls`` balls from room a to room b, two hands."""
    b = TaskBuilder()
    rooms, hands = ("a", "b"), ("left", "right")
    for here in rooms:
        for there in rooms:
            if here != there:
                b.op(f"(move {here} {there})", [f"at-robby {here}"], [f"at-robby {there}"],
                     [f"at-robby {here}"])
    for ball in range(balls):
        for room in rooms:
            for hand in hands:
                b.op(f"(pick ball{ball} {room} {hand})",
                     [f"at ball{ball} {room}", f"at-robby {room}", f"free {hand}"],
                     [f"carry ball{ball} {hand}"], [f"at ball{ball} {room}", f"free {hand}"])
                b.op(f"(drop ball{ball} {room} {hand})",
                     [f"carry ball{ball} {hand}", f"at-robby {room}"],
                     [f"at ball{ball} {room}", f"free {hand}"], [f"carry ball{ball} {hand}"])
    init = ["at-robby a", "free left", "free right", *(f"at ball{i} a" for i in range(balls))]
    return b.task(f"gripper-{balls}", init, [f"at ball{i} b" for i in range(balls)])


def toll_roads() -> GroundTask:
    """Cities on a line with a direct but expensive road from the first to the last:
    the shortest plan (1 step, cost 10) is not the cheapest (4 steps, cost 4)."""
    b = TaskBuilder()
    for city in range(4):
        b.op(f"(drive c{city} c{city + 1})", [f"at c{city}"], [f"at c{city + 1}"], [f"at c{city}"])
    b.op("(drive c0 c4)", ["at c0"], ["at c4"], ["at c0"], cost=10)
    return b.task("toll-roads", ["at c0"], ["at c4"], uses_costs=True)


def one_way_trap() -> GroundTask:
    """A key can be used up in a dead end ((burn key)) before it opens the door; the
    negative precondition keeps the door locked while the alarm is on."""
    b = TaskBuilder()
    b.op("(burn key)", ["have key"], ["ashes"], ["have key"])
    b.op("(open door)", ["have key"], ["door open"], pre_neg=["alarm"])
    b.op("(reset alarm)", ["alarm"], [], ["alarm"])
    b.op("(walk through)", ["door open"], ["outside"])
    return b.task("one-way-trap", ["have key", "alarm"], ["outside"])


def greedy_trap() -> GroundTask:
    """(consume s) reaches one goal at once but uses up what the other needs; the plan is
    (keep s) first. Committing to the first better state, hill-climbing falls in."""
    b = TaskBuilder()
    b.op("(consume s)", ["s"], ["g1"], ["s"])
    b.op("(keep s)", ["s"], ["g2"])
    return b.task("greedy-trap", ["s"], ["g1", "g2"])


def unsolvable() -> GroundTask:
    """The goal fact is never added."""
    b = TaskBuilder()
    b.op("(flip)", ["up"], ["down"], ["up"])
    b.op("(flop)", ["down"], ["up"], ["down"])
    b.fact("goal")
    return b.task("unsolvable", ["up"], ["goal"])


class Tasks:
    """The tasks above by name (``gripper-N`` for N balls), each built afresh."""

    FACTORIES: ClassVar[dict[str, Callable[[], GroundTask]]] = {
        "toll-roads": toll_roads, "one-way-trap": one_way_trap, "unsolvable": unsolvable,
        "greedy-trap": greedy_trap,
    }

    def __getitem__(self, name: str) -> GroundTask:
        if name.startswith("gripper-"):
            return gripper(int(name.removeprefix("gripper-")))
        return self.FACTORIES[name]()

    @staticmethod
    def builder() -> TaskBuilder:
        return TaskBuilder()


@pytest.fixture(scope="session")
def tasks() -> Tasks:
    return Tasks()
