"""The matrix file: what it expands to, and errors that name the file and key path."""

from __future__ import annotations

import re

import pytest

from strips_framework.bench.configs import AnchorConfig, CommandConfig, PlannerConfig
from strips_framework.bench.matrix import Matrix
from strips_framework.bench.problems import find_domain
from strips_framework.errors import ConfigError, InputError

from .conftest import PUSH_ONE_BOX, THREE_BOXES, fake

PROBLEMS = f'[problems]\npaper = ["{PUSH_ONE_BOX}", "{THREE_BOXES}"]\n'


def test_product_and_named_configs_expand_to_runs(write_matrix, tmp_path):
    base = tmp_path / "base.toml"
    base.write_text('[evaluator]\nname = "paper"\ngoal_weight = 2.0\n[limits]\nnodes = 500\n')
    matrix = Matrix.from_file(write_matrix(
        "repetitions = 2\nseed = 10\n" + PROBLEMS
        + '[product]\nbase = "base.toml"\nevaluator = ["paper", "goal-count"]\n'
        + 'strategy = ["means-ends"]\n'
        + '[configs.shallow]\nstrategy = {name = "means-ends", max_goals = 3}\n'
        + f"[configs.fake]\n{fake('solve')}\n"
    ))
    names = [config.name for config in matrix.configs]
    assert names == ["paper", "goal-count", "shallow", "fake"]
    paper, goal_count = matrix.configs[:2]
    assert isinstance(paper, PlannerConfig) and isinstance(matrix.configs[3], CommandConfig)
    # the base's options stay with the class they belong to; its limits stay everywhere
    assert paper.data["evaluator"] == {"name": "paper", "goal_weight": 2.0}
    assert goal_count.data["evaluator"] == {"name": "goal-count"}
    assert goal_count.data["limits"] == {"nodes": 500}
    runs = matrix.runs()
    assert len(runs) == 2 * 2 * 4
    assert len({run.key for run in runs}) == len(runs)
    assert {(run.repetition, run.seed) for run in runs} == {(0, 10), (1, 11)}
    assert matrix.limits.time == 60.0 and matrix.limits.memory == 2048


def test_product_names_say_what_varies(write_matrix):
    matrix = Matrix.from_file(write_matrix(
        PROBLEMS + '[product]\nprover = ["resolution"]\n'
        + 'evaluator = ["paper", {name = "paper", goal_weight = 2.0}]\n'
        + 'strategy = ["means-ends", {name = "means-ends", max_goals = 4}]\n'
    ))
    assert [config.name for config in matrix.configs] == [
        "paper+means-ends", "paper+means-ends(max_goals=4)",
        "paper(goal_weight=2.0)+means-ends", "paper(goal_weight=2.0)+means-ends(max_goals=4)",
    ]
    assert matrix.configs[3].data["strategy"] == {"name": "means-ends", "max_goals": 4}


@pytest.mark.parametrize(("body", "message"), [
    (PROBLEMS + "[configs.x]\nevaluator = 'paper'\n[limitz]\n",
     "'limitz': unknown key (expected one of: repetitions, seed, limits, problems, product, configs)"),
    ("[configs.x]\nevaluator = 'paper'\n", "'problems': missing (expected a table)"),
    (PROBLEMS, "'configs': no configuration"),
    ('[problems]\nx = ["nothing-*.strips"]\n[configs.a]\n',
     "'problems.x': the pattern 'nothing-*.strips' matches no problem file"),
    ('[problems]\nx = 3\n[configs.a]\n', "'problems.x': expected an array of glob patterns, got 3"),
    ("repetitions = 0\n" + PROBLEMS + "[configs.a]\n", "'repetitions': expected an integer from 1 to 10000, got 0"),
    (PROBLEMS + "[limits]\ntime = 'long'\n[configs.a]\n", "'limits.time': expected seconds > 0, got 'long'"),
    (PROBLEMS + "[limits]\nmemroy = 1\n[configs.a]\n", "'limits.memroy': unknown key"),
    (PROBLEMS + "[product]\nevaluator = ['paper', 'nope']\n",
     "'product (nope)': 'evaluator.name': evaluator 'nope' is not registered"),
    (PROBLEMS + "[product]\nevaluatr = ['paper']\n", "'product.evaluatr': unknown key"),
    (PROBLEMS + "[product]\nevaluator = [3]\n", "'product.evaluator[0]': expected a name or a table"),
    (PROBLEMS + "[configs.a]\nevaluator = {name = 'paper', weight = 1}\n",
     "'configs.a': unknown key 'evaluator.weight'"),
    (PROBLEMS + "[configs.a]\nfile = 'missing.toml'\n", "missing.toml: cannot read the config"),
    (PROBLEMS + "[configs.a]\ncommand = ['x', '{problme}']\n",
     "'configs.a.command': bad placeholder in '{problme}'"),
    (PROBLEMS + "[configs.a]\ncommand = 'x'\n", "'configs.a.command': expected an array of strings"),
    (PROBLEMS + "[configs.a]\nanchor = 'lama'\n",
     "'configs.a.anchor': expected one of pyperplan, fast-downward, got 'lama'"),
    (PROBLEMS + "[configs.a]\ncommand = ['x']\nanchor = 'pyperplan'\n",
     "'configs.a': give one of file, command, anchor, not command and anchor"),
    (PROBLEMS + "[product]\nevaluator = ['paper']\n[configs.paper]\n",
     "'configs': the configuration name 'paper' is used twice"),
])
def test_mistakes_name_the_file_and_key_path(write_matrix, body, message):
    path = write_matrix(body)
    with pytest.raises(ConfigError) as error:
        Matrix.from_file(path)
    assert re.match(rf"{re.escape(str(path))}(:\d+)?: ", str(error.value))
    assert message in str(error.value)


