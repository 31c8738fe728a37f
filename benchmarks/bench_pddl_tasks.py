"""Time small IPC tasks (PDDL) under every registered strategy x state heuristic.

    .venv/bin/python -m pytest benchmarks/bench_pddl_tasks.py --benchmark-only

Each case runs ``strips solve PROBLEM --plan-file PLAN`` in-process (loading, grounding and
search: what a user waits for), then checks the plan with ``strips validate``. The
heuristics vary only for strategies that search ground tasks (the others do not use
one). A combination the planner refuses (exit code 2) is skipped with its message. Every
case skips without ``shared/bench/ipc`` beside the repository.
"""

import contextlib
import io

import pytest
import tomli_w
from shared_bench import shared_bench

from strips_framework.bench.problems import find_domain
from strips_framework.cli.main import main
from strips_framework.plugin.registry import Registry

TASKS = ["blocks/task01", "gripper/task01"]
REGISTRY = Registry.from_plugins()
#: A* with an inadmissible heuristic is a combination worth timing, not a mistake.
pytestmark = pytest.mark.filterwarnings(r"ignore:.*with 'admissible' \(its first plan")


COMBINATIONS = [
    *((s, None) for s in REGISTRY.names("strategy")),
    *((s, h) for s in REGISTRY.names("ground-strategy") for h in REGISTRY.names("heuristic")),
]


BENCH = shared_bench("ipc")


def _quiet(argv: list[str]) -> tuple[int, str]:
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main(argv)
    return code, err.getvalue().strip()


@pytest.mark.skipif(BENCH is None, reason="shared/bench/ipc not found")
@pytest.mark.parametrize("task", TASKS)
@pytest.mark.parametrize(("strategy", "heuristic"), COMBINATIONS)
def test_pddl_task(benchmark, tmp_path, task, strategy, heuristic):
    problem = BENCH / f"{task}.pddl"
    config, plan = tmp_path / "strips.toml", tmp_path / "plan.txt"
    data = {"strategy": strategy, "limits": {"time": 20, "nodes": 2000}}
    config.write_text(tomli_w.dumps(data | ({"heuristic": heuristic} if heuristic else {})))
    argv = ["solve", str(problem), "--config", str(config), "--plan-file", str(plan)]
    code, message = benchmark.pedantic(_quiet, args=(argv,), rounds=1, iterations=1)
    if code == 2:
        pytest.skip(f"{strategy}/{heuristic} refused: {message}")
    benchmark.extra_info.update(exit_code=code)
    if code == 0:
        assert _quiet(["validate", str(find_domain(problem)), str(problem), str(plan)])[0] == 0
