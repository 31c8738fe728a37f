"""Backward relevance: which facts and operators can matter to the goal.

Relaxed reachability keeps everything that *can* happen; much of it cannot help: in
rovers, say, data about objectives no goal mentions. A fact is relevant when the goal
needs it, or a relevant operator's or axiom's condition does (positively or negated). An
operator is relevant when it adds a relevant fact or deletes one that some relevant
condition needs to be false; an axiom when its head is relevant. Every plan stays a plan
once the other operators are left out of it (they add nothing anyone reads and delete
nothing a negated condition waits for), and states that differ only in irrelevant facts
are the same state to search, as in Fast Downward's translator.

The analysis runs on the grounder's plain records, before the final fact numbering, so
operators are built once.
"""

from __future__ import annotations

from collections.abc import Sequence

from strips_framework.records import Record


class _Keyed(Record):
    """A record that compares and hashes by ``key``, its fields as one tuple in the order
    records are sorted (the grounder sorts them with ``key=attrgetter("key")``). The key
    and its hash are computed once: the grounder puts hundreds of thousands of these in
    sets and sorts them, which plain tuple comparisons keep cheap."""

    key: tuple
    _hash: int

    __slots__ = ("key", "_hash")

    def _keyed(self, key: tuple) -> None:
        self.key = key
        self._hash = hash(key)

    def __eq__(self, other: object) -> bool:
        return type(other) is type(self) and other.key == self.key  # type: ignore[attr-defined]

    def __hash__(self) -> int:
        return self._hash


class RawEffect(_Keyed):
    """A conditional effect before the final numbering."""

    condition: tuple[int, ...]
    condition_neg: tuple[int, ...]
    add: tuple[int, ...]
    delete: tuple[int, ...]

    __slots__ = ("condition", "condition_neg", "add", "delete")

    def __init__(
        self,
        condition: tuple[int, ...],
        condition_neg: tuple[int, ...],
        add: tuple[int, ...],
        delete: tuple[int, ...],
    ) -> None:
        self.condition = condition
        self.condition_neg = condition_neg
        self.add = add
        self.delete = delete
        self._keyed((condition, condition_neg, add, delete))


class RawOperator(_Keyed):
    """A ground operator before the final numbering (fields in the order operators are
    sorted)."""

    name: str
    pre: tuple[int, ...]
    pre_neg: tuple[int, ...]
    add: tuple[int, ...]
    delete: tuple[int, ...]
    cost: int
    effects: tuple[RawEffect, ...]

    __slots__ = ("name", "pre", "pre_neg", "add", "delete", "cost", "effects")

    def __init__(
        self,
        name: str,
        pre: tuple[int, ...],
        pre_neg: tuple[int, ...],
        add: tuple[int, ...],
        delete: tuple[int, ...],
        cost: int,
        effects: tuple[RawEffect, ...] = (),
    ) -> None:
        self.name = name
        self.pre = pre
        self.pre_neg = pre_neg
        self.add = add
        self.delete = delete
        self.cost = cost
        self.effects = effects
        self._keyed((name, pre, pre_neg, add, delete, cost, tuple([e.key for e in effects])))


class RawAxiom(_Keyed):
    """A ground axiom before the final numbering, fields in sorting order."""

    stratum: int
    head: int
    body: tuple[int, ...]
    body_neg: tuple[int, ...]

    __slots__ = ("stratum", "head", "body", "body_neg")

    def __init__(
        self, stratum: int, head: int, body: tuple[int, ...], body_neg: tuple[int, ...]
    ) -> None:
        self.stratum = stratum
        self.head = head
        self.body = body
        self.body_neg = body_neg
        self._keyed((stratum, head, body, body_neg))


def relevant(
    goal: tuple[int, ...], operators: Sequence[RawOperator], axioms: Sequence[RawAxiom]
) -> tuple[set[int], list[int]]:
    """The relevant facts and the indices of the relevant operators.

    A worklist of ``(fact, polarity)`` pairs: a fact needed true makes the operators that
    add it (and the axioms deriving it) relevant, a fact needed false those that delete
    it (and its axioms); a relevant operator or axiom needs its own conditions. Those of
    an operator include the conditions of all its conditional effects, relevant or not:
    an effect kept for what it adds must not fire more often for what it deletes."""
    adders: dict[int, list[int]] = {}
    deleters: dict[int, list[int]] = {}
    for index, op in enumerate(operators):
        for fact in op.add:
            adders.setdefault(fact, []).append(index)
        for fact in op.delete:
            deleters.setdefault(fact, []).append(index)
        for effect in op.effects:
            for fact in effect.add:
                adders.setdefault(fact, []).append(index)
            for fact in effect.delete:
                deleters.setdefault(fact, []).append(index)
    by_head: dict[int, list[RawAxiom]] = {}
    for axiom in axioms:
        by_head.setdefault(axiom.head, []).append(axiom)
    needed: tuple[set[int], set[int]] = (set(), set())  # needed false, needed true
    chosen: set[int] = set()
    todo = [(fact, True) for fact in goal]
    while todo:
        fact, polarity = todo.pop()
        if fact in needed[polarity]:
            continue
        needed[polarity].add(fact)
        conditions = [(axiom.body, axiom.body_neg) for axiom in by_head.get(fact, ())]
        for index in (adders if polarity else deleters).get(fact, ()):
            if index not in chosen:
                chosen.add(index)
                op = operators[index]
                conditions.append((op.pre, op.pre_neg))
                conditions.extend((e.condition, e.condition_neg) for e in op.effects)
        for positive, negative in conditions:
            todo.extend((condition, True) for condition in positive)
            todo.extend((condition, False) for condition in negative)
    return needed[True] | needed[False], sorted(chosen)
