"""The resolution prover: a DISCOUNT-style given-clause loop with a set of support.

The axioms (world model) are *usable*: indexed from the start and never resolved with each
other. The negated goal is the set of support and waits in the :class:`ClauseQueue`. Each
round picks a given clause, drops it if a retained clause subsumes it, deletes the retained
set-of-support clauses it subsumes, indexes it, and adds its resolvents with the retained
clauses, its factors and (with equality) its paramodulants to the queue. Only processed
clauses are partners, so every inference has a set-of-support premise.

Since usable clauses never change, a :class:`ResolutionSession` imports, simplifies,
factors and indexes M0 once (:class:`_Retained`), and each attempt adds only what is its
own: the model's ADDITIONS and the set of support, in a second layer. A model's deletions
hide M0 clauses by id, so nothing of M0 is copied or walked per attempt (paper, III.D).
Without a set of support the axioms are resolved with each other, which needs them all in
the attempt's own layer; so do equations under unique names, whose instances depend on
the constants of each attempt: those modes have no session speed-up.
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from collections.abc import Set as AbstractSet
from itertools import chain
from typing import ClassVar

from strips_framework.capabilities import (
    ANSWER_LITERALS,
    ANSWERS,
    EFFORT_BOUND,
    EQUALITY,
    QUANTIFIED_AXIOMS,
    SOUND,
    UNCOMPLETED_PROOF,
)
from strips_framework.logic.clauses import Clause, Literal
from strips_framework.logic.terms import ANSWER
from strips_framework.options import Configurable, Option
from strips_framework.worldmodel.proving import (
    GAVE_UP,
    PROVED,
    SATURATED,
    Answer,
    ProofResult,
    ProofTask,
)
from strips_framework.worldmodel.world import InitialModel, WorldModel
from strips_resolution_prover.auto import (
    PRUNED_SHARE,
    SATURATION_SHARE,
    definite_facts,
    is_world_model,
    mentions_equality,
    plan,
)
from strips_resolution_prover.completeness import has_parameter, incompleteness
from strips_resolution_prover.demodulation import Demodulators
from strips_resolution_prover.equality import (
    equality_factors,
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
    Offers,
    eligible,
    factors,
    fewest_partners,
    partner_count,
    resolvents,
)
from strips_resolution_prover.partners import PartnerIndex
from strips_resolution_prover.pclause import (
    PClause,
    from_clause,
    from_fact,
    offset,
    renumber,
    term_depth,
)
from strips_resolution_prover.axiom_relevance import relevant_axioms
from strips_resolution_prover.selection import ClauseQueue, refined_picks, unit_preference
from strips_resolution_prover.subsumption import MatchWork, SubsumptionIndex

#: The values of ``goal_selection`` (see :class:`ResolutionProver`).
GOAL_SELECTIONS = ("every", "fewest", "fewest-shared")
#: Subsumption matcher steps (literal pairings tried) that count as one given clause of
#: the effort bound: about the time a given clause's inferences take.
MATCH_STEPS_PER_GIVEN = 1000


class ResolutionProver(Configurable):
    """Binary resolution with factoring, paramodulation, subsumption and answer extraction.

    Options: ``pick_given_ratio`` weight-queue picks per age-queue pick;
    ``refined_weight_picks`` picks by refined weight (the heaviest literals at 1.5 times)
    after those (``None``: 4 in saturation, none under a set of support,
    :func:`~.selection.refined_picks`); ``unit_preference``
    is the weight-queue penalty per literal beyond the first (0: none; ``None``: 4 on tasks
    with axioms, 0 without, :func:`~.selection.unit_preference`); ``set_of_support``
    false lets axioms be resolved with each other too (goal descendants are still preferred),
    which finds answers that need derived ground facts; ``max_weight`` (symbols, variables 1 and others 2),
    ``max_clause_literals`` and ``max_term_depth`` discard larger conclusions (``None``: no
    limit). A limit that discarded a clause turns saturation into GaveUp, since the search
    was then incomplete. ``schedule`` (the default) is the automatic mode (:mod:`.auto`):
    it picks the set of support, saturation, or saturation then the set of support from
    the task's features, overriding ``set_of_support``; ``schedule = false`` runs the one
    calculus ``set_of_support`` names. ``goal_selection`` is which literals of a goal
    clause are resolved upon: ``"every"`` (each), or, in an attempt over Horn axioms
    without equality whose negated goal is all negative, ``"fewest"`` or
    ``"fewest-shared"`` (:func:`~.inference.fewest_partners`): SLD resolution, as
    complete, and it does not enumerate every subset of a conjunctive goal; other
    attempts resolve on every literal.
    """

    name: ClassVar[str] = "resolution"
    #: With the default options; size limits (``max_clause_literals`` and the like) give
    #: up on what they discard, which keeps the prover sound but not complete.
    capabilities: ClassVar[frozenset[str]] = frozenset(
        {
            EQUALITY,
            QUANTIFIED_AXIOMS,
            ANSWERS,
            ANSWER_LITERALS,
            UNCOMPLETED_PROOF,
            SOUND,
            EFFORT_BOUND,
        }
    )

    options = (
        Option("pick_given_ratio", int, 5, minimum=1, doc="weight-queue picks per age-queue pick"),
        Option("refined_weight_picks", int, None, minimum=0, optional=True,
               doc="picks by refined weight per age-queue pick (unset: by the calculus)"),
        Option("unit_preference", int, None, minimum=0, optional=True,
               doc="weight-queue penalty per literal beyond the first (unset: by the task)"),
        Option("set_of_support", bool, True, doc="resolve axioms only with goal descendants"),
        Option("max_weight", int, 120, minimum=1, optional=True, doc="heavier conclusions dropped"),
        Option("max_clause_literals", int, None, minimum=1, optional=True,
               doc="longer conclusions dropped"),
        Option("max_term_depth", int, None, minimum=0, optional=True, doc="deeper conclusions dropped"),
        Option("schedule", bool, True, doc="pick the calculus from the task's features"),
        Option("goal_selection", str, "every", choices=GOAL_SELECTIONS,
               doc="the goal literals resolved upon (SLD on Horn tasks: 'fewest')"),
    )
    pick_given_ratio: int
    refined_weight_picks: int | None
    unit_preference: int | None
    set_of_support: bool
    max_weight: int | None
    max_clause_literals: int | None
    max_term_depth: int | None
    schedule: bool
    goal_selection: str

    def prove(self, task: ProofTask) -> ProofResult:
        """Refute ``task.axioms`` ∪ ``task.negated_goal`` within ``task.effort`` given clauses."""
        if self.schedule:
            return prove_automatically(self, task)
        initial = InitialModel(task.axioms, rigid=task.rigid)
        return ResolutionSession(self, initial, task.unique_names).prove(
            WorldModel(initial), task.negated_goal, task.effort, task.max_answers
        )

    def open(self, initial: InitialModel, unique_names: bool) -> ResolutionSession:
        """A session on M0, which is imported and indexed here, once."""
        return ResolutionSession(self, initial, unique_names)


def refutes(literals: tuple[Literal, ...]) -> bool:
    """Whether a clause with these literals is a refutation: the empty clause, or only
    answer literals (:data:`~strips_framework.logic.terms.ANSWER`), whose arguments are
    then the answer (the clause is the last of the proof)."""
    return all(positive and atom[0] == ANSWER for positive, atom in literals)


def _positives(clause: Clause) -> int:
    return sum(1 for positive, _ in clause.literals if positive)


def _simplify(
    clause: PClause,
    options: ResolutionProver,
    equality: bool,
    unique_names: bool,
    limits: Limits,
    demodulators: Demodulators | None = None,
) -> PClause | None:
    """Rewrite with the unit equations retained, evaluate equalities and apply the size
    limits; ``None`` deletes the clause."""
    literals = clause.literals
    if equality:
        parents = clause.parents
        if demodulators:
            literals, used = demodulators.rewrite(literals)
            if used:
                parents = (*parents, *used)
                literals = tuple(dict.fromkeys(literals))
                if any((not pos, atom) in literals for pos, atom in literals):
                    return None  # rewriting made a tautology
        evaluated = evaluate(literals, unique_names)
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
    limit = options.max_clause_literals
    depth = options.max_term_depth
    if (limit is not None and len(literals) > limit) or (
        depth is not None and any(term_depth(atom) - 1 > depth for _, atom in literals)
    ):
        limits.discarded = True
        return None
    return clause


class _Retained:
    """Clauses that are partners for given clauses: numbered from ``first_id``, indexed
    for resolution and subsumption, and listed for paramodulation."""

    def __init__(self, first_id: int) -> None:
        self.first_id = first_id
        self.clauses: list[PClause] = []
        self.index = PartnerIndex()
        self.subsumption = SubsumptionIndex()
        self.processed: list[PClause] = []
        self.equational: list[PClause] = []
        self.demodulators = Demodulators()

    def register(self, clause: PClause) -> None:
        clause.id = self.first_id + len(self.clauses)
        self.clauses.append(clause)

    def retain(
        self, clause: PClause, selecting: bool, deletable: bool, ordered: bool = False
    ) -> bool:
        """Index ``clause`` (on the literals :func:`.inference.eligible` allows); whether
        it is a new demodulator."""
        self.processed.append(clause)
        rule = False
        if any(pos and is_equality(atom) for pos, atom in clause.literals):
            self.equational.append(clause)
            rule = self.demodulators.add(clause)
        self.subsumption.add(clause, deletable=deletable)
        for i in eligible(clause.literals, selecting, ordered):
            self.index.add(clause, i)
        return rule


class _Axioms(_Retained):
    """M0 as a session keeps it: its usable clauses (and their factors), with the M0
    clause each came from (``by_origin``), so a model's deletions hide them by id."""

    def __init__(
        self,
        options: ResolutionProver,
        initial: InitialModel,
        unique_names: bool,
        fresh: bool = False,
    ) -> None:
        super().__init__(0)
        self.by_origin: dict[int, list[int]] = {}
        self.refutations: list[PClause] = []
        self.limits = Limits(options.max_weight)
        self.uses_equality = mentions_equality(initial.clauses)
        #: Whether each attempt takes all its axioms afresh (see the module docstring).
        # (Equations in M0 would rewrite clauses whether or not the model hides them; the
        # automatic mode, when a session keeps it, runs each attempt as a task.)
        self.fresh = (
            fresh or options.schedule or not options.set_of_support or self.uses_equality
        )
        #: Saturation shows satisfiability only over axioms known to be satisfiable
        #: (:mod:`.completeness`); M0's verdict is made once, for all its models. Every
        #: clause has a positive literal in ``all_positive`` M0s, and additions keep that.
        self.unknown_satisfiable = incompleteness(
            initial.clauses, set_of_support=True, uses_equality=False
        )
        self.all_positive = all(any(pos for pos, _ in c.literals) for c in initial.clauses)
        self.horn = all(_positives(c) <= 1 for c in initial.clauses)
        if self.fresh:
            return
        for origin, axiom in enumerate(initial.clauses):
            imported = from_fact(axiom) or from_clause(axiom, sos=False)
            if imported is not None:
                self._add(imported, origin, options, unique_names)

    def _add(
        self, clause: PClause, origin: int, options: ResolutionProver, unique_names: bool
    ) -> None:
        simplified = _simplify(clause, options, self.uses_equality, unique_names, self.limits)
        if simplified is None:
            return
        self.register(simplified)
        self.by_origin.setdefault(origin, []).append(simplified.id)
        simplified.processed = True
        if not simplified.literals:
            self.refutations.append(simplified)
            return
        self.retain(simplified, selecting=False, deletable=False)
        if len(simplified.literals) < 2:
            return  # a unit has no factors
        for factor in factors(simplified, self.limits):
            usable = PClause(
                factor.literals, factor.nvars, factor.bindings, sos=False, parents=factor.parents
            )
            self._add(usable, origin, options, unique_names)


