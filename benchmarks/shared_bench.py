"""Where the shared benchmark sets are: ``shared/bench/<kind>`` in the first folder above
this one that has it (``../shared`` beside the repository, as CI lays it out), else the
repository's copy in ``tests/data/bench/<kind>``.

The repository copies the TPTP development set whole (300 KB), and of the IPC set (3.6 MB)
only what the tests name: every domain's first two tasks and depot's fifth (80 KB,
``tests/data/bench/ipc/README.md``), so the tests that ground, search and compare
heuristics on IPC tasks run alike with and without ``../shared``. The benchmarks name
tasks up to 30 of a domain, so they ask :func:`shared_bench`, which gives a partial copy to
no one; the tests ask :func:`small_bench`. Benchmarks import this as a plain module: pytest
puts this folder on ``sys.path`` (``pythonpath`` in pyproject.toml), and so does Python
when one of them is run as a script."""

from __future__ import annotations

from pathlib import Path

#: The repository's copies of shared sets.
BUNDLED = Path(__file__).resolve().parents[1] / "tests" / "data" / "bench"
#: The sets the repository copies whole; of the others it holds a subset.
WHOLE = ("tptp",)


def shared_bench(kind: str) -> Path | None:
    """The folder of the whole ``kind`` set (``ipc``, ``tptp``), or ``None`` when it is
    absent."""
    folder = _beside(kind)
    if folder is not None:
        return folder
    return BUNDLED / kind if kind in WHOLE else None


def small_bench(kind: str) -> Path:
    """The folder of the ``kind`` set, or else of the repository's copy, whole or a
    subset (for tests, which name only the tasks copied, so one missing is a failure,
    not a skip)."""
    return _beside(kind) or BUNDLED / kind


def _beside(kind: str) -> Path | None:
    for parent in Path(__file__).resolve().parents:
        folder = parent / "shared" / "bench" / kind
        if folder.is_dir():
            return folder
    return None
