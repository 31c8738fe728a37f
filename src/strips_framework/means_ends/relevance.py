"""The builtin relevance filter: operators whose add lists continue the proof (III.C).

Two steps, as in the paper. Candidates are the schemata with an add-list atom whose
predicate occurs negated in a difference clause. Each add-list atom of a candidate is then
resolved against each such literal; every resolvent yields one relevant instance, with the
unifier applied to the schema's parameters. ``goto(m, n)`` against ``~ATR(a) | ~ATR(b)``
gives ``goto(m, a)`` (resolvent ``~ATR(b)``) and ``goto(m, b)`` (resolvent ``~ATR(a)``).

Instances are ranked by resolvent size, since an instance that leaves less of the clause
to prove continues the proof further; among equals, instances that would delete fewer of
the facts the proof already rests on come first. The paper leaves the order of candidates
open; this one keeps STRIPS from undoing a goal it has just achieved (after
``pushto(BOX1, BOX2)``, ``pushto(BOX3, BOX2)`` is preferred to ``pushto(BOX2, BOX3)``,
which would delete ``NEXTTO(BOX1, BOX2)``).
"""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Iterator, Sequence
from functools import cache
from typing import ClassVar

from strips_framework.logic.clauses import Clause, Literal
from strips_framework.logic.formulas import And, Atomic, Exists, Formula, Var, conjuncts
from strips_framework.logic.terms import (
    EQUALITY,
    Atom,
    Param,
    Term,
    is_ground,
    params_of,
    variables_of,
)
from strips_framework.logic.unify import substitute, unify
from strips_framework.means_ends.node import Difference, RelevantInstance
from strips_framework.options import Configurable, Option
from strips_framework.records import Record
from strips_framework.worldmodel.fact_join import facts_join
from strips_framework.worldmodel.operators import OperatorInstance, may_delete
from strips_framework.worldmodel.problem import OperatorSchema
from strips_framework.worldmodel.world import InitialModel, WorldModel

#: Schema parameters are renamed to this tag while unifying, so they never meet the goal's
#: own parameters (which carry tag 0: preconditions are built from the schemata).
_RENAMED = 1


class AddListRelevance(Configurable):
    """Relevant instances from resolving add-list atoms against difference clauses.

    An instance is dropped when a parameter that only its effects mention (not its
    precondition) stays unbound or is bound to another operator's parameter: applying it
    would need a value that neither this resolution nor the precondition proof provides.
    It is also dropped when its precondition can never hold: a conjunct (nested
    conjunctions flattened) is a ground atom
    of a *rigid* predicate (one no operator adds and no rule of the model concludes) that
    is not a fact of the model. Facts of rigid predicates can only be deleted, so such an
    atom never becomes true (``pushto(ROBOT, BOX2)`` needs ``PUSHABLE(ROBOT)``).

    ``rank = "cost"`` ranks instances by what choosing them will cost to achieve: the
    resolvent's literals (what is left of the difference) plus the atoms of the
    instance's precondition that no fact of the model matches (what its subgoal must
    achieve; atoms of predicates an axiom concludes are not counted, a fact index cannot
    tell whether they hold). ``"resolvent"`` (the default, which gives the paper's node
    counts) ranks by the resolvent alone. With the relaxed-plan evaluator on depot 03,
    "cost" takes 1,146 nodes where "resolvent" stops at the 10,000-node limit.

    ``rigid_join = true`` drops an instance whose rigid conjuncts with parameters left
    unbound have no joint match among M0's facts (see :meth:`AddListIndex._never_applicable`).
    Off by default: with the paper's evaluator it changes the searches on elevators
    (docs/means-ends.md, "Rigid atoms with unbound parameters").
    """

    name: ClassVar[str] = "add-list"
    capabilities: ClassVar[frozenset[str]] = frozenset()

    options = (
        Option("rank", str, "resolvent", choices=("resolvent", "cost"),
               doc="order relevant instances by the resolvent alone, or by what achieving them costs"),
        Option("rigid_join", bool, False,
               doc="also drop instances whose rigid precondition atoms with unbound "
               "parameters no binding maps onto M0's facts at once"),
        Option("model_bindings", bool, False,
               doc="bind the parameters of an instance that the model's facts allow one "
               "value for (the crate on the pallet a lift is to clear)"),
    )
    rank: str
    rigid_join: bool
    model_bindings: bool

    def for_problem(
        self, operators: Sequence[OperatorSchema], initial: InitialModel
    ) -> AddListIndex:
        """The add-list index of one problem, built once, M0's rigid predicates and
        those its rules conclude."""
        concluded = frozenset(
            (atom[0], len(atom) - 1)
            for clause in initial.clauses
            if not clause.is_unit
            for positive, atom in clause.literals
            if positive
        )
        return AddListIndex(
            _add_atoms_by_predicate(operators), initial.rigid, concluded, self.rank == "cost",
            WorldModel(initial) if self.rigid_join else None, self.model_bindings,
        )


