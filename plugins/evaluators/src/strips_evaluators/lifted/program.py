"""The delete relaxation of a lifted PDDL task as a Datalog program, compiled once per task.

Every action becomes one rule per disjunct of its normalized precondition: the rule's body
is the disjunct's positive atoms, its heads the action's add effects, its cost the
action's. A conditional effect becomes a rule per (precondition disjunct, condition
disjunct) pair whose body joins both and whose heads are the effect's adds, at the
action's cost; a derived predicate (and an auxiliary one the normalizer makes for a
universal condition) a zero-cost rule; a goal that is not a conjunction of atoms the
zero-cost rules of the derived atom ``(@goal)``. This is exactly the relaxation the ground
heuristics use (:mod:`strips_evaluators.heuristics.relaxation`), read before grounding:
negative literals over fluent or derived predicates are ignored, negative static literals,
equalities and the parameters' types are checked, and nothing is enumerated up front but
the instances of rules whose body has no fluent atom (they hold in every state).

A rule is evaluated semi-naively by :mod:`.exploration`: when a fact is settled, every
rule with a body atom of its predicate is joined with that atom bound to the fact and the
other atoms bound to facts settled before (a :class:`Plan` per such *trigger* atom). A
binding is a list of *slots*, one per rule variable followed by the constants the rule
mentions, so every term is a slot number. Facts are the state's tuples
``(predicate, object, ...)``, so an argument's position in a fact is its position in the
atom plus one.
"""

from __future__ import annotations

from collections.abc import Iterator
from itertools import product

from strips_framework.errors import InputError
from strips_framework.grounding.normalize import Clause, Normalizer
from strips_framework.lifted.components import GroundAtom, static_predicates
from strips_framework.pddl.formulas import Atom, Parameter
from strips_framework.pddl.task import Action, PddlTask, missing_cost
from strips_framework.records import Record

#: The derived atom that stands for a goal which is not a conjunction of atoms (as in
#: grounding).
GOAL: GroundAtom = ("@goal",)
#: ``Rule.action`` of a rule that comes from a derived predicate or the goal.
AXIOM = -1


class Check(Record):
    """A test on a binding, run as soon as its slots are bound: ``kind`` is ``"="``,
    ``"!="`` (two slots), ``"type"`` (slot ``a`` in ``domain``) or ``"absent"`` (the
    static fact ``(predicate, *slots)`` does not hold)."""

    kind: str
    slots: tuple[int, ...]
    predicate: str
    domain: frozenset[str]

    __slots__ = ("kind", "slots", "predicate", "domain")

    def __init__(
        self,
        kind: str,
        slots: tuple[int, ...],
        predicate: str = "",
        domain: frozenset[str] = frozenset(),
    ) -> None:
        self.kind = kind
        self.slots = slots
        self.predicate = predicate
        self.domain = domain


class Step(Record):
    """Match the facts of ``predicate`` whose arguments at ``positions`` are the values
    of the ``key`` slots (an index lookup); bind ``binds`` ``(position, slot)``, test
    that ``repeats`` ``(position, slot)`` equal slots bound in this same fact, then run
    ``checks``. ``fluent`` steps match facts settled in the state, the others static
    facts; ``before_trigger`` steps must not match the trigger fact itself (so a rule
    instance is found once, from its first atom that the new fact matches)."""

    predicate: str
    positions: tuple[int, ...]
    key: tuple[int, ...]
    binds: tuple[tuple[int, int], ...]
    repeats: tuple[tuple[int, int], ...]
    checks: tuple[Check, ...]
    fluent: bool
    before_trigger: bool

    __slots__ = (
        "predicate", "positions", "key", "binds", "repeats", "checks", "fluent",
        "before_trigger",
    )  # fmt: skip

    def __init__(
        self,
        predicate: str,
        positions: tuple[int, ...],
        key: tuple[int, ...],
        binds: tuple[tuple[int, int], ...],
        repeats: tuple[tuple[int, int], ...],
        checks: tuple[Check, ...],
        fluent: bool,
        before_trigger: bool,
    ) -> None:
        self.predicate = predicate
        self.positions = positions
        self.key = key
        self.binds = binds
        self.repeats = repeats
        self.checks = checks
        self.fluent = fluent
        self.before_trigger = before_trigger


