"""Width-1 novelty of lifted states within partitions (Lipovetzky and Geffner's BFWS):
a state is novel (1) when it holds an atom that no earlier state of its partition held,
else 2. The partition is the caller's: ``lifted-bfws`` partitions by the estimate,
``lifted-alt-bfws`` by (goal literals lacking, relevant atoms lacking). Novelty ranks
states that look alike to those measures by whether they reach something new."""

from __future__ import annotations

from collections.abc import Collection, Hashable
from collections.abc import Set as AbstractSet

from strips_framework.lifted.components import GroundAtom


class Novelty:
    """The atoms seen so far in each partition."""

    def __init__(self) -> None:
        self._seen: dict[Hashable, set[GroundAtom]] = {}

    def of(
        self,
        state: AbstractSet[GroundAtom] | None,
        partition: Hashable,
        added: Collection[GroundAtom] | None = None,
    ) -> int:
        """1 or 2, and ``state``'s atoms recorded in ``partition``. ``added``, when
        given: ``state`` (then not needed) is a successor of a state tested here in the
        same partition, which it differs from by gaining ``added`` (and losing some).
        That state's atoms were all recorded then, so only ``added`` can be new, and the
        test costs what the action changed rather than the state's size."""
        seen = self._seen.setdefault(partition, set())
        if added is not None:
            new = [atom for atom in added if atom not in seen]
        else:
            assert state is not None
            new = state - seen if seen else state
        if new:
            seen.update(new)
            return 1
        return 2
