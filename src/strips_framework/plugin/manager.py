"""The pluggy plugin manager: the builtins, the installed plugins and the caller's own.

Only imported when the registry must be built from the hooks (see
:mod:`strips_framework.plugin.registry_cache`): pluggy imports :mod:`inspect`, which costs
more than a small task's whole solve.
"""

from __future__ import annotations

import importlib
import os
import warnings
from collections.abc import Iterable

import pluggy

from strips_framework.plugin import entry_points, hookspecs
from strips_framework.plugin.registry import AUTOLOAD_SWITCH, DEFAULT_PLUGINS


class PluginManager(pluggy.PluginManager):
    """pluggy's manager, plus the distribution each installed plugin came from."""

    def __init__(self) -> None:
        super().__init__(hookspecs.PROJECT)
        self.add_hookspecs(hookspecs)
        #: Plugin name -> the name of the distribution that installed it.
        self.distributions: dict[str, str] = {}
        #: The installed plugins that failed to load (left out with a warning).
        self.failed: list[str] = []

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
                self.failed.append(name)
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