class Plan(Record):
    """How to complete a binding of ``rule``: the ``trigger`` step (None for the plan
    that starts from nothing) binds the new fact, then ``steps`` join the other atoms,
    then the ``free`` slots no atom binds range over their ``domains`` (with
    ``final_checks``)."""

    rule: Rule
    trigger: Step | None
    steps: tuple[Step, ...]
    free: tuple[int, ...]
    domains: tuple[tuple[str, ...], ...]
    final_checks: tuple[Check, ...]

    __slots__ = ("rule", "trigger", "steps", "free", "domains", "final_checks")

    def __init__(
        self,
        rule: Rule,
        trigger: Step | None,
        steps: tuple[Step, ...],
        free: tuple[int, ...],
        domains: tuple[tuple[str, ...], ...],
        final_checks: tuple[Check, ...],
    ) -> None:
        self.rule = rule
        self.trigger = trigger
        self.steps = steps
        self.free = free
        self.domains = domains
        self.final_checks = final_checks


class Rule(Record):
    """One relaxed rule. ``template`` is the initial slot list (``None`` for variables,
    then the constants); ``heads`` and ``negative`` are ``(predicate, slots)``;
    ``action`` indexes ``task.domain.actions`` (or is :data:`AXIOM`), ``arity`` is the
    number of the action's parameters (the first slots); the ground operator an instance
    belongs to is its action, ``operator`` (the precondition disjunct) and its first
    ``identity`` slots (the action's parameters and the disjunct's own variables). ``cost`` is the constant
    cost, or ``None`` when ``cost_term`` ``(function, slots)`` gives it per instance."""

    number: int
    template: tuple[str | None, ...]
    heads: tuple[tuple[str, tuple[int, ...]], ...]
    negative: tuple[tuple[str, tuple[int, ...]], ...]
    action: int
    arity: int
    operator: int
    identity: int
    cost: int | None
    cost_term: tuple[str, tuple[int, ...]]
    #: True when two body atoms share a predicate, so an instance may list a fact twice
    #: (the ground relaxation counts a precondition once).
    repeated_predicates: bool

    __slots__ = (
        "number", "template", "heads", "negative", "action", "arity", "operator", "identity", "cost",
        "cost_term", "repeated_predicates",
    )  # fmt: skip

    def __init__(
        self,
        number: int,
        template: tuple[str | None, ...],
        heads: tuple[tuple[str, tuple[int, ...]], ...],
        negative: tuple[tuple[str, tuple[int, ...]], ...],
        action: int,
        arity: int,
        operator: int,
        identity: int,
        cost: int | None,
        cost_term: tuple[str, tuple[int, ...]],
        repeated_predicates: bool,
    ) -> None:
        self.number = number
        self.template = template
        self.heads = heads
        self.negative = negative
        self.action = action
        self.arity = arity
        self.operator = operator
        self.identity = identity
        self.cost = cost
        self.cost_term = cost_term
        self.repeated_predicates = repeated_predicates


