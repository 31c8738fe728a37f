"""A* over world models (``model-astar``): the optimal strategy to compare means-ends analysis with.

It works on the same world models, operators and prover as the STRIPS strategy but
searches forward: a node's successors are all applicable operator instances, found by
proving each precondition schema with answer extraction for its parameters (parameters
that only the effects mention range over the problem's constants). Nodes are expanded in
order of the evaluator's score and the goal is tested when a node is expanded, so with an
admissible evaluator such as ``breadth-first`` the first plan found is a shortest one.
The difference of each node (its failed proof of the goal) is still extracted, for the
evaluators that use it; the relevance filter is not used, since forward search needs the
applicable operators, not the relevant ones.
"""

from __future__ import annotations

import heapq
import itertools
from collections.abc import Iterator
from typing import TYPE_CHECKING, ClassVar

from strips_framework.capabilities import ADMISSIBLE, ANSWERS, OPTIMAL, Requirement
from strips_framework.options import Configurable, Option

if TYPE_CHECKING:
    from strips_framework.limits import Clock, Limits
    from strips_framework.means_ends.components import (
        DifferenceExtractor,
        NodeEvaluator,
        RelevanceFilter,
    )
    from strips_framework.means_ends.goal_prover import GoalProver
    from strips_framework.means_ends.node import Node
    from strips_framework.result import Result
    from strips_framework.worldmodel.operators import OperatorInstance
    from strips_framework.worldmodel.problem import Problem
    from strips_framework.worldmodel.proving import TheoremProver
    from strips_framework.worldmodel.world import WorldModel


class ModelAStarSearch(Configurable):
    """Forward A* (best-first on the evaluator's score) with duplicate detection.

    ``max_answers`` bounds the applicable instances taken from one precondition proof.
    """

    name: ClassVar[str] = "model-astar"
    capabilities: ClassVar[frozenset[str]] = frozenset({OPTIMAL})
    requires: ClassVar[tuple[Requirement, ...]] = (
        Requirement("prover", ANSWERS, "it finds the applicable operator instances from "
                    "the bindings of precondition proofs"),
        Requirement("evaluator", ADMISSIBLE, "its first plan is a shortest one only then",
                    strict=False),
    )
    options = (
        Option("max_answers", int, 256, minimum=0, exclusive_minimum=True,
               doc="applicable instances taken from one precondition proof"),
    )
    max_answers: int

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
        # Imported here, not at the top, so that registering the strategy stays cheap.
        from strips_framework.limits import Clock, LimitReached
        from strips_framework.means_ends.components import evaluator_for_problem
        from strips_framework.means_ends.goal_prover import GoalProver
        from strips_framework.means_ends.node import Goal
        from strips_framework.means_ends.tree import SearchTree
        from strips_framework.result import Status
        goal_prover = GoalProver(problem, prover, limits.effort)
        tree = SearchTree(limits, goal_prover, clock or Clock(limits.time))
        top = (Goal(problem.goal),)
        evaluator = evaluator_for_problem(evaluator, problem.operators, goal_prover.initial)

        def make(
            model: WorldModel,
            parent: Node | None,
            plan: tuple[OperatorInstance, ...],
            applied: OperatorInstance | None = None,
        ) -> Node:
            node = tree.new_node(model, top, parent, plan, applied)
            result = goal_prover.prove(model, problem.goal)
            if not result.proved:
                node.difference = differences.extract(result, goal_prover.negated(problem.goal))
            return node

        # Ties on the score go to the node with more operators applied (the lower
        # estimate, nearer a goal), then first in, as in Fast Downward's A*.
        queue: list[tuple[float, int, int, Node]] = []
        counter = itertools.count()
        # The cheapest known cost of reaching each model; a node reaching it at no lower
        # cost is a duplicate and is never made (or, if superseded later, never expanded).
        best_cost: dict[WorldModel, int] = {}
        try:
            root = make(goal_prover.root_model(), None, ())
            best_cost[root.model] = 0
            heapq.heappush(queue, (evaluator.evaluate(root), 0, next(counter), root))
            while queue:
                tree.check_time()
                _, _, _, node = heapq.heappop(queue)
                if node.difference is None:
                    return tree.result(Status.SOLVED, node)
                if node.cost > best_cost[node.model]:
                    continue
                for instance in self._applicable(problem, goal_prover, node.model):
                    model = instance.apply(node.model)
                    if best_cost.get(model, node.cost + 2) <= node.cost + 1:
                        continue
                    best_cost[model] = node.cost + 1
                    child = make(model, node, (*node.plan, *instance.steps()), instance)
                    score = evaluator.evaluate(child)
                    heapq.heappush(queue, (score, -child.cost, next(counter), child))
        except LimitReached as limit:
            return tree.result(limit.status, None)
        except KeyboardInterrupt:  # Ctrl-C: report what the search did so far
            return tree.result(Status.INTERRUPTED, None)
        return tree.result(Status.EXHAUSTED, None)

    def _applicable(
        self, problem: Problem, goal_prover: GoalProver, model: WorldModel
    ) -> Iterator[OperatorInstance]:
        """Every ground instance whose precondition the prover proves in ``model``."""
        from strips_framework.worldmodel.operators import OperatorInstance

        seen: set[OperatorInstance] = set()
        for schema in problem.operators:
            result = goal_prover.prove(model, schema.precondition, self.max_answers)
            for answer in result.answers:
                partial = OperatorInstance(schema, [(p, t) for p, t in answer if p in schema.parameters])
                free = [p for p in schema.parameters if p not in partial.binding_map()]
                for values in itertools.product(problem.constants, repeat=len(free)):
                    instance = partial.bind(dict(zip(free, values)))
                    if instance.is_ground and instance not in seen:
                        seen.add(instance)
                        yield instance
