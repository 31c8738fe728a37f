"""The wrappers an observer puts around a search's evaluator or estimator (see
:mod:`strips_framework.observer`), and the base class that turns what they see into
events: a node scored (world-model strategies); a state numbered, estimated, an
expansion begun (forward search); the search finished.

Forward search is watched through its run: the estimator's ``watch(run)`` wraps the
run's ``space.add`` (every new state, with its parent and operator, in both the
compiled and the reference loops) and ``budget.check`` (called once per expansion), as
instance attributes, so only a watched run pays for them.
"""

from __future__ import annotations

import math
from array import array
from collections.abc import Mapping, Sequence
from typing import Any, ClassVar

from strips_framework.observer import watch_run

NO_PARENT = -1


class Watcher:
    """An observer of searches (:class:`~strips_framework.observer.SearchObserver`)
    whose subclasses override the event methods they care about. ``g`` holds the path
    cost of every state numbered so far in a forward search."""

    def __init__(self) -> None:
        self.run: Any = None
        self.task: Any = None
        self.g = array("d")
        self.expansions = 0
        self.evaluations = 0
        self._waiting: dict[int, tuple[float, Sequence[int]]] = {}

    # The observer protocol.
    def evaluator(self, inner: Any) -> WatchedEvaluator:
        return WatchedEvaluator(inner, self)

    def estimator(self, inner: Any, task: Any) -> WatchedEstimator:
        self.task = task
        return WatchedEstimator(inner, self)

    def finished(self, result: Any) -> None:
        """The search ended with ``result`` (called by the planner)."""

    # World-model events.
    def node_scored(self, node: Any, score: float, parts: Mapping[str, float] | None) -> None:
        """``node`` was scored ``score`` (``parts``: the evaluator's terms, if it names them)."""

    # Forward events.
    def state_reached(self, number: int, parent: int, operator: int) -> None:
        """State ``number`` was reached from ``parent`` by ``operator`` (-1, -1: the initial state)."""

    def state_estimated(self, number: int, h: float, preferred: Sequence[int]) -> None:
        """State ``number`` was estimated ``h`` (``math.inf``: a dead end)."""

    def expansion_begun(self, count: int) -> None:
        """Expansion number ``count`` (from 1) begins."""

    # Plumbing for the forward wrappers.
    def _watch(self, run: Any) -> None:
        self.run = run
        add, check = run.space.add, run.budget.check
        costs = run.space.costs

        def watched_add(state: int, parent: int, operator: int) -> int:
            number = add(state, parent, operator)
            self.g.append(0.0 if parent == NO_PARENT else self.g[parent] + costs[operator])
            self.state_reached(number, parent, operator)
            waiting = self._waiting.pop(state, None)
            if waiting is not None:  # eager search estimates a state before numbering it
                self.state_estimated(number, *waiting)
            return number

        def watched_check(expanded: int) -> None:
            check(expanded)
            self.expansions = expanded + 1
            self.expansion_begun(expanded + 1)

        run.space.add = watched_add
        run.budget.check = watched_check

    def _estimated(self, state: int, h: float, preferred: Sequence[int]) -> None:
        self.evaluations += 1
        number = self.run.space.number(state) if self.run is not None else None
        if number is None:
            self._waiting[state] = (h, preferred)
        else:
            self.state_estimated(number, h, preferred)


def evaluator_parts(evaluator: Any, node: Any) -> dict[str, float] | None:
    """The terms of ``evaluator``'s score of ``node``, if the evaluator names them
    (an optional ``parts(node)`` method; see docs/explore.md)."""
    parts = getattr(evaluator, "parts", None)
    return None if parts is None else dict(parts(node))


class WatchedEvaluator:
    """A node evaluator that scores as ``inner`` does and tells ``watcher``."""

    name: ClassVar[str] = "watched"

    def __init__(self, inner: Any, watcher: Watcher) -> None:
        self.inner = inner
        self.watcher = watcher

    @property
    def admissible(self) -> bool:
        return bool(getattr(self.inner, "admissible", False))

    def for_problem(self, operators: Any, initial: Any) -> WatchedEvaluator:
        """The inner evaluator prepared for the problem (when it needs it), still watched."""
        prepare = getattr(self.inner, "for_problem", None)
        return self if prepare is None else WatchedEvaluator(prepare(operators, initial), self.watcher)

    def evaluate(self, node: Any) -> float:
        score = self.inner.evaluate(node)
        self.watcher.node_scored(node, score, evaluator_parts(self.inner, node))
        return score

    def parts(self, node: Any) -> dict[str, float] | None:
        return evaluator_parts(self.inner, node)


class WatchedEstimator:
    """A state estimator that estimates as ``inner`` does and tells ``watcher``."""

    def __init__(self, inner: Any, watcher: Watcher) -> None:
        self.inner = inner
        self.watcher = watcher

    def watch(self, run: Any) -> None:
        watch_run(self.inner, run)
        self.watcher._watch(run)

    def estimate(self, state: int) -> float:
        h = self.inner.estimate(state)
        self.watcher._estimated(state, h, ())
        return h

    def estimate_with_preferred(self, state: int) -> tuple[float, Sequence[int]]:
        h, preferred = self.inner.estimate_with_preferred(state)
        self.watcher._estimated(state, h, preferred)
        return h, preferred


def path_numbers(space: Any, task: Any, plan: Sequence[str]) -> list[int]:
    """The numbers of the states along ``plan`` from the initial state."""
    if not len(space):
        return []
    by_name = {op.name: index for index, op in enumerate(task.operators)}
    state, numbers = task.init, [space.number(task.init) or 0]
    for step in plan:
        index = by_name.get(step)
        if index is None:
            break
        state = space.successor(state, index)
        number = space.number(state)
        if number is None:
            break
        numbers.append(number)
    return numbers


def finite(value: float) -> float | None:
    """``value`` for JSON: ``None`` for infinity (a dead end) or NaN."""
    return value if math.isfinite(value) else None
