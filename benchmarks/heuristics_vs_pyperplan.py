"""Evaluations per second of our heuristics against pyperplan's, on the same states.

    .venv/bin/python benchmarks/heuristics_vs_pyperplan.py \
        ../shared/bench/ipc/logistics/task05.pddl ../shared/bench/ipc/blocks/task05.pddl

For each task: ground it, collect states by seeded random walks from the initial state
(those of ``bench_heuristics.py``),
time our ``ff`` and ``lmcut`` over them, then time pyperplan's ``hFFHeuristic`` and
``LmCutHeuristic`` over the same states (by fact name) in pyperplan's own interpreter
(``$ANCHORS_VENV/bin/python``, default ``~/.cache/strips-anchors``, as
``../shared/tools/anchors.py`` installs it). Prints evaluations per second and how many
states got the same value from both. Not a test: pytest does not collect this file.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import time
from collections.abc import Callable, Sequence
from pathlib import Path

from bench_heuristics import random_walk_states

from strips_evaluators.heuristics.ff import FFHeuristic
from strips_evaluators.heuristics.lmcut import LMCutHeuristic
from strips_framework.grounding import ground
from strips_framework.pddl import find_domain, load_task

PYPERPLAN_SIDE = r"""
import json, sys, time
from pyperplan.planner import _parse, _ground
from pyperplan.heuristics.relaxation import hFFHeuristic
from pyperplan.heuristics.lm_cut import LmCutHeuristic
from pyperplan.search.searchspace import make_root_node

job = json.load(sys.stdin)
task = _ground(_parse(job["domain"], job["problem"]))
states = [frozenset(f for f in facts if f in task.facts) for facts in job["states"]]
nodes = [make_root_node(state) for state in states]
report = {}
for name, cls in (("ff", hFFHeuristic), ("lmcut", LmCutHeuristic)):
    heuristic = cls(task)
    values, rounds, start = [], 0, time.perf_counter()
    while True:
        values = [heuristic(node) for node in nodes]
        rounds += 1
        elapsed = time.perf_counter() - start
        if elapsed >= job["seconds"]:
            break
    report[name] = {"per_second": rounds * len(nodes) / elapsed, "values": values}
json.dump(report, sys.stdout)
"""


def time_heuristic(
    evaluate: Callable[[int], object], states: Sequence[int], seconds: float
) -> tuple[float, list[float]]:
    """Evaluations per second over ``states`` (repeated for at least ``seconds``)."""
    rounds, start = 0, time.perf_counter()
    while True:
        values = [evaluate(state) for state in states]
        rounds += 1
        elapsed = time.perf_counter() - start
        if elapsed >= seconds:
            return rounds * len(states) / elapsed, values


def compare(problem: Path, python: Path, count: int, seconds: float) -> None:
    domain = find_domain(problem)
    task = ground(load_task(domain, problem))
    states = random_walk_states(task, count)
    ours = {}
    for cls in (FFHeuristic, LMCutHeuristic):
        estimator = cls().for_task(task)
        ours[cls.name] = time_heuristic(estimator.estimate_with_preferred, states, seconds)
    job = {
        "domain": str(domain),
        "problem": str(problem),
        "seconds": seconds,
        "states": [task.facts_of(state) for state in states],
    }
    answer = subprocess.run(
        [str(python), "-c", PYPERPLAN_SIDE],
        input=json.dumps(job),
        capture_output=True,
        text=True,
        check=True,
    )
    theirs = json.loads(answer.stdout)
    print(
        f"{problem}  ({len(task.facts)} facts, {len(task.operators)} operators, "
        f"{len(states)} states)"
    )
    for name, (per_second, values) in ours.items():
        their = theirs[name]
        same = sum(v[0] == w for v, w in zip(values, their["values"]))
        print(
            f"  {name:6} ours {per_second:9.0f}/s  pyperplan {their['per_second']:9.0f}/s"
            f"  speed-up {per_second / their['per_second']:5.1f}x"
            f"  same value on {same}/{len(states)} states"
        )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("problems", nargs="+", type=Path)
    parser.add_argument("--states", type=int, default=200)
    parser.add_argument("--seconds", type=float, default=2.0)
    default_venv = Path(os.environ.get("ANCHORS_VENV", Path.home() / ".cache/strips-anchors"))
    parser.add_argument("--pyperplan-python", type=Path, default=default_venv / "bin/python")
    arguments = parser.parse_args()
    for problem in arguments.problems:
        compare(problem, arguments.pyperplan_python, arguments.states, arguments.seconds)


if __name__ == "__main__":
    main()
