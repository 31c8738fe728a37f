"""The growing search tree: node numbering, limits, and the final result."""

from __future__ import annotations

from strips_framework.limits import Clock, LimitReached, Limits
from strips_framework.means_ends.goal_prover import GoalProver
from strips_framework.means_ends.node import Goal, Node, path_to
from strips_framework.means_ends.result import Tree, WorldModelStatistics
from strips_framework.result import Result, Status
from strips_framework.worldmodel.operators import OperatorInstance
from strips_framework.worldmodel.world import WorldModel


class SearchTree:
    """``clock`` is the run's (see :class:`~strips_framework.limits.Clock`);
    ``searching_since`` when this search began, for its own time in the statistics.
    ``level`` is stamped on each new node: a hierarchical strategy sets it before it
    searches each abstraction level (see :attr:`Node.level`). Mutable: it grows as the
    search adds nodes."""

    __slots__ = ("limits", "prover", "clock", "nodes", "level", "searching_since")

    def __init__(
        self,
        limits: Limits,
        prover: GoalProver,
        clock: Clock,
        nodes: list[Node] | None = None,
        level: int | None = None,
    ) -> None:
        self.limits = limits
        self.prover = prover
        self.clock = clock
        self.nodes: list[Node] = [] if nodes is None else nodes
        self.level = level
        self.searching_since = clock.elapsed()

    def check_time(self) -> None:
        self.clock.check()

    def new_node(
        self,
        model: WorldModel,
        goals: tuple[Goal, ...],
        parent: Node | None,
        plan: tuple[OperatorInstance, ...],
        applied: OperatorInstance | None = None,
    ) -> Node:
        if len(self.nodes) >= self.limits.nodes:
            raise LimitReached(Status.NODE_LIMIT)
        self.check_time()
        node = Node(len(self.nodes), model, goals, parent, plan, applied, level=self.level)
        self.nodes.append(node)
        return node

    def result(self, status: Status, solution: Node | None) -> Result:
        # A hierarchical search's path runs through every level; its figures count the
        # solution's own level, whose applications are the plan.
        path = [n for n in path_to(solution) if solution is None or n.level == solution.level]
        elapsed = self.clock.elapsed()
        statistics = WorldModelStatistics(
            nodes=len(self.nodes),
            applications=sum(1 for n in self.nodes if n.applied is not None),
            path_nodes=len(path),
            path_applications=sum(1 for n in path if n.applied is not None),
            seconds=elapsed - self.searching_since,
            proving_seconds=self.prover.seconds,
            proof_attempts=self.prover.attempts,
        )
        plan = None if solution is None else tuple(step.ipc() for step in solution.plan)
        return Result(
            status,
            plan,
            None if plan is None else len(plan),
            statistics,
            elapsed,
            tree=Tree(tuple(self.nodes), solution),
        )
