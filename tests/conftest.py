"""Shared fixtures: the installed plugins, a planner factory, and PDDL tasks (the
hand-written domains in ``pddl/data``, or domain and problem texts)."""

from __future__ import annotations

import warnings
from pathlib import Path

import pytest

from strips_framework.pddl import PddlTask, load_task
from strips_framework.planner import Planner
from strips_framework.plugin.config import Config
from strips_framework.plugin.registry import Registry

PDDL_DATA = Path(__file__).parent / "pddl" / "data"


@pytest.fixture(scope="session")
def registry() -> Registry:
    return Registry.from_plugins()


@pytest.fixture(scope="session")
def make_planner(registry):
    def make(**choices: object) -> Planner:
        """A planner with ``strategy=..., evaluator=..., limits={...}`` and the like."""
        return Planner(registry, Config.from_dict(dict(choices)))

    return make


@pytest.fixture(autouse=True)
def _quiet_admissibility_warnings():
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", message=".* needs an evaluator with 'admissible'")
        yield


@pytest.fixture
def load():
    """Load a domain and a problem of ``pddl/data`` by file name."""

    def load(domain: str, problem: str) -> PddlTask:
        return load_task(PDDL_DATA / domain, PDDL_DATA / problem)

    return load


@pytest.fixture
def write_task(tmp_path):
    """Write a domain and a problem text to files and load them."""

    def write(domain: str, problem: str) -> PddlTask:
        (tmp_path / "domain.pddl").write_text(domain)
        (tmp_path / "problem.pddl").write_text(problem)
        return load_task(tmp_path / "domain.pddl", tmp_path / "problem.pddl")

    return write