class AddListIndex(Record):
    """:class:`AddListRelevance` for one problem: candidates by the predicate they add,
    and the rigid predicates of its M0 (only deleted, never added or concluded, so a
    model's rigid facts are M0's less its deletions). ``unmatched`` remembers, by the
    rigid precondition atoms of an instance left with unbound parameters, whether no
    binding maps them onto M0's facts at once: then none maps them onto any model's,
    and instances of many differences share the answer."""

    by_predicate: dict[tuple[str, int], list[tuple[OperatorSchema, dict[Param, Param], Atom]]]
    rigid: frozenset[tuple[str, int]]
    concluded: frozenset[tuple[str, int]]
    by_cost: bool
    root: WorldModel | None
    model_bindings: bool
    unmatched: dict[tuple[Atom, ...], bool]
    settled: dict[tuple[WorldModel, OperatorInstance, bool], OperatorInstance]

    __slots__ = ("by_cost", "by_predicate", "concluded", "model_bindings", "rigid", "root",
                 "settled", "unmatched")  # fmt: skip

    def __init__(
        self,
        by_predicate: dict[tuple[str, int], list[tuple[OperatorSchema, dict[Param, Param], Atom]]],
        rigid: frozenset[tuple[str, int]],
        concluded: frozenset[tuple[str, int]] = frozenset(),
        by_cost: bool = False,
        root: WorldModel | None = None,
        model_bindings: bool = False,
    ) -> None:
        self.by_predicate = by_predicate
        self.rigid = rigid
        self.concluded = concluded
        self.by_cost = by_cost
        self.root = root
        self.model_bindings = model_bindings
        self.unmatched = {}
        self.settled = {}

    def relevant(self, difference: Difference, model: WorldModel) -> list[RelevantInstance]:
        """The relevant instances, ranked. When no instance binds all its parameters
        the unifier touches, the ones whose precondition parameters were left unbound
        instead (see :func:`_bind`): without them the node would have no successor."""
        return self._ranked(difference, model, False) or self._ranked(difference, model, True)

    def _ranked(
        self, difference: Difference, model: WorldModel, loose: bool
    ) -> list[RelevantInstance]:
        protected = _protected_facts(difference, model)
        ranked: dict[OperatorInstance, tuple[tuple[int, ...], RelevantInstance]] = {}
        # What an instance costs besides its resolvent (None: it can never be applied),
        # by instance: the clauses of a difference share most literals, so one instance
        # is found again and again (on elevators, a dozen times per difference).
        judged: dict[OperatorInstance, tuple[int, int] | None] = {}
        # The instance an add atom makes of a literal depends on the literal alone.
        bound: dict[tuple[int, Atom], tuple[OperatorInstance, dict] | None] = {}
        order = 0
        for clause in difference.clauses:
            for position, (positive, atom) in enumerate(clause.literals):
                if positive:
                    continue
                entries = self.by_predicate.get((atom[0], len(atom)), ())
                for number, (schema, renamed, add_atom) in enumerate(entries):
                    slot = (number, atom)
                    if slot not in bound:
                        bound[slot] = _bind(schema, renamed, add_atom, atom, loose)
                    made = bound[slot]
                    if made is None:
                        continue
                    instance, unifier = made
                    if self.model_bindings:
                        # A binding under which the instance can never be applied
                        # settles nothing: the instance stays as the difference made it.
                        settled = self._settled(instance, model)
                        if settled not in judged:
                            judged[settled] = self._judge(settled, model, protected)
                        if judged[settled] is not None:
                            instance = settled
                    if instance not in judged:
                        judged[instance] = self._judge(instance, model, protected)
                    verdict = judged[instance]
                    if verdict is None:
                        continue
                    missing, harm = verdict
                    found = RelevantInstance(instance, _resolvent(clause, position, unifier))
                    size = len(found.resolvent.literals) + missing
                    key = (size, harm, order)
                    order += 1
                    known = ranked.get(found.operator)
                    if known is None or key < known[0]:
                        ranked[found.operator] = (key, found)
        return [found for _, found in sorted(ranked.values(), key=lambda item: item[0])]

    def _settled(
        self, instance: OperatorInstance, model: WorldModel, checked: bool = True
    ) -> OperatorInstance:
        """``instance`` with each parameter bound that the model's facts determine: a
        precondition atom matching exactly one fact binds its parameters (unless
        another such atom gives the parameter another value, or the value leaves a
        rigid atom, which no operator makes true, matching no fact), else the atoms that
        match some fact, joined, bind a parameter they allow one value for (repeated
        while bindings come: one settles the next atom). What the model
        already holds is what the instance will use: ``lift(x, y, pallet2, p)``, pushed
        to clear pallet2, is about the crate that is on it, ``on(y, pallet2)``, at that
        crate's place, with the hoist there. Left unbound, its subgoal's difference
        offers to make some other crate sit on the pallet or become clear, and those
        subgoals loop back through the lift below them. Atoms no fact matches are what
        the subgoal must achieve, left out; atoms of predicates a rule concludes are
        not looked at (the fact index does not decide them).

        With ``checked``, a fact that achieving those atoms would delete binds nothing
        (:meth:`_consumed`): the subgoal changes the model before the instance is
        applied. Kept per model and instance: nodes of one model share most instances,
        whatever their differences."""
        key = (model, instance, checked)
        known = self.settled.get(key)
        if known is None:
            if len(self.settled) >= _SETTLED_KEPT:
                self.settled.clear()
            atoms = [
                part for part in _conjunct_atoms(instance.schema.precondition)
                if (part[0], len(part) - 1) not in self.concluded
            ]
            known = self._settle(instance, model, atoms)
            while checked and known is not instance:
                consumed = self._consumed(instance, known, model, atoms)
                if not consumed:
                    break
                atoms = [part for part in atoms if part not in consumed]
                known = self._settle(instance, model, atoms)
            if known is not instance and self._stranded(instance, known, model, atoms):
                known = instance
            self.settled[key] = known
        return known

    def _settle(
        self, instance: OperatorInstance, model: WorldModel, atoms: list[Atom]
    ) -> OperatorInstance:
        binding = instance.binding_map()
        changed = False
        progress = True
        while progress:
            progress = False
            matched: list[Atom] = []
            proposed: dict[Param, set[Term]] = defaultdict(set)
            for part in atoms:
                atom = substitute(part, binding)
                if not params_of(atom):
                    continue
                matches = _first_matches(atom, model)
                if len(matches) == 1:
                    for param in params_of(atom):
                        value = substitute(param, matches[0])
                        if is_ground(value):
                            proposed[param].add(value)
                if matches:
                    matched.append(atom)
            rigid = [part for part in atoms if (part[0], len(part) - 1) in self.rigid]
            for param, values in proposed.items():
                if len(values) != 1:  # two atoms that disagree settle nothing
                    continue
                trial = {**binding, param: next(iter(values))}
                if all(_first_matches(substitute(part, trial), model) for part in rigid):
                    binding = trial
                    progress = changed = True
            if progress or not matched:
                continue
            for param, value in _join_values(model, matched).items():
                binding[param] = value
                progress = changed = True
        return instance.bind(binding) if changed else instance

    def _consumed(
        self,
        instance: OperatorInstance,
        settled: OperatorInstance,
        model: WorldModel,
        atoms: list[Atom],
    ) -> set[Atom]:
        """The atoms of ``atoms`` through which ``settled`` bound a parameter of
        ``instance`` whose fact an operator making one of its missing atoms deletes (that
        operator bound by the missing atom, then by the model's facts, unchecked). The
        subgoal applies that operator before the instance, so the fact is gone by then:
        on transport, ``drop(v, l2, p, s1, s2)`` for ``at(p, l2)`` joined
        ``capacity(v, s1)`` with the truck that can drop now, at its capacity now; but
        it needs ``in(p, v)``, and the ``pick-up`` that makes it deletes that capacity,
        so the drop bound that way can only be applied after a drop of its own."""
        before = instance.binding_map()
        after = settled.binding_map()
        holding: dict[Atom, Atom] = {}
        missing: list[Atom] = []
        for part in atoms:
            atom = substitute(part, after)
            if _lacks(model, atom):
                missing.append(atom)
            elif is_ground(atom) and any(param not in before for param in params_of(part)):
                holding[atom] = part
        consumed: set[Atom] = set()
        if not holding:
            return consumed
        for atom in missing:
            for achiever in self._achievers(atom, model):
                deletes, _ = self._settled(achiever, model, False).effects()
                consumed.update(holding[fact] for fact in deletes if fact in holding)
        return consumed

    def _stranded(
        self,
        instance: OperatorInstance,
        settled: OperatorInstance,
        model: WorldModel,
        atoms: list[Atom],
    ) -> bool:
        """Whether a missing atom of ``settled`` that holds a parameter the settling
        bound has no operator that could ever make it (every one that adds it is never
        applicable: :meth:`_never_applicable`). The model's facts chose a value the plan
        cannot use: on rovers, ``communicate_rock_data`` for a rock sample was settled on
        the rover at a place that sees the lander, which has no rock analysis equipment,
        so ``have_rock_analysis`` of it can never be made, and the search ended
        *exhausted* after 9 nodes. The instance is then offered as the difference made
        it, its parameters left to its subgoal's proof."""
        before = instance.binding_map()
        after = settled.binding_map()
        for part in atoms:
            if all(param in before for param in params_of(part)):
                continue  # not touched by the settling
            atom = substitute(part, after)
            if _lacks(model, atom) and next(self._achievers(atom, model), None) is None:
                return True
        return False

    def _achievers(self, atom: Atom, model: WorldModel) -> Iterator[OperatorInstance]:
        """The instances that add ``atom`` (bound by it, parameters it leaves free left
        to their proofs) that are not never applicable (:meth:`_never_applicable`)."""
        for schema, renamed, add_atom in self.by_predicate.get((atom[0], len(atom)), ()):
            made = _bind(schema, renamed, add_atom, atom, True)
            if made is not None and not self._never_applicable(made[0], model):
                yield made[0]

    def _never_applicable(self, instance: OperatorInstance, model: WorldModel) -> bool:
        """Whether the rigid conjuncts of the instance's precondition can never hold: a
        ground one is not a fact of ``model``, or those with parameters still unbound
        have no binding that maps them all onto M0's facts at once (a join). Facts of
        rigid predicates are only ever deleted, so what no fact of M0 matches no later
        model's will: ``move-up(lift, ?f1, n0)`` for ``lift-at(lift, n0)`` needs
        ``above(?f1, n0)``, and no floor is below the lowest. The join is made only
        with ``rigid_join`` (``root`` set)."""
        binding = instance.binding_map()
        unbound: list[Atom] = []
        # A translated PDDL precondition nests the action's own conjunction inside the
        # type atoms' one, so the conjuncts are flattened.
        for part in conjuncts(instance.schema.precondition):
            if isinstance(part, Atomic) and (part.atom[0], len(part.atom) - 1) in self.rigid:
                atom = substitute(part.atom, binding)
                if not is_ground(atom):
                    unbound.append(atom)
                elif not model.holds(atom):
                    return True
        if not unbound or self.root is None:
            return False
        key = tuple(unbound)
        verdict = self.unmatched.get(key)
        if verdict is None:
            literals: list[Literal] = [(False, atom) for atom in unbound]
            verdict = self.unmatched[key] = facts_join(self.root, literals) is False
        return verdict

    def _judge(
        self,
        instance: OperatorInstance,
        model: WorldModel,
        protected: dict[tuple[str, int], set[Atom]],
    ) -> tuple[int, int] | None:
        """``None`` when ``instance`` can never be applied in ``model``'s successors,
        else what ranks it besides its resolvent: its missing precondition atoms (with
        ``rank = "cost"``; 0 otherwise) and the facts of the proof it may delete."""
        if self._never_applicable(instance, model):
            return None
        missing = _missing_preconditions(instance, model, self.concluded) if self.by_cost else 0
        return missing, _deleted_count(instance, protected, self.model_bindings)


