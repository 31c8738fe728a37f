"""Feature-vector indexing (Schulz, "Simple and Efficient Clause Subsumption with Feature
Vector Indexing", 2004/2013), as E files its clauses for subsumption.

``C`` can subsume ``D`` only if every count below is no larger in ``C`` than in ``D``:
a substitution maps each literal of ``C`` to its own literal of ``D`` with the same sign
and predicate (multiset subsumption), never removes a symbol, and ``C``'s parameter
bindings are among ``D``'s. So the clauses are filed in a trie, one level per feature,
and forward subsumption of ``D`` walks only the branches whose count is at most ``D``'s
(:meth:`FeatureVectorIndex.at_most`), backward subsumption by ``C`` only those at least
``C``'s (:meth:`FeatureVectorIndex.at_least`). The features, in the order the trie
branches on them: positive and negative literals, then per predicate bucket the
positive and the negative literals (predicates hashed into :data:`BUCKETS` buckets by a
fixed checksum, so the index is the same in every process), the function and constant
symbol occurrences, the parameter bindings.
"""

from __future__ import annotations

import zlib
from collections.abc import Callable, Iterator
from typing import Generic, TypeVar

from strips_framework.logic.clauses import Literal
from strips_framework.logic.terms import Term

#: How many buckets the predicates are hashed into (per sign).
BUCKETS = 8

_bucket_of: dict[tuple[str, int], int] = {}

T = TypeVar("T")


def predicate_bucket(predicate: str, arity: int) -> int:
    found = _bucket_of.get((predicate, arity))
    if found is None:
        found = _bucket_of[(predicate, arity)] = zlib.crc32(f"{predicate}/{arity}".encode()) % BUCKETS
    return found


def _symbols(term: Term) -> int:
    kind = type(term)
    if kind is tuple:
        return 1 + sum(_symbols(arg) for arg in term[1:])
    return 0 if kind is int else 1


def feature_vector(literals: tuple[Literal, ...], bindings: int) -> tuple[int, ...]:
    """The clause's features (see the module docstring)."""
    counts = [0] * (2 * BUCKETS)
    positives = symbols = 0
    for positive, atom in literals:
        positives += positive
        counts[predicate_bucket(atom[0], len(atom)) + (0 if positive else BUCKETS)] += 1
        symbols += sum(_symbols(arg) for arg in atom[1:])
    return (positives, len(literals) - positives, *counts, symbols, bindings)


class FeatureVectorIndex(Generic[T]):
    """Items filed by feature vector in a trie of dicts (insertion-ordered, so a walk
    is deterministic)."""

    def __init__(self) -> None:
        self._root: dict[int, object] = {}
        self._size = 0

    def __len__(self) -> int:
        return self._size

    def add(self, vector: tuple[int, ...], item: T) -> None:
        node = self._root
        for value in vector[:-1]:
            node = node.setdefault(value, {})  # type: ignore[assignment]
        leaf: list[T] = node.setdefault(vector[-1], [])  # type: ignore[assignment]
        leaf.append(item)
        self._size += 1

    def at_most(self, vector: tuple[int, ...]) -> Iterator[T]:
        """Items whose every feature is at most ``vector``'s (possible subsumers)."""
        return self._walk(self._root, vector, 0, lambda key, bound: key <= bound)

    def at_least(self, vector: tuple[int, ...]) -> Iterator[T]:
        """Items whose every feature is at least ``vector``'s (possibly subsumed)."""
        return self._walk(self._root, vector, 0, lambda key, bound: key >= bound)

    def _walk(
        self,
        node: dict[int, object],
        vector: tuple[int, ...],
        depth: int,
        fits: Callable[[int, int], bool],
    ) -> Iterator[T]:
        bound = vector[depth]
        last = depth == len(vector) - 1
        for key, child in node.items():
            if not fits(key, bound):
                continue
            if last:
                yield from child  # type: ignore[misc]
            else:
                yield from self._walk(child, vector, depth + 1, fits)  # type: ignore[arg-type]

    def prune(self, keep: Callable[[T], bool]) -> None:
        """Drop the items ``keep`` rejects (and the branches left empty)."""
        self._size = self._prune(self._root, keep)

    def _prune(self, node: dict[int, object], keep: Callable[[T], bool]) -> int:
        size = 0
        for key in list(node):
            child = node[key]
            if isinstance(child, list):
                child[:] = [item for item in child if keep(item)]
                count = len(child)
            else:
                count = self._prune(child, keep)  # type: ignore[arg-type]
            if count:
                size += count
            else:
                del node[key]
        return size
