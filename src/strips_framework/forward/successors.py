"""Successor generation: which operators apply in a state, and what they make of it.

Testing every operator in every state costs time in proportion to the whole task. Instead
each operator is filed under one of its precondition facts, its *key*: the one the fewest
other operators need, so that the buckets stay small. A state looks only into the
buckets of the key facts it holds (walking its set bits, lowest first) and tests the
full preconditions of the operators there. Operators without positive preconditions are
tested in every state. The order is deterministic: by key fact, then operator number.

This class is the pure-Python reference. :func:`successor_generator` gives the compiled
one (``_successors.pyx``, built by ``pip install`` with Cython) when it is built and
:data:`~strips_framework.compiled.PURE_PYTHON_SWITCH` is not set: the same layout over C
arrays, with the same operators in the same order, so searches expand the same states.
"""

from __future__ import annotations

from collections import Counter
from typing import Protocol

from strips_framework.compiled import compiled_module
from strips_framework.grounding.task import GroundTask


class Successors(Protocol):
    """What a state space needs of a successor generator."""

    keep: tuple[int, ...]
    add: tuple[int, ...]
    effects: tuple[tuple[tuple[int, int, int, int], ...], ...] | None

    def applicable(self, state: int) -> list[int]: ...


def successor_generator(task: GroundTask, compiled: bool | None = None) -> Successors:
    """The compiled generator of ``task`` when it is built, else the reference (``compiled``
    as in :func:`~strips_framework.compiled.compiled_module`)."""
    reference = SuccessorGenerator(task)
    module = compiled_module("strips_framework.forward._successors", compiled)
    return reference if module is None else module.SuccessorGenerator(reference, task)


class SuccessorGenerator:
    def __init__(self, task: GroundTask) -> None:
        operators = task.operators
        needed_by = Counter(fact for op in operators for fact in op.pre)
        buckets: dict[int, list[tuple[int, int, int]]] = {}
        unkeyed: list[tuple[int, int, int]] = []
        for index, op in enumerate(operators):
            entry = (index, op.pre_mask, op.pre_neg_mask)
            if op.pre:
                key = min(op.pre, key=lambda fact: (needed_by[fact], fact))
                buckets.setdefault(1 << key, []).append(entry)
            else:
                unkeyed.append(entry)
        self._buckets = {bit: tuple(entries) for bit, entries in buckets.items()}
        self._key_mask = sum(self._buckets)
        self._unkeyed = tuple(unkeyed)
        #: Per operator: the mask of facts it keeps (all but its unconditional deletes),
        #: and its unconditional adds.
        self.keep = tuple(~op.delete_mask for op in operators)
        self.add = tuple(op.add_mask for op in operators)
        #: Per operator: its conditional effects as (condition, negated condition, delete,
        #: add) masks; None when no operator has any, so plain tasks pay nothing for them.
        self.effects: tuple[tuple[tuple[int, int, int, int], ...], ...] | None = None
        if any(op.effects for op in operators):
            self.effects = tuple(
                tuple(
                    (e.condition_mask, e.condition_neg_mask, e.delete_mask, e.add_mask)
                    for e in op.effects
                )
                for op in operators
            )

    def applicable(self, state: int) -> list[int]:
        """The numbers of the operators applicable in ``state``."""
        found = [i for i, pre, neg in self._unkeyed if state & pre == pre and not state & neg]
        buckets = self._buckets
        keys = state & self._key_mask
        while keys:
            bit = keys & -keys
            for i, pre, neg in buckets[bit]:
                if state & pre == pre and not state & neg:
                    found.append(i)
            keys ^= bit
        return found
