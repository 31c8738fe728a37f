"""One child process under a wall-clock and a memory limit.

The child gets its own process group (so that a timeout kills everything it started,
e.g. Fast Downward's translator and search), an address-space limit (``RLIMIT_AS``: a
memory blow-up fails inside the child, not on the machine), and on Linux is killed if the
thread that started it dies (a killed Dask worker leaves no planner behind). Output goes
to files in the run's folder, so a chatty child cannot block on a full pipe.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import threading
import time
from collections.abc import Mapping, Sequence
from pathlib import Path

from strips_framework.records import Record

POLL_SECONDS = 0.02


class ChildOutcome(Record):
    exit_code: int  # negative: killed by that signal
    timed_out: bool
    wall_seconds: float
    peak_memory_kib: int
    stdout: str
    stderr: str

    __slots__ = ("exit_code", "timed_out", "wall_seconds", "peak_memory_kib", "stdout", "stderr")

    def __init__(
        self,
        exit_code: int,
        timed_out: bool,
        wall_seconds: float,
        peak_memory_kib: int,
        stdout: str,
        stderr: str,
    ) -> None:
        self.exit_code = exit_code
        self.timed_out = timed_out
        self.wall_seconds = wall_seconds
        self.peak_memory_kib = peak_memory_kib
        self.stdout = stdout
        self.stderr = stderr


class LiveGroups:
    """The process groups of the children running now, so that an interrupted runner can
    kill them (they do not see the terminal's Ctrl-C: they are not in its group). Once
    closed, a child that starts late is killed at once."""

    def __init__(self) -> None:
        self._groups: set[int] = set()
        self._lock = threading.Lock()
        self._closed = False

    def add(self, group: int) -> None:
        with self._lock:
            if self._closed:
                _kill_group(group)
            self._groups.add(group)

    def discard(self, group: int) -> None:
        with self._lock:
            self._groups.discard(group)

    def close(self) -> None:
        """Kill every child running now or started later."""
        with self._lock:
            self._closed = True
            for group in self._groups:
                _kill_group(group)


#: Sets the limits in a fresh interpreter, then becomes the command (``exec``): a
#: ``preexec_fn`` would do the same in the forked child, but is unsafe with threads.
LIMITER = """
import ctypes, os, resource, signal, sys
memory = int(sys.argv[1])
resource.setrlimit(resource.RLIMIT_AS, (memory, memory))
if sys.platform == "linux":
    ctypes.CDLL(None).prctl(1, signal.SIGKILL)  # PR_SET_PDEATHSIG
os.execvp(sys.argv[2], sys.argv[2:])
"""


def limited(command: Sequence[str], memory_mib: int) -> list[str]:
    """``command`` under an address-space limit of ``memory_mib``."""
    return [sys.executable, "-c", LIMITER, str(memory_mib * 1024 * 1024), *command]


def _kill_group(group: int) -> None:
    try:
        os.killpg(group, signal.SIGKILL)
    except ProcessLookupError:
        pass


def run_limited(
    command: Sequence[str],
    folder: Path,
    env: Mapping[str, str],
    seconds: float,
    memory_mib: int,
    live: LiveGroups | None = None,
) -> ChildOutcome:
    """Run ``command`` in ``folder``; past ``seconds`` its process group is killed."""
    out_path, err_path = folder / "stdout.txt", folder / "stderr.txt"
    started = time.monotonic()
    with out_path.open("wb") as out, err_path.open("wb") as err:
        child = subprocess.Popen(
            limited(command, memory_mib), cwd=folder, env=dict(env), stdin=subprocess.DEVNULL,
            stdout=out, stderr=err, start_new_session=True,
        )
    if live is not None:
        live.add(child.pid)
    timed_out = False
    try:
        while True:
            pid, status, usage = os.wait4(child.pid, os.WNOHANG)
            if pid:
                break
            if time.monotonic() - started > seconds:
                timed_out = True
                _kill_group(child.pid)
                _, status, usage = os.wait4(child.pid, 0)
                break
            time.sleep(POLL_SECONDS)
    finally:
        if live is not None:
            live.discard(child.pid)
    _kill_group(child.pid)  # anything the child left running
    child.returncode = os.waitstatus_to_exitcode(status)
    return ChildOutcome(
        child.returncode, timed_out, time.monotonic() - started, usage.ru_maxrss,
        out_path.read_text(encoding="utf-8", errors="replace"),
        err_path.read_text(encoding="utf-8", errors="replace"),
    )
