"""The native problem format (``.strips``): a problem written the way the paper's Table 1
reads. The reference is ``docs/problem-format.md``; in short::

    problem three-boxes                   # a keyword in column 1 starts a block
    constants a b c d BOX1 BOX2 BOX3
    primitive ATR/1 AT/2
    facts                                 # indented lines below are its entries
      ATR(a)
    operator goto(m, n)
      pre    ATR(m)
      delete ATR(m)
      add    ATR(n)
    goal exists x: AT(BOX1, x) & AT(BOX2, x) & AT(BOX3, x)

Reading happens in three steps, so declarations may come anywhere in the file: the text
is cut into blocks and entries by indentation (``include`` splices in another file's
blocks); the declarations are read; then everything else is parsed and checked. Every
error is an :class:`~strips_framework.errors.InputError` naming ``file:line:column``.
"""

from __future__ import annotations

import re
from collections.abc import Collection
from pathlib import Path
from typing import ClassVar

from strips_framework.errors import InputError
from strips_framework.logic.formulas import Formula, Truth, params_in
from strips_framework.logic.parser import Arities, Token, WffParser, tokenize
from strips_framework.logic.terms import Atom, Param, atom_to_str, params_of
from strips_framework.options import Configurable
from strips_framework.records import Record
from strips_framework.user_files import read_text
from strips_framework.worldmodel.problem import DerivedFact, OperatorSchema, Problem, SourceSpan

#: Blocks whose indented lines are separate entries; the others continue their first line.
SECTIONS = ("facts", "axioms", "derived", "operator")
KEYWORDS = ("problem", "constants", "primitive", "unique-names", "include", *SECTIONS, "goal")
OPERATOR_PARTS = ("pre", "delete", "add")

_NAME = r"[A-Za-z0-9_]+(?:-[A-Za-z0-9_]+)*"
_KEYWORD = re.compile(_NAME)
_ATOM = rf"({_NAME})(?:\(\s*({_NAME}(?:\s*,\s*{_NAME})*)\s*\))?"
_PLAIN_ATOM = re.compile(_ATOM)
_PLAIN_NAME = re.compile(_NAME)
_PLAIN_CONSTANTS = re.compile(rf"constants(?:[ \t\n,]+{_NAME})*[ \t\n,]*")
_PLAIN_FACTS = re.compile(rf"{_ATOM}(?:\s*,\s*{_ATOM})*[ \t]*")
#: Names the wff parser reads as keywords, never as predicates or constants.
_WORDS = frozenset({"not", "forall", "exists", "true", "false"})

_GROUND_HINT = "facts must be ground; write quantified statements under 'axioms'"
_CLOSED_HINT = "a variable must be bound by 'forall' or 'exists'"


class Entry(Record):
    """A piece of a file: a first line and the lines that continue it, with its position
    (a slotted record: a large world has one per fact, and these are made fastest)."""

    path: str
    line: int
    column: int
    text: str

    __slots__ = ("path", "line", "column", "text")

    def __init__(self, path: str, line: int, column: int, text: str) -> None:
        self.path = path
        self.line = line
        self.column = column
        self.text = text

    def parser(
        self,
        params: tuple[str, ...] = (),
        constants: Collection[str] | None = None,
        arities: Arities | None = None,
        hint: str = "",
    ) -> WffParser:
        tokens = tokenize(self.text, self.path, self.line, self.column, "end of line")
        return WffParser(
            tokens, self.path, params=params, constants=constants, arities=arities, hint=hint
        )


class Block(Record):
    """A line that starts in column 1 (``header``) and the entries indented under it."""

    keyword: str
    header: Entry
    entries: tuple[Entry, ...]

    __slots__ = ("keyword", "header", "entries")

    def __init__(self, keyword: str, header: Entry, entries: tuple[Entry, ...]) -> None:
        self.keyword = keyword
        self.header = header
        self.entries = entries


