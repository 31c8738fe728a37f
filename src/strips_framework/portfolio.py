"""A portfolio: searches tried on one PDDL task, each within its share of the run's time
limit, until one finds a plan; in turn, or one of them beside the others in a second
process.

Why: on a task too large to ground, two searches that never ground are good at different
things. The paper's means-ends analysis works back from the goal and touches only what
the goal's proof needs, so a goal of three ``on`` atoms in a world of 1,900 blocks takes
it a few dozen nodes and a second, where a progression search (ours or Powerlifted) is
lost among a thousand towers; but it is incomplete, and where the goal interacts (the
organic-synthesis tasks, childsnack) it wanders until its limits. The lifted progression
search is complete and heuristic-guided. So the first gets a short slice, and the second
the rest, as Fast Downward's portfolios give their configurations slices of one limit.

Every stage searches with the run's own limits otherwise; the last one gets whatever time
the earlier ones left. A stage that cannot search the task at all (a PDDL feature the
world-model translation or its prover does not handle) is skipped, saying why.

A stage may instead run *beside* the stages after it, in a forked process, for its share
of the limit in CPU seconds. Why: run in turn, a slice costs its whole length wherever
that search finds nothing, and the lifted search solves most of the tasks in a fraction
of it (organic synthesis: 0.2-0.7 s after a 6 s means-ends slice). Beside, the two share
the processor (on one core each runs at half speed), so a task costs at most about twice
what the faster search needs, and a second core makes the pair free. The first plan wins:
the child writes its result to a file and exits, and the parent's SIGCHLD handler ends
its own search with :class:`_BesideSolved`. The price is that when both would find a plan
at about the same moment, which one is reported depends on timing; name a strategy in
the config for a run that is the same every time. A process that is watched (observers,
a progress line) runs its stages in turn: the watchers would not see the child.

A slice run in turn ends on time even inside a long proof attempt: the searches watch their clock
between nodes, but one resolution attempt on a large world model can run for seconds
(childsnack with 7 tables: 13 s in one attempt's equality inferences). So in the main
thread a slice is also an alarm that raises
:class:`~strips_framework.limits.LimitReached` wherever the stage is, as the CLI's alarm
does for the whole run; the CLI's own alarm is put back, with the time it had left, when
the slice ends.
"""

from __future__ import annotations

import os
import pickle
import signal
import sys
import tempfile
import threading
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager, suppress
from functools import partial
from pathlib import Path
from types import FrameType
from typing import TYPE_CHECKING, NoReturn, Protocol

from strips_framework.errors import StripsError
from strips_framework.limits import Clock, LimitReached
from strips_framework.records import Record
from strips_framework.result import Status

if TYPE_CHECKING:
    from strips_framework.pddl import PddlTask
    from strips_framework.plugin.config import Config
    from strips_framework.result import Result


class PddlSearch(Protocol):
    """What a stage runs: a :class:`~strips_framework.planner.Planner` whose config names
    its strategy (the facade imports this module, not the other way round)."""

    @property
    def config(self) -> Config: ...

    def solve_pddl(
        self,
        pddl: PddlTask,
        clock: Clock | None = None,
        parse_seconds: float = 0.0,
        library: Path | None = None,
    ) -> Result: ...


class Stage(Record):
    """One search of a portfolio: a checked planner, the share of the run's time limit it
    may use (``None``: what the earlier stages left), and whether it runs beside the
    stages after it (in a second process, for its share in CPU seconds) rather than
    before them. A stage runs in turn where a second process cannot be made or
    watched (no ``fork``, or other threads running: see :func:`_can_fork`)."""

    planner: PddlSearch
    share: float | None
    beside: bool

    __slots__ = ("beside", "planner", "share")

    def __init__(
        self, planner: PddlSearch, share: float | None = None, beside: bool = False
    ) -> None:
        if share is not None and not 0.0 < share <= 1.0:
            raise ValueError(f"a stage's share of the time limit is in (0, 1], not {share}")
        if beside and share is None:
            raise ValueError(
                "a stage that runs beside the others needs its share of the time limit"
            )
        self.planner = planner
        self.share = share
        self.beside = beside

    @property
    def name(self) -> str:
        return self.planner.config.choices["strategy"].name


