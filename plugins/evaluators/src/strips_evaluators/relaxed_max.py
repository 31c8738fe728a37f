"""An admissible estimate over world models: the first layer of a relaxed planning graph
from the node's model in which the goal holds (hmax with unit costs).

Made for ``model-astar``, whose breadth-first evaluator gives A* no guidance: on the
robot world's light task it cuts the tree from 762 nodes to a few dozen. Unlike
``relaxed-plan`` it grounds nothing up front: the world models of native problems rest on
axioms (``CONNECTS`` is symmetric, a door is in the rooms it joins) that a grounding from
M0's facts does not see, so it explores from each model's own facts, closed under the
axioms at every layer.
"""

from __future__ import annotations

import itertools
import math
from collections import OrderedDict, defaultdict
from collections.abc import Iterator, Sequence
from typing import ClassVar

from strips_framework.capabilities import ADMISSIBLE
from strips_framework.logic.clauses import Clause
from strips_framework.logic.formulas import And, Atomic, Exists, Formula, Not, Var
from strips_framework.logic.terms import EQUALITY, Atom, Param, is_ground
from strips_framework.means_ends.features import subgoals
from strips_framework.means_ends.node import Node
from strips_framework.options import Configurable
from strips_framework.records import Record
from strips_framework.worldmodel.problem import OperatorSchema
from strips_framework.worldmodel.world import InitialModel, WorldModel

#: How many models' estimates a search keeps (the ones used last).
MODELS_KEPT = 4096

Binding = dict[object, object]


class RelaxedMaxEvaluator(Configurable):
    """A*'s ``g + h``: operators applied, plus the larger of two lower bounds.

    - The goal-list bound of ``astar-goals``: one application per goal above G0, one
      more when the first goal is unproved.
    - The relaxed layer of G0: layer 0 holds the model's facts; layer ``i + 1`` adds the
      add lists of every operator instance whose precondition holds in layer ``i``
      closed under M0's Horn axioms. Deletes are ignored, so facts only accumulate and no
      plan reaches G0 in fewer steps than the first layer where it holds (unit costs).

    *Relaxed conditions.* A precondition or goal counts its positive atoms, inside
    conjunctions and existentials, and its (in)equalities; negated atoms, disjunctions and
    universals are taken as true (only more instances apply, so the bound stays a bound).
    A parameter only the effects mention ranges over every constant in sight.

    *When it does not apply.* With a non-Horn axiom or an axiom using equality, the
    closure may miss what the prover proves, so the layer could overestimate: then only
    the goal-list bound is used. A goal no layer reaches scores infinity: no plan exists.
    """

    name: ClassVar[str] = "relaxed-max"
    admissible: ClassVar[bool] = True
    capabilities: ClassVar[frozenset[str]] = frozenset({ADMISSIBLE})

    def for_problem(
        self, operators: Sequence[OperatorSchema], initial: InitialModel
    ) -> RelaxedMaxScorer:
        return RelaxedMaxScorer(_Layers(operators, initial))

    def evaluate(self, node: Node) -> float:
        """Refused: the estimate needs the problem's operators, which a node lacks. The
        builtin strategies call :meth:`for_problem` first and score with its result."""
        raise TypeError("the relaxed-max evaluator scores nodes only after for_problem()")


class RelaxedMaxScorer:
    """:class:`RelaxedMaxEvaluator` prepared for one problem."""

    name = RelaxedMaxEvaluator.name
    admissible = True

    def __init__(self, layers: _Layers) -> None:
        self.layers = layers

    def evaluate(self, node: Node) -> float:
        unproved = 1 if node.difference is not None else 0
        bound = subgoals(node) + unproved
        if unproved and self.layers.exact:
            bound = max(bound, self.layers.first_layer(node.model, node.goals[-1].formula))
        return node.cost + bound


class _Layers:
    """The relaxed exploration of one problem's operators from its models."""

    def __init__(self, operators: Sequence[OperatorSchema], initial: InitialModel) -> None:
        rules = [c for c in initial.clauses if not c.is_unit]
        self.exact = all(_is_horn_rule(c) for c in rules)
        self.rules = [(_head(c), [a for positive, a in c.literals if not positive]) for c in rules]
        self.operators = [(s, _Query.of(s.precondition), s.add_list) for s in operators]
        constants = {
            t for c in initial.clauses for _, a in c.literals for t in a[1:] if type(t) is str
        }
        constants.update(t for s in operators for a in s.add_list for t in a[1:] if type(t) is str)
        self.constants = sorted(constants)
        self._known: OrderedDict[tuple[WorldModel, Formula], float] = OrderedDict()

    def first_layer(self, model: WorldModel, goal: Formula) -> float:
        key = (model, goal)
        known = self._known.get(key)
        if known is None:
            known = self._explore(model, _Query.of(goal))
            self._known[key] = known
            if len(self._known) > MODELS_KEPT:
                self._known.popitem(last=False)
        else:
            self._known.move_to_end(key)
        return known

    def _explore(self, model: WorldModel, goal: _Query) -> float:
        facts = {c.literals[0][1] for c in model.clauses() if c.is_unit and c.literals[0][0]}
        for layer in itertools.count():
            closed = _Facts(self._closure(facts))
            if next(goal.bindings(closed, self.constants), None) is not None:
                return float(layer)
            new = set()
            for _, query, adds in self.operators:
                for binding in query.bindings(closed, self.constants, adds):
                    for atom in adds:
                        ground = _bind(atom, binding)
                        if ground not in closed.all:
                            new.add(ground)
            if not new:
                return math.inf
            facts = closed.all | new
        raise AssertionError("unreachable")

    def _closure(self, facts: set[Atom]) -> set[Atom]:
        """``facts`` closed under the Horn rules (naive fixpoint; small models)."""
        closed = set(facts)
        grew = bool(self.rules)
        while grew:
            grew = False
            index = _Facts(closed)
            for head, body in self.rules:
                query = _Query(body, [], [])
                for binding in query.bindings(index, self.constants, [head]):
                    atom = _bind(head, binding)
                    if is_ground(atom) and atom not in closed:
                        closed.add(atom)
                        grew = True
        return closed


