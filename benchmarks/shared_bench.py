"""Where the shared benchmark sets are: ``shared/bench/<kind>`` in the first folder above
this one that has it (``../shared`` beside the repository, as CI lays it out), else the
repository's small copy in ``tests/data/bench/<kind>`` (the whole TPTP development set;
the first task of eight IPC domains and depot's fifth), so that the tests that use a set
mean something on a machine without ``../shared``. Benchmarks import it as a plain
module: pytest puts this folder on ``sys.path`` (``pythonpath`` in pyproject.toml), and
so does Python when one of them is run as a script."""

from __future__ import annotations

from pathlib import Path

#: The repository's copy of part of the shared sets.
BUNDLED = Path(__file__).resolve().parents[1] / "tests" / "data" / "bench"


def shared_bench(kind: str) -> Path | None:
    """The folder of the ``kind`` set (``ipc``, ``tptp``), or ``None`` when it is absent."""
    for parent in Path(__file__).resolve().parents:
        folder = parent / "shared" / "bench" / kind
        if folder.is_dir():
            return folder
    bundled = BUNDLED / kind
    return bundled if bundled.is_dir() else None
