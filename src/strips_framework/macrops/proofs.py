"""Ground precondition proofs of a plan's steps: which facts each step relies on, and how.

A triangle table needs, for every step, the facts its precondition proof used; its
generalization replays those proofs on lifted clauses (Fikes, Hart & Nilsson 1972). The
proofs are found here by model checking on the simulator's semantics
(:mod:`strips_framework.worldmodel.simulate`), not by the planner's prover, so that a table can be
built for any valid plan (from means-ends or forward search, native or PDDL, or written by
hand) and a proof is a small tree that can be replayed step by step:

- a *fact* of the state (a leaf: it goes into the table),
- a *derived* fact of M0 resting on its primitive supports (paper, III.B),
- a Horn axiom applied to proofs of its body atoms.

A precondition's proof is a :class:`Witness`: the existential variables' values, the
proof of every atom the precondition needs, and the inequalities it tested.
"""

from __future__ import annotations

import itertools
from collections import defaultdict
from collections.abc import Iterator

from strips_framework.errors import StripsError
from strips_framework.logic.formulas import (
    And,
    Atomic,
    Exists,
    Formula,
    Not,
    Or,
    Truth,
    Var,
    formula_to_str,
)
from strips_framework.logic.terms import EQUALITY, Atom, Param, Term
from strips_framework.records import Record
from strips_framework.worldmodel.simulate import Env, Simulator, State, body_matches, ground_term

FACT, DERIVED, RULE = "fact", "derived", "rule"


class MacroError(StripsError):
    """A plan, table or library that the MACROP machinery cannot use, and why."""


class Derivation(Record):
    """How the ground ``atom`` follows from a state.

    ``kind`` is :data:`FACT` (a leaf), :data:`DERIVED` (``children`` are the supports) or
    :data:`RULE`: axiom ``rule`` (an index into ``Simulator.rules``) with head atom
    ``head`` and variable values ``env``, ``children`` proving its body atoms in order.
    """

    atom: Atom
    kind: str
    children: tuple[Derivation, ...]
    rule: int
    head: int
    env: tuple[tuple[Var, Term], ...]

    __slots__ = ("atom", "kind", "children", "rule", "head", "env")

    def __init__(
        self,
        atom: Atom,
        kind: str,
        children: tuple[Derivation, ...] = (),
        rule: int = -1,
        head: int = -1,
        env: tuple[tuple[Var, Term], ...] = (),
    ) -> None:
        self.atom = atom
        self.kind = kind
        self.children = children
        self.rule = rule
        self.head = head
        self.env = env

    def leaves(self) -> Iterator[Derivation]:
        if self.kind == FACT:
            yield self
        for child in self.children:
            yield from child.leaves()


class Needed(Record):
    """One atom occurrence of a precondition (the ``Atomic`` node ``where``) and its proof."""

    where: Atomic
    proof: Derivation

    __slots__ = ("where", "proof")

    def __init__(self, where: Atomic, proof: Derivation) -> None:
        self.where = where
        self.proof = proof


class Witness(Record):
    """A proof of a precondition: the atom occurrences it needed, with their proofs, and
    the equality atoms whose negation it tested (``Atomic`` nodes of the formula, told
    apart by identity, so that generalization can lift them in their own scope)."""

    needed: tuple[Needed, ...]
    unequal: tuple[Atomic, ...]

    __slots__ = ("needed", "unequal")

    def __init__(self, needed: tuple[Needed, ...], unequal: tuple[Atomic, ...]) -> None:
        self.needed = needed
        self.unequal = unequal


