"""MACROPs inside the means-ends search (Fikes, Hart & Nilsson 1972, section 5).

Each MACROP enters the search as macro operators: the whole table and each of its edited
parts (:meth:`Macrop.parts`), as a :class:`MacroSchema` whose precondition is the part's
kernel 1 (its column-0 clauses; its :class:`Distinct` constraints are tested on bindings,
see :meth:`MacroInstance.admits`) and whose add list is its goal row. The relevance
filter of the config then finds a MACROP relevant exactly as it finds an operator: when
the add list of one of its operators (the last of an edited part) continues the
uncompleted proof. :class:`MacroRelevance` offers it in instances whose kernel holds in
the node's model (and, with ``[macrops] subgoals``, with its kernel as a subgoal); once
its precondition is proved the search applies the steps one after another: one node for
the whole sequence, all of its steps in the plan.
"""

from __future__ import annotations

import itertools
from collections.abc import Iterable, Sequence
from typing import Any, ClassVar

from strips_framework.logic.clauses import Clause
from strips_framework.logic.formulas import And, Atomic, Formula
from strips_framework.logic.terms import WILDCARD, Param, Term, is_ground
from strips_framework.logic.unify import substitute, unify
from strips_framework.macrops.kernels import instances
from strips_framework.macrops.macrop import Library
from strips_framework.macrops.table import TriangleTable
from strips_framework.means_ends.components import ProblemRelevance, RelevanceFilter
from strips_framework.means_ends.node import Difference, RelevantInstance
from strips_framework.options import Configurable, Option
from strips_framework.records import Record
from strips_framework.worldmodel.operators import OperatorInstance
from strips_framework.worldmodel.problem import OperatorSchema
from strips_framework.worldmodel.simulate import State
from strips_framework.worldmodel.world import InitialModel, WorldModel


class MacroSchema(OperatorSchema):
    """A MACROP (or an edited part of one) as an operator schema; the ``table`` is not
    compared."""

    table: TriangleTable | None

    FIELDS = (*OperatorSchema.FIELDS, "table")
    COMPARED = OperatorSchema.COMPARED
    __slots__ = ("table",)

    def __init__(self, table: TriangleTable | None = None, **schema: Any) -> None:
        super().__init__(**schema)
        self.table = table


def macro_schema(name: str, table: TriangleTable) -> MacroSchema:
    """The table as an operator: kernel 1 as precondition, the goal row as add list,
    and every step's delete patterns (which the relevance filter ranks by harm)."""
    conditions: list[Formula] = [Atomic(a) for a in table.kernel(1)]
    deletes = {
        pattern for step in table.steps for pattern in step.deletes() if pattern != WILDCARD
    }
    return MacroSchema(
        name=name,
        parameters=table.parameters(),
        precondition=And(conditions) if len(conditions) != 1 else conditions[0],
        add_list=table.goal_row(),
        delete_list=tuple(sorted(deletes, key=repr)),
        table=table,
    )


class MacroInstance(OperatorInstance):
    """An instance of a :class:`MacroSchema`: applied, it applies its table's steps."""

    __slots__ = ()

    def bind(self, more: dict[Param, Term]) -> MacroInstance:
        bound = super().bind(more)
        return MacroInstance(self.schema, bound.binding)

    def admits(self) -> bool:
        """The table's :class:`Distinct` constraints hold (they are checked here, not
        proved with the precondition: inequalities would make the prover reason with
        equality, which costs it far more than this test)."""
        table = self.schema.table
        assert table is not None
        binding = self.binding_map()
        return all(d.holds(binding) for d in table.distinct)

    def steps(self) -> tuple[OperatorInstance, ...]:
        table = self.schema.table
        assert table is not None
        binding = self.binding_map()
        result = []
        for step in table.steps:
            args = [substitute(a, binding) for a in step.arguments]
            result.append(OperatorInstance(step.schema, zip(step.schema.parameters, args)))
        return tuple(result)

    def apply(self, model: WorldModel) -> WorldModel:
        for step in self.steps():
            model = step.apply(model)
        return model

    def __str__(self) -> str:
        return f"{self.schema.name}[{', '.join(map(str, self.steps()))}]"


class MacroUse(Configurable):
    """The ``[macrops]`` table of the config: how a search uses a library.

    A MACROP found relevant is offered in the instances (at most ``instances`` of them)
    whose kernel 1 holds in the node's world model, so applying it is one proof away;
    ``effort`` bounds the attempts to match a kernel clause against a fact while looking
    for them (every node pays it for every relevant MACROP part).
    With ``subgoals`` one whose kernel does not hold is also offered, after the operators,
    with its precondition as the subgoal (the 1972 paper's full use). That costs dearly
    here: a kernel is a conjunction of many clauses, and a failed proof of it leaves a
    large difference (the five-part robot goal, which the default solves in fewer nodes
    with the robot library than without it, README, runs out of time with it; see
    docs/macrops.md).
    """

    options = (
        Option("instances", int, 3, minimum=1, doc="instances offered per relevant MACROP"),
        Option("subgoals", bool, False, doc="also offer MACROPs whose kernel does not hold"),
        Option("effort", int, 2000, minimum=1, doc="kernel-clause matches per kernel looked for"),
    )
    instances: int
    subgoals: bool
    effort: int


