"""Grounding a lifted PDDL task into a :class:`GroundTask`.

Each action becomes one reachability rule per disjunct of its normalized precondition,
each derived predicate one rule per disjunct of its body, and a goal that is not a plain
conjunction of atoms a rule for the derived fact ``(@goal)``. A conditional or universal
effect becomes one rule per disjunct of its condition, over the action's and its own
variables, whose body is the condition plus the action's applicability atom (as in Fast
Downward's translator); the applicability atoms serve reachability only. Relaxed reachability finds
the rule instances that can ever fire; only those become ground operators and axioms.
Static facts (of predicates no action changes) are checked during grounding and left out
of the task; operators that change nothing are dropped, and (by default) so are the facts
and operators backward relevance analysis finds useless for the goal (:mod:`.relevance`).

Determinism: facts are numbered in the order of their names and operators sorted by name
(then by their fact lists), so nothing depends on the iteration order of hashed strings.
"""

from __future__ import annotations

from collections.abc import Callable
from operator import attrgetter, itemgetter

from strips_framework.allocation import collection_paused
from strips_framework.errors import InputError
from strips_framework.grounding.axioms import AxiomEvaluator
from strips_framework.grounding.normalize import Clause, Normalizer
from strips_framework.grounding.reachability import Args, FactIndex, Reachability, Rule, Slots
from strips_framework.grounding.relevance import RawAxiom, RawEffect, RawOperator, relevant
from strips_framework.grounding.task import GroundAxiom, GroundEffect, GroundOperator, GroundTask
from strips_framework.pddl.formulas import Atom, Parameter
from strips_framework.pddl.task import Action, ConditionalEffect, PddlTask, missing_cost
from strips_framework.records import Record

#: The derived fact that stands for a goal which is not a conjunction of atoms.
GOAL = "@goal"
#: Prefix of the predicate that says an action applies, premise of its effects' rules.
APPLICABLE = "@applicable:"
#: The grounder's records sort by their key (their fields in sorting order).
_KEY = attrgetter("key")

Fact = tuple[str, Args]
#: An atom compiled against a rule's slots: the fact numbers of its predicate by
#: arguments, and the function that picks its arguments from an instance's slot values.
Pattern = tuple[dict[Args, int], Callable[[Args], Args]]


class _Source(Record):
    """What a reachability rule stands for: an action, one of its conditional effects,
    or the head of an axiom."""

    clause: Clause
    action: Action | None
    head: Atom | None
    effect: ConditionalEffect | None

    __slots__ = ("clause", "action", "head", "effect")

    def __init__(
        self,
        clause: Clause,
        action: Action | None = None,
        head: Atom | None = None,
        effect: ConditionalEffect | None = None,
    ) -> None:
        self.clause = clause
        self.action = action
        self.head = head
        self.effect = effect


@collection_paused()
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
        changed = {atom.predicate for a in domain.actions for atom in a.changed_atoms()}
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
            heads = action.add
            if action.conditional:
                applicable = _applicable(action)
                heads += (applicable,)
                for effect in action.conditional:
                    for clause in normalizer.clauses(effect.condition):
                        self._add_rule(
                            _Source(clause, action=action, effect=effect),
                            action.params + effect.params,
                            effect.add,
                            (applicable,),
                        )
            for clause in normalizer.clauses(action.precondition):
                self._add_rule(_Source(clause, action=action), action.params, heads)
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
        self,
        source: _Source,
        params: tuple[Parameter, ...],
        heads: tuple[Atom, ...],
        premises: tuple[Atom, ...] = (),
    ) -> None:
        """A rule for ``source``: ``premises`` join the positive atoms of its clause."""
        clause = source.clause
        everything = params + clause.params
        action = source.action
        mentions = clause.negative
        if source.effect is not None:
            mentions += source.effect.delete
        elif action is not None:
            mentions += action.delete
            if isinstance(action.cost, Atom):
                mentions += (action.cost,)
        self.sources.append(source)
        self.rules.append(
            Rule(
                params=tuple(param.name for param in everything),
                domains=tuple(frozenset(self.task.objects_of(param.types)) for param in everything),
                body=premises + tuple(atom for atom in clause.positive if atom.predicate != "="),
                heads=heads,
                absent=tuple(atom for atom in clause.negative if atom.predicate in self.static),
                equal=tuple(_pair(atom) for atom in clause.positive if atom.predicate == "="),
                unequal=tuple(_pair(atom) for atom in clause.negative if atom.predicate == "="),
                mentions=mentions,
            )
        )

    def _task(self, reach: Reachability) -> GroundTask:
        goal_facts = self._goal_facts()
        facts = {
            (pred, args)
            for pred, known in reach.reached.items()
            if not pred.startswith(APPLICABLE)
            for args in known
        }
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
        return task._replace(init=AxiomEvaluator(task).evaluate(task.init))

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
        rules = list(zip(self.sources, reach.slots, reach.instances))
        #: Per action, the conditional effects of each binding of its parameters.
        effects: dict[str, dict[Args, list[RawEffect]]] = {}
        for source, slots, instances in rules:
            if source.effect is not None:
                builder = _Builder(self, source, slots, by_predicate)
                builder.effects(instances, effects.setdefault(source.action.name, {}))
        for source, slots, instances in rules:
            if source.effect is not None:
                continue
            builder = _Builder(self, source, slots, by_predicate)
            if source.action is not None:
                operators.update(builder.operators(instances, effects.get(source.action.name, {})))
            elif source.head is not None:
                axioms.update(builder.axioms(instances, strata[source.head.predicate]))
        return sorted(operators, key=_KEY), sorted(axioms, key=_KEY)

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
            changes = source.effect or action
            self.add = patterns(changes.add)
            self.delete = patterns(changes.delete)
            self.arity = len(action.params)
            cost_args = action.cost.args if isinstance(action.cost, Atom) else ()
            self.cost_args = _picker(slots.of(cost_args if source.effect is None else ()))
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

    def _parts(self, key: Args) -> tuple[Args, set[int], set[int], set[int], set[int]] | None:
        """The slot values of an instance of an action's or effect's rule, and its
        condition's facts (positive, negated), adds and deletes; None when the condition
        contradicts itself."""
        values = key + self.constants
        condition = self._facts(self.pre, values)
        condition_neg = self._facts(self.pre_neg, values)
        if condition & condition_neg:
            return None
        return values, condition, condition_neg, self._facts(self.add, values), self._facts(
            self.delete, values
        )

    def operators(
        self, instances: list[Args], effects: dict[Args, list[RawEffect]]
    ) -> list[RawOperator]:
        """The operators of the instances; ``effects`` holds the conditional effects of
        each binding of the action's parameters."""
        action = self.source.action
        assert action is not None
        result = []
        for key in instances:
            parts = self._parts(key)
            if parts is None:
                continue
            values, pre, pre_neg, add, delete = parts
            conditional = _simplify(pre, pre_neg, add, delete, effects.get(key[: self.arity], ()))
            delete -= add
            if add <= pre and not delete and not conditional:
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
                    conditional,
                )
            )
        return result

    def effects(self, instances: list[Args], into: dict[Args, list[RawEffect]]) -> None:
        """File the effects of the instances of a conditional effect's rule under the
        binding of the action's parameters they belong to."""
        for key in instances:
            parts = self._parts(key)
            if parts is None:
                continue
            _, condition, condition_neg, add, delete = parts
            if add or delete:
                effect = _raw_effect(condition, condition_neg, add, delete)
                into.setdefault(key[: self.arity], []).append(effect)

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


