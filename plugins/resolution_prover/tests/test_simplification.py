"""Simplification by retained units: unit cutting, backward demodulation, and the
discrimination tree that finds the units. Each test fails when its part is removed."""

from __future__ import annotations

import random

from strips_framework.formats.tptp import parse_tptp, szs_status
from strips_framework.logic.clauses import Clause
from strips_framework.logic.terms import Param, Term
from strips_framework.worldmodel.proving import ProofTask
from strips_resolution_prover import ResolutionProver
from strips_resolution_prover.discrimination import DiscriminationTree
from strips_resolution_prover.prover import _attempt
from strips_resolution_prover.subsumption import match_term

SATURATE = {"schedule": False, "set_of_support": False}


def status(text: str, effort: int, **options: object) -> str:
    problem = parse_tptp(text)
    return szs_status(problem, ResolutionProver(**options).prove(problem.task(effort)))


def processed(text: str, effort: int = 10) -> tuple[set[str], set[str]]:
    """The clauses a saturation of ``text`` processed within ``effort``: the live ones
    and the dead (replaced) ones."""
    attempt = _attempt(ResolutionProver(**SATURATE), parse_tptp(text).task(effort))
    attempt.start(1)
    attempt.advance(effort)
    clauses = attempt.own.processed
    return {str(c.to_clause()) for c in clauses if not c.dead}, {
        str(c.to_clause()) for c in clauses if c.dead
    }


def test_a_unit_cuts_the_literals_it_refutes() -> None:
    # p(X, f(X)) cuts all three literals of the rule as it is imported, leaving q, which
    # meets ~q at once. Resolving them away one at a time takes 4 to 6 given clauses.
    text = (
        "cnf(u, axiom, p(X, f(X))). "
        "cnf(r, axiom, ~p(a, f(a)) | ~p(b, f(b)) | ~p(c, f(c)) | q). "
        "cnf(g, negated_conjecture, ~q)."
    )
    for options in (SATURATE, {"schedule": False}):
        assert status(text, effort=3, **options) == "Unsatisfiable"


def test_a_disequation_cuts_the_equation_either_way_round() -> None:
    # f(X) != X matches a = f(a) only read as f(a) = a; the cut leaves q when the clause
    # is picked, so it is never processed (superposition would derive q only from it).
    live, dead = processed("cnf(d, axiom, f(X) != X). cnf(e, axiom, a = f(a) | q).")
    assert live | dead == {"f(x0) != x0", "q"}


def test_a_given_clause_is_simplified_by_units_retained_after_it_was_queued() -> None:
    # Both input clauses are queued before any unit is retained; when picked, the rule
    # is cut by s(f(b)) to ~q(f(f(a))), and that cuts the first clause to r(f(f(b))):
    # neither original is ever processed.
    live, dead = processed(
        "cnf(c, axiom, q(f(f(a))) | r(f(f(b)))). cnf(u, axiom, s(f(b))). "
        "cnf(k, axiom, ~s(f(b)) | ~q(f(f(a))))."
    )
    assert live | dead == {"s(f(b))", "~q(f(f(a)))", "r(f(f(b)))"}


def test_no_more_answers_than_asked_when_one_clause_gives_several() -> None:
    # Q(m) & m != n under unique names: one given clause makes three refutations at once
    # (n := a, c, d); two were asked for.
    m, n = Param("m"), Param("n")
    facts = [Clause([(True, ("Q", "b"))]), Clause([(True, ("R", "a", "c"))])]
    facts.append(Clause([(True, ("R", "d", "d"))]))
    goal = [Clause([(True, ("=", m, n)), (False, ("Q", m))])]
    task = ProofTask(facts, goal, effort=500, max_answers=2, unique_names=True)
    result = ResolutionProver().prove(task)
    assert result.proved and len(result.answers) == 2


def test_a_new_equation_rewrites_the_clauses_kept_before_it() -> None:
    # p(c) is light and picked first; c = a is derived later and orients c -> a, so the
    # retained p(c) is replaced by p(a) (backward demodulation).
    live, dead = processed(
        "cnf(k, axiom, p(c)). cnf(e, axiom, ~r | ~s | c = a). cnf(r, axiom, r). "
        "cnf(s, axiom, s).",
        effort=50,
    )
    assert "c = a" in live
    assert "p(c)" in dead and "p(a)" in live


def _random_term(rng: random.Random, depth: int) -> Term:
    roll = rng.random()
    if depth == 0 or roll < 0.3:
        return rng.randrange(3) if rng.random() < 0.5 else rng.choice(("a", "b", Param("p")))
    return (rng.choice(("f", "g")), *[_random_term(rng, depth - 1) for _ in range(rng.randint(1, 2))])


def test_the_tree_finds_every_atom_that_matches() -> None:
    # Against brute force: every filed atom that matches the query is among the
    # candidates, including those with repeated variables, parameters and nested terms.
    rng = random.Random(10)
    tree: DiscriminationTree[int] = DiscriminationTree()
    atoms = [("P", _random_term(rng, 2), _random_term(rng, 2)) for _ in range(300)]
    for i, atom in enumerate(atoms):
        tree.add(atom, i)
    found_any = 0
    for _ in range(300):
        query = ("P", _random_term(rng, 3), _random_term(rng, 3))
        candidates = list(tree.generalizations(query))
        matching = {i for i, atom in enumerate(atoms) if match_term(atom, query, {})}
        assert matching <= set(candidates)
        assert len(candidates) == len(set(candidates))
        found_any += bool(matching)
        # Candidates are few: never an atom with a clashing symbol.
        clashing = [i for i in candidates if not _fits(atoms[i], query)]
        assert not clashing
    assert found_any > 50


def _fits(pattern: Term, target: Term) -> bool:
    """Whether ``pattern`` matches ``target`` with its variables taken as all distinct."""
    if type(pattern) is int:
        return True
    if type(pattern) is tuple:
        return (
            type(target) is tuple
            and pattern[0] == target[0]
            and len(pattern) == len(target)
            and all(_fits(p, t) for p, t in zip(pattern[1:], target[1:]))
        )
    return pattern == target
