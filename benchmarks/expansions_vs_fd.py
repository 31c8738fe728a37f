"""Expansions, and expansions per second, of our searches against Fast Downward's.

    .venv/bin/python benchmarks/expansions_vs_fd.py                       # anchor35 domains, tasks 1-10
    .venv/bin/python benchmarks/expansions_vs_fd.py depot,satellite --tasks 5 --timeout 60
    .venv/bin/python benchmarks/expansions_vs_fd.py gripper,blocks --search astar

Runs ``strips solve`` and Fast Downward (as ``../shared/tools/anchors.py`` installs it,
under ``$ANCHORS_VENV``, default ``~/.cache/strips-anchors``) on each task: by default
our default PDDL strategy (lazy greedy + hFF with preferred operators) beside
``lazy_greedy([hff], preferred=[hff])``, with ``--search astar`` A* + LM-cut beside
``astar(lmcut())``. It prints both expansion counts and both rates (expansions per
second of search time, as each planner reports it), then per domain the geometric means
of ours/FD over the tasks both solved: of the expansions, which do not depend on the
machine's load and say how far the two searches' behaviour (tie-breaking, preferred
operators, relaxed plans) is apart, and of the rates over the tasks whose search took
Fast Downward at least ``--min-search`` seconds (search-dominated ones; on smaller ones
the rates are timer noise). Not a test: pytest does not collect this file.
"""

from __future__ import annotations

import argparse
import math
import os
import re
import signal
import subprocess
import sys
import tempfile
from collections.abc import Sequence
from pathlib import Path

from shared_bench import shared_bench

from strips_framework.pddl import find_domain

DOMAINS = "blocks,gripper,logistics,miconic,depot,satellite,elevators"
#: Per --search: our config file (None: the default) and Fast Downward's search.
SEARCHES = {
    "lazy": (None, "let(hff, ff(), lazy_greedy([hff], preferred=[hff]))"),
    "astar": ("examples/configs/optimal-pddl.toml", "astar(lmcut())"),
}
OURS = (r"expanded: (\d+)", r"search ([\d.]+) s", "status: solved")
FD = (r"Expanded (\d+) state", r"Search time: ([\d.]+)s", "Solution found")


def _run(command: Sequence[str], patterns: tuple[str, str, str], timeout: float,
         cwd: str) -> tuple[int, float] | None:
    """The expansion count and search seconds a solving run prints; ``None`` when it
    found no plan in time. The run gets a process group of its own, killed whole at the
    timeout: Fast Downward's driver runs the search in a child process, which would
    otherwise outlive it and take a core from every run after it."""
    with subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                          text=True, cwd=cwd, start_new_session=True) as process:
        try:
            stdout, _ = process.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)
            process.communicate()
            return None
    expanded, seconds = (re.search(pattern, stdout) for pattern in patterns[:2])
    if not (expanded and seconds and patterns[2] in stdout):
        return None
    return int(expanded.group(1)), float(seconds.group(1))


def _show(found: tuple[int, float] | None) -> str:
    if found is None:
        return "-"
    expanded, seconds = found
    return f"{expanded} in {seconds:.3f} s ({expanded / max(seconds, 1e-3):.0f}/s)"


def _mean(logs: list[float]) -> str:
    return f"{math.exp(sum(logs) / len(logs)):.2f}" if logs else "-"


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("domains", nargs="?", default=DOMAINS, help="comma-separated domains")
    parser.add_argument("--tasks", type=int, default=10, help="first N tasks of each (default 10)")
    parser.add_argument("--timeout", type=float, default=30.0, help="seconds per run (default 30)")
    parser.add_argument("--search", choices=sorted(SEARCHES), default="lazy")
    parser.add_argument("--min-search", type=float, default=0.1,
                        help="FD search seconds for a task's rates to count (default 0.1)")
    args = parser.parse_args(argv)
    config, fd_search = SEARCHES[args.search]
    bench = shared_bench("ipc")
    venv = Path(os.environ.get("ANCHORS_VENV", Path.home() / ".cache" / "strips-anchors"))
    scripts = sorted(venv.glob("lib/python3*/site-packages/up_fast_downward/downward/fast-downward.py"))
    if bench is None or not scripts:
        parser.error("needs shared/bench/ipc and Fast Downward (../shared/tools/anchors.py setup)")
    strips = [str(Path(sys.executable).parent / "strips"), "solve"]
    if config:
        strips += ["--config", str(Path(__file__).resolve().parents[1] / config)]
    totals: list[list[float]] = [[], []]  # logs of the expansion and rate ratios
    with tempfile.TemporaryDirectory() as scratch:  # Fast Downward writes files where it runs
        for domain in args.domains.split(","):
            logs: list[list[float]] = [[], []]
            solved = [0, 0]
            for index in range(1, args.tasks + 1):
                problem = bench / domain / f"task{index:02d}.pddl"
                if not problem.exists():
                    continue
                files = [str(find_domain(problem)), str(problem)]  # openstacks: one per task
                ours = _run([*strips, *files], OURS, args.timeout, scratch)
                fd = _run([str(venv / "bin" / "python"), str(scripts[0]), *files, "--search",
                           fd_search], FD, args.timeout, scratch)
                print(f"{domain}/{problem.stem}: ours {_show(ours)}, fd {_show(fd)}", flush=True)
                solved[0] += ours is not None
                solved[1] += fd is not None
                if ours and fd and ours[0] and fd[0]:
                    logs[0].append(math.log(ours[0] / fd[0]))
                    if fd[1] >= args.min_search and ours[1] > 0:
                        logs[1].append(math.log(ours[0] / ours[1] / (fd[0] / fd[1])))
            print(f"{domain}: ours/fd expansions {_mean(logs[0])} over {len(logs[0])}, rate "
                  f"{_mean(logs[1])} over {len(logs[1])}; solved ours {solved[0]}, fd {solved[1]}")
            for total, part in zip(totals, logs):
                total.extend(part)
    print(f"all: ours/fd expansions {_mean(totals[0])} over {len(totals[0])} tasks, "
          f"rate {_mean(totals[1])} over {len(totals[1])}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
