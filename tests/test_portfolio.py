"""The portfolio of a task too large to ground (strips_framework.portfolio): means-ends
analysis for a share of the time limit, in turn or beside the lifted search."""

from __future__ import annotations

import os
import signal
import time
from pathlib import Path
from typing import Any

import pytest

from strips_framework import portfolio
from strips_framework.errors import InputError
from strips_framework.limits import Clock
from strips_framework.pddl import parse_task
from strips_framework.planner import Planner
from strips_framework.portfolio import Portfolio, Stage
from strips_framework.result import Status

EXAMPLES = Path(__file__).resolve().parents[1] / "examples" / "pddl"


def _blocks_task(count: int, goal: str) -> Any:
    names = " ".join(f"b{i}" for i in range(count))
    init = " ".join(f"(ontable b{i}) (clear b{i})" for i in range(count))
    problem = f"""(define (problem blocks{count}) (:domain blocksworld) (:objects {names} - block)
 (:init (handempty) {init}) (:goal {goal}))"""
    return parse_task((EXAMPLES / "blocksworld" / "domain.pddl").read_text(), problem)


class _Config:
    def __init__(self, name: str) -> None:
        self.choices = {"strategy": type("Choice", (), {"name": name})()}


class _Scripted:
    """A stand-in planner: ``solve_pddl`` runs ``act`` and records the clock it got."""

    def __init__(self, name: str, act: Any) -> None:
        self.config = _Config(name)
        self.act = act
        self.clocks: list[Clock] = []

    def solve_pddl(self, pddl: Any, clock: Clock, parse_seconds: float = 0.0, library: Any = None) -> Any:
        self.clocks.append(clock)
        return self.act()


class _Ended:
    """A stand-in result: how a stage ended (picklable, as a stage beside the others
    hands its result over in a file)."""

    def __init__(self, status: Status, plan: tuple[str, ...] | None = None) -> None:
        self.status = status
        self.plan = plan

    def _replace(self, **changes: Any) -> _Ended:
        return self


@pytest.fixture
def alone(monkeypatch: pytest.MonkeyPatch) -> None:
    """The side-by-side tests run as if this were the process's only thread: threads an
    earlier test left behind (a Dask client keeps its own for the life of the process)
    would otherwise make every portfolio here run its stages in turn."""
    monkeypatch.setattr(portfolio.threading, "active_count", lambda: 1)


#: The last stage's result in the tests that only follow which stage's result comes back.
_LAST = _Ended(Status.TIME_LIMIT)


def test_a_stage_that_finds_no_plan_hands_the_task_to_the_next(capsys: pytest.CaptureFixture[str]) -> None:
    """Means-ends allowed one node stops at the node limit; lazy greedy lifted search,
    the last stage, then solves the task."""
    task = _blocks_task(4, "(and (on b1 b0) (on b2 b1))")
    means_ends = Planner.create({"strategy": "means-ends", "limits": {"nodes": 1}})
    lifted = Planner.create({"strategy": "lifted-gbfs"})
    result = Portfolio((Stage(means_ends, 0.5), Stage(lifted))).solve_pddl(task)
    assert result.status == Status.SOLVED
    assert result.statistics.family == "lifted"
    assert "strips: means-ends stopped (node-limit after" in capsys.readouterr().err


def test_the_first_plan_found_ends_the_portfolio() -> None:
    task = _blocks_task(4, "(and (on b1 b0))")
    means_ends = Planner.create({"strategy": "means-ends"})
    last = _Scripted("never", lambda: pytest.fail("the last stage ran after a plan was found"))
    result = Portfolio((Stage(means_ends, 0.5), Stage(last))).solve_pddl(task, Clock(60.0))  # type: ignore[arg-type]
    assert result.status == Status.SOLVED
    assert result.plan == ("(pick-up b1)", "(stack b1 b0)")
    assert result.statistics.family == "world-model"


