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

from attrs import field, frozen


def mask_of(facts: tuple[int, ...]) -> int:
    """The bitset of the given fact numbers."""
    mask = 0
    for fact in facts:
        mask |= 1 << fact
    return mask


@frozen
class GroundOperator:
    """One ground action. ``name`` is its IPC plan step, e.g. ``(pick-up a)``."""

    name: str
    pre: tuple[int, ...]
    add: tuple[int, ...]
    delete: tuple[int, ...]
    cost: int = 1
    #: Facts that must be false (PDDL negative preconditions).
    pre_neg: tuple[int, ...] = ()
    pre_mask: int = field(init=False)
    pre_neg_mask: int = field(init=False)
    add_mask: int = field(init=False)
    delete_mask: int = field(init=False)

    @pre_mask.default
    def _pre_mask(self) -> int:
        return mask_of(self.pre)

    @pre_neg_mask.default
    def _pre_neg_mask(self) -> int:
        return mask_of(self.pre_neg)

    @add_mask.default
    def _add_mask(self) -> int:
        return mask_of(self.add)

    @delete_mask.default
    def _delete_mask(self) -> int:
        return mask_of(self.delete)

    def applicable(self, state: int) -> bool:
        return state & self.pre_mask == self.pre_mask and not state & self.pre_neg_mask

    def apply(self, state: int) -> int:
        """The successor before axioms: deletes first, then adds (PDDL semantics)."""
        return (state & ~self.delete_mask) | self.add_mask


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
    goal_mask: int = field(init=False)

    @goal_mask.default
    def _goal_mask(self) -> int:
        return mask_of(self.goal)

    def is_goal(self, state: int) -> bool:
        return state & self.goal_mask == self.goal_mask

    def facts_of(self, state: int) -> list[str]:
        """The names of the facts that hold in ``state``, for messages and tests."""
        return [name for i, name in enumerate(self.facts) if state >> i & 1]
