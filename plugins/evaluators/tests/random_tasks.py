"""Seeded random ground tasks for the heuristic tests: costs (zero included), negative
preconditions, axioms and, on request, conditional effects or a plain variant. A plain module, which
pytest finds through ``pythonpath`` in the root pyproject.toml."""

from __future__ import annotations

import random

from strips_framework.grounding.axioms import AxiomEvaluator
from strips_framework.grounding.task import (
    GroundAxiom,
    GroundEffect,
    GroundOperator,
    GroundTask,
    mask_of,
)


def random_task(seed: int, conditional: bool = False, plain: bool = False) -> GroundTask:
    """A small random task: 7 basic facts, 2 derived ones, 10 operators with costs 0..3;
    with ``conditional``, up to two conditional effects per operator (some of which add
    nothing unconditionally). A ``plain`` task has unit costs and no negative conditions
    (for the properties that hold only there); the same seed draws the same structure."""
    rng = random.Random(seed)
    positive = (lambda facts: ()) if plain else tuple
    basic = list(range(7))
    derived = [7, 8]
    operators = []
    for index in range(10):
        pre = tuple(rng.sample(basic + derived, rng.randint(0, 2)))
        add = tuple(rng.sample(basic, rng.randint(0 if conditional else 1, 2)))
        delete = tuple(f for f in rng.sample(basic, rng.randint(0, 2)) if f not in add)
        pre_neg = positive(f for f in rng.sample(basic, rng.randint(0, 1)) if f not in pre)
        effects = []
        for _ in range(rng.randint(0, 2) if conditional else 0):
            condition = tuple(rng.sample(basic + derived, rng.randint(1, 2)))
            condition_neg = tuple(f for f in rng.sample(basic, rng.randint(0, 1)))
            effects.append(
                GroundEffect(
                    condition,
                    positive(f for f in condition_neg if f not in condition),
                    tuple(rng.sample(basic, 1)),
                    tuple(rng.sample(basic, rng.randint(0, 1))),
                )
            )
        operators.append(
            GroundOperator(
                f"(op{index})", pre, add, delete, 1 if plain else rng.randint(0, 3), pre_neg,
                tuple(effects),
            )
        )
    axioms = (
        GroundAxiom(7, tuple(rng.sample(basic, 2))),
        GroundAxiom(8, tuple(rng.sample(basic, 1)), positive(rng.sample(basic, 1))),
    )
    task = GroundTask(
        name=f"random{seed}",
        facts=tuple(f"(f{i})" for i in range(9)),
        operators=tuple(operators),
        init=0,
        goal=tuple(rng.sample(basic + derived, rng.randint(1, 3))),
        axioms=axioms,
        derived=tuple(derived),
        uses_costs=not plain,
    )
    init = AxiomEvaluator(task).evaluate(mask_of(tuple(rng.sample(basic, rng.randint(1, 3)))))
    return GroundTask(
        task.name, task.facts, task.operators, init, task.goal, axioms, task.derived, not plain
    )
