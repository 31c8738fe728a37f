"""Grounding: static pruning, normalization, costs, goals and axioms on small tasks."""

from __future__ import annotations

from pathlib import Path

import pytest

from strips_framework.errors import InputError
from strips_framework.grounding import ground as ground_all
from strips_framework.grounding.axioms import AxiomEvaluator
from strips_framework.grounding.task import GroundTask

DATA = Path(__file__).parents[1] / "pddl" / "data"


def ground(task):
    """Grounding without relevance pruning, so every reachable fact and operator shows."""
    return ground_all(task, prune_irrelevant=False)


def names(task: GroundTask, facts: tuple[int, ...]) -> list[str]:
    return [task.facts[fact] for fact in facts]


def operator(task: GroundTask, name: str):
    (found,) = [op for op in task.operators if op.name == name]
    return found


def test_blocks_facts_and_operators_are_sorted(load):
    task = ground(load("blocks-domain.pddl", "blocks-3.pddl"))
    assert list(task.facts) == sorted(task.facts)
    assert [op.name for op in task.operators] == sorted(op.name for op in task.operators)
    assert len(task.operators) == 3 + 3 + 9 + 9
    assert names(task, task.goal) == ["(on b c)"]
    assert task.facts_of(task.init) == [
        "(clear a)",
        "(clear c)",
        "(handempty)",
        "(on a b)",
        "(ontable b)",
        "(ontable c)",
    ]
    assert not task.uses_costs and {op.cost for op in task.operators} == {1}


def test_static_facts_are_pruned_and_checked(load):
    task = ground(load("rooms-domain.pddl", "rooms-1.pddl"))
    assert not [fact for fact in task.facts if fact.startswith(("(door", "(fits"))]
    # (door r1 r2) does not exist, so there is no such move.
    assert not [op for op in task.operators if op.name == "(move r1 r2)"]
    move = operator(task, "(move hall1 r1)")
    assert names(task, move.pre) == ["(at hall1)"]


def test_equality_and_negative_preconditions(load):
    task = ground(load("rooms-domain.pddl", "rooms-1.pddl"))
    assert not [op for op in task.operators if op.name == "(move hall1 hall1)"]
    move = operator(task, "(move hall1 r2)")
    assert names(task, move.pre_neg) == ["(locked hall1 r2)"]
    assert not move.applicable(task.init)


def test_either_types_and_the_type_hierarchy(load):
    task = ground(load("rooms-domain.pddl", "rooms-1.pddl"))
    drops = [op.name for op in task.operators if op.name.startswith("(drop")]
    assert drops == ["(drop k1 hall1)", "(drop k1 r1)", "(drop k1 r2)"]


def test_disjunctions_split_operators_under_one_name(load):
    task = ground(load("rooms-domain.pddl", "rooms-1.pddl"))
    cleans = [op for op in task.operators if op.name == "(clean r1)"]
    # imply (visited r1) -> forall k: not key-at: either r1 not visited or no key in r1.
    assert sorted(names(task, op.pre_neg) for op in cleans) == [
        ["(key-at k1 r1)"],
        ["(visited r1)"],
    ]


def test_exists_becomes_extra_variables(write_task):
    task = ground(
        write_task(
            """(define (domain d) (:predicates (p ?x) (q ?x) (done))
           (:action a :parameters () :precondition (exists (?x) (and (p ?x) (q ?x)))
              :effect (done)))""",
            """(define (problem p) (:domain d) (:objects o1 o2 o3)
           (:init (p o1) (p o2) (q o2) (q o3)) (:goal (done)))""",
        )
    )
    # Only o2 satisfies both static atoms: one operator, no precondition left.
    (only,) = task.operators
    assert only.name == "(a)" and only.pre == ()


def test_action_costs(load):
    task = ground(load("rooms-domain.pddl", "rooms-1.pddl"))
    assert task.uses_costs
    costs = {op.name: op.cost for op in task.operators}
    assert costs["(move hall1 r2)"] == 5 and costs["(move r1 hall1)"] == 3
    assert costs["(pick k1 r1)"] == 1 and costs["(unlock hall1 r2 k1)"] == 2
    assert costs["(clean r1)"] == 0  # no cost effect under a cost metric


