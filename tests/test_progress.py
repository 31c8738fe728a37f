"""A long search shows its progress on stderr when stderr is a terminal: scores counted,
the best so far, the time; nothing when it is not."""

from __future__ import annotations

import io
import re
import time
from pathlib import Path


from strips_framework.cli.main import main
from strips_framework.planner import Planner
from strips_framework.progress import Progress

ROOT = Path(__file__).resolve().parents[1]
FIVE_GOALS = ROOT / "examples" / "robot-world" / "five-goals.strips"
BLOCKS = ROOT / "examples" / "pddl" / "blocksworld" / "p4.pddl"
LINE = re.compile(r"\rstrips: (\d+) (states evaluated|nodes scored), best ([-\d.e+]+), [\d.]+ s")


class _Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def _solve_on_a_terminal(monkeypatch, *args: str) -> str:
    monkeypatch.setattr("strips_framework.progress.INTERVAL", 0.001)
    terminal = _Terminal()
    monkeypatch.setattr("sys.stderr", terminal)
    assert main(["solve", *args]) == 0
    return terminal.getvalue()


def test_world_model_search_shows_nodes_scored(monkeypatch):
    shown = LINE.findall(_solve_on_a_terminal(monkeypatch, str(FIVE_GOALS)))
    assert shown and all(kind == "nodes scored" for _, kind, _ in shown)
    counts = [int(count) for count, _, _ in shown]
    assert counts == sorted(counts) and counts[-1] > 0


def test_forward_search_counts_states_evaluated_and_the_best_estimate():
    progress = Progress(io.StringIO())
    planner = Planner.create({"strategy": "astar", "heuristic": "lmcut"})._replace(
        progress=progress
    )
    result = planner.run(BLOCKS)
    assert result.solved and progress.what == "states evaluated"
    assert progress.scored >= result.statistics.evaluated > 0
    assert progress.best == 0  # A* evaluates the goal state it reaches
    assert LINE.match("\r" + progress.line())


def test_the_line_is_shown_every_interval_while_entered():
    stream = io.StringIO()
    progress = Progress(stream, interval=0.001)
    with progress:
        progress.note(7.0)
        progress.note(3.0)
        deadline = time.monotonic() + 10
        while not stream.getvalue() and time.monotonic() < deadline:
            time.sleep(0.01)
    shown = LINE.findall(stream.getvalue())
    assert shown and shown[-1][0] == "2" and shown[-1][2] == "3"
    assert stream.getvalue().endswith("\n")  # the line is ended when the search is


def test_no_progress_when_stderr_is_not_a_terminal(capsys):
    assert main(["solve", str(FIVE_GOALS)]) == 0
    assert "strips: " not in capsys.readouterr().err


def test_an_evaluator_prepared_per_problem_is_counted_too():
    """relaxed-plan scores only once prepared for the problem (``for_problem``): the
    counting wrapper prepares it and still counts (it used to hand the search the
    unprepared evaluator, which refuses to score)."""
    progress = Progress(io.StringIO())
    planner = Planner.create({"evaluator": "relaxed-plan"})._replace(progress=progress)
    result = planner.run(ROOT / "examples" / "robot-world" / "light.strips")
    assert result.solved and progress.scored > 0
