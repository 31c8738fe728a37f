"""Every way a status could be wrong, each shown on a problem that exposes it.

A wrong ``Unsatisfiable`` makes invalid plans, a wrong ``Satisfiable`` loses them. Each
test below names the part of the calculus whose breakage it catches; breaking that part
(the mutants listed in the plugin's README) makes the test fail, since the problem is
decided only when the part works. Problems are TPTP text, run in both configurations:
with a set of support and without (literal selection).
"""

from __future__ import annotations

import pytest

from strips_framework.formats.tptp import parse_tptp, szs_status
from strips_framework.logic.clauses import Clause
from strips_framework.worldmodel.proving import GAVE_UP, PROVED, SATURATED
from strips_resolution_prover import ResolutionProver
from strips_resolution_prover.demodulation import Demodulators
from strips_resolution_prover.kbo import greater
from strips_resolution_prover.pclause import PClause, from_clause
from strips_resolution_prover.subsumption import subsumes

CONFIGS = {
    "sos": {"schedule": False},
    "no-sos": {"schedule": False, "set_of_support": False},
    "auto": {},
}
configs = pytest.mark.parametrize("options", CONFIGS.values(), ids=list(CONFIGS))


def status(text: str, effort: int = 500, **options: object) -> str:
    problem = parse_tptp(text)
    return szs_status(problem, ResolutionProver(**options).prove(problem.task(effort)))


@configs
def test_factoring_of_given_clauses(options: dict) -> None:
    # Refutable only with factors of both clauses; with the first an axiom it is the
    # given clauses' factors (set of support) or the factoring rule itself (selection).
    assert status("cnf(a, axiom, p(X) | p(Y)). cnf(b, negated_conjecture, ~p(U) | ~p(V)).",
                  **options) == "Unsatisfiable"  # fmt: skip
    assert status("cnf(a, plain, p(X) | p(Y)). cnf(b, plain, ~p(U) | ~p(V)).",
                  **options) == "Unsatisfiable"  # fmt: skip


@configs
def test_subsumption_respects_polarity_and_instances(options: dict) -> None:
    # p(a) must not delete ~p(a) | q (polarity), nor p(X) | r(X) delete p(a) | r(b).
    assert status("cnf(a, plain, p(a)). cnf(b, plain, ~p(a) | q). cnf(c, plain, ~q).",
                  **options) == "Unsatisfiable"  # fmt: skip
    assert status("cnf(a, plain, p(X) | r(X)). cnf(b, plain, p(a) | r(b)). "
                  "cnf(c, plain, ~p(a)). cnf(d, plain, ~r(b)).", **options) == "Unsatisfiable"  # fmt: skip


@configs
def test_subsumption_makes_saturation_finite(options: dict) -> None:
    # p(f(X)) | q(Y), p(f(f(X))) | q(Y), ... are all instances of p(X) | q(Y): only
    # forward subsumption (of a non-unit clause) stops the chain.
    text = "cnf(a, plain, p(X) | q(Y)). cnf(b, plain, ~p(X) | p(f(X))). cnf(c, plain, ~q(a) | r)."
    assert status(text, effort=200, **options) == "Satisfiable"



def _clause(*literals: tuple[bool, tuple]) -> PClause:
    imported = from_clause(Clause(literals), sos=True)
    assert imported is not None
    return imported


def test_subsumption_maps_literals_one_to_one_with_their_signs() -> None:
    # p(X,X) | ~p(Y,Z) matches ~p(a,a) | p(a,b) only with the signs swapped.
    assert not subsumes(
        _clause((True, ("p", 0, 0)), (False, ("p", 1, 2))),
        _clause((False, ("p", "a", "a")), (True, ("p", "a", "b"))),
    )
    # r(X,Y) | r(Y,X) reaches r(a,a) | r(b,c) only by using r(a,a) twice (multiset).
    assert not subsumes(
        _clause((True, ("r", 0, 1)), (True, ("r", 1, 0))),
        _clause((True, ("r", "a", "a")), (True, ("r", "b", "c"))),
    )
    assert subsumes(
        _clause((True, ("r", 0, 1)), (False, ("p", 1))),
        _clause((True, ("r", "a", "b")), (False, ("p", "b")), (True, ("q",))),
    )


