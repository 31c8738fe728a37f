"""Nodes of the means-ends search tree (II.B): a world model and a goal list."""

from __future__ import annotations

from collections.abc import Iterable

from strips_framework.logic.clauses import Clause
from strips_framework.logic.formulas import Formula
from strips_framework.records import Record
from strips_framework.worldmodel.operators import OperatorInstance
from strips_framework.worldmodel.world import WorldModel


class Goal(Record):
    """A goal wff and the operator instance whose precondition it is (``None`` for G0)."""

    formula: Formula
    operator: OperatorInstance | None

    __slots__ = ("formula", "operator")

    def __init__(self, formula: Formula, operator: OperatorInstance | None = None) -> None:
        self.formula = formula
        self.operator = operator


class Difference(Record):
    """The clauses of an uncompleted proof that operators should help resolve away.

    ``negated_goal`` keeps the clauses the proof started from: subsumption may have
    removed them from ``clauses``, yet they tell which facts the proof rests on.
    """

    clauses: tuple[Clause, ...]
    negated_goal: tuple[Clause, ...]

    __slots__ = ("clauses", "negated_goal")

    def __init__(self, clauses: Iterable[Clause], negated_goal: Iterable[Clause] = ()) -> None:
        self.clauses = tuple(clauses)
        self.negated_goal = tuple(negated_goal)

    @property
    def complexity(self) -> int:
        """Literals in the smallest clause: how far the proof is from being completed."""
        return min((len(c.literals) for c in self.clauses), default=0)


class RelevantInstance(Record):
    """An operator instance relevant to a difference, and the resolvent that showed it.

    ``resolvent`` is what remains of the difference clause once the instance's add list
    has resolved a literal away; its size ranks instances (smaller is closer to a proof).
    """

    operator: OperatorInstance
    resolvent: Clause

    __slots__ = ("operator", "resolvent")

    def __init__(self, operator: OperatorInstance, resolvent: Clause) -> None:
        self.operator = operator
        self.resolvent = resolvent


class Node:
    """``(world model, goal list)`` plus the bookkeeping the strategies and evaluators use.

    ``plan`` holds the operators applied from the root to this node (its cost so far);
    ``difference`` is set when the first goal could not be proved; ``pending`` holds the
    relevant instances whose successors have not been generated yet. ``level`` is the
    abstraction level the node was made at by a hierarchical strategy (ABSTRIPS: the
    criticality its operators' preconditions are cut at), ``None`` in a one-level search.
    Mutable (the search fills in ``difference`` and ``pending``) and compared by identity.
    """

    __slots__ = ("id", "model", "goals", "parent", "plan", "applied", "difference", "pending",
                 "successors_generated", "level")  # fmt: skip

    def __init__(
        self,
        id: int,
        model: WorldModel,
        goals: tuple[Goal, ...],
        parent: Node | None,
        plan: tuple[OperatorInstance, ...] = (),
        applied: OperatorInstance | None = None,
        difference: Difference | None = None,
        pending: list[RelevantInstance] | None = None,
        successors_generated: int = 0,
        level: int | None = None,
    ) -> None:
        self.id = id
        self.model = model
        self.goals = goals
        self.parent = parent
        self.plan = plan
        self.applied = applied
        self.difference = difference
        self.pending: list[RelevantInstance] = [] if pending is None else pending
        self.successors_generated = successors_generated
        self.level = level

    @property
    def depth(self) -> int:
        """Distance from the root in the search tree."""
        depth, node = 0, self.parent
        while node is not None:
            depth, node = depth + 1, node.parent
        return depth

    @property
    def cost(self) -> int:
        """Operator applications so far (every operator costs 1)."""
        return len(self.plan)


def path_to(node: Node | None) -> list[Node]:
    """The nodes from the root down to ``node`` (empty for ``None``)."""
    path = []
    while node is not None:
        path.append(node)
        node = node.parent
    return path[::-1]
