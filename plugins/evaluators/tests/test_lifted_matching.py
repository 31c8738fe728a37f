"""The compiled join-step functions (:mod:`strips_evaluators.lifted.matching`) against an
interpretation of the step records they are compiled from, on random bindings and
candidate facts of the rules of seeded random tasks (types, constants, equality,
inequality, negated static atoms)."""

from __future__ import annotations

import random

from random_pddl import random_pddl_task

from strips_evaluators.lifted.matching import compiled
from strips_evaluators.lifted.program import Check, Plan, Program, Step
from strips_framework.lifted.components import GroundAtom


def _passes(checks: tuple[Check, ...], slots: list, static: dict[str, set[GroundAtom]]) -> bool:
    """What a check means (the reference the compiled expressions must agree with)."""
    for check in checks:
        values = [slots[s] for s in check.slots]
        if check.kind == "type":
            ok = values[0] in check.domain
        elif check.kind == "!=":
            ok = values[0] != values[1]
        elif check.kind == "=":
            ok = values[0] == values[1]
        else:
            ok = ((check.predicate, *values) in static[check.predicate]) == (
                check.kind == "present"
            )
        if not ok:
            return False
    return True


def _match(step: Step, fact: GroundAtom, slots: list, static: dict[str, set[GroundAtom]]) -> bool:
    for position, slot in step.binds:
        slots[slot] = fact[position]
    for position, slot in step.repeats:
        if fact[position] != slots[slot]:
            return False
    return _passes(step.checks, slots, static)


def _candidate(step: Step, slots: list, pool: list[str], rng: random.Random) -> GroundAtom:
    """A fact of the step's predicate that agrees with ``slots`` on the key (as the index
    lookup guarantees), random elsewhere."""
    size = max(
        [p for p, _ in step.binds] + [p for p, _ in step.repeats] + list(step.positions), default=0
    )
    fact = [rng.choice(pool) for _ in range(size)]
    for position, slot in zip(step.positions, step.key):
        fact[position - 1] = slots[slot]
    return (step.predicate, *fact)


def _plans(program: Program) -> list[Plan]:
    plans = [plan for plans in program.triggers.values() for plan in plans]
    return plans + list(program.unconditional) + list(program.derivations)


def test_compiled_steps_and_final_checks_agree_with_the_records() -> None:
    rng = random.Random(7)
    kinds: set[str] = set()
    compared = 0
    for seed in range(40):
        program = Program(random_pddl_task(seed))
        static = program.static_facts
        pool = sorted(program.objects) + ["@no-such-object"]
        for plan in _plans(program):
            functions = compiled(program, plan)
            steps = [(plan.trigger, functions.trigger)] if plan.trigger is not None else []
            steps += list(zip(plan.steps, functions.steps))
            for step, function in steps:
                kinds.update(check.kind for check in step.checks)
                for _ in range(20):
                    slots = [
                        value if value is not None else rng.choice(pool)
                        for value in plan.rule.template
                    ]
                    fact = _candidate(step, slots, pool, rng)
                    expected_slots = list(slots)
                    expected = _match(step, fact, expected_slots, static)
                    assert function(fact, slots) == expected, (step, fact)
                    assert slots == expected_slots
                    compared += 1
            kinds.update(check.kind for check in plan.final_checks)
            for _ in range(20):
                slots = [
                    value if value is not None else rng.choice(pool) for value in plan.rule.template
                ]
                expected = _passes(plan.final_checks, slots, static)
                assert (functions.final is None or functions.final(slots)) == expected
    assert compared > 1000
    assert {"type", "!=", "=", "absent", "present"} <= kinds, kinds


def test_a_plan_is_compiled_once() -> None:
    program = Program(random_pddl_task(1))
    plan = _plans(program)[0]
    assert compiled(program, plan) is compiled(program, plan)


def test_free_slots_of_a_one_object_type_are_preset_and_the_others_range() -> None:
    """A slot no atom binds ranges over its type's objects at every complete binding;
    with one object it is written once, before the join."""
    seen_preset = seen_free = False
    for seed in range(40):
        program = Program(random_pddl_task(seed))
        for plan in _plans(program):
            functions = compiled(program, plan)
            domains = dict(zip(plan.free, plan.domains))
            assert sorted([slot for slot, _ in functions.preset] + list(functions.free)) == sorted(plan.free)
            for slot, value in functions.preset:
                assert domains[slot] == (value,)
            assert functions.domains == tuple(domains[slot] for slot in functions.free)
            assert all(len(domain) > 1 for domain in functions.domains)
            seen_preset |= bool(functions.preset)
            seen_free |= bool(functions.free)
    assert seen_preset and seen_free
