"""Registers the forward strategies (a module of :data:`~strips_framework.plugins.DEFAULT_PLUGINS`)."""

from __future__ import annotations

from strips_framework.hookspecs import hookimpl
from strips_framework.search.forward.breadth_first import BreadthFirstSearch
from strips_framework.search.forward.eager import AStarSearch, GreedySearch, WeightedAStarSearch
from strips_framework.search.forward.ehc import EnforcedHillClimbing
from strips_framework.search.forward.lazy import LazyGreedySearch


@hookimpl
def strips_register_strategies() -> list[type]:
    return [
        AStarSearch,
        WeightedAStarSearch,
        GreedySearch,
        LazyGreedySearch,
        EnforcedHillClimbing,
        BreadthFirstSearch,
    ]
