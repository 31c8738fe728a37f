"""Mutation fuzzing of every input the ``strips`` command reads: a few hundred mutants of
the shipped examples per format (seeded, so every run sees the same inputs), each run in
this process. None may end in a traceback or a hang; every error is one line naming the
file (for the file formats). ``benchmarks/fuzz_inputs.py`` runs ten thousand and more."""

from __future__ import annotations

from pathlib import Path

import pytest

from strips_framework.testing import fuzz

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "tests" / "pddl" / "data"
PER_FORMAT = 150


#: PDDL tasks with costs, derived predicates and ADL conditions, beside the example's.
TASKS = [(DATA / f"{name}-domain.pddl", DATA / f"{name}-{n}.pddl")
         for name, n in (("rooms", 1), ("lamps", 1), ("crates", 3))]


@pytest.fixture(scope="module")
def space(tmp_path_factory: pytest.TempPathFactory) -> fuzz.Workspace:
    return fuzz.Workspace.create(tmp_path_factory.mktemp("fuzz"), ROOT / "examples", pddl=TASKS)


def _shown(outcome: fuzz.Outcome) -> str:
    detail = (outcome.traceback or outcome.stderr).strip().splitlines()[-3:]
    return f"{outcome.label} {list(outcome.argv)}: exit {outcome.exit_code}: {' / '.join(detail)}"


@pytest.mark.parametrize("fmt", fuzz.FORMATS)
def test_mutated_inputs_end_in_a_result_or_one_clean_error(space: fuzz.Workspace, fmt: str) -> None:
    outcomes = [fuzz.run_case(space, case) for case in fuzz.cases(space, PER_FORMAT, [fmt])]
    crashed = [_shown(o) for o in outcomes if o.crashed]
    hung = [_shown(o) for o in outcomes if o.hung]
    errors = [o for o in outcomes if o.exit_code == fuzz.INPUT_ERROR]
    unclear = [_shown(o) for o in errors if not o.clean_error]
    assert not crashed, "\n".join(crashed)
    assert not hung, "\n".join(hung)
    assert not unclear, "\n".join(unclear)
    if fmt != "command-line":
        nameless = [_shown(o) for o in errors if not o.names_file]
        assert not nameless, "\n".join(nameless)
    assert len(errors) >= PER_FORMAT // 5  # the mutations do break inputs
