"""The relaxed-plan evaluator on a road of places A - B - C (and an unconnected D), with
its relaxation grounded and explored lifted (every test runs with both)."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from shared_bench import small_bench

from strips_evaluators import relaxed_plan
from strips_evaluators.relaxed_plan import (
    RelaxedPlanEvaluator,
    _LiftedRelaxedTask,
    _positive_atoms,
    _RelaxedTask,
)
from strips_framework.logic.cnf import SkolemNames
from strips_framework.logic.terms import is_ground
from strips_framework.pddl import load_task, to_problem
from strips_framework.worldmodel.world import initial_model
from strips_framework.logic.clauses import Clause
from strips_framework.logic.formulas import And, Atomic, Exists, Formula, Not, Var
from strips_framework.logic.terms import Param
from strips_framework.means_ends.components import evaluator_for_problem
from strips_framework.means_ends.node import Goal, Node
from strips_framework.worldmodel.operators import OperatorInstance
from strips_framework.worldmodel.problem import OperatorSchema
from strips_framework.worldmodel.world import InitialModel, WorldModel

X, Y = Param("x"), Param("y")
#: go(x, y): from x to a connected y; it also lights y (one achiever, two atoms).
GO = OperatorSchema(
    "go",
    [X, Y],
    And([Atomic(("AT", X)), Atomic(("ROAD", X, Y)), Not(Atomic(("=", X, Y)))]),
    [("AT", Y), ("LIT", Y)],
    [("AT", X)],
)
FACTS = [("AT", "A"), ("ROAD", "A", "B"), ("ROAD", "B", "C"), ("ROAD", "C", "C")]


def _model(facts: list[tuple]) -> WorldModel:
    return WorldModel(InitialModel([Clause([(True, fact)]) for fact in facts]))


M0 = _model(FACTS)


def _node(*goals: Goal, cost: int = 0, successors: int = 0, model: WorldModel = M0) -> Node:
    node = Node(id=0, model=model, goals=goals, parent=None)
    node.plan = (OperatorInstance(GO, [(X, "A"), (Y, "B")]),) * cost
    node.successors_generated = successors
    return node


RELAXATION = "ground"


@pytest.fixture(autouse=True, params=["ground", "lifted"])
def relaxation(request: pytest.FixtureRequest, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(globals(), "RELAXATION", request.param)


def _score(node: Node, **options: object) -> float:
    options.setdefault("relaxation", RELAXATION)
    evaluator = RelaxedPlanEvaluator(**options)  # type: ignore[arg-type]
    return evaluator_for_problem(evaluator, [GO], node.model.initial).evaluate(node)


def _goal(*atoms: tuple, operator: OperatorInstance | None = None) -> Goal:
    formula: Formula = And([Atomic(a) for a in atoms]) if len(atoms) > 1 else Atomic(atoms[0])
    return Goal(formula, operator)


def test_counts_the_relaxed_plan_to_the_top_goal() -> None:
    assert _score(_node(_goal(("AT", "C")))) == 2
    assert _score(_node(_goal(("AT", "C"))), estimate="add") == 2


def test_ff_counts_a_shared_achiever_once_and_hadd_twice() -> None:
    both = _node(_goal(("AT", "B"), ("LIT", "B")))
    assert _score(both) == 1
    assert _score(both, estimate="add") == 2


def test_an_operator_on_the_goal_list_takes_over_what_it_adds() -> None:
    """Subgoaling on go(B, C) keeps the score level: the operator now on the list adds
    AT(C), so only its precondition AT(B) is left for the relaxed plan."""
    go_bc = OperatorInstance(GO, [(X, "B"), (Y, "C")])
    top = _goal(("AT", "C"))
    subgoal = Goal(go_bc.precondition(), go_bc)
    assert _score(_node(subgoal, top)) == 1 + 1 == _score(_node(top))


def test_an_add_atom_with_an_unbound_parameter_provides_nothing() -> None:
    """go(B, y) on the list adds AT(y) for a y its proof has not chosen yet, so AT(C)
    below it still needs go(B, C): AT(B) and AT(C) in the relaxed plan, not AT(B) only."""
    go_from_b = OperatorInstance(GO, [(X, "B")])
    subgoal = Goal(go_from_b.precondition(), go_from_b)
    assert _score(_node(subgoal, _goal(("AT", "C")))) == 1 + 2


def test_a_later_goal_binds_the_atoms_given_to_it_jointly() -> None:
    """go(B, C) on the list gives LIT(C) to the goal below it, but that goal's LIT(v) and
    ROAD(A, v) share v, and ROAD(A, C) is false: v = B, and LIT(B) costs go(A, B) (hadd
    counts it apart from the AT(B) of go(B, C)'s precondition)."""
    go_bc = OperatorInstance(GO, [(X, "B"), (Y, "C")])
    v = Var("v")
    lit_next_to_a = Goal(Exists([v], And([Atomic(("LIT", v)), Atomic(("ROAD", "A", v))])))
    node = _node(Goal(go_bc.precondition(), go_bc), lit_next_to_a)
    assert _score(node, estimate="add") == 1 + 1 + 1


def test_a_given_atom_binds_a_later_goal_for_free() -> None:
    """go(B, C) on the list gives LIT(C), and ROAD(C, C) holds: v = C costs nothing,
    where v = B would cost go(A, B)."""
    go_bc = OperatorInstance(GO, [(X, "B"), (Y, "C")])
    v = Var("v")
    lit_before_c = Goal(Exists([v], And([Atomic(("LIT", v)), Atomic(("ROAD", v, "C"))])))
    node = _node(Goal(go_bc.precondition(), go_bc), lit_before_c)
    assert _score(node, estimate="add") == 1 + 1


def test_a_parameter_costs_its_cheapest_ground_atom() -> None:
    """go(x, C) needs AT(x) & ROAD(x, C) together: x = B costs one step, x = C two
    (AT(A) and ROAD(B, C) each cost nothing alone, but they do not share an x)."""
    go_to_c = OperatorInstance(GO, [(Y, "C")])
    subgoal = Goal(go_to_c.precondition(), go_to_c)
    assert _score(_node(subgoal, _goal(("AT", "C")))) == 1 + 1


def test_the_cheapest_binding_wins_wherever_it_comes() -> None:
    """Roads A -> C <-> B. Grounding from AT(A) meets LIT(C) first; from AT(C), though,
    LIT(C) costs two steps (there and back) and LIT(B) one."""
    m0 = _model([("AT", "A"), ("ROAD", "A", "C"), ("ROAD", "C", "B"), ("ROAD", "B", "C")])
    at_c = m0.changed(frozenset({("AT", "A")}), frozenset({("AT", "C")}))
    assert _score(_node(_goal(("LIT", Param("z"))), model=at_c)) == 1


def test_existential_variables_are_bound_like_parameters() -> None:
    v = Var("v")
    lit_somewhere = Goal(Exists([v], And([Atomic(("LIT", v)), Atomic(("ROAD", v, "C"))])))
    assert _score(_node(lit_somewhere)) == 1


def test_an_unreachable_goal_is_a_dead_end() -> None:
    assert _score(_node(_goal(("AT", "D")))) == math.inf


def test_inequality_is_decided_when_grounding() -> None:
    """go(C, C) is excluded by x != y, so LIT(C) needs go(B, C) and LIT(A) is never made."""
    assert _score(_node(_goal(("LIT", "C")))) == 2
    assert _score(_node(_goal(("LIT", "A")))) == math.inf


def test_cost_and_successors_are_weighted() -> None:
    node = _node(_goal(("AT", "C")), cost=2, successors=3)
    assert _score(node) == 2 + 0.5 * 2 + 1.0 * 3
    assert _score(node, cost_weight=1.0, successor_weight=0.0) == 2 + 2


def test_refuses_to_score_without_its_problem() -> None:
    with pytest.raises(TypeError, match="for_problem"):
        RelaxedPlanEvaluator().evaluate(_node(_goal(("AT", "C"))))


def test_one_scorer_gives_each_model_its_own_costs() -> None:
    """The costs kept per model (a search returns to a few models often) are never those
    of another model, in whatever order the nodes come."""
    scorer = evaluator_for_problem(RelaxedPlanEvaluator(), [GO], M0.initial)
    at_b = M0.changed(frozenset({("AT", "A")}), frozenset({("AT", "B")}))
    go_bc = OperatorInstance(GO, [(X, "B"), (Y, "C")])
    top = _goal(("AT", "C"))
    scores = [
        scorer.evaluate(_node(*goals, model=model))
        for model in (M0, at_b, M0, at_b)
        for goals in ((top,), (Goal(go_bc.precondition(), go_bc), top))
    ]
    assert scores == [2, 2, 1, 1] * 2


LOCAL_PDDL = Path(__file__).parents[3] / "tests" / "pddl" / "data"
IPC = small_bench("ipc")
TRANSLATABLE = ["blocks-3", "rooms-1", "crates-3", "lamps-1"]
IPC_TASKS = ["logistics/task01", "gripper/task01", "depot/task01", "rovers/task01"]


def _translated(name: str) -> tuple[Path, Path]:
    if "/" in name:
        return IPC / name.split("/")[0] / "domain.pddl", IPC / f"{name}.pddl"
    return LOCAL_PDDL / (name.rsplit("-", 1)[0] + "-domain.pddl"), LOCAL_PDDL / f"{name}.pddl"


@pytest.mark.parametrize("name", TRANSLATABLE + IPC_TASKS)
def test_the_lifted_relaxation_reaches_the_ground_ones_costs(name: str) -> None:
    """On translated PDDL tasks (type atoms, complement predicates, equalities), the
    relaxation explored lifted gives every fact the hadd cost the ground one gives, from
    M0 and from the models one step away."""
    problem = to_problem(load_task(*_translated(name)))
    initial = initial_model(problem, SkolemNames())
    ground = _RelaxedTask.ground(problem.operators, initial)
    lifted = _LiftedRelaxedTask(problem.operators, initial)
    assert ground is not None
    atom_of = {number: atom for atom, number in ground.fact_ids.items()}
    models = [WorldModel(initial)]
    for schema in problem.operators:
        for binding in ground.index.bindings(_positive_atoms(schema.precondition), []):
            instance = OperatorInstance(schema, [(p, binding[p]) for p in schema.parameters if p in binding])
            deleted, added = instance.effects()
            if all(is_ground(atom) for atom in (*deleted, *added)):
                models.append(models[0].changed(frozenset(deleted), frozenset(added)))
                break
    for model in models:
        ground_cost = {atom_of[fact]: value for fact, value in ground._hadd(model)[0].items()}
        lifted_cost = lifted._hadd(model)[0]
        assert ground_cost == {atom: lifted_cost[atom] for atom in ground_cost}
        assert set(lifted_cost) - set(ground_cost) <= {a for a in model.facts()}


def test_auto_explores_lifted_once_grounding_passes_its_limit(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(relaxed_plan, "GROUND_INSTANCES", 1)
    scorer = RelaxedPlanEvaluator(relaxation="auto").for_problem([GO], M0.initial)
    assert isinstance(scorer.task, _LiftedRelaxedTask)
    assert _score(_node(_goal(("AT", "C"))), relaxation="auto") == 2
    monkeypatch.setattr(relaxed_plan, "GROUND_INSTANCES", 1000)
    scorer = RelaxedPlanEvaluator(relaxation="auto").for_problem([GO], M0.initial)
    assert not isinstance(scorer.task, _LiftedRelaxedTask)


def test_an_inequality_in_a_precondition_is_kept() -> None:
    """mark(x, y) needs x != y: with only LINK(A, A), MARK(A) is out of reach."""
    mark = OperatorSchema(
        "mark", [X, Y], And([Atomic(("AT", X)), Atomic(("LINK", X, Y)), Not(Atomic(("=", X, Y)))]),
        [("MARK", Y)], [],
    )  # fmt: skip
    model = _model([("AT", "A"), ("LINK", "A", "A"), ("LINK", "A", "B")])
    evaluator = RelaxedPlanEvaluator(relaxation=RELAXATION)
    scorer = evaluator_for_problem(evaluator, [mark], model.initial)
    assert scorer.evaluate(_node(_goal(("MARK", "A")), model=model)) == math.inf
    assert scorer.evaluate(_node(_goal(("MARK", "B")), model=model)) == 1