def _lacks(model: WorldModel, atom: Atom) -> bool:
    """Whether no fact of ``model`` is ``atom`` (ground) or matches it."""
    return not model.holds(atom) if is_ground(atom) else not _first_matches(atom, model)


def _first_matches(atom: Atom, model: WorldModel) -> list[dict]:
    """The unifiers of ``atom`` with ``model``'s facts, up to the second: whether it
    matches none, one or more is all :meth:`AddListIndex._settle` asks."""
    found: list[dict] = []
    for fact in model.facts_matching(atom):
        unifier = unify(atom, fact, {})
        if unifier is not None:
            found.append(unifier)
            if len(found) == 2:
                break
    return found


#: How many (model, instance) pairs :meth:`AddListIndex._settled` remembers at most.
_SETTLED_KEPT = 200_000
#: Unifications the join of :func:`_join_values` may try before it gives up.
_JOIN_BUDGET = 2_000


def _join_values(model: WorldModel, atoms: list[Atom]) -> dict[Param, Term]:
    """The parameters of ``atoms`` that every joint match of them onto ``model``'s facts
    binds to one and the same value (none when there is no match, or the join runs
    past its budget before it is done)."""
    values: dict[Param, set[Term]] = {param: set() for atom in atoms for param in params_of(atom)}
    left = _JOIN_BUDGET

    def extend(rest: list[Atom], binding: dict) -> bool:
        """False once the join cannot settle anything (budget spent, or every
        parameter has two values)."""
        nonlocal left
        if not rest:
            for param, seen in values.items():
                seen.add(substitute(param, binding))
            return any(len(seen) < 2 for seen in values.values())
        scored = [(list(model.facts_matching(substitute(a, binding))), a) for a in rest]
        candidates, chosen = min(scored, key=lambda pair: len(pair[0]))
        others = [a for a in rest if a is not chosen]
        for fact in candidates:
            left -= 1
            if left < 0:
                return False
            extended = unify(chosen, fact, dict(binding))
            if extended is not None and not extend(others, extended):
                return False
        return True

    if not extend(atoms, {}) or left < 0:
        return {}
    return {
        param: next(iter(seen)) for param, seen in values.items()
        if len(seen) == 1 and is_ground(next(iter(seen)))
    }


