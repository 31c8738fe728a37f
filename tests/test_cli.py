"""The ``strips`` command line: plans, statistics, JSON, DOT trees, and clear errors."""

import json
import subprocess
import sys
from pathlib import Path

import pytest

from strips_framework import exit_codes
from strips_framework.cli.main import main

ROOT = Path(__file__).resolve().parents[1]
THREE_BOXES = ROOT / "examples" / "three-boxes.strips"


def test_solve_prints_the_plan_ipc_style_and_table_2_figures(capsys):
    assert main(["solve", str(THREE_BOXES)]) == 0
    lines = capsys.readouterr().out.splitlines()
    plan = [line for line in lines if not line.startswith(";")]
    assert len(plan) == 4
    assert all(line.startswith("(") and line.endswith(")") for line in plan)
    assert "; nodes: 9 in the tree, 9 on the solution path" in lines
    assert "; operator applications: 4 in the tree, 4 on the solution path" in lines


def test_solve_json_plan_file_and_tree(tmp_path, capsys):
    plan_file, tree = tmp_path / "plan.txt", tmp_path / "tree.dot"
    args = ["solve", str(THREE_BOXES), "--json", "--plan-file", str(plan_file), "--tree", str(tree)]
    assert main(args) == 0
    payload = json.loads(capsys.readouterr().out)
    assert payload["status"] == "solved"
    assert payload["statistics"]["nodes"] == 9
    assert len(payload["plan"]) == 4
    written = [l for l in plan_file.read_text().splitlines() if not l.startswith(";")]
    assert written == payload["plan"] and payload["family"] == "world-model"
    dot = tree.read_text()
    assert dot.startswith("digraph search_tree {")
    assert dot.count("->") == 8  # 9 nodes in a tree
    assert dot.count("color=red") >= 9  # the solution path is highlighted


def test_tree_goals_wrap_whole(tmp_path):
    """A long precondition is wrapped onto more lines of the node's label, never cut."""
    tree = tmp_path / "tree.dot"
    assert main(["solve", str(ROOT / "examples/robot-world/light.strips"), "--tree", str(tree)]) == 0
    label = next(line for line in tree.read_text().splitlines() if line.startswith("  n1 ["))
    lines = label.split('label="', 1)[1].split('"', 1)[0].split("\\l")
    assert all(len(line) <= 60 for line in lines) and "..." not in label
    joined = " ".join(line.strip() for line in lines)
    assert ("pre turnonlight(LIGHTSWITCH1): (exists n: TYPE(n, BOX) & ON(ROBOT, n) & "
            "NEXTTO(n, LIGHTSWITCH1)) & TYPE(LIGHTSWITCH1, LIGHTSWITCH)") in joined


def test_malformed_problem_is_reported_with_file_and_line(tmp_path, capsys):
    bad = tmp_path / "bad.strips"
    bad.write_text("problem bad\nconstants a\nfacts\n  ATR(a\ngoal ATR(a)\n")
    assert main(["solve", str(bad)]) == 2
    err = capsys.readouterr().err
    assert err.startswith(f"strips: error: {bad}:4:")
    assert "Traceback" not in err


def test_missing_problem_file(tmp_path, capsys):
    assert main(["solve", str(tmp_path / "nope.strips")]) == 2
    assert "no such problem file" in capsys.readouterr().err


def test_unknown_plugin_name_in_config(tmp_path, capsys, monkeypatch):
    monkeypatch.setenv("STRIPS_DISABLE_PLUGIN_AUTOLOAD", "1")  # as if z3 were not installed
    config = tmp_path / "strips.toml"
    config.write_text('[prover]\nname = "z3"\n')
    assert main(["solve", str(THREE_BOXES), "--config", str(config)]) == 2
    err = capsys.readouterr().err
    assert "prover 'z3' is not registered (available: joins); plugin autoload is off" in err


def test_plugins_lists_implementations_with_distributions_and_options(capsys):
    assert main(["plugins"]) == 0
    out = capsys.readouterr().out
    assert "strips-resolution-prover" in out and "strips-evaluators" in out
    assert "means-ends" in out and "max_goals = 8  # the longest goal list" in out


