"""``goal_selection``: goal clauses over Horn axioms resolve on chosen literals only."""

from __future__ import annotations

import pytest

from strips_framework.errors import ConfigError
from strips_framework.logic.clauses import Clause
from strips_framework.planner import Planner
from strips_framework.plugin.config import Config
from strips_framework.logic.terms import Param
from strips_framework.testing.session_checks import check_session_agrees_with_fresh_tasks
from strips_framework.worldmodel.proving import PROVED, SATURATED, ProofTask
from strips_framework.worldmodel.world import InitialModel, WorldModel
from strips_resolution_prover import ResolutionProver

F, X = Param("f"), Param("x")
SLD = ResolutionProver(goal_selection="fewest")
SHARED = ResolutionProver(goal_selection="fewest-shared")


def fact(*atom: object) -> Clause:
    return Clause([(True, atom)])


def goal(*atoms: tuple) -> list[Clause]:
    return [Clause([(False, atom) for atom in atoms])]


def _board_task() -> ProofTask:
    """Elevators' board(p, e, f, n1, n2) where the passenger is nowhere: a failed attempt."""
    n1, n2 = Param("n1"), Param("n2")
    axioms = [
        *[fact("floor", f"f{i}") for i in range(6)],
        *[fact("count", f"c{i}") for i in range(6)],
        *[fact("next", f"c{i}", f"c{i + 1}") for i in range(5)],
        fact("lift-at", "e", "f1"), fact("passengers", "e", "c0"),
    ]
    wanted = goal(("floor", F), ("count", n1), ("count", n2), ("lift-at", "e", F),
                  ("passenger-at", "p", F), ("passengers", "e", n1), ("next", n1, n2))
    return ProofTask(axioms, wanted, effort=10_000)


def test_a_failed_conjunctive_goal_does_not_resolve_every_subset_of_it() -> None:
    plain, sld = ResolutionProver().prove(_board_task()), SLD.prove(_board_task())
    assert plain.status == sld.status == SATURATED
    assert sld.effort_used * 5 < plain.effort_used
    # What is left is what the model cannot show: the difference.
    assert str(min(sld.uncompleted, key=lambda c: len(c.literals))) == (
        "~passenger-at(p, f1)  [f=f1, n1=c0, n2=c1]"
    )


def test_literals_tied_at_fewest_partners_all_bind_so_both_differences_are_offered() -> None:
    # board(p, e, f): the lift is on floor 1, the passenger on floor 2.
    axioms = [fact("lift-at", "e", "f1"), fact("passenger-at", "p", "f2")]
    result = SLD.prove(ProofTask(axioms, goal(("lift-at", "e", F), ("passenger-at", "p", F))))
    assert result.status == SATURATED
    left = {str(c) for c in result.uncompleted if len(c.literals) == 1}
    assert left == {"~passenger-at(p, f1)  [f=f1]", "~lift-at(e, f2)  [f=f2]"}


def test_answers_are_those_of_resolving_every_literal() -> None:
    axioms = [
        *[fact("room", r) for r in ("r1", "r2", "r3")],
        fact("door", "r1", "r2"), fact("door", "r2", "r3"),
        Clause([(False, ("door", 0, 1)), (True, ("link", 0, 1))]),
    ]
    wanted = goal(("room", X), ("link", X, "r3"))
    for task in (ProofTask(axioms, wanted, max_answers=5), ProofTask(axioms, goal(("link", X, F)), max_answers=5)):
        plain, sld = ResolutionProver().prove(task), SLD.prove(task)
        assert sld.status == plain.status == PROVED
        assert sorted(sld.answers) == sorted(plain.answers)


def test_non_horn_axioms_keep_the_plain_calculus() -> None:
    # P | Q is not Horn: a goal clause resolved on one literal would not be complete.
    axioms = [Clause([(True, ("P",)), (True, ("Q",))]), Clause([(False, ("P",)), (True, ("R", "a"))]),
              Clause([(False, ("Q",)), (True, ("R", "a"))]), fact("S", "a"), fact("T", "a")]
    task = ProofTask(axioms, goal(("R", "a"), ("S", "a"), ("T", "a")), effort=1000)
    plain, sld = ResolutionProver().prove(task), SLD.prove(task)
    assert sld.status == plain.status == PROVED
    assert sld.effort_used == plain.effort_used


