"""strips-framework: STRIPS (Fikes & Nilsson, 1971) planning over first-order world
models, and forward search over grounded PDDL tasks, behind one Python API
(``docs/api.md``)::

    from strips_framework import Planner
    result = Planner.create().run("examples/robot-world/light.strips")
    print(result.status, result.plan, result.cost)

The names below are imported on first use, so ``import strips_framework.logic`` (say)
does not load the plugin machinery.
"""

from __future__ import annotations

import importlib
from typing import Any

__version__ = "0.1.0"

#: The public API by name, with the module that defines it.
_API = {
    "Planner": "strips_framework.planner",
    "Config": "strips_framework.plugin.config",
    "Limits": "strips_framework.limits",
    "Result": "strips_framework.result",
    "Status": "strips_framework.result",
}

__all__ = ["__version__", *_API]


def __getattr__(name: str) -> Any:
    module = _API.get(name)
    if module is None:
        raise AttributeError(f"module 'strips_framework' has no attribute {name!r}")
    return getattr(importlib.import_module(module), name)
