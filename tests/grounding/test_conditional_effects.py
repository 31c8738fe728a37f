"""Conditional and universal effects (``when``, ``forall``) from the reader through
grounding and forward search to the lifted validator, which evaluates them on its own.

The domains are classic ones: Pednault's briefcase world (the briefcase carries whatever
is in it), a miconic-style elevator whose stop boards and serves every passenger at once,
and switches whose toggles depend on the state before the action."""

from __future__ import annotations

import pytest

from strips_framework.errors import InputError
from strips_framework.forward.space import StateSpace
from strips_framework.grounding import ground
from strips_framework.pddl import to_problem
from strips_framework.pddl.formulas import And, Atom, Not
from strips_framework.pddl.validate import validate_plan

#: Each task with the length of its shortest plan (found by breadth-first search).
TASKS = [
    ("briefcase-domain.pddl", "briefcase-1.pddl", 7),
    ("briefcase-domain.pddl", "briefcase-2.pddl", 12),
    ("elevator-domain.pddl", "elevator-1.pddl", 11),
    ("switches-domain.pddl", "switches-1.pddl", 4),
]
CONFIGS = [
    {"strategy": {"name": "lazy-gbfs"}, "heuristic": {"name": "ff"}},
    {"strategy": {"name": "gbfs"}, "heuristic": {"name": "hadd"}},
    {"strategy": {"name": "ehc", "preferred": False}, "heuristic": {"name": "ff"}},
    {"strategy": {"name": "lazy-gbfs"}, "heuristic": {"name": "lmcount"}},
]
OPTIMAL = ["lmcut", "hmax", "blind"]


def operator(task, name):
    (found,) = [op for op in task.operators if op.name == name]
    return found


def test_the_reader_keeps_the_variables_and_condition_of_each_effect(load):
    task = load("briefcase-domain.pddl", "briefcase-1.pddl")
    move = next(action for action in task.domain.actions if action.name == "move")
    assert move.add == (Atom("is-at", ("?l",)),)
    assert move.delete == (Atom("is-at", ("?m",)),)
    (effect,) = move.conditional
    assert [param.name for param in effect.params] == ["?x"]
    assert effect.params[0].types == ("portable",)
    assert effect.condition == Atom("in", ("?x",))
    assert effect.add == (Atom("at", ("?x", "?l")),)
    assert effect.delete == (Atom("at", ("?x", "?m")),)


def test_nested_when_conditions_accumulate(write_task):
    task = write_task(
        """(define (domain d) (:predicates (p) (q) (r) (s))
        (:action a :effect (when (p) (and (q) (when (r) (not (s)))))))""",
        "(define (problem t) (:domain d) (:init) (:goal (q)))",
    )
    (action,) = task.domain.actions
    inner, outer = action.conditional
    assert outer.condition == Atom("p", ()) and outer.add == (Atom("q", ()),)
    assert inner.condition == And((Atom("p", ()), Atom("r", ())))
    assert inner.delete == (Atom("s", ()),)


def test_grounding_keeps_the_condition_of_each_object(load):
    task = ground(load("briefcase-domain.pddl", "briefcase-1.pddl"), prune_irrelevant=False)
    move = operator(task, "(move home office)")
    assert [task.facts[f] for f in move.add] == ["(is-at office)"]
    shown = sorted(
        (
            [task.facts[f] for f in effect.condition],
            [task.facts[f] for f in effect.add],
            [task.facts[f] for f in effect.delete],
        )
        for effect in move.effects
    )
    assert shown == [
        (["(in d)"], ["(at d office)"], ["(at d home)"]),
        (["(in p)"], ["(at p office)"], ["(at p home)"]),
    ]


def test_an_unconditional_universal_effect_becomes_plain_deletes(load):
    task = ground(load("switches-domain.pddl", "switches-1.pddl"), prune_irrelevant=False)
    reset = operator(task, "(reset)")
    assert not reset.effects
    assert sorted(task.facts[f] for f in reset.delete) == [
        *(f"(on s{i})" for i in range(1, 5)),
        *(f"(touched s{i})" for i in range(1, 5)),
    ]


