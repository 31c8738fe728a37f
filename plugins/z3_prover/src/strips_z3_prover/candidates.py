"""Which parameter instances a model leaves possible as answers.

An instance θ is an answer when G(θ) holds in *every* model of the axioms, so it must hold
in each model Z3 hands us: in the first model of the axioms, and in each countermodel of a
rejected candidate. Evaluating G(θ) in a model for all θ at once prunes the candidates far
faster than asking Z3 about each θ (the robot world has 27 constants, so a precondition
with two open parameters has 729 instances, of which a model typically keeps a handful).

G(θ) holds in a ground model exactly when some clause of ¬G(θ) has an instance, over the
universe, whose literals are all false. Finding those instances is a conjunctive query
over the model's tables: a negated atom must be true, so it is matched against the
atom's true tuples, which binds its variables and parameters; the other literals are
tested once their terms are bound (unbound ones range over the universe).
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from itertools import product

import z3

from strips_framework.logic.clauses import Clause, Literal
from strips_framework.logic.terms import EQUALITY, Param, Term
from strips_z3_prover.encoding import Vocabulary
from strips_z3_prover.relevance import Relevance

Element = int  # a model element, by the id of its Z3 value
Table = frozenset[tuple[Element, ...]]  # the tuples where a predicate is true


class ModelTruth:
    """Truth of ground atoms in one model, over the values of the universe's constants."""

    def __init__(
        self,
        model: z3.ModelRef,
        vocabulary: Vocabulary,
        universe: Sequence[str],
        answers: Sequence[str],
        relevance: Relevance | None = None,
    ) -> None:
        """``universe`` holds the constants the variables range over, ``answers`` the
        named ones parameters may be bound to. With ``relevance`` (a ground session's,
        without positive equations) the model is read as the relevance argument reads
        it: each constant its own element, the atoms that cannot hold false. That is a
        model of every ground instance, with tables no larger than the atoms that can
        hold, where Z3 is free to make the atoms no asserted instance names true."""
        self.model = model
        self.vocabulary = vocabulary
        self._universe = tuple(universe)  # the session's grows; this model does not
        # Elements are compared by AST id, which Z3 reuses once an AST is freed: the
        # values stay referenced here for as long as the ids are used.
        self._values: list = []
        self._z3_value = _Values(model, vocabulary, self._values)
        self._relevance = relevance if relevance is not None and not relevance.everything else None
        if self._relevance is not None:
            # Read over the constants: no constant's value is needed before a table is.
            self.value = {name: i for i, name in enumerate(universe)}
            self.elements = list(range(len(universe)))
        else:
            self.value = {name: self._z3_value[name] for name in universe}
            self.elements = sorted(set(self.value.values()))
        self.names: dict[Element, list[str]] = {}
        for name in answers:
            self.names.setdefault(self.value[name], []).append(name)
        self._tables: dict[tuple[str, int], Table] = {}
        self._representatives: dict[Element, z3.ExprRef] | None = None

    @property
    def _representative(self) -> dict[Element, z3.ExprRef]:
        """A constant for each element of the universe (evaluated once, when a table
        must be read element by element)."""
        if self._representatives is None:
            self._representatives = {}
            for name in self._universe:
                self._representatives.setdefault(
                    self._z3_value[name], self.vocabulary.constant(name)
                )
        return self._representatives

    @property
    def _z3_elements(self) -> list[Element]:
        return sorted(self._representative)

    def table(self, predicate: str, arity: int) -> Table:
        key = (predicate, arity)
        found = self._tables.get(key)
        if found is None:
            found = self._read_table(predicate, arity)
            relevance = self._relevance
            if relevance is not None:
                z3_value, value = self._z3_value, self.value
                found = frozenset(
                    tuple(value[n] for n in row)
                    for row in relevance.atoms.get(key, ())
                    if all(n in value for n in row) and tuple(z3_value[n] for n in row) in found
                )
            self._tables[key] = found
        return found

    def _read_table(self, predicate: str, arity: int) -> Table:
        """The true tuples, from the interpretation's entries when it is a finite table,
        else (a model of quantified axioms defines predicates by expressions) by
        evaluating the predicate on every tuple of the constants' values."""
        symbol = self.vocabulary.predicate(predicate, arity)
        if arity == 0:
            return frozenset({()}) if z3.is_true(self.model.eval(symbol, True)) else frozenset()
        model = self.model
        if not z3.Z3_model_has_interp(model.ctx.ref(), model.model, symbol.ast):
            return frozenset()  # unconstrained: false in the completion
        entries = self.model[symbol].as_list()
        self._values.append(entries)
        default = entries[-1]
        if (z3.is_false(default) or z3.is_true(default)) and all(
            _is_value(x) for entry in entries[:-1] for x in entry
        ):
            # A finite table with a default: read it, never evaluate the predicate (a
            # model often makes a predicate true everywhere: ``else -> True``).
            listed = {
                tuple(arg.get_id() for arg in entry[:-1]): z3.is_true(entry[-1])
                for entry in entries[:-1]
            }
            if z3.is_false(default):
                return frozenset(row for row, true in listed.items() if true)
            return frozenset(
                row for row in product(self._z3_elements, repeat=arity) if listed.get(row, True)
            )
        return frozenset(
            row
            for row in product(self._z3_elements, repeat=arity)
            if z3.is_true(self.model.eval(symbol(*[self._representative[e] for e in row]), True))
        )

    def true_atoms(self, predicates: Sequence[tuple[str, int]]) -> list[tuple]:
        """The atoms of ``predicates`` over named constants that are true in the model."""
        found = []
        for predicate, arity in predicates:
            for row in sorted(self.table(predicate, arity)):
                if all(e in self.names for e in row):
                    found.extend(
                        (predicate, *names) for names in product(*(self.names[e] for e in row))
                    )
        return found

    def holds_named(self, atom: tuple) -> bool:
        return self.holds(atom, tuple(self.value[name] for name in atom[1:]))

    def holds(self, atom: tuple, elements: tuple[Element, ...]) -> bool:
        if atom[0] == EQUALITY and len(atom) == 3:
            return elements[0] == elements[1]
        return elements in self.table(atom[0], len(atom) - 1)


