"""Execute one run: start its child under limits, read what it says, check its plan.

:func:`execute` is what a local thread or a Dask worker calls; it never raises for
anything the run does (a crash, a hang, a memory blow-up, garbage output are all causes
recorded in the row), so one bad run costs that run alone.
"""

from __future__ import annotations

import json
import os
import shutil
import signal
import tempfile
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

from strips_framework.bench import anchors, environment
from strips_framework.bench.configs import RunFiles, strips_command
from strips_framework.bench.isolation import ChildOutcome, LiveGroups, run_limited
from strips_framework.bench.matrix import RunSpec

SOLVED, UNSOLVED, TIMEOUT, MEMOUT, CRASH = "solved", "unsolved", "timeout", "memout", "crash"
FAILURES = (TIMEOUT, MEMOUT, CRASH)

#: Fast Downward's exit codes, which ``strips solve`` follows for PDDL tasks.
PLAN_FOUND_CODES = {0, 1, 2, 3}  # 1-3: a plan, then out of memory and/or time
UNSOLVED_CODES = {10: "unsolvable (translator)", 11: "unsolvable", 12: "search exhausted (incomplete)"}
MEMOUT_CODES = {20, 22, 24}
TIMEOUT_CODES = {21, 23}
MEMORY_ERRORS = ("MemoryError", "std::bad_alloc", "Cannot allocate memory")


def execute(spec: RunSpec, live: LiveGroups | None = None) -> dict[str, Any]:
    """Run ``spec`` in a private folder (removed afterwards) and return its row."""
    folder = Path(tempfile.mkdtemp(prefix="strips-bench-"))
    try:
        return _execute_in(spec, folder, live)
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def _execute_in(spec: RunSpec, folder: Path, live: LiveGroups | None) -> dict[str, Any]:
    problem, domain = spec.problem.path, spec.problem.domain
    if spec.config.copies_inputs:
        problem = Path(shutil.copy(problem, folder / problem.name))
        domain = Path(shutil.copy(domain, folder / "domain.pddl")) if domain else None
    files = RunFiles(problem, domain, folder)
    env = {**os.environ, "PYTHONHASHSEED": str(spec.seed)}
    row = _base_row(spec)
    try:
        command = spec.config.command(files, spec.limits.time)
        outcome = run_limited(command, folder, env, spec.limits.time, spec.limits.memory, live)
    except OSError as error:  # the planner is missing or cannot start on this machine
        return row | {"status": CRASH, "cause": f"cannot start: {error}"}
    row["command"] = command
    steps = read_plan(spec.config.plan_file(files))
    payload = _json_payload(outcome.stdout)
    row |= _measurements(outcome, payload, steps)
    row |= _classify(outcome, payload, steps, spec.limits.time)
    if row["status"] == SOLVED:
        row |= _validate(files, spec.config.plan_file(files), spec, env, live)
    return row


def _base_row(spec: RunSpec) -> dict[str, Any]:
    return {
        "key": spec.key,
        "problem": spec.problem.name,
        "problem_set": spec.problem.problem_set,
        "config": spec.config.name,
        "repetition": spec.repetition,
        "position": spec.position,
        "seed": spec.seed,
        "limits": {"time": spec.limits.time, "memory_mib": spec.limits.memory},
        "config_spec": spec.config.describe(),
        "machine": environment.machine(),
        "versions": environment.versions(),
        "finished": datetime.now(UTC).isoformat(timespec="seconds"),
        "valid": None,
        "validation": None,
    }


def read_plan(path: Path) -> list[str] | None:
    """The steps of a plan file (``;`` comments dropped), or ``None`` if none was written."""
    try:
        lines = path.read_text(encoding="utf-8").splitlines()
    except (OSError, UnicodeDecodeError):
        return None
    steps = [line.split(";", 1)[0].strip() for line in lines]
    return [step for step in steps if step] or None


