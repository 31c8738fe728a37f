"""The conformance kit catches broken plugins, and its own oracle is right."""

import textwrap
from pathlib import Path
from typing import ClassVar

import pytest
from attrs import field, frozen, validators

from strips_framework.capabilities import ADMISSIBLE, ANSWERS, EFFORT_BOUND, SOUND
from strips_framework.formats.native import NativeLoader
from strips_framework.logic.terms import Param
from strips_framework.proving import GAVE_UP, PROVED, SATURATED, ProofResult, ProofTask
from strips_framework.search.node import Node
from strips_framework.testing import (
    CASES,
    ConformanceFailure,
    check_admissible,
    check_case,
    check_declaration,
    check_effort_bound,
    check_options_refuse_wrong_values,
    planner_for,
    recorded_search,
)
from strips_framework.testing.search_checks import state_space

pytest_plugins = ["pytester"]
CASE = {case.name: case for case in CASES}
DATA = Path(__file__).resolve().parent / "data"


@frozen
class _Yes:
    """Proves everything, binding every parameter of the goal to 'nowhere'."""

    name: ClassVar[str] = "yes"
    capabilities: ClassVar[frozenset[str]] = frozenset({ANSWERS, SOUND, EFFORT_BOUND})

    def prove(self, task: ProofTask) -> ProofResult:
        params = sorted({t for c in task.negated_goal for _, a in c.literals for t in a[1:]
                         if type(t) is Param})
        return ProofResult(PROVED, (tuple((p, "nowhere") for p in params),), effort_used=1)


@frozen
class _No:
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
    @frozen
    class _First:
        name: ClassVar[str] = "first"

        def prove(self, task: ProofTask) -> ProofResult:
            return ProofResult(PROVED, (((Param("m"), "a"),),))

    check_case(_First(), CASE["several-answers"], {ANSWERS, SOUND})
    with pytest.raises(ConformanceFailure, match="1 binding.* of the 3 asked for"):
        check_case(_First(), CASE["several-answers"], {ANSWERS, SOUND, "complete"})


def test_declarations_are_checked():
    @frozen
    class _Silent:
        name: ClassVar[str] = "silent"

    @frozen
    class _Typo:
        name: ClassVar[str] = "typo"
        capabilities: ClassVar[frozenset[str]] = frozenset({"anwsers"})

    with pytest.raises(ConformanceFailure, match="'silent' declares no capabilities"):
        check_declaration(_Silent, "prover")
    with pytest.raises(ConformanceFailure, match=r"not in the prover vocabulary: \['anwsers'\]"):
        check_declaration(_Typo, "prover")


def test_options_without_validation_are_caught():
    @frozen
    class _Lax:
        name: ClassVar[str] = "lax"
        strict: int = field(default=1, validator=validators.instance_of(int))
        patience: int = 3

    with pytest.raises(ConformanceFailure, match="option 'patience' accepts"):
        check_options_refuse_wrong_values(_Lax)


@frozen
class _Overestimating:
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
        from attrs import frozen
        from strips_framework.proving import ProofResult
        from strips_framework.testing import ProverConformance

        @frozen
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
        from attrs import field, frozen, validators
        from strips_framework.testing import EvaluatorConformance

        @frozen
        class Weighted:
            name: ClassVar[str] = "weighted"
            capabilities: ClassVar[frozenset[str]] = frozenset()
            weight: float = field(validator=validators.instance_of(float))  # no default

            def evaluate(self, node):
                return node.cost * self.weight

        class TestWeighted(EvaluatorConformance):
            evaluator_class = Weighted
            options = {"weight": 1.0}

        class TestWeightless(EvaluatorConformance):
            evaluator_class = Weighted
    """))
    result = pytester.runpytest_inprocess("-q", "-p", "no:cacheprovider", "-k", "declaration or three-boxes")
    result.assert_outcomes(passed=3, failed=3)
    result.stdout.fnmatch_lines(["*TestWeightless::test_declaration*"])
