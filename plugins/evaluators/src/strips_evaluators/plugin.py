"""Registers this distribution's node evaluators and state heuristics (entry point
``evaluators`` in group ``strips_framework``).

Each hook imports its classes when called; the registry calls a kind's hook only when
that kind is looked up, so a forward search loads no node evaluator and a means-ends
search no state heuristic."""

from __future__ import annotations

from typing import TYPE_CHECKING

from strips_framework.plugin.hookspecs import hookimpl

if TYPE_CHECKING:
    from strips_framework.forward.components import StateHeuristic
    from strips_framework.lifted.components import LiftedHeuristic
    from strips_framework.means_ends.components import NodeEvaluator


@hookimpl
def strips_register_evaluators() -> list[type[NodeEvaluator]]:
    from strips_evaluators.breadth_first import BreadthFirst
    from strips_evaluators.goal_count import GoalCount
    from strips_evaluators.goal_list_bound import GoalListBound
    from strips_evaluators.relaxed_max import RelaxedMaxEvaluator
    from strips_evaluators.relaxed_plan import RelaxedPlanEvaluator

    # The paper's evaluator is the core's (strips_framework.means_ends.evaluator), so that
    # the means-ends search has its default evaluator without this plugin.
    return [BreadthFirst, GoalCount, GoalListBound, RelaxedPlanEvaluator, RelaxedMaxEvaluator]


@hookimpl
def strips_register_heuristics() -> list[type[StateHeuristic]]:
    from strips_evaluators.heuristics.additive import AdditiveHeuristic
    from strips_evaluators.heuristics.ff import FFHeuristic
    from strips_evaluators.heuristics.goal_count import GoalCountHeuristic
    from strips_evaluators.heuristics.hmax import MaxHeuristic
    from strips_evaluators.heuristics.lmcount import LandmarkCountHeuristic
    from strips_evaluators.heuristics.lmcut import LMCutHeuristic

    # The blind heuristic is the core's (strips_framework.forward.blind), so that every
    # ground-task strategy runs without this plugin.
    return [
        GoalCountHeuristic,
        MaxHeuristic,
        AdditiveHeuristic,
        FFHeuristic,
        LMCutHeuristic,
        LandmarkCountHeuristic,
    ]


@hookimpl
def strips_register_lifted_heuristics() -> list[type[LiftedHeuristic]]:
    from strips_evaluators.lifted.heuristics import LiftedAdditive, LiftedFF, LiftedMax

    # The lifted goal-count is the core's (strips_framework.lifted.goal_count), so that a
    # lifted search has a heuristic without this plugin; registering it here too would
    # register the name twice.
    return [LiftedMax, LiftedAdditive, LiftedFF]
