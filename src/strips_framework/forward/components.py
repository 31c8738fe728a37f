"""The pluggable parts of forward search, as the strategies see them: a state heuristic,
bound once per task to a state estimator, and the ground-task strategy itself.

Each is registered by class through a hook (see :mod:`strips_framework.plugin.hookspecs`) and
instantiated once per run from the config. The world-model kinds are in
:mod:`strips_framework.means_ends.components`.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, ClassVar, Protocol

if TYPE_CHECKING:
    from strips_framework.grounding.task import GroundTask
    from strips_framework.limits import Clock, Limits
    from strips_framework.result import Result


class StateEstimator(Protocol):
    """A heuristic bound to one ground task; called for every state the search meets.

    ``estimate`` is all an estimator must have. One that proposes preferred operators
    also has ``estimate_with_preferred`` (:class:`PreferredEstimator`); the searches
    reach it through :func:`with_preferred`, which gives an estimator without it none.

    A state is an int bitset. An estimator whose class sets ``reads_packed = True``
    also takes a state as its packing (bytes: the sorted numbers of its true facts,
    :mod:`~strips_framework.forward.packing`), which lazy search in a packed state space
    then passes as it is instead of making the bitset, whose length is the task's
    facts (:func:`reads_packed`)."""

    def estimate(self, state: int) -> float:
        """The estimated cost from ``state`` to the goal; ``math.inf`` for a dead end."""
        ...


def reads_packed(estimator: StateEstimator) -> bool:
    """Whether ``estimator`` takes states as packings too (see :class:`StateEstimator`)."""
    return bool(getattr(type(estimator), "reads_packed", False))


class PreferredEstimator(StateEstimator, Protocol):
    """An estimator that also proposes preferred operators."""

    def estimate_with_preferred(self, state: int) -> tuple[float, Sequence[int]]:
        """The estimate and the preferred operators (indices into ``task.operators``,
        applicable in ``state``)."""
        ...


def with_preferred(estimator: StateEstimator) -> Callable[[int], tuple[float, Sequence[int]]]:
    """``estimator.estimate_with_preferred``, or, for an estimator without that optional
    method, its ``estimate`` with no preferred operators."""
    method = getattr(estimator, "estimate_with_preferred", None)
    if method is not None:
        return method
    estimate = estimator.estimate

    def without_preferred(state: int) -> tuple[float, Sequence[int]]:
        return estimate(state), ()

    return without_preferred


class StateHeuristic(Protocol):
    name: ClassVar[str]
    #: True when the estimate never exceeds the cost of an optimal plan from the state.
    admissible: ClassVar[bool]

    def for_task(self, task: GroundTask) -> StateEstimator:
        """Precompute what the heuristic needs for ``task``."""
        ...


class GroundTaskStrategy(Protocol):
    """A strategy over ground tasks (the ``ground-strategy`` plugin kind): forward search
    over the states of a task grounded from PDDL input."""

    name: ClassVar[str]
    #: True when running out of states proves the task unsolvable.
    complete: ClassVar[bool]

    def search_task(
        self,
        task: GroundTask,
        estimator: StateEstimator,
        limits: Limits,
        clock: Clock | None = None,
    ) -> Result:
        """Search ``task`` with ``estimator`` (the configured heuristic bound to it); the
        time limit counts from the start of ``clock``, as for
        :class:`~strips_framework.means_ends.components.SearchStrategy`."""
        ...