def read_blocks(path: Path, shown: str, including: tuple[Path, ...] = ()) -> list[Block]:
    """The blocks of the file at ``path`` (called ``shown`` in messages), includes spliced."""
    blocks = []
    for block in _split(read_text(path), shown):
        if block.keyword != "include":
            blocks.append(block)
            continue
        parser = block.header.parser()
        parser.next()
        name = parser.expect("STRING", "a quoted file name")
        parser.end()
        target = path.parent / name.text[1:-1]
        try:
            cycle = target.resolve() in {p.resolve() for p in (*including, path)}
            readable = target.is_file()
        except (OSError, ValueError) as error:  # a name too long, a NUL byte in it
            raise parser.fail(name, f"cannot read the included file: {_reason(error)}") from None
        if cycle:
            raise parser.fail(name, f"including '{name.text[1:-1]}' here would make a cycle")
        if not readable:
            raise parser.fail(name, "cannot read the included file: No such file or directory")
        blocks += read_blocks(target, str(Path(shown).parent / name.text[1:-1]), (*including, path))
    return blocks


def _split(text: str, path: str) -> list[Block]:
    """Cut ``text`` into blocks by indentation; blank and comment-only lines don't count."""
    lines = text.split("\n")
    groups: list[list[tuple[int, int]]] = []  # per block: (line index, indentation)
    for index, raw in enumerate(lines):
        content = raw.lstrip(" \t")
        if not content.strip() or content.startswith("#"):
            continue
        indent = len(raw) - len(content)
        if indent == 0:
            groups.append([(index, 0)])
        elif not groups:
            message = "expected a keyword in column 1 but found an indented line"
            raise InputError(path, index + 1, indent + 1, message)
        else:
            groups[-1].append((index, indent))

    def entry(group: list[tuple[int, int]]) -> Entry:
        (first, indent), last = group[0], group[-1][0]
        text = "\n".join([lines[first][indent:], *lines[first + 1 : last + 1]])
        return Entry(path, first + 1, indent + 1, text)

    blocks = []
    for group in groups:
        line = lines[group[0][0]]
        word = _KEYWORD.match(line)
        keyword = word.group() if word else ""
        if keyword not in KEYWORDS:
            first = tokenize(line, path, group[0][0] + 1)[0]
            message = f"expected a keyword ({', '.join(KEYWORDS)}) but found '{first.text}'"
            raise InputError(path, first.line, first.column, message)
        if keyword not in SECTIONS:
            blocks.append(Block(keyword, entry(group), ()))
            continue
        entries: list[list[tuple[int, int]]] = []
        for item in group[1:]:
            if entries and item[1] > entries[-1][0][1]:
                entries[-1].append(item)  # deeper than the entry's first line: continues it
            else:
                entries.append([item])
        blocks.append(Block(keyword, entry(group[:1]), tuple(map(entry, entries))))
    return blocks


def _reason(error: Exception) -> str:
    return error.strerror if isinstance(error, OSError) and error.strerror else str(error)


