"""A long search shows its progress on stderr when stderr is a terminal: scores counted,
the best so far, the time; nothing when it is not."""

from __future__ import annotations

import io
import re
from pathlib import Path

from strips_framework.cli import main

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


def test_forward_search_shows_states_evaluated(monkeypatch):
    config = ROOT / "examples" / "configs" / "optimal-pddl.toml"
    shown = LINE.findall(_solve_on_a_terminal(monkeypatch, str(BLOCKS), "--config", str(config)))
    assert shown and all(kind == "states evaluated" for _, kind, _ in shown)


def test_no_progress_when_stderr_is_not_a_terminal(capsys):
    assert main(["solve", str(FIVE_GOALS)]) == 0
    assert "strips: " not in capsys.readouterr().err