def test_conditions_are_read_before_the_action_and_adds_win(load):
    """Toggling an off switch turns it on (not also off again), turns off its linked
    switch that is on, and keeps ``(touched s)``: the unconditional add wins over the
    conditional delete of the same atom."""
    task = ground(load("switches-domain.pddl", "switches-1.pddl"), prune_irrelevant=False)
    toggle = operator(task, "(toggle s1)")
    after = StateSpace(task).successor(task.init, task.operators.index(toggle))
    assert toggle.apply(task.init) & ~(1 << task.facts.index("(all-on)")) == after
    assert [f for f in task.facts_of(after) if f != "(all-on)"] == ["(on s1)", "(touched s1)"]


def test_an_effect_that_contradicts_the_precondition_is_dropped(write_task):
    task = write_task(
        """(define (domain d) (:predicates (p) (q) (r))
        (:action a :precondition (p) :effect (and (r) (when (not (p)) (q)) (when (p) (q)))))""",
        "(define (problem t) (:domain d) (:init (p)) (:goal (q)))",
    )
    (op,) = ground(task, prune_irrelevant=False).operators
    assert not op.effects  # one never fires, the other always does
    assert sorted(ground(task, prune_irrelevant=False).facts[f] for f in op.add) == ["(q)", "(r)"]


def test_relevance_keeps_the_conditions_of_kept_effects(load):
    """Pruning must not weaken a condition: every fact an effect's condition names stays."""
    task = ground(load("elevator-domain.pddl", "elevator-1.pddl"))
    names = set(task.facts)
    for op in task.operators:
        for effect in op.effects:
            assert effect.condition or effect.condition_neg
            assert {task.facts[f] for f in effect.condition} <= names
    assert any(op.effects for op in task.operators)


@pytest.mark.parametrize(("domain", "problem", "_optimum"), TASKS)
@pytest.mark.parametrize("config", CONFIGS, ids=lambda c: c["heuristic"]["name"])
def test_satisficing_plans_are_valid_for_the_lifted_validator(
    load, make_planner, domain, problem, _optimum, config
):
    task = load(domain, problem)
    result = make_planner(**config).solve_task(ground(task))
    assert result.solved, result.status
    check = validate_plan(task, result.plan)
    assert check.valid, check.message


@pytest.mark.parametrize(("domain", "problem", "optimum"), TASKS)
@pytest.mark.parametrize("heuristic", OPTIMAL)
def test_astar_finds_the_optimal_plan(load, make_planner, domain, problem, optimum, heuristic):
    task = load(domain, problem)
    planner = make_planner(strategy={"name": "astar"}, heuristic={"name": heuristic})
    result = planner.solve_task(ground(task))
    assert result.solved and len(result.plan) == optimum
    assert validate_plan(task, result.plan).valid


def test_the_validator_applies_effects_only_where_the_condition_held(load):
    task = load("briefcase-domain.pddl", "briefcase-1.pddl")
    # The paycheck was never put in, so it stays home while the briefcase travels.
    check = validate_plan(
        task, ["(put-in d home)", "(move home bank)", "(take-out d)", "(move bank home)"]
    )
    assert not check.valid
    assert "(at p office) is false" in check.message
    plan = ["(put-in d home)", "(put-in p home)", "(move home bank)", "(take-out d)"]
    plan += ["(move bank office)", "(take-out p)", "(move office home)"]
    assert validate_plan(task, plan).valid


def test_means_ends_translation_refuses_conditional_effects(load):
    task = load("briefcase-domain.pddl", "briefcase-1.pddl")
    with pytest.raises(InputError, match="conditional or universal effects of action 'move'"):
        to_problem(task)


def test_a_negated_condition_is_kept_negated(load):
    task = load("elevator-domain.pddl", "elevator-1.pddl")
    stop = next(action for action in task.domain.actions if action.name == "stop")
    board = stop.conditional[-1]
    assert Not(Atom("served", ("?p",))) in board.condition.parts
