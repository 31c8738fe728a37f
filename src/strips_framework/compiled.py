"""Whether the compiled hot loops run, or their pure-Python references.

The core (successor generation) and the evaluators plugin (relaxed explorations, LM-cut)
ship Cython modules that ``pip install`` builds when a C compiler is there; each keeps
its pure-Python implementation as the reference that tests compare it with. One
environment switch picks the references everywhere, to check or measure them.
"""

from __future__ import annotations

import os
from importlib import import_module
from types import ModuleType

#: Set to 1 to run the pure-Python implementations even where compiled ones are built.
PURE_PYTHON_SWITCH = "STRIPS_PURE_PYTHON"


def compiled_module(name: str, compiled: bool | None = None) -> ModuleType | None:
    """The compiled module ``name`` when it is built and ``compiled`` is None (and the
    environment switch is not set), else ``None``; ``compiled=False`` asks for the
    reference, ``compiled=True`` insists on the module (ImportError when it is not
    built)."""
    if compiled is None:
        if os.environ.get(PURE_PYTHON_SWITCH):
            return None
        try:
            return import_module(name)
        except ImportError:
            return None
    return import_module(name) if compiled else None
