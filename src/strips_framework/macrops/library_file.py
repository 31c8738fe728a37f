"""The MACROP library file: a readable text file, an extension of the native format.

    # comments as in .strips files
    world robot-world
      operator goto2(m) 5f1c0e2a9b7d       # a fingerprint of each operator a MACROP uses
      ...
    macrop M1
      learned-from light.strips
      parameters p1 p2 p3 p4
      step 1 goto2(p1)
      step 2 pushto(p1, p2)
      ...
      row 1 col 0 ONFLOOR, INROOM(ROBOT, p3), INROOM(p1, p3)     # marked clauses of a cell
      row 3 col 2 ON(ROBOT, p1)
      unmarked row 4 col 2 NEXTTO(p2, p1)                          # shown in pictures only
      distinct p3 p1 row 5 step 4      # p3 != p1, or step 4 deletes what row 5 needs
      example p1=BOX1 p2=LIGHTSWITCH1 p3=ROOM1 p4=ROOM1
    end

Atoms and terms are written as in ``.strips`` files; names listed after ``parameters``
are parameters, any other name a constant. A library is read against a problem: every
operator a MACROP uses must be one of the problem's, with the same definition (name,
parameters, precondition, add and delete lists) as when it was learned, so a library
learned on one world is refused on another instead of being misused. Every mistake is an
:class:`~strips_framework.errors.InputError` naming the file and line.
"""

from __future__ import annotations

import hashlib
from pathlib import Path

from strips_framework.errors import InputError
from strips_framework.logic.formulas import formula_to_str
from strips_framework.logic.parser import WffParser, tokenize
from strips_framework.logic.terms import Atom, Param, Term, atom_to_str, term_to_str
from strips_framework.macrops.macrop import Library, Macrop
from strips_framework.macrops.table import Cell, Distinct, Step, TriangleTable
from strips_framework.user_files import write_atomically
from strips_framework.worldmodel.problem import OperatorSchema, Problem

HEADER = "# MACROP library (Fikes, Hart & Nilsson 1972): written by 'strips learn'"


def fingerprint(schema: OperatorSchema) -> str:
    """A short hash of an operator's definition: equal exactly when the definitions are."""
    text = "|".join([
        schema.signature(),
        formula_to_str(schema.precondition),
        ", ".join(map(atom_to_str, schema.add_list)),
        ", ".join(map(atom_to_str, schema.delete_list)),
    ])
    return hashlib.sha256(text.encode()).hexdigest()[:12]


def library_text(library: Library, world: str) -> str:
    """The library file for ``library``; ``world`` names the problem family it is for."""
    operators: dict[str, OperatorSchema] = {}
    for macrop in library.macrops:
        for step in macrop.table.steps:
            operators.setdefault(step.schema.name, step.schema)
    lines = [HEADER, f"world {world}"]
    lines += [f"  operator {s.signature()} {fingerprint(s)}" for s in operators.values()]
    for macrop in library.macrops:
        lines += ["", *_macrop_lines(macrop)]
    return "\n".join(lines) + "\n"


def _macrop_lines(macrop: Macrop) -> list[str]:
    table = macrop.table
    lines = [f"macrop {macrop.name}"]
    if macrop.learned_from:
        lines.append(f"  learned-from {macrop.learned_from}")
    lines.append("  parameters " + " ".join(p.name for p in table.parameters()))
    lines += [f"  step {i} {step}" for i, step in enumerate(table.steps, start=1)]
    for (row, col), atoms in sorted(table.marked.items()):
        lines.append(f"  row {row} col {col} {', '.join(map(atom_to_str, atoms))}")
    for (row, col), atoms in sorted(table.unmarked.items()):
        lines.append(f"  unmarked row {row} col {col} {', '.join(map(atom_to_str, atoms))}")
    for d in table.distinct:
        lines.append(f"  distinct {term_to_str(d.left)} {term_to_str(d.right)} "
                     f"row {d.row} step {d.step}")
    if macrop.example:
        lines.append("  example " + " ".join(
            f"{p.name}={term_to_str(v)}" for p, v in macrop.example.items()))
    lines.append("end")
    return lines


def write_library(path: Path, library: Library, world: str) -> None:
    write_atomically(path, library_text(library, world), "the library")


