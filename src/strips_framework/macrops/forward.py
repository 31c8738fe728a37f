"""MACROPs as macro operators of a ground task, for forward search.

Every instance of a MACROP whose steps are all ground operators of the task becomes one
more ground operator: its precondition is what the steps need that earlier steps do not
add, its effects are the steps' effects composed (for STRIPS operators, with deletes before
adds, the composition is exact: ``(s - D1 - D2) | (A1 - D2) | A2``), and its cost is the sum
of theirs. Instances in which a step needs what an earlier one deleted can never apply and
are left out. The search sees an ordinary task; the plan it returns is expanded back into
the steps.
"""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Callable, Iterator, Sequence
from typing import TYPE_CHECKING

from strips_framework.grounding.task import GroundOperator, GroundTask
from strips_framework.logic.terms import Param, Term
from strips_framework.macrops.macrop import Library
from strips_framework.macrops.proofs import MacroError
from strips_framework.macrops.table import TriangleTable

if TYPE_CHECKING:
    from strips_framework.limits import Clock
    from strips_framework.result import Result

#: Macro operator names start with this, so that plans can be expanded.
MACRO_PREFIX = "(macrop "


def with_macros(
    task: GroundTask, library: Library, per_macrop: int = 500, effort: int = 50000
) -> tuple[GroundTask, dict[str, tuple[str, ...]]]:
    """The task with up to ``per_macrop`` ground instances of each MACROP added (found
    within ``effort`` candidate steps), and for each added operator's name the names of
    its steps."""
    if task.axioms or any(op.pre_neg for op in task.operators):
        raise MacroError(
            f"{task.name}: MACROPs as macro operators need a STRIPS task without derived "
            "facts or negative preconditions"
        )
    by_name: dict[str, list[tuple[tuple[str, ...], GroundOperator]]] = defaultdict(list)
    for op in task.operators:
        name, *args = op.name.strip("()").split()
        by_name[name.lower()].append((tuple(a.lower() for a in args), op))
    added: list[GroundOperator] = []
    steps_of: dict[str, tuple[str, ...]] = {}
    for macrop in library.macrops:
        count = 0
        for chosen in _instances(macrop.table, by_name, effort):
            composed = _compose(chosen)
            if composed is None:
                continue
            name = f"{MACRO_PREFIX}{macrop.name} {len(added)})"
            added.append(composed._replace(name=name))
            steps_of[name] = tuple(op.name for op in chosen)
            count += 1
            if count >= per_macrop:
                break
    return task._replace(operators=(*task.operators, *added)), steps_of


def solve_with_macros(
    solve_task: Callable[[GroundTask, Clock | None], Result],
    task: GroundTask,
    library: Library,
    clock: Clock | None = None,
) -> Result:
    """Search ``task`` with the library's macro operators added, by ``solve_task`` (the
    planner's :meth:`~strips_framework.planner.Planner.solve_task`); the plan comes back in
    the task's own steps (on a unit-cost task its cost is then its length)."""
    grown, steps_of = with_macros(task, library)
    result = solve_task(grown, clock)
    if result.plan is None:
        return result
    steps = tuple(expand(result.plan, steps_of))
    return result._replace(plan=steps, cost=result.cost if task.uses_costs else len(steps))


def expand(plan: Sequence[str], steps_of: dict[str, tuple[str, ...]]) -> list[str]:
    """The plan with every macro operator replaced by its steps."""
    return [step for name in plan for step in steps_of.get(name, (name,))]


def _instances(
    table: TriangleTable,
    by_name: dict[str, list[tuple[tuple[str, ...], GroundOperator]]],
    effort: int,
) -> Iterator[list[GroundOperator]]:
    """Ground operators for the table's steps, one binding of its parameters for all,
    with its Distinct constraints kept, and no step needing what an earlier one deleted;
    at most ``effort`` candidate steps are tried (long MACROPs over many objects have
    more partial instances than any search could use)."""
    budget = [effort]

    def extend(index: int, binding: dict[Param, Term], chosen: list[GroundOperator],
               lost: frozenset[int]) -> Iterator[list[GroundOperator]]:
        if index == table.size:
            if all(d.holds(binding) for d in table.distinct):
                yield list(chosen)
            return
        step = table.steps[index]
        for args, op in by_name.get(step.schema.name.lower(), ()):
            budget[0] -= 1
            if budget[0] < 0:
                return
            bound = _match(step.arguments, args, binding)
            if bound is None or lost.intersection(op.pre):
                continue
            chosen.append(op)
            yield from extend(index + 1, bound, chosen,
                              (lost | frozenset(op.delete)) - frozenset(op.add))
            chosen.pop()

    yield from extend(0, {}, [], frozenset())


def _match(pattern: Sequence[Term], values: tuple[str, ...], binding: dict) -> dict | None:
    if len(pattern) != len(values):
        return None
    bound = dict(binding)
    for term, value in zip(pattern, values):
        if type(term) is Param:
            if bound.setdefault(term, value) != value:
                return None
        elif type(term) is not str or term.lower() != value:
            return None
    return bound


def _compose(steps: Sequence[GroundOperator]) -> GroundOperator | None:
    """One operator doing ``steps`` in turn, or ``None`` when a step needs a fact an
    earlier step deleted (no state lets the sequence apply)."""
    pre: set[int] = set()
    add: set[int] = set()
    delete: set[int] = set()
    for op in steps:
        needed = set(op.pre)
        if needed & (delete - add):
            return None
        pre |= needed - add
        add = (add - set(op.delete)) | set(op.add)
        delete = (delete | set(op.delete)) - set(op.add)
    return GroundOperator(
        name="macro",
        pre=tuple(sorted(pre)),
        add=tuple(sorted(add)),
        delete=tuple(sorted(delete)),
        cost=sum(op.cost for op in steps),
    )
