"""Given-clause selection: weight queues and an age queue picked in a fixed cycle.

The weight queue finds short proofs fast; the age queue makes the search fair (every clause
is eventually picked, so saturation means what it says). In saturation a second weight
queue, by :func:`refined_weight`, prefers clauses whose maximal literals are light, as
E's heuristics mix queues of different weights (:func:`refined_picks`). Unit preference
adds a penalty to the weight of every literal beyond the first, so short clauses go
first, which on Horn world models makes the search behave like backward chaining. (A
strict units-first order starves the longer clauses a proof needs; on the TPTP dev set
the penalty 4 did best on tasks with axioms, none on tasks without: see
:func:`unit_preference`.) Ties break on clause id, i.e. derivation order, so the search
never depends on hashing.
"""

from __future__ import annotations

import heapq
from collections import deque
from collections.abc import Sequence

from strips_framework.logic.clauses import Literal
from strips_framework.logic.terms import ANSWER
from strips_resolution_prover.pclause import PClause, term_weight

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


#: Picks by :func:`refined_weight` per age pick in saturation, after the
#: ``pick_given_ratio`` picks by weight (see :func:`refined_picks`).
SATURATION_REFINED_PICKS = 4


def refined_picks(configured: int | None, saturating: bool) -> int:
    """The picks by refined weight per cycle: the configured number, else
    :data:`SATURATION_REFINED_PICKS` in saturation (literal selection and ordering,
    where a clause is used upon few of its literals) and none under a set of support,
    whose goal clauses resolve on every literal: the planner's attempts on world models
    keep their search, and a TPTP problem's saturation gains (GRP012+5: 332 given
    clauses instead of 1,222, E's ``--auto`` 347; the TPTP dev set as a whole: 16 %
    fewer, every status and answer the same). E's automatic mode mixes such queues
    too, with age and with weights of other kinds."""
    if configured is not None:
        return configured
    return SATURATION_REFINED_PICKS if saturating else 0


def refined_weight(literals: Sequence[Literal]) -> int:
    """A clause's weight with its heaviest literals at 1.5 times the others (after E's
    Refinedweight, which multiplies its maximal literals): under ordered inference a
    clause is used upon its maximal literals, so a clause whose maximal literals are
    light makes light conclusions. The heaviest stand in for the maximal (KBO compares
    weights first): comparing literals in the ordering itself took a fifth of the
    answer search's time in SYN074+1.q, where comparing weights costs nothing. Answer
    literals (the answer search's bookkeeping) weigh nothing. Literals weigh
    :func:`~.pclause.term_weight`, doubled to keep the halves integral."""
    weights = [2 * term_weight(atom) for _, atom in literals if atom[0] != ANSWER]
    if not weights:
        return 0
    heaviest = max(weights)
    return sum(weights) + heaviest // 2 * weights.count(heaviest)


class ClauseQueue:
    """Unprocessed clauses; a clause leaves every queue when it is picked from one.

    A cycle of picks: ``pick_given_ratio`` by weight, then ``refined_picks`` by
    :func:`refined_weight`, then one by age.
    """

    def __init__(self, pick_given_ratio: int, unit_preference: int, refined_picks: int = 0) -> None:
        self._ratio = pick_given_ratio
        self._unit_preference = unit_preference
        self._refined_picks = refined_picks
        self._cycle = pick_given_ratio + refined_picks + 1
        self._by_weight: list[tuple[int, int, PClause]] = []
        self._by_refined: list[tuple[int, int, PClause]] = []
        self._by_age: deque[PClause] = deque()
        self._picks = 0
        self._size = 0

    def __len__(self) -> int:
        return self._size

    def push(self, clause: PClause) -> None:
        penalty = self._unit_preference * (len(clause.literals) - 1)
        factor = 1 if clause.sos else NON_GOAL_FACTOR
        heapq.heappush(self._by_weight, ((clause.weight + penalty) * factor, clause.id, clause))
        if self._refined_picks:
            # The literal penalty at half its scale here: this is the queue for long
            # clauses with light maximal literals (SET830-2: 296 given clauses, 540 at
            # full scale, though LCL077-1 took 293 instead of 242).
            refined = refined_weight(clause.literals) + penalty
            heapq.heappush(self._by_refined, (refined * factor, clause.id, clause))
        self._by_age.append(clause)
        self._size += 1

    def pop(self) -> PClause | None:
        """The next given clause, or ``None`` when no clause is waiting."""
        while self._size:
            self._picks += 1
            turn = self._picks % self._cycle
            if turn == 0:
                clause = self._by_age.popleft()
            elif turn <= self._ratio:
                clause = heapq.heappop(self._by_weight)[2]
            else:
                clause = heapq.heappop(self._by_refined)[2]
            if clause.processed:
                continue
            clause.processed = True
            self._size -= 1
            return clause
        return None

    def waiting(self) -> list[PClause]:
        """The clauses not yet picked, in derivation order."""
        return [c for c in self._by_age if not c.processed]
