"""Fact landmarks and their orderings, by Zhu & Givan's label propagation (2003).

A *landmark* is a fact every plan from the initial state makes true at some point. Over
the delete relaxation each fact gets a label, the set of facts that must be true before
it is first reached: a fact of the initial state is its own label; an operator's label
is the union of its preconditions' labels; a fact's label is itself plus the
intersection of the labels its achievers give it. The labels are propagated to a fixed
point (they only shrink once set). The landmarks of the task are the facts in the goal
facts' labels. Labels are bitsets (ints), so union and intersection are single C ops.

Orderings: ``p`` is *naturally* ordered before ``q`` when ``p`` is in ``q``'s label
(every plan reaches ``p`` before ``q`` first holds); ``p`` is *necessary* for ``q`` when
it is a precondition of every reachable achiever of ``q``, so it must hold right before
``q`` becomes true, every time. Necessary orderings are a subset of the greedy-necessary
ones of Richter, Helmert & Westphal (2008); they are what tells a heuristic that a
landmark achieved earlier is required again.
"""

from __future__ import annotations


from strips_evaluators.heuristics.relaxation import RelaxedTask, facts_in
from strips_framework.grounding.task import mask_of
from strips_framework.records import Record


class LandmarkGraph(Record):
    """Landmarks of a task from its initial state, as bitsets over fact numbers."""

    #: The landmarks (artificial and derived facts left out: no operator achieves them).
    landmarks: int
    #: For each fact reached from the initial state, its label; 0 for unreached facts.
    label: list[int]
    #: For each landmark, the landmarks necessary for it (0 for other facts).
    necessary: list[int]
    #: For each landmark, the relaxed operators of real operators that add it.
    achievers: list[list[int]]
    #: False when some goal fact is unreachable even in the relaxation.
    solvable: bool

    __slots__ = ("landmarks", "label", "necessary", "achievers", "solvable")

    def __init__(
        self,
        landmarks: int,
        label: list[int],
        necessary: list[int],
        achievers: list[list[int]],
        solvable: bool,
    ) -> None:
        self.landmarks = landmarks
        self.label = label
        self.necessary = necessary
        self.achievers = achievers
        self.solvable = solvable


def find_landmarks(relaxed: RelaxedTask, init: int, derived: tuple[int, ...]) -> LandmarkGraph:
    label, reachable_ops = _propagate_labels(relaxed, init)
    solvable = all(label[fact] for fact in relaxed.goal)
    landmarks = 0
    if solvable:
        for fact in relaxed.goal:
            landmarks |= label[fact]
    for fact in (relaxed.true_fact, *derived):
        landmarks &= ~(1 << fact)
    achievers: list[list[int]] = [[] for _ in range(relaxed.num_facts)]
    for op in reachable_ops:
        if relaxed.operator[op] >= 0:
            for fact in relaxed.add[op]:
                if landmarks >> fact & 1:
                    achievers[fact].append(op)
    necessary = [0] * relaxed.num_facts
    for fact in facts_in(landmarks & ~init):
        common = -1  # all bits: the intersection over no achiever yet
        for op in achievers[fact]:
            common &= mask_of(relaxed.pre[op])
        necessary[fact] = common & landmarks & ~(1 << fact) if achievers[fact] else 0
    return LandmarkGraph(landmarks, label, necessary, achievers, solvable)


def _propagate_labels(relaxed: RelaxedTask, init: int) -> tuple[list[int], list[int]]:
    """Zhu & Givan labels of every fact (0: unreached) and the operators reached."""
    pre, add, pre_of = relaxed.pre, relaxed.add, relaxed.pre_of
    label = [0] * relaxed.num_facts
    remaining = relaxed.pre_count[:]
    queue = facts_in(init)
    queue.append(relaxed.true_fact)
    for fact in queue:
        label[fact] = 1 << fact
        for op in pre_of[fact]:
            remaining[op] -= 1
    queued = set(queue)
    while queue:
        fact = queue.pop()
        queued.discard(fact)
        for op in pre_of[fact]:
            if remaining[op]:
                continue
            op_label = 0
            for condition in pre[op]:
                op_label |= label[condition]
            for effect in add[op]:
                new = op_label | 1 << effect
                old = label[effect]
                if not old:
                    for later in pre_of[effect]:
                        remaining[later] -= 1
                elif old & new == old:
                    continue
                else:
                    new &= old
                label[effect] = new
                if effect not in queued:
                    queued.add(effect)
                    queue.append(effect)
    return label, [op for op, left in enumerate(remaining) if not left]
