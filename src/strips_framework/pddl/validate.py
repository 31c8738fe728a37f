"""Checking a plan against the lifted task, independently of grounding.

The validator evaluates preconditions and the goal as PDDL formulas over a set of ground
atoms (closed world), computes derived predicates by a stratified fixpoint over the typed
objects, and applies effects deletes-first, conditional effects (``when``, ``forall``)
evaluated on the state before the step. Because it shares nothing with the grounder
but the reader, it also checks the grounder: a plan forward search found on the ground
task must be valid here. A failing check explains the first failing step: the
precondition part that is false, with the action's bindings, or the goal part not reached.
"""

from __future__ import annotations

import re
from collections.abc import Iterator, Sequence
from itertools import product

from strips_framework.pddl.formulas import (
    And,
    Atom,
    Exists,
    Forall,
    Formula,
    Imply,
    Not,
    Or,
    Parameter,
    show,
    substitute,
)
from strips_framework.pddl.task import Action, PddlTask, missing_cost
from strips_framework.records import Record

GroundAtom = tuple[str, tuple[str, ...]]
State = frozenset[GroundAtom]


class PlanCheck(Record):
    """The verdict on a plan; ``cost`` is the total cost (the length without costs)."""

    valid: bool
    message: str
    cost: int

    __slots__ = ("valid", "message", "cost")

    def __init__(self, valid: bool, message: str, cost: int) -> None:
        self.valid = valid
        self.message = message
        self.cost = cost


def validate_plan(task: PddlTask, steps: Sequence[str]) -> PlanCheck:
    """Replay ``steps`` from the initial state and check the goal."""
    return PlanValidator(task).check(steps)


class PlanValidator:
    """PDDL semantics on the lifted task: states are sets of ground atoms without the
    derived ones, which :meth:`closure` adds."""

    def __init__(self, task: PddlTask) -> None:
        self.task = task
        self.actions = {action.name: action for action in task.domain.actions}
        self.derived = {rule.head.predicate for rule in task.domain.derived}
        self.strata = _strata(task)
        self.numeric = dict(task.problem.numeric)

    def initial(self) -> State:
        return frozenset(
            (atom.predicate, atom.args)
            for atom in self.task.problem.init
            if atom.predicate not in self.derived
        )

    def successor(
        self, state: State, action: Action, binding: dict[str, str], model: State | None = None
    ) -> State:
        """The state after ``action``: deletes first, then adds. Conditional effects fire
        for the bindings of their variables whose condition holds in ``model``, the
        closure of ``state`` (computed when not given)."""
        deleted, added = _ground(action.delete, binding), _ground(action.add, binding)
        if action.conditional:
            model = self.closure(state) if model is None else model
            for effect in action.conditional:
                names = [param.name for param in effect.params]
                for values in self._bindings(effect.params):
                    inner = {**binding, **dict(zip(names, values))}
                    if self.holds(effect.condition, inner, model):
                        deleted |= _ground(effect.delete, inner)
                        added |= _ground(effect.add, inner)
        return frozenset((state - deleted) | added)

    def check(self, steps: Sequence[str]) -> PlanCheck:
        state = self.initial()
        cost = 0
        for number, text in enumerate(steps, start=1):
            parsed = self.step(text)
            if isinstance(parsed, str):
                return PlanCheck(False, f"step {number} {text}: {parsed}", cost)
            action, binding = parsed
            model = self.closure(state)
            if not self.holds(action.precondition, binding, model):
                reason = self._why_not(action.precondition, binding, model)
                shown = ", ".join(f"{name} = {value}" for name, value in binding.items())
                where = f" with {shown}" if shown else ""
                return PlanCheck(
                    False,
                    f"step {number} {_step_text(action, binding)}: precondition not "
                    f"satisfied{where}: {reason}",
                    cost,
                )
            state = self.successor(state, action, binding, model)
            cost += self._cost(action, binding)
        model = self.closure(state)
        goal = self.task.problem.goal
        if not self.holds(goal, {}, model):
            return PlanCheck(
                False,
                f"goal not reached after {len(steps)} steps: {self._why_not(goal, {}, model)}",
                cost,
            )
        kind = "general cost" if self.task.problem.minimize_cost else "unit cost"
        return PlanCheck(True, f"plan valid: {len(steps)} steps, cost {cost} ({kind})", cost)

    def step(self, text: str) -> tuple[Action, dict[str, str]] | str:
        """The action and binding of ``(name arg ...)``, or what is wrong with it."""
        words = re.sub(r"[()]", " ", text.lower()).split()
        if not words or not re.fullmatch(r"\s*\([^()]*\)\s*", text):
            return "expected '(action arg ...)'"
        action = self.actions.get(words[0])
        if action is None:
            return f"unknown action {words[0]!r}"
        args = words[1:]
        if len(args) != len(action.params):
            return f"action {action.name!r} takes {len(action.params)} arguments, found {len(args)}"
        for param, value in zip(action.params, args):
            if value not in self.task.objects_of(param.types):
                return (
                    f"{value!r} is not an object of type {' or '.join(param.types)} ({param.name})"
                )
        return action, dict(zip((param.name for param in action.params), args))

    def _cost(self, action: Action, binding: dict[str, str]) -> int:
        if not self.task.problem.minimize_cost:
            return 1
        if action.cost is None:
            return 0
        if isinstance(action.cost, int):
            return action.cost
        term = Atom(action.cost.predicate, substitute(action.cost.args, binding))
        if term not in self.numeric:
            raise missing_cost(self.task, term, action)
        return self.numeric[term]

    def closure(self, state: State) -> State:
        """``state`` with the derived atoms added, stratum by stratum."""
        if not self.derived:
            return state
        model = set(state)
        for stratum in self.strata:
            changed = True
            while changed:
                changed = False
                for rule in stratum:
                    names = [param.name for param in rule.params]
                    for values in self._bindings(rule.params):
                        binding = dict(zip(names, values))
                        head = (rule.head.predicate, substitute(rule.head.args, binding))
                        if head not in model and self.holds(rule.body, binding, model):
                            model.add(head)
                            changed = True
        return frozenset(model)

    def _bindings(self, params: tuple[Parameter, ...]) -> Iterator[tuple[str, ...]]:
        return product(*(self.task.objects_of(param.types) for param in params))

    def holds(
        self, formula: Formula, binding: dict[str, str], model: State | set[GroundAtom]
    ) -> bool:
        if isinstance(formula, Atom):
            args = substitute(formula.args, binding)
            if formula.predicate == "=":
                return args[0] == args[1]
            return (formula.predicate, args) in model
        if isinstance(formula, Not):
            return not self.holds(formula.part, binding, model)
        if isinstance(formula, And):
            return all(self.holds(part, binding, model) for part in formula.parts)
        if isinstance(formula, Or):
            return any(self.holds(part, binding, model) for part in formula.parts)
        if isinstance(formula, Imply):
            return not self.holds(formula.condition, binding, model) or self.holds(
                formula.consequence, binding, model
            )
        names = [param.name for param in formula.params]
        results = (
            self.holds(formula.body, {**binding, **dict(zip(names, values))}, model)
            for values in self._bindings(formula.params)
        )
        return any(results) if isinstance(formula, Exists) else all(results)

    def _why_not(self, formula: Formula, binding: dict[str, str], model: State) -> str:
        """The first conjunct of ``formula`` that is false, shown ground where possible."""
        if isinstance(formula, And):
            for part in formula.parts:
                if not self.holds(part, binding, model):
                    return self._why_not(part, binding, model)
        if isinstance(formula, Imply):
            return self._why_not(formula.consequence, binding, model)
        if isinstance(formula, Atom):
            return f"{Atom(formula.predicate, substitute(formula.args, binding))} is false"
        if isinstance(formula, Not) and isinstance(formula.part, Atom):
            part = formula.part
            return f"{Atom(part.predicate, substitute(part.args, binding))} is true"
        if isinstance(formula, Forall):
            names = [param.name for param in formula.params]
            for values in self._bindings(formula.params):
                inner = {**binding, **dict(zip(names, values))}
                if not self.holds(formula.body, inner, model):
                    shown = ", ".join(f"{n} = {v}" for n, v in zip(names, values))
                    return f"{self._why_not(formula.body, inner, model)} (for {shown})"
        return f"{show(formula)} is false"


