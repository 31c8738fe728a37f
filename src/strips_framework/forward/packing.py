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

A state space that stores packings files them by a *Zobrist code* (:func:`code_of`):
the XOR of its true facts' random 63-bit codes (:func:`fact_code`), which a successor
gets from its parent's by XORing in the codes of the facts that changed, and stores a
successor as its *change* from its parent (:func:`patch` turns the parent's packing
into the successor's): what the operator touched, not what the state holds.
"""

from __future__ import annotations

from array import array
from collections.abc import Callable, Iterable, Sequence
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


#: 64 bits, for :func:`fact_code`'s arithmetic modulo 2**64.
_WORD = (1 << 64) - 1


def fact_code(fact: int) -> int:
    """Fact number ``fact``'s Zobrist code: splitmix64 of the number with its top bit
    dropped (63 bits), the same as ``packed.h``'s. Computed, not drawn and kept: a table
    would cost set-up and memory as long as the task has facts."""
    z = (fact + 0x9E3779B97F4A7C15) & _WORD
    z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & _WORD
    z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & _WORD
    return (z ^ (z >> 31)) >> 1


def codes_xor(facts: Iterable[int]) -> int:
    """The codes of ``facts`` XORed (:func:`fact_code`)."""
    code = 0
    for fact in facts:
        code ^= fact_code(fact)
    return code


def code_of(packed: bytes) -> int:
    """The Zobrist code of the state packed as ``packed``: its facts' codes XORed."""
    facts = array("I")
    facts.frombytes(packed)
    return codes_xor(facts)


def change_of(lost: Sequence[int], gained: Sequence[int]) -> bytes:
    """A change as stored: how many facts were lost, the lost ones and the gained ones
    (each ascending), 4 bytes each."""
    return array("I", (len(lost), *lost, *gained)).tobytes()


def patch(packed: bytes, change: bytes) -> bytes:
    """The packing of the state packed as ``packed`` after ``change`` (:func:`change_of`:
    facts it holds lost, facts it lacks gained)."""
    numbers = array("I")
    numbers.frombytes(change)
    lost = numbers[0] + 1
    facts = array("I")
    facts.frombytes(packed)
    made = (set(facts) - set(numbers[1:lost])) | set(numbers[lost:])
    return array("I", sorted(made)).tobytes()


def zobrist(
    compiled: bool | None = None,
) -> tuple[Callable[[bytes], int], Callable[[bytes, bytes], bytes]]:
    """``code_of`` and ``patch``: compiled when built, as :func:`compiled_module` says."""
    module: ModuleType | None = compiled_module("strips_framework.forward._packing", compiled)
    if module is None:
        return code_of, patch
    return module.code_of, module.patch


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
