"""What a theorem prover is asked and what it answers.

STRIPS asks one kind of question (paper, III.A): does the goal wff G(p) follow from the
world model M, and for which instance p' of its parameters? A prover refutes
``M ∪ ¬G(p)``; the clauses of ¬G(p) are the set of support. When it fails within its
effort bound, the clauses it derived from ¬G(p) are the *uncompleted proof*, from which
the difference extractor computes the node's difference (III.C).

A search asks that question about thousands of world models that all share one M0 and
differ from it by a few ADDITIONS and DELETIONS (III.D). So a prover is *opened* once per
problem on M0 (:meth:`TheoremProver.open`), which validates, clausifies and indexes M0
once, and the :class:`ProverSession` it returns is asked about world models: it sees a
model as M0 with its additions made visible and its deletions (and the derived clauses
resting on them) hidden, without copying M0. A one-off question (a TPTP problem, the
conformance kit) is a :class:`ProofTask`, answered by :meth:`TheoremProver.prove`.
A prover that implements only ``prove`` still works: :func:`open_session` wraps it in a
:class:`TaskSession`, which hands it each model as a fresh task (correct, but each attempt
then costs time linear in |M0|).
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from typing import ClassVar, Protocol

from strips_framework.logic.clauses import Clause
from strips_framework.logic.terms import Param, Term
from strips_framework.records import Record
from strips_framework.worldmodel.world import InitialModel, WorldModel

Answer = tuple[tuple[Param, Term], ...]


def check_clauses(what: str, clauses: Iterable[object]) -> None:
    """Refuse a malformed clause (``TypeError``/``ValueError`` naming ``what[number]``)."""
    for number, clause in enumerate(clauses, start=1):
        if not isinstance(clause, Clause):
            raise TypeError(f"{what}[{number}] must be a Clause, not {type(clause).__name__}")
        problem = _malformed(clause)
        if problem:
            raise ValueError(f"{what}[{number}] ({clause!r}): {problem}")


def _at_least_one(name: str, value: object) -> int:
    """``value`` when it is an int >= 1; else the ``TypeError``/``ValueError`` naming it."""
    if not isinstance(value, int):
        raise TypeError(f"'{name}' must be an int (got {value!r}, a {type(value).__name__})")
    if value < 1:
        raise ValueError(f"'{name}' must be >= 1: {value}")
    return value


def _malformed(clause: Clause) -> str | None:
    """What is wrong with a clause's literals, or ``None``. Not cached: equal clauses may
    differ in type (``1 == True``), and checking costs about 2% of a small proof."""
    for literal in clause.literals:
        if not (isinstance(literal, tuple) and len(literal) == 2 and type(literal[0]) is bool):
            return f"a literal must be a pair (positive: bool, atom), got {literal!r}"
        atom = literal[1]
        if type(atom) is not tuple or not atom or type(atom[0]) is not str or not atom[0]:
            return f"an atom must be a tuple (predicate, *args), got {atom!r}"
        bad = next((t for arg in atom[1:] for t in _bad_terms(arg)), None)
        if bad is not None:
            return (
                f"{bad!r} in {atom!r} is not a term (expected a variable int >= 0, a "
                "constant str, a Param or a tuple (functor, *args))"
            )
    return None


def _bad_terms(term: object) -> Iterable[object]:
    if type(term) is tuple:
        if not term or type(term[0]) is not str:
            yield term
        else:
            for arg in term[1:]:
                yield from _bad_terms(arg)
    elif not (type(term) is str and term or type(term) is Param or type(term) is int and term >= 0):
        yield term


class ProofTask(Record):
    """One question for a prover.

    ``axioms`` is the world model (or a TPTP problem's axioms); ``negated_goal`` is the set
    of support. ``effort`` bounds the work per attempt in the prover's own unit (for the
    resolution prover: given clauses processed). ``max_answers`` > 1 asks the prover to go
    on after the first refutation and collect distinct parameter bindings. With
    ``unique_names`` distinct constants denote distinct objects, so ``a = b`` is false for
    constants ``a`` and ``b`` (the paper's "predicate evaluation" of equality).
    ``rigid`` names predicates, as ``(name, arity)``, whose atoms no operator can make true
    (:attr:`~strips_framework.worldmodel.world.InitialModel.rigid`): the asker's hint on
    which goal literals are not worth leaving in an uncompleted proof. A prover may use it
    to order its search (the resolution prover binds variables through them first); it
    never changes whether a goal is provable.

    A malformed task is refused here (``TypeError``/``ValueError`` naming the clause and
    what was expected), so no prover ever sees one.
    """

    axioms: tuple[Clause, ...]
    negated_goal: tuple[Clause, ...]
    effort: int
    max_answers: int
    unique_names: bool
    rigid: frozenset[tuple[str, int]]

    __slots__ = ("axioms", "negated_goal", "effort", "max_answers", "unique_names", "rigid")

    def __init__(
        self,
        axioms: Iterable[Clause],
        negated_goal: Iterable[Clause],
        effort: int = 1000,
        max_answers: int = 1,
        unique_names: bool = False,
        rigid: Iterable[tuple[str, int]] = frozenset(),
    ) -> None:
        self.axioms = tuple(axioms)
        check_clauses("ProofTask.axioms", self.axioms)
        self.negated_goal = tuple(negated_goal)
        check_clauses("ProofTask.negated_goal", self.negated_goal)
        self.effort = _at_least_one("effort", effort)
        self.max_answers = _at_least_one("max_answers", max_answers)
        if not isinstance(unique_names, bool):
            raise TypeError(f"'unique_names' must be a bool (got {unique_names!r})")
        self.unique_names = unique_names
        self.rigid = frozenset(rigid)

    @classmethod
    def of_model(
        cls,
        model: WorldModel,
        negated_goal: Sequence[Clause],
        effort: int,
        max_answers: int = 1,
        unique_names: bool = False,
    ) -> ProofTask:
        """The fresh task that a session's ``prove(model, ...)`` must answer like: the
        clauses visible in ``model`` are its axioms, its M0's rigid predicates its hint."""
        return cls(
            tuple(model.clauses()), negated_goal, effort, max_answers, unique_names,
            model.initial.rigid,
        )


#: SZS statuses a prover reports (https://tptp.org/TPTP/TPTP/SZSOntology): ``Unsatisfiable``
#: when the clauses were refuted, ``Satisfiable`` when the set of support saturated without
#: a refutation, ``GaveUp`` when the effort bound ran out first.
PROVED, SATURATED, GAVE_UP = "Unsatisfiable", "Satisfiable", "GaveUp"


class ProofResult(Record):
    """A prover's answer.

    ``answers`` holds one parameter binding per refutation found (empty unless proved);
    ``uncompleted`` holds the negated goal and its retained descendants when no proof was
    found (empty when proved); ``proof`` lists the clauses of the first refutation, premises
    first, when the prover keeps them. ``phases`` says what a prover that schedules
    several calculi ran, as ``(calculus, status, effort used)``, for reports such as
    ``strips prove --json`` (empty for a prover with one calculus).
    """

    status: str
    answers: tuple[Answer, ...]
    uncompleted: tuple[Clause, ...]
    effort_used: int
    proof: tuple[Clause, ...]
    phases: tuple[tuple[str, str, int], ...]

    __slots__ = ("status", "answers", "uncompleted", "effort_used", "proof", "phases")

    def __init__(
        self,
        status: str,
        answers: tuple[Answer, ...] = (),
        uncompleted: tuple[Clause, ...] = (),
        effort_used: int = 0,
        proof: tuple[Clause, ...] = (),
        phases: tuple[tuple[str, str, int], ...] = (),
    ) -> None:
        self.status = status
        self.answers = answers
        self.uncompleted = uncompleted
        self.effort_used = effort_used
        self.proof = proof
        self.phases = phases

    @property
    def proved(self) -> bool:
        return self.status == PROVED


class ProverSession(Protocol):
    """A prover opened on one M0, asked about the world models built on it.

    ``prove(model, negated_goal, effort, max_answers)`` answers exactly what
    ``prover.prove(ProofTask.of_model(model, negated_goal, effort, max_answers,
    unique_names))`` would (the conformance kit checks this over long random sequences of
    models); only its cost may differ. ``model.initial`` is always the M0 the session was
    opened on.
    """

    def prove(
        self,
        model: WorldModel,
        negated_goal: Sequence[Clause],
        effort: int,
        max_answers: int = 1,
    ) -> ProofResult:
        """Try to refute the clauses visible in ``model`` ∪ ``negated_goal``."""
        ...


class TheoremProver(Protocol):
    """A prover implementation, registered through ``strips_register_provers``.

    Implementations declare their options (:mod:`strips_framework.options`; the config
    passes them as keyword arguments); ``name`` is what a config
    names them by. ``open`` is
    optional (see :func:`open_session`); a prover that can index M0 once implements it.
    """

    name: ClassVar[str]

    def prove(self, task: ProofTask) -> ProofResult:
        """Try to refute ``task.axioms`` ∪ ``task.negated_goal``."""
        ...


def open_session(prover: TheoremProver, initial: InitialModel, unique_names: bool) -> ProverSession:
    """A session of ``prover`` on M0: its own (``prover.open``) if it has one, else a
    :class:`TaskSession`. M0's clauses are validated here, once."""
    check_clauses("M0", initial.clauses)
    opener = getattr(prover, "open", None)
    if opener is None:
        return TaskSession(prover, unique_names)
    session: ProverSession = opener(initial, unique_names)
    return session


class TaskSession:
    """The adapter for a prover written for one :class:`ProofTask` at a time: each model
    becomes a fresh task over its visible clauses."""

    def __init__(self, prover: TheoremProver, unique_names: bool) -> None:
        self.prover = prover
        self.unique_names = unique_names

    def prove(
        self,
        model: WorldModel,
        negated_goal: Sequence[Clause],
        effort: int,
        max_answers: int = 1,
    ) -> ProofResult:
        task = ProofTask.of_model(model, negated_goal, effort, max_answers, self.unique_names)
        return self.prover.prove(task)
