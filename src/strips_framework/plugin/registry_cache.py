"""What the registry held, cached by installation, so a run need not import pluggy.

Building the registry means importing pluggy (which imports :mod:`inspect`, and with it
``ast``, ``dis`` and ``tokenize``), every plugin module, and every class each hook
returns: more than the whole solve of a small PDDL task. What the hooks return only
changes when something is installed or a plugin's source changes, so after a registry
was built from the installed plugins (no ``extra_plugins``, no hook or plugin that
failed), one line per implementation (kind, name, the class's module and qualified name,
plugin, distribution) is kept in a small file with a *signature*: the installation's
(:func:`strips_framework.plugin.entry_points.signature`) and the modification time and
size of every module those classes and plugins live in. A run whose signature matches
reads the file and imports a class only when it is looked up, so ``strips solve`` on a
PDDL task imports its strategy and its heuristic and nothing else of the plugin system.
Any install, edited plugin module or ``STRIPS_DISABLE_PLUGIN_AUTOLOAD`` change makes the
signature differ and the registry is built through pluggy again (and the file rewritten).
The file sits beside the entry-point cache (``$XDG_CACHE_HOME/strips-framework``).
"""

from __future__ import annotations

import importlib
import os
import sys
from collections.abc import Iterable
from pathlib import Path

from strips_framework.plugin import entry_points

#: One implementation: kind, name, module, qualified name, plugin, distribution ("" for none).
Row = tuple[str, str, str, str, str, str]


def load(autoload: bool) -> list[Row] | None:
    """The cached rows, or ``None`` when there are none for this installation."""
    cache = entry_points.cache_file(_group(autoload))
    if cache is None:
        return None
    try:
        text = cache.read_text(encoding="utf-8")
    except OSError:
        return None
    head, _, body = text.partition("\n\n\n")
    files, _, rows = body.partition("\n\n")
    if head != entry_points.signature() or files != _stamps(files.splitlines()[1:]):
        return None
    return [tuple(row.split("\t")) for row in rows.splitlines() if row]  # type: ignore[misc]


def store(autoload: bool, rows: Iterable[Row], modules: Iterable[str]) -> None:
    """Keep ``rows``, valid while ``modules`` (the plugins' and the classes' modules,
    all imported) and the installation stay as they are."""
    cache = entry_points.cache_file(_group(autoload))
    if cache is None:
        return
    paths = sorted({str(Path(sys.modules[name].__file__ or "")) for name in modules})
    text = "\n".join(["\t".join(row) for row in rows])
    entry_points.write(cache, f"{entry_points.signature()}\n\n\n{_stamps(paths)}\n\n{text}\n")


def resolve(module: str, qualname: str) -> type:
    """The class a row names."""
    target: object = importlib.import_module(module)
    for part in qualname.split("."):
        target = getattr(target, part)
    return target  # type: ignore[return-value]


def row_of(kind: str, name: str, cls: type, plugin: str, distribution: str | None) -> Row | None:
    """The row for a registered class, or ``None`` when it cannot be found again by
    module and qualified name (a class made inside a function, say)."""
    module, qualname = cls.__module__, cls.__qualname__
    fields = (kind, name, module, qualname, plugin, distribution or "")
    if "<" in qualname or any("\t" in f or "\n" in f for f in fields):
        return None
    try:
        found = resolve(module, qualname)
    except (ImportError, AttributeError):
        return None
    return fields if found is cls else None


def _group(autoload: bool) -> str:
    return "registry" if autoload else "registry-builtins"


def _stamps(paths: Iterable[str]) -> str:
    """``files`` then one ``path\\tmtime\\tsize`` line per path (``-`` when it is gone)."""
    lines = ["files"]
    for path in paths:
        path = path.split("\t")[0]
        try:
            info = os.stat(path)
            lines.append(f"{path}\t{info.st_mtime_ns}\t{info.st_size}")
        except OSError:
            lines.append(f"{path}\t-")
    return "\n".join(lines)
