"""Large lifted states as a checkpoint and its changes (:mod:`strips_framework.lifted.delta`)
against the frozensets they stand for: the same atoms, the same packing (so the same
duplicate detection), and searches that expand, evaluate and plan the same."""

from __future__ import annotations

import random
import sys
from pathlib import Path

import pytest

from strips_framework.lifted import delta
from strips_framework.lifted.delta import DeltaState, successor
from strips_framework.lifted.goal_count import LiftedGoalCount
from strips_framework.lifted.search import LiftedBFWS, LiftedLazyGreedySearch
from strips_framework.lifted.space import LiftedStateSpace
from strips_framework.lifted.successors import Successors
from strips_framework.lifted.task import LiftedTask
from strips_framework.limits import Limits
from strips_framework.plugin.registry import Registry

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "plugins" / "evaluators" / "tests"))
from random_pddl import random_pddl_task  # noqa: E402 - the evaluators' seeded random tasks


@pytest.mark.parametrize("seed", range(10))
def test_a_walk_of_changes_holds_the_atoms_of_the_frozensets(seed: int) -> None:
    """A random walk over 600 atoms, a few changed per step: each state has the
    reference frozenset's atoms (membership, iteration, length, equality both ways,
    hash, set operators), packs to the same bytes, and checkpoints are made."""
    rng = random.Random(seed)
    universe = [("p", f"o{i}") for i in range(900)]
    reference = frozenset(rng.sample(universe, 600))
    state = reference
    space = LiftedStateSpace()
    checkpoints = overlays = 0
    for _ in range(300):
        removed = set(rng.sample(sorted(reference), rng.randint(0, 3)))
        added = set(rng.sample([a for a in universe if a not in reference], rng.randint(0, 3)))
        before = state
        state = successor(state, removed, added)
        reference = (reference - removed) | added
        overlays += type(state) is DeltaState
        checkpoints += type(state) is frozenset and type(before) is DeltaState
        assert len(state) == len(reference)
        assert set(state) == set(reference) and sorted(state) == sorted(reference)
        assert state == reference and reference == state and hash(state) == hash(reference)
        probes = rng.sample(universe, 40) + list(removed) + list(added)
        assert [a in state for a in probes] == [a in reference for a in probes]
        assert state - removed == reference - removed and type(state - removed) is frozenset
        assert state | added == reference | added and state & reference == reference
        assert state.union(added, removed) == reference.union(added, removed)
        assert state.difference(removed, added) == reference.difference(removed, added)
        assert state.intersection(probes) == reference.intersection(probes)
        assert space.pack(state) == space.pack(reference)
    assert overlays > 200 and checkpoints >= 3, (overlays, checkpoints)


def test_small_states_stay_frozensets() -> None:
    state = frozenset(("p", str(i)) for i in range(10))
    after = successor(state, {("p", "0")}, {("q", "0")})
    assert type(after) is frozenset and after == (state - {("p", "0")}) | {("q", "0")}


def _trace(strategy: object, pddl: object, heuristic: str) -> tuple:
    registry = Registry.from_plugins()
    estimator = registry.get("lifted-heuristic", heuristic).cls().for_task(pddl)
    result = strategy.search_task(  # type: ignore[attr-defined]
        Successors(LiftedTask(pddl)), estimator, Limits(time=30, expansions=300)
    )
    s = result.statistics
    return (
        result.status,
        result.plan,
        s.expanded,
        s.evaluated,
        s.generated,
        s.states,
        s.bytes_per_state,
    )


@pytest.mark.parametrize("strategy", [LiftedLazyGreedySearch, LiftedBFWS])
@pytest.mark.parametrize("seed", range(15))
def test_searches_over_overlays_are_the_searches_over_frozensets(
    strategy: type, seed: int, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Every state an overlay (and checkpoints often), against every state a frozenset:
    the same states expanded, evaluated, generated and stored, the same plan."""
    pddl = random_pddl_task(seed)
    monkeypatch.setattr(delta, "SMALL", 10**9)
    frozen = _trace(strategy(), pddl, "goal-count")
    monkeypatch.setattr(delta, "SMALL", 0)
    monkeypatch.setattr(delta, "SHARE", 4)
    made = []
    monkeypatch.setattr(delta.DeltaState, "__init__", _counting(made))
    assert _trace(strategy(), pddl, "goal-count") == frozen
    assert made or frozen[2] <= 1


def _counting(made: list) -> object:
    init = DeltaState.__init__

    def counted(self: DeltaState, *args: object) -> None:
        made.append(1)
        init(self, *args)

    return counted


def test_goal_count_and_hadd_take_overlays(monkeypatch: pytest.MonkeyPatch) -> None:
    """The heuristics read an overlay as the frozenset it stands for."""
    registry = Registry.from_plugins()
    for seed in range(10):
        pddl = random_pddl_task(seed)
        successors = Successors(LiftedTask(pddl))
        init = successors.task.init
        overlay = DeltaState(init, frozenset(), frozenset())
        facts = successors.facts(init)
        estimators = [LiftedGoalCount().for_task(pddl)]
        if "hadd" in registry.names("lifted-heuristic"):
            estimators.append(registry.get("lifted-heuristic", "hadd").cls().for_task(pddl))
        for step in successors.applicable(facts)[:5]:
            removed, added, _ = successors.change(init, facts, step)
            child = (init - removed) | added
            as_overlay = DeltaState(init, frozenset(removed), frozenset(added))
            assert as_overlay == child
            for estimator in estimators:
                assert estimator.estimate(as_overlay) == estimator.estimate(child)
        assert all(e.estimate(overlay) == e.estimate(init) for e in estimators)
