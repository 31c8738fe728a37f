"""Unification with the paper's parameter rules (III.A)."""

from strips_framework.logic.terms import Param
from strips_framework.logic.unify import match, substitute, unify

m, n = Param("m"), Param("n")


def test_variable_takes_constant_parameter_and_function_term():
    assert unify(0, "a", {}) == {0: "a"}
    assert unify(0, m, {}) == {0: m}
    assert unify(0, ("f", "a"), {}) == {0: ("f", "a")}


def test_occurs_check():
    assert unify(0, ("f", 0), {}) is None


def test_variable_meeting_parameter_binds_the_variable():
    assert unify(m, 3, {}) == {3: m}


def test_parameter_takes_constants_parameters_and_clean_function_terms():
    assert unify(m, "a", {}) == {m: "a"}
    assert unify(m, n, {}) in ({m: n}, {n: m})
    assert unify(m, ("f", "a"), {}) == {m: ("f", "a")}


def test_parameter_rejects_skolem_terms_variables_and_itself():
    assert unify(m, "sk!1", {}) is None
    assert unify(m, ("sk!2", "a"), {}) is None
    assert unify(m, ("f", 0), {}) is None
    assert unify(m, ("f", m), {}) is None


def test_bindings_compose_through_atoms():
    subst = unify(("AT", m, 0), ("AT", "BOX1", ("f", m)), {})
    assert subst is not None
    assert substitute(("AT", m, 0), subst) == ("AT", "BOX1", ("f", "BOX1"))


def test_clash_fails():
    assert unify(("P", "a"), ("P", "b"), {}) is None
    assert unify(("P", "a"), ("Q", "a"), {}) is None


def test_match_is_one_way():
    assert match(("P", 0, 0), ("P", "a", "a"), {}) == {0: "a"}
    assert match(("P", 0, 0), ("P", "a", "b"), {}) is None
    assert match(("P", "a"), ("P", 0), {}) is None
