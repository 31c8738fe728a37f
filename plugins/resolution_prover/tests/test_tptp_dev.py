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
#: Solved within ``EFFORT`` when this floor was set, minus a little slack.
SOLVED_FLOOR = 24
QUESTIONS_ANSWERED_FLOOR = 3


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


_solved: set[str] = set()
_answered: set[str] = set()


@needs_bench
@pytest.mark.parametrize("path", _files("dev"), ids=lambda p: p.stem)
def test_dev_status_agrees_with_manifest(path: Path) -> None:
    problem = load_tptp(path)
    result = ResolutionProver().prove(problem.task(EFFORT))
    status = szs_status(problem, result)
    if status != "GaveUp":
        assert status == _expected()[problem.name]
        _solved.add(problem.name)


@needs_bench
@pytest.mark.parametrize("path", _files("dev-questions"), ids=lambda p: p.stem)
def test_question_answers_are_correct(path: Path) -> None:
    problem = load_tptp(path)
    task = problem.task(EFFORT)
    result = ResolutionProver().prove(task)
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
    assert ResolutionProver().prove(check).proved
    _answered.add(problem.name)


@needs_bench
def test_enough_problems_solved() -> None:
    """Runs after the parametrized tests above (pytest keeps file order)."""
    if len(_solved) + len(_answered) == 0:
        pytest.skip("run together with the per-problem tests")
    assert len(_solved) >= SOLVED_FLOOR
    assert len(_answered) >= QUESTIONS_ANSWERED_FLOOR
