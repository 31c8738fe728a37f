"""Validation of evaluator options, shared so every evaluator rejects bad weights alike.

Options arrive from the TOML config as keyword arguments. A weight must be a finite,
non-negative number: a negative weight would turn a penalty into a reward and silently
invert the ordering the evaluator documents. Errors name the option in quotes and carry
the attrs attribute, which is how the config reports them by key path.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from types import MappingProxyType
from typing import Any

import attrs


def check_weight(name: str, value: object, attribute: attrs.Attribute | None = None) -> None:
    """Raise unless ``value`` is a finite number >= 0 (``bool`` is not a number here)."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise TypeError(
            f"'{name}' must be a number, not {type(value).__name__}", attribute, value
        )
    if not math.isfinite(value) or value < 0:
        raise ValueError(f"'{name}' must be a finite number >= 0", attribute, value)


def _validate_weight(_instance: Any, attribute: attrs.Attribute, value: object) -> None:
    check_weight(attribute.name, value, attribute)


def weight(default: float) -> Any:
    """An attrs field for a non-negative weight."""
    return attrs.field(default=default, validator=_validate_weight)


def _read_only_table(value: object) -> object:
    """A read-only copy of a mapping; anything else is left for the validator to reject."""
    return MappingProxyType(dict(value)) if isinstance(value, Mapping) else value


def _validate_table(_instance: Any, attribute: attrs.Attribute, value: object) -> None:
    if not isinstance(value, Mapping):
        raise TypeError(
            f"'{attribute.name}' must map names to weights, not {type(value).__name__}",
            attribute,
            value,
        )
    for key, entry in value.items():
        if not isinstance(key, str) or not key:
            raise TypeError(f"'{attribute.name}' keys must be names, got {key!r}", attribute)
        check_weight(f"{attribute.name}.{key}", entry, attribute)


def weight_table() -> Any:
    """An attrs field for a ``{name: weight}`` table, stored read-only.

    It takes no part in hashing: a mapping has no hash, and two evaluators that differ only
    in this table still compare unequal.
    """
    return attrs.field(
        factory=dict, converter=_read_only_table, validator=_validate_table, hash=False
    )
