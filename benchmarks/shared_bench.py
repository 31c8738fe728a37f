"""Where the shared benchmark sets are: ``shared/bench/<kind>`` in the first folder above
this one that has it (``../shared`` beside the repository, as CI lays it out), else the
repository's copy in ``tests/data/bench/<kind>`` where there is one: the whole TPTP
development set (300 KB), so that the prover tests that use it mean something on a
machine without ``../shared``. The IPC set (3.6 MB, and tests that name tasks up to 30
of a domain) is not copied: those tests skip without it. Benchmarks import it as a plain
module: pytest puts this folder on ``sys.path`` (``pythonpath`` in pyproject.toml), and
so does Python when one of them is run as a script."""

from __future__ import annotations

from pathlib import Path

#: The repository's copies of shared sets.
BUNDLED = Path(__file__).resolve().parents[1] / "tests" / "data" / "bench"


def shared_bench(kind: str) -> Path | None:
    """The folder of the ``kind`` set (``ipc``, ``tptp``), or ``None`` when it is absent."""
    for parent in Path(__file__).resolve().parents:
        folder = parent / "shared" / "bench" / kind
        if folder.is_dir():
            return folder
    bundled = BUNDLED / kind
    return bundled if bundled.is_dir() else None
