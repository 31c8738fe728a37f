"""The builtin difference extractor: the uncompleted proof, edited (III.C).

The paper takes as the difference "the set of clauses that form the negation of the goal
wff, plus all of their descendants, less any clauses eliminated by editing strategies", and
notes that a very large one may be cut down heuristically. The prover has already removed
subsumed and evaluated clauses; this extractor drops duplicates and keeps the smallest
clauses (those closest to completing the proof) when there are more than ``max_clauses``.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import ClassVar

from strips_framework.capabilities import UNCOMPLETED_PROOF, Requirement
from strips_framework.logic.clauses import Clause
from strips_framework.means_ends.node import Difference
from strips_framework.options import Configurable, Option
from strips_framework.worldmodel.proving import ProofResult


class UncompletedProofDifference(Configurable):
    """The negated goal and its descendants, smallest first, at most ``max_clauses``."""

    name: ClassVar[str] = "uncompleted-proof"
    capabilities: ClassVar[frozenset[str]] = frozenset()
    requires: ClassVar[tuple[Requirement, ...]] = (
        Requirement("prover", UNCOMPLETED_PROOF, "without it a difference is just the "
                    "negated goal", strict=False),
    )
    options = (
        Option("max_clauses", int, 60, minimum=0, exclusive_minimum=True,
               doc="the difference's clauses kept, smallest first"),
    )
    max_clauses: int

    def extract(self, result: ProofResult, negated_goal: Sequence[Clause]) -> Difference:
        clauses = result.uncompleted or tuple(negated_goal)
        unique = list(dict.fromkeys(c for c in clauses if c.literals))
        # sorted() is stable: among clauses of one size, derivation order decides.
        unique.sort(key=lambda c: len(c.literals))
        return Difference(unique[: self.max_clauses], negated_goal)