def _json_payload(stdout: str) -> dict[str, Any] | None:
    """The ``strips solve --json`` result, if the child printed one."""
    try:
        payload = json.loads(stdout)
    except ValueError:
        return None
    return payload if isinstance(payload, dict) and "status" in payload else None


def _measurements(
    outcome: ChildOutcome, payload: dict[str, Any] | None, steps: list[str] | None
) -> dict[str, Any]:
    statistics = (payload or {}).get("statistics") or {}
    expanded = statistics.get("expanded", statistics.get("nodes"))
    if expanded is None:
        expanded = anchors.parse_expansions(outcome.stdout + "\n" + outcome.stderr)
    return {
        "exit_code": outcome.exit_code,
        "wall_seconds": round(outcome.wall_seconds, 4),
        "planner_seconds": _planner_seconds(payload or {}),
        "proving_seconds": statistics.get("proving_seconds"),
        "expanded": expanded,
        "peak_memory_mib": round(outcome.peak_memory_kib / 1024, 1),
        "planner_status": (payload or {}).get("status"),
        "statistics": statistics or None,
        "plan": steps,
        "plan_length": len(steps) if steps is not None else None,
    }


def _planner_seconds(payload: dict[str, Any]) -> float | None:
    """The planner's own time: the ``seconds`` of a ``strips solve --json`` document (or
    of its statistics), else the sum of the phases its statistics report."""
    statistics = payload.get("statistics") or {}
    for found in (payload, statistics):
        if "seconds" in found:
            return found["seconds"]
    phases = [v for k, v in statistics.items() if k.endswith("_seconds") and k != "proving_seconds"]
    return round(sum(phases), 4) if phases else None


def _classify(
    outcome: ChildOutcome, payload: dict[str, Any] | None, steps: list[str] | None, limit: float
) -> dict[str, Any]:
    """The run's status and, unless solved, its cause."""
    code, stderr = outcome.exit_code, outcome.stderr
    last_line = next((line for line in reversed(stderr.splitlines()) if line.strip()), "")
    if outcome.timed_out:
        return {"status": TIMEOUT, "cause": f"wall-clock limit of {limit:g} s: process group killed"}
    if payload is not None and payload["status"] == SOLVED or (
        payload is None and steps and code in PLAN_FOUND_CODES
    ):
        return {"status": SOLVED, "cause": None}
    if code in MEMOUT_CODES or any(marker in stderr for marker in MEMORY_ERRORS):
        return {"status": MEMOUT, "cause": f"out of memory (exit code {code}): {last_line}".strip()}
    if code in TIMEOUT_CODES:
        return {"status": TIMEOUT, "cause": f"the planner's own time limit (exit code {code})"}
    if payload is not None:
        return {"status": UNSOLVED, "cause": f"planner status: {payload['status']}"}
    if code in UNSOLVED_CODES or code == 0:
        return {"status": UNSOLVED, "cause": UNSOLVED_CODES.get(code, "no plan written")}
    if code < 0:
        return {"status": CRASH, "cause": f"killed by {signal.Signals(-code).name}: {last_line}".strip()}
    return {"status": CRASH, "cause": f"exit code {code}: {last_line or 'no message'}"}


def _validate(
    files: RunFiles, plan: Path, spec: RunSpec, env: dict[str, str], live: LiveGroups | None
) -> dict[str, Any]:
    """``strips validate [DOMAIN] PROBLEM PLAN`` in its own child; its verdict."""
    folder = files.folder / "validate"
    folder.mkdir()
    inputs = [str(files.domain)] if files.domain else []
    command = strips_command("validate", *inputs, str(files.problem), str(plan))
    outcome = run_limited(command, folder, env, spec.limits.time, spec.limits.memory, live)
    message = (outcome.stdout.strip().splitlines() or [""])[0]
    if outcome.exit_code in (0, 1) and not outcome.timed_out:
        return {"valid": outcome.exit_code == 0, "validation": message}
    reason = "time limit" if outcome.timed_out else (outcome.stderr.strip().splitlines() or [""])[-1]
    return {"valid": None, "validation": f"not checked: {reason}"}