class ResolutionSession:
    """The prover opened on one M0 (see the module docstring)."""

    def __init__(self, options: ResolutionProver, initial: InitialModel, unique_names: bool) -> None:
        self.options = options
        self.initial = initial
        self.unique_names = unique_names
        #: In the automatic mode, which M0 clauses are facts if M0 has a world model's
        #: shape: an attempt on a model that is still a world model (:func:`.auto.plan`,
        #: decided from counts, not by walking the model) runs the set of support here.
        self.facts = definite_facts(initial.clauses) if options.schedule else None
        self.fact_count = sum(self.facts) if self.facts is not None else 0
        self.calculus = options
        if self.facts is not None:
            self.calculus = options._replace(schedule=False, set_of_support=True)
        self.axioms = _Axioms(self.calculus, initial, unique_names)
        #: No axioms of its own: the base of an attempt that takes its axioms afresh.
        self.none = _Axioms(self.calculus, InitialModel(()), unique_names, fresh=True)

    def _is_world_model(
        self, hidden: AbstractSet[int], added: Sequence[Clause], negated_goal: Sequence[Clause]
    ) -> bool:
        """:func:`.auto.plan`'s test on the model's visible clauses, from M0's counts."""
        if self.facts is None or mentions_equality(negated_goal):
            return False
        added_facts = definite_facts(added)
        if added_facts is None:
            return False
        visible = len(self.facts) - len(hidden) + len(added)
        facts = self.fact_count - sum(self.facts[i] for i in hidden) + sum(added_facts)
        return visible > 0 and is_world_model(facts, visible)

    def prove(
        self,
        model: WorldModel,
        negated_goal: Sequence[Clause],
        effort: int,
        max_answers: int = 1,
    ) -> ProofResult:
        """Refute the clauses visible in ``model`` ∪ ``negated_goal`` within ``effort``
        given clauses."""
        added = model.added_clauses()
        hidden_m0 = model.hidden()
        if self.options.schedule and not self._is_world_model(hidden_m0, added, negated_goal):
            # The automatic mode's schedule: each attempt is a task of its own.
            task = ProofTask.of_model(model, negated_goal, effort, max_answers, self.unique_names)
            return prove_automatically(self.options, task)
        # Unique names instantiate equations over the constants the visible clauses
        # name, which a model's deletions change: such an attempt takes M0 afresh.
        fresh = self.axioms.fresh or (
            self.unique_names and mentions_equality(chain(negated_goal, added))
        )
        axioms = self.axioms
        if not fresh:
            hidden = {cid for index in hidden_m0 for cid in axioms.by_origin.get(index, ())}
            extra: Sequence[Clause] = added
        else:
            axioms, hidden, extra = self.none, set(), tuple(model.clauses())
        attempt = _Saturation(
            self.calculus,
            axioms,
            hidden,
            extra,
            tuple(negated_goal),
            unique_names=self.unique_names,
            rigid=self.initial.rigid,
            has_axioms=bool(extra) or len(hidden_m0) < len(self.initial.clauses),
        )
        return attempt.run(effort, max_answers)


