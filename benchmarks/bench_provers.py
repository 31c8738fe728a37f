"""Resolution against Z3: the paper's proof tasks, and entailment queries of growing size.

    .venv/bin/python -m pytest benchmarks/bench_provers.py --benchmark-only \\
        --benchmark-group-by=param:family --benchmark-sort=name \\
        --benchmark-columns=min,mean,rounds

- ``paper``: every proof attempt a means-ends run makes on a paper task (recorded once
  from a resolution run, so both provers answer the same questions), replayed in order
  through one session on the task's M0, as a search asks them; Z3 with its incremental
  session (one solver for M0, each model switching its clauses on) and with a fresh
  solver per attempt (``incremental = false``).
- ``facts``: a robot world with ``size`` rooms, each with a door to the corridor and two
  boxes, and the question "which door ``k`` from which room ``l`` leads into room 1"
  (the ``gothrudoor`` precondition): more facts, same axioms.
- ``axioms``: ``size`` case splits, ``A_i(x) | B_i(x)``, ``A_i(x) -> C_i(x)``,
  ``B_i(x) -> C_i(x)``, and the goal ``C_1(c) & ... & C_size(c)``: more axioms, and a
  refutation that resolution can only find by combining every case (2^size clauses),
  while a SAT search splits once per axiom.

Every case checks that both provers decide it the same way. In the normal test run each
case runs once, as a smoke test.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import pytest
from strips_z3_prover import Z3Prover

from strips_framework.logic.clauses import Clause
from strips_framework.logic.terms import Param
from strips_framework.means_ends.goal_prover import GoalProver
from strips_framework.planner import Planner
from strips_framework.plugin.config import Config
from strips_framework.worldmodel.proving import (
    GAVE_UP,
    ProofResult,
    ProofTask,
    ProverSession,
    TheoremProver,
    open_session,
)
from strips_framework.worldmodel.world import InitialModel, WorldModel
from strips_resolution_prover import ResolutionProver

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
PAPER_TASKS = ["three-boxes", "robot-world/light", "robot-world/boxes"]
EFFORT = 20000
PROVERS = {
    "resolution": ResolutionProver,
    "z3": Z3Prover,
    "z3-fresh": lambda: Z3Prover(incremental=False),
}


#: One attempt of a search: (model, negated goal, max answers).
Attempt = tuple[WorldModel, tuple[Clause, ...], int]


class Recording:
    """The attempts of one means-ends run, and the M0 they were made on (mutable: the
    attempts are appended as the run makes them)."""

    __slots__ = ("initial", "unique_names", "attempts")

    def __init__(
        self,
        initial: InitialModel,
        unique_names: bool,
        attempts: list[Attempt] | None = None,
    ) -> None:
        self.initial = initial
        self.unique_names = unique_names
        self.attempts: list[Attempt] = [] if attempts is None else attempts

    def tasks(self) -> list[ProofTask]:
        """The attempts as one-off proof tasks over each model's visible clauses."""
        return [
            ProofTask.of_model(model, goal, EFFORT, answers, self.unique_names)
            for model, goal, answers in self.attempts
        ]

    def replay(self, prover: TheoremProver) -> list[str]:
        """Every attempt through one session of ``prover``, in order; their statuses."""
        session = open_session(prover, self.initial, self.unique_names)
        return [
            session.prove(model, goal, EFFORT, answers).status
            for model, goal, answers in self.attempts
        ]


class _RecordingSession:
    """A resolution session that keeps the attempts it is asked."""

    __slots__ = ("inner", "recording")

    def __init__(self, inner: ProverSession, recording: Recording) -> None:
        self.inner = inner
        self.recording = recording

    def prove(
        self, model: WorldModel, negated_goal: Sequence[Clause], effort: int, max_answers: int = 1
    ) -> ProofResult:
        self.recording.attempts.append((model, tuple(negated_goal), max_answers))
        return self.inner.prove(model, negated_goal, effort, max_answers)


