"""Anchor planners in a matrix: their output read, their plans kept (and, once the CLI
validates PDDL plans, checked). The runs skip when the anchors are not installed."""

from __future__ import annotations

import pytest
from shared_bench import small_bench

from strips_framework.bench import anchors
from strips_framework.cli.main import main

from .conftest import read_rows


def test_expansions_are_read_from_each_planners_output():
    fast_downward = "[t=0.01s] Expanded 12 state(s).\n...\n[t=0.02s] Expanded 31 state(s).\n"
    assert anchors.parse_expansions(fast_downward) == 31
    assert anchors.parse_expansions("2021-01-01 INFO  17 Nodes expanded\n") == 17
    assert anchors.parse_expansions("; status: solved\n; expanded: 9\n") == 9
    assert anchors.parse_expansions("no figures here") is None


@pytest.mark.parametrize(("planner", "table"), [
    (anchors.PYPERPLAN, 'anchor = "pyperplan"\nargs = ["-s", "gbf", "-H", "hff"]'),
    (anchors.FAST_DOWNWARD, 'anchor = "fast-downward"\nsearch = "astar(blind())"'),
], ids=anchors.PLANNERS)
def test_an_anchor_solves_an_ipc_task(planner, table, write_matrix, tmp_path):
    if anchors.planner_command(planner) is None:
        pytest.skip(anchors.missing_note(planner))
    task = small_bench("ipc") / "gripper" / "task01.pddl"
    matrix = write_matrix(
        f'[limits]\ntime = 60\nmemory = 4096\n[problems]\ng = ["{task}"]\n'
        f"[configs.anchor]\n{table}\n"
    )
    out = tmp_path / "results.jsonl"
    assert main(["bench", str(matrix), "-o", str(out), "--no-progress"]) == 0
    [row] = read_rows(out)
    assert row["status"] == "solved", row["cause"]
    assert row["expanded"] > 0 and row["plan_length"] == len(row["plan"]) > 0
    assert row["plan"][0].startswith("(")
    assert row["valid"] is not False
    assert row["config_spec"]["planner"] == planner
