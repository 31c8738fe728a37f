"""``strips bench report``: the summary table, the plots, a Markdown page with both, the
HTML report (:mod:`strips_framework.bench.page`) and, on request, Lab's properties."""

from __future__ import annotations

import csv
import json
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
    rows: Sequence[dict[str, Any]],
    source: Path,
    folder: Path,
    pair: Sequence[str] | None = None,
    lab: bool = False,
) -> str:
    """Write ``summary.csv``, the plots, ``report.md`` and ``report.html`` into
    ``folder`` (and Lab's ``properties`` with ``lab``); return the summary table as
    Markdown. ``pair`` names the scatter plots' two configurations (default: the first
    two; the HTML page lets the reader pick any two)."""
    from strips_framework.bench.page import lab_properties, report_page

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
    intro = (
        f"{len(rows)} runs, {len({t.problem for t in found})} problems, "
        f"{len(names)} configurations; time limit {time_limit:g} s. A problem counts as "
        "solved when every repetition found a plan that the validator did not reject. "
        "Times are the wall clock of each run's process, start-up included, for every "
        "configuration; 'median planner time' is the planner's own where it reports one."
    )
    title = f"Benchmark report: {source.name}"
    shown = [image.name for image in images if image.suffix == ".svg" and image.stem == "cactus"]
    (folder / "report.html").write_text(report_page(found, title, intro, time_limit, shown),
                                        encoding="utf-8")
    if lab:
        properties = lab_properties(found, time_limit)
        (folder / "properties").write_text(json.dumps(properties, indent=2, sort_keys=True),
                                           encoding="utf-8")
    page = [
        f"# {title}",
        "",
        intro,
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
