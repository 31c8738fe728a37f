"""Relaxed reachability: which lifted rules fire, and with which bindings, when delete
effects and negative conditions are ignored.

This is a Datalog fixpoint computed semi-naively: facts wait in a queue; when one is
taken, every rule with a body atom of its predicate is joined with that atom bound to the
fact and the other atoms bound to facts already taken (or to static facts). So each rule
instance is found exactly once, when the last of its body facts is taken. Joins look facts
up through indexes on the bound argument positions, built on first use and kept current;
the order of a rule's atoms is fixed up front: fully bound atoms (mere tests) first, then
static atoms, then those with most arguments bound.

Inside the join a binding is a list of *slots*: one per rule parameter, followed by the
constants the rule mentions, so every atom argument is a slot number and matching a fact
is a few list reads and writes, with no dictionaries and no copies.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Iterable

from strips_framework.pddl.formulas import Atom
from strips_framework.records import Record

Args = tuple[str, ...]


class FactIndex:
    """The facts of one predicate, with indexes keyed by the values at some positions."""

    def __init__(self) -> None:
        self.all: set[Args] = set()
        self._indexes: dict[tuple[int, ...], dict[Args, list[Args]]] = {}

    def add(self, args: Args) -> None:
        self.all.add(args)
        for positions, index in self._indexes.items():
            index.setdefault(tuple([args[i] for i in positions]), []).append(args)

    def matching(self, positions: tuple[int, ...], key: Args) -> list[Args]:
        index = self._indexes.get(positions)
        if index is None:
            index = {}
            for args in self.all:
                index.setdefault(tuple([args[i] for i in positions]), []).append(args)
            self._indexes[positions] = index
        return index.get(key, [])


class Rule(Record):
    """``heads`` become reachable for every binding of ``params`` (each ranging over
    ``domains``, the objects of its type) that makes the atoms of ``body`` reachable,
    leaves the static atoms of ``absent`` false, and satisfies the ``equal`` and
    ``unequal`` pairs of terms."""

    params: tuple[str, ...]
    domains: tuple[frozenset[str], ...]
    body: tuple[Atom, ...]
    heads: tuple[Atom, ...]
    absent: tuple[Atom, ...]
    equal: tuple[tuple[str, str], ...]
    unequal: tuple[tuple[str, str], ...]
    #: Further atoms whose terms need slots: what the caller builds from an instance.
    mentions: tuple[Atom, ...]

    __slots__ = ("params", "domains", "body", "heads", "absent", "equal", "unequal", "mentions")

    def __init__(
        self,
        params: tuple[str, ...],
        domains: tuple[frozenset[str], ...],
        body: tuple[Atom, ...],
        heads: tuple[Atom, ...],
        absent: tuple[Atom, ...] = (),
        equal: tuple[tuple[str, str], ...] = (),
        unequal: tuple[tuple[str, str], ...] = (),
        mentions: tuple[Atom, ...] = (),
    ) -> None:
        self.params = params
        self.domains = domains
        self.body = body
        self.heads = heads
        self.absent = absent
        self.equal = equal
        self.unequal = unequal
        self.mentions = mentions


class Slots:
    """The slot numbers of a rule's terms: parameters first, then constants."""

    def __init__(self, rule: Rule) -> None:
        self.number = {param: i for i, param in enumerate(rule.params)}
        atoms = (*rule.body, *rule.heads, *rule.absent, *rule.mentions)
        terms = [arg for atom in atoms for arg in atom.args]
        terms += [term for pair in (*rule.equal, *rule.unequal) for term in pair]
        for term in terms:
            if term not in self.number:
                self.number[term] = len(self.number)
        self.template: list[str | None] = [None] * len(rule.params)
        self.template += [term for term in self.number if term not in rule.params]

    def of(self, args: Iterable[str]) -> tuple[int, ...]:
        return tuple(self.number[arg] for arg in args)


