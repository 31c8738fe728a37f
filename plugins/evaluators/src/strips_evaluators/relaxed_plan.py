"""A node's remaining cost as a relaxed plan from its world model to its goal list.

The paper leaves the evaluation function open for experiment (II.B, V); this one brings
the delete relaxation of forward planners (hadd, hFF) to means-ends nodes. The schemata
are grounded once per problem by relaxed reachability from M0: every model a search
reaches is made by applying operators to M0, so its facts and the instances applicable in
its relaxation are among those found from M0. Per node, hadd runs from the model's facts
over these ground instances; the goals are the atoms of every goal on the goal list. An
operator earlier on the list is applied before a later goal is needed, so the ground atoms
it adds are free facts for that goal; each goal's atoms are bound jointly, over the
reached facts and those free ones. (Matching a goal atom on its own against any add atom
it might unify with let deep goal lists erase their later goals: ``drive`` adds
``at(truck, ?z)``, which unifies every ``at(?x, ?y)`` of every precondition below it, so
the deeper a list, the cheaper it looked, and means-ends on depot descended into
subgoal chains it never climbed out of.)
"""

from __future__ import annotations

import heapq
import math
from collections import ChainMap, OrderedDict, defaultdict
from collections.abc import Iterator, Mapping, Sequence
from typing import ClassVar

from strips_framework.logic.formulas import Atomic, Exists, Formula, Not, Var, conjuncts
from strips_framework.logic.terms import EQUALITY, Atom, Param, is_ground
from strips_framework.means_ends.node import Node
from strips_framework.means_ends.weights import weight
from strips_framework.options import Configurable, Option
from strips_framework.records import Record
from strips_framework.worldmodel.problem import OperatorSchema
from strips_framework.worldmodel.world import InitialModel, WorldModel

#: Values of the parameters and variables of some atoms.
Binding = dict[object, object]
#: A goal's parameters get the cheapest of at most this many bindings: a goal with many
#: unbound parameters would otherwise cost a join per node.
MAX_BINDINGS = 200
#: How many models' relaxed costs a search keeps (the ones used last).
MODELS_KEPT = 256
#: With ``relaxation = "auto"``, grounding the relaxation stops past this many instances
#: and the lifted relaxation is used instead: a task this large is one whose grounding
#: costs more than the search it serves.
GROUND_INSTANCES = 20_000


class RelaxedPlanEvaluator(Configurable):
    """Greedy best-first on a relaxed plan: ``h + cost_weight * operators applied``.

    h = the operators still on the goal list (each is applied once its precondition is
    proved) + the relaxed cost of the goal atoms from the node's model: the size of an FF
    relaxed plan (``estimate = "ff"``) or the hadd sum (``"add"``). Subgoaling keeps h
    about level, since the new goal-list operator takes over the relaxed plan's achiever of
    the literals it adds; applying an operator lowers it. ``successor_weight`` per
    successor already made lets a node's children go before its next alternative.

    *Relaxation.* Grounded once when it is small, else explored per model without
    grounding (option ``relaxation``; the two give the same hadd values and relaxed plans
    up to ties). Preconditions count their positive atoms (equalities are decided at
    grounding); negated atoms and disjunctions are dropped, which only enlarges what is
    reachable. Atoms of predicates an axiom concludes, or an operator adds with a parameter
    its precondition does not bind, are taken as free: they are not grounded. A goal atom
    with parameters costs its cheapest matching ground atom. A goal that no relaxed plan
    reaches scores infinity (a dead end: no sequence of operators makes it true). Not
    admissible.
    """

    name: ClassVar[str] = "relaxed-plan"
    admissible: ClassVar[bool] = False
    capabilities: ClassVar[frozenset[str]] = frozenset()

    options = (
        Option("estimate", str, "ff", choices=("ff", "add"),
               doc="the relaxed cost: an FF relaxed plan's size, or the hadd sum"),
        weight("cost_weight", 0.5, "per operator applied so far"),
        weight("successor_weight", 1.0, "per successor the node has generated"),
        Option("relaxation", str, "auto", choices=("auto", "ground", "lifted"),
               doc="'ground' grounds the relaxation once, 'lifted' explores it per model "
               "without grounding (strips_evaluators.lifted), 'auto' grounds unless "
               "grounding finds more than GROUND_INSTANCES instances"),
    )
    estimate: str
    cost_weight: float
    successor_weight: float
    relaxation: str

    def for_problem(
        self, operators: Sequence[OperatorSchema], initial: InitialModel
    ) -> RelaxedPlanScorer:
        """The relaxed task of one problem, built once per search."""
        task = None
        if self.relaxation != "lifted":
            limit = GROUND_INSTANCES if self.relaxation == "auto" else None
            task = _RelaxedTask.ground(operators, initial, limit)
        if task is None:
            task = _LiftedRelaxedTask(operators, initial)
        return RelaxedPlanScorer(self, task)

    def evaluate(self, node: Node) -> float:
        """Refused: the estimate needs the problem's operators, which a node lacks. The
        builtin strategies call :meth:`for_problem` first and score with its result."""
        raise TypeError("the relaxed-plan evaluator scores nodes only after for_problem()")


