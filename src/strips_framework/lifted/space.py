"""The states a lifted search has reached, stored compactly.

Atoms are numbered the first time any state holds them. A state of a task whose states
hold :data:`WHOLE` atoms or more is stored as its change from the state it was made
from (the numbers of the atoms it lost and gained, packed 4 bytes each), and every
:data:`CHECKPOINT`-th state along such a chain whole (the sorted numbers of its atoms):
a state of n atoms costs about 4n / CHECKPOINT bytes plus its change and its table
entries, instead of 4n (or the hash table of a frozenset of tuples, about 20 times
more). :meth:`LiftedStateSpace.bytes_per_state` measures it.

The duplicate test of those hashes a state by its atoms' random 63-bit codes (a machine
word: the hash as it is) XORed together (Zobrist hashing), which a successor updates by
the few atoms that changed, so a new state is filed without reading its parent's atoms.
Only when two hashes agree are the states' atom numbers rebuilt and compared, so the
test is exact; states rebuilt lately are kept (:data:`REBUILT`) and a chain is rebuilt
from the nearest of them, as the duplicates a search meets are mostly its recent
states' relatives.

Smaller states are stored whole, their packing (a ``bytes``) their key: hashed and
compared in C, which costs less per state than the Python of a change's key, and takes
about as little room.
"""

from __future__ import annotations

import random
import sys
from array import array
from bisect import bisect_left, insort
from collections import OrderedDict
from collections.abc import Iterable

from strips_framework.lifted.components import ActionInstance, GroundAtom, LiftedState

NO_PARENT = -1
#: A state is stored whole after this many stored as changes along a chain.
CHECKPOINT = 32
#: How many rebuilt states' atom numbers are kept.
REBUILT = 64
#: States are stored as changes when the first holds this many atoms or more.
WHOLE = 64


class StateKey:
    """A state's entry in the duplicate table: equal keys stand for equal states. A key
    made for a state not yet stored holds the state it was made from and the numbers
    of the atoms it lost and gained (or all its atoms' numbers); a stored one, its
    number."""

    __slots__ = ("_hash", "_space", "added", "base", "number", "removed", "whole")

    def __init__(
        self,
        space: LiftedStateSpace,
        code: int,
        base: int = NO_PARENT,
        removed: tuple[int, ...] = (),
        added: tuple[int, ...] = (),
        whole: array | None = None,
    ) -> None:
        self._space = space
        self._hash = code
        self.number: int | None = None
        self.base = base
        self.removed = removed
        self.added = added
        self.whole = whole

    def __hash__(self) -> int:
        return self._hash

    def __eq__(self, other: object) -> bool:
        if self is other:
            return True
        if not isinstance(other, StateKey) or other._hash != self._hash:
            return False
        for one, two in ((self, other), (other, self)):  # an unchanged state, no rebuild
            unchanged = one.number is None and not one.removed and not one.added
            if unchanged and two.number is not None and one.base == two.number:
                return True
        return self.numbers() == other.numbers()

    def numbers(self) -> array:
        """The sorted numbers of the state's atoms (not to be changed: perhaps kept)."""
        space = self._space
        if self.number is not None:
            return space.numbers(self.number)
        if self.whole is not None:
            return self.whole
        keys = array("I", space.numbers(self.base))
        for number in self.removed:
            del keys[bisect_left(keys, number)]
        for number in self.added:
            insort(keys, number)
        return keys


