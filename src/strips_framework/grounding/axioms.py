"""Evaluating the axioms of a ground task (PDDL derived predicates) on a state.

Strata are evaluated in order; within a stratum a worklist propagates new derived facts
to the axioms whose body mentions them, so each axiom is looked at once per body fact that
becomes true rather than once per sweep. Negated body facts belong to lower strata and so
are final by the time their stratum's axioms run (negation as failure is sound).
"""

from __future__ import annotations


from strips_framework.grounding.task import GroundTask, mask_of
from strips_framework.records import Record


class _Rule(Record):
    head: int
    body_mask: int
    neg_mask: int

    __slots__ = ("head", "body_mask", "neg_mask")

    def __init__(self, head: int, body_mask: int, neg_mask: int) -> None:
        self.head = head
        self.body_mask = body_mask
        self.neg_mask = neg_mask


class _Stratum(Record):
    rules: tuple[_Rule, ...]
    #: For a fact derived in this stratum, the rules whose body contains it.
    watching: dict[int, tuple[_Rule, ...]]

    __slots__ = ("rules", "watching")

    def __init__(self, rules: tuple[_Rule, ...], watching: dict[int, tuple[_Rule, ...]]) -> None:
        self.rules = rules
        self.watching = watching


class AxiomEvaluator:
    """``evaluate(state)`` clears the derived bits and recomputes them."""

    def __init__(self, task: GroundTask) -> None:
        self._derived_mask = mask_of(task.derived)
        by_stratum: dict[int, list[_Rule]] = {}
        bodies: dict[int, list[tuple[int, ...]]] = {}
        for axiom in task.axioms:
            rule = _Rule(axiom.head, mask_of(axiom.body), mask_of(axiom.body_neg))
            by_stratum.setdefault(axiom.stratum, []).append(rule)
            bodies.setdefault(axiom.stratum, []).append(axiom.body)
        strata = []
        for level in sorted(by_stratum):
            rules = by_stratum[level]
            heads = {rule.head for rule in rules}
            watching: dict[int, list[_Rule]] = {}
            for rule, body in zip(rules, bodies[level]):
                for fact in body:
                    if fact in heads:
                        watching.setdefault(fact, []).append(rule)
            strata.append(
                _Stratum(tuple(rules), {fact: tuple(rs) for fact, rs in watching.items()})
            )
        self._strata = tuple(strata)

    def evaluate(self, state: int) -> int:
        if not self._strata:
            return state
        state &= ~self._derived_mask
        for stratum in self._strata:
            new = []
            for rule in stratum.rules:
                if _fires(rule, state):
                    state |= 1 << rule.head
                    new.append(rule.head)
            while new:
                for rule in stratum.watching.get(new.pop(), ()):
                    if _fires(rule, state):
                        state |= 1 << rule.head
                        new.append(rule.head)
        return state


def _fires(rule: _Rule, state: int) -> bool:
    return (
        state & rule.body_mask == rule.body_mask
        and not state & rule.neg_mask
        and not state >> rule.head & 1
    )
