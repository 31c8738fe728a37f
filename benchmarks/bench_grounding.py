"""Parse and grounding time of IPC tasks.

    .venv/bin/python -m pytest benchmarks/bench_grounding.py --benchmark-columns=min,mean,rounds
    .venv/bin/python benchmarks/bench_grounding.py             # largest task of each domain
    .venv/bin/python benchmarks/bench_grounding.py gripper     # every task of gripper

The pytest cases time reading (domain + problem) and grounding separately on a few tasks,
three rounds each, so the normal test run keeps them as a smoke test. Run as a script, it
prints for the largest task of every domain in ``shared/bench/ipc`` (or for every task of
the domains named) the number of facts and ground operators and the best of three parse
and ground times (process CPU time, so a loaded machine disturbs it less). Without
``shared/bench/ipc`` the cases skip.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import pytest
from shared_bench import shared_bench

from strips_framework.grounding import ground
from strips_framework.pddl import find_domain, load_task

TASKS = ["blocks/task01", "logistics/task28", "rovers/task30", "satellite/task20"]


BENCH = shared_bench("ipc")


def _problem(name: str) -> Path:
    if BENCH is None:
        pytest.skip("shared/bench/ipc not found")
    return BENCH / f"{name}.pddl"


@pytest.mark.parametrize("name", TASKS)
def test_parse_speed(benchmark, name: str) -> None:
    problem = _problem(name)
    domain = find_domain(problem)
    task = benchmark.pedantic(lambda: load_task(domain, problem), rounds=3, iterations=1)
    assert task.problem.init


@pytest.mark.parametrize("name", TASKS)
def test_ground_speed(benchmark, name: str) -> None:
    problem = _problem(name)
    task = load_task(find_domain(problem), problem)
    grounded = benchmark.pedantic(lambda: ground(task), rounds=3, iterations=1)
    benchmark.extra_info["operators"] = len(grounded.operators)
    assert grounded.operators


def _best_of_three(work, *args) -> tuple[float, object]:
    best, result = float("inf"), None
    for _ in range(3):
        started = time.process_time()
        result = work(*args)
        best = min(best, time.process_time() - started)
    return best, result


def _largest(domain: Path) -> Path:
    """The domain's task with the largest problem file."""
    return max(sorted(domain.glob("task*.pddl")), key=lambda path: path.stat().st_size)


def main(arguments: list[str]) -> None:
    """Without arguments, the largest task of every domain; with domain names, every task
    of those domains (grounding time against the number of operators)."""
    if BENCH is None:
        sys.exit("shared/bench/ipc not found")
    if arguments:
        problems = [p for name in arguments for p in sorted((BENCH / name).glob("task*.pddl"))]
    else:
        domains = sorted(path for path in BENCH.iterdir() if path.is_dir())
        problems = [_largest(domain) for domain in domains]
    print(f"{'task':24} {'facts':>7} {'operators':>10} {'parse s':>8} {'ground s':>9}")
    for problem in problems:
        domain_file = find_domain(problem)
        parse, task = _best_of_three(load_task, domain_file, problem)
        grounding, grounded = _best_of_three(ground, task)
        name = f"{problem.parent.name}/{problem.stem}"
        print(
            f"{name:24} {len(grounded.facts):7} {len(grounded.operators):10} "
            f"{parse:8.4f} {grounding:9.3f}"
        )


if __name__ == "__main__":
    main(sys.argv[1:])
