"""examples/configs/paper.toml says it writes out the defaults: it must choose what the
defaults choose, with every option of each component written out at its default."""

from __future__ import annotations

import tomllib
from pathlib import Path

from strips_framework.limits import Limits
from strips_framework.planner import Planner
from strips_framework.plugin.config import Config

PAPER = Path(__file__).resolve().parents[1] / "examples" / "configs" / "paper.toml"


def test_paper_toml_is_the_defaults_written_out():
    planner = Planner.create()
    written = Config.from_file(PAPER)
    data = tomllib.loads(PAPER.read_text())
    for kind in planner.kinds_used():
        registration = planner.registry.get(kind, planner.config.choice(kind).name)
        assert written.build(planner.registry, kind) == planner.config.build(planner.registry, kind)
        options = {name for name, default in registration.options() if default is not None}
        assert set(data[kind]) - {"name"} == options, f"[{kind}] does not write out every option"
    assert written.limits == Limits(expansions=None, memory=None)
