"""The growing search tree: node numbering, limits, and the final statistics."""

from __future__ import annotations

import time

from attrs import define, field

from strips_framework.operators import OperatorInstance
from strips_framework.search.goal_prover import GoalProver
from strips_framework.search.limits import Limits
from strips_framework.search.node import Goal, Node, path_to
from strips_framework.search.result import NODE_LIMIT, TIME_LIMIT, SearchResult, Statistics
from strips_framework.world import WorldModel


class LimitReached(Exception):
    """Raised inside a search when a limit of the config runs out; carries the status."""

    def __init__(self, status: str) -> None:
        super().__init__(status)
        self.status = status


@define
class SearchTree:
    limits: Limits
    prover: GoalProver
    nodes: list[Node] = field(factory=list)
    started: float = field(factory=time.perf_counter)

    def check_time(self) -> None:
        if time.perf_counter() - self.started > self.limits.time:
            raise LimitReached(TIME_LIMIT)

    def new_node(
        self,
        model: WorldModel,
        goals: tuple[Goal, ...],
        parent: Node | None,
        plan: tuple[OperatorInstance, ...],
        applied: OperatorInstance | None = None,
    ) -> Node:
        if len(self.nodes) >= self.limits.nodes:
            raise LimitReached(NODE_LIMIT)
        self.check_time()
        node = Node(len(self.nodes), model, goals, parent, plan, applied)
        self.nodes.append(node)
        return node

    def result(self, status: str, solution: Node | None) -> SearchResult:
        path = path_to(solution)
        statistics = Statistics(
            nodes=len(self.nodes),
            applications=sum(1 for n in self.nodes if n.applied is not None),
            path_nodes=len(path),
            path_applications=sum(1 for n in path if n.applied is not None),
            seconds=time.perf_counter() - self.started,
            proving_seconds=self.prover.seconds,
            proof_attempts=self.prover.attempts,
        )
        plan = solution.plan if solution is not None else None
        return SearchResult(status, plan, statistics, tuple(self.nodes), solution)
