"""The node evaluators' weight options (the core's paper evaluator and the plugins'),
declared alike so every evaluator refuses bad weights alike.

Options arrive from the TOML config as keyword arguments. A weight must be a finite,
non-negative number: a negative weight would turn a penalty into a reward and silently
invert the ordering the evaluator documents. The checks are the core's option system's
(:class:`strips_framework.options.Option`), so the config reports a refused value at its
key with what was expected.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from types import MappingProxyType

from strips_framework.options import Option


def weight(name: str, default: float, doc: str = "") -> Option:
    """A non-negative, finite weight (an integer is taken as a float)."""
    return Option(name, float, default, minimum=0, finite=True, doc=doc)


def _weights_expected(value: Mapping[object, object]) -> str | None:
    for key, entry in value.items():
        if not isinstance(key, str) or not key:
            return f"names as keys, not {key!r}"
        number = isinstance(entry, (int, float)) and not isinstance(entry, bool)
        if not number or not math.isfinite(entry) or entry < 0:  # type: ignore[operator]
            return f"a finite number >= 0 for {key!r}, not {entry!r}"
    return None


def weight_table(name: str, doc: str = "") -> Option:
    """A ``{name: weight}`` table, stored read-only (empty by default)."""
    return Option(name, dict, MappingProxyType({}), check=_weights_expected,
                  convert=lambda table: MappingProxyType(dict(table)), doc=doc)
