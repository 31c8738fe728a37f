"""One way to declare a value: a :class:`~strips_framework.records.Record` (options: a
``Configurable``). No module of the core or of the plugins here declares one with attrs,
dataclasses or ``NamedTuple``: building those classes costs start-up time on every run
(``benchmarks/startup_declarations.py``), and two ways to write a value are two sets of
rules (converters, ``evolve``, ``_replace``) for a maintainer to know."""

from __future__ import annotations

import ast
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
#: The core's and the plugins' sources (the example plugin in ``examples/`` shows what a
#: third party may write, and is not held to this).
SOURCES = (ROOT / "src", *sorted((ROOT / "plugins").glob("*/src")))

#: Modules whose use means a value declared another way.
OTHER_WAYS = ("attr", "attrs", "dataclasses")


def other_declarations(source: str) -> list[tuple[int, str]]:
    """``(line, what)`` for each import of attrs or dataclasses and each ``NamedTuple`` or
    ``namedtuple`` class in ``source``."""
    found = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Import):
            found += [(node.lineno, f"import {a.name}") for a in node.names
                      if a.name.split(".")[0] in OTHER_WAYS]
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            if node.module.split(".")[0] in OTHER_WAYS:
                found.append((node.lineno, f"from {node.module} import ..."))
            found += [(node.lineno, f"from {node.module} import {a.name}") for a in node.names
                      if a.name in ("NamedTuple", "namedtuple")]
        elif isinstance(node, ast.ClassDef):
            found += [(node.lineno, f"class {node.name}({ast.unparse(base)})")
                      for base in node.bases if ast.unparse(base).endswith("NamedTuple")]
        elif isinstance(node, ast.Call) and ast.unparse(node.func).endswith(("namedtuple", "NamedTuple")):
            found.append((node.lineno, ast.unparse(node.func)))
    return found


def test_no_module_declares_a_value_with_attrs_dataclasses_or_namedtuple():
    offenders = [
        f"{path.relative_to(ROOT)}:{line}: {what}"
        for folder in SOURCES
        for path in sorted(folder.rglob("*.py"))
        for line, what in other_declarations(path.read_text(encoding="utf-8"))
    ]
    assert offenders == [], "declare values as Records, options as Configurable:\n" + "\n".join(offenders)


def test_the_scan_finds_each_other_way():
    assert [what for _, what in other_declarations(
        "import attrs\n@attrs.frozen\nclass A:\n    x: int\n"
    )] == ["import attrs"]
    assert other_declarations("from attrs import frozen\n") == [(1, "from attrs import ...")]
    assert other_declarations("from dataclasses import dataclass\n")[0][1].startswith("from dataclasses")
    named = "import typing\nclass T(typing.NamedTuple):\n    x: int\n"
    assert other_declarations(named) == [(2, "class T(typing.NamedTuple)")]
    assert other_declarations("from collections import namedtuple\nP = namedtuple('P', 'x')\n") == [
        (1, "from collections import namedtuple"), (2, "namedtuple")]
    assert other_declarations("from strips_framework.records import Record\n") == []
