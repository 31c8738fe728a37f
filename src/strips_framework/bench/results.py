"""The results file: JSON lines, one run a line, appended and flushed as runs finish.

A line is written whole and flushed to disk before the next run is counted, so an
interrupted or crashed runner loses nothing that finished. A torn last line (the runner
killed mid-write) is cut off when the file is opened again with ``--resume``.
"""

from __future__ import annotations

import json
import os
from collections.abc import Iterable, Iterator
from pathlib import Path
from typing import TYPE_CHECKING, Any

from strips_framework.errors import InputError
from strips_framework.user_files import read_text

if TYPE_CHECKING:
    from strips_framework.bench.matrix import RunSpec


def read_rows(path: Path) -> list[dict[str, Any]]:
    """Every complete row of a results file."""
    lines = read_text(path, "the results").splitlines(keepends=True)
    return [row for _, row in _complete_rows(lines, str(path))]


def _complete_rows(lines: list[str], where: str) -> Iterator[tuple[int, dict[str, Any]]]:
    """``(end offset, row)`` for each complete line; a torn final line is skipped."""
    offset = 0
    for number, line in enumerate(lines, start=1):
        offset += len(line.encode("utf-8"))
        if not line.endswith("\n") and number == len(lines):
            return
        try:
            row = json.loads(line)
        except ValueError:
            raise InputError(where, number, None, "not a JSON object (a results row)") from None
        if not isinstance(row, dict) or "key" not in row:
            raise InputError(where, number, None, "expected a results row with a 'key'")
        yield offset, row


class ResultsFile:
    """Appends rows; knows the keys already present so that a run is never written twice."""

    def __init__(self, path: Path, resume: bool) -> None:
        self.path = path
        self.done: set[str] = set()
        #: Per configuration name, what the file's rows say it was: its spec and limits.
        self.recorded: dict[str, tuple[Any, Any]] = {}
        if path.exists() and path.stat().st_size and not resume:
            raise InputError(
                str(path), None, None,
                "results file exists: pass --resume to continue it, or choose another --output",
            )
        if path.exists() and resume:
            lines = read_text(path, "the results").splitlines(keepends=True)
            end = 0
            for end, row in _complete_rows(lines, str(path)):
                self.done.add(row["key"])
                self.recorded.setdefault(
                    row.get("config"), (row.get("config_spec"), row.get("limits"))
                )
            with path.open("r+b") as file:
                file.truncate(end)  # drop a torn last line
        path.parent.mkdir(parents=True, exist_ok=True)
        self._file = path.open("a", encoding="utf-8")

    def check_unchanged(self, specs: Iterable[RunSpec]) -> None:
        """Refuse to resume when a configuration of the matrix ran under another spec or
        other limits than the file's rows record: the rows would not be comparable."""
        for spec in specs:
            recorded = self.recorded.get(spec.config.name)
            if recorded is None:
                continue
            limits = {"time": spec.limits.time, "memory_mib": spec.limits.memory}
            for what, was, now in (
                ("configuration", recorded[0], spec.config.describe()),
                ("limits", recorded[1], limits),
            ):
                if was != json.loads(json.dumps(now)):  # as a row holds it
                    raise InputError(
                        str(self.path), None, None,
                        f"cannot resume: the {what} of {spec.config.name!r} changed since "
                        f"these rows were written (then {json.dumps(was, sort_keys=True)}, "
                        f"now {json.dumps(now, sort_keys=True)}); write to another --output",
                    )

    def write(self, row: dict[str, Any]) -> bool:
        """Append ``row`` unless its run is already in the file; ``False`` if it was."""
        if row["key"] in self.done:
            return False
        self._file.write(json.dumps(row, sort_keys=True) + "\n")
        self._file.flush()
        os.fsync(self._file.fileno())
        self.done.add(row["key"])
        return True

    def close(self) -> None:
        self._file.close()


class RowList:
    """Rows kept in memory, for a quick run that writes no file."""

    def __init__(self) -> None:
        self.rows: list[dict[str, Any]] = []
        self.done: set[str] = set()

    def write(self, row: dict[str, Any]) -> bool:
        if row["key"] in self.done:
            return False
        self.rows.append(row)
        self.done.add(row["key"])
        return True

    def close(self) -> None:
        """Nothing to release."""
