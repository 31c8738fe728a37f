"""Start-up: wall time of a whole ``strips solve`` on a small task against pyperplan's.

    .venv/bin/python benchmarks/startup_vs_pyperplan.py                 # blocks task01
    .venv/bin/python benchmarks/startup_vs_pyperplan.py ../shared/bench/ipc/gripper/task01.pddl --runs 40
    .venv/bin/python benchmarks/startup_vs_pyperplan.py --compile-each-run   # no .pyc for either

On a small task nearly all of a planner's wall time is start-up (interpreter, imports,
plugin discovery), so this is what a user running many small tasks pays. Each round runs
``strips solve DOMAIN PROBLEM`` (this venv's ``strips``, lazy greedy + hFF as ``for_pddl``
chooses) and ``pyperplan -s gbf -H hff DOMAIN PROBLEM`` (``$ANCHORS_VENV/bin/pyperplan``,
default ``~/.cache/strips-anchors``, as ``../shared/tools/anchors.py`` installs it) one
after the other, alternating which goes first, so both see the same machine load; the
median of the rounds is printed with the ratio. Not a test: pytest does not collect this
file (timings belong here, not in assertions).
"""

from __future__ import annotations

import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Sequence
from pathlib import Path

from shared_bench import shared_bench


def _pyperplan() -> Path:
    venv = Path(os.environ.get("ANCHORS_VENV", Path.home() / ".cache" / "strips-anchors"))
    return venv / "bin" / "pyperplan"


def _wall(command: Sequence[str], cwd: Path, compile_each_run: bool) -> float:
    """Seconds for one run of ``command``; a failed run is an error, not a fast time.
    Bytecode is written (an installed package has its ``.pyc`` files; without them every
    run would compile the modules again and measure the compiler), unless
    ``compile_each_run``: then no ``.pyc`` file is read or written (an empty
    ``PYTHONPYCACHEPREFIX``), so both planners compile every module they import."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    if compile_each_run:
        env["PYTHONDONTWRITEBYTECODE"] = "1"
        env["PYTHONPYCACHEPREFIX"] = str(cwd / "no-pycache")
    start = time.perf_counter()
    subprocess.run(
        command, cwd=cwd, env=env, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL
    )
    return time.perf_counter() - start


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    bench = shared_bench("ipc")
    default = bench / "blocks" / "task01.pddl" if bench is not None else None
    parser.add_argument("problem", type=Path, nargs="?", default=default, help="a PDDL problem")
    parser.add_argument("--runs", type=int, default=20, help="rounds (default 20)")
    parser.add_argument("--compile-each-run", action="store_true",
                        help="no bytecode files for either planner: each run compiles its modules")
    args = parser.parse_args(argv)
    if args.problem is None:
        parser.error("no problem given and shared/bench/ipc not found")
    strips = Path(sys.executable).parent / "strips"
    times: dict[str, list[float]] = {"strips": [], "pyperplan": []}
    with tempfile.TemporaryDirectory() as folder:  # pyperplan writes PROBLEM.soln beside it
        copy = Path(folder)
        domain, problem = copy / "domain.pddl", copy / args.problem.name
        shutil.copyfile(args.problem.parent / "domain.pddl", domain)
        shutil.copyfile(args.problem, problem)
        commands = {
            "strips": [str(strips), "solve", str(domain), str(problem)],
            "pyperplan": [str(_pyperplan()), "-s", "gbf", "-H", "hff", str(domain), str(problem)],
        }
        for name in ("strips", "pyperplan"):
            _wall(commands[name], copy, args.compile_each_run)  # warm the page cache and the .pyc files
        for round_ in range(args.runs):
            order = list(commands) if round_ % 2 == 0 else list(reversed(commands))
            for name in order:
                times[name].append(_wall(commands[name], copy, args.compile_each_run))
    medians = {name: statistics.median(values) for name, values in times.items()}
    for name, value in medians.items():
        print(f"{name:<10} median {value * 1000:7.1f} ms  (min {min(times[name]) * 1000:.1f}, {args.runs} runs)")
    print(f"ratio strips/pyperplan: {medians['strips'] / medians['pyperplan']:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