class RelaxedPlanScorer(Record):
    """:class:`RelaxedPlanEvaluator` prepared for one problem."""

    options: RelaxedPlanEvaluator
    task: _RelaxedTask

    __slots__ = ("options", "task")

    def __init__(self, options: RelaxedPlanEvaluator, task: _RelaxedTask) -> None:
        self.options = options
        self.task = task

    @property
    def name(self) -> str:
        return self.options.name

    @property
    def admissible(self) -> bool:
        return False

    def evaluate(self, node: Node) -> float:
        return sum(self.parts(node).values())

    def parts(self, node: Node) -> dict[str, float]:
        """The terms of the score, by name (the explorer page shows them)."""
        return {
            "h": self.task.estimate(node, self.options.estimate == "ff"),
            "cost": self.options.cost_weight * node.cost,
            "successors": self.options.successor_weight * node.successors_generated,
        }


class _ModelCosts:
    """One model's hadd costs and achievers, and the cheapest facts found for goals in
    it, by (goal atoms, atoms given by earlier goal-list operators). Mutable: ``cheapest``
    fills as goals are asked about."""

    __slots__ = ("cost", "supporter", "index", "cheapest")

    def __init__(self, cost: dict, supporter: dict, index: _FactIndex | None = None) -> None:
        self.cost = cost
        self.supporter = supporter
        #: The model's reached facts indexed for goal bindings (lifted relaxation only).
        self.index = index
        self.cheapest: dict[tuple[tuple[Atom, ...], frozenset[Atom]], list[int] | None] = {}


