"""The ``strips`` Unified Planning engine: found by name, solving UP problems with plans
that UP's own validator accepts, honest about what it supports, its params and timeout
obeyed."""

from __future__ import annotations

import importlib.util
from pathlib import Path

import pytest
import unified_planning.test.examples as up_examples
from shared_bench import small_bench
from unified_planning.engines import PlanGenerationResultStatus as UpStatus
from unified_planning.engines import ValidationResultStatus
from unified_planning.exceptions import UPUsageError
from unified_planning.io import PDDLReader
from unified_planning.shortcuts import OneshotPlanner, PlanValidator, get_environment

import up_strips

ROOT = Path(__file__).resolve().parents[3]
BLOCKS = ROOT / "examples" / "pddl" / "blocksworld"
#: Five IPC tasks, one per domain.
IPC_TASKS = ["blocks/task01", "gripper/task01", "logistics/task01", "miconic/task01",
             "depot/task01"]

get_environment().credits_stream = None


def _builtin_cases(module: str) -> dict[str, object]:
    """The test cases of ``up_test_cases/builtin/classical/<module>.py``, loaded from the
    file: the package itself imports a ``utils`` module that only its report script puts
    on the path."""
    spec = importlib.util.find_spec("up_test_cases")
    assert spec is not None and spec.origin is not None
    path = Path(spec.origin).parent / "builtin" / "classical" / f"{module}.py"
    loaded = importlib.util.spec_from_file_location(f"up_builtin_{module}", path)
    assert loaded is not None and loaded.loader is not None
    code = importlib.util.module_from_spec(loaded)
    loaded.loader.exec_module(code)
    return code.get_test_cases()


def _test_cases() -> dict[str, object]:
    """UP's engine test cases (its classical builtin ones and its examples) whose kind the
    engine declares; the others are not collected."""
    cases = {**_builtin_cases("basic_problems"), **_builtin_cases("metric_problems")}
    cases.update(
        (name, case) for name, case in up_examples.get_example_problems().items()
    )
    return {
        name: case for name, case in cases.items()
        if up_strips.StripsEngine.supports(case.problem.kind)
    }


CASES = _test_cases()


def _valid(problem, plan) -> bool:
    with PlanValidator(problem_kind=problem.kind, plan_kind=plan.kind) as validator:
        return validator.validate(problem, plan).status == ValidationResultStatus.VALID


def _blocks(name: str = "p4.pddl"):
    return PDDLReader().parse_problem(str(BLOCKS / "domain.pddl"), str(BLOCKS / name))


def test_the_blocks_example_is_solved_and_the_plan_validated():
    problem = _blocks()
    with OneshotPlanner(name="strips") as planner:
        result = planner.solve(problem)
    assert result.status == UpStatus.SOLVED_SATISFICING and result.engine_name == "strips"
    assert _valid(problem, result.plan)
    assert float(result.metrics["engine_internal_time"]) > 0
    assert int(result.metrics["expanded"]) >= 1


@pytest.mark.parametrize(("cheap", "chosen"), [(10**6, "lazy-gbfs"), (10, "means-ends and lifted-alt-bfws")])
def test_the_default_is_strips_solves_and_says_what_it_chose(monkeypatch, cheap, chosen):
    """As ``strips solve`` does: ground when grounding looks cheap, else the searches
    that never ground (here, with the bound lowered, on the blocks example); the choice
    comes back as an INFO log message."""
    from unified_planning.engines import LogLevel

    from strips_framework.lifted import estimate

    monkeypatch.setattr(estimate, "CHEAP_GROUNDING", cheap)
    problem = _blocks()
    with OneshotPlanner(name="strips") as planner:
        result = planner.solve(problem, timeout=60)
    assert result.status == UpStatus.SOLVED_SATISFICING and _valid(problem, result.plan)
    [message] = result.log_messages
    assert message.level == LogLevel.INFO
    assert f"strategy {chosen}: grounding looks " in message.message


def test_the_engine_is_found_by_kind():
    problem = _blocks()
    with OneshotPlanner(problem_kind=problem.kind) as planner:
        assert planner.name == "strips"  # the only planner installed here


@pytest.mark.parametrize("name", sorted(CASES))
def test_up_engine_test_case(name):
    case = CASES[name]
    with OneshotPlanner(name="strips") as planner:
        result = planner.solve(case.problem, timeout=30)
    if case.solvable:
        assert result.status in (UpStatus.SOLVED_SATISFICING, UpStatus.SOLVED_OPTIMALLY)
        assert _valid(case.problem, result.plan)
    else:
        assert result.status == UpStatus.UNSOLVABLE_PROVEN and result.plan is None


def test_enough_of_ups_cases_fit_the_declared_kind():
    assert len(CASES) >= 15
    assert "conditional_effect" not in CASES and "basic_numeric" not in CASES


def test_params_choose_an_optimal_strategy_and_heuristic():
    problem = _blocks()
    params = {"strategy": "astar", "heuristic": "lmcut"}
    with OneshotPlanner(name="strips", params=params) as planner:
        result = planner.solve(problem)
    assert result.status == UpStatus.SOLVED_OPTIMALLY
    assert len(result.plan.actions) == 8 and _valid(problem, result.plan)
    assert result.metrics["expanded"] != "0"


def test_params_reach_the_world_model_family_too():
    problem = _blocks("p2.pddl") if (BLOCKS / "p2.pddl").exists() else _blocks()
    params = {"strategy": "means-ends", "prover": "resolution", "evaluator": "paper",
              "limits": {"nodes": 20000}}
    with OneshotPlanner(name="strips", params=params) as planner:
        result = planner.solve(problem, timeout=60)
    assert result.status == UpStatus.SOLVED_SATISFICING and _valid(problem, result.plan)
    assert "nodes" in result.metrics


def test_the_timeout_is_honoured():
    with OneshotPlanner(name="strips", params={"strategy": "breadth-first"}) as planner:
        result = planner.solve(_blocks(), timeout=1e-9)
    assert result.status == UpStatus.TIMEOUT and result.plan is None


def test_bad_params_are_refused_at_once():
    with pytest.raises(UPUsageError, match="unknown params"):
        OneshotPlanner(name="strips", params={"heuristc": "ff"})
    with pytest.raises(Exception, match="'lmcutt' is not registered"):
        OneshotPlanner(name="strips", params={"heuristic": "lmcutt"})


def test_unsupported_problems_are_not_claimed():
    conditional = up_examples.get_example_problems()["basic_conditional"].problem
    assert not up_strips.StripsEngine.supports(conditional.kind)


@pytest.mark.parametrize("task", IPC_TASKS)
def test_shared_ipc_task(task):
    ipc = small_bench("ipc")  # ../shared, or the repository's copy of these tasks
    domain, problem_file = ipc / task.split("/")[0] / "domain.pddl", ipc / f"{task}.pddl"
    problem = PDDLReader().parse_problem(str(domain), str(problem_file))
    with OneshotPlanner(name="strips") as planner:
        result = planner.solve(problem, timeout=60)
    assert result.status == UpStatus.SOLVED_SATISFICING and _valid(problem, result.plan)


def test_every_status_has_a_unified_planning_status():
    from strips_framework.result import Status
    from up_strips.engine import STATUS

    assert set(STATUS) == set(Status)