def _ground(atoms: tuple[Atom, ...], binding: dict[str, str]) -> set[GroundAtom]:
    return {(atom.predicate, substitute(atom.args, binding)) for atom in atoms}


def _step_text(action: Action, binding: dict[str, str]) -> str:
    return "(" + " ".join((action.name, *(binding[param.name] for param in action.params))) + ")"


def _strata(task: PddlTask) -> list[list]:
    """The derived predicates' rules grouped into strata (negated uses in lower ones)."""
    rules = task.domain.derived
    derived = {rule.head.predicate for rule in rules}
    level = dict.fromkeys(derived, 0)
    for _ in range(len(derived) + 1):
        changed = False
        for rule in rules:
            for predicate, negated in _uses(rule.body, False):
                if predicate in derived:
                    needed = level[predicate] + (1 if negated else 0)
                    if level[rule.head.predicate] < needed:
                        level[rule.head.predicate] = needed
                        changed = True
        if not changed:
            break
    strata: list[list] = [[] for _ in range(max(level.values(), default=-1) + 1)]
    for rule in rules:
        strata[level[rule.head.predicate]].append(rule)
    return strata


def _uses(formula: Formula, negated: bool) -> Iterator[tuple[str, bool]]:
    """The predicates of ``formula`` with whether they occur under negation."""
    if isinstance(formula, Atom):
        yield formula.predicate, negated
    elif isinstance(formula, Not):
        yield from _uses(formula.part, not negated)
    elif isinstance(formula, And | Or):
        for part in formula.parts:
            yield from _uses(part, negated)
    elif isinstance(formula, Imply):
        yield from _uses(formula.condition, not negated)
        yield from _uses(formula.consequence, negated)
    else:
        yield from _uses(formula.body, negated)
