"""The syntax of one plan step, ``(name arg ...)`` (IPC) or ``name(arg, ...)`` (native):
below both the plan files (:mod:`strips_framework.formats.ipc`) and the simulator that
replays steps (:mod:`strips_framework.worldmodel.simulate`), which read the same steps."""

from __future__ import annotations

import re

_FUNCTIONAL = re.compile(r"\s*([^\s(),]+)\s*(?:\(([^()]*)\))?\s*")
_IPC = re.compile(r"\s*\(\s*([^\s()]+)((?:\s+[^\s()]+)*)\s*\)\s*")


def split_step(text: str, *, ipc_only: bool = False) -> list[str] | None:
    """``["name", "arg", ...]`` from ``(name arg ...)`` or (unless ``ipc_only``, as for
    PDDL) the native ``name(arg, ...)``; ``None`` when the text is neither."""
    ipc = _IPC.fullmatch(text)
    if ipc:
        return [ipc.group(1), *ipc.group(2).split()]
    functional = None if ipc_only else _FUNCTIONAL.fullmatch(text)
    if functional is None:
        return None
    inside = functional.group(2)
    args = [] if inside is None or not inside.strip() else [a.strip() for a in inside.split(",")]
    return None if "" in args else [functional.group(1), *args]
