"""The resolution-partner index: which retained literals a given literal may resolve with.

A world model holds thousands of facts of a few predicates (``INROOM``, ``AT``), and a
goal literal such as ``~INROOM(BOX1, x)`` unifies with almost none of them. Filing
literals under their predicate alone made every resolution step scan all the facts of
that predicate, so a proof attempt cost time linear in |M0|. Here each literal is also
filed, for each argument position, under the top symbol of its argument there (a
constant, or a functor with its arity); arguments that are variables or parameters go to
an *open* list of that position, since they unify with anything. A lookup picks the
argument position of the query whose bucket plus open list is shortest, so its cost is
in the literals that share the query's most selective symbol, not in |M0|.

Candidates come back in the order they were filed: a prover's search, and so its
answers, must not depend on the index (an entry a bucket leaves out has another symbol
at that position, so no unifier exists and the unfiltered scan would have skipped it).
"""

from __future__ import annotations

import heapq
from collections.abc import Iterable, Iterator

from strips_framework.logic.clauses import Literal
from strips_framework.logic.terms import Param
from strips_resolution_prover.pclause import PClause

#: One filed literal: filing order, the clause, the literal's position in the clause.
Entry = tuple[int, PClause, int]


def _symbol(term: object) -> object:
    """The top symbol a unifier cannot change: a constant, or ``(functor, arity)``;
    ``None`` for a variable or parameter."""
    kind = type(term)
    if kind is str:
        return term
    if kind is tuple:
        return (term[0], len(term))  # type: ignore[index, arg-type]
    if kind is int or kind is Param:
        return None
    return term


class _Table:
    """The literals of one ``(polarity, predicate, arity)`` key."""

    __slots__ = ("by_symbol", "entries", "open")

    def __init__(self, arity: int) -> None:
        self.entries: list[Entry] = []
        self.by_symbol: list[dict[object, list[Entry]]] = [{} for _ in range(arity)]
        self.open: list[list[Entry]] = [[] for _ in range(arity)]

    def add(self, entry: Entry) -> None:
        self.entries.append(entry)
        atom = entry[1].literals[entry[2]][1]
        for position, arg in enumerate(atom[1:]):
            symbol = _symbol(arg)
            if symbol is None:
                self.open[position].append(entry)
            else:
                self.by_symbol[position].setdefault(symbol, []).append(entry)

    def lookup(self, atom: tuple) -> Iterable[Entry]:
        best: list[Entry] | None = None
        best_open: list[Entry] = []
        size = len(self.entries)
        for position, arg in enumerate(atom[1:]):
            symbol = _symbol(arg)
            if symbol is None:
                continue
            bucket = self.by_symbol[position].get(symbol, [])
            open_ = self.open[position]
            if len(bucket) + len(open_) < size:
                best, best_open, size = bucket, open_, len(bucket) + len(open_)
        if best is None:
            return self.entries
        if not best_open:
            return best
        if not best:
            return best_open
        return heapq.merge(best, best_open, key=lambda entry: entry[0])


class PartnerIndex:
    """Retained literals by ``(polarity, predicate, arity)`` and argument symbols."""

    __slots__ = ("_count", "_tables")

    def __init__(self) -> None:
        self._tables: dict[tuple[bool, str, int], _Table] = {}
        self._count = 0

    def add(self, clause: PClause, position: int) -> None:
        """File literal ``position`` of ``clause``."""
        positive, atom = clause.literals[position]
        key = (positive, atom[0], len(atom))
        table = self._tables.get(key)
        if table is None:
            table = self._tables[key] = _Table(len(atom) - 1)
        table.add((self._count, clause, position))
        self._count += 1

    def partners(self, literal: Literal) -> Iterator[tuple[PClause, int]]:
        """Filed literals of the opposite sign that may unify with ``literal``, in filing
        order (most other candidates are ruled out by a constant that differs)."""
        positive, atom = literal
        table = self._tables.get((not positive, atom[0], len(atom)))
        if table is None:
            return
        for _, clause, position in table.lookup(atom):
            yield clause, position
