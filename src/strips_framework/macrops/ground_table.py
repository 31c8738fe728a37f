"""The triangle table of one valid ground plan, with the proofs it was read from.

Every step's precondition (and, in row n+1, the goal) is proved in the state before it on
the simulator's semantics (:mod:`strips_framework.macrops.proofs`); the facts a proof
rests on are entered in the column of the step that last added them (column 0 when they
held from the start). The proofs are kept: generalization replays them.
"""

from __future__ import annotations

from collections.abc import Sequence

from strips_framework.logic.terms import Atom, Param, Term
from strips_framework.macrops.proofs import Justifier, MacroError, Witness
from strips_framework.macrops.table import Cell, Step, TriangleTable
from strips_framework.records import Record
from strips_framework.result import Result
from strips_framework.worldmodel.operators import OperatorInstance
from strips_framework.worldmodel.problem import Problem
from strips_framework.worldmodel.simulate import Simulator, State


class GroundTable(Record):
    """A plan's :class:`TriangleTable` and, per row 1 .. n+1, the proof of its condition
    and the column each of the proof's facts came from."""

    problem: Problem
    table: TriangleTable
    proofs: tuple[Witness, ...]
    origins: tuple[dict[Atom, int], ...]

    __slots__ = ("problem", "table", "proofs", "origins")

    def __init__(
        self,
        problem: Problem,
        table: TriangleTable,
        proofs: tuple[Witness, ...],
        origins: tuple[dict[Atom, int], ...],
    ) -> None:
        self.problem = problem
        self.table = table
        self.proofs = proofs
        self.origins = origins


def parse_plan(problem: Problem, plan: Sequence[str]) -> list[Step]:
    """The steps of a plan written ``name(arg, ...)`` or ``(name arg ...)``."""
    simulator = Simulator(problem)
    steps = []
    for number, text in enumerate(plan, start=1):
        parsed = simulator.parse_step(text)
        if isinstance(parsed, str):
            raise MacroError(f"plan step {number}, {text.strip()!r}: {parsed}")
        schema, binding = parsed
        steps.append(Step(schema, tuple(binding[p] for p in schema.parameters)))
    return steps


def steps_of(plan: Sequence[OperatorInstance]) -> list[Step]:
    """The steps of a plan the means-ends search found."""
    return [Step(op.schema, op.arguments()) for op in plan]


def solution_steps(result: Result) -> list[Step] | None:
    """The steps of a world-model search's plan, from the operator instances on its
    tree's solution path; ``None`` when it found none."""
    if result.tree is None or result.tree.solution is None:
        return None
    return steps_of(result.tree.solution.plan)


def ground_table(problem: Problem, steps: Sequence[Step]) -> GroundTable:
    """The triangle table of ``steps`` from the problem's initial state; a
    :class:`MacroError` names the first step whose precondition fails (or the goal)."""
    simulator = Simulator(problem)
    state: State = frozenset(problem.facts)
    origin: dict[Atom, int] = {atom: 0 for atom in state}
    marked: dict[Cell, tuple[Atom, ...]] = {}
    unmarked: dict[Cell, tuple[Atom, ...]] = {}
    proofs: list[Witness] = []
    origins: list[dict[Atom, int]] = []
    n = len(steps)
    for row in range(1, n + 2):
        justifier = Justifier(simulator, state)
        if row <= n:
            step = steps[row - 1]
            condition, env = step.schema.precondition, step.binding()
            what = f"step {row}, {step}: its precondition does not hold"
        else:
            condition, env = problem.goal, {}
            what = "the goal does not hold at the end of the plan"
        witness = justifier.witness(condition, env)
        if witness is None:
            raise MacroError(f"cannot build a triangle table: {what}")
        used = {leaf.atom: origin[leaf.atom] for need in witness.needed
                for leaf in need.proof.leaves()}
        proofs.append(witness)
        origins.append(used)
        for atom, col in used.items():
            marked[(row, col)] = (*marked.get((row, col), ()), atom)
        for col in range(1, row):
            rest = tuple(
                a for a in dict.fromkeys(steps[col - 1].adds())
                if origin.get(a) == col and a not in used
            )
            if rest:
                unmarked[(row, col)] = rest
        if row <= n:
            step = steps[row - 1]
            binding: dict[Param, Term] = step.binding()
            after = simulator.apply(step.schema, binding, state)
            for atom in state - after:
                del origin[atom]
            for atom in step.adds():
                origin[atom] = row
            state = after
    return GroundTable(problem, TriangleTable(steps, marked, unmarked), tuple(proofs),
                       tuple(origins))
