"""The ground task means what the lifted task means: on random walks, the grounded
states, applicable operators, derived facts and goal test agree with the lifted
validator's semantics (which shares nothing with the grounder but the reader). The only
lifted actions without a ground operator are those that change nothing."""

from __future__ import annotations

import random
from itertools import product
from pathlib import Path

import pytest
from shared_bench import small_bench

from strips_framework.grounding import ground
from strips_framework.grounding.axioms import AxiomEvaluator
from strips_framework.pddl import PddlTask, find_domain, load_task
from strips_framework.pddl.validate import PlanValidator

DATA = Path(__file__).parents[1] / "pddl" / "data"
IPC = small_bench("ipc")

LOCAL = [
    ("rooms-domain.pddl", "rooms-1.pddl"),
    ("rooms-domain.pddl", "rooms-2.pddl"),
    ("blocks-domain.pddl", "blocks-3.pddl"),
    ("crates-domain.pddl", "crates-3.pddl"),
    ("briefcase-domain.pddl", "briefcase-2.pddl"),
    ("elevator-domain.pddl", "elevator-1.pddl"),
    ("switches-domain.pddl", "switches-1.pddl"),
]
SMALL_IPC = ["blocks", "gripper", "logistics", "miconic", "openstacks", "pegsol"]


def lifted_applicable(task: PddlTask, validator: PlanValidator, model) -> set[str]:
    names = set()
    for action in task.domain.actions:
        params = [param.name for param in action.params]
        domains = [task.objects_of(param.types) for param in action.params]
        for values in product(*domains):
            if validator.holds(action.precondition, dict(zip(params, values)), model):
                names.add("(" + " ".join((action.name, *values)) + ")")
    return names


def walk_and_compare(task: PddlTask, steps: int, seed: int) -> None:
    ground_task = ground(task, prune_irrelevant=False)
    evaluator = AxiomEvaluator(ground_task)
    validator = PlanValidator(task)
    derived = {rule.head.predicate for rule in task.domain.derived}
    changed = {atom.predicate for a in task.domain.actions for atom in a.changed_atoms()}
    rng = random.Random(seed)
    state, lifted = ground_task.init, validator.initial()
    for _ in range(steps):
        model = validator.closure(lifted)
        shown = {f"({' '.join((p, *args))})" for p, args in model if p in changed | derived}
        # Facts of made-up derived predicates ((@goal), (@forallN ...)) have no lifted twin.
        assert {f for f in ground_task.facts_of(state) if not f.startswith("(@")} == shown
        assert ground_task.is_goal(state) == validator.holds(task.problem.goal, {}, model)
        applicable = [op for op in ground_task.operators if op.applicable(state)]
        names = {op.name for op in applicable}
        lifted_names = lifted_applicable(task, validator, model)
        assert names <= lifted_names
        for name in lifted_names - names:  # dropped by grounding as changing nothing
            action, binding = validator.step(name)
            assert validator.successor(lifted, action, binding) == lifted
        if not applicable:
            break
        chosen = rng.choice(applicable)
        action, binding = validator.step(chosen.name)
        state = evaluator.evaluate(chosen.apply(state))
        lifted = validator.successor(lifted, action, binding)


@pytest.mark.parametrize(("domain", "problem"), LOCAL)
def test_local_tasks_agree_on_random_walks(domain, problem):
    task = load_task(DATA / domain, DATA / problem)
    for seed in range(5):
        walk_and_compare(task, steps=15, seed=seed)


@pytest.mark.parametrize("domain", SMALL_IPC)
def test_ipc_first_tasks_agree_on_a_random_walk(domain):
    problem = IPC / domain / "task01.pddl"
    walk_and_compare(load_task(find_domain(problem), problem), steps=10, seed=1)
