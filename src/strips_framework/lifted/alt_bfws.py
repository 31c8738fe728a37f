"""Alternated best-first width search over lifted states (``lifted-alt-bfws``), the
shape of Powerlifted's ``alt-bfws1`` (Corrêa and Seipp's lifted planner, after
Lipovetzky and Geffner's BFWS).

Why this shape: the delete-free heuristic is what costs. A lifted hFF explores the
relaxed task for every state it rates, and on a dead end it saturates it (on
organic-synthesis-MIT p10 over a second a state in Python, where a lazy greedy search
meets dozens of dead ends among the first states it takes). So the heuristic is computed
once per *expanded* state, and a generated child gets only measures that cost what its
action changed:

- ``#g``, the goal literals it lacks (:class:`~.goal_count.GoalLiterals`; a goal that is
  not one conjunction of ground literals counts 0 or 1, tested on the child's facts);
- ``#r``, the *relevant* atoms it lacks: those the relaxed plan of the initial state
  achieves (the estimator's useful atoms, :class:`~.components.Guidance`);
- its width-1 novelty within the partition ``(#g, #r)`` (:class:`~.novelty.Novelty`).

Each child enters two open lists, one ordered by (its parent's estimate, g) and one by
(novelty, #g, g), and, when it is *preferred*, their preferred twins too: a child is
preferred when one of its parent's preferred instances made it, and with
``useful_atoms = true`` also when it gains an atom useful in its parent's relaxed plan
(Powerlifted's test). That is not the default: an atom such as blocksworld's nullary
``arm-empty`` is useful whenever the arm is full, and then every put-down and every
stack onto any of a hundred blocks is preferred; on the hundred-block task of the
hard-to-ground set the preferred lists then take over a hundred states that the
relaxed plan has no use for (no plan in 30 s), where the preferred instances alone
solve it in 10 expansions. With hFF the useful-atom test prefers every child the
instance test prefers (a preferred instance achieves an atom of the plan).
Pops alternate between the estimate's lists and the novelty's, the estimate's first;
within a kind the preferred twin goes first while the search has *credit*: ``boost``
turns at the start, one spent a pop from a preferred list, ``boost`` more whenever an
expanded state's estimate is lower than every earlier one. The goal is tested when a
state is generated; a dead end (estimate ``inf``) is found when it is taken for
expansion, and is not expanded (Powerlifted expands it; no successor of a relaxed dead
end reaches the goal). Greedy: a state keeps the first path that reached it.
"""

from __future__ import annotations

import math
from typing import ClassVar

from strips_framework.forward.openlists import BestFirstOpenList
from strips_framework.lifted.components import Guidance, with_guidance
from strips_framework.lifted.goal_count import GoalLiterals
from strips_framework.lifted.novelty import Novelty
from strips_framework.lifted.search import LiftedRun, LiftedStrategy
from strips_framework.lifted.space import NO_PARENT
from strips_framework.options import Option


