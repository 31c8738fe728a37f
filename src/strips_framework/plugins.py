"""The plugin manager and the registry of implementations it collects.

Builtin implementations are registered exactly like outside ones: each module in
:data:`DEFAULT_PLUGINS` holds ``@hookimpl`` functions, as an installed distribution's
entry-point module in the group ``strips_framework`` does. Nothing is loaded at import
time; :func:`get_plugin_manager` builds a fresh manager on each call, and the
:class:`Registry` calls a kind's hook only when that kind is first looked up (a plugin
module that imports its classes inside its hooks costs nothing until then). Set
``STRIPS_DISABLE_PLUGIN_AUTOLOAD=1`` to skip installed distributions (tests use it).
"""

from __future__ import annotations

import importlib
import os
from collections.abc import Iterable

import attrs
import pluggy
from attrs import frozen

from strips_framework import hookspecs
from strips_framework.errors import PluginError

DEFAULT_PLUGINS = ("strips_framework.builtins",)

#: Each kind of implementation, by its config key: the hook that registers it, and the
#: words for it in messages (singular, plural).
KINDS = {
    "strategy": ("strips_register_strategies", "search strategy", "search strategies"),
    "prover": ("strips_register_provers", "prover", "provers"),
    "difference": (
        "strips_register_difference_extractors", "difference extractor", "difference extractors"
    ),
    "relevance": ("strips_register_relevance_filters", "relevance filter", "relevance filters"),
    "evaluator": ("strips_register_evaluators", "evaluator", "evaluators"),
    "heuristic": ("strips_register_heuristics", "state heuristic", "state heuristics"),
    "loader": ("strips_register_loaders", "problem loader", "problem loaders"),
    "learner": ("strips_register_macro_learners", "macro learner", "macro learners"),
}

#: Distributions known to provide implementations, for the hint in "not registered" errors.
KNOWN_PROVIDERS = {
    ("prover", "resolution"): "strips-resolution-prover",
    ("prover", "z3"): "strips-z3-prover",
    ("evaluator", "paper"): "strips-evaluators",
    ("evaluator", "breadth-first"): "strips-evaluators",
    ("evaluator", "goal-count"): "strips-evaluators",
    ("evaluator", "astar-goals"): "strips-evaluators",
    **{
        ("heuristic", name): "strips-evaluators"
        for name in ("blind", "goal-count", "hmax", "hadd", "ff", "lmcut", "lmcount")
    },
}

AUTOLOAD_SWITCH = "STRIPS_DISABLE_PLUGIN_AUTOLOAD"


def get_plugin_manager(
    extra_plugins: Iterable[object] = (), load_entrypoints: bool | None = None
) -> pluggy.PluginManager:
    """A new plugin manager with the builtins, installed plugins and ``extra_plugins``."""
    manager = pluggy.PluginManager(hookspecs.PROJECT)
    manager.add_hookspecs(hookspecs)
    for module_name in DEFAULT_PLUGINS:
        manager.register(importlib.import_module(module_name), name=module_name)
    if load_entrypoints is None:
        load_entrypoints = not os.environ.get(AUTOLOAD_SWITCH)
    if load_entrypoints:
        manager.load_setuptools_entrypoints(hookspecs.PROJECT)
    for plugin in extra_plugins:
        manager.register(plugin)
    manager.check_pending()
    return manager


@frozen
class Registration:
    """One implementation class and where it came from."""

    kind: str
    name: str
    cls: type
    plugin: str
    distribution: str | None

    def options(self) -> list[tuple[str, object]]:
        """The class's options (its attrs init fields) with their default values."""
        if not attrs.has(self.cls):
            return []
        options = []
        for field in attrs.fields(self.cls):
            if field.init:
                default = field.default
                if isinstance(default, attrs.Factory):  # type: ignore[arg-type]
                    default = default.factory()
                options.append((field.name, default))
        return options

    @property
    def suffixes(self) -> tuple[str, ...]:
        """The file suffixes a problem loader reads (empty for other kinds)."""
        return tuple(getattr(self.cls, "suffixes", ()))


class Registry:
    """Implementation classes by kind and name, as the hooks registered them; each kind's
    hook is called the first time the kind is looked up."""

    def __init__(self, manager: pluggy.PluginManager) -> None:
        self._manager = manager
        self._by_kind: dict[str, dict[str, Registration]] = {}
        self._distributions: dict[int, str] | None = None

    def _kind(self, kind: str) -> dict[str, Registration]:
        """The registrations of ``kind``, collected from its hook on first use."""
        found = self._by_kind.get(kind)
        if found is not None:
            return found
        if self._distributions is None:
            self._distributions = {
                id(plugin): dist.project_name
                for plugin, dist in self._manager.list_plugin_distinfo()
            }
        hook_name, words, _ = KINDS[kind]
        found = {}
        caller = getattr(self._manager.hook, hook_name)
        for impl in reversed(caller.get_hookimpls()):  # registration order
            for cls in impl.function() or ():
                name = getattr(cls, "name", None)
                if not isinstance(name, str) or not name:
                    raise PluginError(
                        f"plugin {impl.plugin_name!r} registered a {words} class "
                        f"{cls.__qualname__} without a 'name' attribute"
                    )
                known = found.get(name)
                if known is not None:
                    raise PluginError(
                        f"{words} {name!r} is registered twice: by {known.plugin!r} "
                        f"and by {impl.plugin_name!r}"
                    )
                found[name] = Registration(
                    kind, name, cls, impl.plugin_name, self._distributions.get(id(impl.plugin))
                )
        self._by_kind[kind] = found
        return found

    @classmethod
    def from_plugins(cls, extra_plugins: Iterable[object] = ()) -> Registry:
        return cls(get_plugin_manager(extra_plugins))

    def names(self, kind: str) -> list[str]:
        return sorted(self._kind(kind))

    def registrations(self, kind: str) -> list[Registration]:
        return [self._kind(kind)[name] for name in self.names(kind)]

    def get(self, kind: str, name: str) -> Registration:
        found = self._kind(kind).get(name)
        if found is not None:
            return found
        words = KINDS[kind][1]
        available = ", ".join(self.names(kind)) or "none"
        message = f"{words} {name!r} is not registered (available: {available})"
        provider = KNOWN_PROVIDERS.get((kind, name))
        if provider:
            message += f"; is {provider} installed?"
        else:
            message += "; is the plugin that provides it installed? 'strips plugins' lists them"
        raise PluginError(message)

    def loader_for(self, suffix: str) -> Registration:
        """The problem loader for files ending in ``suffix``."""
        for registration in self.registrations("loader"):
            if suffix in registration.suffixes:
                return registration
        known = sorted(s for r in self.registrations("loader") for s in r.suffixes)
        raise PluginError(
            f"no problem loader reads '{suffix}' files (known suffixes: {', '.join(known)})"
        )
