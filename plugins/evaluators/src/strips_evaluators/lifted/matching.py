"""A join plan's tests compiled to Python functions, once per task.

The relaxed explorations (:mod:`.exploration`) match every candidate fact of every join
step: write the fact's arguments into the binding's slots, compare the repeated ones and
run the step's checks (types, ``=``/``!=``, static facts present or absent). Interpreting
those from the :class:`~.program.Step` record costs a loop and a dispatch on the check's
kind per check per candidate, which on tasks whose rules carry many inequalities and
typed parameters (organic synthesis: a dozen ``!=`` and a type per bond atom) is most of
an exploration's time. Here each step becomes one function whose body is the step's
assignments and a single ``and`` of its comparisons, written out as source and compiled
(as :func:`collections.namedtuple` builds its methods). The tests compare the compiled
functions with an interpretation of the records on random bindings.
"""

from __future__ import annotations

from collections.abc import Callable

from strips_evaluators.lifted.program import Check, Plan, RuleProgram, Step
from strips_framework.lifted.components import GroundAtom

#: ``match(fact, slots)``: binds ``fact`` into ``slots``; True when it passes the step.
Matcher = Callable[[GroundAtom, list], bool]
#: ``test(slots)``: True when the bound slots pass the checks.
Test = Callable[[list], bool]


class CompiledPlan:
    """The functions of one :class:`~.program.Plan`: ``trigger`` (None without one),
    one per step, and ``final`` for the final checks (None when there are none). Its
    free slots (bound by no atom) are split into ``preset``, ``(slot, object)`` for
    those whose type has one object (written into the slots once, before the join), and
    the ``free`` ones with their ``domains``, which every complete binding ranges over."""

    __slots__ = ("domains", "final", "free", "preset", "steps", "trigger")

    def __init__(self, plan: Plan, static: dict[str, set[GroundAtom]]) -> None:
        self.preset = tuple(
            (slot, domain[0]) for slot, domain in zip(plan.free, plan.domains) if len(domain) == 1
        )
        self.free = tuple(slot for slot, domain in zip(plan.free, plan.domains) if len(domain) != 1)
        self.domains = tuple(domain for domain in plan.domains if len(domain) != 1)
        self.trigger: Matcher | None = (
            None if plan.trigger is None else _matcher(plan.trigger, static)
        )
        self.steps: tuple[Matcher, ...] = tuple(_matcher(step, static) for step in plan.steps)
        self.final: Test | None = None
        if plan.final_checks:
            namespace: dict[str, object] = {}
            conditions = [_condition(check, namespace, static) for check in plan.final_checks]
            self.final = _compile("test", "s", [], conditions, namespace)


def compiled(program: RuleProgram, plan: Plan) -> CompiledPlan:
    """The functions of ``plan``, compiled on first use and kept with the program (a
    plan lives as long as its program, so its identity is the key)."""
    found = program.compiled.get(id(plan))
    if found is None:
        found = program.compiled[id(plan)] = CompiledPlan(plan, program.static_facts)
    return found


def _matcher(step: Step, static: dict[str, set[GroundAtom]]) -> Matcher:
    namespace: dict[str, object] = {}
    assignments = [f"s[{slot}] = fact[{position}]" for position, slot in step.binds]
    conditions = [f"fact[{position}] == s[{slot}]" for position, slot in step.repeats]
    conditions += [_condition(check, namespace, static) for check in step.checks]
    return _compile("match", "fact, s", assignments, conditions, namespace)


def _condition(
    check: Check, namespace: dict[str, object], static: dict[str, set[GroundAtom]]
) -> str:
    """``check`` as a Python expression over the slot list ``s``; the objects it needs
    (a type's domain, a static predicate's facts) go into ``namespace``."""
    slots = [f"s[{slot}]" for slot in check.slots]
    kind = check.kind
    if kind == "type":
        name = f"D{len(namespace)}"
        namespace[name] = check.domain
        return f"{slots[0]} in {name}"
    if kind == "!=":
        return f"{slots[0]} != {slots[1]}"
    if kind == "=":
        return f"{slots[0]} == {slots[1]}"
    name = f"S{len(namespace)}"
    namespace[name] = static[check.predicate]
    fact = "(" + ", ".join([repr(check.predicate), *slots]) + ",)"
    return f"{fact} {'in' if kind == 'present' else 'not in'} {name}"


def _compile(
    name: str,
    parameters: str,
    assignments: list[str],
    conditions: list[str],
    namespace: dict[str, object],
) -> Callable:
    lines = [f"def {name}({parameters}):"]
    lines += [f"    {line}" for line in assignments]
    lines.append(f"    return {' and '.join(conditions) if conditions else 'True'}")
    exec(compile("\n".join(lines), f"<compiled {name}>", "exec"), namespace)  # noqa: S102
    return namespace[name]  # type: ignore[return-value]