class Program:
    """The relaxed program of one task (see the module docstring)."""

    def __init__(self, task: PddlTask) -> None:
        self.task = task
        self.static = static_predicates(task)
        self.derived = {rule.head.predicate for rule in task.domain.derived}
        self.objects = frozenset(task.objects_of(("object",)))
        #: Static facts by predicate, from the initial state.
        self.static_facts: dict[str, set[GroundAtom]] = {name: set() for name in self.static}
        for atom in task.problem.init:
            if atom.predicate in self.static:
                self.static_facts[atom.predicate].add((atom.predicate, *atom.args))
        self.numeric = {
            (term.predicate, *term.args): value for term, value in task.problem.numeric
        }
        self.rules: list[Rule] = []
        #: Per fluent (or derived) predicate, the plans it triggers.
        self.triggers: dict[str, list[Plan]] = {}
        #: Plans of rules without fluent body atoms: their instances hold in every state.
        self.unconditional: list[Plan] = []
        #: Plans that derive a derived predicate's facts from nothing (a full join), for
        #: the exact evaluation of derived predicates in a state (:mod:`.closure`).
        self.derivations: list[Plan] = []
        #: Index keys ``(predicate, positions)`` the plans look facts up with.
        self.fluent_indexes: dict[str, list[tuple[int, ...]]] = {}
        self.static_indexes: dict[tuple[str, tuple[int, ...]], dict[tuple[str, ...], list]] = {}
        normalizer = Normalizer(task)
        for number, action in enumerate(task.domain.actions):
            for operator, clause in enumerate(normalizer.clauses(action.precondition)):
                self._add(clause, action.params, action.add, number, operator, action)
                for effect in action.conditional:
                    if not effect.add:
                        continue
                    for condition in normalizer.clauses(effect.condition):
                        self._add(
                            clause.join(Clause(effect.params)).join(condition),
                            action.params,
                            effect.add,
                            number,
                            operator,
                            action,
                            identity=len(action.params) + len(clause.params),
                        )
        for derived in task.domain.derived:
            for clause in normalizer.clauses(derived.body):
                self._add(clause, derived.params, (derived.head,), AXIOM, 0, None)
        goal_clauses = normalizer.clauses(task.problem.goal)
        self.goal: tuple[GroundAtom, ...]
        if len(goal_clauses) == 1 and not goal_clauses[0].params and not goal_clauses[0].negative:
            atoms = [atom for atom in goal_clauses[0].positive if atom.predicate != "="]
            self.goal = tuple(dict.fromkeys((atom.predicate, *atom.args) for atom in atoms))
        else:
            self.goal = (GOAL,)
            for clause in goal_clauses:
                self._add(clause, (), (Atom(GOAL[0], ()),), AXIOM, 0, None)
        done = 0
        while done < len(normalizer.auxiliary):  # their bodies may add more
            auxiliary = normalizer.auxiliary[done]
            done += 1
            self.derived.add(auxiliary.head.predicate)
            for clause in normalizer.clauses(auxiliary.body):
                self._add(clause, auxiliary.params, (auxiliary.head,), AXIOM, 0, None)
        self.derived.add(GOAL[0])
        #: Goal facts of static predicates that do not hold: no state reaches the goal.
        self.static_goal_missing = sum(
            1
            for fact in self.goal
            if fact[0] in self.static and fact not in self.static_facts[fact[0]]
        )
        #: The goal facts a state can change (fluent or derived ones).
        self.fluent_goal = tuple(fact for fact in self.goal if fact[0] not in self.static)
        for (predicate, positions), index in self.static_indexes.items():
            for fact in self.static_facts.get(predicate, ()):
                index.setdefault(tuple([fact[i] for i in positions]), []).append(fact)

    def cost_of(self, rule: Rule, slots: list[str]) -> int:
        """The cost of the instance of ``rule`` with these slot values."""
        if rule.cost is not None:
            return rule.cost
        function, arguments = rule.cost_term
        term = (function, *[slots[i] for i in arguments])
        value = self.numeric.get(term)
        if value is None:
            action = self.task.domain.actions[rule.action]
            raise missing_cost(self.task, Atom(function, term[1:]), action)
        return value

    def _add(
        self,
        clause: Clause,
        params: tuple[Parameter, ...],
        heads: tuple[Atom, ...],
        action: int,
        operator: int,
        source: Action | None,
        identity: int | None = None,
    ) -> None:
        everything = params + clause.params
        slot = {param.name: i for i, param in enumerate(everything)}
        mentioned = [arg for atom in (*clause.positive, *clause.negative, *heads) for arg in atom.args]
        if source is not None and isinstance(source.cost, Atom):
            mentioned += source.cost.args
        for term in mentioned:
            if term not in slot:
                if term.startswith("?"):
                    raise InputError(
                        self.task.domain_path, source.line if source else None, None,
                        f"variable {term} is not a parameter",
                    )
                slot[term] = len(slot)
        template = (None,) * len(everything) + tuple(list(slot)[len(everything):])
        body = [atom for atom in clause.positive if atom.predicate != "="]
        checks = [Check("=", (slot[a.args[0]], slot[a.args[1]]))
                  for a in clause.positive if a.predicate == "="]  # fmt: skip
        checks += [Check("!=", (slot[a.args[0]], slot[a.args[1]]))
                   for a in clause.negative if a.predicate == "="]  # fmt: skip
        checks += [
            Check("absent", tuple(slot[arg] for arg in a.args), a.predicate)
            for a in clause.negative
            if a.predicate in self.static
        ]
        for i, param in enumerate(everything):
            domain = frozenset(self.task.objects_of(param.types))
            if domain != self.objects:
                checks.append(Check("type", (i,), domain=domain))
        cost: int | None = 1
        cost_term: tuple[str, tuple[int, ...]] = ("", ())
        if source is None:
            cost = 0
        elif self.task.problem.minimize_cost:
            if source.cost is None:
                cost = 0
            elif isinstance(source.cost, int):
                cost = source.cost
            else:
                cost = None
                cost_term = (source.cost.predicate, tuple(slot[a] for a in source.cost.args))
        predicates = [atom.predicate for atom in body]
        rule = Rule(
            number=len(self.rules),
            template=template,
            heads=tuple((a.predicate, tuple(slot[arg] for arg in a.args)) for a in heads),
            negative=tuple(
                (a.predicate, tuple(slot[arg] for arg in a.args))
                for a in clause.negative
                if a.predicate != "=" and a.predicate not in self.static
            ),
            action=action,
            arity=len(params) if action != AXIOM else 0,
            operator=operator,
            identity=len(everything) if identity is None else identity,
            cost=cost,
            cost_term=cost_term,
            repeated_predicates=len(set(predicates)) < len(predicates),
        )
        self.rules.append(rule)
        atoms = [(a.predicate, tuple(slot[arg] for arg in a.args)) for a in body]
        domains = {i: self.task.objects_of(p.types) for i, p in enumerate(everything)}
        fluent = [i for i, (predicate, _) in enumerate(atoms) if predicate not in self.static]
        if action == AXIOM:
            self.derivations.append(self._plan(rule, atoms, None, checks, domains, len(everything)))
        if not fluent:
            self.unconditional.append(self._plan(rule, atoms, None, checks, domains, len(everything)))
        for position in fluent:
            plan = self._plan(rule, atoms, position, checks, domains, len(everything))
            self.triggers.setdefault(atoms[position][0], []).append(plan)

    def _plan(
        self,
        rule: Rule,
        atoms: list[tuple[str, tuple[int, ...]]],
        trigger: int | None,
        checks: list[Check],
        domains: dict[int, tuple[str, ...]],
        variables: int,
    ) -> Plan:
        """The join order: the trigger first, then greedily the atom with most bound
        arguments (static ones first among equals: they filter without growing)."""
        bound = set(range(variables, len(rule.template)))  # constants
        pending = list(checks)
        first = None
        if trigger is not None:
            first = self._step(atoms[trigger], bound, pending, fluent=True, before=False, trigger=True)
        rest = [i for i in range(len(atoms)) if i != trigger]
        steps = []
        while rest:
            def score(i: int) -> tuple[int, int, int]:
                predicate, terms = atoms[i]
                known = sum(1 for t in terms if t in bound)
                return (known == len(terms), known, predicate in self.static)

            best = max(rest, key=score)
            rest.remove(best)
            predicate = atoms[best][0]
            is_fluent = predicate not in self.static
            before = trigger is not None and is_fluent and best < trigger
            steps.append(self._step(atoms[best], bound, pending, is_fluent, before))
        free = tuple(i for i in range(variables) if i not in bound)
        return Plan(
            rule=rule,
            trigger=first,
            steps=tuple(steps),
            free=free,
            domains=tuple(domains[i] for i in free),
            final_checks=tuple(pending),
        )

    def _step(
        self,
        atom: tuple[str, tuple[int, ...]],
        bound: set[int],
        pending: list[Check],
        fluent: bool,
        before: bool,
        trigger: bool = False,
    ) -> Step:
        predicate, terms = atom
        positions, key, binds, repeats = [], [], [], []
        newly: set[int] = set()
        for position, term in enumerate(terms, start=1):
            if term in bound and not trigger:
                positions.append(position)
                key.append(term)
            elif term in bound or term in newly:
                repeats.append((position, term))
            else:
                binds.append((position, term))
                newly.add(term)
        bound |= newly
        ready = [check for check in pending if all(s in bound for s in check.slots)]
        for check in ready:
            pending.remove(check)
        if not trigger:
            table = self.fluent_indexes if fluent else None
            if table is not None:
                table.setdefault(predicate, [])
                if tuple(positions) not in table[predicate]:
                    table[predicate].append(tuple(positions))
            else:
                self.static_indexes.setdefault((predicate, tuple(positions)), {})
        return Step(
            predicate=predicate,
            positions=tuple(positions),
            key=tuple(key),
            binds=tuple(binds),
            repeats=tuple(repeats),
            checks=tuple(ready),
            fluent=fluent,
            before_trigger=before,
        )

    def instances(self, plan: Plan, slots: list[str]) -> Iterator[None]:
        """Complete a binding whose atoms are all matched: every assignment of the free
        slots (over their types' objects) that passes the final checks, written into
        ``slots``; one ``None`` per assignment."""
        if not plan.free:
            if passes(plan.final_checks, slots, self.static_facts):
                yield None
            return
        for values in product(*plan.domains):
            for slot, value in zip(plan.free, values):
                slots[slot] = value
            if passes(plan.final_checks, slots, self.static_facts):
                yield None


def passes(checks: tuple[Check, ...], slots: list[str], static: dict[str, set[GroundAtom]]) -> bool:
    for check in checks:
        kind = check.kind
        if kind == "type":
            if slots[check.slots[0]] not in check.domain:
                return False
        elif kind == "!=":
            if slots[check.slots[0]] == slots[check.slots[1]]:
                return False
        elif kind == "=":
            if slots[check.slots[0]] != slots[check.slots[1]]:
                return False
        elif (check.predicate, *[slots[s] for s in check.slots]) in static[check.predicate]:
            return False
    return True
