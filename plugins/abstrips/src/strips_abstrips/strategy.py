"""The ``abstrips`` strategy: means-ends analysis in a hierarchy of abstraction spaces.

Sacerdoti's ABSTRIPS (1974) plans first in the most abstract space, where operators keep
only their most critical precondition literals (see :mod:`strips_abstrips.hierarchy`),
then refines the plan level by level: at each lower level, STRIPS starts from M0 with the
goal list made of the abstract plan's steps (bound as far as relevance chose them; the
abstract proofs' other bindings are left to the refinement), each step's precondition
(at this level) followed by G0, so that its search only fills in what the abstract plan
left out. The
refined plan goes to the next level down; the plan of the lowest level (the problem
itself) is the answer.

*Backtracking across levels.* When a refinement fails (its search runs out of nodes, or
of the ``refinement_nodes`` it may make), the level above is asked for its next plan
(its search goes on where it stopped), and that one is refined instead; the same plan is
never refined twice. So a failing abstraction costs search but never loses a plan that
the level above can find.

Every level's nodes go into one search tree, each stamped with its level
(:attr:`~strips_framework.means_ends.node.Node.level`); the root of a refinement hangs
under the goal node of the plan it refines, so the solution path runs through every level.
All levels share one prover session and its cache: the models are the same (M0 and the
operators' effects), only the preconditions asked about differ.
"""

from __future__ import annotations

from collections.abc import Mapping
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
    from strips_framework.means_ends.goal_prover import GoalProver
    from strips_framework.means_ends.node import Node
    from strips_framework.means_ends.tree import SearchTree
    from strips_framework.result import Result
    from strips_framework.worldmodel.operators import OperatorInstance
    from strips_framework.worldmodel.problem import Problem
    from strips_framework.worldmodel.proving import TheoremProver
    from strips_abstrips.hierarchy import Hierarchy


class AbstripsSearch(Configurable):
    """ABSTRIPS over the means-ends search of the core.

    ``criticality`` gives the values by predicate (``{INROOM = 2, NEXTTO = 1}``); empty,
    they are computed from the operators and M0 with plans of at most ``short_plan``
    steps counting as short. ``max_goals`` bounds subgoaling as in ``means-ends``
    (counted above the refined plan's own goals). ``refinement_nodes`` is what one
    refinement may make before the level above is asked for another plan.
    ``goal_loops`` is means-ends's check, on by default in both: at every level a
    subgoal is not pushed when it needs what the operator it serves was pushed to add.
    Without it, depot 03 and 04's refinements ran out of their nodes on such loops for
    every plan the level above offered (docs/abstrips.md).
    """

    name: ClassVar[str] = "abstrips"
    capabilities: ClassVar[frozenset[str]] = frozenset()
    requires: ClassVar[tuple[Requirement, ...]] = (
        Requirement("prover", ANSWERS, "it applies each operator with the parameter "
                    "bindings of its precondition's proof"),
    )
    options = (
        Option("max_goals", int, 8, minimum=0, exclusive_minimum=True,
               doc="the longest run of subgoals above a refined plan's goals"),
        Option("criticality", dict, {}, doc="criticality by predicate name; empty: computed"),
        Option("short_plan", int, 1, minimum=0,
               doc="steps a plan may have and still count as short (computed criticalities)"),
        Option("refinement_nodes", int, 2000, minimum=0, exclusive_minimum=True,
               doc="nodes one refinement may make before the level above is asked again"),
        Option("goal_loops", bool, True,
               doc="no subgoal that needs what the operator it serves is there to add "
               "(as means-ends's goal_loops)"),
    )
    max_goals: int
    criticality: Mapping[str, int]
    short_plan: int
    refinement_nodes: int
    goal_loops: bool

    def __init__(self, **options: object) -> None:
        super().__init__(**options)
        for key, value in self.criticality.items():
            if not isinstance(key, str) or isinstance(value, bool) or not isinstance(value, int):
                from strips_framework.options import OptionError

                raise OptionError(
                    "criticality",
                    f"expected predicate names mapped to integers, got {key!r} = {value!r}",
                )

    def hierarchy(self, problem: Problem) -> Hierarchy:
        from strips_abstrips.hierarchy import computed, given

        if self.criticality:
            return given(problem, self.criticality)
        return computed(problem, self.short_plan)

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
        from strips_framework.limits import Clock, LimitReached
        from strips_framework.means_ends.goal_prover import GoalProver
        from strips_framework.means_ends.tree import SearchTree
        from strips_framework.result import Status

        goal_prover = GoalProver(problem, prover, limits.effort,
                                 difference_effort=limits.difference_effort)
        tree = SearchTree(limits, goal_prover, clock or Clock(limits.time))
        refiner = _Refiner(self, self.hierarchy(problem), problem, goal_prover,
                           differences, relevance, evaluator, limits, tree)
        try:
            solution = refiner.refine(0, (), None)
        except LimitReached as limit:
            return tree.result(limit.status, None)
        except KeyboardInterrupt:  # Ctrl-C: report what the search did so far
            return tree.result(Status.INTERRUPTED, None)
        return tree.result(Status.SOLVED if solution else Status.EXHAUSTED, solution)


