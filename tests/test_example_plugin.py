"""The worked example for plugin authors (examples/plugins): installed as a third party's
distribution would be, it shows in 'strips plugins', is chosen from a TOML file, solves
and passes the conformance kit through the one-line classes in its own tests."""

import importlib.util
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "examples" / "plugins"
CLI = "import sys; from strips_framework.cli.main import main; sys.exit(main())"


@pytest.fixture(scope="module")
def environment(tmp_path_factory) -> dict[str, str]:
    """Install the example into a fresh target directory; the environment to run with it."""
    if importlib.util.find_spec("pip") is None:
        pytest.skip("pip is not available in this interpreter, so the example cannot be installed")
    if importlib.util.find_spec("hatchling") is None:
        pytest.skip("hatchling, the example's build backend, is not installed "
                    "(pip install -r requirements-dev.txt installs it)")
    target = tmp_path_factory.mktemp("site-packages")
    subprocess.run(
        [sys.executable, "-m", "pip", "install", "--quiet", "--no-deps", "--no-build-isolation",
         "--no-index", "--target", str(target), str(EXAMPLE)],
        check=True, capture_output=True, text=True,
    )
    env = {k: v for k, v in os.environ.items() if k != "STRIPS_DISABLE_PLUGIN_AUTOLOAD"}
    env["PYTHONPATH"] = os.pathsep.join([str(target), env.get("PYTHONPATH", "")]).rstrip(os.pathsep)
    return env


def strips(env: dict[str, str], *args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-c", CLI, *args], env=env, capture_output=True,
                          text=True, cwd=ROOT, check=False)


def test_strips_plugins_lists_it_with_its_distribution_and_capabilities(environment):
    out = strips(environment, "plugins").stdout
    assert "  facts                strips-example-plugins (example)" in out
    goals_left = out[out.index("  goals-left"):].splitlines()
    assert goals_left[0] == "  goals-left           strips-example-plugins (example)"
    assert "      capabilities: admissible" in goals_left
    assert "      tie_break = 0.01  # subtracted per goal, to prefer deeper nodes among equals" in goals_left


def test_chosen_from_a_toml_file_it_solves_and_the_plan_replays(environment, tmp_path):
    config = tmp_path / "strips.toml"
    config.write_text('prover = "facts"\n[evaluator]\nname = "goals-left"\ntie_break = 0.1\n')
    plan = tmp_path / "plan.txt"
    solved = strips(environment, "solve", "examples/three-boxes.strips", "--config", str(config),
                    "--plan-file", str(plan))
    assert solved.returncode == 0, solved.stderr
    assert "; plan length: 4" in solved.stdout
    checked = strips(environment, "validate", "examples/three-boxes.strips", str(plan))
    assert checked.stdout.strip() == "valid plan of 4 steps: the goal holds at the end"


def test_a_problem_it_cannot_handle_is_refused_before_the_search(environment, tmp_path):
    config = tmp_path / "strips.toml"
    config.write_text('prover = "facts"\n')
    refused = strips(environment, "solve", "examples/robot-world/light.strips", "--config", str(config))
    assert refused.returncode == 2
    assert "needs a prover with 'quantified-axioms' or 'definite-horn', but prover 'facts'" in refused.stderr


def test_its_own_tests_run_the_conformance_kit_and_pass(environment):
    run = subprocess.run(
        [sys.executable, "-m", "pytest", str(EXAMPLE / "tests"), "-q", "-p", "no:cacheprovider"],
        env=environment, capture_output=True, text=True, cwd=EXAMPLE, check=False,
    )
    assert run.returncode == 0, run.stdout[-3000:]
    summary = run.stdout.strip().splitlines()[-1]
    passed = int(summary.split(" passed")[0].split()[-1])
    assert passed >= 25, summary
