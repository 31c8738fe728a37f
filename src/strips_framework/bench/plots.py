"""The two pictures planning papers use: a cactus (coverage) plot and a pairwise scatter.

Both go to PNG and SVG. matplotlib runs on its Agg backend: no display is needed, and
a report can be made on a cluster's head node.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

from strips_framework.bench.summary import Task, configs

FORMATS = ("png", "svg")
#: Line styles for many configurations: ten colours, then the next ten dashed, then
#: dotted...; each line also gets its own marker, so no two configurations look alike.
_COLOURS = plt.get_cmap("tab10").colors
_DASHES = ("-", "--", ":", "-.")
_MARKERS = ("o", "s", "^", "D", "v", "P", "X", "<", ">", "*", "h", "p")


def line_style(index: int) -> dict[str, object]:
    """The colour, dash and marker of configuration ``index``: distinct for the first
    ``len(_COLOURS) * len(_DASHES)`` (40) configurations."""
    return {
        "color": _COLOURS[index % len(_COLOURS)],
        "linestyle": _DASHES[index // len(_COLOURS) % len(_DASHES)],
        "marker": _MARKERS[index % len(_MARKERS)],
    }
METRICS = {"time": "wall-clock time (s, start-up included)", "expansions": "expansions"}


def _save(figure: plt.Figure, stem: Path) -> list[Path]:
    figure.tight_layout()
    paths = [stem.with_suffix(f".{fmt}") for fmt in FORMATS]
    for path in paths:  # "tight": the legend outside the axes is kept whole
        figure.savefig(path, dpi=150, bbox_inches="tight")
    plt.close(figure)
    return paths


def cactus(found: Sequence[Task], time_limit: float, stem: Path) -> list[Path]:
    """The cactus plot (:func:`cactus_figure`) as PNG and SVG."""
    return _save(cactus_figure(found, time_limit), stem)


def cactus_figure(found: Sequence[Task], time_limit: float) -> plt.Figure:
    """Problems solved (y) within a time (x, log scale), one step line per configuration,
    each in its own style (:func:`line_style`), the legend outside the axes (best first),
    and whole problems on the y axis."""
    from matplotlib.ticker import MaxNLocator

    names = configs(found)
    total = len({task.problem for task in found})
    solved_by = {name: sorted(t.time for t in found if t.config == name and t.solved and t.time)
                 for name in names}
    figure, axes = plt.subplots(figsize=(7, 4.5))
    order = sorted(range(len(names)), key=lambda i: -len(solved_by[names[i]]))
    for index in order:
        name = names[index]
        times = solved_by[name]
        solved = len(times)
        xs = [times[0], *times, time_limit] if times else [time_limit]
        ys = [0, *range(1, solved + 1), solved] if times else [0]
        axes.step(xs, ys, where="post", label=f"{name} ({solved}/{total})", linewidth=1.6,
                  markevery=list(range(1, len(xs) - 1)) or None, markersize=4,
                  **line_style(index))
    axes.set_xscale("log")
    axes.set_xlabel("wall-clock time per problem (s, start-up included, log scale)")
    axes.set_ylabel("problems solved")
    axes.set_ylim(0, total + 0.5)
    axes.yaxis.set_major_locator(MaxNLocator(integer=True))
    axes.axvline(time_limit, color="grey", linestyle=":", linewidth=1)
    axes.set_title("Coverage: problems solved within a time")
    axes.grid(True, which="both", alpha=0.3)
    columns = 1 if len(names) <= 20 else 2
    axes.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize="small",
                ncol=columns, borderaxespad=0)
    figure.set_size_inches(7 + 2.6 * columns, max(4.5, 0.22 * len(names) / columns + 1))
    return figure


def scatter(
    found: Sequence[Task], first: str, second: str, metric: str, time_limit: float, stem: Path
) -> list[Path]:
    """One point per problem: ``first``'s value (x) against ``second``'s (y), log-log.

    A problem one side did not solve sits on that side's "unsolved" line, beyond every
    measured value; points below the diagonal are problems where ``second`` did better.
    """

    def value(task: Task | None) -> float | None:
        if task is None or not task.solved:
            return None
        return task.time if metric == "time" else task.expanded

    by_key = {(task.problem, task.config): task for task in found}
    problems = list(dict.fromkeys(task.problem for task in found))
    pairs = [(value(by_key.get((p, first))), value(by_key.get((p, second)))) for p in problems]
    measured = [v for pair in pairs for v in pair if v]
    if metric == "time":
        ceiling = max([time_limit, *measured])
    else:
        ceiling = 2 * max(measured, default=1)
    floor = min(measured, default=ceiling / 10) / 2
    both = [(x, y) for x, y in pairs if x and y]
    one = [(x or ceiling, y or ceiling) for x, y in pairs if bool(x) != bool(y)]
    figure, axes = plt.subplots(figsize=(5.5, 5.5))
    axes.plot([floor, ceiling], [floor, ceiling], color="grey", linewidth=1, label="equal")
    axes.axhline(ceiling, color="red", linestyle=":", linewidth=1, label="unsolved (the limit)")
    axes.axvline(ceiling, color="red", linestyle=":", linewidth=1)
    if both:
        axes.scatter(*zip(*both, strict=True), s=28, label=f"both solved ({len(both)})")
    if one:
        axes.scatter(*zip(*one, strict=True), s=36, marker="x", color="red",
                     label=f"solved by one only ({len(one)})")
    axes.set_xscale("log")
    axes.set_yscale("log")
    axes.set_xlim(floor, ceiling * 1.5)
    axes.set_ylim(floor, ceiling * 1.5)
    axes.set_xlabel(f"{first}: {METRICS[metric]}")
    axes.set_ylabel(f"{second}: {METRICS[metric]}")
    axes.set_title(f"{METRICS[metric].split(' ')[0].capitalize()} per problem (log-log)")
    axes.grid(True, which="both", alpha=0.3)
    axes.legend(loc="best", fontsize="small")
    return _save(figure, stem)
