"""Loading a domain and problem from files, and finding a problem's domain file."""

from __future__ import annotations

import re
from pathlib import Path

from strips_framework.errors import InputError
from strips_framework.pddl.domain_file import read_domain
from strips_framework.pddl.problem_file import read_problem
from strips_framework.pddl.sexpr import Source
from strips_framework.pddl.task import PddlTask
from strips_framework.user_files import is_file

PDDL_SUFFIX = ".pddl"


def is_pddl(problem_path: Path, domain_path: Path | None = None) -> bool:
    """True for PDDL input: a domain is given, or the problem file ends in ``.pddl``."""
    return domain_path is not None or problem_path.suffix.lower() == PDDL_SUFFIX


def _source(path: Path) -> Source:
    """The file's text; bytes that are not UTF-8 become U+FFFD (old IPC files have Latin-1
    comments, which must not stop a task from loading; in a name they fail as any unknown
    name does)."""
    try:
        text = path.read_bytes().decode("utf-8", errors="replace")
    except IsADirectoryError:
        raise InputError(str(path), None, None, "is a folder, not a PDDL file") from None
    except (OSError, ValueError) as error:  # ValueError: a NUL byte in the name
        reason = getattr(error, "strerror", None) or str(error)
        raise InputError(str(path), None, None, f"cannot read the file: {reason}") from None
    return Source(text, str(path))


def load_task(domain_path: Path, problem_path: Path) -> PddlTask:
    """Read and check a domain and a problem file; errors are :class:`InputError`."""
    domain = read_domain(_source(domain_path))
    problem = read_problem(_source(problem_path), domain)
    return PddlTask(domain, problem, str(domain_path), str(problem_path))


def parse_task(
    domain_text: str,
    problem_text: str,
    domain_name: str = "<domain>",
    problem_name: str = "<problem>",
) -> PddlTask:
    """Read and check a domain and a problem given as text (made in code, or written by
    another tool); ``domain_name`` and ``problem_name`` stand for the files in messages."""
    domain = read_domain(Source(domain_text, domain_name))
    problem = read_problem(Source(problem_text, problem_name), domain)
    return PddlTask(domain, problem, domain_name, problem_name)


def domain_candidates(problem_path: Path) -> list[Path]:
    """Where the domain of ``problem_path`` may be, most specific first: the naming rules of
    Fast Downward (``domain.pddl``, ``p01-domain.pddl``, ``domain_p01.pddl``, ...) and of the
    IPC suites that number their domains like their tasks (``domain01.pddl``)."""
    name = problem_path.name
    names = []
    numbers = re.findall(r"\d+", name)
    if numbers:
        names.append(f"domain{numbers[0]}.pddl")
    names += [
        f"{problem_path.stem}-domain.pddl",
        f"{name[:3]}-domain.pddl",
        f"domain_{name}",
        f"domain-{name}",
        "domain.pddl",
    ]
    return [problem_path.parent / candidate for candidate in dict.fromkeys(names)]


def find_domain(problem_path: Path) -> Path:
    """The domain file beside ``problem_path``, or an :class:`InputError` listing the names
    that were tried."""
    candidates = domain_candidates(problem_path)
    for candidate in candidates:
        if is_file(candidate) and candidate != problem_path:
            return candidate
    tried = ", ".join(candidate.name for candidate in candidates)
    raise InputError(
        str(problem_path), None, None, f"no domain file found beside it (tried {tried})"
    )
