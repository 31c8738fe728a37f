"""The ground task: what grounding makes of a PDDL (or native) problem, and what forward
search and state heuristics work on.

Facts are numbered ``0..len(facts)-1`` and a *state* is a Python ``int`` used as a bitset:
bit ``i`` is set when fact ``i`` holds. Bitsets make applicability a single ``&`` and a
successor one ``& ~delete | add``, and states hash and compare as fast as anything in
Python; the tuples of fact numbers beside each mask serve heuristics, which walk facts.

Derived facts (PDDL ``:derived``) are facts too, but no operator adds or deletes them:
they are recomputed from the basic facts by the :attr:`GroundTask.axioms`, stratum by
stratum (negation-as-failure refers only to lower strata). A state as search stores it
always has its derived facts evaluated.
"""

from __future__ import annotations

from typing import Any

from attrs import Factory, field, frozen


def mask_of(facts: tuple[int, ...]) -> int:
    """The bitset of the given fact numbers."""
    mask = 0
    for fact in facts:
        mask |= 1 << fact
    return mask


def _mask(of: str) -> Any:
    """A field computed at construction: the bitset of the fact-number field ``of``."""
    return field(
        init=False, default=Factory(lambda self: mask_of(getattr(self, of)), takes_self=True)
    )


@frozen
class GroundEffect:
    """A conditional effect of a ground operator: when every fact of ``condition`` holds
    and none of ``condition_neg`` does in the state the operator is applied in, the
    ``add`` facts become true and the ``delete`` facts false."""

    condition: tuple[int, ...]
    condition_neg: tuple[int, ...]
    add: tuple[int, ...]
    delete: tuple[int, ...]
    condition_mask: int = _mask("condition")
    condition_neg_mask: int = _mask("condition_neg")
    add_mask: int = _mask("add")
    delete_mask: int = _mask("delete")

    def fires(self, state: int) -> bool:
        mask = self.condition_mask
        return state & mask == mask and not state & self.condition_neg_mask


@frozen
class GroundOperator:
    """One ground action. ``name`` is its IPC plan step, e.g. ``(pick-up a)``. ``add`` and
    ``delete`` are its unconditional effects, ``effects`` the conditional ones."""

    name: str
    pre: tuple[int, ...]
    add: tuple[int, ...]
    delete: tuple[int, ...]
    cost: int = 1
    #: Facts that must be false (PDDL negative preconditions).
    pre_neg: tuple[int, ...] = ()
    effects: tuple[GroundEffect, ...] = ()
    pre_mask: int = _mask("pre")
    pre_neg_mask: int = _mask("pre_neg")
    add_mask: int = _mask("add")
    delete_mask: int = _mask("delete")

    def applicable(self, state: int) -> bool:
        return state & self.pre_mask == self.pre_mask and not state & self.pre_neg_mask

    def apply(self, state: int) -> int:
        """The successor before axioms: the conditional effects whose condition holds in
        ``state`` join the unconditional ones; deletes first, then adds (PDDL semantics)."""
        delete, add = self.delete_mask, self.add_mask
        for effect in self.effects:
            if effect.fires(state):
                delete |= effect.delete_mask
                add |= effect.add_mask
        return (state & ~delete) | add


@frozen
class GroundAxiom:
    """``head`` holds when every fact of ``body`` holds and none of ``body_neg`` does.
    ``body_neg`` facts belong to strata below ``stratum``."""

    head: int
    body: tuple[int, ...]
    body_neg: tuple[int, ...] = ()
    stratum: int = 0


@frozen
class GroundTask:
    """A ground planning task. ``goal`` is a conjunction of facts (a complex PDDL goal is
    compiled to a derived fact); ``init`` is a state with its derived facts evaluated."""

    name: str
    facts: tuple[str, ...]
    operators: tuple[GroundOperator, ...]
    init: int
    goal: tuple[int, ...]
    axioms: tuple[GroundAxiom, ...] = ()
    #: Facts that only axioms make true.
    derived: tuple[int, ...] = ()
    #: True when the task minimizes total-cost (``:action-costs``); else cost = length.
    uses_costs: bool = False
    goal_mask: int = _mask("goal")

    def is_goal(self, state: int) -> bool:
        return state & self.goal_mask == self.goal_mask

    def facts_of(self, state: int) -> list[str]:
        """The names of the facts that hold in ``state``, for messages and tests."""
        return [name for i, name in enumerate(self.facts) if state >> i & 1]
