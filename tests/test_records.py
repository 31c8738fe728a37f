"""Records (``strips_framework.records``): the values of the PDDL path compare by type
and fields, hash alike when equal, and copy with changes."""

from __future__ import annotations

from strips_framework.grounding.task import GroundOperator
from strips_framework.pddl.formulas import TRUE, And, Atom, Exists, Forall, Or, Parameter


def test_records_of_different_types_with_the_same_fields_differ():
    assert And(()) == TRUE and Or(()) != TRUE
    body = Atom("p", ("?x",))
    params = (Parameter("?x"),)
    assert Exists(params, body) != Forall(params, body)
    assert len({Exists(params, body), Forall(params, body), Exists(params, body)}) == 2


def test_equal_records_hash_alike_and_replace_makes_a_changed_copy():
    atom = Atom("on", ("a", "b"))
    assert atom == Atom("on", ("a", "b")) and hash(atom) == hash(Atom("on", ("a", "b")))
    assert atom._replace(args=("b", "a")) == Atom("on", ("b", "a")) and atom.args == ("a", "b")
    assert repr(atom) == "Atom(predicate='on', args=('a', 'b'))"


def test_replace_recomputes_what_a_record_derives_from_its_fields():
    op = GroundOperator("(a)", (0,), (1,), (2,))
    moved = op._replace(pre=(3,))
    assert moved.pre_mask == 0b1000 and op.pre_mask == 0b1
    assert moved != op and moved._replace(pre=(0,)) == op


def test_a_subclass_adding_no_slots_keeps_its_bases_fields():
    from strips_framework.logic.formulas import And as WffAnd
    from strips_framework.logic.formulas import Or as WffOr
    from strips_framework.logic.formulas import Truth

    parts = (Truth(True),)
    assert WffAnd.FIELDS == WffOr.FIELDS == ("parts",)
    assert WffAnd(parts) != WffAnd(()) and WffAnd(parts) != WffOr(parts)
    assert repr(WffAnd(parts)) == "And(parts=(Truth(value=True),))"


def test_fields_left_out_of_compared_are_kept_by_repr_and_replace_but_not_compared():
    from strips_framework.worldmodel.problem import DerivedFact, SourceSpan

    here, there = SourceSpan("a.strips", 3), SourceSpan("b.strips", 9)
    fact = DerivedFact(("P", "a"), [("Q", "a")], here)
    assert fact == DerivedFact(("P", "a"), [("Q", "a")], there)
    assert hash(fact) == hash(DerivedFact(("P", "a"), [("Q", "a")], there))
    assert fact != DerivedFact(("P", "a"), [("R", "a")], here)
    assert fact._replace(supports=()).source == here
    assert "source=SourceSpan(path='a.strips', line=3)" in repr(fact)
