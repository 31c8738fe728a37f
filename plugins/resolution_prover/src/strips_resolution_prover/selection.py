"""Given-clause selection: a weight queue and an age queue picked in a fixed ratio.

The weight queue finds short proofs fast; the age queue makes the search fair (every clause
is eventually picked, so saturation means what it says). Unit preference adds a penalty to
the weight of every literal beyond the first, so short clauses go first, which on Horn world
models makes the search behave like backward chaining. (A strict units-first order starves
the longer clauses a proof needs; on the TPTP dev set the penalty 4 did best on tasks with
axioms, none on tasks without: see :func:`unit_preference`.) Ties break on clause id, i.e. derivation order, so the
search never depends on hashing.
"""

from __future__ import annotations

import heapq
from collections import deque

from strips_resolution_prover.pclause import PClause

#: The default penalty per literal beyond the first on tasks with axioms (the TPTP dev
#: set's best).
SOS_UNIT_PREFERENCE = 4

#: Without a set of support, clauses not descended from the negated goal wait longer in the
#: weight queue (factor 2 beat 1 on the TPTP dev set).
NON_GOAL_FACTOR = 2


def unit_preference(configured: int | None, has_axioms: bool) -> int:
    """The penalty per literal beyond the first: the configured one, else by the task.

    With axioms the penalty keeps the search near the goal: under a set of support goal
    clauses shrink to the empty clause one resolved literal at a time, and preferring
    short ones is backward chaining. A task without axioms (all of it negated conjecture,
    as a FOF theorem stated in one formula) is saturated with literal selection, where a
    clause resolves on one selected literal whatever its length and the long clauses are
    the lemmas a proof needs (the conditional forms of associativity in GRP012+5, picked
    too late with the penalty); there we weigh symbols only, as PyRes and E do. (Symbols
    only on every saturation also sped up SYN581-1 and SET830-2, but the proof of
    SYN074+1.q then took 101 given clauses instead of 63, and its answer search, a
    multiple of that, ran past 10 s.)
    """
    if configured is not None:
        return configured
    return SOS_UNIT_PREFERENCE if has_axioms else 0


class ClauseQueue:
    """Unprocessed clauses; a clause leaves both queues when it is picked from one."""

    def __init__(self, pick_given_ratio: int, unit_preference: int) -> None:
        self._ratio = pick_given_ratio
        self._unit_preference = unit_preference
        self._by_weight: list[tuple[int, int, PClause]] = []
        self._by_age: deque[PClause] = deque()
        self._picks = 0
        self._size = 0

    def __len__(self) -> int:
        return self._size

    def push(self, clause: PClause) -> None:
        priority = clause.weight + self._unit_preference * (len(clause.literals) - 1)
        if not clause.sos:
            priority *= NON_GOAL_FACTOR
        heapq.heappush(self._by_weight, (priority, clause.id, clause))
        self._by_age.append(clause)
        self._size += 1

    def pop(self) -> PClause | None:
        """The next given clause, or ``None`` when no clause is waiting."""
        while self._size:
            self._picks += 1
            if self._picks % (self._ratio + 1) == 0:
                clause = self._by_age.popleft()
            else:
                clause = heapq.heappop(self._by_weight)[2]
            if clause.processed:
                continue
            clause.processed = True
            self._size -= 1
            return clause
        return None

    def waiting(self) -> list[PClause]:
        """The clauses not yet picked, in derivation order."""
        return [c for c in self._by_age if not c.processed]
