"""The resolution prover: a DISCOUNT-style given-clause loop with a set of support.

The axioms (world model) are *usable*: indexed from the start and never resolved with each
other. The negated goal is the set of support and waits in the :class:`ClauseQueue`. Each
round picks a given clause, drops it if a retained clause subsumes it, deletes the retained
set-of-support clauses it subsumes, indexes it, and adds its resolvents with the retained
clauses, its factors and (with equality) its paramodulants to the queue. Only processed
clauses are partners, so every inference has a set-of-support premise.
"""

from __future__ import annotations

from typing import ClassVar

from attrs import define, field
from attrs.validators import ge, instance_of, optional

from strips_framework.capabilities import (
    ANSWERS,
    EFFORT_BOUND,
    EQUALITY,
    QUANTIFIED_AXIOMS,
    SOUND,
    UNCOMPLETED_PROOF,
)
from strips_framework.logic.clauses import Clause, Literal
from strips_framework.proving import GAVE_UP, PROVED, SATURATED, Answer, ProofResult, ProofTask
from strips_resolution_prover.auto import prove_scheduled
from strips_resolution_prover.completeness import incompleteness
from strips_resolution_prover.demodulation import Demodulators
from strips_resolution_prover.equality import (
    equality_resolvents,
    evaluate,
    is_equality,
    names_of,
    paramodulants,
    unique_name_instances,
)
from strips_resolution_prover.inference import (
    RENAME_OFFSET,
    Limits,
    eligible,
    factors,
    resolvents,
)
from strips_resolution_prover.pclause import PClause, from_clause, offset, renumber, term_depth
from strips_resolution_prover.selection import ClauseQueue
from strips_resolution_prover.subsumption import SubsumptionIndex

IndexKey = tuple[bool, str, int]


@define(frozen=True)
class ResolutionProver:
    """Binary resolution with factoring, paramodulation, subsumption and answer extraction.

    Options: ``pick_given_ratio`` weight-queue picks per age-queue pick; ``unit_preference``
    is the weight-queue penalty per literal beyond the first (0: none); ``set_of_support``
    false lets axioms be resolved with each other too (goal descendants are still preferred),
    which finds answers that need derived ground facts; ``max_weight`` (symbols, variables 1 and others 2),
    ``max_clause_literals`` and ``max_term_depth`` discard larger conclusions (``None``: no
    limit). A limit that discarded a clause turns saturation into GaveUp, since the search
    was then incomplete. ``schedule`` (the automatic mode, :mod:`.auto`) runs a set of
    support on a third of the effort, then full saturation on the rest; it overrides
    ``set_of_support``.
    """

    name: ClassVar[str] = "resolution"
    #: With the default options; size limits (``max_clause_literals`` and the like) give
    #: up on what they discard, which keeps the prover sound but not complete.
    capabilities: ClassVar[frozenset[str]] = frozenset(
        {EQUALITY, QUANTIFIED_AXIOMS, ANSWERS, UNCOMPLETED_PROOF, SOUND, EFFORT_BOUND}
    )

    pick_given_ratio: int = field(default=5, validator=[instance_of(int), ge(1)])
    unit_preference: int = field(default=4, validator=[instance_of(int), ge(0)])
    set_of_support: bool = field(default=True, validator=instance_of(bool))
    max_weight: int | None = field(default=120, validator=optional([instance_of(int), ge(1)]))
    max_clause_literals: int | None = field(
        default=None, validator=optional([instance_of(int), ge(1)])
    )
    max_term_depth: int | None = field(default=None, validator=optional([instance_of(int), ge(0)]))
    schedule: bool = field(default=False, validator=instance_of(bool))

    def prove(self, task: ProofTask) -> ProofResult:
        """Refute ``task.axioms`` ∪ ``task.negated_goal`` within ``task.effort`` given clauses."""
        if self.schedule:
            return prove_scheduled(self, task)
        return _Saturation(self, task).run()


