"""Forward state-space search over ground tasks (:mod:`strips_framework.grounding.task`).

A*, weighted A*, eager and lazy greedy best-first search, enforced hill-climbing and
breadth-first search, all over integer-bitset states, with the state heuristics that
plugins register. ``docs/search.md`` describes the strategies, their tie-breaking and
the limits.
"""
