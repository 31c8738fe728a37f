"""Registers the builtin implementations (the module in
:data:`~strips_framework.plugins.DEFAULT_PLUGINS`), exactly as an outside plugin would.

Each hook imports its classes when it is called, not when this module is imported: the
registry calls a kind's hook only when that kind is first looked up, so ``strips solve``
on a PDDL task with a forward strategy never loads the prover, the difference extractor
or the native reader, and the CLI starts faster.
"""

from __future__ import annotations

from strips_framework.hookspecs import hookimpl


@hookimpl
def strips_register_loaders() -> list[type]:
    from strips_framework.formats.native import NativeLoader

    return [NativeLoader]


@hookimpl
def strips_register_difference_extractors() -> list[type]:
    from strips_framework.difference import UncompletedProofDifference

    return [UncompletedProofDifference]


@hookimpl
def strips_register_relevance_filters() -> list[type]:
    from strips_framework.relevance import AddListRelevance

    return [AddListRelevance]


@hookimpl
def strips_register_strategies() -> list[type]:
    from strips_framework.search.means_ends import MeansEndsSearch
    from strips_framework.search.model_astar import ModelAStarSearch

    return [MeansEndsSearch, ModelAStarSearch]


@hookimpl
def strips_register_ground_strategies() -> list[type]:
    from strips_framework.search.forward.breadth_first import BreadthFirstSearch
    from strips_framework.search.forward.eager import (
        AStarSearch,
        GreedySearch,
        WeightedAStarSearch,
    )
    from strips_framework.search.forward.ehc import EnforcedHillClimbing
    from strips_framework.search.forward.lazy import LazyGreedySearch

    return [
        AStarSearch,
        WeightedAStarSearch,
        GreedySearch,
        LazyGreedySearch,
        EnforcedHillClimbing,
        BreadthFirstSearch,
    ]


@hookimpl
def strips_register_macro_learners() -> list[type]:
    from strips_framework.macrops.learning import TriangleTableLearner

    return [TriangleTableLearner]
