"""Checks of strategies and evaluators by solving the kit's small problems.

A run goes through :class:`~strips_framework.planner.Planner` like a user's, so the
config-time capability check applies. Every plan found is replayed in the independent
simulator; an evaluator's scores are recorded as the search asks for them and, when it
claims ``admissible``, compared with the true cost through each node, computed by
:class:`~strips_framework.testing.optimum.StateSpace` without the planner's reasoning.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from functools import cache
from importlib import resources
from pathlib import Path
from types import MappingProxyType, SimpleNamespace
from typing import Any, ClassVar

from strips_framework.capabilities import ADMISSIBLE, OPTIMAL, declared
from strips_framework.formats.native import NativeLoader
from strips_framework.logic.formulas import formula_to_str
from strips_framework.means_ends.components import evaluator_for_problem
from strips_framework.means_ends.node import Node
from strips_framework.planner import Planner
from strips_framework.plugin.config import DEFAULT_CHOICES, TABLE_OF, Config
from strips_framework.plugin.hookspecs import hookimpl
from strips_framework.plugin.registry import KINDS, Registry
from strips_framework.result import Result
from strips_framework.testing.declaration import ConformanceFailure
from strips_framework.testing.optimum import StateSpace
from strips_framework.worldmodel.problem import OperatorSchema, Problem
from strips_framework.worldmodel.simulate import replay
from strips_framework.worldmodel.world import InitialModel

#: The kit's problems: the paper's 3-boxes task and two tasks in a small robot world
#: (one needs ``$`` deletes and four steps, one needs quantified axioms to pass a door).
PROBLEMS = ("three-boxes", "robot-light", "robot-door")
#: Limits of a kit run: each problem needs well under a thousand nodes.
LIMITS = {"nodes": 5000, "time": 120, "effort": 300}
#: At most this many nodes of a run have their true cost computed (the solution path and
#: an even sample of the rest), which keeps an admissibility check to about a second.
CHECKED_NODES = 60


@cache
def load(name: str) -> Problem:
    """One of :data:`PROBLEMS`, read from the package's data."""
    with resources.as_file(resources.files(__package__) / "problems" / f"{name}.strips") as path:
        return NativeLoader().load(Path(path))


@cache
def state_space(name: str) -> StateSpace:
    return StateSpace(load(name))


def planner_for(
    kind: str,
    cls: type,
    choices: Mapping[str, str],
    options: Mapping[str, Any] = MappingProxyType({}),
    limits: Mapping[str, float] = MappingProxyType(LIMITS),
) -> Planner:
    """A planner using ``cls`` with ``options`` for ``kind``, ``choices`` (over the
    defaults) for the rest and ``limits``; ``cls`` is registered for the run unless an
    installed plugin already is it."""
    table = TABLE_OF.get(kind, kind)
    tables: dict[str, Any] = {**DEFAULT_CHOICES, **choices, table: {**options, "name": cls.name}}
    config = Config.from_dict(
        {**tables, "limits": dict(limits)}, f"<conformance kit: {kind} {cls.name!r}>"
    )
    installed = Registry.from_plugins()
    if cls.name in installed.names(kind) and installed.get(kind, cls.name).cls is cls:
        return Planner.create(config)
    plugin = SimpleNamespace(**{KINDS[kind][0]: hookimpl(lambda: [cls])})
    return Planner.create(config, extra_plugins=[plugin])


def check_solves(planner: Planner, name: str) -> Result:
    """The planner solves problem ``name`` and its plan replays; a strategy declaring
    'optimal', with an evaluator declaring 'admissible', finds a shortest plan."""
    result = planner.solve(load(name))
    check_plan(planner, name, result)
    return result


