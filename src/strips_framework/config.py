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

    [limits]
    time = 60        # wall-clock seconds
    nodes = 10000    # nodes generated (world-model strategies)
    effort = 300     # prover effort per proof attempt
    expansions = 100000   # states expanded (forward strategies); unlimited if absent
    memory = 4096    # MiB (forward strategies and the CLI); unlimited if absent

Every table is optional; missing ones take the defaults in :data:`DEFAULT_CHOICES`.
Mistakes are reported with their key path and what was expected.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import attrs
from attrs import frozen

from strips_framework.errors import ConfigError, PluginError
from strips_framework.user_files import read_toml
from strips_framework.plugins import KINDS, Registration, Registry
from strips_framework.search.limits import Limits

COMPONENTS = ("strategy", "prover", "difference", "relevance", "evaluator", "heuristic")
DEFAULT_CHOICES = {
    "strategy": "means-ends",
    "prover": "resolution",
    "difference": "uncompleted-proof",
    "relevance": "add-list",
    "evaluator": "paper",
    "heuristic": "ff",
}
#: The strategy PDDL input gets when the config names none: what Fast Downward's users
#: expect of ``strips solve DOMAIN PROBLEM`` (lazy greedy search with hFF).
PDDL_DEFAULT_STRATEGY = "lazy-gbfs"


@frozen
class Choice:
    """An implementation picked by name, with the options to build it."""

    kind: str
    name: str
    options: dict[str, Any] = attrs.field(factory=dict)


@frozen
class Config:
    choices: dict[str, Choice]
    limits: Limits
    source: str = "<defaults>"
    #: The kinds the config file chose itself (the others took their defaults).
    chosen: frozenset[str] = frozenset()

    @classmethod
    def default(cls) -> Config:
        return cls.from_dict({})

    @classmethod
    def from_file(cls, path: Path) -> Config:
        return cls.from_dict(read_toml(path, "the config"), str(path))

    @classmethod
    def from_dict(cls, data: dict[str, Any], source: str = "<config>") -> Config:
        known = (*COMPONENTS, "limits")
        for key in data:
            if key not in known:
                raise ConfigError(
                    f"{source}: unknown key '{key}' (expected one of: {', '.join(known)})"
                )
        choices = {}
        for kind in COMPONENTS:
            table = data.get(kind, {})
            if isinstance(table, str):  # shorthand: prover = "resolution"
                table = {"name": table}
            if not isinstance(table, dict):
                raise ConfigError(
                    f"{source}: '{kind}' must be a table or an implementation name, "
                    f"got {_type_name(table)}"
                )
            options = dict(table)
            name = options.pop("name", DEFAULT_CHOICES[kind])
            if not isinstance(name, str):
                raise ConfigError(f"{source}: '{kind}.name' must be a string, got {_type_name(name)}")
            choices[kind] = Choice(kind, name, options)
        limits_table = data.get("limits", {})
        if not isinstance(limits_table, dict):
            raise ConfigError(f"{source}: 'limits' must be a table, got {_type_name(limits_table)}")
        limits = _instantiate(Limits, limits_table, "limits", source)
        return cls(choices, limits, source, frozenset(kind for kind in COMPONENTS if kind in data))

    def for_pddl(self) -> Config:
        """This config for PDDL input: the strategy defaults to :data:`PDDL_DEFAULT_STRATEGY`
        unless the config chose one."""
        if "strategy" in self.chosen:
            return self
        choices = {**self.choices, "strategy": Choice("strategy", PDDL_DEFAULT_STRATEGY)}
        return attrs.evolve(self, choices=choices)

    def build(self, registry: Registry, kind: str) -> Any:
        """An instance of the implementation chosen for ``kind``, with its options."""
        choice = self.choices[kind]
        registration = self.registration(registry, kind)
        return _instantiate(registration.cls, choice.options, kind, self.source, registration)

    def registration(self, registry: Registry, kind: str) -> Registration:
        """The registered implementation chosen for ``kind``; an unknown name chosen by
        the config file is reported at its key."""
        try:
            return registry.get(kind, self.choices[kind].name)
        except PluginError as error:
            if kind not in self.chosen:
                raise  # a default: no key of the config file to point at
            raise PluginError(f"{self.source}: '{kind}.name': {error}") from None


_NAMES = {dict: "a table", list: "an array", str: "a string", bool: "a boolean",
          int: "an integer", float: "a float"}


def _type_name(value: object) -> str:
    return _NAMES.get(type(value), type(value).__name__)


def _instantiate(
    cls: type,
    options: dict[str, Any],
    path: str,
    source: str,
    registration: Registration | None = None,
) -> Any:
    """``cls(**options)``, with wrong keys and values reported by key path."""
    what = f"{KINDS[registration.kind][1]} '{registration.name}'" if registration else f"'{path}'"
    fields = {a.name: a for a in attrs.fields(cls) if a.init} if attrs.has(cls) else {}
    for key in options:
        if key not in fields:
            expected = ", ".join(sorted(fields)) or "none"
            raise ConfigError(
                f"{source}: unknown key '{path}.{key}': {what} has no option '{key}' "
                f"(options: {expected})"
            )
    for key, value in options.items():
        default = fields[key].default
        if type(default) is float and type(value) is int:
            options = {**options, key: float(value)}
    try:
        return cls(**options)
    except (TypeError, ValueError) as error:
        raise ConfigError(f"{source}: bad value for {_explain(error, path, options)}") from None


def _explain(error: TypeError | ValueError, path: str, options: dict[str, Any]) -> str:
    """``'path.key': what was expected (got value)`` from an attrs validator's error.

    attrs' ``instance_of`` raises ``TypeError(message, attribute, expected_type, value)``;
    other validators raise with a message naming the attribute in quotes.
    """
    args = error.args
    attribute = next((a for a in args if isinstance(a, attrs.Attribute)), None)
    key = attribute.name if attribute else next(
        (k for k in options if f"'{k}'" in str(args[0])), None
    )
    where = f"'{path}.{key}'" if key else f"'{path}'"
    if attribute is not None and len(args) == 4:
        expected = args[2] if isinstance(args[2], tuple) else (args[2],)
        names = " or ".join(_type_name(t()) if t in _NAMES else t.__name__ for t in expected)
        return f"{where}: expected {names}, got {_type_name(args[3])} {args[3]!r}"
    got = f" (got {options[key]!r})" if key in options else ""
    return f"{where}: {args[0]}{got}"
