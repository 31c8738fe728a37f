"""The automatic mode: which calculus a problem gets, chosen from its features.

The two configurations fail on different problems. A set of support (SOS) keeps the
search on the goal, which is what a large fact base needs: saturating a world model
would derive the consequences of every fact. Without literal selection, though, it
resolves every literal of every goal descendant, and on non-Horn axioms with Skolem
functions a thousand given clauses take seconds (KRS005-1, PUZ031-1 on the TPTP dev
set), and it can show satisfiability only over axioms known to be satisfiable and
without equality. Full saturation with literal selection (superposition with equality,
:mod:`.equality`) is complete, finds proofs that need derived facts (LCL077-1), answers
whose parameter bindings must be derived before the paper's rules let a parameter take
them (III.A: never a term with a variable), and saturates satisfiable sets.

So, from the features of the task (:func:`plan`):

- **no axioms** (every clause is support): saturation, there is nothing to keep apart;
- **a world model** (Horn axioms, each with a positive literal, no equality, at least
  half of them ground facts): the set of support on the whole effort. SOS is complete
  there (:mod:`.completeness`), it is backward chaining over the facts, and a session
  keeps M0 indexed for it (STRIPS asks thousands of such questions);
- **otherwise**: saturation on :data:`SATURATION_SHARE` of the effort, then the set of
  support on the rest, as E's ``--auto-schedule`` runs strategies in turn. The first
  that decides answers; if neither does, the goal-directed run's uncompleted proof is the
  difference.

The run is as deterministic as each of its parts, and ``effort_used`` is their sum.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Literal

from attrs import evolve

from strips_framework.logic.clauses import Clause
from strips_framework.logic.terms import EQUALITY
from strips_framework.worldmodel.proving import GAVE_UP, ProofResult, ProofTask

if TYPE_CHECKING:
    from strips_resolution_prover.prover import ResolutionProver

#: The share of the effort saturation gets when it goes first; the set of support gets
#: the rest.
SATURATION_SHARE = 2 / 3

Plan = Literal["saturation", "set-of-support", "schedule"]


def is_world_model(axioms: Sequence[Clause]) -> bool:
    """Whether ``axioms`` look like a STRIPS world model: definite Horn clauses without
    equality, at least half of them ground facts."""
    facts = 0
    for clause in axioms:
        positives = 0
        for positive, atom in clause.literals:
            if atom[0] == EQUALITY:
                return False
            positives += positive
        if positives != 1:
            return False
        facts += len(clause.literals) == 1 and _is_ground(clause.literals[0][1])
    return 2 * facts >= len(axioms)


def _is_ground(atom: tuple) -> bool:
    return all(type(arg) is str or (type(arg) is tuple and _is_ground(arg)) for arg in atom[1:])


def plan(axioms: Sequence[Clause]) -> Plan:
    """The calculus the automatic mode runs on a task with these axioms."""
    if not axioms:
        return "saturation"
    if is_world_model(axioms):
        return "set-of-support"
    return "schedule"


def prove_automatically(prover: ResolutionProver, task: ProofTask) -> ProofResult:
    """``task`` under the calculus :func:`plan` picks (see the module docstring)."""
    sos = evolve(prover, schedule=False, set_of_support=True)
    saturate = evolve(prover, schedule=False, set_of_support=False)
    chosen = plan(task.axioms)
    if chosen == "set-of-support":
        return sos.prove(task)
    if chosen == "saturation" or task.effort < 2:
        return saturate.prove(task)
    first = saturate.prove(evolve(task, effort=max(1, int(task.effort * SATURATION_SHARE))))
    if first.status != GAVE_UP:
        return first
    second = sos.prove(evolve(task, effort=task.effort - first.effort_used))
    # Decided or not, the goal-directed run's result stands; its uncompleted proof is
    # the difference.
    return evolve(second, effort_used=first.effort_used + second.effort_used)
