"""Grounding a lifted PDDL task into a :class:`GroundTask`.

Each action becomes one reachability rule per disjunct of its normalized precondition,
each derived predicate one rule per disjunct of its body, and a goal that is not a plain
conjunction of atoms a rule for the derived fact ``(@goal)``. Relaxed reachability finds
the rule instances that can ever fire; only those become ground operators and axioms.
Static facts (of predicates no action changes) are checked during grounding and left out
of the task; operators that change nothing are dropped, and (by default) so are the facts
and operators backward relevance analysis finds useless for the goal (:mod:`.relevance`).

Determinism: facts are numbered in the order of their names and operators sorted by name
(then by their fact lists), so nothing depends on the iteration order of hashed strings.
"""

from __future__ import annotations

from collections.abc import Callable
from operator import itemgetter

from attrs import evolve, frozen

from strips_framework.errors import InputError
from strips_framework.grounding.axioms import AxiomEvaluator
from strips_framework.grounding.normalize import Clause, Normalizer
from strips_framework.grounding.reachability import Args, FactIndex, Reachability, Rule, Slots
from strips_framework.grounding.relevance import RawAxiom, RawOperator, relevant
from strips_framework.grounding.task import GroundAxiom, GroundOperator, GroundTask
from strips_framework.pddl.formulas import Atom, Parameter
from strips_framework.pddl.task import Action, PddlTask, missing_cost

#: The derived fact that stands for a goal which is not a conjunction of atoms.
GOAL = "@goal"

Fact = tuple[str, Args]
#: An atom compiled against a rule's slots: the fact numbers of its predicate by
#: arguments, and the function that picks its arguments from an instance's slot values.
Pattern = tuple[dict[Args, int], Callable[[Args], Args]]


@frozen
class _Source:
    """What a reachability rule stands for: an action, or the head of an axiom."""

    clause: Clause
    action: Action | None = None
    head: Atom | None = None


def ground(task: PddlTask, prune_irrelevant: bool = True) -> GroundTask:
    """The ground task of ``task``; see the module docstring. With ``prune_irrelevant``
    the facts and operators that cannot matter to the goal are left out too (see
    :mod:`.relevance`)."""
    return _Grounder(task, prune_irrelevant).ground()


def fact_name(predicate: str, args: Args) -> str:
    return "(" + " ".join((predicate, *args)) + ")"


