"""The TPTP development set: every status we report must be right, and none solved is lost.

The set lives in ``shared/bench/tptp`` beside the repository, and a copy in
``tests/data/bench/tptp`` (``benchmarks/shared_bench.py``).
Each problem runs under a fixed effort bound (given clauses), not a time limit, so the
outcome is the same on every machine.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from shared_bench import shared_bench

from strips_framework.formats.tptp import load_tptp, prove_tptp, szs_answers, szs_status
from strips_framework.logic.clauses import Clause
from strips_framework.logic.unify import substitute
from strips_framework.worldmodel.proving import ProofTask
from strips_resolution_prover import ResolutionProver

EFFORT = 400
#: The prover's configurations: the set of support alone (as STRIPS uses it on world
#: models), saturation alone (literal selection, superposition), and the automatic mode,
#: the default, which picks from the problem's features (auto.py).
CONFIGS = {
    "sos": {"schedule": False},
    "no-sos": {"schedule": False, "set_of_support": False},
    "auto": {},
}
_BOTH = {
    "COM001-1", "GRP003-1", "GRP131-1.002", "KRS082+1", "KRS089+1", "MGT036+3", "NLP095-1",
    "PLA002-1", "PLA003-1", "PUZ001+1", "PUZ001-1", "PUZ002-1", "PUZ003-1", "PUZ008-1",
    "PUZ020-1", "PUZ037-1", "PUZ047+1", "SET044+1", "SET062+3", "SET146+3", "SET824-2",
    "SWV011-1", "SYN031-1", "SYN048+1", "SYN068+1", "SYN074+1", "SYN096-1.008", "SYN320+1",
}  # fmt: skip
#: Floors: the problems each configuration solves within ``EFFORT``, each with the
#: manifest's status (giving up on one of them fails), and the questions it answers.
SOLVED = {
    "sos": _BOTH | {"MSC002-1"},
    # MGT031+1: CounterSatisfiable with =, shown by superposition's saturation.
    "no-sos": _BOTH | {"KRS005-1", "LCL077-1", "MGT031+1", "PUZ018-1", "PUZ028-1", "PUZ031-1",
                       "SET830-2"},
    "auto": _BOTH | {"MSC002-1", "KRS005-1", "LCL077-1", "MGT031+1", "PUZ018-1", "PUZ028-1",
                     "PUZ031-1"},
}  # fmt: skip
ANSWERED = {
    "sos": {"PUZ008-1.q", "SWV011-1.q", "SYN031-1.q", "SYN096-1.008.q"},
    "no-sos": {"PLA003-1.q", "PUZ008-1.q", "PUZ031-1.q", "SWV011-1.q", "SYN031-1.q",
               "SYN096-1.008.q"},
    "auto": {"PLA003-1.q", "PUZ008-1.q", "PUZ031-1.q", "SWV011-1.q", "SYN031-1.q",
             "SYN096-1.008.q"},
}  # fmt: skip


BENCH = shared_bench("tptp")
needs_bench = pytest.mark.skipif(BENCH is None, reason="shared/bench/tptp not found")


def _files(folder: str) -> list[Path]:
    return sorted((BENCH / folder).glob("*.p")) if BENCH else []


def _expected() -> dict[str, str]:
    assert BENCH is not None
    manifest = json.loads((BENCH / "dev-manifest.json").read_text())
    return {entry["name"]: entry["status"] for entry in manifest}


@needs_bench
@pytest.mark.parametrize("config", sorted(CONFIGS))
@pytest.mark.parametrize("path", _files("dev"), ids=lambda p: p.stem)
def test_dev_status_agrees_with_manifest(path: Path, config: str) -> None:
    problem = load_tptp(path)
    result = ResolutionProver(**CONFIGS[config]).prove(problem.task(EFFORT))
    status = szs_status(problem, result)
    if problem.name in SOLVED[config] or status != "GaveUp":
        assert status == _expected()[problem.name]


@needs_bench
@pytest.mark.parametrize("config", sorted(CONFIGS))
@pytest.mark.parametrize("path", _files("dev-questions"), ids=lambda p: p.stem)
def test_question_answers_are_correct(path: Path, config: str) -> None:
    problem = load_tptp(path)
    task = problem.task(EFFORT)
    prover = ResolutionProver(**CONFIGS[config])
    result = prover.prove(task)
    if problem.name in ANSWERED[config]:
        assert result.proved
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


#: Floors beyond ``EFFORT`` for the automatic mode, with the given clauses each needs
#: (about 330 and 690): GRP012+5 (no axioms: symbols only, no unit preference, where
#: the penalty took 2,656; picks by refined weight in saturation, without which it took
#: 1,222) and SET018+4 (saturation of the SInE-relevant axioms).
LATE = {"GRP012+5": 500, "SET018+4": 1000}


@needs_bench
@pytest.mark.parametrize("name", sorted(LATE))
def test_late_floors(name: str) -> None:
    problem = load_tptp(BENCH / "dev" / f"{name}.p")
    result = ResolutionProver().prove(problem.task(LATE[name]))
    assert szs_status(problem, result) == _expected()[name]


#: What a TPTP user gets for each question (``prove_tptp``): the conjecture's status, the
#: original problem's read as a conjecture's.
_AS_CONJECTURE = {"Unsatisfiable": "Theorem", "Theorem": "Theorem",
                  "CounterSatisfiable": "CounterSatisfiable"}  # fmt: skip


@needs_bench
@pytest.mark.parametrize("path", _files("dev-questions"), ids=lambda p: p.stem)
def test_every_question_gets_its_status(path: Path) -> None:
    # A floor for all 13: the conjecture first, then the bounded answer search (a
    # question whose answer search ran first used to spend the effort there).
    problem = load_tptp(path)
    outcome = prove_tptp(ResolutionProver(), problem, EFFORT)
    status, answers = outcome.status, outcome.answers
    assert status == _AS_CONJECTURE[_expected()[problem.name.removesuffix(".q")]]
    if problem.name in ANSWERED["auto"]:
        assert answers