def test_unit_subsumption_of_new_clauses() -> None:
    # An axiom of the set of support is never deleted, so only the unit p(X) stops
    # p(f(X)), p(f(f(X))), ... as they are derived.
    text = "cnf(a, axiom, ~p(X) | p(f(X))). cnf(b, negated_conjecture, p(X))."
    assert status(text, effort=200) == "Satisfiable"


@configs
def test_paramodulation_both_ways_and_below_the_top(options: dict) -> None:
    # From the axiom into the goal, under a function symbol, and with a side literal.
    assert status("fof(e, axiom, f(a) = b). fof(p, axiom, p(g(f(a)))). "
                  "fof(c, conjecture, p(g(b))).", **options) == "Theorem"  # fmt: skip
    # From the goal's descendants into an axiom: the goal's equation is the only one.
    assert status("fof(p, axiom, ![X]: (q(X) => p(h(X)))). fof(q, axiom, q(a)). "
                  "fof(c, conjecture, a = b => p(h(b))).", **options) == "Theorem"  # fmt: skip
    assert status("cnf(e, plain, a = b | s). cnf(n, plain, ~s). cnf(p, plain, p(a)). "
                  "cnf(q, plain, ~p(b)).", **options) == "Unsatisfiable"  # fmt: skip


@configs
def test_no_satisfiable_claim_with_equality_from_an_incomplete_calculus(options: dict) -> None:
    # A pet/owner puzzle with <=> and =, satisfiable only if "owner" were not a function:
    # whatever the search does, it may not report CounterSatisfiable for a theorem, and
    # an equality problem it did not refute is GaveUp (the classic calculus is not
    # complete for equality).
    pets = """
        fof(owner_unique, axiom, ![P, X, Y]: ((owns(X, P) & owns(Y, P)) => X = Y)).
        fof(pet_def, axiom, ![P]: (pet(P) <=> ?[X]: owns(X, P))).
        fof(rex, axiom, pet(rex)).
        fof(who, axiom, owns(ann, rex) | owns(bob, rex)).
        fof(not_bob, axiom, ~owns(bob, rex)).
        fof(walks, axiom, ![X, P]: (walks(X, P) <=> (owns(X, P) & pet(P)))).
        fof(goal, conjecture, walks(ann, rex) & ![X]: (owns(X, rex) => X = ann)).
    """
    assert status(pets, **options) == "Theorem"
    assert status(pets, effort=3, **options) == GAVE_UP
    assert status("fof(a, axiom, f(a) = a). fof(c, conjecture, p(a)).", effort=20,
                  schedule=False) == GAVE_UP  # fmt: skip


def test_superposition_saturation_is_claimed_only_where_it_is_complete() -> None:
    # Without a set of support the calculus is superposition: a saturated set with
    # equality is satisfiable (f(a) = a and ~p(a) have a model)...
    satisfiable = "fof(a, axiom, f(a) = a). fof(c, conjecture, p(a))."
    assert status(satisfiable, effort=20) == "CounterSatisfiable"
    assert status(satisfiable, effort=20, schedule=False, set_of_support=False) == (
        "CounterSatisfiable"
    )
    # ... but not under unique names (evaluated, not axioms of the search) ...
    problem = parse_tptp(satisfiable)
    assert ResolutionProver().prove(problem.task(20, unique_names=True)).status == GAVE_UP
    # ... nor with parameters, which III.A binds only to some terms.
    question = parse_tptp("fof(a, axiom, f(a) = a). fof(q, question, ?[X]: p(X)).")
    assert ResolutionProver().prove(question.task(20)).status == GAVE_UP


@configs
def test_superposition_from_a_variable_side(options: dict) -> None:
    # Everything equals a, so p(b) and ~p(c) clash: only x = a used from its variable
    # side (x := b, x := c) shows it; without that rule saturation would claim a model.
    text = "cnf(e, plain, X = a). cnf(p, plain, p(b)). cnf(n, plain, ~p(c))."
    assert status(text, **options) == "Unsatisfiable"
    assert status("cnf(e, plain, X = a | q(X)). cnf(p, plain, p(b)). cnf(n, plain, ~p(c)). "
                  "cnf(r, plain, ~q(b)). cnf(s, plain, ~q(c)).", **options) == "Unsatisfiable"  # fmt: skip


