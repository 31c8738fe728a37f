"""SInE axiom selection and its place in the automatic mode."""

from __future__ import annotations

from strips_framework.logic.clauses import Clause
from strips_framework.worldmodel.proving import PROVED, ProofTask
from strips_resolution_prover import ResolutionProver
from strips_resolution_prover.axiom_relevance import relevant_axioms

X = 0


def pos(predicate: str, *args: object) -> tuple[bool, tuple]:
    return True, (predicate, *args)


def neg(predicate: str, *args: object) -> tuple[bool, tuple]:
    return False, (predicate, *args)


# ~p(a) follows only through k: A1 is triggered by p (its rarest symbol, m is in three
# axioms), A2 and A3 by k, which nothing reached names, A4 by b.
A1 = Clause([pos("p", X), neg("m", X)], label="A1")
A2 = Clause([pos("m", X), neg("k", X)], label="A2")
A3 = Clause([pos("k", X)], label="A3")
A4 = Clause([pos("m", "b")], label="A4")
GOAL = [Clause([neg("p", "a")])]


def test_an_axiom_is_kept_when_one_of_its_rarest_symbols_is_reached() -> None:
    assert relevant_axioms([A1, A2, A3, A4], GOAL) == [A1]
    # Reaching k keeps A2 and A3; A2's m reaches neither A1 (triggered by p only) nor A4
    # (by b only).
    assert relevant_axioms([A1, A2, A3, A4], [Clause([neg("k", "a")])]) == [A2, A3]


def test_the_clauses_of_one_formula_go_together_and_skolem_symbols_trigger_nothing() -> None:
    # subset's definition: three clauses, one Skolem function in two of them.
    sk = ("sk!1", X, 1)
    subset = [
        Clause([neg("subset", X, 1), neg("member", 2, X), pos("member", 2, 1)], label="s"),
        Clause([pos("subset", X, 1), pos("member", sk, X)], label="s"),
        Clause([pos("subset", X, 1), neg("member", sk, 1)], label="s"),
    ]
    power = [Clause([neg("member", X, ("power", 1)), pos("subset", X, 1)], label="pw")]
    goal = [Clause([neg("subset", "a", "b")])]
    assert relevant_axioms(subset + power, goal) == subset


def test_a_formula_whose_clauses_have_other_rarest_symbols_stays_whole() -> None:
    # f and g occur nowhere else, so the second clause alone would never be reached.
    d = [Clause([neg("d", X), pos("e", X)], label="D"), Clause([pos("f", X), neg("g", X)], label="D")]
    assert relevant_axioms(d, [Clause([neg("d", "a")])]) == d


def test_a_proof_from_the_relevant_axioms_stands_but_their_saturation_claims_nothing() -> None:
    # As above, but m(a) follows through a chain k1 <- k2 <- ... <- k12, which takes the
    # whole task's runs longer than the relevant axioms (A1) take to saturate.
    chain = [Clause([pos("m", X), neg("k1", X)], label="C0")]
    chain += [Clause([pos(f"k{i}", X), neg(f"k{i + 1}", X)], label=f"C{i}") for i in range(1, 12)]
    chain += [Clause([pos("k12", X)], label="C12")]
    axioms = [A1, *chain, A4]
    assert relevant_axioms(axioms, GOAL) == [A1]
    result = ResolutionProver().prove(ProofTask(axioms, GOAL, effort=400))
    assert result.status == PROVED
