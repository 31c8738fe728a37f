"""The ``strips`` command when things go wrong: output paths checked before the search,
files written whole, Ctrl-C with the statistics so far, broken or failing plugins named,
malformed plans as bad input."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from strips_evaluators.goal_count import GoalCount
from strips_evaluators.heuristics.ff import FFEstimator
from strips_framework import exit_codes
from strips_framework.cli.main import main
from strips_framework.means_ends.evaluator import PaperEvaluator

ROOT = Path(__file__).resolve().parents[1]
THREE_BOXES = ROOT / "examples" / "three-boxes.strips"
BLOCKS = ROOT / "examples" / "pddl" / "blocksworld"
PDDL = [str(BLOCKS / "domain.pddl"), str(BLOCKS / "p4.pddl")]


def fail_after(calls: int, error: BaseException):
    """A replacement method that works ``calls`` times, then raises ``error``."""

    def method(self, *args, original, **kwargs):
        method.calls += 1
        if method.calls > calls:
            raise error
        return original(self, *args, **kwargs)

    method.calls = 0
    return method


def patch(monkeypatch, cls: type, name: str, calls: int, error: BaseException) -> None:
    original = getattr(cls, name)
    replacement = fail_after(calls, error)
    monkeypatch.setattr(cls, name, lambda self, *a, **k: replacement(self, *a, original=original, **k))


@pytest.mark.parametrize("option", ["--plan-file", "--tree"])
def test_output_into_a_missing_folder_fails_before_the_search(tmp_path, capsys, monkeypatch, option):
    patch(monkeypatch, PaperEvaluator, "evaluate", 0, AssertionError("the search ran"))
    target = tmp_path / "no" / "such" / "out.txt"
    assert main(["solve", str(THREE_BOXES), option, str(target)]) == exit_codes.INPUT_ERROR
    assert capsys.readouterr().err == (
        f"strips: error: {target}: cannot write "
        f"{'the plan' if option == '--plan-file' else 'the search tree'}: "
        f"cannot write into {target.parent}\n"
    )


def test_result_files_are_written_whole_through_a_rename(tmp_path, monkeypatch):
    plan = tmp_path / "plan.txt"
    plan.write_text("old plan\n")
    renamed: list[tuple[str, str]] = []
    real_replace = os.replace
    monkeypatch.setattr(os, "replace", lambda a, b: (renamed.append((a, b)), real_replace(a, b)))
    assert main(["solve", str(THREE_BOXES), "--plan-file", str(plan)]) == 0
    assert len(renamed) == 1 and renamed[0][1] == plan
    assert Path(renamed[0][0]).parent == tmp_path
    assert plan.read_text().endswith("; cost = 4 (unit cost)\n")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["plan.txt"]  # no temporary left


def test_ctrl_c_in_means_ends_prints_the_statistics_so_far(capsys, monkeypatch):
    patch(monkeypatch, PaperEvaluator, "evaluate", 3, KeyboardInterrupt())
    assert main(["solve", str(THREE_BOXES)]) == exit_codes.INTERRUPTED == 130
    out = capsys.readouterr().out
    assert "; status: interrupted" in out
    nodes = next(line for line in out.splitlines() if line.startswith("; nodes:"))
    assert int(nodes.split()[2]) >= 2  # nodes made before the fourth evaluation


def test_ctrl_c_in_forward_search_prints_the_statistics_so_far(capsys, monkeypatch):
    patch(monkeypatch, FFEstimator, "estimate_with_preferred", 5, KeyboardInterrupt())
    patch(monkeypatch, FFEstimator, "estimate", 5, KeyboardInterrupt())
    assert main(["solve", *PDDL, "--json"]) == 130
    payload = json.loads(capsys.readouterr().out)
    assert payload["status"] == "interrupted" and payload["exit_code"] == 130
    assert payload["statistics"]["evaluated"] >= 1


def test_an_exception_inside_a_plugin_names_the_plugin_with_its_own_exit_code(tmp_path, capsys, monkeypatch):
    patch(monkeypatch, GoalCount, "evaluate", 2, ZeroDivisionError("float division by zero"))
    config = tmp_path / "strips.toml"
    config.write_text('evaluator = "goal-count"\n')
    assert main(["solve", str(THREE_BOXES), "--config", str(config)]) == exit_codes.PLUGIN_ERROR == 32
    err = capsys.readouterr().err
    assert err.startswith(
        "strips: error: evaluator 'goal-count' (plugin strips-evaluators) raised "
        "ZeroDivisionError: float division by zero (at "
    )
    assert err.count("\n") == 1


def test_an_exception_in_the_core_is_not_blamed_on_a_plugin(monkeypatch):
    from strips_framework.means_ends.run import MeansEndsRun

    monkeypatch.setattr(MeansEndsRun, "search", lambda self: 1 / 0)
    with pytest.raises(ZeroDivisionError):
        main(["solve", str(THREE_BOXES)])


def test_an_exception_in_a_builtin_is_a_bug_in_the_core(monkeypatch):
    """The paper's evaluator is the core's: its failure is a traceback, not a plugin's."""
    patch(monkeypatch, PaperEvaluator, "evaluate", 2, ZeroDivisionError("float division by zero"))
    with pytest.raises(ZeroDivisionError):
        main(["solve", str(THREE_BOXES)])