def _attempt(options: ResolutionProver, task: ProofTask) -> _Saturation:
    """A fresh attempt on ``task`` under one calculus (``options.schedule`` false)."""
    axioms = _Axioms(options, InitialModel(()), task.unique_names, fresh=True)
    return _Saturation(
        options,
        axioms,
        set(),
        task.axioms,
        task.negated_goal,
        unique_names=task.unique_names,
        rigid=task.rigid,
        has_axioms=bool(task.axioms),
    )


def prove_automatically(prover: ResolutionProver, task: ProofTask) -> ProofResult:
    """``task`` under the calculus :func:`.auto.plan` picks (see :mod:`.auto`)."""
    sos = prover._replace(schedule=False, set_of_support=True)
    saturate = prover._replace(schedule=False, set_of_support=False)
    chosen = plan(task.axioms, task.negated_goal)
    if chosen == "set-of-support" or chosen == "saturation" or task.effort < 3:
        calculus = sos if chosen == "set-of-support" else saturate
        result = calculus.prove(task)
        return result._replace(phases=((chosen, result.status, result.effort_used),))
    relevant = relevant_axioms(task.axioms, task.negated_goal)
    pruned = task._replace(axioms=relevant) if len(relevant) < len(task.axioms) else None
    return interleave(task, saturate, sos, pruned)


