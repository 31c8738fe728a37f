"""The installed entry points of a group, cached by what is installed.

Asking :mod:`importlib.metadata` for entry points imports it (with ``email``, ``zipfile``,
``csv`` and more) and reads every installed distribution's metadata: tens of
milliseconds, more than the whole solve of a small PDDL task. The answer only changes
when distributions are installed, removed or upgraded, so it is kept in a small file
together with a *signature* of the installation it was read from: for every
``*.dist-info`` and ``*.egg-info`` folder on :data:`sys.path`, its path and the
modification time and size of its ``entry_points.txt``. Computing the signature is one directory listing per
:data:`sys.path` entry and one ``stat`` per distribution; any install, uninstall,
upgrade or edited ``entry_points.txt`` changes it and the next lookup reads the metadata
again (and rewrites the file). There is one file per group and Python installation
(``sys.prefix``: each virtual environment has its own). The cache lives under ``$XDG_CACHE_HOME/strips-framework`` (default
``~/.cache``); where it cannot be written, every lookup reads the metadata.
"""

from __future__ import annotations

import os
import sys
import zlib
from pathlib import Path

#: Where the cache files go (a test points it elsewhere).
CACHE_ENV = "XDG_CACHE_HOME"
_METADATA_SUFFIXES = (".dist-info", ".egg-info")

#: One entry point: its name, its value (``module`` or ``module:attribute``) and the
#: name of the distribution that declares it.
EntryPoint = tuple[str, str, str]


def entry_points(group: str) -> list[EntryPoint]:
    """The entry points of ``group`` in the order :mod:`importlib.metadata` lists them."""
    cache = cache_file(f"entry-points-{group}")
    # The signature's lines hold no blank line: one ends it in the file.
    stamp = signature() + "\n\n"
    if cache is not None:
        try:
            text = cache.read_text(encoding="utf-8")
        except OSError:
            text = ""
        if text.startswith(stamp):
            rows = text[len(stamp) :].splitlines()
            return [tuple(row.split("\t")) for row in rows]  # type: ignore[misc]
    found = _read_metadata(group)
    if cache is not None:
        rows = "".join(f"{name}\t{value}\t{dist}\n" for name, value, dist in found)
        write(cache, stamp + rows)
    return found


def load(value: str) -> object:
    """The object an entry point's value names: a module, or ``module:attribute``."""
    import importlib

    module, _, attribute = value.partition(":")
    target: object = importlib.import_module(module.strip())
    for part in attribute.strip().split(".") if attribute.strip() else ():
        target = getattr(target, part)
    return target


def _read_metadata(group: str) -> list[EntryPoint]:
    import importlib.metadata

    found = []
    for dist in importlib.metadata.distributions():
        for entry in dist.entry_points:
            if entry.group == group:
                found.append((entry.name, entry.value, dist.metadata["Name"]))
    return found


def cache_file(stem: str) -> Path | None:
    """The cache file ``stem`` of this Python installation (``None``: no cache folder)."""
    base = os.environ.get(CACHE_ENV) or os.path.join(os.path.expanduser("~"), ".cache")
    if not os.path.isabs(base):
        return None
    # One file per Python installation (each virtual environment has its own), so that
    # several of them do not keep overwriting one another's.
    installation = zlib.crc32(sys.prefix.encode())
    return Path(base, "strips-framework", f"{stem}-{installation:08x}.txt")


def signature() -> str:
    """What is installed, as far as entry points can tell (see the module docstring)."""
    parts = [sys.version.replace("\n", " ")]
    for entry in sys.path:
        try:
            listing = os.scandir(entry or ".")
        except OSError:
            continue  # a zip file or a missing folder: no metadata folders to list
        with listing:
            names = sorted(item.name for item in listing if item.name.endswith(_METADATA_SUFFIXES))
        for name in names:
            folder = os.path.join(entry, name)
            try:
                info = os.stat(os.path.join(folder, "entry_points.txt"))
                parts.append(f"{folder}\t{info.st_mtime_ns}\t{info.st_size}")
            except OSError:
                parts.append(folder)
    return "\n".join(parts)


def write(path: Path, text: str) -> None:
    """Write ``path`` atomically (a concurrent reader sees the old file or the new one);
    an unwritable cache is no error, only slower."""
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        temporary = path.with_name(f"{path.name}.{os.getpid()}.tmp")
        temporary.write_text(text, encoding="utf-8")
        os.replace(temporary, path)
    except OSError:
        pass
