"""Clause-form conversion, checked against known results and by brute force.

The brute-force check is exact on a finite domain: for every interpretation I of the
input's predicates over {0, 1}, the formula is true in I exactly when some
interpretation of the fresh Skolem functions and definition predicates makes every
clause true in I. That is the property Skolemization and renaming must preserve.
"""

from __future__ import annotations

import itertools
import random
from collections.abc import Iterator

import pytest

from strips_framework.logic.clauses import Clause
from strips_framework.logic.cnf import SkolemNames, clausify, negated_goal_clauses
from strips_framework.logic.formulas import (
    And,
    Atomic,
    Exists,
    Forall,
    Formula,
    Iff,
    Implies,
    Not,
    Or,
    Truth,
    Var,
)
from strips_framework.logic.parser import parse_formula
from strips_framework.logic.terms import Param

DOMAIN = (0, 1)
SIGNATURE = {"P": 1, "Q": 1, "R": 2, "S": 0}

Interpretation = dict[str, object]  # predicate -> set of tuples, function -> dict or value


def clauses_of(text: str, distribution_limit: int = 24) -> list[str]:
    formula = parse_formula(text, params={"m", "n"})
    clauses = clausify(formula, skolem=SkolemNames(), distribution_limit=distribution_limit)
    return [str(c) for c in clauses]


# --- known results ------------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("P & Q | R & S", ["P | R", "P | S", "Q | R", "Q | S"]),
        ("P -> Q", ["~P | Q"]),
        ("P <-> Q", ["~P | Q", "P | ~Q"]),
        ("~(P <-> Q)", ["~P | ~Q", "P | Q"]),
        ("~(P -> Q)", ["P", "~Q"]),
        ("forall x, y, z: R3(x, y, z) -> R3(x, z, y)", ["~R3(x0, x1, x2) | R3(x0, x2, x1)"]),
        ("P | ~P", []),
        ("P | P | Q", ["P | Q"]),
        ("(P | Q) & (Q | P)", ["P | Q", "Q | P"]),
        ("(P | Q) & (P | Q)", ["P | Q"]),
        ("true", []),
        ("false", ["false"]),
        ("false | P", ["P"]),
        ("P & false", ["false"]),
        ("P | true", []),
        ("a = a", []),
        ("a != a | P", ["P"]),
        ("forall x: x = x", []),
    ],
)
def test_known_clause_forms(text: str, expected: list[str]) -> None:
    assert clauses_of(text) == expected


def test_skolem_functions_take_the_enclosing_universal_variables() -> None:
    assert clauses_of("forall x: exists y: R(x, y)") == ["R(x0, sk!1(x0))"]
    assert clauses_of("exists y: forall x: R(x, y)") == ["R(x0, sk!1)"]
    # Only the universals the existential's body depends on: z is not an argument.
    assert clauses_of("forall x, z: P(z) & exists y: R(x, y)") == ["P(x0)", "R(x0, sk!1(x0))"]
    assert clauses_of("forall x: exists y: forall z: exists w: T(x, y, z, w)") == [
        "T(x0, sk!1(x0), x1, sk!2(x0, x1))"
    ]
    # A negated universal is existential, and vice versa.
    assert clauses_of("~forall x: P(x)") == ["~P(sk!1)"]
    assert clauses_of("~exists x: P(x)") == ["~P(x0)"]


def test_variables_are_numbered_in_order_of_appearance_per_clause() -> None:
    assert clauses_of("forall x, y: R(y, x) & (P(y) | Q(x))") == [
        "R(x0, x1)",
        "P(x0) | Q(x1)",
    ]


def test_parameters_stay_parameters_and_are_no_skolem_arguments() -> None:
    formula = parse_formula("P(m) & exists x: R(x, m)", params={"m"})
    clauses = clausify(formula, label="pre", skolem=SkolemNames())
    assert [c.literals for c in clauses] == [
        ((True, ("P", Param("m"))),),
        ((True, ("R", "sk!1", Param("m"))),),
    ]
    assert {c.label for c in clauses} == {"pre"}


def test_one_skolem_names_instance_never_repeats_a_name() -> None:
    names = SkolemNames()
    first = clausify(parse_formula("exists x: P(x)"), skolem=names)
    second = clausify(parse_formula("exists x: P(x)"), skolem=names)
    assert [str(c) for c in first + second] == ["P(sk!1)", "P(sk!2)"]


