"""The lifted plan validator: correct plans pass, wrong ones are explained."""

from __future__ import annotations

from strips_framework.pddl.validate import validate_plan

BLOCKS_PLAN = ["(unstack a b)", "(put-down a)", "(pick-up b)", "(stack b c)"]


def test_accepts_a_correct_plan(load):
    check = validate_plan(load("blocks-domain.pddl", "blocks-3.pddl"), BLOCKS_PLAN)
    assert check.valid
    assert check.cost == 4
    assert check.message == "plan valid: 4 steps, cost 4 (unit cost)"


def test_steps_are_case_insensitive(load):
    steps = [step.upper() for step in BLOCKS_PLAN]
    assert validate_plan(load("blocks-domain.pddl", "blocks-3.pddl"), steps).valid


def test_explains_the_failing_precondition_with_bindings(load):
    check = validate_plan(load("blocks-domain.pddl", "blocks-3.pddl"), ["(pick-up a)"])
    assert not check.valid
    assert check.message == (
        "step 1 (pick-up a): precondition not satisfied with ?x = a: (ontable a) is false"
    )


def test_explains_an_unreached_goal(load):
    check = validate_plan(load("blocks-domain.pddl", "blocks-3.pddl"), BLOCKS_PLAN[:2])
    assert not check.valid
    assert check.message == "goal not reached after 2 steps: (on b c) is false"


def test_rejects_unknown_actions_wrong_arity_and_wrong_types(load):
    task = load("rooms-domain.pddl", "rooms-1.pddl")
    assert "unknown action 'fly'" in validate_plan(task, ["(fly hall1)"]).message
    assert "takes 2 arguments, found 1" in validate_plan(task, ["(move hall1)"]).message
    message = validate_plan(task, ["(clean hall1)"]).message
    assert message == "step 1 (clean hall1): 'hall1' is not an object of type room (?r)"
    assert "expected '(action arg ...)'" in validate_plan(task, ["move hall1 r1"]).message


def test_costs_from_numbers_and_functions(load):
    task = load("rooms-domain.pddl", "rooms-1.pddl")
    plan = [
        "(move hall1 r1)",
        "(pick k1 r1)",
        "(move r1 hall1)",
        "(unlock hall1 r2 k1)",
        "(move hall1 r2)",
        "(clean r2)",
        "(move r2 hall1)",
    ]
    check = validate_plan(task, plan)
    assert check.valid, check.message
    assert check.cost == 3 + 1 + 3 + 2 + 5 + 0 + 5
    assert check.message.endswith("(general cost)")


def test_negative_precondition_failure_is_explained(load):
    task = load("rooms-domain.pddl", "rooms-1.pddl")
    check = validate_plan(task, ["(move hall1 r2)"])
    assert check.message == (
        "step 1 (move hall1 r2): precondition not satisfied with ?from = hall1, ?to = r2: "
        "(locked hall1 r2) is true"
    )


def test_derived_predicates_and_complex_goals(load):
    task = load("rooms-domain.pddl", "rooms-2.pddl")
    plan = ["(move hall1 r1)", "(pick k1 r1)", "(clean r1)"]
    assert validate_plan(task, plan).valid
    # Without the key, the goal needs (not (reachable r1)), which fails: r1 is reachable.
    steps = ["(move hall1 r1)", "(pick k1 r1)", "(move r1 hall1)", "(drop k1 hall1)"]
    check = validate_plan(task, [*steps, "(move hall1 r1)", "(clean r1)"])
    assert not check.valid
    assert check.message.startswith(
        "goal not reached after 6 steps: (or (has k1) (not (reachable r1))) is false"
    )


def test_imply_and_forall_in_preconditions(load):
    task = load("rooms-domain.pddl", "rooms-1.pddl")
    # r1 was visited and still holds k1: cleaning it violates the implication.
    check = validate_plan(task, ["(move hall1 r1)", "(clean r1)"])
    assert not check.valid
    assert "(key-at k1 r1) is true (for ?k = k1)" in check.message
