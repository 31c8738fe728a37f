"""Generalizing a plan's triangle table (Fikes, Hart & Nilsson 1972, section 4).

1. *Lift*: every occurrence of a constant in column 0 becomes its own parameter, every step
   gets its own copy of its operator's parameters, and the clauses a step adds follow its
   parameters. Constants written in the operators (``ROBOT`` in ``goto2``) stay.
2. *Constrain*: replay each row's proof on the lifted table. The precondition atoms of
   step r (with step r's parameters, existential variables as fresh parameters) are
   unified with the lifted facts its proof used, through the same axioms and derived
   facts. The goal row is replayed with the goal's constants lifted too, so that the table
   keeps only the goal's *shape* (``NEXTTO(p1, p2)``), not the task's objects. What is
   left is as general as the proofs allow.
3. *Protect*: the original plan deleted nothing a later step needed, but an instance of
   the lifted plan might (``pushto(p3, p1)`` deletes ``NEXTTO(p1, p2)`` when p3 = p2).
   For every marked clause and every step between the one that supplies it and the row
   that needs it, a delete-list pattern that unifies with the clause gives a
   :class:`Distinct` constraint, chosen among the unifier's bindings as one the original
   plan satisfied. With these, every instance whose kernel holds replays (the soundness
   the tests check with the simulator on random instances).
"""

from __future__ import annotations

import itertools

from strips_framework.logic.formulas import And, Atomic, Exists, Formula, Not, Or
from strips_framework.logic.terms import WILDCARD, Atom, Param, Term
from strips_framework.logic.unify import substitute, unify
from strips_framework.macrops.ground_table import GroundTable
from strips_framework.macrops.proofs import DERIVED, FACT, Derivation, MacroError, Witness
from strips_framework.macrops.table import Cell, Distinct, Step, TriangleTable
from strips_framework.records import Record
from strips_framework.worldmodel.simulate import Simulator, ground_term


class Generalized(Record):
    """A generalized table and the binding of its parameters that gives back the plan it
    was learned from."""

    table: TriangleTable
    example: dict[Param, Term]

    __slots__ = ("table", "example")

    def __init__(self, table: TriangleTable, example: dict[Param, Term]) -> None:
        self.table = table
        self.example = example


class _Lifter:
    def __init__(self, ground: GroundTable) -> None:
        self.ground = ground
        self.rules = Simulator(ground.problem).rules
        self.fresh = itertools.count(1)
        self.example: dict[Param, Term] = {}
        self.subst: dict = {}
        table = ground.table
        self.steps = [
            Step(s.schema, [self._param(p.name, arg) for p, arg in zip(s.schema.parameters, s.arguments)])
            for s in table.steps
        ]
        self.column0: dict[tuple[int, Atom], Atom] = {}

    def _param(self, name: str, value: Term) -> Param:
        param = Param(f"{name}#{next(self.fresh)}")
        self.example[param] = value
        return param

    def lift_constants(self, atom: Atom) -> Atom:
        return (atom[0], *(self._param("c", arg) for arg in atom[1:]))

    def cell_atom(self, row: int, atom: Atom) -> Atom:
        """The lifted form of a fact row ``row`` used, from the cell it sits in."""
        col = self.ground.origins[row - 1][atom]
        if col == 0:
            key = (row, atom)
            if key not in self.column0:
                self.column0[key] = self.lift_constants(atom)
            return self.column0[key]
        ground_adds = self.ground.table.steps[col - 1].adds()
        return self.steps[col - 1].adds()[ground_adds.index(atom)]

    def unify(self, left: Term, right: Term) -> None:
        if unify(left, right, self.subst) is None:
            raise MacroError(
                f"internal error: the lifted proof does not replay ({left} vs {right})"
            )

    def conclusion(self, proof: Derivation, row: int) -> Atom:
        """The lifted atom ``proof`` proves, unifying what its steps need."""
        if proof.kind == FACT:
            return self.cell_atom(row, proof.atom)
        if proof.kind == DERIVED:
            for child in proof.children:
                self.unify(self.conclusion(child, row), child.atom)
            return proof.atom
        rule = self.rules[proof.rule]
        renaming = {var: self._param("v", value) for var, value in proof.env}
        for body, child in zip(rule.body, proof.children):
            self.unify(ground_term(body, renaming), self.conclusion(child, row))
        return ground_term(rule.head[proof.head], renaming)

    def replay(self, row: int, witness: Witness) -> list[tuple[Term, Term]]:
        """Unify row ``row``'s condition with the lifted facts its proof used; return the
        lifted sides of the inequalities it tested."""
        n = len(self.steps)
        if row <= n:
            step = self.steps[row - 1]
            condition: Formula = step.schema.precondition
            scope: dict = step.binding()
            lift_goal = False
        else:
            condition, scope, lift_goal = self.ground.problem.goal, {}, True
        atoms: dict[int, Atom] = {}
        self._lift_formula(condition, scope, atoms, lift_goal)
        for need in witness.needed:
            self.unify(atoms[id(need.where)], self.conclusion(need.proof, row))
        return [(atoms[id(eq)][1], atoms[id(eq)][2]) for eq in witness.unequal]

    def _lift_formula(self, formula: Formula, scope: dict, out: dict[int, Atom], goal: bool) -> None:
        if isinstance(formula, Atomic):
            atom = ground_term(formula.atom, scope)
            if goal:
                atom = (atom[0], *(
                    self._param("g", a) if type(a) is str else a for a in atom[1:]
                ))
            out[id(formula)] = atom
        elif isinstance(formula, Not):
            self._lift_formula(formula.body, scope, out, goal)
        elif isinstance(formula, (And, Or)):
            for part in formula.parts:
                self._lift_formula(part, scope, out, goal)
        elif isinstance(formula, Exists):
            inner = {**scope, **{v: Param(f"{v.name}#{next(self.fresh)}") for v in formula.variables}}
            self._lift_formula(formula.body, inner, out, goal)


