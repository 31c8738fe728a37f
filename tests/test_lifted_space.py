"""The lifted state space (:mod:`strips_framework.lifted.space`) against a table of
frozensets: states stored as changes and checkpoints, keyed by an incremental hash,
find the same duplicates and give back the same states, also when hashes collide."""

from __future__ import annotations

import random

import pytest

from strips_framework.lifted import space as space_module
from strips_framework.lifted.goal_count import LiftedGoalCount
from strips_framework.lifted.search import LiftedBFWS, LiftedLazyGreedySearch
from strips_framework.lifted.space import NO_PARENT, LiftedStateSpace
from strips_framework.lifted.successors import Successors
from strips_framework.lifted.task import LiftedTask
from strips_framework.limits import Limits


class _FewCodes(random.Random):
    """Codes from {0, 1, 2, 3}: most states' hashes collide."""

    def getrandbits(self, k: int) -> int:
        return super().getrandbits(2)


@pytest.mark.parametrize("mode", ["whole", "changes", "colliding changes"])
@pytest.mark.parametrize("seed", range(8))
def test_duplicates_and_states_are_those_of_a_frozenset_table(
    seed: int, mode: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A random search tree over 40 atoms (children of random stored states, a few
    atoms changed, often back to a stored state), its states stored whole or as
    changes: a key is found exactly when the frozenset is, under the same number, and
    every stored state comes back whole, with short checkpoint chains and few states
    kept rebuilt."""
    monkeypatch.setattr(space_module, "WHOLE", 10**9 if mode == "whole" else 0)
    monkeypatch.setattr(space_module, "CHECKPOINT", 3)
    monkeypatch.setattr(space_module, "REBUILT", 2)
    rng = random.Random(seed)
    universe = [("p", f"o{i}") for i in range(40)]
    space = LiftedStateSpace()
    if mode == "colliding changes":
        space._random = _FewCodes(seed)
    init = frozenset(rng.sample(universe, 20))
    reference: dict[frozenset, int] = {init: space.add(space.pack(init), NO_PARENT, None, 0)}
    states = [init]
    found = 0
    for _ in range(400):
        parent = rng.randrange(len(states))
        state = states[parent]
        removed = set(rng.sample(sorted(state), rng.randint(0, 2)))
        added = set(rng.sample([a for a in universe if a not in state], rng.randint(0, 2)))
        child = (state - removed) | added
        key = space.repack(parent, removed, added)
        assert (key in space.ids) == (child in reference)
        if child in reference:
            assert space.ids[key] == reference[child]
            found += 1
        else:
            reference[child] = space.add(key, parent, ("a", ()), 1)
            states.append(child)
        assert space.pack(child) in space.ids and space.ids[space.pack(child)] == reference[child]
    assert found > 30 and len(states) > 100, (found, len(states))
    for state, number in reference.items():
        assert space.state(number) == state
    if mode == "whole":
        assert all(type(key) is bytes for key in space.ids)
    else:
        assert max(space._depths) == 2 and 0 in space._depths[1:]


@pytest.mark.parametrize("strategy", [LiftedLazyGreedySearch, LiftedBFWS])
@pytest.mark.parametrize("seed", range(10))
def test_a_search_finds_the_same_duplicates_with_colliding_hashes(
    strategy: type, seed: int, monkeypatch: pytest.MonkeyPatch
) -> None:
    """States stored as changes, with hashes that mostly collide and short chains: a
    search stores, expands and plans as with its states stored whole (bytes compared):
    the equality test decides, not the hash."""
    import sys
    from pathlib import Path

    sys.path.insert(
        0, str(Path(__file__).resolve().parents[1] / "plugins" / "evaluators" / "tests")
    )
    from random_pddl import random_pddl_task

    pddl = random_pddl_task(seed)

    def trace() -> tuple:
        result = strategy().search_task(
            Successors(LiftedTask(pddl)),
            LiftedGoalCount().for_task(pddl),
            Limits(time=30, expansions=300),
        )
        s = result.statistics
        return result.status, result.plan, s.expanded, s.evaluated, s.generated, s.states

    real = trace()  # (random tasks' states are small: stored whole)
    monkeypatch.setattr(space_module, "WHOLE", 0)
    monkeypatch.setattr(space_module.random, "Random", _FewCodes)
    monkeypatch.setattr(space_module, "CHECKPOINT", 2)
    monkeypatch.setattr(space_module, "REBUILT", 1)
    assert trace() == real
