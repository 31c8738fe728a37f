"""Per-attempt proving time of each prover on the paper's tasks, with the search's nodes.

    taskset -c 1 .venv/bin/python benchmarks/prover_attempts.py [--provers resolution z3
        eprover] [--tasks three-boxes robot-world/light ...] [--repeat 3]

Each task is solved by means-ends analysis with each prover (``[prover] name``), the
proof attempts timed in CPU seconds where the search makes them (``session.prove``,
through the session the search opened on M0). A prover that changes no answer leaves
the search the same, so the node counts must agree across provers: the table shows
each prover's beside the milliseconds an attempt takes (the best of ``--repeat`` runs) and the
ratio to resolution's. E's time includes its process's (``RUSAGE_CHILDREN``).

``--floor`` adds what any E attempt costs before it proves anything, in the same run:
a process started through :mod:`subprocess` (``/bin/true``), E printing its version,
and E ``--auto`` on a one-clause problem, each split into this process's CPU time and
the child's. A session runs E once per attempt, so no attempt of E costs less than
the last of these.
"""

from __future__ import annotations

import argparse
import resource
import subprocess
import sys
import time
from collections.abc import Sequence
from pathlib import Path

from strips_framework.logic.clauses import Clause
from strips_framework.means_ends.goal_prover import GoalProver
from strips_framework.planner import Planner
from strips_framework.plugin.config import Config
from strips_framework.records import Record
from strips_framework.worldmodel.proving import ProofResult, ProverSession
from strips_framework.worldmodel.world import WorldModel

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
TASKS = [
    "three-boxes",
    "robot-world/light",
    "robot-world/boxes",
    "robot-world/other-room",
    "robot-world/five-goals",
]


def _cpu() -> float:
    """CPU seconds of this process and its finished children (E runs as one)."""
    own = time.process_time()
    children = resource.getrusage(resource.RUSAGE_CHILDREN)
    return own + children.ru_utime + children.ru_stime


class _Timed:
    """A session that counts its attempts and their CPU time (mutable: the counts grow)."""

    __slots__ = ("inner", "attempts", "seconds")

    def __init__(self, inner: ProverSession, attempts: int = 0, seconds: float = 0.0) -> None:
        self.inner = inner
        self.attempts = attempts
        self.seconds = seconds

    def prove(
        self, model: WorldModel, negated_goal: Sequence[Clause], effort: int, max_answers: int = 1
    ) -> ProofResult:
        start = _cpu()
        try:
            return self.inner.prove(model, negated_goal, effort, max_answers)
        finally:
            self.seconds += _cpu() - start
            self.attempts += 1


class Measured(Record):
    """What one solve took: its nodes, its proof attempts and their CPU time."""

    nodes: int
    attempts: int
    seconds: float
    solved: bool

    __slots__ = ("nodes", "attempts", "seconds", "solved")

    def __init__(self, nodes: int, attempts: int, seconds: float, solved: bool) -> None:
        self.nodes = nodes
        self.attempts = attempts
        self.seconds = seconds
        self.solved = solved

    @property
    def per_attempt_ms(self) -> float:
        return 1000 * self.seconds / max(1, self.attempts)


def solve(task: str, prover: str) -> Measured:
    """``task`` solved with ``prover``, its attempts timed."""
    config = Config.from_dict({"prover": {"name": prover}, "limits": {"time": 3600}})
    planner = Planner.create(config)
    problem = planner.load(EXAMPLES / f"{task}.strips")
    original = GoalProver._open
    sessions: list[_Timed] = []

    def timed(self: GoalProver) -> None:
        original(self)
        self.session = _Timed(self.session)
        sessions.append(self.session)

    GoalProver._open = timed
    try:
        result = planner.solve(problem)
    finally:
        GoalProver._open = original
    return Measured(
        result.statistics.nodes,
        sum(s.attempts for s in sessions),
        sum(s.seconds for s in sessions),
        result.solved,
    )


def floor(runs: int = 200) -> list[tuple[str, float, float]]:
    """(what, parent ms, child ms) per run of the commands every E attempt includes."""
    from strips_eprover_prover.binary import find_binary

    executable = find_binary()
    commands = [("process start (/bin/true)", ["/bin/true"], "")]
    if executable is not None:
        trivial = "cnf(a, axiom, p).\ncnf(b, negated_conjecture, ~p).\n"
        commands += [
            ("E --version", [executable, "--version"], ""),
            ("E --auto, one-clause problem", [executable, "--auto", "--silent"], trivial),
        ]
    rows = []
    for what, command, text in commands:
        own, children = time.process_time(), _cpu() - time.process_time()
        for _ in range(runs):
            subprocess.run(
                command,
                input=text,
                stdout=subprocess.PIPE,
                stderr=subprocess.DEVNULL,
                text=True,
                check=False,
            )
        parent = time.process_time() - own
        child = _cpu() - time.process_time() - children
        rows.append((what, 1000 * parent / runs, 1000 * child / runs))
    return rows


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--provers", nargs="+", default=["resolution", "z3", "eprover"])
    parser.add_argument("--tasks", nargs="+", default=TASKS)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--floor", action="store_true", help="also E's per-run floor")
    args = parser.parse_args(argv)
    header = "| task |" + "".join(f" {p} nodes | attempts | ms | x |" for p in args.provers)
    print(header)
    print("|" + "---|" * (header.count("|") - 1))
    for task in args.tasks:
        best: dict[str, Measured] = {}
        for prover in args.provers:
            runs = [solve(task, prover) for _ in range(args.repeat)]
            best[prover] = min(runs, key=lambda m: m.seconds)
        base = best[args.provers[0]]
        row = f"| {task} |"
        for prover in args.provers:
            m = best[prover]
            ratio = m.per_attempt_ms / base.per_attempt_ms if base.per_attempt_ms else float("nan")
            nodes = f"{m.nodes}" + ("" if m.solved else " (unsolved)")
            row += f" {nodes} | {m.attempts} | {m.per_attempt_ms:.2f} | {ratio:.1f} |"
        print(row, flush=True)
    if args.floor:
        print("\n| every E run includes | parent ms | child ms |\n|---|---|---|")
        for what, parent, child in floor():
            print(f"| {what} | {parent:.2f} | {child:.2f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
