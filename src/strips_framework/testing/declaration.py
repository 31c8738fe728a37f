"""Checks every implementation class must pass, whatever its kind.

The config builds implementations from TOML by keyword; it relies on the class having a
``name`` and declaring its options as a :class:`~strips_framework.options.Configurable`
(the one way options are declared; a class with none need not be one), being
constructible with them, and refusing wrong values with ``ValueError`` (which the config
turns into a message naming the key). The capabilities a class declares are what the config checks combinations by
and what the kit holds it to, so they must be declared and spelled as in the vocabulary.
"""

from __future__ import annotations

from collections.abc import Mapping
from types import MappingProxyType
from typing import Any

from strips_framework.capabilities import VOCABULARY, declared, requirements, unknown
from strips_framework.options import Configurable, declared_options
from strips_framework.plugin.registry import KINDS


class ConformanceFailure(AssertionError):
    """A plugin does not do what the framework (or its own declaration) promises."""


def check_declaration(
    cls: type, kind: str, options: Mapping[str, Any] = MappingProxyType({})
) -> frozenset[str]:
    """The capabilities ``cls`` declares, after checking its name, declared options, that
    ``cls(**options)`` works, its capability words and its requirements."""
    name = getattr(cls, "name", None)
    if not isinstance(name, str) or not name:
        raise ConformanceFailure(f"{cls.__qualname__} has no 'name' class attribute (a string)")
    if not issubclass(cls, Configurable) and _parameters(cls):
        raise ConformanceFailure(
            f"{name!r}: {cls.__qualname__} takes {', '.join(_parameters(cls))} but declares no "
            "options: derive it from strips_framework.options.Configurable so the config can "
            "pass them by keyword, check them and 'strips plugins' can list them"
        )
    try:
        cls(**options)
    except Exception as error:
        raise ConformanceFailure(
            f"{name!r}: {cls.__qualname__}(**{dict(options)!r}) fails: {error!r}"
        ) from error
    capabilities = declared(cls, kind)
    if capabilities is None:
        raise ConformanceFailure(
            f"{name!r} declares no capabilities: add 'capabilities: ClassVar[frozenset[str]]' "
            f"with words from {sorted(VOCABULARY[kind]) or 'none (an empty set)'}"
        )
    strange = unknown(capabilities, kind)
    if strange:
        raise ConformanceFailure(
            f"{name!r} declares capabilities not in the {kind} vocabulary: {strange} "
            f"(known: {sorted(VOCABULARY[kind])})"
        )
    for need in requirements(cls):
        if need.kind not in KINDS or need.capability not in VOCABULARY.get(need.kind, {}):
            raise ConformanceFailure(
                f"{name!r} requires {need.capability!r} of a {need.kind!r}, which is not a "
                "capability of that kind in the vocabulary"
            )
    return capabilities


def _parameters(cls: type) -> list[str]:
    """The parameters ``cls(...)`` takes (none for a class that takes nothing)."""
    import inspect

    try:
        return list(inspect.signature(cls).parameters)
    except (TypeError, ValueError):  # no signature to read: nothing to say about it
        return []


class _Wrong:
    """A value no option accepts."""

    def __repr__(self) -> str:
        return "<a value of no option's type>"


def check_options_refuse_wrong_values(
    cls: type, options: Mapping[str, Any] = MappingProxyType({})
) -> None:
    """Each option given a value of no sensible type raises ``TypeError``/``ValueError``,
    which the config reports as 'bad value for KEY'; anything else would be a traceback
    or, worse, a silently broken run."""
    for option in declared_options(cls):
        try:
            cls(**{**options, option: _Wrong()})
        except (TypeError, ValueError):
            continue
        except Exception as error:
            raise ConformanceFailure(
                f"{cls.name!r}: option {option!r} given a wrong value raises "
                f"{type(error).__name__} ({error}); it must raise TypeError or ValueError"
            ) from error
        raise ConformanceFailure(
            f"{cls.name!r}: option {option!r} accepts {_Wrong()!r}; declare its type "
            "(strips_framework.options.Option) so a config mistake is reported by key"
        )
