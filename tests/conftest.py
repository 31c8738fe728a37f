"""Shared fixtures: the installed plugins and a planner factory."""

from __future__ import annotations

import warnings

import pytest

from strips_framework.config import Config
from strips_framework.planner import Planner
from strips_framework.plugins import Registry


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
