"""Lifted progression search: forward search whose states are sets of ground atoms and
whose successors come from the query engine (:mod:`.successors`), so the task is never
grounded. The open lists are the forward search's (:mod:`strips_framework.forward.openlists`),
and so are the limits' checks; what differs from a ground search is only how a state is
stored (:mod:`.space`) and expanded.

``lifted-gbfs`` is lazy greedy best-first search with preferred operators, as the ground
``lazy-gbfs`` (and Fast Downward's ``lazy_greedy([h], preferred=[h])``): a state's
successors enter the open list under its own estimate and are made, tested for
duplicates and evaluated only when they come out. By default they are not even listed
when the state is expanded: one *cursor* entry stands for all of them in the full open
list and draws them from the query engine one at a time (:meth:`Successors.stream`), each
time it comes out, going back to the head of its bucket while it has more; the preferred
ones (a handful, named by the heuristic) go into the preferred list at once. The entries
come out in the same order as when every successor is listed, so the search is the same
(with the preferred list, up to the order of one state's preferred successors among
themselves: the heuristic's, not the successor generator's), but an expansion no longer
costs the state's whole branching: a state with thousands of applicable instances pays
for the ones the search takes.
``lifted-bfws`` is eager greedy search
with width-based novelty: every successor is evaluated when generated, and two open
lists alternate, one ordered by the estimate and one by (novelty, estimate) where a
state is novel (1) when it holds an atom no earlier state with the same estimate held,
else 2 (Lipovetzky and Geffner's BFWS(f5), width 1). Powerlifted's ``alt-bfws1``, which
evaluates the heuristic only on expansion, is ``lifted-alt-bfws`` (:mod:`.alt_bfws`).
"""

from __future__ import annotations

import math
from collections import OrderedDict
from collections.abc import Iterator
from itertools import islice
from typing import ClassVar

from strips_framework.forward.budget import Budget, peak_mib
from strips_framework.forward.openlists import AlternationOpenList, BestFirstOpenList, open_list
from strips_framework.lifted.components import (
    ActionInstance,
    GroundAtom,
    LiftedEstimator,
    LiftedState,
)
from strips_framework.lifted.delta import successor
from strips_framework.lifted.novelty import Novelty
from strips_framework.lifted.query import FactBase
from strips_framework.lifted.result import LiftedStatistics
from strips_framework.lifted.space import NO_PARENT, LiftedStateSpace, StateKey
from strips_framework.lifted.successors import Successors, step_name
from strips_framework.limits import Clock, LimitReached, Limits
from strips_framework.options import Configurable, Option
from strips_framework.result import Result, Status

#: How many recent states' fact bases a run keeps (see :attr:`LiftedRun._recent`).
RECENT = 256


class LiftedRun:
    """One search: the successors, the estimator, the limits, the state space and the
    counters, updated in place so that a run stopped by a limit still reports them."""

    def __init__(
        self, successors: Successors, estimator: LiftedEstimator, limits: Limits, clock: Clock
    ) -> None:
        self.successors = successors
        self.estimator = estimator
        self.budget = Budget(limits, clock)
        self.space = LiftedStateSpace()
        self.expanded = 0
        self.evaluated = 0
        self.generated = 0
        self.dead_ends = 0
        #: The states (and fact bases) last expanded or generated, oldest first: a
        #: successor's fact base is made from its parent's, and the states expanded next
        #: are mostly among them.
        self._recent: OrderedDict[int, tuple[LiftedState, FactBase]] = OrderedDict()
        #: The cursors whose streams are live, oldest first: a stream holds its state's
        #: fact base, so only the :data:`RECENT` last used keep theirs.
        self._streams: OrderedDict[int, _Cursor] = OrderedDict()

    def parent(self, number: int) -> tuple[LiftedState, FactBase]:
        """State ``number`` and its fact base (made from scratch when not recent), now
        the most recent."""
        found = self._recent.get(number)
        if found is None:
            state = self.space.state(number)
            found = (state, self.successors.facts(state))
            self.remember(number, *found)
        else:
            self._recent.move_to_end(number)
        return found

    def remember(self, number: int, state: LiftedState, facts: FactBase) -> None:
        recent = self._recent
        recent[number] = (state, facts)
        recent.move_to_end(number)
        if len(recent) > RECENT:
            recent.popitem(last=False)

    def advance(self, cursor: _Cursor) -> bool:
        """Draw ``cursor``'s next successor into ``cursor.step``; False when it has no
        more. A cursor whose stream was let go makes it again and skips what it took."""
        stream = cursor.stream
        if stream is None:
            stream = self.successors.stream(self.parent(cursor.parent)[1])
            stream = cursor.stream = islice(stream, cursor.taken, None)
        cursor.step = next(stream, None)
        cursor.taken += 1
        streams = self._streams
        if cursor.step is None:
            cursor.stream = None
            streams.pop(cursor.parent, None)
            return False
        streams[cursor.parent] = cursor
        streams.move_to_end(cursor.parent)
        if len(streams) > RECENT:
            streams.popitem(last=False)[1].stream = None
        return True

    def child(
        self, parent: int, step: ActionInstance
    ) -> tuple[StateKey, int, set[GroundAtom], set[GroundAtom]]:
        """The duplicate-table key of the state ``step`` leads to from state
        ``parent``, its path cost, and the atoms it lost and gained (for
        :meth:`child_facts`). The key is made from the parent's and the changed atoms
        only (:meth:`LiftedStateSpace.repack`); the state itself is made only for a
        child that is no duplicate (:meth:`child_facts`)."""
        state, facts = self.parent(parent)
        removed, added, cost = self.successors.change(state, facts, step)
        packed = self.space.repack(parent, removed, added)
        return packed, self.space.g[parent] + cost, removed, added

    def child_facts(
        self, parent: int, number: int, removed: set[GroundAtom], added: set[GroundAtom]
    ) -> tuple[LiftedState, FactBase]:
        """State ``number``, a child of ``parent`` by :meth:`child`, and its fact base,
        made from the parent's, and remembered."""
        state, facts = self.parent(parent)
        state = successor(state, removed, added)  # (``removed`` in it, ``added`` not)
        facts = self.successors.facts_after(state, facts, removed, added)
        self.remember(number, state, facts)
        return state, facts


