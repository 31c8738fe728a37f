"""The pluggable parts of lifted search, as the lifted strategies see them.

A lifted state is the set of ground atoms of the task's *fluent* predicates that hold in
it; atoms of static predicates (those no action effect mentions) never change, so they
live once in the task's initial state instead of in every state. Ground atoms are plain
tuples ``(predicate, object, ...)``: they hash fast and need no interning to compare.

A lifted heuristic is bound once per task (``for_task``) and then called for every state;
it must not ground the whole task in ``for_task`` (that is what lifted search avoids), but
may precompute anything linear in the size of the lifted task. Its estimator has
``estimate`` and ``estimate_with_preferred`` (:class:`LiftedEstimator`); one whose
heuristic builds a relaxed plan may also have ``estimate_with_guidance``
(:class:`GuidingEstimator`: the plan's useful atoms besides its preferred instances),
which a search reaches through :func:`with_guidance`, so any estimator works with it.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from collections.abc import Set as AbstractSet
from typing import TYPE_CHECKING, ClassVar, Protocol

from strips_framework.records import Record

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


class Guidance(Record):
    """What a relaxed plan for one state tells a search besides its estimate.

    ``preferred``: action instances applicable in the state that the plan uses (as
    :meth:`LiftedEstimator.estimate_with_preferred` gives them). ``useful``: the atoms
    of the state's predicates that the relaxed plan achieves, i.e. the subgoals it found
    a supporter for (none of them holds in the state; derived and auxiliary atoms are
    left out, as no successor holds those). A successor that gains one of them is
    progress by the plan's lights whichever action instance made it (Powerlifted's
    *useful atoms*); ``lifted-alt-bfws`` takes the useful atoms of the initial state's
    plan as the atoms worth counting, and (with ``useful_atoms = true``) a child that
    gains a useful atom of its parent's plan as a preferred one. ``useful`` is empty for
    a dead end and for a heuristic that computes no relaxed plan."""

    value: float
    preferred: tuple[ActionInstance, ...]
    useful: frozenset[GroundAtom]

    __slots__ = ("value", "preferred", "useful")

    def __init__(
        self,
        value: float,
        preferred: Sequence[ActionInstance] = (),
        useful: frozenset[GroundAtom] = frozenset(),
    ) -> None:
        self.value = value
        self.preferred = tuple(preferred)
        self.useful = useful


class GuidingEstimator(LiftedEstimator, Protocol):
    """An estimator whose heuristic builds a relaxed plan and says what it achieves."""

    def estimate_with_guidance(self, state: LiftedState) -> Guidance:
        """The estimate of ``state`` with its preferred instances and useful atoms."""
        ...


def with_guidance(estimator: LiftedEstimator) -> Callable[[LiftedState], Guidance]:
    """``estimator.estimate_with_guidance``, or, for an estimator without that optional
    method (goal count, hadd, hmax, a third party's), a :class:`Guidance` with its
    estimate and preferred instances and no useful atoms: a search asking for them then
    counts no relevant atoms and prefers the children of preferred instances only."""
    method = getattr(estimator, "estimate_with_guidance", None)
    if method is not None:
        return method
    evaluate = estimator.estimate_with_preferred

    def without_useful_atoms(state: LiftedState) -> Guidance:
        value, preferred = evaluate(state)
        return Guidance(value, preferred)

    return without_useful_atoms


class LiftedHeuristic(Protocol):
    name: ClassVar[str]
    #: True when the estimate never exceeds the cost of an optimal plan from the state.
    admissible: ClassVar[bool]

    def for_task(self, task: PddlTask) -> LiftedEstimator:
        """Precompute what the heuristic needs for ``task``, without grounding it."""
        ...
