"""Plans in the IPC format: one ``(action arg ...)`` a line, ``;`` comments, and a last
line giving the cost as Fast Downward writes it."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from strips_framework.errors import InputError
from strips_framework.plan_steps import split_step
from strips_framework.user_files import read_text


def plan_text(steps: Sequence[str], cost: int, uses_costs: bool) -> str:
    """The plan file: the steps, then ``; cost = N (unit cost)`` or ``(general cost)``."""
    kind = "general cost" if uses_costs else "unit cost"
    return "".join(f"{step}\n" for step in steps) + f"; cost = {cost} ({kind})\n"


def read_plan(path: Path, *, ipc_only: bool = False) -> list[str]:
    """The steps of a plan file, comments and blank lines left out. A line that is not a
    step (see :func:`split_step`) is bad input, reported at its line: whether a step
    *applies* is the validator's question, whether the file is a plan is this one's."""
    steps = []
    for number, line in enumerate(read_text(path, "the plan").splitlines(), start=1):
        step = line.split(";")[0].strip()
        if not step:
            continue
        if split_step(step, ipc_only=ipc_only) is None:
            column = line.index(step[0]) + 1
            expected = "'(name arg ...)'" if ipc_only else "'(name arg ...)' or 'name(arg, ...)'"
            raise InputError(str(path), number, column, f"expected a plan step {expected}")
        steps.append(step)
    return steps
