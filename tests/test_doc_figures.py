"""Figures the docs quote, checked against what the code says or does now.

A doc marks a figure it quotes (a count, a signature, a list, a status table, a whole
output) as ``<!-- figure: NAME -->TEXT<!-- /figure -->``, on one line or around a block;
in Markdown the markers do not show. :data:`FIGURES` says how NAME is produced, and the
test fails when TEXT differs from it (timings, which differ each run, are compared as
``N.NNN s`` and ``NN%``). To check a new figure: wrap it in the markers, add a producer
below; ``STRIPS_UPDATE_FIGURES=1 pytest tests/test_doc_figures.py`` rewrites every marked
text with what its producer gives (review the diff). Markers are read in README.md,
docs/*.md, the plugins' READMEs and the Python sources (docstrings).
"""

from __future__ import annotations

import functools
import inspect
import os
import re
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

import pytest

from strips_framework import Planner, exit_codes
from strips_framework.plugin.config import COMPONENTS, SECTIONS
from strips_framework.result import Status

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"
STRIPS = Path(sys.executable).with_name("strips")
MARKED = re.compile(r"<!-- figure: ([\w-]+) -->(.*?)<!-- /figure -->", re.DOTALL)
#: What varies from run to run in an output: seconds and shares of time.
TIMINGS = re.compile(r"\d+\.\d+ s\b|\(\d+%\)")


def _sources() -> list[Path]:
    return [
        ROOT / "README.md",
        *sorted((ROOT / "docs").glob("*.md")),
        *sorted(ROOT.glob("plugins/*/README.md")),
        *sorted((ROOT / "src").rglob("*.py")),
        *sorted(ROOT.glob("plugins/*/src/**/*.py")),
    ]


def _strips(*argv: str) -> str:
    run = subprocess.run([str(STRIPS), *argv], cwd=ROOT, capture_output=True, text=True, timeout=300)
    return run.stdout


@functools.cache
def _nodes(problem: str) -> int:
    return Planner.create().run(EXAMPLES / problem).statistics.nodes


def _output(*argv: str) -> str:
    """A command and its output, as a doc shows them in a plain block."""
    return f"\n```\n$ strips {' '.join(argv)}\n{_strips(*argv)}```\n"


def _status_table() -> str:
    meaning = {
        Status.SOLVED: "a plan was found",
        Status.UNSOLVABLE: "a complete search visited every reachable state",
        Status.EXHAUSTED: "an incomplete search (`means-ends`, `model-astar`, `ehc`) ran out of "
        "nodes: there may still be a plan",
        Status.NODE_LIMIT: "`[limits] nodes` (world-model searches)",
        Status.EXPANSION_LIMIT: "`[limits] expansions` (forward search)",
        Status.MEMORY_LIMIT: "`[limits] memory`",
        Status.TIME_LIMIT: "`[limits] time`, for the whole run",
        Status.INTERRUPTED: "Ctrl-C: the statistics so far are printed first",
    }
    rows = [f"| `{status}` | {exit_codes.for_status(status)} | {meaning[status]} |" for status in Status]
    return "\n| status | exit code | meaning |\n| --- | --- | --- |\n" + "\n".join(rows) + "\n"


def _run_signature() -> str:
    signature = inspect.signature(Planner.run)
    shown = [
        name if parameter.default is inspect.Parameter.empty else f"{name}={parameter.default!r}"
        for name, parameter in signature.parameters.items()
        if name != "self"
    ]
    return f"`Planner.run({', '.join(shown)})`"


def _resolution_capabilities() -> str:
    from strips_resolution_prover import ResolutionProver

    return ", ".join(f"`{word}`" for word in sorted(ResolutionProver.capabilities))


#: Config files with one mistake each, for docs/config.md's list of messages.
BAD_CONFIGS: list[tuple[bytes, dict[str, str]]] = [
    (b'[strategy\nname = "means-ends"\n', {}),
    (b'[prover]\nname = "r\xe9solution"\n', {}),
    (b'[prover]\nname = "resolution"\npick_givn = 5\n', {}),
    (b"[limits]\nnodes = 0\n", {}),
    (b'[limits]\ntime = "long"\n', {}),
    (b"[limits]\ntime = 1e12\n", {}),
    (b'[heuristic]\nname = "fff"\n', {}),
    (b'[prover]\nname = "z3"\n', {"STRIPS_DISABLE_PLUGIN_AUTOLOAD": "1"}),
    (b"[macrops]\ninstance = 3\n", {}),
    (b'[strategy]\nname = "model-astar"\n', {}),
    (b'[heuristic]\nname = "ff"\n', {}),
]


def _config_errors() -> str:
    """The first line each of :data:`BAD_CONFIGS` makes ``strips solve`` print on stderr."""
    import tempfile

    lines = []
    with tempfile.TemporaryDirectory() as folder:
        for text, environment in BAD_CONFIGS:
            (Path(folder) / "strips.toml").write_bytes(text)
            run = subprocess.run(
                [str(STRIPS), "solve", str(EXAMPLES / "three-boxes.strips"), "--config", "strips.toml"],
                cwd=folder, capture_output=True, text=True, timeout=300, env={**os.environ, **environment},
            )
            lines.append(run.stderr.splitlines()[0])
    return "\n```\n" + "\n".join(lines) + "\n```\n"


#: How each figure is produced, by the name its markers give.
FIGURES: dict[str, Callable[[], str]] = {
    "five-goals-nodes": lambda: str(_nodes("robot-world/five-goals.strips")),
    "boxes-output": lambda: _output("solve", "examples/robot-world/boxes.strips"),
    "status-table": _status_table,
    "status-words": lambda: ", ".join(f"`{status}`" for status in Status),
    "run-signature": _run_signature,
    "config-tables": lambda: ", ".join(f"`{table}`" for table in (*COMPONENTS, "limits", *SECTIONS)),
    "resolution-capabilities": _resolution_capabilities,
    "config-errors": _config_errors,
}


def _marks() -> list[object]:
    found = []
    for path in _sources():
        text = path.read_text(encoding="utf-8")
        for mark in MARKED.finditer(text):
            line = text.count("\n", 0, mark.start()) + 1
            found.append(pytest.param(path, mark.group(1), mark.group(2), id=f"{path.name}:{line}:{mark.group(1)}"))
    return found


MARKS = _marks()


def _same(quoted: str, produced: str) -> bool:
    return TIMINGS.sub("T", quoted) == TIMINGS.sub("T", produced)


def test_every_figure_has_a_producer_and_is_quoted():
    named = {param.values[1] for param in MARKS}
    assert named <= set(FIGURES), f"figures without a producer: {sorted(named - set(FIGURES))}"
    assert set(FIGURES) <= named, f"producers no doc quotes: {sorted(set(FIGURES) - named)}"


@pytest.mark.parametrize(("path", "name", "quoted"), MARKS)
def test_the_quoted_figure_is_the_current_one(path: Path, name: str, quoted: str):
    produced = FIGURES[name]()
    if os.environ.get("STRIPS_UPDATE_FIGURES") and not _same(quoted, produced):
        text = path.read_text(encoding="utf-8")
        old = f"<!-- figure: {name} -->{quoted}<!-- /figure -->"
        path.write_text(text.replace(old, f"<!-- figure: {name} -->{produced}<!-- /figure -->"), encoding="utf-8")
        return
    assert _same(quoted, produced), (
        f"{path.relative_to(ROOT)} quotes {name} as {quoted!r}, now {produced!r} "
        "(STRIPS_UPDATE_FIGURES=1 rewrites it)"
    )
