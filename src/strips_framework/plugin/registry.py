"""The plugin manager and the registry of implementations it collects.

Builtin implementations are registered exactly like outside ones: each module in
:data:`DEFAULT_PLUGINS` holds ``@hookimpl`` functions, as an installed distribution's
entry-point module in the group ``strips_framework`` does (the installed entry points come
from :mod:`strips_framework.plugin.entry_points`, which caches them by what is installed, so a
run does not pay for :mod:`importlib.metadata`). Nothing is loaded at import
time; :func:`get_plugin_manager` builds a fresh manager on each call, and the
:class:`Registry` calls a kind's hook only when that kind is first looked up (a plugin
module that imports its classes inside its hooks costs nothing until then). Set
``STRIPS_DISABLE_PLUGIN_AUTOLOAD=1`` to skip installed distributions (tests use it).
"""

from __future__ import annotations

import importlib
import os
import warnings
from collections.abc import Iterable
from typing import NamedTuple

import pluggy

from strips_framework import options
from strips_framework.errors import PluginError
from strips_framework.plugin import entry_points, hookspecs

DEFAULT_PLUGINS = ("strips_framework.plugin.builtins",)

#: Each kind of implementation, by its config key: the hook that registers it, and the
#: words for it in messages (singular, plural).
KINDS = {
    "strategy": ("strips_register_strategies", "search strategy", "search strategies"),
    "ground-strategy": (
        "strips_register_ground_strategies", "ground-task strategy", "ground-task strategies"
    ),
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


class PluginManager(pluggy.PluginManager):
    """pluggy's manager, plus the distribution each installed plugin came from."""

    def __init__(self) -> None:
        super().__init__(hookspecs.PROJECT)
        self.add_hookspecs(hookspecs)
        #: Plugin name -> the name of the distribution that installed it.
        self.distributions: dict[str, str] = {}

    def load_installed(self) -> None:
        """Register every installed plugin (entry points in the group ``strips_framework``,
        from the cached list of :mod:`.entry_points`) one at a time, as pluggy's
        ``load_setuptools_entrypoints`` does (a name already registered or blocked is
        skipped). A plugin that cannot be imported, or that implements a hook that does not
        exist (a misspelling), is left out with a warning naming it and its distribution:
        one broken third-party plugin must not disable every command, ``strips plugins``
        included."""
        for name, value, distribution in entry_points.entry_points(hookspecs.PROJECT):
            if self.has_plugin(name) or self.is_blocked(name):
                continue
            try:
                self.register(entry_points.load(value), name=name)
                self.check_pending()
            except Exception as error:  # noqa: BLE001 - third-party code, any failure
                if self.has_plugin(name):
                    self.unregister(name=name)
                warnings.warn(
                    f"plugin {name!r} (from {distribution}) failed to load and is left out: "
                    f"{type(error).__name__}: {error}",
                    stacklevel=2,
                )
                continue
            self.distributions[name] = distribution


def get_plugin_manager(
    extra_plugins: Iterable[object] = (), load_entrypoints: bool | None = None
) -> PluginManager:
    """A new plugin manager with the builtins, installed plugins and ``extra_plugins``
    (a mistake in ``extra_plugins``, the caller's own, is an error)."""
    manager = PluginManager()
    for module_name in DEFAULT_PLUGINS:
        manager.register(importlib.import_module(module_name), name=module_name)
    if load_entrypoints is None:
        load_entrypoints = not os.environ.get(AUTOLOAD_SWITCH)
    if load_entrypoints:
        manager.load_installed()
    for plugin in extra_plugins:
        manager.register(plugin)
    manager.check_pending()
    return manager


class Registration(NamedTuple):
    """One implementation class and where it came from."""

    kind: str
    name: str
    cls: type
    plugin: str
    distribution: str | None

    def options(self) -> list[tuple[str, object]]:
        """The class's options (:func:`strips_framework.options.declared_options`) with their
        default values."""
        return list(options.declared_options(self.cls).items())

    @property
    def suffixes(self) -> tuple[str, ...]:
        """The file suffixes a problem loader reads (empty for other kinds)."""
        return tuple(getattr(self.cls, "suffixes", ()))


class Registry:
    """Implementation classes by kind and name, as the hooks registered them; each kind's
    hook is called the first time the kind is looked up."""

    def __init__(self, manager: PluginManager) -> None:
        self._manager = manager
        self._by_kind: dict[str, dict[str, Registration]] = {}

    def _kind(self, kind: str) -> dict[str, Registration]:
        """The registrations of ``kind``, collected from its hook on first use. A plugin
        whose hook raises is left out of the kind with a warning naming it."""
        found = self._by_kind.get(kind)
        if found is not None:
            return found
        hook_name, words, _ = KINDS[kind]
        found = {}
        caller = getattr(self._manager.hook, hook_name)
        for impl in reversed(caller.get_hookimpls()):  # registration order
            try:
                classes = list(impl.function() or ())
            except Exception as error:  # noqa: BLE001 - third-party code, any failure
                warnings.warn(
                    f"plugin {impl.plugin_name!r} failed to register its {KINDS[kind][2]} "
                    f"and is left out of them: {type(error).__name__}: {error}",
                    stacklevel=2,
                )
                continue
            for cls in classes:
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
                distribution = self._manager.distributions.get(impl.plugin_name)
                found[name] = Registration(kind, name, cls, impl.plugin_name, distribution)
        self._by_kind[kind] = found
        return found

    def raised_in(self, error: BaseException) -> tuple[Registration, str] | None:
        """The plugin implementation whose code raised ``error``, and where (``file:line``):
        the innermost frame of the traceback that is a method of a registered class from
        outside the core, or code in the module that defines one (a heuristic's estimator
        beside its heuristic). ``None`` for errors in the core's own code."""
        import traceback  # only on the way to an error message

        plugged = [
            registration
            for found in self._by_kind.values()
            for registration in found.values()
            if not registration.cls.__module__.startswith("strips_framework.")
        ]
        classes = {registration.cls: registration for registration in plugged}
        modules = {registration.cls.__module__: registration for registration in plugged}
        frames = list(traceback.walk_tb(error.__traceback__))
        for frame, _ in reversed(frames):
            registration = classes.get(type(frame.f_locals.get("self"))) or modules.get(
                frame.f_globals.get("__name__", "")
            )
            if registration is not None:
                innermost, line = frames[-1]
                return registration, f"{innermost.f_code.co_filename}:{line}"
        return None

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
