"""Criticality values and the abstraction spaces they define (Sacerdoti 1974).

ABSTRIPS gives each literal of each operator's precondition a *criticality*. The
abstraction space of level ``v`` is the problem whose operators keep only the literals of
criticality ``v`` or more (add and delete lists are kept whole); the top level is the
most abstract, the lowest level is the problem itself.

*Literals.* A precondition is read as a list of literals: the conjuncts of its
conjunctions, inside existential quantifiers too (``exists x [INROOM(ROBOT, x) &
LOCINROOM(m, x)]`` is two literals); any other part (a negation, a disjunction, a
universal) is one literal. A literal is keyed by its operator and its position in that
list; removing literals leaves the quantifiers around what is left.

*Computed values* (Sacerdoti's rule, made precise here since his search for "a short
plan" is not):

- ``STATIC`` (the highest): a literal whose predicates no operator adds or deletes, or an
  equality. No plan can change it, so a plan that ignores it is no plan at all.
- ``CRITICAL``: a literal that no plan of at most ``short_plan`` steps achieves, with the
  operator's other literals taken as true (Sacerdoti: "assuming the literals already
  processed are true").
- ``DETAIL`` (0): the rest, and the negated and compound literals (whose achievement is a
  deletion or a choice, which a later level fixes up).

The short-plan test is a lifted, delete-relaxed regression: an atom is achieved in 0 steps
when it is static, is one of the operator's other literals (matched without binding the
operator's own parameters), or matches a fact of M0 without binding them; in ``k`` steps
when an operator's add list unifies with it and each positive atom of that operator's
precondition is achieved in ``k - 1``. It looks at operators and M0 only, never at the
search, so the hierarchy is the same for every run on a problem.

On the robot world of the paper (``examples/robot-world``) with ``short_plan = 1`` this
gives three levels: TYPE, CONNECTS, PUSHABLE, LOCINROOM static; the rooms (INROOM) and
being on a box (ON) critical, with every NEXTTO but the robot's before a push (which
``goto2`` gives in one step from wherever the robot is); ONFLOOR, true in M0, a detail.
The plugin's tests check that table.
"""

from __future__ import annotations

import itertools
from collections import defaultdict
from collections.abc import Callable, Iterator, Mapping

from strips_framework.logic.formulas import (
    And,
    Atomic,
    Exists,
    Formula,
    Truth,
    Var,
    atoms_of,
    formula_to_str,
)
from strips_framework.logic.terms import EQUALITY, Atom, Param, Term
from strips_framework.logic.unify import substitute, unify
from strips_framework.records import Record
from strips_framework.worldmodel.problem import OperatorSchema, Problem

STATIC, CRITICAL, DETAIL = 2, 1, 0

#: (operator name, literal position) -> criticality
Criticalities = dict[tuple[str, int], int]


def literals(formula: Formula) -> Iterator[Formula]:
    """The literals of a precondition, in the order their positions count."""
    if isinstance(formula, And):
        for part in formula.parts:
            yield from literals(part)
    elif isinstance(formula, Exists):
        yield from literals(formula.body)
    else:
        yield formula


def abstracted(formula: Formula, keep: Callable[[int], bool]) -> Formula:
    """``formula`` with only the literals whose position ``keep`` accepts (``true`` when
    none is kept)."""
    position = itertools.count()

    def walk(part: Formula) -> Formula | None:
        if isinstance(part, And):
            kept = [f for f in map(walk, part.parts) if f is not None]
            return None if not kept else kept[0] if len(kept) == 1 else And(kept)
        if isinstance(part, Exists):
            body = walk(part.body)
            return None if body is None else Exists(part.variables, body)
        return part if keep(next(position)) else None

    return walk(formula) or Truth(True)


class Hierarchy(Record):
    """The criticality of every precondition literal of a problem's operators."""

    values: Criticalities

    __slots__ = ("values",)

    def __init__(self, values: Criticalities) -> None:
        self.values = values

    @property
    def levels(self) -> list[int]:
        """The criticalities that occur, highest (most abstract) first."""
        return sorted(set(self.values.values()) or {DETAIL}, reverse=True)

    def operators_at(
        self, operators: tuple[OperatorSchema, ...], level: int
    ) -> tuple[OperatorSchema, ...]:
        """The operators of the abstraction space of ``level``."""
        return tuple(
            schema._replace(
                precondition=abstracted(
                    schema.precondition,
                    lambda i, name=schema.name: self.values.get((name, i), DETAIL) >= level,
                ),
            )
            for schema in operators
        )

    def problem_at(self, problem: Problem, level: int) -> Problem:
        return problem._replace(operators=self.operators_at(problem.operators, level))

    def table(self, operators: tuple[OperatorSchema, ...]) -> list[tuple[str, str, int]]:
        """(operator, literal, criticality) rows, for reports and tests."""
        return [
            (schema.signature(), formula_to_str(literal), self.values[(schema.name, i)])
            for schema in operators
            for i, literal in enumerate(literals(schema.precondition))
        ]


def given(problem: Problem, table: Mapping[str, int]) -> Hierarchy:
    """Criticalities from a ``{predicate: value}`` table (the TOML ``criticality`` option):
    a literal gets the least value of its predicates; a predicate the table does not name
    counts 0, an equality the highest value in the table."""
    top = max(table.values(), default=0)
    values: Criticalities = {}
    for schema in problem.operators:
        for i, literal in enumerate(literals(schema.precondition)):
            named = [top if a[0] == EQUALITY else table.get(a[0], 0) for a in _atoms(literal)]
            values[(schema.name, i)] = min(named, default=top)
    return Hierarchy(values)