class Portfolio(Record):
    """Stages tried in order (see the module docstring); the last takes what is left."""

    stages: tuple[Stage, ...]

    __slots__ = ("stages",)

    def __init__(self, stages: tuple[Stage, ...]) -> None:
        if not stages:
            raise ValueError("a portfolio needs at least one stage")
        if stages[-1].beside:
            raise ValueError("the last stage of a portfolio has no stage to run beside")
        self.stages = tuple(stages)

    def solve_pddl(
        self,
        pddl: PddlTask,
        clock: Clock | None = None,
        parse_seconds: float = 0.0,
        library: Path | None = None,
    ) -> Result:
        """The first plan any stage finds; else the last stage's result. The plan's result
        keeps its own search's statistics, and its time is the whole run's. Progress
        lines go to stderr (``strips: ...``), as the choice of search does."""
        clock = clock or Clock(self.stages[-1].planner.config.limits.time)
        besides: list[_Beside] = []
        try:
            with _watching(besides):
                result = self._run(pddl, clock, parse_seconds, library, besides)
                if result.status not in (Status.SOLVED, Status.INTERRUPTED, Status.UNSOLVABLE):
                    # The last stage gave up early (a limit of its own, memory): a search
                    # beside it may still find a plan in the time the run has left.
                    _wait(besides, clock)
        except _BesideSolved as solved:
            _say(f"{solved.name} found a plan in its second process")
            return solved.result._replace(seconds=clock.elapsed())
        finally:
            for beside in besides:
                beside.stop()
        return result

    def _run(
        self,
        pddl: PddlTask,
        clock: Clock,
        parse_seconds: float,
        library: Path | None,
        besides: list[_Beside],
    ) -> Result:
        *first, last = self.stages
        for stage, following in zip(first, self.stages[1:], strict=True):
            remaining = clock.seconds - clock.elapsed()
            seconds = min(remaining, clock.seconds * (stage.share or 1.0))
            if seconds <= 0.0:
                break
            if stage.beside and _can_fork():
                besides.append(
                    _Beside.start(stage, pddl, seconds, remaining, parse_seconds, library)
                )
                _say(
                    f"{stage.name} runs beside {following.name} in a second process, for at most "
                    f"{seconds:.1f} s of CPU"
                )
                _check(besides)  # it may have ended before the handler was there to hear it
                continue
            since = clock.elapsed()
            result: Result | None = None
            try:
                with _slice(seconds):
                    result = stage.planner.solve_pddl(
                        pddl, Clock(seconds), parse_seconds=parse_seconds, library=library
                    )
            except StripsError as error:
                _say(
                    f"{stage.name} cannot search this task ({error}); continuing with {following.name}"
                )
                continue
            except LimitReached:  # the slice's alarm outside the search (reading, translating)
                pass
            if result is not None and result.status in (Status.SOLVED, Status.INTERRUPTED):
                return result._replace(seconds=clock.elapsed())
            status = Status.TIME_LIMIT if result is None else result.status
            _say(
                f"{stage.name} stopped ({status} after {clock.elapsed() - since:.1f} s of "
                f"{seconds:.1f}); continuing with {following.name}"
            )
        return last.planner.solve_pddl(pddl, clock, parse_seconds=parse_seconds, library=library)


class _BesideSolved(BaseException):
    """Raised in the parent, wherever its own search is, when a stage beside it has found
    a plan. A :class:`BaseException`, as :class:`LimitReached` is: no ``except
    Exception`` in a search or plugin may take it for an error of its own."""

    def __init__(self, name: str, result: Result) -> None:
        super().__init__(name)
        self.name = name
        self.result = result


class _Beside:
    """A stage running in a forked child. The child searches under a CPU-time alarm
    (``ITIMER_PROF``: its share is processor time, so it costs the stages beside it no
    more than that however the two are scheduled), writes a result with a plan to
    ``path`` and exits with 0; it exits with 1 having found none."""

    def __init__(self, name: str, pid: int, path: str) -> None:
        self.name = name
        self.pid = pid
        self.path = path
        #: The child's exit status once it has been waited for (its pid is then free
        #: for the system to reuse, and is never signalled again).
        self.exit_code: int | None = None

    @classmethod
    def start(
        cls,
        stage: Stage,
        pddl: PddlTask,
        cpu_seconds: float,
        wall_seconds: float,
        parse_seconds: float,
        library: Path | None,
    ) -> _Beside:
        handle, path = tempfile.mkstemp(prefix="strips-beside-", suffix=".pickle")
        os.close(handle)
        search = partial(
            stage.planner.solve_pddl,
            pddl,
            Clock(wall_seconds),
            parse_seconds=parse_seconds,
            library=library,
        )
        sys.stdout.flush()
        sys.stderr.flush()
        pid = os.fork()
        if pid == 0:  # pragma: no cover - the child (its effects are tested, not its lines)
            _child(stage.name, search, cpu_seconds, path)
        return cls(stage.name, pid, path)

    def poll(self) -> Result | None:
        """The child's result if it has ended with a plan; None while it runs or when it
        ended without one."""
        if self.exit_code is None:
            pid, status = os.waitpid(self.pid, os.WNOHANG)
            if pid == 0:
                return None
            self.exit_code = os.waitstatus_to_exitcode(status)
            if self.exit_code == 0:
                try:
                    with open(self.path, "rb") as file:
                        result: Result = pickle.load(file)
                except (OSError, EOFError, pickle.UnpicklingError):
                    return None  # a file that could not be written whole: no plan here
                return result
        return None

    @property
    def running(self) -> bool:
        return self.exit_code is None

    def stop(self) -> None:
        """Kill the child if it still runs, wait for it, and remove its file."""
        if self.exit_code is None:
            os.kill(self.pid, signal.SIGKILL)
            _, status = os.waitpid(self.pid, 0)
            self.exit_code = os.waitstatus_to_exitcode(status)
        with suppress(FileNotFoundError):
            os.unlink(self.path)


