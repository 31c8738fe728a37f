"""Triangle tables (Fikes, Hart & Nilsson 1972): which clauses each step of a plan relies
on, and which step made each of them true.

For a plan op_1 .. op_n the table has rows 1 .. n+1 and columns 0 .. n. Row r lists what
op_r (row n+1: the goal) needs, split by column: column 0 the clauses of the initial model,
column c the clauses op_c added. Those are the *marked* (supporting) clauses. A cell also
shows, unmarked, what op_c added that still holds at row r but nobody there uses. *Kernel i*
is the marked clauses of rows i .. n+1 in columns 0 .. i-1: when they hold, op_i .. op_n
apply in turn and reach the goal row, whatever else the world is like. That is what PLANEX
monitors with, and what makes a table usable "in part" by a later search.

The same class holds a ground table (of one plan) and a generalized one (a MACROP's, over
parameters, with the :class:`Distinct` constraints that keep its steps from deleting what
later steps need).
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Sequence

from strips_framework.logic.terms import Atom, Param, Term, term_to_str
from strips_framework.logic.unify import substitute
from strips_framework.records import Record
from strips_framework.worldmodel.problem import OperatorSchema


class Step(Record):
    """One operator of a table: the schema and its arguments (constants or parameters)."""

    schema: OperatorSchema
    arguments: tuple[Term, ...]

    __slots__ = ("schema", "arguments")

    def __init__(self, schema: OperatorSchema, arguments: Iterable[Term]) -> None:
        self.schema = schema
        self.arguments = tuple(arguments)

    def binding(self) -> dict[Param, Term]:
        return dict(zip(self.schema.parameters, self.arguments))

    def substituted(self, subst: dict) -> Step:
        return Step(self.schema, tuple(substitute(a, subst) for a in self.arguments))

    def adds(self) -> tuple[Atom, ...]:
        binding = self.binding()
        return tuple(substitute(a, binding) for a in self.schema.add_list)

    def deletes(self) -> tuple[Atom, ...]:
        """Delete-list patterns; ``$`` stays a wildcard."""
        binding = self.binding()
        return tuple(substitute(a, binding) for a in self.schema.delete_list)

    def __str__(self) -> str:
        return f"{self.schema.name}({', '.join(map(term_to_str, self.arguments))})"


class Distinct(Record):
    """``left`` and ``right`` must differ, or step ``step`` deletes a clause row ``row``
    needs (two parameters of a generalized plan bound to one object)."""

    left: Term
    right: Term
    row: int
    step: int

    __slots__ = ("left", "right", "row", "step")

    def __init__(self, left: Term, right: Term, row: int, step: int) -> None:
        self.left = left
        self.right = right
        self.row = row
        self.step = step

    def holds(self, binding: dict) -> bool:
        return substitute(self.left, binding) != substitute(self.right, binding)


Cell = tuple[int, int]


class TriangleTable(Record):
    """``marked[(r, c)]`` are the supporting clauses of cell (r, c); ``unmarked[(r, c)]``
    the other clauses op_c added that still hold at row r (shown, never required)."""

    steps: tuple[Step, ...]
    marked: dict[Cell, tuple[Atom, ...]]
    unmarked: dict[Cell, tuple[Atom, ...]]
    distinct: tuple[Distinct, ...]

    __slots__ = ("steps", "marked", "unmarked", "distinct")

    def __init__(
        self,
        steps: Iterable[Step],
        marked: dict[Cell, tuple[Atom, ...]] | None = None,
        unmarked: dict[Cell, tuple[Atom, ...]] | None = None,
        distinct: Iterable[Distinct] = (),
    ) -> None:
        self.steps = tuple(steps)
        self.marked = {} if marked is None else marked
        self.unmarked = {} if unmarked is None else unmarked
        self.distinct = tuple(distinct)

    @property
    def size(self) -> int:
        """n, the number of steps (rows 1 .. n+1, columns 0 .. n)."""
        return len(self.steps)

    def _repr_svg_(self) -> str:
        """The table's picture in a notebook (:func:`~strips_framework.macrops.render.svg_table`)."""
        from strips_framework.macrops.render import svg_table

        return svg_table(self)

    def kernel(self, i: int) -> tuple[Atom, ...]:
        """The marked clauses of kernel ``i`` (1 <= i <= n+1), without repetitions."""
        found = dict.fromkeys(
            atom
            for (row, col), atoms in sorted(self.marked.items())
            if row >= i and col < i
            for atom in atoms
        )
        return tuple(found)

    def kernel_distinct(self, i: int) -> tuple[Distinct, ...]:
        """The constraints that matter once op_i is next: a later step must not delete
        what a later row needs."""
        return tuple(d for d in self.distinct if d.step >= i)

    def goal_row(self) -> tuple[Atom, ...]:
        """What the plan achieves and was made for: the marked clauses of row n+1."""
        return self.kernel(self.size + 1)

    def row_atoms(self, row: int) -> Iterator[tuple[int, Atom]]:
        for (r, col), atoms in sorted(self.marked.items()):
            if r == row:
                for atom in atoms:
                    yield col, atom

    def supporters(self, row: int) -> set[int]:
        """The steps that row ``row`` depends on, directly or through other steps."""
        found: set[int] = set()
        todo = [row]
        while todo:
            r = todo.pop()
            for col, _ in self.row_atoms(r):
                if col and col not in found:
                    found.add(col)
                    todo.append(col)
        return found

    def parameters(self) -> tuple[Param, ...]:
        """The table's parameters, in order of first appearance (steps, cells, then the
        constraints)."""
        seen: dict[Param, None] = {}
        for step in self.steps:
            for arg in step.arguments:
                _collect(arg, seen)
        for key in sorted(self.marked):
            for atom in self.marked[key]:
                _collect(atom, seen)
        for d in self.distinct:
            _collect(d.left, seen)
            _collect(d.right, seen)
        return tuple(seen)

    def substituted(self, subst: dict) -> TriangleTable:
        def cells(table: dict[Cell, tuple[Atom, ...]]) -> dict[Cell, tuple[Atom, ...]]:
            return {
                key: tuple(dict.fromkeys(substitute(a, subst) for a in atoms))
                for key, atoms in table.items()
            }

        return TriangleTable(
            [s.substituted(subst) for s in self.steps],
            cells(self.marked),
            cells(self.unmarked),
            [
                Distinct(substitute(d.left, subst), substitute(d.right, subst), d.row, d.step)
                for d in self.distinct
            ],
        )

    def edited(self, last: int) -> TriangleTable:
        """The part of the plan that leads to step ``last``: that step and the steps that
        support it (following marked clauses back), renumbered. Its goal row holds what
        step ``last`` adds and what the kept steps gave the old goal row."""
        kept = sorted(self.supporters(last) | {last})
        number = {old: new for new, old in enumerate(kept, start=1)}
        number[0] = 0
        rows = {old: new for new, old in enumerate(kept, start=1)}
        goal = len(kept) + 1
        rows[self.size + 1] = goal
        marked: dict[Cell, tuple[Atom, ...]] = {}
        for (row, col), atoms in self.marked.items():
            if row in rows and col in number and not (row == self.size + 1 and col == 0):
                marked[(rows[row], number[col])] = atoms
        final = self.steps[last - 1].adds()
        key = (goal, number[last])
        marked[key] = tuple(dict.fromkeys((*marked.get(key, ()), *final)))
        distinct = [
            Distinct(d.left, d.right, rows[d.row], number[d.step])
            for d in self.distinct
            if d.row in rows and d.step in number
        ]
        return TriangleTable([self.steps[i - 1] for i in kept], marked, {}, distinct)


def _collect(term: Term, seen: dict[Param, None]) -> None:
    if type(term) is Param:
        seen.setdefault(term)
    elif type(term) is tuple:
        for arg in term[1:]:
            _collect(arg, seen)


def cells_by_row(table: TriangleTable) -> Sequence[Sequence[tuple[tuple[Atom, ...], tuple[Atom, ...]]]]:
    """``[row][col] -> (marked, unmarked)`` for rows 1 .. n+1 and columns 0 .. row-1, the
    triangle as the paper draws it (used by the renderers)."""
    n = table.size
    return [
        [
            (table.marked.get((row, col), ()), table.unmarked.get((row, col), ()))
            for col in range(row)
        ]
        for row in range(1, n + 2)
    ]
