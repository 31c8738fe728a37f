"""The configurations a matrix compares, and the command line each one runs.

Three kinds, all run as a child process whose output follows one contract (that of
``strips solve --json``, or failing that Fast Downward's: a plan file, an ``expanded: N``
line, exit code 0 plan found / 11 unsolvable / 12 incomplete search exhausted / 22 out of
memory / 23 out of time):

- :class:`PlannerConfig`: our planner with a ``strips.toml``;
- :class:`CommandConfig`: any command, e.g. another build of the planner or a test double;
- :class:`AnchorConfig`: pyperplan or Fast Downward (PDDL problems only).
"""

from __future__ import annotations

import sys
from functools import cache
from pathlib import Path
from typing import Any

import tomli_w

from strips_framework.bench import anchors
from strips_framework.bench.problems import PDDL, ProblemFile
from strips_framework.records import Record

#: ``strips`` in the child's interpreter, found without relying on PATH (a Dask worker's
#: PATH need not hold the virtual environment).
STRIPS = ("-c", "import sys; from strips_framework.cli.main import main; sys.exit(main())")
PLACEHOLDERS = ("python", "problem", "domain", "plan", "folder")


class RunFiles(Record):
    """Where one run reads and writes: its private folder holds the plan and any config."""

    problem: Path
    domain: Path | None
    folder: Path

    __slots__ = ("problem", "domain", "folder")

    def __init__(self, problem: Path, domain: Path | None, folder: Path) -> None:
        self.problem = problem
        self.domain = domain
        self.folder = folder

    @property
    def plan(self) -> Path:
        return self.folder / "plan.txt"


def strips_command(*args: str) -> list[str]:
    return [sys.executable, *STRIPS, *args]


def planner_time_limit(wall_limit: float) -> float:
    """The ``[limits] time`` our planner gets under a matrix's wall-clock limit: less by a
    fifth, at most 5 s (interpreter start-up, writing the result), so that it stops itself
    and reports its statistics and exit code 23 instead of being killed without them."""
    return wall_limit - min(0.2 * wall_limit, 5.0)


class AnyProblemConfig:
    """What most configurations share: they take every problem, need nothing installed,
    read the problem where it is and write the plan to the run's ``plan.txt``."""

    __slots__ = ()
    copies_inputs = False

    def plan_file(self, files: RunFiles) -> Path:
        return files.plan

    def accepts(self, problem: ProblemFile) -> bool:
        return True

    def missing(self) -> str | None:
        return None


class PlannerConfig(AnyProblemConfig, Record):
    """``strips solve PROBLEM --json`` with ``data`` written out as its ``strips.toml``, its
    time limit no longer than the matrix's allows (:func:`planner_time_limit`)."""

    name: str
    data: dict[str, Any]

    __slots__ = ("name", "data")

    def __init__(self, name: str, data: dict[str, Any]) -> None:
        self.name = name
        self.data = data

    def command(self, files: RunFiles, time_limit: float) -> list[str]:
        config = files.folder / "strips.toml"
        limits = dict(self.data.get("limits", {}))
        limits["time"] = min(limits.get("time", time_limit), planner_time_limit(time_limit))
        data = {**self.data, "limits": limits}
        config.write_text(tomli_w.dumps(data), encoding="utf-8")
        return strips_command(
            "solve", str(files.problem), "--json", "--plan-file", str(files.plan),
            "--config", str(config),
        )

    def accepts(self, problem: ProblemFile) -> bool:
        """Every problem, but PDDL only for a ground-task strategy (native problems are
        first-order world models, which are not grounded)."""
        return problem.path.suffix == PDDL or not searches_ground_tasks(self.data)

    def describe(self) -> dict[str, Any]:
        return {"kind": "planner", "strips.toml": self.data}


@cache
def ground_strategy_names() -> frozenset[str]:
    """The registered ground-task strategies (looked up once per process)."""
    from strips_framework.plugin.registry import Registry

    return frozenset(Registry.from_plugins().names("ground-strategy"))


def searches_ground_tasks(data: dict[str, Any]) -> bool:
    """True when the ``strips.toml`` ``data`` names a ground-task strategy."""
    strategy = data.get("strategy", {})
    name = strategy.get("name") if isinstance(strategy, dict) else strategy
    return name in ground_strategy_names()


class CommandConfig(AnyProblemConfig, Record):
    """A command line with placeholders ``{python} {problem} {domain} {plan} {folder}``."""

    name: str
    template: tuple[str, ...]

    __slots__ = ("name", "template")

    def __init__(self, name: str, template: tuple[str, ...]) -> None:
        self.name = name
        self.template = template

    def command(self, files: RunFiles, time_limit: float) -> list[str]:
        values = {
            "python": sys.executable, "problem": str(files.problem),
            "domain": str(files.domain or ""), "plan": str(files.plan),
            "folder": str(files.folder),
        }
        return [part.format(**values) for part in self.template]

    def describe(self) -> dict[str, Any]:
        return {"kind": "command", "command": list(self.template)}


class AnchorConfig(Record):
    """pyperplan (``args`` e.g. ``-s gbf -H hff``) or Fast Downward (``args`` are driver
    options such as ``--alias lama-first``; ``search`` its ``--search`` string)."""

    name: str
    planner: str
    args: tuple[str, ...]
    search: str | None

    __slots__ = ("name", "planner", "args", "search")

    def __init__(
        self,
        name: str,
        planner: str,
        args: tuple[str, ...],
        search: str | None = None,
    ) -> None:
        self.name = name
        self.planner = planner
        self.args = args
        self.search = search
    #: pyperplan writes its plan beside the problem: each run works on private copies.
    copies_inputs = True

    def command(self, files: RunFiles, time_limit: float) -> list[str]:
        start = anchors.planner_command(self.planner)
        if start is None:
            raise FileNotFoundError(anchors.missing_note(self.planner))
        inputs = [str(files.domain), str(files.problem)]
        if self.planner == anchors.PYPERPLAN:
            return [*start, *self.args, *inputs]
        search = ["--search", self.search] if self.search else []
        return [*start, "--plan-file", str(files.plan), *self.args, *inputs, *search]

    def plan_file(self, files: RunFiles) -> Path:
        if self.planner == anchors.PYPERPLAN:
            return files.problem.with_name(files.problem.name + ".soln")
        return files.plan

    def accepts(self, problem: ProblemFile) -> bool:
        return problem.path.suffix == PDDL

    def missing(self) -> str | None:
        installed = anchors.planner_command(self.planner) is not None
        return None if installed else anchors.missing_note(self.planner)

    def describe(self) -> dict[str, Any]:
        described = {"kind": "anchor", "planner": self.planner, "args": list(self.args)}
        return described | ({"search": self.search} if self.search else {})


Configuration = PlannerConfig | CommandConfig | AnchorConfig