class _RelaxedTask:
    """Ground facts (numbered), ground instances (precondition and add-list fact numbers),
    and what the estimate treats as free."""

    def __init__(self) -> None:
        self.fact_ids: dict[Atom, int] = {}
        self.preconditions: list[tuple[int, ...]] = []
        self.adds: list[tuple[int, ...]] = []
        self.needed_by: list[list[int]] = []
        self.free: set[tuple[str, int]] = set()
        self.index = _FactIndex(())
        self._models: OrderedDict[WorldModel, _ModelCosts] = OrderedDict()

    @classmethod
    def ground(
        cls, operators: Sequence[OperatorSchema], initial: InitialModel, limit: int | None = None
    ) -> _RelaxedTask | None:
        """The ground relaxation; ``None`` once it has more than ``limit`` instances."""
        task = cls()
        task.free = _concluded_by_axioms(initial) | _added_unbound(operators)
        added = {(a[0], len(a)) for schema in operators for a in schema.add_list}
        facts = {atom for atom in initial.facts if is_ground(atom)}
        schemata = [(schema, _positive_atoms(schema.precondition)) for schema in operators]
        instances: dict[tuple[str, tuple], tuple[list[Atom], list[Atom]]] = {}
        index = _FactIndex(sorted(facts, key=repr))  # sorted: bindings in a fixed order
        grew = True
        while grew:  # naive fixpoint: rounds are as many as the relaxed plan's depth
            grew = False
            for schema, atoms in schemata:
                for binding in index.bindings(atoms, _constraints(schema.precondition)):
                    key = (schema.name, tuple(binding.get(p) for p in schema.parameters))
                    if key in instances:
                        continue
                    pre = [_bind(a, binding) for a in atoms if (a[0], len(a)) in added]
                    adds = [_bind(a, binding) for a in schema.add_list]
                    adds = [a for a in adds if is_ground(a)]
                    instances[key] = (pre, adds)
                    if limit is not None and len(instances) > limit:
                        return None
                    for atom in adds:
                        if atom not in index.facts:
                            index.add(atom)
                            grew = True
        for atom in sorted(index.facts, key=repr):
            task._fact(atom)
        task.index = index
        for pre, adds in instances.values():
            number = len(task.preconditions)
            task.preconditions.append(tuple(sorted({task.fact_ids[a] for a in pre})))
            task.adds.append(tuple(task.fact_ids[a] for a in adds))
            for fact in task.preconditions[-1]:
                task.needed_by[fact].append(number)
        return task

    def _fact(self, atom: Atom) -> int:
        number = self.fact_ids.setdefault(atom, len(self.fact_ids))
        if number == len(self.needed_by):
            self.needed_by.append([])
        return number

    def estimate(self, node: Node, ff: bool) -> float:
        known = self._of_model(node.model)
        goals: list[int] = []
        for atoms, provided in _goal_atoms(node, self.free):
            key = (tuple(atoms), provided)
            if key not in known.cheapest:
                known.cheapest[key] = self._cheapest_given(atoms, provided, known.cost)
            best = known.cheapest[key]
            if best is None:
                return math.inf
            goals.extend(best)
        on_list = len(node.goals) - 1
        if not ff:
            return on_list + sum(known.cost[g] for g in goals)
        return on_list + len(self._relaxed_plan(goals, known.supporter))

    def _of_model(self, model: WorldModel) -> _ModelCosts:
        """The hadd costs of ``model`` (and its goals' cheapest facts, filled in as they
        are asked for): a node's successors share its model, and a means-ends search
        keeps returning to a few models (201 in 3,000 nodes on depot 03), so they are
        kept for the :data:`MODELS_KEPT` models used last."""
        known = self._models.get(model)
        if known is None:
            known = _ModelCosts(*self._hadd(model))
            self._models[model] = known
            if len(self._models) > MODELS_KEPT:
                self._models.popitem(last=False)
        else:
            self._models.move_to_end(model)
        return known

    def _cheapest_given(
        self, atoms: list[Atom], provided: frozenset[Atom], cost: dict[int, float]
    ) -> list[int] | None:
        """:meth:`_cheapest` with the ``provided`` atoms free, less those atoms."""
        given = {self.fact_ids[a] for a in provided if a in self.fact_ids}
        if not given:
            return self._cheapest(atoms, cost)
        best = self._cheapest(atoms, ChainMap(dict.fromkeys(given, 0.0), cost))
        return None if best is None else [f for f in best if f not in given]

    def _cheapest(self, atoms: list[Atom], cost: Mapping[int, float]) -> list[int] | None:
        """The reachable ground facts for one goal's atoms under the binding of its
        parameters and variables with the least hadd sum (``None``: none reachable).
        At most :data:`MAX_BINDINGS` bindings are compared."""
        ids = self.fact_ids
        best: list[int] | None = None
        best_sum = math.inf
        for number, binding in enumerate(self.index.bindings(atoms, [], reached=(ids, cost))):
            facts = [ids[_bind(atom, binding)] for atom in atoms]
            total = sum(cost[f] for f in facts)
            if total < best_sum:
                best, best_sum = facts, total
            if number + 1 >= MAX_BINDINGS or best_sum == 0:
                break
        return best

    def _hadd(self, model: WorldModel) -> tuple[dict[int, float], dict[int, int]]:
        """hadd costs of the reachable facts, and each fact's cheapest achiever."""
        ids = self.fact_ids
        cost: dict[int, float] = {}
        queue: list[tuple[float, int]] = []
        for atom in model.facts():
            number = ids.get(atom)
            if number is not None and number not in cost:
                cost[number] = 0.0
                queue.append((0.0, number))
        supporter: dict[int, int] = {}
        missing = [len(pre) for pre in self.preconditions]
        spent = [0.0] * len(self.preconditions)
        for op, pre in enumerate(self.preconditions):
            if not pre:
                self._achieve(op, 1.0, cost, supporter, queue)
        done: set[int] = set()
        while queue:
            value, fact = heapq.heappop(queue)
            if fact in done or value > cost[fact]:
                continue
            done.add(fact)
            for op in self.needed_by[fact]:
                missing[op] -= 1
                spent[op] += value
                if missing[op] == 0:
                    self._achieve(op, spent[op] + 1.0, cost, supporter, queue)
        return cost, supporter

    def _achieve(
        self,
        op: int,
        value: float,
        cost: dict[int, float],
        supporter: dict[int, int],
        queue: list[tuple[float, int]],
    ) -> None:
        for fact in self.adds[op]:
            if value < cost.get(fact, math.inf):
                cost[fact] = value
                supporter[fact] = op
                heapq.heappush(queue, (value, fact))

    def _relaxed_plan(self, goals: list[int], supporter: dict[int, int]) -> set[int]:
        plan: set[int] = set()
        stack, seen = list(goals), set(goals)
        while stack:
            op = supporter.get(stack.pop())
            if op is None or op in plan:
                continue  # a fact of the model, or an achiever already in the plan
            plan.add(op)
            for fact in self.preconditions[op]:
                if fact not in seen:
                    seen.add(fact)
                    stack.append(fact)
        return plan