def _add_atoms_by_predicate(
    operators: Sequence[OperatorSchema],
) -> dict[tuple[str, int], list[tuple[OperatorSchema, dict[Param, Param], Atom]]]:
    """Candidate index: (predicate, arity) -> (schema, renaming, renamed add atom)."""
    index: dict[tuple[str, int], list[tuple[OperatorSchema, dict[Param, Param], Atom]]]
    index = defaultdict(list)
    for schema in operators:
        renaming = {p: Param(p.name, _RENAMED) for p in schema.parameters}
        for atom in schema.add_list:
            index[(atom[0], len(atom))].append((schema, renaming, substitute(atom, renaming)))
    return index


def _bind(
    schema: OperatorSchema,
    renaming: dict[Param, Param],
    add_atom: Atom,
    target: Atom,
    loose: bool = False,
) -> tuple[OperatorInstance, dict] | None:
    """The instance of ``schema`` whose add atom resolves the literal of ``target``,
    and the unifier. A parameter the unifier binds to a parameter of the goal's own
    operator (or to a variable) cannot take that binding: the instance is dropped, or with
    ``loose`` the parameter is left unbound when the precondition has it, for its proof to
    bind. A difference whose literals all hold such parameters (an SLD proof that bound
    none of them: on sokoban, ``at(player, ?ppos)`` and ``clear(?to)`` of
    ``push-to-goal``) gives no instance otherwise, and the search ends exhausted after a
    few nodes."""
    unifier = unify(add_atom, target, {})
    if unifier is None:
        return None
    binding: dict[Param, Term] = {}
    for own, renamed in renaming.items():
        value = substitute(renamed, unifier)
        if value == renamed:
            continue
        if params_of(value) or variables_of(value):
            if loose:
                continue  # left unbound: dropped below unless the precondition has it
            return None  # bound to another operator's parameter, or to a variable
        binding[own] = value
    for own in schema.parameters:
        if own not in binding and own not in schema.precondition_params:
            return None
    return OperatorInstance(schema, binding.items()), unifier