class LiftedStateSpace:
    """States by number, with the parent and the action instance that first reached
    each, and the path cost ``g`` to it."""

    def __init__(self) -> None:
        self._numbers: dict[GroundAtom, int] = {}
        self._atoms: list[GroundAtom] = []
        #: Each atom's random code (see the module docstring); seeded, so that no
        #: search depends on the run.
        self._codes: list[int] = []
        self._random = random.Random(0)
        self.ids: dict[StateKey | bytes, int] = {}
        #: Whether states are stored as changes (decided by the first one's size).
        self._changes: bool | None = None
        #: Per state: its packing (whole, or its change as the count of lost atoms and
        #: the lost and gained atoms' numbers), the state its change is from
        #: (NO_PARENT when whole), the length of that chain, and its hash.
        self._stored: list[bytes] = []
        self._bases = array("q")
        self._depths = bytearray()
        self._hashes = array("Q")
        self.parents = array("q")
        self.steps: list[ActionInstance | None] = []
        self.g: list[int] = []
        self._rebuilt: OrderedDict[int, array] = OrderedDict()
        #: The sizes of the stored packings, summed as they are added (so the figure is
        #: known without walking the states, e.g. after running out of memory).
        self._payload = 0

    def __len__(self) -> int:
        return len(self._stored)

    @property
    def atoms(self) -> int:
        """How many distinct atoms the stored states hold."""
        return len(self._atoms)

    def _number(self, atom: GroundAtom) -> int:
        found = self._numbers.get(atom)
        if found is None:
            found = self._numbers[atom] = len(self._atoms)
            self._atoms.append(atom)
            self._codes.append(self._random.getrandbits(63))
        return found

    def pack(self, state: LiftedState) -> StateKey | bytes:
        """The key of ``state``, from all its atoms."""
        keys = array("I", sorted(map(self._number, state)))
        if self._changes is None:
            self._changes = len(keys) >= WHOLE
        if not self._changes:
            return keys.tobytes()
        code = 0
        codes = self._codes
        for number in keys:
            code ^= codes[number]
        return StateKey(self, code, whole=keys)

    def repack(
        self, parent: int, removed: Iterable[GroundAtom], added: Iterable[GroundAtom]
    ) -> StateKey | bytes:
        """The key of the state that stored state ``parent`` becomes by losing
        ``removed`` (atoms it holds) and gaining ``added`` (atoms it lacks), in time
        linear in the changes (and, for a state stored whole, a copy of its bytes)."""
        numbers = self._numbers
        if not self._changes:
            packed = self._stored[parent]
            if removed or added:
                keys = array("I")
                keys.frombytes(packed)
                for atom in removed:
                    del keys[bisect_left(keys, numbers[atom])]
                for atom in added:
                    insort(keys, self._number(atom))
                packed = keys.tobytes()
            return packed
        lost = tuple(map(numbers.__getitem__, removed))
        gained = tuple(map(self._number, added))
        code = self._hashes[parent]
        codes = self._codes
        for number in lost + gained:
            code ^= codes[number]
        return StateKey(self, code, parent, lost, gained)

    def numbers(self, number: int) -> array:
        """The sorted numbers of stored state ``number``'s atoms, rebuilt from the
        nearest kept or whole state of its chain (and kept)."""
        rebuilt = self._rebuilt
        found = rebuilt.get(number)
        if found is not None:
            rebuilt.move_to_end(number)
            return found
        chain = []
        at = number
        while at not in rebuilt and self._bases[at] != NO_PARENT:
            chain.append(at)
            at = self._bases[at]
        if at in rebuilt:
            keys = array("I", rebuilt[at])
        else:
            keys = array("I")
            keys.frombytes(self._stored[at])
        for at in reversed(chain):
            change = array("I")
            change.frombytes(self._stored[at])
            lost = change[0] + 1
            for atom in change[1:lost]:
                del keys[bisect_left(keys, atom)]
            for atom in change[lost:]:
                insort(keys, atom)
        rebuilt[number] = keys
        if len(rebuilt) > REBUILT:
            rebuilt.popitem(last=False)
        return keys

    def state(self, number: int) -> LiftedState:
        return frozenset(map(self._atoms.__getitem__, self.numbers(number)))

    def add(self, key: StateKey | bytes, parent: int, step: ActionInstance | None, g: int) -> int:
        """Store the state of ``key`` (made by :meth:`pack` or :meth:`repack`)."""
        number = len(self._stored)
        if isinstance(key, bytes):
            self._stored.append(key)
            self._bases.append(NO_PARENT)
            self._depths.append(0)
            self._payload += sys.getsizeof(key)
            self.ids[key] = number
            self.parents.append(parent)
            self.steps.append(step)
            self.g.append(g)
            return number
        depth = self._depths[key.base] + 1 if key.whole is None else 0
        if depth < CHECKPOINT and key.whole is None:
            packed = array("I", (len(key.removed), *key.removed, *key.added)).tobytes()
            self._bases.append(key.base)
        else:
            packed = key.numbers().tobytes()
            self._bases.append(NO_PARENT)
            depth = 0
        self._stored.append(packed)
        self._depths.append(depth)
        self._hashes.append(key._hash)
        self._payload += sys.getsizeof(packed)
        key.number = number
        key.removed = key.added = ()
        key.whole = None
        self.ids[key] = number
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
        """What the stored states cost on average: the packings, the keys and their
        entries in the duplicate table, the per-state arrays and the parent, step and
        g slots (the action instances themselves are shared with the search's open
        list)."""
        if not self._stored:
            return 0.0
        count = len(self._stored)
        table = sys.getsizeof(self.ids) + sys.getsizeof(self._stored) + sys.getsizeof(self.steps)
        table += sys.getsizeof(self.g) + sys.getsizeof(self._hashes) + count
        table += (self.parents.itemsize + self._bases.itemsize) * count
        if self._changes:
            table += count * sys.getsizeof(StateKey.__new__(StateKey))
        return (self._payload + table) / count

    def clear(self) -> None:
        """Let the stored states go (after running out of memory)."""
        self.ids.clear()
        self._stored.clear()
        self._rebuilt.clear()
        self.steps.clear()
        self.g.clear()
