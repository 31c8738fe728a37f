"""Relaxed reachability: which lifted rules fire, and with which bindings, when delete
effects and negative conditions are ignored.

This is a Datalog fixpoint computed semi-naively: facts wait in a queue; when one is
taken, every rule with a body atom of its predicate is joined with that atom bound to the
fact and the other atoms bound to facts already taken (or to static facts). So each rule
instance is found exactly once, when the last of its body facts is taken. Joins look facts
up through indexes on the bound argument positions, built on first use and kept current;
the order of a rule's atoms is fixed up front, checks and static atoms first.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Callable, Iterable

from attrs import frozen

from strips_framework.pddl.formulas import Atom

Args = tuple[str, ...]
Binding = dict[str, str]


class FactIndex:
    """The facts of one predicate, with indexes keyed by the values at some positions."""

    def __init__(self) -> None:
        self.all: set[Args] = set()
        self._indexes: dict[tuple[int, ...], dict[Args, list[Args]]] = {}

    def add(self, args: Args) -> None:
        self.all.add(args)
        for positions, index in self._indexes.items():
            index.setdefault(tuple(args[i] for i in positions), []).append(args)

    def matching(self, positions: tuple[int, ...], key: Args) -> list[Args]:
        index = self._indexes.get(positions)
        if index is None:
            index = {}
            for args in self.all:
                index.setdefault(tuple(args[i] for i in positions), []).append(args)
            self._indexes[positions] = index
        return index.get(key, [])


@frozen
class Rule:
    """``heads`` become reachable for every binding of ``params`` (each ranging over
    ``domains``, the objects of its type) that satisfies the positive ``body`` and the ``equal``/``unequal`` pairs.
    ``checks`` are further tests on the finished binding (e.g. static negative literals)."""

    params: tuple[str, ...]
    domains: tuple[frozenset[str], ...]
    body: tuple[Atom, ...]
    heads: tuple[Atom, ...]
    equal: tuple[tuple[str, str], ...] = ()
    unequal: tuple[tuple[str, str], ...] = ()


@frozen
class _Step:
    """Match ``atom`` against ``facts``: ``positions`` are bound when the step runs."""

    facts: FactIndex
    atom: Atom
    positions: tuple[int, ...]
    free: tuple[tuple[int, str], ...]


class Reachability:
    """The fixpoint over ``rules``; ``static`` holds the facts no rule can change."""

    def __init__(
        self,
        rules: Iterable[Rule],
        static: dict[str, FactIndex],
        check: Callable[[int, Binding], bool],
    ) -> None:
        self.rules = tuple(rules)
        self.static = static
        self.check = check
        self.dynamic: dict[str, FactIndex] = {}
        self.reached: dict[str, set[Args]] = {}
        self.instances: list[list[Args]] = [[] for _ in self.rules]
        self._seen: list[set[Args]] = [set() for _ in self.rules]
        self._queue: deque[tuple[str, Args]] = deque()
        self._triggers: dict[str, list[tuple[int, Atom, list[_Step], list[str]]]] = {}

    def run(self, init: Iterable[tuple[str, Args]]) -> None:
        for number, rule in enumerate(self.rules):
            dynamic = [atom for atom in rule.body if atom.predicate not in self.static]
            if not dynamic:
                steps, rest = self._plan(rule, set(), list(rule.body))
                self._join(number, steps, rest, 0, {})
            for atom in dynamic:
                others = list(rule.body)
                others.remove(atom)
                bound = {arg for arg in atom.args if arg.startswith("?")}
                steps, rest = self._plan(rule, bound, others)
                self._triggers.setdefault(atom.predicate, []).append((number, atom, steps, rest))
        for predicate, args in init:
            self._reach(predicate, args)
        while self._queue:
            predicate, args = self._queue.popleft()
            self._facts(predicate).add(args)
            for number, atom, steps, rest in self._triggers.get(predicate, ()):
                binding = self._unify(number, atom, args, {})
                if binding is not None:
                    self._join(number, steps, rest, 0, binding)

    def _facts(self, predicate: str) -> FactIndex:
        facts = self.static.get(predicate) or self.dynamic.get(predicate)
        if facts is None:
            facts = self.dynamic[predicate] = FactIndex()
        return facts

    def _reach(self, predicate: str, args: Args) -> None:
        known = self.reached.setdefault(predicate, set())
        if args not in known:
            known.add(args)
            self._queue.append((predicate, args))

    def _plan(
        self, rule: Rule, bound: set[str], atoms: list[Atom]
    ) -> tuple[list[_Step], list[str]]:
        """The join order: fully bound atoms first, then static, then most bound; the
        variables no atom binds are enumerated last."""
        steps = []
        bound = set(bound)
        while atoms:

            def score(atom: Atom) -> tuple[bool, bool, int]:
                known = sum(1 for arg in atom.args if not arg.startswith("?") or arg in bound)
                return (known == len(atom.args), atom.predicate in self.static, known)

            atom = max(atoms, key=score)
            atoms.remove(atom)
            positions = tuple(
                i for i, arg in enumerate(atom.args) if not arg.startswith("?") or arg in bound
            )
            free = tuple((i, arg) for i, arg in enumerate(atom.args) if i not in positions)
            steps.append(_Step(self._facts(atom.predicate), atom, positions, free))
            bound.update(arg for _, arg in free)
        return steps, [param for param in rule.params if param not in bound]

    def _unify(self, number: int, atom: Atom, args: Args, binding: Binding) -> Binding | None:
        rule = self.rules[number]
        new = dict(binding)
        for term, value in zip(atom.args, args):
            if not term.startswith("?"):
                if term != value:
                    return None
                continue
            old = new.get(term)
            if old is None:
                domain = rule.domains[rule.params.index(term)]
                if value not in domain:
                    return None
                new[term] = value
            elif old != value:
                return None
        return new

    def _join(
        self, number: int, steps: list[_Step], rest: list[str], depth: int, binding: Binding
    ) -> None:
        if depth == len(steps):
            self._enumerate(number, rest, 0, binding)
            return
        step = steps[depth]
        key = tuple(binding.get(arg, arg) for arg in (step.atom.args[i] for i in step.positions))
        if not step.free:
            if key in step.facts.all:
                self._join(number, steps, rest, depth + 1, binding)
            return
        for args in step.facts.matching(step.positions, key):
            extended = self._unify(number, step.atom, args, binding)
            if extended is not None:
                self._join(number, steps, rest, depth + 1, extended)

    def _enumerate(self, number: int, rest: list[str], depth: int, binding: Binding) -> None:
        rule = self.rules[number]
        if depth < len(rest):
            param = rest[depth]
            for value in sorted(rule.domains[rule.params.index(param)]):
                self._enumerate(number, rest, depth + 1, {**binding, param: value})
            return
        if any(binding.get(a, a) != binding.get(b, b) for a, b in rule.equal):
            return
        if any(binding.get(a, a) == binding.get(b, b) for a, b in rule.unequal):
            return
        values = tuple(binding[param] for param in rule.params)
        if values in self._seen[number] or not self.check(number, binding):
            return
        self._seen[number].add(values)
        self.instances[number].append(values)
        for head in rule.heads:
            self._reach(head.predicate, tuple(binding.get(arg, arg) for arg in head.args))
