"""Plans in the IPC format: one ``(action arg ...)`` a line, ``;`` comments, and a last
line giving the cost as Fast Downward writes it."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from strips_framework.errors import InputError


def plan_text(steps: Sequence[str], cost: int, uses_costs: bool) -> str:
    """The plan file: the steps, then ``; cost = N (unit cost)`` or ``(general cost)``."""
    kind = "general cost" if uses_costs else "unit cost"
    return "".join(f"{step}\n" for step in steps) + f"; cost = {cost} ({kind})\n"


def read_plan(path: Path) -> list[str]:
    """The steps of a plan file, comments and blank lines left out."""
    try:
        lines = path.read_text(encoding="utf-8").splitlines()
    except OSError as error:
        raise InputError(str(path), None, None, f"cannot read plan: {error.strerror}") from None
    steps = (line.split(";")[0].strip() for line in lines)
    return [step for step in steps if step]