def check_plan(planner: Planner, name: str, result: Result) -> None:
    """What :func:`check_solves` checks, of a result already found."""
    problem = load(name)
    what = f"{_describe(planner)} on {name}"
    if not result.solved:
        raise ConformanceFailure(f"{what}: {result.status} after {result.statistics.nodes} nodes")
    steps = [str(step) for step in result.plan]
    outcome = replay(problem, steps)
    if not outcome.valid:
        raise ConformanceFailure(f"{what}: the plan {steps} does not replay: {outcome.message}")
    strategy = planner.registry.get("strategy", planner.config.choices["strategy"].name)
    evaluator = planner.registry.get("evaluator", planner.config.choices["evaluator"].name)
    if OPTIMAL in (declared(strategy.cls, "strategy") or ()) and ADMISSIBLE in (
        declared(evaluator.cls, "evaluator") or ()
    ):
        optimum = state_space(name).optimum
        if len(steps) != optimum:
            raise ConformanceFailure(
                f"{what}: a plan of {len(steps)} steps {steps}, but the shortest has {optimum}; "
                "an 'optimal' strategy with an 'admissible' evaluator must find one"
            )


class ScoreRecorder:
    """Wraps an evaluator and records each node it scores with the score it gave
    (mutable: ``scores`` grows)."""

    name: ClassVar[str] = "kit-score-recorder"
    __slots__ = ("inner", "scores")

    def __init__(self, inner: Any, scores: list[tuple[Node, float]] | None = None) -> None:
        self.inner = inner
        self.scores: list[tuple[Node, float]] = [] if scores is None else scores

    @property
    def admissible(self) -> bool:
        return bool(getattr(self.inner, "admissible", False))

    def for_problem(
        self, operators: Sequence[OperatorSchema], initial: InitialModel
    ) -> ScoreRecorder:
        """The inner evaluator prepared for the problem, recording into the same list."""
        return ScoreRecorder(evaluator_for_problem(self.inner, operators, initial), self.scores)

    def evaluate(self, node: Node) -> float:
        score = self.inner.evaluate(node)
        self.scores.append((node, score))
        return score


def recorded_search(planner: Planner, name: str) -> tuple[Result, ScoreRecorder]:
    """Solve ``name`` with the planner's components, recording the evaluator's scores."""
    build = planner.config.build
    recorder = ScoreRecorder(build(planner.registry, "evaluator"))
    result = build(planner.registry, "strategy").search(
        load(name),
        build(planner.registry, "prover"),
        build(planner.registry, "difference"),
        build(planner.registry, "relevance"),
        recorder,
        planner.config.limits,
    )
    return result, recorder


def check_admissible(name: str, result: Result, recorder: ScoreRecorder) -> int:
    """No recorded score exceeds the node's cost so far plus the least cost still needed
    (on the solution path and an even sample of the other nodes); returns how many nodes
    were checked."""
    space = state_space(name)
    assert result.tree is not None, "a world-model search returns its tree"
    on_path = {id(node) for node in result.tree.solution_path()}
    scored = recorder.scores
    path_scores = [(n, s) for n, s in scored if id(n) in on_path]
    others = [(n, s) for n, s in scored if id(n) not in on_path]
    room = max(CHECKED_NODES - len(path_scores), 0)
    stride = max(len(others) // room, 1) if room else len(others) + 1
    sample = path_scores + others[::stride][:room]
    for node, score in sample:
        if score <= node.cost + len(node.goals) - 1:
            continue  # each goal above G0 costs its operator's application: no search needed
        state = frozenset(node.model.facts())
        true_cost = node.cost + space.cost_to_go(state, node.goals)
        if score > true_cost + 1e-9:
            goals = " ; ".join(formula_to_str(goal.formula) for goal in node.goals)
            raise ConformanceFailure(
                f"evaluator {recorder.inner.name!r} declares 'admissible' but scores {score} "
                f"a node of {name} whose cheapest completion costs {true_cost} "
                f"(node {node.id}: {node.cost} steps so far, goal list [{goals}])"
            )
    return len(sample)


def _describe(planner: Planner) -> str:
    choices = planner.config.choices
    return ", ".join(f"{kind} {choices[kind].name!r}" for kind in ("strategy", "evaluator", "prover"))
