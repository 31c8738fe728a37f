"""The ``strips`` engine: a Unified Planning problem is written as PDDL with UP's own
writer, read by strips-framework's PDDL reader, solved by the planner with the defaults
of ``strips solve`` (lazy greedy search with hFF when grounding looks cheap, else the
searches that never ground; the choice and its reason are an INFO log message) or the
strategy, heuristic, prover and evaluator the ``params`` choose, and the plan is mapped
back to the problem's own actions and objects.

Going through PDDL text keeps one reader (with its checks and error messages) between UP
and the planner, and the writer's name table maps every step back exactly, as the
Fast Downward and ENHSP integrations do.
"""

from __future__ import annotations

import re
import warnings
from collections.abc import Callable
from typing import IO, Any

import unified_planning as up
from unified_planning.engines import (
    Credits,
    Engine,
    PlanGenerationResult,
    PlanGenerationResultStatus,
)
from unified_planning.engines.mixins import OneshotPlannerMixin
from unified_planning.engines.mixins.oneshot_planner import OptimalityGuarantee
from unified_planning.io import PDDLWriter
from unified_planning.model import ProblemKind
from unified_planning.plans import ActionInstance, SequentialPlan

from strips_framework import __version__
from strips_framework.capabilities import ADMISSIBLE, OPTIMAL, declared
from strips_framework.errors import StripsError
from strips_framework.limits import Clock
from strips_framework.pddl import parse_task
from strips_framework.planner import GROUND_STRATEGY, Planner
from strips_framework.portfolio import Portfolio
from strips_framework.result import Result, Status

Status_ = PlanGenerationResultStatus

#: How each strips-framework status reads in Unified Planning (``solved`` is refined to
#: SOLVED_OPTIMALLY when the strategy declares 'optimal' and its partner 'admissible').
STATUS = {
    Status.SOLVED: Status_.SOLVED_SATISFICING,
    Status.UNSOLVABLE: Status_.UNSOLVABLE_PROVEN,
    Status.EXHAUSTED: Status_.UNSOLVABLE_INCOMPLETELY,
    Status.NODE_LIMIT: Status_.UNSOLVABLE_INCOMPLETELY,
    Status.EXPANSION_LIMIT: Status_.UNSOLVABLE_INCOMPLETELY,
    Status.TIME_LIMIT: Status_.TIMEOUT,
    Status.MEMORY_LIMIT: Status_.MEMOUT,
    # UP has no word for a run stopped by the user: no plan, nothing proved.
    Status.INTERRUPTED: Status_.UNSOLVABLE_INCOMPLETELY,
}

#: The config tables a param may name directly (``params={"heuristic": "lmcut"}``).
COMPONENT_PARAMS = ("strategy", "heuristic", "prover", "evaluator")

credits = Credits(
    "strips",
    "strips-framework",
    "",
    "",
    "MIT",
    "STRIPS (Fikes & Nilsson, 1971) revived: means-ends planning over first-order world "
    "models, and forward search (A*, greedy best-first, hill-climbing) with FD-style "
    "heuristics over grounded PDDL.",
    "strips-framework: forward search with hFF, LM-cut and landmarks; means-ends analysis "
    "with a resolution prover.",
)


