"""The package's layers (README, "Layout"): a module imports only from its own layer and
the ones below it, the two pipelines, means-ends over world models and forward search
over ground tasks, do not import each other, and no two parts of one layer import each
other (both ways would make them one part). Imports under ``TYPE_CHECKING`` count too: a
type named from above ties a lower layer to a higher one as much as a call does."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "src" / "strips_framework"

#: Each top-level module or subpackage with its layer; higher numbers sit on lower ones.
LAYER = {
    "errors": 0, "result": 0, "limits": 0, "user_files": 0, "progress": 0, "capabilities": 0,
    "options": 0, "records": 0, "allocation": 0, "compiled": 0, "exit_codes": 0, "plan_steps": 0, "observer": 0,
    "logic": 1,
    "worldmodel": 2, "formats": 2,
    "means_ends": 3, "pddl": 3,
    "grounding": 4,
    "forward": 5, "lifted": 5,
    "macrops": 6,
    "plugin": 7,
    "planner": 8, "learning": 8, "portfolio": 8,
    "cli": 9, "bench": 9, "testing": 9, "explore": 9,
    "__init__": 10,
}  # fmt: skip
#: Parts that must not import each other although their layers would allow it.
APART = [({"means_ends"}, {"pddl", "grounding", "forward", "lifted"})]


def _part(module: str) -> str:
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else "__init__"


def _imports(tree: ast.Module) -> list[tuple[int, str]]:
    """``(line, module)`` of every strips_framework import, ``TYPE_CHECKING`` ones included."""
    found = []
    for node in ast.walk(tree):
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
    for line, imported in _imports(ast.parse(path.read_text())):
        other = _part(imported)
        if other not in LAYER:
            continue  # a module inside the top-level package's namespace, e.g. __version__
        apart = any(
            (mine in a and other in b) or (mine in b and other in a) for a, b in APART
        )
        if LAYER[other] > LAYER[mine] or apart:
            wrong.append(f"line {line}: {mine} imports {imported}")
    assert not wrong, f"{path.relative_to(PACKAGE)}: " + "; ".join(wrong)


def _name(path: Path) -> str:
    return ".".join(path.relative_to(PACKAGE.parent).with_suffix("").parts).removesuffix(".__init__")


def test_no_two_parts_import_each_other():
    """A part importing another that imports it back (through any chain of parts), even
    within one layer: ``cli`` and ``bench`` once shared exit codes that way."""
    edges: dict[str, dict[str, str]] = {}
    for path in _modules():
        mine = _part(_name(path))
        for line, imported in _imports(ast.parse(path.read_text())):
            other = _part(imported)
            if other in LAYER and other != mine:
                edges.setdefault(mine, {}).setdefault(other, f"{path.relative_to(PACKAGE)}:{line}")

    def reaches(start: str, goal: str) -> bool:
        seen, todo = set(), [start]
        while todo:
            part = todo.pop()
            if part == goal:
                return True
            if part not in seen:
                seen.add(part)
                todo.extend(edges.get(part, {}))
        return False

    cycles = sorted(
        f"{a} -> {b} ({where}), and back"
        for a, targets in edges.items()
        for b, where in targets.items()
        if reaches(b, a)
    )
    assert not cycles, "; ".join(cycles)
