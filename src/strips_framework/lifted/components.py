"""The pluggable parts of lifted search, as the lifted strategies see them.

A lifted state is the set of ground atoms of the task's *fluent* predicates that hold in
it; atoms of static predicates (those no action effect mentions) never change, so they
live once in the task's initial state instead of in every state. Ground atoms are plain
tuples ``(predicate, object, ...)``: they hash fast and need no interning to compare.

A lifted heuristic is bound once per task (``for_task``) and then called for every state;
it must not ground the whole task in ``for_task`` (that is what lifted search avoids), but
may precompute anything linear in the size of the lifted task.
"""

from __future__ import annotations

from collections.abc import Sequence
from collections.abc import Set as AbstractSet
from typing import TYPE_CHECKING, ClassVar, Protocol

if TYPE_CHECKING:
    from strips_framework.pddl.task import PddlTask

#: ``(predicate, object, ...)``.
GroundAtom = tuple[str, ...]
#: The fluent atoms that hold in a state (see the module docstring): a frozenset, or
#: for a large state a read-only set that shares most of its atoms with its relatives
#: (:class:`~strips_framework.lifted.delta.DeltaState`). Heuristics test membership,
#: iterate and take its length.
LiftedState = AbstractSet[GroundAtom]
#: An action instance: the action's name and its arguments, in parameter order.
ActionInstance = tuple[str, tuple[str, ...]]


def static_predicates(task: PddlTask) -> frozenset[str]:
    """The predicates no action effect (conditional ones included) adds or deletes; their
    atoms are the same in every state. Derived predicates are not static: their values
    follow the state's."""
    changed = {atom.predicate for action in task.domain.actions for atom in action.changed_atoms()}
    derived = {rule.head.predicate for rule in task.domain.derived}
    declared = {predicate.name for predicate in task.domain.predicates}
    return frozenset(declared - changed - derived)


class LiftedEstimator(Protocol):
    """A lifted heuristic bound to one task; called for every state the search meets."""

    def estimate(self, state: LiftedState) -> float:
        """The estimated cost from ``state`` to the goal; ``math.inf`` for a dead end."""
        ...

    def estimate_with_preferred(
        self, state: LiftedState
    ) -> tuple[float, Sequence[ActionInstance]]:
        """The estimate and the preferred action instances (applicable in ``state``);
        heuristics without preferred operators return an empty sequence."""
        ...


class LiftedHeuristic(Protocol):
    name: ClassVar[str]
    #: True when the estimate never exceeds the cost of an optimal plan from the state.
    admissible: ClassVar[bool]

    def for_task(self, task: PddlTask) -> LiftedEstimator:
        """Precompute what the heuristic needs for ``task``, without grounding it."""
        ...
