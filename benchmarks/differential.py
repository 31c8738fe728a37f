"""Differential run: the resolution prover, z3 and E on generated first-order tasks.

    .venv/bin/python benchmarks/differential.py --cases 5000 [--jobs 2] [--no-e] [--every 100]

Hypothesis generates small first-order models (ground facts with a function symbol,
clauses with variables and disequations, with or without unique names) and goals with
parameters, existential variables and equality (:func:`tasks`; the same cases on every
run, derandomized). Every axiom clause has a positive non-equality literal, so the models
are consistent. Each case goes to every prover; wherever two decide (proved, or
``Satisfiable``), they must decide alike, and every answer a prover returns is re-proved
by *another* prover with the answer applied to the goal (:func:`compare`). Running totals
are printed (flushed) every ``--every`` cases, so a long run can be watched; the final
counts are a table: cases, decided by each, decided by two and by three, disagreements
(must be 0), answers found and answers re-proved, and wall seconds per prover and for
re-proving answers.

Where the time goes: an E call is a process start plus TPTP written and parsed (tens of
milliseconds); the cases are split in batches over ``--jobs`` worker processes, each
started once with its own provers, and every prover call is bounded (effort
:data:`EFFORT` given clauses, subsumption included; E also :data:`E_CPU_LIMIT`
seconds). Generating 5,000 cases takes about 30 s. A call's time is counted when it
returns, so a call that does not return shows as wall time missing from the table: that
was the 10 minutes behind 511 cases (case 512 spent them in subsumption, now bounded;
the 511 cases themselves took 75 s). ``tests/test_differential.py`` runs the same
comparison on a few hundred cases as a property test.
"""

from __future__ import annotations

import argparse
import multiprocessing
import sys
import time
from collections import Counter
from collections.abc import Iterable, Mapping, Sequence

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from strips_eprover_prover import EProver
from strips_eprover_prover.binary import find_binary
from strips_z3_prover import Z3Prover

from strips_framework.logic.clauses import Clause, Literal
from strips_framework.logic.terms import Param
from strips_framework.logic.unify import substitute
from strips_framework.worldmodel.proving import (
    PROVED,
    SATURATED,
    Answer,
    ProofResult,
    ProofTask,
    TheoremProver,
)
from strips_resolution_prover import ResolutionProver

#: Given clauses per call. Most cases are decided within a few dozen; a few equality
#: cases make superposition (or SOS paramodulation) build terms up to ``max_weight`` for
#: every given clause, at ~20 ms each, and those dominated the run at 2,000.
EFFORT = 500
#: E's safety net per call (seconds of CPU); the effort bound is what normally stops it.
E_CPU_LIMIT = 5
CONSTANTS = ("a", "b", "c", "d")
PREDICATES = (("P", 1), ("Q", 1), ("R", 2), ("S", 0))
PARAMS = (Param("m"), Param("n"))
#: Which prover re-proves whose answers: never the one that found them.
CHECKER = {"resolution": "z3", "z3": "resolution", "e": "z3"}


def atom(draw: st.DrawFn, terms: st.SearchStrategy) -> tuple:
    """An atom of one of :data:`PREDICATES` over ``terms``."""
    predicate, arity = draw(st.sampled_from(PREDICATES))
    return (predicate, *(draw(terms) for _ in range(arity)))


@st.composite
def axiom_clauses(draw: st.DrawFn) -> Clause:
    """A clause with one to three literals, at least one positive and not an equation."""
    terms = st.sampled_from(CONSTANTS) | st.sampled_from((0, 1))
    head: Literal = (True, atom(draw, terms))
    body: list[Literal] = []
    for _ in range(draw(st.integers(0, 2))):
        if draw(st.integers(0, 5)) == 0:
            body.append((False, ("=", draw(terms), draw(terms))))
        else:
            body.append((draw(st.booleans()), atom(draw, terms)))
    return Clause(dict.fromkeys([*body, head]))


@st.composite
def tasks(draw: st.DrawFn) -> ProofTask:
    """Facts, axioms and a goal conjunction over parameters, existential variables (the
    integers, universal in the negated goal) and constants."""
    # A function symbol in facts and goals, not in rules (where x -> f(x) would make the
    # models infinite and both searches long).
    ground = st.sampled_from(CONSTANTS) | st.tuples(st.just("f"), st.sampled_from(CONSTANTS))
    facts = [Clause([(True, atom(draw, ground))]) for _ in range(draw(st.integers(0, 8)))]
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
            goal.append((kind > 1, atom(draw, terms)))
    negated = Clause(dict.fromkeys((not positive, atom) for positive, atom in goal))
    return ProofTask(
        [*facts, *axioms],
        [negated],
        effort=EFFORT,
        max_answers=draw(st.integers(1, 3)),
        unique_names=draw(st.booleans()),
    )


def provers(with_e: bool, z3_incremental: bool = False) -> dict[str, TheoremProver]:
    """The provers compared (E only where an E binary is found)."""
    chosen: dict[str, TheoremProver] = {
        "resolution": ResolutionProver(),
        "z3": Z3Prover(incremental=z3_incremental),
    }
    if with_e and find_binary() is not None:
        chosen["e"] = EProver(cpu_limit=E_CPU_LIMIT)
    return chosen


def decided(result: ProofResult) -> bool:
    return result.status in (PROVED, SATURATED)


def instance(task: ProofTask, answer: Answer) -> ProofTask:
    """The task's goal with ``answer`` applied; parameters an answer leaves unbound hold
    for every value, so they become a constant no axiom mentions."""
    binding = {**{p: f"fresh_{p.name}" for p in PARAMS}, **dict(answer)}
    goal = [
        Clause([(sign, substitute(atom, binding)) for sign, atom in clause.literals])
        for clause in task.negated_goal
    ]
    return ProofTask(task.axioms, goal, effort=EFFORT, unique_names=task.unique_names)


