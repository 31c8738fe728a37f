"""Grounding a lifted PDDL task into a :class:`GroundTask`.

Each action becomes one reachability rule per disjunct of its normalized precondition,
each derived predicate one rule per disjunct of its body, and a goal that is not a plain
conjunction of atoms a rule for the derived fact ``(@goal)``. Relaxed reachability finds
the rule instances that can ever fire; only those become ground operators and axioms.
Static facts (of predicates no action changes) are checked during grounding and left out
of the task.

Determinism: facts are numbered in the order of their names and operators sorted by name
(then by their fact lists), so nothing depends on the iteration order of hashed strings.
"""

from __future__ import annotations

from attrs import frozen

from strips_framework.errors import InputError
from strips_framework.grounding.axioms import AxiomEvaluator
from strips_framework.grounding.normalize import Clause, Normalizer
from strips_framework.grounding.reachability import Args, Binding, FactIndex, Reachability, Rule
from strips_framework.grounding.task import GroundAxiom, GroundOperator, GroundTask
from strips_framework.pddl.formulas import Atom, Parameter
from strips_framework.pddl.task import Action, PddlTask, missing_cost

#: The derived fact that stands for a goal which is not a conjunction of atoms.
GOAL = "@goal"

Fact = tuple[str, Args]


@frozen
class _Source:
    """What a reachability rule stands for: an action, or the head of an axiom."""

    clause: Clause
    action: Action | None = None
    head: Atom | None = None


def ground(task: PddlTask) -> GroundTask:
    """The ground task of ``task``; see the module docstring."""
    return _Grounder(task).ground()


def fact_name(predicate: str, args: Args) -> str:
    return "(" + " ".join((predicate, *args)) + ")"


class _Grounder:
    def __init__(self, task: PddlTask) -> None:
        self.task = task
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
        reach = Reachability(self.rules, self.static, self._check)
        reach.run(self.init)
        return self._task(reach)

    def _add_rule(
        self, source: _Source, params: tuple[Parameter, ...], heads: tuple[Atom, ...]
    ) -> None:
        clause = source.clause
        everything = params + clause.params
        self.sources.append(source)
        self.rules.append(
            Rule(
                params=tuple(param.name for param in everything),
                domains=tuple(frozenset(self.task.objects_of(param.types)) for param in everything),
                body=tuple(atom for atom in clause.positive if atom.predicate != "="),
                heads=heads,
                equal=tuple(_pair(atom) for atom in clause.positive if atom.predicate == "="),
                unequal=tuple(_pair(atom) for atom in clause.negative if atom.predicate == "="),
            )
        )

    def _check(self, number: int, binding: Binding) -> bool:
        """Static negative literals: the fact must be absent from the initial state."""
        for atom in self.sources[number].clause.negative:
            facts = self.static.get(atom.predicate)
            if facts is not None and _args(atom, binding) in facts.all:
                return False
        return True

    def _task(self, reach: Reachability) -> GroundTask:
        facts: set[Fact] = {(pred, args) for pred, known in reach.reached.items() for args in known}
        goal_facts = self._goal_facts()
        facts.update(goal_facts)
        names = sorted((fact_name(*fact), fact) for fact in facts)
        number = {fact: i for i, (_, fact) in enumerate(names)}
        operators: set[GroundOperator] = set()
        axioms: set[GroundAxiom] = set()
        strata = self._strata()
        for rule_number, (source, rule) in enumerate(zip(self.sources, self.rules)):
            for values in reach.instances[rule_number]:
                binding = dict(zip(rule.params, values))
                pre = self._literals(source.clause.positive, binding, number)
                pre_neg = self._literals(source.clause.negative, binding, number)
                if source.action is not None:
                    operator = self._operator(source.action, binding, pre, pre_neg, number)
                    if operator is not None:
                        operators.add(operator)
                elif source.head is not None and not set(pre) & set(pre_neg):
                    head = number[(source.head.predicate, _args(source.head, binding))]
                    axioms.add(GroundAxiom(head, pre, pre_neg, strata[source.head.predicate]))
        ordered = sorted(operators, key=lambda op: (op.name, op.pre, op.pre_neg, op.add, op.delete))
        goal = (
            (number[(GOAL, ())],)
            if self.goal_atoms is None
            else tuple(sorted(number[f] for f in goal_facts))
        )
        derived = tuple(i for i, (_, (pred, _)) in enumerate(names) if pred in self.derived)
        init = 0
        for fact in self.init:
            init |= 1 << number[fact]
        task = GroundTask(
            name=self.task.name,
            facts=tuple(name for name, _ in names),
            operators=tuple(ordered),
            init=init,
            goal=goal,
            axioms=tuple(sorted(axioms, key=lambda a: (a.stratum, a.head, a.body, a.body_neg))),
            derived=derived,
            uses_costs=self.task.problem.minimize_cost,
        )
        return GroundTask(
            name=task.name,
            facts=task.facts,
            operators=task.operators,
            init=AxiomEvaluator(task).evaluate(init),
            goal=task.goal,
            axioms=task.axioms,
            derived=task.derived,
            uses_costs=task.uses_costs,
        )

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

    def _literals(
        self, atoms: tuple[Atom, ...], binding: Binding, number: dict[Fact, int]
    ) -> tuple[int, ...]:
        """The fact numbers of the non-static atoms; an atom without a number is never
        reached, which only negative literals can meet (and then they hold)."""
        result = set()
        for atom in atoms:
            if atom.predicate == "=" or atom.predicate in self.static:
                continue
            fact = number.get((atom.predicate, _args(atom, binding)))
            if fact is not None:
                result.add(fact)
        return tuple(sorted(result))

    def _operator(
        self,
        action: Action,
        binding: Binding,
        pre: tuple[int, ...],
        pre_neg: tuple[int, ...],
        number: dict[Fact, int],
    ) -> GroundOperator | None:
        if set(pre) & set(pre_neg):
            return None
        add = {number[(atom.predicate, _args(atom, binding))] for atom in action.add}
        delete = {
            fact
            for atom in action.delete
            if (fact := number.get((atom.predicate, _args(atom, binding)))) is not None
        }
        args = tuple(binding[param.name] for param in action.params)
        return GroundOperator(
            name=fact_name(action.name, args),
            pre=pre,
            add=tuple(sorted(add)),
            delete=tuple(sorted(delete - add)),
            cost=self._cost(action, binding) if self.task.problem.minimize_cost else 1,
            pre_neg=pre_neg,
        )

    def _cost(self, action: Action, binding: Binding) -> int:
        if action.cost is None:
            return 0
        if isinstance(action.cost, int):
            return action.cost
        term = Atom(action.cost.predicate, _args(action.cost, binding))
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


def _pair(atom: Atom) -> tuple[str, str]:
    return atom.args[0], atom.args[1]


def _args(atom: Atom, binding: Binding) -> Args:
    return tuple(binding.get(arg, arg) for arg in atom.args)