def test_negated_goal_clauses() -> None:
    goal = parse_formula("exists x: AT(BOX1, x) & AT(BOX2, x)")
    (clause,) = negated_goal_clauses(goal, SkolemNames())
    assert clause == Clause(
        ((False, ("AT", "BOX1", 0)), (False, ("AT", "BOX2", 0))),
    )
    assert clause.label == "negated goal"
    (skolemized,) = negated_goal_clauses(parse_formula("forall x: P(x)"), SkolemNames())
    assert str(skolemized) == "~P(sk!1)"


def test_an_unbound_variable_is_a_programming_error() -> None:
    with pytest.raises(ValueError, match="variable x is not bound"):
        clausify(Atomic(("P", Var("x"))), skolem=SkolemNames())
    with pytest.raises(ValueError, match="variable x is not bound"):
        clausify(Exists([Var("y")], Atomic(("R", Var("x"), Var("y")))), skolem=SkolemNames())


def test_large_distributions_are_renamed_not_multiplied() -> None:
    text = " | ".join(f"(A{i} & B{i})" for i in range(20))  # 2^20 clauses by distribution
    clauses = clauses_of(text)
    assert len(clauses) <= 24 + 2 * 20
    assert any(c.startswith("~def!") for c in clauses)


def test_definitions_take_the_free_variables_and_parameters() -> None:
    clauses = clauses_of("forall x: (P(x) & Q(x)) | (R(x, m) & S)", distribution_limit=1)
    assert clauses == [
        "def!1(x0) | def!2(x0, m)",
        "~def!1(x0) | P(x0)",
        "~def!1(x0) | Q(x0)",
        "~def!2(x0, m) | R(x0, m)",
        "~def!2(x0, m) | S",
    ]


# --- brute force on a finite domain -------------------------------------------------

x, y, z = Var("x"), Var("y"), Var("z")


def atom(name: str, *args: object) -> Atomic:
    return Atomic((name, *args))


SEMANTIC_CASES: list[Formula] = [
    Forall([x], Exists([y], atom("R", x, y))),
    Exists([y], Forall([x], atom("R", x, y))),
    Forall([x], Implies(atom("P", x), Exists([y], And([atom("R", x, y), atom("Q", y)])))),
    Iff(Forall([x], atom("P", x)), Exists([y], atom("Q", y))),
    Not(Iff(Exists([x], atom("P", x)), Forall([y], Or([atom("Q", y), atom("S")])))),
    Forall([x], Iff(atom("P", x), Exists([y], And([atom("R", x, y), Not(atom("P", y))])))),
    Or([Exists([x], And([atom("P", x), atom("Q", x)])), Truth(False)]),
    Exists([x], Forall([y], Implies(atom("R", x, y), Exists([z], atom("R", y, z))))),
    Not(Forall([x], Exists([y], Or([atom("R", x, y), And([atom("P", y), atom("S")])])))),
    Forall([x], Or([And([atom("P", x), atom("Q", x)]), And([atom("R", x, x), atom("S")])])),
]


def evaluate(f: Formula, interp: Interpretation, env: dict[Var, int]) -> bool:
    if isinstance(f, Atomic):
        return tuple(env[a] for a in f.atom[1:]) in interp[f.atom[0]]  # type: ignore[operator]
    if isinstance(f, Truth):
        return f.value
    if isinstance(f, Not):
        return not evaluate(f.body, interp, env)
    if isinstance(f, And):
        return all(evaluate(p, interp, env) for p in f.parts)
    if isinstance(f, Or):
        return any(evaluate(p, interp, env) for p in f.parts)
    if isinstance(f, Implies):
        return not evaluate(f.premise, interp, env) or evaluate(f.conclusion, interp, env)
    if isinstance(f, Iff):
        return evaluate(f.left, interp, env) == evaluate(f.right, interp, env)
    quantifier = all if isinstance(f, Forall) else any
    return quantifier(
        evaluate(f.body, interp, {**env, **dict(zip(f.variables, values))})
        for values in itertools.product(DOMAIN, repeat=len(f.variables))
    )