def test_mistakes_name_the_line_of_the_key(write_matrix):
    """tomllib keeps no positions: the matrix reader finds the key's line in the text."""
    path = write_matrix(
        PROBLEMS + "\n[configs.a]\nprover = 'resolution'\n"
        "evaluator = {name = 'paper', weight = 2}\n"
    )
    line = path.read_text().splitlines().index("evaluator = {name = 'paper', weight = 2}") + 1
    with pytest.raises(ConfigError) as error:
        Matrix.from_file(path)
    assert str(error.value).startswith(f"{path}:{line}: 'configs.a': ")
    assert "unknown key 'evaluator.weight'" in str(error.value)


def test_bad_toml_and_missing_file_are_reported(write_matrix, tmp_path):
    with pytest.raises(InputError, match=r"matrix.toml:1:10: not valid TOML: Expected ']'"):
        Matrix.from_file(write_matrix("[problems"))
    with pytest.raises(InputError, match="none.toml: cannot read the matrix"):
        Matrix.from_file(tmp_path / "none.toml")
    latin1 = tmp_path / "latin1.toml"
    latin1.write_bytes(b"seed =\xff")
    with pytest.raises(InputError, match=r"latin1.toml:1:7: the matrix is not UTF-8 text"):
        Matrix.from_file(latin1)


@pytest.mark.parametrize(("limits", "message"), [
    ("[limits]\nmemory = 18446744073709551616\n", r"'limits.memory': expected MiB > 0 and <= "),
    ("[limits]\ntime = 1e12\n", r"'limits.time': expected seconds > 0 and <= 1000000000"),
    ("repetitions = 100000\n", r"'repetitions': expected an integer from 1 to 10000"),
    ("seed = 4294967295\nrepetitions = 2\n", r"'seed': expected an integer from 0 to 4294967294"),
])
def test_limits_the_system_cannot_apply_are_refused_when_read(write_matrix, limits, message):
    body = limits + "[problems]\nall = []\n[configs.a]\n"
    with pytest.raises(ConfigError, match=message):
        Matrix.from_file(write_matrix(body))


def test_pddl_sets_skip_domain_files_and_find_each_problems_domain(write_matrix, tmp_path):
    for name in ("blocks/domain.pddl", "blocks/task01.pddl", "blocks/task02.pddl",
                 "stacks/domain01.pddl", "stacks/task01.pddl", "stacks/domain02.pddl",
                 "stacks/task02.pddl", "lonely/task01.pddl"):
        (tmp_path / name).parent.mkdir(exist_ok=True)
        (tmp_path / name).write_text("(define)")
    matrix = Matrix.from_file(write_matrix(
        '[problems]\nipc = ["blocks/*.pddl", "stacks/*.pddl"]\n[configs.ours]\n'
    ))
    found = {p.name: p.domain.name for p in matrix.problems}
    assert found == {
        "blocks/task01.pddl": "domain.pddl", "blocks/task02.pddl": "domain.pddl",
        "stacks/task01.pddl": "domain01.pddl", "stacks/task02.pddl": "domain02.pddl",
    }
    assert find_domain(tmp_path / "lonely" / "task01.pddl") is None
    with pytest.raises(ConfigError, match="'problems.x': no domain file for .*task01.pddl"):
        Matrix.from_file(write_matrix('[problems]\nx = ["lonely/*.pddl"]\n[configs.a]\n'))


def test_anchors_not_installed_or_on_native_problems_are_skipped_with_a_note(
    write_matrix, tmp_path, monkeypatch
):
    monkeypatch.setenv("STRIPS_ANCHORS", str(tmp_path / "no-anchors"))
    matrix = Matrix.from_file(write_matrix(
        PROBLEMS + "[configs.ours]\n[configs.pp]\nanchor = 'pyperplan'\nargs = ['-s', 'gbf']\n"
    ))
    assert isinstance(matrix.configs[1], AnchorConfig)
    assert [run.config.name for run in matrix.runs()] == ["ours", "ours"]
    home = tmp_path / "no-anchors"
    assert matrix.notes() == [(
        f"configuration 'pp' skipped: pyperplan is not installed under {home} "
        "(set STRIPS_ANCHORS to its virtual environment)"
    )]
    fake_home = tmp_path / "anchors"
    (fake_home / "bin").mkdir(parents=True)
    (fake_home / "bin" / "pyperplan").write_text("")
    monkeypatch.setenv("STRIPS_ANCHORS", str(fake_home))
    assert matrix.notes() == [
        "configuration 'pp' runs PDDL problems only (a ground-task strategy, or an anchor "
        "planner): 2 problem(s) skipped"
    ]



def test_a_problem_pattern_that_is_not_a_string_is_an_error(write_matrix):
    with pytest.raises(ConfigError, match=r"'problems.a\[1\]': expected a glob pattern \(a string\), got \['x'\]"):
        Matrix.from_file(write_matrix("[problems]\na = ['*.strips', ['x']]\n[configs.c]\n"))


def test_a_product_table_without_a_name_is_an_error(write_matrix):
    with pytest.raises(ConfigError, match=r"'product.evaluator\[0\]': a table needs a 'name'"):
        Matrix.from_file(write_matrix(PROBLEMS + "[product]\nevaluator = [{weight = 2}]\n"))
