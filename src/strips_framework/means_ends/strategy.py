"""The STRIPS strategy: GPS-style means-ends analysis over (world model, goal list) nodes.

As in the paper (II.B, III.C, Figure 2): when a node is made, its first goal is tried by
the prover. If it is proved, the operator whose precondition it was is applied with the
bindings the proof found, which makes a new node (its first goal is tried at once, and so
on; when the application made a deeper goal true, the goals above it are dropped, since
their operators were there to achieve it). If not, the uncompleted proof becomes the node's difference and the relevant operator
instances for it are computed. The evaluator then picks which node gets its next successor:
the precondition of its next relevant instance pushed onto its goal list. Successors are
made one at a time, so a node stays in the queue while it has relevant instances left.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, ClassVar

from strips_framework.capabilities import ANSWERS, Requirement
from strips_framework.options import Configurable, Option

if TYPE_CHECKING:
    from strips_framework.limits import Clock, Limits
    from strips_framework.means_ends.components import (
        DifferenceExtractor,
        NodeEvaluator,
        RelevanceFilter,
    )
    from strips_framework.result import Result
    from strips_framework.worldmodel.problem import Problem
    from strips_framework.worldmodel.proving import TheoremProver


class MeansEndsSearch(Configurable):
    """Means-ends analysis as STRIPS does it.

    ``max_goals`` bounds the goal list (the depth of subgoaling), which keeps the search
    from regressing forever through ever deeper preconditions. ``goal_loops`` drops a
    relevant instance whose precondition needs an atom that the operator of the goal
    it would serve was pushed to add (:meth:`MeansEndsRun._looping_atoms`);
    ``achiever_loops`` one that needs an atom no operator can make before the atom the
    instance is offered for holds (:meth:`MeansEndsRun._needs_first`).
    """

    name: ClassVar[str] = "means-ends"
    capabilities: ClassVar[frozenset[str]] = frozenset()
    requires: ClassVar[tuple[Requirement, ...]] = (
        Requirement("prover", ANSWERS, "it applies each operator with the parameter "
                    "bindings of its precondition's proof"),
    )
    options = (
        Option("max_goals", int, 8, minimum=0, exclusive_minimum=True,
               doc="the longest goal list (depth of subgoaling)"),
        Option("goal_agenda", bool, False,
               doc="achieve G0's atoms in layers by reasonable orders (goal_order.py)"),
        Option("goal_loops", bool, True,
               doc="no subgoal that needs what the operator it serves is there to add"),
        Option("achiever_loops", bool, False,
               doc="no subgoal that needs an atom which only the atom it is to add lets "
               "an operator make"),
    )
    max_goals: int
    goal_agenda: bool
    goal_loops: bool
    achiever_loops: bool

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
        from strips_framework.limits import Clock
        from strips_framework.means_ends.goal_order import goal_agenda
        from strips_framework.means_ends.goal_prover import GoalProver
        from strips_framework.means_ends.node import Goal
        from strips_framework.means_ends.run import MeansEndsRun

        agenda = goal_agenda(problem)[:-1] if self.goal_agenda else ()
        goal_prover = GoalProver(problem, prover, limits.effort,
                                 difference_effort=limits.difference_effort)
        run = MeansEndsRun(self.max_goals, problem, goal_prover,
                           differences, relevance, evaluator, limits,
                           clock or Clock(limits.time),
                           planned=tuple(Goal(formula) for formula in agenda),
                           goal_loops=self.goal_loops, achiever_loops=self.achiever_loops,
                           agenda_only=True)
        return run.search()
