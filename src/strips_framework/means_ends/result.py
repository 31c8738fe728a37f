"""What a world-model search reports beyond the common
:class:`~strips_framework.result.Result`: the paper's Table 2 figures and the tree."""

from __future__ import annotations

from typing import ClassVar

from strips_framework.means_ends.node import Node, path_to
from strips_framework.records import Record


class WorldModelStatistics(Record):
    """The columns of the paper's Table 2, plus the prover's share of the time.

    ``nodes`` counts every node generated; ``applications`` the nodes made by applying an
    operator; the ``path_`` figures count the same along the solution path (2k+1 nodes and
    k applications for a k-step plan found by means-ends analysis). ``seconds`` is the
    search's own time, of which ``proving_seconds`` went to the prover.
    """

    family: ClassVar[str] = "world-model"

    nodes: int
    applications: int
    path_nodes: int
    path_applications: int
    seconds: float
    proving_seconds: float
    proof_attempts: int

    __slots__ = ("nodes", "applications", "path_nodes", "path_applications", "seconds",
                 "proving_seconds", "proof_attempts")  # fmt: skip

    def __init__(
        self,
        nodes: int,
        applications: int,
        path_nodes: int,
        path_applications: int,
        seconds: float,
        proving_seconds: float,
        proof_attempts: int,
    ) -> None:
        self.nodes = nodes
        self.applications = applications
        self.path_nodes = path_nodes
        self.path_applications = path_applications
        self.seconds = seconds
        self.proving_seconds = proving_seconds
        self.proof_attempts = proof_attempts

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

    def lines(self) -> list[str]:
        return [
            f"nodes: {self.nodes} in the tree, {self.path_nodes} on the solution path",
            (
                f"operator applications: {self.applications} in the tree, "
                f"{self.path_applications} on the solution path"
            ),
            (
                f"search: {self.seconds:.3f} s, proving {self.proving_seconds:.3f} s "
                f"({100 * self.proving_share:.0f}%), {self.proof_attempts} proof attempts"
            ),
            f"expanded: {self.nodes}",
        ]


class Tree(Record):
    """The whole search tree in generation order and its goal node, if any."""

    nodes: tuple[Node, ...]
    solution: Node | None

    __slots__ = ("nodes", "solution")

    def __init__(self, nodes: tuple[Node, ...], solution: Node | None) -> None:
        self.nodes = nodes
        self.solution = solution

    def solution_path(self) -> list[Node]:
        """The nodes from the root to the goal node (empty when unsolved)."""
        return path_to(self.solution)

    def _repr_html_(self) -> str:
        """The tree in a notebook (see :mod:`strips_framework.means_ends.display`)."""
        from strips_framework.means_ends.display import tree_html

        return tree_html(self)
