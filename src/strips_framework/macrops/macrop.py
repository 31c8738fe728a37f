"""MACROPs: generalized triangle tables with a name, kept in a library.

A library keeps itself small (Fikes, Hart & Nilsson 1972; Minton's utility problem, 1990):
a new MACROP that another one subsumes is not added, and one that the new MACROP subsumes
is dropped. B *subsumes* A when A is an instance of B or of one of B's edited parts: B's
steps map onto A's by a substitution under which B needs no more (its kernel 1 is part of
A's), promises no less (its goal row contains A's) and forbids no more (each of its
Distinct constraints is one of A's or cannot fail).
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator

from strips_framework.logic.terms import Param, Term
from strips_framework.macrops.table import TriangleTable
from strips_framework.records import Record
from strips_framework.worldmodel.simulate import ground_term


class Macrop(Record):
    """A named generalized plan; ``learned_from`` names the problem it was learned on and
    ``example`` the binding that gives back that plan."""

    name: str
    table: TriangleTable
    learned_from: str
    example: dict[Param, Term]

    __slots__ = ("name", "table", "learned_from", "example")
    COMPARED = ("name", "table", "learned_from")

    def __init__(
        self,
        name: str,
        table: TriangleTable,
        learned_from: str = "",
        example: dict[Param, Term] | None = None,
    ) -> None:
        self.name = name
        self.table = table
        self.learned_from = learned_from
        self.example = {} if example is None else example

    def parts(self) -> Iterator[tuple[str, TriangleTable]]:
        """The whole table, then each edited part that differs from it, with names
        ``M`` and ``M/j`` (the part leading to step j)."""
        yield self.name, self.table
        seen = {tuple(map(str, self.table.steps))}
        for last in range(1, self.table.size + 1):
            part = self.table.edited(last)
            key = tuple(map(str, part.steps))
            if key not in seen:
                seen.add(key)
                yield f"{self.name}/{last}", part


def subsumes(general: TriangleTable, special: TriangleTable) -> bool:
    """Whether ``general`` (or one of its edited parts) subsumes ``special``."""
    candidates = [general, *(general.edited(j) for j in range(1, general.size + 1))]
    return any(_instance_of(special, c) for c in candidates)


def _instance_of(special: TriangleTable, general: TriangleTable) -> bool:
    if [s.schema.name for s in special.steps] != [s.schema.name for s in general.steps]:
        return False
    subst: dict | None = {}
    for g, s in zip(general.steps, special.steps):
        for a, b in zip(g.arguments, s.arguments):
            subst = _match_param(a, b, subst)
            if subst is None:
                return False
    # The two tables name their parameters alike (p1, p2, ...): apply ``subst`` in one
    # pass, never chasing a binding into the other table's names.
    needed = {ground_term(a, subst) for a in general.kernel(1)}
    if not needed <= set(special.kernel(1)):
        return False
    if not {*special.goal_row()} <= {ground_term(a, subst) for a in general.goal_row()}:
        return False
    forbidden = {frozenset((d.left, d.right)) for d in special.distinct}
    for d in general.distinct:
        left, right = ground_term(d.left, subst), ground_term(d.right, subst)
        if type(left) is str and type(right) is str and left != right:
            continue
        if frozenset((left, right)) not in forbidden:
            return False
    return True


def _match_param(pattern: Term, target: Term, subst: dict) -> dict | None:
    """Bind ``pattern``'s parameters so that it equals ``target`` (one way)."""
    if type(pattern) is Param:
        bound = subst.get(pattern)
        if bound is None:
            return {**subst, pattern: target}
        return subst if bound == target else None
    if type(pattern) is tuple:
        if type(target) is not tuple or len(pattern) != len(target) or pattern[0] != target[0]:
            return None
        for p, t in zip(pattern[1:], target[1:]):
            subst = _match_param(p, t, subst)
            if subst is None:
                return None
        return subst
    return subst if pattern == target else None


class Library(Record):
    """MACROPs in the order they were learned."""

    macrops: tuple[Macrop, ...]

    __slots__ = ("macrops",)

    def __init__(self, macrops: Iterable[Macrop] = ()) -> None:
        self.macrops = tuple(macrops)

    def added(self, new: Macrop) -> tuple[Library, str]:
        """The library with ``new`` in it, unless another MACROP subsumes it (then the
        library is unchanged); MACROPs that ``new`` subsumes are dropped. Also says what
        happened, for ``strips learn``."""
        for old in self.macrops:
            if subsumes(old.table, new.table):
                return self, f"{new.name} not added: {old.name} subsumes it"
        dropped = [old for old in self.macrops if subsumes(new.table, old.table)]
        kept = [old for old in self.macrops if old not in dropped]
        note = f"{new.name} added ({new.table.size} steps)"
        if dropped:
            note += "; it subsumes " + ", ".join(old.name for old in dropped) + " (dropped)"
        return Library((*kept, new)), note

    def names(self) -> list[str]:
        return [m.name for m in self.macrops]

    def fresh_name(self) -> str:
        taken = set(self.names())
        number = len(self.macrops) + 1
        while f"M{number}" in taken:
            number += 1
        return f"M{number}"

