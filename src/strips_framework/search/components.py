"""The pluggable parts of a search, as the strategies see them.

Each is registered by class through a hook (see :mod:`strips_framework.hookspecs`) and
instantiated once per run from the config; strategies call the methods directly.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, ClassVar, Protocol

if TYPE_CHECKING:
    from strips_framework.grounding.task import GroundTask
    from strips_framework.logic.clauses import Clause
    from strips_framework.problem import OperatorSchema, Problem
    from strips_framework.proving import ProofResult, TheoremProver
    from strips_framework.result import Result
    from strips_framework.search.limits import Clock, Limits
    from strips_framework.search.node import Difference, Node, RelevantInstance
    from strips_framework.world import InitialModel, WorldModel


class DifferenceExtractor(Protocol):
    name: ClassVar[str]

    def extract(self, result: ProofResult, negated_goal: Sequence[Clause]) -> Difference:
        """The difference of a failed proof attempt (its uncompleted proof, edited)."""
        ...


class RelevanceFilter(Protocol):
    name: ClassVar[str]

    def for_problem(
        self, operators: Sequence[OperatorSchema], initial: InitialModel
    ) -> ProblemRelevance:
        """Index one problem's operators and M0, once per search."""
        ...


class ProblemRelevance(Protocol):
    """A relevance filter prepared for one problem (:meth:`RelevanceFilter.for_problem`)."""

    def relevant(self, difference: Difference, model: WorldModel) -> list[RelevantInstance]:
        """Relevant operator instances for ``difference`` in ``model``, best first."""
        ...


class NodeEvaluator(Protocol):
    name: ClassVar[str]
    #: True when ``evaluate`` is a lower bound on the cost of a plan through the node.
    admissible: ClassVar[bool]

    def evaluate(self, node: Node) -> float:
        """Score ``node``; strategies expand the lowest score first."""
        ...


def evaluator_for_problem(
    evaluator: NodeEvaluator, operators: Sequence[OperatorSchema], initial: InitialModel
) -> NodeEvaluator:
    """The evaluator a strategy scores one problem's nodes with.

    Most evaluators score a node from the node alone and are used as they are. One that
    needs the problem (a relaxed plan needs its operators and M0) defines
    ``for_problem(operators, initial)``, like :meth:`RelevanceFilter.for_problem`, and the
    evaluator it returns is prepared once per search.
    """
    prepare = getattr(evaluator, "for_problem", None)
    return evaluator if prepare is None else prepare(operators, initial)


class SearchStrategy(Protocol):
    """A world-model strategy (the ``strategy`` plugin kind)."""

    name: ClassVar[str]

    def search(
        self,
        problem: Problem,
        prover: TheoremProver,
        differences: DifferenceExtractor,
        relevance: RelevanceFilter,
        evaluator: NodeEvaluator,
        limits: Limits,
        clock: Clock | None = None,
    ) -> Result:
        """Search for a plan for ``problem``; the time limit counts from the start of
        ``clock`` (the planner's, started when it began reading; default: now), and a
        :class:`~strips_framework.search.limits.LimitReached` raised anywhere inside ends
        the search with its status and the statistics so far."""
        ...


class StateEstimator(Protocol):
    """A heuristic bound to one ground task; called for every state the search meets."""

    def estimate(self, state: int) -> float:
        """The estimated cost from ``state`` to the goal; ``math.inf`` for a dead end."""
        ...

    def estimate_with_preferred(self, state: int) -> tuple[float, Sequence[int]]:
        """The estimate and the preferred operators (indices into ``task.operators``,
        applicable in ``state``); heuristics without them return an empty sequence."""
        ...


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
        time limit counts from the start of ``clock``, as for :class:`SearchStrategy`."""
        ...