def computed(problem: Problem, short_plan: int = 1) -> Hierarchy:
    """Criticalities by the rule of the module docstring."""
    return _Regression(problem, short_plan).hierarchy()


class _Regression:
    """The short-plan test over one problem's operators and M0."""

    def __init__(self, problem: Problem, short_plan: int) -> None:
        self.problem = problem
        self.short_plan = short_plan
        changed = {
            (atom[0], len(atom) - 1)
            for schema in problem.operators
            for atom in (*schema.add_list, *schema.delete_list)
        }
        self.static = {
            (a[0], len(a) - 1)
            for schema in problem.operators
            for a in _atoms(schema.precondition)
        } - changed
        self.achievers: dict[tuple[str, int], list[tuple[OperatorSchema, Atom]]] = defaultdict(list)
        for schema in problem.operators:
            for atom in schema.add_list:
                self.achievers[(atom[0], len(atom) - 1)].append((schema, atom))
        self.facts: dict[tuple[str, int], list[Atom]] = defaultdict(list)
        for fact in problem.facts:
            self.facts[(fact[0], len(fact) - 1)].append(fact)
        self.by_axioms = {(a[0], len(a) - 1) for axiom in problem.axioms for a in atoms_of(axiom)}
        self.tags = itertools.count(1)

    def hierarchy(self) -> Hierarchy:
        values: Criticalities = {}
        for schema in self.problem.operators:
            units = list(literals(schema.precondition))
            own = [_renamed(u.atom, 0) if _positive(u) else None for u in units]
            for i, unit in enumerate(units):
                values[(schema.name, i)] = self._criticality(unit, own[i], [
                    atom for j, atom in enumerate(own) if j != i and atom is not None
                ])
        return Hierarchy(values)

    def _criticality(self, unit: Formula, atom: Atom | None, context: list[Atom]) -> int:
        if all(self._is_static(a) for a in _atoms(unit)):
            return STATIC
        if atom is None:
            return DETAIL  # a negation or a compound literal
        return DETAIL if self._short(atom, context, self.short_plan) else CRITICAL

    def _is_static(self, atom: Atom) -> bool:
        return atom[0] == EQUALITY or (atom[0], len(atom) - 1) in self.static

    def _short(self, atom: Atom, context: list[Atom], steps: int) -> bool:
        if self._is_static(atom):
            return self._satisfiable(atom)
        if self._in_m0(atom):
            return True
        if any(_same_instance(atom, other) for other in context):
            return True
        if steps == 0:
            return False
        for schema, add in self.achievers.get((atom[0], len(atom) - 1), ()):
            tag = next(self.tags)
            binding = unify(_renamed(add, tag), atom, {})
            if binding is None:
                continue
            needed = [
                substitute(_renamed(a, tag), binding)
                for unit in literals(schema.precondition)
                if _positive(unit)
                for a in [unit.atom]  # type: ignore[union-attr]
            ]
            # The achiever may bind the operator's own parameters (an instance of the
            # literal is achieved); the other literals then hold for that instance.
            bound = [substitute(a, binding) for a in context]
            if all(self._short(a, bound, steps - 1) for a in needed):
                return True
        return False

    def _satisfiable(self, atom: Atom) -> bool:
        """A static atom some fact of M0 matches (any binding), or one that an axiom
        may conclude (not tried: taken as true)."""
        key = (atom[0], len(atom) - 1)
        if atom[0] == EQUALITY or key in self.by_axioms:
            return True
        return any(unify(atom, fact, {}) is not None for fact in self.facts.get(key, ()))

    def _in_m0(self, atom: Atom) -> bool:
        """A fact of M0 matches ``atom`` and the operator's own parameters stay free."""
        if any(p.tag == 0 for p in _params(atom)):
            return False
        facts = self.facts.get((atom[0], len(atom) - 1), ())
        return any(unify(atom, fact, {}) is not None for fact in facts)


def _same_instance(atom: Atom, other: Atom) -> bool:
    """``atom`` unifies with ``other`` binding none of the operator's own (tag 0)
    parameters to anything but a fresh parameter, and no two of them to the same one."""
    binding = unify(atom, other, {})
    if binding is None:
        return False
    images: set[Term] = set()
    for param in _params(atom) | _params(other):
        if param.tag != 0:
            continue
        image = substitute(param, binding)
        if image == param:
            continue
        if type(image) is not Param or image.tag == 0 or image in images:
            return False
        images.add(image)
    return True


def _positive(unit: Formula) -> bool:
    return isinstance(unit, Atomic) and unit.atom[0] != EQUALITY


def _atoms(formula: Formula) -> Iterator[Atom]:
    return atoms_of(formula)


def _renamed(atom: Atom, tag: int) -> Atom:
    """``atom`` with its parameters and quantified variables as parameters of ``tag``."""

    def term(t: Term | Var) -> Term:
        if isinstance(t, Var):
            return Param(f"?{t.name}", tag)
        if type(t) is Param:
            return Param(t.name, tag)
        if type(t) is tuple:
            return (t[0], *map(term, t[1:]))
        return t

    return (atom[0], *map(term, atom[1:]))


def _params(atom: Atom) -> set[Param]:
    found: set[Param] = set()
    stack: list[object] = list(atom[1:])
    while stack:
        term = stack.pop()
        if type(term) is Param:
            found.add(term)
        elif type(term) is tuple:
            stack.extend(term[1:])
    return found