def _resolvent(clause: Clause, position: int, unifier: dict) -> Clause:
    """What is left of ``clause`` once the literal at ``position`` is resolved away."""
    rest = [
        (sign, substitute(atom, unifier))
        for i, (sign, atom) in enumerate(clause.literals)
        if i != position
    ]
    return Clause(list(dict.fromkeys(rest)), clause.bindings, label="relevance")


def _missing_preconditions(
    instance: OperatorInstance, model: WorldModel, concluded: frozenset[tuple[str, int]]
) -> int:
    """The atoms of the instance's precondition (its conjuncts, nested conjunctions and
    existentials flattened) that no fact of ``model`` matches: a count of what its subgoal
    still has to achieve."""
    binding = instance.binding_map()
    missing = 0
    for part in _conjunct_atoms(instance.schema.precondition):
        if (part[0], len(part) - 1) in concluded:
            continue  # an axiom may conclude it: no fact to look for
        missing += _lacks(model, substitute(part, binding))
    return missing


@cache
def _conjunct_atoms(formula: Formula) -> tuple[Atom, ...]:
    """The positive atoms but equalities among the conjuncts of ``formula``, inside
    existentials too, their quantified variables as clause variables (so a fact can bind
    them). Cached: it is asked for each candidate instance of a schema."""
    return tuple(a for a in _positive_conjuncts(formula) if a[0] != EQUALITY)


