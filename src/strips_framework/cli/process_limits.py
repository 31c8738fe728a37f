"""Limits the operating system enforces on the whole ``strips`` process.

The searches watch ``[limits]`` themselves, but reading and grounding a large task, or a
heuristic's set-up, can outgrow them too. So the CLI also caps the address space at the
memory limit (allocations beyond it raise :class:`MemoryError`) and sets a wall-clock
alarm that raises :class:`~strips_framework.limits.LimitReached` wherever
the process is. A search catches both and reports the statistics it has; elsewhere the
CLI turns them into exit codes 22 and 23.

The alarm rings :data:`GRACE_SECONDS` after the run's deadline, not at it: a search that
stopped at its own limit (it watches the same clock) is then still writing its result,
and an alarm at the same instant would interrupt that and lose its statistics.

The alarm is the last resort, so it cannot be lost. :class:`LimitReached` is a
``BaseException`` (no ``except Exception`` catches it), and the alarm rings again every
:data:`GRACE_SECONDS`: a second ring means the first exception was swallowed anyway (a
bare ``except:``, or a garbage-collection callback or ``__del__``, where Python prints an
exception and drops it), and the process then stops at once with exit code 23 and the
time it ran, as Fast Downward's driver does when a search overruns its limit.
"""

from __future__ import annotations

import os
import resource
import signal
import sys
import time
from collections.abc import Iterator
from contextlib import contextmanager
from types import FrameType

from strips_framework.exit_codes import OUT_OF_TIME
from strips_framework.limits import Clock, LimitReached, Limits
from strips_framework.result import Status

#: How long after the deadline the alarm rings (see the module docstring).
GRACE_SECONDS = 0.5


class _Alarm:
    """The SIGALRM handler of one run: the first ring raises :class:`LimitReached`, a
    later one (the first was swallowed) ends the process."""

    def __init__(self, clock: Clock) -> None:
        self.clock = clock
        self.rung = False

    def __call__(self, signum: int, frame: FrameType | None) -> None:
        if not self.rung:
            self.rung = True
            raise LimitReached(Status.TIME_LIMIT)
        lines = f"; status: {Status.TIME_LIMIT}\n; time: {self.clock.elapsed():.3f} s\n"
        os.write(sys.stdout.fileno(), lines.encode())
        os.write(sys.stderr.fileno(), b"strips: error: the time limit's exception was swallowed; stopped\n")
        os._exit(OUT_OF_TIME)


@contextmanager
def enforced(limits: Limits, clock: Clock) -> Iterator[None]:
    """Apply the memory limit, and ``clock``'s deadline as an alarm, to the process while
    the block runs."""
    old_handler = signal.signal(signal.SIGALRM, _Alarm(clock))
    remaining = max(clock.deadline - time.perf_counter(), 0.0)
    signal.setitimer(signal.ITIMER_REAL, remaining + GRACE_SECONDS, GRACE_SECONDS)
    old_memory = resource.getrlimit(resource.RLIMIT_AS)
    if limits.memory is not None:
        cap, hard = limits.memory * 2**20, old_memory[1]
        if hard != resource.RLIM_INFINITY:
            cap = min(cap, hard)
        resource.setrlimit(resource.RLIMIT_AS, (cap, hard))
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old_handler)
        resource.setrlimit(resource.RLIMIT_AS, old_memory)


#: The wall-clock safety net of :func:`cpu_limited`: this many times the CPU limit...
WALL_FACTOR = 4
#: ... plus this many seconds.
WALL_EXTRA = 5.0


def _out_of_cpu(signum: int, frame: FrameType | None) -> None:
    raise LimitReached(Status.TIME_LIMIT)


@contextmanager
def cpu_limited(seconds: float) -> Iterator[None]:
    """Raise :class:`LimitReached` wherever the process is once it has used ``seconds``
    of CPU time in the block (``strips prove --time``: a prover's limit is CPU time, as
    E's and Vampire's, so a loaded machine slows a run but does not change its result).
    A prover that runs a child process (E) is stopped by a wall-clock alarm at
    :data:`WALL_FACTOR` times the limit plus :data:`WALL_EXTRA` seconds, since the
    child's CPU time is not the process's (generous: on a machine shared with other
    jobs our own CPU time runs far slower than the wall clock)."""
    old_prof = signal.signal(signal.SIGPROF, _out_of_cpu)
    old_alarm = signal.signal(signal.SIGALRM, _out_of_cpu)
    signal.setitimer(signal.ITIMER_PROF, seconds)
    signal.setitimer(signal.ITIMER_REAL, WALL_FACTOR * seconds + WALL_EXTRA)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_PROF, 0)
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGPROF, old_prof)
        signal.signal(signal.SIGALRM, old_alarm)