def recorded_attempts(name: str) -> Recording:
    """The proof attempts of a means-ends run on ``name``, in the order they were made.
    (The search's own effort bound fits resolution; the replays give both provers the
    same, larger one.)"""
    planner = Planner.create(Config.from_dict({"limits": {"time": 60}}))
    problem = planner.load(EXAMPLES / f"{name}.strips")
    original = GoalProver._open
    recordings: list[Recording] = []

    def record(self: GoalProver) -> None:
        original(self)
        recording = Recording(self.initial, self.problem.unique_names)
        recordings.append(recording)
        self.session = _RecordingSession(self.session, recording)

    GoalProver._open = record
    try:
        assert planner.solve(problem).solved
    finally:
        GoalProver._open = original
    return recordings[0]


def _unit(predicate: str, *args: object) -> Clause:
    return Clause([(True, (predicate, *args))])


def rooms_query(size: int) -> ProofTask:
    """The ``facts`` family (see the module docstring)."""
    corridor = "CORRIDOR"
    axioms = [
        Clause([(False, ("CONNECTS", 0, 1, 2)), (True, ("CONNECTS", 0, 2, 1))]),
        Clause([(False, ("CONNECTS", 0, 1, 2)), (True, ("INROOM", 0, 1))]),
        _unit("INROOM", "ROBOT", corridor),
    ]
    for room in range(1, size + 1):
        axioms.append(_unit("CONNECTS", f"DOOR{room}", f"ROOM{room}", corridor))
        axioms.append(_unit("TYPE", f"DOOR{room}", "DOOR"))
        for box in (1, 2):
            axioms.append(_unit("INROOM", f"BOX{room}_{box}", f"ROOM{room}"))
            axioms.append(_unit("TYPE", f"BOX{room}_{box}", "BOX"))
    axioms.append(_unit("NEXTTO", "ROBOT", "DOOR1"))
    k, l = Param("k"), Param("l")
    goal = Clause(
        [
            (False, ("NEXTTO", "ROBOT", k)),
            (False, ("CONNECTS", k, l, "ROOM1")),
            (False, ("INROOM", "ROBOT", l)),
            (False, ("TYPE", k, "DOOR")),
        ]
    )
    return ProofTask(axioms, [goal], effort=EFFORT, unique_names=True)


def case_split_query(size: int) -> ProofTask:
    """The ``axioms`` family (see the module docstring)."""
    axioms = []
    for i in range(1, size + 1):
        axioms.append(Clause([(True, (f"A{i}", 0)), (True, (f"B{i}", 0))]))
        axioms.append(Clause([(False, (f"A{i}", 0)), (True, (f"C{i}", 0))]))
        axioms.append(Clause([(False, (f"B{i}", 0)), (True, (f"C{i}", 0))]))
    goal = Clause([(False, (f"C{i}", "c")) for i in range(1, size + 1)])
    return ProofTask(axioms, [goal], effort=EFFORT, unique_names=True)


def _solve_all(prover: TheoremProver, tasks: list[ProofTask]) -> list[str]:
    return [prover.prove(task).status for task in tasks]


@pytest.mark.parametrize("prover", sorted(PROVERS))
@pytest.mark.parametrize("task", PAPER_TASKS)
def test_paper(benchmark, task: str, prover: str) -> None:
    benchmark.group = "paper"
    recording = recorded_attempts(task)
    statuses = benchmark.pedantic(
        lambda: recording.replay(PROVERS[prover]()), rounds=1, iterations=1
    )
    assert statuses == _solve_all(ResolutionProver(), recording.tasks())
    benchmark.extra_info.update(family="paper", tasks=len(recording.attempts))


@pytest.mark.parametrize("prover", ["resolution", "z3"])
@pytest.mark.parametrize("size", [2, 4, 8])
def test_facts(benchmark, size: int, prover: str) -> None:
    _query(benchmark, "facts", rooms_query(size), prover)


@pytest.mark.parametrize("prover", ["resolution", "z3"])
@pytest.mark.parametrize("size", [2, 4, 6, 8, 10])
def test_axioms(benchmark, size: int, prover: str) -> None:
    _query(benchmark, "axioms", case_split_query(size), prover)


def _query(benchmark, family: str, task: ProofTask, prover: str) -> None:
    benchmark.group = family
    result = benchmark.pedantic(lambda: PROVERS[prover]().prove(task), rounds=1, iterations=1)
    benchmark.extra_info.update(family=family, status=result.status, effort=result.effort_used)
    other = PROVERS["z3" if prover == "resolution" else "resolution"]().prove(task)
    if other.status != GAVE_UP and result.status != GAVE_UP:
        assert result.proved == other.proved
