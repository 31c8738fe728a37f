"""The uncompleted proof of a prover that keeps none (strips_framework.worldmodel.residue):
the goal cut down by the model's facts and rewritten through its rules. E and the join
engine (``joins``) hand it to the difference extractor, so a means-ends search over them
finds the operators that add a rule's premise relevant, as over the resolution prover."""

from __future__ import annotations

from strips_framework.lifted.prover import JoinProver
from strips_framework.logic.clauses import Clause
from strips_framework.logic.terms import Param
from strips_framework.planner import Planner
from strips_framework.worldmodel.proving import SATURATED, ProofTask
from strips_framework.worldmodel.residue import residue

M = Param("m")


def unit(positive: bool, *atom: object) -> Clause:
    return Clause([(positive, tuple(atom))])


def test_uncompleted_proof_is_the_goal_cut_down_by_the_model() -> None:
    axioms = [unit(True, "P", "a"), Clause([(False, ("R", 0)), (True, ("Q", 0))])]
    goal = [Clause([(False, ("P", M)), (False, ("Q", M))])]
    texts = [str(c) for c in residue(ProofTask(axioms, goal))]
    # ~P(m) | ~Q(m) is subsumed by ~Q(a) [m=a]? No: that one made a binding. Both stay,
    # with the rule's subgoal ~R(a) for Q(a).
    assert texts[0] == "~P(m) | ~Q(m)"
    assert "~Q(a)  [m=a]" in texts and "~R(a)  [m=a]" in texts


def test_a_clause_another_subsumes_with_no_more_bindings_is_dropped() -> None:
    axioms = [unit(True, "P", "a"), unit(True, "S")]
    goal = [Clause([(False, ("S",)), (False, ("P", "a")), (False, ("Q", "a"))])]
    assert [str(c) for c in residue(ProofTask(axioms, goal))] == ["~Q(a)"]


def test_the_join_prover_fails_with_the_residue() -> None:
    """Not only the goal's atoms the model lacks: the rule's premise too."""
    axioms = [unit(True, "AT", "BOX1", "a"), Clause([(False, ("AT", 0, "b")), (True, ("DONE", 0))])]
    task = ProofTask(axioms, [Clause([(False, ("DONE", M)), (False, ("AT", M, "a"))])], unique_names=True)
    result = JoinProver().prove(task)
    assert result.status == SATURATED
    assert result.uncompleted == residue(task)
    assert "~AT(BOX1, b)  [m=BOX1]" in [str(c) for c in result.uncompleted]


def test_means_ends_over_joins_reaches_a_goal_only_a_rule_concludes(tmp_path) -> None:
    """DONE is no operator's: push is relevant only through the rule's premise AT(x, b)."""
    problem = tmp_path / "done.strips"
    problem.write_text(
        "problem done\nconstants a b BOX1\nprimitive AT/2\n"
        "facts\n  AT(BOX1, a)\n"
        "axioms\n  forall x: AT(x, b) -> DONE(x)\n"
        "operator push(k, m, n)\n  pre    AT(k, m)\n  delete AT(k, m)\n  add    AT(k, n)\n"
        "goal DONE(BOX1)\n"
    )
    planner = Planner.create({"prover": "joins"})
    result = planner.solve(planner.load(problem))
    assert result.solved and [str(s) for s in result.plan] == ["(push BOX1 a b)"]
