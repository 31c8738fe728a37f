"""What a Datalog engine answers (strips_framework.logic.horn): safe definite Horn rules and
conjunctive queries, told from everything else a clause form can hold."""

from __future__ import annotations

import pytest

from strips_framework.logic.clauses import Clause
from strips_framework.logic.horn import is_conjunctive_query, is_datalog_rule
from strips_framework.logic.terms import Param

M = Param("m")


@pytest.mark.parametrize(
    ("literals", "expected"),
    [
        ([(True, ("P", "a"))], True),  # a fact
        ([(False, ("CONNECTS", 0, 1, 2)), (True, ("CONNECTS", 0, 2, 1))], True),
        ([(False, ("P", 0)), (True, ("Q", ("f", "a")))], True),  # a ground function term is a name
        ([(True, ("P", 0))], False),  # forall x: P(x): the head's x is bound by no premise
        ([(False, ("P", 0)), (True, ("Q", 0, 1))], False),
        ([(False, ("P", 0)), (True, ("Q", 0)), (True, ("R", 0))], False),  # disjunctive
        ([(False, ("P", 0)), (False, ("Q", 0))], False),  # no head
        ([(False, ("P", 0)), (True, ("Q", ("f", 0)))], False),  # a function term with a variable
        ([(False, ("P", 0, 1)), (True, ("=", 0, 1))], False),  # an equation
        ([(False, ("=", 0, "a")), (True, ("Q", 0))], False),
    ],
)
def test_datalog_rules(literals, expected):
    assert is_datalog_rule(Clause(literals)) is expected


@pytest.mark.parametrize(
    ("clauses", "unique_names", "expected"),
    [
        ([[(False, ("P", M)), (False, ("Q", M, 0))]], True, True),
        ([[(False, ("P", M)), (True, ("=", M, "a"))]], True, True),  # P(m) & m != a
        ([[(False, ("P", M)), (True, ("=", M, "a"))]], False, False),  # no names to compare
        ([[(False, ("P", M)), (False, ("=", M, "a"))]], True, False),  # m = a is an equation
        ([[(True, ("P", M))]], True, False),  # ~P(m)
        ([[(False, ("P", M))], [(False, ("Q", M))]], True, False),  # P(m) | Q(m)
        ([[(False, ("P", ("f", M)))]], True, False),
        ([[]], True, True),  # the goal true
    ],
)
def test_conjunctive_queries(clauses, unique_names, expected):
    negated_goal = [Clause(literals) for literals in clauses]
    assert is_conjunctive_query(negated_goal, unique_names) is expected