def test_costs_without_metric_are_unit(load):
    task = ground(load("rooms-domain.pddl", "rooms-2.pddl"))
    assert not task.uses_costs and {op.cost for op in task.operators} == {1}


def test_derived_predicates_become_stratified_axioms(load):
    task = ground(load("rooms-domain.pddl", "rooms-1.pddl"))
    assert names(task, task.derived) == ["(reachable hall1)", "(reachable r1)", "(reachable r2)"]
    assert {axiom.stratum for axiom in task.axioms} == {0}
    assert "(reachable r1)" in task.facts_of(task.init)
    assert "(reachable r2)" not in task.facts_of(task.init)
    evaluator = AxiomEvaluator(task)
    unlocked = task.init & ~operator(task, "(unlock hall1 r2 k1)").delete_mask
    assert "(reachable r2)" in task.facts_of(evaluator.evaluate(unlocked))


def test_complex_goal_becomes_a_derived_fact_in_a_higher_stratum(load):
    task = ground(load("rooms-domain.pddl", "rooms-2.pddl"))
    assert names(task, task.goal) == ["(@goal)"]
    goal_axioms = [axiom for axiom in task.axioms if task.facts[axiom.head] == "(@goal)"]
    assert goal_axioms and {axiom.stratum for axiom in goal_axioms} == {1}
    assert not task.is_goal(task.init)


def test_axiom_evaluator_is_a_no_op_without_axioms(load):
    task = ground(load("blocks-domain.pddl", "blocks-3.pddl"))
    assert AxiomEvaluator(task).evaluate(task.init) == task.init


def test_axiom_evaluator_clears_stale_derived_facts(load):
    task = ground(load("rooms-domain.pddl", "rooms-1.pddl"))
    reachable_r2 = task.facts.index("(reachable r2)")
    stale = task.init | 1 << reachable_r2
    assert AxiomEvaluator(task).evaluate(stale) == task.init


def test_unreachable_goal_keeps_a_fact_nothing_adds(write_task):
    task = ground(
        write_task(
            """(define (domain d) (:predicates (p ?x) (q ?x))
           (:action a :parameters (?x) :precondition (p ?x) :effect (p ?x)))""",
            """(define (problem p) (:domain d) (:objects o) (:init (p o)) (:goal (q o)))""",
        )
    )
    (goal,) = task.goal
    assert task.facts[goal] == "(q o)"
    assert not any(goal in op.add for op in task.operators)


def test_negation_cycles_among_derived_predicates_are_refused(write_task):
    task = write_task(
        """(define (domain d) (:predicates (p ?x) (q ?x) (r ?x))
           (:derived (p ?x) (and (r ?x) (not (q ?x))))
           (:derived (q ?x) (p ?x))
           (:action a :parameters (?x) :precondition (p ?x) :effect (r ?x)))""",
        """(define (problem p) (:domain d) (:objects o) (:init (r o)) (:goal (r o)))""",
    )
    with pytest.raises(InputError, match="depends negatively on itself"):
        ground(task)


def test_branching_universal_conditions_become_auxiliary_axioms(load):
    task = ground(load("crates-domain.pddl", "crates-3.pddl"))
    (ship,) = [op for op in task.operators if op.name == "(ship)"]
    (violated,) = names(task, ship.pre_neg)
    assert violated.startswith("(@forall")
    assert ship.applicable(task.init)
    heads = {task.facts[axiom.head] for axiom in task.axioms}
    assert violated in heads and "(@goal)" in heads


def test_auxiliary_axioms_keep_grounding_small(write_task):
    crates = " ".join(f"c{i}" for i in range(40))
    task = ground(
        write_task(
            (DATA / "crates-domain.pddl").read_text(),
            f"""(define (problem crates-40) (:domain crates) (:objects {crates} - crate) (:init)
           (:goal (and (shipped) (forall (?c - crate) (imply (heavy ?c) (loaded ?c))))))""",
        )
    )
    # Without auxiliary axioms (ship) would split into 2^40 operators.
    assert [op.name for op in task.operators].count("(ship)") == 1
