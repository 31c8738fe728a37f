"""How long the explorer page of a 10,000-node search takes to open in Chromium, and
its size (the issue's targets: under 2 s, under 10 MB).

    .venv/bin/python -m pytest benchmarks/bench_explorer.py --benchmark-only
    .venv/bin/python benchmarks/bench_explorer.py        # the same, printed

The search is means-ends on the five-part goal with the blind ``breadth-first``
evaluator, stopped by ``[limits] nodes = 10000``. "Open" is from ``page.goto`` of the
file:// URL until the page's script has parsed the data, laid out and drawn the tree
and filled the side panel (``window.explorer.ready``). Debian's chromium, headless, via
Playwright; skipped where either is missing.
"""

from __future__ import annotations

import statistics
import sys
import tempfile
import time
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests" / "explore"))

import figures  # noqa: E402

CONFIG = '[evaluator]\nname = "breadth-first"\n[limits]\nnodes = 10000\ntime = 600\n'


def make_page(folder: Path) -> Path:
    from strips_framework.cli.main import main

    config = folder / "big.toml"
    config.write_text(CONFIG)
    page = folder / "explorer-10000.html"
    main(["solve", str(ROOT / "examples/robot-world/five-goals.strips"), "--config", str(config),
          "--explore", str(page)])
    return page


def open_seconds(launched: object, page_file: Path, in_page: list[float] | None = None) -> float:
    """Seconds from ``goto`` to the page ready; ``in_page`` gets the page's own count
    (from the navigation's start, by ``performance.now()``)."""
    page = launched.new_page(viewport={"width": 1300, "height": 800})
    try:
        started = time.perf_counter()
        page.goto(page_file.resolve().as_uri())
        page.wait_for_function("window.explorer && window.explorer.ready", timeout=60_000)
        seconds = time.perf_counter() - started
        if in_page is not None:
            in_page.append(page.evaluate("window.explorer.openedMs") / 1000)
        return seconds
    finally:
        page.close()


def test_explorer_of_ten_thousand_nodes_opens(benchmark, tmp_path):
    reason = figures.unavailable()
    if reason is not None:
        pytest.skip(reason)
    page_file = make_page(tmp_path)
    size = page_file.stat().st_size
    launched = figures.shared_browser()
    seconds = benchmark.pedantic(open_seconds, args=(launched, page_file), rounds=5)
    benchmark.extra_info["bytes"] = size
    assert size < 10 * 2**20
    assert seconds is None or seconds > 0


if __name__ == "__main__":
    with tempfile.TemporaryDirectory() as scratch, figures.browser() as launched:
        page_file = make_page(Path(scratch))
        in_page: list[float] = []
        times = [open_seconds(launched, page_file, in_page) for _ in range(7)]
        print(f"{page_file.name}: {page_file.stat().st_size / 2**20:.2f} MiB; open "
              f"median {statistics.median(times):.3f} s, min {min(times):.3f} s, "
              f"max {max(times):.3f} s over {len(times)} openings (the page's own count: "
              f"median {statistics.median(in_page):.3f} s)")
