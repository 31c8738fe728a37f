"""A sequential portfolio: searches tried in turn on one PDDL task, each within its share
of the run's time limit, until one finds a plan.

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

A slice ends on time even inside a long proof attempt: the searches watch their clock
between nodes, but one resolution attempt on a large world model can run for seconds
(childsnack with 7 tables: 13 s in one attempt's equality inferences). So in the main
thread a slice is also an alarm that raises
:class:`~strips_framework.limits.LimitReached` wherever the stage is, as the CLI's alarm
does for the whole run; the CLI's own alarm is put back, with the time it had left, when
the slice ends.
"""

from __future__ import annotations

import signal
import sys
import threading
import time
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from types import FrameType
from typing import TYPE_CHECKING, Protocol

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
    """One search of a portfolio: a checked planner, and the share of the run's time limit
    it may use (``None``: what the earlier stages left)."""

    planner: PddlSearch
    share: float | None

    __slots__ = ("planner", "share")

    def __init__(self, planner: PddlSearch, share: float | None = None) -> None:
        if share is not None and not 0.0 < share <= 1.0:
            raise ValueError(f"a stage's share of the time limit is in (0, 1], not {share}")
        self.planner = planner
        self.share = share

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
        self.stages = tuple(stages)

    def solve_pddl(
        self,
        pddl: PddlTask,
        clock: Clock | None = None,
        parse_seconds: float = 0.0,
        library: Path | None = None,
    ) -> Result:
        """The first stage's plan, else the next one's, ...; the last stage's result when
        none finds one. The plan's result keeps its own search's statistics, and its time
        is the whole run's. Progress lines go to stderr (``strips: ...``), as the choice of
        search does."""
        *first, last = self.stages
        clock = clock or Clock(last.planner.config.limits.time)
        for stage, following in zip(first, self.stages[1:], strict=True):
            remaining = clock.seconds - clock.elapsed()
            seconds = min(remaining, clock.seconds * (stage.share or 1.0))
            if seconds <= 0.0:
                break
            since = clock.elapsed()
            result: Result | None = None
            try:
                with _slice(seconds):
                    result = stage.planner.solve_pddl(
                        pddl, Clock(seconds), parse_seconds=parse_seconds, library=library
                    )
            except StripsError as error:
                _say(f"{stage.name} cannot search this task ({error}); continuing with {following.name}")
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
