"""Differential tests: the resolution, Z3 and E provers must agree wherever two decide.

Hypothesis generates small first-order models (ground facts, clauses with variables, with
or without unique names) and goals with parameters, existential variables and equality.
Wherever two provers decide a task (proved, or ``Satisfiable``), they must decide it the
same way, and every answer one returns must make the goal follow: the goal instantiated
with it is not ``Satisfiable`` for *another* prover. Every axiom clause has a positive
non-equality literal, so the models are consistent. E takes part where Debian's
``eprover`` is installed.

The normal suite runs ``DEFAULT_EXAMPLES`` derandomized cases (the same every run);
``STRIPS_DIFFERENTIAL_EXAMPLES=5000`` runs more. Where E (Debian ``eprover``) is installed,
an optional test also compares the three provers on the TPTP development set.
"""

from __future__ import annotations

import os
import shutil
import subprocess
from collections import Counter
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from strips_z3_prover import Z3Prover

from strips_eprover_prover import EProver
from strips_framework.formats.tptp import load_tptp, szs_status
from strips_framework.logic.clauses import Clause, Literal
from strips_framework.logic.terms import Param
from strips_framework.logic.unify import substitute
from strips_framework.worldmodel.proving import (
    GAVE_UP,
    PROVED,
    SATURATED,
    Answer,
    ProofResult,
    ProofTask,
    open_session,
)
from strips_framework.worldmodel.world import InitialModel, WorldModel
from strips_resolution_prover import ResolutionProver

DEFAULT_EXAMPLES = 300
EXAMPLES = int(os.environ.get("STRIPS_DIFFERENTIAL_EXAMPLES", DEFAULT_EXAMPLES))
EFFORT = 2000
RESOLUTION = ResolutionProver()

CONSTANTS = ("a", "b", "c", "d")
PREDICATES = (("P", 1), ("Q", 1), ("R", 2), ("S", 0))
PARAMS = (Param("m"), Param("n"))
#: What each run saw, for the report at the end (decided the same way, answers checked).
TALLY: Counter[str] = Counter()

DIFFERENTIAL = settings(
    max_examples=EXAMPLES,
    derandomize=True,
    deadline=None,
    database=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
)


def _atom(draw: st.DrawFn, terms: st.SearchStrategy) -> tuple:
    predicate, arity = draw(st.sampled_from(PREDICATES))
    return (predicate, *(draw(terms) for _ in range(arity)))


@st.composite
def axiom_clauses(draw: st.DrawFn) -> Clause:
    """A clause with one to three literals, at least one positive and not an equation."""
    terms = st.sampled_from(CONSTANTS) | st.sampled_from((0, 1))
    head: Literal = (True, _atom(draw, terms))
    body: list[Literal] = []
    for _ in range(draw(st.integers(0, 2))):
        if draw(st.integers(0, 5)) == 0:
            body.append((False, ("=", draw(terms), draw(terms))))
        else:
            body.append((draw(st.booleans()), _atom(draw, terms)))
    return Clause(dict.fromkeys([*body, head]))


@st.composite
def tasks(draw: st.DrawFn) -> ProofTask:
    """Facts, axioms and a goal conjunction over parameters, existential variables (the
    integers, universal in the negated goal) and constants."""
    # A function symbol in facts and goals, not in rules (where x -> f(x) would make the
    # models infinite and both searches long).
    ground = st.sampled_from(CONSTANTS) | st.tuples(st.just("f"), st.sampled_from(CONSTANTS))
    facts = [Clause([(True, _atom(draw, ground))]) for _ in range(draw(st.integers(0, 8)))]
    axioms = draw(st.lists(axiom_clauses(), max_size=4))
    simple = ground | st.sampled_from(PARAMS) | st.sampled_from((0,))
    terms = simple | st.tuples(st.just("f"), simple)
    goal: list[Literal] = []
    for _ in range(draw(st.integers(1, 3))):
        kind = draw(st.integers(0, 7))
        if kind == 0:
            # Equations and disequations; under unique names "x = a" is refuted with
            # x := another name (the resolution prover once said Satisfiable here).
            goal.append((draw(st.booleans()), ("=", draw(terms), draw(terms))))
        else:
            goal.append((kind > 1, _atom(draw, terms)))
    negated = Clause(dict.fromkeys((not positive, atom) for positive, atom in goal))
    return ProofTask(
        [*facts, *axioms],
        [negated],
        effort=EFFORT,
        max_answers=draw(st.integers(1, 3)),
        unique_names=draw(st.booleans()),
    )


