"""PLANEX: the highest kernel that holds picks the next step; done work is skipped, lost
work redone, and a world in which no kernel holds is replanned from."""

from __future__ import annotations

import pytest

from strips_framework.macrops import planex
from strips_framework.macrops.ground_table import ground_table, parse_plan, solution_steps
from strips_framework.macrops.planex import FaultModel, Summary, execute
from strips_framework.planner import Planner

LIGHT = ["goto2(BOX1)", "pushto(BOX1, LIGHTSWITCH1)", "climbonbox(BOX1)",
         "turnonlight(LIGHTSWITCH1)"]


def _replanner(problem_seen: list):
    planner = Planner.create()

    def replan(problem):
        problem_seen.append(problem)
        result = planner.solve(problem)
        return solution_steps(result)

    return replan


def test_a_faultless_run_executes_the_plan(robot):
    steps = parse_plan(robot["light"], LIGHT)
    run = execute(robot["light"], steps, _replanner([]), FaultModel(failure=0.0))
    assert run.reached and run.actions == 4
    assert (run.skipped, run.redone, run.replans, run.failures) == (0, 0, 0, 0)


def test_work_already_done_is_skipped(robot):
    """The paper's six-step plan: after goto2 the robot may push at once (kernel 4
    holds), so the climb on and off the box is skipped."""
    six = ["goto2(BOX1)", "climbonbox(BOX1)", "climboffbox(BOX1)", *LIGHT[1:]]
    steps = parse_plan(robot["light"], six)
    run = execute(robot["light"], steps, _replanner([]), FaultModel(failure=0.0))
    assert run.reached and run.skipped == 2 and run.actions == 4


def test_lost_progress_is_redone(robot, monkeypatch):
    """Someone moves the box away from the switch after the push: back to kernel 1 or
    2 (go to the box again, push it again)."""
    problem = robot["light"]
    steps = parse_plan(problem, LIGHT)
    pushed = []

    def disturb(simulator, state, rng):
        if ("NEXTTO", "BOX1", "LIGHTSWITCH1") in state and not pushed:
            pushed.append(True)
            moved = {a for a in state if "BOX1" not in a[1:] or a[0] != "NEXTTO"}
            return frozenset(moved), "BOX1 pushed away"
        return None

    monkeypatch.setattr(planex, "_disturb", disturb)
    run = execute(problem, steps, _replanner([]), FaultModel(failure=0.0, disturbance=1.0))
    assert run.reached and run.redone >= 1 and run.disturbances == 1
    assert run.actions > 4


def test_no_kernel_holds_so_it_replans(robot):
    """Started where the robot is in ROOM2, the light plan's kernels all fail."""
    problem = robot["light"]
    steps = parse_plan(problem, LIGHT)
    elsewhere = frozenset(
        ("INROOM", "ROBOT", "ROOM2") if a == ("INROOM", "ROBOT", "ROOM1") else a
        for a in problem.facts
    )
    seen: list = []
    run = execute(problem, steps, _replanner(seen), FaultModel(failure=0.0), world=elsewhere)
    assert run.reached and run.replans == 1 and len(seen) == 1


def test_one_action_in_ten_failing_still_reaches_the_goal(robot):
    problem = robot["boxes"]
    steps = ground_table(problem, parse_plan(problem, [
        "goto2(BOX1)", "pushto(BOX1, BOX2)", "goto2(BOX3)", "pushto(BOX3, BOX2)"])).table.steps
    faults = FaultModel(failure=0.1, disturbance=0.05, seed=4)
    runs = [execute(problem, steps, _replanner([]), faults, run) for run in range(40)]
    summary = Summary.of(runs)
    assert summary.reached >= 38
    assert summary.failures > 0  # the faults really happened


def test_runs_are_reproducible(robot):
    steps = parse_plan(robot["light"], LIGHT)
    faults = FaultModel(failure=0.3, disturbance=0.2, seed=9)
    first = execute(robot["light"], steps, _replanner([]), faults, 3)
    assert execute(robot["light"], steps, _replanner([]), faults, 3) == first


@pytest.mark.parametrize("value", [-0.1, 1.5])
def test_a_probability_outside_0_1_is_refused(value):
    with pytest.raises(ValueError):
        FaultModel(failure=value)
