"""The robot world of the paper's section IV, its tasks solved once per session, and
random states of that world for the soundness checks."""

from __future__ import annotations

import random
from pathlib import Path

import pytest

from strips_framework.macrops.generalize import Generalized, generalize
from strips_framework.macrops.ground_table import GroundTable, ground_table, solution_steps
from strips_framework.planner import Planner
from strips_framework.worldmodel.problem import Problem
from strips_framework.worldmodel.simulate import State

ROBOT_WORLD = Path(__file__).parents[2] / "examples" / "robot-world"
TASKS = ("light", "boxes", "other-room")
ROOMS = ("ROOM1", "ROOM2", "ROOM3", "ROOM4", "ROOM5")
OBJECTS = ("BOX1", "BOX2", "BOX3", "LIGHTSWITCH1")


@pytest.fixture(scope="session")
def robot() -> dict[str, Problem]:
    planner = Planner.create()
    return {name: planner.load(ROBOT_WORLD / f"{name}.strips") for name in (*TASKS, "five-goals")}


@pytest.fixture(scope="session")
def ground_tables(robot) -> dict[str, GroundTable]:
    planner = Planner.create()
    tables = {}
    for name in TASKS:
        result = planner.solve(robot[name])
        assert result.solved, name
        tables[name] = ground_table(robot[name], solution_steps(result))
    return tables


@pytest.fixture(scope="session")
def generalized(ground_tables) -> dict[str, Generalized]:
    return {name: generalize(table) for name, table in ground_tables.items()}


def random_states(problem: Problem, count: int, seed: int) -> list[State]:
    """Robot-world states: every object and the robot in a random room, some objects next
    to each other or to the robot, the robot on the floor or on a box, the light on or off.
    The rigid facts (types, doors, LOCINROOM) stay those of the problem."""
    rng = random.Random(seed)
    rigid = [a for a in problem.facts if a[0] in ("TYPE", "PUSHABLE", "CONNECTS", "LOCINROOM")]
    states = []
    for _ in range(count):
        room = {thing: rng.choice(ROOMS[:2]) for thing in ("ROBOT", *OBJECTS)}
        facts = set(rigid) | {("INROOM", thing, r) for thing, r in room.items()}
        facts.add(("STATUS", "LIGHTSWITCH1", rng.choice(("ON", "OFF"))))
        things = ["ROBOT", *OBJECTS, "DOOR1", "DOOR2"]
        for _ in range(rng.randint(0, 3)):
            a, b = rng.sample(things, 2)
            facts |= {("NEXTTO", a, b), ("NEXTTO", b, a)}
        if rng.random() < 0.3:
            facts.add(("ON", "ROBOT", rng.choice(("BOX1", "BOX2", "BOX3"))))
        else:
            facts.add(("ONFLOOR",))
        states.append(frozenset(facts))
    return states

