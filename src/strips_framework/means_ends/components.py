"""The pluggable parts of a means-ends or model-A* search, as the strategies see them:
difference extraction, operator relevance, node evaluation and the strategy itself.

Each is registered by class through a hook (see :mod:`strips_framework.plugin.hookspecs`) and
instantiated once per run from the config; strategies call the methods directly. The
forward-search kinds are in :mod:`strips_framework.forward.components`.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, ClassVar, Protocol

if TYPE_CHECKING:
    from strips_framework.limits import Clock, Limits
    from strips_framework.logic.clauses import Clause
    from strips_framework.means_ends.node import Difference, Node, RelevantInstance
    from strips_framework.result import Result
    from strips_framework.worldmodel.problem import OperatorSchema, Problem
    from strips_framework.worldmodel.proving import ProofResult, TheoremProver
    from strips_framework.worldmodel.world import InitialModel, WorldModel


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
        :class:`~strips_framework.limits.LimitReached` raised anywhere inside ends
        the search with its status and the statistics so far."""
        ...