def _simplify(
    pre: set[int],
    pre_neg: set[int],
    add: set[int],
    delete: set[int],
    effects: list[RawEffect] | tuple[()],
) -> tuple[RawEffect, ...]:
    """The conditional ``effects`` of an operator with these preconditions, simplified:
    an effect whose condition contradicts them never fires and is dropped, condition facts
    the preconditions settle are left out, and an effect left without condition joins
    ``add`` and ``delete`` (updated in place). Adds win over deletes, as in PDDL."""
    conditional: list[tuple[set[int], set[int], set[int], set[int]]] = []
    for effect in effects:
        condition, condition_neg = set(effect.condition), set(effect.condition_neg)
        if condition & pre_neg or condition_neg & pre:
            continue
        condition -= pre
        condition_neg -= pre_neg
        if condition or condition_neg:
            conditional.append((condition, condition_neg, set(effect.add), set(effect.delete)))
        else:
            add.update(effect.add)
            delete.update(effect.delete)
    result = set()
    for condition, condition_neg, effect_add, effect_delete in conditional:
        effect_add -= add
        effect_delete -= add | delete | effect_add
        if effect_add or effect_delete:
            result.add(_raw_effect(condition, condition_neg, effect_add, effect_delete))
    return tuple(sorted(result, key=_KEY))


def _raw_effect(
    condition: set[int], condition_neg: set[int], add: set[int], delete: set[int]
) -> RawEffect:
    return RawEffect(
        tuple(sorted(condition)),
        tuple(sorted(condition_neg)),
        tuple(sorted(add)),
        tuple(sorted(delete)),
    )


def _renumber(facts: tuple[int, ...], new: list[int]) -> tuple[int, ...]:
    """``facts`` in the final numbering (``new[old]``, -1 for a fact left out)."""
    return tuple([new[fact] for fact in facts if new[fact] >= 0])


def _final_operators(
    raw: list[RawOperator], new: list[int], kept: int
) -> tuple[GroundOperator, ...]:
    """The operators in the final numbering, ``kept`` facts of ``len(new)`` kept. Where
    facts were left out, an operator whose remaining adds are among its preconditions and
    which deletes nothing remaining changes nothing that matters: it is left out too."""
    result = []
    for op in raw:
        pre, add, delete = _renumber(op.pre, new), _renumber(op.add, new), _renumber(op.delete, new)
        effects = []
        for effect in op.effects:
            effect_add, effect_delete = _renumber(effect.add, new), _renumber(effect.delete, new)
            if effect_add or effect_delete:
                condition = _renumber(effect.condition, new)
                condition_neg = _renumber(effect.condition_neg, new)
                effects.append(GroundEffect(condition, condition_neg, effect_add, effect_delete))
        if kept == len(new) or delete or effects or not set(add) <= set(pre):
            result.append(
                GroundOperator(
                    op.name, pre, add, delete, op.cost, _renumber(op.pre_neg, new), tuple(effects)
                )
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


def _applicable(action: Action) -> Atom:
    """The atom that holds for the bindings under which ``action`` applies."""
    return Atom(APPLICABLE + action.name, tuple(param.name for param in action.params))


def _pair(atom: Atom) -> tuple[str, str]:
    return atom.args[0], atom.args[1]