class _Grounder:
    def __init__(self, task: PddlTask, prune_irrelevant: bool) -> None:
        self.task = task
        self.prune_irrelevant = prune_irrelevant
        domain = task.domain
        self.derived = {rule.head.predicate for rule in domain.derived} | {GOAL}
        changed = {atom.predicate for a in domain.actions for atom in (*a.add, *a.delete)}
        self.static: dict[str, FactIndex] = {
            pred.name: FactIndex()
            for pred in domain.predicates
            if pred.name not in changed and pred.name not in self.derived
        }
        self.init: list[Fact] = []
        for atom in task.problem.init:
            if atom.predicate in self.static:
                self.static[atom.predicate].add(atom.args)
            elif atom.predicate not in self.derived:
                self.init.append((atom.predicate, atom.args))
        self.sources: list[_Source] = []
        self.rules: list[Rule] = []
        self.goal_atoms: tuple[Atom, ...] | None = None
        self.numeric = dict(task.problem.numeric)

    def ground(self) -> GroundTask:
        normalizer = Normalizer(self.task)
        for action in self.task.domain.actions:
            for clause in normalizer.clauses(action.precondition):
                self._add_rule(_Source(clause, action=action), action.params, action.add)
        for derived in self.task.domain.derived:
            for clause in normalizer.clauses(derived.body):
                self._add_rule(_Source(clause, head=derived.head), derived.params, (derived.head,))
        goal_clauses = normalizer.clauses(self.task.problem.goal)
        if len(goal_clauses) == 1 and not goal_clauses[0].params and not goal_clauses[0].negative:
            self.goal_atoms = tuple(
                atom for atom in goal_clauses[0].positive if atom.predicate != "="
            )
        else:
            head = Atom(GOAL, ())
            for clause in goal_clauses:
                self._add_rule(_Source(clause, head=head), (), (head,))
        done = 0
        while done < len(normalizer.auxiliary):  # bodies may add more
            rule = normalizer.auxiliary[done]
            done += 1
            self.derived.add(rule.head.predicate)
            for clause in normalizer.clauses(rule.body):
                self._add_rule(_Source(clause, head=rule.head), rule.params, (rule.head,))
        objects = frozenset(self.task.objects_of(("object",)))
        reach = Reachability(self.rules, self.static, objects)
        reach.run(self.init)
        return self._task(reach)

    def _add_rule(
        self, source: _Source, params: tuple[Parameter, ...], heads: tuple[Atom, ...]
    ) -> None:
        clause = source.clause
        everything = params + clause.params
        action = source.action
        mentions = clause.negative
        if action is not None:
            mentions += action.delete
            if isinstance(action.cost, Atom):
                mentions += (action.cost,)
        self.sources.append(source)
        self.rules.append(
            Rule(
                params=tuple(param.name for param in everything),
                domains=tuple(frozenset(self.task.objects_of(param.types)) for param in everything),
                body=tuple(atom for atom in clause.positive if atom.predicate != "="),
                heads=heads,
                absent=tuple(atom for atom in clause.negative if atom.predicate in self.static),
                equal=tuple(_pair(atom) for atom in clause.positive if atom.predicate == "="),
                unequal=tuple(_pair(atom) for atom in clause.negative if atom.predicate == "="),
                mentions=mentions,
            )
        )

    def _task(self, reach: Reachability) -> GroundTask:
        goal_facts = self._goal_facts()
        facts = {(pred, args) for pred, known in reach.reached.items() for args in known}
        names = sorted((fact_name(*fact), fact) for fact in facts | goal_facts)
        number = {fact: i for i, (_, fact) in enumerate(names)}
        operators, axioms = self._records(reach, number)
        goal = tuple(sorted(number[fact] for fact in goal_facts))
        keep: list[int] | range = range(len(names))
        if self.prune_irrelevant:
            kept, chosen = relevant(goal, operators, axioms)
            keep = sorted(kept)
            operators = [operators[i] for i in chosen]
            axioms = [axiom for axiom in axioms if axiom.head in kept]
        new = [-1] * len(names)
        for i, old in enumerate(keep):
            new[old] = i
        task = GroundTask(
            name=self.task.name,
            facts=tuple(names[old][0] for old in keep),
            operators=_final_operators(operators, new, len(keep)),
            init=sum(1 << new[number[fact]] for fact in set(self.init) if new[number[fact]] >= 0),
            goal=tuple(new[fact] for fact in goal),
            axioms=tuple(
                GroundAxiom(
                    new[a.head], _renumber(a.body, new), _renumber(a.body_neg, new), a.stratum
                )
                for a in axioms
            ),
            derived=tuple(
                new[i]
                for i, (_, (pred, _)) in enumerate(names)
                if pred in self.derived and new[i] >= 0
            ),
            uses_costs=self.task.problem.minimize_cost,
        )
        return evolve(task, init=AxiomEvaluator(task).evaluate(task.init))

    def _records(
        self, reach: Reachability, number: dict[Fact, int]
    ) -> tuple[list[RawOperator], list[RawAxiom]]:
        """The operators and axioms of the instances found, without duplicates, sorted."""
        by_predicate: dict[str, dict[Args, int]] = {}
        for (predicate, args), i in number.items():
            by_predicate.setdefault(predicate, {})[args] = i
        operators: set[RawOperator] = set()
        axioms: set[RawAxiom] = set()
        strata = self._strata()
        for source, slots, instances in zip(self.sources, reach.slots, reach.instances):
            builder = _Builder(self, source, slots, by_predicate)
            if source.action is not None:
                operators.update(builder.operators(instances))
            elif source.head is not None:
                axioms.update(builder.axioms(instances, strata[source.head.predicate]))
        return sorted(operators), sorted(axioms)

    def _goal_facts(self) -> set[Fact]:
        """The goal's atoms, static ones that hold left out. A goal fact nothing reaches
        keeps a number (nothing adds it), so the goal stays a conjunction of facts."""
        if self.goal_atoms is None:
            return {(GOAL, ())}
        result = set()
        for atom in self.goal_atoms:
            static = self.static.get(atom.predicate)
            if static is None or atom.args not in static.all:
                result.add((atom.predicate, atom.args))
        return result

    def cost(self, action: Action, args: Args) -> int:
        """The cost of ``action`` whose cost term has arguments ``args``."""
        if not self.task.problem.minimize_cost:
            return 1
        if action.cost is None:
            return 0
        if isinstance(action.cost, int):
            return action.cost
        term = Atom(action.cost.predicate, args)
        if term not in self.numeric:
            raise missing_cost(self.task, term, action)
        return self.numeric[term]

    def _strata(self) -> dict[str, int]:
        """A stratum for every derived predicate: at least that of the derived predicates
        its body uses, above those it uses negated."""
        level = dict.fromkeys(self.derived, 0)
        changed = True
        while changed:
            changed = False
            for source in self.sources:
                if source.head is None:
                    continue
                head = source.head.predicate
                for atoms, step in ((source.clause.positive, 0), (source.clause.negative, 1)):
                    for atom in atoms:
                        if atom.predicate in level and level[head] < level[atom.predicate] + step:
                            level[head] = level[atom.predicate] + step
                            changed = True
                if level[head] > len(level):
                    raise InputError(
                        self.task.domain_path,
                        None,
                        None,
                        f"derived predicate {head!r} depends negatively on itself "
                        "(the axioms cannot be stratified)",
                    )
        return level