class _Facts:
    """Ground facts by (predicate, arity), for the joins."""

    def __init__(self, facts: set[Atom]) -> None:
        self.all = facts
        self.by_key: dict[tuple[str, int], list[Atom]] = defaultdict(list)
        for atom in facts:
            self.by_key[(atom[0], len(atom))].append(atom)


class _Query(Record):
    """A relaxed condition: atoms to join, equalities and inequalities to check."""

    atoms: list[Atom]
    equal: list[tuple[object, object]]
    unequal: list[tuple[object, object]]

    __slots__ = ("atoms", "equal", "unequal")

    def __init__(
        self,
        atoms: list[Atom],
        equal: list[tuple[object, object]],
        unequal: list[tuple[object, object]],
    ) -> None:
        self.atoms = atoms
        self.equal = equal
        self.unequal = unequal

    @classmethod
    def of(cls, formula: Formula) -> _Query:
        atoms: list[Atom] = []
        equal: list[tuple[object, object]] = []
        unequal: list[tuple[object, object]] = []
        for part in _parts(formula):
            if isinstance(part, Atomic):
                if part.atom[0] == EQUALITY:
                    equal.append((part.atom[1], part.atom[2]))
                else:
                    atoms.append(part.atom)
            elif isinstance(part.body, Atomic) and part.body.atom[0] == EQUALITY:  # a Not
                unequal.append((part.body.atom[1], part.body.atom[2]))
        return cls(atoms, equal, unequal)

    def bindings(
        self, facts: _Facts, constants: list[str], needed: Sequence[Atom] = ()
    ) -> Iterator[Binding]:
        """Bindings of the atoms' open terms to facts, then of the open terms of
        ``needed`` and the (in)equalities that are still unbound, over the constants."""
        for binding in _join(self.atoms, facts, {}):
            terms = [t for atom in needed for t in atom[1:]]
            terms += [t for pair in (*self.equal, *self.unequal) for t in pair]
            rest = {t for t in terms if _open(t) and t not in binding}
            free = sorted(rest, key=repr)
            for values in itertools.product(constants, repeat=len(free)):
                full = {**binding, **dict(zip(free, values))}
                if all(_value(a, full) == _value(b, full) for a, b in self.equal) and all(
                    _value(a, full) != _value(b, full) for a, b in self.unequal
                ):
                    yield full


def _parts(formula: Formula) -> Iterator[Atomic | Not]:
    """The conjuncts a relaxed condition keeps (see :class:`RelaxedMaxEvaluator`)."""
    if isinstance(formula, And):
        for part in formula.parts:
            yield from _parts(part)
    elif isinstance(formula, Exists):
        yield from _parts(formula.body)
    elif isinstance(formula, Atomic):
        yield formula
    elif (
        isinstance(formula, Not)
        and isinstance(formula.body, Atomic)
        and formula.body.atom[0] == EQUALITY
    ):
        yield formula


def _join(atoms: list[Atom], facts: _Facts, binding: Binding) -> Iterator[Binding]:
    if not atoms:
        yield binding
        return
    atom, rest = atoms[0], atoms[1:]
    for fact in facts.by_key.get((atom[0], len(atom)), ()):
        extended = _match(atom, fact, binding)
        if extended is not None:
            yield from _join(rest, facts, extended)


def _match(pattern: Atom, fact: Atom, binding: Binding) -> Binding | None:
    extended = dict(binding)
    for term, value in zip(pattern[1:], fact[1:]):
        if _open(term):
            if extended.setdefault(term, value) != value:
                return None
        elif type(term) is tuple and not is_ground(term):
            continue  # a function term with variables: taken to match (relaxed)
        elif term != value:
            return None
    return extended


def _open(term: object) -> bool:
    return isinstance(term, (Param, Var)) or type(term) is int


def _value(term: object, binding: Binding) -> object:
    return binding.get(term, term) if _open(term) else term


def _bind(atom: Atom, binding: Binding) -> Atom:
    return (atom[0], *(_value(t, binding) for t in atom[1:]))


def _is_horn_rule(clause: Clause) -> bool:
    positives = [a for positive, a in clause.literals if positive]
    return len(positives) == 1 and all(a[0] != EQUALITY for _, a in clause.literals)


def _head(clause: Clause) -> Atom:
    return next((a for positive, a in clause.literals if positive), ("false",))
