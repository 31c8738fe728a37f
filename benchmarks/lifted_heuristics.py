"""Per-state time of the lifted heuristics, beside the ground hFF where grounding is cheap.

    taskset -c 1 .venv/bin/python benchmarks/lifted_heuristics.py PROBLEM.pddl ...
    taskset -c 1 .venv/bin/python benchmarks/lifted_heuristics.py --states 20 \\
        ../shared/bench/htg/logistics/prob28.pddl \\
        ../shared/bench/htg/blocksworld-large-simple--goal-3/p-100-3.pddl

For each task (its domain found beside it) it prints the lifted hFF's set-up time and its
mean CPU time per state (with preferred operators) over the initial state and the states
of a random walk of ``--states`` steps (each step a preferred operator, applied by the
plan validator's semantics), then the grounding time, the ground hFF's set-up time and
its time per state on the same states (compiled when built; ``--no-ground`` skips it,
for tasks too large to ground). The values are printed in pairs: they agree up to ties.
``--rounds N`` evaluates the states N times and keeps the fastest round (a loaded
machine's noise only adds time).
"""

from __future__ import annotations

import argparse
import random
import sys
import time
from pathlib import Path

from strips_evaluators.heuristics.ff import FFHeuristic
from strips_evaluators.lifted.heuristics import LiftedFF
from strips_framework.grounding import ground
from strips_framework.grounding.axioms import AxiomEvaluator
from strips_framework.lifted.components import static_predicates
from strips_framework.pddl import PddlTask, find_domain, load_task
from strips_framework.pddl.validate import PlanValidator


def walk(task: PddlTask, steps: int, seed: int) -> list[frozenset]:
    """Lifted states along a random walk from the initial state: the relaxed plan's
    preferred operators are the moves (they are applicable, and cheap to find)."""
    static = static_predicates(task)
    validator = PlanValidator(task)
    state = validator.initial()
    estimator = LiftedFF().for_task(task)
    rng = random.Random(seed)
    states = []
    for _ in range(steps + 1):
        lifted = frozenset((p, *args) for p, args in state if p not in static)
        states.append(lifted)
        _, preferred = estimator.estimate_with_preferred(lifted)
        if not preferred:
            break
        name, args = rng.choice(list(preferred))
        action = validator.actions[name]
        binding = {param.name: value for param, value in zip(action.params, args)}
        state = validator.successor(state, action, binding)
    return states


def main(argv: list[str]) -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("problems", nargs="+", type=Path)
    parser.add_argument("--states", type=int, default=10)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--no-ground", action="store_true")
    parser.add_argument("--rounds", type=int, default=1)
    args = parser.parse_args(argv)
    print("task  lifted_setup_s  lifted_ms_per_state  ground_s  ground_setup_s  "
          "ground_ms_per_state  values(lifted/ground)")  # fmt: skip
    for problem in args.problems:
        task = load_task(find_domain(problem), problem)
        states = walk(task, args.states, args.seed)
        start = time.process_time()
        lifted = LiftedFF().for_task(task)
        lifted_setup = time.process_time() - start
        best = float("inf")
        for _ in range(args.rounds):
            start = time.process_time()
            lifted_values = [lifted.estimate_with_preferred(state)[0] for state in states]
            best = min(best, time.process_time() - start)
        lifted_ms = 1000 * best / len(states)
        row = f"{problem.parent.name}/{problem.name}  {lifted_setup:.3f}  {lifted_ms:.1f}"
        if args.no_ground:
            print(row, "  -  -  -", lifted_values, flush=True)
            continue
        start = time.process_time()
        grounded = ground(task, prune_irrelevant=False)
        grounding = time.process_time() - start
        start = time.process_time()
        ground_ff = FFHeuristic().for_task(grounded)
        ground_setup = time.process_time() - start
        number = {name: i for i, name in enumerate(grounded.facts)}
        masks = []
        for state in states:
            mask = 0
            for atom in state:
                fact = number.get("(" + " ".join(atom) + ")")
                if fact is not None:
                    mask |= 1 << fact
            masks.append(mask)
        evaluate = AxiomEvaluator(grounded).evaluate
        masks = [evaluate(mask) for mask in masks]
        start = time.process_time()
        ground_values = [ground_ff.estimate_with_preferred(mask)[0] for mask in masks]
        ground_ms = 1000 * (time.process_time() - start) / len(masks)
        print(f"{row}  {grounding:.2f}  {ground_setup:.2f}  {ground_ms:.2f}",
              list(zip(lifted_values, ground_values)), flush=True)  # fmt: skip


if __name__ == "__main__":
    main(sys.argv[1:])
