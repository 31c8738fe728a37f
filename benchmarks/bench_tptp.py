"""Time the resolution prover on a few TPTP development problems.

    .venv/bin/python -m pytest benchmarks/bench_tptp.py --benchmark-columns=min,mean,rounds

Each case is a problem the prover solves in well under a second, so the file doubles as a
smoke test in the normal test run (one round each). Without ``shared/bench/tptp`` beside
the repository the cases skip.
"""

import pytest
from shared_bench import shared_bench

from strips_framework.formats.tptp import load_tptp, szs_status

pytest.importorskip("strips_resolution_prover")
from strips_resolution_prover import ResolutionProver

PROBLEMS = {
    "dev/PUZ001-1": "Unsatisfiable",
    "dev/PUZ047+1": "Theorem",
    "dev/SET146+3": "Theorem",
    "dev/MSC002-1": "Unsatisfiable",
    "dev-questions/SYN031-1.q": "Theorem",
}
EFFORT = 500


BENCH = shared_bench("tptp")


@pytest.mark.skipif(BENCH is None, reason="shared/bench/tptp not found")
@pytest.mark.parametrize("name", sorted(PROBLEMS))
def test_tptp_problem(benchmark, name):
    problem = load_tptp(BENCH / f"{name}.p")
    task = problem.task(EFFORT)
    result = benchmark.pedantic(ResolutionProver().prove, args=(task,), rounds=1, iterations=1)
    benchmark.extra_info.update(effort_used=result.effort_used)
    assert szs_status(problem, result) == PROBLEMS[name]
