"""Helpers for the bench's tests: matrix files in a temporary folder, results read back."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
PUSH_ONE_BOX = ROOT / "tests" / "data" / "push-one-box.strips"
THREE_BOXES = ROOT / "examples" / "three-boxes.strips"
FAKE_PLANNER = Path(__file__).resolve().parent / "fake_planner.py"


def fake(mode: str) -> str:
    """A matrix ``[configs.X]`` body running the fake planner in ``mode``."""
    command = ["{python}", str(FAKE_PLANNER), mode, "{problem}", "{plan}"]
    return f"command = {json.dumps(command)}"


@pytest.fixture
def write_matrix(tmp_path):
    def write(body: str, name: str = "matrix.toml") -> Path:
        path = tmp_path / name
        path.write_text(body, encoding="utf-8")
        return path

    return write


def read_rows(path: Path) -> list[dict]:
    return [json.loads(line) for line in path.read_text(encoding="utf-8").splitlines()]