def test_set_of_support_with_inconsistent_axioms_claims_nothing() -> None:
    # The goal is never touched, but the axioms alone are contradictory, so it follows:
    # a set of support is complete only over satisfiable axioms.
    text = "cnf(a, axiom, p | q). cnf(b, axiom, ~p). cnf(c, axiom, ~q). fof(g, conjecture, r)."
    assert status(text, schedule=False) == GAVE_UP
    assert status(text, schedule=False, set_of_support=False) == "Theorem"
    assert status(text) == "Theorem"  # the automatic mode saturates first
    # Axioms that all have a positive literal are satisfiable: saturation is shown.
    assert status("cnf(a, axiom, p | ~q). cnf(b, axiom, q). fof(g, conjecture, r).") == (
        "CounterSatisfiable"
    )


@configs
def test_discarded_clauses_make_saturation_inconclusive(options: dict) -> None:
    # The refutation needs p(f(f(f(a)))), heavier than max_weight allows: giving up is
    # right, "Satisfiable" would be wrong.
    text = "cnf(a, plain, p(a)). cnf(b, plain, ~p(X) | p(f(X))). cnf(c, plain, ~p(f(f(f(a)))))."
    assert status(text, **options) == "Unsatisfiable"
    assert status(text, max_weight=6, **options) == GAVE_UP
    assert status(text, max_term_depth=1, **options) == GAVE_UP


def test_unique_names_refute_distinct_constants() -> None:
    prover = ResolutionProver()
    problem = parse_tptp("fof(a, axiom, p(a)). fof(c, conjecture, ?[X]: (p(X) & X != b)).")
    assert prover.prove(problem.task(100, unique_names=True)).status == PROVED
    # Without unique names a may be b: the negated goal has a model, which superposition
    # (the automatic mode's choice: the goal has =) shows and the set of support may not
    # claim.
    assert prover.prove(problem.task(100)).status == SATURATED
    assert ResolutionProver(schedule=False).prove(problem.task(100)).status == GAVE_UP


@configs
def test_unique_names_instantiate_equations(options: dict) -> None:
    # exists x: x != a follows once another name is known (x := b); with a only, it does
    # not (a one-element world), and without unique names it does not either.
    prover = ResolutionProver(**options)
    problem = parse_tptp("fof(a, axiom, p(b)). fof(c, conjecture, ?[X]: X != a).")
    assert prover.prove(problem.task(100, unique_names=True)).proved
    assert not prover.prove(problem.task(100)).proved
    alone = parse_tptp("fof(c, conjecture, ?[X]: X != a).")
    assert not prover.prove(alone.task(100, unique_names=True)).proved
    # ... and as an axiom under a set of support: everything is a, yet b is not a.
    contradiction = parse_tptp("fof(a, axiom, ![X]: X = a). fof(b, axiom, p(b)). "
                               "fof(c, conjecture, q).")  # fmt: skip
    assert prover.prove(contradiction.task(100, unique_names=True)).proved


def test_kbo_orients_by_weight_then_precedence_and_never_against_variables() -> None:
    assert greater(("f", ("g", 0)), 0) and not greater(0, ("f", 0))
    assert greater(("f", "a", "b"), "a")
    assert greater("b", "a") and not greater("a", "b")  # same weight: the precedence
    assert not greater(("f", 0), ("g", 1)) and not greater(("g", 1), ("f", 0))  # x vs y
    assert greater(("i", ("i", 0)), ("i", 0))


def test_demodulation_rewrites_to_normal_form() -> None:
    # f(f(x)) = x and g(a) = f(a): p(g(f(f(g(a))))) is rewritten to p(g(f(a))).
    demodulators = Demodulators()
    for clause in (_clause((True, ("=", ("f", ("f", 0)), 0))),
                   _clause((True, ("=", ("g", "a"), ("f", "a"))))):  # fmt: skip
        clause.id = 7
        demodulators.add(clause)
    literals, used = demodulators.rewrite(((True, ("p", ("g", ("f", ("f", ("g", "a")))))),))
    assert literals == ((True, ("p", ("g", ("f", "a")))),) and used
    # And a problem that needs it: with f(f(x)) = x, p(f^6(a)) is p(a).
    assert status("cnf(i, axiom, f(f(X)) = X). cnf(p, axiom, p(a)). "
                  "cnf(g, negated_conjecture, ~p(f(f(f(f(f(f(a)))))))).", effort=4) == (
        "Unsatisfiable"
    )
