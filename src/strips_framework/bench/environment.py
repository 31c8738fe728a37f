"""The machine and software a run happened on, recorded with every row: rows from
different machines (a Dask cluster) or different installs must be told apart."""

from __future__ import annotations

import functools
import os
import platform
import socket
import sys
from importlib import metadata

from strips_framework.plugin.hookspecs import PROJECT

CORE = "strips-framework"


@functools.cache
def machine() -> dict[str, object]:
    return {
        "host": socket.gethostname(),
        "system": platform.platform(),
        "cpu": _cpu_model(),
        "cpus": os.cpu_count(),
        "memory_mib": _memory_mib(),
        "python": sys.version.split()[0],
    }


@functools.cache
def versions() -> dict[str, str]:
    """The core's version and that of every distribution providing plugins."""
    found = {CORE: metadata.version(CORE)}
    for entry_point in metadata.entry_points(group=PROJECT):
        if entry_point.dist is not None:
            found[entry_point.dist.name] = entry_point.dist.version
    return dict(sorted(found.items()))


def _cpu_model() -> str:
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as info:
            for line in info:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or platform.machine()


def _memory_mib() -> int | None:
    try:
        return os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES") // 2**20
    except (ValueError, OSError):
        return None