@pytest.fixture
def broken_distribution(tmp_path, monkeypatch):
    """An installed distribution with two plugins: one that cannot be imported, one that
    implements a misspelled hook."""
    site = tmp_path / "site"
    info = site / "strips_broken-1.0.dist-info"
    info.mkdir(parents=True)
    (info / "METADATA").write_text("Metadata-Version: 2.1\nName: strips-broken\nVersion: 1.0\n")
    (info / "entry_points.txt").write_text(
        "[strips_framework]\nbroken = strips_broken_missing_module\nmisspelled = strips_misspelled\n"
    )
    (site / "strips_misspelled.py").write_text(textwrap.dedent("""
        from strips_framework.plugin.hookspecs import hookimpl

        @hookimpl
        def strips_register_provrs():
            return []
    """))
    monkeypatch.syspath_prepend(str(site))
    monkeypatch.delenv("STRIPS_DISABLE_PLUGIN_AUTOLOAD", raising=False)
    return site


def test_a_plugin_that_fails_to_load_is_named_and_left_out(broken_distribution):
    env = {**os.environ, "PYTHONPATH": str(broken_distribution)}
    env.pop("STRIPS_DISABLE_PLUGIN_AUTOLOAD", None)
    strips = Path(sys.executable).parent / "strips"
    run = subprocess.run([strips, "plugins"], capture_output=True, text=True, env=env, check=False)
    assert run.returncode == 0, run.stderr
    assert "strips-resolution-prover" in run.stdout  # the other plugins still load
    assert run.stderr.splitlines() == [
        "strips: warning: plugin 'broken' (from strips-broken) failed to load and is left out: "
        "ModuleNotFoundError: No module named 'strips_broken_missing_module'",
        "strips: warning: plugin 'misspelled' (from strips-broken) failed to load and is left "
        "out: PluginValidationError: unknown hook 'strips_register_provrs' in plugin "
        f"<module 'strips_misspelled' from '{broken_distribution / 'strips_misspelled.py'}'>",
    ]


def test_commands_that_need_no_broken_plugin_still_run(broken_distribution, capsys):
    with pytest.warns(UserWarning, match="plugin 'broken' .* failed to load"):
        assert main(["solve", str(THREE_BOXES)]) == 0
    assert "; status: solved" in capsys.readouterr().out


def test_a_malformed_plan_line_is_bad_input_at_its_line(tmp_path, capsys):
    plan = tmp_path / "plan.txt"
    plan.write_text("(goto a c)\n; a comment\n(push BOX2 c b\n")
    assert main(["validate", str(THREE_BOXES), str(plan)]) == exit_codes.INPUT_ERROR
    assert capsys.readouterr().err == (
        f"strips: error: {plan}:3:1: expected a plan step '(name arg ...)' or 'name(arg, ...)'\n"
    )


def test_a_pddl_plan_takes_ipc_steps_only(tmp_path, capsys):
    plan = tmp_path / "plan.txt"
    plan.write_text("(unstack b1 b2)\nput-down(b1)\n")
    assert main(["validate", *PDDL, str(plan)]) == exit_codes.INPUT_ERROR
    assert capsys.readouterr().err == f"strips: error: {plan}:2:1: expected a plan step '(name arg ...)'\n"


def test_a_plan_that_is_not_utf8_is_bad_input(tmp_path, capsys):
    plan = tmp_path / "plan.txt"
    plan.write_bytes(b"(goto a c)\n(push BOX2 \xff b)\n")
    assert main(["validate", str(THREE_BOXES), str(plan)]) == exit_codes.INPUT_ERROR
    assert f"{plan}:2:12: the plan is not UTF-8 text" in capsys.readouterr().err


