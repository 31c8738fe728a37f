"""`strips bench report`: the summary table's values, the plots and the Markdown page."""

from __future__ import annotations

import json
from xml.etree import ElementTree

import pytest

from strips_framework.cli.main import main


def row(problem, config, status, time=None, expanded=None, length=None, proving=None,
        valid=True, repetition=0):
    return {
        "key": f"{problem} | {config} | {repetition}", "problem": problem, "config": config,
        "repetition": repetition, "status": status, "planner_seconds": time,
        "wall_seconds": (time or 0) + 0.2, "proving_seconds": proving, "expanded": expanded,
        "plan_length": length, "valid": valid if status == "solved" else None,
        "limits": {"time": 10.0, "memory_mib": 512},
    }


ROWS = [
    row("p1", "paper", "solved", 1.0, 10, 4, 0.5),
    row("p1", "paper", "solved", 3.0, 10, 4, 1.5, repetition=1),  # median of the two: 2.0
    row("p2", "paper", "solved", 4.0, 30, 6, 1.0),
    row("p3", "paper", "timeout"),
    row("p1", "goal-count", "solved", 0.5, 5, 4, 0.5),
    row("p2", "goal-count", "solved", 0.1, 7, 8, 0.05, valid=False),
    row("p3", "goal-count", "memout"),
    row("p1", "fd", "crash"),
    row("p2", "fd", "solved", None, 3, 5),  # no planner time of its own
    row("p3", "fd", "unsolved"),
]


@pytest.fixture
def results(tmp_path):
    path = tmp_path / "runs.jsonl"
    path.write_text("".join(json.dumps(r) + "\n" for r in ROWS))
    return path


def test_report_prints_the_table_and_writes_plots_and_page(results, tmp_path, capsys):
    out = tmp_path / "report"
    assert main(["bench", "report", str(results), "-o", str(out)]) == 0
    table = capsys.readouterr().out.splitlines()
    assert table[0] == (
        "| config | solved | unsolved | timeout | memout | crash | invalid | "
        "total wall time (s) | median wall time (s) | median planner time (s) | "
        "median expansions | median plan length | proving share |"
    )
    # Wall clock for every configuration alike; the planner's own time apart.
    assert table[2] == "| paper | 2/3 | 0 | 1 | 0 | 0 | 0 | 6.400 | 3.200 | 3.000 | 20 | 5 | 33% |"
    assert table[3] == "| goal-count | 1/3 | 0 | 0 | 1 | 0 | 1 | 0.700 | 0.700 | 0.500 | 5 | 4 | 100% |"
    assert table[4] == "| fd | 1/3 | 1 | 0 | 0 | 1 | 0 | 0.200 | 0.200 | - | 3 | 5 | - |"
    for stem in ("cactus", "scatter-time", "scatter-expansions"):
        assert (out / f"{stem}.png").read_bytes().startswith(b"\x89PNG")
        ElementTree.parse(out / f"{stem}.svg")  # well-formed
    page = (out / "report.md").read_text()
    assert "![cactus](cactus.png)" in page and "![scatter-time](scatter-time.png)" in page
    assert "| p2 | 4.200 s, 30 exp, 6 steps | invalid | 0.200 s, 3 exp, 5 steps |" in page
    csv_lines = (out / "summary.csv").read_text().splitlines()
    assert csv_lines[1].startswith("paper,2/3,0,1,0,0,0,6.400,3.200,3.000")


def test_report_pair_and_errors(results, tmp_path, capsys):
    out = tmp_path / "pair"
    assert main(["bench", "report", str(results), "-o", str(out), "--pair", "fd,paper"]) == 0
    assert (out / "scatter-time.svg").is_file()
    assert main(["bench", "report", str(results), "--pair", "fd,lama"]) == 2
    assert "--pair: no configuration 'lama' in the results" in capsys.readouterr().err
    results.write_text(results.read_text() + "not json\n")
    assert main(["bench", "report", str(results)]) == 2
    assert f"{results}:11: not a JSON object" in capsys.readouterr().err
