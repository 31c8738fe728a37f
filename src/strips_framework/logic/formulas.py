"""First-order formulas (wffs) as the parsers produce them and the clausifier consumes them.

Inside formulas, quantified variables are named :class:`Var` objects; they become the
clause-local integer variables of :mod:`strips_framework.logic.terms` only in clause form.
Constants, parameters and function terms are the values of ``terms``.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Mapping

from strips_framework.logic.terms import EQUALITY, Param, Term
from strips_framework.records import Record


class Var(Record):
    """A quantified variable inside a formula, such as ``x`` in ``exists x: AT(BOX1, x)``."""

    name: str

    __slots__ = ("name",)

    def __init__(self, name: str) -> None:
        self.name = name

    def __str__(self) -> str:
        return self.name


class Atomic(Record):
    """An atom ``(predicate, *args)`` used as a formula; ``("=", s, t)`` is equality."""

    atom: tuple

    __slots__ = ("atom",)

    def __init__(self, atom: tuple) -> None:
        self.atom = atom


class Truth(Record):
    """The constants ``true`` and ``false``."""

    value: bool

    __slots__ = ("value",)

    def __init__(self, value: bool) -> None:
        self.value = value


class Not(Record):
    body: Formula

    __slots__ = ("body",)

    def __init__(self, body: Formula) -> None:
        self.body = body


class _Connective(Record):
    """The fields of :class:`And` and :class:`Or`; ``parts`` may be any iterable (kept as
    a tuple). Records compare by type, so a conjunction never equals a disjunction."""

    parts: tuple[Formula, ...]

    __slots__ = ("parts",)

    def __init__(self, parts: Iterable[Formula]) -> None:
        self.parts = tuple(parts)


class And(_Connective):
    """A conjunction."""

    __slots__ = ()


class Or(_Connective):
    """A disjunction."""

    __slots__ = ()


class Implies(Record):
    premise: Formula
    conclusion: Formula

    __slots__ = ("premise", "conclusion")

    def __init__(self, premise: Formula, conclusion: Formula) -> None:
        self.premise = premise
        self.conclusion = conclusion


class Iff(Record):
    left: Formula
    right: Formula

    __slots__ = ("left", "right")

    def __init__(self, left: Formula, right: Formula) -> None:
        self.left = left
        self.right = right


class _Quantified(Record):
    """The fields of :class:`Forall` and :class:`Exists`; ``variables`` may be any
    iterable (kept as a tuple)."""

    variables: tuple[Var, ...]
    body: Formula

    __slots__ = ("variables", "body")

    def __init__(self, variables: Iterable[Var], body: Formula) -> None:
        self.variables = tuple(variables)
        self.body = body


class Forall(_Quantified):
    """``forall x, y: body``."""

    __slots__ = ()


class Exists(_Quantified):
    """``exists x, y: body``."""

    __slots__ = ()


Formula = Atomic | Truth | Not | And | Or | Implies | Iff | Forall | Exists


def conjuncts(formula: Formula) -> Iterator[Formula]:
    """The conjuncts of ``formula``, nested conjunctions flattened (a formula that is no
    conjunction is its own one conjunct)."""
    if isinstance(formula, And):
        for part in formula.parts:
            yield from conjuncts(part)
    else:
        yield formula


def atoms_of(formula: Formula) -> Iterator[tuple]:
    """Yield every atom of ``formula`` (with repetitions), left to right."""
    if isinstance(formula, Atomic):
        yield formula.atom
    elif isinstance(formula, Not):
        yield from atoms_of(formula.body)
    elif isinstance(formula, (And, Or)):
        for part in formula.parts:
            yield from atoms_of(part)
    elif isinstance(formula, Implies):
        yield from atoms_of(formula.premise)
        yield from atoms_of(formula.conclusion)
    elif isinstance(formula, Iff):
        yield from atoms_of(formula.left)
        yield from atoms_of(formula.right)
    elif isinstance(formula, (Forall, Exists)):
        yield from atoms_of(formula.body)


def _term_params(term: Term | Var) -> Iterator[Param]:
    if isinstance(term, Param):
        yield term
    elif type(term) is tuple:
        for arg in term[1:]:
            yield from _term_params(arg)


def params_in(formula: Formula) -> set[Param]:
    return {p for atom in atoms_of(formula) for arg in atom[1:] for p in _term_params(arg)}


def term_variables(term: Term | Var) -> Iterator[Var]:
    """Yield the named variables inside a formula-level term, left to right."""
    if isinstance(term, Var):
        yield term
    elif type(term) is tuple:
        for arg in term[1:]:
            yield from term_variables(arg)


def substitute_free(formula: Formula, binding: Mapping[Var | Param, Term | Var]) -> Formula:
    """Replace parameters, and variables where they occur free, by terms.

    With parameters this makes an instance of a wff schema; with variables (which a
    quantifier inside ``formula`` shadows) it turns a question's variables into parameters.
    """

    def term(t: Term | Var) -> Term | Var:
        if isinstance(t, (Param, Var)):
            return binding.get(t, t)
        if type(t) is tuple:
            return (t[0], *map(term, t[1:]))
        return t

    def walk(f: Formula) -> Formula:
        if isinstance(f, Atomic):
            return Atomic((f.atom[0], *map(term, f.atom[1:])))
        if isinstance(f, Truth):
            return f
        if isinstance(f, Not):
            return Not(walk(f.body))
        if isinstance(f, And):
            return And(map(walk, f.parts))
        if isinstance(f, Or):
            return Or(map(walk, f.parts))
        if isinstance(f, Implies):
            return Implies(walk(f.premise), walk(f.conclusion))
        if isinstance(f, Iff):
            return Iff(walk(f.left), walk(f.right))
        inner = {k: v for k, v in binding.items() if k not in f.variables}
        body = substitute_free(f.body, inner)
        return Forall(f.variables, body) if isinstance(f, Forall) else Exists(f.variables, body)

    return walk(formula) if binding else formula


def formula_to_str(formula: Formula) -> str:
    """ASCII text of a formula in the syntax of :mod:`strips_framework.logic.parser`."""

    def term(t: Term | Var) -> str:
        if isinstance(t, (Var, Param)):
            return t.name
        if type(t) is tuple:
            return f"{t[0]}({', '.join(map(term, t[1:]))})"
        return str(t)

    def atom(a: tuple) -> str:
        if a[0] == EQUALITY:
            return f"{term(a[1])} = {term(a[2])}"
        return a[0] if len(a) == 1 else f"{a[0]}({', '.join(map(term, a[1:]))})"

    def walk(f: Formula, parent: int) -> str:
        # Precedence: quantifiers 0 < iff 1 < implies 2 < or 3 < and 4 < not 5.
        if isinstance(f, Atomic):
            return atom(f.atom)
        if isinstance(f, Truth):
            return "true" if f.value else "false"
        if isinstance(f, Not):
            if isinstance(f.body, Atomic) and f.body.atom[0] == EQUALITY:
                return f"{term(f.body.atom[1])} != {term(f.body.atom[2])}"
            return "~" + walk(f.body, 5)
        if isinstance(f, And):
            text, level = " & ".join(walk(p, 5) for p in f.parts), 4
        elif isinstance(f, Or):
            text, level = " | ".join(walk(p, 4) for p in f.parts), 3
        elif isinstance(f, Implies):
            text, level = f"{walk(f.premise, 3)} -> {walk(f.conclusion, 2)}", 2
        elif isinstance(f, Iff):
            text, level = f"{walk(f.left, 2)} <-> {walk(f.right, 2)}", 1
        else:
            word = "forall" if isinstance(f, Forall) else "exists"
            names = ", ".join(v.name for v in f.variables)
            text, level = f"{word} {names}: {walk(f.body, 0)}", 0
        return f"({text})" if level < parent else text

    return walk(formula, 0)
