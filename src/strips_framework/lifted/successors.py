"""Successors, goal test and derived predicates of lifted states, found by the query
engine: the applicable instances of an action are the answers of its precondition's
queries, never an enumeration of its instances.

A state's :class:`~strips_framework.lifted.query.FactBase` holds its fluent atoms and the
derived atoms its axioms give (evaluated stratum by stratum to a fixpoint, each rule's
body a query, the way a Datalog engine evaluates a stratified program); the task's static
atoms sit under it once for the whole search.
"""

from __future__ import annotations

from collections.abc import Iterator

from strips_framework.lifted.components import ActionInstance, GroundAtom, LiftedState
from strips_framework.lifted.query import FactBase, JoinEngine, QueryEngine
from strips_framework.lifted.task import ActionSchema, LiftedTask, Rule
from strips_framework.pddl.formulas import Atom


def instantiate(atom: Atom, binding: dict[str, str]) -> GroundAtom:
    return (atom.predicate, *[binding.get(arg, arg) for arg in atom.args])


class Successors:
    """The lifted task's states as the search sees them, through one query engine."""

    def __init__(self, task: LiftedTask, engine: QueryEngine | None = None) -> None:
        self.task = task
        self.engine = engine if engine is not None else JoinEngine(task.objects)
        self.static = FactBase(task.static_atoms)
        self.schemas = {schema.name: schema for schema in task.actions}
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
        schema = self.schemas[instance[0]]
        if schema.effects and facts is None:
            facts = self.facts(state)
        binding = dict(zip(schema.params, instance[1]))
        delete = {instantiate(atom, binding) for atom in schema.delete}
        add = {instantiate(atom, binding) for atom in schema.add}
        for effect in schema.effects:
            for extra in self._effect_bindings(effect.params, effect.condition, binding, facts):
                delete.update(instantiate(atom, extra) for atom in effect.delete)
                add.update(instantiate(atom, extra) for atom in effect.add)
        removed = {atom for atom in delete if atom in state and atom not in add}
        added = {atom for atom in add if atom not in state}
        return removed, added, self.task.cost(schema, binding)

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
