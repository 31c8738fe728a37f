"""What every search returns, whichever family it belongs to: one status vocabulary and
one result type.

The families (means-ends and model-A* over first-order world models; forward search over
ground tasks; lifted search over PDDL tasks) count different things, so each keeps its own
statistics record (:class:`~strips_framework.means_ends.result.WorldModelStatistics`,
:class:`~strips_framework.forward.result.ForwardStatistics`,
:class:`~strips_framework.lifted.result.LiftedStatistics`), nested in the one
:class:`Result`; the status, the plan, its cost and the run's time mean the same for all.
"""

from __future__ import annotations

import enum
from typing import ClassVar, Protocol

from strips_framework.records import Record


class Status(enum.StrEnum):
    """How a search ended. A ``str`` subclass, so ``status == "solved"`` and JSON work."""

    SOLVED = "solved"
    #: A complete search visited every reachable state that is not a proven dead end.
    UNSOLVABLE = "unsolvable"
    #: An incomplete search (means-ends, model-A*, enforced hill-climbing) ran out of
    #: nodes without a plan: there may still be one.
    EXHAUSTED = "exhausted"
    NODE_LIMIT = "node-limit"
    EXPANSION_LIMIT = "expansion-limit"
    TIME_LIMIT = "time-limit"
    MEMORY_LIMIT = "memory-limit"
    #: The user pressed Ctrl-C: the search stopped where it was, with its statistics so far.
    INTERRUPTED = "interrupted"

    def __repr__(self) -> str:
        """``'solved'``: messages quote a status as the word the output shows."""
        return repr(self.value)


#: The status each ``[limits]`` key ends a run with.
LIMIT_STATUS = {
    "time": Status.TIME_LIMIT,
    "memory": Status.MEMORY_LIMIT,
    "nodes": Status.NODE_LIMIT,
    "expansions": Status.EXPANSION_LIMIT,
}


def limit_key(status: Status) -> str | None:
    """The ``[limits]`` key whose limit ends a run with ``status``, if one does."""
    return next((key for key, value in LIMIT_STATUS.items() if value == status), None)


class FamilyStatistics(Protocol):
    """The figures one family of searches reports (see the module docstring)."""

    #: ``"world-model"`` or ``"forward"``: which record the JSON ``statistics`` holds.
    family: ClassVar[str]

    def as_dict(self) -> dict[str, float | int]:
        """The figures by name, as the JSON output carries them."""
        ...

    def lines(self) -> list[str]:
        """The figures as ``name: value`` lines for the text output."""
        ...


class CountedStatistics(Record):
    """Statistics whose JSON form is their fields in order: integer counts as they are,
    float figures rounded to :attr:`DIGITS` places. The forward and lifted searches'
    records are such; a record with derived figures writes its own ``as_dict``."""

    __slots__ = ()
    #: Decimal places of each float field in :meth:`as_dict`.
    DIGITS: ClassVar[dict[str, int]] = {}

    def as_dict(self) -> dict[str, float | int]:
        digits = self.DIGITS
        return {
            name: round(value, digits[name]) if name in digits else value
            for name, value in zip(self.FIELDS, self._values(), strict=True)
        }


class Result(Record):
    """One search's outcome.

    ``plan`` holds the steps in IPC form, ``(name arg ...)``, when ``status`` is SOLVED;
    ``cost`` is the plan's total cost (its length on a unit-cost task); ``seconds`` the
    wall-clock time since the planner's clock started (reading and grounding included when
    the planner read the input). ``tree`` is the search tree of a world-model search (for
    ``--tree`` and the evaluators' tests; a :class:`strips_framework.means_ends.result.Tree`,
    which this bottom layer does not name), ``None`` for forward search.
    """

    status: Status
    plan: tuple[str, ...] | None
    cost: int | None
    statistics: FamilyStatistics
    seconds: float
    uses_costs: bool
    tree: object | None

    __slots__ = ("status", "plan", "cost", "statistics", "seconds", "uses_costs", "tree")

    def __init__(
        self,
        status: Status,
        plan: tuple[str, ...] | None,
        cost: int | None,
        statistics: FamilyStatistics,
        seconds: float = 0.0,
        uses_costs: bool = False,
        tree: object | None = None,
    ) -> None:
        self.status = status
        self.plan = plan
        self.cost = cost
        self.statistics = statistics
        self.seconds = seconds
        self.uses_costs = uses_costs
        self.tree = tree

    @property
    def solved(self) -> bool:
        return self.status == Status.SOLVED

    @property
    def limit(self) -> str | None:
        """The ``[limits]`` key that ended the run, if one did."""
        return limit_key(self.status)

    def _repr_html_(self) -> str:
        """The result in a notebook: status, plan and figures, and the tree, if any."""
        from html import escape

        rows = [("status", str(self.status)), ("plan cost", "-" if self.cost is None else str(self.cost)),
                ("time", f"{self.seconds:.3f} s"),
                *((name, str(value)) for name, value in self.statistics.as_dict().items())]
        table = "".join(f"<tr><th style='text-align:left'>{escape(k)}</th><td>{escape(v)}</td></tr>"
                        for k, v in rows)
        steps = "".join(f"<li><code>{escape(step)}</code></li>" for step in self.plan or ())
        plan = f"<ol>{steps}</ol>" if steps else "<p>no plan</p>"
        tree = ""
        if self.tree is not None:
            tree = f"<details><summary>search tree</summary>{self.tree._repr_html_()}</details>"
        return f"<div><table>{table}</table>{plan}{tree}</div>"
