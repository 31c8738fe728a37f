"""What a theorem prover is asked and what it answers.

STRIPS asks one kind of question (paper, III.A): does the goal wff G(p) follow from the
world model M, and for which instance p' of its parameters? A prover refutes
``M ∪ ¬G(p)``; the clauses of ¬G(p) are the set of support. When it fails within its
effort bound, the clauses it derived from ¬G(p) are the *uncompleted proof*, from which
the difference extractor computes the node's difference (III.C).
"""

from __future__ import annotations

from typing import ClassVar, Protocol

from attrs import field, frozen

from strips_framework.logic.clauses import Clause
from strips_framework.logic.terms import Param, Term

Answer = tuple[tuple[Param, Term], ...]


@frozen
class ProofTask:
    """One question for a prover.

    ``axioms`` is the world model (or a TPTP problem's axioms); ``negated_goal`` is the set
    of support. ``effort`` bounds the work per attempt in the prover's own unit (for the
    resolution prover: given clauses processed). ``max_answers`` > 1 asks the prover to go
    on after the first refutation and collect distinct parameter bindings. With
    ``unique_names`` distinct constants denote distinct objects, so ``a = b`` is false for
    constants ``a`` and ``b`` (the paper's "predicate evaluation" of equality).
    """

    axioms: tuple[Clause, ...] = field(converter=tuple)
    negated_goal: tuple[Clause, ...] = field(converter=tuple)
    effort: int = 1000
    max_answers: int = 1
    unique_names: bool = False


#: SZS statuses a prover reports (https://tptp.org/TPTP/TPTP/SZSOntology): ``Unsatisfiable``
#: when the clauses were refuted, ``Satisfiable`` when the set of support saturated without
#: a refutation, ``GaveUp`` when the effort bound ran out first.
PROVED, SATURATED, GAVE_UP = "Unsatisfiable", "Satisfiable", "GaveUp"


@frozen
class ProofResult:
    """A prover's answer.

    ``answers`` holds one parameter binding per refutation found (empty unless proved);
    ``uncompleted`` holds the negated goal and its retained descendants when no proof was
    found (empty when proved); ``proof`` lists the clauses of the first refutation, premises
    first, when the prover keeps them.
    """

    status: str
    answers: tuple[Answer, ...] = ()
    uncompleted: tuple[Clause, ...] = ()
    effort_used: int = 0
    proof: tuple[Clause, ...] = ()

    @property
    def proved(self) -> bool:
        return self.status == PROVED


class TheoremProver(Protocol):
    """A prover implementation, registered through ``strips_register_provers``.

    Implementations are attrs classes whose fields are their options (the config passes
    them as keyword arguments); ``name`` is what a config names them by.
    """

    name: ClassVar[str]

    def prove(self, task: ProofTask) -> ProofResult:
        """Try to refute ``task.axioms`` ∪ ``task.negated_goal``."""
        ...
