"""Open lists with deterministic tie-breaking.

:class:`BestFirstOpenList` pops the entry with the lowest key; among equal keys, the one
inserted first (FIFO), like Fast Downward's standard open list. Keys are numbers or tuples
of numbers (A* uses ``(f, h)``: lowest f, then lowest h, then first in).

:class:`AlternationOpenList` is Fast Downward's alternation over two lists, one with every
entry and one with the entries reached by a preferred operator: it pops from the
non-empty list that has been used least (the full list on ties), and each time the search
makes progress (a new lowest heuristic value) the preferred list is *boosted*: it is
credited ``boost`` extra turns.
"""

from __future__ import annotations

import heapq
import itertools
from typing import Generic, Protocol, TypeVar

Item = TypeVar("Item")


class OpenList(Protocol[Item]):
    def __len__(self) -> int: ...

    def push(self, key: object, item: Item, preferred: bool = False) -> None: ...

    def pop(self) -> Item: ...

    def reward_progress(self) -> None: ...


def open_list(preferred: bool, boost: int) -> OpenList[Item]:
    """An alternation list when preferred operators are used, else a single list."""
    return AlternationOpenList(boost) if preferred else BestFirstOpenList()


class BestFirstOpenList(Generic[Item]):
    def __init__(self) -> None:
        self._heap: list[tuple[object, int, Item]] = []
        self._order = itertools.count()

    def __len__(self) -> int:
        return len(self._heap)

    def push(self, key: object, item: Item, preferred: bool = False) -> None:
        """Insert ``item`` under ``key``; ``preferred`` only matters to alternation."""
        heapq.heappush(self._heap, (key, next(self._order), item))

    def pop(self) -> Item:
        return heapq.heappop(self._heap)[2]

    def reward_progress(self) -> None:
        """Nothing to boost in a single list."""


class AlternationOpenList(Generic[Item]):
    """Two heaps of ``(key, order, item)``: every entry, and the preferred ones (the
    lists are inlined here because the lazy search pushes every successor through them)."""

    def __init__(self, boost: int) -> None:
        self.boost = boost
        self._all: list[tuple[object, int, Item]] = []
        self._preferred: list[tuple[object, int, Item]] = []
        self._order = itertools.count()
        #: Turns taken by each list (lower goes next); boosting lowers the preferred one's.
        self._turns = [0, 0]

    def __len__(self) -> int:
        return len(self._all) + len(self._preferred)

    def push(self, key: object, item: Item, preferred: bool = False) -> None:
        entry = (key, next(self._order), item)
        heapq.heappush(self._all, entry)
        if preferred:
            heapq.heappush(self._preferred, entry)

    def pop(self) -> Item:
        turns = self._turns
        if self._preferred and (turns[1] < turns[0] or not self._all):
            turns[1] += 1
            return heapq.heappop(self._preferred)[2]
        turns[0] += 1
        return heapq.heappop(self._all)[2]

    def reward_progress(self) -> None:
        self._turns[1] -= self.boost
