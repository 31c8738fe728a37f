"""Factoring shared precondition pairs out of relaxed operators.

Grounding multiplies preconditions: in depot, the 150 ``lift`` operators of one hoist at
one place all need ``(at hoist place)`` and ``(available hoist)``, so an exploration
counts those two facts off 150 times each. Here a pair of facts that at least
``min_sharing`` operators need becomes a new fact, reached by a zero-cost *conjunction*
operator with just that pair as preconditions, and the operators need the new fact
instead. A pair shared by k operators then costs 2 + k counter steps instead of 2k. Pairs
are replaced most-shared first (Re-Pair compression), so a new fact can pair up again.

For hmax, hadd and hFF the factored task is equivalent: a conjunction's cost is the max
(or sum) of its pair's costs, exactly what the operators added before, and a relaxed
plan through it expands into the pair's supporters. LM-cut is left unfactored, so that
its cuts stay those of Fast Downward.
"""

from __future__ import annotations

from collections import defaultdict
from heapq import heapify, heappop, heappush
from itertools import combinations

#: The sharing from which a pair gets a conjunction. Each conjunction is one more fact to
#: queue and operator to fire; measured on IPC tasks, pairs shared by 8 or more operators
#: pay for that (hadd 15-20% faster on depot, unchanged where little is shared).
SHARING = 8


def factor_shared_pairs(
    pre: list[tuple[int, ...]], first_new_fact: int, min_sharing: int = SHARING
) -> tuple[list[tuple[int, ...]], list[tuple[int, int]]]:
    """The operators' new preconditions and the conjunctions: new fact
    ``first_new_fact + i`` stands for the pair ``conjunctions[i]``."""
    needs = [set(facts) for facts in pre]
    holders: defaultdict[tuple[int, int], set[int]] = defaultdict(set)
    for op, facts in enumerate(needs):
        for pair in combinations(sorted(facts), 2):
            holders[pair].add(op)
    queue = [(-len(ops), pair) for pair, ops in holders.items() if len(ops) >= min_sharing]
    heapify(queue)
    conjunctions: list[tuple[int, int]] = []
    while queue:
        count, pair = heappop(queue)
        ops = holders[pair]
        if len(ops) != -count:  # shared less since it was queued
            if len(ops) >= min_sharing:
                heappush(queue, (-len(ops), pair))
            continue
        first, second = pair
        node = first_new_fact + len(conjunctions)
        conjunctions.append(pair)
        created = set()
        for op in sorted(ops):
            facts = needs[op]
            facts -= {first, second}
            for other in facts:
                holders[_pair(first, other)].discard(op)
                holders[_pair(second, other)].discard(op)
                key = _pair(node, other)
                holders[key].add(op)
                created.add(key)
            facts.add(node)
        del holders[pair]
        for key in sorted(created):
            if len(holders[key]) >= min_sharing:
                heappush(queue, (-len(holders[key]), key))
    return [tuple(sorted(facts)) for facts in needs], conjunctions


def _pair(a: int, b: int) -> tuple[int, int]:
    return (a, b) if a < b else (b, a)
