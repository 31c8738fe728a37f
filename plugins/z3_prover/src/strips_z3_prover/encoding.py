"""Clauses as Z3 terms over one uninterpreted sort of individuals.

Every constant, function and predicate of the framework's language becomes a Z3 symbol in
a private :class:`z3.Context` (so two provers never share mutable Z3 state): constants are
constants of the sort ``U``, a predicate ``P`` of arity *n* is a function ``U^n -> Bool``
named ``P/n`` (the framework tells ``P/1`` and ``P/2`` apart, so Z3 must too), and ``=`` is
Z3's own equality, so congruence comes for free. Two shapes of clause are produced:

- *ground instances* (:mod:`strips_z3_prover.smtlib`): the clause's variables replaced
  by constant names, for the effectively propositional models that STRIPS worlds are;
- *quantified clauses* (:meth:`Vocabulary.quantified_clause`): the variables bound by a
  ``ForAll``, for models with function symbols, left to Z3's model-based instantiation.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Mapping

import z3

from strips_framework.logic.clauses import Clause, Literal
from strips_framework.logic.terms import EQUALITY, SKOLEM_PREFIX, Param, Term, subterms

#: A variable or parameter replaced by a term (ground) or a Z3 bound constant (quantified).
Binding = Mapping[int | Param, Term]


class Vocabulary:
    """The Z3 symbols of one context, created on first use and cached."""

    def __init__(self) -> None:
        self.context = z3.Context()
        self.sort = z3.DeclareSort("U", self.context)
        self._constants: dict[str, z3.ExprRef] = {}
        self._functions: dict[tuple[str, int], z3.FuncDeclRef] = {}
        self._predicates: dict[tuple[str, int], z3.FuncDeclRef | z3.BoolRef] = {}

    def constant(self, name: str) -> z3.ExprRef:
        found = self._constants.get(name)
        if found is None:
            found = self._constants[name] = z3.Const(name, self.sort)
        return found

    def predicate(self, name: str, arity: int) -> z3.FuncDeclRef | z3.BoolRef:
        """``P/n`` as a Z3 function (a Boolean constant when ``n`` is 0)."""
        key = (name, arity)
        found = self._predicates.get(key)
        if found is None:
            symbol = f"{name}/{arity}"
            if arity == 0:
                found = z3.Bool(symbol, self.context)
            else:
                found = z3.Function(symbol, *[self.sort] * arity, z3.BoolSort(self.context))
            self._predicates[key] = found
        return found

    def term(self, term: Term, binding: Binding) -> z3.ExprRef:
        if type(term) is str:
            return self.constant(term)
        if type(term) is int or type(term) is Param:
            value = binding[term]
            return value if isinstance(value, z3.ExprRef) else self.term(value, {})
        key = (term[0], len(term) - 1)
        function = self._functions.get(key)
        if function is None:
            function = z3.Function(f"{term[0]}/{key[1]}", *[self.sort] * (key[1] + 1))
            self._functions[key] = function
        return function(*[self.term(arg, binding) for arg in term[1:]])

    def atom(self, atom: tuple, binding: Binding) -> z3.BoolRef:
        if atom[0] == EQUALITY and len(atom) == 3:
            return self.term(atom[1], binding) == self.term(atom[2], binding)
        symbol = self.predicate(atom[0], len(atom) - 1)
        if len(atom) == 1:
            return symbol
        return symbol(*[self.term(arg, binding) for arg in atom[1:]])

    def literal(self, literal: Literal, binding: Binding) -> z3.BoolRef:
        positive, atom = literal
        encoded = self.atom(atom, binding)
        return encoded if positive else z3.Not(encoded)

    def disjunction(self, parts: list[z3.BoolRef]) -> z3.BoolRef:
        if not parts:
            return z3.BoolVal(False, self.context)
        return parts[0] if len(parts) == 1 else z3.Or(parts)

    def quantified_clause(self, clause: Clause, binding: Binding) -> z3.BoolRef:
        """``clause`` with its variables universally quantified (parameters from
        ``binding``; a parameter bound to a Z3 constant is quantified by the caller)."""
        variables = sorted(clause_variables(clause))
        bound = {v: z3.Const(f"x!{v}", self.sort) for v in variables}
        body = self.disjunction(
            [self.literal(lit, {**binding, **bound}) for lit in clause.literals]
        )
        if not variables:
            return body
        return z3.ForAll([bound[v] for v in variables], body)


def clause_variables(clause: Clause) -> set[int]:
    return {t for _, atom in clause.literals for t in _atom_terms(atom) if type(t) is int}


def clause_params(clause: Clause) -> set[Param]:
    return {t for _, atom in clause.literals for t in _atom_terms(atom) if type(t) is Param}


def _atom_terms(atom: tuple) -> Iterator[Term]:
    for arg in atom[1:]:
        yield from subterms(arg)


def task_terms(clauses: Iterable[Clause]) -> Iterator[Term]:
    for clause in clauses:
        for _, atom in clause.literals:
            yield from _atom_terms(atom)


class ClauseTerms:
    """What an attempt asks of each clause's terms (function symbols, parameters, the
    constants), worked out once per distinct clause: a session's attempts see M0's
    clauses again and again, and walking their terms was a tenth of an attempt."""

    def __init__(self) -> None:
        self._known: dict[Clause, tuple[bool, bool, frozenset[str]]] = {}

    def of(self, clause: Clause) -> tuple[bool, bool, frozenset[str]]:
        """Whether ``clause`` has a function symbol, a parameter; its constants."""
        found = self._known.get(clause)
        if found is None:
            terms = list(task_terms((clause,)))
            found = self._known[clause] = (
                any(type(t) is tuple for t in terms),
                any(type(t) is Param for t in terms),
                frozenset(t for t in terms if type(t) is str),
            )
        return found


def is_named(term: Term) -> bool:
    """Whether ``term`` is a ground term a parameter may be bound to: no Skolem symbol,
    no variable, no parameter (the unifier's rule, paper III.A)."""
    if type(term) is str:
        return not term.startswith(SKOLEM_PREFIX)
    if type(term) is tuple:
        return not term[0].startswith(SKOLEM_PREFIX) and all(is_named(a) for a in term[1:])
    return False
