"""Expansions of our lazy greedy hFF search against Fast Downward's, task by task.

    .venv/bin/python benchmarks/expansions_vs_fd.py                       # anchor35 domains, tasks 1-10
    .venv/bin/python benchmarks/expansions_vs_fd.py depot,satellite --tasks 5 --timeout 60

Runs ``strips solve`` (the default PDDL strategy, lazy greedy + hFF with preferred
operators) and Fast Downward's ``lazy_greedy([hff], preferred=[hff])`` (as
``../shared/tools/anchors.py`` installs it, under ``$ANCHORS_VENV``, default
``~/.cache/strips-anchors``) on each task, and prints both expansion counts, then per
domain the geometric mean of ours/FD over the tasks both solved and how many each
solved. Expansion counts do not depend on the machine's load, so they say how far the
two searches' behaviour (tie-breaking, preferred operators, relaxed plans) is apart.
Not a test: pytest does not collect this file.
"""

from __future__ import annotations

import argparse
import math
import os
import re
import subprocess
import sys
import tempfile
from collections.abc import Sequence
from pathlib import Path

from shared_bench import shared_bench

DOMAINS = "blocks,gripper,logistics,miconic,depot,satellite,elevators"
FD_SEARCH = "let(hff, ff(), lazy_greedy([hff], preferred=[hff]))"


def _expanded(command: Sequence[str], pattern: str, solved: str, timeout: float, cwd: str) -> int | None:
    """The expansion count a solving run prints; ``None`` when it found no plan in time."""
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=timeout, cwd=cwd)
    except subprocess.TimeoutExpired:
        return None
    found = re.search(pattern, done.stdout)
    return int(found.group(1)) if found and solved in done.stdout else None


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("domains", nargs="?", default=DOMAINS, help="comma-separated domains")
    parser.add_argument("--tasks", type=int, default=10, help="first N tasks of each (default 10)")
    parser.add_argument("--timeout", type=float, default=30.0, help="seconds per run (default 30)")
    args = parser.parse_args(argv)
    bench = shared_bench("ipc")
    venv = Path(os.environ.get("ANCHORS_VENV", Path.home() / ".cache" / "strips-anchors"))
    scripts = sorted(venv.glob("lib/python3*/site-packages/up_fast_downward/downward/fast-downward.py"))
    if bench is None or not scripts:
        parser.error("needs shared/bench/ipc and Fast Downward (../shared/tools/anchors.py setup)")
    strips = str(Path(sys.executable).parent / "strips")
    total, count = 0.0, 0
    with tempfile.TemporaryDirectory() as scratch:  # Fast Downward writes files where it runs
        for domain in args.domains.split(","):
            logs, solved = [], [0, 0]
            for index in range(1, args.tasks + 1):
                problem = bench / domain / f"task{index:02d}.pddl"
                if not problem.exists():
                    continue
                files = [str(bench / domain / "domain.pddl"), str(problem)]
                ours = _expanded([strips, "solve", *files], r"expanded: (\d+)", "solved",
                                 args.timeout, scratch)
                fd = _expanded([str(venv / "bin" / "python"), str(scripts[0]), *files, "--search",
                                FD_SEARCH], r"Expanded (\d+) state", "Solution found",
                               args.timeout, scratch)
                print(f"{domain}/{problem.stem}: ours {ours}, fd {fd}")
                solved[0] += ours is not None
                solved[1] += fd is not None
                if ours and fd:
                    logs.append(math.log(ours / fd))
            mean = f"{math.exp(sum(logs) / len(logs)):.2f}" if logs else "-"
            print(f"{domain}: ours/fd geometric mean {mean} over {len(logs)}; solved ours "
                  f"{solved[0]}, fd {solved[1]}")
            total, count = total + sum(logs), count + len(logs)
    if count:
        print(f"all: ours/fd geometric mean {math.exp(total / count):.2f} over {count} tasks")
    return 0


if __name__ == "__main__":
    sys.exit(main())
