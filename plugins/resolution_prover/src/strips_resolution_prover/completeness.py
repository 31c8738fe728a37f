"""When an exhausted search shows something: the conditions for claiming ``Satisfiable``.

A given-clause loop that runs out of clauses has *saturated* its clause set under its
calculus. That shows the input satisfiable only if the calculus is refutationally complete
for that input with the restrictions that were active. Claiming it otherwise is the worst
thing a prover can do for STRIPS (a goal that follows is reported not to), so the prover
asks :func:`incompleteness` first and gives up when it names a reason.

The reasons, each a way such a claim has been or could be wrong:

- **discarded clauses** (``max_weight``, ``max_clause_literals``, ``max_term_depth``): a
  refutation may have needed one of them;
- **equality** with the classic calculus: paramodulation that skips variables and is only
  weight-ordered, without equality factoring, and under a set of support, is not complete
  (a FOF puzzle with ``<=>`` and ``=`` was reported CounterSatisfiable that way); a
  superposition calculus (ordered, with equality factoring) would be, and is not built
  yet, so equality problems are decided only by a refutation;
- **a set of support with axioms not known to be satisfiable**: the set-of-support
  strategy is complete only when the clauses outside it are satisfiable (Wos et al.,
  1965). We know that cheaply when every axiom has a positive literal (true in the
  interpretation that makes every atom true) or every one has a negative literal.

A goal with parameters that saturated has no *answer*: no instance with one ground,
Skolem-free binding per parameter follows (paper, III.A), which is what ``Satisfiable``
means for such a goal (``P(a) | P(b)`` entails ``exists x: P(x)`` but no instance of
``P(p)``); :func:`~strips_framework.formats.tptp.szs_status` reports a saturated TPTP
question as ``GaveUp`` for that reason.
"""

from __future__ import annotations

from collections.abc import Sequence

from strips_framework.logic.clauses import Clause
from strips_framework.logic.terms import EQUALITY


def incompleteness(
    axioms: Sequence[Clause],
    *,
    set_of_support: bool,
    uses_equality: bool,
) -> str | None:
    """Why saturation of this task would not show satisfiability, or ``None`` if it would.

    ``set_of_support``: the axioms were kept out of the set of support (never resolved
    with each other); ``uses_equality``: some clause has ``=``. Discarded clauses are
    the caller's to check, since they are known only after the search.
    """
    if uses_equality:
        return "equality without a complete calculus for it"
    if set_of_support and axioms and not _trivially_satisfiable(axioms):
        return "a set of support, with axioms not known to be satisfiable"
    return None


def _trivially_satisfiable(clauses: Sequence[Clause]) -> bool:
    """Whether every atom true in a one-element domain, or every non-equality atom false,
    satisfies every clause (an equation is true in a one-element domain)."""
    return all(any(pos for pos, _ in c.literals) for c in clauses) or all(
        any(not pos and atom[0] != EQUALITY for pos, atom in c.literals) for c in clauses
    )
