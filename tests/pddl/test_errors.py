"""Bad input is an InputError naming the file, the line and what was expected."""

from __future__ import annotations

import pytest

from strips_framework.errors import InputError

PROBLEM = "(define (problem p) (:domain d) (:objects a b) (:init (p a)) (:goal (p b)))"


def domain_with(action: str, extra: str = "") -> str:
    return (
        "(define (domain d)\n"
        "  (:requirements :strips)\n"
        f"  (:predicates (p ?x) (q ?x ?y)){extra}\n"
        f"  {action})\n"
    )


@pytest.mark.parametrize(
    ("action", "line", "message"),
    [
        (
            "(:action a :parameters (?x) :precondition (r ?x) :effect (p ?x))",
            4,
            "undeclared predicate 'r'",
        ),
        (
            "(:action a :parameters (?x) :precondition (q ?x) :effect (p ?x))",
            4,
            "predicate 'q' takes 2 arguments, found 1",
        ),
        (
            "(:action a :parameters (?x) :precondition (p ?y) :effect (p ?x))",
            4,
            "unknown variable ?y",
        ),
        (
            "(:action a :parameters (?x) :precondition (p c) :effect (p ?x))",
            4,
            "unknown object or constant 'c'",
        ),
        (
            "(:action a :parameters (?x) :effect (when (p ?x) (increase (total-cost) 1)))",
            4,
            "not supported: action costs inside conditional or universal effects",
        ),
        (
            "(:action a :parameters (?x) :effect (forall (?x) (p ?x)))",
            4,
            "variable ?x is already bound in this action",
        ),
        (
            "(:action a :parameters (?x) :effect (when (p ?y) (p ?x)))",
            4,
            "unknown variable ?y",
        ),
        (
            "(:action a :parameters (?x) :effect (increase (fuel) 1))",
            4,
            "not supported: numeric fluents",
        ),
        (
            "(:action a :parameters (?x) :effect (assign (total-cost) 1))",
            4,
            "not supported: numeric effect 'assign'",
        ),
        (
            "(:action a :parameters (?x) :precondition (> (fuel) 1) :effect (p ?x))",
            4,
            "not supported: numeric conditions",
        ),
        (
            "(:durative-action a :parameters (?x) :duration (= ?duration 1))",
            4,
            "not supported: durative actions",
        ),
        (
            "(:action a :parameters (?x) :precondition (p ?x) :effect (p ?x) :foo 1)",
            4,
            "expected one of :parameters, :precondition, :effect, found ':foo'",
        ),
        ("(:action a :parameters (?x - ) :effect (p ?x))", 4, "expected a type after '-'"),
        ("(:acton a)", 4, "expected :requirements, :types"),
    ],
)
def test_domain_errors_name_file_line_and_expectation(write_task, action, line, message):
    with pytest.raises(InputError) as error:
        write_task(domain_with(action), PROBLEM)
    assert error.value.path.endswith("domain.pddl")
    assert error.value.line == line
    assert message in error.value.message


def test_unsupported_requirement(write_task):
    domain = "(define (domain d)\n (:requirements :strips :durative-actions))"
    with pytest.raises(InputError, match=r"domain.pddl:2:2: not supported: requirement :durative"):
        write_task(domain, PROBLEM)


@pytest.mark.parametrize(
    ("text", "line", "message"),
    [
        ("(define (domain d)\n  (:predicates (p ?x))", 1, "this '(' is never closed"),
        ("(define (domain d))\n)", 2, "unbalanced ')'"),
        ("(define (domain d))\n(define (domain e))", 2, "expected the end of the file"),
        ("", None, "the file is empty"),
        ("(domain d)", 1, "expected '(define (domain NAME) ...)'"),
    ],
)
def test_syntax_errors(write_task, text, line, message):
    with pytest.raises(InputError) as error:
        write_task(text, PROBLEM)
    assert error.value.line == line
    assert message in error.value.message


@pytest.mark.parametrize(
    ("problem", "line", "message"),
    [
        (
            "(define (problem p) (:domain d)\n (:objects a)\n (:init (p b)) (:goal (p a)))",
            3,
            "unknown object or constant 'b'",
        ),
        (
            "(define (problem p) (:domain d) (:objects a)\n (:init (at 10 (p a))) (:goal (p a)))",
            2,
            "not supported: timed initial literals",
        ),
        (
            "(define (problem p) (:domain d) (:objects a) (:init (p a)))",
            1,
            "expected a (:goal ...) section",
        ),
        (
            (
                "(define (problem p) (:domain d) (:objects a) (:init (p a)) (:goal (p a))\n"
                " (:metric maximize (total-cost)))"
            ),
            2,
            "not supported: metrics other than",
        ),
    ],
)
def test_problem_errors(write_task, problem, line, message):
    domain = domain_with("(:action a :parameters (?x) :precondition (p ?x) :effect (p ?x))")
    with pytest.raises(InputError) as error:
        write_task(domain, problem)
    assert error.value.path.endswith("problem.pddl")
    assert error.value.line == line
    assert message in error.value.message


def test_error_text_has_file_line_and_column(write_task):
    with pytest.raises(InputError) as error:
        write_task(
            domain_with("(:action a :parameters (?x) :precondition (r ?x) :effect (p ?x))"), PROBLEM
        )
    assert str(error.value).endswith("domain.pddl:4:45: undeclared predicate 'r'")


def test_derived_predicates_cannot_be_effects(write_task):
    domain = domain_with(
        "(:action a :parameters (?x) :effect (p ?x))", "\n  (:derived (p ?x) (q ?x ?x))"
    )
    with pytest.raises(InputError) as error:
        write_task(domain, PROBLEM)
    assert error.value.line == 5
    assert "changes 'p', a derived predicate" in error.value.message
