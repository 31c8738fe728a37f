"""What a search returns: the plan, the tree, and the paper's Table 2 figures."""

from __future__ import annotations

from attrs import frozen

from strips_framework.operators import OperatorInstance
from strips_framework.search.node import Node, path_to

SOLVED = "solved"
EXHAUSTED = "exhausted"  # every node was expanded: no plan within this strategy's reach
NODE_LIMIT = "node-limit"
TIME_LIMIT = "time-limit"
#: The user pressed Ctrl-C: the search stopped where it was, with its statistics so far.
INTERRUPTED = "interrupted"


@frozen
class Statistics:
    """The columns of the paper's Table 2, plus the prover's share of the time.

    ``nodes`` counts every node generated; ``applications`` the nodes made by applying an
    operator; the ``path_`` figures count the same along the solution path (2k+1 nodes and
    k applications for a k-step plan found by means-ends analysis).
    """

    nodes: int
    applications: int
    path_nodes: int
    path_applications: int
    seconds: float
    proving_seconds: float
    proof_attempts: int

    @property
    def proving_share(self) -> float:
        return self.proving_seconds / self.seconds if self.seconds else 0.0

    def as_dict(self) -> dict[str, float | int]:
        return {
            "nodes": self.nodes,
            "applications": self.applications,
            "path_nodes": self.path_nodes,
            "path_applications": self.path_applications,
            "seconds": round(self.seconds, 4),
            "proving_seconds": round(self.proving_seconds, 4),
            "proving_share": round(self.proving_share, 3),
            "proof_attempts": self.proof_attempts,
        }


@frozen
class SearchResult:
    """``status`` is one of SOLVED, EXHAUSTED, NODE_LIMIT, TIME_LIMIT; ``nodes`` is the
    whole search tree in generation order and ``solution`` its goal node, if any."""

    status: str
    plan: tuple[OperatorInstance, ...] | None
    statistics: Statistics
    nodes: tuple[Node, ...]
    solution: Node | None

    @property
    def solved(self) -> bool:
        return self.status == SOLVED

    def solution_path(self) -> list[Node]:
        """The nodes from the root to the goal node (empty when unsolved)."""
        return path_to(self.solution)
