"""The conformance kit catches broken plugins, and its own oracle is right."""

import itertools
import math
import textwrap
from collections.abc import Callable
from pathlib import Path
from typing import ClassVar

import pytest

from strips_framework.capabilities import (
    ADMISSIBLE,
    ANSWERS,
    EFFORT_BOUND,
    PREFERRED_OPERATORS,
    SOUND,
)
from strips_framework.formats.native import NativeLoader
from strips_framework.forward.result import ForwardStatistics
from strips_framework.grounding.task import GroundTask
from strips_framework.logic.terms import Param
from strips_framework.means_ends.node import Node
from strips_framework.options import Configurable, Option
from strips_framework.result import Result, Status
from strips_framework.testing import (
    CASES,
    TASKS,
    UNSOLVABLE,
    ConformanceFailure,
    check_admissible,
    check_case,
    check_declaration,
    check_effort_bound,
    check_expansion_limit,
    check_heuristic,
    check_options_refuse_wrong_values,
    check_solves_task,
    check_unsolvable,
    planner_for,
    recorded_search,
)
from strips_framework.testing.ground_search_checks import ground_planner
from strips_framework.testing.ground_tasks import task_space
from strips_framework.testing.search_checks import state_space
from strips_framework.worldmodel.proving import GAVE_UP, PROVED, SATURATED, ProofResult, ProofTask

pytest_plugins = ["pytester"]
CASE = {case.name: case for case in CASES}
DATA = Path(__file__).resolve().parent / "data"


class _Yes(Configurable):
    """Proves everything, binding every parameter of the goal to 'nowhere'."""

    name: ClassVar[str] = "yes"
    capabilities: ClassVar[frozenset[str]] = frozenset({ANSWERS, SOUND, EFFORT_BOUND})

    def prove(self, task: ProofTask) -> ProofResult:
        params = sorted({t for c in task.negated_goal for _, a in c.literals for t in a[1:]
                         if type(t) is Param})
        return ProofResult(PROVED, (tuple((p, "nowhere") for p in params),), effort_used=1)


class _No(Configurable):
    """Says Satisfiable to everything."""

    name: ClassVar[str] = "no"
    capabilities: ClassVar[frozenset[str]] = frozenset({ANSWERS, SOUND, EFFORT_BOUND})

    def prove(self, task: ProofTask) -> ProofResult:
        return ProofResult(SATURATED, uncompleted=task.negated_goal, effort_used=task.effort)


def test_a_prover_returning_wrong_witnesses_is_caught():
    with pytest.raises(ConformanceFailure, match=r"binding \{m=nowhere\} does not make the goal follow"):
        check_case(_Yes(), CASE["one-parameter"], _Yes.capabilities)


def test_a_prover_claiming_proofs_it_does_not_have_is_caught():
    with pytest.raises(ConformanceFailure, match="claims a proof, but the goal does not follow"):
        check_case(_Yes(), CASE["dollar-delete-hides-derived"], _Yes.capabilities)


def test_a_prover_calling_a_consequence_satisfiable_is_caught():
    with pytest.raises(ConformanceFailure, match="says Satisfiable, but the goal follows"):
        check_case(_No(), CASE["fact"], _No.capabilities)


def test_a_prover_ignoring_its_effort_bound_is_caught():
    with pytest.raises(ConformanceFailure, match="must give up on a hard goal"):
        check_effort_bound(_Yes())


def test_a_complete_prover_must_find_every_answer_asked_for():
    class _First(Configurable):
        name: ClassVar[str] = "first"

        def prove(self, task: ProofTask) -> ProofResult:
            return ProofResult(PROVED, (((Param("m"), "a"),),))

    check_case(_First(), CASE["several-answers"], {ANSWERS, SOUND})
    with pytest.raises(ConformanceFailure, match="1 binding.* of the 3 asked for"):
        check_case(_First(), CASE["several-answers"], {ANSWERS, SOUND, "complete"})


def test_declarations_are_checked():
    class _Silent(Configurable):
        name: ClassVar[str] = "silent"

    class _Typo(Configurable):
        name: ClassVar[str] = "typo"
        capabilities: ClassVar[frozenset[str]] = frozenset({"anwsers"})

    with pytest.raises(ConformanceFailure, match="'silent' declares no capabilities"):
        check_declaration(_Silent, "prover")
    with pytest.raises(ConformanceFailure, match=r"not in the prover vocabulary: \['anwsers'\]"):
        check_declaration(_Typo, "prover")


def test_options_declared_otherwise_are_caught():
    class _Lax:
        name: ClassVar[str] = "lax"
        capabilities: ClassVar[frozenset[str]] = frozenset()

        def __init__(self, strict: int = 1, patience: int = 3) -> None:
            self.strict, self.patience = strict, patience

    with pytest.raises(ConformanceFailure, match="takes strict, patience but declares no options"):
        check_declaration(_Lax, "prover")

    class _Typed(Configurable):
        name: ClassVar[str] = "typed"
        options = (Option("patience", int, 3),)

    check_options_refuse_wrong_values(_Typed)  # the option system refuses a wrong value