def test_native_plan_names_are_case_sensitive(tmp_path, capsys):
    plan = tmp_path / "plan.txt"
    plan.write_text("(GOTO a c)\n")
    assert main(["validate", str(THREE_BOXES), str(plan)]) == exit_codes.INVALID_PLAN
    assert "no operator 'GOTO'" in capsys.readouterr().out


@pytest.mark.parametrize(
    ("table", "problem", "message"),
    [
        ('[heuristic]\nname = "fff"\n', [str(THREE_BOXES)], "2: 'heuristic.name': state heuristic 'fff' is not registered"),
        ("[heuristic]\nname = \"ff\"\ntypo = 1\n", [str(THREE_BOXES)], "3: unknown key 'heuristic.typo'"),
        ('[evaluator]\nname = "papr"\n', PDDL, "2: 'evaluator.name': evaluator 'papr' is not registered"),
        ('[prover]\nname = "resolution"\nnope = 1\n', PDDL, "3: unknown key 'prover.nope'"),
    ],
)
def test_the_config_is_checked_whole_not_only_the_parts_the_strategy_uses(tmp_path, capsys, table, problem, message):
    config = tmp_path / "strips.toml"
    config.write_text(table)
    assert main(["solve", *problem, "--config", str(config)]) == exit_codes.INPUT_ERROR
    err = capsys.readouterr().err
    assert err.startswith(f"strips: error: {config}:{message}")  # at the key's line


def test_an_unknown_strategy_names_the_config_and_key(tmp_path, capsys):
    config = tmp_path / "strips.toml"
    config.write_text('[strategy]\nname = "modl-astar"\n')
    assert main(["solve", str(THREE_BOXES), "--config", str(config)]) == exit_codes.INPUT_ERROR
    assert capsys.readouterr().err.startswith(
        f"strips: error: {config}:2: 'strategy.name': search strategy 'modl-astar' is not registered"
    )


def _unwritable(tmp_path: Path) -> Path:
    """A path in a folder that cannot be written: /proc for root (who may write anywhere
    else), a read-only folder otherwise."""
    if os.geteuid() == 0:
        return Path("/proc/strips-out")
    folder = tmp_path / "read-only"
    folder.mkdir()
    folder.chmod(0o555)
    return folder / "out"


@pytest.mark.parametrize("command", [
    ["solve", str(THREE_BOXES), "--plan-file", "{out}"],
    ["solve", str(THREE_BOXES), "--tree", "{out}"],
    ["learn", str(ROOT / "examples" / "robot-world" / "light.strips"), "-o", "{out}"],
    ["table", str(THREE_BOXES), "{plan}", "--svg", "{out}"],
    ["table", str(THREE_BOXES), "{plan}", "--html", "{out}"],
    ["bench", str(THREE_BOXES), "--no-progress", "-o", "{out}/results.jsonl"],
], ids=["plan-file", "tree", "learn", "svg", "html", "bench"])
def test_an_output_that_cannot_be_written_is_one_line_not_a_traceback(tmp_path, capsys, command):
    out = _unwritable(tmp_path)
    plan = tmp_path / "boxes.plan"
    assert main(["solve", str(THREE_BOXES), "--plan-file", str(plan)]) == 0
    capsys.readouterr()
    argv = [arg.format(out=out, plan=plan) for arg in command]
    assert main(argv) == exit_codes.INPUT_ERROR
    err = capsys.readouterr().err
    assert err.startswith(f"strips: error: {out}") and err.count("\n") == 1, err


@pytest.mark.parametrize("files", [["{dir}"], [str(ROOT / "examples/pddl/blocksworld/domain.pddl"), "{dir}"]])
def test_a_folder_given_as_the_problem_says_so(tmp_path, capsys, files):
    assert main(["solve", *(f.format(dir=tmp_path) for f in files)]) == exit_codes.INPUT_ERROR
    assert "is a folder, not" in capsys.readouterr().err


def test_bench_without_its_extra_says_how_to_get_it(monkeypatch, capsys):
    """rich and tomli-w are the bench extra's, not the core's dependencies."""
    import importlib.util

    real = importlib.util.find_spec
    monkeypatch.setattr(importlib.util, "find_spec", lambda name, *a: None if name == "rich" else real(name, *a))
    assert main(["bench", str(THREE_BOXES), "--no-progress"]) == exit_codes.INPUT_ERROR
    assert capsys.readouterr().err == (
        "strips: error: strips bench needs rich: pip install 'strips-framework[bench]'\n"
    )
