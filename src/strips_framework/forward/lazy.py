"""Lazy greedy best-first search, as Fast Downward's ``lazy_greedy([h], preferred=[h])``.

A state is evaluated only when it comes out of the open list, not when it is generated:
expanding a state puts its successors in as *(state, operator)* pairs under the
expanded state's own estimate, so a state with many successors costs one heuristic call
instead of one per successor. A popped pair whose state was already reached is dropped
(no reopening). Preferred operators of the expanded state also put their pairs into a
second list; the two lists alternate and the preferred one gets ``boost`` extra turns
each time an expanded state's h is lower than any before it (not at the initial state;
Fast Downward's defaults: alternation, boost 1000).

The loop runs compiled (``_search.pyx``) when it is built; :meth:`LazyGreedySearch.reference_run`
is the pure-Python reference it is compared with, which ``STRIPS_PURE_PYTHON=1`` picks.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from typing import ClassVar

from strips_framework.compiled import compiled_module
from strips_framework.forward.base import ForwardStrategy, SearchRun
from strips_framework.forward.components import with_preferred
from strips_framework.forward.openlists import open_list
from strips_framework.forward.space import NO_PARENT
from strips_framework.options import Option


class LazyGreedySearch(ForwardStrategy):
    """Lazy greedy best-first search with deferred evaluation and preferred operators.
    Ties between equal estimates go first in, first out."""

    name: ClassVar[str] = "lazy-gbfs"
    options = (
        Option("preferred", bool, True, doc="a second open list for preferred operators"),
        Option("boost", int, 1000, minimum=0, doc="extra turns of that list on progress"),
    )
    preferred: bool
    boost: int

    def run(self, run: SearchRun) -> int | None:
        module = compiled_module("strips_framework.forward._search")
        if module is None:
            return self.reference_run(run)
        return module.lazy_greedy(run, self._evaluator(run), self.preferred, self.boost)

    def _evaluator(self, run: SearchRun) -> Callable[[int], tuple[float, Sequence[int]]]:
        """h and the preferred operators of a state (none unless ``preferred``)."""
        if self.preferred:
            return with_preferred(run.estimator)
        estimate = run.estimator.estimate

        def evaluate(state: int) -> tuple[float, tuple[int, ...]]:
            return estimate(state), ()

        return evaluate

    def reference_run(self, run: SearchRun) -> int | None:
        """The search in Python (the compiled loop's reference)."""
        task, space, budget = run.task, run.space, run.budget
        evaluate = self._evaluator(run)
        applicable, successor = space.successors.applicable, space.successor
        find, state_of, add, goal = space.number, space.state, space.add, task.goal_mask
        # An open entry is a (parent, operator) pair packed into one int.
        width = max(len(task.operators), 1)
        frontier = open_list(self.preferred, self.boost)
        best_h = math.inf
        parent, op, state = NO_PARENT, NO_PARENT, task.init
        while True:
            number = add(state, parent, op)
            h, preferred = evaluate(state)
            run.evaluated += 1
            if h == math.inf:
                run.dead_ends += 1
            elif state & goal == goal:
                return number
            else:
                budget.check(run.expanded)
                run.expanded += 1
                if h < best_h:
                    # The initial state's h only sets the mark, as in Fast Downward:
                    # boosting there would give the preferred list 1000 turns up front.
                    if best_h != math.inf:
                        frontier.reward_progress()
                    best_h = h
                successors = applicable(state)
                run.generated += len(successors)
                base = number * width
                frontier.push_all(
                    h, [base + op for op in successors], {base + op for op in preferred}
                )
            while True:
                if not frontier:
                    return None
                parent, op = divmod(frontier.pop(), width)
                state = successor(state_of(parent), op)
                if find(state) is None:
                    break
