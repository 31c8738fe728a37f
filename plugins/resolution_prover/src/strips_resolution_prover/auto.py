"""The automatic mode: set of support first, then full saturation, in one effort budget.

Which of the two configurations suits a problem shows in the problem's features, but
no cheap feature predicts it well: a set of support finds goal-directed proofs in large
axiom sets at once (MSC002-1) and can show satisfiability only over axioms known to be
satisfiable, while full saturation with literal selection finds proofs that need derived
facts from the axioms (LCL077-1, PUZ031-1) and saturates satisfiable clause sets. So, as
E's ``--auto-schedule`` does with its strategies, the automatic mode runs both, each on a
share of the effort: the first that decides (a proof, or a saturation that shows
satisfiability) answers. Where the axioms are all the clauses there is no set of support
to try, and the whole budget goes to saturation.

The share is :data:`SOS_SHARE` of the effort; the run is as deterministic as each of its
parts, and ``effort_used`` is their sum.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from attrs import evolve

from strips_framework.worldmodel.proving import GAVE_UP, ProofResult, ProofTask

if TYPE_CHECKING:
    from strips_resolution_prover.prover import ResolutionProver

#: The share of the effort the set-of-support run gets; saturation gets the rest.
SOS_SHARE = 1 / 3


def prove_scheduled(prover: ResolutionProver, task: ProofTask) -> ProofResult:
    """Set of support on a share of ``task.effort``, then full saturation on the rest."""
    sos = evolve(prover, schedule=False, set_of_support=True)
    saturate = evolve(prover, schedule=False, set_of_support=False)
    if not task.axioms or task.effort < 2:
        return saturate.prove(task)
    first = sos.prove(evolve(task, effort=max(1, int(task.effort * SOS_SHARE))))
    if first.status != GAVE_UP:
        return first
    second = saturate.prove(evolve(task, effort=task.effort - first.effort_used))
    used = first.effort_used + second.effort_used
    if second.status != GAVE_UP:
        return evolve(second, effort_used=used)
    # Neither decided: the goal-directed run's uncompleted proof is the difference.
    return evolve(first, effort_used=used)
