"""Checks of a state heuristic on every reachable state of the kit's PDDL tasks.

The estimates are compared with the exact costs of :mod:`~strips_framework.testing.ground_space`:
what every heuristic owes the strategies (0 on goal states, no negative or NaN values,
``math.inf`` only where no plan exists, preferred operators that apply, the same answer
every time it is asked; preferred operators named if and only if declared) and, for one
declaring ``admissible``, never more than the cost of a cheapest plan from the state.
"""

from __future__ import annotations

import math
from collections.abc import Collection, Sequence

from strips_framework.capabilities import ADMISSIBLE, PREFERRED_OPERATORS
from strips_framework.forward.components import StateHeuristic
from strips_framework.grounding.task import GroundTask
from strips_framework.testing.declaration import ConformanceFailure
from strips_framework.testing.ground_tasks import UNSOLVABLE, ground_task, task_space


def check_heuristic(heuristic: StateHeuristic, name: str, capabilities: Collection[str]) -> int:
    """Check ``heuristic`` on every reachable state of kit task ``name``; returns how many
    states were checked. Each state is estimated by one estimator in breadth-first order,
    then again in reverse order and by a second estimator, which must agree."""
    task = ground_task(name)
    space = task_space(name)
    first = heuristic.for_task(task)
    values = {}
    preferring = 0
    for state in space.states:
        value, preferred = first.estimate_with_preferred(state)
        where = f"{heuristic.name!r} on {name}, state {_show(task, state)}"
        _check_value(value, space.cost_to_go[state], task.is_goal(state), capabilities, where)
        _check_preferred(task, state, preferred, where)
        values[state] = value
        preferring += bool(preferred)
    _check_prefers_as_declared(
        heuristic.name, name, preferring, PREFERRED_OPERATORS in capabilities
    )
    second = heuristic.for_task(task)
    for state in reversed(space.states):
        again = (
            first.estimate(state),
            second.estimate(state),
            second.estimate_with_preferred(state)[0],
        )
        if any(value != values[state] for value in again):
            raise ConformanceFailure(
                f"{heuristic.name!r} on {name}: state {_show(task, state)} first scored "
                f"{values[state]}, then {list(again)} (estimate, a second estimator, with "
                "preferred operators); a heuristic must give a state the same value every time"
            )
    return len(space.states)


def _check_value(
    value: float, exact: float, is_goal: bool, capabilities: Collection[str], where: str
) -> None:
    if not isinstance(value, (int, float)) or math.isnan(value) or value < 0:
        raise ConformanceFailure(f"{where}: estimate {value!r}; it must be a number >= 0")
    if is_goal and value != 0:
        raise ConformanceFailure(f"{where}: a goal state scores {value}; it must score 0")
    if value == math.inf and exact != math.inf:
        raise ConformanceFailure(
            f"{where}: math.inf (a dead end), but a plan of cost {exact} exists from it; "
            "strategies prune such states, so the heuristic would lose plans"
        )
    if ADMISSIBLE in capabilities and value > exact + 1e-9:
        raise ConformanceFailure(
            f"{where}: declares 'admissible' but estimates {value} where the cheapest plan "
            f"costs {exact}"
        )


def _check_preferred(task: GroundTask, state: int, preferred: Sequence[int], where: str) -> None:
    for index in preferred:
        if not isinstance(index, int) or not 0 <= index < len(task.operators):
            raise ConformanceFailure(
                f"{where}: preferred operator {index!r} is not an index into task.operators"
            )
        if not task.operators[index].applicable(state):
            raise ConformanceFailure(
                f"{where}: prefers {task.operators[index].name}, which is not applicable there"
            )


def _check_prefers_as_declared(heuristic: str, name: str, preferring: int, declares: bool) -> None:
    """Strategies use preferred operators only of heuristics declaring them; one that
    declares them must name some wherever a plan exists (every kit task has plans)."""
    if declares and not preferring and name != UNSOLVABLE:
        raise ConformanceFailure(
            f"{heuristic!r} declares {PREFERRED_OPERATORS!r} but prefers no operator in any "
            f"state of {name}"
        )
    if not declares and preferring:
        raise ConformanceFailure(
            f"{heuristic!r} prefers operators in {preferring} states of {name} but does not "
            f"declare {PREFERRED_OPERATORS!r}"
        )


def _show(task: GroundTask, state: int) -> str:
    return "{" + ", ".join(task.facts_of(state)) + "}"
