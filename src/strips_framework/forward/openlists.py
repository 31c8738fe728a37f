"""Open lists with deterministic tie-breaking.

:class:`BestFirstOpenList` pops the entry with the lowest key; among equal keys, the one
inserted first (FIFO), like Fast Downward's standard open list. Keys are numbers or tuples
of numbers (A* uses ``(f, h)``: lowest f, then lowest h, then first in).

:class:`AlternationOpenList` is Fast Downward's alternation over two lists, one with every
entry and one with the entries reached by a preferred operator: it pops from the
non-empty list that has been used least (the full list on ties), and each time the search
makes progress (a new lowest heuristic value) the preferred list is *boosted*: it is
credited ``boost`` extra turns.

Both keep, as Fast Downward does, one FIFO bucket (a deque) per key and a heap of the keys
that have a bucket: a push is a deque append, and the heap sees each key once per
stretch in which its bucket is non-empty. Lazy search pushes every successor of a state
under the same key, so :meth:`push_all` appends them to the bucket in one call.

A search that takes a state's successors one at a time (the lifted lazy search) keeps
one *cursor* entry for them in the full list: :meth:`push_front` puts it back where it
was popped from, at the head of its bucket, so the entries come out in the order they
would have had if all had been pushed at once; :meth:`AlternationOpenList.push_preferred`
puts the preferred ones in the preferred list alone.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Collection, Sequence
from heapq import heappop, heappush
from typing import Generic, Protocol, TypeVar

Item = TypeVar("Item")


class OpenList(Protocol[Item]):
    def __len__(self) -> int: ...

    def push(self, key: object, item: Item, preferred: bool = False) -> None: ...

    def push_all(self, key: object, items: Sequence[Item], preferred: Collection[Item]) -> None: ...

    def pop(self) -> Item: ...

    def push_front(self, key: object, item: Item) -> None: ...

    def reward_progress(self) -> None: ...


def open_list(preferred: bool, boost: int) -> OpenList[Item]:
    """An alternation list when preferred operators are used, else a single list."""
    return AlternationOpenList(boost) if preferred else BestFirstOpenList()


class _Buckets(Generic[Item]):
    """Items by key: a FIFO deque per key and a heap of the keys with a deque."""

    __slots__ = ("buckets", "keys", "size")

    def __init__(self) -> None:
        self.buckets: dict[object, deque[Item]] = {}
        self.keys: list = []
        self.size = 0

    def bucket(self, key: object) -> deque[Item]:
        bucket = self.buckets.get(key)
        if bucket is None:
            bucket = self.buckets[key] = deque()
            heappush(self.keys, key)
        return bucket

    def pop(self) -> Item:
        key = self.keys[0]
        bucket = self.buckets[key]
        item = bucket.popleft()
        if not bucket:
            del self.buckets[key]
            heappop(self.keys)
        self.size -= 1
        return item


class BestFirstOpenList(Generic[Item]):
    def __init__(self) -> None:
        self._items: _Buckets[Item] = _Buckets()

    def __len__(self) -> int:
        return self._items.size

    def push(self, key: object, item: Item, preferred: bool = False) -> None:
        """Insert ``item`` under ``key``; ``preferred`` only matters to alternation."""
        self._items.bucket(key).append(item)
        self._items.size += 1

    def push_all(self, key: object, items: Sequence[Item], preferred: Collection[Item]) -> None:
        """Insert ``items`` under ``key``, in order."""
        if items:
            self._items.bucket(key).extend(items)
            self._items.size += len(items)

    def pop(self) -> Item:
        return self._items.pop()

    def push_front(self, key: object, item: Item) -> None:
        """Insert ``item`` under ``key`` ahead of the entries already there."""
        self._items.bucket(key).appendleft(item)
        self._items.size += 1

    def reward_progress(self) -> None:
        """Nothing to boost in a single list."""


class AlternationOpenList(Generic[Item]):
    """Every entry, and the preferred ones again (an entry in both can be popped from
    each, as in Fast Downward)."""

    def __init__(self, boost: int) -> None:
        self.boost = boost
        self._all: _Buckets[Item] = _Buckets()
        self._preferred: _Buckets[Item] = _Buckets()
        #: Turns taken by each list (lower goes next); boosting lowers the preferred one's.
        self._turns = [0, 0]

    def __len__(self) -> int:
        return self._all.size + self._preferred.size

    def push(self, key: object, item: Item, preferred: bool = False) -> None:
        self._all.bucket(key).append(item)
        self._all.size += 1
        if preferred:
            self._preferred.bucket(key).append(item)
            self._preferred.size += 1

    def push_all(self, key: object, items: Sequence[Item], preferred: Collection[Item]) -> None:
        """Insert ``items`` under ``key``, in order; those in ``preferred`` go into the
        preferred list too."""
        if not items:
            return
        self._all.bucket(key).extend(items)
        self._all.size += len(items)
        if preferred:
            chosen = [item for item in items if item in preferred]
            if chosen:
                self._preferred.bucket(key).extend(chosen)
                self._preferred.size += len(chosen)

    def push_preferred(self, key: object, items: Sequence[Item]) -> None:
        """Insert ``items`` under ``key`` into the preferred list only (their full-list
        entries are made as they are needed, see the module docstring)."""
        if items:
            self._preferred.bucket(key).extend(items)
            self._preferred.size += len(items)

    def push_front(self, key: object, item: Item) -> None:
        """Insert ``item`` under ``key`` in the full list, ahead of the entries there."""
        self._all.bucket(key).appendleft(item)
        self._all.size += 1

    def pop(self) -> Item:
        turns = self._turns
        if self._preferred.size and (turns[1] < turns[0] or not self._all.size):
            turns[1] += 1
            return self._preferred.pop()
        turns[0] += 1
        return self._all.pop()

    def reward_progress(self) -> None:
        self._turns[1] -= self.boost
