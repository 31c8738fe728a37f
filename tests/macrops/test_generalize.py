"""Triangle tables of the paper's plans, their generalization, and its soundness: every
instance whose kernel holds replays in the independent simulator."""

from __future__ import annotations

import itertools

import pytest

from strips_framework.logic.terms import Param
from strips_framework.macrops import generalize as generalize_module
from strips_framework.macrops.generalize import generalize
from strips_framework.macrops.ground_table import ground_table, parse_plan
from strips_framework.macrops.kernels import counterexamples, instances
from strips_framework.macrops.proofs import MacroError
from strips_framework.worldmodel.simulate import Simulator

from .conftest import TASKS, random_states

P = Param


def test_light_table_has_the_papers_rows(ground_tables):
    table = ground_tables["light"].table
    assert [str(s) for s in table.steps][:2] == ["goto2(BOX1)", "climbonbox(BOX1)"]
    # turnonlight needs the box next to the switch (pushto, step 4) and the robot on the
    # box (climbonbox, step 5); the goal row needs what step 6 added.
    assert table.marked[(6, 4)] == (("NEXTTO", "BOX1", "LIGHTSWITCH1"),)
    assert table.marked[(6, 5)] == (("ON", "ROBOT", "BOX1"),)
    assert table.goal_row() == (("STATUS", "LIGHTSWITCH1", "ON"),)
    assert ("TYPE", "LIGHTSWITCH1", "LIGHTSWITCH") in table.kernel(1)
    assert ("NEXTTO", "ROBOT", "BOX1") not in table.kernel(1)  # step 1 makes it true


def test_light_generalizes_to_any_switch_and_box(generalized):
    table = generalized["light"].table
    assert [str(s) for s in table.steps] == [
        "goto2(p1)", "climbonbox(p1)", "climboffbox(p1)", "pushto(p1, p2)",
        "climbonbox(p1)", "turnonlight(p2)",
    ]
    assert table.goal_row() == (("STATUS", P("p2"), "ON"),)
    assert generalized["light"].example[P("p2")] == "LIGHTSWITCH1"


def test_boxes_needs_protection_from_its_last_push(generalized):
    """pushto(p3, p4) deletes NEXTTO(p3, $) and NEXTTO($, p3): p3 must differ from the
    boxes pushed together first."""
    table = generalized["boxes"].table
    pairs = {(d.left, d.right) for d in table.distinct}
    assert (P("p3"), P("p1")) in pairs and (P("p3"), P("p2")) in pairs


def test_a_plan_that_does_not_apply_is_refused(robot):
    steps = parse_plan(robot["light"], ["climbonbox(BOX1)"])
    with pytest.raises(MacroError, match="step 1, climbonbox\\(BOX1\\)"):
        ground_table(robot["light"], steps)


@pytest.mark.parametrize("name", TASKS)
def test_every_instance_of_every_kernel_replays(robot, generalized, name):
    """The soundness promise, on 150 random states of the robot world; the kernels must
    match in many of them, or the check proves nothing."""
    table = generalized[name].table
    simulator = Simulator(robot[name])
    states = random_states(robot[name], 150, seed=13)
    assert list(counterexamples(simulator, table, states)) == []
    matched = sum(
        1 for s in states for i in range(1, table.size + 1)
        if next(instances(table, i, simulator.close(s), simulator.problem.constants), None)
    )
    assert matched >= 50


@pytest.mark.parametrize("name", TASKS)
def test_every_edited_part_replays(robot, generalized, name):
    table = generalized[name].table
    simulator = Simulator(robot[name])
    states = random_states(robot[name], 60, seed=7)
    for last in range(1, table.size + 1):
        assert list(counterexamples(simulator, table.edited(last), states)) == []


def test_dropping_the_protections_is_caught(robot, generalized):
    table = generalized["boxes"].table._replace(distinct=())
    simulator = Simulator(robot["boxes"])
    found = next(counterexamples(simulator, table, random_states(robot["boxes"], 150, 13)), None)
    assert found is not None
    _, _, _, message = found
    assert "does not hold" in message


def test_lifting_without_replaying_the_proofs_is_caught(robot, ground_tables, monkeypatch):
    """A generalization that lifts the table but never constrains it (every constant
    occurrence its own parameter, steps unrelated) is unsound, and the check says so."""
    monkeypatch.setattr(generalize_module._Lifter, "unify", lambda self, left, right: None)
    table = generalize(ground_tables["light"]).table
    simulator = Simulator(robot["light"])
    states = random_states(robot["light"], 40, seed=3)
    assert next(counterexamples(simulator, table, states), None) is not None


def test_the_plan_it_came_from_is_an_instance(robot, generalized):
    for name in TASKS:
        found = generalized[name]
        simulator = Simulator(robot[name])
        initial = frozenset(robot[name].facts)
        closed = simulator.close(initial)
        matches = list(itertools.islice(
            instances(found.table, 1, closed, robot[name].constants, found.example), 1
        ))
        assert matches, name
