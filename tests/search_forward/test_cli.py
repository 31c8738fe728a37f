"""``strips solve`` and ``strips validate`` on PDDL: plan files, output, JSON, exit codes,
limits and determinism."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from strips_framework import exit_codes
from strips_framework.cli.main import main

ROOT = Path(__file__).resolve().parents[2]
BLOCKS = ROOT / "examples" / "pddl" / "blocksworld"
FAST = ROOT / "examples" / "configs" / "fast.toml"
OPTIMAL = ROOT / "examples" / "configs" / "optimal-pddl.toml"
DATA = Path(__file__).resolve().parent / "data"


def config(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "strips.toml"
    path.write_text(text)
    return path


def test_solve_writes_an_ipc_plan_and_prints_the_figures(tmp_path, capsys):
    plan = tmp_path / "plan.txt"
    args = ["solve", str(BLOCKS / "domain.pddl"), str(BLOCKS / "p4.pddl"),
            "--config", str(FAST), "--plan-file", str(plan)]
    assert main(args) == exit_codes.SOLVED
    lines = plan.read_text().splitlines()
    assert all(line.startswith("(") and line.endswith(")") for line in lines[:-1])
    assert lines[-1] == f"; cost = {len(lines) - 1} (unit cost)"
    out = capsys.readouterr().out.splitlines()
    assert out[: len(lines) - 1] == lines[:-1]
    assert "; status: solved" in out
    assert any(line.startswith("; expanded: ") for line in out)
    assert main(["validate", str(BLOCKS / "domain.pddl"), str(BLOCKS / "p4.pddl"), str(plan)]) == 0


def test_the_domain_is_found_beside_the_problem(tmp_path, capsys):
    plan = tmp_path / "plan.txt"
    assert main(["solve", str(BLOCKS / "p4.pddl"), "--config", str(OPTIMAL),
                 "--plan-file", str(plan)]) == 0
    assert plan.read_text().splitlines()[-1] == "; cost = 8 (unit cost)"  # optimal: 8 steps
    assert main(["validate", str(BLOCKS / "p4.pddl"), str(plan)]) == 0


def test_action_costs_give_a_general_cost_plan(tmp_path):
    plan = tmp_path / "plan.txt"
    assert main(["solve", str(DATA / "domain.pddl"), str(DATA / "detour.pddl"),
                 "--config", str(OPTIMAL), "--plan-file", str(plan)]) == 0
    assert plan.read_text() == "(move a b)\n(move b c)\n(move c d)\n; cost = 3 (general cost)\n"


def test_json_gives_plan_status_limit_and_statistics(capsys):
    assert main(["solve", str(BLOCKS / "p4.pddl"), "--config", str(FAST), "--json"]) == 0
    payload = json.loads(capsys.readouterr().out)
    assert payload["status"] == "solved" and payload["limit"] is None
    assert payload["exit_code"] == 0 and payload["cost"] == len(payload["plan"])
    assert payload["config"]["strategy"] == "lazy-gbfs" and payload["config"]["heuristic"] == "ff"
    assert set(payload["statistics"]) == {
        "expanded", "evaluated", "generated", "reopened", "dead_ends", "facts", "operators",
        "parse_seconds", "ground_seconds", "search_seconds", "peak_memory_mib",
    }


def test_unsolvable_task_exits_11(capsys):
    assert main(["solve", str(DATA / "domain.pddl"), str(DATA / "dead-end.pddl"),
                 "--config", str(FAST)]) == exit_codes.UNSOLVABLE
    assert "; status: unsolvable" in capsys.readouterr().out


def test_expansion_limit_exits_12_and_json_names_the_limit(tmp_path, capsys):
    limited = config(tmp_path, '[strategy]\nname = "breadth-first"\n[limits]\nexpansions = 3\n')
    code = main(["solve", str(BLOCKS / "p4.pddl"), "--config", str(limited), "--json"])
    payload = json.loads(capsys.readouterr().out)
    assert code == exit_codes.UNSOLVED_INCOMPLETE == payload["exit_code"]
    assert payload["status"] == "expansion-limit" and payload["limit"] == "expansions"
    assert payload["statistics"]["expanded"] == 3 and payload["plan"] is None


def test_hill_climbing_that_gives_up_exits_12(tmp_path):
    # On these four blocks, hFF's helpful actions lead hill-climbing where it cannot go on.
    tasks = ROOT / "src" / "strips_framework" / "testing" / "tasks"
    ehc = config(tmp_path, '[strategy]\nname = "ehc"\n[heuristic]\nname = "ff"\n')
    files = [str(tasks / "blocks-domain.pddl"), str(tasks / "blocks-4.pddl")]
    assert main(["solve", *files, "--config", str(ehc)]) == 12


def test_wrong_plan_is_explained_at_its_failing_step(tmp_path, capsys):
    plan = tmp_path / "plan.txt"
    plan.write_text("(unstack a b)\n(stack a c)  ; c is not clear\n")
    code = main(["validate", str(BLOCKS / "domain.pddl"), str(BLOCKS / "p4.pddl"), str(plan)])
    assert code == exit_codes.INVALID_PLAN
    out = capsys.readouterr().out
    assert "step 2 (stack a c)" in out and "(clear c) is false" in out


def test_ground_strategy_on_a_native_problem_is_a_config_error(tmp_path, capsys):
    native = ROOT / "examples" / "three-boxes.strips"
    assert main(["solve", str(native), "--config", str(FAST)]) == exit_codes.INPUT_ERROR
    assert "searches ground tasks" in capsys.readouterr().err


def test_too_many_files_is_a_usage_error(capsys):
    files = [str(BLOCKS / "domain.pddl")] * 3
    assert main(["solve", *files]) == exit_codes.INPUT_ERROR
    assert "usage: strips solve [DOMAIN] PROBLEM" in capsys.readouterr().err


@pytest.mark.parametrize("config_path", [FAST, OPTIMAL])
def test_same_output_whatever_the_hash_seed(config_path):
    def run(seed: str) -> str:
        env = {**os.environ, "PYTHONHASHSEED": seed}
        script = "import sys; from strips_framework.cli.main import main; sys.exit(main())"
        command = [sys.executable, "-c", script, "solve", str(BLOCKS / "p4.pddl"),
                   "--config", str(config_path), "--json"]
        done = subprocess.run(command, env=env, capture_output=True, text=True, check=True)
        payload = json.loads(done.stdout)
        statistics = payload["statistics"]
        return json.dumps([payload["plan"], {k: v for k, v in statistics.items()
                                             if not k.endswith(("seconds", "mib"))}])

    assert run("0") == run("1") == run("12345")


def test_pddl_without_a_configured_strategy_gets_lazy_greedy_search(capsys):
    assert main(["solve", str(BLOCKS / "p4.pddl"), "--json"]) == 0
    payload = json.loads(capsys.readouterr().out)
    assert payload["config"]["strategy"] == "lazy-gbfs" and payload["config"]["heuristic"] == "ff"


def test_a_configured_world_model_strategy_runs_on_pddl(tmp_path, capsys):
    means_ends = config(tmp_path, '[strategy]\nname = "means-ends"\n')
    assert main(["solve", str(BLOCKS / "p4.pddl"), "--config", str(means_ends), "--json"]) == 0
    payload = json.loads(capsys.readouterr().out)
    assert payload["config"]["strategy"] == "means-ends" and payload["status"] == "solved"


def test_tree_on_forward_search_is_a_clear_warning_not_a_silent_no_op(tmp_path, capsys):
    tree = tmp_path / "tree.dot"
    with pytest.warns(UserWarning, match="--tree: the forward search keeps no tree to draw"):
        code = main(["solve", str(BLOCKS / "p4.pddl"), "--config", str(FAST),
                     "--tree", str(tree)])
    assert code == exit_codes.SOLVED and not tree.exists()
    assert "; status: solved" in capsys.readouterr().out
