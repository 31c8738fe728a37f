"""Means-ends on an anchors.py suite: the ``--ours`` command, and the table of its runs.

``anchors.py`` keeps a run's status, wall time and plan length (validated), not the
planner's statistics. ``solve`` is the ``--ours`` command: it runs ``strips solve ...
--json`` and appends the JSON to a log, under a digest of the problem file (anchors.py
runs each task on a copy in a folder of its own). ``table`` joins the CSV with that log
through the digests of the suite's problem files: a markdown row per task (status, plan length,
lazy-gbfs's, nodes, proof attempts, ms per attempt, wall seconds), then solved per
domain, the invalid plans, the median of the runs' mean ms per attempt, and the plan
lengths summed over the tasks both solved. Not a pytest benchmark: a suite takes minutes,
and the figures go into docs/means-ends.md by hand.

    python3 ../shared/tools/anchors.py run --suite anchor35 --configs ours,fd-lazy-ff \\
        --ours "$PWD/.venv/bin/python $PWD/benchmarks/anchors_means_ends.py solve \\
                --log $PWD/runs.jsonl --config $PWD/examples/configs/means-ends-relaxed.toml \\
                {domain} {problem} {plan}" --timeout 60 --jobs 1 --out anchor35.csv
    .venv/bin/python benchmarks/anchors_means_ends.py table anchor35.csv runs.jsonl

(Absolute paths: anchors.py runs the command in the task's folder.)
"""

from __future__ import annotations

import argparse
import csv
import hashlib
import json
import statistics
import subprocess
import sys
from pathlib import Path

from shared_bench import shared_bench

#: The ``strips`` command of the interpreter running this script (its venv's).
STRIPS = str(Path(sys.executable).parent / "strips")
BASELINE = "fd-lazy-ff"
#: Where anchors.py's suites are (``None`` without ../shared: give ``--bench``).
BENCH = shared_bench("ipc")


def solve(log: Path, config: Path, domain: Path, problem: Path, plan: Path) -> int:
    """Run the planner once; its JSON goes to stdout and, one line, to ``log``."""
    done = subprocess.run(
        [STRIPS, "solve", str(domain), str(problem), "--config", str(config),
         "--plan-file", str(plan), "--json"],
        capture_output=True, text=True,
    )
    sys.stdout.write(done.stdout)
    sys.stderr.write(done.stderr)
    with log.open("a") as out:
        out.write(json.dumps({"problem": _digest(problem), "result": _json_or_none(done.stdout)}) + "\n")
    return done.returncode


def _digest(problem: Path) -> str:
    return hashlib.sha256(problem.read_bytes()).hexdigest()


def _json_or_none(text: str) -> dict | None:
    try:
        return json.loads(text)
    except json.JSONDecodeError:
        return None


def table(rows_csv: Path, log: Path, bench: Path) -> None:
    rows = list(csv.DictReader(rows_csv.open()))
    runs: dict[str, dict] = {}
    for line in log.read_text().splitlines():
        entry = json.loads(line)
        if entry["result"] is not None:
            runs[entry["problem"]] = entry["result"]
    ours = {(r["domain"], r["task"]): r for r in rows if r["config"] == "ours"}
    base = {(r["domain"], r["task"]): r for r in rows if r["config"] == BASELINE}
    solved: dict[str, list[int]] = {}
    per_run_ms: list[float] = []
    ours_length = base_length = invalid = 0
    print("| task | means-ends | length | lazy-gbfs length | nodes | attempts | ms/attempt | s |")
    print("|---|---|---|---|---|---|---|---|")
    for (domain, task), row in sorted(ours.items()):
        result = runs.get(_digest(bench / domain / f"{task}.pddl"))
        stats = (result or {}).get("statistics") or {}
        attempts = stats.get("proof_attempts") or 0
        ms = 1000 * stats["proving_seconds"] / attempts if attempts else None
        if ms is not None:
            per_run_ms.append(ms)
        ok = row["solved"] == "True"
        counts = solved.setdefault(domain, [0, 0])
        counts[0] += ok
        counts[1] += 1
        invalid += row["valid"] not in ("", "VALID", "no-plan")
        other = base.get((domain, task), {})
        if ok and other.get("solved") == "True":
            ours_length += int(row["plan_len"])
            base_length += int(other["plan_len"])
        status = "solved" if ok else "timeout" if row["status"] == "timeout" else (result or {}).get("status", row["status"])
        print(f"| {domain} {task[-2:]} | {status} | {row['plan_len'] or '-'} | "
              f"{other.get('plan_len') or '-'} | {stats.get('nodes', '-')} | {attempts or '-'} | "
              f"{'-' if ms is None else f'{ms:.2f}'} | {row['wall']} |")
    print()
    total = sum(c[0] for c in solved.values()), sum(c[1] for c in solved.values())
    print(f"solved {total[0]}/{total[1]}: " + ", ".join(f"{d} {c[0]}/{c[1]}" for d, c in sorted(solved.items())))
    print(f"{BASELINE} solved {sum(r['solved'] == 'True' for r in base.values())}/{len(base)}; invalid plans (ours): {invalid}")
    if per_run_ms:
        print(f"median ms per attempt: {statistics.median(per_run_ms):.2f} over {len(per_run_ms)} runs")
    print(f"plan length over the tasks both solved: {ours_length} against {BASELINE}'s {base_length}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    commands = parser.add_subparsers(dest="command", required=True)
    run = commands.add_parser("solve", help="the --ours command")
    run.add_argument("--log", type=Path, required=True)
    run.add_argument("--config", type=Path, required=True)
    run.add_argument("domain", type=Path)
    run.add_argument("problem", type=Path)
    run.add_argument("plan", type=Path)
    show = commands.add_parser("table", help="the markdown table of a suite's runs")
    show.add_argument("csv", type=Path)
    show.add_argument("log", type=Path)
    show.add_argument("--bench", type=Path, default=BENCH, help="the suite's domain folders")
    args = parser.parse_args()
    if args.command == "solve":
        sys.exit(solve(args.log, args.config.resolve(), args.domain, args.problem, args.plan))
    if args.bench is None:
        parser.error("shared/bench/ipc not found: give --bench")
    table(args.csv, args.log, args.bench)


if __name__ == "__main__":
    main()
