"""A large lifted state kept as the atoms of an earlier state (its *checkpoint*, a
frozenset it shares with its relatives) and the few atoms it gained and lost since.

A search makes every new state from its parent by an action that changes a handful of
atoms. As a frozenset, each new state owned a copy of its parent's hash table: at a
thousand cities of logistics, 64 KB copied (mostly onto memory touched for the first
time) for two changed atoms, the largest part of an expansion's cost that grew with the
task. Here a successor costs its change: the parent's gained and lost atoms are updated
(sets as small as the distance to the checkpoint), and a new checkpoint is made only when
they grow past a fraction of the state, so the copying is spread over many states.

A :class:`DeltaState` is a read-only set (``in``, iteration, ``len``, the set operators
of :class:`collections.abc.Set`, equal to and hashing as the frozenset of its atoms), so
the heuristics take it as they take a frozenset. Small states stay frozensets: copying
them is cheaper than testing an overlay's membership in Python.
"""

from __future__ import annotations

from collections.abc import Collection, Iterable, Iterator
from collections.abc import Set as AbstractSet
from itertools import chain, filterfalse

from strips_framework.lifted.components import GroundAtom, LiftedState

#: States of fewer atoms are frozensets (see the module docstring).
SMALL = 256
#: A checkpoint is made when the atoms gained and lost since the last one exceed this
#: share of the state (1/32: at 2,000 atoms, after some 60 changed atoms).
SHARE = 32


class DeltaState(AbstractSet[GroundAtom]):
    """``base`` less ``removed`` (atoms of ``base``) plus ``added`` (atoms not in it)."""

    __slots__ = ("_added", "_base", "_removed", "_size")

    def __init__(
        self,
        base: frozenset[GroundAtom],
        removed: frozenset[GroundAtom],
        added: frozenset[GroundAtom],
    ) -> None:
        self._base = base
        self._removed = removed
        self._added = added
        self._size = len(base) - len(removed) + len(added)

    def __contains__(self, atom: object) -> bool:
        return atom in self._added or (atom in self._base and atom not in self._removed)

    def __iter__(self) -> Iterator[GroundAtom]:
        return chain(self._added, filterfalse(self._removed.__contains__, self._base))

    def __len__(self) -> int:
        return self._size

    def __hash__(self) -> int:
        return hash(frozenset(self))

    def __repr__(self) -> str:
        return f"DeltaState({set(self)!r})"

    def __sub__(self, other: object) -> frozenset[GroundAtom]:
        if not isinstance(other, Iterable):
            return NotImplemented
        others = other if isinstance(other, AbstractSet) else frozenset(other)
        # In C, as a frozenset's difference (e.g. novelty's "atoms not seen yet").
        return self._base.difference(self._removed, others).union(self._added.difference(others))

    def __or__(self, other: object) -> frozenset[GroundAtom]:
        if not isinstance(other, Iterable):
            return NotImplemented
        return self._base.difference(self._removed).union(self._added, other)

    # frozenset's methods, for code written against frozenset states (each in C).
    def union(self, *others: Iterable[GroundAtom]) -> frozenset[GroundAtom]:
        return self._base.difference(self._removed).union(self._added, *others)

    def difference(self, *others: Iterable[GroundAtom]) -> frozenset[GroundAtom]:
        return self._base.difference(self._removed, *others).union(self._added.difference(*others))

    def intersection(self, *others: Iterable[GroundAtom]) -> frozenset[GroundAtom]:
        return self._base.difference(self._removed).union(self._added).intersection(*others)

    @classmethod
    def _from_iterable(cls, atoms: Iterable[GroundAtom]) -> frozenset[GroundAtom]:
        return frozenset(atoms)


def successor(
    state: LiftedState, removed: Collection[GroundAtom], added: Collection[GroundAtom]
) -> LiftedState:
    """``state`` less ``removed`` (atoms it holds) plus ``added`` (atoms it lacks), in
    time linear in the changes and the distance to ``state``'s checkpoint (see the
    module docstring)."""
    if type(state) is DeltaState:
        base = state._base
        gone = state._removed.difference(added).union(base.intersection(removed))
        new = state._added.difference(removed).union(frozenset(added).difference(base))
        if (len(gone) + len(new)) * SHARE <= len(base):
            return DeltaState(base, gone, new)
        return base.difference(gone).union(new)
    if len(state) < SMALL:
        # ``added`` first: a union copies the hash table as it is, a difference then
        # deletes in place; a table with deleted entries is not copied that way (a
        # symmetric difference would hash every atom again).
        if added:
            state = state.union(added)
        if removed:
            state = state.difference(removed)
        return state
    return DeltaState(state, frozenset(removed), frozenset(added))  # type: ignore[arg-type]