class MacroRelevance(Record):
    """The configured relevance filter, asked about the operators and the library's
    macro operators together. The inner filter's order is kept (closest to a proof,
    least harm first), except that among instances that leave equally much of the proof,
    MACROPs that apply now come before operators, and MACROPs that need subgoals after."""

    name: ClassVar[str] = "macrops"
    inner: RelevanceFilter
    schemas: tuple[MacroSchema, ...]
    use: MacroUse

    __slots__ = ("inner", "schemas", "use")

    def __init__(
        self, inner: RelevanceFilter, schemas: Iterable[MacroSchema], use: MacroUse | None = None
    ) -> None:
        self.inner = inner
        self.schemas = tuple(schemas)
        self.use = MacroUse() if use is None else use

    @classmethod
    def of(cls, inner: RelevanceFilter, library: Library, use: MacroUse | None = None) -> MacroRelevance:
        schemas = [macro_schema(name, table) for m in library.macrops for name, table in m.parts()]
        return cls(inner, schemas, use or MacroUse())

    def for_problem(
        self, operators: Sequence[OperatorSchema], initial: InitialModel
    ) -> PreparedMacroRelevance:
        """The inner filter prepared for the operators and the macro operators together."""
        return PreparedMacroRelevance(self, self.inner.for_problem([*operators, *self.schemas], initial))


class PreparedMacroRelevance(Record):
    """:class:`MacroRelevance` for one problem."""

    macros: MacroRelevance
    inner: ProblemRelevance

    __slots__ = ("macros", "inner")

    def __init__(self, macros: MacroRelevance, inner: ProblemRelevance) -> None:
        self.macros = macros
        self.inner = inner

    def relevant(self, difference: Difference, model: WorldModel) -> list[RelevantInstance]:
        use = self.macros.use
        found = self.inner.relevant(difference, model)
        facts: State | None = None
        ranked: list[tuple[tuple[int, int, int], RelevantInstance]] = []
        for rank, item in enumerate(found):
            schema = item.operator.schema
            if not isinstance(schema, MacroSchema):
                ranked.append(((len(item.resolvent.literals), 1, rank), item))
                continue
            assert schema.table is not None
            if facts is None:
                facts = frozenset(model.facts())
            partial, resolvent = _cover(schema, item.operator.binding_map(), item.resolvent)
            size = len(resolvent.literals)
            found_here = instances(schema.table, 1, facts, (), partial, use.effort)
            held = itertools.islice(found_here, use.instances)
            offered = False
            for binding in held:
                offered = True
                macro = MacroInstance(schema, [(p, binding[p]) for p in schema.parameters])
                ranked.append(((size, 0, rank), RelevantInstance(macro, resolvent)))
            if not offered and use.subgoals:
                macro = MacroInstance(schema, partial.items())
                if macro.admits():
                    ranked.append(((size, 2, rank), RelevantInstance(macro, resolvent)))
        return [item for _, item in sorted(ranked, key=lambda pair: pair[0])]


def _cover(
    schema: MacroSchema, binding: dict[Param, Term], resolvent: Clause
) -> tuple[dict[Param, Term], Clause]:
    """Bind more of the MACROP's parameters so that its goal row resolves away further
    literals of the difference clause (a MACROP is worth most where it achieves several
    conjuncts of a goal at once): greedily, literal by literal, the first goal-row atom
    that unifies without breaking a Distinct constraint. The binding and what is left."""
    assert schema.table is not None
    current = dict(binding)
    rest = []
    for literal in resolvent.literals:
        positive, target = literal
        extended = None if positive else _resolving(schema, current, target)
        if extended is None:
            rest.append(literal)
        else:
            current = extended
    return current, Clause(rest, resolvent.bindings, label=resolvent.label)


def _resolving(schema: MacroSchema, binding: dict[Param, Term], target: Term) -> dict | None:
    for atom in schema.add_list:
        unifier = unify(substitute(atom, binding), target, {})
        if unifier is None or any(type(k) is not Param or not is_ground(v)
                                  for k, v in unifier.items()):
            continue
        extended = {**binding, **unifier}
        if all(d.holds(extended) for d in schema.table.distinct):
            return extended
    return None
