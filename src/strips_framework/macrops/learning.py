"""Learning MACROPs from solved problems, and the builtin macro learner.

A macro learner turns a solved problem and its plan into a library with (perhaps) one
more MACROP; it is a plugin kind (``[learner]`` in the config, registered through
``strips_register_macro_learners``), so other generalization methods can be swapped in like
provers and evaluators. :func:`learn_sequence` is ``strips learn``: it solves the problems
in turn, each with the library learned so far, and learns from each plan.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, ClassVar, Protocol

from attrs import field, frozen, validators

from strips_framework.macrops.elimination import eliminate
from strips_framework.macrops.generalize import generalize
from strips_framework.macrops.ground_table import ground_table
from strips_framework.macrops.macrop import Library, Macrop
from strips_framework.macrops.table import Step
from strips_framework.worldmodel.problem import Problem

if TYPE_CHECKING:
    from strips_framework.planner import Planner
    from strips_framework.result import Result


class MacroLearner(Protocol):
    name: ClassVar[str]

    def learn(self, problem: Problem, plan: Sequence[Step], library: Library) -> tuple[Library, str]:
        """The library after learning from ``plan`` (a valid plan for ``problem``), and a
        line saying what was learned."""
        ...


@frozen
class TriangleTableLearner:
    """The 1972 paper's learner: the plan's triangle table, generalized, as one MACROP.

    ``eliminate`` first drops the steps the plan can do without (a MACROP inherits every
    detour of its plan); plans shorter than ``min_steps`` teach nothing a single operator
    does not; ``max_macrops`` caps the library (the oldest MACROP goes first), since every
    MACROP costs relevance tests at every node of later searches.
    """

    name: ClassVar[str] = "triangle-table"
    capabilities: ClassVar[frozenset[str]] = frozenset()
    eliminate: bool = field(default=True, validator=validators.instance_of(bool))
    min_steps: int = field(default=2, validator=[validators.instance_of(int), validators.ge(1)])
    max_macrops: int = field(default=50, validator=[validators.instance_of(int), validators.ge(1)])

    def learn(self, problem: Problem, plan: Sequence[Step], library: Library) -> tuple[Library, str]:
        steps = eliminate(problem, plan) if self.eliminate else list(plan)
        if len(steps) < self.min_steps:
            return library, f"nothing learned: {len(steps)} step(s) after elimination"
        found = generalize(ground_table(problem, steps))
        name = library.fresh_name()
        grown, note = library.added(Macrop(name, found.table, Path(problem.source).name,
                                           found.example))
        if len(grown.macrops) > self.max_macrops:
            oldest = grown.macrops[0]
            grown = Library(grown.macrops[1:])
            note += f"; {oldest.name} dropped (max_macrops = {self.max_macrops})"
        return grown, note


@frozen
class Lesson:
    """One problem of a learning sequence: how it was solved and what was learned."""

    problem: str
    status: str
    nodes: int
    seconds: float
    plan_length: int | None
    macrops_used: int
    note: str


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
    found = planner.solve_task(task) if macrops is None else solve_with_macros(planner, task, macrops)
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
