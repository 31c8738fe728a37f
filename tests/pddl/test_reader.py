"""The PDDL reader: what it accepts, and the lifted task it builds."""

from __future__ import annotations

from pathlib import Path

import pytest

from strips_framework.errors import InputError
from strips_framework.pddl import find_domain
from strips_framework.pddl.formulas import And, Atom, Exists, Forall, Imply, Not, Or

SIMPLE_PROBLEM = "(define (problem p) (:domain d) (:objects a b) (:init (p a)) (:goal (p b)))"


def test_case_is_ignored_everywhere(load):
    task = load("blocks-domain.pddl", "blocks-3.pddl")
    assert task.problem.init[0] == Atom("clear", ("a",))
    assert task.problem.goal == And((Atom("on", ("b", "c")),))
    assert [action.name for action in task.domain.actions] == [
        "pick-up",
        "put-down",
        "stack",
        "unstack",
    ]


def test_type_hierarchy_and_either(load):
    task = load("rooms-domain.pddl", "rooms-1.pddl")
    assert task.objects_of(("place",)) == ("hall1", "r1", "r2")
    assert task.objects_of(("room",)) == ("r1", "r2")
    assert task.objects_of(("room", "hall")) == ("hall1", "r1", "r2")
    assert task.objects_of(("object",)) == ("hall1", "k1", "master", "r1", "r2")
    drop = next(action for action in task.domain.actions if action.name == "drop")
    assert drop.params[1].types == ("room", "hall")


def test_constants_listed_again_as_objects_are_one_object(load):
    task = load("rooms-domain.pddl", "rooms-1.pddl")
    assert [obj.name for obj in task.problem.objects] == ["hall1", "r1", "r2", "k1"]
    assert task.objects_of(("key",)) == ("k1", "master")


def test_adl_formulas(load):
    task = load("rooms-domain.pddl", "rooms-2.pddl")
    goal = task.problem.goal
    assert isinstance(goal, And)
    assert isinstance(goal.parts[0], Exists)
    assert isinstance(goal.parts[1], Or) and isinstance(goal.parts[1].parts[1], Not)
    assert isinstance(goal.parts[2], Forall) and isinstance(goal.parts[2].body, Imply)


def test_derived_predicates_and_costs(load):
    task = load("rooms-domain.pddl", "rooms-1.pddl")
    (derived,) = task.domain.derived
    assert derived.head == Atom("reachable", ("?p",))
    costs = {action.name: action.cost for action in task.domain.actions}
    assert costs == {
        "move": Atom("length", ("?from", "?to")),
        "pick": 1,
        "drop": None,
        "unlock": 2,
        "clean": None,
    }
    assert task.problem.minimize_cost
    assert (Atom("length", ("hall1", "r2")), 5) in task.problem.numeric


def test_types_without_typing_requirement_and_implicit_object(write_task):
    domain = """(define (domain lift) (:requirements :strips)
      (:types passenger - object floor)
      (:predicates (at ?p - passenger ?f - floor))
      (:action go :parameters (?p - passenger ?f ?g - floor) :precondition (at ?p ?f)
         :effect (and (at ?p ?g) (not (at ?p ?f)))))"""
    problem = """(define (problem p) (:domain lift) (:objects p0 - passenger f0 f1 - floor)
      (:init (at p0 f0)) (:goal (at p0 f1)))"""
    task = write_task(domain, problem)
    assert task.objects_of(("floor",)) == ("f0", "f1")
    assert task.objects_of(("object",)) == ("f0", "f1", "p0")


def test_comments_and_extra_requirements(write_task):
    domain = """; leading comment
    (define (domain d) ; trailing
      (:requirements :strips :some-future-flag)
      (:predicates (p ?x)) ; (:predicates (q))
      (:action a :parameters (?x) :precondition (p ?x) :effect (not (p ?x))))"""
    task = write_task(domain, SIMPLE_PROBLEM)
    assert task.domain.requirements == (":strips", ":some-future-flag")


@pytest.mark.parametrize(
    ("name", "domain_file"),
    [
        ("task01.pddl", "domain01.pddl"),
        ("p03.pddl", "p03-domain.pddl"),
        ("p03.pddl", "domain_p03.pddl"),
        ("task07.pddl", "domain.pddl"),
    ],
)
def test_find_domain(tmp_path, name, domain_file):
    (tmp_path / name).write_text(SIMPLE_PROBLEM)
    (tmp_path / domain_file).write_text("")
    assert find_domain(tmp_path / name) == tmp_path / domain_file


def test_find_domain_prefers_the_numbered_domain(tmp_path):
    for name in ("task02.pddl", "domain.pddl", "domain02.pddl"):
        (tmp_path / name).write_text("")
    assert find_domain(tmp_path / "task02.pddl").name == "domain02.pddl"


def test_find_domain_says_what_it_tried(tmp_path):
    with pytest.raises(InputError, match="no domain file found.*domain.pddl"):
        find_domain(tmp_path / "task01.pddl")


def test_missing_file_is_an_input_error(tmp_path):
    with pytest.raises(InputError, match="cannot read the file") as error:
        from strips_framework.pddl import load_task

        load_task(tmp_path / "nope.pddl", tmp_path / "nope2.pddl")
    assert error.value.path == str(Path(tmp_path / "nope.pddl"))
