"""What every forward strategy shares: the run's state space, counters and limits, and
turning the way a search ended into a :class:`~strips_framework.result.Result`."""

from __future__ import annotations

from typing import ClassVar

from strips_framework.forward.budget import Budget, peak_mib
from strips_framework.forward.components import StateEstimator
from strips_framework.forward.result import ForwardStatistics
from strips_framework.forward.space import StateSpace
from strips_framework.grounding.task import GroundTask
from strips_framework.limits import Clock, LimitReached, Limits
from strips_framework.observer import watch_run
from strips_framework.options import Configurable
from strips_framework.result import Result, Status


class SearchRun:
    """One search: the state space, the estimator, the limits and the counters, which the
    strategies update in place so that a run stopped by a limit still reports them."""

    def __init__(
        self, task: GroundTask, estimator: StateEstimator, limits: Limits, clock: Clock
    ) -> None:
        self.task = task
        self.estimator = estimator
        self.budget = Budget(limits, clock)
        self.space = StateSpace(task)
        self.expanded = 0
        self.evaluated = 0
        self.generated = 0
        self.reopened = 0
        self.dead_ends = 0
        watch_run(estimator, self)  # an observer's estimator (--explore) sees the run


class ForwardStrategy(Configurable):
    """The base of the strategies over ground tasks (the ``ground-strategy`` plugin kind,
    :class:`~strips_framework.means_ends.components.GroundTaskStrategy`): the planner gives
    them a :class:`GroundTask` and the heuristic's estimator instead of a first-order
    problem."""

    capabilities: ClassVar[frozenset[str]] = frozenset()
    #: True when running out of states proves the task unsolvable.
    complete: ClassVar[bool] = True

    def search_task(
        self,
        task: GroundTask,
        estimator: StateEstimator,
        limits: Limits,
        clock: Clock | None = None,
    ) -> Result:
        """Search ``task``; the time limit counts from the start of ``clock`` (default:
        now)."""
        clock = clock or Clock(limits.time)
        begin = clock.elapsed()
        run = SearchRun(task, estimator, limits, clock)
        goal: int | None = None
        try:
            goal = self.run(run)
            status = (
                Status.SOLVED
                if goal is not None
                else Status.UNSOLVABLE
                if self.complete
                else Status.EXHAUSTED
            )
        except LimitReached as limit:
            status = limit.status
        except KeyboardInterrupt:  # Ctrl-C: report what the search did so far
            status = Status.INTERRUPTED
        except MemoryError:
            run.space.clear()  # let the search's memory go before anything else is made
            status = Status.MEMORY_LIMIT
        statistics = ForwardStatistics(
            expanded=run.expanded,
            evaluated=run.evaluated,
            generated=run.generated,
            reopened=run.reopened,
            dead_ends=run.dead_ends,
            facts=len(task.facts),
            operators=len(task.operators),
            search_seconds=clock.elapsed() - begin,
            peak_memory_mib=peak_mib(),
        )
        if goal is None:
            return Result(status, None, None, statistics, clock.elapsed(), task.uses_costs)
        steps = run.space.plan_to(goal)
        operators = task.operators
        cost = sum(run.space.costs[i] for i in steps)
        plan = tuple(operators[i].name for i in steps)
        return Result(status, plan, cost, statistics, clock.elapsed(), task.uses_costs)

    def run(self, run: SearchRun) -> int | None:
        """The search proper: the number of a goal state, or None when out of states."""
        raise NotImplementedError