def test_fewest_shared_also_binds_a_variable_from_the_other_literals_that_hold_it() -> None:
    # leave(p, lift, n4): slow1 is at n4, slow0 is not; the passenger is in neither.
    lift = Param("lift")
    axioms = [fact("lift-at", "slow1", "n4"), fact("elevator", "slow0"), fact("elevator", "slow1")]
    task = ProofTask(axioms, goal(("elevator", lift), ("lift-at", lift, "n4"), ("boarded", "p", lift)))
    fewest = {str(c) for c in SLD.prove(task).uncompleted}
    shared = {str(c) for c in SHARED.prove(task).uncompleted}
    assert "~boarded(p, slow1)  [lift=slow1]" in fewest & shared
    assert "~lift-at(slow0, n4) | ~boarded(p, slow0)  [lift=slow0]" in shared - fewest


def test_a_variable_in_a_literal_nothing_resolves_is_bound_through_rigid_literals() -> None:
    # The same leave(p, lift, n4), told that no operator changes elevator: boarded(p, lift)
    # has no partner, so the model cannot settle lift, and every lift is offered, not
    # only the one now at n4.
    lift = Param("lift")
    axioms = [fact("lift-at", "slow1", "n4"), fact("elevator", "slow0"), fact("elevator", "slow1")]
    wanted = goal(("elevator", lift), ("lift-at", lift, "n4"), ("boarded", "p", lift))
    rigid = {("elevator", 1)}
    by_task = SLD.prove(ProofTask(axioms, wanted, rigid=rigid))
    # A session learns them from its M0.
    initial = InitialModel(axioms, rigid=rigid)
    by_session = SLD.open(initial, unique_names=False).prove(WorldModel(initial), wanted, 1000)
    for result in (by_task, by_session):
        left = {str(c) for c in result.uncompleted}
        assert "~boarded(p, slow1)  [lift=slow1]" in left
        assert "~lift-at(slow0, n4) | ~boarded(p, slow0)  [lift=slow0]" in left


def test_a_variable_two_changeable_literals_bind_is_bound_through_rigid_literals() -> None:
    # load-airplane(obj, plane, loc): the package is at pos2, the plane at apt1, and the
    # plan needs both at apt2, which neither literal's partners offer.
    loc = Param("loc")
    axioms = [fact("at", "obj", "pos2"), fact("at", "plane", "apt1"),
              *[fact("place", p) for p in ("pos2", "apt1", "apt2")]]
    wanted = goal(("place", loc), ("at", "obj", loc), ("at", "plane", loc))
    left = {str(c) for c in SLD.prove(ProofTask(axioms, wanted, rigid={("place", 1)})).uncompleted}
    assert "~at(obj, apt2) | ~at(plane, apt2)  [loc=apt2]" in left
    assert "~at(plane, pos2)  [loc=pos2]" in left
    # A variable the model settles is bound through the facts: one literal binds loc.
    settled = goal(("place", loc), ("at", "plane", loc), ("ready", "plane"))
    left = {str(c) for c in SLD.prove(ProofTask(axioms, settled, rigid={("place", 1)})).uncompleted}
    assert "~ready(plane)  [loc=apt1]" in left
    assert not any("apt2" in clause for clause in left)
    # So is one two literals bind alike: both are at apt1 already.
    together = [fact("at", "obj", "apt1"), *axioms[1:]]
    wanted = goal(("place", loc), ("at", "obj", loc), ("at", "plane", loc), ("ready", "plane"))
    left = {str(c) for c in SLD.prove(ProofTask(together, wanted, rigid={("place", 1)})).uncompleted}
    assert "~ready(plane)  [loc=apt1]" in left
    assert not any("apt2" in clause for clause in left)


def test_a_goal_clause_resting_on_a_false_rigid_atom_is_no_difference() -> None:
    # No lift reaches n9, and no operator can change that: nothing is left to achieve.
    lift = Param("lift")
    axioms = [fact("reaches", "slow0", "n1"), fact("lift-at", "slow0", "n1")]
    wanted = goal(("boarded", "p", lift), ("reaches", lift, "n9"))
    result = SLD.prove(ProofTask(axioms, wanted, rigid={("reaches", 2)}))
    assert result.status == SATURATED
    assert result.uncompleted == ()
    # Were reaches an operator's to change, the clause would be the difference.
    assert SLD.prove(ProofTask(axioms, wanted)).uncompleted


def test_a_session_on_a_model_with_rigid_predicates_answers_as_fresh_tasks() -> None:
    for seed in range(3):
        check_session_agrees_with_fresh_tasks(SLD, SLD.capabilities, seed)


def test_a_value_outside_the_choices_is_a_config_error_naming_them() -> None:
    config = Config.from_dict({"prover": {"name": "resolution", "goal_selection": "all"}}, "x.toml")
    with pytest.raises(ConfigError, match=r"x.toml: bad value for 'prover.goal_selection': "
                       r"expected one of 'every', 'fewest', 'fewest-shared', got 'all'"):
        Planner.create(config)
