"""Measure the prover on a folder of TPTP problems, optionally beside E, as a Markdown table.

    python -m strips_resolution_prover.measure DIR [DIR ...] [--effort N] [--time S]
        [--options JSON] [--eprover]

Each problem gets ``--effort`` given clauses and at most ``--time`` CPU seconds (a
profiling timer, so Unix only); E, when asked, runs with ``--auto`` and the same time limit in the same run,
so the two columns come from one machine state, and the geometric mean of the CPU time
ratio (ours/E) over the problems both solve closes the table. ``--options`` are the prover's options as
a JSON object, e.g. ``'{"set_of_support": false}'``.
"""

from __future__ import annotations

import argparse
import json
import math
import resource
import shutil
import signal
import subprocess
import sys
import time
from collections.abc import Iterator
from pathlib import Path

from strips_framework.formats.tptp import load_tptp, prove_tptp
from strips_resolution_prover.prover import ResolutionProver


class _OutOfTime(Exception):
    pass


def _alarm(signum: int, frame: object) -> None:
    raise _OutOfTime


def run_ours(
    prover: ResolutionProver, path: Path, effort: int, seconds: float
) -> tuple[str, float, str]:
    """Status, CPU seconds and answers of our prover on one problem."""
    problem = load_tptp(path)
    start = time.process_time()
    signal.signal(signal.SIGPROF, _alarm)
    signal.setitimer(signal.ITIMER_PROF, seconds)
    try:
        status, answers = prove_tptp(prover, problem, effort)
    except _OutOfTime:
        return "T/O", time.process_time() - start, ""
    finally:
        signal.setitimer(signal.ITIMER_PROF, 0)
    return status, time.process_time() - start, answers or ""


def run_e(path: Path, seconds: float) -> tuple[str, float]:
    """Status and CPU seconds of ``eprover --auto`` on one problem."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    completed = subprocess.run(
        ["eprover", "--auto", "-s", f"--cpu-limit={int(seconds)}", str(path)],
        capture_output=True,
        text=True,
        check=False,
    )
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    used = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    status = "T/O"
    for line in completed.stdout.splitlines():
        if line.startswith("# SZS status"):
            status = line.split()[3]
    return status, used


def _problems(folders: list[Path]) -> Iterator[Path]:
    for folder in folders:
        yield from sorted(folder.glob("*.p"))


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("folders", nargs="+", type=Path)
    parser.add_argument("--effort", type=int, default=20000)
    parser.add_argument("--time", type=float, default=10.0)
    parser.add_argument("--options", type=json.loads, default={})
    parser.add_argument("--eprover", action="store_true")
    args = parser.parse_args(argv)
    prover = ResolutionProver(**args.options)
    with_e = args.eprover and shutil.which("eprover") is not None
    header = "| problem | ours | s |" + (" E | s |" if with_e else "") + " answers |"
    print(header)
    print("|" + "---|" * (header.count("|") - 1))
    solved = e_solved = total = 0
    ratios: list[float] = []
    for path in _problems(args.folders):
        status, seconds, answers = run_ours(prover, path, args.effort, args.time)
        total += 1
        solved += status not in ("T/O", "GaveUp")
        row = f"| {path.stem} | {status} | {seconds:.2f} |"
        if with_e:
            e_status, e_seconds = run_e(path, args.time)
            e_decided = e_status not in ("T/O", "GaveUp", "ResourceOut")
            e_solved += e_decided
            row += f" {e_status} | {e_seconds:.2f} |"
            if e_decided and status not in ("T/O", "GaveUp"):
                # Below 10 ms a CPU clock reads noise: both sides count as 10 ms at least.
                ratios.append(max(seconds, 0.01) / max(e_seconds, 0.01))
        print(f"{row} {answers} |", flush=True)
    print(f"\nours: {solved}/{total}" + (f", E: {e_solved}/{total}" if with_e else ""))
    if ratios:
        mean = math.exp(sum(math.log(r) for r in ratios) / len(ratios))
        print(f"CPU time ours/E, geometric mean over the {len(ratios)} both solve: {mean:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