def test_a_stage_gets_its_share_of_the_limit_and_the_last_what_is_left() -> None:
    first = _Scripted("first", lambda: _Ended(Status.TIME_LIMIT))
    last = _Scripted("last", lambda: _Ended(Status.TIME_LIMIT))
    clock = Clock(40.0)
    Portfolio((Stage(first, 0.25), Stage(last))).solve_pddl(None, clock)  # type: ignore[arg-type]
    assert first.clocks[0].seconds == pytest.approx(10.0, abs=0.1)
    assert last.clocks == [clock]


def test_a_stage_that_cannot_search_the_task_is_skipped_saying_why(
    capsys: pytest.CaptureFixture[str],
) -> None:
    def refuse() -> Any:
        raise InputError("t.pddl", 3, None, "a feature this search does not handle")

    first = _Scripted("first", refuse)
    last = _Scripted("last", lambda: _LAST)
    result = Portfolio((Stage(first, 0.5), Stage(last))).solve_pddl(None, Clock(10.0))  # type: ignore[arg-type]
    assert result is _LAST
    err = capsys.readouterr().err
    assert "strips: first cannot search this task (" in err
    assert "a feature this search does not handle" in err and "continuing with last" in err


def test_a_slice_ends_on_time_inside_a_long_step_and_the_outer_alarm_comes_back() -> None:
    """A stage busy in one step that never looks at its clock (a long proof attempt) is
    stopped by the slice's alarm; the alarm that was set before (the CLI's, for the whole
    run) keeps its handler and the rest of its time."""
    steps: list[int] = []

    def busy() -> Any:
        for step in range(1000):  # 10 s unless the slice's alarm stops it
            time.sleep(0.01)
            steps.append(step)
        return "finished the long step"

    rings: list[int] = []
    outer = signal.signal(signal.SIGALRM, lambda signum, frame: rings.append(signum))
    signal.setitimer(signal.ITIMER_REAL, 100.0)
    try:
        first = _Scripted("busy", busy)
        last = _Scripted("last", lambda: _LAST)
        result = Portfolio((Stage(first, 0.01), Stage(last))).solve_pddl(None, Clock(10.0))  # type: ignore[arg-type]
        handler_after = signal.getsignal(signal.SIGALRM)
        left, _ = signal.getitimer(signal.ITIMER_REAL)
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, outer)
    assert result is _LAST
    assert len(steps) < 1000
    assert handler_after is not None and handler_after not in (signal.SIG_DFL, signal.SIG_IGN)
    assert handler_after.__name__ == "<lambda>"
    assert 90.0 < left <= 100.0
    assert rings == []


