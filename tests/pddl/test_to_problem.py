"""PDDL tasks as framework problems: means-ends analysis and the provers run on them."""

from __future__ import annotations

import pytest

from strips_framework.errors import InputError
from strips_framework.logic.formulas import Forall, Implies
from strips_framework.pddl import to_problem
from strips_framework.pddl.validate import validate_plan


def test_means_ends_solves_a_small_blocks_world(load, make_planner):
    task = load("blocks-domain.pddl", "blocks-3.pddl")
    problem = to_problem(task)
    result = make_planner(strategy="means-ends", prover="resolution").solve(problem)
    assert result.solved
    check = validate_plan(task, list(result.plan))
    assert check.valid, check.message


def test_types_become_unary_facts_and_preconditions(load):
    problem = to_problem(load("blocks-domain.pddl", "blocks-3.pddl"))
    assert ("type:block", "a") in problem.facts
    assert ("type:block", 1) in problem.primitive_predicates
    stack = problem.operator("stack")
    assert "type:block(x)" in str(stack.precondition) or "type:block" in repr(stack.precondition)


TOWER_DOMAIN = """(define (domain tower) (:requirements :strips :derived-predicates)
  (:predicates (on ?x ?y) (above ?x ?y) (free ?x) (top ?x))
  (:derived (above ?x ?y) (or (on ?x ?y) (exists (?z) (and (on ?x ?z) (above ?z ?y)))))
  (:action crown :parameters (?x ?y) :precondition (and (free ?x) (above ?x ?y))
     :effect (top ?x)))"""
TOWER_PROBLEM = """(define (problem t) (:domain tower) (:objects a b c)
  (:init (on a b) (on b c) (free a)) (:goal (top a)))"""


def test_derived_predicates_become_axioms_the_prover_uses(write_task, make_planner):
    task = write_task(TOWER_DOMAIN, TOWER_PROBLEM)
    problem = to_problem(task)
    (axiom,) = problem.axioms
    assert isinstance(axiom, Forall) and isinstance(axiom.body, Implies)
    assert axiom.body.conclusion.atom[0] == "above"
    assert ("above", 2) not in problem.primitive_predicates
    result = make_planner(strategy="means-ends", prover="resolution").solve(problem)
    assert result.solved
    assert validate_plan(task, list(result.plan)).valid


def test_negative_preconditions_become_complement_predicates(load, make_planner):
    task = load("lamps-domain.pddl", "lamps-1.pddl")
    problem = to_problem(task)
    assert ("not:on", "b") in problem.facts and ("not:on", "a") not in problem.facts
    assert ("not:on", 1) in problem.primitive_predicates
    paint = problem.operator("paint")
    assert ("not:dry", paint.parameters[0]) in paint.add_list
    result = make_planner(strategy="means-ends", prover="resolution").solve(problem)
    assert result.solved
    steps = list(result.plan)
    assert steps == ["(switch-off a)", "(paint a)", "(wait a)", "(switch-on a)"]
    assert validate_plan(task, steps).valid


def test_negated_derived_atoms_are_refused(load):
    with pytest.raises(InputError, match=r"rooms-2.pddl: not supported by means-ends analysis"):
        to_problem(load("rooms-domain.pddl", "rooms-2.pddl"))


def test_negation_is_pushed_through_imply_and_forall(load):
    problem = to_problem(load("rooms-domain.pddl", "rooms-1.pddl"))
    text = str(problem.operator("clean").precondition)
    # (imply (visited ?r) (forall (?k - key) (not (key-at ?k ?r)))) becomes
    # not:visited(r) | forall k: type:key(k) -> not:key-at(k, r).
    assert "'not:visited'" in text and "'not:key-at'" in text
    assert "Implies" in text and "Not(" not in text
