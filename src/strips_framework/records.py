"""Records: immutable values as plain classes with ``__slots__``.

Every value of the core and of the plugins here (formulas, clauses, world models, tasks,
results, the config) is a record, rather than an attrs class, a dataclass or a
:class:`typing.NamedTuple` (``tests/test_value_declarations.py`` checks it): an attrs
class compiles its generated methods when it is built, and a NamedTuple evaluates its
annotations and compiles its constructor, at every start-up; a slotted class with a
written-out ``__init__`` is built about twenty times faster, which on a small task is a
measurable part of the whole run (``benchmarks/startup_declarations.py``,
``benchmarks/startup_vs_pyperplan.py``). Converters and checks are written in
``__init__``; state that changes (counters, caches, a search's nodes) lives in plain
classes with ``__slots__``, not in records.

A subclass lists its fields in ``__slots__`` (or, when it also keeps values computed from
them, in ``FIELDS``) and assigns them in ``__init__``; :class:`Record` gives it equality and
hashing by type and fields (so two record types with the same fields never compare
equal), a ``repr`` and ``_replace``. A field that says where a value came from (a source
line, a label) but not what it is stays out of ``COMPARED``, the fields equality and the
hash look at (``FIELDS`` unless the class says otherwise); ``repr`` and ``_replace`` keep
it. Records are not changed after they are built.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, ClassVar

if TYPE_CHECKING:  # a TypeVar bound to a name evaluates it: not at every start-up
    from typing import TypeVar

    _R = TypeVar("_R", bound="Record")


class Record:
    """Equality, hash, ``repr`` and ``_replace`` from the fields the constructor takes."""

    __slots__ = ()
    #: The constructor's parameters, in order; ``__slots__`` unless the class says otherwise
    #: (a subclass that adds no slots keeps its base's, as ``And`` and ``Or`` share theirs).
    FIELDS: ClassVar[tuple[str, ...]] = ()
    #: The fields equality and the hash compare; ``FIELDS`` unless the class says otherwise.
    COMPARED: ClassVar[tuple[str, ...]] = ()

    def __init_subclass__(cls) -> None:
        super().__init_subclass__()
        declares = "FIELDS" in cls.__dict__ or bool(cls.__dict__.get("__slots__"))
        if "FIELDS" not in cls.__dict__:
            cls.FIELDS = tuple(cls.__dict__.get("__slots__", ())) or cls.FIELDS
        if "COMPARED" not in cls.__dict__ and declares:
            cls.COMPARED = cls.FIELDS

    def _values(self) -> tuple[object, ...]:
        return tuple([getattr(self, name) for name in self.COMPARED])

    def __eq__(self, other: object) -> bool:
        return type(other) is type(self) and other._values() == self._values()  # type: ignore[attr-defined]

    def __ne__(self, other: object) -> bool:
        return not self == other

    def __hash__(self) -> int:
        return hash((type(self).__name__, self._values()))

    def __repr__(self) -> str:
        shown = ", ".join(f"{name}={getattr(self, name)!r}" for name in self.FIELDS)
        return f"{type(self).__name__}({shown})"

    def _replace(self: _R, **changes: object) -> _R:
        """A copy with ``changes`` (fields by name), as a NamedTuple's ``_replace``."""
        values = {name: getattr(self, name) for name in self.FIELDS}
        return type(self)(**{**values, **changes})
