"""The wff parser: structure, precedence, printing round trips and error positions."""

from __future__ import annotations

import pytest

from strips_framework.errors import InputError
from strips_framework.logic.formulas import (
    And,
    Atomic,
    Exists,
    Forall,
    Iff,
    Implies,
    Not,
    Or,
    Truth,
    Var,
    formula_to_str,
)
from strips_framework.logic.parser import Arities, parse_formula
from strips_framework.logic.terms import Param

P, Q, R, S = (Atomic((name,)) for name in "PQRS")


def error_of(text: str, **kwargs: object) -> InputError:
    with pytest.raises(InputError) as caught:
        parse_formula(text, **kwargs)  # type: ignore[arg-type]
    return caught.value


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("P & Q | R", Or([And([P, Q]), R])),
        ("P | Q & R", Or([P, And([Q, R])])),
        ("~P & Q", And([Not(P), Q])),
        ("P -> Q -> R", Implies(P, Implies(Q, R))),
        ("P | Q -> R", Implies(Or([P, Q]), R)),
        ("P -> Q <-> R", Iff(Implies(P, Q), R)),
        ("P <-> Q <-> R", Iff(P, Iff(Q, R))),
        ("P & Q & R", And([P, Q, R])),
        ("(P & Q) & R", And([And([P, Q]), R])),
        ("not not P", Not(Not(P))),
        ("true | false", Or([Truth(True), Truth(False)])),
    ],
)
def test_precedence(text: str, expected: object) -> None:
    assert parse_formula(text) == expected


def test_quantifier_body_extends_as_far_right_as_possible() -> None:
    x = Var("x")
    body = Or([Atomic(("Q", x)), R])
    assert parse_formula("P & forall x: Q(x) | R") == And([P, Forall([x], body)])
    assert parse_formula("~exists x: Q(x) | R") == Not(Exists([x], body))


def test_bracket_form_ends_at_the_bracket() -> None:
    text = "exists n [TYPE(n, BOX) & ON(ROBOT, n)] & TYPE(m, SWITCH)"
    formula = parse_formula(text, params={"m"})
    n = Var("n")
    assert formula == And(
        [
            Exists([n], And([Atomic(("TYPE", n, "BOX")), Atomic(("ON", "ROBOT", n))])),
            Atomic(("TYPE", Param("m"), "SWITCH")),
        ]
    )


def test_identifiers_become_variables_parameters_or_constants() -> None:
    formula = parse_formula("forall x: AT(x, m, a, f(x, m))", params=["m"])
    x, m = Var("x"), Param("m")
    assert formula == Forall([x], Atomic(("AT", x, m, "a", ("f", x, m))))


def test_quantified_variable_shadows_a_constant_of_the_same_name() -> None:
    formula = parse_formula("forall d: P(d) & Q(d)", constants={"d"})
    assert formula == Forall([Var("d")], And([Atomic(("P", Var("d"))), Atomic(("Q", Var("d")))]))
    assert parse_formula("P(d)", constants={"d"}) == Atomic(("P", "d"))


def test_equality_and_disequality() -> None:
    assert parse_formula("a = b") == Atomic(("=", "a", "b"))
    assert parse_formula("f(a) != b") == Not(Atomic(("=", ("f", "a"), "b")))
    assert parse_formula("a ≠ b") == parse_formula("a != b")


def test_unicode_symbols_mean_the_ascii_ones() -> None:
    unicode = "∀x,y: ¬P(x) ∧ Q(y) ∨ R → S ⇒ R ↔ ∃z: P(z) ⇔ Q(z)"
    ascii_ = "forall x,y: ~P(x) & Q(y) | R -> S -> R <-> exists z: P(z) <-> Q(z)"
    assert parse_formula(unicode) == parse_formula(ascii_)


def test_hyphenated_names_and_arrows_without_spaces() -> None:
    assert parse_formula("ROOM-1->P") == Implies(Atomic(("ROOM-1",)), P)
    assert parse_formula("P<->Q") == Iff(P, Q)


@pytest.mark.parametrize(
    "text",
    [
        "exists x: AT(BOX1, x) & AT(BOX2, x) & AT(BOX3, x)",
        "forall x, y, z: CONNECTS(x, y, z) -> CONNECTS(x, z, y)",
        "ONFLOOR & (exists x: INROOM(ROBOT, x) & LOCINROOM(m, x))",
        "(P -> Q) -> R",
        "P -> Q -> R",
        "(P <-> Q) <-> R",
        "~(P & Q) | ~~R",
        "(forall x: P(x)) & Q",
        "a != b & f(g(a)) = b",
        "true & ~false",
        "forall x: exists y: R(x, y) | (P <-> Q)",
    ],
)
def test_printing_round_trip(text: str) -> None:
    formula = parse_formula(text, params={"m"})
    assert formula_to_str(formula) == text
    assert parse_formula(formula_to_str(formula), params={"m"}) == formula


def test_error_position_is_relative_to_the_whole_file() -> None:
    text = "P(a) &   # a comment\n  (Q(b) |\n   )"
    error = error_of(text, path="world.strips", line=10, column=7)
    assert (error.path, error.line, error.column) == ("world.strips", 12, 4)
    assert error.message.startswith("expected a formula")
    assert error.message.endswith("but found ')'")
    assert str(error).startswith("world.strips:12:4: expected")


def test_error_on_the_first_line_counts_the_starting_column() -> None:
    error = error_of("P(a b)", path="f", line=3, column=6)
    assert (error.line, error.column) == (3, 10)
    assert error.message == "expected ',' or ')' but found 'b'"


def test_error_at_the_end_of_input() -> None:
    error = error_of("P & (Q")
    assert (error.line, error.column) == (1, 7)
    assert error.message == "expected ')' but found end of input"


@pytest.mark.parametrize(
    ("text", "message"),
    [
        (
            "forall x y: P",
            "expected ',' or ':' or '[' after the quantified variables but found 'y'",
        ),
        ("P Q", "expected end of input but found 'Q'"),
        ("P(a) = ", "expected a term (a constant, variable or parameter) but found end of input"),
        ("P % Q", "found unexpected character '%'"),
        ("P($)", "'$' (the wildcard) is allowed only in delete lists"),
        ("forall x: P(x(a))", "'x' is a variable or parameter and takes no arguments"),
    ],
)
def test_error_messages(text: str, message: str) -> None:
    assert error_of(text).message == message


def test_undeclared_constant_is_named_with_the_known_ones() -> None:
    error = error_of("AT(BOX1, q)", constants=["BOX1", "a"])
    assert error.column == 10
    assert error.message == "undeclared constant 'q' (declared constants: BOX1, a)"
    error = error_of("AT(k, q)", constants=["a"], params=["k", "m"])
    assert "'q' is neither a parameter (k, m) nor a declared constant" in error.message


def test_arity_must_match_the_known_arities() -> None:
    error = error_of("ATR(a) & AT(a)", arities={"AT": 2})
    assert error.column == 10
    assert error.message == "expected 2 arguments for AT (declared) but found 1 argument"


def test_arities_are_fixed_by_first_use() -> None:
    arities = Arities()
    parse_formula("NEXTTO(a, b)", path="p.strips", line=4, arities=arities)
    error = error_of("NEXTTO(a)", path="p.strips", line=9, arities=arities)
    assert error.message == (
        "expected 2 arguments for NEXTTO (as first used at p.strips:4) but found 1 argument"
    )
