"""What a forward search reports beyond the common :class:`~strips_framework.result.Result`:
the counts Fast Downward reports."""

from __future__ import annotations

from strips_framework.result import CountedStatistics


class ForwardStatistics(CountedStatistics):
    """Counts as Fast Downward reports them: ``expanded`` states (successors generated),
    ``evaluated`` heuristic calls, ``generated`` successor states, ``reopened`` closed
    states reached again more cheaply; ``dead_ends`` states the heuristic proved hopeless.
    Times are wall-clock seconds; ``peak_memory_mib`` is the process's peak resident set."""

    family = "forward"  # a class attribute, not a field (FamilyStatistics.family)
    DIGITS = {"parse_seconds": 4, "ground_seconds": 4, "search_seconds": 4, "peak_memory_mib": 1}

    expanded: int
    evaluated: int
    generated: int
    reopened: int
    dead_ends: int
    facts: int
    operators: int
    parse_seconds: float
    ground_seconds: float
    search_seconds: float
    peak_memory_mib: float

    __slots__ = (
        "expanded",
        "evaluated",
        "generated",
        "reopened",
        "dead_ends",
        "facts",
        "operators",
        "parse_seconds",
        "ground_seconds",
        "search_seconds",
        "peak_memory_mib",
    )

    def __init__(
        self,
        expanded: int = 0,
        evaluated: int = 0,
        generated: int = 0,
        reopened: int = 0,
        dead_ends: int = 0,
        facts: int = 0,
        operators: int = 0,
        parse_seconds: float = 0.0,
        ground_seconds: float = 0.0,
        search_seconds: float = 0.0,
        peak_memory_mib: float = 0.0,
    ) -> None:
        self.expanded = expanded
        self.evaluated = evaluated
        self.generated = generated
        self.reopened = reopened
        self.dead_ends = dead_ends
        self.facts = facts
        self.operators = operators
        self.parse_seconds = parse_seconds
        self.ground_seconds = ground_seconds
        self.search_seconds = search_seconds
        self.peak_memory_mib = peak_memory_mib

    def lines(self) -> list[str]:
        """``expanded: N`` and the like, one a line, as Fast Downward users' scripts look
        for them."""
        return [
            f"expanded: {self.expanded}",
            f"evaluated: {self.evaluated}",
            f"generated: {self.generated}",
            f"reopened: {self.reopened}",
            f"dead ends: {self.dead_ends}",
            f"facts: {self.facts}, operators: {self.operators}",
            (
                f"phases: parse {self.parse_seconds:.3f} s, ground {self.ground_seconds:.3f} s, "
                f"search {self.search_seconds:.3f} s"
            ),
            f"peak memory: {self.peak_memory_mib:.1f} MiB",
        ]
