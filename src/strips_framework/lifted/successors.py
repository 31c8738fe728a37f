"""Successors, goal test and derived predicates of lifted states, found by the query
engine: the applicable instances of an action are the answers of its precondition's
queries, never an enumeration of its instances.

A state's :class:`~strips_framework.lifted.query.FactBase` holds its fluent atoms and the
derived atoms its axioms give (evaluated stratum by stratum to a fixpoint, each rule's
body a query, the way a Datalog engine evaluates a stratified program); the task's static
atoms sit under it once for the whole search.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from operator import itemgetter

from strips_framework.lifted.components import ActionInstance, GroundAtom, LiftedState
from strips_framework.lifted.query import FactBase, JoinEngine, QueryEngine
from strips_framework.lifted.task import ActionSchema, LiftedTask, Rule
from strips_framework.pddl.formulas import Atom


def instantiate(atom: Atom, binding: dict[str, str]) -> GroundAtom:
    return (atom.predicate, *[binding.get(arg, arg) for arg in atom.args])


#: Makes a ground atom from an action instance's arguments (see :func:`maker`).
Maker = Callable[[tuple[str, ...]], GroundAtom]


def maker(atom: Atom, params: tuple[str, ...]) -> Maker:
    """``atom`` (whose terms are ``params`` or objects) instantiated by an instance's
    arguments, in parameter order: what :func:`instantiate` gives with the binding of
    ``params`` to them, without making the binding (a search makes one per successor,
    tens of thousands per state in childsnack)."""
    positions = {param: i for i, param in enumerate(params)}
    prefix: GroundAtom = (atom.predicate,)
    if not atom.args:
        return lambda args: prefix
    if all(arg in positions for arg in atom.args):
        indexes = [positions[arg] for arg in atom.args]
        if len(indexes) == 1:
            index = indexes[0]
            return lambda args: (*prefix, args[index])
        getter = itemgetter(*indexes)
        return lambda args: prefix + getter(args)
    terms = [(positions.get(arg, -1), arg) for arg in atom.args]
    return lambda args: (*prefix, *[args[i] if i >= 0 else arg for i, arg in terms])


class Successors:
    """The lifted task's states as the search sees them, through one query engine."""

    def __init__(self, task: LiftedTask, engine: QueryEngine | None = None) -> None:
        self.task = task
        self.engine = engine if engine is not None else JoinEngine(task.objects)
        self.static = FactBase(task.static_atoms)
        self.schemas = {schema.name: schema for schema in task.actions}
        #: Per action, the makers of its unconditional deletes and adds.
        self._effects: dict[str, tuple[tuple[Maker, ...], tuple[Maker, ...]]] = {
            schema.name: (
                tuple(maker(atom, schema.params) for atom in schema.delete),
                tuple(maker(atom, schema.params) for atom in schema.add),
            )
            for schema in task.actions
        }
        #: The cost of every instance of an action whose cost is not a function term.
        self._costs = {
            schema.name: task.cost(schema, {})
            for schema in task.actions
            if not task.uses_costs or isinstance(schema.cost, int)
        }
        strata: dict[int, list[Rule]] = {}
        for rule in task.rules:
            strata.setdefault(rule.stratum, []).append(rule)
        self._strata = [strata[level] for level in sorted(strata)]

    def facts(self, state: LiftedState) -> FactBase:
        """The fact base of ``state``, its derived atoms included."""
        facts = FactBase(state, self.static, self.task.static)
        for rules in self._strata:
            self._saturate(rules, facts)
        return facts

    def facts_after(
        self, state: LiftedState, parent: FactBase, removed: set[GroundAtom], added: set[GroundAtom]
    ) -> FactBase:
        """The fact base of ``state``, which the state of fact base ``parent`` becomes by
        losing ``removed`` and gaining ``added`` (:meth:`change`): made from the parent's
        at the changed atoms only, or from scratch when the task has axioms (their derived
        atoms would have to be derived again)."""
        if self._strata:
            return self.facts(state)
        return parent.changed(state, removed, added)

    def _saturate(self, rules: list[Rule], facts: FactBase) -> None:
        """Fire ``rules`` until they give no new atom (naive evaluation: a stratum of a
        planning domain's axioms is small, and most reach their fixpoint in two rounds)."""
        answers = self.engine.answers
        while True:
            new: list[GroundAtom] = []
            for rule in rules:
                head = rule.head
                variables = rule.body.variables
                for row in answers(rule.body, facts):
                    new.append(instantiate(head, dict(zip(variables, row))))
            if not facts.add(new):
                return

    def is_goal(self, facts: FactBase) -> bool:
        answers = self.engine.answers
        return any(answers(query, facts) for query in self.task.goal)

    def applicable(self, facts: FactBase) -> list[ActionInstance]:
        """The instances of every action whose precondition holds, in the order of the
        domain's actions."""
        answers = self.engine.answers
        found: list[ActionInstance] = []
        for schema in self.task.actions:
            queries, name = schema.precondition, schema.name
            if len(queries) == 1:
                found += [(name, args) for args in answers(queries[0], facts)]
            elif queries:
                every: dict[tuple[str, ...], None] = {}
                for query in queries:
                    every.update(dict.fromkeys(answers(query, facts)))
                found += [(name, args) for args in every]
        return found

    def stream(self, facts: FactBase) -> Iterator[ActionInstance]:
        """The instances :meth:`applicable` lists, in the same order, found one at a
        time (:meth:`JoinEngine.stream`): what a search that takes a state's successors
        as it needs them pays for the first few is not what all of them cost."""
        stream = self.engine.stream
        for schema in self.task.actions:
            queries, name = schema.precondition, schema.name
            if len(queries) == 1:
                for args in stream(queries[0], facts):
                    yield name, args
            elif queries:
                seen: set[tuple[str, ...]] = set()
                for query in queries:
                    for args in stream(query, facts):
                        if args not in seen:
                            seen.add(args)
                            yield name, args

    def apply(
        self, state: LiftedState, facts: FactBase | None, instance: ActionInstance
    ) -> tuple[LiftedState, int]:
        """The state after ``instance`` (applicable in ``state``, whose fact base is
        ``facts``, made here when None and needed) and the instance's cost. Every
        condition is read in ``state``; deletes apply before adds."""
        removed, added, cost = self.change(state, facts, instance)
        return (state - removed) | added, cost

    def change(
        self, state: LiftedState, facts: FactBase | None, instance: ActionInstance
    ) -> tuple[set[GroundAtom], set[GroundAtom], int]:
        """What ``instance`` changes in ``state``: the atoms it makes false and those it
        makes true (each really changing), and its cost (see :meth:`apply`)."""
        name, args = instance
        schema = self.schemas[name]
        deletes, adds = self._effects[name]
        delete = {make(args) for make in deletes}
        add = {make(args) for make in adds}
        cost = self._costs.get(name)
        if schema.effects or cost is None:
            binding = dict(zip(schema.params, args))
            if cost is None:
                cost = self.task.cost(schema, binding)
            if schema.effects and facts is None:
                facts = self.facts(state)
            for effect in schema.effects:
                for extra in self._effect_bindings(effect.params, effect.condition, binding, facts):  # type: ignore[arg-type]
                    delete.update(instantiate(atom, extra) for atom in effect.delete)
                    add.update(instantiate(atom, extra) for atom in effect.add)
        removed = delete.intersection(state).difference(add)
        added = add.difference(state)
        return removed, added, cost

    def _effect_bindings(
        self, params: tuple[str, ...], condition: tuple, binding: dict[str, str], facts: FactBase
    ) -> list[dict[str, str]]:
        found: set[tuple[str, ...]] = set()
        for query in condition:
            found.update(self.engine.answers(query, facts, binding))
        return [{**binding, **dict(zip(params, row))} for row in sorted(found)]

    def schema(self, name: str) -> ActionSchema:
        return self.schemas[name]


def step_name(instance: ActionInstance) -> str:
    """The IPC form of an action instance, ``(name arg ...)``."""
    return "(" + " ".join((instance[0], *instance[1])) + ")"
