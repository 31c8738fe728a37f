"""A discrimination tree: the retained atoms that may *generalize* a query atom.

Unit subsumption and unit cutting (:mod:`.subsumption`) ask, for every literal of every
new clause, which retained unit atoms match it. Trying each unit of the predicate costs
a match per unit, and a group theory written with a ternary ``product`` keeps hundreds
of ``product`` units (GRP012+5 spent 60% of its time there). A discrimination tree, as
in E, Vampire and Otter, files each atom by its symbols in preorder, variables as one
wildcard; a query walks the tree along its own symbols and, at a wildcard, skips the
whole subterm at that position. Only atoms whose every non-variable symbol fits reach a
leaf, so the candidates are few. A variable repeated in a filed atom is a wildcard at
each occurrence, so a candidate still needs the match (:func:`~.subsumption.match_term`)
that checks the occurrences agree; a variable of the query stands for itself and only
meets wildcards.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from typing import Generic, TypeVar

from strips_framework.logic.terms import Term

Item = TypeVar("Item")

#: The symbol a variable of a filed atom becomes (and a key no query symbol equals).
_WILDCARD = object()
#: Where a node keeps the items filed at it.
_LEAF = object()
#: The symbol of a query's variable: it fits only under a wildcard.
_QUERY_VARIABLE = object()


def _symbols(term: Term, out: list[object]) -> None:
    """``term``'s symbols in preorder: a functor with its arity, a constant or parameter
    as itself, a variable as :data:`_WILDCARD`."""
    kind = type(term)
    if kind is tuple:
        out.append((term[0], len(term)))
        for arg in term[1:]:
            _symbols(arg, out)
    elif kind is int:
        out.append(_WILDCARD)
    else:
        out.append(term)


def _query(term: Term, symbols: list[object], ends: list[int]) -> None:
    """``term``'s symbols in preorder, with, at each position, where its subterm ends."""
    at = len(symbols)
    ends.append(0)
    kind = type(term)
    if kind is tuple:
        symbols.append((term[0], len(term)))
        for arg in term[1:]:
            _query(arg, symbols, ends)
    else:
        symbols.append(_QUERY_VARIABLE if kind is int else term)
    ends[at] = len(symbols)


class DiscriminationTree(Generic[Item]):
    """Items filed by an atom; :meth:`generalizations` finds those whose atom may match
    a query atom. Items are kept in insertion order, so retrieval is deterministic."""

    def __init__(self) -> None:
        self._root: dict[object, dict] = {}
        self._size = 0

    def __len__(self) -> int:
        return self._size

    def add(self, atom: tuple, item: Item) -> None:
        symbols: list[object] = [(atom[0], len(atom))]
        for arg in atom[1:]:
            _symbols(arg, symbols)
        node = self._root
        for symbol in symbols:
            node = node.setdefault(symbol, {})
        node.setdefault(_LEAF, []).append(item)
        self._size += 1

    def generalizations(self, atom: tuple) -> Iterator[Item]:
        """The items whose atom's symbols fit ``atom`` (candidates for a match)."""
        top = self._root.get((atom[0], len(atom)))
        if top is None:
            return
        symbols: list[object] = []
        ends: list[int] = []
        for arg in atom[1:]:
            _query(arg, symbols, ends)
        last = len(symbols)
        stack: list[tuple[dict, int]] = [(top, 0)]
        while stack:  # depth first, the exact symbol before the wildcard
            node, at = stack.pop()
            if at == last:
                yield from node.get(_LEAF, ())
                continue
            wildcard = node.get(_WILDCARD)
            if wildcard is not None:
                stack.append((wildcard, ends[at]))
            child = node.get(symbols[at])
            if child is not None:
                stack.append((child, at + 1))

    def prune(self, keep: Callable[[Item], bool]) -> None:
        """Drop the items ``keep`` refuses (dead clauses), leaving empty leaves."""
        stack = [self._root]
        while stack:
            node = stack.pop()
            for key, child in node.items():
                if key is _LEAF:
                    kept = [item for item in child if keep(item)]
                    self._size -= len(child) - len(kept)
                    node[_LEAF] = kept
                else:
                    stack.append(child)
