"""The native loader's fast path (plain ground facts and constants lines read without the
tokenizer) gives the same problem as the wff parser, and leaves every mistake to it."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from strips_framework.errors import InputError
from strips_framework.formats import native
from strips_framework.formats.native import NativeLoader

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from robot_worlds import robot_world  # noqa: E402


def slow(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(native._Reader, "_plain_facts", lambda self, entry: False)
    monkeypatch.setattr(native._Reader, "_plain_constants", lambda self, entry: False)


def test_the_fast_path_reads_what_the_parser_reads(tmp_path: Path, monkeypatch) -> None:
    path = tmp_path / "world.strips"
    path.write_text(robot_world(3000) + "facts\n  HOLDS(BOX1, a), HOLDS( BOX2 ,b ), ONFLOOR\n")
    fast = NativeLoader().load(path)
    slow(monkeypatch)
    assert NativeLoader().load(path) == fast
    assert len(fast.facts) + len(fast.axioms) >= 3000


@pytest.mark.parametrize(
    ("extra", "where", "message"),
    [
        ("facts\n  AT(BOX1, nowhere)\n", (2, 12), "undeclared constant 'nowhere'"),
        ("facts\n  AT(BOX1)\n", (2, 3), "expected 2 arguments for AT (declared at"),
        ("facts\n  HOLDS(a), HOLDS(a, b)\n", (2, 13), "expected 1 argument for HOLDS (as first used at"),
        ("facts\n  NOTED(true)\n", (2, 9), "expected a term"),
        ("constants ROBOT\n", (1, 11), "constant 'ROBOT' is declared twice"),
        ("constants q1 q1\n", (1, 14), "constant 'q1' is declared twice"),
    ],
)
def test_mistakes_on_the_fast_path_are_reported_by_the_parser(tmp_path: Path, extra, where, message) -> None:
    world = robot_world(200)
    path = tmp_path / "world.strips"
    path.write_text(world + extra)
    with pytest.raises(InputError) as error:
        NativeLoader().load(path)
    first = world.count("\n")
    assert (error.value.line - first, error.value.column) == where
    assert message in error.value.message
