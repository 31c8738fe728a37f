"""``strips bench report``'s HTML page (Lab-style tables per domain, a sortable
per-task table, a scatter named on hover), Lab properties, and cactus styles."""

from __future__ import annotations

import json
from collections import defaultdict

import pytest

import figures
import synthetic_bench
from strips_framework.bench.page import log_score
from strips_framework.bench.plots import line_style
from strips_framework.cli.main import main


def test_lab_log_scores():
    assert log_score(None, 100, 1e6) == 0
    assert log_score(50, 100, 1e6) == 1 and log_score(100, 100, 1e6) == 1
    assert log_score(1e4, 100, 1e6) == 0.5
    assert log_score(1e6, 100, 1e6) == 0 and log_score(5e6, 100, 1e6) == 0


def test_sixteen_configurations_get_sixteen_styles():
    styles = {tuple(map(str, line_style(i).values())) for i in range(40)}
    assert len(styles) == 40


def test_cactus_with_sixteen_configurations_reads():
    """Distinct lines, the legend beside the axes (not over the lines), whole problems."""
    import matplotlib.pyplot as plt

    from strips_framework.bench.plots import cactus_figure
    from strips_framework.bench.summary import tasks

    figure = cactus_figure(tasks(synthetic_bench.rows()), 10.0)
    try:
        axes = figure.axes[0]
        lines = [line for line in axes.get_lines() if line.get_label().startswith("config-")]
        assert len(lines) == 16
        looks = {(line.get_color(), line.get_linestyle(), line.get_marker()) for line in lines}
        assert len(looks) == 16
        assert all(tick == int(tick) for tick in axes.get_yticks())
    finally:
        plt.close(figure)
    figure = cactus_figure(tasks(synthetic_bench.rows(problems=1)), 10.0)  # 4 problems
    try:
        axes = figure.axes[0]
        assert all(tick == int(tick) for tick in axes.get_yticks())  # no half problems
        figure.canvas.draw()
        legend = axes.get_legend().get_window_extent()
        assert legend.x0 >= axes.get_window_extent().x1
        # Best first: the legend lists configurations by problems solved.
        solved = [int(text.get_text().split("(")[1].split("/")[0]) for text in axes.get_legend().get_texts()]
        assert solved == sorted(solved, reverse=True)
    finally:
        plt.close(figure)


@pytest.fixture(scope="module")
def report(tmp_path_factory):
    folder = tmp_path_factory.mktemp("report")
    results = synthetic_bench.write(folder / "runs.jsonl")
    assert main(["bench", "report", str(results), "-o", str(folder / "out"), "--lab"]) == 0
    return folder / "out"


def _coverage(rows):
    found = defaultdict(int)
    for row in rows:
        found[row["problem"].split("/")[0], row["config"]] += row["status"] == "solved"
    return found


def test_lab_properties(report):
    properties = json.loads((report / "properties").read_text())
    rows = synthetic_bench.rows()
    assert len(properties) == len(rows)
    coverage = _coverage(rows)
    for (domain, config), solved in coverage.items():
        mine = [p for p in properties.values() if p["domain"] == domain and p["algorithm"] == config]
        assert sum(p["coverage"] for p in mine) == solved
    entry = properties["config-01-blocksworld-p01.pddl"]
    assert entry["id"] == ["config-01", "blocksworld", "p01.pddl"]
    assert entry["error"] == "success" and 0 < entry["score_total_time"] <= 1
    failed = next(p for p in properties.values() if not p["coverage"])
    assert failed["score_expansions"] == 0 and failed["error"].startswith("search-out-of")


def test_report_page_in_the_browser(launched, report):
    rows = synthetic_bench.rows()
    page, problems = figures.open_page(launched, report / "report.html", 1300, 900)
    page.wait_for_selector("#tasks tbody tr")
    # Coverage per domain, as Lab: a row per domain, a column per configuration, a sum.
    table = page.locator("table.domains").first
    header = table.locator("tr").first.locator("th").all_inner_texts()[1:]
    coverage = _coverage(rows)
    for tr in table.locator("tr").all()[1:-1]:
        domain = tr.locator("th").inner_text().split(" (")[0]
        cells = [int(c) for c in tr.locator("td").all_inner_texts()]
        assert cells == [coverage[domain, config] for config in header]
    total = [int(c) for c in table.locator("tr").last.locator("td").all_inner_texts()]
    assert total == [sum(coverage[d, c] for d in synthetic_bench.DOMAINS) for c in header]
    # The per-task table sorts by a column and filters by words.
    assert page.locator("#tasks tbody tr").count() == len(rows)
    page.click("#tasks th[data-key='time']")
    times = page.locator("#tasks tbody tr td:nth-child(5)").all_inner_texts()
    numbers = [float(t) for t in times if t != "-"]
    assert numbers == sorted(numbers) and numbers[0] == min(r["wall_seconds"] for r in rows)
    page.fill("#filter", "depot config-03")
    assert page.locator("#tasks tbody tr").count() == 6
    # The scatter names each problem on hover.
    titles = page.locator("#scatter circle title").all_text_contents()
    assert titles and all(t.split(":")[0].endswith(".pddl") for t in titles)
    page.select_option("#sy", "config-16")
    assert "config-16" in page.inner_text("#scatter")
    assert not problems, problems