class LiftedStrategy(Configurable):
    """The base of the strategies over lifted tasks (the ``lifted-strategy`` plugin
    kind): the planner gives them the task's :class:`Successors` (the compiled task and
    its query engine) and the lifted heuristic's estimator."""

    name: ClassVar[str]
    capabilities: ClassVar[frozenset[str]] = frozenset()
    #: True when running out of states proves the task unsolvable.
    complete: ClassVar[bool] = True

    def search_task(
        self,
        successors: Successors,
        estimator: LiftedEstimator,
        limits: Limits,
        clock: Clock | None = None,
    ) -> Result:
        clock = clock or Clock(limits.time)
        begin = clock.elapsed()
        run = LiftedRun(successors, estimator, limits, clock)
        goal: int | None = None
        try:
            goal = self.run(run)
            status = Status.SOLVED if goal is not None else Status.UNSOLVABLE
        except LimitReached as limit:
            status = limit.status
        except KeyboardInterrupt:
            status = Status.INTERRUPTED
        except MemoryError:
            status = Status.MEMORY_LIMIT
        states, per_state = len(run.space), run.space.bytes_per_state()
        if status == Status.MEMORY_LIMIT:
            run.space.clear()
        task = successors.task
        statistics = LiftedStatistics(
            expanded=run.expanded,
            evaluated=run.evaluated,
            generated=run.generated,
            dead_ends=run.dead_ends,
            states=states,
            bytes_per_state=per_state,
            atoms=run.space.atoms,
            actions=len(task.actions),
            search_seconds=clock.elapsed() - begin,
            peak_memory_mib=peak_mib(),
        )
        if goal is None:
            return Result(status, None, None, statistics, clock.elapsed(), task.uses_costs)
        steps = run.space.plan_to(goal)
        plan = tuple(step_name(step) for step in steps)
        cost = run.space.g[goal]
        return Result(status, plan, cost, statistics, clock.elapsed(), task.uses_costs)

    def run(self, run: LiftedRun) -> int | None:
        """The search proper: the number of a goal state, or None when out of states."""
        raise NotImplementedError


