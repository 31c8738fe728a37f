"""``strips bench report``: the summary table, the plots, and a Markdown page with both."""

from __future__ import annotations

import csv
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from strips_framework.bench import plots
from strips_framework.bench.summary import (
    COLUMNS,
    configs,
    markdown,
    per_problem_rows,
    summary_rows,
    tasks,
)
from strips_framework.errors import ConfigError


def write_report(
    rows: Sequence[dict[str, Any]], source: Path, folder: Path, pair: Sequence[str] | None = None
) -> str:
    """Write ``summary.csv``, the plots and ``report.md`` into ``folder``; return the
    summary table as Markdown. ``pair`` names the scatter plot's two configurations
    (default: the first two)."""
    found = tasks(rows)
    names = configs(found)
    first, second = _pair(names, pair)
    folder.mkdir(parents=True, exist_ok=True)
    table = summary_rows(found)
    with (folder / "summary.csv").open("w", newline="", encoding="utf-8") as out:
        csv.writer(out).writerows([COLUMNS, *table])
    time_limit = max(row.get("limits", {}).get("time", 1.0) for row in rows)
    images = plots.cactus(found, time_limit, folder / "cactus")
    if second is not None:
        for metric in plots.METRICS:
            stem = folder / f"scatter-{metric}"
            images += plots.scatter(found, first, second, metric, time_limit, stem)
    summary = markdown(COLUMNS, table)
    header, per_problem = per_problem_rows(found)
    page = [
        f"# Benchmark report: {source.name}",
        "",
        (
            f"{len(rows)} runs, {len({t.problem for t in found})} problems, "
            f"{len(names)} configurations; time limit {time_limit:g} s. A problem counts as "
            "solved when every repetition found a plan that the validator did not reject. "
            "Times are the wall clock of each run's process, start-up included, for every "
            "configuration; 'median planner time' is the planner's own where it reports one."
        ),
        "",
        summary,
        "",
        *(f"![{image.stem}]({image.name})" for image in images if image.suffix == ".png"),
        "",
        "## Per problem",
        "",
        markdown(header, per_problem),
        "",
    ]
    (folder / "report.md").write_text("\n".join(page), encoding="utf-8")
    return summary


def _pair(names: list[str], pair: Sequence[str] | None) -> tuple[str, str | None]:
    if not names:
        raise ConfigError("the results hold no runs")
    if pair is None:
        return names[0], names[1] if len(names) > 1 else None
    for name in pair:
        if name not in names:
            raise ConfigError(f"--pair: no configuration {name!r} in the results "
                              f"(present: {', '.join(names)})")
    return pair[0], pair[1]