def read_library(path: Path, problem: Problem) -> Library:
    """The library in ``path``, its steps bound to ``problem``'s operators."""
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as error:
        raise InputError(str(path), None, None, f"cannot read library: {error.strerror}") from None
    return _Reader(str(path), problem).read(text)


#: PDDL types become predicates ``type:NAME`` (see :mod:`strips_framework.pddl.translation`);
#: the native syntax has no ``:`` in names, so it is read as this (no name the native
#: syntax or PDDL allows contains it).
_COLON = "__colon__"
_ENTRIES = ("learned-from", "parameters", "step", "row", "unmarked", "distinct", "example")


class _Draft:
    """A MACROP being read from a library file: mutable, filled in entry by entry."""

    __slots__ = ("name", "line", "learned_from", "parameters", "steps", "marked", "unmarked",
                 "distinct", "example")  # fmt: skip

    def __init__(
        self,
        name: str,
        line: int,
        learned_from: str = "",
        parameters: tuple[str, ...] | None = None,
        steps: list[Step] | None = None,
        marked: dict[Cell, tuple[Atom, ...]] | None = None,
        unmarked: dict[Cell, tuple[Atom, ...]] | None = None,
        distinct: list[Distinct] | None = None,
        example: dict[Param, Term] | None = None,
    ) -> None:
        self.name: str = name
        self.line: int = line
        self.learned_from: str = learned_from
        self.parameters: tuple[str, ...] | None = parameters
        self.steps: list[Step] = [] if steps is None else steps
        self.marked: dict[Cell, tuple[Atom, ...]] = {} if marked is None else marked
        self.unmarked: dict[Cell, tuple[Atom, ...]] = {} if unmarked is None else unmarked
        self.distinct: list[Distinct] = [] if distinct is None else distinct
        self.example: dict[Param, Term] = {} if example is None else example