class _Reader:
    """Reads the blocks of one problem into a :class:`Problem`, checking as it goes."""

    def __init__(self, source: str) -> None:
        self.source = source
        self.once: dict[str, str] = {}  # once-only keyword -> where it was given
        self.name = ""
        self.constants: dict[str, str] = {}  # name -> where declared, in order
        self.primitives: set[tuple[str, int]] = set()
        self.arities = Arities()
        self.unique_names = True
        self.facts: dict[Atom, None] = {}  # an ordered set
        self.axioms: list[Formula] = []
        self.derived: list[tuple[DerivedFact, list[tuple[Atom, Token]]]] = []
        self.operators: dict[str, OperatorSchema] = {}
        self.additions: list[tuple[Atom, Token, str, str]] = []  # atom, token, path, operator
        self.goal: Formula | None = None

    def read(self, blocks: list[Block]) -> Problem:
        declarations = {
            "problem": self._problem,
            "constants": self._constants,
            "primitive": self._primitive,
            "unique-names": self._unique_names,
        }
        for block in blocks:
            if block.keyword == "constants" and self._plain_constants(block.header):
                continue
            if block.keyword in declarations:
                declarations[block.keyword](block.header.parser())
        entries = {"facts": self._fact, "axioms": self._axiom, "derived": self._derived}
        for block in blocks:
            if block.keyword in entries:
                header = block.header.parser()
                header.next()
                header.end()
                for entry in block.entries:
                    entries[block.keyword](entry)
            elif block.keyword == "operator":
                self._operator(block)
            elif block.keyword == "goal":
                self._goal(block.header)
        self._check_derived()
        if "problem" not in self.once:
            raise self._missing("problem <name>")
        if self.goal is None:
            raise self._missing("goal <wff>")
        return Problem(
            name=self.name,
            constants=tuple(self.constants),
            primitive_predicates=frozenset(self.primitives),
            facts=tuple(self.facts),
            axioms=tuple(self.axioms),
            derived=tuple(fact for fact, _ in self.derived),
            operators=tuple(self.operators.values()),
            goal=self.goal,
            unique_names=self.unique_names,
            source=self.source,
        )

    def _once(self, parser: WffParser) -> None:
        """Consume the keyword of a line that may be given only once, and check that it is."""
        keyword = parser.next()
        if keyword.text in self.once:
            first = self.once[keyword.text]
            raise parser.fail(keyword, f"'{keyword.text}' is given twice (first at {first})")
        self.once[keyword.text] = f"{parser.path}:{keyword.line}"

    def _parser(self, entry: Entry, params: tuple[str, ...] = (), hint: str = "") -> WffParser:
        """A parser for ``entry`` that knows the declared constants and the arities."""
        return entry.parser(params, self.constants, self.arities, hint)

    def _missing(self, line: str) -> InputError:
        return InputError(self.source, 1, None, f"expected a '{line}' line but found none")

    def _is_primitive(self, atom: Atom) -> bool:
        return (atom[0], len(atom) - 1) in self.primitives

    # --- declarations ---------------------------------------------------------------

    def _problem(self, parser: WffParser) -> None:
        self._once(parser)
        self.name = parser.expect("NAME", "a problem name").text
        parser.end()

    def _constants(self, parser: WffParser) -> None:
        parser.next()
        while parser.peek.kind != "END":
            token = parser.expect("NAME", "a constant name")
            if token.text in self.constants:
                first = self.constants[token.text]
                message = f"constant '{token.text}' is declared twice (first at {first})"
                raise parser.fail(token, message)
            self.constants[token.text] = f"{parser.path}:{token.line}"
            parser.accept("COMMA")

    def _plain_constants(self, entry: Entry) -> bool:
        """Declare the names of a ``constants`` line without the tokenizer when it holds
        nothing but new names (as in a large world); ``False`` otherwise, leaving the
        line to :meth:`_constants` and its messages."""
        text = entry.text
        if not _PLAIN_CONSTANTS.fullmatch(text):
            return False
        found = list(_PLAIN_NAME.finditer(text))[1:]  # after the keyword
        names = [match.group() for match in found]
        if len(set(names)) != len(names) or any(n in self.constants or n in _WORDS for n in names):
            return False
        line, at = entry.line, 0
        for match, name in zip(found, names, strict=True):
            line += text.count("\n", at, match.start())
            at = match.start()
            self.constants[name] = f"{entry.path}:{line}"
        return True

    def _primitive(self, parser: WffParser) -> None:
        parser.next()
        while parser.peek.kind != "END":
            name = parser.expect("NAME", "a predicate name")
            parser.expect("SLASH", f"'/' and the arity after '{name.text}'")
            if parser.peek.kind != "NAME" or not re.fullmatch("[0-9]{1,6}", parser.peek.text):
                raise parser.error("an arity (a number below 1000000)")
            arity = int(parser.next().text)
            if name.text in self.arities.fixed:
                raise parser.fail(name, f"primitive predicate '{name.text}' is declared twice")
            self.arities.fix(name.text, arity, f"declared at {parser.path}:{name.line}")
            self.primitives.add((name.text, arity))
            parser.accept("COMMA")

    def _unique_names(self, parser: WffParser) -> None:
        self._once(parser)
        if parser.peek.text not in ("yes", "no"):
            raise parser.error("'yes' or 'no'")
        self.unique_names = parser.next().text == "yes"
        parser.end()

    # --- facts, axioms, derived facts, goal -----------------------------------------

    def _fact(self, entry: Entry) -> None:
        if self._plain_facts(entry):
            return
        parser = self._parser(entry, hint=_GROUND_HINT)
        for atom, _ in parser.atom_list():
            self.facts[atom] = None
        parser.end()

    def _plain_facts(self, entry: Entry) -> bool:
        """Read a one-line entry of plain ground atoms (``P(a, b), Q(c)``) without the
        tokenizer, as a large world's facts nearly all are: 5x faster. Anything else,
        or any mistake, returns ``False`` before a fact is kept, and the wff parser
        reads the entry and reports the mistake at its column."""
        text = entry.text
        if "\n" in text or not _PLAIN_FACTS.fullmatch(text):
            return False
        atoms = []
        constants, fixed = self.constants, self.arities.fixed
        first_use: dict[str, tuple[int, str]] = {}  # arities this line fixes
        for name, inside in _PLAIN_ATOM.findall(text):
            args = [arg.strip() for arg in inside.split(",")] if inside else []
            if name in _WORDS:
                return False
            for arg in args:
                if arg not in constants or arg in _WORDS:
                    return False
            known = fixed.get(name)
            if known is None:
                known = first_use[name] = first_use.get(name, (len(args), ""))
            if known[0] != len(args):
                return False
            atoms.append((name, *args))
        where = f"{entry.path}:{entry.line}"
        for name, (arity, _) in first_use.items():
            self.arities.fix(name, arity, f"as first used at {where}")
        for atom in atoms:
            self.facts[atom] = None
        return True

    def _axiom(self, entry: Entry) -> None:
        parser = self._parser(entry, hint=_CLOSED_HINT)
        self.axioms.append(parser.formula())
        parser.end()

    def _derived(self, entry: Entry) -> None:
        parser = self._parser(entry, hint="derived facts are ground")
        head = parser.peek
        atom = parser.atom()
        if self._is_primitive(atom):
            message = f"expected a non-primitive derived fact but {atom[0]} is primitive"
            raise parser.fail(head, message)
        parser.expect("LARROW", "'<-' and the primitive facts it rests on")
        supports = parser.atom_list()
        parser.end()
        fact = DerivedFact(atom, [s for s, _ in supports], SourceSpan(entry.path, entry.line))
        self.derived.append((fact, supports))

    def _goal(self, entry: Entry) -> None:
        parser = self._parser(entry, hint=_CLOSED_HINT)
        self._once(parser)
        self.goal = parser.formula()
        parser.end()

    def _check_derived(self) -> None:
        """Supports must be primitive facts of M0; derived predicates are never added."""
        derived_at: dict[str, SourceSpan] = {}
        for fact, supports in self.derived:
            assert fact.source is not None
            derived_at.setdefault(fact.atom[0], fact.source)
            for atom, token in supports:
                if not self._is_primitive(atom):
                    message = f"expected a primitive fact to rest on but {atom[0]} is not primitive"
                elif atom not in self.facts:
                    message = f"{atom_to_str(atom)} is not a fact of the initial model"
                else:
                    continue
                raise InputError(fact.source.path, token.line, token.column, message)
        for atom, token, path, operator in self.additions:
            if atom[0] in derived_at:
                message = (
                    f"operator {operator} adds {atom[0]}, which has derived facts "
                    f"({derived_at[atom[0]]}); an added atom would rest on nothing"
                )
                raise InputError(path, token.line, token.column, message)

    # --- operators ------------------------------------------------------------------

    def _operator(self, block: Block) -> None:
        parser = block.header.parser()
        parser.next()
        name = parser.expect("NAME", "an operator name")
        params: list[Token] = []
        if parser.accept("LPAREN"):
            params.append(parser.expect("NAME", "a parameter name"))
            while parser.accept("COMMA"):
                params.append(parser.expect("NAME", "a parameter name"))
            parser.expect("RPAREN", "',' or ')'")
        parser.end()
        if name.text in self.operators:
            first = self.operators[name.text].source
            raise parser.fail(name, f"operator '{name.text}' is defined twice (first at {first})")
        for i, param in enumerate(params):
            if param.text in (p.text for p in params[:i]):
                raise parser.fail(param, f"parameter '{param.text}' is listed twice")
            if param.text in self.constants:
                raise parser.fail(param, f"parameter '{param.text}' is also a declared constant")
        names = tuple(p.text for p in params)
        pre, lists = self._operator_parts(block, name.text, names)
        path = block.header.path
        self._check_effects(path, name.text, params, pre, lists)
        self.additions += [(a, t, path, name.text) for a, t in lists["add"]]
        adds = [a for a, _ in lists["add"]]
        deletes = [a for a, _ in lists["delete"]]
        source = SourceSpan(path, block.header.line)
        schema = OperatorSchema(name.text, map(Param, names), pre, adds, deletes, source)
        self.operators[name.text] = schema

    def _check_effects(
        self,
        path: str,
        operator: str,
        params: list[Token],
        pre: Formula,
        lists: dict[str, list[tuple[Atom, Token]]],
    ) -> None:
        """Delete lists name primitive predicates only; every parameter can be bound."""
        for atom, token in lists["delete"]:
            if not self._is_primitive(atom):
                message = (
                    f"expected only primitive predicates on a delete list (paper III.B) "
                    f"but {atom[0]}/{len(atom) - 1} is not declared primitive"
                )
                raise InputError(path, token.line, token.column, message)

        def params_of_list(part: str) -> set[Param]:
            return {p for atom, _ in lists[part] for arg in atom[1:] for p in params_of(arg)}

        bindable = params_in(pre) | params_of_list("add")
        for param in params:
            if Param(param.text) not in bindable:
                deleted = Param(param.text) in params_of_list("delete")
                message = (
                    f"parameter '{param.text}' of {operator} occurs "
                    f"{'only in the delete list' if deleted else 'nowhere'}: neither the "
                    f"precondition nor the add list can bind it"
                )
                raise InputError(path, param.line, param.column, message)

    def _operator_parts(
        self, block: Block, operator: str, params: tuple[str, ...]
    ) -> tuple[Formula, dict[str, list[tuple[Atom, Token]]]]:
        """The ``pre``, ``delete`` and ``add`` entries; each may be omitted, none repeated."""
        pre: Formula = Truth(True)
        lists: dict[str, list[tuple[Atom, Token]]] = {"delete": [], "add": []}
        seen: set[str] = set()
        for entry in block.entries:
            parser = self._parser(entry, params)
            part = parser.peek
            if part.kind != "NAME" or part.text not in OPERATOR_PARTS:
                raise parser.error("'pre', 'delete' or 'add'")
            parser.next()
            if part.text in seen:
                raise parser.fail(part, f"'{part.text}' is given twice for operator {operator}")
            seen.add(part.text)
            if part.text == "pre":
                pre = parser.formula()
            else:
                lists[part.text] = parser.atom_list(wildcard=part.text == "delete")
            parser.end()
        return pre, lists


class NativeLoader(Configurable):
    """Loads ``.strips`` files (see ``docs/problem-format.md``)."""

    name: ClassVar[str] = "native"
    suffixes: ClassVar[tuple[str, ...]] = (".strips",)

    def load(self, path: Path) -> Problem:
        return _Reader(str(path)).read(read_blocks(path, str(path)))


def parse_problem(text: str, source: str = "<text>") -> Problem:
    """A problem from native-format text made in code; ``source`` stands for the file in
    messages. ``include`` is refused: it names a file relative to the including one."""
    blocks = _split(text, source)
    for block in blocks:
        if block.keyword == "include":
            where = block.header
            raise InputError(source, where.line, where.column, "'include' needs a file: load "
                             "the problem with Planner.load, or paste the included text")
    return _Reader(source).read(blocks)