class _Step(Record):
    """Match ``facts`` on the ``key`` slots at ``positions``; each entry of ``free`` is
    ``(position, slot, domain, compare)``: bind the slot (checking the domain unless it is
    None) or, when ``compare``, test that it holds the value already bound."""

    facts: FactIndex
    positions: tuple[int, ...]
    key: tuple[int, ...]
    free: tuple[tuple[int, int, frozenset[str] | None, bool], ...]

    __slots__ = ("facts", "positions", "key", "free")

    def __init__(
        self,
        facts: FactIndex,
        positions: tuple[int, ...],
        key: tuple[int, ...],
        free: tuple[tuple[int, int, frozenset[str] | None, bool], ...],
    ) -> None:
        self.facts = facts
        self.positions = positions
        self.key = key
        self.free = free


class _Plan(Record):
    """A way to complete a rule's binding: join ``steps``, then enumerate ``rest``."""

    rule: int
    trigger: _Step | None
    steps: tuple[_Step, ...]
    rest: tuple[tuple[int, tuple[str, ...]], ...]

    __slots__ = ("rule", "trigger", "steps", "rest")

    def __init__(
        self,
        rule: int,
        trigger: _Step | None,
        steps: tuple[_Step, ...],
        rest: tuple[tuple[int, tuple[str, ...]], ...],
    ) -> None:
        self.rule = rule
        self.trigger = trigger
        self.steps = steps
        self.rest = rest


class _Final(Record):
    """The tests and outputs of a rule once its binding is complete, as slot numbers."""

    params: int
    absent: tuple[tuple[FactIndex, tuple[int, ...]], ...]
    equal: tuple[tuple[int, int], ...]
    unequal: tuple[tuple[int, int], ...]
    heads: tuple[tuple[str, tuple[int, ...]], ...]

    __slots__ = ("params", "absent", "equal", "unequal", "heads")

    def __init__(
        self,
        params: int,
        absent: tuple[tuple[FactIndex, tuple[int, ...]], ...],
        equal: tuple[tuple[int, int], ...],
        unequal: tuple[tuple[int, int], ...],
        heads: tuple[tuple[str, tuple[int, ...]], ...],
    ) -> None:
        self.params = params
        self.absent = absent
        self.equal = equal
        self.unequal = unequal
        self.heads = heads


