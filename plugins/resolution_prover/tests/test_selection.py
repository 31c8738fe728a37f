"""Given-clause selection: the weight, refined-weight and age queues and their cycle."""

from __future__ import annotations

from strips_framework.logic.terms import ANSWER
from strips_resolution_prover.pclause import PClause
from strips_resolution_prover.selection import ClauseQueue, refined_picks, refined_weight

X = 0  # a variable in a PClause


def clause(cid: int, *atoms: tuple) -> PClause:
    made = PClause(tuple((True, atom) for atom in atoms), 1, (), sos=True)
    made.id = cid
    return made


def test_refined_weight_multiplies_the_heaviest_literals_and_ignores_answer_literals() -> None:
    # p(a) weighs 4 and q(x) 3: doubled 8 and 6, the heaviest at 1.5 times.
    assert refined_weight(clause(0, ("p", "a"), ("q", X)).literals) == 12 + 6
    # Two heaviest literals are both multiplied.
    assert refined_weight(clause(0, ("p", "a"), ("q", "b")).literals) == 12 + 12
    with_answer = clause(0, ("p", "a"), ("q", X), (ANSWER, ("f", ("f", "a"))))
    assert refined_weight(with_answer.literals) == 12 + 6


def test_the_cycle_picks_by_weight_then_by_refined_weight_then_by_age() -> None:
    # The oldest clause is the heaviest by both weights; two unit clauses weigh 9 (refined
    # 27), a three-literal clause 10 (refined 24): lighter by refined weight, where the
    # clause is used upon its light maximal literals only.
    oldest = clause(0, ("s", ("f", ("f", ("f", ("f", ("f", "a")))))))
    unit = clause(1, ("r", ("f", ("f", ("f", X)))))
    other_unit = clause(2, ("t", ("g", ("g", ("g", X)))))
    spread = clause(3, ("p", "a"), ("q", X), ("u", X))
    assert (unit.weight, spread.weight) == (9, 10)
    queue = ClauseQueue(pick_given_ratio=1, unit_preference=0, refined_picks=1)
    for made in (oldest, unit, other_unit, spread):
        queue.push(made)
    picks = [queue.pop() for _ in range(4)]
    assert picks == [unit, spread, oldest, other_unit]
    assert queue.pop() is None


def test_without_refined_picks_the_cycle_is_weight_then_age() -> None:
    oldest = clause(0, ("s", ("f", ("f", ("f", ("f", ("f", "a")))))))
    unit = clause(1, ("r", ("f", ("f", ("f", X)))))
    spread = clause(2, ("p", "a"), ("q", X), ("u", X))
    queue = ClauseQueue(pick_given_ratio=1, unit_preference=0)
    for made in (oldest, unit, spread):
        queue.push(made)
    assert [queue.pop() for _ in range(3)] == [unit, oldest, spread]


def test_refined_picks_only_in_saturation_unless_configured() -> None:
    # The set of support (the planner's attempts on world models) keeps its search.
    assert refined_picks(None, saturating=False) == 0
    assert refined_picks(None, saturating=True) > 0
    assert refined_picks(2, saturating=False) == 2
    assert refined_picks(0, saturating=True) == 0