class LiftedLazyGreedySearch(LiftedStrategy):
    """Lazy greedy best-first search over lifted states, with preferred operators."""

    name: ClassVar[str] = "lifted-gbfs"
    options = (
        Option("preferred", bool, True, doc="a second open list for preferred operators"),
        Option("boost", int, 1000, minimum=0, doc="extra turns of that list on progress"),
        Option(
            "deferred", bool, True,
            doc="draw a state's successors one at a time as the open list reaches them "
            "(false: list them all when it is expanded)",
        ),
    )  # fmt: skip
    preferred: bool
    boost: int
    deferred: bool

    def run(self, run: LiftedRun) -> int | None:
        successors, space, budget = run.successors, run.space, run.budget
        estimate = run.estimator.estimate
        evaluate_preferred = run.estimator.estimate_with_preferred
        frontier: BestFirstOpenList | AlternationOpenList = open_list(self.preferred, self.boost)
        best_h = math.inf
        state: LiftedState = successors.task.init
        number = space.add(space.pack(state), NO_PARENT, None, 0)
        facts = successors.facts(state)
        while True:
            if successors.is_goal(facts):
                return number
            if self.preferred:
                h, preferred = evaluate_preferred(state)
            else:
                h, preferred = estimate(state), ()
            run.evaluated += 1
            if h == math.inf:
                run.dead_ends += 1
            else:
                budget.check(run.expanded)
                run.expanded += 1
                if h < best_h:
                    if best_h != math.inf:
                        frontier.reward_progress()
                    best_h = h
                run.remember(number, state, facts)
                if self.deferred:
                    cursor = _Cursor(h, number, successors.stream(facts))
                    if run.advance(cursor):
                        frontier.push(h, cursor)
                    if preferred:
                        frontier.push_preferred(h, [(number, step) for step in preferred])  # type: ignore[union-attr]
                else:
                    entries = [(number, step) for step in successors.applicable(facts)]
                    run.generated += len(entries)
                    frontier.push_all(h, entries, {(number, step) for step in preferred})
            while True:
                if not frontier:
                    return None
                entry = frontier.pop()
                if isinstance(entry, _Cursor):
                    run.generated += 1
                    parent, step = entry.parent, entry.step
                    if run.advance(entry):
                        frontier.push_front(entry.key, entry)
                else:
                    run.generated += self.deferred
                    parent, step = entry
                packed, g, removed, added = run.child(parent, step)
                if packed not in space.ids:
                    number = space.add(packed, parent, step, g)
                    state, facts = run.child_facts(parent, number, removed, added)
                    break


class _Cursor:
    """A lazy search's open-list entry for the successors of state ``parent`` (expanded
    with estimate ``key``) not yet taken: ``step`` is the next, drawn from ``stream``
    (None once the stream is let go, see :meth:`LiftedRun.advance`) after ``taken``
    draws. ``generated`` counts the successors taken from cursors and the preferred list
    (those listed at once count when listed)."""

    __slots__ = ("key", "parent", "step", "stream", "taken")

    def __init__(self, key: float, parent: int, stream: Iterator[ActionInstance]) -> None:
        self.key = key
        self.parent = parent
        self.step: ActionInstance | None = None
        self.stream: Iterator[ActionInstance] | None = stream
        self.taken = 0


class LiftedBFWS(LiftedStrategy):
    """Eager greedy search alternating an h-ordered list with a (novelty, h)-ordered one
    (see the module docstring); preferred operators, when the heuristic names them, feed
    a third list as in Powerlifted's ``alt-bfws``."""

    name: ClassVar[str] = "lifted-bfws"
    options = (
        Option("preferred", bool, True, doc="an open list of states reached by preferred operators"),
    )
    preferred: bool

    def run(self, run: LiftedRun) -> int | None:
        successors, space, budget = run.successors, run.space, run.budget
        estimator = run.estimator
        novelty = Novelty()
        lists: list[BestFirstOpenList] = [BestFirstOpenList(), BestFirstOpenList()]
        if self.preferred:
            lists.append(BestFirstOpenList())
        turn = 0
        closed = bytearray()
        estimates: list[float] = []  # by state number
        state = successors.task.init
        facts = successors.facts(state)
        if successors.is_goal(facts):
            space.add(space.pack(state), NO_PARENT, None, 0)
            return 0
        h = estimator.estimate(state)
        run.evaluated += 1
        if h == math.inf:
            run.dead_ends += 1
            return None
        number = space.add(space.pack(state), NO_PARENT, None, 0)
        closed.append(0)
        estimates.append(h)
        lists[0].push(h, number)
        lists[1].push((novelty.of(state, h), h), number)
        while any(lists):
            while True:
                turn = (turn + 1) % len(lists)
                if lists[turn]:
                    break
            number = lists[turn].pop()
            if closed[number]:
                continue
            closed[number] = 1
            budget.check(run.expanded)
            run.expanded += 1
            state, facts = run.parent(number)
            h = estimates[number]
            if self.preferred:
                _, preferred = estimator.estimate_with_preferred(state)
                preferred_steps = set(preferred)
            else:
                preferred_steps = set()
            for step in successors.applicable(facts):
                budget.check(run.expanded)  # each child is evaluated: a slow h adds up
                run.generated += 1
                packed, g, removed, added = run.child(number, step)
                if packed in space.ids:
                    continue
                child_number = space.add(packed, number, step, g)
                child, child_facts = run.child_facts(number, child_number, removed, added)
                if successors.is_goal(child_facts):
                    return child_number
                child_h = estimator.estimate(child)
                run.evaluated += 1
                estimates.append(child_h)
                if child_h == math.inf:
                    run.dead_ends += 1
                    closed.append(1)
                    continue
                closed.append(0)
                lists[0].push(child_h, child_number)
                novel = novelty.of(child, child_h, added if child_h == h else None)
                lists[1].push((novel, child_h), child_number)
                if step in preferred_steps:
                    lists[2].push(child_h, child_number)
        return None
