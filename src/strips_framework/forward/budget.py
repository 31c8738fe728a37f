"""Watching the limits from inside a search loop.

The expansion count and the clock are checked on every expansion (an integer test and a
clock read, small beside the heuristic calls of an expansion); the resident memory only
every :data:`CHECK_INTERVAL` expansions, since reading it costs a system call.
"""

from __future__ import annotations

import math
import os
import resource
import time

from strips_framework.limits import Clock, LimitReached, Limits
from strips_framework.result import Status

CHECK_INTERVAL = 256
_PAGE_MIB = os.sysconf("SC_PAGE_SIZE") / 2**20 if hasattr(os, "sysconf") else 4 / 1024


def resident_mib() -> float:
    """The process's current resident set in MiB (the peak where /proc is missing)."""
    try:
        with open("/proc/self/statm", "rb") as statm:
            return int(statm.read().split()[1]) * _PAGE_MIB
    except OSError:
        return peak_mib()


def peak_mib() -> float:
    """The process's peak resident set in MiB (Linux reports KiB)."""
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


class Budget:
    """The limits of one search, with the time measured by the run's ``clock`` (started
    with the whole run, so reading and grounding use up the same allowance)."""

    def __init__(self, limits: Limits, clock: Clock) -> None:
        self.deadline = clock.deadline
        self.max_expansions = limits.expansions if limits.expansions is not None else math.inf
        self.memory = limits.memory

    def check(self, expanded: int) -> None:
        """Raise :class:`LimitReached` when a limit is exceeded after ``expanded``."""
        if expanded >= self.max_expansions:
            raise LimitReached(Status.EXPANSION_LIMIT)
        if time.perf_counter() > self.deadline:
            raise LimitReached(Status.TIME_LIMIT)
        memory = self.memory
        if memory is not None and expanded % CHECK_INTERVAL == 0 and resident_mib() > memory:
            raise LimitReached(Status.MEMORY_LIMIT)
