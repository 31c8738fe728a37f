"""The quick form: `strips bench PROBLEM... --strategies ... --evaluators ...`."""

from __future__ import annotations

import argparse

from strips_framework.cli.main import main
from strips_framework.plugin.registry import Registry

from .conftest import PUSH_ONE_BOX, ROOT, read_rows

BLOCKS_P4 = ROOT / "examples" / "pddl" / "blocksworld" / "p4.pddl"


def test_quick_form_runs_every_combination_and_prints_the_tables(tmp_path, capsys):
    out = tmp_path / "runs.jsonl"
    args = ["bench", str(PUSH_ONE_BOX), "--strategies", "means-ends",
            "--evaluators", "breadth-first,goal-count,paper,astar-goals", "--jobs", "2",
            "--no-progress", "-o", str(out)]
    assert main(args) == 0
    lines = capsys.readouterr().out.splitlines()
    configs = ["breadth-first", "goal-count", "paper", "astar-goals"]
    assert lines[0] == "| problem | " + " | ".join(configs) + " |"
    assert "push-one-box.strips | " in lines[2]
    assert lines[2].count("2 steps") == 4
    assert [line.split(" | ")[0] for line in lines[6:]] == [f"| {c}" for c in configs]
    rows = read_rows(out)
    assert len(rows) == 4 and all(r["status"] == "solved" and r["valid"] for r in rows)


def test_quick_form_keeps_the_options_of_the_configs_own_choices(tmp_path, capsys):
    config = tmp_path / "strips.toml"
    config.write_text('[strategy]\nname = "means-ends"\nmax_goals = 1\n')
    assert main(["bench", str(PUSH_ONE_BOX), "--config", str(config), "--no-progress"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert lines[0] == "| problem | means-ends+paper+resolution |"
    assert lines[2].endswith("| unsolved |")  # no room for subgoals


def test_quick_form_reports_a_missing_problem(tmp_path, capsys):
    assert main(["bench", str(tmp_path / "none.strips")]) == 2
    assert "no such problem file" in capsys.readouterr().err


def _quick_runs(*targets: str) -> list:
    from strips_framework.bench import command

    parser = argparse.ArgumentParser()
    command.add_parser(parser.add_subparsers(dest="command"))
    args = parser.parse_args(["bench", *targets, "--all"])
    return command._quick_matrix(args).runs()


def test_all_runs_ground_task_strategies_on_pddl_problems_only():
    registry = Registry.from_plugins()
    native = _quick_runs(str(PUSH_ONE_BOX))
    world_model = len(registry.names("strategy"))
    per_strategy = len(registry.names("evaluator")) * len(registry.names("prover"))
    assert len(native) == world_model * per_strategy  # no ground-task strategy crossed
    both = _quick_runs(str(PUSH_ONE_BOX), str(BLOCKS_P4))
    ground = [r for r in both if r.config.name.split("+")[0] in registry.names("ground-strategy")]
    assert ground and all(r.problem.path.suffix == ".pddl" for r in ground)
