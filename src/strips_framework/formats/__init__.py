"""Problem loaders: files in, :class:`~strips_framework.worldmodel.problem.Problem` out."""

from __future__ import annotations

from pathlib import Path
from typing import ClassVar, Protocol

from strips_framework.worldmodel.problem import Problem


class ProblemLoader(Protocol):
    """Reads problem files whose names end with one of ``suffixes``."""

    name: ClassVar[str]
    suffixes: ClassVar[tuple[str, ...]]

    def load(self, path: Path) -> Problem:
        """Read ``path``; raise :class:`~strips_framework.errors.InputError` on bad input."""
        ...