def _decided(result: ProofResult) -> bool:
    return result.status in (PROVED, SATURATED)


def _instance(task: ProofTask, answer: Answer) -> ProofTask:
    """The task's goal with ``answer`` applied; parameters an answer leaves unbound hold
    for every value, so they become a constant no axiom mentions."""
    binding = {**{p: f"fresh_{p.name}" for p in PARAMS}, **dict(answer)}
    instance = [
        Clause([(sign, substitute(atom, binding)) for sign, atom in clause.literals])
        for clause in task.negated_goal
    ]
    return ProofTask(task.axioms, instance, effort=EFFORT, unique_names=task.unique_names)


def _check_answers(task: ProofTask, result: ProofResult, checker: object, who: str) -> None:
    for answer in result.answers:
        check = checker.prove(_instance(task, answer))
        assert check.status != SATURATED, f"{who}'s answer {answer} does not make the goal follow"
        TALLY["answers checked"] += check.proved


@DIFFERENTIAL
@given(task=tasks(), incremental=st.booleans())
def test_resolution_z3_and_e_agree(task: ProofTask, incremental: bool) -> None:
    z3 = Z3Prover(incremental=incremental)
    results = {"resolution": RESOLUTION.prove(task), "z3": z3.prove(task)}
    if EPROVER is not None:
        results["e"] = EProver().prove(task)
    TALLY["cases"] += 1
    decided = {name: r.proved for name, r in results.items() if _decided(r)}
    assert len(set(decided.values())) <= 1, results
    if len(decided) >= 2:
        TALLY["two decided"] += 1
        TALLY["proved"] += any(decided.values())
    if len(decided) == 3:
        TALLY["three decided"] += 1
    _check_answers(task, results["z3"], RESOLUTION, "z3")
    _check_answers(task, results["resolution"], Z3Prover(incremental=False), "resolution")
    if "e" in results:
        _check_answers(task, results["e"], Z3Prover(incremental=False), "e")
    for result in results.values():
        assert len(result.answers) <= task.max_answers
        assert len(set(result.answers)) == len(result.answers)


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
            _atom(draw, st.sampled_from(CONSTANTS)) for _ in range(draw(st.integers(0, 2)))
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
    assert TALLY["two decided"] >= TALLY["cases"] // 2
    assert 0 < TALLY["proved"] < TALLY["two decided"]


# -- E prover on TPTP ------------------------------------------------------------------

EPROVER = shutil.which("eprover")
TPTP = Path(__file__).resolve().parents[2] / "shared" / "bench" / "tptp" / "dev"  # ../shared
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


@pytest.mark.skipif(EPROVER is None or not TPTP.is_dir(), reason="eprover or TPTP set absent")
@pytest.mark.parametrize("path", sorted(TPTP.glob("*.p")), ids=lambda p: p.stem)
def test_z3_resolution_and_e_agree_on_tptp(path: Path) -> None:
    problem = load_tptp(path)
    statuses = {"e": _e_status(path)}
    for name, prover in (("resolution", RESOLUTION), ("z3", Z3Prover(incremental=False))):
        status = szs_status(problem, prover.prove(problem.task(400)))
        statuses[name] = OUR_STATUS.get(status, GAVE_UP)
    decided = {s for s in statuses.values() if s != GAVE_UP}
    assert len(decided) <= 1, statuses