class _Builder:
    """Turns the instances of one rule into ground operators or axioms. Atoms are
    compiled once to a lookup of their predicate's fact numbers and a function picking
    their arguments from an instance's slot values (its parameter values followed by the
    rule's constants)."""

    def __init__(
        self,
        grounder: _Grounder,
        source: _Source,
        slots: Slots,
        numbers: dict[str, dict[Args, int]],
    ) -> None:
        self.grounder = grounder
        self.source = source
        self.constants = tuple(value for value in slots.template if value is not None)
        static = grounder.static

        def patterns(atoms: tuple[Atom, ...]) -> tuple[Pattern, ...]:
            return tuple(
                (numbers.get(atom.predicate, {}), _picker(slots.of(atom.args)))
                for atom in atoms
                if atom.predicate != "=" and atom.predicate not in static
            )

        self.pre = patterns(source.clause.positive)
        self.pre_neg = patterns(source.clause.negative)
        action = source.action
        if action is not None:
            self.add = patterns(action.add)
            self.delete = patterns(action.delete)
            self.arity = len(action.params)
            cost_args = action.cost.args if isinstance(action.cost, Atom) else ()
            self.cost_args = _picker(slots.of(cost_args))
        if source.head is not None:
            (self.head,) = patterns((source.head,))

    @staticmethod
    def _facts(patterns: tuple[Pattern, ...], values: Args) -> set[int]:
        """The numbers of the facts; facts never reached have none and are left out
        (only negative literals and deletes can name them, and then they change nothing)."""
        found = set()
        for facts, pick in patterns:
            fact = facts.get(pick(values))
            if fact is not None:
                found.add(fact)
        return found

    def operators(self, instances: list[Args]) -> list[RawOperator]:
        action = self.source.action
        assert action is not None
        result = []
        for key in instances:
            values = key + self.constants
            pre = self._facts(self.pre, values)
            pre_neg = self._facts(self.pre_neg, values)
            if pre & pre_neg:
                continue
            add = self._facts(self.add, values)
            delete = self._facts(self.delete, values) - add
            if add <= pre and not delete:
                continue  # changes nothing wherever it applies
            cost_args = self.cost_args(values)
            result.append(
                RawOperator(
                    fact_name(action.name, key[: self.arity]),
                    tuple(sorted(pre)),
                    tuple(sorted(pre_neg)),
                    tuple(sorted(add)),
                    tuple(sorted(delete)),
                    self.grounder.cost(action, cost_args),
                )
            )
        return result

    def axioms(self, instances: list[Args], stratum: int) -> list[RawAxiom]:
        facts, pick = self.head
        result = []
        for key in instances:
            values = key + self.constants
            body = self._facts(self.pre, values)
            body_neg = self._facts(self.pre_neg, values)
            if body & body_neg:
                continue
            head = facts[pick(values)]
            result.append(RawAxiom(stratum, head, tuple(sorted(body)), tuple(sorted(body_neg))))
        return result


def _renumber(facts: tuple[int, ...], new: list[int]) -> tuple[int, ...]:
    """``facts`` in the final numbering (``new[old]``, -1 for a fact left out)."""
    return tuple([new[fact] for fact in facts if new[fact] >= 0])


def _final_operators(
    raw: list[RawOperator], new: list[int], kept: int
) -> tuple[GroundOperator, ...]:
    """The operators in the final numbering, ``kept`` facts of ``len(new)`` kept. Where
    facts were left out, an operator whose remaining adds are among its preconditions and
    which deletes nothing remaining changes nothing that matters: it is left out too."""
    if kept == len(new):
        return tuple(
            GroundOperator(op.name, op.pre, op.add, op.delete, op.cost, op.pre_neg) for op in raw
        )
    result = []
    for op in raw:
        pre, add, delete = _renumber(op.pre, new), _renumber(op.add, new), _renumber(op.delete, new)
        if delete or not set(add) <= set(pre):
            result.append(
                GroundOperator(op.name, pre, add, delete, op.cost, _renumber(op.pre_neg, new))
            )
    return tuple(result)


def _picker(slots: tuple[int, ...]) -> Callable[[Args], Args]:
    """A fast function from slot values to the tuple of the values at ``slots``."""
    if len(slots) > 1:
        return itemgetter(*slots)
    if slots:
        (slot,) = slots
        return lambda values: (values[slot],)
    return lambda values: ()


def _pair(atom: Atom) -> tuple[str, str]:
    return atom.args[0], atom.args[1]
