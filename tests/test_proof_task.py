"""A ProofTask refuses malformed values, so no prover ever sees one."""

import pytest

from strips_framework.logic.clauses import Clause
from strips_framework.logic.terms import Param
from strips_framework.worldmodel.proving import ProofTask
from strips_framework.worldmodel.world import InitialModel, WorldModel

GOAL = [Clause([(False, ("P", Param("m")))])]


@pytest.mark.parametrize(("options", "error", "message"), [
    ({"effort": 0}, ValueError, "'effort' must be >= 1"),
    ({"max_answers": 0}, ValueError, "'max_answers' must be >= 1"),
    ({"unique_names": "yes"}, TypeError, "'unique_names' must be"),
    ({"axioms": ["P(a)"]}, TypeError, r"ProofTask.axioms\[1\] must be a Clause, not str"),
    ({"axioms": [Clause([(True, "P")])]}, ValueError,
     r"axioms\[1\] .*: an atom must be a tuple \(predicate, \*args\), got 'P'"),
    ({"axioms": [Clause([(1, ("P", "a"))])]}, ValueError, "a literal must be a pair"),
    ({"axioms": [Clause([(True, ("P", 1.5))])]}, ValueError, r"1.5 in \('P', 1.5\) is not a term"),
    ({"axioms": [Clause([(True, ("P", -1))])]}, ValueError, "-1 in"),
    ({"axioms": [Clause([(True, ("P", ()))])]}, ValueError, r"\(\) in"),
])
def test_malformed_tasks_are_refused(options, error, message):
    with pytest.raises(error, match=message):
        ProofTask(**{"axioms": [], "negated_goal": GOAL, **options})


def test_well_formed_terms_are_accepted():
    axioms = [Clause([(True, ("P", "a", 0, Param("n"), ("f", "b", 1)))])]
    assert ProofTask(axioms, GOAL).effort == 1000


def test_the_fresh_task_of_a_model_carries_its_m0s_rigid_predicates():
    # A session sees them through model.initial; the fresh task it must answer like
    # must be told them too.
    initial = InitialModel([Clause([(True, ("P", "a"))])], rigid={("P", 1)})
    task = ProofTask.of_model(WorldModel(initial), GOAL, effort=10)
    assert task.rigid == {("P", 1)}
    assert [str(c) for c in task.axioms] == ["P(a)"]
