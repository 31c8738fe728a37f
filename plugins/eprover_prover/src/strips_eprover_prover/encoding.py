"""A :class:`ProofTask` as TPTP for E, and E's answer tuples back as parameter bindings.

Symbols are renamed (``p0``, ``f1``, ...): the framework's names (``ROBOT``, ``sk!1``) are
not all TPTP words, and a fixed numbering in order of first occurrence makes the file, and
so E's run, the same for the same task. Unique names, when the task has ``=``, are the
axioms ``c != d`` for every two non-Skolem constants: E's distinct objects (``"c"``) would
only evaluate ground equations, and ``exists x: x != c`` needs ``x`` instantiated.

Axioms are ``cnf(..., axiom, ...)``. A goal without parameters is its negated clauses as
``negated_conjecture``; with parameters it is a ``question``: ``?[P1, P2]: ~(C1 & C2)``
with each clause ``Ci`` universally closed, so E's answer tuples bind the parameters.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Iterator, Sequence

from strips_framework.logic.clauses import Clause, Literal
from strips_framework.logic.terms import EQUALITY, SKOLEM_PREFIX, Param, Term
from strips_framework.worldmodel.proving import Answer, ProofTask


class SymbolTable:
    """The framework's symbols and parameters, numbered for TPTP in order of first use."""

    def __init__(self, unique_names: bool) -> None:
        self.unique_names = unique_names
        self._names: dict[tuple[str, str], str] = {}
        self._back: dict[str, str] = {}
        self.params: dict[Param, str] = {}
        self.constants: dict[str, None] = {}
        self.equality = False

    def symbol(self, kind: str, name: str) -> str:
        key = (kind, name)
        found = self._names.get(key)
        if found is None:
            found = f"{kind}{len(self._names)}"
            self._names[key] = found
            self._back[found] = name
        return found

    def for_attempt(self) -> SymbolTable:
        """A table for one attempt of a session: the symbols so far (shared, so a symbol
        keeps its name for the session), its own parameters and constants."""
        table = SymbolTable(self.unique_names)
        table._names, table._back = self._names, self._back
        return table

    def param(self, param: Param) -> str:
        found = self.params.get(param)
        if found is None:
            found = self.params[param] = f"P{len(self.params)}"
        return found

    def original(self, symbol: str) -> str | None:
        """The framework's symbol for a TPTP one, ``None`` for one E made up (Skolem)."""
        return self._back.get(symbol)


def _term(term: Term, table: SymbolTable) -> str:
    kind = type(term)
    if kind is int:
        return f"X{term}"
    if kind is Param:
        return table.param(term)
    if kind is tuple:
        args = ",".join(_term(arg, table) for arg in term[1:])
        return f"{table.symbol('f', term[0])}({args})"
    symbol = table.symbol("f", term)
    if not term.startswith(SKOLEM_PREFIX):
        table.constants[symbol] = None
    return symbol


def _literal(literal: Literal, table: SymbolTable) -> str:
    positive, atom = literal
    if atom[0] == EQUALITY and len(atom) == 3:
        table.equality = True
        sign = "=" if positive else "!="
        return f"{_term(atom[1], table)} {sign} {_term(atom[2], table)}"
    predicate = table.symbol("p", atom[0])
    args = ",".join(_term(arg, table) for arg in atom[1:])
    text = f"{predicate}({args})" if args else predicate
    return text if positive else f"~{text}"


def disjunction(clause: Clause, table: SymbolTable) -> str:
    literals = [_literal(literal, table) for literal in _bound(clause)]
    return " | ".join(literals) if literals else "$false"


def _bound(clause: Clause) -> Iterator[Literal]:
    """The clause's literals with its own parameter bindings applied."""
    from strips_framework.logic.unify import substitute

    bindings = dict(clause.bindings)
    for positive, atom in clause.literals:
        yield positive, substitute(atom, bindings) if bindings else atom


def _variables(text: str) -> list[str]:
    return list(dict.fromkeys(re.findall(r"\bX\d+\b", text)))


def _closed(text: str) -> str:
    variables = _variables(text)
    return f"![{','.join(variables)}]: ({text})" if variables else f"({text})"


def to_tptp(task: ProofTask) -> tuple[str, SymbolTable]:
    """The task as a TPTP problem, with the table that reads E's answers back."""
    table = SymbolTable(task.unique_names)
    lines = [
        f"cnf(a{number}, axiom, {disjunction(clause, table)})."
        for number, clause in enumerate(task.axioms)
    ]
    if table.params:
        raise ValueError("an axiom has parameters: only the goal may have them")
    goals = goal_lines(task.negated_goal, table, before=True)
    return "\n".join([*lines, *goals]) + "\n", table


