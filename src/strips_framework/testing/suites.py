"""The pytest suites a plugin's tests inherit: one class statement runs the whole kit.

    from strips_framework.testing import ProverConformance

    class TestMyProver(ProverConformance):
        prover_class = MyProver

pytest collects the inherited ``test_*`` methods in the subclass (the base classes do
not start with ``Test``, so they are not collected themselves). Cases that exercise a
capability the class does not declare are skipped, with the reason; a failure message
says which case, what the plugin answered and what was expected.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any, ClassVar

import pytest

from strips_framework.capabilities import (
    ADMISSIBLE,
    EFFORT_BOUND,
    OPTIMAL,
    UNCOMPLETED_PROOF,
    declared,
)
from strips_framework.config import DEFAULT_CHOICES
from strips_framework.planner import Planner
from strips_framework.plugins import KINDS, Registry
from strips_framework.proving import TheoremProver
from strips_framework.search.model_astar import ModelAStarSearch
from strips_framework.search.means_ends import MeansEndsSearch
from strips_framework.testing.declaration import (
    check_declaration,
    check_options_refuse_wrong_values,
)
from strips_framework.testing.prover_cases import CASES, ProverCase
from strips_framework.testing.prover_checks import (
    check_case,
    check_effort_bound,
    check_refuses_unsupported,
    check_uncompleted_proof,
)
from strips_framework.testing.search_checks import (
    PROBLEMS,
    check_admissible,
    check_plan,
    check_solves,
    planner_for,
    recorded_search,
)


class _Conformance:
    """What every kind's suite checks: the declaration and the options."""

    kind: ClassVar[str]
    #: The class attribute a plugin's test sets: ``prover_class`` and so on.
    slot: ClassVar[str]
    #: Options to build the class with (as a config table would give them), when its
    #: defaults are not what should be checked, or it has options without defaults.
    options: ClassVar[Mapping[str, Any]] = {}

    @classmethod
    def implementation(cls) -> type:
        return getattr(cls, cls.slot)

    @classmethod
    def capabilities(cls) -> frozenset[str]:
        return declared(cls.implementation(), cls.kind) or frozenset()

    def test_declaration(self) -> None:
        check_declaration(self.implementation(), self.kind, self.options)

    def test_options_refuse_wrong_values(self) -> None:
        check_options_refuse_wrong_values(self.implementation(), self.options)

    def _require(self, capability: str) -> None:
        if capability not in self.capabilities():
            pytest.skip(f"{self.implementation().name!r} does not declare {capability!r}")


class ProverConformance(_Conformance):
    """The kit for a theorem prover: set ``prover_class`` (and ``options``, if the
    defaults are not what should be checked)."""

    kind = "prover"
    slot = "prover_class"
    prover_class: ClassVar[type]

    @pytest.fixture
    def prover(self) -> TheoremProver:
        return self.prover_class(**self.options)

    @pytest.mark.parametrize("case", CASES, ids=lambda case: case.name)
    def test_known_answer(self, prover: TheoremProver, case: ProverCase) -> None:
        missing = case.needs - self.capabilities()
        if missing:
            pytest.skip(f"{self.prover_class.name!r} does not declare {sorted(missing)}")
        check_case(prover, case, self.capabilities())

    def test_uncompleted_proof_holds_what_is_left(self, prover: TheoremProver) -> None:
        self._require(UNCOMPLETED_PROOF)
        check_uncompleted_proof(prover)

    def test_tiny_effort_gives_up_deterministically(self, prover: TheoremProver) -> None:
        self._require(EFFORT_BOUND)
        check_effort_bound(prover)

    def test_refuses_what_it_does_not_support(self, prover: TheoremProver) -> None:
        check_refuses_unsupported(prover, self.capabilities())


def _planner(
    kind: str, cls: type, choices: Mapping[str, str], options: Mapping[str, Any]
) -> Planner:
    """A kit planner, or a skip when a partner it needs is not installed."""
    registry = Registry.from_plugins()
    for partner, name in {**DEFAULT_CHOICES, **choices}.items():
        if partner != kind and name not in registry.names(partner):
            pytest.skip(
                f"the kit runs {cls.name!r} with {KINDS[partner][1]} {name!r}, which is not "
                f"installed; install it or set partners = {{{partner!r}: ...}}"
            )
    return planner_for(kind, cls, choices, options)


class EvaluatorConformance(_Conformance):
    """The kit for a node evaluator: set ``evaluator_class``. Both builtin strategies
    solve the kit's problems with it (the other components are the config defaults,
    overridden by ``partners``, e.g. ``{"prover": "z3"}``); an evaluator declaring
    'admissible' has its scores checked against the true costs."""

    kind = "evaluator"
    slot = "evaluator_class"
    evaluator_class: ClassVar[type]
    partners: ClassVar[Mapping[str, str]] = {}

    @pytest.mark.parametrize("problem", PROBLEMS)
    @pytest.mark.parametrize("strategy", [MeansEndsSearch.name, ModelAStarSearch.name])
    def test_solves_and_scores_within_the_true_cost(self, strategy: str, problem: str) -> None:
        choices = {**self.partners, "strategy": strategy}
        planner = _planner("evaluator", self.evaluator_class, choices, self.options)
        result, recorder = recorded_search(planner, problem)
        check_plan(planner, problem, result)
        if ADMISSIBLE in self.capabilities():
            check_admissible(problem, result, recorder)


class StrategyConformance(_Conformance):
    """The kit for a search strategy: set ``strategy_class``. It solves the kit's problems
    with the config's default partners (overridden by ``partners``); a strategy declaring
    'optimal' must find shortest plans with every installed admissible evaluator."""

    kind = "strategy"
    slot = "strategy_class"
    strategy_class: ClassVar[type]
    partners: ClassVar[Mapping[str, str]] = {}

    @pytest.mark.parametrize("problem", PROBLEMS)
    def test_solves(self, problem: str) -> None:
        planner = _planner("strategy", self.strategy_class, self.partners, self.options)
        check_solves(planner, problem)

    @pytest.mark.parametrize("problem", PROBLEMS)
    def test_optimal_with_admissible_evaluators(self, problem: str) -> None:
        self._require(OPTIMAL)
        registry = Registry.from_plugins()
        admissible = [
            r.name
            for r in registry.registrations("evaluator")
            if ADMISSIBLE in (declared(r.cls, "evaluator") or ())
        ]
        if not admissible:
            pytest.skip(f"no installed {KINDS['evaluator'][1]} declares 'admissible'")
        for evaluator in admissible:
            choices = {**DEFAULT_CHOICES, **self.partners, "evaluator": evaluator}
            planner = _planner("strategy", self.strategy_class, choices, self.options)
            check_solves(planner, problem)
