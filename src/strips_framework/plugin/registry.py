"""The registry of implementations the plugins' hooks register.

Builtin implementations are registered exactly like outside ones: each module in
:data:`DEFAULT_PLUGINS` holds ``@hookimpl`` functions, as an installed distribution's
entry-point module in the group ``strips_framework`` does; the pluggy manager that collects
them is :mod:`strips_framework.plugin.manager`. Nothing is loaded at import time: the
:class:`Registry` calls a kind's hook only when that kind is first looked up (a plugin
module that imports its classes inside its hooks costs nothing until then), and
:meth:`Registry.from_plugins` reads what the installed plugins registered from
:mod:`strips_framework.plugin.registry_cache` when nothing changed since, importing
neither pluggy nor any plugin, and each class only when it is looked up. Set
``STRIPS_DISABLE_PLUGIN_AUTOLOAD=1`` to skip installed distributions (tests use it).
"""

from __future__ import annotations

import os
import warnings
from collections.abc import Iterable
from typing import TYPE_CHECKING

from strips_framework import options
from strips_framework.errors import PluginError, did_you_mean
from strips_framework.plugin import registry_cache

if TYPE_CHECKING:
    from strips_framework.plugin.manager import PluginManager

DEFAULT_PLUGINS = ("strips_framework.plugin.builtins",)

#: Each kind of implementation, by its config key: the hook that registers it, and the
#: words for it in messages (singular, plural).
KINDS = {
    "strategy": ("strips_register_strategies", "search strategy", "search strategies"),
    "ground-strategy": (
        "strips_register_ground_strategies", "ground-task strategy", "ground-task strategies"
    ),
    "lifted-strategy": (
        "strips_register_lifted_strategies", "lifted-task strategy", "lifted-task strategies"
    ),
    "prover": ("strips_register_provers", "prover", "provers"),
    "difference": (
        "strips_register_difference_extractors", "difference extractor", "difference extractors"
    ),
    "relevance": ("strips_register_relevance_filters", "relevance filter", "relevance filters"),
    "evaluator": ("strips_register_evaluators", "evaluator", "evaluators"),
    "heuristic": ("strips_register_heuristics", "state heuristic", "state heuristics"),
    "lifted-heuristic": (
        "strips_register_lifted_heuristics", "lifted heuristic", "lifted heuristics"
    ),
    "loader": ("strips_register_loaders", "problem loader", "problem loaders"),
    "learner": ("strips_register_macro_learners", "macro learner", "macro learners"),
}

AUTOLOAD_SWITCH = "STRIPS_DISABLE_PLUGIN_AUTOLOAD"


