"""What ``strips solve`` imports on a PDDL task: the forward-search path only; and on a
native STRIPS task: the means-ends path, without attrs either. Start-up
is most of the wall time on small tasks (``benchmarks/startup_vs_pyperplan.py``), and a
module imported by accident (the MACROP commands, the world-model layer, a prover) costs
milliseconds on every run; which modules get loaded is deterministic, so it is tested
here while the timing stays in the benchmark."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
EXAMPLE = EXAMPLES / "pddl" / "blocksworld"

SCRIPT = """
import contextlib, io, sys
from strips_framework.cli.main import main
with contextlib.redirect_stdout(io.StringIO()):
    code = main(["solve", *sys.argv[1:]])
print(code)
print(" ".join(sorted(sys.modules)))
"""

#: Packages and modules a PDDL solve with the default (lazy greedy + hFF) config needs
#: none of.
NOT_NEEDED = (
    "strips_framework.macrops",
    "strips_framework.worldmodel",
    "strips_framework.logic",
    "strips_framework.means_ends.run",
    "strips_framework.means_ends.goal_prover",
    "strips_framework.formats.native",
    "strips_framework.bench.runner",
    "strips_resolution_prover.prover",
    "strips_z3_prover.prover",
    "importlib.metadata",
    "tempfile",
    "json",
    # attrs: importing it (inspect, ast, dis) and building its classes cost more than a
    # small task's whole solve; the PDDL path declares options with
    # strips_framework.options and its records as strips_framework.records classes.
    "attr",
    "attrs",
    # The registry comes from its cache (plugin/registry_cache.py) on the second run:
    # neither pluggy (which imports inspect) nor any plugin module, nor any class but
    # the strategy's and the heuristic's.
    "pluggy",
    "inspect",
    "strips_framework.plugin.manager",
    "strips_framework.plugin.builtins",
    "strips_framework.means_ends",
    "strips_framework.forward.eager",
    "strips_evaluators.plugin",
    "strips_evaluators.heuristics.lmcut",
)


def _loaded(tmp_path: Path, *problem: Path) -> list[str]:
    """The modules loaded by a second ``strips solve`` of ``problem`` (the first run builds
    the registry through pluggy and caches it), which must solve it."""
    env = {**os.environ, "XDG_CACHE_HOME": str(tmp_path / "cache")}
    run = [sys.executable, "-c", SCRIPT, *map(str, problem)]
    for _ in range(2):
        done = subprocess.run(run, env=env, capture_output=True, text=True, check=True)
    code, modules = done.stdout.splitlines()
    assert code == "0"
    return modules.split()


def _among(loaded: list[str], names: tuple[str, ...]) -> list[str]:
    return [m for m in loaded if any(m == n or m.startswith(n + ".") for n in names)]


def test_a_pddl_solve_imports_only_the_forward_search_path(tmp_path):
    loaded = _loaded(tmp_path, EXAMPLE / "domain.pddl", EXAMPLE / "p4.pddl")
    assert "strips_framework.forward.lazy" in loaded  # the search did run
    assert _among(loaded, NOT_NEEDED) == []


def test_a_native_solve_declares_its_values_without_attrs(tmp_path):
    """The means-ends path (world model, clauses, the resolution prover) declares its
    values as records too: nothing on it imports attrs (which pulls inspect, ast and dis)
    or dataclasses."""
    loaded = _loaded(tmp_path, EXAMPLES / "robot-world" / "light.strips")
    assert "strips_framework.means_ends.run" in loaded  # the means-ends search did run
    assert _among(loaded, ("attr", "attrs", "dataclasses")) == []
