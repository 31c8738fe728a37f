"""The TPTP development set: every status we report must be right, and enough are solved.

The set lives in ``shared/bench/tptp`` beside the repository; without it these tests skip.
Each problem runs under a fixed effort bound (given clauses), not a time limit, so the
outcome is the same on every machine.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from strips_framework.formats.tptp import load_tptp, szs_answers, szs_status
from strips_framework.logic.clauses import Clause
from strips_framework.logic.unify import substitute
from strips_framework.proving import ProofTask
from strips_resolution_prover import ResolutionProver

EFFORT = 400
#: The prover's configurations: the default (set of support, as STRIPS uses it) and
#: without a set of support (literal selection), which suits TPTP's clause sets better.
CONFIGS = {"sos": {}, "no-sos": {"set_of_support": False}}
#: Solved within ``EFFORT`` per configuration when these floors were set, minus a little
#: slack: (dev problems solved, questions answered).
FLOORS = {"sos": (27, 3), "no-sos": (32, 5)}


def _find_bench() -> Path | None:
    for parent in Path(__file__).resolve().parents:
        candidate = parent / "shared" / "bench" / "tptp"
        if candidate.is_dir():
            return candidate
    return None


BENCH = _find_bench()
needs_bench = pytest.mark.skipif(BENCH is None, reason="shared/bench/tptp not found")


def _files(folder: str) -> list[Path]:
    return sorted((BENCH / folder).glob("*.p")) if BENCH else []


def _expected() -> dict[str, str]:
    assert BENCH is not None
    manifest = json.loads((BENCH / "dev-manifest.json").read_text())
    return {entry["name"]: entry["status"] for entry in manifest}


_solved: dict[str, set[str]] = {config: set() for config in CONFIGS}
_answered: dict[str, set[str]] = {config: set() for config in CONFIGS}


@needs_bench
@pytest.mark.parametrize("config", sorted(CONFIGS))
@pytest.mark.parametrize("path", _files("dev"), ids=lambda p: p.stem)
def test_dev_status_agrees_with_manifest(path: Path, config: str) -> None:
    problem = load_tptp(path)
    result = ResolutionProver(**CONFIGS[config]).prove(problem.task(EFFORT))
    status = szs_status(problem, result)
    if status != "GaveUp":
        assert status == _expected()[problem.name]
        _solved[config].add(problem.name)


@needs_bench
@pytest.mark.parametrize("config", sorted(CONFIGS))
@pytest.mark.parametrize("path", _files("dev-questions"), ids=lambda p: p.stem)
def test_question_answers_are_correct(path: Path, config: str) -> None:
    problem = load_tptp(path)
    task = problem.task(EFFORT)
    prover = ResolutionProver(**CONFIGS[config])
    result = prover.prove(task)
    if not result.proved:
        return
    assert _expected()[problem.name.removesuffix(".q")] in ("Theorem", "Unsatisfiable")
    assert szs_answers(problem, result)
    # The answer is right if the question, instantiated with it, is a theorem.
    binding = dict(result.answers[0])
    instance = [
        Clause([(pos, substitute(atom, binding)) for pos, atom in clause.literals])
        for clause in task.negated_goal
    ]
    check = ProofTask(task.axioms, instance, effort=EFFORT)
    assert prover.prove(check).proved
    _answered[config].add(problem.name)


@needs_bench
@pytest.mark.parametrize("config", sorted(CONFIGS))
def test_enough_problems_solved(config: str) -> None:
    """Runs after the parametrized tests above (pytest keeps file order)."""
    if len(_solved[config]) + len(_answered[config]) == 0:
        pytest.skip("run together with the per-problem tests")
    solved_floor, answered_floor = FLOORS[config]
    assert len(_solved[config]) >= solved_floor
    assert len(_answered[config]) >= answered_floor