class _Saturation:
    """The state of one proof attempt.

    New clauses get the cheap checks (evaluation, duplicates, unit subsumption); the full
    forward subsumption check runs when a clause is picked, as in DISCOUNT, since most
    queued clauses are never picked.
    """

    def __init__(self, options: ResolutionProver, task: ProofTask) -> None:
        self.options = options
        self.task = task
        self.clauses: list[PClause] = []
        self.queue = ClauseQueue(options.pick_given_ratio, options.unit_preference)
        self.index: dict[IndexKey, list[tuple[PClause, int]]] = {}
        self.subsumption = SubsumptionIndex()
        self.processed: list[PClause] = []
        self.equational: list[PClause] = []
        self.demodulators = Demodulators()
        self.seen: set[tuple[tuple[Literal, ...], tuple]] = set()
        self.answers: list[Answer] = []
        self.limits = Limits(options.max_weight)
        self.refutation: PClause | None = None
        # Literal selection needs every clause to be resolved with every other: it is
        # incomplete with a set of support, whose usable clauses never meet each other.
        self.selecting = not options.set_of_support or not task.axioms
        self.uses_equality = any(
            is_equality(atom)
            for clause in (*task.axioms, *task.negated_goal)
            for _, atom in clause.literals
        )
        self._names: tuple[str, ...] | None = None

    # -- the loop -----------------------------------------------------------------------

    def run(self) -> ProofResult:
        for axiom in self.task.axioms:
            imported = from_clause(axiom, sos=False)
            if imported is None:
                continue
            if self.options.set_of_support:
                self._add_axiom(imported)
            else:
                self._add_new(imported)
        for goal in self.task.negated_goal:
            imported = from_clause(goal, sos=True)
            if imported is not None:
                self._add_new(imported)
        effort = 0
        while not self._done() and effort < self.task.effort:
            given = self.queue.pop()
            if given is None:
                break
            if self._answered(given) or self.subsumption.is_subsumed(given):
                given.dead = True
                continue
            effort += 1
            self._process(given)
        return self._result(effort)

    def _done(self) -> bool:
        return len(self.answers) >= self.task.max_answers

    def _process(self, given: PClause) -> None:
        for victim in self.subsumption.subsumed_by(given):
            victim.dead = True
            self.subsumption.note_deleted()
        self._retain(given)
        renamed = tuple((pos, offset(atom, RENAME_OFFSET)) for pos, atom in given.literals)
        selected = eligible(given.literals, self.selecting)
        for clause in resolvents(given, renamed, selected, self.index, self.limits):
            self._add_new(clause)
            if self._done():
                return
        for clause in factors(given, self.limits, self.selecting):
            self._add_new(clause)
        if self.uses_equality:
            self._equality_inferences(given, renamed)

    def _equality_inferences(self, given: PClause, renamed: tuple[Literal, ...]) -> None:
        for clause in equality_resolvents(given, self.limits):
            self._add_new(clause)
        for clause in unique_name_instances(given, self._names_known, self.limits):
            self._add_new(clause)
        has_equation = any(pos and is_equality(atom) for pos, atom in given.literals)
        partners = self.processed if has_equation else self.equational
        for clause in paramodulants(given, renamed, list(partners), self.limits):
            self._add_new(clause)
            if self._done():
                return

    def _names_known(self) -> tuple[str, ...]:
        """The task's names under unique names (none without), found on first use."""
        if self._names is None:
            task = self.task
            self._names = (
                names_of(lit for c in (*task.axioms, *task.negated_goal) for lit in c.literals)
                if task.unique_names
                else ()
            )
        return self._names

    # -- clause bookkeeping ---------------------------------------------------------------

    def _register(self, clause: PClause) -> None:
        clause.id = len(self.clauses)
        self.clauses.append(clause)

    def _retain(self, clause: PClause) -> None:
        """Make ``clause`` a partner for later given clauses."""
        self.processed.append(clause)
        if any(pos and is_equality(atom) for pos, atom in clause.literals):
            self.equational.append(clause)
            self.demodulators.add(clause)
        self.subsumption.add(clause, deletable=clause.sos or not self.options.set_of_support)
        for i in eligible(clause.literals, self.selecting):
            positive, atom = clause.literals[i]
            self.index.setdefault((positive, atom[0], len(atom)), []).append((clause, i))

    def _add_axiom(self, clause: PClause) -> None:
        simplified = self._simplify(clause)
        if simplified is None:
            return
        self._register(simplified)
        simplified.processed = True
        if not simplified.literals:
            self._record_refutation(simplified)
            return
        self._retain(simplified)
        # Factors of usable clauses are usable too: resolution is between factors; and so
        # are their instances made false equations by unique names.
        derived = (
            *factors(simplified, self.limits),
            *unique_name_instances(simplified, self._names_known, self.limits),
        )
        for clause in derived:
            self._add_axiom(
                PClause(
                    clause.literals,
                    clause.nvars,
                    clause.bindings,
                    sos=False,
                    parents=clause.parents,
                )
            )

    def _add_new(self, clause: PClause) -> None:
        """Simplify a new set-of-support clause and queue it, or record a refutation."""
        if clause.parents and not self.options.set_of_support:
            clause.sos = any(self.clauses[parent].sos for parent in clause.parents)
        simplified = self._simplify(clause)
        if simplified is None:
            return
        if not simplified.literals:
            if simplified.bindings not in self.answers:
                self._register(simplified)
                self._record_refutation(simplified)
            return
        signature = (simplified.literals, simplified.bindings)
        if signature in self.seen or self.subsumption.is_subsumed_by_unit(simplified):
            return
        self.seen.add(signature)
        self._register(simplified)
        self.queue.push(simplified)

    def _simplify(self, clause: PClause) -> PClause | None:
        """Evaluate equalities and apply the size limits; ``None`` deletes the clause."""
        literals = clause.literals
        if self.uses_equality:
            parents = clause.parents
            if self.demodulators:
                literals, used = self.demodulators.rewrite(literals)
                if used:
                    parents = (*parents, *used)
                    literals = tuple(dict.fromkeys(literals))
                    if any((not pos, atom) in literals for pos, atom in literals):
                        return None  # rewriting made a tautology
            evaluated = evaluate(literals, self.task.unique_names)
            if evaluated is None:
                return None
            if evaluated is not clause.literals:
                numbering: dict[int, int] = {}
                literals = tuple((pos, renumber(atom, numbering)) for pos, atom in evaluated)
                clause = PClause(
                    literals,
                    len(numbering),
                    clause.bindings,
                    sos=clause.sos,
                    parents=parents,
                    label=clause.label,
                )
        limit = self.options.max_clause_literals
        depth = self.options.max_term_depth
        if (limit is not None and len(literals) > limit) or (
            depth is not None and any(term_depth(atom) - 1 > depth for _, atom in literals)
        ):
            self.limits.discarded = True
            return None
        return clause

    def _record_refutation(self, clause: PClause) -> None:
        self.answers.append(clause.bindings)
        if self.refutation is None:
            self.refutation = clause

    def _answered(self, clause: PClause) -> bool:
        """Whether every refutation through ``clause`` would repeat an answer found."""
        if not self.answers:
            return False
        bindings = set(clause.bindings)
        return any(set(answer) <= bindings for answer in self.answers)

    # -- results ------------------------------------------------------------------------

    def _result(self, effort: int) -> ProofResult:
        if self.answers:
            return ProofResult(
                PROVED, answers=tuple(self.answers), effort_used=effort, proof=self._proof()
            )
        saturated = not len(self.queue) and not self.limits.discarded
        status = SATURATED if saturated and self._complete() else GAVE_UP
        uncompleted = tuple(c.to_clause() for c in self.clauses if c.sos and not c.dead)
        return ProofResult(status, uncompleted=uncompleted, effort_used=effort)

    def _complete(self) -> bool:
        """Whether saturation here shows satisfiability (see :mod:`.completeness`)."""
        reason = incompleteness(
            self.task.axioms,
            set_of_support=self.options.set_of_support,
            uses_equality=self.uses_equality,
        )
        return reason is None

    def _proof(self) -> tuple[Clause, ...]:
        """The refutation's clauses, premises before conclusions (by derivation order)."""
        assert self.refutation is not None
        needed: set[int] = set()
        stack = [self.refutation.id]
        while stack:
            cid = stack.pop()
            if cid not in needed:
                needed.add(cid)
                stack.extend(self.clauses[cid].parents)
        return tuple(self.clauses[cid].to_clause() for cid in sorted(needed))
