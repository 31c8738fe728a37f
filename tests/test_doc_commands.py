"""The command examples of README.md and docs/*.md run as written, and say what they
claim. A command is collected when it can run in CI: no placeholder (``PROBLEM``,
``HOST``), every input it names exists in the repository, and it is not a benchmark
matrix run (minutes) or a Dask run (a cluster). Each runs in a fresh folder beside a link
to ``examples/``, so the files it writes (plan.txt, runs.jsonl) land there, after the
commands above it in its block (a block is a session: ``strips learn ... -o robot.lib``
makes the library the next line uses; only the commands that write what a command reads
are replayed before it). Commands run in bash, so ``{a,b}`` expands."""

from __future__ import annotations

import re
import shlex
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
DOCS = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
STRIPS = Path(sys.executable).with_name("strips")
PLACEHOLDER = re.compile(r"\b[A-Z]{3,}\b")
INPUT = re.compile(r"\.(strips|pddl|toml|p|inc)$")
OUTPUT_OPTIONS = ("-o", "--output", "--plan-file", "--tree")
#: A comment claiming a figure the command's output must show (see the test below).
CLAIM = re.compile(r"#.*?\d+ (steps|nodes instead of \d+)")


def _shell_lines(text: str) -> list[tuple[int, str, tuple[str, ...]]]:
    """``(line number, command, the commands above it in its block)`` for each
    ``strips`` command in the sh blocks, with ``\\`` continuations joined and the ``$ ``
    prompt dropped."""
    found = []
    for block in re.finditer(r"```sh\n(.*?)```", text, re.DOTALL):
        earlier: list[str] = []
        first = text.count("\n", 0, block.start()) + 2
        pending, start = "", 0
        for offset, line in enumerate(block.group(1).splitlines()):
            if not pending:
                start = first + offset
            pending += line.rstrip("\\").rstrip() + " "
            if line.endswith("\\"):
                continue
            command = pending.strip().removeprefix("$ ")
            pending = ""
            if re.match(r"^(\.venv/bin/)?strips ", command):
                found.append((start, command, tuple(earlier)))
                earlier.append(command)
    return found


def _expand(word: str) -> list[str]:
    """A word with one ``{a,b}`` group as bash expands it."""
    group = re.search(r"\{([^{}]*,[^{}]*)\}", word)
    if group is None:
        return [word]
    return [word[: group.start()] + part + word[group.end() :] for part in group.group(1).split(",")]


def _runnable(command: str) -> bool:
    words, _, _ = command.partition("#")
    argv = shlex.split(words)
    if PLACEHOLDER.search(words) or "--scheduler" in argv:
        return False
    if argv[1:2] == ["bench"] and any(a.startswith("examples/bench/") for a in argv):
        return False  # a whole matrix: minutes of runs
    if argv[1:3] == ["bench", "report"]:
        return False  # reads the results of a matrix run
    inputs = [
        word for before, word in zip(["", *argv], argv)
        if INPUT.search(word) and before not in OUTPUT_OPTIONS
    ]
    return all((ROOT / path).exists() for word in inputs for path in _expand(word))


def _commands() -> list[object]:
    """The runnable commands, each subcommand on the same inputs once (docs/bench.md
    repeats README's quick form)."""
    found, seen = [], set()
    for doc in DOCS:
        for line, command, earlier in _shell_lines(doc.read_text()):
            argv = shlex.split(command.partition("#")[0])
            key = (argv[1], *sorted(w for w in argv if INPUT.search(w)))
            if CLAIM.search(command):  # a command that claims a figure is always run
                key = (*key, command)
            if _runnable(command) and key not in seen:
                seen.add(key)
                setup = _needed(argv, [c for c in earlier if _runnable(c)])
                found.append(pytest.param(command, setup, id=f"{doc.name}:{line}"))
    return found


def _writes(argv: list[str]) -> set[str]:
    """The files a command writes (the words after its output options)."""
    return {word for before, word in zip(argv, argv[1:]) if before in OUTPUT_OPTIONS}


def _needed(argv: list[str], earlier: list[str]) -> tuple[str, ...]:
    """The earlier commands of the block that write a file this command reads, and those
    that theirs need in turn, in block order: a session replays only what it depends on
    (replaying every earlier command made the README block quadratic in its length)."""
    words = {w for word in argv for w in _expand(word)}
    chosen: list[str] = []
    for command in reversed(earlier):
        earlier_argv = shlex.split(command.partition("#")[0])
        if _writes(earlier_argv) & words:
            chosen.append(command)
            words |= {w for word in earlier_argv for w in _expand(word)}
    return tuple(reversed(chosen))


COMMANDS = _commands()


def _run(command: str, folder: Path) -> subprocess.CompletedProcess[str]:
    if not (folder / "examples").exists():
        (folder / "examples").symlink_to(ROOT / "examples")
    words = command.partition("#")[0].strip()
    script = shlex.quote(str(STRIPS)) + " " + words.split(" ", 1)[1]
    return subprocess.run(
        ["bash", "-c", script], cwd=folder, capture_output=True, text=True, timeout=300
    )


def test_the_readme_commands_are_collected():
    ids = [param.id for param in COMMANDS]
    assert sum(i.startswith("README.md:") for i in ids) >= 4, ids


@pytest.mark.parametrize(("command", "setup"), COMMANDS)
def test_command_runs_and_keeps_its_claims(command: str, setup: tuple[str, ...], tmp_path: Path):
    for earlier in setup:
        made = _run(earlier, tmp_path)
        assert made.returncode in (0, 1, 11, 12), (earlier, made.stderr)  # ran, plan or not
    done = _run(command, tmp_path)
    assert done.returncode == 0, done.stderr
    assert "Traceback" not in done.stderr
    claim = re.search(r"#.*?(\d+) steps", command)
    if claim:  # "# A*: 4 steps"
        assert f"; plan length: {claim.group(1)}" in done.stdout.splitlines()
    nodes = re.search(r"#.*?(\d+) nodes instead of (\d+)", command)
    if nodes:  # "--macrops robot.lib  # 90 nodes instead of 153": with the library, then without
        assert f"; nodes: {nodes.group(1)} in the tree" in done.stdout, done.stdout
        alone = _run(re.sub(r"--macrops \S+", "", command), tmp_path)
        assert f"; nodes: {nodes.group(2)} in the tree" in alone.stdout, alone.stdout
    for written in re.findall(r"--plan-file (\S+)", command):
        assert (tmp_path / written).read_text().splitlines()[-1].startswith("; cost = ")


def test_the_readme_sample_output_is_what_the_command_prints(tmp_path: Path):
    """The ``$ strips solve ...`` block: the same plan and the same counts (times vary)."""
    text = (ROOT / "README.md").read_text()
    sample = re.search(r"```\n\$ (strips solve \S+)\n(.*?)```", text, re.DOTALL)
    assert sample is not None
    done = _run(sample.group(1), tmp_path)
    timed = ("; time:", "; search:")
    shown = [line for line in sample.group(2).splitlines() if not line.startswith(timed)]
    printed = [line for line in done.stdout.splitlines() if not line.startswith(timed)]
    assert printed == shown
