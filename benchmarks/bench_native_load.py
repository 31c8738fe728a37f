"""Loading large native worlds: robot worlds of 100 to 100,000 facts and axioms (see
``robot_worlds.py``), read by the ``.strips`` loader.

    .venv/bin/python -m pytest benchmarks/bench_native_load.py --benchmark-only \\
        --benchmark-columns=min,mean,rounds

Goal (issue 9): 100,000 formulas in 2 s or less. The normal test run loads each size once.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from robot_worlds import robot_world

from strips_framework.formats.native import NativeLoader

SIZES = (100, 1_000, 10_000, 100_000)


@pytest.mark.parametrize("formulas", SIZES)
def test_load_robot_world(benchmark, tmp_path: Path, formulas: int) -> None:
    path = tmp_path / f"world-{formulas}.strips"
    path.write_text(robot_world(formulas))
    problem = benchmark.pedantic(NativeLoader().load, args=(path,), rounds=3, iterations=1)
    loaded = len(problem.facts) + len(problem.axioms)
    benchmark.extra_info.update(formulas=loaded)
    assert abs(loaded - formulas) <= max(3, formulas // 100)
