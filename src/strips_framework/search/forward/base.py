"""What every forward strategy shares: the run's state space, counters and limits, and
turning the way a search ended into a :class:`ForwardResult`."""

from __future__ import annotations

import time
from typing import ClassVar

from strips_framework.grounding.task import GroundTask
from strips_framework.search.components import StateEstimator
from strips_framework.search.forward.budget import Budget, LimitReached, peak_mib
from strips_framework.search.forward.result import (
    EXHAUSTED_INCOMPLETE,
    INTERRUPTED,
    MEMORY_LIMIT,
    SOLVED,
    UNSOLVABLE,
    ForwardResult,
    ForwardStatistics,
)
from strips_framework.search.forward.space import StateSpace
from strips_framework.search.limits import Limits


class SearchRun:
    """One search: the state space, the estimator, the limits and the counters, which the
    strategies update in place so that a run stopped by a limit still reports them."""

    def __init__(
        self, task: GroundTask, estimator: StateEstimator, limits: Limits, started: float
    ) -> None:
        self.task = task
        self.estimator = estimator
        self.budget = Budget(limits, started)
        self.space = StateSpace(task)
        self.expanded = 0
        self.evaluated = 0
        self.generated = 0
        self.reopened = 0
        self.dead_ends = 0


class ForwardStrategy:
    """The base of the strategies over ground tasks: the planner gives them a
    :class:`GroundTask` and the heuristic's estimator instead of a first-order problem."""

    works_on: ClassVar[str] = "ground-task"
    capabilities: ClassVar[frozenset[str]] = frozenset()
    #: True when running out of states proves the task unsolvable.
    complete: ClassVar[bool] = True

    def search_task(
        self,
        task: GroundTask,
        estimator: StateEstimator,
        limits: Limits,
        started: float | None = None,
    ) -> ForwardResult:
        """Search ``task``; the time limit counts from ``started`` (default: now)."""
        begin = time.perf_counter()
        run = SearchRun(task, estimator, limits, begin if started is None else started)
        goal: int | None = None
        try:
            goal = self.run(run)
            status = (
                SOLVED
                if goal is not None
                else UNSOLVABLE
                if self.complete
                else EXHAUSTED_INCOMPLETE
            )
        except LimitReached as limit:
            status = limit.status
        except KeyboardInterrupt:  # Ctrl-C: report what the search did so far
            status = INTERRUPTED
        except MemoryError:
            run.space.clear()  # let the search's memory go before anything else is made
            status = MEMORY_LIMIT
        statistics = ForwardStatistics(
            expanded=run.expanded,
            evaluated=run.evaluated,
            generated=run.generated,
            reopened=run.reopened,
            dead_ends=run.dead_ends,
            facts=len(task.facts),
            operators=len(task.operators),
            search_seconds=time.perf_counter() - begin,
            peak_memory_mib=peak_mib(),
        )
        if goal is None:
            return ForwardResult(status, None, None, statistics, task.uses_costs)
        steps = run.space.plan_to(goal)
        operators = task.operators
        cost = sum(run.space.costs[i] for i in steps)
        return ForwardResult(
            status, tuple(operators[i].name for i in steps), cost, statistics, task.uses_costs
        )

    def run(self, run: SearchRun) -> int | None:
        """The search proper: the number of a goal state, or None when out of states."""
        raise NotImplementedError
