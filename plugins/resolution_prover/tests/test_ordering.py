"""Literal maximality: ordered resolution and superposition infer only on literals no
other literal of their clause is above (KBO's multiset extension on literals)."""

from __future__ import annotations

from strips_framework.logic.clauses import Clause
from strips_framework.worldmodel.proving import PROVED, SATURATED, ProofTask
from strips_resolution_prover import ResolutionProver
from strips_resolution_prover.equality import paramodulants
from strips_resolution_prover.inference import RENAME_OFFSET, Limits, eligible
from strips_resolution_prover.kbo import literal_greater
from strips_resolution_prover.pclause import PClause, from_clause, offset

BIG = ("f", ("f", "a"))


def _pc(*literals) -> PClause:
    clause = from_clause(Clause(literals), sos=True)
    assert clause is not None
    return clause


def _rewritten(source: PClause, target: PClause, ordered: bool) -> set:
    """The literals of the paramodulants from ``source`` into ``target`` (saturating)."""
    source.id, target.id = 1, 2
    renamed = tuple((pos, offset(atom, RENAME_OFFSET)) for pos, atom in source.literals)
    made = paramodulants(source, renamed, [target], Limits(None), saturating=True, ordered=ordered)
    return {lit for clause in made for lit in clause.literals}


def test_the_literal_ordering() -> None:
    # Equations as multisets of their sides; a negative literal above its positive twin;
    # an atom A as A = TOP, below an equation with a bigger side.
    assert literal_greater((True, ("=", BIG, "b")), (True, ("=", "c", "d")))
    assert literal_greater((False, ("=", "a", "b")), (True, ("=", "a", "b")))
    assert literal_greater((False, ("p", "a")), (True, ("p", "a")))
    assert literal_greater((True, ("=", ("p_term", BIG), "b")), (True, ("p", "a")))
    assert not literal_greater((True, ("p", 0)), (True, ("q", 1)))  # variables: no order


def test_a_positive_clause_with_equations_is_eligible_only_on_its_maximal_literals() -> None:
    literals = ((True, ("=", "c", "d")), (True, ("=", BIG, "b")), (True, ("p", "a")))
    assert eligible(literals, selecting=True, ordered=True) == (1,)
    # Unordered (an answer search with parameters), every literal.
    assert eligible(literals, selecting=True, ordered=False) == (0, 1, 2)


def test_superposition_rewrites_only_from_and_into_maximal_literals() -> None:
    # f(f(a)) = b | c = d: only f(f(a)) = b is maximal, so c = d (oriented d -> c)
    # rewrites nothing; into q(d) | r(f(f(a)), d), only the maximal r(...) is rewritten.
    source = _pc((True, ("=", BIG, "b")), (True, ("=", "c", "d")))
    target = _pc((True, ("q", "d")), (True, ("r", BIG, "d")))
    rewritten = _rewritten(source, target, ordered=True)
    assert (True, ("r", "b", "d")) in rewritten
    assert (True, ("q", "c")) not in rewritten and (True, ("r", BIG, "c")) not in rewritten
    assert (True, ("q", "c")) in _rewritten(source, target, ordered=False)


def test_maximality_keeps_saturation_sound_and_complete() -> None:
    # Refuted with ordering on (no parameters), and a satisfiable set still saturates.
    axioms = [
        Clause([(True, ("=", ("f", "a"), "a")), (True, ("p", "b"))]),
        Clause([(False, ("p", "b"))]),
    ]
    goal = [Clause([(False, ("=", ("f", ("f", "a")), "a"))])]
    assert ResolutionProver().prove(ProofTask(axioms, goal, effort=200)).status == PROVED
    sat = [Clause([(True, ("=", ("f", "a"), "a")), (True, ("p", "b"))])]
    prover = ResolutionProver(schedule=False, set_of_support=False)
    assert prover.prove(ProofTask([], sat, effort=200)).status == SATURATED


def test_superposition_rewrites_a_clause_only_in_its_maximal_literals() -> None:
    # d = c (oriented d -> c) into q(d) | r(f(f(a)), d): only the maximal r(...) is
    # rewritten; unordered (with parameters), q(d) too.
    source = _pc((True, ("=", "d", "c")))
    target = _pc((True, ("q", "d")), (True, ("r", BIG, "d")))
    rewritten = _rewritten(source, target, ordered=True)
    assert (True, ("r", BIG, "c")) in rewritten and (True, ("q", "c")) not in rewritten
    assert (True, ("q", "c")) in _rewritten(source, target, ordered=False)
