"""Learning MACROPs from a sequence of problems (``strips learn``): solve each with the
library learned so far, then learn from its plan with the configured macro learner
(:mod:`strips_framework.macrops.learning`). It drives the planner facade, so it sits
beside it, above the MACROP machinery it uses."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from strips_framework.macrops.learning import MacroLearner
from strips_framework.macrops.macrop import Library
from strips_framework.macrops.table import Step
from strips_framework.records import Record
from strips_framework.worldmodel.problem import Problem

if TYPE_CHECKING:
    from strips_framework.planner import Planner
    from strips_framework.result import Result


class Lesson(Record):
    """One problem of a learning sequence: how it was solved and what was learned."""

    problem: str
    status: str
    nodes: int
    seconds: float
    plan_length: int | None
    macrops_used: int
    note: str

    __slots__ = ("problem", "status", "nodes", "seconds", "plan_length", "macrops_used", "note")

    def __init__(
        self,
        problem: str,
        status: str,
        nodes: int,
        seconds: float,
        plan_length: int | None,
        macrops_used: int,
        note: str,
    ) -> None:
        self.problem = problem
        self.status = status
        self.nodes = nodes
        self.seconds = seconds
        self.plan_length = plan_length
        self.macrops_used = macrops_used
        self.note = note


def solve_with(
    planner: Planner, path: Path, library: Library, domain: Path | None = None
) -> tuple[Problem, Result, list[Step] | None]:
    """Solve one problem with the library (a forward strategy gets it as macro
    operators); the problem as a first-order one, the result and the plan's steps."""
    from strips_framework.macrops.forward import solve_with_macros
    from strips_framework.macrops.ground_table import parse_plan, solution_steps
    from strips_framework.pddl.files import is_pddl

    macrops = library if library.macrops else None
    if not is_pddl(path, domain):
        problem = planner.load(path)
        result = planner.solve(problem, library=macrops)
        return problem, result, solution_steps(result)
    from strips_framework.pddl import to_problem

    pddl = planner.load_pddl(path, domain)
    problem = to_problem(pddl)
    if not planner.searches_ground_tasks:
        result = planner.solve(problem, library=macrops)
        return problem, result, solution_steps(result)
    from strips_framework.grounding import ground

    task = ground(pddl)
    found = planner.solve_task(task) if macrops is None else solve_with_macros(planner.solve_task, task, macrops)
    return problem, found, None if found.plan is None else parse_plan(problem, found.plan)


def _figures(result: Result) -> tuple[int, float, int]:
    """Nodes (forward search: expansions), seconds, and MACROPs on the solution path."""
    from strips_framework.forward.result import ForwardStatistics
    from strips_framework.means_ends.result import WorldModelStatistics

    statistics = result.statistics
    if isinstance(statistics, ForwardStatistics):
        return statistics.expanded, statistics.search_seconds, 0
    assert isinstance(statistics, WorldModelStatistics) and result.tree is not None
    used = sum(1 for node in result.tree.solution_path()
               if node.applied is not None and len(node.applied.steps()) > 1)
    return statistics.nodes, statistics.seconds, used


def learn_sequence(
    planner: Planner,
    problems: Sequence[tuple[Path | None, Path]],
    library: Library,
    learner: MacroLearner,
) -> tuple[Library, list[Lesson]]:
    """Solve ``(domain, problem)`` pairs in turn, each with the MACROPs learned so far, and
    learn from every plan found."""
    lessons = []
    for domain, path in problems:
        problem, result, steps = solve_with(planner, path, library, domain)
        nodes, seconds, used = _figures(result)
        if steps is None:
            note = "not solved: nothing learned"
        else:
            library, note = learner.learn(problem, steps, library)
        lessons.append(Lesson(path.name, result.status, nodes, seconds,
                              None if steps is None else len(steps), used, note))
    return library, lessons
