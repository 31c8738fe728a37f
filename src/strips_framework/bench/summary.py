"""From result rows to per-task outcomes and the per-configuration summary table.

A *task* is one problem under one configuration; its repetitions are folded into one
outcome: solved when every repetition found a plan that the validator did not reject,
with the median of each measurement. Time is the wall clock of the child process, start-up
included, for every configuration alike (ours, anchors, commands), so that columns
compare like with like; the planner's own time (``strips solve`` reports it, interpreter
start-up excluded) has a column of its own, empty for planners that report none.
"""

from __future__ import annotations

import statistics
from collections import defaultdict
from collections.abc import Sequence
from pathlib import PurePath
from typing import Any

from strips_framework.bench.runner import FAILURES, SOLVED, UNSOLVED
from strips_framework.records import Record

COLUMNS = (
    "config", "solved", "unsolved", "timeout", "memout", "crash", "invalid",
    "total wall time (s)", "median wall time (s)", "median planner time (s)",
    "median expansions", "median plan length", "proving share",
)


class Task(Record):
    problem: str
    config: str
    solved: bool
    status: str  # solved, or the status of the first repetition that was not
    time: float | None
    expanded: float | None
    plan_length: float | None
    proving_seconds: float | None
    planner_seconds: float | None
    invalid: bool
    #: The benchmark domain, as Downward Lab groups tasks: the problem's folder (else
    #: its problem set).
    domain: str

    __slots__ = ("problem", "config", "solved", "status", "time", "expanded", "plan_length",
                 "proving_seconds", "planner_seconds", "invalid", "domain")  # fmt: skip

    def __init__(
        self,
        problem: str,
        config: str,
        solved: bool,
        status: str,
        time: float | None,
        expanded: float | None,
        plan_length: float | None,
        proving_seconds: float | None,
        planner_seconds: float | None,
        invalid: bool,
        domain: str = "",
    ) -> None:
        self.problem = problem
        self.config = config
        self.solved = solved
        self.status = status
        self.time = time
        self.expanded = expanded
        self.plan_length = plan_length
        self.proving_seconds = proving_seconds
        self.planner_seconds = planner_seconds
        self.invalid = invalid
        self.domain = domain


def _median(values: list[Any]) -> float | None:
    present = [v for v in values if v is not None]
    return statistics.median(present) if present else None


def tasks(rows: Sequence[dict[str, Any]]) -> list[Task]:
    """One outcome per (problem, configuration), in the matrix's order (rows finish in
    any order)."""
    grouped: dict[tuple[str, str], list[dict[str, Any]]] = defaultdict(list)
    for row in sorted(rows, key=lambda row: row.get("position", len(rows))):
        grouped[row["problem"], row["config"]].append(row)
    found = []
    for (problem, config), runs in grouped.items():
        invalid = any(run.get("valid") is False for run in runs)
        solved = all(run["status"] == SOLVED for run in runs) and not invalid
        status = next((run["status"] for run in runs if run["status"] != SOLVED), SOLVED)
        found.append(Task(
            problem, config, solved, "invalid" if invalid else status,
            _median([run.get("wall_seconds") for run in runs]),
            _median([run.get("expanded") for run in runs]),
            _median([run.get("plan_length") for run in runs]),
            _median([run.get("proving_seconds") for run in runs]),
            _median([run.get("planner_seconds") for run in runs]),
            invalid,
            PurePath(problem).parent.name or runs[0].get("problem_set") or "",
        ))
    return found


def configs(found: Sequence[Task]) -> list[str]:
    return list(dict.fromkeys(task.config for task in found))


def summary_rows(found: Sequence[Task]) -> list[list[str]]:
    """The summary table's cells, one row per configuration (see :data:`COLUMNS`)."""
    table = []
    for config in configs(found):
        mine = [task for task in found if task.config == config]
        solved = [task for task in mine if task.solved]
        times = [task.time for task in solved if task.time is not None]
        proving = [t.proving_seconds for t in solved if t.proving_seconds is not None]
        planner = [t.planner_seconds for t in solved if t.proving_seconds is not None]
        share = sum(proving) / sum(planner) if proving and sum(planner) else None
        table.append([
            config,
            f"{len(solved)}/{len(mine)}",
            *(str(sum(task.status == status for task in mine)) for status in (UNSOLVED, *FAILURES)),
            str(sum(task.invalid for task in mine)),
            _cell(sum(times) if times else None, ".3f"),
            _cell(_median(times), ".3f"),
            _cell(_median([task.planner_seconds for task in solved]), ".3f"),
            _cell(_median([task.expanded for task in solved]), "g"),
            _cell(_median([task.plan_length for task in solved]), "g"),
            _cell(share, ".0%"),
        ])
    return table


def _cell(value: float | None, spec: str) -> str:
    return "-" if value is None else format(value, spec)


def markdown(header: Sequence[str], rows: Sequence[Sequence[str]]) -> str:
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    return "\n".join(lines + ["| " + " | ".join(row) + " |" for row in rows])


def per_problem_rows(found: Sequence[Task]) -> tuple[list[str], list[list[str]]]:
    """A problem x configuration table: wall time, expansions and plan length, or the
    status."""
    names = configs(found)
    by_key = {(task.problem, task.config): task for task in found}
    rows = []
    for problem in dict.fromkeys(task.problem for task in found):
        cells = [problem]
        for config in names:
            task = by_key.get((problem, config))
            if task is None:
                cells.append("")
            elif task.solved:
                cells.append(
                    f"{_cell(task.time, '.3f')} s, {_cell(task.expanded, 'g')} exp, "
                    f"{_cell(task.plan_length, 'g')} steps"
                )
            else:
                cells.append(task.status)
        rows.append(cells)
    return ["problem", *names], rows