class _Reader:
    def __init__(self, path: str, problem: Problem) -> None:
        self.path, self.problem = path, problem
        self.operators = {schema.name: schema for schema in problem.operators}
        self.world: dict[str, tuple[str, int]] = {}  # operator name -> (fingerprint, line)

    def fail(self, line: int, message: str) -> InputError:
        return InputError(self.path, line, None, message)

    def read(self, text: str) -> Library:
        macrops: list[Macrop] = []
        draft: _Draft | None = None
        seen_world = False
        for number, raw in enumerate(text.splitlines(), start=1):
            line = raw.split("#", 1)[0].strip()
            if not line:
                continue
            word, _, rest = line.partition(" ")
            rest = rest.strip()
            if draft is None:
                if word == "world":
                    seen_world = True
                elif word == "operator" and seen_world:
                    self._operator(number, rest)
                elif word == "macrop":
                    if not rest.isidentifier() and not rest.replace("-", "_").isidentifier():
                        raise self.fail(number, f"expected a MACROP name after 'macrop', got {rest!r}")
                    draft = _Draft(rest, number)
                else:
                    raise self.fail(number, f"expected 'world', 'operator' or 'macrop', got {word!r}")
            elif word == "end":
                macrops.append(self._finish(draft, number))
                draft = None
            else:
                self._entry(draft, number, word, rest)
        if draft is not None:
            raise self.fail(draft.line, f"MACROP {draft.name} has no 'end'")
        return Library(macrops)

    def _operator(self, number: int, rest: str) -> None:
        signature, _, digest = rest.rpartition(" ")
        name = signature.split("(", 1)[0].strip()
        if not name or not digest:
            raise self.fail(number, "expected 'operator NAME(PARAMS) FINGERPRINT'")
        schema = self.operators.get(name)
        if schema is None:
            raise self.fail(number, f"the library was learned with an operator {signature} "
                            f"that {self.problem.source} does not have")
        if fingerprint(schema) != digest or schema.signature() != signature.strip():
            raise self.fail(number, f"operator {signature} differs from {schema.signature()} "
                            f"in {self.problem.source}: the library was learned on another "
                            "world and cannot be used here")
        self.world[name] = (digest, number)

    def _entry(self, draft: _Draft, number: int, word: str, rest: str) -> None:
        if word not in _ENTRIES:
            raise self.fail(number, f"expected {', '.join(repr(w) for w in _ENTRIES)} or 'end' "
                            f"in MACROP {draft.name}, got {word!r}")
        if word == "learned-from":
            draft.learned_from = rest
        elif word == "parameters":
            draft.parameters = tuple(rest.split())
        elif draft.parameters is None:
            raise self.fail(number, f"expected 'parameters' before '{word}' in MACROP {draft.name}")
        elif word == "step":
            self._step(draft, number, rest)
        elif word == "row":
            self._cell(draft, number, rest, draft.marked)
        elif word == "unmarked":
            head, _, tail = rest.partition(" ")
            if head != "row":
                raise self.fail(number, "expected 'unmarked row R col C ATOMS'")
            self._cell(draft, number, tail, draft.unmarked)
        elif word == "distinct":
            self._distinct(draft, number, rest)
        else:
            for pair in rest.split():
                name, _, value = pair.partition("=")
                if name not in draft.parameters or not value:
                    raise self.fail(number, f"expected PARAMETER=CONSTANT, got {pair!r}")
                draft.example[Param(name)] = value

    def _parser(self, draft: _Draft, number: int, text: str) -> WffParser:
        return WffParser(tokenize(text, self.path, number, 1), self.path,
                         params=draft.parameters or (), constants=self.problem.constants,
                         hint="a library names only the parameters it declares and the "
                         "constants of the problem")

    def _step(self, draft: _Draft, number: int, rest: str) -> None:
        index, _, text = rest.partition(" ")
        if index != str(len(draft.steps) + 1):
            raise self.fail(number, f"expected step {len(draft.steps) + 1}, got 'step {index}'")
        bare = text.strip().removesuffix("()")
        if bare.isidentifier():  # an operator without parameters
            name, args = bare, ()
        else:
            parser = self._parser(draft, number, text)
            term = parser.term()
            parser.end()
            if type(term) is not tuple:
                raise self.fail(number, f"expected 'step {index} OPERATOR(ARGS)', got {text!r}")
            name, args = term[0], term[1:]
        schema = self.operators.get(name)
        if schema is None or name not in self.world:
            raise self.fail(number, f"step {index} uses operator {name!r}, which the library's "
                            "'world' block does not list")
        if len(args) != len(schema.parameters):
            raise self.fail(number, f"{schema.signature()} takes {len(schema.parameters)} "
                            f"argument(s), got {len(args)}")
        draft.steps.append(Step(schema, args))

    def _cell(self, draft: _Draft, number: int, rest: str, cells: dict) -> None:
        words = rest.split(None, 3)
        if len(words) < 4 or words[1] != "col" or not (words[0].isdigit() and words[2].isdigit()):
            raise self.fail(number, "expected 'row R col C ATOM, ATOM, ...'")
        row, col = int(words[0]), int(words[2])
        if not 0 <= col < row:
            raise self.fail(number, f"cell (row {row}, col {col}) is not in the triangle: "
                            "the column must be below the row")
        parser = self._parser(draft, number, words[3].replace(":", _COLON))
        atoms = tuple(
            (atom[0].replace(_COLON, ":"), *atom[1:]) for atom, _ in parser.atom_list()
        )
        parser.end()
        cells[(row, col)] = atoms

    def _distinct(self, draft: _Draft, number: int, rest: str) -> None:
        words = rest.split()
        if len(words) != 6 or words[2] != "row" or words[4] != "step" \
                or not (words[3].isdigit() and words[5].isdigit()):
            raise self.fail(number, "expected 'distinct TERM TERM row R step K'")
        params = draft.parameters or ()
        left, right = (Param(w) if w in params else w for w in words[:2])
        draft.distinct.append(Distinct(left, right, int(words[3]), int(words[5])))

    def _finish(self, draft: _Draft, number: int) -> Macrop:
        if not draft.steps:
            raise self.fail(number, f"MACROP {draft.name} has no steps")
        n = len(draft.steps)
        for row, col in (*draft.marked, *draft.unmarked):
            if row > n + 1:
                raise self.fail(number, f"MACROP {draft.name} has {n} steps, so rows go up to "
                                f"{n + 1}, not {row}")
        table = TriangleTable(draft.steps, draft.marked, draft.unmarked, draft.distinct)
        return Macrop(draft.name, table, draft.learned_from, draft.example)

