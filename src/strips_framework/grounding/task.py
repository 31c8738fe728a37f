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

from typing import ClassVar

from strips_framework.records import Record


def mask_of(facts: tuple[int, ...]) -> int:
    """The bitset of the given fact numbers."""
    mask = 0
    for fact in facts:
        mask |= 1 << fact
    return mask


def facts_in(state: int) -> list[int]:
    """The fact numbers set in ``state``, ascending. Scans the binary string with
    ``str.find``, so the Python-level work is one step per true fact, not per fact."""
    digits = bin(state)[:1:-1]
    facts = []
    find = digits.find
    position = find("1")
    while position >= 0:
        facts.append(position)
        position = find("1", position + 1)
    return facts


class _Masked(Record):
    """A record whose fact tuples named in ``MASKED`` also have masks, made on first use
    (:meth:`masks`): a mask is as long as its highest fact number, so making them for
    every operator up front would cost time and memory in proportion to operators times
    facts, while a search touches the masks of the operators it applies."""

    __slots__ = ()
    MASKED: ClassVar[tuple[str, ...]] = ()

    def masks(self) -> tuple[int, ...]:
        """The masks of the ``MASKED`` fields, in order."""
        masks = self._masks  # type: ignore[attr-defined]
        if masks is None:
            masks = self._masks = tuple([mask_of(getattr(self, name)) for name in self.MASKED])
        return masks


def _mask(position: int) -> property:
    return property(lambda self: self.masks()[position], doc="A mask (see :class:`_Masked`).")


class GroundEffect(_Masked):
    """A conditional effect of a ground operator: when every fact of ``condition`` holds
    and none of ``condition_neg`` does in the state the operator is applied in, the
    ``add`` facts become true and the ``delete`` facts false."""

    FIELDS = ("condition", "condition_neg", "add", "delete")
    MASKED = FIELDS
    __slots__ = (*FIELDS, "_masks")
    condition_mask, condition_neg_mask, add_mask, delete_mask = map(_mask, range(4))

    def __init__(
        self,
        condition: tuple[int, ...],
        condition_neg: tuple[int, ...],
        add: tuple[int, ...],
        delete: tuple[int, ...],
    ) -> None:
        self.condition, self.condition_neg, self.add, self.delete = condition, condition_neg, add, delete
        self._masks: tuple[int, ...] | None = None

    def fires(self, state: int) -> bool:
        condition, condition_neg, _, _ = self.masks()
        return state & condition == condition and not state & condition_neg


class GroundOperator(_Masked):
    """One ground action. ``name`` is its IPC plan step, e.g. ``(pick-up a)``. ``add`` and
    ``delete`` are its unconditional effects, ``effects`` the conditional ones;
    ``pre_neg`` the facts that must be false (PDDL negative preconditions)."""

    FIELDS = ("name", "pre", "add", "delete", "cost", "pre_neg", "effects")
    MASKED = ("pre", "pre_neg", "add", "delete")
    __slots__ = (*FIELDS, "_masks")
    pre_mask, pre_neg_mask, add_mask, delete_mask = map(_mask, range(4))

    def __init__(
        self,
        name: str,
        pre: tuple[int, ...],
        add: tuple[int, ...],
        delete: tuple[int, ...],
        cost: int = 1,
        pre_neg: tuple[int, ...] = (),
        effects: tuple[GroundEffect, ...] = (),
    ) -> None:
        self.name, self.pre, self.add, self.delete = name, pre, add, delete
        self.cost, self.pre_neg, self.effects = cost, pre_neg, effects
        self._masks: tuple[int, ...] | None = None

    def applicable(self, state: int) -> bool:
        pre, neg, _, _ = self.masks()
        return state & pre == pre and not state & neg

    def apply(self, state: int) -> int:
        """The successor before axioms: the conditional effects whose condition holds in
        ``state`` join the unconditional ones; deletes first, then adds (PDDL semantics)."""
        _, _, add, delete = self.masks()
        for effect in self.effects:
            if effect.fires(state):
                delete |= effect.delete_mask
                add |= effect.add_mask
        return (state & ~delete) | add


class GroundAxiom(Record):
    """``head`` holds when every fact of ``body`` holds and none of ``body_neg`` does.
    ``body_neg`` facts belong to strata below ``stratum``."""

    head: int
    body: tuple[int, ...]
    body_neg: tuple[int, ...]
    stratum: int

    __slots__ = ("head", "body", "body_neg", "stratum")

    def __init__(
        self,
        head: int,
        body: tuple[int, ...],
        body_neg: tuple[int, ...] = (),
        stratum: int = 0,
    ) -> None:
        self.head = head
        self.body = body
        self.body_neg = body_neg
        self.stratum = stratum


class GroundTask(Record):
    """A ground planning task. ``goal`` is a conjunction of facts (a complex PDDL goal is
    compiled to a derived fact); ``init`` is a state with its derived facts evaluated.
    ``derived`` are the facts only axioms make true; ``uses_costs`` is true when the task
    minimizes total-cost (``:action-costs``), else cost = length."""

    FIELDS = ("name", "facts", "operators", "init", "goal", "axioms", "derived", "uses_costs")
    __slots__ = (*FIELDS, "goal_mask")

    def __init__(
        self,
        name: str,
        facts: tuple[str, ...],
        operators: tuple[GroundOperator, ...],
        init: int,
        goal: tuple[int, ...],
        axioms: tuple[GroundAxiom, ...] = (),
        derived: tuple[int, ...] = (),
        uses_costs: bool = False,
    ) -> None:
        self.name, self.facts, self.operators, self.init, self.goal = name, facts, operators, init, goal
        self.axioms, self.derived, self.uses_costs = axioms, derived, uses_costs
        self.goal_mask = mask_of(goal)

    def is_goal(self, state: int) -> bool:
        return state & self.goal_mask == self.goal_mask

    def facts_of(self, state: int) -> list[str]:
        """The names of the facts that hold in ``state``, for messages and tests."""
        return [name for i, name in enumerate(self.facts) if state >> i & 1]
