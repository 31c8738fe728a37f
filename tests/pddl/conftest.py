"""Fixtures for the PDDL tests: the hand-written domains in ``data/``."""

from __future__ import annotations

from pathlib import Path

import pytest

from strips_framework.pddl import PddlTask, load_task

DATA = Path(__file__).parent / "data"


@pytest.fixture
def load():
    def load(domain: str, problem: str) -> PddlTask:
        return load_task(DATA / domain, DATA / problem)

    return load


@pytest.fixture
def write(tmp_path):
    """Write a domain and a problem text to files and load them."""

    def write(domain: str, problem: str) -> PddlTask:
        (tmp_path / "domain.pddl").write_text(domain)
        (tmp_path / "problem.pddl").write_text(problem)
        return load_task(tmp_path / "domain.pddl", tmp_path / "problem.pddl")

    return write
