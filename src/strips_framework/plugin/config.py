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

Every table is optional; missing ones take the registered defaults of :data:`DEFAULTS`.
Mistakes are reported at the line the key is written on (when the file writes it), with
their key path and what was expected.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import Any

from strips_framework.errors import ConfigError, PluginError, did_you_mean
from strips_framework.limits import Limits
from strips_framework.options import Configurable, OptionError, declared_options, type_words
from strips_framework.plugin.registry import KINDS, Registration, Registry
from strips_framework.records import Record
from strips_framework.user_files import KeyLines, read_toml_with_keys

COMPONENTS = (
    "strategy", "prover", "difference", "relevance", "evaluator", "heuristic", "learner"
)
#: What each table takes when the config file names no implementation: the first of these
#: names that is registered (:func:`default_name`), else the one registered. Two come
#: from plugin distributions (``resolution`` from strips-resolution-prover, ``ff`` from
#: strips-evaluators); with plugin autoload off the prover is the builtin ``joins`` and
#: the means-ends search runs on the core alone (docs/config.md).
DEFAULTS: dict[str, tuple[str, ...]] = {
    "strategy": ("means-ends",),
    "prover": ("resolution",),
    "difference": ("uncompleted-proof",),
    "relevance": ("add-list",),
    "evaluator": ("paper",),
    "heuristic": ("ff",),
    "learner": ("triangle-table",),
}
#: The first preference of every table (the config before the registry is asked).
DEFAULT_CHOICES = {kind: names[0] for kind, names in DEFAULTS.items()}
#: Tables that configure a use rather than a component: ``[execution]`` is PLANEX's fault
#: model (``strips execute``, :mod:`strips_framework.macrops.planex`), ``[macrops]`` how a
#: search uses a MACROP library (:class:`strips_framework.macrops.search.MacroUse`).
SECTIONS = ("execution", "macrops")
#: The class each of :data:`SECTIONS` is read into, ``(module, class)``: imported only when
#: the config file writes the table, which is then checked at once (a typo in it is an
#: error before anything runs, as in every other table).
SECTION_CLASSES = {
    "execution": ("strips_framework.macrops.planex", "FaultModel"),
    "macrops": ("strips_framework.macrops.search", "MacroUse"),
}
#: The strategies PDDL input gets when the config names none, in order of preference (the
#: first registered one): what Fast Downward's users expect of ``strips solve DOMAIN
#: PROBLEM`` (lazy greedy search with hFF).
PDDL_DEFAULT_STRATEGIES = ("lazy-gbfs",)
PDDL_DEFAULT_STRATEGY = PDDL_DEFAULT_STRATEGIES[0]
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

    def __init__(self, kind: str, name: str, options: Mapping[str, Any] | None = None) -> None:
        self.kind = kind
        self.name = name
        self.options = dict(options or {})  # its own: never shared with a caller or a default

    def __hash__(self) -> int:  # the option values may be TOML arrays or tables
        return hash((self.kind, self.name, tuple(self.options)))


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
        sections: Mapping[str, dict[str, Any]] | None = None,
    ) -> None:
        self.choices = dict(choices)
        self.limits = limits
        self.source = source
        self.chosen = chosen
        self.sections = dict(sections or {})

    def __hash__(self) -> int:  # choices and sections are dicts; equal configs hash alike
        return hash((tuple(self.choices.values()), self.limits, self.source, self.chosen, tuple(self.sections)))

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
                    f"{source.at(key)}: unknown key '{key}'{did_you_mean(key, known)} "
                    f"(expected one of: {', '.join(known)})"
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
            if key in data:
                _instantiate(_section_class(key), table, key, source)
            sections[key] = table
        chosen = frozenset(kind for kind in COMPONENTS if kind in data)
        return cls(choices, limits, source, chosen, sections)

    def for_pddl(self, registry: Registry | None = None) -> Config:
        """This config for PDDL input: the strategy defaults to the first registered of
        :data:`PDDL_DEFAULT_STRATEGIES` (the first of them without a ``registry``) unless
        the config chose one."""
        if "strategy" in self.chosen:
            return self
        kinds = ("ground-strategy", "strategy")
        name = PDDL_DEFAULT_STRATEGY if registry is None else default_name(registry, kinds, PDDL_DEFAULT_STRATEGIES)
        if self.choices["strategy"].name == name:
            return self
        return self._replace(choices={**self.choices, "strategy": Choice("strategy", name)})

    def with_registered_defaults(self, registry: Registry, tables: Iterable[str]) -> Config:
        """This config with each of ``tables`` that the config file did not choose set to
        its registered default (:func:`default_name`)."""
        choices = dict(self.choices)
        for table in tables:
            if table in self.chosen or table not in DEFAULTS:
                continue
            # A lifted strategy's [heuristic] default is the planner's (lifted heuristics).
            kinds = STRATEGY_KINDS if table == "strategy" else (table,)
            name = default_name(registry, kinds, (choices[table].name, *DEFAULTS[table]))
            if name != choices[table].name:
                choices[table] = Choice(table, name)
        return self if choices == self.choices else self._replace(choices=choices)

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

    def section(self, key: str) -> Any:
        """The ``[key]`` table (one of :data:`SECTIONS`) built into its class, with wrong
        keys and values reported by key path."""
        return _instantiate(_section_class(key), self.sections.get(key, {}), key, self.source)

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
            if table not in self.chosen:  # a default: no key of the config file to point at
                raise PluginError(f"no [{table}] chosen, and the default {error}") from None
            raise PluginError(f"{self.source.at(table + '.name')}: '{table}.name': {error}") from None


def _section_class(key: str) -> type:
    import importlib

    module, name = SECTION_CLASSES[key]
    return getattr(importlib.import_module(module), name)


def default_name(registry: Registry, kinds: tuple[str, ...], preferred: tuple[str, ...]) -> str:
    """The default implementation of a table that takes ``kinds``: the first ``preferred``
    name registered, else the only one registered. Otherwise the first preference, whose
    lookup then says what is missing and what is registered instead."""
    registered = [name for kind in kinds for name in registry.names(kind)]
    for name in preferred:
        if name in registered:
            return name
    return registered[0] if len(registered) == 1 else preferred[0]


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
            if not issubclass(cls, Configurable):
                expected += "; a class declares options by deriving from strips_framework.options.Configurable"
            raise ConfigError(
                f"{source.at(path + '.' + key)}: unknown key '{path}.{key}': {what} has no "
                f"option '{key}'{did_you_mean(key, defaults)} (options: {expected})"
            )
    try:
        return cls(**options)
    except OptionError as error:  # the option system's own words, with the key path
        where = source.at(f"{path}.{error.option}")
        raise ConfigError(f"{where}: bad value for '{path}.{error.option}': {error.explanation}") from None
