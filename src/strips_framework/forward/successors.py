"""Successor generation: which operators apply in a state, and what they make of it.

Testing every operator in every state costs time in proportion to the whole task. Instead
each operator is filed under one of its precondition facts, its *key*: the one the fewest
other operators need, so that the buckets stay small. A state looks only into the
buckets of the key facts it holds (walking its set bits, lowest first) and tests the
full preconditions of the operators there. Operators without positive preconditions are
tested in every state. The order is deterministic: by key fact, then operator number.
An operator's place in that order (its *position*: the unkeyed operators first, then the
buckets by key fact) lets a search take a state's applicable operators one at a time
(:meth:`SuccessorGenerator.next_applicable`), resuming where it left off, instead of
listing them all: lazy search takes a few of a large state's thousands.

A state is given as an int bitset, or, where the state space stores it packed, as its
packing (the sorted numbers of its true facts, :mod:`.packing`): the walk over a
packing and the successor of a packing (:meth:`SuccessorGenerator.step_packed`) cost
what the state holds and the operator changes, not what the task has.

This class is the pure-Python reference. :func:`successor_generator` gives the compiled
one (``_successors.pyx``, built by ``pip install`` with Cython) when it is built and
:data:`~strips_framework.compiled.PURE_PYTHON_SWITCH` is not set: the same layout over C
arrays, with the same operators in the same order, so searches expand the same states.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Callable, Iterable, Mapping, Sequence
from functools import cached_property
from typing import Protocol

from strips_framework.allocation import collection_paused
from strips_framework.compiled import compiled_module
from strips_framework.forward.packing import change_of, codes_xor, pack, unpack
from strips_framework.grounding.task import GroundOperator, GroundTask, facts_in


class Successors(Protocol):
    """What a state space needs of a successor generator."""

    delete: Mapping[int, int]
    add: Mapping[int, int]
    effects: Mapping[int, tuple[tuple[int, int, int, int], ...]] | None

    @property
    def order(self) -> Sequence[int]:
        """The operators in the order :meth:`applicable` lists them, by position."""
        ...

    def applicable(self, state: int) -> list[int]: ...

    def next_applicable(self, state: int | bytes, position: int) -> int: ...

    def ordered(self, state: int | bytes, operators: Iterable[int]) -> list[int]: ...

    def apply(self, state: int, operator: int) -> int: ...

    def step_packed(self, packed: bytes, operator: int, code: int) -> tuple[bytes, bytes, int]: ...


@collection_paused()
def successor_generator(task: GroundTask, compiled: bool | None = None) -> Successors:
    """The compiled generator of ``task`` when it is built, else the reference (``compiled``
    as in :func:`~strips_framework.compiled.compiled_module`)."""
    reference = SuccessorGenerator(task)
    module = compiled_module("strips_framework.forward._successors", compiled)
    return reference if module is None else module.SuccessorGenerator(reference, task)


class _OperatorMasks(dict[int, int]):
    """Per operator number, a mask made on first use (``mask(operator)``): a search applies
    few of a large task's operators, and a mask costs as much as the task has facts."""

    def __init__(
        self, mask: Callable[[GroundOperator], int], operators: Sequence[GroundOperator]
    ) -> None:
        super().__init__()
        self._mask = mask
        self._operators = operators

    def __missing__(self, operator: int) -> int:
        value = self[operator] = self._mask(self._operators[operator])
        return value


class SuccessorGenerator:
    def __init__(self, task: GroundTask) -> None:
        operators = task.operators
        needed_by = Counter(fact for op in operators for fact in op.pre)
        #: Per key fact, the operators filed under it (see the module docstring).
        buckets: dict[int, list[int]] = {}
        unkeyed: list[int] = []
        for index, op in enumerate(operators):
            if op.pre:
                key = min(op.pre, key=lambda fact: (needed_by[fact], fact))
                buckets.setdefault(key, []).append(index)
            else:
                unkeyed.append(index)
        self.buckets: dict[int, tuple[int, ...]] = {
            key: tuple(entries) for key, entries in buckets.items()
        }
        self.unkeyed = tuple(unkeyed)
        self._operators = operators
        #: Per operator: the masks of its unconditional deletes and adds.
        self.delete = _OperatorMasks(lambda op: op.delete_mask, operators)
        self.add = _OperatorMasks(lambda op: op.add_mask, operators)
        #: Per operator: its conditional effects as (condition, negated condition, delete,
        #: add) masks; None when no operator has any, so plain tasks pay nothing for them.
        self.effects: Mapping[int, tuple[tuple[int, int, int, int], ...]] | None = None
        if any(op.effects for op in operators):
            self.effects = _OperatorMasks(_effect_masks, operators)  # type: ignore[arg-type]

    def applicable(self, state: int) -> list[int]:
        """The numbers of the operators applicable in ``state``."""
        operators = self._operators
        found = [i for i in self.unkeyed if operators[i].applicable(state)]
        buckets = self.buckets
        for fact in facts_in(state):
            for i in buckets.get(fact, ()):
                if operators[i].applicable(state):
                    found.append(i)
        return found

    @cached_property
    def order(self) -> tuple[int, ...]:
        """The operators in the order :meth:`applicable` lists them, by position (made
        on first use: the compiled generator lays out its own)."""
        return self.unkeyed + tuple(op for key in sorted(self.buckets) for op in self.buckets[key])

    @cached_property
    def position(self) -> dict[int, int]:
        """Per operator number, its position in :attr:`order`."""
        return {op: place for place, op in enumerate(self.order)}

    def next_applicable(self, state: int | bytes, position: int) -> int:
        """The position (in :attr:`order`) of the first operator applicable in ``state``
        (a bitset or its packing) at ``position`` or after, or -1 if none."""
        if isinstance(state, bytes):
            state = unpack(state)
        places = [self.position[op] for op in self.applicable(state)]
        return next((place for place in places if place >= position), -1)

    def ordered(self, state: int | bytes, operators: Iterable[int]) -> list[int]:
        """Those of ``operators`` applicable in ``state`` (a bitset or its packing), once
        each, in the order :meth:`applicable` lists them (a heuristic's preferred
        operators, queued as a search would queue them from the full list)."""
        if isinstance(state, bytes):
            state = unpack(state)
        found = {op for op in operators if self._operators[op].applicable(state)}
        return sorted(found, key=self.position.__getitem__)

    def step_packed(self, packed: bytes, operator: int, code: int) -> tuple[bytes, bytes, int]:
        """The packing of what :meth:`apply` makes of the state packed as ``packed``,
        the change from ``packed`` to it (:func:`~.packing.change_of`: the facts it lost
        and gained) and its Zobrist code, given ``code``, the Zobrist code of ``packed``
        (XORed with the codes of the facts that changed)."""
        state = unpack(packed)
        made = self.apply(state, operator)
        lost, gained = facts_in(state ^ (state & made)), facts_in(made ^ (made & state))
        return pack(made), change_of(lost, gained), code ^ codes_xor(lost + gained)

    def apply(self, state: int, operator: int) -> int:
        """The state ``operator`` makes of ``state`` without its conditional effects
        and axioms. Deletes come out as ``state ^ (state & delete)``, not ``state &
        ~delete``: an operand's complement (a negative int) costs a conversion as long
        as the state, several times the other operations (0.17 ms at a million facts
        against 0.006 ms)."""
        return (state ^ (state & self.delete[operator])) | self.add[operator]


def _effect_masks(op: GroundOperator) -> tuple[tuple[int, int, int, int], ...]:
    return tuple(
        (e.condition_mask, e.condition_neg_mask, e.delete_mask, e.add_mask) for e in op.effects
    )