def goal_lines(
    negated_goal: Sequence[Clause], table: SymbolTable, before: bool = False
) -> list[str]:
    """The negated goal's lines: its clauses, or with parameters a ``question`` over
    them; with ``before``, the unique-names axioms over the constants the table has
    seen when the task has equality (a session's attempts without equality need none)."""
    goals = [disjunction(clause, table) for clause in negated_goal]
    lines: list[str] = []
    if before and table.unique_names and table.equality:
        names = list(table.constants)
        lines.extend(
            f"cnf(u{i}_{j}, axiom, {names[i]} != {names[j]})."
            for i in range(len(names))
            for j in range(i + 1, len(names))
        )
    if not goals:
        return lines
    if table.params:
        body = " & ".join(_closed(goal) for goal in goals)
        params = ",".join(table.params.values())
        lines.append(f"fof(goal, question, ?[{params}]: ~({body})).")
    else:
        lines.extend(f"cnf(g{number}, negated_conjecture, {goal})." for number, goal in enumerate(goals))
    return lines


def mentions_equality(clauses: Iterable[Clause]) -> bool:
    return any(atom[0] == EQUALITY for clause in clauses for _, atom in clause.literals)


_TOKEN = re.compile(r'\s*("[^"]*"|[A-Za-z_][A-Za-z0-9_]*|[(),\[\]|])')


def _tokens(text: str) -> list[str]:
    tokens = []
    pos = 0
    while pos < len(text) and text[pos:].strip():
        found = _TOKEN.match(text, pos)
        if found is None:
            raise ValueError(f"unexpected answer text from E: {text!r}")
        tokens.append(found.group(1))
        pos = found.end()
    return tokens


class _UnknownSymbol(Exception):
    """An answer term uses a symbol E introduced (a Skolem function): not a binding."""


def _parse_term(tokens: list[str], pos: int, table: SymbolTable) -> tuple[Term | None, int]:
    """A term at ``tokens[pos]``: ``None`` for a variable (the answer leaves it open)."""
    head = tokens[pos]
    pos += 1
    if head[0].isupper() or head[0] == "_":
        return None, pos
    name = table.original(head)
    if name is None or name.startswith(SKOLEM_PREFIX):
        raise _UnknownSymbol(head)
    if pos < len(tokens) and tokens[pos] == "(":
        args: list[Term] = []
        pos += 1
        while True:
            arg, pos = _parse_term(tokens, pos, table)
            if arg is None:
                raise _UnknownSymbol("a variable inside a term")
            args.append(arg)
            if tokens[pos] == ")":
                return (name, *args), pos + 1
            pos += 1  # ','
    return name, pos


def parse_answers(lines: Iterable[str], table: SymbolTable) -> list[Answer]:
    """The bindings of E's ``# SZS answers Tuple [[t1, t2]|_]`` lines (``%`` since E 3),
    in E's order;
    tuples with E's own Skolem symbols or variables inside terms are left out (a parameter
    is never bound to those, paper III.A), a variable alone leaves its parameter open, and
    one that stands for two parameters (``[X, X]``: they must be equal) leaves the tuple
    out too. A
    disjunctive answer, ``[([a]|[b])|_]`` (the goal holds for one of the tuples, which one
    is not known), binds nothing either: the paper's answers are definite."""
    params = list(table.params)
    answers: list[Answer] = []
    for line in lines:
        if not line[1:].startswith(" SZS answers Tuple") or line[:1] not in "#%":
            continue
        text = line[len("# SZS answers Tuple") :].split(" for ")[0]
        if text.lstrip().startswith("[("):
            continue
        tokens = _tokens(text)
        try:
            values = _tuple(tokens, table)
        except _UnknownSymbol:
            continue
        binding = tuple(
            sorted(
                ((p, v) for p, v in zip(params, values) if v is not None),
                key=lambda pair: (pair[0].name, pair[0].tag),
            )
        )
        if binding not in answers:
            answers.append(binding)
    return answers


def _tuple(tokens: list[str], table: SymbolTable) -> list[Term | None]:
    """``[ [ t1 , t2 ] | _ ]``: the terms of the first (only) tuple."""
    pos = 2  # '[' '['
    values: list[Term | None] = []
    open_values: set[str] = set()
    while tokens[pos] != "]":
        head = tokens[pos]
        if head[0].isupper() or head[0] == "_":
            if head in open_values:
                # [X, X]: the parameters must be equal, which no binding per parameter says.
                raise _UnknownSymbol("a variable shared by two answers")
            open_values.add(head)
        value, pos = _parse_term(tokens, pos, table)
        values.append(value)
        if tokens[pos] == ",":
            pos += 1
    return values