class LiftedAlternatedBFWS(LiftedStrategy):
    """Alternated BFWS: the heuristic on expansion, goal count, relevant atoms and
    novelty on generation (see the module docstring)."""

    name: ClassVar[str] = "lifted-alt-bfws"
    options = (
        Option("preferred", bool, True, doc="preferred twins of both open lists"),
        Option(
            "useful_atoms", bool, False,
            doc="prefer, besides the children of preferred instances, every child that "
            "gains an atom useful in its parent's relaxed plan (Powerlifted's test)",
        ),
        Option(
            "boost", int, 1000, minimum=0,
            doc="pops from the preferred lists allowed at the start and added whenever the "
            "expanded states' estimate reaches a new low",
        ),
    )  # fmt: skip
    preferred: bool
    useful_atoms: bool
    boost: int

    def run(self, run: LiftedRun) -> int | None:
        successors, space, budget = run.successors, run.space, run.budget
        guide = with_guidance(run.estimator)
        goal = GoalLiterals(successors.task)
        state = successors.task.init
        number = space.add(space.pack(state), NO_PARENT, None, 0)
        facts = successors.facts(state)
        run.remember(number, state, facts)
        if successors.is_goal(facts):
            return number
        first = guide(state)
        run.evaluated += 1
        if first.value == math.inf:
            run.dead_ends += 1
            return None
        relevant = first.useful
        # By state number: (#g, #r); and whether it was taken from the open lists.
        counts = [(goal.missing(state) if goal.simple else 1, len(relevant))]
        closed = bytearray(1)
        novelty = Novelty()
        lists = _Alternation(self.boost if self.preferred else 0, self.boost)
        lists.push(number, (first.value, 0), (novelty.of(state, counts[0]), counts[0][0], 0), False)
        best = first.value
        guidance: Guidance | None = first  # the initial state's, computed already
        while lists:
            number = lists.pop()
            if closed[number]:
                continue
            closed[number] = 1
            budget.check(run.expanded)
            state, facts = run.parent(number)
            if guidance is None:
                guidance = guide(state)
                run.evaluated += 1
            h = guidance.value
            useful = guidance.useful if self.useful_atoms else frozenset()
            preferred_steps = set(guidance.preferred) if self.preferred else set()
            guidance = None
            if h == math.inf:
                run.dead_ends += 1
                continue
            run.expanded += 1
            if h < best:
                best = h
                lists.reward_progress()
            parent_counts = counts[number]
            goals_left, relevant_left = parent_counts
            # LiftedRun.child, without looking the parent up again for each child (a
            # childsnack state has some 50,000 applicable instances).
            g_parent = space.g[number]
            change, repack = successors.change, space.repack
            for step in successors.applicable(facts):
                budget.check(run.expanded - 1)  # the time, within this expansion
                run.generated += 1
                removed, added, cost = change(state, facts, step)
                packed = repack(number, removed, added)
                g = g_parent + cost
                if packed in space.ids:
                    continue
                child = space.add(packed, number, step, g)
                closed.append(0)
                if goal.simple:
                    child_goals = goals_left + goal.change(removed, added)
                    if not child_goals:
                        return child
                else:
                    if successors.is_goal(run.child_facts(number, child, removed, added)[1]):
                        return child
                    child_goals = 1
                child_counts = (
                    child_goals,
                    relevant_left
                    + len(relevant.intersection(removed))
                    - len(relevant.intersection(added)),
                )
                counts.append(child_counts)
                if child_counts == parent_counts:
                    novel = novelty.of(None, child_counts, added)
                else:
                    novel = novelty.of(state.union(added).difference(removed), child_counts)
                preferred = self.preferred and (
                    not useful.isdisjoint(added) or step in preferred_steps
                )
                lists.push(child, (h, g), (novel, child_goals, g), preferred)
        return None


class _Alternation:
    """Powerlifted's four open lists of state numbers: by estimate, by novelty, and the
    preferred twin of each. A state is in both regular lists (and in both twins when
    preferred), so it can be popped up to four times; the search skips it once closed."""

    __slots__ = ("by_h", "by_h_preferred", "by_novelty", "by_novelty_preferred", "credit",
                 "boost", "novelty_turn")  # fmt: skip

    def __init__(self, credit: int, boost: int) -> None:
        self.by_h: BestFirstOpenList[int] = BestFirstOpenList()
        self.by_h_preferred: BestFirstOpenList[int] = BestFirstOpenList()
        self.by_novelty: BestFirstOpenList[int] = BestFirstOpenList()
        self.by_novelty_preferred: BestFirstOpenList[int] = BestFirstOpenList()
        #: Pops from a preferred list left before the next progress.
        self.credit = credit
        self.boost = boost
        self.novelty_turn = False

    def __bool__(self) -> bool:
        # The preferred twins hold states that are in the regular lists as well, but a
        # regular list may have given them up first: all four count.
        return bool(
            len(self.by_h) or len(self.by_novelty) or len(self.by_h_preferred)
            or len(self.by_novelty_preferred)
        )  # fmt: skip

    def push(self, number: int, h_key: tuple, novelty_key: tuple, preferred: bool) -> None:
        self.by_h.push(h_key, number)
        self.by_novelty.push(novelty_key, number)
        if preferred:
            self.by_h_preferred.push(h_key, number)
            self.by_novelty_preferred.push(novelty_key, number)

    def pop(self) -> int:
        """The next state number from this turn's kind: its preferred twin while there
        is credit, else its regular list, else the twin (the regular list may have given
        up every state first). Every state enters both kinds and pops alternate, so
        when any list has an entry, the kind whose turn it is has one."""
        if self.novelty_turn:
            twin, regular = self.by_novelty_preferred, self.by_novelty
        else:
            twin, regular = self.by_h_preferred, self.by_h
        self.novelty_turn = not self.novelty_turn
        if self.credit > 0 and len(twin):
            self.credit -= 1
            return twin.pop()
        if len(regular):
            return regular.pop()
        return twin.pop()

    def reward_progress(self) -> None:
        self.credit += self.boost