def interleave(
    task: ProofTask,
    saturate: ResolutionProver,
    sos: ResolutionProver,
    pruned: ProofTask | None = None,
) -> ProofResult:
    """Saturation and the set of support on ``task`` side by side, as if run in parallel
    with :data:`~.auto.SATURATION_SHARE` of the effort for saturation (see :mod:`.auto`);
    with ``pruned`` (the task on its relevant axioms, :mod:`.axiom_relevance`), saturation of
    that too, on :data:`~.auto.PRUNED_SHARE` of the effort, taken from the other two.

    Each attempt keeps its state, so interleaving loses no work: in round ``r`` of
    ``task.effort`` rounds each has had ``r / task.effort`` of its share. The first that
    decides answers, except that the set of support running out of clauses for a goal
    with parameters only says it found no answer (saturation, which derives the ground
    instances a parameter may take (III.A), then goes on with the rest of the effort),
    and that the pruned run saturating says nothing about the whole task. One that
    stops without deciding hands the effort it did not use to the others; if none
    decides, the set of support's result (its uncompleted proof is the difference)
    stands. The effort used is the sum, so the run is as deterministic as each part.
    """
    effort = task.effort
    asks = any(has_parameter(atom) for c in task.negated_goal for _, atom in c.literals)
    attempts = [_attempt(saturate, task), _attempt(sos, task)]
    names = ["saturation", "set-of-support"]
    claims = [True, not asks]
    rest = effort
    if pruned is not None:
        attempts.append(_attempt(saturate, pruned))
        names.append("saturation of the SInE-relevant axioms")
        claims.append(False)
        rest = effort - max(1, int(effort * PRUNED_SHARE))
    share = max(1, min(rest - 1, int(rest * SATURATION_SHARE)))
    bounds = [share, rest - share] + [effort - rest] * (pruned is not None)
    for attempt in attempts:
        attempt.start(task.max_answers)
    live = list(range(len(attempts)))
    for round_ in range(1, effort + 1):
        for i in tuple(live):
            attempt = attempts[i]
            target = bounds[i] if len(live) == 1 else -(-round_ * bounds[i] // effort)
            if not attempt.advance(target) and attempt.effort < bounds[i]:
                continue
            result = attempt.result()
            if result.status == PROVED or (result.status == SATURATED and claims[i]):
                return _schedule_result(result, attempts, names, i)
            live.remove(i)
            _hand_on(bounds[i] - attempt.effort, live, bounds)
            bounds[i] = attempt.effort
        if not live:
            break
    return _schedule_result(attempts[1].result(), attempts, names, None)


def _schedule_result(
    result: ProofResult, attempts: Sequence[_Saturation], names: Sequence[str], decided: int | None
) -> ProofResult:
    """The deciding attempt's result (or the set of support's), with the effort of all
    and each one's phase: the decider's status (the set of support's when none decided),
    ``GaveUp`` for the others."""
    shown = 1 if decided is None else decided
    phases = tuple(
        (name, result.status if i == shown else GAVE_UP, attempt.effort)
        for i, (name, attempt) in enumerate(zip(names, attempts))
    )
    return result._replace(effort_used=sum(a.effort for a in attempts), phases=phases)


def _hand_on(unused: int, live: Sequence[int], bounds: list[int]) -> None:
    """Share the effort an attempt did not use among the ``live`` ones, in proportion to
    their bounds (the remainder to the first), so the bounds still sum to the effort."""
    if not live or unused <= 0:
        return
    total = sum(bounds[i] for i in live)
    given = 0
    for i in live:
        extra = unused * bounds[i] // total if total else 0
        bounds[i] += extra
        given += extra
    bounds[live[0]] += unused - given


class _Saturation:
    """The state of one proof attempt: the session's axioms, less ``hidden``, and a layer
    of its own for ``extra`` (the model's additions; with no set of support, every
    visible clause) and the set of support.

    New clauses get the cheap checks (evaluation, duplicates, unit subsumption); the full
    forward subsumption check runs when a clause is picked, as in DISCOUNT, since most
    queued clauses are never picked.
    """

    def __init__(
        self,
        options: ResolutionProver,
        axioms: _Axioms,
        hidden: AbstractSet[int],
        extra: Sequence[Clause],
        negated_goal: tuple[Clause, ...],
        *,
        unique_names: bool,
        rigid: frozenset[tuple[str, int]],
        has_axioms: bool,
    ) -> None:
        self.options = options
        self.axioms = axioms
        self.hidden = hidden
        self.extra = extra
        self.negated_goal = negated_goal
        self.unique_names = unique_names
        self.rigid = rigid
        #: What goal literals' partners offer (:func:`.inference.fewest_partners`).
        self.offers: Offers = {}
        self.own = _Retained(len(axioms.clauses))
        self.seen: set[tuple[tuple[Literal, ...], tuple]] = set()
        self.answers: list[Answer] = []
        self.max_answers = 1
        self.limits = Limits(options.max_weight)
        self.limits.discarded = axioms.limits.discarded
        self.refutation: PClause | None = None
        # Literal selection needs every clause to be resolved with every other: it is
        # incomplete with a set of support, whose usable clauses never meet each other.
        self.selecting = not options.set_of_support or not has_axioms
        # Ordered resolution too, unless the goal has parameters: an answer search binds
        # each parameter once per derivation (paper, III.A), a restriction of the
        # calculus under which leaving out non-maximal literals would lose answers.
        self.ordered = self.selecting and not any(
            has_parameter(atom) for clause in negated_goal for _, atom in clause.literals
        )
        self.queue = ClauseQueue(
            options.pick_given_ratio,
            unit_preference(options.unit_preference, has_axioms),
            refined_picks(options.refined_weight_picks, self.selecting),
        )
        self.has_axioms = has_axioms
        self.uses_equality = axioms.uses_equality or mentions_equality(
            chain(extra, negated_goal)
        )
        # SLD resolution: Horn axioms (the additions are positive units) and goal clauses
        # without positive literals, so every derived clause is a goal clause too.
        self.sld_possible = (
            not self.selecting
            and not self.uses_equality
            and axioms.horn
            and all(_positives(c) <= 1 for c in extra)
            and not any(_positives(c) for c in negated_goal)
        )
        self.sld = False  # decided by start(), which knows how many answers are wanted
        self._names: tuple[str, ...] | None = None
        self.work = MatchWork()
        self.given_clauses = 0
        self.bound = 0

    # -- the loop -----------------------------------------------------------------------

    def run(self, effort_bound: int, max_answers: int) -> ProofResult:
        self.start(max_answers)
        self.advance(effort_bound)
        return self.result()

    def start(self, max_answers: int) -> None:
        """Import the attempt's own axioms and the negated goal."""
        self.max_answers = max_answers
        # An answer enumeration (model-A*'s applicable instances) is SLD whenever it can
        # be: resolving on every goal literal finds each answer once per order of the
        # literals, 2^k partial proofs of a k-literal precondition (on the robot world
        # 30 of 40 ms a pushto attempt); one literal at a time finds the same answers.
        self.sld = self.sld_possible and (self.options.goal_selection != "every" or max_answers > 1)
        for refutation in self.axioms.refutations:
            if refutation.id not in self.hidden:
                self._record_refutation(refutation)
        for axiom in self.extra:
            imported = from_clause(axiom, sos=False)
            if imported is None:
                continue
            if self.options.set_of_support:
                self._add_axiom(imported)
            else:
                self._add_new(imported)
        for goal in self.negated_goal:
            imported = from_clause(goal, sos=True)
            if imported is not None:
                self._add_new(imported)

    def advance(self, effort_bound: int) -> bool:
        """Pick given clauses until the effort reaches ``effort_bound``; whether the
        attempt is over (enough answers, or nothing left to pick)."""
        self.bound = effort_bound
        while not self._done() and self.effort < effort_bound:
            given = self.queue.pop()
            if given is None:
                return True
            if self._answered(given) or self._subsumed(given):
                given.dead = True
                continue
            if self._simplifiable(given):
                # An equation or unit retained since it was queued simplifies it: the
                # simplified clause is the given clause in its place (as in E; queued
                # again, it would lose its turn).
                given.dead = True
                copy = PClause(
                    given.literals,
                    given.nvars,
                    given.bindings,
                    sos=given.sos,
                    parents=(given.id,),
                    label=given.label,
                )
                simplified = self._prepared(copy)
                if simplified is None:
                    continue
                if self._subsumed(simplified):
                    simplified.dead = True
                    continue
                simplified.processed = True
                given = simplified
            self.given_clauses += 1
            self._process(given)
        return self._done()

    @property
    def effort(self) -> int:
        """Effort spent: given clauses, and subsumption matching at
        :data:`MATCH_STEPS_PER_GIVEN` steps each, so that no part of the loop runs
        unbounded while the count of given clauses stands still. The last given
        clause's matching can carry it past the bound (by at most what
        :data:`~.subsumption.MATCH_BUDGET` allows its tests); it is reported as the
        bound, which a result's ``effort_used`` never exceeds."""
        return min(self.bound, self.given_clauses + self.work.steps // MATCH_STEPS_PER_GIVEN)

    def _done(self) -> bool:
        return len(self.answers) >= self.max_answers

    def _process(self, given: PClause) -> None:
        for victim in self.own.subsumption.subsumed_by(given, self.work):
            victim.dead = True
            self.own.subsumption.note_deleted()
        if self._retain(given):
            self._rewrite_retained(given)
        renamed = tuple((pos, offset(atom, RENAME_OFFSET)) for pos, atom in given.literals)
        if self.sld:
            shared = self.options.goal_selection == "fewest-shared"
            selected = fewest_partners(
                given, renamed, self._partners, shared, self.rigid, self.offers
            )
        else:
            selected = eligible(given.literals, self.selecting, self.ordered)
        for clause in resolvents(given, renamed, selected, self._partners, self.limits):
            self._add_new(clause)
            if self._done():
                return
        if self.sld:
            return  # SLD resolution is complete without factoring
        for clause in factors(given, self.limits, self.selecting):
            self._add_new(clause)
        if self.uses_equality:
            self._equality_inferences(given, renamed)

    def _equality_inferences(self, given: PClause, renamed: tuple[Literal, ...]) -> None:
        for clause in equality_resolvents(given, self.limits):
            self._add_new(clause)
        if self.selecting:  # saturation: the superposition calculus (see .equality)
            for clause in equality_factors(given, self.limits):
                self._add_new(clause)
        for clause in unique_name_instances(given, self._names_known, self.limits):
            self._add_new(clause)
        has_equation = any(pos and is_equality(atom) for pos, atom in given.literals)
        lists = (
            (self.axioms.processed, self.own.processed)
            if has_equation
            else (self.axioms.equational, self.own.equational)
        )
        partners = [c for c in chain(*lists) if c.id not in self.hidden]
        for clause in paramodulants(
            given, renamed, partners, self.limits, saturating=self.selecting, ordered=self.ordered
        ):
            self._add_new(clause)
            if self._done():
                return

    def _names_known(self) -> tuple[str, ...]:
        """The constants equations are instantiated with under unique names (none
        without), found on first use; an attempt with equations under unique names has
        its axioms fresh, all in ``extra``."""
        if self._names is None:
            clauses = chain(self.extra, self.negated_goal)
            self._names = (
                names_of(lit for c in clauses for lit in c.literals) if self.unique_names else ()
            )
        return self._names

    # -- the two layers -------------------------------------------------------------------

    def _partners(self, literal: Literal) -> Iterator[tuple[PClause, int]]:
        hidden = self.hidden
        if hidden:
            for entry in self.axioms.index.partners(literal):
                if entry[0].id not in hidden:
                    yield entry
        else:
            yield from self.axioms.index.partners(literal)
        yield from self.own.index.partners(literal)

    def _rests_on_false_rigid_atom(self, clause: PClause) -> bool:
        """Whether a goal clause has a literal of a rigid predicate that nothing resolves.
        Over Horn axioms it can then never be refuted, in this model or any an operator
        makes (rigid atoms are only deleted), so it is deleted as the paper's evaluation
        deletes a clause (III.C): it is no part of the difference either."""
        renamed: tuple[Literal, ...] | None = None
        for i, (_, atom) in enumerate(clause.literals):
            if (atom[0], len(atom) - 1) in self.rigid:
                if renamed is None:
                    renamed = tuple((pos, offset(a, RENAME_OFFSET)) for pos, a in clause.literals)
                if not partner_count(clause, renamed, i, self._partners, self.offers):
                    return True
        return False

    def _subsumed_by_unit(self, clause: PClause) -> bool:
        return self.axioms.subsumption.is_subsumed_by_unit(
            clause, self.hidden
        ) or self.own.subsumption.is_subsumed_by_unit(clause)

    def _cut_by_units(self, clause: PClause, parents: tuple[int, ...]) -> PClause:
        """``clause`` without the literals whose complements are instances of retained
        unit clauses (E's simplify-reflect, unit deletion): resolving with the unit gives
        the clause without the literal, which subsumes it, so the shorter clause replaces
        it at no loss of completeness. On a theory such as a group's, written with a
        ternary ``product`` and a Skolem function for its totality, most new clauses
        carry a literal that a unit settles (GRP012+5). ``parents``: the premises of the
        result besides the units used (the clause's own, or the clause itself)."""
        bindings = set(clause.bindings)
        kept: list[Literal] = []
        used: list[int] = []
        for positive, atom in clause.literals:
            unit = self._unit_against(not positive, atom, bindings)
            if unit is None and is_equality(atom):  # s = t is t = s
                unit = self._unit_against(not positive, (atom[0], atom[2], atom[1]), bindings)
            if unit is None:
                kept.append((positive, atom))
            else:
                used.append(unit.id)
        if not used:
            return clause
        numbering: dict[int, int] = {}
        literals = tuple((pos, renumber(atom, numbering)) for pos, atom in kept)
        return PClause(
            literals,
            len(numbering),
            clause.bindings,
            sos=clause.sos,
            parents=(*parents, *used),
            label=clause.label,
        )

    def _simplifiable(self, clause: PClause) -> bool:
        """Whether a retained unit equation rewrites ``clause`` or a unit cuts it."""
        if self.uses_equality and self.own.demodulators:
            if self.own.demodulators.rewrite(clause.literals)[1]:
                return True
        return self._cut_by_units(clause, ()) is not clause

    def _unit_against(
        self, positive: bool, atom: tuple, bindings: AbstractSet[object]
    ) -> PClause | None:
        return self.axioms.subsumption.unit_matching(
            positive, atom, bindings, self.hidden
        ) or self.own.subsumption.unit_matching(positive, atom, bindings)

    def _subsumed(self, clause: PClause) -> bool:
        return self.axioms.subsumption.is_subsumed(
            clause, self.work, self.hidden
        ) or self.own.subsumption.is_subsumed(clause, self.work)

    def _clause(self, cid: int) -> PClause:
        first = self.own.first_id
        return self.axioms.clauses[cid] if cid < first else self.own.clauses[cid - first]

    # -- clause bookkeeping ---------------------------------------------------------------

    def _deletable(self, clause: PClause) -> bool:
        """Whether ``clause`` may be replaced: under a set of support, usable clauses
        never are (they are the fixed world model)."""
        return clause.sos or not self.options.set_of_support

    def _retain(self, clause: PClause) -> bool:
        """Make ``clause`` a partner for later given clauses; whether it is a new
        demodulator."""
        return self.own.retain(clause, self.selecting, self._deletable(clause), self.ordered)

    def _rewrite_retained(self, rule: PClause) -> None:
        """Backward demodulation: each retained clause that the new unit equation ``rule``
        rewrites is replaced by its rewritten form, which goes back into the queue (the
        original is dead to every index)."""
        rewriter = Demodulators()
        rewriter.add(rule)
        for clause in self.own.processed:
            if clause.dead or clause is rule or not self._deletable(clause):
                continue
            literals, used = rewriter.rewrite(clause.literals)
            if not used:
                continue
            clause.dead = True
            self.own.subsumption.note_deleted()
            numbering: dict[int, int] = {}
            renumbered = tuple((pos, renumber(atom, numbering)) for pos, atom in literals)
            self._add_new(
                PClause(
                    renumbered,
                    len(numbering),
                    clause.bindings,
                    sos=clause.sos,
                    parents=(clause.id, rule.id),
                    label=clause.label,
                )
            )

    def _add_axiom(self, clause: PClause) -> None:
        simplified = self._simplify(clause)
        if simplified is None:
            return
        self.own.register(simplified)
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
        prepared = self._prepared(clause)
        if prepared is not None:
            self.queue.push(prepared)

    def _prepared(self, clause: PClause) -> PClause | None:
        """``clause`` simplified and registered, or ``None`` if it was deleted or was a
        refutation (recorded)."""
        if clause.parents and not self.options.set_of_support:
            clause.sos = any(self._clause(parent).sos for parent in clause.parents)
        simplified = self._simplify(clause)
        if simplified is None:
            return
        simplified = self._cut_by_units(simplified, simplified.parents)
        if refutes(simplified.literals):
            if simplified.bindings not in self.answers and not self._done():
                self.own.register(simplified)
                self._record_refutation(simplified)
            return None
        signature = (simplified.literals, simplified.bindings)
        if signature in self.seen or self._subsumed_by_unit(simplified):
            return None
        selecting_goals = self.sld and self.options.goal_selection != "every"
        if selecting_goals and self._rests_on_false_rigid_atom(simplified):
            return None
        self.seen.add(signature)
        self.own.register(simplified)
        return simplified

    def _simplify(self, clause: PClause) -> PClause | None:
        return _simplify(
            clause,
            self.options,
            self.uses_equality,
            self.unique_names,
            self.limits,
            self.own.demodulators,
        )

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

    def result(self) -> ProofResult:
        effort = self.effort
        if self.answers:
            return ProofResult(
                PROVED, answers=tuple(self.answers), effort_used=effort, proof=self._proof()
            )
        saturated = not len(self.queue) and not self.limits.discarded
        status = SATURATED if saturated and self._complete() else GAVE_UP
        uncompleted = tuple(c.to_clause() for c in self.own.clauses if c.sos and not c.dead)
        return ProofResult(status, uncompleted=uncompleted, effort_used=effort)

    def _complete(self) -> bool:
        """Whether saturation here shows satisfiability (see :mod:`.completeness`). Over a
        session's M0 the verdict on M0 was made once; hidden clauses are not taken out
        of it, which can only turn a Satisfiable into GaveUp."""
        set_of_support = self.options.set_of_support and self.has_axioms
        if self.axioms.fresh or self.uses_equality:
            reason = incompleteness(
                self.extra,
                set_of_support=set_of_support,
                uses_equality=self.uses_equality,
                unique_names=self.unique_names,
                goal=self.negated_goal,
            )
            return reason is None
        if not set_of_support:
            return True
        # The additions are positive units: an M0 whose clauses all have a positive
        # literal stays satisfiable with them, any other only without them.
        return self.axioms.all_positive or (
            self.axioms.unknown_satisfiable is None and not self.extra
        )

    def _proof(self) -> tuple[Clause, ...]:
        """The refutation's clauses, premises before conclusions (by derivation order)."""
        assert self.refutation is not None
        needed: set[int] = set()
        stack = [self.refutation.id]
        while stack:
            cid = stack.pop()
            if cid not in needed:
                needed.add(cid)
                stack.extend(self._clause(cid).parents)
        return tuple(self._clause(cid).to_clause() for cid in sorted(needed))