class Registration:
    """One implementation class and where it came from. ``cls`` is the class, or
    ``(module, qualified name)`` to import it from when it is first used (a registration
    read from the cache)."""

    __slots__ = ("kind", "name", "_cls", "plugin", "distribution")

    def __init__(
        self, kind: str, name: str, cls: type | tuple[str, str], plugin: str, distribution: str | None
    ) -> None:
        self.kind, self.name, self._cls = kind, name, cls
        self.plugin, self.distribution = plugin, distribution

    @property
    def cls(self) -> type:
        if isinstance(self._cls, tuple):
            self._cls = registry_cache.resolve(*self._cls)
        return self._cls

    @property
    def module(self) -> str:
        """The module that defines the class (without importing it)."""
        return self._cls[0] if isinstance(self._cls, tuple) else self._cls.__module__

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Registration) and other._key() == self._key()

    def __hash__(self) -> int:
        return hash(self._key())

    def _key(self) -> tuple[object, ...]:
        return (self.kind, self.name, self.cls, self.plugin, self.distribution)

    def __repr__(self) -> str:
        return f"Registration({self.kind!r}, {self.name!r}, {self.cls!r}, {self.plugin!r})"

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

    def __init__(
        self, manager: PluginManager | None, cached: dict[str, dict[str, Registration]] | None = None
    ) -> None:
        """A registry over ``manager``'s hooks, or holding the ``cached`` registrations
        of every kind (then ``manager`` is ``None``)."""
        self._manager = manager
        self._by_kind: dict[str, dict[str, Registration]] = dict(cached or {})
        #: False once a plugin's hook raised (its classes are missing).
        self.complete = True

    def _kind(self, kind: str) -> dict[str, Registration]:
        """The registrations of ``kind``, collected from its hook on first use. A plugin
        whose hook raises is left out of the kind with a warning naming it."""
        found = self._by_kind.get(kind)
        if found is not None:
            return found
        if self._manager is None:  # from the cache, which holds every kind
            return {}
        hook_name, words, _ = KINDS[kind]
        found = {}
        caller = getattr(self._manager.hook, hook_name)
        for impl in reversed(caller.get_hookimpls()):  # registration order
            try:
                classes = list(impl.function() or ())
            except Exception as error:  # noqa: BLE001 - third-party code, any failure
                self.complete = False
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
            if not registration.module.startswith("strips_framework.")
        ]
        # A class still to be imported from the cache has no instance yet: its module is
        # enough, and importing every class on the way to an error message is not.
        classes = {r._cls: r for r in plugged if isinstance(r._cls, type)}
        modules = {registration.module: registration for registration in plugged}
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
        """The registry of the builtins, the installed plugins (unless
        ``STRIPS_DISABLE_PLUGIN_AUTOLOAD`` is set) and ``extra_plugins``; without extra
        plugins, read from the cache when the installation is unchanged, and cached
        otherwise (see :mod:`strips_framework.plugin.registry_cache`)."""
        extra = list(extra_plugins)
        autoload = not os.environ.get(AUTOLOAD_SWITCH)
        if not extra:
            rows = registry_cache.load(autoload)
            if rows is not None:
                cached: dict[str, dict[str, Registration]] = {kind: {} for kind in KINDS}
                for kind, name, module, qualname, plugin, distribution in rows:
                    registration = Registration(kind, name, (module, qualname), plugin, distribution or None)
                    cached[kind][name] = registration
                return cls(None, cached)
        from strips_framework.plugin.manager import get_plugin_manager

        registry = cls(get_plugin_manager(extra))
        if not extra:
            registry._cache(autoload)
        return registry

    def _cache(self, autoload: bool) -> None:
        """Write every kind's registrations to the cache, unless a plugin failed to load
        or to register (the next run then tries again, and warns again), or a class
        cannot be found again by name. Collected in a registry of their own, quietly:
        this one stays lazy, and warns when the run looks a failing kind up."""
        assert self._manager is not None
        every = Registry(self._manager)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            kinds = [every._kind(kind) for kind in KINDS]
        if not every.complete or self._manager.failed:
            return
        rows = []
        for found in kinds:
            for r in found.values():
                row = registry_cache.row_of(r.kind, r.name, r.cls, r.plugin, r.distribution)
                if row is None:
                    return
                rows.append(row)
        plugins = [getattr(plugin, "__name__", type(plugin).__module__) for plugin in self._manager.get_plugins()]
        registry_cache.store(autoload, rows, [*plugins, *(row[2] for row in rows)])

    def names(self, kind: str) -> list[str]:
        return sorted(self._kind(kind))

    def registrations(self, kind: str) -> list[Registration]:
        return [self._kind(kind)[name] for name in self.names(kind)]

    def get(self, kind: str, name: str) -> Registration:
        found = self._kind(kind).get(name)
        if found is not None:
            return found
        raise PluginError(self._not_registered(kind, name))

    def _not_registered(self, kind: str, name: str) -> str:
        """Why ``name`` cannot be had: what is registered instead, a close name, and
        whether the installed plugins were loaded at all."""
        names = self.names(kind)
        message = f"{KINDS[kind][1]} {name!r} is not registered (available: {', '.join(names) or 'none'})"
        close = did_you_mean(name, names)
        if close:
            return message + close
        if os.environ.get(AUTOLOAD_SWITCH):
            from strips_framework.plugin import entry_points, hookspecs

            installed = sorted({dist for _, _, dist in entry_points.entry_points(hookspecs.PROJECT)})
            skipped = f" (installed: {', '.join(installed)})" if installed else ""
            return f"{message}; plugin autoload is off ({AUTOLOAD_SWITCH} is set), so no installed plugin is loaded{skipped}"
        return f"{message}; is the plugin that provides it installed? 'strips plugins' lists them"

    def loader_for(self, suffix: str) -> Registration:
        """The problem loader for files ending in ``suffix``."""
        for registration in self.registrations("loader"):
            if suffix in registration.suffixes:
                return registration
        known = sorted(s for r in self.registrations("loader") for s in r.suffixes)
        raise PluginError(
            f"no problem loader reads '{suffix}' files (known suffixes: {', '.join(known)})"
        )
