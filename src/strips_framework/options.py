"""Declared options: what an implementation class is configured with, typed and checked.

The config builds each implementation as ``cls(**options)`` from its TOML table, and
``strips plugins`` lists what can be set; both ask :func:`declared_options` for the class's
options. A class declares them as :class:`Option` values in its ``options`` tuple and
derives from :class:`Configurable`, whose ``__init__`` takes each option by keyword (or
its default), checks it and refuses a wrong value with :class:`OptionError`, a
``ValueError`` naming the option and what was expected, which the config reports at the
key's line. Instances are immutable and compare by type and option values.

This is the one way options are declared, in the core and in every plugin here: not
attrs, because importing it and building attrs classes costs more than a small task's
whole solve (``benchmarks/startup_declarations.py``: 40 classes of three options take
about 90 ms with attrs, under 1 ms here), and because the config's messages then come
from :class:`OptionError` itself, not from another library's exceptions.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from typing import Any, ClassVar

from strips_framework.records import Record

#: The words for a value of each type, as TOML users know them.
_ARTICLES = {bool: "a boolean", int: "an integer", float: "a float", str: "a string",
             dict: "a table", list: "an array"}  # fmt: skip


def type_words(types: tuple[type, ...]) -> str:
    """``an integer or a float``: the types of a value, as a message says them."""
    return " or ".join(_ARTICLES.get(t, t.__name__) for t in types)


class OptionError(ValueError):
    """A value an option does not accept: ``explanation`` says what was expected and what
    came, and the config prefixes it with the option's key path."""

    def __init__(self, option: str, explanation: str) -> None:
        super().__init__(f"'{option}': {explanation}")
        self.option = option
        self.explanation = explanation


class Option:
    """One option: its name, the types it accepts, its default and its bounds.

    ``types`` is a type or a tuple of them; ``bool`` is never taken for a number, and an
    integer given to an option that accepts floats (TOML writes ``2`` for ``2.0``)
    becomes a float. ``minimum``/``maximum`` bound numbers (``exclusive_minimum`` makes the
    lower bound strict); ``choices`` lists the only values allowed; ``optional`` also
    accepts ``None``; ``finite`` refuses ``inf`` and ``nan``. ``check`` is any further
    test: it gets the value and returns what was expected when it refuses it (else
    ``None``); ``convert`` then makes the stored value (say, a read-only copy of a table).
    ``doc`` says what the option does (``strips plugins`` shows it)."""

    __slots__ = ("name", "types", "default", "minimum", "exclusive_minimum", "maximum",
                 "choices", "optional", "finite", "check_value", "convert", "doc")  # fmt: skip

    def __init__(
        self,
        name: str,
        types: type | tuple[type, ...],
        default: object,
        *,
        minimum: float | None = None,
        exclusive_minimum: bool = False,
        maximum: float | None = None,
        choices: tuple[object, ...] = (),
        optional: bool = False,
        finite: bool = False,
        check: Callable[[Any], str | None] | None = None,
        convert: Callable[[Any], Any] | None = None,
        doc: str = "",
    ) -> None:
        self.name, self.default, self.doc = name, default, doc
        self.types = types if isinstance(types, tuple) else (types,)
        self.minimum, self.exclusive_minimum, self.maximum = minimum, exclusive_minimum, maximum
        self.choices, self.optional, self.finite = choices, optional, finite
        self.check_value, self.convert = check, convert

    def check(self, value: object) -> Any:
        """``value`` as the option stores it; :class:`OptionError` when it is refused."""
        if value is None and self.optional:
            return None
        if float in self.types and type(value) is int:
            value = float(value)
        wrong_bool = isinstance(value, bool) and bool not in self.types
        if wrong_bool or not isinstance(value, self.types):
            accepted = (int, *self.types) if float in self.types and int not in self.types else self.types
            got = type_words((type(value),))
            raise OptionError(self.name, f"expected {type_words(accepted)}, got {got} {value!r}")
        if self.choices and value not in self.choices:
            allowed = ", ".join(map(repr, self.choices))
            raise OptionError(self.name, f"expected one of {allowed}, got {value!r}")
        low, high = self.minimum, self.maximum
        if low is not None and (value < low or (self.exclusive_minimum and value == low)):  # type: ignore[operator]
            bound = f"{'>' if self.exclusive_minimum else '>='} {low}"
            raise OptionError(self.name, f"expected a value {bound} (got {value!r})")
        if high is not None and not value <= high:  # type: ignore[operator]
            raise OptionError(self.name, f"expected a value <= {high} (got {value!r})")
        if self.finite and isinstance(value, float) and not math.isfinite(value):
            raise OptionError(self.name, f"expected a finite number (got {value!r})")
        if self.check_value is not None:
            expected = self.check_value(value)
            if expected is not None:
                raise OptionError(self.name, f"expected {expected} (got {value!r})")
        return value if self.convert is None else self.convert(value)


class Configurable(Record):
    """An implementation built from its declared :attr:`options` by keyword; a
    :class:`~strips_framework.records.Record` whose fields are its options."""

    __slots__ = ()
    #: What the class can be configured with, in the order ``strips plugins`` lists them.
    options: ClassVar[tuple[Option, ...]] = ()

    def __init_subclass__(cls) -> None:
        super().__init_subclass__()
        cls.FIELDS = cls.COMPARED = tuple(option.name for option in cls.options)

    def __init__(self, **values: object) -> None:
        declared_names = {option.name for option in self.options}
        for key in values:
            if key not in declared_names:
                raise TypeError(f"{type(self).__qualname__} has no option {key!r}")
        for option in self.options:
            if option.name in values:
                value = option.check(values[option.name])
            else:  # a default is stored as a given value would be (converted)
                value = option.default if option.convert is None else option.convert(option.default)
            object.__setattr__(self, option.name, value)

    def __setattr__(self, name: str, value: object) -> None:
        raise AttributeError(f"{type(self).__qualname__} is immutable: options are set when it is built")

    def __hash__(self) -> int:  # a table option (a read-only mapping) hashes by its items
        values = (tuple(sorted(v.items())) if isinstance(v, Mapping) else v for v in self._values())
        return hash((type(self).__name__, *values))


def declared(cls: type) -> tuple[Option, ...]:
    """The options of ``cls`` in declaration order: a :class:`Configurable`'s
    :attr:`~Configurable.options`; none for any other class."""
    return cls.options if isinstance(cls, type) and issubclass(cls, Configurable) else ()


def declared_options(cls: type) -> dict[str, object]:
    """The options of ``cls`` with their defaults, in declaration order."""
    return {option.name: option.default for option in declared(cls)}
