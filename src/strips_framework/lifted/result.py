"""What a lifted search reports beyond the common :class:`~strips_framework.result.Result`:
Fast Downward's counts, and what a grounded search has no use for: how many states were
stored and what each costs in memory."""

from __future__ import annotations

from strips_framework.result import CountedStatistics


class LiftedStatistics(CountedStatistics):
    """``expanded``, ``evaluated``, ``generated`` and ``dead_ends`` as Fast Downward
    counts them; ``states`` stored, ``bytes_per_state`` what each costs in the state
    space (:meth:`~strips_framework.lifted.space.LiftedStateSpace.bytes_per_state`),
    ``atoms`` the distinct atoms the states held, ``actions`` the action schemas. Times
    are wall-clock seconds (``setup_seconds``: compiling the task and the heuristic's
    set-up); ``peak_memory_mib`` is the process's peak resident set."""

    family = "lifted"  # a class attribute, not a field (FamilyStatistics.family)
    DIGITS = {
        "bytes_per_state": 1,
        "parse_seconds": 4,
        "setup_seconds": 4,
        "search_seconds": 4,
        "peak_memory_mib": 1,
    }

    expanded: int
    evaluated: int
    generated: int
    dead_ends: int
    states: int
    bytes_per_state: float
    atoms: int
    actions: int
    parse_seconds: float
    setup_seconds: float
    search_seconds: float
    peak_memory_mib: float

    __slots__ = (
        "expanded",
        "evaluated",
        "generated",
        "dead_ends",
        "states",
        "bytes_per_state",
        "atoms",
        "actions",
        "parse_seconds",
        "setup_seconds",
        "search_seconds",
        "peak_memory_mib",
    )

    def __init__(
        self,
        expanded: int = 0,
        evaluated: int = 0,
        generated: int = 0,
        dead_ends: int = 0,
        states: int = 0,
        bytes_per_state: float = 0.0,
        atoms: int = 0,
        actions: int = 0,
        parse_seconds: float = 0.0,
        setup_seconds: float = 0.0,
        search_seconds: float = 0.0,
        peak_memory_mib: float = 0.0,
    ) -> None:
        self.expanded = expanded
        self.evaluated = evaluated
        self.generated = generated
        self.dead_ends = dead_ends
        self.states = states
        self.bytes_per_state = bytes_per_state
        self.atoms = atoms
        self.actions = actions
        self.parse_seconds = parse_seconds
        self.setup_seconds = setup_seconds
        self.search_seconds = search_seconds
        self.peak_memory_mib = peak_memory_mib

    def lines(self) -> list[str]:
        """``expanded: N`` and the like, one a line, as for the forward search."""
        return [
            f"expanded: {self.expanded}",
            f"evaluated: {self.evaluated}",
            f"generated: {self.generated}",
            f"dead ends: {self.dead_ends}",
            f"states: {self.states} ({self.bytes_per_state:.0f} bytes each), atoms: "
            f"{self.atoms}, action schemas: {self.actions}",
            (
                f"phases: parse {self.parse_seconds:.3f} s, set-up {self.setup_seconds:.3f} s, "
                f"search {self.search_seconds:.3f} s"
            ),
            f"peak memory: {self.peak_memory_mib:.1f} MiB",
        ]
