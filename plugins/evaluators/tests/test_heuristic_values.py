"""Heuristic values on small tasks, worked out by hand (see SMALL_TASKS in conftest.py)."""

from __future__ import annotations

import math

import pytest

from strips_evaluators.heuristics.ff import FFHeuristic
from strips_framework.plugin.registry import Registry

# This plugin's state heuristics and the core's builtin blind one, as a run finds them.
_REGISTRY = Registry.from_plugins()
HEURISTICS = {name: _REGISTRY.get("heuristic", name).cls for name in _REGISTRY.names("heuristic")}

INF = math.inf

#: Initial-state value of each heuristic on each task.
EXPECTED = {
    "chain": {"blind": 1, "goal-count": 1, "hmax": 3, "hadd": 3, "ff": 3, "lmcut": 3, "lmcount": 3},
    "fork": {"blind": 1, "goal-count": 1, "hmax": 2, "hadd": 3, "ff": 3, "lmcut": 3, "lmcount": 3},
    "shared": {
        "blind": 1,
        "goal-count": 2,
        "hmax": 2,
        "hadd": 4,
        "ff": 3,
        "lmcut": 3,
        "lmcount": 3,
    },
    "costs": {"blind": 1, "goal-count": 1, "hmax": 3, "hadd": 3, "ff": 3, "lmcut": 3, "lmcount": 2},
    "axiom": {"blind": 1, "goal-count": 1, "hmax": 2, "hadd": 3, "ff": 2, "lmcut": 2, "lmcount": 2},
    "negative": {
        "blind": 1,
        "goal-count": 1,
        "hmax": 1,
        "hadd": 1,
        "ff": 1,
        "lmcut": 1,
        "lmcount": 1,
    },
    "dead": {
        "blind": 1,
        "goal-count": 2,
        "hmax": INF,
        "hadd": INF,
        "ff": INF,
        "lmcut": INF,
        "lmcount": INF,
    },
}


@pytest.mark.parametrize(
    ("task_name", "heuristic_name", "value"),
    [(task, name, value) for task, row in EXPECTED.items() for name, value in row.items()],
)
def test_initial_state_value(small_task, task_name: str, heuristic_name: str, value: float) -> None:
    task = small_task(task_name)
    estimator = HEURISTICS[heuristic_name]().for_task(task)
    assert estimator.estimate(task.init) == value
    assert estimator.estimate_with_preferred(task.init)[0] == value


@pytest.mark.parametrize("heuristic_name", sorted(HEURISTICS))
@pytest.mark.parametrize("task_name", ["chain", "shared", "costs", "axiom"])
def test_goal_states_score_zero(small_task, task_name: str, heuristic_name: str) -> None:
    task = small_task(task_name)
    goal_state = task.init | task.goal_mask
    assert HEURISTICS[heuristic_name]().for_task(task).estimate(goal_state) == 0


def test_ff_prefers_the_relaxed_plan_operators_applicable_in_the_state(small_task) -> None:
    task = small_task("fork")
    value, preferred = FFHeuristic().for_task(task).estimate_with_preferred(task.init)
    assert value == 3
    assert [task.operators[i].name for i in preferred] == ["sp", "sq"]


def test_ff_follows_the_cheapest_supporters(small_task) -> None:
    task = small_task("costs")
    _, preferred = FFHeuristic().for_task(task).estimate_with_preferred(task.init)
    assert [task.operators[i].name for i in preferred] == ["to-m"]


def test_ff_does_not_prefer_operators_whose_negative_precondition_fails(small_task) -> None:
    task = small_task("negative")
    value, preferred = FFHeuristic().for_task(task).estimate_with_preferred(task.init)
    assert (value, list(preferred)) == (1, [])
    unlocked = task.init & ~(1 << task.facts.index("q"))
    assert FFHeuristic().for_task(task).estimate_with_preferred(unlocked) == (1, [0])


def test_ff_on_a_dead_end_prefers_nothing(small_task) -> None:
    task = small_task("dead")
    assert FFHeuristic().for_task(task).estimate_with_preferred(task.init) == (INF, [])


HAND = [
    ("grab1", "free", "held1", "free"),
    ("place1", "held1", "placed1 free", "held1"),
    ("grab2", "free", "held2", "free"),
    ("place2", "held2", "placed2 free", "held2"),
]


def test_lmcount_counts_landmarks_required_again(make_task) -> None:
    """After grab1, ``free`` was reached (it held initially) but is necessary for held2,
    which is still to come: it counts again, beside placed1, held2 and placed2."""
    task = make_task(HAND, init="free", goal="placed1 placed2")
    estimator = HEURISTICS["lmcount"]().for_task(task)
    assert estimator.estimate(task.init) == 4  # held1, placed1, held2, placed2
    after_grab = task.operators[0].apply(task.init)
    value, preferred = estimator.estimate_with_preferred(after_grab)
    assert value == 4
    assert [task.operators[i].name for i in preferred] == ["place1"]
    after_place = task.operators[1].apply(after_grab)
    assert estimator.estimate(after_place) == 2  # held2, placed2; placed1 stays accepted


def test_lmcount_weighs_landmarks_by_their_cheapest_achiever(small_task) -> None:
    task = small_task("costs")  # g is a landmark (cheapest achiever costs 2), m is not
    value, preferred = HEURISTICS["lmcount"]().for_task(task).estimate_with_preferred(task.init)
    assert value == 2
    assert [task.operators[i].name for i in preferred] == ["direct"]


#: ``done`` the slow way (cost 2), or the fast way that also needs ``tool`` (cost 1 each);
#: the goal wants ``key`` too. Optimal cost 3 (get-key, slow; or get-key, get-tool, fast).
KEY_AND_TOOL = [
    ("slow", "start", "done", "", 2),
    ("fast", "start key tool", "done", "", 1),
    ("get-tool", "", "tool", "", 1),
    ("get-key", "", "key", "", 1),
]


def test_lmcut_breaks_supporter_ties_at_the_goal_zone_border(make_task) -> None:
    """After the first cut ({slow, fast}, 1) ``fast`` costs 0 and ``done`` and ``key``
    tie at hmax 1. Taking ``key`` through the zero-cost ``fast`` into the goal zone gives
    the weak landmark {slow, get-key} (get-key is needed anyway) and h = 2. Fast
    Downward's tie-breaking takes a tied precondition that no zero-cost operator adds
    (``key``, at the zone's border) as the goal's supporter instead: landmarks {get-key}
    and then {slow, get-tool}, h = 3, the optimal cost."""
    task = make_task(KEY_AND_TOOL, init="start", goal="done key", uses_costs=True)
    assert HEURISTICS["lmcut"]().for_task(task).estimate(task.init) == 3


def test_ff_supporter_ties_go_to_the_fact_reached_last(make_task) -> None:
    """``p`` and ``q`` both hold, and ``x`` costs 1 through either operator. Facts of
    equal cost leave the queue last in, first out, as in Fast Downward: ``q`` (queued
    after ``p``, which influences it through ``spoil``: causal order) goes first, so
    ``from-q`` reaches ``x`` first, becomes its supporter and the preferred operator."""
    task = make_task(
        [("from-p", "p", "x", ""), ("from-q", "q", "x", ""), ("spoil", "p", "", "q")],
        init="p q",
        goal="x",
    )
    value, preferred = HEURISTICS["ff"]().for_task(task).estimate_with_preferred(task.init)
    assert value == 1
    assert [task.operators[i].name for i in preferred] == ["from-q"]