class Justifier:
    """The closure of one state with the first proof found of every atom in it."""

    def __init__(self, simulator: Simulator, state: State) -> None:
        self.simulator = simulator
        proofs: dict[Atom, Derivation] = {atom: Derivation(atom, FACT) for atom in state}
        for fact in simulator.problem.derived:
            if fact.atom not in proofs and all(s in state for s in fact.supports):
                children = tuple(proofs[s] for s in fact.supports)
                proofs[fact.atom] = Derivation(fact.atom, DERIVED, children)
        by_predicate: dict[tuple[str, int], set[Atom]] = defaultdict(set)
        for atom in proofs:
            by_predicate[atom[0], len(atom)].add(atom)
        constants = simulator.problem.constants
        changed = True
        while changed:
            changed = False
            for number, rule in enumerate(simulator.rules):
                for env in list(body_matches(rule.body, by_predicate, {})):
                    for values in itertools.product(constants, repeat=len(rule.free)):
                        full = {**env, **dict(zip(rule.free, values))}
                        children = tuple(proofs[ground_term(a, full)] for a in rule.body)
                        for head, atom in enumerate(rule.head):
                            grounded = ground_term(atom, full)
                            if grounded in proofs:
                                continue
                            pairs = tuple(sorted(full.items(), key=lambda kv: str(kv[0])))
                            proofs[grounded] = Derivation(
                                grounded, RULE, children, number, head, pairs
                            )
                            by_predicate[grounded[0], len(grounded)].add(grounded)
                            changed = True
        self.proofs = proofs
        self.by_predicate = by_predicate

    def witness(self, formula: Formula, env: Env) -> Witness | None:
        """A proof of ``formula`` (positive-existential, with inequalities) in this
        state, or ``None`` when it does not hold."""
        for found in self._prove(formula, dict(env)):
            return found
        return None

    def _prove(self, formula: Formula, env: dict) -> Iterator[Witness]:
        if isinstance(formula, Truth):
            if formula.value:
                yield Witness((), ())
            return
        if isinstance(formula, Atomic):
            yield from self._prove_atom(formula, env)
            return
        if isinstance(formula, Not) and isinstance(formula.body, Atomic):
            atom = ground_term(formula.body.atom, env)
            if atom[0] == EQUALITY and _ground(atom) and atom[1] != atom[2]:
                yield Witness((), (formula.body,))
            return
        if isinstance(formula, And):
            yield from self._prove_all(formula.parts, env)
            return
        if isinstance(formula, Or):
            for part in formula.parts:
                yield from self._prove(part, env)
            return
        if isinstance(formula, Exists):
            yield from self._prove_exists(formula, env)
            return
        raise MacroError(
            f"cannot build a triangle table: the precondition part {formula_to_str(formula)} "
            "is not a conjunction, disjunction or existential of atoms and inequalities"
        )

    def _prove_atom(self, formula: Atomic, env: dict) -> Iterator[Witness]:
        pattern = ground_term(formula.atom, env)
        if pattern[0] == EQUALITY:
            if _ground(pattern) and pattern[1] == pattern[2]:
                yield Witness((), ())
            return
        if _ground(pattern):
            proof = self.proofs.get(pattern)
            if proof is not None:
                yield Witness((Needed(formula, proof),), ())
            return
        for atom in sorted(self.by_predicate.get((pattern[0], len(pattern)), ()), key=repr):
            extended = _match(pattern, atom, env)
            if extended is not None:
                env.update(extended)
                yield Witness((Needed(formula, self.proofs[atom]),), ())
                for key in extended:
                    del env[key]

    def _prove_all(self, parts: tuple[Formula, ...], env: dict) -> Iterator[Witness]:
        if not parts:
            yield Witness((), ())
            return
        for first in self._prove(parts[0], env):
            for rest in self._prove_all(parts[1:], env):
                yield _join(first, rest)

    def _prove_exists(self, formula: Exists, env: dict) -> Iterator[Witness]:
        saved = {v: env.pop(v) for v in formula.variables if v in env}
        try:
            yield from self._prove(formula.body, env)
        finally:
            env.update(saved)


def _ground(atom: Atom) -> bool:
    return not any(isinstance(t, (Var, Param)) for t in _terms(atom))


def _terms(term: Term) -> Iterator[Term]:
    yield term
    if type(term) is tuple:
        for arg in term[1:]:
            yield from _terms(arg)


def _match(pattern: Term, atom: Term, env: dict) -> dict | None:
    """The new bindings of ``pattern``'s unbound variables that make it ``atom``."""
    new: dict = {}
    stack = [(pattern, atom)]
    while stack:
        p, a = stack.pop()
        if isinstance(p, Var):
            bound = new.get(p, env.get(p))
            if bound is None:
                new[p] = a
            elif bound != a:
                return None
        elif type(p) is tuple:
            if type(a) is not tuple or len(a) != len(p) or a[0] != p[0]:
                return None
            stack.extend(zip(p[1:], a[1:]))
        elif p != a:
            return None
    return new


def _join(left: Witness, right: Witness) -> Witness:
    return Witness(left.needed + right.needed, left.unequal + right.unequal)
