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
from strips_framework.forward.eager import AStarSearch
from strips_framework.forward.lazy import LazyGreedySearch
from strips_framework.means_ends.model_astar import ModelAStarSearch
from strips_framework.means_ends.strategy import MeansEndsSearch
from strips_framework.planner import GROUND_STRATEGY, Planner
from strips_framework.plugin.config import DEFAULT_CHOICES
from strips_framework.plugin.registry import KINDS, Registry
from strips_framework.testing.declaration import (
    ConformanceFailure,
    check_declaration,
    check_options_refuse_wrong_values,
)
from strips_framework.testing.ground_search_checks import (
    TASK_LIMITS,
    check_expansion_limit,
    check_solves_task,
    check_unsolvable,
    ground_planner,
    solve_task,
)
from strips_framework.testing.ground_tasks import TASKS, UNSOLVABLE
from strips_framework.testing.heuristic_checks import check_heuristic
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
from strips_framework.testing.session_checks import (
    check_session_agrees_with_fresh_tasks,
    check_session_hides_and_revives_derived_clauses,
)
from strips_framework.worldmodel.proving import TheoremProver


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
    #: Models per random walk of the session check (two walks); a slow prover's own
    #: suite may take fewer.
    session_steps: ClassVar[int] = 40

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

    @pytest.mark.parametrize("seed", range(2))
    def test_session_answers_like_fresh_tasks(self, prover: TheoremProver, seed: int) -> None:
        check_session_agrees_with_fresh_tasks(
            prover, self.capabilities(), seed, self.session_steps
        )

    def test_session_hides_and_revives_derived_clauses(self, prover: TheoremProver) -> None:
        check_session_hides_and_revives_derived_clauses(prover)


def _planner(
    kind: str, cls: type, choices: Mapping[str, str], options: Mapping[str, Any]
) -> Planner:
    """A kit planner, or a skip when a partner it needs is not installed."""
    registry = Registry.from_plugins()
    for partner, name in {**DEFAULT_CHOICES, **choices}.items():
        if partner not in (kind, "strategy") and name not in registry.names(partner):
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
    """The kit for a world-model search strategy: set ``strategy_class``. It solves the
    kit's problems with the config's default partners (overridden by ``partners``); one
    declaring 'optimal' must find shortest plans with every installed admissible
    evaluator."""

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


class GroundStrategyConformance(_Conformance):
    """The kit for a ground-task search strategy: set ``strategy_class``. It solves the
    kit's PDDL tasks with every installed heuristic (or ``partners["heuristic"]``): plans
    valid under the lifted validator, cheapest ones when it declares 'optimal' and the
    heuristic 'admissible'; no plan on an unsolvable task; and it stops at an expansion
    limit. A strategy with ``complete = False`` may give up ('exhausted') but must solve
    some task."""

    kind = GROUND_STRATEGY
    slot = "strategy_class"
    strategy_class: ClassVar[type]
    partners: ClassVar[Mapping[str, str]] = {}

    def _ground_planners(self, limits: Mapping[str, float] = TASK_LIMITS) -> list[Planner]:
        """A planner per heuristic the kit runs the strategy with."""
        heuristics = [self.partners["heuristic"]] if "heuristic" in self.partners else (
            Registry.from_plugins().names("heuristic")
        )
        if not heuristics:
            pytest.skip(f"no {KINDS['heuristic'][1]} is installed")
        return [
            ground_planner(self.kind, self.strategy_class, {"heuristic": h}, self.options, limits)
            for h in heuristics
        ]

    @pytest.mark.parametrize("task", TASKS)
    def test_solves_task_with_each_heuristic(self, task: str) -> None:
        for planner in self._ground_planners():
            check_solves_task(planner, task)

    def test_incomplete_still_solves_some_task(self) -> None:
        if getattr(self.strategy_class, "complete", True):
            pytest.skip(f"{self.strategy_class.name!r} is complete: it must solve every task")
        planners = self._ground_planners()
        if not any(solve_task(p, task).solved for p in planners for task in TASKS):
            raise ConformanceFailure(
                f"{self.strategy_class.name!r} gives up on every kit task with every heuristic"
            )

    def test_no_plan_for_an_unsolvable_task(self) -> None:
        for planner in self._ground_planners():
            check_unsolvable(planner)

    def test_stops_at_an_expansion_limit(self) -> None:
        unlimited = self._ground_planners()
        limited = self._ground_planners({**TASK_LIMITS, "expansions": 1})
        for full, planner in zip(unlimited, limited):
            check_expansion_limit(planner, TASKS[0], solve_task(full, TASKS[0]))


class HeuristicConformance(_Conformance):
    """The kit for a state heuristic: set ``heuristic_class``. On every reachable state
    of the kit's PDDL tasks: 0 on goal states, no negative values, ``math.inf`` only on
    dead ends, applicable preferred operators (named only when 'preferred-operators' is
    declared), the same value when asked again; with 'admissible', never above the cost
    of a cheapest plan. Then lazy greedy search and A* solve the tasks with it."""

    kind = "heuristic"
    slot = "heuristic_class"
    heuristic_class: ClassVar[type]

    @pytest.mark.parametrize("task", (*TASKS, UNSOLVABLE))
    def test_estimates_on_every_reachable_state(self, task: str) -> None:
        check_heuristic(self.heuristic_class(**self.options), task, self.capabilities())

    @pytest.mark.parametrize("task", TASKS)
    @pytest.mark.parametrize("strategy", [LazyGreedySearch, AStarSearch], ids=lambda s: s.name)
    def test_guides_search(self, strategy: type, task: str) -> None:
        choices = {"strategy": strategy.name}
        planner = ground_planner("heuristic", self.heuristic_class, choices, self.options)
        check_solves_task(planner, task)