class _Atoms(dict):
    """The lifted relaxation's "fact numbers": every atom stands for itself."""

    def __missing__(self, atom: Atom) -> Atom:
        return atom

    def __contains__(self, atom: object) -> bool:
        return True


class _LiftedRelaxedTask(_RelaxedTask):
    """The same relaxation and estimates as :class:`_RelaxedTask`, explored per model by
    the lifted heuristics' semi-naive Dijkstra (:mod:`strips_evaluators.lifted`) instead
    of grounded up front: facts are the atoms themselves, and each model's reached facts
    are indexed for its goals' bindings."""

    def __init__(self, operators: Sequence[OperatorSchema], initial: InitialModel) -> None:
        from strips_evaluators.lifted.exploration import Exploration
        from strips_evaluators.lifted.schemata import SchemaProgram

        super().__init__()
        self.free = _concluded_by_axioms(initial) | _added_unbound(operators)
        self.fact_ids = _Atoms()
        described = [
            (schema.name, _positive_atoms(schema.precondition),
             _constraints(schema.precondition), list(schema.add_list))
            for schema in operators
        ]  # fmt: skip
        facts = sorted((atom for atom in initial.facts if is_ground(atom)), key=repr)
        self.program = SchemaProgram(described, facts)
        self.exploration = Exploration(self.program)

    def _of_model(self, model: WorldModel) -> _ModelCosts:
        known = super()._of_model(model)
        self.index = known.index  # type: ignore[assignment]
        return known

    def _hadd(self, model: WorldModel) -> tuple[dict, dict, _FactIndex]:  # type: ignore[override]
        # Static facts too: they cost 0, and goals bind to them.
        state = {atom for atom in model.facts() if is_ground(atom)}
        cost, supporter = self.exploration.costs(state, additive=True, until=())
        return cost, supporter, _FactIndex(sorted(cost, key=repr))

    def _relaxed_plan(self, goals: list, supporter: dict) -> set:  # type: ignore[override]
        from strips_evaluators.lifted.exploration import relaxed_plan

        # The goals come from reached facts, so every one counts as reached (fact_ids).
        return set(relaxed_plan(self.program, self.fact_ids, supporter, goals)[1])


class _FactIndex:
    """Ground facts by predicate and by (predicate, position, constant), for the joins."""

    def __init__(self, facts: Sequence[Atom]) -> None:
        self.facts: set[Atom] = set()
        self._by_key: dict[tuple, list[Atom]] = defaultdict(list)
        for atom in facts:
            self.add(atom)

    def add(self, atom: Atom) -> None:
        self.facts.add(atom)
        self._by_key[(atom[0], len(atom))].append(atom)
        for position, arg in enumerate(atom[1:], start=1):
            self._by_key[(atom[0], len(atom), position, arg)].append(atom)

    def bindings(
        self,
        atoms: list[Atom],
        constraints: list[tuple[bool, Atom]],
        binding: Binding | None = None,
        reached: tuple[dict[Atom, int], Mapping[int, float]] | None = None,
    ) -> Iterator[Binding]:
        """Every binding of the atoms' parameters and variables to facts, most bound atom
        first; with ``reached`` (fact numbers and costs), to reached facts only."""
        binding = {} if binding is None else binding
        if not atoms:
            if all(_holds(c, binding) for c in constraints):
                yield dict(binding)
            return
        rest = list(atoms)
        atom = max(rest, key=lambda a: sum(not _open(t) or t in binding for t in a[1:]))
        rest.remove(atom)
        for fact in self._candidates(atom, binding):
            if reached is not None and reached[0][fact] not in reached[1]:
                continue
            extended = _extend(atom, fact, binding)
            if extended is not None:
                yield from self.bindings(rest, constraints, extended, reached)

    def _candidates(self, atom: Atom, binding: Binding) -> list[Atom]:
        best = self._by_key.get((atom[0], len(atom)), [])
        for position, term in enumerate(atom[1:], start=1):
            value = binding.get(term, term) if _open(term) else term
            if not _open(value):
                bucket = self._by_key.get((atom[0], len(atom), position, value), [])
                if len(bucket) < len(best):
                    best = bucket
        return list(best)


