"""Where the shared benchmark sets are: ``shared/bench/<kind>`` in the first folder above
this one that has it (``../shared`` beside the repository, as CI lays it out). Benchmarks
import it as a plain module: pytest puts this folder on ``sys.path`` (``pythonpath`` in
pyproject.toml), and so does Python when one of them is run as a script."""

from __future__ import annotations

from pathlib import Path


def shared_bench(kind: str) -> Path | None:
    """The folder of the ``kind`` set (``ipc``, ``tptp``), or ``None`` when it is absent."""
    for parent in Path(__file__).resolve().parents:
        folder = parent / "shared" / "bench" / kind
        if folder.is_dir():
            return folder
    return None