class _Refiner:
    """One ABSTRIPS search: a means-ends run per refinement, levels highest first."""

    def __init__(
        self,
        options: AbstripsSearch,
        hierarchy: Hierarchy,
        problem: Problem,
        goal_prover: GoalProver,
        differences: DifferenceExtractor,
        relevance: RelevanceFilter,
        evaluator: NodeEvaluator,
        limits: Limits,
        tree: SearchTree,
    ) -> None:
        self.options = options
        self.levels = hierarchy.levels
        self.problems = [hierarchy.problem_at(problem, level) for level in self.levels]
        self.goal_prover = goal_prover
        self.differences = differences
        self.relevance = relevance
        self.evaluator = evaluator
        self.limits = limits
        self.tree = tree

    def refine(
        self, index: int, plan: tuple[OperatorInstance, ...], above: Node | None
    ) -> Node | None:
        """A goal node of the lowest level whose plan refines ``plan`` (the plan of
        level ``index - 1``; empty at the top), or ``None`` when none was found."""
        from strips_framework.means_ends.node import Goal
        from strips_framework.means_ends.run import MeansEndsRun
        from strips_framework.worldmodel.operators import OperatorInstance

        problem = self.problems[index]
        schemata = {schema.name: schema for schema in problem.operators}
        steps = [OperatorInstance(schemata[step.schema_name], step.binding) for step in plan]
        run = MeansEndsRun(
            self.options.max_goals, problem, self.goal_prover, self.differences,
            self.relevance, self.evaluator, self.limits, self.tree.clock, tree=self.tree,
            planned=tuple(Goal(step.precondition(), step) for step in steps), parent=above,
            max_nodes=None if index == 0 else self.options.refinement_nodes,
            distinct_plans=index < len(self.levels) - 1, goal_loops=self.options.goal_loops,
        )
        tried: set[tuple[OperatorInstance, ...]] = set()
        level = self.tree.level = self.levels[index]
        for solution in run.solutions():
            if index == len(self.levels) - 1:
                return solution
            steps = _as_chosen(solution, level)
            if steps in tried:
                continue
            tried.add(steps)
            refined = self.refine(index + 1, steps, solution)
            if refined is not None:
                return refined
            self.tree.level = self.levels[index]  # back at this level: its nodes again
        return None


def _as_chosen(solution: Node, level: int) -> tuple[OperatorInstance, ...]:
    """The plan of ``solution``'s level with each step bound as far as the search chose
    it (by relevance, to achieve a goal), not as far as the abstract precondition's proof
    bound it: parameters the abstract space left free (which hoist, which place, when
    ``at`` is a detail) are the refinement's to choose, and binding them to the abstract
    proof's first answer made abstract plans that no refinement could follow."""
    from strips_framework.means_ends.node import path_to

    return tuple(
        node.parent.goals[0].operator
        for node in path_to(solution)
        if node.level == level and node.applied is not None
        and node.parent is not None and node.parent.goals[0].operator is not None
    )

