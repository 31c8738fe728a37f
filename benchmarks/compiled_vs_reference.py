"""The compiled search loops and successor generator against their pure-Python references,
in one process on one task, so that the load hits both alike.

    .venv/bin/python benchmarks/compiled_vs_reference.py depot/task08
    .venv/bin/python benchmarks/compiled_vs_reference.py gripper/task04 --search astar

Runs the search (lazy greedy + hFF, or A* + LM-cut; the heuristic compiled either way)
``--rounds`` times each way, alternating: with the compiled loop and generator, with the
strategy's ``reference_run`` and the reference generator, and with only the generator
compiled. Prints the expansions (the same every way, or it stops) and the best search
time of each. Not a test: pytest does not collect this file.
"""

from __future__ import annotations

import argparse
import sys
import time
from collections.abc import Sequence

from shared_bench import shared_bench

from strips_framework.forward import space as state_space
from strips_framework.forward.eager import AStarSearch
from strips_framework.forward.lazy import LazyGreedySearch
from strips_framework.forward.successors import successor_generator
from strips_framework.grounding import ground
from strips_framework.limits import Limits
from strips_framework.pddl import find_domain, load_task
from strips_framework.plugin.registry import Registry

SEARCHES = {"lazy": (LazyGreedySearch, "ff"), "astar": (AStarSearch, "lmcut")}
#: Per way: whether the loop, and whether the successor generator, run compiled.
WAYS = {"compiled": (True, True), "reference": (False, False), "generator only": (False, True)}


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("task", help="DOMAIN/taskNN of the shared IPC set")
    parser.add_argument("--search", choices=sorted(SEARCHES), default="lazy")
    parser.add_argument("--rounds", type=int, default=3)
    args = parser.parse_args(argv)
    bench = shared_bench("ipc")
    if bench is None:
        parser.error("needs shared/bench/ipc")
    problem = bench / f"{args.task}.pddl"
    task = ground(load_task(find_domain(problem), problem))
    strategy_class, heuristic = SEARCHES[args.search]
    heuristic_class = Registry.from_plugins().get("heuristic", heuristic).cls
    best: dict[str, float] = {}
    counts: set[int] = set()
    for _ in range(args.rounds):
        for way, (loop, generator) in WAYS.items():
            state_space.successor_generator = (  # type: ignore[assignment]
                lambda ground_task, compiled=generator: successor_generator(ground_task, compiled)
            )
            strategy = strategy_class()
            if not loop:
                object.__setattr__(strategy, "run", strategy.reference_run)
            started = time.perf_counter()
            result = strategy.search_task(task, heuristic_class().for_task(task), Limits(time=600))
            best[way] = min(best.get(way, float("inf")), time.perf_counter() - started)
            counts.add(result.statistics.expanded)
    if len(counts) != 1:
        print(f"expansions differ between the ways: {sorted(counts)}")
        return 1
    (expanded,) = counts
    print(f"{args.task} {args.search}: {expanded} expansions")
    for way, seconds in best.items():
        print(f"  {way}: {seconds:.3f} s ({expanded / seconds:.0f} expansions/s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