class StripsEngine(Engine, OneshotPlannerMixin):
    """One-shot planner ``strips``.

    ``params`` (all optional): ``strategy``, ``heuristic``, ``prover``, ``evaluator``: an
    implementation name or a table of name and options, as in the TOML config
    (``{"strategy": {"name": "wastar", "weight": 3}}``); ``limits``: the ``[limits]``
    table (``time`` is overridden by the ``timeout`` given to ``solve``).
    """

    def __init__(self, **params: Any) -> None:
        Engine.__init__(self)
        OneshotPlannerMixin.__init__(self)
        unknown = sorted(set(params) - {*COMPONENT_PARAMS, "limits"})
        if unknown:
            raise up.exceptions.UPUsageError(
                f"strips: unknown params {unknown} (known: {', '.join(COMPONENT_PARAMS)}, limits)"
            )
        self._params = params
        self._planner(None).for_pddl()  # a bad choice or option is reported here, not later

    @property
    def name(self) -> str:
        return "strips"

    @staticmethod
    def supported_kind() -> ProblemKind:
        """What the PDDL reader and the grounder handle (docs/pddl.md): classical
        action-based problems with typing, negative, disjunctive, equality and quantified
        conditions, and integer action costs. No conditional or quantified effects, no
        numeric fluents, no time."""
        kind = ProblemKind(version=2)
        kind.set_problem_class("ACTION_BASED")
        for typing in ("FLAT_TYPING", "HIERARCHICAL_TYPING"):
            kind.set_typing(typing)
        for condition in (
            "NEGATIVE_CONDITIONS",
            "DISJUNCTIVE_CONDITIONS",
            "EQUALITIES",
            "EXISTENTIAL_CONDITIONS",
            "UNIVERSAL_CONDITIONS",
        ):
            kind.set_conditions_kind(condition)
        kind.set_quality_metrics("ACTIONS_COST")
        kind.set_quality_metrics("PLAN_LENGTH")
        kind.set_actions_cost_kind("INT_NUMBERS_IN_ACTIONS_COST")
        return kind

    @staticmethod
    def supports(problem_kind: ProblemKind) -> bool:
        return problem_kind <= StripsEngine.supported_kind()

    @staticmethod
    def satisfies(optimality_guarantee: OptimalityGuarantee) -> bool:
        """Satisficing by default (lazy greedy search); with ``params`` choosing ``astar``
        and an admissible heuristic a run reports SOLVED_OPTIMALLY, but the class cannot
        promise it for every configuration."""
        return optimality_guarantee == OptimalityGuarantee.SATISFICING

    @staticmethod
    def get_credits(**kwargs: Any) -> Credits:
        return credits

    def _planner(self, timeout: float | None) -> Planner:
        config: dict[str, Any] = {k: v for k, v in self._params.items() if k != "limits"}
        limits = dict(self._params.get("limits", {}))
        if timeout is not None:
            limits["time"] = float(timeout)
        config["limits"] = limits
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # soft capability warnings: the user chose
            return Planner.create(config)

    def _solve(
        self,
        problem: up.model.AbstractProblem,
        heuristic: Callable[[up.model.state.State], float | None] | None = None,
        timeout: float | None = None,
        output_stream: IO[str] | None = None,
    ) -> PlanGenerationResult:
        assert isinstance(problem, up.model.Problem)
        if heuristic is not None:
            warnings.warn("strips: a custom heuristic is not supported; ignored", stacklevel=2)
        planner = self._planner(timeout)
        clock = Clock(planner.config.limits.time)  # the timeout covers writing and reading
        writer = PDDLWriter(problem)
        try:
            task = parse_task(
                writer.get_domain(), writer.get_problem(), "<UP domain>", "<UP problem>"
            )
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                search, reason = planner.for_pddl_task(task)
            result = search.solve_pddl(task, clock, parse_seconds=clock.elapsed())
        except StripsError as error:
            return PlanGenerationResult(
                Status_.UNSUPPORTED_PROBLEM, None, self.name, log_messages=[_log(error)]
            )
        if output_stream is not None:
            from strips_framework.cli.report import text_lines

            output_stream.write("\n".join(text_lines(result)) + "\n")
        plan = None
        if result.plan is not None:
            plan = SequentialPlan([_action_instance(writer, step) for step in result.plan])
        chosen = [_log(reason, up.engines.LogLevel.INFO)] if reason else []
        return PlanGenerationResult(
            _status(search, result),
            plan,
            self.name,
            metrics=_metrics(result),
            log_messages=chosen,
        )


_STEP = re.compile(r"^\((\S+)((?:\s+\S+)*)\)$")


def _action_instance(writer: PDDLWriter, step: str) -> ActionInstance:
    """The problem's own action and objects for the IPC step ``(name arg ...)``."""
    match = _STEP.match(step)
    assert match is not None, f"not an IPC step: {step!r}"
    action = writer.get_item_named(match.group(1))
    arguments = [writer.get_item_named(name) for name in match.group(2).split()]
    return ActionInstance(action, arguments)  # type: ignore[arg-type]


def _status(planner: Planner | Portfolio, result: Result) -> PlanGenerationResultStatus:
    status = STATUS[result.status]
    if status != Status_.SOLVED_SATISFICING or not isinstance(planner, Planner):
        return status  # a portfolio's searches are satisficing
    if not planner.searches_ground_tasks:
        return status
    strategy = planner.registry.get(GROUND_STRATEGY, planner.config.choice(GROUND_STRATEGY).name)
    heuristic = planner.registry.get("heuristic", planner.config.choice("heuristic").name)
    if OPTIMAL in (declared(strategy.cls, GROUND_STRATEGY) or ()) and ADMISSIBLE in (
        declared(heuristic.cls, "heuristic") or ()
    ):
        return Status_.SOLVED_OPTIMALLY
    return status


def _metrics(result: Result) -> dict[str, str]:
    """UP's ``engine_internal_time`` and the family's figures, as strings."""
    figures = {name: str(value) for name, value in result.statistics.as_dict().items()}
    return {"engine_internal_time": f"{result.seconds:.6f}", **figures}


def _log(
    message: StripsError | str, level: up.engines.LogLevel = up.engines.LogLevel.ERROR
) -> up.engines.LogMessage:
    return up.engines.LogMessage(level, f"strips {__version__}: {message}")
