"""Relevant operator instances from a difference (III.C)."""

from strips_framework.logic.clauses import Clause
from strips_framework.logic.formulas import And, Atomic
from strips_framework.logic.terms import Param
from strips_framework.problem import OperatorSchema
from strips_framework.relevance import AddListRelevance
from strips_framework.search.node import Difference

k, m, n = Param("k"), Param("m"), Param("n")
GOTO = OperatorSchema("goto", [m, n], Atomic(("ATR", m)), [("ATR", n)], [("ATR", m)])
PUSH = OperatorSchema(
    "push", [k, m, n], And([Atomic(("AT", k, m)), Atomic(("ATR", m))]),
    [("AT", k, n), ("ATR", n)], [("AT", k, m), ("ATR", m)],
)


def test_papers_example_two_instances_of_goto():
    difference = Difference([Clause([(False, ("ATR", "a")), (False, ("ATR", "b"))])])
    found = AddListRelevance().relevant(difference, [GOTO, PUSH])
    names = sorted(str(r.operator) for r in found)
    assert names == ["goto(m, a)", "goto(m, b)", "push(k, m, a)", "push(k, m, b)"]
    by_name = {str(r.operator): str(r.resolvent) for r in found}
    assert by_name["goto(m, a)"] == "~ATR(b)"


def test_smaller_resolvents_rank_first_and_unbindable_instances_are_dropped():
    difference = Difference([
        Clause([(False, ("AT", "BOX1", 0)), (False, ("AT", "BOX2", 0))]),
        Clause([(False, ("AT", "BOX2", "b"))]),
    ])
    found = AddListRelevance().relevant(difference, [PUSH])
    # push(BOX1, m, x) would leave n unbound (it is not in the precondition): dropped.
    assert [str(r.operator) for r in found] == ["push(BOX2, m, b)"]
    assert found[0].resolvent.literals == ()


def test_instance_bound_to_another_operators_parameter_is_dropped():
    goal_param = Param("m")
    difference = Difference([Clause([(False, ("ATR", goal_param))])])
    assert AddListRelevance().relevant(difference, [GOTO]) == []
