"""Deciding a goal by the model's facts (:mod:`strips_framework.worldmodel.fact_join`,
:meth:`GoalProver.decide`) and the attempt it shortens (:meth:`GoalProver.attempt`)."""

from itertools import combinations, product

from strips_framework.formats.native import parse_problem
from strips_framework.logic.formulas import And, Atomic, Exists, Not, Var
from strips_framework.logic.terms import Param
from strips_framework.means_ends.goal_prover import GoalProver
from strips_framework.worldmodel.fact_join import facts_join
from strips_resolution_prover import ResolutionProver

# ON and CLEAR hold only as facts; ABOVE is concluded by a rule, so the prover must be
# asked about any goal that has it.
WORLD = """
problem join
constants a b c d
primitive ON/2 CLEAR/1 ABOVE/2

facts
  ON(a, b)
  ON(b, c)
  CLEAR(a)
  CLEAR(d)

axioms
  forall x, y: ON(x, y) -> ABOVE(x, y)

operator move(x, y, z)
  pre    ON(x, y) & CLEAR(x) & CLEAR(z)
  delete ON(x, y), CLEAR(z)
  add    ON(x, z), CLEAR(y)

goal ON(a, d)
"""

X, Y = Var("x"), Var("y")
K, M = Param("k"), Param("m")
TERMS = ("a", "d", K, X)


def _prover(effort: int = 300, difference_effort: int | None = None) -> GoalProver:
    problem = parse_problem(WORLD, "join.strips")
    return GoalProver(problem, ResolutionProver(), effort, difference_effort=difference_effort)


def _goals():
    """Every conjunction of one or two ON/CLEAR atoms over constants, a parameter and an
    existential variable; with an inequality too where the parameter is in each atom
    and ``a`` in one (a failed attempt with one saturates only after hundreds of given
    clauses): ``k != a``."""
    atoms = [Atomic(("ON", s, t)) for s, t in product(TERMS, repeat=2)]
    atoms += [Atomic(("CLEAR", t)) for t in TERMS]
    for size in (1, 2):
        for parts in combinations(atoms, size):
            yield parts
            if all(K in part.atom for part in parts) and any("a" in p.atom for p in parts):
                yield (*parts, Not(Atomic(("=", K, "a"))))


def _formula(parts):
    body = And(list(parts))
    has_x = any(X in part.atom[1:] for part in parts if isinstance(part, Atomic))
    return Exists([X], body) if has_x else body


def test_the_facts_decide_a_conjunctive_goal_as_the_prover_does():
    """On M0 and on the model after move(a, b, d), every goal the join decides gets the prover's
    answer (given effort enough), and most are decided."""
    prover = _prover(effort=1000)
    root = prover.root_model()
    after = root.changed(frozenset({("ON", "a", "b"), ("CLEAR", "d")}),
                         frozenset({("ON", "a", "d"), ("CLEAR", "b")}))
    assert after != root
    decided = undecided = 0
    for model in (root, after):
        for parts in _goals():
            goal = _formula(parts)
            verdict = prover.decide(model, goal)
            if verdict is None:
                undecided += 1
                continue
            decided += 1
            assert verdict == prover.prove(model, goal).proved, goal
    assert decided > 10 * undecided


def test_a_goal_with_a_predicate_a_rule_concludes_is_left_to_the_prover():
    prover = _prover()
    model = prover.root_model()
    above = And([Atomic(("ABOVE", "a", "b")), Atomic(("CLEAR", "a"))])
    assert prover.decide(model, above) is None
    assert prover.prove(model, above).proved


def test_an_inequality_is_decided_by_names_when_both_sides_have_one():
    """``k != m`` with ``m`` in no atom: no name for ``m``, so the facts cannot say;
    with both bound by facts, two names are distinct exactly when they differ."""
    prover = _prover()
    model = prover.root_model()
    goal = And([Atomic(("CLEAR", K)), Not(Atomic(("=", K, M)))])
    assert prover.decide(model, goal) is None
    distinct = And([Atomic(("CLEAR", K)), Atomic(("ON", K, M)), Not(Atomic(("=", K, M)))])
    assert prover.decide(model, distinct) is True  # ON(a, b), CLEAR(a): a != b
    only_a = Exists([X], And([Atomic(("CLEAR", K)), Atomic(("ON", K, X)),
                              Not(Atomic(("=", K, "a")))]))
    assert prover.decide(model, only_a) is False  # only k = a matches
    assert not prover.prove(model, only_a).proved


def test_a_join_that_runs_out_of_budget_is_undecided():
    prover = _prover()
    model = prover.root_model()
    # Both ON facts are tried before CLEAR(c) is found missing below each.
    goal = Exists([X, Y], And([Atomic(("ON", X, Y)), Atomic(("CLEAR", Y))]))
    literals = prover.negated(goal)[0].literals
    assert facts_join(model, literals) is False
    assert facts_join(model, literals, budget=1) is None


def test_an_attempt_on_a_goal_the_facts_refute_stops_at_the_difference_effort():
    """The uncompleted proof of a goal known false is built within ``difference_effort``;
    a goal that may be provable gets the full effort."""
    prover = _prover(effort=300, difference_effort=2)
    model = prover.root_model()
    false = Exists([X, Y], And([Atomic(("ON", X, Y)), Atomic(("CLEAR", Y)), Atomic(("CLEAR", X))]))
    assert prover.decide(model, false) is False
    result = prover.attempt(model, false)
    assert not result.proved and result.effort_used <= 2
    full = _prover(effort=300)
    assert full.attempt(model, false).effort_used > 2
    true = And([Atomic(("ON", K, "b")), Atomic(("CLEAR", K))])
    assert prover.attempt(model, true).proved