def test_a_slice_after_a_handler_set_outside_python_leaves_the_default(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """``signal.getsignal`` says None for a handler Python did not set; the slice cannot
    put that back, and leaves the default rather than failing."""
    monkeypatch.setattr(signal, "getsignal", lambda signum: None)
    first = _Scripted("first", lambda: _Ended(Status.TIME_LIMIT))
    last = _Scripted("last", lambda: _LAST)
    before = signal.signal(signal.SIGALRM, signal.SIG_IGN)
    try:
        result = Portfolio((Stage(first, 0.5), Stage(last))).solve_pddl(None, Clock(10.0))  # type: ignore[arg-type]
        after = signal.signal(signal.SIGALRM, before)
    finally:
        signal.signal(signal.SIGALRM, before)
    assert result is _LAST
    assert after is signal.SIG_DFL


def test_an_interrupted_stage_ends_the_portfolio() -> None:
    first = _Scripted("first", lambda: _Ended(Status.INTERRUPTED))
    last = _Scripted("last", lambda: pytest.fail("ran after Ctrl-C"))
    result = Portfolio((Stage(first, 0.5), Stage(last))).solve_pddl(None, Clock(10.0))  # type: ignore[arg-type]
    assert result.status == Status.INTERRUPTED


def test_a_task_too_large_to_ground_gets_means_ends_beside_the_lifted_search_and_says_so(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch,
    alone: None,
) -> None:
    from strips_framework.cli.main import main
    from strips_framework.lifted import estimate

    monkeypatch.setattr(estimate, "CHEAP_GROUNDING", 10)
    problem = tmp_path / "problem.pddl"
    problem.write_text((EXAMPLES / "blocksworld" / "p4.pddl").read_text())
    assert main(["solve", str(EXAMPLES / "blocksworld" / "domain.pddl"), str(problem), "--json"]) == 0
    err = capsys.readouterr().err
    assert "strips: strategy means-ends and lifted-alt-bfws: grounding looks expensive" in err
    assert "means-ends beside it, for at most 10% of the time limit in CPU" in err
    assert "strips: means-ends runs beside lifted-alt-bfws in a second process" in err


def test_means_ends_runs_beside_unless_something_in_this_process_watches_the_search() -> None:
    """An observer or the progress line would not see a search in a second process."""
    planner = Planner.create()
    stage = planner._means_ends_stage()
    assert stage is not None and stage.beside
    watched = planner._replace(observers=(object(),))._means_ends_stage()
    assert watched is not None and not watched.beside
    shown = planner._replace(progress=object())._means_ends_stage()
    assert shown is not None and not shown.beside


class _Started:
    """The children a portfolio starts, recorded (by wrapping ``_Beside.start``)."""

    def __init__(self, monkeypatch: pytest.MonkeyPatch) -> None:
        self.children: list[Any] = []
        start = portfolio._Beside.start

        def recorded(*args: Any) -> Any:
            child = start(*args)
            self.children.append(child)
            return child

        monkeypatch.setattr(portfolio._Beside, "start", staticmethod(recorded))


def _spin() -> Any:
    """A search that never ends by itself (CPU-bound, so a CPU-time alarm ends it)."""
    while True:
        sum(range(1000))


def test_a_plan_found_beside_ends_the_search_in_the_parent(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str],
    alone: None,
) -> None:
    started = _Started(monkeypatch)
    steps: list[int] = []

    def busy() -> Any:
        for step in range(2000):  # 20 s unless the child's plan stops it
            time.sleep(0.01)
            steps.append(step)
        return _Ended(Status.TIME_LIMIT)

    first = _Scripted("first", lambda: _Ended(Status.SOLVED, ("(a)",)))
    last = _Scripted("last", busy)
    result = Portfolio((Stage(first, 0.5, beside=True), Stage(last))).solve_pddl(None, Clock(30.0))  # type: ignore[arg-type]
    assert result.status == Status.SOLVED and result.plan == ("(a)",)
    assert first.clocks == []  # it searched in the child, not here
    assert len(steps) < 2000
    assert [child.exit_code for child in started.children] == [0]
    assert not Path(started.children[0].path).exists()
    assert "strips: first found a plan in its second process" in capsys.readouterr().err


def test_a_plan_found_in_the_parent_first_kills_the_search_beside_it(
    monkeypatch: pytest.MonkeyPatch,
    alone: None,
) -> None:
    started = _Started(monkeypatch)
    first = _Scripted("first", _spin)
    last = _Scripted("last", lambda: _Ended(Status.SOLVED, ("(b)",)))
    result = Portfolio((Stage(first, 0.5, beside=True), Stage(last))).solve_pddl(None, Clock(30.0))  # type: ignore[arg-type]
    assert result.plan == ("(b)",)
    assert [child.exit_code for child in started.children] == [-signal.SIGKILL]
    with pytest.raises(ChildProcessError):  # waited for: no zombie left behind
        os.waitpid(started.children[0].pid, os.WNOHANG)


