"""README's layout block says what is where: every entry it names exists, and every
module and subpackage of the core and every plugin distribution is in it."""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
BLOCK = (ROOT / "README.md").read_text().split("## Layout", 1)[1].split("```", 2)[1]
CORE, REST = BLOCK.split("\nplugins/\n", 1)
PLUGINS = REST.split("\nbenchmarks/", 1)[0]
PACKAGE = ROOT / "src" / "strips_framework"


def _entries(text: str) -> list[str]:
    """The names that start the block's two-space-indented lines (``a.py, b.py`` lists
    count each)."""
    names = []
    for listed in re.findall(r"^  ((?:[\w.]+/?, )*[\w.]+/?)", text, re.M):
        names += listed.split(", ")
    return names


def test_every_entry_exists():
    for name in _entries(CORE):
        assert (PACKAGE / name.rstrip("/")).exists(), f"README's layout names {name}: no such file"
    for name in _entries(PLUGINS):
        assert (ROOT / "plugins" / name.rstrip("/")).is_dir(), f"README names plugins/{name}"


def test_every_module_and_plugin_is_in_the_block():
    mentioned = set(re.findall(r"[\w]+(?:\.py|/)", CORE))
    for path in PACKAGE.iterdir():
        if path.name in ("__init__.py", "__pycache__") or not (path.suffix == ".py" or path.is_dir()):
            continue
        name = path.name + ("/" if path.is_dir() else "")
        assert name in mentioned, f"src/strips_framework/{name} is not in README's layout"
    for path in (ROOT / "plugins").iterdir():
        assert f"{path.name}/" in PLUGINS, f"plugins/{path.name} is not in README's layout"