def _extend(atom: Atom, fact: Atom, binding: Binding) -> Binding | None:
    extended = dict(binding)
    for term, value in zip(atom[1:], fact[1:]):
        if _open(term):
            if extended.setdefault(term, value) != value:
                return None
        elif term != value:
            return None
    return extended


def _positive_atoms(formula: Formula) -> list[Atom]:
    """The precondition's positive atoms other than equalities: what grounding joins."""
    return [
        part.atom
        for part in conjuncts(formula)
        if isinstance(part, Atomic) and part.atom[0] != EQUALITY
    ]


def _constraints(formula: Formula) -> list[tuple[bool, Atom]]:
    """The precondition's (in)equalities, checked on a complete binding."""
    found = []
    for part in conjuncts(formula):
        if isinstance(part, Atomic) and part.atom[0] == EQUALITY:
            found.append((True, part.atom))
        elif isinstance(part, Not) and isinstance(part.body, Atomic) and part.body.atom[0] == EQUALITY:
            found.append((False, part.body.atom))
    return found


def _holds(constraint: tuple[bool, Atom], binding: Binding) -> bool:
    equal, (_, left, right) = constraint
    left, right = binding.get(left, left), binding.get(right, right)
    if _open(left) or _open(right):
        return True  # an effect-only parameter: the relaxation does not decide it
    return (left == right) == equal


def _open(term: object) -> bool:
    """A parameter, or a variable of a formula or a clause: what a binding gives a value."""
    return isinstance(term, (Param, Var)) or type(term) is int


def _bind(atom: Atom, binding: Binding) -> Atom:
    return (atom[0], *(binding.get(t, t) if _open(t) else t for t in atom[1:]))


def _concluded_by_axioms(initial: InitialModel) -> set[tuple[str, int]]:
    """Predicates a non-unit clause of M0 concludes, or a derived fact (one resting on
    supports) holds: their atoms are derived, not added."""
    return {
        (atom[0], len(atom))
        for number, clause in enumerate(initial.clauses)
        if not clause.is_unit or number in initial.supports
        for positive, atom in clause.literals
        if positive
    }


def _added_unbound(operators: Sequence[OperatorSchema]) -> set[tuple[str, int]]:
    """Predicates some schema adds with a parameter its precondition does not bind."""
    return {
        (atom[0], len(atom))
        for schema in operators
        for atom in schema.add_list
        if any(isinstance(t, Param) and t not in schema.precondition_params for t in atom[1:])
    }


def _asserted_atoms(formula: Formula) -> Iterator[Atom]:
    """The atoms a goal asserts: its positive conjuncts, inside existentials too (their
    variables match any constant). Negations and disjunctions are dropped (relaxed)."""
    for part in conjuncts(formula):
        if isinstance(part, Atomic):
            yield part.atom
        elif isinstance(part, Exists):
            yield from _asserted_atoms(part.body)


def _goal_atoms(
    node: Node, free: set[tuple[str, int]]
) -> Iterator[tuple[list[Atom], frozenset[Atom]]]:
    """Per goal on the list, its atoms that need a relaxed plan (not free, no equality),
    and the ground atoms the operators of earlier goals add (applied before this goal is
    needed). An add atom with an unbound parameter provides nothing: which atom it adds
    is decided by its precondition's proof, not yet made."""
    provided: set[Atom] = set()
    for goal in node.goals:
        yield [
            atom
            for atom in _asserted_atoms(goal.formula)
            if atom[0] != EQUALITY and (atom[0], len(atom)) not in free
        ], frozenset(provided)
        if goal.operator is not None:
            provided.update(atom for atom in goal.operator.effects()[1] if is_ground(atom))
