"""When an exhausted search shows something: the conditions for claiming ``Satisfiable``.

A given-clause loop that runs out of clauses has *saturated* its clause set under its
calculus. That shows the input satisfiable only if the calculus is refutationally complete
for that input with the restrictions that were active. Claiming it otherwise is the worst
thing a prover can do for STRIPS (a goal that follows is reported not to), so the prover
asks :func:`incompleteness` first and gives up when it names a reason.

The reasons, each a way such a claim has been or could be wrong:

- **discarded clauses** (``max_weight``, ``max_clause_literals``, ``max_term_depth``): a
  refutation may have needed one of them;
- **equality under a set of support**: there paramodulation skips variable sides and
  equality factoring, and axioms are never paramodulated into each other, which is not
  complete (a FOF puzzle with ``<=>`` and ``=`` was reported CounterSatisfiable that
  way). Without a set of support the calculus is superposition (:mod:`.equality`), which
  is complete, so such a saturation is claimed, except
- **equality under unique names**: the unique-names axioms ``c != d`` are not clauses of
  the search but evaluation and instantiation (:mod:`.equality`), so no completeness
  theorem covers the combination, and
- **equality with parameters**: a parameter is a constant that a proof may bind, only to
  what III.A allows; superposition's completeness says nothing about such bindings;
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
from strips_framework.logic.terms import EQUALITY, Param, Term


def incompleteness(
    axioms: Sequence[Clause],
    *,
    set_of_support: bool,
    uses_equality: bool,
    unique_names: bool = False,
    goal: Sequence[Clause] = (),
) -> str | None:
    """Why saturation of this task would not show satisfiability, or ``None`` if it would.

    ``set_of_support``: there were axioms and they were kept out of the set of support
    (never resolved with each other); ``uses_equality``: some clause has ``=``; ``goal``:
    the negated goal, looked at for parameters. Discarded clauses are the caller's to check, since they are
    known only after the search.
    """
    if uses_equality:
        if set_of_support:
            return "equality under a set of support"
        if unique_names:
            return "equality under unique names"
        if any(has_parameter(atom) for c in goal for _, atom in c.literals):
            return "equality with parameters"
    if set_of_support and axioms and not _trivially_satisfiable(axioms):
        return "a set of support, with axioms not known to be satisfiable"
    return None


def has_parameter(term: Term) -> bool:
    if type(term) is tuple:
        return any(has_parameter(arg) for arg in term[1:])
    return type(term) is Param


def _trivially_satisfiable(clauses: Sequence[Clause]) -> bool:
    """Whether every atom true in a one-element domain, or every non-equality atom false,
    satisfies every clause (an equation is true in a one-element domain)."""
    return all(any(pos for pos, _ in c.literals) for c in clauses) or all(
        any(not pos and atom[0] != EQUALITY for pos, atom in c.literals) for c in clauses
    )
