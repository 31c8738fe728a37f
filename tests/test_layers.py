"""The package's layers (README, "Layout"): a module imports only from its own layer and
the ones below it, and the two pipelines, means-ends over world models and forward search
over ground tasks, do not import each other. Imports under ``TYPE_CHECKING`` are left
out: a type annotation may name a class from above without loading it."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "src" / "strips_framework"

#: Each top-level module or subpackage with its layer; higher numbers sit on lower ones.
LAYER = {
    "errors": 0, "result": 0, "limits": 0, "user_files": 0, "progress": 0, "capabilities": 0,
    "options": 0, "records": 0, "compiled": 0, "observer": 0,
    "logic": 1,
    "worldmodel": 2, "formats": 2,
    "means_ends": 3, "pddl": 3,
    "grounding": 4,
    "forward": 5, "lifted": 5,
    "macrops": 6,
    "plugin": 7,
    "planner": 8,
    "cli": 9, "bench": 9, "testing": 9, "explore": 9,
    "__init__": 10,
}  # fmt: skip
#: Parts that must not import each other although their layers would allow it.
APART = [({"means_ends"}, {"pddl", "grounding", "forward", "lifted"})]


def _part(module: str) -> str:
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else "__init__"


def _runtime_imports(tree: ast.Module) -> list[tuple[int, str]]:
    """``(line, module)`` of every strips_framework import outside ``TYPE_CHECKING``."""
    typing_only = {
        id(inner)
        for node in ast.walk(tree)
        if isinstance(node, ast.If) and "TYPE_CHECKING" in ast.unparse(node.test)
        for inner in ast.walk(node)
    }
    found = []
    for node in ast.walk(tree):
        if id(node) in typing_only:
            continue
        if isinstance(node, ast.ImportFrom) and (node.module or "").startswith("strips_framework"):
            if node.module == "strips_framework":
                found += [(node.lineno, f"strips_framework.{a.name}") for a in node.names]
            else:
                found.append((node.lineno, node.module))
        elif isinstance(node, ast.Import):
            found += [(node.lineno, a.name) for a in node.names if a.name.startswith("strips_framework")]
    return found


def _modules() -> list[Path]:
    return sorted(PACKAGE.rglob("*.py"))


def test_every_part_of_the_package_has_a_layer():
    modules = {p.stem for p in PACKAGE.glob("*.py")}
    packages = {p.parent.name for p in PACKAGE.glob("*/__init__.py")}  # not stale caches
    parts = modules | packages
    assert parts == set(LAYER)


@pytest.mark.parametrize("path", _modules(), ids=lambda p: str(p.relative_to(PACKAGE)))
def test_imports_go_down(path: Path):
    module = ".".join(path.relative_to(PACKAGE.parent).with_suffix("").parts)
    mine = _part(module.removesuffix(".__init__"))
    wrong = []
    for line, imported in _runtime_imports(ast.parse(path.read_text())):
        other = _part(imported)
        if other not in LAYER:
            continue  # a module inside the top-level package's namespace, e.g. __version__
        apart = any(
            (mine in a and other in b) or (mine in b and other in a) for a, b in APART
        )
        if LAYER[other] > LAYER[mine] or apart:
            wrong.append(f"line {line}: {mine} imports {imported}")
    assert not wrong, f"{path.relative_to(PACKAGE)}: " + "; ".join(wrong)
