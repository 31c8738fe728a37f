"""Subsumption: the pre-filters and the matcher agree with the definition, and no test
runs unbounded.

Multi-literal subsumption is NP-complete; before the matcher was ordered and bounded,
case 512 of ``benchmarks/differential.py`` (the task below) spent minutes in one test.
The step counts asserted here are the matcher's own (:class:`MatchWork`), so the tests
say how much work a check took without timing anything.
"""

from __future__ import annotations

from itertools import permutations

from hypothesis import given, settings
from hypothesis import strategies as st

from strips_framework.logic.clauses import Clause, Literal
from strips_framework.logic.terms import Param
from strips_framework.worldmodel.proving import GAVE_UP, ProofTask
from strips_resolution_prover import ResolutionProver
from strips_resolution_prover.feature_index import FeatureVectorIndex, predicate_bucket
from strips_resolution_prover.pclause import PClause, from_clause
from strips_resolution_prover.subsumption import (
    MATCH_BUDGET,
    MatchWork,
    SubsumptionIndex,
    match_term,
    subsumes,
)


def _clause(*literals: Literal, bindings: tuple = ()) -> PClause:
    imported = from_clause(Clause(literals, bindings), sos=True)
    assert imported is not None
    return imported


def _nest(term: object, times: int) -> object:
    for _ in range(times):
        term = ("f", term)
    return term


def _r(first: object, var: int) -> Literal:
    return (False, ("R", first, var))


M, N = Param("m"), Param("n")
#: The pair the differential run's case 512 hung on: eight interchangeable literals in
#: the pattern, nine in the target, and a literal (``R(f⁹(c), X8)``) that matches nothing.
HUNG_PATTERN = _clause(
    *(_r(("f", "c"), i) for i in range(8)),
    _r(_nest("c", 9), 8),
    _r("c", 9),
    (True, ("=", "c", ("f", "c"))),
    bindings=((M, ("f", "c")), (N, "c")),
)
HUNG_TARGET = _clause(
    *(_r(("f", "c"), i) for i in range(9)),
    _r(_nest("c", 10), 9),
    _r("c", 10),
    (True, ("=", "c", ("f", "c"))),
    bindings=((M, ("f", "c")), (N, "c")),
)


def test_a_pattern_literal_without_a_match_ends_the_test_at_once() -> None:
    work = MatchWork()
    assert not subsumes(HUNG_PATTERN, HUNG_TARGET, work)
    # One pass over the literal pairs, no backtracking (plain backtracking tried every
    # injective mapping of the eight literals: millions of steps).
    assert work.steps <= len(HUNG_PATTERN.literals) * len(HUNG_TARGET.literals)


def test_interchangeable_literals_are_assigned_by_a_matching() -> None:
    # R(a, X) | R(X, Y) plus eight variable-disjoint ~R(f(c), _): the eight compete only
    # for target literals, which a bipartite matching settles without backtracking.
    pattern = _clause((True, ("R", "a", 20)), (True, ("R", 20, 21)), *(_r(("f", "c"), i) for i in range(8)))
    target = _clause((True, ("R", "a", "b")), (True, ("R", "b", "c")), *(_r(("f", "c"), i) for i in range(7)), _r(("f", "d"), 7))
    work = MatchWork()
    assert not subsumes(pattern, target, work)
    assert work.steps <= 2 * len(pattern.literals) * len(target.literals)
    fits = _clause(*target.literals[:-1], _r(("f", "c"), 7))
    assert subsumes(pattern, fits)


def test_independent_literals_still_map_one_to_one() -> None:
    # p(X, a) | p(Y, a) share no variable, and both match only p(a, a) in the first
    # target: the bipartite matching, not the substitution, says no.
    pattern = _clause((True, ("p", 0, "a")), (True, ("p", 1, "a")))
    assert not subsumes(pattern, _clause((True, ("p", "a", "a")), (True, ("p", "b", "b"))))
    assert subsumes(pattern, _clause((True, ("p", "a", "a")), (True, ("p", "b", "a"))))