def _positive_conjuncts(formula: Formula) -> Iterator[Atom]:
    names: dict[Var, int] = {}

    def term(t: object) -> object:
        if isinstance(t, Var):
            return names.setdefault(t, len(names))
        if type(t) is tuple:
            return (t[0], *map(term, t[1:]))
        return t

    stack = [formula]
    while stack:
        part = stack.pop()
        if isinstance(part, Exists):
            stack.append(part.body)
        elif isinstance(part, And):
            stack.extend(reversed(part.parts))
        elif isinstance(part, Atomic):
            yield (part.atom[0], *map(term, part.atom[1:]))


def _protected_facts(
    difference: Difference, model: WorldModel
) -> dict[tuple[str, int], set[Atom]]:
    """Facts of ``model`` that could resolve away a literal of the difference: the facts
    the proof rests on or could rest on (found through the model's fact index), filed by
    (predicate, arity), since a delete pattern can only match facts of its own predicate
    and in a large world there are many of them."""
    wanted = {
        atom
        for clause in (*difference.negated_goal, *difference.clauses)
        for positive, atom in clause.literals
        if not positive
    }
    filed: dict[tuple[str, int], set[Atom]] = defaultdict(set)
    for atom in wanted:
        for fact in model.facts_matching(atom):
            if unify(atom, fact, {}) is not None:
                filed[(fact[0], len(fact))].add(fact)
    return filed


def _deleted_count(
    instance: OperatorInstance, facts: dict[tuple[str, int], set[Atom]], bound_only: bool
) -> int:
    """How many of ``facts`` the instance's delete list may delete (unbound parameters and
    wildcards match anything); each pattern is tried only on the facts of its predicate.
    ``bound_only`` (with model bindings) counts only patterns with no parameter left
    unbound: an instance is then bound as far as the model settles it, and a pattern it
    leaves unbound names no fact yet. Counted as deleting every fact it matches, it
    would rank each instance the model cannot settle below every one it can, whatever
    those delete: on pegsol the root offered the jumps possible at once (bound through
    the pegs in place) before any jump its subgoal would set up."""
    patterns, _ = instance.effects()
    by_key: dict[tuple[str, int], list[Atom]] = defaultdict(list)
    for pattern in patterns:
        if bound_only and params_of(pattern):
            continue
        by_key[(pattern[0], len(pattern))].append(pattern)
    return sum(
        1
        for key, same in by_key.items()
        for fact in facts.get(key, ())
        if any(may_delete(p, fact) for p in same)
    )