"""The TOML config (``strips.toml``): which implementations to use, their options, limits.

    [strategy]
    name = "means-ends"          # every key but 'name' is an option of the chosen class
    max_goals = 8

    [prover]
    name = "resolution"

    [evaluator]
    name = "paper"

    [heuristic]                  # for the strategies over ground tasks (PDDL)
    name = "ff"

    [learner]                    # for 'strips learn' (MACROPs)
    name = "triangle-table"

    [limits]
    time = 60        # wall-clock seconds
    nodes = 10000    # nodes generated (world-model strategies)
    effort = 300     # prover effort per proof attempt
    expansions = 100000   # states expanded (forward strategies); unlimited if absent
    memory = 4096    # MiB (forward strategies and the CLI); unlimited if absent

    [macrops]        # how 'solve --macrops' uses a library
    instances = 3    # instances offered per relevant MACROP whose kernel holds
    subgoals = false # also offer MACROPs whose kernel does not hold, as subgoals
    effort = 2000    # clause-against-fact matches per kernel looked for

    [execution]      # PLANEX's simulated world ('strips execute')
    failure = 0.1    # chance that an action has no effect
    disturbance = 0.05   # chance that the world changes after a step
    seed = 0

Every table is optional; missing ones take the defaults in :data:`DEFAULT_CHOICES`.
Mistakes are reported at the line the key is written on (when the file writes it), with
their key path and what was expected.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from strips_framework.errors import ConfigError, PluginError
from strips_framework.limits import Limits
from strips_framework.options import OptionError, declared_options, type_words
from strips_framework.plugin.registry import KINDS, Registration, Registry
from strips_framework.records import Record
from strips_framework.user_files import KeyLines, read_toml_with_keys

COMPONENTS = (
    "strategy", "prover", "difference", "relevance", "evaluator", "heuristic", "learner"
)
DEFAULT_CHOICES = {
    "strategy": "means-ends",
    "prover": "resolution",
    "difference": "uncompleted-proof",
    "relevance": "add-list",
    "evaluator": "paper",
    "heuristic": "ff",
    "learner": "triangle-table",
}
#: Tables that configure a use rather than a component: ``[execution]`` is PLANEX's fault
#: model (``strips execute``, :mod:`strips_framework.macrops.planex`), ``[macrops]`` how a
#: search uses a MACROP library (:class:`strips_framework.macrops.search.MacroUse`).
SECTIONS = ("execution", "macrops")
#: The strategy PDDL input gets when the config names none: what Fast Downward's users
#: expect of ``strips solve DOMAIN PROBLEM`` (lazy greedy search with hFF).
PDDL_DEFAULT_STRATEGY = "lazy-gbfs"
#: The config table that chooses a plugin kind, where it is not the kind itself: both
#: kinds of strategy are named in ``[strategy]`` (so their names must not clash).
TABLE_OF = {
    "ground-strategy": "strategy",
    "lifted-strategy": "strategy",
    "lifted-heuristic": "heuristic",
}
#: The kinds of strategy the ``[strategy]`` table may name.
STRATEGY_KINDS = ("strategy", "ground-strategy", "lifted-strategy")


class Choice(Record):
    """An implementation picked by name, with the options to build it."""

    kind: str
    name: str
    options: dict[str, Any]

    __slots__ = ("kind", "name", "options")

    def __init__(self, kind: str, name: str, options: dict[str, Any] = {}) -> None:
        self.kind = kind
        self.name = name
        self.options = options


class Config(Record):
    """What a config file (or the defaults) chose: read it with :meth:`from_file`."""

    choices: dict[str, Choice]
    limits: Limits
    #: The file the config came from, and where its keys are written (for messages).
    source: KeyLines
    #: The kinds the config file chose itself (the others took their defaults).
    chosen: frozenset[str]
    #: The tables of :data:`SECTIONS`, as written (read by the commands that use them).
    sections: dict[str, dict[str, Any]]

    __slots__ = ("choices", "limits", "source", "chosen", "sections")

    def __init__(
        self,
        choices: dict[str, Choice],
        limits: Limits,
        source: KeyLines = KeyLines("<defaults>"),
        chosen: frozenset[str] = frozenset(),
        sections: dict[str, dict[str, Any]] = {},
    ) -> None:
        self.choices = choices
        self.limits = limits
        self.source = source
        self.chosen = chosen
        self.sections = sections

    @classmethod
    def default(cls) -> Config:
        return cls.from_dict({})

    @classmethod
    def from_file(cls, path: Path) -> Config:
        return cls.from_dict(*read_toml_with_keys(path, "the config"))

    @classmethod
    def from_dict(cls, data: dict[str, Any], source: str | KeyLines = "<config>") -> Config:
        source = KeyLines(source) if isinstance(source, str) else source
        known = (*COMPONENTS, "limits", *SECTIONS)
        for key in data:
            if key not in known:
                raise ConfigError(
                    f"{source.at(key)}: unknown key '{key}' (expected one of: {', '.join(known)})"
                )
        choices = {}
        for kind in COMPONENTS:
            table = data.get(kind, {})
            if isinstance(table, str):  # shorthand: prover = "resolution"
                table = {"name": table}
            if not isinstance(table, dict):
                raise ConfigError(
                    f"{source.at(kind)}: '{kind}' must be a table or an implementation name, "
                    f"got {_type_name(table)}"
                )
            options = dict(table)
            name = options.pop("name", DEFAULT_CHOICES[kind])
            if not isinstance(name, str):
                raise ConfigError(
                    f"{source.at(kind + '.name')}: '{kind}.name' must be a string, "
                    f"got {_type_name(name)}"
                )
            choices[kind] = Choice(kind, name, options)
        limits_table = data.get("limits", {})
        if not isinstance(limits_table, dict):
            raise ConfigError(
                f"{source.at('limits')}: 'limits' must be a table, got {_type_name(limits_table)}"
            )
        limits = _instantiate(Limits, limits_table, "limits", source)
        sections = {}
        for key in SECTIONS:
            table = data.get(key, {})
            if not isinstance(table, dict):
                raise ConfigError(f"{source.at(key)}: '{key}' must be a table, got {_type_name(table)}")
            sections[key] = table
        chosen = frozenset(kind for kind in COMPONENTS if kind in data)
        return cls(choices, limits, source, chosen, sections)

    def for_pddl(self) -> Config:
        """This config for PDDL input: the strategy defaults to :data:`PDDL_DEFAULT_STRATEGY`
        unless the config chose one."""
        if "strategy" in self.chosen or self.choices["strategy"].name == PDDL_DEFAULT_STRATEGY:
            return self
        choices = {**self.choices, "strategy": Choice("strategy", PDDL_DEFAULT_STRATEGY)}
        return self._replace(choices=choices)

    def table_of(self, kind: str) -> str:
        """The config table that chooses the implementation of plugin kind ``kind``."""
        return TABLE_OF.get(kind, kind)

    def choice(self, kind: str) -> Choice:
        """What the config chose for plugin kind ``kind``."""
        return self.choices[self.table_of(kind)]

    def strategy_kind(self, registry: Registry) -> str:
        """``"ground-strategy"`` when ``[strategy]`` names a ground-task strategy,
        ``"lifted-strategy"`` when it names a lifted one, ``"strategy"`` when it names a
        world-model one."""
        name = self.choices["strategy"].name
        kinds = [kind for kind in STRATEGY_KINDS if name in registry.names(kind)]
        if len(kinds) > 1:
            words = " and as a ".join(KINDS[kind][1] for kind in kinds)
            raise PluginError(
                f"strategy {name!r} is registered both as a {words}; one plugin must "
                "rename its class"
            )
        if not kinds:
            available = ", ".join(sorted(n for kind in STRATEGY_KINDS for n in registry.names(kind)))
            raise PluginError(
                f"{self.source.at('strategy.name')}: 'strategy.name': search strategy {name!r} "
                "is not registered "
                f"(available: {available}); 'strips plugins' lists them"
            )
        return kinds[0]

    def section(self, cls: type, key: str) -> Any:
        """``cls`` built from the ``[key]`` table (one of :data:`SECTIONS`), with wrong keys
        and values reported by key path."""
        return _instantiate(cls, self.sections.get(key, {}), key, self.source)

    def build(self, registry: Registry, kind: str) -> Any:
        """An instance of the implementation chosen for ``kind``, with its options."""
        registration = self.registration(registry, kind)
        table = self.table_of(kind)
        return _instantiate(registration.cls, self.choice(kind).options, table, self.source, registration)

    def registration(self, registry: Registry, kind: str) -> Registration:
        """The registered implementation chosen for ``kind``; an unknown name chosen by
        the config file is reported at its key."""
        table = self.table_of(kind)
        try:
            return registry.get(kind, self.choice(kind).name)
        except PluginError as error:
            if table not in self.chosen:
                raise  # a default: no key of the config file to point at
            raise PluginError(f"{self.source.at(table + '.name')}: '{table}.name': {error}") from None


def _type_name(value: object) -> str:
    return type_words((type(value),))


def _instantiate(
    cls: type,
    options: dict[str, Any],
    path: str,
    source: KeyLines,
    registration: Registration | None = None,
) -> Any:
    """``cls(**options)``, with wrong keys and values reported by key path."""
    what = f"{KINDS[registration.kind][1]} '{registration.name}'" if registration else f"'{path}'"
    defaults = declared_options(cls)
    for key in options:
        if key not in defaults:
            expected = ", ".join(sorted(defaults)) or "none"
            raise ConfigError(
                f"{source.at(path + '.' + key)}: unknown key '{path}.{key}': {what} has no "
                f"option '{key}' "
                f"(options: {expected})"
            )
    for key, value in options.items():
        if type(defaults[key]) is float and type(value) is int:
            options = {**options, key: float(value)}
    try:
        return cls(**options)
    except (TypeError, ValueError) as error:
        key, explained = _explain(error, path, options)
        where = source.at(f"{path}.{key}" if key else path)
        raise ConfigError(f"{where}: bad value for {explained}") from None


def _explain(
    error: TypeError | ValueError, path: str, options: dict[str, Any]
) -> tuple[str | None, str]:
    """The key and ``'path.key': what was expected (got value)`` from a declared option's
    :class:`~strips_framework.options.OptionError` or an attrs validator's error.

    attrs' ``instance_of`` raises ``TypeError(message, attribute, expected_type, value)``
    and ``in_`` ``ValueError(message, attribute, options, value)``; other validators raise
    with a message naming the attribute in quotes.
    """
    if isinstance(error, OptionError):
        return error.option, f"'{path}.{error.option}': {error.explanation}"
    args = error.args
    attribute = next((a for a in args if type(a).__name__ == "Attribute"), None)
    key = attribute.name if attribute else next(
        (k for k in options if f"'{k}'" in str(args[0])), None
    )
    where = f"'{path}.{key}'" if key else f"'{path}'"
    if attribute is not None and len(args) == 4:
        expected = args[2] if isinstance(args[2], tuple) else (args[2],)
        if not all(isinstance(t, type) for t in expected):  # attrs' ``in_``: the values
            values = ", ".join(repr(v) for v in expected)
            return key, f"{where}: expected one of {values}, got {args[3]!r}"
        return key, f"{where}: expected {type_words(expected)}, got {_type_name(args[3])} {args[3]!r}"
    got = f" (got {options[key]!r})" if key in options else ""
    return key, f"{where}: {args[0]}{got}"
