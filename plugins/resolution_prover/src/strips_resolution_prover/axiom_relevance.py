"""Axiom relevance: the axioms a goal can reach through its symbols (SInE).

Set theories and other libraries state many definitions of which a conjecture needs a
few; saturating all of them buries the proof (SET018+4: pairs and singletons among
power sets, unions, sums and products). Hoder and Voronkov's SInE selection, which E and
Vampire offer as a preprocessing step, keeps an axiom when one of its *rarest* symbols
(counted over the axioms) is reached from the goal, then follows the symbols of the
axioms kept: ``subset`` is reached from ``equal_set``'s definition, but the definition
of ``power_set`` is triggered only by ``power_set``, which nothing reached names.

An axiom here is a formula: clauses with the same non-empty ``label`` (the clauses a
TPTP formula was clausified into) go together, other clauses stand alone. Skolem
symbols (which clausification invents, one formula's own) and equality trigger nothing.

Dropping axioms is sound for proofs, not for saturation: a proof from some axioms is
one from all, while a subset that saturates says nothing, so the automatic mode uses a
run on the relevant axioms only for refutations (:func:`~.prover.interleave`).
"""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Iterator, Sequence

from strips_framework.logic.clauses import Clause
from strips_framework.logic.terms import EQUALITY, SKOLEM_PREFIX, Term

#: A symbol triggers an axiom when it occurs in at most this many times as many axioms
#: as the axiom's rarest symbol does (SInE's tolerance; 1: only its rarest symbols).
TOLERANCE = 1.0


def relevant_axioms(axioms: Sequence[Clause], negated_goal: Sequence[Clause]) -> list[Clause]:
    """The axioms SInE selects for the goal, in their order."""
    groups: dict[object, list[int]] = defaultdict(list)
    for i, clause in enumerate(axioms):
        groups[clause.label or i].append(i)
    members = list(groups.values())
    symbols = [{s for i in group for s in _symbols(axioms[i])} for group in members]
    occurrences: dict[object, int] = defaultdict(int)
    for found in symbols:
        for symbol in found:
            occurrences[symbol] += 1
    triggers: dict[object, list[int]] = defaultdict(list)
    for g, found in enumerate(symbols):
        if found:
            rarest = min(occurrences[s] for s in found)
            for symbol in found:
                if occurrences[symbol] <= TOLERANCE * rarest:
                    triggers[symbol].append(g)
    reached = {s for clause in negated_goal for s in _symbols(clause)}
    frontier = list(reached)
    kept = {g for g, found in enumerate(symbols) if not found}  # symbol-free: keep
    while frontier:
        for g in triggers.get(frontier.pop(), ()):
            if g not in kept:
                kept.add(g)
                fresh = symbols[g] - reached
                reached |= fresh
                frontier.extend(fresh)
    chosen = sorted(i for g in kept for i in members[g])
    return [axioms[i] for i in chosen]


def _symbols(clause: Clause) -> Iterator[tuple[str, int]]:
    for _, atom in clause.literals:
        if atom[0] != EQUALITY:
            yield atom[0], len(atom) - 1
        for arg in atom[1:]:
            yield from _term_symbols(arg)


def _term_symbols(term: Term) -> Iterator[tuple[str, int]]:
    if type(term) is str:
        if not term.startswith(SKOLEM_PREFIX):
            yield term, 0
    elif type(term) is tuple:
        if not term[0].startswith(SKOLEM_PREFIX):
            yield term[0], len(term) - 1
        for arg in term[1:]:
            yield from _term_symbols(arg)