def surviving(
    truth: ModelTruth, negated_goal: Sequence[Clause], params: Sequence[Param]
) -> set[tuple[str, ...]]:
    """The name tuples θ (in ``params`` order) for which G(θ) holds in the model."""
    named = [e for e in truth.elements if e in truth.names]
    found: set[tuple[str, ...]] = set()
    for clause in negated_goal:
        for binding in _falsifying(truth, _ordered(clause.literals), {}, named):
            choices = [
                truth.names[binding[p]]
                if p in binding
                else [n for e in named for n in truth.names[e]]
                for p in params
            ]
            found.update(product(*choices))
    return found


def _ordered(literals: Sequence[Literal]) -> list[Literal]:
    """Negated atoms first: matching them against true tuples binds the most."""
    return sorted(literals, key=lambda lit: (lit[0] or lit[1][0] == EQUALITY, len(lit[1])))


def _falsifying(
    truth: ModelTruth,
    literals: list[Literal],
    binding: dict[Term, Element],
    named: list[Element],
) -> Iterator[dict[Term, Element]]:
    """Extensions of ``binding`` (variables and parameters to elements) under which every
    literal of ``literals`` is false in the model."""
    if not literals:
        yield binding
        return
    (positive, atom), rest = literals[0], literals[1:]
    args = atom[1:]
    generator = not positive and atom[0] != EQUALITY
    for extended in _bindings(truth, atom, args, binding, named, generator):
        values = tuple(_value(truth, a, extended) for a in args)
        if truth.holds(atom, values) != positive:
            yield from _falsifying(truth, rest, extended, named)


def _bindings(
    truth: ModelTruth,
    atom: tuple,
    args: tuple[Term, ...],
    binding: dict[Term, Element],
    named: list[Element],
    from_table: bool,
) -> Iterator[dict[Term, Element]]:
    """Ways to bind the unbound variables and parameters of ``args``."""
    open_terms = list(dict.fromkeys(a for a in args if _open(a, binding)))
    if not open_terms:
        yield binding
        return
    if from_table:
        for row in truth.table(atom[0], len(args)):
            extended = dict(binding)
            if all(_match(truth, a, e, extended) for a, e in zip(args, row)):
                yield extended
        return
    domains = [named if type(t) is Param else truth.elements for t in open_terms]
    for values in product(*domains):
        yield {**binding, **dict(zip(open_terms, values))}


def _open(term: Term, binding: dict[Term, Element]) -> bool:
    return (type(term) is int or type(term) is Param) and term not in binding


def _match(truth: ModelTruth, term: Term, element: Element, binding: dict[Term, Element]) -> bool:
    if type(term) is str:
        return truth.value[term] == element
    bound = binding.get(term)
    if bound is not None:
        return bound == element
    if type(term) is Param and element not in truth.names:
        return False  # a parameter is only ever bound to a named constant
    binding[term] = element
    return True


def _value(truth: ModelTruth, term: Term, binding: dict[Term, Element]) -> Element:
    return truth.value[term] if type(term) is str else binding[term]


class _Values(dict):
    """The element id of each constant, evaluated in the model on first use: a model
    of a big universe is read only at the constants a table or a goal names."""

    def __init__(self, model: z3.ModelRef, vocabulary: Vocabulary, keep: list) -> None:
        super().__init__()
        self._model, self._vocabulary, self._keep = model, vocabulary, keep

    def __missing__(self, name: str) -> Element:
        value = self._model.eval(self._vocabulary.constant(name), True)
        self._keep.append(value)
        found = self[name] = value.get_id()
        return found


def _is_value(expression: z3.ExprRef) -> bool:
    return z3.is_true(expression) or z3.is_false(expression) or expression.num_args() == 0