def test_the_matcher_stops_at_its_budget() -> None:
    # A nine-cycle R(X0,X1), ..., R(X8,X0) into a two-coloured graph (every edge between
    # the a's and the b's): an odd cycle has no image there, which only exhaustive
    # search shows. "Not shown subsumed" is the sound answer when the budget runs out.
    cycle = _clause(*((True, ("R", i, (i + 1) % 9)) for i in range(9)))
    edges = [(True, ("R", a, b)) for a in ("a1", "a2", "a3") for b in ("b1", "b2", "b3")]
    graph = _clause(*edges, *((pos, (p, y, x)) for pos, (p, x, y) in edges))
    work = MatchWork()
    assert not subsumes(cycle, graph, work)
    assert work.steps <= MATCH_BUDGET + len(cycle.literals) * len(graph.literals) + 1


def test_differential_case_512_finishes_within_its_effort() -> None:
    # Facts S, Q(f(a)), P(f(b)), P(a); goal R(f(c), x) & n != m (no R fact: nothing
    # proves it, and equality with parameters may not be claimed Satisfiable).
    facts = [Clause([(True, atom)]) for atom in (("S",), ("Q", ("f", "a")), ("P", ("f", "b")), ("P", "a"))]
    goal = Clause([(False, ("R", ("f", "c"), 0)), (True, ("=", N, M))])
    task = ProofTask(facts, [goal], effort=60, max_answers=3)
    result = ResolutionProver().prove(task)
    assert result.status == GAVE_UP
    assert result.effort_used <= task.effort


# -- against the definition ----------------------------------------------------------

TERMS = st.sampled_from(["a", "b", 0, 1, 2]) | st.tuples(st.just("f"), st.sampled_from(["a", 0, 1]))
LITERALS = st.tuples(
    st.booleans(), st.sampled_from(["P", "Q"]).flatmap(lambda p: st.tuples(st.just(p), TERMS, TERMS))
)


def _by_definition(c: PClause, d: PClause) -> bool:
    """Some injective, sign- and predicate-preserving map of literals with one
    substitution (targets' variables are constants here)."""
    for image in permutations(d.literals, len(c.literals)):
        subst: dict[int, object] = {}
        if all(
            pos == tpos and match_term(atom, tatom, subst)
            for (pos, atom), (tpos, tatom) in zip(c.literals, image, strict=True)
        ):
            return True
    return False


@settings(max_examples=300, derandomize=True, database=None, deadline=None)
@given(
    c=st.lists(LITERALS, min_size=1, max_size=3, unique=True),
    d=st.lists(LITERALS, min_size=1, max_size=4, unique=True),
)
def test_subsumes_agrees_with_the_definition(c: list[Literal], d: list[Literal]) -> None:
    pattern = from_clause(Clause(c), sos=True)
    target = from_clause(Clause(d), sos=True)
    if pattern is None or target is None:
        return  # a tautology
    assert subsumes(pattern, target) == _by_definition(pattern, target)


@settings(max_examples=200, derandomize=True, database=None, deadline=None)
@given(
    units=st.lists(LITERALS, min_size=1, max_size=6),
    d=st.lists(LITERALS, min_size=1, max_size=3, unique=True),
)
def test_the_unit_index_finds_every_matching_unit(units: list[Literal], d: list[Literal]) -> None:
    # Units are filed by the top symbols of their arguments and looked up under every
    # generalization of a literal's: a unit with a variable, or the same symbol, at
    # each position. Whatever the index skips must be a unit that does not match.
    index = SubsumptionIndex()
    for unit in units:
        clause = from_clause(Clause([unit]), sos=True)
        assert clause is not None
        index.add(clause, deletable=True)
    target = from_clause(Clause(d), sos=True)
    if target is None:
        return
    expected = any(
        pos == tpos and match_term(_renumbered(atom), tatom, {})
        for pos, atom in units
        for tpos, tatom in target.literals
    )
    assert index.is_subsumed_by_unit(target) == expected


def _renumbered(atom: tuple) -> tuple:
    clause = from_clause(Clause([(True, atom)]), sos=True)
    assert clause is not None
    return clause.literals[0][1]


