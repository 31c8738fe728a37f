"""A goal agenda for means-ends analysis: reasonable orders between G0's atoms.

Koehler and Hoffmann (JAIR 12, 2000) call goal A *reasonably ordered* before goal B when,
once B holds, A cannot be achieved without destroying B: in depot or blocks,
``on(crate1, crate0)`` is best achieved after ``on(crate0, pallet1)``, since moving crate0
needs ``clear(crate0)``, which ``on(crate1, crate0)`` rules out. STRIPS left to itself
picks differences from the uncompleted proof of all of G0 and stacks the top crate first,
then spends thousands of nodes undoing it.

The orders are approximated lifted, from the operators' add, delete and precondition
lists and M0, with no grounding:

- *necessary facts* of a goal atom A: the ground atoms every operator that adds A needs
  in its precondition (intersected over the achieving schemata, with A's bindings), and,
  two levels down, what every achiever of those preconditions needs (a crate must be
  ``clear`` before a hoist lifts it, before it is dropped on the pallet);
- fact p is *inconsistent* with goal B when not both hold in M0 and every operator that
  adds B deletes p (``drop(h, crate1, crate0, place)`` deletes ``clear(crate0)``);
- A comes before B when a necessary fact of A is inconsistent with B.

The agenda is G0's atoms in layers (each layer the goals no unplaced goal must precede;
on a cycle, all the rest), and the search achieves them one atom at a time, layer after
layer (within a layer in G0's order): its entries are the growing conjunctions, each one
atom longer than the last. An entry that adds a whole layer at once left the search to
work on all of the layer's atoms together, each from its own uncompleted proof: on depot
04 of IPC 2002 (layer one: crates onto pallets that other stacks occupy), means-ends
with the relaxed-plan evaluator took 5,240 nodes, about 1,300 one atom at a time (depot
03: 1,321 and 1,091). Goals with no orders among them make a one-entry agenda: G0.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator

from strips_framework.logic.formulas import And, Atomic, Formula, conjuncts
from strips_framework.logic.terms import EQUALITY, WILDCARD, Atom, Param, Term, is_ground
from strips_framework.logic.unify import substitute, unify
from strips_framework.worldmodel.problem import OperatorSchema, Problem
from strips_framework.worldmodel.world import WorldModel

#: What the necessary facts of a goal are judged against: M0's facts, or a model.
Facts = frozenset[Atom] | WorldModel

#: How many achiever levels the necessary facts of a goal are collected from.
_DEPTH = 2


def goal_agenda(problem: Problem) -> tuple[Formula, ...]:
    """The conjunctions to achieve in turn, each one atom longer than the one before,
    the last being G0 (``(G0,)`` when G0 is not a conjunction of ground atoms or its
    atoms have no reasonable orders)."""
    atoms = _ground_goal_atoms(problem.goal)
    if atoms is None or len(atoms) < 2:
        return (problem.goal,)
    layers = agenda_layers(atoms, problem.operators, frozenset(problem.facts))
    if len(layers) < 2:
        return (problem.goal,)
    agenda: list[Formula] = []
    achieved: list[Atom] = []
    for atom in (atom for layer in layers for atom in layer):
        achieved.append(atom)
        agenda.append(And(tuple(Atomic(a) for a in achieved)))
    return (*agenda[:-1], problem.goal)


def agenda_layers(
    goals: list[Atom], operators: Iterable[OperatorSchema], initial: frozenset[Atom]
) -> list[list[Atom]]:
    """``goals`` in layers by reasonable orders, each in its first order within a layer."""
    operators = tuple(operators)
    before = {
        (a, b)
        for a in goals
        for b in goals
        if a != b and any(_inconsistent(p, b, operators, initial)
                          for p in _necessary(a, operators, initial, _DEPTH))
    }
    layers, left = [], list(goals)
    while left:
        free = [b for b in left if not any((a, b) in before for a in left if a != b)]
        layer = free or left  # a cycle: no order among the rest is trusted
        layers.append(layer)
        left = [goal for goal in left if goal not in layer]
    return layers


def _ground_goal_atoms(goal: Formula) -> list[Atom] | None:
    atoms = []
    for part in conjuncts(goal):
        if not isinstance(part, Atomic) or not is_ground(part.atom):
            return None
        if part.atom not in atoms:
            atoms.append(part.atom)
    return atoms


def _necessary(
    atom: Atom, operators: tuple[OperatorSchema, ...], initial: Facts, depth: int,
    strict: bool = False,
) -> set[Atom]:
    """Ground atoms that hold whenever an operator adding ``atom`` is applied for the
    first time (see the module docstring); empty when no operator adds it. ``strict``:
    see :func:`_only_after`."""
    common: set[Atom] | None = None
    for schema, binding in _achievers(atom, operators):
        pres = [_unbound_to_variables(substitute(pre, binding), {})
                for pre in _positive_atoms(schema.precondition)]
        if any(_only_after(pre, atom, operators, initial, strict) for pre in pres):
            continue
        found: set[Atom] = {pre for pre in pres if is_ground(pre)}
        if depth > 1:
            for pre in pres:
                found |= _necessary(pre, operators, initial, depth - 1, strict)
        common = found if common is None else common & found
    return common or set()


def _only_after(
    pre: Atom, atom: Atom, operators: tuple[OperatorSchema, ...], initial: Facts,
    strict: bool = False,
) -> bool:
    """Whether ``pre`` can only hold once ``atom`` has held: no M0 fact matches it and
    every operator adding it needs ``atom`` (depot's ``unload`` makes ``lifting(h, c)``
    from ``in(c, t)``, which only ``load`` adds, from ``lifting(h, c)``: the first
    ``lifting`` of a crate on the floor comes from ``lift``, which needs it ``clear``).
    ``strict``: a need that matches ``atom`` only by giving a parameter ``pre`` leaves
    free a value does not count: ``available(h)`` comes from dropping any crate, not
    only after ``lifting(h, c)`` of one ``c``."""
    if _matched(pre, initial):
        return False
    achievers = 0
    for schema, binding in _achievers(pre, operators):
        achievers += 1
        needs = (substitute(p, binding) for p in _positive_atoms(schema.precondition))
        if not any(_needs(need, atom, strict) for need in needs):
            return False
    return achievers > 0


def _needs(need: Atom, atom: Atom, strict: bool) -> bool:
    """Whether precondition atom ``need`` asks for ``atom`` (see :func:`_only_after`)."""
    unifier = unify(need, atom, {})
    if unifier is None or not strict:
        return unifier is not None
    return not any(
        is_ground(substitute(term, unifier))
        for term in need[1:] if isinstance(term, (Param, int))
    )


def _matched(atom: Atom, facts: Facts) -> bool:
    """Whether a fact of ``facts`` (a set of atoms, or a world model) unifies with ``atom``."""
    if isinstance(facts, WorldModel):
        candidates: Iterable[Atom] = facts.facts_matching(atom)
    else:
        candidates = (fact for fact in facts if fact[0] == atom[0])
    return any(unify(atom, fact, {}) is not None for fact in candidates)


def needed_first(atom: Atom, goal: Atom, operators: tuple[OperatorSchema, ...],
                 model: WorldModel) -> bool:
    """Whether ``goal`` (ground) must hold before any operator can first make ``atom``
    true from ``model``: it is in the precondition of every achiever of ``atom`` that
    does not need ``atom`` itself (see :func:`_necessary`, one level). An instance
    pushed to achieve ``goal`` that needs ``atom`` goes round in a circle: depot's
    ``drop(x, crate5, z, p)``, offered for ``clear(crate5)``, needs
    ``lifting(x, crate5)``, and a crate on a stack is lifted only once it is clear."""
    atom = _unbound_to_variables(atom, {})
    return not _matched(atom, model) and goal in _necessary(atom, operators, model, 1, True)


def _inconsistent(
    fact: Atom, goal: Atom, operators: tuple[OperatorSchema, ...], initial: frozenset[Atom]
) -> bool:
    """Whether every operator that adds ``goal`` deletes ``fact`` (and M0 does not hold
    both): then ``fact`` and ``goal`` are not expected to hold together."""
    if fact == goal or (fact in initial and goal in initial):
        return False
    achievers = 0
    for schema, binding in _achievers(goal, operators):
        achievers += 1
        if not any(_deletes(substitute(d, binding), fact) for d in schema.delete_list):
            return False
    return achievers > 0


def _achievers(
    atom: Atom, operators: tuple[OperatorSchema, ...]
) -> Iterator[tuple[OperatorSchema, dict]]:
    """Each schema with an add-list atom that unifies with ``atom``, and the unifier."""
    for schema in operators:
        for add in schema.add_list:
            binding = unify(add, atom, {})
            if binding is not None:
                yield schema, binding


def _deletes(pattern: Atom, fact: Atom) -> bool:
    return len(pattern) == len(fact) and all(
        p == f or p == WILDCARD for p, f in zip(pattern, fact)
    )


def _positive_atoms(formula: Formula) -> Iterable[Atom]:
    for part in conjuncts(formula):
        if isinstance(part, Atomic) and part.atom[0] != EQUALITY:
            yield part.atom


def _unbound_to_variables(term: Term, names: dict[Param, int]) -> Term:
    """``term`` with its schema parameters made unification variables (one per
    parameter), so that a deeper level's schema (maybe the same one) does not take them
    for its own parameters."""
    if isinstance(term, Param):
        return names.setdefault(term, len(names))
    if isinstance(term, tuple):
        return tuple(_unbound_to_variables(t, names) if i else t for i, t in enumerate(term))
    return term