def test_a_search_beside_ends_at_its_share_of_cpu_time(monkeypatch: pytest.MonkeyPatch, alone: None) -> None:
    """The last stage gives up early (its own limit), so the portfolio waits for the
    child; the child, spinning, is ended by its CPU-time alarm after 0.1 s of CPU and
    exits by itself (1: no plan), long before the run's 30 s would have it killed."""
    started = _Started(monkeypatch)
    first = _Scripted("first", _spin)
    last = _Scripted("last", lambda: _Ended(Status.MEMORY_LIMIT))
    result = Portfolio((Stage(first, 0.1 / 30.0, beside=True), Stage(last))).solve_pddl(None, Clock(30.0))  # type: ignore[arg-type]
    assert result.status == Status.MEMORY_LIMIT
    assert [child.exit_code for child in started.children] == [1]


def test_when_the_last_stage_gives_up_early_a_plan_found_beside_still_counts(alone: None) -> None:
    def later() -> Any:
        time.sleep(0.2)
        return _Ended(Status.SOLVED, ("(c)",))

    first = _Scripted("first", later)
    last = _Scripted("last", lambda: _Ended(Status.NODE_LIMIT))
    result = Portfolio((Stage(first, 0.5, beside=True), Stage(last))).solve_pddl(None, Clock(30.0))  # type: ignore[arg-type]
    assert result.plan == ("(c)",)


def test_while_another_thread_runs_a_stage_beside_runs_in_turn() -> None:
    """A fork would copy the locks the other thread holds (held for ever in the child)."""
    import threading

    stop = threading.Event()
    other = threading.Thread(target=stop.wait)
    other.start()
    try:
        first = _Scripted("first", lambda: _Ended(Status.TIME_LIMIT))
        last = _Scripted("last", lambda: _LAST)
        result = Portfolio((Stage(first, 0.5, beside=True), Stage(last))).solve_pddl(None, Clock(10.0))  # type: ignore[arg-type]
    finally:
        stop.set()
        other.join()
    assert result is _LAST
    assert len(first.clocks) == 1  # it ran here, in turn


def test_outside_the_main_thread_a_stage_beside_runs_in_turn() -> None:
    """Signals reach only the main thread, so no child can be watched from another."""
    import threading

    first = _Scripted("first", lambda: _Ended(Status.TIME_LIMIT))
    last = _Scripted("last", lambda: _LAST)
    results: list[Any] = []
    thread = threading.Thread(
        target=lambda: results.append(
            Portfolio((Stage(first, 0.5, beside=True), Stage(last))).solve_pddl(None, Clock(10.0))  # type: ignore[arg-type]
        )
    )
    thread.start()
    thread.join()
    assert results == [_LAST]
    assert len(first.clocks) == 1  # it ran here, in turn


def test_stage_shares_are_checked() -> None:
    planner = Planner.create({"strategy": "means-ends"})
    for share in (0.0, 1.5, -0.1):
        with pytest.raises(ValueError, match="share of the time limit"):
            Stage(planner, share)
    with pytest.raises(ValueError, match="at least one stage"):
        Portfolio(())
    with pytest.raises(ValueError, match="needs its share"):
        Stage(planner, beside=True)
    with pytest.raises(ValueError, match="no stage to run beside"):
        Portfolio((Stage(planner), Stage(planner, 0.5, beside=True)))


def test_a_result_file_that_cannot_be_read_is_no_plan(monkeypatch: pytest.MonkeyPatch, alone: None) -> None:
    """The child said it found a plan but its file holds none (a full disk, say): the
    parent's search goes on, rather than failing on the file in the middle of it."""

    def nothing(result: Any, path: str) -> None:
        Path(path).write_bytes(b"")

    monkeypatch.setattr(portfolio, "_write", nothing)

    def slow() -> Any:
        time.sleep(0.3)
        return _LAST

    first = _Scripted("first", lambda: _Ended(Status.SOLVED, ("(a)",)))
    last = _Scripted("last", slow)
    result = Portfolio((Stage(first, 0.5, beside=True), Stage(last))).solve_pddl(None, Clock(30.0))  # type: ignore[arg-type]
    assert result is _LAST
