"""Lazy greedy best-first search, as Fast Downward's ``lazy_greedy([h], preferred=[h])``.

A state is evaluated only when it comes out of the open list, not when it is generated:
expanding a state puts its successors in under the expanded state's own estimate, so a
state with many successors costs one heuristic call instead of one per successor. A
successor whose state was already reached is dropped (no reopening). The successors are
not even listed: one *cursor* entry in the full list stands for them and takes them from
the successor generator one at a time, in its order
(:meth:`~.successors.SuccessorGenerator.next_applicable`), going back to the head of its
bucket while there are more, so they come out as if all had been queued at once, and an
expansion costs the successors the search takes, not the state's branching (blocks with
900 blocks: 91 applicable, one or two taken). ``generated`` counts those taken.
Preferred operators of the expanded state also put their pairs into a second list (in
the generator's order, as they would come out of the full list); the two lists alternate
and the preferred one gets ``boost`` extra turns each time an expanded state's h is
lower than any before it (not at the initial state; Fast Downward's defaults:
alternation, boost 1000).

The loop runs compiled (``_search.pyx``) when it is built; :meth:`LazyGreedySearch.reference_run`
is the pure-Python reference it is compared with, which ``STRIPS_PURE_PYTHON=1`` picks.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from typing import ClassVar

from strips_framework.compiled import compiled_module
from strips_framework.forward.base import ForwardStrategy, SearchRun
from strips_framework.forward.components import reads_packed, with_preferred
from strips_framework.forward.openlists import OpenList, open_list
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

    def _evaluator(self, run: SearchRun) -> Callable[[int | bytes], tuple[float, Sequence[int]]]:
        """h and the preferred operators of a state (none unless ``preferred``), as the
        search holds it: a packing where the space makes successors' packings
        (:attr:`~.space.StateSpace.merges`), unpacked first for an estimator that does
        not read packings, else a bitset."""
        if self.preferred:
            evaluate = with_preferred(run.estimator)
        else:
            estimate = run.estimator.estimate

            def evaluate(state: int) -> tuple[float, Sequence[int]]:
                return estimate(state), ()

        if not run.space.merges or reads_packed(run.estimator):
            return evaluate  # type: ignore[return-value]
        unpack = run.space.unpack

        def evaluate_unpacked(state: int | bytes) -> tuple[float, Sequence[int]]:
            return evaluate(unpack(state))  # type: ignore[arg-type]

        return evaluate_unpacked

    def reference_run(self, run: SearchRun) -> int | None:
        """The search in Python (the compiled loop's reference)."""
        task, space, budget = run.task, run.space, run.budget
        evaluate = self._evaluator(run)
        successors = space.successors
        following_of, ordered, order = (
            successors.next_applicable,
            successors.ordered,
            successors.order,
        )
        frontier: OpenList[_Cursor | tuple[int, int]] = open_list(self.preferred, self.boost)
        best_h = math.inf
        number = space.add(task.init, NO_PARENT, NO_PARENT)
        state = space.stored(number) if space.merges else task.init
        while True:
            h, preferred = evaluate(state)
            run.evaluated += 1
            if h == math.inf:
                run.dead_ends += 1
            elif space.is_goal(state):
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
                position = following_of(space.stored(number), 0)
                if position >= 0:
                    frontier.push(h, _Cursor(h, number, position))
                    if preferred:
                        picked = [(number, op) for op in ordered(state, preferred)]
                        frontier.push_preferred(h, picked)  # type: ignore[attr-defined]
            while True:
                if not frontier:
                    return None
                entry = frontier.pop()
                if isinstance(entry, _Cursor):
                    parent, op = entry.parent, order[entry.position]
                    entry.position = following_of(space.stored(parent), entry.position + 1)
                    if entry.position >= 0:
                        frontier.push_front(entry.key, entry)
                else:
                    parent, op = entry
                run.generated += 1
                number = space.take(parent, op)
                if number >= 0:
                    state = space.stored(number) if space.merges else space.state(number)
                    break


class _Cursor:
    """A full-list entry for the successors of state ``parent`` (expanded with estimate
    ``key``) not taken yet: ``position`` is the next one's in the successor generator's
    order (see the module docstring)."""

    __slots__ = ("key", "parent", "position")

    def __init__(self, key: float, parent: int, position: int) -> None:
        self.key, self.parent, self.position = key, parent, position
