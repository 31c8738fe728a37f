"""The paper's evaluator (the core's builtin one), term by term on hand-built nodes."""

from __future__ import annotations

import pytest

from strips_framework.logic.clauses import Clause
from strips_framework.logic.formulas import And, Atomic, Not
from strips_framework.logic.terms import Param
from strips_framework.means_ends.evaluator import PaperEvaluator
from strips_framework.means_ends.features import top_goal_atoms_missing
from strips_framework.means_ends.node import Goal, Node
from strips_framework.options import OptionError
from strips_framework.testing.nodes import hand_built_node as make_node
from strips_framework.worldmodel.world import InitialModel, WorldModel


def test_each_factor_counts_with_its_weight() -> None:
    evaluator = PaperEvaluator(
        goal_weight=1,
        predicate_weight=10,
        difference_weight=100,
        cost_weight=1000,
        successor_weight=10_000,
        pending_weight=100_000,
        top_goal_weight=1_000_000,
    )
    node = make_node(
        subgoals=["A B", "C"],
        difference=[3, 2, 4],
        cost=1,
        successors=2,
        pending=[1, 0],
    )
    # G0 (DONE) is not a fact of the node's empty model: one missing atom.
    assert evaluator.evaluate(node) == 2 + 3 * 10 + 2 * 100 + 1000 + 2 * 10_000 + 100_000 + 1_000_000


def test_predicate_table_overrides_the_default_and_equality_is_free() -> None:
    evaluator = PaperEvaluator(
        goal_weight=0, difference_weight=0, predicate_weight=1, predicate_weights={"INROOM": 5},
        top_goal_weight=0,
    )
    goal = And([Atomic(("INROOM", "ROBOT", "ROOM1")), Atomic(("NEXTTO", "ROBOT", "BOX1")),
                Not(Atomic(("=", "ROOM1", "ROOM2")))])
    assert evaluator.evaluate(make_node(subgoals=[goal])) == 5 + 1


def test_top_goal_is_not_counted_among_the_goals() -> None:
    assert PaperEvaluator(top_goal_weight=0).evaluate(make_node(difference=None)) == 0


def test_top_goal_term_counts_the_ground_atoms_of_g0_the_model_lacks() -> None:
    """Two of G0's three ground atoms are facts of the model: one missing; the conjunct
    with a variable and the equality are not counted."""
    facts = [Clause([(True, atom)]) for atom in [("AT", "P1", "F1"), ("AT", "P2", "F2")]]
    model = WorldModel(InitialModel(facts))
    goal = And([Atomic(("AT", "P1", "F1")), Atomic(("AT", "P2", "F2")), Atomic(("AT", "P3", "F3")),
                Atomic(("AT", "P4", Param("f"))), Not(Atomic(("=", "F1", "F2")))])
    node = Node(0, model, (Goal(goal),), None, difference=None)
    assert PaperEvaluator(goal_weight=0, difference_weight=0, top_goal_weight=1).evaluate(node) == 1
    assert top_goal_atoms_missing(Node(0, WorldModel(InitialModel([])), (Goal(goal),), None)) == 3


def test_fewer_goals_and_smaller_differences_win() -> None:
    evaluator = PaperEvaluator()
    shallow = make_node(subgoals=["A"])
    deep = make_node(subgoals=["A", "B"])
    assert evaluator.evaluate(shallow) < evaluator.evaluate(deep)
    assert evaluator.evaluate(make_node(difference=[1, 5])) < evaluator.evaluate(
        make_node(difference=[2])
    )


def test_defaults_lean_depth_first() -> None:
    """A fresh subgoal beats its parent once the parent has made it, and applying the
    subgoal's operator (which pops it) beats the subgoal node."""
    evaluator = PaperEvaluator()
    parent = make_node(subgoals=["A B"], successors=1, pending=[0])
    child = make_node(subgoals=["C D E", "A B"], pending=[0])
    applied = make_node(subgoals=["A B"], cost=1, pending=[0])
    assert evaluator.evaluate(child) < evaluator.evaluate(parent)
    assert evaluator.evaluate(applied) < evaluator.evaluate(child)


def test_next_pending_instance_is_the_one_measured() -> None:
    evaluator = PaperEvaluator(difference_weight=0, pending_weight=1, top_goal_weight=0)
    assert evaluator.evaluate(make_node(pending=[2, 0])) == 2
    assert evaluator.evaluate(make_node(pending=[])) == 0


@pytest.mark.parametrize(
    "options",
    [
        {"goal_weight": -1.0},
        {"successor_weight": float("nan")},
        {"cost_weight": "1"},
        {"pending_weight": True},
        {"predicate_weights": {"AT": -2}},
        {"predicate_weights": {"AT": "heavy"}},
        {"predicate_weights": [("AT", 1.0)]},
        {"predicate_weights": {"": 1.0}},
    ],
)
def test_bad_options_are_rejected_naming_the_option(options) -> None:
    with pytest.raises(OptionError) as raised:
        PaperEvaluator(**options)
    assert f"'{next(iter(options))}" in str(raised.value.args[0])


def test_weight_table_is_read_only_and_compared() -> None:
    table = {"AT": 2.0}
    evaluator = PaperEvaluator(predicate_weights=table)
    table["AT"] = 9.0
    assert evaluator.predicate_weights["AT"] == 2.0
    with pytest.raises(TypeError):
        evaluator.predicate_weights["AT"] = 3.0  # type: ignore[index]
    assert evaluator == PaperEvaluator(predicate_weights={"AT": 2.0})
    assert evaluator != PaperEvaluator()
    hash(evaluator)
