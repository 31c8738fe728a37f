"""The plugins' packaging: each pins the core's version range, since each imports the
core's internals (a new minor version of the core may move them)."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest
from packaging.requirements import Requirement

from strips_framework import __version__

ROOT = Path(__file__).resolve().parents[1]
PLUGINS = sorted([*ROOT.glob("plugins/*/pyproject.toml"), ROOT / "examples/plugins/pyproject.toml"])


@pytest.mark.parametrize("pyproject", PLUGINS, ids=lambda p: p.parent.name)
def test_plugin_pins_a_core_version_range_holding_this_core(pyproject: Path) -> None:
    dependencies = tomllib.loads(pyproject.read_text())["project"]["dependencies"]
    core = [r for r in map(Requirement, dependencies) if r.name == "strips-framework"]
    assert len(core) == 1, f"{pyproject}: no strips-framework dependency"
    specifier = core[0].specifier
    assert __version__ in specifier, f"{pyproject}: {specifier} excludes the core {__version__}"
    assert any(s.operator in ("<", "<=", "~=", "==") for s in specifier), (
        f"{pyproject}: {specifier or 'no version'} has no upper bound"
    )
