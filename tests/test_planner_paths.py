"""The planner's Python API takes file names as ``str`` or :class:`~pathlib.Path`, as
``Planner.run`` always did: a user in a notebook types a string."""

from __future__ import annotations

from pathlib import Path

from strips_framework.planner import Planner

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def test_load_takes_a_string_like_a_path():
    planner = Planner.create()
    path = EXAMPLES / "robot-world" / "light.strips"
    assert planner.load(str(path)) == planner.load(path)


def test_load_pddl_takes_strings_with_and_without_a_domain():
    planner = Planner.create()
    problem = EXAMPLES / "pddl" / "blocksworld" / "p4.pddl"
    domain = problem.parent / "domain.pddl"
    by_path = planner.load_pddl(problem, domain)
    assert planner.load_pddl(str(problem), str(domain)) == by_path
    assert planner.load_pddl(str(problem)) == by_path
