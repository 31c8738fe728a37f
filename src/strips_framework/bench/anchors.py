"""Anchor planners: pyperplan and Fast Downward, run beside ours on PDDL problems.

They live in their own virtual environment (``STRIPS_ANCHORS``, default
``~/.cache/strips-anchors``) so that their dependencies never meet ours; set it up with
``python -m venv ~/.cache/strips-anchors && ~/.cache/strips-anchors/bin/pip install
pyperplan up-fast-downward``. Where they are is looked up on the machine that runs them,
so a Dask worker uses its own installation.
"""

from __future__ import annotations

import os
import re
from pathlib import Path

ANCHORS_ENV = "STRIPS_ANCHORS"
PYPERPLAN = "pyperplan"
FAST_DOWNWARD = "fast-downward"
PLANNERS = (PYPERPLAN, FAST_DOWNWARD)

#: How each planner reports its expansions (the last match counts: FD prints one per
#: search iteration); ``expanded: N`` is the line ``strips solve`` prints.
EXPANSIONS = (
    re.compile(r"(\d+) Nodes expanded"),
    re.compile(r"\] Expanded (\d+) state\(s\)\."),
    re.compile(r"(?im)^\W*expanded\s*[:=]\s*(\d+)"),
)


def anchor_home() -> Path:
    return Path(os.environ.get(ANCHORS_ENV, Path.home() / ".cache" / "strips-anchors"))


def planner_command(planner: str) -> list[str] | None:
    """The command that starts ``planner``, or ``None`` when it is not installed."""
    home = anchor_home()
    if planner == PYPERPLAN:
        script = home / "bin" / "pyperplan"
        return [str(script)] if script.is_file() else None
    scripts = sorted(
        (home / "lib").glob("python3*/site-packages/up_fast_downward/downward/fast-downward.py")
    )
    python = home / "bin" / "python"
    return [str(python), str(scripts[0])] if scripts and python.is_file() else None


def missing_note(planner: str) -> str:
    return (
        f"{planner} is not installed under {anchor_home()} (set {ANCHORS_ENV} to its "
        f"virtual environment)"
    )


def parse_expansions(output: str) -> int | None:
    for pattern in EXPANSIONS:
        found = pattern.findall(output)
        if found:
            return int(found[-1])
    return None