def compare(
    task: ProofTask, chosen: Mapping[str, TheoremProver], tally: Counter[str]
) -> dict[str, ProofResult]:
    """Run every prover on ``task``, count what happened in ``tally`` and raise
    ``AssertionError`` on a disagreement or an answer another prover refutes."""
    results: dict[str, ProofResult] = {}
    for name, prover in chosen.items():
        start = time.perf_counter()
        results[name] = prover.prove(task)
        tally[f"seconds {name}"] += time.perf_counter() - start
    tally["cases"] += 1
    verdicts = {name: r.proved for name, r in results.items() if decided(r)}
    for name in verdicts:
        tally[f"decided by {name}"] += 1
    if len(set(verdicts.values())) > 1:
        tally["disagreements"] += 1
        raise AssertionError(f"provers disagree on {task}: {results}")
    tally["decided by two"] += len(verdicts) >= 2
    tally["decided by three"] += len(verdicts) == 3
    tally["proved (two decided)"] += len(verdicts) >= 2 and any(verdicts.values())
    for name, result in results.items():
        assert len(result.answers) <= task.max_answers, (name, result)
        assert len(set(result.answers)) == len(result.answers), (name, result)
        checker = chosen[CHECKER[name]]
        for answer in result.answers:
            tally["answers"] += 1
            start = time.perf_counter()
            check = checker.prove(instance(task, answer))
            tally["seconds re-proving"] += time.perf_counter() - start
            if check.status == SATURATED:
                tally["answers refuted"] += 1
                raise AssertionError(f"{name}'s answer {answer} does not follow: {task}")
            tally["answers re-proved"] += check.proved
    return results


def generate(count: int) -> list[ProofTask]:
    """``count`` cases, the same on every run (derandomized Hypothesis)."""
    found: list[ProofTask] = []

    @settings(
        max_examples=count,
        derandomize=True,
        database=None,
        deadline=None,
        suppress_health_check=list(HealthCheck),
    )
    @given(task=tasks())
    def collect(task: ProofTask) -> None:
        found.append(task)

    collect()
    return found[:count]


#: A worker's provers, made once per process (see :func:`_start_worker`).
_CHOSEN: dict[str, TheoremProver] = {}


def _start_worker(with_e: bool) -> None:
    _CHOSEN.update(provers(with_e))


def _run_batch(cases: list[ProofTask]) -> tuple[Counter[str], list[str]]:
    tally: Counter[str] = Counter()
    failures: list[str] = []
    for task in cases:
        try:
            compare(task, _CHOSEN, tally)
        except AssertionError as failure:
            failures.append(str(failure))
    return tally, failures


def progress(tally: Counter[str], names: Sequence[str], seconds: float) -> str:
    """One line of running totals."""
    decided = " ".join(f"{name} {tally[f'decided by {name}']}" for name in names)
    return (
        f"{tally['cases']} cases, {seconds:.0f} s: decided {decided}, by two "
        f"{tally['decided by two']}, disagreements {tally['disagreements']}, answers "
        f"{tally['answers']} re-proved {tally['answers re-proved']}"
    )


def run(
    cases: list[ProofTask], jobs: int, with_e: bool, every: int = 0
) -> tuple[Counter[str], list[str]]:
    """Compare the provers on ``cases`` in ``jobs`` worker processes (made once, each with
    its own provers), in batches of ``every`` cases, printing running totals (flushed)
    after each batch; ``every = 0`` prints nothing."""
    size = every or max(1, len(cases) // max(jobs, 1))
    batches = [cases[i : i + size] for i in range(0, len(cases), size)]
    tally: Counter[str] = Counter()
    failures: list[str] = []
    names = list(provers(with_e))
    start = time.perf_counter()
    pool = None
    if jobs > 1:
        pool = multiprocessing.get_context("spawn").Pool(jobs, _start_worker, (with_e,))
        results: Iterable[tuple[Counter[str], list[str]]] = pool.imap(_run_batch, batches)
    else:
        _start_worker(with_e)
        results = map(_run_batch, batches)
    try:
        for part, failed in results:
            tally.update(part)
            failures.extend(failed)
            if every:
                print(progress(tally, names, time.perf_counter() - start), flush=True)
    finally:
        if pool is not None:
            pool.close()
            pool.join()
    return tally, failures


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--cases", type=int, default=5000)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--no-e", action="store_true", help="leave E out")
    parser.add_argument(
        "--every", type=int, default=100, help="print running totals every N cases (0: never)"
    )
    args = parser.parse_args(argv)
    start = time.perf_counter()
    cases = generate(args.cases)
    generated = time.perf_counter() - start
    tally, failures = run(cases, args.jobs, not args.no_e, args.every)
    print(f"{len(cases)} cases generated in {generated:.1f} s, "
          f"compared in {time.perf_counter() - start - generated:.1f} s wall")  # fmt: skip
    names = provers(not args.no_e)
    print("| count | value |\n|---|---|")
    for key in (
        "cases",
        *(f"decided by {name}" for name in names),
        "decided by two",
        "decided by three",
        "proved (two decided)",
        "disagreements",
        "answers",
        "answers re-proved",
        "answers refuted",
    ):
        print(f"| {key} | {tally[key]} |")
    for name in names:
        print(f"| wall seconds in {name} calls (all jobs) | {tally[f'seconds {name}']:.1f} |")
    print(f"| wall seconds re-proving answers (all jobs) | {tally['seconds re-proving']:.1f} |")
    for failure in failures:
        print(f"FAILURE: {failure}", file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