FUNCTION_LITERALS = st.tuples(
    st.booleans(),
    st.sampled_from(["P", "Q", "R", "S"]).flatmap(
        lambda p: st.tuples(st.just(p), TERMS, st.one_of(TERMS, st.tuples(st.just("g"), TERMS)))
    ),
)


@settings(max_examples=200, derandomize=True, database=None, deadline=None)
@given(
    kept=st.lists(st.lists(FUNCTION_LITERALS, min_size=2, max_size=3, unique=True), max_size=8),
    d=st.lists(FUNCTION_LITERALS, min_size=2, max_size=4, unique=True),
)
def test_the_feature_vector_index_finds_every_subsumer_and_every_subsumed(
    kept: list[list[Literal]], d: list[Literal]
) -> None:
    # Forward: the index shows d subsumed iff some kept clause subsumes it. Backward:
    # it yields exactly the kept clauses d subsumes. Whatever a feature (literals per
    # sign and predicate bucket, symbols, bindings) prunes must not be a subsumer.
    index = SubsumptionIndex()
    clauses = []
    for n, literals in enumerate(kept):
        clause = from_clause(Clause(literals), sos=True)
        if clause is None:
            continue
        clause.id = n
        index.add(clause, deletable=True)
        clauses.append(clause)
    target = from_clause(Clause(d), sos=True)
    if target is None:
        return
    target.id = len(kept)
    expected = any(_by_definition(c, target) for c in clauses)
    assert index.is_subsumed(target, MatchWork()) == expected
    backward = {c.id for c in index.subsumed_by(target, MatchWork())}
    assert backward == {c.id for c in clauses if _by_definition(target, c)}


def test_the_index_never_offers_a_clause_with_more_of_a_feature() -> None:
    # Candidates the trie walk offers, before any test on them: P(X) | P(Y) has two
    # positive P literals, more than P(a) | Q(a); P(X) | ~Q(Y) has a positive P, which
    # ~P(a) | Q(b) has not (same counts per sign, other predicates per sign).
    assert predicate_bucket("P", 2) != predicate_bucket("Q", 2)
    index = FeatureVectorIndex[str]()
    two_p = _clause((True, ("P", 0, 0)), (True, ("P", 1, 1)))
    p_not_q = _clause((True, ("P", 0, 0)), (False, ("Q", 1, 1)))
    index.add(two_p.vector, "two P")
    index.add(p_not_q.vector, "P, not Q")
    assert list(index.at_most(_clause((True, ("P", "a", "a")), (True, ("Q", "a", "a"))).vector)) == []
    assert list(index.at_most(_clause((False, ("P", "a", "a")), (True, ("Q", "b", "b"))).vector)) == []
    assert list(index.at_most(_clause((True, ("P", "a", "a")), (True, ("P", "b", "b"))).vector)) == [
        "two P"
    ]


def test_backward_subsumption_finds_the_longer_clauses_it_subsumes() -> None:
    index = SubsumptionIndex()
    longer = _clause((True, ("P", "a")), (True, ("Q", "a")), (True, ("R", "b")))
    longer.id = 1
    index.add(longer, deletable=True)
    general = _clause((True, ("P", 0)), (True, ("Q", 0)))
    general.id = 2
    assert list(index.subsumed_by(general, MatchWork())) == [longer]


def test_a_clause_with_a_binding_subsumes_one_with_the_same_binding() -> None:
    # Filed under its binding m := a, found from the subsumed clause's own bindings.
    index = SubsumptionIndex()
    subsumer = _clause((False, ("P", 0)), (False, ("Q", 0)), bindings=((M, "a"),))
    subsumer.id = 1
    index.add(subsumer, deletable=True)
    target = _clause((False, ("P", "b")), (False, ("Q", "b")), bindings=((M, "a"),))
    assert index.is_subsumed(target, MatchWork())
    other = _clause((False, ("P", "b")), (False, ("Q", "b")), bindings=((M, "c"),))
    assert not index.is_subsumed(other, MatchWork())
