"""Means-ends analysis on the first IPC tasks of a few domains, beside lazy-gbfs.

Runs ``strips solve DOMAIN PROBLEM --config CFG --json`` once per task and config (each
in its own process, so one run's time limit or memory never touches another) and prints
one row per run: status, plan length, nodes, proof attempts and the mean milliseconds per
attempt (``proving_seconds / proof_attempts``), then coverage per config. A forward
config reports its expansions in the nodes column. Not a pytest benchmark: a run takes
minutes, and the figures go into docs/means-ends.md by hand.

    python benchmarks/means_ends_ipc.py --tasks 2 --time 30 \
        examples/configs/paper.toml examples/configs/means-ends-relaxed.toml \
        examples/configs/fast.toml
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
from pathlib import Path

from shared_bench import shared_bench

#: The ``strips`` command of the interpreter running this script (its venv's).
STRIPS = str(Path(sys.executable).parent / "strips")
DOMAINS = ("depot", "elevators", "logistics", "blocks", "gripper", "miconic")


def run(domain: Path, problem: Path, config: Path, seconds: int) -> dict:
    """One ``strips solve --json`` run with the config's ``[limits] time`` overridden."""
    text = config.read_text()
    with tempfile.NamedTemporaryFile("w", suffix=".toml", delete=False) as limited:
        limited.write(_with_time_limit(text, seconds))
    try:
        done = subprocess.run(
            [STRIPS, "solve", str(domain), str(problem),
             "--config", limited.name, "--json"],
            capture_output=True, text=True, timeout=seconds + 60,
        )
    finally:
        Path(limited.name).unlink()
    return json.loads(done.stdout)


def _with_time_limit(text: str, seconds: int) -> str:
    """The config with ``[limits] time = seconds`` (the table added when it is missing)."""
    lines = [line for line in text.splitlines() if not line.strip().startswith("time ")]
    if "[limits]" not in lines:
        lines.append("[limits]")
    at = lines.index("[limits]") + 1
    return "\n".join([*lines[:at], f"time = {seconds}", *lines[at:]]) + "\n"


def row(result: dict) -> tuple:
    stats = result.get("statistics") or {}
    attempts = stats.get("proof_attempts")
    per_attempt = (
        1000 * stats["proving_seconds"] / attempts if attempts else None
    )
    nodes = stats.get("nodes", stats.get("expanded"))
    return (result["status"], result["plan_length"], nodes, attempts, per_attempt,
            result["seconds"])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("configs", nargs="+", type=Path)
    parser.add_argument("--tasks", type=int, default=2, help="first N tasks per domain")
    parser.add_argument("--time", type=int, default=30, help="seconds per run")
    parser.add_argument("--domains", nargs="+", default=DOMAINS)
    args = parser.parse_args()
    ipc = shared_bench("ipc")
    if ipc is None:
        sys.exit("strips: error: shared/bench/ipc not found above this folder")
    solved = {config.name: 0 for config in args.configs}
    print("domain/task | config | status | length | nodes | attempts | ms/attempt | s")
    for name in args.domains:
        for number in range(1, args.tasks + 1):
            problem = ipc / name / f"task{number:02d}.pddl"
            for config in args.configs:
                status, length, nodes, attempts, per, seconds = row(
                    run(ipc / name / "domain.pddl", problem, config, args.time))
                solved[config.name] += status == "solved"
                per_text = "-" if per is None else f"{per:.2f}"
                print(f"{name}/{problem.stem} | {config.stem} | {status} | {length} | "
                      f"{nodes} | {attempts} | {per_text} | {seconds:.1f}", flush=True)
    total = len(args.domains) * args.tasks
    for config, count in solved.items():
        print(f"coverage {config}: {count}/{total}")


if __name__ == "__main__":
    main()