class _Overestimating(Configurable):
    """Claims admissible, but counts two steps per goal on the goal list, plus one."""

    name: ClassVar[str] = "overestimating"
    capabilities: ClassVar[frozenset[str]] = frozenset({ADMISSIBLE})
    admissible: ClassVar[bool] = True

    def evaluate(self, node: Node) -> float:
        return node.cost + 2.0 * len(node.goals) + 1


@pytest.mark.parametrize("strategy", ["means-ends", "model-astar"])
def test_an_evaluator_claiming_admissible_but_overestimating_is_caught(strategy):
    planner = planner_for("evaluator", _Overestimating, {"strategy": strategy})
    result, recorder = recorded_search(planner, "robot-door")
    with pytest.raises(ConformanceFailure, match="declares 'admissible' but scores"):
        check_admissible("robot-door", result, recorder)


def test_the_kits_optimum_is_the_known_one():
    assert [state_space(name).optimum for name in ("three-boxes", "robot-light", "robot-door")] == [4, 4, 3]
    from strips_framework.testing.optimum import StateSpace

    assert StateSpace(NativeLoader().load(DATA / "push-one-box.strips")).optimum == 2


def test_one_line_in_a_plugins_tests_runs_the_kit_and_reports_failures(pytester):
    pytester.makepyfile(test_broken=textwrap.dedent("""
        from typing import ClassVar
        from strips_framework.worldmodel.proving import ProofResult
        from strips_framework.testing import ProverConformance

        class Defeatist:
            name: ClassVar[str] = "defeatist"
            capabilities: ClassVar[frozenset[str]] = frozenset({"sound", "answers"})

            def prove(self, task):
                return ProofResult("Satisfiable", uncompleted=task.negated_goal)

        class TestDefeatist(ProverConformance):
            prover_class = Defeatist
    """))
    result = pytester.runpytest_inprocess("-q", "-p", "no:cacheprovider")
    outcomes = result.parseoutcomes()
    assert outcomes["failed"] >= 10 and outcomes["passed"] >= 5
    result.stdout.fnmatch_lines(["*says Satisfiable, but the goal follows*"])


def test_the_status_words_are_the_szs_ones():
    assert (PROVED, SATURATED, GAVE_UP) == ("Unsatisfiable", "Satisfiable", "GaveUp")


def test_the_suites_build_the_class_with_the_options_given(pytester):
    pytester.makepyfile(test_options=textwrap.dedent("""
        from typing import ClassVar
        from strips_framework.options import Configurable, Option
        from strips_framework.testing import EvaluatorConformance

        class Weighted(Configurable):
            name: ClassVar[str] = "weighted"
            capabilities: ClassVar[frozenset[str]] = frozenset()
            options = (Option("weight", float, 1.0),)

            def evaluate(self, node):
                return node.cost * self.weight

        class TestWeighted(EvaluatorConformance):
            evaluator_class = Weighted
            options = {"weight": 1.0}

        class TestWeightless(EvaluatorConformance):
            evaluator_class = Weighted
            options = {"weight": "heavy"}  # refused: every test of the kit fails
    """))
    result = pytester.runpytest_inprocess("-q", "-p", "no:cacheprovider", "-k", "declaration or three-boxes")
    result.assert_outcomes(passed=3, failed=3)
    result.stdout.fnmatch_lines(["*TestWeightless::test_declaration*"])


class _Estimator:
    """Estimates by a function of the task and the state; prefers what ``prefer`` says."""

    def __init__(
        self,
        task: GroundTask,
        value: Callable[[GroundTask, int], float],
        prefer: Callable[[GroundTask, int], list[int]],
    ) -> None:
        self.task, self.value, self.prefer = task, value, prefer

    def estimate(self, state: int) -> float:
        return self.value(self.task, state)

    def estimate_with_preferred(self, state: int) -> tuple[float, list[int]]:
        return self.value(self.task, state), self.prefer(self.task, state)


def _heuristic(name: str, value, claims=frozenset(), prefer=lambda task, state: []) -> type:
    """A state heuristic class named ``name`` declaring ``claims``."""

    class _Heuristic(Configurable):
        capabilities: ClassVar[frozenset[str]] = frozenset(claims)

        def for_task(self, task: GroundTask) -> _Estimator:
            return _Estimator(task, value, prefer)

    _Heuristic.name = name
    return _Heuristic


def _goals_left(task: GroundTask, state: int) -> float:
    return sum(1 for fact in task.goal if not state >> fact & 1)


