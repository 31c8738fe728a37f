"""Feature-vector indexing (Schulz, "Simple and Efficient Clause Subsumption with Feature
Vector Indexing", 2004/2013), as E files its clauses for subsumption.

``C`` can subsume ``D`` only if every count below is no larger in ``C`` than in ``D``:
a substitution maps each literal of ``C`` to its own literal of ``D`` with the same sign
and predicate (multiset subsumption), never removes a symbol, and ``C``'s parameter
bindings are among ``D``'s. So the clauses are filed by their feature vectors, and
forward subsumption of ``D`` looks only at the clauses whose counts are all at most
``D``'s (:meth:`FeatureVectorIndex.at_most`), backward subsumption by ``C`` only at
those at least ``C``'s (:meth:`FeatureVectorIndex.at_least`). The features: positive
and negative literals, then per predicate bucket the
positive and the negative literals (predicates hashed into :data:`BUCKETS` buckets by a
fixed checksum, so the index is the same in every process), the function and constant
symbol occurrences, the parameter bindings.
"""

from __future__ import annotations

import zlib
from collections.abc import Callable, Iterator
from operator import ge, le
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
        found = zlib.crc32(f"{predicate}/{arity}".encode()) % BUCKETS
        _bucket_of[(predicate, arity)] = found
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
    """Items filed by feature vector: a first level by the literal counts per sign, then
    by the whole vector, each vector's items in insertion order (dicts are too, so a walk
    is deterministic). E's tries branch on every feature; in Python a walk through
    twenty levels of generators costs more than it prunes on the small sets a proof
    attempt keeps, so below the first level the distinct vectors are compared whole."""

    def __init__(self) -> None:
        self._by_signs: dict[tuple[int, int], dict[tuple[int, ...], list[T]]] = {}
        self._size = 0

    def __len__(self) -> int:
        return self._size

    def add(self, vector: tuple[int, ...], item: T) -> None:
        vectors = self._by_signs.setdefault((vector[0], vector[1]), {})
        vectors.setdefault(vector, []).append(item)
        self._size += 1

    def at_most(self, vector: tuple[int, ...]) -> Iterator[T]:
        """Items whose every feature is at most ``vector``'s (possible subsumers)."""
        positives, negatives = vector[0], vector[1]
        for (p, n), vectors in self._by_signs.items():
            if p <= positives and n <= negatives:
                for filed, items in vectors.items():
                    if all(map(le, filed, vector)):
                        yield from items

    def at_least(self, vector: tuple[int, ...]) -> Iterator[T]:
        """Items whose every feature is at least ``vector``'s (possibly subsumed)."""
        positives, negatives = vector[0], vector[1]
        for (p, n), vectors in self._by_signs.items():
            if p >= positives and n >= negatives:
                for filed, items in vectors.items():
                    if all(map(ge, filed, vector)):
                        yield from items

    def prune(self, keep: Callable[[T], bool]) -> None:
        """Drop the items ``keep`` rejects (and the vectors left without any)."""
        size = 0
        for signs in list(self._by_signs):
            vectors = self._by_signs[signs]
            for filed in list(vectors):
                kept = [item for item in vectors[filed] if keep(item)]
                if kept:
                    vectors[filed] = kept
                    size += len(kept)
                else:
                    del vectors[filed]
            if not vectors:
                del self._by_signs[signs]
        self._size = size
