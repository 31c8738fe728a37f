"""Fixtures for the grounding tests: tasks from the PDDL test data and the IPC suite."""

from __future__ import annotations

from pathlib import Path

import pytest

from strips_framework.pddl import PddlTask, load_task

DATA = Path(__file__).parents[1] / "pddl" / "data"


@pytest.fixture
def load():
    def load(domain: str, problem: str) -> PddlTask:
        return load_task(DATA / domain, DATA / problem)

    return load


@pytest.fixture
def write_task(tmp_path):
    """Load a domain and a problem given as text."""

    def write(domain: str, problem: str) -> PddlTask:
        (tmp_path / "domain.pddl").write_text(domain)
        (tmp_path / "problem.pddl").write_text(problem)
        return load_task(tmp_path / "domain.pddl", tmp_path / "problem.pddl")

    return write
