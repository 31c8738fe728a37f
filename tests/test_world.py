"""World models as M0 plus ADDITIONS and DELETIONS (III.B, III.D)."""

from strips_framework.logic.clauses import Clause
from strips_framework.logic.cnf import SkolemNames
from strips_framework.logic.formulas import Atomic, Forall, Implies, Var
from strips_framework.logic.terms import Param
from strips_framework.worldmodel.operators import OperatorInstance
from strips_framework.worldmodel.problem import DerivedFact, OperatorSchema, Problem
from strips_framework.worldmodel.world import InitialModel, WorldModel, initial_model


def unit(*atom):
    return Clause([(True, atom)])


def test_deletions_and_additions_leave_m0_untouched():
    m0 = InitialModel([unit("ATR", "a"), unit("AT", "BOX1", "b")])
    model = WorldModel(m0).changed(frozenset({("ATR", "a")}), frozenset({("ATR", "c")}))
    assert [str(c) for c in model.clauses()] == ["AT(BOX1, b)", "ATR(c)"]
    assert model.deletions == {0}
    assert model.additions == {("ATR", "c")}
    assert [str(c) for c in WorldModel(m0).clauses()] == ["ATR(a)", "AT(BOX1, b)"]


def test_readding_a_deleted_m0_fact_revives_it():
    m0 = InitialModel([unit("ATR", "a")])
    away = WorldModel(m0).changed(frozenset({("ATR", "a")}), frozenset({("ATR", "b")}))
    back = away.changed(frozenset({("ATR", "b")}), frozenset({("ATR", "a")}))
    assert back == WorldModel(m0)


def test_derived_clause_is_visible_only_while_its_supports_are():
    m0 = InitialModel(
        [unit("AT", "B1", "a"), unit("AT", "B2", "a"), unit("NEXTTO", "B1", "B2")],
        supports={2: frozenset({0, 1})},
    )
    model = WorldModel(m0)
    assert "NEXTTO(B1, B2)" in [str(c) for c in model.clauses()]
    moved = model.changed(frozenset({("AT", "B1", "a")}), frozenset({("AT", "B1", "c")}))
    assert "NEXTTO(B1, B2)" not in [str(c) for c in moved.clauses()]


def test_wildcard_delete_and_application():
    k, m, n = Param("k"), Param("m"), Param("n")
    push = OperatorSchema(
        "push", [k, m, n], Atomic(("AT", k, m)), [("AT", k, n), ("ATR", n)],
        [("AT", k, "$"), ("ATR", "$")],
    )
    m0 = InitialModel([unit("ATR", "c"), unit("AT", "BOX2", "c"), unit("AT", "BOX1", "b")])
    instance = OperatorInstance(push, [(k, "BOX2"), (m, "c"), (n, "b")])
    after = instance.apply(WorldModel(m0))
    assert sorted(map(str, after.clauses())) == ["AT(BOX1, b)", "AT(BOX2, b)", "ATR(b)"]
    assert str(instance) == "push(BOX2, c, b)"
    assert instance.ipc() == "(push BOX2 c b)"


def test_rigid_predicates_are_those_only_deletions_change():
    # ATR is added by goto, CONNECTS concluded by a rule, NEXTTO a derived fact (it comes
    # back with its supports) although NEXTTO(B1, B2) is a plain fact: PUSHABLE, TYPE and
    # AT (nothing adds it) are rigid.
    m, n = Param("m"), Param("n")
    x, y, z = Var("x"), Var("y"), Var("z")
    goto = OperatorSchema("goto", [m, n], Atomic(("ATR", m)), [("ATR", n)], [("ATR", m)])
    symmetric = Forall([x, y, z], Implies(Atomic(("CONNECTS", x, y, z)), Atomic(("CONNECTS", x, z, y))))
    facts = [("ATR", "a"), ("PUSHABLE", "B1"), ("TYPE", "B1", "BOX"), ("CONNECTS", "D", "R1", "R2"),
             ("AT", "B1", "a"), ("NEXTTO", "B1", "B2")]
    problem = Problem(
        "rigid", ["a", "B1", "B2", "BOX", "D", "R1", "R2"], {("ATR", 1), ("AT", 2)}, facts, [symmetric],
        [DerivedFact(("NEXTTO", "B1", "a"), [("AT", "B1", "a")])], [goto], Atomic(("ATR", "b")),
    )
    rigid = initial_model(problem, SkolemNames()).rigid
    assert rigid == {("PUSHABLE", 1), ("TYPE", 2), ("AT", 2)}
