"""Ground states packed as the sorted numbers of their true facts, 4 bytes each.

A ground state is an int bitset over all the task's facts (see
:mod:`~strips_framework.grounding.task`): its size, its hash and its comparison grow
with the facts the task has, not with those that hold. Where true facts are few (blocks
with 1,000 blocks: a million facts, about a thousand true), a stored state as a bitset
costs a hundred times its packing, and hashing it for the duplicate test costs as much
as the rest of an expansion. :class:`~strips_framework.forward.space.StateSpace` keeps
such states packed (a ``bytes``, hashed and compared in C) and unpacks the few it works
on.

These functions are the pure-Python reference; ``_packing.pyx`` (built by ``pip
install`` with Cython) is the compiled one, which reads and makes the int's digits in
place, and :func:`packing` picks it as
:func:`~strips_framework.compiled.compiled_module` says.

:func:`held_counter` counts which of a few facts (a goal) a state holds: with masks,
``(mask & state).bit_count()`` costs as much as the mask is long, i.e. up to the
highest of those facts' numbers (20 µs a state at 800,000 facts); compiled, it reads
one digit per fact, or searches a packing once per fact.
"""

from __future__ import annotations

from array import array
from collections.abc import Callable, Sequence
from types import ModuleType

from strips_framework.compiled import compiled_module
from strips_framework.grounding.task import facts_in, mask_of


def pack(state: int) -> bytes:
    """The numbers of the facts true in ``state``, ascending, as 4-byte integers."""
    return array("I", facts_in(state)).tobytes()


def unpack(packed: bytes) -> int:
    """The state (bitset) whose true facts ``packed`` lists."""
    facts = array("I")
    facts.frombytes(packed)
    if not facts:
        return 0
    bits = bytearray(facts[-1] // 8 + 1)
    for fact in facts:
        bits[fact >> 3] |= 1 << (fact & 7)
    return int.from_bytes(bits, "little")


def packing(compiled: bool | None = None) -> tuple[Callable[[int], bytes], Callable[[bytes], int]]:
    """``pack`` and ``unpack``: compiled when built, as :func:`compiled_module` says."""
    module: ModuleType | None = compiled_module("strips_framework.forward._packing", compiled)
    if module is None:
        return pack, unpack
    return module.pack, module.unpack


def held_counter(
    facts: Sequence[int], compiled: bool | None = None
) -> Callable[[int | bytes], int]:
    """A function of a state (a bitset or its packing): how many of ``facts`` hold in
    it (compiled when built)."""
    module: ModuleType | None = compiled_module("strips_framework.forward._packing", compiled)
    if module is not None:
        return module.HeldCounter(facts)  # type: ignore[no-any-return]
    mask = mask_of(tuple(facts))

    def held(state: int | bytes) -> int:
        if isinstance(state, bytes):
            state = unpack(state)
        return (mask & state).bit_count()

    return held