class Reachability:
    """The fixpoint over ``rules``; ``static`` holds the facts no rule can change (every
    static predicate has an entry, possibly empty); ``objects`` are all the objects."""

    def __init__(
        self, rules: Iterable[Rule], static: dict[str, FactIndex], objects: frozenset[str]
    ) -> None:
        self.rules = tuple(rules)
        self.objects = objects
        self.static = static
        self.dynamic: dict[str, FactIndex] = {}
        self.reached: dict[str, set[Args]] = {}
        #: The parameter values of every instance found, per rule.
        self.instances: list[list[Args]] = [[] for _ in self.rules]
        self.slots = [Slots(rule) for rule in self.rules]
        self._seen: list[set[Args]] = [set() for _ in self.rules]
        self._queue: deque[tuple[str, Args]] = deque()
        self._finals = [self._final(number) for number in range(len(self.rules))]

    def run(self, init: Iterable[tuple[str, Args]]) -> None:
        triggers: dict[str, list[_Plan]] = {}
        for number, rule in enumerate(self.rules):
            dynamic = [atom for atom in rule.body if atom.predicate not in self.static]
            if not dynamic:
                self._complete(self._plan(number, None, list(rule.body)), 0, self._values(number))
            for atom in dynamic:
                others = list(rule.body)
                others.remove(atom)
                triggers.setdefault(atom.predicate, []).append(self._plan(number, atom, others))
        for predicate, args in init:
            self._reach(predicate, args)
        while self._queue:
            predicate, args = self._queue.popleft()
            self._facts(predicate).add(args)
            for plan in triggers.get(predicate, ()):
                values = self._values(plan.rule)
                if _match(plan.trigger, args, values):  # type: ignore[arg-type]
                    self._complete(plan, 0, values)

    def _values(self, number: int) -> list[str | None]:
        return list(self.slots[number].template)

    def _facts(self, predicate: str) -> FactIndex:
        facts = self.static.get(predicate) or self.dynamic.get(predicate)
        if facts is None:
            facts = self.dynamic[predicate] = FactIndex()
        return facts

    def _reach(self, predicate: str, args: Args) -> None:
        known = self.reached.get(predicate)
        if known is None:
            known = self.reached[predicate] = set()
        if args not in known:
            known.add(args)
            self._queue.append((predicate, args))

    def _plan(self, number: int, trigger: Atom | None, atoms: list[Atom]) -> _Plan:
        rule, slots = self.rules[number], self.slots[number]
        bound = {slot for slot, value in enumerate(slots.template) if value is not None}
        first = None
        if trigger is not None:
            first = self._step(number, trigger, set(), bound)
        steps = []
        while atoms:

            def score(atom: Atom) -> tuple[bool, bool, int]:
                known = sum(1 for slot in slots.of(atom.args) if slot in bound)
                return (known == len(atom.args), atom.predicate in self.static, known)

            atom = max(atoms, key=score)
            atoms.remove(atom)
            steps.append(self._step(number, atom, set(bound), bound))
        rest = tuple(
            (slot, tuple(sorted(rule.domains[slot])))
            for slot in range(len(rule.params))
            if slot not in bound
        )
        return _Plan(number, first, tuple(steps), rest)

    def _step(self, number: int, atom: Atom, before: set[int], bound: set[int]) -> _Step:
        """A step matching ``atom`` when the slots ``before`` are bound; adds the slots it
        binds to ``bound``."""
        rule, slots = self.rules[number], self.slots[number]
        arg_slots = slots.of(atom.args)
        positions = tuple(i for i, slot in enumerate(arg_slots) if slot in before)
        free = []
        for position, slot in enumerate(arg_slots):
            if slot in before:
                continue
            domain = rule.domains[slot] if slot < len(rule.params) else None
            if domain is not None and len(domain) == len(self.objects):
                domain = None  # every object: nothing to check
            free.append((position, slot, domain, slot in bound))
            bound.add(slot)
        return _Step(
            self._facts(atom.predicate),
            positions,
            tuple(arg_slots[i] for i in positions),
            tuple(free),
        )

    def _final(self, number: int) -> _Final:
        rule, slots = self.rules[number], self.slots[number]
        return _Final(
            len(rule.params),
            tuple((self._facts(a.predicate), slots.of(a.args)) for a in rule.absent),
            tuple((slots.number[a], slots.number[b]) for a, b in rule.equal),
            tuple((slots.number[a], slots.number[b]) for a, b in rule.unequal),
            tuple((head.predicate, slots.of(head.args)) for head in rule.heads),
        )

    def _complete(self, plan: _Plan, depth: int, values: list) -> None:
        if depth < len(plan.steps):
            step = plan.steps[depth]
            key = tuple([values[slot] for slot in step.key])
            if not step.free:
                if key in step.facts.all:
                    self._complete(plan, depth + 1, values)
                return
            for args in step.facts.matching(step.positions, key):
                if _match(step, args, values):
                    self._complete(plan, depth + 1, values)
        else:
            self._enumerate(plan, 0, values)

    def _enumerate(self, plan: _Plan, depth: int, values: list) -> None:
        if depth < len(plan.rest):
            slot, domain = plan.rest[depth]
            for value in domain:
                values[slot] = value
                self._enumerate(plan, depth + 1, values)
            return
        final = self._finals[plan.rule]
        for a, b in final.equal:
            if values[a] != values[b]:
                return
        for a, b in final.unequal:
            if values[a] == values[b]:
                return
        for facts, slots in final.absent:
            if tuple([values[slot] for slot in slots]) in facts.all:
                return
        key = tuple(values[: final.params])
        seen = self._seen[plan.rule]
        if key in seen:
            return
        seen.add(key)
        self.instances[plan.rule].append(key)
        for predicate, slots in final.heads:
            self._reach(predicate, tuple([values[slot] for slot in slots]))


def _match(step: _Step, args: Args, values: list) -> bool:
    """Bind the free slots of ``step`` to ``args``; False when a value does not fit."""
    for position, slot, domain, compare in step.free:
        value = args[position]
        if compare:
            if values[slot] != value:
                return False
        elif domain is not None and value not in domain:
            return False
        else:
            values[slot] = value
    return True
