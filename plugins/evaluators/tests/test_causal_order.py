"""The order a state's facts enter hadd's exploration (``causal_order.py``): sources of the
fact causal graph first, so that the facts depending on others leave the last-in-first-
out queue first, as Fast Downward's variable order makes its exploration do. The order
decides which of equally cheap supporters hFF's relaxed plan takes, hence the preferred
operators; both explorers (compiled and reference) must follow it."""

from __future__ import annotations

import pytest
from shared_bench import small_bench

from strips_evaluators.heuristics.causal_order import causal_order
from strips_evaluators.heuristics.exploration import explorer
from strips_evaluators.heuristics.relaxation import relax
from strips_framework.grounding import ground
from strips_framework.pddl import find_domain, load_task

#: A package and a truck at A; the package is mentioned first, so it has the lower fact
#: number. Loading needs both and deletes the package's place: an arc from the truck's
#: fact to the package's, none back. ``(by-truck)`` and ``(by-package)`` reach the goal
#: equally cheaply from one of them each.
OPERATORS = [
    ("(load)", "package-at-a truck-at-a", "package-in", "package-at-a"),
    ("(drive)", "truck-at-a", "truck-at-b", "truck-at-a"),
    ("(by-package)", "package-at-a", "goal", ""),
    ("(by-truck)", "truck-at-a", "goal", ""),
]


def test_a_fact_comes_before_the_facts_it_influences(make_task):
    task = make_task(OPERATORS, "package-at-a truck-at-a", "goal")
    order = [task.facts[fact] for fact in causal_order(task)]
    assert order.index("truck-at-a") < order.index("package-at-a") < order.index("goal")
    assert sorted(order) == sorted(task.facts)


@pytest.mark.parametrize("compiled", [False, True])
def test_the_influenced_fact_is_explored_first_and_its_operator_supports(make_task, compiled):
    """Pushed after the truck's fact, the package's leaves the stack first, so
    ``(by-package)`` reaches the goal first and is the relaxed plan (in ascending fact
    order it would be ``(by-truck)``)."""
    task = make_task(OPERATORS, "package-at-a truck-at-a", "goal")
    hff, preferred = explorer(relax(task), compiled=compiled).preferred(task.init)
    assert hff == 1
    assert [task.operators[op].name for op in preferred] == ["(by-package)"]


IPC = small_bench("ipc")
#: The first six steps of Fast Downward's plan for depot task05.
FD_PLAN_START = [
    "(drive truck1 distributor0 depot0)",
    "(lift hoist0 crate4 crate3 depot0)",
    "(load hoist0 crate4 truck1 depot0)",
    "(drive truck1 depot0 distributor1)",
    "(drive truck0 depot0 distributor1)",
    "(lift hoist2 crate9 crate5 distributor1)",
]


@pytest.mark.parametrize("compiled", [False, True])
def test_depot_relaxed_plans_share_a_truck_as_fast_downwards_do(compiled):
    """Depot task05 after the first six steps of Fast Downward's plan (a hoist holds
    crate9, both trucks at distributor1): Fast Downward's hFF is 35, with one truck
    carrying everything; ascending fact order gives 39, the relaxed plan loading crate9
    into the other truck and driving both."""
    problem = IPC / "depot" / "task05.pddl"
    task = ground(load_task(find_domain(problem), problem))
    by_name = {op.name: op for op in task.operators}
    state = task.init
    for step in FD_PLAN_START:
        assert by_name[step].applicable(state), step
        state = by_name[step].apply(state)
    assert explorer(relax(task, factor_sharing=8), compiled=compiled).relaxed_plan(state)[0] == 35