def _child(
    name: str, search: Callable[[], Result], cpu_seconds: float, path: str
) -> NoReturn:  # pragma: no cover - runs in the forked child
    """The forked child's whole life: it never returns into the parent's code (no
    ``finally`` of the parent's, no test runner), whatever happens."""
    code = 1
    try:
        signal.signal(signal.SIGCHLD, signal.SIG_DFL)
        signal.signal(signal.SIGALRM, signal.SIG_DFL)
        signal.signal(signal.SIGPROF, _end_of_slice)
        signal.setitimer(signal.ITIMER_PROF, cpu_seconds)
        try:
            result = search()
        except StripsError as error:
            _say(f"{name} cannot search this task ({error})")
        except LimitReached:
            _say(f"{name} stopped ({Status.TIME_LIMIT} after {cpu_seconds:.1f} s of CPU)")
        else:
            signal.setitimer(signal.ITIMER_PROF, 0)
            if result.status == Status.SOLVED:
                _write(result, path)
                code = 0
            elif result.status != Status.INTERRUPTED:
                _say(f"{name} stopped ({result.status}, in its second process)")
    except BaseException:  # noqa: BLE001 - Ctrl-C or a kill: the child just ends, quietly
        code = 1
    finally:
        with suppress(BaseException):
            sys.stdout.flush()
            sys.stderr.flush()
        os._exit(code)


def _write(result: Result, path: str) -> None:
    """The result, pickled; without its search tree if the tree will not pickle."""
    try:
        data = pickle.dumps(result)
    except (pickle.PicklingError, TypeError, AttributeError):
        data = pickle.dumps(result._replace(tree=None))
    with open(path, "wb") as file:
        file.write(data)


def _can_fork() -> bool:
    """Whether a child can be forked and watched: a platform with ``fork``, and only the
    main thread running (signals reach no other, and a fork copies a lock another thread
    holds, as a notebook's output threads do, held for ever in the child)."""
    return hasattr(os, "fork") and hasattr(signal, "SIGCHLD") and threading.active_count() == 1


def _check(besides: list[_Beside]) -> None:
    """Raise :class:`_BesideSolved` if a child has ended with a plan. SIGCHLD is held
    back meanwhile: its handler calls this too, and must not wait for a child this call
    has already waited for (whose status would then be lost)."""
    held = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGCHLD})
    try:
        for beside in besides:
            result = beside.poll()
            if result is not None:
                raise _BesideSolved(beside.name, result)
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, held)


def _wait(besides: list[_Beside], clock: Clock) -> None:
    """Until every child has ended or the clock runs out (the SIGCHLD handler raises
    when one ends with a plan)."""
    while any(beside.running for beside in besides) and clock.elapsed() < clock.seconds:
        _check(besides)
        time.sleep(0.01)


@contextmanager
def _watching(besides: list[_Beside]) -> Iterator[None]:
    """A SIGCHLD handler that raises :class:`_BesideSolved` when a child in ``besides``
    has ended with a plan (other children, a prover's say, are not waited for here)."""
    if not _can_fork():
        yield
        return

    def ended(signum: int, frame: FrameType | None) -> None:
        _check(besides)

    outer = signal.signal(signal.SIGCHLD, ended)
    try:
        yield
    finally:
        signal.signal(signal.SIGCHLD, signal.SIG_DFL if outer is None else outer)


@contextmanager
def _slice(seconds: float) -> Iterator[None]:
    """An alarm that raises :class:`LimitReached` once ``seconds`` from now, in the main
    thread (signals reach no other); the alarm that was set before, if any, gets its
    handler back and the time it had left (at least a moment, so that a deadline that
    passed during the slice still rings)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    outer_handler = signal.getsignal(signal.SIGALRM)
    outer_delay, outer_interval = signal.getitimer(signal.ITIMER_REAL)
    started = time.perf_counter()
    signal.signal(signal.SIGALRM, _end_of_slice)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        # None: the handler was set outside Python, which cannot be put back; the
        # default then, as before any handler was set.
        signal.signal(signal.SIGALRM, signal.SIG_DFL if outer_handler is None else outer_handler)
        if outer_delay > 0:
            left = max(outer_delay - (time.perf_counter() - started), 1e-3)
            signal.setitimer(signal.ITIMER_REAL, left, outer_interval)


def _end_of_slice(signum: int, frame: FrameType | None) -> None:
    raise LimitReached(Status.TIME_LIMIT)


def _say(line: str) -> None:
    print(f"strips: {line}", file=sys.stderr)
