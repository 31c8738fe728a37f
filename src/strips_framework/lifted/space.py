"""The states a lifted search has reached, stored compactly.

A state is kept as the sorted numbers of its atoms packed 4 bytes each (atoms are
numbered the first time any state holds them), so a state of n atoms costs 4n bytes plus
the constant overhead of a ``bytes`` object and its entries in the tables, instead of
the hash table of a frozenset of tuples (about 20 times more). Equal states pack to
equal bytes, which is the duplicate test. :meth:`LiftedStateSpace.bytes_per_state`
measures what a state costs here.
"""

from __future__ import annotations

import sys
from array import array
from bisect import bisect_left, insort
from collections.abc import Iterable

from strips_framework.lifted.components import ActionInstance, GroundAtom, LiftedState

NO_PARENT = -1


class LiftedStateSpace:
    """States by number, with the parent and the action instance that first reached
    each, and the path cost ``g`` to it."""

    def __init__(self) -> None:
        self._numbers: dict[GroundAtom, int] = {}
        self._atoms: list[GroundAtom] = []
        self.ids: dict[bytes, int] = {}
        self.packed: list[bytes] = []
        self.parents = array("q")
        self.steps: list[ActionInstance | None] = []
        self.g: list[int] = []
        #: The sizes of the packed states, summed as they are added (so the figure is
        #: known without walking the states, e.g. after running out of memory).
        self._payload = 0

    def __len__(self) -> int:
        return len(self.packed)

    @property
    def atoms(self) -> int:
        """How many distinct atoms the stored states hold."""
        return len(self._atoms)

    def pack(self, state: LiftedState) -> bytes:
        numbers = self._numbers
        try:
            keys = [numbers[atom] for atom in state]
        except KeyError:
            keys = [self._number(atom) for atom in state]
        keys.sort()
        return array("I", keys).tobytes()

    def repack(self, packed: bytes, removed: Iterable[GroundAtom], added: Iterable[GroundAtom]) -> bytes:
        """The packing of a state that differs from the one ``packed`` by ``removed``
        (atoms it holds) and ``added`` (atoms it lacks): the same as :meth:`pack` of
        that state, in time linear in the changes plus one copy of the bytes."""
        keys = array("I")
        keys.frombytes(packed)
        numbers = self._numbers
        for atom in removed:
            del keys[bisect_left(keys, numbers[atom])]
        for atom in added:
            insort(keys, self._number(atom))
        return keys.tobytes()

    def _number(self, atom: GroundAtom) -> int:
        found = self._numbers.get(atom)
        if found is None:
            found = self._numbers[atom] = len(self._atoms)
            self._atoms.append(atom)
        return found

    def state(self, number: int) -> LiftedState:
        keys = array("I")
        keys.frombytes(self.packed[number])
        return frozenset(map(self._atoms.__getitem__, keys))

    def add(self, packed: bytes, parent: int, step: ActionInstance | None, g: int) -> int:
        number = len(self.packed)
        self.ids[packed] = number
        self._payload += sys.getsizeof(packed)
        self.packed.append(packed)
        self.parents.append(parent)
        self.steps.append(step)
        self.g.append(g)
        return number

    def reparent(self, number: int, parent: int, step: ActionInstance, g: int) -> None:
        self.parents[number] = parent
        self.steps[number] = step
        self.g[number] = g

    def plan_to(self, number: int) -> list[ActionInstance]:
        steps = []
        while self.parents[number] != NO_PARENT:
            step = self.steps[number]
            assert step is not None
            steps.append(step)
            number = self.parents[number]
        steps.reverse()
        return steps

    def bytes_per_state(self) -> float:
        """What the stored states cost on average: the packed bytes objects, their
        entries in the duplicate table, the parent, step and g slots (the action
        instances themselves are shared with the search's open list)."""
        if not self.packed:
            return 0.0
        table = sys.getsizeof(self.ids) + sys.getsizeof(self.packed) + sys.getsizeof(self.steps)
        table += sys.getsizeof(self.g) + self.parents.itemsize * len(self.parents)
        return (self._payload + table) / len(self.packed)

    def clear(self) -> None:
        """Let the stored states go (after running out of memory)."""
        self.ids.clear()
        self.packed.clear()
        self.steps.clear()
        self.g.clear()
