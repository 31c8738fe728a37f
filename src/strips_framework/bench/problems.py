"""Problem sets of a matrix: globs over native and PDDL problem files.

A PDDL problem is passed to ``strips solve`` alone (the planner finds its domain); the
bench finds the domain too, by the planner's own rules (:func:`strips_framework.pddl.find_domain`),
because plan validation and the anchor planners need it named. Domain files matched by a glob are
not problems and are left out.
"""

from __future__ import annotations

import glob
import os
from pathlib import Path

from strips_framework.errors import ConfigError, InputError
from strips_framework.pddl import find_domain as find_pddl_domain
from strips_framework.records import Record

PDDL = ".pddl"


class ProblemFile(Record):
    """One problem of a set; ``name`` is its path as the matrix's folder sees it, unique
    within the matrix and stable across machines, so it keys the results."""

    name: str
    problem_set: str
    path: Path
    domain: Path | None

    __slots__ = ("name", "problem_set", "path", "domain")

    def __init__(self, name: str, problem_set: str, path: Path, domain: Path | None) -> None:
        self.name = name
        self.problem_set = problem_set
        self.path = path
        self.domain = domain


def is_domain_file(path: Path) -> bool:
    return path.suffix == PDDL and "domain" in path.name


def find_domain(problem: Path) -> Path | None:
    """The domain of a PDDL problem, or ``None`` when there is none beside it."""
    try:
        return find_pddl_domain(problem)
    except InputError:
        return None


def expand_problem_set(set_name: str, patterns: list[str], base: Path, where: str) -> list[ProblemFile]:
    """Every file matched by ``patterns`` (relative to ``base``), sorted, without domain
    files; ``where`` names the matrix key in errors."""
    found: dict[Path, None] = {}
    for pattern in patterns:
        matches = sorted(glob.glob(str(base / pattern), recursive=True))
        files = [Path(m).resolve() for m in matches if Path(m).is_file()]
        files = [f for f in files if not is_domain_file(f)]
        if not files:
            raise ConfigError(f"{where}: the pattern {pattern!r} matches no problem file")
        found.update(dict.fromkeys(files))
    problems = []
    for path in found:
        domain = find_domain(path) if path.suffix == PDDL else None
        if path.suffix == PDDL and domain is None:
            raise ConfigError(
                f"{where}: no domain file for {path} (expected domain.pddl beside it, "
                f"or domainNN.pddl for taskNN.pddl)"
            )
        name = os.path.relpath(path, base)
        problems.append(ProblemFile(name, set_name, path, domain))
    return problems
