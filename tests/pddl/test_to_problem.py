"""PDDL tasks as framework problems: means-ends analysis and the provers run on them."""

from __future__ import annotations

import pytest

from strips_framework.errors import InputError
from strips_framework.logic.formulas import Forall, Implies
from strips_framework.pddl import to_problem
from strips_framework.pddl.validate import validate_plan


def ipc_steps(plan) -> list[str]:
    steps = []
    for instance in plan:
        args = " ".join(str(arg) for arg in instance.arguments())
        steps.append(f"({instance.schema_name} {args})")
    return steps


def test_means_ends_solves_a_small_blocks_world(load, make_planner):
    task = load("blocks-domain.pddl", "blocks-3.pddl")
    problem = to_problem(task)
    result = make_planner(strategy="means-ends", prover="resolution").solve(problem)
    assert result.solved
    check = validate_plan(task, ipc_steps(result.plan))
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


def test_derived_predicates_become_axioms_the_prover_uses(write, make_planner):
    task = write(TOWER_DOMAIN, TOWER_PROBLEM)
    problem = to_problem(task)
    (axiom,) = problem.axioms
    assert isinstance(axiom, Forall) and isinstance(axiom.body, Implies)
    assert axiom.body.conclusion.atom[0] == "above"
    assert ("above", 2) not in problem.primitive_predicates
    result = make_planner(strategy="means-ends", prover="resolution").solve(problem)
    assert result.solved
    assert validate_plan(task, ipc_steps(result.plan)).valid


def test_negated_atoms_are_refused_for_the_open_world_provers(load):
    with pytest.raises(InputError, match=r"rooms-domain.pddl:20: not supported by means-ends"):
        to_problem(load("rooms-domain.pddl", "rooms-1.pddl"))
