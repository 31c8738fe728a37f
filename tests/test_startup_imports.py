"""What ``strips solve`` imports on a PDDL task: the forward-search path only. Start-up
is most of the wall time on small tasks (``benchmarks/startup_vs_pyperplan.py``), and a
module imported by accident (the MACROP commands, the world-model layer, a prover) costs
milliseconds on every run; which modules get loaded is deterministic, so it is tested
here while the timing stays in the benchmark."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "pddl" / "blocksworld"

SCRIPT = """
import contextlib, io, sys
from strips_framework.cli.main import main
with contextlib.redirect_stdout(io.StringIO()):
    code = main(["solve", sys.argv[1], sys.argv[2]])
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


def test_a_pddl_solve_imports_only_the_forward_search_path(tmp_path):
    env = {**os.environ, "XDG_CACHE_HOME": str(tmp_path / "cache")}
    run = [sys.executable, "-c", SCRIPT, str(EXAMPLE / "domain.pddl"), str(EXAMPLE / "p4.pddl")]
    for _ in range(2):  # the first run builds the registry through pluggy (and caches it)
        done = subprocess.run(run, env=env, capture_output=True, text=True, check=True)
    code, modules = done.stdout.splitlines()
    assert code == "0"
    loaded = modules.split()
    assert "strips_framework.forward.lazy" in loaded  # the search did run
    unwanted = [m for m in loaded if any(m == n or m.startswith(n + ".") for n in NOT_NEEDED)]
    assert unwanted == []