def test_a_heuristic_claiming_admissible_but_overestimating_is_caught():
    doubled = _heuristic("doubled", lambda task, s: 2.0 * _goals_left(task, s), {ADMISSIBLE})
    with pytest.raises(ConformanceFailure, match="'admissible' but estimates 6.0 where .* costs 5"):
        check_heuristic(doubled(), "blocks-4", doubled.capabilities)
    check_heuristic(doubled(), "blocks-4", frozenset())  # fine when not claimed


def test_a_heuristic_calling_a_solvable_state_a_dead_end_is_caught():
    hopeless = _heuristic("hopeless", lambda task, state: 0 if task.is_goal(state) else math.inf)
    with pytest.raises(ConformanceFailure, match=r"math.inf \(a dead end\), but a plan of cost 3"):
        check_heuristic(hopeless(), "fuel-4", frozenset())
    check_heuristic(hopeless(), UNSOLVABLE, frozenset())  # there every state is a dead end


def test_a_heuristic_preferring_an_inapplicable_operator_is_caught():
    def inapplicable(task: GroundTask, state: int) -> list[int]:
        return [next(i for i, op in enumerate(task.operators) if not op.applicable(state))]

    pushy = _heuristic("pushy", _goals_left, {PREFERRED_OPERATORS}, inapplicable)
    with pytest.raises(ConformanceFailure, match="prefers .* which is not applicable there"):
        check_heuristic(pushy(), "gripper-3", pushy.capabilities)


def test_preferred_operators_must_match_the_declaration():
    def applicable(task: GroundTask, state: int) -> list[int]:
        return [i for i, op in enumerate(task.operators) if op.applicable(state)][:1]

    quiet = _heuristic("quiet", _goals_left, {PREFERRED_OPERATORS})
    with pytest.raises(ConformanceFailure, match="declares 'preferred-operators' but prefers no"):
        check_heuristic(quiet(), "circuit-1", quiet.capabilities)
    secretive = _heuristic("secretive", _goals_left, prefer=applicable)
    with pytest.raises(ConformanceFailure, match="but does not declare 'preferred-operators'"):
        check_heuristic(secretive(), "circuit-1", secretive.capabilities)


def test_a_heuristic_with_a_memory_is_caught():
    calls = itertools.count()
    moody = _heuristic("moody", lambda task, s: _goals_left(task, s) * (next(calls) % 2 + 1))
    with pytest.raises(ConformanceFailure, match="a heuristic must give a state the same value"):
        check_heuristic(moody(), "delivery-2", frozenset())


class _Hasty(Configurable):
    """Returns the first operator as the whole plan."""

    name: ClassVar[str] = "hasty"
    capabilities: ClassVar[frozenset[str]] = frozenset()
    complete: ClassVar[bool] = True

    def search_task(self, task, estimator, limits, clock=None) -> Result:
        return Result(Status.SOLVED, (task.operators[0].name,), 1, ForwardStatistics())


def test_a_ground_strategy_returning_an_invalid_plan_is_caught():
    planner = ground_planner("ground-strategy", _Hasty, {"heuristic": "blind"})
    with pytest.raises(ConformanceFailure, match="is not valid"):
        check_solves_task(planner, "blocks-4")
    with pytest.raises(ConformanceFailure, match="the task has no plan"):
        check_unsolvable(planner)
    limited = ground_planner("ground-strategy", _Hasty, {"heuristic": "blind"}, limits={"expansions": 1})
    unlimited = Result(Status.SOLVED, None, None, ForwardStatistics(expanded=5))
    with pytest.raises(ConformanceFailure, match="expected 'expansion-limit'"):
        check_expansion_limit(limited, "blocks-4", unlimited)


def test_the_kits_task_optima_are_the_known_ones():
    assert [task_space(name).optimum for name in (*TASKS, UNSOLVABLE)] == [6, 9, 14, 3, 5, math.inf]


def test_one_line_runs_the_heuristic_kit_and_reports_failures(pytester):
    pytester.makepyfile(test_broken_heuristic=textwrap.dedent("""
        import math
        from typing import ClassVar
        from strips_framework.testing import HeuristicConformance

        class Estimator:
            def __init__(self, task):
                self.task = task

            def estimate(self, state):
                return 0.0 if self.task.is_goal(state) else 100.0

            def estimate_with_preferred(self, state):
                return self.estimate(state), ()

        class Boastful:
            name: ClassVar[str] = "boastful"
            capabilities: ClassVar[frozenset[str]] = frozenset({"admissible"})

            def for_task(self, task):
                return Estimator(task)

        class TestBoastful(HeuristicConformance):
            heuristic_class = Boastful
    """))
    result = pytester.runpytest_inprocess("-q", "-p", "no:cacheprovider")
    outcomes = result.parseoutcomes()
    assert outcomes["failed"] == 5 and outcomes["passed"] >= 10  # the unsolvable task passes
    result.stdout.fnmatch_lines(["*declares 'admissible' but estimates 100.0*"])