def generalize(ground: GroundTable) -> Generalized:
    """The most general table whose proofs are instances of ``ground``'s, with the
    constraints that keep its instances sound; parameters renamed ``p1, p2, ...``."""
    lifter = _Lifter(ground)
    table = ground.table
    n = table.size
    unequal: list[tuple[int, Term, Term]] = []
    for row, witness in enumerate(ground.proofs, start=1):
        unequal.extend((row, left, right) for left, right in lifter.replay(row, witness))
    marked: dict[Cell, tuple[Atom, ...]] = {}
    for (row, col), atoms in table.marked.items():
        if row == n + 1 and col == 0:
            continue  # what held from the start and the goal needs: not the plan's doing
        marked[(row, col)] = tuple(lifter.cell_atom(row, a) for a in atoms)
    unmarked = {
        (row, col): tuple(
            lifter.steps[col - 1].adds()[table.steps[col - 1].adds().index(a)] for a in atoms
        )
        for (row, col), atoms in table.unmarked.items()
    }
    subst = lifter.subst
    lifted = TriangleTable(lifter.steps, marked, unmarked).substituted(subst)
    example = _example(lifter.example, subst)
    distinct = [
        Distinct(substitute(left, subst), substitute(right, subst), row, row)
        for row, left, right in unequal
    ]
    distinct.extend(_protections(lifted, example))
    lifted = TriangleTable(lifted.steps, lifted.marked, lifted.unmarked, distinct)
    names = {p: Param(f"p{i}") for i, p in enumerate(lifted.parameters(), start=1)}
    return Generalized(
        lifted.substituted(names),
        {names[p]: value for p, value in example.items() if p in names},
    )


def _example(values: dict[Param, Term], subst: dict) -> dict[Param, Term]:
    """The original plan's value of each parameter left after ``subst``."""
    example: dict[Param, Term] = {}
    for param, value in values.items():
        representative = substitute(param, subst)
        if type(representative) is Param:
            example[representative] = value
    return example


def _protections(table: TriangleTable, example: dict[Param, Term]) -> list[Distinct]:
    """The :class:`Distinct` constraints that keep each step from deleting a marked clause
    that a later row needs from an earlier column (see the module's point 3)."""
    found: dict[Distinct, None] = {}
    wildcard = itertools.count()
    for (row, col), atoms in sorted(table.marked.items()):
        for atom in atoms:
            for k in range(col + 1, row):
                for pattern in table.steps[k - 1].deletes():
                    renamed = _rename_wildcards(pattern, wildcard)
                    unifier = unify(renamed, atom, {})
                    if unifier is None:
                        continue
                    pairs = [
                        (key, substitute(key, unifier))
                        for key in unifier
                        if not _is_wildcard(key)
                    ]
                    pairs = [(k_, v) for k_, v in pairs if not _is_wildcard(v)]
                    chosen = next(
                        ((left, right) for left, right in pairs
                         if substitute(left, example) != substitute(right, example)),
                        None,
                    )
                    if chosen is None:
                        raise MacroError(
                            f"internal error: step {k} deletes {atom}, which row {row} needs"
                        )
                    found.setdefault(Distinct(*chosen, row, k))
    return list(found)


def _rename_wildcards(term: Term, counter: itertools.count) -> Term:
    if term == WILDCARD:
        return Param(f"$#{next(counter)}")
    if type(term) is tuple:
        return (term[0], *(_rename_wildcards(a, counter) for a in term[1:]))
    return term


def _is_wildcard(term: Term) -> bool:
    return type(term) is Param and term.name.startswith("$#")
