"""Benchmark runs: every problem under every chosen prover x evaluator x strategy.

Each run reports the paper's Table 2 figures and whether the plan replays in the
independent simulator, so a fast but wrong combination cannot look good.
"""

from __future__ import annotations

import csv
import itertools
from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import TextIO

from attrs import frozen

from strips_framework.config import Config
from strips_framework.planner import Planner
from strips_framework.simulate import replay

COLUMNS = (
    "problem", "strategy", "evaluator", "prover", "status", "plan", "valid", "nodes",
    "path_nodes", "applications", "path_applications", "seconds", "proving_share",
)


@frozen
class Run:
    problem: str
    strategy: str
    evaluator: str
    prover: str
    status: str
    plan: int | None
    valid: bool | None
    nodes: int
    path_nodes: int
    applications: int
    path_applications: int
    seconds: float
    proving_share: float

    def row(self) -> list[object]:
        return [getattr(self, column) for column in COLUMNS]


def run_matrix(
    base: Config,
    problems: Sequence[Path],
    strategies: Iterable[str],
    evaluators: Iterable[str],
    provers: Iterable[str],
) -> list[Run]:
    """Solve every problem with every combination; the base config supplies the rest."""
    runs = []
    for strategy, evaluator, prover in itertools.product(strategies, evaluators, provers):
        choices = {kind: {"name": c.name, **c.options} for kind, c in base.choices.items()}
        for kind, name in (("strategy", strategy), ("evaluator", evaluator), ("prover", prover)):
            if name != base.choices[kind].name:  # the base's options belong to its choice
                choices[kind] = {"name": name}
        limits = {"time": base.limits.time, "nodes": base.limits.nodes, "effort": base.limits.effort}
        planner = Planner.create(Config.from_dict({**choices, "limits": limits}, base.source))
        for path in problems:
            problem = planner.load(path)
            result = planner.solve(problem)
            s = result.statistics
            plan = [str(step) for step in result.plan] if result.plan is not None else None
            runs.append(Run(
                problem.name, strategy, evaluator, prover, result.status,
                len(plan) if plan is not None else None,
                replay(problem, plan).valid if plan is not None else None,
                s.nodes, s.path_nodes, s.applications, s.path_applications,
                round(s.seconds, 3), round(s.proving_share, 2),
            ))
    return runs


def markdown_table(runs: Sequence[Run]) -> str:
    def cell(value: object) -> str:
        return "-" if value is None else str(value)

    lines = ["| " + " | ".join(COLUMNS) + " |", "|" + "---|" * len(COLUMNS)]
    lines += ["| " + " | ".join(cell(v) for v in run.row()) + " |" for run in runs]
    return "\n".join(lines)


def write_csv(runs: Sequence[Run], out: TextIO) -> None:
    writer = csv.writer(out)
    writer.writerow(COLUMNS)
    writer.writerows(run.row() for run in runs)
