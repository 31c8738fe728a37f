"""The core with no plugin distribution loaded (``STRIPS_DISABLE_PLUGIN_AUTOLOAD``): its
builtins, the paper's evaluator (``paper``) and the join engine as prover (``joins``),
solve the paper's tasks by means-ends analysis as the resolution prover does, node for
node, and ``strips plugins`` lists them."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from strips_framework.planner import Planner
from strips_framework.plugin.config import Config
from strips_framework.plugin.manager import get_plugin_manager
from strips_framework.plugin.registry import Registry
from strips_framework.worldmodel.simulate import replay

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"
STRIPS = Path(sys.executable).parent / "strips"

#: (task, nodes in the tree): the resolution prover's counts (tests/test_paper_tasks.py
#: bounds them by the paper's Table 2), which the core alone reaches exactly.
PAPER_TASKS = [
    ("three-boxes.strips", 9),
    ("robot-world/light.strips", 13),
    ("robot-world/boxes.strips", 9),
    ("robot-world/other-room.strips", 12),
]


def _core_alone(command: list[str]) -> subprocess.CompletedProcess[str]:
    """``strips COMMAND`` in a fresh process with plugin autoload off."""
    env = {**os.environ, "STRIPS_DISABLE_PLUGIN_AUTOLOAD": "1"}
    return subprocess.run(
        [str(STRIPS), *command], capture_output=True, text=True, env=env, check=False, timeout=120
    )


@pytest.fixture(scope="module")
def core_planner() -> Planner:
    """The defaults over the builtins alone."""
    return Planner(Registry(get_plugin_manager(load_entrypoints=False)), Config.default()).checked()


def test_the_defaults_are_the_builtins(core_planner):
    assert core_planner.config.choices["prover"].name == "joins"
    assert core_planner.config.choices["evaluator"].name == "paper"
    assert core_planner.config.choices["strategy"].name == "means-ends"


@pytest.mark.parametrize(("name", "nodes"), PAPER_TASKS, ids=[n for n, _ in PAPER_TASKS])
def test_the_core_alone_solves_the_papers_tasks_with_its_node_counts(core_planner, name, nodes):
    problem = core_planner.load(EXAMPLES / name)
    result = core_planner.solve(problem)
    assert result.solved, result.status
    assert replay(problem, [str(step) for step in result.plan]).valid
    assert result.statistics.nodes == nodes


def test_strips_solve_light_in_a_fresh_process_without_plugins():
    run = _core_alone(["solve", str(EXAMPLES / "robot-world" / "light.strips"), "--json"])
    assert run.returncode == 0, run.stderr
    payload = json.loads(run.stdout)
    assert payload["status"] == "solved"
    assert payload["plan"] == [
        "(goto2 BOX1)", "(climbonbox BOX1)", "(climboffbox BOX1)",
        "(pushto BOX1 LIGHTSWITCH1)", "(climbonbox BOX1)", "(turnonlight LIGHTSWITCH1)",
    ]
    assert payload["statistics"]["nodes"] == 13


def test_strips_plugins_in_a_fresh_process_lists_the_builtins_only():
    run = _core_alone(["plugins"])
    assert run.returncode == 0, run.stderr
    lines = run.stdout.splitlines()
    assert any(line.startswith("  paper ") and line.endswith("builtin (strips_framework.plugin.builtins)") for line in lines)
    assert any(line.startswith("  joins ") and "builtin" in line for line in lines)
    assert "strips-evaluators" not in run.stdout and "strips-resolution-prover" not in run.stdout


def test_a_pddl_task_with_the_core_alone_is_searched_lifted_and_says_why():
    """The core has lifted goal count but no informed state heuristic: the default PDDL
    run searches without grounding instead of stopping at the missing 'ff'."""
    domain = EXAMPLES / "pddl" / "blocksworld" / "domain.pddl"
    run = _core_alone(["solve", str(domain), str(domain.parent / "p4.pddl"), "--json"])
    assert run.returncode == 0, run.stderr
    assert "strategy lifted-alt-bfws: the ground search's default heuristic (ff) is not registered" in run.stderr
    payload = json.loads(run.stdout)
    assert payload["status"] == "solved"
    assert payload["family"] == "lifted"


def test_the_ground_strategies_run_with_the_core_alone_on_its_blind_heuristic(tmp_path):
    """breadth-first ignores its heuristic and A* takes blind as uniform-cost search: both
    shortest plans, without strips-evaluators."""
    domain = EXAMPLES / "pddl" / "blocksworld" / "domain.pddl"
    for strategy in ("breadth-first", "astar"):
        config = tmp_path / f"{strategy}.toml"
        config.write_text(f'[strategy]\nname = "{strategy}"\n')
        run = _core_alone(["solve", str(domain), str(domain.parent / "p4.pddl"), "--config", str(config), "--json"])
        assert run.returncode == 0, run.stderr
        payload = json.loads(run.stdout)
        assert payload["status"] == "solved" and len(payload["plan"]) == 8, payload
