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


@pytest.mark.parametrize(
    ("action", "message"),
    [
        ("(:action a :parameters (?x) :precondition (p ?x) :precondition (q ?x ?x)"
         " :effect (p ?x))", ":precondition is given twice in action 'a'"),
        ("(:action a :parameters (?x) :effect (p ?x) :effect (not (p ?x)))",
         ":effect is given twice in action 'a'"),
        ("(:action a :parameters (?x) :parameters (?y) :effect (p ?x))",
         ":parameters is given twice"),
    ],
)
def test_a_repeated_action_part_is_an_error_not_a_replacement(write_task, action, message):
    with pytest.raises(InputError, match=message) as error:
        write_task(domain_with(action), PROBLEM)
    assert error.value.line == 4


def test_a_second_goal_is_an_error_not_a_replacement(write_task):
    domain = domain_with("(:action a :parameters (?x) :effect (p ?x))")
    problem = "(define (problem p) (:domain d) (:objects a b) (:init (p a))\n (:goal (p b))\n (:goal (p a)))"
    with pytest.raises(InputError, match=r"problem.pddl:3:2: \(:goal \.\.\.\) is given twice \(first at line 2\)"):
        write_task(domain, problem)


def test_a_repeated_requirements_section_is_an_error(write_task):
    domain = domain_with("(:action a :parameters (?x) :effect (p ?x))", "\n  (:requirements :typing)")
    with pytest.raises(InputError, match=r"domain.pddl:4:3: \(:requirements \.\.\.\) is given twice"):
        write_task(domain, PROBLEM)


TYPED = (
    "(define (domain d)\n"
    "  (:types vehicle - object truck - vehicle)\n"
    "  (:predicates (at ?v - vehicle))\n"
    "  (:action go :parameters (?v - {kind}) :effect (at ?v)))\n"
)


@pytest.mark.parametrize("kind", ["vann", "(either truck vann)"])
def test_an_undeclared_type_is_an_error(write_task, kind):
    problem = "(define (problem p) (:domain d) (:objects t - truck) (:init) (:goal (at t)))"
    with pytest.raises(InputError, match=r"domain.pddl:4:\d+: undeclared type 'vann' \(declared types: object, truck, vehicle\)"):
        write_task(TYPED.format(kind=kind), problem)


def test_an_undeclared_object_type_is_an_error_in_the_problem(write_task):
    problem = "(define (problem p) (:domain d)\n (:objects t - lorry) (:init) (:goal (at t)))"
    with pytest.raises(InputError, match=r"problem.pddl:2:2: undeclared type 'lorry'"):
        write_task(TYPED.format(kind="truck"), problem)


def test_a_domain_name_mismatch_is_a_warning(write_task):
    problem = "(define (problem p)\n (:domain other) (:objects t - truck) (:init) (:goal (at t)))"
    with pytest.warns(UserWarning, match=r"problem.pddl:2:2: the problem names domain 'other', but the domain file defines 'd'"):
        task = write_task(TYPED.format(kind="truck"), problem)
    assert task.problem.domain_name == "other"


BLOCKS = (
    "(define (domain b)\n"                                          # 1
    "  (:predicates (on ?x ?y) (clear ?x))\n"                       # 2
    "  (:action stack\n"                                            # 3
    "    :parameters (?x ?y)\n"                                     # 4
    "    :precondition (and (clear ?x)\n"                           # 5
    "                       (clear ?y))\n"                          # 6
    "    :effect (and (on ?x ?y) (not (clear ?y))))\n"              # 7
    "  (:action unstack\n"                                          # 8
    "    :parameters (?x ?y)\n"                                     # 9
    "    :precondition (on ?x ?y)\n"                                # 10
    "    :effect (and (clear ?y) (not (on ?x ?y)))))\n"             # 11
)


@pytest.mark.parametrize(
    ("old", "new", "line", "message"),
    [
        ("(clear ?y))\n    :effect", "(clear ?y)\n    :effect", 5, "this '(' is not closed before line 7"),
        ("(not (clear ?y))))", "(not (clear ?y)))", 3, "this '(' is not closed before line 8"),
        ("(clear ?x)\n", "(clear ?x))\n", 5, "this ')' closes the '(' of line 5 too early"),
    ],
)
def test_a_parenthesis_error_points_at_the_parenthesis_not_at_define(write_task, old, new, line, message):
    assert old in BLOCKS
    with pytest.raises(InputError) as error:
        write_task(BLOCKS.replace(old, new), PROBLEM)
    assert error.value.line == line
    assert message in error.value.message


def test_lists_nested_deeper_than_the_limit_are_refused_at_the_deep_parenthesis(write_task):
    goal = "(not " * 200 + "(p a)" + ")" * 200
    problem = f"(define (problem p) (:domain d) (:objects a)\n (:init) (:goal {goal}))"
    with pytest.raises(InputError, match=r"problem.pddl:2:\d+: lists nested deeper than 100 levels"):
        write_task(domain_with("(:action a :parameters (?x) :effect (p ?x))"), problem)


@pytest.mark.parametrize("amount", ["inf", "nan", "1e400", "9" * 5000, "-1", "2.5"])
def test_a_cost_that_is_no_natural_number_is_an_error(write_task, amount):
    action = f"(:action a :parameters (?x) :effect (and (p ?x) (increase (total-cost) {amount})))"
    domain = domain_with(action).replace("(q ?x ?y))", "(q ?x ?y))\n  (:functions (total-cost) - number)")
    with pytest.raises(InputError, match="expected a number|not supported: action cost") as error:
        write_task(domain, PROBLEM)
    assert error.value.line is not None