def value(term: object, interp: Interpretation, assignment: dict[int, int]) -> int:
    if type(term) is int:
        return assignment[term]
    if type(term) is str:
        return interp[term]  # type: ignore[return-value]
    args = tuple(value(a, interp, assignment) for a in term[1:])  # type: ignore[index]
    return interp[term[0]][args]  # type: ignore[index]


def clauses_hold(clauses: list[Clause], interp: Interpretation) -> bool:
    for clause in clauses:
        variables = sorted({t for _, a in clause.literals for arg in a[1:] for t in _ints(arg)})
        for values in itertools.product(DOMAIN, repeat=len(variables)):
            assignment = dict(zip(variables, values))
            if not any(
                (tuple(value(arg, interp, assignment) for arg in a[1:]) in interp[a[0]]) == pos
                for pos, a in clause.literals
            ):
                return False
    return True


def _ints(term: object) -> Iterator[int]:
    if type(term) is int:
        yield term
    elif type(term) is tuple:
        for arg in term[1:]:
            yield from _ints(arg)


def relations(arity: int) -> Iterator[set[tuple[int, ...]]]:
    tuples = list(itertools.product(DOMAIN, repeat=arity))
    for chosen in itertools.product((False, True), repeat=len(tuples)):
        yield {t for t, keep in zip(tuples, chosen) if keep}


def functions(arity: int) -> Iterator[object]:
    if arity == 0:
        yield from DOMAIN
        return
    inputs = list(itertools.product(DOMAIN, repeat=arity))
    for outputs in itertools.product(DOMAIN, repeat=len(inputs)):
        yield dict(zip(inputs, outputs))


def fresh_symbols(clauses: list[Clause]) -> tuple[dict[str, int], dict[str, int]]:
    """The Skolem functions and definition predicates of ``clauses``, with arities."""
    funcs: dict[str, int] = {}
    preds: dict[str, int] = {}
    for clause in clauses:
        for _, a in clause.literals:
            if a[0].startswith("def!"):
                preds[a[0]] = len(a) - 1
            for arg in a[1:]:
                stack = [arg]
                while stack:
                    t = stack.pop()
                    if type(t) is str:
                        funcs[t] = 0
                    elif type(t) is tuple:
                        funcs[t[0]] = len(t) - 1
                        stack.extend(t[1:])
    return funcs, preds


def extensions(clauses: list[Clause]) -> list[Interpretation]:
    funcs, preds = fresh_symbols(clauses)
    choices = [[(f, v) for v in functions(k)] for f, k in funcs.items()]
    choices += [[(p, v) for v in relations(k)] for p, k in preds.items()]
    return [dict(combo) for combo in itertools.product(*choices)]


def interpretations() -> Iterator[Interpretation]:
    names = list(SIGNATURE)
    for rels in itertools.product(*(list(relations(SIGNATURE[n])) for n in names)):
        yield dict(zip(names, rels))


@pytest.mark.parametrize("limit", [24, 1])
@pytest.mark.parametrize("formula", SEMANTIC_CASES, ids=range(len(SEMANTIC_CASES)))
def test_clause_form_is_true_exactly_where_the_formula_is(formula: Formula, limit: int) -> None:
    clauses = clausify(formula, skolem=SkolemNames(), distribution_limit=limit)
    extra = extensions(clauses)
    for interp in interpretations():
        expected = evaluate(formula, interp, {})
        assert expected == any(clauses_hold(clauses, {**interp, **e}) for e in extra), interp


def random_formula(rng: random.Random, depth: int) -> Formula:
    if depth == 0 or rng.random() < 0.2:
        return Atomic((rng.choice("PQRS"),))
    kind = rng.choice([Not, And, Or, Implies, Iff])
    if kind is Not:
        return Not(random_formula(rng, depth - 1))
    if kind in (And, Or):
        return kind([random_formula(rng, depth - 1) for _ in range(rng.randint(2, 3))])
    return kind(random_formula(rng, depth - 1), random_formula(rng, depth - 1))


@pytest.mark.parametrize("seed", range(40))
def test_propositional_clause_form_is_equivalent(seed: int) -> None:
    formula = random_formula(random.Random(seed), 4)
    clauses = clausify(formula, skolem=SkolemNames(), distribution_limit=10**9)
    for values in itertools.product((False, True), repeat=4):
        truth = {name: {()} if v else set() for name, v in zip("PQRS", values)}
        assert evaluate(formula, truth, {}) == clauses_hold(clauses, truth)
