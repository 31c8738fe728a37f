"""Registers the builtin implementations (the module in
:data:`~strips_framework.plugin.registry.DEFAULT_PLUGINS`), exactly as an outside plugin would.

Each hook imports its classes when it is called, not when this module is imported: the
registry calls a kind's hook only when that kind is first looked up, so ``strips solve``
on a PDDL task with a forward strategy never loads the prover, the difference extractor
or the native reader, and the CLI starts faster.
"""

from __future__ import annotations

from strips_framework.plugin.hookspecs import hookimpl


@hookimpl
def strips_register_loaders() -> list[type]:
    from strips_framework.formats.native import NativeLoader

    return [NativeLoader]


@hookimpl
def strips_register_difference_extractors() -> list[type]:
    from strips_framework.means_ends.difference import UncompletedProofDifference

    return [UncompletedProofDifference]


@hookimpl
def strips_register_evaluators() -> list[type]:
    from strips_framework.means_ends.evaluator import PaperEvaluator

    return [PaperEvaluator]


@hookimpl
def strips_register_relevance_filters() -> list[type]:
    from strips_framework.means_ends.relevance import AddListRelevance

    return [AddListRelevance]


@hookimpl
def strips_register_strategies() -> list[type]:
    from strips_framework.means_ends.model_astar import ModelAStarSearch
    from strips_framework.means_ends.strategy import MeansEndsSearch

    return [MeansEndsSearch, ModelAStarSearch]


@hookimpl
def strips_register_ground_strategies() -> list[type]:
    from strips_framework.forward.breadth_first import BreadthFirstSearch
    from strips_framework.forward.eager import (
        AStarSearch,
        GreedySearch,
        WeightedAStarSearch,
    )
    from strips_framework.forward.ehc import EnforcedHillClimbing
    from strips_framework.forward.lazy import LazyGreedySearch

    return [
        AStarSearch,
        WeightedAStarSearch,
        GreedySearch,
        LazyGreedySearch,
        EnforcedHillClimbing,
        BreadthFirstSearch,
    ]


@hookimpl
def strips_register_lifted_strategies() -> list[type]:
    from strips_framework.lifted.alt_bfws import LiftedAlternatedBFWS
    from strips_framework.lifted.search import LiftedBFWS, LiftedLazyGreedySearch

    return [LiftedLazyGreedySearch, LiftedBFWS, LiftedAlternatedBFWS]


@hookimpl
def strips_register_heuristics() -> list[type]:
    from strips_framework.forward.blind import BlindHeuristic

    return [BlindHeuristic]


@hookimpl
def strips_register_lifted_heuristics() -> list[type]:
    from strips_framework.lifted.goal_count import LiftedGoalCount

    return [LiftedGoalCount]


@hookimpl
def strips_register_macro_learners() -> list[type]:
    from strips_framework.macrops.learning import TriangleTableLearner

    return [TriangleTableLearner]


@hookimpl
def strips_register_provers() -> list[type]:
    from strips_framework.lifted.prover import JoinProver

    return [JoinProver]
