"""What a forward search returns: status, plan, cost and the figures of the run."""

from __future__ import annotations

from attrs import frozen

from strips_framework.search import result

SOLVED = "solved"
#: A complete search visited every reachable state that is not a proven dead end.
UNSOLVABLE = "unsolvable"
#: An incomplete search (enforced hill-climbing) gave up without a plan.
EXHAUSTED_INCOMPLETE = "exhausted-incomplete"
TIME_LIMIT = "time-limit"
MEMORY_LIMIT = "memory-limit"
EXPANSION_LIMIT = "expansion-limit"
INTERRUPTED = result.INTERRUPTED

#: The status that each limit ends a run with, by the ``[limits]`` key.
LIMIT_STATUS = {"time": TIME_LIMIT, "memory": MEMORY_LIMIT, "expansions": EXPANSION_LIMIT}


@frozen
class ForwardStatistics:
    """Counts as Fast Downward reports them: ``expanded`` states (successors generated),
    ``evaluated`` heuristic calls, ``generated`` successor states, ``reopened`` closed
    states reached again more cheaply; ``dead_ends`` states the heuristic proved hopeless.
    Times are wall-clock seconds; ``peak_memory_mib`` is the process's peak resident set."""

    expanded: int = 0
    evaluated: int = 0
    generated: int = 0
    reopened: int = 0
    dead_ends: int = 0
    facts: int = 0
    operators: int = 0
    parse_seconds: float = 0.0
    ground_seconds: float = 0.0
    search_seconds: float = 0.0
    peak_memory_mib: float = 0.0

    def as_dict(self) -> dict[str, float | int]:
        return {
            "expanded": self.expanded,
            "evaluated": self.evaluated,
            "generated": self.generated,
            "reopened": self.reopened,
            "dead_ends": self.dead_ends,
            "facts": self.facts,
            "operators": self.operators,
            "parse_seconds": round(self.parse_seconds, 4),
            "ground_seconds": round(self.ground_seconds, 4),
            "search_seconds": round(self.search_seconds, 4),
            "peak_memory_mib": round(self.peak_memory_mib, 1),
        }


@frozen
class ForwardResult:
    """``plan`` holds the operator names (IPC steps) when ``status`` is SOLVED; ``cost``
    is the plan's total cost (its length on a unit-cost task). ``limit`` names the
    ``[limits]`` key that ended the run, if one did."""

    status: str
    plan: tuple[str, ...] | None
    cost: int | None
    statistics: ForwardStatistics
    uses_costs: bool = False

    @property
    def solved(self) -> bool:
        return self.status == SOLVED

    @property
    def limit(self) -> str | None:
        return next((key for key, status in LIMIT_STATUS.items() if status == self.status), None)