def test_installed_command_reports_errors_without_a_traceback(tmp_path):
    bad = tmp_path / "bad.strips"
    bad.write_text("problem bad\ngoal FOO(\n")
    run = subprocess.run(
        [Path(sys.executable).parent / "strips", "solve", str(bad)],
        capture_output=True, text=True, check=False,
    )
    assert run.returncode == 2
    assert "Traceback" not in run.stderr
    assert f"{bad}:2:" in run.stderr


@pytest.mark.parametrize("status", ["Unsatisfiable"])
def test_prove_reports_an_szs_status(tmp_path, capsys, status):
    problem = tmp_path / "tiny.p"
    problem.write_text("cnf(a, axiom, p(a)).\ncnf(b, negated_conjecture, ~p(X)).\n")
    assert main(["prove", str(problem)]) == 0
    assert f"SZS status {status}" in capsys.readouterr().out


def test_prove_reports_a_theorem_whose_only_answer_is_disjunctive(tmp_path, capsys):
    problem = tmp_path / "either.p"
    problem.write_text("cnf(a, axiom, p(a) | p(b)).\nfof(q, question, ? [X] : p(X)).\n")
    assert main(["prove", str(problem)]) == 0
    assert capsys.readouterr().out == (
        "% SZS status Theorem for either\n% SZS answers Tuple [([a]|[b])|_] for either\n"
    )


@pytest.mark.parametrize("prover", ["resolution", "z3"])
def test_prove_with_a_prover_named_on_the_command_line(tmp_path, capsys, prover):
    # Satisfiable, which only a prover that reasons (not one that gives up) reports.
    problem = tmp_path / "tiny.p"
    problem.write_text("cnf(a, axiom, p(a)).\ncnf(b, negated_conjecture, ~p(b)).\n")
    assert main(["prove", str(problem), "--prover", prover]) == 1  # as E: saturated
    assert "SZS status Satisfiable" in capsys.readouterr().out
    assert main(["prove", str(problem), "--prover", "no-such"]) == 2
    assert "prover 'no-such' is not registered" in capsys.readouterr().err


def test_validate_replays_a_plan_file_in_the_simulator(tmp_path, capsys):
    plan = tmp_path / "plan.txt"
    assert main(["solve", str(THREE_BOXES), "--plan-file", str(plan)]) == 0
    capsys.readouterr()
    assert main(["validate", str(THREE_BOXES), str(plan)]) == 0
    assert capsys.readouterr().out.startswith("valid plan of 4 steps")
    plan.write_text("(goto a c)\n(push BOX2 c b)\n")
    assert main(["validate", str(THREE_BOXES), str(plan)]) == 1
    assert "the goal fails in the final state" in capsys.readouterr().out


def test_prove_names_a_missing_file(tmp_path, capsys):
    assert main(["prove", str(tmp_path / "none.p")]) == 2
    err = capsys.readouterr().err
    assert err == f"strips: error: {tmp_path / 'none.p'}: cannot read the file: No such file or directory\n"


def test_a_time_limit_during_a_world_model_search_reports_its_statistics(tmp_path, capsys):
    """The process alarm and the search's own check are one limit: a time limit that runs
    out during the search ends it with the statistics so far, not 'before the search'."""
    config = tmp_path / "strips.toml"
    config.write_text('[evaluator]\nname = "breadth-first"\n[limits]\ntime = 0.5\n')
    problem = ROOT / "examples" / "robot-world" / "five-goals.strips"
    code = main(["solve", str(problem), "--config", str(config), "--json"])
    payload = json.loads(capsys.readouterr().out)
    assert code == exit_codes.OUT_OF_TIME == payload["exit_code"]
    assert payload["status"] == "time-limit" and payload["limit"] == "time"
    assert payload["family"] == "world-model" and payload["statistics"]["nodes"] > 0
    assert 0.5 <= payload["seconds"] < 5


def test_version(capsys):
    from strips_framework import __version__

    with pytest.raises(SystemExit) as done:
        main(["--version"])
    assert done.value.code == 0 and capsys.readouterr().out == f"strips {__version__}\n"


def test_every_status_has_an_exit_code():
    from strips_framework.result import Status

    assert set(exit_codes.BY_STATUS) == set(Status)


def test_plugins_lists_the_core_alone(capsys, monkeypatch):
    monkeypatch.setenv("STRIPS_DISABLE_PLUGIN_AUTOLOAD", "1")
    assert main(["plugins"]) == 0
    out = capsys.readouterr().out
    assert "means-ends           builtin" in out and "strips-evaluators" not in out
