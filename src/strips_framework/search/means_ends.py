"""The STRIPS strategy: GPS-style means-ends analysis over (world model, goal list) nodes.

As in the paper (II.B, III.C, Figure 2): when a node is made, its first goal is tried by
the prover. If it is proved, the operator whose precondition it was is applied with the
bindings the proof found, which makes a new node (its first goal is tried at once, and so
on). If not, the uncompleted proof becomes the node's difference and the relevant operator
instances for it are computed. The evaluator then picks which node gets its next successor:
the precondition of its next relevant instance pushed onto its goal list. Successors are
made one at a time, so a node stays in the queue while it has relevant instances left.
"""

from __future__ import annotations

import heapq
from typing import ClassVar

from attrs import field, frozen, validators

from strips_framework.capabilities import ANSWERS, Requirement
from strips_framework.hookspecs import hookimpl
from strips_framework.operators import OperatorInstance
from strips_framework.problem import Problem
from strips_framework.proving import ProofResult, TheoremProver
from strips_framework.search.components import (
    DifferenceExtractor,
    NodeEvaluator,
    RelevanceFilter,
)
from strips_framework.search.goal_prover import GoalProver
from strips_framework.search.limits import Limits
from strips_framework.search.node import Goal, Node
from strips_framework.search.result import EXHAUSTED, SOLVED, SearchResult
from strips_framework.search.tree import LimitReached, SearchTree
from strips_framework.world import WorldModel


@frozen
class MeansEndsSearch:
    """Means-ends analysis as STRIPS does it.

    ``max_goals`` bounds the goal list (the depth of subgoaling), which keeps the search
    from regressing forever through ever deeper preconditions.
    """

    name: ClassVar[str] = "means-ends"
    capabilities: ClassVar[frozenset[str]] = frozenset()
    requires: ClassVar[tuple[Requirement, ...]] = (
        Requirement("prover", ANSWERS, "it applies each operator with the parameter "
                    "bindings of its precondition's proof"),
    )
    max_goals: int = field(default=8, validator=[validators.instance_of(int), validators.gt(0)])

    def search(
        self,
        problem: Problem,
        prover: TheoremProver,
        differences: DifferenceExtractor,
        relevance: RelevanceFilter,
        evaluator: NodeEvaluator,
        limits: Limits,
    ) -> SearchResult:
        run = _Run(self, problem, GoalProver(problem, prover, limits.effort), differences,
                   relevance, evaluator, limits)
        return run.search()


class _Run:
    """The state of one means-ends search."""

    def __init__(
        self,
        strategy: MeansEndsSearch,
        problem: Problem,
        goal_prover: GoalProver,
        differences: DifferenceExtractor,
        relevance: RelevanceFilter,
        evaluator: NodeEvaluator,
        limits: Limits,
    ) -> None:
        self.max_goals = strategy.max_goals
        self.operators = problem.operators
        self.goal_prover = goal_prover
        self.differences = differences
        self.relevance = relevance
        self.evaluator = evaluator
        self.tree = SearchTree(limits, goal_prover)
        self.queue: list[tuple[float, int, Node]] = []
        self.pushes = 0
        self.seen: set[tuple[WorldModel, tuple[Goal, ...]]] = set()
        self.top_goal = Goal(problem.goal)

    def search(self) -> SearchResult:
        try:
            solution = self._make(self.goal_prover.root_model(), (self.top_goal,), None, ())
            while solution is None and self.queue:
                self.tree.check_time()
                _, _, node = heapq.heappop(self.queue)
                solution = self._expand(node)
        except LimitReached as limit:
            return self.tree.result(limit.status, None)
        return self.tree.result(SOLVED if solution else EXHAUSTED, solution)

    def _push(self, node: Node) -> None:
        self.pushes += 1
        heapq.heappush(self.queue, (self.evaluator.evaluate(node), self.pushes, node))

    def _expand(self, node: Node) -> Node | None:
        """Make the successor of ``node`` for its next relevant instance."""
        instance = node.pending.pop(0)
        node.successors_generated += 1
        if node.pending:
            self._push(node)
        subgoal = Goal(instance.operator.precondition(), instance.operator)
        return self._make(node.model, (subgoal, *node.goals), node, node.plan)

    def _make(
        self,
        model: WorldModel,
        goals: tuple[Goal, ...],
        parent: Node | None,
        plan: tuple[OperatorInstance, ...],
        applied: OperatorInstance | None = None,
    ) -> Node | None:
        """Make a node and try its first goal; return the goal node if the task is solved.

        Proved preconditions are applied in a loop rather than by recursion, since a chain
        of applications can be as long as the goal list.
        """
        while True:
            node = self.tree.new_node(model, goals, parent, plan, applied)
            if (model, goals) in self.seen:
                return None  # the same problem is already being worked on elsewhere
            self.seen.add((model, goals))
            first = goals[0]
            result = self.goal_prover.prove(model, first.formula)
            if not result.proved:
                self._set_difference(node, result)
                return None
            if first.operator is None:
                return node
            operator = first.operator.bind(dict(result.answers[0]))
            if not operator.is_ground:
                return None  # the proof left a parameter of the effects unbound
            model, goals, parent = operator.apply(model), goals[1:], node
            plan, applied = (*plan, operator), operator

    def _set_difference(self, node: Node, result: ProofResult) -> None:
        negated = self.goal_prover.negated(node.goals[0].formula)
        node.difference = self.differences.extract(result, negated)
        if len(node.goals) >= self.max_goals:
            return
        on_goal_list = {goal.operator for goal in node.goals}
        node.pending = [
            found
            for found in self.relevance.relevant(node.difference, self.operators, node.model)
            if found.operator not in on_goal_list
        ]
        if node.pending:
            self._push(node)


@hookimpl
def strips_register_strategies() -> list[type]:
    return [MeansEndsSearch]
